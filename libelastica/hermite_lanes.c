/*
 * The objective of the x chart (hermite_objective.c's el__hermite_x_objective) at two
 * abscissae at once: the bracketing samples of a piece (hermite_tension.c) are known
 * before any is evaluated and are independent of each other. One evaluation is a chain
 * of square roots and divisions (the curvature data (19), |F|, the half angles at both
 * ends, the amplitude difference, its reduction, Carlson's duplication) whose latency is
 * its cost; two side by side (lanes.h) share each SSE2 operation. Every lane's operations
 * are the scalar evaluation's in the same order (no contraction, no reassociation), its
 * branches taken lane by lane as selections: the same bits (test_hermite_tension.c
 * compares them). A pair whose lanes need both kinds of curve (inflectional and not),
 * and case 3, are left to the scalar evaluation.
 */
#include "hermite_internal.h"
#include "lanes.h"

/* hermite_objective.c's half_angle in both lanes: sin and cos of atan2(S, C) / 2; its
 * 1 + C iR (C >= 0) and 1 - C iR (C < 0) are both 1 + |C| iR, bit for bit */
static void half_angles(el_d2 S, el_d2 C, el_d2 iR, el_d2 *sh, el_d2 *ch)
{
    const el_m2 pos = C >= 0.0;
    const el_d2 q = el_d2_sqrt(0.5 * (1.0 + el_d2_abs(C) * iR));
    const el_d2 sn = el_d2_sel(S >= 0.0, q, -q);      /* C < 0: the sine (times +-1 exactly) */
    const el_d2 o = 0.5 * S * iR / el_d2_sel(pos, q, sn);
    *sh = el_d2_sel(pos, o, sn);
    *ch = el_d2_sel(pos, q, o);
}

/* hermite_objective.c's amp_reduce in both lanes: at most two halvings of U (where the
 * amplitude is beyond pi/2), the second where big; S, C in, the reduced sine out in *S,
 * Carlson's x and y, mult and acc. */
static void amp_reduce2(el_d2 *S, el_d2 C, el_m2 big, el_d2 k2, el_d2 kc2, el_d2 *x, el_d2 *y, el_d2 *mult,
                        el_d2 *acc)
{
    el_d2 s = *S, X = C * C, mu = {1.0, 1.0}, ac = {0.0, 0.0};
    el_m2 act = el_m2_or(el_m2_or(big, C < 0.0), s < 0.0);
    for (int pass = 0; pass < 2 && el_m2_any(act); pass++) {
        const el_m2 cp = C > 0.0;
        const el_d2 dn = el_d2_sqrt(kc2 + k2 * X), q = el_d2_sel(cp, 1.0 + C, dn - C);
        const el_d2 inv = 1.0 / ((1.0 + dn) * q);
        const el_d2 s2 = el_d2_sel(cp, s * s * inv, (1.0 - C) * q * inv);
        const el_d2 c2 = el_d2_sel(C < 0.0, kc2 * s * s * inv, (dn + C) * q * inv);
        ac = el_d2_sel(act, ac + mu * s2 * s, ac);
        mu = el_d2_sel(act, mu * 2.0, mu);
        s = el_d2_sel(act, el_d2_sqrt(s2), s);
        X = el_d2_sel(act, c2, X);
        /* big: U/2 in (K, 2K], halved once more (unless c2 = 0, the loop's test) */
        C = el_d2_sel(act, -el_d2_sqrt(c2), C);
        act = pass == 0 ? el_m2_and(el_m2_and(act, big), el_m2_or(C < 0.0, s < 0.0)) : (el_m2){0, 0};
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
EL__INLINE el_m2 state2(const hprob *pr, el_d2 x, int b, el_d2 *k1o, el_d2 *k1po, el_d2 *F1o, el_d2 *F2o,
                    el_d2 *Fno, el_m2 *inflo)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    const el_d2 w = x * x - s, C = 0.5 * w * P1 + x, A = x * x * V2 + s * (1.0 - V2);
    el_d2 k1, k0p;
    el_m2 bad = {0, 0};
    if (pr->hcase == 2) {
        k1 = C;                                           /* (21) */
        k0p = (A - C * C) * pr->i2V1;                     /* (22) */
    } else {
        const el_d2 c0 = 2.0 * V1 * C + A * P2;
        const el_d2 disc = V1 * V1 + P2 * c0;             /* (18) */
        bad = disc < 0.0;
        const el_d2 sq = el_d2_sqrt(disc);
        /* (19), the branch's cancellation-free form (V1's sign is the problem's) */
        if (b == 0) k1 = V1 > 0.0 ? c0 / (V1 + sq) : (-V1 + sq) * pr->iP2;
        else        k1 = V1 < 0.0 ? c0 / (V1 - sq) : (-V1 - sq) * pr->iP2;
        k0p = fabs(V1) > fabs(P2) ? (A - k1 * k1) * pr->i2V1 : (k1 - C) * pr->iP2;   /* (20) */
    }
    *k1o = k1;
    *k1po = k0p * V2 + 0.5 * (x * x - s) * V1;            /* (14) */
    /* el__hermite_state_class */
    const el_d2 F1 = -2.0 * k0p, F2 = x * x - s, Fn = el_d2_sqrt(F1 * F1 + F2 * F2);
    const el_m2 infl = Fn > s;
    *F1o = F1;
    *F2o = F2;
    *Fno = Fn;
    *inflo = infl;
    const el_m2 good = el_m2_and(el_m2_and(el_m2_and(el_d2_finite(k1), el_d2_finite(k0p)),
                                           el_m2_and(Fn > 1e-13 * (1.0 + fabs(s)), Fn + s > 0.0)),
                                 el_m2_or(infl, x * k1 > 0.0));
    return el_m2_or(bad, el_m2_andnot(good, (el_m2){-1, -1}));
}

/* The objective at the lanes' x (cases 1 and 2) into f; 0 where the pair is left to the
 * scalar evaluation (an inflectional and a non-inflectional lane). */
EL__INLINE int objective2(const hprob *pr, el_d2 x, int b, double qs, el_d2 *f)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2;
    el_d2 k1, k1p, F1, F2, Fn;
    el_m2 infl;
    const el_m2 bad = state2(pr, x, b, &k1, &k1p, &F1, &F2, &Fn, &infl);
    const el_m2 ni = el_m2_andnot(bad, infl), nn = el_m2_andnot(el_m2_or(bad, infl), (el_m2){-1, -1});
    if (el_m2_any(ni) && el_m2_any(nn)) return 0;
    const int inflectional = el_m2_any(ni);
    /* shape_prepare: the modulus, the half angles at both ends, the amplitude difference */
    const el_d2 km2 = Fn + s, sep = Fn - s, i2F = 0.5 / Fn, k2 = km2 * i2F, kc2 = sep * i2F;
    const el_d2 rmu = el_d2_sqrt(0.5 * Fn), S1 = -2.0 * k1p, C1 = k1 * k1 - s;
    el_d2 sh0, ch0, sh1, ch1;
    half_angles(F1, F2, 2.0 * i2F, &sh0, &ch0);
    half_angles(S1, C1, 1.0 / el_d2_sqrt(S1 * S1 + C1 * C1), &sh1, &ch1);
    el_d2 sa0, ca0, da0, sa1, ca1, da1, m, mc;
    if (inflectional) {
        /* sn, cn, dn of u at both ends */
        const el_d2 ikm = 1.0 / el_d2_sqrt(km2), ik = 2.0 * rmu * ikm;
        sa0 = sh0 * ik; ca0 = x * ikm; da0 = ch0;
        sa1 = sh1 * ik; ca1 = k1 * ikm; da1 = ch1;
        m = k2;
        mc = kc2;
    } else {
        /* amplitudes of v = k u for the modulus 1/k, mirrored by the sign of kappa */
        const el_d2 eps = el_d2_sel(x > 0.0, (el_d2){1.0, 1.0}, (el_d2){-1.0, -1.0}), km = el_d2_sqrt(km2);
        m = 2.0 * Fn / km2;
        mc = -sep / km2;
        sa0 = eps * sh0; ca0 = ch0; da0 = el_d2_abs(x) / km;
        sa1 = eps * sh1; ca1 = ch1; da1 = el_d2_abs(k1) / km;
    }
    /* amplitude_difference (DLMF 22.8.1-3) */
    const el_d2 iden = 1.0 / (da0 * da0 + m * sa0 * sa0 * ca1 * ca1);
    el_d2 smu = (sa1 * ca0 * da0 - sa0 * ca1 * da1) * iden;
    el_d2 cmu = (ca1 * ca0 + sa1 * sa0 * da1 * da0) * iden;
    const el_d2 prod_before = sa1 * sa0 * smu;
    smu = el_d2_sel(el_m2_and(cmu > 0.0, el_d2_abs(smu) <= 1e-14), (el_d2){0.0, 0.0}, smu);   /* WHOLE_PERIOD */
    const el_m2 wrap = el_m2_or(smu < 0.0, el_m2_and(smu == 0.0, cmu > 0.0));
    el_d2 prod, Lscale, Escale, Dfac;
    el_m2 big;
    if (inflectional) {
        big = wrap;
        prod = sa1 * sa0 * smu;
        Lscale = 1.0 / rmu;
        Escale = km2 * Lscale;
        Dfac = (el_d2){1.0, 1.0};
    } else {
        /* sin mu >= 0 fixes the common sign; the product is the same for either */
        big = (el_m2){0, 0};
        smu = el_d2_sel(wrap, -smu, smu);
        cmu = el_d2_sel(wrap, -cmu, cmu);
        prod = prod_before;
        Lscale = 1.0 / (el_d2_sqrt(k2) * rmu);
        Escale = km2 * Lscale;
        Dfac = m;
    }
    el_d2 cx, cy, mult, acc, rf, rd;
    el_m2 ok;
    amp_reduce2(&smu, cmu, big, m, mc, &cx, &cy, &mult, &acc);
    el__carlson_fd2(cx, cy, qs, &rf, &rd, &ok);
    /* amp_fd and shape_finish: F = u1 - u0 (or v1 - v0), D; L, E and f (12) */
    const el_d2 F = mult * smu * rf, D = mult * smu * smu * smu * rd / 3.0 + acc;
    const el_d2 L = Lscale * F, E = Escale * (F - Dfac * (D + prod));
    const el_d2 v = (E - s * L - (F1 * P1 + F2 * P2)) * (2.0 * i2F);
    ok = el_m2_and(ok, el_m2_andnot(bad, el_m2_and(el_m2_and(el_d2_finite(F), el_d2_finite(D)),
                                                  el_m2_and(el_d2_finite(v), L > 0.0))));
    *f = el_d2_sel(ok, v, (el_d2){NAN, NAN});
    return 1;
}

void el__hermite_x_objectives(const hprob *pr, const double *x, int n, int b, double qs, double *f)
{
    for (int i = 0; i < n; i += 2) {
        /* an odd count's last pair repeats its abscissa */
        const el_d2 xs = {x[i], x[i + 1 < n ? i + 1 : i]};
        el_d2 fs;
        if (pr->hcase != 3 && objective2(pr, xs, b, qs, &fs)) {
            f[i] = fs[0];
            if (i + 1 < n) f[i + 1] = fs[1];
        } else {
            for (int l = i; l < n && l < i + 2; l++) el__hermite_x_objective(pr, x[l], b, qs, f + l);
        }
    }
}


void el__hermite_sample_pieces(const hprob *pr, int b, const hpiece *pc, int np, int room, double qs, double *cosn,
                               double *xs, double *fs, int *off)
{
    double tx[HERMITE_GATHER_MAX], tf[HERMITE_GATHER_MAX];
    int idx[HERMITE_GATHER_MAX];
    for (int i = 0, o = 0; i < np; o += pc[i].ns + 1 + room, i++) {
        const double a = pc[i].a, w = pc[i].b - pc[i].a, eps = 1e-10 * w + 1e-14 * (fabs(a) + fabs(pc[i].b));
        const int ns = pc[i].ns;
        off[i] = w > 4.0 * eps ? o : -1;
        if (off[i] < 0) continue;
        /* cos(pi j / ns) by the Chebyshev recurrence c_{j+1} = 2 c_1 c_j - c_{j-1} */
        double c1;
        if (ns < HERMITE_NCOS) {
            if (isnan(cosn[ns])) cosn[ns] = cos(M_PI / ns);
            c1 = cosn[ns];
        } else {
            c1 = cos(M_PI / ns);
        }
        double cprev = c1, cj = 1.0, *x = xs + o;
        for (int j = 0; j <= ns; j++) {
            x[j] = a + w * 0.5 * (1.0 - cj);
            if (j == 0) x[j] = a + eps;
            if (j == ns) x[j] = pc[i].b - eps;
            const double cnext = 2.0 * c1 * cj - cprev;
            cprev = cj;
            cj = cnext;
        }
    }
    /* by kind: inflectional, non-inflectional, mixed (a pair of an inflectional and a
     * non-inflectional sample is evaluated one by one) */
    static const int kinds[3] = {CLASS_INFL, CLASS_NONINFL, CLASS_MIXED};
    for (int k = 0; k < 3; k++) {
        int n = 0;
        for (int i = 0; i < np; i++)
            if (off[i] >= 0 && pc[i].cls == kinds[k])
                for (int j = 0; j <= pc[i].ns; j++) idx[n++] = off[i] + j;
        if (!n) continue;
        for (int j = 0; j < n; j++) tx[j] = xs[idx[j]];
        el__hermite_x_objectives(pr, tx, n, b, qs, tf);
        for (int j = 0; j < n; j++) fs[idx[j]] = tf[j];
    }
}
