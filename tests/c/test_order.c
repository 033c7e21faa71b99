/* The screen of points' order (el_order_screen): extent, the every-step-th polyline's
 * length and mean |turn| a vertex, on polylines whose figures are known exactly. */
#include "testutil.h"

#include <string.h>

/* The unit square's corners walked round twice: sides 1, every turn +pi/2. */
START_TEST(test_screen_square)
{
    const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
    el_order_screen_result r;
    ck_assert_int_eq(el_order_screen(sq, 9, 1, 1, &r), EL_OK);
    ck_assert(r.extent == 1.0 && r.length == 8.0);
    ck_assert_double_eq_tol(r.turn, M_PI / 2, 1e-15);
    /* every second corner: the diagonals, back and forth, sqrt 2 long, turning pi */
    ck_assert_int_eq(el_order_screen(sq, 9, 2, 1, &r), EL_OK);
    ck_assert(r.extent == 1.0);
    ck_assert_double_eq_tol(r.length, 4 * sqrt(2.0), 1e-15);
    ck_assert_double_eq_tol(r.turn, M_PI, 1e-15);
    /* not asked: NaN; a step past the end: one point, no length */
    ck_assert_int_eq(el_order_screen(sq, 9, 1, 0, &r), EL_OK);
    ck_assert(isnan(r.turn) && r.length == 8.0);
    ck_assert_int_eq(el_order_screen(sq, 9, 9, 1, &r), EL_OK);
    ck_assert(r.length == 0.0 && isnan(r.turn) && r.extent == 1.0);
}
END_TEST

/* A circle's regular polygon of m sides turns 2 pi / m a vertex; its length is m times
 * the chord, summed pairwise (a long sum: exact to a few ulps); a repeated point's zero
 * side turns 0, not atan2(0, -0) = pi. */
START_TEST(test_screen_circle_and_repeats)
{
    const size_t m = 1000;
    double *xy = malloc(2 * (m + 1) * sizeof *xy), *rep = malloc(4 * (m + 1) * sizeof *rep);
    for (size_t i = 0; i <= m; i++) {
        const double a = 2 * M_PI * (double)i / (double)m;
        xy[2 * i] = 3.0 * cos(a);
        xy[2 * i + 1] = 3.0 * sin(a);
        memcpy(rep + 4 * i, xy + 2 * i, 2 * sizeof *xy);
        memcpy(rep + 4 * i + 2, xy + 2 * i, 2 * sizeof *xy);
    }
    el_order_screen_result r, q;
    ck_assert_int_eq(el_order_screen(xy, m + 1, 1, 1, &r), EL_OK);
    ck_assert_double_eq_tol(r.extent, 6.0, 1e-14);
    ck_assert_double_eq_tol(r.length, 6.0 * m * sin(M_PI / m), 1e-12);
    ck_assert_double_eq_tol(r.turn, 2 * M_PI / m, 1e-12);
    /* each point twice: the same length, and every vertex has a zero side, which turns
     * atan2(+-0, +0) = 0 (the dot summed from +0, as numpy's einsum does) */
    ck_assert_int_eq(el_order_screen(rep, 2 * (m + 1), 1, 1, &q), EL_OK);
    ck_assert(q.length == r.length || fabs(q.length - r.length) < 1e-12);
    ck_assert(q.turn == 0.0);
    free(xy);
    free(rep);
}
END_TEST

START_TEST(test_screen_bad_input)
{
    double xy[] = {0, 0, 1, 2, 3, 1};
    el_order_screen_result r;
    memset(&r, 0x5a, sizeof r);
    const el_order_screen_result before = r;
    ck_assert_int_eq(el_order_screen(NULL, 3, 1, 1, &r), EL_EINVAL);
    ck_assert_int_eq(el_order_screen(xy, 0, 1, 1, &r), EL_EINVAL);
    ck_assert_int_eq(el_order_screen(xy, 3, 0, 1, &r), EL_EINVAL);
    ck_assert_int_eq(el_order_screen(xy, 3, 1, 1, NULL), EL_EINVAL);
    xy[3] = NAN;
    ck_assert_int_eq(el_order_screen(xy, 3, 1, 1, &r), EL_EINVAL);
    xy[3] = INFINITY;
    ck_assert_int_eq(el_order_screen(xy, 3, 1, 1, &r), EL_EINVAL);
    ck_assert(memcmp(&r, &before, sizeof r) == 0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("order");
    TCase *tc = tcase_create("order");
    tcase_add_test(tc, test_screen_square);
    tcase_add_test(tc, test_screen_circle_and_repeats);
    tcase_add_test(tc, test_screen_bad_input);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
