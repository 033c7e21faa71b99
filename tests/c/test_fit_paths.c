/* A fit whose start tangent is an Ipopt row (mu bounded: the start-state chart is off) ends
 * at least as low as Ipopt's L-BFGS path finds for the same call (fit_restart.c,
 * el__fit_other_path). QA18 M5: 200 points on y = sin x, x in [0, 3], held to start tangent
 * 0.9 and end curvature 0.1 with mu in [0.01, 0.3]: the exact path's guesses all ended at rms
 * 0.0931 (the unconstrained fit's basin), L-BFGS from the first guess at 0.0678 under
 * OpenBLAS's SkylakeX kernel (0.0931 under Haswell, Zen, Sandybridge, Prescott: which basin
 * L-BFGS reaches turns on rounding). */
#include "testutil.h"
#include <elastica.h>
#include <math.h>

START_TEST(test_fit_rows_bounded_keeps_the_lower_path)
{
    enum { N = 200 };
    double xy[2 * N];
    for (int i = 0; i < N; i++) {
        const double t = i / (N - 1.0) * 3.0;
        xy[2 * i] = t;
        xy[2 * i + 1] = sin(t) + 0.01 * sin(97.0 * i);
    }
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.constraints = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_CURVATURE;
    o.start_tangent = 0.9;
    o.end_curvature = 0.1;
    o.lower[3] = 0.01;
    o.upper[3] = 0.3;
    el_fit_smooth_result r, lb;
    ck_assert_int_eq(el_fit_smooth(xy, N, &o, NULL, &r, NULL, NULL), EL_OK);
    o.limited_memory = 1;
    ck_assert_int_eq(el_fit_smooth(xy, N, &o, NULL, &lb, NULL, NULL), EL_OK);
    /* the constraints and the bound met */
    const double s[2] = {0.0, r.params.length};
    double P[4], th[2], ka[2];
    ck_assert_int_eq(el_smooth_eval(&r.params, 2, s, P, th, ka), EL_OK);
    ck_assert_double_le(fabs(remainder(th[0] - 0.9, 2 * M_PI)), 1e-9);
    ck_assert_double_le(fabs(ka[1] - 0.1), 1e-9);
    ck_assert(r.params.mu >= 0.01 && r.params.mu <= 0.3);
    /* the lower of the two paths (main under SkylakeX: 0.0931 against 0.0678), never above the
     * exact path's own basin */
    ck_assert_msg(r.rms <= lb.rms * (1.0 + 1e-9) && r.rms <= 0.09315, "rms %.6g, L-BFGS %.6g", r.rms, lb.rms);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_paths");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_fit_rows_bounded_keeps_the_lower_path);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
