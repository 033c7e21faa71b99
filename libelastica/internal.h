/* Internal helpers shared by the library's files (not installed). */
#ifndef EL_INTERNAL_H
#define EL_INTERNAL_H

#include "elastica.h"
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Turn GSL's aborting error handler off (once per process, thread-safe); every
 * entry point that calls GSL calls this first and maps GSL statuses to EL_ codes. */
void el__gsl_quiet(void);

/* EL_OK when all n values are finite. */
int el__all_finite(const double *v, size_t n);

/* Checked size arithmetic: every array size the library computes goes through
 * these, so none can wrap around. Return 0 and store the result, or 1 when it
 * would exceed SIZE_MAX (no such array can exist; callers answer EL_ENOMEM for
 * what they allocate, EL_EINVAL for a count the caller claims to hold). */
static inline int el__size_mul(size_t a, size_t b, size_t *out)
{
    if (b != 0 && a > (size_t)-1 / b) return 1;
    *out = a * b;
    return 0;
}

static inline int el__size_add(size_t a, size_t b, size_t *out)
{
    if (a > (size_t)-1 - b) return 1;
    *out = a + b;
    return 0;
}

/* 1 when count elements of per * elem bytes each do not fit in memory (the
 * product wraps around SIZE_MAX), e.g. el__too_many(n, 2, sizeof(double)) for n
 * interleaved points; 0 otherwise. */
static inline int el__too_many(size_t count, size_t per, size_t elem)
{
    size_t t;
    return el__size_mul(count, per, &t) || el__size_mul(t, elem, &t);
}

/* malloc of count * per elements of elem bytes; NULL when that wraps or fails. */
void *el__alloc(size_t count, size_t per, size_t elem);
/* realloc likewise; p is left untouched (still owned by the caller) on NULL. */
void *el__realloc(void *p, size_t count, size_t per, size_t elem);

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

#endif
