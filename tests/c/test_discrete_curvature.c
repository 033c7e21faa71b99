/* el_discrete_curvature keeps its relative digits however small the step z: against
 * references computed here by other means than discrete.c's k sn(z) cn(u_i) / dn(z),
 *  - the Maclaurin series in z of K_i = a(u_i + z) - a(u_i - z) = int k cn (a' = k cn,
 *    sin a = k sn, cos a = dn: seed 000 (4.3)) from one-point Jacobi values at u_i;
 *  - at k = 1 the elementary closed form tan(K_i/2) = sinh z / cosh u_i (sn = tanh,
 *    cn = dn = sech), up to steps z where sech z underflows.
 * The difference k (sn_{i+1} dn_{i-1} - dn_{i+1} sn_{i-1}) used before lost eps / |K|
 * relative: 1.9e-7 at z = 2.4e-8, 1e-4 at z = 1e-12. */
#include "testutil.h"
#include <float.h>
#include <stdio.h>

enum { N = 1000 };

/* The largest error found, in eps x (|kappa| + 1e-3 x the curve's largest) x (1 + max(1, k)|u|):
 * a Jacobi value at u carries the rounding of its phase, max(1, k)|u| eps (the allowance of
 * test_fastpath.c), and cn(u) is exact to a few roundings of its scale, not near its zeros. */
static double worst;

static void check_kappa(const el_discrete_params *p, size_t i, double got, double ref, double scale, double tol)
{
    const double u = fabs(p->q + p->z * (double)(i + 1)) * fmax(1.0, p->k);
    const double allowed = DBL_EPSILON * (fabs(ref) + 1e-3 * scale) * (1.0 + u);
    worst = fmax(worst, fabs(got - ref) / allowed);
    ck_assert_msg(fabs(got - ref) <= tol * allowed,
                  "kappa[%zu] = %.17g, reference %.17g: %.3g relative (k=%g z=%g q=%g)", i, got, ref,
                  fabs(got - ref) / fabs(ref), p->k, p->z, p->q);
}

START_TEST(small_steps_keep_the_relative_digits)
{
    /* K = 2 k z cn + (k z^3 / 3) cn (k^2 sn^2 - dn^2) + O(z^5): (cn)'' = cn (k^2 sn^2 - dn^2);
     * the z^5 term is below 1e-20 relative here (|z| <= 1e-5) */
    const double ks[] = {0.0, 1e-8, 0.3, 0.99, 1.0, 1.01, 5.0};
    const double zs[] = {1e-12, 2.4e-8, -3e-7, 1e-6, 1e-5};
    const double qs[] = {0.0, 0.37, -2.9, 7.3};
    static double ka[N];
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++)
        for (size_t b = 0; b < sizeof zs / sizeof *zs; b++)
            for (size_t c = 0; c < sizeof qs / sizeof *qs; c++) {
                el_discrete_params p = {0.5, -1.0, 0.02, 0.3, zs[b], qs[c], ks[a]};
                ck_assert_int_eq(el_discrete_curvature(&p, N, ka), EL_OK);
                const double k = p.k, z = p.z, scale = 2.0 / p.h * k * fabs(z);
                for (size_t i = 0; i + 2 < N; i++) {
                    el_jacobi J;
                    ck_assert_int_eq(el_jacobi_eval(p.q + z * (double)(i + 1), k, &J, NULL, NULL), EL_OK);
                    const double K = 2.0 * k * z * J.cn + k * z * z * z / 3.0 * J.cn * (k * k * J.sn * J.sn - J.dn * J.dn);
                    const double ref = 2.0 / p.h * tan(K / 2.0);
                    if (k == 0.0) ck_assert(ka[i] == 0.0);
                    else check_kappa(&p, i, ka[i], ref, scale, 64.0);
                }
            }
    printf("small z: worst error %.3g of eps (|kappa| + 1e-3 max|kappa|)(1 + max(1,k)|u|)\n", worst);
    worst = 0.0;
}
END_TEST

START_TEST(separatrix_matches_its_closed_form)
{
    /* k = 1: a = gd(u), tan(K_i/2) = sinh z / cosh u_i for every z: dense to a vertex every
     * few hundred decay lengths, where sech z is 1e-261 (the last: 2 sinh z / (e^z + e^-z)) */
    const double zs[] = {1e-12, 2.4e-8, 1e-4, 0.05, -0.7, 3.0, 30.0, 600.0};
    const double qs[] = {0.0, -4.1, 1.3};
    static double ka[N];
    for (size_t b = 0; b < sizeof zs / sizeof *zs; b++)
        for (size_t c = 0; c < sizeof qs / sizeof *qs; c++) {
            const size_t n = fabs(zs[b]) > 1.0 ? 4 : N;
            el_discrete_params p = {0.0, 0.0, 0.1, -1.2, zs[b], qs[c], 1.0};
            ck_assert_int_eq(el_discrete_curvature(&p, n, ka), EL_OK);
            double scale = 0.0, ref[N];
            for (size_t i = 0; i + 2 < n; i++) {
                const double u = p.q + p.z * (double)(i + 1), z = p.z;
                ref[i] = 2.0 / p.h * (fabs(z) > 300.0 ? copysign(exp(fabs(z) - fabs(u)), z) : sinh(z) / cosh(u));
                scale = fmax(scale, fabs(ref[i]));
            }
            for (size_t i = 0; i + 2 < n; i++) check_kappa(&p, i, ka[i], ref[i], scale, 64.0);
        }
    printf("k = 1: worst error %.3g of eps (|kappa| + 1e-3 max|kappa|)(1 + |u|)\n", worst);
    worst = 0.0;
    /* past sech z's range (z > ~708) the turning angle still has its value: K = pi / 2 at a
     * vertex u_1 = z after u_0 = 0, kappa = 2 / h */
    el_discrete_params far = {0.0, 0.0, 0.1, 0.0, 720.0, 0.0, 1.0};
    ck_assert_int_eq(el_discrete_curvature(&far, 3, ka), EL_OK);
    ck_assert_close(ka[0], 2.0 / far.h, 4.0 * DBL_EPSILON * ka[0]);
}
END_TEST

/* k = 1 far along the separatrix: cn(u_i) = sech u_i underflows past |u_i| ~ 708, but with
 * a big step z the curvature (2/h) sinh z / cosh u_i = (2/h) e^(z - u) (1 - e^-2z) / (1 + e^-2u)
 * is an ordinary number (e^-40 at z = 700, u = 740): its relative digits, u and z exact
 * integers (n = 3: the one interior vertex u_1 = q + z). The ratio k sn(z) cn(u) / dn(z)
 * gave 0 there. */
START_TEST(separatrix_far_out_keeps_its_digits)
{
    const double zs[] = {30.0, 100.0, 400.0, 700.0, -700.0};
    const double us[] = {709.0, 740.0, 800.0, 1000.0, 1099.0, -760.0};
    double ka[1], worst_rel = 0.0;
    int nchecked = 0;
    for (size_t b = 0; b < sizeof zs / sizeof *zs; b++)
        for (size_t c = 0; c < sizeof us / sizeof *us; c++) {
            const double z = zs[b], u = us[c], a = fabs(z) - fabs(u);
            if (a < -700.0) continue;                        /* the curvature itself subnormal */
            el_discrete_params p = {0.0, 0.0, 0.7, 0.3, z, u - z, 1.0};
            ck_assert_int_eq(el_discrete_curvature(&p, 3, ka), EL_OK);
            const double ref = copysign(2.0 / p.h * exp(a) * -expm1(-2.0 * fabs(z)) / (1.0 + exp(-2.0 * fabs(u))), z);
            const double rel = fabs(ka[0] - ref) / fabs(ref);
            ck_assert_msg(rel <= 64.0 * DBL_EPSILON, "z %g u %g: kappa %.17g, (2/h) sinh z / cosh u %.17g", z, u,
                          ka[0], ref);
            worst_rel = fmax(worst_rel, rel);
            nchecked++;
        }
    ck_assert_int_ge(nchecked, 15);
    printf("k = 1, |u| > 708: %d vertices, worst relative error %.3g eps\n", nchecked, worst_rel / DBL_EPSILON);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("discrete_curvature");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, small_steps_keep_the_relative_digits);
    tcase_add_test(tc, separatrix_matches_its_closed_form);
    tcase_add_test(tc, separatrix_far_out_keeps_its_digits);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
