/*
 * The fit's options and end constraints (fit.c's driver calls these): the options'
 * defaults and check, the constraints in normalised units and the bounds they add, the
 * check of a result against them, the start of a constrained fit by continuation in the
 * start-state chart (the constraints it holds exactly), and the reversal that turns end
 * constraints into start ones.
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

void el_fit_options_defaults(el_fit_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    for (int j = 0; j < FIT_NP; j++) { opt->lower[j] = -HUGE_VAL; opt->upper[j] = HUGE_VAL; }
    opt->tol = 1e-12;
    opt->max_iter = 200;
    opt->max_candidates = 6;
    opt->param_mode = EL_PARAM_AUTO;
    opt->distance = EL_DISTANCE_AUTO;
    opt->length_range[1] = HUGE_VAL;
    opt->k_range[0] = -HUGE_VAL;
    opt->k_range[1] = HUGE_VAL;
}

int el__fit_check_options(const el_fit_options *o, int model, int *which)
{
    *which = 0;
    if (!(o->tol > 0.0) || !isfinite(o->tol) || o->max_iter < 1 || o->max_candidates < 1)
        return EL_EINVAL;
    if (o->param_mode < EL_PARAM_AUTO || o->param_mode > EL_PARAM_CHORD) return EL_EINVAL;
    if (o->distance < EL_DISTANCE_AUTO || o->distance > EL_DISTANCE_PAIRED) return EL_EINVAL;
    for (int j = 0; j < FIT_NP; j++) {
        if (isnan(o->lower[j]) || isnan(o->upper[j]) || o->lower[j] > o->upper[j]) return EL_EINVAL;
        /* a flag, 0 or 1: another value (2, -1, a count) was held as 1 (QA22 E) */
        if (o->fixed[j] != 0 && o->fixed[j] != 1) return EL_EINVAL;
        if (!o->fixed[j]) continue;
        const double v = o->value[j];
        if (!isfinite(v) || v < o->lower[j] || v > o->upper[j]) return EL_EINVAL;
        if (model == FIT_DISCRETE && j == 2 && !(v > 0.0)) return EL_EINVAL;   /* h */
        if (model == FIT_SMOOTH && ((j == 3 && !(v > 0.0)) || (j == 6 && v < 0.0))) return EL_EINVAL;
    }
    const int c = o->constraints;
    if (c & ~255) return EL_EINVAL;
    const double vals[8] = {o->start_point[0], o->start_point[1], o->end_point[0], o->end_point[1],
                            o->start_tangent, o->end_tangent, o->start_curvature, o->end_curvature};
    const int bits[8] = {1, 1, 2, 2, 4, 8, 16, 32};
    for (int a = 0; a < 8; a++)
        if ((c & bits[a]) && !isfinite(vals[a])) { *which = bits[a]; return EL_EINVAL; }
    if ((c & EL_CONSTRAIN_LENGTH) && !(o->length_range[0] >= 0.0 && o->length_range[0] <= o->length_range[1]
                                      && isfinite(o->length_range[0]) && !isnan(o->length_range[1]))) {
        *which = EL_CONSTRAIN_LENGTH;
        return EL_EINVAL;
    }
    if ((c & EL_CONSTRAIN_K) && !(o->k_range[0] <= o->k_range[1])) { *which = EL_CONSTRAIN_K; return EL_EINVAL; }
    if (c & EL_CONSTRAIN_START_POINT)
        for (int j = 0; j < 2; j++)
            if (o->fixed[j] && o->value[j] != o->start_point[j]) { *which = EL_CONSTRAIN_START_POINT; return EL_EINVAL; }
    return EL_OK;
}

/* The constraints in normalised units, and the bounds they add. */
void el__fit_setup_constraints(const el_fit_options *o, int model, size_t n, double cx, double cy,
                              double sc, fit_constraints *con, double *lo, double *hi)
{
    memset(con, 0, sizeof *con);
    con->mask = o->constraints;
    con->start_xy[0] = (o->start_point[0] - cx) / sc; con->start_xy[1] = (o->start_point[1] - cy) / sc;
    con->end_xy[0] = (o->end_point[0] - cx) / sc; con->end_xy[1] = (o->end_point[1] - cy) / sc;
    con->start_theta = o->start_tangent; con->end_theta = o->end_tangent;
    con->start_kappa = o->start_curvature * sc; con->end_kappa = o->end_curvature * sc;
    const double per = model == FIT_DISCRETE ? (double)(n - 1) : 1.0;
    if (o->constraints & EL_CONSTRAIN_LENGTH) {
        const int j = fit_length_slot(model);
        lo[j] = fmax(lo[j], o->length_range[0] / per / sc);
        hi[j] = fmin(hi[j], o->length_range[1] / per / sc);
    }
    if (o->constraints & EL_CONSTRAIN_K) {
        const int j = fit_k_slot(model);
        lo[j] = fmax(lo[j], o->k_range[0]);
        hi[j] = fmin(hi[j], o->k_range[1]);
    }
}

/* Which constraint the normalised parameters v violate most (0: none), after a solve:
 * points and curvatures to 1e-10 of the data's rms radius, angles to 1e-10 rad, a
 * tangent not reversed, the length and k within their ranges. */
int el__fit_violated(const fit_objective *ob, const fit_constraints *con, const double *v,
                    const double *lo, const double *hi, double *tmp)
{
    const int model = ob->map.model, mask = con->mask;
    const double tol = 1e-10;
    const int jl = fit_length_slot(model), jk = fit_k_slot(model);
    if ((mask & EL_CONSTRAIN_LENGTH) && (v[jl] < lo[jl] * (1 - 1e-14) || v[jl] > hi[jl] * (1 + 1e-14)))
        return EL_CONSTRAIN_LENGTH;
    if ((mask & EL_CONSTRAIN_K) && (v[jk] < lo[jk] - 1e-14 || v[jk] > hi[jk] + 1e-14))
        return EL_CONSTRAIN_K;
    int worst = 0;
    double wv = 0.0;
    for (int at_end = 0; at_end < 2; at_end++) {
        const int pbit = at_end ? EL_CONSTRAIN_END_POINT : EL_CONSTRAIN_START_POINT;
        const int tbit = at_end ? EL_CONSTRAIN_END_TANGENT : EL_CONSTRAIN_START_TANGENT;
        const int kbit = at_end ? EL_CONSTRAIN_END_CURVATURE : EL_CONSTRAIN_START_CURVATURE;
        if (!(mask & (pbit | tbit | kbit))) continue;
        fit_end e;
        if (el__fit_end_state(model, v, ob->n, at_end, &e, tmp)) return mask & (pbit | tbit | kbit);
        const double *P = at_end ? con->end_xy : con->start_xy;
        const double err[3] = {(mask & pbit) ? fmax(fabs(e.xy[0] - P[0]), fabs(e.xy[1] - P[1])) : 0.0,
                               (mask & tbit) ? fabs(remainder(e.theta - (at_end ? con->end_theta : con->start_theta), 2.0 * M_PI)) : 0.0,
                               (mask & kbit) ? fabs(e.kappa - (at_end ? con->end_kappa : con->start_kappa)) : 0.0};
        const int bits[3] = {pbit, tbit, kbit};
        for (int a = 0; a < 3; a++)
            if (err[a] > tol && err[a] > wv) { wv = err[a]; worst = bits[a]; }
    }
    return worst;
}

int el__fit_meets(fit_objective *ob, const fit_map *map, const fit_constraints *con,
                  const double *x, const double *lo, const double *hi, double *tmp)
{
    double v[2][FIT_NP];
    return el__fit_map_eval(map, x, v, NULL) == EL_OK &&
           !el__fit_violated(ob, con, v[0], lo, hi, tmp);
}

/*
 * A start for a fit with a start tangent or curvature (bits) in the start-state chart
 * (free_map: the chart, those variables free): the fit with them free from the guess p0,
 * then the chart's theta0 / kappa0 moved from that fit's values to their targets in
 * HELD_STAGES stages, each fitted by Levenberg-Marquardt from the last, so the fit
 * follows the basin of the unconstrained one instead of starting from the guess with
 * its start state replaced (measured: a noise-free S forced to start at an inflection,
 * rms 4.2 or 8.0 from the guesses, 1.44 by continuation); none (0) where the free fit and
 * the first stage both crawl to max_iter uncertified (crawled) and nothing but the start
 * is held. The targets are the
 * constraints where the chart holds them exactly (the tangent; smooth, the curvature;
 * discrete, a zero curvature); else (a discrete curvature (3.4)) the chart value that
 * would meet it on the free fit's curve (kappa0 = (n-1) h kappa), a start near the
 * constraint for Ipopt's row. x: out's variables on return (p0's when nothing could be
 * fitted); fs: the free fit's f and the last stage's (0, 0 where a stage failed: the
 * measure of conditions the data do not share, fit_choose.c's unshared). Returns the
 * iterations.
 */
/* stages: HELD_STAGES, more where the tangent turns by more than HELD_TURN a stage (measured:
 * 62 points along a loop, a start tangent 1 rad from the free fit's: four stages of 0.25
 * rad ended at rms 0.23 of the normalised points on every guess, sixteen at 0.097) */
enum { HELD_STAGES = 4, HELD_STAGES_MAX = 32 };
#define HELD_TURN 0.0625
/* the ends chart's a = kappa0 L (el__fit_ends_held) in stages of asinh a at most this long:
 * moved linearly from the free fit's (|a| up to ~5e4 on sparse sketches) its stages jumped
 * to other basins (measured: 59 points, discrete, a zero start curvature: rms 0.197 linearly,
 * 0.031 so, the start-state chart's fit 0.040) */
#define HELD_ASINH 1.0
/* Levenberg-Marquardt ran to max_iter and did not reach the first-order condition. The free
 * fit and the first stage so, and the continuation follows no basin: the next stages crawl
 * too (measured: QA15's 1365-point sheer scan, paired, held at its first point and a tangent
 * 0.8 rad off the data's: the free fit crawls towards k = 1, then 32 stages to max_iter on
 * each of six guesses, 35268 evaluations, 10 s, for the fit the direct starts reach in 1731).
 * Not a free fit alone, nor later stages: among stages that stall, as on sparse sketches,
 * such a continuation still found the lower basin (bench_fit_sparse.py seed 5 case 7, G2
 * start 0.3 rad off: 0.0601, 0.0657 without it). Only where the start state is all that is
 * held (start_only): with end rows the continuation's end is Ipopt's start, and a crawled
 * one was the better on 2 of 3 sketches (seed 5 case 27, seed 6 cases 29 and 35, G2 start
 * 0.3 rad off, G1 end: 0.0270, 0.00044, 0.0202 against 0.0402, 0.00076, 0.0184). */
static int crawled(const fit_solution *sol, int max_iter)
{
    return !sol->certified && sol->iters >= max_iter;
}

int el__fit_held_start(fit_objective *ob, const fit_map *out, const fit_map *free_map, int bits,
                      const fit_constraints *con, int max_iter, const double *p0, double *x,
                      double *fs)
{
    const int model = free_map->model;
    const int sl[2] = {model == FIT_DISCRETE ? 3 : 2, model == FIT_DISCRETE ? 4 : 3};
    const int bit[2] = {EL_CONSTRAIN_START_TANGENT, EL_CONSTRAIN_START_CURVATURE};
    double v[2][FIT_NP], xf[FIT_MAXX], from[2] = {0.0, 0.0}, to[2] = {con->start_theta, con->start_kappa};
    const fit_map saved = ob->map;
    int iters = 0;
    fit_solution sol;
    fs[0] = fs[1] = 0.0;
    el__fit_map_inverse(out, p0, x);
    ob->map = *free_map;
    ob->have_base = 0;
    el__fit_map_inverse(free_map, p0, xf);
    if (el__fit_lm(ob, xf, max_iter, &sol) != EL_OK || el__fit_map_eval(free_map, sol.x, v, NULL)) {
        ob->map = saved;
        ob->have_base = 0;
        return 0;
    }
    iters += sol.iters;
    const double f_free = sol.val.f;
    const int crawling = crawled(&sol, max_iter);
    const int start_only = !(con->mask & ~(EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_TANGENT |
                                           EL_CONSTRAIN_START_CURVATURE));
    fit_map stage = *free_map;
    stage.nx = 0;
    for (int j = 0; j < free_map->nx; j++) {
        const int slot = free_map->idx[j];
        if (slot == sl[0]) from[0] = sol.x[j];
        if (slot == sl[1]) from[1] = sol.x[j];
        if (!((slot == sl[0] && (bits & bit[0])) || (slot == sl[1] && (bits & bit[1])))) stage.idx[stage.nx++] = slot;
    }
    if (model == FIT_DISCRETE) to[1] = (double)(ob->n - 1) * v[0][2] * con->start_kappa;
    const double turn = (bits & bit[0]) ? fabs(remainder(to[0] - from[0], 2.0 * M_PI)) : 0.0;
    /* the ends chart's a = kappa0 L: in stages of asinh a (HELD_ASINH) */
    const int ends = free_map->chart == FIT_CHART_ENDS && (bits & bit[1]);
    const double as0 = asinh(from[1]), as1 = asinh(to[1]), span = ends ? fabs(as1 - as0) : 0.0;
    const int stages = (int)fmin(HELD_STAGES_MAX, fmax(HELD_STAGES, fmax(ceil(turn / HELD_TURN), ceil(span / HELD_ASINH))));
    for (int k = 1; k <= stages; k++) {
        const double t = (double)k / stages;
        for (int a = 0; a < 2; a++)
            if (bits & bit[a])
                stage.fixed[sl[a]] = t == 1.0 ? to[a] : a == 0 ? from[0] + t * remainder(to[0] - from[0], 2.0 * M_PI)
                                   : ends ? sinh(as0 + t * (as1 - as0))
                                          : from[1] + t * (to[1] - from[1]);
        ob->map = stage;
        ob->have_base = 0;
        double xs[FIT_MAXX];
        el__fit_map_inverse(&stage, v[0], xs);
        if (el__fit_lm(ob, xs, max_iter, &sol) != EL_OK || el__fit_map_eval(&stage, sol.x, v, NULL)) break;
        iters += sol.iters;
        if (k == 1 && start_only && crawling && crawled(&sol, max_iter)) {
            ob->map = saved;      /* the free fit and the first stage crawled: no start */
            ob->have_base = 0;
            return 0;
        }
        el__fit_map_inverse(out, v[0], x);
        if (k == stages) { fs[0] = f_free; fs[1] = sol.val.f; }
    }
    ob->map = saved;
    ob->have_base = 0;
    return iters;
}

/* How well a fit handles the constraints at one end were they at its start: the start
 * point (x0, y0), and through the start-state chart the start tangent, the smooth start
 * curvature and the discrete zero start curvature are held exactly; other discrete
 * curvatures are started near (fit_run). */
int el__fit_held_score(const el_fit_options *o, int model, int at_end)
{
    const int c = o->constraints;
    const int pbit = at_end ? EL_CONSTRAIN_END_POINT : EL_CONSTRAIN_START_POINT;
    const int tbit = at_end ? EL_CONSTRAIN_END_TANGENT : EL_CONSTRAIN_START_TANGENT;
    const int kbit = at_end ? EL_CONSTRAIN_END_CURVATURE : EL_CONSTRAIN_START_CURVATURE;
    const double kv = at_end ? o->end_curvature : o->start_curvature;
    /* 2 for each held exactly, 1 for a discrete curvature (a start by continuation in the
     * chart, el__fit_held_start) */
    return 2 * !!(c & pbit) + 2 * !!(c & tbit) + ((c & kbit) ? (model == FIT_SMOOTH || kv == 0.0 ? 2 : 1) : 0);
}

/* The same curve run backwards (input units, p in the Jacobian order): smooth by
 * el_smooth_reverse; discrete vertex j' = vertex n-1-j is
 * (gamma_{n-1}, h, phi + pi, -z, q + (n-1) z, k) (Theta_j = phi + a_j + a_{j+1}). Both
 * are involutions; then the canonical form (k >= 0 inflectional). */
int el__fit_reverse_params(int model, size_t n, double *p)
{
    double end[2];
    if (model == FIT_SMOOTH) {
        const el_smooth_params sp = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        el_smooth_params r;
        if (el_smooth_reverse(&sp, &r)) return EL_EDOM;
        const double a[FIT_NP] = {r.x0, r.y0, r.phi, r.mu, r.k, r.q, r.length};
        memcpy(p, a, sizeof a);
        end[0] = r.x0; end[1] = r.y0;
    } else {
        el_discrete_params dp = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        double *xy = malloc(sizeof(double) * 2 * n);
        if (!xy) return EL_ENOMEM;
        int st = el_discrete_eval(&dp, n, xy);
        memcpy(end, xy + 2 * (n - 1), sizeof end);
        free(xy);
        if (st) return EL_EDOM;
        p[5] += (double)(n - 1) * p[4];
        p[4] = -p[4];
        p[3] += M_PI;
    }
    p[0] = end[0]; p[1] = end[1];
    p[3 - (model == FIT_SMOOTH)] = remainder(p[3 - (model == FIT_SMOOTH)], 2.0 * M_PI);
    return el__fit_canonical(model, p, 1);
}
