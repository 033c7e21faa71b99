/* Elastic splines (issue 14): the work one el_spline_solve spends over every path it tries is
 * bounded (spline.c's WORK_BUDGET: 8 x max_steps x max_iter evaluations of the chain) and said
 * in the result (work, stopped). */
#include "spline_check.h"
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The fuzz driver's slow input (fuzz/corpus/fuzz-spline-solve-length-g2-collinear-slow.bin, 1.00 s
 * of CPU in make check's fuzz stage at eb4b739, two solves of it per input): 36 collinear
 * points (t, 2t), G2 ends (the end's curvature DBL_MAX), by length 15.458 = 6.9 x the polygon,
 * max_steps 15, max_iter 37. No spline reaches that length: el__spline_solve_length's four paths
 * fail, then spline_bracket.c's ladder and the four paths again from each way of its bracket:
 * 6468 chain evaluations (2.16 G instructions) to say EL_ERANGE. With the budget the search
 * stops at 8 x 15 x 37 = 4440 (what it had met said as before: EL_ERANGE, reach). */
START_TEST(length_search_stops_at_its_budget)
{
    double xy[72];
    for (int i = 0; i < 36; i++) {
        const double t = i / 35.0;
        xy[2 * i] = t;
        xy[2 * i + 1] = 2 * t;
    }
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.mode = EL_SPLINE_LENGTH;
    o.sigma = 3.8666361486228733;
    o.length = 15.457999542229343;
    o.start.kind = o.end.kind = EL_SPLINE_G2;
    o.start.tangent[0] = 3.4792095826657512;
    o.start.tangent[1] = 0.58059052414740209;
    o.start.curvature = 0.53501182574196982;
    o.end.tangent[0] = 0.58931868467231241;
    o.end.tangent[1] = -0.34065766384374763;
    o.end.curvature = DBL_MAX;
    o.max_iter = 37;
    o.max_steps = 15;
    el_spline_result r;
    const int st = el_spline_solve(xy, 36, &o, &r);
    const unsigned long budget = 8ul * 15 * 37;
    /* past the budget: each Newton call left still evaluates its start once, a continuation
     * halves its step down to its least (a few dozen more) */
    ck_assert_msg(r.work <= budget + budget / 10, "work %lu, budget %lu", r.work, budget);
    ck_assert_int_eq(r.stopped, 1);
    ck_assert_int_eq(st, EL_ERANGE);
    ck_assert(r.reach[1] > 0.0);   /* the lengths met, as without the budget */
    el_spline_result_free(&r);
}
END_TEST

/* A spline the search reaches well within the budget: work counted, not stopped */
START_TEST(ordinary_solve_within_budget)
{
    const double xy[] = {0, 0, 1, 0.4, 2, 0.1, 3.2, 0.8, 4, 0};
    el_spline_options o;
    el_spline_options_defaults(&o);
    for (int mode = 0; mode < 2; mode++) {
        o.mode = mode ? EL_SPLINE_LENGTH : EL_SPLINE_TENSION;
        o.length = 5.0;
        el_spline_result r;
        ck_assert_int_eq(el_spline_solve(xy, 5, &o, &r), EL_OK);
        ck_assert(r.work > 0 && r.work < 8ul * 60 * 60);
        ck_assert_int_eq(r.stopped, 0);
        el_spline_result_free(&r);
    }
}
END_TEST

/* The fuzz's slow el_spline_to_bspline input (fuzz/corpus/fuzz-spline-to-bspline-g2-huge-slow.bin,
 * 7.4 s of CPU at full speed): 14 collinear points (t, 2t) x 1e300, G2 ends, tension 42.3.
 * The solve fails (EL_ENOCONV); sigma x (longest span)^2 is inf, so the largest tension was
 * looked for, but every rung's tension sigma h^2 / h^2 (h^2 inf) is 0: ten identical solves
 * at sigma 0, each with its own budget. Now none is made (its rungs are no tensions), and
 * the result says the whole call's work. */
START_TEST(largest_makes_no_solve_where_its_rungs_are_no_tensions)
{
    double xy[28];
    for (int i = 0; i < 14; i++) {
        xy[2 * i] = 1e300 * i / 13.0;
        xy[2 * i + 1] = 2e300 * i / 13.0;
    }
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 42.307927061875333;
    o.start.kind = o.end.kind = EL_SPLINE_G2;
    o.start.tangent[0] = -0.73458457312886249;
    o.start.tangent[1] = 0.8024;
    o.start.curvature = 2.0582894636453801;
    o.end.tangent[0] = -0.35133897917143508;
    o.end.tangent[1] = 0.48482490272373546;
    o.end.curvature = -1.6614938582436865;
    double largest[3];
    int nsolves = -1;
    el__spwork work = {0, 0, 0};
    double h = 0.0;
    for (int i = 0; i < 13; i++) h = fmax(h, hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]));
    ck_assert_int_eq(el__spline_largest(xy, 14, &o, h, largest, &nsolves, &work), EL_OK);
    ck_assert_int_eq(nsolves, 0);
    ck_assert_int_eq(work.evals, 0);
    ck_assert(largest[0] == 0.0 && largest[1] == 0.0 && largest[2] == 0.0);
    el_spline_result r, r1;
    ck_assert_int_eq(el_spline_solve(xy, 14, &o, &r), EL_ENOCONV);
    ck_assert_int_eq(el__spline_solve_paths(xy, 14, &o, 1, &r1), EL_ENOCONV);
    ck_assert_int_eq(r.work, r1.work);   /* the one solve's: nothing more */
    el_spline_result_free(&r);
    el_spline_result_free(&r1);
}
END_TEST

/* Where the largest tension is looked for, its solves' work is the call's too, counted into
 * the result's work (before, work said the first solve's alone: QA16's 7 ducks with a G2
 * start at sigma 50, sigma h^2 17450, its 6 solves each with its search by length uncounted) */
START_TEST(largest_solves_counted_in_work)
{
    static const double qa16[] = {-70, 3, -85, 12, -95, 25, -98, 40, -93, 58, -80, 70, -62, 75};
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 50.0;
    o.start.kind = EL_SPLINE_G2;
    o.start.tangent[0] = -1.0;
    o.start.tangent[1] = 0.0;
    o.start.curvature = 0.0;
    o.max_iter = o.max_steps = 30;
    el_spline_result r, r1;
    ck_assert_int_eq(el_spline_solve(qa16, 7, &o, &r), EL_ENOCONV);
    ck_assert_int_eq(el__spline_solve_paths(qa16, 7, &o, 1, &r1), EL_ENOCONV);
    double largest[3];
    int nsolves = -1;
    el__spwork work = {0, 0, 0};
    double hm = 0.0;
    for (int i = 0; i < 6; i++) hm = fmax(hm, hypot(qa16[2 * i + 2] - qa16[2 * i], qa16[2 * i + 3] - qa16[2 * i + 1]));
    ck_assert_int_eq(el__spline_largest(qa16, 7, &o, hm, largest, &nsolves, &work), EL_OK);
    ck_assert(nsolves > 0 && work.evals > 0);
    ck_assert_msg(r.work == r1.work + work.evals, "work %lu, the solve %lu + the largest's %lu", r.work, r1.work,
                  work.evals);
    ck_assert(r.largest[0] == largest[0] && r.largest[0] > 0.0);
    el_spline_result_free(&r);
    el_spline_result_free(&r1);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_work");
    TCase *tc = tcase_create("spline_work");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, length_search_stops_at_its_budget);
    tcase_add_test(tc, ordinary_solve_within_budget);
    tcase_add_test(tc, largest_makes_no_solve_where_its_rungs_are_no_tensions);
    tcase_add_test(tc, largest_solves_counted_in_work);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
