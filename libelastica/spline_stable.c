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
 * Lagrangian's second variation is positive on the variations that keep the length: with
 * each span eliminated as above, the bordered matrix [H g; g^T -gamma], where
 * g_i = dL / d theta_i (the pieces' cL[1], cL[2]) and gamma = -sum_j dL_j / d sigma
 * (-cL[3]: a span's own give in length at fixed end angles, gamma > 0 where each span is
 * stable), has exactly one negative eigenvalue; i.e. H + g g^T / gamma is positive
 * definite (Schur complement of -gamma). By Haynsworth's inertia additivity (Schur
 * complement of H instead) the constraint removes one of H's negative eigenvalues iff
 * gamma + g^T H^{-1} g < 0 (GSL's symmetric tridiagonal solve for H^{-1} g).
 * Not judged: a chain with a circle piece (el__spline_unstable_result). Not tested here: a span unstable for its own end data (a conjugate point inside a
 * span), which H cannot see.
 */
#include "internal.h"
#include <gsl/gsl_linalg.h>

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

/* The length held (file comment): 1 where the constraint removes one of H's neg > 0
 * negative eigenvalues (gamma + g^T H^{-1} g < 0), else 0 (H singular: 0, not judged
 * better); H in w->dg, w->up on rows i0..i1, w->b and w->y its work */
static int length_lifts_one(el__spchain *w, size_t i0, size_t i1)
{
    double gamma = 0.0, *g = w->b, *u = w->y;
    for (size_t i = i0; i <= i1; i++) g[i] = 0.0;
    for (size_t j = 0; j < w->m; j++) {
        const el__spiece *pc = &w->pc[j];
        gamma -= pc->cL[3];   /* dL_j / d sigma at fixed end angles: D[3] = J^{-1} h^2 e4 */
        if (j >= i0 && j <= i1) g[j] += pc->cL[1];
        if (j + 1 >= i0 && j + 1 <= i1) g[j + 1] += pc->cL[2];
    }
    const size_t k = i1 - i0 + 1;
    if (k == 1) u[i0] = g[i0] / w->dg[i0];
    else {
        gsl_vector_const_view dv = gsl_vector_const_view_array(w->dg + i0, k);
        gsl_vector_const_view ev = gsl_vector_const_view_array(w->up + i0, k - 1);
        gsl_vector_const_view bv = gsl_vector_const_view_array(g + i0, k);
        gsl_vector_view xv = gsl_vector_view_array(u + i0, k);
        if (gsl_linalg_solve_symm_tridiag(&dv.vector, &ev.vector, &bv.vector, &xv.vector)) return 0;
    }
    double gu = 0.0;
    for (size_t i = i0; i <= i1; i++) gu += g[i] * u[i];
    return isfinite(gu) && gamma + gu < 0.0;
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
    if (!el__chain_jac_current(w) && !isfinite(el__chain_eval(w, 1))) return 0;
    el__spline_hessian(w);
    double *dg = w->dg, *up = w->up, *z = w->z;
    const size_t i0 = w->slot[0] == EL__SLOT_ANGLE ? 0 : 1;
    const size_t i1 = w->slot[n - 1] == EL__SLOT_ANGLE ? n - 1 : n - 2;
    if (i0 > i1) return 0;
    int neg = el__tridiag_negatives(dg, up, i0, i1, 0.0);
    if (neg && held) neg -= length_lifts_one(w, i0, i1);
    if (!neg) return 0;
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
    return neg;
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
    if (res->npieces == w->m && !(L == res->length && res->sigma == (w->lmode ? w->sigma / (S * S) : w->sigma_user))) {
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
