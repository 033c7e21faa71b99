/*
 * Whether points may be paired with a discrete curve's vertices (seed 000 (4.6)), the
 * choice of distance="auto": before the fit, the points spaced evenly along one pass of
 * the data (el__fit_evenly_spaced, el__fit_retrace); after a paired fit, its points where
 * their vertices are along its polygon (el__fit_slips, el__fit_skips; el__fit_unpaired in
 * fit_restart.c refits where they are not).
 */
#include "fit_ends.h"
#include <math.h>

/* w = max(3, (n-1)/16): the run of segments or points each test averages over */
static size_t pairing_window(size_t n) { return (n - 1) / 16 > 3 ? (n - 1) / 16 : 3; }

/* Whether the points are spaced evenly along the data: the mean segment of every run
 * of w = max(3, (n-1)/16) consecutive segments within 1.3 x of each other's (a run's
 * mean evens out the noise of scanned samples taken at equal steps, not a change of
 * density or a gap). The discrete model's paired distance (seed 000 (4.6)) is meant
 * for such data (an equilateral polygon, el_resample_equilateral's, or equal steps); on
 * other points (sketched, scanned unevenly, with gaps) a vertex is not where its point
 * is, and the paired fit is far from the points (measured: 42 points of two densities,
 * noise 0.2: paired rms 12.4, orthogonal 0.15; a 175-point scan of spacing 1:6 with
 * two gaps, noise 0.15: 4.2 and 0.15). */
/* Even spacing in this sense is necessary for the pairing, not sufficient: a slow change of
 * spacing, or points at random places (every run as dense as the next), pass it, and the
 * paired fit is then judged by its points' slip along the polygon (el__fit_unpaired). */
int el__fit_evenly_spaced(const double *xy, size_t n)
{
    const size_t m = n - 1, w = pairing_window(n);
    if (m < w) return 1;
    double run = 0.0, lo = HUGE_VAL, hi = 0.0;
    for (size_t i = 0; i < m; i++) {
        run += hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]);
        if (i >= w)
            run -= hypot(xy[2 * (i - w) + 2] - xy[2 * (i - w)],
                         xy[2 * (i - w) + 3] - xy[2 * (i - w) + 1]);
        if (i + 1 >= w) { lo = fmin(lo, run); hi = fmax(hi, run); }
    }
    if (!(hi <= 1.3 * lo)) return 0;
    /* The chords of the same runs (point i to point i + w): where the points are closer
     * than their noise, every segment is mostly noise and the runs' sums are alike
     * whatever the spacing, while a run's chord is its stretch of the curve to the noise
     * of its two ends (the chord is within 3 % of the arc where a run turns by less than
     * 0.8 rad). Within 1.3 x of each other's and 4 noise levels (rms per point, el__fit_noise_rms).
     * Measured (QA23 F5): 20 000 scanned points of spacing 1:12 (the runs' chords 1:2.3),
     * noise 0.2 at a mean spacing of 0.018: the sums within 1.02 x, the points taken for
     * evenly spaced, the discrete model paired them with its vertices, and five guesses'
     * paired fits crawled 163-200 iterations each to rms 0.081 before the fit by distance
     * (927 iterations in all, 4.6 ms / 2 for evenly spaced points). */
    lo = HUGE_VAL; hi = 0.0;
    for (size_t i = 0; i + w < n; i++) {
        const double *a = xy + 2 * i, *b = a + 2 * w;
        const double c = hypot(b[0] - a[0], b[1] - a[1]);
        lo = fmin(lo, c); hi = fmax(hi, c);
        if (i + 2 * w < n) {     /* the turn from this run's chord to the next one's */
            const double ux = b[0] - a[0], uy = b[1] - a[1], vx = b[2 * w] - b[0], vy = b[2 * w + 1] - b[1];
            if (!(fabs(atan2(ux * vy - uy * vx, ux * vx + uy * vy)) < 0.8)) return 1;
        }
    }
    if (hi <= 1.3 * lo) return 1;
    double cx, cy, sc;
    if (el__fit_normalisation(xy, n, &cx, &cy, &sc)) return 1;
    /* A chord's length varies by nu (the two ends' noise along it); the largest and the
     * smallest of n - w of them by up to ~ sqrt(2 ln(n - w)) nu each way (the extremes of
     * so many normal deviates), not by a fixed 2 nu: evenly spaced points 100 x closer than
     * their noise (20 000 on an arc, noise 0.2, spacing 0.0018: runs' chords of 11 nu) were
     * taken for uneven 20 of 20 times with 4 nu, paired before (2 iterations, 30 ms; by
     * distance 33, 180 ms). At least 4 nu, as for few runs. */
    const double spread = fmax(4.0, 2.0 * sqrt(2.0 * log((double)(n - w))));
    return hi <= 1.3 * lo + spread * el__fit_noise_rms(xy, n, sc) * sc;
}

/* The first point where the data turn back on themselves and run back over a stretch (a
 * scan passed back and forth): a vertex i whose chords to the points k back and k on
 * point opposite ways (dot < 0) at every k = 1..w, w = max(3, (n-1)/16); 0 where none
 * does. Evenly spaced all the same, such points are not one pass: the paired polygon must
 * retrace them (QA18's 188 points scanned s 0 -> 12 -> 8 -> 30, noise 0.05: paired rms
 * 1.14, refitted by distance from it 0.50, length 63 for 30; the orthogonal fit 0.050;
 * the apex found in 60 of 60 draws, noise 0.02-0.1). A smooth curve's polygon turns by
 * less than 90 degrees at a vertex (k = 1); a regular polygon that turns more has k = 3's
 * chords forward again. Over the whole w only: a noise cloud (points far closer than
 * their noise) turns so at a few k near its ends (10 of bench_fit.py's 5000-point sets).
 * A dot that is NaN (products overflowing to inf - inf, coordinates ~1e154 apart) is no
 * turn, as any dot not below 0. */
size_t el__fit_retrace(const double *xy, size_t n)
{
    const size_t w = pairing_window(n);
    for (size_t i = w; i + w < n; i++) {
        size_t k = 1;
        for (; k <= w; k++) {
            const double *p = xy + 2 * i, *a = p - 2 * k, *b = p + 2 * k;
            if (!((p[0] - a[0]) * (b[0] - p[0]) + (p[1] - a[1]) * (b[1] - p[1]) < 0.0)) break;
        }
        if (k > w) return i;
    }
    return 0;
}

/* The public el__fit_retrace: the binding's check of a fit's points that run back (el.fit's
 * OrderWarning where the fit does not follow them, order.py's data_run_back) asks the fit's
 * own test, not a copy of it. */
int el_fit_turn_back(const double *xy, size_t n, size_t *first)
{
    if (!xy || !first || n < 1 || el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;
    *first = el__fit_retrace(xy, n);
    return EL_OK;
}

/* The paired fit's points slip along its polygon by more than PAIRING_SLIP times their
 * distance from it (rms of foot arc length - i h against the rms distance, beyond 1e-4 of
 * the polygon's length: a fit without noise differs from its points by the model's O(h^2)
 * along the polygon more than across): the points are not where their vertices are, and
 * pairing them pulled the polygon (the spacing test passes points whose step grows slowly,
 * or dense points at random places). Measured, paired fits and their points, noise 0.1:
 * equal steps slip 1.0-1.25 x their distance (noise-free: 3.6 x, below the floor); a step
 * growing by 5 % end to end 2.2-2.5 x (rms 0.19 where the distance to the polygon gives
 * 0.101), by 10 % 2.4 x (0.44 for 0.093, k 0.79 for 0.70), by 25 % over 20 points 1.5 x
 * (the pull moves the polygon across too: 1.22 for 0.079); 10 000 points at random places
 * 3.1 x (0.14 for 0.099). */
#define PAIRING_SLIP 1.3

/* d (NULL: not read), a free fit's distances: the noise across is then also read from their
 * point-to-point part (the rms of d_i - d_{i-1} over sqrt 2, up by 3 x its sampling error
 * 0.87 / sqrt n). The pull is smooth along the polygon: it leaves the differences, while it
 * raises the rms and lowers the slip. Points at random places denser than their noise are
 * pulled so (QA's 50 000 along 600, noise 0.2: slip 35 h, rms 25 h, the differences' 16.6 h
 * = the noise; judged by the rms they stayed paired at 1.53 x the orthogonal fit's rms from
 * 45 000 points on, where that walk, L / sqrt(6 n), nears the noise). Only where the slip
 * exceeds a segment and the rms, and not with constraints or fixed values (callers pass
 * NULL): there the curve's misfit is smooth too (a start pinned off the data: slip 0.13 h;
 * a noise-free S forced to an inflection: 1.27 h and the differences' 0.92 h for an rms of
 * 1.05 h; test_misfit's corner of two arms: 31.7 h for an rms of 60 h). */
int el__fit_slips(size_t n, double h, double rms, const double *d, const double *fs)
{
    /* in units of the segment h (slips squared in input units underflowed at 1e-160, points
     * staying paired at 5e9 x the orthogonal fit's rms, and overflowed at 1e160) */
    double su = 0.0;
    for (size_t i = 0; i < n; i++) {
        const double u = fs[i] / h - (double)i;
        su += u * u;
    }
    const double slip = sqrt(su / (double)n), least = 1e-4 * (double)(n - 1);
    if (slip > PAIRING_SLIP * (rms / h) + least) return 1;
    if (!d || !(slip > 1.0) || !(slip > rms / h)) return 0;
    double sd = 0.0;
    for (size_t i = 1; i < n; i++) {
        const double e = (d[i] - d[i - 1]) / h;
        sd += e * e;
    }
    return slip > PAIRING_SLIP * sqrt(sd / (2.0 * (double)(n - 1))) * (1.0 + 3.0 / sqrt((double)n)) + least;
}


/* The paired fit's polygon runs on past its points at an end: the stretch from vertex 0 to
 * the first foot (fs, input units), or from the last foot to vertex n - 1, longer than
 * FIT_RETRACE_PAST x the points' noise (input units, fit_ends.h) and 3 segments h. A pen that retraced an
 * end (starts a few px into the stroke, runs back to the true start, then along) passes
 * the spacing test and the retrace test (its turn within w of the end), and pairing its
 * first points with the first vertices stretches the polygon past the stroke's end where
 * no point is; the slip of those few points is diluted in the rms of all (measured, QA24
 * F9: a pixel stroke of 2101 points, noise 0.31 px, an end retrace of ~6 px: the polygon
 * 5.3 and 5.05 px past the first and last feet, 17 noise levels, slip below the gate; by
 * distance 0.73 px from every point). And 3 segments: a paired fit's polygon without noise
 * ends up to a couple of segments past its last foot (bench_fit.py's set 355, 100 points at
 * noise 3e-7: 2.02 h, refitted by distance from the paired fit as before). */

int el__fit_overruns(size_t n, double h, double noise, const double *fs)
{
    double a = HUGE_VAL, b = -HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        a = fmin(a, fs[i]);
        b = fmax(b, fs[i]);
    }
    const double L = h * (double)(n - 1), least = fmax(FIT_RETRACE_PAST * noise, 3.0 * h);
    return a > least || L - b > least;
}

/* The paired fit's points jump a vertex: the mean slip (foot arc length / h - i) of the w
 * = max(3, (n-1)/16) points from some point g on differs from the w points' before it by
 * more than PAIRING_STEP vertices and 4 x its noise sqrt(2 / w) rms / h (a point missing
 * from, or doubled in, an evenly spaced scan; the spacing test's runs move by 1 / w for
 * it, less than their noise). Only where a step of one vertex stands that far above the
 * noise: points far closer than their noise are a cloud whose feet spread otherwise (two
 * of bench_fit's 5000-point sets, rms 35 h: steps of 11 vertices, 4.1 x). Measured on
 * QA18's scans (200 points, spacing 0.15, noise 0.05, 4 x noise 0.54; 20 draws each):
 * without dropouts the largest step 0.28-0.43 vertex; with 1, 2 or 4 single-point
 * dropouts the largest 0.62-1.61, the paired fits that pass the spacing test at 1.03-1.22
 * x the orthogonal fit's rms. */
#define PAIRING_STEP 0.5

int el__fit_skips(size_t n, double h, double rms, const double *fs)
{
    const size_t w = pairing_window(n);
    const double wd = (double)w, noise = 4.0 * sqrt(2.0 / wd) * rms / h;
    if (n < 2 * w || !(noise <= 1.0)) return 0;
    double before = 0.0, after = 0.0, top = 0.0;
    for (size_t i = 0; i < w; i++) {
        before += fs[i] / h - (double)i;
        after += fs[i + w] / h - (double)(i + w);
    }
    for (size_t g = w;; g++) {      /* before: points g-w..g-1, after: g..g+w-1 */
        top = fmax(top, fabs(after - before));
        if (g + w >= n) break;
        const double ug = fs[g] / h - (double)g;
        before += ug - (fs[g - w] / h - (double)(g - w));
        after += fs[g + w] / h - (double)(g + w) - ug;
    }
    return top / wd > fmax(PAIRING_STEP, noise);
}
