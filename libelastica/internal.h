/* Internal helpers shared by the library's files (not installed). */
#ifndef EL_INTERNAL_H
#define EL_INTERNAL_H

#include "elastica.h"
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
/* Join count clamped planar B-splines of one degree p in 3..7, each on its own
 * parameter interval, end to end into *out (parameters shifted to follow each
 * other), C2 at the joints (knot multiplicity p - 2): each joint pole is the
 * next part's first, then the joint knot is removed twice (Piegl & Tiller A5.8),
 * which is exact when the parts meet with equal point, first and second
 * derivatives. *err: the largest gap between the parts' joint poles and removal
 * distance (a bound on how far *out is from the parts); out->max_deviation = -1.
 * bspline.c. Errors: EL_EINVAL, EL_ENOMEM. */
int el__bspline_join_c2(const el_bspline *parts, size_t count, el_bspline *out, double *err);

/* For the tests of spline.c: the piece p as the Hermite elastica of its own ends
 * (h = |gamma(L) - gamma(0)|), v = (phi, ln mu, k, q, L): J[25] = dR/dv with
 * R = ((gamma(L) - end)/h, theta(0) - ta, theta(L) - tb, (2 mu (2k^2-1) - sigma) h^2),
 * g0[5], g1[5] = d kappa(0)/dv, d kappa(L)/dv, M[25] = d(theta0, kappa0, kappa0', sigma, L)/dv,
 * d[9] = d(kappa(0), kappa(L), L)/d(ta, tb, sigma) by the implicit function theorem. */
int el__spline_piece_jacobians(const el_smooth_params *p, double *J, double *g0, double *g1,
                               double *M, double *d);

#endif

/* Turn GSL's aborting error handler off (once per process, thread-safe); every
 * entry point that calls GSL calls this first and maps GSL statuses to EL_ codes. */
void el__gsl_quiet(void);

/* EL_OK when all n values are finite. */
int el__all_finite(const double *v, size_t n);

/* Carlson's R_F(x, y, z) (when rf != NULL) and R_D(x, y, z) in one duplication loop
 * (ellint.c); x, y >= 0, not both 0, z > 0. qs = 1: double precision; qs < 1:
 * relative accuracy ~1e-16 qs^-8 (qs = 0.2: 4e-11), fewer duplication steps.
 * EL_EDOM on bad arguments. */
int el__carlson_fd(double x, double y, double z, double qs, double *rf, double *rd);
/* The complete integrals K(k) and D(k) = int_0^(pi/2) sin^2 / sqrt(1 - k^2 sin^2) =
 * (K - E)/k^2 for 0 <= k < 1, given kc2 = 1 - k^2 formed without cancellation
 * (ellint.c, AGM). EL_EDOM unless kc2 > 0. */
int el__ellint_complete(double k, double kc2, double *K, double *D);

/* What el_jacobi_eval precomputes for one modulus k: kg = min(k, 1/k), its
 * complementary modulus kp = sqrt(1 - kg^2) formed without cancellation, the
 * quarter period K(kg) and the complete integrals D, J over [0, pi/2]; J only
 * with_dk (it serves the k-derivatives alone; NaN otherwise). */
typedef struct el__modulus {
    double k, kg, kp, K, Dc, Jc;
} el__modulus;
int el__modulus_init(double k, int with_dk, el__modulus *mod);
/* el_jacobi_eval for a prepared modulus: the cheap path for many u at one k
 * (d_dk only if the modulus was prepared with_dk). */
int el__jacobi_eval_mod(const el__modulus *mod, double u, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk);

/* Jacobi values and k-derivatives at u_n = z n + q for n = 0..count-1, by the
 * addition theorems with a fresh el_jacobi_eval every few steps (jacobi.c).
 * The amplitude am is not propagated (set to 0); every other field is.
 * val[count] required; d_dk[count] optional (NULL). */
int el__jacobi_progression(double q, double z, double k, size_t count,
                           el_jacobi *val, el_jacobi *d_dk);

/* Join count clamped planar B-splines of one degree p in 3..7, each on its own
 * parameter interval, end to end into *out (parameters shifted to follow each
 * other), C2 at the joints (knot multiplicity p - 2): each joint pole is the
 * next part's first, then the joint knot is removed twice (Piegl & Tiller A5.8),
 * which is exact when the parts meet with equal point, first and second
 * derivatives. *err: the largest gap between the parts' joint poles and removal
 * distance (a bound on how far *out is from the parts); out->max_deviation = -1.
 * bspline.c. Errors: EL_EINVAL, EL_ENOMEM. */
int el__bspline_join_c2(const el_bspline *parts, size_t count, el_bspline *out, double *err);

/* For the tests of spline.c: the piece p as the Hermite elastica of its own ends
 * (h = |gamma(L) - gamma(0)|), v = (phi, ln mu, k, q, L): J[25] = dR/dv with
 * R = ((gamma(L) - end)/h, theta(0) - ta, theta(L) - tb, (2 mu (2k^2-1) - sigma) h^2),
 * g0[5], g1[5] = d kappa(0)/dv, d kappa(L)/dv, M[25] = d(theta0, kappa0, kappa0', sigma, L)/dv,
 * d[9] = d(kappa(0), kappa(L), L)/d(ta, tb, sigma) by the implicit function theorem. */
int el__spline_piece_jacobians(const el_smooth_params *p, double *J, double *g0, double *g1,
                               double *M, double *d);

#endif
