/* Shared helpers for the Check test programs: one runner per test file. */
#ifndef EL_TESTUTIL_H
#define EL_TESTUTIL_H

#include <check.h>
#include <math.h>
#include <stdlib.h>
#include "elastica.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* |a - b| <= tol, with a message naming both values. */
#define ck_assert_close(a, b, tol) do { \
    double _a = (a), _b = (b), _t = (tol); \
    ck_assert_msg(fabs(_a - _b) <= _t, "%s = %.17g, %s = %.17g, |diff| = %.3g > %.3g", \
                  #a, _a, #b, _b, fabs(_a - _b), _t); } while (0)

/* The discrete curve p's tangent at vertex j, theta_j = phi + 2 a(q + j z) (sin a = k sn,
 * cos a = dn: the fit's tangent constraint; seed 000 (4.4)). */
static inline double discrete_vertex_tangent(const el_discrete_params *p, double j)
{
    el_jacobi J;
    ck_assert_int_eq(el_jacobi_eval(p->q + j * p->z, p->k, &J, NULL, NULL), EL_OK);
    return p->phi + 2.0 * atan2(p->k * J.sn, J.dn);
}

/* Deterministic uniform random number in [lo, hi) (xorshift, per-test state). */
static inline double test_uniform(unsigned long long *state, double lo, double hi)
{
    unsigned long long x = *state;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    *state = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

/* Deterministic standard normal number (Box-Muller from two test_uniform draws). */
static inline double test_normal(unsigned long long *state)
{
    const double u1 = test_uniform(state, 1e-300, 1.0), u2 = test_uniform(state, 0.0, 1.0);
    return sqrt(-2.0 * log(u1)) * cos(2.0 * M_PI * u2);
}

/* Run one suite, return the process exit code. */
static inline int test_run_suite(Suite *s)
{
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}

#endif
