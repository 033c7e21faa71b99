/* Hermite interpolation by elastic curves (seed 004): every returned curve is
 * checked with the evaluator of smooth.c (ends, energy, inflections), the
 * paper's case-1 example of §5, the polynomial (40) by its defining property,
 * random problems in both modes, near the separatrix and up to high tension (the
 * degenerate data, bad input and el_hermite_solve_into: test_hermite_edge.c). */
#include "testutil.h"
#include "hermite_internal.h"
#include "hermite_scan.h"
#include "hermite_check.h"
#include <stdio.h>
#include <string.h>

/* ------------------------------------------------------------ seed 004 §5, figure 1 */

START_TEST(paper_case1_example)
{
    double P[2] = {0.868, -0.497}, V[2] = {-0.917, -0.398};
    double n = hypot(P[0], P[1]);
    P[0] /= n; P[1] /= n;   /* the printed data are rounded to 3 digits */
    n = hypot(V[0], V[1]);
    V[0] /= n; V[1] /= n;
    el_hermite_analysis a;
    ck_assert_int_eq(el_hermite_analyse(P, V, 10.99, &a), EL_OK);
    ck_assert_int_eq(a.hcase, 1);
    /* the paper's table gives |kappa_m| < 11.5 for this sigma; the exact bound is inside */
    ck_assert(a.kappa_bound <= 11.5 && a.kappa_bound > 4.852);
    /* I~ = [-11.5, -2.71] U [-0.356, 11.5] */
    ck_assert_uint_eq(a.ninterval, 2);
    ck_assert_close(a.interval[1], -2.71, 0.005);
    ck_assert_close(a.interval[2], -0.356, 0.005);
    ck_assert_close(a.interval[0], -a.kappa_bound, 1e-12);
    ck_assert_close(a.interval[3], a.kappa_bound, 1e-12);
    /* R1 = {-4.006, 0.478, 1.079} (f1), R2 = {-4.375, -3.777, -2.718, 2.299, 4.076} (f2) */
    const double R[8] = {-4.375, -4.006, -3.777, -2.718, 0.478, 1.079, 2.299, 4.076};
    const int grp[8] = {2, 1, 2, 2, 1, 1, 2, 2};
    ck_assert_uint_eq(a.nroot, 8);
    for (int i = 0; i < 8; i++) {
        ck_assert_close(a.root[i], R[i], 0.005);
        /* roots of one group belong to one objective function */
        for (int j = 0; j < 8; j++)
            ck_assert_int_eq(grp[i] == grp[j], a.root_branch[i] == a.root_branch[j]);
    }
    /* special values (45): -5.283, -3.315, 0.675, 3.315 */
    const double S[4] = {-5.283, -3.315, 0.675, 3.315};
    ck_assert_uint_eq(a.nspecial, 4);
    for (int i = 0; i < 4; i++) ck_assert_close(a.special[i], S[i], 0.002);

    /* the solution kappa0 = -4.852 is among all solutions */
    const double p0[2] = {0, 0}, t0[2] = {0, 1};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = 10.99;
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, P, V, &o, &r), EL_OK);
    int found = 0;
    for (size_t i = 0; i < r.count; i++) found |= fabs(r.solutions[i].kappa0 + 4.852) < 0.002;
    ck_assert_msg(found, "kappa0 = -4.852 not among %zu solutions", r.count);
    check_result(p0, t0, P, V, &r, 1e-10);
    el_hermite_result_free(&r);
}
END_TEST

/* The roots of (40) are where kappa_m^2 = 2 sigma: check with (8), (15), (16)
 * and (17) (kappa0' from the first integral must be real and consistent). */
START_TEST(polynomial_40_roots_are_class_boundaries)
{
    unsigned long long st = 99;
    int checked = 0;
    for (int t = 0; t < 200; t++) {
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double P[2] = {cos(a), sin(a)}, V[2] = {cos(b), sin(b)};
        const double sigma = test_uniform(&st, 0.5, 40.0);
        el_hermite_analysis an;
        ck_assert_int_eq(el_hermite_analyse(P, V, sigma, &an), EL_OK);
        for (size_t i = 0; i < an.nroot; i++) {
            const double k0 = an.root[i];
            /* branch of (17): P2 k1^2 + 2 V1 k1 - 2 V1 C - A P2 = 0 */
            const double w = k0 * k0 - sigma, C = 0.5 * w * P[0] + k0, A = w * V[1] + sigma;
            const double disc = V[0] * V[0] + P[1] * (2.0 * V[0] * C + A * P[1]);
            const double sq = sqrt(fmax(disc, 0.0));
            /* roots of (17) without cancellation: product of the roots = -c0 / P2 */
            const double c0 = 2.0 * V[0] * C + A * P[1];
            double k1;
            if (an.root_branch[i] == 0) k1 = V[0] > 0.0 ? c0 / (V[0] + sq) : (-V[0] + sq) / P[1];
            else k1 = V[0] < 0.0 ? c0 / (V[0] - sq) : (-V[0] - sq) / P[1];
            /* kappa0' by (16), or by (15) when P2 is small */
            const double k0p = fabs(V[0]) > fabs(P[1]) ? (A - k1 * k1) / (2.0 * V[0]) : (k1 - C) / P[1];
            /* (8) with kappa_m^2 = 2 sigma: 4 k0'^2 = sigma^2 - (k0^2 - sigma)^2 */
            const double lhs = 4.0 * k0p * k0p, rhs = sigma * sigma - w * w;
            ck_assert_msg(fabs(lhs - rhs) <= 1e-6 * (sigma * sigma + lhs),
                          "root %g: 4k0'^2 = %g, sigma^2 - (k0^2-sigma)^2 = %g", k0, lhs, rhs);
            checked++;
        }
    }
    ck_assert_int_gt(checked, 50);
}
END_TEST

/* ------------------------------------------------------------ random problems */

START_TEST(random_tension_problems_meet_the_ends)
{
    unsigned long long st = 12345;
    size_t total = 0;
    for (int t = 0; t < 150; t++) {
        const double p0[2] = {test_uniform(&st, -3, 3), test_uniform(&st, -3, 3)};
        const double p1[2] = {test_uniform(&st, -3, 3), test_uniform(&st, -3, 3)};
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double t0[2] = {2.0 * cos(a), 2.0 * sin(a)}, t1[2] = {0.5 * cos(b), 0.5 * sin(b)};
        const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = test_uniform(&st, -20.0, 60.0) / (d * d);
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        for (size_t i = 0; i < r.count; i++) ck_assert_close(r.solutions[i].sigma, o.sigma, 1e-15 * fabs(o.sigma));
        check_result(p0, t0, p1, t1, &r, 1e-10);
        total += r.count;
        el_hermite_result_free(&r);
    }
    ck_assert_uint_gt(total, 150);
}
END_TEST

START_TEST(random_length_problems_meet_the_ends)
{
    unsigned long long st = 777;
    size_t total = 0;
    for (int t = 0; t < 12; t++) {
        const double p0[2] = {0.3, -0.2};
        const double p1[2] = {test_uniform(&st, -2, 2), test_uniform(&st, -2, 2)};
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.mode = EL_HERMITE_LENGTH;
        o.length = d * test_uniform(&st, 1.1, 3.0);
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        for (size_t i = 0; i < r.count; i++)
            ck_assert_close(r.solutions[i].length, o.length, 1e-9 * o.length);
        check_result(p0, t0, p1, t1, &r, 1e-10);
        total += r.count;
        el_hermite_result_free(&r);
    }
    ck_assert_uint_gt(total, 12);
}
END_TEST

/* A solution found in tension mode is found again in length mode with its
 * length, with the same sigma (the two modes are inverse problems). */
START_TEST(length_mode_inverts_tension_mode)
{
    const double p0[2] = {0, 0}, t0[2] = {1, 0.2}, p1[2] = {1.5, 0.7}, t1[2] = {-0.3, 1};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = 7.0;
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_gt(r.count, 0);
    for (size_t i = 0; i < r.count && i < 3; i++) {
        el_hermite_options ol;
        el_hermite_options_defaults(&ol);
        ol.mode = EL_HERMITE_LENGTH;
        ol.length = r.solutions[i].length;
        el_hermite_result rl;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &ol, &rl), EL_OK);
        int found = 0;
        for (size_t j = 0; j < rl.count; j++)
            found |= fabs(rl.solutions[j].sigma - 7.0) < 1e-7 &&
                     fabs(rl.solutions[j].kappa0 - r.solutions[i].kappa0) < 1e-6;
        ck_assert_msg(found, "tension solution %zu (L = %g) not found by length", i, ol.length);
        check_result(p0, t0, p1, t1, &rl, 1e-10);
        el_hermite_result_free(&rl);
    }
    el_hermite_result_free(&r);
}
END_TEST

/* Mirroring the data in the x axis mirrors every solution: same length, energy,
 * sigma, opposite curvatures; a loop keeps |k| and flips the sign of k (k < -1 is
 * the clockwise loop, returned running from p0 to p1 like every solution). */
START_TEST(mirrored_data_give_mirrored_solutions)
{
    unsigned long long st = 4242;
    int ccw = 0, cw = 0;
    for (int t = 0; t < 60; t++) {
        const double p0[2] = {test_uniform(&st, -2, 2), test_uniform(&st, -2, 2)};
        const double p1[2] = {test_uniform(&st, -2, 2), test_uniform(&st, -2, 2)};
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        const double m0[2] = {p0[0], -p0[1]}, m1[2] = {p1[0], -p1[1]};
        const double u0[2] = {t0[0], -t0[1]}, u1[2] = {t1[0], -t1[1]};
        const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = test_uniform(&st, -10.0, 60.0) / (d * d);
        el_hermite_result r, m;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        ck_assert_int_eq(el_hermite_solve(m0, u0, m1, u1, &o, &m), EL_OK);
        check_result(p0, t0, p1, t1, &r, 1e-10);
        check_result(m0, u0, m1, u1, &m, 1e-10);
        ck_assert_uint_eq(r.count, m.count);
        for (size_t i = 0; i < r.count; i++) {
            const el_hermite_solution *x = &r.solutions[i];
            int found = 0;
            for (size_t j = 0; j < m.count && !found; j++) {
                const el_hermite_solution *y = &m.solutions[j];
                found = fabs(x->length - y->length) <= 1e-8 * x->length &&
                        fabs(x->energy - y->energy) <= 1e-8 * (1.0 + x->energy) &&
                        fabs(x->kappa0 + y->kappa0) <= 1e-7 * (1.0 + fabs(x->kappa0)) &&
                        fabs(x->kappa1 + y->kappa1) <= 1e-7 * (1.0 + fabs(x->kappa1));
                if (found && fabs(x->curve.k) > 1.0 + 1e-6)
                    ck_assert_msg(fabs(x->curve.k + y->curve.k) <= 1e-7 * fabs(x->curve.k),
                                  "loop k %g mirrored to k %g", x->curve.k, y->curve.k);
            }
            ck_assert_msg(found, "solution %zu (L %g, kappa0 %g) has no mirror image", i,
                          x->length, x->kappa0);
            cw += x->curve.k < -1.0;
            ccw += x->curve.k > 1.0;
        }
        el_hermite_result_free(&r);
        el_hermite_result_free(&m);
    }
    /* both orientations of loops occurred */
    ck_assert_int_gt(cw, 3);
    ck_assert_int_gt(ccw, 3);
}
END_TEST

/* Large tension (sigma |p1-p0|^2 in [100, 600]): many solutions lie within 1e-7 of
 * the separatrix |k| = 1, where one ulp of k moves the end of a curve through a saddle
 * by 1e-10..1e-2. Every one is returned at the default tol (one piece, or a chain
 * split at its saddles, each meeting the ends to 1e-10 and checked as above), none
 * counted unrepresentable, and a looser tol returns the same curves. */
START_TEST(near_separatrix_solutions_meet_tol)
{
    unsigned long long st = 31337;
    size_t strict = 0, chains = 0, near = 0;
    for (int t = 0; t < 40; t++) {
        const double p0[2] = {0, 0}, t0[2] = {1, 0};
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double p1[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = test_uniform(&st, 100.0, 600.0);
        el_hermite_result r, l;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        check_result(p0, t0, p1, t1, &r, 1e-10);
        ck_assert_uint_eq(r.unrepresentable, 0);
        strict += r.count;
        for (size_t i = 0; i < r.count; i++) {
            near += fabs(fabs(r.solutions[i].curve.k) - 1.0) < 1e-7;
            chains += r.solutions[i].npieces > 1;
        }
        o.tol = 1e-6;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &l), EL_OK);
        check_result(p0, t0, p1, t1, &l, 1e-6);
        ck_assert_uint_eq(l.count, r.count);
        ck_assert_uint_eq(l.unrepresentable, 0);
        el_hermite_result_free(&r);
        el_hermite_result_free(&l);
    }
    ck_assert_uint_gt(near, 20);
    ck_assert_uint_gt(chains, 10);
    fprintf(stderr, "near_separatrix_solutions_meet_tol: %zu solutions, %zu within 1e-7 of |k| = 1, %zu chains\n",
            strict, near, chains);
}
END_TEST

/* Near-straight curves with aligned tangents at sigma |p1-p0|^2 in [300, 1000]: 2-piece chains
 * (L ~ 1 + 1e-8..1e-5 |p1 - p0|) whose root, in the separatrix chart, sits at the limit of
 * doubles (one ulp of y moves f by 1e-11..1e-8: #479's bracket closes between
 * f = 1.1e-10 and -2.8e-11 six ulps apart). hermite.c tried the chain only for |f| <= 1e-11
 * and lost them (the random problems, tangents within 0.05 rad of the chord and sigma
 * |p1-p0|^2 uniform in [-10, 1000], that b1c7360 solved and 970c3e6 missed: 2 of 1000,
 * 10 of 3000 with another seed); the chain's own
 * Gauss-Newton takes any root bracket_root keeps (|f| <= 1e-8), and the final acceptance
 * (residual <= tol by el_smooth_eval, checked here) is unchanged. The last one (#741) was
 * lost where bracket_root returned the last state it evaluated (f = 1.5e-8, one ulp of y
 * from f = -1.3e-22) with the separatrix cache of hermite_tension.c. Each problem returns the
 * curve (L, kappa0, normalised by |p1 - p0|, as b1c7360 gave them to 10 digits). */
static const struct { double p0[2], t0[2], p1[2], t1[2], sigma, L, k0; } near_straight[] = {
    {{0x1.89b7c418eec7cp+0, 0x1.6af775aa5aef8p-1}, {0x1.2689f9a74c93bp-1, 0x1.a2cbfe0f35b09p-1},  /* seed 12345 #479 */
     {0x1.3a799b24aab4ap+1, 0x1.e310c25beb7d6p+0}, {0x1.3b9f83a54a52bp-1, 0x1.93252c395e9a9p-1}, 0x1.a0c82881bc43cp+8, 1.000028285, -1.119725433},
    {{0x1.b0d4d5e01c08cp+0, 0x1.1a0f14c32e82ep+2}, {-0x1.e92885dd5aaadp-1, 0x1.2e71c8f6aa812p-2},  /* seed 12345 #698 */
     {-0x1.f6ab6018710d8p-1, 0x1.53e9b8ed6da54p+2}, {-0x1.e4c3ddcf5c36p-1, 0x1.4986936ea062fp-2}, 0x1.44ea6bc0fef4cp+5, 1.00001347, -0.3643390624},
    {{0x1.7b4604165a9b8p-1, 0x1.ad772f322a4bcp+0}, {-0x1.8502590ad6227p-3, 0x1.f6adc6da29b44p-1},  /* seed 777 #1153 */
     {0x1.3ccae98b4e27dp-1, 0x1.411f2abbc35f1p+1}, {-0x1.23a6287d301f7p-3, 0x1.fac8249ffb948p-1}, 0x1.33ccb80e3c87cp+9, 1.000034613, -0.7170727909},
    {{-0x1.eaf00173ecb84p+1, 0x1.35d1709b25838p+0}, {-0x1.b512a94ede288p-7, -0x1.fff456fb24f17p-1},  /* seed 777 #1264 */
     {-0x1.eb66073a37484p+1, 0x1.e9bf15a48bcedp-1}, {-0x1.f5d926c831c55p-7, -0x1.fff0a0964389bp-1}, 0x1.d0ab7b5323ee4p+12, 1.000000032, -0.01296710349},
    {{-0x1.3ccdd00acc3bap+2, 0x1.842e2a28cc378p+1}, {-0x1.d93b6de79df68p-6, -0x1.ffc95049bac43p-1},  /* seed 777 #1844 */
     {-0x1.3cf3645321b17p+2, 0x1.617333b222d4ep+1}, {-0x1.ab47237e5d3acp-8, -0x1.fffd36d7ab275p-1}, 0x1.735d8da37a82cp+13, 1.000005013, 0.4478564013},
    {{-0x1.51fc35da63e94p+0, -0x1.8cada1409ca48p-1}, {0x1.9bebc5bed6032p-2, 0x1.d4bf601ce1069p-1},  /* seed 777 #1905 */
     {-0x1.295961da235f2p+0, -0x1.a380329d0d91p-2}, {0x1.98f1f7de18a38p-2, 0x1.d566048b414dcp-1}, 0x1.754ca82ab13b3p+12, 1.000000176, 0.08917443293},
    {{-0x1.1640ef0100a96p+1, -0x1.0f326892d0936p+2}, {-0x1.556c2d8ff77abp-3, -0x1.f8d5c4f725d7cp-1},  /* seed 777 #2025 */
     {-0x1.e2407706efebap+1, -0x1.9525c73721edbp+3}, {-0x1.7d3cd6d71ab2p-3, -0x1.f70d01c5e853fp-1}, 0x1.82ee84adf0156p+3, 1.000004487, -0.4323128092},
    {{-0x1.dcf7e9463fa06p+1, -0x1.ad3a405177c3cp+1}, {-0x1.7cc8d3d00d416p-1, -0x1.564487f7d63eap-1},  /* seed 777 #2048 */
     {-0x1.5b743607673dbp+3, -0x1.34e53fec436bap+3}, {-0x1.8050375e1f7c2p-1, -0x1.524ceff541368p-1}, 0x1.64381c464e6c2p+2, 1.000001216, -0.1451435697},
    {{0x1.01518c6b0cbc8p-1, -0x1.d96aa0d17ee24p+0}, {-0x1.291e336bc677ap-4, -0x1.fea6b479f6728p-1},  /* seed 777 #2472 */
     {0x1.91ba1a61b2defp-2, -0x1.6d3ce01bcbeb9p+1}, {-0x1.bf6130d3fcd8bp-4, -0x1.fcefd2ed8f70dp-1}, 0x1.cf013258edf83p+9, 1.00001547, -0.8395892575},
    {{0x1.2dea4a5d93f18p+0, -0x1.81135810d8b8cp+1}, {0x1.234573d1029a5p-1, -0x1.a513774c17257p-1},  /* seed 777 #2538 */
     {0x1.0ca60404fdb58p+1, -0x1.1b791efcafe51p+2}, {0x1.15237ab057515p-1, -0x1.ae825d3a9469cp-1}, 0x1.383c5f05dfbcp+8, 1.000011238, -0.6829223999},
    {{0x1.0276eb101054p+2, 0x1.3f743fcef557cp+1}, {0x1.c5851664f9d4bp-1, -0x1.db3defa07062cp-2},  /* seed 777 #2645 */
     {0x1.126deb4a082d5p+2, 0x1.2eaf407604affp+1}, {0x1.c5381147d548fp-1, -0x1.dc637b9698c9p-2}, 0x1.d8c12208e92c7p+12, 1.000000015, -0.01782049955},
    {{-0x1.d19fe47fba71ep+1, -0x1.ae27a02dca42p-1}, {0x1.e8f28e66fe1bbp-3, 0x1.f131bc04daa02p-1},  /* seed 777 #2809 */
     {-0x1.9d60a504745c2p+1, 0x1.4d260f769201p-1}, {0x1.11e366d8836d3p-2, 0x1.ed589529be4f4p-1}, 0x1.2fcd2c1bf63b4p+7, 1.000012798, -0.3791556246},
    {{0x1.76ce1e715e4d8p+0, -0x1.a4a32fbc7968p-5}, {-0x1.fffc6ca9bbf1ap-1, -0x1.e411bc764ed48p-8},  /* seed 777 #741 */
     {0x1.44bfbf0f1acafp+0, -0x1.bfb38e7f12cf4p-5}, {-0x1.ffebec24929c7p-1, -0x1.1ec29cd8fbdadp-6}, 0x1.adf755287a811p+13, 1.000001387, 0.1643718109},
};

START_TEST(near_straight_chains_at_the_limit_of_doubles)
{
    const int n = (int)(sizeof near_straight / sizeof near_straight[0]);
    double worst_jump = 0.0;
    for (int i = 0; i < n; i++) {
        const double *p0 = near_straight[i].p0, *t0 = near_straight[i].t0;
        const double *p1 = near_straight[i].p1, *t1 = near_straight[i].t1;
        const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = near_straight[i].sigma;
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        int found = 0;
        for (size_t j = 0; j < r.count; j++) {
            const el_hermite_solution *s = &r.solutions[j];
            if (!(fabs(s->length / d - near_straight[i].L) <= 1e-9 * near_straight[i].L &&
                  fabs(s->kappa0 * d - near_straight[i].k0) <= 1e-8 * (1.0 + fabs(near_straight[i].k0))))
                continue;
            found = 1;
            ck_assert_int_eq(s->npieces, 2);
            /* the ends to tol, the joint to 1e-12 (hermite_check.h's measures) */
            const el_smooth_params *pc[3];
            pieces_of(s, pc);
            double xy[2][4], th[2][2], kap[2][2];
            for (int k = 0; k < 2; k++) {
                const double sv[2] = {0.0, pc[k]->length};
                ck_assert_int_eq(el_smooth_eval(pc[k], 2, sv, xy[k], th[k], kap[k]), EL_OK);
            }
            ck_assert(hypot(xy[0][0] - p0[0], xy[0][1] - p0[1]) <= o.tol * d);
            ck_assert(fabs(wrap(th[0][0] - atan2(t0[1], t0[0]))) <= o.tol);
            ck_assert(hypot(xy[1][0] - xy[0][2], xy[1][1] - xy[0][3]) <= 1e-12 * d);
            ck_assert(fabs(wrap(th[1][0] - th[0][1])) <= 1e-12);
            ck_assert(hypot(xy[1][2] - p1[0], xy[1][3] - p1[1]) <= o.tol * d);
            ck_assert(fabs(wrap(th[1][1] - atan2(t1[1], t1[0]))) <= o.tol);
            /* the curvature's jump at the joint against the far loop's peak curvature
             * kappa_m = 2 |k| sqrt(mu) (hermite_chain.c: ~1e-8 of it), not against the
             * near-straight curve's own (check_solution's 1e-7 of max |kappa|, ~1e-3 of
             * kappa_m here, which b1c7360's chains of these problems exceed as well) */
            const double km = 2.0 * fabs(pc[0]->k) * sqrt(pc[0]->mu), jump = fabs(kap[0][1] - kap[1][0]) / km;
            ck_assert_msg(jump <= 1e-8, "problem %d: curvature jump %g of kappa_m", i, jump);
            worst_jump = fmax(worst_jump, jump);
        }
        ck_assert_msg(found, "problem %d: the curve L %.10g, kappa0 %.10g (|p1 - p0| = 1) is missing", i,
                      near_straight[i].L, near_straight[i].k0);
        el_hermite_result_free(&r);
    }
    fprintf(stderr, "near_straight_chains_at_the_limit_of_doubles: %d problems, curvature jumps up to %.2g of kappa_m\n",
            n, worst_jump);
}
END_TEST

/* n random length-mode problems near the chord (L / |p1 - p0| uniform in [1.02, Lmax]),
 * each result checked (ends to 1e-10, the given length, none unrepresentable): the
 * solutions, the chains and the one-piece curves within 1e-7 of |k| = 1 added to c[0..2]. */
static void solve_near_the_chord(unsigned long long st, int n, double Lmax, size_t c[3])
{
    for (int t = 0; t < n; t++) {
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.mode = EL_HERMITE_LENGTH;
        o.length = test_uniform(&st, 1.02, Lmax);
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        check_result(p0, t0, p1, t1, &r, 1e-10);
        ck_assert_uint_eq(r.unrepresentable, 0);
        for (size_t i = 0; i < r.count; i++) {
            const el_hermite_solution *s = &r.solutions[i];
            ck_assert_close(s->length, o.length, 1e-12 * o.length);
            c[1] += s->npieces > 1;
            c[2] += s->npieces == 1 && fabs(fabs(s->curve.k) - 1.0) < 1e-7;
        }
        c[0] += r.count;
        el_hermite_result_free(&r);
    }
}

/* Length mode near the chord (L = 1.02..1.05 |p1 - p0|): the solutions of high tension
 * (sigma |p1-p0|^2 up to ~1e5) come as chains where one piece cannot meet tol; every
 * one meets the ends and has the given length, none is unrepresentable. */
START_TEST(length_mode_near_the_chord_returns_chains)
{
    size_t c[3] = {0, 0, 0};
    solve_near_the_chord(555, 12, 1.05, c);
    ck_assert_uint_gt(c[1], 5);
    fprintf(stderr, "length_mode_near_the_chord_returns_chains: %zu solutions, %zu chains\n", c[0], c[1]);
}
END_TEST

/* The polish (hermite.c: Newton, then Gauss-Newton at the few doubles nearest k) brings
 * one-piece curves within 1e-7 of |k| = 1 to tol in length mode near the chord; it uses
 * one finite-difference Jacobian per polish (a chord method). On these 60 problems the
 * former Newton with a new Jacobian per step returned 235 solutions, 30 of them one
 * piece within 1e-7 of |k| = 1 (137 chains); without any polish 229, 1 and 176 (all
 * three with a tracer whose predictor was bent by the curvature of C; the tangent
 * predictor, which finds 9 more solutions in 8000 random length problems, finds one
 * fewer here: 234). */
START_TEST(polish_keeps_near_separatrix_curves_in_one_piece)
{
    size_t c[3] = {0, 0, 0};
    solve_near_the_chord(4242, 60, 1.3, c);
    ck_assert_uint_ge(c[0], 234);
    ck_assert_uint_ge(c[2], 30);
    fprintf(stderr, "polish_keeps_near_separatrix_curves_in_one_piece: %zu solutions, %zu one piece near |k| = 1\n",
            c[0], c[2]);
}
END_TEST

/* The separatrix samples of the tension solve start each Newton of el__hermite_sep_eval
 * from the previous sample's state (the fast path) and retry from the piece's guess
 * where that fails (hermite_tension.c piece_eval). Checked against the plain path, every
 * sample from the crossing itself, on the crossings (roots of (40)) of random problems
 * at sigma |p1-p0|^2 in [100, 1e4], NY samples per side down to |F| - sigma = 1e-300 sigma:
 * where the plain path gives a state, the fast path (with its retry) gives the same f. */
START_TEST(separatrix_warm_start_gives_the_plain_states)
{
    unsigned long long st = 4711;
    int nsamples = 0, nretry = 0;
    for (int t = 0; t < 60; t++) {
        double P[2], V[2], sigma;
        hprob pr;
        el_hermite_analysis an;
        high_tension_problem(&st, P, V, &sigma, &pr, &an);
        for (size_t i = 0; i < an.nroot; i++) {
            for (int side = -1; side <= 1; side += 2) {
                double warm = an.root[i];
                for (int j = 0; j < NY; j++) {
                    const double tt = (double)j / (NY - 1);
                    const double y = log(1e-3 * sigma) - 690.0 * (1.0 - tt) * (1.0 - tt);
                    hstate cold_st, warm_st;
                    hgrad g;
                    double wc = an.root[i], ww = warm;
                    if (el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma, 1.0, &wc,
                                             &cold_st, &g, NULL))
                        continue;
                    nsamples++;
                    if (el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma, 1.0, &ww,
                                             &warm_st, NULL, NULL)) {
                        nretry++;              /* the retry from the piece's guess: the plain path */
                        continue;
                    }
                    ck_assert_msg(fabs(warm_st.f - cold_st.f) <= 1e-9 * (1.0 + fabs(cold_st.f)) &&
                                      fabs(warm_st.L - cold_st.L) <= 1e-9 * cold_st.L,
                                  "sigma %g y %g: f %.17g (warm) vs %.17g", sigma, y, warm_st.f, cold_st.f);
                    warm = ww;
                }
            }
        }
    }
    printf("separatrix_warm_start_gives_the_plain_states: %d samples, %d retried\n", nsamples, nretry);
    ck_assert_int_gt(nsamples, 1000);
}
END_TEST

/* Issue 12: no solution lost for sigma |p1-p0|^2 in [0, 1e4]. Every root of the dense
 * scan above is a returned solution (meeting the ends to 1e-10, checked with
 * el_smooth_eval; one piece, or near the separatrix a chain split at its saddles) and
 * none is counted unrepresentable. Problems: sigma uniform in [0, 100], log-uniform in
 * [100, 1e3] and [1e3, 1e4], random end point and tangents (p0 = 0, t0 = (0, 1), |p1| = 1). */
START_TEST(no_solution_lost_up_to_high_tension)
{
    unsigned long long st = 2718;
    int nscan = 0, nret = 0, nchain = 0;
    for (int t = 0; t < 150; t++) {
        const double a = test_uniform(&st, -M_PI, M_PI), c = test_uniform(&st, -M_PI, M_PI);
        const double u = test_uniform(&st, 0.0, 1.0);
        const double sigma = t % 3 == 0 ? 100.0 * u : t % 3 == 1 ? 100.0 * pow(10.0, u) : 1e3 * pow(10.0, u);
        const double p0[2] = {0, 0}, t0[2] = {0, 1}, p1[2] = {cos(a), sin(a)}, t1[2] = {cos(c), sin(c)};
        scan_root r[MAXSCAN];
        el_hermite_result res;
        int n;
        if (!scan_and_solve(p1, t1, sigma, NX, r, &n, &res)) continue;
        check_result(p0, t0, p1, t1, &res, 1e-10);
        for (int i = 0; i < n; i++) {
            const int found = scan_root_found(&r[i], &res);
            ck_assert_msg(found, "sigma %g: the solution kappa0 %.10g, L %.10g of the scan is missing",
                          sigma, r[i].k0, r[i].L);
        }
        ck_assert_msg(res.unrepresentable == 0, "sigma %g: %zu counted unrepresentable", sigma,
                      res.unrepresentable);
        nscan += n;
        nret += (int)res.count;
        for (size_t j = 0; j < res.count; j++) nchain += res.solutions[j].npieces > 1;
        el_hermite_result_free(&res);
    }
    ck_assert_int_gt(nscan, 200);
    ck_assert_int_gt(nchain, 50);   /* the high tensions do need chains */
    fprintf(stderr, "no_solution_lost_up_to_high_tension: %d scan roots, %d returned, %d of them chains\n",
            nscan, nret, nchain);
}
END_TEST

/* The chains lie on the exact curve: tests/data/hermite_chain_ref.txt holds points
 * of exact solutions near the separatrix (sigma |p1-p0|^2 in [300, 1e4]), found at 90
 * digits by Newton on the first integrals (tests/data/gen_hermite_chain_ref.py); each
 * is among the returned solutions (same kappa0 and length), and the chain passes
 * within 1e-9 |p1 - p0| of every reference point (the header's ~5e-10: what a double
 * k near 1 allows) at the same arc length, up to a shift along the curve of the
 * size of its length's error. */
START_TEST(chains_lie_on_the_exact_curve)
{
    FILE *f = fopen("../data/hermite_chain_ref.txt", "r");
    ck_assert_msg(f != NULL, "tests/data/hermite_chain_ref.txt missing");
    int lines = 0, chains = 0;
    double worst = 0.0, P[2], V[2], sigma, L, k0, xy[22];
    int np;
    while (fscanf(f, "%lf %lf %lf %lf %lf %lf %lf %d", &P[0], &P[1], &V[0], &V[1], &sigma, &L, &k0, &np) == 8) {
        for (int j = 0; j < 22; j++) ck_assert_int_eq(fscanf(f, "%lf", &xy[j]), 1);
        lines++;
        const double p0[2] = {0, 0}, t0[2] = {0, 1};
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = sigma;
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, P, V, &o, &r), EL_OK);
        const el_hermite_solution *s = NULL;
        for (size_t i = 0; i < r.count && !s; i++)
            if (fabs(r.solutions[i].kappa0 - k0) <= 1e-6 * (1.0 + fabs(k0)) &&
                fabs(r.solutions[i].length - L) <= 1e-6 * L)
                s = &r.solutions[i];
        ck_assert_msg(s != NULL, "sigma %g: the exact solution kappa0 %.10g, L %.10g is not returned", sigma, k0, L);
        chains += s->npieces > 1;
        const el_smooth_params *pc[3];
        const int n = pieces_of(s, pc);
        for (int j = 0; j <= 10; j++) {
            /* the piece holding arc length t, and the distance across the curve */
            double t = s->length * j / 10.0, q[2], th;
            int i = 0;
            while (i + 1 < n && t > pc[i]->length) t -= pc[i++]->length;
            ck_assert_int_eq(el_smooth_eval(pc[i], 1, &t, q, &th, NULL), EL_OK);
            const double dx = q[0] - xy[2 * j], dy = q[1] - xy[2 * j + 1];
            worst = fmax(worst, fabs(dx * sin(th) - dy * cos(th)));
            ck_assert_msg(hypot(dx, dy) <= 1e-9 + 2.0 * fabs(s->length - L),
                          "sigma %g, point %d: %g from the exact curve", sigma, j, hypot(dx, dy));
        }
        el_hermite_result_free(&r);
    }
    fclose(f);
    ck_assert_int_ge(lines, 30);
    ck_assert_int_ge(chains, 30);
    ck_assert_msg(worst <= 1e-9, "a chain lies %g across from the exact curve", worst);
    fprintf(stderr, "chains_lie_on_the_exact_curve: %d solutions (%d chains), at most %.2g across\n",
            lines, chains, worst);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite");
    TCase *tc = tcase_create("hermite");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, paper_case1_example);
    tcase_add_test(tc, polynomial_40_roots_are_class_boundaries);
    tcase_add_test(tc, random_tension_problems_meet_the_ends);
    tcase_add_test(tc, random_length_problems_meet_the_ends);
    tcase_add_test(tc, length_mode_inverts_tension_mode);
    tcase_add_test(tc, mirrored_data_give_mirrored_solutions);
    tcase_add_test(tc, near_separatrix_solutions_meet_tol);
    tcase_add_test(tc, near_straight_chains_at_the_limit_of_doubles);
    tcase_add_test(tc, length_mode_near_the_chord_returns_chains);
    tcase_add_test(tc, polish_keeps_near_separatrix_curves_in_one_piece);
    tcase_add_test(tc, no_solution_lost_up_to_high_tension);
    tcase_add_test(tc, chains_lie_on_the_exact_curve);
    tcase_add_test(tc, separatrix_warm_start_gives_the_plain_states);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
