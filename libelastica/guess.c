/*
 * Initial parameters for the fit, seed 000 §4.3 (discrete) and its smooth
 * analogue (Brander et al.), in the one-formula parametrisation of the header
 * (every k > 0, k > 1 = the paper's case (i) with modulus 1/k).
 *
 * Derivation used here (smooth, then applied to both models). With
 * a = (theta - phi)/2, sin a = k sn u, cos a = dn u, u = w s + q (w = sqrt(mu)):
 *   kappa = 2k w cn u,  d kappa/ds = -2k mu sn dn = -mu Y_local',
 * so kappa = mu2 x - mu1 y + A with (mu1, mu2) = mu (cos phi, sin phi)   (4.25);
 *   sin Psi = cos 2a = 1 - 2k^2 sn^2 = mu U^2/2 + A U + B,  U = <I, gamma>  (4.26)
 * with B = 1 - 2k^2 + A^2/(2 mu), i.e. k = (1/2) sqrt(A^2/mu - 2(B - 1))  (4.37),
 * for every k > 0 ((4.36) is the same relation for the reciprocal modulus).
 *
 * Differences from the paper, and why:
 *  - (4.34) is solved once integrated, theta(s) = theta_0 + mu2 X(s) - mu1 Y(s) + A s,
 *    X = int x ds, Y = int y ds: tangent angles instead of second differences,
 *    so noise of 1 % of the length does not swamp the estimate. Dense data are
 *    first reduced to the polygon of ~32 block means (same reason, and speed).
 *  - q and z: instead of inverting only at both ends and counting m by (4.38),
 *    the amplitude psi = atan2(sn u, cn u) is taken at every segment (sn u from
 *    the tangent, sin a / k; cn u from the fitted curvature, kappa / (2 k w)),
 *    unwrapped along the curve (this counts the monotone pieces from the data),
 *    u = F(psi; k) by gsl_sf_ellint_F, and u = w s + q is a straight-line fit
 *    (4.54). For k > 1, psi = a and u = F(a; 1/k)/k.
 *  - Orientation: the phase fit gives w < 0 when u decreases along the data;
 *    for the smooth model that is the curve (|w|, -k, -q), so clockwise loops
 *    get k < -1 (to_smooth); the discrete model keeps k > 0 and z < 0.
 *  - Ambiguity (k near 1, a wrong unwrap) is handled by candidates: the guess on
 *    the other side of k = 1, a circular-arc / straight-line guess and the arc of the
 *    circle fitted to the points (no tangent angles); the fit tries them in order of
 *    their initial rms.
 */
#include "fit_internal.h"
#include "guess_internal.h"
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit.h>
#include <gsl/gsl_sf_ellint.h>

/* GUESSES_MAX from one polygon, of the two polygons (guess_run) the CAND_OUT best ranked
 * handed out (the header's "at most 6") */
enum { BLOCKS = EL__GUESS_BLOCKS, RAW_MAX = EL__GUESS_RAW_MAX, GUESSES_MAX = 6, NCAND_MAX = 2 * GUESSES_MAX, CAND_OUT = 6,
       MERGE_NOISE = 2, MERGED_MIN = 8 };

/* A model-independent guess in normalised coordinates: u(s) = w s + q, s = t L. */
typedef struct cguess {
    double phi, w, k, q, L;
} cguess;

/* the spread about the centroid, over the centroid's |x| + |y|, below which the points are
 * tested for all equal (el__fit_normalisation) */
static const double EQUAL_LOOK = 1e-6;

/*
 * Centroid and rms radius of the points: the normalisation of the guess and the fit.
 * The spread is measured first as the largest deviation, so that 1e+-300 inputs cannot
 * overflow; a spread below DBL_MIN / DBL_EPSILON (~1e-292: differences of the points
 * would be denormal, losing their digits) or beyond double's range is EL_EDOM; all points
 * equal to rounding (below) EL_ESINGULAR.
 */
int el__fit_normalisation(const double *xy, size_t n, double *cx, double *cy, double *sc)
{
    double mx = 0.0, my = 0.0;
    for (size_t i = 0; i < n; i++) { mx += xy[2 * i] / (double)n; my += xy[2 * i + 1] / (double)n; }
    double amax = 0.0;     /* (the maxima by comparison, which skips NaN as fmax does: no libm call a point) */
    for (size_t i = 0; i < n; i++) {
        const double ax = fabs(xy[2 * i] - mx), ay = fabs(xy[2 * i + 1] - my);
        if (ax > amax) amax = ax;
        if (ay > amax) amax = ay;
    }
    if (amax == 0.0) return EL_ESINGULAR;
    /* all points equal to rounding (el_plane_fit's, el_find_inflection's rule): their spread
     * about the first (exact differences: the centroid of equal points far from the origin is
     * off by rounding, 20 x (12345.6, -7.5) spread 1.8e-12 about it) within 32 rounding units
     * of the largest coordinate. Looked at only where the spread about the centroid is below
     * EQUAL_LOOK of its size: equal points' is within (32 + n) eps of it (the sum's rounding) */
    if (amax <= EQUAL_LOOK * (fabs(mx) + fabs(my))) {
        double ext = 0.0, big = 0.0;
        for (size_t i = 0; i < n; i++) {
            const double ex = fabs(xy[2 * i] - xy[0]), ey = fabs(xy[2 * i + 1] - xy[1]);
            const double bx = fabs(xy[2 * i]), by = fabs(xy[2 * i + 1]);
            if (ex > ext) ext = ex;
            if (ey > ext) ext = ey;
            if (bx > big) big = bx;
            if (by > big) big = by;
        }
        if (!(ext > 32.0 * DBL_EPSILON * big)) return EL_ESINGULAR;
    }
    if (!isfinite(amax) || amax < DBL_MIN / DBL_EPSILON || !isfinite(mx) || !isfinite(my)) return EL_EDOM;
    double r2 = 0.0;
    for (size_t i = 0; i < n; i++) {
        double dx = (xy[2 * i] - mx) / amax, dy = (xy[2 * i + 1] - my) / amax;
        r2 += dx * dx + dy * dy;
    }
    const double sc0 = amax * sqrt(r2 / (double)n);
    if (!(sc0 > 0.0) || !isfinite(sc0)) return EL_EDOM;
    *cx = mx; *cy = my; *sc = sc0;
    return EL_OK;
}

/* The fit's units (fit.c), from the same normalisation (the noise level: fit_noise.c). */

/* A parameter value j in input units -> normalised (the smooth mu -> w = sqrt(mu)). */
double el__fit_norm_param(int model, int j, double v, double cx, double cy, double sc)
{
    if (j == 0) return (v - cx) / sc;
    if (j == 1) return (v - cy) / sc;
    if (j == fit_length_slot(model)) return v / sc;
    if (model == FIT_SMOOTH && j == 3) return v >= 0.0 ? sqrt(v) * sc : NAN;
    return v;
}

double el__fit_denorm_param(int model, int j, double v, double cx, double cy, double sc)
{
    if (j == 0) return cx + sc * v;
    if (j == 1) return cy + sc * v;
    if (j == fit_length_slot(model)) return v * sc;
    if (model == FIT_SMOOTH && j == 3) return (v / sc) * (v / sc);
    return v;
}

/* EL_EINVAL unless xy holds n >= nmin finite points (the fit's entry points' test) */
int el__fit_check_points(const double *xy, size_t n, size_t nmin)
{
    if (!xy || n < nmin) return EL_EINVAL;
    return el__all_finite(xy, 2 * n) ? EL_EINVAL : EL_OK;
}

/* The points, normalised on the fly, and their fractions (fit_internal.h, shared with
 * guess_spacing.c, which holds the spacing tests). */
typedef el__guess_points points;
typedef el__guess_fractions fractions;

/* the noise level, as a part of the mean side, from which CHORD measures along the block
 * means (QA23's scans: 11 x the mean side; the test's equilateral elastica samples: ~0) */
#define BLOCK_ARC_NOISE 0.1

static int fractions_start(fractions *f, const points *p, int mode, int *mode_used)
{
    memset(f, 0, sizeof *f);
    f->p = p;
    double nu = -1.0;      /* not yet estimated */
    double M[2 * BLOCKS];  /* the block means, once per call (n > RAW_MAX) */
    if (p->n > RAW_MAX && mode != EL_PARAM_UNIFORM) el__guess_block_means(p, M);
    if (mode == EL_PARAM_AUTO) mode = el__guess_evenly_spaced(p, M, &nu) ? EL_PARAM_UNIFORM : EL_PARAM_CHORD;
    f->chord = mode == EL_PARAM_CHORD;
    if (f->chord) {
        if (nu < 0.0) nu = el__fit_noise_rms(p->xy, p->n, p->sc);
        f->noise2 = 2.0 * nu * nu;
    }
    double P[2], Q[2];
    el__guess_point_at(p, 0, Q);
    for (size_t i = 1; i < p->n; i++) {
        el__guess_point_at(p, i, P);
        f->total += el__guess_side(f, P[0] - Q[0], P[1] - Q[1]);
        Q[0] = P[0]; Q[1] = P[1];
    }
    if (!(f->total > 0.0)) return EL_ESINGULAR;
    /* the block means' polygon where the noise is a sizeable part of a side (the points'
     * chords are then mostly noise); clean chords are their own measure (equilateral
     * samples: the block polygon's corners moved t by 2e-4 where chords give i / (n - 1)) */
    if (f->chord && p->n > RAW_MAX && nu > BLOCK_ARC_NOISE * f->total / (double)(p->n - 1))
        el__guess_block_arcs(f, M);
    if (mode_used) *mode_used = mode;
    return EL_OK;
}

static double fractions_next(fractions *f)
{
    const size_t i = f->i++, n = f->p->n;
    if (!f->chord) return (double)i / (double)(n - 1);
    double P[2];
    el__guess_point_at(f->p, i, P);
    if (i > 0) f->run += el__guess_side(f, P[0] - f->prev[0], P[1] - f->prev[1]);
    f->prev[0] = P[0]; f->prev[1] = P[1];
    if (i + 1 == n) return 1.0;
    if (!f->nb) return f->run / f->total;
    while (f->b + 2 < f->nb && i > f->ci[f->b + 1]) f->b++;
    const double t = (el__guess_block_map(f, f->b, i, f->run) - f->a0) / (f->a1 - f->a0);
    return fmin(fmax(t, 0.0), 1.0);
}

int el_fit_fractions(const double *xy, size_t n, int mode, double *t, int *mode_used)
{
    if (el__fit_check_points(xy, n, 2) || !t || mode < EL_PARAM_AUTO || mode > EL_PARAM_CHORD)
        return EL_EINVAL;
    points p = {xy, n, 0.0, 0.0, 1.0};
    int st = el__fit_normalisation(xy, n, &p.cx, &p.cy, &p.sc);
    fractions f;
    if (st || (st = fractions_start(&f, &p, mode, mode_used))) return st;
    for (size_t i = 0; i < n; i++) t[i] = fractions_next(&f);
    return EL_OK;
}

/* F(psi; k) for any real psi and 0 <= k < 1 (GSL >= 2 reduces psi itself). */
static double ellF(double psi, double k)
{
    gsl_sf_result r;
    if (gsl_sf_ellint_F_e(psi, k, GSL_PREC_DOUBLE, &r)) return NAN;
    return r.val;
}

static double ellK(double k)
{
    gsl_sf_result r;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r)) return NAN;
    return r.val;
}

/* Linear least squares y = X c (n rows, p columns, row-major X) by gsl_multifit_linear. */
static int linfit(size_t n, size_t p, const double *X, const double *y, double *c)
{
    if (n < p) return EL_ESINGULAR;
    gsl_matrix *A = gsl_matrix_alloc(n, p), *cov = gsl_matrix_alloc(p, p);
    gsl_vector *b = gsl_vector_alloc(n), *cv = gsl_vector_alloc(p);
    gsl_multifit_linear_workspace *ws = gsl_multifit_linear_alloc(n, p);
    int st = EL_ENOMEM;
    if (A && cov && b && cv && ws) {
        for (size_t i = 0; i < n; i++) {
            for (size_t j = 0; j < p; j++) gsl_matrix_set(A, i, j, X[i * p + j]);
            gsl_vector_set(b, i, y[i]);
        }
        double chisq;
        st = gsl_multifit_linear(A, b, cv, cov, &chisq, ws) ? EL_EINTERNAL : EL_OK;
        for (size_t j = 0; j < p && !st; j++) {
            c[j] = gsl_vector_get(cv, j);
            if (!isfinite(c[j])) st = EL_ESINGULAR;
        }
    }
    if (ws) gsl_multifit_linear_free(ws);
    if (A) gsl_matrix_free(A);
    if (cov) gsl_matrix_free(cov);
    if (b) gsl_vector_free(b);
    if (cv) gsl_vector_free(cv);
    return st;
}

/* The reduced polygon: block means Q (m points) at fractions tau; consecutive
 * duplicates dropped. Returns m. Few points (n <= RAW_MAX) are their own blocks, except
 * with merge > 0: a point nearer than merge to its block's first point joins that block.
 * A side of length l between two noisy points has a tangent angle off by ~ rms / l (the
 * normal part of their difference), so sides of a few noise levels give tangent angles
 * of noise, which wreck (4.34) and the unwrapped phase, and add ~ 2 rms^2 / l each to the
 * polygon's length; sparse points at uneven places have such sides (measured on 20
 * points at random arc lengths of a loop, 0.1 % noise, lbfgs_repro.py's trial 27: every
 * guess of the points themselves fits to rms 0.033 or worse, the merged polygon's to
 * 0.0040; on 120 sets of 10-40 random points, 0.1-2 % noise: 23 -> 14 fits worse than
 * the best known by > 1 %, 17 lower by > 1 %, 7 higher, 6 of them still below the true
 * curve's own rms; the 30 noise-free sets to rounding). */
static size_t reduce(const points *p, fractions *f, double merge, double *Q, double *tau)
{
    const size_t n = p->n, m = n <= RAW_MAX ? n : BLOCKS;
    size_t out = 0;
    if (n <= RAW_MAX && merge > 0.0) {
        double sum[3] = {0.0, 0.0, 0.0}, F[2] = {0.0, 0.0};
        size_t cnt = 0;
        for (size_t i = 0; i < n; i++) {
            double P[2];
            el__guess_point_at(p, i, P);
            const double t = fractions_next(f);
            if (cnt > 0 && fit_norm(P[0] - F[0], P[1] - F[1]) >= merge) {
                Q[2 * out] = sum[0] / (double)cnt; Q[2 * out + 1] = sum[1] / (double)cnt; tau[out++] = sum[2] / (double)cnt;
                cnt = 0; sum[0] = sum[1] = sum[2] = 0.0;
            }
            if (cnt++ == 0) { F[0] = P[0]; F[1] = P[1]; }
            sum[0] += P[0]; sum[1] += P[1]; sum[2] += t;
        }
        Q[2 * out] = sum[0] / (double)cnt; Q[2 * out + 1] = sum[1] / (double)cnt; tau[out++] = sum[2] / (double)cnt;
        return out;
    }
    for (size_t b = 0; b < m; b++) {
        size_t lo = b * n / m, hi = (b + 1) * n / m;
        double x = 0, y = 0, tt = 0, P[2];
        for (size_t i = lo; i < hi; i++) { el__guess_point_at(p, i, P); x += P[0]; y += P[1]; tt += fractions_next(f); }
        x /= (double)(hi - lo); y /= (double)(hi - lo); tt /= (double)(hi - lo);
        if (out > 0 && x == Q[2 * out - 2] && y == Q[2 * out - 1]) continue;
        Q[2 * out] = x; Q[2 * out + 1] = y; tau[out] = tt;
        out++;
    }
    return out;
}

/* Segment data of the reduced polygon. */
typedef struct segs {
    size_t m;                 /* segments */
    double theta[BLOCKS + RAW_MAX];   /* unwrapped tangent angle */
    double sigma[BLOCKS + RAW_MAX];   /* arc parameter of the midpoint */
    double mx[BLOCKS + RAW_MAX], my[BLOCKS + RAW_MAX];
    double X[BLOCKS + RAW_MAX], Y[BLOCKS + RAW_MAX];  /* int x ds, int y ds at midpoints */
    double L;                 /* model length estimate */
} segs;

static int segments(const double *Q, const double *tau, size_t m, segs *S)
{
    if (m < 2) return EL_ESINGULAR;
    double len = 0.0;
    for (size_t b = 0; b + 1 < m; b++)
        len += hypot(Q[2 * b + 2] - Q[2 * b], Q[2 * b + 3] - Q[2 * b + 1]);
    double span = tau[m - 1] - tau[0];
    if (!(len > 0.0) || !(span > 0.0)) return EL_ESINGULAR;
    S->L = len / span;
    S->m = m - 1;
    double X = 0.0, Y = 0.0, prev = 0.0;
    for (size_t b = 0; b + 1 < m; b++) {
        const double *A = Q + 2 * b, *B = A + 2;
        double s0 = tau[b] * S->L, s1 = tau[b + 1] * S->L, sm = 0.5 * (s0 + s1);
        double mx = 0.5 * (A[0] + B[0]), my = 0.5 * (A[1] + B[1]);
        double th = atan2(B[1] - A[1], B[0] - A[0]);
        if (b > 0) th += 2.0 * M_PI * nearbyint((prev - th) / (2.0 * M_PI));
        prev = th;
        S->theta[b] = th;
        S->sigma[b] = sm;
        S->mx[b] = mx; S->my[b] = my;
        S->X[b] = X + 0.5 * (A[0] + mx) * (sm - s0);
        S->Y[b] = Y + 0.5 * (A[1] + my) * (sm - s0);
        X += 0.5 * (A[0] + B[0]) * (s1 - s0);
        Y += 0.5 * (A[1] + B[1]) * (s1 - s0);
    }
    return EL_OK;
}

/* u at the segment midpoints for modulus k, then u = w s + q by least squares. */
static int phase_fit(const segs *S, double phi, double mu, double A, double k, cguess *g)
{
    const size_t m = S->m;
    double X[2 * (BLOCKS + RAW_MAX)], u[BLOCKS + RAW_MAX];
    const double sp = sin(phi), cp = cos(phi), kmax = 2.0 * k * sqrt(mu);
    double prev = 0.0;
    for (size_t b = 0; b < m; b++) {
        double psi;
        if (k < 1.0) {
            double a = 0.5 * remainder(S->theta[b] - phi, 2.0 * M_PI);
            double U = sp * S->mx[b] - cp * S->my[b];
            psi = atan2(sin(a) / k, (mu * U + A) / kmax);
            if (b > 0) psi += 2.0 * M_PI * nearbyint((prev - psi) / (2.0 * M_PI));
        } else {
            double d = S->theta[b] - phi;
            if (b == 0) d = remainder(d, 2.0 * M_PI);
            else d += 2.0 * M_PI * nearbyint((2.0 * prev - d) / (2.0 * M_PI));
            psi = 0.5 * d;
        }
        prev = psi;
        u[b] = k < 1.0 ? ellF(psi, k) : ellF(psi, 1.0 / k) / k;
        if (!isfinite(u[b])) return EL_EINTERNAL;
        X[2 * b] = S->sigma[b];
        X[2 * b + 1] = 1.0;
    }
    double c[2];
    int st = linfit(m, 2, X, u, c);
    if (st) return st;
    g->phi = phi; g->k = k; g->w = c[0]; g->q = c[1]; g->L = S->L;
    return EL_OK;
}

/*
 * A circular arc of curvature kappa, start tangent theta0, length L as a guess: an
 * elastica whose curvature kappa = 2 k w cn u stays within ~1 % of kappa along it. Turning
 * by 2 rad or more, k = 10 (cn u within 1 % of 1 for k > 1), u(0) = 0. A gentler arc has
 * the force F = w^2 at 1e-2 / L^2 instead, along the arc's mid tangent (phi = theta0 +
 * kappa L / 2: the turn is a small swing about the pendulum's rest, theta'' = -F sin(theta
 * - phi), which changes the curvature by ~F L^2 / 8 of itself): with k = 10 the force
 * (kappa / 20)^2 of a nearly straight arc was ~1e-9, where the fit's start-state chart
 * (fit_model.c) is singular and Levenberg-Marquardt could take no step (measured: noisy
 * straight lines of 100-180 points, 3 of 40 fits ended at Ipopt's max_iter crawling
 * along k = 1). The two agree at kappa L = 2. From the start state (theta0 - phi = 2 a(q),
 * kappa = 2 k w cn q): S = sin((theta0 - phi) / 2), C = |kappa| / (2 |w|), k = hypot(S, C),
 * q = F(asin(S / k) | k) for k < 1, F((theta0 - phi) / 2 | 1/k) / k otherwise (sn q = S/k,
 * cn q = C/k > 0), w < 0 for kappa < 0 (fit_model.c's chart).
 */
enum { NEAR_CIRCLE_K = 10 };
static void near_circle(double theta0, double kappa, double L, cguess *g)
{
    const double w0 = 0.1 / L;
    g->L = L;
    if (fabs(kappa) >= 2.0 * NEAR_CIRCLE_K * w0) {
        g->k = NEAR_CIRCLE_K;
        g->w = kappa / (2.0 * g->k);
        g->q = 0.0;
        g->phi = theta0;
        return;
    }
    const double half = -0.25 * kappa * L, S = sin(half), C = fabs(kappa) / (2.0 * w0), k = hypot(S, C);
    g->phi = theta0 + 0.5 * kappa * L;
    g->w = kappa < 0.0 ? -w0 : w0;
    g->k = k;
    g->q = k == 0.0 ? 0.0 : k < 1.0 ? ellF(asin(S / k), k) : ellF(half, 1.0 / k) / k;   /* NaN: no guess */
}

/* Guesses in normalised coordinates from the polygon reduced with `merge` (reduce);
 * returns how many (<= GUESSES_MAX; none from a merged polygon that kept every point or
 * fewer than MERGED_MIN). */
static size_t guesses(const points *p, fractions *f, double merge, cguess *out)
{
    double Q[2 * (RAW_MAX + 1)], tau[RAW_MAX + 1];
    size_t m = reduce(p, f, merge, Q, tau), cnt = 0;
    if (merge > 0.0 && (m < MERGED_MIN || m == p->n)) return 0;
    segs S;
    if (segments(Q, tau, m, &S)) return 0;
    /* (4.34) integrated: theta = theta_0 + mu2 X - mu1 Y + A s */
    if (S.m >= 5) {
        double X[4 * (BLOCKS + RAW_MAX)], c[4];
        for (size_t b = 0; b < S.m; b++) {
            X[4 * b] = 1.0; X[4 * b + 1] = S.X[b]; X[4 * b + 2] = -S.Y[b]; X[4 * b + 3] = S.sigma[b];
        }
        if (!linfit(S.m, 4, X, S.theta, c)) {
            double mu2 = c[1], mu1 = c[2], A = c[3], mu = hypot(mu1, mu2);
            if (mu > 1e-9) {
                double phi = atan2(mu2, mu1), sp = sin(phi), cp = cos(phi), B = 0.0;
                for (size_t b = 0; b < S.m; b++) {        /* (4.35) */
                    double U = sp * S.mx[b] - cp * S.my[b];
                    B += cos(S.theta[b] - phi) - 0.5 * mu * U * U - A * U;
                }
                B /= (double)S.m;
                double k2 = 0.5 * (A * A / (2.0 * mu) + 1.0 - B); /* (4.37), every k */
                double k = sqrt(fmax(k2, 1e-8));
                if (fabs(k - 1.0) < 1e-6) k = 1.0 - 1e-6;
                if (!phase_fit(&S, phi, mu, A, k, &out[cnt])) {
                    /* m - 1 and m + 1 monotone pieces (4.38): the u-span one half
                     * period shorter / longer, same u at mid-length */
                    const cguess g0 = out[cnt++];
                    const double half = k < 1.0 ? 2.0 * ellK(k) : 2.0 * ellK(1.0 / k) / k;
                    const double span = g0.w * g0.L, umid = g0.q + 0.5 * span;
                    for (int sgn = -1; sgn <= 1; sgn += 2) {
                        double sp2 = span + sgn * (span >= 0 ? half : -half);
                        if (sp2 * span <= 0.0 || !isfinite(sp2)) continue;
                        cguess g1 = g0;
                        g1.w = sp2 / g0.L;
                        g1.q = umid - 0.5 * sp2;
                        out[cnt++] = g1;
                    }
                }
                if (k > 0.5 && k < 2.0) {    /* the other side of k = 1 */
                    double k2b = fabs(k - 1.0) < 0.1 ? (k < 1.0 ? 1.1 : 0.9) : 1.0 / k;
                    if (!phase_fit(&S, phi, mu, A, k2b, &out[cnt])) cnt++;
                }
            }
        }
    }
    /* circular arc / straight line: theta = theta_0 + A s */
    {
        double X[2 * (BLOCKS + RAW_MAX)], c[2];
        for (size_t b = 0; b < S.m; b++) { X[2 * b] = 1.0; X[2 * b + 1] = S.sigma[b]; }
        if (!linfit(S.m, 2, X, S.theta, c)) {
            double A = c[1], L = S.L;
            cguess *g = &out[cnt];
            g->L = L;
            if (fabs(A) * L < 1e-3) {        /* nearly straight: tiny k */
                g->k = 1e-3; g->w = 1.0 / L; g->q = 0.0; g->phi = c[0] + 0.5 * A * L;
            } else {
                near_circle(c[0], A, L, g);
            }
            cnt++;
        }
    }
    /* the circle nearest the polygon's points algebraically (Kasa: x^2 + y^2 + D x + E y + F
     * = 0, linear in D, E, F), its arc from the first point's angle about the centre to the
     * last's. It uses no tangent angle, which points clustered closer than their noise spoil
     * (measured: 59 points along a gentle arc, k = 0.39 turning by 1.2 rad, noise 1 %,
     * turned by 0..88 degrees: the guesses above reached rms 0.0090 only through the
     * other model's fit or not at all (0.034-0.045 at 60-64 degrees); the fit from this
     * one, 0.0090 at every angle in ~3 ms). Nearly straight (turning < 1e-3): the line above. */
    if (m >= 3) {
        double X[3 * (RAW_MAX + 1)], b[RAW_MAX + 1], c[3];
        for (size_t i = 0; i < m; i++) {
            const double x = Q[2 * i], y = Q[2 * i + 1];
            X[3 * i] = x; X[3 * i + 1] = y; X[3 * i + 2] = 1.0;
            b[i] = -(x * x + y * y);
        }
        if (!linfit(m, 3, X, b, c)) {
            const double cx = -0.5 * c[0], cy = -0.5 * c[1], R = sqrt(cx * cx + cy * cy - c[2]);
            double prev = atan2(Q[1] - cy, Q[0] - cx), turn = 0.0;
            const double a0 = prev;
            for (size_t i = 1; i < m; i++) {
                const double a = atan2(Q[2 * i + 1] - cy, Q[2 * i] - cx);
                turn += remainder(a - prev, 2.0 * M_PI);
                prev = a;
            }
            if (isfinite(R) && R > 0.0 && fabs(turn) >= 1e-3 && isfinite(turn)) {
                const double sg = turn > 0.0 ? 1.0 : -1.0;     /* the tangent at the first point: */
                near_circle(a0 + sg * 0.5 * M_PI, sg / R, R * fabs(turn), &out[cnt++]);
            }
        }
    }
    return cnt;
}

/* Smooth parameters from a continuous guess (x0 = y0 = 0). u(s) = w s + q with
 * w < 0 is the same curve as (|w|, -k, -q) (sn(-u) = -sn u, dn(-u) = dn u, so
 * k sn u is unchanged): for k > 1 the clockwise loop, k < -1. For k < 1 the
 * same curve also has k >= 0: u' = -w s - q - 2K (sn, dn unchanged), used there. */
static void to_smooth(const cguess *g, el_smooth_params *p)
{
    double w = g->w, q = g->q, k = g->k;
    if (w < 0.0) {
        if (k < 1.0) q = -q - 2.0 * ellK(k);
        else { k = -k; q = -q; }
        w = -w;
    }
    if (!(w > 1e-9)) w = 1e-9;
    p->x0 = 0.0; p->y0 = 0.0; p->phi = g->phi; p->mu = w * w; p->k = k; p->q = q;
    p->length = g->L;
}

static void to_discrete(const cguess *g, size_t n, el_discrete_params *p)
{
    double h = g->L / (double)(n - 1);
    p->x0 = 0.0; p->y0 = 0.0; p->h = h; p->phi = g->phi; p->z = g->w * h; p->q = g->q; p->k = g->k;
}

/*
 * x0, y0 by (4.55) for a candidate with x0 = y0 = 0: the mean of P_i - G_i, and the rms
 * of the placed curve, its standard deviation (Welford's update), over at most
 * PLACE_POINTS of the points (every stride-th): a guess only ranks the candidates and
 * starts the fit, and evaluating six candidates at every point of a dense scan cost
 * as much as the fit itself. For the discrete model with more points than that the
 * candidate is evaluated as its continuum limit (vertex i ~ the smooth elastica with
 * u = (z/h) s + q at s = i h, the same phi, k, q; the difference is O(h^2)).
 */
enum { PLACE_POINTS = 128 };

static double place(int model, const points *p, const double *v, double *x0, double *y0,
                    const fractions *f0, double *tmp)
{
    /* every stride-th point: arc lengths in arithmetic progression where the data's are,
     * which el_smooth_eval evaluates by the addition theorems */
    const size_t n = p->n, stride = (n + PLACE_POINTS - 1) / PLACE_POINTS, m = (n - 1) / stride + 1;
    double G[2 * PLACE_POINTS], s[PLACE_POINTS], mean[2] = {0.0, 0.0}, m2 = 0.0;
    size_t idx[PLACE_POINTS];
    for (size_t j = 0; j < m; j++) idx[j] = j * stride;
    int st;
    if (model == FIT_DISCRETE && m == n) {
        fit_walk w;
        el__fit_walk_start(v, &w);
        st = el__fit_discrete_rows(v, &w, n, G, NULL, 0, tmp);
    } else if (model == FIT_DISCRETE) {
        const double vs[FIT_NP] = {0.0, 0.0, v[3], v[4] / v[2], v[6], v[5], v[2] * (double)(n - 1)};
        for (size_t j = 0; j < m; j++) s[j] = v[2] * (double)idx[j];
        st = el__fit_smooth_rows(vs, m, s, G, NULL);
    } else {
        fractions f = *f0;
        for (size_t i = 0, j = 0; i < n && j < m; i++) {
            const double t = fractions_next(&f);
            if (i == idx[j]) s[j++] = t * v[6];
        }
        st = el__fit_smooth_rows(v, m, s, G, NULL);
    }
    if (st) return HUGE_VAL;
    for (size_t j = 0; j < m; j++) {
        double P[2], d[2], delta[2];
        el__guess_point_at(p, idx[j], P);
        const double cnt = (double)(j + 1);
        for (int c = 0; c < 2; c++) {
            d[c] = P[c] - G[2 * j + c];
            delta[c] = d[c] - mean[c];
            mean[c] += delta[c] / cnt;
        }
        m2 += delta[0] * (d[0] - mean[0]) + delta[1] * (d[1] - mean[1]);
    }
    *x0 = mean[0]; *y0 = mean[1];
    const double r = sqrt(fmax(m2, 0.0) / (double)m);
    return isfinite(r) ? r : HUGE_VAL;
}

/* Smooth parameters from a continuous guess (x0 = y0 = 0): internal form (w). */
static void to_internal(int model, const cguess *g, size_t n, double *v)
{
    memset(v, 0, sizeof(double) * FIT_NP);
    if (model == FIT_DISCRETE) {
        el_discrete_params p;
        to_discrete(g, n, &p);
        const double d[FIT_NP] = {0.0, 0.0, p.h, p.phi, p.z, p.q, p.k};
        memcpy(v, d, sizeof d);
    } else {
        el_smooth_params p;
        to_smooth(g, &p);
        const double d[FIT_NP] = {0.0, 0.0, p.phi, sqrt(p.mu), p.k, p.q, p.length};
        memcpy(v, d, sizeof d);
    }
}

/* Common driver: model 0 discrete, 1 smooth. */
static int guess_run(int model, const double *xy, size_t n, int mode, void *cand, size_t cap,
                     size_t *count)
{
    if (el__fit_check_points(xy, n, 4) || !cand || cap == 0 || !count) return EL_EINVAL;
    if (mode < EL_PARAM_AUTO || mode > EL_PARAM_CHORD) return EL_EINVAL;
    el__gsl_quiet();
    points p = {xy, n, 0.0, 0.0, 1.0};
    int st = el__fit_normalisation(xy, n, &p.cx, &p.cy, &p.sc);
    if (st) return st;
    fractions f0, f;
    if ((st = fractions_start(&f0, &p, model == FIT_DISCRETE ? EL_PARAM_UNIFORM : mode, NULL))) return st;
    f = f0;
    double *tmp = malloc(sizeof(double) * FIT_WORK);
    if (!tmp) return EL_ENOMEM;
    /* few points: also the guesses from the polygon with the sides shorter than
     * MERGE_NOISE noise levels merged (reduce), both sets ranked together */
    cguess g[NCAND_MAX];
    const double merge = n <= RAW_MAX ? MERGE_NOISE * el__fit_noise_rms(xy, n, p.sc) : 0.0;
    size_t ng = guesses(&p, &f, 0.0, g);
    if (merge > 0.0) {
        f = f0;
        ng += guesses(&p, &f, merge, g + ng);
    }
    double v[NCAND_MAX][FIT_NP], rms[NCAND_MAX];
    size_t order[NCAND_MAX], nok = 0;
    for (size_t c = 0; c < ng; c++) {
        to_internal(model, &g[c], n, v[c]);
        rms[c] = place(model, &p, v[c], &v[c][0], &v[c][1], &f0, tmp);
        if (!isfinite(rms[c])) continue;
        /* insertion by rms */
        size_t j = nok++;
        while (j > 0 && rms[order[j - 1]] > rms[c]) { order[j] = order[j - 1]; j--; }
        order[j] = c;
    }
    free(tmp);
    if (nok == 0) return EL_ESINGULAR;
    size_t m = nok < cap ? nok : cap;
    if (m > CAND_OUT) m = CAND_OUT;
    double out[CAND_OUT][FIT_NP];
    for (size_t j = 0; j < m; j++) {
        for (int i = 0; i < FIT_NP; i++) out[j][i] = el__fit_denorm_param(model, i, v[order[j]][i], p.cx, p.cy, p.sc);
        /* parameters outside double's range (mu of a 1e300-sized curve underflows) */
        if (el__all_finite(out[j], FIT_NP) || !(out[j][model == FIT_DISCRETE ? 2 : 3] >= DBL_MIN)) return EL_EDOM;
    }
    for (size_t j = 0; j < m; j++) {
        const double *o = out[j];
        if (model == FIT_DISCRETE) {
            el_discrete_params *d = (el_discrete_params *)cand + j;
            d->x0 = o[0]; d->y0 = o[1]; d->h = o[2]; d->phi = o[3]; d->z = o[4]; d->q = o[5]; d->k = o[6];
        } else {
            el_smooth_params *sp = (el_smooth_params *)cand + j;
            sp->x0 = o[0]; sp->y0 = o[1]; sp->phi = o[2]; sp->mu = o[3]; sp->k = o[4]; sp->q = o[5]; sp->length = o[6];
        }
    }
    *count = m;
    return EL_OK;
}

int el_guess_discrete(const double *xy, size_t n, el_discrete_params *cand, size_t cap,
                      size_t *count)
{
    return guess_run(0, xy, n, EL_PARAM_AUTO, cand, cap, count);
}

int el_guess_smooth(const double *xy, size_t n, int mode, el_smooth_params *cand, size_t cap,
                    size_t *count)
{
    return guess_run(1, xy, n, mode, cand, cap, count);
}
