/* el_fit_options.figures (the binding's checks of a fit in the fit's one call): the result's
 * median_distance is the median of |distances| (of the two middle ones the mean), its
 * noise_quick el_fit_noise_quick's figure of the points, to the bit; max_error is the largest
 * |distance| (what the binding's outlier test takes beside the median); asking them changes
 * nothing else of the fit (every field and every distance and foot the same bits); not asked,
 * or without distances, NaN. Both models, paired and orthogonal, noisy scans, one with a
 * point dragged off, and a few sketched points. */
#include "testutil.h"
#include <stdlib.h>
#include <string.h>

enum { NMAX = 400 };

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of |d| by sorting: the middle value, or (0.0 + lo + hi) / 2 (numpy's). */
static double median_abs(const double *d, size_t n)
{
    double a[NMAX];
    for (size_t i = 0; i < n; i++) a[i] = fabs(d[i]);
    qsort(a, n, sizeof a[0], cmp_double);
    return n % 2 ? a[n / 2] : (0.0 + a[n / 2 - 1] + a[n / 2]) / 2.0;
}

/* Points on a smooth elastica at n places (uneven where uneven), noise sigma, point n / 3
 * dragged off by drag. */
static void data(int kind, size_t n, int uneven, double sigma, double drag, unsigned long long *rng,
                 double *xy)
{
    static const double ks[] = {0.5, 0.95, 2.0};
    const el_smooth_params p = {test_uniform(rng, -5.0, 5.0), test_uniform(rng, -5.0, 5.0),
                                test_uniform(rng, -3.0, 3.0), 1.0, ks[kind], test_uniform(rng, -1.0, 1.0),
                                3.0};
    double s[NMAX];
    for (size_t i = 0; i < n; i++)
        s[i] = p.length * (uneven ? pow((double)i / (double)(n - 1), 1.4) : (double)i / (double)(n - 1));
    ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
    for (size_t i = 0; i < 2 * n; i++) xy[i] += sigma * test_normal(rng);
    xy[2 * (n / 3) + 1] += drag;
}

/* One fit with and without figures: the same bits everywhere, the figures as defined. */
static void check_fit(int smooth, int distance, const double *xy, size_t n)
{
    el_fit_options o;
    el_fit_options_defaults(&o);
    ck_assert_int_eq(o.figures, 0);
    o.distance = distance;
    double d0[NMAX], f0[NMAX], d1[NMAX], f1[NMAX], noise;
    ck_assert_int_eq(el_fit_noise_quick(xy, n, &noise), EL_OK);
    if (smooth) {
        el_fit_smooth_result r0, r1;
        memset(&r0, 0, sizeof r0);
        memset(&r1, 0, sizeof r1);
        const int s0 = el_fit_smooth(xy, n, &o, NULL, &r0, d0, f0);
        o.figures = 1;
        const int s1 = el_fit_smooth(xy, n, &o, NULL, &r1, d1, f1);
        ck_assert_int_eq(s0, s1);
        ck_assert(isnan(r0.median_distance) && isnan(r0.noise_quick));
        ck_assert_double_eq(r1.median_distance, median_abs(d1, n));
        ck_assert_double_eq(r1.noise_quick, noise);
        r1.median_distance = r0.median_distance;
        r1.noise_quick = r0.noise_quick;
        ck_assert(memcmp(&r0, &r1, sizeof r0) == 0);
    } else {
        el_fit_discrete_result r0, r1;
        memset(&r0, 0, sizeof r0);
        memset(&r1, 0, sizeof r1);
        const int s0 = el_fit_discrete(xy, n, &o, NULL, &r0, d0, f0);
        o.figures = 1;
        const int s1 = el_fit_discrete(xy, n, &o, NULL, &r1, d1, f1);
        ck_assert_int_eq(s0, s1);
        ck_assert(isnan(r0.median_distance) && isnan(r0.noise_quick));
        ck_assert_double_eq(r1.median_distance, median_abs(d1, n));
        ck_assert_double_eq(r1.noise_quick, noise);
        double emax = 0.0;
        for (size_t i = 0; i < n; i++) emax = fabs(d1[i]) > emax ? fabs(d1[i]) : emax;
        ck_assert_double_eq(r1.max_error, emax);
        r1.median_distance = r0.median_distance;
        r1.noise_quick = r0.noise_quick;
        ck_assert(memcmp(&r0, &r1, sizeof r0) == 0);
        /* without distances: no median, the noise figure all the same */
        ck_assert_int_eq(el_fit_discrete(xy, n, &o, NULL, &r1, NULL, NULL), s0);
        ck_assert(isnan(r1.median_distance));
        ck_assert_double_eq(r1.noise_quick, noise);
    }
    ck_assert(memcmp(d0, d1, sizeof(double) * n) == 0);
    ck_assert(memcmp(f0, f1, sizeof(double) * n) == 0);
}

START_TEST(test_fit_figures_are_their_definitions)
{
    unsigned long long rng = 20261207ULL;
    static const size_t sizes[] = {7, 20, 101, 400};
    double xy[2 * NMAX];
    for (int kind = 0; kind < 3; kind++)
        for (size_t a = 0; a < sizeof sizes / sizeof sizes[0]; a++)
            for (int uneven = 0; uneven < 2; uneven++) {
                const size_t n = sizes[a];
                data(kind, n, uneven, 1e-3 * (double)(kind + 1), a == 2 ? 0.3 : 0.0, &rng, xy);
                for (int smooth = 0; smooth < 2; smooth++) {
                    check_fit(smooth, EL_DISTANCE_AUTO, xy, n);
                    check_fit(smooth, EL_DISTANCE_PAIRED, xy, n);
                }
            }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_figures");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_fit_figures_are_their_definitions);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
