/*
 * Point-to-curve distances of the report (fit_internal.h), the smooth curve's and the
 * dispatch: the nearest point anywhere on the curves (el__fit_nearest_everywhere: a loop
 * passing close to itself), left out where the curve turns too little to come back;
 * the polygon's searches are fit_polygon.c's. Signed distances: positive when the point
 * lies left of the curve (its direction of increasing s; for a keyline side, away from
 * the joint).
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

/*
 * The feet of el__fit_feet_distances and el__fit_polygon_distances are the nearest points
 * near each point's place along the data (the fit's own foot, or its vertex). A curve that
 * passes close to itself (a loop) can come nearer to a point somewhere else; the distance
 * to the curve is the nearest of all. Smooth curves (the polygons': fit_polygon.c) are cut
 * into pieces of arc length l (about twice the median distance, at least 1/128 of the
 * length); every point of a piece lies within l/2 of the midpoint of
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

/* 0: the grid is full (impossible by GRID_ENTRIES' bound; the caller's EL_EINTERNAL) */
static int grid_add(grid *g, const piece *p, int id)
{
    const long x0 = fit_cell_index((p->cx - p->r) / g->cell), x1 = fit_cell_index((p->cx + p->r) / g->cell);
    const long y0 = fit_cell_index((p->cy - p->r) / g->cell), y1 = fit_cell_index((p->cy + p->r) / g->cell);
    for (long ix = x0; ix <= x1; ix++)
        for (long iy = y0; iy <= y1; iy++) {
            if (g->used >= GRID_ENTRIES) return 0;
            const size_t h = fit_cell_hash(ix, iy, (1UL << HASH_BITS) - 1);
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

/* A smooth curve of the search (parameters v, the fit's) prepared for Newton's steps one
 * point at a time (el__smooth_point); st: el__fit_to_smooth's or el__smooth_prepare's
 * status, which each of its evaluations returns. */
typedef struct near_curve {
    el__smooth_curve c;         /* c.p.length: the curve's length, v[6] */
    int st;
} near_curve;

static void near_curve_init(const double *v, near_curve *nc)
{
    el_smooth_params p;
    memset(nc, 0, sizeof *nc);      /* c.p.length 0 where the curve is not one */
    nc->st = el__fit_to_smooth(v, &p);
    if (!nc->st) nc->st = el__smooth_prepare(&p, &nc->c);
}

/* Newton's method for the nearest point of a smooth curve to P from arc length u: signed
 * distance (+ left of the curve's own direction) and arc length. Each step one
 * el__smooth_point: el_smooth_eval's values at u bit for bit, at under half its cost for
 * one point (its set-up, the modulus and the base point, once per curve here). */
static int newton_nearest(const near_curve *nc, double u, double lo, double hi, const double *P, double *d, double *s)
{
    int st = nc->st;
    if (st) return st;
    double xy[2], th = 0.0, ka = 0.0;
    for (int it = 0; it < FIT_NEWTON_MAX; it++) {
        if ((st = el__smooth_point(&nc->c, u, xy, &th, &ka))) return st;
        const double dx = xy[0] - P[0], dy = xy[1] - P[1], c = cos(th), sn = sin(th);
        const double t = c * dx + sn * dy, e = c * dy - sn * dx;
        const double un = fmin(fmax(u + fit_foot_step(t, e, ka, nc->c.p.length), lo), hi), du = un - u;
        if (fabs(du) <= 1e-14 * (nc->c.p.length + 1e-300)) { u = un; break; }
        u = un;
    }
    if ((st = el__smooth_point(&nc->c, u, xy, &th, NULL))) return st;
    const double dx = P[0] - xy[0], dy = P[1] - xy[1];
    *d = cos(th) * dy - sin(th) * dx < 0.0 ? -hypot(dx, dy) : hypot(dx, dy);
    *s = u;
    return EL_OK;
}

/* The nearest point of piece p of a smooth curve to P: Newton from its middle. */
static int piece_nearest(const near_curve *nc, const piece *p, const double *P, double *d, double *s)
{
    return newton_nearest(nc, 0.5 * (p->s0 + p->s1), 0.0, nc->c.p.length, P, d, s);
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
static int dense_nearest(const near_curve *curve, dense_samples *ds, double s0, double s1, const double *P, size_t i,
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
        const int st = newton_nearest(curve, u, fmax(u - h, 0.0), fmin(u + h, ds->len), P, &d, &s);
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

static int consider(double v[2][FIT_NP], const near_curve *curves, const piece *p, const double *P,
                    const own_foot *f0, dense_samples *dense, size_t i, double *dist, double *foot, int *side)
{
    /* a piece that turns by more than 1/2, or a point too far for its distance to be
     * convex along the curve: on the samples */
    const double kmax = kappa_bound(v[p->curve]);
    dense_samples *ds = dense[p->curve].xy && (kmax * 2.0 * p->r > 0.5 || kmax * fabs(dist[i]) > DENSE_KD)
                            ? &dense[p->curve] : NULL;
    /* pieces already searched: those at the foot (the distance is convex there) */
    const double near = 2.0 * p->r;
    if (!ds && p->curve == f0->curve && p->s1 >= f0->s - near && p->s0 <= f0->s + near) return EL_OK;
    if (ds) return dense_nearest(&curves[p->curve], ds, p->s0, p->s1, P, i, dist, foot, side);
    double d = HUGE_VAL, s = 0.0;
    int st = piece_nearest(&curves[p->curve], p, P, &d, &s);
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

int el__fit_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                               const size_t nv[2], double *dist, double *foot, int *side)
{
    const int nc = o->map.ncurves;
    const size_t n = o->n;
    if (feet_are_nearest(o, v[0], V[0], nv[0], dist)) return EL_OK;
    if (o->map.model == FIT_DISCRETE) return el__fit_polygon_nearest_everywhere(o, v, V, nv, dist, foot, side);
    const double len[2] = {v[0][6], nc > 1 ? v[1][6] : 0.0};
    const double dmed = fit_mean_distance(dist, n);
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
    near_curve curves[2];
    for (int c = 0; c < nc && !st; c++) {
        first[c] = np;
        near_curve_init(v[c], &curves[c]);
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
            const long x0 = fit_cell_index((p->cx - R) / g->cell), x1 = fit_cell_index((p->cx + R) / g->cell);
            const long y0 = fit_cell_index((p->cy - R) / g->cell), y1 = fit_cell_index((p->cy + R) / g->cell);
            const int all = (double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np;
            for (long ix = x0; ix <= x1; ix++)
                for (long iy = y0; iy <= y1; iy++)
                    for (int e = all ? 0 : g->head[fit_cell_hash(ix, iy, (1UL << HASH_BITS) - 1)]; all ? e < np : e >= 0; e = all ? e + 1 : g->next[e]) {
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
            const long x0 = fit_cell_index((P[0] - d0) / g->cell), x1 = fit_cell_index((P[0] + d0) / g->cell);
            const long y0 = fit_cell_index((P[1] - d0) / g->cell), y1 = fit_cell_index((P[1] + d0) / g->cell);
            const unsigned tag = (unsigned)i + 1u;
            const own_foot f0 = {side ? side[i] : 0, foot[i]};
            if ((double)(x1 - x0 + 1) * (double)(y1 - y0 + 1) > 4.0 * np) {   /* far: every piece */
                for (int j = 0; j < np && !st; j++)
                    if (disk_reaches(&pc[j], P, fabs(dist[i])))
                        st = consider(v, curves, &pc[j], P, &f0, dense, i, dist, foot, side);
                continue;
            }
            for (long ix = x0; ix <= x1 && !st; ix++)
                for (long iy = y0; iy <= y1 && !st; iy++)
                    for (int e = g->head[fit_cell_hash(ix, iy, (1UL << HASH_BITS) - 1)]; e >= 0 && !st; e = g->next[e]) {
                        const int j = g->item[e];
                        if (stamp[j] == tag) continue;
                        stamp[j] = tag;
                        if (disk_reaches(&pc[j], P, fabs(dist[i])))
                            st = consider(v, curves, &pc[j], P, &f0, dense, i, dist, foot, side);
                    }
        }
    }
    free(sep);
    free(pc); free(g); free(stamp);
    dense_free(&dense[0]); dense_free(&dense[1]);
    return st;
}
