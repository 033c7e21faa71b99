/*
 * Internal declarations of the length mode's three files:
 *   hermite_length.c        the search: the sigma range, the seed lines (tension solutions
 *                           that start the tracing) and the traces from each seed;
 *   hermite_length_trace.c  the tracing of a curve of tension solutions (C) from a seed and
 *                           the solutions of the given length on it;
 *   hermite_length_chart.c  the points of C in the charts of the curvature data and the
 *                           passage from one chart to another.
 */
#ifndef EL_HERMITE_LENGTH_INTERNAL_H
#define EL_HERMITE_LENGTH_INTERNAL_H

#include "hermite_internal.h"

/* A point of C in a chart (u, v; b): tracer coordinates (U, V) = (asinh u, asinh v),
 * t = asinh(sigma), the state, and the gradients of f, L and t in (U, V). In the
 * separatrix chart (chart = CHART_SEP over the chart base, on the side side of k = 1)
 * the base coordinate number fi is replaced by y / SEP_SCALE, y = ln|(|F| - sigma)|,
 * and w holds its value. */
#define CHART_SEP 3
#define SEP_SCALE 8.0
typedef struct {
    int chart, base, fi, side, b;
    double U, V, w, sigma, t;
    hstate st;
    double fg[2], Lg[2], tg[2], sg[2];   /* sg: gradient of |F| - sigma */
    double wg[2];                        /* separatrix chart: gradient of w */
} cpt;

/* A seed line: its seeds end before seed number end (they follow the line before's),
 * their t within [tlo, thi] (t of a seed in case 3 or a separatrix chart is asinh of
 * its state's sigma, within rounding of the line's) */
typedef struct {
    int end;
    double tlo, thi;
} seed_line;

typedef struct {
    const hprob *pr;
    double Lt, tlo, thi, thi_trace;   /* t = asinh(sigma): seed lines in [tlo, thi]; traces end past thi_trace with L < Lt */
    double thi_lines;                 /* the lines below the top one are placed over [tlo, thi_lines] (seeds) */
    double thi_bound;                 /* and past thi_bound (the sigma bound, sigma_range) whatever L */
    cpt *seed;
    int nseed;
    seed_line *line;   /* the seed lines in order (nline) */
    int nline;
    char *visited;
    long evals, max_evals;
    double long_curves;   /* a trace ends where L passes long_curves Lt, increasing */
    double line_power;    /* the seed lines' placement (seeds) */
    int lean_seeds;       /* seed lines by el__hermite_seed_tension (else el__hermite_solve_tension) */
    int retrace;          /* follow a trace through seeds other traces visited (step_events) */
    int newton_seeds;     /* every seed line crossing by Newton (seed_by_interpolation's plain counterpart) */
    int chord_start;      /* the crossings' Newton from the chord (hermite_start's plain counterpart) */
    double line_sep;      /* the seed lines' separatrix pieces above this sigma (LINE_SEP_SIGMA) */
    hrootlist *out;
} tracer;

/* Follow C from seed number origin in the direction dir (+-1 along its tangent): its
 * solutions (L = Lt) into T->out, the seeds it passes marked visited
 * (hermite_length_trace.c). */
int el__hlen_trace(tracer *T, int origin, double dir);

/* el__hermite_solve_length with every trace followed through the seeds other traces
 * visited (step_events' plain counterpart, for test_hermite_length.c) */
int el__hlen_solve_retracing(hprob *pr, double Lt, int nl, int ns, hrootlist *out);
/* el__hermite_solve_length with every seed line crossing matched to its seed by Newton
 * (seed_by_interpolation's plain counterpart, for test_hermite_length.c) */
int el__hlen_solve_newton_seeds(hprob *pr, double Lt, int nl, int ns, hrootlist *out);
/* el__hermite_solve_length with the Newton of every L = Lt crossing started on the step's
 * chord (hermite_start's plain counterpart, for test_hermite_length.c) */
int el__hlen_solve_chord_start(hprob *pr, double Lt, int nl, int ns, hrootlist *out);

/* el__hermite_solve_length with the seed lines' separatrix pieces above SEP_SIGMA, as the
 * tension mode's (LINE_SEP_SIGMA's plain counterpart, for test_hermite_length.c) */
int el__hlen_solve_line_pieces(hprob *pr, double Lt, int nl, int ns, hrootlist *out);

/* B(d) of the length mode's sigma range: every point of C with length L > 1 and sigma > 0 has
 * sigma (L - 1)^2 <= B(d), d the turn between the normalised problem's end tangents
 * (derivation in hermite_length.c; at most HLEN_SIGMA_E2, at d = 0). */
double el__hlen_sigma_bound(const hprob *pr);

/* sinh to a few ulps, faster than libm's (the tracer's coordinates are asinh of the chart's) */
double el__hlen_sinh(double x);
/* hypot(a, b), faster than libm's */
double el__hlen_norm(double a, double b);

/* The point (U, V) in the chart of `like` (chart, base, fi, side, b; its w the separatrix
 * chart's starting guess), into *p (undefined where it fails); counts one evaluation
 * (EL_EMAXITER past the limit). */
int el__hlen_eval(tracer *T, const cpt *like, double U, double V, cpt *p);
/* p re-expressed in its better conditioned chart (same state; unchanged where it is). */
int el__hlen_rechart(tracer *T, cpt *p);
/* Same point of the curvature-data surface (tension, kappa0, kappa0'). */
int el__hlen_same_hstate(double s1, const hstate *a, double s2, const hstate *b);
int el__hlen_same_state(const cpt *a, const cpt *b);
/* Same chart (and branch, side). */
int el__hlen_same_chart(const cpt *a, const cpt *b);
/* The point p in its other charts, k = 0 .. NALT - 1 (EL_OK where chart k gives p's state). */
#define NALT 5
int el__hlen_alt_chart(tracer *T, const cpt *p, int k, cpt *alt);
/* p's coordinates in the chart of q (for orienting q's tangent). */
void el__hlen_coords_in(const hprob *pr, const cpt *p, const cpt *q, double *U, double *V);
/* The point of C of a tension root r (tension sigma) in the chart of its kind. */
int el__hlen_seed_point(tracer *T, const hroot *r, double sigma, cpt *s);

#endif
