/*
 * The elliptic integrals the library computes itself:
 * - Carlson's symmetric R_F(x, y, z) and R_D(x, y, z) together, by the
 *   duplication theorem and the series of DLMF 19.36.1-2 to seventh order (one
 *   duplication step fewer than Carlson's 1995 fifth-order series): both share
 *   the duplicated arguments, so one loop gives both;
 * - the complete integrals K(k) and D(k) = (K - E)/k^2 by the AGM.
 *
 * Written by hand, not taken from GSL, for speed and accuracy: they are the inner
 * loop of every Jacobi evaluation (jacobi.c) and of every Hermite objective
 * evaluation (hermite_objective.c); gsl_sf_ellint_RF_e / _RD_e (argument checks, error
 * estimates, one duplication loop each) cost about five times as much, and GSL's
 * Kcomp / Ecomp take only k and form 1 - k^2 themselves, which loses digits near
 * k = 1 (here k'^2 comes in exactly). tests/c/test_ellint.c checks them against GSL.
 */
#include "internal.h"
#include "lanes.h"
#include <float.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

/* sqrt(x) and sqrt(y) at once where SSE2 has a two-lane square root (the same
 * correctly rounded values: the duplication loop's latency is its square roots) */
static void sqrt2(double x, double y, double *sx, double *sy)
{
#if defined(__SSE2__)
    const __m128d r = _mm_sqrt_pd(_mm_set_pd(y, x));
    *sx = _mm_cvtsd_f64(r);
    *sy = _mm_cvtsd_f64(_mm_unpackhi_pd(r, r));
#else
    *sx = sqrt(x);
    *sy = sqrt(y);
#endif
}

/* max(|a - x|, |a - y|, |a - z|) without libm's fmax calls (inner loop) */
static double maxdev(double a, double x, double y, double z)
{
    const double dx = fabs(a - x), dy = fabs(a - y), dz = fabs(a - z);
    const double m = dx > dy ? dx : dy;
    return m > dz ? m : dz;
}

#include "ellint_series.h"

DEFINE_RF_SERIES(rf_series, double, sqrt)
DEFINE_RD_SERIES(rd_series, double, sqrt)

static int carlson_args_ok(double x, double y, double z)
{
    /* x, y >= 0 (NaN fails): x + y > 0 iff not both 0; the sum finite iff each is */
    return x >= 0.0 && y >= 0.0 && z > 0.0 && x + y > 0.0 && x + y + z <= DBL_MAX;
}

int el__carlson_fd(double x, double y, double z, double qs, double *rf, double *rd)
{
    if (!carlson_args_ok(x, y, z)) return EL_EDOM;
    const double AF0 = (x + y + z) / 3.0, AD0 = (x + y + 3.0 * z) / 5.0;
    const double x0 = x, y0 = y;
    /* stop when the truncated series (error ~ c d^8, d the largest relative deviation
     * from the mean; c ~ 0.02 for R_F, 0.3 for R_D, measured against mpmath) is
     * accurate to r relative: d <= 1/Q with Q = 80 (R_F), 120 (R_D) times qs for
     * r = 1e-16 (qs = 1); r ~ 1e-16 qs^-8 otherwise */
    const double QF = rf ? qs * 80.0 * maxdev(AF0, x, y, z) : 0.0;
    const double QD = qs * 120.0 * maxdev(AD0, x, y, z);
    /* 80 or 120 times the deviation beyond DBL_MAX (a sum of the arguments near it, x = 0,
     * y = 1e308): the test Q dev0 >= A below would hold for ever (A reaches inf). Such
     * arguments are outside what this computes anyway: R_D's num / den overflows to inf / inf
     * once the arguments pass ~1e40 (EL_EDOM below), so they get that status at once. */
    if (QF > DBL_MAX || QD > DBL_MAX) return EL_EDOM;
    /* The duplication x <- (x + lam)/4 (DLMF 19.26.18) without the 1/4: the arguments
     * and means grow by 4 per step instead, lam by 4 and the square roots by 2, which are
     * exact scalings (the same bits as Carlson's, one multiplication less on the loop's
     * critical path); the deviations from the means shrink by 4 per step relative to
     * them, so the test d <= 1/Q reads Q dev0 < A. R_D's sum of
     * 4^-n / (sqrt(z_n) (z_n + lam_n)) in Carlson's scale (d = 8^-n times ours) kept
     * as one fraction num / den (the denominators are O(1) and there are a handful: no
     * overflow). */
    double AF = AF0, AD = AD0, f2 = 1.0, f4 = 1.0, f8 = 1.0, num = 0.0, den = 1.0;
    while (QF >= AF || QD >= AD) {
        /* sqrt is what this loop costs: z = 1 (every caller's first step) is free */
        double sx, sy;
        sqrt2(x, y, &sx, &sy);
        const double sz = z == 1.0 ? 1.0 : sqrt(z);
        const double lam = sx * sy + sx * sz + sy * sz, d = f8 * (sz * (z + lam));
        num = num * d + f4 * den;
        den *= d;
        AF += lam;
        AD += lam;
        x += lam;
        y += lam;
        z += lam;
        f2 *= 2.0;
        f4 *= 0.25;
        f8 *= 0.125;
    }
    if (rf) *rf = rf_series(AF0, x0, y0, f2, AF);
    *rd = rd_series(AD0, x0, y0, f2, AD, num, den);
    return (rf && !isfinite(*rf)) || !isfinite(*rd) ? EL_EDOM : EL_OK;
}

#define LANES_W 2
#include "carlson_lanes.h"

/* a0 = 1, b0 = k', c0 = k, a_{n+1} = (a_n + b_n)/2, b_{n+1} = sqrt(a_n b_n),
 * c_{n+1} = c_n^2 / (4 a_{n+1}) (no cancellation, unlike (a_n - b_n)/2): K = pi / (2 a_N)
 * and K - E = K sum 2^(n-1) c_n^2 (A&S 17.6), so D = (K - E)/k^2 = K sum 2^(n-1) (c_n/k)^2
 * with c_n / k carried along (no cancellation as k -> 0). Quadratic convergence, one
 * sqrt per step: three times cheaper than R_F and R_D. */
int el__ellint_complete(double k, double kc2, double *K, double *D)
{
    if (!(kc2 > 0.0) || !(k >= 0.0) || !isfinite(k + kc2)) return EL_EDOM;
    double a = 1.0, b = sqrt(kc2), c = k, ct = 1.0, w = 0.5, sum = 0.5; /* ct = c_n / k */
    /* stop at |a - b| <= 1e-9 a: one more step is then exact to rounding (quadratic
     * convergence). K alone (D = NULL): the same a_n and stop, without the c_n sums (two
     * divisions a step) */
    for (int n = 0; n < 40; n++) {
        const double an = 0.5 * (a + b);
        if (D) {
            ct = c * ct / (4.0 * an);
            c = c * c / (4.0 * an);
            w *= 2.0;
            sum += w * ct * ct;
        }
        const int last = fabs(a - b) <= 1e-9 * a;
        b = sqrt(a * b);
        a = an;
        if (last) break;
    }
    *K = M_PI / (2.0 * a);
    if (D) *D = *K * sum;
    return EL_OK;
}
