/* Shared by the tests of fits to sparse noisy sketches (test_fit_held.c,
 * test_fit_discrete_rows.c): the rms of the points to the curve they were drawn from, and
 * that curve's end states as a fit's constraints. */
#ifndef EL_SKETCH_CHECK_H
#define EL_SKETCH_CHECK_H

#include "testutil.h"
#include <math.h>
#include <stdlib.h>

/* The rms distance of the points to the curve p: the nearest of its m samples at equal
 * steps of arc length, by brute force (independent of any fit). */
static inline double sampled_rms(const double *xy, size_t n, const el_smooth_params *p, size_t m)
{
    double *s = malloc(sizeof(double) * m), *P = malloc(sizeof(double) * 2 * m);
    ck_assert(s && P);
    for (size_t j = 0; j < m; j++) s[j] = p->length * (double)j / ((double)m - 1.0);
    ck_assert_int_eq(el_smooth_eval(p, m, s, P, NULL, NULL), EL_OK);
    double s2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double best = HUGE_VAL;
        for (size_t j = 0; j < m; j++) {
            const double dx = P[2 * j] - xy[2 * i], dy = P[2 * j + 1] - xy[2 * i + 1];
            best = fmin(best, dx * dx + dy * dy);
        }
        s2 += best;
    }
    free(s);
    free(P);
    return sqrt(s2 / (double)n);
}

/* sampled_rms of 20001 samples (spaced 5e-5 of the length: each distance off by < 1e-8,
 * far below the sketches' noise) */
static inline double true_rms(const double *xy, size_t n, const el_smooth_params *p)
{
    return sampled_rms(xy, n, p, 20001);
}

/* Options with the constraints mask taken from the curve p: its end points, tangents and
 * curvatures (into P, th, ka as well). */
static inline el_fit_options constraints_of(const el_smooth_params *p, int mask, double P[4], double th[2], double ka[2])
{
    const double s[2] = {0.0, p->length};
    ck_assert_int_eq(el_smooth_eval(p, 2, s, P, th, ka), EL_OK);
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.constraints = mask;
    o.start_point[0] = P[0]; o.start_point[1] = P[1];
    o.end_point[0] = P[2]; o.end_point[1] = P[3];
    o.start_tangent = th[0]; o.end_tangent = th[1];
    o.start_curvature = ka[0]; o.end_curvature = ka[1];
    return o;
}

#endif
