/* Keyline preparation (seed 000 §5.3): plane fit, equilateral resampling,
 * PCA re-normalisation, RDP-style inflection estimate. */
#include "testutil.h"

#include <float.h>
#include <string.h>

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

/* A random proper rotation: columns u, v, w (Gram-Schmidt of random vectors). */
static void random_frame(unsigned long long *st, double *u, double *v, double *w)
{
    for (int j = 0; j < 3; j++) { u[j] = test_normal(st); v[j] = test_normal(st); }
    double nu = sqrt(dot3(u, u));
    for (int j = 0; j < 3; j++) u[j] /= nu;
    double d = dot3(u, v);
    for (int j = 0; j < 3; j++) v[j] -= d * u[j];
    double nv = sqrt(dot3(v, v));
    for (int j = 0; j < 3; j++) v[j] /= nv;
    w[0] = u[1] * v[2] - u[2] * v[1];
    w[1] = u[2] * v[0] - u[0] * v[2];
    w[2] = u[0] * v[1] - u[1] * v[0];
}

/* A planar curve with one inflection, (t, 0.3 t^3 - 0.4 t), t in [-1.5, 1.7], embedded
 * on the plane origin + x u + y v. scale multiplies the curve (not the offset). */
static void tilted_curve(size_t n, double scale, const double *o, const double *u,
                         const double *v, const double *w, double zsig, unsigned long long *st,
                         double *xyz)
{
    for (size_t i = 0; i < n; i++) {
        double t = -1.5 + 3.2 * (double)i / (double)(n - 1);
        double x = scale * t, y = scale * (0.3 * t * t * t - 0.4 * t);
        double z = zsig > 0 ? zsig * scale * test_normal(st) : 0.0;
        for (int j = 0; j < 3; j++) xyz[3 * i + j] = o[j] + x * u[j] + y * v[j] + z * w[j];
    }
}

static void check_frame(const el_frame *f)
{
    const double *e[3] = {f->e1, f->e2, f->e3};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) ck_assert_close(dot3(e[i], e[j]), i == j ? 1.0 : 0.0, 1e-14);
    double c[3] = {f->e1[1] * f->e2[2] - f->e1[2] * f->e2[1], f->e1[2] * f->e2[0] - f->e1[0] * f->e2[2],
                   f->e1[0] * f->e2[1] - f->e1[1] * f->e2[0]};
    for (int j = 0; j < 3; j++) ck_assert_close(c[j], f->e3[j], 1e-14);   /* right-handed */
    ck_assert(f->lambda[0] >= f->lambda[1] && f->lambda[1] >= f->lambda[2] && f->lambda[2] >= 0);
}

/* ------------------------------------------------------------------ plane fit */

START_TEST(test_plane_fit_recovers_plane)
{
    unsigned long long st = 0x9e3779b97f4a7c15ULL + (unsigned long long)_i;
    const double scales[3] = {1.0, 1e-9, 1e9};
    double scale = scales[_i % 3];
    double u[3], v[3], w[3], o[3];
    random_frame(&st, u, v, w);
    for (int j = 0; j < 3; j++) o[j] = test_uniform(&st, -5, 5) * scale;
    enum { N = 200 };
    double xyz[3 * N], xy[2 * N], back[3 * N], rms;
    tilted_curve(N, scale, o, u, v, w, 0.0, &st, xyz);
    el_frame f;
    ck_assert_int_eq(el_plane_fit(xyz, N, &f, xy, &rms), EL_OK);
    check_frame(&f);
    ck_assert_close(fabs(dot3(f.e3, w)), 1.0, 1e-12);          /* the true normal */
    ck_assert(f.e3[2] > 0 || (fabs(f.e3[2]) <= 1e-9 && f.e3[1] >= 0));
    double chord[3];
    for (int j = 0; j < 3; j++) chord[j] = xyz[3 * (N - 1) + j] - xyz[j];
    ck_assert(dot3(f.e1, chord) > 0);                        /* e1 from first to last point */
    ck_assert(rms <= 1e-12 * scale);
    ck_assert(f.lambda[2] <= 1e-14 * f.lambda[0]);
    /* centroid (5.1) and the trace of C = sum of the eigenvalues */
    double c[3] = {0, 0, 0}, tr = 0;
    for (size_t i = 0; i < N; i++)
        for (int j = 0; j < 3; j++) c[j] += xyz[3 * i + j] / N;
    for (int j = 0; j < 3; j++) ck_assert_close(f.origin[j], c[j], 1e-13 * (fabs(c[j]) + scale));
    for (size_t i = 0; i < N; i++)
        for (int j = 0; j < 3; j++) tr += (xyz[3 * i + j] - c[j]) * (xyz[3 * i + j] - c[j]) / N;
    ck_assert_close(f.lambda[0] + f.lambda[1] + f.lambda[2], tr, 1e-12 * tr);
    /* the plane coordinates are the curve's up to a rotation: distances are kept */
    for (size_t i = 1; i < N; i++) {
        double d2 = hypot(xy[2 * i] - xy[0], xy[2 * i + 1] - xy[1]);
        double d3 = sqrt((xyz[3 * i] - xyz[0]) * (xyz[3 * i] - xyz[0]) +
                         (xyz[3 * i + 1] - xyz[1]) * (xyz[3 * i + 1] - xyz[1]) +
                         (xyz[3 * i + 2] - xyz[2]) * (xyz[3 * i + 2] - xyz[2]));
        ck_assert_close(d2, d3, 1e-12 * scale);
    }
    /* round trip 3D -> 2D -> 3D */
    ck_assert_int_eq(el_frame_to_3d(&f, N, xy, back), EL_OK);
    for (size_t i = 0; i < 3 * N; i++) ck_assert_close(back[i], xyz[i], 1e-12 * scale * 10);
    /* el_frame_project agrees with the fit's coordinates */
    double xy2[2 * N], z[N];
    ck_assert_int_eq(el_frame_project(&f, N, xyz, xy2, z), EL_OK);
    for (size_t i = 0; i < N; i++) {
        ck_assert_close(xy2[2 * i], xy[2 * i], 1e-13 * scale);
        ck_assert_close(xy2[2 * i + 1], xy[2 * i + 1], 1e-13 * scale);
        ck_assert(fabs(z[i]) <= 1e-12 * scale);
    }
}
END_TEST

START_TEST(test_plane_fit_noisy)
{
    unsigned long long st = 12345;
    double u[3], v[3], w[3], o[3] = {100, -40, 7};
    random_frame(&st, u, v, w);
    enum { N = 500 };
    double xyz[3 * N], xy[2 * N], back[3 * N], z[N], rms;
    const double sig = 1e-3;
    tilted_curve(N, 1.0, o, u, v, w, sig, &st, xyz);
    el_frame f;
    ck_assert_int_eq(el_plane_fit(xyz, N, &f, xy, &rms), EL_OK);
    check_frame(&f);
    ck_assert(fabs(dot3(f.e3, w)) > 1.0 - 1e-4);                /* normal to within the noise */
    ck_assert(rms > 0.8 * sig && rms < 1.2 * sig);
    ck_assert_close(rms * rms, f.lambda[2], 1e-10);             /* rms^2 = lambda_3 */
    /* xyz = to_3d(x', y') + z' e3 exactly */
    ck_assert_int_eq(el_frame_to_3d(&f, N, xy, back), EL_OK);
    ck_assert_int_eq(el_frame_project(&f, N, xyz, xy, z), EL_OK);
    for (size_t i = 0; i < N; i++)
        for (int j = 0; j < 3; j++) ck_assert_close(back[3 * i + j] + z[i] * f.e3[j], xyz[3 * i + j], 1e-12);
}
END_TEST

START_TEST(test_plane_fit_sign_convention)
{
    /* a curve in the xy-plane keeps its orientation: e3 = +z, e1 along +x when it runs left to right */
    enum { N = 50 };
    double xyz[3 * N], xy[2 * N];
    for (size_t i = 0; i < N; i++) {
        double t = (double)i / (N - 1);
        xyz[3 * i] = 10 * t;
        xyz[3 * i + 1] = sin(3 * t);
        xyz[3 * i + 2] = 2.0;
    }
    el_frame f;
    ck_assert_int_eq(el_plane_fit(xyz, N, &f, xy, NULL), EL_OK);
    ck_assert_close(f.e3[2], 1.0, 1e-14);
    ck_assert(f.e1[0] > 0.9);
    /* walked backwards, e1 flips, e3 stays: the picture is rotated by pi, not mirrored */
    double rev[3 * N];
    for (size_t i = 0; i < N; i++) memcpy(rev + 3 * i, xyz + 3 * (N - 1 - i), 3 * sizeof(double));
    el_frame g;
    ck_assert_int_eq(el_plane_fit(rev, N, &g, NULL, NULL), EL_OK);
    ck_assert_close(g.e3[2], 1.0, 1e-14);
    for (int j = 0; j < 3; j++) ck_assert_close(g.e1[j], -f.e1[j], 1e-14);
    /* collinear points are accepted: y' = 0 */
    for (size_t i = 0; i < N; i++) {
        xyz[3 * i] = 1.0 + i;
        xyz[3 * i + 1] = 2.0 * i;
        xyz[3 * i + 2] = -1.0 * i;
    }
    ck_assert_int_eq(el_plane_fit(xyz, N, &f, xy, NULL), EL_OK);
    check_frame(&f);
    for (size_t i = 0; i < N; i++) ck_assert(fabs(xy[2 * i + 1]) < 1e-12);
}
END_TEST

START_TEST(test_plane_fit_bad_input)
{
    double xyz[12] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 1}, xy[8] = {7, 7, 7, 7, 7, 7, 7, 7};
    el_frame f;
    memset(&f, 0, sizeof f);
    f.origin[0] = 42;
    ck_assert_int_eq(el_plane_fit(NULL, 4, &f, xy, NULL), EL_EINVAL);
    ck_assert_int_eq(el_plane_fit(xyz, 2, &f, xy, NULL), EL_EINVAL);
    xyz[4] = NAN;
    ck_assert_int_eq(el_plane_fit(xyz, 4, &f, xy, NULL), EL_EINVAL);
    xyz[4] = INFINITY;
    ck_assert_int_eq(el_plane_fit(xyz, 4, &f, xy, NULL), EL_EINVAL);
    double same[12];
    for (int i = 0; i < 4; i++) { same[3 * i] = 0.1; same[3 * i + 1] = 1e8 / 3; same[3 * i + 2] = -7.3; }
    ck_assert_int_eq(el_plane_fit(same, 4, &f, xy, NULL), EL_ESINGULAR);
    ck_assert_close(f.origin[0], 42.0, 0);   /* outputs untouched */
    ck_assert_close(xy[0], 7.0, 0);
    double p2[4] = {1, 2, 3, 4};
    ck_assert_int_eq(el_frame_to_3d(NULL, 1, p2, xyz), EL_EINVAL);
    f.e1[0] = NAN;
    ck_assert_int_eq(el_frame_to_3d(&f, 1, p2, xyz), EL_EINVAL);
    ck_assert_int_eq(el_frame_project(&f, 1, xyz, p2, NULL), EL_EINVAL);
}
END_TEST

/* ------------------------------------------------------------------ 2D PCA */

START_TEST(test_pca_normalize)
{
    unsigned long long st = 777 + (unsigned long long)_i;
    enum { N = 300 };
    double xy[2 * N], out[2 * N], back[2 * N];
    double a = test_uniform(&st, -M_PI, M_PI), ox = test_uniform(&st, -50, 50), oy = test_uniform(&st, -50, 50);
    for (size_t i = 0; i < N; i++) {
        double t = test_uniform(&st, -3, 3), s = 0.5 * sin(2 * t) + 0.01 * test_normal(&st);
        xy[2 * i] = ox + cos(a) * t - sin(a) * s;
        xy[2 * i + 1] = oy + sin(a) * t + cos(a) * s;
    }
    el_frame2d f;
    ck_assert_int_eq(el_pca_normalize(xy, N, &f, out), EL_OK);
    /* D of the new coordinates is diagonal with the eigenvalues, the centroid is 0 */
    double mx = 0, my = 0, sxx = 0, syy = 0, sxy = 0;
    for (size_t i = 0; i < N; i++) { mx += out[2 * i] / N; my += out[2 * i + 1] / N; }
    for (size_t i = 0; i < N; i++) {
        sxx += out[2 * i] * out[2 * i] / N;
        syy += out[2 * i + 1] * out[2 * i + 1] / N;
        sxy += out[2 * i] * out[2 * i + 1] / N;
    }
    ck_assert(fabs(mx) < 1e-12 && fabs(my) < 1e-12);
    ck_assert_close(sxx, f.mu[0], 1e-12 * f.mu[0]);
    ck_assert_close(syy, f.mu[1], 1e-11 * f.mu[0]);
    ck_assert(fabs(sxy) < 1e-12 * f.mu[0]);
    ck_assert(f.mu[0] >= f.mu[1]);
    /* signs: diagonal of (f1 f2) positive, a rotation */
    ck_assert(f.f1[0] > 0 && f.f2[1] > 0);
    ck_assert_close(f.f1[0] * f.f2[1] - f.f1[1] * f.f2[0], 1.0, 1e-14);
    ck_assert_int_eq(el_frame2d_to_parent(&f, N, out, back), EL_OK);
    for (size_t i = 0; i < 2 * N; i++) ck_assert_close(back[i], xy[i], 1e-12 * 100);
    /* in place */
    memcpy(back, xy, sizeof xy);
    ck_assert_int_eq(el_frame2d_to_local(&f, N, back, back), EL_OK);
    for (size_t i = 0; i < 2 * N; i++) ck_assert_close(back[i], out[i], 1e-12);
    ck_assert_int_eq(el_pca_normalize(xy, N, NULL, xy), EL_OK);
    for (size_t i = 0; i < 2 * N; i++) ck_assert_close(xy[i], out[i], 1e-12);
}
END_TEST

START_TEST(test_pca_bad_input)
{
    double xy[6] = {1, 1, 1, 1, 1, 1}, out[6] = {9, 9, 9, 9, 9, 9};
    el_frame2d f;
    ck_assert_int_eq(el_pca_normalize(xy, 3, &f, out), EL_ESINGULAR);
    ck_assert_int_eq(el_pca_normalize(xy, 1, &f, out), EL_EINVAL);
    ck_assert_int_eq(el_pca_normalize(NULL, 3, &f, out), EL_EINVAL);
    xy[3] = NAN;
    ck_assert_int_eq(el_pca_normalize(xy, 3, &f, out), EL_EINVAL);
    ck_assert_close(out[0], 9.0, 0);
}
END_TEST

/* ------------------------------------------------------------------ resampling */

/* Distance from X to the polyline p (n points). */
static double dist_polyline(const double *X, const double *p, size_t n)
{
    double best = INFINITY;
    for (size_t j = 0; j + 1 < n; j++) {
        const double *A = p + 2 * j, *B = A + 2;
        double dx = B[0] - A[0], dy = B[1] - A[1], L2 = dx * dx + dy * dy;
        double t = L2 > 0 ? ((X[0] - A[0]) * dx + (X[1] - A[1]) * dy) / L2 : 0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        best = fmin(best, hypot(X[0] - A[0] - t * dx, X[1] - A[1] - t * dy));
    }
    return best;
}

/* Largest arc-length position on the polyline (walked from its first point) of a
 * point at distance r from A, by brute force with a dense check of every
 * segment; -1 if none. Independent of the library's tree search. */
static double farthest_hit(const double *p, size_t n, const double *A, double r)
{
    double s0 = 0, best = -1;
    for (size_t j = 0; j + 1 < n; j++) {
        const double *P = p + 2 * j, *Q = P + 2;
        double L = hypot(Q[0] - P[0], Q[1] - P[1]);
        /* |X - A| is convex along the segment: no hit if both ends are inside
         * the circle or the whole segment is outside it */
        double dP = hypot(P[0] - A[0], P[1] - A[1]), dQ = hypot(Q[0] - A[0], Q[1] - A[1]);
        const double AQ[2] = {A[0], A[1]};
        int maybe = fmax(dP, dQ) >= r * (1 - 1e-12) && dist_polyline(AQ, P, 2) <= r * (1 + 1e-12);
        if (L > 0 && maybe) {
            /* bisection on sign changes of g(t) = |P + t(Q-P) - A| - r over a fine grid */
            enum { M = 64 };
            double prev = hypot(P[0] - A[0], P[1] - A[1]) - r;
            for (int m = 1; m <= M; m++) {
                double t = (double)m / M;
                double g = hypot(P[0] + t * (Q[0] - P[0]) - A[0], P[1] + t * (Q[1] - P[1]) - A[1]) - r;
                if ((prev <= 0 && g >= 0) || (prev >= 0 && g <= 0)) {
                    double lo = (m - 1.0) / M, hi = t;
                    for (int it = 0; it < 60; it++) {
                        double mid = 0.5 * (lo + hi);
                        double gm = hypot(P[0] + mid * (Q[0] - P[0]) - A[0], P[1] + mid * (Q[1] - P[1]) - A[1]) - r;
                        if ((gm <= 0) == (prev <= 0)) lo = mid; else hi = mid;
                    }
                    best = fmax(best, s0 + 0.5 * (lo + hi) * L);
                }
                prev = g;
            }
        }
        s0 += L;
    }
    return best;
}

/* Check every property of a resampling of p (walked from its first point). */
static void check_resampling(const double *p, size_t n, double r, const el_resample_result *res,
                             double scale)
{
    ck_assert(res->n >= 2);
    for (size_t k = 0; k < res->n; k++) {
        ck_assert(dist_polyline(res->xy + 2 * k, p, n) <= 1e-12 * scale);   /* on the curve */
        if (k > 0) {
            double seg = hypot(res->xy[2 * k] - res->xy[2 * k - 2], res->xy[2 * k + 1] - res->xy[2 * k - 1]);
            ck_assert_close(seg, r, 1e-12 * r);                             /* equilateral */
            ck_assert(res->s[k] > res->s[k - 1]);                           /* never goes back */
        }
        /* the next vertex is the hit nearest the far end; none after the stop point */
        double far = farthest_hit(p, n, res->xy + 2 * k, r);
        if (k + 1 < res->n) ck_assert_close(res->s[k + 1], far, 1e-7 * scale);   /* bisection: ~sqrt(eps) at tangent hits */
        else ck_assert_msg(far <= res->s[k] + 1e-9 * scale, "a point ahead at distance r after the stop point");
    }
}

START_TEST(test_resample_straight)
{
    double p[4] = {0, 0, 10.5, 0};
    el_resample_result res;
    ck_assert_int_eq(el_resample_equilateral(p, 2, 1.0, &res), EL_OK);
    ck_assert_uint_eq(res.n, 11);
    ck_assert_close(res.xy[2 * 10], 10.0, 1e-14);
    ck_assert_close(res.remainder, 0.5, 1e-14);
    ck_assert_int_eq(res.reversed, 0);
    el_resample_free(&res);
    ck_assert_ptr_null(res.xy);
    el_resample_free(&res);   /* twice is harmless */
    /* exact multiple: the last vertex is the end point (a hit at a shared vertex) */
    double q[8] = {0, 0, 1, 0, 2, 0, 3, 0};
    ck_assert_int_eq(el_resample_equilateral(q, 4, 1.0, &res), EL_OK);
    ck_assert_uint_eq(res.n, 4);
    for (size_t k = 0; k < 4; k++) ck_assert_close(res.xy[2 * k], (double)k, 1e-15);
    el_resample_free(&res);
    /* walked from the left end: a right-to-left input is reversed */
    double rl[6] = {5, 1, 2.5, 0, 0, 1};
    ck_assert_int_eq(el_resample_equilateral(rl, 3, 0.7, &res), EL_OK);
    ck_assert_int_eq(res.reversed, 1);
    ck_assert_close(res.xy[0], 0.0, 0);
    ck_assert_close(res.xy[1], 1.0, 0);
    double fw[6] = {0, 1, 2.5, 0, 5, 1};
    check_resampling(fw, 3, 0.7, &res, 5);
    el_resample_free(&res);
}
END_TEST

START_TEST(test_resample_s_curve)
{
    unsigned long long st = 99;
    enum { N = 400 };
    double p[2 * N];
    for (size_t i = 0; i < N; i++) {   /* irregular sampling of an S */
        double t = -2.0 + 4.0 * ((double)i + (i > 0 && i < N - 1 ? test_uniform(&st, -0.4, 0.4) : 0)) / (N - 1);
        p[2 * i] = 30 * t;
        p[2 * i + 1] = 20 * sin(1.3 * t) + 3 * t * t;
    }
    const double rs[3] = {0.37, 2.0, 17.0};
    for (int i = 0; i < 3; i++) {
        el_resample_result res;
        ck_assert_int_eq(el_resample_equilateral(p, N, rs[i], &res), EL_OK);
        check_resampling(p, N, rs[i], &res, 100);
        ck_assert(res.remainder >= 0);
        ck_assert_close(res.s[0], 0.0, 0);
        el_resample_free(&res);
    }
}
END_TEST

/* A hairpin: right along y = 0, a half circle of diameter g, back left along y = g. */
static size_t hairpin(double g, double *p)
{
    size_t n = 0;
    for (int i = 0; i <= 40; i++) { p[2 * n] = 10.0 * i / 40; p[2 * n + 1] = 0; n++; }
    for (int i = 1; i < 20; i++) {
        double a = -M_PI / 2 + M_PI * i / 20;
        p[2 * n] = 10 + 0.5 * g * cos(a);
        p[2 * n + 1] = 0.5 * g + 0.5 * g * sin(a);
        n++;
    }
    for (int i = 0; i <= 30; i++) { p[2 * n] = 10 - 6.0 * i / 30; p[2 * n + 1] = g; n++; }
    return n;
}

START_TEST(test_resample_hairpin)
{
    double p[2 * 100];
    el_resample_result res;
    /* gap narrower than r: the circle reaches the returning branch, which is
     * nearer the far end, so the polygon jumps across the hairpin */
    size_t n = hairpin(0.6, p);
    ck_assert_int_eq(el_resample_equilateral(p, n, 1.0, &res), EL_OK);
    check_resampling(p, n, 1.0, &res, 10);
    int crossed = 0;
    double maxx = 0;
    for (size_t k = 1; k < res.n; k++) {
        if (res.xy[2 * k - 1] < 1e-12 && res.xy[2 * k + 1] > 0.6 - 1e-12) crossed++;
        maxx = fmax(maxx, res.xy[2 * k]);
    }
    ck_assert_int_eq(crossed, 1);
    ck_assert(maxx < 10.0);                       /* the turn itself is skipped */
    el_resample_free(&res);
    /* gap wider than r: it follows the turn */
    n = hairpin(3.0, p);
    ck_assert_int_eq(el_resample_equilateral(p, n, 1.0, &res), EL_OK);
    check_resampling(p, n, 1.0, &res, 10);
    maxx = 0;
    for (size_t k = 0; k < res.n; k++) maxx = fmax(maxx, res.xy[2 * k]);
    ck_assert(maxx > 11.0);
    el_resample_free(&res);
}
END_TEST

START_TEST(test_resample_stop_point)
{
    /* a hook at the end: from the vertex before it the only points at distance r
     * lie behind, so it is the stop point although length remains */
    double p[8] = {0, 0, 5, 0, 5, 0.3, 4.98, 0.3};
    el_resample_result res;
    ck_assert_int_eq(el_resample_equilateral(p, 4, 1.0, &res), EL_OK);
    check_resampling(p, 4, 1.0, &res, 5);
    ck_assert_uint_eq(res.n, 6);
    ck_assert_close(res.xy[2 * 5], 5.0, 1e-14);    /* A_6 = (5, 0), the corner */
    ck_assert_close(res.xy[2 * 5 + 1], 0.0, 1e-14);
    ck_assert_close(res.remainder, 0.32, 1e-14);
    el_resample_free(&res);
    /* a longer hook: from A_5 = (4, 0) the circle meets the hook's returning
     * piece, which is nearer the far end than the corner: A_6 lies on it */
    double h[8] = {0, 0, 5, 0, 5, 0.4, 4.6, 0.4};
    ck_assert_int_eq(el_resample_equilateral(h, 4, 1.0, &res), EL_OK);
    check_resampling(h, 4, 1.0, &res, 5);
    ck_assert_uint_eq(res.n, 6);
    ck_assert_close(res.xy[2 * 5], 4.0 + sqrt(1.0 - 0.16), 1e-14);
    ck_assert_close(res.xy[2 * 5 + 1], 0.4, 1e-14);
    el_resample_free(&res);
    /* a spiral: many hits per circle */
    enum { N = 2000 };
    double sp[2 * N];
    for (size_t i = 0; i < N; i++) {
        double th = 6 * M_PI * (double)i / (N - 1);
        sp[2 * i] = (1 + th) * cos(th);
        sp[2 * i + 1] = (1 + th) * sin(th);
    }
    const double rs[3] = {0.3, 4.0, 9.0};
    for (int i = 0; i < 3; i++) {
        ck_assert_int_eq(el_resample_equilateral(sp, N, rs[i], &res), EL_OK);
        check_resampling(sp, N, rs[i], &res, 20);
        el_resample_free(&res);
    }
}
END_TEST

START_TEST(test_resample_bad_input)
{
    double p[8] = {0, 0, 1, 0, 2, 0, 3, 0};
    el_resample_result res;
    memset(&res, 0, sizeof res);
    res.n = 77;
    ck_assert_int_eq(el_resample_equilateral(p, 4, 0.0, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(p, 4, -1.0, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(p, 4, NAN, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(p, 4, INFINITY, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(p, 4, 3.5, &res), EL_EINVAL);   /* r > curve */
    ck_assert_int_eq(el_resample_equilateral(p, 1, 0.5, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(NULL, 4, 0.5, &res), EL_EINVAL);
    ck_assert_int_eq(el_resample_equilateral(p, 4, 0.5, NULL), EL_EINVAL);
    p[3] = NAN;
    ck_assert_int_eq(el_resample_equilateral(p, 4, 0.5, &res), EL_EINVAL);
    double same[6] = {2, 3, 2, 3, 2, 3};
    ck_assert_int_eq(el_resample_equilateral(same, 3, 0.5, &res), EL_ESINGULAR);
    ck_assert_uint_eq(res.n, 77);   /* untouched */
    /* repeated consecutive points are fine */
    double rep[10] = {0, 0, 1, 0, 1, 0, 1, 0, 3, 0};
    ck_assert_int_eq(el_resample_equilateral(rep, 5, 0.5, &res), EL_OK);
    ck_assert_uint_eq(res.n, 7);
    el_resample_free(&res);
    el_resample_free(NULL);
}
END_TEST

/* ------------------------------------------------------------------ inflection */

/* The generated S: a noisy cubic y = a (x - xi)^3 + b (x - xi) with a b < 0
 * (or the reverse), rotated, resampled, re-normalised. Returns the distance
 * from the estimate to the true inflection, in units of r. */
static double cubic_trial(unsigned long long *st, double noise, double *rout)
{
    enum { N = 600 };
    double xi = test_uniform(st, -0.35, 0.35);
    double a = test_uniform(st, 1.0, 3.0) * (test_uniform(st, 0, 1) < 0.5 ? -1 : 1);
    double b = -a * test_uniform(st, 0.3, 0.8);
    double ang = test_uniform(st, -M_PI, M_PI);
    double p[2 * N];
    for (size_t i = 0; i < N; i++) {
        double x = -1.0 + 2.0 * (double)i / (N - 1), dx = x - xi;
        double y = a * dx * dx * dx + b * dx + noise * test_normal(st);
        x += noise * test_normal(st);
        p[2 * i] = cos(ang) * x - sin(ang) * y;
        p[2 * i + 1] = sin(ang) * x + cos(ang) * y;
    }
    double ti[2] = {cos(ang) * xi, sin(ang) * xi};   /* the inflection (xi, 0) rotated */
    double xy[2 * N];
    el_frame2d f0;
    ck_assert_int_eq(el_pca_normalize(p, N, &f0, xy), EL_OK);   /* x' as after the plane fit */
    ck_assert_int_eq(el_frame2d_to_local(&f0, 1, ti, ti), EL_OK);
    double r = 0.01;
    el_resample_result res;
    ck_assert_int_eq(el_resample_equilateral(xy, N, r, &res), EL_OK);
    el_frame2d f;
    ck_assert_int_eq(el_pca_normalize(res.xy, res.n, &f, res.xy), EL_OK);
    ck_assert_int_eq(el_frame2d_to_local(&f, 1, ti, ti), EL_OK);
    el_inflection inf;
    ck_assert_int_eq(el_find_inflection(res.xy, res.n, 0, &inf), EL_OK);
    ck_assert(inf.index < res.n && (inf.neighbor + 1 == inf.index || inf.index + 1 == inf.neighbor));
    ck_assert(inf.end == 0 || inf.end == res.n - 1);
    double e = hypot(res.xy[2 * inf.index] - ti[0], res.xy[2 * inf.index + 1] - ti[1]) / r;
    el_resample_free(&res);
    *rout = r;
    return e;
}

START_TEST(test_inflection_cubic)
{
    /* The RDP-style estimate is local: near the inflection the curve is almost
     * straight, so noise moves it. Noise-free it is the vertex next to the true
     * inflection; the error grows about like sqrt(noise) (measured over 100
     * curves: mean 0.5 r at 1e-6 of the length, 1.5 r at 1e-5, 4.7 r at 1e-4). */
    unsigned long long st = 2024;
    double r, worst[3] = {0, 0, 0}, mean[3] = {0, 0, 0};
    const double noise[3] = {0.0, 2e-6, 2e-5};   /* absolute, the curve is 2 long */
    const int trials = 30;
    for (int t = 0; t < trials; t++)
        for (int k = 0; k < 3; k++) {
            double e = cubic_trial(&st, noise[k], &r);
            worst[k] = fmax(worst[k], e);
            mean[k] += e / trials;
        }
    ck_assert_msg(worst[0] <= 1.0, "noise-free: %g r from the inflection", worst[0]);
    ck_assert_msg(worst[1] <= 3.0, "noise 1e-6 of the length: %g r from the inflection", worst[1]);
    ck_assert_msg(worst[2] <= 10.0 && mean[2] <= 3.0, "noise 1e-5 of the length: worst %g r, mean %g r",
                  worst[2], mean[2]);
}
END_TEST

START_TEST(test_inflection_invariance)
{
    /* the estimate does not depend on rotation, translation or the walking direction */
    enum { N = 300 };
    double p[2 * N], q[2 * N], rv[2 * N];
    unsigned long long st = 5;
    for (size_t i = 0; i < N; i++) {
        double t = -1.2 + 2.9 * (double)i / (N - 1);
        p[2 * i] = t;
        p[2 * i + 1] = sin(2.2 * t) * 0.4 + 0.002 * test_normal(&st);
    }
    el_inflection a, b, c;
    ck_assert_int_eq(el_find_inflection(p, N, 0, &a), EL_OK);
    for (int k = 0; k < 8; k++) {
        double ang = test_uniform(&st, -M_PI, M_PI), ox = test_uniform(&st, -1e3, 1e3);
        for (size_t i = 0; i < N; i++) {
            q[2 * i] = ox + cos(ang) * p[2 * i] - sin(ang) * p[2 * i + 1];
            q[2 * i + 1] = -ox + sin(ang) * p[2 * i] + cos(ang) * p[2 * i + 1];
        }
        ck_assert_int_eq(el_find_inflection(q, N, 0, &b), EL_OK);
        ck_assert_uint_eq(b.index, a.index);
    }
    for (size_t i = 0; i < N; i++) { rv[2 * i] = p[2 * (N - 1 - i)]; rv[2 * i + 1] = p[2 * (N - 1 - i) + 1]; }
    ck_assert_int_eq(el_find_inflection(rv, N, 0, &c), EL_OK);
    ck_assert_uint_eq(c.index, N - 1 - a.index);
    ck_assert_uint_eq(c.apex, N - 1 - a.apex);
}
END_TEST

START_TEST(test_inflection_near_end)
{
    /* sin on [0, 1.15 pi]: the lobe beyond the inflection (x = pi) is tiny */
    enum { N = 800 };
    double p[2 * N];
    for (size_t i = 0; i < N; i++) {
        double t = 1.15 * M_PI * (double)i / (N - 1);
        p[2 * i] = t;
        p[2 * i + 1] = sin(t);
    }
    el_inflection inf;
    for (int side = 0; side <= 1; side++) {
        ck_assert_int_eq(el_find_inflection(p, N, side, &inf), EL_OK);
        ck_assert_uint_eq(inf.end, N - 1);
        ck_assert(fabs(p[2 * inf.index] - M_PI) <= 1.5 * (p[2] - p[0]));
    }
    /* forcing the wrong side finds no sign change there: the answer is not near pi */
    ck_assert_int_eq(el_find_inflection(p, N, -1, &inf), EL_OK);
    ck_assert_uint_eq(inf.end, 0);
    ck_assert(fabs(p[2 * inf.index] - M_PI) > 1.0);
}
END_TEST

START_TEST(test_inflection_bad_input)
{
    enum { N = 50 };
    double p[2 * N];
    el_inflection inf;
    memset(&inf, 0, sizeof inf);
    inf.index = 99;
    /* convex arc: no inflection */
    for (size_t i = 0; i < N; i++) { p[2 * i] = cos(2.0 * i / N); p[2 * i + 1] = sin(2.0 * i / N); }
    ck_assert_int_eq(el_find_inflection(p, N, 0, &inf), EL_EDOM);
    /* collinear */
    for (size_t i = 0; i < N; i++) { p[2 * i] = 0.1 * i; p[2 * i + 1] = 0.3 * i; }
    ck_assert_int_eq(el_find_inflection(p, N, 0, &inf), EL_EDOM);
    /* closed loop */
    for (size_t i = 0; i < N; i++) {
        p[2 * i] = cos(2 * M_PI * i / (N - 1)) + 0.3 * cos(6 * M_PI * i / (N - 1));
        p[2 * i + 1] = sin(2 * M_PI * i / (N - 1));
    }
    ck_assert_int_eq(el_find_inflection(p, N, 0, &inf), EL_EDOM);
    /* all equal */
    for (size_t i = 0; i < 2 * N; i++) p[i] = 1.25;
    ck_assert_int_eq(el_find_inflection(p, N, 0, &inf), EL_ESINGULAR);
    for (size_t i = 0; i < N; i++) { p[2 * i] = i; p[2 * i + 1] = sin(0.2 * i); }
    ck_assert_int_eq(el_find_inflection(p, 3, 0, &inf), EL_EINVAL);
    ck_assert_int_eq(el_find_inflection(p, N, 2, &inf), EL_EINVAL);
    ck_assert_int_eq(el_find_inflection(NULL, N, 0, &inf), EL_EINVAL);
    ck_assert_int_eq(el_find_inflection(p, N, 0, NULL), EL_EINVAL);
    p[7] = INFINITY;
    ck_assert_int_eq(el_find_inflection(p, N, 0, &inf), EL_EINVAL);
    ck_assert_uint_eq(inf.index, 99);
    /* four points, the smallest S */
    double s4[8] = {0, 0, 1, 1, 2, -1, 3, 0};
    ck_assert_int_eq(el_find_inflection(s4, 4, 0, &inf), EL_OK);
    ck_assert(inf.index == 1 || inf.index == 2);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("prep");
    TCase *tc = tcase_create("prep");
    tcase_add_loop_test(tc, test_plane_fit_recovers_plane, 0, 9);
    tcase_add_test(tc, test_plane_fit_noisy);
    tcase_add_test(tc, test_plane_fit_sign_convention);
    tcase_add_test(tc, test_plane_fit_bad_input);
    tcase_add_loop_test(tc, test_pca_normalize, 0, 4);
    tcase_add_test(tc, test_pca_bad_input);
    tcase_add_test(tc, test_resample_straight);
    tcase_add_test(tc, test_resample_s_curve);
    tcase_add_test(tc, test_resample_hairpin);
    tcase_add_test(tc, test_resample_stop_point);
    tcase_add_test(tc, test_resample_bad_input);
    tcase_add_test(tc, test_inflection_cubic);
    tcase_add_test(tc, test_inflection_invariance);
    tcase_add_test(tc, test_inflection_near_end);
    tcase_add_test(tc, test_inflection_bad_input);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
