/*
 * Bounds and constraints through Ipopt's C interface (fit_internal.h): what the
 * Levenberg-Marquardt path cannot do, and its fallback when a result is not certified.
 *
 *   minimise f(x) = (1/2n) sum r^2   subject to  xl <= x <= xu,  c(x) = 0,
 *
 * f and its gradient J^T r / n from el__fit_objective_eval (the feet projected at every
 * evaluation, from those of the line search's base: f is a function of x along a
 * search; the discrete model by distance: f alone at the line search's trial points,
 * ensure); the constraints (end point, tangent directions, curvatures at the ends) with
 * their analytic Jacobians from el__fit_end_state; the Hessian of the Lagrangian by
 * differences of its analytic gradient (cb_h). A tangent direction alpha is the
 * constraint sin(theta - alpha) = 0, smooth everywhere; the reversed direction
 * (cos < 0) is caught by the caller's check of the result.
 *
 * Options: no output, and no ipopt.opt: option_file_name "" makes Ipopt 3.11 read no
 * options file (checked: a file in the working directory with print_level 12 and
 * linear_solver ma57 changes nothing, tests/c/test_fit.c). Constraints are met to 1e-12
 * (normalised coordinates) at every accepted stop: constr_viol_tol and its acceptable twin.
 *
 * L-BFGS (el_fit_options.limited_memory; measured on 30 smooth fits of 20 uneven points
 * with 0.1 % noise, briefs/lbfgs_repro.py):
 * - no watchdog: it accepts a trial step, projects the smooth feet there, and may return
 *   to the earlier iterate, whose f is then evaluated with those feet (f at the same point
 *   1.6e-2 instead of 9.8e-4; the fit ended EL_EMAXITER at rms 0.0219 against 0.00507);
 * - 20 update pairs, not Ipopt's 6 for up to 7 variables: with 6 the matrix never spans
 *   the space, the line search halved ~14 times per iteration (18 981 evaluations in all;
 *   2 690 with 20), and the discrete fit of test_fit_lbfgs's sketch with a start tangent
 *   ended EL_EMAXITER;
 * - the low-rank update in the augmented system ('extended'): Ipopt's default
 *   Sherman-Morrison calls MUMPS, each call at its fixed cost, for each of the 2 x 20
 *   update vectors at every iteration (one fit: 3.0e8 -> 1.1e8 instructions, the same
 *   iterates);
 * - without constraint rows or bounds, the stop is the first-order certificate (cb_iter),
 *   and Ipopt's 'acceptable' stop (a gradient below 1e-6 for 15 iterations) is off: it
 *   ended noise-free 1000-point fits at rms up to 2.5e-8 of the length. (At an active
 *   bound the gradient does not vanish: the certificate would never hold, and 23 of 24
 *   fits with a k or length range ended uncertified, EL_ENOCONV.)
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <IpStdCInterface.h>

/* Debian's MUMPS (dmumps_seq, Ipopt's only linear solver here) keeps Fortran module
 * state and crashes when two solves run at once (checked: 4 threads abort in
 * DMUMPS_LOAD_INIT). The one piece of process-wide state in the library is therefore
 * this lock: concurrent fits are safe, their Ipopt solves run one at a time (the common
 * path, fit_lm.c, takes no lock). */
static pthread_mutex_t ipopt_lock = PTHREAD_MUTEX_INITIALIZER;

enum { LBFGS_FLAT = 3, LBFGS_RATE_SPAN = 10 };     /* cb_iter */
#define FIT_ROWS_TOL 1e-12     /* constr_viol_tol: the rows met (normalised units) */
/* cb_iter's rate test with rows (o->rows_cap) at iterates within this of them (Ipopt's inf_pr,
 * normalised units: 1e-4 of the points' rms radius, Ipopt's own default constr_viol_tol; the
 * runs it stops crept along the rows at 1e-5 .. 1e-13 off them, 15-65 x the kept f) */
#define ROWS_NEAR 1e-4

typedef struct ipctx {
    fit_objective *o;
    const fit_constraints *con;
    int nx, m, limited_memory;
    double xkey[FIT_MAXX];
    int have, have_normal;  /* val at xkey, with g and H */
    fit_value val;
    double best_f, best_x[FIT_MAXX];
    double feas_f, feas_x[FIT_MAXX];    /* the lowest iterate that meets the rows (cb_grad) */
    int iters;
    double *tmp;
    double *anchor;     /* smooth feet: those of the last point whose gradient Ipopt took */
    int have_anchor;
    double gx[FIT_MAXX];    /* L-BFGS: the last point whose gradient Ipopt took, its value */
    fit_value gval;
    int have_g, certified;
    double last_f, recent[LBFGS_RATE_SPAN];     /* cb_iter's stall and rate tests */
    int flat, n_iter, max_iter;
    int free;               /* L-BFGS without constraint rows or bounds: cb_iter stops it */
    int rows_cap;           /* with rows: the rate test at iterates that meet them (o->rows_cap) */
    double rows_x[FIT_MAXX], rows[FIT_NCON];    /* the constraint rows at rows_x (keep_rows) */
    int have_rows;
} ipctx;

/* Whether c->val holds the objective at x (with g and H when normal). */
static int cached(const ipctx *c, const double *x, int normal)
{
    return c->have && (c->have_normal || !normal) && !memcmp(c->xkey, x, sizeof(double) * (size_t)c->nx);
}

/* The objective at x into c->val (with g and H when normal). Only f where that is the same
 * number without them: the discrete model by distance (its f from the polygon's
 * distances, computed before the Jacobian; the line search's trial points, most of the
 * evaluations, need no more). The smooth feet and the paired walk: always in full. */
static int ensure(ipctx *c, const double *x, int normal)
{
    if (cached(c, x, normal)) return EL_OK;
    const int want = normal || !c->o->poly;
    c->have = 0;
    /* every evaluation projects the feet from the same start, those of the point whose
     * gradient Ipopt took last (the line search's base): projected from the last trial's
     * instead, a foot could change branch between trials, f was then not continuous
     * along the search direction, and the line search halved alpha down to 5e-324
     * (~1075 evaluations) before Ipopt gave up (measured: a noisy 1000-point smooth fit
     * with L-BFGS, EL_ENOCONV after 246 iterations, 1.9 s; anchored EL_OK after 78,
     * 0.4 s, rms 1.012 of the exact Hessian's instead of 1.074) */
    if (c->have_anchor) memcpy(c->o->s, c->anchor, sizeof(double) * c->o->n);
    int st = el__fit_objective_eval(c->o, x, want, &c->val);
    if (st) return st;
    memcpy(c->xkey, x, sizeof(double) * (size_t)c->nx);
    c->have = 1;
    c->have_normal = want;
    if (c->val.f < c->best_f) {
        c->best_f = c->val.f;
        memcpy(c->best_x, x, sizeof(double) * (size_t)c->nx);
    }
    return EL_OK;
}

/* Constraint rows at x: values (and d/dx when J). */
int el__fit_constraint_rows(const fit_objective *o, const fit_constraints *con, const double *x,
                            double *c, double *J, int *which, double *tmp)
{
    const int nx = o->map.nx;
    double v[2][FIT_NP], M[FIT_NP * FIT_MAXX];
    if (el__fit_map_eval(&o->map, x, v, M)) return -1;
    fit_end e[2];
    int have[2] = {0, 0}, rows = 0;
    for (int bit = 0; bit < 6; bit++) {
        const int flag = 1 << bit;
        if (!(con->mask & flag) || flag == EL_CONSTRAIN_START_POINT) continue;
        const int at_end = flag == EL_CONSTRAIN_END_POINT || flag == EL_CONSTRAIN_END_TANGENT ||
                           flag == EL_CONSTRAIN_END_CURVATURE;
        if (!have[at_end]) {
            if (el__fit_end_state(o->map.model, v[0], o->n, at_end, &e[at_end], tmp)) return -1;
            have[at_end] = 1;
        }
        const fit_end *E = &e[at_end];
        double dc[2][FIT_NP];
        int nr = 1;
        if (flag == EL_CONSTRAIN_END_POINT) {
            nr = 2;
            c[rows] = E->xy[0] - con->end_xy[0];
            c[rows + 1] = E->xy[1] - con->end_xy[1];
            memcpy(dc, E->dxy, sizeof dc);
        } else if (flag == EL_CONSTRAIN_START_TANGENT || flag == EL_CONSTRAIN_END_TANGENT) {
            const double alpha = at_end ? con->end_theta : con->start_theta;
            /* 2 sin(delta / 2), delta = theta - alpha in [-pi, pi]: the signed distance of the
             * unit tangents, zero only where they agree (sin(delta) vanished at the reversed
             * tangent too, and Ipopt reported such points solved: measured, a discrete G1-G1
             * sketch of 59 points failed with EL_EDOM, every guess's fit reversed at an end) */
            const double half = 0.5 * remainder(E->theta - alpha, 2.0 * M_PI);
            c[rows] = 2.0 * sin(half);
            for (int j = 0; j < FIT_NP; j++) dc[0][j] = cos(half) * E->dtheta[j];
        } else {
            /* kappa - kappa* divided by what makes kappa vanish on the straight line,
             * 2 |k w| (smooth, kappa = 2 k w cn u) or 2 |k z| / h (discrete, kappa =
             * (2/h) tan(D/2) with the turning D ~ 2 k z cn u): the same zeros, but kappa = 0
             * at an end is then cn u = 0 (an inflection) with a gradient that stays away
             * from zero, instead of k, w or z -> 0, where the constraint's gradient vanishes
             * and Ipopt slid to a straight line (measured: examples/sample_2d.csv, discrete,
             * end curvature 0: rms 7.7 on the line, 0.27 at the inflection) */
            const double ks = at_end ? con->end_kappa : con->start_kappa;
            const int smooth = o->map.model == FIT_SMOOTH;
            const int ik = smooth ? 4 : 6, iw = smooth ? 3 : 4;
            const double ka = fmax(fabs(v[0][ik]), 1e-12), wa = fmax(fabs(v[0][iw]), 1e-12);
            const double den = 2.0 * ka * wa / (smooth ? 1.0 : v[0][2]);
            c[rows] = (E->kappa - ks) / den;
            for (int j = 0; j < FIT_NP; j++) dc[0][j] = E->dkappa[j] / den;
            dc[0][ik] -= c[rows] * copysign(1.0, v[0][ik]) / ka;
            dc[0][iw] -= c[rows] * copysign(1.0, v[0][iw]) / wa;
            if (!smooth) dc[0][2] += c[rows] / v[0][2];
        }
        for (int r = 0; r < nr; r++) {
            if (which) which[rows + r] = flag;
            if (J)
                for (int j = 0; j < nx; j++) {
                    double t = 0.0;
                    for (int a = 0; a < FIT_NP; a++) t += dc[r][a] * M[a * nx + j];
                    J[(rows + r) * nx + j] = t;
                }
        }
        rows += nr;
    }
    return rows;
}

/* The rows el__fit_constraint_rows returned (rows of them) at x, kept for cb_grad at the
 * same x; 1 when there are c->m. */
static int keep_rows(ipctx *c, const double *x, int rows, const double *cv)
{
    c->have_rows = rows == c->m;
    if (c->have_rows) {
        memcpy(c->rows_x, x, sizeof(double) * (size_t)c->nx);
        memcpy(c->rows, cv, sizeof(double) * (size_t)c->m);
    }
    return c->have_rows;
}

static Bool cb_f(Index n, Number *x, Bool new_x, Number *obj, UserDataPtr ud)
{
    (void)n; (void)new_x;
    ipctx *c = ud;
    if (ensure(c, x, 0)) return FALSE;
    *obj = c->val.f;
    return isfinite(*obj) ? TRUE : FALSE;
}

static Bool cb_grad(Index n, Number *x, Bool new_x, Number *g, UserDataPtr ud)
{
    (void)n;
    ipctx *c = ud;
    if (ensure(c, x, 1)) return FALSE;
    if (c->anchor) { memcpy(c->anchor, c->o->s, sizeof(double) * c->o->n); c->have_anchor = 1; }
    if (c->m > 0 && !fit_has_feet(c->o) && c->val.f < c->feas_f) {
        /* an iterate (Ipopt takes the gradient of each) within constr_viol_tol of the rows */
        double cv[FIT_NCON], worst = 0.0;
        /* the rows cb_g or cb_jac_g computed at this x (keep_rows), if Ipopt asked for them first */
        const int kept = !new_x && c->have_rows && !memcmp(c->rows_x, x, sizeof(double) * (size_t)c->nx);
        if (kept) memcpy(cv, c->rows, sizeof(double) * (size_t)c->m);
        if (kept || el__fit_constraint_rows(c->o, c->con, x, cv, NULL, NULL, c->tmp) == c->m) {
            for (int r = 0; r < c->m; r++) worst = fmax(worst, fabs(cv[r]));
            if (worst <= FIT_ROWS_TOL) {
                c->feas_f = c->val.f;
                memcpy(c->feas_x, x, sizeof(double) * (size_t)c->nx);
            }
        }
    }
    if (c->limited_memory) {
        memcpy(c->gx, x, sizeof(double) * (size_t)c->nx);
        c->gval = c->val;
        c->have_g = 1;
    }
    memcpy(g, c->val.g, sizeof(double) * (size_t)c->nx);
    return !el__all_finite(g, (size_t)c->nx);
}

static Bool cb_g(Index n, Number *x, Bool new_x, Index m, Number *g, UserDataPtr ud)
{
    (void)n; (void)new_x;
    ipctx *c = ud;
    if (m == 0) return TRUE;
    /* (every value handed to Ipopt finite: MUMPS crashes on inf in its matrix) */
    return keep_rows(c, x, el__fit_constraint_rows(c->o, c->con, x, g, NULL, NULL, c->tmp), g) &&
           !el__all_finite(g, (size_t)m);
}

static Bool cb_jac_g(Index n, Number *x, Bool new_x, Index m, Index nele, Index *iRow, Index *jCol,
                     Number *values, UserDataPtr ud)
{
    (void)new_x; (void)nele;
    ipctx *c = ud;
    if (!values) {
        Index e = 0;
        for (Index r = 0; r < m; r++)
            for (Index j = 0; j < n; j++) { iRow[e] = r; jCol[e] = j; e++; }
        return TRUE;
    }
    double cv[FIT_NCON];
    return keep_rows(c, x, el__fit_constraint_rows(c->o, c->con, x, cv, values, NULL, c->tmp), cv) &&
           !el__all_finite(values, (size_t)m * (size_t)n);
}

/*
 * Hessian of the Lagrangian, lower triangle. With constraints, or for orthogonal
 * distance: forward differences of its analytic gradient obj_factor J^T r / n +
 * sum lambda_r grad c_r (nx more evaluations). The Gauss-Newton matrix J^T J leaves
 * out the residuals' curvature (for orthogonal distance the feet's coupling), and
 * constrained solves then crept along the constraints for hundreds of iterations
 * (measured: a sketched S with a start tangent, 200+ iterations without reaching 1e-12;
 * with this Hessian 28). Bounds alone on paired residuals: J^T J / n (positive
 * semidefinite; the start is the best point of the active bounds, fit_candidate.c).
 */
static int lagrangian_gradient(ipctx *c, const double *x, double of, const double *lambda, int m,
                               double *gl)
{
    fit_value v;
    /* at x: the cached objective where it is the same number (the discrete model's:
     * a function of x alone, unlike the smooth feet, which ensure moves first) */
    const fit_value *pv = &v;
    if (!fit_has_feet(c->o) && cached(c, x, 1))
        pv = &c->val;
    else if (el__fit_objective_eval(c->o, x, 1, &v))
        return 0;
    for (int i = 0; i < c->nx; i++) gl[i] = of * pv->g[i];
    if (m > 0) {
        double cv[FIT_NCON], J[FIT_NCON * FIT_MAXX];
        if (el__fit_constraint_rows(c->o, c->con, x, cv, J, NULL, c->tmp) != m) return 0;
        for (int r = 0; r < m; r++)
            for (int i = 0; i < c->nx; i++) gl[i] += lambda[r] * J[r * c->nx + i];
    }
    return 1;
}

static Bool cb_h(Index n, Number *x, Bool new_x, Number obj_factor, Index m, Number *lambda,
                 Bool new_lambda, Index nele, Index *iRow, Index *jCol, Number *values,
                 UserDataPtr ud)
{
    (void)new_x; (void)new_lambda; (void)nele;
    ipctx *c = ud;
    if (!values) {
        Index e = 0;
        for (Index r = 0; r < n; r++)
            for (Index q = 0; q <= r; q++) { iRow[e] = r; jCol[e] = q; e++; }
        return TRUE;
    }
    const int exact = fit_has_feet(c->o) || m > 0;
    double g0[FIT_MAXX], g1[FIT_MAXX], xp[FIT_MAXX], H[FIT_MAXX * FIT_MAXX] = {0};
    if (exact) {
        if (!lagrangian_gradient(c, x, obj_factor, lambda, m, g0)) return FALSE;
        for (Index j = 0; j < n; j++) {
            const double h = 1e-7 * (1.0 + fabs(x[j]));
            memcpy(xp, x, sizeof(double) * (size_t)n);
            xp[j] = x[j] + h;
            if (!lagrangian_gradient(c, xp, obj_factor, lambda, m, g1)) return FALSE;
            for (Index i = 0; i < n; i++) H[j * n + i] = (g1[i] - g0[i]) / h;
        }
        c->have = 0;        /* the objective's cache was overwritten */
    }
    if (!exact) {
        if (ensure(c, x, 1)) return FALSE;
        for (Index i = 0; i < n * n; i++) H[i] += obj_factor * c->val.H[i];
    }
    Index e = 0;
    for (Index r = 0; r < n; r++)
        for (Index q = 0; q <= r; q++) values[e++] = 0.5 * (H[r * n + q] + H[q * n + r]);
    return !el__all_finite(values, (size_t)e);
}

/* f at this iteration hopeless against an earlier guess's (o->f_ceiling): the decrease of
 * the last LBFGS_RATE_SPAN iterations, kept up for the remaining ones, would not reach it
 * (fit_lm.c's rate test). */
static int hopeless(ipctx *c, double f)
{
    const double ceiling = c->o->f_ceiling;
    const int k = c->n_iter++;
    const double old = c->recent[k % LBFGS_RATE_SPAN];
    c->recent[k % LBFGS_RATE_SPAN] = f;
    return k >= 2 * LBFGS_RATE_SPAN && f > ceiling && (old - f) / LBFGS_RATE_SPAN * (c->max_iter - k) < f - ceiling;
}

/*
 * L-BFGS's stop without constraint rows or finite bounds (c->free: the certificate is the
 * first-order condition of f alone; with them Ipopt's own tests, 'acceptable' included),
 * at every iteration, at the point whose gradient Ipopt took last (the iterate: the
 * watchdog, which goes back to an earlier one, is off):
 * - certified: the first-order condition of fit_lm.c, g^T H^-1 g <= 1e-13 2f with the
 *   Gauss-Newton H (Ipopt's own tests are absolute: 'tol' on the gradient ended noise-free
 *   fits at 1e-8 of the length, and noisy fits, whose f at the optimum is known only to
 *   ~1e-13 of itself, never met it and halved every line search ~20-50 times to max_iter);
 * - stalled: LBFGS_FLAT iterations in a row lowered f by less than 1e-12 of itself (steps
 *   judged by rounding alone); certified when the Gauss-Newton decrease is within 1e-11 of
 *   f (fit_lm.c's stall certificate) or within the rounding of f, whose residuals are
 *   known to ~1e-14 of the data's size: |delta f| ~ 1e-14 sqrt(2f) (a near-exact fit,
 *   rms 4e-8, stalled at 1e-8 of f); else an uncertified stop (Ipopt's status 5 then
 *   means EL_ENOCONV);
 * - hopeless against an earlier guess (o->f_ceiling): fit_lm.c's rate test.
 * The exact Hessian's runs without rows stop by the rate test alone (on Ipopt's objective:
 * with bounds, later guesses of 1000 points crept 200 iterations from outside a k range,
 * 4-9 s each, test_fit_lbfgs.c's k range); with rows Ipopt's own tests, and, where the caller
 * holds the run to a kept fit that meets the rows (o->rows_cap, fit_choose.c), the rate test
 * on Ipopt's objective at the iterates near them too (inf_pr within ROWS_NEAR, outside
 * the restoration phase: an iterate off the rows can lie below every fit that meets them).
 * Measured on sine-like scans of 200-400 noisy points held G1 at both ends: later guesses'
 * runs crept along the rows at 15-65 x the kept fit's objective, ~3 ms an iteration.
 */
static Bool cb_iter(Index alg_mod, Index iter, Number obj, Number inf_pr, Number inf_du, Number mu,
                    Number d_norm, Number reg, Number alpha_du, Number alpha_pr, Index ls,
                    UserDataPtr ud)
{
    (void)obj; (void)inf_du; (void)mu; (void)d_norm; (void)reg;
    (void)alpha_du; (void)alpha_pr; (void)ls;
    ipctx *c = ud;
    c->iters = iter;
    if (!c->free) {
        /* the exact Hessian without rows (bounds alone, every iterate within them): the
         * rate test on Ipopt's objective (an earlier f need not meet rows) */
        if (c->m > 0 && !(c->rows_cap && inf_pr <= ROWS_NEAR)) return TRUE;
        return alg_mod != 0 || !hopeless(c, obj);
    }
    if (alg_mod != 0 || !c->have_g) return TRUE;
    const double f = c->gval.f;
    c->flat = iter > 0 && f >= c->last_f * (1.0 - 1e-12) ? c->flat + 1 : 0;
    c->last_f = f;
    if (el__fit_first_order(&c->gval, c->nx, c->o->lm_tol) ||
        (c->flat >= LBFGS_FLAT && el__fit_first_order(&c->gval, c->nx, fmax(1e-11, 1e-14 * sqrt(2.0 / f))))) {
        c->certified = 1;
        return FALSE;
    }
    return !hopeless(c, f) && c->flat < LBFGS_FLAT;
}

/*
 * The variables' scales for Ipopt's L-BFGS (its user scaling, x~_j = d_j x_j): d_j =
 * sqrt(H_jj) of the Gauss-Newton matrix J^T J / n at the start, divided by the largest
 * and kept >= 1e-4 (a variable without influence there is not blown up). The fit's
 * variables differ in curvature by orders of magnitude (H_jj from 1 to 1.7e-4 of the
 * largest on fuzz/corpus/fuzz-fit-discrete-lbfgs-start-tangent-slow.bin), and L-BFGS,
 * whose first matrix is a multiple of the identity, took steps of norm up to 1e7 that
 * the line search cut back 15-20 times, crawling to max_iter: that input 5 x 191
 * iterations, 3.3 s, ending with EL_EDOM (the start tangent unmet); scaled, 209
 * iterations, 0.4 s, EL_OK with the exact Hessian's rms. The exact Hessian is invariant
 * to this scaling and is left unscaled. Returns 0 (no scaling) when the start cannot be
 * evaluated.
 */
static int lbfgs_scaling(fit_objective *o, const double *x, double *d)
{
    const int nx = o->map.nx;
    fit_value v;
    if (el__fit_objective_eval(o, x, 1, &v) != EL_OK) return 0;
    double top = 0.0;
    for (int j = 0; j < nx; j++) {
        d[j] = sqrt(fmax(v.H[j * nx + j], 0.0));
        top = fmax(top, d[j]);
    }
    if (!(top > 0.0) || !isfinite(top)) return 0;
    for (int j = 0; j < nx; j++) d[j] = fmax(d[j] / top, 1e-4);
    return 1;
}

/* L-BFGS's options (the file's head). */
static int lbfgs_options(IpoptProblem pr, int free)
{
    return AddIpoptIntOption(pr, "watchdog_shortened_iter_trigger", 0)
        && AddIpoptIntOption(pr, "limited_memory_max_history", 20)
        && AddIpoptStrOption(pr, "limited_memory_aug_solver", "extended")
        && (!free || AddIpoptIntOption(pr, "acceptable_iter", 0));
}

int el__fit_ipopt(fit_objective *o, const double *xl, const double *xu, const fit_constraints *con,
                  const el_fit_options *opt, double *x, fit_ipopt_out *out, double *tmp)
{
    const int nx = o->map.nx;
    memset(out, 0, sizeof *out);      /* its callers read it on every return (iterations: 0) */
    out->f = HUGE_VAL;
    ipctx c;
    memset(&c, 0, sizeof c);
    c.o = o; c.con = con; c.nx = nx; c.tmp = tmp; c.limited_memory = opt->limited_memory;
    c.max_iter = opt->max_iter;
    c.best_f = c.feas_f = HUGE_VAL;
    double cv[FIT_NCON];
    c.m = con ? el__fit_constraint_rows(o, con, x, cv, NULL, NULL, tmp) : 0;
    if (c.m < 0) return EL_EDOM;
    /* Every variable fixed by its bounds: Debian's Ipopt 3.14 dereferences a null iterate
     * in IpoptApplication::call_optimize then (fuzz: a segfault in GetIterateFromComp,
     * el_fit_discrete with all seven bounds lo = hi). That point is the only one: its
     * objective, Ipopt not run; with constraints to meet, no point (EL_EDOM). */
    int nfree = 0;
    for (int j = 0; j < nx; j++) nfree += xl[j] < xu[j];
    if (nfree == 0) {
        for (int j = 0; j < nx; j++) x[j] = xl[j];
        fit_value at;
        if (c.m > 0 || el__fit_objective_eval(o, x, 0, &at) != EL_OK) return EL_EDOM;
        out->f = at.f;
        return EL_OK;
    }
    c.free = opt->limited_memory && c.m == 0;
    c.rows_cap = o->rows_cap && c.m > 0;
    for (int j = 0; j < nx; j++) c.free &= !isfinite(xl[j]) && !isfinite(xu[j]);
    if (fit_has_feet(o) && !(c.anchor = malloc(sizeof(double) * o->n))) return EL_ENOMEM;
    const int saved = o->exact_feet;
    o->exact_feet = 1;
    double L[FIT_MAXX], U[FIT_MAXX], gl[FIT_NCON] = {0}, gu[FIT_NCON] = {0};
    for (int j = 0; j < nx; j++) {
        L[j] = isfinite(xl[j]) ? xl[j] : -1e20;
        U[j] = isfinite(xu[j]) ? xu[j] : 1e20;
        x[j] = fmin(fmax(x[j], xl[j]), xu[j]);
    }
    double xscale[FIT_MAXX];
    const int scaled = opt->limited_memory && lbfgs_scaling(o, x, xscale);
    if (pthread_mutex_lock(&ipopt_lock)) { o->exact_feet = saved; free(c.anchor); return EL_EINTERNAL; }
    IpoptProblem pr = CreateIpoptProblem(nx, L, U, c.m, gl, gu, c.m * nx, nx * (nx + 1) / 2, 0,
                                         cb_f, cb_g, cb_grad, cb_jac_g, cb_h);
    int ok = pr != NULL;
    ok = ok && AddIpoptStrOption(pr, "option_file_name", "")
            && AddIpoptIntOption(pr, "print_level", 0)
            && AddIpoptStrOption(pr, "sb", "yes")
            && AddIpoptNumOption(pr, "tol", opt->tol)
            && AddIpoptIntOption(pr, "max_iter", opt->max_iter)
            && AddIpoptNumOption(pr, "bound_relax_factor", 0.0)
            && AddIpoptNumOption(pr, "constr_viol_tol", FIT_ROWS_TOL)
            && AddIpoptNumOption(pr, "acceptable_constr_viol_tol", FIT_ROWS_TOL)
            /* MUMPS's workspace: the default 1000 % over its estimate maps (and faults in)
             * 0.2-1.5 MB afresh at every solve for KKT systems of at most a few dozen rows;
             * 5 % (Ipopt's own suggestion for small problems) is enough for them: Ipopt
             * doubles it and refactors should MUMPS ask for more (INFO(1) -8/-9) */
            && AddIpoptIntOption(pr, "mumps_mem_percent", 5)
            && AddIpoptStrOption(pr, "mu_strategy", "monotone")
            && AddIpoptNumOption(pr, "mu_init", 1e-9)
            /* noisy data: Gauss-Newton converges linearly on a non-zero residual; stop
             * once the objective stalls (relative change < 1e-10 twice) */
            && (opt->limited_memory
                || (AddIpoptNumOption(pr, "acceptable_tol", 1e-3)
                    && AddIpoptNumOption(pr, "acceptable_obj_change_tol", 1e-10)
                    && AddIpoptIntOption(pr, "acceptable_iter", 2)))
            && (!opt->limited_memory || lbfgs_options(pr, c.free))
            && AddIpoptStrOption(pr, "hessian_approximation",
                                 opt->limited_memory ? "limited-memory" : "exact")
            && SetIntermediateCallback(pr, cb_iter)
            && (!scaled || (SetIpoptProblemScaling(pr, 1.0, xscale, NULL)
                            && AddIpoptStrOption(pr, "nlp_scaling_method", "user-scaling")));
    enum ApplicationReturnStatus rs = Internal_Error;
    double obj = HUGE_VAL;
    if (ok) rs = IpoptSolve(pr, x, NULL, &obj, NULL, NULL, NULL, &c);
    if (pr) FreeIpoptProblem(pr);
    pthread_mutex_unlock(&ipopt_lock);
    out->ran = ok;
    out->ipopt_status = (int)rs;
    out->iters = c.iters;
    out->certified = c.certified;
    if (c.certified) {      /* the certified point with its feet (those of its gradient) */
        memcpy(x, c.gx, sizeof(double) * (size_t)nx);
        if (c.anchor) memcpy(o->s, c.anchor, sizeof(double) * o->n);
        free(c.anchor);
        out->f = c.gval.f;
        o->exact_feet = saved;
        return EL_OK;
    }
    free(c.anchor);
    /* inside the bounds: where a slack is tiny Ipopt moves its bound ('slack_move', ~1e-12
     * each time), and a solution at a bound ended beyond it (measured: L-BFGS, k 3.4e-11
     * over the end of a k range, EL_EDOM) */
    for (int j = 0; j < nx; j++) {
        if (isfinite(x[j])) x[j] = fmin(fmax(x[j], xl[j]), xu[j]);
        c.best_x[j] = fmin(fmax(c.best_x[j], xl[j]), xu[j]);
    }
    /* the final point when feasible and no worse than the best seen, which is only
     * guaranteed feasible without constraints */
    fit_value fin;
    const int fin_ok = el__all_finite(x, (size_t)nx) == EL_OK && el__fit_objective_eval(o, x, 0, &fin) == EL_OK;
    if (!fin_ok || (c.m == 0 && c.best_f < fin.f)) {
        if (!isfinite(c.best_f)) { o->exact_feet = saved; return ok ? EL_ENOCONV : EL_EINTERNAL; }
        memcpy(x, c.best_x, sizeof(double) * (size_t)nx);
        out->f = c.best_f;
    } else if (c.feas_f < fin.f * (1.0 - 1e-9)) {
        /* with rows (discrete): an earlier iterate that met them lower than the final point
         * (the filter takes steps that raise f while the rows' violation falls: measured,
         * the 2000-point discrete fit held at 4 x its start curvature, f 0.015534 at the
         * 10th of 200 iterations, 0.015904 at the cap), by more than the wobble of a
         * converged run's last steps (1e-9 of f: below it the reported rms, a distance
         * other than f's end residuals, rose by up to 4e-11 of itself) */
        fit_value fv;
        for (int j = 0; j < nx; j++) x[j] = fmin(fmax(c.feas_x[j], xl[j]), xu[j]);
        out->f = el__fit_objective_eval(o, x, 0, &fv) == EL_OK ? fv.f : c.feas_f;
    } else {
        out->f = fin.f;
    }
    if (fit_has_feet(o)) el__fit_objective_project(o, x);
    o->exact_feet = saved;
    return ok ? EL_OK : EL_EINTERNAL;
}
