/* A fit stopped by max_iter while it still misses a constraint: the cap, not the
 * constraint, stopped it. The runs inside say so by their own status (FIT_ECAPPED, no fit
 * to them, as EL_EDOM) and the public wrappers return it as EL_EMAXITER with the
 * constraint named; where nothing caps the same fit meets the constraint (EL_OK). Before,
 * the runs inside read EL_EDOM and the wrappers guessed the cap back from the kept fit's
 * Ipopt status. Data: 60 points along an S-shaped smooth elastica (length 120), spacing
 * growing along it, each coordinate moved by 0.15 sin / cos of its index; discrete, the
 * start point held at the first point and the start curvature at -0.05 (the curve's own
 * is 0.056). */
#include "testutil.h"
#include "fit_internal.h"
#include <math.h>
#include <string.h>

enum { N = 60 };

static void s_points(double *xy)
{
    const double L = 120.0, w = 1.6 * 2.0 * M_PI / L / 2.0;
    const el_smooth_params p = {3.0, -2.0, 0.4, w * w, 0.8, 0.6, L};
    double s[N];
    for (int i = 0; i < N; i++) s[i] = L * pow((double)i / (N - 1), 1.3);
    ck_assert_int_eq(el_smooth_eval(&p, N, s, xy, NULL, NULL), EL_OK);
    for (int i = 0; i < N; i++) {
        xy[2 * i] += 0.15 * sin(12.9898 * i);
        xy[2 * i + 1] += 0.15 * cos(78.233 * i);
    }
}

static void held_options(const double *xy, el_fit_options *o)
{
    el_fit_options_defaults(o);
    o->constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_CURVATURE;
    o->start_point[0] = xy[0];
    o->start_point[1] = xy[1];
    o->start_curvature = -0.05;
}

START_TEST(test_capped_run_says_so)
{
    double xy[2 * N];
    s_points(xy);
    el_fit_options o;
    held_options(xy, &o);
    el_fit_discrete_result r;
    ck_assert_int_eq(el_fit_discrete(xy, N, &o, NULL, &r, NULL, NULL), EL_OK);     /* feasible */
    for (int cap = 1; cap <= 3; cap++) {
        o.max_iter = cap;
        fit_out fo;
        memset(&fo, 0, sizeof fo);
        fo.status = -1;
        const int st = el__fit_run_framed(FIT_DISCRETE, xy, N, &o, 0, NULL, &fo, NULL, NULL);
        ck_assert_msg(st == FIT_ECAPPED && fo.status == FIT_ECAPPED, "cap %d: run %d, status %d", cap, st,
                      fo.status);
        ck_assert_int_eq(fo.constraint, EL_CONSTRAIN_START_CURVATURE);
        ck_assert(fo.used_ipopt && fo.ipopt_status == -1);
        const int pst = el_fit_discrete(xy, N, &o, NULL, &r, NULL, NULL);
        ck_assert_msg(pst == EL_EMAXITER && r.status == EL_EMAXITER, "cap %d: %d", cap, pst);
        ck_assert_int_eq(r.constraint, EL_CONSTRAIN_START_CURVATURE);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit cap");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_capped_run_says_so);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
