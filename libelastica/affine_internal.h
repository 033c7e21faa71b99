/*
 * Helpers of affine.c and affine_polyline.c (seed 002): edge vectors and their
 * determinants on interleaved points, and the input checks both files share.
 */
#ifndef EL_AFFINE_INTERNAL_H
#define EL_AFFINE_INTERNAL_H
#include "internal.h"

static inline double det2(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

/* det(v_{i-1}, v_i) etc. on interleaved points: edge j is x_{j+1} - x_j. */
static inline void edge(const double *xy, size_t j, double v[2])
{
    v[0] = xy[2 * (j + 1)] - xy[2 * j];
    v[1] = xy[2 * (j + 1) + 1] - xy[2 * j + 1];
}

static inline int points_ok(size_t npts, const double *xy, size_t min)
{
    if (!xy || npts < min || el__too_many(npts, 2, sizeof(double))) return EL_EINVAL;
    return el__all_finite(xy, 2 * npts);
}

/*
 * The functions below multiply two or three edge vectors (areas, and the
 * ratios of areas the curvatures are). Their products stay inside double's
 * range, and keep their precision, only when the largest edge component m is
 * in [1e-150, 1e150] (or 0: all points equal, which each function treats as
 * degenerate input): EL_EDOM otherwise (an edge may also overflow, e.g.
 * between -1e308 and 1e308).
 */
static inline int edges_in_range(size_t npts, const double *xy)
{
    double m = 0.0;
    for (size_t j = 0; j + 1 < npts; j++)
        for (int c = 0; c < 2; c++) m = fmax(m, fabs(xy[2 * (j + 1) + c] - xy[2 * j + c]));
    if (!isfinite(m) || m > 1e150 || (m > 0.0 && m < 1e-150)) return EL_EDOM;
    return EL_OK;
}

#endif
