/* basis_min and the convex-hull flag of the seed 003 bases against dense
 * sampling (uniform, and 1e-6 apart within 0.01 of each end, where the dips of
 * m > 0.99 lie), and against the shape at the ends: h_1(1) = h_1'(1) = 0, so
 * h_1''(1) < 0 means h_1 < 0 just before t = 1. */
#include "testutil.h"
#include "internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>
#include <stdio.h>

/* The least h_i(t) over the dense grid (*tmin where), evaluated in one call. */
static double dense_min(const el_blend_basis *b, double *tmin)
{
    enum { N = 20000, E = 10000, NT = N + 1 + 2 * (E + 1) };
    static double t[NT], h[4 * NT];   /* the grid is the same for every basis */
    size_t k = 0;
    for (int part = 0; part < 3; part++) {
        const int n = part == 0 ? N : E;
        for (int j = 0; j <= n; j++)
            t[k++] = part == 0 ? (double)j / N : part == 1 ? 0.01 * j / E : 1.0 - 0.01 * j / E;
    }
    ck_assert_int_eq(el_blend_basis_eval(b, NT, t, h, NULL, NULL), EL_OK);
    double mn = HUGE_VAL;
    for (size_t j = 0; j < NT; j++)
        for (int i = 0; i < 4; i++)
            if (h[4 * j + i] < mn) { mn = h[4 * j + i]; *tmin = t[j]; }
    return mn;
}

static void check_basis(const el_blend_basis *b, const char *what)
{
    double tmin = 0.0;
    const double mn = dense_min(b, &tmin);
    /* the exact minimum is at most any sample, and not far below the dense one */
    ck_assert_msg(b->basis_min <= mn + 1e-15, "%s: basis_min %.6g above a sample %.6g (t = %.6g)",
                  what, b->basis_min, mn, tmin);
    ck_assert_msg(b->basis_min >= mn - 1e-6 * fabs(mn) - 1e-9,   /* the grid's 5e-5 steps */ "%s: basis_min %.6g, dense %.6g",
                  what, b->basis_min, mn);
    if (fabs(mn + 1e-12) > 1e-14)   /* the flag: h_i >= -1e-12 (rounding) everywhere */
        ck_assert_msg(b->convex_hull == (mn >= -1e-12), "%s: convex_hull %d, dense min %.6g",
                      what, b->convex_hull, mn);
    if (!b->convex_hull)            /* a point moves at least 1 - 2 basis_min as far */
        ck_assert_msg(b->lebesgue >= 1.0 - 2.0 * b->basis_min - 1e-13,   /* sum h_i = 1 to 1e-14 */
                      "%s: lebesgue %.17g",
                      what, b->lebesgue);
    /* the end shape: h_1''(1) < 0 is a dip below 0 next to t = 1 (at h_1''(1) = -1e-4,
     * m = 1 - 1e-5, the dip is ~ -1e-15: below that, rounding) */
    double t1 = 1.0, d2h[4];
    ck_assert_int_eq(el_blend_basis_eval(b, 1, &t1, NULL, NULL, d2h), EL_OK);
    if (d2h[1] < -1e-4) ck_assert_msg(b->basis_min < 0.0, "%s: h_1''(1) = %.3g, basis_min %.3g",
                                      what, d2h[1], b->basis_min);
}

/* m in (0, 1) up to 1 - 1e-12, d across its range (the refused K(k) = 2 band skipped) */
START_TEST(elliptic_basis_min_is_exact)
{
    const double m[] = {0.0, 0.1, 0.3, 0.5, 0.6, 0.62, 0.7, 0.9, 0.95, 0.98, 0.99, 0.995, 0.999,
                        1 - 1e-4, 1 - 1e-5, 1 - 1e-6, 1 - 1e-8, 1 - 1e-10, 1 - 1e-12};
    const double d[] = {0.05, 0.5, 1.0, 2.0, 3.0, 10.0, 100.0};
    const int im = _i / (int)(sizeof d / sizeof *d), id = _i % (int)(sizeof d / sizeof *d);
    el_blend_basis b;
    int st = el_blend_init_elliptic(&b, sqrt(m[im]), d[id]);
    if (st == EL_ESINGULAR) return;
    ck_assert_int_eq(st, EL_OK);
    char what[64];
    snprintf(what, sizeof what, "m = %.13g, d = %g", m[im], d[id]);
    check_basis(&b, what);
}
END_TEST

/* the QA figures: m = 0.99, 0.995, 0.999 with d = 2 dip to -1.05e-6, -1.4e-7, -1.4e-9 */
START_TEST(near_one_dips_are_reported)
{
    const double m[] = {0.99, 0.995, 0.999}, want[] = {-1.054e-6, -1.428e-7, -1.375e-9};
    for (int i = 0; i < 3; i++) {
        el_blend_basis b;
        ck_assert_int_eq(el_blend_init_elliptic(&b, sqrt(m[i]), 2.0), EL_OK);
        ck_assert_int_eq(b.convex_hull, 0);
        ck_assert_close(b.basis_min, want[i], 1e-3 * fabs(want[i]));
        ck_assert(b.lebesgue > 1.0);
    }
}
END_TEST

START_TEST(mq_basis_min_is_exact)
{
    const double c[] = {0.05, 0.3, 1.0, 3.0, -1.0}, d[] = {0.2, 1.0, 3.0, 20.0};
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 4; j++) {
            el_blend_basis b;
            ck_assert_int_eq(el_blend_init_mq(&b, c[i], d[j]), EL_OK);
            char what[64];
            snprintf(what, sizeof what, "MQ c = %g, d = %g", c[i], d[j]);
            check_basis(&b, what);
        }
}
END_TEST

/* GSL's sn(u; m) (quiet: the test's own status check). */
static double sn_gsl(double u, double m)
{
    double sn, cn, dn;
    ck_assert_int_eq(gsl_sf_elljac_e(u, m, &sn, &cn, &dn), GSL_SUCCESS);
    return sn;
}

/*
 * The identity the elliptic branch and bound rests on: sn'' = -S(sn) with
 * S(s) = (1 + m) s - 2 m s^3 (el__blend_sn_S), checked against GSL's sn by central
 * second differences (Richardson over steps 0.02 and 0.01: measured <= 5.9e-9, from its h^4 term) for m from
 * 1e-14 to 1 - 1e-12 and u across a period [0, 4K]; and blend.c's f_2'' against
 * -K^2 S(f_2) at t across [0, 1], the two files' forms of it agreeing to rounding.
 */
START_TEST(sn_second_derivative_identity)
{
    const double m[] = {1e-14, 1e-8, 1e-3, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1 - 1e-6, 1 - 1e-9, 1 - 1e-12};
    for (size_t i = 0; i < sizeof m / sizeof *m; i++) {
        const double K = gsl_sf_ellint_Kcomp(sqrt(m[i]), GSL_PREC_DOUBLE);
        enum { NU = 400 };
        for (int j = 0; j <= NU; j++) {
            const double u = 4.0 * K * j / NU, s = sn_gsl(u, m[i]);
            double D[2];
            for (int r = 0; r < 2; r++) {
                const double h = r ? 0.01 : 0.02;
                D[r] = (sn_gsl(u + h, m[i]) - 2.0 * s + sn_gsl(u - h, m[i])) / (h * h);
            }
            const double fd = (4.0 * D[1] - D[0]) / 3.0, err = fabs(fd + el__blend_sn_S(m[i], s));
            ck_assert_msg(err <= 1e-8, "m = %.13g u = %g: sn'' %.12g, -S(sn) %.12g", m[i], u, fd,
                          -el__blend_sn_S(m[i], s));
        }
        el_blend_basis b;
        if (el_blend_init_elliptic(&b, sqrt(m[i]), 1.0) != EL_OK) continue;
        for (int j = 0; j <= 100; j++) {
            double f[4], df[4], d2f[4];
            ck_assert_int_eq(el__blend_span_at(&b, j / 100.0, f, df, d2f), EL_OK);
            const double want = -b.K * b.K * el__blend_sn_S(b.k * b.k, f[2]);
            ck_assert_msg(fabs(d2f[2] - want) <= 1e-13 * b.K * b.K, "m = %.13g t = %g: f_2'' %.17g, "
                          "-K^2 S(f_2) %.17g", m[i], j / 100.0, d2f[2], want);
        }
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("blend_hull");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_loop_test(tc, elliptic_basis_min_is_exact, 0, 19 * 7);
    tcase_add_test(tc, near_one_dips_are_reported);
    tcase_add_test(tc, mq_basis_min_is_exact);
    tcase_add_test(tc, sn_second_derivative_identity);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
