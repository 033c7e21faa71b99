/*
 * hermite_lanes.c's objective in four lanes: the same text (hermite_lanes_body.h,
 * carlson_lanes.h) in AVX's 256-bit registers. This object alone is compiled with -mavx2
 * (the Makefile; no -mfma and -ffp-contract=off: no fused multiply-add, each lane rounds
 * as the scalar code does), and el__hermite_x_objectives calls it only where
 * __builtin_cpu_supports("avx2"): the library runs on every x86-64 and elsewhere. On
 * bench_hermite.py's 10 000 problems by tension: the solutions bit for bit those of the
 * two lanes, 13 % fewer instructions in el_hermite_solve, ~9 % less time (AMD EPYC, Zen 3:
 * a 256-bit square root or division costs what a 128-bit one does).
 */
#include "hermite_internal.h"
#include "lanes.h"

#if EL__LANES4
#if !defined(__AVX2__)
#error "hermite_lanes_avx2.c is compiled with -mavx2 (the Makefile)"
#endif

#define LANES_W 4
#include "carlson_lanes.h"

#define LANES_NARROWER el__hermite_x_objectives2
#include "hermite_lanes_body.h"

void el__carlson_fd4v(const double *x, const double *y, double qs, double *rf, double *rd, int *ok)
{
    el_d4 f, d;
    el_m4 m;
    el__carlson_fd4((el_d4){x[0], x[1], x[2], x[3]}, (el_d4){y[0], y[1], y[2], y[3]}, qs, &f, &d, &m);
    for (int l = 0; l < 4; l++) {
        rf[l] = f[l];
        rd[l] = d[l];
        ok[l] = m[l] != 0;
    }
}
#else
/* not x86-64 (or EL_NO_LANES4): el__hermite_x_objectives keeps to two lanes */
typedef int el__no_lanes4;
#endif
