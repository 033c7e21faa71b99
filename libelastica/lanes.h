/*
 * Two doubles side by side, for evaluations that are independent of each other and
 * computed together (hermite_lanes.c, ellint.c's el__carlson_fd2): GCC's vector
 * extension (also Clang's), two-lane SSE2 operations on x86-64 and plain code
 * elsewhere. Each lane's arithmetic is what the scalar code's would be (IEEE operations
 * lane by lane; square roots correctly rounded either way), so the values are the same
 * bits; branches become masks (a comparison gives all ones or zero per lane) and
 * selections by them.
 */
#ifndef EL_LANES_H
#define EL_LANES_H

#include <math.h>
#include <stdint.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

typedef double el_d2 __attribute__((vector_size(16)));
typedef long long el_m2 __attribute__((vector_size(16)));

/* a where m, else b */
static inline el_d2 el_d2_sel(el_m2 m, el_d2 a, el_d2 b)
{
#if defined(__SSE2__)
    /* and, andnot, or (GCC turns the generic expression into a lane-by-lane branch) */
    const __m128d mm = (__m128d)m;
    return (el_d2)_mm_or_pd(_mm_and_pd(mm, (__m128d)a), _mm_andnot_pd(mm, (__m128d)b));
#else
    return (el_d2)(((el_m2)a & m) | ((el_m2)b & ~m));
#endif
}

static inline el_d2 el_d2_sqrt(el_d2 a)
{
#if defined(__SSE2__)
    return (el_d2)_mm_sqrt_pd((__m128d)a);
#else
    return (el_d2){sqrt(a[0]), sqrt(a[1])};
#endif
}

/* a where m, else +0 */
static inline el_d2 el_d2_and(el_d2 a, el_m2 m)
{
#if defined(__SSE2__)
    return (el_d2)_mm_and_pd((__m128d)a, (__m128d)m);
#else
    return (el_d2)((el_m2)a & m);
#endif
}

/* fabs: the sign bit cleared */
static inline el_d2 el_d2_abs(el_d2 a) { return (el_d2)((el_m2)a & (el_m2){INT64_MAX, INT64_MAX}); }

/* isfinite lane by lane: a - a is 0 for finite a, NaN for infinities and NaNs */
static inline el_m2 el_d2_finite(el_d2 a) { return a - a == 0.0; }

/* m | n: SSE2's or where the compiler would otherwise turn two comparisons' masks into
 * booleans and back (a dozen instructions in the duplication loop's test) */
static inline el_m2 el_m2_or(el_m2 m, el_m2 n)
{
#if defined(__SSE2__)
    return (el_m2)_mm_or_pd((__m128d)m, (__m128d)n);
#else
    return m | n;
#endif
}

/* m & n, and ~m & n, likewise */
static inline el_m2 el_m2_and(el_m2 m, el_m2 n)
{
#if defined(__SSE2__)
    return (el_m2)_mm_and_pd((__m128d)m, (__m128d)n);
#else
    return m & n;
#endif
}

static inline el_m2 el_m2_andnot(el_m2 m, el_m2 n)
{
#if defined(__SSE2__)
    return (el_m2)_mm_andnot_pd((__m128d)m, (__m128d)n);
#else
    return ~m & n;
#endif
}

/* whether m is set in either lane (the sign bits: a mask is all ones or zero) */
static inline int el_m2_any(el_m2 m)
{
#if defined(__SSE2__)
    return _mm_movemask_pd((__m128d)m) != 0;
#else
    return (m[0] | m[1]) != 0;
#endif
}

/* Carlson's R_F and R_D of (x, y, 1) lane by lane (ellint.c): el__carlson_fd's values,
 * ok all ones where it gives EL_OK. */
void el__carlson_fd2(el_d2 x, el_d2 y, double qs, el_d2 *rf, el_d2 *rd, el_m2 *ok);

#endif
