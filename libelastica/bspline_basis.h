/*
 * B-spline basis functions shared by bspline.c (evaluation, interpolation) and
 * bspline_approx_fit.c (the certified approximation of an elastica), static inline so
 * that the approximation's loops keep them inlined and unrolled for p = 3.
 * Piegl & Tiller, The NURBS Book, A2.1/A2.2.
 */
#ifndef EL_BSPLINE_BASIS_H
#define EL_BSPLINE_BASIS_H
#include <stddef.h>
#include "internal.h"

enum { MAXDEG_FIT = 7, MAXDEG_BASIS = 15 };

/* The fit's inner loops are written once with the degree p as a parameter and
 * inlined with p = 3 (the default degree) as a constant, which lets the
 * compiler unroll them; other degrees take the generic copy. */
#define FIT_INLINE EL__INLINE
#if defined(__clang__)
#define FIT_UNROLL _Pragma("unroll 8")   /* (a full unroll of the generic copy fails) */
#elif defined(__GNUC__) && __GNUC__ >= 8
#define FIT_UNROLL _Pragma("GCC unroll 8")
#else
#define FIT_UNROLL
#endif

/* Span index k with U[k] <= t < U[k+1], p <= k <= npoles-1 (t = U[npoles] gives
 * the last span). Piegl & Tiller A2.1. */
static inline size_t find_span(const double *U, size_t npoles, int p, double t)
{
    if (t >= U[npoles]) return npoles - 1;
    size_t lo = (size_t)p, hi = npoles;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (t < U[mid]) hi = mid; else lo = mid;
    }
    return lo;
}

/* The p+1 non-zero basis functions N_{k-p..k}(t) on span k (A2.2), p <= 15. */
static inline void basis_funs(const double *U, size_t k, int p, double t, double *N)
{
    double left[MAXDEG_BASIS + 1], right[MAXDEG_BASIS + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; j++) {
        left[j] = t - U[k + 1 - (size_t)j];
        right[j] = U[k + (size_t)j] - t;
        double saved = 0.0;
        for (int r = 0; r < j; r++) {
            const double tmp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
}

/*
 * basis_funs with the reciprocals of its knot differences precomputed for the
 * span (span_recips): the denominators right[r+1] + left[j-r] of A2.2 are
 * U[k+r+1] - U[k+1-j+r], independent of t, so a fit that evaluates the basis
 * at many samples of one span divides only once per span. inv: p(p+1)/2.
 */
static inline void span_recips(const double *U, size_t k, int p, double *inv)
{
    int m = 0;
    for (int j = 1; j <= p; j++)
        for (int r = 0; r < j; r++)
            inv[m++] = 1.0 / (U[k + (size_t)r + 1] - U[k + 1 + (size_t)r - (size_t)j]);
}

FIT_INLINE void basis_funs_inv(const double *U, size_t k, int p, double t, const double *inv,
                           double *N)
{
    double left[MAXDEG_BASIS + 1], right[MAXDEG_BASIS + 1];
    N[0] = 1.0;
    int m = 0;
    FIT_UNROLL for (int j = 1; j <= p; j++) {
        left[j] = t - U[k + 1 - (size_t)j];
        right[j] = U[k + (size_t)j] - t;
        double saved = 0.0;
        FIT_UNROLL for (int r = 0; r < j; r++) {
            const double tmp = N[r] * inv[m++];
            N[r] = saved + right[r + 1] * tmp;
            saved = left[j - r] * tmp;
        }
        N[j] = saved;
    }
}

#endif
