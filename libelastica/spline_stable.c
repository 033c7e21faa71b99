/*
 * Is a free batten (tension mode) a minimum or only an equilibrium? The second
 * variation, reduced to the knot angles (spline.c).
 *
 * Each span's energy E_j(ta, tb) = integral kappa^2 + sigma ds of its Hermite
 * elastica (free length, seed 004) has dE_j/dta = -2 kappa(0), dE_j/dtb = 2 kappa(L),
 * so the spline's E(theta) = sum E_j has the gradient 2 (kappa^- - kappa^+) (the knot
 * equations F_i / l_i, spline_chain.c) and the Hessian
 *   H = 2 [d kappa^- / d theta - d kappa^+ / d theta],
 * symmetric tridiagonal, from the pieces' c0, c1 (d kappa(0), d kappa(L) in ta, tb
 * at R = 0: the implicit function theorem, spline_piece.c). Every variation of the
 * batten splits into one that keeps the knot angles (each span's own problem) and the
 * spans' response to the angles, so with every span stable for its own end data the
 * batten is a minimum iff H is positive definite (the Schur complement of the second
 * variation; Maddocks' reduction of the Jacobi test to the knots). A negative
 * eigenvalue: moving the angles along its vector lowers the energy, the batten leaves
 * its ducks (a free one, sigma = 0: a span grows without bound, as a polyline of the
 * same ducks minimised from it does, QA19 W2). Inertia by Sylvester's law (the negative
 * pivots of L D L^T: el__tridiag_negatives, spline_buckle.c); the least eigenvalue by
 * bisection on that count and its vector by inverse iteration (el__tridiag_inverse_iter),
 * the span named the one whose length grows most along it (relative to its length:
 * dL = cL . d theta).
 * Under tension (sigma > 0 given) the same H is the Hessian of sum_j E_j + sigma L_j: a
 * negative eigenvalue is a batten the tension does not hold either (it would snap to
 * another shape, the spans moving along that vector). By length (sigma the multiplier of
 * sum L_j = L) the batten is a minimum of sum_j E_j under that constraint iff the
 * Lagrangian's second variation is positive on the variations that keep the length. With
 * e_j(theta, l_j) span j's energy at given end angles and length, c_j = d2 e_j / d l_j^2 =
 * 1 / gamma_j, gamma_j = -dL_j / d sigma at fixed end angles (-cL[3]), completing the square
 * in each l_j leaves dtheta^T H dtheta + sum_j c_j s_j^2 on sum_j s_j = -g . dtheta, where
 * g_i = dL / d theta_i (the pieces' cL[1], cL[2]): the form of the bordered matrix
 * K = [H 0 g; 0 C 1; g^T 1^T 0], C = diag(c_j), whose negative count is the constrained
 * form's plus one (one constraint). Haynsworth's inertia additivity, C's Schur complement
 * first ([H g; g^T -gamma], gamma = sum_j gamma_j), then H's, gives the count on the
 * constraint
 *   neg(H) + #{j: gamma_j < 0} + [gamma + g^T H^{-1} g > 0] - 1
 * (el__spline_length_negatives). Where every gamma_j > 0 (each span gives length as the
 * tension grows) this is neg(H) less one iff gamma + g^T H^{-1} g < 0: the constraint lifts
 * one of H's negative eigenvalues. A span past its force-free length on its branch (a
 * clamped U-turn span: sigma(L) least at L0 ~ 2.19 chords) has gamma_j < 0: two such spans,
 * or one with H positive definite and gamma > 0, are unstable by moving length between
 * spans at fixed angles, which H alone cannot see. H^{-1} g by GSL's banded LU with partial
 * pivoting (H is indefinite here: a symmetric LDL^T without pivoting returns a wrong solve
 * with status 0 where a leading block is near singular); a singular H, a gamma_j = 0 or a
 * failed solve: not judged (0).
 * TENSION_COUNT: by tension (sigma fixed, every l_j free) the same split without the
 * constraint: the second variation in (theta, l) has the block C = diag(c_j) in the lengths,
 * f_j = e_j + sigma l_j having d2 f_j / d l_j^2 = d2 e_j / d l_j^2 = 1 / gamma_j, and H (the
 * free-length E_j's Hessian) is its Schur complement, so its negative count is
 *   neg(H) + #{j: gamma_j < 0}
 * (Haynsworth). A span past its force-free length is a maximum of integral kappa^2 + sigma ds
 * in its own length at fixed end angles: a U-turn span (chord 1, tangents (0, 1), (0, -1))
 * at sigma 0.3 on its branch of length 2.894: gamma = -2.458, and el_hermite_solve by length
 * gives d2/dl2 (integral kappa^2 + sigma l) = -0.4067 = 1 / gamma; it read stable (0) before.
 * Its span is named where H has no negative eigenvalue: of the spans with gamma_j < 0 the
 * one of the most negative c_j = 1 / gamma_j (C's least eigenvalue, whose mode is that span's
 * length alone; revspline's finding 8: the least gamma_j named before, the least unstable).
 * Not judged: a chain with a circle piece, or a result whose piece count is not the chain's
 * (el__spline_unstable_result). Not tested here: a span unstable for its own end data at
 * fixed length (a conjugate point inside a span), which neither H nor gamma_j sees.
 */
#include "internal.h"
#include <gsl/gsl_linalg.h>
#include <stdlib.h>

/* The least |gamma_j| / h^3 whose sign tension mode's count trusts (el__spline_unstable_as). */
#define GAMMA_ROUNDING 1e-6

/* H of the header: E_j's 2 x 2 Hessian from piece j's c0, c1 summed at its two knots */
void el__spline_hessian(el__spchain *w)
{
    double *dg = w->dg, *up = w->up;
    for (size_t i = 0; i < w->n; i++) dg[i] = up[i] = 0.0;
    for (size_t j = 0; j < w->m; j++) {   /* E_j's Hessian in (ta, tb), at knots j, j + 1 */
        const el__spiece *pc = &w->pc[j];
        dg[j] -= 2.0 * pc->c0[1];
        dg[j + 1] += 2.0 * pc->c1[2];
        up[j] = pc->c1[1] - pc->c0[2];   /* the mean of its two equal entries */
    }
}

/* The file comment's count on the length constraint: H (dg, up: k x k tridiagonal, neg(H) =
 * negH), g (k), gam (m: the spans' gamma_j); -1 where not judged (H singular, a gamma_j
 * 0 or not finite, no memory). H^{-1} g: GSL's banded LU with partial pivoting (lb = ub =
 * 1); its band storage holds A(i, j) at AB(j, lb + ub + i - j) (LAPACK's dgbtrf, one column
 * of A a row of AB). */
int el__spline_length_negatives(const double *dg, const double *up, const double *g, size_t k, int negH,
                                const double *gam, size_t m)
{
    double gamma = 0.0;
    int nc = 0;
    for (size_t j = 0; j < m; j++) {
        if (!isfinite(gam[j]) || gam[j] == 0.0) return -1;
        gamma += gam[j];
        nc += gam[j] < 0.0;
    }
    if (!negH && !nc) return 0;   /* (H and C positive definite: so is the constrained form) */
    double gu = 0.0;
    if (k == 1) gu = g[0] * g[0] / dg[0];
    else {
        double *buf = malloc(k * 5 * sizeof *buf);
        unsigned *piv = malloc(k * sizeof *piv);
        if (!buf || !piv) { free(buf); free(piv); return -1; }
        double *u = buf + 4 * k;
        for (size_t j = 0; j < k; j++) {   /* column j of H: rows j - 1, j, j + 1 */
            buf[4 * j + 1] = j > 0 ? up[j - 1] : 0.0;
            buf[4 * j + 2] = dg[j];
            buf[4 * j + 3] = j + 1 < k ? up[j] : 0.0;
        }
        gsl_matrix_view ab = gsl_matrix_view_array(buf, k, 4);
        gsl_vector_uint_view pv = gsl_vector_uint_view_array(piv, k);
        gsl_vector_const_view bv = gsl_vector_const_view_array(g, k);
        gsl_vector_view xv = gsl_vector_view_array(u, k);
        int rc = gsl_linalg_LU_band_decomp(k, 1, 1, &ab.matrix, &pv.vector);
        if (!rc) rc = gsl_linalg_LU_band_solve(1, 1, &ab.matrix, &pv.vector, &bv.vector, &xv.vector);
        for (size_t i = 0; i < k; i++) gu += g[i] * u[i];
        free(buf);
        free(piv);
        if (rc) return -1;
    }
    if (!isfinite(gu) || gamma + gu == 0.0) return -1;
    return negH + nc + (gamma + gu > 0.0) - 1;
}

/* Of two spans past their force-free length (gamma_j, gamma_i < 0), is j's c_j = 1 / gamma_j the
 * more negative (the steeper fall of its energy in its own length, C's least eigenvalue: the
 * span moving most along that mode, elastica.h's slide_span)? */
static int steeper(double gam_j, double gam_i)
{
    return 1.0 / gam_j < 1.0 / gam_i;
}

/* el__spline_length_negatives on w's H (rows i0..i1, in w->dg, w->up), w->b its g; *span (0 on
 * entry) the span past its force-free length of the most negative c_j (steeper) where one is */
static int length_negatives(el__spchain *w, size_t i0, size_t i1, int negH, size_t *span)
{
    double *g = w->b, *gam = w->y;   /* (y: m <= n entries) */
    for (size_t i = i0; i <= i1; i++) g[i] = 0.0;
    for (size_t j = 0; j < w->m; j++) {
        const el__spiece *pc = &w->pc[j];
        gam[j] = -pc->cL[3];   /* -dL_j / d sigma at fixed end angles: D[3] = J^{-1} h^2 e4 */
        if (j >= i0 && j <= i1) g[j] += pc->cL[1];
        if (j + 1 >= i0 && j + 1 <= i1) g[j + 1] += pc->cL[2];
        if (gam[j] < 0.0 && !(gam[*span] < 0.0 && !steeper(gam[j], gam[*span]))) *span = j;
    }
    const int neg = el__spline_length_negatives(w->dg + i0, w->up + i0, g + i0, i1 - i0 + 1, negH, gam, w->m);
    return neg < 0 ? 0 : neg;
}

int el__spline_unstable(el__spchain *w, size_t *span)
{
    return w->lmode ? 0 : el__spline_unstable_as(w, 0, span);
}

int el__spline_unstable_as(el__spchain *w, int held, size_t *span)
{
    const size_t n = w->n, m = w->m;
    *span = 0;
    if (w->closed || w->ng || n < 2) return 0;
    /* H needs the pieces' c0, c1 at the solution: mostly still those of the solver's last
     * step (spline.c's free battens: 200 of 202), evaluated again only where not */
    if (!el__chain_jac_current(w) && !isfinite(el__chain_reeval(w, 1))) return 0;
    el__spline_hessian(w);
    double *dg = w->dg, *up = w->up, *z = w->z;
    const size_t i0 = w->slot[0] == EL__SLOT_ANGLE ? 0 : 1;
    const size_t i1 = w->slot[n - 1] == EL__SLOT_ANGLE ? n - 1 : n - 2;
    /* by tension: the spans past their force-free length (gamma_j < 0, TENSION_COUNT); a
     * gamma_j not finite or 0 (C = diag(1 / gamma_j) undefined: the Schur split needs it):
     * not judged (0), the rule of el__spline_length_negatives. A nearly straight span's
     * gamma_j is O(h^3 theta^2) and its sign below GAMMA_ROUNDING h^3 is rounding's (1000
     * ducks on a sine, free batten: 573 spans read -2.1e-8 h^3 .. -7e-14 h^3, every one
     * nearly straight, and the batten was refused as sliding off; a span truly past its
     * force-free length reads O(0.01 .. 1) h^3: the U-turn above -2.46 h^3): counted only
     * past it */
    int nc = 0;
    size_t cspan = 0;
    if (!held)
        for (size_t j = 0; j < m; j++) {
            const double gam = -w->pc[j].cL[3], h = w->pc[j].h;
            if (!isfinite(gam) || gam == 0.0) return 0;
            if (!(gam < -GAMMA_ROUNDING * h * h * h)) continue;
            if (!nc || steeper(gam, -w->pc[cspan].cL[3])) cspan = j;
            nc++;
        }
    if (i0 > i1) { *span = cspan; return nc; }
    int neg = el__tridiag_negatives(dg, up, i0, i1, 0.0);
    if (held) {
        const int negH = neg;
        neg = length_negatives(w, i0, i1, negH, span);
        if (!neg) *span = 0;
        if (!negH || !neg) return neg;   /* (H positive definite: the negative gamma_j's span) */
    }
    if (!neg) { *span = cspan; return nc; }
    /* the least eigenvalue: between Gershgorin's bound and 0 */
    double lo = 0.0, hi = 0.0;
    for (size_t i = i0; i <= i1; i++)
        lo = fmin(lo, dg[i] - (i > i0 ? fabs(up[i - 1]) : 0.0) - (i < i1 ? fabs(up[i]) : 0.0));
    for (int it = 0; it < 100 && hi - lo > 1e-14 * (fabs(lo) + fabs(hi)); it++) {
        const double mid = 0.5 * (lo + hi);
        if (el__tridiag_negatives(dg, up, i0, i1, mid)) hi = mid; else lo = mid;
    }
    /* its vector: inverse iteration just below it (H - shift I positive definite); one
     * free knot is its own */
    const double shift = lo - 1e-6 * fabs(lo);
    for (size_t i = 0; i < n; i++) z[i] = 0.0;
    for (size_t i = i0; i <= i1; i++) dg[i] -= shift;
    if (i0 == i1) z[i0] = 1.0;
    else el__tridiag_inverse_iter(w, i0, i1);
    double most = -1.0;
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        const double dL = fabs(pc->cL[1] * z[j] + pc->cL[2] * z[j + 1]) / pc->v[EL__SP_L];
        if (dL > most) { most = dL; *span = j; }
    }
    return neg + nc;
}

int el__spline_unstable_result(el__spchain *w, const el_spline_result *res, double S, int held, size_t *span)
{
    /* w holds res unless a by-length fallback (spline_bracket.c) left it elsewhere: res's
     * pieces loaded then (make_result's units inverted), its Jacobians evaluated anew */
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[EL__SP_L] * S;
    /* a circle piece (|k| >= 1e3: sigma = kappa^2, no force) is not judged: its parameters
     * resolve it only to make_result's rule, its Jacobian's columns are ill-conditioned
     * there (an arc with held tangents at its force-free tension read unstable, 1e-3 above
     * and below it stable) */
    for (size_t j = 0; j < res->npieces; j++)
        if (el__spline_circle_piece(&res->pieces[j], w->tol)) return 0;
    if (res->npieces != w->m) return 0;   /* another chain's pieces: not judged */
    if (!(L == res->length && res->sigma == (w->lmode ? w->sigma / (S * S) : w->sigma_user))) {
        for (size_t j = 0; j < w->m; j++) {
            const el_smooth_params *p = &res->pieces[j];
            double *v = w->pc[j].v;
            v[EL__SP_PHI] = p->phi;
            v[EL__SP_NU] = log(p->mu * S * S);
            v[EL__SP_K] = p->k;
            v[EL__SP_Q] = p->q;
            v[EL__SP_L] = p->length / S;
        }
        w->sigma = res->sigma * S * S;
        for (size_t i = 0; i < w->n; i++) w->x[i] = res->angles[i];
    }
    return el__spline_unstable_as(w, held, span);
}

/*
 * STABLE_FAMILY (tension mode's own solve, open, no guides): where the solve's batten is an
 * equilibrium but no minimum (el__spline_unstable_as > 0: neg(H) > 0 or a span past its
 * force-free length), the family followed in sigma to the tension asked from the solutions at
 * the rungs STABLE_RUNGS (sigma h^2 on the mean chord, the unit here; each solved as tension
 * mode solves it, then continuation linear in sigma, el__spline_tension_from): the first that
 * arrives stable, converged, winding away no more than the batten found and of less integral
 * kappa^2 + sigma ds is kept. revspline's six ducks (tests/c/test_spline_stable_family.c),
 * natural ends, at tension 0: the direct Newton's batten 7.160 long (energy 13.54) has a span
 * past its force-free length, so 3f30dda's count refused it (EL_EDOM, "slides off"), where the
 * family from sigma h^2 1e-3 arrives at a stable one 5.701 long (12.07); at 0.03 / 0.1 the
 * same (7.17 unstable -> 5.70 stable). Only where the verdict is unstable: every stable
 * result is as before (the call is not made). w: the solution at w->sigma (tension mode);
 * *found 1 with the stable one in w, else 0 with w as it was (bit for bit); EL_OK or
 * EL_ENOMEM.
 */
static const double STABLE_RUNGS[] = {1e-3, 1e-2, 1e-1, 1.0, EL__SP_HIGH_SIGMA};
enum { NSTABLE_RUNGS = sizeof STABLE_RUNGS / sizeof STABLE_RUNGS[0] };

/* integral kappa^2 + sigma ds of the chain (internal units), and its length */
static double family_energy(const el__spchain *w, double *L)
{
    double e = 0.0;
    *L = 0.0;
    for (size_t j = 0; j < w->m; j++) {
        e += w->pc[j].energy;
        *L += w->pc[j].v[EL__SP_L];
    }
    return e + w->sigma * *L;
}

/* winding away from its ducks as el__chain_wanders says (longer than EL__SP_WANDER x their
 * polygon, or crossing itself where it does not: the tension solves' rule, spline_path.c's
 * unwind); -1 out of memory. (Without it QA19 W2's SHARP ducks at 20 / P^2 took a stable one
 * 1.64 x its polygon, less energy, for the unstable 1.13 x one) */
static int family_loops(const el__spchain *w, double L)
{
    double poly = 0.0;
    for (size_t j = 0; j < w->m; j++) poly += w->pc[j].h;
    return L > EL__SP_WANDER * poly ? 1 : el__chain_crosses(w);
}

int el__spline_stable_family(el__spchain *w, int max_steps, int *found)
{
    *found = 0;
    size_t span;
    if (w->lmode || w->closed || w->ng || w->near || !(el__spline_unstable_as(w, 0, &span) > 0)) return EL_OK;
    const double target = w->sigma;
    double L0;
    const double f0 = family_energy(w, &L0);
    const int l0 = family_loops(w, L0);
    if (l0 < 0) return EL_ENOMEM;
    const size_t n = w->n, m = w->m;
    double *buf = malloc(sizeof(double) * (n + 2 * EL__NV * m));
    if (!buf) return EL_ENOMEM;
    el__spsnap was = {buf, buf + n, buf + n + EL__NV * m, 0.0};
    el__snap_save(w, &was);
    const int it0 = w->iterations, nb = w->neighbours;
    w->neighbours = 0;
    int st = EL_OK;
    for (int i = 0; i < NSTABLE_RUNGS && !*found; i++) {
        if (STABLE_RUNGS[i] == target) continue;
        w->near = 0;
        w->sigma = STABLE_RUNGS[i];
        st = el__spline_solve_tension(w, max_steps, 1);
        if (st == EL_OK && !w->near) st = el__spline_tension_from(w, max_steps, target);
        if (st == EL_ENOMEM) break;
        if (st != EL_OK || w->near || w->sigma != target) { st = EL_OK; continue; }
        double L;
        const double f = family_energy(w, &L);
        const int l = family_loops(w, L);
        if (l < 0) { st = EL_ENOMEM; break; }
        *found = f < f0 && l <= l0 && !el__spline_unstable_as(w, 0, &span);
    }
    w->neighbours = nb;
    w->near = 0;
    w->lmode = 0;
    if (!*found) {   /* the batten found, as it was */
        el__snap_load(w, &was);
        w->sigma = target;
        w->iterations = it0;
        el__chain_reeval(w, 1);
    }
    free(buf);
    return st;
}
