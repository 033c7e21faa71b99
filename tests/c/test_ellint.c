/* The library's own elliptic integrals (libelastica/ellint.c, written for speed):
 * Carlson's R_F / R_D and the complete K, D against GSL's R_F / R_D, over the
 * argument ranges the library uses and beyond. */
#include "testutil.h"
#include "internal.h"
#include "lanes.h"
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>
#include <stdio.h>
#include <string.h>

/* Relative error of both integrals at (x, y, z) against GSL; fails above tol. */
static double check_point(double x, double y, double z, double qs, double tol)
{
    gsl_sf_result gf, gd;
    ck_assert_msg(gsl_sf_ellint_RF_e(x, y, z, GSL_PREC_DOUBLE, &gf) == GSL_SUCCESS &&
                  gsl_sf_ellint_RD_e(x, y, z, GSL_PREC_DOUBLE, &gd) == GSL_SUCCESS,
                  "GSL fails at (%g, %g, %g)", x, y, z);
    double rf, rd, rd_only;
    ck_assert_int_eq(el__carlson_fd(x, y, z, qs, &rf, &rd), EL_OK);
    ck_assert_int_eq(el__carlson_fd(x, y, z, qs, NULL, &rd_only), EL_OK);
    const double ef = fabs(rf - gf.val) / gf.val, ed = fabs(rd - gd.val) / gd.val;
    const double eo = fabs(rd_only - gd.val) / gd.val;
    ck_assert_msg(ef <= tol && ed <= tol && eo <= tol,
                  "(%.17g, %.17g, %.17g) qs %g: R_F err %.3g, R_D err %.3g / %.3g", x, y, z, qs,
                  ef, ed, eo);
    return fmax(ef, fmax(ed, eo));
}

START_TEST(carlson_matches_gsl)
{
    gsl_set_error_handler_off();
    unsigned long long st = 77;
    double worst = 0.0, worst_coarse = 0.0;
    for (int i = 0; i < 20000; i++) {
        /* the library's arguments: (cos^2, 1 - k^2 sin^2, 1) and (cos^2, 1, dn^2), with
         * values down to 1e-12 (near the separatrix) and ordinary magnitudes */
        const double a = test_uniform(&st, 0.0, 1.0), b = pow(10.0, test_uniform(&st, -12.0, 0.0));
        const double c = test_uniform(&st, 0.0, 4.0), w = pow(10.0, test_uniform(&st, -3.0, 3.0));
        worst = fmax(worst, check_point(a, b, 1.0, 1.0, 2e-15));
        worst = fmax(worst, check_point(a, 1.0, b, 1.0, 2e-15));
        worst = fmax(worst, check_point(c * w, a * w, b * w, 1.0, 2e-15));
        worst_coarse = fmax(worst_coarse, check_point(a, b, 1.0, 0.2, 1e-10));
    }
    /* complete integrals: x = 0 */
    worst = fmax(worst, check_point(0.0, 0.5, 1.0, 1.0, 2e-15));
    worst = fmax(worst, check_point(0.0, 1e-200, 1.0, 1.0, 2e-15));
    printf("ellint: R_F, R_D worst relative error against GSL %.2e (double), %.2e (coarse)\n", worst,
           worst_coarse);
}
END_TEST

/* Carlson's algorithm as he writes it (DLMF 19.26.18, 19.36.1-2): the arguments and means
 * divided by 4 every step, one scalar sqrt each, the stopping rule and series of
 * ellint.c. el__carlson_fd's loop keeps them unscaled (exact powers of two) and takes two
 * square roots in one SSE2 instruction: the same arithmetic, so the same bits. */
static void carlson_plain(double x, double y, double z, double qs, double *rf, double *rd)
{
    const double AF0 = (x + y + z) / 3.0, AD0 = (x + y + 3.0 * z) / 5.0, x0 = x, y0 = y;
    const double QF = qs * 80.0 * fmax(fabs(AF0 - x), fmax(fabs(AF0 - y), fabs(AF0 - z)));
    const double QD = qs * 120.0 * fmax(fabs(AD0 - x), fmax(fabs(AD0 - y), fabs(AD0 - z)));
    double AF = AF0, AD = AD0, f4 = 1.0, num = 0.0, den = 1.0;
    while (f4 * QF >= AF || f4 * QD >= AD) {
        const double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        const double lam = sx * sy + sx * sz + sy * sz, d = sz * (z + lam);
        num = num * d + f4 * den;
        den *= d;
        AF = 0.25 * (AF + lam);
        AD = 0.25 * (AD + lam);
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        f4 *= 0.25;
    }
    double iA = 1.0 / AF, X = f4 * (AF0 - x0) * iA, Y = f4 * (AF0 - y0) * iA, Z = -X - Y;
    double E2 = X * Y - Z * Z, E3 = X * Y * Z;
    *rf = (1.0 + E2 * (-1.0 / 10.0 + E2 * (1.0 / 24.0 - 5.0 / 208.0 * E2) + E3 * (-3.0 / 44.0 + 1.0 / 16.0 * E2)) +
           E3 * (1.0 / 14.0 + 3.0 / 104.0 * E3)) * sqrt(iA);
    iA = 1.0 / AD;
    X = f4 * (AD0 - x0) * iA;
    Y = f4 * (AD0 - y0) * iA;
    Z = -(X + Y) / 3.0;
    const double XY = X * Y, Z2 = Z * Z;
    E2 = XY - 6.0 * Z2;
    E3 = (3.0 * XY - 8.0 * Z2) * Z;
    const double E4 = 3.0 * (XY - Z2) * Z2, E5 = XY * Z2 * Z;
    *rd = f4 * iA * sqrt(iA) *
              (1.0 + E2 * (-3.0 / 14.0 + E2 * (9.0 / 88.0 - 1.0 / 16.0 * E2 + 45.0 / 272.0 * E3) +
                           E3 * (-9.0 / 52.0) + E4 * (3.0 / 20.0) + E5 * (-9.0 / 68.0)) +
               E3 * (1.0 / 6.0 + E3 * (3.0 / 40.0) + E4 * (-9.0 / 68.0)) + E4 * (-3.0 / 22.0) +
               E5 * (3.0 / 26.0)) +
          3.0 * num / den;
}

/* The fast loop against the plain one bit for bit: the library's arguments (x, y in
 * [0, 1] down to 1e-14, z = 1, either order), arguments over 18 decades, zeros (complete
 * integrals), both precisions. */
START_TEST(carlson_fast_loop_is_plain_loop)
{
    unsigned long long st = 4242;
    for (int i = 0; i < 200000; i++) {
        double x, y, z = 1.0;
        if (i % 2) {
            x = test_uniform(&st, 0.0, 1.0);
            y = pow(10.0, test_uniform(&st, -14.0, 0.0));
            if (i % 4 == 1) { const double t = x; x = y; y = t; }
        } else {
            x = pow(10.0, test_uniform(&st, -15.0, 3.0));
            y = pow(10.0, test_uniform(&st, -15.0, 3.0));
            z = pow(10.0, test_uniform(&st, -15.0, 3.0));
        }
        if (i % 10 == 3) x = 0.0;
        const double qs = i % 3 ? 1.0 : 0.1;
        double rf, rd, pf, pd;
        ck_assert_int_eq(el__carlson_fd(x, y, z, qs, &rf, &rd), EL_OK);
        carlson_plain(x, y, z, qs, &pf, &pd);
        ck_assert_msg(rf == pf && rd == pd, "(%.17g, %.17g, %.17g) qs %g: R_F %.17g / %.17g, R_D %.17g / %.17g",
                      x, y, z, qs, rf, pf, rd, pd);
    }
}
END_TEST

/* a lane's arguments for the lane tests below: the objective's (cos^2, k'^2 + k^2 cos^2),
 * wide, near 1 (few steps), bad or 0 beside a positive */
static void carlson_lane_args(unsigned long long *stp, int t, double *x, double *y)
{
    /* (and 1e308 twice: their sum beyond DBL_MAX; one such value beside 0, where 80 times
     * the deviation overflows, is carlson_returns_near_dbl_max's) */
    static const double bad[] = {-1e-300, -1.0, 0.0, NAN, INFINITY, 1e308};
    unsigned long long st = *stp;
    const int kind = (int)test_uniform(&st, 0.0, 4.0);
    if (kind == 0) {                    /* the objective's: cos^2, k'^2 + k^2 cos^2 */
        const double c2 = test_uniform(&st, 0.0, 1.0), kc2 = pow(10.0, test_uniform(&st, -300.0, 0.0));
        *x = t % 7 == 0 ? 0.0 : c2;
        *y = kc2 + (1.0 - kc2) * *x;
    } else if (kind == 1) {             /* wide */
        *x = pow(10.0, test_uniform(&st, -300.0, 300.0));
        *y = pow(10.0, test_uniform(&st, -300.0, 300.0));
    } else if (kind == 2) {             /* near 1: few steps */
        *x = 1.0 + test_uniform(&st, -1e-3, 1e-3);
        *y = 1.0 + test_uniform(&st, -1e-3, 1e-3);
    } else {                            /* bad, or 0 beside a positive */
        const int i = (int)test_uniform(&st, 0.0, 5.0), j = (int)test_uniform(&st, 0.0, 5.0);
        *x = t % 11 == 0 ? bad[5] : bad[i];
        *y = t % 11 == 0 ? bad[5] : t % 3 ? bad[j] : test_uniform(&st, 0.0, 2.0);
    }
    *stp = st;
}

/* K = R_F(0, k'^2, 1), D = R_D(0, k'^2, 1) / 3 (DLMF 19.25.1), k from 0 to 1 - 1e-15. */
/* el__carlson_fd2 (two argument pairs side by side, hermite_lanes.c's samples) against
 * el__carlson_fd lane by lane: the same bits, and ok where it gives EL_OK, over the
 * objective's arguments (x = cos^2 in [0, 1], y = k'^2 + k^2 x) at every k including
 * k -> 1 and k'^2 -> 0, arguments over 600 decades, pairs whose lanes stop after different
 * numbers of duplication steps, and bad arguments (negative, both 0, NaN, infinite, a sum
 * beyond DBL_MAX) beside good ones, at the coarse and the full precision. */
START_TEST(carlson_two_lanes_equal_the_scalar)
{
    unsigned long long st = 99;
    long nok = 0, nbad = 0;
    for (int t = 0; t < 200000; t++) {
        double x[2], y[2];
        for (int l = 0; l < 2; l++) carlson_lane_args(&st, t, x + l, y + l);
        const double qs = t % 2 ? 1.0 : 0.1;
        el_d2 rf2, rd2;
        el_m2 ok2;
        el__carlson_fd2((el_d2){x[0], x[1]}, (el_d2){y[0], y[1]}, qs, &rf2, &rd2, &ok2);
        for (int l = 0; l < 2; l++) {
            double rf, rd;
            const int rc = el__carlson_fd(x[l], y[l], 1.0, qs, &rf, &rd);
            ck_assert_msg((rc == EL_OK) == (ok2[l] != 0), "(%g, %g): status %d, ok %lld", x[l], y[l], rc, ok2[l]);
            if (rc) { nbad++; continue; }
            const double a = rf2[l], b = rd2[l];
            ck_assert_msg(memcmp(&a, &rf, sizeof a) == 0 && memcmp(&b, &rd, sizeof b) == 0,
                          "(%.17g, %.17g) qs %g: R_F %.17g / %.17g, R_D %.17g / %.17g", x[l], y[l], qs, a, rf, b, rd);
            nok++;
        }
    }
    ck_assert_msg(nok > 200000 && nbad > 100000, "%ld ok, %ld bad", nok, nbad);   /* both outcomes covered */
}
END_TEST

#if EL__LANES4
/* el__carlson_fd4 (hermite_lanes_avx2.c: four argument pairs in AVX2 lanes, where the
 * processor has it) against el__carlson_fd lane by lane, as the two lanes above: the same
 * bits, ok where it gives EL_OK, lanes stopping after different numbers of steps, bad
 * arguments and those where the stopping test overflows beside good ones. */
START_TEST(carlson_four_lanes_equal_the_scalar)
{
    if (!el__lanes4_available()) {   /* el__hermite_x_objectives keeps to two lanes there */
        fprintf(stderr, "carlson_four_lanes_equal_the_scalar: no AVX2 on this processor, four lanes not run\n");
        return;
    }
    unsigned long long st = 4444;
    long nok = 0, nbad = 0;
    for (int t = 0; t < 200000; t++) {
        double x[4], y[4], rf4[4], rd4[4];
        int ok4[4];
        for (int l = 0; l < 4; l++) carlson_lane_args(&st, t, x + l, y + l);
        if (t % 13 == 0) { x[t % 4] = 0.0; y[t % 4] = 1.7e308; }   /* 80 times the deviation overflows */
        const double qs = t % 2 ? 1.0 : 0.1;
        el__carlson_fd4v(x, y, qs, rf4, rd4, ok4);
        for (int l = 0; l < 4; l++) {
            double rf, rd;
            const int rc = el__carlson_fd(x[l], y[l], 1.0, qs, &rf, &rd);
            ck_assert_msg((rc == EL_OK) == ok4[l], "(%g, %g): status %d, ok %d", x[l], y[l], rc, ok4[l]);
            if (rc) { nbad++; continue; }
            ck_assert_msg(memcmp(&rf4[l], &rf, sizeof rf) == 0 && memcmp(&rd4[l], &rd, sizeof rd) == 0,
                          "(%.17g, %.17g) qs %g: R_F %.17g / %.17g, R_D %.17g / %.17g", x[l], y[l], qs, rf4[l], rf,
                          rd4[l], rd);
            nok++;
        }
    }
    ck_assert_msg(nok > 400000 && nbad > 200000, "%ld ok, %ld bad", nok, nbad);   /* both outcomes covered */
}
END_TEST
#endif

START_TEST(complete_integrals_match_gsl)
{
    gsl_set_error_handler_off();
    double worst = 0.0;
    for (int i = 0; i <= 400; i++) {
        /* k'^2 from 1 down to 1e-30 (k -> 1), then k from 1e-6 down to 1e-16 (k -> 0) */
        double k, kc2;
        if (i <= 300) {
            kc2 = pow(10.0, -i / 10.0);
            k = sqrt(1.0 - kc2);
        } else {
            k = pow(10.0, -6.0 - (i - 300) / 10.0);
            kc2 = 1.0 - k * k;
        }
        gsl_sf_result gf, gd;
        ck_assert_int_eq(gsl_sf_ellint_RF_e(0.0, kc2, 1.0, GSL_PREC_DOUBLE, &gf), GSL_SUCCESS);
        ck_assert_int_eq(gsl_sf_ellint_RD_e(0.0, kc2, 1.0, GSL_PREC_DOUBLE, &gd), GSL_SUCCESS);
        double K, D;
        ck_assert_int_eq(el__ellint_complete(k, kc2, &K, &D), EL_OK);
        double Konly;   /* K alone (D = NULL): the same bits */
        ck_assert_int_eq(el__ellint_complete(k, kc2, &Konly, NULL), EL_OK);
        ck_assert(memcmp(&K, &Konly, sizeof K) == 0);
        const double eK = fabs(K - gf.val) / gf.val, eD = fabs(D - gd.val / 3.0) / (gd.val / 3.0);
        ck_assert_msg(eK <= 2e-15 && eD <= 4e-15, "k'^2 = %.17g: K err %.3g, D err %.3g", kc2, eK, eD);
        worst = fmax(worst, fmax(eK, eD));
    }
    double K, D;
    ck_assert_int_eq(el__ellint_complete(0.0, 1.0, &K, &D), EL_OK);
    ck_assert_close(K, M_PI / 2.0, 1e-16);
    ck_assert_close(D, M_PI / 4.0, 1e-16);                /* int_0^(pi/2) sin^2 */
    ck_assert_int_eq(el__ellint_complete(1.0, 0.0, &K, &D), EL_EDOM);
    ck_assert_int_eq(el__ellint_complete(0.5, NAN, &K, &D), EL_EDOM);
    ck_assert_int_eq(el__ellint_complete(1.0, 0.0, &K, NULL), EL_EDOM);
    ck_assert_int_eq(el__ellint_complete(0.5, NAN, &K, NULL), EL_EDOM);
    ck_assert_int_eq(el__ellint_complete(NAN, 0.5, &K, NULL), EL_EDOM);
    /* K alone against K with D at random k'^2 over (0, 1) and the period's range near 0 */
    unsigned long long st = 99;
    for (int i = 0; i < 100000; i++) {
        const double kc = i % 2 ? test_uniform(&st, 0.0, 1.0) : pow(10.0, test_uniform(&st, -300.0, 0.0));
        const double kk = sqrt(1.0 - kc);
        double K1, D1, K2;
        const int r1 = el__ellint_complete(kk, kc, &K1, &D1), r2 = el__ellint_complete(kk, kc, &K2, NULL);
        ck_assert_int_eq(r1, r2);
        if (!r1) ck_assert(memcmp(&K1, &K2, sizeof K1) == 0);
    }
    printf("ellint: complete K, D worst relative error against GSL %.2e\n", worst);
}
END_TEST

START_TEST(carlson_rejects_bad_arguments)
{
    double rf, rd;
    const double bad[][3] = {{-1e-300, 1, 1}, {1, -1, 1}, {1, 1, 0}, {0, 0, 1}, {NAN, 1, 1},
                             {1, INFINITY, 1}, {1, 1, -2}, {0, -0.0, 1}, {-0.0, -0.0, 1}, {INFINITY, 0, 1},
                             {1, 1, INFINITY}, {1, NAN, 1}, {1, 1, NAN}, {1e308, 1e308, 1}, {0, 0, 1e300}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        ck_assert_int_eq(el__carlson_fd(bad[i][0], bad[i][1], bad[i][2], 1.0, &rf, &rd), EL_EDOM);
    /* the edge of the domain that is accepted: one of x, y zero or subnormal, the sum
     * just finite */
    const double good[][3] = {{0, 4.9e-324, 1}, {4.9e-324, 0, 1}, {0, 1, 1e-10}, {-0.0, 1, 1},
                              {1e307, 1e307, 1e307}};
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++)
        ck_assert_int_eq(el__carlson_fd(good[i][0], good[i][1], good[i][2], 1.0, &rf, &rd), EL_OK);
}
END_TEST

/* Arguments whose sum nears DBL_MAX, where 80 or 120 times the deviation from the mean
 * overflows (x = 0, y = 1e308: the duplication loop's stopping test never failed and the
 * call never returned): they return EL_EDOM, as arguments beyond ~1e40 do already (R_D's
 * duplication sum overflows), in both precisions, with or without R_F, in el__carlson_fd2
 * beside an ordinary lane, whose bits stay el__carlson_fd's. Its own timeout: the code
 * before hung here. */
START_TEST(carlson_returns_near_dbl_max)
{
    const double ys[] = {1e307, 1e308, 1.7e308, DBL_MAX / 2.0, DBL_MAX - 2.0};
    for (size_t i = 0; i < sizeof ys / sizeof ys[0]; i++)
        for (int c = 0; c < 2; c++) {
            const double y = ys[i], qs = c ? 0.1 : 1.0;
            double rf, rd;
            ck_assert_int_eq(el__carlson_fd(0.0, y, 1.0, qs, &rf, &rd), EL_EDOM);
            ck_assert_int_eq(el__carlson_fd(y, 0.0, 1.0, qs, &rf, &rd), EL_EDOM);
            ck_assert_int_eq(el__carlson_fd(0.0, y, 1.0, qs, NULL, &rd), EL_EDOM);   /* jacobi.c's call */
            ck_assert_int_eq(el__carlson_fd(0.0, 1.0, y, qs, NULL, &rd), EL_EDOM);
        }
    /* any big argument (sum up to DBL_MAX), zeros beside it, in any place: a status */
    unsigned long long st = 31337;
    for (int t = 0; t < 20000; t++) {
        double a[3];
        for (int j = 0; j < 3; j++) a[j] = t % 5 == j ? 0.0 : pow(10.0, test_uniform(&st, -300.0, 308.0));
        a[t % 3] = test_uniform(&st, 0.0, 1.0) * DBL_MAX;
        if (a[0] + a[1] + a[2] > DBL_MAX) for (int j = 0; j < 3; j++) a[j] *= 0.5;
        double rf, rd;
        const int rc = el__carlson_fd(a[0], a[1], a[2], t % 2 ? 1.0 : 0.1, t % 3 ? &rf : NULL, &rd);
        ck_assert(rc == EL_EDOM || (rc == EL_OK && isfinite(rd)));
    }
    /* two lanes: such a lane beside an ordinary, a bad and another such one */
    const double other[][2] = {{0.3, 0.7}, {0.0, 1e-300}, {-1.0, 1.0}, {0.0, 1.7e308}, {1e308, 0.0}, {0.5, 0.5}};
    for (size_t i = 0; i < sizeof other / sizeof other[0]; i++)
        for (int swap = 0; swap < 2; swap++)
            for (int c = 0; c < 2; c++) {
                const double x[2] = {swap ? other[i][0] : 0.0, swap ? 0.0 : other[i][0]};
                const double y[2] = {swap ? other[i][1] : 1.7e308, swap ? 1.7e308 : other[i][1]};
                const double qs = c ? 0.1 : 1.0;
                el_d2 rf2, rd2;
                el_m2 ok2;
                el__carlson_fd2((el_d2){x[0], x[1]}, (el_d2){y[0], y[1]}, qs, &rf2, &rd2, &ok2);
                for (int l = 0; l < 2; l++) {
                    double rf, rd;
                    const int rc = el__carlson_fd(x[l], y[l], 1.0, qs, &rf, &rd);
                    ck_assert_msg((rc == EL_OK) == (ok2[l] != 0), "(%g, %g): %d, %lld", x[l], y[l], rc, ok2[l]);
                    const double a = rf2[l], b = rd2[l];
                    if (!rc) ck_assert(memcmp(&a, &rf, sizeof a) == 0 && memcmp(&b, &rd, sizeof b) == 0);
                }
            }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("ellint");
    TCase *tc = tcase_create("ellint");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, carlson_matches_gsl);
    tcase_add_test(tc, carlson_fast_loop_is_plain_loop);
    tcase_add_test(tc, carlson_two_lanes_equal_the_scalar);
#if EL__LANES4
    tcase_add_test(tc, carlson_four_lanes_equal_the_scalar);
#endif
    tcase_add_test(tc, complete_integrals_match_gsl);
    tcase_add_test(tc, carlson_rejects_bad_arguments);
    suite_add_tcase(s, tc);
    TCase *big = tcase_create("near DBL_MAX");   /* what hung: its own short timeout */
    tcase_set_timeout(big, 20);
    tcase_add_test(big, carlson_returns_near_dbl_max);
    suite_add_tcase(s, big);
    return test_run_suite(s);
}
