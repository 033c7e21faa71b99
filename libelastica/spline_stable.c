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
 * Not tested here: a span unstable for its own end data (a conjugate point inside a
 * span), which H cannot see.
 */
#include "internal.h"

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

int el__spline_unstable(el__spchain *w, size_t *span)
{
    const size_t n = w->n, m = w->m;
    *span = 0;
    if (w->closed || w->ng || w->lmode || n < 2) return 0;
    /* H needs the pieces' c0, c1 at the solution: mostly still those of the solver's last
     * step (spline.c's free battens: 200 of 202), evaluated again only where not */
    if (!el__chain_jac_current(w) && !isfinite(el__chain_eval(w, 1))) return 0;
    el__spline_hessian(w);
    double *dg = w->dg, *up = w->up, *z = w->z;
    const size_t i0 = w->slot[0] == EL__SLOT_ANGLE ? 0 : 1;
    const size_t i1 = w->slot[n - 1] == EL__SLOT_ANGLE ? n - 1 : n - 2;
    if (i0 > i1) return 0;
    const int neg = el__tridiag_negatives(dg, up, i0, i1, 0.0);
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
