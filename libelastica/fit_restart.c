/*
 * A fit's further runs of el__fit_run (fit.c): the unconstrained fit as a constrained
 * fit's last start, the smooth fit as a discrete fit's, the paired fit's curve and the
 * other model's fit as starts of a fit by distance that strays from its points, the rows'
 * fit of an uncertified fit pinned at both ends, and fits of the points in reverse order.
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <gsl/gsl_sf_ellint.h>

/* ------------------------------------------------------------ further starts */

/* A constrained fit's last start, when every guess ended far above the noise: the fit
 * without the constraints (the caller's fixed parameters and bounds kept), whose curve
 * lies in the data's basin, normalised into v. The guesses are started with the
 * constraints imposed, which can put them all in another basin (measured on 600 sparse
 * uneven noisy smooth sets, tests/c/test_fit_basin.c: start point and tangent fixed, rms
 * 0.0053 where this start reaches 0.0033, the fit from the true curve's). None when the
 * free fit's objective is not below f_below (the caller's share of the constrained fits'
 * best, the same objective): the constrained optimum near it would not be lower.
 * EL_ENOMEM, or EL_EDOM when there is no such start. */
int el__fit_unconstrained_start(int model, const double *xy, size_t n, const el_fit_options *opt, double cx,
                                double cy, double sc, double f_below, double *v)
{
    el_fit_options f = *opt;
    f.constraints = 0;
    fit_out fo;
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    const int st = el__fit_run(model, xy, n, &f, FIT_RUN_LM_ONLY, NULL, &fo, NULL, NULL);    /* a start: no Ipopt */
    if (st == EL_ENOMEM) return st;
    if (!fit_gave_curve(fo.status) || !(fo.f < f_below))
        return EL_EDOM;
    for (int j = 0; j < FIT_NP; j++) v[j] = el__fit_norm_param(model, j, fo.params[j], cx, cy, sc);
    return el__all_finite(v, FIT_NP) ? EL_EDOM : EL_OK;
}

/* A curve of n points' fit of the other model as this model's parameters p (input units,
 * the Jacobian order): the discrete model as the smooth one's continuum limit, h = L / (n - 1),
 * z = w h and phi, q, k its own (a loop turning clockwise, k < -1, as (-w, -k, -q)); the
 * smooth one from the discrete, w = z / h (z < 0: the curve (|w|, -k, -q)), L = (n - 1) h. */
static void continuum_limit(int to_model, size_t n, const double *from, double *p)
{
    if (to_model == FIT_DISCRETE) {
        const double h = from[6] / (double)(n - 1), sw = from[4] < -1.0 ? -1.0 : 1.0;
        const double v[FIT_NP] = {from[0], from[1], h, from[2], sw * sqrt(from[3]) * h, sw * from[5], sw * from[4]};
        memcpy(p, v, sizeof v);
    } else {
        const double h = from[2], w = from[4] / h, sw = w < 0.0 ? -1.0 : 1.0;
        const double v[FIT_NP] = {from[0], from[1], from[3], w * w, sw * from[6], sw * from[5], (double)(n - 1) * h};
        memcpy(p, v, sizeof v);
    }
}

/* A discrete fit's last start where its constraints are Ipopt's rows and every guess
 * ended far from the noise, off the rows or off its points: the smooth fit with the same
 * constraints (whose held start state and direct start reach the data's basin, fit.c),
 * as the discrete model's continuum limit, h = L / (n - 1), z = w h and phi, q, k its
 * own (a loop turning clockwise, k < -1, is (-w, -k, -q)), normalised into v. The rows
 * start the guesses' fits from the free fit's basin, where a sparse sketch's may hold no
 * polygon near the data that meets them (measured on 4 x 150 sparse uneven noisy
 * sketches, discrete with start point and tangent, and with both points and one or both
 * tangents: polygons of length 1.5-51740 along an arc of length 1, at up to 4 x the rms
 * this start reaches). EL_ENOMEM, or EL_EDOM when there is none. */
int el__fit_smooth_start(const double *xy, size_t n, const el_fit_options *opt, int flags,
                         double cx, double cy, double sc, double *v)
{
    el_fit_options so = *opt;
    so.distance = EL_DISTANCE_ORTHOGONAL;
    fit_out fo;
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    const int st = el__fit_run_either_way(FIT_SMOOTH, xy, n, &so, flags, NULL, &fo, NULL, NULL);
    if (st == EL_ENOMEM) return st;
    if (!fit_gave_curve(fo.status)) return EL_EDOM;
    double p[FIT_NP];
    continuum_limit(FIT_DISCRETE, n, fo.params, p);
    for (int j = 0; j < FIT_NP; j++) v[j] = el__fit_norm_param(FIT_DISCRETE, j, p[j], cx, cy, sc);
    return el__all_finite(v, FIT_NP) ? EL_EDOM : EL_OK;
}

int el__fit_conjugate(el_smooth_params *p)
{
    const double k = fabs(p->k);
    el_jacobi J;
    if (!(k > 0.0 && k < 1.0) || el_jacobi_eval(p->q, k, &J, NULL, NULL) || fabs(J.cn) > 1e-6)
        return EL_EDOM;
    /* Delta = theta0 - phi = 2 asin(k sn q), |Delta| < pi; k' = cos(Delta / 2) = dn q */
    const double sd = (p->k < 0.0) == (J.sn < 0.0) ? 1.0 : -1.0, kc = J.dn;
    gsl_sf_result K, Kc;
    if (!(kc > 0.0 && kc < 1.0) || gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) ||
        gsl_sf_ellint_Kcomp_e(kc, GSL_PREC_DOUBLE, &Kc))
        return EL_EDOM;
    const double wc = sqrt(p->mu) * Kc.val / K.val;
    p->phi += sd * M_PI;
    p->mu = wc * wc;
    p->k = kc;
    p->q = -sd * Kc.val;
    return el_smooth_check(p) ? EL_EDOM : EL_OK;
}

/* The chord of a smooth curve's ends, or 0 where it cannot be evaluated. */
static double chord_of(const el_smooth_params *p)
{
    double e[2];
    if (el_smooth_eval(p, 1, &p->length, e, NULL, NULL)) return 0.0;
    return hypot(e[0] - p->x0, e[1] - p->y0);
}

/* the conjugate's growth to the held fit's chord, at most (its chord vanishes where its
 * loops' advance does, near k' = 0.91) */
static const double CONJUGATE_GROWTH = 100.0;

int el__fit_conjugate_start(const double *xy, size_t n, const el_fit_options *opt, double cx,
                            double cy, double sc, double v[2][FIT_NP])
{
    el_fit_options f = *opt;
    f.constraints &= EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_TANGENT |
                     EL_CONSTRAIN_START_CURVATURE;       /* the held start state alone */
    fit_out fo;
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    const int st = el__fit_run(FIT_SMOOTH, xy, n, &f, FIT_RUN_LM_ONLY | FIT_RUN_INNER, NULL, &fo,
                               NULL, NULL);
    if (st == EL_ENOMEM) return st;
    if (!fit_gave_curve(fo.status)) return EL_EDOM;
    el_smooth_params c = {fo.params[0], fo.params[1], fo.params[2], fo.params[3], fo.params[4],
                          fo.params[5], fo.params[6]};
    const double chord = chord_of(&c);
    if (el__fit_conjugate(&c)) return EL_EDOM;
    /* the conjugate spans less (a loop between inflections): also scaled up to the held
     * fit's chord */
    const double grow = fmin(chord / fmax(chord_of(&c), DBL_MIN), CONJUGATE_GROWTH);
    for (int a = 0; a < 2; a++) {
        const double g = a ? fmax(grow, 1.0) : 1.0;
        const double p[FIT_NP] = {c.x0, c.y0, c.phi, c.mu / (g * g), c.k, c.q, c.length * g};
        for (int j = 0; j < FIT_NP; j++)
            v[a][j] = el__fit_norm_param(FIT_SMOOTH, j, p[j], cx, cy, sc);
        if (el__all_finite(v[a], FIT_NP)) return EL_EDOM;
    }
    return EL_OK;
}

/* The curve's length of a fit's result. */
double el__fit_out_length(int model, size_t n, const fit_out *r)
{
    return model == FIT_SMOOTH ? r->params[6] : (double)(n - 1) * r->params[2];
}

/* el__fit_replace: fit_internal.h */
void el__fit_replace(fit_out *res, fit_out *alt, const double *buf, size_t n, double *d, double *fs)
{
    if (d) memcpy(d, buf, sizeof(double) * n);
    memcpy(fs, buf + n, sizeof(double) * n);
    alt->iterations += res->iterations;
    alt->candidates += res->candidates;
    *res = *alt;
}

/* A fit by distance to the curve that strays from its points (el__fit_stray: a loop
 * between two points, the points' order run backwards) where a curve near them has
 * a lower rms only by the curve's freedom between them: the paired fit, which passes
 * the points in their order, and the orthogonal fit from its curve, kept in place of
 * *res (d, fs its distances and feet, input units) when it follows the points or strays
 * less than half as far (stray: *res's el__fit_stray; noise, scale: the data's noise
 * level and size, input units); then, for a free fit, the other model's fit as the start
 * (below).
 * Measured on sparse uneven noisy smooth sets (test_fit_basin.c): a curve of length 4.5
 * looping twice round 41 points along an arc of length 1 (rms 0.00354), 0.00366 this
 * way, the fit from the true curve's. EL_OK (whether replaced or not) or EL_ENOMEM. */
int el__fit_follow_points(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, double noise,
                          double scale, double stray, fit_out *res, double *d, double *fs)
{
    el_fit_options po;
    if (opt) po = *opt; else el_fit_options_defaults(&po);
    po.distance = EL_DISTANCE_PAIRED;
    fit_out paired, fo;
    memset(&paired, 0, sizeof paired);
    paired.status = -1;
    int st = el__fit_run(model, xy, n, &po, FIT_RUN_INNER, NULL, &paired, NULL, NULL);
    if (st == EL_ENOMEM) return st;
    if (!fit_gave_curve(paired.status) && po.constraints) {
        /* no paired curve meets the held constraints: the unconstrained fit by distance,
         * which follows the points, as the start */
        po.constraints = 0;
        po.distance = EL_DISTANCE_ORTHOGONAL;
        memset(&paired, 0, sizeof paired);
        paired.status = -1;
        if ((st = el__fit_run(model, xy, n, &po, FIT_RUN_INNER, NULL, &paired, NULL, NULL)) == EL_ENOMEM) return st;
        po.constraints = opt->constraints;
    }
    if (!fit_gave_curve(paired.status)) return EL_OK;
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    po.distance = EL_DISTANCE_ORTHOGONAL;
    po.use_initial = 1;
    memset(&fo, 0, sizeof fo);
    fo.status = -1;
    st = el__fit_run(model, xy, n, &po, FIT_RUN_INNER, paired.params, &fo, buf, buf + n);
    /* the refit's own stray; -1 (out of memory) and a refit without a curve: not kept */
    const double refit_stray = st != EL_ENOMEM && fit_gave_curve(fo.status)
        ? el__fit_stray(xy, n, buf + n, el__fit_out_length(model, n, &fo), noise, scale) : -1.0;
    const double stray_rms = res->rms;    /* the fit that strays */
    int follows = stray <= FIT_STRAY;     /* *res follows its points */
    if (refit_stray >= 0.0 && (refit_stray <= FIT_STRAY || refit_stray < 0.5 * stray)) {
        fo.iterations += paired.iterations;
        fo.candidates += paired.candidates;
        el__fit_replace(res, &fo, buf, n, d, fs);
        follows = refit_stray <= FIT_STRAY;
    }
    /* a free fit that nothing near follows as closely as it strays (the paired refit strays
     * too or is higher): the other model's fit of the points (without this start in turn)
     * as the start, kept when it follows them and is lower than *res (a loop drawn by sparse
     * points can look like straying: LOOP15 of test_fit_basin.c, the true curve's basin at
     * 0.0081, stray 0.14, would give way to 0.048 if following alone counted). The guesses
     * can all end, by rounding, in another basin than the points' (measured: a sketch of 59
     * points along an arc, turned by 0..88 degrees in steps of 2, rms 0.0090 at 20 of the
     * 45 orientations by the smooth model and 38 by the discrete, up to 0.045 at the others,
     * the paired refit that follows the points 3.6 x the straying fit's; with this start
     * 0.0090 at 42 by both models. 150 random sketches: no rms changed) */
    /* (fixed values and bounds: the parameters mean other things in the other model) */
    const int other_ok = st != EL_ENOMEM && !po.constraints && !(flags & FIT_RUN_NO_OTHER) &&
                         (!follows || res->rms > stray_rms) && fit_options_unbounded(&po);
    if (other_ok) {
        el_fit_options oo = po;
        oo.distance = EL_DISTANCE_AUTO;
        oo.use_initial = 0;
        fit_out other;
        memset(&other, 0, sizeof other);
        other.status = -1;
        st = el__fit_run(model == FIT_SMOOTH ? FIT_DISCRETE : FIT_SMOOTH, xy, n, &oo, FIT_RUN_NO_OTHER | FIT_RUN_INNER,
                         NULL, &other, NULL, NULL);
        if (st != EL_ENOMEM && fit_gave_curve(other.status)) {
            double p[FIT_NP];
            continuum_limit(model, n, other.params, p);
            memset(&fo, 0, sizeof fo);
            fo.status = -1;
            st = el__fit_run(model, xy, n, &po, FIT_RUN_INNER, p, &fo, buf, buf + n);
            const double other_stray = st != EL_ENOMEM && fit_gave_curve(fo.status)
                ? el__fit_stray(xy, n, buf + n, el__fit_out_length(model, n, &fo), noise, scale) : -1.0;
            if (other_stray >= 0.0 && other_stray <= FIT_STRAY && fo.rms < res->rms) {
                fo.iterations += other.iterations;
                fo.candidates += other.candidates;
                el__fit_replace(res, &fo, buf, n, d, fs);
            }
        }
    }
    free(buf);
    return st == EL_ENOMEM ? st : EL_OK;
}

/* el__fit_run from *res's curve (the caller's start; res NULL: the options' own starts) with
 * the options opt, the distance measure replaced unless distance < 0: its result into *alt,
 * its distances and feet into *buf (2 n, the caller frees it); EL_ENOMEM (*buf NULL), else
 * el__fit_run's status. */
static int rerun_from(int model, const double *xy, size_t n, const el_fit_options *opt, int distance, int flags,
                      const fit_out *res, fit_out *alt, double **buf)
{
    el_fit_options ro;
    if (opt) ro = *opt; else el_fit_options_defaults(&ro);
    if (distance >= 0) ro.distance = distance;
    if (res) ro.use_initial = 1;
    memset(alt, 0, sizeof *alt);
    alt->status = -1;
    *buf = malloc(sizeof(double) * 2 * n);
    if (!*buf) return EL_ENOMEM;
    return el__fit_run(model, xy, n, &ro, flags, res ? res->params : NULL, alt, *buf, *buf + n);
}

/* A converged paired fit farther than PAIRED_FAR x the points' noise from them (and than
 * 1e-3 of its polygon's length, so that noise-free fits are not judged by a noise figure
 * of rounding): no pairing of such points fits them, whatever the slip says (the slip is
 * judged against the rms, so a fit far enough off passes: QA21gui F3's scans of 30 000 -
 * 50 000 points, denser 50 x at one end than at the other, noise 0.05, stayed paired at
 * rms 10.0 - 10.1, 200 x, where by distance 0.057). 20, not misfit.py's 4 (MISFIT_RATIO): an
 * equilateral polygon of 59 vertices through a noisy scan fits paired at 3.4 x its noise
 * figure, as well as by distance (0.536 / 0.533), and stays paired (seed 000 (4.6);
 * test_fit's test_discrete_default_on_uneven_points_reaches_the_noise). */
#define PAIRED_FAR 20.0

int el__fit_unpaired(int model, const double *xy, size_t n, const el_fit_options *opt, double noise, fit_out *res,
                     double *d, double *fs)
{
    const double h = res->params[2];
    const int free_fit = !opt || (!opt->constraints && fit_options_unbounded(opt));   /* NULL: defaults */
    const int slips = el__fit_slips(n, h, res->rms, free_fit ? d : NULL, fs);
    const int far = free_fit && res->rms > PAIRED_FAR * noise && res->rms > 1e-3 * h * (double)(n - 1);
    /* a retraced end of a scan (el__fit_overruns; a sketch's few points are not a pen's trace):
     * afresh, as its curve runs on past the points, and kept by the rule below */
    const int overruns = free_fit && !far && n >= FIT_SKETCH_POINTS && el__fit_overruns(n, h, noise, fs);
    if (!slips && !far && !overruns && !el__fit_skips(n, h, res->rms, fs)) return res->status;
    fit_out alt;
    double *buf;
    /* slipping: from this fit's curve; a skipped vertex, a paired fit far from its points,
     * or one that did not converge: afresh, as distance="orthogonal". (A scan denser than its noise at one end
     * passes the spacing test, its segments all noise; its paired fit wanders to max_iter,
     * rms 7.4 for noise 0.05 on QA21gui F3's 10 000 points, and Ipopt's refit from that
     * curve ran for minutes through curves far from the points, where afresh it is 0.4 s.) */
    /* afresh only for a free fit: with end conditions a fit from nothing may shrink onto
     * them (the GUI smoke's start curvature no fit meets: 0.43 nm long) */
    const int from_fit = slips && !far && !overruns && (res->status == EL_OK || !free_fit);
    const int st = rerun_from(model, xy, n, opt, EL_DISTANCE_ORTHOGONAL, 0, from_fit ? res : NULL, &alt, &buf);
    /* an overrun costs the paired fit no distance (no point lies past its points' feet):
     * the fit by distance, whose ends are its first and last points' feet, is kept within
     * half a noise level of its rms (QA24 F9: 0.29844 against the overrun's 0.29819) */
    const double above = overruns ? 0.5 * noise : 0.0;
    /* and there, as fit_ends.c's keep_lower, only as good a fit as its status: a converged
     * paired fit is not given up for an uncertified one of higher rms (revE 3) */
    const int as_good = !overruns || alt.status == EL_OK || res->status != EL_OK;
    if (st != EL_ENOMEM && alt.status != -1 && as_good && alt.rms < res->rms + above) {
        if (from_fit) memcpy(alt.initial, res->initial, sizeof alt.initial);
        el__fit_replace(res, &alt, buf, n, d, fs);
    }
    free(buf);
    return st == EL_ENOMEM ? st : res->status;
}

/* A fit that Levenberg-Marquardt did not certify, fitted again from its result by Ipopt
 * (el__fit_run with the result as the caller's start). flags FIT_RUN_ROWS: a fit pinned
 * at both ends in the ends chart, the end point as Ipopt's rows (measured: one of 1200
 * sparse sketches pinned at both ends, a discrete fit near k = 1 where Levenberg-Marquardt
 * crept to max_iter; the rows certify it in 26 ms, rms 0.005 % lower); FIT_RUN_POLISH: a
 * fit without rows, Ipopt from where Levenberg-Marquardt stops. The refit replaces *res (d,
 * fs its distances and feet) when certified, or, without rows (which an uncertified run
 * need not meet), when lower. EL_OK when replaced by a certified fit, else res->status,
 * or EL_ENOMEM. */
int el__fit_fallback(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, fit_out *res,
                     double *d, double *fs)
{
    fit_out alt;
    double *buf;
    int st = rerun_from(model, xy, n, opt, -1, flags, res, &alt, &buf);
    const int lower = !(flags & FIT_RUN_ROWS) && (st == EL_ENOCONV || st == EL_EMAXITER) && alt.f < res->f;
    if (st == EL_OK || lower) {
        memcpy(alt.initial, res->initial, sizeof alt.initial);
        el__fit_replace(res, &alt, buf, n, d, fs);
    } else if (st != EL_ENOMEM) {
        st = res->status;
    }
    free(buf);
    return st;
}

/*
 * A fit pinned at both ends with a zero start curvature, fitted again in the ends chart
 * with that curvature held as a = 0 (fit_model.c; scale-free, so the chart holds it exactly):
 * the start-state chart's fit, with the end point as Ipopt's rows, and this one fall into
 * different basins, each the lower on some sets (measured on 100 sparse uneven noisy
 * sketches, bench_fit_sparse.py's seed 5, pinned at their curve's ends, a zero curvature at
 * one end, each model: this one lower by > 1 % on 5-14 of 100, higher on 2-8, either by up
 * to 2.3 x). The lower is kept: lower than before on 2-4 of 100 per model and end, higher on
 * none, the median CPU 5.2 -> 7.7 ms (this one by Levenberg-Marquardt alone, ~2.5 ms).
 * With a zero curvature at both ends (a natural batten between two pins) the ends chart's
 * run comes first and alone where it gives a fit (fit.c: the smooth fit searches its family,
 * fit_natural.c, the discrete one starts from that curve), this only where it gives none.
 * With another end curvature only where the first did not certify a fit: of 200 such fits,
 * 2 that met none now meet them and 4 are lower.
 */
int el__fit_ends_held(int model, const double *xy, size_t n, const el_fit_options *opt, fit_out *res, double *d,
                      double *fs)
{
    return el__fit_refit_lower(model, xy, n, opt, FIT_RUN_ENDS_HELD, 0.0, res, d, fs);
}

/*
 * A constrained fit's second optimiser: where bounds or fixed values keep the start-state
 * chart off (fit.c, choose_charts), a start tangent or curvature is an Ipopt row like the end
 * conditions, and every guess goes the same way: Levenberg-Marquardt to the unconstrained fit,
 * the rows' penalty from there, the bounds' face, Ipopt (fit_candidate.c). The guesses then
 * end in the unconstrained fit's basin, however many (max_candidates). Ipopt's L-BFGS path
 * (el_fit_options.limited_memory) runs from each guess itself and can reach another basin:
 * QA's 200 points of y = sin x held at start tangent 0.9 and end curvature 0.1, mu in
 * [0.01, 0.3]: rms 0.0931 by the exact path from each of its 5 (or 20) guesses, 0.0678 by
 * L-BFGS from its first under OpenBLAS's SkylakeX kernel (0.0931 under Haswell, Zen,
 * Sandybridge, Prescott: its basin turns on rounding; exact Ipopt from that guess itself, or
 * from its paired fit, returns to 0.0931). Both paths run, the lower kept: lower by more
 * than rounding (the same point reached again leaves the fit as it was).
 */
int el__fit_other_path(int model, const double *xy, size_t n, const el_fit_options *opt, fit_out *res,
                       double *d, double *fs)
{
    el_fit_options lo;
    if (opt) lo = *opt; else el_fit_options_defaults(&lo);
    lo.limited_memory = 1;
    return el__fit_refit_lower(model, xy, n, &lo, 0, 1e-9, res, d, fs);
}

/* el__fit_refit_lower: fit_internal.h */
int el__fit_refit_lower(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, double margin,
                        fit_out *res, double *d, double *fs)
{
    fit_out alt;
    memset(&alt, 0, sizeof alt);
    alt.status = -1;
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    const int st = el__fit_run(model, xy, n, opt, flags | FIT_RUN_INNER, NULL, &alt, buf, buf + n);
    /* lower, or where the first fit gave none that meets the constraints (an uncertified one
     * that does is kept when lower: it is the better fit, only its certificate is missing) */
    if (st == EL_OK && (!fit_gave_curve(res->status) || alt.rms < res->rms * (1.0 - margin)))
        el__fit_replace(res, &alt, buf, n, d, fs);
    free(buf);
    return st == EL_ENOMEM ? st : res->status;
}

/* ------------------------------------------------------------ reversed fits */

/* The least sum of squared distances from the points q (nq) to places c (m) taken in order,
 * forwards (dir 1) or backwards (-1): a place for each point, none before the one before
 * (dynamic programming over the places; row: m doubles). */
static double ordered_cost(const double *q, size_t nq, const double *c, size_t m, int dir,
                           double *row)
{
    for (size_t i = 0; i < nq; i++) {
        double lead = HUGE_VAL;     /* least cost to the previous point at a place not after j */
        for (size_t a = 0; a < m; a++) {
            const size_t j = dir > 0 ? a : m - 1 - a;
            const double dx = c[2 * j] - q[2 * i], dy = c[2 * j + 1] - q[2 * i + 1];
            lead = fmin(lead, i ? row[j] : 0.0);
            row[j] = lead + dx * dx + dy * dy;
        }
    }
    double best = HUGE_VAL;
    for (size_t j = 0; j < m; j++) best = fmin(best, row[j]);
    return best;
}

/* The caller's start p (input units, n points) run backwards, canonical, where its curve runs
 * against the points' order: up to ORIENT_POINTS of the points (evenly by index) are nearer
 * ORIENT_SAMPLES places along it (discrete: its vertices) taken backwards than forwards
 * (ordered_cost). An elastica run backwards is one, and every fit's start, feet and
 * constraints run from point 0: the previous fit of sample_2d.csv reversed was a start that
 * converged to a curve 16 x its length, rms 12.7 for 0.147 (QA). Not each point's nearest
 * place: a start off the points' far part (a start 3 % long, turned by 0.05 rad, along a
 * curve bent round to near itself) has them nearest its first pass. p is left as it is where
 * its curve cannot be evaluated. EL_OK or EL_ENOMEM. */
enum { ORIENT_SAMPLES = 128, ORIENT_POINTS = 256 };

static int orient_initial(int model, const double *xy, size_t n, double *p)
{
    const size_t cs = (n + ORIENT_SAMPLES - 1) / ORIENT_SAMPLES;
    const size_t ps = (n + ORIENT_POINTS - 1) / ORIENT_POINTS;
    const size_t nv = model == FIT_SMOOTH ? ORIENT_SAMPLES : n;     /* the curve's places */
    const size_t m = model == FIT_SMOOTH ? nv : (n + cs - 1) / cs, nq = (n + ps - 1) / ps;
    double *c = malloc(sizeof(double) * (2 * nv + 2 * nq + m));
    if (!c) return EL_ENOMEM;
    double *q = c + 2 * nv, *row = q + 2 * nq;
    int st;
    if (model == FIT_SMOOTH) {
        const el_smooth_params sp = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        for (size_t j = 0; j < m; j++) row[j] = p[6] * (double)j / (double)(m - 1);
        st = el_smooth_eval(&sp, m, row, c, NULL, NULL);
    } else {
        const el_discrete_params dp = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        st = el_discrete_eval(&dp, n, c);
        for (size_t j = 0; j < m; j++) memmove(c + 2 * j, c + 2 * j * cs, sizeof(double) * 2);
    }
    for (size_t i = 0; i < nq; i++) memcpy(q + 2 * i, xy + 2 * i * ps, sizeof(double) * 2);
    const int back = !st && ordered_cost(q, nq, c, m, -1, row) < ordered_cost(q, nq, c, m, 1, row);
    free(c);
    if (back) {
        double r[FIT_NP];
        memcpy(r, p, sizeof r);
        st = el__fit_reverse_params(model, n, r);
        if (st == EL_ENOMEM) return st;
        if (!st) memcpy(p, r, sizeof r);
    }
    return EL_OK;
}

/*
 * el__fit_run, on the points in reverse order when the end holds more constraints than the
 * start (a fit holds start constraints exactly, the end's are Ipopt's rows): the end
 * constraints become start ones, and the result is turned round (params, initial,
 * distances with the other sign, feet from the other end). Only when nothing else
 * depends on the direction: no fixed parameters, bounds, initial curve or (smooth)
 * signed k range.
 */
int el__fit_run_either_way(int model, const double *xy, size_t n, const el_fit_options *opt,
                           int flags, const double *init, fit_out *res, double *dist, double *foot)
{
    int plain = !opt || !xy || n < 4 || opt->use_initial || (model == FIT_SMOOTH && (opt->constraints & EL_CONSTRAIN_K)) ||
                el__fit_held_score(opt, model, 1) <= el__fit_held_score(opt, model, 0);
    plain = plain || !fit_options_unbounded(opt);
    if (plain && opt && opt->use_initial && init && xy && n >= 4) {   /* run as the points */
        double p[FIT_NP];
        memcpy(p, init, sizeof p);
        const int ost = el__all_finite(p, FIT_NP) ? EL_OK : orient_initial(model, xy, n, p);
        return ost ? ost : el__fit_run(model, xy, n, opt, flags, p, res, dist, foot);
    }
    if (plain) return el__fit_run(model, xy, n, opt, flags, init, res, dist, foot);
    el_fit_options o = *opt;
    const int c = opt->constraints, swap[3][2] = {{EL_CONSTRAIN_START_POINT, EL_CONSTRAIN_END_POINT},
                                                  {EL_CONSTRAIN_START_TANGENT, EL_CONSTRAIN_END_TANGENT},
                                                  {EL_CONSTRAIN_START_CURVATURE, EL_CONSTRAIN_END_CURVATURE}};
    o.constraints = c & ~(swap[0][0] | swap[0][1] | swap[1][0] | swap[1][1] | swap[2][0] | swap[2][1]);
    for (int a = 0; a < 3; a++) {
        if (c & swap[a][0]) o.constraints |= swap[a][1];
        if (c & swap[a][1]) o.constraints |= swap[a][0];
    }
    memcpy(o.start_point, opt->end_point, sizeof o.start_point);
    memcpy(o.end_point, opt->start_point, sizeof o.end_point);
    o.start_tangent = opt->end_tangent + M_PI; o.end_tangent = opt->start_tangent + M_PI;
    o.start_curvature = -opt->end_curvature; o.end_curvature = -opt->start_curvature;
    double *rxy = malloc(sizeof(double) * 2 * n);
    if (!rxy) return EL_ENOMEM;
    for (size_t i = 0; i < n; i++) { rxy[2 * i] = xy[2 * (n - 1 - i)]; rxy[2 * i + 1] = xy[2 * (n - 1 - i) + 1]; }
    int st = el__fit_run(model, rxy, n, &o, flags, NULL, res, dist, foot);
    free(rxy);
    res->seen.xy = NULL;    /* what it saw was of the reversed points */
    if (res->status == -1) {        /* failed before a result: the bits back */
        for (int a = 0; a < 3; a++)
            if (res->constraint == swap[a][0] || res->constraint == swap[a][1])
                res->constraint ^= swap[a][0] | swap[a][1];
        return st;
    }
    const double total = model == FIT_SMOOTH ? res->params[6] : (double)(n - 1) * res->params[2];
    for (size_t i = 0; dist && i < n - 1 - i; i++) {
        const double d = dist[i];
        dist[i] = -dist[n - 1 - i];
        dist[n - 1 - i] = -d;
    }
    if (dist && n % 2) dist[n / 2] = -dist[n / 2];
    for (size_t i = 0; foot && i <= n - 1 - i; i++) {
        const double f = foot[i];
        foot[i] = total - foot[n - 1 - i];
        foot[n - 1 - i] = total - f;
    }
    for (int a = 0; a < 3; a++)
        if (res->constraint == swap[a][0] || res->constraint == swap[a][1]) res->constraint ^= swap[a][0] | swap[a][1];
    if (el__fit_reverse_params(model, n, res->params) || el__fit_reverse_params(model, n, res->initial))
        return el__fit_run(model, xy, n, opt, flags, init, res, dist, foot);
    return st;
}
