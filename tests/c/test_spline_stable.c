/* The free batten (tension 0) that is an equilibrium but no minimum (spline_stable.c):
 * EL_EDOM with el_spline_result's slides and the span that slides; stable ones as before. */
#include "spline_check.h"
#include <stdio.h>

/* 5 ducks: two along +x, a tip at (10, 0), then two going back at deg degrees from the
 * incoming direction (QA19's sweep) */
static void turn(double deg, double xy[10])
{
    const double t = deg * M_PI / 180.0, d[2] = {cos(t), sin(t)};
    const double p[10] = {0, 0, 5, 0, 10, 0, 10 + 4.5 * d[0], 4.5 * d[1], 10 + 9.5 * d[0], 9.5 * d[1] + 0.5};
    memcpy(xy, p, sizeof p);
}

static el_spline_options free_batten(void)
{
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 0.0;
    return o;
}

/* QA19 W2: 5 ducks turning 170 deg were returned EL_OK (E 2.2926, length 21.99), an
 * unstable equilibrium: a polyline of 40 edges per span, Newton-solved beside it, has one
 * negative eigenvalue of its reduced Hessian (-0.0233) and a minimiser from it slides the
 * span from the tip (point 2) to point 3 off to length 1.2e7; likewise the same layout
 * turning 160 .. 172 deg (163 .. 172 returned EL_OK before). */
START_TEST(unstable_free_batten_slides_off)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    const double deg[] = {160, 163, 165, 167, 169, 170, 172};
    el_spline_options o = free_batten();
    for (int c = 0; c < 8; c++) {
        double xy[10];
        if (c == 0) memcpy(xy, sharp, sizeof xy); else turn(deg[c - 1], xy);
        el_spline_result r;
        ck_assert_msg(el_spline_solve(xy, 5, &o, &r) == EL_EDOM, "case %d", c);
        ck_assert_int_eq(r.slides, 1);
        ck_assert_uint_eq(r.slide_span, 2);
        ck_assert_uint_eq(r.npieces, 0);
        ck_assert_ptr_null(r.pieces);
        el_spline_result_free(&r);
    }
}
END_TEST

/* QA19's controls, whose polylines have no negative eigenvalue (smallest 0.124, 0.090,
 * 0.043, 0.053, 0.25): solved, G2 at every duck, slides 0 */
START_TEST(stable_free_battens_are_solved)
{
    const double irregular[10] = {0, 0, 3.1, 1.2, 7.9, 1.6, 10.2, 0.4, 15.0, -1.9};
    const double t120[10] = {0, 0, 5, 0, 9, 1.5, 8, 5, 6, 9};
    const double t150[10] = {0, 0, 5, 0, 9.5, 1.0, 6.5, 3.5, 2.5, 5.5};
    const double zigzag[12] = {0, 0, 1, 1, 2, 0, 3, 1, 4, 0, 5, 1};
    const double *xy[4] = {irregular, t120, t150, zigzag};
    const size_t n[4] = {5, 5, 5, 6};
    el_spline_options o = free_batten();
    for (int c = 0; c < 4; c++) {
        el_spline_result r;
        ck_assert_msg(el_spline_solve(xy[c], n[c], &o, &r) == EL_OK, "case %d", c);
        ck_assert_int_eq(r.slides, 0);
        ck_assert_int_eq(r.loops, 0);
        check_spline(xy[c], n[c], &o, &r, 1e-9);
        el_spline_result_free(&r);
    }
}
END_TEST

/* A tension > 0 is not judged (the message's advice): the 170-deg ducks solve at sigma 0.3,
 * slides 0 (a minimum there: its reduced Hessian positive definite, by spline_stable.c's
 * test run at that tension) */
START_TEST(a_tension_is_not_judged)
{
    const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    el_spline_options o = free_batten();
    o.sigma = 0.3;
    el_spline_result r;
    ck_assert_int_eq(el_spline_solve(sharp, 5, &o, &r), EL_OK);
    ck_assert_int_eq(r.slides, 0);
    check_spline(sharp, 5, &o, &r, 1e-9);
    el_spline_result_free(&r);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_stable");
    TCase *tc = tcase_create("spline_stable");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, unstable_free_batten_slides_off);
    tcase_add_test(tc, stable_free_battens_are_solved);
    tcase_add_test(tc, a_tension_is_not_judged);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
