/* The Hermite solver's fast paths against their plain counterparts, over the whole
 * range (random data in every direction, tensions from -50 to 1e5 on a log scale,
 * nearly degenerate data: P2 next to the case-1 threshold, V1 = 0):
 * - the branch of a root of (40) formed directly (hermite_poly.c) against the choice
 *   by el__hermite_curvdata's states on both branches: the same branch at the roots
 *   of (40), at the roots of (18) (where the branches meet) and anywhere in [-B, B]. */
#include "testutil.h"
#include "hermite_internal.h"
#include <stdio.h>

#define require(cond, ...) do { if (!(cond)) ck_abort_msg(__VA_ARGS__); } while (0)

/* A case-1 problem: P, V unit vectors from the angles a, b. */
static hprob problem(double a, double b, double sigma)
{
    hprob pr;
    pr.P1 = cos(a);
    pr.P2 = sin(a);
    pr.V1 = cos(b);
    pr.V2 = sin(b);
    pr.sigma = sigma;
    pr.Lmin = 1.0;
    el__hermite_set_case(&pr);
    return pr;
}

static void branch_matches(const hprob *pr, double x, int *checked)
{
    const int fast = el__hermite_root_branch(pr, x), plain = el__hermite_root_branch_plain(pr, x);
    require(fast == plain, "branch at x = %.17g: %d, plain %d (P %.17g %.17g V %.17g %.17g sigma %.17g)",
            x, fast, plain, pr->P1, pr->P2, pr->V1, pr->V2, pr->sigma);
    ++*checked;
}

START_TEST(root_branch_matches_curvdata_states)
{
    unsigned long long st = 0x40b7a9ULL;
    int checked = 0, at_roots = 0;
    for (int t = 0; t < 6000; t++) {
        double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        /* nearly degenerate data: P2 just above the case-1 threshold, V1 = 0 exactly */
        if (t % 10 == 1) a = (t % 20 == 1 ? 1.0 : -1.0) * 2e-13;
        const int band = t % 4;
        const double sigma = band == 0 ? test_uniform(&st, -50.0, 50.0)
                             : band == 1 ? exp(test_uniform(&st, log(1e-10), log(1e5)))
                             : band == 2 ? -exp(test_uniform(&st, log(1e-10), log(50.0)))
                                         : exp(test_uniform(&st, log(100.0), log(1e5)));
        hprob pr = problem(a, b, sigma);
        if (t % 10 == 2) { pr.V1 = 0.0; pr.V2 = b > 0.0 ? 1.0 : -1.0; }
        if (pr.hcase != 1) continue;
        double B;
        ck_assert_int_eq(el__hermite_kappa_bound(pr.sigma, pr.Lmin, &B), EL_OK);
        if (!(B > 0.0)) continue;
        pr.B = B;
        double r[16];
        int nr = 0;
        if (pr.sigma > 0.0) {
            el__hermite_poly40_roots(&pr, r, &nr);
            for (int i = 0; i < nr; i++) branch_matches(&pr, r[i], &at_roots);
        }
        double c[3];
        el__hermite_disc_coeffs(&pr, c);
        if (el__poly_real_roots(c, 2, r, &nr) == EL_OK)
            for (int i = 0; i < nr; i++) {
                branch_matches(&pr, r[i], &checked);
                branch_matches(&pr, nextafter(r[i], INFINITY), &checked);
                branch_matches(&pr, nextafter(r[i], -INFINITY), &checked);
            }
        for (int i = 0; i < 8; i++) branch_matches(&pr, test_uniform(&st, -B, B), &checked);
    }
    printf("root branch: %d points at roots of (40), %d others\n", at_roots, checked);
    ck_assert_int_gt(at_roots, 3000);
    ck_assert_int_gt(checked, 20000);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite_fast");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, root_branch_matches_curvdata_states);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
