/*
 * Whether a fit follows its points (fit.c's stray rule, fit_choose.c's and fit_follow.c's
 * sketch rules, the report's wander gap): the length of curve no point accounts for (strays),
 * the curve's swing between two points where there is none (gap sag), its crossings where
 * the points' polygon has none (loops), and the gap it wanders in, points passed out of
 * order included (el__fit_wander_gap). Split from fit_refit.c, verbatim.
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include <stdlib.h>

/* The gap k along the curve (between the feet idx[k], idx[k + 1]; idx NULL: in order) as
 * the gap i between points i and i + 1 before the later of its two points (i itself where
 * the curve passes them in order; where it passes points a < b adjacent along it, those
 * between them lie elsewhere along it, and it comes to b from a: the gap b - 1, b) */
static long gap_index(const size_t *idx, size_t k)
{
    if (!idx) return (long)k;
    return (long)(idx[k] > idx[k + 1] ? idx[k] : idx[k + 1]) - 1;
}

double el__fit_stray(const double *xy, size_t n, const double *fs, double L, double noise, double scale)
{
    return el__fit_stray_held(xy, n, fs, L, noise, scale, NULL);
}

/* el__fit_stray_held, and in *at (may be NULL) the gap holding the most of the curve no
 * point accounts for (named by gap_index); in *of_curve (may be NULL) that length over the
 * length of the curve the points do account for where that is the shorter than their
 * polygon (el__fit_stray_curve) */
static double stray_at(const double *xy, size_t n, const double *fs, double L, double noise,
                       double scale, const double ends[4], long *at, double *of_curve)
{
    /* the feet by arc length: read in place where they are in order, else through their
     * indices sorted (8 bytes a point: at 10^6 noisy points half the neighbours swap) */
    int in_order = 1;
    for (size_t i = 0; i + 1 < n && in_order; i++) in_order = fs[i] <= fs[i + 1];
    size_t *idx = NULL;
    if (!in_order) {
        if (!(idx = malloc(sizeof *idx * n))) return -1.0;
        if (el__fit_feet_order(fs, idx, n)) { free(idx); return -1.0; }
    }
    /* lengths over scale (the data's size): sqrt of sums of squares without overflow,
     * cheaper than hypot (2 % of a 1000-point smooth fit with hypot) */
    const double is = 1.0 / scale, slack = 4.0 * noise * is;
    const size_t first = idx ? idx[0] : 0, last = idx ? idx[n - 1] : n - 1;
    /* a held end's allowance: 1.6 x its chord to the nearest point (none where not held) */
    double lead = 0.0, tail = 0.0;
    if (ends && isfinite(ends[0]))
        lead = 1.6 * hypot(xy[2 * first] - ends[0], xy[2 * first + 1] - ends[1]) * is;
    if (ends && isfinite(ends[2]))
        tail = 1.6 * hypot(xy[2 * last] - ends[2], xy[2 * last + 1] - ends[3]) * is;
    const double s0 = fmax(0.0, fs[first] * is - lead - slack), s1 = fmax(0.0, (L - fs[last]) * is - tail - slack);
    double poly = 0.0, stray = s0 + s1, most = 0.0;
    /* the ends' share: the gap next to that end's point along the curve */
    if (at && s0 > most) { most = s0; *at = gap_index(idx, 0); }
    if (at && s1 > most) { most = s1; *at = gap_index(idx, n - 2); }
    for (size_t k = 0; k + 1 < n; k++) {
        const size_t a = idx ? idx[k] : k, b = idx ? idx[k + 1] : k + 1;
        const double cx = (xy[2 * b] - xy[2 * a]) * is, cy = (xy[2 * b + 1] - xy[2 * a + 1]) * is;
        const double px = (xy[2 * k + 2] - xy[2 * k]) * is, py = (xy[2 * k + 3] - xy[2 * k + 1]) * is;
        const double sk = fmax(0.0, (fs[b] - fs[a]) * is - 1.6 * sqrt(cx * cx + cy * cy) - slack);
        stray += sk;
        poly += sqrt(px * px + py * py);
        if (at && sk > most) { most = sk; *at = gap_index(idx, k); }
    }
    free(idx);
    if (of_curve) {
        const double held = L * is - stray, base = fmin(poly, held);
        *of_curve = stray <= 0.0 ? 0.0 : base > 0.0 ? stray / base : HUGE_VAL;
    }
    return stray / poly;
}

double el__fit_stray_curve(const double *xy, size_t n, const double *fs, double L, double noise, double scale,
                           double *stray)
{
    double of_curve = -1.0;
    const double s = stray_at(xy, n, fs, L, noise, scale, NULL, NULL, &of_curve);
    if (stray) *stray = s;
    return s < 0.0 ? -1.0 : of_curve;
}

double el__fit_stray_held(const double *xy, size_t n, const double *fs, double L, double noise,
                          double scale, const double ends[4])
{
    return stray_at(xy, n, fs, L, noise, scale, ends, NULL, NULL);
}

/* samples of the curve in each gap between adjacent feet (el__fit_gap_sag), its ends
 * included: a wave of the gap's length peaks within 1 - cos(pi / 32) of its height between
 * two of them */
enum { GAP_SAMPLES = 32, GAP_M = GAP_SAMPLES + 1 };

/* the angle a - b in (-pi, pi] */
static double turn_between(double a, double b) { return remainder(a - b, 2.0 * M_PI); }

/* |the polygon's turn| at its k-th point in the order idx (0 at its ends) */
static double polygon_turn(const double *xy, size_t n, const size_t *idx, size_t k)
{
    if (k == 0 || k + 1 >= n) return 0.0;
    const double *P = xy + 2 * idx[k - 1], *Q = xy + 2 * idx[k], *R = xy + 2 * idx[k + 1];
    return fabs(turn_between(atan2(R[1] - Q[1], R[0] - Q[0]), atan2(Q[1] - P[1], Q[0] - P[0])));
}

/* The sag of gap k (between the feet idx[k], idx[k + 1]) as el__fit_gap_sag measures it,
 * from m samples g (2m) of the curve from foot to foot, ends included, and their tangent
 * angles th; -HUGE_VAL where the curve turns there by at most FIT_GAP_TURN beyond the
 * polygon's turns at the gap's two points */
static double sag_of_gap(const double *xy, size_t n, const size_t *idx, size_t k, const double *g,
                         const double *th, size_t m, double noise)
{
    const double *A = xy + 2 * idx[k], *B = xy + 2 * idx[k + 1];
    const double ux = B[0] - A[0], uy = B[1] - A[1], chord = hypot(ux, uy);
    /* the curve's turning there beyond the polygon's at the gap's two points */
    double turn = -polygon_turn(xy, n, idx, k) - polygon_turn(xy, n, idx, k + 1);
    for (size_t j = 1; j < m; j++) turn += fabs(turn_between(th[j], th[j - 1]));
    if (!(chord > 0.0) || !(turn > FIT_GAP_TURN)) return -HUGE_VAL;
    double far = 0.0;   /* the farthest inner sample from the segment A B */
    for (size_t j = 1; j + 1 < m; j++) {
        const double *G = g + 2 * j;
        const double t = fit_clamp(((G[0] - A[0]) * ux + (G[1] - A[1]) * uy) / (chord * chord), 0.0, 1.0);
        far = fmax(far, hypot(G[0] - A[0] - t * ux, G[1] - A[1] - t * uy));
    }
    return (far - 4.0 * noise) / chord;
}

/* el__fit_gap_sag, and in *at (may be NULL, else -1 on entry) the first gap along the curve
 * whose sag is above FIT_GAP_SAG (named by gap_index) */
static double gap_sag_at(const double *xy, size_t n, const double *fs, const double *p, double noise, long *at)
{
    const el_smooth_params c = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
    size_t *idx = malloc(sizeof *idx * n);
    double *s = malloc(sizeof(double) * 4 * GAP_M * (n - 1));
    if (!idx || !s || el__fit_feet_order(fs, idx, n)) { free(idx); free(s); return -1.0; }
    double *g = s + GAP_M * (n - 1), *th = g + 2 * GAP_M * (n - 1), worst = 0.0;
    for (size_t k = 0; k + 1 < n; k++)
        for (int j = 0; j < GAP_M; j++)
            s[k * GAP_M + j] = fs[idx[k]] + (fs[idx[k + 1]] - fs[idx[k]]) * j / GAP_SAMPLES;
    /* a curve that cannot be evaluated there shows no sag (its other tests judge it) */
    if (el_smooth_eval(&c, GAP_M * (n - 1), s, g, th, NULL)) { free(idx); free(s); return 0.0; }
    for (size_t k = 0; k + 1 < n; k++) {
        const double sag = sag_of_gap(xy, n, idx, k, g + 2 * k * GAP_M, th + k * GAP_M, GAP_M, noise);
        worst = fmax(worst, sag);
        if (at && *at < 0 && sag > FIT_GAP_SAG) *at = gap_index(idx, k);
    }
    free(idx);
    free(s);
    return worst;
}

double el__fit_gap_sag(const double *xy, size_t n, const double *fs, const double *p, double noise)
{
    return gap_sag_at(xy, n, fs, p, noise, NULL);
}

/* The point at arc length f (in [0, (n - 1) h]) of the polygon V and its segment's direction,
 * appended to g, th (*m of them) */
static void polygon_sample(const double *V, size_t n, double h, double f, double *g, double *th, size_t *m)
{
    const size_t j = (size_t)fit_clamp(floor(f / h), 0.0, (double)(n - 2));
    const double t = (f - (double)j * h) / h, *P = V + 2 * j, dx = P[2] - P[0], dy = P[3] - P[1];
    g[2 * *m] = P[0] + t * dx;
    g[2 * *m + 1] = P[1] + t * dy;
    th[(*m)++] = atan2(dy, dx);
}

/* el__fit_gap_sag's measure on a discrete fit's polygon V (n vertices, segment h; fs its
 * feet, arc length from vertex 0): a polygon turns at its vertices alone and lies farthest
 * from a chord at one, so its samples in a gap are the feet's points and the vertices between
 * them, each with the direction of the segment that leaves it (their differences: the
 * vertices' turns). The first gap whose sag is above FIT_GAP_SAG, named by gap_index (-1:
 * none, or out of memory). */
static long polygon_swing_gap(const double *xy, size_t n, const double *fs, const double *V, double h,
                              double noise)
{
    size_t *idx = malloc(sizeof *idx * n);
    double *g = malloc(sizeof(double) * 3 * (n + 2));
    long at = -1;
    if (!idx || !g || el__fit_feet_order(fs, idx, n)) { free(idx); free(g); return -1; }
    double *th = g + 2 * (n + 2);
    const double L = (double)(n - 1) * h;
    for (size_t k = 0; k + 1 < n && at < 0; k++) {
        const double fa = fit_clamp(fs[idx[k]], 0.0, L), fb = fit_clamp(fs[idx[k + 1]], 0.0, L);
        if (!(fa <= fb)) continue;      /* a NaN foot */
        size_t m = 0;
        polygon_sample(V, n, h, fa, g, th, &m);
        for (size_t i = (size_t)(fa / h) + 1; i + 1 < n && (double)i * h < fb; i++) {
            const double *Q = V + 2 * i;
            g[2 * m] = Q[0];
            g[2 * m + 1] = Q[1];
            th[m++] = atan2(Q[3] - Q[1], Q[2] - Q[0]);
        }
        polygon_sample(V, n, h, fb, g, th, &m);
        if (sag_of_gap(xy, n, idx, k, g, th, m, noise) > FIT_GAP_SAG) at = gap_index(idx, k);
    }
    free(idx);
    free(g);
    return at;
}

int el__fit_strays_at(fit_objective *ob, const double *x, double noise, double *d, double *fs, double *tmp)
{
    double v[2][FIT_NP];
    if (el__fit_map_eval(&ob->map, x, v, NULL) || el__fit_curve_distances(ob, x, v, 0, d, fs, tmp)) return 0;
    ob->rest_ok = 0;     /* d, fs no longer hold an evaluation's points at rest */
    for (size_t i = 0; i < ob->n; i++) fs[i] *= ob->sc;
    const double L = ob->map.model == FIT_SMOOTH ? v[0][6] : (double)(ob->n - 1) * v[0][2];
    const double stray = el__fit_stray_held(ob->xy, ob->n, fs, L * ob->sc, noise * ob->sc, ob->sc,
                                            ob->held_ends);
    return stray > FIT_STRAY;
}

/* the chords of the crossing test: a loop narrower than about L / CROSS_CHORDS is missed;
 * the points' polygon by POINT_CHORDS (measured: 300 points with noise 0.5 % of their
 * extent at spacing 1/60 of it, every 2nd point's polygon crossed itself, every 5th not) */
enum { CROSS_CHORDS = 256, POINT_CHORDS = 64 };

/* Whether the polygon through every step-th of the m points p (and the last) crosses
 * itself: two chords, not neighbours, each one's ends on both sides of the other; with
 * span >= 0, the vertices between them spanning more than span (their box's diagonal).
 * loop (may be NULL): the first crossing's loop, from the first chord's start to the second
 * chord's end (indices into p). tol > 0: each chord's ends farther than tol from the other's
 * line (chords that touch or lie on one line within it do not cross: a straight fit's collinear
 * chords crossed by their rounding); 0: the signs alone. */
static int chords_cross(const double *p, size_t m, size_t step, double span, size_t loop[2], double tol)
{
    size_t idx[CROSS_CHORDS + 2], nc = 0;
    for (size_t i = 0; i < m; i += step) idx[nc++] = i;
    if (idx[nc - 1] != m - 1) idx[nc++] = m - 1;
    for (size_t a = 0; a + 1 < nc; a++) {
        const double *A = p + 2 * idx[a], *A1 = p + 2 * idx[a + 1], ax = A1[0] - A[0], ay = A1[1] - A[1];
        double box[4] = {A1[0], A1[0], A1[1], A1[1]};      /* the loop's vertices' box */
        for (size_t b = a + 2; b + 1 < nc; b++) {
            const double *B = p + 2 * idx[b], *B1 = p + 2 * idx[b + 1], bx = B1[0] - B[0], by = B1[1] - B[1];
            if (span >= 0.0) {
                box[0] = fmin(box[0], B[0]); box[1] = fmax(box[1], B[0]);
                box[2] = fmin(box[2], B[1]); box[3] = fmax(box[3], B[1]);
                if (!(hypot(box[1] - box[0], box[3] - box[2]) > span)) continue;
            }
            const double s1 = ax * (B[1] - A[1]) - ay * (B[0] - A[0]), s2 = ax * (B1[1] - A[1]) - ay * (B1[0] - A[0]);
            if ((s1 > 0.0) == (s2 > 0.0)) continue;
            const double s3 = bx * (A[1] - B[1]) - by * (A[0] - B[0]), s4 = bx * (A1[1] - B[1]) - by * (A1[0] - B[0]);
            if (tol > 0.0 && !(fmin(fabs(s1), fabs(s2)) > tol * hypot(ax, ay) &&
                               fmin(fabs(s3), fabs(s4)) > tol * hypot(bx, by)))
                continue;
            if ((s3 > 0.0) != (s4 > 0.0)) {
                if (loop) { loop[0] = idx[a]; loop[1] = idx[b + 1]; }
                return 1;
            }
        }
    }
    return 0;
}

/* step through m points for at most c chords */
static size_t chord_step(size_t m, size_t c) { return m > c + 1 ? (m - 1 + c - 1) / c : 1; }

int el__fit_crosses_itself(const fit_objective *ob, const double *x)
{
    double v[2][FIT_NP];
    if (ob->map.ncurves != 1 || el__fit_map_eval(&ob->map, x, v, NULL)) return 0;
    if (ob->map.model == FIT_SMOOTH) {
        double s[CROSS_CHORDS + 1], p[2 * (CROSS_CHORDS + 1)];
        el_smooth_params c;
        if (el__fit_to_smooth(v[0], &c)) return 0;
        for (int j = 0; j <= CROSS_CHORDS; j++) s[j] = c.length * j / CROSS_CHORDS;
        if (el_smooth_eval(&c, CROSS_CHORDS + 1, s, p, NULL, NULL)) return 0;
        return chords_cross(p, CROSS_CHORDS + 1, 1, -1.0, NULL, 0.0);
    }
    const size_t n = ob->n;
    double *V = malloc(sizeof(double) * (2 * n + 2 * (FIT_BLOCK + 2) * (FIT_NP + 1)));
    if (!V) return 0;       /* as a curve that cannot be evaluated: no crossing seen */
    fit_walk w;
    el__fit_walk_start(v[0], &w);
    int st = EL_OK;
    for (size_t a = 0; a < n && !st; a += FIT_BLOCK)
        st = el__fit_discrete_rows(v[0], &w, n - a < FIT_BLOCK ? n - a : FIT_BLOCK, V + 2 * a, NULL, 0, V + 2 * n);
    const int cross = !st && !el__all_finite(V, 2 * n) &&
                      chords_cross(V, n, chord_step(n, CROSS_CHORDS), -1.0, NULL, 0.0);
    free(V);
    return cross;
}

/* A crossing of the points' polygon is the data's own loop where the points between its
 * chords span more than LOOP_NOISE x the noise figure (el__fit_noise_rms): noisy points
 * closer than their noise cross each other (31 points sketched along 82 mm with ~1 % noise:
 * 5 crossings, loops spanning 0.1-0.6 mm; a fit's chain of 10 loops passed for the data's
 * own, QA) */
#define LOOP_NOISE 4.0

int el__fit_loops(fit_objective *ob, const double *x)
{
    const int cross = el__fit_crosses_itself(ob, x);
    if (cross && !ob->points_cross) {
        const double span = LOOP_NOISE * el__fit_noise_rms(ob->xy, ob->n, ob->sc) * ob->sc;
        ob->points_cross = 1 + chords_cross(ob->xy, ob->n, chord_step(ob->n, POINT_CHORDS), span, NULL, 0.0);
    }
    return cross && ob->points_cross == 1;
}

int el__fit_wanders(fit_objective *ob, const double *x, int *strays, double noise, double *d, double *fs, double *tmp)
{
    if (el__fit_loops(ob, x)) return 1;
    if (*strays < 0) *strays = el__fit_strays_at(ob, x, noise, d, fs, tmp);
    return *strays;
}

/* a fit that crosses itself gives way to one at most this multiple of its objective (rms
 * 2 x) */
#define LOOP_GIVE 4.0

int el__fit_fair_over_loop(fit_objective *ob, const double *x, double f, int *strays,
                           const double *best_x, double best_f, int *best_loops, double noise,
                           double *d, double *fs, double *tmp)
{
    if (!(f < LOOP_GIVE * best_f)) return 0;
    if (*best_loops < 0) *best_loops = el__fit_loops(ob, best_x);
    return *best_loops && !el__fit_wanders(ob, x, strays, noise, d, fs, tmp);
}

/* The gap along the curve (feet fs in the order idx) that holds arc length m, named by
 * gap_index: the first before the first foot, the last beyond the last */
static long gap_at_length(const size_t *idx, size_t n, const double *fs, double m)
{
    size_t k = 0;
    while (k + 2 < n && !(m <= fs[idx[k + 1]])) k++;
    return gap_index(idx, k);
}

/* the crossings el__fit_wander_gap reports: each chord's ends off the other's line by more
 * than this of the data's size (the curve's points are evaluated to ~1e-13 of it) */
#define ROUNDING 1e-9

/* The distance of q from the polyline V (m vertices at arc lengths j ds) over the arcs
 * [a, b]: the segments that meet it. */
static double stretch_distance(const double *V, size_t m, double ds, double a, double b, const double *q)
{
    double best = HUGE_VAL;
    for (size_t j = 0; j + 1 < m; j++) {
        if ((double)(j + 1) * ds < a || (double)j * ds > b) continue;
        const double *A = V + 2 * j, ux = A[2] - A[0], uy = A[3] - A[1], u2 = ux * ux + uy * uy;
        const double t = u2 > 0.0 ? fit_clamp(((q[0] - A[0]) * ux + (q[1] - A[1]) * uy) / u2, 0.0, 1.0) : 0.0;
        best = fmin(best, hypot(q[0] - A[0] - t * ux, q[1] - A[1] - t * uy));
    }
    return best;
}

/* The distance of q from the polyline V (as stretch_distance's) over the arc lengths [a, b]
 * exactly (its segments cut there), the arc length where it is nearest in *at, and the
 * farthest q is from V between *at and c (V's vertices and those two places) in *far */
static double nearest_arc(const double *V, size_t m, double ds, double a, double b, const double *q, double c,
                          double *at, double *far)
{
    double best = HUGE_VAL;
    *at = a;
    for (size_t j = 0; j + 1 < m; j++) {
        const double s0 = (double)j * ds, lo = fmax(0.0, (a - s0) / ds), hi = fmin(1.0, (b - s0) / ds);
        if (!(lo <= hi)) continue;
        const double *A = V + 2 * j, ux = A[2] - A[0], uy = A[3] - A[1], u2 = ux * ux + uy * uy;
        const double t = u2 > 0.0 ? fit_clamp(((q[0] - A[0]) * ux + (q[1] - A[1]) * uy) / u2, lo, hi) : lo;
        const double d = hypot(q[0] - A[0] - t * ux, q[1] - A[1] - t * uy);
        if (d < best) { best = d; *at = s0 + t * ds; }
    }
    const double lo = fmin(*at, c), hi = fmax(*at, c);
    *far = 0.0;
    for (size_t j = 0; j < m; j++) {
        const double sj = (double)j * ds;
        if (sj >= lo && sj <= hi) *far = fmax(*far, hypot(q[0] - V[2 * j], q[1] - V[2 * j + 1]));
    }
    *far = fmax(*far, fmax(best, stretch_distance(V, m, ds, c, c, q)));
    return best;
}

/* The point of the polyline V (as stretch_distance's) at arc length f, clamped to it */
static void polyline_at(const double *V, size_t m, double ds, double f, double *G)
{
    const double t = fit_clamp(f / ds, 0.0, (double)(m - 1));
    const size_t j = t >= (double)(m - 1) ? m - 2 : (size_t)t;
    G[0] = V[2 * j] + (t - (double)j) * (V[2 * j + 2] - V[2 * j]);
    G[1] = V[2 * j + 1] + (t - (double)j) * (V[2 * j + 3] - V[2 * j + 1]);
}

/* The distance of G from the segment A B */
static double segment_distance(const double *G, const double *A, const double *B)
{
    const double ux = B[0] - A[0], uy = B[1] - A[1], u2 = ux * ux + uy * uy;
    const double t = u2 > 0.0 ? fit_clamp(((G[0] - A[0]) * ux + (G[1] - A[1]) * uy) / u2, 0.0, 1.0) : 0.0;
    return hypot(G[0] - A[0] - t * ux, G[1] - A[1] - t * uy);
}

/* The farthest the polyline V goes from the segment A B over the arc lengths [a, b] (its
 * vertices there and its points at a and b) */
static double off_chord(const double *V, size_t m, double ds, double a, double b, const double *A, const double *B)
{
    double Ga[2], Gb[2];
    polyline_at(V, m, ds, a, Ga);
    polyline_at(V, m, ds, b, Gb);
    double far = fmax(segment_distance(Ga, A, B), segment_distance(Gb, A, B));
    for (size_t j = 0; j < m; j++)
        if ((double)j * ds > a && (double)j * ds < b) far = fmax(far, segment_distance(V + 2 * j, A, B));
    return far;
}

/* How much the polyline V (as stretch_distance's) turns over the arc lengths [a, b]: the
 * sum of |turn|s at its vertices there (sag_of_gap's measure on the samples it has) */
static double polyline_turn(const double *V, size_t m, double ds, double a, double b)
{
    double turn = 0.0;
    for (size_t j = 1; j + 1 < m; j++) {
        if (!((double)j * ds > a && (double)j * ds < b)) continue;
        const double *Q = V + 2 * j;
        turn += fabs(turn_between(atan2(Q[3] - Q[1], Q[2] - Q[0]), atan2(Q[1] - Q[-1], Q[0] - Q[-2])));
    }
    return turn;
}

/* |the turn| of the points' polygon at point i in the given order (0 at its ends) */
static double given_turn(const double *xy, size_t n, size_t i)
{
    if (i == 0 || i + 1 >= n) return 0.0;
    const double *P = xy + 2 * i - 2, *Q = xy + 2 * i, *R = xy + 2 * i + 2;
    return fabs(turn_between(atan2(R[1] - Q[1], R[0] - Q[0]), atan2(Q[1] - P[1], Q[0] - P[0])));
}

/* Whether the polyline V (as stretch_distance's) swings between points i and i + 1 over the
 * arc lengths between a and b by el__fit_gap_sag's measure (fit_internal.h): turning by more
 * than FIT_GAP_TURN beyond the points' polygon at the two and going farther than 4 noise
 * levels plus FIT_GAP_SAG of their chord from that chord */
static int swings_between(const double *xy, size_t n, size_t i, const double *V, size_t m, double ds, double a,
                          double b, double level)
{
    const double *p = xy + 2 * i, *q = p + 2, lo = fmin(a, b), hi = fmax(a, b);
    const double chord = hypot(q[0] - p[0], q[1] - p[1]);
    return polyline_turn(V, m, ds, lo, hi) - given_turn(xy, n, i) - given_turn(xy, n, i + 1) > FIT_GAP_TURN &&
           off_chord(V, m, ds, lo, hi, p, q) - 4.0 * level > FIT_GAP_SAG * chord;
}

/* A sketch's first gap i whose point i + 1 the curve passes before point i and not after
 * it as well: its foot behind point i's by more than half their distance and 8 noise levels
 * (far beyond noise's swap of close points: sketches drawn from a curve in order, noise
 * 0.1-1 %, swap by up to 4), and the curve between point i's foot and point i + 2's not
 * within twice its distance from the curve plus 4 noise levels (a point where a loop
 * crosses itself is near both passes) (QA: 8 clicks fitted at rms 0.14 in the order 0 1 5 4
 * 3 2 6 7, their feet 36.3, 33.3, 22.9, 22.1 along the curve from point 2 to 5, where the
 * sorted feet add no unaccounted length); -1 where none. V: the curve's polyline (m
 * vertices, ds apart). */
static long passed_back(const double *xy, size_t n, const double *fs, double level, const double *V, size_t m,
                        double ds)
{
    for (size_t i = 0; i + 1 < n; i++) {
        const double *q = xy + 2 * i + 2;
        const double chord = hypot(q[0] - xy[2 * i], q[1] - xy[2 * i + 1]);
        if (!(fs[i] - fs[i + 1] > fmax(0.5 * chord, 8.0 * level))) continue;
        const double here = stretch_distance(V, m, ds, 0.0, HUGE_VAL, q);
        /* (up to the first foot of a later point beyond point i's: where point i + 2 lies at
         * a crossing as well, its foot behind too, the next that is not) */
        size_t j = i + 2;
        while (j < n && !(fs[j] >= fs[i])) j++;
        double at_q, far_q;
        const double on = j == i + 2 ? stretch_distance(V, m, ds, fs[i], j < n ? fs[j] : HUGE_VAL, q)
                                     : nearest_arc(V, m, ds, fs[i], j < n ? fs[j] : HUGE_VAL, q, fs[i], &at_q, &far_q);
        /* (beyond point i + 2's foot, the curve on to point i + 1 not swinging, as below) */
        if (on <= 2.0 * here + 4.0 * level && (j == i + 2 || !swings_between(xy, n, i, V, m, ds, fs[i], at_q, level)))
            continue;
        /* the same rule for point i: where the curve passes point i between point i - 1's
         * foot and point i + 1's as well (within twice its distance plus 4 noise levels),
         * point i lies where a loop crosses itself, its foot on the later pass; the curve runs
         * in order from point i to i + 1 and nothing passes back (QA24 F13: 50 integer-pixel
         * clicks on a script loop, point 2 0.34 px from the later pass at s = 98.3 and 0.73
         * from the first at s = 3.2, before point 3's foot at 5.2, the two 2 px apart: named
         * "wanders between points 2 and 3") */
        const double *p = xy + 2 * i;
        const double own = stretch_distance(V, m, ds, 0.0, HUGE_VAL, p);
        const double a = i > 0 ? fs[i - 1] : 0.0, near = 2.0 * own + 4.0 * level;
        double at, far;
        /* ... a pass of its own: the curve goes farther than that from point i between it
         * and point i's foot (QA's 8 clicks in the order 0 1 5 4 3 2 6 7: point 5 is near the
         * curve at point 4's foot, 3 before its own, along one pass that nears it all the way) */
        const double before = nearest_arc(V, m, ds, a, fs[i + 1], p, fs[i], &at, &far);
        /* ... and that pass runs on to point i + 1 without swinging: from there to point
         * i + 1's foot it does not swing by el__fit_gap_sag's measure (fit_internal.h): turning
         * by more than FIT_GAP_TURN beyond the points' polygon at the two and going farther
         * than 4 noise levels plus FIT_GAP_SAG of their chord from that chord: the gap is then
         * an ordinary one, judged as any (the same 50 clicks: 0.71 px off the 2 px chord) */
        if (!(before <= near && far > near && !swings_between(xy, n, i, V, m, ds, at, fs[i + 1], level)))
            return (long)i;
    }
    return -1;
}

long el__fit_wander_gap(int model, const double *xy, size_t n, const double *p, const double *fs, double rms,
                        const double ends[4], const fit_seen *seen)
{
    double cx, cy, sc;
    if (seen && (seen->xy != xy || seen->n != n)) seen = NULL;    /* of other points */
    if (seen) sc = seen->sc;
    else if (n < 3 || el__fit_normalisation(xy, n, &cx, &cy, &sc)) return -1;
    const double noise = seen ? seen->noise : el__fit_noise_rms(xy, n, sc) * sc;
    /* a sketch's level (result_wanders, fit_follow.c), else the data's (fit.c's stray rule) */
    const double level = n < FIT_SKETCH_POINTS ? fmin(noise, rms) : noise;
    const double h = p[2], L = model == FIT_SMOOTH ? p[6] : (double)(n - 1) * h;
    long at = -1;
    /* the stray rule, unless the fit's found it follows its points at this level (no held
     * ends: they change the measure) */
    const int held = ends && (isfinite(ends[0]) || isfinite(ends[2]));
    if (!(seen && seen->follows && level == seen->noise && !held)) {
        double of_curve = -1.0;
        const double stray = stray_at(xy, n, fs, L, level, sc, ends, &at, &of_curve);
        if (stray > FIT_STRAY || of_curve > FIT_STRAY) return at;
        if (!(stray >= 0.0)) return -1;     /* out of memory */
    }
    /* more points than a sketch's: the stray rule alone, as the fit's (the crossing test's
     * 256 chords cost a 1000-point fit 40 %) */
    if (n >= FIT_SKETCH_POINTS) return -1;
    /* the curve's polygon: 256 chords of the smooth curve, the discrete one's vertices */
    const size_t m = model == FIT_SMOOTH ? CROSS_CHORDS + 1 : n;
    double *V = malloc(sizeof(double) * 2 * m);
    size_t loop[2];
    if (!V) return -1;
    int st;
    if (model == FIT_SMOOTH) {
        const el_smooth_params c = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        double s[CROSS_CHORDS + 1];
        for (size_t j = 0; j < m; j++) s[j] = L * (double)j / CROSS_CHORDS;
        st = el_smooth_eval(&c, m, s, V, NULL, NULL);
    } else {
        const el_discrete_params c = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        st = el_discrete_eval(&c, n, V);
    }
    /* a loop where the points' polygon has none (el__fit_loops): the gap of its middle;
     * else a sketch's swing between two points (el__fit_gap_sag) */
    const double ds = model == FIT_SMOOTH ? L / CROSS_CHORDS : h;
    at = -1;
    if (st) {
        /* a curve that cannot be evaluated: judged by its stray alone */
    } else if ((at = passed_back(xy, n, fs, level, V, m, ds)) >= 0) {
        /* points passed out of order */
    } else if (chords_cross(V, m, chord_step(m, CROSS_CHORDS), -1.0, loop, ROUNDING * sc) &&
               !chords_cross(xy, n, chord_step(n, POINT_CHORDS), LOOP_NOISE * noise, NULL, ROUNDING * sc)) {
        size_t *idx = malloc(sizeof *idx * n);
        if (idx && !el__fit_feet_order(fs, idx, n)) at = gap_at_length(idx, n, fs, 0.5 * (double)(loop[0] + loop[1]) * ds);
        free(idx);
    } else {
        if (model == FIT_SMOOTH) gap_sag_at(xy, n, fs, p, level, &at);
        else at = polygon_swing_gap(xy, n, fs, V, h, level);
    }
    free(V);
    return at;
}
