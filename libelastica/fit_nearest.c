/*
 * Point-to-curve distances of the report (fit_internal.h): the discrete model's distance
 * of each point to the polygon of the vertices, searched from the segments at the
 * point's own vertex outwards while the distance decreases (el__fit_polygon_distances), and
 * for both models the nearest point anywhere on the curves (el__fit_nearest_everywhere: a
 * loop passing close to itself). Signed distances: positive when the point lies left of
 * the curve (its direction of increasing s; for a keyline side, away from the joint).
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

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

/* The reach of nearest_segment for the distance d and the longest segment lmax. */
static inline double reach_of(double d, double lmax) { return (d + lmax) * (1.0 + 1e-9); }

/*
 * The nearest of the segments j0 .. j1 - 1 of the polygon V to P when nearer than
 * sqrt(*bd) (the first of equal ones): *bd (squared), *bj, *bt updated. Segments are
 * left out without changing any result: one A-B of length at most lmax has no point
 * nearer to P than |P - A| - lmax (triangle inequality), so one with |P - A| beyond
 * *r = reach_of(sqrt(*bd), lmax) (the caller's first; it shrinks with *bd) is farther
 * than sqrt(*bd) by 1e-9 of it, far beyond the rounding of segment_distance2 (~1e-15):
 * its squared distance would compare as larger, and leaving it out changes neither the
 * nearest segment nor the order in which ties are met.
 */
static inline int beyond2(const double *A, const double *P, double r2);

static inline void nearest_in_block(const double *V, long j0, long j1, const double *P, double lmax, double *r,
                                    double *bd, long *bj, double *bt)
{
    double r2 = *r * *r;
    for (long j = j0; j < j1; j += 2) {
        /* segments j, j + 1 (held to j1); a pair beyond at the reach then is beyond at
         * the smaller reach after segment j too */
        const int far = beyond2(V + 2 * j, P, r2) | (j + 1 < j1 ? 0 : 2);
        if (far == 3) continue;
        for (long m = j; m < j + 2; m++) {
            if (far >> (m - j) & 1) continue;
            double t;
            const double d2 = segment_distance2(V + 2 * m, V + 2 * m + 2, P, &t);
            if (d2 < *bd) {
                *bd = d2; *bj = m; *bt = t;
                const double rn = reach_of(sqrt(d2), lmax);
                if (rn < *r) { *r = rn; r2 = rn * rn; }
            }
        }
    }
}

/* Bits 0 and 1: whether the vertices A and A + 2 lie beyond sqrt(r2) from P (both at
 * once where SSE2 has two lanes: the same products and sums as one at a time; NaN: not
 * beyond, as the scalar test). */
static inline int beyond2(const double *A, const double *P, double r2)
{
#if defined(__SSE2__)
    const __m128d p = _mm_loadu_pd(P), a = _mm_sub_pd(p, _mm_loadu_pd(A)), b = _mm_sub_pd(p, _mm_loadu_pd(A + 2));
    const __m128d a2 = _mm_mul_pd(a, a), b2 = _mm_mul_pd(b, b);
    return _mm_movemask_pd(_mm_cmpgt_pd(_mm_add_pd(_mm_unpacklo_pd(a2, b2), _mm_unpackhi_pd(a2, b2)), _mm_set1_pd(r2)));
#else
    const double ax = P[0] - A[0], ay = P[1] - A[1], bx = P[0] - A[2], by = P[1] - A[3];
    return (ax * ax + ay * ay > r2) | (bx * bx + by * by > r2) << 1;
#endif
}

/*
 * The same by blocks of BLOCK segments: a block whose first vertex lies beyond
 * *r + BLOCK lmax (by the octagon norm max(|x|, |y|, (|x| + |y|) / sqrt 2) <= |x|, no
 * square root) is left out whole, its vertices lying within (BLOCK - 1) lmax of that
 * one (dense polygons: 5000 points, 1950 -> 1700 us a fit). (Leaving out
 * (|P - A| - *r) / lmax segments at each vertex beyond: fewer instructions, 7 % more
 * time on 1000 points, the loop's next index waiting for that bound.)
 */
enum { BLOCK = 16 };
static inline void nearest_segment(const double *V, long j0, long j1, const double *P, double lmax, double *r,
                                   double *bd, long *bj, double *bt)
{
    for (long j = j0; j < j1; j += BLOCK) {
        const long e = j1 - j > BLOCK ? j + BLOCK : j1;
        if (e - j == BLOCK) {
            const double ax = fabs(P[0] - V[2 * j]), ay = fabs(P[1] - V[2 * j + 1]);
            const double m = ax > ay ? ax : ay, o = 0.7071067811865475 * (ax + ay);
            if ((m > o ? m : o) > *r + BLOCK * lmax) continue;
        }
        nearest_in_block(V, j, e, P, lmax, r, bd, bj, bt);
    }
}

/* The longest segment of the polygon of nv vertices (nearest_segment's lmax). */
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
 * searched too, or fewer where the polygon turns little (below): where the polygon's
 * direction varies within pi/2 (el__fit_nearest_everywhere checks) no point farther along it
 * can be nearer than d (|V(s) - V(s')| >= cos(pi/4) |s - s'|), so this is the nearest
 * point; elsewhere that search goes on.
 *
 * Fewer segments: along the polygon f(s) = |V(s) - P|^2 / 2 has f'' = 1 on a segment and
 * f' jumps by (v - P).(T' - T) at a vertex v (unit tangents T before, T' after), by at
 * most c l with c = |v - P| tmax / lmin (tmax the largest |T' - T|, lmin the shortest
 * segment l). With c < 1 at every vertex of the stretch (|v - P| <= d + its arc length
 * from the foot), f' at the segments' starts grows by at least (1 - c) lmin a segment,
 * from above -lmin at a local minimum's segment: local minima lie within
 * ceil(1 / (1 - c)) - 1 segments of each other, and f grows from them to the stretch's
 * ends; that many segments each way hold the stretch's nearest point (one for c <= 1/2).
 */
void el__fit_polygon_distances(const fit_objective *o, const double *V, size_t nv, double h,
                               size_t first, long step, double *dist, double *foot)
{
    const long last = (long)nv - 2;
    /* the polygon's largest turning |T' - T| at its vertices over its shortest segment
     * (the bound of the jumps of f' above; a zero-length or non-finite segment: NaN, so
     * that every stretch is searched whole) */
    double tmax = 0.0, lmin = HUGE_VAL, tx = 0.0, ty = 0.0;
    for (size_t j = 0; j + 1 < nv; j++) {
        const double ux = V[2 * j + 2] - V[2 * j], uy = V[2 * j + 3] - V[2 * j + 1], l = sqrt(ux * ux + uy * uy);
        const double nx = ux / l, ny = uy / l, t2 = (nx - tx) * (nx - tx) + (ny - ty) * (ny - ty);
        if (!(l > 0.0 && l < HUGE_VAL)) { tmax = NAN; break; }
        if (j > 0 && t2 > tmax) tmax = t2;
        if (l < lmin) lmin = l;
        tx = nx; ty = ny;
    }
    const double turn_per_length = sqrt(tmax) / lmin * (1.0 + 1e-9);
    const double lmax = longest_segment(V, nv);
    for (size_t j = 0; j < nv; j++) {
        const size_t g = (size_t)((long)first + step * (long)j);
        double P[2];
        fit_point(o, g, P);
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
        long clo = j0, chi = j0 - 1;     /* the segments searched so far, clo .. chi */
        for (int dir = -1; dir <= 1; dir += 2) {
            for (long seg = dir < 0 ? j0 - 1 : j0; seg >= 0 && seg <= last; seg += dir) {
                double t;
                const double d2 = segment_distance2(V + 2 * seg, V + 2 * seg + 2, P, &t);
                if (dir < 0) clo = seg; else chi = seg;
                if (d2 < bd) { bd = d2; best = seg; bt = t; }
                if (dir < 0 ? t > 0.0 : t < 1.0) break;     /* not at the far end: stop */
            }
        }
        if (best < 0) { dist[g] = 0.0; foot[g] = 0.0; continue; }
        /* the stretch around the foot, again around a nearer foot found in it (the
         * search for nearer points elsewhere, el__fit_nearest_everywhere, leaves out the
         * stretch around the final foot: it must have been searched; measured: a foot
         * moved 6 segments, its neighbour outside the first stretch 1.3 nearer). The
         * segments searched already (clo .. chi, around the foot) cannot come strictly
         * nearer than it: left out. */
        for (long centre = -1; centre != best;) {
            centre = best;
            const double d = sqrt(bd);
            /* at most the whole polygon (a far point's d / h can pass the range of long) */
            const double span = ceil(2.0 * 1.4142135623730951 * d / h) + 1.0;
            const double c = turn_per_length * (d + (span + 1.0) * lmax);
            const double few = c < 1.0 ? ceil(1.0 / (1.0 - c)) - 1.0 : HUGE_VAL, m = few < span ? few : span;
            const long reach = m >= 1.0 ? (m <= (double)(last + 1) ? (long)m : last + 1) : 1;
            const long lo = centre - reach < 0 ? 0 : centre - reach, hi = centre + reach > last ? last : centre + reach;
            double r = reach_of(d, lmax);
            nearest_segment(V, lo, hi < clo ? hi + 1 : clo, P, lmax, &r, &bd, &best, &bt);
            nearest_segment(V, lo > chi ? lo : chi + 1, hi + 1, P, lmax, &r, &bd, &best, &bt);
            if (lo < clo) clo = lo;
            if (hi > chi) chi = hi;
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
 * Smooth curves (the polygons': polygon_nearest_everywhere below) are cut into pieces of arc length l (about twice the median distance, at
 * least 1/128 of the length); every point of a piece lies within l/2 of the midpoint of
 * its end points (triangle inequality), so a piece can hold a nearer point only if that
 * disk comes within the point's distance. The disks go into a hash grid of cells of at
 * least their diameter; each point visits the cells its distance reaches, and only the
 * pieces away from its own foot whose disk is near enough are searched (Newton's method
 * from the piece's middle). O(n) work for ordinary data.
 */
enum { MAX_PIECES = 128, HASH_BITS = 11, SEP_LEVELS = 4 };
/* The grid's entries: a piece's disk (diameter 2 r <= cell, el__fit_nearest_everywhere) spans
 * 2 cells per axis, 3 when rounding of (c +- r) / cell crosses one more integer: at most 9
 * entries for each of the 2 MAX_PIECES pieces (grid_add reports more as EL_EINTERNAL) */
enum { GRID_ENTRIES = 9 * 2 * MAX_PIECES };

typedef struct piece {
    double cx, cy, r, s0, s1;   /* disk, arc range on its curve */
    int curve;
} piece;

typedef struct grid {
    double cell;
    int head[1 << HASH_BITS];
    int next[GRID_ENTRIES], item[GRID_ENTRIES];
    int used;
} grid;

/* The grid cell of coordinate x from q = x / cell (polygons: x times 1 / cell, monotone
 * too): floor(q) by the truncating conversion, exact within +-2^40, where it is held (a
 * far, diverging curve gives quotients no long holds; the searches below then take
 * every piece; libm's floor is a call on baseline x86-64); NaN gives -2^40. */
static long cell_index(double q)
{
    const double lim = 1099511627776.0;
    if (q >= -lim && q <= lim) {
        const long c = (long)q;
        return (double)c > q ? c - 1 : c;
    }
    return q > 0.0 ? (long)lim : -(long)lim;
}

/* The bucket of cell (ix, iy) among mask + 1 (a power of two) */
static size_t cell_hash(long ix, long iy, size_t mask)
{
    const unsigned long h = (unsigned long)ix * 73856093UL ^ (unsigned long)iy * 19349663UL;
    return (size_t)(h & mask);
}

/* 0: the grid is full (impossible by GRID_ENTRIES' bound; the caller's EL_EINTERNAL) */
static int grid_add(grid *g, const piece *p, int id)
{
    const long x0 = cell_index((p->cx - p->r) / g->cell), x1 = cell_index((p->cx + p->r) / g->cell);
    const long y0 = cell_index((p->cy - p->r) / g->cell), y1 = cell_index((p->cy + p->r) / g->cell);
    for (long ix = x0; ix <= x1; ix++)
        for (long iy = y0; iy <= y1; iy++) {
            if (g->used >= GRID_ENTRIES) return 0;
            const size_t h = cell_hash(ix, iy, (1UL << HASH_BITS) - 1);
            g->item[g->used] = id;
            g->next[g->used] = g->head[h];
            g->head[h] = g->used++;
        }
    return 1;
}

/* The points of a smooth curve at arc lengths s_j = len j / m, j = 0..m (one
 * evaluation of the sorted samples). */
static int curve_points(const double *v, double len, int m, double *xy)
{
    double s[MAX_PIECES + 1];
    for (int j = 0; j <= m; j++) s[j] = len * j / m;
    el_smooth_params p;
    int st = el__fit_to_smooth(v, &p);
    return st ? st : el_smooth_eval(&p, (size_t)m + 1, s, xy, NULL, NULL);
}

/* The bound of |kappa| on the smooth curve v: 2 |k| sqrt(mu) (seed 000 (4.3); v[3] = +-sqrt(mu)). */
static double kappa_bound(const double *v) { return 2.0 * fabs(v[4] * v[3]); }

/* Newton's method for the nearest point of a smooth curve (parameters v) to P from arc
 * length u: signed distance (+ left of the curve's own direction) and arc length. */
static int newton_nearest(const double *v, double u, double lo, double hi, const double *P, double *d, double *s)
{
    el_smooth_params sp;
    int st = el__fit_to_smooth(v, &sp);
    if (st) return st;
    double xy[2], th = 0.0, ka = 0.0;
    for (int it = 0; it < FIT_NEWTON_MAX; it++) {
        if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, &ka))) return st;
        const double dx = xy[0] - P[0], dy = xy[1] - P[1], c = cos(th), sn = sin(th);
        const double t = c * dx + sn * dy, e = c * dy - sn * dx;
        const double un = fmin(fmax(u + fit_foot_step(t, e, ka, v[6]), lo), hi), du = un - u;
        if (fabs(du) <= 1e-14 * (v[6] + 1e-300)) { u = un; break; }
        u = un;
    }
    if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, NULL))) return st;
    const double dx = P[0] - xy[0], dy = P[1] - xy[1];
    *d = cos(th) * dy - sin(th) * dx < 0.0 ? -hypot(dx, dy) : hypot(dx, dy);
    *s = u;
    return EL_OK;
}

/* The nearest point of piece p of a smooth curve to P: Newton from its middle. */
static int piece_nearest(const double *v, const piece *p, const double *P, double *d, double *s)
{
    return newton_nearest(v, 0.5 * (p->s0 + p->s1), 0.0, v[6], P, d, s);
}

/*
 * Where the pieces' argument fails: the foot's neighbourhood is left out of the search
 * (consider) because the squared distance g(s) = |gamma(s) - P|^2 is convex there, and a
 * piece is searched by Newton from its middle, which finds its one local minimum. Both
 * hold where g'' = 2 (1 - kappa (P - gamma).N) > 0 for the parts of the curve within the
 * point's distance d0, which |kappa| <= kappa_max = 2 |k| sqrt(mu) guarantees when
 * kappa_max d0 < 1. A point farther from a tight loop than its radius of curvature (noise
 * the size of the loop) can have a nearer point next to its foot, or two minima in one
 * piece (measured: 329 of 9600 points, up to 0.2 % of the length too far). So pieces
 * that turn by more than 1/2 (kappa_max times their length), and every piece within reach
 * of a point with kappa_max d0 > DENSE_KD (the per-point test for a search elsewhere
 * left out, the foot's neighbourhood searched too), are searched on samples of the
 * curve spaced so that the tangent turns by at most 0.1 between them (dense_nearest).
 */
enum { DENSE_MAX = 1 << 14 };
#define DENSE_KD 0.25   /* kappa_max d above which a point's search is dense_nearest's */

typedef struct dense_samples {
    int curve;
    size_t m;        /* samples s_j = len j / (m - 1) */
    double len, kmax, *xy, *tan;   /* points, unit tangents */
} dense_samples;

static int dense_init(const double *v, int curve, dense_samples *ds)
{
    const double len = v[6], kmax = kappa_bound(v);
    const double want = ceil(len * kmax / 0.1) + 2.0;
    ds->curve = curve;
    ds->len = len;
    ds->m = want < 64.0 ? 64 : want > (double)DENSE_MAX ? DENSE_MAX : (size_t)want;
    ds->kmax = kmax;
    ds->xy = malloc(2 * ds->m * sizeof *ds->xy);
    ds->tan = malloc(2 * ds->m * sizeof *ds->tan);
    double *s = malloc(2 * ds->m * sizeof *s), *th = s + ds->m;
    if (!ds->xy || !ds->tan || !s) { free(s); return EL_ENOMEM; }
    for (size_t j = 0; j < ds->m; j++) s[j] = len * (double)j / (double)(ds->m - 1);
    el_smooth_params sp;
    int st = el__fit_to_smooth(v, &sp);
    if (!st) st = el_smooth_eval(&sp, ds->m, s, ds->xy, th, NULL);
    for (size_t j = 0; j < ds->m && !st; j++) { ds->tan[2 * j] = cos(th[j]); ds->tan[2 * j + 1] = sin(th[j]); }
    free(s);
    return st;
}

static void dense_free(dense_samples *ds)
{
    free(ds->xy);
    free(ds->tan);
}

/* A lower bound of g = |gamma - P|^2 on [s_j - h, s_j + h] from sample j (g_j = d2):
 * g(s_j + t) >= g_j + 2 t (gamma_j - P).T_j + t^2 (1 - kappa_max rho) (Taylor's theorem
 * with g'' = 2 (1 - kappa (P - gamma).N) >= 2 (1 - kappa_max rho), rho = sqrt(g_j) + h
 * bounding |gamma - P| there), minimised over |t| <= h. */
static double dense_lower_bound(const dense_samples *ds, size_t j, double h, const double *P, double d2)
{
    const double a = (ds->xy[2 * j] - P[0]) * ds->tan[2 * j] + (ds->xy[2 * j + 1] - P[1]) * ds->tan[2 * j + 1];
    const double c = 1.0 - ds->kmax * (sqrt(d2) + h);
    const double lo = d2 - 2.0 * fabs(a) * h + c * h * h;        /* at t = -+h */
    if (c > 0.0 && fabs(a) < c * h) return d2 - a * a / c;       /* the vertex inside */
    return lo;
}

/* Point i against the samples of [s0, s1]: Newton's steps, held to the neighbouring
 * samples, from the local minima of the sampled distance whose interval can hold a
 * nearer point than the distance so far (a sample is at most h/2 farther than the
 * nearest point of its interval; then dense_lower_bound), except the foot's own: the
 * DENSE_TRIES nearest of them, nearest first, each tested again against the distance
 * the ones before reached (bounded work where the samples are coarse: many minima). */
enum { DENSE_TRIES = 8 };
static int dense_nearest(const double *v, dense_samples *ds, double s0, double s1, const double *P, size_t i,
                         double *dist, double *foot, int *side)
{
    const double h = ds->len / (double)(ds->m - 1), *C = ds->xy;
    /* the samples of [s0, s1] and one beyond each end (held to the curve; NaN: none) */
    const double a = floor(s0 / h) - 1.0, b = ceil(s1 / h) + 1.0, last = (double)(ds->m - 1);
    if (!(a <= b)) return EL_OK;
    const size_t j0 = a > 0.0 ? (a < last ? (size_t)a : ds->m - 1) : 0, j1 = b > 0.0 ? (b < last ? (size_t)b : ds->m - 1) : 0;
    size_t cj[DENSE_TRIES];
    double cd[DENSE_TRIES];
    int nc = 0;
    double d2[3] = {HUGE_VAL, 0.0, 0.0};    /* samples j - 1, j, j + 1 */
    d2[1] = (C[2 * j0] - P[0]) * (C[2 * j0] - P[0]) + (C[2 * j0 + 1] - P[1]) * (C[2 * j0 + 1] - P[1]);
    for (size_t j = j0; j <= j1; j++) {
        d2[2] = HUGE_VAL;
        if (j + 1 <= j1) {
            const double dx = C[2 * j + 2] - P[0], dy = C[2 * j + 3] - P[1];
            d2[2] = dx * dx + dy * dy;
        }
        const double lim = fabs(dist[i]) + 0.5 * h;
        const int inside = (j > j0 || j == 0) && (j < j1 || j == ds->m - 1);
        /* the foot found so far is its own interval's minimum */
        const int own = (side ? side[i] : 0) == ds->curve && fabs(h * (double)j - foot[i]) <= h;
        if (inside && !own && d2[1] <= d2[0] && d2[1] <= d2[2] && d2[1] < lim * lim &&
            (nc < DENSE_TRIES || d2[1] < cd[nc - 1])) {
            /* into the candidates, ascending (the last one out when full) */
            int k = nc < DENSE_TRIES ? nc++ : nc - 1;
            for (; k > 0 && cd[k - 1] > d2[1]; k--) { cd[k] = cd[k - 1]; cj[k] = cj[k - 1]; }
            cd[k] = d2[1];
            cj[k] = j;
        }
        d2[0] = d2[1];
        d2[1] = d2[2];
    }
    for (int k = 0; k < nc; k++) {
        if (!(dense_lower_bound(ds, cj[k], h, P, cd[k]) < dist[i] * dist[i])) continue;
        const double u = h * (double)cj[k];
        double d = HUGE_VAL, s = 0.0;
        const int st = newton_nearest(v, u, fmax(u - h, 0.0), fmin(u + h, ds->len), P, &d, &s);
        if (st) return st;
        if (fabs(d) < fabs(dist[i])) {
            dist[i] = d; foot[i] = s;
            if (side) side[i] = ds->curve;
        }
    }
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
    double s;
} own_foot;

static int consider(double v[2][FIT_NP], const piece *p, const double *P, const own_foot *f0, dense_samples *dense,
                    size_t i, double *dist, double *foot, int *side)
{
    /* a piece that turns by more than 1/2, or a point too far for its distance to be
     * convex along the curve: on the samples */
    const double kmax = kappa_bound(v[p->curve]);
    dense_samples *ds = dense[p->curve].xy && (kmax * 2.0 * p->r > 0.5 || kmax * fabs(dist[i]) > DENSE_KD)
                            ? &dense[p->curve] : NULL;
    /* pieces already searched: those at the foot (the distance is convex there) */
    const double near = 2.0 * p->r;
    if (!ds && p->curve == f0->curve && p->s1 >= f0->s - near && p->s0 <= f0->s + near) return EL_OK;
    if (ds) return dense_nearest(v[p->curve], ds, p->s0, p->s1, P, i, dist, foot, side);
    double d = HUGE_VAL, s = 0.0;
    int st = piece_nearest(v[p->curve], p, P, &d, &s);
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
 * over that stretch (el__fit_polygon_distances).
 */
static int feet_are_nearest(const fit_objective *o, const double *v, const double *V, size_t nv,
                            const double *dist)
{
    if (o->map.ncurves != 1) return 0;
    if (o->map.model == FIT_DISCRETE) {
        /* the segments' directions in a cone of at most pi/2, lo counter-clockwise to hi,
         * widened by a direction beyond either (cross products; consecutive directions
         * less than pi/2 apart, dot > 0, else not proved: a new one lies within pi of the
         * cone, so the signs tell its side) */
        double lo[2] = {0.0, 0.0}, hi[2] = {0.0, 0.0}, pr[2] = {0.0, 0.0};
        for (size_t j = 0; j + 1 < nv; j++) {
            const double u[2] = {V[2 * j + 2] - V[2 * j], V[2 * j + 3] - V[2 * j + 1]};
            if (j > 0) {
                if (!(pr[0] * u[0] + pr[1] * u[1] > 0.0)) return 0;
                if (hi[0] * u[1] - hi[1] * u[0] > 0.0) { hi[0] = u[0]; hi[1] = u[1]; }
                else if (lo[0] * u[1] - lo[1] * u[0] < 0.0) { lo[0] = u[0]; lo[1] = u[1]; }
                if (!(lo[0] * hi[1] - lo[1] * hi[0] >= 0.0 && lo[0] * hi[0] + lo[1] * hi[1] >= 0.0)) return 0;
            } else {
                lo[0] = hi[0] = u[0]; lo[1] = hi[1] = u[1];
            }
            pr[0] = u[0]; pr[1] = u[1];
        }
        return 1;
    }
    double dmax = 0.0, kmax = 0.0, tmin = HUGE_VAL, tmax = -HUGE_VAL;
    for (size_t i = 0; i < o->n; i++) dmax = fmax(dmax, fabs(dist[i]));
    enum { M = 129 };
    double s[M], th[M], ka[M];
    el_smooth_params p;
    for (int j = 0; j < M; j++) s[j] = v[6] * j / (M - 1);
    if (el__fit_to_smooth(v, &p) || el_smooth_eval(&p, M, s, NULL, th, ka)) return 0;
    for (int j = 0; j < M; j++) {
        tmin = fmin(tmin, th[j]); tmax = fmax(tmax, th[j]);
        kmax = fmax(kmax, fabs(ka[j]));
    }
    /* between samples |kappa| may exceed its sampled maximum by one step's worth */
    kmax *= 1.5;
    return tmax - tmin <= 0.5 * M_PI && kmax * dmax <= 0.1;
}

/* A typical distance: the mean |d| of a spread sample of the n distances. */
static double mean_distance(const double *dist, size_t n)
{
    const size_t step = n > 1024 ? n / 1024 : 1;
    size_t cnt = 0;
    double sum = 0.0;
    for (size_t i = 0; i < n; i += step, cnt++) sum += fabs(dist[i]);
    return sum / (double)cnt;
}

/*
 * The discrete model's search elsewhere (el__fit_nearest_everywhere): each point's own
 * search, el__fit_polygon_distances, covered the segments within arc length 2 sqrt 2 d of
 * its foot (or proved them farther, d kappa <= 0.1); every other segment that can come
 * nearer than d has its first vertex within d + lmax of the point (nearest_segment).
 * The polygons are cut into runs of consecutive segments whose first vertices share a
 * grid cell (of 8 max(mean |d|, lmax): a point's reach spans 1-2 cells per axis),
 * bucketed by a hash of the cell (counting sort); a point visits the cells within that
 * reach (every run when the cells outnumber the runs) and searches the runs there
 * outside its own stretch. Exact (tests/c/test_fit_nearest.c: against every segment);
 * O(n) for ordinary data.
 */
typedef struct polygon_query {
    const double *P;
    int own;                /* the point's curve, its stretch's segments x0 .. x1 - 1 */
    long x0, x1;
    double lmax, r, bd, bt; /* nearest_segment's; best: segment bj of curve bc */
    long bj;
    int bc;
} polygon_query;

/*
 * The direction of (x, y) in (-pi, pi] to within 2e-6 (tests/c/test_fit_nearest.c checks
 * it against atan2): Hastings' odd polynomial of degree 11 for atan on [0, 1] (error
 * 1.7e-6) after the reduction to the first octant. The windows below take a direction
 * per segment; libm's atan2 cost three times the rest of their work, and their proof
 * allows for the error.
 */
double el__fit_direction(double x, double y)
{
    const double ax = fabs(x), ay = fabs(y), mx = ax > ay ? ax : ay, mn = ax > ay ? ay : ax;
    const double a = mx > 0.0 ? mn / mx : 0.0, s = a * a;
    double r = a * (0.99997726 + s * (-0.33262347 + s * (0.19354346 + s * (-0.11643287 + s * (0.05265332 - 0.01172120 * s)))));
    if (ay > ax) r = 0.5 * M_PI - r;
    if (x < 0.0) r = M_PI - r;
    return y < 0.0 ? -r : r;
}

/*
 * The polygon's windows of direction: for each of its ns segments j, the last segment
 * j + fwd[j] and the first j - back[j] such that the directions of the segments from j
 * to there lie within an angle of pi/2. Along such a window a point at arc length D
 * from a foot F lies at least D cos(pi/4) from F (the chord is at least the arc times
 * the cosine of the largest angle to the middle direction), so one at D >= 2 sqrt 2 d,
 * outside the point's own stretch, is no nearer than d to a point at distance d from F:
 * the search elsewhere leaves the window out. The directions (el__fit_direction, within
 * 2e-6 each: the range is held to pi/2 - 1e-5) are unwrapped by the turning at each
 * vertex, taken in [-pi, pi] (a turning near pi, where that choice can err, ends every
 * window); a zero-length or non-finite segment ends every window too, and a window
 * spans at most WINDOW_MAX segments beyond its first and ends where a queue below is
 * full (shorter windows prove less, never wrongly). Two pointers with monotone queues
 * (rings) of the window's largest and smallest direction: O(ns) time, 4 bytes a
 * segment. 0: no memory.
 */
enum { WINDOW_MAX = 65535, WINDOW_RING = 65536 };
typedef struct dir_entry {
    long j;
    double th;
} dir_entry;

/* The direction of segment j of V; 0 when it has none (zero length, not finite: it is
 * measured again each time, as such a segment ends every window). */
static int segment_direction(const double *V, long j, double *dir)
{
    const double ux = V[2 * j + 2] - V[2 * j], uy = V[2 * j + 3] - V[2 * j + 1], u2 = ux * ux + uy * uy;
    if (!(u2 > 0.0 && u2 < HUGE_VAL)) return 0;
    *dir = el__fit_direction(ux, uy);
    return 1;
}

static int direction_windows(const double *V, long ns, unsigned short *fwd, unsigned short *back)
{
    const double aperture = 0.5 * M_PI - 1e-5;
    unsigned long ring = 1;
    while (ring < WINDOW_RING && ring < (unsigned long)ns + 1) ring *= 2;
    dir_entry *qmax = malloc(sizeof(dir_entry) * ring), *qmin = malloc(sizeof(dir_entry) * ring);
    if (!qmax || !qmin) { free(qmax); free(qmin); return 0; }
    const unsigned long mask = ring - 1;
    unsigned long h0 = 0, t0 = 0, h1 = 0, t1 = 0;  /* queue heads and tails, counted */
    long e = -1;                                    /* the window [j, e] */
    double raw = 0.0, th = 0.0;                     /* segment e's direction, and unwrapped */
    int next_ok = 0;                                /* segment e + 1's, once measured */
    double next = 0.0, next_th = 0.0;
    for (long j = 0; j < ns; j++) {
        if (e < j) {        /* a window from j alone */
            e = j;
            next_ok = 0;
            h0 = t0 = h1 = t1 = 0;
            if (!segment_direction(V, j, &raw)) { fwd[j] = 0; continue; }
            th = raw;
            qmax[t0++ & mask] = (dir_entry){j, th};
            qmin[t1++ & mask] = (dir_entry){j, th};
        }
        while (qmax[h0 & mask].j < j) h0++;
        while (qmin[h1 & mask].j < j) h1++;
        /* grow while the next segment keeps the directions' range within the aperture */
        while (e + 1 < ns && e + 1 - j <= WINDOW_MAX && t0 - h0 < ring && t1 - h1 < ring) {
            if (!next_ok) {
                if (!segment_direction(V, e + 1, &next)) break;
                const double turn = next - raw;
                next_th = th + (turn > M_PI ? turn - 2.0 * M_PI : turn < -M_PI ? turn + 2.0 * M_PI : turn);
                next_ok = 1;
            }
            const double t = next_th;
            const double hi = t > qmax[h0 & mask].th ? t : qmax[h0 & mask].th;
            const double lo = t < qmin[h1 & mask].th ? t : qmin[h1 & mask].th;
            if (!(hi - lo <= aperture)) break;
            e++;
            raw = next;
            th = t;
            next_ok = 0;
            while (t0 > h0 && qmax[(t0 - 1) & mask].th <= t) t0--;
            qmax[t0++ & mask] = (dir_entry){e, t};
            while (t1 > h1 && qmin[(t1 - 1) & mask].th >= t) t1--;
            qmin[t1++ & mask] = (dir_entry){e, t};
        }
        fwd[j] = (unsigned short)(e - j);
    }
    /* back: the first i whose window reaches j (the windows' ends grow with i) */
    for (long j = 0, i = 0; j < ns; j++) {
        while ((long)fwd[i] + i < j) i++;
        back[j] = (unsigned short)(j - i);
    }
    free(qmax); free(qmin);
    return 1;
}

/* The nearest segment of count runs ru (curve, first segment, end) to q->P, outside the
 * point's own stretch and its direction windows. */
static void search_runs(const double *V[2], const long *ru, size_t count, polygon_query *q)
{
    for (size_t e = 0; e < count; e++, ru += 3) {
        const int c = (int)ru[0];
        const long j0 = ru[1], j1 = ru[2];
        const double was = q->bd;
        /* the parts before and after the stretch (the whole run off the own curve) */
        const long x0 = c == q->own ? q->x0 : j1, x1 = c == q->own ? q->x1 : j1;
        nearest_segment(V[c], j0, j1 < x0 ? j1 : x0, q->P, q->lmax, &q->r, &q->bd, &q->bj, &q->bt);
        nearest_segment(V[c], j0 > x1 ? j0 : x1, j1, q->P, q->lmax, &q->r, &q->bd, &q->bj, &q->bt);
        if (q->bd < was) q->bc = c;
    }
}

static int polygon_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                                      const size_t nv[2], double *dist, double *foot, int *side)
{
    const int nc = o->map.ncurves;
    long ns[2] = {0, 0};           /* segments of each curve */
    double lmax = 0.0, inv_h[2] = {0.0, 0.0};
    for (int c = 0; c < nc; c++) {
        inv_h[c] = 1.0 / v[c][2];
        if (nv[c] < 2) continue;
        ns[c] = (long)nv[c] - 1;
        const double l = longest_segment(V[c], nv[c]);
        if (l > lmax) lmax = l;
    }
    const size_t nseg = (size_t)(ns[0] + ns[1]);
    if (nseg == 0) return EL_OK;
    const double inv = 1.0 / (8.0 * fmax(mean_distance(dist, o->n), lmax));      /* 1 / cell */
    size_t nb = 1;
    while (nb < nseg) nb *= 2;
    /* the runs (curve, first segment, end) in order, their buckets; then sorted by bucket */
    size_t *start = calloc(nb + 1, sizeof(size_t)), *key = malloc(sizeof(size_t) * nseg);
    long *run = malloc(sizeof(long) * 3 * nseg), *sorted = malloc(sizeof(long) * 3 * nseg);
    unsigned short *win = malloc(sizeof(unsigned short) * 2 * nseg), *fwd[2] = {win, win + 2 * ns[0]};
    int st = start && key && run && sorted && win ? EL_OK : EL_ENOMEM;
    for (int c = 0; c < nc && !st; c++)
        if (ns[c] > 0 && !direction_windows(V[c], ns[c], fwd[c], fwd[c] + ns[c])) st = EL_ENOMEM;
    if (st) { free(start); free(key); free(run); free(sorted); free(win); return st; }
    size_t nr = 0;
    for (int c = 0; c < nc; c++) {
        long ix = 0, iy = 0;
        for (long j = 0; j < ns[c]; j++) {
            const long jx = cell_index(V[c][2 * j] * inv), jy = cell_index(V[c][2 * j + 1] * inv);
            if (j > 0 && jx == ix && jy == iy) { run[3 * nr - 1]++; continue; }
            ix = jx; iy = jy;
            run[3 * nr] = c; run[3 * nr + 1] = j; run[3 * nr + 2] = j + 1;
            key[nr] = cell_hash(ix, iy, nb - 1);
            start[key[nr] + 1]++;
            nr++;
        }
    }
    for (size_t b = 0; b < nb; b++) start[b + 1] += start[b];
    for (size_t e = 0; e < nr; e++) memcpy(sorted + 3 * start[key[e]]++, run + 3 * e, sizeof(long) * 3);
    for (size_t b = nb; b > 0; b--) start[b] = start[b - 1];
    start[0] = 0;
    for (size_t i = 0; i < o->n; i++) {
        const double d0 = fabs(dist[i]);
        if (!(d0 > 0.0)) continue;
        double P[2];
        fit_point(o, i, P);
        polygon_query q = {P, side ? side[i] : 0, 0, 0, lmax, reach_of(d0, lmax), HUGE_VAL, 0.0, -1, 0};
        /* the stretch: segments j with j h >= foot - 2 sqrt 2 d and (j + 1) h <= foot + 2 sqrt 2 d
         * (to rounding: el__fit_polygon_distances searched a segment more each way), held to
         * the curve (NaN: none); ceil and floor of the non-negative bounds by truncation */
        const double span = 2.0 * 1.4142135623730951 * d0, top = (double)ns[q.own];
        double a = (foot[i] - span) * inv_h[q.own], b = (foot[i] + span) * inv_h[q.own];
        a = a > 0.0 ? (a < top ? a : top) : 0.0;
        b = b > 0.0 ? (b < top ? b : top) : 0.0;
        q.x0 = (long)a + ((double)(long)a < a);
        q.x1 = (long)b;
        /* and the direction windows of the foot's segment (one segment on either side, in
         * case the foot's rounding gave the neighbour) */
        if (ns[q.own] > 0 && isfinite(foot[i])) {
            const double u = foot[i] * inv_h[q.own];
            const long f = u > 0.0 ? (u < top - 1.0 ? (long)u : ns[q.own] - 1) : 0;
            const long flo = f > 0 ? f - 1 : 0, fhi = f + 1 < ns[q.own] ? f + 1 : f;
            const long w0 = fhi - (long)fwd[q.own][ns[q.own] + fhi], w1 = flo + (long)fwd[q.own][flo] + 1;
            if (w0 < q.x0) q.x0 = w0;
            if (w1 > q.x1) q.x1 = w1;
        }
        const long cx0 = cell_index((P[0] - q.r) * inv), cx1 = cell_index((P[0] + q.r) * inv);
        const long cy0 = cell_index((P[1] - q.r) * inv), cy1 = cell_index((P[1] + q.r) * inv);
        if ((double)(cx1 - cx0 + 1) * (double)(cy1 - cy0 + 1) > (double)nr) {
            search_runs(V, run, nr, &q);     /* far: every run */
        } else {
            for (long ix = cx0; ix <= cx1; ix++)
                for (long iy = cy0; iy <= cy1; iy++) {
                    const size_t bk = cell_hash(ix, iy, nb - 1);
                    search_runs(V, sorted + 3 * start[bk], start[bk + 1] - start[bk], &q);
                }
        }
        if (q.bj < 0) continue;
        const double d = segment_signed(V[q.bc] + 2 * q.bj, V[q.bc] + 2 * q.bj + 2, P, q.bt);
        if (fabs(d) < d0) {
            dist[i] = d;
            foot[i] = v[q.bc][2] * ((double)q.bj + q.bt);
            if (side) side[i] = q.bc;
        }
    }
    free(start); free(key); free(run); free(sorted); free(win);
    return EL_OK;
}

int el__fit_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                               const size_t nv[2], double *dist, double *foot, int *side)
{
    const int nc = o->map.ncurves;
    const size_t n = o->n;
    if (feet_are_nearest(o, v[0], V[0], nv[0], dist)) return EL_OK;
    if (o->map.model == FIT_DISCRETE) return polygon_nearest_everywhere(o, v, V, nv, dist, foot, side);
    const double len[2] = {v[0][6], nc > 1 ? v[1][6] : 0.0};
    const double dmed = mean_distance(dist, n);
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++)
        if (fabs(dist[i]) > dmax) dmax = fabs(dist[i]);     /* fmax(dmax, |d|), not a call */
    piece *pc = malloc(sizeof(piece) * 2 * MAX_PIECES);
    grid *g = malloc(sizeof(grid));
    unsigned *stamp = malloc(sizeof(unsigned) * 2 * MAX_PIECES);
    double *sep = malloc(sizeof(double) * 2 * MAX_PIECES * SEP_LEVELS);
    if (!pc || !g || !stamp || !sep) { free(pc); free(g); free(stamp); free(sep); return EL_ENOMEM; }
    int np = 0, st = EL_OK, first[2] = {0, 0}, count[2] = {0, 0};
    /* the curves a point may be too far from for the pieces' argument (dense_nearest) */
    dense_samples dense[2];
    memset(dense, 0, sizeof dense);
    double kmax[2] = {0.0, 0.0};
    double rmax = 0.0;
    for (int c = 0; c < nc && !st; c++) {
        first[c] = np;
        if (!(len[c] > 0.0)) continue;
        const int m = (int)fmin(fmax(ceil(len[c] / (2.0 * dmed + 1e-300)), 8.0), (double)MAX_PIECES);
        double ends[2 * (MAX_PIECES + 1)];
        if ((st = curve_points(v[c], len[c], m, ends))) break;
        for (int j = 0; j < m; j++) {
            const double s0 = len[c] * j / m, s1 = len[c] * (j + 1) / m, *a = ends + 2 * j, *b = a + 2;
            piece *p = &pc[np++];
            p->cx = 0.5 * (a[0] + b[0]); p->cy = 0.5 * (a[1] + b[1]);
            p->r = 0.5 * (s1 - s0); p->s0 = s0; p->s1 = s1; p->curve = c;
            rmax = fmax(rmax, p->r);
        }
        count[c] = np - first[c];
        /* points too far for the pieces' argument, or pieces that turn too much (dense_nearest) */
        kmax[c] = kappa_bound(v[c]);
        if (kmax[c] * dmax > DENSE_KD || kmax[c] * len[c] / m > 0.5) st = dense_init(v[c], c, &dense[c]);
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
            const long x0 = cell_index((p->cx - R) / g->cell), x1 = cell_index((p->cx + R) / g->cell);
            const long y0 = cell_index((p->cy - R) / g->cell), y1 = cell_index((p->cy + R) / g->cell);
            const int all = (double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np;
            for (long ix = x0; ix <= x1; ix++)
                for (long iy = y0; iy <= y1; iy++)
                    for (int e = all ? 0 : g->head[cell_hash(ix, iy, (1UL << HASH_BITS) - 1)]; all ? e < np : e >= 0; e = all ? e + 1 : g->next[e]) {
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
            fit_point(o, i, P);
            const double d0 = fabs(dist[i]);
            if (!(d0 > 0.0)) continue;
            const int c = side ? side[i] : 0;
            if (count[c] == 0) continue;
            if (!(dense[c].xy && kmax[c] * d0 > DENSE_KD)) {
                /* the foot's piece and its neighbours: near another part? (not asked where
                 * the point is too far for the distance's convexity: dense_nearest). A
                 * part at separation a from their middles has points within a + 4 rmax
                 * of the foot along the curve. */
                /* first[c] + floor(foot / piece length) held to the curve's pieces (NaN: 0) */
                const double at = foot[i] / (2.0 * pc[first[c]].r);
                const int jf = first[c] + (at > 0.0 ? (at < count[c] - 1.0 ? (int)at : count[c] - 1) : 0);
                const int lo = jf > first[c] ? jf - 1 : jf, hi = jf + 1 < first[c] + count[c] ? jf + 1 : jf;
                int any = 0, l = 0;
                while (l + 1 < SEP_LEVELS && reach_l[l + 1] >= 2.0 * d0) l++;
                for (int j = lo; j <= hi; j++) any |= sep[SEP_LEVELS * j + l] + 4.0 * rmax > 2.0 * 1.4142135623730951 * d0;
                if (!any) continue;
            }
            const long x0 = cell_index((P[0] - d0) / g->cell), x1 = cell_index((P[0] + d0) / g->cell);
            const long y0 = cell_index((P[1] - d0) / g->cell), y1 = cell_index((P[1] + d0) / g->cell);
            const unsigned tag = (unsigned)i + 1u;
            const own_foot f0 = {side ? side[i] : 0, foot[i]};
            if ((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np) {   /* far: every piece */
                for (int j = 0; j < np && !st; j++)
                    if (disk_reaches(&pc[j], P, fabs(dist[i])))
                        st = consider(v, &pc[j], P, &f0, dense, i, dist, foot, side);
                continue;
            }
            for (long ix = x0; ix <= x1 && !st; ix++)
                for (long iy = y0; iy <= y1 && !st; iy++)
                    for (int e = g->head[cell_hash(ix, iy, (1UL << HASH_BITS) - 1)]; e >= 0 && !st; e = g->next[e]) {
                        const int j = g->item[e];
                        if (stamp[j] == tag) continue;
                        stamp[j] = tag;
                        if (disk_reaches(&pc[j], P, fabs(dist[i])))
                            st = consider(v, &pc[j], P, &f0, dense, i, dist, foot, side);
                    }
        }
    }
    free(sep);
    free(pc); free(g); free(stamp);
    dense_free(&dense[0]); dense_free(&dense[1]);
    return st;
}
