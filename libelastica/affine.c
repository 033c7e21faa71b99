/*
 * Affine arc-length polylines, seed 002 (Kaeferboeck, "Affine arc length
 * polylines and curvature continuous uniform B-splines"): the invariants of a
 * given polyline and the B-splines built on it.
 *
 *   §2.1  affine polyline coordinates A_i, B_i (1), affine length L2 (3)
 *   §2.2  discrete affine curvature k_i (4), affine evolute (5)
 *   §2.4  inner / outer / middle osculating conics and their curvatures (7)
 *   §2.5  Chaikin subdivision, uniform quadratic B-splines (G2 <=> A_i = A)
 *   §3    R^n: affine length elements (8), (9), Theorem 4, Lane–Riesenfeld (10)
 *
 * §4, the approximation of a curve by an affine arc-length polyline, is in
 * affine_polyline.c.
 */
#include "affine_internal.h"
#include <gsl/gsl_linalg.h>
#include <float.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ §2.1, (1), (3) */

int el_affine_coords(size_t npts, const double *xy, double *A, double *B)
{
    if (points_ok(npts, xy, 3) || !A) return EL_EINVAL;
    if (edges_in_range(npts, xy)) return EL_EDOM;
    for (size_t i = 1; i + 1 < npts; i++) {
        double vm[2], v0[2];
        edge(xy, i - 1, vm);
        edge(xy, i, v0);
        A[i - 1] = det2(vm[0], vm[1], v0[0], v0[1]);
        if (B && i + 2 < npts) {
            double vp[2];
            edge(xy, i + 1, vp);
            B[i - 1] = det2(vm[0], vm[1], vp[0], vp[1]);
        }
    }
    return EL_OK;
}

int el_affine_length(size_t npts, const double *xy, double *L2)
{
    if (points_ok(npts, xy, 3) || !L2) return EL_EINVAL;
    if (edges_in_range(npts, xy)) return EL_EDOM;
    double sum = 0.0;
    for (size_t i = 1; i + 1 < npts; i++) {
        double vm[2], v0[2];
        edge(xy, i - 1, vm);
        edge(xy, i, v0);
        sum += cbrt(det2(vm[0], vm[1], v0[0], v0[1]));   /* (3) */
    }
    *L2 = sum;
    return EL_OK;
}

/* k_i of the quadruple x_{i-1}..x_{i+2} (4): det(n_i, n_{i+1}) / A with
 * det(n_i, n_{i+1}) = A_i + A_{i+1} - B_i and A = (A_i + A_{i+1}) / 2. */
static int quad_k(const double *xy, size_t i, double *k, double *Ai, double *Ai1)
{
    double vm[2], v0[2], vp[2];
    edge(xy, i - 1, vm);
    edge(xy, i, v0);
    edge(xy, i + 1, vp);
    double a0 = det2(vm[0], vm[1], v0[0], v0[1]);
    double a1 = det2(v0[0], v0[1], vp[0], vp[1]);
    double b = det2(vm[0], vm[1], vp[0], vp[1]);
    double A = 0.5 * (a0 + a1);
    if (A == 0.0) return EL_ESINGULAR;
    *k = (a0 + a1 - b) / A;
    if (Ai) *Ai = a0;
    if (Ai1) *Ai1 = a1;
    return EL_OK;
}

int el_affine_curvature(size_t npts, const double *xy, double *k)
{
    if (points_ok(npts, xy, 4) || !k) return EL_EINVAL;
    if (edges_in_range(npts, xy)) return EL_EDOM;
    for (size_t i = 1; i + 2 < npts; i++) {
        int st = quad_k(xy, i, &k[i - 1], NULL, NULL);
        if (st) return st;
    }
    return EL_OK;
}

/* -------------------------------------------------------- §2.4, Theorem 2, (7) */

/*
 * Derivation (ours; the paper proves (7) in a normal form only). In the affine
 * frame o = (x_i + x_{i+1})/2, e1 = v_i/2, e2 = (v_{i+1} - v_{i-1})/2 the quadruple
 * is x_i = (-1,0), x_{i+1} = (1,0), x_{i-1} = (-(3-k),1), x_{i+2} = (3-k,1) (by (4)),
 * the evolute point (5) is (0, 1/k), and the conics symmetric in u with that
 * centre are u^2 + k(4-k) w^2 - 2(4-k) w + delta = 0:
 *   outer (through the 4 points)                      delta = -1
 *   inner (tangent to w = 0 at u = 0, scaled sqrt(1-k/4)) delta = 0
 *   middle (scaled (1-k/4)^(1/4), the geometric mean)  delta = -sqrt(4-k)/(2+sqrt(4-k)).
 * det(e1, e2) = (A_i + A_{i+1})/4 = A/2.
 */
/* The conic of `kind` of the quadruple x_{i-1}..x_{i+2} into *cn: EL_ESINGULAR
 * (A = 0), EL_EDOM (not equal-area, k_i >= 4 for inner / middle, or a value
 * beyond double's range: coordinates far from the points' scale). */
static int conic_of(const double *xy, size_t i, int kind, el_affine_conic *cn)
{
    double k, a0, a1;
    int st = quad_k(xy, i, &k, &a0, &a1);
    if (st) return st;
    if (fabs(a0 - a1) > 1e-6 * fmax(fabs(a0), fabs(a1))) return EL_EDOM;
    if (kind != EL_CONIC_OUTER && !(k < 4.0)) return EL_EDOM;
    double A = 0.5 * (a0 + a1);
    const double *xm = xy + 2 * (i - 1), *x0 = xy + 2 * i, *x1 = xy + 2 * (i + 1),
                 *x2 = xy + 2 * (i + 2);
    double o[2] = {0.5 * (x0[0] + x1[0]), 0.5 * (x0[1] + x1[1])};
    double e1[2] = {0.5 * (x1[0] - x0[0]), 0.5 * (x1[1] - x0[1])};
    double e2[2] = {0.5 * (xm[0] + x2[0]) - o[0], 0.5 * (xm[1] + x2[1]) - o[1]};
    double de = det2(e1[0], e1[1], e2[0], e2[1]);
    /* rows of E^{-1}, E = [e1 e2]: (u, w) = E^{-1} (X - o) */
    double r1[2] = {e2[1] / de, -e2[0] / de};
    double r2[2] = {-e1[1] / de, e1[0] / de};
    double beta = k * (4.0 - k), gamma = -2.0 * (4.0 - k), delta;
    double fac; /* (1-k/4)^p of (7) */
    if (kind == EL_CONIC_OUTER) {
        delta = -1.0;
        fac = cbrt(1.0 - 0.25 * k);
    } else if (kind == EL_CONIC_INNER) {
        delta = 0.0;
        fac = 1.0 / cbrt(1.0 - 0.25 * k);
    } else {
        double r = sqrt(4.0 - k);
        delta = -r / (2.0 + r);
        fac = 1.0;
    }
    double P11 = r1[0] * r1[0] + beta * r2[0] * r2[0];
    double P12 = r1[0] * r1[1] + beta * r2[0] * r2[1];
    double P22 = r1[1] * r1[1] + beta * r2[1] * r2[1];
    double L[2] = {gamma * r2[0], gamma * r2[1]};
    double Po[2] = {P11 * o[0] + P12 * o[1], P12 * o[0] + P22 * o[1]};
    double c[6] = {P11, 2.0 * P12, P22, -2.0 * Po[0] + L[0], -2.0 * Po[1] + L[1],
                   o[0] * Po[0] + o[1] * Po[1] - L[0] * o[0] - L[1] * o[1] + delta};
    double sc = fmax(fabs(c[0]), fmax(fabs(c[1]), fabs(c[2])));
    for (int j = 0; j < 6; j++) cn->coef[j] = c[j] / sc;
    cn->type = k > 0.0 ? 1 : (k < 0.0 ? -1 : 0);
    if (k != 0.0) { /* (5): xi_i = x_i + n_i / k_i */
        cn->center[0] = x0[0] + (xm[0] - 2.0 * x0[0] + x1[0]) / k;
        cn->center[1] = x0[1] + (xm[1] - 2.0 * x0[1] + x1[1]) / k;
    } else {
        cn->center[0] = cn->center[1] = 0.0;
    }
    double Am23 = 1.0 / (cbrt(A) * cbrt(A)); /* A^(-2/3), real cube root */
    cn->kappa = Am23 * k * fac;               /* (7) */
    if (el__all_finite(cn->coef, 6) || el__all_finite(cn->center, 2) || !isfinite(cn->kappa))
        return EL_EDOM;
    return EL_OK;
}

int el_affine_osculating_conics(size_t npts, const double *xy, int kind, el_affine_conic *out)
{
    if (points_ok(npts, xy, 4) || !out) return EL_EINVAL;
    if (kind != EL_CONIC_OUTER && kind != EL_CONIC_INNER && kind != EL_CONIC_MIDDLE) return EL_EINVAL;
    if (edges_in_range(npts, xy)) return EL_EDOM;
    size_t m = npts - 3;
    /* validate everything first: outputs untouched on error */
    for (size_t i = 1; i <= m; i++) {
        el_affine_conic cn;
        int st = conic_of(xy, i, kind, &cn);
        if (st) return st;
    }
    for (size_t i = 1; i <= m; i++) conic_of(xy, i, kind, &out[i - 1]);
    return EL_OK;
}

/* ------------------------------------------------------------ §2.5, Theorem 5 */

int el_affine_chaikin(size_t npts, const double *xy, double *out)
{
    if (points_ok(npts, xy, 2) || !out) return EL_EINVAL;
    for (size_t i = 0; i + 1 < npts; i++)
        for (int c = 0; c < 2; c++) {
            double a = xy[2 * i + c], b = xy[2 * (i + 1) + c];
            out[4 * i + c] = 0.75 * a + 0.25 * b;       /* x_{i+1/4} */
            out[4 * i + 2 + c] = 0.25 * a + 0.75 * b;   /* x_{i+3/4} */
        }
    return EL_OK;
}

int el_affine_lane_riesenfeld(int dim, int degree, size_t npts, const double *x, double *out)
{
    if (dim < 1 || degree < 1 || !x || !out || npts < 1) return EL_EINVAL;
    size_t d = (size_t)dim, len = 2 * npts;
    /* x holds d npts doubles, the workspace twice as many */
    if (el__too_many(npts, 2 * d, sizeof(double)) || len <= (size_t)degree) return EL_EINVAL;
    if (el__all_finite(x, d * npts)) return EL_EINVAL;
    double *w = el__alloc(len, d, sizeof *w);
    if (!w) return EL_ENOMEM;
    for (size_t i = 0; i < npts; i++)
        for (size_t c = 0; c < d; c++) w[2 * i * d + c] = w[(2 * i + 1) * d + c] = x[i * d + c];
    for (int r = 0; r < degree; r++, len--)      /* mu^degree (halves first: no overflow) */
        for (size_t i = 0; i + 1 < len; i++)
            for (size_t c = 0; c < d; c++) w[i * d + c] = 0.5 * w[i * d + c] + 0.5 * w[(i + 1) * d + c];
    memcpy(out, w, len * d * sizeof *w);
    free(w);
    return EL_OK;
}

/* ------------------------------------------------------------ §3, (8), (9) */

/*
 * det(dx_i..dx_{i+n-1}) by GSL's LU on the columns scaled by powers of two (exact),
 * so that entries near 1e+-300 neither overflow nor underflow inside the
 * elimination: *mant * 2^*expo is the determinant, |mant| in [1/2, 1) (mant = 0
 * for a zero column, or a zero pivot, which partial pivoting meets only on a
 * singular matrix).
 */
static int scaled_det(size_t n, const double *x, size_t i, gsl_matrix *M, gsl_permutation *perm,
                      double *mant, long *expo)
{
    long e = 0;
    *mant = 0.0;
    *expo = 0;
    for (size_t c = 0; c < n; c++) {       /* column c = dx_{i+c} */
        double big = 0.0;
        for (size_t r = 0; r < n; r++) {
            const double v = x[(i + c + 1) * n + r] - x[(i + c) * n + r];
            gsl_matrix_set(M, r, c, v);
            big = fmax(big, fabs(v));
        }
        if (!isfinite(big)) return EL_EDOM;   /* an edge overflows */
        if (big == 0.0) return EL_OK;          /* repeated point: det = 0 */
        const int ec = ilogb(big);
        for (size_t r = 0; r < n; r++) gsl_matrix_set(M, r, c, ldexp(gsl_matrix_get(M, r, c), -ec));
        e += ec;
    }
    int signum;
    if (gsl_linalg_LU_decomp(M, perm, &signum)) return EL_EINTERNAL;
    double m = signum;
    for (size_t r = 0; r < n; r++) {   /* the pivots' product, renormalised as it goes */
        int k;
        m = frexp(m * gsl_matrix_get(M, r, r), &k);
        e += k;
        if (m == 0.0) return EL_OK;    /* a zero pivot: singular */
    }
    if (!isfinite(m)) return EL_EINTERNAL;
    *mant = m;
    *expo = e;
    return EL_OK;
}

int el_affine_elements_nd(int dim, size_t npts, const double *x, double *D, double *Ln)
{
    if (dim < 2 || !x || npts < (size_t)dim + 1) return EL_EINVAL;
    size_t n = (size_t)dim;
    if (el__too_many(npts, n, sizeof(double)) || el__all_finite(x, n * npts)) return EL_EINVAL;
    el__gsl_quiet();
    gsl_matrix *M = gsl_matrix_alloc(n, n);
    gsl_permutation *perm = gsl_permutation_alloc(n);
    if (!M || !perm) {
        gsl_matrix_free(M);
        gsl_permutation_free(perm);
        return EL_ENOMEM;
    }
    int st = EL_OK;
    double sum = 0.0, ex = 2.0 / ((double)n * (double)(n + 1));
    /* validate first (every element in double's range), then write */
    for (int pass = 0; pass < 2 && st == EL_OK; pass++) {
        for (size_t i = 0; i + n < npts && st == EL_OK; i++) {
            double mant;
            long e;
            if ((st = scaled_det(n, x, i, M, perm, &mant, &e))) break;
            /* |mant| in [1/2, 1): D = mant 2^e must be a double */
            if (mant != 0.0 && e > DBL_MAX_EXP) { st = EL_EDOM; break; }
            if (pass == 0) continue;
            if (D) D[i] = mant == 0.0 ? 0.0 : ldexp(mant, (int)fmax((double)e, -2100.0));
            /* (8) from the logarithm, which does not underflow with D */
            if (mant != 0.0)
                sum += (mant < 0 ? -1.0 : 1.0) * exp2(ex * (log2(fabs(mant)) + (double)e));
        }
    }
    gsl_matrix_free(M);
    gsl_permutation_free(perm);
    if (st == EL_OK && Ln) *Ln = sum;
    return st;
}

/* -------------------------------------------------- uniform B-splines, Theorem 4 */

/* Blossom F(u_1..u_n) of the uniform spline (knots t_i = i) on the span [m, m+1],
 * controls x_{m-n}..x_m, by de Boor's algorithm with one argument per level. */
static void uniform_blossom(size_t d, int n, const double *x, size_t m, const double *u,
                            double *work, double *res)
{
    for (int i = 0; i <= n; i++) memcpy(work + i * d, x + (m - (size_t)n + (size_t)i) * d, d * sizeof *work);
    for (int r = 1; r <= n; r++)
        for (int i = n; i >= r; i--) {
            double g = (double)(m - (size_t)n + (size_t)i);
            double alpha = (u[r - 1] - g) / (double)(n + 1 - r);
            for (size_t c = 0; c < d; c++)
                work[i * d + c] = (1.0 - alpha) * work[(i - 1) * d + c] + alpha * work[i * d + c];
        }
    memcpy(res, work + n * d, d * sizeof *res);
}

int el_affine_uniform_bspline(int dim, int degree, size_t npts, const double *x,
                              int clamped, struct el_bspline *out)
{
    if (dim < 1 || degree < 1 || !x || !out || npts < (size_t)degree + 1) return EL_EINVAL;
    size_t d = (size_t)dim, n = (size_t)degree, N = npts - 1;
    if (el__too_many(npts, d, 2 * sizeof(double)) || el__all_finite(x, d * npts)) return EL_EINVAL;
    size_t nk = clamped ? N - n + 2 : npts + n + 1;
    double *poles = el__alloc(npts, d, sizeof *poles);
    double *knots = el__alloc(nk, 1, sizeof *knots);
    int *mults = el__alloc(nk, 1, sizeof *mults);
    double *work = el__alloc(n + 1, d, sizeof *work);
    double *u = el__alloc(n, 1, sizeof *u);
    if (!poles || !knots || !mults || !work || !u) {
        free(poles); free(knots); free(mults); free(work); free(u);
        return EL_ENOMEM;
    }
    memcpy(poles, x, d * npts * sizeof *poles);
    for (size_t j = 0; j < nk; j++) {
        knots[j] = (double)j;
        mults[j] = 1;
    }
    if (clamped) {
        mults[0] = mults[nk - 1] = degree + 1;
        /* Clamped knots T'_l = max(n, min(l, N+1)) (unshifted); pole j is the
         * blossom at T'_{j+1..j+n} (de Boor–Fix), evaluated on the first span
         * [n, n+1] for the left poles and on the last span [N, N+1] for the right. */
        for (size_t j = 0; j + 2 <= n; j++) {
            for (size_t r = 0; r < n; r++) u[r] = (double)(j + 1 + r < n ? n : j + 1 + r);
            uniform_blossom(d, degree, x, n, u, work, poles + j * d);
        }
        for (size_t j = N + 2 - n; j <= N && n >= 2; j++) {
            if (j + 2 <= n) continue; /* already a left pole (short polylines) */
            for (size_t r = 0; r < n; r++) u[r] = (double)(j + 1 + r > N + 1 ? N + 1 : j + 1 + r);
            uniform_blossom(d, degree, x, N, u, work, poles + j * d);
        }
    }
    free(work);
    free(u);
    if (clamped && el__all_finite(poles, d * npts)) {   /* the blossoms extrapolate: may overflow */
        free(poles); free(knots); free(mults);
        return EL_EDOM;
    }
    out->degree = degree;
    out->dim = dim;
    out->npoles = npts;
    out->poles = poles;
    out->nknots = nk;
    out->knots = knots;
    out->mults = mults;
    out->max_deviation = 0.0;
    return EL_OK;
}

int el_affine_quadratic_bspline(size_t npts, const double *xy, int clamped, struct el_bspline *out)
{
    if (points_ok(npts, xy, 3)) return EL_EINVAL;
    return el_affine_uniform_bspline(2, 2, npts, xy, clamped, out);
}

/* ------------------------------------------ exact end points, every joint kept G2 */

/*
 * Derivation (ours; the paper leaves the ends open). The uniform quadratic B-spline
 * of x_0..x_m is the chain of parabolas (m_i, x_i, m_{i+1}), m_i = (x_{i-1} + x_i)/2,
 * i = 1..m-1; a quadratic Bezier (b0, b1, b2) has curvature det(b1-b0, b2-b1) /
 * (2 |b1-b0|^3) at b0 and det(b1-b0, b2-b1) / (2 |b2-b1|^3) at b2, so segment i
 * starts with curvature A_i / |v_{i-1}|^3 and ends with A_i / |v_i|^3 (G2 at m_i iff
 * A_{i-1} = A_i, §2.5). The first segment is replaced by the parabola
 * (P, c, m_2) with c = m_2 - (lambda/2) v_1 on the joint's tangent line: it ends
 * with curvature 2 det(m_2 - P, v_1) / (lambda^2 |v_1|^3), which equals the next
 * segment's A_2 / |v_1|^3 iff lambda^2 = 2 det(m_2 - P, v_1) / A_2. As a B-spline,
 * c and x_2 are consecutive poles with knot intervals lambda and 1 (the joint
 * (c + lambda x_2) / (1 + lambda) is m_2). For P = x_0 on an affine arc-length
 * polyline lambda = sqrt 2. The last segment mirrors this.
 */
/* The end parabola (P, c, m) [sgn = +1] or (m, c, P) [sgn = -1] meeting the joint m with
 * tangent v and curvature A / |v|^3: its knot interval lambda and control point c. */
static int g2_end(const double *P, const double *m, const double *v, double A, double sgn,
                  double *lambda, double c[2])
{
    if (A == 0.0) return EL_ESINGULAR;
    /* start: 2 det(m_2 - P, v_1) / A_2; end: 2 det(v_{m-2}, P - m_{m-1}) / A_{m-2}, the same */
    double l2 = 2.0 * det2(m[0] - P[0], m[1] - P[1], v[0], v[1]) / A;
    if (!(l2 > 0.0) || !isfinite(l2)) return EL_EDOM;   /* P not ahead of the joint's tangent */
    *lambda = sqrt(l2);
    c[0] = m[0] - sgn * 0.5 * *lambda * v[0];
    c[1] = m[1] - sgn * 0.5 * *lambda * v[1];
    return EL_OK;
}

int el_affine_g2_bspline(size_t npts, const double *xy, const double *start, const double *end,
                         struct el_bspline *out)
{
    if (points_ok(npts, xy, 4) || !out) return EL_EINVAL;
    if ((start && el__all_finite(start, 2)) || (end && el__all_finite(end, 2))) return EL_EINVAL;
    size_t m = npts - 1;
    double v1[2], vl[2], m2[2], ml[2], a[4];
    edge(xy, 1, v1);
    edge(xy, m - 2, vl);
    /* A_2 = det(v_1, v_2) and A_{m-2} = det(v_{m-3}, v_{m-2}) (A_1, A_2 when m = 3) */
    {
        double va[2], vb[2];
        edge(xy, 1, va);
        edge(xy, 2, vb);
        a[0] = det2(va[0], va[1], vb[0], vb[1]);
        edge(xy, m - 3, va);
        edge(xy, m - 2, vb);
        a[1] = det2(va[0], va[1], vb[0], vb[1]);
    }
    m2[0] = 0.5 * (xy[2] + xy[4]);
    m2[1] = 0.5 * (xy[3] + xy[5]);
    ml[0] = 0.5 * (xy[2 * (m - 2)] + xy[2 * (m - 1)]);
    ml[1] = 0.5 * (xy[2 * (m - 2) + 1] + xy[2 * (m - 1) + 1]);
    double lam = 1.0, mu = 1.0, c0[2] = {xy[2], xy[3]}, c1[2] = {xy[2 * (m - 1)], xy[2 * (m - 1) + 1]};
    double p0[2] = {0.5 * (xy[0] + xy[2]), 0.5 * (xy[1] + xy[3])};
    double p1[2] = {0.5 * (xy[2 * (m - 1)] + xy[2 * m]), 0.5 * (xy[2 * (m - 1) + 1] + xy[2 * m + 1])};
    int st;
    if (start) {
        if ((st = g2_end(start, m2, v1, a[0], 1.0, &lam, c0))) return st;
        memcpy(p0, start, sizeof p0);
    }
    if (end) {   /* mirrored: c_1 = m_{m-1} + (mu/2) v_{m-2} */
        if ((st = g2_end(end, ml, vl, a[1], -1.0, &mu, c1))) return st;
        memcpy(p1, end, sizeof p1);
    }
    el_bspline b;
    if ((st = el_bspline_alloc(&b, 2, 2, npts, m))) return st;
    memcpy(b.poles, p0, sizeof p0);
    memcpy(b.poles + 2, c0, sizeof c0);
    memcpy(b.poles + 4, xy + 4, 2 * (m - 3) * sizeof *xy);     /* x_2 .. x_{m-2} */
    memcpy(b.poles + 2 * (m - 1), c1, sizeof c1);
    memcpy(b.poles + 2 * m, p1, sizeof p1);
    b.knots[0] = 0.0;
    for (size_t j = 1; j + 1 < m; j++) b.knots[j] = lam + (double)(j - 1);
    b.knots[m - 1] = lam + (double)(m - 3) + mu;
    for (size_t j = 0; j < m; j++) b.mults[j] = 1;
    b.mults[0] = b.mults[m - 1] = 3;
    b.max_deviation = -1.0;
    if (el_bspline_check(&b)) {   /* end points so far away that the knots or poles overflow */
        el_bspline_free(&b);
        return EL_EDOM;
    }
    *out = b;
    return EL_OK;
}
