/* The discrete fit's distance="auto" pairs vertex i with point i only where the points are
 * one pass at equal steps (fit_pairing.c). QA18: a scan passed back and forth over part of
 * its length (s 0 -> 12 -> 8 -> 30) is evenly spaced but not one pass: paired, its polygon
 * retraced and the refit by distance from it stayed there (rms 0.50, 10 x the noise, length
 * 63 for 30, status ok); an evenly spaced scan with single points missing was paired across
 * the gaps (rms up to 1.22 x the orthogonal fit's, status ok, no warning). Both now fit as
 * distance="orthogonal" does; evenly spaced scans without dropouts stay paired. */
#include "testutil.h"
#include <stdlib.h>
#include <string.h>

/* QA18's curve: length 30, one inflection */
static const el_smooth_params TRUTH = {0.0, 0.0, 0.1, 0.04, 0.75, -0.9, 30.0};
enum { MAXN = 200 };

/* the points of TRUTH at the n arc lengths s, each coordinate + noise N(0, 1), seeded */
static void scan(const double *s, size_t n, double noise, unsigned long long seed, double *xy)
{
    ck_assert_int_eq(el_smooth_eval(&TRUTH, n, s, xy, NULL, NULL), EL_OK);
    unsigned long long st = (seed + 1) * 0x9E3779B97F4A7C15ULL;
    for (size_t i = 0; i < 2 * n; i++) xy[i] += noise * test_normal(&st);
}

/* the default fit and distance="orthogonal"'s of the n points xy */
static void fit_both(const double *xy, size_t n, el_fit_discrete_result *autofit, el_fit_discrete_result *orth)
{
    el_fit_options o;
    el_fit_options_defaults(&o);
    const int st = el_fit_discrete(xy, n, &o, NULL, autofit, NULL, NULL);
    ck_assert_msg(st == EL_OK || st == EL_EMAXITER, "status %d", st);
    o.distance = EL_DISTANCE_ORTHOGONAL;
    ck_assert_int_eq(el_fit_discrete(xy, n, &o, NULL, orth, NULL, NULL), EL_OK);
}

/* back and forth: 60 points on s 0..12, 19 back to 8, 109 on to 30, noise 0.05 (spacing
 * 0.2 both ways). Main, 16 of 200 draws paired by the spacing test (the others not), each
 * refitted by distance from its retraced polygon: rms 1.08-1.11 and length 34 (status 6
 * or 0), or a hairball of length 965-2929 at rms 0.08-0.15; these three: 0.080 (1143),
 * 1.098 (33.9), 0.113 (965) */
START_TEST(test_back_and_forth_scan_is_not_paired)
{
    double s[188], xy[2 * 188];
    size_t n = 0;
    for (int i = 0; i < 60; i++) s[n++] = 12.0 * i / 59.0;
    for (int i = 1; i < 20; i++) s[n++] = 12.0 - 4.0 * i / 19.0;
    for (int i = 1; i < 110; i++) s[n++] = 8.0 + 22.0 * i / 109.0;
    ck_assert_uint_eq(n, 188);
    const unsigned long long seeds[] = {18, 42, 47};
    scan(s, n, 0.05, seeds[_i], xy);
    el_fit_discrete_result a, b;
    fit_both(xy, n, &a, &b);
    const double length = a.params.h * (double)(n - 1);     /* n vertices */
    ck_assert_int_eq(a.distance, EL_DISTANCE_ORTHOGONAL);
    ck_assert_msg(a.rms < 1.2 * 0.05 && fabs(length - 30.0) < 0.5, "draw %d: rms %g, length %g (truth 30)",
                  _i, a.rms, length);
    ck_assert_int_eq(a.status, EL_OK);
    ck_assert_msg(a.rms <= b.rms * (1.0 + 1e-6), "draw %d: rms %.9g, orthogonal %.9g", _i, a.rms, b.rms);
}
END_TEST

/* 200 points at equal steps of 0.15 along the curve, noise 0.05, the points drop[0..nd-1]
 * left out */
static size_t dropout_scan(const int *drop, int nd, unsigned long long seed, double *xy)
{
    double s[MAXN];
    size_t n = 0;
    for (int i = 0; i < MAXN; i++) {
        int out = 0;
        for (int j = 0; j < nd; j++) out |= drop[j] == i;
        if (!out) s[n++] = 30.0 * i / (MAXN - 1.0);
    }
    scan(s, n, 0.05, seed, xy);
    return n;
}

/* one or two single-point dropouts, draws that main paired at 1.03-1.18 x the orthogonal
 * fit's rms (the points' mean slip stepping by 0.91-1.04 vertex at a dropout, 0.51-0.62
 * the threshold) */
static const struct { int drop[2], nd; unsigned long long seed; } DROPOUTS[] = {
    {{68, -1}, 1, 11}, {{74, -1}, 1, 51}, {{73, -1}, 1, 79},
    {{169, 95}, 2, 60}, {{156, 183}, 2, 73}, {{73, 105}, 2, 79},
};

START_TEST(test_dropouts_are_not_paired)
{
    double xy[2 * MAXN];
    const size_t n = dropout_scan(DROPOUTS[_i].drop, DROPOUTS[_i].nd, DROPOUTS[_i].seed, xy);
    el_fit_discrete_result a, b;
    fit_both(xy, n, &a, &b);
    ck_assert_int_eq(a.distance, EL_DISTANCE_ORTHOGONAL);
    ck_assert_msg(a.rms <= b.rms * (1.0 + 1e-6), "case %d: rms %.9g, orthogonal %.9g", _i, a.rms, b.rms);
}
END_TEST

/* the same scans without dropouts: paired, as before (draws whose spacing passes the
 * test, paired at 1.002-1.009 x the orthogonal fit's rms) */
START_TEST(test_even_scans_stay_paired)
{
    double xy[2 * MAXN];
    const unsigned long long seeds[] = {3, 11, 12};
    const size_t n = dropout_scan(NULL, 0, seeds[_i], xy);
    el_fit_discrete_result a, b;
    fit_both(xy, n, &a, &b);
    ck_assert_int_eq(a.distance, EL_DISTANCE_PAIRED);
}
END_TEST

/* QA19's scan: points at random places along an elastica of length 600 (phi 0.2, mu 1e-4,
 * k 0.8, q 0.3), denser than their noise. The spacing test passes them and the paired fit
 * pulls its polygon across to keep them near their vertices, which the slip test read
 * against that inflated rms: main paired these at 1.91 (3000 points, noise 1), 1.70 (5000,
 * 1), 1.20 and 1.16 (3000, 2) x the orthogonal fit's rms, silently (QA's 50 000 points,
 * noise 0.2: 1.53 x). */
static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static const struct { size_t n; double noise; unsigned long long seed; } RANDOM_PLACES[] = {
    {3000, 1.0, 2}, {5000, 1.0, 6}, {3000, 2.0, 9}, {3000, 2.0, 10},
};

START_TEST(test_random_places_fit_as_orthogonal)
{
    const el_smooth_params truth = {0.0, 0.0, 0.2, 1e-4, 0.8, 0.3, 600.0};
    const size_t n = RANDOM_PLACES[_i].n;
    double *s = malloc(n * sizeof *s), *xy = malloc(2 * n * sizeof *xy);
    ck_assert(s && xy);
    unsigned long long st = (RANDOM_PLACES[_i].seed + 1) * 0x9E3779B97F4A7C15ULL;
    for (size_t i = 0; i < n; i++) s[i] = test_uniform(&st, 0.0, truth.length);
    qsort(s, n, sizeof *s, by_value);
    ck_assert_int_eq(el_smooth_eval(&truth, n, s, xy, NULL, NULL), EL_OK);
    for (size_t i = 0; i < 2 * n; i++) xy[i] += RANDOM_PLACES[_i].noise * test_normal(&st);
    el_fit_discrete_result a, b;
    fit_both(xy, n, &a, &b);
    ck_assert_msg(a.rms <= 1.05 * b.rms, "case %d: rms %.6g, orthogonal %.6g", _i, a.rms, b.rms);
    free(s);
    free(xy);
}
END_TEST

/* The turn test by its definition: the least i, w <= i < n - w, whose chords to the points k
 * before and after point opposite ways (dot < 0) at every k = 1..w, w = max(3, (n-1)/16) */
static size_t turn_by_definition(const double *xy, size_t n)
{
    const size_t w = (n - 1) / 16 > 3 ? (n - 1) / 16 : 3;
    for (size_t i = w; i + w < n; i++) {
        int all = 1;
        for (size_t k = 1; k <= w && all; k++) {
            const double bx = xy[2 * i] - xy[2 * (i - k)], by = xy[2 * i + 1] - xy[2 * (i - k) + 1];
            const double ox = xy[2 * (i + k)] - xy[2 * i], oy = xy[2 * (i + k) + 1] - xy[2 * i + 1];
            all = bx * ox + by * oy < 0.0;
        }
        if (all) return i;
    }
    return 0;
}

/* el_fit_turn_back, the public face of the fit's own test (the binding's OrderWarning asked a
 * numpy copy of it, order.turn_back): QA18's scans passed back and forth turn at their apex
 * (point 59, s = 12), as the test's definition says, and are not paired (the fit's use of it,
 * test_back_and_forth_scan_is_not_paired); the same scans in one pass, with and without
 * dropouts, turn nowhere; a V of 90 degrees does not turn (dot 0), nor where its dots
 * overflow (coordinates 1e200 apart: +inf - inf is NaN, which the fit's former test, dot >= 0
 * to stop, read as a turn); fewer than 7 points never; bad input EL_EINVAL, *first
 * untouched. */
START_TEST(test_turn_back_is_the_fits_test)
{
    double s[188], xy[2 * MAXN];
    size_t n = 0, first = 77;
    for (int i = 0; i < 60; i++) s[n++] = 12.0 * i / 59.0;
    for (int i = 1; i < 20; i++) s[n++] = 12.0 - 4.0 * i / 19.0;
    for (int i = 1; i < 110; i++) s[n++] = 8.0 + 22.0 * i / 109.0;
    const unsigned long long seeds[] = {18, 42, 47};
    for (int d = 0; d < 3; d++) {
        scan(s, n, 0.05, seeds[d], xy);
        ck_assert_int_eq(el_fit_turn_back(xy, n, &first), EL_OK);
        ck_assert_msg(first >= 57 && first <= 61 && first == turn_by_definition(xy, n),
                      "draw %d: turn at %zu (definition %zu)", d, first, turn_by_definition(xy, n));
    }
    for (int d = 0; d < (int)(sizeof DROPOUTS / sizeof DROPOUTS[0]) + 3; d++) {
        const size_t m = d < 3 ? dropout_scan(NULL, 0, (unsigned long long)d + 3, xy)
                               : dropout_scan(DROPOUTS[d - 3].drop, DROPOUTS[d - 3].nd, DROPOUTS[d - 3].seed, xy);
        ck_assert_int_eq(el_fit_turn_back(xy, m, &first), EL_OK);
        ck_assert_msg(first == 0, "one pass %d: turn at %zu", d, first);
    }
    /* a V, x monotone, its arms at +-45 degrees: chords at 90 degrees, dot 0 at the apex */
    for (int big = 0; big < 2; big++) {
        const double u = big ? 1e200 : 1.0;
        double v[2 * 15];
        for (int j = 0; j < 15; j++) { v[2 * j] = j * u; v[2 * j + 1] = -fabs(j - 7.0) * u; }
        ck_assert_int_eq(el_fit_turn_back(v, 15, &first), EL_OK);
        ck_assert_msg(first == 0, "V at scale %g: turn at %zu", u, first);
    }
    /* a hairpin (out 8, back 7: the points on two parallel lines) turns at its tip */
    double hp[2 * 15];
    for (int j = 0; j < 15; j++) { hp[2 * j] = j < 8 ? j : 14 - j; hp[2 * j + 1] = j < 8 ? 0.0 : 0.5; }
    ck_assert_int_eq(el_fit_turn_back(hp, 15, &first), EL_OK);
    ck_assert_uint_eq(first, 7);
    for (size_t m = 1; m < 7; m++) {
        ck_assert_int_eq(el_fit_turn_back(hp, m, &first), EL_OK);
        ck_assert_uint_eq(first, 0);
    }
    first = 77;
    ck_assert_int_eq(el_fit_turn_back(NULL, 15, &first), EL_EINVAL);
    ck_assert_int_eq(el_fit_turn_back(hp, 15, NULL), EL_EINVAL);
    ck_assert_int_eq(el_fit_turn_back(hp, 0, &first), EL_EINVAL);
    hp[9] = NAN;
    ck_assert_int_eq(el_fit_turn_back(hp, 15, &first), EL_EINVAL);
    ck_assert_uint_eq(first, 77);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_pairing");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, test_back_and_forth_scan_is_not_paired, 0, 3);
    tcase_add_loop_test(tc, test_dropouts_are_not_paired, 0, (int)(sizeof DROPOUTS / sizeof DROPOUTS[0]));
    tcase_add_loop_test(tc, test_even_scans_stay_paired, 0, 3);
    tcase_add_loop_test(tc, test_random_places_fit_as_orthogonal, 0,
                        (int)(sizeof RANDOM_PLACES / sizeof RANDOM_PLACES[0]));
    tcase_add_test(tc, test_turn_back_is_the_fits_test);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
