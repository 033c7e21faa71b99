/* Elastic splines (issue 14): the work one el_spline_solve CALL spends over every solve and
 * search it makes is bounded (spline.c's WORK_BUDGET: max_steps x max_iter x (16 + 64 / m)
 * evaluations of the chain of m pieces, one budget for the call) and said in the result
 * (work, stopped). */

#include "spline_check.h"
#include <float.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Evaluations a call stopped by its budget makes past it at most here: re-evaluations of a
 * known state after a search (el__chain_reeval), none of a search (measured: 1, 4, 6) */
#define PAST_BUDGET 8

/* The call's budget (spline.c's work_budget) for n points, open */
static unsigned long call_budget(const el_spline_options *o, size_t n)
{
    const unsigned long si = (unsigned long)o->max_steps * (unsigned long)o->max_iter;
    return si * 16 + si * 64 / (n - 1);
}

/* The fuzz driver's slow input (fuzz/corpus/fuzz-spline-solve-length-g2-collinear-slow.bin, 1.00 s
 * of CPU in make check's fuzz stage at eb4b739, two solves of it per input): 36 collinear
 * points (t, 2t), G2 ends (the end's curvature DBL_MAX), by length 15.458 = 6.9 x the polygon,
 * max_steps 15, max_iter 37. That curvature times the mean chord is no batten's (spline.c's
 * UNITS): EL_EDOM before any search, no work. With an end curvature of 1 no spline reaches
 * that length either: el__spline_solve_length's paths fail, then spline_bracket.c's ladder
 * and the paths again from each way of its bracket: 5794 chain evaluations (0.5 s; 9158
 * before spline_path.c's SAME_PATH ran no copy of a plain path) to say EL_ERANGE, within the
 * call's budget 15 x 37 x (16 + 64 / 35) = 9894 (cee94bf's 8 x 15 x 37 for each solve stopped
 * it at 4543). */
START_TEST(length_search_within_the_call_budget)
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
    ck_assert_int_eq(el_spline_solve(xy, 36, &o, &r), EL_EDOM);
    ck_assert(r.work == 0 && r.npieces == 0);
    o.end.curvature = 1.0;
    const int st = el_spline_solve(xy, 36, &o, &r);
    const unsigned long budget = call_budget(&o, 36);
    ck_assert_msg(r.work <= budget, "work %lu, budget %lu", r.work, budget);
    ck_assert_int_eq(r.stopped, 0);
    ck_assert_int_eq(st, EL_ERANGE);
    ck_assert(r.reach[1] > 0.0);
    el_spline_result_free(&r);
}
END_TEST

/* The fuzz's el_spline_to_bspline hang (fuzz/corpus/fuzz-spline-to-bspline-g2-tension-hang.bin,
 * 18.8 s sanitized, 9.7 s of CPU at full speed): 7 scattered points, tension 49.5, a G2 start
 * and a clamped end. No G2 batten at that tension: the search by length (spline_g2_tension.c,
 * up to NLADDER + BRENT_ITER length solves), then the largest tension's solves, each with a
 * search by length of its own: 805 120 chain evaluations at 3b81982, each solve within a
 * budget of its own. Now the whole call within one: 3600 x (16 + 64 / 6) = 96 000 (and the
 * re-evaluations past it, PAST_BUDGET), stopped said, the status EL_ENOCONV, no pieces. */
START_TEST(one_budget_for_the_whole_call)
{
    static const double xy[] = {-3.1804379339284354, 0.96238651102464345, 8.0825513084611273, 7.2494087129015021,
                                -7.4218356603341729, -1.8420038809568717e-66, 6.2831853071795862, -4.8229190508888378,
                                -2.9130998702983142, -1, 4.9406564584124654e-324, 8.9568932631418328,
                                -1.7457109983782794e-143, -6.3640802624551771};
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 49.549858854047457;
    o.start.kind = EL_SPLINE_G2;
    o.start.tangent[0] = -0.91366445410849162;
    o.start.tangent[1] = 0.99597161821927216;
    o.start.curvature = 1.2866102082856488;
    o.end.kind = EL_SPLINE_TANGENT;
    o.end.tangent[0] = 4.7414358739604783;
    o.end.tangent[1] = -0.83196765087357893;
    el_spline_result r;
    const int st = el_spline_solve(xy, 7, &o, &r);
    const unsigned long budget = call_budget(&o, 7);
    /* past it only re-evaluations of known states (el__chain_reeval), a few */
    ck_assert_msg(r.work <= budget + PAST_BUDGET, "work %lu, budget %lu", r.work, budget);
    ck_assert_int_eq(r.stopped, 1);
    ck_assert_int_eq(st, EL_ENOCONV);
    ck_assert_int_eq(r.npieces, 0);
    el_spline_result_free(&r);
}
END_TEST

/* The budget ending the free batten's (sigma 0) solve is no proof that it slides off its ducks:
 * EL_ENOCONV with stopped, not EL_EDOM (which said "give a tension > 0" for a batten the
 * defaults solve: 6 evaluations; at max_steps = max_iter = 1 the budget is 16 + 64 / 6 = 26,
 * el__spline_solve_within with budgets 1 .. 4 said EL_EDOM) */
START_TEST(budget_is_no_proof_of_sliding)
{
    static const double xy[] = {0, 0, 3, 1, 6, 0.5, 9, 2.2, 12, 1.1, 14, 3.4, 17, 2.9};
    el_spline_options o;
    el_spline_options_defaults(&o);
    el_spline_result r;
    ck_assert_int_eq(el_spline_solve(xy, 7, &o, &r), EL_OK);   /* it holds at the defaults */
    el_spline_result_free(&r);
    for (unsigned long b = 1; b < 5; b++) {
        el__spwork w = {0, b, 0};
        const int st = el__spline_solve_within(xy, 7, &o, &w, &r);
        ck_assert_msg(st == EL_ENOCONV, "budget %lu: status %d", b, st);
        ck_assert_int_eq(r.stopped, 1);
        el_spline_result_free(&r);
    }
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
        ck_assert(r.work > 0 && r.work < call_budget(&o, 5));
        ck_assert_int_eq(r.stopped, 0);
        el_spline_result_free(&r);
    }
}
END_TEST

/* The fuzz's slow el_spline_to_bspline input (fuzz/corpus/fuzz-spline-to-bspline-g2-huge-slow.bin,
 * 7.4 s of CPU at full speed): 14 collinear points (t, 2t) x 1e300, G2 ends, tension 42.3.
 * The solve failed (EL_ENOCONV); sigma x (longest span)^2 is inf, so the largest tension was
 * looked for, but every rung's tension sigma h^2 / h^2 (h^2 inf) is 0: ten identical solves
 * at sigma 0, each with its own budget. el__spline_largest makes none (its rungs are no
 * tensions); the solve is now refused before any search (spline.c's UNITS: the mean chord
 * 1.7e299 > 1e150): EL_EDOM, no work (it spent 0.7 s to say EL_ENOCONV). */
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
    el__spwork work = {0, ULONG_MAX, 0};   /* no budget */
    double h = 0.0;
    for (int i = 0; i < 13; i++) h = fmax(h, hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]));
    ck_assert_int_eq(el__spline_largest(xy, 14, &o, h, largest, &nsolves, &work), EL_OK);
    ck_assert_int_eq(nsolves, 0);
    ck_assert_int_eq(work.evals, 0);
    ck_assert(largest[0] == 0.0 && largest[1] == 0.0 && largest[2] == 0.0);
    el_spline_result r, r1;
    ck_assert_int_eq(el_spline_solve(xy, 14, &o, &r), EL_EDOM);
    ck_assert_int_eq(el__spline_solve_paths(xy, 14, &o, 1, &r1), EL_EDOM);
    ck_assert(r.work == 0 && r1.work == 0 && r.npieces == 0 && r1.npieces == 0);
    el_spline_result_free(&r);
    el_spline_result_free(&r1);
}
END_TEST

/* spline.c's UNITS: the three points (0, 0), (s, 0), (s, s) (mean chord S = s), a G2 start
 * of tangent (1, 0.2) and curvature kg where kg is finite. */
static int units_solve(double s, double sigma, double kg, int lmode, el_spline_result *r)
{
    const double xy[6] = {0, 0, s, 0, s, s};
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = sigma;
    if (lmode) {
        o.mode = EL_SPLINE_LENGTH;
        o.length = 2.2 * s;
    }
    if (isfinite(kg)) {
        o.start.kind = EL_SPLINE_G2;
        o.start.tangent[0] = 1.0;
        o.start.tangent[1] = 0.2;
        o.start.curvature = kg;
    }
    return el_spline_solve(xy, 3, &o, r);
}

/* What the spline's units (the mean chord S) cannot represent is refused before any search,
 * EL_EDOM with no work: S outside [1e-150, 1e150], sigma S^2 or a G2 end's |kappa| S above
 * 1e150 (finite but absurd: sigma 1e307, kappa 1e307). Before, each reached the searches
 * (sigma S^2 = 1e307: ~14 000 evaluations for EL_ENOCONV; S just outside: solved with forces
 * of 1e-300). Just inside the bounds each solves or fails as before (the statuses of
 * e8b1b54): S = 1e150 and 1e-150 solve, by tension and by length; sigma S^2 = 1e150 and
 * |kappa| S = 1e150 (at S = 1 and at S = 1e100) fail as they did, EL_ENOCONV. The work
 * asserted is what it must be, not a count of this build's searches: none where refused,
 * some and within the call's budget (max_steps x max_iter x (16 + 64 / m), a re-evaluation
 * or two past it) where not, and the same in the solver's units at either scale. */
START_TEST(units_outside_are_refused_before_any_search)
{
    const double no = NAN, out = 1.0000001;
    const struct { double s, sigma, kg; int lmode, st; } c[] = {
        {1e150, 0, no, 0, EL_OK},           {1e150 * out, 0, no, 0, EL_EDOM},
        {1e-150, 0, no, 0, EL_OK},          {1e-150 / out, 0, no, 0, EL_EDOM},
        {1e150, 0, no, 1, EL_OK},           {1e-150, 0, no, 1, EL_OK},
        {1e150 * out, 0, no, 1, EL_EDOM},   {1e-150 / out, 0, no, 1, EL_EDOM},
        {1, 1e150, no, 0, EL_ENOCONV},      {1, 1e150 * out, no, 0, EL_EDOM},
        {1, 1e307, no, 0, EL_EDOM},         {1e100, 1e-50 * out, no, 0, EL_EDOM},
        {1, 0, 1e150, 0, EL_ENOCONV},       {1, 0, -1e150 * out, 0, EL_EDOM},
        {1, 0, -1e150, 1, EL_ENOCONV},      {1, 0, 1e150 * out, 1, EL_EDOM},
        {1, 0, 1e307, 1, EL_EDOM},          {1e100, 0, 1e49, 0, EL_ENOCONV},
        {1e100, 0, 1e50 * out, 0, EL_EDOM},
    };
    el_spline_options d;
    el_spline_options_defaults(&d);
    const unsigned long si = (unsigned long)d.max_steps * (unsigned long)d.max_iter;
    const unsigned long budget = si * 16 + si * 64 / 2;   /* 2 pieces */
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        el_spline_result r;
        const int st = units_solve(c[i].s, c[i].sigma, c[i].kg, c[i].lmode, &r);
        const int ok = st == EL_EDOM ? r.work == 0 : r.work > 0 && r.work <= budget + 8;
        ck_assert_msg(st == c[i].st && ok, "case %zu: status %d work %lu, expected %d, %s", i, st,
                      (unsigned long)r.work, c[i].st, c[i].st == EL_EDOM ? "none" : "within the budget");
        if (st == EL_EDOM) ck_assert(r.npieces == 0 && r.pieces == NULL);
        el_spline_result_free(&r);
    }
    /* |kappa| S = 1e149 at S = 1 and at S = 1e100: one problem in the solver's units */
    el_spline_result a, b;
    const int sa = units_solve(1, 0, 1e149, 0, &a), sb = units_solve(1e100, 0, 1e49, 0, &b);
    ck_assert_msg(sa == sb && a.work == b.work, "status %d / %d, work %lu / %lu", sa, sb,
                  (unsigned long)a.work, (unsigned long)b.work);
    el_spline_result_free(&a);
    el_spline_result_free(&b);
}
END_TEST

/* spline.c's UNITS in length mode: the length over the mean chord above 1e150 is refused
 * before any search too. Five sketched points at 1e-20 asked for a length of 1e300 (L / S =
 * 1e320, inf in the solver's units) came back EL_OK with the free batten, 4.2e-20 long; just
 * inside (L / S = 1e150 at S = 1) the length search runs and says EL_ERANGE as before. */
START_TEST(a_length_beyond_the_units_is_refused)
{
    const double base[10] = {0, 0, 1, 0.3, 2, 0.1, 3, 0.5, 4, 0.2};
    const struct { double s, length; int st; } c[] = {
        {1e-20, 1e300, EL_EDOM}, {1e-150, 1e200, EL_EDOM}, {1, 1.0000001, EL_EDOM}, {1, 0.9999999, EL_ERANGE},
    };   /* at s = 1 the length in units of 1e150 x the mean chord */
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        double xy[10];
        for (int k = 0; k < 10; k++) xy[k] = base[k] * c[i].s;
        el_spline_options o;
        el_spline_options_defaults(&o);
        o.mode = EL_SPLINE_LENGTH;
        double S = 0.0;
        for (int j = 0; j < 4; j++) S += hypot(xy[2 * j + 2] - xy[2 * j], xy[2 * j + 3] - xy[2 * j + 1]) / 4.0;
        o.length = c[i].s == 1 ? c[i].length * 1e150 * S : c[i].length;
        el_spline_result r;
        const int st = el_spline_solve(xy, 5, &o, &r);
        ck_assert_msg(st == c[i].st, "case %zu: status %d (length %g), expected %d", i, st, r.length, c[i].st);
        if (st == EL_EDOM) ck_assert(r.work == 0 && r.npieces == 0 && r.pieces == NULL);
        el_spline_result_free(&r);
    }
}
END_TEST

/* Where the largest tension is looked for, its solves' work is the call's too, counted into
 * the result's work (QA16's 7 ducks with a G2 start at sigma 50, sigma h^2 17450, 30 x 30):
 * el__spline_largest's solves count on into the counter it is given (without a budget: work
 * > 0), and within el_spline_solve they share the call's budget, 900 x (16 + 64 / 6) = 24 000:
 * the first solve (its search by length) spends it, the largest's makes none (before, each
 * solve had a budget of its own: 284 995 evaluations, 3.0 s) */
START_TEST(largest_solves_share_the_call_budget)
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
    const unsigned long budget = call_budget(&o, 7);
    /* past it only re-evaluations of known states (el__chain_reeval), a few */
    ck_assert_msg(r.work <= budget + PAST_BUDGET, "work %lu, budget %lu", r.work, budget);
    ck_assert_int_eq(r.stopped, 1);
    double hm = 0.0;
    for (int i = 0; i < 6; i++) hm = fmax(hm, hypot(qa16[2 * i + 2] - qa16[2 * i], qa16[2 * i + 3] - qa16[2 * i + 1]));
    double largest[3];
    int nsolves = -1;
    el__spwork spent = {r1.work, budget, 0};   /* the call's counter after its first solve */
    ck_assert_int_eq(el__spline_largest(qa16, 7, &o, hm, largest, &nsolves, &spent), EL_OK);
    ck_assert_int_eq(nsolves, 0);
    ck_assert_int_eq(spent.evals, r1.work);
    el__spwork work = {0, ULONG_MAX, 0};   /* no budget: its solves counted */
    o.max_iter = o.max_steps = 10;
    ck_assert_int_eq(el__spline_largest(qa16, 7, &o, hm, largest, &nsolves, &work), EL_OK);
    ck_assert(nsolves > 0 && work.evals > 0);
    el_spline_result_free(&r);
    el_spline_result_free(&r1);
}
END_TEST

/* A result EL_OK where the budget ended the call is judged on its own pieces (revF 4, 5): a
 * known state reloaded after a search ("snapshot load; evaluate; EL_OK", el__chain_newton's
 * restore) is evaluated again past the budget (el__chain_reeval), else its pieces' figures
 * (Kq, energy, dkap0, Jacobians) were the last trial's and the stability check was refused.
 * QA19 W2's sharp ducks at sigma 1e-2 (test_spline_unstable.c): an unstable batten, 375
 * evaluations with no budget, the STABLE_FAMILY search after it finding no stable one; at every
 * budget b = 1 .. 375 an EL_OK result with the same pieces says what the unbounded one says
 * (before: unstable 0 at b = 27 .. 375, the check's evaluation refused), and the call goes a
 * few evaluations past b at most (6 here), re-evaluations only. */
START_TEST(a_stopped_result_is_judged_on_its_own_pieces)
{
    static const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 1e-2;
    el__spwork free_work = {0, ULONG_MAX, 0};
    el_spline_result u;
    ck_assert_int_eq(el__spline_solve_within(sharp, 5, &o, &free_work, &u), EL_OK);
    ck_assert_int_eq(u.unstable, 1);
    const unsigned long W = free_work.evals;
    int same = 0;
    for (unsigned long b = 1; b <= W; b++) {
        el__spwork w = {0, b, 0};
        el_spline_result r;
        const int st = el__spline_solve_within(sharp, 5, &o, &w, &r);
        ck_assert_msg(w.evals <= b + PAST_BUDGET, "budget %lu: %lu evaluations", b, w.evals);
        if (st == EL_OK && r.npieces == u.npieces && !memcmp(r.pieces, u.pieces, u.npieces * sizeof *u.pieces)) {
            same++;
            ck_assert_msg(r.unstable == u.unstable, "budget %lu: unstable %d, unbounded %d", b, r.unstable, u.unstable);
            ck_assert_msg(r.energy == u.energy && r.max_curvature == u.max_curvature, "budget %lu", b);
            ck_assert(!memcmp(r.forces, u.forces, 2 * u.npieces * sizeof *u.forces));
            ck_assert(!memcmp(r.curvatures, u.curvatures, u.npoints * sizeof *u.curvatures));
        }
        if (st == EL_OK || st == EL_ENOCONV || st == EL_ERANGE) el_spline_result_free(&r);
    }
    ck_assert_int_gt(same, 100);   /* the batten is reached long before the search ends */
    el_spline_result_free(&u);
}
END_TEST

/* EL_EDOM from a solve (the free batten found slides off its ducks) says its work too (revF
 * 10: it carried work 0): the sharp ducks at tension 0, a batten found and refused */
START_TEST(a_sliding_batten_says_its_work)
{
    static const double sharp[10] = {0, 0, 5, 0, 10, 0.3, 5.5, 1.2, 0.5, 1.6};
    el_spline_options o;
    el_spline_options_defaults(&o);
    el_spline_result r;
    ck_assert_int_eq(el_spline_solve(sharp, 5, &o, &r), EL_EDOM);
    ck_assert_int_eq(r.slides, 1);
    ck_assert(r.work > 0 && r.work < call_budget(&o, 5));
    ck_assert_int_eq(r.stopped, 0);
}
END_TEST

/* ring77 (closed) by the length of its fair spline at sigma h^2 = 20 (test_spline_reach.c
 * length_mode_prefers_the_fair_spline: spline_bracket.c's ways from the rungs, FAIR_RUNGS), 6751
 * evaluations unbounded: with the budget spent during the ways, each way left began with a
 * re-evaluation of its rung (from_state, narrow, el__spline_length_from): 20 past the budget at
 * b = 3499, 21 at 4159 (revA's sweep of 200 budgets); now no way begins once it is spent (7). */
START_TEST(no_way_from_a_rung_begins_past_the_budget)
{
    double h = 0.0;
    for (int i = 0; i < 12; i++) {
        const int j = (i + 1) % 12;
        h = fmax(h, hypot(ring77[2 * j] - ring77[2 * i], ring77[2 * j + 1] - ring77[2 * i + 1]));
    }
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.closed = 1;
    o.sigma = 20.0 / (h * h);
    el_spline_result t;
    ck_assert_int_eq(el_spline_solve(ring77, 12, &o, &t), EL_OK);
    el_spline_options ol;
    el_spline_options_defaults(&ol);
    ol.closed = 1;
    ol.mode = EL_SPLINE_LENGTH;
    ol.length = t.length;
    el_spline_result_free(&t);
    static const unsigned long budgets[] = {3499, 4159};
    for (int i = 0; i < 2; i++) {
        el__spwork w = {0, budgets[i], 0};
        el_spline_result r;
        const int st = el__spline_solve_within(ring77, 12, &ol, &w, &r);
        ck_assert_msg(w.evals <= budgets[i] + PAST_BUDGET, "budget %lu: %lu evaluations", budgets[i], w.evals);
        if (st == EL_OK || st == EL_ENOCONV || st == EL_ERANGE) el_spline_result_free(&r);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_work");
    TCase *tc = tcase_create("spline_work");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, length_search_within_the_call_budget);
    tcase_add_test(tc, one_budget_for_the_whole_call);
    tcase_add_test(tc, ordinary_solve_within_budget);
    tcase_add_test(tc, budget_is_no_proof_of_sliding);
    tcase_add_test(tc, largest_makes_no_solve_where_its_rungs_are_no_tensions);
    tcase_add_test(tc, largest_solves_share_the_call_budget);
    tcase_add_test(tc, a_stopped_result_is_judged_on_its_own_pieces);
    tcase_add_test(tc, a_sliding_batten_says_its_work);
    tcase_add_test(tc, no_way_from_a_rung_begins_past_the_budget);
    tcase_add_test(tc, units_outside_are_refused_before_any_search);
    tcase_add_test(tc, a_length_beyond_the_units_is_refused);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
