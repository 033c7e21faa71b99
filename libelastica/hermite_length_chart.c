/*
 * The length mode's points of C (hermite_length.c) in the charts of the curvature data
 * (hermite_objective.c): their evaluation with the gradients in the tracer's coordinates
 * (asinh of the chart's), the separatrix chart that replaces one coordinate by
 * ln(|F| - sigma) near k = 1, and the passage from one chart to another where one is
 * better conditioned (rechart) or where one folds (the other charts of a point).
 */
#include "hermite_length_internal.h"
#include <string.h>

/* sinh by one exp where |x| >= 1/2 (there e^|x| - e^-|x| loses at most a factor 1.6 to
 * cancellation: a few ulps), by its Taylor series to x^15 / 15! below (the next term is
 * below 1e-19 |x|), libm's beyond 700: glibc's sinh goes through expm1 for every |x| < 22
 * and cost 5 % of the length mode (two calls per evaluation of a point of C). */
double el__hlen_sinh(double x)
{
    const double a = fabs(x);
    if (a < 0.5) {
        const double z = x * x;
        return x + x * z * (1.0 / 6 + z * (1.0 / 120 + z * (1.0 / 5040 + z * (1.0 / 362880 +
               z * (1.0 / 39916800 + z * (1.0 / 6227020800.0 + z * (1.0 / 1307674368000.0)))))));
    }
    if (!(a <= 700.0)) return sinh(x);
    const double e = exp(a);
    return copysign(0.5 * (e - 1.0 / e), x);
}

/* hypot by sqrt(a^2 + b^2) where the squares' sum lies in [1e-290, 1e290] (no overflow, no
 * subnormals), libm's outside: glibc's hypot cost 2 % of the length mode's instructions
 * (tangents, step lengths, |F|). The squares and their sum rounded (relative error of the
 * sum <= 2u + u^2, u = 2^-53), the square root halves it and rounds once more: within
 * 2u + O(u^2) of the exact value (test_hermite_length.c). */
double el__hlen_norm(double a, double b)
{
    const double s = a * a + b * b;
    return s >= 1e-290 && s <= 1e290 ? sqrt(s) : hypot(a, b);
}

/* Evaluate the chart of `like` (chart, base, side, b; w as the separatrix chart's
 * starting guess) at (U, V) into *p (the state directly into p->st: *p is undefined
 * where it fails, and no caller reads it then). */
int el__hlen_eval(tracer *T, const cpt *like, double U, double V, cpt *p)
{
    hgrad g;
    double sigma, w = like->w, c[2];
    if (++T->evals > T->max_evals) return EL_EMAXITER;
    int rc;
    /* cosh from sinh (d asinh(u)/du = 1 / sqrt(1 + u^2)) */
    if (like->chart == CHART_SEP) {
        const int fi = like->fi;
        /* the replaced coordinate extrapolated from like's as the starting guess */
        if (isfinite(like->wg[0] + like->wg[1]))
            w += like->wg[0] * (U - like->U) + like->wg[1] * (V - like->V);
        const double y = SEP_SCALE * (fi ? V : U), other = el__hlen_sinh(fi ? U : V);
        rc = el__hermite_sep_eval(T->pr, like->base, fi, like->b, like->side, y, other, 1.0, &w, &p->st, &g,
                                  &sigma);
        c[fi] = SEP_SCALE;
        c[1 - fi] = sqrt(1.0 + other * other);
    } else {
        const double u = el__hlen_sinh(U), v = el__hlen_sinh(V);
        rc = el__hermite_chart_eval(T->pr, like->chart, u, v, like->b, &p->st, &g, &sigma);
        c[0] = sqrt(1.0 + u * u);
        c[1] = sqrt(1.0 + v * v);
    }
    if (rc) return rc;
    const double it = 1.0 / sqrt(1.0 + sigma * sigma);
    p->chart = like->chart;
    p->base = like->base;
    p->fi = like->fi;
    p->side = like->side;
    p->sg[0] = g.sep[0] * c[0];
    p->sg[1] = g.sep[1] * c[1];
    p->wg[0] = like->chart == CHART_SEP ? g.w[0] * c[0] : NAN;
    p->wg[1] = like->chart == CHART_SEP ? g.w[1] * c[1] : NAN;
    p->b = like->b;
    p->U = U;
    p->V = V;
    p->w = w;
    p->sigma = sigma;
    /* the charts X and K1 have t = asinh(sigma) as their coordinate V */
    p->t = (like->chart == HCHART_X || like->chart == HCHART_K1) ? V
           : like->chart == CHART_SEP && like->fi == 0 && like->base != HCHART_C3 ? V : asinh(sigma);
    for (int i = 0; i < 2; i++) {
        p->fg[i] = g.f[i] * c[i];
        p->Lg[i] = g.L[i] * c[i];
        p->tg[i] = g.s[i] * c[i] * it;
    }
    return isfinite(p->fg[0] + p->fg[1] + p->Lg[0] + p->Lg[1]) ? EL_OK : EL_EDOM;
}

/* A chart without the separatrix replacement */
static cpt chart_spec(int chart, int b)
{
    cpt c;
    memset(&c, 0, sizeof c);
    c.chart = c.base = chart;
    c.b = b;
    c.wg[0] = c.wg[1] = NAN;
    return c;
}

/* |F| - sigma of a point, and |F| + sigma (its scale) */
static double sep_dist(const cpt *p, double *scale)
{
    const double F1 = -2.0 * p->st.k0p, F2 = p->st.k0 * p->st.k0 - p->sigma, Fn = el__hlen_norm(F1, F2);
    *scale = Fn + fabs(p->sigma);
    return p->st.has_sep ? p->st.sep : Fn - p->sigma;
}

/* Coordinate number i of a state in the chart `base` (raw, not asinh) */
static double base_coord(const hprob *pr, int base, int i, const hstate *st, double sigma)
{
    if (base == HCHART_C3) return i ? st->k0p : st->k0;
    if (i) return sigma;
    return base == HCHART_K1 ? st->k1 : pr->hcase == 3 ? st->k0p : st->k0;
}


/* The point re-expressed in the better conditioned chart (same state; EL_OK with *p
 * unchanged when it is already):
 * - near the separatrix (|F| - sigma below 1e-3 of |F| + sigma) where the objective
 *   depends on ln(|F| - sigma) (the curve passes near the saddle; |df/dy| >= 1e-6),
 *   the separatrix chart, there C follows the separatrix exponentially closely; back
 *   to the base chart above 1e-2, or where that dependence fades (C crosses k = 1);
 * - in case 1, K1 near the fold of X where the branches of (17) meet
 *   (|d asinh kappa1 / d asinh x| along a sigma line above 4; back to X below 1/4):
 *   (18) = a2 x^2 + a1 x + a0 = W^2, W = P2 kappa1 + V1, so dkappa1/dx = (2 a2 x + a1) / (2 P2 W). */
/* *p re-expressed in the chart of spec at (U, V) if that works (else unchanged) */
static int switch_to(tracer *T, const cpt *spec, double U, double V, cpt *p)
{
    cpt q;
    const int rc = el__hlen_eval(T, spec, U, V, &q);
    if (rc == EL_EMAXITER) return rc;
    if (!rc) *p = q;
    return EL_OK;
}

/* The point p of a separatrix chart in the separatrix chart replacing the other base
 * coordinate, into *q (EL_OK). */
static int sep_other(tracer *T, const cpt *p, cpt *q)
{
    double scale, c[2];
    const double d = sep_dist(p, &scale);
    for (int i = 0; i < 2; i++) c[i] = asinh(base_coord(T->pr, p->base, i, &p->st, p->sigma));
    const int nfi = 1 - p->fi;
    cpt sep = *p;
    sep.fi = nfi;
    sep.w = base_coord(T->pr, p->base, nfi, &p->st, p->sigma);
    sep.wg[0] = sep.wg[1] = NAN;
    const double Y = log(fabs(d)) / SEP_SCALE;
    return el__hlen_eval(T, &sep, nfi ? c[0] : Y, nfi ? Y : c[1], q);
}

int el__hlen_rechart(tracer *T, cpt *p)
{
    const hprob *pr = T->pr;
    double scale;
    const double d = sep_dist(p, &scale);
    if (p->chart == CHART_SEP) {
        const int fi = p->fi;
        const double fy = p->fg[fi] / SEP_SCALE;
        cpt base = chart_spec(p->base, p->b);
        double c[2];
        for (int i = 0; i < 2; i++) c[i] = asinh(base_coord(pr, p->base, i, &p->st, p->sigma));
        if (!(fabs(d) <= 1e-2 * scale && fabs(fy) >= 1e-7)) return switch_to(T, &base, c[0], c[1], p);
        /* the replaced coordinate: the one |F| - sigma varies more along (the separatrix
         * curve is a graph over the other there) in the base chart. |F| - sigma is a
         * function of y alone here, so with A = asinh(w) = A(y, other') the ratio of its
         * base gradient's components is |dA/dother'| = |dw/dother'| / sqrt(1 + w^2)
         * (chain rule; no evaluation in the base chart needed): the other one past 2 */
        const double ratio = fabs(p->wg[1 - fi]) / sqrt(1.0 + p->w * p->w);
        if (!(ratio > 2.0)) return EL_OK;
        cpt q;
        const int rc = sep_other(T, p, &q);
        if (!rc) *p = q;
        return rc == EL_EMAXITER ? rc : EL_OK;
    }
    if (p->sigma > 0.0 && fabs(d) < 1e-3 * scale && d != 0.0) {
        cpt sep = *p, q;
        const int fi = fabs(p->sg[1]) > fabs(p->sg[0]);
        sep.chart = CHART_SEP;
        sep.base = p->chart;
        sep.fi = fi;
        sep.side = d > 0.0 ? 1 : -1;
        sep.w = base_coord(pr, p->chart, fi, &p->st, p->sigma);
        sep.wg[0] = sep.wg[1] = NAN;
        const double Y = log(fabs(d)) / SEP_SCALE;
        int rc = el__hlen_eval(T, &sep, fi ? p->U : Y, fi ? Y : p->V, &q);
        if (rc == EL_EMAXITER) return rc;
        if (!rc && fabs(q.fg[fi] / SEP_SCALE) >= 1e-6) { *p = q; return EL_OK; }
    }
    if (pr->hcase != 1) return EL_OK;
    const double x = p->st.k0, k1 = p->st.k1, W = pr->P2 * k1 + pr->V1;
    const double dd = 2.0 * (pr->P2 * pr->V1 * pr->P1 + pr->P2 * pr->P2 * pr->V2) * x + 2.0 * pr->P2 * pr->V1;
    const double r = fabs(dd / (2.0 * pr->P2 * W)) * sqrt((1.0 + x * x) / (1.0 + k1 * k1));
    if (p->chart == HCHART_X && r > 4.0) {
        const cpt c = chart_spec(HCHART_K1, dd >= 0.0 ? 0 : 1);
        return switch_to(T, &c, asinh(k1), p->V, p);
    }
    if (p->chart == HCHART_K1 && r < 0.25) {
        const cpt c = chart_spec(HCHART_X, W >= 0.0 ? 0 : 1);
        return switch_to(T, &c, asinh(x), p->V, p);
    }
    return EL_OK;
}

/* Same point of the curvature-data surface (same tension, kappa0, kappa0'). */
int el__hlen_same_hstate(double s1, const hstate *a, double s2, const hstate *b)
{
    if (a->has_sep && b->has_sep && !(fabs(a->sep - b->sep) <= 1e-6 * fabs(a->sep))) return 0;
    return fabs(s1 - s2) <= 1e-9 * (1.0 + fabs(s1)) &&
           fabs(a->k0 - b->k0) <= 1e-8 * (1.0 + fabs(a->k0)) &&
           fabs(a->k0p - b->k0p) <= 1e-8 * (1.0 + fabs(a->k0p));
}

int el__hlen_same_state(const cpt *a, const cpt *b) { return el__hlen_same_hstate(a->sigma, &a->st, b->sigma, &b->st); }

/* The charts of point p other than its own, k = 0 .. NALT - 1: in case 1 the separatrix
 * charts (either coordinate replaced; near the separatrix) and the plain chart over the
 * other base of X and K1, then the separatrix chart replacing the other coordinate and
 * the plain base chart of p's own base. EL_OK with the point there in *alt when the
 * chart exists and gives p's state back, else EL_EDOM (or EL_EMAXITER). */
int el__hlen_alt_chart(tracer *T, const cpt *p, int k, cpt *alt)
{
    const hprob *pr = T->pr;
    double scale;
    const double d = sep_dist(p, &scale);
    const int near_sep = p->sigma > 0.0 && d != 0.0 && fabs(d) <= 1e-2 * scale;
    int base = p->base, b = p->b, rc;
    if (k < 3) {
        if (pr->hcase != 1) return EL_EDOM;
        if (base == HCHART_X) {
            base = HCHART_K1;
            b = 2.0 * (pr->P2 * pr->V1 * pr->P1 + pr->P2 * pr->P2 * pr->V2) * p->st.k0 + 2.0 * pr->P2 * pr->V1 >= 0.0 ? 0 : 1;
        } else {
            base = HCHART_X;
            b = pr->P2 * p->st.k1 + pr->V1 >= 0.0 ? 0 : 1;
        }
    } else if (p->chart != CHART_SEP) {
        return EL_EDOM;
    }
    cpt c = chart_spec(base, b);
    double u[2];
    for (int i = 0; i < 2; i++) u[i] = asinh(base_coord(pr, base, i, &p->st, p->sigma));
    if (k == 0 || k == 1 || k == 3) {
        const int fi = k == 3 ? 1 - p->fi : k;
        if (!near_sep) return EL_EDOM;
        c.chart = CHART_SEP;
        c.fi = fi;
        c.side = d > 0.0 ? 1 : -1;
        c.w = base_coord(pr, base, fi, &p->st, p->sigma);
        u[fi] = log(fabs(d)) / SEP_SCALE;
    }
    if ((rc = el__hlen_eval(T, &c, u[0], u[1], alt))) return rc == EL_EMAXITER ? rc : EL_EDOM;
    return el__hlen_same_state(alt, p) ? EL_OK : EL_EDOM;
}

/* The point's coordinates in the chart of q (for orienting q's tangent). */
void el__hlen_coords_in(const hprob *pr, const cpt *p, const cpt *q, double *U, double *V)
{
    *U = p->U;
    *V = p->V;
    if (p->chart == q->chart && p->base == q->base && p->fi == q->fi) return;
    double scale, c[2];
    for (int i = 0; i < 2; i++) c[i] = asinh(base_coord(pr, q->base, i, &p->st, p->sigma));
    if (q->chart == CHART_SEP) c[q->fi] = log(fabs(sep_dist(p, &scale)) + 1e-300) / SEP_SCALE;
    *U = c[0];
    *V = c[1];
}


/* Same chart (and branch, side) */
int el__hlen_same_chart(const cpt *a, const cpt *b)
{
    return a->chart == b->chart && a->base == b->base && a->fi == b->fi && a->b == b->b && a->side == b->side;
}


/* The point of C of a tension root r (tension sigma) in the chart of its kind, into *s:
 * near the separatrix the root carries |F| - sigma exactly (hstate.sep) and the base
 * coordinates alone do not fix the state (a rounded kappa0 lands on another one), so
 * the separatrix chart, replacing either coordinate, is tried first and kept where it
 * gives the root's state back. */
int el__hlen_seed_point(tracer *T, const hroot *r, double sigma, cpt *s)
{
    const hprob *pr = T->pr;
    const int base = pr->hcase == 3 ? HCHART_C3 : HCHART_X, b = pr->hcase == 3 ? r->b >= 2 : r->b;
    const cpt c = chart_spec(base, b);
    double u[2];
    for (int i = 0; i < 2; i++) u[i] = asinh(base_coord(pr, base, i, &r->st, sigma));
    if (r->st.has_sep && r->st.sep != 0.0) {
        const double Y = log(fabs(r->st.sep)) / SEP_SCALE;
        for (int fi = 0; fi < 2; fi++) {
            cpt sep = c;
            sep.chart = CHART_SEP;
            sep.fi = fi;
            sep.side = r->st.sep > 0.0 ? 1 : -1;
            sep.w = base_coord(pr, base, fi, &r->st, sigma);
            const int rc = el__hlen_eval(T, &sep, fi ? u[0] : Y, fi ? Y : u[1], s);
            if (rc == EL_EMAXITER) return rc;
            if (!rc && el__hlen_same_hstate(sigma, &r->st, s->sigma, &s->st)) return EL_OK;
        }
    }
    return el__hlen_eval(T, &c, u[0], u[1], s);
}
