/*
 * Blending-function curves of seed 003 (Miura, Gobithaasan, Shida, Wang,
 * Misro: "Curve modeling with Jacobi elliptic functions"), built like Eck's
 * MQ-curves. See the header for the conventions; the derivation:
 *
 * A segment phi(t) = sum_i q_i h_i(t) with h_0, h_1 in span{f_0..f_3} (2.13),
 * h_2(t) = h_1(1-t), h_3(t) = h_0(1-t). Since f_0 <-> f_3 and f_1 <-> f_2 under
 * t -> 1-t, h_3 has the coefficients of h_0 reversed and h_2 those of h_1.
 *  - Bezier-like ends: phi(0) = q_0 needs h_0(0) = 1, h_1(0) = h_2(0) = h_3(0) = 0,
 *    i.e. h_0(0) = 1, h_1(0) = 0, h_1(1) = 0, h_0(1) = 0.
 *  - phi'(0) parallel to q_1 - q_0 (2.8)/(2.11) needs h_2'(0) = h_3'(0) = 0,
 *    i.e. h_1'(1) = 0 and h_0'(1) = 0 (2.9)/(2.10).
 *  - the free end-derivative: h_0'(0) = -d (2.14); with the partition of unity
 *    h_1'(0) = d, so phi'(0) = d (q_1 - q_0) and phi'(1) = d (q_3 - q_2).
 *  - partition of unity (2.15): sum_i h_i = A (f_0 + f_3) + B (f_1 + f_2) with
 *    A = a_0 + a_3 + b_0 + b_3, B = a_1 + a_2 + b_1 + b_2; f_0 + f_3 = 1, so
 *    A = 1, B = 0. The end conditions give sum_i h_i(0) = 1 = A + B (f_1(0) + f_1(1)),
 *    so B = 0 implies A = 1: the ninth condition is redundant (the paper's
 *    "9 constraints, linearly dependent"), and the 8x8 system (2.17) keeps B = 0.
 * For the elliptic span the rows are exactly the paper's printed (2.17)
 * (f_1(0) = sn K = 1, f_1'(1) = -K, f_2'(0) = K, f_1'(0) = -K cn K dn K = 0).
 * Closed form there: a_1 = (K - d) / (K (2 - K)), singular at K(k) = 2.
 * For the MQ span, d = 1/alpha(c) (2.5) reproduces Eck's Omega_i (2.4); the
 * printed Omega_1 swaps the two square roots (it does not vanish at t = 0 for
 * c != 1), the form that does is (s+c)^2 beta/alpha (t + c f_1 - s f_2).
 */
#include "internal.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_permutation.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_sf_elljac.h>

/* Condition number above which the 8x8 (2.17) or a 4x4 collocation system is singular. */
static const double COND_MAX = 1e13;

/* basis_min below this is rounding, not a negative basis function. */
static const double HULL_TOL = 1e-12;

static int basis_stats(el_blend_basis *b);
static int span_at(const el_blend_basis *b, double t, double f[4], double df[4], double d2f[4]);
static int basis_at(const el_blend_basis *b, double t, double h[4], double dh[4], double d2h[4]);

int el__blend_span_at(const el_blend_basis *b, double t, double f[4], double df[4], double d2f[4])
{
    return span_at(b, t, f, df, d2f);
}

int el__blend_basis_at(const el_blend_basis *b, double t, double h[4], double dh[4], double d2h[4])
{
    return basis_at(b, t, h, dh, d2h);
}

int el__blend_basis_ok(const el_blend_basis *b)
{
    if (!b || (b->kind != EL_BLEND_MQ && b->kind != EL_BLEND_ELLIPTIC)) return 0;
    return b->d > 0.0 && isfinite(b->d);
}

/* f_j(t), f_j'(t), f_j''(t) of the span (2.1) / (2.16); any output may be NULL. */
static int span_at(const el_blend_basis *b, double t, double f[4], double df[4], double d2f[4])
{
    double v[4], dv[4], d2v[4];
    v[0] = 1.0 - t; dv[0] = -1.0; d2v[0] = 0.0;
    v[3] = t;       dv[3] = 1.0;  d2v[3] = 0.0;
    if (b->kind == EL_BLEND_MQ) {
        const double c = b->c, c2 = c * c;
        const double r1 = hypot(c, 1.0 - t), r2 = hypot(c, t);
        v[1] = r1; dv[1] = -(1.0 - t) / r1; d2v[1] = c2 / (r1 * r1 * r1);
        v[2] = r2; dv[2] = t / r2;          d2v[2] = c2 / (r2 * r2 * r2);
    } else {
        const double K = b->K, k2 = b->k * b->k;
        double sn1, cn1, dn1, sn2, cn2, dn2;
        if (gsl_sf_elljac_e((1.0 - t) * K, k2, &sn1, &cn1, &dn1) != GSL_SUCCESS ||
            gsl_sf_elljac_e(t * K, k2, &sn2, &cn2, &dn2) != GSL_SUCCESS)
            return EL_EINTERNAL;
        /* d/du sn = cn dn, d2/du2 sn = -sn (dn^2 + k^2 cn^2) */
        v[1] = sn1; dv[1] = -K * cn1 * dn1; d2v[1] = -K * K * sn1 * (dn1 * dn1 + k2 * cn1 * cn1);
        v[2] = sn2; dv[2] = K * cn2 * dn2;  d2v[2] = -K * K * sn2 * (dn2 * dn2 + k2 * cn2 * cn2);
    }
    if (f) memcpy(f, v, sizeof v);
    if (df) memcpy(df, dv, sizeof dv);
    if (d2f) memcpy(d2f, d2v, sizeof d2v);
    return EL_OK;
}

/* 1-norm of an n x n matrix. */
static double norm1(const gsl_matrix *A)
{
    double best = 0.0;
    for (size_t j = 0; j < A->size2; j++) {
        double s = 0.0;
        for (size_t i = 0; i < A->size1; i++) s += fabs(gsl_matrix_get(A, i, j));
        if (s > best) best = s;
    }
    return best;
}

/*
 * Invert the n x n row-major matrix a into ainv by GSL's LU; *cond = the 1-norm
 * condition number. EL_ESINGULAR when a pivot vanishes or cond > COND_MAX.
 */
static int invert(size_t n, const double *a, double *ainv, double *cond)
{
    gsl_matrix *A = gsl_matrix_alloc(n, n), *Ai = gsl_matrix_alloc(n, n);
    gsl_permutation *perm = gsl_permutation_alloc(n);
    int st = EL_OK, sign;
    if (!A || !Ai || !perm) { st = EL_ENOMEM; goto done; }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) gsl_matrix_set(A, i, j, a[i * n + j]);
    const double anorm = norm1(A);
    if (gsl_linalg_LU_decomp(A, perm, &sign) != GSL_SUCCESS) { st = EL_EINTERNAL; goto done; }
    for (size_t i = 0; i < n; i++)
        if (gsl_matrix_get(A, i, i) == 0.0) { st = EL_ESINGULAR; goto done; }
    if (gsl_linalg_LU_invert(A, perm, Ai) != GSL_SUCCESS) { st = EL_ESINGULAR; goto done; }
    for (size_t i = 0; i < n; i++)   /* (an inverse beyond double's range is singular too) */
        for (size_t j = 0; j < n; j++)
            if (!isfinite(gsl_matrix_get(Ai, i, j))) { st = EL_ESINGULAR; goto done; }
    const double c = anorm * norm1(Ai);
    if (!(c <= COND_MAX)) { st = EL_ESINGULAR; goto done; }
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) ainv[i * n + j] = gsl_matrix_get(Ai, i, j);
    if (cond) *cond = c;
done:
    gsl_matrix_free(A);
    gsl_matrix_free(Ai);
    gsl_permutation_free(perm);
    return st;
}

/*
 * The span in the equivalent "bubble" form g = (f_0, B_1, B_2, f_3) with
 *   B_1 = f_1 - f_1(0) f_0 - f_1(1) f_3,   B_2(t) = B_1(1-t),
 * which vanish at both ends. Same span, but the end values of a function are
 * its f_0 / f_3 coefficients exactly, and the MQ bubbles are computed without
 * the cancellation of sqrt(c^2 + x^2) against its chord:
 *   B_1 = x (x/(r_1 + c) - 1/(s + c)),  x = 1 - t, r_1 = sqrt(c^2 + x^2), s = sqrt(c^2 + 1)
 * (from r_1 - c = x^2/(r_1 + c) and s - c = 1/(s + c)). Elliptic: B_1 = sn((1-t)K) - (1-t).
 */
static double mq_bubble(double c, double s, double x)
{
    const double r = hypot(c, x);
    return x * (x / (r + c) - 1.0 / (s + c));
}

static int bubble_at(const el_blend_basis *b, double t, double g[4], double dg[4], double d2g[4])
{
    double f[4], df[4], d2f[4];
    int st = span_at(b, t, f, df, d2f);
    if (st != EL_OK) return st;
    double e0, e1; /* f_1(0) = f_2(1) and f_1(1) = f_2(0) */
    if (b->kind == EL_BLEND_MQ) {
        const double c = fabs(b->c), s = hypot(c, 1.0);
        e0 = s;
        e1 = c;
        g[1] = mq_bubble(c, s, 1.0 - t);
        g[2] = mq_bubble(c, s, t);
    } else {
        e0 = 1.0;
        e1 = 0.0;
        g[1] = f[1] - (1.0 - t);
        g[2] = f[2] - t;
    }
    g[0] = f[0];
    g[3] = f[3];
    if (dg) {
        dg[0] = -1.0;
        dg[3] = 1.0;
        dg[1] = df[1] + e0 - e1;
        dg[2] = df[2] + e1 - e0;
    }
    if (d2g) memcpy(d2g, d2f, sizeof d2f);
    return EL_OK;
}

/*
 * Solve the 8x8 system (2.17) for b->G, b->M, b->Minv, b->cond (b->kind,
 * c/k/K, d set). The unknowns are the coefficients of h_0 and h_1 on the
 * bubble form g; M (on the paper's f_j) follows from B_1 = f_1 - f_1(0) f_0 - f_1(1) f_3.
 */
static int solve_system(el_blend_basis *b)
{
    double g0[4], dg0[4], g1[4], dg1[4];
    int st = bubble_at(b, 0.0, g0, dg0, NULL);
    if (st == EL_OK) st = bubble_at(b, 1.0, g1, dg1, NULL);
    if (st != EL_OK) return st;
    /* the bubbles vanish at the ends by construction: use the exact zeros */
    g0[1] = g0[2] = g1[1] = g1[2] = 0.0;
    /* unknowns x = (a_0..a_3, b_0..b_3) on g; rows: the conditions (2.14)-(2.15) */
    double A[64] = {0}, Ainv[64], r[8] = {1.0, 0.0, 0.0, -b->d, 0.0, 0.0, 0.0, 0.0};
    for (int j = 0; j < 4; j++) {
        A[0 * 8 + j] = g0[j];       /* h_0(0) = 1 */
        A[1 * 8 + j] = g1[j];       /* h_0(1) = 0 */
        A[2 * 8 + j] = dg1[j];      /* h_0'(1) = 0 */
        A[3 * 8 + j] = dg0[j];      /* h_0'(0) = -d */
        A[4 * 8 + 4 + j] = g0[j];   /* h_1(0) = 0 */
        A[5 * 8 + 4 + j] = g1[j];   /* h_1(1) = 0 */
        A[6 * 8 + 4 + j] = dg1[j];  /* h_1'(1) = 0 */
    }
    A[7 * 8 + 1] = A[7 * 8 + 2] = A[7 * 8 + 5] = A[7 * 8 + 6] = 1.0; /* (2.15) B = 0 */
    double cond;
    st = invert(8, A, Ainv, &cond);
    if (st != EL_OK) return st;
    double x[8];
    for (int i = 0; i < 8; i++) {
        x[i] = 0.0;
        for (int j = 0; j < 8; j++) x[i] += Ainv[i * 8 + j] * r[j];
    }
    double G[16], M[16], Minv[16], c4;
    for (int j = 0; j < 4; j++) {
        G[0 * 4 + j] = x[j];          /* h_0 */
        G[1 * 4 + j] = x[4 + j];      /* h_1 */
        G[2 * 4 + j] = x[4 + 3 - j];  /* h_2(t) = h_1(1-t): f_0 <-> f_3, B_1 <-> B_2 */
        G[3 * 4 + j] = x[3 - j];      /* h_3(t) = h_0(1-t) */
    }
    double f0[4], f1[4];
    if ((st = span_at(b, 0.0, f0, NULL, NULL)) != EL_OK) return st;
    if ((st = span_at(b, 1.0, f1, NULL, NULL)) != EL_OK) return st;
    for (int i = 0; i < 4; i++) {
        const double *gi = G + 4 * i;
        M[4 * i + 0] = gi[0] - gi[1] * f0[1] - gi[2] * f0[2];
        M[4 * i + 1] = gi[1];
        M[4 * i + 2] = gi[2];
        M[4 * i + 3] = gi[3] - gi[1] * f1[1] - gi[2] * f1[2];
    }
    st = invert(4, M, Minv, &c4);
    if (st != EL_OK) return st;
    memcpy(b->G, G, sizeof G);
    memcpy(b->M, M, sizeof M);
    memcpy(b->Minv, Minv, sizeof Minv);
    b->cond = cond;
    return EL_OK;
}

int el_blend_init_mq(el_blend_basis *b, double c, double d)
{
    if (!b || !isfinite(c) || !isfinite(d) || !(d > 0.0)) return EL_EINVAL;
    if (c == 0.0) return EL_EDOM;
    el__gsl_quiet();
    el_blend_basis t;
    memset(&t, 0, sizeof t);
    t.kind = EL_BLEND_MQ;
    t.c = c;
    t.d = d;
    int st = solve_system(&t);
    if (st == EL_OK) st = basis_stats(&t);
    if (st == EL_OK) *b = t;
    return st;
}

int el_blend_init_elliptic(el_blend_basis *b, double k, double d)
{
    if (!b || !isfinite(k) || !isfinite(d) || !(d > 0.0) || k < 0.0) return EL_EINVAL;
    if (k >= 1.0) return EL_EDOM;
    el__gsl_quiet();
    gsl_sf_result K;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) != GSL_SUCCESS || !isfinite(K.val))
        return EL_EDOM;
    el_blend_basis t;
    memset(&t, 0, sizeof t);
    t.kind = EL_BLEND_ELLIPTIC;
    t.k = k;
    t.K = K.val;
    t.d = d;
    int st = solve_system(&t);
    /* the neighbourhood of K = 2 (header): the basis is not determined well
     * enough there to be of use (it grows like 1/|2 - K|) */
    if (st == EL_OK && t.cond > EL_BLEND_COND_MAX) st = EL_ESINGULAR;
    if (st == EL_OK) st = basis_stats(&t);
    if (st == EL_OK) *b = t;
    return st;
}

/* s(c), beta(c), alpha(c) of (2.5), for c > 0. */
static void eck_aux(double c, double *s, double *beta, double *alpha)
{
    *s = hypot(c, 1.0);
    *beta = *s / (*s + c);
    *alpha = c * *s / (2.0 * c * c + 1.0 + c * *s);
}

int el_blend_eck_d(double c, double *d)
{
    if (!d || !isfinite(c)) return EL_EINVAL;
    if (c == 0.0) return EL_EDOM;
    double s, beta, alpha;
    eck_aux(fabs(c), &s, &beta, &alpha);
    if (!isfinite(1.0 / alpha)) return EL_EDOM;   /* |c| < ~1e-308: d ~ 1/|c| overflows */
    *d = 1.0 / alpha;
    return EL_OK;
}

int el_blend_eck_omega(double c, size_t n, const double *t, double *omega)
{
    if (!isfinite(c) || (n > 0 && (!t || !omega)) || el__too_many(n, 4, sizeof(double)) ||
        el__all_finite(t, n))
        return EL_EINVAL;
    if (c == 0.0) return EL_EDOM;
    c = fabs(c);
    double s, beta, alpha;
    eck_aux(c, &s, &beta, &alpha);
    const double scale = (s + c) * (s + c) * beta / alpha;
    for (size_t i = 0; i < n; i++) {
        const double x = t[i], y = 1.0 - x;
        /* (2.4), Omega_1 corrected: t + c sqrt(c^2+(1-t)^2) - s sqrt(c^2+t^2) */
        const double o1 = scale * (x + c * hypot(c, y) - s * hypot(c, x));
        const double o2 = scale * (y + c * hypot(c, x) - s * hypot(c, y)); /* Omega_1(1-t) */
        const double o3 = x - alpha * o1 + (alpha - 1.0) * o2;
        const double o0 = y - alpha * o2 + (alpha - 1.0) * o1;             /* Omega_3(1-t) */
        omega[4 * i + 0] = o0;
        omega[4 * i + 1] = o1;
        omega[4 * i + 2] = o2;
        omega[4 * i + 3] = o3;
        if (el__all_finite(omega + 4 * i, 4)) return EL_EDOM;   /* tiny |c|, or t far outside */
    }
    return EL_OK;
}

/* One of the per-point functions below (span_at, basis_at): four values and
 * (where the pointers are not NULL) their first and second derivatives at t. */
typedef int (*point_fn)(const el_blend_basis *b, double t, double v[4], double dv[4], double d2v[4]);

/* f(t_i) for n parameter values into rows of 4, after the shared argument checks. */
static int eval_points(point_fn f, const el_blend_basis *b, size_t n, const double *t,
                       double *v, double *dv, double *d2v)
{
    if (!el__blend_basis_ok(b) || (n > 0 && !t) || el__too_many(n, 4, sizeof(double)) ||
        el__all_finite(t, n))
        return EL_EINVAL;
    el__gsl_quiet();
    for (size_t i = 0; i < n; i++) {
        double *out[3] = {v ? v + 4 * i : NULL, dv ? dv + 4 * i : NULL, d2v ? d2v + 4 * i : NULL};
        int st = f(b, t[i], out[0], out[1], out[2]);
        if (st != EL_OK) return st;
        for (int o = 0; o < 3; o++)   /* t far outside [0, 1] can leave double's range */
            if (out[o] && el__all_finite(out[o], 4)) return EL_EDOM;
    }
    return EL_OK;
}

int el_blend_span_eval(const el_blend_basis *b, size_t n, const double *t,
                       double *f, double *df, double *d2f)
{
    return eval_points(span_at, b, n, t, f, df, d2f);
}

/* h_i = sum_j G_ij g_j (= sum_j M_ij f_j) for one parameter value (and derivatives). */
static int basis_at(const el_blend_basis *b, double t, double h[4], double dh[4], double d2h[4])
{
    double g[3][4];
    int st = bubble_at(b, t, g[0], g[1], g[2]);
    if (st != EL_OK) return st;
    double *out[3] = {h, dh, d2h};
    for (int o = 0; o < 3; o++) {
        if (!out[o]) continue;
        for (int i = 0; i < 4; i++) {
            double s = 0.0;
            for (int j = 0; j < 4; j++) s += b->G[4 * i + j] * g[o][j];
            out[o][i] = s;
        }
    }
    return EL_OK;
}

int el_blend_basis_eval(const el_blend_basis *b, size_t n, const double *t,
                        double *h, double *dh, double *d2h)
{
    return eval_points(basis_at, b, n, t, h, dh, d2h);
}

/* ------------------------------------------------------------- basis_min, lebesgue */

/* What basis_stats() extremises: sign * min_i h_i(t) or sign * sum_i |h_i(t)|. */
typedef struct stat_ctx {
    const el_blend_basis *b;
    int lebesgue;     /* 0: min_i h_i; 1: sum_i |h_i| */
    double sign;      /* +1: minimise; -1: maximise */
    int status;
} stat_ctx;

static double stat_fn(double t, void *p)
{
    stat_ctx *c = p;
    double h[4];
    int st = basis_at(c->b, t, h, NULL, NULL);
    if (st != EL_OK) { c->status = st; return 0.0; }
    double v = c->lebesgue ? 0.0 : h[0];
    for (int i = 0; i < 4; i++) v = c->lebesgue ? v + fabs(h[i]) : fmin(v, h[i]);
    return c->sign * v;
}

/*
 * The smallest value of sign * f over [0, 1]: the least of 65 samples, then GSL's
 * Brent around it (the basis functions have few extrema; f is smooth but at
 * the crossings of two h_i, which Brent's golden-section steps tolerate).
 */
static int extremum(stat_ctx *c, double *best)
{
    enum { S = 64 };
    double f[S + 1];
    size_t j = 0;
    for (size_t i = 0; i <= S; i++) {
        f[i] = stat_fn((double)i / S, c);
        if (f[i] < f[j]) j = i;
    }
    if (c->status != EL_OK) return c->status;
    *best = f[j];
    if (j == 0 || j == S || !(f[j] < f[j - 1] && f[j] < f[j + 1])) return EL_OK;
    gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!m) return EL_ENOMEM;
    gsl_function F = {stat_fn, c};
    if (gsl_min_fminimizer_set_with_values(m, &F, (double)j / S, f[j], (double)(j - 1) / S,
                                           f[j - 1], (double)(j + 1) / S, f[j + 1]) == GSL_SUCCESS) {
        for (int it = 0; it < 60 && c->status == EL_OK; it++) {
            if (gsl_min_fminimizer_iterate(m) != GSL_SUCCESS) break;
            if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m), gsl_min_fminimizer_x_upper(m),
                                      1e-10, 0.0) == GSL_SUCCESS)
                break;
        }
        *best = fmin(*best, gsl_min_fminimizer_f_minimum(m));
    }
    gsl_min_fminimizer_free(m);
    return c->status;
}

/* b->basis_min, b->convex_hull, b->lebesgue (b->G set). */
static int basis_stats(el_blend_basis *b)
{
    stat_ctx hi = {b, 1, -1.0, EL_OK};
    double vmin, tmin, vmax;
    int st = el__blend_basis_min(b, &vmin, &tmin);   /* exact: blend_hull.c */
    if (st == EL_OK) st = extremum(&hi, &vmax);
    if (st != EL_OK) return st;
    b->basis_min = vmin;
    b->convex_hull = vmin >= -HULL_TOL;
    b->lebesgue = fmax(-vmax, 1.0);   /* sum |h_i| >= sum h_i = 1 */
    if (!b->convex_hull) {
        /* a dip the samples miss (next to an end): sum |h_i| there */
        const double at_min = -stat_fn(tmin, &hi);
        if (hi.status != EL_OK) return hi.status;
        b->lebesgue = fmax(b->lebesgue, at_min);
    }
    return EL_OK;
}

/* out_j = sum_i in_i A[4i + j] for 4 points (row vector of points times A). */
static void points_times(const double *in, const double *A, double *out)
{
    double r[8];
    for (int j = 0; j < 4; j++) {
        r[2 * j] = r[2 * j + 1] = 0.0;
        for (int i = 0; i < 4; i++) {
            r[2 * j] += in[2 * i] * A[4 * i + j];
            r[2 * j + 1] += in[2 * i + 1] * A[4 * i + j];
        }
    }
    memcpy(out, r, sizeof r);
}

/* out = in A for 4 points unless a value leaves double's range (EL_EDOM, out untouched). */
static int points_times_checked(const double *in, const double *A, double *out)
{
    double r[8];
    points_times(in, A, r);
    if (el__all_finite(r, 8)) return EL_EDOM;
    memcpy(out, r, sizeof r);
    return EL_OK;
}

int el_blend_control_points(const el_blend_basis *b, const double *p, double *q)
{
    if (!el__blend_basis_ok(b) || !p || !q || el__all_finite(p, 8)) return EL_EINVAL;
    return points_times_checked(p, b->Minv, q); /* (2.19) q = p M^-1 */
}

int el_blend_coefficients(const el_blend_basis *b, const double *q, double *p)
{
    if (!el__blend_basis_ok(b) || !p || !q || el__all_finite(q, 8)) return EL_EINVAL;
    return points_times_checked(q, b->M, p); /* (2.18) p = q M */
}

/* phi(t) and phi'(t) of one segment with control points q (8 doubles). */
int el__blend_segment_at(const el_blend_basis *b, const double *q, double t, double xy[2], double dxy[2])
{
    double h[4], dh[4];
    int st = basis_at(b, t, h, dh, NULL);
    if (st != EL_OK) return st;
    double x = 0, y = 0, dx = 0, dy = 0;
    for (int i = 0; i < 4; i++) {
        x += q[2 * i] * h[i];
        y += q[2 * i + 1] * h[i];
        dx += q[2 * i] * dh[i];
        dy += q[2 * i + 1] * dh[i];
    }
    if (xy) { xy[0] = x; xy[1] = y; }
    if (dxy) { dxy[0] = dx; dxy[1] = dy; }
    return EL_OK;
}

int el_blend_eval(const el_blend_basis *b, const double *q, size_t n, const double *t,
                  double *xy, double *dxy)
{
    return el_blend_composite_eval(b, 1, q, n, t, xy, dxy);
}

/* Segment index and local parameter of a global t in a composite of nseg segments. */
static double locate(size_t nseg, double t, size_t *seg)
{
    double f = floor(t);
    size_t s = f <= 0.0 ? 0 : (f >= (double)(nseg - 1) ? nseg - 1 : (size_t)f);
    *seg = s;
    return t - (double)s;
}

static int composite_at(const el_blend_basis *b, size_t nseg, const double *q, double t,
                        double xy[2], double dxy[2])
{
    size_t s;
    double u = locate(nseg, t, &s);
    return el__blend_segment_at(b, q + 6 * s, u, xy, dxy);
}

int el_blend_composite_eval(const el_blend_basis *b, size_t nseg, const double *q,
                            size_t n, const double *t, double *xy, double *dxy)
{
    if (!el__blend_basis_ok(b) || nseg < 1 || !q || (n > 0 && (!t || !xy)) ||
        el__too_many(nseg + 1, 6, sizeof(double)) || el__too_many(n, 2, sizeof(double)) ||
        el__all_finite(q, 6 * nseg + 2) || el__all_finite(t, n))
        return EL_EINVAL;
    el__gsl_quiet();
    for (size_t i = 0; i < n; i++) {
        int st = composite_at(b, nseg, q, t[i], xy + 2 * i, dxy ? dxy + 2 * i : NULL);
        if (st != EL_OK) return st;
        if (el__all_finite(xy + 2 * i, 2) || (dxy && el__all_finite(dxy + 2 * i, 2)))
            return EL_EDOM;   /* control points near DBL_MAX, or t far outside */
    }
    return EL_OK;
}

int el_blend_from_points(const el_blend_basis *b, const double *pts, int mode, double *q)
{
    if (!el__blend_basis_ok(b) || !pts || !q || el__all_finite(pts, 8)) return EL_EINVAL;
    if (mode == EL_BLEND_PICK_CONTROL) {
        memmove(q, pts, 8 * sizeof *q);
        return EL_OK;
    }
    if (mode != EL_BLEND_PICK_INTERPOLATE) return EL_EINVAL;
    el__gsl_quiet();
    double tt[4] = {0.0, 0.0, 0.0, 0.0};
    for (int i = 1; i < 4; i++) {
        const double ch = hypot(pts[2 * i] - pts[2 * i - 2], pts[2 * i + 1] - pts[2 * i - 1]);
        if (!(ch > 0.0)) return EL_ESINGULAR;
        tt[i] = tt[i - 1] + ch;
    }
    if (!isfinite(tt[3])) return EL_EDOM;   /* the chords overflow: coordinates near DBL_MAX */
    for (int i = 1; i < 3; i++) tt[i] /= tt[3];
    tt[3] = 1.0;
    /* collocation H[i][j] = h_j(t_i); H Q = P, solved through H^-1 */
    double H[16], Hinv[16];
    for (int i = 0; i < 4; i++) {
        int st = basis_at(b, tt[i], H + 4 * i, NULL, NULL);
        if (st != EL_OK) return st;
    }
    int st = invert(4, H, Hinv, NULL);
    if (st != EL_OK) return st;
    double r[8];
    for (int i = 0; i < 4; i++) {
        r[2 * i] = r[2 * i + 1] = 0.0;
        for (int j = 0; j < 4; j++) {
            r[2 * i] += Hinv[4 * i + j] * pts[2 * j];
            r[2 * i + 1] += Hinv[4 * i + j] * pts[2 * j + 1];
        }
    }
    if (el__all_finite(r, 8)) return EL_EDOM;
    memcpy(q, r, sizeof r);
    return EL_OK;
}

/* Control points of the C1 composite through npts points; closed: one more segment
 * from the last point back to the first, the tangents wrapped (q: 3 npts + 1 points). */
static int composite_through(const el_blend_basis *b, size_t npts, const double *pts, int closed,
                             double *q)
{
    /* the tangents are differences of points: in range when the coordinates are */
    for (size_t i = 0; i < 2 * npts; i++)
        if (fabs(pts[i]) > 1e300) return EL_EDOM;
    const double *P = pts;
    const size_t last = npts - 1, nq = 3 * (closed ? npts : npts - 1) + 1;
    for (size_t i = 0; i < npts; i++) {
        double T[2];
        for (int c = 0; c < 2; c++) {
            if (closed)   /* Catmull-Rom all round: P_{i+1} - P_{i-1} taken cyclically */
                T[c] = (P[2 * ((i + 1) % npts) + c] - P[2 * ((i + last) % npts) + c]) / 2.0;
            else if (npts == 2)
                T[c] = P[2 + c] - P[c];
            else if (i == 0)
                T[c] = (-3.0 * P[c] + 4.0 * P[2 + c] - P[4 + c]) / 2.0;
            else if (i == last)
                T[c] = (3.0 * P[2 * last + c] - 4.0 * P[2 * (last - 1) + c] + P[2 * (last - 2) + c]) / 2.0;
            else
                T[c] = (P[2 * (i + 1) + c] - P[2 * (i - 1) + c]) / 2.0;
        }
        /* phi'(0) = d (q_1 - q_0), phi'(1) = d (q_3 - q_2) (2.11) */
        for (int c = 0; c < 2; c++) {
            q[6 * i + c] = P[2 * i + c];
            if (i < last || closed) q[6 * i + 2 + c] = P[2 * i + c] + T[c] / b->d;
            if (i > 0) q[6 * i - 2 + c] = P[2 * i + c] - T[c] / b->d;
            else if (closed) q[2 * (nq - 2) + c] = P[c] - T[c] / b->d;
        }
    }
    if (closed) { q[2 * (nq - 1)] = P[0]; q[2 * (nq - 1) + 1] = P[1]; }
    return el__all_finite(q, 2 * nq) ? EL_EDOM : EL_OK;   /* T/d beyond range: tiny d */
}

int el_blend_composite_through(const el_blend_basis *b, size_t npts, const double *pts,
                               double *q)
{
    if (!el__blend_basis_ok(b) || npts < 2 || !pts || !q || el__too_many(npts, 6, sizeof(double)) ||
        el__all_finite(pts, 2 * npts))
        return EL_EINVAL;
    return composite_through(b, npts, pts, 0, q);
}

int el_blend_composite_closed(const el_blend_basis *b, size_t npts, const double *pts, double *q)
{
    if (!el__blend_basis_ok(b) || npts < 3 || !pts || !q || el__too_many(npts + 1, 6, sizeof(double)) ||
        el__all_finite(pts, 2 * npts))
        return EL_EINVAL;
    return composite_through(b, npts, pts, 1, q);
}
