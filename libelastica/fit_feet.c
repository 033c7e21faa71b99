/*
 * Foot points and point-to-curve distances (fit_internal.h).
 *
 * Smooth: the foot of P on the curve is where T(s) . (gamma(s) - P) = 0; Newton's method
 * from the current foot, with derivative 1 + kappa N . (gamma - P) (bounded below, so a
 * point beyond the centre of curvature still moves the right way), the foot held in the
 * curve's range. For the keyline, sigma < 0 is the first curve at -sigma and sigma >= 0
 * the second: d gamma / d sigma = -T on the first, the second derivative kappa N on both,
 * so one Newton iteration serves the joined curve and a foot crosses the joint freely.
 * Discrete: the nearest point of the polygon of the vertices, searched from the segments
 * at the point's own vertex outwards while the distance decreases.
 * Signed distances: positive when the point lies left of the curve (its direction of
 * increasing s; for a keyline side, away from the joint).
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

enum { NEWTON_MAX = 40 };

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
        int st = fit_to_smooth(v[c], &p);
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

static void point(const fit_objective *o, size_t i, double *P)
{
    P[0] = (o->xy[2 * i] - o->cx) / o->sc;
    P[1] = (o->xy[2 * i + 1] - o->cy) / o->sc;
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
    for (int it = 0; it < NEWTON_MAX && na > 0; it++) {
        for (size_t i = 0; i < na; i++) cur[i] = sig[act[i]];
        int st = feet_eval(o, v, cur, na, &b);
        if (st) return st;
        const int last = it + 1 == NEWTON_MAX;
        size_t keep = 0;
        for (size_t i = 0; i < na; i++) {
            double P[2];
            point(o, pt ? pt[act[i]] : act[i], P);
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
void fit_feet_range(const fit_objective *o, double v[2][FIT_NP], int extended, double *lo, double *hi)
{
    const int ext = extended && !(o->map.ncurves == 1 && o->exact_ends);
    const double e = ext ? 1.05 : 1.0;
    *lo = o->map.ncurves == 2 ? -e * v[0][6] : (ext ? -0.05 * v[0][6] : 0.0);
    *hi = e * v[o->map.ncurves == 2 ? 1 : 0][6];
}

int fit_objective_project(fit_objective *o, const double *x)
{
    double v[2][FIT_NP], lo, hi;
    int st = fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    fit_feet_range(o, v, 1, &lo, &hi);
    /* the ends keep their places (their residuals are full vectors) */
    for (size_t a = 1; a + 1 < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - 1 - a < FIT_BLOCK ? o->n - 1 - a : FIT_BLOCK;
        if ((st = project_block(o, v, a, m, o->s, lo, hi, NULL, 0))) return st;
    }
    fit_feet_range(o, v, 0, &lo, &hi);
    o->s[0] = lo;
    o->s[o->n - 1] = hi;
    return EL_OK;
}

int fit_feet_distances(fit_objective *o, const double *x, double *dist, double *foot, int *side)
{
    double v[2][FIT_NP], lo, hi;
    int st = fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    fit_feet_range(o, v, 0, &lo, &hi);
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
 * rest): the passes the curve's samples show (fit_feet_elsewhere; a pass it misses is
 * the refit's, fit.c), none sampled where a foot is proven the nearest point (an open
 * arc: fit_feet_unproven). The search everywhere took more on loops (measured on the 42
 * noisy 1000-point smooth curves of bench_fit.py: 428M instructions against 169M, one
 * loop's 20.3M against 5.6M); on open arcs the samples of every pass cost more than it
 * (2.0M against 3.1M), the proof less (whole fits of 45 open and looped arcs of 20 -
 * 5000 points against main's: none above +2 % but one spiral's +3.5 %).
 */
int fit_feet_start(fit_objective *o, const double *x)
{
    double v[2][FIT_NP];
    o->have_base = 0;
    int st = fit_map_eval(&o->map, x, v, NULL);
    if (st) return st;
    for (size_t i = 0; i < o->n; i++) o->s[i] = o->t[i] * v[0][6];
    double *d = o->rest, *fs = o->rest_foot;    /* the report's arrays (fit_run) */
    o->rest_ok = 0;
    size_t moved;
    if (fit_feet_elsewhere(o, x, v, d, fs, &moved) == EL_OK) {
        memcpy(o->s + 1, fs + 1, sizeof(double) * (o->n - 2));
        o->s[0] = 0.0;
        o->s[o->n - 1] = v[0][6];
    }
    return EL_OK;
}

int fit_feet_project_list(const fit_objective *o, double v[2][FIT_NP], const size_t *pt, size_t m, double *sig,
                          double *dist)
{
    double lo, hi;
    fit_feet_range(o, v, 0, &lo, &hi);
    int st = EL_OK;
    size_t act[FIT_BLOCK];
    for (size_t a = 0; a < m && !st; a += FIT_BLOCK) {
        const size_t na = m - a < FIT_BLOCK ? m - a : FIT_BLOCK;
        for (size_t k = 0; k < na; k++) act[k] = a + k;
        st = project_entries(o, v, act, na, pt, sig, lo, hi, dist);
    }
    return st;
}

/* Squared distance of P to segment A-B, and the fraction t of its nearest point.
 * (The clamp to [0, 1] by comparisons, NaN to 0 as fmin(fmax(t, 0), 1) does: the
 * report's hot loop, where libm's fmin/fmax are calls.) */
static inline double segment_distance2(const double *A, const double *B, const double *P, double *t)
{
    const double ux = B[0] - A[0], uy = B[1] - A[1], l2 = ux * ux + uy * uy;
    const double px = P[0] - A[0], py = P[1] - A[1];
    double tt = l2 > 0.0 ? (px * ux + py * uy) / l2 : 0.0;
    tt = tt > 0.0 ? (tt < 1.0 ? tt : 1.0) : 0.0;
    const double dx = px - tt * ux, dy = py - tt * uy;
    *t = tt;
    return dx * dx + dy * dy;
}

/* The signed distance (+ = left of A -> B) of P to the point of segment A-B at t. */
static double segment_signed(const double *A, const double *B, const double *P, double t)
{
    const double ux = B[0] - A[0], uy = B[1] - A[1];
    const double dx = P[0] - A[0] - t * ux, dy = P[1] - A[1] - t * uy;
    const double d = sqrt(dx * dx + dy * dy);
    return ux * dy - uy * dx < 0.0 ? -d : d;
}

/*
 * A bound that leaves out segments without changing any result: a segment A-B of
 * length at most lmax has no point nearer to P than |P - A| - lmax (triangle
 * inequality), so one with |P - A|^2 > beyond_sq(d, lmax) is farther than d by 1e-9 of
 * d + lmax, far beyond the rounding of segment_distance2 (~1e-15): its squared distance
 * would compare as larger than d^2, and leaving it out changes neither the nearest
 * segment nor the order in which ties are met.
 */
static inline double beyond_sq(double d, double lmax)
{
    const double r = (d + lmax) * (1.0 + 1e-9);
    return r * r;
}

static inline int segment_beyond(const double *A, const double *P, double r2)
{
    const double dx = P[0] - A[0], dy = P[1] - A[1];
    return dx * dx + dy * dy > r2;
}

/* The longest segment of the polygon of nv vertices (a bound for beyond_sq). */
static double longest_segment(const double *V, size_t nv)
{
    double l2 = 0.0;
    for (size_t j = 0; j + 1 < nv; j++) {
        const double ux = V[2 * j + 2] - V[2 * j], uy = V[2 * j + 3] - V[2 * j + 1], u2 = ux * ux + uy * uy;
        if (u2 > l2) l2 = u2;
    }
    return sqrt(l2) * (1.0 + 1e-12);
}

/*
 * The polygon of nv vertices V (normalised), data point first + step j <-> vertex j:
 * each point's distance to the polygon near its own vertex, its foot as arc length
 * h (segment + t) from vertex 0. A walk from the two segments at the vertex, on while
 * the nearest point of the last segment is its far end, finds a local minimum d; the
 * polygon has kinks, so every segment within arc length 2 sqrt 2 d + h of it is then
 * searched too (one segment each way where d kappa <= 0.1): where the polygon's
 * direction varies within pi/2 (fit_nearest_everywhere checks) no point farther along it
 * can be nearer than d (|V(s) - V(s')| >= cos(pi/4) |s - s'|), so this is the nearest
 * point; elsewhere that search goes on.
 */
void fit_polygon_distances(const fit_objective *o, const double *V, size_t nv, double h,
                           size_t first, long step, double *dist, double *foot)
{
    const long last = (long)nv - 2;
    /* the polygon's largest curvature, sin(turning) / h at its vertices: a point with
     * d kappa <= 0.1 has its distance growing away from the walk's foot, so one more
     * segment each way is enough (as for the smooth curve) */
    double kmax = 0.0;
    for (size_t j = 1; j + 1 < nv; j++) {
        const double ax = V[2 * j] - V[2 * j - 2], ay = V[2 * j + 1] - V[2 * j - 1];
        const double bx = V[2 * j + 2] - V[2 * j], by = V[2 * j + 3] - V[2 * j + 1];
        const double kj = fabs(ax * by - ay * bx) / (h * h * h);
        if (kj > kmax) kmax = kj;        /* fmax(kmax, kj): kmax is never NaN */
    }
    const double lmax = longest_segment(V, nv);
    for (size_t j = 0; j < nv; j++) {
        const size_t g = (size_t)((long)first + step * (long)j);
        double P[2];
        point(o, g, P);
        long best = -1;
        double bd = HUGE_VAL, bt = 0.0;
        /* start where the point projects along the polygon's direction at its vertex:
         * on dense polygons (spacing far below the noise) the foot lies many segments
         * from the point's own vertex */
        long j0 = (long)j;
        {
            const long a = (long)j < last ? (long)j : last;
            const double ux = V[2 * a + 2] - V[2 * a], uy = V[2 * a + 3] - V[2 * a + 1];
            const double along = ((P[0] - V[2 * j]) * ux + (P[1] - V[2 * j + 1]) * uy) / (h * h);
            if (fabs(along) > 1.0 && isfinite(along)) {
                const double jj = (double)j + along;
                j0 = jj < 0.0 ? 0 : jj > (double)(last + 1) ? last + 1 : (long)floor(jj);
            }
        }
        for (int dir = -1; dir <= 1; dir += 2) {
            for (long seg = dir < 0 ? j0 - 1 : j0; seg >= 0 && seg <= last; seg += dir) {
                double t;
                const double d2 = segment_distance2(V + 2 * seg, V + 2 * seg + 2, P, &t);
                if (d2 < bd) { bd = d2; best = seg; bt = t; }
                if (dir < 0 ? t > 0.0 : t < 1.0) break;     /* not at the far end: stop */
            }
        }
        if (best < 0) { dist[g] = 0.0; foot[g] = 0.0; continue; }
        /* the stretch around the foot, again around a nearer foot found in it (the
         * search for nearer points elsewhere, fit_nearest_everywhere, leaves out the
         * stretch around the final foot: it must have been searched; measured: a foot
         * moved 6 segments, its neighbour outside the first stretch 1.3 nearer) */
        for (long centre = -1; centre != best;) {
            centre = best;
            const double d = sqrt(bd);
            /* at most the whole polygon (a far point's d / h can pass the range of long) */
            const double span = ceil(2.0 * 1.4142135623730951 * d / h) + 1.0;
            const long reach = kmax * d <= 0.1 ? 1 : span <= (double)(last + 1) ? (long)span : last + 1;
            const long lo = centre - reach < 0 ? 0 : centre - reach, hi = centre + reach > last ? last : centre + reach;
            double r2 = beyond_sq(d, lmax);
            for (long seg = lo; seg <= hi; seg++) {
                if (segment_beyond(V + 2 * seg, P, r2)) continue;
                double t;
                const double d2 = segment_distance2(V + 2 * seg, V + 2 * seg + 2, P, &t);
                if (d2 < bd) { bd = d2; best = seg; bt = t; r2 = beyond_sq(sqrt(bd), lmax); }
            }
        }
        dist[g] = segment_signed(V + 2 * best, V + 2 * best + 2, P, bt);
        foot[g] = h * ((double)best + bt);
    }
}

/* ------------------------------------------------------------ the nearest point */

/*
 * The feet above are the nearest points near each point's place along the data (the
 * fit's own foot, or its vertex). A curve that passes close to itself (a loop) can come
 * nearer to a point somewhere else; the distance to the curve is the nearest of all.
 * The curves are cut into pieces of arc length l (about twice the median distance, at
 * least 1/128 of the length); every point of a piece lies within l/2 of the midpoint of
 * its end points (triangle inequality), so a piece can hold a nearer point only if that
 * disk comes within the point's distance. The disks go into a hash grid of cells of at
 * least their diameter; each point visits the cells its distance reaches, and only the
 * pieces away from its own foot whose disk is near enough are searched (Newton's method
 * from the piece's middle; the polygon's segments). O(n) work for ordinary data.
 */
enum { MAX_PIECES = 128, HASH_BITS = 11, SEP_LEVELS = 4 };
/* The grid's entries: a piece's disk (diameter 2 r <= cell, fit_nearest_everywhere) spans
 * 2 cells per axis, 3 when rounding of (c +- r) / cell crosses one more integer: at most 9
 * entries for each of the 2 MAX_PIECES pieces (grid_add reports more as EL_EINTERNAL) */
enum { GRID_ENTRIES = 9 * 2 * MAX_PIECES };

typedef struct piece {
    double cx, cy, r, s0, s1;   /* disk, arc range on its curve */
    double lmax;                /* polygon: its longest segment (beyond_sq) */
    int curve;
} piece;

typedef struct grid {
    double cell;
    int head[1 << HASH_BITS];
    int next[GRID_ENTRIES], item[GRID_ENTRIES];
    int used;
} grid;

/* The grid cell of coordinate x: floor(x / cell), held to +-2^40 (a far, diverging
 * curve gives quotients no long holds; the searches below then take every piece).
 * floor by the truncating conversion, which is exact within that range (libm's floor
 * is a call on baseline x86-64, four a point here); NaN gives -2^40 as before. */
static long cell_index(double x, double cell)
{
    const double q = x / cell, lim = 1099511627776.0;
    if (q >= -lim && q <= lim) {
        const long c = (long)q;
        return (double)c > q ? c - 1 : c;
    }
    return q > 0.0 ? (long)lim : -(long)lim;
}

static unsigned cell_hash(long ix, long iy)
{
    const unsigned long h = (unsigned long)ix * 73856093UL ^ (unsigned long)iy * 19349663UL;
    return (unsigned)(h & ((1UL << HASH_BITS) - 1));
}

/* 0: the grid is full (impossible by GRID_ENTRIES' bound; the caller's EL_EINTERNAL) */
static int grid_add(grid *g, const piece *p, int id)
{
    const long x0 = cell_index(p->cx - p->r, g->cell), x1 = cell_index(p->cx + p->r, g->cell);
    const long y0 = cell_index(p->cy - p->r, g->cell), y1 = cell_index(p->cy + p->r, g->cell);
    for (long ix = x0; ix <= x1; ix++)
        for (long iy = y0; iy <= y1; iy++) {
            if (g->used >= GRID_ENTRIES) return 0;
            const unsigned h = cell_hash(ix, iy);
            g->item[g->used] = id;
            g->next[g->used] = g->head[h];
            g->head[h] = g->used++;
        }
    return 1;
}

/* The points of a curve at arc lengths s_j = len j / m, j = 0..m (smooth: one
 * evaluation of the sorted samples; discrete: along the polygon V). */
static int curve_points(const fit_objective *o, const double *v, const double *V, size_t nv, double len,
                        int m, double *xy)
{
    double s[MAX_PIECES + 1];
    for (int j = 0; j <= m; j++) s[j] = len * j / m;
    if (o->map.model == FIT_SMOOTH) {
        el_smooth_params p;
        int st = fit_to_smooth(v, &p);
        return st ? st : el_smooth_eval(&p, (size_t)m + 1, s, xy, NULL, NULL);
    }
    const double h = v[2];
    for (int k = 0; k <= m; k++) {
        size_t j = (size_t)fmin(fmax(floor(s[k] / h), 0.0), (double)nv - 2.0);
        const double t = fmin(fmax(s[k] / h - (double)j, 0.0), 1.0);
        xy[2 * k] = V[2 * j] + t * (V[2 * j + 2] - V[2 * j]);
        xy[2 * k + 1] = V[2 * j + 1] + t * (V[2 * j + 3] - V[2 * j + 1]);
    }
    return EL_OK;
}

/* The nearest point of piece p to P: signed distance (+ left of the curve's own
 * direction) and arc length. The polygon's segments farther than the distance so far,
 * dnow, are left out (beyond_sq): the nearest of the others is the piece's nearest
 * whenever that is nearer than dnow (else *d may be HUGE_VAL, also not nearer). */
static int piece_nearest(const fit_objective *o, const double *v, const double *V, size_t nv,
                         const piece *p, const double *P, int branch_only, double dnow, double *d, double *s)
{
    if (o->map.model == FIT_DISCRETE) {
        const double h = v[2], r2 = beyond_sq(dnow, p->lmax);
        const long j0 = (long)floor(p->s0 / h), j1 = (long)ceil(p->s1 / h);
        double best = HUGE_VAL, bt = 0.0;
        long bj = -1;
        for (long j = j0 < 0 ? 0 : j0; j < j1 && j <= (long)nv - 2; j++) {
            if (segment_beyond(V + 2 * j, P, r2)) continue;
            double t;
            const double d2 = segment_distance2(V + 2 * j, V + 2 * j + 2, P, &t);
            if (d2 < best) { best = d2; bj = j; bt = t; }
        }
        if (bj < 0) { *d = HUGE_VAL; return EL_OK; }
        *d = segment_signed(V + 2 * bj, V + 2 * bj + 2, P, bt);
        *s = h * ((double)bj + bt);
        return EL_OK;
    }
    el_smooth_params sp;
    int st = fit_to_smooth(v, &sp);
    if (st) return st;
    double u = 0.5 * (p->s0 + p->s1), xy[2], th = 0.0, ka = 0.0;
    for (int it = 0; it < NEWTON_MAX; it++) {
        if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, &ka))) return st;
        const double dx = xy[0] - P[0], dy = xy[1] - P[1], c = cos(th), sn = sin(th);
        const double t = c * dx + sn * dy, e = c * dy - sn * dx;
        const double un = fmin(fmax(u + fit_foot_step(t, e, ka, v[6]), 0.0), v[6]), du = un - u;
        if (branch_only && fabs(du) <= 1e-7 * (v[6] + 1e-300)) {
            /* the distance at u + du to second order, as project_block's */
            const double a = t + du, b = e + 0.5 * ka * du * du, dist = sqrt(a * a + b * b);
            *d = b > 0.0 ? -dist : dist;
            *s = un;
            return EL_OK;
        }
        if (fabs(du) <= 1e-14 * (v[6] + 1e-300)) { u = un; break; }
        u = un;
    }
    if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, NULL))) return st;
    const double dx = P[0] - xy[0], dy = P[1] - xy[1];
    *d = cos(th) * dy - sin(th) * dx < 0.0 ? -hypot(dx, dy) : hypot(dx, dy);
    *s = u;
    return EL_OK;
}

/* Whether the disk of piece p comes nearer to P than d (the callers' test before
 * consider, inlined: most pieces a point visits are farther). */
static inline int disk_reaches(const piece *p, const double *P, double d)
{
    const double dx = P[0] - p->cx, dy = P[1] - p->cy, reach = d + p->r;
    return dx * dx + dy * dy < reach * reach;
}

/* Point i against piece p, whose disk comes nearer than the distance so far
 * (disk_reaches): searched when it is away from the point's own foot (whose
 * neighbourhood was searched). */
typedef struct own_foot {
    int curve;
    double s, d;
} own_foot;

static int consider(const fit_objective *o, double v[2][FIT_NP], const double *V[2], const size_t nv[2],
                    const piece *p, const double *P, const own_foot *f0, int branch_only, size_t i, double *dist,
                    double *foot, int *side)
{
    /* pieces already searched: smooth, those at the foot (the distance is convex there);
     * the polygon, those inside the stretch fit_polygon_distances searched */
    const double near = o->map.model == FIT_SMOOTH ? 2.0 * p->r : 2.0 * 1.4142135623730951 * f0->d;
    if (p->curve == f0->curve && (o->map.model == FIT_SMOOTH
                                  ? p->s1 >= f0->s - near && p->s0 <= f0->s + near
                                  : p->s0 >= f0->s - near && p->s1 <= f0->s + near)) return EL_OK;
    double d = HUGE_VAL, s = 0.0;
    int st = piece_nearest(o, v[p->curve], V[p->curve], nv[p->curve], p, P, branch_only, fabs(dist[i]), &d, &s);
    if (!st && fabs(d) < fabs(dist[i])) {
        dist[i] = d; foot[i] = s;
        if (side) side[i] = p->curve;
    }
    return st;
}

/*
 * When the search can be left out: a single curve whose tangent turns by at most pi/2
 * (so |gamma(s) - gamma(s')| >= cos(pi/4) |s - s'|: a point nearer than d to P lies
 * within arc length 2 sqrt 2 d of the foot found) and, smooth, whose curvature is at
 * most 0.1 / d for the largest distance d (the distance is convex along the curve over
 * that stretch: the foot found is the nearest point); the polygon's feet were searched
 * over that stretch (fit_polygon_distances).
 */
static int feet_are_nearest(const fit_objective *o, const double *v, const double *V, size_t nv,
                            const double *dist)
{
    if (o->map.ncurves != 1) return 0;
    double tmin = HUGE_VAL, tmax = -HUGE_VAL;
    if (o->map.model == FIT_DISCRETE) {
        /* the segments' directions, unwrapped; the span only grows, so the walk stops
         * once it exceeds pi/2 */
        double prev = 0.0;
        for (size_t j = 0; j + 1 < nv; j++) {
            double t = atan2(V[2 * j + 3] - V[2 * j + 1], V[2 * j + 2] - V[2 * j]);
            if (j > 0) t += 2.0 * M_PI * nearbyint((prev - t) / (2.0 * M_PI));
            prev = t;
            tmin = fmin(tmin, t); tmax = fmax(tmax, t);
            if (tmax - tmin > 0.5 * M_PI) return 0;
        }
        return tmax - tmin <= 0.5 * M_PI;
    }
    double dmax = 0.0, kmax = 0.0;
    for (size_t i = 0; i < o->n; i++) dmax = fmax(dmax, fabs(dist[i]));
    enum { M = 129 };
    double s[M], th[M], ka[M];
    el_smooth_params p;
    for (int j = 0; j < M; j++) s[j] = v[6] * j / (M - 1);
    if (fit_to_smooth(v, &p) || el_smooth_eval(&p, M, s, NULL, th, ka)) return 0;
    for (int j = 0; j < M; j++) {
        tmin = fmin(tmin, th[j]); tmax = fmax(tmax, th[j]);
        kmax = fmax(kmax, fabs(ka[j]));
    }
    /* between samples |kappa| may exceed its sampled maximum by one step's worth */
    kmax *= 1.5;
    return tmax - tmin <= 0.5 * M_PI && kmax * dmax <= 0.1;
}

int fit_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                           const size_t nv[2], int branch_only, double *dist, double *foot, int *side)
{
    const int nc = o->map.ncurves;
    const size_t n = o->n;
    if (feet_are_nearest(o, v[0], V[0], nv[0], dist)) return EL_OK;
    double len[2] = {0.0, 0.0}, dmed = 0.0;
    for (int c = 0; c < nc; c++)
        len[c] = o->map.model == FIT_SMOOTH ? v[c][6] : v[c][2] * (double)(nv[c] - 1);
    {   /* a typical distance: the mean |d| of a spread sample */
        const size_t step = n > 1024 ? n / 1024 : 1;
        size_t cnt = 0;
        for (size_t i = 0; i < n; i += step, cnt++) dmed += fabs(dist[i]);
        dmed /= (double)cnt;
    }
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++)
        if (fabs(dist[i]) > dmax) dmax = fabs(dist[i]);     /* fmax(dmax, |d|), not a call */
    piece *pc = malloc(sizeof(piece) * 2 * MAX_PIECES);
    grid *g = malloc(sizeof(grid));
    unsigned *stamp = malloc(sizeof(unsigned) * 2 * MAX_PIECES);
    double *sep = malloc(sizeof(double) * 2 * MAX_PIECES * SEP_LEVELS);
    if (!pc || !g || !stamp || !sep) { free(pc); free(g); free(stamp); free(sep); return EL_ENOMEM; }
    int np = 0, st = EL_OK, first[2] = {0, 0}, count[2] = {0, 0};
    double rmax = 0.0;
    for (int c = 0; c < nc && !st; c++) {
        first[c] = np;
        if (!(len[c] > 0.0)) continue;
        const int m = (int)fmin(fmax(ceil(len[c] / (2.0 * dmed + 1e-300)), 8.0), (double)MAX_PIECES);
        const double lmax = o->map.model == FIT_DISCRETE ? longest_segment(V[c], nv[c]) : 0.0;
        double ends[2 * (MAX_PIECES + 1)];
        if ((st = curve_points(o, v[c], V[c], nv[c], len[c], m, ends))) break;
        for (int j = 0; j < m; j++) {
            const double s0 = len[c] * j / m, s1 = len[c] * (j + 1) / m, *a = ends + 2 * j, *b = a + 2;
            piece *p = &pc[np++];
            p->cx = 0.5 * (a[0] + b[0]); p->cy = 0.5 * (a[1] + b[1]);
            p->r = 0.5 * (s1 - s0); p->s0 = s0; p->s1 = s1; p->curve = c; p->lmax = lmax;
            rmax = fmax(rmax, p->r);
        }
        count[c] = np - first[c];
    }
    if (!st && np > 0) {
        memset(g->head, -1, sizeof g->head);
        g->used = 0;
        /* cells of the reach of the pair test below: a piece then looks at 3 x 3 cells */
        g->cell = fmax(fmax(2.0 * rmax, 2.0 * dmed), 2.0 * dmax + 2.0 * rmax);
        for (int j = 0; j < np; j++) {
            if (!grid_add(g, &pc[j], j)) st = EL_EINTERNAL;
            stamp[j] = 0;
        }
        for (int j = 0; j < np * SEP_LEVELS; j++) sep[j] = 0.0;
        double reach_l[SEP_LEVELS];     /* 2 dmax / 2^l */
        reach_l[0] = 2.0 * dmax;
        for (int l = 1; l < SEP_LEVELS; l++) reach_l[l] = 0.5 * reach_l[l - 1];
        /* for each piece the farthest (in arc length) part of the curve that comes within
         * 2 dmax of it (another curve: HUGE_VAL): only a point whose foot is there and
         * whose own search (a stretch of 2 sqrt 2 d around its foot) did not reach that
         * part can have a nearer point elsewhere. (With the stretch of dmax for every
         * point, a point nearer than dmax missed a loop passing 5.7 from it, measured.)
         * The same within 2 dmax / 2^l, levels l = 1 .. SEP_LEVELS - 1 (sep[SEP_LEVELS j +
         * l]): a point at distance d0 can only have a nearer point within 2 d0 of its foot,
         * so it takes the level of the smallest reach still >= 2 d0 (the same argument,
         * with its own distance for the largest one: most points of an open arc then need
         * no search, as the parts within 2 d0 of their foot are next to it along the arc) */
        const unsigned ptag = 0x80000000u;
        for (int j = 0; j < np; j++) {
            const piece *p = &pc[j];
            const double R = 2.0 * dmax + p->r + rmax;
            const long x0 = cell_index(p->cx - R, g->cell), x1 = cell_index(p->cx + R, g->cell);
            const long y0 = cell_index(p->cy - R, g->cell), y1 = cell_index(p->cy + R, g->cell);
            const int all = (double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np;
            for (long ix = x0; ix <= x1; ix++)
                for (long iy = y0; iy <= y1; iy++)
                    for (int e = all ? 0 : g->head[cell_hash(ix, iy)]; all ? e < np : e >= 0; e = all ? e + 1 : g->next[e]) {
                        const int q = all ? e : g->item[e];
                        const piece *pq = &pc[q];
                        if (stamp[q] == (ptag | (unsigned)j)) continue;
                        stamp[q] = ptag | (unsigned)j;
                        const double dx = pq->cx - p->cx, dy = pq->cy - p->cy, dd = dx * dx + dy * dy;
                        const double a = pq->curve == p->curve ? fabs(0.5 * (pq->s0 + pq->s1 - p->s0 - p->s1)) : HUGE_VAL;
                        for (int l = 0; l < SEP_LEVELS; l++) {
                            const double reach = reach_l[l] + p->r + pq->r;
                            if (dd >= reach * reach) break;          /* and the smaller reaches */
                            double *sj = &sep[SEP_LEVELS * j + l], *sq = &sep[SEP_LEVELS * q + l];
                            if (a > *sj) *sj = a;      /* fmax: sep is never NaN */
                            if (a > *sq) *sq = a;
                        }
                    }
        }
        for (int j = 0; j < np; j++) stamp[j] = 0;
        for (size_t i = 0; i < n && !st; i++) {
            double P[2];
            point(o, i, P);
            const double d0 = fabs(dist[i]);
            if (!(d0 > 0.0)) continue;
            {   /* the foot's piece and its neighbours: near another part? */
                const int c = side ? side[i] : 0;
                if (count[c] == 0) continue;
                /* first[c] + floor(foot / piece length) held to the curve's pieces (NaN: 0) */
                const double at = foot[i] / (2.0 * pc[first[c]].r);
                const int jf = first[c] + (at > 0.0 ? (at < count[c] - 1.0 ? (int)at : count[c] - 1) : 0);
                const int lo = jf > first[c] ? jf - 1 : jf, hi = jf + 1 < first[c] + count[c] ? jf + 1 : jf;
                int any = 0, l = 0;
                while (l + 1 < SEP_LEVELS && reach_l[l + 1] >= 2.0 * d0) l++;
                for (int j = lo; j <= hi; j++) any |= sep[SEP_LEVELS * j + l] > 2.0 * 1.4142135623730951 * d0 + 4.0 * rmax;
                if (!any) continue;
            }
            const long x0 = cell_index(P[0] - d0, g->cell), x1 = cell_index(P[0] + d0, g->cell);
            const long y0 = cell_index(P[1] - d0, g->cell), y1 = cell_index(P[1] + d0, g->cell);
            const unsigned tag = (unsigned)i + 1u;
            const own_foot f0 = {side ? side[i] : 0, foot[i], d0};
            if ((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np) {   /* far: every piece */
                for (int j = 0; j < np && !st; j++)
                    if (disk_reaches(&pc[j], P, fabs(dist[i])))
                        st = consider(o, v, V, nv, &pc[j], P, &f0, branch_only, i, dist, foot, side);
                continue;
            }
            for (long ix = x0; ix <= x1 && !st; ix++)
                for (long iy = y0; iy <= y1 && !st; iy++)
                    for (int e = g->head[cell_hash(ix, iy)]; e >= 0 && !st; e = g->next[e]) {
                        const int j = g->item[e];
                        if (stamp[j] == tag) continue;
                        stamp[j] = tag;
                        if (disk_reaches(&pc[j], P, fabs(dist[i])))
                            st = consider(o, v, V, nv, &pc[j], P, &f0, branch_only, i, dist, foot, side);
                    }
        }
    }
    free(sep);
    free(pc); free(g); free(stamp);
    return st;
}
