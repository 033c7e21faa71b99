/* Fits whose constraints no curve of the model meets: the fit returned (EL_EDOM naming a
 * constraint, or EL_EMAXITER) is the candidate nearest to meeting them, not the one of the
 * lowest objective among those that miss them (fit_choose.c, keep_the_better). QA22's ship
 * frame (qa22_held.h, 57 points) held at its own end tangents and curvatures with its end
 * points swapped: 8 equations for 7 parameters. Smooth, the lowest objective among the
 * starts (each missing them) was kept before: its held values missed by 8.13 (an end
 * curvature, the points' rms radius being 1) at rms 2.87, where another start's miss by
 * 3.00 at rms 3.81; on the way a start missing by 178 was kept for an objective 0.3 % lower
 * than one missing by 3.0. Discrete: 2.65 either way (guarded here).
 * The errors are measured without the library's fit code: end points from el_discrete_eval
 * / el_smooth_eval, discrete end tangents theta_0, theta_n-1 (seed 000 (4.4)), discrete end
 * curvatures (2/h) tan(K/2) at the end vertices of the polygon extended by one vertex (seed
 * 000 (3.4)), smooth ones from el_smooth_eval's theta and kappa. */
#include "testutil.h"
#include "qa22_held.h"
#include <math.h>
#include <string.h>

enum { N57 = sizeof FRAME57 / sizeof FRAME57[0] / 2 };

/* The frame's conditions: its end tangents and curvatures, its end points swapped. */
static void swapped_frame(el_fit_options *o)
{
    el_fit_options_defaults(o);
    o->constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT | EL_CONSTRAIN_START_TANGENT |
                     EL_CONSTRAIN_END_TANGENT | EL_CONSTRAIN_START_CURVATURE | EL_CONSTRAIN_END_CURVATURE;
    memcpy(o->start_point, FRAME57 + 2 * (N57 - 1), sizeof o->start_point);
    memcpy(o->end_point, FRAME57, sizeof o->end_point);
    o->start_tangent = FRAME57_T[0];
    o->end_tangent = FRAME57_T[1];
    o->start_curvature = FRAME57_K[0];
    o->end_curvature = FRAME57_K[1];
}

/* The points' rms radius about their centroid (the fit's normalising scale). */
static double rms_radius(const double *xy, size_t n)
{
    double cx = 0.0, cy = 0.0, s2 = 0.0;
    for (size_t i = 0; i < n; i++) { cx += xy[2 * i]; cy += xy[2 * i + 1]; }
    cx /= (double)n; cy /= (double)n;
    for (size_t i = 0; i < n; i++) s2 += pow(xy[2 * i] - cx, 2) + pow(xy[2 * i + 1] - cy, 2);
    return sqrt(s2 / (double)n);
}

/* The largest error of the held values: points and curvatures in units of the rms radius
 * sc (a point's larger coordinate difference / sc, a curvature's difference x sc), tangents
 * in rad. */
static double worst_error(const el_fit_options *o, const double P[2][2], const double T[2],
                          const double K[2], double sc)
{
    const double held_p[2][2] = {{o->start_point[0], o->start_point[1]}, {o->end_point[0], o->end_point[1]}};
    const double held_t[2] = {o->start_tangent, o->end_tangent};
    const double held_k[2] = {o->start_curvature, o->end_curvature};
    double w = 0.0;
    for (int e = 0; e < 2; e++) {
        w = fmax(w, fmax(fabs(P[e][0] - held_p[e][0]), fabs(P[e][1] - held_p[e][1])) / sc);
        w = fmax(w, fabs(remainder(T[e] - held_t[e], 2.0 * M_PI)));
        w = fmax(w, fabs(K[e] - held_k[e]) * sc);
    }
    return w;
}

START_TEST(test_fit_discrete_infeasible_keeps_the_nearest)
{
    el_fit_options o;
    swapped_frame(&o);
    el_fit_discrete_result r;
    const int st = el_fit_discrete(FRAME57, N57, &o, NULL, &r, NULL, NULL);
    ck_assert_msg(st == EL_EDOM || st == EL_EMAXITER, "status %d", st);
    ck_assert_int_eq(r.status, st);
    ck_assert(r.constraint != 0 || st == EL_EMAXITER);
    double V[2 * (N57 + 2)], kappa[N57 + 2];
    ck_assert_int_eq(el_discrete_eval(&r.params, N57, V), EL_OK);
    el_discrete_params ex = r.params;     /* extended by one vertex at each end */
    ex.q -= ex.z;
    ck_assert_int_eq(el_discrete_curvature(&ex, N57 + 2, kappa), EL_OK);
    const double P[2][2] = {{V[0], V[1]}, {V[2 * N57 - 2], V[2 * N57 - 1]}};
    const double T[2] = {discrete_vertex_tangent(&r.params, 0.0),
                         discrete_vertex_tangent(&r.params, (double)(N57 - 1))};
    const double K[2] = {kappa[0], kappa[N57 - 1]};
    const double w = worst_error(&o, P, T, K, rms_radius(FRAME57, N57));
    ck_assert_msg(w < 4.0, "discrete: held values missed by %.4g (rms %.4g, h %.3g)", w, r.rms,
                  r.params.h);
}
END_TEST

START_TEST(test_fit_smooth_infeasible_keeps_the_nearest)
{
    el_fit_options o;
    swapped_frame(&o);
    el_fit_smooth_result r;
    const int st = el_fit_smooth(FRAME57, N57, &o, NULL, &r, NULL, NULL);
    ck_assert_msg(st == EL_EDOM || st == EL_EMAXITER, "status %d", st);
    ck_assert_int_eq(r.status, st);
    const double s[2] = {0.0, r.params.length};
    double xy[4], th[2], ka[2];
    ck_assert_int_eq(el_smooth_eval(&r.params, 2, s, xy, th, ka), EL_OK);
    const double P[2][2] = {{xy[0], xy[1]}, {xy[2], xy[3]}};
    const double w = worst_error(&o, P, th, ka, rms_radius(FRAME57, N57));
    ck_assert_msg(w < 4.0, "smooth: held values missed by %.4g (rms %.4g, length %.3g)", w, r.rms,
                  r.params.length);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_infeasible");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, test_fit_discrete_infeasible_keeps_the_nearest);
    tcase_add_test(tc, test_fit_smooth_infeasible_keeps_the_nearest);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
