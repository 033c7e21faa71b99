/* Core: Jacobi functions, smooth and discrete elastica — each formula checked by
 * its defining identity, references from mpmath, gradients by finite differences. */
#define _POSIX_C_SOURCE 200112L /* pthreads */
#include "testutil.h"
#include "internal.h"
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_elljac.h>
#include <stdint.h>
#include <pthread.h>
#include <stdio.h>
#include <string.h>

/* ------------------------------------------------------------ jacobi */

START_TEST(jacobi_matches_mpmath_table)
{
    FILE *f = fopen("../data/jacobi_ref.csv", "r");
    ck_assert_msg(f != NULL, "tests/data/jacobi_ref.csv missing");
    char line[512];
    ck_assert(fgets(line, sizeof line, f) != NULL); /* header */
    int rows = 0;
    double worst = 0.0;
    while (fgets(line, sizeof line, f)) {
        double k, u, ref[5];
        ck_assert_int_eq(sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf", &k, &u,
                                &ref[0], &ref[1], &ref[2], &ref[3], &ref[4]), 7);
        el_jacobi v;
        ck_assert_int_eq(el_jacobi_eval(u, k, &v, NULL, NULL), EL_OK);
        const double got[5] = {v.sn, v.cn, v.dn, v.am, v.E};
        for (int j = 0; j < 5; j++) {
            double err = fabs(got[j] - ref[j]);
            if (err > worst) worst = err;
            ck_assert_msg(err <= 1e-13, "k=%.17g u=%g field %d: %.17g vs %.17g (err %.3g)",
                          k, u, j, got[j], ref[j], err);
        }
        /* E = u - k^2 D by definition of D */
        ck_assert_close(v.E, u - k * k * v.D, 1e-12 * (1.0 + fabs(u)));
        rows++;
    }
    fclose(f);
    ck_assert_int_ge(rows, 100);
    printf("jacobi: %d reference rows x 5 fields, worst abs error %.2e\n", rows, worst);
}
END_TEST

static double field(const el_jacobi *v, int j)
{
    const double a[6] = {v->sn, v->cn, v->dn, v->am, v->E, v->D};
    return a[j];
}

START_TEST(jacobi_derivatives_match_finite_differences)
{
    const double ks[] = {0.0, 1e-8, 0.05, 0.3, 0.9, 0.99, 1.0, 1.01, 1.5, 2.0, 50.0};
    const double us[] = {-23.1, -3.3, -0.4, 0.0, 0.7, 2.9, 11.2, 37.0};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++)
        for (size_t b = 0; b < sizeof us / sizeof *us; b++) {
            const double k = ks[a], u = us[b];
            el_jacobi v, du, dk, p, m;
            ck_assert_int_eq(el_jacobi_eval(u, k, &v, &du, &dk), EL_OK);
            const double hu = 1e-6;
            el_jacobi_eval(u + hu, k, &p, NULL, NULL);
            el_jacobi_eval(u - hu, k, &m, NULL, NULL);
            for (int j = 0; j < 6; j++) {
                double fd = (field(&p, j) - field(&m, j)) / (2 * hu);
                double an = field(&du, j);
                ck_assert_msg(fabs(fd - an) <= 1e-6 * fmax(1.0, fabs(an)),
                              "d/du field %d at k=%g u=%g: %.12g vs fd %.12g", j, k, u, an, fd);
            }
            if (k < 1e-3) continue; /* the k-step would cross k = 0 */
            /* at k = 1, d^2/dk^2 ~ e^(2|u|): central differences only hold for small |u|
             * (larger u: jacobi_near_k_equal_1_keeps_relative_digits, against mpmath) */
            if (k == 1.0 && fabs(u) > 4.0) continue;
            const double hk = 1e-7 * k;
            el_jacobi_eval(u, k + hk, &p, NULL, NULL);
            el_jacobi_eval(u, k - hk, &m, NULL, NULL);
            for (int j = 0; j < 6; j++) {
                double fd = (field(&p, j) - field(&m, j)) / (2 * hk);
                double an = field(&dk, j);
                ck_assert_msg(fabs(fd - an) <= 2e-6 * fmax(1.0, fabs(an)),
                              "d/dk field %d at k=%g u=%g: %.12g vs fd %.12g", j, k, u, an, fd);
            }
        }
}
END_TEST

START_TEST(jacobi_small_k_derivative_is_analytic)
{
    /* at tiny k, d sn/dk -> 0 and dD/dk = O(k): compare with the O(k) series
     * of sn(u,k) = sin u - (k^2/4)(u - sin u cos u) cos u + O(k^4) */
    const double k = 1e-8, u = 2.0;
    el_jacobi v, dk;
    ck_assert_int_eq(el_jacobi_eval(u, k, &v, NULL, &dk), EL_OK);
    double expect = -(k / 2.0) * (u - sin(u) * cos(u)) * cos(u);
    ck_assert_close(dk.sn, expect, 1e-20);
}
END_TEST

START_TEST(jacobi_rejects_bad_input)
{
    el_jacobi v = {1, 2, 3, 4, 5, 6};
    ck_assert_int_eq(el_jacobi_eval(1.0, -0.1, &v, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_jacobi_eval(NAN, 0.5, &v, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_jacobi_eval(1.0, INFINITY, &v, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_jacobi_eval(1.0, 0.5, NULL, NULL, NULL), EL_EINVAL);
    ck_assert(v.sn == 1 && v.D == 6); /* untouched */
    ck_assert_str_ne(el_strerror(EL_EINVAL), el_strerror(EL_OK));
    ck_assert_ptr_nonnull(el_strerror(12345));
}
END_TEST

/* The AGM with Bulirsch's division-only backward recurrence (jacobi.c) against GSL's
 * gsl_sf_elljac_e (the textbook recurrence, an asin and a sin per level) over the whole
 * range: k from 0 to 1 - 1e-4 (GSL forms 1 - k^2 itself, so k nearer 1 is left to
 * jacobi_near_k_equal_1_keeps_relative_digits), u from 1e-300 to 60 and both signs (the
 * Maclaurin branch below 1e-9, the reduction to |u| <= 1 and the doublings above):
 * sn, cn, dn within 64 eps of GSL plus what a phase error of a few |u| eps moves them by
 * (GSL's own: |u| eps times the slopes cn dn, sn dn, k^2 sn cn). */
START_TEST(jacobi_matches_gsl_elljac_over_the_range)
{
    unsigned long long st = 9091;
    int n = 0;
    double worst = 0.0;
    for (int t = 0; t < 20000; t++) {
        const double k = t % 4 == 0 ? pow(10.0, -test_uniform(&st, 0.0, 8.0)) :
                         t % 4 == 1 ? 1.0 - pow(10.0, -test_uniform(&st, 0.0, 4.0)) : test_uniform(&st, 0.0, 1.0);
        const double mag = t % 3 == 0 ? pow(10.0, -test_uniform(&st, 9.0, 300.0)) :
                           t % 3 == 1 ? pow(10.0, -test_uniform(&st, 0.0, 9.0)) : test_uniform(&st, 0.0, 60.0);
        const double u = test_uniform(&st, 0.0, 1.0) < 0.5 ? -mag : mag;
        double sn, cn, dn;
        if (gsl_sf_elljac_e(u, k * k, &sn, &cn, &dn) != GSL_SUCCESS) continue;
        el_jacobi v;
        ck_assert_int_eq(el_jacobi_eval(u, k, &v, NULL, NULL), EL_OK);
        const double got[3] = {v.sn, v.cn, v.dn}, ref[3] = {sn, cn, dn};
        const double slope[3] = {fabs(cn * dn), fabs(sn * dn), k * k * fabs(sn * cn)};
        for (int j = 0; j < 3; j++) {
            const double err = fabs(got[j] - ref[j]) / (fabs(ref[j]) + 16.0 * fabs(u) * slope[j] + 1e-300);
            worst = fmax(worst, err);
            ck_assert_msg(err <= 64.0 * DBL_EPSILON, "k=%.17g u=%.17g field %d: %.17g vs GSL %.17g (relative %.3g)", k,
                          u, j, got[j], ref[j], err);
        }
        n++;
    }
    ck_assert_int_gt(n, 19000);
    printf("jacobi against gsl_sf_elljac_e: %d points, worst relative error %.2e\n", n, worst);
}
END_TEST

START_TEST(jacobi_near_k_equal_1_keeps_relative_digits)
{
    /* |k| within 1e-4 .. 1e-15 of 1, u across the plateau sn ~ 1 where cn, dn ~ 2 e^-u are
     * tiny: cn and dn to relative accuracy (the AGM alone lost 4e-10 there, and
     * rounding 1/k for k > 1 another 2e-13 of cn: issue 12's 7e-10 L differences), D
     * and the k-derivatives of cn and D (dD/dk by L - sn^2 J cancelled to 1e-3 at k = 1,
     * u = 15) against mpmath (tests/data/gen_jacobi_near1_ref.py) */
    FILE *f = fopen("../data/jacobi_near1_ref.csv", "r");
    ck_assert_msg(f != NULL, "tests/data/jacobi_near1_ref.csv missing");
    char line[1024];
    ck_assert(fgets(line, sizeof line, f) != NULL);
    int rows = 0;
    double worst = 0.0;
    while (fgets(line, sizeof line, f)) {
        double k, u, ref[6];
        ck_assert_int_eq(sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &k, &u, &ref[0], &ref[1], &ref[2], &ref[3],
                                &ref[4], &ref[5]), 8);
        el_jacobi v, dk;
        ck_assert_int_eq(el_jacobi_eval(u, k, &v, NULL, &dk), EL_OK);
        const double got[6] = {v.sn, v.cn, v.dn, v.D, dk.cn, dk.D};
        /* relative to the value plus what the phase's own rounding, a few |u| eps, moves
         * it by (the slopes d/du from the reference: cn dn, -sn dn, -k^2 sn cn, sn^2;
         * for the derivatives, their size: near the turning point K they grow like the
         * period's sensitivity u dK/dk) */
        const double sn = ref[0], cn = ref[1], dn = ref[2];
        const double slope[6] = {fabs(cn * dn), fabs(sn * dn), k * k * fabs(sn * cn), sn * sn,
                                 fabs(ref[4]) + fabs(ref[5]), fabs(ref[4]) + fabs(ref[5])};
        for (int j = 0; j < 6; j++) {
            const double err = fabs(got[j] - ref[j]) / (fabs(ref[j]) + fabs(u) * slope[j] + 1e-300);
            worst = fmax(worst, err);
            ck_assert_msg(err <= 64.0 * DBL_EPSILON, "k=%.17g u=%g field %d: %.17g vs %.17g (relative %.3g)", k, u, j,
                          got[j], ref[j], err);
        }
        rows++;
    }
    fclose(f);
    ck_assert_int_ge(rows, 50);
    printf("jacobi near k = 1: %d rows x 6 fields, worst relative error %.2e\n", rows, worst);
}
END_TEST

START_TEST(jacobi_k_equal_1_derivatives_are_finite_until_they_overflow)
{
    /* at k = 1 the k-derivatives have closed forms (A&S 16.15 to first order in k'^2);
     * they grow like e^u / 4 and overflow only past u ~ 710 (J underflowed at 350 before) */
    const double us[] = {0.5, 20.0, 100.0, 400.0, 700.0, -650.0};
    for (size_t i = 0; i < sizeof us / sizeof *us; i++) {
        const double u = us[i], th = tanh(u);
        el_jacobi v, dk;
        ck_assert_int_eq(el_jacobi_eval(u, 1.0, &v, NULL, &dk), EL_OK);
        ck_assert_close(dk.sn, -0.5 * (th - u / (cosh(u) * cosh(u))), 1e-15);
        ck_assert_close(dk.D, -1.5 * (u - th) + 0.5 * u * th * th, 1e-14 * fabs(u));
        ck_assert(isfinite(dk.cn) && isfinite(dk.dn) && isfinite(dk.am) && isfinite(dk.E));
        ck_assert_close(v.E, th, 1e-16); /* E = tanh u, not u - D with its cancellation */
    }
    el_jacobi v = {1, 2, 3, 4, 5, 6}, dk = v;
    ck_assert_int_eq(el_jacobi_eval(720.0, 1.0, &v, NULL, &dk), EL_EDOM);
    ck_assert(v.sn == 1 && dk.D == 6); /* untouched */
    ck_assert_int_eq(el_jacobi_eval(1e300, 1.0, &v, NULL, NULL), EL_OK); /* no period at k = 1 */
    ck_assert(v.sn == 1.0 && v.cn == 0.0 && v.E == 1.0);
}
END_TEST

START_TEST(jacobi_reports_lost_phase_and_overflow_as_edom)
{
    /* max(1, k)|u| > 2^50: the period is known to a rounding, the phase to nothing */
    el_jacobi v = {1, 2, 3, 4, 5, 6}, d = v;
    ck_assert_int_eq(el_jacobi_eval(1e16, 0.5, &v, NULL, NULL), EL_EDOM);
    ck_assert_int_eq(el_jacobi_eval(4e14, 3.0, &v, &d, NULL), EL_EDOM);
    ck_assert_int_eq(el_jacobi_eval(1.0, 1e200, &v, NULL, &d), EL_EDOM);
    ck_assert(v.sn == 1 && d.D == 6);
    ck_assert_int_eq(el_jacobi_eval(1e15, 0.5, &v, NULL, NULL), EL_OK); /* 2^50 > 1e15 */
    /* huge k with a small enough u: values finite, no EL_EINTERNAL (k'^2 = (k-1)(k+1)/k^2
     * overflowed past k = 1e154); the k-derivatives need k^2 and report EL_EDOM */
    ck_assert_int_eq(el_jacobi_eval(1e-300, 1e300, &v, NULL, NULL), EL_OK);
    ck_assert(isfinite(v.sn) && isfinite(v.D) && fabs(v.sn - sin(1.0) * 1e-300) <= 1e-315);
    ck_assert_int_eq(el_jacobi_eval(1e-300, 1e300, &v, NULL, &d), EL_EDOM);
    /* denormal arguments and moduli */
    ck_assert_int_eq(el_jacobi_eval(4.9e-324, 0.5, &v, &d, &d), EL_OK);
    ck_assert(v.sn == 4.9e-324 && v.cn == 1.0);
    ck_assert_int_eq(el_jacobi_eval(1.0, 4.9e-324, &v, NULL, &d), EL_OK);
    ck_assert_close(v.sn, sin(1.0), 2e-16);
}
END_TEST

START_TEST(walk_offset_series_are_the_maclaurin_series)
{
    /* the coefficients from the differential equations' recurrence (jacobi_walk.c)
     * against the known polynomials in m = k^2 (DLMF 22.10.1-3), and D = int sn^2 */
    const double ks[] = {0.0, 0.6, 1.0, 3.0};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        const double k = ks[a], m = k * k;
        el__walk wk;
        ck_assert_int_eq(el__walk_init(&wk, k, 1, 100), EL_OK);
        double u[3] = {0.0, 1e-3 / wk.kappa, 0.0};
        el_jacobi val[3], dk[3];
        ck_assert_int_eq(el__walk_values(&wk, 3, u, val, dk), EL_OK); /* an offset from an anchor */
        ck_assert(wk.have_series);
        const double sn[5] = {1, -(1 + m) / 6, (1 + 14 * m + m * m) / 120, -(1 + 135 * m + 135 * m * m + m * m * m) / 5040,
                              (1 + 1228 * m + 5478 * m * m + 1228 * m * m * m + m * m * m * m) / 362880};
        const double cn[4] = {1, -0.5, (1 + 4 * m) / 24, -(1 + 44 * m + 16 * m * m) / 720};
        const double dn[4] = {1, -m / 2, m * (4 + m) / 24, -m * (16 + 44 * m + m * m) / 720};
        const double D[2] = {1.0 / 3.0, -(1 + m) / 15};
        for (int j = 0; j < 5; j++) ck_assert_close(wk.ser[0][j], sn[j], 1e-15 * fabs(sn[j]) + 1e-300);
        for (int j = 0; j < 4; j++) {
            ck_assert_close(wk.ser[1][j], cn[j], 1e-15 * fabs(cn[j]));
            ck_assert_close(wk.ser[2][j], dn[j], 1e-15 * fabs(dn[j]));
        }
        for (int j = 0; j < 2; j++) ck_assert_close(wk.ser[3][j], D[j], 1e-15 * fabs(D[j]));
        /* k-derivatives: d/dk of the same polynomials */
        ck_assert_close(wk.ser[4][1], -k / 3.0, 1e-16);
        ck_assert_close(wk.ser[5][2], k / 3.0, 1e-16);
        ck_assert_close(wk.ser[6][1], -k, 1e-16);
        ck_assert_close(wk.ser[7][1], -2.0 * k / 15.0, 1e-16);
    }
    /* the truncation bound: at k = 1 the coefficients are those of tanh, sech and
     * u - tanh, whose absolute values (tan, sec, tan - u) bound every |k| <= 1 and, in
     * x = max(1, k)|u|, every k > 1; the k-derivative of a degree-d polynomial in k^2 adds
     * a factor 2d <= 12. Their tails at x = 1/32 past u^9 (sn, D) and u^10 (cn, dn),
     * from the next three Maclaurin coefficients of tan and sec (the rest is a geometric
     * series of ratio (2x/pi)^2), are far below a rounding of the O(1) sums they enter */
    const double x = 1.0 / 32.0, geo = 1.0 / (1.0 - 4.0 * x * x / (M_PI * M_PI));
    const double tan_tail = (1382.0 / 155925.0 * pow(x, 11) + 21844.0 / 6081075.0 * pow(x, 13) +
                             929569.0 / 638512875.0 * pow(x, 15)) * geo;
    const double sec_tail = (2702765.0 / 479001600.0 * pow(x, 12) + 199360981.0 / 87178291200.0 * pow(x, 14) +
                             19391512145.0 / 20922789888000.0 * pow(x, 16)) * geo;
    ck_assert(tan_tail < 0x1p-61 && sec_tail < 0x1p-66);
    ck_assert(12.0 * tan_tail < 0x1p-58 && 12.0 * sec_tail < 0x1p-63);
}
END_TEST

/* ------------------------------------------------------------ smooth */

static el_smooth_params smooth(double k)
{
    el_smooth_params p = {0.3, -1.2, 0.7, 1.9, k, 0.45, 6.0};
    return p;
}

START_TEST(smooth_unit_speed_and_curvature)
{
    const double ks[] = {0.0, 0.4, 0.95, 1.0, 1.05, 2.5, 30.0};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_smooth_params p = smooth(ks[a]);
        enum { N = 200 };
        const double h = 1e-4;
        double s[3 * N], xy[6 * N], th[3 * N], ka[3 * N];
        for (int i = 0; i < N; i++) {
            double si = p.length * (i + 0.5) / N;
            s[3 * i] = si - h; s[3 * i + 1] = si; s[3 * i + 2] = si + h;
        }
        ck_assert_int_eq(el_smooth_eval(&p, 3 * N, s, xy, th, ka), EL_OK);
        for (int i = 0; i < N; i++) {
            const double *a0 = xy + 6 * i, *a2 = a0 + 4;
            double speed = hypot(a2[0] - a0[0], a2[1] - a0[1]) / (2 * h);
            double kfd = (th[3 * i + 2] - th[3 * i]) / (2 * h), kap = ka[3 * i + 1];
            ck_assert_msg(fabs(speed - 1.0) <= 1e-7 * (1 + kap * kap), "|gamma'| = %.12g at k=%g", speed, p.k);
            ck_assert_msg(fabs(kfd - kap) <= 1e-6 * (1 + fabs(kap) * kap * kap), "theta' %.12g vs kappa %.12g at k=%g",
                          kfd, kap, p.k);
            /* the tangent of the points is (cos theta, sin theta) */
            double ang = atan2(a2[1] - a0[1], a2[0] - a0[0]) - th[3 * i + 1];
            ck_assert_msg(fabs(remainder(ang, 2 * M_PI)) <= 1e-6 * (1 + kap * kap), "tangent angle off by %g", ang);
        }
    }
}
END_TEST

START_TEST(smooth_curvature_satisfies_elastica_equation)
{
    /* kappa'' + kappa^3/2 - lambda kappa = 0 with ONE lambda per curve, fitted by least squares */
    const double ks[] = {0.3, 0.8, 1.0, 1.3, 4.0};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_smooth_params p = smooth(ks[a]);
        enum { N = 300 };
        const double h = 1e-3;
        double s[3 * N], ka[3 * N], r[N], kk[N];
        for (int i = 0; i < N; i++) {
            double si = 0.1 + 5.8 * i / (N - 1.0);
            s[3 * i] = si - h; s[3 * i + 1] = si; s[3 * i + 2] = si + h;
        }
        ck_assert_int_eq(el_smooth_eval(&p, 3 * N, s, NULL, NULL, ka), EL_OK);
        double num = 0, den = 0, scale = 0;
        for (int i = 0; i < N; i++) {
            double k0 = ka[3 * i + 1], kpp = (ka[3 * i + 2] - 2 * k0 + ka[3 * i]) / (h * h);
            r[i] = kpp + 0.5 * k0 * k0 * k0; /* = lambda kappa */
            kk[i] = k0;
            num += r[i] * k0; den += k0 * k0;
            scale = fmax(scale, fabs(k0 * k0 * k0));
        }
        double lambda = num / den;
        for (int i = 0; i < N; i++)
            ck_assert_msg(fabs(r[i] - lambda * kk[i]) <= 1e-5 * scale, "k=%g residual %.3g (scale %.3g)",
                          p.k, r[i] - lambda * kk[i], scale);
        /* and lambda is the closed form mu (2k^2 - 1) of seed 000 (2.23) */
        ck_assert_close(lambda, p.mu * (2 * p.k * p.k - 1), 1e-5 * (1 + fabs(lambda)));
    }
}
END_TEST

START_TEST(smooth_points_continuous_across_k_equal_1)
{
    /* both one-sided differences shrink linearly with |k - 1|: continuity (with a finite
     * derivative) across the separatrix, the two families meeting in one formula */
    enum { N = 50 };
    double s[N], one_xy[2 * N], xy[2 * N];
    for (int i = 0; i < N; i++) s[i] = 6.0 * i / (N - 1.0);
    el_smooth_params one = smooth(1.0);
    ck_assert_int_eq(el_smooth_eval(&one, N, s, one_xy, NULL, NULL), EL_OK);
    for (int side = -1; side <= 1; side += 2) {
        double prev = 0;
        for (int e = 6; e <= 12; e += 2) {
            el_smooth_params p = smooth(1.0 + side * pow(10.0, -e));
            ck_assert_int_eq(el_smooth_eval(&p, N, s, xy, NULL, NULL), EL_OK);
            double d = 0;
            for (int i = 0; i < 2 * N; i++) d = fmax(d, fabs(xy[i] - one_xy[i]));
            if (e > 6) ck_assert_msg(d < prev / 30, "side %d 1e-%d: %.3g after %.3g", side, e, d, prev);
            prev = d;
        }
        ck_assert_msg(prev < 1e-8, "difference at |k-1| = 1e-12 is %.3g", prev);
    }
}
END_TEST

START_TEST(smooth_energy_matches_quadrature)
{
    const double ks[] = {0.0, 0.5, 1.0, 1.7};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_smooth_params p = smooth(ks[a]);
        enum { N = 4001 };
        static double s[N], ka[N];
        for (int i = 0; i < N; i++) s[i] = p.length * i / (N - 1.0);
        ck_assert_int_eq(el_smooth_eval(&p, N, s, NULL, NULL, ka), EL_OK);
        double simpson = 0, h = p.length / (N - 1.0);
        for (int i = 0; i < N; i++) simpson += (i == 0 || i == N - 1 ? 1 : (i % 2 ? 4 : 2)) * ka[i] * ka[i];
        simpson *= h / 3;
        double e;
        ck_assert_int_eq(el_smooth_energy(&p, &e), EL_OK);
        ck_assert_close(e, simpson, 1e-9 * (1 + simpson));
    }
}
END_TEST

/* central finite-difference check of a 7-column Jacobian */
typedef int (*eval_fn)(const double *par, size_t n, const double *s, double *xy);

static int smooth_eval_t(const double *par, size_t n, const double *t, double *xy)
{
    el_smooth_params p = {par[0], par[1], par[2], par[3], par[4], par[5], par[6]};
    double s[64];
    for (size_t i = 0; i < n; i++) s[i] = t[i] * p.length;
    return el_smooth_eval(&p, n, s, xy, NULL, NULL);
}

static int discrete_eval_n(const double *par, size_t n, const double *unused, double *xy)
{
    (void)unused;
    el_discrete_params p = {par[0], par[1], par[2], par[3], par[4], par[5], par[6]};
    return el_discrete_eval(&p, n, xy);
}

static void check_jacobian_fd(eval_fn f, const double *par, size_t n, const double *t, const double *jac,
                              const char *what)
{
    double xp[128], xm[128];
    for (int j = 0; j < 7; j++) {
        double pp[7], pm[7];
        memcpy(pp, par, sizeof pp); memcpy(pm, par, sizeof pm);
        double h = 1e-6 * fmax(1.0, fabs(par[j]));
        pp[j] += h; pm[j] -= h;
        ck_assert_int_eq(f(pp, n, t, xp), EL_OK);
        ck_assert_int_eq(f(pm, n, t, xm), EL_OK);
        double big = 1.0;
        for (size_t i = 0; i < 2 * n; i++) big = fmax(big, fabs(jac[i * 7 + j]));
        for (size_t i = 0; i < 2 * n; i++) {
            double fd = (xp[i] - xm[i]) / (2 * h);
            ck_assert_msg(fabs(fd - jac[i * 7 + j]) <= 1e-6 * big, "%s: column %d row %zu: %.12g vs fd %.12g",
                          what, j, i, jac[i * 7 + j], fd);
        }
    }
}

START_TEST(smooth_jacobian_matches_finite_differences)
{
    unsigned long long rng = 0x5eed1234ULL;
    for (int trial = 0; trial < 40; trial++) {
        double k = trial % 2 ? test_uniform(&rng, 0.05, 0.97) : test_uniform(&rng, 1.03, 4.0);
        if (trial % 4 >= 2) k = -k; /* the mirror images */
        double par[7] = {test_uniform(&rng, -2, 2), test_uniform(&rng, -2, 2), test_uniform(&rng, -3, 3),
                         test_uniform(&rng, 0.2, 3), k, test_uniform(&rng, -2, 2), test_uniform(&rng, 0.5, 4)};
        enum { N = 12 };
        double t[N], s[N], jac[N * 2 * 7];
        for (int i = 0; i < N; i++) { t[i] = test_uniform(&rng, 0, 1); s[i] = t[i] * par[6]; }
        el_smooth_params p = {par[0], par[1], par[2], par[3], par[4], par[5], par[6]};
        ck_assert_int_eq(el_smooth_jacobian(&p, N, s, NULL, jac), EL_OK);
        check_jacobian_fd(smooth_eval_t, par, N, t, jac, "smooth");
    }
}
END_TEST

START_TEST(smooth_negative_k_is_the_mirror_image)
{
    /* k -> -k reflects the curve in the line through (x0, y0) at angle phi; for
     * |k| > 1 that turns a counter-clockwise loop into a clockwise one */
    const double ks[] = {0.4, 1.0, 2.5};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_smooth_params p = smooth(ks[a]), m = p;
        m.k = -p.k;
        enum { N = 40 };
        double s[N], xy[2 * N], xm[2 * N], th[N], thm[N], ka[N], kam[N];
        for (int i = 0; i < N; i++) s[i] = p.length * i / (N - 1.0);
        ck_assert_int_eq(el_smooth_eval(&p, N, s, xy, th, ka), EL_OK);
        ck_assert_int_eq(el_smooth_eval(&m, N, s, xm, thm, kam), EL_OK);
        const double c = cos(p.phi), sn = sin(p.phi);
        for (int i = 0; i < N; i++) {
            /* coordinates along / across the mirror line */
            double dx = xy[2 * i] - p.x0, dy = xy[2 * i + 1] - p.y0;
            double mx = xm[2 * i] - p.x0, my = xm[2 * i + 1] - p.y0;
            ck_assert_close(c * dx + sn * dy, c * mx + sn * my, 1e-12);
            ck_assert_close(-sn * dx + c * dy, -(-sn * mx + c * my), 1e-12);
            ck_assert_close(thm[i] - p.phi, -(th[i] - p.phi), 1e-12);
            ck_assert_close(kam[i], -ka[i], 1e-12);
        }
        double e, em;
        ck_assert_int_eq(el_smooth_energy(&p, &e), EL_OK);
        ck_assert_int_eq(el_smooth_energy(&m, &em), EL_OK);
        ck_assert_close(e, em, 1e-12 * e);
        if (p.k > 1.0) ck_assert(kam[0] < 0 && kam[N / 2] < 0); /* clockwise */
    }
}
END_TEST

START_TEST(smooth_reverse_runs_the_same_points_backwards)
{
    /* gamma_r(s) = gamma(L - s), theta_r = theta(L - s) + pi (mod 2 pi), kappa_r = -kappa(L - s),
     * over k across 1 and its sign, phases and scales, at 3 (sparse) and 41 samples */
    const double ks[] = {0.0, 0.3, -0.7, 0.999, 1.0, -1.0, 1.001, 2.5, -4.0};
    const double mus[] = {1e-4, 0.8, 50.0};
    const size_t ns[] = {3, 41};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++)
        for (size_t b = 0; b < sizeof mus / sizeof *mus; b++)
            for (size_t c = 0; c < 2; c++) {
                const double mu = mus[b];
                const el_smooth_params p = {1.5, -2.0, 0.7, mu, ks[a], 0.3 + a, 6.0 / sqrt(mu)};
                el_smooth_params r;
                ck_assert_int_eq(el_smooth_reverse(&p, &r), EL_OK);
                ck_assert_close(r.length, p.length, 0.0);
                const size_t n = ns[c];
                double s[41], sb[41], xy[82], xr[82], th[41], thr[41], ka[41], kar[41];
                for (size_t i = 0; i < n; i++) {
                    s[i] = p.length * i / (n - 1.0);
                    sb[i] = p.length - s[i];
                }
                ck_assert_int_eq(el_smooth_eval(&p, n, sb, xy, th, ka), EL_OK);
                ck_assert_int_eq(el_smooth_eval(&r, n, s, xr, thr, kar), EL_OK);
                const double tol = 1e-11 * (1.0 + p.length);
                for (size_t i = 0; i < n; i++) {
                    ck_assert_close(xr[2 * i], xy[2 * i], tol);
                    ck_assert_close(xr[2 * i + 1], xy[2 * i + 1], tol);
                    const double dth = remainder(thr[i] - th[i] - M_PI, 2.0 * M_PI);
                    ck_assert_close(dth, 0.0, 1e-10);
                    ck_assert_close(kar[i], -ka[i], 1e-10 * (1.0 + fabs(ka[i])));
                }
                el_smooth_params twice = r;
                ck_assert_int_eq(el_smooth_reverse(&twice, &twice), EL_OK); /* out may equal p */
                double xt[2];
                ck_assert_int_eq(el_smooth_eval(&twice, 1, &p.length, xt, NULL, NULL), EL_OK);
                double xe[2];
                ck_assert_int_eq(el_smooth_eval(&p, 1, &p.length, xe, NULL, NULL), EL_OK);
                ck_assert_close(xt[0], xe[0], tol);
                ck_assert_close(xt[1], xe[1], tol);
            }
    el_smooth_params bad = {0, 0, 0, -1.0, 0.5, 0, 1}, out = {0};
    ck_assert_int_eq(el_smooth_reverse(&bad, &out), EL_EINVAL);
    ck_assert_int_eq(out.mu, 0.0);
    ck_assert_int_eq(el_smooth_reverse(NULL, &out), EL_EINVAL);
    bad.mu = 1.0;
    ck_assert_int_eq(el_smooth_reverse(&bad, NULL), EL_EINVAL);
}
END_TEST

START_TEST(smooth_rejects_bad_input)
{
    double s[2] = {0, 1}, xy[4] = {7, 7, 7, 7}, jac[28], e = 7;
    el_smooth_params good = smooth(0.5);
    el_smooth_params bad[6];
    for (int i = 0; i < 6; i++) bad[i] = good;
    bad[0].mu = 0; bad[1].mu = -1; bad[2].k = NAN; bad[3].length = -1; bad[4].q = NAN; bad[5].phi = INFINITY;
    for (int i = 0; i < 6; i++) {
        ck_assert_int_eq(el_smooth_eval(&bad[i], 2, s, xy, NULL, NULL), EL_EINVAL);
        ck_assert_int_eq(el_smooth_jacobian(&bad[i], 2, s, xy, jac), EL_EINVAL);
        ck_assert_int_eq(el_smooth_energy(&bad[i], &e), EL_EINVAL);
    }
    double sn[2] = {0, NAN};
    ck_assert_int_eq(el_smooth_eval(&good, 2, sn, xy, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_smooth_eval(NULL, 2, s, xy, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_smooth_eval(&good, 2, NULL, xy, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_smooth_jacobian(&good, 2, s, xy, NULL), EL_EINVAL);
    ck_assert_int_eq(el_smooth_energy(&good, NULL), EL_EINVAL);
    for (int i = 0; i < 4; i++) ck_assert(xy[i] == 7);
    ck_assert(e == 7);
}
END_TEST

START_TEST(smooth_unresolvable_samples_are_edom_with_nan_outputs)
{
    /* no digits left: a result is finite and valid, or EL_EDOM says why and every
     * output is NaN (never half-written) */
    const double s2[2] = {0.0, 1e6};
    double xy[4] = {7, 7, 7, 7}, th[2], ka[2], jac[28], e = 7;
    el_smooth_params phase = {0, 0, 0, 1e20, 0.5, 0, 1e6}; /* |u| = 1e16 > 2^50 */
    ck_assert_int_eq(el_smooth_eval(&phase, 2, s2, xy, th, ka), EL_EDOM);
    for (int i = 0; i < 4; i++) ck_assert(isnan(xy[i]));
    ck_assert(isnan(th[0]) && isnan(th[1]) && isnan(ka[0]) && isnan(ka[1]));
    ck_assert_int_eq(el_smooth_jacobian(&phase, 2, s2, xy, jac), EL_EDOM);
    for (int i = 0; i < 28; i++) ck_assert(isnan(jac[i]));
    ck_assert_int_eq(el_smooth_energy(&phase, &e), EL_EDOM);
    ck_assert(isnan(e));
    /* sqrt(mu) s far below the rounding of q: u = q + sqrt(mu) s has no digits of s */
    const double s1[2] = {0.0, 1.0};
    el_smooth_params flat = {0, 0, 0, 1e-300, 0.5, 1.0, 1.0};
    ck_assert_int_eq(el_smooth_eval(&flat, 2, s1, xy, NULL, NULL), EL_EDOM);
    ck_assert(isnan(xy[0]) && isnan(xy[3]));
    ck_assert_int_eq(el_smooth_energy(&flat, &e), EL_EDOM);
    el_smooth_params denormal = flat;
    denormal.mu = 4.9e-324;
    ck_assert_int_eq(el_smooth_eval(&denormal, 2, s1, xy, NULL, NULL), EL_EDOM);
    /* overflow of a result: |k| = 1 has no period, the position passes DBL_MAX */
    el_smooth_params far = {DBL_MAX, 0, M_PI, 1.0, 1.0, 0.0, 1e300};
    const double s3[2] = {0.0, 1e300};
    ck_assert_int_eq(el_smooth_eval(&far, 2, s3, xy, NULL, NULL), EL_EDOM);
    ck_assert(isnan(xy[0]) && isnan(xy[2]));
    /* the k column at |k| = 1 past u ~ 710 (d cn/dk ~ e^u / 4) */
    el_smooth_params sep = {0, 0, 0, 1.0, -1.0, 0.0, 800.0};
    const double s4[2] = {0.0, 800.0};
    ck_assert_int_eq(el_smooth_jacobian(&sep, 2, s4, NULL, jac), EL_EDOM);
    ck_assert_int_eq(el_smooth_eval(&sep, 2, s4, xy, NULL, NULL), EL_OK); /* the points are fine */
    ck_assert(isfinite(xy[2]) && fabs(xy[2] + 798.0) < 1e-9); /* back along the axis: -800 + 2 tanh */
    /* extreme but valid: still EL_OK and finite */
    el_smooth_params big = {1e6, -1e6, 0.3, 1e8, 0.7, 0.4, 1e6};
    ck_assert_int_eq(el_smooth_eval(&big, 2, s2, xy, th, ka), EL_OK);
    ck_assert(isfinite(xy[2]) && isfinite(th[1]) && isfinite(ka[1]));
    el_smooth_params tiny_k = {0, 0, 0, 1.0, 4.9e-324, 0.3, 2.0};
    ck_assert_int_eq(el_smooth_eval(&tiny_k, 2, s1, xy, NULL, NULL), EL_OK);
    ck_assert_close(xy[2], 1.0, 1e-15);
}
END_TEST

START_TEST(smooth_huge_n_is_einval_before_any_write)
{
    /* n * 14 * sizeof(double) would wrap: no caller can own such arrays, and nothing
     * may be read or written (the arrays here hold two points) */
    el_smooth_params p = smooth(0.5);
    double s[2] = {0, 1}, xy[4] = {7, 7, 7, 7}, jac[28] = {7};
    const size_t huge[3] = {SIZE_MAX, SIZE_MAX / 112 + 1, (SIZE_MAX >> 3) + 1};
    for (int i = 0; i < 3; i++) {
        ck_assert_int_eq(el_smooth_eval(&p, huge[i], s, xy, NULL, NULL), EL_EINVAL);
        ck_assert_int_eq(el_smooth_jacobian(&p, huge[i], s, xy, jac), EL_EINVAL);
    }
    for (int i = 0; i < 4; i++) ck_assert(xy[i] == 7);
    ck_assert(jac[0] == 7);
}
END_TEST

START_TEST(smooth_energy_at_separatrix_has_no_cancellation)
{
    /* at |k| = 1 the energy 4 sqrt(mu) (tanh u1 - tanh q) comes from E = tanh, not from
     * u - D(u) with D ~ u: exact to rounding even for a 1e6-long curve */
    el_smooth_params p = {0, 0, 0, 4.0, 1.0, -0.5, 1e6};
    double e;
    ck_assert_int_eq(el_smooth_energy(&p, &e), EL_OK);
    ck_assert_close(e, 4.0 * 2.0 * (1.0 - tanh(-0.5)), 1e-15 * e);
}
END_TEST

/* ------------------------------------------------------------ discrete */

static el_discrete_params discrete(double k)
{
    el_discrete_params p = {0.4, -0.3, 0.05, 0.6, 0.07, 0.35, k};
    return p;
}

START_TEST(discrete_segments_mcmillan_and_conserved_quantity)
{
    const double ks[] = {0.2, 0.7, 0.99, 1.01, 1.6, 8.0};
    enum { N = 400 };
    static double xy[2 * N], ka[N];
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_discrete_params p = discrete(ks[a]);
        ck_assert_int_eq(el_discrete_eval(&p, N, xy), EL_OK);
        ck_assert_int_eq(el_discrete_curvature(&p, N, ka), EL_OK);
        const double h = p.h;
        for (int i = 0; i + 1 < N; i++)
            ck_assert_close(hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]), h, 1e-12 * h);
        /* curvature from the vertices themselves: (2/h) tan(K/2), K the turning angle (3.4) */
        double kmax = 0;
        for (int i = 1; i + 1 < N; i++) {
            double ax = xy[2 * i] - xy[2 * i - 2], ay = xy[2 * i + 1] - xy[2 * i - 1];
            double bx = xy[2 * i + 2] - xy[2 * i], by = xy[2 * i + 3] - xy[2 * i + 1];
            double K = atan2(ax * by - ay * bx, ax * bx + ay * by);
            ck_assert_close(ka[i - 1], 2.0 / h * tan(K / 2), 1e-9 * (1 + fabs(ka[i - 1])));
            kmax = fmax(kmax, fabs(ka[i - 1]));
        }
        /* McMillan map (3.9): kappa_{n+1} + kappa_{n-1} = alpha kappa_n / (1 + h^2 kappa_n^2 / 4), one alpha */
        double num = 0, den = 0;
        for (int i = 1; i + 1 < N - 2; i++) {
            double g = ka[i] / (1 + h * h * ka[i] * ka[i] / 4);
            num += (ka[i + 1] + ka[i - 1]) * g; den += g * g;
        }
        double alpha = num / den;
        for (int i = 1; i + 1 < N - 2; i++) {
            double res = ka[i + 1] + ka[i - 1] - alpha * ka[i] / (1 + h * h * ka[i] * ka[i] / 4);
            ck_assert_msg(fabs(res) <= 1e-10 * kmax, "k=%g McMillan residual %.3g (kmax %.3g)", p.k, res, kmax);
        }
        /* conserved quantity (3.18), one C */
        double C0 = ka[1] * ka[1] + ka[0] * ka[0] - alpha * ka[1] * ka[0] + h * h / 4 * ka[1] * ka[1] * ka[0] * ka[0];
        for (int i = 0; i + 1 < N - 2; i++) {
            double C = ka[i + 1] * ka[i + 1] + ka[i] * ka[i] - alpha * ka[i + 1] * ka[i]
                     + h * h / 4 * ka[i + 1] * ka[i + 1] * ka[i] * ka[i];
            ck_assert_msg(fabs(C - C0) <= 1e-10 * kmax * kmax, "k=%g (3.18) drift %.3g", p.k, C - C0);
        }
    }
}
END_TEST

START_TEST(discrete_continuum_limit_is_second_order)
{
    /* z = sqrt(mu) h: the vertices approach the smooth elastica at s = n h as O(h^2) */
    const double ks[] = {0.6, 1.4};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++) {
        el_smooth_params sp = {0.2, 0.1, 0.3, 1.5, ks[a], 0.2, 4.0};
        double err[4];
        for (int lev = 0; lev < 4; lev++) {
            int n = 40 << lev;
            double h = sp.length / n;
            el_discrete_params dp = {sp.x0, sp.y0, h, sp.phi, sqrt(sp.mu) * h, sp.q, sp.k};
            double *xy = malloc(2 * (n + 1) * sizeof *xy), *ref = malloc(2 * (n + 1) * sizeof *ref);
            double *s = malloc((n + 1) * sizeof *s);
            for (int i = 0; i <= n; i++) s[i] = i * h;
            ck_assert_int_eq(el_discrete_eval(&dp, n + 1, xy), EL_OK);
            ck_assert_int_eq(el_smooth_eval(&sp, n + 1, s, ref, NULL, NULL), EL_OK);
            err[lev] = 0;
            for (int i = 0; i < 2 * (n + 1); i++) err[lev] = fmax(err[lev], fabs(xy[i] - ref[i]));
            free(xy); free(ref); free(s);
        }
        printf("continuum limit k=%g: max error", sp.k);
        for (int lev = 0; lev < 4; lev++) printf(" %.3e", err[lev]);
        printf("  rates");
        for (int lev = 1; lev < 4; lev++) {
            double rate = log2(err[lev - 1] / err[lev]);
            printf(" %.3f", rate);
            ck_assert_msg(rate > 1.9 && rate < 2.1, "rate %.3f is not 2", rate);
        }
        printf("\n");
    }
}
END_TEST

START_TEST(discrete_jacobian_matches_finite_differences)
{
    unsigned long long rng = 0xfeedULL;
    for (int trial = 0; trial < 40; trial++) {
        double k = trial % 2 ? test_uniform(&rng, 0.05, 0.97) : test_uniform(&rng, 1.03, 4.0);
        double par[7] = {test_uniform(&rng, -2, 2), test_uniform(&rng, -2, 2), test_uniform(&rng, 0.01, 0.3),
                         test_uniform(&rng, -3, 3), test_uniform(&rng, -0.3, 0.3), test_uniform(&rng, -2, 2), k};
        enum { N = 60 };
        double jac[N * 14], xy[2 * N];
        el_discrete_params p = {par[0], par[1], par[2], par[3], par[4], par[5], par[6]};
        ck_assert_int_eq(el_discrete_jacobian(&p, N, xy, jac), EL_OK);
        check_jacobian_fd(discrete_eval_n, par, N, NULL, jac, "discrete");
        double xy2[2 * N];
        ck_assert_int_eq(el_discrete_eval(&p, N, xy2), EL_OK);
        for (int i = 0; i < 2 * N; i++) ck_assert_close(xy[i], xy2[i], 1e-13);
    }
}
END_TEST

START_TEST(discrete_rejects_bad_input)
{
    double xy[6] = {7, 7, 7, 7, 7, 7}, jac[42], ka[1] = {7};
    el_discrete_params good = discrete(0.5), bad[5];
    for (int i = 0; i < 5; i++) bad[i] = good;
    bad[0].h = 0; bad[1].h = -1; bad[2].k = -1; bad[3].z = NAN; bad[4].x0 = -INFINITY;
    for (int i = 0; i < 5; i++) {
        ck_assert_int_eq(el_discrete_eval(&bad[i], 3, xy), EL_EINVAL);
        ck_assert_int_eq(el_discrete_jacobian(&bad[i], 3, xy, jac), EL_EINVAL);
        ck_assert_int_eq(el_discrete_curvature(&bad[i], 3, ka), EL_EINVAL);
    }
    ck_assert_int_eq(el_discrete_eval(&good, 1, xy), EL_EINVAL);
    ck_assert_int_eq(el_discrete_eval(&good, 3, NULL), EL_EINVAL);
    ck_assert_int_eq(el_discrete_eval(NULL, 3, xy), EL_EINVAL);
    ck_assert_int_eq(el_discrete_curvature(&good, 2, ka), EL_EINVAL);
    ck_assert_int_eq(el_discrete_jacobian(&good, 3, xy, NULL), EL_EINVAL);
    for (int i = 0; i < 6; i++) ck_assert(xy[i] == 7);
    ck_assert(ka[0] == 7);
}
END_TEST

START_TEST(discrete_out_of_range_is_edom_or_einval_before_any_write)
{
    double xy[6] = {7, 7, 7, 7, 7, 7}, jac[42], ka[1] = {7};
    el_discrete_params good = discrete(0.5);
    ck_assert_int_eq(el_discrete_eval(&good, SIZE_MAX, xy), EL_EINVAL);
    ck_assert_int_eq(el_discrete_jacobian(&good, SIZE_MAX / 112 + 1, xy, jac), EL_EINVAL);
    ck_assert_int_eq(el_discrete_curvature(&good, SIZE_MAX, ka), EL_EINVAL);
    for (int i = 0; i < 6; i++) ck_assert(xy[i] == 7);
    ck_assert(ka[0] == 7);
    /* the last vertex's phase z (n - 1) + q past 2^50: EL_EDOM, outputs NaN */
    el_discrete_params phase = good;
    phase.z = 1e15;
    ck_assert_int_eq(el_discrete_eval(&phase, 3, xy), EL_EDOM);
    for (int i = 0; i < 6; i++) ck_assert(isnan(xy[i]));
    ck_assert_int_eq(el_discrete_curvature(&phase, 3, ka), EL_EDOM);
    ck_assert(isnan(ka[0]));
    ck_assert_int_eq(el_discrete_jacobian(&phase, 3, NULL, jac), EL_EDOM);
    for (int i = 0; i < 42; i++) ck_assert(isnan(jac[i]));
    /* vertices past DBL_MAX */
    el_discrete_params far = {DBL_MAX, 0, 1e300, 0, 0.1, 0, 0.5};
    ck_assert_int_eq(el_discrete_eval(&far, 3, xy), EL_EDOM);
    ck_assert(isnan(xy[0]));
    /* a sparse curve with |z| large and k = 1 exactly: EL_OK, finite (0/0 before) */
    el_discrete_params sep = {0, 0, 1.0, 0, 30.0, -45.0, 1.0};
    ck_assert_int_eq(el_discrete_eval(&sep, 3, xy), EL_OK);
    for (int i = 0; i < 6; i++) ck_assert(isfinite(xy[i]));
}
END_TEST

/* ------------------------------------------------------------ threads */

typedef struct { el_smooth_params p; double jac[300 * 14]; int status; } thread_job;

static void *thread_eval(void *arg)
{
    thread_job *j = arg;
    double s[300];
    for (int i = 0; i < 300; i++) s[i] = j->p.length * sqrt(i / 299.0); /* scattered */
    j->status = EL_OK;
    for (int rep = 0; rep < 20 && j->status == EL_OK; rep++)
        j->status = el_smooth_jacobian(&j->p, 300, s, NULL, j->jac);
    return NULL;
}

START_TEST(two_threads_evaluate_at_once)
{
    /* no shared mutable state: concurrent results equal serial ones bit for bit */
    static thread_job a, b, ref_a, ref_b;
    a.p = ref_a.p = smooth(0.7);
    b.p = ref_b.p = smooth(2.2);
    thread_eval(&ref_a);
    thread_eval(&ref_b);
    pthread_t ta, tb;
    ck_assert_int_eq(pthread_create(&ta, NULL, thread_eval, &a), 0);
    ck_assert_int_eq(pthread_create(&tb, NULL, thread_eval, &b), 0);
    pthread_join(ta, NULL);
    pthread_join(tb, NULL);
    ck_assert_int_eq(a.status, EL_OK);
    ck_assert_int_eq(b.status, EL_OK);
    ck_assert(memcmp(a.jac, ref_a.jac, sizeof a.jac) == 0);
    ck_assert(memcmp(b.jac, ref_b.jac, sizeof b.jac) == 0);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("core");
    TCase *j = tcase_create("jacobi"), *sm = tcase_create("smooth"), *d = tcase_create("discrete");
    tcase_set_timeout(j, 120); tcase_set_timeout(sm, 120); tcase_set_timeout(d, 120);
    tcase_add_test(j, jacobi_matches_mpmath_table);
    tcase_add_test(j, jacobi_derivatives_match_finite_differences);
    tcase_add_test(j, jacobi_small_k_derivative_is_analytic);
    tcase_add_test(j, jacobi_rejects_bad_input);
    tcase_add_test(j, jacobi_near_k_equal_1_keeps_relative_digits);
    tcase_add_test(j, jacobi_matches_gsl_elljac_over_the_range);
    tcase_add_test(j, jacobi_k_equal_1_derivatives_are_finite_until_they_overflow);
    tcase_add_test(j, jacobi_reports_lost_phase_and_overflow_as_edom);
    tcase_add_test(j, walk_offset_series_are_the_maclaurin_series);
    tcase_add_test(sm, smooth_unit_speed_and_curvature);
    tcase_add_test(sm, smooth_curvature_satisfies_elastica_equation);
    tcase_add_test(sm, smooth_points_continuous_across_k_equal_1);
    tcase_add_test(sm, smooth_energy_matches_quadrature);
    tcase_add_test(sm, smooth_jacobian_matches_finite_differences);
    tcase_add_test(sm, smooth_negative_k_is_the_mirror_image);
    tcase_add_test(sm, smooth_reverse_runs_the_same_points_backwards);
    tcase_add_test(sm, smooth_rejects_bad_input);
    tcase_add_test(sm, smooth_unresolvable_samples_are_edom_with_nan_outputs);
    tcase_add_test(sm, smooth_huge_n_is_einval_before_any_write);
    tcase_add_test(sm, smooth_energy_at_separatrix_has_no_cancellation);
    tcase_add_test(d, discrete_segments_mcmillan_and_conserved_quantity);
    tcase_add_test(d, discrete_continuum_limit_is_second_order);
    tcase_add_test(d, discrete_jacobian_matches_finite_differences);
    tcase_add_test(d, discrete_rejects_bad_input);
    tcase_add_test(d, discrete_out_of_range_is_edom_or_einval_before_any_write);
    tcase_add_test(sm, two_threads_evaluate_at_once);
    suite_add_tcase(s, j); suite_add_tcase(s, sm); suite_add_tcase(s, d);
    return test_run_suite(s);
}
