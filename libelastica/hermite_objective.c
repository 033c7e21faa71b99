/*
 * The normalised Hermite problem of seed 004: the curvature data of Theorem 6 for
 * the unknown, the curve of Theorem 7 through two curvature states, and the objective.
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
#include "hermite_internal.h"
#include <float.h>

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

EL__INLINE void amp_reduce(double S, double C, int big, double k2, double kc2, reduced_amp *r)
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

int el__hermite_ell_fd(double S, double C, int big, double k2, double kc2, double qs,
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

double el__hermite_wrap_pi(double a) /* into (-pi, pi] */
{
    /* fmod is exact: below 2 pi in size it returns a itself, so the call only above */
    if (!(fabs(a) < 2.0 * M_PI)) a = fmod(a, 2.0 * M_PI);
    if (a <= -M_PI) a += 2.0 * M_PI;
    if (a > M_PI) a -= 2.0 * M_PI;
    return a;
}


/* Case 3 (P2 = 0, V1 = 0): the four kappa0 of (24) as functions of sigma:
 * kappa0^2 = sigma, or (P1 kappa0 + 2)^2 = sigma P1^2 + 4 V2. NaN if not real. */
double el__hermite_case3_kappa0(const hprob *pr, int fam)
{
    const double s = pr->sigma;
    if (fam < 2) return s >= 0.0 ? (fam ? -sqrt(s) : sqrt(s)) : NAN;
    const double r = s * pr->P1 * pr->P1 + 4.0 * pr->V2;
    if (r < 0.0) return NAN;
    return (-2.0 + (fam == 2 ? 1.0 : -1.0) * sqrt(r)) / pr->P1;
}

/* Theorem 6: curvature data for the unknown x (kappa0 in case 1, 2; kappa0' in
 * case 3) on branch b (case 1: root of (17); case 3: the kappa0 of (24)). */
/* el__hermite_curvdata, inlined into el__hermite_x_objective */
EL__INLINE int curvdata(const hprob *pr, double x, int b, hstate *st)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    double k0, k0p, k1;
    if (pr->hcase == 3) {
        k0 = el__hermite_case3_kappa0(pr, b);
        if (!isfinite(k0)) return EL_EDOM;
        k0p = x;
        k1 = 0.5 * (k0 * k0 - s) * P1 + k0;                /* (16), P2 = 0 */
    } else {
        k0 = x;
        /* A = w V2 + sigma as kappa0^2 V2 + sigma (1 - V2) (1 - V2 exact for V2 >= 1/2):
         * with V nearly T(0) the terms of w V2 + sigma cancel, and the rounding of w (an ulp
         * of sigma) made A, and kappa1, kappa0' with it, step with kappa0 */
        const double w = k0 * k0 - s, C = 0.5 * w * P1 + k0, A = k0 * k0 * V2 + s * (1.0 - V2);
        if (pr->hcase == 2) {
            k1 = C;                                          /* (21) */
            k0p = (A - C * C) * pr->i2V1;                    /* (22) */
        } else {
            const double c0 = 2.0 * V1 * C + A * P2;
            const double disc = V1 * V1 + P2 * c0;           /* (18) */
            if (disc < 0.0) return EL_EDOM;
            const double sq = sqrt(disc);
            /* (19) in the cancellation-free form: b = 0 is (-V1 + sq)/P2, b = 1 is (-V1 - sq)/P2 */
            if (b == 0) k1 = V1 > 0.0 ? c0 / (V1 + sq) : (-V1 + sq) * pr->iP2;
            else        k1 = V1 < 0.0 ? c0 / (V1 - sq) : (-V1 - sq) * pr->iP2;
            /* (20) kappa0' = (kappa1 - C)/P2, or equivalently (15) solved for kappa0' */
            k0p = fabs(V1) > fabs(P2) ? (A - k1 * k1) * pr->i2V1 : (k1 - C) * pr->iP2;
        }
    }
    st->k0 = k0;
    st->k0p = k0p;
    st->k1 = k1;
    st->k1p = k0p * V2 + 0.5 * (k0 * k0 - s) * V1;          /* (14) */
    st->has_sep = 0;
    return isfinite(k1) && isfinite(k0p) ? EL_OK : EL_EDOM;
}

int el__hermite_curvdata(const hprob *pr, double x, int b, hstate *st) { return curvdata(pr, x, b, st); }


/* el__hermite_state_class, inlined into shape_prepare */
EL__INLINE int state_class(const hprob *pr, const hstate *st, double *Fn)
{
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s;
    /* sqrt rather than hypot (inner loop; the values are far from overflow) */
    *Fn = sqrt(F1 * F1 + F2 * F2);
    if (st->has_sep) *Fn = s + st->sep;        /* the separatrix chart's exact |F| - sigma */
    if (!(*Fn > 1e-13 * (1.0 + fabs(s))) || !(*Fn + s > 0.0)) return CLASS_NONE;
    if (st->has_sep ? st->sep > 0.0 : *Fn > s) return CLASS_INFL;   /* k'^2 = (|F| - sigma) / (2 |F|) > 0 */
    return st->k0 * st->k1 > 0.0 ? CLASS_NONINFL : CLASS_NONE;
}

int el__hermite_state_class(const hprob *pr, const hstate *st, double *Fn) { return state_class(pr, st, Fn); }

int el__hermite_x_class(const hprob *pr, double x, int b)
{
    hstate st;
    double Fn;
    return curvdata(pr, x, b, &st) ? CLASS_NONE : state_class(pr, &st, &Fn);
}

/* What shape_finish needs besides the two Carlson integrals of the reduced amplitude:
 * L = Lscale F, E = Escale (F - Dfac (D + prod)), f = (E - sigma L - FP) iFn; and
 * what shape_grad needs: m, mc the parameter of the integrals and its complement,
 * the sine, cosine and delta amplitude of the amplitude at both ends, |F|, kappa_m^2,
 * sqrt(mu) = sqrt(|F|/2), F and (S1, C1) = |F| (sin, cos) of theta1 - phi. */
/* An end state equal to the start state within rounding is a whole period away (L = T):
 * with parallel end tangents one branch of (17) has kappa1 = kappa0, kappa1' = kappa0'
 * everywhere, and sin mu, zero but for rounding, took L = 0+ or T at random, so that the
 * objective jumped along it and roots came and went with the samples (200 random problems
 * with parallel tangents: 87 solution sets changed between 12 and 300 samples, the
 * least-energy solution among those lost; with any tangents: none) */
#define WHOLE_PERIOD 1e-14

typedef struct {
    reduced_amp ra;
    double Lscale, Escale, Dfac, prod, FP, iFn;
    int infl;
    double m, mc, sa0, ca0, da0, sa1, ca1, da1;
    double Fn, km2, rmu, F1, F2, S1, C1, sh0, ch0, sh1, ch1;
} shapework;

/* Theorem 7 and its supplement: the curvature function through (kappa0, kappa0')
 * reaches (kappa1, kappa1') at a unique L in (0, T]; then length, energy and the
 * objective f, in two halves around the one Carlson R_F/R_D evaluation of the
 * reduced amplitude (el__hermite_shape_eval). Inlined, with amp_reduce and state_class, into
 * its three callers: el__hermite_shape_eval_to's copy (every sample and root-finder step)
 * drops the stores only shape_grad reads and keeps the reduced amplitude in registers; the
 * same arithmetic, the same bits, 5.6 % fewer instructions on the tension bench (issue 16). */
EL__INLINE int shape_prepare(const hprob *pr, hstate *st, shapework *w)
{
    double Fn;
    const int cls = state_class(pr, st, &Fn);
    if (cls == CLASS_NONE) return EL_EDOM;
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s, km2 = Fn + s;
    /* k^2 = kappa_m^2 / (2 |F|) and its complement, exact up to the one difference
     * |F| - sigma, which is the separatrix distance itself */
    const double sep = st->has_sep ? st->sep : Fn - s;
    const double i2F = 0.5 / Fn, k2 = km2 * i2F, kc2 = sep * i2F, rmu = sqrt(0.5 * Fn);
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
        if (cmu > 0.0 && fabs(smu) <= WHOLE_PERIOD) smu = 0.0;
        const int big = smu < 0.0 || (smu == 0.0 && cmu > 0.0);
        amp_reduce(smu, cmu, big, k2, kc2, &w->ra);
        st->s0 = s0;        /* for make_solution's inflection count */
        st->c0 = c0;
        st->s1 = s1;
        st->c1 = c1;
        st->big = big;
        w->m = k2;
        w->mc = kc2;
        w->sa0 = s0; w->ca0 = c0; w->da0 = ch0;
        w->sa1 = s1; w->ca1 = c1; w->da1 = ch1;
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
        const double m2 = 2.0 * Fn / km2, mc2 = -sep / km2;
        const double b0 = eps * sh0, b1 = eps * sh1;
        amplitude_difference(m2, b0, ch0, fabs(st->k0) / km, b1, ch1, fabs(st->k1) / km, &smu, &cmu);
        /* the product b1 b0 sin mu is the same for either sign choice */
        w->prod = b1 * b0 * smu;
        if (cmu > 0.0 && fabs(smu) <= WHOLE_PERIOD) smu = 0.0;
        if (smu < 0.0 || (smu == 0.0 && cmu > 0.0)) { smu = -smu; cmu = -cmu; }
        amp_reduce(smu, cmu, 0, m2, mc2, &w->ra);
        w->m = m2;
        w->mc = mc2;
        w->sa0 = b0; w->ca0 = ch0; w->da0 = fabs(st->k0) / km;
        w->sa1 = b1; w->ca1 = ch1; w->da1 = fabs(st->k1) / km;
        /* F = v(L) - v(0), dv/ds = k sqrt(mu); int dn^2 dv = F - m^2 D */
        const double iw = 1.0 / (sqrt(k2) * rmu);
        w->Lscale = iw;
        w->Escale = km2 * iw;
        w->Dfac = m2;
    }
    st->infl = w->infl = cls == CLASS_INFL;
    w->FP = F1 * pr->P1 + F2 * pr->P2;
    w->iFn = 2.0 * i2F;
    w->Fn = Fn; w->km2 = km2; w->rmu = rmu; w->F1 = F1; w->F2 = F2; w->S1 = S1; w->C1 = C1;
    w->sh0 = sh0; w->ch0 = ch0; w->sh1 = sh1; w->ch1 = ch1;
    return EL_OK;
}

/* U = F(mu) (the argument difference u1 - u0, or v1 - v0), DD = D(mu) + prod
 * (int sn^2 du, or int sn^2 dv, over it) */
static int shape_finish(const hprob *pr, const shapework *w, double rf, double rd, hstate *st,
                        double *U, double *DD)
{
    double F, D;
    const int rc = amp_fd(&w->ra, rf, rd, &F, &D);
    if (rc) return rc;
    *U = F;
    *DD = D + w->prod;
    st->L = w->Lscale * F;
    st->E = w->Escale * (F - w->Dfac * *DD);
    st->f = (st->E - pr->sigma * st->L - w->FP) * w->iFn;   /* (12) along F */
    return isfinite(st->f) && st->L > 0.0 ? EL_OK : EL_EDOM;
}

/* Charts of the surface of curvature data (Theorem 6): the state from two coordinates
 * (u, v) and a sheet b, with the derivatives of kappa0, kappa0', kappa1, kappa1' and
 * sigma in u ([0]) and v ([1]).
 *   HCHART_X  (x, sigma): the unknown x of el__hermite_curvdata on branch b;
 *   HCHART_K1 (kappa1, sigma), case 1: kappa0 the root b of (18) = (P2 kappa1 + V1)^2
 *             (b = 0: d(18)/dkappa0 >= 0), on the branch of (17) given by the sign of
 *             P2 kappa1 + V1 (b = 0 of curvdata when >= 0): regular where the branches of
 *             (17) meet ((18) = 0), where HCHART_X folds;
 *   HCHART_C3 (kappa0, kappa0'), case 3: sigma = kappa0^2 (b = 0) or from the other pair
 *             of (24), (P1 kappa0 + 2)^2 = sigma P1^2 + 4 V2 (b = 1): regular where the
 *             two members of a pair meet. */
/* kappa0' and its derivatives from kappa0, kappa1, sigma and theirs: (16), or (15)
 * when V1 dominates (case 1); (22) in case 2; then kappa1' by (14). have_slopes: the
 * state's kappa0', kappa1' are curvdata's, the same expressions (the same bits), and
 * only their derivatives are formed. */
static void slopes_and_grad(const hprob *pr, int have_slopes, hstate *st, curv_grad *g)
{
    const double P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2, s = pr->sigma;
    const double k0 = st->k0, k1 = st->k1, w = k0 * k0 - s, C = 0.5 * w * P1 + k0;
    const double A = k0 * k0 * V2 + s * (1.0 - V2);             /* as in el__hermite_curvdata */
    const int use15 = pr->hcase == 2 || fabs(V1) > fabs(P2);
    if (!have_slopes) {
        if (pr->hcase != 3) st->k0p = use15 ? (A - k1 * k1) * pr->i2V1 : (k1 - C) * pr->iP2;
        st->k1p = st->k0p * V2 + 0.5 * w * V1;                  /* (14) */
    }
    for (int i = 0; i < 2; i++) {
        const double dw = 2.0 * k0 * g->k0[i] - g->s[i], dC = 0.5 * P1 * dw + g->k0[i];
        const double dA = V2 * dw + g->s[i];
        if (pr->hcase != 3)
            g->k0p[i] = use15 ? (dA - 2.0 * k1 * g->k1[i]) / (2.0 * V1) : (g->k1[i] - dC) / P2;
        g->k1p[i] = g->k0p[i] * V2 + 0.5 * dw * V1;
    }
}

/* The state of chart point (u, v, b) and its derivatives; EL_EDOM where it has none. */
static int chart_state(const hprob *pr0, int chart, double u, double v, int b, hprob *pr,
                       hstate *st, curv_grad *g)
{
    const double P1 = pr0->P1, P2 = pr0->P2, V1 = pr0->V1, V2 = pr0->V2;
    /* every derivative stored below (the zeros too; k0p and k1p by slopes_and_grad
     * outside case 3): no memset of the struct per evaluation */
    g->has_dsep = 0;
    *pr = *pr0;
    st->has_sep = 0;
    if (chart == HCHART_C3) {
        const double k0 = u, q = P1 * k0 + 2.0;
        pr->sigma = b == 0 ? k0 * k0 : (q * q - 4.0 * V2) / (P1 * P1);
        st->k0 = k0;
        st->k0p = v;
        st->k1 = 0.5 * (k0 * k0 - pr->sigma) * P1 + k0;         /* (16), P2 = 0 */
        g->k0[0] = 1.0; g->k0[1] = 0.0;
        g->k0p[0] = 0.0; g->k0p[1] = 1.0;
        g->s[0] = b == 0 ? 2.0 * k0 : 2.0 * q / P1; g->s[1] = 0.0;
        g->k1[0] = 0.5 * P1 * (2.0 * k0 - g->s[0]) + 1.0; g->k1[1] = 0.0;
    } else if (chart == HCHART_K1) {
        /* (18) as a quadratic in kappa0: disc = a2 x^2 + a1 x + a0(sigma) = W^2 */
        const double s = v, W = P2 * u + V1;
        const double a2 = P2 * V1 * P1 + P2 * P2 * V2, a1 = 2.0 * P2 * V1;
        const double a0 = V1 * V1 - P2 * V1 * P1 * s + P2 * P2 * s * (1.0 - V2) - W * W;
        const double dq = a1 * a1 - 4.0 * a2 * a0;
        if (!(dq >= 0.0) || a2 == 0.0) return EL_EDOM;
        const double r = (b == 0 ? 1.0 : -1.0) * sqrt(dq);   /* = 2 a2 x + a1 */
        const double x = (r - a1) * a1 > 0.0 ? (r - a1) / (2.0 * a2) : -2.0 * a0 / (a1 + r);
        if (!(r != 0.0)) return EL_EDOM;
        pr->sigma = s;
        st->k0 = x;
        st->k1 = u;
        g->k1[0] = 1.0; g->k1[1] = 0.0;
        g->s[0] = 0.0; g->s[1] = 1.0;
        g->k0[0] = 2.0 * W * P2 / r;                          /* d(18)/dx dx = 2 W P2 dkappa1 */
        g->k0[1] = -(-P2 * V1 * P1 + P2 * P2 * (1.0 - V2)) / r;
    } else {
        pr->sigma = v;
        if (curvdata(pr, u, b, st)) return EL_EDOM;
        g->s[0] = 0.0; g->s[1] = 1.0;
        if (pr->hcase == 3) {
            /* x = kappa0'; kappa0 = +-sqrt(sigma) or (P1 kappa0 + 2)^2 = sigma P1^2 + 4 V2 */
            g->k0p[0] = 1.0; g->k0p[1] = 0.0;
            g->k0[0] = 0.0;
            g->k0[1] = b < 2 ? 0.5 / st->k0 : 0.5 * P1 / (P1 * st->k0 + 2.0);
            g->k1[0] = 0.0;
            g->k1[1] = (P1 * st->k0 + 1.0) * g->k0[1] - 0.5 * P1;
        } else {
            g->k0[0] = 1.0; g->k0[1] = 0.0;
            const double dw0 = 2.0 * st->k0, dC0 = 0.5 * P1 * dw0 + 1.0, dA0 = V2 * dw0;
            const double dC1 = -0.5 * P1, dA1 = 1.0 - V2;
            if (pr->hcase == 2) {
                g->k1[0] = dC0;
                g->k1[1] = dC1;
            } else {
                /* (17) differentiated: 2 (P2 kappa1 + V1) dkappa1 = 2 V1 dC + P2 dA */
                const double iq = 0.5 / (P2 * st->k1 + V1);
                g->k1[0] = (2.0 * V1 * dC0 + P2 * dA0) * iq;
                g->k1[1] = (2.0 * V1 * dC1 + P2 * dA1) * iq;
            }
        }
    }
    slopes_and_grad(pr, chart == HCHART_X, st, g);
    return isfinite(st->k0p) && isfinite(st->k1) && isfinite(st->k1p) ? EL_OK : EL_EDOM;
}

/* Gradient of L, E and f from the curvature data's (curv_grad) by the chain rule
 * through shape_prepare, with the derivatives of the incomplete integrals in their
 * amplitude a and parameter m (DLMF 19.4.1-2 and dF/da = 1/Delta, dD/da = sin^2 a/Delta):
 *   dF/dm = (E - (1-m) F) / (2 m (1-m)) - sin a cos a / (2 (1-m) Delta),
 *   dE/dm = (E - F) / (2m),  D = (F - E)/m,
 * taken as differences between the two ends: with U = F(a1) - F(a0), DD = D(a1) - D(a0)
 * and E(a1) - E(a0) = U - m DD,
 *   dU/dm = (U - DD - T) / (2 (1-m)),  T = [sin a cos a / Delta] from a0 to a1,
 *   dDD/dm = (dU/dm - DD/2) / m.
 * Inflectional: sin a = sin h / k, cos a = kappa / kappa_m, Delta = cos h, so
 * da = cos a d(sin a) - sin a d(cos a); non-inflectional: a = +-h. */
static void shape_grad(const hprob *pr, const hstate *st, const curv_grad *cg, const shapework *w,
                       double U, double DD, hgrad *g)
{
    const double s = pr->sigma, Fn = w->Fn, m = w->m, km2 = w->km2, km = sqrt(km2);
    for (int i = 0; i < 2; i++) {
        const double ds = cg->s[i];
        const double dF1 = -2.0 * cg->k0p[i], dF2 = 2.0 * st->k0 * cg->k0[i] - ds;
        const double dFn = (w->F1 * dF1 + w->F2 * dF2) / Fn, dkm2 = dFn + ds;
        const double dh0 = 0.5 * (w->F2 * dF1 - w->F1 * dF2) / (Fn * Fn);
        const double dS1 = -2.0 * cg->k1p[i], dC1 = 2.0 * st->k1 * cg->k1[i] - ds;
        const double dh1 = 0.5 * (w->C1 * dS1 - w->S1 * dC1) / (w->S1 * w->S1 + w->C1 * w->C1);
        /* the parameter from the separatrix distance delta = |F| - sigma: inflectional
         * m' = 1 - m = delta / (2|F|), non-inflectional 1 - m = -delta / kappa_m^2 */
        const double dsep = cg->has_dsep ? cg->dsep[i] : dFn - ds;
        double dm, da0, da1;
        if (w->infl) {
            dm = (2.0 * w->mc * dFn - dsep) / (2.0 * Fn);
            const double ik = 1.0 / sqrt(m), dik = -0.5 * ik * ik * ik * dm;
            const double ikm = 1.0 / km, dikm = -0.5 * ikm * ikm * ikm * dkm2;
            const double ds0 = w->ch0 * dh0 * ik + w->sh0 * dik, dc0 = cg->k0[i] * ikm + st->k0 * dikm;
            const double ds1 = w->ch1 * dh1 * ik + w->sh1 * dik, dc1 = cg->k1[i] * ikm + st->k1 * dikm;
            da0 = w->ca0 * ds0 - w->sa0 * dc0;
            da1 = w->ca1 * ds1 - w->sa1 * dc1;
        } else {
            dm = (dsep + w->mc * dkm2) / km2;
            const double eps = st->k0 > 0.0 ? 1.0 : -1.0;
            da0 = eps * dh0;
            da1 = eps * dh1;
        }
        const double T = w->sa1 * w->ca1 / w->da1 - w->sa0 * w->ca0 / w->da0;
        const double dUm = (U - DD - T) / (2.0 * w->mc), dDDm = (dUm - 0.5 * DD) / m;
        const double dU = da1 / w->da1 - da0 / w->da0 + dUm * dm;
        const double dDD = w->sa1 * w->sa1 / w->da1 * da1 - w->sa0 * w->sa0 / w->da0 * da0 + dDDm * dm;
        double dL, dE;
        if (w->infl) {
            /* L = U / sqrt(mu), E = kappa_m^2 (U - DD) / sqrt(mu) */
            const double drmu = dFn / (4.0 * w->rmu);
            dL = (dU - st->L * drmu) / w->rmu;
            dE = (dkm2 * (U - DD) + km2 * (dU - dDD) - st->E * drmu) / w->rmu;
        } else {
            /* L = 2 U / kappa_m, E = 2 kappa_m (U - m DD) */
            const double dkm = dkm2 / (2.0 * km);
            dL = (2.0 * dU - st->L * dkm) / km;
            dE = 2.0 * dkm * (U - m * DD) + 2.0 * km * (dU - dm * DD - m * dDD);
        }
        const double dFP = dF1 * pr->P1 + dF2 * pr->P2;
        g->L[i] = dL;
        g->E[i] = dE;
        g->s[i] = ds;
        g->sep[i] = dsep;
        g->f[i] = (dE - s * dL - st->L * ds - dFP - st->f * dFn) / Fn;
    }
}

int el__hermite_shape_eval_to(const hprob *pr, double qs, double fine_below, hstate *st, int *fine)
{
    shapework w;
    double rf, rd, U, DD;
    int rc = shape_prepare(pr, st, &w);
    if (!rc) rc = el__carlson_fd(w.ra.x, w.ra.y, 1.0, qs, &rf, &rd);
    if (rc || (rc = shape_finish(pr, &w, rf, rd, st, &U, &DD))) return rc;
    if (fine) *fine = qs >= 1.0;
    if (qs >= 1.0 || !(fabs(st->f) <= fine_below)) return EL_OK;
    /* the same state to double precision: the integrals again, the rest kept */
    if ((rc = el__carlson_fd(w.ra.x, w.ra.y, 1.0, 1.0, &rf, &rd)) || (rc = shape_finish(pr, &w, rf, rd, st, &U, &DD)))
        return rc;
    if (fine) *fine = 1;
    return EL_OK;
}

int el__hermite_shape_eval(const hprob *pr, double qs, hstate *st)
{
    return el__hermite_shape_eval_to(pr, qs, -1.0, st, NULL);   /* |f| <= -1: never continued */
}

/* curvdata, shape_prepare, the integrals and shape_finish inlined into one function on a
 * local state: what the bracketing samples need (their f), without the state's stores */
int el__hermite_x_objective(const hprob *pr, double x, int b, double qs, double *f)
{
    hstate st;
    shapework w;
    double rf, rd, U, DD;
    int rc = curvdata(pr, x, b, &st);
    if (!rc) rc = shape_prepare(pr, &st, &w);
    if (!rc) rc = el__carlson_fd(w.ra.x, w.ra.y, 1.0, qs, &rf, &rd);
    if (!rc) rc = shape_finish(pr, &w, rf, rd, &st, &U, &DD);
    *f = rc ? NAN : st.f;
    return rc;
}

int el__hermite_chart_eval(const hprob *pr, int chart, double u, double v, int b, hstate *st,
                           hgrad *g, double *sigma)
{
    shapework w;
    curv_grad cg;
    hprob q;
    double rf, rd, U, DD;
    int rc = chart_state(pr, chart, u, v, b, &q, st, &cg);
    if (!rc) rc = shape_prepare(&q, st, &w);
    if (!rc) rc = el__carlson_fd(w.ra.x, w.ra.y, 1.0, 1.0, &rf, &rd);
    if (!rc) rc = shape_finish(&q, &w, rf, rd, st, &U, &DD);
    if (rc) return rc;
    shape_grad(&q, st, &cg, &w, U, DD, g);
    if (sigma) *sigma = q.sigma;
    return isfinite(g->f[0]) && isfinite(g->f[1]) ? EL_OK : EL_EDOM;
}

/* |F| - sigma of a state, without the cancellation of the difference:
 * |F|^2 - sigma^2 = 4 kappa0'^2 + kappa0^2 (kappa0^2 - 2 sigma); its derivative from curv_grad. */
static double sep_of(const hprob *pr, const hstate *st, const curv_grad *cg, int i, double *dsep)
{
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s;
    const double Fn = sqrt(F1 * F1 + F2 * F2);
    *dsep = (F1 * -2.0 * cg->k0p[i] + F2 * (2.0 * st->k0 * cg->k0[i] - cg->s[i])) / Fn - cg->s[i];
    return (F1 * F1 + st->k0 * st->k0 * (st->k0 * st->k0 - 2.0 * s)) / (Fn + s);
}

/* The rounding of sep_of's value: a few ulps of its numerator's terms over |F| + sigma. */
static double sep_rounding(const hprob *pr, const hstate *st)
{
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s, q = st->k0 * st->k0;
    return 8.0 * DBL_EPSILON * (F1 * F1 + q * (q + 2.0 * fabs(s))) / (sqrt(F1 * F1 + F2 * F2) + fabs(s));
}

static int sep_point_at(const hprob *pr, int base, int fi, int b, double other, double w, sep_point *p)
{
    p->w = w;
    if (chart_state(pr, base, fi ? other : w, fi ? w : other, b, &p->q, &p->st, &p->cg)) return EL_EDOM;
    p->d = sep_of(&p->q, &p->st, &p->cg, fi, &p->dd);
    return isfinite(p->d) && isfinite(p->dd) && p->dd != 0.0 ? EL_OK : EL_EDOM;
}

/* Whether |F| - sigma runs monotonically (d/dw of the sign sgn) from p to t through their
 * midpoint: a long step of Newton's that passed over a hump and a valley to a
 * neighbouring crossing is caught there (one more evaluation). */
static int sep_monotone_mid(const hprob *pr, int base, int fi, int b, double other, const sep_point *p,
                            const sep_point *t, double sgn)
{
    sep_point m;
    const double dir = t->w > p->w ? sgn : -sgn;
    return !sep_point_at(pr, base, fi, b, other, 0.5 * (p->w + t->w), &m) && m.dd * sgn > 0.0 &&
           (m.d - p->d) * dir > 0.0 && (t->d - m.d) * dir > 0.0;
}

/* |F| - sigma = target along w from the guess **pp (evaluated; *pp, *tp: the two points'
 * storage, *pp the result): Newton, safeguarded so that the root is the one on the
 * monotone stretch of |F| - sigma the guess lies on (the same crossing of the separatrix),
 * whatever the guess there:
 * - before the target is bracketed a step is taken only where d(|F| - sigma)/dw keeps the
 *   guess's sign, the secant from the last point agrees with it, the error
 *   |(|F| - sigma) - target| decreases and, for a step above 1e-3 (1 + |w|), the midpoint
 *   lies between (sep_monotone_mid); else it is halved. Halved to the resolution of w,
 *   past a peak the parabola through the two slopes puts well short of the target, or
 *   after 60 evaluations (the former damped Newton's limit), there is no root on the
 *   stretch (the target lies beyond its hump or the chart's domain): that Newton crept
 *   towards such a peak for all its 60 steps (856 of the length bench's 139k calls);
 * - once points on both sides of the target are known the steps stay between them (no
 *   step over a hump to a neighbouring crossing): Newton's where it falls inside and at
 *   most halves the last, else the midpoint (Numerical Recipes' rtsafe);
 * - it stops where the error is at the rounding of sep_of's terms (sep_rounding), the step
 *   or the bracket at the resolution of w, or, within 4e-16 sigma, where a step no longer
 *   reduces the error (the noise of |F| - sigma: the rounding of kappa0' from (17)).
 *   It stopped at 4e-16 sigma: next to a crossing |F| - sigma is many orders below
 *   sigma, and w, and f with it (~1e-7 at sigma |p1-p0|^2 ~ 100..1000), depended on the
 *   guess, so the root finder's |f| stalled above what the solver keeps.
 * Hand-written: GSL's bracketed solvers (brent) need the bracket first and discard the
 * derivative the chart gives with the value, its Newton (gsl_root_fdfsolver) has no
 * safeguard, and the stretch (the sign of the slope) is a condition none of them knows. */
static int sep_solve(const hprob *pr, int base, int fi, int b, double other, double target, sep_point **pp,
                     sep_point **tp)
{
    sep_point *p = *pp, *t = *tp;
    const double sgn = p->dd > 0.0 ? 1.0 : -1.0;
    double lo = NAN, hi = NAN;   /* sgn ((|F| - sigma) - target) < 0 at lo, > 0 at hi */
    double last = INFINITY;      /* the last step's size */
    int evals = 0;               /* at most 60 evaluations (each pass makes at least one) */
    for (;;) {
        const double r = p->d - target, res = 4e-16 * fabs(p->w);
        if (!(fabs(r) > sep_rounding(&p->q, &p->st))) return EL_OK;
        /* within the rounding of sigma (the bound of the noise of |F| - sigma) a step that
         * does not reduce the error ends the iteration */
        const int noise = fabs(r) <= 4e-16 * (fabs(p->q.sigma) + fabs(p->d) + fabs(p->q.sigma + p->d));
        if (sgn * r < 0.0) lo = p->w; else hi = p->w;
        double step = -r / p->dd;
        if (!(fabs(step) > res)) return EL_OK;           /* Newton's step at the resolution of w */
        if (!isnan(lo + hi)) {
            /* bracketed: Newton's step where it falls inside and at most halves the last,
             * else the midpoint (as Numerical Recipes' rtsafe) */
            const double wn = p->w + step;
            if (fabs(hi - lo) <= 2.0 * res) return EL_OK;
            if (!(lo < hi ? wn > lo && wn < hi : wn > hi && wn < lo) || !(fabs(step) <= 0.5 * last))
                step = 0.5 * (lo + hi) - p->w;
            last = fabs(step);
            if (++evals > 60 || sep_point_at(pr, base, fi, b, other, p->w + step, t) || !(t->dd * sgn > 0.0))
                return noise ? EL_OK : EL_ENOCONV;
            if (noise && !(fabs(t->d - target) < fabs(r))) return EL_OK;
            *tp = p;
            *pp = p = t;
            t = *tp;
            continue;
        }
        for (;;) {
            /* no better point: no root on the stretch, or the noise */
            if (!(fabs(step) > res)) return noise ? EL_OK : EL_ENOCONV;
            if (++evals > 60) return EL_ENOCONV;
            const int bad = sep_point_at(pr, base, fi, b, other, p->w + step, t);
            if (!bad && t->dd * sgn > 0.0 && (t->d - p->d) * step * sgn > 0.0 && fabs(t->d - target) < fabs(r) &&
                (fabs(step) <= 1e-3 * (1.0 + fabs(p->w)) || sep_monotone_mid(pr, base, fi, b, other, p, t, sgn))) {
                *tp = p;
                *pp = p = t;
                t = *tp;
                break;
            }
            if (noise) return EL_OK;
            /* past the hump's peak by a short step, still short of the target */
            if (!bad && !(t->dd * sgn > 0.0) && sgn * (t->d - target) < 0.0 && fabs(step) <= 1e-3 * (1.0 + fabs(p->w))) {
                const double c = (t->dd - p->dd) / step;
                if (sgn * (p->d - 0.5 * p->dd * p->dd / c - target) < -0.25 * fabs(r)) return EL_ENOCONV;
            }
            step *= 0.5;
        }
        last = fabs(step);
    }
}

/* The x chart's state (case 1, 2) with |F| - sigma = target exactly: kappa0' from
 * kappa0 and target by (8), 4 kappa0'^2 = (|F| - sigma + kappa0^2)(|F| + sigma - kappa0^2)
 * (its sign the sheet's), kappa1 by (16), kappa1' by (14), and kappa0 = w refined by Newton
 * on (15), r = kappa1^2 + 2 V1 kappa0' - A, its last step (below the resolution of kappa0)
 * taken to first order in the others. sep_solve's w is where |F| - sigma computed from the
 * kappa0' of (17) meets the target; that kappa0' carries an ulp of rounding, which moves
 * |F| - sigma by ~eps |kappa0'|^2 / sigma and w by a few ulps; next to the saddle, where the
 * length goes with ln(|F| - sigma), f moved by up to ~1e-10 (near-straight solutions at
 * sigma |p1-p0|^2 ~ 100..1000). Here |F| - sigma is exact by construction and the rounding
 * falls on (15), which f feels less: the largest difference between guesses in
 * test_hermite_tension.c drops from 8.9e-10 to 2.9e-10, and of the former solver's t_aligned tension
 * solutions (seed 777, 3000 problems) 10 are lost instead of 16 (371 gained, 363 without).
 * Unchanged (EL_EDOM) where the refinement does not settle within 1e-9 of w. */
static int sep_exact_state(const hprob *q, double target, double *w, hstate *st)
{
    const double s = q->sigma, P1 = q->P1, P2 = q->P2, V1 = q->V1, V2 = q->V2, sgn = st->k0p < 0.0 ? -1.0 : 1.0;
    double k0 = *w;
    for (int it = 0;; it++) {
        const double k2 = k0 * k0, X = (target + k2) * (2.0 * s + target - k2);
        if (!(X > 0.0)) return EL_EDOM;
        const double k0p = sgn * 0.5 * sqrt(X);
        const double k1 = k0p * P2 + 0.5 * (k2 - s) * P1 + k0;                        /* (16) */
        const double r = k1 * k1 + 2.0 * V1 * k0p - (k2 * V2 + s * (1.0 - V2));        /* (15) */
        const double dk0p = k0 * (s - k2) / (2.0 * k0p), dk1 = dk0p * P2 + k0 * P1 + 1.0;
        const double step = -r / (2.0 * k1 * dk1 + 2.0 * V1 * dk0p - 2.0 * k0 * V2);
        if (!isfinite(step) || !(fabs(k0 + step - *w) <= 1e-9 * (1.0 + fabs(*w)))) return EL_EDOM;
        if (fabs(step) > 4e-16 * fabs(k0) && it < 4) {
            k0 += step;
            continue;
        }
        /* kappa1 and kappa1' are small next to the saddle and resolve the last step */
        *w = k0;
        st->k0 = k0;
        st->k0p = k0p + dk0p * step;
        st->k1 = k1 + dk1 * step;
        st->k1p = k0p * V2 + 0.5 * (k2 - s) * V1 + (dk0p * V2 + k0 * V1) * step;       /* (14) */
        return EL_OK;
    }
}

int el__hermite_sep_eval(const hprob *pr, int base, int fi, int b, int side, double y,
                         double other, double qs, double *w, hstate *st, hgrad *g, double *sigma)
{
    return el__hermite_sep_eval_from(pr, base, fi, b, side, y, other, qs, w, st, g, sigma, NULL);
}

int el__hermite_sep_eval_from(const hprob *pr, int base, int fi, int b, int side, double y, double other,
                              double qs, double *w, hstate *st, hgrad *g, double *sigma, hsep_cache *cache)
{
    const int oi = 1 - fi;
    const double target = side * exp(y);
    sep_point local[2], *buf = cache ? cache->pt : local, *p = buf, *t = buf + 1;
    if (cache && cache->valid && cache->w == *w) {
        p = buf + cache->cur;     /* the last call's point: its state, not evaluated again */
        t = buf + (1 - cache->cur);
    } else if (sep_point_at(pr, base, fi, b, other, *w, p)) {
        if (cache) cache->valid = 0;
        return EL_EDOM;
    }
    if (cache) cache->valid = 0;
    const int src = sep_solve(pr, base, fi, b, other, target, &p, &t);
    if (src) return src;
    double ww = p->w;
    const double d = p->d, dd = p->dd;
    const hprob q = p->q;
    curv_grad *cgp = &p->cg;
    *st = p->st;
    if (base == HCHART_X && fi == 0 && pr->hcase != 3) sep_exact_state(&q, target, &ww, st);
    if (target * d < 0.0 && fabs(d - target) > 1e-12 * fabs(q.sigma)) return EL_ENOCONV;
    st->has_sep = 1;
    st->sep = target;
    shapework sw;
    double rf, rd, U, DD;
    int rc = shape_prepare(&q, st, &sw);
    if (!rc) rc = el__carlson_fd(sw.ra.x, sw.ra.y, 1.0, qs, &rf, &rd);
    if (!rc) rc = shape_finish(&q, &sw, rf, rd, st, &U, &DD);
    if (rc) return rc;
    *w = ww;
    if (sigma) *sigma = q.sigma;
    if (!g) {
        if (cache) {
            cache->cur = (int)(p - buf);
            cache->valid = 1;
            cache->w = ww;
        }
        return EL_OK;
    }
    /* (y, other) -> base coordinates: d(base)/dy = target / d_w, d(base)/d(other) = -d_o / d_w */
    double d_o;
    sep_of(&q, st, cgp, oi, &d_o);
    const double wy = target / dd, wo = -d_o / dd;
    double *cols[5] = {cgp->k0, cgp->k0p, cgp->k1, cgp->k1p, cgp->s};
    for (int j = 0; j < 5; j++) {
        cols[j][oi] += cols[j][fi] * wo;
        cols[j][fi] *= wy;
    }
    cgp->has_dsep = 1;
    cgp->dsep[fi] = target;
    cgp->dsep[oi] = 0.0;
    shape_grad(&q, st, cgp, &sw, U, DD, g);
    g->w[fi] = wy;
    g->w[oi] = wo;
    return isfinite(g->f[0]) && isfinite(g->f[1]) ? EL_OK : EL_EDOM;
}

int el__hermite_eval_grad(const hprob *pr, double x, int b, hstate *st, hgrad *g)
{
    return el__hermite_chart_eval(pr, HCHART_X, x, pr->sigma, b, st, g, NULL);
}

int el__hermite_full_eval(const hprob *pr, double x, int b, hstate *st)
{
    int rc = el__hermite_curvdata(pr, x, b, st);
    return rc ? rc : el__hermite_shape_eval(pr, 1.0, st);
}


void el__hermite_set_case(hprob *pr)
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
    /* infinite where P2 or V1 is 0: no case's formulas then use them */
    pr->iP2 = 1.0 / pr->P2;
    pr->i2V1 = 0.5 / pr->V1;
}

