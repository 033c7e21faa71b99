/* Blending-function curves (seed 003): every property checked by its defining
 * identity — conditions (2.14)-(2.15), end tangents (2.8)/(2.11), Eck's
 * Omega_i (2.4) and relations (2.6)/(2.7), the rope example (2.16)-(2.19),
 * derivatives by finite differences, bad input. */
#include "testutil.h"
#include <stdio.h>
#include <string.h>
#include <gsl/gsl_sf_ellint.h>

enum { NT = 201 };

static void grid(double *t, int n)
{
    for (int i = 0; i < n; i++) t[i] = (double)i / (double)(n - 1);
}

/* A few bases: elliptic (modulus k) and MQ, several d. */
typedef struct { int kind; double p, d; } case_t;
static const case_t CASES[] = {
    {EL_BLEND_ELLIPTIC, 0.0, 2.0}, {EL_BLEND_ELLIPTIC, 0.3, 0.5}, {EL_BLEND_ELLIPTIC, 0.5477225575051661, 2.0},
    {EL_BLEND_ELLIPTIC, 0.7, 3.0}, {EL_BLEND_ELLIPTIC, 0.9, 7.0}, {EL_BLEND_ELLIPTIC, 0.99, 1.0},
    {EL_BLEND_MQ, 0.5, 0.5}, {EL_BLEND_MQ, 1.0, 3.0}, {EL_BLEND_MQ, 2.0, 1.5}, {EL_BLEND_MQ, -1.0, 0.5},
};
enum { NCASES = sizeof CASES / sizeof *CASES };

static void init_case(int i, el_blend_basis *b)
{
    const case_t *c = &CASES[i];
    int st = c->kind == EL_BLEND_MQ ? el_blend_init_mq(b, c->p, c->d) : el_blend_init_elliptic(b, c->p, c->d);
    ck_assert_int_eq(st, EL_OK);
}

START_TEST(partition_of_unity_and_end_conditions)
{
    el_blend_basis b;
    init_case(_i, &b);
    const double d = CASES[_i].d;
    double t[NT], h[4 * NT], dh[4 * NT];
    grid(t, NT);
    ck_assert_int_eq(el_blend_basis_eval(&b, NT, t, h, dh, NULL), EL_OK);
    for (int i = 0; i < NT; i++) {
        ck_assert_close(h[4 * i] + h[4 * i + 1] + h[4 * i + 2] + h[4 * i + 3], 1.0, 1e-14);
        ck_assert_close(dh[4 * i] + dh[4 * i + 1] + dh[4 * i + 2] + dh[4 * i + 3], 0.0, 1e-13 * (1 + d));
        /* symmetry h_2(t) = h_1(1-t), h_3(t) = h_0(1-t); the grid is symmetric */
        const int r = NT - 1 - i;
        ck_assert_close(h[4 * i + 2], h[4 * r + 1], 1e-14);
        ck_assert_close(h[4 * i + 3], h[4 * r + 0], 1e-14);
    }
    /* (2.14): h_0(0) = 1, h_0(1) = 0, h_0'(1) = 0, h_0'(0) = -d; h_1(0) = h_1(1) = h_1'(1) = 0 */
    const double *h0 = h, *h1 = h + 4 * (NT - 1), *g0 = dh, *g1 = dh + 4 * (NT - 1);
    ck_assert_close(h0[0], 1.0, 1e-14);
    ck_assert_close(h1[0], 0.0, 1e-14);
    ck_assert_close(g1[0], 0.0, 1e-14 * (1 + d));
    ck_assert_close(g0[0], -d, 1e-14 * (1 + d));
    ck_assert_close(h0[1], 0.0, 1e-14);
    ck_assert_close(h1[1], 0.0, 1e-14);
    ck_assert_close(g1[1], 0.0, 1e-14 * (1 + d));
    ck_assert_close(g0[1], d, 1e-14 * (1 + d));
    /* hence h_2, h_3 vanish with their derivative at t = 0 and h_0, h_1 at t = 1 */
    ck_assert_close(h0[2], 0.0, 1e-14);
    ck_assert_close(h0[3], 0.0, 1e-14);
    ck_assert_close(g0[2], 0.0, 1e-14 * (1 + d));
    ck_assert_close(g0[3], 0.0, 1e-14 * (1 + d));
    ck_assert_close(h1[3], 1.0, 1e-14);
}
END_TEST

START_TEST(derivatives_match_finite_differences)
{
    el_blend_basis b;
    init_case(_i, &b);
    double t[9] = {0.0, 0.05, 0.2, 0.37, 0.5, 0.61, 0.8, 0.97, 1.0};
    double h[36], dh[36], d2h[36], f[36], df[36], d2f[36];
    ck_assert_int_eq(el_blend_basis_eval(&b, 9, t, h, dh, d2h), EL_OK);
    ck_assert_int_eq(el_blend_span_eval(&b, 9, t, f, df, d2f), EL_OK);
    const double e = 1e-5;
    for (int i = 0; i < 9; i++) {
        double tp = t[i] + e, tm = t[i] - e, hp[4], hm[4], dp[4], dm[4], fp[4], fm[4];
        el_blend_basis_eval(&b, 1, &tp, hp, dp, NULL);
        el_blend_basis_eval(&b, 1, &tm, hm, dm, NULL);
        el_blend_span_eval(&b, 1, &tp, fp, NULL, NULL);
        el_blend_span_eval(&b, 1, &tm, fm, NULL, NULL);
        for (int j = 0; j < 4; j++) {
            double s = 1 + fabs(dh[4 * i + j]) + fabs(d2h[4 * i + j]);
            ck_assert_close(dh[4 * i + j], (hp[j] - hm[j]) / (2 * e), 1e-7 * s);
            ck_assert_close(d2h[4 * i + j], (dp[j] - dm[j]) / (2 * e), 1e-6 * s);
            ck_assert_close(df[4 * i + j], (fp[j] - fm[j]) / (2 * e), 1e-7 * (1 + fabs(d2f[4 * i + j])));
            /* h = M f (the sum has cancellation for the MQ span: bound its rounding) */
            double hf = 0.0, mag = 0.0;
            for (int l = 0; l < 4; l++) {
                hf += b.M[4 * j + l] * f[4 * i + l];
                mag += fabs(b.M[4 * j + l] * f[4 * i + l]);
            }
            ck_assert_close(h[4 * i + j], hf, 1e-15 + 4e-16 * mag);
        }
    }
}
END_TEST

START_TEST(end_tangents_along_control_legs)
{
    el_blend_basis b;
    init_case(_i, &b);
    unsigned long long rng = 88172645463325252ULL + (unsigned long long)_i;
    for (int trial = 0; trial < 5; trial++) {
        double q[8], t[2] = {0.0, 1.0}, xy[4], dxy[4];
        for (int j = 0; j < 8; j++) q[j] = test_uniform(&rng, -3, 3);
        ck_assert_int_eq(el_blend_eval(&b, q, 2, t, xy, dxy), EL_OK);
        for (int c = 0; c < 2; c++) {
            ck_assert_close(xy[c], q[c], 1e-13);
            ck_assert_close(xy[2 + c], q[6 + c], 1e-13);
            /* (2.8)/(2.11): phi'(0) = d (q_1 - q_0), phi'(1) = d (q_3 - q_2) */
            ck_assert_close(dxy[c], b.d * (q[2 + c] - q[c]), 1e-12 * (1 + b.d));
            ck_assert_close(dxy[2 + c], b.d * (q[6 + c] - q[4 + c]), 1e-12 * (1 + b.d));
        }
    }
}
END_TEST

/* (2.5) directly. */
static void eck_aux(double c, double *s, double *alpha, double *beta)
{
    *s = sqrt(c * c + 1);
    *beta = *s / (*s + c);
    *alpha = c * *s / (2 * c * c + 1 + c * *s);
}

START_TEST(eck_omega_reproduced_at_eck_d)
{
    const double cs[] = {0.25, 0.5, 1.0, 2.0, 3.0};
    const double c = cs[_i];
    double s, alpha, beta, d;
    eck_aux(c, &s, &alpha, &beta);
    ck_assert_int_eq(el_blend_eck_d(c, &d), EL_OK);
    ck_assert_close(d, 1.0 / alpha, 1e-14 * d);
    /* the paper's d formula below Figure 1 */
    ck_assert_close(d, (c * (s + 2 * c) + 1) / (c * s), 1e-14 * d);
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_mq(&b, c, d), EL_OK);
    double t[NT], h[4 * NT], om[4 * NT];
    grid(t, NT);
    ck_assert_int_eq(el_blend_basis_eval(&b, NT, t, h, NULL, NULL), EL_OK);
    ck_assert_int_eq(el_blend_eck_omega(c, NT, t, om), EL_OK);
    /* both are differences of O(|coefficients|) terms: compare relative to them */
    double scale = 0.0;
    for (int j = 0; j < 16; j++) scale += fabs(b.M[j]);
    for (int i = 0; i < 4 * NT; i++) ck_assert_close(h[i], om[i], 1e-15 * scale * (1 + s));
    /* Omega_3 = t - alpha Omega_1 + (alpha - 1) Omega_2 (2.4): linear precision */
    for (int i = 0; i < NT; i++)
        ck_assert_close(h[4 * i + 3], t[i] - alpha * h[4 * i + 1] + (alpha - 1) * h[4 * i + 2],
                        1e-15 * scale * (1 + s));
    /* (2.6): b = T a, i.e. T = (M^T)^-1: T M^T = I */
    const double T[16] = {1, s, c, 0,
                          1 - alpha, s - alpha / s, c, alpha,
                          alpha, c, s - alpha / s, 1 - alpha,
                          0, c, s, 1};
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < 4; j++) {
            double v = 0.0;
            for (int l = 0; l < 4; l++) v += T[4 * i + l] * b.M[4 * j + l];
            ck_assert_close(v, i == j ? 1.0 : 0.0, 1e-13 * scale);
        }
    /* (2.7): b_1 = phi(1) + (alpha-1) phi'(1) + alpha beta phi''(1), b_2 mirrored */
    unsigned long long rng = 0x9E3779B97F4A7C15ULL;
    for (int trial = 0; trial < 4; trial++) {
        double q[4], e[2] = {0.0, 1.0}, hh[8], dd[8], d2[8];
        for (int j = 0; j < 4; j++) q[j] = test_uniform(&rng, -1, 1);
        ck_assert_int_eq(el_blend_basis_eval(&b, 2, e, hh, dd, d2), EL_OK);
        double v[2] = {0, 0}, v1[2] = {0, 0}, v2[2] = {0, 0};
        for (int r = 0; r < 2; r++)
            for (int j = 0; j < 4; j++) {
                v[r] += q[j] * hh[4 * r + j];
                v1[r] += q[j] * dd[4 * r + j];
                v2[r] += q[j] * d2[4 * r + j];
            }
        ck_assert_close(q[1], v[1] + (alpha - 1) * v1[1] + alpha * beta * v2[1], 1e-13 * scale);
        ck_assert_close(q[2], v[0] + (1 - alpha) * v1[0] + alpha * beta * v2[0], 1e-13 * scale);
        ck_assert_close(q[1], v[0] + alpha * v1[0], 1e-13 * scale);
        ck_assert_close(q[2], v[1] - alpha * v1[1], 1e-13 * scale);
    }
}
END_TEST

START_TEST(figure1_shapes)
{
    /* Figure 1: (c, d) = (1, 1/2) and (1, 3). Defining conditions, then the shape
     * of a Bernstein-like basis: all four nonnegative on [0, 1], h_0 decreasing,
     * h_3 increasing, h_1 with a single interior maximum; larger d pulls the
     * interior functions up near the ends: h_1'(0) = d. */
    const double ds[2] = {0.5, 3.0};
    double t[NT], h[2][4 * NT], dh[4 * NT];
    grid(t, NT);
    for (int c = 0; c < 2; c++) {
        el_blend_basis b;
        ck_assert_int_eq(el_blend_init_mq(&b, 1.0, ds[c]), EL_OK);
        ck_assert_int_eq(el_blend_basis_eval(&b, NT, t, h[c], dh, NULL), EL_OK);
        ck_assert_close(dh[1], ds[c], 1e-13);
        ck_assert_close(dh[0], -ds[c], 1e-13);
        int peaks = 0;
        for (int i = 0; i < NT; i++) {
            for (int j = 0; j < 4; j++) ck_assert(h[c][4 * i + j] >= -1e-15);
            if (i > 0) {
                ck_assert(h[c][4 * i] < h[c][4 * (i - 1)]);
                ck_assert(h[c][4 * i + 3] > h[c][4 * (i - 1) + 3]);
            }
            if (i > 0 && i < NT - 1 && h[c][4 * i + 1] > h[c][4 * (i - 1) + 1] &&
                h[c][4 * i + 1] >= h[c][4 * (i + 1) + 1])
                peaks++;
        }
        ck_assert_int_eq(peaks, 1);
    }
    /* near t = 0: h_1 ~ d t, so the d = 3 function lies above the d = 1/2 one */
    ck_assert(h[1][4 * 1 + 1] > h[0][4 * 1 + 1]);
}
END_TEST

START_TEST(rope_example)
{
    /* (2.16): C(t) = (t, sn(Kt)) = p_0 (1-t) + p_1 sn((1-t)K) + p_2 sn(Kt) + p_3 t */
    const double p[8] = {0, 0, 0, 0, 0, 1, 1, 0};
    /* The paper's 'k = 0.3' is the parameter m = k^2: modulus sqrt(0.3). */
    const double k = sqrt(0.3), d = 2.0;
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, k, d), EL_OK);
    double q[8];
    ck_assert_int_eq(el_blend_control_points(&b, p, q), EL_OK);
    const double printed[8] = {0, 0, 0.5, 0.856945, 0.5, 1, 1, 1};
    for (int j = 0; j < 8; j++) ck_assert_close(q[j], printed[j], 5e-7);
    /* exactly: q_1 = q_0 + C'(0)/d = (1/d, K/d), q_2 = q_3 - C'(1)/d = (1 - 1/d, 1) */
    ck_assert_close(q[3], b.K / d, 1e-14);
    ck_assert_close(b.K, gsl_sf_ellint_Kcomp(k, GSL_PREC_DOUBLE), 1e-15);
    double t[NT], xy[2 * NT];
    grid(t, NT);
    ck_assert_int_eq(el_blend_eval(&b, q, NT, t, xy, NULL), EL_OK);
    for (int i = 0; i < NT; i++) {
        el_jacobi v;
        ck_assert_int_eq(el_jacobi_eval(b.K * t[i], k, &v, NULL, NULL), EL_OK);
        ck_assert_close(xy[2 * i], t[i], 1e-14);
        ck_assert_close(xy[2 * i + 1], v.sn, 1e-14);
    }
    /* round trip p = q M (2.18) */
    double p2[8];
    ck_assert_int_eq(el_blend_coefficients(&b, q, p2), EL_OK);
    for (int j = 0; j < 8; j++) ck_assert_close(p2[j], p[j], 1e-14);
    /* with modulus 0.3 the printed 0.856945 is not reproduced: K(0.3)/2 = 0.804 */
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.3, d), EL_OK);
    ck_assert_int_eq(el_blend_control_points(&b, p, q), EL_OK);
    ck_assert(fabs(q[3] - 0.856945) > 0.05);
}
END_TEST

/* Modulus where K(k) = 2 (bisection on GSL's K). */
static double k_where_K_is_2(void)
{
    double lo = 0.5, hi = 0.95;
    for (int i = 0; i < 200; i++) {
        double mid = 0.5 * (lo + hi);
        if (gsl_sf_ellint_Kcomp(mid, GSL_PREC_DOUBLE) < 2.0) lo = mid; else hi = mid;
    }
    return 0.5 * (lo + hi);
}

START_TEST(bad_input)
{
    el_blend_basis b, keep;
    memset(&b, 0x5a, sizeof b);
    memcpy(&keep, &b, sizeof b);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 1.0, 2.0), EL_EDOM);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 1.5, 2.0), EL_EDOM);
    ck_assert_int_eq(el_blend_init_elliptic(&b, -0.1, 2.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_elliptic(&b, NAN, 2.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 0.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, -1.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, INFINITY), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_elliptic(NULL, 0.5, 2.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_mq(&b, 0.0, 2.0), EL_EDOM);
    ck_assert_int_eq(el_blend_init_mq(&b, 1.0, 0.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_init_mq(&b, 1.0, -3.0), EL_EINVAL);
    ck_assert_int_eq(el_blend_eck_d(0.0, &b.d), EL_EDOM);
    /* singular system: K(k) = 2, where a_1 = (K - d)/(K (2 - K)) has no value */
    const double ks = k_where_K_is_2();
    ck_assert_int_eq(el_blend_init_elliptic(&b, ks, 2.0), EL_ESINGULAR);
    ck_assert_int_eq(el_blend_init_elliptic(&b, ks, 0.7), EL_ESINGULAR);
    ck_assert(memcmp(&b, &keep, sizeof b) == 0);
    /* away from it the condition number is moderate */
    ck_assert_int_eq(el_blend_init_elliptic(&b, ks - 0.05, 2.0), EL_OK);
    ck_assert(b.cond < 1e4);
    /* evaluation: NaN t, NULL */
    double t[2] = {0.5, NAN}, h[8], q[8] = {0, 0, 1, 0, 2, 1, 3, 0}, xy[4];
    ck_assert_int_eq(el_blend_basis_eval(&b, 2, t, h, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_blend_eval(&b, q, 2, t, xy, NULL), EL_EINVAL);
    ck_assert_int_eq(el_blend_eval(NULL, q, 1, t, xy, NULL), EL_EINVAL);
    ck_assert_int_eq(el_blend_from_points(&b, q, 7, xy), EL_EINVAL);
    /* coincident picked points */
    double pts[8] = {0, 0, 1, 1, 1, 1, 2, 0}, out[8];
    ck_assert_int_eq(el_blend_from_points(&b, pts, EL_BLEND_PICK_INTERPOLATE, out), EL_ESINGULAR);
    el_bspline bs;
    memset(&bs, 0, sizeof bs);
    ck_assert_int_eq(el_blend_to_bspline(&b, 1, q, 0.0, &bs), EL_EINVAL);
    ck_assert_int_eq(el_blend_to_bspline(&b, 0, q, 1e-6, &bs), EL_EINVAL);
}
END_TEST

START_TEST(from_points_interpolates_at_chord_parameters)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.6, 2.5), EL_OK);
    const double pts[8] = {0, 0, 1, 2, 3, 2.5, 4, 0};
    double q[8], tt[4] = {0, 0, 0, 1}, xy[8];
    ck_assert_int_eq(el_blend_from_points(&b, pts, EL_BLEND_PICK_INTERPOLATE, q), EL_OK);
    double L = 0;
    for (int i = 1; i < 4; i++) {
        L += hypot(pts[2 * i] - pts[2 * i - 2], pts[2 * i + 1] - pts[2 * i - 1]);
        if (i < 3) tt[i] = L;
    }
    tt[1] /= L;
    tt[2] /= L;
    ck_assert_int_eq(el_blend_eval(&b, q, 4, tt, xy, NULL), EL_OK);
    for (int j = 0; j < 8; j++) ck_assert_close(xy[j], pts[j], 1e-12);
    ck_assert_int_eq(el_blend_from_points(&b, pts, EL_BLEND_PICK_CONTROL, q), EL_OK);
    for (int j = 0; j < 8; j++) ck_assert_close(q[j], pts[j], 0.0);
}
END_TEST

START_TEST(composite_is_c1_through_the_points)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 2.0), EL_OK);
    enum { NP = 5 };
    const double pts[2 * NP] = {0, 0, 1, 1, 2.5, 0.5, 3, -1, 4.5, 0};
    double q[6 * NP - 4];
    ck_assert_int_eq(el_blend_composite_through(&b, NP, pts, q), EL_OK);
    for (int i = 0; i < NP; i++) {
        const double e = 1e-9;
        double t[3] = {i - e, (double)i, i + e}, xy[6], dxy[6];
        ck_assert_int_eq(el_blend_composite_eval(&b, NP - 1, q, 3, t, xy, dxy), EL_OK);
        ck_assert_close(xy[2], pts[2 * i], 1e-13);
        ck_assert_close(xy[3], pts[2 * i + 1], 1e-13);
        for (int c = 0; c < 2; c++) {
            ck_assert_close(xy[c], xy[4 + c], 1e-8);    /* C0 */
            ck_assert_close(dxy[c], dxy[4 + c], 1e-7);  /* C1 */
        }
        if (i > 0 && i < NP - 1) /* G1: q_{3i-1}, q_{3i}, q_{3i+1} collinear */
            ck_assert_close((q[6 * i - 2] - q[6 * i]) * (q[6 * i + 3] - q[6 * i + 1]),
                            (q[6 * i - 1] - q[6 * i + 1]) * (q[6 * i + 2] - q[6 * i]), 1e-13);
    }
}
END_TEST

/* Closed: the seam at P_0 is a joint like the others, C1 in the global parameter
 * (the open composite through the same points with P_0 repeated has a corner there:
 * 53.1 deg on a square). */
START_TEST(closed_composite_is_c1_at_the_seam)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, sqrt(0.3), 2.0), EL_OK);
    enum { NP = 4 };
    const double pts[2 * NP + 2] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};
    double q[6 * NP + 2], qo[6 * (NP + 1) - 4];
    ck_assert_int_eq(el_blend_composite_closed(&b, NP, pts, q), EL_OK);
    ck_assert_int_eq(el_blend_composite_closed(&b, 2, pts, q), EL_EINVAL);
    ck_assert_int_eq(el_blend_composite_closed(&b, NP, pts, q), EL_OK);
    const double e = 1e-9, ends[2] = {0.0, NP};
    double xy[4], dxy[4];
    ck_assert_int_eq(el_blend_composite_eval(&b, NP, q, 2, ends, xy, dxy), EL_OK);
    for (int c = 0; c < 2; c++) {
        ck_assert_close(xy[c], xy[2 + c], 0.0);      /* closed: ends at P_0 */
        ck_assert_close(dxy[c], dxy[2 + c], 1e-13);  /* C1 at the seam */
    }
    for (int i = 1; i < NP; i++) {
        double t[3] = {i - e, (double)i, i + e}, p3[6], d3[6];
        ck_assert_int_eq(el_blend_composite_eval(&b, NP, q, 3, t, p3, d3), EL_OK);
        ck_assert_close(p3[2], pts[2 * i], 1e-13);
        ck_assert_close(p3[3], pts[2 * i + 1], 1e-13);
        for (int c = 0; c < 2; c++) ck_assert_close(d3[c], d3[4 + c], 1e-7);
    }
    /* the open one through P_0..P_3, P_0 has the corner */
    ck_assert_int_eq(el_blend_composite_through(&b, NP + 1, pts, qo), EL_OK);
    ck_assert_int_eq(el_blend_composite_eval(&b, NP, qo, 2, ends, xy, dxy), EL_OK);
    const double turn = atan2(dxy[0] * dxy[3] - dxy[1] * dxy[2], dxy[0] * dxy[2] + dxy[1] * dxy[3]);
    ck_assert_close(fabs(turn) * 180.0 / M_PI, 53.13, 0.01);
}
END_TEST

/* Independent clamped B-spline evaluation (de Boor's algorithm on the flat knots). */
static void deboor(const el_bspline *s, const double *u, double x, double out[2])
{
    const int p = s->degree;
    size_t l = (size_t)p;
    while (l + 1 < s->npoles && u[l + 1] <= x) l++;
    double d[8][2];
    for (int j = 0; j <= p; j++)
        for (int c = 0; c < 2; c++) d[j][c] = s->poles[2 * (l - (size_t)p + (size_t)j) + c];
    for (int r = 1; r <= p; r++)
        for (int j = p; j >= r; j--) {
            size_t i = l - (size_t)p + (size_t)j;
            double a = (x - u[i]) / (u[i + (size_t)p + 1 - (size_t)r] - u[i]);
            for (int c = 0; c < 2; c++) d[j][c] = (1 - a) * d[j - 1][c] + a * d[j][c];
        }
    out[0] = d[p][0];
    out[1] = d[p][1];
}

START_TEST(to_bspline_within_tolerance)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, sqrt(0.3), 2.0), EL_OK);
    const double p[8] = {0, 0, 0, 0, 0, 1, 1, 0};
    double q[8];
    ck_assert_int_eq(el_blend_control_points(&b, p, q), EL_OK);
    const double tols[2] = {1e-4, 1e-8};
    for (int k = 0; k < 2; k++) {
        el_bspline s;
        memset(&s, 0, sizeof s);
        ck_assert_int_eq(el_blend_to_bspline(&b, 1, q, tols[k], &s), EL_OK);
        ck_assert_int_eq(s.degree, 3);
        ck_assert_int_eq(el_bspline_check(&s), EL_OK);
        ck_assert(s.max_deviation >= 0 && s.max_deviation <= tols[k]);
        size_t total = 0;
        for (size_t i = 0; i < s.nknots; i++) total += (size_t)s.mults[i];
        ck_assert_uint_eq(total, s.npoles + 4);
        double *u = malloc(total * sizeof *u);
        size_t m = 0;
        for (size_t i = 0; i < s.nknots; i++)
            for (int r = 0; r < s.mults[i]; r++) u[m++] = s.knots[i];
        /* independent check on a grid finer than the fitter's */
        double worst = 0;
        for (int i = 0; i <= 3000; i++) {
            double t = i / 3000.0, xy[2], bb[2];
            el_blend_eval(&b, q, 1, &t, xy, NULL);
            deboor(&s, u, t, bb);
            double e = hypot(xy[0] - bb[0], xy[1] - bb[1]);
            if (e > worst) worst = e;
        }
        ck_assert_msg(worst <= s.max_deviation * (1 + 1e-6) + 1e-15, "worst %g > certified %g",
                      worst, s.max_deviation);
        printf("blend to_bspline tol %g: %zu poles, certified %.3g, sampled %.3g\n", tols[k],
               s.npoles, s.max_deviation, worst);
        free(u);
        el_bspline_free(&s);
    }
}
END_TEST

START_TEST(composite_to_bspline_and_noconv)
{
    el_blend_basis b;
    ck_assert_int_eq(el_blend_init_elliptic(&b, 0.5, 2.0), EL_OK);
    enum { NP = 4 };
    const double pts[2 * NP] = {0, 0, 1, 1, 2, 0, 3, 1};
    double q[6 * NP - 4];
    ck_assert_int_eq(el_blend_composite_through(&b, NP, pts, q), EL_OK);
    el_bspline s;
    memset(&s, 0, sizeof s);
    const double tol = 1e-6;
    ck_assert_int_eq(el_blend_to_bspline(&b, NP - 1, q, tol, &s), EL_OK);
    ck_assert(s.max_deviation <= tol);
    ck_assert_int_eq(el_bspline_check(&s), EL_OK);
    size_t total = 0;
    for (size_t i = 0; i < s.nknots; i++) {
        total += (size_t)s.mults[i];
        if (s.knots[i] == 1.0 || s.knots[i] == 2.0) ck_assert_int_eq(s.mults[i], 3);
    }
    ck_assert_uint_eq(total, s.npoles + 4);
    ck_assert_close(s.knots[s.nknots - 1], NP - 1, 0.0);
    double *u = malloc(total * sizeof *u);
    size_t m = 0;
    for (size_t i = 0; i < s.nknots; i++)
        for (int r = 0; r < s.mults[i]; r++) u[m++] = s.knots[i];
    for (int i = 0; i <= 3000; i++) {
        double t = (NP - 1) * i / 3000.0, xy[2], bb[2];
        el_blend_composite_eval(&b, NP - 1, q, 1, &t, xy, NULL);
        deboor(&s, u, t, bb);
        ck_assert(hypot(xy[0] - bb[0], xy[1] - bb[1]) <= tol);
    }
    free(u);
    el_bspline_free(&s);
    /* below what the coordinates resolve: EL_EDOM at once, out untouched */
    memset(&s, 0x5a, sizeof s);
    ck_assert_int_eq(el_blend_to_bspline(&b, 1, q, 1e-300, &s), EL_EDOM);
    ck_assert_int_eq(el_blend_to_bspline(&b, 1, q, 1e-14, &s), EL_EDOM);
    ck_assert_int_eq(((unsigned char *)&s)[0], 0x5a);
    /* resolvable but not reached with 256 spans: EL_ENOCONV with the best spline */
    ck_assert_int_eq(el_blend_to_bspline(&b, 1, q, 1e-12, &s), EL_ENOCONV);
    ck_assert(s.npoles > 4 && s.max_deviation > 1e-12 && s.max_deviation < 1e-10);
    el_bspline_free(&s);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("blend");
    TCase *tc = tcase_create("blend");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, partition_of_unity_and_end_conditions, 0, NCASES);
    tcase_add_loop_test(tc, derivatives_match_finite_differences, 0, NCASES);
    tcase_add_loop_test(tc, end_tangents_along_control_legs, 0, NCASES);
    tcase_add_loop_test(tc, eck_omega_reproduced_at_eck_d, 0, 5);
    tcase_add_test(tc, figure1_shapes);
    tcase_add_test(tc, rope_example);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, from_points_interpolates_at_chord_parameters);
    tcase_add_test(tc, composite_is_c1_through_the_points);
    tcase_add_test(tc, closed_composite_is_c1_at_the_seam);
    tcase_add_test(tc, to_bspline_within_tolerance);
    tcase_add_test(tc, composite_to_bspline_and_noconv);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
