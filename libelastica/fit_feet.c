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

/* Newton's step for the foot, -t / (1 + kappa e) (gamma - P = t T + e N), with its
 * derivative bounded below (a point beyond the centre of curvature still moves the right
 * way) and the step to half the radius of curvature (or of the range): a foot stays on
 * its branch of a tight loop instead of jumping to another. */
double fit_foot_step(double t, double e, double kappa, double range)
{
    const double u = -t / fmax(1.0 + kappa * e, 0.25), lim = 0.5 / fmax(fabs(kappa), 1.0 / range);
    return fmin(fmax(u, -lim), lim);
}

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
 * The feet sig[g] (g = the points a .. a+m-1) to the nearest points in [lo, hi], and
 * when dist != NULL the signed distances (+ = left of the curve's own direction). Newton's method; once a step u is below 1e-7 of the range the foot is
 * sigma + u and, with gamma - P = t T + e N at sigma, the distance follows from
 *   gamma(sigma + u) - P = (t + u) T + (e + kappa u^2 / 2) N + O(u^3)
 * (exact for u = 0, a foot held at an end of the range), so the converged feet cost no
 * further evaluation.
 */
static int project_block(const fit_objective *o, double v[2][FIT_NP], size_t a, size_t m,
                         double *sig, double lo, double hi, double *dist)
{
    double cur[FIT_BLOCK];
    size_t act[FIT_BLOCK], na = m;
    for (size_t i = 0; i < m; i++) act[i] = a + i;
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
            point(o, act[i], P);
            const double dx = b.xy[2 * i] - P[0], dy = b.xy[2 * i + 1] - P[1];
            const double Tx = b.T[2 * i], Ty = b.T[2 * i + 1];
            const double t = b.dirs[i] * (Tx * dx + Ty * dy);     /* d/dsigma of |gamma - P|^2 / 2 */
            const double e = Tx * dy - Ty * dx;                    /* N . (gamma - P) */
            const double u = (last ? 0.0 : fmin(fmax(cur[i] + fit_foot_step(t, e, b.kappa[i], hi - lo), lo), hi)) - cur[i];
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

/* The feet's range: the curve over [0, L] (keyline: sigma in [-L1, L2]) for distances;
 * for the objective the curve extended by 5 % of its length at its ends, so that a
 * point a little beyond an end (noise around the first and last points) has a smooth
 * normal distance instead of a kink where its foot reaches the end (fit_objective.c). */
void fit_feet_range(const fit_objective *o, double v[2][FIT_NP], int extended, double *lo, double *hi)
{
    const double e = extended ? 1.05 : 1.0;
    *lo = o->map.ncurves == 2 ? -e * v[0][6] : (extended ? -0.05 * v[0][6] : 0.0);
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
        if ((st = project_block(o, v, a, m, o->s, lo, hi, NULL))) return st;
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
    for (size_t i = 0; i < o->n; i++) sig[i] = fmin(fmax(o->s[i], lo), hi);
    for (size_t a = 0; a < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - a < FIT_BLOCK ? o->n - a : FIT_BLOCK;
        if ((st = project_block(o, v, a, m, sig, lo, hi, dist))) return st;
    }
    for (size_t i = 0; i < o->n; i++) {
        foot[i] = fabs(sig[i]);
        if (side) side[i] = o->map.ncurves == 2 && sig[i] >= 0.0;
    }
    return EL_OK;
}

/* Distance of P to segment A-B (direction of B - A): signed, and the fraction t. */
static double segment_distance(const double *A, const double *B, const double *P, double *t)
{
    const double ux = B[0] - A[0], uy = B[1] - A[1], l2 = ux * ux + uy * uy;
    double tt = l2 > 0.0 ? ((P[0] - A[0]) * ux + (P[1] - A[1]) * uy) / l2 : 0.0;
    tt = fmin(fmax(tt, 0.0), 1.0);
    const double fx = A[0] + tt * ux, fy = A[1] + tt * uy;
    const double d = hypot(P[0] - fx, P[1] - fy);
    *t = tt;
    return ux * (P[1] - fy) - uy * (P[0] - fx) < 0.0 ? -d : d;
}

/*
 * The polygon of nv vertices V (normalised), data point first + step j <-> vertex j:
 * each point's distance to the nearest segment, searched outwards from the segments at
 * its own vertex while the distance decreases (at least two segments each way), its
 * foot as arc length h (segment + t) from vertex 0.
 */
void fit_polygon_distances(const fit_objective *o, const double *V, size_t nv, double h,
                           size_t first, long step, double *dist, double *foot)
{
    const long last = (long)nv - 2;
    for (size_t j = 0; j < nv; j++) {
        const size_t g = (size_t)((long)first + step * (long)j);
        double P[2];
        point(o, g, P);
        long best = -1;
        double bd = HUGE_VAL, bs = 0.0, bt = 0.0;
        for (int dir = -1; dir <= 1; dir += 2) {
            double prev = HUGE_VAL;
            for (long seg = dir < 0 ? (long)j - 1 : (long)j; seg >= 0 && seg <= last; seg += dir) {
                double t;
                const double d = segment_distance(V + 2 * seg, V + 2 * seg + 2, P, &t);
                if (fabs(d) < fabs(bd)) { bd = d; best = seg; bt = t; bs = d; }
                const long away = dir < 0 ? (long)j - 1 - seg : seg - (long)j;
                if (away >= 1 && fabs(d) >= prev) break;
                prev = fabs(d);
            }
        }
        if (best < 0) { dist[g] = 0.0; foot[g] = 0.0; continue; }
        dist[g] = bs;
        foot[g] = h * ((double)best + bt);
    }
}

/* ------------------------------------------------------------ the nearest point */

/*
 * The feet above are the nearest points near each point's place along the data (the
 * fit's own foot, or its vertex). A curve that passes close to itself (a loop) can come
 * nearer to a point somewhere else; the distance to the curve is the nearest of all.
 * The curves are cut into pieces of arc length l (about twice the median distance, at
 * least 1/512 of the length); every point of a piece lies within l/2 of the midpoint of
 * its end points (triangle inequality), so a piece can hold a nearer point only if that
 * disk comes within the point's distance. The disks go into a hash grid of cells of at
 * least their diameter; each point visits the cells its distance reaches, and only the
 * pieces away from its own foot whose disk is near enough are searched (Newton's method
 * from the piece's middle; the polygon's segments). O(n) work for ordinary data.
 */
enum { MAX_PIECES = 512, HASH_BITS = 13 };

typedef struct piece {
    double cx, cy, r, s0, s1;   /* disk, arc range on its curve */
    int curve;
} piece;

typedef struct grid {
    double cell;
    int head[1 << HASH_BITS];
    int next[8 * MAX_PIECES], item[8 * MAX_PIECES];
    int used;
} grid;

static unsigned cell_hash(long ix, long iy)
{
    const unsigned long h = (unsigned long)ix * 73856093UL ^ (unsigned long)iy * 19349663UL;
    return (unsigned)(h & ((1UL << HASH_BITS) - 1));
}

static void grid_add(grid *g, const piece *p, int id)
{
    const long x0 = (long)floor((p->cx - p->r) / g->cell), x1 = (long)floor((p->cx + p->r) / g->cell);
    const long y0 = (long)floor((p->cy - p->r) / g->cell), y1 = (long)floor((p->cy + p->r) / g->cell);
    for (long ix = x0; ix <= x1; ix++)
        for (long iy = y0; iy <= y1; iy++) {
            if (g->used >= 8 * MAX_PIECES) return;
            const unsigned h = cell_hash(ix, iy);
            g->item[g->used] = id;
            g->next[g->used] = g->head[h];
            g->head[h] = g->used++;
        }
}

/* A point of a curve at arc length s (smooth; discrete: along the polygon V). */
static int curve_point(const fit_objective *o, const double *v, const double *V, size_t nv, double s,
                       double *xy)
{
    if (o->map.model == FIT_SMOOTH) {
        el_smooth_params p;
        int st = fit_to_smooth(v, &p);
        return st ? st : el_smooth_eval(&p, 1, &s, xy, NULL, NULL);
    }
    const double h = v[2];
    size_t j = (size_t)fmin(fmax(floor(s / h), 0.0), (double)nv - 2.0);
    const double t = fmin(fmax(s / h - (double)j, 0.0), 1.0);
    xy[0] = V[2 * j] + t * (V[2 * j + 2] - V[2 * j]);
    xy[1] = V[2 * j + 1] + t * (V[2 * j + 3] - V[2 * j + 1]);
    return EL_OK;
}

/* The nearest point of piece p to P: signed distance (+ left of the curve's own
 * direction) and arc length. */
static int piece_nearest(const fit_objective *o, const double *v, const double *V, size_t nv,
                         const piece *p, const double *P, double *d, double *s)
{
    if (o->map.model == FIT_DISCRETE) {
        const double h = v[2];
        const long j0 = (long)floor(p->s0 / h), j1 = (long)ceil(p->s1 / h);
        double best = HUGE_VAL;
        for (long j = j0 < 0 ? 0 : j0; j < j1 && j <= (long)nv - 2; j++) {
            double t;
            const double dd = segment_distance(V + 2 * j, V + 2 * j + 2, P, &t);
            if (fabs(dd) < fabs(best)) { best = dd; *s = h * ((double)j + t); }
        }
        *d = best;
        return EL_OK;
    }
    el_smooth_params sp;
    int st = fit_to_smooth(v, &sp);
    if (st) return st;
    double u = 0.5 * (p->s0 + p->s1), xy[2], th = 0.0, ka = 0.0;
    for (int it = 0; it < NEWTON_MAX; it++) {
        if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, &ka))) return st;
        const double dx = xy[0] - P[0], dy = xy[1] - P[1], c = cos(th), sn = sin(th);
        const double step = fit_foot_step(c * dx + sn * dy, c * dy - sn * dx, ka, v[6]);
        const double un = fmin(fmax(u + step, 0.0), v[6]);
        if (fabs(un - u) <= 1e-14 * (v[6] + 1e-300)) { u = un; break; }
        u = un;
    }
    if ((st = el_smooth_eval(&sp, 1, &u, xy, &th, NULL))) return st;
    const double dx = P[0] - xy[0], dy = P[1] - xy[1];
    *d = cos(th) * dy - sin(th) * dx < 0.0 ? -hypot(dx, dy) : hypot(dx, dy);
    *s = u;
    return EL_OK;
}

/* Point i against piece p: searched when its disk comes nearer than the distance so far
 * and it is away from the point's own foot (whose neighbourhood was searched). */
typedef struct own_foot {
    int curve;
    double s;
} own_foot;

static int consider(const fit_objective *o, double v[2][FIT_NP], const double *V[2], const size_t nv[2],
                    const piece *p, const double *P, const own_foot *f0, size_t i, double *dist,
                    double *foot, int *side)
{
    if (hypot(P[0] - p->cx, P[1] - p->cy) - p->r >= fabs(dist[i])) return EL_OK;
    if (p->curve == f0->curve && p->s1 >= f0->s - 2.0 * p->r && p->s0 <= f0->s + 2.0 * p->r) return EL_OK;
    double d = HUGE_VAL, s = 0.0;
    int st = piece_nearest(o, v[p->curve], V[p->curve], nv[p->curve], p, P, &d, &s);
    if (!st && fabs(d) < fabs(dist[i])) {
        dist[i] = d; foot[i] = s;
        if (side) side[i] = p->curve;
    }
    return st;
}

int fit_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                           const size_t nv[2], double *dist, double *foot, int *side)
{
    const int nc = o->map.ncurves;
    const size_t n = o->n;
    double len[2] = {0.0, 0.0}, dmed = 0.0;
    for (int c = 0; c < nc; c++)
        len[c] = o->map.model == FIT_SMOOTH ? v[c][6] : v[c][2] * (double)(nv[c] - 1);
    {   /* a typical distance: the mean |d| of a spread sample */
        const size_t step = n > 1024 ? n / 1024 : 1;
        size_t cnt = 0;
        for (size_t i = 0; i < n; i += step, cnt++) dmed += fabs(dist[i]);
        dmed /= (double)cnt;
    }
    piece *pc = malloc(sizeof(piece) * 2 * MAX_PIECES);
    grid *g = malloc(sizeof(grid));
    unsigned *stamp = malloc(sizeof(unsigned) * 2 * MAX_PIECES);
    if (!pc || !g || !stamp) { free(pc); free(g); free(stamp); return EL_ENOMEM; }
    int np = 0, st = EL_OK;
    double rmax = 0.0;
    for (int c = 0; c < nc && !st; c++) {
        if (!(len[c] > 0.0)) continue;
        const int m = (int)fmin(fmax(ceil(len[c] / (2.0 * dmed + 1e-300)), 8.0), (double)MAX_PIECES);
        double a[2], b[2];
        if ((st = curve_point(o, v[c], V[c], nv[c], 0.0, a))) break;
        for (int j = 0; j < m; j++) {
            const double s0 = len[c] * j / m, s1 = len[c] * (j + 1) / m;
            if ((st = curve_point(o, v[c], V[c], nv[c], s1, b))) break;
            piece *p = &pc[np++];
            p->cx = 0.5 * (a[0] + b[0]); p->cy = 0.5 * (a[1] + b[1]);
            p->r = 0.5 * (s1 - s0); p->s0 = s0; p->s1 = s1; p->curve = c;
            rmax = fmax(rmax, p->r);
            a[0] = b[0]; a[1] = b[1];
        }
    }
    if (!st && np > 0) {
        memset(g->head, -1, sizeof g->head);
        g->used = 0;
        g->cell = fmax(2.0 * rmax, 2.0 * dmed);
        for (int j = 0; j < np; j++) { grid_add(g, &pc[j], j); stamp[j] = 0; }
        for (size_t i = 0; i < n && !st; i++) {
            double P[2];
            point(o, i, P);
            const double d0 = fabs(dist[i]);
            if (!(d0 > 0.0)) continue;
            const long x0 = (long)floor((P[0] - d0) / g->cell), x1 = (long)floor((P[0] + d0) / g->cell);
            const long y0 = (long)floor((P[1] - d0) / g->cell), y1 = (long)floor((P[1] + d0) / g->cell);
            const unsigned tag = (unsigned)i + 1u;
            const own_foot f0 = {side ? side[i] : 0, foot[i]};
            if ((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np) {   /* far: every piece */
                for (int j = 0; j < np && !st; j++) st = consider(o, v, V, nv, &pc[j], P, &f0, i, dist, foot, side);
                continue;
            }
            for (long ix = x0; ix <= x1 && !st; ix++)
                for (long iy = y0; iy <= y1 && !st; iy++)
                    for (int e = g->head[cell_hash(ix, iy)]; e >= 0 && !st; e = g->next[e]) {
                        const int j = g->item[e];
                        if (stamp[j] == tag) continue;
                        stamp[j] = tag;
                        st = consider(o, v, V, nv, &pc[j], P, &f0, i, dist, foot, side);
                    }
        }
    }
    free(pc); free(g); free(stamp);
    return st;
}
