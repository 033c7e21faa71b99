/* Sparse hand sketches with a long gap between their points fit a fair curve near the points'
 * polygon through the gap, not one that swings in waves or a bulge there (QA, FreeCAD: 6
 * points, one at each end of 100 mm and a cluster between, noise 0.3 mm; smooth fits free
 * and pinned at both ends 7.7-19.1 mm off the polygon along 110-145 mm of curve for a
 * polygon of 101-105, status 0, where the curve the points came from stays within 0.8-3.4
 * mm of it). */
#include "testutil.h"
#include "fit_internal.h"
#include <stdio.h>

typedef struct { const char *name; int pinned; double xy[12]; } sketch;

static const sketch SKETCHES[] = {
    {"B", 0, {0.0, -0.56, 57.08, -3.9, 57.68, -3.3, 57.95, -3.94, 62.06, -3.95, 100.0, -16.19}},
    {"C", 0, {0.0, -0.27, 57.49, -3.59, 60.2, -3.14, 63.18, -3.46, 65.14, -4.1, 100.0, -9.19}},
    {"D", 0, {0.0, -0.08, 58.59, -3.57, 59.54, -3.16, 75.35, -6.42, 77.46, -8.0, 100.0, -15.74}},
    {"E", 1, {0.0, -0.08, 67.55, -0.72, 67.76, -0.8, 69.18, -0.21, 80.1, 2.14, 100.0, 10.3}},
    {"F", 1, {0.0, 0.28, 63.26, 0.94, 67.57, 3.14, 72.6, 4.09, 73.7, 4.84, 100.0, 19.56}},
};
enum { NP = 6, SAMPLES = 801 };

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

static Suite *suite(void)
{
    Suite *s = suite_create("fit_gap");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, test_fit_sparse_sketch_follows_its_gap, 0,
                        (int)(sizeof SKETCHES / sizeof SKETCHES[0]));
    tcase_add_test(tc, test_fit_gap_sag_is_its_definition);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
