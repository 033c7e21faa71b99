/* The default fit on sparse points at uneven places with a little noise (a designer's
 * sketch) reaches the basin of the curve they were drawn from: its rms within 1 % of the
 * fit started from the true parameters. Before guess.c's noise estimate for uneven
 * spacing and its merged polygon, each of these stopped in a worse basin (rms 0.0328,
 * 0.0484, 0.0282 against 0.0040, 0.0081, 0.0049): the plain third differences took the
 * unevenness for noise (7-20 x the truth), and the guesses of the points themselves, with
 * sides of a few noise levels, all landed in the same wrong basin. */
#include "testutil.h"
#include <math.h>

/* 20 points of a loop (k = 1.128) at random arc lengths, noise 0.1 % of the length per
 * coordinate (lbfgs_repro.py, seed 1, trial 27) */
static const double LOOP20[] = {
    -0.0055209694623237528, -0.0067852404587290614, 0.18418585213075661, 0.080702923028870638,
    0.29090040041975318, 0.66814659423739731, 0.24365037288526453, 0.77392505093653563,
    -0.63457007798287157, 1.0238897395630022, -0.75797914969158497, 0.91543617981887648,
    -0.79659889309361187, 0.84253336589177752, -0.84658436556750594, 0.72659370562632652,
    -0.82993986385464302, 0.71755735499556683, -0.81487540192477348, 0.54077453545959009,
    -0.76854268491998767, 0.45759806997279701, -0.58222967601437625, 0.33957947875091982,
    -0.29683080010055551, 0.39658853303778074, -0.29833745635399173, 0.39004299202542991,
    -0.26028708959211566, 1.1645596932019475, -0.27940196470016143, 1.1899884756621666,
    -0.69614514520476156, 1.4260603219702797, -0.7178914885700447, 1.4263340731934604,
    -0.89770430374157417, 1.4285699877239291, -1.1047534028673291, 1.3396117171472293,
};
static const el_smooth_params LOOP20_TRUE = {0.0, 0.0, -0.63976382031839818, 1.7628602265492361, 1.1278912191500383, 0.36852510090279234, 4.9448128979706398};

/* 15 points of a loop (k = 1.321), the same kind (basin.md's sparse set, case 83) */
static const double LOOP15[] = {
    -0.01230977795034318, -0.0008442147650366596, 0.69264452870771875, -0.24194091094337733,
    0.55127957480645295, 0.051748733287564345, 0.4587351104692029, 0.093432654515684568,
    0.28609809938387371, 0.065461193451931687, 0.18419880932648372, -0.46456206983332254,
    0.4659702082892801, -0.6006181985719824, 0.46408451720467941, -0.60075475841321813,
    0.43078473960922209, 0.061307815058777991, 0.43596772022023128, 0.039232571513624852,
    0.43410230296438274, 0.027933285840054826, 0.39046831498641865, -0.36015380273597736,
    0.95185490983363497, 0.1401656082563156, 0.56625186844656272, -0.073614352599109187,
    1.3024296528604369, -0.40900428571178604,
};
static const el_smooth_params LOOP15_TRUE = {0.0, 0.0, -2.9965783924236202, 1.6861144055922339, 1.3214596669947136, 0.17143843498827982, 7.9960146169945023};

/* 35 points of a loop (k = 1.582), fitted by the discrete model (case 82) */
static const double LOOP35[] = {
    -0.0055561072141315721, -0.0067280980646332216, 0.037135528641454849, 0.23516907920485045,
    -0.20434285820511111, 0.48265419251083841, -0.3970401421229478, 0.46420851901005927,
    -0.45239157286258058, 0.42316544282316693, -0.51643157034355158, 0.36096275532833777,
    -0.53004316502314652, 0.32094122776234335, -0.54863493857868928, 0.23991777948643284,
    -0.54891617144625127, 0.2270400582195137, -0.37655632237478104, -0.043809098393246496,
    -0.35972802360794975, -0.057168502625913102, -0.3132363014555552, -0.065453272803864301,
    0.081518787238290216, 0.16944885802589002, 0.10596860117415757, 0.23291305579178814,
    0.092716620394153737, 0.2602617972595353, 0.096689892523144666, 0.25991002425949306,
    -0.43932455866770381, 0.14837349553121637, -0.28172149267372659, 0.050194294200547211,
    -0.16330419719444877, 0.036106613167226818, -0.091046474314213185, 0.047755510143862701,
    -0.030769265497261073, 0.07014269745405971, -0.026378880312487026, 0.071223996207091786,
    0.11535745539279603, 0.22343919739855325, 0.14249847994769144, 0.28138256210726509,
    0.15153893046218153, 0.33289348439058009, 0.16408549917910928, 0.3683302937520177,
    0.15968846932886199, 0.38865099695192429, 0.1312317552084572, 0.49581104279979032,
    0.13545025431394028, 0.50125353414372298, 0.12573387573307085, 0.53673696626194045,
    0.10517477203926752, 0.55635918672451656, -0.13937837778541559, 0.71544361258528877,
    -0.35881547580023637, 0.62960154829383141, -0.44448975869501967, 0.46703533288883525,
    -0.28666969457337538, 0.18352994601690703,
};
static const el_smooth_params LOOP35_TRUE = {0.0, 0.0, -2.0605714552488221, 1.311762577844654, 1.5821603134562194, 3.370640416661506, 5.3454115274955019};

static void check_smooth(const double *xy, size_t n, const el_smooth_params *truth)
{
    el_fit_smooth_result def, from_truth;
    ck_assert_int_eq(el_fit_smooth(xy, n, NULL, NULL, &def, NULL, NULL), EL_OK);
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.use_initial = 1;
    ck_assert_int_eq(el_fit_smooth(xy, n, &o, truth, &from_truth, NULL, NULL), EL_OK);
    ck_assert_msg(def.rms <= 1.01 * from_truth.rms, "n %zu: default rms %.6g, from the truth %.6g (k %g, %g)",
                  n, def.rms, from_truth.rms, def.params.k, from_truth.params.k);
}

START_TEST(test_fit_sparse_uneven_loop_smooth)
{
    check_smooth(LOOP20, sizeof LOOP20 / sizeof LOOP20[0] / 2, &LOOP20_TRUE);
    check_smooth(LOOP15, sizeof LOOP15 / sizeof LOOP15[0] / 2, &LOOP15_TRUE);
}
END_TEST

START_TEST(test_fit_sparse_uneven_loop_discrete)
{
    const size_t n = sizeof LOOP35 / sizeof LOOP35[0] / 2;
    const el_smooth_params *t = &LOOP35_TRUE;
    const double h = t->length / (double)(n - 1);
    const el_discrete_params truth = {t->x0, t->y0, h, t->phi, sqrt(t->mu) * h, t->q, t->k};
    el_fit_discrete_result def, from_truth;
    ck_assert_int_eq(el_fit_discrete(LOOP35, n, NULL, NULL, &def, NULL, NULL), EL_OK);
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.use_initial = 1;
    ck_assert_int_eq(el_fit_discrete(LOOP35, n, &o, &truth, &from_truth, NULL, NULL), EL_OK);
    ck_assert_msg(def.rms <= 1.01 * from_truth.rms, "default rms %.6g, from the truth %.6g", def.rms, from_truth.rms);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_basin");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_fit_sparse_uneven_loop_smooth);
    tcase_add_test(tc, test_fit_sparse_uneven_loop_discrete);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
