/*
 * The near-straight Hermite solution under tension (sigma > 0) between tangents nearly
 * along the chord, the end point ahead: its root in the separatrix chart, started from
 * the linear beam.
 *
 * Its curvature state at s = 0 lies on the saddle's stable manifold to within
 * |F| - sigma ~ 4 a b exp(-sqrt(sigma / 2) L) (below): in the x chart (kappa0) that is
 * below one ulp for sigma |p1 - p0|^2 above ~10 and tangents ~1e-8 rad off the chord, or
 * ~1e-4 at 1e3 (the header's former limits), and the solver's bracketing lost it.
 * The separatrix chart (hermite_objective.c) takes y = ln|(|F| - sigma)| as the unknown,
 * where the objective is smooth and nearly affine; the linear beam gives y to O(theta^2)
 * and the secant below the root.
 *
 * Linear beam (normalised: |P| = 1, angles theta from the chord, s along it): the conserved
 * F gives kappa'' = (sigma - kappa^2) kappa / 2, linearised kappa'' = g^2 kappa with
 * g = sqrt(sigma / 2), so theta = theta' integrated is
 *   theta(s) = c + alpha e^(-g s) + beta e^(-g (1 - s)),
 * with theta(0) = t0, theta(1) = t1 and the deflection int_0^1 theta = 0. With E = e^-g,
 * S = alpha + beta, D = alpha - beta:
 *   D (1 - E) = t0 - t1,   S ((1 + E) - 2 (1 - E) / g) = t0 + t1,   c = -S (1 - E) / g.
 * kappa = -g alpha e^(-g s) + g beta e^(-g (1 - s)), and with (8) at the state,
 * |F| - sigma = (kappa'^2 / g^2 - kappa^2) (1 + O(kappa^2 / sigma)) = 4 g^2 alpha beta E,
 * the same at every s (conserved); L = 1 + int_0^1 theta^2 / 2.
 */
#include "hermite_internal.h"
#include <string.h>

/* The linear beam above for sigma > 0 (normalised): *bm its coefficients, the start state,
 * ln| |F| - sigma | and its sign, the length. EL_EDOM where sigma <= 0 or the beam is
 * singular. */
int el__hermite_near_beam(double sigma, double t0, double t1, hbeam *bm)
{
    memset(bm, 0, sizeof *bm);
    if (!(sigma > 0.0) || !isfinite(sigma)) return EL_EDOM;
    const double g = sqrt(0.5 * sigma), E = exp(-g), omE = -expm1(-g);
    const double den = (1.0 + E) - 2.0 * omE / g;   /* g^2 / 6 - g^3 / 6 + ... for small g */
    if (!(den > 0.0)) return EL_EDOM;
    const double S = (t0 + t1) / den, D = (t0 - t1) / omE;
    bm->g = g;
    bm->alpha = 0.5 * (S + D);
    bm->beta = 0.5 * (S - D);
    bm->c = -S * omE / g;
    bm->k0 = -g * bm->alpha + g * bm->beta * E;
    bm->k0p = g * g * (bm->alpha + bm->beta * E);
    const double ab = bm->alpha * bm->beta;
    bm->side = ab > 0.0 ? 1 : ab < 0.0 ? -1 : 0;
    bm->lnsep = bm->side ? log(4.0 * g * g * fabs(ab)) - g : -INFINITY;
    const double a = bm->alpha, b = bm->beta, c = bm->c;
    const double w2 = c * c + 2.0 * c * S * omE / g + (a * a + b * b) * omE * (1.0 + E) / (2.0 * g) +
                      2.0 * ab * E;   /* int_0^1 theta^2 */
    bm->L = 1.0 + 0.5 * w2;
    bm->amax = fmax(fabs(t0), fabs(t1));
    return EL_OK;
}

/* F and D (hermite_objective.c) of the amplitude atan2(S, C) in (-pi, pi], odd in it */
static int fd_odd(double S, double C, double k2, double kc2, double *F, double *D)
{
    const int rc = el__hermite_ell_fd(fabs(S), C, 0, k2, kc2, 1.0, F, D);
    *F = copysign(*F, S);
    *D = copysign(*D, S);
    return rc;
}

/* L, E and f of the state (|F| - sigma = st->sep exact) as the objective defines them
 * (hermite_objective.c, shape_prepare and shape_finish), but from each end's incomplete
 * integrals: the objective's one integral of the amplitude difference (DLMF 22.8) takes
 * its cosine as c0 c1 + s0 s1 d0 d1, which cancels where both ends lie next to the saddle
 * (tangents 1e-4 rad off the chord at sigma |p1 - p0|^2 = 3000: c0 c1 ~ -7e-11 against
 * |F| - sigma ~ 1e-23 sigma) and left L independent of |F| - sigma. */
static int near_shape(const hprob *pr, hstate *st)
{
    const double s = pr->sigma, F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - s;
    const double Fn = s + st->sep, km2 = Fn + s, rmu = sqrt(0.5 * Fn), k2 = km2 / (2.0 * Fn);
    if (!(Fn > 0.0) || !(km2 > 0.0)) return EL_EDOM;
    /* h = (theta - phi) / 2 at both ends, theta - phi = atan2(-2 kappa', kappa^2 - sigma) */
    const double h0 = 0.5 * atan2(F1, F2), h1 = 0.5 * atan2(-2.0 * st->k1p, st->k1 * st->k1 - s);
    double a0[2], a1[2], m, mc, scale, per;
    if (st->sep > 0.0) {          /* sin a = sin h / k, cos a = kappa / kappa_m; L in (0, 4 K] */
        const double ik = sqrt(2.0 * Fn / km2), ikm = 1.0 / sqrt(km2);
        a0[0] = sin(h0) * ik; a0[1] = st->k0 * ikm;
        a1[0] = sin(h1) * ik; a1[1] = st->k1 * ikm;
        m = k2; mc = st->sep / (2.0 * Fn); scale = 1.0 / rmu; per = 4.0;
    } else {                      /* m = 1/k: sin b = eps sin h, cos b = cos h; L in (0, 2 K] */
        const double eps = st->k0 > 0.0 ? 1.0 : -1.0;
        a0[0] = eps * sin(h0); a0[1] = cos(h0);
        a1[0] = eps * sin(h1); a1[1] = cos(h1);
        m = 1.0 / k2; mc = -st->sep / km2; scale = 1.0 / (sqrt(k2) * rmu); per = 2.0;
    }
    double F0, D0, Fe, De, K, Dc;
    int rc;
    if ((rc = fd_odd(a0[0], a0[1], m, mc, &F0, &D0)) || (rc = fd_odd(a1[0], a1[1], m, mc, &Fe, &De)) ||
        (rc = el__ellint_complete(sqrt(m), mc, &K, &Dc)))
        return rc;
    double U = Fe - F0, DD = De - D0;
    if (!(U > 0.0)) { U += per * K; DD += per * Dc; }
    st->infl = st->sep > 0.0;
    st->s0 = a0[0]; st->c0 = a0[1]; st->s1 = a1[0]; st->c1 = a1[1];
    st->big = st->infl && U > 2.0 * K;
    st->L = scale * U;
    st->E = km2 * scale * (U - (st->infl ? 1.0 : m) * DD);
    st->f = (st->E - s * st->L - (F1 * pr->P1 + F2 * pr->P2)) / Fn;
    return isfinite(st->f) && st->L > 0.0 ? EL_OK : EL_EDOM;
}

/* The start state on branch b's crossing of the saddle's stable manifold, |F| = sigma with
 * kappa' = -kappa sqrt(g^2 - kappa^2 / 4) ((8) solved for kappa'), from the beam's kappa0:
 * secant steps on that relation's residual, which keeps its relative precision (the x
 * chart's |F| - sigma, from |F| formed first, loses it: ~1e-16 sigma absolute). */
static int near_crossing(const hprob *pr, int b, double x0, hstate *st)
{
    const double g2 = 0.5 * pr->sigma;
    double xa = x0, xb = x0 * (1.0 + 1e-6), qa, qb;
    hstate sa, sb;
    if (el__hermite_curvdata(pr, xa, b, &sa) || el__hermite_curvdata(pr, xb, b, &sb)) return EL_EDOM;
    qa = sa.k0p + xa * sqrt(g2 - 0.25 * xa * xa);
    qb = sb.k0p + xb * sqrt(g2 - 0.25 * xb * xb);
    for (int it = 0; it < 40 && qb != 0.0 && qa != qb && xa != xb; it++) {
        const double xn = xb - qb * (xb - xa) / (qb - qa);
        hstate sn;
        if (!isfinite(xn) || el__hermite_curvdata(pr, xn, b, &sn)) return EL_EDOM;
        xa = xb; qa = qb;
        xb = xn; sb = sn;
        qb = sn.k0p + xn * sqrt(g2 - 0.25 * xn * xn);
    }
    if (!(fabs(qb) <= 1e-10 * fabs(sb.k0p)) || !(fabs(xb - x0) <= 0.5 * fabs(x0))) return EL_EDOM;
    *st = sb;
    return EL_OK;
}

/* f at |F| - sigma = side e^y from the crossing's state c (near_shape's f) into *st */
static int near_eval(const hprob *pr, const hstate *c, int side, double y, hstate *st)
{
    *st = *c;
    st->has_sep = 1;
    st->sep = side * exp(y);
    return near_shape(pr, st);
}

/* The root near the beam's y on branch b: secant steps in y (f is affine in y to
 * O(|F| - sigma), hermite_tension.c), kept while |f| falls; pushed where |f| <= 1e-12
 * and the curve is the beam's (L - 1 within half the beam's, or 1e-9: a curve with loops
 * is ~1 / sqrt(sigma) longer, and the other branch can hold one at sigma ~1e5) */
static int near_root(const hprob *pr, int b, const hbeam *bm, hrootlist *out)
{
    hstate c, sa, sb;
    double ya = bm->lnsep, yb = ya + 0.5;
    double w = bm->k0;
    /* below NEAR_EXACT the beam's own states (kappa' on the separatrix, the end's at s = 1:
     * O(theta^2) relative): (16)-(20) lose them there (tangents 1e-7 rad off the chord at
     * sigma |p1 - p0|^2 = 30: kappa0 21 % off; ~1e-8: V2 = 1 in doubles, the discriminant of
     * (18) rounds below 0); above, the crossing, or where (17) has no real root the
     * separatrix chart's state */
    /* (and just above NEAR_EXACT where neither gives a state: tangents 1e-6 rad and 0 at
     * sigma |p1 - p0|^2 = 1e5, the angle 1e-6 + 1 ulp from the world's: the curve lost, its
     * mirror image found; the beam's states are O(1e-10) relative off there) */
    int exact = bm->amax <= NEAR_EXACT;
    if (!exact && near_crossing(pr, b, bm->k0, &c) &&
        el__hermite_sep_eval(pr, HCHART_X, 0, b, bm->side, ya, pr->sigma, 1.0, &w, &c, NULL, NULL)) {
        if (!(bm->amax <= 10.0 * NEAR_EXACT)) return EL_OK;
        exact = 1;
    }
    if (exact) {
        if (b) return EL_OK;                      /* one state for both branches */
        const double g2 = bm->g * bm->g, E = exp(-bm->g);
        memset(&c, 0, sizeof c);
        c.k0 = bm->k0;
        c.k0p = -c.k0 * sqrt(g2 - 0.25 * c.k0 * c.k0);
        c.k1 = bm->g * (bm->beta - bm->alpha * E);
        c.k1p = c.k1 * sqrt(g2 - 0.25 * c.k1 * c.k1);
    }
    if (near_eval(pr, &c, bm->side, ya, &sa) ||
        near_eval(pr, &c, bm->side, yb, &sb))
        return EL_OK;
    for (int it = 0; it < 30 && sb.f != 0.0 && sa.f != sb.f; it++) {
        const double yn = yb - sb.f * (yb - ya) / (sb.f - sa.f);
        hstate sn;
        if (!isfinite(yn) || yn < -700.0 || near_eval(pr, &c, bm->side, yn, &sn) ||
            !(fabs(sn.f) < fmax(fabs(sa.f), fabs(sb.f))))
            break;
        ya = yb; sa = sb;
        yb = yn; sb = sn;
        if (fabs(yb - ya) <= 1e-15 * (1.0 + fabs(yb))) break;
    }
    if (fabs(sa.f) < fabs(sb.f)) sb = sa;
    if (!(fabs(sb.f) <= 1e-12) || !(fabs(sb.L - bm->L) <= 0.5 * (bm->L - 1.0) + 1e-9)) return EL_OK;
    hroot r = el__hermite_mkroot(c.k0, b, pr->sigma);   /* x = kappa0 (case 1) */
    r.st = sb;
    return el__hermite_roots_push(out, &r);
}

/* A near-straight solution's representation against its root's state st: EL_EDOM where
 * its end curvatures are more than 10 % of the largest off the root's (a chain's curvature
 * is ~1e-8 kappa_m off, hermite_chain.c, and a piece's with k rounded to 1 as far: at
 * tangents ~1e-9 rad off the chord that is its whole curvature; at 1 % mirrored problems
 * fell on either side of the bound); else EL_OK with its end
 * curvatures and has_inflection from them (the curve passes the saddle within
 * |kappa| / kappa_m ~1e-10 of am = pi/2, below make_solution's 1e-9 guard; the beam's
 * curvature a e^(-g s) + b e^(-g (L - s)) has one zero at most). */
int el__hermite_near_check(const hframe *fr, const hstate *st, el_hermite_solution *s)
{
    const el_smooth_params *last = s->npieces > 1 ? &s->rest[s->npieces - 2] : &s->curve;
    const double e0 = 0.0, e1 = last->length;
    double k0, k1;
    if (el_smooth_eval(&s->curve, 1, &e0, NULL, NULL, &k0) || el_smooth_eval(last, 1, &e1, NULL, NULL, &k1))
        return EL_EDOM;
    const double kn = 0.1 * fmax(fabs(st->k0), fabs(st->k1)) / fr->d;
    if (!(fabs(k0 - st->k0 / fr->d) <= kn && fabs(k1 - st->k1 / fr->d) <= kn)) return EL_EDOM;
    s->kappa0 = k0;
    s->kappa1 = k1;
    s->has_inflection = k0 * k1 < 0.0;
    return EL_OK;
}

int el__hermite_near_roots(const hprob *pr, hrootlist *out)
{
    /* (|P1| = |sin t0|, |V1| = |sin(t1 - t0)|: no atan2 for the problems far from it) */
    if (pr->hcase != 1 || !(pr->P2 > 0.0) || fabs(pr->P1) > NEAR_CHORD || fabs(pr->V1) > 2.0 * NEAR_CHORD)
        return EL_OK;
    /* angles from the chord P to T(0) = (0, 1) and to V */
    const double t0 = atan2(pr->P1, pr->P2);
    const double t1 = atan2(pr->P1 * pr->V2 - pr->P2 * pr->V1, pr->P1 * pr->V1 + pr->P2 * pr->V2);
    if (!(fabs(t0) <= NEAR_CHORD && fabs(t1) <= NEAR_CHORD)) return EL_OK;
    hbeam bm;
    if (el__hermite_near_beam(pr->sigma, t0, t1, &bm) || !bm.side) return EL_OK;
    for (int b = 0; b < 2; b++) {
        const int rc = near_root(pr, b, &bm, out);
        if (rc) return rc;
    }
    return EL_OK;
}

/* ------------------------------------------------------------ the world-frame beam, |sigma| d^2 <= 10 */

/* Tangents within NEAR_CHORD rad of the chord, the end point ahead, |sigma| |p1 - p0|^2
 * at most NEAR_SIGMA: the near-straight curve, from the linear beam's (the conserved F =
 * (kappa^2 - sigma) T + 2 kappa' N gives kappa'' = (sigma - kappa^2) kappa / 2; linearised
 * kappa'' = sigma kappa / 2: kappa = A f1 + B f2 with f1, f2 = 1, s (sigma = 0), cosh / sinh
 * (sigma > 0), cos / sin (sigma < 0) of sqrt(|sigma| / 2) s), whose slope theta = theta0 +
 * integral kappa ends at theta1 and whose deflection integral theta vanishes at s = d
 * (Simpson's rule, NEAR_SIMPSON intervals), L = d + integral theta^2 / 2; Newton on its
 * start state and length (near_newton), polished (polish, polish_fixed_k). EL_EDOM where it
 * cannot be evaluated (a buckling load makes the linear system singular), else EL_OK with
 * its residual: above tol where the polish fails, or where the parameters cannot carry it
 * (at sigma = 0 the curve is a piece sqrt(mu) L ~ |theta| of a huge elastica, whose closed
 * form loses ~eps / (sqrt(mu) L) to cancellation; so at |sigma| d^2 below ~theta^2, where
 * sqrt(mu) L ~ max(|theta|, sqrt(|sigma|) d): hermite.c counts it unrepresentable). Written because the solver's bracketing
 * misses it there: at sigma = 0 with tangents +-a of a shallow arc, for every a from 1e-9 to
 * 3e-4 (QA); of 1500 random such problems (tangents 1e-9 to 1e-2 rad off the chord, sigma
 * |p1 - p0|^2 0 or in [-10, 10]) 411 lacked it, 136 now: 96 at sigma = 0 counted
 * unrepresentable, 40 at other tensions with tangents ~1e-9..1e-8 rad off the chord (below 0:
 * kappa_m^2 = |F| + sigma cancelled, now taken without, el__hermite_params_from_state); none
 * listed twice */
#define NEAR_SIGMA 10.0
/* the clamped beam's buckling load: theta = c + a sin(w s) + b cos(w s), w = sqrt(-sigma / 2),
 * with theta(0) = theta(d) = int theta = 0 has the solution sin(2 pi s / d) at w d = 2 pi
 * (the linear system's determinant, 2 sin(w d / 2) (2 sin(w d / 2) - w d cos(w d / 2)) / w^2,
 * vanishes first there): sigma d^2 = -8 pi^2, where the near-straight curve stops existing */
#define NEAR_BUCKLING 78.95683520871486
enum { NEAR_SIMPSON = 64 };

static double near_basis(int j, double sigma, double s)
{
    const double w = sqrt(0.5 * fabs(sigma)) * s;
    if (sigma == 0.0) return j ? s : 1.0;
    if (sigma > 0.0) return j ? sinh(w) : cosh(w);
    return j ? sin(w) : cos(w);
}

/* The end conditions' residual (end point / d, end tangent) of the curve from p0, t0 with
 * the start state (kappa0, kappa0') = x[0], x[1] and length x[2] at tension sigma */
static int near_residual(const hframe *fr, double sigma, const double x[3], double r[3], el_smooth_params *p)
{
    double xy[4], th[2];
    if (el__hermite_params_from_state(fr->p0[0], fr->p0[1], fr->psi0, x[0], x[1], sigma, x[2],
                                      NULL, p) ||
        el_smooth_check(p) || el__smooth_ends(p, xy, th))
        return EL_EDOM;
    r[0] = (xy[2] - fr->p1[0]) / fr->d;
    r[1] = (xy[3] - fr->p1[1]) / fr->d;
    r[2] = el__hermite_wrap_pi(th[1] - fr->psi1);
    return isfinite(r[0]) && isfinite(r[1]) && isfinite(r[2]) ? EL_OK : EL_EDOM;
}

/* Newton on the start state and the length from x (the linear beam's), a finite-difference
 * Jacobian each step (steps scale: the state's size, ~theta / d and theta / d^2), while
 * the residual falls; the curve into s->curve */
static void near_newton(const hframe *fr, double sigma, double scale, double x[3], el_hermite_solution *s)
{
    const double d = fr->d, hs[3] = {1e-6 * scale / d, 1e-6 * scale / (d * d), 1e-6 * scale * d};
    double r[3];
    el_smooth_params p;
    if (near_residual(fr, sigma, x, r, &p)) return;
    double rn = fmax(fabs(r[0]), fmax(fabs(r[1]), fabs(r[2])));
    s->curve = p;
    for (int it = 0; it < 12 && rn > 0.0; it++) {
        double J[9], rp[3], rm[3];
        for (int c = 0; c < 3; c++) {
            double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
            xp[c] += hs[c];
            xm[c] -= hs[c];
            if (near_residual(fr, sigma, xp, rp, &p) || near_residual(fr, sigma, xm, rm, &p)) return;
            for (int i = 0; i < 3; i++) J[i * 3 + c] = (rp[i] - rm[i]) / (2.0 * hs[c]);
        }
        int perm[3];
        double dx[3] = {-r[0], -r[1], -r[2]};
        if (el__lu_factor(J, 3, perm)) return;
        el__lu_solve(J, 3, perm, dx);
        const double xn[3] = {x[0] + dx[0], x[1] + dx[1], x[2] + dx[2]};
        double rt[3];
        if (near_residual(fr, sigma, xn, rt, &p)) return;
        const double tn = fmax(fabs(rt[0]), fmax(fabs(rt[1]), fabs(rt[2])));
        if (!(tn < rn)) return;
        memcpy(x, xn, sizeof xn);
        memcpy(r, rt, sizeof rt);
        rn = tn;
        s->curve = p;
    }
}

int el__hermite_near_straight(const hframe *fr, double sigma, double tol, el_hermite_solution *s)
{
    const double d = fr->d, chi = atan2(fr->p1[1] - fr->p0[1], fr->p1[0] - fr->p0[0]);
    const double t0 = el__hermite_wrap_pi(fr->psi0 - chi), t1 = el__hermite_wrap_pi(fr->psi1 - chi);
    if (!(fabs(t0) <= NEAR_CHORD && fabs(t1) <= NEAR_CHORD && sigma * d * d <= NEAR_SIGMA &&
          sigma * d * d > -NEAR_BUCKLING))
        return EL_EDOM;
    /* integral f_j and integral (d - s) f_j over [0, d] (the turning and the deflection) */
    const double h = d / NEAR_SIMPSON;
    double I[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
    for (int i = 0; i <= NEAR_SIMPSON; i++) {
        const double wt = (i == 0 || i == NEAR_SIMPSON ? 1.0 : i % 2 ? 4.0 : 2.0) * h / 3.0, x = i * h;
        for (int j = 0; j < 2; j++) {
            I[0][j] += wt * near_basis(j, sigma, x);
            I[1][j] += wt * (d - x) * near_basis(j, sigma, x);
        }
    }
    const double det = I[0][0] * I[1][1] - I[0][1] * I[1][0], r0 = t1 - t0, r1 = -t0 * d;
    if (!(fabs(det) > 0.0)) return EL_EDOM;
    const double A = (r0 * I[1][1] - I[0][1] * r1) / det, B = (I[0][0] * r1 - I[1][0] * r0) / det;
    const double g = sqrt(0.5 * fabs(sigma));
    const double k0 = A, k0p = sigma == 0.0 ? B : B * g;      /* f1'(0) = 0, f2'(0) = 1 or g */
    /* L = d + integral theta^2 / 2, theta = t0 + integral kappa (the trapezoid's running sum) */
    double theta = t0, w2 = 0.0, kprev = k0, klast = k0;
    int turns = 0;     /* kappa's changes of sign inside, across a sample where it is 0 too
                        * (parallel tangents: 0 at the middle, which hid the - to + change) */
    for (int i = 1; i <= NEAR_SIMPSON; i++) {
        const double x = i * h, k = A * near_basis(0, sigma, x) + B * near_basis(1, sigma, x);
        const double th = theta + 0.5 * h * (kprev + k);
        turns += i < NEAR_SIMPSON && k != 0.0 && klast != 0.0 && (k < 0.0) != (klast < 0.0);
        if (k != 0.0) klast = k;
        w2 += 0.5 * h * (theta * theta + th * th);
        theta = th;
        kprev = k;
    }
    memset(s, 0, sizeof *s);
    s->npieces = 1;
    s->sigma = sigma;
    double x[3] = {k0, k0p, d + 0.5 * w2};
    if (el__hermite_params_from_state(fr->p0[0], fr->p0[1], fr->psi0, x[0], x[1], sigma, x[2],
                                      NULL, &s->curve))
        return EL_EDOM;
    near_newton(fr, sigma, fmax(fabs(t0), fabs(t1)), x, s);
    s->length = s->curve.length;
    if (el__hermite_residual(fr, s, &s->residual)) return EL_EDOM;
    if (el__hermite_polish(fr, sigma, tol, s) || el_smooth_energy(&s->curve, &s->energy)) return EL_EDOM;
    s->has_inflection = turns > 0;   /* the linear beam's: the polish moves kappa by O(theta^3) */
    return EL_OK;
}

