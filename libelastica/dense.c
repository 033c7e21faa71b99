/*
 * Small dense systems shared by the solvers (the elastic spline's pieces and chain,
 * Hermite's Newton steps, the fit's Gauss-Newton steps). Written out rather than
 * GSL's LU and Cholesky for two reasons: GSL sends every triangular solve through
 * BLAS (dtrsv with OpenBLAS's locking), about ten times the arithmetic of a 5 x 5
 * system, and these solvers factor one per Newton iteration; and GSL reports a
 * singular or indefinite matrix to its process-wide error handler, which a caller
 * may have set to abort, where here such a matrix is an expected answer.
 */
#include "internal.h"

/* LU with partial pivoting of the n x n row-major a, in place; EL_ESINGULAR on a zero
 * (or non-finite) pivot. */
int el__lu_factor(double *a, int n, int *perm)
{
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int r = c + 1; r < n; r++)
            if (fabs(a[r * n + c]) > fabs(a[p * n + c])) p = r;
        perm[c] = p;
        if (!(fabs(a[p * n + c]) > 1e-300) || !isfinite(a[p * n + c])) return EL_ESINGULAR;
        if (p != c)
            for (int j = 0; j < n; j++) { const double t = a[c * n + j]; a[c * n + j] = a[p * n + j]; a[p * n + j] = t; }
        const double inv = 1.0 / a[c * n + c];
        for (int r = c + 1; r < n; r++) {
            const double f = a[r * n + c] *= inv;
            for (int j = c + 1; j < n; j++) a[r * n + j] -= f * a[c * n + j];
        }
    }
    return EL_OK;
}

/* The solve of b in place with el__lu_factor's a and perm. */
void el__lu_solve(const double *a, int n, const int *perm, double *b)
{
    for (int c = 0; c < n; c++) {   /* the row exchanges, in order */
        const double t = b[perm[c]]; b[perm[c]] = b[c]; b[c] = t;
    }
    for (int r = 1; r < n; r++)
        for (int c = 0; c < r; c++) b[r] -= a[r * n + c] * b[c];
    for (int r = n - 1; r >= 0; r--) {
        double sum = b[r];
        for (int j = r + 1; j < n; j++) sum -= a[r * n + j] * b[j];
        b[r] = sum / a[r * n + r];
    }
}

/* A x = b for symmetric a (n x n, row-major, overwritten by its Cholesky factor in the
 * lower triangle), x in b; EL_ESINGULAR when a is not numerically positive definite
 * (a pivot <= 0) or x is not finite. */
int el__cholesky_solve(double *a, int n, double *b)
{
    for (int j = 0; j < n; j++) {
        double d = a[j * n + j];
        for (int k = 0; k < j; k++) d -= a[j * n + k] * a[j * n + k];
        if (!(d > 0.0) || !isfinite(d)) return EL_ESINGULAR;
        const double ljj = sqrt(d);
        a[j * n + j] = ljj;
        for (int i = j + 1; i < n; i++) {
            double v = a[i * n + j];
            for (int k = 0; k < j; k++) v -= a[i * n + k] * a[j * n + k];
            a[i * n + j] = v / ljj;
        }
    }
    for (int i = 0; i < n; i++) {             /* L y = b */
        double v = b[i];
        for (int k = 0; k < i; k++) v -= a[i * n + k] * b[k];
        b[i] = v / a[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {        /* L^T x = y */
        double v = b[i];
        for (int k = i + 1; k < n; k++) v -= a[k * n + i] * b[k];
        b[i] = v / a[i * n + i];
    }
    return el__all_finite(b, (size_t)n) ? EL_ESINGULAR : EL_OK;
}
