/*
 * A fit kept where it follows its points (el__fit_run's further runs, fit.c): a refit that
 * would replace it taken only where it does not cross itself (the loop rules after the stray
 * rule and after the polish), and a sketch's fit that wanders (strays, crosses itself, or
 * swings between two points) given way to the lowest fit of more guesses that follows them.
 * Split from fit_restart.c, verbatim.
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The fit in *res (input units) crosses itself: its parameters in ob's map (norm: cx, cy,
 * sc of the fit's normalisation) */
static int result_loops(fit_objective *ob, int model, const double norm[3], const fit_out *res)
{
    double p[FIT_NP], x[FIT_MAXX];
    for (int j = 0; j < FIT_NP; j++) p[j] = el__fit_norm_param(model, j, res->params[j], norm[0], norm[1], norm[2]);
    el__fit_map_inverse(&ob->map, p, x);
    return el__fit_loops(ob, x);
}

/* After el__fit_run kept a fit over a lower one that crosses itself or strays: that one
 * went on (before the rule) to el__fit_follow_points, whose refit from the paired curve can
 * end lower and following the points (sweep of /tmp/scrib, smooth, start point and tangent
 * 0.1 rad off the data's: 0.1397 -> 0.1321, 0.1263 -> 0.1246 as before the rule, 0.1250 ->
 * 0.1217). Smooth only: on the discrete fits it gained on 2 of 100 at +30 s CPU. */
int el__fit_follow_unless_loops(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                                double noise, double stray, fit_objective *ob, const double norm[3], fit_out *res,
                                double *d, double *fs)
{
    fit_out alt = *res;
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    memcpy(buf, d, sizeof(double) * n);
    memcpy(buf + n, fs, sizeof(double) * n);
    const int st = el__fit_follow_points(model, xy, n, opt, flags, noise, norm[2], stray, &alt, buf, buf + n);
    if (st == EL_OK && alt.rms < res->rms && !result_loops(ob, model, norm, &alt)) {
        *res = alt;     /* (its iterations counted res's already) */
        memcpy(d, buf, sizeof(double) * n);
        memcpy(fs, buf + n, sizeof(double) * n);
    }
    free(buf);
    return st;
}

/* After that rule, the kept fit's polish does not end on a loop either (a discrete start
 * point and tangent, 231 points: 0.120 -> 0.092 crossing itself 3 times) */
int el__fit_fallback_unless_loops(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                                  fit_objective *ob, const double norm[3], fit_out *res, double *d, double *fs)
{
    fit_out kept = *res;
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    memcpy(buf, d, sizeof(double) * n);
    memcpy(buf + n, fs, sizeof(double) * n);
    int st = el__fit_fallback(model, xy, n, opt, flags, res, d, fs);
    if (st != EL_ENOMEM && result_loops(ob, model, norm, res)) {
        *res = kept;
        memcpy(d, buf, sizeof(double) * n);
        memcpy(fs, buf + n, sizeof(double) * n);
        st = res->status;
    }
    free(buf);
    return st;
}

/* ------------------------------------------------------------ sketches */

/* Whether the smooth fit in *res (fs: its feet) wanders: STRAYS from its points
 * (el__fit_stray, at its own rms as the noise where that is below the data's figure noise:
 * a few points' figure holds their bending, fit.c, and its slack of 4 x 0.3 of their size
 * hid a curve 2.2 x their polygon's length) or crosses itself where their polygon does not;
 * else SWINGS between two of them (el__fit_gap_sag, the same noise); else FOLLOWS. */
enum { FOLLOWS = 0, STRAYS = 1, SWINGS = 2 };
static double result_stray(const double *xy, size_t n, double noise, const fit_objective *ob,
                           const double norm[3], const fit_out *res, const double *fs)
{
    return el__fit_stray_held(xy, n, fs, res->params[6], fmin(noise, res->rms), norm[2], ob->held_ends);
}

static int result_wanders(const double *xy, size_t n, double noise, fit_objective *ob,
                          const double norm[3], const fit_out *res, const double *fs)
{
    const double level = fmin(noise, res->rms);
    const double stray = result_stray(xy, n, noise, ob, norm, res, fs);
    if (!(stray <= FIT_STRAY) || result_loops(ob, FIT_SMOOTH, norm, res)) return STRAYS;
    return el__fit_gap_sag(xy, n, fs, res->params, level) > FIT_GAP_SAG ? SWINGS : FOLLOWS;
}

/* The length bounds of the bounded refits (lowest_that_follows), times the points' polygon
 * length. Few points admit a fit that passes them at a lower rms by swinging between them,
 * and a descent from a fair curve slides down to it: a sketch of 6 points, one at each end
 * of 100 mm and a cluster between, noise 0.3 mm: rms 0.200 along a snake of 145 mm, 19 mm
 * off the 57 mm gap, where the fit of the polygon's own samples (rms 0.56 to the points)
 * went; held to the polygon's length, 102.7, rms 0.208, 2.8 mm off. The longer bound keeps
 * a fair fit of a curve longer than its polygon (5 points: rms 0.0046 along 1.12 x their
 * polygon at the bound of 1.2 x, 0.0091 at 1 x). */
static const double GAP_LENGTHS[] = {1.0, 1.2};
enum { NGAP = sizeof GAP_LENGTHS / sizeof GAP_LENGTHS[0] };

/* Run c of lowest_that_follows: starts[c] from its own feet (go, flags), or past ns the
 * fit of go's constraints with the length at most GAP_LENGTHS[c - ns] x the points' polygon
 * (within go's own range; from the guesses: no start), alt->status -1 where that range is
 * empty. The run's status. */
static int follow_run(const double *xy, size_t n, const el_fit_options *go, int flags,
                      const double (*starts)[FIT_NP], size_t ns, size_t c, fit_out *alt,
                      double *buf)
{
    if (c < ns) return el__fit_run(FIT_SMOOTH, xy, n, go, flags, starts[c], alt, buf, buf + n);
    double poly = 0.0;
    for (size_t i = 0; i + 1 < n; i++)
        poly += hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]);
    el_fit_options gb = *go;
    const int had = gb.constraints & EL_CONSTRAIN_LENGTH;
    gb.use_initial = 0;
    gb.constraints |= EL_CONSTRAIN_LENGTH;
    gb.length_range[0] = had ? go->length_range[0] : 0.0;
    gb.length_range[1] = GAP_LENGTHS[c - ns] * poly;
    if (had) gb.length_range[1] = fmin(gb.length_range[1], go->length_range[1]);
    if (!(gb.length_range[0] <= gb.length_range[1])) return EL_OK;
    /* inner: no sketch rules of its own (they would come back here) */
    return el__fit_run(FIT_SMOOTH, xy, n, &gb, FIT_RUN_INNER, NULL, alt, buf, buf + n);
}

/* The bounded runs (follow_run) a straying fit *res (feet fs) adds to its starts': all where it
 * coils (el__fit_stray > FIT_COIL; from every start, one such fit of 14 sketched points under
 * both end tangents and an end curvature 0 stayed at 8.3 x their polygon's length, where the
 * fit bounded to 1.2 x follows them), none otherwise. */
static size_t coil_runs(const double *xy, size_t n, double noise, const fit_objective *ob,
                        const double norm[3], const fit_out *res, const double *fs)
{
    return result_stray(xy, n, noise, ob, norm, res, fs) > FIT_COIL ? NGAP : 0;
}

/* Each of the ns starts fitted from its own feet (go: use_initial; flags: el__fit_run's),
 * then nb runs of go's constraints with the length bounded (follow_run), the lowest that
 * does not wander (result_wanders) replacing *res (d, fs) when its rms is at most
 * FIT_SKETCH_TOL of the data's size above *res's (where *res coils, el__fit_stray above
 * FIT_COIL: the lowest that does not coil, within FIT_COIL_TOL); *replaced says so.
 * res->status, or EL_ENOMEM. */
static int lowest_that_follows(const double *xy, size_t n, const el_fit_options *go, int flags,
                               const double (*starts)[FIT_NP], size_t ns, size_t nb,
                               double noise, fit_objective *ob, const double norm[3],
                               fit_out *res, double *d, double *fs, int *replaced)
{
    double *buf = malloc(sizeof(double) * 4 * n);     /* a run's distances and feet, the best's */
    if (!buf) return EL_ENOMEM;
    const int coils = result_stray(xy, n, noise, ob, norm, res, fs) > FIT_COIL;
    fit_out best, alt;
    best.status = -1;
    int st = EL_OK, iters = 0;
    for (size_t c = 0; c < ns + nb && st != EL_ENOMEM; c++) {
        memset(&alt, 0, sizeof alt);
        alt.status = -1;
        st = follow_run(xy, n, go, flags, starts, ns, c, &alt, buf);
        iters += alt.iterations;
        /* a bounded run left unconverged is not kept (its fair fits of 6 points pinned at both
         * ends stalled, EL_ENOCONV or EL_EMAXITER, where the tighter bound's converged) */
        if (st == EL_ENOMEM || !fit_gave_curve(alt.status) || (c >= ns && alt.status != EL_OK)) continue;
        /* a start's fit judged as before the swing rule (el__fit_gap_sag): judged by it too, a
         * fit of 5 points straying along 5.7 x their curve's length stayed, where a start's
         * fit along 1.44 x, which swings, had replaced it */
        /* a coiling fit gives way to one that does not coil, even one that crosses itself
         * or swings (a figure eight's 14 sketched points: rms 0.026 along 85 x their
         * polygon's length, where the fair curve crossing itself once has 0.068 along 1.01 x) */
        const int wanders = !coils ? result_wanders(xy, n, noise, ob, norm, &alt, buf + n)
                          : result_stray(xy, n, noise, ob, norm, &alt, buf + n) > FIT_COIL ? STRAYS : FOLLOWS;
        if (wanders == STRAYS || (wanders == SWINGS && c >= ns) ||
            (best.status != -1 && !(alt.rms < best.rms)))
            continue;
        best = alt;
        memcpy(buf + 2 * n, buf, sizeof(double) * 2 * n);
    }
    if (st != EL_ENOMEM && best.status != -1 &&
        best.rms <= res->rms + (coils ? FIT_COIL_TOL : FIT_SKETCH_TOL) * norm[2]) {
        best.iterations = iters;
        el__fit_replace(res, &best, buf + 2 * n, n, d, fs);
        *replaced = 1;
    }
    free(buf);
    return st == EL_ENOMEM ? st : res->status;
}

/* A fit that follows its points but swings between two of them (result_wanders: SWINGS):
 * go's constraints fitted with the length bounded (follow_run), the lowest that does not
 * wander replacing it as in lowest_that_follows (a descent free of the bound slides back
 * down to the swing: GAP_LENGTHS). */
static int swings(const double *xy, size_t n, const el_fit_options *go, double noise,
                  fit_objective *ob, const double norm[3], fit_out *res, double *d, double *fs,
                  int *replaced)
{
    return lowest_that_follows(xy, n, go, FIT_RUN_INNER, NULL, 0, NGAP, noise, ob, norm, res, d,
                               fs, replaced);
}

/* Up to FIT_SKETCH_GUESSES default guesses of the points appended to starts[*ns]. */
static int add_guesses(const double *xy, size_t n, const el_fit_options *go,
                       double (*starts)[FIT_NP], size_t *ns)
{
    el_smooth_params g[FIT_SKETCH_GUESSES];
    size_t ng = 0;
    if (el_guess_smooth(xy, n, go->param_mode, g, FIT_SKETCH_GUESSES, &ng) == EL_ENOMEM)
        return EL_ENOMEM;
    if ((size_t)go->max_candidates < ng) ng = (size_t)go->max_candidates;
    for (size_t c = 0; c < ng; c++) {
        const double p[FIT_NP] = {g[c].x0, g[c].y0, g[c].phi, g[c].mu, g[c].k, g[c].q, g[c].length};
        memcpy(starts[(*ns)++], p, sizeof p);
    }
    return EL_OK;
}

/* Few points admit many elasticae through them (5 points: 7 residuals for the 7 parameters,
 * the end points' feet held), and the paired start (fit_candidate.c) led every guess to a
 * loop, where from their own feet they follow the points: a quarter circle's 5 sketched
 * points, 0.1 % noise, rms 0.0119 along a curve 32 x their polygon's length, or 5.6e-13
 * crossing itself at 10 x; from the guesses' feet 2.7e-16 and 1.4e-16 along them
 * (tests/python/test_fit.py). Measured on 1200 sketches of 5-9 points along 5 curves, 0.5 %
 * noise (QA's bug4.py, seeds 41-46): looping or > 2 x their curve's length 74 -> 9 (5
 * points: 70 of 299 -> 9); of the 75 changed, rms lower on 42, higher on 33 by at most
 * 0.0095 of the data's size (a loop of length 48 at 4.5e-4 along a sine of length 5.7, now
 * 0.021 at 6.0); CPU 17.2 -> 14.2 s (the loops had crawled to max_iter). The guesses' runs
 * by Levenberg-Marquardt alone: the kept one is polished once (fit.c); with each polished,
 * the same fits in 19.7 s, the slowest 1.0 s. bench_fit_sparse.py's 300 free smooth sets
 * of 6-59 points (seeds 5, 6): none changed. */
int el__fit_sketch_follows(const double *xy, size_t n, const el_fit_options *opt, double noise,
                           fit_objective *ob, const double norm[3], fit_out *res, double *d,
                           double *fs, int *replaced)
{
    const int wanders = result_wanders(xy, n, noise, ob, norm, res, fs);
    if (wanders == FOLLOWS) return res->status;
    el_fit_options go;
    if (opt) go = *opt; else el_fit_options_defaults(&go);
    if (wanders == SWINGS) return swings(xy, n, &go, noise, ob, norm, res, d, fs, replaced);
    double starts[FIT_SKETCH_GUESSES][FIT_NP];
    size_t ns = 0;
    if (add_guesses(xy, n, &go, starts, &ns) == EL_ENOMEM) return EL_ENOMEM;
    go.use_initial = 1;     /* the caller's start: from its own feet (fit.c) */
    return lowest_that_follows(xy, n, &go, FIT_RUN_LM_ONLY, (const double (*)[FIT_NP])starts, ns,
                               coil_runs(xy, n, noise, ob, norm, res, fs), noise, ob, norm, res, d, fs,
                               replaced);
}

/* A sketch's constrained smooth fit in *res (d, fs: its distances and feet) that wanders
 * (result_wanders): fitted again with its constraints from the free fit's curve and from the
 * guesses, each from its own feet (el__fit_run's caller's start), the lowest that meets them
 * and does not wander kept when its rms is at most FIT_SKETCH_TOL of the data's size above
 * *res's. Few points admit elasticae of any length through them, and the guesses under the
 * constraints, and the free start (Levenberg-Marquardt's alone, not its sketch's refits),
 * all ended on such curves: a ship section of 5 offsets (polyline 5676 mm) whose free fit
 * is exact, length 5999, fitted with both end tangents to a coil of length 7.6e6 at rms 0.74
 * (Ipopt's rows: no stray rule at the end), pinned at both ends to a pass of 1.07e7 at 50.1,
 * with start point and tangent to 24983 at 3.32; now 0.12, 4e-11 and 0.13 along 6000 (QA,
 * tests/python/test_fit.py). res->status, or EL_ENOMEM. */
int el__fit_sketch_follows_held(const double *xy, size_t n, const el_fit_options *opt, double noise,
                                fit_objective *ob, const double norm[3], fit_out *res, double *d,
                                double *fs)
{
    const int wanders = result_wanders(xy, n, noise, ob, norm, res, fs);
    int replaced = 0;
    if (wanders == FOLLOWS) return res->status;
    if (wanders == SWINGS) return swings(xy, n, opt, noise, ob, norm, res, d, fs, &replaced);
    el_fit_options go = *opt;
    double starts[1 + FIT_SKETCH_GUESSES][FIT_NP];
    size_t ns = 0;
    go.constraints = 0;
    fit_out alt;
    memset(&alt, 0, sizeof alt);
    alt.status = -1;
    if (el__fit_run(FIT_SMOOTH, xy, n, &go, 0, NULL, &alt, NULL, NULL) == EL_ENOMEM ||
        add_guesses(xy, n, &go, starts + fit_gave_curve(alt.status), &ns) == EL_ENOMEM)
        return EL_ENOMEM;
    if (fit_gave_curve(alt.status)) { memcpy(starts[0], alt.params, sizeof starts[0]); ns++; }
    go = *opt;
    go.use_initial = 1;     /* each run polished (flags 0) */
    return lowest_that_follows(xy, n, &go, 0, (const double (*)[FIT_NP])starts, ns,
                               coil_runs(xy, n, noise, ob, norm, res, fs), noise, ob, norm, res, d, fs,
                               &replaced);
}
