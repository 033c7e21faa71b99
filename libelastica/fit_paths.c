/*
 * A constrained fit's second optimiser (fit_internal.h): where bounds or fixed values keep
 * the start-state chart off (fit.c, choose_charts), a start tangent or curvature is an Ipopt
 * row like the end conditions, and every guess goes the same way: Levenberg-Marquardt to the
 * unconstrained fit, the rows' penalty from there, the bounds' face, Ipopt (fit_candidate.c).
 * The guesses then end in the unconstrained fit's basin, however many (max_candidates).
 * Ipopt's L-BFGS path (el_fit_options.limited_memory) runs from each guess itself and can
 * reach another basin: QA's 200 points of y = sin x held at start tangent 0.9 and end
 * curvature 0.1, mu in [0.01, 0.3]: rms 0.0931 by the exact path from each of its 5 (or 20)
 * guesses, 0.0678 by L-BFGS from its first under OpenBLAS's SkylakeX kernel (0.0931 under
 * Haswell, Zen, Sandybridge, Prescott: its basin turns on rounding; exact Ipopt from that guess
 * itself, or from its paired fit, returns to 0.0931). Both paths run, the lower kept.
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <string.h>

int el__fit_other_path(int model, const double *xy, size_t n, const el_fit_options *opt, fit_out *res,
                       double *d, double *fs)
{
    el_fit_options lo;
    if (opt) lo = *opt; else el_fit_options_defaults(&lo);
    lo.limited_memory = 1;
    fit_out alt;
    memset(&alt, 0, sizeof alt);
    alt.status = -1;
    double *buf = malloc(sizeof(double) * 2 * n);
    if (!buf) return EL_ENOMEM;
    const int st = el__fit_run(model, xy, n, &lo, FIT_RUN_INNER, NULL, &alt, buf, buf + n);
    /* lower by more than rounding (the same point reached again leaves the fit as it was), or
     * where the first fit gave none that meets the constraints */
    const int none = res->status != EL_OK && res->status != EL_ENOCONV && res->status != EL_EMAXITER;
    if (st == EL_OK && (none || alt.rms < res->rms * (1.0 - 1e-9))) el__fit_replace(res, &alt, buf, n, d, fs);
    free(buf);
    return st == EL_ENOMEM ? st : res->status;
}
