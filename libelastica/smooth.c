/*
 * Smooth elastica segment in closed form, seed 000 (4.3) with the continuous
 * parameter u = sqrt(mu) s + q; one formula for every real k (header): the
 * Jacobi functions take |k|, and the sign of k is the orientation (k -> -k is
 * the mirror image in the line through (x0, y0) at angle phi).
 *
 * With a = (theta - phi)/2, sin a = k sn u, cos a = dn u, the unit tangent in
 * the frame rotated by phi is (cos 2a, sin 2a) = (1 - 2k^2 sn^2, 2k sn dn), and
 * since d/du D = sn^2 and d/du cn = -sn dn:
 *   X(s) = ((u - q) - 2k^2 (D(u) - D(q))) / sqrt(mu),
 *   Y(s) = -2k (cn u - cn q) / sqrt(mu),
 *   gamma(s) = (x0, y0) + R(phi) (X, Y),   kappa = 2 a' = 2k sqrt(mu) cn u.
 */
#include "internal.h"
#include <stdlib.h>

int el_smooth_check(const el_smooth_params *p)
{
    if (!p) return EL_EINVAL;
    const double v[7] = {p->x0, p->y0, p->phi, p->mu, p->k, p->q, p->length};
    if (el__all_finite(v, 7) || !(p->mu > 0.0) || p->length < 0.0) return EL_EINVAL;
    return EL_OK;
}

/* True when s is an arithmetic progression to rounding (sampling grids). */
static int equally_spaced(size_t n, const double *s)
{
    if (n < 8) return 0;
    const double ds = (s[n - 1] - s[0]) / (double)(n - 1);
    const double tol = 1e-13 * (fabs(s[0]) + fabs(s[n - 1]) + fabs(ds) * (double)n);
    for (size_t i = 0; i < n; i++)
        if (fabs(s[i] - (s[0] + ds * (double)i)) > tol) return 0;
    return 1;
}

/* Jacobi values (and derivatives in |k|, with a modulus prepared with_dk) at
 * u_i = sqrt(mu) s_i + q, plus the base point u = q. */
static int jacobi_at(const el_smooth_params *p, const el__modulus *mod, size_t n, const double *s,
                     el_jacobi *val, el_jacobi *dk, el_jacobi *base, el_jacobi *base_dk)
{
    const double w = sqrt(p->mu);
    int st = el__jacobi_eval_mod(mod, p->q, base, NULL, base_dk);
    if (st) return st;
    if (equally_spaced(n, s)) {
        const double ds = (s[n - 1] - s[0]) / (double)(n - 1);
        return el__jacobi_progression(w * s[0] + p->q, w * ds, fabs(p->k), n, val, dk);
    }
    for (size_t i = 0; i < n; i++) {
        if (s[i] == 0.0 && (!dk || base_dk)) {          /* u = q: the base point itself */
            val[i] = *base;
            if (dk) dk[i] = *base_dk;
        } else if ((st = el__jacobi_eval_mod(mod, w * s[i] + p->q, &val[i], NULL, dk ? &dk[i] : NULL))) {
            return st;
        }
    }
    return EL_OK;
}

/* theta - phi = 2a with a continuous in s, a odd in k. For |k| <= 1, |a| <= pi/2
 * (dn >= 0); for |k| > 1, a = am(|k| u; 1/|k|) grows without bound: the branch of
 * atan2(|k| sn, dn) nearest n pi, n = the number of half periods 2K(1/|k|) in |k| u. */
static double half_angle(double u, double k, double K_reciprocal, const el_jacobi *v)
{
    const double ka = fabs(k);
    double a = atan2(ka * v->sn, v->dn);
    if (ka > 1.0) {
        double npi = M_PI * nearbyint(ka * u / (2.0 * K_reciprocal));
        a += 2.0 * M_PI * nearbyint((npi - a) / (2.0 * M_PI));
    }
    return copysign(1.0, k) * a;
}

static int check_eval_args(const el_smooth_params *p, size_t n, const double *s)
{
    if (el_smooth_check(p)) return EL_EINVAL;
    if (n > 0 && !s) return EL_EINVAL;
    return n > 0 ? el__all_finite(s, n) : EL_OK;
}

int el_smooth_eval(const el_smooth_params *p, size_t n, const double *s,
                   double *xy, double *theta, double *kappa)
{
    int st = check_eval_args(p, n, s);
    if (st || n == 0) return st;
    el__modulus mod;
    if ((st = el__modulus_init(fabs(p->k), 0, &mod))) return st;
    el_jacobi *v = malloc(n * sizeof *v), b;
    if (!v) return EL_ENOMEM;
    if ((st = jacobi_at(p, &mod, n, s, v, NULL, &b, NULL))) { free(v); return st; }
    const double w = sqrt(p->mu), k = p->k, c = cos(p->phi), sp = sin(p->phi);
    for (size_t i = 0; i < n; i++) {
        const double u = w * s[i] + p->q;
        if (xy) {
            const double X = ((u - p->q) - 2.0 * k * k * (v[i].D - b.D)) / w;
            const double Y = -2.0 * k * (v[i].cn - b.cn) / w;
            xy[2 * i] = p->x0 + c * X - sp * Y;
            xy[2 * i + 1] = p->y0 + sp * X + c * Y;
        }
        if (theta) theta[i] = p->phi + 2.0 * half_angle(u, k, mod.K, &v[i]);
        if (kappa) kappa[i] = 2.0 * k * w * v[i].cn;
    }
    free(v);
    return EL_OK;
}

int el_smooth_jacobian(const el_smooth_params *p, size_t n, const double *s,
                       double *xy, double *jac)
{
    int st = check_eval_args(p, n, s);
    if (st || n == 0) return st;
    if (!jac) return EL_EINVAL;
    el__modulus mod;
    if ((st = el__modulus_init(fabs(p->k), 1, &mod))) return st;
    el_jacobi *v = malloc(2 * n * sizeof *v), b, bk;
    if (!v) return EL_ENOMEM;
    el_jacobi *vk = v + n;
    if ((st = jacobi_at(p, &mod, n, s, v, vk, &b, &bk))) { free(v); return st; }
    const double w = sqrt(p->mu), k = p->k, c = cos(p->phi), sp = sin(p->phi);
    const double m = k * k, sgn = copysign(1.0, k);
    for (size_t i = 0; i < n; i++) {
        const double si = s[i], u = w * si + p->q;
        const double P = (u - p->q) - 2.0 * m * (v[i].D - b.D), X = P / w;
        const double Qy = -2.0 * k * (v[i].cn - b.cn), Y = Qy / w;
        /* tangent in the rotated frame */
        const double tx = 1.0 - 2.0 * m * v[i].sn * v[i].sn, ty = 2.0 * k * v[i].sn * v[i].dn;
        /* d/dw with u = w s + q: dP/dw = s tx, dQy/dw = s ty */
        const double Xw = (si * tx - X) / w, Yw = (si * ty - Y) / w;
        /* vk holds derivatives in |k|: d/dk = sign(k) d/d|k| */
        const double Xk = (-4.0 * k * (v[i].D - b.D) - 2.0 * m * sgn * (vk[i].D - bk.D)) / w;
        const double Yk = (-2.0 * (v[i].cn - b.cn) - 2.0 * k * sgn * (vk[i].cn - bk.cn)) / w;
        const double Xq = -2.0 * m * (v[i].sn * v[i].sn - b.sn * b.sn) / w;
        const double Yq = 2.0 * k * (v[i].sn * v[i].dn - b.sn * b.dn) / w;
        const double t = p->length > 0.0 ? si / p->length : 0.0;
        /* local derivative vectors (X,Y)_p for phi, mu, k, q, length */
        const double lx[5] = {-Y, Xw / (2.0 * w), Xk, Xq, t * tx};
        const double ly[5] = {X, Yw / (2.0 * w), Yk, Yq, t * ty};
        double *rx = jac + (2 * i) * 7, *ry = rx + 7;
        rx[0] = 1.0; rx[1] = 0.0;
        ry[0] = 0.0; ry[1] = 1.0;
        for (int j = 0; j < 5; j++) {
            rx[2 + j] = c * lx[j] - sp * ly[j];
            ry[2 + j] = sp * lx[j] + c * ly[j];
        }
        if (xy) {
            xy[2 * i] = p->x0 + c * X - sp * Y;
            xy[2 * i + 1] = p->y0 + sp * X + c * Y;
        }
    }
    free(v);
    return EL_OK;
}

/* int kappa^2 ds = 4 k^2 mu int cn^2 ds = 4 k^2 sqrt(mu) [(u - D(u))]_q^{u1}. */
int el_smooth_energy(const el_smooth_params *p, double *energy)
{
    if (el_smooth_check(p) || !energy) return EL_EINVAL;
    const double w = sqrt(p->mu), u1 = w * p->length + p->q;
    el_jacobi a, b;
    int st;
    if ((st = el_jacobi_eval(p->q, fabs(p->k), &a, NULL, NULL))) return st;
    if ((st = el_jacobi_eval(u1, fabs(p->k), &b, NULL, NULL))) return st;
    *energy = 4.0 * p->k * p->k * w * ((u1 - p->q) - (b.D - a.D));
    return EL_OK;
}
