/* The Python binding's one-call el.fit (binding.h; not public). */
#include <math.h>
#include <stdlib.h>

#include <gsl/gsl_statistics_double.h>

#include "elastica.h"
#include "binding.h"
#include "binding_abi.h" /* EL_BINDING_DIGEST, written by the build (_cdef.py --binding-abi) */
#include "internal.h"

unsigned long el_binding_digest(void) { return EL_BINDING_DIGEST; }

/* numpy's spacing(m) of m > 0: the gap to the next double above it */
static double spacing(double m)
{
    return nextafter(m, HUGE_VAL) - m;
}

/* require_distinct's first test (fit_input.py): the first 4 points pairwise apart */
static int head_distinct(const double *xy, size_t n, double rounding_ulps)
{
    double hi = xy[0], lo = xy[0];
    for (size_t i = 1; i < 2 * n; i++) {
        if (xy[i] > hi) hi = xy[i];
        if (xy[i] < lo) lo = xy[i];
    }
    const double m = -lo > hi ? -lo : hi;          /* Python's max(hi, -lo): hi unless -lo > hi */
    if (!(m > 0.0)) return 0;                     /* (-0.0's spacing is negative: the plain path) */
    const double tol = rounding_ulps * spacing(m);
    for (size_t a = 0; a < 4; a++)
        for (size_t b = a + 1; b < 4; b++)
            if (!(fabs(xy[2 * a] - xy[2 * b]) > tol || fabs(xy[2 * a + 1] - xy[2 * b + 1]) > tol))
                return 0;
    return 1;
}

/* figures[1], [2]: the median of |d| (_median.py's value) and the maximum; NaN else */
static void distance_figures(const double *d, size_t n, double *figures)
{
    double *a = malloc(n * sizeof *a);
    if (!a) return;
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++) {
        a[i] = fabs(d[i]);
        if (!isfinite(a[i])) { free(a); return; }
        if (a[i] > dmax) dmax = a[i];
    }
    /* GSL's median (gsl_stats_select's places (n - 1) / 2 and n / 2, a reordered): np.median's
     * value; none where the two middle values' sum overflows (NaN left, as _median.py gives) */
    el__gsl_quiet();          /* (no GSL error is possible here, n >= 4: the rule all the same) */
    const double mid = gsl_stats_median(a, 1, n);
    free(a);
    if (!isfinite(mid)) return;
    figures[1] = mid;
    figures[2] = dmax;
}

int el_binding_fit(const double *xy, size_t n, const el_fit_options *opt,
                   el_fit_discrete_result *discrete, el_fit_smooth_result *smooth,
                   double *distances, double *foot_s, double rounding_ulps,
                   size_t screen_step, int screen_turn, el_order_screen_result *screen,
                   double *figures)
{
    if (!figures) return -1;
    figures[0] = figures[1] = figures[2] = NAN;
    if (!xy || !opt || !distances || !foot_s || !screen || (!discrete == !smooth) || n < 4)
        return -1;
    if (el_order_screen(xy, n, screen_step, screen_turn, screen) != EL_OK ||
        !head_distinct(xy, n, rounding_ulps))
        return -1;
    const int st = discrete ? el_fit_discrete(xy, n, opt, NULL, discrete, distances, foot_s)
                            : el_fit_smooth(xy, n, opt, NULL, smooth, distances, foot_s);
    double quick;
    if (el_fit_noise_quick(xy, n, &quick) == EL_OK) figures[0] = quick;
    if (st == EL_OK || st == EL_ENOCONV || st == EL_EMAXITER) distance_figures(distances, n, figures);
    return st;
}
