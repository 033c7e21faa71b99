/*
 * Regression tests of issue 12's findings in affine, bspline, blend and prep:
 * size computations that wrapped, unbounded work and silent truncation,
 * EL_OK with NaN/inf at extreme magnitudes, outputs not written as the header
 * says, and the elliptic blends' singular neighbourhood of K = 2. Each test is
 * named after what it guards.
 */
#include "testutil.h"
#include <float.h>
#include <stdint.h>
#include <string.h>
#include <time.h>
#include <stdlib.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include "internal.h"

static double cpu_seconds(void) { return (double)clock() / CLOCKS_PER_SEC; }

/* 200 samples of a unit circle's arc. */
static void arc_samples(double *p, size_t n, double turn)
{
    for (size_t i = 0; i < n; i++) {
        const double t = turn * (double)i / (double)(n - 1);
        p[2 * i] = cos(t);
        p[2 * i + 1] = sin(t);
    }
}

/* ------------------------------------------------------------------ affine */

START_TEST(affine_polyline_huge_n_refused_without_overflow)
{
    double p[400];
    arc_samples(p, 200, 2.5);
    const size_t huge[] = {((size_t)1 << 61) - 1, ((size_t)1 << 62) - 1, SIZE_MAX,
                           (size_t)EL_AFFINE_MAX_EDGES + 1};
    for (size_t i = 0; i < sizeof huge / sizeof *huge; i++) {
        el_affine_result r;
        memset(&r, 0x5a, sizeof r);
        const double t0 = cpu_seconds();
        ck_assert_int_eq(el_affine_polyline(200, p, NULL, 0, NULL, huge[i], NULL, &r), EL_EDOM);
        ck_assert(cpu_seconds() - t0 < 1.0);   /* at once, not after building n vertices */
        ck_assert_int_eq(((unsigned char *)&r)[0], 0x5a);   /* res filled only on success */
    }
    el_affine_result r;
    ck_assert_int_eq(el_affine_polyline(200, p, NULL, 0, NULL, 20, NULL, &r), EL_OK);
    ck_assert_uint_eq(r.npts, 21);
    el_affine_result_free(&r);
}
END_TEST

START_TEST(affine_elements_nd_coincident_points_give_zero_not_nan)
{
    double x[12];
    for (int i = 0; i < 12; i++) x[i] = 1.0;   /* 6 equal points in R^2 */
    double D[4], Ln = -1.0;
    ck_assert_int_eq(el_affine_elements_nd(2, 6, x, D, &Ln), EL_OK);
    for (int i = 0; i < 4; i++) ck_assert(D[i] == 0.0);
    ck_assert(Ln == 0.0);
    /* collinear edges (no zero column, singular): 0 too */
    for (int i = 0; i < 6; i++) { x[2 * i] = i; x[2 * i + 1] = 2.0 * i; }
    ck_assert_int_eq(el_affine_elements_nd(2, 6, x, D, &Ln), EL_OK);
    for (int i = 0; i < 4; i++) ck_assert(D[i] == 0.0);
}
END_TEST

/* det(dx_i, dx_{i+1}) of a scaled polyline is scale^2 det: exact at 1e+-150,
 * an element beyond double's range is EL_EDOM (D untouched), and Ln keeps
 * elements whose D underflows. */
START_TEST(affine_elements_nd_extreme_scales)
{
    const double base[10] = {0, 0, 1, 0, 2, 1, 2, 3, 0, 4};
    double D0[3], L0, D[3], L;
    ck_assert_int_eq(el_affine_elements_nd(2, 5, base, D0, &L0), EL_OK);
    const double scales[] = {1e150, 1e-150, 0x1p-500};
    for (int s = 0; s < 3; s++) {
        double x[10];
        for (int i = 0; i < 10; i++) x[i] = base[i] * scales[s];
        ck_assert_int_eq(el_affine_elements_nd(2, 5, x, D, &L), EL_OK);
        for (int i = 0; i < 3; i++)
            ck_assert_close(D[i], D0[i] * scales[s] * scales[s], 1e-14 * fabs(D0[i] * scales[s] * scales[s]));
        ck_assert_close(L, L0 * cbrt(scales[s] * scales[s]), 1e-13 * fabs(L0 * cbrt(scales[s] * scales[s])));
    }
    double x[10];
    for (int i = 0; i < 10; i++) x[i] = base[i] * 1e200;   /* D ~ 1e400 */
    D[0] = 7.0;
    ck_assert_int_eq(el_affine_elements_nd(2, 5, x, D, &L), EL_EDOM);
    ck_assert(D[0] == 7.0);
    for (int i = 0; i < 10; i++) x[i] = base[i] * 1e-200;   /* D ~ 1e-400: underflows */
    ck_assert_int_eq(el_affine_elements_nd(2, 5, x, D, &L), EL_OK);
    ck_assert(isfinite(L) && L != 0.0);
    const double c2 = cbrt(1e-200) * cbrt(1e-200);   /* |D|^(1/3) scales by cbrt(s^2) */
    ck_assert_close(L, L0 * c2, 1e-12 * fabs(L0) * c2);
}
END_TEST

START_TEST(affine_planar_functions_refuse_values_beyond_double_range)
{
    double xy[10] = {0, 0, 1, 0, 2, 1, 2, 3, 0, 4}, big[10], A[3], B[2], k[2], S[4], L;
    for (int i = 0; i < 10; i++) big[i] = xy[i] * 1e160;   /* areas ~ 1e320 */
    ck_assert_int_eq(el_affine_coords(5, big, A, B), EL_EDOM);
    ck_assert_int_eq(el_affine_length(5, big, &L), EL_EDOM);
    ck_assert_int_eq(el_affine_curvature(5, big, k), EL_EDOM);
    ck_assert_int_eq(el_affine_parabolic_lengths(5, big, S), EL_EDOM);
    for (int i = 0; i < 10; i++) big[i] = xy[i] * 1e-160;   /* areas ~ 1e-320: no precision */
    ck_assert_int_eq(el_affine_length(5, big, &L), EL_EDOM);
    /* far from the origin but moderate edges: fine, and finite */
    for (int i = 0; i < 10; i++) big[i] = xy[i] + 1e300;
    ck_assert_int_eq(el_affine_coords(5, big, A, B), EL_OK);
    for (int i = 0; i < 3; i++) ck_assert(isfinite(A[i]));
    el_affine_conic c[2];
    memset(c, 0x5a, sizeof c);   /* conics: coefficients with x^2 ~ 1e600: EL_EDOM, untouched */
    const double par[10] = {1e300, 1e300, 1e300 + 1, 1e300 + 1, 1e300 + 2, 1e300 + 4,
                            1e300 + 3, 1e300 + 9, 1e300 + 4, 1e300 + 16};
    const int st = el_affine_osculating_conics(5, par, EL_CONIC_OUTER, c);
    ck_assert(st == EL_EDOM || st == EL_ESINGULAR);
    ck_assert_int_eq(((unsigned char *)c)[0], 0x5a);
}
END_TEST

START_TEST(lane_riesenfeld_near_dbl_max_does_not_overflow)
{
    const double x[3] = {0.0, -DBL_MAX, 1.0};
    double out[4];
    ck_assert_int_eq(el_affine_lane_riesenfeld(1, 2, 3, x, out), EL_OK);
    for (int i = 0; i < 4; i++) ck_assert(isfinite(out[i]));
    ck_assert_int_eq(el_affine_lane_riesenfeld(1, 1, SIZE_MAX / 2, x, out), EL_EINVAL);
}
END_TEST

/* ----------------------------------------------------------------- bspline */

START_TEST(bspline_alloc_refuses_sizes_that_wrap)
{
    el_bspline b;
    memset(&b, 0x5a, sizeof b);
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 2, SIZE_MAX / 2, 2), EL_ENOMEM);   /* dim npoles wraps */
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 2, SIZE_MAX / 16 + 1, 2), EL_ENOMEM);   /* bytes wrap */
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 1, 8, SIZE_MAX / 4), EL_ENOMEM);
    ck_assert_int_eq(((unsigned char *)&b)[0], 0x5a);
    ck_assert_int_eq(el_bspline_alloc(&b, 3, 2, 8, 2), EL_OK);
    el_bspline_free(&b);
}
END_TEST

START_TEST(bspline_check_degree_int_max_without_overflow)
{
    double poles[16] = {0}, knots[2] = {0, 1};
    int mults[2] = {4, 4};
    el_bspline b = {3, 2, 4, poles, 2, knots, mults, -1.0};
    ck_assert_int_eq(el_bspline_check(&b), EL_OK);
    b.degree = INT32_MAX;   /* degree + 1 overflowed int */
    ck_assert_int_eq(el_bspline_check(&b), EL_EINVAL);
    b.degree = 3;
    b.npoles = SIZE_MAX - 2;   /* npoles + degree + 1 wraps to 2 */
    ck_assert_int_eq(el_bspline_check(&b), EL_EINVAL);
    b.npoles = 4;
    knots[0] = -DBL_MAX; knots[1] = DBL_MAX;   /* knot range beyond double */
    ck_assert_int_eq(el_bspline_check(&b), EL_EINVAL);
}
END_TEST

START_TEST(bspline_curvature_large_derivatives_stay_finite)
{
    /* a parabola scaled by 1e200: |B'|^3 would overflow, the curvature does not */
    double poles[6] = {0, 0, 1e200, 0, 2e200, 2e200}, knots[2] = {0, 1};
    int mults[2] = {3, 3};
    el_bspline b = {2, 2, 3, poles, 2, knots, mults, -1.0};
    double t[3] = {0.0, 0.5, 1.0}, k[3];
    ck_assert_int_eq(el_bspline_curvature(&b, 3, t, k), EL_OK);
    for (int i = 0; i < 3; i++) ck_assert(isfinite(k[i]) && k[i] > 0.0);
    /* the curvature of the unit-scale parabola divided by 1e200 */
    double unit[6] = {0, 0, 1, 0, 2, 2}, k1[3];
    b.poles = unit;
    ck_assert_int_eq(el_bspline_curvature(&b, 3, t, k1), EL_OK);
    for (int i = 0; i < 3; i++) ck_assert_close(k[i], k1[i] * 1e-200, 1e-14 * k1[i] * 1e-200);
}
END_TEST

START_TEST(smooth_to_bspline_bounded_work_refused_at_once)
{
    const el_smooth_params cases[] = {
        {0, 0, 0, 1.0, 1e8, 0.0, 1.0},     /* k 1e8: turns 2e8 rad */
        {0, 0, 0, 1e8, 0.9, 0.0, 1.0},     /* mu 1e8 */
        {0, 0, 0, 1.0, 0.9, 0.0, 1e8},     /* length 1e8 */
        {0, 0, 0, 1.0, -3.0, 0.0, 3000.0}, /* a clockwise loop: |k| counts */
    };
    for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
        el_bspline b;
        memset(&b, 0x5a, sizeof b);
        const double t0 = cpu_seconds();
        ck_assert_int_eq(el_smooth_to_bspline(&cases[i], 1e-6, 3, &b), EL_EDOM);
        ck_assert(cpu_seconds() - t0 < 0.5);
        ck_assert_int_eq(((unsigned char *)&b)[0], 0x5a);
    }
    /* tol below what the curve's scale resolves: the phase q counts */
    el_smooth_params p = {0, 0, 0, 1.0, 0.7, 0.0, 5.0};
    el_bspline b;
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-300, 3, &b), EL_EDOM);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-12, 3, &b), EL_OK);
    el_bspline_free(&b);
    p.q = 1e6;   /* 1e-14 |q| / sqrt(mu) = 1e-8 */
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-9, 3, &b), EL_EDOM);
}
END_TEST

START_TEST(smooth_to_bspline_emaxiter_returns_the_best_spline)
{
    /* 2000 long, turning ~3600 rad, tol 1e-6: needs more than EL_BSPLINE_MAX_POLES */
    const el_smooth_params p = {0, 0, 0, 1.0, 0.9, 0.1, 2000.0};
    el_bspline b;
    memset(&b, 0, sizeof b);
    ck_assert_int_eq(el_smooth_to_bspline(&p, 1e-6, 3, &b), EL_EMAXITER);
    ck_assert_int_eq(el_bspline_check(&b), EL_OK);   /* written, valid */
    ck_assert(b.npoles <= EL_BSPLINE_MAX_POLES);
    ck_assert(b.max_deviation > 1e-6 && isfinite(b.max_deviation));
    /* the deviation is certified: sample it */
    double t[401], xy[802], g[802];
    for (int i = 0; i <= 400; i++) t[i] = p.length * i / 400.0;
    ck_assert_int_eq(el_bspline_eval(&b, 401, t, xy), EL_OK);
    ck_assert_int_eq(el_smooth_eval(&p, 401, t, g, NULL, NULL), EL_OK);
    for (int i = 0; i <= 400; i++)
        ck_assert(hypot(xy[2 * i] - g[2 * i], xy[2 * i + 1] - g[2 * i + 1]) <= 2.0 * b.max_deviation);
    el_bspline_free(&b);
}
END_TEST

/* the interpolant is scale invariant: at 1e-300 (GSL's tridiagonal solver met a
 * zero pivot there and called the error handler) and 1e300 it is the unit one scaled */
START_TEST(interpolate_c2_tiny_and_huge_scales)
{
    double xy[2 * 40];
    for (int i = 0; i < 40; i++) { xy[2 * i] = i / 39.0; xy[2 * i + 1] = (i % 2) ? 0.1 : -0.1; }
    el_bspline b0, b;
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, 40, &b0), EL_OK);
    const double sc[] = {0x1p-1000, 0x1p1000};
    for (int s = 0; s < 2; s++) {
        double p[80];
        for (int i = 0; i < 80; i++) p[i] = xy[i] * sc[s];
        ck_assert_int_eq(el_bspline_interpolate_c2(p, 40, &b), EL_OK);
        for (size_t i = 0; i < 2 * b.npoles; i++)
            ck_assert_close(b.poles[i] / sc[s], b0.poles[i], 1e-12);
        el_bspline_free(&b);
    }
    el_bspline_free(&b0);
}
END_TEST

START_TEST(interpolate_c2_huge_coordinates_edom)
{
    double xy[6] = {-1e308, 0, 0, 1e308, 1e308, 0};
    el_bspline b;
    memset(&b, 0x5a, sizeof b);
    ck_assert_int_eq(el_bspline_interpolate_c2(xy, 3, &b), EL_EDOM);
    ck_assert_int_eq(((unsigned char *)&b)[0], 0x5a);
}
END_TEST

/* ------------------------------------------------------------------- blend */

START_TEST(elliptic_blend_refuses_the_k2_neighbourhood)
{
    el_blend_basis b;
    const double m_refused[] = {0.6438, 0.6392, 0.6484, 0.644};
    for (size_t i = 0; i < sizeof m_refused / sizeof *m_refused; i++) {
        memset(&b, 0x5a, sizeof b);
        ck_assert_int_eq(el_blend_init_elliptic(&b, sqrt(m_refused[i]), 2.0), EL_ESINGULAR);
        ck_assert_int_eq(((unsigned char *)&b)[0], 0x5a);
    }
    /* the documented interval: k in (0.79932, 0.80544) */
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.7993, 2.0), EL_OK);
    ck_assert(b.cond <= EL_BLEND_COND_MAX);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.7994, 2.0), EL_ESINGULAR);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.8054, 2.0), EL_ESINGULAR);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.8055, 2.0), EL_OK);
    /* the basis there is bounded as documented: lebesgue <= 6 at the edge, d = 2 */
    ck_assert(b.lebesgue < 6.0 && b.basis_min > -2.5);
}
END_TEST

/* basis_min / lebesgue against dense sampling; convex_hull against the sign */
START_TEST(blend_basis_min_and_convex_hull_reported)
{
    struct { int mq; double par, d; int hull; } cases[] = {
        {0, 0.3, 2.0, 1}, {0, 0.62, 2.0, 0}, {0, 0.85, 2.0, 0}, {0, 0.5, 4.0, 0},
        {1, 1.0, 0.0, 1}, {1, 0.3, 0.0, 1},
    };
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        el_blend_basis b;
        if (cases[c].mq) {
            double d;
            ck_assert_int_eq(el_blend_eck_d(cases[c].par, &d), EL_OK);
            ck_assert_int_eq(el_blend_init_mq(&b, cases[c].par, d), EL_OK);
        } else {
            ck_assert_int_eq(el_blend_init_elliptic(&b, sqrt(cases[c].par), cases[c].d), EL_OK);
        }
        double mn = HUGE_VAL, leb = 0.0;
        for (int i = 0; i <= 20000; i++) {
            double t = i / 20000.0, h[4], s = 0.0;
            ck_assert_int_eq(el_blend_basis_eval(&b, 1, &t, h, NULL, NULL), EL_OK);
            for (int j = 0; j < 4; j++) { mn = fmin(mn, h[j]); s += fabs(h[j]); }
            leb = fmax(leb, s);
        }
        ck_assert_int_eq(b.convex_hull, cases[c].hull);
        ck_assert(b.basis_min <= mn + 1e-12);           /* not above any sample */
        ck_assert_close(b.basis_min, mn, 1e-8 + 1e-6 * fabs(mn));
        ck_assert(b.lebesgue >= leb - 1e-12);
        ck_assert_close(b.lebesgue, leb, 1e-8 * leb);
    }
}
END_TEST

START_TEST(blend_values_beyond_double_range_edom)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 2.0), EL_OK);
    /* inside [0, 1] with the convex hull: a convex combination, no overflow */
    const double q[8] = {0, 0, DBL_MAX, 0, DBL_MAX, DBL_MAX, 0, DBL_MAX};
    double t[3] = {0.2, 0.5, 0.8}, xy[6], dxy[6];
    ck_assert_int_eq(el_blend_eval(&b, q, 3, t, xy, NULL), EL_OK);
    for (int i = 0; i < 6; i++) ck_assert(isfinite(xy[i]));
    /* the derivative at t = 0, d (q_1 - q_0) = 2 DBL_MAX, overflows */
    double t0 = 0.0;
    ck_assert_int_eq(el_blend_eval(&b, q, 1, &t0, xy, dxy), EL_EDOM);
    /* t far outside [0, 1] with large control points */
    double tfar[1] = {1e200}, q3[8];
    for (int i = 0; i < 8; i++) q3[i] = 1e200 * (i % 3);
    ck_assert_int_eq(el_blend_init_mq(&b, 1.0, 3.0), EL_OK);
    ck_assert_int_eq(el_blend_eval(&b, q3, 1, tfar, xy, NULL), EL_EDOM);
    double d;
    ck_assert_int_eq(el_blend_eck_d(1e-320, &d), EL_EDOM);    /* d ~ 1/c overflows */
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 5e-324), EL_ESINGULAR);   /* h_1 ~ 0 */
    double o[4], tt = 0.5;
    ck_assert_int_eq(el_blend_eck_omega(1e-320, 1, &tt, o), EL_EDOM);
}
END_TEST

/* -------------------------------------------------------------------- prep */

START_TEST(resample_long_segment_small_r_is_not_truncated)
{
    const double seg[4] = {0, 0, 1000, 0};
    el_resample_result r;
    ck_assert_int_eq(el_resample_equilateral(seg, 2, 2e-3, &r), EL_OK);
    ck_assert_uint_eq(r.n, 500001);   /* 524 vertices with EL_OK before */
    ck_assert(r.remainder < 2e-3);
    ck_assert(fabs(r.xy[2 * (r.n - 1)] - 1000.0) < 2e-3);
    for (size_t k = 1; k < r.n; k += 9973)
        ck_assert_close(hypot(r.xy[2 * k] - r.xy[2 * k - 2], r.xy[2 * k + 1] - r.xy[2 * k - 1]),
                        2e-3, 1e-12);
    el_resample_free(&r);
}
END_TEST

START_TEST(resample_past_the_vertex_limit_refused_at_once)
{
    double arc[2 * 3000];
    for (int i = 0; i < 3000; i++) {   /* a 330-long keyline-like arc far from the origin */
        const double a = 3.3 * i / 2999.0;
        arc[2 * i] = 1000.0 + 100.0 * cos(a);
        arc[2 * i + 1] = -500.0 + 100.0 * sin(a);
    }
    const double rs[] = {1e-9, 1e-5, 330.0 / (EL_RESAMPLE_MAX_VERTICES - 1) * 0.99};
    for (int i = 0; i < 3; i++) {
        el_resample_result r;
        memset(&r, 0x5a, sizeof r);
        const double t0 = cpu_seconds();
        ck_assert_int_eq(el_resample_equilateral(arc, 3000, rs[i], &r), EL_EDOM);
        ck_assert(cpu_seconds() - t0 < 0.5);
        ck_assert_int_eq(((unsigned char *)&r)[0], 0x5a);
    }
    /* just inside the limit: every vertex, the whole arc */
    el_resample_result r;
    ck_assert_int_eq(el_resample_equilateral(arc, 3000, 1e-3, &r), EL_OK);
    ck_assert(r.remainder < 1e-3);
    el_resample_free(&r);
}
END_TEST

/* the same polygon at scales 1e-300 .. 1e300 (powers of two: exact) resamples alike */
START_TEST(resample_extreme_scales_scale_invariant)
{
    const double sq[8] = {0, 0, 1, 0, 1, 1, 2, 1};
    el_resample_result r0;
    ck_assert_int_eq(el_resample_equilateral(sq, 4, 0.3, &r0), EL_OK);
    const double sc[] = {0x1p-1000, 0x1p-1060, 0x1p1000};
    for (int s = 0; s < 3; s++) {
        double p[8];
        for (int i = 0; i < 8; i++) p[i] = sq[i] * sc[s];
        el_resample_result r;
        ck_assert_int_eq(el_resample_equilateral(p, 4, 0.3 * sc[s], &r), EL_OK);
        ck_assert_uint_eq(r.n, r0.n);
        for (size_t k = 0; k < 2 * r.n; k++)
            ck_assert_close(r.xy[k] / sc[s], r0.xy[k], s == 1 ? 1e-4 : 1e-15);   /* denormals: ~14 bits */
        el_resample_free(&r);
    }
    el_resample_free(&r0);
}
END_TEST

START_TEST(plane_fit_and_pca_extreme_magnitudes)
{
    double xyz[3 * 20], xy[2 * 20], rms;
    el_frame f;
    for (int i = 0; i < 20; i++) {   /* a tilted arc */
        xyz[3 * i] = cos(0.1 * i);
        xyz[3 * i + 1] = sin(0.1 * i);
        xyz[3 * i + 2] = 0.3 * cos(0.1 * i) + 0.01 * (i % 3);
    }
    el_frame f0;
    double xy0[40], rms0;
    ck_assert_int_eq(el_plane_fit(xyz, 20, &f0, xy0, &rms0), EL_OK);
    const double sc[] = {0x1p-1000, 0x1p500, 0x1p-1050};
    for (int s = 0; s < 3; s++) {
        double p[60];
        for (int i = 0; i < 60; i++) p[i] = xyz[i] * sc[s];
        ck_assert_int_eq(el_plane_fit(p, 20, &f, xy, &rms), EL_OK);
        ck_assert(isfinite(rms) && isfinite(f.lambda[0]));
        for (int j = 0; j < 3; j++) ck_assert_close(f.e3[j], f0.e3[j], s == 2 ? 1e-3 : 1e-12);
        ck_assert_close(rms / sc[s], rms0, s == 2 ? 1e-2 : 1e-12);
    }
    double p[60];   /* a spread of 1e200: the eigenvalues (units^2) overflow */
    for (int i = 0; i < 60; i++) p[i] = xyz[i] * 1e200;
    memset(&f, 0x5a, sizeof f);
    ck_assert_int_eq(el_plane_fit(p, 20, &f, xy, &rms), EL_EDOM);
    ck_assert_int_eq(((unsigned char *)&f)[0], 0x5a);
    for (int i = 0; i < 60; i++) p[i] = (i % 2 ? -1.0 : 1.0) * DBL_MAX;   /* sums overflowed */
    ck_assert_int_eq(el_plane_fit(p, 20, &f, xy, &rms), EL_EDOM);
    for (int i = 0; i < 30; i++) { p[2 * i] = (i % 2 ? -1.0 : 1.0) * DBL_MAX; p[2 * i + 1] = i; }
    el_frame2d g;
    ck_assert_int_eq(el_pca_normalize(p, 30, &g, NULL), EL_EDOM);
}
END_TEST

START_TEST(find_inflection_extreme_scales)
{
    double xy[2 * 60];
    for (int i = 0; i < 60; i++) {   /* a cubic: one inflection */
        const double t = -1.0 + 2.0 * i / 59.0 + 0.1;
        xy[2 * i] = t;
        xy[2 * i + 1] = t * t * t - 0.5 * t;
    }
    el_inflection r0, r;
    ck_assert_int_eq(el_find_inflection(xy, 60, 0, &r0), EL_OK);
    const double sc[] = {1e-200, 1e200, 0x1p-1040};
    for (int s = 0; s < 3; s++) {
        double p[120];
        for (int i = 0; i < 120; i++) p[i] = xy[i] * sc[s];
        ck_assert_int_eq(el_find_inflection(p, 60, 0, &r), EL_OK);
        if (s < 2) ck_assert_uint_eq(r.index, r0.index);
        else ck_assert(labs((long)r.index - (long)r0.index) <= 2);   /* denormals: coarse */
    }
}
END_TEST

/* ------------------------------------------------------------- small solves */

static int handler_calls;
static void count_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason; (void)file; (void)line; (void)gsl_errno;
    handler_calls++;
}

/* dense.c's LU and Cholesky: the solution of GSL's own solvers on regular matrices
 * (random, n = 1..9), EL_ESINGULAR on singular / indefinite ones (exact duplicate
 * rows, zero matrices, an indefinite symmetric matrix), and GSL's error handler never
 * called (a caller's may abort) */
START_TEST(small_solves_match_gsl_and_never_call_the_handler)
{
    gsl_error_handler_t *old = gsl_set_error_handler(count_handler);
    handler_calls = 0;
    unsigned seed = 7;
    for (size_t n = 1; n <= 9; n++)
        for (int rep = 0; rep < 20; rep++) {
            double M[81], A[81], S[81], b[9], x[9], y[9], ref[9];
            for (size_t i = 0; i < n * n; i++) M[i] = rand_r(&seed) / (double)RAND_MAX - 0.5;
            for (size_t i = 0; i < n; i++) b[i] = rand_r(&seed) / (double)RAND_MAX - 0.5;
            for (size_t i = 0; i < n; i++)        /* S = M^T M + I / 10: SPD */
                for (size_t j = 0; j < n; j++) {
                    double v = i == j ? 0.1 : 0.0;
                    for (size_t k = 0; k < n; k++) v += M[k * n + i] * M[k * n + j];
                    S[i * n + j] = v;
                }
            memcpy(A, M, sizeof(double) * n * n);
            memcpy(x, b, sizeof(double) * n);
            int perm[9];
            ck_assert_int_eq(el__lu_factor(A, (int)n, perm), EL_OK);
            el__lu_solve(A, (int)n, perm, x);
            memcpy(A, S, sizeof(double) * n * n);
            memcpy(y, b, sizeof(double) * n);
            ck_assert_int_eq(el__cholesky_solve(A, (int)n, y), EL_OK);
            /* references: GSL's LU and Cholesky on copies */
            gsl_matrix_view Mv = gsl_matrix_view_array(M, n, n), Sv = gsl_matrix_view_array(S, n, n);
            gsl_vector_view bv = gsl_vector_view_array(b, n), rv = gsl_vector_view_array(ref, n);
            gsl_permutation *p = gsl_permutation_alloc(n);
            int sg;
            ck_assert_int_eq(gsl_linalg_LU_decomp(&Mv.matrix, p, &sg), 0);
            ck_assert_int_eq(gsl_linalg_LU_solve(&Mv.matrix, p, &bv.vector, &rv.vector), 0);
            for (size_t i = 0; i < n; i++) ck_assert_close(x[i], ref[i], 1e-9 * (1.0 + fabs(ref[i])));
            ck_assert_int_eq(gsl_linalg_cholesky_decomp1(&Sv.matrix), 0);
            ck_assert_int_eq(gsl_linalg_cholesky_solve(&Sv.matrix, &bv.vector, &rv.vector), 0);
            for (size_t i = 0; i < n; i++) ck_assert_close(y[i], ref[i], 1e-9 * (1.0 + fabs(ref[i])));
            gsl_permutation_free(p);
        }
    double dup[9] = {1, 2, 3, 1, 2, 3, 0, 1, 5}, zero[4] = {0}, ones[4] = {1, 1, 1, 1};
    double indef[4] = {1, 2, 2, 1}, rhs[3] = {1, 2, 3};
    int perm[3];
    ck_assert_int_eq(el__lu_factor(dup, 3, perm), EL_ESINGULAR);
    ck_assert_int_eq(el__lu_factor(zero, 2, perm), EL_ESINGULAR);
    memset(zero, 0, sizeof zero);
    ck_assert_int_eq(el__cholesky_solve(zero, 2, rhs), EL_ESINGULAR);
    ck_assert_int_eq(el__cholesky_solve(ones, 2, rhs), EL_ESINGULAR);    /* pivot exactly 0 */
    ck_assert_int_eq(el__cholesky_solve(indef, 2, rhs), EL_ESINGULAR);
    ck_assert_int_eq(handler_calls, 0);
    gsl_set_error_handler(old);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("robust");
    TCase *tc = tcase_create("robust");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, affine_polyline_huge_n_refused_without_overflow);
    tcase_add_test(tc, affine_elements_nd_coincident_points_give_zero_not_nan);
    tcase_add_test(tc, affine_elements_nd_extreme_scales);
    tcase_add_test(tc, affine_planar_functions_refuse_values_beyond_double_range);
    tcase_add_test(tc, lane_riesenfeld_near_dbl_max_does_not_overflow);
    tcase_add_test(tc, bspline_alloc_refuses_sizes_that_wrap);
    tcase_add_test(tc, bspline_check_degree_int_max_without_overflow);
    tcase_add_test(tc, bspline_curvature_large_derivatives_stay_finite);
    tcase_add_test(tc, smooth_to_bspline_bounded_work_refused_at_once);
    tcase_add_test(tc, smooth_to_bspline_emaxiter_returns_the_best_spline);
    tcase_add_test(tc, interpolate_c2_tiny_and_huge_scales);
    tcase_add_test(tc, interpolate_c2_huge_coordinates_edom);
    tcase_add_test(tc, elliptic_blend_refuses_the_k2_neighbourhood);
    tcase_add_test(tc, blend_basis_min_and_convex_hull_reported);
    tcase_add_test(tc, blend_values_beyond_double_range_edom);
    tcase_add_test(tc, resample_long_segment_small_r_is_not_truncated);
    tcase_add_test(tc, resample_past_the_vertex_limit_refused_at_once);
    tcase_add_test(tc, resample_extreme_scales_scale_invariant);
    tcase_add_test(tc, plane_fit_and_pca_extreme_magnitudes);
    tcase_add_test(tc, find_inflection_extreme_scales);
    tcase_add_test(tc, small_solves_match_gsl_and_never_call_the_handler);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
