/*
 * A fit's starts (el__fit_run's first middle stage, fit.c; fitted and chosen among in
 * fit_choose.c): the initial guesses (guess.c, seed 000 §4.3) or the caller's start, the
 * noise figures of the stopping rule, which further starts the run may take, and those
 * taken first (the unconstrained fit's curve for held ends, the natural batten's member,
 * the smooth fit's curve for a discrete fit, the conjugate starts at a held inflection).
 */
#include "fit_internal.h"
#include <string.h>
/* ------------------------------------------------------------ the starts */

/* The initial guesses (el_guess_discrete / el_guess_smooth, up to max_candidates) or the
 * caller's start, normalised, into cand.
 * The caller's start with constraints: fitted from its own feet first (caller_start), then
 * as before, from its held start state (a start-state chart singular on a near-straight
 * curve: 7 points with 0.2 % noise, G1 at both ends, the first failed the end tangent); the
 * lower that meets them is kept. From the held start alone, 6 points (5 within the first
 * fifth of a 130 mm curve, with 0.02 mm noise, and its far end) joined with the true curve's
 * own end points and tangents ended at rms 3.0 where the true curve, the start, has 0.024
 * (QA). (And el__fit_follow_points' refit from the paired curve: from the held start alone,
 * a start point and tangent on 40 uneven points went back to a loop of length 38.8 for
 * points spanning 10.1, rms 0.067; from its feet 0.090 along them, QA.) */
static int initial_guesses(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int model = R->model;
    const double cx = R->cx, cy = R->cy, sc = R->sc;
    int st;
    R->caller_twice = o->use_initial && o->constraints && R->kind == FIT_ORTHOGONAL;
    if (o->use_initial) {
        for (int j = 0; j < FIT_NP; j++)
            R->cand[0][j] = el__fit_norm_param(model, j, R->init[j], cx, cy, sc);
        R->ncand = 1;
        if (R->caller_twice) {
            memcpy(R->cand[1], R->cand[0], sizeof R->cand[0]);
            R->ncand = 2;
        }
    } else if (model == FIT_DISCRETE) {
        el_discrete_params g[FIT_MAXCAND];
        if ((st = el_guess_discrete(R->xy, R->n, g, FIT_MAXCAND, &R->ncand))) return st;
        for (size_t c = 0; c < R->ncand; c++) {
            const double p[FIT_NP] = {g[c].x0, g[c].y0, g[c].h, g[c].phi, g[c].z, g[c].q, g[c].k};
            for (int j = 0; j < FIT_NP; j++)
                R->cand[c][j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
        }
    } else {
        el_smooth_params g[FIT_MAXCAND];
        if ((st = el_guess_smooth(R->xy, R->n, o->param_mode, g, FIT_MAXCAND, &R->ncand)))
            return st;
        for (size_t c = 0; c < R->ncand; c++) {
            const double p[FIT_NP] = {g[c].x0, g[c].y0, g[c].phi, g[c].mu, g[c].k, g[c].q,
                                      g[c].length};
            for (int j = 0; j < FIT_NP; j++)
                R->cand[c][j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
        }
    }
    if ((size_t)o->max_candidates < R->ncand) R->ncand = (size_t)o->max_candidates;
    return EL_OK;
}

/* The noise figures of the stopping rule: rms per point of both coordinates; a distance to
 * the curve sees the normal part, 1/sqrt(2) (120 sparse uneven noisy sets: 14 -> 12 worse
 * than the best basin by > 1 %). Constrained fits keep the plain figure: the rule cannot
 * know their constraints' cost in rms (278 constrained fit_set.py fits: no rms changed by
 * > 1e-8, 15 % more candidates, one 4 -> 323 ms); the unconstrained start
 * (el__fit_unconstrained_start) is tried while above the data's figure.
 * Smooth: a guess whose fit from the paired start ends this far above the noise
 * (ob.f_direct) is fitted from its own feet too (fit_candidate.c; measured: from 3 to 10 x
 * the noise figure, the clustered exact points there reach 4e-14, a sparse uneven loop of
 * 15 points (test_fit_basin.c) keeps its basin). A free fit of fewer than
 * FIT_SKETCH_POINTS unevenly spaced points always: the noise figure of a few points spread
 * along a curve holds its bending (6 points exactly on an elastica, 5 close together and
 * one far: 3.1e-3, the fit from the paired start 2.3e-3, from the guess's feet 2e-13;
 * bench_fit_sparse.py's 1100 fits of 6-59 points: no count changed, the free fits' median
 * time the same). Evenly spaced points' chord fractions are their places: a keyline's
 * resampled sides (~20-50 vertices) took 1.9 ms instead of 1.1 for the same fits. */
static void noise_rule(fit_run_state *R)
{
    R->noise_rms = el__fit_noise_rms(R->xy, R->n, R->sc);
    R->data_noise = R->noise_rms * (R->kind == FIT_ORTHOGONAL ? 0.70710678118654752 : 1.0);
    R->noise = R->o.constraints ? el__fit_noise_plain(R->xy, R->n, R->sc) : R->data_noise;
    if (R->kind == FIT_ORTHOGONAL)
        R->ob.f_direct = R->n < FIT_SKETCH_POINTS && !R->o.constraints &&
                                 !el__fit_evenly_spaced(R->xy, R->n)
                             ? 0.0 : 0.5 * (5.0 * R->noise) * (5.0 * R->noise);   /* rms^2 / 2 */
}

/* Which further starts the run may take, and which fits Ipopt polishes. */
static void start_rules(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int need_ipopt = R->need_ipopt, lm_only = R->lm_only, flags = R->flags;
    /* The further starts (fit_restart.c) where the fit needs no Ipopt rows: with them each
     * run is Ipopt's, ~1.5 ms an iteration (a sparse discrete fit with a start tangent took
     * 1.8 s with them). With rows, a smooth sketch's too (fewer than FIT_SKETCH_POINTS
     * points; the caller's fit, not one run inside another), whatever its noise figure, when
     * its free fit is below FREE_GAIN (fit_choose.c) of the best constrained one's
     * objective: a G1-G1 fit of 6 points exactly on an elastica, whose constraints are its
     * own, ended on a figure-eight
     * 11 times as long, rms 0.096 where the free fit has 2e-11; one of 7 points on a
     * near-straight curve, turning by 721 degrees at 6.9 x its true curve's rms
     * (bench_fit_sparse: no count higher, G1-G1 and G2-G1 fits above their true curve's fit
     * 1 -> 0 and 2 -> 1; median time of a G1-G1 sketch 4.1 -> 4.9 ms, 7.1 without FREE_GAIN.
     * Not discrete: its fits there were not worse, and its rows' runs cost three times as
     * much) */
    R->sketch_rows = need_ipopt && R->n < FIT_SKETCH_POINTS && R->model == FIT_SMOOTH &&
                     !(flags & FIT_RUN_INNER);
    R->free_start = o->constraints && (!need_ipopt || R->sketch_rows) && !o->use_initial &&
                    !lm_only;
    /* a discrete fit with rows, a held start state or both ends held: the smooth fit's curve
     * (el__fit_smooth_start) as a start, fitted from where it is (no held start's
     * continuation), where nothing holds the smooth fit's parameters to other meanings (fixed
     * values, bounds, the signed k range; with rows, not for L-BFGS); the first but with held
     * ends (el__fit_starts) */
    R->smooth_start = R->model == FIT_DISCRETE && (need_ipopt || R->ends_chart || R->staged) &&
                      !o->use_initial && !lm_only && (!o->limited_memory || !need_ipopt) &&
                      !(o->constraints & EL_CONSTRAIN_K) && !(flags & FIT_RUN_ENDS_HELD);
    /* the caller's (o holds a start point in x0, y0) */
    R->smooth_start = R->smooth_start && fit_options_unbounded(R->opt);
    R->free_ci = (size_t)-1;
    /* without rows or bounds, Ipopt polishes only in el__fit_fallback's run (FIT_RUN_POLISH):
     * the fit kept, when Levenberg-Marquardt leaves it uncertified, not every guess and
     * refit so left. Each polish cost ~1.3 ms an iteration, up to max_iter, and crept along
     * the valley where Levenberg-Marquardt had: measured on 2 x 150 sparse uneven noisy
     * sketches (bench_fit_sparse.py's generator, seeds 6 and 7), both models, free: 37
     * polishes in 15 fits, none certified, 8.9 s of the 9.8 s CPU of the 600 fits; without
     * them every rms the same to 1 %, every fit certified, 0.8 s. The 504-curve suite:
     * success the same, every rms the same to 1e-3. With bounds each guess is polished as
     * before: Levenberg-Marquardt creeps towards an active bound, where Ipopt stops (a k
     * range excluding the points' k: a guess crept 200 iterations towards its end, and
     * Ipopt from its point reached it) */
    int bounded = 0;
    for (int j = 0; j < R->map.nx; j++) bounded |= isfinite(R->xl[j]) || isfinite(R->xu[j]);
    /* deferred: this fit's guesses and refits are not polished; its kept fit may be */
    R->deferred = !lm_only && !need_ipopt && !bounded && !(flags & FIT_RUN_POLISH);
    R->no_polish = lm_only || R->deferred;   /* with rows Ipopt runs whatever it is */
    /* el__fit_fallback's run: Ipopt straight from the kept fit (the caller's start), its
     * feet from its curve, as the polish of a guess was; its refits are not polished */
    R->polish_run = (flags & FIT_RUN_POLISH) && !lm_only && !need_ipopt && o->use_initial;
    R->refit_no_polish = R->no_polish || R->polish_run;
    /* the caller's own start (el_fit_options.use_initial): fitted from its own feet, the
     * nearest points of its curve, without the paired start, which pairs the points with
     * their chord fractions and can lead away from it (measured: 6 points exactly on an
     * elastica, 5 close together and one far: from the true curve rms 2.3e-3, an extra wave
     * in the gap; from its feet 3e-16). The library's own reruns from a fit, and constrained
     * fits (their held start moves the curve first), keep that start */
    R->caller_start = o->use_initial && !(flags & FIT_RUN_INNER) && R->kind == FIT_ORTHOGONAL &&
                      !o->constraints;
}

/* Room for m starts before the others (shift_starts), or the room given back. */
static void shift_starts(fit_run_state *R, size_t m)
{
    memmove(R->cand[m], R->cand[0], R->ncand * sizeof R->cand[0]);
}

static void unshift_starts(fit_run_state *R, size_t m)
{
    memmove(R->cand[0], R->cand[m], R->ncand * sizeof R->cand[0]);
}

/* After shift_starts(R, 1) and a start computed into cand[0] (status st): kept first, its
 * index into *ci, or (failed) the starts shifted back; EL_ENOMEM passed on. */
static int keep_first_start(fit_run_state *R, int st, size_t *ci)
{
    if (st == EL_ENOMEM) return st;
    if (st == EL_OK) { *ci = 0; R->ncand++; }
    else unshift_starts(R, 1);
    return EL_OK;
}

/* Held ends: the unconstrained fit's curve turned and scaled onto them is the first start.
 * The guesses turned and scaled onto the ends can lie far from the points (a set of 23
 * points near k = 1: all six at 0.24-1.7, two crawling to max_iter, 0.97 s; this start
 * 0.0106 in 3 iterations), and the guesses' basin need not hold the best fit (smooth, 43
 * points: rms 1.43 x the drawn curve's at the noise rule, 0.99 x so). */
static int free_start_for_ends(fit_run_state *R)
{
    if (!(R->ends_chart && R->free_start)) return EL_OK;
    shift_starts(R, 1);
    const int fst = el__fit_unconstrained_start(R->model, R->xy, R->n, R->opt, R->cx, R->cy, R->sc,
                                                HUGE_VAL, R->cand[0]);
    R->free_start = 0;
    return keep_first_start(R, fst, &R->free_ci);
}

/* The natural batten (this run of the ends chart with the end curvature 0 too, a row): its
 * fit is the family's member that fit_natural.c finds, taken as it is (certified along the
 * family; its iterations the members evaluated), the guesses and Ipopt only where there is
 * none. Measured on 100 of bench_fit_sparse.py's sketches (seed 5) pinned at their curve's
 * ends with both curvatures 0, against the former path (this chart's and the start-state
 * chart's fits by Ipopt from the guesses, the lower kept): fits that stray from their points
 * 38 -> 6 (their loops and snakes had the lower rms of 27), median CPU 188 -> 32 ms, the
 * slowest 1.85 -> 0.06 s, none uncertified.
 * Discrete: the smooth natural batten's curve (el__fit_smooth_start) meets the zero
 * curvatures at both ends exactly (q = K, q + (n - 1) z = K + 2 m K) and the ends chart
 * turns and scales it onto the pins: Ipopt from there, the guesses only where it fails.
 * Measured on the same 100 sketches against the former path (both charts' fits from the
 * guesses, the lower kept): fits that stray 52 -> 8 (the lower rms of 36 former fits came
 * from loops wound across the points), median CPU 352 -> 32 ms, the slowest 2.56 -> 0.15 s,
 * none uncertified. */
static int natural_start(fit_run_state *R)
{
    R->natural_ci = (size_t)-1;
    R->natural_ok = R->natural_evals = 0;
    if (!(R->natural && R->ends_chart && (R->model == FIT_DISCRETE || R->ob.rest))) return EL_OK;
    shift_starts(R, 1);
    const int nst = R->model == FIT_SMOOTH
                  ? el__fit_natural_fit(&R->ob, R->noise_rms, R->cand[0], &R->natural_ok,
                                        &R->natural_evals)
                  : el__fit_smooth_start(R->xy, R->n, R->opt, FIT_RUN_NO_CONJUGATE, R->cx, R->cy,
                                         R->sc, R->cand[0]);
    return keep_first_start(R, nst, &R->natural_ci);
}

/* A discrete fit's smooth start first. The guesses' fits with a held start tangent or rows
 * end far from the points (a scribble of 888 self-crossings, 25 x the data's length, at the
 * lowest objective: its points' distances are searched near their own vertices), or at a
 * length of 10 for points spanning 5, even from the free fit; from the smooth fit's curve,
 * 0.0205 at once, as the smooth model's (300 uneven points of an elliptic arc, true start
 * point and tangent, QA). With rows each guess crept to 2400-4500 Ipopt iterations (2000
 * points: 26 s). */
static int smooth_start_first(fit_run_state *R)
{
    R->smooth_ci = (size_t)-1;
    if (!(R->smooth_start && !R->ends_chart)) return EL_OK;
    shift_starts(R, 1);
    const int sst = el__fit_smooth_start(R->xy, R->n, R->opt, FIT_RUN_NO_CONJUGATE, R->cx, R->cy,
                                         R->sc, R->cand[0]);
    R->smooth_start = 0;
    return keep_first_start(R, sst, &R->smooth_ci);
}

/* Held at an inflection (start tangent and zero curvature) with a tangent row at the other
 * end: the held state's curves whose tangents lie on the guesses' side of the inflection's
 * cannot reach a row beyond it, and Ipopt stopped off the row from every guess (sine scans
 * held at both true tangents and a zero end curvature, the points reversed: EL_EDOM on 2 of
 * 3, the nearly straight curve at 46 x the free fit's rms on the third, QA). First the held
 * fit's conjugate, turning the other way round (el__fit_conjugate_start), fitted from where
 * it is, its feet found again (el__fit_refeet): rms 0.100, 0.181, 0.182, where 150 random
 * starts reach 0.100, 0.171, 0.117. */
static int conjugate_starts(fit_run_state *R)
{
    const int inflection = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE;
    R->nconj = 0;    /* the conjugate starts: the first nconj candidates */
    if (!((R->held & inflection) == inflection && R->con.start_kappa == 0.0 &&
          (R->con_rows.mask & EL_CONSTRAIN_END_TANGENT) && !R->o.use_initial && !R->lm_only &&
          !(R->flags & (FIT_RUN_INNER | FIT_RUN_NO_CONJUGATE))))
        return EL_OK;
    const size_t m = R->model == FIT_SMOOTH ? 2 : 1;
    shift_starts(R, m);
    /* discrete: the smooth fit that has them, as its smooth start (without them: the
     * smooth start's continuum limit of the conjugate was 1.75 on #10, this 0.207) */
    int cst;
    if (R->model == FIT_SMOOTH) {
        double conj[2][FIT_NP];
        cst = el__fit_conjugate_start(R->xy, R->n, R->opt, R->cx, R->cy, R->sc, conj);
        if (cst == EL_OK) memcpy(R->cand, conj, sizeof conj);
    } else {
        cst = el__fit_smooth_start(R->xy, R->n, R->opt, 0, R->cx, R->cy, R->sc, R->cand[0]);
    }
    if (cst == EL_ENOMEM) return cst;
    if (cst == EL_OK) { R->nconj = m; R->ncand += m; }
    else unshift_starts(R, m);
    return EL_OK;
}

/* Joined G1 at both ends (smooth, by distance, nothing else held or bounded): after the
 * guesses, the members of the Hermite families of those ends nearest the points
 * (fit_g1_family.c, up to FIT_G1_STARTS: of other families, and one that follows them)
 * whose objective is below MEMBER_GAIN x the kept fit's (any, where that does not meet the
 * constraints), each fitted by Ipopt straight from its own feet (the guesses' path,
 * Levenberg-Marquardt first, where that run does not meet them): a second pass of the
 * candidates. Measured on 300 sketches of 5-22 points clustered along 10-40 % of a curve
 * (0-0.5 % noise, 0-2 points elsewhere, its ends and tangents): fits above 1.01 x their
 * true curve's rms 19 -> 1 (at up to 28 x before), none worse by 1 %, one EL_EDOM fitted;
 * median CPU 10.7 -> 14.7 ms; bench_fit_sparse.py's G1-G1 sets 1 -> 0 above their true
 * curve, median 4.4 -> 9.5 ms (the scan's 19 tension solves, their members' distances, up
 * to 3 Ipopt runs). Fitted among the guesses instead, the members cost 2-4 x the median and
 * their fits ended in other basins where a guess's reached the true curve's. */
static void family_rule(fit_run_state *R)
{
    const el_fit_options *o = &R->o;
    const int both = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
    int g1_only = R->model == FIT_SMOOTH && R->kind == FIT_ORTHOGONAL && R->ob.rest &&
                  !o->use_initial && !R->lm_only && !(R->flags & FIT_RUN_INNER) &&
                  o->constraints == (both | EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_TANGENT);
    for (int j = 0; j < FIT_NP && g1_only; j++)
        if ((o->fixed[j] && j > 1) || isfinite(R->lo[j]) || isfinite(R->hi[j])) g1_only = 0;
    R->nfamily = 0;     /* the family members' pass: its candidates are those */
    R->family_pass = g1_only;
    R->family_won = R->kept_last = 0;
}

int el__fit_starts(fit_run_state *R)
{
    int st;
    if ((st = initial_guesses(R))) return st;
    noise_rule(R);
    memset(&R->best, 0, sizeof R->best);
    R->best.f = HUGE_VAL;
    R->best.status = EL_ENOCONV;
    R->best_strays = -1;    /* best strays from its points (el__fit_strays_at), once known */
    R->best_loops = -1;     /* best crosses itself (el__fit_loops), once known */
    R->wander_kept = 0;     /* keep_the_better (or a sketch's) kept a fit that does not wander */
    R->best_meets = 0;      /* with rows: best meets the constraints */
    memcpy(R->best_init, R->cand[0], sizeof R->best_init);
    R->iters = R->tried = R->last_is_best = R->ipopt_spent = 0;   /* Ipopt runs to max_iter */
    start_rules(R);
    if ((st = free_start_for_ends(R)) || (st = natural_start(R)) || (st = smooth_start_first(R)) ||
        (st = conjugate_starts(R)))
        return st;
    family_rule(R);
    return EL_OK;
}
