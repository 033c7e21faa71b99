/* Discrete fits whose constraints are Ipopt's rows (a pinned end point, an end tangent, the
 * start tangent: the discrete model holds only the start point and a zero start curvature
 * exactly) on sparse noisy points at uneven places, fitted by distance to the polygon (the
 * default on such points): a designer's sketch with the ends it must join. The
 * constraints are those of the smooth curve the points were drawn from (its end points;
 * its end tangents, which the polygon's first and last segments must follow), and the fit
 * must meet them and follow the points: its rms within 20 % of that curve's own (computed
 * here from dense samples) and its length within 10 % of that curve's. Each set is one of
 * 150 random sets of 6-59 points (numpy default_rng(6), the generator of
 * bench/bench_fit_sparse.py); each test failed before fit.c's selection of the fits that
 * meet the rows, the tangent row 2 sin(delta / 2) and the smooth fit's start
 * (el__fit_smooth_start). */
#include "sketch_arc59.h"
#include "sketch_check.h"

/* 40 points of a gentle arc (k = 0.46, turning by 1.06 rad), noise 1 % of the extent (set 23) */
static const double PP40[] = {
    0.0009874783037724674, -0.004152025388101198, 0.09404839225815138, 0.02738082256408414,
    0.12996499228556951, 0.03649057741630204, 0.15036785488672658, 0.0573132252405732,
    0.1475849664360206, 0.06797781166225962, 0.20452874873149654, 0.07717529745095376,
    0.23726611292088845, 0.09878165743573795, 0.2602345227728791, 0.11824929052918647,
    0.28450617802867467, 0.12725822575456217, 0.2952161147390524, 0.14320670159998192,
    0.33110687763619845, 0.1606709236269453, 0.38808909207847025, 0.21489153668243482,
    0.3988940585785393, 0.21845536267677593, 0.41382194295668884, 0.23154385644669107,
    0.42103884447948386, 0.23325083399626473, 0.44833162363883694, 0.2655668003619676,
    0.4704580514236905, 0.2765708710707472, 0.4814596218807637, 0.29127506258082203,
    0.4827587798150691, 0.3023928733161671, 0.49016176996495925, 0.31766695175010023,
    0.49929021282110597, 0.3239821507936356, 0.4942392817808098, 0.32235457199599343,
    0.4995847196117259, 0.32454999947320134, 0.5068743232226683, 0.31690987032490875,
    0.5271319635662608, 0.35553388312678574, 0.512947530233448, 0.35991930087801016,
    0.5429059714108905, 0.37583849191420476, 0.582375446476472, 0.4357245361448565,
    0.578666863147604, 0.45805271127838976, 0.6011931592372877, 0.4871326336751527,
    0.5990522391643703, 0.48476203532684575, 0.6116489513102928, 0.49751835054003185,
    0.6154504304244209, 0.5482346603840492, 0.6388440516604251, 0.564231038623373,
    0.643521076719734, 0.568193838210056, 0.6513024824496152, 0.5786676940615443,
    0.6463477108790734, 0.590053976207565, 0.6368277549928107, 0.5999634963254954,
    0.665837379496288, 0.6269248010662086, 0.6699580212911108, 0.684619712134539,
};
static const el_smooth_params PP40_TRUE = {0, 0, 1.091026926051888, 1.6921439796757685, 0.46300181324831136, -1.0021897334153347, 1};

/* 7 points of a bend (k = -0.76, turning by 1.3 rad), noise 1 % (set 172) */
static const double TT7[] = {
    -0.0048011984996511065, -3.442907179601966e-05, -0.06912759288678973, -0.0716806112442387,
    -0.05580466383831978, -0.09490525868611542, -0.14804721205475194, -0.19303816879816374,
    -0.22703722817676544, -0.24624094202923136, -0.36363381266763595, -0.43099512546980684,
    -0.37216209046189375, -0.846180489939498,
};
static const el_smooth_params TT7_TRUE = {0, 0, -0.6014626651767014, 4.990296157108886, -0.7576176791625856, 1.3298170295599037, 1};


/* The default discrete fit of xy with the constraints mask taken from the smooth curve p:
 * EL_OK, each constraint met by the polygon (vertices 0 and n-1, the first and last
 * segments' directions: to 1e-9), rms within 20 % of p's own, length within 10 % of p's. */
static void check_meets_and_follows(const double *xy, size_t n, const el_smooth_params *p, int mask)
{
    double P[4], th[2], ka[2];
    const el_fit_options o = constraints_of(p, mask, P, th, ka);
    el_fit_discrete_result r;
    const int st = el_fit_discrete(xy, n, &o, NULL, &r, NULL, NULL);
    ck_assert_msg(st == EL_OK, "n %zu, constraints %#x: status %d (constraint %#x)", n, (unsigned)mask, st,
                  (unsigned)r.constraint);
    double V[2 * 64];
    ck_assert(n <= 64);
    ck_assert_int_eq(el_discrete_eval(&r.params, n, V), EL_OK);
    if (mask & EL_CONSTRAIN_START_POINT) ck_assert(hypot(V[0] - P[0], V[1] - P[1]) <= 1e-9);
    if (mask & EL_CONSTRAIN_END_POINT) ck_assert(hypot(V[2 * n - 2] - P[2], V[2 * n - 1] - P[3]) <= 1e-9);
    if (mask & EL_CONSTRAIN_START_TANGENT)
        ck_assert(fabs(remainder(atan2(V[3] - V[1], V[2] - V[0]) - th[0], 2.0 * M_PI)) <= 1e-9);
    if (mask & EL_CONSTRAIN_END_TANGENT)
        ck_assert(fabs(remainder(atan2(V[2 * n - 1] - V[2 * n - 3], V[2 * n - 2] - V[2 * n - 4]) - th[1],
                                 2.0 * M_PI)) <= 1e-9);
    const double truth = true_rms(xy, n, p), length = r.params.h * (double)(n - 1);
    ck_assert_msg(r.rms <= 1.2 * truth && fabs(length - p->length) <= 0.1 * p->length,
                  "n %zu, constraints %#x: rms %.6g length %.4g; the smooth curve %.6g, %.4g", n,
                  (unsigned)mask, r.rms, length, truth, p->length);
}

#define G1_START (EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_START_TANGENT)
#define G1_END (EL_CONSTRAIN_END_POINT | EL_CONSTRAIN_END_TANGENT)

/* Both end points pinned: EL_EDOM before (every guess's Ipopt run crept along the
 * end-point rows to max_iter, 5203 iterations, and ended off them). */
START_TEST(test_fit_discrete_pinned_ends)
{
    check_meets_and_follows(PP40, sizeof PP40 / sizeof PP40[0] / 2, &PP40_TRUE,
                            EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT);
}
END_TEST

/* G1 at both ends. TT7: EL_EDOM before, the first guess's fit, off the end tangent at
 * max_iter, kept for its lower f over three that met it. ARC59: EL_EDOM before, every
 * guess's fit with a reversed end tangent, where sin(theta - alpha) vanishes too. */
START_TEST(test_fit_discrete_g1_ends)
{
    check_meets_and_follows(TT7, sizeof TT7 / sizeof TT7[0] / 2, &TT7_TRUE, G1_START | G1_END);
    check_meets_and_follows(ARC59, sizeof ARC59 / sizeof ARC59[0] / 2, &ARC59_TRUE, G1_START | G1_END);
}
END_TEST

/* G1 start alone: before, a polygon of length 51740 (segments of 900 zigzagging through
 * the points, rms 0.0152, 1.6 x the smooth curve's) within the noise rule; every guess's
 * fit is far from the points or strays, and the smooth fit's start reaches 0.0093. */
START_TEST(test_fit_discrete_g1_start)
{
    check_meets_and_follows(ARC59, sizeof ARC59 / sizeof ARC59[0] / 2, &ARC59_TRUE, G1_START);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_discrete_rows");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_fit_discrete_pinned_ends);
    tcase_add_test(tc, test_fit_discrete_g1_ends);
    tcase_add_test(tc, test_fit_discrete_g1_start);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
