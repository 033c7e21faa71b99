/* A fit whose basin must not turn on rounding. QA's FreeCAD fit of a sketched B-spline
 * (60 points, mm) joined G2 to an arc at its start (start point, tangent and curvature 0.02
 * held) and following a line's direction at its end (a tangent row 0.41 rad from the fit
 * that holds the start alone): two minima meet these, rms 2.130 and 2.169 mm, and the fit
 * landed in the one or the other as the document's save and reopen moved the points by
 * ~4e-14 mm (Ipopt's one jump from el__fit_held_start's continuation to the row; main: 13 of
 * 20 fits of points moved by 1e-13 relative in the higher one under Haswell's kernel, 15 of
 * 20 under SkylakeX's). fit_candidate.c's rows_halfway runs Ipopt to the row in two stages
 * too and keeps the lower. make check-c runs the case any_kernel again under several OpenBLAS
 * kernels. */
#include "testutil.h"
#include <math.h>
#include <string.h>

/* the points as the reopened document gave them (mm, in the fit's plane) */
static const double QA_G2[] = {
    -20.000000000000007, 10.0, -18.63407889221952, 10.00312690796433, -17.26818690864744,
    10.012573502227093, -15.902354325211718, 10.028429541827196, -14.536612440579773,
    10.05076991982485, -13.170993223089084, 10.079650555323937, -11.805528829528512,
    10.115103445060278, -10.440250967301417, 10.157130719250379, -9.07519006821218,
    10.205697523405048, -7.710374239994344, 10.260723524521605, -6.345827961911972,
    10.322072818505871, -4.981570495109018, 10.389541999192513, -3.6176139894860633,
    10.462846143207754, -2.253961290469615, 10.541602477157378, -0.8906034861180991,
    10.625311535959087, 0.4724827060610153, 10.713335710182669, 1.8353375250732356,
    10.80487523860833, 3.198020413103535, 10.898941959057577, 4.560611445261436,
    10.994331520935754, 5.923211261057659, 11.08959532404835, 7.285938592212936,
    11.183014210352935, 8.648924280536725, 11.272576903765716, 10.012300582955334,
    11.355967318407039, 11.376184693901763, 11.43056599022169, 12.740655938726938,
    11.49347173662113, 14.105727157026948, 11.541549742747389, 15.471312450493997,
    11.57151099953073, 16.8371955261241, 11.580024792515026, 18.203004775801205,
    11.563860540059796, 19.56820211808845, 11.520048288251456, 20.93210445342197,
    11.44624917003308, 22.2940932270823, 11.342941673797817, 23.653754394983586,
    11.212485285647144, 25.010853082168047, 11.057591843602328, 26.365324068294846,
    10.881161222176058, 27.717247810663558, 10.686146391885263, 29.066817621030566,
    10.475439436922546, 30.41430435911837, 10.251784762631864, 31.76002352031454,
    10.017720308375416, 33.10430765173124, 9.775543869480078, 34.447485266912416,
    9.527299731033374, 35.78986615611718, 9.274780343074617, 37.13173225085696, 9.019538190080937,
    38.47333289641046, 8.76290386062881, 39.81488336840493, 8.50600728236543, 41.156565608116544,
    8.249799969963066, 42.49853035159504, 7.99507686021505, 43.84090003271451, 7.742496863037104,
    45.18377202079474, 7.492601656425993, 46.52722189889098, 7.245832526364108,
    47.871306598908184, 7.00254522959359, 49.21606728890185, 6.763022964776953, 50.56153196241005,
    6.527487597132927, 51.90771771544478, 6.296109309239835, 53.25463271900977, 6.069014857906652,
    54.602277907811505, 5.846294611878596, 55.9506484122689, 5.6280085331045715, 57.2997347632512,
    5.414191248901597, 58.64952389875082, 5.204856345850551, 60.00000000000001, 5.000000000000007,
};
enum { QA_N = sizeof QA_G2 / sizeof QA_G2[0] / 2 };

static void qa_options(el_fit_options *o)
{
    el_fit_options_defaults(o);
    o->constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_TANGENT |
                     EL_CONSTRAIN_START_CURVATURE | EL_CONSTRAIN_END_TANGENT;
    o->start_point[0] = -20.000000000000014;
    o->start_point[1] = 9.999999999999998;
    o->start_tangent = -8.326672684688673e-17;
    o->start_curvature = 0.020000000000000007;
    o->end_tangent = -0.2449786631268641;
}

/* The fit of the QA points, and of the same points each coordinate times (1 + 1e-13 g), g
 * standard normal: every one the same curve to 1e-9 (its rms, length, mu, k), and that curve
 * the lower of the two minima: the higher one lies above it (the fit from its curve alone,
 * max_candidates 1: Ipopt from its own feet, which stays at a minimum). */
START_TEST(test_a_rounding_of_the_points_keeps_the_basin)
{
    el_fit_options o;
    qa_options(&o);
    el_fit_smooth_result r0, r;
    ck_assert_int_eq(el_fit_smooth(QA_G2, QA_N, &o, NULL, &r0, NULL, NULL), EL_OK);
    unsigned long long seed = 20261206u;
    double xy[2 * QA_N], worst = 0.0;
    for (int t = 0; t < 12; t++) {
        for (int i = 0; i < 2 * QA_N; i++) xy[i] = QA_G2[i] * (1.0 + 1e-13 * test_normal(&seed));
        ck_assert_int_eq(el_fit_smooth(xy, QA_N, &o, NULL, &r, NULL, NULL), EL_OK);
        const double d[4] = {fabs(r.rms - r0.rms) / r0.rms,
                             fabs(r.params.length - r0.params.length) / r0.params.length,
                             fabs(r.params.mu - r0.params.mu) / r0.params.mu,
                             fabs(r.params.k - r0.params.k) / fabs(r0.params.k)};
        for (int j = 0; j < 4; j++) worst = fmax(worst, d[j]);
        ck_assert_msg(worst <= 1e-9, "moved by 1e-13 (%d): rms %.10g, L %.10g mm, where the points "
                      "as given: rms %.10g, L %.10g mm", t, r.rms, r.params.length, r0.rms,
                      r0.params.length);
    }
    /* the higher minimum: the fit that held the row from QA's reopened document */
    const el_smooth_params high = {-20.000000000000014, 9.999999999999998, -0.09918220857589195,
                                   0.004896381717656052, 0.15126303768201163, 0.33402025439937183,
                                   78.35387171676307};
    el_fit_options oi = o;
    oi.use_initial = 1;
    oi.max_candidates = 1;
    ck_assert_int_eq(el_fit_smooth(QA_G2, QA_N, &oi, &high, &r, NULL, NULL), EL_OK);
    ck_assert_msg(r.rms > 1.01 * r0.rms, "the other minimum: rms %.10g, the fit's %.10g", r.rms, r0.rms);
    ck_assert_msg(r0.rms < 2.1298, "rms %.10g (the lower minimum: 2.12977 mm)", r0.rms);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_rounding");
    TCase *any = tcase_create("any_kernel");
    tcase_set_timeout(any, 120);
    tcase_add_test(any, test_a_rounding_of_the_points_keeps_the_basin);
    suite_add_tcase(s, any);
    return s;
}

int main(void) { return test_run_suite(suite()); }
