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
#include <stdlib.h>
#include <string.h>

/* 4 sqrt(2) K(1/sqrt 2): the period times kappa_m of the sigma = 0 elastica. */
#define C0_PERIOD 10.4882572784299
#define MAXPTS 64
/* el__carlson_fd's precision for the bracketing samples: ~1e-8 relative (ellint.c) */
#define COARSE_QS 0.1

/* ------------------------------------------------------------ elliptic helpers */

/* F(mu, k) and D(mu, k) = int_0^mu sin^2 t / sqrt(1 - k^2 sin^2 t) dt for an amplitude
 * mu in [0, 2 pi] given by S = sin mu, C = cos mu and big = (mu > pi) (which S and C
 * leave open at S = 0), k^2 and kc2 = 1 - k^2 formed without cancellation by the
 * caller (k < 1, or k = 1 with mu < pi/2). The argument U = F(mu) is halved, at most
 * twice, until its amplitude is at most pi/2, by the half-argument formulas
 * (DLMF 22.6.19)
 *   sn^2(U/2) = (1 - cn U) / (1 + dn U),  cn^2(U/2) = (dn U + cn U) / (1 + dn U),
 * in the forms without cancellation 1 - cn = sn^2 / (1 + cn) and
 * dn + cn = k'^2 sn^2 / (dn - cn), with dn^2 = k'^2 + k^2 cn^2, and the doubling
 * D(2v) = 2 D(v) + sn^2 v sn 2v (the addition theorem for D, jacobi.c). Then
 * F = S R_F(C^2, dn^2, 1), D = S^3 R_D(C^2, dn^2, 1) / 3 (DLMF 19.25.5, 19.25.13): no
 * complete integral is needed. */
typedef struct {
    double S, x, y;       /* sine of the reduced amplitude; Carlson's x = cos^2, y = dn^2 */
    double mult, acc;     /* F = mult S R_F(x, y, 1), D = mult S^3 R_D(x, y, 1) / 3 + acc */
} reduced_amp;

static void amp_reduce(double S, double C, int big, double k2, double kc2, reduced_amp *r)
{
    double mult = 1.0, acc = 0.0, x = C * C;
    while (big || C < 0.0 || S < 0.0) {
        /* one division: inv = 1 / ((1 + dn) q), q = 1 + C or dn - C */
        const double dn = sqrt(kc2 + k2 * x), q = C > 0.0 ? 1.0 + C : dn - C;
        const double inv = 1.0 / ((1.0 + dn) * q);
        const double s2 = C > 0.0 ? S * S * inv : (1.0 - C) * q * inv;
        const double c2 = C < 0.0 ? kc2 * S * S * inv : (dn + C) * q * inv;
        acc += mult * s2 * S;
        mult *= 2.0;
        S = sqrt(s2);                          /* sn(U/2) >= 0: U/2 in (0, 2K] */
        x = c2;
        if (!big) break;                       /* U/2 <= K: amplitude at most pi/2 */
        C = -sqrt(c2);                         /* U/2 in (K, 2K]: halve once more */
        big = 0;
    }
    r->S = S;
    r->x = x;
    r->y = kc2 + k2 * x;
    r->mult = mult;
    r->acc = acc;
}

static int amp_fd(const reduced_amp *r, double rf, double rd, double *F, double *D)
{
    *F = r->mult * r->S * rf;
    *D = r->mult * r->S * r->S * r->S * rd / 3.0 + r->acc;
    return (isfinite(*F) && isfinite(*D)) ? EL_OK : EL_EDOM;
}

static int ell_fd_amp(double S, double C, int big, double k2, double kc2, double qs,
                      double *F, double *D)
{
    reduced_amp r;
    double rf, rd;
    amp_reduce(S, C, big, k2, kc2, &r);
    const int rc = el__carlson_fd(r.x, r.y, 1.0, qs, &rf, &rd);
    return rc ? rc : amp_fd(&r, rf, rd, F, D);
}

/* The amplitude mu = am(u1 - u0) of a difference of arguments by the addition
 * theorems (DLMF 22.8.1-3), from the amplitudes a0, a1 of u0, u1 (sines s, cosines c,
 * delta amplitudes d = sqrt(1 - k^2 s^2)), den = 1 - k^2 s0^2 s1^2 = d0^2 + k^2 s0^2 c1^2
 * (the sum has no cancellation):
 *   sin mu = (s1 c0 d0 - s0 c1 d1) / den,  cos mu = (c1 c0 + s1 s0 d1 d0) / den.
 * Then F(a1) - F(a0) = F(mu) and, by the addition theorem for E (DLMF 19.11.2)
 * with D = (F - E)/k^2, D(a1) - D(a0) = D(mu) + s1 s0 sin mu: one incomplete
 * integral per difference instead of two, and no cancellation between them. */
static void amplitude_difference(double k2, double s0, double c0, double d0, double s1,
                                 double c1, double d1, double *smu, double *cmu)
{
    const double iden = 1.0 / (d0 * d0 + k2 * s0 * s0 * c1 * c1);
    *smu = (s1 * c0 * d0 - s0 * c1 * d1) * iden;
    *cmu = (c1 * c0 + s1 * s0 * d1 * d0) * iden;
}

/* sin and cos of h = atan2(S, C) / 2 in (-pi/2, pi/2], iR = 1 / hypot(S, C), by the
 * half-angle formulas (no atan2, sin, cos in the objective's inner loop; sqrt and
 * division are what it costs, so each is used once). */
static void half_angle(double S, double C, double iR, double *sh, double *ch)
{
    if (C >= 0.0) {
        *ch = sqrt(0.5 * (1.0 + C * iR));
        *sh = 0.5 * S * iR / *ch;
    } else {
        *sh = (S >= 0.0 ? 1.0 : -1.0) * sqrt(0.5 * (1.0 - C * iR));
        *ch = 0.5 * S * iR / *sh;
    }
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
    int infl;                  /* inflectional (k < 1) */
    double s0, c0, s1, c1;     /* inflectional: sn, cn of u at both ends */
    int big;                   /* inflectional: u(L) - u(0) exceeds half a period (2 Kc) */
    double L, E;               /* length, energy */
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

/* The kind of curve a curvature state starts (Theorem 7), |F| into *Fn.
 * CLASS_NONE: none the objective covers: F = 0 (the circle kappa_m^2 = sigma,
 * singular, (45)), kappa_m = 0 (straight, handled apart), or non-inflectional with
 * kappa0 kappa1 <= 0 against (44); CLASS_MIXED: see piece_class. */
enum { CLASS_NONE, CLASS_INFL, CLASS_NONINFL, CLASS_MIXED };

static int state_class(const hprob *pr, const hstate *st, double *Fn)
{
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s;
    /* sqrt rather than hypot (inner loop; the values are far from overflow) */
    *Fn = sqrt(F1 * F1 + F2 * F2);
    if (!(*Fn > 1e-13 * (1.0 + fabs(s))) || !(*Fn + s > 0.0)) return CLASS_NONE;
    if (*Fn > s) return CLASS_INFL;            /* k < 1: k'^2 = (|F| - sigma) / (2 |F|) > 0 */
    return st->k0 * st->k1 > 0.0 ? CLASS_NONINFL : CLASS_NONE;
}

/* What shape_finish needs besides the two Carlson integrals of the reduced amplitude:
 * L = Lscale F, E = Escale (F - Dfac (D + prod)), f = (E - sigma L - FP) iFn. */
typedef struct {
    reduced_amp ra;
    double Lscale, Escale, Dfac, prod, FP, iFn;
} shapework;

/* Theorem 7 and its supplement: the curvature function through (kappa0, kappa0')
 * reaches (kappa1, kappa1') at a unique L in (0, T]; then length, energy and the
 * objective f, in two halves around the one Carlson R_F/R_D evaluation of the
 * reduced amplitude (shape_eval). */
static int shape_prepare(const hprob *pr, hstate *st, shapework *w)
{
    double Fn;
    const int cls = state_class(pr, st, &Fn);
    if (cls == CLASS_NONE) return EL_EDOM;
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s, km2 = Fn + s;
    /* k^2 = kappa_m^2 / (2 |F|) and its complement, exact up to the one difference
     * |F| - sigma, which is the separatrix distance itself */
    const double i2F = 0.5 / Fn, k2 = km2 * i2F, kc2 = (Fn - s) * i2F, rmu = sqrt(0.5 * Fn);
    /* h = (theta - phi)/2 at both ends: theta - phi = atan2(-2 kappa', kappa^2 - sigma) */
    const double S1 = -2.0 * st->k1p, C1 = st->k1 * st->k1 - s;
    double sh0, ch0, sh1, ch1, smu, cmu;
    half_angle(F1, F2, 2.0 * i2F, &sh0, &ch0);
    half_angle(S1, C1, 1.0 / sqrt(S1 * S1 + C1 * C1), &sh1, &ch1);
    if (cls == CLASS_INFL) {
        /* amplitude a of u: sin a = sn u = sin h / k, cos a = cn u = kappa / kappa_m,
         * delta amplitude dn u = cos h. L in (0, T] is u1 - u0 in (0, 4 Kc], whose
         * amplitude mu is in (0, 2 pi]; sin mu = 0 with cos mu > 0 is a whole period
         * (the end state repeats the start) */
        const double ikm = 1.0 / sqrt(km2), ik = 2.0 * rmu * ikm;   /* 1/k = sqrt(2 |F|) / kappa_m */
        const double s0 = sh0 * ik, c0 = st->k0 * ikm, s1 = sh1 * ik, c1 = st->k1 * ikm;
        amplitude_difference(k2, s0, c0, ch0, s1, c1, ch1, &smu, &cmu);
        const int big = smu < 0.0 || (smu == 0.0 && cmu > 0.0);
        amp_reduce(smu, cmu, big, k2, kc2, &w->ra);
        st->s0 = s0;        /* for make_solution's inflection count */
        st->c0 = c0;
        st->s1 = s1;
        st->c1 = c1;
        st->big = big;
        /* F = u(L) - u(0), D + prod = int_u0^u1 sn^2, int cn^2 du = u - int sn^2 du */
        const double irmu = 1.0 / rmu;
        w->Lscale = irmu;
        w->Escale = km2 * irmu;
        w->Dfac = 1.0;
        w->prod = s1 * s0 * smu;
    } else {
        /* non-inflectional: kappa keeps its sign, Theorem 7 (ii) needs kappa0 kappa1 > 0 (44);
         * amplitude b of v = k u for the modulus m = 1/k: sin b = eps sin h, cos b = cos h,
         * delta amplitude |kappa| / kappa_m (eps = sign of kappa mirrors the curve). L in
         * (0, T] is v1 - v0 in (0, 2 Kc], amplitude mu in (0, pi]: (sin, cos) of mu are
         * known up to a common sign (b is defined mod pi), fixed by sin mu >= 0; sin mu = 0
         * is a whole period (the end state repeats the start) */
        const double eps = st->k0 > 0.0 ? 1.0 : -1.0, km = sqrt(km2);
        const double m2 = 2.0 * Fn / km2, mc2 = (s - Fn) / km2;
        const double b0 = eps * sh0, b1 = eps * sh1;
        amplitude_difference(m2, b0, ch0, fabs(st->k0) / km, b1, ch1, fabs(st->k1) / km, &smu, &cmu);
        /* the product b1 b0 sin mu is the same for either sign choice */
        w->prod = b1 * b0 * smu;
        if (smu < 0.0 || (smu == 0.0 && cmu > 0.0)) { smu = -smu; cmu = -cmu; }
        amp_reduce(smu, cmu, 0, m2, mc2, &w->ra);
        /* F = v(L) - v(0), dv/ds = k sqrt(mu); int dn^2 dv = F - m^2 D */
        const double iw = 1.0 / (sqrt(k2) * rmu);
        w->Lscale = iw;
        w->Escale = km2 * iw;
        w->Dfac = m2;
    }
    st->infl = cls == CLASS_INFL;
    w->FP = F1 * pr->P1 + F2 * pr->P2;
    w->iFn = 2.0 * i2F;
    return EL_OK;
}

static int shape_finish(const hprob *pr, const shapework *w, double rf, double rd, hstate *st)
{
    double F, D;
    const int rc = amp_fd(&w->ra, rf, rd, &F, &D);
    if (rc) return rc;
    st->L = w->Lscale * F;
    st->E = w->Escale * (F - w->Dfac * (D + w->prod));
    st->f = (st->E - pr->sigma * st->L - w->FP) * w->iFn;   /* (12) along F */
    return isfinite(st->f) && st->L > 0.0 ? EL_OK : EL_EDOM;
}

static int shape_eval(const hprob *pr, double qs, hstate *st)
{
    shapework w;
    double rf, rd;
    int rc = shape_prepare(pr, st, &w);
    if (!rc) rc = el__carlson_fd(w.ra.x, w.ra.y, 1.0, qs, &rf, &rd);
    return rc ? rc : shape_finish(pr, &w, rf, rd, st);
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
    /* the AGM with k'^2 = (|F| - sigma) / (2 |F|): cheaper than GSL's Kcomp */
    if (el__ellint_complete(k, (Fn - sigma) / (2.0 * Fn), &K, &D)) return NAN;
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
        if (gsl_root_test_interval(a, b, 0.0, 1e-3) == GSL_SUCCESS) break;
    }
    /* the bracket's upper end has T < Lmin: a bound whatever the bracket's width */
    *B = gsl_root_fsolver_x_upper(s) * (1.0 + 1e-9);
    gsl_root_fsolver_free(s);
    return EL_OK;
}

/* ------------------------------------------------------------ split points */

/* A split point; soft: kappa0 = 0 or kappa1 = 0, which bound the pieces where (44)
 * fails but leave the objective smooth on the inflectional side (seed 004 §4
 * intersects only the non-inflectional pieces with (44)). */
typedef struct { double x; int soft; } splitpt;
typedef struct { splitpt v[MAXPTS]; int n; } ptlist;

static void pt_add(ptlist *l, double x, int soft)
{
    if (isfinite(x) && l->n < MAXPTS) {
        l->v[l->n].x = x;
        l->v[l->n++].soft = soft;
    }
}

/* Sort by x: insertion sort, the lists being a dozen points long (qsort's
 * indirect comparisons and merge buffer cost more than the sort itself here). */
static void sort_splitpts(splitpt *v, int n)
{
    for (int i = 1; i < n; i++) {
        const splitpt t = v[i];
        int j = i;
        for (; j > 0 && v[j - 1].x > t.x; j--) v[j] = v[j - 1];
        v[j] = t;
    }
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
        const double dd = fabs(sqrt(F1 * F1 + F2 * F2) - pr->sigma);   /* kappa_m^2 - 2 sigma */
        if (dd < bd) { bd = dd; best = b; }
    }
    return best;
}


/* The kind of curve at x (state_class; cheap, the curvature data only); CLASS_NONE
 * also outside (18). */
static int point_class(const hprob *pr, int b, double x)
{
    hstate st;
    double Fn;
    return curvdata(pr, x, b, &st) ? CLASS_NONE : state_class(pr, &st, &Fn);
}

/* Split points of branch b: (18) ends, (40) roots, (44) kappa0 = 0 and kappa1 = 0,
 * (45) special values; case 3: (41), kappa0' = 0. */
static int split_points(const hprob *pr, int b, double X, const double *r40, const int *b40,
                        int n40, ptlist *l)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    double r[16];
    int nr, rc;
    l->n = 0;
    if (pr->hcase == 3) {
        const double k0 = case3_kappa0(pr, b), c = k0 * k0 - s, q = s * s - c * c;
        pt_add(l, 0.0, 0);
        if (q >= 0.0) { pt_add(l, 0.5 * sqrt(q), 0); pt_add(l, -0.5 * sqrt(q), 0); } /* (41) */
        return EL_OK;
    }
    if (pr->hcase == 1) {
        double a[3];
        disc_coeffs(pr, a);
        if ((rc = poly_real_roots(a, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 0);
        /* kappa1 = 0 in (17): 2 V1 C + A P2 = 0 */
        const double q[3] = {V1 * P1 * s + P2 * V2 * s - P2 * s, -2.0 * V1, -V1 * P1 - P2 * V2};
        if ((rc = poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 1);
    } else {
        const double q[3] = {-0.5 * P1 * s, 1.0, 0.5 * P1}; /* C = 0 */
        if ((rc = poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 1);
    }
    pt_add(l, 0.0, 1);
    for (int i = 0; i < n40; i++)
        if (b40[i] == b) pt_add(l, r40[i], 0);
    /* (45): seed 004 §4 evaluates its objective (35), x1(L) - P1, there and keeps the
     * value as a split point where it vanishes (an unwanted zero) or is singular. The
     * objective here is the error along F, regular where F is parallel to x1; it
     * vanished at none of the special values of the 10 000 bench problems (31 000
     * evaluated). So only the singular ones split: F = 0 (the circle kappa0^2 = sigma,
     * kappa0' = 0 on this branch) and those without a curve (point_class) */
    if ((rc = special_values(pr, r, &nr))) return rc;
    for (int i = 0; i < nr; i++)
        if (fabs(r[i]) < X && point_class(pr, b, r[i]) == CLASS_NONE) pt_add(l, r[i], 0);
    return EL_OK;
}

/* ------------------------------------------------------------ root finding on the pieces */

/* The objective of one branch with a small cache of the last evaluations: GSL's
 * Brent re-evaluates the bracket ends (already sampled) in gsl_root_fsolver_set,
 * and the root it returns is its last evaluation, whose state the solution needs. */
#define NCACHE 4
typedef struct {
    const hprob *pr;
    int b;
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
 * about 1e-8 instead of 1e-16 (COARSE_QS, one or two duplication steps fewer); its
 * sign and rough size are used, and Brent and every accepted root use full_eval. */
static double fobj_coarse(fctx *c, double x)
{
    hstate st;
    int rc = curvdata(c->pr, x, c->b, &st);
    if (!rc) rc = shape_eval(c->pr, COARSE_QS, &st);
    if (rc) return GSL_NAN;
    return st.f;
}

static double fobj(double x, void *p)
{
    fctx *c = p;
    hstate st;
    if (cached_eval(c, x, 0, &st)) return GSL_NAN;
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

/* The coarse objective, signed for a minimiser (only its sign at the minimum matters). */
static double negf(double x, void *p) { return -fobj_coarse(p, x); }
static double posf(double x, void *p) { return fobj_coarse(p, x); }

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
                const double fxm = fobj_coarse(c, xm);
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

/* The lowest value a convex function g = sign * f can take on [xs[j], xs[j+1]] given
 * the samples: the secant of a neighbouring interval where g > 0 at both ends,
 * extended, lies below a convex function (+inf when no neighbour qualifies). */
static double convex_lower_bound(const double *xs, const double *fs, int n, int j, double sign)
{
    double lb = -INFINITY;
    int any = 0;
    for (int side = -1; side <= 1; side += 2) {
        const int p = side < 0 ? j - 1 : j + 1, q = p + 1;   /* the neighbour [xs[p], xs[q]] */
        if (p < 0 || q >= n || !(sign * fs[p] > 0.0) || !(sign * fs[q] > 0.0)) continue;
        const double slope = sign * (fs[q] - fs[p]) / (xs[q] - xs[p]);
        const double g0 = sign * fs[p] + slope * (xs[j] - xs[p]);
        const double g1 = sign * fs[p] + slope * (xs[j + 1] - xs[p]);
        lb = fmax(lb, fmin(g0, g1));
        any = 1;
    }
    return any ? lb : INFINITY;
}

/* The interval to sample next, or -1. Seed 004 §5 observes that the objective
 * is convex between two zeros close together; so two zeros can only hide in an
 * interval without a sign change where the convex lower bound from its
 * neighbours reaches zero, and the lowest such interval is bisected. An interval
 * with one failed evaluation (no curve there, or a singular point) is bisected
 * first while wider than nanw: the objective is steep next to such a region and
 * zeros crowd there; then it is bounded like the others from its finite side.
 * Intervals narrower than minw are left. */
static int interval_to_refine(const double *xs, const double *fs, int n, double minw, double nanw)
{
    int best = -1;
    double blb = 0.0;
    for (int j = 0; j + 1 < n; j++) {
        const double fa = fs[j], fb = fs[j + 1];
        double sign;
        if (isfinite(fa) && isfinite(fb)) {
            if (!(fa * fb > 0.0)) continue;                 /* a sign change: Brent's */
            sign = fa > 0.0 ? 1.0 : -1.0;
        } else if (isfinite(fa) || isfinite(fb)) {
            const double f = isfinite(fa) ? fa : fb;
            if (f == 0.0) continue;
            sign = f > 0.0 ? 1.0 : -1.0;
            if (xs[j + 1] - xs[j] > nanw) return j;
        } else {
            continue;
        }
        if (!(xs[j + 1] - xs[j] > minw)) continue;
        double lb = convex_lower_bound(xs, fs, n, j, sign);
        /* no same-sign neighbour says anything (next to a sign change, say):
         * one bisection gives the interval a neighbour of its own */
        if (lb == INFINITY && xs[j + 1] - xs[j] > 10.0 * nanw) lb = 0.0;
        if (lb <= blb) { blb = lb; best = j; }
    }
    return best;
}

/* Sample one piece (Chebyshev spacing, ends nudged inside: the split points are
 * where the objective is singular or not differentiable), refine where two zeros
 * may hide (interval_to_refine, at most REFINE_MAX more samples), Brent on sign
 * changes. */
/* A sample whose |f| is below TOUCH_RATIO times both neighbours' (same sign) gets the
 * touch check even when the parabola through the three does not reach zero: the
 * objective is often far from a parabola on a sample interval (steep near a split
 * point). It only adds checks, so it finds a superset; without these checks 9 of
 * the 25 264 solutions of the bench problems (300 samples) are missed, with them 1. */
#define TOUCH_RATIO 0.5
#define REFINE_MAX 12
static int solve_piece(fctx *c, double a, double b, int ns, hrootlist *out)
{
    double xs[1002 + REFINE_MAX], fs[1002 + REFINE_MAX];
    const double eps = 1e-10 * (b - a) + 1e-14 * (fabs(a) + fabs(b));
    int rc;
    if (!(b - a > 4.0 * eps)) return EL_OK;
    /* cos(pi j / ns) by the Chebyshev recurrence c_{j+1} = 2 c_1 c_j - c_{j-1} */
    const double c1 = cos(M_PI / ns);
    double cprev = c1, cj = 1.0;
    for (int j = 0; j <= ns; j++) {
        xs[j] = a + (b - a) * 0.5 * (1.0 - cj);
        if (j == 0) xs[j] = a + eps;
        if (j == ns) xs[j] = b - eps;
        fs[j] = fobj_coarse(c, xs[j]);
        const double cnext = 2.0 * c1 * cj - cprev;
        cprev = cj;
        cj = cnext;
    }
    for (int r = 0; r < REFINE_MAX; r++) {
        const int j = interval_to_refine(xs, fs, ns + 1, 1e-6 * (b - a), 1e-3 * (b - a));
        if (j < 0) break;
        memmove(xs + j + 2, xs + j + 1, (size_t)(ns - j) * sizeof *xs);
        memmove(fs + j + 2, fs + j + 1, (size_t)(ns - j) * sizeof *fs);
        xs[j + 1] = 0.5 * (xs[j] + xs[j + 2]);
        fs[j + 1] = fobj_coarse(c, xs[j + 1]);
        ns++;
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

/* The kind of curve on a piece between split points, from its midpoint;
 * CLASS_NONE is confirmed at the quarter points, and CLASS_MIXED (they disagree:
 * a split point missed by rounding) has the piece searched as it is. */
static int piece_class(const hprob *pr, int b, double a, double c)
{
    const int mid = point_class(pr, b, 0.5 * (a + c));
    if (mid != CLASS_NONE) return mid;
    /* a piece is skipped only when the quarter points agree */
    const int c1 = point_class(pr, b, a + 0.25 * (c - a)), c3 = point_class(pr, b, a + 0.75 * (c - a));
    return c1 == CLASS_NONE && c3 == CLASS_NONE ? CLASS_NONE : CLASS_MIXED;
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
        if ((rc = split_points(pr, b, X, r40, b40, n40, &l))) return rc;
        splitpt pts[MAXPTS + 2] = {{-X, 0}, {X, 0}};
        int n = 2, cls[MAXPTS + 1];
        for (int i = 0; i < l.n; i++)
            if (l.v[i].x > -X && l.v[i].x < X) pts[n++] = l.v[i];
        sort_splitpts(pts, n);
        for (int i = 0; i + 1 < n; i++) cls[i] = piece_class(pr, b, pts[i].x, pts[i + 1].x);
        fctx c;
        fctx_init(&c, pr, b);
        for (int i = 0; i + 1 < n; i++) {
            if (cls[i] == CLASS_NONE) continue;            /* no curve anywhere on the piece */
            /* inflectional neighbours across a soft split point form one piece */
            const double a = pts[i].x;
            while (cls[i] == CLASS_INFL && i + 2 < n && pts[i + 1].soft && cls[i + 1] == CLASS_INFL) i++;
            const double bb = pts[i + 1].x;
            /* samples in proportion to the piece's share of the domain, at least 2 */
            const int m = 1 + (int)ceil(ns * (bb - a) / (2.0 * X));
            if ((rc = solve_piece(&c, a, bb, m > 1000 ? 1000 : m, out))) return rc;
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
    const double k2 = km2 / (2.0 * Fn), kc2 = (Fn - sigma) / (2.0 * Fn);
    const double h = 0.5 * wrap_pi(theta - atan2(F[1], F[0]));
    p->mu = 0.5 * Fn;
    p->phi = atan2(F[1], F[0]);
    double Fq, Dq;
    int rc;
    /* q = F(amplitude): F is odd in the amplitude, which lies in (-pi, pi] */
    if (kc2 > 0.0) {
        const double y = sqrt(2.0 * Fn) * sin(h), r = hypot(y, kappa);
        if ((rc = ell_fd_amp(fabs(y) / r, kappa / r, 0, k2, kc2, 1.0, &Fq, &Dq))) return rc;
        p->k = sqrt(k2);
        p->q = copysign(Fq, y);
    } else {
        const double k = sqrt(k2), m2 = 2.0 * Fn / km2, mc2 = (sigma - Fn) / km2;
        const double eps = kappa > 0.0 ? 1.0 : -1.0;
        if (!(kappa != 0.0)) return EL_EDOM;
        if ((rc = ell_fd_amp(fabs(sin(h)), cos(h), 0, m2, mc2, 1.0, &Fq, &Dq))) return rc;
        p->k = eps * k;
        p->q = copysign(Fq, eps * h) / k;
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

/* The polish's step test: -1 if q is invalid, else 1 if its end residual (the
 * first four entries of polish_res, max norm) is below that of r, else 0; rq gets
 * q's residual vector. */
static int step_improves(const frame *fr, int mode, double target, const el_smooth_params *q,
                         const double *r, double *rq)
{
    if (el_smooth_check(q) || polish_res(fr, q, mode, target, rq)) return -1;
    double n0 = 0.0, n1 = 0.0;
    for (int i = 0; i < 4; i++) { n0 = fmax(n0, fabs(r[i])); n1 = fmax(n1, fabs(rq[i])); }
    return n1 < n0;
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
        const int better = step_improves(fr, mode, target, &q, r, rq);
        if (better < 0) return;
        if (!better) break;
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
            if (step_improves(fr, mode, target, &q, r, rq) != 1) break;
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
        /* kappa = kappa_m cn(u): a zero inside iff the amplitude am u passes an odd
         * multiple of pi/2 between its values a0, a0 + d at the ends, d in (0, 2 pi]
         * (am(u + 2 Kc) = am u + pi): d > pi iff u(L) - u(0) > 2 Kc, which decides d
         * where rounding leaves it open (a whole period, d = 2 pi, has two zeros) */
        const double a0 = atan2(st->s0, st->c0);
        double d = atan2(st->s1, st->c1) - a0;
        d -= 2.0 * M_PI * floor(d / (2.0 * M_PI));
        if (st->big && d <= M_PI) d += 2.0 * M_PI;
        if (!st->big && d > 1.5 * M_PI) d -= 2.0 * M_PI;
        const double a = (a0 - M_PI_2) / M_PI + 1e-9, b = (a0 + d - M_PI_2) / M_PI - 1e-9;
        /* zeros of cn strictly inside: integers n with a < n < b (a zero at an end is no inflection) */
        s->has_inflection = ceil(b) - floor(a) - 1.0 > 0.5;
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
    opt->samples = 12;
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
