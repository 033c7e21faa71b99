/*
 * The certified B-spline approximation of an elastica, between its two files:
 * bspline_approx.c (knots, the search, the API) and bspline_approx_fit.c (the
 * least-squares poles on a grid of exact samples, the certified distance).
 */
#ifndef EL_BSPLINE_APPROX_H
#define EL_BSPLINE_APPROX_H
#include "internal.h"
#include "bspline_basis.h"

typedef struct fit_ws {
    const el_smooth_params *par;
    int p;               /* degree */
    double L, tol;
    size_t M;            /* grid: M+1 samples s_i = i L / M */
    double *s, *xy, *th, *ka;
    double *cs;          /* cos theta, sin theta of the grid, interleaved */
    double *Bc;          /* basis functions of the grid for the current knots, (M+1)(p+1) */
    size_t *kc;          /* their span indices */
    size_t cap;          /* capacity in spans */
    double *U;           /* flat knots, cap + 2p + 1 */
    double *AB, *bx, *by;
    double *err;         /* per-span sampled error */
    double *dist;        /* per-grid-point distance (certification) */
    int nfix;            /* poles fixed at each end: 2 (point, tangent) or 3 (and curvature) */
    size_t nmin;         /* fewest spans that leave them distinct */
} fit_ws;

/* frees the workspace's arrays */
void el__approx_free(fit_ws *w);
/* (re)samples the exact curve on a uniform grid of M + 1 points */
int el__approx_grid(fit_ws *w, size_t M);
/* room for N spans */
int el__approx_reserve(fit_ws *w, size_t N);
/* flat clamped knots from breaks[0..N] (breaks[0] = 0, breaks[N] = L) */
void el__approx_set_knots(fit_ws *w, size_t N, const double *breaks);
/* a finer grid where the smallest span of breaks has fewer than 3(p+1) samples
 * (EL_EMAXITER: finer than the arithmetic can use) */
int el__approx_ensure_grid(fit_ws *w, size_t N, const double *breaks);
/* the grid's basis functions for the current knots */
void el__approx_basis(fit_ws *w, size_t N);
/* the least-squares poles (2 (N + p) values), the end poles fixed */
int el__approx_poles(fit_ws *w, size_t N, double *poles);
/* the sampled distance per span (w->err, to steer the knots); returns the largest */
double el__approx_errors(fit_ws *w, size_t N, const double *poles);
/* the certified largest distance *dmax and the t where it occurs */
int el__approx_certify(fit_ws *w, size_t N, const double *poles, double *dmax, double *worst);

#endif
