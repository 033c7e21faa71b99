/*
 * The objective of the x chart in LANES_W lanes (hermite_lanes.c: 2, SSE2;
 * hermite_lanes_avx2.c: 4, AVX): one text for both widths (lanes_generic.h). Every lane's
 * operations are el__hermite_x_objective's in the same order (no contraction, no
 * reassociation), its branches taken lane by lane as selections: the same bits.
 */
#include "lanes_generic.h"

/* hermite_objective.c's half_angle lane by lane: sin and cos of atan2(S, C) / 2; its
 * 1 + C iR (C >= 0) and 1 - C iR (C < 0) are both 1 + |C| iR, bit for bit */
static void half_angles(LV S, LV C, LV iR, LV *sh, LV *ch)
{
    const LM pos = C >= 0.0;
    const LV q = lv_sqrt(0.5 * (1.0 + lv_abs(C) * iR));
    const LV sn = lv_sel(S >= 0.0, q, -q);      /* C < 0: the sine (times +-1 exactly) */
    const LV o = 0.5 * S * iR / lv_sel(pos, q, sn);
    *sh = lv_sel(pos, o, sn);
    *ch = lv_sel(pos, q, o);
}

/* hermite_objective.c's amp_reduce lane by lane: at most two halvings of U (where the
 * amplitude is beyond pi/2), the second where big; S, C in, the reduced sine out in *S,
 * Carlson's x and y, mult and acc. */
static void amp_reduce_lanes(LV *S, LV C, LM big, LV k2, LV kc2, LV *x, LV *y, LV *mult,
                        LV *acc)
{
    LV s = *S, X = C * C, mu = LV1(1.0), ac = LV1(0.0);
    LM act = lm_or(lm_or(big, C < 0.0), s < 0.0);
    for (int pass = 0; pass < 2 && lm_any(act); pass++) {
        const LM cp = C > 0.0;
        const LV dn = lv_sqrt(kc2 + k2 * X), q = lv_sel(cp, 1.0 + C, dn - C);
        const LV inv = 1.0 / ((1.0 + dn) * q);
        const LV s2 = lv_sel(cp, s * s * inv, (1.0 - C) * q * inv);
        const LV c2 = lv_sel(C < 0.0, kc2 * s * s * inv, (dn + C) * q * inv);
        ac = lv_sel(act, ac + mu * s2 * s, ac);
        mu = lv_sel(act, mu * 2.0, mu);
        s = lv_sel(act, lv_sqrt(s2), s);
        X = lv_sel(act, c2, X);
        /* big: U/2 in (K, 2K], halved once more (unless c2 = 0, the loop's test) */
        C = lv_sel(act, -lv_sqrt(c2), C);
        act = pass == 0 ? lm_and(lm_and(act, big), lm_or(C < 0.0, s < 0.0)) : LM_NONE;
    }
    *S = s;
    *x = X;
    *y = kc2 + k2 * X;
    *mult = mu;
    *acc = ac;
}

/* The curvature data (el__hermite_curvdata, Theorem 6) at the lanes' x (cases 1 and 2)
 * and el__hermite_state_class's |F| and F: the lanes without a curve the objective covers
 * (CLASS_NONE) returned set, *infl set where the curve is inflectional. */
EL__INLINE LM state_lanes(const hprob *pr, LV x, int b, LV *k1o, LV *k1po, LV *F1o, LV *F2o,
                    LV *Fno, LM *inflo)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    const LV w = x * x - s, C = 0.5 * w * P1 + x, A = x * x * V2 + s * (1.0 - V2);
    LV k1, k0p;
    LM bad = LM_NONE;
    if (pr->hcase == 2) {
        k1 = C;                                           /* (21) */
        k0p = (A - C * C) * pr->i2V1;                     /* (22) */
    } else {
        const LV c0 = 2.0 * V1 * C + A * P2;
        const LV disc = V1 * V1 + P2 * c0;             /* (18) */
        bad = disc < 0.0;
        const LV sq = lv_sqrt(disc);
        /* (19), the branch's cancellation-free form (V1's sign is the problem's) */
        if (b == 0) k1 = V1 > 0.0 ? c0 / (V1 + sq) : (-V1 + sq) * pr->iP2;
        else        k1 = V1 < 0.0 ? c0 / (V1 - sq) : (-V1 - sq) * pr->iP2;
        k0p = fabs(V1) > fabs(P2) ? (A - k1 * k1) * pr->i2V1 : (k1 - C) * pr->iP2;   /* (20) */
    }
    *k1o = k1;
    *k1po = k0p * V2 + 0.5 * (x * x - s) * V1;            /* (14) */
    /* el__hermite_state_class */
    const LV F1 = -2.0 * k0p, F2 = x * x - s, Fn = lv_sqrt(F1 * F1 + F2 * F2);
    const LM infl = Fn > s;
    *F1o = F1;
    *F2o = F2;
    *Fno = Fn;
    *inflo = infl;
    const LM good = lm_and(lm_and(lm_and(lv_finite(k1), lv_finite(k0p)),
                                           lm_and(Fn > 1e-13 * (1.0 + fabs(s)), Fn + s > 0.0)),
                                 lm_or(infl, x * k1 > 0.0));
    return lm_or(bad, lm_andnot(good, LM_ALL));
}

/* The objective at the lanes' x (cases 1 and 2) into f; 0 where the pair is left to the
 * scalar evaluation (an inflectional and a non-inflectional lane). */
EL__INLINE int objective_lanes(const hprob *pr, LV x, int b, double qs, LV *f)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2;
    LV k1, k1p, F1, F2, Fn;
    LM infl;
    const LM bad = state_lanes(pr, x, b, &k1, &k1p, &F1, &F2, &Fn, &infl);
    const LM ni = lm_andnot(bad, infl), nn = lm_andnot(lm_or(bad, infl), LM_ALL);
    if (lm_any(ni) && lm_any(nn)) return 0;
    const int inflectional = lm_any(ni);
    /* shape_prepare: the modulus, the half angles at both ends, the amplitude difference */
    const LV km2 = Fn + s, sep = Fn - s, i2F = 0.5 / Fn, k2 = km2 * i2F, kc2 = sep * i2F;
    const LV rmu = lv_sqrt(0.5 * Fn), S1 = -2.0 * k1p, C1 = k1 * k1 - s;
    LV sh0, ch0, sh1, ch1;
    half_angles(F1, F2, 2.0 * i2F, &sh0, &ch0);
    half_angles(S1, C1, 1.0 / lv_sqrt(S1 * S1 + C1 * C1), &sh1, &ch1);
    LV sa0, ca0, da0, sa1, ca1, da1, m, mc;
    if (inflectional) {
        /* sn, cn, dn of u at both ends */
        const LV ikm = 1.0 / lv_sqrt(km2), ik = 2.0 * rmu * ikm;
        sa0 = sh0 * ik; ca0 = x * ikm; da0 = ch0;
        sa1 = sh1 * ik; ca1 = k1 * ikm; da1 = ch1;
        m = k2;
        mc = kc2;
    } else {
        /* amplitudes of v = k u for the modulus 1/k, mirrored by the sign of kappa */
        const LV eps = lv_sel(x > 0.0, LV1(1.0), LV1(-1.0)), km = lv_sqrt(km2);
        m = 2.0 * Fn / km2;
        mc = -sep / km2;
        sa0 = eps * sh0; ca0 = ch0; da0 = lv_abs(x) / km;
        sa1 = eps * sh1; ca1 = ch1; da1 = lv_abs(k1) / km;
    }
    /* amplitude_difference (DLMF 22.8.1-3) */
    const LV iden = 1.0 / (da0 * da0 + m * sa0 * sa0 * ca1 * ca1);
    LV smu = (sa1 * ca0 * da0 - sa0 * ca1 * da1) * iden;
    LV cmu = (ca1 * ca0 + sa1 * sa0 * da1 * da0) * iden;
    const LV prod_before = sa1 * sa0 * smu;
    smu = lv_sel(lm_and(cmu > 0.0, lv_abs(smu) <= 1e-14), LV1(0.0), smu);   /* WHOLE_PERIOD */
    const LM wrap = lm_or(smu < 0.0, lm_and(smu == 0.0, cmu > 0.0));
    LV prod, Lscale, Escale, Dfac;
    LM big;
    if (inflectional) {
        big = wrap;
        prod = sa1 * sa0 * smu;
        Lscale = 1.0 / rmu;
        Escale = km2 * Lscale;
        Dfac = LV1(1.0);
    } else {
        /* sin mu >= 0 fixes the common sign; the product is the same for either */
        big = LM_NONE;
        smu = lv_sel(wrap, -smu, smu);
        cmu = lv_sel(wrap, -cmu, cmu);
        prod = prod_before;
        Lscale = 1.0 / (lv_sqrt(k2) * rmu);
        Escale = km2 * Lscale;
        Dfac = m;
    }
    LV cx, cy, mult, acc, rf, rd;
    LM ok;
    amp_reduce_lanes(&smu, cmu, big, m, mc, &cx, &cy, &mult, &acc);
    LN(el__carlson_fd)(cx, cy, qs, &rf, &rd, &ok);
    /* amp_fd and shape_finish: F = u1 - u0 (or v1 - v0), D; L, E and f (12) */
    const LV F = mult * smu * rf, D = mult * smu * smu * smu * rd / 3.0 + acc;
    const LV L = Lscale * F, E = Escale * (F - Dfac * (D + prod));
    const LV v = (E - s * L - (F1 * P1 + F2 * P2)) * (2.0 * i2F);
    ok = lm_and(ok, lm_andnot(bad, lm_and(lm_and(lv_finite(F), lv_finite(D)),
                                                  lm_and(lv_finite(v), L > 0.0))));
    *f = lv_sel(ok, v, LV1(NAN));
    return 1;
}

/* The objective at the n abscissae x[0..n), LANES_W at a time; a group whose lanes need
 * both kinds of curve, or case 3, by the narrower evaluation (LANES_NARROWER: the scalar
 * one for two lanes, two lanes for four) */
void LN(el__hermite_x_objectives)(const hprob *pr, const double *x, int n, int b, double qs, double *f)
{
    for (int i = 0; i < n; i += LANES_W) {
        /* a short last group repeats its last abscissa */
        LV xs, fs;
        for (int l = 0; l < LANES_W; l++) xs[l] = x[i + l < n ? i + l : n - 1];
        if (pr->hcase != 3 && objective_lanes(pr, xs, b, qs, &fs)) {
            for (int l = 0; l < LANES_W && i + l < n; l++) f[i + l] = fs[l];
        } else {
            LANES_NARROWER(pr, x + i, n - i < LANES_W ? n - i : LANES_W, b, qs, f + i);
        }
    }
}

/* el__hermite_x_class at the n abscissae x[0..n) (cases 1 and 2), LANES_W at a time: the
 * class from state_lanes' masks (the same comparisons on the same values as curvdata and
 * state_class: CLASS_NONE where curvdata fails or state_class finds no curve) */
void LN(el__hermite_x_classes)(const hprob *pr, const double *x, int n, int b, int *cls)
{
    for (int i = 0; i < n; i += LANES_W) {
        LV xs, k1, k1p, F1, F2, Fn;
        LM infl;
        for (int l = 0; l < LANES_W; l++) xs[l] = x[i + l < n ? i + l : n - 1];
        const LM none = state_lanes(pr, xs, b, &k1, &k1p, &F1, &F2, &Fn, &infl);
        for (int l = 0; l < LANES_W && i + l < n; l++)
            cls[i + l] = none[l] ? CLASS_NONE : infl[l] ? CLASS_INFL : CLASS_NONINFL;
    }
}
