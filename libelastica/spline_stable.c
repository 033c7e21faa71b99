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
#include <stdlib.h>
#include <string.h>
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

/* ------------------------------------------------------------------ under tension */

/*
 * At sigma > 0 the batten through the ducks that is no minimum has a stable one beside it
 * (the tension sigma L keeps its spans finite, where at sigma = 0 a span slides off), and
 * that is the batten: the unstable equilibrium is left along its least eigenvalue's vector
 * z, then E(theta) = sum_j E_j + sigma L_j is minimised over the knot angles, each span
 * its Hermite elastica for its end angles (el__spiece_newton from its last state), with
 * the gradient dE / d theta_i = 2 (kappa_i^- - kappa_i^+) (the knot residuals F_i / l_i)
 * and the Hessian H of el__spline_hessian, exact there (every span solved: R = 0):
 * - along +z and -z: t = T0, T0 x TGROW, ... up to TMAX rad while E falls (the least
 *   energy kept; a span that fails stops the walk);
 * - from the lowest: Newton on E with H shifted to positive definite where it is not
 *   (H + tau I, tau = max(0, delta - lambda_min): the Levenberg-Marquardt / Goldfeld
 *   modification, Nocedal & Wright 3.4), each step at most MAXSTEP rad, halved until
 *   Armijo's decrease of E holds, until |F| <= DESCENT_F;
 * - then el__chain_newton on the whole chain (the solver's own: its knot equations and
 *   the pieces' together) to the options' tol, from those angles and pieces.
 * Kept: the lower-energy of the two signs' results that are solutions, minima
 * (el__spline_unstable 0), lower than the equilibrium's energy and follow their ducks
 * (el_spline_result's loops 0: the solver's own preference, spline_fair.c). A span whose
 * branch folds on the way (its Hermite problem has no solution near its last one) takes
 * the least-energy Hermite elastica of its end angles (el__spiece_hermite): past the fold the
 * stable batten's sliding span is on another branch (the 170-deg ducks at sigma 1e-2: the
 * batten 22.0 long before, 70.4 after). GSL's symmetric
 * tridiagonal solver for the steps; the descent is written here because GSL's
 * multimin would re-solve every span for each of its function calls with no Hessian
 * (its BFGS needs O(n) times as many), and H is at hand.
 */
enum { WALK = 24, DESCENT = 200, HALVE = 30 };
static const double T0 = 0.01, TGROW = 1.5, TMAX = 3.0, MAXSTEP = 0.5, DESCENT_F = 1e-8;

/* E at the knot angles w->x, every piece re-solved from its current v; INFINITY where one
 * fails (its v then as Newton left it) */
static double energy_at(el__spchain *w)
{
    double E = 0.0;
    for (size_t j = 0; j < w->m; j++) {
        el__spiece *pc = &w->pc[j];
        el__sptargets t;
        el__chain_targets(w, j, &t);
        /* its branch followed; where that folds, the least-energy Hermite elastica of
         * those end angles (the branch a span past the fold takes) */
        if (el__spiece_newton(pc, &t, 0.1 * w->aim) &&
            (el__spiece_hermite(pc, &t) || el__spiece_newton(pc, &t, 0.1 * w->aim)))
            return INFINITY;
        E += pc->energy + w->sigma * pc->v[EL__SP_L];
    }
    return E;
}

static void save(const el__spchain *w, double *x, double *v)
{
    memcpy(x, w->x, w->n * sizeof *x);
    for (size_t j = 0; j < w->m; j++) memcpy(v + EL__NV * j, w->pc[j].v, sizeof w->pc[j].v);
}

static void load(el__spchain *w, const double *x, const double *v)
{
    memcpy(w->x, x, w->n * sizeof *x);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].v, v + EL__NV * j, sizeof w->pc[j].v);
}

/* the least eigenvalue of dg, up on rows i0..i1: bisection on the negative count between
 * Gershgorin's bound and its upper one */
static double least_eigenvalue(const double *dg, const double *up, size_t i0, size_t i1)
{
    double lo = 0.0, hi = 0.0;
    for (size_t i = i0; i <= i1; i++) {
        const double r = (i > i0 ? fabs(up[i - 1]) : 0.0) + (i < i1 ? fabs(up[i]) : 0.0);
        lo = fmin(lo, dg[i] - r);
        hi = fmax(hi, dg[i] + r);
    }
    for (int it = 0; it < 200 && hi - lo > 1e-14 * (fabs(lo) + fabs(hi)); it++) {
        const double mid = 0.5 * (lo + hi);
        if (el__tridiag_negatives(dg, up, i0, i1, mid)) hi = mid; else lo = mid;
    }
    return lo;
}

/* The descent of the header from the chain's state (every piece solved for w->x, energy
 * *E): EL_OK at |F| <= DESCENT_F, else EL_ENOCONV; g, d, xs, vs: work (n, n, n, EL__NV m) */
static int descend(el__spchain *w, size_t i0, size_t i1, double *E, double *g, double *d, double *xs,
                   double *vs)
{
    for (int it = 0; it < DESCENT; it++) {
        if (!isfinite(el__chain_eval(w, 1))) return EL_ENOCONV;
        double fmax_ = 0.0;
        for (size_t i = i0; i <= i1; i++) {
            g[i] = 2.0 * w->F[i] / w->ell[i];   /* dE / d theta_i (file comment) */
            fmax_ = fmax(fmax_, fabs(w->F[i]));
        }
        if (fmax_ <= DESCENT_F) return EL_OK;
        el__spline_hessian(w);
        double *dg = w->dg, *up = w->up, hmax = 0.0;
        for (size_t i = i0; i <= i1; i++) hmax = fmax(hmax, fabs(dg[i]));
        const double lmin = least_eigenvalue(dg, up, i0, i1), delta = 1e-3 * hmax + 1e-12;
        const double tau = lmin < delta ? delta - lmin : 0.0;
        for (size_t i = i0; i <= i1; i++) { dg[i] += tau; w->b[i] = -g[i]; }
        const size_t k = i1 - i0 + 1;
        if (k == 1) d[i0] = w->b[i0] / dg[i0];
        else {
            gsl_vector_view dv = gsl_vector_view_array(dg + i0, k), ev = gsl_vector_view_array(up + i0, k - 1);
            gsl_vector_view bv = gsl_vector_view_array(w->b + i0, k), xv = gsl_vector_view_array(d + i0, k);
            if (gsl_linalg_solve_symm_tridiag(&dv.vector, &ev.vector, &bv.vector, &xv.vector)) return EL_ENOCONV;
        }
        double slope = 0.0, dm = 0.0;
        for (size_t i = i0; i <= i1; i++) { slope += g[i] * d[i]; dm = fmax(dm, fabs(d[i])); }
        if (!(slope < 0.0) || !isfinite(dm)) return EL_ENOCONV;
        double al = dm > MAXSTEP ? MAXSTEP / dm : 1.0;
        save(w, xs, vs);
        int ok = 0;
        for (int h = 0; h < HALVE && !ok; h++, al *= 0.5) {
            load(w, xs, vs);
            for (size_t i = i0; i <= i1; i++) w->x[i] = xs[i] + al * d[i];
            const double En = energy_at(w);
            ok = En <= *E + 1e-4 * al * slope;
            if (ok) *E = En;
        }
        if (!ok) { load(w, xs, vs); energy_at(w); return EL_ENOCONV; }
    }
    return EL_ENOCONV;
}

int el__spline_stabilise(el__spchain *w)
{
    const size_t n = w->n, m = w->m;
    const size_t i0 = w->slot[0] == EL__SLOT_ANGLE ? 0 : 1;
    const size_t i1 = w->slot[n - 1] == EL__SLOT_ANGLE ? n - 1 : n - 2;
    double *buf = malloc((7 * n + 3 * EL__NV * m) * sizeof *buf);
    if (!buf) return EL_ENOMEM;
    double *z = buf, *x0 = z + n, *xb = x0 + n, *g = xb + n, *d = g + n, *xs = d + n, *xk = xs + n;
    double *v0 = xk + n, *vb = v0 + EL__NV * m, *vs = vb + EL__NV * m;
    const double zm = el__max_abs(w->z, n);   /* the vector of its largest angle 1 */
    for (size_t i = 0; i < n; i++) z[i] = w->z[i] / zm;
    save(w, x0, v0);
    const int iters = w->iterations;
    double E0 = 0.0;
    for (size_t j = 0; j < m; j++) E0 += w->pc[j].energy + w->sigma * w->pc[j].v[EL__SP_L];
    double Ebest = E0;
    int found = 0;
    for (int sgn = -1; sgn <= 1; sgn += 2) {
        load(w, x0, v0);
        double E = E0, t = T0, tk = 0.0;
        save(w, xk, vs);   /* the lowest point of the walk */
        for (int s = 0; s < WALK && t <= TMAX; s++, t *= TGROW) {
            for (size_t i = i0; i <= i1; i++) w->x[i] = x0[i] + sgn * t * z[i];
            const double Et = energy_at(w);
            if (!(Et < E)) break;
            E = Et;
            tk = t;
            save(w, xk, vs);
        }
        if (tk == 0.0) continue;
        load(w, xk, vs);
        energy_at(w);
        descend(w, i0, i1, &E, g, d, xs, vs);
        /* the solver's Newton on the whole chain to tol from there: a solution, a minimum,
         * below the equilibrium and the other sign's */
        if (el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol)) continue;
        double En = 0.0;
        for (size_t j = 0; j < m; j++) En += w->pc[j].energy + w->sigma * w->pc[j].v[EL__SP_L];
        size_t sp;
        if (!(En < Ebest) || el__spline_unstable(w, &sp) != 0) continue;
        /* and follows its ducks (el_spline_result's loops: no crossing of its own, at most
         * 4 x their polygon), as every tension solution the solver keeps (spline_fair.c) */
        double poly = 0.0, L = 0.0;
        for (size_t j = 0; j < m; j++) { poly += w->pc[j].h; L += w->pc[j].v[EL__SP_L]; }
        const int cr = L > 4.0 * poly ? 1 : el__chain_crosses(w);
        if (cr < 0) { free(buf); return EL_ENOMEM; }
        if (cr) continue;
        Ebest = En;
        found = 1;
        save(w, xb, vb);
    }
    load(w, found ? xb : x0, found ? vb : v0);
    if (!found) w->iterations = iters;
    el__chain_eval(w, 1);
    free(buf);
    return found ? EL_OK : EL_ENOCONV;
}
