/*
 * One piece of an elastic spline (spline.c): the Hermite elastica of tension s
 * from (0, ta) to (dx, dy, tb) as the five parameters v = (phi, ln mu, k, q, L)
 * of a smooth elastica, with its residuals R, Jacobian J = dR/dv, the end
 * curvatures' gradients g0, g1 and the eliminated columns spline_chain.c's Newton
 * needs; the state (theta0, kappa0, kappa0', sigma, L) the steps are taken in;
 * the start of a piece (the linearised batten, or el_hermite_solve).
 *
 * Derivatives (u = sqrt(mu) s + q, w = sqrt(mu), the Jacobi functions at
 * modulus |k|, d/d|k| from el_jacobi_eval, identities d sn/du = cn dn,
 * d cn/du = -sn dn, dn^2 + k^2 sn^2 = 1 for every real k):
 *   a = (theta - phi)/2 = atan2(k sn, dn):  da/du = k cn,
 *       da/dk = dn (sn + |k| sn_|k|) - |k| sn dn_|k|;
 *   kappa = 2 k w cn:  d/dnu = kappa/2 - k w^2 s sn dn, d/dk = 2 w (cn + |k| cn_|k|),
 *       d/dq = -2 k w sn dn, d/ds = -2 k w^2 sn dn;
 *   kappa' = -2 k mu sn dn:  d/dk = -2 mu (sn dn + |k| (sn dn)_|k|),
 *       d/dq = -2 k mu cn (dn^2 - k^2 sn^2);
 *   theta(L) = phi + 2 a(u1): d/dnu = k cn w L, d/dq = 2 k cn, d/dL = kappa(L);
 *   gamma(L) = P + R(phi)(X, Y), X = (u1 - q - 2k^2 (D(u1) - D(q)))/w,
 *       Y = -2k (cn u1 - cn q)/w: d/dphi = R(phi)(-Y, X), d/dnu = R(phi)(L T - (X,Y))/2
 *       with T = (1 - 2k^2 sn^2, 2k sn dn)(u1) (the unit tangent in the frame), as
 *       el_smooth_jacobian (tests/c/test_spline.c compares every column with it
 *       and with finite differences, and the eliminated derivatives with Hermite
 *       solutions of perturbed data).
 * State -> parameters (piece_from_state): the force F_EL = (kappa^2 - sigma) T +
 * 2 kappa' N (spline.c) has |F_EL| = 2 mu along phi; k^2 = (|F_EL| + sigma) /
 * (2 |F_EL|) (|k| < 1 iff the curvature has zeros, seed 004 Theorem 2), and q
 * from the amplitude: sn q = sin a / k, cn q = kappa / (2 k sqrt(mu)) for |k| < 1,
 * |k| q = F(a | 1/|k|) for |k| > 1 (the reciprocal-modulus transformation).
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>

enum { PIECE_ITER = 40 };

/* A straight piece's least tension (units of 1/h^2; piece_from_state). */
static const double LINE_TENSION = 1e-4;

/* ------------------------------------------------------------------ one el__spiece */

/* theta - phi = 2a, the same branch as el_smooth_eval's: for |k| <= 1,
 * a = atan2(k sn, dn) in [-pi/2, pi/2]; for |k| > 1 a grows with u (a loop), and
 * is the value of atan2 within pi of j pi, j = the number of half periods
 * 2K(1/|k|) in |k| u (K_reciprocal = K(1/|k|)). */
static double half_angle(double u, double k, double K_reciprocal, const el_jacobi *v)
{
    const double ka = fabs(k), a = atan2(ka * v->sn, v->dn);
    if (!(ka > 1.0)) return copysign(1.0, k) * a;
    const double jpi = M_PI * nearbyint(ka * u / (2.0 * K_reciprocal)), d = a - jpi;
    return copysign(1.0, k) * (jpi + d - 2.0 * M_PI * nearbyint(d / (2.0 * M_PI)));
}

/* da/dk of a = atan2(k sn(u;|k|), dn(u;|k|)) (file comment). */
static double half_angle_dk(double k, const el_jacobi *v, const el_jacobi *vk)
{
    const double ka = fabs(k);
    return v->dn * (v->sn + ka * vk->sn) - ka * v->sn * vk->dn;
}

/* Residuals, end angles and curvatures of piece pc for the el__sptargets t; with jac,
 * also J, its LU and the eliminated columns D and coefficients c0, c1, cL. */
static int piece_eval_raw(el__spiece *pc, const el__sptargets *t, int jac, double *raw);

int el__spiece_eval(el__spiece *pc, const el__sptargets *t, int jac)
{
    return piece_eval_raw(pc, t, jac, NULL);
}

/* el__spiece_eval; raw (when not NULL, with jac): J before its factorisation, then
 * g0, g1 (35 values), for el__spline_piece_jacobians. */
static int piece_eval_raw(el__spiece *pc, const el__sptargets *t, int jac, double *raw)
{
    const double phi = pc->v[EL__SP_PHI], nu = pc->v[EL__SP_NU], k = pc->v[EL__SP_K], q = pc->v[EL__SP_Q],
                 L = pc->v[EL__SP_L];
    if (!isfinite(phi) || !isfinite(nu) || !isfinite(k) || !isfinite(q) || !isfinite(L) ||
        !(L > 0.0) || nu > 700.0 || nu < -700.0)
        return EL_EDOM;
    const double mu = exp(nu), w = sqrt(mu), ka = fabs(k), u1 = w * L + q;
    el__modulus mod;
    el_jacobi a0, a1, k0, k1;
    int st;
    if ((st = el__modulus_init(ka, jac, &mod))) return st;
    if ((st = el__jacobi_eval_mod(&mod, q, &a0, NULL, jac ? &k0 : NULL))) return st;
    if ((st = el__jacobi_eval_mod(&mod, u1, &a1, NULL, jac ? &k1 : NULL))) return st;
    const double c = cos(phi), sp = sin(phi), k2 = k * k;
    const double X = ((u1 - q) - 2.0 * k2 * (a1.D - a0.D)) / w, Y = -2.0 * k * (a1.cn - a0.cn) / w;
    const double gx = c * X - sp * Y - pc->dx, gy = sp * X + c * Y - pc->dy;
    const double h = pc->h, h2 = h * h;
    pc->th0 = phi + 2.0 * half_angle(q, k, mod.K, &a0);
    pc->th1 = phi + 2.0 * half_angle(u1, k, mod.K, &a1);
    pc->kap0 = 2.0 * k * w * a0.cn;
    pc->kap1 = 2.0 * k * w * a1.cn;
    pc->dkap0 = -2.0 * k * mu * a0.sn * a0.dn;
    pc->energy = 4.0 * k2 * w * ((u1 - q) - (a1.D - a0.D));   /* el_smooth_energy */
    pc->Kq = mod.K;
    pc->st[0] = pc->th0;
    pc->st[1] = pc->kap0;
    pc->st[2] = pc->dkap0;
    pc->st[3] = 2.0 * mu * (2.0 * k2 - 1.0);
    pc->st[4] = L;
    pc->R[0] = gx / h;
    pc->R[1] = gy / h;
    pc->R[2] = pc->th0 - t->ta;
    pc->R[3] = pc->th1 - t->tb;
    pc->R[4] = (2.0 * mu * (2.0 * k2 - 1.0) - t->s) * h2;
    for (int i = 0; i < EL__NV; i++)
        if (!isfinite(pc->R[i])) return EL_EDOM;
    if (!jac) return EL_OK;
    pc->jac_ok = 0;   /* D, c0, c1, cL about to change: current again only at the end */

    const double tx = 1.0 - 2.0 * k2 * a1.sn * a1.sn, ty = 2.0 * k * a1.sn * a1.dn;
    double lx[EL__NV], ly[EL__NV];   /* d(X, Y)/dv in the frame; phi column apart */
    lx[EL__SP_PHI] = -Y; ly[EL__SP_PHI] = X;
    lx[EL__SP_NU] = 0.5 * (L * tx - X); ly[EL__SP_NU] = 0.5 * (L * ty - Y);
    lx[EL__SP_K] = (-4.0 * k * (a1.D - a0.D) - 2.0 * k * ka * (k1.D - k0.D)) / w;
    ly[EL__SP_K] = (-2.0 * (a1.cn - a0.cn) - 2.0 * ka * (k1.cn - k0.cn)) / w;
    lx[EL__SP_Q] = -2.0 * k2 * (a1.sn * a1.sn - a0.sn * a0.sn) / w;
    ly[EL__SP_Q] = 2.0 * k * (a1.sn * a1.dn - a0.sn * a0.dn) / w;
    lx[EL__SP_L] = tx; ly[EL__SP_L] = ty;
    double J[EL__NV * EL__NV];
    for (int j = 0; j < EL__NV; j++) {
        J[0 * EL__NV + j] = (c * lx[j] - sp * ly[j]) / h;
        J[1 * EL__NV + j] = (sp * lx[j] + c * ly[j]) / h;
    }
    const double sd0 = a0.sn * a0.dn, sd1 = a1.sn * a1.dn;
    const double th0[EL__NV] = {1.0, 0.0, 2.0 * half_angle_dk(k, &a0, &k0), 2.0 * k * a0.cn, 0.0};
    const double th1[EL__NV] = {1.0, k * a1.cn * w * L, 2.0 * half_angle_dk(k, &a1, &k1),
                            2.0 * k * a1.cn, pc->kap1};
    const double g0[EL__NV] = {0.0, 0.5 * pc->kap0, 2.0 * w * (a0.cn + ka * k0.cn),
                           -2.0 * k * w * sd0, 0.0};
    const double g1[EL__NV] = {0.0, 0.5 * pc->kap1 - k * mu * L * sd1, 2.0 * w * (a1.cn + ka * k1.cn),
                           -2.0 * k * w * sd1, -2.0 * k * mu * sd1};
    const double ten[EL__NV] = {0.0, 2.0 * mu * (2.0 * k2 - 1.0) * h2, 8.0 * mu * k * h2, 0.0, 0.0};
    /* kappa0' = -2 k mu sn dn (q): d/dk = -2 mu (sn dn + |k| (sn dn)_|k|), d/dq = -2 k mu cn (dn^2 - k^2 sn^2) */
    const double dk0[EL__NV] = {0.0, pc->dkap0,
                            -2.0 * mu * (sd0 + ka * (k0.sn * a0.dn + a0.sn * k0.dn)),
                            -2.0 * k * mu * a0.cn * (a0.dn * a0.dn - k2 * a0.sn * a0.sn), 0.0};
    for (int j = 0; j < EL__NV; j++) {
        pc->M[0 * EL__NV + j] = th0[j];
        pc->M[1 * EL__NV + j] = g0[j];
        pc->M[2 * EL__NV + j] = dk0[j];
        pc->M[3 * EL__NV + j] = ten[j] / h2;
        pc->M[4 * EL__NV + j] = j == EL__SP_L;
    }
    memcpy(J + 2 * EL__NV, th0, sizeof th0);
    memcpy(J + 3 * EL__NV, th1, sizeof th1);
    memcpy(J + 4 * EL__NV, ten, sizeof ten);

    if (raw) {
        memcpy(raw, J, sizeof J);
        memcpy(raw + EL__NV * EL__NV, g0, sizeof g0);
        memcpy(raw + EL__NV * EL__NV + EL__NV, g1, sizeof g1);
    }
    int perm[EL__NV];
    if (el__lu_factor(J, EL__NV, perm)) return EL_ESINGULAR;
    const int guided = pc->gn[0] != 0.0 || pc->gn[1] != 0.0;
    for (int r = 0; r < 4 + guided; r++) {
        double rhs[EL__NV] = {0};
        if (r == 0) memcpy(rhs, pc->R, sizeof rhs);
        else if (r == 4) { rhs[0] = pc->gn[0] / h; rhs[1] = pc->gn[1] / h; }
        else rhs[r + 1] = r == 3 ? h2 : 1.0;
        el__lu_solve(J, EL__NV, perm, rhs);
        memcpy(pc->D[r], rhs, sizeof rhs);
        double s0 = 0.0, s1 = 0.0;
        for (int i = 0; i < EL__NV; i++) { s0 += g0[i] * rhs[i]; s1 += g1[i] * rhs[i]; }
        pc->c0[r] = s0;
        pc->c1[r] = s1;
        pc->cL[r] = rhs[EL__SP_L];
        if (!isfinite(s0) || !isfinite(s1) || !isfinite(rhs[EL__SP_L])) return EL_ESINGULAR;
    }
    memcpy(pc->jv, pc->v, sizeof pc->jv);
    pc->jh = h;
    pc->jac_ok = 1;
    return EL_OK;
}

/* Compared rather than cleared by hand: v and h change in every file of the solver
 * (steps, snapshots, starts, continuation, guide chords), and a flag each of them had to
 * clear would go stale with the first new one. Bitwise (memcmp): equal values evaluate
 * to equal coefficients; a -0.0 for 0.0 only costs a re-evaluation. */
int el__spiece_jac_current(const el__spiece *pc)
{
    return pc->jac_ok && !memcmp(pc->jv, pc->v, sizeof pc->jv) && !memcmp(&pc->jh, &pc->h, sizeof pc->h);
}

double el__max_abs(const double *v, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

/* Incomplete elliptic integral of the first kind F(psi | k) for |psi| <= pi,
 * 0 <= k <= 1 with kc2 = 1 - k^2 given without cancellation: Carlson,
 * F = sin psi R_F(cos^2 psi, 1 - k^2 sin^2 psi, 1) on |psi| <= pi/2 and
 * F(psi) = 2K - F(pi - psi) beyond (ellint.c; GSL's gsl_sf_ellint_F costs
 * about twice as much). k = 1: |psi| < pi/2 only, F = asinh(tan psi). NaN outside. */
static double ellint_F(double psi, double k, double kc2)
{
    if (!(fabs(psi) <= M_PI)) return NAN;
    if (!(kc2 > 0.0)) return fabs(psi) < 0.5 * M_PI ? asinh(tan(psi)) : NAN;
    const double a = fabs(psi), r = a > 0.5 * M_PI ? M_PI - a : a, sn = sin(r), cs = cos(r);
    double rf, rd, K = 0.0, D;
    if (el__carlson_fd(cs * cs, kc2 + k * k * cs * cs, 1.0, 1.0, &rf, &rd)) return NAN;
    if (a > 0.5 * M_PI && el__ellint_complete(k, kc2, &K, &D)) return NAN;
    const double F = a > 0.5 * M_PI ? 2.0 * K - sn * rf : sn * rf;
    return copysign(F, psi);
}

/* ellint_F for |psi| < pi/2 given sin psi and cos psi > 0 (cos psi resolved near
 * pi/2, where psi itself is not): F = sin psi R_F(cos^2 psi, kc2 + k^2 cos^2 psi, 1). */
static double ellint_F_sc(double sn, double cs, double k, double kc2)
{
    double rf, rd;
    if (!(cs > 0.0) || el__carlson_fd(cs * cs, kc2 + k * k * cs * cs, 1.0, 1.0, &rf, &rd)) return NAN;
    return sn * rf;
}

/* Parameters of the elastica of tension s through a state (theta, kappa,
 * kappa') at arc length sm from the piece's start, the start at u = q. */
static int piece_from_state(el__spiece *pc, double theta, double kappa, double dkappa, double s,
                            double sm, double L)
{
    const double T[2] = {cos(theta), sin(theta)}, N[2] = {-T[1], T[0]};
    const double wv = kappa * kappa - s;
    double Fx = wv * T[0] + 2.0 * dkappa * N[0], Fy = wv * T[1] + 2.0 * dkappa * N[1];
    double Fn = hypot(Fx, Fy);
    /* Fn^2 - s^2 = P = kappa^2 (kappa^2 - 2 s) + 4 kappa'^2, so
     * 1 - k^2 = (Fn - s) / (2 Fn) = P / (2 Fn (Fn + s)) and k^2 = (Fn + s) / (2 Fn) =
     * P / (2 Fn (Fn - s)): the second forms without the cancellation of Fn - s
     * when s > 0 (under tension, near the separatrix) and of Fn + s when s < 0
     * (a nearly straight piece under compression, k -> 0) */
    const double P = kappa * kappa * (kappa * kappa - 2.0 * s) + 4.0 * dkappa * dkappa;
    double kc2 = s > 0.0 ? P / (2.0 * Fn * (Fn + s)) : (Fn - s) / (2.0 * Fn);
    double k2 = s < 0.0 ? P / (2.0 * Fn * (Fn - s)) : (Fn + s) / (2.0 * Fn);
    /* a circle or a line: a small force along -T. Its least size keeps |k| <~ 1e4,
     * where a circle is resolved best (the arc differs from it by ~1 / k^2, and
     * the position's cancellation grows as k^2 eps; el_hermite_solve's 1e4) */
    int line = 0, tail = 1;   /* tail: Fn, kc2 and k2 from the state itself */
    if (!(Fn > 1e-8 * (fabs(s) + kappa * kappa + 1e-300))) {
        tail = 0;
        Fn = 1e-8 * (fabs(s) + kappa * kappa) + 1e-12;
        Fx = -Fn * T[0];
        Fy = -Fn * T[1];
        kc2 = (Fn - s) / (2.0 * Fn);
        k2 = (Fn + s) / (2.0 * Fn);
        line = kc2 > 0.0;   /* kappa and s ~ 0 */
    }
    /* a line under little or no tension (F ~ 0, k^2 = 1/2 above: it cannot turn
     * theta pi/2 from phi, the start was pi/2 off) or a straight state (el__spiece_start
     * on a straight span) under a tension whose mu = s/2 the Jacobian does not resolve
     * (its columns grow as mu^-1/2 and swamp the length's; Newton stalls below
     * ~1e-6 / h^2): the separatrix's tail under LINE_TENSION / h^2, the same line;
     * Newton relaxes the tension (G2 ends bent from a straight free batten) */
    const double s_line = LINE_TENSION / (pc->h > 0.0 ? pc->h * pc->h : 1.0);
    if (line || (kappa == 0.0 && dkappa == 0.0 && s > 0.0 && s < s_line)) {
        tail = 0;
        Fn = s_line;
        Fx = -Fn * T[0];
        Fy = -Fn * T[1];
        kc2 = 0.0;
        k2 = 1.0;
    }
    if (!(k2 > 0.0) || !isfinite(k2)) return EL_EDOM;   /* k = 0: a straight piece, no q */
    const double mu = 0.5 * Fn, phi0 = atan2(Fy, Fx);
    k2 = kc2 > 0.0 ? fmin(k2, 1.0) : fmax(k2, 1.0);
    double d = theta - phi0;
    d -= 2.0 * M_PI * nearbyint(d / (2.0 * M_PI));
    const double a = 0.5 * d, phi = theta - 2.0 * a;   /* theta = phi + 2a exactly */
    double k, u;
    if (kc2 > 0.0) {
        k = sqrt(k2);
        const double psi = atan2(sin(a) / k, kappa / (2.0 * k * sqrt(mu)));
        u = ellint_F(psi, k, kc2);
        /* The same curve with u - 2K j and k -> (-1)^j k (sn, cn change sign over
         * 2K, dn does not: theta, kappa and gamma are unchanged): put the end
         * nearer a peak of |cn| (u = 0 mod 2K: the larger curvature) at u near 0.
         * There its curvature does not depend on K(k), which near the separatrix
         * a double's k resolves only to ~1e-16 / (1 - k^2) (so only there). */
        double K, Dk;
        if (kc2 < 1e-4 && el__ellint_complete(k, kc2, &K, &Dk) == EL_OK) {
            const double u0 = u - sqrt(mu) * sm, u1 = u0 + sqrt(mu) * L;
            const double j0 = nearbyint(u0 / (2.0 * K)), j1 = nearbyint(u1 / (2.0 * K));
            const double j = fabs(u0 - 2.0 * K * j0) <= fabs(u1 - 2.0 * K * j1) ? j0 : j1;
            u -= 2.0 * K * j;
            if (fmod(j, 2.0) != 0.0) k = -k;
        }
    } else {
        const double ka = sqrt(k2);
        k = kappa < 0.0 ? -ka : ka;
        /* far down the separatrix's tail (|a| within 1e-8 of pi/2: a nearly straight
         * piece under tension, kappa ~ 4 sqrt(mu) e^-|u|), u = asinh(tan a) depends on
         * pi/2 - |a| ~ kappa / (2 sqrt(mu)), which theta - phi0 resolves only to ~1e-16;
         * clamping it to 1e-8 put a bend there that grows e^{sqrt(mu) L} along the piece
         * (~1e12 at sigma h^2 = 1600): EL_ENOCONV. cos a from the state instead:
         * cos^2 a = (1 + cos 2a)/2 = (kappa^2 + P/(Fn + s)) / (2 Fn) (F.T = Fn cos 2a =
         * kappa^2 - s; Fn - s = P/(Fn + s)), to rounding relative to kappa^2 */
        const int far = tail && s > 0.0 && ka < 1.0 + 1e-12 && fabs(a) > 0.5 * M_PI - 1e-8;
        const double c2 = far ? (kappa * kappa + P / (Fn + s)) / (2.0 * Fn) : -1.0;
        if (c2 > 0.0) {
            const double ca = sqrt(c2), sa = copysign(sqrt(fmax(0.0, 1.0 - c2)), k < 0.0 ? -a : a);
            u = (!(ka > 1.0) ? asinh(sa / ca) : ellint_F_sc(sa, ca, 1.0 / ka, -kc2 / k2)) / ka;
        } else {
            /* k = 1 exactly: the separatrix, a = +-pi/2 is at u = infinity (a straight
             * state under tension); start a little inside, on its tail */
            const double am = ka < 1.0 + 1e-12 ? copysign(fmin(fabs(a), 0.5 * M_PI - 1e-8), a) : a;
            /* modulus 1/|k|: its complement 1 - 1/k^2 = -kc2 / k^2 */
            u = ellint_F(k < 0.0 ? -am : am, 1.0 / ka, -kc2 / k2) / ka;
        }
    }
    if (!isfinite(u)) return EL_EDOM;
    pc->v[EL__SP_PHI] = phi;
    pc->v[EL__SP_NU] = log(mu);
    pc->v[EL__SP_K] = k;
    pc->v[EL__SP_Q] = u - sqrt(mu) * sm;
    pc->v[EL__SP_L] = L;
    return EL_OK;
}

int el__spiece_set_state(el__spiece *pc, const double *st)
{
    /* no piece of length <= 0: a secant predictor past one (spline_continuation.c's predict)
     * ended a continuation on a chain through one, -2.05 long (QA16's ship line) */
    if (!(st[4] > 0.0)) return EL_EDOM;
    return piece_from_state(pc, st[0], st[1], st[2], st[3], 0.0, st[4]);
}

/*
 * One Newton step of a piece, taken from (v0, st0) along the parameter step dv
 * in its state: st0 + al M dv, converted back in closed form (piece_from_state).
 * The state is a regular coordinate of the pieces, where phi and mu are the
 * polar coordinates of the force, singular at a circle (F = 0, |k| -> infinity):
 * a straight step in (phi, ln mu, k, q, L) crosses it badly. Prepare ps from the
 * piece and dv; return the largest fraction al of the step that keeps the length
 * positive and the state within a factor of its size (in units of the chord).
 */
double el__spiece_step_prepare(const el__spiece *pc, const double *dv, el__spstep *ps, double al)
{
    memcpy(ps->v0, pc->v, sizeof ps->v0);
    memcpy(ps->s0, pc->st, sizeof ps->s0);
    for (int i = 0; i < EL__NV; i++) {
        double sum = 0.0;
        for (int j = 0; j < EL__NV; j++) sum += pc->M[i * EL__NV + j] * dv[j];
        ps->ds[i] = sum;
    }
    const double h = pc->h, *st = pc->st, *dst = ps->ds;
    const double lim[4] = {0.5, fmax(1.0, 2.0 * fabs(st[1]) * h) / h,
                           fmax(2.0, 2.0 * fabs(st[2]) * h * h) / (h * h),
                           fmax(4.0, 2.0 * fabs(st[3]) * h * h) / (h * h)};
    for (int i = 0; i < 4; i++)
        if (fabs(dst[i]) * al > lim[i]) al = lim[i] / fabs(dst[i]);
    if (dst[4] < 0.0 && -dst[4] * al > 0.75 * st[4]) al = 0.75 * st[4] / -dst[4];
    return al;
}

int el__spiece_step_apply(el__spiece *pc, const el__spstep *ps, double al)
{
    double sn[EL__NV];
    for (int i = 0; i < EL__NV; i++) sn[i] = ps->s0[i] + al * ps->ds[i];
    return el__spiece_set_state(pc, sn);
}

/* The piece alone (fixed el__sptargets): Newton on R, stepping in the state. */
int el__spiece_newton(el__spiece *pc, const el__sptargets *t, double tol)
{
    int st = el__spiece_eval(pc, t, 1);
    if (st) return st;
    double r = el__max_abs(pc->R, EL__NV);
    for (int it = 0; it < PIECE_ITER && r > tol; it++) {
        double dv[EL__NV];
        el__spstep ps;
        for (int i = 0; i < EL__NV; i++) dv[i] = -pc->D[0][i];
        double al = el__spiece_step_prepare(pc, dv, &ps, 1.0);
        int ok = 0;
        for (int hv = 0; hv <= EL__SP_HALVINGS; hv++, al *= 0.5) {
            if (el__spiece_step_apply(pc, &ps, al) || el__spiece_eval(pc, t, 1)) continue;
            const double rn = el__max_abs(pc->R, EL__NV);
            if (rn < (1.0 - 1e-4 * al) * r) { r = rn; ok = 1; break; }
        }
        if (!ok) {
            memcpy(pc->v, ps.v0, sizeof ps.v0);
            el__spiece_eval(pc, t, 1);
            break;
        }
    }
    return r <= tol ? EL_OK : EL_ENOCONV;
}

/* The two non-affine solutions f1, f2 of w'''' = (s/2) w'' and their
 * derivatives 0..3 at s: e^{-om s}, e^{-om (h - s)} under tension (om^2 = s/2),
 * cos, sin(om s) under compression (om^2 = -s/2), s^2, s^3 where om h is small. */
enum { BASIS_POLY, BASIS_EXP, BASIS_TRIG };
static void start_basis(int kind, double om, double h, double s, double b1[4], double b2[4])
{
    if (kind == BASIS_EXP) {
        const double e1 = exp(-om * s), e2 = exp(-om * (h - s));
        for (int d = 0; d < 4; d++) {
            b1[d] = e1 * pow(-om, d);
            b2[d] = e2 * pow(om, d);
        }
    } else if (kind == BASIS_TRIG) {
        const double c = cos(om * s), sn = sin(om * s), o2 = om * om;
        b1[0] = c; b1[1] = -om * sn; b1[2] = -o2 * c; b1[3] = o2 * om * sn;
        b2[0] = sn; b2[1] = om * c; b2[2] = -o2 * sn; b2[3] = -o2 * om * c;
    } else {
        b1[0] = s * s; b1[1] = 2.0 * s; b1[2] = 2.0; b1[3] = 0.0;
        b2[0] = s * s * s; b2[1] = 3.0 * s * s; b2[2] = 6.0 * s; b2[3] = 6.0;
    }
}

/* The linearised batten on the chord: w'''' = (s/2) w'' with w = 0 at both ends
 * and slopes tan(alpha), tan(beta); its midpoint state starts the piece. Under
 * compression near a span's clamped load (om h -> 2 pi) the bow it gives is
 * large for small end slopes, as the batten's. */
int el__spiece_start(el__spiece *pc, const el__sptargets *t)
{
    const double h = hypot(pc->dx, pc->dy), c0 = atan2(pc->dy, pc->dx);
    const double c = c0 + 2.0 * M_PI * nearbyint((0.5 * (t->ta + t->tb) - c0) / (2.0 * M_PI));
    const double al = t->ta - c, be = t->tb - c;
    const double sa = tan(fmax(fmin(al, 1.3), -1.3)), sb = tan(fmax(fmin(be, 1.3), -1.3));
    const double om = sqrt(0.5 * fabs(t->s));
    /* w = A + B s + C f1 + D f2 */
    const int kind = !(om * h > 0.1) ? BASIS_POLY : t->s > 0.0 ? BASIS_EXP : BASIS_TRIG;
    double M[16], rhs[4] = {0.0, 0.0, sa, sb};
    for (int e = 0; e < 2; e++) {
        const double s = e ? h : 0.0;
        double b1[4], b2[4];
        start_basis(kind, om, h, s, b1, b2);
        M[(0 + e) * 4 + 0] = 1.0; M[(0 + e) * 4 + 1] = s; M[(0 + e) * 4 + 2] = b1[0]; M[(0 + e) * 4 + 3] = b2[0];
        M[(2 + e) * 4 + 0] = 0.0; M[(2 + e) * 4 + 1] = 1.0; M[(2 + e) * 4 + 2] = b1[1]; M[(2 + e) * 4 + 3] = b2[1];
    }
    int perm[4];
    if (el__lu_factor(M, 4, perm)) return EL_ESINGULAR;
    el__lu_solve(M, 4, perm, rhs);
    /* state at the midpoint */
    const double sm = 0.5 * h;
    double wd[4], b1[4], b2[4];
    start_basis(kind, om, h, sm, b1, b2);
    for (int d = 0; d < 4; d++) wd[d] = rhs[2] * b1[d] + rhs[3] * b2[d];
    wd[1] += rhs[1];
    /* arc length ~ h + 1/2 int w'^2 (Simpson on the slopes) */
    const double L = h + h / 12.0 * (sa * sa + 4.0 * wd[1] * wd[1] + sb * sb);
    const double g = 1.0 + wd[1] * wd[1];
    const double theta = c + atan(wd[1]), kappa = wd[2] / pow(g, 1.5);
    const double dkappa = wd[3] / (g * g) - 3.0 * wd[1] * wd[2] * wd[2] / (g * g * g);
    /* targets along the chord to rounding (a rotated line: ~1e-16), not compressed: the
     * line (piece_from_state: the separatrix's tail), as an unrotated one; a bend of
     * 1e-16 put the piece far down the tail (u ~ 30, not 19), where its parameters do
     * not resolve the force (the G2 bend from it failed at tensions 0 to 3e-6) */
    const int line = fabs(al) <= 1e-12 && fabs(be) <= 1e-12 && t->s >= 0.0;
    return piece_from_state(pc, theta, line ? 0.0 : kappa, line ? 0.0 : dkappa, t->s, 0.5 * L, L);
}

/* The piece by el_hermite_solve: the least-energy solution with the turning tb - ta. */
int el__spiece_hermite(el__spiece *pc, const el__sptargets *t)
{
    const double p0[2] = {0.0, 0.0}, p1[2] = {pc->dx, pc->dy};
    const double t0[2] = {cos(t->ta), sin(t->ta)}, t1[2] = {cos(t->tb), sin(t->tb)};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = t->s;
    el_hermite_result r;
    int st = el_hermite_solve(p0, t0, p1, t1, &o, &r);
    if (st) return st;
    st = EL_ENOCONV;
    for (size_t i = 0; i < r.count; i++) {   /* sorted by energy */
        const el_smooth_params *p = &r.solutions[i].curve;
        double s2[2] = {0.0, p->length}, th[2];
        if (el_smooth_eval(p, 2, s2, NULL, th, NULL)) continue;
        const double shift = t->ta - th[0];
        if (fabs((th[1] - th[0]) - (t->tb - t->ta)) > 1e-6) continue;
        pc->v[EL__SP_PHI] = p->phi + shift;
        pc->v[EL__SP_NU] = log(p->mu);
        pc->v[EL__SP_K] = p->k;
        pc->v[EL__SP_Q] = p->q;
        pc->v[EL__SP_L] = p->length;
        st = EL_OK;
        break;
    }
    el_hermite_result_free(&r);
    return st;
}

/* internal.h: the piece's Jacobians and implicit derivatives, for the tests. */
int el__spline_piece_jacobians(const el_smooth_params *p, double *J, double *g0, double *g1,
                               double *M, double *d)
{
    if (el_smooth_check(p) || !(p->length > 0.0) || !J || !g0 || !g1 || !M || !d) return EL_EINVAL;
    el__gsl_quiet();
    const double s[2] = {0.0, p->length};
    double xy[4], th[2];
    int st = el_smooth_eval(p, 2, s, xy, th, NULL);
    if (st) return st;
    el__spiece pc;
    memset(&pc, 0, sizeof pc);
    pc.v[EL__SP_PHI] = p->phi; pc.v[EL__SP_NU] = log(p->mu); pc.v[EL__SP_K] = p->k; pc.v[EL__SP_Q] = p->q;
    pc.v[EL__SP_L] = p->length;
    pc.dx = xy[2] - xy[0];
    pc.dy = xy[3] - xy[1];
    pc.h = hypot(pc.dx, pc.dy);
    if (!(pc.h > 0.0)) return EL_EDOM;
    pc.gn[0] = -pc.dy / pc.h;   /* the end moved along the chord's normal, as by a guide duck */
    pc.gn[1] = pc.dx / pc.h;
    const el__sptargets t = {th[0], th[1], 2.0 * p->mu * (2.0 * p->k * p->k - 1.0), -1, -1, -1, -1, -1};
    double raw[EL__NV * EL__NV + 2 * EL__NV];
    if ((st = piece_eval_raw(&pc, &t, 1, raw))) return st;
    memcpy(J, raw, EL__NV * EL__NV * sizeof *J);
    memcpy(g0, raw + EL__NV * EL__NV, EL__NV * sizeof *g0);
    memcpy(g1, raw + EL__NV * EL__NV + EL__NV, EL__NV * sizeof *g1);
    memcpy(M, pc.M, sizeof pc.M);
    for (int r = 0; r < 4; r++) {
        d[r] = pc.c0[r + 1];
        d[4 + r] = pc.c1[r + 1];
        d[8 + r] = pc.cL[r + 1];
    }
    return EL_OK;
}

