/*
 * One initial guess of a fit solved (el__fit_run's candidates and refits): the smooth
 * orthogonal fit's paired start and its feet, Levenberg-Marquardt with its first-order
 * certificate, and Ipopt where something needs it: constraint rows (from a quadratic
 * penalty's point), the point outside the bounds (from the best point of the bounds'
 * face), or, unless deferred, a point left uncertified.
 */
#include "fit_internal.h"
#include "fit_obstate.h"
#include <stdlib.h>
#include <string.h>

static int ipopt_to_status(int rs)
{
    switch (rs) {
    case 0: case 1: return EL_OK;          /* Solve_Succeeded, Solved_To_Acceptable_Level */
    case -1: case -4: return EL_EMAXITER;  /* Maximum_Iterations_Exceeded, Maximum_CpuTime_Exceeded */
    /* Infeasible_Problem_Detected (2) too: Ipopt's restoration phase failed from its point,
     * no proof of infeasibility; whether the fit meets the constraints is checked at its end
     * (el__fit_violated names one it does not meet; a G1-G1 fit from a curve meeting them
     * failed with EL_EDOM naming none) */
    default: return EL_ENOCONV;
    }
}

/*
 * A start for Ipopt when the unconstrained fit lies outside the bounds: the variables
 * beyond them held at their bounds and the others fitted again (Levenberg-Marquardt),
 * so that Ipopt starts at the best point of the active bounds' face instead of at a
 * clamped point far from any fit (measured: a k bound excluding the data's k, 200 Ipopt
 * iterations from the clamped point, a handful from this one). Returns the iterations.
 */
static int bounded_start(fit_objective *ob, const double *xl, const double *xu, int max_iter, double *x)
{
    const fit_map full = ob->map;
    fit_map m = full;
    double v[2][FIT_NP];
    for (int j = 0; j < full.nx; j++) x[j] = fmin(fmax(x[j], xl[j]), xu[j]);
    if (el__fit_map_eval(&full, x, v, NULL)) return 0;
    memcpy(m.fixed, v[0], sizeof m.fixed);
    m.nx = 0;
    int moved[FIT_MAXX];
    for (int j = 0; j < full.nx; j++) {
        moved[j] = x[j] > xl[j] && x[j] < xu[j];
        if (moved[j]) m.idx[m.nx++] = full.idx[j];
    }
    if (m.nx == full.nx || m.nx == 0 || full.chart) return 0;
    ob->map = m;
    double xr[FIT_MAXX];
    for (int j = 0, r = 0; j < full.nx; j++)
        if (moved[j]) xr[r++] = x[j];
    fit_solution sol;
    const int st = el__fit_lm(ob, xr, max_iter, &sol);
    ob->map = full;
    if (st) return 0;
    for (int j = 0, r = 0; j < full.nx; j++)
        if (moved[j]) x[j] = fmin(fmax(sol.x[r++], xl[j]), xu[j]);
    return sol.iters;
}

/* The largest |row| of the constraint rows con at x; HUGE_VAL where they cannot be
 * evaluated or one is not a number. They are met where it is at most 1e-10. */
static double rows_violation(fit_objective *ob, const fit_constraints *con, const double *x, double *tmp)
{
    double c[FIT_NCON], cc = 0.0;
    const int rows = el__fit_constraint_rows(ob, con, x, c, NULL, NULL, tmp);
    for (int k = 0; k < rows; k++) cc = fabs(c[k]) <= cc ? cc : isnan(c[k]) ? HUGE_VAL : fabs(c[k]);
    return rows < 0 ? HUGE_VAL : cc;
}

/* The rows of con met at x (rows_violation) and the first-order condition on their tangent
 * space there (el__fit_first_order_rows) at the certificate's tolerance. */
static int rows_first_order(fit_objective *ob, const fit_constraints *con, const double *x, double *tmp)
{
    double c[FIT_NCON], A[FIT_NCON * FIT_MAXX];
    fit_value v;
    const int m = el__fit_constraint_rows(ob, con, x, c, A, NULL, tmp);
    if (m < 0 || el__fit_objective_eval(ob, x, 1, &v) != EL_OK) return 0;
    for (int k = 0; k < m; k++)
        if (!(fabs(c[k]) <= 1e-10)) return 0;
    return el__fit_first_order_rows(&v, A, m, ob->map.nx, ob->lm_tol);
}

/* The rows' targets at x (their curve's values there): con's rows with their targets moved
 * the fraction t of the way from those values to con's own. EL_OK, or EL_EDOM where the curve
 * cannot be evaluated. */
static int rows_towards(const fit_objective *ob, const fit_constraints *con, const double *x, double t,
                        fit_constraints *out, double *tmp)
{
    double v[2][FIT_NP];
    fit_end e[2];
    if (el__fit_map_eval(&ob->map, x, v, NULL) ||
        el__fit_end_state(ob->map.model, v[0], ob->n, 0, &e[0], tmp) ||
        el__fit_end_state(ob->map.model, v[0], ob->n, 1, &e[1], tmp))
        return EL_EDOM;
    *out = *con;
    out->start_theta = e[0].theta + t * remainder(con->start_theta - e[0].theta, 2.0 * M_PI);
    out->end_theta = e[1].theta + t * remainder(con->end_theta - e[1].theta, 2.0 * M_PI);
    out->start_kappa = e[0].kappa + t * (con->start_kappa - e[0].kappa);
    out->end_kappa = e[1].kappa + t * (con->end_kappa - e[1].kappa);
    for (int c = 0; c < 2; c++) out->end_xy[c] = e[1].xy[c] + t * (con->end_xy[c] - e[1].xy[c]);
    return EL_OK;
}

/* The objective's state (its fields, feet and distances at rest) as a fit left it, put back
 * after another run from the same start that is not kept: the kept fit's later steps then
 * see exactly what they saw before that run. */
typedef fit_ob_state ob_state;

static double *feet_block(const fit_objective *ob) { return ob->s < ob->s_next ? ob->s : ob->s_next; }

/* el__fit_ob_save: fit_obstate.h */
int el__fit_ob_save(const fit_objective *ob, fit_ob_state *k)
{
    const size_t n = ob->n;
    if (!(k->buf = malloc(sizeof(double) * 4 * n))) return EL_ENOMEM;
    k->ob = *ob;
    memcpy(k->buf, feet_block(ob), sizeof(double) * 2 * n);
    if (ob->rest) memcpy(k->buf + 2 * n, ob->rest, sizeof(double) * n);
    if (ob->rest_foot) memcpy(k->buf + 3 * n, ob->rest_foot, sizeof(double) * n);
    return EL_OK;
}

/* el__fit_ob_restore: fit_obstate.h */
void el__fit_ob_restore(fit_objective *ob, const fit_ob_state *k)
{
    const size_t n = ob->n;
    *ob = k->ob;
    memcpy(feet_block(ob), k->buf, sizeof(double) * 2 * n);
    if (ob->rest) memcpy(ob->rest, k->buf + 2 * n, sizeof(double) * n);
    if (ob->rest_foot) memcpy(ob->rest_foot, k->buf + 3 * n, sizeof(double) * n);
}

/* A start by continuation (el__fit_held_start) far from the rows: Ipopt's one run from it
 * jumps to them, and the basin it lands in can turn on rounding (a sketch's fit G2-joined at
 * its start, its end tangent a row 0.41 rad from the continuation's: two minima of rms 2.130
 * and 2.169 mm, the one or the other after the document's round trip moved the points by
 * 4e-14, QA). Ipopt in two stages too, to the rows halfway (rows_towards) and then to them,
 * from the same start (start: the objective as the first run began, x0 its point); the fit
 * *r is replaced where that one meets the rows and is lower by more than the rounding of f,
 * else the objective is put back as the first run left it (kept). The second run matters
 * only below *r's f where *r meets the rows, and below best_f where the run is held to the
 * kept fit (ob->rows_cap, fit_choose.c): held to the lower of them (fit_ipopt.c's rate test
 * at iterates near the rows) unless o->exhaustive. Measured on sine-like scans of
 * 200-400 noisy points held G1 at both ends: these runs were 80 % of the Ipopt iterations,
 * 200 to max_iter at 15-65 x *r's f. EL_OK or EL_ENOMEM. */
static int rows_halfway(fit_objective *ob, const el_fit_options *o, const fit_constraints *con,
                        const double *xl, const double *xu, const double *x0, const ob_state *start,
                        double best_f, fit_candidate *r, double *tmp)
{
    const int r_meets = rows_violation(ob, con, r->x, tmp) <= 1e-10;
    const int nx = ob->map.nx;
    ob_state kept;
    if (el__fit_ob_save(ob, &kept)) return EL_ENOMEM;
    el__fit_ob_restore(ob, start);
    ob->f_ceiling = HUGE_VAL;
    double x[FIT_MAXX];
    memcpy(x, x0, sizeof(double) * (size_t)nx);
    fit_constraints half;
    fit_ipopt_out io;
    int st = rows_towards(ob, con, x, 0.5, &half, tmp);
    if (st == EL_OK) st = el__fit_ipopt(ob, xl, xu, &half, o, x, &io, tmp);
    const int first = st == EL_OK ? io.iters : 0;
    const int capped = ob->rows_cap;
    const double ceiling = fmin(capped ? best_f : HUGE_VAL, r_meets ? r->f : HUGE_VAL);
    if (!o->exhaustive && ceiling < HUGE_VAL) {
        ob->f_ceiling = ceiling;
        ob->rows_cap = 1;
    }
    if (st == EL_OK) st = el__fit_ipopt(ob, xl, xu, con, o, x, &io, tmp);
    ob->f_ceiling = HUGE_VAL;
    ob->rows_cap = capped;
    if (st == EL_ENOMEM || st == EL_EINTERNAL) { free(kept.buf); return st; }
    const int meets = st == EL_OK && rows_violation(ob, con, x, tmp) <= 1e-10;
    if (meets && (!r_meets || io.f < r->f * (1.0 - 1e-9))) {
        memcpy(r->x, x, sizeof(double) * (size_t)nx);
        r->f = io.f;
        r->ipopt_status = io.ipopt_status;
        r->status = io.certified ? EL_OK : ipopt_to_status(io.ipopt_status);
        if (r->status == EL_ENOCONV && rows_first_order(ob, con, r->x, tmp)) r->status = EL_OK;
        r->iters += first + io.iters;
    } else {
        el__fit_ob_restore(ob, &kept);
        r->iters += first + (st == EL_OK ? io.iters : 0);
    }
    free(kept.buf);
    memcpy(ob->halfway_x, x0, sizeof(double) * (size_t)nx);
    ob->halfway_seen = 1;
    return EL_OK;
}

/* Whether rows_halfway ran from x (to 1e-9) last: its fit is among the candidates already. */
static int halfway_ran(const fit_objective *ob, const double *x)
{
    int same = ob->halfway_seen;
    for (int j = 0; j < ob->map.nx && same; j++)
        same = fabs(x[j] - ob->halfway_x[j]) <= 1e-9 * (1.0 + fabs(x[j]));
    return same;
}

int el__fit_solve_candidate(fit_objective *ob, const el_fit_options *o, const fit_constraints *con,
                            const double *xl, const double *xu, int need_ipopt, int no_polish,
                            const double *x0, double best_f, fit_candidate *r, double *tmp, int near_start,
                            int warm)
{
    const int nx = ob->map.nx;
    memset(r, 0, sizeof *r);
    memcpy(r->x, x0, sizeof(double) * (size_t)nx);
    r->f = HUGE_VAL;
    r->status = EL_ENOCONV;
    fit_solution sol;
    int lm_ok = 0, inside = 1;
    double xs[FIT_MAXX];
    memcpy(xs, x0, sizeof(double) * (size_t)nx);
    int crawled = 0;
    const double *guess = x0;
    if (!warm && ob->kind == FIT_ORTHOGONAL && ob->map.model == FIT_SMOOTH) {
        /* the paired fit first: its pairing with the data's order keeps loops and sparse
         * points on their branch, and on equilateral data it is close and cheap (points
         * equally spaced in s); then the feet from its places */
        ob->kind = FIT_PAIRED;
        /* only a start: stopped once a Gauss-Newton step would lower the paired f by
         * less than 1e-9 of itself, far below its gap to the orthogonal f (measured on
         * the 42 noisy 1000-point curves of bench_fit.py: one evaluation fewer on most,
         * every rms the same to 1e-9 but one 2e-8 lower; at 1e-6 one fit of the 252
         * smooth suite curves ended 3e-5 higher) */
        const double certificate = ob->lm_tol;
        ob->lm_tol = 1e-9;
        int pst;
        if (o->limited_memory) {
            /* the same start by the caller's optimiser: Ipopt's L-BFGS, stopped at the same
             * certificate (fit_ipopt.c). From the guess's fractions instead, the feet
             * projected onto a loop's other pass stayed there, and L-BFGS ended at a worse
             * optimum (measured: 20 uneven noisy points, rms 0.0901 and 0.00390 against
             * the exact path's 0.0328 and 0.00384; with the feet nearest the guess
             * instead, 10 of 30 such fits worse). A paired fit that crawled to max_iter
             * without its certificate (a sketch with a gap, whose paired valley the exact
             * path also crawls) is no start: the guess then (measured: 1000 noisy points,
             * EL_EMAXITER at rms 0.0544 from the crawled start, EL_OK at 0.0466 from the
             * guess, the exact path 0.0534) */
            fit_ipopt_out po;
            memcpy(sol.x, x0, sizeof(double) * (size_t)nx);
            pst = el__fit_ipopt(ob, xl, xu, NULL, o, sol.x, &po, tmp);
            sol.iters = po.iters;
            if (pst == EL_OK && !po.certified) {
                r->iters += po.iters;
                pst = EL_ENOCONV;
            }
            if (pst == EL_ENOMEM || pst == EL_EINTERNAL) {
                ob->lm_tol = certificate;
                ob->kind = FIT_ORTHOGONAL;
                return pst;
            }
        } else {
            pst = el__fit_lm(ob, x0, o->max_iter, &sol);
            crawled = pst == EL_OK && !sol.certified;
        }
        ob->lm_tol = certificate;
        if (pst == EL_OK) {
            memcpy(xs, sol.x, sizeof(double) * (size_t)nx);
            r->iters += sol.iters;
        }
        ob->kind = FIT_ORTHOGONAL;
        if (el__fit_feet_start(ob, xs) != EL_OK) memcpy(xs, x0, sizeof(double) * (size_t)nx);
    }
    x0 = xs;
    ob->f_ceiling = best_f;
    /* near_start: x0 is near the constrained optimum already (el__fit_held_start's continuation):
     * Ipopt from there, not from the unconstrained fit that Levenberg-Marquardt would
     * return to; or it is the fit to polish (el__fit_fallback's run) */
    const int lst = o->limited_memory || (near_start && (need_ipopt || !no_polish)) ? EL_EINVAL
                  : el__fit_lm(ob, x0, o->max_iter, &sol);
    /* a paired start that crawled to max_iter without its certificate (a sketch with a
     * gap, whose chord fractions misplace the points after it) may be far from the fit:
     * Levenberg-Marquardt from the guess too, kept when certified lower (measured, 1000
     * noisy sketched points: rms 0.057, 0.0071, 0.0129 from the crawled start, 0.0031,
     * 0.0034, 0.0039 from the guess, the fits from the true curves'; an uncertified
     * point is no measure: on 20 uneven points the crawled start's 0.0058, reached by
     * Ipopt, would have lost to the guess's 0.104) */
    /* a paired start that ended far above the data's noise (ob->f_direct) may have led into
     * another basin: the chord fractions of clustered points misplace them along the
     * curve (measured: 9 points exactly on a gentle S, a cluster of 4 within 0.1 of its
     * length of 6.8 and a pair at its end: rms 0.0046 from the paired start, even from the
     * true curve; from the guess's feet 4e-14). Levenberg-Marquardt from the guess's own
     * feet too, kept when certified lower (noisy fits end at the noise: not run there; nor
     * for constraint rows, whose Ipopt run starts from the paired fit's basin). Where it is
     * not kept, the kept point's feet are put back as its run left them: projected afresh
     * from its curve, a foot can move to another pass of a loop and the fit with it (a
     * sparse uneven loop of 15 points, test_fit_basin.c: 0.0081 -> 0.025) */
    const int above = lst == EL_OK && ob->map.model == FIT_SMOOTH && !warm && !need_ipopt && sol.val.f > ob->f_direct;
    if (lst == EL_OK && (crawled || above)) {
        fit_solution g;
        double *feet = malloc(sizeof(double) * ob->n);
        if (!feet) return EL_ENOMEM;
        memcpy(feet, ob->s, sizeof(double) * ob->n);
        if (el__fit_feet_start(ob, guess) == EL_OK && el__fit_lm(ob, guess, o->max_iter, &g) == EL_OK) {
            r->iters += g.iters;
            if (g.certified && g.val.f < sol.val.f) {
                sol = g;
            } else {
                memcpy(ob->s, feet, sizeof(double) * ob->n);
                ob->have_base = 0;       /* no evaluation of these feet is cached */
                ob->rest_ok = 0;
            }
        }
        free(feet);
    }
    ob->f_ceiling = HUGE_VAL;
    if (lst == EL_OK) {
        memcpy(r->x, sol.x, sizeof(double) * (size_t)nx);
        r->f = sol.val.f;
        r->iters += sol.iters;
        lm_ok = 1;
        for (int j = 0; j < nx; j++) inside &= sol.x[j] >= xl[j] && sol.x[j] <= xu[j];
        if (sol.certified && inside && !need_ipopt) { r->status = EL_OK; return EL_OK; }
        if (!sol.certified && sol.iters >= o->max_iter && !need_ipopt && inside) r->status = EL_EMAXITER;
        if (no_polish && inside && !need_ipopt) return EL_OK;
        /* a later guess that ended above an earlier one's objective: Ipopt would only
         * polish a worse fit (measured: 200 Ipopt iterations, 0.2 s, on 16 points whose
         * third guess crawled along a flat valley) */
        if (inside && !need_ipopt && r->f > best_f) return EL_OK;
    }
    fit_ipopt_out io;
    double x[FIT_MAXX], xpen[FIT_MAXX];
    int pen_met = 0;     /* the penalty's last point meets the rows (xpen) */
    memcpy(x, lm_ok ? r->x : x0, sizeof(double) * (size_t)nx);
    if (lm_ok && need_ipopt) {
        /* Ipopt from the unconstrained optimum took wild first steps where the constraint
         * is far from met there (measured: sample_2d.csv, discrete, end curvature 0: a
         * straight line, rms 7.7, instead of 0.27): first a quadratic penalty
         * (rho/2)|c|^2 with rho raised 100-fold from 1 (normalised units), each stage by
         * Levenberg-Marquardt from the last, so Ipopt starts near the constrained optimum */
        ob->pen = con;
        ob->pen_tmp = tmp;
        for (ob->pen_rho = 1.0; ob->pen_rho <= 1e10; ob->pen_rho *= 100.0) {
            if (el__fit_lm(ob, x, o->max_iter, &sol) != EL_OK) break;
            memcpy(x, sol.x, sizeof(double) * (size_t)nx);
            r->iters += sol.iters;
            const double cc = rows_violation(ob, con, x, tmp);
            pen_met = cc <= 1e-10;
            if (cc == HUGE_VAL || pen_met) break;
        }
        ob->pen = NULL;
        if (pen_met) memcpy(xpen, x, sizeof(double) * (size_t)nx);
        inside = 1;
        for (int j = 0; j < nx; j++) inside &= x[j] >= xl[j] && x[j] <= xu[j];
    }
    if (lm_ok && !inside) r->iters += bounded_start(ob, xl, xu, o->max_iter, x);
    /* Ipopt stops a guess that cannot reach an earlier one's f (fit_ipopt.c): with L-BFGS,
     * and without rows (bounds alone: every iterate within them, f comparable). Measured:
     * 1000 points of a curve, the discrete model with a k range excluding the curve's
     * (test_fit_lbfgs.c): two later guesses each ran Ipopt to max_iter from outside the
     * range, 4-9 s each on a polygon far from the points. With rows where the caller asks
     * (ob->rows_cap, fit_choose.c: a later start while the kept fit meets them), at the
     * iterates near them */
    if (o->limited_memory || !need_ipopt || ob->rows_cap) ob->f_ceiling = best_f;
    /* the continuation's start with rows that leave the fit free (fewer than its variables:
     * where as many determine it, its curves are isolated, chosen among by other rules; a
     * 9-point sketch held at 7 conditions went from a coil of 100 x its length, rms 0.0023,
     * to one of 1.6 x, 0.134): its feet and point kept for rows_halfway */
    double rc[FIT_NCON];
    const int halfway = near_start && !warm && need_ipopt && !lm_ok && fit_has_feet(ob) &&
                        !halfway_ran(ob, x) &&
                        el__fit_constraint_rows(ob, con, x, rc, NULL, NULL, tmp) < nx;
    double xstart[FIT_MAXX];
    ob_state start = {.buf = NULL};
    if (halfway) {
        if (el__fit_ob_save(ob, &start)) return EL_ENOMEM;
        memcpy(xstart, x, sizeof(double) * (size_t)nx);
    }
    int st = el__fit_ipopt(ob, xl, xu, need_ipopt ? con : NULL, o, x, &io, tmp);
    ob->f_ceiling = HUGE_VAL;
    if (st == EL_EINTERNAL || st == EL_ENOMEM) { free(start.buf); return st; }
    if (io.ran) {
        r->used_ipopt = 1;
        r->ipopt_status = io.ipopt_status;
        r->iters += io.iters;
    }
    /* Ipopt's point when it had to run (constraints, the LM point outside the bounds)
     * or when it improved on an uncertified one */
    if (st == EL_OK && (io.f <= r->f || need_ipopt || !lm_ok || !inside)) {
        memcpy(r->x, x, sizeof(double) * (size_t)nx);
        r->f = io.f;
        r->status = io.certified ? EL_OK : ipopt_to_status(io.ipopt_status);
    }
    /* Ipopt's point off the rows where the penalty's met them: the penalty's, uncertified
     * (measured: 40 uneven noisy points along a gentle arc, both ends pinned, discrete by
     * distance: Ipopt crept along the end-point rows from each guess to max_iter, 5203
     * iterations, and the fit failed with EL_EDOM, where the penalty's point met them at
     * an f 2e-4 of itself above Ipopt's last) */
    if (pen_met && !(rows_violation(ob, con, r->x, tmp) <= 1e-10)) {
        fit_value fv;
        if (el__fit_objective_eval(ob, xpen, 0, &fv) == EL_OK) {
            memcpy(r->x, xpen, sizeof(double) * (size_t)nx);
            r->f = fv.f;
            r->status = EL_ENOCONV;
        }
    }
    /* Ipopt stopped short of its own tests (restoration failed, 'infeasible') at a point that
     * meets the rows: a fit where the first-order condition on the rows' tangent space holds
     * (measured: pinned ends with a zero end curvature, Ipopt status -2 or 2 under one BLAS
     * kernel and 0 or 1 under another at the same point, rms equal to 1e-12) */
    if (r->status == EL_ENOCONV && need_ipopt && st == EL_OK && rows_first_order(ob, con, r->x, tmp))
        r->status = EL_OK;
    /* a zero-residual fit that Ipopt could not certify (its step became tiny) is a fit */
    if (r->status == EL_ENOCONV && r->f <= FIT_EXACT_F) r->status = EL_OK;
    if (halfway && st == EL_OK) st = rows_halfway(ob, o, con, xl, xu, xstart, &start, best_f, r, tmp);
    free(start.buf);
    return st == EL_EINTERNAL || st == EL_ENOMEM ? st : EL_OK;
}

int el__fit_refeet(fit_objective *ob, const el_fit_options *o, const fit_constraints *rows,
                   const fit_constraints *con, const double *lo, const double *hi, const double *xl,
                   const double *xu, int no_polish, fit_candidate *r, int *stale, double *tmp)
{
    for (int round = 0; round < REFEET_ROUNDS && ob->rest; round++) {
        if (!el__fit_meets(ob, &ob->map, con, r->x, lo, hi, tmp) || el__fit_feet_start(ob, r->x))
            break;
        fit_candidate rb;
        const int st = el__fit_solve_candidate(ob, o, rows, xl, xu, 1, no_polish, r->x, HUGE_VAL,
                                               &rb, tmp, 1, 1);
        if (st) return st;
        rb.iters += r->iters;
        if (!(rb.f < r->f * (1.0 - 1e-6)) || !el__fit_meets(ob, &ob->map, con, rb.x, lo, hi, tmp)) {
            r->iters = rb.iters;
            *stale = 1;     /* ob's feet: rb's */
            break;
        }
        *r = rb;
    }
    return EL_OK;
}
