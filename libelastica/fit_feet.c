/*
 * Foot points and point-to-curve distances (fit_internal.h).
 *
 * Smooth: the foot of P on the curve is where T(s) . (gamma(s) - P) = 0; Newton's method
 * from the current foot, with derivative 1 + kappa N . (gamma - P) (bounded below, so a
 * point beyond the centre of curvature still moves the right way), the foot held in the
 * curve's range. For the keyline, sigma < 0 is the first curve at -sigma and sigma >= 0
 * the second: d gamma / d sigma = -T on the first, the second derivative kappa N on both,
 * so one Newton iteration serves the joined curve and a foot crosses the joint freely.
 * The polygon's distances: fit_polygon.c; the nearest point anywhere: fit_nearest.c. The
 * feet's order along the curve (el__fit_feet_order) at the end.
 * Signed distances: positive when the point lies left of the curve (its direction of
 * increasing s; for a keyline side, away from the joint).
 */
#include "fit_internal.h"
#include <gsl/gsl_sort.h>
#include <stdlib.h>
#include <string.h>

/* gamma, d gamma / d sigma and the curvature term at m feet sig (one block). */
typedef struct feet_block {
    double xy[2 * FIT_BLOCK], T[2 * FIT_BLOCK], kappa[FIT_BLOCK], dirs[FIT_BLOCK];
} feet_block;

static int feet_eval(const fit_objective *o, double v[2][FIT_NP], const double *sig, size_t m,
                     feet_block *b)
{
    double s[FIT_BLOCK], xy[2 * FIT_BLOCK], th[FIT_BLOCK], ka[FIT_BLOCK];
    size_t pos[FIT_BLOCK];
    const int nc = o->map.ncurves;
    for (int c = 0; c < nc; c++) {
        size_t cnt = 0;
        for (size_t i = 0; i < m; i++) {
            const int on_first = nc == 1 || sig[i] < 0.0;
            if (on_first != (c == 0)) continue;
            pos[cnt] = i;
            s[cnt++] = nc == 1 ? sig[i] : fabs(sig[i]);
        }
        if (cnt == 0) continue;
        el_smooth_params p;
        int st = el__fit_to_smooth(v[c], &p);
        if (st || (st = el_smooth_eval(&p, cnt, s, xy, th, ka))) return st ? st : EL_EDOM;
        const double dir = nc == 2 && c == 0 ? -1.0 : 1.0;
        for (size_t j = 0; j < cnt; j++) {
            const size_t i = pos[j];
            b->xy[2 * i] = xy[2 * j];
            b->xy[2 * i + 1] = xy[2 * j + 1];
            b->T[2 * i] = cos(th[j]);
            b->T[2 * i + 1] = sin(th[j]);
            b->kappa[i] = ka[j];
            b->dirs[i] = dir;
        }
    }
    return EL_OK;
}

/*
 * The feet sig[k] of the entries k in act[0 .. na-1] (entry k: the foot of point pt[k],
 * or of point k when pt is NULL) to the nearest points in [lo, hi], and when dist !=
 * NULL their signed distances dist[k] (+ = left of the curve's own direction). Newton's
 * method; once a step u is below 1e-7 of the range the foot is sigma + u and, with
 * gamma - P = t T + e N at sigma, the distance follows from
 *   gamma(sigma + u) - P = (t + u) T + (e + kappa u^2 / 2) N + O(u^3)
 * (exact for u = 0, a foot held at an end of the range), so the converged feet cost no
 * further evaluation. act (at most FIT_BLOCK entries) is overwritten.
 */
static int project_entries(const fit_objective *o, double v[2][FIT_NP], size_t *act, size_t na, const size_t *pt,
                           double *sig, double lo, double hi, double *dist)
{
    double cur[FIT_BLOCK];
    const double tol = 1e-7 * (hi - lo + 1e-300);
    feet_block b;
    for (int it = 0; it < FIT_NEWTON_MAX && na > 0; it++) {
        for (size_t i = 0; i < na; i++) cur[i] = sig[act[i]];
        int st = feet_eval(o, v, cur, na, &b);
        if (st) return st;
        const int last = it + 1 == FIT_NEWTON_MAX;
        size_t keep = 0;
        for (size_t i = 0; i < na; i++) {
            double P[2];
            fit_point(o, pt ? pt[act[i]] : act[i], P);
            const double dx = b.xy[2 * i] - P[0], dy = b.xy[2 * i + 1] - P[1];
            const double Tx = b.T[2 * i], Ty = b.T[2 * i + 1];
            const double t = b.dirs[i] * (Tx * dx + Ty * dy);     /* d/dsigma of |gamma - P|^2 / 2 */
            const double e = Tx * dy - Ty * dx;                    /* N . (gamma - P) */
            /* the last iteration keeps the foot where it is (u = 0) and writes its distance */
            const double u = last ? 0.0 : fit_clamp(cur[i] + fit_foot_step(t, e, b.kappa[i], hi - lo), lo, hi) - cur[i];
            sig[act[i]] = cur[i] + u;
            if (fabs(u) > tol) { act[keep++] = act[i]; continue; }
            if (dist) {
                const double p = t + u, q = e + 0.5 * b.kappa[i] * u * u;
                const double d = sqrt(p * p + q * q);
                dist[act[i]] = q > 0.0 ? -d : d;     /* N . (P - gamma) = -q: left of the curve's own direction */
            }
        }
        na = keep;
    }
    return EL_OK;
}

/* The feet sig[g] of the points g = a .. a+m-1 (m <= FIT_BLOCK), with keep_rest only
 * those whose dist[g] is NaN (project_entries). */
static int project_block(const fit_objective *o, double v[2][FIT_NP], size_t a, size_t m,
                         double *sig, double lo, double hi, double *dist, int keep_rest)
{
    size_t act[FIT_BLOCK], na = 0;
    for (size_t i = 0; i < m; i++)
        if (!keep_rest || isnan(dist[a + i])) act[na++] = a + i;
    return project_entries(o, v, act, na, NULL, sig, lo, hi, dist);
}

/* The feet's range: the curve over [0, L] (keyline: sigma in [-L1, L2]) for distances;
 * for the objective the curve extended by 5 % of its length at its ends, so that a
 * point a little beyond an end (noise around the first and last points) has a smooth
 * normal distance instead of a kink where its foot reaches the end (fit_objective.c);
 * but [0, L] for a constrained fit (o->exact_ends), whose points beyond an end count
 * their distance to that end (continuous, with its gradient, with the normal distance
 * as the foot reaches the end): its objective is then the distance reported. On the
 * extension a start tangent constrained away from the data's bent the extension onto
 * the first points (measured: rms 1.62 reported where 1.51 exists, found by SLSQP);
 * unconstrained fits end at the first and last points' feet, where the extension does
 * not matter, and converge faster with it (measured: a 1000-point uneven scan 2 x). */
void el__fit_feet_range(const fit_objective *o, double v[2][FIT_NP], int extended, double *lo, double *hi)
{
    const int ext = extended && !(o->map.ncurves == 1 && o->exact_ends);
    const double e = ext ? 1.05 : 1.0;
    *lo = o->map.ncurves == 2 ? -e * v[0][6] : (ext ? -0.05 * v[0][6] : 0.0);
    *hi = e * v[o->map.ncurves == 2 ? 1 : 0][6];
}

int el__fit_objective_project(fit_objective *o, const double *x)
{
    double v[2][FIT_NP], lo, hi;
    int st = el__fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    el__fit_feet_range(o, v, 1, &lo, &hi);
    /* the ends paired with the curve's keep their places (their residuals are full vectors) */
    const size_t first = fit_end_paired(o, 0), stop = o->n - fit_end_paired(o, o->n - 1);
    for (size_t a = first; a < stop; a += FIT_BLOCK) {
        const size_t m = stop - a < FIT_BLOCK ? stop - a : FIT_BLOCK;
        if ((st = project_block(o, v, a, m, o->s, lo, hi, NULL, 0))) return st;
    }
    el__fit_feet_range(o, v, 0, &lo, &hi);
    if (first) o->s[0] = lo;
    if (stop < o->n) o->s[o->n - 1] = hi;
    return EL_OK;
}

int el__fit_feet_distances(fit_objective *o, const double *x, double *dist, double *foot, int *side)
{
    double v[2][FIT_NP], lo, hi;
    int st = el__fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    el__fit_feet_range(o, v, 0, &lo, &hi);
    double *sig = o->s_next;
    /* the points the last evaluation, at this x, found at rest keep its distances and
     * feet (fit_objective.c) */
    const int keep = o->rest_ok && o->rest == dist && o->rest_foot == foot &&
                     !memcmp(o->rest_x, x, sizeof(double) * (size_t)o->map.nx);
    for (size_t i = 0; i < o->n; i++)
        sig[i] = keep && !isnan(dist[i]) ? foot[i] : fmin(fmax(o->s[i], lo), hi);
    for (size_t a = 0; a < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - a < FIT_BLOCK ? o->n - a : FIT_BLOCK;
        if ((st = project_block(o, v, a, m, sig, lo, hi, dist, keep))) return st;
    }
    o->rest_ok = 0;
    for (size_t i = 0; i < o->n; i++) {
        foot[i] = fabs(sig[i]);
        if (side) side[i] = o->map.ncurves == 2 && sig[i] >= 0.0;
    }
    return EL_OK;
}

/*
 * The smooth orthogonal fit's first feet for the curve at x: each where that curve comes
 * nearest (loops, sparse points: not always near the point's place), so the fit starts
 * from the curve's own point-to-curve distances and only improves on them; the
 * fractions' places t_i L if that search fails. Only the branch of each foot matters
 * here (the fit moves the feet by Newton steps at every evaluation and certifies them at
 * rest): the passes the curve's samples show (el__fit_feet_elsewhere; a pass it misses is
 * the refit's, fit.c), none sampled where a foot is proven the nearest point (an open
 * arc: el__fit_feet_unproven). The search everywhere took more on loops (measured on the 42
 * noisy 1000-point smooth curves of bench_fit.py: 428M instructions against 169M, one
 * loop's 20.3M against 5.6M); on open arcs the samples of every pass cost more than it
 * (2.0M against 3.1M), the proof less (whole fits of 45 open and looped arcs of 20 -
 * 5000 points against main's: none above +2 % but one spiral's +3.5 %).
 */
int el__fit_feet_start(fit_objective *o, const double *x)
{
    double v[2][FIT_NP];
    o->have_base = 0;
    int st = el__fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    for (size_t i = 0; i < o->n; i++) o->s[i] = o->t[i] * v[0][6];
    double *d = o->rest, *fs = o->rest_foot;    /* the report's arrays (fit_run) */
    o->rest_ok = 0;
    size_t moved;
    if (el__fit_feet_elsewhere(o, x, v, d, fs, &moved) == EL_OK) {
        memcpy(o->s, fs, sizeof(double) * o->n);
        if (fit_end_paired(o, 0)) o->s[0] = 0.0;
        if (fit_end_paired(o, o->n - 1)) o->s[o->n - 1] = v[0][6];
    }
    return EL_OK;
}

int el__fit_feet_project_list(const fit_objective *o, double v[2][FIT_NP], const size_t *pt, size_t m, double *sig,
                              double *dist)
{
    double lo, hi;
    el__fit_feet_range(o, v, 0, &lo, &hi);
    int st = EL_OK;
    size_t act[FIT_BLOCK];
    for (size_t a = 0; a < m && !st; a += FIT_BLOCK) {
        const size_t na = m - a < FIT_BLOCK ? m - a : FIT_BLOCK;
        for (size_t k = 0; k < na; k++) act[k] = a + k;
        st = project_entries(o, v, act, na, pt, sig, lo, hi, dist);
    }
    return st;
}

/* ---- the feet in order along the curve (the stray rule, the wander report: fit_wander.c) */

typedef struct { double foot; size_t index; } foot_index;

static int by_foot_then_index(const void *a, const void *b)
{
    const foot_index *x = a, *y = b;     /* a total order: a NaN foot after every number */
    if (x->foot < y->foot) return -1;
    if (x->foot > y->foot) return 1;
    if (isnan(x->foot) != isnan(y->foot)) return isnan(x->foot) ? 1 : -1;
    return (x->index > y->index) - (x->index < y->index);
}

static int by_index(const void *a, const void *b)
{
    const size_t x = *(const size_t *)a, y = *(const size_t *)b;
    return (x > y) - (x < y);
}

/* Header: by insertion, linear in n where the feet are in order but for a few (qsort
 * cost 4 % of a 1000-point smooth fit); past FEET_ORDER_MOVES moves a point (the feet
 * far out of order, insertion's n^2 / 4 moves: 10^6 noisy points, each foot among ~10^3
 * neighbours) by GSL's heapsort of the indices, in place, then each run of equal feet by
 * index: the same order as insertion's. (qsort on (foot, index) pairs took 16 bytes a
 * point and glibc's merge buffer as much: a 10^6-point smooth fit's peak 65 -> 88 MiB;
 * gsl_sort_index: none, and 255 against 307 ms there.) NaN feet, which neither
 * insertion's nor GSL's comparisons order, by the pairs: NaN last. */
#define FEET_ORDER_MOVES 32
#define FEET_PER_BUCKET 16
/* Insertion over the whole array first only up to this many moves a point, then the
 * buckets (the same order, either way): the feet of 1000 noisy points fitted paired (1 %
 * noise, 10 point spacings) pass it in 18 of bench_fit.py's 42 curves, and insertion's 32
 * moves a point spent before the buckets made el__fit_feet_order 0.21 M instructions of
 * el.fit's 5.15 M (the report's el__fit_wander_gap, every fit); now 0.09 M (callgrind) */
#define FEET_INSERTION_MOVES 4
/* Insertion of idx (n indices into fs) into the order of their feet, equal feet keeping
 * their order; stops past budget moves: whether it finished. */
static int insertion_within(const double *fs, size_t *idx, size_t n, size_t budget)
{
    size_t moves = 0;
    for (size_t k = 1; k < n && moves <= budget; k++) {
        const size_t t = idx[k];
        size_t j = k;
        for (; j > 0 && fs[idx[j - 1]] > fs[t]; j--) idx[j] = idx[j - 1];
        idx[j] = t;
        moves += k - j;
    }
    return moves <= budget;
}

/* The feet (no NaN) in n / FEET_PER_BUCKET buckets of equal arc length (their counts 0.5 MiB
 * for 10^6 points, below the fit's peak), each point's index placed in its
 * bucket in index order, then insertion within the buckets: linear where the feet spread
 * along the curve, as a fit's do (10^6 noisy points: the heapsort below was ~40 % of the
 * fit, and of the report of where it wanders), the same order as insertion's (equal feet
 * share a bucket, in index order). 1 where insertion passes budget moves (feet piled in
 * a few buckets) or out of memory: the caller sorts otherwise. */
static int bucket_order(const double *fs, size_t *idx, size_t n, size_t budget)
{
    double lo = fs[0], hi = fs[0];
    for (size_t k = 1; k < n; k++) { lo = fmin(lo, fs[k]); hi = fmax(hi, fs[k]); }
    if (!(hi > lo)) {
        for (size_t k = 0; k < n; k++) idx[k] = k;
        return 0;
    }
    const size_t nb = n / FEET_PER_BUCKET + 1;
    size_t *start = calloc(nb + 1, sizeof *start);
    if (!start) return 1;
    const double scale = (double)(nb - 1) / (hi - lo);
#define FOOT_BUCKET(k) ((size_t)fmin((double)(nb - 1), (fs[k] - lo) * scale))
    for (size_t k = 0; k < n; k++) start[FOOT_BUCKET(k) + 1]++;
    for (size_t b = 0; b < nb; b++) start[b + 1] += start[b];
    for (size_t k = 0; k < n; k++) idx[start[FOOT_BUCKET(k)]++] = k;
#undef FOOT_BUCKET
    free(start);
    return !insertion_within(fs, idx, n, budget);
}

int el__fit_feet_order(const double *fs, size_t *idx, size_t n)
{
    int any_nan = 0;
    for (size_t k = 0; k < n; k++) any_nan |= isnan(fs[k]);
    if (any_nan) {
        foot_index *pairs = malloc(sizeof *pairs * n);
        if (!pairs) return -1;
        for (size_t k = 0; k < n; k++) { pairs[k].foot = fs[k]; pairs[k].index = k; }
        qsort(pairs, n, sizeof *pairs, by_foot_then_index);
        for (size_t k = 0; k < n; k++) idx[k] = pairs[k].index;
        free(pairs);
        return 0;
    }
    const size_t budget = FEET_ORDER_MOVES * n;
    for (size_t k = 0; k < n; k++) idx[k] = k;
    if (insertion_within(fs, idx, n, FEET_INSERTION_MOVES * n)) return 0;
    if (!bucket_order(fs, idx, n, budget)) return 0;
    gsl_sort_index(idx, fs, 1, n);
    for (size_t a = 0, b; a < n; a = b) {
        for (b = a + 1; b < n && fs[idx[b]] == fs[idx[a]]; b++) {}
        if (b - a > 1) qsort(idx + a, b - a, sizeof *idx, by_index);
    }
    return 0;
}
