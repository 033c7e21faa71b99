/*
 * Jacobi elliptic functions sn, cn, dn, am, E, D for every modulus k >= 0,
 * with derivatives in u and k.
 *
 * sn, cn, dn come from the AGM with the complementary modulus passed exactly
 * (jacobi_agm: GSL's elljac takes only m = k^2, which loses digits near k = 1);
 * Carlson's R_D and the complete integrals from ellint.c (GSL's are slower). GSL has
 * neither the Jacobi epsilon function
 * nor derivatives in the modulus, so those are built here from the integrals
 * (amplitude phi = am u, Delta = dn u):
 *   D(phi) = int_0^phi sin^2/Delta   = (sin^3 phi / 3) R_D(cos^2, Delta^2, 1)   (DLMF 19.25.13)
 *   J(phi) = int_0^phi sin^2/Delta^3 = (sin^3 phi / 3) R_D(cos^2, 1, Delta^2)
 *   L(phi) = int_0^phi sin^4/Delta^3 = (J - D)/k^2   (series in k^2 for small k)
 * and, at fixed u (u = F(phi, k)):
 *   d am/dk = -k Delta J,   dD/dk = k (L - sn^2 J),   E = u - k^2 D.
 * k > 1 goes through the reciprocal-modulus transformation (header comment).
 */
#include "internal.h"

/* Below this k, L = (J - D)/k^2 loses more than two digits: use its series. */
#define SMALL_K 0.1

/* Carlson R_D to double precision. */
static int carlson_rd(double x, double y, double z, double *out)
{
    return el__carlson_fd(x, y, z, 1.0, NULL, out);
}

/* L(phi) = int_0^phi sin^4 t (1 - k^2 sin^2 t)^(-3/2) dt for k < SMALL_K, by the
 * binomial series sum_j c_j k^(2j) int sin^(4+2j), c_j = (3/2)(5/2)...(j+1/2)/j!,
 * with int_0^phi sin^(2p) = ((2p-1)/(2p)) I_{p-1} - sin^(2p-1) cos / (2p). */
static double small_k_L(double phi, double k)
{
    const double s = sin(phi), c = cos(phi), m = k * k;
    double I = phi, spow = s; /* I_0, sin^(2p-1) for p = 1 */
    double sum = 0.0, coef = 1.0, mj = 1.0;
    for (int p = 1; p <= 16; p++) {
        I = ((2.0 * p - 1.0) / (2.0 * p)) * I - spow * c / (2.0 * p);
        spow *= s * s;
        if (p >= 2) {
            int j = p - 2;
            if (j > 0) { coef *= (j + 0.5) / j; mj *= m; }
            sum += coef * mj * I;
        }
    }
    return sum;
}

int el__modulus_init(double k, int with_dk, el__modulus *mod)
{
    if (!mod || !isfinite(k) || k < 0.0) return EL_EINVAL;
    const double kg = k <= 1.0 ? k : 1.0 / k; /* the modulus the core sees */
    mod->k = k;
    mod->kg = kg;
    /* (k - 1)(k + 1) would overflow for k > 1e154 */
    mod->kp = k <= 1.0 ? sqrt((1.0 - k) * (1.0 + k)) : sqrt(k - 1.0) * sqrt(k + 1.0) / k;
    mod->K = mod->Dc = mod->Jc = INFINITY;
    if (!with_dk) mod->Jc = NAN;
    if (kg < 1.0) {
        /* k'^2 from kp keeps its relative accuracy as k -> 1, where 1 - k*k would
         * not (GSL's Kcomp forms 1 - k*k itself); K and D over the quarter period
         * [0, pi/2] of the amplitude by the AGM, J = R_D(0, 1, k'^2) / 3 */
        const double kp2 = mod->kp * mod->kp;
        if (el__ellint_complete(kg, kp2, &mod->K, &mod->Dc) ||
            (with_dk && carlson_rd(0.0, 1.0, kp2, &mod->Jc)))
            return EL_EDOM; /* not reached: 0 < kp2 <= 1 */
        if (with_dk) mod->Jc /= 3.0;
    }
    return EL_OK;
}

/*
 * sn, cn, dn for 0 <= k < 1 and |u| <= 1 (jacobi_reduced's range) by the
 * arithmetic-geometric mean and the descending Landen transformation in Bulirsch's form
 * (Numerical Recipes 3rd ed., sncndn; R. Bulirsch, Numer. Math. 7 (1965) 78): the AGM
 * a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n) from a_0 = 1, b_0 = k' (the
 * complementary modulus comes in exactly: GSL's gsl_sf_elljac_e takes only m = k^2 and
 * forms 1 - m itself, which near k = 1 loses half the digits of k'^2, 1e-13 errors at
 * |u| ~ 10, k = 1 - 1e-6), then the amplitude's cotangent carried back through the
 * levels by products and one division each, where the textbook recurrence
 * phi_{n-1} = (phi_n + asin(c_n/a_n sin phi_n))/2 (A&S 16.4.3) takes an asin and a sin
 * per level (six of each per call: the end-residual check of every Hermite solution
 * spent 4 % of the tension solve's time in them). The AGM stops at |a - b| <= 1e-8 a,
 * its limit then exact to rounding (quadratic convergence). |u| < 1e-9: the Maclaurin
 * series to u^3 (the next terms are below rounding), where the cotangent would overflow.
 */
static void jacobi_agm(double u, double k, double kp, double *sn, double *cn, double *dn)
{
    enum { NMAX = 16 };
    if (fabs(u) < 1e-9) {
        const double u2 = u * u;
        *sn = u * (1.0 - (1.0 + k * k) * u2 / 6.0);
        *cn = 1.0 - 0.5 * u2;
        *dn = 1.0 - 0.5 * k * k * u2;
        return;
    }
    double am[NMAX + 1], bm[NMAX + 1], a = 1.0, b = kp, c = 1.0;
    int n = 0;
    while (n < NMAX) {
        am[n] = a;
        bm[n] = b;
        n++;
        c = 0.5 * (a + b);
        if (fabs(a - b) <= 1e-8 * a) break;
        b = sqrt(a * b);
        a = c;
    }
    u *= c;
    const double s = sin(u);
    double cot = cos(u) / s, d = 1.0, w = c * cot;
    for (int j = n - 1; j >= 0; j--) {
        cot *= w;
        w *= d;
        d = (bm[j] + cot) / (am[j] + cot);
        cot = w / am[j];
    }
    const double r = 1.0 / sqrt(w * w + 1.0);
    *sn = s >= 0.0 ? r : -r;
    *cn = w * *sn;
    /* 1 - k^2 sn^2 as a sum of squares, consistent with sn and cn to rounding (the
     * recurrence's own d agrees only to its accuracy: 3e-15 off the identity on the
     * plateau near k = 1, which the doublings and theta = 2 atan2(k sn, dn) inherit) */
    *dn = sqrt(*cn * *cn + kp * kp * *sn * *sn);
}

/*
 * sn, cn, dn and D at |x| <= K/2 (0 <= k < 1). Near k = 1 that interval holds a
 * plateau where sn ~ 1 and cn ~ dn ~ 2 e^-|x| are tiny; there the AGM's last
 * asin(c/a sin phi) sits next to 1 and loses cn's relative digits (4e-10 at
 * |k| = 1 +- 1e-15, x = 9), and R_D(cn^2, dn^2, 1) with them D's (4e-10). So the AGM
 * and R_D run at x / 2^j <= 1, and j duplications, in forms whose terms share a sign
 * while |2v| <= K/2 (cn^2 - k' sn^2 >= 0 up to 2v = K), carry the values up:
 *   den = cn^2 (1 + sn^2) + k'^2 sn^4 (= 1 - k^2 sn^4),  sn(2v) = 2 sn cn dn / den,
 *   cn(2v) = (cn^2 - k' sn^2)(cn^2 + k' sn^2) / den,  dn(2v) = (cn^2 dn^2 + k'^2 sn^2) / den,
 *   D(2v) = 2 D(v) + sn^2 sn(2v)   (the addition theorems at a = b = v).
 * Each doubles the relative error, as a phase error would: ~|x| eps in all.
 * For k <= 0.8, K/2 < 1 and nothing is doubled.
 */
static int jacobi_reduced(const el__modulus *mod, double x, double *sn, double *cn, double *dn, double *D)
{
    const double kp = mod->kp, kp2 = kp * kp;
    double s, c, d, Dv, v = x;
    int j = 0, st;
    while (fabs(v) > 1.0) { v *= 0.5; j++; } /* exact */
    jacobi_agm(v, mod->kg, kp, &s, &c, &d);
    if ((st = carlson_rd(c * c, d * d, 1.0, &Dv))) return st;
    Dv *= s * s * s / 3.0;
    for (; j > 0; j--) {
        const double s2 = s * s, c2 = c * c, den = c2 * (1.0 + s2) + kp2 * s2 * s2;
        const double ns = 2.0 * s * c * d / den;
        c = (c2 - kp * s2) * (c2 + kp * s2) / den;
        d = (c2 * d * d + kp2 * s2) / den;
        Dv = 2.0 * Dv + s2 * ns;
        s = ns;
    }
    *sn = s; *cn = c; *dn = d; *D = Dv;
    return EL_OK;
}

/*
 * Core for 0 <= k = mod->kg <= 1. Fills val (all fields) and, if dk != NULL,
 * the k-derivatives at fixed u of sn, cn, dn, am, D, E.
 */
static int jacobi_le1(const el__modulus *mod, double u, el_jacobi *val, el_jacobi *dk, int want_am)
{
    const double k = mod->kg, m = k * k;
    double sn, cn, dn, phi, D, nhalf = 0.0; /* nhalf: number of half periods 2K removed */
    double sr, cr, dr;                      /* sn, cn, dn of the reduced argument */
    int st;

    if (k == 1.0) {
        sn = tanh(u);
        cn = dn = 1.0 / cosh(u);
        phi = atan(sinh(u));
        D = u - sn;
        sr = sn; cr = cn; dr = dn;
    } else {
        nhalf = nearbyint(u / (2.0 * mod->K));
        double r = fma(-nhalf, 2.0 * mod->K, u); /* one rounding */
        if (fabs(r) <= 0.5 * mod->K) {
            if ((st = jacobi_reduced(mod, r, &sn, &cn, &dn, &D))) return st;
        } else {
            /* GSL and R_D lose digits near m = 1 for arguments close to K: use the
             * quarter-period shift with the smaller x = K - |r|,
             *   sn(K-x) = cd x, cn(K-x) = k' sd x, dn(K-x) = k' nd x,
             *   D(K-x) = D(K) - D(x) - sn x cd x   (addition theorem for D). */
            double s, c, d, Dx, kp = mod->kp;
            if ((st = jacobi_reduced(mod, mod->K - fabs(r), &s, &c, &d, &Dx))) return st;
            sn = copysign(c / d, r);
            cn = kp * s / d;
            dn = kp / d;
            D = copysign(mod->Dc - Dx - s * c / d, r);
        }
        sr = sn; cr = cn; dr = dn;
        /* |r| <= K so cn >= 0: phi in [-pi/2, pi/2]; not wanted (el__jacobi_values): 0, a
         * finite placeholder (the k-derivatives need it) */
        phi = want_am || dk ? atan2(sn, cn) : 0.0;
        if (nhalf != 0.0) {
            D += nhalf * 2.0 * mod->Dc;
            if (fmod(nhalf, 2.0) != 0.0) { sn = -sn; cn = -cn; }
            phi += nhalf * M_PI;
        }
    }
    if (dk && k == 1.0) {
        /* the first order in k'^2 of A&S 16.15.1-4 with d(k'^2)/dk = -2, and its
         * integral for D: closed forms where J below would underflow (|u| > 350) */
        const double th = sn, sh = sinh(u), usech = u * cn;
        dk->am = -0.5 * (sh - usech);
        dk->sn = -0.5 * (th - usech * cn);
        dk->cn = 0.5 * th * (sh - usech);
        dk->dn = -0.5 * th * (sh + usech);
        dk->D = -1.5 * D + 0.5 * u * th * th;
        dk->E = -2.0 * D - dk->D;
    } else if (dk) {
        /* J over the reduced amplitude, plus whole half periods */
        double J;
        if ((st = carlson_rd(cr * cr, 1.0, dr * dr, &J))) return st;
        J *= sr * sr * sr / 3.0;
        if (nhalf != 0.0) J += nhalf * 2.0 * mod->Jc;
        double am_k = -k * dn * J;
        dk->am = am_k;
        dk->sn = cn * am_k;
        dk->cn = -sn * am_k;
        /* dn = sqrt(1 - k^2 sin^2 phi): -k sin^2/Delta + k^3 sin cos J */
        dk->dn = (dn > 0.0 ? -k * sn * sn / dn : -INFINITY) + m * k * sn * cn * J;
        if (k == 0.0) dk->dn = 0.0;
        /* dD/dk = k (L - sn^2 J) = (J dn^2 - D) / k: the first form with the series of
         * L for small k (where the second cancels to k^2), the second elsewhere (on
         * the plateau sn ~ 1 near k = 1, J ~ 1/(2 dn^2) is huge and L - sn^2 J
         * would cancel to eps J: 1e-3 at k = 1, u = 15) */
        dk->D = k < SMALL_K ? k * (small_k_L(phi, k) - sn * sn * J) : (J * dn * dn - D) / k;
        dk->E = -2.0 * k * D - m * dk->D;
    }
    val->sn = sn; val->cn = cn; val->dn = dn; val->am = phi; val->D = D;
    val->E = k == 1.0 ? sn : u - m * D; /* at k = 1, E = tanh u without cancellation */
    return EL_OK;
}

static int jacobi_eval(const el__modulus *mod, double u, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk,
                       int want_am)
{
    if (!val || !isfinite(u)) return EL_EINVAL;
    const double k = mod->k;
    el_jacobi v, dk;
    int st;
    if (k != 1.0 && (k > 1.0 ? k : 1.0) * fabs(u) > EL__PHASE_MAX) return EL_EDOM;
    if (k <= 1.0) {
        if ((st = jacobi_le1(mod, u, &v, d_dk ? &dk : NULL, want_am))) return st;
    } else {
        /* reciprocal modulus: f(u, k) = g(ku, 1/k) */
        const double kr = mod->kg, w = k * u;
        el_jacobi g, gk;
        if ((st = jacobi_le1(mod, w, &g, d_dk ? &gk : NULL, 0))) return st;   /* g.am unused */
        v.sn = g.sn * kr;
        v.cn = g.dn;
        v.dn = g.cn;
        v.D = g.D * kr * kr * kr;
        v.E = u - g.D * kr;
        v.am = want_am ? atan2(v.sn, v.cn) : 0.0;
        if (d_dk) {
            /* d/dk g(ku, 1/k) = u g_w - g_kr / k^2, with g_w from the u-identities */
            const double kr2 = kr * kr;
            double gsn_w = g.cn * g.dn, gcn_w = -g.sn * g.dn, gdn_w = -kr2 * g.sn * g.cn;
            double gD_w = g.sn * g.sn;
            dk.sn = (u * gsn_w - gk.sn * kr2) * kr - g.sn * kr2;
            dk.cn = u * gdn_w - gk.dn * kr2;
            dk.dn = u * gcn_w - gk.cn * kr2;
            dk.D = (u * gD_w - gk.D * kr2) * kr2 * kr - 3.0 * g.D * kr2 * kr2;
            dk.E = -2.0 * k * v.D - k * k * dk.D;
            dk.am = v.cn * dk.sn - v.sn * dk.cn;
        }
    }
    /* k-derivatives overflow at k = 1 beyond |u| ~ 700 (d cn/dk ~ e^|u| / 4 there) and
     * for k > 1e154 (k^2 D); values never, but check them too */
    /* isfinite inline, not el__all_finite's call over an array (every evaluation) */
    if (!(isfinite(v.sn) && isfinite(v.cn) && isfinite(v.dn) && isfinite(v.am) && isfinite(v.D) && isfinite(v.E)))
        return EL_EDOM;
    if (d_dk) {
        const double der[6] = {dk.sn, dk.cn, dk.dn, dk.am, dk.D, dk.E};
        if (el__all_finite(der, 6)) return EL_EDOM;
        *d_dk = dk;
    }
    if (d_du) {
        d_du->sn = v.cn * v.dn;
        d_du->cn = -v.sn * v.dn;
        d_du->dn = -k * (k * v.sn) * v.cn; /* k sn is bounded by 1: no overflow */
        d_du->am = v.dn;
        d_du->E = v.dn * v.dn;
        d_du->D = v.sn * v.sn;
    }
    /* am finite whenever sn, cn are (atan2 of finite values plus whole half periods,
     * or atan(sinh u)): its placeholder changes no status above */
    if (!want_am) v.am = NAN;
    *val = v;
    return EL_OK;
}

int el__jacobi_eval_mod(const el__modulus *mod, double u, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk)
{
    return jacobi_eval(mod, u, val, d_du, d_dk, 1);
}

int el__jacobi_values(const el__modulus *mod, double u, el_jacobi *val)
{
    return jacobi_eval(mod, u, val, NULL, NULL, 0);
}

int el_jacobi_eval(double u, double k, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk)
{
    el__modulus mod;
    if (!val || !isfinite(u)) return EL_EINVAL;
    int st = el__modulus_init(k, d_dk != NULL, &mod);
    return st ? st : el__jacobi_eval_mod(&mod, u, val, d_du, d_dk);
}
