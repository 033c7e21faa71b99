/*
 * The points' own noise level, without a fit: el_fit_noise (the header) and the fit's
 * stopping rule, guesses and misfit check (el__fit_noise_rms, el__fit_noise_plain).
 * GSL has no noise estimator for unevenly spaced curve samples (its gsl_stats_* give the
 * medians used here), hence these third-difference figures.
 */
#include "fit_internal.h"
#include <stdlib.h>
#include <gsl/gsl_statistics_double.h>

/* stencils at most (evenly spread), the frame's probe */
enum { NOISE_SAMPLES = 65536, FRAME_PROBE = 32 };
/* spread_noise's search of the stride k: stencils of its probes, and at least at a stride
 * taken; the chords' span of the band (SPREAD_SPAN x the figure's noise, rms per point /
 * sqrt 2, and SPREAD_ALONG x the half stride's chords), the figure's growth from the half
 * stride's taken for noise (SPREAD_GROW), the chords' shrinking that ends the search
 * (SPREAD_BACK), the probe's figure over the smaller one that has all stencils looked at
 * (SPREAD_LOOK) and their figure's that is taken (SPREAD_TAKE) */
enum { SPREAD_PROBE = 256, SPREAD_MIN = 200 };
static const double SPREAD_SPAN = 14.0, SPREAD_ALONG = 1.8, SPREAD_GROW = 1.5, SPREAD_BACK = 0.8,
                    SPREAD_LOOK = 1.1, SPREAD_TAKE = 1.25;

/* Noise level of the points (rms per point), the smaller of two estimates (both from
 * third differences, in which a smooth curve's turning cancels; second differences carry
 * its curvature, so that sparse tight loops would look noisy), each the median over at
 * most NOISE_SAMPLES stencils, evenly spread:
 *  - plain: P_{i+2} - 3P_{i+1} + 3P_i - P_{i-1} has variance 20 sigma^2 per coordinate,
 *    |.|^2 mean 40 sigma^2 = 20 rms^2 and median ln 2 of the mean (a chi-square of two
 *    degrees). A straight line cancels only at equal spacing: on uneven spacing its
 *    slope times the unevenness remains (measured: 20 points at random arc lengths, 0.1 %
 *    noise, 12x the truth in the median; with no noise, 1.8 % of the length);
 *  - in the stencil's frame (noise_frame): any spacing. */
static double noise_plain(const double *xy, size_t n, double sc, double *d)
{
    const size_t m = n - 3 < NOISE_SAMPLES ? n - 3 : NOISE_SAMPLES;
    for (size_t a = 0; a < m; a++) {
        const size_t i = 1 + a * (n - 3) / m;
        double e[2];
        for (int c = 0; c < 2; c++) {
            const double p0 = xy[2 * (i - 1) + c], p1 = xy[2 * i + c], p2 = xy[2 * (i + 1) + c], p3 = xy[2 * (i + 2) + c];
            e[c] = ((p3 - p0) - 3.0 * (p2 - p1)) / sc;
        }
        d[a] = e[0] * e[0] + e[1] * e[1];
    }
    const double med = gsl_stats_median(d, 1, m);   /* quickselect; reorders d */
    return sqrt(med / (20.0 * 0.69314718055994531));
}

/* The stencil P_{i-1} .. P_{i+2} in the frame of the chord P_{i-2} P_{i+3} (its outer
 * neighbours, so that the frame does not depend on the stencil's own noise): abscissae
 * x_j, ordinates y_j, and the third divided difference of y over x, sum_j w_j y_j with
 * w_j = 1 / prod_{l != j} (x_j - x_l) = (-1)^j V_j / V (V the Vandermonde product of the
 * four x, V_j that of the other three: no division, no overflow), cancels every quadratic
 * y(x), hence a straight line at any spacing. With isotropic noise of sigma per
 * coordinate, the y_j's noise is independent of the x_j's, so e = sum w_j y_j / |w| has
 * variance sigma^2 whatever the spacing (for the curve's, the x noise enters times the
 * slope of y(x), small: the frame is nearly the tangent); e^2 has mean sigma^2 = rms^2 / 2
 * and median 0.454936 of that (a chi-square of one degree). On equal spacing w is
 * (-1, 3, -3, 1) (measured: within 1.05x of the truth on dense curves, 0.1 % and 1 %
 * noise, uniform, random or sketched spacing; 1.07x on 20 random points, 0.1 %).
 * The stencils are of every k-th point (P_b, P_{b+k} .. P_{b+5k}, b evenly spread over the
 * n - 5k starts); with chord, d holds 2 cap doubles and *chord is the median of the chords
 * |P_{b+5k} - P_b| (normalised). */
static double noise_frame(const double *xy, size_t n, size_t k, double sc, size_t cap, double *d,
                          double *chord)
{
    const size_t span = n - 5 * k, m = span < cap ? span : cap, step = 2 * k;
    const double inv = 1.0 / sc;
    double *u2s = d + cap;
    size_t cnt = 0;
    for (size_t a = 0; a < m; a++) {
        const size_t b = a * span / m;
        const double *lo = xy + 2 * b, *o = lo + step, *hi = o + 4 * step;
        /* the frame's direction U unnormalised: e scales as |U| (y as |U|, w as |U|^3) */
        const double ux = (hi[0] - lo[0]) * inv, uy = (hi[1] - lo[1]) * inv;
        const double u2 = ux * ux + uy * uy;
        if (!(u2 > 0.0) || !isfinite(u2)) continue;
        double x[4], y[4];
        const double *q = o;
        for (int j = 0; j < 4; j++, q += step) {
            const double dx = (q[0] - o[0]) * inv, dy = (q[1] - o[1]) * inv;
            x[j] = dx * ux + dy * uy;
            y[j] = dy * ux - dx * uy;
        }
        const double d01 = x[1] - x[0], d02 = x[2] - x[0], d03 = x[3] - x[0];
        const double d12 = x[2] - x[1], d13 = x[3] - x[1], d23 = x[3] - x[2];
        /* a point repeated (a pen at rest, a scanner's duplicate) is no independent sample:
         * its copies' difference, the limit of w at coincident abscissae, is 0 */
        if ((d01 == 0.0 && y[1] == y[0]) || (d02 == 0.0 && y[2] == y[0]) || (d03 == 0.0 && y[3] == y[0]) ||
            (d12 == 0.0 && y[2] == y[1]) || (d13 == 0.0 && y[3] == y[1]) || (d23 == 0.0 && y[3] == y[2]))
            continue;
        const double w[4] = {d12 * d13 * d23, -d02 * d03 * d23, d01 * d03 * d13, -d01 * d02 * d12};
        double wmax = 0.0;
        for (int j = 0; j < 4; j++)
            if (fabs(w[j]) > wmax) wmax = fabs(w[j]);
        if (!(wmax > 0.0) || !isfinite(wmax)) continue;      /* abscissae coincident in two pairs or three */
        const double r = 1.0 / wmax;
        double num = 0.0, w2 = 0.0;
        for (int j = 0; j < 4; j++) {
            const double wj = w[j] * r;
            num += wj * y[j];
            w2 += wj * wj;
        }
        if (chord) u2s[cnt] = u2;
        d[cnt++] = num * num / (w2 * u2);
    }
    if (chord) *chord = 0.0;
    if (cnt == 0) return HUGE_VAL;
    if (chord) *chord = sqrt(gsl_stats_median(u2s, 1, cnt));
    const double med = gsl_stats_median(d, 1, cnt);
    return sqrt(2.0 * med / 0.45493642311957283);
}

/* The frame figure of every k-th point where it is the noise's and exceeds the smaller
 * figure fig SPREAD_TAKE x, else fig. Points sorted along their curve (a dense scan in curve
 * order: spacing h far below the noise sigma) lie nearly in line along it, scattered across:
 * stencils of consecutive points run across the band and see a fraction of the noise (1e5
 * points along 3 units, noise 0.05: 0.0017), plain third differences the part across alone
 * (0.57 of it). Stencils of every k-th point span the band once 5 k h is well above sigma:
 * the stride doubles (k = 2, 4, ..., SPREAD_MIN stencils at least) until their chords span
 * the band (inside it they stay ~sigma while the figure grows ~2 x per doubling; short of
 * SPREAD_SPAN the order's error along the curve still lifts the figure, 1.1-1.4 x at chords
 * of 3-6 sigma in el.curve_order's) and the figure has stopped growing (a curve's cubic term
 * grows 8 x, pure noise's is stable; noise correlated from point to point, a polygon
 * resampled densely along noisy points, grows until the stride passes its correlation).
 * Each stride is judged by a probe of SPREAD_PROBE stencils. Measured (noise 0.05, spacing
 * 1/100 .. 2 x it, 1000 .. 1e5 points, in their order, sorted by a noisy key or in
 * el.curve_order): 0.90-1.10 x the noise, 0.85-1.15 at 4000 points and spacing 1/100 (the
 * stride taken, 256, leaves few stencils apart); given order, where the plain figure is the
 * noise's, no stride's is taken (bench_fit.py's 504 curves: the same figures, but for 12
 * noise-free 5000-point sets that the every (n / 1000)-th point's check took their curve's
 * cubic term at for noise, 128 x their figure now; their fits unchanged). */
static double spread_noise(const double *xy, size_t n, double sc, double fig, double *d)
{
    double f0, c0, f1, c1;
    if (n < 10 + SPREAD_MIN) return fig;
    f0 = noise_frame(xy, n, 1, sc, SPREAD_PROBE, d, &c0);
    for (size_t k = 2; 5 * k + SPREAD_MIN <= n; k *= 2, f0 = f1, c0 = c1) {
        f1 = noise_frame(xy, n, k, sc, SPREAD_PROBE, d, &c1);
        if (!(c1 >= SPREAD_BACK * c0)) return fig;      /* past a turn: a loop's, no band's */
        const int spans = c1 >= SPREAD_ALONG * c0 && c1 >= SPREAD_SPAN * 0.70710678118654752 * f1;
        if (!(spans && f1 < SPREAD_GROW * f0)) continue;
        if (!(f1 > SPREAD_LOOK * fig)) return fig;
        const double wide = noise_frame(xy, n, k, sc, NOISE_SAMPLES, d, NULL);
        return wide > SPREAD_TAKE * fig && isfinite(wide) ? wide : fig;
    }
    return fig;
}

/* The smaller figure (or spread_noise's), d the stencils' buffer (NOISE_SAMPLES or n - 3
 * doubles, 2 SPREAD_PROBE at least). */
static double noise_rms(const double *xy, size_t n, double sc, double *d)
{
    const double plain = noise_plain(xy, n, sc, d);
    double frame = n >= 6 ? noise_frame(xy, n, 1, sc, FRAME_PROBE, d, NULL) : HUGE_VAL;
    /* beyond the probe's FRAME_PROBE stencils all of them only where the probe is below half
     * of plain: equally spaced data keep the plain figure to the bit at the probe's cost
     * (report_drv.c's 42 1000-point fits: +0.2 % instructions; all stencils: +3.8 %) */
    if (n - 5 > FRAME_PROBE)
        frame = frame < 0.5 * plain ? noise_frame(xy, n, 1, sc, NOISE_SAMPLES, d, NULL) : HUGE_VAL;
    return spread_noise(xy, n, sc, fmin(plain, frame), d);
}

/* One of the figures (plain alone, or as noise_rms picks) with its stencils' buffer */
static int noise_figure(const double *xy, size_t n, double sc, int plain_only, double *figure)
{
    const size_t m = n - 3 < NOISE_SAMPLES ? n - 3 : NOISE_SAMPLES;
    double *d = malloc(sizeof(double) * (m > 2 * SPREAD_PROBE ? m : 2 * SPREAD_PROBE));
    if (!d) return EL_ENOMEM;
    *figure = plain_only ? noise_plain(xy, n, sc, d) : noise_rms(xy, n, sc, d);
    free(d);
    return EL_OK;
}

double el__fit_noise_rms(const double *xy, size_t n, double sc)
{
    double nu = 0.0;        /* 0 also without memory */
    if (n >= 4) noise_figure(xy, n, sc, 0, &nu);
    return nu;
}

/* The figure as a distance to the curve: its normal part, 1/sqrt(2) of the rms per point. */
int el_fit_noise(const double *xy, size_t n, double *noise)
{
    double cx, cy, sc, nu;
    int st;
    if (el__fit_check_points(xy, n, 4) || !noise) return EL_EINVAL;
    if ((st = el__fit_normalisation(xy, n, &cx, &cy, &sc))) return st;
    if ((st = noise_figure(xy, n, sc, 0, &nu))) return st;
    *noise = nu * sc * 0.70710678118654752;
    return EL_OK;
}

/* The plain figure alone (fit.c's stop rule for a constrained fit). */
double el__fit_noise_plain(const double *xy, size_t n, double sc)
{
    double plain = 0.0;
    if (n >= 4) noise_figure(xy, n, sc, 1, &plain);
    return plain;
}
