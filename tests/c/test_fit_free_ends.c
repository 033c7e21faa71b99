/* A scan dense at one end (QA18): 200 points along a 30-long elastica at arc lengths
 * s = 30 u^p (u evenly spaced: spacing ~1e-5 at the dense end for p = 4), Gaussian noise
 * 0.05 on each coordinate. The smooth fit ties its first and last points to its ends
 * (fit_objective.c); where point 0's noise puts it inside the dense cloud the curve stopped
 * there and the points beyond it piled their feet at s = 0: rms up to 1.7 x the true curve's
 * on the same points (QA's draws: 57 feet at s = 0). The fit must be
 * at least as good as the truth by its own measure, the point-to-curve rms (the truth's from
 * 60001 samples of it, nearest by brute force: independent of the fit), and span its points:
 * its feet from 0 to its length. fit_ends.c refits such fits with their ends free. */
#include "sketch_check.h"

enum { NPTS = 200, NSAMPLES = 60001 };
static const el_smooth_params TRUTH = {0.0, 0.0, 0.1, 0.04, 0.75, -0.9, 30.0};

/* The scan (dense at the start, or at the end), its points' rms distance to the truth. */
static double scan(double p, int dense_end, unsigned long long seed, double *xy)
{
    double s[NPTS];
    for (size_t i = 0; i < NPTS; i++) {
        const double u = pow((double)i / (NPTS - 1), p);
        s[i] = 30.0 * (dense_end ? 1.0 - pow((double)(NPTS - 1 - i) / (NPTS - 1), p) : u);
    }
    ck_assert_int_eq(el_smooth_eval(&TRUTH, NPTS, s, xy, NULL, NULL), EL_OK);
    unsigned long long rng = seed;
    for (size_t i = 0; i < 2 * NPTS; i++) xy[i] += 0.05 * test_normal(&rng);
    return sampled_rms(xy, NPTS, &TRUTH, NSAMPLES);
}

typedef struct scan_case { double p; int dense_end; unsigned long long seed; } scan_case;

/* draws main left above the truth (its ratio; its feet piled at the dense end): seed 2 of
 * p = 4 (2.03 x; 55 feet at s = 0), 15 of p = 4 (2.33 x; 59), 2 of p = 2.5 (1.52 x; 26),
 * 15 of p = 2.5 dense at the end (1.16 x; 20 at s = L). Now 0.95, 0.97, 0.97, 0.95 x. */
static const scan_case cases[] = {{4.0, 0, 2}, {4.0, 0, 15}, {2.5, 0, 2}, {2.5, 1, 15}};

START_TEST(test_dense_end_fit_at_least_the_truth)
{
    const scan_case *c = &cases[_i];
    double xy[2 * NPTS], d[NPTS], fs[NPTS];
    const double truth = scan(c->p, c->dense_end, c->seed, xy);
    el_fit_smooth_result r;
    const int st = el_fit_smooth(xy, NPTS, NULL, NULL, &r, d, fs);
    ck_assert_msg(st == EL_OK, "case %d: status %d", _i, st);
    ck_assert_msg(r.rms <= truth, "case %d: rms %.6g above the truth's %.6g (%.3f x)", _i, r.rms, truth,
                  r.rms / truth);
    double lo = HUGE_VAL, hi = -HUGE_VAL, s2 = 0.0;
    for (size_t i = 0; i < NPTS; i++) { lo = fmin(lo, fs[i]); hi = fmax(hi, fs[i]); s2 += d[i] * d[i]; }
    ck_assert_close(sqrt(s2 / NPTS), r.rms, 1e-12 * r.rms);
    ck_assert_msg(lo >= 0.0 && lo <= 1e-9 * r.params.length, "case %d: first foot %.3g", _i, lo);
    ck_assert_msg(hi <= r.params.length && hi >= (1.0 - 1e-9) * r.params.length, "case %d: last foot %.9g of %.9g",
                  _i, hi, r.params.length);
    /* the distances are the curve's: each point's to its foot, and no sample nearer */
    double g[2 * NPTS];
    ck_assert_int_eq(el_smooth_eval(&r.params, NPTS, fs, g, NULL, NULL), EL_OK);
    for (size_t i = 0; i < NPTS; i++)
        ck_assert_close(hypot(g[2 * i] - xy[2 * i], g[2 * i + 1] - xy[2 * i + 1]), fabs(d[i]), 1e-9);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_free_ends");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, test_dense_end_fit_at_least_the_truth, 0, (int)(sizeof cases / sizeof cases[0]));
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
