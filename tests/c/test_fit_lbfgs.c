/* Fits with Ipopt's L-BFGS Hessian (el_fit_options.limited_memory, the paper's setting):
 * they converge to the exact Hessian's fit instead of crawling to max_iter. */
#include "testutil.h"
#include <stdlib.h>

/* make fuzz's input fuzz/corpus/fuzz-fit-discrete-lbfgs-start-tangent-slow.bin: 62
 * points (pairs repeated) at the scale 1e300, a start tangent, 5 candidates of 191
 * iterations. Unscaled, L-BFGS ran every candidate to max_iter (1560 iterations, 3.3 s)
 * and returned EL_EDOM with the tangent unmet; with the variables scaled
 * (fit_ipopt.c, lbfgs_scaling) 209 iterations and the exact Hessian's rms. The tangent,
 * 1 rad from the free fit's, is now held in the start-state chart (the discrete vertex
 * tangent), reached in 16 continuation stages (four ended at rms 0.23 of the normalised
 * points, every guess, 1-1.8 s a fit; sixteen at 0.097 in 0.03-0.07 s). */
static const double loop62[] = {
    -0.0012859825871474283, -0.017132662840944536, 0.11763869014871596, 0.04041954775995996,
    0.15382062186005924, 0.16103249793030622, 0.15382062186005924, 0.16103249793030622,
    0.24915348539201607, 0.33989629605501126, 0.3014303810398028, 0.44064684094187684,
    0.3014303810398028, 0.44064684094187684, 0.292423734415156, 0.6933648335591391,
    0.2741322332560045, 0.7757020191976756, 0.2741322332560045, 0.7757020191976756,
    0.26257774933743183, 0.990092797764374, 0.20772161016742124, 1.122908129720868,
    0.20772161016742124, 1.122908129720868, 0.06461960389409364, 1.283152722589659,
    0.04814303870344209, 1.414270653446109, 0.04814303870344209, 1.414270653446109,
    -0.1310406562122715, 1.5907139740889489, -0.19615648450349293, 1.6661028716021575,
    -0.19615648450349293, 1.6661028716021575, -0.3447550466481251, 1.8194335961865264,
    -0.38079521625765994, 1.949596223768778, -0.38079521625765994, 1.949596223768778,
    -0.5154016614297712, 2.087611281414948, -0.5676119123809127, 2.2139986394231985,
    -0.5676119123809127, 2.2139986394231985, -0.6967826301271609, 2.3704591930720156,
    -0.7403604392502922, 2.476990720663165, -0.7403604392502922, 2.476990720663165,
    -0.7819061375166738, 2.7105192393028177, -0.7935978010800825, 2.840882308212578,
    -0.7935978010800825, 2.840882308212578, -0.77432394020737, 3.0492675707572445,
    -0.7390579839665793, 3.1377511608975905, -0.7390579839665793, 3.1377511608975905,
    -0.5984695357587674, 3.3380435309898906, -0.5214776170021409, 3.4080895902991735,
    -0.5214776170021409, 3.4080895902991735, -0.3172242253195049, 3.5314322369577527,
    -0.20038558968380088, 3.5251172328042495, -0.20038558968380088, 3.5251172328042495,
    0.029095360184691416, 3.498916216831769, 0.12912664748731353, 3.4491787337486084,
    0.12912664748731353, 3.4491787337486084, 0.29262973682062093, 3.298244162699715,
    0.3518192526380363, 3.203448566995134, 0.3518192526380363, 3.203448566995134,
    0.42135027404915226, 2.9916587725355295, 0.43240140926021675, 2.86257446974129,
    0.43240140926021675, 2.86257446974129, 0.39686490062852, 2.669633458784822,
    0.37561955599022784, 2.539479041872807, 0.37561955599022784, 2.539479041872807,
    0.2737605262502058, 2.353099369706266, 0.24139849506231448, 2.253986527209735,
    0.24139849506231448, 2.253986527209735, 0.12183095403452769, 2.060754408586593,
    0.04826216675543829, 1.9819371438900477, 0.04826216675543829, 1.9819371438900477,
    -0.07514867242401224, 1.7888931341018506, -0.12542072203559226, 1.6769273543083676,
    -0.12542072203559226, 1.6769273543083676, -0.2854443205865087, 1.53215809742674,
};

START_TEST(test_lbfgs_start_tangent_converges_not_crawls)
{
    const size_t n = sizeof loop62 / sizeof loop62[0] / 2;
    double xy[sizeof loop62 / sizeof loop62[0]];
    for (size_t i = 0; i < 2 * n; i++) xy[i] = loop62[i] * 1e300;
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.max_iter = 191;
    o.max_candidates = 5;
    o.constraints = EL_CONSTRAIN_START_TANGENT;
    o.start_tangent = 1.5113145647364004;
    el_fit_discrete_result exact, lbfgs;
    ck_assert_int_eq(el_fit_discrete(xy, n, &o, NULL, &exact, NULL, NULL), EL_OK);
    o.limited_memory = 1;
    const int st = el_fit_discrete(xy, n, &o, NULL, &lbfgs, NULL, NULL);
    ck_assert_msg(st == EL_OK, "status %d, %d iterations", st, lbfgs.iterations);
    /* the held tangent's continuation stages (fit_constraints.c) count in both */
    ck_assert_msg(lbfgs.iterations <= exact.iterations + 2 * o.max_iter, "%d iterations, exact Hessian %d",
                  lbfgs.iterations, exact.iterations);
    ck_assert_msg(fabs(lbfgs.rms - exact.rms) <= 1e-6 * exact.rms, "rms %.17g, exact Hessian %.17g",
                  lbfgs.rms, exact.rms);
}
END_TEST

/* A designer's sample: 40 points along a smooth elastica, dense then sparse with a gap,
 * noise ~1 % of the length; both models with free ends and with a start tangent 0.2 rad
 * off: L-BFGS ends with EL_OK at the exact Hessian's rms (to 1e-6). The discrete model
 * with that tangent ended in a worse local optimum (rms 8.86 against 2.12) and then
 * EL_EMAXITER while Ipopt's L-BFGS kept 6 pairs for 7 variables (fit_ipopt.c, its
 * options). */
START_TEST(test_lbfgs_uneven_noisy_converges)
{
    const el_smooth_params c = {0.0, 0.0, -1.028, 1.0 / (105.0 * 105.0), 0.65, 0.25, 330.0};
    enum { N = 40 };
    double s[N], xy[2 * N];
    unsigned long long rng = 5;
    for (int i = 0; i < N; i++)
        s[i] = c.length * (i < 28 ? 0.3 * i / 27.0 : 0.45 + 0.55 * (i - 28) / 11.0);
    ck_assert_int_eq(el_smooth_eval(&c, N, s, xy, NULL, NULL), EL_OK);
    for (int i = 0; i < 2 * N; i++) xy[i] += test_uniform(&rng, -3.3, 3.3);
    for (int model = 0; model < 2; model++)
        for (int con = 0; con <= 1; con++) {
            el_fit_options o;
            el_fit_options_defaults(&o);
            if (con) { o.constraints = EL_CONSTRAIN_START_TANGENT; o.start_tangent = c.phi + 0.2; }
            double rms[2];
            int st[2];
            for (int lm = 0; lm < 2; lm++) {
                o.limited_memory = lm;
                if (model) {
                    el_fit_smooth_result r;
                    st[lm] = el_fit_smooth(xy, N, &o, NULL, &r, NULL, NULL);
                    rms[lm] = r.rms;
                } else {
                    el_fit_discrete_result r;
                    st[lm] = el_fit_discrete(xy, N, &o, NULL, &r, NULL, NULL);
                    rms[lm] = r.rms;
                }
            }
            ck_assert_int_eq(st[0], EL_OK);
            ck_assert_msg(st[1] == EL_OK, "model %d constraint %d: status %d", model, con, st[1]);
            ck_assert_msg(fabs(rms[1] - rms[0]) <= 1e-6 * rms[0], "model %d constraint %d: rms %.17g, exact %.17g",
                          model, con, rms[1], rms[0]);
        }
}
END_TEST

/* 1000 points along a smooth elastica (k 0.917, a normal noise of 1 % of the length), the
 * smooth model by orthogonal distance with L-BFGS. The feet were projected from the last
 * trial point's, so along a search direction f jumped where a foot changed branch; the
 * line search halved alpha up to ~1075 times and the fit ended with EL_ENOCONV after 222
 * iterations. Projected from the line search's base point (fit_ipopt.c, ensure): EL_OK
 * within the first candidate, at the exact Hessian's rms (to 1e-4). */
START_TEST(test_lbfgs_feet_from_the_line_search_base)
{
    enum { N = 1000 };
    unsigned long long rng = 5;
    el_smooth_params p = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    p.phi = test_uniform(&rng, -3, 3);
    p.mu = test_uniform(&rng, 0.5, 2);
    p.k = exp(test_uniform(&rng, log(0.1), log(0.99)));
    p.q = test_uniform(&rng, -2, 2);
    p.length = test_uniform(&rng, 3, 9) / sqrt(p.mu);
    static double s[N], xy[2 * N];
    for (int i = 0; i < N; i++) s[i] = p.length * i / (N - 1);
    ck_assert_int_eq(el_smooth_eval(&p, N, s, xy, NULL, NULL), EL_OK);
    for (int i = 0; i < 2 * N; i++) xy[i] += 0.01 * p.length / sqrt(2.0) * test_normal(&rng);
    el_fit_options o;
    el_fit_options_defaults(&o);
    el_fit_smooth_result exact, lbfgs;
    ck_assert_int_eq(el_fit_smooth(xy, N, &o, NULL, &exact, NULL, NULL), EL_OK);
    o.limited_memory = 1;
    const int st = el_fit_smooth(xy, N, &o, NULL, &lbfgs, NULL, NULL);
    ck_assert_msg(st == EL_OK && lbfgs.iterations < o.max_iter, "status %d, %d iterations", st,
                  lbfgs.iterations);
    ck_assert_msg(fabs(lbfgs.rms - exact.rms) <= 1e-4 * exact.rms, "rms %.17g, exact Hessian %.17g",
                  lbfgs.rms, exact.rms);
}
END_TEST

/* Sparse noisy data: 20 points at random arc lengths of random elasticae (k 0.97, 1.13,
 * 1.50), noise 0.1 % of the length, the smooth model (three of the 30 fits of
 * briefs/lbfgs_repro.py). L-BFGS ended EL_EMAXITER after 600 iterations (0.8 s), the
 * first two at rms 0.0219 and 0.158 against the exact path's 0.00507 and 0.0328: Ipopt's
 * watchdog took a trial step, the feet were projected there and kept when it went back
 * (f at the same point 1.6e-2 instead of 9.8e-4), and no stop test met noisy data at its
 * optimum. The third ended EL_OK at rms 0.00390 against 0.00384: its feet, projected from
 * the guess's fractions, stayed on a loop's other pass (fit.c: the paired start). Now:
 * EL_OK at the exact path's rms (to 1e-6), the kept fit stopped by the first-order
 * certificate (Ipopt's status 5). */
static const double repro00[] = {
    -0.010959780540619694, -0.0010140022986277872, 0.1281501386937386, 0.7426497960418197,
    0.025562799104582225, 1.1418073326724105, -0.09152656512062816, 1.450820090036046,
    -0.10416686682139108, 1.5570829853346655, -0.14640679710978177, 1.6780265353919699,
    -0.1899164898803758, 1.8329279860577918, -0.17092148268194346, 2.2477617409826705,
    -0.16638319989032177, 2.288570501662849, -0.14056543644600275, 2.3656439262698266,
    -0.04559292881600266, 2.516513332138237, 0.08908934590735276, 2.6395620424141235,
    0.39300661780786544, 2.6903515380405154, 0.4467104006222164, 2.673901486140591,
    0.2607896819974921, 1.8140211929437502, 0.24004553050575525, 1.8087780140401437,
    0.04752861646976357, 1.75805327202416, -0.1817893243392672, 1.7619602897626587,
    -0.9461504778576316, 1.8734949973927817, -1.1751829021249252, 1.9049775325565688,
};
static const double repro27[] = {
    -0.005520969462323753, -0.006785240458729061, 0.1841858521307566, 0.08070292302887064,
    0.2909004004197532, 0.6681465942373973, 0.24365037288526453, 0.7739250509365356,
    -0.6345700779828716, 1.0238897395630022, -0.757979149691585, 0.9154361798188765,
    -0.7965988930936119, 0.8425333658917775, -0.8465843655675059, 0.7265937056263265,
    -0.829939863854643, 0.7175573549955668, -0.8148754019247735, 0.5407745354595901,
    -0.7685426849199877, 0.457598069972797, -0.5822296760143763, 0.3395794787509198,
    -0.2968308001005555, 0.39658853303778074, -0.2983374563539917, 0.3900429920254299,
    -0.26028708959211566, 1.1645596932019475, -0.27940196470016143, 1.1899884756621666,
    -0.6961451452047616, 1.4260603219702797, -0.7178914885700447, 1.4263340731934604,
    -0.8977043037415742, 1.428569987723929, -1.1047534028673291, 1.3396117171472293,
};
static const double repro29[] = {
    -0.001239638060082814, -0.005593270463796793, -0.678510687347675, -0.01503789478194494,
    -0.6474851369038184, -0.22443547396182872, -0.566117777680264, -0.3090648410101745,
    -0.32460179463738115, -0.33887961006006145, -0.0939514335249582, -0.09318308202301717,
    -0.10073412286131497, -0.083528258797756, -0.13786109739752006, 0.1581542218419088,
    -0.40783784203091533, 0.34053541543004273, -0.4976185602581164, 0.34278130976569626,
    -0.6163564940032835, 0.29793782918339073, -0.7761935700913227, -0.07134970613634495,
    -0.6359389885335187, -0.23091026699465556, -0.5887145613903207, -0.2470433229022578,
    -0.5100532224584079, -0.25324419408061455, -0.45169034035984734, -0.24336015019440219,
    -0.22031871211151335, 0.16943721471613524, -0.34833904084239187, 0.35885603083609974,
    -0.599592513787672, 0.44745047192618165, -0.7484197929414423, -0.12743145281861692,
};

START_TEST(test_lbfgs_sparse_noisy_smooth_at_the_exact_optimum)
{
    const double *data[3] = {repro00, repro27, repro29};
    for (int c = 0; c < 3; c++) {
        const size_t n = 20;
        el_fit_options o;
        el_fit_options_defaults(&o);
        el_fit_smooth_result exact, lbfgs;
        ck_assert_int_eq(el_fit_smooth(data[c], n, &o, NULL, &exact, NULL, NULL), EL_OK);
        o.limited_memory = 1;
        const int st = el_fit_smooth(data[c], n, &o, NULL, &lbfgs, NULL, NULL);
        ck_assert_msg(st == EL_OK, "case %d: status %d after %d iterations", c, st, lbfgs.iterations);
        ck_assert_msg(lbfgs.ipopt_status == 5, "case %d: Ipopt's status %d, not the certificate's stop", c,
                      lbfgs.ipopt_status);
        ck_assert_msg(fabs(lbfgs.rms - exact.rms) <= 1e-6 * exact.rms, "case %d: rms %.17g, exact Hessian %.17g",
                      c, lbfgs.rms, exact.rms);
    }
}
END_TEST

/* Noise-free discrete elasticae of 1000 vertices (k 0.125, 0.4, 3; paired distance):
 * the fit is exact. L-BFGS ended at Ipopt's 'acceptable' level (a gradient below 1e-6
 * for 15 iterations) at rms up to 2.5e-8 of the length, tried the further guesses
 * (200-430 iterations) and once ended EL_EMAXITER; stopped by the first-order
 * certificate instead, every fit is exact to 3e-12 of the length within the first guess. */
START_TEST(test_lbfgs_noise_free_discrete_exact)
{
    enum { N = 1000 };
    static double xy[2 * N];
    for (int t = 0; t < 12; t++) {
        const double k = t < 4 ? 0.125 : t < 8 ? 0.4 : 3.0;
        const el_discrete_params p = {0.0, 0.0, 1.0 / N, -1.0 + 0.5 * (t % 4), (t % 2 ? 1 : -1) * 2.5 / (N - 1),
                                      0.3 * t - 1.5, k};
        ck_assert_int_eq(el_discrete_eval(&p, N, xy), EL_OK);
        el_fit_options o;
        el_fit_options_defaults(&o);
        o.limited_memory = 1;
        o.distance = EL_DISTANCE_PAIRED;
        el_fit_discrete_result r;
        const int st = el_fit_discrete(xy, N, &o, NULL, &r, NULL, NULL);
        const double L = (N - 1) * p.h;
        ck_assert_msg(st == EL_OK, "t %d: status %d", t, st);
        ck_assert_msg(r.rms <= 1e-10 * L, "t %d: rms %.3g of the length", t, r.rms / L);
        ck_assert_msg(r.candidates == 1 && r.iterations < o.max_iter, "t %d: %d candidates, %d iterations", t,
                      r.candidates, r.iterations);
    }
}
END_TEST

/* A k range whose end the fit reaches (1000 noise-free points at random arc lengths of a
 * smooth elastica, the discrete model, k <= 0.8 x the curve's): where a slack is tiny
 * Ipopt moves its bound (slack_move), and L-BFGS ended with k up to 3.2e-11 beyond the
 * range's end, EL_EDOM. Kept inside (fit_ipopt.c): EL_OK at the exact path's rms. */
static int by_value(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

START_TEST(test_lbfgs_k_range_end_kept)
{
    enum { N = 1000 };
    static double s[N], xy[2 * N];
    const unsigned long long seeds[2] = {1, 4};
    for (int t = 0; t < 2; t++) {
        unsigned long long rng = seeds[t];
        el_smooth_params c = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
        c.phi = test_uniform(&rng, -1, 1);
        c.mu = test_uniform(&rng, 0.3, 2);
        c.k = test_uniform(&rng, 0.3, 1.6);
        c.q = test_uniform(&rng, 0, 3);
        c.length = test_uniform(&rng, 2, 6);
        for (int i = 0; i < N; i++) s[i] = test_uniform(&rng, 0, c.length);
        qsort(s, N, sizeof s[0], by_value);
        s[0] = 0.0;
        s[N - 1] = c.length;
        ck_assert_int_eq(el_smooth_eval(&c, N, s, xy, NULL, NULL), EL_OK);
        el_fit_options o;
        el_fit_options_defaults(&o);
        o.constraints = EL_CONSTRAIN_K;
        o.k_range[0] = 0.0;
        o.k_range[1] = 0.8 * c.k;
        el_fit_discrete_result exact, lbfgs;
        ck_assert_int_eq(el_fit_discrete(xy, N, &o, NULL, &exact, NULL, NULL), EL_OK);
        o.limited_memory = 1;
        const int st = el_fit_discrete(xy, N, &o, NULL, &lbfgs, NULL, NULL);
        ck_assert_msg(st == EL_OK, "seed %llu: status %d, k %.17g, range end %.17g", seeds[t], st, lbfgs.params.k,
                      o.k_range[1]);
        ck_assert(lbfgs.params.k <= o.k_range[1]);
        ck_assert_msg(fabs(lbfgs.rms - exact.rms) <= 1e-6 * exact.rms, "seed %llu: rms %.17g, exact %.17g", seeds[t],
                      lbfgs.rms, exact.rms);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_lbfgs");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_lbfgs_start_tangent_converges_not_crawls);
    tcase_add_test(tc, test_lbfgs_uneven_noisy_converges);
    tcase_add_test(tc, test_lbfgs_feet_from_the_line_search_base);
    tcase_add_test(tc, test_lbfgs_sparse_noisy_smooth_at_the_exact_optimum);
    tcase_add_test(tc, test_lbfgs_noise_free_discrete_exact);
    tcase_add_test(tc, test_lbfgs_k_range_end_kept);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
