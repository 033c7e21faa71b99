/*
 * The fit of each start and the choice among them (el__fit_run's second middle stage,
 * fit.c; the starts from fit_starts.c). Each start is fitted (fit_candidate.c) in the order
 * of the list, the next only while the best rms is above both the exact level and 1.5 x the
 * noise level (el__fit_noise_rms); or last the unconstrained or the smooth fit's curve,
 * while every guess is far from the noise. A fit replaces the kept one by the rules of
 * keep_the_better. Joined G1 at both ends, the Hermite families' members (fit_g1_family.c)
 * are a second pass.
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include "fit_obstate.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a G1 family member is fitted where its own objective is below this multiple of the kept
 * fit's: its fit comes lower (16 sketched points between nearly collinear lines: a member
 * at 1.12 x a guess's looping fit reached 0.86 x it, following the points, QA) */
static const double MEMBER_GAIN = 4.0;
/* a sketch's free fit with rows is a start where its objective is below this share of the
 * constrained fits' best (its rms below half theirs: constraints that cost that much are
 * not the data's own, or the guesses missed their basin) */
static const double FREE_GAIN = 0.25;

/* The first feet of a fit by distance with feet (orthogonal smooth): the fractions' places
 * t_i on a curve of the given length. */
static void first_feet(fit_objective *ob, const double *t, double length)
{
    if (fit_has_feet(ob))
        for (size_t i = 0; i < ob->n; i++) ob->s[i] = t[i] * length;
}

/* ------------------------------------------------------------ each start fitted */

/* What the candidate loop does next: go on with this start, skip to the next, stop. */
enum { GO_ON, GO_SKIP, GO_STOP };

/* One start's fit: r, from the parameters p0 (normalised, its fixed values set);
 * feet_stale: ob's feet are not r's; strays: r strays from its points (-1: not known);
 * meets: r meets the constraints (with rows, or the unconstrained start). */
typedef struct fit_trial {
    fit_candidate r;
    double p0[FIT_NP];
    int feet_stale, strays, meets;
} fit_trial;

/* The slot after the guesses (every guess far from the noise): one more start, the
 * unconstrained fit's curve first, then the smooth fit's; *go GO_SKIP where that gave none
 * and the other may, GO_STOP where none is left. */
static int add_last_start(fit_run_state *R, int *go)
{
    const int use_free = R->free_start;
    double *slot = R->cand[R->ncand];
    const double f_below = (R->sketch_rows ? FREE_GAIN : 0.99) * R->best.f;
    const int fst = use_free
                  ? el__fit_unconstrained_start(R->model, R->xy, R->n, R->opt, R->cx, R->cy, R->sc,
                                                f_below, slot)
                  : el__fit_smooth_start(R->xy, R->n, R->opt, FIT_RUN_NO_CONJUGATE, R->cx, R->cy,
                                         R->sc, slot);
    if (fst == EL_ENOMEM) return fst;
    if (use_free) R->free_start = 0; else R->smooth_start = 0;
    *go = GO_ON;
    if (fst) {
        *go = R->smooth_start ? GO_SKIP : GO_STOP;    /* the smooth start in this slot */
        return EL_OK;
    }
    if (use_free) R->free_ci = R->ncand; else R->smooth_ci = R->ncand;
    R->ncand++;
    return EL_OK;
}

/* A family member whose Ipopt run did not meet the rows (6 points exactly on a curve: to
 * max_iter at a minimum it could not certify): from it as from a guess,
 * Levenberg-Marquardt first, kept when that meets them. */
static int member_as_guess(fit_run_state *R, fit_trial *tr, const double *x0)
{
    fit_objective *ob = &R->ob;
    if (el__fit_meets(ob, &R->map, &R->con, tr->r.x, R->lo, R->hi, R->tmp) ||
        el__fit_feet_start(ob, x0) != EL_OK)
        return EL_OK;
    fit_candidate rb;
    int st = el__fit_solve_candidate(ob, &R->o, &R->con_rows, R->xl, R->xu, R->need_ipopt,
                                     R->no_polish, x0, R->best.f, &rb, R->tmp, 0, 1);
    if (st) return st;
    rb.iters += tr->r.iters;
    if (el__fit_meets(ob, &R->map, &R->con, rb.x, R->lo, R->hi, R->tmp)) tr->r = rb;
    else tr->r.iters = rb.iters;
    return EL_OK;
}

/* Smooth: where the continuation's fit is above the noise or strays from the points, the
 * guess with the held start state set to the constraints directly is fitted too, kept when
 * lower (with rows: when it meets them and is lower, or the continuation's does not). The
 * continuation follows the free fit's basin, which need not hold the constrained one
 * (measured on 2 x 150 sparse noisy sets of each of 7 kinds, from 6 to 59 points: a
 * G2-start fit, rms 0.039 where its true curve has 0.0117; four G2-start G1-end sets
 * EL_EDOM that their true curves meet; a G1-G1 set along a loop of length 2.9 at 2.1 x its
 * true curve's rms, another fit 5 x; none worse. Straying: a start curvature alone, a loop
 * of length 3.1 at rms 0.0217 within the noise rule, 0.0095 directly). */
static int direct_held_start(fit_run_state *R, fit_trial *tr, double *x0)
{
    fit_objective *ob = &R->ob;
    const int need_ipopt = R->need_ipopt;
    fit_candidate *r = &tr->r, rd;
    first_feet(ob, R->t, tr->p0[6]);
    el__fit_map_inverse(&R->map, tr->p0, x0);
    ob->have_base = 0;
    int st = el__fit_solve_candidate(ob, &R->o, &R->con_rows, R->xl, R->xu, need_ipopt,
                                     R->no_polish, x0, R->best.f, &rd, R->tmp, 0, 0);
    if (st) return st;
    rd.iters += r->iters;
    const int r_meets = !need_ipopt || el__fit_meets(ob, &R->map, &R->con, r->x, R->lo, R->hi,
                                                     R->tmp);
    const int rd_meets = !need_ipopt || el__fit_meets(ob, &R->map, &R->con, rd.x, R->lo, R->hi,
                                                      R->tmp);
    const int direct = rd_meets && (!r_meets || rd.f < r->f);
    R->ipopt_spent += el__fit_ran_out(direct ? r : &rd);   /* the run let go; the kept one later */
    if (direct) { *r = rd; tr->strays = -1; }
    else { r->iters = rd.iters; tr->feet_stale = 1; }     /* ob.s: the direct fit's feet */
    return EL_OK;
}

/* Conditions the data do not share (a designer's wrong value): a held start's continuation
 * (el__fit_held_start's Levenberg-Marquardt, fs: the free fit's f and the held one's) ends
 * above UNSHARED x the free fit's rms and the noise figure, and above UNSHARED_RMS (of the
 * points' rms radius). Such a fit's later starts are held to the same wrong value: with rows,
 * once one start's Ipopt run has ended at max_iter and a fit meets them, no other start's
 * Ipopt runs (solve_start: GO_STOP). Measured on the qa9 scan held at 4 x its start curvature
 * (bench_fit.py wrong_conditions), discrete: the continuation's rms 350 x the free fit's at
 * 182 points, 380 x at 2000; the runs left out ended at 1.4 x and 11 x the kept fit's f, 0.34
 * and 8 s of 1.35 and 15.8 s, the fit the same. Constraints the data share leave the
 * continuation near the free fit (the sparse sketch suites: every fit the same). */
static const double UNSHARED = 10.0, UNSHARED_RMS = 0.01;
static int unshared(const fit_run_state *R, const double *fs)
{
    const double held = sqrt(2.0 * fs[1]), free = sqrt(2.0 * fs[0]);
    return held > UNSHARED_RMS && held > UNSHARED * fmax(free, R->noise);
}

/* A start fitted (fit_candidate.c) from x0: a held start state reached by continuation
 * first (el__fit_held_start) unless the start is a curve's own; a conjugate start's feet
 * found again (el__fit_refeet); then member_as_guess and direct_held_start. */
static int solve_start(fit_run_state *R, size_t ci, fit_trial *tr, double *x0, int from_smooth,
                       int from_curve, int *go)
{
    fit_objective *ob = &R->ob;
    fit_candidate *r = &tr->r;
    int pre = 0, st;
    if (R->staged && !R->polish_run && !from_smooth && !from_curve) {
        double fs[2];
        pre = el__fit_held_start(ob, &R->map, &R->free_map, R->staged, &R->con, R->o.max_iter,
                                 tr->p0, x0, fs);
        first_feet(ob, R->t, tr->p0[6]);      /* again (the stages moved them) */
        R->unshared |= unshared(R, fs);
        if (R->unshared && R->need_ipopt && R->best_meets && R->ipopt_spent >= 1) {
            memset(r, 0, sizeof *r);
            r->f = HUGE_VAL;
            r->status = EL_ENOCONV;
            r->iters = pre;
            *go = GO_STOP;
            return EL_OK;
        }
    }
    /* the discrete fit's smooth start with rows (from_smooth, need_ipopt) is near too: Ipopt
     * from the smooth fit's polygon, which meets the rows nearly, not from the unconstrained
     * fit that Levenberg-Marquardt would return to and the penalty stages from there. From
     * that basin every start of a ship frame held at both end tangents and curvatures (57
     * points with a gap, 1 % noise, QA22 B) shrank to h ~ 1e-14 .. 1e-9 off the rows and the
     * fit ended EL_EMAXITER at rms 3.84 with an end curvature 5e7 off; Ipopt from the smooth
     * polygon meets them in 2 iterations at rms 0.3564, the smooth fit's. An ellipse arc held
     * at both ends, both curvatures and a length bound (QA22 A): 0.4038 at the bound, wander
     * gap 34 -> 0.2688, the smooth fit's. The caller's start of a discrete fit with rows
     * (caller_twice's first) so too: started on the smooth fit's polygon, 0.2686 off the
     * rows, the ellipse returned 0.4038 on the bound; now 0.2688 (scipy SLSQP's from there) */
    const int near = (R->staged && pre > 0) || R->polish_run ||
                     (from_smooth && (ci == R->natural_ci || R->need_ipopt)) || ci < R->nfamily ||
                     ci < R->nconj ||
                     (R->caller_twice && ci == 0 && R->need_ipopt && R->model == FIT_DISCRETE);
    if ((st = el__fit_solve_candidate(ob, &R->o, &R->con_rows, R->xl, R->xu, R->need_ipopt,
                                      R->no_polish, x0, R->best.f, r, R->tmp, near,
                                      R->polish_run || from_curve)))
        return st;
    r->iters += pre;
    if (ci < R->nconj && (st = el__fit_refeet(ob, &R->o, &R->con_rows, &R->con, R->lo, R->hi, R->xl,
                                              R->xu, R->no_polish, r, &tr->feet_stale, R->tmp)))
        return st;
    if (ci < R->nfamily && (st = member_as_guess(R, tr, x0))) return st;
    if (R->staged && !R->polish_run && !from_curve && R->model == FIT_SMOOTH &&
        (!(sqrt(2.0 * r->f) <= 1.5 * R->noise && r->status == EL_OK) ||
         (ob->rest &&
          (tr->strays = el__fit_strays_at(ob, r->x, R->noise_rms, R->d, R->fs, R->tmp)))))
        return direct_held_start(R, tr, x0);
    return EL_OK;
}

/* Whether start ci's Ipopt runs are held to the kept fit's objective (ob->rows_cap: stopped
 * at an iterate near the rows once the rate test says it cannot reach it, fit_ipopt.c):
 * with rows, where the kept fit meets them and does not cross itself (a fit that crosses
 * itself gives way to a higher one that does not, keep_the_better), for a guess or a further
 * start (not the G1 family's members nor the conjugate starts: their rules read the run's
 * end), unless the caller asks for every run to its end (el_fit_options.exhaustive). A run so
 * stopped ends above the kept fit (at the stop: the rate test is a forecast, not a proof):
 * it is not kept, and it counts as a run to max_iter (el__fit_ran_out, stop_rule). Measured on sine-like scans of 200-400 noisy points held G1 at both ends
 * (2-3 inflections, the data no elastica: the held fit 3-5 x the free one's rms): the later
 * guesses took 1300-3100 iterations each (Levenberg-Marquardt's stages and Ipopt's), 0.4-1.5
 * s, to fits 17-40 x the kept one's objective. */
static int rows_capped(fit_run_state *R, size_t ci)
{
    if (R->o.exhaustive || !R->need_ipopt || !R->best_meets || !isfinite(R->best.f) ||
        ci < R->nfamily || ci < R->nconj)
        return 0;
    if (R->best_loops < 0) R->best_loops = el__fit_loops(&R->ob, R->best.x);
    return !R->best_loops;
}

/* Start ci fitted into *tr: its fixed parameters set (the discrete u(s) kept where h is
 * fixed), turned and scaled onto held ends; *go GO_SKIP where it cannot be evaluated. */
static int fit_one_start(fit_run_state *R, size_t ci, fit_trial *tr, int *go)
{
    fit_objective *ob = &R->ob;
    const fit_map *map = &R->map;
    double *p0 = tr->p0, x0[FIT_MAXX];
    *go = GO_SKIP;
    memcpy(p0, R->cand[ci], sizeof tr->p0);
    for (int j = 0; j < FIT_NP; j++) {
        if (!R->o.fixed[j]) continue;
        if (R->model == FIT_DISCRETE && j == 2 && !R->o.fixed[4]) p0[4] *= map->fixed[2] / p0[2];
        p0[j] = map->fixed[j];
    }
    if (el__all_finite(p0, FIT_NP)) return EL_OK;
    el__fit_map_inverse(map, p0, x0);
    if (R->ends_chart) {       /* the guess turned and scaled onto the ends (its feet too) */
        double ve[2][FIT_NP];
        if (el__fit_map_eval(map, x0, ve, NULL)) return EL_OK;
        memcpy(p0, ve[0], sizeof tr->p0);
    }
    first_feet(ob, R->t, p0[6]);
    /* the natural batten's member */
    const int family = ci == R->natural_ci && R->model == FIT_SMOOTH;
    /* the smooth fit's curve */
    const int from_smooth = (ci == R->natural_ci || ci == R->smooth_ci) && R->model == FIT_DISCRETE;
    /* a curve's own start (the caller's, or a sketch's free fit with rows): from its feet,
     * neither the held start's continuation nor the paired start, which moved the free fit
     * above from its curve onto the same figure-eight */
    const int from_curve = R->caller_start || (R->caller_twice && ci == 0) || ci < R->nfamily ||
                           ci < R->nconj ||
                           (R->sketch_rows && ci == R->free_ci && R->kind == FIT_ORTHOGONAL);
    if ((R->polish_run || from_curve || family) && ob->rest && el__fit_feet_start(ob, x0))
        return EL_OK;
    tr->feet_stale = 0;
    tr->strays = -1;
    if (map->nx == 0 || family) {
        /* nothing to fit, or the natural batten's member (its fit, certified along the
         * family where Brent's minimiser converged: fit_natural.c) */
        fit_value fv;
        if (el__fit_objective_eval(ob, x0, 0, &fv)) return EL_OK;
        memset(&tr->r, 0, sizeof tr->r);
        memcpy(tr->r.x, x0, sizeof tr->r.x);
        tr->r.f = fv.f;
        tr->r.status = !family || R->natural_ok ? EL_OK : EL_ENOCONV;
        tr->r.iters = family ? R->natural_evals : 0;
    } else {
        ob->rows_cap = rows_capped(R, ci);
        int st = solve_start(R, ci, tr, x0, from_smooth, from_curve, go);
        ob->rows_cap = 0;
        if (st || *go == GO_STOP) return st;
    }
    *go = GO_ON;
    return EL_OK;
}

/* ------------------------------------------------------------ the choice */

/* Start ci's fit counted, and kept (R->best) where it is the better.
 * The unconstrained start only where its fit meets the constraints (where Ipopt could not,
 * its f is that of the free fit); with rows, a fit that meets them before one that does
 * not, whatever their f (measured: a discrete G1-G1 sketch of 7 points, whose first guess
 * ended at Ipopt's max_iter off the end tangent below the f of the three that met it,
 * failed with EL_EDOM).
 * A constrained fit that crosses itself or strays from its points (el__fit_wanders) does not
 * replace one that does neither (a G1 family member: 7 noisy points along a near-straight
 * curve, a loop in a gap between them, rms 0.84 x the kept fit's, within el__fit_stray's
 * allowance for a curved arc; el__fit_follow_points' refit of the hull profile above from
 * the paired curve: its held start's loop below its feet's fit). Not the other way round:
 * a fit pinned away from clustered points strays by that measure (test_fit_basin.c's
 * clustered G1 sketch: 28 x its true curve's rms); but one that crosses itself gives way
 * to one that does not (el__fit_fair_over_loop). */
static void keep_the_better(fit_run_state *R, size_t ci, fit_trial *tr)
{
    fit_objective *ob = &R->ob;
    const fit_candidate *r = &tr->r;
    const int need_ipopt = R->need_ipopt, constrained = R->o.constraints && !R->lm_only;
    R->tried++;
    R->iters += r->iters;
    const int r_meets = (need_ipopt || ci == R->free_ci) &&
                        el__fit_meets(ob, &R->map, &R->con, r->x, R->lo, R->hi, R->tmp);
    tr->meets = r_meets;
    R->last_is_best = ci == R->free_ci ? r_meets && r->f < R->best.f
                    : need_ipopt ? (r_meets && !R->best_meets) ||
                                       (r_meets == R->best_meets && r->f < R->best.f)
                    : r->f < R->best.f;
    if (R->last_is_best && constrained && isfinite(R->best.f) && (R->best_meets || !need_ipopt) &&
        el__fit_wanders(ob, r->x, &tr->strays, R->noise_rms, R->d, R->fs, R->tmp)) {
        R->last_is_best = el__fit_wanders(ob, R->best.x, &R->best_strays, R->noise_rms, R->d,
                                          R->fs, R->tmp);
        R->wander_kept |= !R->last_is_best;
    } else if (!R->last_is_best && constrained && (need_ipopt || ci == R->free_ci ? r_meets : 1) &&
               el__fit_fair_over_loop(ob, r->x, r->f, &tr->strays, R->best.x, R->best.f,
                                      &R->best_loops, R->noise_rms, R->d, R->fs, R->tmp)) {
        R->last_is_best = R->wander_kept = 1;
    }
    if (R->last_is_best) {
        R->best = *r;
        R->best_strays = tr->strays;
        R->best_meets = r_meets;
        memcpy(R->best_init, tr->p0, sizeof tr->p0);
        R->best_loops = -1;
        R->family_won |= ci < R->nfamily;
    }
    R->last_is_best &= !tr->feet_stale;
}

/* Paired by the spacing test alone, the smooth start's polygon certified and kept: where
 * its points slip along it (el__fit_slips), the guesses fit a pairing that el__fit_unpaired
 * replaces (2000 uneven points, G1 at both ends: three guesses' continuations crept
 * 2400-4500 iterations each, 26 s, before its refit by distance from this one). */
static int smooth_start_slips(fit_run_state *R)
{
    double vs[2][FIT_NP], s2 = 0.0;
    if (el__fit_map_eval(&R->map, R->best.x, vs, NULL) != EL_OK ||
        el__fit_curve_distances(&R->ob, R->best.x, vs, 0, R->d, R->fs, R->tmp) != EL_OK)
        return 0;
    for (size_t i = 0; i < R->n; i++) s2 += R->d[i] * R->d[i];
    return el__fit_slips(R->n, vs[0][2], sqrt(s2 / (double)R->n), NULL, R->fs);
}

/* Whether the candidates stop after start ci's fit (GO_STOP), or go on (GO_ON; *ci moved
 * to the last guess where only the further starts are left). */
static int stop_rule(fit_run_state *R, size_t *ci, const fit_trial *tr)
{
    const int need_ipopt = R->need_ipopt;
    const fit_candidate *best = &R->best;
    /* the natural batten's member meets the rows: every fit that does is a member of
     * the family already searched */
    if (*ci == R->natural_ci && tr->meets) return GO_STOP;
    if (*ci == R->smooth_ci && R->last_is_best && best->status == EL_OK && R->kind == FIT_PAIRED &&
        R->o.distance == EL_DISTANCE_AUTO && !(R->flags & FIT_RUN_INNER) &&
        (R->best_meets || !need_ipopt) && smooth_start_slips(R))
        return GO_STOP;
    const double rms = sqrt(2.0 * best->f);
    if (rms <= 1e-10 || R->map.nx == 0) return GO_STOP;
    if (*ci < R->nfamily) return GO_ON;    /* every family member fitted */
    /* constraint rows: Ipopt's runs that end at max_iter, at most two over the guesses once
     * one has met the constraints (converged, or the penalty's point); while none has, no
     * refit after one (the fuzzer's 11 points with end constraints: five runs to max_iter,
     * 1.3 s; a discrete sketch of 45 points pinned at both ends, every guess to max_iter,
     * 3.1 s) */
    if (need_ipopt && (R->ipopt_spent += el__fit_ran_out(&tr->r)) >= 2 &&
        (best->status == EL_OK || R->best_meets)) {
        if (!R->smooth_start && !(R->free_start && R->sketch_rows)) return GO_STOP;
        /* no more guesses; the smooth fit's (or a sketch's free) start next */
        *ci = R->ncand - 1;
        return GO_ON;
    }
    /* with rows there is no follow_points refit at the end: a fit that strays from its
     * points (a loop where there is none) is no reason to stop (measured on the sets of
     * direct_held_start: with the direct start but without this check, a G1-G1 fit of 41
     * points stopped on a loop of length 3.0 at rms 0.0133, where the next guess reaches
     * 0.0079 and the true curve, length 1, has 0.0081) */
    if (need_ipopt && R->kind == FIT_ORTHOGONAL && rms <= 1.5 * R->noise && best->status == EL_OK &&
        R->best_strays < 0)
        R->best_strays = el__fit_strays_at(&R->ob, best->x, R->noise_rms, R->d, R->fs, R->tmp);
    /* a fit where Levenberg-Marquardt stalled uncertified (no step lowers f), whose polish
     * is deferred (el__fit_fallback after the run), stops too: the polish made it EL_OK here
     * before (measured: a smooth fit with a start tangent of 45 points, the first guess
     * stalled at rms 0.68 x the noise figure; without this all five guesses and the
     * unconstrained start ran, 14 -> 56 ms, for the same fit). Not one that crawled to
     * max_iter: the next guesses can reach a lower basin (a discrete sketch of 41 points:
     * 0.0072 by the third guess, where the first crawled to 0.016 within 1.5 x the figure) */
    const int settled = best->status == EL_OK || (R->deferred && best->status == EL_ENOCONV);
    if (rms <= 1.5 * R->noise && settled &&
        !(need_ipopt && R->kind == FIT_ORTHOGONAL && R->best_strays > 0)) {
        /* held ends: the discrete fit's smooth start too, while above the data's own
         * figure (the constrained fits' plain noise figure is high on sparse curved
         * points: a set of 41 points whose polygon ended at 2.7 x its curve's rms, length
         * 1.22 for 1, within 1.5 of it; the smooth start reaches 0.93 x) */
        const int more = (R->free_start || (R->smooth_start && R->ends_chart)) &&
                         (rms > 1.5 * R->data_noise || (R->free_start && R->sketch_rows));
        if (!more) return GO_STOP;
        *ci = R->ncand - 1;   /* no more guesses; the unconstrained start next */
    }
    return GO_ON;
}

/* The kept fit (smooth, by distance, with rows) above the stop rule's level, whose nearest
 * points, found from the fractions' places as settle_feet's (fit.c), lie on another pass of
 * the curve than its feet (either of kept_feet_elsewhere's tests, which takes one by whether
 * ob's feet are the kept fit's: el__fit_nearer_than, or el__fit_feet_moved where they are): fitted again from its point with those feet
 * now, as settle_feet does after the last start, and kept where that refit is certified,
 * meets the rows, is lower and exact (rms 1e-10 of the data's size: stop_rule's first stop).
 * Else the objective is put back as it was (the refit's iterations counted), and the starts
 * go on as before. Measured: 1000 noise-free points of an elastica sketched with a gap,
 * both end tangents held (test_fit.py's exact fits): the first start ended at rms 7.9e-5 with
 * feet on the other pass, five more starts ran (7639 iterations, three to Ipopt's max_iter, 4.9 s
 * CPU) for settle_feet to reach 1.2e-14 from the same point; now that refit after the first. */
static int settle_early(fit_run_state *R, size_t ci)
{
    fit_objective *ob = &R->ob;
    const size_t n = R->n;
    const double rms = sqrt(2.0 * R->best.f);
    if (!(R->need_ipopt && R->best_meets && R->best.status == EL_OK &&
          R->kind == FIT_ORTHOGONAL && R->model == FIT_SMOOTH && fit_has_feet(ob) && ob->rest &&
          R->map.nx > 0 && ci >= R->nfamily && rms > 1e-10 && rms > 1.5 * R->noise))
        return EL_OK;
    /* this kept fit refitted already (the starts since kept none better): the same refit
     * from the same curve and the same feet, rejected again (revB: 6 identical refits on an
     * exact 50-point sketch; +24 iterations on noisy 200-point fits). f > 0 here (rms above) */
    if (R->best.f == R->settle_tried_f) return EL_OK;
    R->settle_tried_f = R->best.f;
    double v[2][FIT_NP];
    if (el__fit_map_eval(&R->map, R->best.x, v, NULL) != EL_OK) return EL_OK;
    fit_ob_state saved;
    /* the nearest points' distances and feet: arrays of their own (R->d is ob's rest array,
     * whose evaluations leave NaN where a foot is not at rest) */
    double *d = malloc(sizeof(double) * 2 * n), *fs = d + n;
    if (!d) return EL_ENOMEM;
    if (el__fit_ob_save(ob, &saved)) { free(d); return EL_ENOMEM; }
    const double L = v[0][6];
    int elsewhere = 0, st = EL_OK;
    /* from the fractions' places, as evaluate_kept (fit.c) starts a fit without its own feet:
     * Newton's steps from its own feet stay on their pass */
    first_feet(ob, R->t, L);
    ob->have_base = ob->rest_ok = 0;
    if (el__fit_curve_distances(ob, R->best.x, v, 0, d, fs, R->tmp) == EL_OK &&
        !el__all_finite(d, 2 * n)) {
        el__fit_ob_restore(ob, &saved);      /* the feet as the fit left them */
        /* its feet elsewhere (where they are its own: a later run's may be in ob), or its
         * distances below its fit */
        elsewhere = el__fit_nearer_than(d, n, R->best.f) ||
                    (R->last_is_best && el__fit_feet_moved(ob->s, fs, n, L));
    }
    fit_candidate r;
    int took = 0;
    if (elsewhere) {
        el__fit_feet_set(ob, fs, L);
        st = el__fit_solve_candidate(ob, &R->o, &R->con_rows, R->xl, R->xu, R->need_ipopt,
                                     R->refit_no_polish, R->best.x, R->best.f, &r, R->tmp, 1, 1);
        if (!st) {
            R->iters += r.iters;
            const double rr = sqrt(2.0 * r.f);
            /* exact (stop_rule's first stop): no other start can end lower but by rounding. Not
             * at the noise rule's level: there the starts after it reach other basins
             * (test_fit_basin.c's clustered G1 sketch CLUSTER_S2_104: a refit at the noise
             * figure stopped the starts at 28 x the true curve's rms) */
            took = r.status == EL_OK && r.f < R->best.f && rr <= 1e-10 &&
                   el__fit_meets(ob, &R->map, &R->con, r.x, R->lo, R->hi, R->tmp);
        }
    }
    if (took) {
        R->best = r;
        R->last_is_best = 1;      /* ob's feet are the refit's */
        R->best_strays = R->best_loops = -1;
        ob->have_base = ob->rest_ok = 0;
    } else {
        el__fit_ob_restore(ob, &saved);
    }
    free(saved.buf);
    free(d);
    return st == EL_ENOMEM || st == EL_EINTERNAL ? st : EL_OK;
}

/* One pass over the starts cand[0..ncand) and then the last one (add_last_start). */
static int candidate_pass(fit_run_state *R)
{
    for (size_t ci = 0; ci < R->ncand + (R->free_start || R->smooth_start); ci++) {
        int go = GO_ON, st;
        if (ci == R->ncand) {
            if ((st = add_last_start(R, &go))) return st;
            if (go == GO_STOP) break;
            if (go == GO_SKIP) { ci--; continue; }
        }
        fit_trial tr;
        if ((st = fit_one_start(R, ci, &tr, &go))) return st;
        if (go == GO_SKIP) continue;
        if (go == GO_STOP) {
            /* (solve_start: conditions not shared) as stop_rule's limit on the runs */
            R->iters += tr.r.iters;
            R->last_is_best = 0;
            if (!R->smooth_start && !(R->free_start && R->sketch_rows)) break;
            ci = R->ncand - 1;
            continue;
        }
        keep_the_better(R, ci, &tr);
        if ((st = settle_early(R, ci))) return st;
        if (stop_rule(R, &ci, &tr) == GO_STOP) break;
    }
    return EL_OK;
}

/* The G1 family members' pass (family_rule): once, after the guesses, the kept fit's feet
 * saved; the members (el__fit_g1_family_start) as the only starts, R->nfamily of them. */
static int g1_family_starts(fit_run_state *R)
{
    R->family_pass = 0;
    if (!(R->kept_feet = malloc(sizeof(double) * R->n))) return EL_ENOMEM;
    memcpy(R->kept_feet, R->ob.s, sizeof(double) * R->n);
    R->kept_last = R->last_is_best;
    int nf = FIT_G1_STARTS;
    const int gst = el__fit_g1_family_start(&R->ob, &R->con, R->noise_rms,
                                            R->best_meets ? MEMBER_GAIN * R->best.f : HUGE_VAL,
                                            R->cand, &nf, FIT_G1_WAVES);
    if (gst == EL_ENOMEM) return gst;
    R->nfamily = gst ? 0 : (size_t)nf;
    if (R->nfamily > 0) {
        R->ncand = R->nfamily;
        R->free_start = R->smooth_start = 0;
        R->free_ci = R->natural_ci = (size_t)-1;
        R->nconj = 0;
    }
    return EL_OK;
}

/* The caller's start with constraints, taken as it is where it meets them and lies below
 * every fit from it (its objective at its nearest feet): a fit never returns a curve worse
 * than the start it was given. Where as many rows as variables hold, the curves that meet
 * them are isolated and the start is one of them; its fits from its feet and its held state
 * ended on others (6 points, a start point, tangent and curvature and an end point and
 * tangent held: from curves of rms 0.9756 and 1.0393 that meet them, fits of 0.9964 and
 * 1.0908). Only there (R->determined), its status EL_OK: a point of the first-order condition
 * with the rows' multipliers. Elsewhere, where no fit from it met the rows, the start as it
 * is, EL_ENOCONV: 31 points between nearly collinear lines joined G1 at both ends, from
 * their tension-0 batten, every fit missed the start tangent and the call failed EL_EDOM
 * under OpenBLAS's Sandybridge and Prescott kernels and the reference BLAS (met under
 * SkylakeX, Haswell, Zen and Nehalem). EL_OK, or EL_ENOMEM. */
static int caller_start_as_is(fit_run_state *R)
{
    fit_objective *ob = &R->ob;
    if (!R->caller_twice || !ob->rest || R->map.nx == 0) return EL_OK;
    if (!R->determined && (R->best_meets || !R->need_ipopt)) return EL_OK;
    double p0[FIT_NP], x0[FIT_MAXX], c[FIT_NCON];
    int which[FIT_NCON];
    memcpy(p0, R->cand[0], sizeof p0);
    for (int j = 0; j < FIT_NP; j++)
        if (R->o.fixed[j]) p0[j] = R->map.fixed[j];
    el__fit_map_inverse(&R->map, p0, x0);
    double *kept = malloc(sizeof(double) * R->n);     /* the kept fit's feet, put back */
    if (!kept) return EL_ENOMEM;
    memcpy(kept, ob->s, sizeof(double) * R->n);
    fit_value fv;
    const int as_is = !el__fit_feet_start(ob, x0) && !el__fit_objective_eval(ob, x0, 0, &fv) &&
                      (fv.f < R->best.f || !R->determined) &&
                      el__fit_meets(ob, &R->map, &R->con, x0, R->lo, R->hi, R->tmp);
    if (as_is) {
        const int rows = el__fit_constraint_rows(ob, &R->con_rows, x0, c, NULL, which, R->tmp);
        memset(&R->best, 0, sizeof R->best);
        memcpy(R->best.x, x0, sizeof R->best.x);
        R->best.f = fv.f;
        /* EL_OK only where the rows are as many as the variables (rows < 0: not evaluable) */
        R->best.status = R->determined && rows == R->map.nx ? EL_OK : EL_ENOCONV;
        memcpy(R->best_init, p0, sizeof p0);
        R->best_meets = R->last_is_best = 1;
        R->best_strays = R->best_loops = -1;
    } else {
        memcpy(ob->s, kept, sizeof(double) * R->n);
    }
    ob->have_base = 0;
    ob->rest_ok = 0;
    free(kept);
    return EL_OK;
}

int el__fit_choose(fit_run_state *R)
{
    int st;
    for (;;) {
        if ((st = candidate_pass(R))) return st;
        if (!R->family_pass) break;
        if ((st = g1_family_starts(R))) return st;
        if (R->nfamily == 0) break;
    }
    if (R->kept_feet && !R->family_won) {     /* the kept fit as the guesses left it */
        memcpy(R->ob.s, R->kept_feet, sizeof(double) * R->n);
        R->ob.have_base = 0;
        R->ob.rest_ok = 0;
        R->last_is_best = R->kept_last;
    }
    if ((st = caller_start_as_is(R))) return st;
    if (!isfinite(R->best.f)) {      /* no guess could be evaluated: the first one, unfitted */
        R->best.status = EL_ENOCONV;
        el__fit_map_inverse(&R->map, R->best_init, R->best.x);
    }
    return EL_OK;
}
