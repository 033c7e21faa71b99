/*
 * A smooth keyline whose feet pile up at a far end, fitted again tied to the points
 * farthest along each side (fit_ends.h, el__fit_keyline_ends).
 *
 * The smooth keyline ties point 0 to the first side's far end and point n-1 to the
 * second's by full residual vectors (fit_objective.c keyline_smooth), as the plain smooth
 * fit ties its ends (fit_ends.c, which this follows): on a scan dense at its start, point
 * 0's noise can put it inside the cloud, the first side then stops there and the points
 * beyond it count their distance to its end (measured: 200 points along a 20-long
 * elastica at s ~ u^4, noise 0.05: rms 1.81 x the true curve's, 60 feet at the far end).
 * The objective's feet reach 5 % past each far end (el__fit_feet_range), so those points
 * cost nothing there while the tie holds the length. Where one point in PILE_SHARE (and
 * PILE_LEAST) piles at a far end, the points farthest along each side on the curves continued
 * (KEYLINE_REACH) are moved to the ends of a copy of the points, each side is cut to that
 * point's foot (the joint stays), and Levenberg-Marquardt fits the keyline tied to them.
 * That fit replaces the first where certified (or the first was not) and of lower rms
 * (every point's distance to the curve, as reported), in rounds while the rms falls by
 * PILE_GAIN. Measured on 40 scans dense at one end (200 points along a 20-long elastica
 * at s ~ u^1.5 .. u^4, noise 0.05): keyline rms / the true curve's 0.885-0.990 (before:
 * 0.934-1.812, 13 above 1). A keyline without such a pile is not touched (one count of its
 * feet).
 */
#include "fit_ends.h"
#include <stdlib.h>
#include <string.h>

/* the curves continued to this multiple of their lengths to find the points farthest along */
static const double KEYLINE_REACH = 1.5;

/* The sum of squared distances of the points to the keyline at x (feet fs, sides sd), EL_OK
 * or el__fit_feet_distances' error. */
static int sum_sq(fit_objective *o, const double *x, double *d, double *fs, int *sd, double *s2)
{
    const int st = el__fit_feet_distances(o, x, d, fs, sd);
    if (st) return st;
    double a = 0.0;
    for (size_t i = 0; i < o->n; i++) a += d[i] * d[i];
    *s2 = a;
    return EL_OK;
}

/* The keyline fitted from x with the points farthest along its sides, measured on its curves
 * continued to KEYLINE_REACH x their lengths (feet fs, sides sd: el__fit_feet_distances from
 * ob's feet), moved to points 0 and n-1 of a copy pxy and tied to its far ends, each side cut
 * to that point's foot; its solution *t, its sum of squares *s2 (0 where it gave none), its
 * feet sig (signed, the caller's order). *same: the extremes are points 0 and n-1. */
static int tied_at_extremes(fit_objective *ob, const double *x0, int max_iter, double *pxy, double *sig,
                            double *d, double *fs, int *sd, fit_solution *t, double *s2, int *iters, int *same)
{
    const size_t n = ob->n;
    double x[FIT_MAXX];
    memcpy(x, x0, sizeof x);
    x[5] *= KEYLINE_REACH;      /* L1, L2: fit_keyline.c's variables (smooth, nx = 9) */
    x[8] *= KEYLINE_REACH;
    *s2 = 0.0;
    *same = 1;
    int st = el__fit_feet_distances(ob, x, d, fs, sd);
    if (st) return st == EL_ENOMEM ? st : EL_OK;
    size_t lo = n, hi = n;
    for (size_t i = 0; i < n; i++) {
        size_t *e = sd[i] ? &hi : &lo;
        if (*e == n || fs[i] > fs[*e]) *e = i;
    }
    if (lo == n || hi == n || lo == n - 1 || hi == 0 || !(fs[lo] > 0.0 && fs[hi] > 0.0)) return EL_OK;
    *same = lo == 0 && hi == n - 1;
    if (*same) return EL_OK;
    x[5] = fs[lo];
    x[8] = fs[hi];
    memcpy(pxy, ob->xy, sizeof(double) * 2 * n);
    for (size_t i = 0; i < n; i++) sig[i] = sd[i] ? fs[i] : -fs[i];
    swap_points(pxy, sig, NULL, 0, lo);
    swap_points(pxy, sig, NULL, n - 1, hi);
    fit_objective o2;
    if ((st = el__fit_objective_init(&o2, FIT_KEYLINE, &ob->map, pxy, n, ob->cx, ob->cy, ob->sc, NULL)))
        return st;
    o2.split = ob->split;
    memcpy(o2.s, sig, sizeof(double) * n);
    st = el__fit_lm(&o2, x, max_iter, t);
    if (st == EL_OK) {
        *iters += t->iters;
        double a;
        if (sum_sq(&o2, t->x, d, fs, sd, &a) == EL_OK) {
            *s2 = a;
            for (size_t i = 0; i < n; i++) sig[i] = sd[i] ? fs[i] : -fs[i];
            swap_points(pxy, sig, NULL, n - 1, hi);     /* back to the caller's order */
            swap_points(pxy, sig, NULL, 0, lo);
        }
    }
    el__fit_objective_free(&o2);
    return st == EL_ENOMEM ? st : EL_OK;
}

int el__fit_keyline_ends(fit_objective *ob, int max_iter, fit_solution *sol, int *iters)
{
    const size_t n = ob->n;
    if (ob->map.nx != 9) return EL_OK;     /* the smooth keyline (fit_keyline.c calls it for it alone) */
    const double L[2] = {sol->x[5], sol->x[8]};     /* the sides' lengths, as tied_at_extremes */
    double *buf = malloc(sizeof(double) * 6 * n);
    int *sd = malloc(sizeof(int) * n);
    if (!buf || !sd) { free(buf); free(sd); return EL_ENOMEM; }
    double *d = buf, *fs = buf + n, *pxy = buf + 2 * n, *sig = buf + 4 * n;
    int st = EL_OK;
    double base;
    if (sum_sq(ob, sol->x, d, fs, sd, &base)) goto done;
    size_t pile[2] = {0, 0};
    for (size_t i = 1; i + 1 < n; i++)
        if (fs[i] >= L[sd[i]]) pile[sd[i]]++;
    const size_t least = fit_ends_pile(n);
    if (pile[0] < least && pile[1] < least) goto done;
    for (int round = 0; round < PILE_ROUNDS; round++) {
        fit_solution t;
        double s2;
        int same;
        st = tied_at_extremes(ob, sol->x, max_iter, pxy, sig, d, fs, sd, &t, &s2, iters, &same);
        if (st || same || !(s2 > 0.0 && s2 < base && (t.certified || !sol->certified))) break;
        const int gain = s2 < (1.0 - PILE_GAIN) * base;
        *sol = t;
        base = s2;
        memcpy(ob->s, sig, sizeof(double) * n);
        if (!gain) break;
    }
    ob->have_base = 0;
    ob->rest_ok = 0;
done:
    free(buf);
    free(sd);
    return st;
}
