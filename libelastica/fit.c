/*
 * Least-squares fairing, the public entry points (the pieces: fit_internal.h).
 *
 *   minimise f = (1/2n) sum_i r_i^2
 *
 * in normalised coordinates (centroid at the origin, rms radius 1), so tolerances mean
 * the same at every scale; r_i is the paired residual of seed 000 (4.6) (discrete, and
 * smooth on request) or the distance of P_i to the curve (smooth, the default;
 * fit_objective.c). The discrete h and z are O(1/n): the optimiser sees (n-1) h and
 * (n-1) z. Several initial guesses (guess.c) may be fitted, in the order of their
 * initial rms; the next is tried only while the best rms is above both the exact level
 * and 1.5 x the noise level estimated from third differences (el__fit_noise_rms, its
 * normal part for a distance to the curve; the plain figure for a constrained fit).
 * Each is fitted (fit_candidate.c) by Levenberg-Marquardt (fit_lm.c); a result certified
 * by its first-order condition and inside the caller's bounds is final. Ipopt
 * (fit_ipopt.c) runs from there for bounds that are active, constraints, or an
 * uncertified result.
 * Constraints on the start point are the parameters x0, y0 held, a start tangent or
 * curvature are the start-state chart's variables held (choose_charts); a fit whose end
 * has more of these than its start runs on the points reversed (fit_restart.c). The
 * others go to Ipopt's constraint interface. Every result is checked against its
 * constraints. Further starts (fit_restart.c): a constrained fit's from the unconstrained
 * fit, and one that strays from its points from the paired fit.
 *
 * el__fit_run in stages, handing on a fit_run_state: read_options, normalised_bounds,
 * choose_charts, build_map, alloc_work; the starts (fit_starts.c) and the choice among
 * their fits (fit_choose.c); settle_feet (the kept fit's feet on its nearest pass); report_distances,
 * report_params (input units); follow_the_points and further_runs (fit_restart.c).
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include "fit_ends.h"
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <stdint.h>

enum { FEET_ROUNDS = 4, SAMPLED_ROUNDS = 5 };
/* the sampled refits' stop (settle_feet): a Gauss-Newton step would lower f by less than this */
static const double LOOSE_TOL = 1e-5;

/* ------------------------------------------------------------ the problem */

/* The options in force (the caller's or the defaults), the input checked and its
 * normalisation (centroid at the origin, rms radius 1); a held start point is x0, y0
 * fixed. EL_OK, else the run's status (res->constraint naming a bad constraint). */
static int read_options(fit_run_state *R)
{
    el_fit_options *o = &R->o;
    if (R->opt) *o = *R->opt; else el_fit_options_defaults(o);
    int which = 0;
    if (!R->xy || R->n < 4 || el__all_finite(R->xy, 2 * R->n)) return EL_EINVAL;
    int st = el__fit_check_options(o, R->model, &which);
    if (st) { R->res->constraint = which; return st; }
    if (o->use_initial && (!R->init || el__all_finite(R->init, FIT_NP))) return EL_EINVAL;
    el__gsl_quiet();
    if ((st = el__fit_normalisation(R->xy, R->n, &R->cx, &R->cy, &R->sc))) return st;
    R->norm[0] = R->cx; R->norm[1] = R->cy; R->norm[2] = R->sc;
    /* start point: x0, y0 held */
    if (o->constraints & EL_CONSTRAIN_START_POINT) {
        o->fixed[0] = o->fixed[1] = 1;
        o->value[0] = o->start_point[0]; o->value[1] = o->start_point[1];
    }
    return EL_OK;
}

/* The normalised bounds lo, hi: the model's and the caller's, then the constraints' (and
 * the constraints in normalised units, con), checked against each other and the fixed
 * values; the sign continuations (el__fit_canonical) closed where they would change a
 * held meaning. EL_OK, else EL_EINVAL or EL_EDOM with res->constraint. */
static int normalised_bounds(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int model = R->model;
    const double cx = R->cx, cy = R->cy, sc = R->sc;
    double *lo = R->lo, *hi = R->hi;
    for (int j = 0; j < FIT_NP; j++) {
        double a = el__fit_norm_param(model, j, o->lower[j], cx, cy, sc);
        double b = el__fit_norm_param(model, j, o->upper[j], cx, cy, sc);
        lo[j] = isnan(a) ? -HUGE_VAL : fmin(a, b);
        hi[j] = isnan(b) ? HUGE_VAL : fmax(a, b);
    }
    el__fit_setup_constraints(o, model, R->n, cx, cy, sc, &R->con, lo, hi);
    const int is_len = o->constraints & EL_CONSTRAIN_LENGTH, is_k = o->constraints & EL_CONSTRAIN_K;
    for (int j = 0; j < FIT_NP; j++) {
        if (lo[j] > hi[j]) {
            R->res->constraint = (j == fit_length_slot(model) && is_len) ? EL_CONSTRAIN_LENGTH
                               : (j == fit_k_slot(model) && is_k) ? EL_CONSTRAIN_K : 0;
            return EL_EINVAL;
        }
        if (o->fixed[j]) {
            const double v = el__fit_norm_param(model, j, o->value[j], cx, cy, sc);
            if (!isfinite(v) || v < lo[j] || v > hi[j]) {
                R->res->constraint = j == fit_length_slot(model) ? is_len
                                   : j == fit_k_slot(model) ? is_k : 0;
                return EL_EINVAL;
            }
        }
    }
    /* the end point out of reach of the longest allowed curve */
    const int len_start = EL_CONSTRAIN_LENGTH | EL_CONSTRAIN_START_POINT;
    if ((o->constraints & EL_CONSTRAIN_END_POINT) && (o->constraints & len_start) == len_start) {
        const fit_constraints *con = &R->con;
        const double chord = hypot(con->end_xy[0] - con->start_xy[0],
                                   con->end_xy[1] - con->start_xy[1]);
        const double maxlen = hi[fit_length_slot(model)] *
                              (model == FIT_DISCRETE ? (double)(R->n - 1) : 1.0);
        if (chord > maxlen * (1.0 + 1e-12)) {
            R->res->constraint = EL_CONSTRAIN_LENGTH;
            return EL_EDOM;
        }
    }
    /* discrete k < 0 is used internally by shifting q (el__fit_canonical): not when q is
     * fixed; smooth w < 0 flips k and q: not when either is fixed or bounded */
    const int ik = fit_k_slot(model);
    R->ik = ik;
    if (model == FIT_DISCRETE && o->fixed[5] && !o->fixed[ik]) lo[ik] = fmax(lo[ik], 0.0);
    if (model == FIT_SMOOTH && (o->fixed[ik] || o->fixed[5] || isfinite(lo[ik]) ||
                                isfinite(hi[ik]) || isfinite(lo[5]) || isfinite(hi[5])))
        lo[3] = fmax(lo[3], 0.0);
    return EL_OK;
}

/* The distance (kind) and the charts of the map: the start-state chart replaces
 * (phi, w or z, k, q) when all four are free and unbounded; it then holds a start tangent
 * (theta0; discrete: vertex 0's theta_0, fit_model.c) and a start curvature (smooth:
 * kappa0; discrete: 0, where its seed 000 (3.4) curvature and the chart's 2 k W cn q vanish
 * together, at cn q = 0) as variables fixed at their values: met exactly, no constraint
 * row. As rows (Ipopt, in (phi, w, k, q)) kappa0 = 0 was reached only along k -> 1,
 * q -> oo, where its gradient vanishes: a false EL_EDOM or a far worse local fit
 * (measured: a noise-free S, start curvature 0: rms 7.9 stalled at the separatrix; held:
 * 1.61). */
static void choose_charts(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const fit_constraints *con = &R->con;
    const int model = R->model, flags = R->flags, ik = R->ik;
    R->kind = o->distance == EL_DISTANCE_PAIRED ? FIT_PAIRED
            : o->distance == EL_DISTANCE_ORTHOGONAL ? FIT_ORTHOGONAL
            : model == FIT_SMOOTH || !el__fit_evenly_spaced(R->xy, R->n) || el__fit_retrace(R->xy, R->n)
                ? FIT_ORTHOGONAL : FIT_PAIRED;
    const int sl[4] = {model == FIT_DISCRETE ? 3 : 2, model == FIT_DISCRETE ? 4 : 3, ik, 5};
    memcpy(R->sl, sl, sizeof sl);
    R->chart_ok = 1;
    R->held = 0;
    for (int a = 0; a < 4; a++)
        if (o->fixed[sl[a]] || isfinite(R->lo[sl[a]]) || isfinite(R->hi[sl[a]])) R->chart_ok = 0;
    const int start_state = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE;
    if (R->chart_ok && model == FIT_SMOOTH) R->held = o->constraints & start_state;
    if (R->chart_ok && model == FIT_DISCRETE)
        R->held = (o->constraints & EL_CONSTRAIN_START_TANGENT) |
                  ((o->constraints & EL_CONSTRAIN_START_CURVATURE) && con->start_kappa == 0.0
                       ? EL_CONSTRAIN_START_CURVATURE : 0);
    /* both end points and nothing else: the ends chart (fit_model.c) holds both, and the fit
     * needs no Ipopt (FIT_RUN_ROWS: as rows, the fallback in further_runs). Measured on 4 x
     * 150 sparse uneven noisy sketches of 6-59 points (bench_fit_sparse.py's generator, seeds
     * 6 and 7), pinned at their curve's ends and at their first and last points, each model,
     * against the rows: uncertified fits 23 -> 0, rms better by > 1 % 30, worse 2 (by 1-2.5
     * %), CPU 53 s -> 3.4 s over the 1200 fits, 105 -> 2 above 0.1 s, the slowest 1.6 ->
     * 0.34 s */
    R->chord[0] = con->end_xy[0] - con->start_xy[0];
    R->chord[1] = con->end_xy[1] - con->start_xy[1];
    const int jl = fit_length_slot(model);
    R->jl = jl;
    /* with a zero start curvature too (FIT_RUN_ENDS_HELD, el__fit_ends_held): the chart's
     * a = kappa0 L held at 0, scale-free; an end curvature stays a row */
    const int both = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
    R->zero_k0 = (o->constraints & EL_CONSTRAIN_START_CURVATURE) && con->start_kappa == 0.0
                     ? EL_CONSTRAIN_START_CURVATURE : 0;
    R->ends_ok = R->chart_ok && !(flags & FIT_RUN_ROWS) && (o->constraints & both) == both &&
                 !(o->constraints & ~(both | R->zero_k0 | EL_CONSTRAIN_END_CURVATURE)) &&
                 fit_norm(R->chord[0], R->chord[1]) > 1e-9 && !isfinite(R->lo[jl]) &&
                 !isfinite(R->hi[jl]) && !o->fixed[jl];
    R->ends_chart = R->ends_ok &&
                    (o->constraints == both || (R->zero_k0 && (flags & FIT_RUN_ENDS_HELD)));
    if (R->ends_chart) R->held = EL_CONSTRAIN_END_POINT | R->zero_k0;
    /* the natural batten (both end curvatures 0 too): smooth by distance, every fit that meets
     * the constraints is a member of a family of one parameter per number of half-waves,
     * searched whole (fit_natural.c) in the ends chart's run (FIT_RUN_ENDS_HELD, el__fit_run);
     * discrete, that run from this smooth fit; the start-state chart's run and
     * el__fit_ends_held only where that gives no fit */
    R->natural = R->ends_ok && R->zero_k0 && (o->constraints & EL_CONSTRAIN_END_CURVATURE) &&
                 con->end_kappa == 0.0 && (model == FIT_DISCRETE || R->kind == FIT_ORTHOGONAL) &&
                 !o->use_initial && !R->lm_only;
}

/* The map from the optimiser's variables to the parameters (fit_model.c): the free
 * parameters, their scales, the chart; the constraints left to Ipopt's rows (con_rows) and
 * the variables' bounds xl, xu. */
static void build_map(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int model = R->model, *sl = R->sl, held = R->held, ends_chart = R->ends_chart;
    const int start_state = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE;
    R->need_ipopt = (o->constraints & ~(EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_LENGTH |
                                        EL_CONSTRAIN_K | held)) != 0;
    /* the discrete non-zero start curvature stays an Ipopt row, started by continuation in
     * the chart (el__fit_held_start; measured on a sketched S, then with the first segment's
     * direction as the start tangent, a row too: rms 0.70 in 1400 iterations from the free
     * fit, 0.35 by continuation) */
    R->staged = R->chart_ok ? (held | o->constraints) & start_state : 0;
    R->con_rows = R->con;        /* the constraints left to Ipopt's rows */
    R->con_rows.mask &= ~held;
    fit_map *map = &R->map;
    memset(map, 0, sizeof *map);
    map->model = model; map->ncurves = 1;
    map->chart = ends_chart ? FIT_CHART_ENDS
               : R->chart_ok && (!R->need_ipopt || R->staged) ? FIT_CHART_START : FIT_CHART_NONE;
    map->chord[0] = R->chord[0]; map->chord[1] = R->chord[1];
    for (int j = 0; j < FIT_NP; j++) {
        map->scale[j] = (model == FIT_DISCRETE && (j == 2 || j == 4)) ? (double)(R->n - 1) : 1.0;
        if (o->fixed[j])
            map->fixed[j] = el__fit_norm_param(model, j, o->value[j], R->cx, R->cy, R->sc);
        else if (j == sl[0] && (held & EL_CONSTRAIN_START_TANGENT))
            map->fixed[j] = R->con.start_theta;
        else if (j == sl[1] && (held & EL_CONSTRAIN_START_CURVATURE))
            map->fixed[j] = R->con.start_kappa;
        else if (!ends_chart || j == sl[1] || j == sl[2] || j == sl[3])
            map->idx[map->nx++] = j;
    }
    R->free_map = *map;          /* the same with the held chart variables free */
    R->free_map.nx = 0;
    for (int j = 0; j < FIT_NP; j++)
        if (ends_chart ? j == sl[1] || j == sl[2] || j == sl[3] : !o->fixed[j])
            R->free_map.idx[R->free_map.nx++] = j;
    for (int j = 0; j < map->nx; j++) {
        const int col = map->idx[j];
        R->xl[j] = isfinite(R->lo[col]) ? R->lo[col] * map->scale[col] : -HUGE_VAL;
        R->xu[j] = isfinite(R->hi[col]) ? R->hi[col] * map->scale[col] : HUGE_VAL;
    }
}

/* The run's work: scratch, the smooth fractions (paired positions, first feet), the
 * objective, the distances and feet reported (the caller's arrays dist, foot, or dbuf;
 * also the smooth orthogonal fit's start feet and the distances its evaluations found at
 * rest). EL_OK, EL_ENOMEM, or an error of el_fit_fractions / el__fit_objective_init. */
static int alloc_work(fit_run_state *R, double *dist, double *foot)
{
    const size_t n = R->n;
    int st;
    R->mode = EL_PARAM_UNIFORM;
    if (!(R->tmp = malloc(sizeof(double) * FIT_WORK))) return EL_ENOMEM;
    if (R->model == FIT_SMOOTH) {
        if (!(R->t = malloc(sizeof(double) * n))) return EL_ENOMEM;
        if ((st = el_fit_fractions(R->xy, n, R->o.param_mode, R->t, &R->mode))) return st;
    }
    if ((st = el__fit_objective_init(&R->ob, R->kind, &R->map, R->xy, n, R->cx, R->cy, R->sc,
                                     R->t)))
        return st;
    R->ob.exact_ends = R->o.constraints != 0 || (R->flags & FIT_RUN_FREE_ENDS);
    /* free ends: the first and last points' feet free, as a held end point's (fit_end_paired) */
    if (R->flags & FIT_RUN_FREE_ENDS)
        for (int j = 0; j < 2; j++) {
            R->ob.held_ends[j] = R->xy[j];
            R->ob.held_ends[2 + j] = R->xy[2 * (n - 1) + (size_t)j];
        }
    /* as many rows as variables: the curves that meet the constraints are isolated, and the
     * held end points' own (fit_end_paired, el__fit_stray_held); not more (none meets them but
     * the data's own curve: a fit of all six constraints, from an uncertified one that met them
     * to one off the end curvature, rms 0.0030 -> 0.0035) */
    const int rows = fit_conditions(R->con_rows.mask & ~EL_CONSTRAIN_START_POINT);
    R->determined = R->need_ipopt && R->model == FIT_SMOOTH && R->map.ncurves == 1 &&
                    rows == R->map.nx;
    if (R->determined && (R->o.constraints & EL_CONSTRAIN_START_POINT))
        memcpy(R->ob.held_ends, R->o.start_point, sizeof R->o.start_point);
    if (R->determined && (R->o.constraints & EL_CONSTRAIN_END_POINT))
        memcpy(R->ob.held_ends + 2, R->o.end_point, sizeof R->o.end_point);
    R->d = dist;
    R->fs = foot;
    if ((!R->d || !R->fs) && !(R->dbuf = malloc(sizeof(double) * 2 * n))) return EL_ENOMEM;
    if (!R->d) R->d = R->dbuf;
    if (!R->fs) R->fs = R->dbuf + n;
    if (R->model == FIT_SMOOTH && R->kind == FIT_ORTHOGONAL) {
        R->ob.rest = R->d;
        R->ob.rest_foot = R->fs;
    }
    return EL_OK;
}

/* ------------------------------------------------------------ the kept fit's feet */

/* The kept curve (R->best) evaluated: its parameters v, the feet of a fit that has none of
 * its own from the fractions, the constraint it violates (status EL_EDOM then, FIT_ECAPPED
 * where its Ipopt run stopped at max_iter: Maximum_Iterations_Exceeded, -1). */
static void evaluate_kept(fit_run_state *R)
{
    fit_objective *ob = &R->ob;
    R->status = R->best.status;
    R->constraint = 0;
    R->ok = el__fit_map_eval(&R->map, R->best.x, R->v, NULL) == EL_OK;
    if (R->ok && ob->s && !(R->last_is_best && fit_has_feet(ob)))   /* else the fit's own feet */
        for (size_t i = 0; i < R->n; i++) ob->s[i] = R->t[i] * R->v[0][6];
    if (R->ok && (R->constraint = el__fit_violated(ob, &R->con, R->v[0], R->lo, R->hi, R->tmp)))
        R->status = R->best.used_ipopt && R->best.ipopt_status == -1 ? FIT_ECAPPED : EL_EDOM;
}

/* Whether the kept fit's nearest points (R->d, fs) lie elsewhere than its feet: by more
 * than 1e-3 of the length, or, when the fit's feet are gone, its distances below its fit. */
static int kept_feet_elsewhere(const fit_run_state *R)
{
    return R->last_is_best ? el__fit_feet_moved(R->ob.s, R->fs, R->n, R->v[0][6])
                           : el__fit_nearer_than(R->d, R->n, R->best.f);
}

/* settle_feet's rounds: the certificate's tolerance, whether to refit, the sampled rounds
 * and whether they go on, whether the kept fit is a loose one (stopped at LOOSE_TOL), the
 * rounds by the search everywhere. */
typedef struct feet_rounds {
    double certificate;
    int refit, sampled, sampling, loose, round;
} feet_rounds;

/* The kept point, stopped at LOOSE_TOL, certified from its feet (the nearest ones when a
 * later refit's replaced them). st: the round's status so far, returned where the fit
 * cannot start; else EL_OK or the solver's error. */
static int certify_loose(fit_run_state *R, int st)
{
    fit_candidate r;
    R->ob.have_base = 0;
    if ((!R->last_is_best && el__fit_feet_start(&R->ob, R->best.x)) ||
        (st = el__fit_solve_candidate(&R->ob, &R->o, &R->con_rows, R->xl, R->xu, R->need_ipopt,
                                      R->refit_no_polish, R->best.x, HUGE_VAL, &r, R->tmp, 1, 1)) ||
        !isfinite(r.f)) {
        if (st) return st;
        R->best.status = EL_ENOCONV;
        R->last_is_best = 0;
        return EL_OK;
    }
    R->iters += r.iters;
    R->best = r;
    R->last_is_best = 1;
    return EL_OK;
}

/* The kept fit fitted again from its point with the feet fs: a cheap refit (moved > 0:
 * Levenberg-Marquardt alone, stopped at LOOSE_TOL) or one by the search everywhere; kept
 * when lower (with constraint rows: and meeting them; where Ipopt could not, r.f is
 * Levenberg-Marquardt's, free). EL_OK or the solver's error. */
static int refit_from_feet(fit_run_state *R, size_t moved, feet_rounds *fr)
{
    fit_objective *ob = &R->ob;
    el__fit_feet_set(ob, R->fs, R->v[0][6]);
    fit_candidate r;
    if (moved) ob->lm_tol = LOOSE_TOL;
    const int st = el__fit_solve_candidate(ob, &R->o, &R->con_rows, R->xl, R->xu, R->need_ipopt,
                                           moved || R->refit_no_polish, R->best.x, R->best.f, &r,
                                           R->tmp, 1, 1);
    ob->lm_tol = fr->certificate;
    if (st) return st;
    R->iters += r.iters;
    R->ipopt_spent += el__fit_ran_out(&r);
    if (moved && !(r.status == EL_OK && r.f < R->best.f)) {
        /* a cheap refit not certified lower: the rounds by the search everywhere */
        fr->sampling = 0;
        R->last_is_best = 0;
        return EL_OK;
    }
    /* else once more for the kept curve's distances */
    fr->refit = r.f < R->best.f &&
                (!R->need_ipopt || el__fit_meets(ob, &R->map, &R->con, r.x, R->lo, R->hi, R->tmp));
    R->last_is_best = fr->refit;
    if (fr->refit) {
        R->best = r;
        fr->loose = moved != 0;
    }
    return EL_OK;
}

/* The kept curve: its distances and constraints (evaluate_kept), refitted while its feet
 * are on another pass than its nearest points.
 * The smooth orthogonal fit moves each foot by Newton steps, which keep it on its branch:
 * a foot that started where a rough curve (the paired start) came nearest, on another pass
 * of a loop than the fit's nearest point, stays at that stationary point of its distance,
 * and the fit is certified at rest there (measured: 20 noise-free sketched points, one foot
 * at distance 2.6e-2 on the other pass where the nearest is 1e-3 away, certified at rms
 * 1.07e-3; the exact fit 4e-15). The nearest points are then elsewhere (by more than 1e-3
 * of the length, far beyond a foot at rest; the extension's feet beyond the curve aside),
 * or, when the fit's feet are gone (an earlier guess kept), the distances below the fit's:
 * fitted again from its point with these feet, while that lowers f. A refit moves the
 * curve, and near a crossing of two passes more feet change pass (measured on bench_fit.py's
 * 42 noisy 1000-point smooth curves: 19 refitted, one's moved feet 110, 43, 12, 5, 2 in
 * turn), so the rounds are cheap ones while they find feet elsewhere: the feet from the
 * curve's samples (el__fit_feet_elsewhere, each verified nearer; only once a sampled search,
 * the start's, has seen other passes near the points or the search everywhere has found feet
 * elsewhere), the refit by Levenberg-Marquardt alone, stopped at LOOSE_TOL and certified
 * once at the end; then the search everywhere (the report's) for what they missed; none
 * after FEET_ROUNDS refits by that search (a fit left with feet elsewhere that the samples
 * do not show would be refitted to the wrong feet). Measured on those 42 (callgrind, with
 * el__fit_feet_start's sampled search): 3.17e9 -> 1.83e9 instructions (before any refit
 * 1.31e9; el_fit_smooth alone 3.15e9 -> 1.81e9 with or without el__fit_feet_unproven's
 * proof), 15 rms lower (by up to 0.7 %), 25 the same to 1e-9, two higher by 5e-8 and
 * 1.4e-5 at an objective f lower by 2e-14 and 5e-5 (feet on the extension beyond an end,
 * which the reported distances do not use). */
static int settle_feet(fit_run_state *R)
{
    fit_objective *ob = &R->ob;
    fit_candidate *best = &R->best;
    feet_rounds fr = {ob->lm_tol, 1, 0, !R->need_ipopt && !R->o.limited_memory, 0, 0};
    int st = EL_OK;
    for (;;) {
        evaluate_kept(R);
        const int may_refit = R->ok && fr.refit && ob->rest && isfinite(best->f) &&
                              best->f > FIT_EXACT_F && R->map.nx > 0 &&
                              !(R->need_ipopt && R->ipopt_spent >= 1 && best->status != EL_OK);
        size_t moved = 0;
        int projected = 0;
        if (may_refit && R->last_is_best && fr.sampling && ob->other_passes &&
            fr.sampled < SAMPLED_ROUNDS && fr.round < FEET_ROUNDS && !best->used_ipopt) {
            if ((st = el__fit_feet_elsewhere(ob, best->x, R->v, R->d, R->fs, &moved)) == EL_ENOMEM)
                return st;
            projected = st == EL_OK;
        }
        if (moved) {
            fr.sampled++;
        } else if (fr.loose && R->ok) {
            fr.loose = 0;
            if ((st = certify_loose(R, st))) return st;
            continue;
        } else {
            if (R->ok)
                R->ok = el__fit_curve_distances(ob, best->x, R->v, projected, R->d, R->fs,
                                                R->tmp) == EL_OK &&
                        !el__all_finite(R->d, R->n) && !el__all_finite(R->fs, R->n);
            /* after SAMPLED_ROUNDS that all found feet elsewhere: no more rounds */
            if (!R->ok || !may_refit || fr.round == FEET_ROUNDS || fr.sampled == SAMPLED_ROUNDS)
                break;
            if (!kept_feet_elsewhere(R)) break;
            fr.round++;
            ob->other_passes = 1;
        }
        if ((st = refit_from_feet(R, moved, &fr))) return st;
    }
    return EL_OK;
}

/* ------------------------------------------------------------ the result */

/* The kept fit's distances and feet in input units, its rms and maximum error; a fit
 * whose distances are beyond double precision is none (EL_EDOM, ok = 0). */
static void report_distances(fit_run_state *R)
{
    const size_t n = R->n;
    const double sc = R->sc;
    double *d = R->d, *fs = R->fs;
    double s2 = 0.0, emax = 0.0;
    for (size_t i = 0; R->ok && i < n; i++) {
        s2 += d[i] * d[i];
        if (fabs(d[i]) > emax) emax = fabs(d[i]);     /* fmax, without a libm call (d is finite) */
        d[i] *= sc;
        fs[i] *= sc;
    }
    /* in the input's units too (fuzz: feet of 1e306 times the scale of 1e2 overflowed) */
    if (R->ok)
        R->ok = isfinite(sc * sqrt(s2 / (double)n)) && isfinite(sc * emax) &&
                !el__all_finite(fs, n);
    if (!R->ok) {
        R->status = EL_EDOM;
        for (size_t i = 0; i < n; i++) { d[i] = HUGE_VAL; fs[i] = 0.0; }
    }
    R->res->rms = R->ok ? sc * sqrt(s2 / (double)n) : HUGE_VAL;
    R->res->max_error = R->ok ? sc * emax : HUGE_VAL;
}

/* The kept fit's parameters in the model's form (el__fit_canonical) and input units, and
 * the rest of the result; never NaN, inf, mu = 0 or a curve outside the model (EL_EDOM:
 * outside double's range). Returns the result's status. */
static int report_params(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int model = R->model, ik = R->ik;
    fit_out *res = R->res;
    double *v0 = R->v[0];
    /* smooth -1 < k < 0 as k >= 0 with q + 2K when k, q are free and may move so */
    double shifted[FIT_NP];
    memcpy(shifted, v0, sizeof shifted);
    const int may_shift = model == FIT_SMOOTH && !o->fixed[ik] && !o->fixed[5] &&
                          el__fit_canonical(model, shifted, 1) == EL_OK &&
                          shifted[ik] >= R->lo[ik] && shifted[ik] <= R->hi[ik] &&
                          shifted[5] >= R->lo[5] && shifted[5] <= R->hi[5];
    if (!R->ok || el__fit_canonical(model, v0, may_shift)) {    /* only for unevaluable points */
        memcpy(v0, R->best_init, sizeof R->v[0]);
        el__fit_canonical(model, v0, 0);
        if (R->status == EL_OK) R->status = EL_ENOCONV;
    }
    for (int j = 0; j < FIT_NP; j++) {
        res->params[j] = o->fixed[j] ? o->value[j]
                                     : el__fit_denorm_param(model, j, v0[j], R->cx, R->cy, R->sc);
        res->initial[j] = o->use_initial ? R->init[j]
                        : el__fit_denorm_param(model, j, R->best_init[j], R->cx, R->cy, R->sc);
        if (!o->use_initial && o->fixed[j]) res->initial[j] = o->value[j];
    }
    int valid = !el__all_finite(res->params, FIT_NP) && !el__all_finite(res->initial, FIT_NP);
    if (model == FIT_SMOOTH) valid = valid && res->params[3] >= DBL_MIN && res->params[6] >= 0.0;
    else valid = valid && res->params[2] >= DBL_MIN && res->params[6] >= 0.0;
    if (!valid) {
        R->status = EL_EDOM;
        for (int j = 0; j < FIT_NP; j++) {
            if (!isfinite(res->params[j])) res->params[j] = 0.0;
            if (!isfinite(res->initial[j])) res->initial[j] = 0.0;
        }
    }
    res->iterations = R->iters; res->candidates = R->tried;
    res->f = R->best.f;
    res->ipopt_status = R->best.used_ipopt ? R->best.ipopt_status : 0;
    res->used_ipopt = R->best.used_ipopt;
    res->mode = R->mode;
    res->distance = R->kind == FIT_PAIRED ? EL_DISTANCE_PAIRED : EL_DISTANCE_ORTHOGONAL;
    res->constraint = R->constraint;
    res->seen = (fit_seen){R->xy, R->n, R->sc, R->noise_rms * R->sc, 0};
    return res->status = R->status;
}

/* ------------------------------------------------------------ further runs */

/* A refit's status st: the fit it may have replaced is no longer the one res->seen found to
 * follow its points. */
static int refitted(fit_run_state *R, int st)
{
    R->res->seen.follows = 0;
    return st;
}

/* A fit by distance without rows that strays from its points: refitted from the paired
 * curve or the other model's fit (el__fit_follow_points); a sketch's free fit that still
 * wanders: its guesses from their feet (fit_follow.c). st: the result's status; returns
 * the run's. */
static int follow_the_points(fit_run_state *R, int st)
{
    const el_fit_options *o = &R->o;
    const int model = R->model, flags = R->flags;
    const size_t n = R->n;
    if (!(R->ok && R->kind == FIT_ORTHOGONAL && !R->need_ipopt && !o->use_initial && !R->lm_only))
        return st;
    const double noise_in = R->noise_rms * R->sc;
    double stray = -1.0;
    const double of_curve = el__fit_stray_curve(R->xy, n, R->fs, el__fit_out_length(model, n, R->res),
                                                noise_in, R->sc, &stray);
    /* for the report: by both measures (el__fit_wander_gap) */
    R->res->seen.follows = stray >= 0.0 && stray <= FIT_STRAY && of_curve <= FIT_STRAY;
    /* el__fit_ends_held's run that strays is not kept (the fit it would replace has
     * followed its points already) */
    if (stray > FIT_STRAY && (flags & FIT_RUN_ENDS_HELD))
        st = EL_ENOCONV;
    else if (stray > FIT_STRAY &&
             (st = refitted(R, el__fit_follow_points(model, R->xy, n, R->opt, flags, noise_in, R->sc,
                                                     stray, R->res, R->d, R->fs))) == EL_OK)
        st = R->res->status;
    /* keep_the_better kept a fit over a lower one that crosses itself or strays: that one
     * went on (as before the rule) to el__fit_follow_points, whose refit from the paired
     * curve can end lower and following the points; tried here too, kept when lower and
     * not crossing itself. Smooth only: on the sweep's discrete start point + tangent fits
     * it gained on 2 of 100 at +30 s CPU (/tmp/scrib/sweep.py: smooth, start point and
     * tangent 0.1 rad off the data's, 0.1397 -> 0.1321, 0.1263 -> 0.1246 as before the
     * rule, and 0.1250 -> 0.1217) */
    else if (R->wander_kept && o->constraints && model == FIT_SMOOTH &&
             (st = refitted(R, el__fit_follow_unless_loops(model, R->xy, n, R->opt, flags, noise_in,
                                                           stray, &R->ob, R->norm, R->res, R->d,
                                                           R->fs))) == EL_OK)
        st = R->res->status;
    /* a sketch's free fit that still wanders: its guesses from their feet (fit_follow.c) */
    if (st != EL_ENOMEM && model == FIT_SMOOTH && !o->constraints && n < FIT_SKETCH_POINTS &&
        !(flags & FIT_RUN_INNER))
        st = refitted(R, el__fit_sketch_follows(R->xy, n, R->opt, noise_in, &R->ob, R->norm, R->res,
                                                R->d, R->fs, &R->wander_kept));
    return st;
}

/* The further runs of a fit that is the caller's (fit_restart.c): by distance where a paired
 * fit's points slip, Ipopt from an uncertified fit, the ends chart for held ends with a zero
 * start curvature, other starts for a sketch's constrained fit that wanders. st: the run's
 * status so far; returns the run's. */
static int further_runs(fit_run_state *R, int st)
{
    const el_fit_options *o = &R->o;
    const int model = R->model, flags = R->flags, inner = flags & FIT_RUN_INNER;
    const int caller_fit = !o->use_initial && !R->lm_only;
    const double *xy = R->xy;
    const size_t n = R->n;
    /* paired by the spacing test alone: refitted by distance to the polygon where its points
     * slip along the polygon from their vertices */
    int unpaired = 0;
    if (R->ok && R->kind == FIT_PAIRED && o->distance == EL_DISTANCE_AUTO && caller_fit &&
        !inner && st != EL_ENOMEM) {
        st = refitted(R, el__fit_unpaired(model, xy, n, R->opt, R->noise_rms * R->sc, R->res, R->d, R->fs));
        unpaired = R->res->distance == EL_DISTANCE_ORTHOGONAL;   /* its run polished it as needed */
    }
    /* not certified: Ipopt from this one; held ends as its rows */
    if (R->deferred && !unpaired && !inner && (st == EL_ENOCONV || st == EL_EMAXITER)) {
        const int rows = R->ends_chart ? FIT_RUN_ROWS : FIT_RUN_POLISH;
        /* after the rule that keeps a fit that neither crosses itself nor strays: its polish
         * does not end on a loop either (el__fit_fallback_unless_loops) */
        st = refitted(R, R->wander_kept
                             ? el__fit_fallback_unless_loops(model, xy, n, R->opt, rows, &R->ob,
                                                             R->norm, R->res, R->d, R->fs)
                             : el__fit_fallback(model, xy, n, R->opt, rows, R->res, R->d, R->fs));
    }
    /* pinned at both ends with a zero start curvature: fitted in the ends chart too, that
     * curvature held there (el__fit_ends_held); with an end curvature other than 0 (a row
     * in either chart, where the ends chart's runs are the slower) only when this fit was
     * not certified; the natural batten's ran first (el__fit_run) */
    if (R->ends_ok && R->zero_k0 && !R->ends_chart && !R->natural && caller_fit && !inner &&
        st != EL_ENOMEM &&
        (!(o->constraints & EL_CONSTRAIN_END_CURVATURE) || R->con.end_kappa == 0.0 || st != EL_OK))
        st = refitted(R, el__fit_ends_held(model, xy, n, R->opt, R->res, R->d, R->fs));
    /* a sketch's constrained fit that wanders: its constraints from other starts (not the
     * natural batten's, whose family was searched whole) */
    if (R->ok && model == FIT_SMOOTH && R->kind == FIT_ORTHOGONAL && o->constraints &&
        n < FIT_SKETCH_POINTS && !R->natural && caller_fit && !inner && fit_gave_curve(st))
        st = refitted(R, el__fit_sketch_follows_held(xy, n, R->opt, R->noise_rms * R->sc, &R->ob,
                                                     R->norm, R->res, R->d, R->fs));
    /* rows where bounds or fixed values keep the start-state chart off: the guesses all end in
     * the unconstrained fit's basin; Ipopt's L-BFGS path from each guess too, the lower kept
     * (fit_restart.c, el__fit_other_path), unless the fit is within 1.5 x the noise figure
     * (the candidates' stop) */
    if (R->ok && R->need_ipopt && !R->chart_ok && !o->limited_memory && caller_fit && !inner &&
        st != EL_ENOMEM && !(R->res->rms <= 1.5 * R->noise * R->sc && st == EL_OK))
        st = refitted(R, el__fit_other_path(model, xy, n, R->opt, R->res, R->d, R->fs));
    return st;
}

/* ------------------------------------------------------------ the run */

int el__fit_run(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                const double *init, fit_out *res, double *dist, double *foot)
{
    fit_run_state R;
    memset(&R, 0, sizeof R);
    R.model = model; R.xy = xy; R.n = n; R.opt = opt; R.flags = flags; R.init = init; R.res = res;
    R.lm_only = flags & FIT_RUN_LM_ONLY;
    int st = read_options(&R);
    if (st || (st = normalised_bounds(&R))) return st;
    choose_charts(&R);
    if (R.natural && !R.ends_chart && !(flags & FIT_RUN_INNER)) {
        /* the natural batten: the ends chart's run first */
        st = el__fit_run(model, xy, n, opt, flags | FIT_RUN_ENDS_HELD, init, res, dist, foot);
        if (st == EL_ENOMEM || st == EL_OK || res->status == EL_ENOCONV ||
            res->status == EL_EMAXITER)
            return st;
    }
    build_map(&R);
    if (!(st = alloc_work(&R, dist, foot)) && !(st = el__fit_starts(&R)) &&
        !(st = el__fit_choose(&R)) && !(st = settle_feet(&R))) {
        report_distances(&R);
        st = report_params(&R);
        st = follow_the_points(&R, st);
        st = further_runs(&R, st);
    }
    el__fit_objective_free(&R.ob);
    free(R.kept_feet);
    free(R.dbuf);
    free(R.t);
    free(R.tmp);
    return st;
}

/* The kept fit's gap it wanders in (el__fit_wander_gap) in the caller's points and feet fs
 * (input units), from what the fit saw (fo->seen); a start point held (or x0, y0 fixed) or an
 * end point held allows it the curve to that point (el__fit_stray_held's ends). */
static long wander_gap(int model, const double *xy, size_t n, const el_fit_options *opt,
                       const fit_out *fo, const double *fs)
{
    double ends[4] = {NAN, NAN, NAN, NAN};
    if (opt && ((opt->constraints & EL_CONSTRAIN_START_POINT) || (opt->fixed[0] && opt->fixed[1]))) {
        const int c = opt->constraints & EL_CONSTRAIN_START_POINT;
        ends[0] = c ? opt->start_point[0] : opt->value[0];
        ends[1] = c ? opt->start_point[1] : opt->value[1];
    }
    if (opt && (opt->constraints & EL_CONSTRAIN_END_POINT)) memcpy(ends + 2, opt->end_point, sizeof opt->end_point);
    return el__fit_wander_gap(model, xy, n, fo->params, fs, fo->rms, ends, &fo->seen);
}

/* One public fit: el__fit_run_framed with the feet kept for wander_gap where the caller
 * takes none (-1 for the gap where they cannot be allocated). */
static int public_fit(int model, const double *xy, size_t n, const el_fit_options *opt,
                      const double *init, fit_out *fo, double *distances, double *foot_s, long *gap)
{
    double *buf = NULL;
    if (!foot_s && xy && n >= 4 && n < SIZE_MAX / (2 * sizeof(double)))
        foot_s = buf = malloc(sizeof(double) * n);
    memset(fo, 0, sizeof *fo);
    fo->status = -1;
    int st = el__fit_run_framed(model, xy, n, opt, 0, init, fo, distances, foot_s);
    if (fo->status != -1) st = el__fit_free_ends(model, xy, n, opt, st, fo, distances, foot_s);
    if (model == FIT_SMOOTH && fo->status != -1 && st != EL_ENOMEM) el__fit_trim_to_feet(opt, st, fo, foot_s, n);
    *gap = fo->status != -1 && foot_s ? wander_gap(model, xy, n, opt, fo, foot_s) : -1;
    free(buf);
    return st;
}

/* The public wrappers: the result struct written only once a result exists. */
int el_fit_discrete(const double *xy, size_t n, const el_fit_options *opt,
                    const el_discrete_params *initial, el_fit_discrete_result *res,
                    double *distances, double *foot_s)
{
    if (!res) return EL_EINVAL;
    double init[FIT_NP];
    if (initial) {
        const double p[FIT_NP] = {initial->x0, initial->y0, initial->h, initial->phi, initial->z,
                                  initial->q, initial->k};
        memcpy(init, p, sizeof init);
    }
    fit_out fo;
    long gap;
    const int st = public_fit(FIT_DISCRETE, xy, n, opt, initial ? init : NULL, &fo, distances, foot_s, &gap);
    if (fo.status == -1) {        /* failed before a result existed */
        if (fo.constraint) res->constraint = fo.constraint;
        return st;
    }
    fo.status = fit_public_status(fo.status);
    FIT_PUBLISH(res, fo, el_discrete_params);
    res->wander_gap = gap;
    return fo.status;
}

int el_fit_smooth(const double *xy, size_t n, const el_fit_options *opt,
                  const el_smooth_params *initial, el_fit_smooth_result *res,
                  double *distances, double *foot_s)
{
    if (!res) return EL_EINVAL;
    double init[FIT_NP];
    if (initial) {
        const double p[FIT_NP] = {initial->x0, initial->y0, initial->phi, initial->mu, initial->k,
                                  initial->q, initial->length};
        memcpy(init, p, sizeof init);
    }
    fit_out fo;
    long gap;
    const int st = public_fit(FIT_SMOOTH, xy, n, opt, initial ? init : NULL, &fo, distances, foot_s, &gap);
    if (fo.status == -1) {
        if (fo.constraint) res->constraint = fo.constraint;
        return st;
    }
    fo.status = fit_public_status(fo.status);
    FIT_PUBLISH(res, fo, el_smooth_params);
    res->wander_gap = gap;
    res->param_mode = fo.mode;
    return fo.status;
}

int el__fit_start(int model, const double *xy, size_t n, const el_fit_options *opt, double *v,
                  int *mode, int *iters, double *foot)
{
    fit_out fo;
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    int st = el__fit_run(model, xy, n, opt, FIT_RUN_LM_ONLY, NULL, &fo, NULL, foot);
    if (fo.status == -1) return st;
    memcpy(v, fo.params, sizeof fo.params);
    if (mode) *mode = fo.mode;
    *iters += fo.iterations;
    return fo.status;
}
