/* Sparse hand sketches with a long gap between their points fit a fair curve near the points'
 * polygon through the gap, not one that swings in waves or a bulge there (QA, FreeCAD: 6
 * points, one at each end of 100 mm and a cluster between, noise 0.3 mm; smooth fits free
 * and pinned at both ends 7.7-19.1 mm off the polygon along 110-145 mm of curve for a
 * polygon of 101-105, status 0, where the curve the points came from stays within 0.8-3.4
 * mm of it). */
#include "testutil.h"
#include "fit_internal.h"
#include "fit_wander.h"
#include <stdio.h>
#include <string.h>

typedef struct { const char *name; int pinned; double xy[12]; } sketch;

static const sketch SKETCHES[] = {
    {"B", 0, {0.0, -0.56, 57.08, -3.9, 57.68, -3.3, 57.95, -3.94, 62.06, -3.95, 100.0, -16.19}},
    {"C", 0, {0.0, -0.27, 57.49, -3.59, 60.2, -3.14, 63.18, -3.46, 65.14, -4.1, 100.0, -9.19}},
    {"D", 0, {0.0, -0.08, 58.59, -3.57, 59.54, -3.16, 75.35, -6.42, 77.46, -8.0, 100.0, -15.74}},
    {"E", 1, {0.0, -0.08, 67.55, -0.72, 67.76, -0.8, 69.18, -0.21, 80.1, 2.14, 100.0, 10.3}},
    {"F", 1, {0.0, 0.28, 63.26, 0.94, 67.57, 3.14, 72.6, 4.09, 73.7, 4.84, 100.0, 19.56}},
};
enum { NP = 6, SAMPLES = 801, DENSE = 4001 };

/* the distance of q from the polygon of the n points xy */
static double polygon_distance(const double *q, const double *xy, size_t n)
{
    double best = HUGE_VAL;
    for (size_t i = 0; i + 1 < n; i++) {
        const double *A = xy + 2 * i, ux = A[2] - A[0], uy = A[3] - A[1];
        double t = ((q[0] - A[0]) * ux + (q[1] - A[1]) * uy) / (ux * ux + uy * uy);
        t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
        best = fmin(best, hypot(q[0] - A[0] - t * ux, q[1] - A[1] - t * uy));
    }
    return best;
}

/* A sketch whose kept fit swings in its last gap (bench_fit_sparse.py seed 5 case 670: 18
 * points along a curve of length 1, noise 0.0097; the smooth fit, rms 0.0066, status 0,
 * turns by 3.3 rad between points 16 and 17, 0.29 of their chord off it) */
static const double SWING[] = {
    0.0006418172386133665, -0.009172698423006604, -0.0393050280158322, 0.0888978269240638,
    -0.04410652357552151, 0.07781816337897415, -0.06945529273743643, 0.13534246980265838,
    -0.0681711519605496, 0.18711934872776317, -0.08534547502582791, 0.17483787973439557,
    -0.07971644440404725, 0.19351333159523354, -0.08292744962692104, 0.22925476870406705,
    -0.11768717301276027, 0.26796689603919843, -0.13233479065612236, 0.33431893963611714,
    -0.13570815118322452, 0.3441094674465781, -0.11974186746684463, 0.3577549927298168,
    -0.14291521256031886, 0.39371468126658143, -0.14679271320366788, 0.3947725451877166,
    -0.15124322533443688, 0.42582445746101916, -0.17995681897253346, 0.500828792412778,
    -0.1867935999826268, 0.5313171576065319, -0.11944538649982038, 0.960615311034519};
enum { NSWING = sizeof SWING / sizeof SWING[0] / 2 };

/* |the turn at its k-th point of the path through the points xy in the order o| (0 at its ends) */
static double path_turn(const double *xy, const size_t *o, size_t n, size_t k)
{
    if (k == 0 || k + 1 >= n) return 0.0;
    const double *P = xy + 2 * o[k - 1], *Q = xy + 2 * o[k], *R = xy + 2 * o[k + 1];
    return fabs(remainder(atan2(R[1] - Q[1], R[0] - Q[0]) - atan2(Q[1] - P[1], Q[0] - P[0]), 2.0 * M_PI));
}

/* The first gap between two points adjacent along the smooth curve p (their feet fs adjacent:
 * a, b, named b - 1 for a < b, as el_fit_smooth names it) where it swings, by DENSE samples
 * between the two feet: it turns there by more than FIT_GAP_TURN beyond the turns of the
 * points' path (in the feet's order) at a and b, and comes farther than FIT_GAP_SAG of their
 * chord plus 4 level from that chord; -1 where none does. *far: the distance of the sample
 * farthest from the points' polygon (over all gaps), *far_a, *far_b: the feet around it. */
static long dense_swing_gap(const el_smooth_params *p, const double *xy, size_t n, const double *fs,
                            double level, double *far, double *far_a, double *far_b)
{
    static double s[DENSE], g[2 * DENSE], th[DENSE];
    size_t o[64];
    ck_assert(n <= 64);
    for (size_t i = 0; i < n; i++) {        /* the points by their feet */
        size_t j = i;
        for (; j > 0 && fs[o[j - 1]] > fs[i]; j--) o[j] = o[j - 1];
        o[j] = i;
    }
    long first = -1;
    *far = -1.0;
    for (size_t k = 0; k + 1 < n; k++) {
        const size_t a = o[k], b = o[k + 1];
        for (int j = 0; j < DENSE; j++) s[j] = fs[a] + (fs[b] - fs[a]) * j / (DENSE - 1.0);
        ck_assert_int_eq(el_smooth_eval(p, DENSE, s, g, th, NULL), EL_OK);
        const double *A = xy + 2 * a, *B = xy + 2 * b, ux = B[0] - A[0], uy = B[1] - A[1], ch = hypot(ux, uy);
        double turn = -path_turn(xy, o, n, k) - path_turn(xy, o, n, k + 1), off = 0.0;
        for (int j = 0; j < DENSE; j++) {
            double t = ((g[2 * j] - A[0]) * ux + (g[2 * j + 1] - A[1]) * uy) / (ch * ch);
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            off = fmax(off, hypot(g[2 * j] - A[0] - t * ux, g[2 * j + 1] - A[1] - t * uy));
            if (j) turn += fabs(th[j] - th[j - 1]);
            const double e = polygon_distance(g + 2 * j, xy, n);
            if (e > *far) { *far = e; *far_a = fs[a]; *far_b = fs[b]; }
        }
        if (first < 0 && turn > FIT_GAP_TURN && off > FIT_GAP_SAG * ch + 4.0 * level)
            first = (long)(a > b ? a : b) - 1;
    }
    return first;
}

/* Each sketch's smooth fit (free, or 'Pin start + Pin end'): between its first and last foot
 * within 5 mm of the points' polygon (its own curve: 3.4 at most), no longer than 1.1 x the
 * polygon, at an rms within twice the sketch's noise of 0.3 mm. */
START_TEST(test_fit_sparse_sketch_follows_its_gap)
{
    const sketch *k = &SKETCHES[_i];
    el_fit_options o;
    el_fit_options_defaults(&o);
    if (k->pinned) {
        o.constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
        o.start_point[0] = k->xy[0]; o.start_point[1] = k->xy[1];
        o.end_point[0] = k->xy[2 * NP - 2]; o.end_point[1] = k->xy[2 * NP - 1];
    }
    el_fit_smooth_result r;
    double d[NP], fs[NP];
    const int st = el_fit_smooth(k->xy, NP, &o, NULL, &r, d, fs);
    ck_assert_msg(st == EL_OK, "%s: status %d", k->name, st);
    double lo = HUGE_VAL, hi = -HUGE_VAL, poly = 0.0;
    for (int i = 0; i < NP; i++) { lo = fmin(lo, fs[i]); hi = fmax(hi, fs[i]); }
    for (int i = 0; i + 1 < NP; i++)
        poly += hypot(k->xy[2 * i + 2] - k->xy[2 * i], k->xy[2 * i + 3] - k->xy[2 * i + 1]);
    static double s[SAMPLES], q[2 * SAMPLES];
    for (int j = 0; j < SAMPLES; j++) s[j] = lo + (hi - lo) * j / (SAMPLES - 1.0);
    ck_assert_int_eq(el_smooth_eval(&r.params, SAMPLES, s, q, NULL, NULL), EL_OK);
    double off = 0.0;
    for (int j = 0; j < SAMPLES; j++) off = fmax(off, polygon_distance(q + 2 * j, k->xy, NP));
    ck_assert_msg(off < 5.0, "%s: %.1f mm off the points' polygon (rms %.3f)", k->name, off, r.rms);
    ck_assert_msg(r.params.length < 1.1 * poly, "%s: length %.1f for a polygon of %.1f", k->name,
                  r.params.length, poly);
    ck_assert_msg(r.rms < 0.6, "%s: rms %.3f", k->name, r.rms);
    /* it follows its points, and says so: no gap swings by dense samples either */
    double far, fa, fb;
    ck_assert_msg(dense_swing_gap(&r.params, k->xy, NP, fs, 0.0, &far, &fa, &fb) == -1, "%s", k->name);
    ck_assert_msg(r.wander_gap == -1, "%s: wander_gap %ld", k->name, r.wander_gap);
}
END_TEST

/* A fit that swings between two points where no refit follows them says where: wander_gap
 * names the gap the dense samples find swinging (by el__fit_gap_sag's definition, at the
 * fit's rms as the noise level: the detector's is at most that), the first, and the curve's
 * farthest sample from the points' polygon, 10 x its rms off it, lies in that gap; its
 * distances alone do not show it (all within 3 rms) */
START_TEST(test_fit_that_swings_names_its_gap)
{
    el_fit_smooth_result r;
    double d[NSWING], fs[NSWING], far, fa, fb;
    ck_assert_int_eq(el_fit_smooth(SWING, NSWING, NULL, NULL, &r, d, fs), EL_OK);
    const long gap = dense_swing_gap(&r.params, SWING, NSWING, fs, r.rms, &far, &fa, &fb);
    ck_assert_msg(gap >= 0, "no gap swings (rms %.4g)", r.rms);
    ck_assert_msg(r.wander_gap == gap, "wander_gap %ld, the dense samples' %ld", r.wander_gap, gap);
    ck_assert_msg(far > 10.0 * r.rms && fa == fs[gap] && fb == fs[gap + 1],
                  "farthest %.3g between feet %.4g and %.4g, gap %ld from %.4g to %.4g", far, fa, fb, gap,
                  fs[gap], fs[gap + 1]);
    for (int i = 0; i < NSWING; i++) ck_assert_msg(fabs(d[i]) < 3.0 * r.rms, "point %d: %.3g", i, d[i]);
    /* without the result arrays alike */
    el_fit_smooth_result r2;
    ck_assert_int_eq(el_fit_smooth(SWING, NSWING, NULL, NULL, &r2, NULL, NULL), EL_OK);
    ck_assert_int_eq(r2.wander_gap, r.wander_gap);
    ck_assert(memcmp(&r2.params, &r.params, sizeof r.params) == 0);
}
END_TEST

/* 8 clicks whose fit passes them out of order (QA: rms 0.14 for noise 0.2, in the order
 * 0 1 5 4 3 2 6 7 along the curve, status 0, no warning before): wander_gap names the first
 * gap whose second point the curve passes first, measured here from dense samples (each
 * point's nearest sample's arc length; the rms as the noise level, the library's at most
 * that), both models; every point near the curve all the same */
static const double BACK8[] = {
    -0.3123155064274531, -0.3998459709537178, 2.3037709051939164, -0.2100425891154530,
    10.716017639108571, -29.858151548005839, 8.2266748545831767, -28.294460052086894,
    5.3313045553450742, -18.774293019531545, 5.5341275881942975, -18.002893559636476,
    7.6461033913124217, -22.668050798815415, 7.3819699298382631, -22.772108081185507,
};

/* the arc length of the nearest of m samples g (2m, at arc lengths s) to each point */
static void dense_feet(const double *g, const double *s, size_t m, const double *xy, size_t n, double *f)
{
    for (size_t i = 0; i < n; i++) {
        double best = HUGE_VAL;
        for (size_t j = 0; j < m; j++) {
            const double d = hypot(g[2 * j] - xy[2 * i], g[2 * j + 1] - xy[2 * i + 1]);
            if (d < best) { best = d; f[i] = s[j]; }
        }
    }
}

START_TEST(test_fit_out_of_order_names_its_gap)
{
    enum { N = 8, M = 20001 };
    static double g[2 * M], s[M];
    for (int model = 0; model < 2; model++) {
        double d[N], f[N], rms, L;
        long gap;
        if (model == 0) {
            el_fit_smooth_result r;
            ck_assert_int_eq(el_fit_smooth(BACK8, N, NULL, NULL, &r, d, NULL), EL_OK);
            L = r.params.length;
            for (int j = 0; j < M; j++) s[j] = L * j / (M - 1);
            ck_assert_int_eq(el_smooth_eval(&r.params, M, s, g, NULL, NULL), EL_OK);
            rms = r.rms;
            gap = r.wander_gap;
        } else {
            el_fit_discrete_result r;
            double V[2 * N];
            ck_assert_int_eq(el_fit_discrete(BACK8, N, NULL, NULL, &r, d, NULL), EL_OK);
            ck_assert_int_eq(el_discrete_eval(&r.params, N, V), EL_OK);
            L = r.params.h * (N - 1);
            for (int j = 0; j < M; j++) {      /* the polygon, M samples */
                const double t = (double)j / (M - 1) * (N - 1);
                const int k = t >= N - 1 ? N - 2 : (int)t;
                s[j] = t * r.params.h;
                g[2 * j] = V[2 * k] + (t - k) * (V[2 * k + 2] - V[2 * k]);
                g[2 * j + 1] = V[2 * k + 1] + (t - k) * (V[2 * k + 3] - V[2 * k + 1]);
            }
            rms = r.rms;
            gap = r.wander_gap;
        }
        dense_feet(g, s, M, BACK8, N, f);
        long first = -1;
        for (int i = 0; i + 1 < N && first < 0; i++) {
            const double chord = hypot(BACK8[2 * i + 2] - BACK8[2 * i], BACK8[2 * i + 3] - BACK8[2 * i + 1]);
            if (f[i] - f[i + 1] > fmax(0.5 * chord, 8.0 * rms) + 2.0 * L / (M - 1)) first = i;
        }
        ck_assert_msg(first == 2 && gap == first, "model %d: wander_gap %ld, the dense feet's %ld", model, gap, first);
        for (int i = 0; i < N; i++) ck_assert_msg(fabs(d[i]) < 3.0 * rms, "model %d point %d: %.3g", model, i, d[i]);
    }
}
END_TEST

/* el__fit_gap_sag's definition on one gap (two points on a curve, their feet out of order,
 * no noise, no polygon turn): where the curve turns there by more than FIT_GAP_TURN in all,
 * its farthest distance from their chord over that chord (brute force with 4001 samples; its
 * 31 within 1 - cos(pi / 32) of the peak, 0.5 %, where the gap is under a wave long), else 0 */
START_TEST(test_fit_gap_sag_is_its_definition)
{
    unsigned long long state = 7;
    int swings = 0, fair = 0;
    for (int c = 0; c < 400; c++) {
        el_smooth_params q = {test_uniform(&state, -5, 5), test_uniform(&state, -5, 5),
                              test_uniform(&state, -3, 3), pow(10.0, test_uniform(&state, -1, 0)),
                              test_uniform(&state, -0.99, 0.99), test_uniform(&state, -3, 3), 0.0};
        q.length = test_uniform(&state, 1.0, 6.0);   /* under a wave (4 K / sqrt(mu) > 2 pi) */
        enum { M = 4001 };
        const double fs[2] = {q.length, 0.0};
        const double par[FIT_NP] = {q.x0, q.y0, q.phi, q.mu, q.k, q.q, q.length};
        double xy[4];
        ck_assert_int_eq(el_smooth_eval(&q, 2, fs, xy, NULL, NULL), EL_OK);
        static double s[M], g[2 * M], th[M];
        for (int j = 0; j < M; j++) s[j] = q.length * j / (M - 1.0);
        ck_assert_int_eq(el_smooth_eval(&q, M, s, g, th, NULL), EL_OK);
        const double *A = xy + 2, *B = xy, ux = B[0] - A[0], uy = B[1] - A[1], ch = hypot(ux, uy);
        double want = 0.0, turn = 0.0;
        for (int j = 0; j < M; j++) {
            double t = ((g[2 * j] - A[0]) * ux + (g[2 * j + 1] - A[1]) * uy) / (ch * ch);
            t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
            want = fmax(want, hypot(g[2 * j] - A[0] - t * ux, g[2 * j + 1] - A[1] - t * uy) / ch);
            if (j) turn += fabs(th[j] - th[j - 1]);
        }
        const double sag = el__fit_gap_sag(xy, 2, fs, par, 0.0);
        if (turn > 1.05 * FIT_GAP_TURN) {
            swings++;
            ck_assert_msg(sag <= want * (1.0 + 1e-12) && sag >= want * (1.0 - 0.005),
                          "curve %d: %.6g against %.6g", c, sag, want);
            /* a noise level: 4 of them off the farthest distance */
            ck_assert_msg(fabs(el__fit_gap_sag(xy, 2, fs, par, 1e-3) - (sag - 4e-3 / ch)) < 1e-12,
                          "curve %d: noise", c);
        } else if (turn < 0.95 * FIT_GAP_TURN) {
            fair++;
            ck_assert_msg(sag == 0.0, "curve %d turning %.3g: %.6g", c, turn, sag);
        }
    }
    ck_assert_msg(swings > 20 && fair > 20, "%d swing, %d fair", swings, fair);
}
END_TEST

/* Points exactly on a line, fitted exactly by both models (the discrete one paired): they
 * follow their points (the polygon's collinear chords, crossing by their rounding alone, are
 * no loop: gap 6 before) */
START_TEST(test_straight_fit_follows_its_points)
{
    enum { N = 25 };
    double xy[2 * N], d[N], fs[N];
    for (int i = 0; i < N; i++) {
        xy[2 * i] = -1.0 + 3.0 * i / (N - 1.0);
        xy[2 * i + 1] = 0.5 * xy[2 * i] + 1.0;
    }
    el_fit_discrete_result rd;
    ck_assert_int_eq(el_fit_discrete(xy, N, NULL, NULL, &rd, d, fs), EL_OK);
    ck_assert_msg(rd.rms < 1e-12, "rms %g", rd.rms);
    ck_assert_int_eq(rd.wander_gap, -1);
    el_fit_smooth_result rs;
    ck_assert_int_eq(el_fit_smooth(xy, N, NULL, NULL, &rs, d, fs), EL_OK);
    ck_assert_int_eq(rs.wander_gap, -1);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_gap");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, test_fit_sparse_sketch_follows_its_gap, 0,
                        (int)(sizeof SKETCHES / sizeof SKETCHES[0]));
    tcase_add_test(tc, test_fit_gap_sag_is_its_definition);
    tcase_add_test(tc, test_fit_that_swings_names_its_gap);
    tcase_add_test(tc, test_fit_out_of_order_names_its_gap);
    tcase_add_test(tc, test_straight_fit_follows_its_points);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
