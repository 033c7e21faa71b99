/*
 * The points' own noise level, without a fit: el_fit_noise, el_fit_noise_quick (the
 * header) and the fit's stopping rule, guesses and misfit check (el__fit_noise_rms,
 * el__fit_noise_plain).
 * GSL has no noise estimator for unevenly spaced curve samples (its gsl_stats_* give the
 * medians used here), hence these third-difference figures.
 */
#include "fit_internal.h"
#include <float.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_statistics_double.h>

/* stencils at most (evenly spread), the frame's probe, every k-th point's check (noise_rms) */
enum { NOISE_SAMPLES = 65536, FRAME_PROBE = 32, SPREAD_POINTS = 1000, SPREAD_CONFIRM = 2 };
/* noise_rms's sorted-points test: every k-th point's figure over the plain one, and the
 * every 2k-th's over the k-th's */
static const double SPREAD_SORTED = 1.4, SPREAD_SAME = 2.0;
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
 * One stencil: P_b, P_{b+k} .. P_{b+5k} from lo = P_b, step = 2 k doubles; e^2 in *e2 and
 * the chord's |U|^2 (normalised) in *u2; 0 where it is no sample (a repeated point,
 * coincident abscissae). */
EL__INLINE int frame_stencil(const double *lo, size_t step, double inv, double *e2, double *u2)
{
    const double *o = lo + step, *hi = o + 4 * step;
    /* the frame's direction U unnormalised: e scales as |U| (y as |U|, w as |U|^3) */
    const double ux = (hi[0] - lo[0]) * inv, uy = (hi[1] - lo[1]) * inv;
    *u2 = ux * ux + uy * uy;
    if (!(*u2 > 0.0) || !isfinite(*u2)) return 0;
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
        return 0;
    const double w[4] = {d12 * d13 * d23, -d02 * d03 * d23, d01 * d03 * d13, -d01 * d02 * d12};
    double wmax = 0.0;
    for (int j = 0; j < 4; j++)
        if (fabs(w[j]) > wmax) wmax = fabs(w[j]);
    if (!(wmax > 0.0) || !isfinite(wmax)) return 0;      /* abscissae coincident in two pairs or three */
    const double r = 1.0 / wmax;
    double num = 0.0, w2 = 0.0;
    for (int j = 0; j < 4; j++) {
        const double wj = w[j] * r;
        num += wj * y[j];
        w2 += wj * wj;
    }
    *e2 = num * num / (w2 * *u2);
    return 1;
}

/* The figure from d's cnt stencils (HUGE_VAL: none). */
static double frame_figure(double *d, size_t cnt)
{
    if (cnt == 0) return HUGE_VAL;
    const double med = gsl_stats_median(d, 1, cnt);
    return sqrt(2.0 * med / 0.45493642311957283);
}

/* The frame figure of n points that are every k-th of xy (point i at xy + 2 k i). */
static double noise_frame(const double *xy, size_t n, size_t k, double sc, size_t cap, double *d)
{
    const size_t span = n - 5, m = span < cap ? span : cap, step = 2 * k;
    const double inv = 1.0 / sc;
    size_t cnt = 0;
    double u2;
    for (size_t a = 0; a < m; a++) {
        const size_t i = 2 + a * span / m;
        cnt += frame_stencil(xy + step * (i - 2), step, inv, d + cnt, &u2);
    }
    return frame_figure(d, cnt);
}

/* The frame figure of stencils of every k-th point from every start b (P_b .. P_{b+5k}, up
 * to cap starts evenly spread over the n - 5k), with *chord (where asked) the median of their
 * chords |P_{b+5k} - P_b| (normalised); d holds 2 min(n - 5k, cap) doubles. */
static double noise_stride(const double *xy, size_t n, size_t k, double sc, size_t cap, double *d,
                           double *chord)
{
    const size_t span = n - 5 * k, m = span < cap ? span : cap;
    const double inv = 1.0 / sc;
    double *u2s = d + m;
    size_t cnt = 0;
    for (size_t a = 0; a < m; a++) {
        const size_t b = a * span / m;
        if (frame_stencil(xy + 2 * b, 2 * k, inv, d + cnt, u2s + cnt)) cnt++;
    }
    if (chord) *chord = cnt ? sqrt(gsl_stats_median(u2s, 1, cnt)) : 0.0;
    return frame_figure(d, cnt);
}

/* The smaller figure, d the stencils' buffer (NOISE_SAMPLES or n - 3 doubles); local: that
 * of consecutive points alone (*small either way), without the check of every k-th point
 * below. */
static double noise_rms(const double *xy, size_t n, double sc, double *d, int local, double *small)
{
    const double plain = noise_plain(xy, n, sc, d);
    double frame = n >= 6 ? noise_frame(xy, n, 1, sc, FRAME_PROBE, d) : HUGE_VAL;
    /* beyond the probe's FRAME_PROBE stencils all of them only where the probe is below half
     * of plain: equally spaced data keep the plain figure to the bit at the probe's cost
     * (report_drv.c's 42 1000-point fits: +0.2 % instructions; all stencils: +3.8 %) */
    if (n - 5 > FRAME_PROBE)
        frame = frame < 0.5 * plain ? noise_frame(xy, n, 1, sc, NOISE_SAMPLES, d) : HUGE_VAL;
    *small = fmin(plain, frame);
    if (local) return *small;
    /* points sorted along their curve (a dense scan in curve order, the spacing far below
     * the noise) lie nearly in line along it, scattered across: each stencil's chord runs
     * across the band, its cubic along the scatter, and the frame sees a fraction of the
     * noise (1e5 points, noise 0.05: 0.0014). The stencils of every k-th point span the
     * band: where their figure exceeds the plain one and SPREAD_CONFIRM x the frame's, it
     * is taken (noise-free curves: far below the plain figure; noisy uneven scans: about
     * the frame's). Less dense (4e3 and 1e4 points there: spacing 0.5 and 0.2 x the noise)
     * the frame sees most of the noise and stays above half the plain figure, which sees
     * its part across alone: a chi-square of one degree read as two, sqrt(0.455 / 1.386) =
     * 0.57 of it. So the figure of every k-th point is also taken where it exceeds the
     * plain one SPREAD_SORTED x and is noise, the same at every 2k-th point (a smooth
     * curve's cubic term grows 8 x). Measured on the 504-curve suite's 5000-point sets
     * (noise 0.1 and 1 %): in their order the k-th points' figure is 0.93-1.18 x the plain
     * one; in curve order, where taken, 1.62-2.38 x, the 2k-th's 0.80-1.43 x the k-th's;
     * noise-free, the 2k-th's 7.9-8.1 x. A polygon resampled densely along noisy points
     * (noise correlated from vertex to vertex, which third differences cancel) is taken
     * too: 4164 vertices at noise 0.5, 0.035 -> 0.34. k = n / SPREAD_POINTS, read in place. */
    if (n >= 2 * SPREAD_POINTS) {
        const size_t k = n / SPREAD_POINTS;
        const double wide = noise_frame(xy, n / k, k, sc, NOISE_SAMPLES, d);
        if (frame < plain && wide > SPREAD_CONFIRM * frame && wide > plain) return wide;
        if (wide > SPREAD_SORTED * plain &&
            noise_frame(xy, n / (2 * k), 2 * k, sc, NOISE_SAMPLES, d) < SPREAD_SAME * wide)
            return wide;
    }
    return fmin(plain, frame);
}

/* The figure of stencils of every k-th point where their chords span the noise band: that
 * figure where it exceeds small, the smaller figure of consecutive points, SPREAD_TAKE x,
 * else fig (noise_rms's); el_fit_noise's (the fit's own uses, el__fit_noise_rms, keep fig:
 * a figure too low there only lets a fit run on). Points sorted along their curve (a dense
 * scan in curve order: spacing h far below the noise sigma) lie nearly in line along it,
 * scattered across: stencils of consecutive points run across the band and see a fraction
 * of the noise (1e5 points along 3 units, noise 0.05: 0.0013), the plain figure the part
 * across alone (0.57 of it), and noise_rms's every (n / 1000)-th point is still inside the
 * band on a short curve. Stencils of every k-th point span it once 5 k h is well above
 * sigma: the stride doubles (k = 2, 4, ..., SPREAD_MIN stencils at least) until their
 * chords span the band (inside it they stay ~sigma while the figure grows ~2 x per
 * doubling; short of SPREAD_SPAN the order's error along the curve still lifts the figure,
 * 1.1-1.4 x in el.curve_order's) and the figure has stopped growing (a curve's cubic term
 * grows 8 x, pure noise's is stable; noise correlated from point to point, a polygon
 * resampled densely along noisy points, grows until the stride passes its correlation).
 * Each stride is judged by a probe of SPREAD_PROBE stencils (545802a's search). */
static double spread_noise(const double *xy, size_t n, double sc, double small, double fig, double *d)
{
    double f0, c0, f1, c1;
    if (n < 10 + SPREAD_MIN) return fig;
    f0 = noise_stride(xy, n, 1, sc, SPREAD_PROBE, d, &c0);
    for (size_t k = 2; 5 * k + SPREAD_MIN <= n; k *= 2, f0 = f1, c0 = c1) {
        f1 = noise_stride(xy, n, k, sc, SPREAD_PROBE, d, &c1);
        if (!(c1 >= SPREAD_BACK * c0)) return fig;      /* past a turn: a loop's, no band's */
        const int spans = c1 >= SPREAD_ALONG * c0 && c1 >= SPREAD_SPAN * 0.70710678118654752 * f1;
        if (!(spans && f1 < SPREAD_GROW * f0)) continue;
        if (!(f1 > SPREAD_LOOK * small)) return fig;
        const double wide = noise_stride(xy, n, k, sc, NOISE_SAMPLES, d, NULL);
        return wide > SPREAD_TAKE * small && isfinite(wide) ? wide : fig;
    }
    return fig;
}

/* the fit's figure (noise_rms), consecutive points' alone, the plain one, el_fit_noise's */
enum { FIGURE_FIT, FIGURE_LOCAL, FIGURE_PLAIN, FIGURE_SPREAD };

/* Repeated points (a scanner writing every point twice, a pen at rest) carry no noise: a
 * stencil holding two copies reads the spacing (the plain one: (P_3 - P_0) - 3 (P_2 - P_1)
 * with P_1 = P_2 is two spacings) or nothing (the frame's skips it), so that every point
 * twice read 0.4 x the spacing, not the noise (QA20: 50 exact points 1.1e-4 -> 0.031).
 * The figures see each run of repeats once: a point is dropped where both its coordinates
 * lie within REPEAT_REL x the scale sc (of the rms radius; a scan's spacing is far above) plus
 * REPEAT_ULPS rounding units of the first point's |x| + |y| (copies that went through
 * arithmetic far from the origin, where the offset dwarfs the extent and so every
 * coordinate; one bound: 11 instructions a point) of the last point kept. The stencils'
 * neighbours are the points' order (every k-th point), not their distance: copies apart in
 * the order are no stencil's neighbours but where the order comes back (the frame skips
 * such a stencil). */
static const double REPEAT_REL = 1e-12, REPEAT_ULPS = 4.0 * DBL_EPSILON;

static int repeats(const double *p, const double *q, double tol)
{
    return fabs(p[0] - q[0]) <= tol && fabs(p[1] - q[1]) <= tol;
}

/* The repeats' bound of points xy of scale sc */
static double repeat_tol(const double *xy, double sc)
{
    return REPEAT_REL * sc + REPEAT_ULPS * (fabs(xy[0]) + fabs(xy[1]));
}

/* The first point that repeats the one before it; n where none does. */
static size_t first_repeat(const double *xy, size_t n, double tol)
{
    size_t i = 1;
    while (i < n && !repeats(xy + 2 * i, xy + 2 * (i - 1), tol)) i++;
    return i;
}

/* xy's points after i (i: first_repeat's, < n) that repeat no point kept before them,
 * written into k after its first i points (xy's, already there): the count kept. k may be
 * xy itself (a point is written at or before its own place, after it was read). */
static size_t drop_repeats(const double *xy, size_t n, size_t i, double tol, double *k)
{
    size_t c = i;
    for (i++; i < n; i++)
        if (!repeats(xy + 2 * i, k + 2 * (c - 1), tol)) {
            k[2 * c] = xy[2 * i];
            k[2 * c + 1] = xy[2 * i + 1];
            c++;
        }
    return c;
}

/* The points with runs of repeats kept once: *m of them; *kept NULL where none is dropped (xy
 * itself, the figures bit-identical to before), else a copy to free. EL_ENOMEM. */
static int distinct_points(const double *xy, size_t n, double sc, size_t *m, double **kept)
{
    const double tol = repeat_tol(xy, sc);
    const size_t i = first_repeat(xy, n, tol);
    *m = n;
    *kept = NULL;
    if (i == n) return EL_OK;
    double *k = malloc(sizeof(double) * 2 * n);
    if (!k) return EL_ENOMEM;
    memcpy(k, xy, sizeof(double) * 2 * i);
    *m = drop_repeats(xy, n, i, tol, k);
    *kept = k;
    return EL_OK;
}

int el_fit_distinct(const double *xy, size_t n, double *out, size_t *m)
{
    double cx, cy, sc;
    if (el__fit_check_points(xy, n, 1) || !out || !m) return EL_EINVAL;
    const int st = el__fit_normalisation(xy, n, &cx, &cy, &sc);
    if (st == EL_ESINGULAR) {       /* all equal to rounding: all repeats of the first */
        out[0] = xy[0];
        out[1] = xy[1];
        *m = 1;
        return EL_OK;
    }
    if (st) return st;
    const double tol = repeat_tol(xy, sc);
    const size_t i = first_repeat(xy, n, tol);
    if (out != xy) memcpy(out, xy, sizeof(double) * 2 * i);
    *m = i == n ? n : drop_repeats(xy, n, i, tol, out);
    return EL_OK;
}

/* One of the figures with its stencils' buffer */
static int noise_figure(const double *xy, size_t n, double sc, int which, double *figure)
{
    const size_t m = n - 3 < NOISE_SAMPLES ? n - 3 : NOISE_SAMPLES;
    const size_t need = which == FIGURE_SPREAD ? 2 * (m > SPREAD_PROBE ? m : SPREAD_PROBE) : m;
    double *d = malloc(sizeof(double) * need), small;
    if (!d) return EL_ENOMEM;
    if (which == FIGURE_PLAIN)
        *figure = noise_plain(xy, n, sc, d);
    else
        *figure = noise_rms(xy, n, sc, d, which == FIGURE_LOCAL, &small);
    if (which == FIGURE_SPREAD) *figure = spread_noise(xy, n, sc, small, *figure, d);
    free(d);
    return EL_OK;
}

/* A figure of the distinct points (distinct_points) in units of sc: 0 for fewer than 4, and
 * also without memory. */
static double distinct_figure(const double *xy, size_t n, double sc, int which)
{
    double nu = 0.0, *kept;
    size_t m;
    if (n < 4 || distinct_points(xy, n, sc, &m, &kept)) return nu;
    if (m >= 4) noise_figure(kept ? kept : xy, m, sc, which, &nu);
    free(kept);
    return nu;
}

double el__fit_noise_rms(const double *xy, size_t n, double sc)
{
    return distinct_figure(xy, n, sc, FIGURE_FIT);
}

/* The figure as a distance to the curve: its normal part, 1/sqrt(2) of the rms per point. */
static int public_noise(const double *xy, size_t n, int which, double *noise)
{
    double cx, cy, sc, nu, *kept;
    size_t m;
    int st;
    if (el__fit_check_points(xy, n, 4) || !noise) return EL_EINVAL;
    if ((st = el__fit_normalisation(xy, n, &cx, &cy, &sc))) return st;
    /* repeats seen once, and the scale of the points kept: the figure of the set without them */
    if ((st = distinct_points(xy, n, sc, &m, &kept))) return st;
    if (kept) {
        st = m < 4 ? EL_EINVAL : el__fit_normalisation(kept, m, &cx, &cy, &sc);
        if (!st) st = noise_figure(kept, m, sc, which, &nu);
        free(kept);
    } else {
        st = noise_figure(xy, n, sc, which, &nu);
    }
    if (st) return st;
    const double figure = nu * sc * 0.70710678118654752;
    if (!isfinite(figure)) return EL_EDOM;      /* points spread near DBL_MAX: it overflows */
    *noise = figure;
    return EL_OK;
}

int el_fit_noise(const double *xy, size_t n, double *noise)
{
    return public_noise(xy, n, FIGURE_SPREAD, noise);
}

int el_fit_noise_quick(const double *xy, size_t n, double *noise)
{
    return public_noise(xy, n, FIGURE_LOCAL, noise);
}

/* The plain figure alone (fit.c's stop rule for a constrained fit). */
double el__fit_noise_plain(const double *xy, size_t n, double sc)
{
    return distinct_figure(xy, n, sc, FIGURE_PLAIN);
}
