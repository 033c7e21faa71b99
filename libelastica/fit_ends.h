/*
 * A fit whose feet pile up at an end (a scan dense there, a pen's retrace) fitted again tied
 * to the points farthest along it, between its files (not installed): fit_ends.c (the plain
 * smooth and discrete fits by distance), fit_keyline_ends.c (the smooth keyline, which follows
 * it); fit_pairing.c takes FIT_RETRACE_PAST from here (a paired polygon past a retraced end).
 */
#ifndef EL_FIT_ENDS_H
#define EL_FIT_ENDS_H

#include "fit_internal.h"

/* points other than the end's own with their foot at that end that start the refit: at
 * least PILE_LEAST and one in PILE_SHARE of all (noise alone piles a few: on
 * bench_fit.py's noisy 1000- and 5000-point smooth fits up to 8 of 1000 and 67 of 5000, whose
 * refits cost 5 x a fit and took 22 MiB more at 10^6 points for a lower rms by < 1e-3 of
 * it; QA's scans dense at one end pile 8..56 of 200) */
enum { PILE_LEAST = 3, PILE_SHARE = 50 };
/* A retraced end: points beyond a fit's end by more than FIT_RETRACE_PAST of the points' noise
 * levels (el__fit_noise_rms x sc, input units: the rms per point of x and y together, sqrt 2 x
 * the noise across the curve, so 8 levels are ~11 sigma; QA24's 0.25 px pixel strokes: a level
 * 0.33-0.38 px, 8 levels 2.6-3.0 px). Noise alone puts a dense end's points a few levels
 * beyond it. The one figure of both tests of a pen that went back over an end:
 *   fit_ends.c piles_up, a fit by distance (smooth or discrete) tied to a point inside the
 *   stroke: PILE_LEAST points with their feet at an end, the farthest beyond it by this many
 *   levels and PILE_LEAST beyond half as far;
 *   fit_pairing.c el__fit_overruns, a paired polygon running on past its first or last foot by
 *   this many levels (and 3 segments). */
static const double FIT_RETRACE_PAST = 8.0;
/* rounds at most: each from the last one's fit, tied to its extremes, while that lowers the
 * rms (on a 1000-point scan, noise 1 %, 9 rounds crept to the optimum, 0.056338 -> 0.056019,
 * where L-BFGS's free run reached it at once) */
enum { PILE_ROUNDS = 10 };
/* and while a round lowers it by this much of itself (the rounds crept on a 5000-point cloud
 * of three noisy loops: 11 fits of ~230 iterations each, the last five together 0.06 %) */
static const double PILE_GAIN = 1e-4;

/* The fewest piled points of n that start the refit. */
static inline size_t fit_ends_pile(size_t n)
{
    return n / PILE_SHARE > PILE_LEAST ? n / PILE_SHARE : PILE_LEAST;
}

/* Points i and j of xy (and of the n-arrays a, b, may be NULL) swapped. */
static inline void swap_points(double *xy, double *a, double *b, size_t i, size_t j)
{
    for (int c = 0; c < 2; c++) {
        const double t = xy[2 * i + c];
        xy[2 * i + c] = xy[2 * j + c];
        xy[2 * j + c] = t;
    }
    if (a) { const double t = a[i]; a[i] = a[j]; a[j] = t; }
    if (b) { const double t = b[i]; b[i] = b[j]; b[j] = t; }
}

/* fit_ends.c: a public fit by distance (model: FIT_SMOOTH or FIT_DISCRETE) without
 * constraints, fixed parameters or bounds (*res, status st, its distances d (may be NULL) and
 * feet fs, input units) whose feet pile up at an end, fitted again from its curve with its ends
 * free (FIT_RUN_FREE_ENDS, smooth only) and tied to the points farthest along it each way, kept while its rms is lower; the status of
 * the fit kept, or EL_ENOMEM. */
int el__fit_free_ends(int model, const double *xy, size_t n, const el_fit_options *opt, int st, fit_out *res,
                      double *d, double *fs);
/* fit_keyline_ends.c: a smooth keyline (*sol, ob) whose feet pile at a far end refitted tied to
 * the points farthest along it; *sol and ob's feet replaced where lower. EL_OK or EL_ENOMEM. */
int el__fit_keyline_ends(fit_objective *ob, int max_iter, fit_solution *sol, int *iters);
/* fit_ends.c: the smooth curve p cut to [a, b] of its arc length, gamma_cut(s) = gamma(a + s)
 * (test_fit_cut.c): start gamma(a), q + sqrt(mu) a (seed 000 (4.2)), length b - a. EL_OK or
 * el_smooth_eval's error (p unchanged). */
int el__fit_cut(double *p, double a, double b);
/* fit_ends.c: a public smooth fit by distance without constraints, fixed parameters or
 * bounds (*res, status st: a curve given) cut to its feet's range [min fs, max fs] (its
 * feet fs, input units, shifted to the cut curve's arc length) where a tail beyond the
 * outermost foot is longer than 1e-9 of its length: no point's distance changes (each
 * foot is the point's nearest on [0, L], inside the range), and the curve starts and ends at
 * the outermost feet as the header says. A fit stopped at the iteration limit with its ends
 * free kept such tails (QA21 F2: ell3000.csv, 3000 uneven points along an ellipse arc of
 * 78.3 with 15 glitches, status 6, a 99.3-long curve whose first foot is at s 16.65, its
 * start 17.9 from point 0). EL_OK (the fit kept as it was where the cut cannot be
 * evaluated). */
int el__fit_trim_to_feet(const el_fit_options *opt, int st, fit_out *res, double *fs, size_t n);

#endif
