/*
 * Hermite interpolation for a given tension, seed 004 §4: the kappa_m bound of
 * Theorem 9, the pieces between the split points ((18), (40), (44), (45); the
 * polynomials and their roots in hermite_poly.c), sampling and root finding on each.
 */
#include "hermite_internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_math.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>
#include <stdlib.h>
#include <string.h>

#define MAXPTS 64
/* a branch's MAXPTS + 2 points fit el__hermite_piece_classes' gathers (hermite_lanes.c): C99's
 * compile-time check, an array of negative size otherwise */
typedef char el__maxpts_fit_the_gathers[MAXPTS + 2 <= HERMITE_GATHER_MAX / 2 ? 1 : -1];
/* el__carlson_fd's precision for the bracketing samples: ~1e-8 relative (ellint.c) */
#define COARSE_QS 0.1

/* ------------------------------------------------------------ Theorem 9: the kappa_m bound */

/* Period of the inflectional elastica with kappa_m, sigma (kappa_m^2 > 2 sigma). */
static double period_infl(double km, double sigma)
{
    const double Fn = km * km - sigma, k = sqrt(km * km / (2.0 * Fn));
    double K;
    /* the AGM with k'^2 = (|F| - sigma) / (2 |F|): cheaper than GSL's Kcomp (K alone) */
    if (el__ellint_complete(k, (Fn - sigma) / (2.0 * Fn), &K, NULL)) return NAN;
    return 4.0 * K / sqrt(0.5 * Fn);
}

/* lo, hi: the bracket's ends, whose periods Tlo, Thi are known (gsl_root_fsolver_set
 * evaluates both ends again: the same values, served here) */
typedef struct { double sigma, Lmin, lo, Tlo, hi, Thi; } tparam;
static double period_gap(double km, void *p)
{
    const tparam *t = p;
    return (km == t->lo ? t->Tlo : km == t->hi ? t->Thi : period_infl(km, t->sigma)) - t->Lmin;
}

/* Every solution has T >= L >= Lmin. sigma <= 0: k^2 <= 1/2, so
 * T <= 4 K(1/sqrt2) sqrt2 / sqrt(kappa_m^2 - sigma) and kappa_m^2 <= (C0/Lmin)^2 + sigma;
 * sigma > 0: the non-inflectional curves have kappa_m^2 <= 2 sigma, and T decreases
 * with kappa_m on the inflectional side (proof of Theorem 9): solve T(kappa_m) = Lmin
 * (Brent). This is (37) without the epsilon: exact for every sigma. */
int el__hermite_kappa_bound(double sigma, double Lmin, double *B)
{
    const double c = C0_PERIOD / Lmin;
    if (sigma <= 0.0) {
        const double b2 = c * c + sigma;
        *B = b2 > 0.0 ? sqrt(b2) * (1.0 + 1e-9) : -1.0;
        return EL_OK;
    }
    const double lo = sqrt(2.0 * sigma) * (1.0 + 1e-12);
    double hi = sqrt(2.0 * sigma) + c;
    double Thi = period_infl(hi, sigma);   /* each period evaluated once: the AGM */
    for (int i = 0; i < 200 && !(Thi < Lmin); i++) Thi = period_infl(hi *= 2.0, sigma);
    if (!(Thi < Lmin)) return EL_EINTERNAL;
    const double Tlo = period_infl(lo, sigma);
    if (!(Tlo > Lmin)) { *B = lo; return EL_OK; }
    tparam tp = {sigma, Lmin, lo, Tlo, hi, Thi};
    gsl_function fn = {period_gap, &tp};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    int rc = EL_OK;
    if (gsl_root_fsolver_set(s, &fn, lo, hi) != GSL_SUCCESS) rc = EL_EINTERNAL;
    for (int it = 0; it < 200 && !rc; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
        double a = gsl_root_fsolver_x_lower(s), b = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(a, b, 0.0, 1e-3) == GSL_SUCCESS) break;
    }
    /* the bracket's upper end has T < Lmin: a bound whatever the bracket's width */
    if (!rc) *B = gsl_root_fsolver_x_upper(s) * (1.0 + 1e-9);
    gsl_root_fsolver_free(s);
    return rc;
}

/* ------------------------------------------------------------ split points */

/* A split point; soft: kappa0 = 0 or kappa1 = 0, which bound the pieces where (44)
 * fails but leave the objective smooth on the inflectional side (seed 004 §4
 * intersects only the non-inflectional pieces with (44)); SPLIT_SEP: a root of (40)
 * (or (41) in case 3), where the curve is the separatrix (kappa_m^2 = 2 sigma, k = 1). */
enum { SPLIT_HARD, SPLIT_SOFT, SPLIT_SEP };
typedef struct { double x; int soft; } splitpt;
typedef struct { splitpt v[MAXPTS]; int n; } ptlist;

static void pt_add(ptlist *l, double x, int soft)
{
    if (isfinite(x) && l->n < MAXPTS) {
        l->v[l->n].x = x;
        l->v[l->n++].soft = soft;
    }
}

/* Sort by x: insertion sort, the lists being a dozen points long (qsort's
 * indirect comparisons and merge buffer cost more than the sort itself here). */
static void sort_splitpts(splitpt *v, int n)
{
    for (int i = 1; i < n; i++) {
        const splitpt t = v[i];
        int j = i;
        for (; j > 0 && v[j - 1].x > t.x; j--) v[j] = v[j - 1];
        v[j] = t;
    }
}

/* Domain of the unknown on branch b: [-X, X]. */
static double domain_half(const hprob *pr, int b)
{
    if (pr->B < 0.0) return -1.0;
    if (pr->hcase != 3) return pr->B;
    const double k0 = el__hermite_case3_kappa0(pr, b), s = pr->sigma;
    if (!isfinite(k0) || k0 * k0 > pr->B * pr->B) return -1.0;
    const double a = pr->B * pr->B - s, c = k0 * k0 - s, r = a * a - c * c; /* (8) */
    return r > 0.0 ? 0.5 * sqrt(r) : -1.0;
}

/* Split points of branch b: (18) ends, (40) roots, (44) kappa0 = 0 and kappa1 = 0,
 * (45) special values; case 3: (41), kappa0' = 0. */
static int split_points(const hprob *pr, int b, double X, const double *r40, const int *b40,
                        int n40, ptlist *l)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    double r[16];
    int nr, rc;
    l->n = 0;
    if (pr->hcase == 3) {
        const double k0 = el__hermite_case3_kappa0(pr, b), c = k0 * k0 - s, q = s * s - c * c;
        pt_add(l, 0.0, 0);
        if (q >= 0.0) { pt_add(l, 0.5 * sqrt(q), SPLIT_SEP); pt_add(l, -0.5 * sqrt(q), SPLIT_SEP); } /* (41) */
        return EL_OK;
    }
    if (pr->hcase == 1) {
        double a[3];
        el__hermite_disc_coeffs(pr, a);
        if ((rc = el__poly_real_roots(a, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 0);
        /* kappa1 = 0 in (17): 2 V1 C + A P2 = 0 */
        const double q[3] = {V1 * P1 * s + P2 * V2 * s - P2 * s, -2.0 * V1, -V1 * P1 - P2 * V2};
        if ((rc = el__poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 1);
    } else {
        const double q[3] = {-0.5 * P1 * s, 1.0, 0.5 * P1}; /* C = 0 */
        if ((rc = el__poly_real_roots(q, 2, r, &nr))) return rc;
        for (int i = 0; i < nr; i++) pt_add(l, r[i], 1);
    }
    pt_add(l, 0.0, 1);
    for (int i = 0; i < n40; i++)
        if (b40[i] == b) pt_add(l, r40[i], SPLIT_SEP);
    /* (45): seed 004 §4 evaluates its objective (35), x1(L) - P1, there and keeps the
     * value as a split point where it vanishes (an unwanted zero) or is singular. The
     * objective here is the error along F, regular where F is parallel to x1; it
     * vanished at none of the special values of the 10 000 bench problems (31 000
     * evaluated). So only the singular ones split: F = 0 (the circle kappa0^2 = sigma,
     * kappa0' = 0 on this branch) and those without a curve (el__hermite_x_class's
     * CLASS_NONE, also outside (18); the values in the domain classified together) */
    if ((rc = el__hermite_special_values(pr, r, &nr))) return rc;
    double xv[16];
    int cv[16], nv = 0;
    for (int i = 0; i < nr; i++)
        if (fabs(r[i]) < X) xv[nv++] = r[i];
    el__hermite_x_classes(pr, xv, nv, b, cv);
    for (int i = 0; i < nv; i++)
        if (cv[i] == CLASS_NONE) pt_add(l, xv[i], 0);
    return EL_OK;
}

/* ------------------------------------------------------------ root finding on the pieces */

/* The objective of one branch. */
typedef struct {
    const hprob *pr;
    int b;
    /* sep: the abscissa is y = ln(side (|F| - sigma)) of the separatrix chart over the
     * base chart (x, or case 3's (kappa0, kappa0') at the family's kappa0), w0 the
     * starting guess of its Newton (hermite_objective.c) */
    int sep, side;
    double w0, w_start;
    hsep_cache *sc;   /* the separatrix chart's last point (sep) */
    int lean;   /* the length mode's seeds (el__hermite_seed_tension): solve_sep_piece */
    double sep_lo, sep_hi;   /* the piece's ends at separatrix crossings (bracket_root), or NAN */
} fctx;

static void fctx_init(fctx *c, const hprob *pr, int b)
{
    memset(c, 0, sizeof *c);
    c->pr = pr;
    c->b = b;
    c->sep_lo = c->sep_hi = NAN;
}

/* The objective at abscissa u (x, or y in the separatrix chart) with Carlson's
 * precision qs; *x gets the unknown x of the state. */
static int piece_eval(fctx *c, double u, double qs, hstate *st, double *x)
{
    if (!c->sep) {
        *x = u;
        const int rc = el__hermite_curvdata(c->pr, u, c->b, st);
        return rc ? rc : el__hermite_shape_eval(c->pr, qs, st);
    }
    const hprob *pr = c->pr;
    int rc = EL_EDOM;
    /* Newton from the last state's w (a nearby y: fewer steps, the same state), and
     * from the piece's starting guess w_start where that fails: next to the resolution
     * of w (|F| - sigma ~ 1e-12 sigma) a start too close may stop short of the target */
    for (int k = 0; k < 2 && rc; k++) {
        double w = k ? c->w_start : c->w0;
        if (k && w == c->w0) break;
        rc = pr->hcase == 3
            ? el__hermite_sep_eval_from(pr, HCHART_C3, 1, c->b >= 2, c->side, u, el__hermite_case3_kappa0(pr, c->b), qs,
                                        &w, st, NULL, NULL, c->sc)
            : el__hermite_sep_eval_from(pr, HCHART_X, 0, c->b, c->side, u, pr->sigma, qs, &w, st, NULL, NULL, c->sc);
        *x = w;
        if (!rc) c->w0 = w;
    }
    return rc;
}

/* piece_eval with COARSE_QS, continued to double precision where |f| <= fine_below
 * (*fine says which): in the x chart the state prepared once
 * (el__hermite_shape_eval_to), in the separatrix chart evaluated again. */
static int piece_eval_to(fctx *c, double u, double fine_below, hstate *st, double *x, int *fine)
{
    if (!c->sep) {
        *x = u;
        const int rc = el__hermite_curvdata(c->pr, u, c->b, st);
        return rc ? rc : el__hermite_shape_eval_to(c->pr, COARSE_QS, fine_below, st, fine);
    }
    int rc = piece_eval(c, u, COARSE_QS, st, x);
    *fine = 0;
    if (rc || !(fabs(st->f) <= fine_below)) return rc;
    *fine = 1;
    return piece_eval(c, u, 1.0, st, x);
}

/* The objective for the samples that look for sign changes: elliptic integrals to
 * about 1e-8 instead of 1e-16 (COARSE_QS, one or two duplication steps fewer); its
 * sign and rough size are used, and the root finder and every accepted root the full precision. */
static double fobj_coarse(fctx *c, double x)
{
    if (!c->sep) {
        double f;
        el__hermite_x_objective(c->pr, x, c->b, COARSE_QS, &f);
        return f;
    }
    hstate st;
    double w;
    return piece_eval(c, x, COARSE_QS, &st, &w) ? GSL_NAN : st.f;
}

hroot el__hermite_mkroot(double x, int b, double sigma)
{
    hroot r;
    memset(&r, 0, sizeof r);
    r.x = x;
    r.b = b;
    r.sigma = sigma;
    return r;
}

int el__hermite_roots_push(hrootlist *l, const hroot *r)
{
    if (l->n == l->cap) {
        size_t cap = l->cap ? 2 * l->cap : EL__ROOTS_FIRST;
        hroot *v = realloc(l->v, cap * sizeof *v);
        if (!v) return EL_ENOMEM;
        l->v = v;
        l->cap = cap;
    }
    l->v[l->n++] = *r;
    return EL_OK;
}

/* The third point of bracket_root's steps: inverse quadratic interpolation through
 * (t0, f0), (t1, f1), (t2, f2) at f = 0 (Brent's step; NAN where two values coincide). */
static double inverse_quadratic(double t0, double f0, double t1, double f1, double t2, double f2)
{
    if (f0 == f1 || f0 == f2 || f1 == f2) return NAN;
    return t0 * f1 * f2 / ((f0 - f1) * (f0 - f2)) + t1 * f0 * f2 / ((f1 - f0) * (f1 - f2)) +
           t2 * f0 * f1 / ((f2 - f0) * (f2 - f1));
}

/* bracket_root bisects when the bracket has not halved over BISECT_EVERY steps, and gives up
 * after BRACKET_ITMAX: 33 such windows, as many guaranteed halvings as the former every
 * third step in 100. */
#define BISECT_EVERY 6
#define BRACKET_ITMAX (33 * BISECT_EVERY + 2)

/* The root on [a, b] with f(a) f(b) < 0 (the samples' coarse values), by inverse quadratic
 * interpolation (Brent's step) through the bracket's ends and the point last dropped from
 * it where that step falls inside the bracket, else the Anderson-Bjorck variant of regula
 * falsi (superlinear, the bracket kept), with a bisection where the bracket has not halved
 * over BISECT_EVERY steps: coarse while
 * the bracket is wider than 1e-6 of its abscissae and |f| > 1e-3 (a coarse value costs
 * 0.93 of a full one; one continued to full precision below 1e-6, 1.4: from |f| <= 1e-3 the
 * next step mostly lands there), then in full precision until |f| (the end position error
 * along F, |P| = 1) is at rounding level (1e-14), the bracket is 4e-16 |x| wide, or the
 * secant step from a full value is below the rounding of x: that value is the root to
 * double precision (steep f rounds above 1e-14; the step, falling on it, used to give way
 * to bisecting the wide bracket). The root: that last state where |f| <= 1e-8; else, in the
 * separatrix chart, the full-precision state of least |f| the iteration evaluated where
 * that one has: next to the saddle a near-straight root's bracket can close one ulp of y
 * wide between f = -1.3e-22 and 1.5e-8, the last, and the root was dropped (the state is
 * kept, not evaluated again: within the rounding of w it depends on the Newton's guess,
 * and at the abscissa of f = 4e-9 a second evaluation gave more than 1e-8). The last state,
 * not the least |f|, where both qualify: where f is steep its rounding (~1e-13) can put the
 * least |f| off the sign change. In the x chart a root accepted with |f| above 1e-14 (f
 * steep: the bracket or the step at the rounding of x) is compared with the adjacent double
 * towards the bracket's other end, and the one of smaller |f| kept: the sign change lies
 * between them to rounding, which of the two the steps reach is chance, and the residual
 * of such a steep root differs between them (one more evaluation for 7 % of the bench's
 * roots). A sign change across a jump of f (L wrapping at a period) is none: the bracket
 * closes with |f| large; in the x chart the jump is declared only where a step also failed
 * to halve |f|, since a steep root (f ~ 0.01 over 1e-8 of x at sigma |p1-p0|^2 = 629) can
 * leave |f| above 1e-4 on a bracket that narrow.
 * Next to a separatrix crossing x_c (a root of (40), (41)) that ends the piece, the steps
 * are taken in t = ln|x - x_c|: |F| - sigma, so k'^2 = (|F| - sigma) / (2 |F|),
 * vanishes linearly in x - x_c, and the length (K = ln(4/k') + O(k'^2 ln k')), hence f, is
 * A + B t + O(e^t t), nearly affine in t, while in x regula falsi crawls along the
 * logarithm (half of the bench problems' roots lie within 20 % of the piece's width from a
 * crossing); the bisections stay in x, which a root far from x_c needs. Evaluations per
 * root on the 10 000 bench problems: 6.49 with the secant steps alone and a bisection
 * check every third step, 5.80 with the interpolation and every sixth (8.6 before the
 * t chart). The separatrix chart keeps the secant steps, the check every third step and
 * the former jump test (its states depend on its Newton's guess within rounding). */
static int bracket_root(fctx *c, double a, double fa, double b, double fb, hrootlist *out)
{
    hroot r = el__hermite_mkroot(a, c->b, c->pr->sigma), best;
    double best_f = INFINITY;   /* separatrix chart: best, the full-precision state of least |f| */
    int ok = 0, full = 0, bfull = 0;   /* bfull: f(b) evaluated here in full precision */
    /* the chart of the steps: t = ln(dir (x - xc)), or t = x (dir = 0) */
    const double lo = a < b ? a : b, hi = a < b ? b : a;
    double xc = 0.0, dir = 0.0;
    if (lo > c->sep_lo && lo - c->sep_lo < 1e-6 * (hi - lo)) { xc = c->sep_lo; dir = 1.0; }
    else if (hi < c->sep_hi && c->sep_hi - hi < 1e-6 * (hi - lo)) { xc = c->sep_hi; dir = -1.0; }
    double ta = dir != 0.0 ? log(dir * (a - xc)) : a, tb = dir != 0.0 ? log(dir * (b - xc)) : b;
    /* fa0: f(a) itself (fa carries Anderson-Bjorck's scalings); (tp, fp): the point last
     * dropped from the bracket, none yet */
    double fa0 = fa, tp = NAN, fp = NAN;
    double halved = fabs(b - a);   /* the bracket `every` steps ago: bisect unless it halved */
    /* the separatrix chart keeps the secant steps with a check every third step in 100 */
    const int every = c->sep ? 3 : BISECT_EVERY, itmax = c->sep ? 100 : BRACKET_ITMAX;
    for (int it = 0; it < itmax; it++) {
        /* a, b finite: comparisons instead of libm's fmax, fmin (inner loop) */
        const double span = fabs(b - a), scale = fabs(a) > fabs(b) ? fabs(a) : fabs(b);
        if (!full && (span <= 1e-6 * (scale + 1e-3) || fabs(fb) <= 1e-3)) full = 1;
        /* the step in the chart, t its value there (NAN: x by bisection): the interpolation
         * where it falls inside the bracket, else the secant */
        double t = c->sep ? NAN : inverse_quadratic(ta, fa0, tb, fb, tp, fp);
        if (!(ta < tb ? t > ta && t < tb : t > tb && t < ta)) t = (ta * fb - tb * fa) / (fb - fa);
        double x = dir != 0.0 ? xc + dir * exp(t) : t;
        /* the secant step from a full-precision b below the rounding of x: b is the root */
        if (bfull && fabs(x - b) <= 2e-16 * scale) { ok = 1; break; }
        if (it % every == every - 1) {
            if (!(span < 0.5 * halved)) x = t = NAN;
            halved = span;
        }
        if (!(a < b ? x > a && x < b : x > b && x < a)) { x = 0.5 * (a + b); t = NAN; }
        const double step = fabs(x - b);
        double w;
        /* no curve: no root; near the root (|f| <= 1e-6) its value in full precision */
        double f;
        if (!full && !c->sep) {
            /* x chart, coarse: f alone (el__hermite_x_objective); where |f| <= 1e-6 the state
             * in full precision, as piece_eval_to's continuation gives it (the same bits) */
            if (el__hermite_x_objective(c->pr, x, c->b, COARSE_QS, &f)) break;
            w = x;
            if (fabs(f) <= 1e-6) {
                full = 1;
                if (piece_eval(c, x, 1.0, &r.st, &w)) break;
                f = r.st.f;
            }
        } else {
            if (full ? piece_eval(c, x, 1.0, &r.st, &w) : piece_eval_to(c, x, 1e-6, &r.st, &w, &full)) break;
            f = r.st.f;
        }
        r.x = w;
        if (c->sep && full && fabs(f) < best_f) {
            best = r;
            best_f = fabs(f);
        }
        if (full && (fabs(f) <= 1e-14 || span <= 4e-16 * scale || step <= 2e-16 * scale)) { ok = 1; break; }
        /* a jump: |f| stays large as the bracket closes, and (x chart) the step did not
         * halve it, as a step towards a steep root does */
        if (span < 1e-9 * (1.0 + fabs(x)) && !(fabs(f) < 1e-4) && (c->sep || !(fabs(f) < 0.5 * fabs(fb)))) break;
        if (f * fb < 0.0) {
            tp = ta;
            fp = fa0;
            a = b;
            ta = tb;
            fa = fa0 = fb;
        } else {
            const double m = 1.0 - f / fb;
            fa *= m > 0.0 ? m : 0.5;
            tp = tb;
            fp = fb;
        }
        b = x;
        tb = dir == 0.0 ? x : !isnan(t) ? t : log(dir * (x - xc));
        fb = f;
        bfull = full;
    }
    if (!ok) return EL_OK;
    /* x chart, a root accepted above 1e-14 (steep f): the adjacent double towards the
     * bracket's other end where its |f| is smaller */
    if (!c->sep && !(fabs(r.st.f) <= 1e-14)) {
        hroot rn = r;
        if (!piece_eval(c, nextafter(r.x, a), 1.0, &rn.st, &rn.x) && fabs(rn.st.f) < fabs(r.st.f)) r = rn;
    }
    if (!(fabs(r.st.f) <= 1e-8)) {
        if (!(best_f <= 1e-8)) return EL_OK;
        r = best;
    }
    return el__hermite_roots_push(out, &r);
}

/* The coarse objective, signed for a minimiser (only its sign at the minimum matters). */
static double negf(double x, void *p) { return -fobj_coarse(p, x); }
static double posf(double x, void *p) { return fobj_coarse(p, x); }

/* A lower bound of a convex g on [l, u] from its values at l < m < u: the secant through
 * (m, gm), (u, gu) lies below g left of m, the one through (l, gl), (m, gm) right of m;
 * their lowest values on [l, u] are at l and at u. */
static double convex_bracket_bound(double l, double gl, double m, double gm, double u, double gu)
{
    const double left = gm - (gu - gm) * (m - l) / (u - m);
    const double right = gm - (gl - gm) * (u - m) / (m - l);
    return fmin(left, right);
}

/* Two zeros closer than the sampling step (seed 004 §5 (a), (b): at most two per
 * piece, the objective convex between them): minimise sign * f on the bracket;
 * if the minimum changes sign, both zeros are bracketed. The same convexity ends the
 * search early: once the minimiser's bracket (lower, minimum, upper) bounds sign * f
 * above TOUCH_CLEAR on it (convex_bracket_bound), no zero (nor a double zero, |f| <=
 * 1e-11) lies there. (Brent's minimiser otherwise runs to its 40-iteration cap on most
 * of these brackets, its interval test being relative to 1e-9.) */
#define TOUCH_CLEAR 1e-8
static int touch_check(fctx *c, double a, double fa, double m, double fm, double b, double fb,
                       hrootlist *out)
{
    const double sg = fm > 0.0 ? 1.0 : -1.0;
    gsl_function fn = {fm > 0.0 ? posf : negf, c};
    gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!s) return EL_ENOMEM;
    int rc = EL_OK;
    /* the three samples are known: no re-evaluation */
    if (gsl_min_fminimizer_set_with_values(s, &fn, m, sg * fm, a, sg * fa, b, sg * fb) == GSL_SUCCESS) {
        for (int it = 0; it < 40; it++) {
            if (gsl_min_fminimizer_iterate(s) != GSL_SUCCESS) break;
            const double xm = gsl_min_fminimizer_x_minimum(s), v = gsl_min_fminimizer_f_minimum(s);
            if (v < 0.0) {
                gsl_min_fminimizer_free(s);
                const double fxm = fobj_coarse(c, xm);
                if ((rc = bracket_root(c, a, fa, xm, fxm, out))) return rc;
                return bracket_root(c, xm, fxm, b, fb, out);
            }
            const double lo = gsl_min_fminimizer_x_lower(s), up = gsl_min_fminimizer_x_upper(s);
            if (lo < xm && xm < up && convex_bracket_bound(lo, s->f_lower, xm, v, up, s->f_upper) > TOUCH_CLEAR) {
                gsl_min_fminimizer_free(s);
                return EL_OK;
            }
            if (gsl_min_test_interval(lo, up, 1e-11, 1e-9) == GSL_SUCCESS) break;
        }
        /* a double zero (tangency): accept it when f vanishes there */
        const double xm = gsl_min_fminimizer_x_minimum(s);
        hroot r = el__hermite_mkroot(xm, c->b, c->pr->sigma);
        if (!piece_eval(c, xm, 1.0, &r.st, &r.x) && fabs(r.st.f) <= 1e-11) rc = el__hermite_roots_push(out, &r);
    }
    gsl_min_fminimizer_free(s);
    return rc;
}

/* |f| at the vertex of the parabola through three samples around a local minimum
 * of |f| (same sign): small when two zeros may hide between the samples. */
static double parabola_min(const double *x, const double *f)
{
    const double sg = f[1] > 0.0 ? 1.0 : -1.0;
    const double d1 = (f[1] - f[0]) / (x[1] - x[0]), d2 = (f[2] - f[1]) / (x[2] - x[1]);
    const double a = (d2 - d1) / (x[2] - x[0]);          /* f = f1 + d (x - x1) + a (x - x1)^2 */
    const double d = d1 + a * (x[1] - x[0]);
    if (!(sg * a > 0.0)) return 0.0;                     /* not convex towards zero: check anyway */
    return sg * (f[1] - d * d / (4.0 * a));
}

/* The lowest value a convex function g = sign * f can take on [xs[j], xs[j+1]] given
 * the samples: the secant of a neighbouring interval where g > 0 at both ends,
 * extended, lies below a convex function (+inf when no neighbour qualifies). The
 * bound is the larger of the two sides': once one side's exceeds above (the caller's
 * best so far), that side's is returned (the caller only asks whether it is <= above). */
static double convex_lower_bound(const double *xs, const double *fs, int n, int j, double sign, double above)
{
    double lb = -INFINITY;
    int any = 0;
    for (int side = -1; side <= 1 && !(lb > above); side += 2) {
        const int p = side < 0 ? j - 1 : j + 1, q = p + 1;   /* the neighbour [xs[p], xs[q]] */
        if (p < 0 || q >= n || !(sign * fs[p] > 0.0) || !(sign * fs[q] > 0.0)) continue;
        const double slope = sign * (fs[q] - fs[p]) / (xs[q] - xs[p]);
        const double g0 = sign * fs[p] + slope * (xs[j] - xs[p]);
        const double g1 = sign * fs[p] + slope * (xs[j + 1] - xs[p]);
        const double g = g0 < g1 ? g0 : g1;     /* finite: no libm fmin/fmax calls here */
        if (g > lb) lb = g;
        any = 1;
    }
    return any ? lb : INFINITY;
}

/* The interval to sample next, or -1. Seed 004 §5 observes that the objective
 * is convex between two zeros close together; so two zeros can only hide in an
 * interval without a sign change where the convex lower bound from its
 * neighbours reaches zero, and the lowest such interval is bisected. An interval
 * with one failed evaluation (no curve there, or a singular point) is bisected
 * first while wider than nanw: the objective is steep next to such a region and
 * zeros crowd there; then it is bounded like the others from its finite side.
 * Intervals narrower than minw are left. */
static int interval_to_refine(const double *xs, const double *fs, int n, double minw, double nanw)
{
    int best = -1;
    double blb = 0.0;
    for (int j = 0; j + 1 < n; j++) {
        const double fa = fs[j], fb = fs[j + 1];
        double sign;
        if (isfinite(fa) && isfinite(fb)) {
            if (!(fa * fb > 0.0)) continue;                 /* a sign change: bracket_root */
            sign = fa > 0.0 ? 1.0 : -1.0;
        } else if (isfinite(fa) || isfinite(fb)) {
            const double f = isfinite(fa) ? fa : fb;
            if (f == 0.0) continue;
            sign = f > 0.0 ? 1.0 : -1.0;
            if (xs[j + 1] - xs[j] > nanw) return j;
        } else {
            continue;
        }
        if (!(xs[j + 1] - xs[j] > minw)) continue;
        double lb = convex_lower_bound(xs, fs, n, j, sign, blb);
        /* no same-sign neighbour says anything (next to a sign change, say):
         * one bisection gives the interval a neighbour of its own */
        if (lb == INFINITY && xs[j + 1] - xs[j] > 10.0 * nanw) lb = 0.0;
        if (lb <= blb) { blb = lb; best = j; }
    }
    return best;
}

/* Sample one piece (Chebyshev spacing, ends nudged inside: the split points are
 * where the objective is singular or not differentiable), refine where two zeros
 * may hide (interval_to_refine, at most REFINE_MAX more samples), bracket_root on sign
 * changes. */
/* A sample whose |f| is below TOUCH_RATIO times both neighbours' (same sign) gets the
 * touch check even when the parabola through the three does not reach zero: the
 * objective is often far from a parabola on a sample interval (steep near a split
 * point). It only adds checks, so it finds a superset; without these checks 9 of
 * the 25 264 solutions of the bench problems (300 samples) are missed, with them 1. */
#define TOUCH_RATIO 0.5
#define REFINE_MAX 12
/* Refinement and root extraction on the ns + 1 samples xs (ascending), fs of a piece
 * of width w (arrays with room for REFINE_MAX more). */
static int solve_samples(fctx *c, double *xs, double *fs, int ns, double w, hrootlist *out)
{
    int rc;
    const double a = xs[0], b = a + w;
    for (int r = 0; r < REFINE_MAX; r++) {
        const int j = interval_to_refine(xs, fs, ns + 1, 1e-6 * (b - a), 1e-3 * (b - a));
        if (j < 0) break;
        memmove(xs + j + 2, xs + j + 1, (size_t)(ns - j) * sizeof *xs);
        memmove(fs + j + 2, fs + j + 1, (size_t)(ns - j) * sizeof *fs);
        xs[j + 1] = 0.5 * (xs[j] + xs[j + 2]);
        fs[j + 1] = fobj_coarse(c, xs[j + 1]);
        ns++;
    }
    for (int j = 0; j < ns; j++) {
        if (!isfinite(fs[j]) || !isfinite(fs[j + 1])) continue;
        if (fs[j] == 0.0) {
            hroot r = el__hermite_mkroot(xs[j], c->b, c->pr->sigma);
            if (!piece_eval(c, xs[j], 1.0, &r.st, &r.x) && (rc = el__hermite_roots_push(out, &r))) return rc;
        } else if (fs[j] * fs[j + 1] < 0.0) {
            if ((rc = bracket_root(c, xs[j], fs[j], xs[j + 1], fs[j + 1], out))) return rc;
        } else if (j > 0 && isfinite(fs[j - 1]) && fs[j - 1] * fs[j] > 0.0 &&
                   fabs(fs[j]) < fabs(fs[j - 1]) && fabs(fs[j]) < fabs(fs[j + 1]) &&
                   (parabola_min(xs + j - 1, fs + j - 1) < 0.5 * fabs(fs[j]) ||
                    fabs(fs[j]) < TOUCH_RATIO * fmin(fabs(fs[j - 1]), fabs(fs[j + 1])))) {
            if ((rc = touch_check(c, xs[j - 1], fs[j - 1], xs[j], fs[j], xs[j + 1], fs[j + 1], out)))
                return rc;
        }
    }
    return EL_OK;
}

/* The piece p: its samples (el__hermite_sample_pieces), refinement and roots. */
static int solve_piece(fctx *c, const hpiece *p, double *cosn, hrootlist *out)
{
    double xs[1002 + REFINE_MAX], fs[1002 + REFINE_MAX];
    int off;
    el__hermite_sample_pieces(c->pr, c->b, p, 1, REFINE_MAX, COARSE_QS, cosn, xs, fs, &off);
    if (off < 0) return EL_OK;
    c->sep_lo = p->sep_lo;
    c->sep_hi = p->sep_hi;
    return solve_samples(c, xs, fs, p->ns, p->b - p->a, out);
}

/* A branch's pieces searched in the x chart alone (no separatrix pieces): every piece's
 * samples evaluated together (el__hermite_sample_pieces: fewer pairs of samples left half
 * empty, a piece having 4.4 samples on average on the bench's problems), then each piece
 * refined and its roots found in order: the same values and roots as solve_piece's, piece
 * by piece. */
static int solve_pieces_x(fctx *c, const hpiece *pc, int np, double *cosn, hrootlist *out)
{
    double xs[HERMITE_GATHER_MAX], fs[HERMITE_GATHER_MAX];
    int total = 0, rc, off[MAXPTS + 1];
    for (int i = 0; i < np; i++) total += pc[i].ns + 1 + REFINE_MAX;
    if (total > HERMITE_GATHER_MAX) {
        for (int i = 0; i < np; i++)
            if ((rc = solve_piece(c, pc + i, cosn, out))) return rc;
        return EL_OK;
    }
    el__hermite_sample_pieces(c->pr, c->b, pc, np, REFINE_MAX, COARSE_QS, cosn, xs, fs, off);
    for (int i = 0; i < np; i++) {
        if (off[i] < 0) continue;
        c->sep_lo = pc[i].sep_lo;
        c->sep_hi = pc[i].sep_hi;
        if ((rc = solve_samples(c, xs + off[i], fs + off[i], pc[i].ns, pc[i].b - pc[i].a, out))) return rc;
    }
    return EL_OK;
}

/* Near a separatrix crossing (a root of (40), (41)) for sigma above SEP_SIGMA the
 * solutions lie exponentially close to it (ln(1/(|F| - sigma)) grows like
 * sqrt(2 sigma) times the length passed near the saddle): there the piece is searched
 * in y = ln|(|F| - sigma)| (the separatrix chart, hermite_objective.c), where the
 * objective is smooth and, for small |F| - sigma, linear in y. Samples from y_c
 * (|F| - sigma = 1e-3 sigma, where the x chart takes over) at growing distances down to
 * |F| - sigma = 1e-300 sigma. */
static const double sep_steps[] = {0.0, 1.0, 2.5, 5.0, 10.0, 20.0, 40.0, 80.0, 160.0, 320.0, 690.0};
enum { NSEP = sizeof sep_steps / sizeof sep_steps[0] };

/* fyc: the coarse value at y_c, which separatrix_end has evaluated; el__hermite_sep_eval
 * is a function of y (not of its Newton's guess: test_hermite_tension.c), so a value is
 * computed once: the lean samples are among the full ones and are kept when those are
 * taken. The root finder starts from the state at y_c (w_start), as when y_c was the last
 * sample. Against the plain searches: test_hermite_tension.c (every root of a dense scan)
 * and test_hermite_length.c (the lean seeds against the tension mode's full search). */
static int solve_sep_piece(fctx *c, double yc, double fyc, hrootlist *out)
{
    double xs[NSEP + REFINE_MAX], fs[NSEP + REFINE_MAX];
    int have[NSEP] = {0};
    for (int j = 0; j < NSEP; j++) xs[j] = yc - sep_steps[NSEP - 1 - j];
    fs[NSEP - 1] = fyc;
    have[NSEP - 1] = 1;
    if (c->lean) {
        /* the length mode's seeds: the samples between y_c - 40 and y_c - 690 dropped where
         * the objective is affine there. With eps = |F| - sigma = e^y, the state is analytic
         * in eps and the length (hence f) is A + B ln eps + O(eps ln eps) (K(m) = ln(4/k')
         * + O(k'^2 ln k'), k'^2 = eps / (2|F|)): below y_c - 40 (eps < 4e-21 sigma) the
         * remainder is below rounding, and an affine f has at most the one root the two end
         * samples bracket. Not so where an end's amplitude tends to pi/2 with eps (kappa0
         * or kappa1 tending to 0 on the separatrix): the slopes over [y_c - 40, y_c - 20]
         * and [y_c - 690, y_c - 40] then differ, and the full samples are taken. */
        static const int lean[] = {0, 4, 5, 6, 7, 8, 9, 10};   /* y_c - 690, - 40, ..., - 1, y_c */
        enum { NLEAN = sizeof lean / sizeof lean[0] };
        double lx[NLEAN + REFINE_MAX], lf[NLEAN + REFINE_MAX];
        for (int i = 0; i < NLEAN; i++) {
            const int j = lean[i];
            if (!have[j]) fs[j] = fobj_coarse(c, xs[j]);
            have[j] = 1;
            lx[i] = xs[j];
            lf[i] = fs[j];
        }
        const double s1 = (lf[2] - lf[1]) / 20.0, s2 = (lf[1] - lf[0]) / 650.0;
        const double tol = 1e-6 * (fabs(s1) + fabs(s2) + (fabs(lf[0]) + fabs(lf[1]) + fabs(lf[2])) / 20.0);
        c->w0 = c->w_start;
        if (fabs(s1 - s2) <= tol) return solve_samples(c, lx, lf, NLEAN - 1, sep_steps[NSEP - 1], out);
    }
    for (int j = 0; j < NSEP; j++)
        if (!have[j]) fs[j] = fobj_coarse(c, xs[j]);
    c->w0 = c->w_start;
    return solve_samples(c, xs, fs, NSEP - 1, sep_steps[NSEP - 1], out);
}

/* The end x_end of a piece is a separatrix crossing and the piece runs towards
 * x_end + dir: the separatrix piece next to it, and into *xc the x where the x chart
 * takes over (x_end when there is none). */
static int separatrix_end(const hprob *pr, int b, double x_end, double dir, double width, int lean,
                          hrootlist *out, double *xc)
{
    *xc = x_end;
    if (!(pr->sigma > SEP_SIGMA)) return EL_OK;
    /* the side of the separatrix the piece lies on: the sign of |F| - sigma inside */
    hstate st;
    const double xin = x_end + dir * 1e-6 * width;
    if (el__hermite_curvdata(pr, xin, b, &st)) return EL_OK;
    const double F1 = -2.0 * st.k0p, F2 = st.k0 * st.k0 - pr->sigma, d = sqrt(F1 * F1 + F2 * F2) - pr->sigma;
    if (d == 0.0) return EL_OK;
    fctx c;
    hsep_cache sc;
    sc.valid = 0;
    fctx_init(&c, pr, b);
    c.sep = 1;
    c.sc = &sc;
    c.lean = lean;
    c.side = d > 0.0 ? 1 : -1;
    c.w0 = c.w_start = xin;
    /* y_c: |F| - sigma = 1e-3 sigma, or half its value mid-piece where the piece does
     * not reach that far from the separatrix */
    double dc = 1e-3 * pr->sigma;
    if (!el__hermite_curvdata(pr, x_end + 0.5 * dir * width, b, &st)) {
        const double G1 = -2.0 * st.k0p, G2 = st.k0 * st.k0 - pr->sigma, dm = sqrt(G1 * G1 + G2 * G2) - pr->sigma;
        if (dm * d > 0.0) dc = fmin(dc, 0.5 * fabs(dm));
    }
    const double yc = log(dc);
    double x;
    if (piece_eval(&c, yc, COARSE_QS, &st, &x) || !((x - x_end) * dir > 0.0) || !(fabs(x - x_end) < width))
        return EL_OK;                                  /* the x chart covers the piece */
    *xc = x;
    c.w0 = c.w_start = x;
    return solve_sep_piece(&c, yc, st.f, out);
}

static int nbranches(const hprob *pr) { return pr->hcase == 1 ? 2 : pr->hcase == 2 ? 1 : 4; }

/* All roots of the objectives for fixed sigma (seed 004 §4); lean: solve_sep_piece; the
 * separatrix pieces (separatrix_end) only above sep_sigma (SEP_SIGMA but for the length
 * mode's seed lines), the x chart covering the whole piece below. */
static int solve_tension(hprob *pr, int ns, int lean, double sep_sigma, hrootlist *out)
{
    int rc = el__hermite_kappa_bound(pr->sigma, pr->Lmin, &pr->B);
    if (rc || pr->B < 0.0) return rc;
    /* roots of (40) in [-B, B], each assigned to its objective; for sigma <= 0
     * kappa_m^2 = 2 sigma cannot happen (apart from kappa = 0, a split point anyway) */
    double r40[8];
    int b40[8], n40 = 0;
    if (pr->hcase != 3 && pr->sigma > 0.0) {
        double r[8];
        int nr;
        el__hermite_poly40_roots(pr, r, &nr);
        for (int i = 0; i < nr; i++)
            if (fabs(r[i]) < pr->B) {
                /* the separatrix pieces (above SEP_SIGMA) need the crossing to rounding */
                b40[n40] = el__hermite_root_branch(pr, r[i]);
                r40[n40] = pr->sigma > SEP_SIGMA ? el__hermite_crossing_refine(pr, b40[n40], r[i]) : r[i];
                n40++;
            }
    }
    double cosn[HERMITE_NCOS];
    for (int i = 0; i < HERMITE_NCOS; i++) cosn[i] = NAN;
    for (int b = 0; b < nbranches(pr); b++) {
        const double X = domain_half(pr, b);
        if (!(X > 0.0)) continue;
        ptlist l;
        if ((rc = split_points(pr, b, X, r40, b40, n40, &l))) return rc;
        splitpt pts[MAXPTS + 2];   /* pts[0..n) used: no zero-initialisation of its 1 KB */
        int n = 1, cls[MAXPTS + 1];
        pts[0] = (splitpt){-X, 0};
        for (int i = 0; i < l.n; i++)
            if (l.v[i].x > -X && l.v[i].x < X) pts[n++] = l.v[i];
        /* X, the unique largest, appended last: the stable sort's result as with X second,
         * without moving it past every other point */
        pts[n++] = (splitpt){X, 0};
        sort_splitpts(pts, n);
        /* the kind of curve on each piece (from its midpoint, CLASS_NONE confirmed at the
         * quarter points), all pieces' points classified together */
        double px[MAXPTS + 2];
        for (int i = 0; i < n; i++) px[i] = pts[i].x;
        el__hermite_piece_classes(pr, b, px, n, cls);
        fctx c;
        fctx_init(&c, pr, b);
        /* without separatrix pieces the pieces' samples are evaluated together */
        const int sep = pr->sigma > sep_sigma;
        hpiece pc[MAXPTS + 1];
        int np = 0;
        for (int i = 0; i + 1 < n; i++) {
            if (cls[i] == CLASS_NONE) continue;            /* no curve anywhere on the piece */
            /* inflectional neighbours across a soft split point form one piece */
            const double a = pts[i].x;
            const int a_sep = pts[i].soft == SPLIT_SEP;
            while (cls[i] == CLASS_INFL && i + 2 < n && pts[i + 1].soft == SPLIT_SOFT && cls[i + 1] == CLASS_INFL) i++;
            const double bb = pts[i + 1].x;
            /* separatrix crossings at the ends: the pieces next to them in y (above) */
            double xa = a, xb = bb;
            if (a_sep && sep && (rc = separatrix_end(pr, b, a, 1.0, bb - a, lean, out, &xa))) return rc;
            if (pts[i + 1].soft == SPLIT_SEP && sep && (rc = separatrix_end(pr, b, bb, -1.0, bb - xa, lean, out, &xb))) return rc;
            /* samples in proportion to the piece's share of the domain, at least 2 */
            const int m = 1 + (int)ceil(ns * (bb - a) / (2.0 * X));
            const hpiece p = {xa, xb, a_sep && xa == a ? a : NAN, pts[i + 1].soft == SPLIT_SEP && xb == bb ? bb : NAN,
                              m > 1000 ? 1000 : m, cls[i]};
            if (!sep) pc[np++] = p;
            else if ((rc = solve_piece(&c, &p, cosn, out))) return rc;
        }
        if (np && (rc = solve_pieces_x(&c, pc, np, cosn, out))) return rc;
    }
    return EL_OK;
}


int el__hermite_solve_tension(hprob *pr, int ns, hrootlist *out) { return solve_tension(pr, ns, 0, SEP_SIGMA, out); }

int el__hermite_seed_tension(hprob *pr, int ns, double sep_sigma, hrootlist *out)
{
    return solve_tension(pr, ns, 1, fmax(sep_sigma, SEP_SIGMA), out);
}
