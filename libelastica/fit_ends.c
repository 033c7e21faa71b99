/*
 * A free smooth fit whose feet pile up at an end, fitted again with its ends free and tied
 * to the points farthest along it (fit_ends.h, el__fit_free_ends). The discrete fit by
 * distance ties its polygon's first and last vertices to the first and last points as the
 * smooth fit ties its ends (fit_objective.c discrete_orthogonal) and stops short of a retraced
 * end alike: it is refitted tied to its extremes the same way (its polygon's end vertices and
 * end segments' angles for the curve's ends and tangents), without run_free (a polygon cut to
 * its feet's range is not one of n vertices). Measured: 100 pixel strokes with retraces of
 * 0-12 px (noise 0.2-0.6 px, 0.5 / 1 px quanta, even and uneven steps), the point farthest
 * from the polygon > 2 px in 62 before, 43 after (28 refitted, 1.43-3.85 -> 0.66-2.23 px, rms
 * lower in all 28); the rest lie within FIT_RETRACE_PAST levels of the tied end.
 *
 * The smooth fit by distance ties its first and last points to gamma(0) and gamma(L) by
 * full residual vectors (fit_objective.c), so the curve begins and ends at their feet. On a
 * scan dense at one end (spacing far below the noise) the first point's noise can put it
 * inside the cloud: the curve then stops there, the points beyond it count their distance
 * to its end point (their feet held at s = 0), and the fit is not the least-squares one
 * (measured, QA: 200 points along a 30-long elastica at s ~ u^4, noise 0.05: rms 0.0899,
 * the true curve's 0.0527, 57 feet at s = 0; the same points with point 0 swapped with point
 * 10: 0.0503). Where such feet pile up (PILE_LEAST points or more but the end point
 * itself at either end), the fit runs again from its curve: first with no point tied
 * (run_free), its curve cut to its feet's range and tied from there to the points at its
 * ends; else, and then in further rounds from the fit kept, on the points reordered so that
 * the first and last are those farthest back and forward along it (a point beyond an end by
 * its tangential offset from that end), which the tie then lets the curve reach. Each is
 * kept when certified as the fit was and of lower rms; the rounds go on while one lowers it
 * by PILE_GAIN. A fit without such a pile is not touched (one count of its feet).
 * Measured: QA's 40 draws of such scans (s ~ u^1.5 .. u^4), smooth rms / the truth's on the
 * same points 0.894-0.997 (before: 0.941-1.707, 14 above 1); bench_fit.py's smooth fits, whose
 * noise piles a few feet (below one in PILE_SHARE), untouched.
 */
#include "fit_ends.h"
#include "fit_wander.h"
#include <stdlib.h>
#include <string.h>

/* The length of the fit p of n points (model: FIT_SMOOTH or FIT_DISCRETE): the smooth curve's
 * L, the discrete polygon's (n - 1) h (its vertices as many as the points). */
static double curve_length(int model, const double *p, size_t n)
{
    return model == FIT_SMOOTH ? p[6] : p[2] * (double)(n - 1);
}

/* Which end of [0, L] the foot f is at (0: the start, 1: the end, -1: neither), L the fit's
 * length (curve_length). The smooth fit clamps its feet to [0, L] exactly; the polygon's foot
 * at its last vertex is j h + t h, which rounds below (n - 1) h (measured: L - 2.8e-14 on a
 * 227-long polygon), so a foot within 1e-12 L of its end is at it. */
static int end_of(int model, double f, double L)
{
    return f <= 0.0 ? 0 : f >= (model == FIT_SMOOTH ? L : L * (1.0 - 1e-12)) ? 1 : -1;
}

/* The points but end point e (0 or n-1) whose feet fs are at that end of the fit's [0, L]. */
static size_t piled(int model, const double *fs, size_t n, double L, size_t e)
{
    size_t c = 0;
    for (size_t i = 0; i < n; i++)
        if (i != e && end_of(model, fs[i], L) == (e == 0 ? 0 : 1)) c++;
    return c;
}

/* The ends g (start x, y, then end x, y) and the end tangents' angles th of the fit p of n
 * points: the smooth curve's (el__smooth_ends), or the discrete polygon's first and last
 * vertices and the angles Theta_0, Theta_{n-2} of its first and last segments (seed 000
 * (4.3); its n vertices by el_discrete_eval into V, 2n, the caller's). EL_OK or their error. */
static int curve_ends(int model, const double *p, size_t n, double *V, double g[4], double th[2])
{
    if (model == FIT_SMOOTH) {
        const el_smooth_params c = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
        return el__smooth_ends(&c, g, th);
    }
    el_discrete_params dp;
    int st = el__fit_to_discrete(p, &dp, NULL);
    if (!st) st = el_discrete_eval(&dp, n, V);
    if (st) return st;
    const double *W = V + 2 * (n - 2);
    g[0] = V[0];
    g[1] = V[1];
    g[2] = W[2];
    g[3] = W[3];
    th[0] = atan2(V[3] - V[1], V[2] - V[0]);
    th[1] = atan2(W[3] - W[1], W[2] - W[0]);
    return EL_OK;
}

/* The points lo, hi farthest back and forward along the fit p (model, input units, feet fs):
 * each point's foot, or for a foot held at an end the end's arc length plus the point's
 * offset along the end's tangent. EL_OK or curve_ends' error (V: its scratch). */
static int extremes(int model, const double *p, const double *xy, const double *fs, size_t n, double *V,
                    size_t *lo, size_t *hi)
{
    double g[4], th[2];
    const int st = curve_ends(model, p, n, V, g, th);
    if (st) return st;
    const double L = curve_length(model, p, n);
    double a = HUGE_VAL, b = -HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        const int e = end_of(model, fs[i], L);
        const double at = e < 0 ? fs[i]
                        : (e ? L : 0.0) + cos(th[e]) * (xy[2 * i] - g[2 * e]) + sin(th[e]) * (xy[2 * i + 1] - g[2 * e + 1]);
        if (at < a) { a = at; *lo = i; }
        if (at > b) { b = at; *hi = i; }
    }
    return a < b ? EL_OK : EL_EDOM;
}

/* How far point i of xy lies beyond end e (0: start, 1: end; g, th: curve_ends') along
 * that end's tangent, outward (back from the start, on from the end). */
static double beyond(const double *xy, size_t i, int e, const double g[4], const double th[2])
{
    const double on = cos(th[e]) * (xy[2 * i] - g[2 * e]) + sin(th[e]) * (xy[2 * i + 1] - g[2 * e + 1]);
    return e ? on : -on;
}

/* Whether the feet fs of the fit p (noise: the points' noise level, input units, 0: not
 * known) pile up at an end: PILE_SHARE's count of points there (a scan dense at that end), or
 * PILE_LEAST of them and the farthest beyond the end by FIT_RETRACE_PAST noise levels, with
 * PILE_LEAST of them beyond half as far (a pen that retraced its end: the stroke's first or last point
 * lies inside it, the points before or after run back to the true end, and the curve tied to
 * that point stops short of them by the retrace; QA24 F10: pixel strokes of ~2100 points,
 * noise ~0.3 px, 32-37 such points at an end, below PILE_SHARE's 42, beyond it by up to 6.6
 * px: max_error 6.2-7.8 px, rms 0.67-0.79, the refit 0.29, 1.1-1.3 px, as the same points in
 * curve order). Half as far: a retrace is a run of points out to the farthest, where one point
 * alone far beyond is an outlier, which the refit tied to it reaches by a tail with no ink
 * (measured: a pen's dwell at an end and one lift-off spike 3-15 px past it, 15 of 45 strokes
 * drawn out to the spike, 3.6-13.5 px past the stroke's end, 5 of their OutlierWarnings lost;
 * test_fit_end_retrace.py). */
static int piles_up(int model, const double *p, const double *xy, const double *fs, size_t n, double noise,
                    double *V)
{
    const double L = curve_length(model, p, n);
    const size_t c[2] = {piled(model, fs, n, L, 0), piled(model, fs, n, L, n - 1)}, pile = fit_ends_pile(n);
    if (c[0] >= pile || c[1] >= pile) return 1;
    if ((c[0] < PILE_LEAST && c[1] < PILE_LEAST) || !(noise > 0.0)) return 0;
    /* a polygon's vertex tied to the first (last) point lies inside the stroke, the point's
     * own foot FIT_RETRACE_PAST levels in from that end, with points piled beyond the end: the
     * pen went back over it, and the tie's residual held the polygon between that point and
     * the ink's end, the points beyond it fewer and nearer than the test below asks (QA24's
     * strokes, 9 px retraces: < 2 px beyond, 2.0-2.3 px short; test_fit_end_retrace.py).
     * It is no mark of a retrace alone: on the discrete model it also fires on 9 of
     * bench_fit.py's 504 curves, noisy scans dense at one end (the tied point inside the dense
     * cloud), rms 0.04-1.6 % lower for ~3 x their CPU (revC). Not for the smooth curve: it
     * reaches such ends without it (0 of 190 test strokes changed), and on those noisy scans
     * it fired on 23 of 504, 5.5 x the CPU for an rms 0.04-18 % lower (discends' sweep) */
    const double in[2] = {fs[0], L - fs[n - 1]};
    for (int e = 0; e < 2 && model != FIT_SMOOTH; e++)
        if (c[e] >= PILE_LEAST && in[e] > FIT_RETRACE_PAST * noise) return 1;
    double g[4], th[2], far[2] = {0.0, 0.0};
    if (curve_ends(model, p, n, V, g, th)) return 0;
    for (size_t i = 0; i < n; i++) {
        const int e = end_of(model, fs[i], L);
        if (e >= 0) far[e] = fmax(far[e], beyond(xy, i, e, g, th));
    }
    size_t half[2] = {0, 0};
    for (size_t i = 0; i < n; i++) {
        const int e = end_of(model, fs[i], L);
        if (e >= 0 && beyond(xy, i, e, g, th) > 0.5 * far[e]) half[e]++;
    }
    for (int e = 0; e < 2; e++)
        if (c[e] >= PILE_LEAST && far[e] > FIT_RETRACE_PAST * noise && half[e] >= PILE_LEAST) return 1;
    return 0;
}

/* el__fit_cut: fit_ends.h */
int el__fit_cut(double *p, double a, double b)
{
    const el_smooth_params c = {p[0], p[1], p[2], p[3], p[4], p[5], p[6]};
    double xy[2];
    const int st = el_smooth_eval(&c, 1, &a, xy, NULL, NULL);
    if (st) return st;
    p[0] = xy[0];
    p[1] = xy[1];
    p[5] += sqrt(p[3]) * a;
    p[6] = b - a;
    return EL_OK;
}

/* The fit from the curve p (options ro) of the points with lo and hi moved first and last
 * (pxy: 2n), into *alt, its distances and feet into buf (2n, the caller's order); flags:
 * el__fit_run's. Its status. */
static int run_tied(int model, const double *xy, size_t n, const el_fit_options *ro, int flags, const double *p,
                    size_t lo, size_t hi, fit_out *alt, double *buf, double *pxy)
{
    memcpy(pxy, xy, sizeof(double) * 2 * n);
    if (hi == 0) hi = lo;       /* where swapping lo to 0 takes it */
    swap_points(pxy, NULL, NULL, 0, lo);
    swap_points(pxy, NULL, NULL, n - 1, hi);
    memset(alt, 0, sizeof *alt);
    alt->status = -1;
    const int st = el__fit_run(model, pxy, n, ro, flags | FIT_RUN_INNER, p, alt, buf, buf + n);
    swap_points(pxy, buf, buf + n, n - 1, hi);
    swap_points(pxy, buf, buf + n, 0, lo);
    return st;
}

/* The first round's other way: the fit from *res with no point tied (FIT_RUN_FREE_ENDS: each
 * point's distance to the curve over [0, L], the start and length free), its curve cut to its
 * feet's range, then tied to the points at its ends from there. Where the tail beyond the
 * outermost feet carries no residual, Levenberg-Marquardt may run the length far out
 * (measured: to 3e12) and stop uncertified, but it moves the ends where the data has them:
 * on bench_fit.py's suite (1000 and 5000 points, noise 1 %) its rms was up to 10 % below the
 * extremes' tie alone. Its status, EL_EDOM where it gave no curve to cut. */
static int run_free(const double *xy, size_t n, const el_fit_options *ro, const fit_out *res, fit_out *alt,
                    double *buf, double *pxy)
{
    const double *af = buf + n;
    int st = run_tied(FIT_SMOOTH, xy, n, ro, FIT_RUN_FREE_ENDS, res->params, 0, n - 1, alt, buf, pxy);
    if (st == EL_ENOMEM) return st;
    if (!fit_gave_curve(st)) return EL_EDOM;      /* no feet in af to scan */
    size_t lo = 0, hi = 0;
    for (size_t i = 1; i < n; i++) {
        if (af[i] < af[lo]) lo = i;
        if (af[i] > af[hi]) hi = i;
    }
    if (!(af[hi] > af[lo]) || el__fit_cut(alt->params, af[lo], af[hi])) return EL_EDOM;
    double p[FIT_NP];
    memcpy(p, alt->params, sizeof p);
    return run_tied(FIT_SMOOTH, xy, n, ro, 0, p, lo, hi, alt, buf, pxy);
}

/* Whether the fit r (feet fs, input units) strays from the points xy: a stretch of curve no
 * point accounts for, by el__fit_stray or el__fit_stray_curve (noisy points' long polygon),
 * above FIT_STRAY at the noise and scale the first fit's run saw (seen). */
static int strays(int model, const double *xy, size_t n, const fit_out *r, const double *fs, const fit_seen *seen)
{
    double stray = -1.0;
    if (!(seen->sc > 0.0)) return 0;      /* no run seen: not judged */
    const double of_curve = el__fit_stray_curve(xy, n, fs, curve_length(model, r->params, n), seen->noise,
                                                seen->sc, &stray);
    return stray > FIT_STRAY || of_curve > FIT_STRAY;
}

/* An alternative alt (status ast) replaces *res (status *st; d, fs its distances and feet)
 * where it is a fit as good as its status and of lower rms, and does not stray from the
 * points xy where *res does not (strays: run_free's curve, cut to its feet's range, can keep
 * a loop through empty space that a few points' feet end on: QA21's hand-drawn stroke, 400
 * points, noise 1, rms 1.059 -> 1.030 by a curve 251 long for a stroke of 115, its feet
 * leaving s 118..248 empty, up to 48 from every point; el__fit_stray 0.087 there,
 * el__fit_stray_curve 0.33); buf: alt's distances and feet. 0: not replaced, 1: replaced,
 * 2: replaced and lower by PILE_GAIN of its rms. */
static int keep_lower(int model, const double *xy, fit_out *res, int *st, fit_out *alt, int ast, const double *buf,
                      size_t n, double *d, double *fs)
{
    const int took = ast == EL_OK || (*st != EL_OK && fit_gave_curve(ast));
    if (!took || alt->status != ast || !(alt->rms < res->rms)) return 0;
    if (strays(model, xy, n, alt, buf + n, &res->seen) && !strays(model, xy, n, res, fs, &res->seen)) return 0;
    const int gain = alt->rms < (1.0 - PILE_GAIN) * res->rms;
    memcpy(alt->initial, res->initial, sizeof alt->initial);
    alt->seen = res->seen;
    alt->seen.follows = 0;
    el__fit_replace(res, alt, buf, n, d, fs);
    *st = ast;
    return 1 + gain;
}

int el__fit_free_ends(int model, const double *xy, size_t n, const el_fit_options *opt, int st, fit_out *res,
                      double *d, double *fs)
{
    el_fit_options ro;
    if (opt) ro = *opt; else el_fit_options_defaults(&ro);
    if (!(fs && n >= 2 && res->distance == EL_DISTANCE_ORTHOGONAL && !ro.constraints && fit_gave_curve(st) &&
          st == res->status && fit_options_unbounded(&ro)))
        return st;
    ro.use_initial = 1;
    ro.distance = EL_DISTANCE_ORTHOGONAL;
    /* the discrete polygon's vertices (curve_ends), then the refits' distances, feet, points */
    double *V = NULL, *buf = NULL;
    if (model != FIT_SMOOTH && !(V = malloc(sizeof(double) * 2 * n))) return EL_ENOMEM;
    size_t was[2] = {0, n - 1};          /* the points the last round tied */
    for (int round = 0; round < PILE_ROUNDS; round++) {
        size_t lo = 0, hi = n - 1;
        if ((!round && !piles_up(model, res->params, xy, fs, n, res->seen.sc > 0.0 ? res->seen.noise : 0.0, V)) ||
            extremes(model, res->params, xy, fs, n, V, &lo, &hi) || (round && lo == was[0] && hi == was[1]))
            break;
        if (!buf && !(buf = malloc(sizeof(double) * 4 * n))) { st = EL_ENOMEM; break; }
        fit_out alt;
        int kept = 0, ast;
        /* run_free is the smooth curve's (FIT_RUN_FREE_ENDS, el__fit_cut): a polygon cut to its
         * feet's range is not one of n vertices; the discrete fit is tied to its extremes */
        if (round == 0 && model == FIT_SMOOTH) {
            if ((ast = run_free(xy, n, &ro, res, &alt, buf, buf + 2 * n)) == EL_ENOMEM) { st = ast; break; }
            kept = keep_lower(model, xy, res, &st, &alt, ast, buf, n, d, fs);
        }
        if (!kept && !(lo == 0 && hi == n - 1)) {
            if ((ast = run_tied(model, xy, n, &ro, 0, res->params, lo, hi, &alt, buf, buf + 2 * n)) == EL_ENOMEM) {
                st = ast;
                break;
            }
            kept = keep_lower(model, xy, res, &st, &alt, ast, buf, n, d, fs);
            was[0] = lo;
            was[1] = hi;
        }
        if (kept < 2) break;        /* none, or lower by less than PILE_GAIN */
    }
    free(buf);
    free(V);
    return st;
}

int el__fit_trim_to_feet(const el_fit_options *opt, int st, fit_out *res, double *fs, size_t n)
{
    el_fit_options ro;
    if (opt) ro = *opt; else el_fit_options_defaults(&ro);
    if (!(fs && n >= 2 && res->distance == EL_DISTANCE_ORTHOGONAL && !ro.constraints && fit_gave_curve(st) &&
          fit_options_unbounded(&ro)))
        return EL_OK;
    double a = fs[0], b = fs[0];
    for (size_t i = 1; i < n; i++) {
        a = fmin(a, fs[i]);
        b = fmax(b, fs[i]);
    }
    const double L = res->params[6], tol = 1e-9 * L;
    if (!(b > a) || !(a > tol || L - b > tol)) return EL_OK;
    double p[FIT_NP];
    memcpy(p, res->params, sizeof p);
    if (el__fit_cut(p, fmax(a, 0.0), fmin(b, L))) return EL_OK;     /* kept as it is */
    memcpy(res->params, p, sizeof p);
    for (size_t i = 0; i < n; i++) fs[i] -= fmax(a, 0.0);
    return EL_OK;
}
