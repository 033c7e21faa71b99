/* Hermite interpolation by elastic curves (seed 004): every returned curve is
 * checked with the evaluator of smooth.c (ends, energy, inflections), the
 * paper's case-1 example of §5, the polynomial (40) by its defining property,
 * and the degenerate data of the issue. */
#include "testutil.h"
#include "hermite_internal.h"
#include "hermite_scan.h"
#include <stdio.h>
#include <string.h>

static double wrap(double a)
{
    a = fmod(a, 2.0 * M_PI);
    if (a > M_PI) a -= 2.0 * M_PI;
    if (a < -M_PI) a += 2.0 * M_PI;
    return a;
}

/* The pieces of a solution: curve, then rest[0..npieces-2]. */
static int pieces_of(const el_hermite_solution *s, const el_smooth_params **p)
{
    ck_assert_msg(s->npieces >= 1 && s->npieces <= 3, "npieces %d", s->npieces);
    p[0] = &s->curve;
    for (int i = 1; i < s->npieces; i++) p[i] = &s->rest[i - 1];
    for (int i = s->npieces; i < 3; i++) ck_assert(s->rest[i - 1].length == 0.0);
    return s->npieces;
}

/* Both ends met in the direction p0 -> p1 (position / |p1 - p0| and tangent
 * angle to tol), the orientation in the sign of k (a loop, |k| > 1, turns with
 * the sign of k), energy by el_smooth_energy, has_inflection by sampled
 * curvature, length = the sum of the pieces'. A chain's pieces follow each other
 * (position and tangent to 1e-12) and are the same elastica: the solution's tension
 * and the same |F| = 2 mu in every piece, force directions phi equal (mod 2 pi) and
 * curvature continuous to 1e-7 of the largest. */
static void check_solution(const double p0[2], const double t0[2], const double p1[2],
                           const double t1[2], const el_hermite_solution *s, double tol)
{
    const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    const double ta = atan2(t0[1], t0[0]), tb = atan2(t1[1], t1[0]);
    const el_smooth_params *pc[3];
    const int n = pieces_of(s, pc);
    double Lsum = 0.0, E = 0.0, xy[4], th[2], kap[2], prev[3] = {p0[0], p0[1], ta}, kprev = 0.0;
    double kend[3][2];
    for (int i = 0; i < n; i++) {
        ck_assert_int_eq(el_smooth_check(pc[i]), EL_OK);
        ck_assert(pc[i]->length > 0.0);
        const double sv[2] = {0.0, pc[i]->length};
        ck_assert_int_eq(el_smooth_eval(pc[i], 2, sv, xy, th, kap), EL_OK);
        const double gap = hypot(xy[0] - prev[0], xy[1] - prev[1]), turn = fabs(wrap(th[0] - prev[2]));
        if (i == 0) {
            ck_assert_msg(gap <= tol * d, "start point off by %g", gap);
            ck_assert_msg(turn <= tol, "start tangent off by %g", turn);
        } else {
            ck_assert_msg(gap <= 1e-12 * d && turn <= 1e-12, "joint %d: gap %g, turn %g", i, gap, turn);
            /* the same elastica: tension, |F| and its direction */
            const double si = 2.0 * pc[i]->mu * (2.0 * pc[i]->k * pc[i]->k - 1.0);
            ck_assert_close(si, s->sigma, 1e-12 * fabs(s->sigma));
            ck_assert_close(pc[i]->mu, pc[0]->mu, 1e-12 * pc[0]->mu);
            ck_assert_msg(fabs(wrap(pc[i]->phi - pc[0]->phi)) <= 1e-7, "joint %d: phi %.17g, %.17g", i,
                          pc[i]->phi, pc[0]->phi);
            kend[i - 1][1] = kap[0];
            kend[i - 1][0] = kprev;
        }
        prev[0] = xy[2]; prev[1] = xy[3]; prev[2] = th[1];
        kprev = kap[1];
        if (i == 0) ck_assert_close(kap[0], s->kappa0, fmax(1e-8, 100.0 * tol) * (1.0 + fabs(kap[0])));
        double e;
        ck_assert_int_eq(el_smooth_energy(pc[i], &e), EL_OK);
        E += e;
        Lsum += pc[i]->length;
    }
    ck_assert_msg(hypot(prev[0] - p1[0], prev[1] - p1[1]) <= tol * d, "end point off by %g (k %g, %d pieces)",
                  hypot(prev[0] - p1[0], prev[1] - p1[1]), s->curve.k, n);
    ck_assert_msg(fabs(wrap(prev[2] - tb)) <= tol, "end tangent off by %g", wrap(prev[2] - tb));
    ck_assert_close(Lsum, s->length, 1e-14 * s->length);
    if (n == 1) ck_assert_close(s->curve.length, s->length, 0.0);
    /* the end curvatures as reported, to 1e-8 (relative; looser with a looser tol) */
    const double ktol = fmax(1e-8, 100.0 * tol);
    ck_assert_close(kprev, s->kappa1, ktol * (1.0 + fabs(kprev)));
    ck_assert_close(E, s->energy, ktol * (1.0 + E));
    /* inflection: sign change of kappa on a fine grid of every piece; a loop's
     * curvature has the sign of k everywhere */
    enum { NS = 2001 };
    static double ss[NS], kk[3][NS];
    double kmax = 0.0;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < NS; j++) ss[j] = pc[i]->length * j / (NS - 1);
        ck_assert_int_eq(el_smooth_eval(pc[i], NS, ss, NULL, NULL, kk[i]), EL_OK);
        for (int j = 0; j < NS; j++) kmax = fmax(kmax, fabs(kk[i][j]));
        if (fabs(pc[i]->k) > 1.0) {
            ck_assert_msg(pc[i]->k * kk[i][0] > 0.0 && pc[i]->k * kk[i][NS - 1] > 0.0,
                          "loop k %g with kappa0 %g, kappa1 %g", pc[i]->k, kk[i][0], kk[i][NS - 1]);
            ck_assert_int_eq(s->has_inflection, 0);
        }
    }
    for (int i = 0; i + 1 < n; i++)
        ck_assert_msg(fabs(kend[i][0] - kend[i][1]) <= 1e-7 * kmax, "joint %d: curvature %g, %g (max %g)",
                      i + 1, kend[i][0], kend[i][1], kmax);
    int change = 0;
    double last = 0.0; /* sign changes among the samples that are not ~0 (ends may be zeros) */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < NS; j++) {
            if (fabs(kk[i][j]) <= 1e-7 * kmax) continue;
            if (last * kk[i][j] < 0.0) change = 1;
            last = kk[i][j];
        }
    ck_assert_msg(change == s->has_inflection, "has_inflection %d, sampled %d (k %g, L %g, kappa0 %g, kappa1 %g)",
                  s->has_inflection, change, s->curve.k, s->length, s->kappa0, s->kappa1);
}

static void check_result(const double p0[2], const double t0[2], const double p1[2],
                         const double t1[2], const el_hermite_result *r, double tol)
{
    for (size_t i = 0; i < r->count; i++) {
        check_solution(p0, t0, p1, t1, &r->solutions[i], tol);
        if (i > 0) ck_assert(r->solutions[i - 1].energy <= r->solutions[i].energy);
    }
}

/* Solve, check every solution, free; the number of solutions. */
static size_t solve_and_check(const double p0[2], const double t0[2], const double p1[2],
                              const double t1[2], const el_hermite_options *o, double tol)
{
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, o, &r), EL_OK);
    check_result(p0, t0, p1, t1, &r, tol);
    const size_t n = r.count;
    el_hermite_result_free(&r);
    return n;
}

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

/* ------------------------------------------------------------ degenerate data */

START_TEST(collinear_data_give_the_straight_segment)
{
    const double p0[2] = {1, 1}, t0[2] = {3, 4}, p1[2] = {4, 5}, t1[2] = {0.6, 0.8};
    const double sig[3] = {-3.0, 0.0, 5.0};
    for (int i = 0; i < 3; i++) {
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = sig[i];
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        ck_assert_uint_gt(r.count, 0);
        /* the lowest energy is the segment: k = 0, length 5, energy 0 */
        ck_assert_close(r.solutions[0].energy, 0.0, 1e-12);
        ck_assert_close(r.solutions[0].length, 5.0, 1e-12);
        ck_assert_int_eq(r.solutions[0].has_inflection, 0);
        check_result(p0, t0, p1, t1, &r, 1e-10);
        el_hermite_result_free(&r);
    }
    /* length mode with L = |p1 - p0|: only the segment */
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_LENGTH;
    o.length = 5.0;
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_eq(r.count, 1);
    ck_assert_close(r.solutions[0].curve.k, 0.0, 0.0);
    el_hermite_result_free(&r);
    /* buckled strip: L > |p1 - p0| with collinear data gives curved solutions (sigma < 0 among them) */
    o.length = 6.0;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_gt(r.count, 0);
    int compressed = 0;
    for (size_t i = 0; i < r.count; i++) compressed |= r.solutions[i].sigma < 0.0;
    ck_assert(compressed);
    check_result(p0, t0, p1, t1, &r, 1e-10);
    el_hermite_result_free(&r);
}
END_TEST

START_TEST(opposite_and_parallel_tangents)
{
    /* t1 = -t0 with p1 across (case 3 of Theorem 6) and t1 = t0 (case 2-like) */
    const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {0, 1}, m0[2] = {-1, 0};
    const double q1[2] = {1, 1};
    const double sig[4] = {-2.0, 0.0, 1.0, 9.0};
    size_t total = 0;
    for (int i = 0; i < 4; i++) {
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.sigma = sig[i];
        total += solve_and_check(p0, t0, p1, m0, &o, 1e-10);
        total += solve_and_check(p0, t0, q1, t0, &o, 1e-10);
    }
    ck_assert_uint_gt(total, 4);
}
END_TEST

START_TEST(circle_is_found_to_its_accuracy)
{
    /* the half circle of radius 1/2 is an elastica for sigma = kappa^2 = 4 */
    const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {0, 1}, t1[2] = {-1, 0};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = 4.0;
    o.tol = 1e-6;
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    int found = 0;
    for (size_t i = 0; i < r.count; i++)
        found |= fabs(r.solutions[i].length - M_PI / 2) < 1e-12 && fabs(r.solutions[i].kappa0 - 2.0) < 1e-12;
    ck_assert(found);
    check_result(p0, t0, p1, t1, &r, 1e-6);
    el_hermite_result_free(&r);
}
END_TEST

/* The semicircle between antiparallel tangents, (2, 0) heading (0, -1) to (0, 0)
 * heading (0, 1), radius 1: an elastica for sigma = 1 (length pi, energy pi) that one
 * el_smooth_params meets only to ~1e-8 (the k -> infinity limit): at the default
 * tol it must be counted as unrepresentable, not silently dropped (tension and length). */
START_TEST(semicircle_counted_not_dropped)
{
    const double p0[2] = {2, 0}, t0[2] = {0, -1}, p1[2] = {0, 0}, t1[2] = {0, 1};
    for (int mode = 0; mode < 2; mode++) {
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.mode = mode ? EL_HERMITE_LENGTH : EL_HERMITE_TENSION;
        o.sigma = 1.0;
        o.length = M_PI;
        el_hermite_result r;
        const int rc = el_hermite_solve(p0, t0, p1, t1, &o, &r);
        ck_assert_int_eq(rc, EL_OK);
        int found = 0;
        for (size_t i = 0; i < r.count; i++)
            found |= fabs(r.solutions[i].length - M_PI) < 1e-9 && fabs(r.solutions[i].energy - M_PI) < 1e-6;
        ck_assert_msg(found || r.unrepresentable >= 1, "mode %d: the semicircle is lost", mode);
        el_hermite_result_free(&r);
        /* at a tol it meets, it is a solution */
        o.tol = 1e-6;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
        found = 0;
        for (size_t i = 0; i < r.count; i++)
            found |= fabs(r.solutions[i].length - M_PI) < 1e-9 && fabs(r.solutions[i].energy - M_PI) < 1e-6;
        ck_assert_msg(found, "mode %d: the semicircle at tol 1e-6", mode);
        el_hermite_result_free(&r);
    }
}
END_TEST

/* A length-mode problem (random, bench-like) where the trace used to step over a pair
 * of solutions at sigma ~ 666 and ~ 733 (L changing fast along the curve of solutions):
 * each must be found, and each is a solution of the tension mode at its sigma. */
START_TEST(length_mode_close_pair_where_length_varies_fast)
{
    const double a = 1.1279159307184674, b = -1.5291763854072054;
    const double p0[2] = {0, 0}, p1[2] = {0.19054130743500819, -0.19303363065595369};
    const double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
    const double want[2] = {665.711544036, 732.8718963};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_LENGTH;
    o.length = 0.53351931374167216;
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    check_result(p0, t0, p1, t1, &r, o.tol);
    for (int k = 0; k < 2; k++) {
        int found = 0;
        for (size_t i = 0; i < r.count; i++)
            found |= fabs(r.solutions[i].sigma - want[k]) < 1e-6 * want[k];
        ck_assert_msg(found, "the solution at sigma %g is lost", want[k]);
        el_hermite_options ot;
        el_hermite_options_defaults(&ot);
        ot.sigma = want[k];
        el_hermite_result rt;
        ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &ot, &rt), EL_OK);
        found = 0;
        for (size_t i = 0; i < rt.count; i++) found |= fabs(rt.solutions[i].length - o.length) < 1e-8;
        ck_assert(found);
        el_hermite_result_free(&rt);
    }
    el_hermite_result_free(&r);
}
END_TEST

START_TEST(bad_input_and_clear_statuses)
{
    const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {1, 0.5}, t1[2] = {0, 1}, z[2] = {0, 0};
    const double nanv[2] = {NAN, 0};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    el_hermite_result r = {7, NULL, 0};
    ck_assert_int_eq(el_hermite_solve(NULL, t0, p1, t1, &o, &r), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve(p0, z, p1, t1, &o, &r), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve(p0, t0, nanv, t1, &o, &r), EL_EINVAL);
    ck_assert_uint_eq(r.count, 7); /* untouched on EL_EINVAL */
    /* p0 = p1: the normalisation |P| = 1 of seed 004 is impossible */
    ck_assert_int_eq(el_hermite_solve(p0, t0, p0, t1, &o, &r), EL_EDOM);
    /* length shorter than the chord */
    o.mode = EL_HERMITE_LENGTH;
    o.length = 0.5;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_EDOM);
    o.length = -1.0;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_EINVAL);
    o.mode = 7;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_EINVAL);
    /* strong compression: the period 4 sqrt2 K(1/sqrt2)/sqrt(-sigma) < |p1 - p0|, no curve */
    el_hermite_options_defaults(&o);
    o.sigma = -500.0;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_eq(r.count, 0);
    el_hermite_result_free(&r);
    el_hermite_result_free(NULL);
    el_hermite_analysis a;
    const double P[2] = {2, 0}, V[2] = {0, 1};
    ck_assert_int_eq(el_hermite_analyse(P, V, 1.0, &a), EL_EINVAL);
}
END_TEST

/* Every status of el_hermite_solve / el_hermite_analyse the header lists, each from
 * the input that causes it; EL_EINVAL leaves res untouched, EL_EDOM empties it. */
START_TEST(each_status_from_its_cause)
{
    const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {1, 0.5}, t1[2] = {0, 1};
    el_hermite_options o;
    el_hermite_result r = {5, NULL, 3};
    /* bad options: EL_EINVAL, res untouched */
    struct { int which; double v; } bad[] = {
        {0, 2.0}, {1, NAN}, {1, INFINITY}, {2, 0.0}, {2, -1e-10}, {2, NAN}, {3, 3}, {3, 1001},
        {4, 0}, {4, 257}, {5, 0}, {6, 0.0}, {6, -2.0}, {6, NAN}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        el_hermite_options_defaults(&o);
        switch (bad[i].which) {
        case 0: o.mode = (int)bad[i].v; break;
        case 1: o.sigma = bad[i].v; break;
        case 2: o.tol = bad[i].v; break;
        case 3: o.samples = (int)bad[i].v; break;
        case 4: o.grid = (int)bad[i].v; break;
        case 5: o.max_solutions = (size_t)bad[i].v; break;
        default: o.mode = EL_HERMITE_LENGTH; o.length = bad[i].v; break;
        }
        ck_assert_msg(el_hermite_solve(p0, t0, p1, t1, &o, &r) == EL_EINVAL, "bad option %zu accepted", i);
        ck_assert_uint_eq(r.count, 5);
        ck_assert_uint_eq(r.unrepresentable, 3);
    }
    /* the limits themselves are accepted */
    el_hermite_options_defaults(&o);
    o.samples = 4; o.grid = 1; o.max_solutions = 1;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_le(r.count, 1);
    el_hermite_result_free(&r);
    o.samples = 1000; o.grid = 256;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    el_hermite_result_free(&r);
    /* outside the range: EL_EDOM, res empty */
    el_hermite_options_defaults(&o);
    const double far[2] = {2e100, 0}, near[2] = {1e-101, 0}, big1[2] = {6e99, 0}, big2[2] = {-6e99, 1e99};
    r.count = 5;
    ck_assert_int_eq(el_hermite_solve(p0, t0, far, t1, &o, &r), EL_EDOM);      /* coordinate > 1e100 */
    ck_assert_uint_eq(r.count, 0);
    ck_assert_int_eq(el_hermite_solve(p0, t0, near, t1, &o, &r), EL_EDOM);     /* |p1 - p0| < 1e-100 */
    ck_assert_int_eq(el_hermite_solve(big1, t0, big2, t1, &o, &r), EL_EDOM);   /* |p1 - p0| > 1e100 */
    o.sigma = 1.01e5 / 1.25;                                                    /* sigma |p1 - p0|^2 > 1e5 */
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_EDOM);
    o.sigma = 0.99e5 / 1.25;                                                    /* just inside: solved */
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    el_hermite_result_free(&r);
    o.sigma = -1e300;                                                           /* no curve, not an error */
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, &r), EL_OK);
    ck_assert_uint_eq(r.count, 0);
    el_hermite_result_free(&r);
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_LENGTH;
    const double tiny[2] = {1e-90, 0};
    o.length = 1e300;                                                           /* length / |p1 - p0| overflows */
    ck_assert_int_eq(el_hermite_solve(p0, t0, tiny, t1, &o, &r), EL_EDOM);
    /* the tiny and huge scales inside the range are solved like the unit one */
    el_hermite_options_defaults(&o);
    o.sigma = 7.0;
    const double q1[2] = {1.5, 0.7}, q0[2] = {0, 0}, u0[2] = {1, 0.2}, u1[2] = {-0.3, 1};
    size_t n1 = solve_and_check(q0, u0, q1, u1, &o, 1e-10);
    for (int e = -90; e <= 90; e += 60) {
        const double sc = pow(10.0, e), s1[2] = {1.5 * sc, 0.7 * sc};
        o.sigma = 7.0 / (sc * sc);
        ck_assert_uint_eq(solve_and_check(q0, u0, s1, u1, &o, 1e-10), n1);
    }
    /* analyse: EL_EINVAL, EL_EDOM */
    el_hermite_analysis a;
    const double P[2] = {0.6, 0.8}, V[2] = {0, 1}, P2[2] = {0.6, 0.81};
    ck_assert_int_eq(el_hermite_analyse(NULL, V, 1.0, &a), EL_EINVAL);
    ck_assert_int_eq(el_hermite_analyse(P2, V, 1.0, &a), EL_EINVAL);
    ck_assert_int_eq(el_hermite_analyse(P, V, NAN, &a), EL_EINVAL);
    ck_assert_int_eq(el_hermite_analyse(P, V, 2e5, &a), EL_EDOM);
    ck_assert_int_eq(el_hermite_analyse(P, V, -1e300, &a), EL_OK);
    ck_assert(a.kappa_bound < 0.0);
}
END_TEST

/* Every field of two solutions equal (the same solver run twice is deterministic);
 * not memcmp: the structs' padding bytes are not part of the result. */
static void assert_same_solution(const el_hermite_solution *a, const el_hermite_solution *b)
{
    const el_smooth_params *pa[3] = {&a->curve, &a->rest[0], &a->rest[1]};
    const el_smooth_params *pb[3] = {&b->curve, &b->rest[0], &b->rest[1]};
    for (int i = 0; i < 3; i++)
        ck_assert(pa[i]->x0 == pb[i]->x0 && pa[i]->y0 == pb[i]->y0 && pa[i]->phi == pb[i]->phi &&
                  pa[i]->mu == pb[i]->mu && pa[i]->k == pb[i]->k && pa[i]->q == pb[i]->q &&
                  pa[i]->length == pb[i]->length);
    ck_assert(a->length == b->length && a->sigma == b->sigma && a->energy == b->energy &&
              a->has_inflection == b->has_inflection && a->kappa0 == b->kappa0 &&
              a->kappa1 == b->kappa1 && a->residual == b->residual && a->npieces == b->npieces);
}

/* el_hermite_solve_into gives el_hermite_solve's solutions (chains and unrepresentable
 * counts included: tension up to sigma d^2 = 3000, length mode, the semicircle at a tol
 * it misses), only the first cap of them when the array is shorter (with the full count),
 * the count alone with cap 0; EL_EINVAL writes nothing, EL_EDOM zero counts. */
START_TEST(solve_into_gives_the_solutions_of_solve)
{
    unsigned long long st = 777;
    el_hermite_solution into[64];
    size_t total = 0, chains = 0, unrep = 0;
    for (int t = 0; t < 60; t++) {
        double p0[2] = {test_uniform(&st, -3, 3), test_uniform(&st, -3, 3)};
        double p1[2] = {test_uniform(&st, -3, 3), test_uniform(&st, -3, 3)};
        const double a = test_uniform(&st, -M_PI, M_PI), b = test_uniform(&st, -M_PI, M_PI);
        double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        if (t % 3 == 2) {
            o.mode = EL_HERMITE_LENGTH;
            o.length = d * test_uniform(&st, 1.05, 3.0);
        } else {
            o.sigma = test_uniform(&st, -10.0, t % 3 ? 3000.0 : 40.0) / (d * d);
        }
        if (t == 0) {   /* the semicircle, unrepresentable at the default tol */
            p0[0] = 2; p0[1] = 0; t0[0] = 0; t0[1] = -1; p1[0] = 0; p1[1] = 0; t1[0] = 0; t1[1] = 1;
            o.sigma = 1.0;
        }
        el_hermite_result r;
        const int rc = el_hermite_solve(p0, t0, p1, t1, &o, &r);
        size_t count = 99, nu = 99;
        ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, into, 64, &count, &nu), rc);
        ck_assert_uint_eq(count, r.count);
        ck_assert_uint_eq(nu, r.unrepresentable);
        for (size_t i = 0; i < r.count; i++) {
            assert_same_solution(&into[i], &r.solutions[i]);
            chains += r.solutions[i].npieces > 1;
        }
        /* a shorter array: its cap lowest-energy solutions, the full count */
        if (r.count > 1) {
            el_hermite_solution few[2];
            few[1].npieces = -7;   /* not written */
            ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, few, 1, &count, &nu), rc);
            ck_assert_uint_eq(count, r.count);
            assert_same_solution(&few[0], &r.solutions[0]);
            ck_assert_int_eq(few[1].npieces, -7);
        }
        ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, NULL, 0, &count, &nu), rc);
        ck_assert_uint_eq(count, r.count);
        total += r.count;
        unrep += r.unrepresentable;
        el_hermite_result_free(&r);
    }
    ck_assert_uint_gt(total, 100);
    ck_assert_uint_gt(chains, 0);
    ck_assert_uint_gt(unrep, 0);
    /* EL_EINVAL writes nothing (its own NULLs and el_hermite_solve's); EL_EDOM zero counts */
    const double p0[2] = {0, 0}, t0[2] = {1, 0}, p1[2] = {1, 0.5}, t1[2] = {0, 1}, nanv[2] = {NAN, 0};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    size_t count = 5, nu = 3;
    into[0].npieces = -7;
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, into, 1, NULL, &nu), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, into, 1, &count, NULL), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, &o, NULL, 1, &count, &nu), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, nanv, t1, &o, into, 1, &count, &nu), EL_EINVAL);
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, p1, t1, NULL, into, 1, &count, &nu), EL_EINVAL);
    ck_assert(count == 5 && nu == 3 && into[0].npieces == -7);
    ck_assert_int_eq(el_hermite_solve_into(p0, t0, p0, t1, &o, into, 1, &count, &nu), EL_EDOM);
    ck_assert(count == 0 && nu == 0 && into[0].npieces == -7);
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
    tcase_add_test(tc, length_mode_near_the_chord_returns_chains);
    tcase_add_test(tc, polish_keeps_near_separatrix_curves_in_one_piece);
    tcase_add_test(tc, no_solution_lost_up_to_high_tension);
    tcase_add_test(tc, chains_lie_on_the_exact_curve);
    tcase_add_test(tc, collinear_data_give_the_straight_segment);
    tcase_add_test(tc, opposite_and_parallel_tangents);
    tcase_add_test(tc, circle_is_found_to_its_accuracy);
    tcase_add_test(tc, semicircle_counted_not_dropped);
    tcase_add_test(tc, separatrix_warm_start_gives_the_plain_states);
    tcase_add_test(tc, length_mode_close_pair_where_length_varies_fast);
    tcase_add_test(tc, bad_input_and_clear_statuses);
    tcase_add_test(tc, each_status_from_its_cause);
    tcase_add_test(tc, solve_into_gives_the_solutions_of_solve);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
