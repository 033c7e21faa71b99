/* The smooth orthogonal fit's feet on sketched points (a dense run, a gap, a sparse run):
 * a foot that starts on another pass of the curve than its nearest point must not stay
 * there (fit.c, fit_run: the report's nearest feet, the fit again from them). Noise-free
 * points of an elastica with k > 1 (the curve turns through a full loop): the default fit
 * is exact to rounding, free and with both end tangents held, by Levenberg-Marquardt and
 * by L-BFGS. Before: rms 1.07e-3 (20 points, free) and 9.3e-4 (50 points, tangents),
 * certified with one foot on the other pass. */
#include "testutil.h"

typedef struct sketch_case {
    el_smooth_params p;
    size_t n, dense;        /* points, of which the first `dense` in [0, 0.3 L] */
    int tangents;
} sketch_case;

/* fit_set.py (the brief's) seed 8, cases 17 and 19 */
static const sketch_case cases[] = {
    {{0.0, 0.0, -0.8995678828729252, 0.679946804466786, 1.5838703362067086, 0.9954604626501212, 5.9938437947981855},
     20, 14, 0},
    {{0.0, 0.0, -0.7601865196030071, 1.150775390300568, 1.3253068667048868, 1.4627525534219716, 5.619178144390364},
     50, 35, 1},
};

/* The points at s = 0 .. 0.3 L (dense) and 0.45 L .. L, their rms radius, the end tangents. */
static double sketch(const sketch_case *c, double *xy, double th[2])
{
    double s[64], ends[2] = {0.0, c->p.length}, exy[4];
    const double L = c->p.length;
    for (size_t i = 0; i < c->dense; i++) s[i] = 0.3 * L * (double)i / (double)(c->dense - 1);
    for (size_t i = c->dense; i < c->n; i++)
        s[i] = 0.45 * L + 0.55 * L * (double)(i - c->dense) / (double)(c->n - c->dense - 1);
    ck_assert_int_eq(el_smooth_eval(&c->p, c->n, s, xy, NULL, NULL), EL_OK);
    ck_assert_int_eq(el_smooth_eval(&c->p, 2, ends, exy, th, NULL), EL_OK);
    double mx = 0.0, my = 0.0, r2 = 0.0;
    for (size_t i = 0; i < c->n; i++) { mx += xy[2 * i] / (double)c->n; my += xy[2 * i + 1] / (double)c->n; }
    for (size_t i = 0; i < c->n; i++)
        r2 += ((xy[2 * i] - mx) * (xy[2 * i] - mx) + (xy[2 * i + 1] - my) * (xy[2 * i + 1] - my)) / (double)c->n;
    return sqrt(r2);
}

START_TEST(test_sketched_noise_free_exact)
{
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++)
        for (int lbfgs = 0; lbfgs < 2; lbfgs++) {
            double xy[128], th[2];
            const double size = sketch(&cases[c], xy, th);
            el_fit_options o;
            el_fit_options_defaults(&o);
            o.limited_memory = lbfgs;
            if (cases[c].tangents) {
                o.constraints = EL_CONSTRAIN_START_TANGENT | EL_CONSTRAIN_END_TANGENT;
                o.start_tangent = th[0];
                o.end_tangent = th[1];
            }
            el_fit_smooth_result r;
            const int st = el_fit_smooth(xy, cases[c].n, &o, NULL, &r, NULL, NULL);
            ck_assert_msg(st == EL_OK, "case %zu lbfgs %d: status %d", c, lbfgs, st);
            ck_assert_msg(r.rms <= 1e-9 * size, "case %zu lbfgs %d: rms %.3g of the size", c, lbfgs, r.rms / size);
        }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_feet");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_sketched_noise_free_exact);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
