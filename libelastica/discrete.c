/*
 * Bobenko–Suris discrete elastica, seed 000 §3–4, in the form (4.3)–(4.4)
 * with the erratum of (4.4): Theta_n = phi + a_n + a_{n+1}, where
 * a_n = (theta_n - phi)/2, sin a_n = k sn(u_n;k), cos a_n = dn(u_n;k),
 * u_n = z n + q, and gamma_{n+1} = gamma_n + h (cos Theta_n, sin Theta_n).
 * The u_n are an arithmetic progression, so the Jacobi values come from the
 * addition theorems (el__walk_grid, jacobi_walk.c) at a few flops per vertex,
 * a block of vertices at a time (no memory that grows with n).
 */
#include "internal.h"
#include <float.h>
#include <stdint.h>

/* No caller can pass more vertices: jac would hold 14 n doubles, past SIZE_MAX bytes. */
#define MAX_VERTICES (SIZE_MAX / (14 * sizeof(double)))
enum { BLOCK = 64 };

int el_discrete_check(const el_discrete_params *p)
{
    if (!p) return EL_EINVAL;
    const double v[7] = {p->x0, p->y0, p->h, p->phi, p->z, p->q, p->k};
    if (el__all_finite(v, 7) || !(p->h > 0.0) || p->k < 0.0) return EL_EINVAL;
    return EL_OK;
}

/* EL_EINVAL for bad arguments, EL_EDOM when the phase u_n = z n + q of some vertex
 * leaves double precision's range (max(1, k)|u_n| > EL__PHASE_MAX, k != 1). */
static int check_args(const el_discrete_params *p, size_t n, size_t nmin, const void *out)
{
    if (el_discrete_check(p) || n < nmin || n > MAX_VERTICES || !out) return EL_EINVAL;
    const double ulast = fabs(p->q + p->z * (double)(n - 1)), u0 = fabs(p->q);
    const double umax = ulast > u0 ? ulast : u0;
    if (!isfinite(umax) || (p->k != 1.0 && (p->k > 1.0 ? p->k : 1.0) * umax > EL__PHASE_MAX))
        return EL_EDOM;
    return EL_OK;
}

/* The walk over the vertices' u_n = z n + q. */
static int walk_start(const el_discrete_params *p, size_t n, int with_dk, el__walk *wk)
{
    int st = el__walk_init(wk, p->k, with_dk, n);
    if (!st) st = el__walk_grid(wk, p->q, p->z);
    return st ? EL_EDOM : EL_OK;
}

/* Every output element NaN (the contract of EL_EDOM). */
static int domain_error(double *a, size_t count, double *b, size_t bcount)
{
    for (size_t i = 0; a && i < count; i++) a[i] = NAN;
    for (size_t i = 0; b && i < bcount; i++) b[i] = NAN;
    return EL_EDOM;
}

/* Tangent of segment i in the frame rotated by phi: angle a_i + a_{i+1}. */
static void segment_tangent(double k, const el_jacobi *a, const el_jacobi *b, double *tx, double *ty)
{
    *tx = a->dn * b->dn - k * k * a->sn * b->sn;
    *ty = k * (a->sn * b->dn + a->dn * b->sn);
}

int el_discrete_eval(const el_discrete_params *p, size_t n, double *xy)
{
    int st = check_args(p, n, 2, xy);
    el__walk wk;
    if (st == EL_EINVAL) return st;
    if (st || walk_start(p, n, 0, &wk)) return domain_error(xy, 2 * n, NULL, 0);
    const double c = p->h * cos(p->phi), s = p->h * sin(p->phi);
    double x = p->x0, y = p->y0;
    el_jacobi prev = {0}, v[BLOCK];   /* prev: set before its first use (i > 0) */
    for (size_t i0 = 0; i0 < n; i0 += BLOCK) {
        const size_t nb = n - i0 < BLOCK ? n - i0 : BLOCK;
        if (el__walk_values(&wk, nb, NULL, v, NULL)) return domain_error(xy, 2 * n, NULL, 0);
        for (size_t j = 0; j < nb; j++) {
            const size_t i = i0 + j;
            if (i > 0) {
                double tx, ty;
                segment_tangent(p->k, &prev, &v[j], &tx, &ty);
                x += c * tx - s * ty;
                y += s * tx + c * ty;
            }
            xy[2 * i] = x; xy[2 * i + 1] = y;
            prev = v[j];
        }
    }
    if (!isfinite(x) || !isfinite(y)) return domain_error(xy, 2 * n, NULL, 0);
    return EL_OK;
}

/* el_discrete_curvature's vertex where the ratio may not serve (dn(z) or, at k = 1,
 * cn(u_i) below DBL_MIN): before[0], before[1], b are vertices i - 1, i, i + 1. */
static double kappa_general(double k, double two_h, int by_ratio, double t,
                           const el_jacobi before[2], const el_jacobi *b)
{
    if (by_ratio && fabs(before[1].cn) >= DBL_MIN) return two_h * (t * before[1].cn);
    const el_jacobi *a = &before[0];
    const double sinK = k * (b->sn * a->dn - b->dn * a->sn);
    const double cosK = b->dn * a->dn + k * k * b->sn * a->sn;
    const double kap = two_h * sinK / (1.0 + cosK);
    /* k = 1 far out where both terms underflow too: the ratio's signed zero */
    return by_ratio && kap == 0.0 ? two_h * (t * before[1].cn) : kap;
}

/* kappa_i = (2/h) tan(K_i/2), K_i = Theta_i - Theta_{i-1} = a_{i+1} - a_{i-1} (3.4). With
 * u = u_i, u_{i+-1} = u +- z, the addition theorems (sin a = k sn, cos a = dn) give
 *   sin K_i = 2 k sn(z) dn(z) cn(u) / Q,  1 + cos K_i = 2 dn(z)^2 / Q,  Q = dn(u)^2 + k^2 sn(u)^2 cn(z)^2,
 * so tan(K_i/2) = k sn(z) cn(u_i) / dn(z): one product per vertex, exact to a few roundings
 * of cn(u_i) (the discrete (4.3)'s kappa = 2 k sqrt(mu) cn(u)). The difference
 * k (sn_{i+1} dn_{i-1} - dn_{i+1} sn_{i-1}) of nearly equal terms lost eps / |K| relative
 * (1.9e-7 at z = 2.4e-8); it stays only where dn(z) is below DBL_MIN (k = 1 and |z| > ~708,
 * where cn(u_i) and dn(z) underflow but tan(K_i/2) = sinh z / cosh u_i need not, and at k = 1
 * where cn(u_i) alone does, |u_i| > ~708: kappa_general; k > 1 with
 * K = pi to double precision: infinite curvature, EL_EDOM either way). */
int el_discrete_curvature(const el_discrete_params *p, size_t n, double *kappa)
{
    int st = check_args(p, n, 3, kappa);
    el__walk wk;
    el_jacobi zv;
    if (st == EL_EINVAL) return st;
    if (st || walk_start(p, n, 0, &wk) || el__jacobi_values(&wk.mod, p->z, &zv))
        return domain_error(kappa, n - 2, NULL, 0);
    const double k = p->k, two_h = 2.0 / p->h;
    const int by_ratio = fabs(zv.dn) >= DBL_MIN;
    const double t = by_ratio ? k * zv.sn / zv.dn : 0.0; /* tan(K_i/2) / cn(u_i); |t| < 1 / DBL_MIN */
    /* k = 1: cn(u_i) = sech u_i underflows past |u_i| ~ 708 where t = sinh z can be large and
     * sinh z / cosh u_i an ordinary number (e^-40 at z = 700, u_i = 740): the difference there
     * (its terms sech(u_i - z), sech(u_i + z) do not both underflow). k != 1: cn underflows
     * only next to its zeros, where the product's absolute error is below DBL_MIN |t|. */
    const int plain = by_ratio && fabs(k) != 1.0;   /* the ratio at every vertex */
    double bad = 0.0; /* x * 0 is NaN for inf and NaN */
    el_jacobi before[2] = {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0}}, v[BLOCK]; /* vertices i-2, i-1 */
    for (size_t i0 = 0; i0 < n; i0 += BLOCK) {
        const size_t nb = n - i0 < BLOCK ? n - i0 : BLOCK;
        if (el__walk_values(&wk, nb, NULL, v, NULL)) return domain_error(kappa, n - 2, NULL, 0);
        /* i = i0 + j: vertex i is one ahead of the interior vertex i - 1, kappa[i - 2] */
        if (plain) {
            for (size_t j = 0; j < nb; j++) {
                if (i0 + j >= 2) {
                    kappa[i0 + j - 2] = two_h * (t * before[1].cn);
                    bad += kappa[i0 + j - 2] * 0.0;
                }
                before[1] = v[j];
            }
        } else {
            for (size_t j = 0; j < nb; j++) {
                if (i0 + j >= 2) {
                    kappa[i0 + j - 2] = kappa_general(k, two_h, by_ratio, t, before, &v[j]);
                    bad += kappa[i0 + j - 2] * 0.0;
                }
                before[0] = before[1];
                before[1] = v[j];
            }
        }
    }
    if (bad != 0.0) return domain_error(kappa, n - 2, NULL, 0);
    return EL_OK;
}

/* Recursion (4.10): d gamma_{i+1} = d gamma_i + h R(phi) N_i (d a_i + d a_{i+1}) for z, q, k,
 * with d a/du = k cn and d a/dk = dn (sn + k sn_k) - k sn dn_k (from dn^2 + k^2 sn^2 = 1). */
int el_discrete_jacobian(const el_discrete_params *p, size_t n, double *xy, double *jac)
{
    int st = check_args(p, n, 2, jac);
    el__walk wk;
    if (st == EL_EINVAL) return st;
    if (st || walk_start(p, n, 1, &wk)) return domain_error(xy, 2 * n, jac, 14 * n);
    const double k = p->k, h = p->h, c = cos(p->phi), s = sin(p->phi);
    double x = p->x0, y = p->y0, bad = 0.0;
    double dz[2] = {0, 0}, dq[2] = {0, 0}, dk[2] = {0, 0};
    double az0 = 0.0, aq0 = 0.0, ak0 = 0.0; /* derivatives of a_(i-1) */
    el_jacobi prev, v[BLOCK], vk[BLOCK];
    for (size_t i0 = 0; i0 < n; i0 += BLOCK) {
        const size_t nb = n - i0 < BLOCK ? n - i0 : BLOCK;
        if (el__walk_values(&wk, nb, NULL, v, vk)) return domain_error(xy, 2 * n, jac, 14 * n);
        for (size_t j = 0; j < nb; j++) {
            const size_t i = i0 + j;
            const el_jacobi *b = &v[j], *bk = &vk[j];
            const double az1 = (double)i * k * b->cn, aq1 = k * b->cn;
            const double ak1 = b->dn * (b->sn + k * bk->sn) - k * b->sn * bk->dn;
            if (i > 0) { /* segment i - 1 -> i */
                double tx, ty;
                segment_tangent(k, &prev, b, &tx, &ty);
                const double Tx = c * tx - s * ty, Ty = s * tx + c * ty; /* global tangent */
                const double Nx = -h * Ty, Ny = h * Tx;                  /* h times global normal */
                x += h * Tx; y += h * Ty;
                dz[0] += Nx * (az0 + az1); dz[1] += Ny * (az0 + az1);
                dq[0] += Nx * (aq0 + aq1); dq[1] += Ny * (aq0 + aq1);
                dk[0] += Nx * (ak0 + ak1); dk[1] += Ny * (ak0 + ak1);
            }
            double *rx = jac + 2 * i * 7, *ry = rx + 7;
            rx[0] = 1.0; rx[1] = 0.0; rx[2] = (x - p->x0) / h; rx[3] = -(y - p->y0);
            ry[0] = 0.0; ry[1] = 1.0; ry[2] = (y - p->y0) / h; ry[3] = x - p->x0;
            rx[4] = dz[0]; rx[5] = dq[0]; rx[6] = dk[0];
            ry[4] = dz[1]; ry[5] = dq[1]; ry[6] = dk[1];
            if (xy) { xy[2 * i] = x; xy[2 * i + 1] = y; }
            az0 = az1; aq0 = aq1; ak0 = ak1;
            prev = *b;
        }
        bad += (x + dz[0] + dz[1] + dq[0] + dq[1] + dk[0] + dk[1]) * 0.0;
    }
    if (bad != 0.0 || !isfinite(y)) return domain_error(xy, 2 * n, jac, 14 * n);
    return EL_OK;
}
