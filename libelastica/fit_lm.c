/*
 * Levenberg-Marquardt on the fit's objective (fit_internal.h), the common path of every
 * fit: no bounds, no constraints, a handful of variables, n of 10^1..10^6 residuals.
 *
 * Why by hand and not GSL's gsl_multifit_nlinear / gsl_multilarge_nlinear: the first
 * stores the n x p Jacobian, the second (which takes J^T J from a callback, as here)
 * keeps five residual-length vectors (f, f_trial, two work vectors and the unused
 * geodesic-acceleration vector): 80 bytes per point for the paired fit, which alone
 * exceeds the memory budget of a 10^6-point fit (80 MiB). This solver needs only f, the
 * gradient and the p x p normal equations, which el__fit_objective_eval computes block by
 * block in the same pass as the residuals; and a trial point's normal equations come
 * with its objective (a step is usually accepted), so an accepted iteration costs one
 * evaluation. The iteration itself is the textbook one (Nielsen's damping update, as in
 * GSL; More's scaling by the largest diagonal of J^T J seen), with GSL's Cholesky for
 * the p x p solve.
 *
 * Certificate (the first-order condition): a point is a minimum to working precision when
 * its gradient, measured in the norm of the Gauss-Newton matrix, is at the rounding
 * level of the objective: g^T (J^T J)^-1 g <= 1e-13 |r|^2 (a full Gauss-Newton step
 * would lower f by less than 1e-13 of itself; the parameters are then within ~1e-6 of
 * their statistical error of their optimum), or when the rms residual is at the
 * rounding level of the model's evaluation, 1e-11 of the data's rms radius (FIT_EXACT_F).
 * With lazy feet (orthogonal fits) the condition is checked again after the feet have
 * been projected exactly.
 */
#include "fit_internal.h"
#include <string.h>

enum { LM_ROUNDS = 4, LM_RATE_SPAN = 10 };

/* (H + lambda diag(D)) d = -g by Cholesky. J^T J of nearly dependent columns can be
 * indefinite in rounding; then a ridge of 1e-12 .. 1e-4 diag(D) is tried for this solve
 * only (the damping itself is the trust region's business). EL_ESINGULAR if none works. */
static int lm_step(const fit_value *v, const double *D, double lambda, int nx, double *d)
{
    double A[FIT_MAXX * FIT_MAXX];
    for (double ridge = 0.0; ridge <= 1e-4; ridge = ridge == 0.0 ? 1e-12 : ridge * 1e4) {
        const double lam = fmax(lambda, ridge);
        memcpy(A, v->H, sizeof(double) * (size_t)(nx * nx));
        for (int j = 0; j < nx; j++) {
            A[j * nx + j] += lam * D[j];
            d[j] = -v->g[j];
        }
        if (el__cholesky_solve(A, nx, d) == EL_OK) return EL_OK;   /* dense.c */
    }
    return EL_ESINGULAR;
}

int el__fit_first_order(const fit_value *v, int nx, double tol)
{
    if (!(v->f > FIT_EXACT_F)) return 1;
    /* the gradient in the norm of the Gauss-Newton matrix: g^T H^-1 g, twice the
     * decrease a full Gauss-Newton step would still bring */
    double d[FIT_MAXX], D[FIT_MAXX] = {0};
    for (int j = 0; j < nx; j++) D[j] = fmax(v->H[j * nx + j], 1e-300);
    if (lm_step(v, D, 0.0, nx, d)) return 0;
    double dec = 0.0;
    for (int j = 0; j < nx; j++) dec -= v->g[j] * d[j];
    return dec <= tol * 2.0 * v->f;
}

/* The first-order condition on the rows' tangent space (a fit whose constraint rows A x = c
 * are met): the Gauss-Newton step restricted to A d = 0, by the KKT system
 * [H A^T; A 0] [d; lambda] = [-g; 0] (H d + A^T lambda = -g, so d^T H d = -g^T d), and
 * -g^T d <= tol 2f as in el__fit_first_order (twice the decrease the step would bring).
 * A: m x nx row-major, the rows' derivatives; m = 0 is el__fit_first_order. */
int el__fit_first_order_rows(const fit_value *v, const double *A, int m, int nx, double tol)
{
    if (!(v->f > FIT_EXACT_F)) return 1;
    const int K = nx + m;
    double M[(FIT_MAXX + FIT_NCON) * (FIT_MAXX + FIT_NCON)], b[FIT_MAXX + FIT_NCON];
    int perm[FIT_MAXX + FIT_NCON];
    if (m < 0 || m > FIT_NCON) return 0;
    for (int i = 0; i < K; i++)
        for (int j = 0; j < K; j++) {
            double e = 0.0;
            if (i < nx && j < nx) e = v->H[i >= j ? i * nx + j : j * nx + i];   /* lower triangle */
            else if (i >= nx && j < nx) e = A[(i - nx) * nx + j];
            else if (i < nx && j >= nx) e = A[(j - nx) * nx + i];
            M[i * K + j] = e;
        }
    for (int i = 0; i < K; i++) b[i] = i < nx ? -v->g[i] : 0.0;
    if (el__lu_factor(M, K, perm)) return 0;
    el__lu_solve(M, K, perm, b);
    double dec = 0.0;
    for (int j = 0; j < nx; j++) dec -= v->g[j] * b[j];
    return isfinite(dec) && dec <= tol * 2.0 * v->f;
}

/* |d|_D = sqrt(sum D_j d_j^2), the step length in the scaled variables. */
static double scaled_norm(const double *d, const double *D, int nx)
{
    double s = 0.0;
    for (int j = 0; j < nx; j++) s += D[j] * d[j] * d[j];
    return sqrt(s);
}

/* After a rejected step of scaled length len: the damping (at least lambda) whose step
 * is at most that long, by factors of 4 (7 x 7 solves, no evaluation). A plain
 * lambda *= nu leaves the step unchanged while lambda is below the small eigenvalues
 * of the scaled J^T J (measured: five rejected evaluations in a row from lambda = 1e-9
 * on a gently curved arc before the step shortened at all). */
static double damping_for(const fit_value *v, const double *D, double lambda, int nx, double len)
{
    double d[FIT_MAXX];
    for (int t = 0; t < 40 && lambda < 1e20; t++) {
        if (!lm_step(v, D, lambda, nx, d) && scaled_norm(d, D, nx) <= len) break;
        lambda *= 4.0;
    }
    return lambda;
}

static void scaling(const fit_value *v, int nx, double *D)
{
    double mx = 0.0;
    for (int j = 0; j < nx; j++) mx = fmax(mx, v->H[j * nx + j]);
    for (int j = 0; j < nx; j++) D[j] = fmax(D[j], fmax(v->H[j * nx + j], 1e-30 * mx + 1e-300));
}

int el__fit_lm(fit_objective *o, const double *x0, int max_iter, fit_solution *sol)
{
    const int nx = o->map.nx;
    const int lazy = fit_has_feet(o) && !o->exact_feet;
    fit_value val, trial;
    double x[FIT_MAXX], xt[FIT_MAXX], d[FIT_MAXX], D[FIT_MAXX] = {0};
    memcpy(x, x0, sizeof(double) * (size_t)nx);
    int st = el__fit_objective_eval(o, x, 1, &val);
    if (st) return st;
    el__fit_objective_accept(o);
    scaling(&val, nx, D);
    double lambda = 1e-9, nu = 2.0, recent[LM_RATE_SPAN];
    int iters = 0, rounds = 0, certified = 0, stalled = 0;
    while (iters < max_iter) {
        /* hopeless against o->f_ceiling: the decrease of the last LM_RATE_SPAN
         * iterations, kept up for the remaining ones, would not get there */
        if (iters >= 2 * LM_RATE_SPAN && val.f > o->f_ceiling &&
            (recent[iters % LM_RATE_SPAN] - val.f) / LM_RATE_SPAN * (max_iter - iters) < val.f - o->f_ceiling)
            break;
        recent[iters % LM_RATE_SPAN] = val.f;
        if (el__fit_first_order(&val, nx, o->lm_tol) || !(val.f > FIT_EXACT_F)) {
            /* with lazy feet the certificate needs feet at rest: moved by u < 1e-6 in the
             * evaluation (whose rows are those of the moved feet), they are the nearest
             * points to O(kappa u^2) ~ 1e-12, and the gradient is off by that relative to
             * |r| |J|, far below the certificate's sqrt(1e-13) (a tighter bound cost one
             * more evaluation on most fits) */
            if (!lazy || o->last_move <= 1e-6) { certified = 1; break; }
            if (rounds++ >= LM_ROUNDS) break;
            /* the feet one Newton step on at the same x (an accepted step has already
             * moved them: accepting again would swap back to the older feet) */
            if ((st = el__fit_objective_eval(o, x, 1, &val))) break;
            el__fit_objective_accept(o);
            continue;
        }
        if (lm_step(&val, D, lambda, nx, d)) {
            lambda *= nu; nu *= 2.0;
            if (lambda > 1e20) break;
            continue;
        }
        /* a step leaving the model's domain stops short of its boundary */
        const double alpha = el__fit_map_step_limit(&o->map, x, d);
        for (int i = 0; i < nx; i++) d[i] *= alpha;
        double pred = 0.0, dHd = 0.0;
        for (int i = 0; i < nx; i++) {
            double t = 0.0;
            for (int j = 0; j < nx; j++) t += val.H[i * nx + j] * d[j];
            dHd += d[i] * t;
            pred -= val.g[i] * d[i];
            xt[i] = x[i] + d[i];
        }
        pred -= 0.5 * dHd;
        iters++;
        const int ok = el__fit_objective_eval(o, xt, 1, &trial) == EL_OK;
        const double rho = ok && pred > 0.0 ? (val.f - trial.f) / pred : -1.0;
        /* a step whose predicted gain is below the objective's rounding (the residuals
         * are known to ~1e-14 of the curve's size, f to ~1e-12 of itself on noisy
         * data) cannot be judged by f: taken when the first-order condition holds at the
         * trial point and f is the same there to that rounding (measured: the decrease
         * 5e-14 f short of the certificate's 1e-13, every step then "rejected" by 1e-13 f
         * of noise until the damping ran out and Ipopt polished for 50 ms) */
        const int rounding = ok && pred <= 1e-12 * val.f && trial.f <= val.f * (1.0 + 1e-12) &&
                             el__fit_first_order(&trial, nx, 1e-13);
        if (rounding || (ok && trial.f < val.f && rho > 1e-4)) {
            const double rel = (val.f - trial.f) / val.f;
            memcpy(x, xt, sizeof(double) * (size_t)nx);
            val = trial;
            el__fit_objective_accept(o);
            scaling(&val, nx, D);
            const double c = 2.0 * fmin(fmax(rho, 0.0), 1.0) - 1.0;
            lambda *= fmax(1.0 / 3.0, 1.0 - c * c * c);
            nu = 2.0;
            /* the decrease is at rounding level: no later step can be told from noise */
            if ((rel < 1e-15 || rounding) && !lazy) break;
        } else {
            /* a rejected step from a point already within the stall certificate (below):
             * shorter steps would only be judged by rounding too */
            if (ok && el__fit_first_order(&val, nx, 1e-11)) { stalled = 1; break; }
            lambda = damping_for(&val, D, lambda * nu, nx, (ok ? 0.25 : 0.1) * scaled_norm(d, D, nx));
            nu *= 2.0;
            if (lambda > 1e20) { stalled = 1; break; }
        }
    }
    /* No step lowers f any more (the damping ran out, or a step failed from a point as
     * close as this): the point is a minimum to the
     * accuracy of the evaluation when the Gauss-Newton decrease is within 1e-11 of f
     * (measured: on a loop of k = 11 the decrease g^T H^-1 g of nearby points scattered
     * over 2e-19 .. 5e-18 with the certificate's bound at 1.3e-18, the Jacobian's own
     * rounding; the parameters are then within 3e-6 of their statistical error of the
     * optimum). */
    const double tol = stalled ? 1e-11 : 1e-13;
    if (lazy && !certified) {
        /* what is returned is measured at exact feet */
        if (el__fit_objective_project(o, x) == EL_OK && el__fit_objective_eval(o, x, 1, &val) == EL_OK)
            certified = el__fit_first_order(&val, nx, tol) || !(val.f > FIT_EXACT_F);
    }
    memcpy(sol->x, x, sizeof(double) * (size_t)nx);
    sol->val = val;
    sol->iters = iters;
    sol->certified = certified || el__fit_first_order(&val, nx, tol);
    return EL_OK;
}
