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
#include <float.h>
#include <stdint.h>

/* No caller can pass more points: jac would hold 14 n doubles, past SIZE_MAX bytes. */
#define MAX_POINTS (SIZE_MAX / (14 * sizeof(double)))

int el_smooth_check(const el_smooth_params *p)
{
    if (!p) return EL_EINVAL;
    /* isfinite inline (every evaluation and end check passes here) */
    if (!(isfinite(p->x0) && isfinite(p->y0) && isfinite(p->phi) && isfinite(p->mu) && isfinite(p->k) &&
          isfinite(p->q) && isfinite(p->length)) || !(p->mu > 0.0) || p->length < 0.0)
        return EL_EINVAL;
    return EL_OK;
}

/* Points per block: the Jacobi values of one block live on the stack, so evaluation
 * needs no memory that grows with n. */
enum { BLOCK = 64 };

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

/* What one pass over the samples finds (EL_EINVAL for a non-finite s): the largest
 * |u| = |sqrt(mu) s + q| (with the base point u = q) and |s|, and whether s is an
 * arithmetic progression to a few roundings (sampling grids such as linspace; the
 * grid walk evaluates at s0 + ds i, at most 8 eps (|s0| + |s_(n-1)|) from s_i). */
typedef struct samples {
    double umax, smax;
    int uniform;
} samples;

static int scan_samples(const el_smooth_params *p, size_t n, const double *s, samples *sc)
{
    if (el_smooth_check(p) || (n > 0 && !s) || n > MAX_POINTS) return EL_EINVAL;
    const double w = sqrt(p->mu), ds = n > 1 ? (s[n - 1] - s[0]) / (double)(n - 1) : 0.0;
    double umax = fabs(p->q), smax = 0.0, dev = 0.0;
    int finite = 1;
    for (size_t i = 0; i < n; i++) {
        const double u = fabs(w * s[i] + p->q), a = fabs(s[i]), e = fabs(s[i] - (s[0] + ds * (double)i));
        finite &= a <= DBL_MAX; /* false for NaN too */
        umax = u > umax ? u : umax;
        smax = a > smax ? a : smax;
        dev = e > dev ? e : dev;
    }
    if (!finite) return EL_EINVAL;
    sc->umax = umax;
    sc->smax = smax;
    sc->uniform = n >= WALK_MIN_POINTS && dev <= 8.0 * DBL_EPSILON * (fabs(s[0]) + fabs(s[n - 1]));
    return EL_OK;
}

/*
 * EL_EDOM when double precision cannot resolve the samples (header): the phase
 * max(1, |k|)|u| past EL__PHASE_MAX (|k| != 1), or the closed form's rounding,
 * eps (1 + |u|)(1 + |k|) / sqrt(mu) (u = sqrt(mu) s + q is rounded, then D(u) - D(q)
 * and cn u - cn q are divided by sqrt(mu)), above 1e-3 of the extent
 * max(length, |s_i|): fewer than three digits left.
 */
static int smooth_domain(const el_smooth_params *p, const samples *sc)
{
    const double w = sqrt(p->mu), ka = fabs(p->k), umax = sc->umax;
    if (!isfinite(umax) || (ka != 1.0 && (ka > 1.0 ? ka : 1.0) * umax > EL__PHASE_MAX))
        return EL_EDOM;
    const double extent = sc->smax > p->length ? sc->smax : p->length;
    if (DBL_EPSILON * (1.0 + umax) * (1.0 + ka) > 1e-3 * w * extent && extent > 0.0) return EL_EDOM;
    return EL_OK;
}

/* Every output element NaN (the contract of EL_EDOM): nothing half-written looks valid. */
static void fill_nan(double *a, size_t count)
{
    if (a)
        for (size_t i = 0; i < count; i++) a[i] = NAN;
}

/* The walk over u_i = sqrt(mu) s_i + q (the grid walk for equally spaced s) and the
 * Jacobi values at the base point u = q. */
static int walk_start(const el_smooth_params *p, size_t n, const double *s, const samples *sc,
                      int with_dk, el__walk *wk, el_jacobi *base, el_jacobi *base_dk)
{
    const double w = sqrt(p->mu);
    int st = smooth_domain(p, sc);
    if (!st) st = el__walk_init(wk, fabs(p->k), with_dk, n);
    if (!st && sc->uniform)
        st = el__walk_grid(wk, w * s[0] + p->q, w * ((s[n - 1] - s[0]) / (double)(n - 1)));
    /* am is not read (el__jacobi_values: the same other values, no atan2) */
    if (!st) st = base_dk ? el__jacobi_eval_mod(&wk->mod, p->q, base, NULL, base_dk) : el__jacobi_values(&wk->mod, p->q, base);
    return st ? EL_EDOM : EL_OK; /* inputs are checked: only overflow fails here */
}

/* The Jacobi values at the block's points u (and their k-derivatives if vk). A point
 * at the base u = q itself (s = 0: the start of every end-residual check) takes the
 * base point's values when each point gets a fresh evaluation anyway (WALK_PLAIN):
 * the same evaluation, so the same values, one evaluation fewer. (The other walks
 * step from point to point: skipping one would change their path.) */
static int block_values(el__walk *wk, size_t nb, const double *u, double q, const el_jacobi *base,
                        const el_jacobi *base_dk, el_jacobi *v, el_jacobi *vk)
{
    if (wk->mode != WALK_PLAIN) return el__walk_values(wk, nb, u, v, vk);
    for (size_t j = 0; j < nb; j++) {
        if (u[j] == q) {
            v[j] = *base;
            if (vk) vk[j] = *base_dk;
            continue;
        }
        const int st = el__walk_values(wk, 1, u + j, v + j, vk ? vk + j : NULL);
        if (st) return st;
    }
    return EL_OK;
}

/* The curve's frame (el__smooth_curve's p, w, iw, c, s; the modulus and base point are
 * the caller's). */
static void curve_frame(const el_smooth_params *p, el__smooth_curve *c)
{
    c->p = *p;
    c->w = sqrt(p->mu);
    c->iw = 1.0 / c->w;
    c->c = cos(p->phi);
    c->s = sin(p->phi);
}

/* The point at u = sqrt(mu) s + q from its Jacobi values v (the header's formulas):
 * position, tangent angle and curvature into entry i of those of xy, theta, kappa not
 * NULL; adds x - x of each value written to *finite (0 while all are finite). */
static inline void point_values(const el__smooth_curve *c, double u, const el_jacobi *v, size_t i,
                                double *xy, double *theta, double *kappa, double *finite)
{
    const el_smooth_params *p = &c->p;
    const double k = p->k;
    if (xy) {
        const double X = ((u - p->q) - 2.0 * k * k * (v->D - c->base.D)) * c->iw;
        const double Y = -2.0 * k * (v->cn - c->base.cn) * c->iw;
        xy[2 * i] = p->x0 + c->c * X - c->s * Y;
        xy[2 * i + 1] = p->y0 + c->s * X + c->c * Y;
        *finite += (xy[2 * i] - xy[2 * i]) + (xy[2 * i + 1] - xy[2 * i + 1]);
    }
    if (theta) {
        theta[i] = p->phi + 2.0 * half_angle(u, k, c->mod.K, v);
        *finite += theta[i] - theta[i];
    }
    if (kappa) {
        kappa[i] = 2.0 * k * c->w * v->cn;
        *finite += kappa[i] - kappa[i];
    }
}

int el_smooth_eval(const el_smooth_params *p, size_t n, const double *s,
                   double *xy, double *theta, double *kappa)
{
    samples sc;
    int st = scan_samples(p, n, s, &sc);
    if (st || n == 0) return st;
    el__walk wk;
    el_jacobi b;
    st = walk_start(p, n, s, &sc, 0, &wk, &b, NULL);
    /* the curve for point_values, a copy no callee sees: the stores through xy cannot
     * alias it (its base filled in place, as block_values' argument: +0.6 % instructions
     * on 1000-point evaluations) */
    el__smooth_curve cv;
    if (!st) {
        curve_frame(p, &cv);
        cv.mod = wk.mod;
        cv.base = b;
    }
    double finite = 0.0; /* x - x is 0 for finite x, NaN otherwise: stays 0 while no output overflows */
    for (size_t i0 = 0; i0 < n && !st; i0 += BLOCK) {
        const size_t nb = n - i0 < BLOCK ? n - i0 : BLOCK;
        double u[BLOCK];
        el_jacobi v[BLOCK];
        for (size_t j = 0; j < nb; j++) u[j] = cv.w * s[i0 + j] + p->q;
        if ((st = block_values(&wk, nb, u, p->q, &b, NULL, v, NULL))) break;
        for (size_t j = 0; j < nb; j++) point_values(&cv, u[j], &v[j], i0 + j, xy, theta, kappa, &finite);
    }
    if (st || finite != 0.0) {
        fill_nan(xy, 2 * n);
        fill_nan(theta, n);
        fill_nan(kappa, n);
        return EL_EDOM;
    }
    return EL_OK;
}

/* Header (internal.h): with two samples the walk is WALK_PLAIN (n < WALK_MIN_POINTS), each
 * point a fresh el__jacobi_values and the one at u = q the base point's values
 * (block_values), so these are the prepared curve's two points (el__smooth_point, below);
 * the status: the domain of the two samples together is that of the end s = length alone
 * (umax and the extent largest there), which a failing start shares (test_hermite_tension.c
 * compares the two bit for bit). 1.2 % of the tension mode's instructions went to the
 * general path's set-up. */
int el__smooth_ends(const el_smooth_params *p, double xy[4], double th[2])
{
    el__smooth_curve c;
    int st = el__smooth_prepare(p, &c);
    if (st == EL_EINVAL) return st;
    if (!st) st = el__smooth_point(&c, 0.0, xy, th, NULL);
    if (!st) st = el__smooth_point(&c, p->length, xy + 2, th + 1, NULL);
    if (st) {
        fill_nan(xy, 4);
        fill_nan(th, 2);
        return EL_EDOM;
    }
    return EL_OK;
}

/* Header (internal.h): el_smooth_eval with one sample is WALK_PLAIN, the point a fresh
 * el__jacobi_values (the base point's values at u = q), the domain checked with
 * umax = max(|q|, |u|) and smax = |s| (scan_samples, smooth_domain): the same here, the
 * modulus and base point once. Measured (k = 0.8, s over [0.3, 2.3]): a single-point
 * el_smooth_eval 600-690 ns, this 280-320 ns. */
int el__smooth_prepare(const el_smooth_params *p, el__smooth_curve *c)
{
    if (el_smooth_check(p)) return EL_EINVAL;
    curve_frame(p, c);
    /* the domain is each point's (el__smooth_point); these fail only where it does or
     * on overflow, as in el_smooth_eval */
    return el__modulus_init(fabs(p->k), 0, &c->mod) || el__jacobi_values(&c->mod, p->q, &c->base) ? EL_EDOM : EL_OK;
}

int el__smooth_point(const el__smooth_curve *c, double s, double xy[2], double *theta, double *kappa)
{
    const el_smooth_params *p = &c->p;
    const double u = c->w * s + p->q;
    if (!(fabs(s) <= DBL_MAX)) return EL_EINVAL;
    const double au = fabs(u), uq = fabs(p->q);
    const samples sc = {au > uq ? au : uq, fabs(s), 0};
    el_jacobi v;
    int st = smooth_domain(p, &sc);
    if (!st) {
        if (u == p->q) v = c->base;
        else st = el__jacobi_values(&c->mod, u, &v) ? EL_EDOM : EL_OK;
    }
    double finite = 0.0;
    if (!st) point_values(c, u, &v, 0, xy, theta, kappa, &finite);
    if (st || finite != 0.0) {
        fill_nan(xy, 2);
        fill_nan(theta, 1);
        fill_nan(kappa, 1);
        return EL_EDOM;
    }
    return EL_OK;
}

int el_smooth_jacobian(const el_smooth_params *p, size_t n, const double *s,
                       double *xy, double *jac)
{
    samples sc;
    int st = scan_samples(p, n, s, &sc);
    if (st || n == 0) return st;
    if (!jac) return EL_EINVAL;
    el__walk wk;
    el_jacobi b, bk;
    st = walk_start(p, n, s, &sc, 1, &wk, &b, &bk);
    const double w = sqrt(p->mu), iw = 1.0 / w, k = p->k, c = cos(p->phi), sp = sin(p->phi);
    const double m = k * k, sgn = copysign(1.0, k);
    double finite = 0.0; /* as in el_smooth_eval */
    for (size_t i0 = 0; i0 < n && !st; i0 += BLOCK) {
        const size_t nb = n - i0 < BLOCK ? n - i0 : BLOCK;
        double u[BLOCK];
        el_jacobi v[BLOCK], vk[BLOCK];
        for (size_t j = 0; j < nb; j++) u[j] = w * s[i0 + j] + p->q;
        if ((st = block_values(&wk, nb, u, p->q, &b, &bk, v, vk))) break;
        for (size_t j = 0; j < nb; j++) {
            const size_t i = i0 + j;
            const double si = s[i];
            const double X = ((u[j] - p->q) - 2.0 * m * (v[j].D - b.D)) * iw;
            const double Y = -2.0 * k * (v[j].cn - b.cn) * iw;
            /* tangent in the rotated frame */
            const double tx = 1.0 - 2.0 * m * v[j].sn * v[j].sn, ty = 2.0 * k * v[j].sn * v[j].dn;
            /* d/dw with u = w s + q: dP/dw = s tx, dQy/dw = s ty */
            const double Xw = (si * tx - X) * iw, Yw = (si * ty - Y) * iw;
            /* vk holds derivatives in |k|: d/dk = sign(k) d/d|k| */
            const double Xk = (-4.0 * k * (v[j].D - b.D) - 2.0 * m * sgn * (vk[j].D - bk.D)) * iw;
            const double Yk = (-2.0 * (v[j].cn - b.cn) - 2.0 * k * sgn * (vk[j].cn - bk.cn)) * iw;
            const double Xq = -2.0 * m * (v[j].sn * v[j].sn - b.sn * b.sn) * iw;
            const double Yq = 2.0 * k * (v[j].sn * v[j].dn - b.sn * b.dn) * iw;
            const double t = p->length > 0.0 ? si / p->length : 0.0;
            /* local derivative vectors (X,Y)_p for phi, mu, k, q, length */
            const double lx[5] = {-Y, 0.5 * Xw * iw, Xk, Xq, t * tx};
            const double ly[5] = {X, 0.5 * Yw * iw, Yk, Yq, t * ty};
            double *rx = jac + (2 * i) * 7, *ry = rx + 7;
            rx[0] = 1.0; rx[1] = 0.0;
            ry[0] = 0.0; ry[1] = 1.0;
            double zero = 0.0; /* as in el_smooth_eval */
            for (int col = 0; col < 5; col++) {
                rx[2 + col] = c * lx[col] - sp * ly[col];
                ry[2 + col] = sp * lx[col] + c * ly[col];
                zero += (rx[2 + col] - rx[2 + col]) + (ry[2 + col] - ry[2 + col]);
            }
            if (xy) {
                xy[2 * i] = p->x0 + c * X - sp * Y;
                xy[2 * i + 1] = p->y0 + sp * X + c * Y;
                zero += (xy[2 * i] - xy[2 * i]) + (xy[2 * i + 1] - xy[2 * i + 1]);
            }
            finite += zero;
        }
    }
    if (st || finite != 0.0) {
        fill_nan(xy, 2 * n);
        fill_nan(jac, 14 * n);
        return EL_EDOM;
    }
    return EL_OK;
}

/* Run backwards (header): the end point by el_smooth_eval, the rest by sn odd, dn even. */
int el_smooth_reverse(const el_smooth_params *p, el_smooth_params *out)
{
    if (!out || el_smooth_check(p)) return EL_EINVAL;
    double end[2];
    int st = el_smooth_eval(p, 1, &p->length, end, NULL, NULL);
    if (st) return st;
    const el_smooth_params r = {end[0], end[1], p->phi + M_PI, p->mu, -p->k,
                                -(sqrt(p->mu) * p->length + p->q), p->length};
    if (el_smooth_check(&r)) return EL_EDOM;
    *out = r;
    return EL_OK;
}

/* int kappa^2 ds = 4 k^2 mu int cn^2 ds = 4 k^2 sqrt(mu) [u - D(u)]_q^{u1}; at |k| = 1,
 * 4 sqrt(mu) [E(u)]_q^{u1} with E = tanh (no cancellation of u - D for long curves). */
int el_smooth_energy(const el_smooth_params *p, double *energy)
{
    samples sc;
    if (!p || !energy || scan_samples(p, 1, &p->length, &sc)) return EL_EINVAL;
    const double w = sqrt(p->mu), u1 = w * p->length + p->q, ka = fabs(p->k);
    el__modulus mod;
    el_jacobi a, b;
    if (smooth_domain(p, &sc) || el__modulus_init(ka, 0, &mod) ||
        el__jacobi_values(&mod, p->q, &a) || el__jacobi_values(&mod, u1, &b)) {   /* E, D: no am */
        *energy = NAN;
        return EL_EDOM;
    }
    const double e = ka == 1.0 ? 4.0 * w * (b.E - a.E) : 4.0 * ka * ka * w * ((u1 - p->q) - (b.D - a.D));
    *energy = isfinite(e) ? e : NAN;
    return isfinite(e) ? EL_OK : EL_EDOM;
}
