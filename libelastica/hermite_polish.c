/*
 * A Hermite solution against its data (seed 004): its end residual, measured as
 * el_smooth_eval gives the curve's ends, and the polish that moves a curve found by the
 * solver's variables (the normalised frame's curvature data) onto the data in the curve's
 * own parameters: Newton on (phi, mu, k, q, length), then Gauss-Newton with k held at its
 * nearest doubles (near the separatrix, where the ulp of k moves the end). hermite.c's
 * roots, hermite_near.c's near-straight curve and hermite_case3.c's curves use it.
 */
#include "hermite_internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <float.h>
#include <string.h>

static double angle_err(double a, double b) { return fabs(el__hermite_wrap_pi(a - b)); }

/* The end residual of the curve p from the ends' values xy, th at s = 0 and L. */
static double end_residual(const hframe *fr, const double xy[4], const double th[2])
{
    const double *a = fr->p0, *b = fr->p1;
    double e = fmax(hypot(xy[0] - a[0], xy[1] - a[1]), hypot(xy[2] - b[0], xy[3] - b[1])) / fr->d;
    return fmax(e, fmax(angle_err(th[0], fr->psi0), angle_err(th[1], fr->psi1)));
}

/* End residual of a solution measured as el_smooth_eval gives its ends. */
int el__hermite_residual(const hframe *fr, const el_hermite_solution *s, double *res)
{
    double xy[4], th[2];
    int rc = el__smooth_ends(&s->curve, xy, th);
    if (rc) return rc;
    *res = end_residual(fr, xy, th);
    return EL_OK;
}

/* A polished solution's end curvatures, from its curve (make_solution's were the root's) */
static int end_curvatures(el_hermite_solution *t)
{
    const double ends[2] = {0.0, t->curve.length};
    double kappa[2];
    const int rc = el_smooth_eval(&t->curve, 2, ends, NULL, NULL, kappa);
    if (!rc) {
        t->kappa0 = kappa[0];
        t->kappa1 = kappa[1];
    }
    return rc;
}

/* A polish's outcome: the curve p, at end residual res, replaces s's where res is lower, with
 * its length, energy and end curvatures (by length its sigma too: sigma = 2 mu (2k^2 - 1),
 * |F| of seed 004 (8) in the header's parametrisation, hermite.c); s is left as it was where
 * res is not lower or p's energy or end curvatures fail. */
static void adopt_if_lower(int mode, const el_smooth_params *p, double res, el_hermite_solution *s)
{
    if (!(res < s->residual)) return;
    el_hermite_solution t = *s;
    t.curve = *p;
    t.length = p->length;
    t.residual = res;
    if (mode == EL_HERMITE_LENGTH) t.sigma = 2.0 * p->mu * (2.0 * p->k * p->k - 1.0);
    if (el_smooth_energy(p, &t.energy) || end_curvatures(&t)) return;
    *s = t;
}

/* Residual vector of a solution for the polish (its ends as el_smooth_eval gives them):
 * end point (2, / d), tangent angles at both ends (2), and the mode's scalar condition
 * (sigma or length);
 * *res (if res) gets the end residual (el__hermite_residual()) of the same evaluation. */
static int polish_res(const hframe *fr, const el_smooth_params *p, int mode, double target,
                      double *r, double *res)
{
    double xy[4], th[2];
    int rc = el__smooth_ends(p, xy, th);
    if (rc) return rc;
    if (res) *res = end_residual(fr, xy, th);
    r[0] = (xy[2] - fr->p1[0]) / fr->d;
    r[1] = (xy[3] - fr->p1[1]) / fr->d;
    r[2] = el__hermite_wrap_pi(th[0] - fr->psi0);
    r[3] = el__hermite_wrap_pi(th[1] - fr->psi1);
    r[4] = mode == EL_HERMITE_TENSION
               ? (2.0 * p->mu * (2.0 * p->k * p->k - 1.0) - target) * fr->d * fr->d / (1.0 + fabs(target) * fr->d * fr->d)
               : (p->length - target) / fr->d;
    return EL_OK;
}

/* The polish's step test: -1 if q is invalid, else 1 if its end residual (the
 * first four entries of polish_res, max norm) is below that of r, else 0; rq gets
 * q's residual vector, *res its end residual. */
static int step_improves(const hframe *fr, int mode, double target, const el_smooth_params *q,
                         const double *r, double *rq, double *res)
{
    if (el_smooth_check(q) || polish_res(fr, q, mode, target, rq, res)) return -1;
    double n0 = 0.0, n1 = 0.0;
    for (int i = 0; i < 4; i++) { n0 = fmax(n0, fabs(r[i])); n1 = fmax(n1, fabs(rq[i])); }
    return n1 < n0;
}

/* Newton on (phi, mu, k, q, length) with a finite-difference Jacobian, for the
 * solutions whose end residual, measured with el_smooth_eval, misses tol by a
 * little (near the separatrix k = 1 the map from kappa0 to the parameters is
 * ill-conditioned). Keeps the result only when the residual improves. */
void el__hermite_polish_newton(const hframe *fr, int mode, double target, el_hermite_solution *s)
{
    el_smooth_params p = s->curve;
    double r[5], res, J[25], *v[5] = {&p.phi, &p.mu, &p.k, &p.q, &p.length};
    if (polish_res(fr, &p, mode, target, r, &res)) return;
    for (int j = 0; j < 5; j++) {
        /* k: a step relative to the distance from the separatrix, where gamma
         * varies on the scale |k| - 1 (the period grows like log 1/||k| - 1|) */
        const double v0 = *v[j];
        const double h = j == 2 ? 1e-7 * fmin(fabs(v0) + 1e-3, fmax(fabs(fabs(v0) - 1.0), 1e-9))
                                : 1e-7 * (fabs(v0) + (j == 1 ? p.mu : 1e-3));
        double rp[5], rm[5];
        *v[j] = v0 + h;
        int e1 = polish_res(fr, &p, mode, target, rp, NULL);
        *v[j] = v0 - h;
        int e2 = polish_res(fr, &p, mode, target, rm, NULL);
        *v[j] = v0;
        if (e1 || e2) return;
        for (int i = 0; i < 5; i++) J[i * 5 + j] = (rp[i] - rm[i]) / (2.0 * h);
    }
    /* J dv = -r by LU with partial pivoting (dense.c); the start's Jacobian serves
     * every step (a chord method: the steps are ~ the residual, < 1e-5, so J changes
     * by far less than the convergence notices, and a step costs one evaluation
     * instead of eleven) */
    int perm[5];
    if (el__lu_factor(J, 5, perm)) return;
    for (int it = 0; it < 4; it++) {
        double dv[5];
        for (int i = 0; i < 5; i++) dv[i] = -r[i];
        el__lu_solve(J, 5, perm, dv);
        for (int i = 0; i < 5; i++) if (!isfinite(dv[i])) return;
        el_smooth_params q = p;
        q.phi += dv[0]; q.mu += dv[1]; q.k += dv[2]; q.q += dv[3];
        if (mode == EL_HERMITE_TENSION) q.length += dv[4]; /* length mode: L stays exact */
        double rq[5], resq;
        const int better = step_improves(fr, mode, target, &q, r, rq, &resq);
        if (better < 0) return;
        if (!better) break;
        p = q;
        memcpy(r, rq, sizeof r);
        res = resq;
    }
    adopt_if_lower(mode, &p, res, s);
}

/* The finite-difference Jacobian (4 x 3, row-major) of the end conditions (the first
 * four entries of polish_res) in polish_fixed_k's parameters at p; nonzero if p or a
 * perturbed p is invalid. */
static int fixed_k_jacobian(const hframe *fr, int mode, double target, el_smooth_params p, double *J)
{
    double *v[3] = {&p.phi, &p.q, mode == EL_HERMITE_TENSION ? &p.length : &p.mu};
    for (int c = 0; c < 3; c++) {
        const double v0 = *v[c], h = 1e-7 * (fabs(v0) + (c == 2 ? fabs(v0) : 1e-3));
        double rp[5], rm[5];
        int bad;
        *v[c] = v0 + h;
        bad = el_smooth_check(&p) || polish_res(fr, &p, mode, target, rp, NULL);
        *v[c] = v0 - h;
        bad |= el_smooth_check(&p) || polish_res(fr, &p, mode, target, rm, NULL);
        *v[c] = v0;
        if (bad) return 1;
        for (int i = 0; i < 4; i++) J[i * 3 + c] = (rp[i] - rm[i]) / (2.0 * h);
    }
    return 0;
}

/* Second polish for the solutions the first one leaves above tol: near the
 * separatrix |dgamma(L)/dk| is 1e6..1e8 at fixed (phi, mu, q, L) (sigma
 * |p1-p0|^2 > ~100), so the ulp of the stored k alone moves the end by 1e-10..1e-8,
 * whatever the accuracy of el_smooth_eval (~1e-13 there, checked against a
 * 40-digit evaluation). The rounding of k is compensated by the other
 * parameters: for each k among the nearest few doubles, with the mode's
 * condition kept exact (tension: mu = sigma / (2 (2k^2 - 1)); length: L fixed),
 * Gauss-Newton on the remaining three parameters (tension: phi, q, L; length:
 * phi, mu, q) fits the four end conditions in least squares (GSL QR); the best
 * curve is kept if it improves the residual. */
void el__hermite_polish_fixed_k(const hframe *fr, int mode, double target, el_hermite_solution *s)
{
    el_smooth_params best = s->curve;
    double best_res = s->residual, J[12], tau[3];
    int have_J = 0, no_J = 0;
    for (int j = -4; j <= 4; j++) {
        el_smooth_params p = s->curve;
        for (int i = 0; i < abs(j); i++) p.k = nextafter(p.k, j > 0 ? INFINITY : -INFINITY);
        if (mode == EL_HERMITE_TENSION) p.mu = target / (2.0 * (2.0 * p.k * p.k - 1.0));
        if (el_smooth_check(&p)) continue;
        double r[5], res;
        if (polish_res(fr, &p, mode, target, r, &res)) continue;
        /* the Jacobian (QR-factored) of the first valid k serves every k and step (a
         * chord method): the k are a few ulps apart and the steps ~ the residual, so
         * it changes by ~1e-8 relative between them, far below what Gauss-Newton's
         * convergence notices, and the k are 1 + 4 evaluations each instead of ~30 */
        if (!have_J && !no_J) {
            gsl_matrix_view Jm = gsl_matrix_view_array(J, 4, 3);
            gsl_vector_view tv = gsl_vector_view_array(tau, 3);
            have_J = !fixed_k_jacobian(fr, mode, target, p, J) &&
                     gsl_linalg_QR_decomp(&Jm.matrix, &tv.vector) == GSL_SUCCESS;
            no_J = !have_J;
        }
        for (int it = 0; it < 4 && have_J; it++) {
            double rhs[4], dv[3], lsr[4];
            for (int i = 0; i < 4; i++) rhs[i] = -r[i];
            gsl_matrix_view Jm = gsl_matrix_view_array(J, 4, 3);
            gsl_vector_view bv = gsl_vector_view_array(rhs, 4), xv = gsl_vector_view_array(dv, 3);
            gsl_vector_view tv = gsl_vector_view_array(tau, 3), rv = gsl_vector_view_array(lsr, 4);
            if (gsl_linalg_QR_lssolve(&Jm.matrix, &tv.vector, &bv.vector, &xv.vector, &rv.vector) != GSL_SUCCESS)
                break;
            el_smooth_params q = p;
            double *w[3] = {&q.phi, &q.q, mode == EL_HERMITE_TENSION ? &q.length : &q.mu};
            for (int c = 0; c < 3; c++) *w[c] += isfinite(dv[c]) ? dv[c] : NAN;
            double rq[5], resq;
            if (step_improves(fr, mode, target, &q, r, rq, &resq) != 1) break;
            p = q;
            memcpy(r, rq, sizeof r);
            res = resq;
        }
        if (!(res < best_res)) continue;
        best = p;
        best_res = res;
    }
    adopt_if_lower(mode, &best, best_res, s);
}
/* polish, then polish_fixed_k where it misses tol, and the end curvatures from the curve
 * (hermite_near.c's near-straight curve at |sigma| |p1 - p0|^2 <= 10) */
int el__hermite_polish(const hframe *fr, double sigma, double tol, el_hermite_solution *s)
{
    el__hermite_polish_newton(fr, EL_HERMITE_TENSION, sigma, s);
    if (s->residual > tol) el__hermite_polish_fixed_k(fr, EL_HERMITE_TENSION, sigma, s);
    return end_curvatures(s);
}

/* polish (once even where the residual is within tol: a start that meets the ends to just
 * tol is polished below it), then again while it improves and misses tol (a start ~1e-3 off:
 * the chord method's four steps from there), polish_fixed_k where it still misses tol, in
 * either mode (target: the given sigma or length), and the end curvatures from the curve
 * (hermite_case3.c's curves) */
int el__hermite_polish_to(const hframe *fr, int mode, double target, double tol, el_hermite_solution *s)
{
    for (int i = 0; i < 4 && (i == 0 || s->residual > tol); i++) {
        const double before = s->residual;
        el__hermite_polish_newton(fr, mode, target, s);
        if (!(s->residual < before)) break;
    }
    if (s->residual > tol) el__hermite_polish_fixed_k(fr, mode, target, s);
    return end_curvatures(s);
}

/* Whether the curve p is at most one curvature period long (to 1e-12 relative; with
 * rounding, also to the period's uncertainty from the double k, DBL_EPSILON / (k'^2 K)
 * relative: one ulp of k moves K by ~eps / k'^2 (K ~ ln(4 / k'), dK / d(k'^2) = -1 / (2 k'^2)),
 * which near the separatrix exceeds it: 1.3 % at k = 1 + 2 ulps, where a loop polished onto
 * exact data runs that far past its double k's period; without it the loop at a = 0, d = 1e-3,
 * sigma d^2 1762 is lost): kappa = kappa_m cn(u; k), period 4 K(k) in u, for |k| < 1; kappa =
 * 2 k sqrt(mu) dn(|k| u; 1/|k|), period 2 K(1/|k|) in |k| u, for |k| > 1 (the header's
 * parametrisation). k' and K are the evaluator's (el__modulus_init: k'^2 from sqrt(|k| - 1)
 * sqrt(|k| + 1) / |k|, exact to a few ulps as k -> 1, where (1 - g)(1 + g) of g = 1 / |k|
 * lost it to ~eps / k'^2 relative). */
int el__hermite_within_period(const el_smooth_params *p, int rounding)
{
    const double k = fabs(p->k);
    el__modulus mod;
    /* (no period known: rejected, a curve longer than one would be added otherwise) */
    if (el__modulus_init(k, 0, &mod)) return 0;
    if (mod.kg == 1.0) return 1;   /* the separatrix: no period */
    if (!isfinite(mod.K)) return 0;
    const double period = (k < 1.0 ? 4.0 * mod.K : 2.0 * mod.K / k) / sqrt(p->mu);
    const double slack = 1e-12 + (rounding ? DBL_EPSILON / (mod.kp * mod.kp * mod.K) : 0.0);
    return p->length <= period * (1.0 + slack);
}
