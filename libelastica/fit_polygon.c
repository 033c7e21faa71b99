/*
 * The discrete model's point-to-polygon distances (the report's, fit_internal.h): each
 * point's distance to the polygon of the vertices, searched from the segments at the
 * point's own vertex outwards while the distance decreases (el__fit_polygon_distances),
 * and the nearest segment anywhere (el__fit_polygon_nearest_everywhere: a polygon passing
 * close to itself). Signed distances: positive when the point lies left of the polygon.
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
 * A hierarchy of axis-aligned bounding boxes over runs of TREE_LEAF consecutive segments
 * (a complete binary tree over the runs, node 1 the root, node i's children 2i, 2i + 1),
 * built once per evaluation in O(n) where a stretch is long (a dense polygon: spacing far
 * below the noise, d / h in the thousands; a curve far from its points while a fit
 * wanders). GSL has no spatial index (nor Ipopt): written here. The nearest segment of a
 * range of them is found by a descent, the nearer child first, that leaves out a box
 * farther than the best so far: exact, not an approximation (tree_search); a box holding
 * a vertex that is not finite is the whole plane (never left out).
 */
/* TREE_EAGER: from this many vertices the tree is built before the first point, so that
 * the walks can skip its nodes (the large scans it is for); below, only where the stretch
 * searches' long ranges pay for it (nearest_in_range): a 1000-point fit calls this at every slip check, and building the tree
 * at each call cost its paired fit 0.26 ms of 0.6 (el.fit vs scipy 3.3 -> 2.5 x). The
 * answer is the same either way (test_fit_polygon_tree). */
enum { TREE_LEAF = 8, TREE_MIN = 4 * BLOCK, TREE_EAGER = 4096 };
typedef struct seg_tree {
    const double *V;
    long ns, size;          /* segments; leaves (a power of 2), TREE_LEAF segments each */
    double *box;            /* 4 a node: xmin, xmax, ymin, ymax */
    double *dir;            /* 6 a node: its segments' B - A: min and max x, min and max y,
                             * largest and smallest squared length (-1: a vertex not finite) */
} seg_tree;

static int tree_build(seg_tree *T, const double *V, long ns)
{
    T->V = V;
    T->ns = ns;
    long nleaf = (ns + TREE_LEAF - 1) / TREE_LEAF;
    T->size = 1;
    while (T->size < nleaf) T->size *= 2;
    T->box = malloc(sizeof(double) * 10 * 2 * (size_t)T->size);
    if (!T->box) return 0;
    T->dir = T->box + 4 * 2 * (size_t)T->size;
    for (long i = 0; i < T->size; i++) {
        double *b = T->box + 4 * (T->size + i);
        b[0] = b[2] = HUGE_VAL; b[1] = b[3] = -HUGE_VAL;       /* empty */
        const long j1 = (i + 1) * TREE_LEAF < ns ? (i + 1) * TREE_LEAF : ns;
        for (long k = i * TREE_LEAF; k <= j1 && i * TREE_LEAF < ns; k++) {   /* vertices of the run */
            const double x = V[2 * k], y = V[2 * k + 1];
            if (!(isfinite(x) && isfinite(y))) { b[0] = b[2] = -HUGE_VAL; b[1] = b[3] = HUGE_VAL; break; }
            if (x < b[0]) b[0] = x;
            if (x > b[1]) b[1] = x;
            if (y < b[2]) b[2] = y;
            if (y > b[3]) b[3] = y;
        }
        double *u = T->dir + 6 * (T->size + i);
        u[0] = u[2] = u[5] = HUGE_VAL; u[1] = u[3] = u[4] = -HUGE_VAL;
        for (long m = i * TREE_LEAF; m < j1; m++) {
            const double ux = V[2 * m + 2] - V[2 * m], uy = V[2 * m + 3] - V[2 * m + 1], l2 = ux * ux + uy * uy;
            if (!(isfinite(ux) && isfinite(uy) && isfinite(l2) && b[0] > -HUGE_VAL)) { u[5] = -1.0; break; }
            if (ux < u[0]) u[0] = ux;
            if (ux > u[1]) u[1] = ux;
            if (uy < u[2]) u[2] = uy;
            if (uy > u[3]) u[3] = uy;
            if (l2 > u[4]) u[4] = l2;
            if (l2 < u[5]) u[5] = l2;
        }
    }
    for (long i = T->size - 1; i >= 1; i--) {
        double *b = T->box + 4 * i;
        const double *l = T->box + 8 * i, *r = l + 4;
        b[0] = l[0] < r[0] ? l[0] : r[0];
        b[1] = l[1] > r[1] ? l[1] : r[1];
        b[2] = l[2] < r[2] ? l[2] : r[2];
        b[3] = l[3] > r[3] ? l[3] : r[3];
        double *u = T->dir + 6 * i;
        const double *ul = T->dir + 12 * i, *ur = ul + 6;
        for (int k = 0; k < 6; k += 2) {
            u[k] = ul[k] < ur[k] ? ul[k] : ur[k];
            u[k + 1] = ul[k + 1] > ur[k + 1] ? ul[k + 1] : ur[k + 1];
        }
        u[4] = ul[4] > ur[4] ? ul[4] : ur[4];
        u[5] = ul[5] < ur[5] ? ul[5] : ur[5];
    }
    return 1;
}

/*
 * Whether the walk of el__fit_polygon_distances goes on through every segment A-B of
 * node, forward (dir 1: the nearest point of each is its end B, t computes to 1) or
 * backward (dir -1: its start A, t computes to 0): by interval bounds of
 * X = (P - A).(B - A) over the node's vertex box and its segments' B - A. t computes to 1
 * where X >= |B - A|^2 (1 + 1e-12) + s, to 0 where X <= -s, s = 1e-12 (|P - A|x |ux| +
 * |P - A|y |uy|) bounding the rounding of the dot product, the division and the bounds
 * (each below 1e-15 of those terms). Unproved (a vertex not finite, an overflow, NaN):
 * 0, the segments walked one by one.
 */
static inline double lo_product(double a0, double a1, double b0, double b1)
{
    const double p = a0 * b0, q = a0 * b1, r = a1 * b0, w = a1 * b1;
    const double m = p < q ? p : q, n = r < w ? r : w;
    return m < n ? m : n;
}

static int walk_passes(const seg_tree *T, long node, const double *P, int dir)
{
    const double *b = T->box + 4 * node, *u = T->dir + 6 * node;
    if (!(u[5] >= 0.0) || (dir > 0 && !(u[5] > 0.0))) return 0;
    const double x0 = P[0] - b[1], x1 = P[0] - b[0], y0 = P[1] - b[3], y1 = P[1] - b[2];
    const double mx = fabs(x0) > fabs(x1) ? fabs(x0) : fabs(x1), my = fabs(y0) > fabs(y1) ? fabs(y0) : fabs(y1);
    const double ux = fabs(u[0]) > fabs(u[1]) ? fabs(u[0]) : fabs(u[1]);
    const double uy = fabs(u[2]) > fabs(u[3]) ? fabs(u[2]) : fabs(u[3]);
    const double s = 1e-12 * (mx * ux + my * uy);
    if (!(s < HUGE_VAL)) return 0;
    if (dir > 0) {
        const double lo = lo_product(x0, x1, u[0], u[1]) + lo_product(y0, y1, u[2], u[3]);
        return lo >= u[4] * (1.0 + 1e-12) + s && lo < HUGE_VAL;
    }
    const double hi = -lo_product(x0, x1, -u[1], -u[0]) - lo_product(y0, y1, -u[3], -u[2]);
    return hi <= -s && hi > -HUGE_VAL;
}

/* The squared distance of P to box b (0 inside; a NaN P: 0). */
static inline double box_distance2(const double *b, const double *P)
{
    const double dx = b[0] - P[0] > 0.0 ? b[0] - P[0] : P[0] - b[1] > 0.0 ? P[0] - b[1] : 0.0;
    const double dy = b[2] - P[1] > 0.0 ? b[2] - P[1] : P[1] - b[3] > 0.0 ? P[1] - b[3] : 0.0;
    return dx * dx + dy * dy;
}

typedef struct tree_query {
    const double *P;
    long a, b;              /* the segments a .. b - 1 */
    double lmax, bd, bound2, bt;
    long bj;                /* -1: none nearer than the caller's bd yet */
    int later;              /* of equal distances the last (a scan backwards), else the first */
} tree_query;

/* The bound of the boxes searched for bd: a segment whose squared distance computes to
 * at most bd is within sqrt(bd) of P to the rounding of segment_distance2 (below 1e-14
 * (d + lmax), |P - A| <= d + lmax), its box nearer still; this allows 1e-9 of d + lmax. */
static inline double tree_bound2(double bd, double lmax)
{
    const double b = sqrt(bd) * (1.0 + 1e-9) + 1e-9 * lmax;
    return b * b;
}

/*
 * The nearest of the segments q->a .. q->b - 1 in node's segments lo .. hi - 1 strictly
 * nearer than the caller's bd, and among equal ones the first (the order of the linear
 * scan, which keeps the first of equal distances): a descent in any order that takes a
 * segment when nearer, or as near and earlier. Boxes beyond tree_bound2 are left out.
 */
static void tree_search(const seg_tree *T, long node, long lo, long hi, tree_query *q)
{
    if (hi <= q->a || lo >= q->b) return;
    if (node >= T->size) {
        const long m0 = lo > q->a ? lo : q->a, m1 = hi < q->b ? hi : q->b;
        for (long m = m0; m < m1; m++) {
            double t;
            const double d2 = segment_distance2(T->V + 2 * m, T->V + 2 * m + 2, q->P, &t);
            if (d2 < q->bd || (d2 == q->bd && q->bj >= 0 && (q->later ? m > q->bj : m < q->bj))) {
                q->bd = d2; q->bj = m; q->bt = t;
                q->bound2 = tree_bound2(d2, q->lmax);
            }
        }
        return;
    }
    const long mid = lo + (hi - lo) / 2;
    const double *bl = T->box + 8 * node, *br = bl + 4;
    const double dl = box_distance2(bl, q->P), dr = box_distance2(br, q->P);
    if (dl <= dr) {
        if (!(dl > q->bound2)) tree_search(T, 2 * node, lo, mid, q);
        if (!(dr > q->bound2)) tree_search(T, 2 * node + 1, mid, hi, q);
    } else {
        if (!(dr > q->bound2)) tree_search(T, 2 * node + 1, mid, hi, q);
        if (!(dl > q->bound2)) tree_search(T, 2 * node, lo, mid, q);
    }
}

/* nearest_segment over j0 .. j1 - 1, by the tree where the range is long (without memory,
 * or accelerate 0, by the scan): the same segment. The tree is built once the long ranges
 * scanned so far (*scanned segments) pass the polygon's segments, what a build costs
 * (O(n)): a few long ranges cost less by the scan (a 1000-point paired fit met some in 26
 * of bench_fit.py's 84 noisy 1000-point fits, and built the tree for them, 86 000
 * instructions, where the scans cost a few thousand); many, at most twice the cheaper. */
static inline void nearest_in_range(seg_tree *T, int *tree_state, long *scanned, long *visits,
                                    const double *V, long ns, long j0, long j1, const double *P,
                                    double lmax, double *r, double *bd, long *bj, double *bt)
{
    if (j1 - j0 >= TREE_MIN && *tree_state == 0 && (*scanned += j1 - j0) > ns) {
        *tree_state = tree_build(T, V, ns) ? 1 : -1;
        *visits += ns;
    }
    if (j1 - j0 < TREE_MIN || *tree_state != 1) {
        if (j1 > j0) *visits += j1 - j0;
        nearest_segment(V, j0, j1, P, lmax, r, bd, bj, bt);
        return;
    }
    ++*visits;
    tree_query q = {P, j0, j1, lmax, *bd, tree_bound2(*bd, lmax), 0.0, -1, 0};
    if (!(T->box[4] <= T->box[5])) return;      /* no segment */
    tree_search(T, 1, 0, T->size * TREE_LEAF, &q);
    if (q.bj < 0) return;
    *bd = q.bd; *bj = q.bj; *bt = q.bt;
    const double rn = reach_of(sqrt(q.bd), lmax);
    if (rn < *r) *r = rn;
}

/*
 * The walk's skip at segment seg in direction dir: the largest node of the tree that
 * starts (dir 1) or ends (dir -1) at seg and that the walk passes whole (walk_passes);
 * its nearest segment taken as the walk would (bd, best, bt: strictly nearer than bd, of
 * equal ones the first met); the next segment of the walk returned, or seg when none.
 */
static long walk_skip(const seg_tree *T, long seg, int dir, const double *P, double lmax, double *bd, long *best,
                      double *bt)
{
    const long edge = dir > 0 ? seg : seg + 1;     /* the block's boundary at seg */
    if (edge % TREE_LEAF) return seg;
    long leaf = edge / TREE_LEAF - (dir > 0 ? 0 : 1), node = -1, span = 0;
    if (leaf < 0 || leaf >= T->size || (dir > 0 && (leaf + 1) * TREE_LEAF > T->ns)) return seg;
    for (long nd = T->size + leaf, k = 1; ; nd /= 2, k *= 2) {
        if (dir > 0 ? (edge / TREE_LEAF + k) * TREE_LEAF > T->ns : edge / TREE_LEAF < k) break;
        if (!walk_passes(T, nd, P, dir)) break;
        node = nd; span = k * TREE_LEAF;
        if (dir > 0 ? nd % 2 : !(nd % 2)) break;   /* the parent starts (ends) elsewhere */
    }
    if (node < 0) return seg;
    (void)node;
    tree_query q = {P, dir > 0 ? seg : seg + 1 - span, dir > 0 ? seg + span : seg + 1, lmax, *bd,
                    tree_bound2(*bd, lmax), 0.0, -1, dir < 0};
    tree_search(T, 1, 0, T->size * TREE_LEAF, &q);
    if (q.bj >= 0) { *bd = q.bd; *best = q.bj; *bt = q.bt; }
    return dir > 0 ? seg + span : seg - span;
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
    el__fit_polygon_distances_by(o, V, nv, h, first, step, dist, foot, 1);
}

void el__fit_polygon_distances_by(const fit_objective *o, const double *V, size_t nv, double h,
                                  size_t first, long step, double *dist, double *foot, int accelerate)
{
    el__fit_polygon_distances_counted(o, V, nv, h, first, step, dist, foot, accelerate, NULL);
}

void el__fit_polygon_distances_counted(const fit_objective *o, const double *V, size_t nv, double h,
                                       size_t first, long step, double *dist, double *foot,
                                       int accelerate, long *visited)
{
    seg_tree T = {V, 0, 0, NULL, NULL};
    int tree_state = accelerate ? 0 : -1;       /* 0: not built yet, 1: built, -1: the scan */
    long scanned = 0;                           /* segments of long ranges scanned (nearest_in_range) */
    long visits = 0;                            /* the work: *visited (fit_internal.h) */
    if (accelerate && nv > TREE_EAGER) {
        tree_state = tree_build(&T, V, (long)nv - 1) ? 1 : -1;
        visits += (long)nv - 1;
    }
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
            long walked = 0;
            for (long seg = dir < 0 ? j0 - 1 : j0; seg >= 0 && seg <= last; seg += dir) {
                /* a long walk's segments count as a long range's (nearest_in_range): the
                 * tree is built once they pass the polygon's segments */
                if (tree_state == 0 && ++walked > TREE_MIN && ++scanned > last + 1) {
                    tree_state = tree_build(&T, V, last + 1) ? 1 : -1;
                    visits += last + 1;
                }
                /* a run of segments the walk passes whole: skipped by the tree */
                if (tree_state == 1) {
                    const long next = walk_skip(&T, seg, dir, P, lmax, &bd, &best, &bt);
                    if (next != seg) {
                        visits++;
                        if (dir < 0) clo = next + 1; else chi = next - 1;
                        seg = next - dir;
                        continue;
                    }
                }
                double t;
                const double d2 = segment_distance2(V + 2 * seg, V + 2 * seg + 2, P, &t);
                visits++;
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
            nearest_in_range(&T, &tree_state, &scanned, &visits, V, last + 1, lo,
                             hi < clo ? hi + 1 : clo, P, lmax, &r, &bd, &best, &bt);
            nearest_in_range(&T, &tree_state, &scanned, &visits, V, last + 1,
                             lo > chi ? lo : chi + 1, hi + 1, P, lmax, &r, &bd, &best, &bt);
            if (lo < clo) clo = lo;
            if (hi > chi) chi = hi;
        }
        dist[g] = segment_signed(V + 2 * best, V + 2 * best + 2, P, bt);
        foot[g] = h * ((double)best + bt);
    }
    free(T.box);
    if (visited) *visited = visits;
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

int el__fit_polygon_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
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
    const double inv = 1.0 / (8.0 * fmax(fit_mean_distance(dist, o->n), lmax));      /* 1 / cell */
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
            const long jx = fit_cell_index(V[c][2 * j] * inv), jy = fit_cell_index(V[c][2 * j + 1] * inv);
            if (j > 0 && jx == ix && jy == iy) { run[3 * nr - 1]++; continue; }
            ix = jx; iy = jy;
            run[3 * nr] = c; run[3 * nr + 1] = j; run[3 * nr + 2] = j + 1;
            key[nr] = fit_cell_hash(ix, iy, nb - 1);
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
        const long cx0 = fit_cell_index((P[0] - q.r) * inv), cx1 = fit_cell_index((P[0] + q.r) * inv);
        const long cy0 = fit_cell_index((P[1] - q.r) * inv), cy1 = fit_cell_index((P[1] + q.r) * inv);
        if ((double)(cx1 - cx0 + 1) * (double)(cy1 - cy0 + 1) > (double)nr) {
            search_runs(V, run, nr, &q);     /* far: every run */
        } else {
            for (long ix = cx0; ix <= cx1; ix++)
                for (long iy = cy0; iy <= cy1; iy++) {
                    const size_t bk = fit_cell_hash(ix, iy, nb - 1);
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
