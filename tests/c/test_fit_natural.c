/* The natural batten: smooth fits pinned at both ends with both end curvatures 0
 * (fit_natural.c). Every such curve is a member of a one-parameter family per number of
 * half-waves m (both ends inflections on the chord), and the fit is a search of it, not
 * Ipopt's rows from the guesses. Checked here: the moduli that bound the family (k*, where
 * 2E = K, and the touching lobes' k_t) by their defining identities and on sampled curves;
 * members recovered exactly from sparse uneven points at extreme scales, without Ipopt;
 * the search against a dense brute-force scan of the family; and a designer's sketch
 * (numpy default_rng(5), bench/bench_fit_sparse.py's generator, case 26) where the rows'
 * fit wound a chain of loops across the points and this one follows them. */
#include "testutil.h"
#include "fit_internal.h"
#include "fit_wander.h"
#include <gsl/gsl_sf_ellint.h>
#include <string.h>

/* seed 5 case 26: 42 points, noise 1.0 % of the extent, pinned at its curve's ends */
static const double ZK26[] = {
    0.007537621093488366, 0.0007232589560732242, -0.022606941068267234, -0.024552999774020617,
    -0.022393526941902865, -0.037121465482378505, -0.023598668170016778, -0.04079454305872011,
    -0.027248975880878476, -0.0410532569728234, -0.06231962016579648, -0.09144046041326485,
    -0.057274780249671496, -0.10054057823145325, -0.07306013448153292, -0.13478476891772942,
    -0.056968217601249496, -0.15249430337630712, -0.06553251255111985, -0.1588599663577215,
    -0.061171541498188556, -0.19223907735551518, -0.04595623882921383, -0.26020891948542857,
    -0.04046465933135456, -0.24404706341070564, -0.039742240733535716, -0.26643968205451235,
    -0.04253839095394632, -0.25995862414707993, -0.028484374416078286, -0.26612551061640305,
    -0.024222758718115748, -0.27593200184104927, -0.012275175256183773, -0.28865372652109167,
    0.016969397250481834, -0.309264312023813, 0.01078346495182105, -0.30155218580566984,
    0.017811126993860338, -0.3352214738932286, 0.037877445243607546, -0.3277732269104721,
    0.06163826971236968, -0.34502998228960435, 0.08669264589081975, -0.35677819466949157,
    0.17789660943227392, -0.38078086888372387, 0.19648758001426192, -0.3802655314591339,
    0.23892846432649026, -0.37368874373526356, 0.24394626175536954, -0.3793548808698263,
    0.3120850545312063, -0.385116474930424, 0.352120450194486, -0.37003301924668525,
    0.34968533298247784, -0.3816726929209138, 0.38418020879581183, -0.38079796002211874,
    0.4016405123757178, -0.37870291548591034, 0.41889834511887014, -0.3821679985979763,
    0.48109718983702265, -0.393536581683778, 0.5249245688343798, -0.4183588152327474,
    0.5413819650691507, -0.42630357584662104, 0.5530642278645678, -0.42917758633269837,
    0.6053171144635179, -0.4721615309050423, 0.6052034032809331, -0.47654577169176965,
    0.6062856314010006, -0.4893879587073966, 0.5995593378341393, -0.49239676098816015,
};
static const double ZK26_ENDS[4] = {0.0, 0.0, 0.604160611224581, -0.49118107594545246};
#define N_OF(a) (sizeof a / sizeof a[0] / 2)

/* The member of m half-waves, modulus k (k < 0: the mirror image), length L at angle phi
 * from (x0, y0), from its definition: u from K to K + 2 m K (GSL's K). */
static el_smooth_params member_of(int m, double k, double L, double phi, double x0, double y0)
{
    const double K = gsl_sf_ellint_Kcomp(fabs(k), GSL_PREC_DOUBLE), w = 2.0 * m * K / L;
    const el_smooth_params p = {x0, y0, phi, w * w, k, K, L};
    return p;
}

/* Whether the polygon of ns samples of p crosses itself (segments not adjacent) */
static int crosses_itself(const el_smooth_params *p, size_t ns)
{
    double *s = calloc(ns, sizeof(double)), *xy = malloc(sizeof(double) * 2 * ns);
    ck_assert(s && xy);
    for (size_t i = 0; i < ns; i++) s[i] = p->length * (double)i / (double)(ns - 1);
    ck_assert_int_eq(el_smooth_eval(p, ns, s, xy, NULL, NULL), EL_OK);
    int hit = 0;
    for (size_t i = 0; i + 1 < ns && !hit; i++)
        for (size_t j = i + 2; j + 1 < ns && !hit; j++) {
            const double *a = xy + 2 * i, *b = xy + 2 * i + 2, *c = xy + 2 * j, *d = xy + 2 * j + 2;
            const double r0 = b[0] - a[0], r1 = b[1] - a[1], s0 = d[0] - c[0], s1 = d[1] - c[1];
            const double den = r0 * s1 - r1 * s0;
            if (den == 0.0) continue;
            const double t = ((c[0] - a[0]) * s1 - (c[1] - a[1]) * s0) / den;
            const double u = ((c[0] - a[0]) * r1 - (c[1] - a[1]) * r0) / den;
            hit = t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0;
        }
    free(s);
    free(xy);
    return hit;
}

/* k*: 2E = K; k_t: lobes j and j + 2 touch, 2 E(phi1) - F(phi1) = 2 (2E - K) with
 * sin phi1 = 1 / (sqrt2 k) (GSL's integrals); on sampled curves of unit mu: m <= 2 simple
 * below k*, the ends passed each other above it; m >= 3 simple below k_t, crossing above */
START_TEST(test_natural_moduli_bound_the_simple_members)
{
    double ks, kt;
    ck_assert_int_eq(el__natural_moduli(&ks, &kt), EL_OK);
    const double K = gsl_sf_ellint_Kcomp(ks, GSL_PREC_DOUBLE), E = gsl_sf_ellint_Ecomp(ks, GSL_PREC_DOUBLE);
    ck_assert_msg(fabs(2.0 * E - K) <= 1e-13, "k* %.17g: 2E - K = %g", ks, 2.0 * E - K);
    const double phi1 = asin(1.0 / (sqrt(2.0) * kt)), Kt = gsl_sf_ellint_Kcomp(kt, GSL_PREC_DOUBLE);
    const double gap = 2.0 * gsl_sf_ellint_E(phi1, kt, GSL_PREC_DOUBLE) - gsl_sf_ellint_F(phi1, kt, GSL_PREC_DOUBLE) -
                       2.0 * (2.0 * gsl_sf_ellint_Ecomp(kt, GSL_PREC_DOUBLE) - Kt);
    ck_assert_msg(fabs(gap) <= 1e-13 && kt > sqrt(0.5) && kt < ks, "k_t %.17g: gap %g", kt, gap);
    for (int m = 1; m <= 4; m++) {
        const double kb = m <= 2 ? ks : kt;
        for (int side = -1; side <= 1; side += 2) {
            const double k = kb * (1.0 + 2e-3 * side), K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE);
            const el_smooth_params p = {0.0, 0.0, 0.0, 1.0, k, K, 2.0 * m * K};
            ck_assert_msg(crosses_itself(&p, 600 * (size_t)m) == (side > 0), "m %d: k %.6f", m, k);
        }
    }
}
END_TEST

/* The natural batten's options: pinned at ends (start, end), both curvatures 0 */
static el_fit_options natural_options(const double *ends)
{
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT | EL_CONSTRAIN_START_CURVATURE |
                    EL_CONSTRAIN_END_CURVATURE;
    memcpy(o.start_point, ends, sizeof o.start_point);
    memcpy(o.end_point, ends + 2, sizeof o.end_point);
    o.start_curvature = o.end_curvature = 0.0;
    return o;
}

/* The natural fit of the points xy (n) pinned at ends (distances d, feet fs: NULL or n each) */
static int natural_fit(const double *xy, size_t n, const double *ends, el_fit_smooth_result *r, double *d, double *fs)
{
    const el_fit_options o = natural_options(ends);
    return el_fit_smooth(xy, n, &o, NULL, r, d, fs);
}

/* Both ends at the pins and of curvature 0 (to 1e-9 of the size), as el_smooth_eval sees them */
static void check_natural_ends(const el_smooth_params *p, const double *ends, double size)
{
    const double s[2] = {0.0, p->length};
    double xy[4], th[2], ka[2];
    ck_assert_int_eq(el_smooth_eval(p, 2, s, xy, th, ka), EL_OK);
    ck_assert(hypot(xy[0] - ends[0], xy[1] - ends[1]) <= 1e-9 * size);
    ck_assert(hypot(xy[2] - ends[2], xy[3] - ends[3]) <= 1e-9 * size);
    ck_assert_msg(fabs(ka[0]) * size <= 1e-9 && fabs(ka[1]) * size <= 1e-9, "curvatures %g %g", ka[0], ka[1]);
}

/* Members through sparse uneven samples (smoothstep spacing, 5 + 6 m points) at scales
 * 1e-6, 1, 1e6: recovered to rounding (rms 1e-9 of the size), certified, without Ipopt */
START_TEST(test_natural_members_recovered_exactly)
{
    const struct { int m; double k, phi; } cases[] = {{1, 0.5, 0.7}, {2, -0.8, -2.0}, {3, 0.6, 2.9}, {4, -0.84, 0.1},
                                                      {1, 0.9, 1.3}, {2, 0.05, -0.4}};
    const double scales[3] = {1e-6, 1.0, 1e6};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int a = 0; a < 3; a++) {
            const double sc = scales[a];
            const el_smooth_params p = member_of(cases[c].m, cases[c].k, sc, cases[c].phi, 0.3 * sc, -0.2 * sc);
            const size_t n = 5 + 6 * (size_t)cases[c].m;
            double s[32], xy[64], ends[4];
            for (size_t i = 0; i < n; i++) {
                const double t = (double)i / (double)(n - 1);
                s[i] = p.length * t * t * (3.0 - 2.0 * t);
            }
            ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
            memcpy(ends, xy, 2 * sizeof(double));
            memcpy(ends + 2, xy + 2 * n - 2, 2 * sizeof(double));
            el_fit_smooth_result r;
            const int st = natural_fit(xy, n, ends, &r, NULL, NULL);
            ck_assert_msg(st == EL_OK && r.rms <= 1e-9 * sc && !r.used_ipopt,
                          "m %d k %g scale %g: status %d rms %g (of the size) ipopt %d", cases[c].m, cases[c].k, sc, st,
                          r.rms / sc, r.used_ipopt);
            check_natural_ends(&r.params, ends, sc);
        }
}
END_TEST

/* The point-to-curve rms of the points to p, by its ns samples' nearest (an upper bound) */
static double sampled_rms(const el_smooth_params *p, const double *xy, size_t n, size_t ns, double *buf)
{
    double *s = buf, *q = buf + ns;
    for (size_t i = 0; i < ns; i++) s[i] = p->length * (double)i / (double)(ns - 1);
    if (el_smooth_eval(p, ns, s, q, NULL, NULL)) return HUGE_VAL;
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) {
        double best = HUGE_VAL;
        for (size_t j = 0; j < ns; j++) {
            const double dx = q[2 * j] - xy[2 * i], dy = q[2 * j + 1] - xy[2 * i + 1], d2 = dx * dx + dy * dy;
            if (d2 < best) best = d2;
        }
        sum += best;
    }
    return sqrt(sum / (double)n);
}

/* Noisy sparse uneven points along members (noise 0.5 % of the size): the fit is no
 * farther from them than any member of a dense scan (m = 1..5, both mirror images, 240
 * moduli up to each m's bound, the curve by 1500 samples) */
START_TEST(test_natural_fit_is_the_family_minimum)
{
    double ks, kt;
    ck_assert_int_eq(el__natural_moduli(&ks, &kt), EL_OK);
    const struct { int m; double k; } cases[] = {{1, 0.6}, {2, -0.45}, {3, 0.7}};
    unsigned long long state = 2026;
    double *buf = malloc(sizeof(double) * 3 * 1500);
    ck_assert(buf);
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const el_smooth_params p = member_of(cases[c].m, cases[c].k, 1.0, 0.4, 0.0, 0.0);
        const size_t n = 16;
        double s[16], xy[32], ends[4];
        for (size_t i = 0; i < n; i++) s[i] = p.length * (i == 0 ? 0.0 : i == n - 1 ? 1.0 : test_uniform(&state, 0.0, 1.0));
        ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
        memcpy(ends, xy, 2 * sizeof(double));
        memcpy(ends + 2, xy + 2 * n - 2, 2 * sizeof(double));
        for (size_t i = 0; i < 2 * n; i++) xy[i] += 0.005 * test_normal(&state);
        el_fit_smooth_result r;
        ck_assert_int_eq(natural_fit(xy, n, ends, &r, NULL, NULL), EL_OK);
        ck_assert(!r.used_ipopt);
        check_natural_ends(&r.params, ends, 1.0);
        const double chord = hypot(ends[2] - ends[0], ends[3] - ends[1]);
        const double alpha = atan2(ends[3] - ends[1], ends[2] - ends[0]);
        double scan = HUGE_VAL;
        for (int m = 1; m <= 5; m++)
            for (int j = 1; j <= 240; j++)
                for (int mir = 0; mir < 2; mir++) {
                    const double k = (m <= 2 ? ks : kt) * j / 241.0;
                    const double K = gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE), g = 2.0 * gsl_sf_ellint_Ecomp(k, GSL_PREC_DOUBLE) - K;
                    const el_smooth_params q = member_of(m, mir ? -k : k, chord * K / g, alpha, ends[0], ends[1]);
                    const double rms = sampled_rms(&q, xy, n, 1500, buf);
                    if (rms < scan) scan = rms;
                }
        ck_assert_msg(r.rms <= scan * (1.0 + 1e-6), "m %d: rms %.9g, the scan's %.9g", cases[c].m, r.rms, scan);
    }
    free(buf);
}
END_TEST

/* Dense scans (more points than the search samples with: it sees 64 of them, the
 * minimiser all): noisy (0.3 % of the size) along members at scale 1e3, no higher than the
 * start-state chart's fit by Ipopt's rows (el__fit_run with FIT_RUN_INNER, the former path,
 * which the dense points lead to the same basin); noise-free, recovered to rounding */
START_TEST(test_natural_fit_of_dense_points)
{
    const struct { int m; double k; size_t n; double noise; } cases[] = {
        {2, 0.6, 500, 3e-3}, {3, -0.75, 3000, 3e-3}, {1, 0.4, 1000, 0.0}, {4, 0.8, 2000, 0.0}};
    unsigned long long state = 77;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const size_t n = cases[c].n;
        const el_smooth_params p = member_of(cases[c].m, cases[c].k, 1e3, -0.9, 50.0, 20.0);
        double *s = malloc(sizeof(double) * 7 * n), *xy = s + n, *d = xy + 2 * n, *fs = d + n, *pd = fs + n, *pfs = pd + n;
        ck_assert(s);
        for (size_t i = 0; i < n; i++) s[i] = p.length * (i == 0 ? 0.0 : i == n - 1 ? 1.0 : test_uniform(&state, 0.0, 1.0));
        for (size_t i = 1; i < n; i++)      /* sorted: the points in their order along the curve */
            for (size_t j = i; j > 0 && s[j - 1] > s[j]; j--) { const double t = s[j]; s[j] = s[j - 1]; s[j - 1] = t; }
        ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
        double ends[4] = {xy[0], xy[1], xy[2 * n - 2], xy[2 * n - 1]};
        for (size_t i = 0; i < 2 * n; i++) xy[i] += cases[c].noise * 1e3 * test_normal(&state);
        el_fit_smooth_result r;
        const int st = natural_fit(xy, n, ends, &r, d, fs);
        ck_assert_msg(st == EL_OK && !r.used_ipopt, "case %zu: status %d ipopt %d", c, st, r.used_ipopt);
        check_natural_ends(&r.params, ends, 1e3);
        if (cases[c].noise == 0.0) {
            ck_assert_msg(r.rms <= 1e-9 * 1e3, "case %zu: rms %g", c, r.rms);
        } else {
            const el_fit_options o = natural_options(ends);
            fit_out rows;
            memset(&rows, 0, sizeof rows);
            rows.status = -1;
            ck_assert_int_eq(el__fit_run(FIT_SMOOTH, xy, n, &o, FIT_RUN_INNER, NULL, &rows, pd, pfs), EL_OK);
            ck_assert_msg(r.rms <= rows.rms * (1.0 + 1e-6), "case %zu: rms %.9g, the rows' %.9g", c, r.rms, rows.rms);
        }
        free(s);
    }
}
END_TEST

/* Noisy points along a straight line (noise 1e-3 and 1e-6 of its length), pinned at its
 * ends: a member bent by ~k^2 of the segment (tau ~ -14 and -28) fits them closer than the
 * segment, by both models, certified (the segment alone was kept, smooth, and the discrete
 * polygon from it left uncertified). The start-state chart's fit by Ipopt is 1.5 % lower
 * here with 9 half-waves, fitting the noise: the search stops at the points' chord
 * crossings + 4 (at least 6) */
START_TEST(test_natural_fit_of_nearly_straight_points)
{
    const double noises[2] = {1e-3, 1e-6};
    for (int a = 0; a < 2; a++)
        for (int model = 0; model < 2; model++) {
            unsigned long long state = 4;
            enum { N = 30 };
            double xy[2 * N], t[N], d[N], fs[N];
            for (size_t i = 0; i < N; i++) t[i] = i == 0 ? 0.0 : i == N - 1 ? 1.0 : test_uniform(&state, 0.0, 1.0);
            for (size_t i = 1; i < N; i++)
                for (size_t j = i; j > 0 && t[j - 1] > t[j]; j--) { const double u = t[j]; t[j] = t[j - 1]; t[j - 1] = u; }
            const double ends[4] = {1.0, -1.0, 4.0, 1.0}, len = hypot(3.0, 2.0);
            double seg = 0.0;      /* the segment's sum of squared distances */
            for (size_t i = 0; i < N; i++) {
                const double e = i == 0 || i == N - 1 ? 0.0 : noises[a] * len * test_normal(&state);
                xy[2 * i] = 1.0 + 3.0 * t[i] - 2.0 / len * e;
                xy[2 * i + 1] = -1.0 + 2.0 * t[i] + 3.0 / len * e;
                seg += e * e;
            }
            const el_fit_options o = natural_options(ends);
            double rms;
            int st, ipopt;
            if (model == FIT_SMOOTH) {
                el_fit_smooth_result r;
                st = el_fit_smooth(xy, N, &o, NULL, &r, d, fs);
                rms = r.rms;
                ipopt = r.used_ipopt;
                check_natural_ends(&r.params, ends, len);
            } else {
                el_fit_discrete_result r;
                st = el_fit_discrete(xy, N, &o, NULL, &r, d, fs);
                rms = r.rms;
                ipopt = !r.used_ipopt;      /* the discrete one's Ipopt polishes, as it should */
            }
            ck_assert_msg(st == EL_OK && !ipopt, "model %d noise %g: status %d", model, noises[a], st);
            const double seg_rms = sqrt(seg / N);
            ck_assert_msg(rms < 0.99 * seg_rms, "model %d noise %g: rms %.9g, the segment's %.9g", model, noises[a], rms,
                          seg_rms);
        }
}
END_TEST

/* A sketch whose curve bends at its ends, pinned there with curvature 0: the rows' fit
 * (the start-state chart, el__fit_run with FIT_RUN_INNER, the former path) wound a chain of
 * 16 loops across the points (length 9.3, rms 0.0145); this one is a simple curve that
 * follows them (el__fit_stray), certified, without Ipopt */
START_TEST(test_natural_fit_follows_a_sketch)
{
    const size_t n = N_OF(ZK26);
    double *d = malloc(sizeof(double) * 2 * n), *fs = d + n;
    ck_assert(d);
    el_fit_smooth_result r;
    ck_assert_int_eq(natural_fit(ZK26, n, ZK26_ENDS, &r, d, fs), EL_OK);
    ck_assert(!r.used_ipopt);
    check_natural_ends(&r.params, ZK26_ENDS, 1.0);
    ck_assert(!crosses_itself(&r.params, 4000));
    double cx, cy, sc;
    ck_assert_int_eq(el__fit_normalisation(ZK26, n, &cx, &cy, &sc), EL_OK);
    const double noise = el__fit_noise_rms(ZK26, n, sc) * sc;
    const double stray = el__fit_stray(ZK26, n, fs, r.params.length, noise, sc);
    ck_assert_msg(stray <= FIT_STRAY && r.rms < 0.1, "stray %g rms %g length %g", stray, r.rms, r.params.length);
    fit_out rows;
    memset(&rows, 0, sizeof rows);
    rows.status = -1;
    const el_fit_options o = natural_options(ZK26_ENDS);
    ck_assert_int_eq(el__fit_run(FIT_SMOOTH, ZK26, n, &o, FIT_RUN_INNER, NULL, &rows, d, fs), EL_OK);
    const el_smooth_params rp = {rows.params[0], rows.params[1], rows.params[2], rows.params[3], rows.params[4],
                                 rows.params[5], rows.params[6]};
    ck_assert_msg(el__fit_stray(ZK26, n, fs, rp.length, noise, sc) > FIT_STRAY && crosses_itself(&rp, 8000),
                  "the rows' fit: length %g rms %g", rp.length, rows.rms);
    free(d);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_natural");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_natural_moduli_bound_the_simple_members);
    tcase_add_test(tc, test_natural_members_recovered_exactly);
    tcase_add_test(tc, test_natural_fit_is_the_family_minimum);
    tcase_add_test(tc, test_natural_fit_follows_a_sketch);
    tcase_add_test(tc, test_natural_fit_of_dense_points);
    tcase_add_test(tc, test_natural_fit_of_nearly_straight_points);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
