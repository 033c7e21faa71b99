/*
 * The exact minimum of the seed 003 blending functions on [0, 1] (basis_min and
 * with it the convex-hull flag), by branch and bound on the second derivative.
 *
 * h_i = sum_j G_ij g_j with g = (1-t, B_1, B_2, t), B_j'' = f_j'', so
 *   h_i'' = G_i1 f_1''(t) + G_i2 f_2''(t),
 * elliptic: f_2''(t) = -K^2 S(sn(Kt)), f_1''(t) = -K^2 S(sn((1-t)K)) with
 *   S(s) = (1 + m) s - 2 m s^3   (sn'' = -sn (dn^2 + m cn^2)),
 * sn(Kt) increasing on [0, 1] and S concave on s >= 0; MQ: f_j'' = c^2 / r_j^3,
 * monotone in t. So the range of h_i'' on any [a, b] is known exactly. On a
 * piece where h_i'' >= 0 the minimum is an end or the one zero of h_i' (GSL's
 * Brent root finder); where h_i'' <= 0 it is an end; elsewhere a lower bound
 * from the ends' values and slopes decides whether to bisect. This finds the
 * dips of width < 0.01 next to an end (m > 0.99: h_1(1) = h_1'(1) = 0 with
 * h_1''(1) < 0) that 64 samples miss.
 */
#include "internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

enum { SAMPLES = 64, MAX_DEPTH = 48, STACK = 2 * MAX_DEPTH + 8 };

/* A lower bound above best - PRUNE cannot lower the minimum by more than rounding. */
static const double PRUNE = 1e-17;

/* h_i, h_i' at t, with the span's f_1, f_2 and f_1'', f_2'' there (for the ranges). */
typedef struct knot { double t, h, dh, f[2], d2f[2]; } knot;

/* S(s) = (1 + m) s - 2 m s^3 = -sn'' where sn = s: sn'' = -sn (dn^2 + m cn^2) with
 * dn^2 = 1 - m s^2, cn^2 = 1 - s^2. */
double el__blend_sn_S(double m, double s)
{
    return (1.0 + m) * s - 2.0 * m * s * s * s;
}

/* S over s in [lo, hi] (subset of [0, 1]). */
static void s_range(double m, double lo, double hi, double *smin, double *smax)
{
    const double a = el__blend_sn_S(m, lo);
    const double b = el__blend_sn_S(m, hi);
    *smin = fmin(a, b);                      /* concave: least at an end */
    *smax = fmax(a, b);
    if (m > 0.0) {
        const double s = sqrt((1.0 + m) / (6.0 * m));   /* S'(s) = 0 */
        if (s > lo && s < hi) *smax = el__blend_sn_S(m, s);
    }
}

/* The ranges of f_1'' and f_2'' on [a.t, c.t]: r = (f1lo, f1hi, f2lo, f2hi). */
static void span_d2_range(const el_blend_basis *b, const knot *a, const knot *c, double r[4])
{
    for (int j = 0; j < 2; j++) {
        if (b->kind == EL_BLEND_MQ) {           /* monotone in t */
            r[2 * j] = fmin(a->d2f[j], c->d2f[j]);
            r[2 * j + 1] = fmax(a->d2f[j], c->d2f[j]);
        } else {                                /* -K^2 S(sn), sn monotone in t */
            const double K2 = b->K * b->K, m = b->k * b->k;
            double smin, smax;
            s_range(m, fmax(fmin(a->f[j], c->f[j]), 0.0), fmin(fmax(a->f[j], c->f[j]), 1.0),
                    &smin, &smax);
            r[2 * j] = -K2 * smax;
            r[2 * j + 1] = -K2 * smin;
        }
    }
}

/* [lo, hi] of g * [x, y]. */
static void scale_range(double g, double x, double y, double *lo, double *hi)
{
    *lo = fmin(g * x, g * y);
    *hi = fmax(g * x, g * y);
}

typedef struct root_ctx { const el_blend_basis *b; int i; int status; } root_ctx;

static double dh_fn(double t, void *p)
{
    root_ctx *c = p;
    double h[4], dh[4];
    int st = el__blend_basis_at(c->b, t, h, dh, NULL);
    if (st != EL_OK) { c->status = st; return 0.0; }
    return dh[c->i];
}

/* The knots of the four h_i at t. */
static int knots_at(const el_blend_basis *b, double t, knot k[4])
{
    double h[4], dh[4], f[4], d2f[4];
    int st = el__blend_basis_at(b, t, h, dh, NULL);
    if (st == EL_OK) st = el__blend_span_at(b, t, f, NULL, d2f);
    if (st != EL_OK) return st;
    for (int i = 0; i < 4; i++) {
        k[i].t = t;
        k[i].h = h[i];
        k[i].dh = dh[i];
        k[i].f[0] = f[1]; k[i].f[1] = f[2];
        k[i].d2f[0] = d2f[1]; k[i].d2f[1] = d2f[2];
    }
    return EL_OK;
}

/* The zero of h_i' in (a, c), where h_i is convex and h_i'(a) < 0 < h_i'(c): Brent. */
static int convex_min(const el_blend_basis *b, int i, const knot *a, const knot *c,
                      double *best, double *tbest)
{
    root_ctx ctx = {b, i, EL_OK};
    gsl_function F = {dh_fn, &ctx};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    double t = 0.5 * (a->t + c->t);
    if (gsl_root_fsolver_set(s, &F, a->t, c->t) == GSL_SUCCESS) {
        for (int it = 0; it < 100 && ctx.status == EL_OK; it++) {
            if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
            t = gsl_root_fsolver_root(s);
            if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s),
                                       1e-15, 0.0) == GSL_SUCCESS)
                break;
        }
    }
    gsl_root_fsolver_free(s);
    if (ctx.status != EL_OK) return ctx.status;
    double h[4];
    int st = el__blend_basis_at(b, t, h, NULL, NULL);
    if (st == EL_OK && h[i] < *best) { *best = h[i]; *tbest = t; }
    return st;
}

/* Lower bound of h on [a, c] when h'' in [lo, hi] (lo < 0 < hi). */
static double lower_bound(const knot *a, const knot *c, double lo, double hi)
{
    const double w = c->t - a->t;
    const double chord = fmin(a->h, c->h) - hi * w * w / 8.0;   /* h - chord = h''/2 (t-a)(t-c) */
    const double from_a = fmin(a->h, a->h + a->dh * w + 0.5 * lo * w * w);   /* Taylor, concave */
    const double from_c = fmin(c->h, c->h - c->dh * w + 0.5 * lo * w * w);
    return fmax(chord, fmax(from_a, from_c));
}

/* Branch and bound for h_i on [a, c]: lowers *best (at *tbest). */
static int piece_min(const el_blend_basis *b, int i, knot a0, knot c0, double *best, double *tbest)
{
    struct { knot a, c; int depth; } stack[STACK];
    int top = 0;
    stack[top].a = a0; stack[top].c = c0; stack[top].depth = 0; top++;
    while (top > 0) {
        top--;
        const knot a = stack[top].a, c = stack[top].c;
        const int depth = stack[top].depth;
        double r[4], lo1, hi1, lo2, hi2;
        int st;
        span_d2_range(b, &a, &c, r);
        scale_range(b->G[4 * i + 1], r[0], r[1], &lo1, &hi1);
        scale_range(b->G[4 * i + 2], r[2], r[3], &lo2, &hi2);
        const double pad = 1e-12 * (fabs(lo1) + fabs(hi1) + fabs(lo2) + fabs(hi2));
        const double lo = lo1 + lo2 - pad, hi = hi1 + hi2 + pad;
        if (lo >= 0.0) {                         /* convex: an end or the zero of h' */
            if (a.dh < 0.0 && c.dh > 0.0) {
                st = convex_min(b, i, &a, &c, best, tbest);
                if (st != EL_OK) return st;
            }
            continue;
        }
        if (hi <= 0.0) continue;                 /* concave: an end (already counted) */
        if (lower_bound(&a, &c, lo, hi) >= *best - PRUNE) continue;
        knot mk[4];
        if ((st = knots_at(b, 0.5 * (a.t + c.t), mk)) != EL_OK) return st;
        const knot mid = mk[i];
        if (mid.h < *best) { *best = mid.h; *tbest = mid.t; }
        if (depth >= MAX_DEPTH || top + 2 > STACK) continue;
        stack[top].a = mid; stack[top].c = c; stack[top].depth = depth + 1; top++;
        stack[top].a = a; stack[top].c = mid; stack[top].depth = depth + 1; top++;
    }
    return EL_OK;
}

int el__blend_basis_min(const el_blend_basis *b, double *vmin, double *tmin)
{
    knot k[4][SAMPLES + 1];
    double best = HUGE_VAL, tbest = 0.0;
    for (int j = 0; j <= SAMPLES; j++) {
        knot kj[4];
        int st = knots_at(b, (double)j / SAMPLES, kj);
        if (st != EL_OK) return st;
        for (int i = 0; i < 4; i++) {
            k[i][j] = kj[i];
            if (kj[i].h < best) { best = kj[i].h; tbest = kj[i].t; }
        }
    }
    for (int i = 0; i < 4; i++)
        for (int j = 0; j < SAMPLES; j++) {
            int st = piece_min(b, i, k[i][j], k[i][j + 1], &best, &tbest);
            if (st != EL_OK) return st;
        }
    *vmin = best;
    *tmin = tbest;
    return EL_OK;
}
