/* Tests of libelastica/affine.c and affine_polyline.c (seed 002): every formula against its defining identity. */
#include "testutil.h"
#include <string.h>

static double det2(const double *a, const double *b) { return a[0] * b[1] - a[1] * b[0]; }

/* An affine arc-length polyline with prescribed k_i: v_{i+1} = (2 - k_i) v_i - v_{i-1}
 * (from (2) with A_i = A), so det(v_i, v_{i+1}) = det(v_{i-1}, v_i) = A. */
static void make_aal(size_t npts, const double *k, const double v0[2], const double v1[2], double *xy)
{
    double vm[2] = {v0[0], v0[1]}, v[2] = {v1[0], v1[1]};
    xy[0] = 0.3;
    xy[1] = -0.2;
    xy[2] = xy[0] + vm[0];
    xy[3] = xy[1] + vm[1];
    for (size_t i = 2; i < npts; i++) {
        xy[2 * i] = xy[2 * i - 2] + v[0];
        xy[2 * i + 1] = xy[2 * i - 1] + v[1];
        double kk = k[i - 1];
        double vn[2] = {(2.0 - kk) * v[0] - vm[0], (2.0 - kk) * v[1] - vm[1]};
        memcpy(vm, v, sizeof v);
        memcpy(v, vn, sizeof v);
    }
}

/* Minimal B-spline derivative by de Boor on the flat knot vector (test-local, independent of bspline.c):
 * derivative of order r at t in span [T[s], T[s+1]] (segment chosen by the caller). */
static void test_deriv(const el_bspline *b, size_t span, double t, int r, double *out)
{
    int p = b->degree;
    size_t d = (size_t)b->dim;
    double T[256];
    size_t nt = 0;
    for (size_t i = 0; i < b->nknots; i++)
        for (int m = 0; m < b->mults[i]; m++) T[nt++] = b->knots[i];
    double c[16][8];
    for (int i = 0; i <= p; i++)
        for (size_t k = 0; k < d; k++) c[i][k] = b->poles[(span - (size_t)p + (size_t)i) * d + k];
    /* derivative control points: r differencing steps on the local poles */
    for (int q = 1; q <= r; q++)
        for (int i = p; i >= q; i--) {
            size_t g = span - (size_t)p + (size_t)i;
            double den = T[g + (size_t)p + 1 - (size_t)q] - T[g];
            for (size_t k = 0; k < d; k++) c[i][k] = (double)(p - q + 1) * (c[i][k] - c[i - 1][k]) / den;
        }
    /* de Boor on the remaining degree p - r */
    for (int q = 1; q <= p - r; q++)
        for (int i = p; i >= r + q; i--) {
            size_t g = span - (size_t)p + (size_t)i;
            double den = T[g + (size_t)(p - r) + 1 - (size_t)q] - T[g];
            double a = (t - T[g]) / den;
            for (size_t k = 0; k < d; k++) c[i][k] = (1.0 - a) * c[i - 1][k] + a * c[i][k];
        }
    for (size_t k = 0; k < d; k++) out[k] = c[p][k];
}

START_TEST(test_coords_and_curvature)
{
    unsigned long long st = 42;
    enum { N = 9 };
    double xy[2 * N], A[N], B[N], k[N], L2;
    for (int i = 0; i < 2 * N; i++) xy[i] = test_uniform(&st, -1, 1);
    ck_assert_int_eq(el_affine_coords(N, xy, A, B), EL_OK);
    ck_assert_int_eq(el_affine_curvature(N, xy, k), EL_OK);
    ck_assert_int_eq(el_affine_length(N, xy, &L2), EL_OK);
    double sum = 0;
    for (int i = 1; i + 1 < N; i++) {
        double vm[2] = {xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]};
        double v[2] = {xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]};
        ck_assert_close(A[i - 1], det2(vm, v), 1e-15);
        sum += cbrt(A[i - 1]);
        if (i + 2 < N) {
            double vp[2] = {xy[2 * i + 4] - xy[2 * i + 2], xy[2 * i + 5] - xy[2 * i + 3]};
            ck_assert_close(B[i - 1], det2(vm, vp), 1e-15);
            double ni[2] = {v[0] - vm[0], v[1] - vm[1]}, ni1[2] = {vp[0] - v[0], vp[1] - v[1]};
            ck_assert_close(k[i - 1], det2(ni, ni1) / (0.5 * (A[i - 1] + det2(v, vp))), 1e-12);
        }
    }
    ck_assert_close(L2, sum, 1e-14);

    /* an affine arc-length polyline: (2), (4) and k = 2 - B/A */
    enum { M = 12 };
    double kk[M], p[2 * M], v0[2] = {1.0, 0.1}, v1[2] = {0.8, 0.6};
    for (int i = 0; i < M; i++) kk[i] = test_uniform(&st, -0.5, 1.5);
    make_aal(M, kk, v0, v1, p);
    double Ap[M], Bp[M], kp[M];
    ck_assert_int_eq(el_affine_coords(M, p, Ap, Bp), EL_OK);
    ck_assert_int_eq(el_affine_curvature(M, p, kp), EL_OK);
    for (int i = 1; i + 2 < M; i++) {
        ck_assert_close(Ap[i - 1], Ap[0], 1e-12);
        ck_assert_close(kp[i - 1], kk[i], 1e-11);
        ck_assert_close(kp[i - 1], 2.0 - Bp[i - 1] / Ap[0], 1e-11);
        for (int c = 0; c < 2; c++)   /* (4): x_{i+2} - x_{i-1} = (3 - k_i)(x_{i+1} - x_i) */
            ck_assert_close(p[2 * (i + 2) + c] - p[2 * (i - 1) + c],
                            (3.0 - kp[i - 1]) * (p[2 * (i + 1) + c] - p[2 * i + c]), 1e-11);
    }
}
END_TEST

/* Affinely regular polylines (orbits of an affine map) have constant k; on a conic with
 * non-regular spacing k alternates between two values (Theorem 1). */
START_TEST(test_theorem1)
{
    enum { N = 14 };
    double M[4] = {1.7, 0.4, -0.3, 0.6}, lam = 0.37, xy[2 * N], k[N];
    for (int conic = 0; conic < 2; conic++) {
        for (int j = 0; j < N; j++) {
            double c = conic ? cosh(lam * j) : cos(lam * j), s = conic ? sinh(lam * j) : sin(lam * j);
            xy[2 * j] = M[0] * c + M[1] * s + 0.2;
            xy[2 * j + 1] = M[2] * c + M[3] * s - 1.0;
        }
        ck_assert_int_eq(el_affine_curvature(N, xy, k), EL_OK);
        double kex = conic ? 2.0 - 2.0 * cosh(lam) : 2.0 - 2.0 * cos(lam);
        for (int i = 0; i < N - 3; i++) ck_assert_close(k[i], kex, 1e-10);
    }
    /* circle, angles 0, a, then each next vertex by det = A (bisection on the angle step) */
    double A = 0.02, th[N];
    th[0] = 0.0;
    th[1] = 0.31;   /* not the regular step */
    for (int i = 1; i + 1 < N; i++) {
        double a = th[i] - th[i - 1], lo = 1e-9, hi = 2.0;
        for (int it = 0; it < 200; it++) {
            double b = 0.5 * (lo + hi);
            double f = 4.0 * sin(0.5 * a) * sin(0.5 * b) * sin(0.5 * (a + b)) - A;
            if (f > 0) hi = b; else lo = b;
        }
        th[i + 1] = th[i] + 0.5 * (lo + hi);
    }
    for (int j = 0; j < N; j++) {
        xy[2 * j] = 2.0 * cos(th[j]);       /* an ellipse: affine image of the circle */
        xy[2 * j + 1] = 0.5 * sin(th[j]) + 0.3 * cos(th[j]);
    }
    double Av[N];
    ck_assert_int_eq(el_affine_coords(N, xy, Av, NULL), EL_OK);
    for (int i = 0; i < N - 2; i++) ck_assert_close(Av[i], Av[0], 1e-12);
    ck_assert_int_eq(el_affine_curvature(N, xy, k), EL_OK);
    for (int i = 1; i + 1 < N - 3; i++) ck_assert_close(k[i - 1], k[i + 1], 1e-8);
    ck_assert_msg(fabs(k[0] - k[1]) > 1e-3, "spacing not regular, k must alternate: %g %g", k[0], k[1]);
}
END_TEST

static double conic_q(const double *c, double x, double y)
{
    return c[0] * x * x + c[1] * x * y + c[2] * y * y + c[3] * x + c[4] * y + c[5];
}

/* smooth affine curvature of a central conic a x^2 + b xy + c y^2 + d x + e y + f = 0:
 * (X-xi)^T M (X-xi) = 1  ->  kappa = cbrt(det M) (circle radius r: r^(-4/3)). */
static void conic_center_kappa(const double *c, double *xi, double *kappa)
{
    double P[4] = {c[0], 0.5 * c[1], 0.5 * c[1], c[2]}, bb[2] = {0.5 * c[3], 0.5 * c[4]};
    double dP = P[0] * P[3] - P[1] * P[2];
    xi[0] = -(P[3] * bb[0] - P[1] * bb[1]) / dP;
    xi[1] = -(-P[2] * bb[0] + P[0] * bb[1]) / dP;
    double g = -(c[5] + bb[0] * xi[0] + bb[1] * xi[1]);  /* Q(xi) = c5 + b.xi */
    *kappa = cbrt(dP / (g * g));
}

START_TEST(test_osculating_conics)
{
    unsigned long long st = 7;
    enum { M = 10 };
    double kk[M], p[2 * M], v0[2] = {1.0, 0.0}, v1[2] = {0.7, 0.5};
    for (int i = 0; i < M; i++) kk[i] = (i % 3 == 0) ? test_uniform(&st, -1.0, -0.1) : test_uniform(&st, 0.1, 3.5);
    make_aal(M, kk, v0, v1, p);
    el_affine_conic co[M], ci[M], cm[M];
    ck_assert_int_eq(el_affine_osculating_conics(M, p, EL_CONIC_OUTER, co), EL_OK);
    ck_assert_int_eq(el_affine_osculating_conics(M, p, EL_CONIC_INNER, ci), EL_OK);
    ck_assert_int_eq(el_affine_osculating_conics(M, p, EL_CONIC_MIDDLE, cm), EL_OK);
    double A;
    ck_assert_int_eq(el_affine_coords(3, p, &A, NULL), EL_OK);
    for (int i = 1; i + 2 < M; i++) {
        const double *x = p + 2 * (i - 1);  /* x_{i-1}..x_{i+2} */
        double k = kk[i];
        ck_assert_int_eq(co[i - 1].type, k > 0 ? 1 : -1);
        for (int j = 0; j < 4; j++) ck_assert_close(conic_q(co[i - 1].coef, x[2 * j], x[2 * j + 1]), 0.0, 1e-10);
        for (int e = 0; e < 3; e++) {  /* inner: tangent to the edges at their midpoints */
            double mx = 0.5 * (x[2 * e] + x[2 * e + 2]), my = 0.5 * (x[2 * e + 1] + x[2 * e + 3]);
            double vx = x[2 * e + 2] - x[2 * e], vy = x[2 * e + 3] - x[2 * e + 1];
            const double *c = ci[i - 1].coef;
            ck_assert_close(conic_q(c, mx, my), 0.0, 1e-10);
            double gx = 2 * c[0] * mx + c[1] * my + c[3], gy = c[1] * mx + 2 * c[2] * my + c[4];
            ck_assert_close(gx * vx + gy * vy, 0.0, 1e-9);
        }
        /* all three have the evolute point (5) as centre, and the curvatures (7) */
        double xi[2], kap[3];
        const el_affine_conic *cs[3] = {&co[i - 1], &ci[i - 1], &cm[i - 1]};
        for (int t = 0; t < 3; t++) {
            conic_center_kappa(cs[t]->coef, xi, &kap[t]);
            ck_assert_close(xi[0], cs[t]->center[0], 1e-8 * (1 + fabs(xi[0])));
            ck_assert_close(xi[1], cs[t]->center[1], 1e-8 * (1 + fabs(xi[1])));
            ck_assert_close(kap[t], cs[t]->kappa, 1e-9 * fabs(kap[t]));
        }
        double a23 = cbrt(A) * cbrt(A);
        ck_assert_close(cm[i - 1].kappa, k / a23, 1e-9 * fabs(k / a23));
        ck_assert_close(co[i - 1].kappa, k / a23 * cbrt(1 - k / 4), 1e-9 * fabs(k / a23));
        ck_assert_close(ci[i - 1].kappa, k / a23 / cbrt(1 - k / 4), 1e-9 * fabs(k / a23));
        ck_assert_close(cm[i - 1].kappa * cm[i - 1].kappa, co[i - 1].kappa * ci[i - 1].kappa,
                        1e-9 * cm[i - 1].kappa * cm[i - 1].kappa);
        double ev[2] = {x[2] + (x[0] - 2 * x[2] + x[4]) / k, x[3] + (x[1] - 2 * x[3] + x[5]) / k};
        ck_assert_close(co[i - 1].center[0], ev[0], 1e-10 * (1 + fabs(ev[0])));
    }
    /* affinely regular polygon on a circle of radius r: the outer conic is that circle */
    enum { R = 8 };
    double r = 1.3, lam = 0.5, q[2 * R];
    for (int j = 0; j < R; j++) {
        q[2 * j] = r * cos(lam * j);
        q[2 * j + 1] = r * sin(lam * j);
    }
    ck_assert_int_eq(el_affine_osculating_conics(R, q, EL_CONIC_OUTER, co), EL_OK);
    ck_assert_close(co[2].kappa, pow(r, -4.0 / 3.0), 1e-12);
    ck_assert_close(co[2].center[0], 0.0, 1e-12);
    /* a parabola quadruple: k = 0, type 0 */
    double par[8] = {-1.5, 2.25, -0.5, 0.25, 0.5, 0.25, 1.5, 2.25};
    ck_assert_int_eq(el_affine_osculating_conics(4, par, EL_CONIC_OUTER, co), EL_OK);
    ck_assert_int_eq(co[0].type, 0);
    ck_assert_close(co[0].kappa, 0.0, 1e-15);
    for (int j = 0; j < 4; j++) ck_assert_close(conic_q(co[0].coef, par[2 * j], par[2 * j + 1]), 0.0, 1e-12);
    /* not equal-area -> EL_EDOM, outputs untouched */
    double bad[8] = {0, 0, 1, 0, 2, 1, 2, 3};
    co[0].kappa = 99.0;
    ck_assert_int_eq(el_affine_osculating_conics(4, bad, EL_CONIC_MIDDLE, co), EL_EDOM);
    ck_assert_close(co[0].kappa, 99.0, 0.0);
    ck_assert_int_eq(el_affine_osculating_conics(4, par, 7, co), EL_EINVAL);
}
END_TEST

START_TEST(test_chaikin_lane_riesenfeld)
{
    unsigned long long st = 99;
    enum { N = 11 };
    double xy[2 * N], out[4 * N], L0, L1;
    for (int i = 0; i < N; i++) {   /* a wiggly polyline with both turning senses */
        xy[2 * i] = i + test_uniform(&st, -0.3, 0.3);
        xy[2 * i + 1] = test_uniform(&st, -1, 1);
    }
    ck_assert_int_eq(el_affine_chaikin(N, xy, out), EL_OK);
    ck_assert_int_eq(el_affine_length(N, xy, &L0), EL_OK);
    ck_assert_int_eq(el_affine_length(2 * (N - 1), out, &L1), EL_OK);
    ck_assert_close(L1, L0, 1e-12);
    /* affine arc-length polyline: A' = A / 8 everywhere */
    double kk[N], p[2 * N], v0[2] = {1, 0}, v1[2] = {0.5, 0.5}, A[2 * N];
    for (int i = 0; i < N; i++) kk[i] = test_uniform(&st, 0.2, 1.0);
    make_aal(N, kk, v0, v1, p);
    ck_assert_int_eq(el_affine_chaikin(N, p, out), EL_OK);
    ck_assert_int_eq(el_affine_coords(2 * (N - 1), out, A, NULL), EL_OK);
    for (int i = 0; i < 2 * (N - 1) - 2; i++) ck_assert_close(A[i], 0.5 / 8.0, 1e-13);
    /* Lane–Riesenfeld of degree 2 is Chaikin */
    double lr[4 * N];
    ck_assert_int_eq(el_affine_lane_riesenfeld(2, 2, N, xy, lr), EL_OK);
    ck_assert_int_eq(el_affine_chaikin(N, xy, out), EL_OK);
    for (int i = 0; i < 4 * (N - 1); i++) ck_assert_close(lr[i], out[i], 1e-15);
    /* Theorem 5 in R^3 and R^4: each element gives two with 2^(-n(n+1)/2) of its det */
    for (int n = 3; n <= 4; n++) {
        enum { P = 9 };
        double x[4 * P], y[4 * 2 * P], D[P], Dp[2 * P], Ln, Lnp;
        for (int i = 0; i < n * P; i++) x[i] = test_uniform(&st, -1, 1);
        ck_assert_int_eq(el_affine_lane_riesenfeld(n, n, P, x, y), EL_OK);
        ck_assert_int_eq(el_affine_elements_nd(n, P, x, D, &Ln), EL_OK);
        ck_assert_int_eq(el_affine_elements_nd(n, 2 * P - n, y, Dp, &Lnp), EL_OK);
        double f = pow(2.0, -0.5 * n * (n + 1));
        for (int i = 0; i < P - n; i++) {
            ck_assert_close(Dp[2 * i], f * D[i], 1e-12);
            ck_assert_close(Dp[2 * i + 1], f * D[i], 1e-12);
        }
        ck_assert_close(Lnp, Ln, 1e-12);   /* L_n halves per element (10), total kept */
    }
    /* in R^2 the elements are the A_i */
    double D2[N];
    ck_assert_int_eq(el_affine_elements_nd(2, N, xy, D2, NULL), EL_OK);
    ck_assert_int_eq(el_affine_coords(N, xy, A, NULL), EL_OK);
    for (int i = 0; i < N - 2; i++) ck_assert_close(D2[i], A[i], 1e-15);
}
END_TEST

/* curvature of a planar B-spline from the left / right segment at a joint */
static double kappa_at(const el_bspline *b, size_t span, double t)
{
    double d1[2], d2[2];
    test_deriv(b, span, t, 1, d1);
    test_deriv(b, span, t, 2, d2);
    return det2(d1, d2) / pow(hypot(d1[0], d1[1]), 3);
}

START_TEST(test_quadratic_bspline_g2)
{
    unsigned long long st = 5;
    enum { N = 12 };
    double kk[N], p[2 * N], v0[2] = {1, 0.2}, v1[2] = {0.4, 0.9};
    for (int i = 0; i < N; i++) kk[i] = test_uniform(&st, -0.4, 1.5);
    make_aal(N, kk, v0, v1, p);
    for (int pass = 0; pass < 2; pass++) {   /* 0: affine arc-length polyline, 1: perturbed */
        if (pass) p[2 * 6 + 1] += 0.05;
        for (int clamped = 0; clamped < 2; clamped++) {
            el_bspline b;
            ck_assert_int_eq(el_affine_quadratic_bspline(N, p, clamped, &b), EL_OK);
            ck_assert_int_eq(b.degree, 2);
            ck_assert_uint_eq(b.npoles, N);
            size_t flat = 0;
            for (size_t i = 0; i < b.nknots; i++) flat += (size_t)b.mults[i];
            ck_assert_uint_eq(flat, b.npoles + 3);
            double maxjump = 0.0;
            /* joints: unclamped knots 3..N-1 (spans 2..N-1), clamped knots 1..N-3 */
            for (size_t s = 3; s + 1 <= N; s++) {
                double t = clamped ? (double)(s - 2) : (double)s;
                size_t span = clamped ? s : s;      /* flat index of the span starting at t */
                double kl = kappa_at(&b, span - 1, t), kr = kappa_at(&b, span, t);
                double rel = fabs(kl - kr) / fmax(fabs(kl), fabs(kr));
                if (rel > maxjump) maxjump = rel;
            }
            if (pass == 0) ck_assert_msg(maxjump <= 1e-9, "G2 jump %g", maxjump);
            else ck_assert_msg(maxjump > 1e-3, "perturbed polyline should not be G2 (%g)", maxjump);
            /* the curve starts at (x0 + x1)/2 */
            double q[2];
            test_deriv(&b, 2, clamped ? 0.0 : 2.0, 0, q);
            ck_assert_close(q[0], 0.5 * (p[0] + p[2]), 1e-14);
            ck_assert_close(q[1], 0.5 * (p[1] + p[3]), 1e-14);
            el_bspline_free(&b);
        }
    }
    /* clamped and unclamped are the same curve */
    el_bspline bc, bu;
    ck_assert_int_eq(el_affine_quadratic_bspline(N, p, 1, &bc), EL_OK);
    ck_assert_int_eq(el_affine_quadratic_bspline(N, p, 0, &bu), EL_OK);
    for (double u = 0.0; u < N - 2; u += 0.37) {
        size_t s = (size_t)floor(u);
        double a[2], c[2];
        test_deriv(&bc, s + 2, u, 0, a);
        test_deriv(&bu, s + 2, u + 2.0, 0, c);
        ck_assert_close(a[0], c[0], 1e-13);
        ck_assert_close(a[1], c[1], 1e-13);
    }
    el_bspline_free(&bc);
    el_bspline_free(&bu);
}
END_TEST

/* Theorem 4 in R^3: the cubic uniform B-spline of an affine arc-length polyline has
 * det(f', f'', f''') = D on every segment, hence continuous torsion; clamped = unclamped. */
START_TEST(test_theorem4_cubic)
{
    unsigned long long st = 11;
    enum { N = 10 };
    double x[3 * N], Dc = 0.3;
    for (int i = 0; i < 9; i++) x[i] = test_uniform(&st, -1, 1);
    /* x3 such that det(dx0, dx1, dx2) = Dc, then onwards */
    for (int i = 3; i < N; i++) {
        double *a = x + 3 * (i - 3), *b = x + 3 * (i - 2), *c = x + 3 * (i - 1);
        double e0[3], e1[3], r[3], cr[3];
        for (int j = 0; j < 3; j++) {
            e0[j] = b[j] - a[j];
            e1[j] = c[j] - b[j];
            r[j] = test_uniform(&st, -1, 1);
        }
        cr[0] = e0[1] * e1[2] - e0[2] * e1[1];
        cr[1] = e0[2] * e1[0] - e0[0] * e1[2];
        cr[2] = e0[0] * e1[1] - e0[1] * e1[0];
        double dr = cr[0] * r[0] + cr[1] * r[1] + cr[2] * r[2], cc = cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2];
        double t = (Dc - dr) / cc;
        for (int j = 0; j < 3; j++) x[3 * i + j] = c[j] + r[j] + t * cr[j];
    }
    double D[N];
    ck_assert_int_eq(el_affine_elements_nd(3, N, x, D, NULL), EL_OK);
    for (int i = 0; i < N - 3; i++) ck_assert_close(D[i], Dc, 1e-12);
    el_bspline b;
    ck_assert_int_eq(el_affine_uniform_bspline(3, 3, N, x, 0, &b), EL_OK);
    for (size_t s = 3; s < N; s++)   /* spans 3..N-1 of knots 0..N+3 */
        for (int side = 0; side < 2; side++) {
            double t = side ? (double)s + 1.0 : (double)s;  /* both ends of each segment */
            double f1[3], f2[3], f3[3];
            test_deriv(&b, s, t, 1, f1);
            test_deriv(&b, s, t, 2, f2);
            test_deriv(&b, s, t, 3, f3);
            double det = f1[0] * (f2[1] * f3[2] - f2[2] * f3[1]) - f1[1] * (f2[0] * f3[2] - f2[2] * f3[0])
                         + f1[2] * (f2[0] * f3[1] - f2[1] * f3[0]);
            ck_assert_close(det, Dc, 1e-11);
        }
    el_bspline bc;
    ck_assert_int_eq(el_affine_uniform_bspline(3, 3, N, x, 1, &bc), EL_OK);
    ck_assert_int_eq(bc.mults[0], 4);
    for (double u = 0.05; u < N - 3; u += 0.41) {
        size_t s = (size_t)floor(u);
        double a[3], c[3];
        test_deriv(&bc, s + 3, u, 0, a);
        test_deriv(&b, s + 3, u + 3.0, 0, c);
        for (int j = 0; j < 3; j++) ck_assert_close(a[j], c[j], 1e-13);
    }
    el_bspline_free(&b);
    el_bspline_free(&bc);
}
END_TEST

START_TEST(test_parabolic_lengths)
{
    enum { N = 21 };
    double p[2 * N], S[N];
    for (int j = 0; j < N; j++) {   /* uniform samples of y = x^2: f~ is the parabola itself */
        double t = -1.0 + 0.1 * j;
        p[2 * j] = t;
        p[2 * j + 1] = t * t;
    }
    ck_assert_int_eq(el_affine_parabolic_lengths(N, p, S), EL_OK);
    for (int j = 0; j < N - 1; j++) ck_assert_close(S[j], cbrt(2.0) * 0.1, 1e-13);   /* det(f', f'') = 2 */
    /* ellipse a = 2, b = 1, clockwise: total affine length -2 pi (ab)^(1/3), O(h^2) */
    enum { E = 401 };
    static double q[2 * E], SE[E];
    for (int j = 0; j < E; j++) {
        double t = -2.0 * M_PI * j / (E - 1);
        q[2 * j] = 2.0 * cos(t);
        q[2 * j + 1] = sin(t);
    }
    ck_assert_int_eq(el_affine_parabolic_lengths(E, q, SE), EL_OK);
    double sum = 0;
    for (int j = 0; j < E - 1; j++) sum += SE[j];
    ck_assert_close(sum, -2.0 * M_PI * cbrt(2.0), 1e-5);
}
END_TEST

/* §4 on an ellipse: the result is (nearly) affinely regular. */
START_TEST(test_polyline_ellipse)
{
    enum { E = 601 };
    static double q[2 * E];
    for (int j = 0; j < E; j++) {
        double t = 0.2 + 2.5 * j / (E - 1);
        q[2 * j] = 2.0 * cos(t) + 0.5 * sin(t);
        q[2 * j + 1] = sin(t);
    }
    el_affine_result r;
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 25, NULL, &r), EL_OK);
    ck_assert_uint_eq(r.npts, 26);
    ck_assert_uint_eq(r.npieces, 1);
    double A[32], k[32];
    ck_assert_int_eq(el_affine_coords(r.npts, r.xy, A, NULL), EL_OK);
    for (size_t i = 0; i < r.npts - 2; i++) ck_assert_close(A[i], r.A[0], 1e-12 * fabs(r.A[0]));
    ck_assert_int_eq(el_affine_curvature(r.npts, r.xy, k), EL_OK);
    double kmin = k[0], kmax = k[0];
    for (size_t i = 0; i < r.npts - 3; i++) {
        kmin = fmin(kmin, k[i]);
        kmax = fmax(kmax, k[i]);
    }
    ck_assert_msg(kmax - kmin < 1e-4 * kmax, "k not constant: %g .. %g", kmin, kmax);
    for (size_t i = 0; i + 1 < r.npts; i++) {   /* vertices on the ellipse (det of the map = 2) */
        double x = r.xy[2 * i], y = r.xy[2 * i + 1];
        double c = (x - 0.5 * y) / 2.0, s = y;
        ck_assert_close(c * c + s * s, 1.0, 1e-7);
    }
    /* A = (S/n)^3 with S ~ the ellipse's affine length over the arc, 2.5 (ab)^(1/3) */
    ck_assert_close(r.S_total, 2.5 * cbrt(2.0), 1e-5);
    ck_assert_close(cbrt(r.A[0]), r.S_total / 25.0, 1e-12);
    ck_assert_close(r.t[r.npts - 1], (double)(E - 1), 0.05 * (E - 1) / 25.0);  /* ends near the end */
    el_affine_result_free(&r);
    ck_assert_ptr_null(r.xy);
}
END_TEST

/* fit_ends on a circle turning 4.2 times, E samples with exact tangents: 6 edges (< 3 a
 * turn) find no A landing the last vertex on the last sample, and the vertices ran on
 * along the last parabola continued, to t = 202 of 159 (EL_OK): now EL_EDOM, res
 * untouched. 13 edges land on it. */
START_TEST(test_polyline_fit_ends_past_the_end)
{
    enum { E = 160 };
    static double q[2 * E], tan[2 * E];
    for (int j = 0; j < E; j++) {
        double a = 2.0 * M_PI * 4.2 * j / (E - 1);
        q[2 * j] = cos(a);
        q[2 * j + 1] = sin(a);
        tan[2 * j] = -sin(a);
        tan[2 * j + 1] = cos(a);
    }
    el_affine_options o;
    el_affine_options_defaults(&o);
    o.fit_ends = 1;
    el_affine_result r, r0;
    memset(&r, 0xa5, sizeof r);
    r0 = r;
    for (int with_tan = 0; with_tan < 2; with_tan++) {
        const double *T = with_tan ? tan : NULL;
        ck_assert_int_eq(el_affine_polyline(E, q, T, 0, NULL, 6, &o, &r), EL_EDOM);
        ck_assert(memcmp(&r, &r0, sizeof r) == 0);
        ck_assert_int_eq(el_affine_polyline(E, q, T, 0, NULL, 13, &o, &r), EL_OK);
        ck_assert_close(r.t[13], (double)(E - 1), 1e-6);
        el_affine_result_free(&r);
        memset(&r, 0xa5, sizeof r);
    }
}
END_TEST

/* fit_ends short of the end: E samples (with and without their exact tangents) of a circle
 * turning 4.2 times, and of an elastica turning 4.3 times (k = 2.425 > 1: no inflection,
 * curvature 2.0 .. 4.85). Too few edges for the turning: on the circle A's edges turn at
 * most ~2 pi / 3 each (det(v, v') peaks there), so no A reaches the end, and the secant's
 * best stopped short, EL_OK: the circle at 8..12 edges ended at t = 99.7, 105.1, 117.4,
 * 130.9, 148.9 of 159, the elastica at 10..14 edges at t = 94.1 .. 146.5 (111.1 .. 154.5
 * with tangents). Now EL_EDOM, res untouched, as past the end; 16 edges land on both. */
START_TEST(test_polyline_fit_ends_short_of_the_end)
{
    enum { E = 160 };
    static double q[2][2 * E], tan[2][2 * E];
    el_smooth_params ep = {0.0, 0.0, 0.1258, 1.0, 2.425, 0.9756, 5.7357};
    double s[E], theta[E];
    for (int j = 0; j < E; j++) {
        double a = 2.0 * M_PI * 4.2 * j / (E - 1);
        q[0][2 * j] = cos(a);
        q[0][2 * j + 1] = sin(a);
        tan[0][2 * j] = -sin(a);
        tan[0][2 * j + 1] = cos(a);
        s[j] = ep.length * j / (E - 1);
    }
    ck_assert_int_eq(el_smooth_eval(&ep, E, s, q[1], theta, NULL), EL_OK);
    for (int j = 0; j < E; j++) {
        tan[1][2 * j] = cos(theta[j]);
        tan[1][2 * j + 1] = sin(theta[j]);
    }
    const size_t few[2] = {8, 10};      /* the first short count: circle, elastica */
    el_affine_options o;
    el_affine_options_defaults(&o);
    o.fit_ends = 1;
    el_affine_result r, r0;
    for (int curve = 0; curve < 2; curve++) {
        for (int with_tan = 0; with_tan < 2; with_tan++) {
            const double *T = with_tan ? tan[curve] : NULL;
            for (size_t n = few[curve]; n < few[curve] + 5; n++) {
                memset(&r, 0xa5, sizeof r);
                r0 = r;
                ck_assert_int_eq(el_affine_polyline(E, q[curve], T, 0, NULL, n, &o, &r), EL_EDOM);
                ck_assert(memcmp(&r, &r0, sizeof r) == 0);
            }
            ck_assert_int_eq(el_affine_polyline(E, q[curve], T, 0, NULL, 16, &o, &r), EL_OK);
            ck_assert_close(r.t[16], (double)(E - 1), 1e-6);
            el_affine_result_free(&r);
        }
    }
}
END_TEST

/* E samples of y = sin x over [0.4, 2 pi - 0.4]: an S curve, inflection x = pi at E/2. */
static void sine_samples(int E, double *q)
{
    for (int j = 0; j < E; j++) {
        double x = 0.4 + (2.0 * M_PI - 0.8) * j / (E - 1);
        q[2 * j] = x;
        q[2 * j + 1] = sin(x);
    }
}

/* An S curve: split at the inflection; without splitting or with a wrong split -> EL_EDOM. */
START_TEST(test_polyline_inflection)
{
    enum { E = 801 };
    static double q[2 * E];
    sine_samples(E, q);
    el_affine_result r;
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 30, NULL, &r), EL_OK);
    ck_assert_uint_eq(r.npieces, 2);
    ck_assert_close(r.infl_param[0], 400.0, 1.0);    /* x = pi at sample 400 */
    ck_assert_msg(r.A[0] < 0 && r.A[1] > 0, "A signs %g %g", r.A[0], r.A[1]);
    ck_assert_uint_eq(r.piece_start[1], 15);
    double A[64];
    ck_assert_int_eq(el_affine_coords(r.npts, r.xy, A, NULL), EL_OK);
    for (size_t p = 0; p < 2; p++)
        for (size_t i = r.piece_start[p] + 1; i < r.piece_start[p + 1]; i++)
            ck_assert_close(A[i - 1], r.A[p], 1e-12 * fabs(r.A[p]));
    el_affine_result_free(&r);

    el_affine_options o;
    el_affine_options_defaults(&o);
    o.split_inflections = 0;
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 30, &o, &r), EL_EDOM);
    size_t wrong[1] = {100};   /* says [100, 800] is inflection-free: it is not */
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 1, wrong, 30, NULL, &r), EL_EDOM);
    size_t right[1] = {400};
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 1, right, 30, NULL, &r), EL_OK);
    el_affine_result_free(&r);
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 5, NULL, &r), EL_EDOM);  /* < 3 per piece */
    /* fit_ends: the piece's last vertex lands on the inflection and on the curve's end */
    el_affine_options_defaults(&o);
    o.fit_ends = 1;
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 30, &o, &r), EL_OK);
    ck_assert_close(r.t[r.piece_start[1]], 400.0, 1e-6);
    ck_assert_close(r.t[r.npts - 1], 800.0, 1e-6);
    ck_assert_close(r.xy[2 * r.piece_start[1]], M_PI, 1e-6);
    ck_assert_int_eq(el_affine_coords(r.npts, r.xy, A, NULL), EL_OK);
    for (size_t p = 0; p < 2; p++)
        for (size_t i = r.piece_start[p] + 1; i < r.piece_start[p + 1]; i++)
            ck_assert_close(A[i - 1], r.A[p], 1e-12 * fabs(r.A[p]));
    el_affine_result_free(&r);
}
END_TEST

/* Largest relative curvature jump over the interior joints of a clamped quadratic
 * B-spline (knots K_1..K_{nknots-2}; flat spans j+1 | j+2 meet at K_j). */
static double max_joint_jump(const el_bspline *b)
{
    double worst = 0.0;
    for (size_t j = 1; j + 1 < b->nknots; j++) {
        double kl = kappa_at(b, j + 1, b->knots[j]), kr = kappa_at(b, j + 2, b->knots[j]);
        worst = fmax(worst, fabs(kl - kr) / fmax(fabs(kl), fabs(kr)));
    }
    return worst;
}

static void end_points(const el_bspline *b, double p0[2], double p1[2])
{
    test_deriv(b, 2, b->knots[0], 0, p0);
    test_deriv(b, b->npoles - 1, b->knots[b->nknots - 1], 0, p1);
}

/* el_affine_g2_bspline: exact ends, G2 at every joint (curvature measured from both
 * sides), lambda = sqrt 2 for ends at x_0 / x_m, NULL ends = the clamped uniform spline. */
START_TEST(test_g2_bspline_exact_ends)
{
    unsigned long long st = 11;
    enum { N = 14 };
    double kk[N], p[2 * N], v0[2] = {1, 0.1}, v1[2] = {0.6, 0.7};
    for (int i = 0; i < N; i++) kk[i] = test_uniform(&st, 0.2, 1.2);
    make_aal(N, kk, v0, v1, p);
    el_bspline b, u;
    double q0[2], q1[2];
    /* ends on the polyline's first / last vertex */
    ck_assert_int_eq(el_affine_g2_bspline(N, p, p, p + 2 * (N - 1), &b), EL_OK);
    ck_assert_int_eq(b.degree, 2);
    ck_assert_uint_eq(b.npoles, N);
    ck_assert_int_eq(el_bspline_check(&b), EL_OK);
    end_points(&b, q0, q1);
    ck_assert_close(q0[0], p[0], 1e-15);
    ck_assert_close(q0[1], p[1], 1e-15);
    ck_assert_close(q1[0], p[2 * N - 2], 1e-14);
    ck_assert_close(q1[1], p[2 * N - 1], 1e-14);
    ck_assert_close(b.knots[1], sqrt(2.0), 1e-12);
    ck_assert_close(b.knots[b.nknots - 1] - b.knots[b.nknots - 2], sqrt(2.0), 1e-12);
    ck_assert_msg(max_joint_jump(&b) <= 1e-9, "G2 jump %g", max_joint_jump(&b));
    /* every pole but the two next to each end is a polyline vertex */
    for (size_t i = 2; i + 2 < N; i++) {
        ck_assert_close(b.poles[2 * i], p[2 * i], 0.0);
        ck_assert_close(b.poles[2 * i + 1], p[2 * i + 1], 0.0);
    }
    el_bspline_free(&b);
    /* ends elsewhere on the turning side: still exact and G2 */
    double s0[2] = {p[0] + 0.1 * (p[2] - p[0]), p[1] + 0.1 * (p[3] - p[1])};
    double s1[2] = {0.5 * (p[2 * N - 4] + p[2 * N - 2]), 0.5 * (p[2 * N - 3] + p[2 * N - 1])};
    ck_assert_int_eq(el_affine_g2_bspline(N, p, s0, s1, &b), EL_OK);
    end_points(&b, q0, q1);
    ck_assert_close(q0[0], s0[0], 1e-15);
    ck_assert_close(q1[1], s1[1], 1e-14);
    ck_assert_msg(max_joint_jump(&b) <= 1e-9, "G2 jump %g", max_joint_jump(&b));
    el_bspline_free(&b);
    /* NULL ends: the clamped uniform spline (x0+x1)/2 .. (x_{N-2}+x_{N-1})/2 */
    ck_assert_int_eq(el_affine_g2_bspline(N, p, NULL, NULL, &b), EL_OK);
    ck_assert_int_eq(el_affine_quadratic_bspline(N, p, 1, &u), EL_OK);
    ck_assert_uint_eq(b.nknots, u.nknots);
    for (size_t i = 0; i < 2 * N; i++) ck_assert_close(b.poles[i], u.poles[i], 1e-15);
    for (size_t i = 0; i < b.nknots; i++) ck_assert_close(b.knots[i], u.knots[i], 1e-15);
    el_bspline_free(&b);
    el_bspline_free(&u);
    /* the smallest polyline, 4 vertices: both end segments meet at m_2 */
    ck_assert_int_eq(el_affine_g2_bspline(4, p, p, p + 6, &b), EL_OK);
    ck_assert_uint_eq(b.nknots, 3);
    ck_assert_msg(max_joint_jump(&b) <= 1e-9, "G2 jump %g", max_joint_jump(&b));
    end_points(&b, q0, q1);
    ck_assert_close(q1[0], p[6], 1e-15);
    el_bspline_free(&b);
    /* a perturbed (not affine arc-length) polyline is not G2: the check can fail */
    p[2 * 7 + 1] += 0.05;
    ck_assert_int_eq(el_affine_g2_bspline(N, p, p, p + 2 * (N - 1), &b), EL_OK);
    ck_assert_msg(max_joint_jump(&b) > 1e-3, "perturbed polyline judged G2 (%g)", max_joint_jump(&b));
    el_bspline_free(&b);
}
END_TEST

/* §4 + el_affine_g2_bspline on an S curve: one G2 spline per inflection-free piece,
 * starting and ending exactly on the curve's ends and its inflection, within O(h^2). */
START_TEST(test_g2_bspline_pieces_of_a_curve)
{
    enum { E = 801 };
    static double q[2 * E];
    sine_samples(E, q);
    el_affine_options o;
    el_affine_options_defaults(&o);
    o.fit_ends = 1;
    el_affine_result r;
    ck_assert_int_eq(el_affine_polyline(E, q, NULL, 0, NULL, 40, &o, &r), EL_OK);
    ck_assert_uint_eq(r.npieces, 2);
    size_t ends[3] = {0, (size_t)r.infl_param[0], E - 1};
    for (size_t p = 0; p < 2; p++) {
        size_t a = r.piece_start[p], n = r.piece_start[p + 1] - a + 1;
        el_bspline b;
        ck_assert_int_eq(el_affine_g2_bspline(n, r.xy + 2 * a, q + 2 * ends[p], q + 2 * ends[p + 1], &b),
                         EL_OK);
        double q0[2], q1[2];
        end_points(&b, q0, q1);
        ck_assert_close(q0[0], q[2 * ends[p]], 1e-15);
        ck_assert_close(q0[1], q[2 * ends[p] + 1], 1e-15);
        ck_assert_close(q1[0], q[2 * ends[p + 1]], 1e-14);
        ck_assert_close(q1[1], q[2 * ends[p + 1] + 1], 1e-14);
        ck_assert_msg(max_joint_jump(&b) <= 1e-8, "piece %zu G2 jump %g", p, max_joint_jump(&b));
        /* close to y = sin x everywhere (20 edges per piece: |sin x - y| ~ 1e-3) */
        double worst = 0.0;
        for (size_t s = 2; s < b.npoles; s++)
            for (int i = 0; i <= 8; i++) {
                double t = b.knots[s - 2] + (b.knots[s - 1] - b.knots[s - 2]) * i / 8.0, xy[2];
                test_deriv(&b, s, t, 0, xy);
                worst = fmax(worst, fabs(sin(xy[0]) - xy[1]));
            }
        ck_assert_msg(worst < 5e-3, "piece %zu off the curve by %g", p, worst);
        el_bspline_free(&b);
    }
    el_affine_result_free(&r);
}
END_TEST

/* el_affine_end_pieces names exactly the edge counts at which el_affine_polyline keeps the
 * end pieces (seed 002 §4.4: n S_end / S_total < 1.5 leaves one out): a wavy curve
 * 20 sin(x / 30) with an inflection 2 mm from its start (QA22gui F6) and its mirror (the
 * inflection at the end), with and without tangents; at every n around the counts named,
 * the polyline starts at sample 0 iff n >= n_min[0] and has all the pieces iff n >= n_min[1]. */
START_TEST(test_end_pieces_counts_are_the_polylines)
{
    enum { NS = 4001 };
    static double p[2 * NS], T[2 * NS];
    for (int mirror = 0; mirror < 2; mirror++)
        for (int with_t = 0; with_t < 2; with_t++) {
            for (int j = 0; j < NS; j++) {
                double x = -2.0 + 182.0 * j / (NS - 1);
                if (mirror) x = 178.0 - 182.0 * j / (NS - 1);   /* the inflection at x = 0 last */
                double c = (20.0 / 30.0) * cos(x / 30.0), d = mirror ? -1.0 : 1.0;
                p[2 * j] = x + 3000.0;
                p[2 * j + 1] = 20.0 * sin(x / 30.0) - 1000.0;
                T[2 * j] = d / hypot(1.0, c);
                T[2 * j + 1] = d * c / hypot(1.0, c);
            }
            size_t npieces = 0, ends[2], n_min[2];
            ck_assert_int_eq(el_affine_end_pieces(NS, p, with_t ? T : NULL, 0, NULL, NULL, &npieces,
                                                  ends, n_min), EL_OK);
            ck_assert_uint_eq(npieces, 3);
            ck_assert(n_min[0] > 3 && n_min[1] >= n_min[0] && n_min[1] < EL_AFFINE_MAX_EDGES);
            /* the short piece is the one next to the inflection at x = 0 */
            if (!mirror) ck_assert(ends[0] < NS / 40 && n_min[1] > 100);
            else ck_assert(NS - 1 - ends[1] < NS / 40 && n_min[0] < 100 && n_min[1] > 100);
            el_affine_options o;
            el_affine_options_defaults(&o);
            o.fit_ends = 1;             /* (the pieces kept do not depend on the options) */
            size_t probe[] = {n_min[0] - 1, n_min[0], n_min[1] - 1, n_min[1], 24};
            for (size_t q = 0; q < sizeof probe / sizeof *probe; q++) {
                size_t n = probe[q];
                if (n < 9 || (q > 0 && n == probe[q - 1])) continue;
                el_affine_result r;
                int st = el_affine_polyline(NS, p, with_t ? T : NULL, 0, NULL, n, &o, &r);
                ck_assert_msg(st == EL_OK, "mirror %d tangents %d n %zu: status %d", mirror,
                              with_t, n, st);
                ck_assert_msg((r.t[0] == 0.0) == (n >= n_min[0]),
                              "mirror %d tangents %d n %zu: starts at %g, n_min %zu", mirror,
                              with_t, n, r.t[0], n_min[0]);
                ck_assert_msg((r.npieces == npieces) == (n >= n_min[1]),
                              "mirror %d tangents %d n %zu: %zu pieces, n_min %zu", mirror,
                              with_t, n, r.npieces, n_min[1]);
                el_affine_result_free(&r);
            }
        }
    /* one piece: kept at every count; bad input as el_affine_polyline's */
    double arc[2 * 40];
    for (int j = 0; j < 40; j++) {
        arc[2 * j] = cos(0.05 * j);
        arc[2 * j + 1] = sin(0.05 * j);
    }
    size_t npieces, ends[2], n_min[2];
    ck_assert_int_eq(el_affine_end_pieces(40, arc, NULL, 0, NULL, NULL, &npieces, ends, n_min), EL_OK);
    ck_assert_uint_eq(npieces, 1);
    ck_assert_uint_eq(n_min[0], 3);
    ck_assert_uint_eq(n_min[1], 3);
    ck_assert_uint_eq(ends[0], 39);
    ck_assert_uint_eq(ends[1], 0);
    double line[8] = {0, 0, 1, 0, 2, 0, 3, 0};
    ck_assert_int_eq(el_affine_end_pieces(4, line, NULL, 0, NULL, NULL, &npieces, ends, n_min), EL_EDOM);
    ck_assert_int_eq(el_affine_end_pieces(3, arc, NULL, 0, NULL, NULL, &npieces, ends, n_min), EL_EINVAL);
    ck_assert_int_eq(el_affine_end_pieces(40, arc, NULL, 0, NULL, NULL, NULL, ends, n_min), EL_EINVAL);
}
END_TEST

START_TEST(test_bad_input)
{
    double xy[8] = {0, 0, 1, 0, 1, 1, 0, 2}, A[4], k[4], L, out[16];
    el_bspline b;
    el_affine_result r;
    ck_assert_int_eq(el_affine_coords(2, xy, A, NULL), EL_EINVAL);
    ck_assert_int_eq(el_affine_coords(3, NULL, A, NULL), EL_EINVAL);
    ck_assert_int_eq(el_affine_length(2, xy, &L), EL_EINVAL);
    ck_assert_int_eq(el_affine_curvature(3, xy, k), EL_EINVAL);
    ck_assert_int_eq(el_affine_quadratic_bspline(2, xy, 1, &b), EL_EINVAL);
    ck_assert_int_eq(el_affine_uniform_bspline(2, 3, 3, xy, 1, &b), EL_EINVAL);
    ck_assert_int_eq(el_affine_lane_riesenfeld(2, 4, 2, xy, out), EL_EINVAL);
    ck_assert_int_eq(el_affine_elements_nd(3, 3, xy, A, NULL), EL_EINVAL);
    ck_assert_int_eq(el_affine_polyline(3, xy, NULL, 0, NULL, 5, NULL, &r), EL_EINVAL);
    ck_assert_int_eq(el_affine_polyline(4, xy, NULL, 0, NULL, 2, NULL, &r), EL_EINVAL);
    size_t bad[1] = {0};
    ck_assert_int_eq(el_affine_polyline(4, xy, NULL, 1, bad, 3, NULL, &r), EL_EINVAL);
    xy[3] = NAN;
    ck_assert_int_eq(el_affine_coords(4, xy, A, NULL), EL_EINVAL);
    ck_assert_int_eq(el_affine_chaikin(4, xy, out), EL_EINVAL);
    xy[3] = 0;
    double line[8] = {0, 0, 1, 0, 2, 0, 3, 0};
    ck_assert_int_eq(el_affine_curvature(4, line, k), EL_ESINGULAR);
    ck_assert_int_eq(el_affine_polyline(4, line, NULL, 0, NULL, 3, NULL, &r), EL_EDOM);
    el_affine_result_free(NULL);
    /* el_affine_g2_bspline: too short, NaN, a straight polyline, an end behind its joint */
    double aal[8] = {0, 0, 1, 0, 1.5, 1, 1.5, 2.5}, bad_end[2] = {5, -3}, nan_end[2] = {NAN, 0};
    ck_assert_int_eq(el_affine_g2_bspline(3, aal, NULL, NULL, &b), EL_EINVAL);
    ck_assert_int_eq(el_affine_g2_bspline(4, aal, nan_end, NULL, &b), EL_EINVAL);
    ck_assert_int_eq(el_affine_g2_bspline(4, aal, NULL, NULL, NULL), EL_EINVAL);
    ck_assert_int_eq(el_affine_g2_bspline(4, line, line, NULL, &b), EL_ESINGULAR);
    ck_assert_int_eq(el_affine_g2_bspline(4, aal, bad_end, NULL, &b), EL_EDOM);
    ck_assert_int_eq(el_affine_g2_bspline(4, aal, NULL, bad_end, &b), EL_EDOM);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("affine");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_coords_and_curvature);
    tcase_add_test(tc, test_theorem1);
    tcase_add_test(tc, test_osculating_conics);
    tcase_add_test(tc, test_chaikin_lane_riesenfeld);
    tcase_add_test(tc, test_quadratic_bspline_g2);
    tcase_add_test(tc, test_theorem4_cubic);
    tcase_add_test(tc, test_parabolic_lengths);
    tcase_add_test(tc, test_polyline_ellipse);
    tcase_add_test(tc, test_polyline_inflection);
    tcase_add_test(tc, test_polyline_fit_ends_past_the_end);
    tcase_add_test(tc, test_polyline_fit_ends_short_of_the_end);
    tcase_add_test(tc, test_g2_bspline_exact_ends);
    tcase_add_test(tc, test_g2_bspline_pieces_of_a_curve);
    tcase_add_test(tc, test_end_pieces_counts_are_the_polylines);
    tcase_add_test(tc, test_bad_input);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
