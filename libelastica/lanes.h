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

/* The four lanes (el_d4 below) are built on x86-64 (hermite_lanes_avx2.c, compiled with
 * -mavx2) unless EL_NO_LANES4 is defined (then only the two, as on other processors), and
 * run where el__lanes4_available(): the processor has AVX2 and the OS saves its registers. */
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__)) && !defined(EL_NO_LANES4)
#define EL__LANES4 1
#else
#define EL__LANES4 0
#endif
int el__lanes4_available(void);
/* el__carlson_fd4 on arrays of four (for the tests, which are not compiled for AVX2): ok[l]
 * 1 where lane l is EL_OK; only where el__lanes4_available() */
void el__carlson_fd4v(const double *x, const double *y, double qs, double *rf, double *rd, int *ok);

#if defined(__AVX__)
#include <immintrin.h>
/* Four doubles side by side: the same operations in AVX's 256-bit registers, for the
 * objects compiled with -mavx2 (hermite_lanes_avx2.c) and run only where the processor
 * has it (el__lanes4_available). Without -mfma, and with -ffp-contract=off, no
 * multiplication and addition are fused: each lane rounds as the scalar code does. */
typedef double el_d4 __attribute__((vector_size(32)));
typedef long long el_m4 __attribute__((vector_size(32)));

/* a where m, else b (a blend by the mask's sign bits: a mask is all ones or zero) */
static inline el_d4 el_d4_sel(el_m4 m, el_d4 a, el_d4 b)
{
    return (el_d4)_mm256_blendv_pd((__m256d)b, (__m256d)a, (__m256d)m);
}
static inline el_d4 el_d4_sqrt(el_d4 a) { return (el_d4)_mm256_sqrt_pd((__m256d)a); }
static inline el_d4 el_d4_and(el_d4 a, el_m4 m) { return (el_d4)_mm256_and_pd((__m256d)a, (__m256d)m); }
static inline el_d4 el_d4_abs(el_d4 a)
{
    return (el_d4)((el_m4)a & (el_m4){INT64_MAX, INT64_MAX, INT64_MAX, INT64_MAX});
}
static inline el_m4 el_d4_finite(el_d4 a) { return a - a == 0.0; }
static inline el_m4 el_m4_or(el_m4 m, el_m4 n) { return (el_m4)_mm256_or_pd((__m256d)m, (__m256d)n); }
static inline el_m4 el_m4_and(el_m4 m, el_m4 n) { return (el_m4)_mm256_and_pd((__m256d)m, (__m256d)n); }
static inline el_m4 el_m4_andnot(el_m4 m, el_m4 n) { return (el_m4)_mm256_andnot_pd((__m256d)m, (__m256d)n); }
static inline int el_m4_any(el_m4 m) { return _mm256_movemask_pd((__m256d)m) != 0; }

/* el__carlson_fd2 in four lanes (hermite_lanes_avx2.c) */
void el__carlson_fd4(el_d4 x, el_d4 y, double qs, el_d4 *rf, el_d4 *rd, el_m4 *ok);
#endif

#endif
