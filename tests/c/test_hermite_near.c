/* The near-straight Hermite solution under tension (hermite_near.c): the linear beam
 * against its defining equation, and the solution present at every tension from 10 to
 * EL_HERMITE_SIGMA_D2_MAX between tangents near the chord, checked (hermite_check.h),
 * against the beam's start curvature, and mirrored problems giving mirrored sets. */
#include "testutil.h"
#include "hermite_internal.h"
#include "hermite_check.h"
#include <stdio.h>

/* theta(s) of the beam and its derivatives kappa, kappa', kappa'' (closed form) */
static void beam_at(const hbeam *b, double s, double v[4])
{
    const double e0 = exp(-b->g * s), e1 = exp(-b->g * (1.0 - s)), g = b->g;
    v[0] = b->c + b->alpha * e0 + b->beta * e1;
    for (int j = 1; j < 4; j++) {
        const double gj = pow(g, j);
        v[j] = gj * ((j % 2 ? -1.0 : 1.0) * b->alpha * e0 + b->beta * e1);
    }
}

/* kappa'' = sigma kappa / 2 (by central differences of kappa), theta(0) = t0, theta(1) = t1,
 * int theta = 0 and L = 1 + int theta^2 / 2 (Simpson, 4000 intervals), |F| - sigma
 * = kappa'^2 / g^2 - kappa^2 at two points, and kappa0, kappa0' the beam's at s = 0 */
START_TEST(linear_beam_satisfies_its_equations)
{
    const double sig[] = {3.0, 10.0, 100.0, 3000.0, 1e5};
    const double tt[][2] = {{1e-3, 1e-3}, {1e-3, -1e-3}, {2e-3, 0.0}, {-1e-4, 3e-4}};
    for (size_t i = 0; i < sizeof sig / sizeof sig[0]; i++)
        for (size_t j = 0; j < sizeof tt / sizeof tt[0]; j++) {
            hbeam b;
            ck_assert_int_eq(el__hermite_near_beam(sig[i], tt[j][0], tt[j][1], &b), EL_OK);
            double v0[4], v1[4];
            beam_at(&b, 0.0, v0);
            beam_at(&b, 1.0, v1);
            const double a = fabs(tt[j][0]) + fabs(tt[j][1]);
            ck_assert(fabs(v0[0] - tt[j][0]) <= 1e-14 * a && fabs(v1[0] - tt[j][1]) <= 1e-14 * a);
            ck_assert(fabs(b.k0 - v0[1]) <= 1e-13 * fabs(v0[1]) && fabs(b.k0p - v0[2]) <= 1e-13 * fabs(v0[2]));
            const int n = 4000;
            double I = 0.0, I2 = 0.0;
            for (int m = 0; m <= n; m++) {
                double v[4];
                beam_at(&b, (double)m / n, v);
                const double w = (m == 0 || m == n ? 1.0 : m % 2 ? 4.0 : 2.0) / (3.0 * n);
                I += w * v[0];
                I2 += w * v[0] * v[0];
            }
            const double simpson = pow(b.g / n, 4) * 10.0;   /* the rule's error scale */
            ck_assert_msg(fabs(I) <= (1e-13 + simpson) * a, "sigma %g: int theta %g", sig[i], I);
            /* the closed form's terms are ~ (theta / g^2)^2 where g is small: rounding at that
             * scale, and L's own rounding (an ulp of 1) */
            const double cancel = 1.0 + pow(b.g, -4.0);
            ck_assert_msg(fabs(b.L - 1.0 - 0.5 * I2) <= (1e-12 * cancel + simpson) * a * a + 4e-16,
                          "sigma %g: L - 1 %.12e against %.12e",
                          sig[i], b.L - 1.0, 0.5 * I2);
            for (double s = 0.2; s < 1.0; s += 0.5) {
                double v[4], vp[4], vm[4];
                const double h = 1e-3 / b.g;
                beam_at(&b, s, v);
                beam_at(&b, s + h, vp);
                beam_at(&b, s - h, vm);
                const double kpp = (vp[1] - 2.0 * v[1] + vm[1]) / (h * h);
                const double rhs = 0.5 * sig[i] * v[1];
                ck_assert_msg(fabs(kpp - rhs) <= 1e-5 * (fabs(kpp) + fabs(rhs)),
                              "sigma %g s %g: kappa'' %g, sigma kappa / 2 %g", sig[i], s, kpp, rhs);
                const double sep = v[2] * v[2] / (b.g * b.g) - v[1] * v[1];
                const double bsep = b.side * exp(b.lnsep);
                ck_assert_msg(b.side != 0 && fabs(bsep - sep) <= 1e-9 * v[1] * v[1] + 1e-12 * fabs(sep),
                              "sigma %g s %g: |F| - sigma %g against %g", sig[i], s, bsep, sep);
            }
        }
}
END_TEST

/* The near-straight solution of p0, t0 -> p1, t1 (length within 1e-3 of the chord) */
static const el_hermite_solution *near_straight(const el_hermite_result *r, double d)
{
    for (size_t k = 0; k < r->count; k++)
        if (fabs(r->solutions[k].length - d) <= 1e-3 * d) return &r->solutions[k];
    return NULL;
}

/* The problem (chord at angle chi, length d, tangents a0, a1 off it; mirrored in the x axis)
 * solved; its ends into p[0..7] (p0, t0, p1, t1) */
static void solve_at(double chi, double d, double a0, double a1, double sd2, int mirror, double p[8],
                     el_hermite_result *r)
{
    const double m = mirror ? -1.0 : 1.0;
    const double v[8] = {0.5, -1.0, cos(m * (chi + a0)), sin(m * (chi + a0)), 0.5 + d * cos(m * chi),
                         -1.0 + d * sin(m * chi), cos(m * (chi + a1)), sin(m * (chi + a1))};
    for (int i = 0; i < 8; i++) p[i] = v[i];
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = sd2 / (d * d);
    ck_assert_int_eq(el_hermite_solve(p, p + 2, p + 4, p + 6, &o, r), EL_OK);
}

/* Tangents 1e-9 to 1e-2 rad off the chord (parallel, symmetric, one-sided; both signs), sigma
 * |p1 - p0|^2 from -70 (the clamped beam buckles at -8 pi^2) to 1e5: the near-straight curve
 * is returned, the least energy, or counted in unrepresentable where no representation meets
 * tol (main lost it silently in 223 of 528 such QA problems at
 * sigma |p1 - p0|^2 10 to 3000, 1e-9 to 1e-4 rad); its ends, energy, curvature and joints
 * checked (hermite_check.h); above 0 its start curvature the linear beam's to O(theta^2 +
 * 1/(sigma |p1 - p0|^2)) (or a chain's known error); the mirrored problem has it too. */
START_TEST(near_straight_curve_at_every_tension)
{
    const double offs[] = {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2};
    const double sd2[] = {-70.0, -50.0, -30.0, -10.0, -3.0, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1e3, 3e3,
                          1e4, 3e4, 1e5};
    const double chi = 0.3, d = 2.0;
    int n = 0, chains = 0, unrep = 0, mirror_split = 0;
    double worst = 0.0;
    for (size_t i = 0; i < sizeof offs / sizeof offs[0]; i++)
        for (int sg = -1; sg <= 1; sg += 2)
            for (int shape = 0; shape < 3; shape++)
                for (size_t j = 0; j < sizeof sd2 / sizeof sd2[0]; j++) {
                    const double a0 = sg * offs[i], a1 = shape == 0 ? a0 : shape == 1 ? -a0 : 0.0;
                    el_hermite_result r, q;
                    double pr[8], pq[8];
                    solve_at(chi, d, a0, a1, sd2[j], 0, pr, &r);
                    solve_at(chi, d, a0, a1, sd2[j], 1, pq, &q);
                    const el_hermite_solution *s = near_straight(&r, d);
                    ck_assert_msg((s != NULL && s == &r.solutions[0]) || (s == NULL && r.unrepresentable >= 1),
                                  "a0 %g a1 %g sigma d^2 %g: no near-straight curve first among %zu (%zu "
                                  "unrepresentable)", a0, a1, sd2[j], r.count, r.unrepresentable);
                    hbeam b;
                    ck_assert_int_eq(el__hermite_near_beam(fabs(sd2[j]), a0, a1, &b), EL_OK);
                    unrep += s == NULL;
                    /* ends, energy, curvature, a chain's joints (the other solutions: the tests of
                     * test_hermite*.c) */
                    if (s) check_solution(pr, pr + 2, pr + 4, pr + 6, s, 1e-10);
                    const el_hermite_solution *sm = near_straight(&q, d);
                    if (sm) check_solution(pq, pq + 2, pq + 4, pq + 6, sm, 1e-10);
                    /* to 3 %, or a chain's curvature error, ~1e-8 kappa_m (hermite_chain.c; main's own
                     * chains at tangents 1e-7 rad, sigma |p1 - p0|^2 = 30: 21 % of kappa0) */
                    const double kmd = sqrt(2.0 * fabs(sd2[j]));
                    const double rel = s ? fabs(s->kappa0 * d - b.k0) / fabs(b.k0) : 0.0;
                    ck_assert_msg(sd2[j] < 0.0 || rel <= 3e-2 ||
                                      (s->npieces > 1 && fabs(s->kappa0 * d - b.k0) <= 2e-8 * kmd),
                                  "a0 %g a1 %g sigma d^2 %g: kappa0 d %.10g, the beam's %.10g", a0, a1, sd2[j],
                                  s->kappa0 * d, b.k0);
                    if (s && s->npieces == 1 && sd2[j] > 0.0) worst = fmax(worst, rel);
                    chains += s && s->npieces > 1;
                    /* the near-straight curve mirrored: returned or counted on both sides (the
                     * roots' own chain can meet tol on one side only: main's, e.g. tangents -+1e-7
                     * rad at sigma |p1 - p0|^2 = 1), the same energy where both return it (to 1e-8,
                     * or to the rounding of a chain's pieces, whose energies ~sqrt(sigma) |p1 - p0|
                     * cancel to its ~theta^2: 1e-12 of that). (The other solutions' sets can differ:
                     * main's, e.g. tangents +-1e-6 rad at sigma |p1 - p0|^2 = 1e3, 2 loops counted
                     * unrepresentable on one side only.) */
                    ck_assert_msg(sm != NULL || q.unrepresentable >= 1, "a0 %g a1 %g sigma d^2 %g: mirrored, no "
                                  "near-straight curve among %zu (%zu unrepresentable)", a0, a1, sd2[j], q.count,
                                  q.unrepresentable);
                    if (s && sm)
                        ck_assert_msg(fabs(s->energy - sm->energy) <=
                                          1e-8 * s->energy + 1e-12 * sqrt(fabs(sd2[j])) / d,
                                      "a0 %g a1 %g sigma d^2 %g: energy %.12g, mirrored %.12g", a0, a1, sd2[j],
                                      s->energy, sm->energy);
                    mirror_split += q.count != r.count || q.unrepresentable != r.unrepresentable;
                    el_hermite_result_free(&r);
                    el_hermite_result_free(&q);
                    n++;
                }
    fprintf(stderr, "near_straight_curve_at_every_tension: %d problems (and their mirrors), %d as chains, %d "
            "counted unrepresentable, %d whose other solutions differ from the mirror's, single pieces' "
            "kappa0 within %.2g of the beam's\n",
            n, chains, unrep, mirror_split, worst);
}
END_TEST

/* Below sigma = 0 next to the centre kappa_m^2 = |F| + sigma cancels (hermite.c,
 * el__hermite_params_from_state): the curve from a start state (kappa, kappa') ~1e-9 at
 * sigma |p1 - p0|^2 = -10 has that state at s = 0 (kappa by el_smooth_eval, kappa' by a
 * central difference) and the force (8) of the state, |F| = 2 mu = kappa_m^2 - sigma with
 * kappa_m = 2 |k| sqrt(mu) (main: EL_EDOM, kappa_m^2 rounded to 0, below ~1e-8) */
START_TEST(state_next_to_the_centre_below_zero)
{
    const double sig[] = {-3.0, -10.0, -50.0}, kap[] = {1e-9, 3e-9, 1e-8, 1e-7};
    for (size_t i = 0; i < sizeof sig / sizeof *sig; i++)
        for (size_t j = 0; j < sizeof kap / sizeof *kap; j++) {
            const double k0 = kap[j], k0p = -2.0 * kap[j], s = sig[i];
            el_smooth_params p;
            ck_assert_int_eq(el__hermite_params_from_state(0.0, 0.0, 0.3, k0, k0p, s, 1.0, NULL, &p), EL_OK);
            const double h = 1e-4, sv[3] = {0.0, h, 2.0 * h};
            double kv[3];
            ck_assert_int_eq(el_smooth_eval(&p, 3, sv, NULL, NULL, kv), EL_OK);
            const double dk = (-3.0 * kv[0] + 4.0 * kv[1] - kv[2]) / (2.0 * h);
            ck_assert_msg(fabs(kv[0] - k0) <= 1e-6 * k0, "sigma %g kappa %g: kappa(0) %.10g", s, k0, kv[0]);
            ck_assert_msg(fabs(dk - k0p) <= 1e-4 * fabs(k0p), "sigma %g: kappa'(0) %.10g against %g", s, dk, k0p);
            const double Fn = hypot(k0 * k0 - s, 2.0 * k0p), km = 2.0 * fabs(p.k) * sqrt(p.mu);
            ck_assert_msg(fabs(2.0 * p.mu - Fn) <= 1e-14 * Fn, "sigma %g: 2 mu %.17g, |F| %.17g", s, 2.0 * p.mu, Fn);
            const double km2 = k0 * k0 * (k0 * k0 - 2.0 * s) + 4.0 * k0p * k0p;   /* (|F| + sigma)(|F| - sigma) */
            ck_assert_msg(fabs(km * km * (Fn - s) - km2) <= 1e-12 * km2, "sigma %g kappa %g: kappa_m^2 %.10g", s, k0,
                          km * km);
        }
}
END_TEST

/* Where main lost the near-straight curve silently (neither returned nor counted): tiny
 * tensions |sigma| |p1 - p0|^2 1e-14..1e-10 with tangents 1e-9..1e-6 rad off the chord (7
 * of the QA's bows at 1e-14..1e-11; the sigma = 0 sliver's limit, el_hermite_solve, was only
 * counted at 0), below 0 tangents 1e-10..3e-9 rad (kappa_m^2 = |F| + sigma cancelled),
 * tangents tol = 1e-10 rad off (collinear by rounding, the segment dropped at its residual
 * ~tol) and 1e-2 rad off a chord at 0.3 rad (0.01000000000000001 from the world's angles,
 * outside the near-straight range), the bow's tangents -+1e-10 rad at 1e-4 (k rounded to 1,
 * residual 1.2e-8), tangents 1e-6 rad and 0 at 1e5 on a chord at -1 rad (no curve at all;
 * found on the mirrored chord at 1 rad): each returned (checked, hermite_check.h) or counted
 * in unrepresentable, on chords at 0.3 and 1 rad and their mirror images */
START_TEST(near_straight_never_silently_missing)
{
    const double offs[] = {1e-10, 1e-9, 3e-9, 1e-8, 1e-7, 1e-6, 1e-2};
    const double sd2[] = {-50.0, -10.0, -3.0, -1e-14, 0.0, 1e-14, 1e-13, 1e-12, 1e-11, 1e-10, 1e-6, 1e-4, 1e5};
    int n = 0, unrep = 0;
    for (size_t i = 0; i < sizeof offs / sizeof *offs; i++)
        for (int sg = -1; sg <= 1; sg += 2)
            for (int shape = 0; shape < 3; shape++)
                for (size_t j = 0; j < sizeof sd2 / sizeof *sd2; j++)
                    for (int m = 0; m < 4; m++) {
                        const double a0 = sg * offs[i], a1 = shape == 0 ? a0 : shape == 1 ? -a0 : 0.0;
                        el_hermite_result r;
                        double p[8];
                        solve_at(m < 2 ? 0.3 : 1.0, 2.0, a0, a1, sd2[j], m % 2, p, &r);
                        const el_hermite_solution *s = near_straight(&r, 2.0);
                        ck_assert_msg(s != NULL || r.unrepresentable >= 1, "a0 %g a1 %g sigma d^2 %g mirror %d: no "
                                      "near-straight curve among %zu, none counted", a0, a1, sd2[j], m, r.count);
                        /* (the segment at tangents tol off ends tol d off: to tol and the coordinates'
                         * rounding, ~ulp(|p1|) / d, which the header puts on top of tol) */
                        if (s) check_solution(p, p + 2, p + 4, p + 6, s, 1e-10 + 1e-15);
                        unrep += s == NULL;
                        n++;
                        el_hermite_result_free(&r);
                    }
    fprintf(stderr, "near_straight_never_silently_missing: %d problems, %d counted unrepresentable\n", n, unrep);
}
END_TEST

/* A chain is one elastica: its pieces share the force F, direction phi (hermite_check.h).
 * Every chain returned between tangents 3e-8 to 1e-2 rad off a chord at 0.3 rad, sigma
 * |p1 - p0|^2 35 to 1e5, checked: main returned 254 of them (of 44 064 problems) whose
 * pieces' phi differ by 2.6e-7 rad (near-straight, tangents 1e-4 rad at 35) up to 0.9 rad mod
 * 2 pi (tangents -1e-6, +1e-6 rad at 1e5, phi 22.29 and 46.88), the ends met: the
 * correction's phases turn a piece placed by its tangent (hermite_chain.c) */
START_TEST(chains_share_one_force)
{
    const double offs[] = {3e-8, 3e-7, 1e-6, 1e-4, 3e-4, 1e-3, 3e-3, 1e-2};
    const double sd2[] = {35.0, 60.0, 3e3, 1e4, 1e5};
    int chains = 0;
    for (size_t i = 0; i < sizeof offs / sizeof *offs; i++)
        for (int sg = -1; sg <= 1; sg += 2)
            for (int shape = 0; shape < 3; shape++)
                for (size_t j = 0; j < sizeof sd2 / sizeof *sd2; j++)
                    for (int m = 0; m < 2; m++) {
                        const double a0 = sg * offs[i], a1 = shape == 0 ? a0 : shape == 1 ? -a0 : 0.0;
                        el_hermite_result r;
                        double p[8];
                        solve_at(0.3, 2.0, a0, a1, sd2[j], m, p, &r);
                        /* every chain's pieces: one tension, |F| = 2 mu and phi (mod 2 pi); the
                         * near-straight ones checked in full (hermite_check.h: the loops' ends can
                         * hold curvatures ~1e-7 of their peak, of either sign, which its sampled
                         * inflection test does not see) */
                        for (size_t k = 0; k < r.count; k++) {
                            const el_hermite_solution *h = &r.solutions[k];
                            for (int q = 0; q + 1 < h->npieces; q++) {
                                const el_smooth_params *a = &h->curve, *b = &h->rest[q];
                                ck_assert_msg(fabs(wrap(b->phi - a->phi)) <= 1e-7 && fabs(b->mu - a->mu) <= 1e-12 * a->mu,
                                              "a0 %g a1 %g sigma d^2 %g mirror %d: L %.12g, piece %d's phi %.17g, the "
                                              "first's %.17g", a0, a1, sd2[j], m, h->length, q + 2, b->phi, a->phi);
                            }
                            if (h->npieces > 1 && h->length <= 2.0 * (1.0 + 1e-3))
                                check_solution(p, p + 2, p + 4, p + 6, h, 1e-10);
                            chains += h->npieces > 1;
                        }
                        el_hermite_result_free(&r);
                    }
    ck_assert_int_gt(chains, 100);
    fprintf(stderr, "chains_share_one_force: %d chains\n", chains);
}
END_TEST

int main(void)
{
    (void)check_result;   /* hermite_check.h's: the other solutions are test_hermite*.c's */
    Suite *s = suite_create("hermite_near");
    TCase *tc = tcase_create("hermite_near");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, linear_beam_satisfies_its_equations);
    tcase_add_test(tc, near_straight_curve_at_every_tension);
    tcase_add_test(tc, state_next_to_the_centre_below_zero);
    tcase_add_test(tc, near_straight_never_silently_missing);
    tcase_add_test(tc, chains_share_one_force);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
