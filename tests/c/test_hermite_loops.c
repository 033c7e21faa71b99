/* Hermite solutions between tangents along the chord (t0 = t1 along p1 - p0) at high tension:
 * besides the straight segment, a loop turning once counter-clockwise and its mirror image in
 * the chord, clockwise. Each is one curvature period of a non-inflectional elastica whose k - 1
 * lies far below double precision (~e^-(sqrt(mu) L)): the separatrix k = +-1 in double, kappa =
 * 2 sqrt(mu) sech(sqrt(mu) s + q), sqrt(mu) = sqrt(sigma / 2), its length beyond the chord
 * 4 / sqrt(mu) and its energy 8 sqrt(mu) (integrals of sech^2), returned as a chain. The
 * symmetric problem's solution set is closed under the chord's mirror (hermite_symmetry.c),
 * but the mirror image of such a chain was taken for the chain itself
 * (el__hermite_same_solution compared the turning of the first pieces only, and a chain's first
 * piece ends before its loop): tangents (cos -2.5, sin -2.5) at sigma |p1 - p0|^2 = 5000, the
 * ccw loop alone. Every curve checked by hermite_check.h. */
#include "testutil.h"
#include "hermite_check.h"
#include <stdio.h>

START_TEST(a_loops_mirror_image_is_kept_beside_it)
{
    const double scale[] = {1.0, 0.1, 1e4};
    for (size_t c = 0; c < sizeof scale / sizeof scale[0]; c++) {
        const double d = scale[c], sd2 = 5000.0, t[2] = {cos(-2.5), sin(-2.5)};
        const double p0[2] = {0.0, 0.0}, p1[2] = {d * t[0], d * t[1]};
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = sd2 / (d * d);
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t, p1, t, &o, &r), EL_OK);
        check_result(p0, t, p1, t, &r, o.tol);
        const double rm = sqrt(0.5 * sd2);   /* sqrt(mu) |p1 - p0| */
        int ccw = 0, cw = 0, chains = 0;
        for (size_t j = 0; j < r.count; j++) {
            const el_hermite_solution *s = &r.solutions[j];
            if (s->energy * d < 1e-6) continue;   /* the segment */
            ck_assert_msg(fabs(s->length / d - (1.0 + 4.0 / rm)) <= 1e-9 &&
                          fabs(s->energy * d - 8.0 * rm) <= 1e-9 * 8.0 * rm,
                          "scale %g: L %.12g E %.12g, the loop's %.12g %.12g", d, s->length / d,
                          s->energy * d, 1.0 + 4.0 / rm, 8.0 * rm);
            if (s->curve.k > 0.0) ccw++; else cw++;
            chains += s->npieces > 1;
        }
        ck_assert_msg(ccw == 1 && cw == 1 && r.count == 3, "scale %g: %zu solutions, %d ccw, %d cw loops", d,
                      r.count, ccw, cw);
        ck_assert_int_eq(chains, 2);
        el_hermite_result_free(&r);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite_loops");
    TCase *tc = tcase_create("hermite_loops");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, a_loops_mirror_image_is_kept_beside_it);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
