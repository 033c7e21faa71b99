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
 * curvature are the start-state chart's variables held (el__fit_run); a fit whose end has
 * more of these than its start runs on the points reversed (fit_restart.c). The
 * others go to Ipopt's constraint interface. Every result is checked against its
 * constraints. Further starts (fit_restart.c): a constrained fit's from the unconstrained
 * fit, and one that strays from its points from the paired fit.
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>
#include <float.h>

/* SKETCH_POINTS: fewer points are a sketch's (bench_fit_sparse.py draws 6-59), whose noise
 * figure holds their curve's bending too (ob.f_direct) */
enum { MAXCAND = 6, FEET_ROUNDS = 4, SAMPLED_ROUNDS = 5, SKETCH_POINTS = 60, G1_STARTS = 3 };
/* a G1 family member is fitted where its own objective is below this multiple of the kept
 * fit's: its fit comes lower (16 sketched points between nearly collinear lines: a member
 * at 1.12 x a guess's looping fit reached 0.86 x it, following the points, QA) */
static const double MEMBER_GAIN = 4.0;
/* a sketch's free fit with rows is a start where its objective is below this share of the
 * constrained fits' best (its rms below half theirs: constraints that cost that much are
 * not the data's own, or the guesses missed their basin) */
static const double FREE_GAIN = 0.25;
/* the sampled refits' stop (el__fit_run): a Gauss-Newton step would lower f by less than this */
static const double LOOSE_TOL = 1e-5;

/* ------------------------------------------------------------ one fit */

/* Whether the points are spaced evenly along the data: the mean segment of every run
 * of w = max(3, (n-1)/16) consecutive segments within 1.3 x of each other's (a run's
 * mean evens out the noise of scanned samples taken at equal steps, not a change of
 * density or a gap). The discrete model's paired distance (seed 000 (4.6)) is meant
 * for such data (an equilateral polygon, el_resample_equilateral's, or equal steps); on
 * other points (sketched, scanned unevenly, with gaps) a vertex is not where its point
 * is, and the paired fit is far from the points (measured: 42 points of two densities,
 * noise 0.2: paired rms 12.4, orthogonal 0.15; a 175-point scan of spacing 1:6 with
 * two gaps, noise 0.15: 4.2 and 0.15). */
/* Even spacing in this sense is necessary for the pairing, not sufficient: a slow change of
 * spacing, or points at random places (every run as dense as the next), pass it, and the
 * paired fit is then judged by its points' slip along the polygon (el__fit_unpaired). */
static int evenly_spaced(const double *xy, size_t n)
{
    const size_t m = n - 1, w = m / 16 > 3 ? m / 16 : 3;
    if (m < w) return 1;
    double run = 0.0, lo = HUGE_VAL, hi = 0.0;
    for (size_t i = 0; i < m; i++) {
        run += hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]);
        if (i >= w) run -= hypot(xy[2 * (i - w) + 2] - xy[2 * (i - w)], xy[2 * (i - w) + 3] - xy[2 * (i - w) + 1]);
        if (i + 1 >= w) { lo = fmin(lo, run); hi = fmax(hi, run); }
    }
    return hi <= 1.3 * lo;
}

/* The first feet of a fit by distance with feet (orthogonal smooth): the fractions' places
 * t_i on a curve of the given length. */
static void first_feet(fit_objective *ob, const double *t, double length)
{
    if (fit_has_feet(ob))
        for (size_t i = 0; i < ob->n; i++) ob->s[i] = t[i] * length;
}

int el__fit_run(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                const double *init, fit_out *res, double *dist, double *foot)
{
    const int lm_only = flags & FIT_RUN_LM_ONLY;
    el_fit_options o;
    if (opt) o = *opt; else el_fit_options_defaults(&o);
    int which = 0;
    if (!xy || n < 4 || el__all_finite(xy, 2 * n)) return EL_EINVAL;
    int st = el__fit_check_options(&o, model, &which);
    if (st) { res->constraint = which; return st; }
    if (o.use_initial && (!init || el__all_finite(init, FIT_NP))) return EL_EINVAL;
    el__gsl_quiet();
    double cx, cy, sc;
    if ((st = el__fit_normalisation(xy, n, &cx, &cy, &sc))) return st;
    const double norm[3] = {cx, cy, sc};

    /* start point: x0, y0 held */
    if (o.constraints & EL_CONSTRAIN_START_POINT) {
        o.fixed[0] = o.fixed[1] = 1;
        o.value[0] = o.start_point[0]; o.value[1] = o.start_point[1];
    }
    /* normalised bounds: the model's and the caller's, then the constraints' */
    double lo[FIT_NP], hi[FIT_NP];
    for (int j = 0; j < FIT_NP; j++) {
        double a = el__fit_norm_param(model, j, o.lower[j], cx, cy, sc);
        double b = el__fit_norm_param(model, j, o.upper[j], cx, cy, sc);
        lo[j] = isnan(a) ? -HUGE_VAL : fmin(a, b);
        hi[j] = isnan(b) ? HUGE_VAL : fmax(a, b);
    }
    fit_constraints con;
    el__fit_setup_constraints(&o, model, n, cx, cy, sc, &con, lo, hi);
    for (int j = 0; j < FIT_NP; j++) {
        if (lo[j] > hi[j]) {
            res->constraint = (j == fit_length_slot(model) && (o.constraints & EL_CONSTRAIN_LENGTH)) ? EL_CONSTRAIN_LENGTH
                            : (j == fit_k_slot(model) && (o.constraints & EL_CONSTRAIN_K)) ? EL_CONSTRAIN_K : 0;
            return EL_EINVAL;
        }
        if (o.fixed[j]) {
            const double v = el__fit_norm_param(model, j, o.value[j], cx, cy, sc);
            if (!isfinite(v) || v < lo[j] || v > hi[j]) {
                res->constraint = j == fit_length_slot(model) ? o.constraints & EL_CONSTRAIN_LENGTH
                                : j == fit_k_slot(model) ? o.constraints & EL_CONSTRAIN_K : 0;
                return EL_EINVAL;
            }
        }
    }
    /* the end point out of reach of the longest allowed curve */
    if ((o.constraints & EL_CONSTRAIN_END_POINT) && (o.constraints & (EL_CONSTRAIN_LENGTH | EL_CONSTRAIN_START_POINT)) ==
        (EL_CONSTRAIN_LENGTH | EL_CONSTRAIN_START_POINT)) {
        const double chord = hypot(con.end_xy[0] - con.start_xy[0], con.end_xy[1] - con.start_xy[1]);
        const double maxlen = hi[fit_length_slot(model)] * (model == FIT_DISCRETE ? (double)(n - 1) : 1.0);
        if (chord > maxlen * (1.0 + 1e-12)) { res->constraint = EL_CONSTRAIN_LENGTH; return EL_EDOM; }
    }
    /* discrete k < 0 is used internally by shifting q (el__fit_canonical): not when q is
     * fixed; smooth w < 0 flips k and q: not when either is fixed or bounded */
    const int ik = fit_k_slot(model);
    if (model == FIT_DISCRETE && o.fixed[5] && !o.fixed[ik]) lo[ik] = fmax(lo[ik], 0.0);
    if (model == FIT_SMOOTH && (o.fixed[ik] || o.fixed[5] || isfinite(lo[ik]) || isfinite(hi[ik]) ||
                                isfinite(lo[5]) || isfinite(hi[5])))
        lo[3] = fmax(lo[3], 0.0);

    const int kind = o.distance == EL_DISTANCE_PAIRED ? FIT_PAIRED : o.distance == EL_DISTANCE_ORTHOGONAL ? FIT_ORTHOGONAL
                   : model == FIT_SMOOTH || !evenly_spaced(xy, n) ? FIT_ORTHOGONAL : FIT_PAIRED;

    /* the map: free parameters, their scales, the start-state chart. The chart replaces
     * (phi, w or z, k, q) when all four are free and unbounded; it then holds a start
     * tangent (theta0; discrete: vertex 0's theta_0, fit_model.c) and a start curvature
     * (smooth: kappa0; discrete: 0, where
     * its (3.4) curvature and the chart's 2 k W cn q vanish together, at cn q = 0) as
     * variables fixed at their values: met exactly, no constraint row. As rows (Ipopt,
     * in (phi, w, k, q)) kappa0 = 0 was reached only along k -> 1, q -> oo, where its
     * gradient vanishes: a false EL_EDOM or a far worse local fit (measured: a
     * noise-free S, start curvature 0: rms 7.9 stalled at the separatrix; held: 1.61). */
    const int sl[4] = {model == FIT_DISCRETE ? 3 : 2, model == FIT_DISCRETE ? 4 : 3, ik, 5};
    int chart_ok = 1, held = 0;
    for (int a = 0; a < 4; a++)
        if (o.fixed[sl[a]] || isfinite(lo[sl[a]]) || isfinite(hi[sl[a]])) chart_ok = 0;
    if (chart_ok && model == FIT_SMOOTH) held = o.constraints & (EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE);
    if (chart_ok && model == FIT_DISCRETE)
        held = (o.constraints & EL_CONSTRAIN_START_TANGENT) |
               ((o.constraints & EL_CONSTRAIN_START_CURVATURE) && con.start_kappa == 0.0 ? EL_CONSTRAIN_START_CURVATURE : 0);
    /* both end points and nothing else: the ends chart (fit_model.c) holds both, and the fit
     * needs no Ipopt (FIT_RUN_ROWS: as rows, the fallback below). Measured on 4 x 150 sparse
     * uneven noisy sketches of 6-59 points (bench_fit_sparse.py's generator, seeds 6 and 7),
     * pinned at their curve's ends and at their first and last points, each model, against
     * the rows: uncertified fits 23 -> 0, rms better by > 1 % 30, worse 2 (by 1-2.5 %),
     * CPU 53 s -> 3.4 s over the 1200 fits, 105 -> 2 above 0.1 s, the slowest 1.6 -> 0.34 s */
    const double chord[2] = {con.end_xy[0] - con.start_xy[0], con.end_xy[1] - con.start_xy[1]};
    const int jl = fit_length_slot(model);
    /* with a zero start curvature too (FIT_RUN_ENDS_HELD, el__fit_ends_held): the chart's
     * a = kappa0 L held at 0, scale-free; an end curvature stays a row */
    const int both = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
    const int zero_k0 = (o.constraints & EL_CONSTRAIN_START_CURVATURE) && con.start_kappa == 0.0 ? EL_CONSTRAIN_START_CURVATURE : 0;
    const int ends_ok = chart_ok && !(flags & FIT_RUN_ROWS) && (o.constraints & both) == both &&
                        !(o.constraints & ~(both | zero_k0 | EL_CONSTRAIN_END_CURVATURE)) &&
                        fit_norm(chord[0], chord[1]) > 1e-9 && !isfinite(lo[jl]) && !isfinite(hi[jl]) && !o.fixed[jl];
    const int ends_chart = ends_ok && (o.constraints == both || (zero_k0 && (flags & FIT_RUN_ENDS_HELD)));
    if (ends_chart) held = EL_CONSTRAIN_END_POINT | zero_k0;
    /* the natural batten (both end curvatures 0 too): smooth by distance, every fit that meets
     * the constraints is a member of a family of one parameter per number of half-waves,
     * searched whole (fit_natural.c) in the ends chart's run (FIT_RUN_ENDS_HELD, below);
     * discrete, that run from this smooth fit; the start-state chart's run and
     * el__fit_ends_held only where that gives no fit */
    const int natural = ends_ok && zero_k0 && (o.constraints & EL_CONSTRAIN_END_CURVATURE) && con.end_kappa == 0.0 &&
                        (model == FIT_DISCRETE || kind == FIT_ORTHOGONAL) && !o.use_initial && !lm_only;
    if (natural && !ends_chart && !(flags & FIT_RUN_INNER)) {
        st = el__fit_run(model, xy, n, opt, flags | FIT_RUN_ENDS_HELD, init, res, dist, foot);
        if (st == EL_ENOMEM || st == EL_OK || res->status == EL_ENOCONV || res->status == EL_EMAXITER) return st;
    }
    const int need_ipopt = (o.constraints & ~(EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_LENGTH | EL_CONSTRAIN_K | held)) != 0;
    /* the discrete non-zero start curvature stays an Ipopt row, started by continuation in
     * the chart (el__fit_held_start; measured on a sketched S, then with the first segment's
     * direction as the start tangent, a row too: rms 0.70 in 1400 iterations from the free
     * fit, 0.35 by continuation) */
    const int staged = chart_ok ? (held | o.constraints) & (EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE) : 0;
    fit_constraints con_rows = con;      /* the constraints left to Ipopt's rows */
    con_rows.mask &= ~held;
    fit_map map;
    memset(&map, 0, sizeof map);
    map.model = model; map.ncurves = 1;
    map.chart = ends_chart ? FIT_CHART_ENDS : chart_ok && (!need_ipopt || staged) ? FIT_CHART_START : FIT_CHART_NONE;
    map.chord[0] = chord[0]; map.chord[1] = chord[1];
    for (int j = 0; j < FIT_NP; j++) {
        map.scale[j] = (model == FIT_DISCRETE && (j == 2 || j == 4)) ? (double)(n - 1) : 1.0;
        if (o.fixed[j]) map.fixed[j] = el__fit_norm_param(model, j, o.value[j], cx, cy, sc);
        else if (j == sl[0] && (held & EL_CONSTRAIN_START_TANGENT)) map.fixed[j] = con.start_theta;
        else if (j == sl[1] && (held & EL_CONSTRAIN_START_CURVATURE)) map.fixed[j] = con.start_kappa;
        else if (!ends_chart || j == sl[1] || j == sl[2] || j == sl[3]) map.idx[map.nx++] = j;
    }
    fit_map free_map = map;              /* the same with the held chart variables free */
    free_map.nx = 0;
    for (int j = 0; j < FIT_NP; j++)
        if (ends_chart ? j == sl[1] || j == sl[2] || j == sl[3] : !o.fixed[j]) free_map.idx[free_map.nx++] = j;
    double xl[FIT_MAXX], xu[FIT_MAXX];
    for (int j = 0; j < map.nx; j++) {
        const int col = map.idx[j];
        xl[j] = isfinite(lo[col]) ? lo[col] * map.scale[col] : -HUGE_VAL;
        xu[j] = isfinite(hi[col]) ? hi[col] * map.scale[col] : HUGE_VAL;
    }

    /* fractions (smooth: paired positions, first feet) */
    double *t = NULL, *tmp = NULL, *dbuf = NULL, *d = dist, *fs = foot;
    double *kept_feet = NULL;   /* the kept fit's feet before the G1 family members' pass */
    fit_objective ob;
    memset(&ob, 0, sizeof ob);
    int mode = EL_PARAM_UNIFORM;
    st = EL_ENOMEM;
    tmp = malloc(sizeof(double) * FIT_WORK);
    if (!tmp) goto done;
    if (model == FIT_SMOOTH) {
        if (!(t = malloc(sizeof(double) * n))) goto done;
        if ((st = el_fit_fractions(xy, n, o.param_mode, t, &mode))) goto done;
    }
    if ((st = el__fit_objective_init(&ob, kind, &map, xy, n, cx, cy, sc, t))) goto done;
    ob.exact_ends = o.constraints != 0;
    /* the distances and feet reported, the caller's arrays or dbuf; also the smooth
     * orthogonal fit's start feet and the distances its evaluations found at rest */
    if ((!d || !fs) && !(dbuf = malloc(sizeof(double) * 2 * n))) { st = EL_ENOMEM; goto done; }
    if (!d) d = dbuf;
    if (!fs) fs = dbuf + n;
    if (model == FIT_SMOOTH && kind == FIT_ORTHOGONAL) { ob.rest = d; ob.rest_foot = fs; }

    /* candidates (normalised internal parameters); more: free_start, smooth_start, the two
     * conjugate starts, the G1 ends' family members */
    double cand[MAXCAND + 4 + G1_STARTS][FIT_NP];
    size_t ncand = 0;
    /* the caller's start with constraints: fitted from its own feet first (caller_start),
     * then as before, from its held start state (a start-state chart singular on a
     * near-straight curve: 7 points with 0.2 % noise, G1 at both ends, the first failed the
     * end tangent); the lower that meets them is kept. From the held start alone, 6 points (5
     * within the first fifth of a 130 mm curve, with 0.02 mm noise, and its far end) joined
     * with the true curve's own end points and tangents ended at rms 3.0 where the true
     * curve, the start, has 0.024 (QA) */
    /* (and el__fit_follow_points' refit from the paired curve: from the held start alone, a
     * start point and tangent on 40 uneven points went back to a loop of length 38.8 for
     * points spanning 10.1, rms 0.067; from its feet 0.090 along them, QA) */
    const int caller_twice = o.use_initial && o.constraints && kind == FIT_ORTHOGONAL;
    if (o.use_initial) {
        for (int j = 0; j < FIT_NP; j++) cand[0][j] = el__fit_norm_param(model, j, init[j], cx, cy, sc);
        ncand = 1;
        if (caller_twice) {
            memcpy(cand[1], cand[0], sizeof cand[0]);
            ncand = 2;
        }
    } else if (model == FIT_DISCRETE) {
        el_discrete_params g[MAXCAND];
        if ((st = el_guess_discrete(xy, n, g, MAXCAND, &ncand))) goto done;
        for (size_t c = 0; c < ncand; c++) {
            const double p[FIT_NP] = {g[c].x0, g[c].y0, g[c].h, g[c].phi, g[c].z, g[c].q, g[c].k};
            for (int j = 0; j < FIT_NP; j++) cand[c][j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
        }
    } else {
        el_smooth_params g[MAXCAND];
        if ((st = el_guess_smooth(xy, n, o.param_mode, g, MAXCAND, &ncand))) goto done;
        for (size_t c = 0; c < ncand; c++) {
            const double p[FIT_NP] = {g[c].x0, g[c].y0, g[c].phi, g[c].mu, g[c].k, g[c].q, g[c].length};
            for (int j = 0; j < FIT_NP; j++) cand[c][j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
        }
    }
    if ((size_t)o.max_candidates < ncand) ncand = (size_t)o.max_candidates;

    /* rms per point of both coordinates; a distance to the curve sees the normal part, 1/sqrt(2)
     * (120 sparse uneven noisy sets: 14 -> 12 worse than the best basin by > 1 %). Constrained fits
     * keep the plain figure: the rule cannot know their constraints' cost in rms (278 constrained
     * fit_set.py fits: no rms changed by > 1e-8, 15 % more candidates, one 4 -> 323 ms); the
     * unconstrained start (el__fit_unconstrained_start) is tried while above the data's figure */
    const double noise_rms = el__fit_noise_rms(xy, n, sc);
    const double data_noise = noise_rms * (kind == FIT_ORTHOGONAL ? 0.70710678118654752 : 1.0);
    const double noise = o.constraints ? el__fit_noise_plain(xy, n, sc) : data_noise;
    /* smooth: a guess whose fit from the paired start ends this far above the noise is fitted
     * from its own feet too (fit_candidate.c; measured: from 3 to 10 x the noise figure, the
     * clustered exact points there reach 4e-14, a sparse uneven loop of 15 points
     * (test_fit_basin.c) keeps its basin). A free fit of fewer than SKETCH_POINTS unevenly
     * spaced points always: the noise figure of a few points spread along a curve holds its
     * bending (6 points exactly on an elastica, 5 close together and one far: 3.1e-3, the fit
     * from the paired start 2.3e-3, from the guess's feet 2e-13; bench_fit_sparse.py's 1100
     * fits of 6-59 points: no count changed, the free fits' median time the same). Evenly
     * spaced points' chord fractions are their places: a keyline's resampled sides (~20-50
     * vertices) took 1.9 ms instead of 1.1 for the same fits */
    if (kind == FIT_ORTHOGONAL)
        ob.f_direct = n < SKETCH_POINTS && !o.constraints && !evenly_spaced(xy, n)
                          ? 0.0 : 0.5 * (5.0 * noise) * (5.0 * noise);   /* rms^2 / 2 */
    fit_candidate best;
    int best_strays = -1;      /* best strays from its points (el__fit_strays_at), once known */
    int best_loops = -1;       /* best crosses itself (el__fit_loops), once known */
    int wander_kept = 0;       /* the rule below (or a sketch's) kept a fit that does not wander */
    int best_meets = 0;        /* with rows: best meets the constraints */
    memset(&best, 0, sizeof best);
    best.f = HUGE_VAL;
    best.status = EL_ENOCONV;
    double best_init[FIT_NP];
    memcpy(best_init, cand[0], sizeof best_init);
    /* the further starts (fit_restart.c) where the fit needs no Ipopt rows: with them each
     * run is Ipopt's, ~1.5 ms an iteration (a sparse discrete fit with a start tangent
     * took 1.8 s with them) */
    int iters = 0, tried = 0, last_is_best = 0, ipopt_spent = 0;   /* Ipopt runs to max_iter */
    /* with rows, a smooth sketch's too (fewer than SKETCH_POINTS points; the caller's fit, not
     * one run inside another), whatever its noise figure, when its free fit is below
     * FREE_GAIN of the best constrained one's objective: a G1-G1 fit of 6 points exactly on an
     * elastica, whose constraints are its own, ended on a figure-eight 11 times as long, rms
     * 0.096 where the free fit has 2e-11; one of 7 points on a near-straight curve, turning by
     * 721 degrees at 6.9 x its true curve's rms (bench_fit_sparse: no count higher, G1-G1 and
     * G2-G1 fits above their true curve's fit 1 -> 0 and 2 -> 1; median time of a G1-G1
     * sketch 4.1 -> 4.9 ms, 7.1 without FREE_GAIN. Not discrete: its fits there were not worse,
     * and its rows' runs cost three times as much) */
    const int sketch_rows = need_ipopt && n < SKETCH_POINTS && model == FIT_SMOOTH && !(flags & FIT_RUN_INNER);
    int free_start = o.constraints && (!need_ipopt || sketch_rows) && !o.use_initial && !lm_only;
    /* a discrete fit with rows, a held start state or both ends held: the smooth fit's curve
     * (el__fit_smooth_start) as a start, fitted from where it is (no held start's
     * continuation), where nothing holds the smooth fit's parameters to other meanings (fixed
     * values, bounds, the signed k range; with rows, not for L-BFGS); the first but with held
     * ends (below) */
    int smooth_start = model == FIT_DISCRETE && (need_ipopt || ends_chart || staged) && !o.use_initial && !lm_only &&
                       (!o.limited_memory || !need_ipopt) && !(o.constraints & EL_CONSTRAIN_K) && !(flags & FIT_RUN_ENDS_HELD);
    for (int j = 0; j < FIT_NP && smooth_start; j++)     /* the caller's (o holds a start point in x0, y0) */
        if (opt->fixed[j] || isfinite(opt->lower[j]) || isfinite(opt->upper[j])) smooth_start = 0;
    size_t free_ci = (size_t)-1;    /* the unconstrained start's index in cand, once added */
    /* without rows or bounds, Ipopt polishes only in el__fit_fallback's run (FIT_RUN_POLISH):
     * the fit kept, when Levenberg-Marquardt leaves it uncertified (below), not every guess
     * and refit so left. Each polish cost ~1.3 ms an iteration, up to max_iter, and crept
     * along the valley where Levenberg-Marquardt had: measured on 2 x 150 sparse uneven
     * noisy sketches (bench_fit_sparse.py's generator, seeds 6 and 7), both models, free:
     * 37 polishes in 15 fits, none certified, 8.9 s of the 9.8 s CPU of the 600 fits;
     * without them every rms the same to 1 %, every fit certified, 0.8 s. The 504-curve
     * suite: success the same, every rms the same to 1e-3. With bounds each guess is
     * polished as before: Levenberg-Marquardt creeps towards an active bound, where Ipopt
     * stops (a k range excluding the points' k: a guess crept 200 iterations towards its
     * end, and Ipopt from its point reached it) */
    int bounded = 0;
    for (int j = 0; j < map.nx; j++) bounded |= isfinite(xl[j]) || isfinite(xu[j]);
    /* deferred: this fit's guesses and refits are not polished; its kept fit may be */
    const int deferred = !lm_only && !need_ipopt && !bounded && !(flags & FIT_RUN_POLISH);
    const int no_polish = lm_only || deferred;   /* with rows Ipopt runs whatever it is */
    /* el__fit_fallback's run: Ipopt straight from the kept fit (the caller's start), its
     * feet from its curve, as the polish of a guess was; its refits are not polished */
    const int polish_run = (flags & FIT_RUN_POLISH) && !lm_only && !need_ipopt && o.use_initial;
    const int refit_no_polish = no_polish || polish_run;
    /* the caller's own start (el_fit_options.use_initial): fitted from its own feet, the
     * nearest points of its curve, without the paired start, which pairs the points with
     * their chord fractions and can lead away from it (measured: 6 points exactly on an
     * elastica, 5 close together and one far: from the true curve rms 2.3e-3, an extra wave
     * in the gap; from its feet 3e-16). The library's own reruns from a fit, and constrained
     * fits (their held start moves the curve first), keep that start */
    const int caller_start = o.use_initial && !(flags & FIT_RUN_INNER) && kind == FIT_ORTHOGONAL && !o.constraints;
    if (ends_chart && free_start) {
        /* held ends: the unconstrained fit's curve turned and scaled onto them is the first
         * start. The guesses turned and scaled onto the ends can lie far from the points (a
         * set of 23 points near k = 1: all six at 0.24-1.7, two crawling to max_iter, 0.97 s;
         * this start 0.0106 in 3 iterations), and the guesses' basin need not hold the best
         * fit (smooth, 43 points: rms 1.43 x the drawn curve's at the noise rule, 0.99 x so) */
        memmove(cand[1], cand[0], ncand * sizeof cand[0]);
        const int fst = el__fit_unconstrained_start(model, xy, n, opt, cx, cy, sc, HUGE_VAL, cand[0]);
        if (fst == EL_ENOMEM) { st = fst; goto done; }
        if (fst == EL_OK) { free_ci = 0; ncand++; }
        else memmove(cand[0], cand[1], ncand * sizeof cand[0]);
        free_start = 0;
    }
    /* the natural batten (this run of the ends chart with the end curvature 0 too, a row):
     * its fit is the family's member that fit_natural.c finds, taken as it is (certified
     * along the family; its iterations the members evaluated), the guesses and Ipopt only
     * where there is none. Measured on 100 of bench_fit_sparse.py's sketches (seed 5) pinned
     * at their curve's ends with both curvatures 0, against the former path (this chart's
     * and the start-state chart's fits by Ipopt from the guesses, the lower kept): fits that
     * stray from their points 38 -> 6 (their loops and snakes had the lower rms of 27),
     * median CPU 188 -> 32 ms, the slowest 1.85 -> 0.06 s, none uncertified */
    size_t natural_ci = (size_t)-1;
    int natural_ok = 0, natural_evals = 0;
    if (natural && ends_chart && (model == FIT_DISCRETE || ob.rest)) {
        /* discrete: the smooth natural batten's curve (el__fit_smooth_start) meets the
         * zero curvatures at both ends exactly (q = K, q + (n - 1) z = K + 2 m K) and the
         * ends chart turns and scales it onto the pins: Ipopt from there, the guesses only
         * where it fails. Measured on the same 100 sketches against the former path (both
         * charts' fits from the guesses, the lower kept): fits that stray 52 -> 8 (the lower
         * rms of 36 former fits came from loops wound across the points), median CPU 352 ->
         * 32 ms, the slowest 2.56 -> 0.15 s, none uncertified */
        memmove(cand[1], cand[0], ncand * sizeof cand[0]);
        const int nst = model == FIT_SMOOTH
                      ? el__fit_natural_fit(&ob, noise_rms, cand[0], &natural_ok, &natural_evals)
                      : el__fit_smooth_start(xy, n, opt, FIT_RUN_NO_CONJUGATE, cx, cy, sc, cand[0]);
        if (nst == EL_ENOMEM) { st = nst; goto done; }
        if (nst == EL_OK) { natural_ci = 0; ncand++; }
        else memmove(cand[0], cand[1], ncand * sizeof cand[0]);
    }
    /* The guesses' fits with a held start tangent or rows end far from the points (a scribble
     * of 888 self-crossings, 25 x the data's length, at the lowest objective: its points'
     * distances are searched near their own vertices), or at a length of 10 for points
     * spanning 5, even from the free fit; from the smooth fit's curve, 0.0205 at once, as the
     * smooth model's (300 uneven points of an elliptic arc, true start point and tangent, QA).
     * With rows each guess crept to 2400-4500 Ipopt iterations (2000 points: 26 s). */
    size_t smooth_ci = (size_t)-1;
    if (smooth_start && !ends_chart) {
        memmove(cand[1], cand[0], ncand * sizeof cand[0]);
        const int sst = el__fit_smooth_start(xy, n, opt, FIT_RUN_NO_CONJUGATE, cx, cy, sc, cand[0]);
        if (sst == EL_ENOMEM) { st = sst; goto done; }
        if (sst == EL_OK) { smooth_ci = 0; ncand++; }
        else memmove(cand[0], cand[1], ncand * sizeof cand[0]);
        smooth_start = 0;
    }
    /* held at an inflection (start tangent and zero curvature) with a tangent row at the other
     * end: the held state's curves whose tangents lie on the guesses' side of the inflection's
     * cannot reach a row beyond it, and Ipopt stopped off the row from every guess (sine scans
     * held at both true tangents and a zero end curvature, the points reversed: EL_EDOM on 2 of
     * 3, the nearly straight curve at 46 x the free fit's rms on the third, QA). First the held
     * fit's conjugate, turning the other way round (el__fit_conjugate_start), fitted from where
     * it is, its feet found again (el__fit_refeet): rms 0.100, 0.181, 0.182, where 150 random
     * starts reach 0.100, 0.171, 0.117 */
    size_t nconj = 0;    /* the conjugate starts: the first nconj candidates */
    const int inflection = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_START_CURVATURE;
    if ((held & inflection) == inflection && con.start_kappa == 0.0 &&
        (con_rows.mask & EL_CONSTRAIN_END_TANGENT) && !o.use_initial && !lm_only &&
        !(flags & (FIT_RUN_INNER | FIT_RUN_NO_CONJUGATE))) {
        const size_t m = model == FIT_SMOOTH ? 2 : 1;
        memmove(cand[m], cand[0], ncand * sizeof cand[0]);
        /* discrete: the smooth fit that has them, as its smooth start (without them: the
         * smooth start's continuum limit of the conjugate was 1.75 on #10, this 0.207) */
        const int cst = model == FIT_SMOOTH
                      ? el__fit_conjugate_start(xy, n, opt, cx, cy, sc, cand)
                      : el__fit_smooth_start(xy, n, opt, 0, cx, cy, sc, cand[0]);
        if (cst == EL_ENOMEM) { st = cst; goto done; }
        if (cst == EL_OK) { nconj = m; ncand += m; }
        else memmove(cand[0], cand[m], ncand * sizeof cand[0]);
    }
    /* joined G1 at both ends (smooth, by distance, nothing else held or bounded): after the
     * guesses, the members of the Hermite families of those ends nearest the points
     * (fit_g1_family.c, up to G1_STARTS: of other families, and one that follows them) whose
     * objective is below MEMBER_GAIN x the kept fit's (any, where that does not meet the
     * constraints), each fitted by Ipopt straight from its own feet (the guesses' path,
     * Levenberg-Marquardt first, where that run does not meet them): a second pass of the loop
     * below. Measured on 300 sketches of 5-22 points clustered along 10-40 % of a curve (0-0.5 %
     * noise, 0-2 points elsewhere, its ends and tangents): fits above 1.01 x their true curve's
     * rms 19 -> 1 (at up to 28 x before), none worse by 1 %, one EL_EDOM fitted; median CPU 10.7
     * -> 14.7 ms; bench_fit_sparse.py's G1-G1 sets 1 -> 0 above their true curve, median 4.4 ->
     * 9.5 ms (the scan's 19 tension solves, their members' distances, up to 3 Ipopt runs). Fitted
     * among the guesses instead, the members cost 2-4 x the median and their fits ended in other
     * basins where a guess's reached the true curve's */
    int g1_only = model == FIT_SMOOTH && kind == FIT_ORTHOGONAL && ob.rest && !o.use_initial && !lm_only &&
                  !(flags & FIT_RUN_INNER) && o.constraints == (both | EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_TANGENT);
    for (int j = 0; j < FIT_NP && g1_only; j++)
        if ((o.fixed[j] && j > 1) || isfinite(lo[j]) || isfinite(hi[j])) g1_only = 0;
    size_t nfamily = 0;     /* the family members' pass: its candidates are those */
    int family_pass = g1_only, family_won = 0, kept_last = 0;
candidates:
    for (size_t ci = 0; ci < ncand + (free_start || smooth_start); ci++) {
        if (ci == ncand) {      /* every guess far from the noise: one more start, the unconstrained first */
            const int use_free = free_start;
            const int fst = use_free ? el__fit_unconstrained_start(model, xy, n, opt, cx, cy, sc,
                                                                   (sketch_rows ? FREE_GAIN : 0.99) * best.f, cand[ncand])
                                     : el__fit_smooth_start(xy, n, opt, FIT_RUN_NO_CONJUGATE, cx,
                                                            cy, sc, cand[ncand]);
            if (fst == EL_ENOMEM) { st = fst; goto done; }
            if (use_free) free_start = 0; else smooth_start = 0;
            if (fst) {
                if (!smooth_start) break;
                ci--;           /* the smooth start in this slot */
                continue;
            }
            if (use_free) free_ci = ncand; else smooth_ci = ncand;
            ncand++;
        }
        double p0[FIT_NP], x0[FIT_MAXX];
        memcpy(p0, cand[ci], sizeof p0);
        for (int j = 0; j < FIT_NP; j++) {
            if (!o.fixed[j]) continue;
            if (model == FIT_DISCRETE && j == 2 && !o.fixed[4]) p0[4] *= map.fixed[2] / p0[2];   /* keep u(s) */
            p0[j] = map.fixed[j];
        }
        if (el__all_finite(p0, FIT_NP)) continue;
        el__fit_map_inverse(&map, p0, x0);
        if (ends_chart) {       /* the guess turned and scaled onto the ends (its feet too) */
            double ve[2][FIT_NP];
            if (el__fit_map_eval(&map, x0, ve, NULL)) continue;
            memcpy(p0, ve[0], sizeof p0);
        }
        first_feet(&ob, t, p0[6]);
        const int family = ci == natural_ci && model == FIT_SMOOTH;   /* the natural batten's member */
        const int from_smooth = (ci == natural_ci || ci == smooth_ci) && model == FIT_DISCRETE;   /* the smooth fit's curve */
        /* a curve's own start (the caller's, or a sketch's free fit with rows): from its feet,
         * neither the held start's continuation nor the paired start, which moved the
         * free fit above from its curve onto the same figure-eight */
        const int from_curve = caller_start || (caller_twice && ci == 0) || ci < nfamily ||
                               ci < nconj ||
                               (sketch_rows && ci == free_ci && kind == FIT_ORTHOGONAL);
        if ((polish_run || from_curve || family) && ob.rest && el__fit_feet_start(&ob, x0)) continue;
        fit_candidate r;
        int feet_stale = 0, r_strays = -1;     /* r_strays: r strays from its points, once known */
        if (map.nx == 0 || family) {
            /* nothing to fit, or the natural batten's member (its fit, certified along the
             * family where Brent's minimiser converged: fit_natural.c) */
            fit_value fv;
            if (el__fit_objective_eval(&ob, x0, 0, &fv)) continue;
            memset(&r, 0, sizeof r);
            memcpy(r.x, x0, sizeof r.x);
            r.f = fv.f;
            r.status = !family || natural_ok ? EL_OK : EL_ENOCONV;
            r.iters = family ? natural_evals : 0;
        } else {
            int pre = 0;
            if (staged && !polish_run && !from_smooth && !from_curve) {
                pre = el__fit_held_start(&ob, &map, &free_map, staged, &con, o.max_iter, p0, x0);
                first_feet(&ob, t, p0[6]);      /* again (the stages moved them) */
            }
            const int near = (staged && pre > 0) || polish_run ||
                             (from_smooth && ci == natural_ci) || ci < nfamily || ci < nconj;
            if ((st = el__fit_solve_candidate(&ob, &o, &con_rows, xl, xu, need_ipopt, no_polish, x0,
                                              best.f, &r, tmp, near, polish_run || from_curve)))
                goto done;
            r.iters += pre;
            if (ci < nconj && (st = el__fit_refeet(&ob, &o, &con_rows, &con, lo, hi, xl, xu,
                                                   no_polish, &r, &feet_stale, tmp)))
                goto done;
            /* a family member whose Ipopt run did not meet the rows (6 points exactly on a
             * curve: to max_iter at a minimum it could not certify): from it as from a
             * guess, Levenberg-Marquardt first, kept when that meets them */
            if (ci < nfamily && !el__fit_meets(&ob, &map, &con, r.x, lo, hi, tmp) &&
                el__fit_feet_start(&ob, x0) == EL_OK) {
                fit_candidate rb;
                if ((st = el__fit_solve_candidate(&ob, &o, &con_rows, xl, xu, need_ipopt, no_polish, x0, best.f, &rb,
                                                  tmp, 0, 1)))
                    goto done;
                rb.iters += r.iters;
                if (el__fit_meets(&ob, &map, &con, rb.x, lo, hi, tmp)) r = rb;
                else r.iters = rb.iters;
            }
            /* smooth: where the continuation's fit is above the noise or strays from the
             * points, the guess with the held start state set to the constraints directly is
             * fitted too, kept when lower (with rows: when it meets them and is lower, or the
             * continuation's does not). The continuation follows the free fit's basin, which
             * need not hold the constrained one (measured on 2 x 150 sparse noisy sets of
             * each of 7 kinds, from 6 to 59 points: a G2-start fit, rms 0.039 where its true
             * curve has 0.0117; four G2-start G1-end sets EL_EDOM that their true curves
             * meet; a G1-G1 set along a loop of length 2.9 at 2.1 x its true curve's rms,
             * another fit 5 x; none worse. Straying: a start curvature alone, a loop of
             * length 3.1 at rms 0.0217 within the noise rule, 0.0095 directly) */
            if (staged && !polish_run && !from_curve && model == FIT_SMOOTH &&
                (!(sqrt(2.0 * r.f) <= 1.5 * noise && r.status == EL_OK) ||
                 (ob.rest && (r_strays = el__fit_strays_at(&ob, r.x, noise_rms, d, fs, tmp))))) {
                fit_candidate rd;
                first_feet(&ob, t, p0[6]);
                el__fit_map_inverse(&map, p0, x0);
                ob.have_base = 0;
                if ((st = el__fit_solve_candidate(&ob, &o, &con_rows, xl, xu, need_ipopt, no_polish, x0, best.f, &rd, tmp, 0, 0)))
                    goto done;
                rd.iters += r.iters;
                const int r_meets = !need_ipopt || el__fit_meets(&ob, &map, &con, r.x, lo, hi, tmp);
                const int rd_meets = !need_ipopt || el__fit_meets(&ob, &map, &con, rd.x, lo, hi,
                                                                  tmp);
                const int direct = rd_meets && (!r_meets || rd.f < r.f);
                ipopt_spent += el__fit_ran_out(direct ? &r : &rd);    /* the run let go; the kept one below */
                if (direct) { r = rd; r_strays = -1; }
                else { r.iters = rd.iters; feet_stale = 1; }     /* ob.s: the direct fit's feet */
            }
        }
        tried++;
        iters += r.iters;
        /* the unconstrained start only where its fit meets the constraints (where Ipopt
         * could not, its f is that of the free fit); with rows, a fit that meets them
         * before one that does not, whatever their f (measured: a discrete G1-G1 sketch of
         * 7 points, whose first guess ended at Ipopt's max_iter off the end tangent below
         * the f of the three that met it, failed with EL_EDOM) */
        const int r_meets = (need_ipopt || ci == free_ci) &&
                            el__fit_meets(&ob, &map, &con, r.x, lo, hi, tmp);
        last_is_best = ci == free_ci ? r_meets && r.f < best.f
                     : need_ipopt ? (r_meets && !best_meets) || (r_meets == best_meets && r.f < best.f)
                     : r.f < best.f;
        /* a constrained fit that crosses itself or strays from its points (el__fit_wanders)
         * does not replace one that does neither (a G1 family member: 7 noisy points along a
         * near-straight curve, a loop in a gap between them, rms 0.84 x the kept fit's, within
         * el__fit_stray's allowance for a curved arc; el__fit_follow_points' refit of the
         * hull profile above from the paired curve: its held start's loop below its feet's
         * fit). Not the other way round: a fit pinned away from clustered points strays by
         * that measure (test_fit_basin.c's clustered G1 sketch: 28 x its true curve's rms) */
        if (last_is_best && o.constraints && !lm_only && isfinite(best.f) && (best_meets || !need_ipopt) &&
            el__fit_wanders(&ob, r.x, &r_strays, noise_rms, d, fs, tmp)) {
            last_is_best = el__fit_wanders(&ob, best.x, &best_strays, noise_rms, d, fs, tmp);
            wander_kept |= !last_is_best;
        } else if (!last_is_best && o.constraints && !lm_only &&
                   (need_ipopt || ci == free_ci ? r_meets : 1) &&
                   el__fit_fair_over_loop(&ob, r.x, r.f, &r_strays, best.x, best.f, &best_loops,
                                          noise_rms, d, fs, tmp)) {
            /* the other way round where best crosses itself (el__fit_fair_over_loop) */
            last_is_best = wander_kept = 1;
        }
        if (last_is_best) {
            best = r; best_strays = r_strays; best_meets = r_meets; memcpy(best_init, p0, sizeof p0);
            best_loops = -1;
            family_won |= ci < nfamily;
        }
        last_is_best &= !feet_stale;
        /* the natural batten's member meets the rows: every fit that does is a member of
         * the family already searched */
        if (ci == natural_ci && r_meets) break;
        /* paired by the spacing test alone, the smooth start's polygon certified and kept:
         * where its points slip along it, the guesses fit a pairing that el__fit_unpaired
         * replaces (2000 uneven points, G1 at both ends: three guesses' continuations crept
         * 2400-4500 iterations each, 26 s, before its refit by distance from this one) */
        if (ci == smooth_ci && last_is_best && best.status == EL_OK && kind == FIT_PAIRED &&
            o.distance == EL_DISTANCE_AUTO && !(flags & FIT_RUN_INNER) && (best_meets || !need_ipopt)) {
            double vs[2][FIT_NP], s2 = 0.0;
            if (el__fit_map_eval(&map, best.x, vs, NULL) == EL_OK &&
                el__fit_curve_distances(&ob, best.x, vs, 0, d, fs, tmp) == EL_OK) {
                for (size_t i = 0; i < n; i++) s2 += d[i] * d[i];
                if (el__fit_slips(n, vs[0][2], sqrt(s2 / (double)n), fs)) break;
            }
        }
        const double rms = sqrt(2.0 * best.f);
        if (rms <= 1e-10 || map.nx == 0) break;
        if (ci < nfamily) continue;    /* every family member fitted */
        /* constraint rows: Ipopt's runs that end at max_iter, at most two over the guesses
         * once one has met the constraints (converged, or the penalty's point); while none
         * has, no refit below after one (the fuzzer's 11 points with end constraints: five
         * runs to max_iter, 1.3 s; a discrete sketch of 45 points pinned at both ends,
         * every guess to max_iter, 3.1 s) */
        if (need_ipopt && (ipopt_spent += el__fit_ran_out(&r)) >= 2 && (best.status == EL_OK || best_meets)) {
            if (!smooth_start && !(free_start && sketch_rows)) break;
            ci = ncand - 1;     /* no more guesses; the smooth fit's (or a sketch's free) start next */
            continue;
        }
        /* with rows there is no follow_points refit at the end: a fit that strays from its
         * points (a loop where there is none) is no reason to stop (measured on the sets
         * above: with the direct start but without this check, a G1-G1 fit of 41 points
         * stopped on a loop of length 3.0 at rms 0.0133, where the next guess reaches
         * 0.0079 and the true curve, length 1, has 0.0081) */
        if (need_ipopt && kind == FIT_ORTHOGONAL && rms <= 1.5 * noise && best.status == EL_OK && best_strays < 0)
            best_strays = el__fit_strays_at(&ob, best.x, noise_rms, d, fs, tmp);
        /* a fit where Levenberg-Marquardt stalled uncertified (no step lowers f), whose polish
         * is deferred (el__fit_fallback below), stops too: the polish made it EL_OK here before
         * (measured: a smooth fit with a start tangent of 45 points, the first guess stalled
         * at rms 0.68 x the noise figure; without this all five guesses and the unconstrained
         * start ran, 14 -> 56 ms, for the same fit). Not one that crawled to max_iter: the
         * next guesses can reach a lower basin (a discrete sketch of 41 points: 0.0072 by
         * the third guess, where the first crawled to 0.016 within 1.5 x the figure) */
        const int settled = best.status == EL_OK || (deferred && best.status == EL_ENOCONV);
        if (rms <= 1.5 * noise && settled && !(need_ipopt && kind == FIT_ORTHOGONAL && best_strays > 0)) {
            /* held ends: the discrete fit's smooth start too, while above the data's own
             * figure (the constrained fits' plain noise figure is high on sparse curved
             * points: a set of 41 points whose polygon ended at 2.7 x its curve's rms, length
             * 1.22 for 1, within 1.5 of it; the smooth start reaches 0.93 x) */
            const int more = (free_start || (smooth_start && ends_chart)) &&
                             (rms > 1.5 * data_noise || (free_start && sketch_rows));
            if (!more) break;
            ci = ncand - 1;     /* no more guesses; the unconstrained start next */
        }
    }
    if (family_pass) {      /* once, after the guesses */
        family_pass = 0;
        if (!(kept_feet = malloc(sizeof(double) * n))) { st = EL_ENOMEM; goto done; }
        memcpy(kept_feet, ob.s, sizeof(double) * n);
        kept_last = last_is_best;
        int nf = G1_STARTS;
        const int gst = el__fit_g1_family_start(&ob, &con, noise_rms, best_meets ? MEMBER_GAIN * best.f : HUGE_VAL,
                                                cand, &nf);
        if (gst == EL_ENOMEM) { st = gst; goto done; }
        nfamily = gst ? 0 : (size_t)nf;
        if (nfamily > 0) {
            ncand = nfamily;
            free_start = smooth_start = 0;
            free_ci = natural_ci = (size_t)-1;
            nconj = 0;
            goto candidates;
        }
    }
    if (kept_feet && !family_won) {     /* the kept fit as the guesses left it */
        memcpy(ob.s, kept_feet, sizeof(double) * n);
        ob.have_base = 0;
        ob.rest_ok = 0;
        last_is_best = kept_last;
    }
    if (!isfinite(best.f)) {      /* no guess could be evaluated: the first one, unfitted */
        best.status = EL_ENOCONV;
        el__fit_map_inverse(&map, best_init, best.x);
    }

    /* the kept curve: its distances, constraints, canonical form, input units */
    double v[2][FIT_NP];
    const double certificate = ob.lm_tol;
    int status, constraint, ok, refit = 1, sampled = 0, sampling = !need_ipopt && !o.limited_memory, loose = 0;
    for (int round = 0;;) {
        status = best.status;
        constraint = 0;
        ok = el__fit_map_eval(&map, best.x, v, NULL) == EL_OK;
        if (ok && ob.s && !(last_is_best && fit_has_feet(&ob)))   /* else the fit's own feet */
            for (size_t i = 0; i < n; i++) ob.s[i] = t[i] * v[0][6];
        if (ok && (constraint = el__fit_violated(&ob, &con, v[0], lo, hi, tmp))) status = EL_EDOM;
        /* The smooth orthogonal fit moves each foot by Newton steps, which keep it on its
         * branch: a foot that started where a rough curve (the paired start) came nearest,
         * on another pass of a loop than the fit's nearest point, stays at that stationary
         * point of its distance, and the fit is certified at rest there (measured: 20
         * noise-free sketched points, one foot at distance 2.6e-2 on the other pass where
         * the nearest is 1e-3 away, certified at rms 1.07e-3; the exact fit 4e-15). The
         * nearest points are then elsewhere (by more than 1e-3 of the length, far beyond a
         * foot at rest; the extension's feet beyond the curve aside), or, when the fit's
         * feet are gone (an earlier guess kept), the distances below the fit's: fitted
         * again from its point with these feet, while that lowers f. A refit moves the
         * curve, and near a crossing of two passes more feet change pass (measured on
         * bench_fit.py's 42 noisy 1000-point smooth curves: 19 refitted, one's moved feet
         * 110, 43, 12, 5, 2 in turn), so the rounds are cheap ones while they find feet
         * elsewhere: the feet from the curve's samples (el__fit_feet_elsewhere, each verified
         * nearer; only once a sampled search, the start's, has seen other passes near the
         * points or the search everywhere has found feet elsewhere), the refit by
         * Levenberg-Marquardt alone, stopped at LOOSE_TOL and certified once at the end;
         * then the search everywhere (the report's) for what they missed; none after FEET_ROUNDS refits by that search (a fit left with feet
         * elsewhere that the samples do not show would be refitted to the wrong feet).
         * Measured on those 42 (callgrind, with el__fit_feet_start's sampled search):
         * 3.17e9 -> 1.83e9 instructions (before any refit 1.31e9; el_fit_smooth alone
         * 3.15e9 -> 1.81e9 with or without el__fit_feet_unproven's proof), 15 rms lower (by up
         * to 0.7 %), 25 the same to 1e-9, two higher by 5e-8 and 1.4e-5 at an objective f
         * lower by 2e-14 and 5e-5 (feet on the extension beyond an end, which the
         * reported distances do not use). */
        const int may_refit = ok && refit && ob.rest && isfinite(best.f) && best.f > FIT_EXACT_F && map.nx > 0 &&
                              !(need_ipopt && ipopt_spent >= 1 && best.status != EL_OK);
        size_t moved = 0;
        int projected = 0;
        if (may_refit && last_is_best && sampling && ob.other_passes && sampled < SAMPLED_ROUNDS && round < FEET_ROUNDS &&
            !best.used_ipopt) {
            if ((st = el__fit_feet_elsewhere(&ob, best.x, v, d, fs, &moved)) == EL_ENOMEM) goto done;
            projected = st == EL_OK;
        }
        if (moved) {
            sampled++;
        } else if (loose && ok) {
            /* the kept point, stopped at LOOSE_TOL, certified from its feet (the nearest
             * ones when a later refit's replaced them) */
            loose = 0;
            fit_candidate r;
            ob.have_base = 0;
            if ((!last_is_best && el__fit_feet_start(&ob, best.x)) ||
                (st = el__fit_solve_candidate(&ob, &o, &con_rows, xl, xu, need_ipopt, refit_no_polish, best.x, HUGE_VAL, &r, tmp, 1, 1)) ||
                !isfinite(r.f)) {
                if (st) goto done;
                best.status = EL_ENOCONV;
                last_is_best = 0;
                continue;
            }
            iters += r.iters;
            best = r;
            last_is_best = 1;
            continue;
        } else {
            if (ok) ok = el__fit_curve_distances(&ob, best.x, v, projected, d, fs, tmp) == EL_OK &&
                         !el__all_finite(d, n) && !el__all_finite(fs, n);
            /* after SAMPLED_ROUNDS that all found feet elsewhere: no more rounds */
            if (!ok || !may_refit || round == FEET_ROUNDS || sampled == SAMPLED_ROUNDS) break;
            int elsewhere = 0;
            if (last_is_best) {
                for (size_t i = 1; i + 1 < n; i++)
                    elsewhere |= ob.s[i] >= 0.0 && ob.s[i] <= v[0][6] && fabs(fs[i] - ob.s[i]) > 1e-3 * v[0][6];
            } else {
                double s2 = 0.0;
                for (size_t i = 0; i < n; i++) s2 += d[i] * d[i];
                elsewhere = s2 < 2.0 * (double)n * best.f * (1.0 - 1e-6);
            }
            if (!elsewhere) break;
            round++;
            ob.other_passes = 1;
        }
        memcpy(ob.s + 1, fs + 1, sizeof(double) * (n - 2));
        ob.s[0] = 0.0;
        ob.s[n - 1] = v[0][6];
        ob.have_base = 0;
        fit_candidate r;
        if (moved) ob.lm_tol = LOOSE_TOL;
        st = el__fit_solve_candidate(&ob, &o, &con_rows, xl, xu, need_ipopt, moved || refit_no_polish, best.x, best.f, &r, tmp, 1, 1);
        ob.lm_tol = certificate;
        if (st) goto done;
        iters += r.iters;
        ipopt_spent += el__fit_ran_out(&r);
        if (moved && !(r.status == EL_OK && r.f < best.f)) {
            /* a cheap refit not certified lower: the rounds by the search everywhere */
            sampling = 0;
            last_is_best = 0;
            continue;
        }
        /* else once more for the kept curve's distances; with constraint rows only a refit
         * that meets them (where Ipopt could not, r.f is Levenberg-Marquardt's, free) */
        refit = r.f < best.f && (!need_ipopt || el__fit_meets(&ob, &map, &con, r.x, lo, hi, tmp));
        last_is_best = refit;
        if (refit) {
            best = r;
            loose = moved != 0;
        }
    }
    double s2 = 0.0, emax = 0.0;
    for (size_t i = 0; ok && i < n; i++) {
        s2 += d[i] * d[i];
        if (fabs(d[i]) > emax) emax = fabs(d[i]);     /* fmax, without a libm call (d is finite) */
        d[i] *= sc;
        fs[i] *= sc;
    }
    /* in the input's units too (fuzz: feet of 1e306 times the scale of 1e2 overflowed) */
    if (ok) ok = isfinite(sc * sqrt(s2 / (double)n)) && isfinite(sc * emax) && !el__all_finite(fs, n);
    if (!ok) {
        status = EL_EDOM;        /* its distances are beyond double precision: not a fit */
        for (size_t i = 0; i < n; i++) { d[i] = HUGE_VAL; fs[i] = 0.0; }
    }
    res->rms = ok ? sc * sqrt(s2 / (double)n) : HUGE_VAL;
    res->max_error = ok ? sc * emax : HUGE_VAL;
    {   /* smooth -1 < k < 0 as k >= 0 with q + 2K when k, q are free and may move so */
        double shifted[FIT_NP];
        memcpy(shifted, v[0], sizeof shifted);
        const int may_shift = model == FIT_SMOOTH && !o.fixed[ik] && !o.fixed[5] &&
                              el__fit_canonical(model, shifted, 1) == EL_OK &&
                              shifted[ik] >= lo[ik] && shifted[ik] <= hi[ik] &&
                              shifted[5] >= lo[5] && shifted[5] <= hi[5];
        if (!ok || el__fit_canonical(model, v[0], may_shift)) {    /* only for unevaluable points */
            memcpy(v[0], best_init, sizeof v[0]);
            el__fit_canonical(model, v[0], 0);
            if (status == EL_OK) status = EL_ENOCONV;
        }
    }
    for (int j = 0; j < FIT_NP; j++) {
        res->params[j] = o.fixed[j] ? o.value[j] : el__fit_denorm_param(model, j, v[0][j], cx, cy, sc);
        res->initial[j] = o.use_initial ? init[j] : el__fit_denorm_param(model, j, best_init[j], cx, cy, sc);
        if (!o.use_initial && o.fixed[j]) res->initial[j] = o.value[j];
    }
    /* never hand out NaN, inf, mu = 0 or a curve outside the model: outside double's range */
    {
        int valid = !el__all_finite(res->params, FIT_NP) && !el__all_finite(res->initial, FIT_NP);
        if (model == FIT_SMOOTH) valid = valid && res->params[3] >= DBL_MIN && res->params[6] >= 0.0;
        else valid = valid && res->params[2] >= DBL_MIN && res->params[6] >= 0.0;
        if (!valid) {
            status = EL_EDOM;
            for (int j = 0; j < FIT_NP; j++) {
                if (!isfinite(res->params[j])) res->params[j] = 0.0;
                if (!isfinite(res->initial[j])) res->initial[j] = 0.0;
            }
        }
    }
    res->iterations = iters; res->candidates = tried;
    res->f = best.f;
    res->ipopt_status = best.used_ipopt ? best.ipopt_status : 0;
    res->used_ipopt = best.used_ipopt;
    res->mode = mode;
    res->distance = kind == FIT_PAIRED ? EL_DISTANCE_PAIRED : EL_DISTANCE_ORTHOGONAL;
    res->constraint = constraint;
    res->status = st = status;
    if (ok && kind == FIT_ORTHOGONAL && !need_ipopt && !o.use_initial && !lm_only) {
        const double noise_in = noise_rms * sc;
        const double stray = el__fit_stray(xy, n, fs, el__fit_out_length(model, n, res), noise_in, sc);
        /* el__fit_ends_held's run that strays is not kept (the fit it would replace has
         * followed its points already) */
        if (stray > FIT_STRAY && (flags & FIT_RUN_ENDS_HELD)) st = EL_ENOCONV;
        else if (stray > FIT_STRAY && (st = el__fit_follow_points(model, xy, n, opt, flags, noise_in, sc, stray, res, d, fs)) == EL_OK)
            st = res->status;
        /* the rule above kept a fit over a lower one that crosses itself or strays: that one
         * went on (as before the rule) to el__fit_follow_points, whose refit from the paired
         * curve can end lower and following the points; tried here too, kept when lower and
         * not crossing itself. Smooth only: on the sweep's discrete start point + tangent fits
         * it gained on 2 of 100 at +30 s CPU (/tmp/scrib/sweep.py: smooth, start point and
         * tangent 0.1 rad off the data's, 0.1397 -> 0.1321, 0.1263 -> 0.1246 as before the
         * rule, and 0.1250 -> 0.1217) */
        else if (wander_kept && o.constraints && model == FIT_SMOOTH &&
                 (st = el__fit_follow_unless_loops(model, xy, n, opt, flags, noise_in, stray, &ob, norm, res, d, fs)) ==
                     EL_OK)
            st = res->status;
        /* a sketch's free fit that still wanders: its guesses from their feet (fit_restart.c) */
        if (st != EL_ENOMEM && model == FIT_SMOOTH && !o.constraints && n < SKETCH_POINTS &&
            !(flags & FIT_RUN_INNER))
            st = el__fit_sketch_follows(xy, n, opt, noise_in, &ob, norm, res, d, fs, &wander_kept);
    }
    /* paired by the spacing test alone: refitted by distance to the polygon where its points
     * slip along the polygon from their vertices (fit_restart.c) */
    int unpaired = 0;
    if (ok && kind == FIT_PAIRED && o.distance == EL_DISTANCE_AUTO && !o.use_initial && !lm_only &&
        !(flags & FIT_RUN_INNER) && st != EL_ENOMEM) {
        st = el__fit_unpaired(model, xy, n, opt, res, d, fs);
        unpaired = res->distance == EL_DISTANCE_ORTHOGONAL;   /* its run polished it as needed */
    }
    /* not certified: Ipopt from this one (fit_restart.c); held ends as its rows */
    if (deferred && !unpaired && !(flags & FIT_RUN_INNER) && (st == EL_ENOCONV || st == EL_EMAXITER)) {
        const int rows = ends_chart ? FIT_RUN_ROWS : FIT_RUN_POLISH;
        /* after the rule that keeps a fit that neither crosses itself nor strays: its polish
         * does not end on a loop either (el__fit_fallback_unless_loops) */
        st = wander_kept
                 ? el__fit_fallback_unless_loops(model, xy, n, opt, rows, &ob, norm, res, d, fs)
                 : el__fit_fallback(model, xy, n, opt, rows, res, d, fs);
    }
    /* pinned at both ends with a zero start curvature: fitted in the ends chart too, that
     * curvature held there (el__fit_ends_held); with an end curvature other than 0 (a row
     * in either chart, where the ends chart's runs are the slower) only when this fit was
     * not certified; the natural batten's ran first (above) */
    if (ends_ok && zero_k0 && !ends_chart && !natural && !lm_only && !o.use_initial && !(flags & FIT_RUN_INNER) &&
        st != EL_ENOMEM &&
        (!(o.constraints & EL_CONSTRAIN_END_CURVATURE) || con.end_kappa == 0.0 || st != EL_OK))
        st = el__fit_ends_held(model, xy, n, opt, res, d, fs);
    /* a sketch's constrained fit that wanders: its constraints from other starts (fit_restart.c;
     * not the natural batten's, whose family was searched whole) */
    if (ok && model == FIT_SMOOTH && kind == FIT_ORTHOGONAL && o.constraints && n < SKETCH_POINTS &&
        !natural && !o.use_initial && !lm_only && !(flags & FIT_RUN_INNER) &&
        (st == EL_OK || st == EL_ENOCONV || st == EL_EMAXITER))
        st = el__fit_sketch_follows_held(xy, n, opt, noise_rms * sc, &ob, norm, res, d, fs);
done:
    el__fit_objective_free(&ob);
    free(kept_feet);
    free(dbuf);
    free(t);
    free(tmp);
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
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    int st = el__fit_run_either_way(FIT_DISCRETE, xy, n, opt, 0, initial ? init : NULL, &fo,
                                    distances, foot_s);
    if (fo.status == -1) {        /* failed before a result existed */
        if (fo.constraint) res->constraint = fo.constraint;
        return st;
    }
    FIT_PUBLISH(res, fo, el_discrete_params);
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
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    int st = el__fit_run_either_way(FIT_SMOOTH, xy, n, opt, 0, initial ? init : NULL, &fo,
                                    distances, foot_s);
    if (fo.status == -1) {
        if (fo.constraint) res->constraint = fo.constraint;
        return st;
    }
    FIT_PUBLISH(res, fo, el_smooth_params);
    res->param_mode = fo.mode;
    return fo.status;
}

int el__fit_start(int model, const double *xy, size_t n, const el_fit_options *opt, double *v, int *mode,
                  int *iters, double *foot)
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
