/* A fit of the same points and constraints moved rigidly is the same curve moved (FreeCAD:
 * a fit joined G2 to an arc at its start and G1 to a line at its end). 6 sketched points,
 * start point, tangent and curvature and end point and tangent held: 7 conditions on the 7
 * parameters, so the fits are the isolated curves that meet them, and which one a fit ends
 * on depends on its path. Before: over 6 rotations x 4 translations 7 distinct curves (rms
 * 0.93 - 1.42), the lowest three loops of length 90 for a chord of 63 (the held start and
 * end points paired with the first and last points, whose distances to the curve the fit
 * did not see; el__fit_stray took the curve from a held end to the first point for a stray,
 * so the loop rules never applied), and a refit from one of them went to another, higher. */
#include "testutil.h"

static const double PTS[6][2] = {{5, .2}, {14, .5}, {22, -.4}, {35, -2.8}, {47, -4.6}, {57, -5.1}};

/* the sketch turned by deg degrees and moved by (tx, ty): points xy, options o */
static void placed(double deg, double tx, double ty, double *xy, el_fit_options *o)
{
    const double a = deg * M_PI / 180.0, c = cos(a), s = sin(a);
    for (int i = 0; i < 6; i++) {
        xy[2 * i] = c * PTS[i][0] - s * PTS[i][1] + tx;
        xy[2 * i + 1] = s * PTS[i][0] + c * PTS[i][1] + ty;
    }
    el_fit_options_defaults(o);
    o->constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_TANGENT |
                     EL_CONSTRAIN_START_CURVATURE | EL_CONSTRAIN_END_POINT |
                     EL_CONSTRAIN_END_TANGENT;
    o->start_point[0] = -3.0 * c + tx;
    o->start_point[1] = -3.0 * s + ty;
    o->end_point[0] = 60.0 * c + 5.0 * s + tx;
    o->end_point[1] = 60.0 * s - 5.0 * c + ty;
    o->start_tangent = o->end_tangent = a;
    o->start_curvature = 1.0 / 28.0;
}

/* whether the curve's polygon of 256 chords crosses itself */
static int crosses_itself(const el_smooth_params *p)
{
    enum { M = 257 };
    double s[M], xy[2 * M];
    for (int i = 0; i < M; i++) s[i] = p->length * i / (M - 1);
    ck_assert_int_eq(el_smooth_eval(p, M, s, xy, NULL, NULL), EL_OK);
    for (int i = 0; i + 1 < M; i++)
        for (int j = i + 2; j + 1 < M; j++) {
            const double *a = xy + 2 * i, *b = a + 2, *c = xy + 2 * j, *d = c + 2;
            const double o1 = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
            const double o2 = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
            const double o3 = (d[0] - c[0]) * (a[1] - c[1]) - (d[1] - c[1]) * (a[0] - c[0]);
            const double o4 = (d[0] - c[0]) * (b[1] - c[1]) - (d[1] - c[1]) * (b[0] - c[0]);
            if ((o1 > 0) != (o2 > 0) && (o3 > 0) != (o4 > 0)) return 1;
        }
    return 0;
}

/* the rms distance of the 6 points xy to the curve p, from 400001 samples (a relative
 * error ~1e-9 at these distances) */
static double rms_of(const el_smooth_params *p, const double *xy)
{
    enum { M = 400001 };
    double *s = malloc(sizeof(double) * 3 * M), *g = s + M, s2 = 0.0;
    ck_assert_ptr_nonnull(s);
    for (int i = 0; i < M; i++) s[i] = p->length * i / (M - 1);
    ck_assert_int_eq(el_smooth_eval(p, M, s, g, NULL, NULL), EL_OK);
    for (int j = 0; j < 6; j++) {
        double best = HUGE_VAL;
        for (int i = 0; i < M; i++)
            best = fmin(best, hypot(g[2 * i] - xy[2 * j], g[2 * i + 1] - xy[2 * j + 1]));
        s2 += best * best;
    }
    free(s);
    return sqrt(s2 / 6.0);
}

/* 24 placements: one rms and length to 1e-9, meeting the constraints, not crossing itself */
START_TEST(test_fit_same_under_rigid_motion)
{
    const double degs[] = {0, 40, 90, 137, -70, 200};
    const double moves[4][2] = {{0, 0}, {100, 50}, {-20, 7}, {5e3, -2e3}};
    double rms0 = NAN, len0 = NAN;
    for (int r = 0; r < 6; r++)
        for (int t = 0; t < 4; t++) {
            double xy[12];
            el_fit_options o;
            placed(degs[r], moves[t][0], moves[t][1], xy, &o);
            el_fit_smooth_result res;
            ck_assert_int_eq(el_fit_smooth(xy, 6, &o, NULL, &res, NULL, NULL), EL_OK);
            ck_assert_msg(!crosses_itself(&res.params), "%g deg (%g, %g): crosses itself, rms %g",
                          degs[r], moves[t][0], moves[t][1], res.rms);
            double end[4], th[2], ka[2], s2[2] = {0.0, res.params.length};
            ck_assert_int_eq(el_smooth_eval(&res.params, 2, s2, end, th, ka), EL_OK);
            ck_assert_close(end[2], o.end_point[0], 1e-8);
            ck_assert_close(end[3], o.end_point[1], 1e-8);
            ck_assert_close(remainder(th[1] - o.end_tangent, 2 * M_PI), 0.0, 1e-9);
            ck_assert_close(ka[0], o.start_curvature, 1e-12);
            if (isnan(rms0)) { rms0 = res.rms; len0 = res.params.length; continue; }
            ck_assert_msg(fabs(res.rms - rms0) <= 1e-9 * rms0 &&
                              fabs(res.params.length - len0) <= 1e-9 * len0,
                          "%g deg (%g, %g): rms %.12g length %.12g, first %.12g %.12g", degs[r],
                          moves[t][0], moves[t][1], res.rms, res.params.length, rms0, len0);
        }
}
END_TEST

/* A fit from a curve that meets the constraints ends no higher than that curve: the curves
 * of rms 0.9756 and 1.0393 that the fits at -70 deg, (100, 50) and 0 deg, (-20, 7) found
 * before, moved back (before: refitted to 0.9793 and 1.0566, with the feet of the held ends
 * free 0.9964 and 1.0908). */
START_TEST(test_fit_from_a_curve_that_meets_them_is_not_above_it)
{
    const el_smooth_params starts[2] = {
        {-2.9999999999999987, -1.9984014443252818e-15, -0.079199070969451002, 0.15729837448063533,
         0.059954301317410613, 0.72145105994495395, 63.42619045848717},
        {-3, 0, -0.080922380026576021, 0.65585068804448843, 0.046069721193145161,
         1.0720561145595791, 63.334670011866081},
    };
    double xy[12];
    el_fit_options o;
    placed(0, 0, 0, xy, &o);
    o.use_initial = 1;
    for (int r = 0; r < 2; r++) {
        const double rms_start = rms_of(&starts[r], xy);
        el_fit_smooth_result res;
        ck_assert_int_eq(el_fit_smooth(xy, 6, &o, &starts[r], &res, NULL, NULL), EL_OK);
        ck_assert_msg(res.rms <= rms_start * (1.0 + 1e-6), "start %d: from %.9g to %.9g", r,
                      rms_start, res.rms);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_rigid");
    TCase *tc = tcase_create("rigid");
    tcase_set_timeout(tc, 600);
    tcase_add_test(tc, test_fit_same_under_rigid_motion);
    tcase_add_test(tc, test_fit_from_a_curve_that_meets_them_is_not_above_it);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
