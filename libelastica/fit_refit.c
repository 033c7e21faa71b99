/*
 * The kept curve's distances (the report, fit.c) and the smooth orthogonal fit's feet
 * elsewhere: a foot at rest on another pass of a loop than the point's nearest point
 * (fit.c's refit).
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

enum { CANDS = 8,        /* el__fit_feet_elsewhere's candidates per point */
       PIECES = FIT_PIECES,
       OWN_MAX = 16 };    /* el__fit_feet_unproven: feet's pieces searched for the pieces sampled */

/* Distances and feet (normalised) of every point to the kept curve: near each point's
 * own place, then wherever the curve comes nearer. projected (smooth): d and fs hold the
 * first already (el__fit_feet_distances at x, as el__fit_feet_elsewhere leaves them). */
int el__fit_curve_distances(fit_objective *ob, const double *x, double v[2][FIT_NP], int projected, double *d,
                            double *fs, double *tmp)
{
    const size_t n = ob->n;
    const size_t nv[2] = {n, 0};
    if (ob->map.model == FIT_SMOOTH) {
        const double *V[2] = {NULL, NULL};
        const int st = projected ? EL_OK : el__fit_feet_distances(ob, x, d, fs, NULL);
        return st ? st : el__fit_nearest_everywhere(ob, v, V, nv, d, fs, NULL);
    }
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    fit_walk w;
    el__fit_walk_start(v[0], &w);
    int st = EL_OK;
    for (size_t a = 0; a < n && !st; a += FIT_BLOCK) {
        const size_t m = n - a < FIT_BLOCK ? n - a : FIT_BLOCK;
        st = el__fit_discrete_rows(v[0], &w, m, buf + 2 * a, NULL, 0, tmp);
    }
    if (!st) {
        const double *V[2] = {buf, NULL};
        el__fit_polygon_distances(ob, buf, n, v[0][2], 0, 1, d, fs);
        st = el__fit_nearest_everywhere(ob, v, V, nv, d, fs, NULL);
    }
    free(buf);
    return st;
}

/* The grid cell index of coordinate x from x0 by cells of size c, held to [0, nc - 1]. */
static size_t cell_of(double x, double x0, double c, size_t nc)
{
    const double q = (x - x0) / c;
    return q > 0.0 ? (q < (double)(nc - 1) ? (size_t)q : nc - 1) : 0;
}

static double dist2(const double *a, const double *P)
{
    const double dx = a[0] - P[0], dy = a[1] - P[1];
    return dx * dx + dy * dy;
}

/*
 * The proof that a foot is the nearest point, which spares the samples' search on an open
 * arc: the curve cut into PIECES pieces j of arc length l = L / PIECES, every point of
 * piece j within r = l / 2 of the midpoint c_j of its ends, |c_(j+1) - c_j| <= l. With D
 * = max |d_i|, a point gamma(s') nearer to P than its foot gamma(s0) in piece j (distance
 * |d| <= D) is within 2 D of gamma(s0), so its piece's midpoint is nearer to c_j than
 * 2 D + 2 r: a piece of j's window [qa_j, qb_j], the pieces that near and j. Over the
 * window (|s - s0| <= A) |gamma(s) - P|^2 / 2 has second derivative 1 + kappa N .
 * (gamma - P) >= 1 - |kappa| (|d| + A), positive when |kappa| (|d| + A) < 1: one minimum
 * in the window, the foot (a stationary point or an end, Newton's), and none nearer
 * outside. |kappa| is bounded on a piece by its ends' and its slope: kappa = 2 k sqrt(mu)
 * cn u (seed 000 (4.3)), d kappa / ds = -2 k mu sn dn u with |sn dn| <= 1 for |k| <= 1
 * and |k sn dn| <= 1 for |k| > 1 (sn(u, k) = sn(k u, 1/k) / k, dn(u, k) = cn(k u, 1/k)),
 * so |d kappa / ds| <= 2 min(|k|, 1) mu; and |kappa| <= 2 |k| sqrt(mu) everywhere.
 */
typedef struct windows {
    double l, kmax[PIECES];     /* the bound of |kappa| over j's window */
    double c[2 * PIECES];       /* the pieces' midpoints */
    int qa[PIECES], qb[PIECES];
} windows;

static int windows_of(const el_smooth_params *p, double D, windows *w)
{
    /* reach with a margin of 1e-9 for the rounding of the midpoints' distances */
    const double L = p->length, l = L / PIECES, r = 0.5 * l, reach = (2.0 * D + 2.0 * r) * (1.0 + 1e-9);
    double s[PIECES + 1], xy[2 * (PIECES + 1)], ka[PIECES + 1], kb[PIECES], *c = w->c;
    for (int j = 0; j <= PIECES; j++) s[j] = L * j / PIECES;
    const int st = el_smooth_eval(p, PIECES + 1, s, xy, NULL, ka);
    if (st) return st;
    const double slope = 2.0 * fmin(fabs(p->k), 1.0) * p->mu, cap = 2.0 * fabs(p->k) * sqrt(p->mu);
    for (int j = 0; j < PIECES; j++) {
        c[2 * j] = 0.5 * (xy[2 * j] + xy[2 * j + 2]);
        c[2 * j + 1] = 0.5 * (xy[2 * j + 1] + xy[2 * j + 3]);
        kb[j] = fmin(fmax(fabs(ka[j]), fabs(ka[j + 1])) + slope * r, cap);
    }
    w->l = l;
    for (int j = 0; j < PIECES; j++) {
        /* the first and the last piece within reach, each by steps from an end: from q,
         * whose midpoint is delta away, the next that may be within reach is
         * 1 + (delta - reach) / l further (|c_(q+1) - c_q| <= l; a margin of 1e-9 for
         * rounding); j itself is */
        int qa = 0, qb = PIECES - 1;
        for (double delta; qa < j && !((delta = sqrt(dist2(c + 2 * qa, c + 2 * j))) < reach);)
            qa += 1 + (int)fmin((delta - reach) / (l * (1.0 + 1e-9)), (double)PIECES);
        for (double delta; qb > j && !((delta = sqrt(dist2(c + 2 * qb, c + 2 * j))) < reach);)
            qb -= 1 + (int)fmin((delta - reach) / (l * (1.0 + 1e-9)), (double)PIECES);
        if (qa > j) qa = j;
        if (qb < j) qb = j;
        w->qa[j] = qa;
        w->qb[j] = qb;
        /* the bound over the window; HUGE_VAL once it already fails for every foot in j
         * (A >= l max(j - qa, qb - j)) */
        const double Amin = l * (double)(j - qa > qb - j ? j - qa : qb - j);
        double km = 0.0;
        for (int q = qa; q <= qb && km < HUGE_VAL; q++) {
            km = fmax(km, kb[q]);
            if (km * Amin >= 1.0) km = HUGE_VAL;
        }
        w->kmax[j] = km;
    }
    return EL_OK;
}

/* Whether the foot s0 (distance d) is proven the nearest point by the windows. */
static int proven(const windows *w, double d, double s0)
{
    if (!(fabs(d) < HUGE_VAL && s0 >= 0.0)) return 0;
    const int j = (int)fmin(s0 / w->l, PIECES - 1.0);
    const double A = fmax(s0 - w->qa[j] * w->l, (w->qb[j] + 1) * w->l - s0);
    return w->kmax[j] * (fabs(d) + A) < 1.0;
}

int el__fit_feet_unproven(const fit_objective *o, double v[2][FIT_NP], const double *d, const double *fs,
                          unsigned char *unproven, size_t *nopen, unsigned char mark[FIT_PIECES])
{
    const size_t n = o->n;
    double D = 0.0;
    for (size_t i = 0; i < n; i++) D = fmax(D, fabs(d[i]));
    el_smooth_params p;
    windows w;
    int st;
    if ((st = el__fit_to_smooth(v[0], &p)) || (st = D < HUGE_VAL ? windows_of(&p, D, &w) : EL_EDOM)) return st;
    *nopen = 0;
    unproven[0] = unproven[n - 1] = 0;
    for (size_t i = 1; i + 1 < n; i++) *nopen += unproven[i] = !proven(&w, d[i], fs[i]);
    /* the pieces that can hold a point nearer to an unproven point: within 2 D + 2 r of
     * its foot's piece; more than OWN_MAX feet's pieces (a loop): every piece (the scans
     * would cost more than they spare) */
    unsigned char own[PIECES] = {0};
    int nown = 0;
    for (size_t i = 1; i + 1 < n; i++)
        if (unproven[i]) {
            const int j = (int)fmin(fmax(fs[i] / w.l, 0.0), PIECES - 1.0);
            nown += !own[j];
            own[j] = 1;
        }
    memset(mark, nown > OWN_MAX, PIECES);
    const double reach = (2.0 * D + w.l) * (1.0 + 1e-9);
    for (int j = 0; j < PIECES && nown <= OWN_MAX; j++)
        for (int q = 0, e; own[j] && q < PIECES; q += e) {
            const double delta = sqrt(dist2(w.c + 2 * q, w.c + 2 * j));
            mark[q] |= delta < reach;
            e = delta < reach ? 1 : 1 + (int)fmin((delta - reach) / (w.l * (1.0 + 1e-9)), (double)PIECES);
        }
    return EL_OK;
}

/*
 * The distances d and feet fs of the points to the smooth curve at x (one curve), Newton
 * from the feet o->s (el__fit_feet_distances), then for each inner point whose foot is not
 * proven the nearest point (el__fit_feet_unproven; on an open arc usually none, and then no
 * sample is taken) a foot on another pass of the curve that is nearer, found from the
 * curve's samples gamma(j h), h = L / M, on the pieces that can hold one:
 * a sample that is a local minimum of the sampled distance, at least 1.5 h from the foot
 * (the foot's own minimum lies within h of it), within |d| + h of the point (a nearer
 * minimum elsewhere has a sample within h / 2 of it, nearer than |d| + h / 2); from each
 * of the CANDS nearest such samples Newton's method to its foot, the nearest foot taken
 * when nearer than |d| and more than 1e-3 L away (fit.c's test of a foot elsewhere). Those points' d, fs
 * are then the nearer ones; *moved counts those whose foot in o->s lies on [0, L] (a
 * foot on the extension beyond an end is moved, not counted: fit.c's test); a candidate
 * sets o->other_passes. A pass
 * narrower than ~2 h, or a minimum that Newton's method misses from its sample, is not
 * found: the search everywhere (el__fit_nearest_everywhere, the report's) decides at the end.
 */
int el__fit_feet_elsewhere(fit_objective *o, const double *x, double v[2][FIT_NP], double *d, double *fs,
                           size_t *moved)
{
    const size_t n = o->n;
    *moved = 0;
    int st = el__fit_feet_distances(o, x, d, fs, NULL);
    const double L = v[0][6];
    el_smooth_params p;
    if (st || o->map.ncurves != 1 || n < 3 || !(L > 0.0)) return st;
    /* the points whose feet are not proven nearest: searched below */
    unsigned char *unproven = malloc(n), mark[PIECES];
    if (!unproven) return EL_ENOMEM;
    size_t nopen = 0;
    if ((st = el__fit_to_smooth(v[0], &p)) || (st = el__fit_feet_unproven(o, v, d, fs, unproven, &nopen, mark)) ||
        nopen == 0) {
        free(unproven);
        return st;
    }
    /* samples every half mean distance (a point's disk then holds a few of each pass),
     * at most twice the points' density, at least 256, at most 16384, per = M / PIECES
     * to a piece; only those of the pieces marked (their ends are samples) */
    double dm = 0.0;
    for (size_t i = 0; i < n; i++) dm += fabs(d[i]);
    dm /= (double)n;
    const double cap = fmin(2.0 * (double)n, 16384.0);
    const size_t per = (size_t)ceil(fmax(fmin(ceil(2.0 * L / (dm + 1e-300)), cap), 256.0) / PIECES), M = per * PIECES;
    const double h = L / (double)M;
    double *buf = malloc(sizeof(double) * (3 * (M + 1) + 2 * CANDS * FIT_BLOCK));
    size_t *ord = malloc(sizeof(size_t) * (2 * (M + 1) + 4 * (M + 1) + 2 + CANDS * FIT_BLOCK));
    if (!buf || !ord) { free(buf); free(ord); free(unproven); return EL_ENOMEM; }
    double *sj = buf, *xy = buf + M + 1, *cs = buf + 3 * (M + 1), *cd = cs + CANDS * FIT_BLOCK;
    size_t *gi = ord + M + 1, ns = 0;           /* sample k is gamma(gi[k] h) */
    for (size_t q = 0; q < PIECES; q++)
        if (mark[q])
            for (size_t g = q * per + (q > 0 && mark[q - 1]); g <= (q + 1) * per; g++) {
                gi[ns] = g;
                sj[ns++] = L * (double)g / (double)M;
            }
    if (ns == 0 || (st = el_smooth_eval(&p, ns, sj, xy, NULL, NULL))) goto out;
    /* the samples by grid cell (counting sort), cells of twice the mean distance, at most
     * 4 (M + 1) of them */
    double x0 = HUGE_VAL, x1 = -HUGE_VAL, y0 = HUGE_VAL, y1 = -HUGE_VAL;
    for (size_t j = 0; j < ns; j++) {
        const double a = xy[2 * j], b = xy[2 * j + 1];
        if (a < x0) x0 = a;
        if (a > x1) x1 = a;
        if (b < y0) y0 = b;
        if (b > y1) y1 = b;
    }
    if (!isfinite(x1 - x0) || !isfinite(y1 - y0) || !isfinite(dm)) { st = EL_EDOM; goto out; }
    double c = fmax(2.0 * dm, h);
    size_t nx, ny;
    for (;; c *= 2.0) {
        nx = (size_t)fmin((x1 - x0) / c, 4.0 * (double)ns) + 1;
        ny = (size_t)fmin((y1 - y0) / c, 4.0 * (double)ns) + 1;
        if ((double)nx * (double)ny <= 4.0 * (double)ns) break;
    }
    size_t *head = gi + M + 1, *cp = head + 4 * ns + 2;    /* nx ny + 1 cell starts; candidates' points */
    memset(head, 0, sizeof(size_t) * (nx * ny + 1));
    for (size_t j = 0; j < ns; j++) head[cell_of(xy[2 * j + 1], y0, c, ny) * nx + cell_of(xy[2 * j], x0, c, nx) + 1]++;
    for (size_t k = 0; k < nx * ny; k++) head[k + 1] += head[k];
    for (size_t j = 0; j < ns; j++) {
        const size_t k = cell_of(xy[2 * j + 1], y0, c, ny) * nx + cell_of(xy[2 * j], x0, c, nx);
        ord[head[k]++] = j;
    }
    for (size_t k = nx * ny; k > 0; k--) head[k] = head[k - 1];
    head[0] = 0;
    /* each point's candidates: the nearest CANDS such samples (a crowded loop may hold
     * several passes within reach), by blocks of FIT_BLOCK points */
    for (size_t a = 1; a + 1 < n && !st; a += FIT_BLOCK) {
        const size_t m = n - 1 - a < FIT_BLOCK ? n - 1 - a : FIT_BLOCK;
        size_t nc = 0;
        for (size_t i = a; i < a + m; i++) {
            if (!unproven[i]) continue;
            const double P[2] = {(o->xy[2 * i] - o->cx) / o->sc, (o->xy[2 * i + 1] - o->cy) / o->sc};
            const double R = fabs(d[i]) + h;
            if (!(P[0] + R >= x0 && P[0] - R <= x1 && P[1] + R >= y0 && P[1] - R <= y1)) continue;
            const size_t ia = cell_of(P[0] - R, x0, c, nx), ib = cell_of(P[0] + R, x0, c, nx);
            const size_t ja = cell_of(P[1] - R, y0, c, ny), jb = cell_of(P[1] + R, y0, c, ny);
            double q2[CANDS];
            size_t k = 0;                       /* candidates of point i: cs[nc .. nc+k-1] */
            for (size_t cy = ja; cy <= jb; cy++)
                for (size_t e = head[cy * nx + ia]; e < head[cy * nx + ib + 1]; e++) {
                    const size_t j = ord[e];
                    const double q = dist2(xy + 2 * j, P);
                    if (q >= R * R || (k == CANDS && q >= q2[CANDS - 1]) || fabs(sj[j] - fs[i]) < 1.5 * h) continue;
                    if ((j > 0 && gi[j - 1] + 1 == gi[j] && dist2(xy + 2 * j - 2, P) < q) ||
                        (j + 1 < ns && gi[j + 1] == gi[j] + 1 && dist2(xy + 2 * j + 2, P) < q)) continue;
                    size_t r = k < CANDS ? k++ : CANDS - 1;     /* sorted insertion, the farthest dropped */
                    for (; r > 0 && q2[r - 1] > q; r--) { q2[r] = q2[r - 1]; cs[nc + r] = cs[nc + r - 1]; }
                    q2[r] = q;
                    cs[nc + r] = sj[j];
                }
            for (size_t r = 0; r < k; r++) cp[nc + r] = i;
            nc += k;
            o->other_passes |= k > 0;
        }
        if (nc == 0 || (st = el__fit_feet_project_list(o, v, cp, nc, cs, cd))) continue;
        for (size_t r = 0; r < nc;) {           /* point i's candidates: r .. r2-1 */
            const size_t i = cp[r];
            size_t r2 = r, best = nc;
            double dbest = fabs(d[i]);
            for (; r2 < nc && cp[r2] == i; r2++)
                if (fabs(cd[r2]) < dbest && fabs(cs[r2] - fs[i]) > 1e-3 * L) { dbest = fabs(cd[r2]); best = r2; }
            if (best < nc) {
                d[i] = cd[best];
                fs[i] = cs[best];
                *moved += o->s[i] >= 0.0 && o->s[i] <= L;   /* the extension's feet aside */
            }
            r = r2;
        }
    }
out:
    free(buf);
    free(ord);
    free(unproven);
    return st;
}

int el__fit_curve_feet(fit_objective *ob, double v[2][FIT_NP], double *x, double *d, double *fs)
{
    el__fit_map_inverse(&ob->map, v[0], x);
    if (el__fit_map_eval(&ob->map, x, v, NULL)) return EL_EDOM;
    for (size_t i = 0; i < ob->n; i++) ob->s[i] = ob->t[i] * v[0][6];
    ob->have_base = 0;
    ob->rest_ok = 0;
    size_t moved;
    return el__fit_feet_elsewhere(ob, x, v, d, fs, &moved);
}

/* el__fit_feet_moved, el__fit_nearer_than, el__fit_feet_set: fit_internal.h */
int el__fit_feet_moved(const double *s, const double *fs, size_t n, double L)
{
    int moved = 0;
    for (size_t i = 1; i + 1 < n; i++)
        moved |= s[i] >= 0.0 && s[i] <= L && fabs(fs[i] - s[i]) > 1e-3 * L;
    return moved;
}

int el__fit_nearer_than(const double *d, size_t n, double f)
{
    double s2 = 0.0;
    for (size_t i = 0; i < n; i++) s2 += d[i] * d[i];
    return s2 < 2.0 * (double)n * f * (1.0 - 1e-6);
}

void el__fit_feet_set(fit_objective *ob, const double *fs, double L)
{
    const size_t n = ob->n;
    memcpy(ob->s, fs, sizeof(double) * n);
    if (fit_end_paired(ob, 0)) ob->s[0] = 0.0;
    if (fit_end_paired(ob, n - 1)) ob->s[n - 1] = L;
    ob->have_base = 0;
}
