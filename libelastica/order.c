/*
 * The polyline screen of the binding's order check (python/libelastica/order.py,
 * out_of_order): the points' extent, the length and mean |turn| a vertex of the
 * polyline through every step-th point (step 1: the whole polyline). O(n), no
 * allocation, where numpy took a dozen array passes and copies on every fit.
 *
 * Sums are numpy's pairwise sums (blocks of 128, eight accumulators): the binding's
 * answers stay those of its former numpy formulas, bit for bit (but atan2: numpy's
 * vectorised one differs by an ulp or two). The library builds
 * with -std=c99, so a*b + c*d is not contracted to an fma (numpy's is not either).
 */
#include "internal.h"

#include <math.h>

/* What a term of a pairwise sum is: a side's length or a vertex's |turn|. */
typedef struct {
    const double *xy;
    size_t step;
    int turn;
} terms;

/* The side from point i step to point (i + 1) step. */
static void side(const terms *t, size_t i, double *d)
{
    const double *p = t->xy + 2 * i * t->step, *q = p + 2 * t->step;
    d[0] = q[0] - p[0];
    d[1] = q[1] - p[1];
}

/* Term i: |side i| = sqrt(d.d); or the |turn| at the vertex between sides i and i + 1,
 * |atan2(a x b, a . b)|, the dot summed from +0 as numpy's einsum does: a zero side
 * (a repeated point) turns atan2(0, +0) = 0, not atan2(0, -0) = pi. */
static double term(const terms *t, size_t i)
{
    double a[2], b[2];
    side(t, i, a);
    if (!t->turn) return sqrt(a[0] * a[0] + a[1] * a[1]);
    side(t, i + 1, b);
    return fabs(atan2(a[0] * b[1] - a[1] * b[0], 0.0 + a[0] * b[0] + a[1] * b[1]));
}

/* Terms lo .. lo + n - 1 summed as numpy's pairwise_sum (umath/loops_utils.h.src). */
static double pairwise(const terms *t, size_t lo, size_t n)
{
    if (n > 128) {
        size_t n2 = n / 2;
        n2 -= n2 % 8;
        return pairwise(t, lo, n2) + pairwise(t, lo + n2, n - n2);
    }
    double res = 0.0;
    size_t i = 0;
    if (n >= 8) {
        double r[8];
        for (int j = 0; j < 8; j++) r[j] = term(t, lo + (size_t)j);
        for (i = 8; i < n - n % 8; i += 8)
            for (int j = 0; j < 8; j++) r[j] += term(t, lo + i + (size_t)j);
        res = ((r[0] + r[1]) + (r[2] + r[3])) + ((r[4] + r[5]) + (r[6] + r[7]));
    }
    for (; i < n; i++) res += term(t, lo + i);
    return res;
}

int el_order_screen(const double *xy, size_t n, size_t step, int turn,
                    el_order_screen_result *out)
{
    if (!xy || !out || n < 1 || step < 1 || el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;
    double lo[2] = {xy[0], xy[1]}, hi[2] = {xy[0], xy[1]};
    for (size_t k = 1; k < n; k++)
        for (int j = 0; j < 2; j++) {
            const double v = xy[2 * k + j];
            if (v < lo[j]) lo[j] = v;
            if (v > hi[j]) hi[j] = v;
        }
    const size_t m = (n - 1) / step + 1;     /* points 0, step, 2 step, ... */
    terms t = {xy, step, 0};
    el_order_screen_result r;
    r.extent = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    r.length = pairwise(&t, 0, m - 1);
    r.turn = NAN;
    if (turn && m >= 3) {
        t.turn = 1;
        r.turn = pairwise(&t, 0, m - 2) / (double)(m - 2);
    }
    *out = r;
    return EL_OK;
}
