/*
 * Hermite interpolation by elastic curves, seed 004: all curves of length at
 * most one curvature period from (p0, t0) to (p1, t1).
 *
 * Relations (rederived; the OCR lost them). With T = x', N = J T the constant
 * force vector of 2 kappa'' + kappa^3 - sigma kappa = 0 is
 *   F = (kappa^2 - sigma) T + 2 kappa' N,      |F| = kappa_m^2 - sigma,    (8)
 * (d/ds F = (2 kappa'' + kappa^3 - sigma kappa) N = 0), and
 *   kappa(s) - kappa(0) = det(x(s) - x(0), F) / 2,                        (10)
 *   E(s) = int_0^s kappa^2 = <F, x(s) - x(0)> + sigma s.                   (12)
 * In the normalised frame x(0) = 0, T(0) = (0,1), N(0) = (-1,0),
 * F = (-2 kappa0', kappa0^2 - sigma); F in the frame of V = x'(L) gives
 *   kappa1' = kappa0' V2 + (kappa0^2 - sigma) V1 / 2,                      (14)
 *   kappa1^2 = -2 kappa0' V1 + (kappa0^2 - sigma) V2 + sigma,              (15)
 *   kappa1 = kappa0' P2 + (kappa0^2 - sigma) P1 / 2 + kappa0.              (16)
 * Eliminating kappa0' with (16): P2 kappa1^2 + 2 V1 kappa1 - 2 V1 C - A P2 = 0
 * (17) with A = (kappa0^2 - sigma) V2 + sigma, C = (kappa0^2 - sigma) P1/2 + kappa0.
 *
 * In the library's parametrisation (header, seed 000 (4.3)): kappa_m^2 = 4 k^2 mu,
 * |F| = 2 mu, sigma = 2 mu (2k^2 - 1), phi = angle of F, and with
 * h = (theta - phi)/2: k < 1: sn u = sin h / k, cn u = kappa / kappa_m, so the
 * amplitude of u is atan2(sqrt(2|F|) sin h, kappa); k > 1: am(k u; 1/k) = h.
 *
 * Objective (35): given the curvature data at both ends the curve meets the
 * tangent V and the component of P across F (Theorem 8); the remaining
 * condition is the component along F, which by (12) is
 *   f = (E(L) - sigma L - <F, P>) / |F|     (the position error along F).
 * This is the paper's x1(L) - P1 rotated into the frame of F; unlike x1 it
 * stays a valid objective where F is parallel to x1 (kappa0^2 = sigma).
 */
#include "internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_poly.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>
#include <stdlib.h>
#include <string.h>

/* 4 sqrt(2) K(1/sqrt 2): the period times kappa_m of the sigma = 0 elastica. */
#define C0_PERIOD 10.4882572784299
#define MAXPTS 64

/* ------------------------------------------------------------ elliptic helpers */

/* Carlson's R_F(x, y, z) and R_D(x, y, z) together by the duplication theorem
 * (Carlson 1995, DLMF 19.36.1-2): both integrals share the duplicated arguments.
 * Written by hand because this is the inner loop of every objective evaluation
 * and GSL's gsl_sf_ellint_RF_e/RD_e (error estimates, argument checks, one
 * duplication loop each) cost about five times as much; agrees with GSL to 1e-15
 * relative (checked on 2e5 random arguments while writing; the end-condition
 * tests check it indirectly, every solution being verified by smooth.c).
 * x, y, z >= 0, at most one of x, y zero, z > 0. */
static void carlson_fd(double x, double y, double z, double qs, double *rf, double *rd)
{
    const double AF0 = (x + y + z) / 3.0, AD0 = (x + y + 3.0 * z) / 5.0;
    const double x0 = x, y0 = y;
    /* Q = (3r)^(-1/6) max|A0 - .| for R_F and (r/4)^(-1/6) max|A0 - .| for R_D, r = 1e-16;
     * qs = 1, or qs = 0.1 for r = 1e-10 (the coarse samples, see fobj_coarse) */
    const double QF = qs * 2.4e2 * fmax(fabs(AF0 - x), fmax(fabs(AF0 - y), fabs(AF0 - z)));
    const double QD = qs * 5.2e2 * fmax(fabs(AD0 - x), fmax(fabs(AD0 - y), fabs(AD0 - z)));
    double AF = AF0, AD = AD0, f4 = 1.0, sum = 0.0;
    while (f4 * QF >= fabs(AF) || f4 * QD >= fabs(AD)) {
        const double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        const double lam = sx * sy + sx * sz + sy * sz;
        sum += f4 / (sz * (z + lam));
        AF = 0.25 * (AF + lam);
        AD = 0.25 * (AD + lam);
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        f4 *= 0.25;
    }
    {
        const double X = f4 * (AF0 - x0) / AF, Y = f4 * (AF0 - y0) / AF, Z = -X - Y;
        const double E2 = X * Y - Z * Z, E3 = X * Y * Z;
        *rf = (1.0 - E2 / 10.0 + E3 / 14.0 + E2 * E2 / 24.0 - 3.0 * E2 * E3 / 44.0) / sqrt(AF);
    }
    {
        const double X = f4 * (AD0 - x0) / AD, Y = f4 * (AD0 - y0) / AD, Z = -(X + Y) / 3.0;
        const double XY = X * Y, Z2 = Z * Z;
        const double E2 = XY - 6.0 * Z2, E3 = (3.0 * XY - 8.0 * Z2) * Z;
        const double E4 = 3.0 * (XY - Z2) * Z2, E5 = XY * Z2 * Z;
        *rd = f4 / (AD * sqrt(AD)) *
                  (1.0 - 3.0 * E2 / 14.0 + E3 / 6.0 + 9.0 * E2 * E2 / 88.0 - 3.0 * E4 / 22.0 -
                   9.0 * E2 * E3 / 52.0 + 3.0 * E5 / 26.0) + 3.0 * sum;
    }
}

/* F(alpha, k) and D(alpha, k) = int_0^alpha sin^2 t / sqrt(1 - k^2 sin^2 t) dt for
 * every real alpha (k < 1, or k = 1 with |alpha| < pi/2):
 * F = s R_F(c^2, 1 - k^2 s^2, 1), D = s^3 R_D(c^2, 1 - k^2 s^2, 1) / 3 on
 * |alpha| <= pi/2, and the quasi-periods 2 Kc, 2 Dc. */
static int ell_fd(double alpha, double sa, double ca, double k, double Kc, double Dc, double qs,
                  double *F, double *D)
{
    /* alpha = n pi + b, |b| <= pi/2: sin b = (-1)^n sin alpha, cos^2 b = cos^2 alpha */
    const double n = nearbyint(alpha / M_PI);
    const double s = fmod(n, 2.0) != 0.0 ? -sa : sa, c2 = ca * ca, s2 = s * s;
    const double y = 1.0 - k * k * s2;
    double rf, rd;
    if (!(y > 0.0) && !(c2 > 0.0)) return EL_EDOM;
    carlson_fd(c2, y, 1.0, qs, &rf, &rd);
    *F = s * rf + 2.0 * n * Kc;
    *D = s * s2 * rd / 3.0 + 2.0 * n * Dc;
    return (isfinite(*F) && isfinite(*D)) ? EL_OK : EL_EDOM;
}

/* sin and cos of h = atan2(S, C) / 2 in (-pi/2, pi/2], R = hypot(S, C) > 0, by the
 * half-angle formulas (no atan2, sin, cos in the objective's inner loop). */
static void half_angle(double S, double C, double R, double *sh, double *ch)
{
    if (C >= 0.0) {
        *ch = sqrt(0.5 * (1.0 + C / R));
        *sh = S / (2.0 * R * *ch);
    } else {
        *sh = (S >= 0.0 ? 1.0 : -1.0) * sqrt(0.5 * (1.0 - C / R));
        *ch = S / (2.0 * R * *sh);
    }
}

/* Complete integrals Kc = F(pi/2, k), Dc = D(pi/2, k), k < 1, by the AGM (quadratic
 * convergence, one sqrt per step; three times cheaper than R_F and R_D here):
 * a0 = 1, b0 = k', c0 = k, c_{n+1} = c_n^2 / (4 a_{n+1}), K = pi / (2 a_N), and
 * K - E = K sum 2^(n-1) c_n^2, so Dc = (K - E)/k^2 = K sum 2^(n-1) (c_n/k)^2 with
 * c_n / k carried along (no cancellation as k -> 0). */
static int ell_complete(double k, double *Kc, double *Dc)
{
    const double kp2 = 1.0 - k * k;
    if (!(kp2 > 0.0) || !(k >= 0.0)) return EL_EDOM;
    double a = 1.0, b = sqrt(kp2), c = k, ct = 1.0, w = 0.5, sum = 0.5; /* ct = c_n / k */
    /* stop at |a - b| <= 1e-9 a: one more step is then exact to rounding (quadratic
     * convergence); it is taken without the sqrt, b being irrelevant after it */
    for (int n = 0; n < 40; n++) {
        const double an = 0.5 * (a + b);
        ct = c * ct / (4.0 * an);   /* c_{n+1}/k = c_n (c_n/k) / (4 a_{n+1}) */
        c = c * c / (4.0 * an);
        w *= 2.0;
        sum += w * ct * ct;
        const int last = fabs(a - b) <= 1e-9 * a;
        b = sqrt(a * b);
        a = an;
        if (last) break;
    }
    *Kc = M_PI / (2.0 * a);
    *Dc = *Kc * sum;
    return EL_OK;
}

/* x reduced into (0, period]. */
static double wrap_pos(double x, double period)
{
    double r = fmod(x, period);
    if (r <= 0.0) r += period;
    return r;
}

static double wrap_pi(double a) /* into (-pi, pi] */
{
    a = fmod(a, 2.0 * M_PI);
    if (a <= -M_PI) a += 2.0 * M_PI;
    if (a > M_PI) a -= 2.0 * M_PI;
    return a;
}

/* ------------------------------------------------------------ the normalised problem */

typedef struct hprob {
    double P1, P2, V1, V2, sigma;
    int hcase;        /* 1, 2, 3 (Theorem 6) */
    double Lmin;      /* lower bound of the length: 1 (tension mode) or L (length mode) */
    double B;         /* kappa_m bound (Theorem 9); < 0: no solution */
} hprob;

/* Curvature data at both ends and the values derived from it. */
typedef struct hstate {
    double k0, k0p, k1, k1p;   /* kappa0, kappa0', kappa1, kappa1' */
    double Fn, km2;            /* |F|, kappa_m^2 */
    int infl;                  /* inflectional (k < 1) */
    double L, T, E;            /* length, period, energy */
    double f;                  /* objective */
} hstate;

/* Case 3 (P2 = 0, V1 = 0): the four kappa0 of (24) as functions of sigma:
 * kappa0^2 = sigma, or (P1 kappa0 + 2)^2 = sigma P1^2 + 4 V2. NaN if not real. */
static double case3_kappa0(const hprob *pr, int fam)
{
    const double s = pr->sigma;
    if (fam < 2) return s >= 0.0 ? (fam ? -sqrt(s) : sqrt(s)) : NAN;
    const double r = s * pr->P1 * pr->P1 + 4.0 * pr->V2;
    if (r < 0.0) return NAN;
    return (-2.0 + (fam == 2 ? 1.0 : -1.0) * sqrt(r)) / pr->P1;
}

/* Theorem 6: curvature data for the unknown x (kappa0 in case 1, 2; kappa0' in
 * case 3) on branch b (case 1: root of (17); case 3: the kappa0 of (24)). */
static int curvdata(const hprob *pr, double x, int b, hstate *st)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    double k0, k0p, k1;
    if (pr->hcase == 3) {
        k0 = case3_kappa0(pr, b);
        if (!isfinite(k0)) return EL_EDOM;
        k0p = x;
        k1 = 0.5 * (k0 * k0 - s) * P1 + k0;                /* (16), P2 = 0 */
    } else {
        k0 = x;
        const double w = k0 * k0 - s, C = 0.5 * w * P1 + k0, A = w * V2 + s;
        if (pr->hcase == 2) {
            k1 = C;                                          /* (21) */
            k0p = (A - C * C) / (2.0 * V1);                  /* (22) */
        } else {
            const double c0 = 2.0 * V1 * C + A * P2;
            const double disc = V1 * V1 + P2 * c0;           /* (18) */
            if (disc < 0.0) return EL_EDOM;
            const double sq = sqrt(disc);
            /* (19) in the cancellation-free form: b = 0 is (-V1 + sq)/P2, b = 1 is (-V1 - sq)/P2 */
            if (b == 0) k1 = V1 > 0.0 ? c0 / (V1 + sq) : (-V1 + sq) / P2;
            else        k1 = V1 < 0.0 ? c0 / (V1 - sq) : (-V1 - sq) / P2;
            /* (20) kappa0' = (kappa1 - C)/P2, or equivalently (15) solved for kappa0' */
            k0p = fabs(V1) > fabs(P2) ? (A - k1 * k1) / (2.0 * V1) : (k1 - C) / P2;
        }
    }
    st->k0 = k0;
    st->k0p = k0p;
    st->k1 = k1;
    st->k1p = k0p * V2 + 0.5 * (k0 * k0 - s) * V1;          /* (14) */
    return isfinite(k1) && isfinite(k0p) ? EL_OK : EL_EDOM;
}

/* Theorem 7 and its supplement: the curvature function through (kappa0, kappa0')
 * reaches (kappa1, kappa1') at a unique L in (0, T]; then length, energy and
 * the objective f. */
static int shape_eval(const hprob *pr, double qs, hstate *st)
{
    const double s = pr->sigma;
    const double F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s;
    /* sqrt rather than hypot (inner loop; the values are far from overflow) */
    const double Fn = sqrt(F1 * F1 + F2 * F2);
    if (!(Fn > 1e-13 * (1.0 + fabs(s)))) return EL_EDOM; /* circle (kappa_m^2 = sigma), (45) */
    const double km2 = Fn + s;
    if (!(km2 > 0.0)) return EL_EDOM;                    /* kappa = 0: straight, handled apart */
    const double k2 = km2 / (2.0 * Fn), rmu = sqrt(0.5 * Fn);
    /* h = (theta - phi)/2 at both ends: theta - phi = atan2(-2 kappa', kappa^2 - sigma) */
    const double S1 = -2.0 * st->k1p, C1 = st->k1 * st->k1 - s;
    double sh0, ch0, sh1, ch1;
    half_angle(F1, F2, Fn, &sh0, &ch0);
    half_angle(S1, C1, sqrt(S1 * S1 + C1 * C1), &sh1, &ch1);
    double L, T, E;
    int rc;
    if (k2 < 1.0) {
        /* amplitude of u: sin = sin h / k = sqrt(2|F|) sin h / kappa_m, cos = kappa / kappa_m */
        const double k = sqrt(k2), sF = sqrt(2.0 * Fn), km = sqrt(km2);
        double Kc, Dc, Fa, Da, Fb, Db;
        if ((rc = ell_complete(k, &Kc, &Dc))) return rc;
        const double s0 = sF * sh0 / km, c0 = st->k0 / km, s1 = sF * sh1 / km, c1 = st->k1 / km;
        const double al0 = atan2(s0, c0);
        const double al1 = al0 + wrap_pos(atan2(s1, c1) - al0, 2.0 * M_PI);
        if ((rc = ell_fd(al0, s0, c0, k, Kc, Dc, qs, &Fa, &Da)) ||
            (rc = ell_fd(al1, s1, c1, k, Kc, Dc, qs, &Fb, &Db)))
            return rc;
        const double du = Fb - Fa;                       /* u(L) - u(0) */
        L = du / rmu;
        T = 4.0 * Kc / rmu;
        E = km2 / rmu * (du - (Db - Da));                /* int cn^2 du = u - int sn^2 du */
    } else {
        /* non-inflectional: kappa keeps its sign, Theorem 7 (ii) needs kappa0 kappa1 > 0 (44);
         * am(k u; 1/k) = h (the sign eps of kappa mirrors the curve) */
        if (!(st->k0 * st->k1 > 0.0)) return EL_EDOM;
        const double eps = st->k0 > 0.0 ? 1.0 : -1.0, m = sqrt(1.0 / k2), kk = sqrt(k2);
        double Kc, Dc, Fa, Da, Fb, Db;
        if ((rc = ell_complete(m, &Kc, &Dc))) return rc;
        const double b0 = eps * atan2(sh0, ch0), e1 = eps * atan2(sh1, ch1);
        const double b1 = b0 + wrap_pos(e1 - b0, M_PI);
        /* b1 = e1 + j pi: sin b1 = (-1)^j sin e1 (the sign is fixed inside ell_fd) */
        const double j = nearbyint((b1 - e1) / M_PI), sg = fmod(j, 2.0) != 0.0 ? -1.0 : 1.0;
        if ((rc = ell_fd(b0, eps * sh0, ch0, m, Kc, Dc, qs, &Fa, &Da)) ||
            (rc = ell_fd(b1, sg * eps * sh1, ch1, m, Kc, Dc, qs, &Fb, &Db)))
            return rc;
        const double dv = Fb - Fa, w = kk * rmu;         /* v = k u, dv/ds = k sqrt(mu) */
        L = dv / w;
        T = 2.0 * Kc / w;
        E = km2 / w * (dv - m * m * (Db - Da));          /* int dn^2 dv = F - m^2 D */
    }
    st->Fn = Fn;
    st->km2 = km2;
    st->infl = k2 < 1.0;
    st->L = L;
    st->T = T;
    st->E = E;
    st->f = (E - s * L - (F1 * pr->P1 + F2 * pr->P2)) / Fn;   /* (12) along F */
    return isfinite(st->f) && L > 0.0 ? EL_OK : EL_EDOM;
}

static int full_eval(const hprob *pr, double x, int b, hstate *st)
{
    int rc = curvdata(pr, x, b, st);
    return rc ? rc : shape_eval(pr, 1.0, st);
}

/* ------------------------------------------------------------ Theorem 9: the kappa_m bound */

/* Period of the inflectional elastica with kappa_m, sigma (kappa_m^2 > 2 sigma). */
static double period_infl(double km, double sigma)
{
    const double Fn = km * km - sigma, k = sqrt(km * km / (2.0 * Fn));
    double K, D;
    if (ell_complete(k, &K, &D)) return NAN;   /* the AGM: cheaper than gsl_sf_ellint_Kcomp_e */
    return 4.0 * K / sqrt(0.5 * Fn);
}

typedef struct { double sigma, Lmin; } tparam;
static double period_gap(double km, void *p)
{
    const tparam *t = p;
    return period_infl(km, t->sigma) - t->Lmin;
}

/* Every solution has T >= L >= Lmin. sigma <= 0: k^2 <= 1/2, so
 * T <= 4 K(1/sqrt2) sqrt2 / sqrt(kappa_m^2 - sigma) and kappa_m^2 <= (C0/Lmin)^2 + sigma;
 * sigma > 0: the non-inflectional curves have kappa_m^2 <= 2 sigma, and T decreases
 * with kappa_m on the inflectional side (proof of Theorem 9): solve T(kappa_m) = Lmin
 * (Brent). This is (37) without the epsilon: exact for every sigma. */
static int kappa_bound(double sigma, double Lmin, double *B)
{
    const double c = C0_PERIOD / Lmin;
    if (sigma <= 0.0) {
        const double b2 = c * c + sigma;
        *B = b2 > 0.0 ? sqrt(b2) * (1.0 + 1e-9) : -1.0;
        return EL_OK;
    }
    const double lo = sqrt(2.0 * sigma) * (1.0 + 1e-12);
    double hi = sqrt(2.0 * sigma) + c;
    for (int i = 0; i < 200 && !(period_infl(hi, sigma) < Lmin); i++) hi *= 2.0;
    if (!(period_infl(hi, sigma) < Lmin)) return EL_EINTERNAL;
    if (!(period_infl(lo, sigma) > Lmin)) { *B = lo; return EL_OK; }
    tparam tp = {sigma, Lmin};
    gsl_function fn = {period_gap, &tp};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    if (gsl_root_fsolver_set(s, &fn, lo, hi) != GSL_SUCCESS) { gsl_root_fsolver_free(s); return EL_EINTERNAL; }
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
        double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(a, b, 0.0, 1e-12) == GSL_SUCCESS) break;
    }
    *B = gsl_root_fsolver_x_upper(s) * (1.0 + 1e-9);
    gsl_root_fsolver_free(s);
    return EL_OK;
}

/* ------------------------------------------------------------ split points */

typedef struct { double v[MAXPTS]; int n; } ptlist;

static void pt_add(ptlist *l, double x)
{
    if (isfinite(x) && l->n < MAXPTS) l->v[l->n++] = x;
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Real roots of sum c[i] x^i (degree <= 8) by gsl_poly_complex_solve. */
static int poly_real_roots(const double *c_in, int deg, double *roots, int *nroots)
{
    double c[9];
    double cmax = 0.0;
    for (int i = 0; i <= deg; i++) { c[i] = c_in[i]; cmax = fmax(cmax, fabs(c[i])); }
    *nroots = 0;
    while (deg > 0 && fabs(c[deg]) <= 1e-14 * cmax) deg--;
    if (deg <= 0) return EL_OK;
    if (deg <= 2) {
        double r0, r1;
        int n = deg == 2 ? gsl_poly_solve_quadratic(c[2], c[1], c[0], &r0, &r1)
                         : (r0 = -c[0] / c[1], 1);
        if (n > 0) roots[(*nroots)++] = r0;
        if (n > 1) roots[(*nroots)++] = r1;
        return EL_OK;
    }
    double z[16];
    gsl_poly_complex_workspace *w = gsl_poly_complex_workspace_alloc((size_t)deg + 1);
    if (!w) return EL_ENOMEM;
    int rc = gsl_poly_complex_solve(c, (size_t)deg + 1, w, z);
    gsl_poly_complex_workspace_free(w);
    if (rc != GSL_SUCCESS) return EL_EINTERNAL;
    for (int i = 0; i < deg; i++)
        if (fabs(z[2 * i + 1]) <= 1e-7 * (1.0 + fabs(z[2 * i]))) roots[(*nroots)++] = z[2 * i];
    return EL_OK;
}

/* Small polynomial arithmetic (coefficients low to high, degree <= 8). */
typedef struct { double c[9]; int d; } poly;
static poly pmul(poly a, poly b)
{
    poly r = {{0}, a.d + b.d};
    for (int i = 0; i <= a.d; i++)
        for (int j = 0; j <= b.d; j++) r.c[i + j] += a.c[i] * b.c[j];
    return r;
}
static poly padd(poly a, double sa, poly b, double sb)
{
    poly r = {{0}, a.d > b.d ? a.d : b.d};
    for (int i = 0; i <= a.d; i++) r.c[i] += sa * a.c[i];
    for (int i = 0; i <= b.d; i++) r.c[i] += sb * b.c[i];
    return r;
}

/* Polynomial (40) (Theorem 11): its roots are the kappa0 with kappa_m^2 = 2 sigma.
 * kappa_m^2 = 2 sigma in (8) gives 4 kappa0'^2 = -D, D = (kappa0^2 - sigma)^2 - sigma^2 (42).
 * Case 1: with (16) 4 (kappa1 - C)^2 + P2^2 D = 0 (43); subtracting 4/P2 (17) leaves
 * kappa1 = N / M, N = 4 P2 C^2 + P2^3 D + 8 V1 C + 4 A P2, M = 8 (P2 C + V1); so
 * 4 (N - C M)^2 + P2^2 D M^2 = 0, degree 8, leading 4 P2^2 (P1^2 + P2^2)^2 as printed.
 * Case 2: kappa0' = (A - C^2)/(2 V1) gives (A - C^2)^2 + V1^2 D = 0. */
static poly poly40(const hprob *pr)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    const poly w = {{-s, 0, 1}, 2};
    const poly C = {{-0.5 * s * P1, 1.0, 0.5 * P1}, 2};
    const poly A = {{s - s * V2, 0, V2}, 2};
    const poly one = {{1}, 0};
    const poly D = padd(pmul(w, w), 1.0, one, -s * s);
    if (pr->hcase == 2) {
        const poly AC = padd(A, 1.0, pmul(C, C), -1.0);
        return padd(pmul(AC, AC), 1.0, D, V1 * V1);
    }
    poly N = padd(pmul(C, C), 4.0 * P2, D, P2 * P2 * P2);
    N = padd(N, 1.0, C, 8.0 * V1);
    N = padd(N, 1.0, A, 4.0 * P2);
    const poly M = padd(C, 8.0 * P2, one, 8.0 * V1);
    const poly NC = padd(N, 1.0, pmul(C, M), -1.0);
    return padd(pmul(NC, NC), 4.0, pmul(D, pmul(M, M)), P2 * P2);
}

/* (45): kappa0^2 = sigma, and kappa0' = 0, which by (15), (16) is C^2 = A. With
 * w = kappa0^2 - sigma, C^2 - A = w (w P1^2/4 + P1 kappa0 + 1 - V2): the quartic
 * splits into kappa0^2 = sigma and a quadratic, so at most four values. */
static int special_values(const hprob *pr, double *out, int *n)
{
    *n = 0;
    const double s = pr->sigma, P1 = pr->P1, V2 = pr->V2;
    if (s >= 0.0) { out[(*n)++] = -sqrt(s); out[(*n)++] = sqrt(s); }
    if (pr->hcase == 3) return EL_OK;
    const double q[3] = {1.0 - V2 - 0.25 * s * P1 * P1, P1, 0.25 * P1 * P1};
    double r[2];
    int nr, rc = poly_real_roots(q, 2, r, &nr);
    if (rc) return rc;
    for (int i = 0; i < nr; i++) out[(*n)++] = r[i];
    return EL_OK;
}

/* The ends of (18) (case 1): disc(kappa0) = a2 kappa0^2 + a1 kappa0 + a0 >= 0. */
static void disc_coeffs(const hprob *pr, double a[3])
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    a[2] = P2 * V1 * P1 + P2 * P2 * V2;
    a[1] = 2.0 * P2 * V1;
    a[0] = V1 * V1 - P2 * V1 * P1 * s + P2 * P2 * s * (1.0 - V2);
}

/* Domain of the unknown on branch b: [-X, X]. */
static double domain_half(const hprob *pr, int b)
{
    if (pr->B < 0.0) return -1.0;
    if (pr->hcase != 3) return pr->B;
    const double k0 = case3_kappa0(pr, b), s = pr->sigma;
    if (!isfinite(k0) || k0 * k0 > pr->B * pr->B) return -1.0;
    const double a = pr->B * pr->B - s, c = k0 * k0 - s, r = a * a - c * c; /* (8) */
    return r > 0.0 ? 0.5 * sqrt(r) : -1.0;
}

/* Which root of (17) has kappa_m^2 = 2 sigma at a root of (40) (seed 004 §4:
 * the roots are divided in two groups, one per objective function). */
static int root_branch(const hprob *pr, double x)
{
    if (pr->hcase != 1) return 0;
    int best = 0;
    double bd = INFINITY;
    for (int b = 0; b < 2; b++) {
        hstate st;
        if (curvdata(pr, x, b, &st)) continue;
        const double F1 = -2.0 * st.k0p, F2 = st.k0 * st.k0 - pr->sigma;
        const double dd = fabs(hypot(F1, F2) - pr->sigma);   /* kappa_m^2 - 2 sigma */
        if (dd < bd) { bd = dd; best = b; }
    }
    return best;
}

/* Split points of branch b: (18) ends, (40) roots, (44) kappa0 = 0 and kappa1 = 0,
 * (45) special values; case 3: (41), kappa0' = 0. */
static int split_points(const hprob *pr, int b, const double *r40, const int *b40, int n40,
                        ptlist *l)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    double r[16];
    int nr, rc;
    l->n = 0;
    if (pr->hcase == 3) {
        const double k0 = case3_kappa0(pr, b), c = k0 * k0 - s, q = s * s - c * c;
        pt_add(l, 0.0);
        if (q >= 0.0) { pt_add(l, 0.5 * sqrt(q)); pt_add(l, -0.5 * sqrt(q)); } /* (41) */
        return EL_OK;
    }
    if (pr->hcase == 1) {
        double a[3];
        disc_coeffs(pr, a);
        if ((rc = poly_real_roots(a, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i]);
        /* kappa1 = 0 in (17): 2 V1 C + A P2 = 0 */
        const double q[3] = {V1 * P1 * s + P2 * V2 * s - P2 * s, -2.0 * V1, -V1 * P1 - P2 * V2};
        if ((rc = poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i]);
    } else {
        const double q[3] = {-0.5 * P1 * s, 1.0, 0.5 * P1}; /* C = 0 */
        if ((rc = poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i]);
    }
    pt_add(l, 0.0);
    for (int i = 0; i < n40; i++)
        if (b40[i] == b) pt_add(l, r40[i]);
    /* (45): seed 004 §4 evaluates the objective there and keeps the value as a split
     * point only where the objective vanishes (an unwanted zero) or is singular */
    if ((rc = special_values(pr, r, &nr))) return rc;
    for (int i = 0; i < nr; i++) {
        hstate st;
        if (full_eval(pr, r[i], b, &st) || fabs(st.f) < 1e-6) pt_add(l, r[i]);
    }
    return EL_OK;
}

/* ------------------------------------------------------------ root finding on the pieces */

/* The objective of one branch with a small cache of the last evaluations: GSL's
 * Brent re-evaluates the bracket ends (already sampled) in gsl_root_fsolver_set,
 * and the root it returns is its last evaluation, whose state the solution needs. */
#define NCACHE 4
typedef struct {
    const hprob *pr;
    int b, nfail;
    int ci;                      /* next slot */
    double cx[NCACHE];           /* cached abscissae (NaN: empty) */
    int crc[NCACHE], cfull[NCACHE];
    hstate cst[NCACHE];          /* cfull: full state, else only cst.f */
} fctx;

static void fctx_init(fctx *c, const hprob *pr, int b)
{
    memset(c, 0, sizeof *c);
    c->pr = pr;
    c->b = b;
    for (int i = 0; i < NCACHE; i++) c->cx[i] = NAN;
}

static void cache_put(fctx *c, double x, int rc, const hstate *st, int full)
{
    const int i = c->ci;
    c->ci = (i + 1) % NCACHE;
    c->cx[i] = x;
    c->crc[i] = rc;
    c->cfull[i] = full;
    c->cst[i] = *st;
}

/* full_eval through the cache; need_full: the whole state is wanted, not only f. */
static int cached_eval(fctx *c, double x, int need_full, hstate *st)
{
    for (int i = 0; i < NCACHE; i++)
        if (c->cx[i] == x && (c->cfull[i] || !need_full)) { *st = c->cst[i]; return c->crc[i]; }
    const int rc = full_eval(c->pr, x, c->b, st);
    cache_put(c, x, rc, st, 1);
    return rc;
}

/* Seed the cache with a known objective value (a sample). */
static void cache_seed(fctx *c, double x, double f)
{
    hstate st;
    memset(&st, 0, sizeof st);
    st.f = f;
    cache_put(c, x, isfinite(f) ? EL_OK : EL_EDOM, &st, 0);
}

/* The objective for the samples that look for sign changes: elliptic integrals to
 * 1e-10 instead of 1e-16 (two duplication steps fewer); only its sign is used, and
 * Brent and every accepted root use full_eval. */
static double fobj_coarse(fctx *c, double x)
{
    hstate st;
    int rc = curvdata(c->pr, x, c->b, &st);
    if (!rc) rc = shape_eval(c->pr, 0.1, &st);
    if (rc) { c->nfail++; return GSL_NAN; }
    return st.f;
}

static double fobj(double x, void *p)
{
    fctx *c = p;
    hstate st;
    if (cached_eval(c, x, 0, &st)) { c->nfail++; return GSL_NAN; }
    return st.f;
}

/* Raw solutions of the normalised problem. */
typedef struct { double x; int b; double sigma; hstate st; } hroot;
typedef struct { hroot *v; size_t n, cap; } hrootlist;

static hroot mkroot(double x, int b, double sigma)
{
    hroot r;
    memset(&r, 0, sizeof r);
    r.x = x;
    r.b = b;
    r.sigma = sigma;
    return r;
}

static int roots_push(hrootlist *l, const hroot *r)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : 16;
        hroot *v = realloc(l->v, cap * sizeof *v);
        if (!v) return EL_ENOMEM;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = *r;
    return EL_OK;
}

/* Brent (gsl_root_fsolver_brent) on [a, b] with f(a) f(b) < 0; accept a root where
 * |f| is small (a sign change across a jump of f is not a root). */
static int brent_root(fctx *c, double a, double fa, double b, double fb, hrootlist *out)
{
    cache_seed(c, a, fa);
    cache_seed(c, b, fb);
    gsl_function fn = {fobj, c};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    int ok = gsl_root_fsolver_set(s, &fn, a, b) == GSL_SUCCESS;
    double x = 0.5 * (a + b);
    for (int it = 0; ok && it < 200; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) { ok = 0; break; }
        x = gsl_root_fsolver_root(s);
        const double lo = gsl_root_fsolver_x_lower(s), hi = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(lo, hi, 1e-300, 4e-16) == GSL_SUCCESS) break;
        /* |f| (the end position error along F, |P| = 1) at rounding level: done, without
         * the last steps that only shrink the bracket from the other side (x was GSL's
         * last evaluation: the cache answers) */
        {
            hstate st;
            if (!cached_eval(c, x, 0, &st) && fabs(st.f) <= 1e-14) break;
        }
        /* a sign change across a jump of f (L wrapping at a period): |f| stays large
         * while the bracket shrinks; a root would need a slope above 1e5 */
        if (hi - lo < 1e-9 * (1.0 + fabs(x)) && !(fabs(fobj(x, c)) < 1e-4)) { ok = 0; break; }
    }
    gsl_root_fsolver_free(s);
    if (!ok) return EL_OK;
    hroot r = mkroot(x, c->b, c->pr->sigma);
    if (cached_eval(c, x, 1, &r.st)) return EL_OK;
    if (!(fabs(r.st.f) <= 1e-8)) return EL_OK;
    return roots_push(out, &r);
}

static double negf(double x, void *p) { return -fobj(x, p); }
static double posf(double x, void *p) { return fobj(x, p); }

/* Two zeros closer than the sampling step (seed 004 §5 (a), (b): at most two per
 * piece, the objective convex between them): minimise sign * f on the bracket;
 * if the minimum changes sign, both zeros are bracketed. */
static int touch_check(fctx *c, double a, double fa, double m, double fm, double b, double fb,
                       hrootlist *out)
{
    const double sg = fm > 0.0 ? 1.0 : -1.0;
    gsl_function fn = {fm > 0.0 ? posf : negf, c};
    gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!s) return EL_ENOMEM;
    int rc = EL_OK;
    /* the three samples are known: no re-evaluation */
    if (gsl_min_fminimizer_set_with_values(s, &fn, m, sg * fm, a, sg * fa, b, sg * fb) == GSL_SUCCESS) {
        for (int it = 0; it < 40; it++) {
            if (gsl_min_fminimizer_iterate(s) != GSL_SUCCESS) break;
            const double xm = gsl_min_fminimizer_x_minimum(s), v = gsl_min_fminimizer_f_minimum(s);
            if (v < 0.0) {
                gsl_min_fminimizer_free(s);
                const double fxm = fobj(xm, c);
                if ((rc = brent_root(c, a, fa, xm, fxm, out))) return rc;
                return brent_root(c, xm, fxm, b, fb, out);
            }
            if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(s), gsl_min_fminimizer_x_upper(s),
                                      1e-11, 1e-9) == GSL_SUCCESS) break;
        }
        /* a double zero (tangency): accept it when f vanishes there */
        const double xm = gsl_min_fminimizer_x_minimum(s);
        hroot r = mkroot(xm, c->b, c->pr->sigma);
        if (!cached_eval(c, xm, 1, &r.st) && fabs(r.st.f) <= 1e-11) rc = roots_push(out, &r);
    }
    gsl_min_fminimizer_free(s);
    return rc;
}

/* |f| at the vertex of the parabola through three samples around a local minimum
 * of |f| (same sign): small when two zeros may hide between the samples. */
static double parabola_min(const double *x, const double *f)
{
    const double sg = f[1] > 0.0 ? 1.0 : -1.0;
    const double d1 = (f[1] - f[0]) / (x[1] - x[0]), d2 = (f[2] - f[1]) / (x[2] - x[1]);
    const double a = (d2 - d1) / (x[2] - x[0]);          /* f = f1 + d (x - x1) + a (x - x1)^2 */
    const double d = d1 + a * (x[1] - x[0]);
    if (!(sg * a > 0.0)) return 0.0;                     /* not convex towards zero: check anyway */
    return sg * (f[1] - d * d / (4.0 * a));
}

/* Sample one piece (Chebyshev spacing, ends nudged inside: the split points are
 * where the objective is singular or not differentiable), Brent on sign changes. */
/* A sample whose |f| is below TOUCH_RATIO times both neighbours' (same sign) gets the
 * touch check even when the parabola through the three does not reach zero: the
 * objective is often far from a parabola on a sample interval (steep near a split
 * point). On 10 000 bench problems this halves the solutions missed against 300
 * samples (24 -> 12 of 25 256; sigma |p1-p0|^2 in [0, 5]: 170 -> 82 of 27 000), at
 * no measurable cost; it only adds checks, so it finds a superset. */
#define TOUCH_RATIO 0.5
static int solve_piece(fctx *c, double a, double b, int ns, hrootlist *out)
{
    double xs[1002], fs[1002];
    const double eps = 1e-10 * (b - a) + 1e-14 * (fabs(a) + fabs(b));
    int rc;
    if (!(b - a > 4.0 * eps)) return EL_OK;
    for (int j = 0; j <= ns; j++) {
        double t = 0.5 * (1.0 - cos(M_PI * j / ns));
        xs[j] = a + (b - a) * t;
        if (j == 0) xs[j] = a + eps;
        if (j == ns) xs[j] = b - eps;
        fs[j] = fobj_coarse(c, xs[j]);
    }
    for (int j = 0; j < ns; j++) {
        if (!isfinite(fs[j]) || !isfinite(fs[j + 1])) continue;
        if (fs[j] == 0.0) {
            hroot r = mkroot(xs[j], c->b, c->pr->sigma);
            if (!full_eval(c->pr, xs[j], c->b, &r.st) && (rc = roots_push(out, &r))) return rc;
        } else if (fs[j] * fs[j + 1] < 0.0) {
            if ((rc = brent_root(c, xs[j], fs[j], xs[j + 1], fs[j + 1], out))) return rc;
        } else if (j > 0 && isfinite(fs[j - 1]) && fs[j - 1] * fs[j] > 0.0 &&
                   fabs(fs[j]) < fabs(fs[j - 1]) && fabs(fs[j]) < fabs(fs[j + 1]) &&
                   (parabola_min(xs + j - 1, fs + j - 1) < 0.5 * fabs(fs[j]) ||
                    fabs(fs[j]) < TOUCH_RATIO * fmin(fabs(fs[j - 1]), fabs(fs[j + 1])))) {
            if ((rc = touch_check(c, xs[j - 1], fs[j - 1], xs[j], fs[j], xs[j + 1], fs[j + 1], out)))
                return rc;
        }
    }
    return EL_OK;
}

static int nbranches(const hprob *pr) { return pr->hcase == 1 ? 2 : pr->hcase == 2 ? 1 : 4; }

static void set_case(hprob *pr)
{
    const double tiny = 1e-13;
    if (fabs(pr->P2) > tiny) pr->hcase = 1;
    else if (fabs(pr->V1) > tiny) { pr->hcase = 2; pr->P2 = 0.0; }
    else {
        pr->hcase = 3;
        pr->P2 = 0.0;
        pr->V1 = 0.0;
        pr->P1 = pr->P1 > 0.0 ? 1.0 : -1.0;
        pr->V2 = pr->V2 > 0.0 ? 1.0 : -1.0;
    }
}

/* All roots of the objectives for fixed sigma (seed 004 §4). */
static int solve_tension_normalised(hprob *pr, int ns, hrootlist *out)
{
    int rc = kappa_bound(pr->sigma, pr->Lmin, &pr->B);
    if (rc || pr->B < 0.0) return rc;
    /* roots of (40) in [-B, B], each assigned to its objective; for sigma <= 0
     * kappa_m^2 = 2 sigma cannot happen (apart from kappa = 0, a split point anyway) */
    double r40[8];
    int b40[8], n40 = 0;
    if (pr->hcase != 3 && pr->sigma > 0.0) {
        double r[8];
        int nr;
        const poly p = poly40(pr);
        if ((rc = poly_real_roots(p.c, p.d, r, &nr))) return rc;
        for (int i = 0; i < nr; i++)
            if (fabs(r[i]) < pr->B) { r40[n40] = r[i]; b40[n40++] = root_branch(pr, r[i]); }
    }
    for (int b = 0; b < nbranches(pr); b++) {
        const double X = domain_half(pr, b);
        if (!(X > 0.0)) continue;
        ptlist l;
        if ((rc = split_points(pr, b, r40, b40, n40, &l))) return rc;
        double pts[MAXPTS + 2];
        int n = 0;
        pts[n++] = -X;
        pts[n++] = X;
        for (int i = 0; i < l.n; i++)
            if (l.v[i] > -X && l.v[i] < X) pts[n++] = l.v[i];
        qsort(pts, (size_t)n, sizeof *pts, cmp_double);
        fctx c;
        fctx_init(&c, pr, b);
        for (int i = 0; i + 1 < n; i++) {
            /* samples in proportion to the piece's share of the domain, at least 2 */
            const int m = 1 + (int)ceil(ns * (pts[i + 1] - pts[i]) / (2.0 * X));
            if ((rc = solve_piece(&c, pts[i], pts[i + 1], m > 1000 ? 1000 : m, out))) return rc;
        }
    }
    return EL_OK;
}

/* ------------------------------------------------------------ length mode */

/* Newton on (x, sigma) for f = 0, L = Lt with a finite-difference Jacobian. */
static int newton_length(hprob *pr, int b, double Lt, double x, double sg, hroot *res)
{
    hprob q = *pr;
    hstate st;
    double r0 = INFINITY;
    for (int it = 0; it < 30; it++) {
        q.sigma = sg;
        if (full_eval(&q, x, b, &st)) return EL_EDOM;
        const double g0 = st.f, h0 = (st.L - Lt) / Lt, r = fabs(g0) + fabs(h0);
        if (r < 1e-14) break;
        if (it > 0 && r >= r0 && r < 1e-11) break;
        r0 = r;
        const double hx = 1e-7 * (1.0 + fabs(x)), hs = 1e-7 * (1.0 + fabs(sg));
        hstate a, c;
        if (full_eval(&q, x + hx, b, &a)) { if (full_eval(&q, x - hx, b, &a)) return EL_EDOM; a.f = 2 * g0 - a.f; a.L = 2 * st.L - a.L; }
        q.sigma = sg + hs;
        if (full_eval(&q, x, b, &c)) return EL_EDOM;
        q.sigma = sg;
        const double J11 = (a.f - g0) / hx, J12 = (c.f - g0) / hs;
        const double J21 = (a.L - st.L) / (Lt * hx), J22 = (c.L - st.L) / (Lt * hs);
        const double det = J11 * J22 - J12 * J21;
        if (!(fabs(det) > 0.0) || !isfinite(det)) return EL_EDOM;
        double dx = -(J22 * g0 - J12 * h0) / det, ds = -(-J21 * g0 + J11 * h0) / det;
        /* trust region: the objective is only piecewise smooth (class changes, branch ends) */
        const double lim = fmax(fabs(dx) / (0.2 * (1.0 + fabs(x))), fabs(ds) / (0.2 * (1.0 + fabs(sg))));
        if (lim > 1.0) { dx /= lim; ds /= lim; }
        /* damping: halve until the residual decreases */
        int accepted = 0;
        for (int h = 0; h < 12; h++) {
            q.sigma = sg + ds;
            hstate t;
            if (!full_eval(&q, x + dx, b, &t) && fabs(t.f) + fabs((t.L - Lt) / Lt) < r) {
                x += dx;
                sg += ds;
                accepted = 1;
                break;
            }
            dx *= 0.5;
            ds *= 0.5;
        }
        q.sigma = sg;
        if (!accepted) break;
    }
    q.sigma = sg;
    if (full_eval(&q, x, b, &st)) return EL_EDOM;
    if (!(fabs(st.f) < 1e-9 && fabs(st.L - Lt) < 1e-9 * Lt)) return EL_ENOCONV;
    res->x = x;
    res->b = b;
    res->sigma = sg;
    res->st = st;
    return EL_OK;
}

/* sigma range of length-mode solutions (normalised |P| = 1, length Lt > 1):
 * sigma >= -(C0/Lt)^2 (Theorem 9 bound, sigma <= 0 case); and since
 * |P| >= <P, -F/|F|> = L - 2 int dn^2(u) ds >= L - 2 I / sqrt(mu) with I <= 2 pi the
 * integral of dn^2 over one period, mu <= (4 pi / (Lt - 1))^2 and
 * sigma = 2 mu (2k^2 - 1) <= 2 mu for k <= 1; for k > 1 likewise with
 * nu = k^2 mu <= (4 / (Lt - 1))^2 and sigma <= 4 nu. */
static void sigma_range(double Lt, double *lo, double *hi)
{
    const double c = C0_PERIOD / Lt, e = Lt - 1.0;
    *lo = -c * c;
    *hi = fmax(32.0 * M_PI * M_PI / (e * e), 64.0 / (e * e));
}

static int cmp_root(const void *a, const void *b)
{
    const hroot *x = a, *y = b;
    if (x->b != y->b) return x->b - y->b;
    return (x->x > y->x) - (x->x < y->x);
}

/* All tension solutions on the line sigma = sinh(t), sorted by branch and x. */
static int sigma_line(const hprob *pr, double t, int ns, hrootlist *l)
{
    hprob q = *pr;
    q.sigma = sinh(t);
    q.Lmin = 1.0;
    l->n = 0;
    int rc = solve_tension_normalised(&q, ns, l);
    if (!rc && l->n > 1) qsort(l->v, l->n, sizeof *l->v, cmp_root);
    return rc;
}

/* Neighbours on one line with L - Lt of opposite signs (a fold of the curve
 * between lines): Newton from their midpoint. */
static int line_pairs(hprob *pr, double Lt, const hrootlist *l, hrootlist *out)
{
    int rc = EL_OK;
    for (size_t a = 0; a + 1 < l->n && !rc; a++) {
        const hroot *ra = &l->v[a], *rb = &l->v[a + 1];
        if ((ra->st.L - Lt) * (rb->st.L - Lt) > 0.0) continue;
        hroot r;
        if (!newton_length(pr, ra->b, Lt, 0.5 * (ra->x + rb->x), ra->sigma, &r)) rc = roots_push(out, &r);
        if (!rc && rb->b != ra->b && !newton_length(pr, rb->b, Lt, 0.5 * (ra->x + rb->x), ra->sigma, &r))
            rc = roots_push(out, &r);
    }
    return rc;
}

/* Between the lines ta < tb: where the number of solutions changes (folds) the
 * strip is halved (depth <= 6); then every pair (root on a, root on b) with
 * L - Lt of opposite signs starts Newton from the interpolated point (the two
 * roots of (17) join where (18) vanishes, so a curve may change branch). */
static int strip_pairs(hprob *pr, double Lt, int ns, double ta, const hrootlist *A,
                       double tb, const hrootlist *B, int depth, hrootlist *out)
{
    int rc = EL_OK;
    if (A->n != B->n && depth < 6) {
        hrootlist M = {NULL, 0, 0};
        const double tm = 0.5 * (ta + tb);
        if (!(rc = sigma_line(pr, tm, ns, &M)) && !(rc = line_pairs(pr, Lt, &M, out)) &&
            !(rc = strip_pairs(pr, Lt, ns, ta, A, tm, &M, depth + 1, out)))
            rc = strip_pairs(pr, Lt, ns, tm, &M, tb, B, depth + 1, out);
        free(M.v);
        return rc;
    }
    for (size_t a = 0; a < A->n && !rc; a++)
        for (size_t c = 0; c < B->n && !rc; c++) {
            const hroot *ra = &A->v[a], *rb = &B->v[c];
            const double ha = ra->st.L - Lt, hb = rb->st.L - Lt;
            if (ha * hb > 0.0) continue;
            const double t = ha == hb ? 0.5 : ha / (ha - hb);
            const double x0 = ra->x + t * (rb->x - ra->x), s0 = ra->sigma + t * (rb->sigma - ra->sigma);
            hroot r;
            /* from the interpolated point, else from the nearer of the two roots (on the curve) */
            if (!newton_length(pr, ra->b, Lt, x0, s0, &r)) rc = roots_push(out, &r);
            else if (!newton_length(pr, ra->b, Lt, t < 0.5 ? ra->x : rb->x, t < 0.5 ? ra->sigma : rb->sigma, &r))
                rc = roots_push(out, &r);
            if (!rc && rb->b != ra->b && !newton_length(pr, rb->b, Lt, x0, s0, &r))
                rc = roots_push(out, &r);
        }
    return rc;
}

/* Length mode: on ng + 1 lines sigma_j (asinh-spaced over sigma_range) all tension
 * solutions are computed (above); the solution curves are continuous in sigma, so
 * a curve crossing L = Lt shows as a sign change of L - Lt between lines (or
 * between neighbours on one line near a fold), and starts Newton on (x, sigma). */
static int solve_length_normalised(hprob *pr, double Lt, int ng, int ns, hrootlist *out)
{
    double slo, shi;
    sigma_range(Lt, &slo, &shi);
    const double tlo = asinh(slo), thi = asinh(shi);
    hrootlist prev = {NULL, 0, 0}, cur = {NULL, 0, 0};
    int rc = EL_OK;
    double tprev = tlo;
    for (int j = 0; j <= ng && !rc; j++) {
        const double t = tlo + (thi - tlo) * j / ng;
        if ((rc = sigma_line(pr, t, ns, &cur)) || (rc = line_pairs(pr, Lt, &cur, out))) break;
        if (j > 0 && (rc = strip_pairs(pr, Lt, ns, tprev, &prev, t, &cur, 0, out))) break;
        hrootlist tmp = prev;
        prev = cur;
        cur = tmp;
        tprev = t;
    }
    free(prev.v);
    free(cur.v);
    return rc;
}

/* ------------------------------------------------------------ world-frame solutions */

/* el_smooth_params of the elastica starting at (x0, y0) with tangent angle theta,
 * curvature kappa, kappa' = dkappa, tension sigma, length L (the inverse of the
 * header's parametrisation, see the top of this file). A non-inflectional curve
 * (kappa != 0 throughout) gets the sign of kappa as the sign of k: k < -1 is the
 * clockwise loop, the mirror image of the k > 1 loop in the line through (x0, y0)
 * along F. The mirror R maps T -> R T, N -> -R N, kappa -> -kappa, kappa' -> -kappa',
 * so F = (kappa^2 - sigma) T + 2 kappa' N -> R F = F: phi and mu are those of the
 * mirrored curve, and with a = theta - phi over 2, sin a = k sn(u;|k|) =
 * sign(k) sn(|k| u; 1/|k|), cos a = dn(u;|k|) = cn(|k| u; 1/|k|), so
 * am(|k| q; 1/|k|) = sign(k) a. */
static int params_from_state(double x0, double y0, double theta, double kappa, double dkappa,
                             double sigma, double L, el_smooth_params *p)
{
    const double T[2] = {cos(theta), sin(theta)}, N[2] = {-T[1], T[0]};
    const double w = kappa * kappa - sigma;
    const double F[2] = {w * T[0] + 2.0 * dkappa * N[0], w * T[1] + 2.0 * dkappa * N[1]};
    const double Fn = hypot(F[0], F[1]);
    p->x0 = x0;
    p->y0 = y0;
    p->length = L;
    const double km2 = Fn + sigma;
    if (!(Fn > 0.0) || !(km2 > 0.0)) return EL_EDOM;
    const double k2 = km2 / (2.0 * Fn), h = 0.5 * wrap_pi(theta - atan2(F[1], F[0]));
    p->mu = 0.5 * Fn;
    p->phi = atan2(F[1], F[0]);
    double Kc, Dc, Fq, Dq;
    int rc;
    if (k2 < 1.0) {
        const double k = sqrt(k2);
        if ((rc = ell_complete(k, &Kc, &Dc))) return rc;
        const double y = sqrt(2.0 * Fn) * sin(h), r = hypot(y, kappa);
        if ((rc = ell_fd(atan2(y, kappa), y / r, kappa / r, k, Kc, Dc, 1.0, &Fq, &Dq))) return rc;
        p->k = k;
        p->q = Fq;
    } else {
        const double k = sqrt(k2), m = 1.0 / k, eps = kappa > 0.0 ? 1.0 : -1.0;
        if (!(kappa != 0.0)) return EL_EDOM;
        if ((rc = ell_complete(m, &Kc, &Dc))) return rc;
        if ((rc = ell_fd(eps * h, eps * sin(h), cos(h), m, Kc, Dc, 1.0, &Fq, &Dq))) return rc;
        p->k = eps * k;
        p->q = Fq / k;
    }
    return EL_OK;
}

typedef struct {
    double p0[2], p1[2], psi0, psi1, d, rot; /* rot = psi0 - pi/2: normalised -> world angle */
} frame;

static double angle_err(double a, double b) { return fabs(wrap_pi(a - b)); }

/* End residual of a solution measured with el_smooth_eval. */
static int residual(const frame *fr, const el_hermite_solution *s, double *res)
{
    const double sv[2] = {0.0, s->curve.length};
    double xy[4], th[2];
    int rc = el_smooth_eval(&s->curve, 2, sv, xy, th, NULL);
    if (rc) return rc;
    const double *a = fr->p0, *b = fr->p1;
    double e = fmax(hypot(xy[0] - a[0], xy[1] - a[1]), hypot(xy[2] - b[0], xy[3] - b[1])) / fr->d;
    e = fmax(e, fmax(angle_err(th[0], fr->psi0), angle_err(th[1], fr->psi1)));
    *res = e;
    return EL_OK;
}

/* Residual vector of a solution for the polish: end point (2, / d), tangent
 * angles at both ends (2), and the mode's scalar condition (sigma or length). */
static int polish_res(const frame *fr, const el_smooth_params *p, int mode, double target,
                      double *r)
{
    const double sv[2] = {0.0, p->length};
    double xy[4], th[2];
    int rc = el_smooth_eval(p, 2, sv, xy, th, NULL);
    if (rc) return rc;
    r[0] = (xy[2] - fr->p1[0]) / fr->d;
    r[1] = (xy[3] - fr->p1[1]) / fr->d;
    r[2] = wrap_pi(th[0] - fr->psi0);
    r[3] = wrap_pi(th[1] - fr->psi1);
    r[4] = mode == EL_HERMITE_TENSION
               ? (2.0 * p->mu * (2.0 * p->k * p->k - 1.0) - target) * fr->d * fr->d / (1.0 + fabs(target) * fr->d * fr->d)
               : (p->length - target) / fr->d;
    return EL_OK;
}

/* Newton on (phi, mu, k, q, length) with a finite-difference Jacobian, for the
 * solutions whose end residual, measured with el_smooth_eval, misses tol by a
 * little (near the separatrix k = 1 the map from kappa0 to the parameters is
 * ill-conditioned). Keeps the result only when the residual improves. */
static void polish(const frame *fr, int mode, double target, el_hermite_solution *s)
{
    el_smooth_params p = s->curve;
    double r[5];
    if (polish_res(fr, &p, mode, target, r)) return;
    for (int it = 0; it < 4; it++) {
        double J[25], *v[5] = {&p.phi, &p.mu, &p.k, &p.q, &p.length};
        for (int j = 0; j < 5; j++) {
            /* k: a step relative to the distance from the separatrix, where gamma
             * varies on the scale |k| - 1 (the period grows like log 1/||k| - 1|) */
            const double v0 = *v[j];
            const double h = j == 2 ? 1e-7 * fmin(fabs(v0) + 1e-3, fmax(fabs(fabs(v0) - 1.0), 1e-9))
                                    : 1e-7 * (fabs(v0) + (j == 1 ? p.mu : 1e-3));
            double rp[5], rm[5];
            *v[j] = v0 + h;
            int e1 = polish_res(fr, &p, mode, target, rp);
            *v[j] = v0 - h;
            int e2 = polish_res(fr, &p, mode, target, rm);
            *v[j] = v0;
            if (e1 || e2) return;
            for (int i = 0; i < 5; i++) J[i * 5 + j] = (rp[i] - rm[i]) / (2.0 * h);
        }
        /* J dv = -r by LU with partial pivoting (GSL) */
        double rhs[5], dv[5];
        for (int i = 0; i < 5; i++) rhs[i] = -r[i];
        gsl_matrix_view Jm = gsl_matrix_view_array(J, 5, 5);
        gsl_vector_view bv = gsl_vector_view_array(rhs, 5), xv = gsl_vector_view_array(dv, 5);
        gsl_permutation perm_s;
        size_t perm_data[5];
        perm_s.size = 5;
        perm_s.data = perm_data;
        int signum;
        if (gsl_linalg_LU_decomp(&Jm.matrix, &perm_s, &signum) != GSL_SUCCESS ||
            gsl_linalg_LU_solve(&Jm.matrix, &perm_s, &bv.vector, &xv.vector) != GSL_SUCCESS)
            return;
        for (int i = 0; i < 5; i++) if (!isfinite(dv[i])) return;
        el_smooth_params q = p;
        q.phi += dv[0]; q.mu += dv[1]; q.k += dv[2]; q.q += dv[3];
        if (mode == EL_HERMITE_TENSION) q.length += dv[4]; /* length mode: L stays exact */
        double rq[5];
        if (el_smooth_check(&q) || polish_res(fr, &q, mode, target, rq)) return;
        double n0 = 0.0, n1 = 0.0;
        for (int i = 0; i < 4; i++) { n0 = fmax(n0, fabs(r[i])); n1 = fmax(n1, fabs(rq[i])); }
        if (!(n1 < n0)) break;
        p = q;
        memcpy(r, rq, sizeof r);
    }
    el_hermite_solution t = *s;
    t.curve = p;
    t.length = p.length;
    double res;
    if (residual(fr, &t, &res) || !(res < s->residual)) return;
    t.residual = res;
    if (mode == EL_HERMITE_LENGTH) t.sigma = 2.0 * p.mu * (2.0 * p.k * p.k - 1.0);
    if (el_smooth_energy(&p, &t.energy)) return;
    *s = t;
}

/* Second polish for the solutions the first one leaves above tol: near the
 * separatrix |dgamma(L)/dk| is 1e6..1e8 at fixed (phi, mu, q, L) (sigma
 * |p1-p0|^2 > ~100), so the ulp of the stored k alone moves the end by 1e-10..1e-8,
 * whatever the accuracy of el_smooth_eval (~1e-13 there, checked against a
 * 40-digit evaluation). The rounding of k is compensated by the other
 * parameters: for each k among the nearest few doubles, with the mode's
 * condition kept exact (tension: mu = sigma / (2 (2k^2 - 1)); length: L fixed),
 * Gauss-Newton on the remaining three parameters (tension: phi, q, L; length:
 * phi, mu, q) fits the four end conditions in least squares (GSL QR); the best
 * curve is kept if it improves the residual. */
static void polish_fixed_k(const frame *fr, int mode, double target, el_hermite_solution *s)
{
    el_smooth_params best = s->curve;
    double best_res = s->residual;
    for (int j = -4; j <= 4; j++) {
        el_smooth_params p = s->curve;
        for (int i = 0; i < abs(j); i++) p.k = nextafter(p.k, j > 0 ? INFINITY : -INFINITY);
        if (mode == EL_HERMITE_TENSION) p.mu = target / (2.0 * (2.0 * p.k * p.k - 1.0));
        if (el_smooth_check(&p)) continue;
        double *v[3] = {&p.phi, &p.q, mode == EL_HERMITE_TENSION ? &p.length : &p.mu};
        double r[5];
        if (polish_res(fr, &p, mode, target, r)) continue;
        for (int it = 0; it < 4; it++) {
            double J[12], rhs[4], dv[3], tau[3], lsr[4];
            int bad = 0;
            for (int c = 0; c < 3 && !bad; c++) {
                const double v0 = *v[c], h = 1e-7 * (fabs(v0) + (c == 2 ? fabs(v0) : 1e-3));
                double rp[5], rm[5];
                *v[c] = v0 + h;
                bad |= el_smooth_check(&p) || polish_res(fr, &p, mode, target, rp);
                *v[c] = v0 - h;
                bad |= el_smooth_check(&p) || polish_res(fr, &p, mode, target, rm);
                *v[c] = v0;
                for (int i = 0; i < 4; i++) J[i * 3 + c] = (rp[i] - rm[i]) / (2.0 * h);
            }
            if (bad) break;
            for (int i = 0; i < 4; i++) rhs[i] = -r[i];
            gsl_matrix_view Jm = gsl_matrix_view_array(J, 4, 3);
            gsl_vector_view bv = gsl_vector_view_array(rhs, 4), xv = gsl_vector_view_array(dv, 3);
            gsl_vector_view tv = gsl_vector_view_array(tau, 3), rv = gsl_vector_view_array(lsr, 4);
            if (gsl_linalg_QR_decomp(&Jm.matrix, &tv.vector) != GSL_SUCCESS ||
                gsl_linalg_QR_lssolve(&Jm.matrix, &tv.vector, &bv.vector, &xv.vector, &rv.vector) != GSL_SUCCESS)
                break;
            el_smooth_params q = p;
            double *w[3] = {&q.phi, &q.q, mode == EL_HERMITE_TENSION ? &q.length : &q.mu};
            for (int c = 0; c < 3; c++) *w[c] += isfinite(dv[c]) ? dv[c] : NAN;
            double rq[5];
            if (el_smooth_check(&q) || polish_res(fr, &q, mode, target, rq)) break;
            double n0 = 0.0, n1 = 0.0;
            for (int i = 0; i < 4; i++) { n0 = fmax(n0, fabs(r[i])); n1 = fmax(n1, fabs(rq[i])); }
            if (!(n1 < n0)) break;
            p = q;
            memcpy(r, rq, sizeof r);
        }
        el_hermite_solution t = *s;
        t.curve = p;
        double res;
        if (residual(fr, &t, &res) || !(res < best_res)) continue;
        best = p;
        best_res = res;
    }
    if (!(best_res < s->residual)) return;
    el_hermite_solution t = *s;
    t.curve = best;
    t.length = best.length;
    t.residual = best_res;
    if (mode == EL_HERMITE_LENGTH) t.sigma = 2.0 * best.mu * (2.0 * best.k * best.k - 1.0);
    if (el_smooth_energy(&best, &t.energy)) return;
    *s = t;
}

static int make_solution(const frame *fr, const hroot *r, el_hermite_solution *s)
{
    const hstate *st = &r->st;
    const double d = fr->d;
    memset(s, 0, sizeof *s);
    s->length = st->L * d;
    s->sigma = r->sigma / (d * d);
    s->energy = st->E / d;
    s->kappa0 = st->k0 / d;
    s->kappa1 = st->k1 / d;
    s->has_inflection = 0;
    if (st->infl) {
        /* kappa = kappa_m cn(u): a zero inside iff the amplitude passes an odd multiple of pi/2 */
        const double sF = sqrt(2.0 * st->Fn), s0 = r->sigma;
        const double al0 = atan2(sF * sin(0.5 * atan2(-2.0 * st->k0p, st->k0 * st->k0 - s0)), st->k0);
        const double al1 = al0 + wrap_pos(atan2(sF * sin(0.5 * atan2(-2.0 * st->k1p, st->k1 * st->k1 - s0)),
                                                st->k1) - al0, 2.0 * M_PI);
        /* zeros of cn strictly inside: integers n with a < n < b (a zero at an end is no inflection) */
        const double a = (al0 - M_PI_2) / M_PI + 1e-9, b = (al1 - M_PI_2) / M_PI - 1e-9;
        s->has_inflection = ceil(b) - floor(a) - 1.0 > 0.5;
        /* a whole period (end state = start state: the amplitudes above tie, and their
         * rounding may disagree with the one in shape_eval that gave L = T) has two
         * zeros of kappa, at least one of them strictly inside */
        if (st->L >= st->T * (1.0 - 1e-9)) s->has_inflection = 1;
    }
    return params_from_state(fr->p0[0], fr->p0[1], fr->psi0, st->k0 / d, st->k0p / (d * d),
                             s->sigma, s->length, &s->curve);
}

static int straight_solution(const frame *fr, double sigma, el_hermite_solution *s)
{
    memset(s, 0, sizeof *s);
    s->curve.x0 = fr->p0[0];
    s->curve.y0 = fr->p0[1];
    s->curve.phi = fr->psi0;
    s->curve.mu = 1.0 / (fr->d * fr->d);
    s->curve.k = 0.0;
    s->curve.q = 0.0;
    s->curve.length = s->length = fr->d;
    s->sigma = sigma;
    return EL_OK;
}

/* The circular arc from (p0, t0) through p1, if it ends with tangent t1: curvature
 * c = 2 det(t0, P) / |P|^2 (P = p1 - p0), turning angle 2 beta (beta: from t0 to P).
 * A circle is an elastica for sigma = c^2 (kappa_m^2 = sigma, F = 0), where the
 * objective (35) is singular (Theorem 8 excludes it), so it is checked apart. The
 * parametrisation reaches it only as k -> infinity (k^2 mu fixed): k = 1e4 is used,
 * with kappa = 2 k sqrt(mu) dn(k u; 1/k) constant to 1/(2 k^2) = 5e-9 relative, and
 * el_smooth_eval's closed form loses about eps k^2 to cancellation, so the arc
 * meets the ends only to ~1e-8: it is returned when that is within opt->tol. */
static int circle_arc(const frame *fr, const double u0[2], const double u1[2],
                      double *c, double *L)
{
    const double P[2] = {fr->p1[0] - fr->p0[0], fr->p1[1] - fr->p0[1]};
    const double beta = atan2(u0[0] * P[1] - u0[1] * P[0], u0[0] * P[0] + u0[1] * P[1]);
    if (fabs(beta) < 1e-8) return 0;                       /* straight, handled apart */
    if (angle_err(fr->psi0 + 2.0 * beta, atan2(u1[1], u1[0])) > 1e-12) return 0;
    *c = 2.0 * sin(beta) / fr->d;
    *L = 2.0 * beta / *c;
    return 1;
}

static int circle_solution(const frame *fr, double c, double L, el_hermite_solution *s)
{
    const double k = 1e4;
    memset(s, 0, sizeof *s);
    s->curve.x0 = fr->p0[0];
    s->curve.y0 = fr->p0[1];
    s->curve.phi = fr->psi0;
    s->curve.k = c < 0.0 ? -k : k;              /* clockwise: kappa = 2 k sqrt(mu) dn < 0 */
    s->curve.mu = c * c / (4.0 * k * k);
    s->curve.q = 0.0;
    s->curve.length = s->length = L;
    s->sigma = c * c;
    s->energy = c * c * L;
    s->kappa0 = s->kappa1 = c;
    return EL_OK;
}

static int cmp_energy(const void *a, const void *b)
{
    const el_hermite_solution *x = a, *y = b;
    return (x->energy > y->energy) - (x->energy < y->energy);
}

static int same_solution(const el_hermite_solution *a, const el_hermite_solution *b, double d)
{
    const double tk = 1e-6 / d;
    return fabs(a->length - b->length) <= 1e-7 * (a->length + b->length) &&
           fabs(a->kappa0 - b->kappa0) <= tk * (1.0 + fabs(a->kappa0) * d) &&
           fabs(a->kappa1 - b->kappa1) <= tk * (1.0 + fabs(a->kappa1) * d) &&
           fabs(a->sigma - b->sigma) * d * d <= 1e-6 * (1.0 + fabs(a->sigma) * d * d);
}

void el_hermite_options_defaults(el_hermite_options *opt)
{
    if (!opt) return;
    opt->mode = EL_HERMITE_TENSION;
    opt->sigma = 0.0;
    opt->length = 0.0;
    opt->tol = 1e-10;
    opt->samples = 16;
    opt->grid = 72;
    opt->max_solutions = 64;
}

void el_hermite_result_free(el_hermite_result *res)
{
    if (!res) return;
    free(res->solutions);
    res->solutions = NULL;
    res->count = 0;
}

static int unit(const double t[2], double u[2])
{
    const double n = hypot(t[0], t[1]);
    if (!(n > 0.0) || !isfinite(n)) return EL_EINVAL;
    u[0] = t[0] / n;
    u[1] = t[1] / n;
    return EL_OK;
}

int el_hermite_solve(const double p0[2], const double t0[2], const double p1[2],
                     const double t1[2], const el_hermite_options *opt,
                     el_hermite_result *res)
{
    if (!p0 || !t0 || !p1 || !t1 || !opt || !res) return EL_EINVAL;
    const double all[8] = {p0[0], p0[1], t0[0], t0[1], p1[0], p1[1], t1[0], t1[1]};
    double u0[2], u1[2];
    if (el__all_finite(all, 8) || unit(t0, u0) || unit(t1, u1)) return EL_EINVAL;
    if (opt->mode != EL_HERMITE_TENSION && opt->mode != EL_HERMITE_LENGTH) return EL_EINVAL;
    if (!isfinite(opt->sigma) || !isfinite(opt->length) || !(opt->tol > 0.0) ||
        opt->samples < 4 || opt->samples > 1000 || opt->grid < 8 || opt->grid > 2000 ||
        opt->max_solutions == 0)
        return EL_EINVAL;
    if (opt->mode == EL_HERMITE_LENGTH && !(opt->length > 0.0)) return EL_EINVAL;
    el__gsl_quiet();
    res->count = 0;
    res->solutions = NULL;

    /* normalisation (seed 004 §4): p0 = 0, t0 = (0, 1), |p1 - p0| = 1, sigma d^2 */
    frame fr;
    memcpy(fr.p0, p0, sizeof fr.p0);
    memcpy(fr.p1, p1, sizeof fr.p1);
    fr.psi0 = atan2(u0[1], u0[0]);
    fr.psi1 = atan2(u1[1], u1[0]);
    fr.d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    fr.rot = fr.psi0 - M_PI_2;
    if (!(fr.d > 1e-300)) return EL_EDOM;
    const double cr = cos(fr.rot), sr = sin(fr.rot);
    const double dx = (p1[0] - p0[0]) / fr.d, dy = (p1[1] - p0[1]) / fr.d;
    hprob pr;
    pr.P1 = cr * dx + sr * dy;
    pr.P2 = -sr * dx + cr * dy;
    pr.V1 = cr * u1[0] + sr * u1[1];
    pr.V2 = -sr * u1[0] + cr * u1[1];
    set_case(&pr);
    const int collinear = fabs(pr.P1) < 1e-13 && pr.P2 > 0.0 && fabs(pr.V1) < 1e-13 && pr.V2 > 0.0;

    hrootlist roots = {NULL, 0, 0};
    int rc;
    double Ln = 0.0;
    if (opt->mode == EL_HERMITE_TENSION) {
        pr.sigma = opt->sigma * fr.d * fr.d;
        pr.Lmin = 1.0;
        rc = solve_tension_normalised(&pr, opt->samples, &roots);
    } else {
        Ln = opt->length / fr.d;
        if (Ln < 1.0 - 1e-12) return EL_EDOM;
        pr.sigma = 0.0;
        pr.Lmin = Ln;
        rc = Ln > 1.0 + 1e-12 ? solve_length_normalised(&pr, Ln, opt->grid, opt->samples, &roots) : EL_OK;
    }
    if (rc) { free(roots.v); return rc; }

    size_t cap = roots.n + 2;
    el_hermite_solution *sol = malloc(cap * sizeof *sol);
    if (!sol) { free(roots.v); return EL_ENOMEM; }
    size_t n = 0;
    if (collinear && (opt->mode == EL_HERMITE_TENSION || Ln <= 1.0 + 1e-12)) {
        straight_solution(&fr, opt->mode == EL_HERMITE_TENSION ? opt->sigma : 0.0, &sol[n]);
        if (!residual(&fr, &sol[n], &sol[n].residual)) n++;
    }
    double cc, cL;
    if (circle_arc(&fr, u0, u1, &cc, &cL) &&
        (opt->mode == EL_HERMITE_TENSION ? fabs(opt->sigma - cc * cc) <= 1e-12 * cc * cc
                                         : fabs(opt->length - cL) <= 1e-12 * cL)) {
        circle_solution(&fr, cc, cL, &sol[n]);
        if (!residual(&fr, &sol[n], &sol[n].residual) && sol[n].residual <= opt->tol) n++;
    }
    for (size_t i = 0; i < roots.n; i++) {
        el_hermite_solution s;
        if (make_solution(&fr, &roots.v[i], &s)) continue;
        /* the mode's given value is exact, not the root finder's approximation of it */
        if (opt->mode == EL_HERMITE_TENSION) s.sigma = opt->sigma;
        else s.length = s.curve.length = opt->length;
        if (residual(&fr, &s, &s.residual)) continue;
        if (s.residual > opt->tol && s.residual < 1e-5) {
            const double target = opt->mode == EL_HERMITE_TENSION ? opt->sigma : opt->length;
            polish(&fr, opt->mode, target, &s);
            if (s.residual > opt->tol) polish_fixed_k(&fr, opt->mode, target, &s);
        }
        if (!(s.residual <= opt->tol)) continue;
        int dup = 0;
        for (size_t j = 0; j < n && !dup; j++) {
            if (same_solution(&s, &sol[j], fr.d)) {
                dup = 1;
                if (s.residual < sol[j].residual) sol[j] = s;
            }
        }
        if (!dup) sol[n++] = s;
    }
    free(roots.v);
    qsort(sol, n, sizeof *sol, cmp_energy);
    if (n > opt->max_solutions) n = opt->max_solutions;
    if (n == 0) { free(sol); sol = NULL; }
    res->count = n;
    res->solutions = sol;
    return EL_OK;
}

int el_hermite_analyse(const double P[2], const double V[2], double sigma,
                       el_hermite_analysis *a)
{
    if (!P || !V || !a) return EL_EINVAL;
    const double v[5] = {P[0], P[1], V[0], V[1], sigma};
    if (el__all_finite(v, 5) || fabs(hypot(P[0], P[1]) - 1.0) > 1e-9 ||
        fabs(hypot(V[0], V[1]) - 1.0) > 1e-9)
        return EL_EINVAL;
    el__gsl_quiet();
    hprob pr = {P[0], P[1], V[0], V[1], sigma, 0, 1.0, 0.0};
    set_case(&pr);
    int rc = kappa_bound(sigma, 1.0, &pr.B);
    if (rc) return rc;
    el_hermite_analysis out;
    memset(&out, 0, sizeof out);
    out.hcase = pr.hcase;
    out.kappa_bound = pr.B;
    if (pr.B < 0.0) { *a = out; return EL_OK; }
    double lo = -pr.B, hi = pr.B;
    if (pr.hcase == 1) {
        double c[3], r[2];
        int nr;
        disc_coeffs(&pr, c);
        if ((rc = poly_real_roots(c, 2, r, &nr))) return rc;
        /* pieces of [lo, hi] where disc >= 0 */
        double pts[4] = {lo, hi, 0, 0};
        int np = 2;
        for (int i = 0; i < nr; i++) if (r[i] > lo && r[i] < hi) pts[np++] = r[i];
        qsort(pts, (size_t)np, sizeof *pts, cmp_double);
        for (int i = 0; i + 1 < np; i++) {
            const double m = 0.5 * (pts[i] + pts[i + 1]);
            if (c[2] * m * m + c[1] * m + c[0] < 0.0) continue;
            if (out.ninterval > 0 && out.interval[2 * out.ninterval - 1] == pts[i])
                out.interval[2 * out.ninterval - 1] = pts[i + 1];
            else if (out.ninterval < 2) {
                out.interval[2 * out.ninterval] = pts[i];
                out.interval[2 * out.ninterval + 1] = pts[i + 1];
                out.ninterval++;
            }
        }
    } else if (pr.hcase == 2) {
        out.ninterval = 1;
        out.interval[0] = lo;
        out.interval[1] = hi;
    }
    if (pr.hcase != 3) {
        double r[8];
        int nr;
        const poly p = poly40(&pr);
        if ((rc = poly_real_roots(p.c, p.d, r, &nr))) return rc;
        qsort(r, (size_t)nr, sizeof *r, cmp_double);
        for (int i = 0; i < nr && out.nroot < 8; i++) {
            int inside = 0;
            for (size_t j = 0; j < out.ninterval; j++)
                inside |= r[i] >= out.interval[2 * j] && r[i] <= out.interval[2 * j + 1];
            if (!inside) continue;
            const int best = root_branch(&pr, r[i]);
            out.root[out.nroot] = r[i];
            out.root_branch[out.nroot++] = best;
        }
        int ns;
        if ((rc = special_values(&pr, out.special, &ns))) return rc;
        out.nspecial = (size_t)ns;
        qsort(out.special, out.nspecial, sizeof(double), cmp_double);
    }
    *a = out;
    return EL_OK;
}
