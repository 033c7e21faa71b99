/*
 * The fit's objective (fit_internal.h), f = (1/2n) sum r^2, and its normal equations
 * g = J^T r / n, H = J^T J / n, computed block by block: a block of FIT_BLOCK samples is
 * evaluated (points and d gamma / d v), its residual rows are formed and folded into
 * 7 x 7 sums per curve, and H = sum_c M_c^T A_c M_c with M_c = d v_c / d x. J is never
 * stored, so memory does not grow with n beyond the foot parameters.
 *
 * Residuals:
 *  paired      r_i = gamma_i - P_i (two rows), seed 000 (4.6);
 *  orthogonal  (smooth) interior points: r_i = N_i . (gamma(s_i) - P_i), the signed
 *              distance along the normal at the foot s_i; the ends: gamma(0) - P_0 and
 *              gamma(L) - P_{n-1} in full (two rows each). The start and the length are
 *              free, so the start slides along the curve until its residual is normal
 *              too: at the optimum the curve begins and ends at the feet of the first
 *              and last points (the tangential part of an end residual is the
 *              derivative of f along that slide). A held end point cannot slide: its
 *              point is then an interior one (fit_end_paired).
 * Why variable projection with feet carried along, and not the feet as Ipopt variables
 * (the arrow-shaped problem of n + 7 variables): measured on 1000 noisy points
 * (bench/bench_fit.c, fit_orthogonal_formulation: same data, start and objective), the
 * arrow problem in Ipopt took 41-67 ms in 4 iterations, this 5-9 ms in 8 (7-8x): each
 * Ipopt iteration factorises an (n + 7)-square KKT matrix with MUMPS and evaluates the
 * curve, its Jacobian and the Hessian's arrow at the feet; here an iteration is one
 * evaluation of points and Jacobian at the feet and a 7 x 7 solve. The row
 * r_i = N_i . J_i is exact at the foot (N . T = 0 and (gamma - P) || N, so d/ds_i and
 * the change of N drop out): the Gauss-Newton matrix of the reduced problem
 * (Kaufman's variable projection), which is also the arrow matrix with the feet
 * eliminated. The feet are not re-projected at each trial point: they are predicted
 * from the last accepted point (foot_shift: the tangential motion of the curve under the
 * step), then moved by one Newton step whose residual error is of third order, and the
 * objective counts the distances at the moved feet (ortho_rows). Results are certified
 * with feet at rest (fit_lm.c), and the reported distances come from an exact projection
 * (fit_feet.c).
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

/* Work buffer: points, Jacobian rows, the walk's block, samples, residual rows by column. */
enum {
    W_XY = 0,
    W_JAC = W_XY + 2 * (FIT_BLOCK + 1),
    W_TMP = W_JAC + 2 * (FIT_BLOCK + 1) * FIT_NP,
    W_S = W_TMP + 2 * (FIT_BLOCK + 2) * (FIT_NP + 1),
    W_COL = W_S + FIT_BLOCK,
    W_RES = W_COL + FIT_NP * 2 * FIT_BLOCK,
    W_SIZE = W_RES + 2 * FIT_BLOCK
};

int el__fit_objective_init(fit_objective *o, int kind, const fit_map *map, const double *xy, size_t n,
                           double cx, double cy, double sc, const double *t)
{
    memset(o, 0, sizeof *o);
    o->kind = kind; o->map = *map; o->n = n; o->xy = xy;
    o->cx = cx; o->cy = cy; o->sc = sc; o->t = t;
    o->f_ceiling = HUGE_VAL;
    o->f_direct = HUGE_VAL;
    o->lm_tol = 1e-13;
    for (int j = 0; j < 4; j++) o->held_ends[j] = NAN;
    const int feet = map->model == FIT_SMOOTH;
    o->work = malloc(sizeof(double) * (W_SIZE + (feet ? 2 * n : 0)));
    if (!o->work) return EL_ENOMEM;
    if (feet) { o->s = o->work + W_SIZE; o->s_next = o->s + n; }
    if (!feet && kind == FIT_ORTHOGONAL) {
        o->poly = malloc(sizeof(double) * 4 * n);
        o->bucket = malloc(sizeof(size_t) * 2 * n);
        if (!o->poly || !o->bucket) { el__fit_objective_free(o); return EL_ENOMEM; }
        o->order = o->bucket + n;
    }
    return EL_OK;
}

void el__fit_objective_free(fit_objective *o)
{
    free(o->work);
    free(o->poly);
    free(o->bucket);
    o->work = NULL;
    o->poly = NULL;
    o->bucket = o->order = NULL;
}

/* Sums of one curve: A = sum row row^T (lower triangle), b = sum row r. */
typedef struct sums {
    double A[FIT_NP][FIT_NP], b[FIT_NP];
} sums;

/*
 * Fold `rows` residual rows, stored by column (col[j * stride + r]), into s. Each
 * entry of A is a dot product of two columns. The dot product runs on pairs of doubles
 * (GCC/Clang vector extension, SSE2 on x86-64) with four partial sums: a reduction the
 * compiler does not reorder by itself. Measured on a 512-row block (the fold compiled
 * alone, CPU time, the shared two-core test machine): a plain loop 33 ns a row, four
 * scalar partial sums (the fallback below; -DFIT_SCALAR_DOT selects it) 9-14 ns, pairs
 * 7-9 ns; -O3 instead of -O2 changed none of them, so no special flags.
 */
#if defined(__GNUC__) && !defined(FIT_SCALAR_DOT)
typedef double pair __attribute__((vector_size(16)));

static double dot(const double *a, const double *b, int m)
{
    pair s0 = {0.0, 0.0}, s1 = s0, s2 = s0, s3 = s0;
    int r = 0;
    for (; r + 8 <= m; r += 8) {
        pair a0, a1, a2, a3, b0, b1, b2, b3;
        memcpy(&a0, a + r, 16); memcpy(&a1, a + r + 2, 16); memcpy(&a2, a + r + 4, 16); memcpy(&a3, a + r + 6, 16);
        memcpy(&b0, b + r, 16); memcpy(&b1, b + r + 2, 16); memcpy(&b2, b + r + 4, 16); memcpy(&b3, b + r + 6, 16);
        s0 += a0 * b0; s1 += a1 * b1; s2 += a2 * b2; s3 += a3 * b3;
    }
    const pair t = (s0 + s1) + (s2 + s3);
    double sum = t[0] + t[1];
    for (; r < m; r++) sum += a[r] * b[r];
    return sum;
}

/* dot(a, b) and dot(a, c) in one pass (a loaded once): the same sums as dot's. */
static void dot2(const double *a, const double *b, const double *c, int m, double *ab, double *ac)
{
    pair s0 = {0.0, 0.0}, s1 = s0, s2 = s0, s3 = s0, u0 = s0, u1 = s0, u2 = s0, u3 = s0;
    int r = 0;
    for (; r + 8 <= m; r += 8) {
        pair a0, a1, a2, a3, x0, x1, x2, x3;
        memcpy(&a0, a + r, 16); memcpy(&a1, a + r + 2, 16); memcpy(&a2, a + r + 4, 16); memcpy(&a3, a + r + 6, 16);
        memcpy(&x0, b + r, 16); memcpy(&x1, b + r + 2, 16); memcpy(&x2, b + r + 4, 16); memcpy(&x3, b + r + 6, 16);
        s0 += a0 * x0; s1 += a1 * x1; s2 += a2 * x2; s3 += a3 * x3;
        memcpy(&x0, c + r, 16); memcpy(&x1, c + r + 2, 16); memcpy(&x2, c + r + 4, 16); memcpy(&x3, c + r + 6, 16);
        u0 += a0 * x0; u1 += a1 * x1; u2 += a2 * x2; u3 += a3 * x3;
    }
    const pair t = (s0 + s1) + (s2 + s3), v = (u0 + u1) + (u2 + u3);
    double sb = t[0] + t[1], sc = v[0] + v[1];
    for (; r < m; r++) { sb += a[r] * b[r]; sc += a[r] * c[r]; }
    *ab = sb;
    *ac = sc;
}

/* dot(a, b) for a = (1, 0, 1, 0, ...) (*even) and a = (0, 1, 0, 1, ...) (*odd) in one
 * pass: the same partial sums in the same order without the products (by 1: exact; by
 * 0: zeros, which change no sum but a zero's sign, and fold adds every dot to a sum
 * that starts at +0, so the sums are the same numbers), the two lanes of b's pairs. */
static void dot_every_other2(const double *b, int m, double *even, double *odd)
{
    pair s0 = {0.0, 0.0}, s1 = s0, s2 = s0, s3 = s0;
    int r = 0;
    for (; r + 8 <= m; r += 8) {
        pair b0, b1, b2, b3;
        memcpy(&b0, b + r, 16); memcpy(&b1, b + r + 2, 16); memcpy(&b2, b + r + 4, 16); memcpy(&b3, b + r + 6, 16);
        s0 += b0; s1 += b1; s2 += b2; s3 += b3;
    }
    const pair t = (s0 + s1) + (s2 + s3);
    double sum[2] = {t[0], t[1]};
    for (; r < m; r++) sum[r & 1] += b[r];
    *even = sum[0];
    *odd = sum[1];
}
#else
static double dot(const double *a, const double *b, int m)
{
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    int r = 0;
    for (; r + 4 <= m; r += 4) {
        s0 += a[r] * b[r]; s1 += a[r + 1] * b[r + 1];
        s2 += a[r + 2] * b[r + 2]; s3 += a[r + 3] * b[r + 3];
    }
    for (; r < m; r++) s0 += a[r] * b[r];
    return (s0 + s1) + (s2 + s3);
}

/* dot(a, b) for a = (1, 0, 1, 0, ...) (parity 0) or (0, 1, 0, 1, ...) (parity 1), as
 * dot_every_other2 above */
static double dot_every_other(const double *b, int m, int parity)
{
    double s[4] = {0.0, 0.0, 0.0, 0.0};
    int r = 0;
    for (; r + 4 <= m; r += 4) { s[parity] += b[r + parity]; s[parity + 2] += b[r + 2 + parity]; }
    for (; r < m; r++)
        if ((r & 1) == parity) s[0] += b[r];
    return (s[0] + s[1]) + (s[2] + s[3]);
}

static void dot2(const double *a, const double *b, const double *c, int m, double *ab, double *ac)
{
    *ab = dot(a, b, m);
    *ac = dot(a, c, m);
}

static void dot_every_other2(const double *b, int m, double *even, double *odd)
{
    *even = dot_every_other(b, m, 0);
    *odd = dot_every_other(b, m, 1);
}
#endif

/* b[a] += ca.res and A[a][b] += ca.cb for b = b0..a, two at a time (dot2). */
static void fold_column(sums *s, int a, int b0, const double *col, int stride, const double *res, int rows)
{
    const double *ca = col + a * stride, *with[FIT_NP + 1];
    double *out[FIT_NP + 1], e, o;
    int k = 0;
    out[k] = &s->b[a]; with[k++] = res;
    for (int b = b0; b <= a; b++) { out[k] = &s->A[a][b]; with[k++] = col + b * stride; }
    for (int j = 0; j + 1 < k; j += 2) {
        dot2(ca, with[j], with[j + 1], rows, &e, &o);
        *out[j] += e;
        *out[j + 1] += o;
    }
    if (k % 2) *out[k - 1] += dot(ca, with[k - 1], rows);
}

static void fold(sums *s, const double *col, int stride, const double *res, int rows)
{
    for (int a = 0; a < FIT_NP; a++) fold_column(s, a, 0, col, stride, res, rows);
}

/* fold for rows (x, y) of points paired with a discrete curve's vertices, whose first
 * two columns, d/dx0 and d/dy0, are (1, 0, 1, 0, ...) and (0, 1, 0, 1, ...) (not stored:
 * el__fit_discrete_rows writes columns 2..6): their dot products as sums of every other entry (the same
 * numbers; 15 of the 35 products), their products with each other the counts of ones
 * (exact, as dot sums them) and 0 (which adds nothing to a sum that starts at +0). */
static void fold_paired(sums *s, const double *col, int stride, const double *res, int rows)
{
    double e, o;
    s->A[0][0] += (double)((rows + 1) / 2);
    s->A[1][1] += (double)(rows / 2);
    dot_every_other2(res, rows, &e, &o);
    s->b[0] += e;
    s->b[1] += o;
    for (int a = 2; a < FIT_NP; a++) {
        const double *ca = col + a * stride;
        dot_every_other2(ca, rows, &e, &o);
        s->A[a][0] += e;
        s->A[a][1] += o;
        fold_column(s, a, 2, col, stride, res, rows);
    }
}

/* Residual rows of paired points: gamma_i - P_g for the m samples, g = first + step i;
 * the Jacobian's rows jac (when not NULL) to columns. */
static double paired_rows(const fit_objective *o, const double *xy, const double *jac, size_t m,
                          size_t first, long step, double *col, double *res)
{
    double f = 0.0;
    const int stride = 2 * FIT_BLOCK;
    for (size_t i = 0; i < m; i++) {
        double P[2];
        fit_point(o, (size_t)((long)first + step * (long)i), P);
        for (int c = 0; c < 2; c++) {
            const size_t r = 2 * i + c;
            const double d = xy[r] - P[c];
            res[r] = d;
            f += d * d;
            if (jac)
                for (int j = 0; j < FIT_NP; j++) col[j * stride + r] = jac[r * FIT_NP + j];
        }
    }
    return f;
}

/* The discrete curve's vertices j < nv paired with data points first + step j; the
 * rows of vertex 0 left out when skip0 (the keyline's joint, paired once). */
static int discrete_paired(fit_objective *o, const double *v, size_t nv, size_t first, long step,
                           int skip0, int want, sums *S, double *f)
{
    double *w = o->work, *xy = w + W_XY, *col = w + W_COL, *res = w + W_RES;
    fit_walk walk;
    el__fit_walk_start(v, &walk);
    size_t done = 0;
    int st;
    while (done < nv) {
        const size_t m = nv - done < FIT_BLOCK ? nv - done : FIT_BLOCK;
        if ((st = el__fit_discrete_rows(v, &walk, m, xy, want ? col : NULL, 2 * FIT_BLOCK, w + W_TMP))) return st;
        const size_t k0 = done == 0 && skip0 ? 1 : 0;
        const size_t g0 = (size_t)((long)first + step * (long)(done + k0));
        if (want) {
            *f += paired_rows(o, xy + 2 * k0, NULL, m - k0, g0, step, NULL, res);
            fold_paired(S, col + 2 * k0, 2 * FIT_BLOCK, res, (int)(2 * (m - k0)));
        } else {
            for (size_t i = k0; i < m; i++) {
                double P[2];
                fit_point(o, (size_t)((long)first + step * (long)(done + i)), P);
                const double dx = xy[2 * i] - P[0], dy = xy[2 * i + 1] - P[1];
                *f += dx * dx + dy * dy;
            }
        }
        done += m;
    }
    return EL_OK;
}

/*
 * Discrete orthogonal: each point's distance to the polygon of the n vertices, its foot
 * projected exactly at every evaluation (el__fit_polygon_distances, O(n) from the point's
 * vertex). Interior points: r_i = |P_i - gamma(sigma_i)|, gamma(sigma) = (1-t) V_j +
 * t V_{j+1}, with the row -u_i . d gamma(sigma_i) / dv at the foot held (u_i the unit
 * vector from the foot to the point): exact, as the distance's derivative along the
 * polygon vanishes at an interior foot, and at a vertex foot it is |P - V_j| (variable
 * projection, as the smooth fit's). The ends V_0 - P_0 and V_{n-1} - P_{n-1} in full, so
 * the polygon spans the data (its length (n-1) h is otherwise free beyond the ends).
 * The Jacobian is walked in blocks of vertices; the points, bucketed by their foot's
 * segment, are folded in chunks of at most FIT_BLOCK rows.
 */
static int discrete_orthogonal(fit_objective *o, const double *v, int want, sums *S, double *f)
{
    const size_t n = o->n;
    double *w = o->work, *jac = w + W_JAC, *col = w + W_COL, *res = w + W_RES;
    double *V = o->poly, *dist = V + 2 * n, *foot = dist + n;
    fit_walk walk;
    el__fit_walk_start(v, &walk);
    int st;
    for (size_t a = 0; a < n; a += FIT_BLOCK) {
        const size_t m = n - a < FIT_BLOCK ? n - a : FIT_BLOCK;
        if ((st = el__fit_discrete_rows(v, &walk, m, V + 2 * a, NULL, 0, w + W_TMP))) return st;
    }
    const double h = v[2];
    el__fit_polygon_distances(o, V, n, h, 0, 1, dist, foot);
    double P0[2], P1[2];
    fit_point(o, 0, P0);
    fit_point(o, n - 1, P1);
    const double e[4] = {V[0] - P0[0], V[1] - P0[1], V[2 * n - 2] - P1[0], V[2 * n - 1] - P1[1]};
    for (int c = 0; c < 4; c++) *f += e[c] * e[c];
    for (size_t i = 1; i + 1 < n; i++) *f += dist[i] * dist[i];
    if (!want) return EL_OK;
    /* counting sort of the interior points by segment */
    size_t *cnt = o->bucket, *ord = o->order;
    memset(cnt, 0, sizeof(size_t) * n);
    for (size_t i = 1; i + 1 < n; i++) cnt[(size_t)fit_clamp(floor(foot[i] / h), 0.0, (double)n - 2.0)]++;
    for (size_t j = 0, sum = 0; j < n; j++) { const size_t c = cnt[j]; cnt[j] = sum; sum += c; }
    for (size_t i = 1; i + 1 < n; i++) ord[cnt[(size_t)fit_clamp(floor(foot[i] / h), 0.0, (double)n - 2.0)]++] = i;
    /* cnt[j] is now the end of segment j's points in ord */
    el_discrete_params dp;
    double dq_dk = 0.0;
    if ((st = el__fit_to_discrete(v, &dp, &dq_dk))) return st;
    const int stride = 2 * FIT_BLOCK;
    int rows = 0;
    size_t next = 0;          /* the next position in ord */
    el__fit_walk_start(v, &walk);
    for (size_t a = 0; a < n; a += FIT_BLOCK) {
        const size_t m = n - a < FIT_BLOCK ? n - a : FIT_BLOCK;
        double xy[2 * (FIT_BLOCK + 1)];
        if ((st = el__fit_discrete_rows(v, &walk, m, xy, jac, 0, w + W_TMP))) return st;
        /* vertex a + m's derivative (the walk's, before the k < 0 column change) */
        double dn[2][FIT_NP];
        memcpy(dn, walk.d, sizeof dn);
        if (v[6] < 0.0)
            for (int c = 0; c < 2; c++) dn[c][6] = -(dn[c][6] + dq_dk * dn[c][5]);
        for (size_t j = a; j < a + m; j++) {
            const double *dj = jac + 2 * (j - a) * FIT_NP;
            const double *dk = j + 1 < a + m ? jac + 2 * (j + 1 - a) * FIT_NP : dn[0];
            const int end = j == 0 ? 0 : j == n - 1 ? 1 : -1;
            if (end >= 0) {         /* an end's full residual */
                for (int c = 0; c < 2; c++, rows++) {
                    res[rows] = e[2 * end + c];
                    for (int q = 0; q < FIT_NP; q++) col[q * stride + rows] = dj[c * FIT_NP + q];
                }
            }
            for (; j + 1 < n && next < cnt[j]; next++) {
                const size_t i = ord[next];
                double P[2];
                fit_point(o, i, P);
                const double t = fit_clamp(foot[i] / h - (double)j, 0.0, 1.0);
                const double gx = (1.0 - t) * V[2 * j] + t * V[2 * j + 2], gy = (1.0 - t) * V[2 * j + 1] + t * V[2 * j + 3];
                double ux = P[0] - gx, uy = P[1] - gy;
                const double d = fit_norm(ux, uy);
                if (d > 0.0) { ux /= d; uy /= d; }
                else {              /* on the polygon: its left normal */
                    const double sx = V[2 * j + 2] - V[2 * j], sy = V[2 * j + 3] - V[2 * j + 1], l = fit_norm(sx, sy);
                    ux = l > 0.0 ? -sy / l : 0.0; uy = l > 0.0 ? sx / l : 0.0;
                }
                res[rows] = d;
                for (int q = 0; q < FIT_NP; q++)
                    col[q * stride + rows] = -(ux * ((1.0 - t) * dj[q] + t * dk[q]) +
                                               uy * ((1.0 - t) * dj[FIT_NP + q] + t * dk[FIT_NP + q]));
                if (++rows >= stride - 2) { fold(S, col, stride, res, rows); rows = 0; }
            }
            if (rows >= stride - 2) { fold(S, col, stride, res, rows); rows = 0; }
        }
    }
    if (rows) fold(S, col, stride, res, rows);
    return EL_OK;
}

static int smooth_paired(fit_objective *o, const double *v, int want, sums *S, double *f)
{
    double *w = o->work, *xy = w + W_XY, *jac = w + W_JAC, *s = w + W_S, *col = w + W_COL,
           *res = w + W_RES;
    int st;
    for (size_t a = 0; a < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - a < FIT_BLOCK ? o->n - a : FIT_BLOCK;
        for (size_t i = 0; i < m; i++) s[i] = o->t[a + i] * v[6];
        if ((st = el__fit_smooth_rows(v, m, s, xy, want ? jac : NULL))) return st;
        if (want) {
            *f += paired_rows(o, xy, jac, m, a, 1, col, res);
            fold(S, col, 2 * FIT_BLOCK, res, (int)(2 * m));
        } else {
            for (size_t i = 0; i < m; i++) {
                double P[2];
                fit_point(o, a + i, P);
                const double dx = xy[2 * i] - P[0], dy = xy[2 * i + 1] - P[1];
                *f += dx * dx + dy * dy;
            }
        }
    }
    return EL_OK;
}

/* The start of a smooth curve: unit tangent R(phi) (1 - 2k^2 sn^2, 2k sn dn) at u = q
 * (smooth.c) and curvature 2 k w cn q, for any signs of w and k. */
static int start_state(const double *v, double *T0, double *kappa0)
{
    el_jacobi J;
    if (el_jacobi_eval(v[5], fabs(v[4]), &J, NULL, NULL)) return EL_EDOM;
    const double k = v[4], tx = 1.0 - 2.0 * k * k * J.sn * J.sn, ty = 2.0 * k * J.sn * J.dn;
    const double c = cos(v[2]), sp = sin(v[2]);
    T0[0] = c * tx - sp * ty;
    T0[1] = sp * tx + c * ty;
    *kappa0 = 2.0 * k * v[3] * J.cn;
    return EL_OK;
}

/*
 * Orthogonal residual rows of the m samples of one smooth curve at s[i] (the block's
 * points idx[i]; end[i]: 0 interior, 1 an end point with its full residual), appended
 * at *rows; the objective at the feet after one Newton step, and those feet s_new[i].
 * Everything comes from the one evaluation of points and Jacobian at s:
 *   T(s) = w d gamma/dq + T(0)                (u = w s + q; smooth.c's closed form),
 *   kappa(s) = kappa(0) - w^2 Y(s)            (curvature affine in the position, seed 000
 *                                              (4.25); Y = the rotated frame's y of gamma - gamma0),
 * and with gamma - P = t T + e N the foot moves by u = -t / (1 + kappa e) (Newton), after
 * which |gamma(s + u) - P|^2 = (t + u)^2 + (e + kappa u^2 / 2)^2 + O(u^3): the value
 * counted, so a step's gain is measured at the moved feet; the row is that foot's too.
 */
typedef struct ortho_block {
    const double *v;
    size_t m;
    const double *s;
    const size_t *idx;
    const unsigned char *end;
    double lo, hi;           /* the foot's range on this curve */
    double *rest;            /* o->rest (one curve) or NULL */
} ortho_block;

static int ortho_rows(fit_objective *o, const ortho_block *b, int want, double *col, double *res,
                      int *rows, double *f, double *s_new)
{
    double *w = o->work, *xy = w + W_XY, *jac = w + W_JAC, T0[2], kappa0;
    int st = el__fit_smooth_rows(b->v, b->m, b->s, xy, jac);
    if (st || (st = start_state(b->v, T0, &kappa0))) return st;
    const double wv = b->v[3], w2 = wv * wv, cp = cos(b->v[2]), sp = sin(b->v[2]);
    const int stride = 2 * FIT_BLOCK;
    for (size_t i = 0; i < b->m; i++) {
        const double *jx = jac + 2 * i * FIT_NP, *jy = jx + FIT_NP;
        double P[2];
        fit_point(o, b->idx[i], P);
        const double gx = xy[2 * i], gy = xy[2 * i + 1], dx = gx - P[0], dy = gy - P[1];
        s_new[i] = b->s[i];
        if (b->rest) b->rest[b->idx[i]] = NAN;
        if (b->end[i]) {
            *f += dx * dx + dy * dy;
            if (want) {
                const int r = (*rows)++, r2 = (*rows)++;
                res[r] = dx; res[r2] = dy;
                for (int j = 0; j < FIT_NP; j++) { col[j * stride + r] = jx[j]; col[j * stride + r2] = jy[j]; }
            }
            continue;
        }
        double Tx = wv * jx[5] + T0[0], Ty = wv * jy[5] + T0[1];
        const double tn = fit_norm(Tx, Ty);
        Tx /= tn; Ty /= tn;
        const double t = Tx * dx + Ty * dy, e = Ty * -dx + Tx * dy;   /* e = N . (gamma - P) */
        double ex = -Ty, ey = Tx, r = e, d2;
        if ((b->s[i] <= b->lo && t > 0.0) || (b->s[i] >= b->hi && t < 0.0)) {
            /* the foot held at an end of the extended curve, the point beyond it: the
             * distance to that end point */
            const double d = fit_norm(dx, dy);
            if (d > 0.0) { ex = dx / d; ey = dy / d; r = d; }
            d2 = dx * dx + dy * dy;
        } else {
            const double kappa = kappa0 - w2 * (-sp * (gx - b->v[0]) + cp * (gy - b->v[1]));
            const double u = fit_clamp(b->s[i] + fit_foot_step(t, e, kappa, b->v[6]), b->lo, b->hi) - b->s[i];
            const double a = t + u, c = e + 0.5 * kappa * u * u;
            d2 = a * a + c * c;
            s_new[i] = b->s[i] + u;
            o->last_move = fmax(o->last_move, fabs(u));
            if (b->rest && fabs(u) <= 1e-7 * (b->v[6] + 1e-300) && s_new[i] >= 0.0 && s_new[i] <= b->v[6]) {
                const double d = sqrt(d2);
                b->rest[b->idx[i]] = c > 0.0 ? -d : d;    /* as project_block's */
                o->rest_foot[b->idx[i]] = s_new[i];
            }
            /* the row of the moved foot: its residual c, its normal N turned by kappa u
             * (to first order N - kappa u T), so that f, g and H describe the same point */
            r = c;
            ex = -Ty - kappa * u * Tx;
            ey = Tx - kappa * u * Ty;
            const double en = fit_norm(ex, ey);
            ex /= en; ey /= en;
        }
        *f += d2;
        if (want) {
            const int q = (*rows)++;
            res[q] = r;
            for (int j = 0; j < FIT_NP; j++) col[j * stride + q] = ex * jx[j] + ey * jy[j];
        }
    }
    return EL_OK;
}

/*
 * Where a foot goes when the variables change by dx: the point gamma(s) moves by
 * (d gamma/dx) dx, its foot by minus the tangential part, ds = -b(s) . dx with
 * b = (d gamma / dx)^T T. b is smooth in s and is sampled at FIT_KNOTS arc lengths of
 * the base curve (the last accepted point) and interpolated linearly; the feet of a
 * trial point then start within second order of their place, as if the feet were
 * variables of the step (the arrow-shaped Gauss-Newton step, eliminated). The length
 * column is dropped: a foot at fixed s does not move with L (smooth.c's column is at
 * fixed s / L). The prediction is linear in x, not in the curve's parameters v: near a
 * circle a small step of the shape variables changes k, w and q by amounts whose
 * effects on the curve cancel to first order only (measured: k 16.6 -> 15 in a step
 * of 0.003, the feet predicted in v half a radius off and the step rejected seven
 * times; in x the first step is accepted).
 */
static int base_knots(fit_objective *o, int c, const double *v, const double *M)
{
    double s[FIT_KNOTS], *xy = o->work + W_XY, *jac = o->work + W_JAC, T0[2], kappa0;
    const int nx = o->map.nx;
    int st = start_state(v, T0, &kappa0);
    for (int j = 0; j < FIT_KNOTS; j++) s[j] = v[6] * (double)j / (double)(FIT_KNOTS - 1);
    if (st || (st = el__fit_smooth_rows(v, FIT_KNOTS, s, xy, jac))) return st;
    for (int j = 0; j < FIT_KNOTS; j++) {
        const double *jx = jac + 2 * j * FIT_NP, *jy = jx + FIT_NP;
        double Tx = v[3] * jx[5] + T0[0], Ty = v[3] * jy[5] + T0[1], b[FIT_NP];
        const double tn = fit_norm(Tx, Ty);
        Tx /= tn; Ty /= tn;
        for (int a = 0; a < FIT_NP; a++) b[a] = a == 6 ? 0.0 : Tx * jx[a] + Ty * jy[a];
        for (int i = 0; i < nx; i++) {
            double t = 0.0;
            for (int a = 0; a < FIT_NP; a++) t += b[a] * M[a * nx + i];
            o->knot_b[c][j][i] = t;
        }
    }
    o->base_len[c] = v[6];
    return EL_OK;
}

/* The shifts at the knots for the step of this evaluation, -b(s_j) . dx (each foot
 * then interpolates two of them). */
static void knot_shifts(fit_objective *o)
{
    for (int c = 0; c < o->map.ncurves; c++)
        for (int j = 0; j < FIT_KNOTS; j++) {
            double ds = 0.0;
            for (int i = 0; i < o->map.nx; i++) ds -= o->knot_b[c][j][i] * o->step[i];
            o->knot_ds[c][j] = ds;
        }
}

static double foot_shift(const fit_objective *o, int c, double s)
{
    if (!o->have_base || o->exact_feet) return 0.0;
    const double L = o->base_len[c];
    const double pos = L > 0.0 ? fit_clamp(s / L, 0.0, 1.0) * (FIT_KNOTS - 1) : 0.0;
    const int j = pos >= FIT_KNOTS - 1 ? FIT_KNOTS - 2 : (int)pos;
    const double f = pos - j;
    return (1.0 - f) * o->knot_ds[c][j] + f * o->knot_ds[c][j + 1];
}

/* Orthogonal objective of one smooth curve. */
static int smooth_orthogonal(fit_objective *o, const double *v, int want, sums *S, double *f)
{
    double *w = o->work, *s = w + W_S, *col = w + W_COL, *res = w + W_RES;
    size_t idx[FIT_BLOCK];
    unsigned char end[FIT_BLOCK];
    const double L = v[6];
    double vv[2][FIT_NP], lo, hi;
    memcpy(vv[0], v, sizeof vv[0]);
    el__fit_feet_range(o, vv, 1, &lo, &hi);
    int st;
    for (size_t a = 0; a < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - a < FIT_BLOCK ? o->n - a : FIT_BLOCK;
        for (size_t i = 0; i < m; i++) {
            const size_t g = a + i;
            idx[i] = g;
            end[i] = fit_end_paired(o, g);
            s[i] = !end[i] ? fit_clamp(o->s[g] + foot_shift(o, 0, o->s[g]), lo, hi)
                 : g == 0  ? 0.0 : L;
        }
        ortho_block b = {v, m, s, idx, end, lo, hi, o->rest_foot ? o->rest : NULL};
        int rows = 0;
        if ((st = ortho_rows(o, &b, want, col, res, &rows, f, o->s_next + a))) return st;
        if (want) fold(S, col, 2 * FIT_BLOCK, res, rows);
    }
    return EL_OK;
}

/*
 * The keyline, smooth: sigma_i < 0 lies on the first curve at s = -sigma, sigma >= 0 on
 * the second at s = sigma; both start at the joint. Point 0 is the first curve's end,
 * point n-1 the second's.
 */
static int keyline_smooth(fit_objective *o, double v[2][FIT_NP], int want, sums S[2], double *f)
{
    double *w = o->work, *s = w + W_S, *col = w + W_COL, *res = w + W_RES;
    size_t idx[FIT_BLOCK];
    unsigned char end[FIT_BLOCK];
    double snew[FIT_BLOCK];
    int st;
    for (size_t a = 0; a < o->n; a += FIT_BLOCK) {
        const size_t m = o->n - a < FIT_BLOCK ? o->n - a : FIT_BLOCK;
        for (int c = 0; c < 2; c++) {
            const double L = v[c][6];
            double lo, hi;
            el__fit_feet_range(o, v, 1, &lo, &hi);
            const double far = c == 0 ? -lo : hi;
            size_t cnt = 0;
            for (size_t i = 0; i < m; i++) {
                const size_t g = a + i;
                double sig = o->s[g];
                if (g != 0 && g != o->n - 1)          /* sigma < 0 runs against s */
                    sig += sig < 0.0 ? -foot_shift(o, 0, -sig) : foot_shift(o, 1, sig);
                const int on_first = g == 0 || (g != o->n - 1 && sig < 0.0);
                if (on_first != (c == 0)) continue;
                idx[cnt] = g;
                end[cnt] = g == 0 || g == o->n - 1;
                s[cnt] = end[cnt] ? L : fmin(fabs(sig), far);
                cnt++;
            }
            if (cnt == 0) continue;
            /* no lower clamp: a foot passing the joint continues on the other curve */
            ortho_block b = {v[c], cnt, s, idx, end, -HUGE_VAL, far, NULL};
            int rows = 0;
            if ((st = ortho_rows(o, &b, want, col, res, &rows, f, snew))) return st;
            if (want) fold(&S[c], col, 2 * FIT_BLOCK, res, rows);
            for (size_t i = 0; i < cnt; i++) o->s_next[idx[i]] = c == 0 ? -snew[i] : snew[i];
        }
    }
    return EL_OK;
}

int el__fit_objective_eval(fit_objective *o, const double *x, int want_normal, fit_value *out)
{
    const fit_map *m = &o->map;
    const int nx = m->nx, nc = m->ncurves;
    double v[2][FIT_NP], M[2][FIT_NP * FIT_MAXX];
    int st = el__fit_map_eval(m, x, v, want_normal ? M[0] : NULL);
    if (st) return st;
    memcpy(o->last_x, x, sizeof(double) * (size_t)nx);
    for (int i = 0; i < nx; i++) o->step[i] = x[i] - o->base_x[i];
    if (o->have_base && !o->exact_feet && fit_has_feet(o)) knot_shifts(o);
    o->last_move = 0.0;
    if (o->exact_feet && fit_has_feet(o) && (st = el__fit_objective_project(o, x))) return st;
    sums S[2];
    memset(S, 0, sizeof S);
    double f = 0.0;
    if (o->kind == FIT_KEYLINE && m->model == FIT_SMOOTH) {
        st = keyline_smooth(o, v, want_normal, S, &f);
    } else if (o->kind == FIT_KEYLINE) {
        /* first curve: vertices 0..split <-> points split..0; second: vertices 1.. <->
         * points split+1.. (its vertex 0 is the shared joint, paired once) */
        st = discrete_paired(o, v[0], o->split + 1, o->split, -1, 0, want_normal, &S[0], &f);
        if (!st) st = discrete_paired(o, v[1], o->n - o->split, o->split, 1, 1, want_normal, &S[1], &f);
    } else if (m->model == FIT_DISCRETE && o->kind == FIT_ORTHOGONAL) {
        st = discrete_orthogonal(o, v[0], want_normal, &S[0], &f);
    } else if (m->model == FIT_DISCRETE) {
        st = discrete_paired(o, v[0], o->n, 0, 1, 0, want_normal, &S[0], &f);
    } else if (o->kind == FIT_PAIRED) {
        st = smooth_paired(o, v[0], want_normal, &S[0], &f);
    } else {
        o->rest_ok = 0;
        memcpy(o->rest_x, x, sizeof(double) * (size_t)nx);
        st = smooth_orthogonal(o, v[0], want_normal, &S[0], &f);
        o->rest_ok = !st && o->rest && o->rest_foot;
    }
    if (st) return st;
    const double inv = 1.0 / (double)o->n;
    out->f = 0.5 * f * inv;
    double pc[FIT_NCON], pJ[FIT_NCON * FIT_MAXX];
    int prows = 0;
    if (o->pen) {
        prows = el__fit_constraint_rows(o, o->pen, x, pc, want_normal ? pJ : NULL, NULL, o->pen_tmp);
        if (prows < 0) return EL_EDOM;
        for (int r = 0; r < prows; r++) out->f += 0.5 * o->pen_rho * pc[r] * pc[r];
    }
    if (!isfinite(out->f)) return EL_EDOM;
    if (!want_normal) return EL_OK;
    /* H = sum_c M_c^T A_c M_c, g = sum_c M_c^T b_c (A_c symmetric from its lower triangle) */
    memset(out->g, 0, sizeof out->g);
    memset(out->H, 0, sizeof out->H);
    for (int c = 0; c < nc; c++) {
        double A[FIT_NP][FIT_NP], AM[FIT_NP][FIT_MAXX];
        for (int a = 0; a < FIT_NP; a++)
            for (int b = 0; b <= a; b++) A[a][b] = A[b][a] = S[c].A[a][b];
        const double *Mc = M[c];
        for (int a = 0; a < FIT_NP; a++)
            for (int j = 0; j < nx; j++) {
                double t = 0.0;
                for (int b = 0; b < FIT_NP; b++) t += A[a][b] * Mc[b * nx + j];
                AM[a][j] = t;
            }
        for (int i = 0; i < nx; i++) {
            double gi = 0.0;
            for (int a = 0; a < FIT_NP; a++) gi += Mc[a * nx + i] * S[c].b[a];
            out->g[i] += gi * inv;
            for (int j = 0; j <= i; j++) {
                double t = 0.0;
                for (int a = 0; a < FIT_NP; a++) t += Mc[a * nx + i] * AM[a][j];
                out->H[i * nx + j] += t * inv;
            }
        }
    }
    for (int r = 0; r < prows; r++)
        for (int i = 0; i < nx; i++) {
            out->g[i] += o->pen_rho * pJ[r * nx + i] * pc[r];
            for (int j = 0; j <= i; j++) out->H[i * nx + j] += o->pen_rho * pJ[r * nx + i] * pJ[r * nx + j];
        }
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < i; j++) out->H[j * nx + i] = out->H[i * nx + j];
    if (el__all_finite(out->g, (size_t)nx) || el__all_finite(out->H, (size_t)(nx * nx))) return EL_EDOM;
    return EL_OK;
}

void el__fit_objective_accept(fit_objective *o)
{
    if (!fit_has_feet(o) || o->exact_feet) return;
    double *t = o->s;
    o->s = o->s_next;
    o->s_next = t;
    memcpy(o->base_x, o->last_x, sizeof o->base_x);
    double v[2][FIT_NP], M[2][FIT_NP * FIT_MAXX];
    o->have_base = el__fit_map_eval(&o->map, o->base_x, v, M[0]) == EL_OK;
    for (int c = 0; c < o->map.ncurves && o->have_base; c++)
        if (base_knots(o, c, v[c], M[c])) o->have_base = 0;
}
