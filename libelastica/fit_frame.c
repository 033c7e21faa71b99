/*
 * The public fits in a frame of the constraints' own: a fit with a start or end tangent held
 * and as many conditions as parameters runs on the points turned so that the held tangent is
 * 0 (about the held start point, else the first point, which becomes the origin), and its
 * curve is turned back.
 *
 * Why: the fit's steps are not covariant under rotation (Levenberg-Marquardt's diagonal
 * scaling, the variables' scales, the start-state chart's force components Fx, Fy, the
 * guesses), so the same points moved rigidly took other paths; where many curves meet the
 * constraints they ended on different ones. Measured: 6 sketched points, start point, tangent
 * and curvature and end point and tangent held (7 conditions on the 7 parameters: the fits
 * are the isolated curves that meet them), over 6 rotations x 4 translations: 5 distinct
 * curves (rms 0.976 - 1.421), the 4 translations of each rotation the same; turned to the
 * held tangent, all 24 the same to 1e-9. Translations alone are the normalisation's
 * (el__fit_normalisation: the centroid), exact but for rounding.
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

/* (x, y) - o turned by -a (c = cos a, s = sin a), in place; back: turned by a, + o */
static void to_frame(double *p, const double o[2], double c, double s)
{
    const double x = p[0] - o[0], y = p[1] - o[1];
    p[0] = c * x + s * y;
    p[1] = c * y - s * x;
}
static void from_frame(double *p, const double o[2], double c, double s)
{
    const double x = p[0], y = p[1];
    p[0] = o[0] + (c * x - s * y);
    p[1] = o[1] + (s * x + c * y);
}

int el__fit_run_framed(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                       const double *init, fit_out *res, double *dist, double *foot)
{
    const int iphi = model == FIT_SMOOTH ? 2 : 3, bits = opt ? opt->constraints : 0;
    const int held = bits & (EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_TANGENT);
    const double a = !held                                  ? 0.0
                   : bits & EL_CONSTRAIN_START_TANGENT ? opt->start_tangent : opt->end_tangent;
    /* as many conditions as parameters (the curves that meet them isolated, the fit's path
     * choosing among them); x0, y0 and phi fixed or bounded by the caller: their values are in
     * the caller's frame */
    int conds = fit_conditions(bits);
    for (int j = 0; j < FIT_NP && opt; j++) conds += opt->fixed[j] != 0;
    int framed = held && conds == FIT_NP && xy && n >= 4 && isfinite(a) && isfinite(xy[0]) &&
                 isfinite(xy[1]);
    for (int j = 0; j < FIT_NP && framed; j++)
        if (j < 2 || j == iphi)
            framed = !opt->fixed[j] && !isfinite(opt->lower[j]) && !isfinite(opt->upper[j]);
    if (!framed) return el__fit_run_either_way(model, xy, n, opt, flags, init, res, dist, foot);
    const double c = cos(a), s = sin(a);
    double o[2] = {xy[0], xy[1]}, p[FIT_NP];
    if (bits & EL_CONSTRAIN_START_POINT) memcpy(o, opt->start_point, sizeof o);
    if (!isfinite(o[0]) || !isfinite(o[1]))
        return el__fit_run_either_way(model, xy, n, opt, flags, init, res, dist, foot);
    double *rxy = malloc(sizeof(double) * 2 * n);
    if (!rxy) return EL_ENOMEM;
    memcpy(rxy, xy, sizeof(double) * 2 * n);
    for (size_t i = 0; i < n; i++) to_frame(rxy + 2 * i, o, c, s);
    el_fit_options fo = *opt;
    to_frame(fo.start_point, o, c, s);
    to_frame(fo.end_point, o, c, s);
    fo.start_tangent -= a;
    fo.end_tangent -= a;
    if (init) {
        memcpy(p, init, sizeof p);
        to_frame(p, o, c, s);
        p[iphi] -= a;
    }
    const int st = el__fit_run_either_way(model, rxy, n, &fo, flags, init ? p : NULL, res, dist,
                                          foot);
    free(rxy);
    res->seen.xy = NULL;    /* what it saw was of the turned points */
    if (res->status != -1) {
        from_frame(res->params, o, c, s);
        from_frame(res->initial, o, c, s);
        res->params[iphi] += a;
        res->initial[iphi] += a;
    }
    return st;
}
