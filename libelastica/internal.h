/* Internal helpers shared by the library's files (not installed). */
#ifndef EL_INTERNAL_H
#define EL_INTERNAL_H

#include "elastica.h"
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
/* The largest max(1, k)|u| whose Jacobi functions keep digits: 2K is known to a
 * rounding, so reducing u costs |u| 2^-53 of the phase (a quarter at this bound). */
#define EL__PHASE_MAX 0x1p50

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

/* The largest max(1, k)|u| whose Jacobi functions keep digits: 2K is known to a
 * rounding, so reducing u costs |u| 2^-53 of the phase (a quarter at this bound). */
#define EL__PHASE_MAX 0x1p50

#endif
