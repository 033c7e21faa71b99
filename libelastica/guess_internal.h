/* guess_internal.h: what guess.c (el_fit_fractions) and guess_spacing.c (its spacing tests)
 * share, and no other file: the points of a guess and the fractions along them. */
#ifndef EL_GUESS_INTERNAL_H
#define EL_GUESS_INTERNAL_H

#include <math.h>
#include <stddef.h>

/* guess.c and guess_spacing.c: the points of a guess, normalised on the fly; the fractions
 * t_i along them (uniform, or the chord-length parameter) one by one. */
enum { EL__GUESS_BLOCKS = 32, EL__GUESS_RAW_MAX = 40 };
typedef struct el__guess_points {
    const double *xy;
    size_t n;
    double cx, cy, sc;
} el__guess_points;

static inline void el__guess_point_at(const el__guess_points *p, size_t i, double *P)
{
    P[0] = (p->xy[2 * i] - p->cx) / p->sc;
    P[1] = (p->xy[2 * i + 1] - p->cy) / p->sc;
}

typedef struct el__guess_fractions {
    const el__guess_points *p;
    int chord;
    size_t i;
    double total, run, prev[2];
    double noise2;      /* 2 nu^2: what noise of rms nu per point adds to a side's square */
    /* chord, n > EL__GUESS_RAW_MAX: the arc length A[b] along the polygon of the
     * EL__GUESS_BLOCKS block means at its blocks' middle points ci[b], where the chord run is
     * C[b]; between them the run is mapped linearly onto A (guess.c's fractions_next); b: the interval
     * of the last point */
    size_t nb, b, ci[EL__GUESS_BLOCKS];
    double A[EL__GUESS_BLOCKS], C[EL__GUESS_BLOCKS], a0, a1;
} el__guess_fractions;

/* A side of the chord polygon, its noise taken out: the points' noise (rms nu each,
 * independent) lengthens a side d to sqrt(d^2 + 2 nu^2) on average, so on sparse noisy
 * points the plain chords gave a cluster of close points far more of the curve than it
 * spans, and the paired start bent the curve into a loop there (measured on 150 sparse
 * uneven noisy sets: seed 6 of bench_fit_sparse.py's kind). Sides shorter than the noise
 * keep a tenth of their length (the order of the points stays). */
static inline double el__guess_side(const el__guess_fractions *f, double dx, double dy)
{
    const double d2 = dx * dx + dy * dy;
    return f->noise2 > 0.0 ? sqrt(fmax(d2 - f->noise2, 0.01 * d2)) : sqrt(d2);
}

/* guess_spacing.c: the spacing tests of el_fit_fractions (EL_PARAM_AUTO, EL_PARAM_CHORD).
 * Q: the means of EL__GUESS_BLOCKS blocks of consecutive points (2 EL__GUESS_BLOCKS values),
 * n > EL__GUESS_RAW_MAX, computed once per call. */
void el__guess_block_means(const el__guess_points *p, double *Q);
/* Whether the points are evenly spaced along the curve (Q: their block means, NULL for
 * n <= EL__GUESS_RAW_MAX); *nu: the noise estimate when made, else left. */
int el__guess_evenly_spaced(const el__guess_points *p, const double *Q, double *nu);
/* The chord run mapped onto the block-mean polygon's arc (f->nb > 0). */
double el__guess_block_map(const el__guess_fractions *f, size_t b, size_t i, double run);
/* Chord fractions of many points measured along the polygon of the block means Q
 * (f->nb = 0: the plain chords). */
void el__guess_block_arcs(el__guess_fractions *f, const double *Q);

#endif
