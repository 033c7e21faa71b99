/* Shared by the tests of fits to sparse noisy sketches (test_fit_held.c,
 * test_fit_discrete_rows.c): the rms of the points to the curve they were drawn from. */
#ifndef EL_SKETCH_CHECK_H
#define EL_SKETCH_CHECK_H

#include "testutil.h"
#include <math.h>

/* The rms distance of the points to the curve p: the nearest of 20001 samples (spaced
 * 5e-5 of the length: each distance off by < 1e-8, far below the points' noise). */
static double true_rms(const double *xy, size_t n, const el_smooth_params *p)
{
    enum { M = 20001 };
    static double s[M], P[2 * M];
    for (int j = 0; j < M; j++) s[j] = p->length * j / (M - 1.0);
    ck_assert_int_eq(el_smooth_eval(p, M, s, P, NULL, NULL), EL_OK);
    double s2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double best = HUGE_VAL;
        for (int j = 0; j < M; j++) {
            const double dx = P[2 * j] - xy[2 * i], dy = P[2 * j + 1] - xy[2 * i + 1];
            best = fmin(best, dx * dx + dy * dy);
        }
        s2 += best;
    }
    return sqrt(s2 / (double)n);
}

#endif
