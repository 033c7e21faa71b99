/* Fits with Ipopt's L-BFGS Hessian (el_fit_options.limited_memory, the paper's setting):
 * they converge to the exact Hessian's fit instead of crawling to max_iter. */
#include "testutil.h"

/* make fuzz's input fuzz/corpus/fuzz-fit-discrete-lbfgs-start-tangent-slow.bin: 62
 * points (pairs repeated) at the scale 1e300, a start tangent, 5 candidates of 191
 * iterations. Unscaled, L-BFGS ran every candidate to max_iter (1560 iterations, 3.3 s)
 * and returned EL_EDOM with the tangent unmet; with the variables scaled
 * (fit_ipopt.c, lbfgs_scaling) 209 iterations and the exact Hessian's rms. */
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
    ck_assert_msg(lbfgs.iterations <= 2 * o.max_iter, "%d iterations", lbfgs.iterations);
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

static Suite *suite(void)
{
    Suite *s = suite_create("fit_lbfgs");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_lbfgs_start_tangent_converges_not_crawls);
    tcase_add_test(tc, test_lbfgs_uneven_noisy_converges);
    tcase_add_test(tc, test_lbfgs_feet_from_the_line_search_base);
    tcase_add_test(tc, test_lbfgs_noise_free_discrete_exact);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
