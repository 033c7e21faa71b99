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

/* Check's ck_assert_msg (and every ck_assert_* built on it) writes a checkpoint at each
 * assertion that passes, one write(2) each: 15 M of them in make check-c (loops asserting
 * per point), ~40 % of its CPU time and more under ASan. Here a passing assertion records
 * nothing; a failing one calls Check's _ck_assert_failed exactly as check.h does (same
 * file, line, expression, message). Only a crash or a timeout is located less closely: at
 * the test's start (or its last mark_point()) instead of its last passing assertion. */
#undef ck_assert_msg
#define ck_assert_msg(expr, ...) \
    ((expr) ? (void)0 : _ck_assert_failed(__FILE__, __LINE__, "Assertion '"#expr"' failed" , ## __VA_ARGS__))

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

/* A smooth curve of kind 0..7 for the fast paths' equality tests, its length left to the
 * caller (drawn from *state in a fixed order: x0, y0, phi, mu, then k and q by kind):
 * mu 1e-12..1e12; k in (-1, 1), +-(1 +- 1e-16..1e-1), +-1, up to +-50, 0, or in (-3, 3);
 * kind 5 |q| 1e10..1e17 (phases past EL__PHASE_MAX), kind 7 |x0| to 1e6; *sign a random sign. */
static inline el_smooth_params test_smooth_of_kind(int kind, unsigned long long *state, double *sign)
{
    el_smooth_params p;
    p.x0 = test_uniform(state, -10.0, 10.0) * (kind == 7 ? 1e6 : 1.0);
    p.y0 = test_uniform(state, -10.0, 10.0);
    p.phi = test_uniform(state, -10.0, 10.0);
    p.mu = pow(10.0, test_uniform(state, -12.0, 12.0));
    const double e = pow(10.0, test_uniform(state, -16.0, -1.0)) * (test_uniform(state, 0.0, 1.0) < 0.5 ? -1.0 : 1.0);
    const double sg = test_uniform(state, 0.0, 1.0) < 0.5 ? -1.0 : 1.0;
    p.k = kind == 0 ? test_uniform(state, -1.0, 1.0) : kind == 1 ? sg * (1.0 + e) : kind == 2 ? sg
        : kind == 3 ? test_uniform(state, -50.0, 50.0) : kind == 4 ? 0.0 : test_uniform(state, -3.0, 3.0);
    p.q = kind == 5 ? sg * pow(10.0, test_uniform(state, 10.0, 17.0)) : test_uniform(state, -50.0, 50.0);
    p.length = 0.0;
    *sign = sg;
    return p;
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
