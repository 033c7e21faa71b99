/* Initial guess (guess.c), seed 000 §4.3: the modulus k from (4.34)-(4.37)
 * and the phase fit land close to the truth on noise-free data; invariance. */
#include "testutil.h"
#include "fit_internal.h"
#include <gsl/gsl_sf_ellint.h>

static double half_period(double k)
{
    return k < 1.0 ? 2.0 * gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE)
                   : 2.0 * gsl_sf_ellint_Kcomp(1.0 / k, GSL_PREC_DOUBLE) / k;
}

static const double KS[] = {0.1, 0.3, 0.6, 0.9, 1.2, 2.0, 5.0};

/* (4.37) in the one-formula parametrisation gives k for both cases. */
START_TEST(test_guess_k_discrete)
{
    const size_t sizes[] = {20, 200};
    double xy[2 * 200];
    for (size_t a = 0; a < sizeof KS / sizeof KS[0]; a++)
        for (int si = 0; si < 2; si++)
            for (int pieces = 1; pieces <= 3; pieces++) {
                size_t n = sizes[si];
                double sign = pieces == 2 ? -1.0 : 1.0;   /* z < 0: turning the other way */
                el_discrete_params p = {0.2, -0.4, 1.0 / (double)n, 0.4,
                                        sign * 0.9 * pieces * half_period(KS[a]) / (double)(n - 1),
                                        0.3, KS[a]};
                ck_assert_int_eq(el_discrete_eval(&p, n, xy), EL_OK);
                el_discrete_params c[4];
                size_t cnt = 0;
                ck_assert_int_eq(el_guess_discrete(xy, n, c, 4, &cnt), EL_OK);
                ck_assert(cnt >= 1);
                ck_assert_msg(fabs(c[0].k - p.k) <= 0.05 * p.k, "k %g n %zu pieces %d: guess %g",
                              p.k, n, pieces, c[0].k);
                ck_assert_close(c[0].h, p.h, 0.05 * p.h);
                /* for k > 1 the sense of turning is the sign of z (for k < 1 the
                 * reflection u -> -u - 2K gives the same curve with -z) */
                if (p.k > 1.0) ck_assert_msg(c[0].z * p.z > 0.0, "sense of z, k %g", p.k);
            }
}
END_TEST

/* Smooth: for loops the sign of k is the sense of turning (k < -1 clockwise);
 * the guess finds it. Inflectional curves with k < 0 are the same as with |k|. */
START_TEST(test_guess_k_smooth)
{
    double xy[2 * 200], s[200];
    for (size_t a = 0; a < 2 * sizeof KS / sizeof KS[0]; a++)
        for (int pieces = 1; pieces <= 3; pieces++) {
            const size_t n = 200;
            const size_t nk = sizeof KS / sizeof KS[0];
            const double k = a < nk ? KS[a] : -KS[a - nk];
            el_smooth_params p = {1.0, 2.0, -0.7, 2.0, k, 0.3, 0.9 * pieces * half_period(fabs(k)) / sqrt(2.0)};
            for (size_t i = 0; i < n; i++) s[i] = p.length * (double)i / (double)(n - 1);
            ck_assert_int_eq(el_smooth_eval(&p, n, s, xy, NULL, NULL), EL_OK);
            el_smooth_params c[4];
            size_t cnt = 0;
            ck_assert_int_eq(el_guess_smooth(xy, n, EL_PARAM_AUTO, c, 4, &cnt), EL_OK);
            const double kt = fabs(k) > 1.0 ? k : fabs(k);
            ck_assert_msg(fabs(c[0].k - kt) <= 0.05 * fabs(kt), "k %g pieces %d: guess %g", p.k, pieces, c[0].k);
            ck_assert_close(c[0].length, p.length, 0.05 * p.length);   /* polygon length */
            ck_assert_close(c[0].mu, p.mu, 0.1 * p.mu);
            ck_assert(el_smooth_check(&c[0]) == EL_OK);
        }
}
END_TEST

/* A similarity transform of the data transforms the guess (h, x0, y0 scale;
 * k, z, q do not). */
START_TEST(test_guess_similarity)
{
    const size_t n = 100;
    double xy[2 * 100], big[2 * 100];
    el_discrete_params p = {0.0, 0.0, 0.01, 0.5, 0.03, -0.2, 0.7};
    ck_assert_int_eq(el_discrete_eval(&p, n, xy), EL_OK);
    el_discrete_params a[4], b[4];
    size_t na = 0, nb = 0;
    ck_assert_int_eq(el_guess_discrete(xy, n, a, 4, &na), EL_OK);
    const double sc = 1e7;
    for (size_t i = 0; i < 2 * n; i++) big[i] = sc * xy[i] - 3e7;
    ck_assert_int_eq(el_guess_discrete(big, n, b, 4, &nb), EL_OK);
    ck_assert_int_eq(na, nb);
    ck_assert_close(b[0].h, sc * a[0].h, 1e-9 * sc * a[0].h);
    ck_assert_close(b[0].k, a[0].k, 1e-9);
    ck_assert_close(b[0].z, a[0].z, 1e-9);
    ck_assert_close(b[0].x0, sc * a[0].x0 - 3e7, 1e-6 * sc);
}
END_TEST

START_TEST(test_guess_bad_input)
{
    double xy[8] = {0, 0, 1, 0, 2, 1, 3, 3};
    el_discrete_params c[2];
    el_smooth_params sc[2];
    size_t cnt = 99;
    ck_assert_int_eq(el_guess_discrete(xy, 3, c, 2, &cnt), EL_EINVAL);
    ck_assert_int_eq(el_guess_discrete(xy, 4, c, 0, &cnt), EL_EINVAL);
    ck_assert_int_eq(el_guess_discrete(NULL, 4, c, 2, &cnt), EL_EINVAL);
    ck_assert_int_eq(el_guess_smooth(xy, 4, 7, sc, 2, &cnt), EL_EINVAL);
    ck_assert_int_eq(cnt, 99);
    xy[3] = NAN;
    ck_assert_int_eq(el_guess_smooth(xy, 4, EL_PARAM_AUTO, sc, 2, &cnt), EL_EINVAL);
    xy[3] = 0;
    ck_assert_int_eq(el_guess_discrete(xy, 4, c, 2, &cnt), EL_OK);   /* 4 points suffice */
    ck_assert(cnt >= 1 && cnt <= 2 && el_discrete_check(&c[0]) == EL_OK);
    double t[4];
    ck_assert_int_eq(el_fit_fractions(xy, 4, 3, t, NULL), EL_EINVAL);
}
END_TEST

/* el_fit_fractions' chord parameter by its definition: each side d of the points' polygon
 * (normalised units) counts sqrt(max(d^2 - 2 nu^2, d^2 / 100)), nu the noise level the fit
 * estimates (el__fit_noise_rms); on uneven noisy points that differs from the plain
 * chords, on noise-free points along a line it is the plain chords. */
START_TEST(test_fractions_noise_out)
{
    enum { N = 40 };
    double xy[2 * N], t[N], cx, cy, sc;
    for (int pass = 0; pass < 2; pass++) {
        unsigned long long r = 2463534242ULL;
        for (int i = 0; i < N; i++) {
            r ^= r << 13; r ^= r >> 7; r ^= r << 17;
            const double s = (double)i * i / ((N - 1.0) * (N - 1.0)), e = pass ? 0.0 : 0.03 * ((double)(r >> 11) / 9007199254740992.0 - 0.5);
            xy[2 * i] = 3.0 * s + e;
            xy[2 * i + 1] = pass ? 0.5 * s : sin(2.0 * s) + e;
        }
        int mode = -1;
        ck_assert_int_eq(el_fit_fractions(xy, N, EL_PARAM_CHORD, t, &mode), EL_OK);
        ck_assert_int_eq(mode, EL_PARAM_CHORD);
        ck_assert_int_eq(el__fit_normalisation(xy, N, &cx, &cy, &sc), EL_OK);
        const double nu = el__fit_noise_rms(xy, N, sc), n2 = 2.0 * nu * nu;
        ck_assert(pass ? nu < 1e-12 : nu > 1e-4);
        double cum[N], plain[N];
        cum[0] = plain[0] = 0.0;
        for (int i = 1; i < N; i++) {
            const double dx = (xy[2 * i] - xy[2 * i - 2]) / sc, dy = (xy[2 * i + 1] - xy[2 * i - 1]) / sc, d2 = dx * dx + dy * dy;
            cum[i] = cum[i - 1] + sqrt(fmax(d2 - n2, 0.01 * d2));
            plain[i] = plain[i - 1] + sqrt(d2);
        }
        double moved = 0.0;
        for (int i = 0; i < N; i++) {
            ck_assert_msg(fabs(t[i] - cum[i] / cum[N - 1]) <= 1e-14, "pass %d t[%d] %.17g, by definition %.17g",
                          pass, i, t[i], cum[i] / cum[N - 1]);
            moved = fmax(moved, fabs(t[i] - plain[i] / plain[N - 1]));
        }
        ck_assert_msg(pass ? moved <= 1e-14 : moved > 1e-3, "pass %d: %g from the plain chords", pass, moved);
    }
}
END_TEST

/* A circular arc's guess is an elastica of the arc's curvature to 1 % along it, and each
 * such guess (near_circle's, and (4.34)'s where its curvature is that constant) starts
 * with the arc's tangent at its first point (the start state it is built from) and, for
 * an arc turning by less than 2 rad, has a force mu = w^2 not vanishing against its
 * length (mu L^2 >= 1e-3): with k = 10 for every arc, a nearly straight one's mu was
 * ~(turn / 20)^2, where the fit's start-state chart is singular (fit_model.c) and
 * Levenberg-Marquardt took no step from the guess (guess.c, near_circle). Turns from
 * 1e-3 rad to 3 rad either way, at scales 1e-3 and 1e3. */
START_TEST(test_guess_arc_is_a_near_circle)
{
    enum { N = 50 };
    const double turns[] = {1.2e-3, 0.01, 0.05, 0.5, 1.5, 1.99, 2.01, 3.0};
    double xy[2 * N], s[N], th[N], ka[N];
    for (size_t a = 0; a < sizeof turns / sizeof turns[0]; a++)
        for (int sense = -1; sense <= 1; sense += 2)
            for (double scale = 1e-3; scale < 1e4; scale *= 1e6) {
                const double R = 10.0 * scale, turn = sense * turns[a], L = R * fabs(turn);
                for (int i = 0; i < N; i++) {
                    const double ang = 0.3 + turn * i / (N - 1.0);    /* kappa = sense / R */
                    xy[2 * i] = 5.0 * scale + R * cos(ang);
                    xy[2 * i + 1] = R * sin(ang);
                }
                el_smooth_params c[6];
                size_t cnt = 0;
                ck_assert_int_eq(el_guess_smooth(xy, N, EL_PARAM_AUTO, c, 6, &cnt), EL_OK);
                int found = 0;
                for (size_t j = 0; j < cnt; j++) {     /* every candidate of the arc's curvature */
                    for (int i = 0; i < N; i++) s[i] = c[j].length * i / (N - 1.0);
                    if (el_smooth_eval(&c[j], N, s, xy, th, ka) != EL_OK) continue;
                    double dev = 0.0;
                    for (int i = 0; i < N; i++) dev = fmax(dev, fabs(ka[i] * R * sense - 1.0));
                    if (dev > 0.01) continue;
                    const double muL2 = c[j].mu * c[j].length * c[j].length;
                    ck_assert_msg(fabs(turn) >= 2.0 || muL2 >= 1e-3, "turn %g scale %g: mu L^2 = %g",
                                  turn, scale, muL2);
                    if (!found)        /* the best ranked of them: the arc's length */
                        ck_assert_msg(fabs(c[j].length - L) <= 0.01 * L, "turn %g: length %g of %g", turn,
                                      c[j].length, L);
                    found = 1;
                    /* the start state it was built from (theta0 = phi + 2 a(q), placed by
                     * the mean offset): the arc's first tangent and point */
                    const double dth = remainder(th[0] - (0.3 + sense * 0.5 * M_PI), 2.0 * M_PI);
                    const double dp = hypot(xy[0] - (5.0 * scale + R * cos(0.3)), xy[1] - R * sin(0.3));
                    ck_assert_msg(fabs(dth) <= 0.02 && dp <= 0.01 * L, "turn %g scale %g: start tangent off "
                                  "by %g rad, start point by %g of %g", turn, scale, dth, dp, L);
                }
                ck_assert_msg(found, "turn %g scale %g: no guess of constant curvature 1/R", turn, scale);
            }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("guess");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_guess_k_discrete);
    tcase_add_test(tc, test_guess_k_smooth);
    tcase_add_test(tc, test_guess_similarity);
    tcase_add_test(tc, test_guess_bad_input);
    tcase_add_test(tc, test_fractions_noise_out);
    tcase_add_test(tc, test_guess_arc_is_a_near_circle);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
