/* Hermite solutions between tangents along the chord (t0 = t1 along p1 - p0), by tension and by
 * length: besides the straight segment, a loop turning once counter-clockwise and its mirror image in the chord,
 * clockwise. Each is one curvature period of a non-inflectional elastica whose k - 1 lies at or
 * below double precision above sigma |p1 - p0|^2 ~ 1000 (~e^-(sqrt(mu) L)): kappa = 2 sqrt(mu)
 * sech(sqrt(mu) s + q) at the separatrix, sqrt(mu) = sqrt(sigma / 2), its length beyond the chord
 * 4 / sqrt(mu) and its energy 8 sqrt(mu) (integrals of sech^2). hermite_chord.c returns each as one
 * piece in closed form, or counts it unrepresentable where no piece meets tol (sigma |p1 - p0|^2
 * ~ 1300 .. 4000, k = 1 + a few ulps); the roots return some as chains. The solution set is closed
 * under the chord's mirror (hermite_symmetry.c), but the mirror image of a chain was taken for
 * the chain itself (el__hermite_same_solution compared the turning of the first pieces only, and
 * a chain's first piece ends before its loop): tested on a chain directly, since the solves
 * above return single pieces. Every curve checked by hermite_check.h. */
#include "testutil.h"
#include "hermite_check.h"
#include "hermite_internal.h"
#include <gsl/gsl_sf_ellint.h>
#include <stdio.h>
#include <string.h>

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
        /* (both now hermite_chord.c's closed-form loops, single pieces: no chain left) */
        ck_assert_int_eq(chains, 0);
        el_hermite_result_free(&r);
    }
}
END_TEST

/* The turning of a solution (all pieces) and where along it |kappa| peaks (fraction of L). */
static double turning_of(const el_hermite_solution *s, double *peak)
{
    const el_smooth_params *pc[3];
    const int n = pieces_of(s, pc);
    double w = 0.0, base = 0.0, kmax = -1.0;
    for (int i = 0; i < n; i++) {
        const double h[2] = {0.0, pc[i]->length};
        double t[2];
        ck_assert_int_eq(el_smooth_eval(pc[i], 2, h, NULL, t, NULL), EL_OK);
        w += t[1] - t[0];
        for (int j = 0; j <= 4000; j++) {
            double sj = pc[i]->length * j / 4000.0, kj;
            ck_assert_int_eq(el_smooth_eval(pc[i], 1, &sj, NULL, NULL, &kj), EL_OK);
            if (fabs(kj) > kmax) { kmax = fabs(kj); *peak = (base + sj) / s->length; }
        }
        base += pc[i]->length;
    }
    return w;
}

/* Tangents along the chord by tension, exact data in every frame: p0 (0, 0), p1 d (cos a, sin a),
 * t0 = t1 = (cos a, sin a), turned (a = 0, 0.3, pi/2, 2, -2.5), scaled (d = 1e-3 .. 1e3),
 * shifted by (3000, -2100) d, sigma d^2 = 50 .. 9e4: the segment and exactly one loop of each
 * sense, the mirror pair of one length and energy, each symmetric as the data (its curvature
 * peaks at L / 2), at most one period, and from sigma d^2 = 5000 on the separatrix's length
 * d (1 + 4 / (sqrt(mu) d)) and energy 8 sqrt(mu) (sqrt(mu) d = sqrt(sigma d^2 / 2); e^-K below
 * 1e-18). Before hermite_chord.c: the segment alone from sigma d^2 ~ 600 on (exact data at angle
 * 0), one loop or none elsewhere (/tmp/hermloop/NOTES.md, mechanisms 1 and 2). */
START_TEST(loops_between_tangents_along_the_chord_by_tension)
{
    const double angles[] = {0.0, 0.3, M_PI / 2, 2.0, -2.5}, scales[] = {1e-3, 1.0, 1e3};
    const double sd2s[] = {50.0, 600.0, 5000.0, 12800.0, 51200.0, 9e4};
    for (size_t ia = 0; ia < 5; ia++)
        for (size_t is = 0; is < 3; is++)
            for (int off = 0; off < 2; off++)
                for (size_t iv = 0; iv < 6; iv++) {
                    const double d = scales[is], t[2] = {cos(angles[ia]), sin(angles[ia])};
                    const double p0[2] = {off * 3000.0 * d, off * -2100.0 * d};
                    const double p1[2] = {p0[0] + d * t[0], p0[1] + d * t[1]};
                    el_hermite_options o;
                    el_hermite_options_defaults(&o);
                    o.sigma = sd2s[iv] / (d * d);
                    el_hermite_result r;
                    ck_assert_int_eq(el_hermite_solve(p0, t, p1, t, &o, &r), EL_OK);
                    check_result(p0, t, p1, t, &r, o.tol);
                    int ccw = 0, cw = 0;
                    double LE[2][2] = {{0, 0}, {0, 0}};
                    for (size_t j = 0; j < r.count; j++) {
                        const el_hermite_solution *s = &r.solutions[j];
                        double peak = 0.0;
                        const double w = turning_of(s, &peak);
                        if (fabs(fabs(w) - 2.0 * M_PI) > 1e-6) continue;
                        const int ix = w > 0.0 ? 0 : 1;
                        ccw += !ix;
                        cw += ix;
                        LE[ix][0] = s->length / d;
                        LE[ix][1] = s->energy * d;
                        ck_assert_msg(fabs(peak - 0.5) <= 1e-3, "a %g d %g off %d sigma d^2 %g: the loop peaks at %g of L",
                                      angles[ia], d, off, sd2s[iv], peak);
                        const double k = fabs(s->curve.k);
                        if (s->npieces == 1 && k > 1.0) {
                            const double period = 2.0 * gsl_sf_ellint_Kcomp(1.0 / k, GSL_PREC_DOUBLE) / (k * sqrt(s->curve.mu));
                            ck_assert(s->length <= period * (1.0 + 1e-8));
                        }
                        if (sd2s[iv] >= 5000.0) {
                            const double rm = sqrt(0.5 * sd2s[iv]);
                            ck_assert_msg(fabs(s->length / d - (1.0 + 4.0 / rm)) <= 1e-9 &&
                                          fabs(s->energy * d - 8.0 * rm) <= 1e-9 * 8.0 * rm,
                                          "L %.12g E %.12g, the separatrix's %.12g %.12g", s->length / d,
                                          s->energy * d, 1.0 + 4.0 / rm, 8.0 * rm);
                        }
                    }
                    ck_assert_msg(ccw == 1 && cw == 1 && r.count == 3,
                                  "a %g d %g off %d sigma d^2 %g: %zu solutions, %d ccw, %d cw loops", angles[ia], d,
                                  off, sd2s[iv], r.count, ccw, cw);
                    ck_assert(fabs(LE[0][0] - LE[1][0]) <= 1e-9 * LE[0][0] && fabs(LE[0][1] - LE[1][1]) <= 1e-9 * LE[0][1]);
                    el_hermite_result_free(&r);
                }
}
END_TEST

/* Tangents along the chord by length, p0 (0, 0), p1 d (cos a, sin a), t0 = t1 = (cos a, sin a)
 * turned (a = 0, 0.3, pi/2, 2, -2.5), scaled (d = 1e-3 .. 1e3), shifted by (3000, -2100) d,
 * exact or with p1 moved across the chord by 1e-14 or -1e-12 d, length 1.01 .. 1.25 d: exactly
 * one loop of each sense (turning +-2 pi once), of the given length, the pair of one energy,
 * each peaking at L / 2, at most one period, every curve checked by hermite_check.h, and below
 * 1.1 d the separatrix's sqrt(mu) d = 4 / (L / d - 1), energy 8 sqrt(mu) (the closed form's
 * k' ~ e^-(sqrt(mu) d / 2) below 1e-17). Before (hermite_chord.c by tension only): p0 (0, 0),
 * p1 (0.2, 0), length 1.05 d: the two whole-period bumps alone, no loop below ~1.1 d. */
START_TEST(loops_between_tangents_along_the_chord_by_length)
{
    const double angles[] = {0.0, 0.3, M_PI / 2, 2.0, -2.5}, scales[] = {1e-3, 0.2, 1e3};
    const double Ls[] = {1.01, 1.05, 1.08, 1.25}, moves[] = {0.0, 1e-14, -1e-12};
    for (size_t ia = 0; ia < 5; ia++)
        for (size_t is = 0; is < 3; is++)
            for (int off = 0; off < 2; off++)
                for (size_t im = 0; im < 3; im++)
                    for (size_t iL = 0; iL < 4; iL++) {
                        const double d = scales[is], t[2] = {cos(angles[ia]), sin(angles[ia])};
                        const double p0[2] = {off * 3000.0 * d, off * -2100.0 * d};
                        const double e = moves[im] * d;
                        const double p1[2] = {p0[0] + d * t[0] - e * t[1], p0[1] + d * t[1] + e * t[0]};
                        el_hermite_options o;
                        el_hermite_options_defaults(&o);
                        o.mode = EL_HERMITE_LENGTH;
                        o.length = Ls[iL] * d;
                        el_hermite_result r;
                        ck_assert_int_eq(el_hermite_solve(p0, t, p1, t, &o, &r), EL_OK);
                        check_result(p0, t, p1, t, &r, o.tol);
                        int ccw = 0, cw = 0;
                        double E[2] = {0, 0};
                        for (size_t j = 0; j < r.count; j++) {
                            const el_hermite_solution *s = &r.solutions[j];
                            double peak = 0.0;
                            const double w = turning_of(s, &peak);
                            ck_assert(fabs(s->length - o.length) <= 1e-12 * o.length);
                            if (fabs(fabs(w) - 2.0 * M_PI) > 1e-6) continue;
                            const int ix = w > 0.0 ? 0 : 1;
                            ccw += !ix;
                            cw += ix;
                            E[ix] = s->energy * d;
                            ck_assert_msg(fabs(peak - 0.5) <= 1e-3,
                                          "a %g d %g off %d move %g L %g: the loop peaks at %g of L",
                                          angles[ia], d, off, moves[im], Ls[iL], peak);
                            const double k = fabs(s->curve.k);
                            if (s->npieces == 1 && k > 1.0) {
                                const double K = gsl_sf_ellint_Kcomp(1.0 / k, GSL_PREC_DOUBLE);
                                ck_assert(s->length <= 2.0 * K / (k * sqrt(s->curve.mu)) * (1.0 + 1e-8));
                            }
                            if (Ls[iL] <= 1.1 && s->npieces == 1) {
                                const double rm = 4.0 / (Ls[iL] - 1.0);
                                ck_assert_msg(fabs(sqrt(s->curve.mu) * d - rm) <= 1e-9 * rm &&
                                              fabs(s->energy * d - 8.0 * rm) <= 1e-9 * 8.0 * rm,
                                              "sqrt(mu) d %.12g E %.12g, the separatrix's %.12g %.12g",
                                              sqrt(s->curve.mu) * d, s->energy * d, rm, 8.0 * rm);
                            }
                        }
                        ck_assert_msg(ccw == 1 && cw == 1,
                                      "a %g d %g off %d move %g L %g: %zu solutions, %d ccw, %d cw loops",
                                      angles[ia], d, off, moves[im], Ls[iL], r.count, ccw, cw);
                        ck_assert(fabs(E[0] - E[1]) <= 1e-9 * E[0]);
                        el_hermite_result_free(&r);
                    }
}
END_TEST

/* Exact tangents along the chord at sigma |p1 - p0|^2 in the band 1000 .. 5000, which the grid
 * above steps over: there the closed-form loop's k is 1 + a few ulps (or rounds to 1 with e^-K
 * ~ 1e-9) and no single piece meets tol 1e-10 (residual 1.1e-9 at 2000): both loops are returned
 * or counted in res.unrepresentable, besides the segment. They were dropped and not counted
 * (a 0, d 1, sigma d^2 2000: the segment alone, unrepresentable 0; 252 of 6000 problems). */
START_TEST(loops_at_every_tension_are_returned_or_counted)
{
    const double angles[] = {0.0, 0.3, M_PI / 2, 2.0, -2.5}, scales[] = {1e-3, 1.0, 1e3};
    for (size_t ia = 0; ia < 5; ia++)
        for (size_t is = 0; is < 3; is++)
            for (int off = 0; off < 2; off++)
                for (double sd2 = 1000.0; sd2 <= 5000.0; sd2 *= 1.12) {
                    const double d = scales[is], t[2] = {cos(angles[ia]), sin(angles[ia])};
                    const double p0[2] = {off * 3000.0 * d, off * -2100.0 * d};
                    const double p1[2] = {p0[0] + d * t[0], p0[1] + d * t[1]};
                    el_hermite_options o;
                    el_hermite_options_defaults(&o);
                    o.sigma = sd2 / (d * d);
                    el_hermite_result r;
                    ck_assert_int_eq(el_hermite_solve(p0, t, p1, t, &o, &r), EL_OK);
                    check_result(p0, t, p1, t, &r, o.tol);
                    ck_assert_msg(r.count + r.unrepresentable == 3, "a %g d %g off %d sigma d^2 %g: %zu + %zu unrepresentable",
                                  angles[ia], d, off, sd2, r.count, r.unrepresentable);
                    el_hermite_result_free(&r);
                }
}
END_TEST

/* By length, exact tangents along the chord at L in 1.085 .. 1.17 |p1 - p0|: the loops of the
 * closed form whose k - 1 lies below an ulp there (sqrt(mu) |p1 - p0| ~ 25 .. 45) and whose tails
 * e^-(sqrt(mu) L / 2) stay above tol, so that no single piece meets tol 1e-10 (the closed form's
 * residual ~1e-9): both loops are returned (the tracer's chains, from ~1.125 on) or counted in
 * res.unrepresentable, besides the two buckled curves one period long (hermite_symmetry.c).
 * They were dropped and not counted from 1.09 to 1.12 (a 0, d 1: 2 solutions, unrepresentable 0,
 * or 1 at 1.115 and 1.12: the roots' own count, of one of them). */
START_TEST(loops_at_every_length_are_returned_or_counted)
{
    const double angles[] = {0.0, 0.3, M_PI / 2, 2.0, -2.5}, scales[] = {1e-3, 1.0, 1e3};
    for (size_t ia = 0; ia < 5; ia++)
        for (size_t is = 0; is < 3; is++)
            for (int off = 0; off < 2; off++)
                for (int iL = 0; iL <= 17; iL++) {
                    const double Ln = 1.085 + 0.005 * iL;
                    const double d = scales[is], t[2] = {cos(angles[ia]), sin(angles[ia])};
                    const double p0[2] = {off * 3000.0 * d, off * -2100.0 * d};
                    const double p1[2] = {p0[0] + d * t[0], p0[1] + d * t[1]};
                    el_hermite_options o;
                    el_hermite_options_defaults(&o);
                    o.mode = EL_HERMITE_LENGTH;
                    o.length = Ln * d;
                    el_hermite_result r;
                    ck_assert_int_eq(el_hermite_solve(p0, t, p1, t, &o, &r), EL_OK);
                    check_result(p0, t, p1, t, &r, o.tol);
                    size_t loops = 0;
                    for (size_t j = 0; j < r.count; j++) {
                        double peak;
                        loops += fabs(fabs(turning_of(&r.solutions[j], &peak)) - 2.0 * M_PI) <= 1e-6;
                    }
                    ck_assert_msg(r.count - loops == 2 && loops + r.unrepresentable == 2,
                                  "a %g d %g off %d L %g d: %zu solutions (%zu loops) + %zu unrepresentable",
                                  angles[ia], d, off, Ln, r.count, loops, r.unrepresentable);
                    el_hermite_result_free(&r);
                }
}
END_TEST

/* el__hermite_same_solution on a chain and its mirror image in the chord (hermite.c: the chain
 * branch). A separatrix loop (k = 1, mu = 1, u from -22 to 22) split at u = -18, before its loop:
 * the first pieces of the chain and of its mirror turn alike (by ~1e-7 rad), the end curvatures
 * (~1e-9) and lengths agree, and only the whole curves' turning, +-2 pi, tells them apart. The
 * chord loops are single pieces now, so no solve reaches this branch: taken for the chain, the
 * mirror image of a loop was dropped (tangents (cos -2.5, sin -2.5) at sigma d^2 = 5000). */
static void mirror_piece(const el_smooth_params *p, double y0, el_smooth_params *m)
{
    *m = *p;
    m->y0 = 2.0 * y0 - p->y0;
    m->phi = -p->phi;
    m->k = -p->k;
}

START_TEST(a_chain_and_its_mirror_image_are_two_solutions)
{
    el_hermite_solution a;
    memset(&a, 0, sizeof a);
    el_smooth_params p = {.x0 = 0.5, .y0 = -2.0, .phi = M_PI, .mu = 1.0, .k = 1.0, .q = -22.0, .length = 4.0};
    ck_assert_int_eq(el_smooth_check(&p), EL_OK);
    const double h[2] = {0.0, p.length};
    double xy[4], th[2], ka[2];
    ck_assert_int_eq(el_smooth_eval(&p, 2, h, xy, th, ka), EL_OK);
    ck_assert(fabs(th[1] - th[0]) <= 5e-7);   /* (the premise: the first piece ends before the loop) */
    el_smooth_params r = p;
    r.x0 = xy[2];
    r.y0 = xy[3];
    r.q = -18.0;
    r.length = 40.0;
    const double hr[2] = {0.0, r.length};
    double xyr[4], thr[2], kar[2];
    ck_assert_int_eq(el_smooth_eval(&r, 2, hr, xyr, thr, kar), EL_OK);
    a.curve = p;
    a.rest[0] = r;
    a.npieces = 2;
    a.length = 44.0;
    a.sigma = 2.0;
    a.kappa0 = ka[0];
    a.kappa1 = kar[1];
    a.energy = 16.0;
    const double d = hypot(xyr[2] - p.x0, xyr[3] - p.y0);
    el_hermite_solution b = a;
    mirror_piece(&a.curve, p.y0, &b.curve);
    mirror_piece(&a.rest[0], p.y0, &b.rest[0]);
    b.kappa0 = -a.kappa0;
    b.kappa1 = -a.kappa1;
    /* the mirror image is the reflected curve: its end is a's reflected, its turning -a's */
    ck_assert_int_eq(el_smooth_eval(&b.rest[0], 2, hr, xy, th, NULL), EL_OK);
    ck_assert(fabs(xy[2] - xyr[2]) <= 1e-12 * d && fabs(xy[3] - (2.0 * p.y0 - xyr[3])) <= 1e-12 * d);
    ck_assert(fabs((thr[1] - thr[0]) - 2.0 * M_PI) <= 1e-6 && fabs((th[1] - th[0]) + 2.0 * M_PI) <= 1e-6);
    ck_assert(fabs(a.kappa0) * d < 1e-7 && fabs(a.kappa1) * d < 1e-7);
    ck_assert(el__hermite_same_solution(&a, &a, d));
    ck_assert(el__hermite_same_solution(&b, &b, d));
    ck_assert_msg(!el__hermite_same_solution(&a, &b, d), "the mirror image taken for the chain");
    ck_assert_msg(!el__hermite_same_solution(&b, &a, d), "the chain taken for its mirror image");
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite_loops");
    TCase *tc = tcase_create("hermite_loops");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, a_loops_mirror_image_is_kept_beside_it);
    tcase_add_test(tc, loops_between_tangents_along_the_chord_by_tension);
    tcase_add_test(tc, loops_between_tangents_along_the_chord_by_length);
    tcase_add_test(tc, loops_at_every_tension_are_returned_or_counted);
    tcase_add_test(tc, loops_at_every_length_are_returned_or_counted);
    tcase_add_test(tc, a_chain_and_its_mirror_image_are_two_solutions);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
