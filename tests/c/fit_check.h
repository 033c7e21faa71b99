/* Shared by the fit tests that take the fit's parts one by one (test_fit_parts.c,
 * test_fit_nearest.c): a map with every parameter free, and the orthogonal objective
 * over noisy samples of one smooth curve. */
#ifndef EL_FIT_CHECK_H
#define EL_FIT_CHECK_H

#include "testutil.h"
#include "fit_internal.h"
#include <string.h>

/* One curve of the model with every parameter free, x = v. */
static fit_map all_free_unscaled(int model)
{
    fit_map m;
    memset(&m, 0, sizeof m);
    m.model = model;
    m.ncurves = 1;
    for (int j = 0; j < FIT_NP; j++) { m.scale[j] = 1.0; m.idx[m.nx++] = j; }
    return m;
}

/* The smooth curve v (normalised) sampled at n equal steps s[i], each coordinate moved by
 * noise * U(-1, 1), in the caller's units (centre cx, cy, scale sc) into xy; the
 * orthogonal objective *o of those points with each foot at its sample (o->s = s), and
 * x (all_free_unscaled's variables) and vv (the curve's parameters) at v. */
static void noisy_smooth_objective(const double *v, size_t n, double noise, double cx, double cy, double sc,
                                   unsigned long long *rng, double *s, double *xy, fit_objective *o,
                                   double *x, double vv[2][FIT_NP])
{
    el_smooth_params p;
    ck_assert_int_eq(el__fit_to_smooth(v, &p), EL_OK);
    for (size_t i = 0; i < n; i++) s[i] = v[6] * (double)i / (double)(n - 1);
    ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
    for (size_t i = 0; i < n; i++) {
        xy[2 * i] = cx + sc * (xy[2 * i] + noise * test_uniform(rng, -1, 1));
        xy[2 * i + 1] = cy + sc * (xy[2 * i + 1] + noise * test_uniform(rng, -1, 1));
    }
    const fit_map m = all_free_unscaled(FIT_SMOOTH);
    ck_assert_int_eq(el__fit_objective_init(o, FIT_ORTHOGONAL, &m, xy, n, cx, cy, sc, NULL), EL_OK);
    el__fit_map_inverse(&m, v, x);
    memcpy(vv[0], v, sizeof vv[0]);
    for (size_t i = 0; i < n; i++) o->s[i] = s[i];
}

#endif
