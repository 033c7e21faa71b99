/*
 * The polynomials of seed 004 §4 and their real roots in an interval: (18) (the
 * domain of case 1), (40) (the separatrix crossings, Theorem 11; refined on the
 * curvature data and assigned to their branch) and (45) (the special values), for
 * hermite_tension.c; el_hermite_analyse reports them with the kappa_m bound.
 */
#include "hermite_internal.h"
#include <gsl/gsl_poly.h>
#include <float.h>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#include <stdlib.h>
#include <string.h>

/* Real roots of sum c[i] x^i (degree <= 2) by gsl_poly_solve_quadratic. */
int el__poly_real_roots(const double *c_in, int deg, double *roots, int *nroots)
{
    double c[3];
    double cmax = 0.0;
    /* a comparison, not libm's fmax (a call: NaN rules): cmax stays a number either way */
    for (int i = 0; i <= deg; i++) { c[i] = c_in[i]; cmax = fabs(c[i]) > cmax ? fabs(c[i]) : cmax; }
    *nroots = 0;
    while (deg > 0 && fabs(c[deg]) <= 1e-14 * cmax) deg--;
    if (deg <= 0) return EL_OK;
    double r0, r1;
    const int n = deg == 2 ? gsl_poly_solve_quadratic(c[2], c[1], c[0], &r0, &r1) : (r0 = -c[0] / c[1], 1);
    if (n > 0) roots[(*nroots)++] = r0;
    if (n > 1) roots[(*nroots)++] = r1;
    return EL_OK;
}

/* p(x) and p'(x) by Horner's scheme */
static double horner(const double *c, int deg, double x, double *dp)
{
    double v = c[deg], d = 0.0;
    for (int i = deg - 1; i >= 0; i--) { d = d * x + v; v = v * x + c[i]; }
    *dp = d;
    return v;
}

/* The degree of sum c[i] x^i on [lo, hi] by the terms' sizes there, |c_i| R^i: a leading
 * coefficient negligible on it (a degenerate problem) lowers the degree. */
static int effective_degree(const double *c, int deg, double lo, double hi)
{
    const double R = fmax(1.0, fmax(fabs(lo), fabs(hi)));
    double tmax = 0.0, Ri = 1.0, Rdeg[9];
    for (int i = 0; i <= deg; i++, Ri *= R) {
        Rdeg[i] = Ri;
        tmax = fabs(c[i]) * Ri > tmax ? fabs(c[i]) * Ri : tmax;   /* fmax without the call */
    }
    while (deg > 0 && fabs(c[deg]) * Rdeg[deg] <= 1e-14 * tmax) deg--;
    return deg;
}

/* The root of sum c[i] x^i in [a, b], where its value fa at a and p(b) differ in sign, to
 * the relative precision tol: Newton's method from x inside the bracket, kept there
 * (bisection when a step leaves it or the previous step did not halve it; rtsafe of
 * Numerical Recipes). Inlined with deg constant for (40)'s usual degree 8
 * (bracketed_root below): horner unrolled, the same operations. */
static inline double bracketed_root_deg(const double *c, const int deg, double a, double b, double fa,
                                        double x, double tol)
{
    double dp, dxold = b - a, dx = dxold, ga = fa;
    double fx = horner(c, deg, x, &dp);
    for (int it = 0; it < 100; it++) {
        if (((x - b) * dp - fx) * ((x - a) * dp - fx) > 0.0 || fabs(2.0 * fx) > fabs(dxold * dp)) {
            dxold = dx;
            dx = 0.5 * (b - a);
            x = a + dx;
        } else {
            dxold = dx;
            dx = fx / dp;
            x -= dx;
        }
        if (fabs(dx) <= tol * fabs(x) + 1e-300) break;
        fx = horner(c, deg, x, &dp);
        if (fx == 0.0) break;
        if (fx * ga > 0.0) { a = x; ga = fx; } else b = x;
    }
    return x;
}

static double bracketed_root(const double *c, int deg, double a, double b, double fa, double x, double tol)
{
    return deg == 8 ? bracketed_root_deg(c, 8, a, b, fa, x, tol) : bracketed_root_deg(c, deg, a, b, fa, x, tol);
}

/* The real roots of sum c[i] x^i (degree <= 8) in [lo, hi], ascending: between
 * consecutive real roots of the derivative (found the same way, down to degree 2, to
 * the relative precision tol) the polynomial is monotone, so every sign change there
 * holds exactly one root (bracketed_root from the midpoint). Written here because GSL's
 * gsl_poly_complex_solve (the eigenvalues of the companion matrix) returns close
 * real roots of (40) as complex pairs once sigma is large (its coefficients then span
 * thirty orders of magnitude: none found at sigma |p1-p0|^2 = 4000 on test problems),
 * and computes the complex roots that are not needed. A root of even multiplicity
 * (no sign change) is not found. The plain counterpart of el__poly_roots_in (below),
 * and its fallback. */
void el__poly_roots_in_plain(const double *c, int deg, double lo, double hi, double tol,
                             double *roots, int *nroots)
{
    deg = effective_degree(c, deg, lo, hi);
    *nroots = 0;
    if (deg <= 0 || !(hi > lo)) return;
    if (deg <= 2) {
        double r[2];
        int n;
        el__poly_real_roots(c, deg, r, &n);
        for (int i = 0; i < n; i++)
            if (r[i] >= lo && r[i] <= hi) roots[(*nroots)++] = r[i];
        if (*nroots == 2 && roots[0] > roots[1]) { const double t = roots[0]; roots[0] = roots[1]; roots[1] = t; }
        return;
    }
    double d[8], crit[8], pts[10], dp;
    int nc;
    for (int i = 1; i <= deg; i++) d[i - 1] = i * c[i];
    el__poly_roots_in_plain(d, deg - 1, lo, hi, 1e-7, crit, &nc);
    int np = 0;
    pts[np++] = lo;
    for (int i = 0; i < nc; i++) pts[np++] = crit[i];
    pts[np++] = hi;
    double fb = horner(c, deg, lo, &dp);
    for (int i = 0; i + 1 < np; i++) {
        const double a = pts[i], b = pts[i + 1], fa = fb;
        fb = horner(c, deg, b, &dp);
        if (fa == 0.0) {
            if (*nroots == 0 || roots[*nroots - 1] != a) roots[(*nroots)++] = a;
            continue;
        }
        if (fb == 0.0 || fa * fb > 0.0) continue;
        roots[(*nroots)++] = bracketed_root(c, deg, a, b, fa, 0.5 * (a + b), tol);
    }
}

/* ------------------------------------------------------------ root isolation */

/* Bernstein coefficients b[0..n] of p on [lo, hi] (p(lo + (hi - lo) t) = sum b_k
 * C(n,k) t^k (1-t)^(n-k)) and a bound *err of their rounding errors: the Taylor shift
 * p(lo + y) by repeated synthetic division, the scaling y = (hi - lo) t, then
 * b_k = sum_{j <= k} C(k,j) / C(n,j) q_j (Farin, Curves and Surfaces for CAGD, 5.6). The
 * bound comes from the same sums over absolute values: each term passes at most 2n + 2
 * roundings, so |error| <= 4 (n + 1) eps times the sum of |terms|, taken with a margin. */
static inline void bernstein_coeffs(const double *c, const int n, double lo, double hi, double *b,
                                    double *err)
{
    double q[9], qa[9];
    for (int i = 0; i <= n; i++) { q[i] = c[i]; qa[i] = fabs(c[i]); }
#pragma GCC unroll 8
    for (int i = 0; i < n; i++)
#pragma GCC unroll 8
        for (int j = n - 1; j >= i; j--) {
            q[j] += lo * q[j + 1];
            qa[j] += fabs(lo) * qa[j + 1];
        }
    double hj = 1.0;
    for (int j = 0; j <= n; j++, hj *= hi - lo) { q[j] *= hj; qa[j] *= hj; }
    *err = 0.0;
    /* C(k,j) / C(n,j) = prod_{i<j} (k - i) / (n - i) */
#pragma GCC unroll 9
    for (int k = 0; k <= n; k++) {
        double sum = 0.0, sa = 0.0, w = 1.0;
#pragma GCC unroll 9
        for (int j = 0; j <= k; j++) {
            sum += w * q[j];
            sa += w * qa[j];
            w *= (double)(k - j) / (double)(n - j);
        }
        b[k] = sum;
        const double e = 16.0 * (n + 1) * DBL_EPSILON * sa;
        if (e > *err) *err = e;             /* fmax(*err, e): a NaN e leaves *err */
    }
}

/* de Casteljau's subdivision at t = 1/2 into bl (left half) and br (right). The halves'
 * coefficients are averages of the parent's, so their errors are at most the parent's
 * bound plus n roundings of at most eps max |b| each (bmax): *err grows by that. */
static inline void bernstein_halves(const double *b, const int n, double bmax, double *bl, double *br,
                                    double *err)
{
    double w[9];
    for (int k = 0; k <= n; k++) w[k] = b[k];
#pragma GCC unroll 9
    for (int r = 0; r <= n; r++) {
        bl[r] = w[0];
        br[n - r] = w[n - r];
#pragma GCC unroll 8
        for (int k = 0; k < n - r; k++) w[k] = 0.5 * (w[k] + w[k + 1]);
    }
    *err += 2.0 * n * DBL_EPSILON * bmax;
}

/* Depth of the subdivision before an interval is handed to the plain method: where
 * rounding leaves a coefficient's sign open (p at rounding level: a double root, a root
 * at a subdivision point, coefficients spanning many orders of magnitude: halving such an
 * interval further doubles the unsure ones), and where two roots are still not apart
 * (2^-24 of the interval). */
#define UNSURE_DEPTH 6
#define ISOLATE_DEPTH 24

/* The polynomial being isolated and the roots found so far (at most its degree n: more
 * means rounding broke Descartes' count, underflow on a tiny interval say, and *full is
 * set for the plain method to take over). */
typedef struct {
    const double *c;
    int n;
    double tol;
    double *roots;
    int nroots, full;
} isolation;

static void add_root(isolation *w, double x)
{
    if (w->nroots < w->n) w->roots[w->nroots++] = x;
    else w->full = 1;
}

static void isolate(isolation *w, double a, double b, const double *bc, double err, int depth);
static void isolate8(isolation *w, double a, double b, const double *bc, double err, int depth);

/* The roots in [a, b] of w's polynomial (degree n = w->n), its Bernstein coefficients bc
 * there with the error bound err, ascending into w: by Descartes' rule for the Bernstein
 * basis the number of sign changes of bc bounds the number of roots and has its parity,
 * so none where bc keeps its sign, exactly one where it changes sign once (found by
 * Newton from where the control polygon crosses zero), else the halves. Inlined into
 * isolate8 with n = 8 constant ((40)'s usual degree: the loops unrolled, the same
 * operations) and into isolate for other degrees. */
static inline void isolate_deg(isolation *w, const int n, double a, double b, const double *bc, double err,
                               int depth)
{
    if (w->full) return;
    /* the signs as bit masks, without branches (they follow no pattern a predictor could
     * learn): pos, neg, bit k for bc[k] > err, < -err; unsure: a sign rounding leaves open
     * (neither bit). With every sign sure, bit j of pos ^ (pos >> 1) is a change between
     * k = j and j + 1: none (return), one (cross, the k after it), or more (halve). */
    unsigned pos = 0, neg = 0;
    int k = 0;
#if defined(__SSE2__)
    /* two coefficients per comparison (movmskpd gathers the lanes' results as bits): the
     * same comparisons (IEEE, a NaN compares false either way), 18 scalar comparisons and
     * their shifts were 10 % of el__hermite_poly40_roots */
    const __m128d pe = _mm_set1_pd(err), ne = _mm_set1_pd(-err);
    for (; k < n; k += 2) {
        const __m128d v = _mm_loadu_pd(bc + k);
        pos |= (unsigned)_mm_movemask_pd(_mm_cmpgt_pd(v, pe)) << k;
        neg |= (unsigned)_mm_movemask_pd(_mm_cmplt_pd(v, ne)) << k;
    }
#endif
    for (; k <= n; k++) {
        pos |= (unsigned)(bc[k] > err) << k;
        neg |= (unsigned)(bc[k] < -err) << k;
    }
    const unsigned all = (2u << n) - 1u, ch = (pos ^ (pos >> 1)) & (all >> 1);
    const int unsure = (pos | neg) != all;
    if (!unsure && ch == 0) return;
    if (!unsure && (ch & (ch - 1u)) == 0) {
        int cross = 1;
        for (unsigned c = ch; !(c & 1u); c >>= 1) cross++;
        const double t = (cross - bc[cross] / (bc[cross] - bc[cross - 1])) / n;
        add_root(w, bracketed_root(w->c, n, a, b, bc[0], a + t * (b - a), w->tol));
        return;
    }
    if (depth >= (unsure ? UNSURE_DEPTH : ISOLATE_DEPTH)) {
        double r[8];
        int nr;
        el__poly_roots_in_plain(w->c, n, a, b, w->tol, r, &nr);
        for (int i = 0; i < nr; i++)
            if (w->nroots == 0 || r[i] > w->roots[w->nroots - 1]) add_root(w, r[i]);
        return;
    }
    double bl[9], br[9], bmax = 0.0;
    for (int k = 0; k <= n; k++) bmax = fabs(bc[k]) > bmax ? fabs(bc[k]) : bmax;
    bernstein_halves(bc, n, bmax, bl, br, &err);
    const double m = 0.5 * (a + b);
    if (n == 8) {
        isolate8(w, a, m, bl, err, depth + 1);
        isolate8(w, m, b, br, err, depth + 1);
    } else {
        isolate(w, a, m, bl, err, depth + 1);
        isolate(w, m, b, br, err, depth + 1);
    }
}

static void isolate8(isolation *w, double a, double b, const double *bc, double err, int depth)
{
    isolate_deg(w, 8, a, b, bc, err, depth);
}

static void isolate(isolation *w, double a, double b, const double *bc, double err, int depth)
{
    isolate_deg(w, w->n, a, b, bc, err, depth);
}

/* The same roots as el__poly_roots_in_plain, isolated first by the signs of Bernstein
 * coefficients: no roots of the derivatives to locate (of the degree-8 polynomial (40),
 * with four to eight roots in the interval, the plain method locates about thirty, each
 * by Newton's method), ~8 halvings instead. Where rounding leaves the count open the plain
 * method takes over on that interval, and on the whole where more roots than the degree
 * came out (isolate). Checked against the plain method in tests/c/test_hermite_tension.c. */
void el__poly_roots_in(const double *c, int deg, double lo, double hi, double tol, double *roots,
                       int *nroots)
{
    deg = effective_degree(c, deg, lo, hi);
    *nroots = 0;
    if (deg <= 2 || !(hi > lo)) {
        el__poly_roots_in_plain(c, deg, lo, hi, tol, roots, nroots);
        return;
    }
    double b[9], err;
    isolation w = {c, deg, tol, roots, 0, 0};
    if (deg == 8) {                         /* n constant: the loops unrolled, the same operations */
        bernstein_coeffs(c, 8, lo, hi, b, &err);
        isolate8(&w, lo, hi, b, err, 0);
    } else {
        bernstein_coeffs(c, deg, lo, hi, b, &err);
        isolate(&w, lo, hi, b, err, 0);
    }
    if (w.full) el__poly_roots_in_plain(c, deg, lo, hi, tol, roots, nroots);
    else *nroots = w.nroots;
}

/* Small polynomial arithmetic (coefficients low to high, degree <= 8). */
typedef struct { double c[9]; int d; } poly;
static poly pmul(poly a, poly b)
{
    poly r = {{0}, a.d + b.d};
    for (int i = 0; i <= a.d; i++)
        for (int j = 0; j <= b.d; j++) r.c[i + j] += a.c[i] * b.c[j];
    return r;
}
static poly padd(poly a, double sa, poly b, double sb)
{
    poly r = {{0}, a.d > b.d ? a.d : b.d};
    for (int i = 0; i <= a.d; i++) r.c[i] += sa * a.c[i];
    for (int i = 0; i <= b.d; i++) r.c[i] += sb * b.c[i];
    return r;
}

/* Polynomial (40) (Theorem 11): its roots are the kappa0 with kappa_m^2 = 2 sigma.
 * kappa_m^2 = 2 sigma in (8) gives 4 kappa0'^2 = -D, D = (kappa0^2 - sigma)^2 - sigma^2 (42).
 * Case 1: with (16) 4 (kappa1 - C)^2 + P2^2 D = 0 (43); subtracting 4/P2 (17) leaves
 * kappa1 = N / M, N = 4 P2 C^2 + P2^3 D + 8 V1 C + 4 A P2, M = 8 (P2 C + V1); so
 * 4 (N - C M)^2 + P2^2 D M^2 = 0, degree 8, leading 4 P2^2 (P1^2 + P2^2)^2 as printed.
 * Since N - C M = P2 (4 (A - C^2) + P2^2 D), that is P2^2 times
 *   4 (4 (A - C^2) + P2^2 D)^2 + D M^2,      leading 4 (P1^2 + P2^2)^2,
 * which is formed here: the printed product loses the D M^2 term to rounding when P2 is
 * small (P2 ~ 1e-11: a noisy square whose roots come and go), this form tends to 64 times
 * case 2's as P2 -> 0.
 * Case 2: kappa0' = (A - C^2)/(2 V1) gives (A - C^2)^2 + V1^2 D = 0. */
static poly poly40(const hprob *pr)
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    const poly w = {{-s, 0, 1}, 2};
    const poly C = {{-0.5 * s * P1, 1.0, 0.5 * P1}, 2};
    const poly A = {{s - s * V2, 0, V2}, 2};
    const poly one = {{1}, 0};
    const poly D = padd(pmul(w, w), 1.0, one, -s * s);
    const poly AC = padd(A, 1.0, pmul(C, C), -1.0);
    if (pr->hcase == 2) return padd(pmul(AC, AC), 1.0, D, V1 * V1);
    const poly Q = padd(AC, 4.0, D, P2 * P2);           /* (N - C M) / P2 */
    const poly M = padd(C, 8.0 * P2, one, 8.0 * V1);
    return padd(pmul(Q, Q), 4.0, pmul(D, pmul(M, M)), 1.0);
}

/* (45): kappa0^2 = sigma, and kappa0' = 0, which by (15), (16) is C^2 = A. With
 * w = kappa0^2 - sigma, C^2 - A = w (w P1^2/4 + P1 kappa0 + 1 - V2): the quartic
 * splits into kappa0^2 = sigma and a quadratic, so at most four values. */
int el__hermite_special_values(const hprob *pr, double *out, int *n)
{
    *n = 0;
    const double s = pr->sigma, P1 = pr->P1, V2 = pr->V2;
    if (s >= 0.0) { out[(*n)++] = -sqrt(s); out[(*n)++] = sqrt(s); }
    if (pr->hcase == 3) return EL_OK;
    const double q[3] = {1.0 - V2 - 0.25 * s * P1 * P1, P1, 0.25 * P1 * P1};
    double r[2];
    int nr, rc = el__poly_real_roots(q, 2, r, &nr);
    if (rc) return rc;
    for (int i = 0; i < nr; i++) out[(*n)++] = r[i];
    return EL_OK;
}

/* The ends of (18) (case 1): disc(kappa0) = a2 kappa0^2 + a1 kappa0 + a0 >= 0. */
void el__hermite_disc_coeffs(const hprob *pr, double a[3])
{
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    a[2] = P2 * V1 * P1 + P2 * P2 * V2;
    a[1] = 2.0 * P2 * V1;
    a[0] = V1 * V1 - P2 * V1 * P1 * s + P2 * P2 * s * (1.0 - V2);
}

int el__hermite_poly40(const hprob *pr, double c[9])
{
    const poly p = poly40(pr);
    memcpy(c, p.c, sizeof p.c);
    return p.d;
}

/* ------------------------------------------------------------ the separatrix crossings */

/* Where (40) can vanish: it is a square plus D M^2 (case 1, poly40 above) or plus
 * V1^2 D (case 2), D = kappa0^2 (kappa0^2 - 2 sigma) (42), so its roots have
 * kappa0^2 <= 2 sigma (kappa_m^2 = 2 sigma >= kappa0^2): [-sqrt(2 sigma), sqrt(2 sigma)]
 * (widened by rounding's margin) holds the roots of [-B, B] with fewer critical points
 * of the derivatives to locate. */
static double poly40_range(double sigma, double B)
{
    return fmin(B, sqrt(2.0 * sigma) * (1.0 + 1e-9));
}

/* The roots of (40) in the range of poly40_range, ascending. Up to SEP_SIGMA by Bernstein
 * isolation (el__poly_roots_in); above, where the separatrix pieces start from these
 * crossings (el__hermite_crossing_refine) and the solutions hug them exponentially
 * closely, by the plain method as before: the two differ by up to 1e-13 after the
 * refinement near a close pair of crossings, and on 3000 problems per kind with tangents
 * aligned to the chord (sigma |p1-p0|^2 from 100 to 1100) that moved 6 of 6161 solutions
 * out of reach and 2 others into it (the solver's own sensitivity there, not the roots'
 * accuracy). */
void el__hermite_poly40_roots(const hprob *pr, double *r, int *nr)
{
    double pc[9];
    const int pd = el__hermite_poly40(pr, pc);
    const double X40 = poly40_range(pr->sigma, pr->B);
    if (pr->sigma > SEP_SIGMA) el__poly_roots_in_plain(pc, pd, -X40, X40, 4e-16, r, nr);
    else el__poly_roots_in(pc, pd, -X40, X40, 4e-16, r, nr);
}

/* Which root of (17) has kappa_m^2 = 2 sigma at a root of (40) (seed 004 §4:
 * the roots are divided in two groups, one per objective function): the branch b
 * whose |(|F| - sigma)| is the smaller. kappa0 = x and (18) are common to both
 * branches, so kappa1 and kappa0' of each are formed here directly, by
 * el__hermite_curvdata's formulas (19), (20) (the same values: test_hermite_tension.c
 * checks the choice against curvdata's states), and (18) < 0 or a non-finite state
 * (which curvdata rejects) leaves a branch out. */
int el__hermite_root_branch(const hprob *pr, double x)
{
    if (pr->hcase != 1) return 0;
    const double s = pr->sigma, P1 = pr->P1, P2 = pr->P2, V1 = pr->V1, V2 = pr->V2;
    const double w = x * x - s, C = 0.5 * w * P1 + x, A = x * x * V2 + s * (1.0 - V2);   /* as curvdata's */
    const double c0 = 2.0 * V1 * C + A * P2, disc = V1 * V1 + P2 * c0;     /* (18) */
    if (disc < 0.0) return 0;
    const double sq = sqrt(disc), F2 = w;
    int best = 0;
    double bd = INFINITY;
    for (int b = 0; b < 2; b++) {
        double k1;
        if (b == 0) k1 = V1 > 0.0 ? c0 / (V1 + sq) : (-V1 + sq) * pr->iP2;    /* (19) */
        else        k1 = V1 < 0.0 ? c0 / (V1 - sq) : (-V1 - sq) * pr->iP2;
        /* (20) */
        const double k0p = fabs(V1) > fabs(P2) ? (A - k1 * k1) * pr->i2V1 : (k1 - C) * pr->iP2;
        if (!isfinite(k1) || !isfinite(k0p)) continue;
        const double F1 = -2.0 * k0p;
        const double dd = fabs(sqrt(F1 * F1 + F2 * F2) - s);   /* kappa_m^2 - 2 sigma */
        if (dd < bd) { bd = dd; best = b; }
    }
    return best;
}

/* The same choice by el__hermite_curvdata's states (the plain counterpart: the tests' reference). */
int el__hermite_root_branch_plain(const hprob *pr, double x)
{
    if (pr->hcase != 1) return 0;
    int best = 0;
    double bd = INFINITY;
    for (int b = 0; b < 2; b++) {
        hstate st;
        if (el__hermite_curvdata(pr, x, b, &st)) continue;
        const double F1 = -2.0 * st.k0p, F2 = st.k0 * st.k0 - pr->sigma;
        const double dd = fabs(sqrt(F1 * F1 + F2 * F2) - pr->sigma);   /* kappa_m^2 - 2 sigma */
        if (dd < bd) { bd = dd; best = b; }
    }
    return best;
}

/* |F|^2 - sigma^2 = 4 kappa0'^2 + kappa0^2 (kappa0^2 - 2 sigma) at x on branch b, from
 * the curvature data alone (NaN outside (18)): what a root of (40) makes zero. */
static double crossing_gap(const hprob *pr, int b, double x)
{
    hstate st;
    if (el__hermite_curvdata(pr, x, b, &st)) return NAN;
    return 4.0 * st.k0p * st.k0p + st.k0 * st.k0 * (st.k0 * st.k0 - 2.0 * pr->sigma);
}

/* A root x of (40), assigned to branch b, refined by the secant method on crossing_gap:
 * the polynomial's coefficients span many orders of magnitude at high tension, which
 * leaves its roots up to ~1e-12 relative off (1.7e-10 at sigma |p1-p0|^2 = 4000), while
 * the solutions there lie exponentially closer to the crossing, from which the
 * separatrix pieces start. The refined value is kept only when it lowers |gap| and
 * moves x by less than 1e-6 (1 + |x|) (the same crossing). */
double el__hermite_crossing_refine(const hprob *pr, int b, double x)
{
    double x0 = x, g0 = crossing_gap(pr, b, x0);
    if (!isfinite(g0) || g0 == 0.0) return x;
    double x1 = x0 + 1e-10 * (1.0 + fabs(x0)), g1 = crossing_gap(pr, b, x1);
    for (int it = 0; it < 8 && isfinite(g1) && g1 != g0 && g1 != 0.0; it++) {
        const double x2 = x1 - g1 * (x1 - x0) / (g1 - g0);
        if (!(fabs(x2 - x) < 1e-6 * (1.0 + fabs(x)))) return x;
        x0 = x1;
        g0 = g1;
        x1 = x2;
        g1 = crossing_gap(pr, b, x1);
        if (fabs(x1 - x0) <= 4e-16 * fabs(x1)) break;
    }
    return isfinite(g1) && fabs(g1) < fabs(crossing_gap(pr, b, x)) ? x1 : x;
}

/* ------------------------------------------------------------ the analysis */

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int el_hermite_analyse(const double P[2], const double V[2], double sigma,
                       el_hermite_analysis *a)
{
    if (!P || !V || !a) return EL_EINVAL;
    const double v[5] = {P[0], P[1], V[0], V[1], sigma};
    if (el__all_finite(v, 5) || fabs(hypot(P[0], P[1]) - 1.0) > 1e-9 ||
        fabs(hypot(V[0], V[1]) - 1.0) > 1e-9)
        return EL_EINVAL;
    if (sigma > EL_HERMITE_SIGMA_D2_MAX) return EL_EDOM;   /* the range of el_hermite_solve */
    el__gsl_quiet();
    hprob pr = {P[0], P[1], V[0], V[1], sigma, 0, 1.0, 0.0, 0.0, 0.0};   /* set_case: the rest */
    el__hermite_set_case(&pr);
    int rc = el__hermite_kappa_bound(sigma, 1.0, &pr.B);
    if (rc) return rc;
    el_hermite_analysis out;
    memset(&out, 0, sizeof out);
    out.hcase = pr.hcase;
    out.kappa_bound = pr.B;
    if (pr.B < 0.0) { *a = out; return EL_OK; }
    double lo = -pr.B, hi = pr.B;
    if (pr.hcase == 1) {
        double c[3], r[2];
        int nr;
        el__hermite_disc_coeffs(&pr, c);
        if ((rc = el__poly_real_roots(c, 2, r, &nr))) return rc;
        /* pieces of [lo, hi] where disc >= 0 */
        double pts[4] = {lo, hi, 0, 0};
        int np = 2;
        for (int i = 0; i < nr; i++) if (r[i] > lo && r[i] < hi) pts[np++] = r[i];
        qsort(pts, (size_t)np, sizeof *pts, cmp_double);
        for (int i = 0; i + 1 < np; i++) {
            const double m = 0.5 * (pts[i] + pts[i + 1]);
            if (c[2] * m * m + c[1] * m + c[0] < 0.0) continue;
            if (out.ninterval > 0 && out.interval[2 * out.ninterval - 1] == pts[i])
                out.interval[2 * out.ninterval - 1] = pts[i + 1];
            else if (out.ninterval < 2) {
                out.interval[2 * out.ninterval] = pts[i];
                out.interval[2 * out.ninterval + 1] = pts[i + 1];
                out.ninterval++;
            }
        }
    } else if (pr.hcase == 2) {
        out.ninterval = 1;
        out.interval[0] = lo;
        out.interval[1] = hi;
    }
    if (pr.hcase != 3) {
        double r[8];
        int nr;
        el__hermite_poly40_roots(&pr, r, &nr);
        for (int i = 0; i < nr && out.nroot < 8; i++) {
            int inside = 0;
            for (size_t j = 0; j < out.ninterval; j++)
                inside |= r[i] >= out.interval[2 * j] && r[i] <= out.interval[2 * j + 1];
            if (!inside) continue;
            const int best = el__hermite_root_branch(&pr, r[i]);
            out.root[out.nroot] = el__hermite_crossing_refine(&pr, best, r[i]);
            out.root_branch[out.nroot++] = best;
        }
        int ns;
        if ((rc = el__hermite_special_values(&pr, out.special, &ns))) return rc;
        out.nspecial = (size_t)ns;
        qsort(out.special, out.nspecial, sizeof(double), cmp_double);
    }
    *a = out;
    return EL_OK;
}

