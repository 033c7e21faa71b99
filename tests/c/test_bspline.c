/* B-splines: evaluation against the Cox-de Boor recursion, derivatives,
 * curvature, natural C2 interpolation, certified elastica approximation. */
#include "testutil.h"
#include <string.h>

/* ---------------------------------------------------------------- helpers */

/* Cox-de Boor recursion for N_{i,p}(t) on the flat knots U (0/0 = 0); the
 * half-open convention, with the last span closed at the end of the domain. */
static double cox_de_boor(const double *U, size_t m, int i, int p, double t)
{
    if (p == 0) {
        if (U[i] <= t && t < U[i + 1]) return 1.0;
        /* t = last knot: the last non-empty span counts */
        if (t == U[m - 1] && U[i] < U[i + 1] && U[i + 1] == U[m - 1]) return 1.0;
        return 0.0;
    }
    double v = 0.0;
    if (U[i + p] > U[i]) v += (t - U[i]) / (U[i + p] - U[i]) * cox_de_boor(U, m, i, p - 1, t);
    if (U[i + p + 1] > U[i + 1])
        v += (U[i + p + 1] - t) / (U[i + p + 1] - U[i + 1]) * cox_de_boor(U, m, i + 1, p - 1, t);
    return v;
}

/* A random valid B-spline (random knots, interior multiplicities 1..degree). */
static void random_bspline(unsigned long long *rs, int degree, int dim, el_bspline *b)
{
    size_t nk = 2 + (size_t)test_uniform(rs, 0.0, 5.0);
    int mults[8];
    size_t total = 0;
    for (size_t i = 0; i < nk; i++) {
        mults[i] = (i == 0 || i + 1 == nk) ? degree + 1 : 1 + (int)test_uniform(rs, 0.0, degree);
        total += (size_t)mults[i];
    }
    ck_assert_int_eq(el_bspline_alloc(b, degree, dim, total - (size_t)degree - 1, nk), EL_OK);
    double x = test_uniform(rs, -2.0, 0.0);
    for (size_t i = 0; i < nk; i++) {
        b->knots[i] = x;
        b->mults[i] = mults[i];
        x += test_uniform(rs, 0.1, 1.5);
    }
    for (size_t i = 0; i < (size_t)dim * b->npoles; i++) b->poles[i] = test_uniform(rs, -3.0, 3.0);
    ck_assert_int_eq(el_bspline_check(b), EL_OK);
}

/* ---------------------------------------------------------------- evaluation */

START_TEST(test_eval_matches_cox_de_boor)
{
    unsigned long long rs = 0x9e3779b97f4a7c15ULL;
    for (int degree = 1; degree <= 7; degree++)
        for (int trial = 0; trial < 4; trial++) {
            el_bspline b;
            const int dim = 1 + trial % 3;
            random_bspline(&rs, degree, dim, &b);
            const size_t m = b.npoles + (size_t)degree + 1;
            double U[64];
            ck_assert_int_eq(el_bspline_flat_knots(&b, U), EL_OK);
            const double a = b.knots[0], z = b.knots[b.nknots - 1];
            for (int j = 0; j <= 40; j++) {
                double t = j == 40 ? z : a + (z - a) * j / 40.0, pt[3];
                if (j % 7 == 3) t = b.knots[j % b.nknots];   /* exactly at knots too */
                ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_OK);
                for (int c = 0; c < dim; c++) {
                    double ref = 0.0;
                    for (size_t i = 0; i < b.npoles; i++)
                        ref += cox_de_boor(U, m, (int)i, degree, t) * b.poles[i * (size_t)dim + (size_t)c];
                    ck_assert_close(pt[c], ref, 1e-12);
                }
            }
            el_bspline_free(&b);
            ck_assert_ptr_null(b.poles);
        }
}
END_TEST

START_TEST(test_derivatives_by_finite_differences)
{
    unsigned long long rs = 12345;
    for (int degree = 2; degree <= 7; degree++) {
        el_bspline b;
        random_bspline(&rs, degree, 2, &b);
        for (int j = 1; j < 30; j++) {
            /* stay away from knots: derivatives jump there when mults are high */
            double t = b.knots[0] + (b.knots[b.nknots - 1] - b.knots[0]) * (j + 0.37) / 30.5;
            int nearknot = 0;
            for (size_t i = 0; i < b.nknots; i++) nearknot |= fabs(t - b.knots[i]) < 1e-3;
            if (nearknot) continue;
            const double h = 1e-5;
            double tt[3] = {t - h, t, t + h}, p[6], d1[2], d2[2], d3[2];
            ck_assert_int_eq(el_bspline_eval(&b, 3, tt, p), EL_OK);
            ck_assert_int_eq(el_bspline_derivative(&b, 1, 1, &t, d1), EL_OK);
            ck_assert_int_eq(el_bspline_derivative(&b, 2, 1, &t, d2), EL_OK);
            for (int c = 0; c < 2; c++) {
                const double scale = 1.0 + fabs(d1[c]) + fabs(d2[c]);
                ck_assert_close(d1[c], (p[4 + c] - p[c]) / (2 * h), 1e-6 * scale);
                ck_assert_close(d2[c], (p[4 + c] - 2 * p[2 + c] + p[c]) / (h * h), 1e-3 * scale);
            }
            ck_assert_int_eq(el_bspline_derivative(&b, degree + 1, 1, &t, d3), EL_OK);
            ck_assert(d3[0] == 0.0 && d3[1] == 0.0);
        }
        el_bspline_free(&b);
    }
}
END_TEST

START_TEST(test_curvature_parabola)
{
    /* y = x^2 as a quadratic Bezier: poles (-1,1), (0,-1), (1,1) */
    el_bspline b;
    ck_assert_int_eq(el_bspline_alloc(&b, 2, 2, 3, 2), EL_OK);
    const double P[6] = {-1, 1, 0, -1, 1, 1};
    memcpy(b.poles, P, sizeof P);
    b.knots[0] = 0; b.knots[1] = 1; b.mults[0] = b.mults[1] = 3;
    for (int j = 0; j <= 10; j++) {
        double t = j / 10.0, pt[2], kappa;
        ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_OK);
        ck_assert_close(pt[1], pt[0] * pt[0], 1e-14);
        ck_assert_int_eq(el_bspline_curvature(&b, 1, &t, &kappa), EL_OK);
        ck_assert_close(kappa, 2.0 / pow(1 + 4 * pt[0] * pt[0], 1.5), 1e-12);
    }
    el_bspline_free(&b);
}
END_TEST

START_TEST(test_bad_bsplines)
{
    el_bspline b;
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 2, 3, 2), EL_EINVAL);   /* npoles < degree+1 */
    ck_assert_int_eq(el_bspline_alloc(NULL, 3, 2, 4, 2), EL_EINVAL);
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 2, 4, 2), EL_OK);
    b.knots[0] = 0; b.knots[1] = 1;
    b.mults[0] = 4; b.mults[1] = 3;                                  /* sum of mults wrong */
    ck_assert_int_eq(el_bspline_check(&b), EL_EINVAL);
    b.mults[1] = 4;
    ck_assert_int_eq(el_bspline_check(&b), EL_OK);
    double t = 1.5, pt[2] = {7, 7};
    ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_EDOM);       /* outside the domain */
    t = NAN;
    ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_EINVAL);
    ck_assert(pt[0] == 7 && pt[1] == 7);
    t = 0.5;
    double kappa;
    ck_assert_int_eq(el_bspline_curvature(&b, 1, &t, &kappa), EL_ESINGULAR);  /* all poles 0 */
    b.knots[1] = 0;                                                  /* not increasing */
    ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_EINVAL);
    b.knots[1] = 1;
    b.poles[3] = INFINITY;
    ck_assert_int_eq(el_bspline_check(&b), EL_EINVAL);
    el_bspline_free(&b);
    el_bspline_free(NULL);
}
END_TEST

/* ---------------------------------------------------------------- C2 interpolation */

START_TEST(test_interpolate_c2_discrete_elastica)
{
    el_discrete_params dp = {0.0, 0.0, 0.3, 0.2, 0.25, 0.1, 0.8};
    enum { NV = 25 };
    double xy[2 * NV];
    ck_assert_int_eq(el_discrete_eval(&dp, NV, xy), EL_OK);
    el_bspline b;
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, NV, &b), EL_OK);
    ck_assert_int_eq((int)b.npoles, NV + 2);
    ck_assert_int_eq((int)b.nknots, NV);
    ck_assert_int_eq(b.degree, 3);
    for (int i = 0; i < NV; i++) {
        double pt[2];
        ck_assert_int_eq(el_bspline_eval(&b, 1, &b.knots[i], pt), EL_OK);
        ck_assert_close(pt[0], xy[2 * i], 1e-12);
        ck_assert_close(pt[1], xy[2 * i + 1], 1e-12);
        if (i > 0) ck_assert_close(b.knots[i] - b.knots[i - 1], 0.3, 1e-12);   /* chord length */
    }
    double max_jump3 = 0.0;
    for (int i = 1; i + 1 < NV; i++) {   /* continuity of B', B'' at interior knots */
        const double eps = 1e-7, t[2] = {b.knots[i] - eps, b.knots[i] + eps};
        for (int order = 1; order <= 3; order++) {
            double d[4];
            ck_assert_int_eq(el_bspline_derivative(&b, order, 2, t, d), EL_OK);
            const double jump = hypot(d[2] - d[0], d[3] - d[1]);
            if (order < 3) ck_assert_msg(jump < 1e-5, "order %d jump %g at knot %d", order, jump, i);
            else if (jump > max_jump3) max_jump3 = jump;
        }
    }
    ck_assert(max_jump3 > 1e-3);   /* only C2: the third derivative jumps */
    const double ends[2] = {b.knots[0], b.knots[NV - 1]};
    double d2[4];
    ck_assert_int_eq(el_bspline_derivative(&b, 2, 2, ends, d2), EL_OK);
    for (int c = 0; c < 4; c++) ck_assert_close(d2[c], 0.0, 1e-10);   /* natural ends */
    el_bspline_free(&b);
}
END_TEST

/* end conditions: the asked first or second derivative exactly, the vertices still
 * interpolated, C2 inside; natural ends equal el_bspline_interpolate_c2 */
START_TEST(interpolate_c2_ends_meet_their_derivatives)
{
    el_discrete_params dp = {0.5, -0.2, 0.3, 0.2, 0.25, 0.1, 0.8};
    enum { NV = 12 };
    double xy[2 * NV];
    ck_assert_int_eq(el_discrete_eval(&dp, NV, xy), EL_OK);
    const el_bspline_end kinds[4][2] = {
        {{1, {0.6, 0.8}, {0, 0}}, {1, {-1.0, 0.0}, {0, 0}}},   /* clamped tangents */
        {{2, {0.3, -1.1}, {0, 0}}, {2, {0.0, 0.7}, {0, 0}}},   /* given second derivatives */
        {{1, {0.0, 1.0}, {0, 0}}, {2, {0.0, 0.0}, {0, 0}}},    /* mixed, the end natural */
        {{2, {0.0, 0.0}, {0, 0}}, {2, {0.0, 0.0}, {0, 0}}},    /* natural both: the plain cubic */
    };
    for (int c = 0; c < 4; c++) {
        el_bspline b, plain;
        ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, NV, &kinds[c][0], &kinds[c][1], &b), EL_OK);
        for (int i = 0; i < NV; i++) {
            double pt[2];
            ck_assert_int_eq(el_bspline_eval(&b, 1, &b.knots[i], pt), EL_OK);
            ck_assert_close(pt[0], xy[2 * i], 1e-12);
            ck_assert_close(pt[1], xy[2 * i + 1], 1e-12);
        }
        const double t[2] = {b.knots[0], b.knots[NV - 1]};
        for (int e = 0; e < 2; e++) {
            const el_bspline_end *end = &kinds[c][e];
            double d[2];
            ck_assert_int_eq(el_bspline_derivative(&b, end->order, 1, &t[e], d), EL_OK);
            ck_assert_close(d[0], end->value[0], 1e-12);
            ck_assert_close(d[1], end->value[1], 1e-12);
        }
        for (int i = 1; i + 1 < NV; i++) {   /* C2 at interior knots */
            const double eps = 1e-7, tt[2] = {b.knots[i] - eps, b.knots[i] + eps};
            double d[4];
            ck_assert_int_eq(el_bspline_derivative(&b, 2, 2, tt, d), EL_OK);
            ck_assert(hypot(d[2] - d[0], d[3] - d[1]) < 1e-5);
        }
        if (c == 3) {
            ck_assert_int_eq(el_bspline_interpolate_c2(xy, NV, &plain), EL_OK);
            for (size_t j = 0; j < 2 * plain.npoles; j++) ck_assert_close(b.poles[j], plain.poles[j], 1e-13);
            el_bspline_free(&plain);
        }
        el_bspline_free(&b);
    }
    /* two vertices with both tangents: the cubic Hermite segment */
    const double two[4] = {0, 0, 2, 0};
    el_bspline b;
    ck_assert_int_eq(el_bspline_interpolate_c2_ends(two, 2, &kinds[0][0], &kinds[0][1], &b), EL_OK);
    double d[2];
    ck_assert_int_eq(el_bspline_derivative(&b, 1, 1, &b.knots[0], d), EL_OK);
    ck_assert_close(d[0], 0.6, 1e-14);
    el_bspline_free(&b);
    /* bad end conditions */
    el_bspline_end bad = {0, {0, 0}, {0, 0}};
    ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, NV, &bad, NULL, &b), EL_EINVAL);
    bad.order = 1; bad.value[1] = NAN;
    ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, NV, NULL, &bad, &b), EL_EINVAL);
}
END_TEST

/* G2 ends (order 3): B' and B'' at the end both as asked, so a unit tangent T and
 * kappa N give the curvature kappa there; the vertices still at their chord-length
 * parameters, C2 at every interior knot (the extra ones too), one pole more per G2 end;
 * with either other order at the other end, on polylines of 2 to 12 vertices at
 * scales 1e-6, 1 and 1e6 (the conditions scaled with them: kappa ~ 1/scale). */
START_TEST(interpolate_c2_g2_ends_meet_tangent_and_curvature)
{
    unsigned long long rng = 77;
    const int sizes[] = {2, 3, 4, 12};
    const double scales[] = {1e-6, 1.0, 1e6};
    for (int si = 0; si < 3; si++)
        for (int ni = 0; ni < 4; ni++)
            for (int c = 0; c < 5; c++) {
                const double S = scales[si];
                const int n = sizes[ni];
                double xy[2 * 12], u[12];
                for (int i = 0; i < n; i++) {     /* a wavy polyline, rightwards */
                    xy[2 * i] = S * (i + test_uniform(&rng, -0.3, 0.3));
                    xy[2 * i + 1] = S * test_uniform(&rng, -0.8, 0.8);
                    u[i] = i ? u[i - 1] + hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]) : 0.0;
                }
                const double a0 = test_uniform(&rng, -1, 1), a1 = test_uniform(&rng, -1, 1);
                const double k0 = test_uniform(&rng, -2, 2) / S, k1 = test_uniform(&rng, -2, 2) / S;
                const el_bspline_end g2s = {3, {cos(a0), sin(a0)}, {-k0 * sin(a0), k0 * cos(a0)}};
                const el_bspline_end g2e = {3, {cos(a1), sin(a1)}, {-k1 * sin(a1), k1 * cos(a1)}};
                const el_bspline_end t1 = {1, {cos(a1), sin(a1)}, {0, 0}};
                const el_bspline_end d2 = {2, {-k0 * sin(a0), k0 * cos(a0)}, {0, 0}};
                const el_bspline_end *ends[5][2] = {
                    {&g2s, NULL}, {NULL, &g2e}, {&g2s, &g2e}, {&g2s, &t1}, {&d2, &g2e}};
                const el_bspline_end *s0 = ends[c][0], *s1 = ends[c][1];
                el_bspline b;
                ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, (size_t)n, s0, s1, &b), EL_OK);
                const int extra = (s0 && s0->order == 3) + (s1 && s1->order == 3);
                ck_assert_uint_eq(b.npoles, (size_t)(n + 2 + extra));
                ck_assert_uint_eq(b.nknots, (size_t)(n + extra));
                for (int i = 0; i < n; i++) {
                    double pt[2];
                    ck_assert_int_eq(el_bspline_eval(&b, 1, &u[i], pt), EL_OK);
                    ck_assert_close(pt[0], xy[2 * i], 1e-12 * S * n);
                    ck_assert_close(pt[1], xy[2 * i + 1], 1e-12 * S * n);
                }
                const double t[2] = {0.0, u[n - 1]};
                for (int e = 0; e < 2; e++) {
                    const el_bspline_end *end = ends[c][e];
                    if (!end) continue;
                    double d[2], dd[2], kappa;
                    ck_assert_int_eq(el_bspline_derivative(&b, 1, 1, &t[e], d), EL_OK);
                    ck_assert_int_eq(el_bspline_derivative(&b, 2, 1, &t[e], dd), EL_OK);
                    const double *want1 = end->order == 2 ? NULL : end->value;
                    const double *want2 = end->order == 3 ? end->value2 : end->order == 2 ? end->value : NULL;
                    if (want1) {
                        ck_assert_close(d[0], want1[0], 1e-11);
                        ck_assert_close(d[1], want1[1], 1e-11);
                    }
                    if (want2) {
                        ck_assert_close(dd[0], want2[0], 1e-9 / S);
                        ck_assert_close(dd[1], want2[1], 1e-9 / S);
                    }
                    if (end->order == 3) {
                        ck_assert_int_eq(el_bspline_curvature(&b, 1, &t[e], &kappa), EL_OK);
                        ck_assert_close(kappa, e ? k1 : k0, 1e-9 / S);
                    }
                }
                for (size_t i = 1; i + 1 < b.nknots; i++) {   /* C2 at every interior knot */
                    const double h = 1e-7 * u[n - 1], tt[2] = {b.knots[i] - h, b.knots[i] + h};
                    double dd[4];
                    ck_assert(b.knots[i] > b.knots[i - 1]);
                    ck_assert_int_eq(el_bspline_derivative(&b, 2, 2, tt, dd), EL_OK);
                    ck_assert(hypot(dd[2] - dd[0], dd[3] - dd[1]) < 1e-4 / S);
                }
                el_bspline_free(&b);
            }
    /* an order-3 end with a non-finite second value */
    el_bspline b;
    const double xy[4] = {0, 0, 1, 0};
    el_bspline_end bad = {3, {1, 0}, {0, NAN}};
    ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, 2, &bad, NULL, &b), EL_EINVAL);
    bad.order = 4;
    bad.value2[1] = 0.0;
    ck_assert_int_eq(el_bspline_interpolate_c2_ends(xy, 2, NULL, &bad, &b), EL_EINVAL);
}
END_TEST

START_TEST(test_interpolate_c2_bad_input)
{
    el_bspline b;
    memset(&b, 0x5a, sizeof b);
    const el_bspline untouched = b;
    double xy[8] = {0, 0, 1, 0, 1, 0, 2, 1};
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, 1, &b), EL_EINVAL);
    ck_assert_int_eq(el_bspline_interpolate_c2(NULL, 4, &b), EL_EINVAL);
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, 4, &b), EL_ESINGULAR);  /* repeated vertex */
    xy[3] = NAN;
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, 4, &b), EL_EINVAL);
    ck_assert(memcmp(&b, &untouched, sizeof b) == 0);
    /* two vertices: the straight segment */
    double two[4] = {0, 0, 3, 4};
    ck_assert_int_eq(el_bspline_interpolate_c2(two, 2, &b), EL_OK);
    double t = 2.5, pt[2];
    ck_assert_int_eq(el_bspline_eval(&b, 1, &t, pt), EL_OK);
    ck_assert_close(pt[0], 1.5, 1e-14);
    ck_assert_close(pt[1], 2.0, 1e-14);
    el_bspline_free(&b);
}
END_TEST

/* ---------------------------------------------------------------- elastica -> B-spline */

/* Independent dense measurement of the distance B-spline -> elastica: 40
 * samples per span, foot points by Newton to convergence with exact
 * el_smooth_eval at every step. */
static double measure(const el_smooth_params *p, const el_bspline *b)
{
    const size_t n = 40 * (b->nknots - 1) + 1;
    double *t = malloc(n * sizeof *t), *P = malloc(2 * n * sizeof *P), *s = malloc(n * sizeof *s),
           *g = malloc(2 * n * sizeof *g), *th = malloc(n * sizeof *th), *ka = malloc(n * sizeof *ka);
    ck_assert(t && P && s && g && th && ka);
    for (size_t j = 0; j + 1 < b->nknots; j++)
        for (int k = 0; k < 40; k++)
            t[40 * j + (size_t)k] = b->knots[j] + (b->knots[j + 1] - b->knots[j]) * k / 40.0;
    t[n - 1] = b->knots[b->nknots - 1];
    ck_assert_int_eq(el_bspline_eval(b, n, t, P), EL_OK);
    memcpy(s, t, n * sizeof *s);
    for (int it = 0; it < 6; it++) {
        ck_assert_int_eq(el_smooth_eval(p, n, s, g, th, ka), EL_OK);
        for (size_t i = 0; i < n; i++) {
            const double rx = P[2 * i] - g[2 * i], ry = P[2 * i + 1] - g[2 * i + 1];
            const double f = rx * cos(th[i]) + ry * sin(th[i]);
            const double fp = 1.0 - ka[i] * (-rx * sin(th[i]) + ry * cos(th[i]));
            s[i] = fmin(fmax(s[i] + f / fp, 0.0), p->length);
        }
    }
    ck_assert_int_eq(el_smooth_eval(p, n, s, g, NULL, NULL), EL_OK);
    double dmax = 0.0;
    for (size_t i = 0; i < n; i++) dmax = fmax(dmax, hypot(P[2 * i] - g[2 * i], P[2 * i + 1] - g[2 * i + 1]));
    free(t); free(P); free(s); free(g); free(th); free(ka);
    return dmax;
}

static const el_smooth_params CURVES[3] = {
    {0.3, -0.2, 0.4, 1.0, 0.8, 0.3, 8.0},       /* inflectional, k < 1 */
    {1.0, 2.0, -1.0, 2.0, 1.5, 0.2, 5.0},       /* loops, k > 1 */
    {0.0, 0.0, 0.0, 0.7, 0.99999, -2.0, 7.0},   /* near the separatrix k = 1 */
};

START_TEST(test_smooth_to_bspline_certified)
{
    const el_smooth_params *p = &CURVES[_i / 3];
    const double rel[3] = {1e-3, 1e-6, 1e-9}, tol = rel[_i % 3] * p->length;
    el_bspline b;
    ck_assert_int_eq(el_smooth_to_bspline(p, tol, 3, &b), EL_OK);
    ck_assert_int_eq(el_bspline_check(&b), EL_OK);
    ck_assert_int_eq(b.degree, 3);
    ck_assert(b.max_deviation > 0.0 && b.max_deviation <= tol);
    ck_assert_double_eq(b.knots[0], 0.0);
    ck_assert_double_eq(b.knots[b.nknots - 1], p->length);
    const double m = measure(p, &b);
    ck_assert_msg(m <= b.max_deviation * (1 + 1e-6) + 1e-14 * p->length,
                  "measured %g > certified %g", m, b.max_deviation);
    ck_assert_msg(b.max_deviation <= 1.1 * m, "certified %g not within 10%% of measured %g",
                  b.max_deviation, m);
    el_bspline_free(&b);
}
END_TEST

START_TEST(test_smooth_to_bspline_degrees)
{
    const el_smooth_params *p = &CURVES[0];
    const double tol = 1e-6 * p->length;
    size_t prev = (size_t)-1;
    for (int degree = 3; degree <= 7; degree++) {
        el_bspline b;
        ck_assert_int_eq(el_smooth_to_bspline(p, tol, degree, &b), EL_OK);
        ck_assert_int_eq(b.degree, degree);
        ck_assert(b.max_deviation <= tol);
        const double m = measure(p, &b);
        ck_assert(m <= b.max_deviation * (1 + 1e-6) && b.max_deviation <= 1.1 * m);
        if (degree <= 5) ck_assert_uint_lt(b.npoles, prev);   /* higher degree, fewer poles */
        prev = b.npoles;
        el_bspline_free(&b);
    }
}
END_TEST

/* The end conditions a CAD user relies on for tangent (G1) joins: B(0), B(L)
 * are exactly the elastica's end points (as el_smooth_eval gives them), and
 * B'(0), B'(L) are the exact unit tangents (cos theta, sin theta): direction to
 * 1e-12 rad, and speed 1 (arc-length parameter), for k below, near, at and
 * above 1 and tolerances 1e-3 .. 1e-9. */
START_TEST(test_smooth_to_bspline_end_tangents)
{
    static const double ks[7] = {0.3, 0.8, 0.99999, 1.0, 1.00001, 1.5, 3.0};
    static const double rels[4] = {1e-3, 1e-5, 1e-7, 1e-9};
    const double k = ks[_i / 4], rel = rels[_i % 4];
    const el_smooth_params p = {0.7, -1.3, 2.1 - 0.5 * _i, 1.3, k, -0.9 + 0.37 * _i, 6.0};
    const int degree = 3 + _i % 3 * 2;   /* 3, 5, 7 */
    const double tol = rel * p.length;
    el_bspline b;
    ck_assert_int_eq(el_smooth_to_bspline(&p, tol, degree, &b), EL_OK);
    ck_assert(b.max_deviation > 0.0 && b.max_deviation <= tol);
    const double ends[2] = {0.0, p.length};
    double P[4], D[4];
    ck_assert_int_eq(el_bspline_eval(&b, 2, ends, P), EL_OK);
    ck_assert_int_eq(el_bspline_derivative(&b, 1, 2, ends, D), EL_OK);
    for (int e = 0; e < 2; e++) {
        double g[2], th;
        ck_assert_int_eq(el_smooth_eval(&p, 1, &ends[e], g, &th, NULL), EL_OK);
        ck_assert_double_eq(P[2 * e], g[0]);
        ck_assert_double_eq(P[2 * e + 1], g[1]);
        const double c = cos(th), sn = sin(th), dx = D[2 * e], dy = D[2 * e + 1];
        const double ang = atan2(c * dy - sn * dx, c * dx + sn * dy);   /* B' vs T, in (-pi, pi] */
        ck_assert_msg(fabs(ang) <= 1e-12, "k=%g rel=%g end %d: tangent off by %g rad", k, rel, e, ang);
        ck_assert_msg(fabs(hypot(dx, dy) - 1.0) <= 1e-12, "k=%g rel=%g end %d: speed %.17g", k, rel,
                      e, hypot(dx, dy));
    }
    el_bspline_free(&b);
}
END_TEST

START_TEST(test_smooth_to_bspline_bad_input)
{
    el_smooth_params p = CURVES[1];
    el_bspline b;
    memset(&b, 0x5a, sizeof b);
    const el_bspline untouched = b;
    ck_assert_int_eq(el_smooth_to_bspline(&p, 0.0, 3, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, -1e-3, 3, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, NAN, 3, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, INFINITY, 3, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-3, 2, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-3, 8, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(NULL, 1e-3, 3, &b), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-3, 3, NULL), EL_EINVAL);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-16 * p.length, 3, &b), EL_EDOM);  /* below rounding */
    p.mu = -1.0;
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-3, 3, &b), EL_EINVAL);
    ck_assert(memcmp(&b, &untouched, sizeof b) == 0);
    /* k = 0 is a straight line: one span */
    p = CURVES[1];
    p.k = 0.0;
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-9, 3, &b), EL_OK);
    ck_assert_int_eq((int)b.npoles, 4);
    ck_assert(b.max_deviation <= 1e-9);
    el_bspline_free(&b);
    /* a zero-length segment is a point */
    p = CURVES[1];
    p.length = 0.0;
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-3, 4, &b), EL_OK);
    ck_assert_int_eq((int)b.npoles, 5);
    ck_assert_double_eq(b.max_deviation, 0.0);
    ck_assert_double_eq(b.poles[8], p.x0);
    el_bspline_free(&b);
}
END_TEST

/* A chain whose pieces do not meet (a kink, a gap) is refused before anything is written:
 * the C2 join's bound does not see a kink (0.5 rad between pieces 2 long was certified at
 * 0.0171 where the B-spline lay 0.0175 from them, QA); within tol they convert */
START_TEST(test_chain_pieces_must_meet)
{
    /* the second piece continues the first's elastica (q advanced by sqrt(mu) L): G2 */
    el_smooth_params pc[2] = {{0.0, 0.0, 0.0, 1.0, 0.5, 0.3, 2.0}, {0.0, 0.0, 0.0, 1.0, 0.5, 2.3, 2.0}};
    const double s[2] = {0.0, pc[0].length};
    double xy[4];
    ck_assert_int_eq(el_smooth_eval(&pc[0], 2, s, xy, NULL, NULL), EL_OK);
    el_bspline b;
    memset(&b, 0x5a, sizeof b);
    const el_bspline untouched = b;
    const double tol = 1e-6, kinks[3] = {0.5, 0.0, 1e-3 * tol / 2.0}, gaps[3] = {0.0, 0.1, 1e-3 * tol};
    for (int c = 0; c < 3; c++) {
        pc[1].x0 = xy[2] + gaps[c];
        pc[1].y0 = xy[3];
        pc[1].phi = kinks[c];
        const int st = el_smooth_chain_to_bspline(pc, 2, tol, 5, &b);
        if (c < 2) {
            ck_assert_int_eq(st, EL_EINVAL);
            ck_assert(memcmp(&b, &untouched, sizeof b) == 0);
        } else {
            ck_assert_msg(st == EL_OK && b.max_deviation <= tol, "status %d, certified %g", st, b.max_deviation);
            el_bspline_free(&b);
        }
    }
}
END_TEST

/* The joins' rounding is part of the chain's budget: elastic splines (tension 0) through
 * 50 points of (x, 0.3 sin 3x), x up to 1 to 3.9 km in mm, within tol = 1e-6 and 2e-6
 * (1e-12 of their length, 50 x the rounding floor): 9 of these 48 ended EL_EMAXITER,
 * pieces certified just below tol plus the joins' ~5e-10 above it ("not reached
 * (certified 1e-06)", QA); the pieces are now fitted within what the joins leave. */
START_TEST(chain_at_large_coordinates_keeps_the_joins_within_tol)
{
    for (int j = 0; j < 24; j++) {
        const double scale = 1e6 * (1.0 + j / 8.0);
        double xy[100];
        for (int i = 0; i < 50; i++) {
            const double t = (double)i / 49.0;
            xy[2 * i] = scale * t;
            xy[2 * i + 1] = scale * 0.3 * sin(3.0 * t);
        }
        el_spline_options o;
        el_spline_options_defaults(&o);
        el_spline_result r;
        ck_assert_int_eq(el_spline_solve(xy, 50, &o, &r), EL_OK);
        for (int c = 1; c <= 2; c++) {
            el_bspline b;
            const int st = el_spline_to_bspline(&r, c * 1e-6, 3, &b);
            ck_assert_msg(st == EL_OK && b.max_deviation <= c * 1e-6, "scale %g tol %g: status %d, certified %.17g",
                          scale, c * 1e-6, st, b.max_deviation);
            el_bspline_free(&b);
        }
        el_spline_result_free(&r);
    }
}
END_TEST

/* A curve given with a huge angle phi is the same curve as with phi reduced to
 * [-pi, pi] (el_smooth_eval rotates its points by cos, sin phi), and is approximated as
 * that one is: the same poles, certified to tol. Before, the tangent angle phi + turning
 * lost the turning to rounding and the approximation steered by it: the fuzzer's curve
 * (phi = -3.3e305) took 12 s of CPU and 92 poles for 65 (G2 ends; 2.7 s with G1 ends). */
START_TEST(huge_angle_is_approximated_as_the_reduced_one)
{
    const double phis[3] = {-3.332121159901045e+305, 1e12, -2e6};
    el_smooth_params p = {-2.6274509803921573, -2.5783169298847941, 0.0, 36.869058823529407,
                          -0.78823529411764692, -5.2549019607843146, 7.3725490196078427};
    const double tol = 0.00055619229251544985;
    for (int i = 0; i < 3; i++)
        for (int g2 = 0; g2 < 2; g2++) {
            p.phi = phis[i];
            el_smooth_params r = p;
            r.phi = atan2(sin(p.phi), cos(p.phi));
            el_bspline b, br;
            const int st = g2 ? el_smooth_to_bspline_g2(&p, tol, 7, &b) : el_smooth_to_bspline(&p, tol, 7, &b);
            ck_assert_int_eq(st, EL_OK);
            ck_assert_int_eq(g2 ? el_smooth_to_bspline_g2(&r, tol, 7, &br) : el_smooth_to_bspline(&r, tol, 7, &br),
                             EL_OK);
            ck_assert_msg(b.npoles == br.npoles, "phi %g: %zu poles, %zu for the reduced angle", p.phi,
                          b.npoles, br.npoles);
            for (size_t j = 0; j < 2 * b.npoles; j++) ck_assert_double_eq(b.poles[j], br.poles[j]);
            ck_assert(b.max_deviation <= tol);
            const double m = measure(&r, &b);   /* the reduced angle's tangents are exact */
            ck_assert_msg(m <= b.max_deviation * (1 + 1e-6) + 1e-14 * p.length, "measured %g > %g", m,
                          b.max_deviation);
            el_bspline_free(&b);
            el_bspline_free(&br);
        }
}
END_TEST

/* Straight and near-straight elasticae at every scale, 1e-6 to 1e9: a few poles within a
 * designer's tol (1e-3) and a relative one (near-straight: 4 to 26 at 1e-3 on 1e9). A line has no knot density of its own (g = 0);
 * the unit density stood in, and the pole estimate grew as L / tol^(1/(p+1)): from
 * L ~ 3e4 at tol 1e-3 it passed the pole limit (EL_EDOM). */
START_TEST(straight_curves_at_every_scale)
{
    for (int e = -6; e <= 9; e++) {
        const double L = pow(10.0, e);
        const el_smooth_params curves[3] = {
            {L, -2.0 * L, 0.7, 1.0 / (L * L), 0.0, 0.0, L},       /* a line */
            {0.0, 0.0, 0.3, 1.0 / (L * L), 1e-4, 0.5, L},         /* bows ~1e-4 L */
            {0.0, 0.0, -2.0, 1.0 / (L * L), -1e-7, -1.0, L},      /* ~1e-7 L */
        };
        for (int c = 0; c < 3; c++)
            for (int t = 0; t < 2; t++)
                for (int degree = 3; degree <= 5; degree += 2)
                    for (int g2 = 0; g2 < 2; g2++) {
                        const el_smooth_params *p = &curves[c];
                        const double tol = t ? 1e-6 * L : 1e-3;
                        el_bspline b;
                        const int st = g2 ? el_smooth_to_bspline_g2(p, tol, degree, &b)
                                          : el_smooth_to_bspline(p, tol, degree, &b);
                        ck_assert_msg(st == EL_OK, "L %g curve %d tol %g degree %d g2 %d: status %d",
                                      L, c, tol, degree, g2, st);
                        /* a line: the fewest its fixed end poles allow */
                        const size_t most = c ? 40 : (size_t)degree + 3;
                        ck_assert_msg(b.npoles <= most, "L %g curve %d tol %g: %zu poles", L, c, tol,
                                      b.npoles);
                        ck_assert(b.max_deviation <= tol);
                        ck_assert_double_le(measure(p, &b), tol);
                        el_bspline_free(&b);
                    }
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("bspline");
    TCase *tc = tcase_create("bspline");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_eval_matches_cox_de_boor);
    tcase_add_test(tc, test_derivatives_by_finite_differences);
    tcase_add_test(tc, test_curvature_parabola);
    tcase_add_test(tc, test_bad_bsplines);
    tcase_add_test(tc, test_interpolate_c2_discrete_elastica);
    tcase_add_test(tc, test_interpolate_c2_bad_input);
    tcase_add_test(tc, interpolate_c2_ends_meet_their_derivatives);
    tcase_add_test(tc, interpolate_c2_g2_ends_meet_tangent_and_curvature);
    tcase_add_loop_test(tc, test_smooth_to_bspline_certified, 0, 9);
    tcase_add_test(tc, test_smooth_to_bspline_degrees);
    tcase_add_loop_test(tc, test_smooth_to_bspline_end_tangents, 0, 28);
    tcase_add_test(tc, test_smooth_to_bspline_bad_input);
    tcase_add_test(tc, test_chain_pieces_must_meet);
    tcase_add_test(tc, huge_angle_is_approximated_as_the_reduced_one);
    tcase_add_test(tc, straight_curves_at_every_scale);
    tcase_add_test(tc, chain_at_large_coordinates_keeps_the_joins_within_tol);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
