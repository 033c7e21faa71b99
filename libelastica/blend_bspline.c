/*
 * Seed 003 curves as B-splines (el_blend_to_bspline): every segment of a blend
 * curve fitted by a clamped cubic B-spline within a tolerance, the segments
 * joined; the blending functions themselves are in blend.c.
 */
#include "internal.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_bspline.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_min.h>

/*
 * One segment is fitted at a time, on t in [0, 1], by a clamped cubic with N
 * uniform spans (GSL's gsl_bspline: order 4, N + 1 breakpoints, N + 3 poles);
 * the segments are then joined with triple knots (spline_export).
 */
typedef struct spline {
    size_t np;                  /* poles, N + 3 */
    gsl_bspline_workspace *w;   /* knots and basis evaluation */
    gsl_vector *B;              /* the 4 nonzero basis values */
    double *P;                  /* 2 np, interleaved */
} spline;

static void spline_free(spline *s)
{
    if (s->w) gsl_bspline_free(s->w);
    gsl_vector_free(s->B);
    free(s->P);
    s->w = NULL;
    s->B = NULL;
    s->P = NULL;
}

/* The 4 nonzero basis functions at x into N4; returns the index of the first. */
static int bs_basis(const spline *s, double x, double N4[4], size_t *i0)
{
    size_t istart, iend;
    if (gsl_bspline_eval_nonzero(x, s->B, &istart, &iend, s->w) != GSL_SUCCESS) return EL_EINTERNAL;
    for (int r = 0; r < 4; r++) N4[r] = gsl_vector_get(s->B, (size_t)r);
    *i0 = istart;
    return EL_OK;
}

typedef struct fit_ctx {
    const el_blend_basis *b;
    const double *q;            /* the segment's 4 control points */
    const spline *s;
    int status;
} fit_ctx;

/* -|phi(t) - B(t)|, the function Brent minimises. */
static double neg_dev(double t, void *p)
{
    fit_ctx *c = p;
    double a[2], N4[4], x = 0.0, y = 0.0;
    size_t i0;
    int st = el__blend_segment_at(c->b, c->q, t, a, NULL);
    if (st == EL_OK) st = bs_basis(c->s, t, N4, &i0);
    if (st != EL_OK) { c->status = st; return 0.0; }
    for (int r = 0; r < 4; r++) {
        x += N4[r] * c->s->P[2 * (i0 + (size_t)r)];
        y += N4[r] * c->s->P[2 * (i0 + (size_t)r) + 1];
    }
    const double dev = hypot(a[0] - x, a[1] - y);
    /* (GSL's minimiser must see finite values: its error handler is the caller's) */
    if (!isfinite(dev)) { c->status = EL_EDOM; return 0.0; }
    return -dev;
}

/* Certified deviation: dense samples (32 per span), then Brent around every local maximum. */
static int max_deviation(fit_ctx *c, size_t nspan, double *dev)
{
    const size_t g = 32 * nspan;
    double *e = malloc((g + 1) * sizeof *e);
    gsl_min_fminimizer *m = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    int st = EL_OK;
    if (!e || !m) { st = EL_ENOMEM; goto done; }
    for (size_t i = 0; i <= g; i++) e[i] = -neg_dev((double)i / (double)g, c);
    if (c->status != EL_OK) { st = c->status; goto done; }
    double best = 0.0;
    for (size_t i = 0; i <= g; i++) best = e[i] > best ? e[i] : best;
    gsl_function F = {neg_dev, c};
    for (size_t i = 1; i < g; i++) {
        if (!(e[i] > e[i - 1] && e[i] > e[i + 1])) continue;
        /* refine only a peak whose parabola through the samples could beat the best
         * seen (by 1 %): the many small peaks of a good fit cost nothing */
        const double pred = e[i] + (e[i + 1] - e[i - 1]) * (e[i + 1] - e[i - 1]) /
                                       (8.0 * (2.0 * e[i] - e[i - 1] - e[i + 1]));
        if (1.01 * pred < best) continue;
        const double lo = (double)(i - 1) / (double)g, mid = (double)i / (double)g,
                     hi = (double)(i + 1) / (double)g;
        if (gsl_min_fminimizer_set_with_values(m, &F, mid, -e[i], lo, -e[i - 1], hi, -e[i + 1]) !=
            GSL_SUCCESS)
            continue;
        for (int it = 0; it < 60; it++) {
            if (gsl_min_fminimizer_iterate(m) != GSL_SUCCESS) break;
            if (gsl_min_test_interval(gsl_min_fminimizer_x_lower(m), gsl_min_fminimizer_x_upper(m),
                                      1e-14, 0.0) == GSL_SUCCESS)
                break;
        }
        const double v = -gsl_min_fminimizer_f_minimum(m);
        if (v > best) best = v;
    }
    if (c->status != EL_OK) { st = c->status; goto done; }
    *dev = best;
done:
    free(e);
    gsl_min_fminimizer_free(m);
    return st;
}

/* One least-squares fit of the segment with N uniform spans into s (allocated here). */
static int fit_once(fit_ctx *c, size_t N, spline *s)
{
    int st = EL_OK;
    s->np = N + 3;
    s->w = gsl_bspline_alloc(4, N + 1);
    s->B = gsl_vector_alloc(4);
    s->P = malloc(2 * s->np * sizeof *s->P);
    if (!s->w || !s->B || !s->P) return EL_ENOMEM;
    if (gsl_bspline_knots_uniform(0.0, 1.0, s->w) != GSL_SUCCESS) return EL_EINTERNAL;
    const size_t np = s->np;
    const double h = 1.0 / (double)N;
    /* Hermite ends: B(0) = phi(0), B'(0) = 3 (P_1 - P_0)/h, mirrored at t = 1 */
    double a[2], da[2], e[2], de[2];
    if ((st = el__blend_segment_at(c->b, c->q, 0.0, a, da)) != EL_OK) return st;
    if ((st = el__blend_segment_at(c->b, c->q, 1.0, e, de)) != EL_OK) return st;
    for (int j = 0; j < 2; j++) {
        s->P[j] = a[j];
        s->P[2 + j] = a[j] + da[j] * h / 3.0;
        s->P[2 * (np - 1) + j] = e[j];
        s->P[2 * (np - 2) + j] = e[j] - de[j] * h / 3.0;
    }
    const size_t nfree = np - 4;
    if (nfree == 0) return EL_OK;
    /*
     * Inner poles 2..np-3 by linear least squares on 8 samples per span. The
     * collocation matrix has 4 nonzeros per row, so the normal equations are
     * banded (bandwidth 3) and well conditioned (dense samples, B-spline basis):
     * GSL's banded Cholesky solves them in O(np) instead of a dense SVD.
     * GSL band storage: AB(i, j) = A(i + j, i).
     */
    const size_t m = 8 * N + 1, band = nfree < 4 ? nfree : 4; /* GSL: bandwidth < order */
    gsl_matrix *AB = gsl_matrix_calloc(nfree, band);
    gsl_vector *rhs[2] = {gsl_vector_calloc(nfree), gsl_vector_calloc(nfree)};
    if (!AB || !rhs[0] || !rhs[1]) { st = EL_ENOMEM; goto done; }
    for (size_t i = 0; i < m; i++) {
        const double t = (double)i / (double)(m - 1);
        double pt[2], N4[4];
        size_t i0;
        if ((st = el__blend_segment_at(c->b, c->q, t, pt, NULL)) != EL_OK) goto done;
        if ((st = bs_basis(s, t, N4, &i0)) != EL_OK) goto done;
        for (int r = 0; r < 4; r++) {
            const size_t p = i0 + (size_t)r;
            if (p < 2 || p > np - 3) { /* fixed pole: move to the right side */
                pt[0] -= N4[r] * s->P[2 * p];
                pt[1] -= N4[r] * s->P[2 * p + 1];
            }
        }
        for (int r = 0; r < 4; r++) {
            const size_t p = i0 + (size_t)r;
            if (p < 2 || p > np - 3) continue;
            for (int r2 = r; r2 < 4; r2++) {
                const size_t p2 = i0 + (size_t)r2;
                if (p2 > np - 3 || p2 - p >= band) break;
                *gsl_matrix_ptr(AB, p - 2, p2 - p) += N4[r] * N4[r2];
            }
            *gsl_vector_ptr(rhs[0], p - 2) += N4[r] * pt[0];
            *gsl_vector_ptr(rhs[1], p - 2) += N4[r] * pt[1];
        }
    }
    if (gsl_linalg_cholesky_band_decomp(AB) != GSL_SUCCESS) { st = EL_EINTERNAL; goto done; }
    for (int j = 0; j < 2; j++) {
        if (gsl_linalg_cholesky_band_svx(AB, rhs[j]) != GSL_SUCCESS) { st = EL_EINTERNAL; goto done; }
        for (size_t p = 0; p < nfree; p++) s->P[2 * (p + 2) + j] = gsl_vector_get(rhs[j], p);
    }
done:
    gsl_matrix_free(AB);
    gsl_vector_free(rhs[0]);
    gsl_vector_free(rhs[1]);
    return st;
}

/*
 * Join the per-segment splines (segment g on [g, g+1]) into the public result
 * type: triple knots at the joins, the shared pole (the join point q_{3g})
 * taken once (from the segment before).
 */
static int spline_export(const spline *segs, size_t nseg, double dev, el_bspline *out)
{
    size_t np = 1, nk = nseg + 1;
    for (size_t g = 0; g < nseg; g++) {
        np += segs[g].np - 1;
        nk += segs[g].np - 4; /* interior knots of segment g */
    }
    el_bspline r;
    int st = el_bspline_alloc(&r, 3, 2, np, nk);
    if (st != EL_OK) return st;
    double *poles = r.poles, *knots = r.knots;
    int *mults = r.mults;
    size_t ip = 0, ik = 0;
    poles[ip++] = segs[0].P[0];
    poles[ip++] = segs[0].P[1];
    knots[ik] = 0.0;
    mults[ik++] = 4;
    for (size_t g = 0; g < nseg; g++) {
        const spline *sg = &segs[g];
        memcpy(poles + ip, sg->P + 2, 2 * (sg->np - 1) * sizeof *poles);
        ip += 2 * (sg->np - 1);
        for (size_t j = 4; j < sg->np; j++) { /* flat knots 4..np-1 are the interior ones */
            knots[ik] = (double)g + gsl_vector_get(sg->w->knots, j);
            mults[ik++] = 1;
        }
        knots[ik] = (double)(g + 1);
        mults[ik++] = g + 1 < nseg ? 3 : 4;
    }
    r.max_deviation = dev;
    *out = r;
    return EL_OK;
}

/* Fit one segment (control points q, 8 doubles): N = 1, 2, 3, 4, 6, 8, 12, ... 256
 * spans (about x1.5) until the certified deviation is <= tol; the best one in *best. */
static int fit_segment(const el_blend_basis *b, const double *q, double tol, spline *best,
                       double *best_dev)
{
    fit_ctx c = {b, q, NULL, EL_OK};
    *best_dev = INFINITY;
    int st = EL_OK;
    for (size_t N = 1; N <= 256; N = N < 2 ? N + 1 : (N & (N - 1)) ? N / 3 * 4 : N / 2 * 3) {
        spline s = {0, NULL, NULL, NULL};
        double dev = INFINITY;
        st = fit_once(&c, N, &s);
        if (st == EL_OK) {
            c.s = &s;
            st = max_deviation(&c, N, &dev);
        }
        if (st != EL_OK) {
            spline_free(&s);
            break;
        }
        if (dev < *best_dev) {
            spline_free(best);
            *best = s;
            *best_dev = dev;
        } else {
            spline_free(&s);
        }
        if (*best_dev <= tol) break;
    }
    return st;
}

int el_blend_to_bspline(const el_blend_basis *b, size_t nseg, const double *q, double tol,
                        el_bspline *out)
{
    if (!el__blend_basis_ok(b) || nseg < 1 || nseg > 100000 || !q || !out || !isfinite(tol) ||
        !(tol > 0.0) || el__all_finite(q, 6 * nseg + 2))
        return EL_EINVAL;
    el__gsl_quiet();
    /* below what the coordinates resolve (their rounding, amplified by the
     * basis at most lebesgue times) no fit can be certified: refused at once */
    double qmax = 0.0;
    for (size_t i = 0; i < 6 * nseg + 2; i++) qmax = fmax(qmax, fabs(q[i]));
    if (tol < 64.0 * DBL_EPSILON * fmax(b->lebesgue, 1.0) * qmax) return EL_EDOM;
    spline *segs = calloc(nseg, sizeof *segs);
    if (!segs) return EL_ENOMEM;
    double dev = 0.0;
    int st = EL_OK;
    for (size_t g = 0; g < nseg && st == EL_OK; g++) {
        double dg = 0.0;
        st = fit_segment(b, q + 6 * g, tol, &segs[g], &dg);
        if (dg > dev) dev = dg;
    }
    for (size_t g = 0; g < nseg && st == EL_OK; g++)
        if (el__all_finite(segs[g].P, 2 * segs[g].np)) st = EL_EDOM;   /* control points near DBL_MAX */
    if (st == EL_OK) st = spline_export(segs, nseg, dev, out);
    for (size_t g = 0; g < nseg; g++) spline_free(&segs[g]);
    free(segs);
    if (st != EL_OK) return st;
    return dev <= tol ? EL_OK : EL_ENOCONV;
}
