/*
 * el__carlson_fd2 and el__carlson_fd4: one text for both widths (lanes_generic.h),
 * included with LANES_W set by ellint.c (2) and hermite_lanes_avx2.c (4).
 */
#include "lanes_generic.h"
#include "ellint_series.h"
#include <float.h>

DEFINE_RF_SERIES(LN(rf_series), LV, lv_sqrt)
DEFINE_RD_SERIES(LN(rd_series), LV, lv_sqrt)

/* el__carlson_fd(x, y, 1, qs, ...) in LANES_W lanes at once (lanes.h), the same operations
 * lane by lane: the duplication loop runs until every lane's test stop it, a lane's values
 * frozen from its own stop on. Two (four) evaluations' square roots and divisions side by side, in
 * one SSE2 (AVX) operation each (one evaluation's chain of them is what el__carlson_fd costs, its
 * latency). A lane with bad arguments computes (1, 1, 1) and has ok = 0. */
void LN(el__carlson_fd)(LV x, LV y, double qs, LV *rf, LV *rd, LM *ok)
{
    const LV one = LV1(1.0);
    LM good = lm_and(lm_and(x >= 0.0, y >= 0.0), lm_and(x + y > 0.0, x + y + 1.0 <= DBL_MAX));  /* carlson_args_ok */
    x = lv_sel(good, x, one);
    y = lv_sel(good, y, one);
    LV z = one;
    const LV x0 = x, y0 = y, AF0 = (x + y + z) / 3.0, AD0 = (x + y + 3.0 * z) / 5.0;
    /* maxdev */
    const LV fx = lv_abs(AF0 - x), fy = lv_abs(AF0 - y), fz = lv_abs(AF0 - z);
    const LV fm = lv_sel(fx > fy, fx, fy), dx = lv_abs(AD0 - x), dy = lv_abs(AD0 - y);
    const LV dz = lv_abs(AD0 - z), dm = lv_sel(dx > dy, dx, dy);
    LV QF = qs * 80.0 * lv_sel(fm > fz, fm, fz), QD = qs * 120.0 * lv_sel(dm > dz, dm, dz);
    /* el__carlson_fd's EL_EDOM where the stopping test overflows: such a lane runs no step
     * (0 < A) and is not ok; the other lane's steps and values are its own */
    const LM huge = lm_or(QF > DBL_MAX, QD > DBL_MAX);
    if (lm_any(huge)) {
        QF = lv_sel(huge, LV1(0.0), QF);
        QD = lv_sel(huge, LV1(0.0), QD);
        good = lm_andnot(huge, good);
    }
    LV AF = AF0, AD = AD0, f2 = one, f4 = one, f8 = one, num = LV1(0.0), den = one;
    for (;;) {
        const LM act = lm_or(QF >= AF, QD >= AD);
        if (!lm_any(act)) break;
        const LV sx = lv_sqrt(x), sy = lv_sqrt(y), sz = lv_sqrt(z);   /* sqrt(1) = 1 */
        const LV lam = sx * sy + sx * sz + sy * sz, d = f8 * (sz * (z + lam));
        /* a stopped lane keeps what the series reads (AF, AD, f2, num, den: lam & act is +0
         * there, and v + 0 = v for the positive sums); its x, y, z, f4, f8 run on unread */
        const LV lact = lv_and(lam, act);
        num = lv_sel(act, num * d + f4 * den, num);
        den = lv_sel(act, den * d, den);
        AF = AF + lact;
        AD = AD + lact;
        x = x + lam;
        y = y + lam;
        z = z + lam;
        f2 = f2 + lv_and(f2, act);   /* f2 * 2 exactly */
        f4 = f4 * 0.25;
        f8 = f8 * 0.125;
    }
    *rf = LN(rf_series)(AF0, x0, y0, f2, AF);
    *rd = LN(rd_series)(AD0, x0, y0, f2, AD, num, den);
    *ok = lm_and(good, lm_and(lv_finite(*rf), lv_finite(*rd)));
}

