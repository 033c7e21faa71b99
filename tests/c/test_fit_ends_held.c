/* Fits pinned at both ends with a zero curvature at one or both (a batten with a free end
 * between two pins): the start-state chart holds the zero start curvature and leaves the
 * end point to Ipopt's rows; the ends chart (fit_model.c) holds both end points and, since
 * kappa0 L = 0 is free of scale, that curvature too (el__fit_ends_held, fit_restart.c). The
 * two fall into different basins, and the fit keeps the lower. Sparse noisy points at
 * uneven places along a smooth curve of length 1 (numpy default_rng(5), the generator of
 * bench/bench_fit_sparse.py), pinned at that curve's ends, by both models; the plain
 * counterpart is the start-state chart's fit alone (el__fit_run with FIT_RUN_INNER). Each
 * test failed before the ends chart held the curvature: ZK13 smooth at 2.9 x this rms,
 * ZK101 at 2.0 x, ZK17 discrete with both end curvatures 0 not met (EL_EDOM), where the ends
 * chart meets them, ZK79 discrete and ZK101 smooth with both at 3.0 and 2.2 x. */
#include "testutil.h"
#include "fit_internal.h"
#include "fit_wander.h"
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <string.h>

/* seed 5 case 13: 9 points, noise 1.0 % of the extent; its curve's ends (start,
 * end) and end curvatures 2.18, -0.308 */
static const double ZK13[] = {
    0.001761020665737351, -0.012215033753461049, -0.03344242350789735, 0.03941813613755728,
    -0.0536143330209436, 0.05289269613557455, -0.11223911214413396, 0.10617140908351802,
    -0.13075836368890292, 0.12102405173858574, -0.20311974097709298, 0.15461693276767738,
    -0.4974828968223471, 0.3105478969795347, -0.5249550973048296, 0.36489638317497125,
    -0.6444198458577148, 0.6888962176305,
};
static const double ZK13_ENDS[4] = {0.0, 0.0, -0.6541806597270909, 0.6892469608505178};

/* seed 5 case 17: 20 points, noise 0.1 % of the extent; its curve's ends (start,
 * end) and end curvatures 0.858, -1.91 */
static const double ZK17[] = {
    0.0006755737794895713, 0.0018335298687661534, -0.019796123152254715, -0.08192890935126274,
    -0.022790957328004388, -0.09503850376827082, -0.02544558257832018, -0.1033350177277167,
    -0.026212497363594007, -0.11702431334615507, -0.03175760863848828, -0.20960821537789634,
    -0.026456264306712024, -0.2524674527339609, -0.02650686269339421, -0.25902692467487515,
    -0.004849948103303594, -0.35376671689203104, 0.00625667552119867, -0.3818708495043089,
    0.016890454923704695, -0.4079540761720713, 0.023429270361292626, -0.4197852904968917,
    0.07789897894665114, -0.5080770687138972, 0.11289642093506938, -0.5562062763485146,
    0.15002877057116346, -0.6017696621446614, 0.22618269192469462, -0.68954367272201, 0.260557559427757,
    -0.7294513436717341, 0.29201775813109504, -0.777549054423681, 0.32940775206569056,
    -0.8377348057162852, 0.34798506591275363, -0.8822768768448872,
};
static const double ZK17_ENDS[4] = {0.0, 0.0, 0.34869160545814004, -0.8826586926338388};

/* seed 5 case 79: 39 points, noise 0.1 % of the extent; its curve's ends (start,
 * end) and end curvatures 4.6, 0.815 */
static const double ZK79[] = {
    -0.00040535797820151297, 0.00012617046776578552, -0.010113682431007734, 0.02801331780148278,
    -0.014350389290180388, 0.03474245542875305, -0.019650045826616957, 0.0451704877169173,
    -0.020029713773859297, 0.046807498946255535, -0.02552313150441567, 0.058058747872969,
    -0.053926074497443494, 0.09722163846525576, -0.061525892879117056, 0.10497020793985211,
    -0.10277949310594149, 0.1463607163344172, -0.12130352146424217, 0.16385315383105006,
    -0.1346830090899161, 0.17551206758408205, -0.15960574907781366, 0.19719175405072362,
    -0.1772095509838691, 0.21409524014317594, -0.2000082992411681, 0.23576647803437434,
    -0.21160766376482976, 0.24639562445364252, -0.21780256954453575, 0.2550586329089273,
    -0.23152502063845137, 0.27089569629762017, -0.23227370306839087, 0.2725137001930923,
    -0.24437765185037624, 0.2885972971007015, -0.2587174666098936, 0.3104471345374235,
    -0.27450080052572823, 0.34222378266999554, -0.27603100912178713, 0.4871156448462637,
    -0.26604401008103484, 0.5067462516374124, -0.26286070278964857, 0.5119173862517271,
    -0.25654437478023884, 0.5218872351793906, -0.22134528185215077, 0.5603691318043367,
    -0.16233717522485078, 0.5917828810906941, -0.15776660725657274, 0.594463484057282,
    -0.131853723753188, 0.6021400054056519, -0.12468322223763587, 0.6048135873546865,
    -0.12214864305369852, 0.6023030581844435, -0.10251546584992877, 0.6060065927385917,
    -0.0792573576872706, 0.6098551995379686, -0.07824636299029246, 0.6078397663724968,
    -0.07144871361904509, 0.6087830017960852, -0.05385416279566098, 0.6092446506703848,
    -0.0027975883298273735, 0.6077893405599006, 0.042600478840294664, 0.6027852961043486,
    0.08297721271406922, 0.597436456183948,
};
static const double ZK79_ENDS[4] = {0.0, 0.0, 0.08357768339401914, 0.5975771316811409};

/* seed 5 case 101: 33 points, noise 1.0 % of the extent; its curve's ends (start,
 * end) and end curvatures 0.712, -0.369 */
static const double ZK101[] = {
    -0.0043195769468589735, 0.0004955387116694806, 0.10882802937127273, -0.08186409998600758,
    0.11345653199103428, -0.10267762097299783, 0.2163556684098798, -0.17741671731970565,
    0.23665151247649585, -0.1896742263368405, 0.2648738959069006, -0.19387612334561202,
    0.2735775886868798, -0.18759492232024993, 0.30984818227738575, -0.24552847954360843,
    0.303437860931394, -0.22507354164246934, 0.3016292216556924, -0.24046953838856663,
    0.3332736976253152, -0.23300691348963676, 0.38244341170956603, -0.2749807242916496,
    0.39336214666583663, -0.2658778530993347, 0.39894818156868506, -0.276224949716906,
    0.39356423937340407, -0.27835753766230265, 0.4220851191104401, -0.2796936533840104,
    0.4806639661834783, -0.31325368567720124, 0.5484809607016556, -0.36734206808851816,
    0.6072738052739061, -0.3806613395594709, 0.6216489896513684, -0.40651268156209497,
    0.6322336290729188, -0.39419319157398797, 0.6273045857574223, -0.3863676670820298,
    0.6857779784279386, -0.42981273276365084, 0.7073332372625863, -0.4333539760026796,
    0.710520475919168, -0.4441217862820518, 0.7444482026616847, -0.45776570905453545,
    0.7348962135255358, -0.47264574871312665, 0.769138045790115, -0.47141086279449906,
    0.7448385891776484, -0.4569920664163047, 0.7672080332792494, -0.48546051777617444,
    0.8003547197384059, -0.48050862616878987, 0.827339648517339, -0.5090132219583937,
    0.8508996540628274, -0.527292398171958,
};
static const double ZK101_ENDS[4] = {0.0, 0.0, 0.8512010162887202, -0.5191942594449669};

#define N_OF(a) (sizeof a / sizeof a[0] / 2)

/* The curvature of a fit's curve (params in the model's Jacobian order) at its start (at_end
 * 0) or end (1): the discrete one that of the polygon extended by a vertex (fit_internal.h,
 * on the internal parameters: the smooth w = sqrt(mu)). */
static double end_curvature(int model, const double *params, size_t n, int at_end)
{
    static double tmp[FIT_WORK];
    double v[FIT_NP];
    for (int j = 0; j < FIT_NP; j++) v[j] = el__fit_norm_param(model, j, params[j], 0.0, 0.0, 1.0);
    fit_end e;
    ck_assert_int_eq(el__fit_end_state(model, v, n, at_end, &e, tmp), EL_OK);
    return e.kappa;
}

/* The fit of xy (n points, scaled by scale about the origin) pinned at ends (start, end,
 * scaled) with the zero curvatures of mask (EL_CONSTRAIN_START_CURVATURE and / or
 * EL_CONSTRAIN_END_CURVATURE): EL_OK, both ends and those curvatures met (to 1e-9 of the
 * size, curvatures times the size), its rms no higher than the plain counterpart's when
 * that met them, and at most `gain` x it; gain < 0: the natural batten's checks below. */
static void check_zero_curvature(int model, const double *xy0, size_t n, const double *ends0, int mask, double scale,
                                double gain)
{
    double xy[2 * 64], ends[4];
    ck_assert(n <= 64);
    for (size_t i = 0; i < 2 * n; i++) xy[i] = xy0[i] * scale;
    for (int i = 0; i < 4; i++) ends[i] = ends0[i] * scale;
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT | mask;
    memcpy(o.start_point, ends, sizeof o.start_point);
    memcpy(o.end_point, ends + 2, sizeof o.end_point);
    o.start_curvature = o.end_curvature = 0.0;
    fit_out plain, fit;
    double pd[64], pfs[64];     /* the plain fit's distances and feet (the natural batten's checks) */
    memset(&plain, 0, sizeof plain);
    memset(&fit, 0, sizeof fit);
    plain.status = fit.status = -1;
    if (mask == EL_CONSTRAIN_END_CURVATURE) {
        /* the fit runs reversed (the zero curvature at its start): so does the plain one */
        double rxy[2 * 64];
        for (size_t i = 0; i < n; i++) { rxy[2 * i] = xy[2 * (n - 1 - i)]; rxy[2 * i + 1] = xy[2 * (n - 1 - i) + 1]; }
        el_fit_options r = o;
        r.constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT | EL_CONSTRAIN_START_CURVATURE;
        memcpy(r.start_point, ends + 2, sizeof r.start_point);
        memcpy(r.end_point, ends, sizeof r.end_point);
        (void)el__fit_run(model, rxy, n, &r, FIT_RUN_INNER, NULL, &plain, NULL, NULL);
    } else {
        (void)el__fit_run(model, xy, n, &o, FIT_RUN_INNER, NULL, &plain, pd, pfs);
    }
    double d[64], fs[64];
    const int st = el__fit_run_either_way(model, xy, n, &o, 0, NULL, &fit, d, fs);
    ck_assert_msg(st == EL_OK, "model %d n %zu scale %g: status %d", model, n, scale, st);
    double V[2 * 64];
    if (model == FIT_SMOOTH) {
        const el_smooth_params p = {fit.params[0], fit.params[1], fit.params[2], fit.params[3], fit.params[4],
                                    fit.params[5], fit.params[6]};
        const double s[2] = {0.0, p.length};
        ck_assert_int_eq(el_smooth_eval(&p, 2, s, V, NULL, NULL), EL_OK);
        V[2 * n - 2] = V[2];
        V[2 * n - 1] = V[3];
    } else {
        const el_discrete_params p = {fit.params[0], fit.params[1], fit.params[2], fit.params[3], fit.params[4],
                                      fit.params[5], fit.params[6]};
        ck_assert_int_eq(el_discrete_eval(&p, n, V), EL_OK);
    }
    ck_assert(hypot(V[0] - ends[0], V[1] - ends[1]) <= 1e-9 * scale);
    ck_assert(hypot(V[2 * n - 2] - ends[2], V[2 * n - 1] - ends[3]) <= 1e-9 * scale);
    for (int at_end = 0; at_end < 2; at_end++)
        if (mask & (at_end ? EL_CONSTRAIN_END_CURVATURE : EL_CONSTRAIN_START_CURVATURE))
            ck_assert_msg(fabs(end_curvature(model, fit.params, n, at_end)) * scale <= 1e-9,
                          "model %d scale %g: curvature %g at end %d", model, scale,
                          end_curvature(model, fit.params, n, at_end), at_end);
    const int plain_fit = plain.status == EL_OK || plain.status == EL_ENOCONV || plain.status == EL_EMAXITER;
    if (gain > 0.0 && plain_fit)
        ck_assert_msg(fit.rms <= plain.rms * (1.0 + 1e-9) && fit.rms <= gain * plain.rms,
                      "model %d n %zu scale %g: rms %.6g, the start-state chart's %.6g", model, n, scale,
                      fit.rms / scale, plain.rms / scale);
    if (gain < 0.0) {
        /* the natural batten (fit_natural.c): it follows its points (el__fit_stray), where
         * a lower fit may wind loops across them; no higher than the start-state chart's
         * fit where that follows them too */
        double cx, cy, sc;
        ck_assert_int_eq(el__fit_normalisation(xy, n, &cx, &cy, &sc), EL_OK);
        const double noise = el__fit_noise_rms(xy, n, sc) * sc;
        const double stray = el__fit_stray(xy, n, fs, el__fit_out_length(model, n, &fit), noise, sc);
        ck_assert_msg(stray <= FIT_STRAY, "model %d n %zu: stray %g, rms %g", model, n, stray, fit.rms / scale);
        /* the plain fit above, run on xy with o (not reversed: both curvatures held) */
        ck_assert(mask != EL_CONSTRAIN_END_CURVATURE);
        if (plain_fit && el__fit_stray(xy, n, pfs, el__fit_out_length(model, n, &plain), noise, sc) <= FIT_STRAY)
            ck_assert_msg(fit.rms <= plain.rms * (1.0 + 1e-9), "model %d n %zu: rms %.6g, the start-state chart's %.6g",
                          model, n, fit.rms / scale, plain.rms / scale);
    }
}

/* A zero start curvature: ZK13 smooth (9 points; the start-state chart's fit 0.0442, the
 * ends chart's 0.0151), at the sketch's scale and at 1e-6 and 1e6 of it; discrete, no
 * higher. */
START_TEST(test_fit_zero_start_curvature_held_in_ends_chart)
{
    const double scales[3] = {1.0, 1e-6, 1e6};
    for (int a = 0; a < 3; a++)
        check_zero_curvature(FIT_SMOOTH, ZK13, N_OF(ZK13), ZK13_ENDS, EL_CONSTRAIN_START_CURVATURE, scales[a], 0.5);
    check_zero_curvature(FIT_DISCRETE, ZK13, N_OF(ZK13), ZK13_ENDS, EL_CONSTRAIN_START_CURVATURE, 1.0, 1.0);
}
END_TEST

/* A zero end curvature: the fit runs reversed (fit_restart.c), the curvature held at its
 * start; ZK101 by both models (the start-state chart's 0.0171 / 0.0163, the ends chart's
 * 0.0083 / 0.0083; discrete, the start-state chart's from the smooth fit's curve first
 * reaches 0.0083 too: no higher); the plain counterpart reversed too. */
START_TEST(test_fit_zero_end_curvature_held_reversed)
{
    check_zero_curvature(FIT_SMOOTH, ZK101, N_OF(ZK101), ZK101_ENDS, EL_CONSTRAIN_END_CURVATURE, 1.0, 0.6);
    check_zero_curvature(FIT_DISCRETE, ZK101, N_OF(ZK101), ZK101_ENDS, EL_CONSTRAIN_END_CURVATURE, 1.0, 1.0);
}
END_TEST

/* Both end curvatures zero (a natural batten: fit_natural.c, and the discrete fit from
 * it): ZK17 discrete, where the start-state chart's fit met no polygon (EL_EDOM), meets
 * them; ZK79 discrete and ZK101 both models (at scales 1, 1e-6, 1e6) follow their points,
 * no higher than the start-state chart's fit where that follows them (ZK79's former fit in
 * the ends chart, 0.0175 against 0.0523, wound a polygon of length 14.9 across points
 * along 1). */
START_TEST(test_fit_zero_curvatures_both_ends_met)
{
    const int both = EL_CONSTRAIN_START_CURVATURE | EL_CONSTRAIN_END_CURVATURE;
    check_zero_curvature(FIT_DISCRETE, ZK17, N_OF(ZK17), ZK17_ENDS, both, 1.0, -1.0);
    check_zero_curvature(FIT_DISCRETE, ZK79, N_OF(ZK79), ZK79_ENDS, both, 1.0, -1.0);
    check_zero_curvature(FIT_SMOOTH, ZK101, N_OF(ZK101), ZK101_ENDS, both, 1.0, -1.0);
    check_zero_curvature(FIT_SMOOTH, ZK101, N_OF(ZK101), ZK101_ENDS, both, 1e-6, -1.0);
    check_zero_curvature(FIT_DISCRETE, ZK101, N_OF(ZK101), ZK101_ENDS, both, 1e6, -1.0);
}
END_TEST

/* The conjugate (el__fit_conjugate) by its defining identities, not its formula: on 300
 * inflectional curves (k = +-0.03..0.99, mu 1e-4..1e4, starting at an inflection q = K, -K,
 * 3K) it starts at the same point with the same tangent and zero curvature, its next
 * inflection lies as far along (w scaled by K(k') / K(k)) with the original's tangent there
 * (mod 2 pi), and half way between it runs opposite to the original (theta + pi): between its
 * inflections it turns the other way round, through the directions the original does not
 * take. */
/* |a - b| mod 2 pi, in [0, pi] */
static double angle_diff(double a, double b)
{
    return fabs(remainder(a - b, 2.0 * M_PI));
}

START_TEST(test_conjugate_turns_the_other_way_between_the_same_inflections)
{
    double worst[4] = {0, 0, 0, 0};
    unsigned long long seed = 12345u;
    for (int t = 0; t < 300; t++) {
        const double u3 = test_uniform(&seed, 0.0, 1.0);
        const double k = (t % 2 ? -1.0 : 1.0) * test_uniform(&seed, 0.03, 0.99);
        const double mu = pow(10.0, test_uniform(&seed, -4.0, 4.0));
        const double K = gsl_sf_ellint_Kcomp(fabs(k), GSL_PREC_DOUBLE), w = sqrt(mu);
        const double q = (t % 3 == 0 ? 1.0 : t % 3 == 1 ? -1.0 : 3.0) * K;
        const double half = 2.0 * K / w;             /* inflection to inflection */
        el_smooth_params p = {u3 - 0.5, 0.25, 6.0 * u3 - 3.0, mu, k, q, 2.0 * half}, c = p;
        ck_assert_int_eq(el__fit_conjugate(&c), EL_OK);
        const double s[3] = {0.0, 0.5 * half, half};
        double xy[2][6], th[2][3], ka[2][3];
        ck_assert_int_eq(el_smooth_eval(&p, 3, s, xy[0], th[0], ka[0]), EL_OK);
        ck_assert_int_eq(el_smooth_eval(&c, 3, s, xy[1], th[1], ka[1]), EL_OK);
        worst[0] = fmax(worst[0], hypot(xy[1][0] - xy[0][0], xy[1][1] - xy[0][1]) * w);
        worst[1] = fmax(worst[1], fmax(angle_diff(th[1][0], th[0][0]),
                                       angle_diff(th[1][2], th[0][2])));
        worst[2] = fmax(worst[2], fmax(fabs(ka[1][0]), fabs(ka[1][2])) / w);
        worst[3] = fmax(worst[3], angle_diff(th[1][1], th[0][1] + M_PI));
    }
    ck_assert_msg(worst[0] <= 1e-12 && worst[1] <= 1e-11 && worst[2] <= 1e-11 && worst[3] <= 1e-11,
                  "start %.3g, inflection tangents %.3g, curvatures %.3g, mid tangent %.3g",
                  worst[0], worst[1], worst[2], worst[3]);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_ends_held");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_fit_zero_start_curvature_held_in_ends_chart);
    tcase_add_test(tc, test_fit_zero_curvatures_both_ends_met);
    tcase_add_test(tc, test_conjugate_turns_the_other_way_between_the_same_inflections);
    suite_add_tcase(s, tc);
    /* results that must not depend on OpenBLAS's CPU kernel: make check-c runs this case
     * again under several (OPENBLAS_CORETYPE; the discrete fit ended EL_ENOCONV under
     * Nehalem's, Ipopt's restoration failing at the certified point) */
    TCase *any = tcase_create("any_kernel");
    tcase_set_timeout(any, 120);
    tcase_add_test(any, test_fit_zero_end_curvature_held_reversed);
    suite_add_tcase(s, any);
    return s;
}

int main(void) { return test_run_suite(suite()); }
