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

/* Jacobi sn, cn, dn, D (and k-derivatives) at many u_i at a few flops per point
 * (jacobi_walk.c; am and E are not filled). The caller keeps max(1, k)|u_i| <= EL__PHASE_MAX.
 *   el__walk wk;
 *   el__walk_init(&wk, k, with_dk, n);         any u_i (fast when sorted), or
 *   el__walk_grid(&wk, u0, z);                 after init: u_i = u0 + z i, u ignored;
 *   el__walk_values(&wk, count, u, val, dk);   the next count points (call repeatedly);
 * with n < WALK_MIN_POINTS every point gets a fresh el__jacobi_eval_mod (setup would
 * cost more). dk[count] only when with_dk. Statuses: those of el__jacobi_eval_mod. */
enum { WALK_PLAIN, WALK_GRID, WALK_ANCHORED, WALK_MIN_POINTS = 8 };
typedef struct el__walk {
    el__modulus mod;
    double k, kappa;           /* k >= 0 and max(1, k) */
    int with_dk, mode, from_grid;
    double u0, z;              /* the grid u0 + z i, next = the index of the next point */
    size_t next;
    el_jacobi zstep, zstepk, cur, curk;
    double H, ua;              /* anchor spacing; where the anchors' fresh evaluation is */
    int ja, steps;             /* current anchor (index from ua), steps since fresh; -1: none */
    int have_hstep, have_series;
    el_jacobi hstep[2], hstepk[2], anc, anck;
    double ser[8][6];          /* Maclaurin coefficients of sn cn dn D and their k-derivatives */
} el__walk;
int el__walk_init(el__walk *wk, double k, int with_dk, size_t n);
int el__walk_grid(el__walk *wk, double u0, double z);
int el__walk_values(el__walk *wk, size_t count, const double *u, el_jacobi *val, el_jacobi *dk);

/* The largest max(1, k)|u| whose Jacobi functions keep digits: 2K is known to a
 * rounding, so reducing u costs |u| 2^-53 of the phase (a quarter at this bound). */
#define EL__PHASE_MAX 0x1p50

#endif
