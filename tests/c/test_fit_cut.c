/* el__fit_cut (fit_ends.c): a smooth curve cut to [a, b] of its arc length by moving its
 * start to gamma(a) and its phase to q + sqrt(mu) a (u = sqrt(mu) s + q, seed 000 (4.2)) is
 * the same curve: gamma_cut(s) = gamma(a + s) and theta_cut(s) = theta(a + s) for s in
 * [0, b - a], for moduli below and above 1 (inflectional and not), either orientation,
 * several phases, scales and cut points. */
#include "testutil.h"
#include "fit_ends.h"
#include <math.h>

START_TEST(test_cut_is_the_same_curve)
{
    static const double ks[] = {0.3, 0.8, -0.95, 1.5, -3.0}, qs[] = {0.0, -0.9, 1.7};
    static const double mus[] = {0.04, 2.5}, cuts[][2] = {{0.0, 2.0}, {0.7, 3.1}, {1.9, 4.6}};
    enum { NS = 41 };
    int cases = 0;
    for (size_t ik = 0; ik < sizeof ks / sizeof *ks; ik++)
        for (size_t iq = 0; iq < sizeof qs / sizeof *qs; iq++)
            for (size_t im = 0; im < sizeof mus / sizeof *mus; im++)
                for (size_t ic = 0; ic < sizeof cuts / sizeof *cuts; ic++) {
                    const double a = cuts[ic][0], b = cuts[ic][1];
                    const el_smooth_params c = {0.4, -1.3, 0.6, mus[im], ks[ik], qs[iq], 5.0};
                    double p[FIT_NP] = {c.x0, c.y0, c.phi, c.mu, c.k, c.q, c.length};
                    ck_assert_int_eq(el__fit_cut(p, a, b), EL_OK);
                    const el_smooth_params cc = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
                    ck_assert_double_eq(cc.length, b - a);
                    double s[NS], sa[NS], g[2 * NS], gc[2 * NS], th[NS], thc[NS];
                    for (int i = 0; i < NS; i++) {
                        s[i] = (b - a) * i / (NS - 1.0);
                        sa[i] = a + s[i];
                    }
                    ck_assert_int_eq(el_smooth_eval(&c, NS, sa, g, th, NULL), EL_OK);
                    ck_assert_int_eq(el_smooth_eval(&cc, NS, s, gc, thc, NULL), EL_OK);
                    /* the scale: the curve's extent from its start (its length bounds it) */
                    const double tol = 1e-12 * (1.0 + c.length);
                    for (int i = 0; i < NS; i++) {
                        ck_assert_msg(fabs(gc[2 * i] - g[2 * i]) <= tol && fabs(gc[2 * i + 1] - g[2 * i + 1]) <= tol,
                                      "k %g q %g mu %g cut [%g, %g] s %g: (%.17g, %.17g) for (%.17g, %.17g)", c.k,
                                      c.q, c.mu, a, b, s[i], gc[2 * i], gc[2 * i + 1], g[2 * i], g[2 * i + 1]);
                        ck_assert_msg(fabs(remainder(thc[i] - th[i], 2.0 * M_PI)) <= 1e-12,
                                      "k %g q %g mu %g cut [%g, %g] s %g: angle %.17g for %.17g", c.k, c.q, c.mu,
                                      a, b, s[i], thc[i], th[i]);
                    }
                    cases++;
                }
    ck_assert_int_eq(cases, 90);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_cut");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_cut_is_the_same_curve);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
