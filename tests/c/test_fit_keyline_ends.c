/* A smooth keyline of a scan dense at its start (fit_keyline_ends.c): 200 points along a
 * 20-long elastica with one inflection at arc lengths s = 20 u^p (u evenly spaced), Gaussian
 * noise 0.05 on each coordinate, split at the point nearest the inflection (s = (K(0.75) +
 * 0.9) / sqrt(mu): u = sqrt(mu) s + q at K, seed 000 (4.2)). The keyline ties point 0 to the
 * first side's far end (fit_objective.c); where point 0's noise puts it inside the dense
 * cloud the side stopped there and the points beyond it piled their feet at its end. The
 * keyline must be at least as good as the truth by its own measure, the point-to-curve rms
 * of all points (the truth's from 60001 samples, nearest by brute force: independent of
 * the fit), whatever OpenBLAS kernel solves its steps. */
#include "sketch_check.h"
#include <gsl/gsl_sf_ellint.h>

enum { NPTS = 200, NSAMPLES = 60001 };
static const el_smooth_params TRUTH = {0.0, 0.0, 0.1, 0.04, 0.75, -0.9, 20.0};

typedef struct scan_case { double p; unsigned long long seed; } scan_case;

/* draws main left above the truth (its ratio): seeds 2 and 15 of p = 4 (2.11, 2.34 x) and
 * of p = 2.5 (1.59, 1.73 x). Now 0.945, 0.956, 0.970, 0.971 x. */
static const scan_case cases[] = {{4.0, 2}, {4.0, 15}, {2.5, 2}, {2.5, 15}};

START_TEST(test_dense_start_keyline_at_least_the_truth)
{
    const scan_case *c = &cases[_i];
    double s[NPTS], xy[2 * NPTS], d[NPTS], fs[NPTS];
    int side[NPTS];
    for (size_t i = 0; i < NPTS; i++) s[i] = 20.0 * pow((double)i / (NPTS - 1), c->p);
    ck_assert_int_eq(el_smooth_eval(&TRUTH, NPTS, s, xy, NULL, NULL), EL_OK);
    unsigned long long rng = c->seed;
    for (size_t i = 0; i < 2 * NPTS; i++) xy[i] += 0.05 * test_normal(&rng);
    const double truth = sampled_rms(xy, NPTS, &TRUTH, NSAMPLES);
    const double s_inflection = (gsl_sf_ellint_Kcomp(0.75, GSL_PREC_DOUBLE) + 0.9) / 0.2;
    const size_t split = (size_t)((NPTS - 1) * pow(s_inflection / 20.0, 1.0 / c->p));
    el_fit_smooth_result f, g;
    const int st = el_fit_keyline_smooth(xy, NPTS, split, NULL, &f, &g, d, fs, side);
    ck_assert_msg(st == EL_OK, "case %d: status %d", _i, st);
    double s2 = 0.0;
    size_t far[2] = {0, 0};
    for (size_t i = 0; i < NPTS; i++) {
        s2 += d[i] * d[i];
        far[side[i]] += fs[i] >= (side[i] ? g.params.length : f.params.length);
    }
    const double rms = sqrt(s2 / NPTS);
    ck_assert_msg(rms <= truth, "case %d: rms %.6g above the truth's %.6g (%.3f x); feet at the far ends %zu, %zu",
                  _i, rms, truth, rms / truth, far[0], far[1]);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_keyline_ends");
    TCase *tc = tcase_create("any_kernel");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, test_dense_start_keyline_at_least_the_truth, 0, (int)(sizeof cases / sizeof cases[0]));
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
