/*
 * Bobenko–Suris discrete elastica, seed 000 §3–4, in the form (4.3)–(4.4)
 * with the erratum of (4.4): Theta_n = phi + a_n + a_{n+1}, where
 * a_n = (theta_n - phi)/2, sin a_n = k sn(u_n;k), cos a_n = dn(u_n;k),
 * u_n = z n + q, and gamma_{n+1} = gamma_n + h (cos Theta_n, sin Theta_n).
 * The u_n are an arithmetic progression, so the Jacobi values come from the
 * addition theorems (el__jacobi_progression) at a few flops per vertex.
 */
#include "internal.h"
#include <stdlib.h>

int el_discrete_check(const el_discrete_params *p)
{
    if (!p) return EL_EINVAL;
    const double v[7] = {p->x0, p->y0, p->h, p->phi, p->z, p->q, p->k};
    if (el__all_finite(v, 7) || !(p->h > 0.0) || p->k < 0.0) return EL_EINVAL;
    return EL_OK;
}

/* Jacobi values (and k-derivatives if dk) at the n vertices. */
static int vertex_jacobi(const el_discrete_params *p, size_t n, el_jacobi **val, el_jacobi **dk)
{
    el_jacobi *v = malloc((dk ? 2 : 1) * n * sizeof *v);
    if (!v) return EL_ENOMEM;
    int st = el__jacobi_progression(p->q, p->z, p->k, n, v, dk ? v + n : NULL);
    if (st) { free(v); return st; }
    *val = v;
    if (dk) *dk = v + n;
    return EL_OK;
}

/* Tangent of segment i in the frame rotated by phi: angle a_i + a_{i+1}. */
static void segment_tangent(double k, const el_jacobi *a, const el_jacobi *b, double *tx, double *ty)
{
    *tx = a->dn * b->dn - k * k * a->sn * b->sn;
    *ty = k * (a->sn * b->dn + a->dn * b->sn);
}

int el_discrete_eval(const el_discrete_params *p, size_t n, double *xy)
{
    if (el_discrete_check(p) || n < 2 || !xy) return EL_EINVAL;
    el_jacobi *v;
    int st = vertex_jacobi(p, n, &v, NULL);
    if (st) return st;
    const double c = p->h * cos(p->phi), s = p->h * sin(p->phi);
    double x = p->x0, y = p->y0;
    xy[0] = x; xy[1] = y;
    for (size_t i = 0; i + 1 < n; i++) {
        double tx, ty;
        segment_tangent(p->k, &v[i], &v[i + 1], &tx, &ty);
        x += c * tx - s * ty;
        y += s * tx + c * ty;
        xy[2 * i + 2] = x; xy[2 * i + 3] = y;
    }
    free(v);
    return EL_OK;
}

/* kappa_i = (2/h) tan(K_i/2), K_i = Theta_i - Theta_{i-1} = a_{i+1} - a_{i-1} (3.4). */
int el_discrete_curvature(const el_discrete_params *p, size_t n, double *kappa)
{
    if (el_discrete_check(p) || n < 3 || !kappa) return EL_EINVAL;
    el_jacobi *v;
    int st = vertex_jacobi(p, n, &v, NULL);
    if (st) return st;
    const double k = p->k;
    for (size_t i = 1; i + 1 < n; i++) {
        const el_jacobi *a = &v[i - 1], *b = &v[i + 1];
        const double sinK = k * (b->sn * a->dn - b->dn * a->sn);
        const double cosK = b->dn * a->dn + k * k * b->sn * a->sn;
        kappa[i - 1] = 2.0 / p->h * sinK / (1.0 + cosK);
    }
    free(v);
    return EL_OK;
}

/* Recursion (4.10): d gamma_{i+1} = d gamma_i + h R(phi) N_i (d a_i + d a_{i+1}) for z, q, k,
 * with d a/du = k cn and d a/dk = dn (sn + k sn_k) - k sn dn_k (from dn^2 + k^2 sn^2 = 1). */
int el_discrete_jacobian(const el_discrete_params *p, size_t n, double *xy, double *jac)
{
    if (el_discrete_check(p) || n < 2 || !jac) return EL_EINVAL;
    el_jacobi *v, *vk;
    int st = vertex_jacobi(p, n, &v, &vk);
    if (st) return st;
    const double k = p->k, h = p->h, c = cos(p->phi), s = sin(p->phi);
    double x = p->x0, y = p->y0;
    double dz[2] = {0, 0}, dq[2] = {0, 0}, dk[2] = {0, 0};
    double az0 = 0.0, aq0 = k * v[0].cn, ak0 = v[0].dn * (v[0].sn + k * vk[0].sn) - k * v[0].sn * vk[0].dn;
    for (size_t i = 0; i < n; i++) {
        double *rx = jac + 2 * i * 7, *ry = rx + 7;
        rx[0] = 1.0; rx[1] = 0.0; rx[2] = (x - p->x0) / h; rx[3] = -(y - p->y0);
        ry[0] = 0.0; ry[1] = 1.0; ry[2] = (y - p->y0) / h; ry[3] = x - p->x0;
        rx[4] = dz[0]; rx[5] = dq[0]; rx[6] = dk[0];
        ry[4] = dz[1]; ry[5] = dq[1]; ry[6] = dk[1];
        if (xy) { xy[2 * i] = x; xy[2 * i + 1] = y; }
        if (i + 1 == n) break;
        const el_jacobi *b = &v[i + 1], *bk = &vk[i + 1];
        const double az1 = (double)(i + 1) * k * b->cn, aq1 = k * b->cn;
        const double ak1 = b->dn * (b->sn + k * bk->sn) - k * b->sn * bk->dn;
        double tx, ty;
        segment_tangent(k, &v[i], b, &tx, &ty);
        const double Tx = c * tx - s * ty, Ty = s * tx + c * ty; /* global tangent */
        const double Nx = -h * Ty, Ny = h * Tx;                  /* h times global normal */
        x += h * Tx; y += h * Ty;
        dz[0] += Nx * (az0 + az1); dz[1] += Ny * (az0 + az1);
        dq[0] += Nx * (aq0 + aq1); dq[1] += Ny * (aq0 + aq1);
        dk[0] += Nx * (ak0 + ak1); dk[1] += Ny * (ak0 + ak1);
        az0 = az1; aq0 = aq1; ak0 = ak1;
    }
    free(v);
    return EL_OK;
}
