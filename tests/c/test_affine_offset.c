/* el_affine_polyline and el_affine_end_pieces far from the origin (UTM-like coordinates):
 * the same samples translated give the same polyline translated, to rounding of the local
 * size, not of the offset (affine_polyline.c local_origin). */
#include "testutil.h"
#include <string.h>

enum { E = 801 };
static const double OFF[2] = {512345.678, 5012345.432};

/* An ellipse arc (one piece) or an S (a cubic's graph, one inflection) around (0.3, -0.2),
 * and its tangents. */
static void shape(int s_curve, double *q, double *tan)
{
    for (int j = 0; j < E; j++) {
        double t = (double)j / (E - 1);
        if (s_curve) {
            double x = 3.0 * t - 1.5;
            q[2 * j] = 0.3 + x;
            q[2 * j + 1] = -0.2 + 0.4 * x * x * x - 0.9 * x;
            tan[2 * j] = 1.0;
            tan[2 * j + 1] = 1.2 * x * x - 0.9;
        } else {
            double a = 0.2 + 2.5 * t;
            q[2 * j] = 0.3 + 2.0 * cos(a) + 0.5 * sin(a);
            q[2 * j + 1] = -0.2 + sin(a);
            tan[2 * j] = -2.0 * sin(a) + 0.5 * cos(a);
            tan[2 * j + 1] = cos(a);
        }
    }
}

/* One ulp of x (x normal, > 0 or < 0). */
static double ulp(double x) { return nextafter(fabs(x), INFINITY) - fabs(x); }

/* The largest |a - b| / max(|b|, floor) over n values. */
static double rel_diff(size_t n, const double *a, const double *b, double floor)
{
    double w = 0.0;
    for (size_t i = 0; i < n; i++) w = fmax(w, fabs(a[i] - b[i]) / fmax(fabs(b[i]), floor));
    return w;
}

/* Samples q + OFF (rounded: the data as a survey gives them) and their exact local copy
 * (q + OFF) - OFF (Sterbenz): the polyline of the far ones less OFF against the local
 * ones'. Both compute on samples within a few sizes of their origin, so they differ by
 * what the construction makes of rounding of the local size (~4): t (f~'s parameter, the
 * minimiser of a flat psi) up to 4e-12 of its range, vertices 5.3e-12, A 4.2e-13 relative,
 * psi 1.5e-15 (measured, 8 cases); asserted 2e-11, 2e-11, 2e-12, 1e-14, the vertices beyond
 * the half ulp of OFF their own coordinates are rounded to. Main computed in the offset's
 * ulps (9.3e-10 at 5e6): t 4.9e-9 .. 1.8e-7 apart, vertices 2.1e-8 .. 5.2e-7, A 3e-9 ..
 * 4.4e-8 relative, psi 5e-12 .. 5e-9. The pieces el_affine_end_pieces finds: the same. */
START_TEST(test_polyline_far_from_the_origin)
{
    static double q[2 * E], tan[2 * E], far[2 * E], loc[2 * E];
    const int s_curve = _i / 4, with_tan = (_i / 2) % 2, fit_ends = _i % 2;
    shape(s_curve, q, tan);
    for (int j = 0; j < 2 * E; j++) {
        far[j] = q[j] + OFF[j % 2];
        loc[j] = far[j] - OFF[j % 2];
    }
    el_affine_options o;
    el_affine_options_defaults(&o);
    o.fit_ends = fit_ends;
    el_affine_result rf, rl;
    const double *T = with_tan ? tan : NULL;
    ck_assert_int_eq(el_affine_polyline(E, far, T, 0, NULL, 24, &o, &rf), EL_OK);
    ck_assert_int_eq(el_affine_polyline(E, loc, T, 0, NULL, 24, &o, &rl), EL_OK);
    ck_assert_uint_eq(rf.npts, rl.npts);
    ck_assert_uint_eq(rf.npieces, rl.npieces);
    ck_assert_uint_eq(rf.npieces, s_curve ? 2 : 1);
    double dt = rel_diff(rf.npts, rf.t, rl.t, (double)E);
    double dA = rel_diff(rf.npieces, rf.A, rl.A, 0.0);
    double dS = fabs(rf.S_total - rl.S_total) / rl.S_total, dx = 0.0;
    for (size_t j = 0; j < 2 * rf.npts; j++)
        dx = fmax(dx, fabs((rf.xy[j] - OFF[j % 2]) - rl.xy[j]) - 0.5 * ulp(OFF[j % 2]));
    double dpsi_abs = 0.0;
    for (size_t p = 0; p < rf.npieces; p++) dpsi_abs = fmax(dpsi_abs, fabs(rf.psi[p] - rl.psi[p]));
    ck_assert_msg(dt <= 2e-11 && dA <= 2e-12 && dS <= 1e-15 && dx <= 2e-11 && dpsi_abs <= 1e-14,
                  "case %d: t %.3g, A %.3g, S %.3g relative apart, psi %.3g, vertices %.3g "
                  "beyond the offset's rounding", _i, dt, dA, dS, dpsi_abs, dx);
    size_t np[2], ends[2][2], nmin[2][2];
    ck_assert_int_eq(el_affine_end_pieces(E, far, T, 0, NULL, &o, &np[0], ends[0], nmin[0]), EL_OK);
    ck_assert_int_eq(el_affine_end_pieces(E, loc, T, 0, NULL, &o, &np[1], ends[1], nmin[1]), EL_OK);
    ck_assert(np[0] == np[1] && !memcmp(ends[0], ends[1], sizeof ends[0]) &&
              !memcmp(nmin[0], nmin[1], sizeof nmin[0]));
    el_affine_result_free(&rf);
    el_affine_result_free(&rl);
}
END_TEST

/* A translation by a multiple of 2^k (>= the samples' extent) computes on the same local
 * samples: t, A, psi, S_total to the bit; a curve near the origin is not moved at all. */
START_TEST(test_polyline_translated_by_a_power_of_two_grid)
{
    static double q[2 * E], tan[2 * E], far[2 * E];
    shape(1, q, tan);
    for (int j = 0; j < 2 * E; j++) q[j] = ldexp(nearbyint(ldexp(q[j], 26)), -26);  /* on K's grid */
    const double K[2] = {ldexp(3.0, 21), -ldexp(5.0, 20)};   /* multiples of 2^20 */
    for (int j = 0; j < 2 * E; j++) far[j] = q[j] + K[j % 2];
    el_affine_result rf, rq;
    ck_assert_int_eq(el_affine_polyline(E, far, NULL, 0, NULL, 30, NULL, &rf), EL_OK);
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 30, NULL, &rq), EL_OK);
    ck_assert_uint_eq(rf.npts, rq.npts);
    ck_assert(!memcmp(rf.t, rq.t, rf.npts * sizeof *rf.t));
    ck_assert(!memcmp(rf.A, rq.A, rf.npieces * sizeof *rf.A));
    ck_assert(!memcmp(rf.psi, rq.psi, rf.npieces * sizeof *rf.psi));
    ck_assert(rf.S_total == rq.S_total);
    for (size_t j = 0; j < 2 * rf.npts; j++)   /* the vertices: q's plus K, rounded once */
        ck_assert(rf.xy[j] == rq.xy[j] + K[j % 2]);
    el_affine_result_free(&rf);
    el_affine_result_free(&rq);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("affine_offset");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, test_polyline_far_from_the_origin, 0, 8);
    tcase_add_test(tc, test_polyline_translated_by_a_power_of_two_grid);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
