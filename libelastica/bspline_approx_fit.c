/*
 * The least-squares B-spline of an elastica on a grid of exact samples, and the
 * certified distance between the two (bspline_approx.c chooses the knots and drives
 * the search). GSL does the linear algebra (banded Cholesky of the normal
 * equations) and the local maximisation (Brent).
 *
 *  - the B-spline is parametrised by the arc length s of the elastica on
 *    [0, length]; poles by linear least squares on a uniform grid of exact samples
 *    gamma(s_i) (at least 3(p+1) in the smallest span), the first two and last
 *    two poles fixed so that B(0) = gamma(0), B(L) = gamma(L) and B'(0), B'(L)
 *    are the exact unit tangents (el__approx_poles()): both ends are interpolated
 *    with the elastica's tangent (G1 joins to other geometry stay exact);
 *  - the distance: for t in [0, L], the foot point on the elastica is
 *    s1(t) = clamp(t + Delta), Delta = e.T / max(1 - kappa e.N, 1/2) (one
 *    Newton step on (B(t) - gamma(s)).T(s) = 0 from s = t, e = B(t) - gamma(t)),
 *    and d(t) = |B(t) - gamma(s1(t))|. As s1 is continuous with s1(0) = 0 and
 *    s1(L) = L, every point of either curve is within max d of the other: max d
 *    bounds the Hausdorff distance from above, and it is within rounding of it
 *    because the Newton step leaves an O(|e|^2 kappa) foot-point error that
 *    changes d only to second order; gamma(s1) comes from the Taylor expansion
 *    at t plus a bound of its remainder (taylor_distance()), so d stays an
 *    upper bound;
 *  - certification (el__approx_certify()): d at every grid point from the exact
 *    gamma, theta, kappa there, then Brent (GSL) maximisation of d around the
 *    grid's local maxima (exact evaluation at every step), largest predicted
 *    first; reported with 16 eps (|x0| + |y0| + L) added for the rounding of the
 *    evaluations.
 * Cost: the least-squares fits dominate the approximation, so the loops avoid
 * divisions (the knot differences of a span are inverted once, span_recips()), are
 * unrolled for p = 3 (FIT_INLINE/FIT_UNROLL), sum a span's normal equations in
 * registers and compare squared distances while steering. These change only the
 * rounding, not the algorithm.
 */
#include "bspline_approx.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_vector.h>

void el__approx_free(fit_ws *w)
{
    free(w->s); free(w->xy); free(w->th); free(w->ka); free(w->cs); free(w->Bc); free(w->kc);
    free(w->U); free(w->AB); free(w->bx); free(w->by); free(w->err); free(w->dist);
}

/* (Re)sample the exact curve on a uniform grid of M+1 points (el_smooth_eval
 * takes the addition-theorem path for equally spaced s). */
int el__approx_grid(fit_ws *w, size_t M)
{
    free(w->s); free(w->xy); free(w->th); free(w->ka); free(w->dist);
    free(w->cs); free(w->Bc); free(w->kc);
    w->cs = malloc(2 * (M + 1) * sizeof *w->cs);
    w->Bc = malloc((M + 1) * (size_t)(w->p + 1) * sizeof *w->Bc);
    w->kc = malloc((M + 1) * sizeof *w->kc);
    w->s = malloc((M + 1) * sizeof *w->s);
    w->xy = malloc(2 * (M + 1) * sizeof *w->xy);
    w->th = malloc((M + 1) * sizeof *w->th);
    w->ka = malloc((M + 1) * sizeof *w->ka);
    w->dist = malloc((M + 1) * sizeof *w->dist);
    w->M = M;
    if (!w->s || !w->xy || !w->th || !w->ka || !w->dist || !w->cs || !w->Bc || !w->kc)
        return EL_ENOMEM;
    for (size_t i = 0; i <= M; i++) w->s[i] = w->L * (double)i / (double)M;
    w->s[M] = w->L;
    int st = el_smooth_eval(w->par, M + 1, w->s, w->xy, w->th, w->ka);
    /* the ends exactly as a single-point el_smooth_eval gives them (they become
     * the fixed end poles and tangents, el__approx_poles), not with the rounding of
     * the progression */
    if (!st) st = el_smooth_eval(w->par, 1, &w->s[0], w->xy, w->th, w->ka);
    if (!st) st = el_smooth_eval(w->par, 1, &w->s[M], w->xy + 2 * M, w->th + M, w->ka + M);
    for (size_t i = 0; i <= M && !st; i++) {
        w->cs[2 * i] = cos(w->th[i]);
        w->cs[2 * i + 1] = sin(w->th[i]);
    }
    return st;
}

int el__approx_reserve(fit_ws *w, size_t N)
{
    if (N <= w->cap) return EL_OK;
    size_t cap = N + N / 2 + 8;
    const size_t p = (size_t)w->p;
    double *U = realloc(w->U, (cap + 2 * p + 1) * sizeof *U);
    if (U) w->U = U;
    double *AB = realloc(w->AB, (cap + p) * (p + 1) * sizeof *AB);
    if (AB) w->AB = AB;
    double *bx = realloc(w->bx, (cap + p) * sizeof *bx);
    if (bx) w->bx = bx;
    double *by = realloc(w->by, (cap + p) * sizeof *by);
    if (by) w->by = by;
    double *err = realloc(w->err, cap * sizeof *err);
    if (err) w->err = err;
    if (!U || !AB || !bx || !by || !err) return EL_ENOMEM;
    w->cap = cap;
    return EL_OK;
}

/* Flat clamped knots from breaks[0..N] (breaks[0] = 0, breaks[N] = L). */
void el__approx_set_knots(fit_ws *w, size_t N, const double *breaks)
{
    const size_t p = (size_t)w->p;
    for (size_t i = 0; i <= p; i++) { w->U[i] = 0.0; w->U[N + p + i] = w->L; }
    for (size_t j = 1; j < N; j++) w->U[p + j] = breaks[j];
}

/* Enough grid points in the smallest span: at least 3(p+1). */
int el__approx_ensure_grid(fit_ws *w, size_t N, const double *breaks)
{
    double hmin = w->L;
    for (size_t j = 0; j < N; j++) hmin = fmin(hmin, breaks[j + 1] - breaks[j]);
    const double need = 3.0 * (w->p + 1) * w->L / hmin;
    if ((double)w->M >= need) return EL_OK;
    if (need > 4e6) return EL_EMAXITER;   /* knots finer than the arithmetic can use */
    return el__approx_grid(w, (size_t)ceil(fmax(1.25 * need, 1.5 * (double)w->M)));
}

/*
 * Least squares for the poles with both end points and both end tangents
 * imposed (n = N + p poles, flat clamped knots U_0 = .. = U_p = 0,
 * U_{n} = .. = U_{n+p} = L). The first derivative poles (Piegl & Tiller (3.8))
 * give at the ends
 *   B'(0) = p (P_1 - P_0) / (U_{p+1} - U_1),
 *   B'(L) = p (P_{n-1} - P_{n-2}) / (U_{n+p-1} - U_{n-1}),
 * with U_1 = 0 and U_{n+p-1} = L, so with the exact unit tangents
 * T_0 = (cos theta(0), sin theta(0)), T_L = (cos theta(L), sin theta(L)) (the
 * spline's parameter is the arc length, speed 1):
 *   P_0 = gamma(0),  P_1 = P_0 + U_{p+1} / p T_0,
 *   P_{n-1} = gamma(L),  P_{n-2} = P_{n-1} - (L - U_{n-1}) / p T_L.
 * (N = 1: U_{p+1} = L and U_{n-1} = U_p = 0, the same formulas; p >= 3 makes
 * the four indices distinct.) The unknowns P_2..P_{n-3} (nu = n - 4 of them,
 * possibly none) by linear least squares on the grid: normal equations
 * sum_i N_a(s_i) N_c(s_i), banded with p sub-diagonals, by GSL's banded
 * Cholesky, the fixed poles' contributions moved to the right-hand side.
 * poles: 2n.
 */
/* The basis functions of the grid for the current knots (w->Bc, w->kc). */
FIT_INLINE void fit_basis_p(fit_ws *w, size_t N, const int p)
{
    const size_t n = N + (size_t)p;
    const double *U = w->U;
    size_t k = (size_t)p;
    double inv[(MAXDEG_FIT * (MAXDEG_FIT + 1)) / 2];
    span_recips(U, k, p, inv);
    for (size_t i = 0; i <= w->M; i++) {
        const double t = w->s[i];
        if (k + 1 < n && t >= U[k + 1]) {
            while (k + 1 < n && t >= U[k + 1]) k++;
            span_recips(U, k, p, inv);
        }
        basis_funs_inv(U, k, p, t, inv, w->Bc + i * (size_t)(p + 1));
        w->kc[i] = k;
    }
}

void el__approx_basis(fit_ws *w, size_t N)
{
    if (w->p == 3) fit_basis_p(w, N, 3);
    else fit_basis_p(w, N, w->p);
}

/* Normal equations of the free poles (el__approx_poles), from the grid's basis. */
FIT_INLINE void normal_equations(fit_ws *w, size_t n, size_t nd, const double *poles, const int p)
{
    const size_t f = (size_t)w->nfix;   /* fixed poles 0..f-1 and n-f..n-1 */
    for (size_t i = 0; i <= w->M; i++) {
        const double *B = w->Bc + i * (size_t)(p + 1);
        const size_t k = w->kc[i];
        double tx = w->xy[2 * i], ty = w->xy[2 * i + 1];
        const size_t g0 = k - (size_t)p;
        if (p == 3 && g0 >= f && k + f < n) {
            /* cubic, no fixed pole in this span: the whole span summed in
             * registers first (p = 3 spelled out so that it is unrolled) */
            double A00 = 0, A01 = 0, A02 = 0, A03 = 0, A11 = 0, A12 = 0, A13 = 0, A22 = 0,
                   A23 = 0, A33 = 0, x0 = 0, x1 = 0, x2 = 0, x3 = 0, y0 = 0, y1 = 0, y2 = 0,
                   y3 = 0;
            for (;;) {
                const double b0 = B[0], b1 = B[1], b2 = B[2], b3 = B[3];
                A00 += b0 * b0; A01 += b0 * b1; A02 += b0 * b2; A03 += b0 * b3;
                A11 += b1 * b1; A12 += b1 * b2; A13 += b1 * b3;
                A22 += b2 * b2; A23 += b2 * b3; A33 += b3 * b3;
                x0 += b0 * tx; x1 += b1 * tx; x2 += b2 * tx; x3 += b3 * tx;
                y0 += b0 * ty; y1 += b1 * ty; y2 += b2 * ty; y3 += b3 * ty;
                if (i == w->M || w->kc[i + 1] != k) break;
                i++;
                B += 4;
                tx = w->xy[2 * i];
                ty = w->xy[2 * i + 1];
            }
            double *Ar = w->AB + (g0 - f) * nd, *bx = w->bx + (g0 - f), *by = w->by + (g0 - f);
            Ar[0] += A00; Ar[1] += A01; Ar[2] += A02; Ar[3] += A03;
            Ar[nd] += A11; Ar[nd + 1] += A12; Ar[nd + 2] += A13;
            Ar[2 * nd] += A22; Ar[2 * nd + 1] += A23;
            Ar[3 * nd] += A33;
            bx[0] += x0; bx[1] += x1; bx[2] += x2; bx[3] += x3;
            by[0] += y0; by[1] += y1; by[2] += y2; by[3] += y3;
            continue;
        }
        if (g0 >= f && k + f < n) {   /* no fixed pole in this span */
            double *Ar = w->AB + (g0 - f) * nd;
            FIT_UNROLL for (int a = 0; a <= p; a++, Ar += nd) {
                w->bx[g0 - f + (size_t)a] += B[a] * tx;
                w->by[g0 - f + (size_t)a] += B[a] * ty;
                FIT_UNROLL for (int c = a; c <= p; c++) Ar[c - a] += B[a] * B[c];
            }
            continue;
        }
        FIT_UNROLL for (int a = 0; a <= p; a++) {
            const size_t g = g0 + (size_t)a;
            if (g < f || g + f >= n) { tx -= B[a] * poles[2 * g]; ty -= B[a] * poles[2 * g + 1]; }
        }
        FIT_UNROLL for (int a = 0; a <= p; a++) {
            const size_t ga = g0 + (size_t)a;
            if (ga < f || ga + f >= n) continue;
            w->bx[ga - f] += B[a] * tx;
            w->by[ga - f] += B[a] * ty;
            FIT_UNROLL for (int c = a; c <= p; c++) {
                const size_t gc = g0 + (size_t)c;
                if (gc + f >= n) continue;
                w->AB[(ga - f) * nd + (gc - ga)] += B[a] * B[c];
            }
        }
    }
}

int el__approx_poles(fit_ws *w, size_t N, double *poles)
{
    const int p = w->p;
    const size_t f = (size_t)w->nfix, n = N + (size_t)p, nu = n - 2 * f;
    const size_t nd = nu ? ((size_t)p < nu ? (size_t)p : nu - 1) + 1 : 1;
    const double *U = w->U;
    /* fixed poles: 0, 1, n-2, n-1 (the grid's end samples are the exact ends), and 2, n-3 for G2 */
    const double a0 = U[p + 1] / p, a1 = (w->L - U[n - 1]) / p;
    const double *e0 = w->xy, *e1 = w->xy + 2 * w->M, *T0 = w->cs, *T1 = w->cs + 2 * w->M;
    poles[0] = e0[0]; poles[1] = e0[1];
    poles[2] = e0[0] + a0 * T0[0]; poles[3] = e0[1] + a0 * T0[1];
    poles[2 * (n - 1)] = e1[0]; poles[2 * (n - 1) + 1] = e1[1];
    poles[2 * (n - 2)] = e1[0] - a1 * T1[0]; poles[2 * (n - 2) + 1] = e1[1] - a1 * T1[1];
    if (f == 3) {   /* and B''(0), B''(L) = kappa N (el_smooth_to_bspline_g2) */
        const double b0 = U[p + 2], b1 = w->L - U[n - 2], c = 1.0 / (p * (p - 1.0));
        const double k0 = w->ka[0] * U[p + 1] * c, k1 = w->ka[w->M] * (w->L - U[n - 1]) * c;
        poles[4] = poles[2] + b0 * (T0[0] / p - k0 * T0[1]);
        poles[5] = poles[3] + b0 * (T0[1] / p + k0 * T0[0]);
        poles[2 * (n - 3)] = poles[2 * (n - 2)] + b1 * (-T1[0] / p - k1 * T1[1]);
        poles[2 * (n - 3) + 1] = poles[2 * (n - 2) + 1] + b1 * (-T1[1] / p + k1 * T1[0]);
    }
    if (nu) {
        memset(w->AB, 0, nu * nd * sizeof *w->AB);
        memset(w->bx, 0, nu * sizeof *w->bx);
        memset(w->by, 0, nu * sizeof *w->by);
    }
    el__approx_basis(w, N);
    if (nu) {
        if (p == 3) normal_equations(w, n, nd, poles, 3);
        else normal_equations(w, n, nd, poles, p);
    }
    if (nu) {
        gsl_matrix_view A = gsl_matrix_view_array(w->AB, nu, nd);
        if (gsl_linalg_cholesky_band_decomp(&A.matrix)) return EL_ESINGULAR;
        gsl_vector_view vx = gsl_vector_view_array(w->bx, nu), vy = gsl_vector_view_array(w->by, nu);
        if (gsl_linalg_cholesky_band_svx(&A.matrix, &vx.vector) ||
            gsl_linalg_cholesky_band_svx(&A.matrix, &vy.vector))
            return EL_ESINGULAR;
        for (size_t j = 0; j < nu; j++) {
            poles[2 * (j + f)] = w->bx[j];
            poles[2 * (j + f) + 1] = w->by[j];
        }
    }
    return el__all_finite(poles, 2 * n) ? EL_ESINGULAR : EL_OK;
}

/* B(t) on span k of the fit's knots. */
static void fit_point(const fit_ws *w, const double *poles, size_t k, double t, double *P)
{
    double B[MAXDEG_FIT + 1];
    basis_funs(w->U, k, w->p, t, B);
    P[0] = P[1] = 0.0;
    for (int a = 0; a <= w->p; a++) {
        const size_t g = k - (size_t)w->p + (size_t)a;
        P[0] += B[a] * poles[2 * g];
        P[1] += B[a] * poles[2 * g + 1];
    }
}

/* Newton step of the foot point from s = t (file comment). */
FIT_INLINE double foot_step(double ex, double ey, double c, double sn, double kappa)
{
    const double eT = ex * c + ey * sn, eN = -ex * sn + ey * c;
    const double den = 1.0 - kappa * eN;   /* (ternaries: fmax is a call at -O2) */
    return eT / (den > 0.5 ? den : 0.5);
}

/* B at grid point i from the cached basis functions of the last el__approx_poles. */
FIT_INLINE void grid_point_p(const fit_ws *w, const double *poles, size_t i, double *P, const int p)
{
    const double *B = w->Bc + i * (size_t)(p + 1);
    const size_t g0 = w->kc[i] - (size_t)p;
    P[0] = P[1] = 0.0;
    FIT_UNROLL for (int a = 0; a <= p; a++) {
        P[0] += B[a] * poles[2 * (g0 + (size_t)a)];
        P[1] += B[a] * poles[2 * (g0 + (size_t)a) + 1];
    }
}

/* |B(t) - (gamma(t) + D T + D^2/2 kappa N)|^2 and the step D = s1 - t. */
FIT_INLINE double taylor_sq(const fit_ws *w, const double *P, const double *g, double c,
                            double sn, double ka, double t, double *Dout)
{
    double s1 = t + foot_step(P[0] - g[0], P[1] - g[1], c, sn, ka);
    s1 = s1 < 0.0 ? 0.0 : (s1 > w->L ? w->L : s1);
    const double D = s1 - t, h = 0.5 * D * D * ka;
    const double dx = P[0] - g[0] - D * c + h * sn, dy = P[1] - g[1] - D * sn - h * c;
    *Dout = D;
    return dx * dx + dy * dy;
}

/*
 * d(t) = |B(t) - gamma(s1)|. gamma(s1) by Taylor from t,
 * gamma(t) + D T + D^2/2 kappa N, plus the remainder bound |D|^3/6 max|gamma^(3)|,
 * |gamma^(3)| = |kappa' N - kappa^2 T| <= sqrt(kappa'_max^2 + kappa_max^4) = c3 with
 * kappa_max = 2k sqrt(mu) and kappa'_max = 2 mu min(k, 1) (|cn|, |dn| <= 1 and
 * |sn dn| <= min(1, 1/k) by the reciprocal-modulus transformation): an upper
 * bound of |B(t) - gamma(s1)| from exact gamma, theta, kappa at t.
 */

FIT_INLINE double taylor_distance(const fit_ws *w, const double *P, const double *g, double c,
                              double sn, double ka, double t, double c3)
{
    double D, d2 = taylor_sq(w, P, g, c, sn, ka, t, &D);
    return sqrt(d2) + fabs(D * D * D) * c3 / 6.0;
}

/* Sampled distance per span, to steer the knots (w->err); returns the largest. */
FIT_INLINE double fit_errors_p(fit_ws *w, size_t N, const double *poles, const int p)
{
    memset(w->err, 0, N * sizeof *w->err);
    double emax = 0.0;
    for (size_t i = 0; i <= w->M; i++) {
        double P[2];
        grid_point_p(w, poles, i, P, p);
        double D;   /* squared distances here (no remainder term), roots below */
        const double d = taylor_sq(w, P, w->xy + 2 * i, w->cs[2 * i], w->cs[2 * i + 1],
                                   w->ka[i], w->s[i], &D);
        const size_t k = w->kc[i], j = k - (size_t)p;
        if (d > w->err[j]) w->err[j] = d;
        if (j > 0 && w->s[i] == w->U[k] && d > w->err[j - 1]) w->err[j - 1] = d;
        if (d > emax) emax = d;
    }
    for (size_t j = 0; j < N; j++) w->err[j] = sqrt(w->err[j]);
    return sqrt(emax);
}

double el__approx_errors(fit_ws *w, size_t N, const double *poles)
{
    return w->p == 3 ? fit_errors_p(w, N, poles, 3) : fit_errors_p(w, N, poles, w->p);
}


typedef struct cert_ctx {
    fit_ws *w;
    const double *poles;
    size_t n;
    double c3;
    int status;
} cert_ctx;

static double exact_distance(cert_ctx *c, double t)
{
    fit_ws *w = c->w;
    double g[2], th, ka, P[2];
    int st = el_smooth_eval(w->par, 1, &t, g, &th, &ka);
    if (st) { c->status = st; return 0.0; }
    fit_point(w, c->poles, find_span(w->U, c->n, w->p, t), t, P);
    const double d = taylor_distance(w, P, g, cos(th), sin(th), ka, t, c->c3);
    /* (GSL's minimiser must see finite values: its error handler is the caller's) */
    if (!isfinite(d)) { c->status = EL_EDOM; return 0.0; }
    return d;
}

static double neg_distance(double t, void *ctx) { return -exact_distance(ctx, t); }

typedef struct peak { size_t i; double pred; } peak;

static int peak_cmp(const void *a, const void *b)
{
    const double x = ((const peak *)a)->pred, y = ((const peak *)b)->pred;
    return (x < y) - (x > y);   /* descending */
}

/* d at every grid point (w->dist), the largest and where. */
FIT_INLINE void certify_grid(fit_ws *w, const double *poles, double c3, double *best, double *tb,
                             const int p)
{
    for (size_t i = 0; i <= w->M; i++) {
        double P[2];
        grid_point_p(w, poles, i, P, p);
        w->dist[i] = taylor_distance(w, P, w->xy + 2 * i, w->cs[2 * i], w->cs[2 * i + 1],
                                     w->ka[i], w->s[i], c3);
        if (w->dist[i] > *best) { *best = w->dist[i]; *tb = w->s[i]; }
    }
}

/*
 * Certified max distance (file comment); *worst = the t where it occurs.
 * Grid values first (exact gamma, theta, kappa of the grid); then Brent (GSL)
 * around the grid's local maxima, in decreasing order of their parabolic
 * peak prediction, until the next prediction is 1 % below the best value.
 */
int el__approx_certify(fit_ws *w, size_t N, const double *poles, double *dmax, double *worst)
{
    const size_t n = N + (size_t)w->p, M = w->M;
    const double k = fabs(w->par->k), mu = w->par->mu, kmax = 2.0 * k * sqrt(mu), /* sign of k: orientation */
                 k1max = 2.0 * mu * fmin(k, 1.0);
    const double c3 = sqrt(k1max * k1max + kmax * kmax * kmax * kmax);
    double best = 0.0, tb = 0.0;
    if (w->p == 3) certify_grid(w, poles, c3, &best, &tb, 3);
    else certify_grid(w, poles, c3, &best, &tb, w->p);
    size_t np = 0;
    for (size_t i = 1; i < M; i++)
        if (w->dist[i] > w->dist[i - 1] && w->dist[i] > w->dist[i + 1]) np++;
    peak *pk = malloc((np ? np : 1) * sizeof *pk);
    if (!pk) return EL_ENOMEM;
    np = 0;
    for (size_t i = 1; i < M; i++) {
        const double a = w->dist[i - 1], d = w->dist[i], c = w->dist[i + 1];
        if (!(d > a && d > c)) continue;
        pk[np].i = i;
        pk[np++].pred = d + (c - a) * (c - a) / (8.0 * (2.0 * d - a - c));
    }
    qsort(pk, np, sizeof *pk, peak_cmp);
    cert_ctx ctx = {w, poles, n, c3, EL_OK};
    gsl_min_fminimizer *mz = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!mz) { free(pk); return EL_ENOMEM; }
    gsl_function F = {neg_distance, &ctx};
    for (size_t j = 0; j < np; j++) {
        if (1.01 * pk[j].pred < best) break;
        const size_t i = pk[j].i;
        if (gsl_min_fminimizer_set_with_values(mz, &F, w->s[i], -w->dist[i], w->s[i - 1],
                                               -w->dist[i - 1], w->s[i + 1], -w->dist[i + 1]))
            continue;
        for (int it = 0; it < 40; it++) {
            if (gsl_min_fminimizer_iterate(mz) || ctx.status) break;
            const double a = gsl_min_fminimizer_x_lower(mz), b = gsl_min_fminimizer_x_upper(mz);
            if (gsl_min_test_interval(a, b, 1e-3 * (w->s[i + 1] - w->s[i - 1]), 0.0) != GSL_CONTINUE)
                break;
        }
        if (ctx.status) break;
        const double dm = -gsl_min_fminimizer_f_minimum(mz);
        if (dm > best) { best = dm; tb = gsl_min_fminimizer_x_minimum(mz); }
    }
    gsl_min_fminimizer_free(mz);
    free(pk);
    if (ctx.status) return ctx.status;
    /* rounding of the evaluations (positions of size |x0| + |y0| + L) */
    *dmax = best + 16.0 * DBL_EPSILON * (fabs(w->par->x0) + fabs(w->par->y0) + w->L);
    *worst = tb;
    return EL_OK;
}
