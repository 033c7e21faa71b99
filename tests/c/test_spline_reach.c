/* Elastic splines (issue 14) by length where the family of tension solutions folds in
 * sigma with the knot angles standing still (ducks whose symmetry fixes every tangent: a
 * star, a ring on a circle), lengths that only tension mode's splines lead to (spline_bracket.c),
 * and lengths beyond the splines the solve reaches (EL_ERANGE with the lengths it met,
 * el_spline_result's reach). */
#include "spline_check.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* a closed star of n ducks, radii ro (even) and ri (odd); its polygon's length */
static double star(double *xy, int n, double ro, double ri)
{
    double poly = 0.0;
    for (int i = 0; i < n; i++) {
        const double a = 2.0 * M_PI * i / n, r = i % 2 ? ri : ro;
        xy[2 * i] = r * cos(a);
        xy[2 * i + 1] = r * sin(a);
    }
    for (int i = 0; i < n; i++) {
        const int j = (i + 1) % n;
        poly += hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]);
    }
    return poly;
}

/* QA: the closed 10-duck star (radii 20/8) by length failed from 1.25 x its polygon (no
 * spline reached: the path stalled at 1.242 x, sigma h^2 -19.39, where sigma folds back and
 * the knot angles, fixed by the symmetry, do not move). The splines exist: each length
 * 1.25 .. 2 x met, G2 at every duck (check_spline, measured on the pieces), not crossing
 * itself, its tension continuing the one at 1.2 x (compressed, sigma h^2 in -20 .. 0) */
START_TEST(star_by_length_passes_the_fold)
{
    double xy[20];
    const double poly = star(xy, 10, 20.0, 8.0);
    double hmax = 0.0;
    for (int i = 0; i < 10; i++) {
        const int j = (i + 1) % 10;
        hmax = fmax(hmax, hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]));
    }
    const double f[] = {1.25, 1.3, 1.4, 1.5, 1.75, 2.0};
    for (size_t i = 0; i < sizeof f / sizeof f[0]; i++) {
        el_spline_options o = closed_length(f[i] * poly);
        el_spline_result r;
        ck_assert_msg(solve(xy, 10, &o, &r) == EL_OK, "star at %g x", f[i]);
        check_spline(xy, 10, &o, &r, 1e-9);
        ck_assert_int_eq(r.loops, 0);
        ck_assert_int_eq(el__spline_crosses(r.pieces, r.npieces, 1), 0);
        ck_assert_msg(r.sigma * hmax * hmax > -20.0 && r.sigma < 0.0, "%g x: sigma h^2 %g", f[i],
                      r.sigma * hmax * hmax);
        el_spline_result_free(&r);
    }
}
END_TEST

/* QA: 8 ducks on the unit circle, closed, by length: integral kappa^2 58.3 at 1.2 x, then
 * 221 at 1.25 x, 241 at 1.3 x, 644 at 1.5 x (the leap over the stall landed on a higher
 * mode). Now the family followed with the length as a coordinate, the fairer of the two:
 * 72.9, 85.9, 124.3, each below the energy of the 1.2 x spline scaled by the length's
 * excess ratio squared (the higher mode's were 3-5 x that) */
START_TEST(ring_by_length_keeps_its_first_mode)
{
    double xy[16];
    const double poly = unit_ring8(xy);
    el_spline_options o = closed_length(1.2 * poly);
    el_spline_result r;
    ck_assert_int_eq(solve(xy, 8, &o, &r), EL_OK);
    const double e12 = r.energy;
    el_spline_result_free(&r);
    const double f[] = {1.25, 1.3, 1.5};
    double prev = e12;
    for (size_t i = 0; i < 3; i++) {
        o = closed_length(f[i] * poly);
        ck_assert_int_eq(solve(xy, 8, &o, &r), EL_OK);
        check_spline(xy, 8, &o, &r, 1e-9);
        ck_assert_int_eq(r.loops, 0);
        const double x = (f[i] - 1.0) / 0.2;
        ck_assert_msg(r.energy > prev && r.energy < e12 * x * x, "%g x: energy %g (1.2 x: %g)", f[i],
                      r.energy, e12);
        prev = r.energy;
        el_spline_result_free(&r);
    }
}
END_TEST

/* QA13's 8-point random walk (numpy default_rng(1), normal(0, 10) steps; no free batten: it
 * slides off its ducks) */
static const double walk8[] = {3.45584192064786, 8.216181435011583, 6.760212682481731, -4.815390881032027,
                               15.813771349212908, -0.35164515739191415, 10.444238995610057, 5.459535884571617,
                               14.089962957470814, 8.400860851126875, 14.374185370628782, 13.867990717251345,
                               7.009644500612112, 12.238891237320818, 2.18845137381233, 18.227353363667092};

/* Every length a tension-mode spline has is reached by length mode: tensions sigma x
 * (longest span)^2 over 0.03 .. 200 on the walk (QA13: no length 1.03 .. 15 x its polygon
 * was reached, tension mode gives 1.04 .. 7.9 x), a designer's sketch and the unit ring
 * (reached before too), 0.3 .. 40 on ring77 (none reached, 1.23 .. 12.7 x); each length asked
 * back is met, G2 through every duck (check_spline); on the walk, the sketch and the ring it
 * is the same spline (its tension) */
/* QA14's 14 sketched clicks of an S (mm): at sigma h^2 300 and 450 (h the longest span) a
 * ladder rung solved from scratch left the family (40 -> 80: longer), so length mode failed */
static const double sketch14[] = {
    0.57327012469906891, -1.598253353959777, 3.9211466295721404, 2.6011705754291135,
    29.834162482837776, 24.198453199160106, 39.059823392328063, 28.528457647828446,
    63.085785455778513, 28.192390614565415, 64.043371468756234, 27.32553570961592,
    86.454232224701414, 11.360367890586563, 89.036441617337474, 10.690102300880961,
    101.12736359056353, 1.311340646288452, 140.21593116692799, -27.767781486134023,
    142.17165976844774, -29.421791295474112, 161.18704344809802, -27.067690172472609,
    174.12185299272863, -21.43265727535508, 199.98302123166616, 0.48737319426618525
};

START_TEST(length_mode_reaches_the_lengths_of_tension_mode)
{
    double ring[16];
    unit_ring8(ring);
    const struct { const double *xy; size_t n; int closed, same; double sh2[10], tol; } c[] = {
        {walk8, 8, 0, 1, {0.03, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 200.0, 0.0}, 0.0},
        {sketch, NSKETCH, 0, 1, {0.03, 0.3, 3.0, 30.0, 200.0, 0.0}, 0.0},
        {ring, 8, 1, 1, {0.03, 0.3, 3.0, 30.0, 200.0, 0.0}, 0.0},
        {ring77, 12, 1, 0, {0.3, 1.0, 3.0, 10.0, 40.0, 0.0}, 0.0},
        {sketch14, 14, 0, 1, {300.0, 450.0, 0.0}, 1e-7},   /* QA's tol: tension mode's own residual 1.5e-8 at 450 */
    };
    for (size_t k = 0; k < sizeof c / sizeof c[0]; k++) {
        const size_t n = c[k].n, m = c[k].closed ? n : n - 1;
        double h = 0.0;
        for (size_t j = 0; j < m; j++) {
            const size_t e = (j + 1) % n;
            h = fmax(h, hypot(c[k].xy[2 * e] - c[k].xy[2 * j], c[k].xy[2 * e + 1] - c[k].xy[2 * j + 1]));
        }
        for (size_t i = 0; c[k].sh2[i] > 0.0; i++) {
            el_spline_options o = opts(EL_SPLINE_TENSION, c[k].sh2[i] / (h * h));
            o.closed = c[k].closed;
            if (c[k].tol > 0.0) o.tol = c[k].tol;
            el_spline_result t, l;
            ck_assert_msg(solve(c[k].xy, n, &o, &t) == EL_OK, "set %zu tension %g", k, c[k].sh2[i]);
            el_spline_options ol = opts(EL_SPLINE_LENGTH, t.length);
            ol.closed = c[k].closed;
            ol.tol = o.tol;
            ck_assert_msg(solve(c[k].xy, n, &ol, &l) == EL_OK, "set %zu: length %g of tension %g", k, t.length,
                          c[k].sh2[i]);
            check_spline(c[k].xy, n, &ol, &l, fmax(1e-9, o.tol));   /* knots to the tol asked */
            if (c[k].same) ck_assert_msg(fabs(l.sigma - t.sigma) <= 1e-6 * t.sigma, "set %zu: tension %.9g, asked %.9g",
                                         k, l.sigma * h * h, c[k].sh2[i]);
            el_spline_result_free(&t);
            el_spline_result_free(&l);
        }
    }
}
END_TEST

/* QA14's t10 sheer (11 ducks near a parabola, trial 13) at sigma h^2 300: tension mode's
 * spline is accepted within its resolution (1.04e-9 at tol 1e-10); by its length the
 * bracket kept the first near spline reached (1.1e-7, tension 2.093), refused: now the
 * one of least residual, the same spline */
static const double sheer11[] = {
    0.0059601927122216744, 0.89528330050807747, 11.873368879273762, 0.05301503539094142,
    12.963401402077901, 0.029719266170520307, 13.747880900795289, 0.027293166633681403,
    14.107167855382293, 0.025335729151174973, 14.857339456439643, 0.042465596151814111,
    18.02667326142161, 0.095491601262073358, 19.618661659577143, 0.16477833967726552,
    21.985243089798658, 0.29589228743172724, 22.791543795204891, 0.35729583961134848,
    30.014058874357215, 1.1574038780693228
};

START_TEST(length_mode_keeps_the_nearest_of_the_bracket)
{
    const double h = longest_side(sheer11, 11);
    el_spline_options o = opts(EL_SPLINE_TENSION, 300.0 / (h * h));
    el_spline_result t, l;
    ck_assert_int_eq(solve(sheer11, 11, &o, &t), EL_OK);
    el_spline_options ol = opts(EL_SPLINE_LENGTH, t.length);
    ck_assert_int_eq(solve(sheer11, 11, &ol, &l), EL_OK);
    ck_assert_msg(l.residual <= fmax(ol.tol, fmin(l.resolution, 1e-7)), "residual %g", l.residual);
    ck_assert_msg(fabs(l.length - t.length) <= 1e-9 * t.length, "length %.12g", l.length);
    ck_assert_msg(fabs(l.sigma - t.sigma) <= 1e-6 * t.sigma, "tension %.9g of %.9g", l.sigma, t.sigma);
    ck_assert_int_eq(l.loops, 0);
    el_spline_result_free(&t);
    el_spline_result_free(&l);
}
END_TEST

/* ring77 at the length of its fair tension-mode spline at sigma h^2 = 20 (longest side, 1.266 x
 * its polygon): by length the solve returned a spline of that length crossing itself (sigma h^2
 * 35.7, loops 1), the family through every rung of the bracket crossing itself there; now the
 * fair one, from the finer rungs that do not cross themselves (spline_bracket.c FAIR_RUNGS) */
START_TEST(length_mode_prefers_the_fair_spline)
{
    const double h = fmax(longest_side(ring77, 12), hypot(ring77[22] - ring77[0], ring77[23] - ring77[1]));
    el_spline_options o = closed_opts(EL_SPLINE_TENSION, 20.0 / (h * h));
    el_spline_result t, l;
    ck_assert_int_eq(solve(ring77, 12, &o, &t), EL_OK);
    ck_assert_int_eq(t.loops, 0);
    el_spline_options ol = closed_length(t.length);
    ck_assert_int_eq(solve(ring77, 12, &ol, &l), EL_OK);
    check_spline(ring77, 12, &ol, &l, 1e-9);
    ck_assert_msg(l.loops == 0, "crosses itself at sigma h^2 %.6g", l.sigma * h * h);
    ck_assert_msg(fabs(l.sigma - t.sigma) <= 1e-6 * t.sigma, "tension %.9g of %.9g", l.sigma * h * h, 20.0);
    ck_assert_msg(fabs(l.energy - t.energy) <= 1e-6 * t.energy, "energy %.9g of %.9g", l.energy, t.energy);
    el_spline_result_free(&t);
    el_spline_result_free(&l);
}
END_TEST

/* A length beyond every spline the solve met: EL_ERANGE, with the least and greatest
 * lengths met (reach[0..1]) around the free batten's and the longest without a crossing
 * (reach[2]); the star at 6 x its polygon (it met 1.118 .. 5.49 x, fair up to 2.16 x),
 * a 4-duck star at 1.02 x (shorter needs a tension beyond the solver's reach). A
 * length inside the range solves, with reach set too */
START_TEST(length_beyond_reach_says_how_far)
{
    double xy[20];
    const double poly = star(xy, 10, 20.0, 8.0);
    el_spline_options o = closed_length(6.0 * poly);
    el_spline_result r;
    ck_assert_int_eq(solve(xy, 10, &o, &r), EL_ERANGE);
    ck_assert_int_eq((int)r.npieces, 0);
    ck_assert_ptr_null(r.pieces);
    ck_assert_msg(r.reach[0] > 1.1 * poly && r.reach[0] < 1.2 * poly, "shortest %g", r.reach[0] / poly);
    ck_assert_msg(r.reach[1] > 2.0 * poly && r.reach[1] < 6.0 * poly, "longest %g", r.reach[1] / poly);
    ck_assert_msg(r.reach[2] >= 2.0 * poly && r.reach[2] < r.reach[1], "fair %g", r.reach[2] / poly);
    el_spline_result_free(&r);
    o = closed_length(2.0 * poly);
    ck_assert_int_eq(solve(xy, 10, &o, &r), EL_OK);
    ck_assert_msg(r.reach[2] >= 2.0 * poly, "fair %g", r.reach[2] / poly);
    el_spline_result_free(&r);
    double sq[8];
    const double p4 = star(sq, 4, 1.0, 0.4);
    o = closed_length(1.02 * p4);
    ck_assert_int_eq(solve(sq, 4, &o, &r), EL_ERANGE);
    ck_assert_msg(r.reach[0] > 1.02 * p4 && r.reach[0] <= r.reach[1], "shortest %g", r.reach[0] / p4);
    el_spline_result_free(&r);
    ck_assert_str_eq(el_strerror(EL_ERANGE), "target beyond the range of solutions reached");
}
END_TEST

/* Where no family was followed (ring77: no free batten, no batten under tension from the
 * chain's start) a length shorter than every tension-mode spline the solve met: EL_ERANGE
 * with those splines' lengths (tension mode's fair ones reached by length end at ~1.07 x
 * the polygon, sigma h^2 ~480 on the longest span); before: EL_ENOCONV, "no spline
 * reached", reach empty. At 1.1 x (EL_ERANGE before TAUT_FAILS, spline_bracket.c: no
 * taut batten at sigma h^2 40 on the mean chord, the ladder's rung at 20 longer) the fair
 * spline of that length, on tension mode's family: its tension gives it back */
START_TEST(length_beyond_the_tension_splines_met)
{
    double poly = 0.0, h = 0.0;
    for (int i = 0; i < 12; i++) {
        const int j = (i + 1) % 12;
        const double c = hypot(ring77[2 * j] - ring77[2 * i], ring77[2 * j + 1] - ring77[2 * i + 1]);
        poly += c;
        h = fmax(h, c);
    }
    el_spline_options o = closed_length(1.05 * poly);
    el_spline_result r;
    ck_assert_int_eq(solve(ring77, 12, &o, &r), EL_ERANGE);
    ck_assert_int_eq((int)r.npieces, 0);
    ck_assert_msg(r.reach[0] > 1.05 * poly && r.reach[0] < 1.2 * poly, "shortest %g", r.reach[0] / poly);
    ck_assert_msg(r.reach[1] >= r.reach[0] && r.reach[2] >= r.reach[0] && r.reach[2] <= r.reach[1],
                  "reach %g %g %g", r.reach[0] / poly, r.reach[1] / poly, r.reach[2] / poly);
    el_spline_result_free(&r);
    o = closed_length(1.1 * poly);
    ck_assert_int_eq(solve(ring77, 12, &o, &r), EL_OK);
    check_spline(ring77, 12, &o, &r, 1e-9);
    ck_assert_int_eq(r.loops, 0);
    ck_assert_msg(r.sigma * h * h > 150.0 && r.sigma * h * h < 300.0, "sigma h^2 %g", r.sigma * h * h);
    el_spline_options t = closed_opts(EL_SPLINE_TENSION, r.sigma);
    el_spline_result rt;
    ck_assert_int_eq(solve(ring77, 12, &t, &rt), EL_OK);
    ck_assert_msg(fabs(rt.length - 1.1 * poly) <= 1e-8 * poly, "tension mode's length %.12g x", rt.length / poly);
    ck_assert_int_eq(rt.loops, 0);
    el_spline_result_free(&rt);
    el_spline_result_free(&r);
}
END_TEST

/* 8 random ducks closed into a ring with two deep bays (no free batten: EL_EDOM at tension
 * 0): by length 1.1 and 1.3 x its polygon no spline was reached (no batten under sigma h^2 =
 * 40, 4 or 0.4 converged from the chain's start to be followed); now from the taut batten's
 * start (TAUT_START, spline_path.c), followed in length: G2, without loops */
START_TEST(closed_bays_by_length_from_the_taut_start)
{
    static const double bays[] = {0.2353, 0.5589, 0.1218, 1.1909, -0.2192, 1.2372, -0.2647, 0.7511,
                                  -0.5042, 1.018, -0.3757, 0.3796, -0.5925, -0.6832, 0.0724, -1.0755};
    double poly = 0.0;
    for (int i = 0; i < 8; i++) {
        const int j = (i + 1) % 8;
        poly += hypot(bays[2 * j] - bays[2 * i], bays[2 * j + 1] - bays[2 * i + 1]);
    }
    const double f[] = {1.1, 1.3};
    for (int i = 0; i < 2; i++) {
        el_spline_options o = closed_length(f[i] * poly);
        el_spline_result r;
        ck_assert_msg(solve(bays, 8, &o, &r) == EL_OK, "%g x", f[i]);
        check_spline(bays, 8, &o, &r, 1e-9);
        ck_assert_int_eq(r.loops, 0);
        el_spline_result_free(&r);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_reach");
    TCase *tc = tcase_create("spline_reach");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, star_by_length_passes_the_fold);
    tcase_add_test(tc, ring_by_length_keeps_its_first_mode);
    tcase_add_test(tc, length_mode_reaches_the_lengths_of_tension_mode);
    tcase_add_test(tc, length_mode_keeps_the_nearest_of_the_bracket);
    tcase_add_test(tc, length_beyond_reach_says_how_far);
    tcase_add_test(tc, length_beyond_the_tension_splines_met);
    tcase_add_test(tc, closed_bays_by_length_from_the_taut_start);
    tcase_add_test(tc, length_mode_prefers_the_fair_spline);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
