/*
 * Does a spline follow its ducks (spline.c, spline_path.c)? A batten through ducks
 * whose polygon does not cross itself does not cross itself either; an equilibrium
 * that does (a figure eight, a loop between two ducks) is another critical point of
 * integral kappa^2 + sigma ds, not the batten. The curve is sampled (each piece at
 * 16 points per chord of its length, at least 16) and the polyline's proper
 * crossings between non-adjacent segments are looked for by a sweep in x (segments
 * sorted by their least x; a pair is tested only while the boxes overlap in x), so
 * a fair curve costs O(N log N). Most curves need no samples (tame): a piece of length L
 * between knots a, b lies in the ellipse |p - a| + |p - b| <= L, so pieces whose
 * ellipses' boxes do not meet do not cross; and along two joined pieces the tangent
 * stays within kb L of its angle at the joint (kb = 2 |k| sqrt(mu) >= |kappa|, the
 * amplitude of kappa = 2 k sqrt(mu) cn), so where 2 kb L < pi on both the pair turns
 * less than pi: monotone along the bisecting direction, it crosses neither itself nor
 * its neighbour.
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>

typedef struct { double x0, x1; size_t i; } seg_box;

static int by_x0(const void *a, const void *b)
{
    const double u = ((const seg_box *)a)->x0, v = ((const seg_box *)b)->x0;
    return (u > v) - (u < v);
}

/* sign of the cross product (b - a) x (c - a) */
static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* The proper crossings of the polyline xy (np points; closed: the last joins the first):
 * segments that are not neighbours, each strictly through the other, found by the sweep
 * in x; pairs (i, j), i < j, of segment indices into *pairs where pairs is not NULL
 * (malloc'ed, the caller frees; NULL for none), *cnt of them, stopping at the first where
 * first is set. 0, or EL_ENOMEM as -1. */
static int sweep_crossings(const double *xy, size_t np, int closed, int first, size_t **pairs, size_t *cnt)
{
    if (pairs) *pairs = NULL;
    *cnt = 0;
    const size_t ns = closed ? np : np - 1;
    if (ns < 3) return 0;
    seg_box *b = malloc(ns * sizeof *b);
    if (!b) return -1;
    for (size_t i = 0; i < ns; i++) {
        const double xa = xy[2 * i], xb = xy[2 * ((i + 1) % np)];
        b[i].x0 = fmin(xa, xb);
        b[i].x1 = fmax(xa, xb);
        b[i].i = i;
    }
    qsort(b, ns, sizeof *b, by_x0);
    size_t cap = 0, *out = NULL;
    for (size_t a = 0; a < ns && !(first && *cnt); a++) {
        const size_t i = b[a].i;
        const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % np);
        for (size_t c = a + 1; c < ns && b[c].x0 <= b[a].x1 && !(first && *cnt); c++) {
            const size_t j = b[c].i, d = i > j ? i - j : j - i;
            if (d <= 1 || (closed && d == ns - 1)) continue;   /* neighbours share a point */
            const double *r = xy + 2 * j, *s = xy + 2 * ((j + 1) % np);
            if (fmax(p[1], q[1]) < fmin(r[1], s[1]) || fmax(r[1], s[1]) < fmin(p[1], q[1])) continue;
            if (!(orient(p, q, r) * orient(p, q, s) < 0.0 && orient(r, s, p) * orient(r, s, q) < 0.0)) continue;
            if (pairs) {
                if (*cnt == cap) {
                    cap = cap ? 2 * cap : 16;
                    size_t *t = realloc(out, 2 * cap * sizeof *t);
                    if (!t) { free(out); free(b); *cnt = 0; return -1; }
                    out = t;
                }
                out[2 * *cnt] = i < j ? i : j;
                out[2 * *cnt + 1] = i < j ? j : i;
            }
            (*cnt)++;
        }
    }
    free(b);
    if (pairs) *pairs = out;
    return 0;
}

/* The polyline xy crosses itself (sweep_crossings): 1, 0, or EL_ENOMEM as -1. */
static int polyline_crosses(const double *xy, size_t np, int closed)
{
    size_t cnt;
    return sweep_crossings(xy, np, closed, 1, NULL, &cnt) ? -1 : cnt > 0;
}

/* No crossing possible (see above): every piece turns by less than pi / 2 from either
 * end, and the boxes of the ellipses of pieces that are not neighbours do not meet
 * (knots: m + 1 points, the last the end of the last piece) */
static int tame(const el_smooth_params *p, size_t m, const double *knots, int closed)
{
    for (size_t j = 0; j < m; j++)
        if (!(2.0 * fabs(p[j].k) * sqrt(p[j].mu) * p[j].length < 0.5 * M_PI)) return 0;
    seg_box *b = malloc(m * sizeof *b);
    double *y = malloc(2 * m * sizeof *y);
    if (!b || !y) { free(b); free(y); return 0; }
    for (size_t j = 0; j < m; j++) {
        const double *a = knots + 2 * j, *e = knots + 2 * (j + 1);
        const double h = hypot(e[0] - a[0], e[1] - a[1]), L = fmax(p[j].length, h);
        const double A = 0.5 * L, B = 0.5 * sqrt(L * L - h * h);   /* semi-axes */
        const double c = h > 0.0 ? (e[0] - a[0]) / h : 1.0, sn = h > 0.0 ? (e[1] - a[1]) / h : 0.0;
        const double wx = hypot(A * c, B * sn), wy = hypot(A * sn, B * c);
        const double mx = 0.5 * (a[0] + e[0]), my = 0.5 * (a[1] + e[1]);
        b[j].x0 = mx - wx; b[j].x1 = mx + wx; b[j].i = j;
        y[2 * j] = my - wy; y[2 * j + 1] = my + wy;
    }
    qsort(b, m, sizeof *b, by_x0);
    int ok = 1;
    for (size_t u = 0; u < m && ok; u++)
        for (size_t v = u + 1; v < m && b[v].x0 <= b[u].x1 && ok; v++) {
            const size_t i = b[u].i, j = b[v].i, d = i > j ? i - j : j - i;
            if (d <= 1 || (closed && d == m - 1)) continue;
            ok = y[2 * i + 1] < y[2 * j] || y[2 * j + 1] < y[2 * i];
        }
    free(b);
    free(y);
    return ok;
}

/* The knots of the m pieces (m + 1 points, the last the end of the last piece, also in
 * end): malloc'ed, NULL where out of memory or the end is not evaluated (*bad 1). */
static double *knots_of(const el_smooth_params *p, size_t m, double end[2], int *bad)
{
    *bad = 0;
    double *knots = malloc(2 * (m + 1) * sizeof *knots);
    if (!knots) return NULL;
    for (size_t j = 0; j < m; j++) { knots[2 * j] = p[j].x0; knots[2 * j + 1] = p[j].y0; }
    double s1 = p[m - 1].length;
    if (el_smooth_eval(&p[m - 1], 1, &s1, end, NULL, NULL)) { free(knots); *bad = 1; return NULL; }
    knots[2 * m] = end[0];
    knots[2 * m + 1] = end[1];
    return knots;
}

/* The curve sampled (each piece at 16 points per chord of its length, at least 16; its
 * end appended where open): *k points, cnt[j] of piece j; malloc'ed xy (NULL: no
 * memory, or not evaluated: *bad 1) */
static double *sampled(const el_smooth_params *p, size_t m, int closed, const double *knots,
                       const double end[2], size_t *cnt, size_t *k, int *bad)
{
    *bad = 0;
    size_t total = 0;
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % (closed ? m : m + 1);
        const double h = hypot(knots[2 * e] - p[j].x0, knots[2 * e + 1] - p[j].y0);
        const double r = h > 0.0 ? p[j].length / h : 1.0;
        cnt[j] = r < 64.0 ? 16 * (size_t)ceil(r) : 1024;
        total += cnt[j];
    }
    double *xy = malloc(2 * (total + 1) * sizeof *xy), *s = malloc((1024 + 1) * sizeof *s);
    if (!xy || !s) { free(xy); free(s); return NULL; }
    *k = 0;
    for (size_t j = 0; j < m; j++) {
        for (size_t i = 0; i < cnt[j]; i++) s[i] = p[j].length * (double)i / (double)cnt[j];
        if (el_smooth_eval(&p[j], cnt[j], s, xy + 2 * *k, NULL, NULL)) {
            free(xy); free(s); *bad = 1; return NULL;
        }
        *k += cnt[j];
    }
    if (!closed) { xy[2 * *k] = end[0]; xy[2 * *k + 1] = end[1]; (*k)++; }
    free(s);
    return xy;
}

int el__spline_crosses(const el_smooth_params *p, size_t m, int closed)
{
    if (m < 2) return 0;
    /* the ducks' polygon (the knots): where it crosses itself the curve may */
    double end[2];
    int bad;
    double *knots = knots_of(p, m, end, &bad);
    if (!knots) return bad ? 0 : -1;
    const int poly = polyline_crosses(knots, closed ? m : m + 1, closed);
    if (poly != 0) { free(knots); return poly < 0 ? -1 : 0; }
    if (tame(p, m, knots, closed)) { free(knots); return 0; }
    size_t *cnt = malloc(m * sizeof *cnt), k = 0;
    if (!cnt) { free(knots); return -1; }
    double *xy = sampled(p, m, closed, knots, end, cnt, &k, &bad);
    const int found = xy ? polyline_crosses(xy, k, closed) : bad ? 0 : -1;
    free(xy); free(cnt); free(knots);
    return found;
}

/* pieces i and j are within one of each other (closed: around). The +- 1 lets a loop pass
 * where it lies beside a crossing of the polygon: QA's random walk 20 (11 ducks, its polygon
 * crossing 6 times, (1, 3) among them) at sigma h^2 1 (longest span) has lobes in spans 1,
 * 2, 4, 6 (3.8 x its polygon), and spans 1 and 2 cross (a loop round duck 2) matched by the
 * polygon's (1, 3): loops 0. Neighbours crossing always looping flags it, but also a crossing
 * that slid past a duck (the ducks of a figure eight on its crossing); not changed. */
static int near_piece(size_t i, size_t j, size_t m, int closed)
{
    const size_t d = i > j ? i - j : j - i;
    return d <= 1 || (closed && d + 1 >= m);
}

int el__spline_loops(const el_smooth_params *p, size_t m, int closed)
{
    if (m < 2) return 0;
    double end[2];
    int bad;
    double *knots = knots_of(p, m, end, &bad);
    if (!knots) return bad ? 0 : -1;
    size_t *pp = NULL, npp = 0;
    if (sweep_crossings(knots, closed ? m : m + 1, closed, 0, &pp, &npp)) { free(knots); return -1; }
    if (npp == 0) { free(knots); return el__spline_crosses(p, m, closed); }   /* as it was */
    /* the polygon crosses itself: the curve's crossings, in pieces, against the polygon's */
    size_t *cnt = malloc(m * sizeof *cnt), k = 0, *sp = NULL, nsp = 0;
    double *xy = cnt ? sampled(p, m, closed, knots, end, cnt, &k, &bad) : NULL;
    int loops = xy ? 0 : bad ? 0 : -1;
    if (xy && sweep_crossings(xy, k, closed, 0, &sp, &nsp)) loops = -1;
    if (xy && loops == 0 && nsp > 0) {
        size_t *piece = malloc(k * sizeof *piece);   /* the piece of each sample segment */
        if (!piece) loops = -1;
        for (size_t j = 0, a = 0; loops == 0 && j < m; j++)
            for (size_t i = 0; i < cnt[j]; i++) piece[a++] = j;
        for (size_t c = 0; loops == 0 && c < nsp; c++) { sp[2 * c] = piece[sp[2 * c]]; sp[2 * c + 1] = piece[sp[2 * c + 1]]; }
        for (size_t c = 0; loops == 0 && c < nsp; c++) {
            /* a crossing of pieces (i, j) with none of the polygon's between the same pieces
             * or a neighbour of each (a crossing slid past a duck) ... */
            const size_t i = sp[2 * c], j = sp[2 * c + 1];
            int matched = 0;
            for (size_t v = 0; v < npp && !matched; v++)
                matched = (near_piece(i, pp[2 * v], m, closed) && near_piece(j, pp[2 * v + 1], m, closed)) ||
                          (near_piece(i, pp[2 * v + 1], m, closed) && near_piece(j, pp[2 * v], m, closed));
            /* ... nor, between pieces that are not neighbours, a second crossing beside it
             * (i or j the same, the other within one: a duck passed on its other side,
             * the two crossings bounding a lens, no loop); neighbours crossing loop */
            for (size_t u = 0; u < nsp && !matched && !near_piece(i, j, m, closed); u++) {
                const size_t a = sp[2 * u], b = sp[2 * u + 1];
                matched = u != c && !near_piece(a, b, m, closed) &&
                          ((a == i && near_piece(b, j, m, closed)) || (b == j && near_piece(a, i, m, closed)));
            }
            loops = !matched;
        }
        free(piece);
    }
    free(sp); free(pp); free(xy); free(cnt); free(knots);
    return loops;
}

int el__chain_crosses(const el__spchain *w)
{
    const size_t m = w->m;
    el_smooth_params *p = malloc(m * sizeof *p);
    if (!p) return -1;
    double x = 0.0, y = 0.0;
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        p[j].x0 = x; p[j].y0 = y;
        p[j].phi = pc->v[EL__SP_PHI]; p[j].mu = exp(pc->v[EL__SP_NU]);
        p[j].k = pc->v[EL__SP_K]; p[j].q = pc->v[EL__SP_Q]; p[j].length = pc->v[EL__SP_L];
        x += pc->dx;
        y += pc->dy;
    }
    const int c = el__spline_loops(p, m, w->closed);
    free(p);
    return c;
}

/* ------------------------------------------------------------------ tension mode */

static double total_length(const el__spchain *w)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[EL__SP_L];
    return L;
}

static double chain_energy(const el__spchain *w)
{
    double e = 0.0;
    for (size_t j = 0; j < w->m; j++) e += w->pc[j].energy;
    return e;
}

/* Longer than EL__SP_WANDER x its polygon, or looping as el_spline_result's loops says
 * (el__chain_crosses, above): not the batten through its ducks */
int el__chain_wanders(const el__spchain *w)
{
    double poly = 0.0;
    for (size_t j = 0; j < w->m; j++) poly += w->pc[j].h;
    return total_length(w) > EL__SP_WANDER * poly || el__chain_crosses(w) == 1;
}

/* integral kappa^2 + sigma ds: the pieces' equations (2 kappa'' + kappa^3 - sigma kappa = 0)
 * and the joints' (kappa continuous: its first variation in a knot angle, spline.c) make a
 * tension solution a critical point of it among the curves through the ducks; of two at
 * one sigma the batten is the lesser */
static double lagrangian(const el__spchain *w)
{
    return chain_energy(w) + w->sigma * total_length(w);
}

/*
 * The tension solution in w (st: its status) where it wanders or failed: the family of
 * tension solutions from the taut batten (sigma h^2 = EL__SP_HIGH_SIGMA on the mean chord,
 * near the polygon) followed by pseudo-arclength down to target
 * (el__spline_follow_family), through the folds in sigma where continuation in sigma
 * itself stops or jumps branch (spline_path.c's from_sigma). Of the solutions found the
 * one that does not wander is kept, then the lower lagrangian. Measured (QA): spike ducks
 * (0,0),(1,0),(1.05,1),(1.1,0),(2,0) at sigma 1.25 gave a figure eight 1.51 x the polygon
 * (integral kappa^2 + sigma L = 42.45), now the fair batten 1.25 x (31.51; the length
 * mode's batten of 1.25 x, at its sigma 1.284: 31.68); t71 of 200 random ducks at the
 * tension of its length-mode batten gave 5.9 x the polygon, crossing itself, now that
 * batten. Over 1809 problems (those ducks, 4 tensions, 3 lengths, clamped and G2 ends) 6
 * changed, each from a curve crossing itself or 1.8-5 x its polygon to a fair one
 * (1.1-2 x; one of them of higher integral kappa^2 + sigma L: fair comes first), 8 former
 * failures solved, the rest identical. The starts are those that converge fair; where none
 * was reached and a start was refused only for wandering, its family too (loose), so the
 * looping spline is returned flagged rather than none (a random walk of 11 ducks whose
 * polygon crosses 3 times, at sigma h^2 10: EL_ENOCONV once its starts were judged by the
 * loop rule, 1.44 x and flagged again).
 */
int el__spline_refair(el__spchain *w, int max_steps, int st, double target)
{
    if (st == EL_ENOMEM || !(target < EL__SP_HIGH_SIGMA) || (st == EL_OK && !el__chain_wanders(w))) return st;
    const size_t n = w->n, m = w->m;
    double *buf = malloc(sizeof(double) * (n + 2 * EL__NV * m));
    if (!buf) return EL_ENOMEM;
    el__spsnap best = {buf, buf + n, buf + n + EL__NV * m, 0.0};
    double low = HUGE_VAL;   /* the best's lagrangian, */
    int bad = 2;             /* and whether it wanders (2: none yet) */
    if (st == EL_OK) { el__snap_save(w, &best); low = lagrangian(w); bad = 1; }
    /* the family followed with the tension's step capped (2), then not (1): each can
     * step over the other's branch point (t71, t14 need the first, the spike the second);
     * each from the first of these tensions whose Newton from the start converges to a
     * batten that does not wander (EL__SP_HIGH_SIGMA itself can fail: t71) */
    const double from[4] = {EL__SP_HIGH_SIGMA, 10.0, 4.0, 1.0};   /* sigma h^2 on the mean chord */
    /* loose: where nothing was reached and a start was refused for wandering (refused),
     * the family from that start too, so the looping spline is returned rather than none */
    int refused = 0;
    for (int loose = 0; loose < 2 && (!loose || (bad == 2 && refused)); loose++)
        for (int mode = 2; mode >= 1 && bad; mode--) {
            int sf = EL_ENOCONV;
            for (int i = 0; i < 4 && from[i] > target && sf == EL_ENOCONV; i++) {
                w->near = 0;
                w->lmode = 0;
                w->sigma = from[i];
                el__chain_start_angles(w);
                sf = el__chain_start_pieces(w);
                if (sf == EL_ENOMEM) break;
                if (sf || el__chain_newton(w, EL__SP_DIRECT_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR))
                    sf = EL_ENOCONV;
                else if (!loose && el__chain_wanders(w))
                    sf = EL_ENOCONV, refused = 1;
                else
                    sf = el__spline_follow_family(w, max_steps, target, mode);
            }
            w->lmode = 0;
            if (sf == EL_ENOMEM) { free(buf); return sf; }
            if (sf) continue;
            const int wd = el__chain_wanders(w);
            const double lag = lagrangian(w);
            if (wd < bad || (wd == bad && lag < low)) { el__snap_save(w, &best); bad = wd; low = lag; }
        }
    w->near = 0;
    w->sigma = target;
    if (bad < 2) { el__snap_load(w, &best); el__chain_reeval(w, 0); st = EL_OK; }
    free(buf);
    return st;
}

