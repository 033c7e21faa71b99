/*
 * The spacing tests of the fractions t_i (guess.c's fractions_start, el_fit_fractions):
 * whether points are evenly spaced along the curve (EL_PARAM_AUTO), and the chord
 * fractions of many points measured along the polygon of their block means
 * (EL_PARAM_CHORD), noise-robust for dense uneven scans. The block means are computed
 * once per call (el__guess_block_means) and handed to both.
 */
#include "fit_internal.h"
#include "guess_internal.h"
#include <math.h>

enum { BLOCKS = EL__GUESS_BLOCKS, RAW_MAX = EL__GUESS_RAW_MAX };
typedef el__guess_points points;
typedef el__guess_fractions fractions;

/* The means of BLOCKS blocks of consecutive points (n > RAW_MAX), Q: 2 BLOCKS. */
void el__guess_block_means(const points *p, double *Q)
{
    const size_t n = p->n;
    for (size_t b = 0; b < BLOCKS; b++) {
        const size_t lo = b * n / BLOCKS, hi = (b + 1) * n / BLOCKS;
        double x = 0, y = 0, P[2];
        for (size_t i = lo; i < hi; i++) { el__guess_point_at(p, i, P); x += P[0]; y += P[1]; }
        Q[2 * b] = x / (double)(hi - lo);
        Q[2 * b + 1] = y / (double)(hi - lo);
    }
}

/* Sides of the polygon of the m vertices Q (the block means, or the points for few
 * points): the coefficient of variation of their lengths. */
static double side_cv(const double *Q, size_t m)
{
    double sum = 0, sum2 = 0;
    for (size_t b = 1; b < m; b++) {
        const double d = hypot(Q[2 * b] - Q[2 * b - 2], Q[2 * b + 1] - Q[2 * b - 1]);
        sum += d; sum2 += d * d;
    }
    double mean = sum / (double)(m - 1), var = sum2 / (double)(m - 1) - mean * mean;
    return mean > 0 ? sqrt(fmax(var, 0.0)) / mean : HUGE_VAL;
}

/* Whether the polygon of the block means Q (BLOCKS) turns by less than 0.3 rad at every
 * vertex: the means then lie along the curve (a block's mean is off its arc by ~ its
 * chord x its turn / 8) and the polygon's sides measure the arc between them to ~ 0.4 %. */
static int follows_curve(const double *Q)
{
    for (size_t b = 1; b + 1 < BLOCKS; b++) {
        const double ax = Q[2 * b] - Q[2 * b - 2], ay = Q[2 * b + 1] - Q[2 * b - 1];
        const double bx = Q[2 * b + 2] - Q[2 * b], by = Q[2 * b + 3] - Q[2 * b + 1];
        if (!(fabs(atan2(ax * by - ay * bx, ax * bx + ay * by)) < 0.3)) return 0;
    }
    return 1;
}

/* Whether the points are evenly spaced along the curve (the uniform fractions), for
 * EL_PARAM_AUTO: the sides of the polygon of block means (side_cv) of equal
 * length but for the noise nu of the points (rms, normalised). A side between the means of
 * two blocks of n / BLOCKS points varies by nu sqrt(BLOCKS / n) from the noise alone; the
 * sides may vary by 3 x that and 5 % more. Few points (n <= RAW_MAX: the points
 * themselves, whose sides vary by their noise) as before: a coefficient of variation of
 * 0.5 at most. The old test, 0.5 for every n, took scanner-density points (the spacing
 * 1:2 between the blocks, 1:12 between points; QA23 F5) for evenly spaced ones: their
 * uniform fractions were 7.7 % of the length off, the paired start of the fit crawled
 * 137-200 iterations to a curve far from the points and the fit from it 200 more
 * (20 000 points, noise 0.2: 234 iterations, 4 from evenly spaced ones). Only where the
 * block means follow the curve (follows_curve): the means of blocks that turn far
 * (the suite's loops of k up to 30, 100 points: 3 a block) are spaced by the curvature as
 * much as by the points (bench_fit.py's noise-free sets: 22 of 84 then chord, up to 391
 * iterations for 4). */
int el__guess_evenly_spaced(const points *p, const double *Q, double *nu)
{
    const size_t n = p->n;
    if (n <= RAW_MAX) {
        double R[2 * RAW_MAX];
        for (size_t i = 0; i < n; i++) el__guess_point_at(p, i, R + 2 * i);
        return side_cv(R, n) <= 0.5;
    }
    if (!follows_curve(Q)) return side_cv(Q, BLOCKS) <= 0.5;
    double r[BLOCKS], sum = 0.0, sum2 = 0.0, len = 0.0;
    /* each side per point between the blocks' middles (blocks of n / BLOCKS points differ
     * by one point: 50 points, blocks of 1 and 2, the sides 1 and 1.5 steps) */
    for (size_t b = 1; b < BLOCKS; b++) {
        const double side = hypot(Q[2 * b] - Q[2 * b - 2], Q[2 * b + 1] - Q[2 * b - 1]);
        const double gap = 0.5 * (double)((b + 1) * n / BLOCKS - (b - 1) * n / BLOCKS);
        r[b] = side / gap;
        len += side;
        sum += r[b];
    }
    const double mean = sum / (BLOCKS - 1);
    for (size_t b = 1; b < BLOCKS; b++) sum2 += (r[b] - mean) * (r[b] - mean);
    const double cvr = mean > 0.0 ? sqrt(sum2 / (BLOCKS - 1)) / mean : HUGE_VAL;
    if (cvr <= 0.05) return 1;
    *nu = el__fit_noise_rms(p->xy, n, p->sc);      /* fractions_start's, estimated once */
    return cvr <= 0.05 + 3.0 * *nu * sqrt((double)BLOCKS / (double)n) / (len / (BLOCKS - 1));
}

/* The chord run mapped onto the block-mean polygon's arc: between the middle points of
 * blocks b and b + 1 linearly in the run (in the index where the run does not advance),
 * beyond the first and last middle points by the nearest interval's ratio. */
double el__guess_block_map(const fractions *f, size_t b, size_t i, double run)
{
    const double dC = f->C[b + 1] - f->C[b], dA = f->A[b + 1] - f->A[b];
    if (dC > 0.0) return f->A[b] + dA * (run - f->C[b]) / dC;
    const double di = (double)f->ci[b + 1] - (double)f->ci[b];
    return f->A[b] + dA * ((double)i - (double)f->ci[b]) / di;
}

/* Chord fractions of many points (n > RAW_MAX) measured along the polygon of the
 * BLOCKS block means, the points' own chords only sharing each stretch between two
 * blocks' middles out: chords between points closer than their noise are mostly noise
 * (side() keeps a tenth of such a side), and their sum says little of the arc between
 * two places of the curve; the block means are sqrt(n / BLOCKS) times less noisy
 * (measured: 20 000 scanned points of spacing 1:12, noise 0.2 and 11 x their mean
 * spacing: the plain chords 4.7 % of the length off the true fractions at most, 262
 * iterations of the fit; along the block means 0.3 %, 17). */
void el__guess_block_arcs(fractions *f, const double *Q)
{
    const points *p = f->p;
    const size_t n = p->n;
    double P[2], R[2], run = 0.0;
    if (!follows_curve(Q)) return;      /* the plain chords */
    f->nb = BLOCKS;
    for (size_t b = 0; b < BLOCKS; b++) {
        f->ci[b] = (b * n / BLOCKS + (b + 1) * n / BLOCKS - 1) / 2;
        f->A[b] = b ? f->A[b - 1] + hypot(Q[2 * b] - Q[2 * b - 2], Q[2 * b + 1] - Q[2 * b - 1]) : 0.0;
    }
    el__guess_point_at(p, 0, R);
    for (size_t i = 0, b = 0; i < n && b < BLOCKS; i++) {
        el__guess_point_at(p, i, P);
        if (i > 0) run += el__guess_side(f, P[0] - R[0], P[1] - R[1]);
        R[0] = P[0]; R[1] = P[1];
        while (b < BLOCKS && f->ci[b] == i) f->C[b++] = run;
    }
    f->a0 = el__guess_block_map(f, 0, 0, 0.0);
    f->a1 = el__guess_block_map(f, BLOCKS - 2, n - 1, f->total);
    if (!(f->a1 > f->a0)) f->nb = 0;     /* every block mean alike: the plain chords */
}
