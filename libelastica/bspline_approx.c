/*
 * The tolerance-certified B-spline approximation of a smooth elastica segment
 * (issue 4): el_smooth_to_bspline, its G2 variant and el_smooth_chain_to_bspline
 * (pieces joined C2 by bspline.c's knot removal). GSL does the linear algebra
 * (banded Cholesky of the normal equations) and the local maximisation (Brent).
 *
 * Approximation of an elastica (el_smooth_to_bspline):
 *  - the B-spline is parametrised by the arc length s of the elastica on
 *    [0, length], clamped, simple interior knots (C^{p-1});
 *  - poles by linear least squares on a uniform grid of exact samples gamma(s_i)
 *    (at least 3(p+1) in the smallest span), the first two and last two poles
 *    fixed so that B(0) = gamma(0), B(L) = gamma(L) and B'(0), B'(L) are the
 *    exact unit tangents (fit_poles()): both ends are interpolated with the
 *    elastica's tangent (G1 joins to other geometry stay exact);
 *  - knots: a degree-p spline's error on a span h is about c h^{p+1}
 *    |gamma^(p+1)|, so knots equidistribute the integral of
 *    g = |gamma^(p+1)|^{1/(p+1)}, computed exactly from the pendulum equation
 *    of the tangent angle (density()); the number of spans N is found by
 *    scaling with the error ratio and bisection; then the knots are moved by
 *    the measured span errors (correction(), accumulated over the tries, which
 *    also gives the end spans the extra density their fixed end poles need),
 *    from the smallest failing N downwards by the error ratio and bisection;
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
 *  - certification (certify()): d at every grid point from the exact gamma,
 *    theta, kappa there, then Brent (GSL) maximisation of d around the grid's
 *    local maxima (exact evaluation at every step), largest predicted first;
 *    reported as max_deviation (plus 16 eps (|x0| + |y0| + L) for the rounding
 *    of the evaluations). If it exceeds tol, the search is redone with
 *    a lower target for the sampled error, and knots are inserted as a last
 *    resort.
 * Cost (issue 4 asks <= 1 ms at 1e-6 L, degree 3): about seven least-squares
 * fits on ~1000 samples dominate, so the fit's loops avoid divisions (the knot
 * differences of a span are inverted once, span_recips()), are unrolled for
 * p = 3 (FIT_INLINE/FIT_UNROLL), sum a span's normal equations in registers,
 * compare squared distances while steering, and the final certified fit reuses
 * the poles of the search's last passing fit when knots and grid are the same
 * (no refit). These change only the rounding, not the algorithm.
 */
#include "internal.h"
#include "bspline_basis.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_vector.h>

/* ------------------------------------------------------------------ elastica -> B-spline */

typedef struct fit_ws {
    const el_smooth_params *par;
    int p;               /* degree */
    double L, tol;
    size_t M;            /* grid: M+1 samples s_i = i L / M */
    double *s, *xy, *th, *ka;
    double *cs;          /* cos theta, sin theta of the grid, interleaved */
    double *Bc;          /* basis functions of the grid for the current knots, (M+1)(p+1) */
    size_t *kc;          /* their span indices */
    size_t cap;          /* capacity in spans */
    double *U;           /* flat knots, cap + 2p + 1 */
    double *AB, *bx, *by;
    double *err;         /* per-span sampled error */
    double *dist;        /* per-grid-point distance (certification) */
    int nfix;            /* poles fixed at each end: 2 (point, tangent) or 3 (and curvature) */
    size_t nmin;         /* fewest spans that leave them distinct */
} fit_ws;

static void ws_free(fit_ws *w)
{
    free(w->s); free(w->xy); free(w->th); free(w->ka); free(w->cs); free(w->Bc); free(w->kc);
    free(w->U); free(w->AB); free(w->bx); free(w->by); free(w->err); free(w->dist);
}

/* (Re)sample the exact curve on a uniform grid of M+1 points (el_smooth_eval
 * takes the addition-theorem path for equally spaced s). */
static int ws_grid(fit_ws *w, size_t M)
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
     * the fixed end poles and tangents, fit_poles), not with the rounding of
     * the progression */
    if (!st) st = el_smooth_eval(w->par, 1, &w->s[0], w->xy, w->th, w->ka);
    if (!st) st = el_smooth_eval(w->par, 1, &w->s[M], w->xy + 2 * M, w->th + M, w->ka + M);
    for (size_t i = 0; i <= M && !st; i++) {
        w->cs[2 * i] = cos(w->th[i]);
        w->cs[2 * i + 1] = sin(w->th[i]);
    }
    return st;
}

static int ws_reserve(fit_ws *w, size_t N)
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
static void set_knots(fit_ws *w, size_t N, const double *breaks)
{
    const size_t p = (size_t)w->p;
    for (size_t i = 0; i <= p; i++) { w->U[i] = 0.0; w->U[N + p + i] = w->L; }
    for (size_t j = 1; j < N; j++) w->U[p + j] = breaks[j];
}

/* Enough grid points in the smallest span: at least 3(p+1). */
static int ensure_grid(fit_ws *w, size_t N, const double *breaks)
{
    double hmin = w->L;
    for (size_t j = 0; j < N; j++) hmin = fmin(hmin, breaks[j + 1] - breaks[j]);
    const double need = 3.0 * (w->p + 1) * w->L / hmin;
    if ((double)w->M >= need) return EL_OK;
    if (need > 4e6) return EL_EMAXITER;   /* knots finer than the arithmetic can use */
    return ws_grid(w, (size_t)ceil(fmax(1.25 * need, 1.5 * (double)w->M)));
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

static void fit_basis(fit_ws *w, size_t N)
{
    if (w->p == 3) fit_basis_p(w, N, 3);
    else fit_basis_p(w, N, w->p);
}

/* Normal equations of the free poles (fit_poles), from the grid's basis. */
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

static int fit_poles(fit_ws *w, size_t N, double *poles)
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
    fit_basis(w, N);
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

/* B at grid point i from the cached basis functions of the last fit_poles. */
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

static double fit_errors(fit_ws *w, size_t N, const double *poles)
{
    return w->p == 3 ? fit_errors_p(w, N, poles, 3) : fit_errors_p(w, N, poles, w->p);
}

/*
 * Knot density from the curve itself. With psi = theta - phi the elastica is
 * the pendulum psi'' = -mu sin psi (kappa' = -2k mu sn dn = -mu sin(theta-phi),
 * from k sn = sin a, dn = cos a, a = psi/2). Taylor coefficients at s0 by the
 * recurrences of automatic differentiation (S = sin psi, C = cos psi):
 *   S_j = (1/j) sum_{m=1..j} m psi_m C_{j-m},  C_j = -(1/j) sum m psi_m S_{j-m},
 *   (j+2)(j+1) psi_{j+2} = -mu S_j,  psi_0 = theta - phi, psi_1 = kappa;
 * gamma' = e^{i phi} (C + i S), so |gamma^(p+1)(s0)| = p! |C_p + i S_p|. A
 * degree-p spline's error on a span h is about c h^{p+1} |gamma^(p+1)|, so
 * knots equidistributing the integral of g = |gamma^(p+1)|^{1/(p+1)} (plus 5 %
 * of its mean so that no span becomes huge where it vanishes) make the span
 * errors about equal. g: M+1 values of the density, G: M+1 cumulative values
 * (trapezoid rule).
 */
static void cumulate(const fit_ws *w, const double *g, const double *corr, double *G);

FIT_INLINE void density_p(const fit_ws *w, double *g, const int p)
{
    double fact = 1.0;
    for (int j = 2; j <= p; j++) fact *= j;
    const double cphi = cos(w->par->phi), sphi = sin(w->par->phi);
    for (size_t i = 0; i <= w->M; i++) {
        double psi[MAXDEG_FIT + 3], S[MAXDEG_FIT + 3], C[MAXDEG_FIT + 3];   /* +1: unrolling */
        psi[1] = w->ka[i];
        /* sin, cos of psi_0 = theta - phi from the grid's cos, sin theta */
        S[0] = w->cs[2 * i + 1] * cphi - w->cs[2 * i] * sphi;
        C[0] = w->cs[2 * i] * cphi + w->cs[2 * i + 1] * sphi;
        FIT_UNROLL for (int j = 1; j <= p; j++) {
            if (j + 1 <= p) psi[j + 1] = -w->par->mu * S[j - 1] / ((double)(j + 1) * j);
            double sa = 0.0, ca = 0.0;
            FIT_UNROLL for (int m = 1; m <= j; m++) {
                sa += m * psi[m] * C[j - m];
                ca -= m * psi[m] * S[j - m];
            }
            S[j] = sa / j;
            C[j] = ca / j;
        }
        const double d = fact * sqrt(C[p] * C[p] + S[p] * S[p]);
        g[i] = p == 3 ? sqrt(sqrt(d)) : pow(d, 1.0 / (p + 1));
    }
}

static void density(const fit_ws *w, double *g, double *G)
{
    if (w->p == 3) density_p(w, g, 3);
    else density_p(w, g, w->p);
    double mean = 0.0;
    for (size_t i = 0; i <= w->M; i++) mean += g[i];
    mean /= (double)(w->M + 1);
    for (size_t i = 0; i <= w->M; i++) g[i] = mean > 0.0 ? g[i] + 0.05 * mean : 1.0;   /* 0: a line */
    cumulate(w, g, NULL, G);
}

/* G = cumulative integral of g, times the per-grid-point factor cm[i] when cm
 * is given (the accumulated corrections of the knot moving). */
static void cumulate(const fit_ws *w, const double *g, const double *cm, double *G)
{
    const double h = w->L / (double)w->M;
    double acc = 0.0, prev = g[0] * (cm ? cm[0] : 1.0);
    G[0] = 0.0;
    for (size_t i = 1; i <= w->M; i++) {
        const double gi = g[i] * (cm ? cm[i] : 1.0);
        acc += 0.5 * (prev + gi) * h;
        prev = gi;
        G[i] = acc;
    }
}

/*
 * Correction of the density by the last fit's span errors: the density of span
 * j is multiplied by (e_j / mean e)^{1/(p+1)}, clamped to [1/2, 2], so that
 * equidistribution moves knots towards the spans with the larger errors.
 */
static void correction(const fit_ws *w, size_t N, double *corr)
{
    const double ex = 1.0 / (w->p + 1);
    double mean = 0.0;
    for (size_t j = 0; j < N; j++) mean += pow(w->err[j], ex);
    mean /= (double)N;
    for (size_t j = 0; j < N; j++)
        corr[j] = mean > 0.0 ? fmin(fmax(pow(w->err[j], ex) / mean, 0.5), 2.0) : 1.0;
}

/* breaks[0..N] equidistributing G on the grid; EL_ESINGULAR if two coincide. */
static int breaks_for(const fit_ws *w, const double *G, size_t N, double *breaks)
{
    const double tot = G[w->M];
    breaks[0] = 0.0;
    breaks[N] = w->L;
    size_t i = 0;
    for (size_t j = 1; j < N; j++) {
        const double target = tot * (double)j / (double)N;
        while (i + 1 < w->M && G[i + 1] < target) i++;
        const double f = fmin(fmax((target - G[i]) / (G[i + 1] - G[i]), 0.0), 1.0);
        breaks[j] = w->s[i] + f * (w->s[i + 1] - w->s[i]);
        if (!(breaks[j] > breaks[j - 1])) return EL_ESINGULAR;
    }
    return breaks[N] > breaks[N - 1] ? EL_OK : EL_ESINGULAR;
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
static int certify(fit_ws *w, size_t N, const double *poles, double *dmax, double *worst)
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

static int emit(const fit_ws *w, size_t N, const double *breaks, const double *poles,
                double dev, el_bspline *out)
{
    const size_t n = N + (size_t)w->p;
    el_bspline b;
    int st = el_bspline_alloc(&b, w->p, 2, n, N + 1);
    if (st) return st;
    memcpy(b.poles, poles, 2 * n * sizeof *poles);
    for (size_t j = 0; j <= N; j++) { b.knots[j] = breaks[j]; b.mults[j] = 1; }
    b.knots[N] = w->L;
    b.mults[0] = b.mults[N] = w->p + 1;
    b.max_deviation = dev;
    *out = b;
    return EL_OK;
}

/* el_smooth_to_bspline with nfix poles fixed at each end (2: G1 ends, 3: G2 ends). */
static int smooth_to_bspline(const el_smooth_params *par_in, double tol, int degree, int nfix,
                             el_bspline *out)
{
    if (!out || el_smooth_check(par_in) || !isfinite(tol) || !(tol > 0.0) || degree < 3 ||
        degree > MAXDEG_FIT)
        return EL_EINVAL;
    el__gsl_quiet();
    /* A huge angle phi: the same curve with phi in [-pi, pi]. el_smooth_eval rotates the
     * points by cos, sin phi (exact for any phi) but returns the tangent angle as phi plus
     * the shape's own turning, which rounds to ~1e-16 |phi| (phi = -3e305: a constant
     * tangent), and the approximation steers by it (fuzz: 12 s of CPU, 92 poles for a
     * curve that takes 65). atan2(sin, cos) keeps cos and sin phi to rounding; below
     * 1e6 (turning exact to 1e-10) phi is kept, so the end poles stay el_smooth_eval's
     * end points bit for bit. */
    el_smooth_params reduced = *par_in;
    if (fabs(reduced.phi) > 1e6) reduced.phi = atan2(sin(reduced.phi), cos(reduced.phi));
    const el_smooth_params *par = &reduced;
    const int p = degree;
    const double L = par->length;
    if (L == 0.0) {   /* a point: every pole there, exact */
        el_bspline b;
        int st = el_bspline_alloc(&b, p, 2, (size_t)p + 1, 2);
        if (st) return st;
        for (int i = 0; i <= p; i++) { b.poles[2 * i] = par->x0; b.poles[2 * i + 1] = par->y0; }
        b.knots[0] = 0.0; b.knots[1] = 1.0; b.mults[0] = b.mults[1] = p + 1;
        b.max_deviation = 0.0;
        *out = b;
        return EL_OK;
    }
    /* bounded work (header): below what double precision resolves (the phase q
     * carries an absolute rounding of eps |q| into u), or more turning than the
     * pole limit can follow, is refused at once */
    if (tol < 1e-14 * (L + fabs(par->x0) + fabs(par->y0) + fabs(par->q) / sqrt(par->mu)))
        return EL_EDOM;
    const double turn = 2.0 * fabs(par->k) * sqrt(par->mu) * L;   /* >= integral |kappa| */
    if (!(turn <= (double)EL_BSPLINE_MAX_POLES)) return EL_EDOM;
    const size_t Nmax = EL_BSPLINE_MAX_POLES - (size_t)p;   /* spans */
    fit_ws w;
    memset(&w, 0, sizeof w);
    w.par = par; w.p = p; w.L = L; w.tol = tol;
    w.nfix = nfix;
    w.nmin = 2 * nfix > p + 1 ? (size_t)(2 * nfix - p) : 1;
    double *breaks = NULL, *nb = NULL, *poles = NULL, *G = NULL;
    double *bestbr = NULL, *corr = NULL, *Gc = NULL, *cm = NULL;
    double *svp = NULL, *svb = NULL;   /* poles and breaks of the last passing fit */
    size_t svN = 0, svM = 0;           /* its spans and grid */
    double dev = INFINITY, tw = 0.0;
    int st, status = EL_OK;
#define GROW(ptr, cnt) do { double *q_ = realloc(ptr, (cnt) * sizeof *q_); \
        if (!q_) { st = EL_ENOMEM; goto done; } ptr = q_; } while (0)

    /* a first grid for the knot density: 16 points per radian of turning at
     * least (bound 2k sqrt(mu) L); ensure_grid refines it for the knots */
    {
        const double M0 = fmax(16.0 * (p + 1), 16.0 * ceil(turn));
        if ((st = ws_grid(&w, (size_t)M0))) goto done;
    }
    size_t Mg = 0;   /* grid size G belongs to */
    const double ex = 1.0 / (p + 1);
    /* the sampled error a fit must reach; lowered when the certified value
     * (which sees the peaks between grid points) exceeds tol */
    double accept = tol;
    size_t N = 0;
    for (int round = 0; round < 3; round++) {
        /* the number of spans: scale by the error ratio, then bisect between
         * the largest failing and the smallest passing N */
        size_t lo_fail = 0, hi_pass = 0;   /* hi_pass = 0: none yet */
        size_t Nlast = 0;                  /* spans of the last fit (w.err, w.kc) */
        size_t Nmoved = 0;                 /* bestbr holds passing moved knots for Nmoved */
        double e = 0.0;
        for (int it = 0; it < 40; it++) {
            if (Mg != w.M) {
                GROW(G, 2 * (w.M + 1));
                density(&w, G + w.M + 1, G);
                Mg = w.M;
            }
            if (N == 0) {
                double x = ceil(0.19 * G[w.M] / pow(accept, ex));
                /* the estimate is good to a factor ~1.5: twice the limit is out of reach */
                if (!(x <= 2.0 * (double)Nmax)) { st = EL_EDOM; goto done; }
                N = x < (double)w.nmin ? w.nmin : (x > (double)Nmax ? Nmax : (size_t)x);
            }
            if ((st = ws_reserve(&w, N))) goto done;
            GROW(breaks, N + 1);
            if ((st = breaks_for(&w, G, N, breaks))) goto done;
            if ((st = ensure_grid(&w, N, breaks)) == EL_EMAXITER) { st = EL_OK; break; }
            if (st) goto done;
            if (Mg != w.M) { it--; continue; }   /* finer grid: recompute the density, same N */
            set_knots(&w, N, breaks);
            GROW(poles, 2 * (N + (size_t)p));
            if ((st = fit_poles(&w, N, poles))) goto done;
            e = fit_errors(&w, N, poles);
            Nlast = N;
            if (e <= accept) {   /* kept: the final fit below reuses it when it is this one */
                GROW(svp, 2 * (N + (size_t)p));
                GROW(svb, N + 1);
                memcpy(svp, poles, 2 * (N + (size_t)p) * sizeof *poles);
                memcpy(svb, breaks, (N + 1) * sizeof *breaks);
                svN = N; svM = w.M;
            }
            if (e <= accept) { if (!hi_pass || N < hi_pass) hi_pass = N; }
            else if (N > lo_fail) lo_fail = N;
            if (hi_pass && hi_pass == lo_fail + 1) break;
            size_t Nn;
            const double r = pow(e / (0.96 * accept), ex) * (double)N;   /* aim just below */
            if (e > accept) Nn = !(r <= (double)Nmax) ? Nmax : (size_t)ceil(r);
            else Nn = r >= 0.0 ? (size_t)floor(r) : 0;   /* (r <= N here) */
            if (e > accept && N >= Nmax) break;   /* the pole limit: best effort below */
            if (e > accept && Nn <= N) Nn = N + 1;
            if (e <= accept && Nn >= N) Nn = N - 1;
            if (Nn <= lo_fail) Nn = lo_fail + 1;
            if (hi_pass && Nn >= hi_pass) Nn = hi_pass - 1;
            if (Nn < w.nmin || Nn == N) break;
            N = Nn;
        }

        /* fewer spans by moving knots: the density corrected by the span errors
         * of the last fit (any N) places the knots, first for N = lo_fail;
         * then N is lowered by the error ratio after a success (as above) and
         * bisected between the smallest moved success and the largest moved
         * failure. The corrections accumulate (cm, per grid point): the end
         * spans, whose first and last two poles are fixed by the end tangents
         * (fit_poles), need a lasting extra density that the curve's own
         * density() does not predict. */
        if (hi_pass && lo_fail && Mg == w.M) {
            size_t Nc = lo_fail, mfail = 0;   /* largest failing N with moved knots */
            int retried = 0;                  /* Nc is being retried */
            GROW(cm, w.M + 1);
            for (size_t i = 0; i <= w.M; i++) cm[i] = 1.0;
            for (int tries = 0; tries < 10 && Nc >= 1; tries++) {
                GROW(corr, Nlast);
                correction(&w, Nlast, corr);
                for (size_t i = 0; i <= w.M; i++) cm[i] *= corr[w.kc[i] - (size_t)p];
                GROW(nb, Nc + 1);
                if ((st = ws_reserve(&w, Nc))) goto done;
                int regrid = 0;
                for (;;) {   /* knots; a finer grid if they need one (cm carried over) */
                    GROW(Gc, w.M + 1);
                    cumulate(&w, G + w.M + 1, cm, Gc);
                    if (breaks_for(&w, Gc, Nc, nb)) { regrid = -1; break; }
                    const size_t M0 = w.M;
                    if ((st = ensure_grid(&w, Nc, nb)) == EL_EMAXITER) { st = EL_OK; regrid = -1; break; }
                    if (st) goto done;
                    if (w.M == M0) break;
                    if (++regrid > 2) { regrid = -1; break; }   /* G is redone after the loop */
                    GROW(G, 2 * (w.M + 1));
                    density(&w, G + w.M + 1, G);
                    Mg = w.M;
                    double *c2 = malloc((w.M + 1) * sizeof *c2);
                    if (!c2) { st = EL_ENOMEM; goto done; }
                    for (size_t i = 0; i <= w.M; i++)   /* nearest old grid point */
                        c2[i] = cm[(size_t)floor((double)i * (double)M0 / (double)w.M + 0.5)];
                    free(cm);
                    cm = c2;
                }
                if (regrid < 0) break;
                set_knots(&w, Nc, nb);
                GROW(poles, 2 * (Nc + (size_t)p));
                if ((st = fit_poles(&w, Nc, poles))) goto done;
                e = fit_errors(&w, Nc, poles);
                Nlast = Nc;
                if (e <= accept) {
                    GROW(svp, 2 * (Nc + (size_t)p));
                    GROW(svb, Nc + 1);
                    memcpy(svp, poles, 2 * (Nc + (size_t)p) * sizeof *poles);
                    memcpy(svb, nb, (Nc + 1) * sizeof *nb);
                    svN = Nc; svM = w.M;
                }
                size_t Nn;
                if (e <= accept) {
                    GROW(bestbr, Nc + 1);
                    memcpy(bestbr, nb, (Nc + 1) * sizeof *nb);
                    hi_pass = Nmoved = Nc;
                    if (mfail >= Nc) mfail = 0;
                    const double r = floor(pow(e / (0.96 * accept), ex) * (double)Nc);
                    Nn = r < (double)Nc ? (size_t)r : Nc - 1;
                    if (Nn <= mfail) Nn = mfail + (Nc - mfail) / 2;
                    if (Nn <= mfail) break;
                } else {
                    mfail = Nc;
                    if (!retried && !Nmoved) Nn = Nc;   /* once more, with the further correction */
                    else if (!Nmoved || (Nn = Nc + (Nmoved - Nc) / 2) == Nc) break;
                }
                if (Nn < w.nmin || (Nmoved && Nn >= Nmoved)) break;
                retried = Nn == Nc;
                Nc = Nn;
            }
        }
        if (hi_pass) N = hi_pass;
        else status = EL_EMAXITER;   /* best effort: the last N tried, certified honestly */
        if (Mg != w.M) { GROW(G, 2 * (w.M + 1)); density(&w, G + w.M + 1, G); Mg = w.M; }
        GROW(breaks, N + 1);
        if ((st = ws_reserve(&w, N))) goto done;
        if (Nmoved && Nmoved == N) memcpy(breaks, bestbr, (N + 1) * sizeof *breaks);
        else if ((st = breaks_for(&w, G, N, breaks))) goto done;
        /* knots finer than the grid limit: fewer spans (N = 1 always fits), best effort */
        while ((st = ensure_grid(&w, N, breaks)) == EL_EMAXITER && N > 1) {
            status = EL_EMAXITER;
            N /= 2;
            if ((st = breaks_for(&w, G, N, breaks))) goto done;
        }
        if (st) goto done;
        set_knots(&w, N, breaks);
        GROW(poles, 2 * (N + (size_t)p));
        if (svN == N && svM == w.M && !memcmp(svb, breaks, (N + 1) * sizeof *breaks)) {
            fit_basis(&w, N);   /* the same fit as the saved one: no refit */
            memcpy(poles, svp, 2 * (N + (size_t)p) * sizeof *poles);
        } else if ((st = fit_poles(&w, N, poles))) goto done;
        if ((st = certify(&w, N, poles, &dev, &tw))) goto done;
        if (dev <= tol || status) break;
        accept *= 0.995 * tol / dev;
    }

    /* last resort: split the span holding the worst point until certified; at a
     * limit (iterations, poles, grid) the last certified spline is the answer */
    for (int it = 0; dev > tol && !status; it++) {
        if (it == 30 || N >= Nmax) { status = EL_EMAXITER; break; }
        size_t j = 0;
        while (j + 1 < N && tw >= breaks[j + 1]) j++;
        GROW(nb, N + 2);
        memcpy(nb, breaks, (j + 1) * sizeof *nb);
        nb[j + 1] = 0.5 * (breaks[j] + breaks[j + 1]);
        memcpy(nb + j + 2, breaks + j + 1, (N - j) * sizeof *nb);
        if ((st = ws_reserve(&w, N + 1))) goto done;
        if ((st = ensure_grid(&w, N + 1, nb)) == EL_EMAXITER) {
            st = EL_OK;
            status = EL_EMAXITER;
            break;
        }
        if (st) goto done;
        double *tmp = breaks; breaks = nb; nb = tmp;
        N++;
        set_knots(&w, N, breaks);
        GROW(poles, 2 * (N + (size_t)p));
        if ((st = fit_poles(&w, N, poles))) goto done;
        if ((st = certify(&w, N, poles, &dev, &tw))) goto done;
    }
    st = emit(&w, N, breaks, poles, dev, out);
#undef GROW
done:
    free(breaks); free(nb); free(poles); free(G); free(bestbr); free(corr); free(Gc); free(cm);
    free(svp); free(svb);
    ws_free(&w);
    return st ? st : status;
}

int el_smooth_to_bspline(const el_smooth_params *par, double tol, int degree, el_bspline *out)
{
    return smooth_to_bspline(par, tol, degree, 2, out);
}

int el_smooth_to_bspline_g2(const el_smooth_params *par, double tol, int degree, el_bspline *out)
{
    return smooth_to_bspline(par, tol, degree, 3, out);
}

int el_smooth_chain_to_bspline(const el_smooth_params *pieces, size_t m, double tol, int degree,
                               el_bspline *out)
{
    if (!pieces || !m || !out || !isfinite(tol) || !(tol > 0.0) || degree < 3 || degree > 7)
        return EL_EINVAL;
    for (size_t j = 0; j < m; j++)   /* every piece checked before any work */
        if (el_smooth_check(&pieces[j])) return EL_EINVAL;
    el_bspline *parts = calloc(m, sizeof *parts);
    if (!parts) return EL_ENOMEM;
    int st = EL_OK, status = EL_OK;
    double dev = 0.0;
    for (size_t j = 0; j < m && !st; j++) {
        st = el_smooth_to_bspline_g2(&pieces[j], tol, degree, &parts[j]);
        if (st == EL_EMAXITER) { status = st; st = EL_OK; }
        if (!st) dev = fmax(dev, parts[j].max_deviation);
    }
    double err = 0.0;
    el_bspline b;
    if (!st) st = el__bspline_join_c2(parts, m, &b, &err);
    for (size_t j = 0; j < m; j++) el_bspline_free(&parts[j]);
    free(parts);
    if (st) return st;
    b.max_deviation = dev + err;
    if (b.max_deviation > tol) status = EL_EMAXITER;
    *out = b;
    return status;
}
