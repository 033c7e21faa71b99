/*
 * How the fitting code's files meet (not installed):
 *   fit.c            the public entry points and el__fit_run's stages: options,
 *                    normalisation, charts and map, the kept fit's feet, results and
 *                    distances in input units, the further runs;
 *   fit_starts.c     the run's starts (guesses and further starts), the noise rule;
 *   fit_choose.c     each start's fit and the choice among them;
 *   fit_candidate.c  one initial guess solved: Levenberg-Marquardt, then Ipopt where
 *                    rows, bounds or an uncertified point need it;
 *   fit_model.c      the optimiser's parameters: internal parameter vectors, the maps
 *                    variables -> parameters with their derivatives, model points and
 *                    Jacobians block by block, the curve's end states (point, tangent,
 *                    curvature) with derivatives;
 *   fit_objective.c  residuals and the normal equations J^T J, J^T r (streamed in blocks,
 *                    never storing J), foot points and point-to-curve distances;
 *   fit_lm.c         Levenberg-Marquardt and its first-order certificate;
 *   fit_ipopt.c      bounds and constraints through Ipopt (and the fallback);
 *   fit_keyline.c    the keyline as one problem: two curves sharing a G2 joint;
 *   fit_frame.c      the public fits in the frame of a held tangent.
 * Everything is in normalised coordinates: points P = (xy - c) / sc.
 */
#ifndef EL_FIT_INTERNAL_H
#define EL_FIT_INTERNAL_H

#include "internal.h"

enum {
    FIT_NP = 7,        /* parameters of one curve */
    FIT_PIECES = 128,  /* el__fit_feet_unproven's pieces of the curve */
    FIT_MAXX = 9,      /* optimiser variables at most (the keyline's joint problem) */
    FIT_BLOCK = 256,   /* samples per block of the streamed Jacobian */
    FIT_NCON = 6,      /* constraint rows at most */
    FIT_KNOTS = 65,    /* samples of the tangential motion of a curve (fit_objective.c) */
    /* scratch for a walk over a discrete curve: a block's points, Jacobian rows and the
     * walk's own buffer (el__fit_discrete_rows: 2 (m + 1) (FIT_NP + 1) doubles) */
    FIT_WORK = 2 * FIT_BLOCK * (FIT_NP + 1) + 2 * (FIT_BLOCK + 1) * (FIT_NP + 1)
};

enum fit_model { FIT_DISCRETE = 0, FIT_SMOOTH = 1 };

/* |(x, y)| for normalised coordinates (O(1): no overflow to guard against, unlike
 * hypot, which costs several times as much in the per-point loops). */
static inline double fit_norm(double x, double y) { return sqrt(x * x + y * y); }

/* a run's status st gave a curve: converged or the best seen (not an error, nor unmet rows) */
static inline int fit_gave_curve(int st) { return st == EL_OK || st == EL_ENOCONV || st == EL_EMAXITER; }

/* nothing fixed or bounded in the options' FIT_NP slots */
static inline int fit_options_unbounded(const el_fit_options *o)
{
    int j = 0;
    while (j < FIT_NP && !o->fixed[j] && !isfinite(o->lower[j]) && !isfinite(o->upper[j])) j++;
    return j == FIT_NP;
}

/*
 * Internal parameters of one curve (normalised coordinates):
 *   discrete v = (x0, y0, h, phi, z, q, k) with -1 < k < 0 allowed: the curve of
 *     |k| and q + 2K(|k|) (sn(u + 2K) = -sn u, dn(u + 2K) = dn u);
 *   smooth   v = (x0, y0, phi, w, k, q, L) with w = sqrt(mu) of either sign: w < 0 is
 *     the curve (|w|, -k, -q) (sn odd, dn even), so k sn u is unchanged.
 * Both continuations let a Gauss-Newton step cross k = 0 or w = 0 instead of
 * stalling at a bound; el__fit_canonical() maps results back to the model's form.
 */
int el__fit_to_discrete(const double *v, el_discrete_params *p, double *dq_dk);
int el__fit_to_smooth(const double *v, el_smooth_params *p);
int el__fit_canonical(int model, double *v, int may_shift);

/* Points (xy, 2m) and, when jac != NULL, d gamma / d v (jac[(2i+c)*7 + j]) of the
 * smooth model at m arc lengths s. */
int el__fit_smooth_rows(const double *v, size_t m, const double *s, double *xy, double *jac);

/* The discrete vertices walked in blocks: the walk carries the next vertex and its
 * derivative, so vertex i of a block has the same d gamma_i / d v as one call over
 * the whole curve (tested). jac (when not NULL): rows jac[(2i+c)*7 + j], or with
 * cstride > 0 by column, jac[j * cstride + 2i + c], columns 2..6 only (the paired
 * fit's fold). */
typedef struct fit_walk {
    size_t next;                 /* index of the next vertex */
    double xy[2], d[2][FIT_NP];  /* that vertex and its derivative */
} fit_walk;
void el__fit_walk_start(const double *v, fit_walk *w);
int el__fit_discrete_rows(const double *v, fit_walk *w, size_t m, double *xy, double *jac,
                          size_t cstride, double *tmp /* 2 (m+1) (7+1) */);

/* State of a curve at arc length s (smooth; s = 0 or L) or at a vertex end
 * (discrete, at_end = 0: vertex 0, 1: vertex n-1 of n): point, tangent angle, curvature
 * and their derivatives with respect to v. The discrete curvature at an end is that of
 * the curve extended by one vertex, kappa_0 = (2/h) tan((Theta_0 - Theta_{-1})/2). */
typedef struct fit_end {
    double xy[2], theta, kappa;
    double dxy[2][FIT_NP], dtheta[FIT_NP], dkappa[FIT_NP];
} fit_end;
int el__fit_end_state(int model, const double *v, size_t n, int at_end, fit_end *e,
                      double *tmp /* discrete end: fit_walk block buffers, FIT_WORK doubles */);

/* The charts of a map (fit_model.c): none; the start state (theta0, kappa0, F) in the
 * slots of (phi, w or z, k, q); both end points held, x = (a, Gx, Gy) in the slots of
 * (w or z, k, q), the start state of the curve's shape at unit length (x0, y0 in fixed[];
 * a zero start curvature held too: a = 0 in fixed[], x = (Gx, Gy)). */
enum { FIT_CHART_NONE = 0, FIT_CHART_START = 1, FIT_CHART_ENDS = 2 };

/* The map from the optimiser's variables x to the curves' internal parameters. */
typedef struct fit_map {
    int model, ncurves, nx;
    /* one curve: x_j = v[idx[j]] * scale[idx[j]] for the free parameters, the others at
     * fixed[]; with chart, the slots of (phi, w or z, k, q) hold the start-state chart
     * (theta0, kappa0, Fx, Fy) instead (fit_model.c) */
    int idx[FIT_NP], chart;      /* FIT_CHART_* */
    double scale[FIT_NP], fixed[FIT_NP];
    double chord[2];             /* FIT_CHART_ENDS: the held end point minus the start point */
    /* keyline (ncurves = 2): x = (xJ, yJ, psi, a1, b1, c1, a2, b2, c2), fit_keyline.c;
     * discrete: scale[c] = (vertices of side c) - 1 */
    double fixed_h;              /* discrete keyline: h of both sides held (> 0), else 0 */
} fit_map;

/* v[c] (c < ncurves) and M = d v / d x (may be NULL): curve c's 7 x nx block, row-major,
 * at M + c * FIT_NP * FIT_MAXX. */
int el__fit_map_eval(const fit_map *m, const double *x, double v[2][FIT_NP], double *M);
/* The largest step fraction alpha <= 1 that keeps x + alpha d in the model's domain. */
double el__fit_map_step_limit(const fit_map *m, const double *x, const double *d);
/* x for the parameters v[0] (one curve). */
void el__fit_map_inverse(const fit_map *m, const double *v, double *x);
int el__fit_keyline_map(const fit_map *m, const double *x, double v[2][FIT_NP], double *M);

/* ------------------------------------------------------------------ objective */

enum fit_kind {
    FIT_PAIRED,        /* point i <-> vertex i (discrete) or gamma(t_i L) (smooth) */
    FIT_ORTHOGONAL,    /* distance to the curve (smooth) or the polygon (discrete); ends:
                          gamma(0) - P_0, gamma(end) - P_n-1 */
    FIT_KEYLINE        /* two curves sharing the joint: paired (discrete), orthogonal (smooth) */
};

typedef struct fit_objective {
    int kind;
    fit_map map;
    size_t n;
    const double *xy;            /* the caller's points, input units */
    double cx, cy, sc;           /* normalisation P = (xy - c) / sc */
    const double *t;             /* FIT_PAIRED smooth: fractions t_i */
    double *s, *s_next;          /* orthogonal: foot parameters (n each); keyline smooth:
                                    sigma < 0 on the first curve at -sigma, >= 0 the second */
    int exact_feet;              /* project the feet at every evaluation (Ipopt) */
    int exact_ends;              /* feet within the curve, not its extension (fit_feet.c) */
    /* the feet's motion under a step of the variables x from the last accepted point
     * (base): b(s) = (d gamma(s) / d x)^T T(s) sampled at FIT_KNOTS arc lengths of each
     * curve (in x, the optimiser's well-scaled variables, not in v: fit_objective.c) */
    double last_move;            /* the largest foot move of the last evaluation */
    int have_base;
    double base_x[FIT_MAXX], last_x[FIT_MAXX], step[FIT_MAXX], base_len[2];
    double knot_b[2][FIT_KNOTS][FIT_MAXX], knot_ds[2][FIT_KNOTS];
    /* a later guess's Levenberg-Marquardt gives up once it cannot reach this objective
     * (an earlier guess's) at its recent rate within its remaining iterations
     * (fit_lm.c); HUGE_VAL (el__fit_objective_init): never */
    double f_ceiling;
    /* with constraint rows: Ipopt's run is held to f_ceiling too, at iterates near the rows
     * (fit_ipopt.c, cb_iter; set by fit_choose.c for a later start while the kept fit meets
     * them, and by rows_halfway, fit_candidate.c; 0, el__fit_objective_init: never) */
    int rows_cap;
    /* smooth orthogonal: a fit from the paired start that ends above this objective (far
     * above the data's noise, fit_starts.c) is fitted from its guess's own feet too
     * (fit_candidate.c); HUGE_VAL (el__fit_objective_init): never */
    double f_direct;
    /* Levenberg-Marquardt stops once a Gauss-Newton step would lower f by less than
     * lm_tol of itself (fit_lm.c; el__fit_objective_init: 1e-13, the certificate) */
    double lm_tol;
    /* smooth orthogonal, one curve: the reported distances' and feet's arrays (n each,
     * may be NULL), holding after each evaluation the signed distance and the moved foot
     * of every point whose foot that evaluation found at rest within [0, L] (a Newton
     * step below 1e-7 L, el__fit_feet_distances' test), distance NaN for the others; rest_x:
     * the variables it was at, rest_ok: set by a completed evaluation, cleared by other
     * writers of the arrays. el__fit_feet_distances at rest_x takes those points as they are
     * (the report after the fit: one evaluation of every point fewer) */
    double *rest, *rest_foot, rest_x[FIT_MAXX];
    int rest_ok;
    /* smooth orthogonal: a sampled search for feet on another pass (el__fit_feet_elsewhere)
     * has seen a pass within reach of a point, other than its own (el__fit_objective_init: 0) */
    int other_passes;
    /* the points' own polygon crosses itself (el__fit_wanders; 0 until known, then 1: no, 2: yes) */
    int points_cross;
    /* the held start and end points (input units; NaN where not held: el__fit_objective_init),
     * the ends of el__fit_stray_held's allowance */
    double held_ends[4];
    size_t split;                /* discrete keyline: the data index of the joint */
    double *work;                /* block buffers */
    /* discrete orthogonal: the polygon (2n), distances and feet (n each) of the last
     * evaluation, and the points bucketed by their foot's segment (fit_objective.c) */
    double *poly;
    size_t *bucket, *order;
    /* a quadratic penalty (rho/2) |c(x)|^2 of constraint rows added to f (fit_candidate.c's
     * start of a constrained fit); pen NULL: none. pen_tmp: FIT_WORK doubles */
    const struct fit_constraints *pen;
    double pen_rho, *pen_tmp;
    /* the last start fit_candidate.c's rows_halfway ran from (halfway_seen: there is one):
     * the guesses' continuations often end at the same point, run from once */
    double halfway_x[FIT_MAXX];
    int halfway_seen;
} fit_objective;

/* f = (1/2n) sum r^2; when want_normal also g = J^T r / n and H = J^T J / n (lower
 * triangle filled, row-major nx x nx) in the variables x. */
typedef struct fit_value {
    double f;
    double g[FIT_MAXX], H[FIT_MAXX * FIT_MAXX];
} fit_value;

int el__fit_objective_init(fit_objective *o, int kind, const fit_map *map, const double *xy, size_t n,
                           double cx, double cy, double sc, const double *t);
/* The smooth feet are variables of the objective (orthogonal, keyline); a paired smooth
 * objective keeps the arrays for the distances only. */
static inline int fit_has_feet(const fit_objective *o) { return o->s && o->kind != FIT_PAIRED; }
/* Point i in normalised units (the fit's centre cx, cy and scale sc). */
static inline void fit_point(const fit_objective *o, size_t i, double *P)
{
    P[0] = (o->xy[2 * i] - o->cx) / o->sc;
    P[1] = (o->xy[2 * i + 1] - o->cy) / o->sc;
}
/* The conditions an end-constraint mask sets: 2 a held point, 1 a tangent or a curvature
 * (the length and k ranges none). */
static inline int fit_conditions(int mask)
{
    return 2 * !!(mask & EL_CONSTRAIN_START_POINT) + 2 * !!(mask & EL_CONSTRAIN_END_POINT) +
           !!(mask & EL_CONSTRAIN_START_TANGENT) + !!(mask & EL_CONSTRAIN_END_TANGENT) +
           !!(mask & EL_CONSTRAIN_START_CURVATURE) + !!(mask & EL_CONSTRAIN_END_CURVATURE);
}
/* Whether point g is paired with the curve's end (its residual gamma(0) - P_0 or gamma(L) -
 * P_{n-1} in full, fit_objective.c): the first and last points, but not where that end point
 * is held, whose residual would be a constant and the point's distance to the curve unseen
 * by the fit (there its foot is free, as an interior point's). */
static inline int fit_end_paired(const fit_objective *o, size_t g)
{
    return (g == 0 && isnan(o->held_ends[0])) || (g == o->n - 1 && isnan(o->held_ends[2]));
}
/* Newton's iterations for a foot on the smooth curve (fit_feet.c, fit_nearest.c). */
enum { FIT_NEWTON_MAX = 40 };
void el__fit_objective_free(fit_objective *o);
int el__fit_objective_eval(fit_objective *o, const double *x, int want_normal, fit_value *out);
/* After an accepted step of a lazy-foot evaluation (want_normal at the accepted x): the
 * feet move to the updated ones computed there. */
void el__fit_objective_accept(fit_objective *o);
/* Feet to the nearest points (Newton, from the current feet) at x. */
int el__fit_objective_project(fit_objective *o, const double *x);

/* min(max(x, lo), hi) for finite values, inline (libm's fmin / fmax are calls, in the
 * per-point loops of the feet). */
static inline double fit_clamp(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

/* Newton's step for the foot, -t / (1 + kappa e) (gamma - P = t T + e N: t, e the
 * tangential and normal parts of gamma - P, kappa the curvature, range the curve's
 * extent), with its derivative bounded below (a point beyond the centre of curvature
 * still moves the right way) and the step to half the radius of curvature (or of the
 * range): a foot stays on its branch of a tight loop instead of jumping to another. */
static inline double fit_foot_step(double t, double e, double kappa, double range)
{
    const double den = 1.0 + kappa * e, ak = fabs(kappa), ir = 1.0 / range;
    const double lim = 0.5 / (ak > ir ? ak : ir);
    return fit_clamp(-t / (den > 0.25 ? den : 0.25), -lim, lim);
}
/* The feet's range [lo, hi]: the curve itself, or extended (the objective's). */
void el__fit_feet_range(const fit_objective *o, double v[2][FIT_NP], int extended, double *lo, double *hi);
/* Smooth orthogonal, one curve, o->rest and o->rest_foot set (fit.c's buffers): the first
 * feet of a fit from x, each where the curve at x comes nearest (else at t_i L); an error
 * only when that curve cannot be evaluated. */
int el__fit_feet_start(fit_objective *o, const double *x);
/* Smooth, one curve: the m feet sig[k] of the points pt[k] by Newton's method from
 * sig[k] to the nearest points in [0, L], with their signed distances dist[k]. */
int el__fit_feet_project_list(const fit_objective *o, double v[2][FIT_NP], const size_t *pt, size_t m, double *sig,
                              double *dist);
/* Signed distances (left of the curve positive), feet (arc length; for the keyline from
 * the joint) and sides (keyline; may be NULL) of every point at x, normalised units:
 * the feet projected from o->s (which keeps the objective's feet). */
int el__fit_feet_distances(fit_objective *o, const double *x, double *dist, double *foot, int *side);
/* fit_polygon.c: the same for the polygon of nv vertices V (normalised) of one discrete
 * curve of segment h, vertex j <-> point first + step j. */
void el__fit_polygon_distances(const fit_objective *o, const double *V, size_t nv, double h,
                               size_t first, long step, double *dist, double *foot);
/* The same, accelerate 0: every stretch by the linear scan (the reference the tests hold
 * the bounding-box search to: the same feet and distances, bit for bit). */
void el__fit_polygon_distances_by(const fit_objective *o, const double *V, size_t nv, double h,
                                  size_t first, long step, double *dist, double *foot, int accelerate);
/* The same, the work counted into *visited (may be NULL): the segments whose distance the
 * walks and the scanned ranges measured, the polygon's segments at each build of the tree,
 * one per search of it (a range or a run the walk skips); deterministic, for tests that
 * hold the search to O(n) work (test_fit_polygon_work.c). */
void el__fit_polygon_distances_counted(const fit_objective *o, const double *V, size_t nv, double h,
                                       size_t first, long step, double *dist, double *foot,
                                       int accelerate, long *visited);
/* The direction of (x, y) in (-pi, pi] to within 2e-6 (fit_polygon.c). */
double el__fit_direction(double x, double y);
/* fit_polygon.c: el__fit_nearest_everywhere's search of the discrete model's polygons. */
int el__fit_polygon_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                                       const size_t nv[2], double *dist, double *foot, int *side);
/* The distances above, corrected where the curve comes nearer elsewhere (a loop
 * passing close to itself): dist, foot, side (may be NULL) in and out; for the discrete
 * model V[c] are the vertices (nv[c]) of curve c. The signs are each curve's own. */
int el__fit_nearest_everywhere(const fit_objective *o, double v[2][FIT_NP], const double *V[2],
                               const size_t nv[2], double *dist, double *foot, int *side);
/* The hash grids of the searches everywhere (fit_nearest.c, fit_polygon.c): the grid cell
 * of coordinate x from q = x / cell (polygons: x times 1 / cell, monotone too): floor(q)
 * by the truncating conversion, exact within +-2^40, where it is held (a far, diverging
 * curve gives quotients no long holds; the searches then take every piece; libm's floor
 * is a call on baseline x86-64); NaN gives -2^40. */
static inline long fit_cell_index(double q)
{
    const double lim = 1099511627776.0;
    if (q >= -lim && q <= lim) {
        const long c = (long)q;
        return (double)c > q ? c - 1 : c;
    }
    return q > 0.0 ? (long)lim : -(long)lim;
}

/* The bucket of cell (ix, iy) among mask + 1 (a power of two) */
static inline size_t fit_cell_hash(long ix, long iy, size_t mask)
{
    const unsigned long h = (unsigned long)ix * 73856093UL ^ (unsigned long)iy * 19349663UL;
    return (size_t)(h & mask);
}

/* A typical distance: the mean |d| of a spread sample of the n distances. */
static inline double fit_mean_distance(const double *dist, size_t n)
{
    const size_t step = n > 1024 ? n / 1024 : 1;
    size_t cnt = 0;
    double sum = 0.0;
    for (size_t i = 0; i < n; i += step, cnt++) sum += fabs(dist[i]);
    return sum / (double)cnt;
}

/* fit_refit.c: the distances and feet (normalised) of every point to the kept curve x
 * (v its parameters), near each point's own place, then wherever the curve comes nearer;
 * projected (smooth): d, fs hold the first already (el__fit_feet_distances at x); tmp:
 * FIT_WORK doubles. */
int el__fit_curve_distances(fit_objective *ob, const double *x, double v[2][FIT_NP], int projected, double *d,
                            double *fs, double *tmp);
/* What a fit computed that its report (el__fit_wander_gap) needs again: of the points xy
 * (n), their scale sc (el__fit_normalisation) and noise, el__fit_noise_rms x sc; follows:
 * fit.c's stray rule found the fit (its parameters and feet as reported) to follow them
 * (el__fit_stray at that noise, without held ends, within FIT_STRAY). */
typedef struct fit_seen {
    const double *xy;
    size_t n;
    double sc, noise;
    int follows;
} fit_seen;
/* fit_feet.c: idx (n entries) the indices 0..n-1 in the order of fs, ties by index;
 * 0, or -1 when out of memory (NaN feet far out of order take n pairs of workspace) */
int el__fit_feet_order(const double *fs, size_t *idx, size_t n);
/* fit_refit.c: the smooth distances d and feet fs of the points at x (v its parameters,
 * one curve), the feet projected from o->s, then those found nearer on another pass of
 * the curve from its samples (*moved of them whose foot in o->s lies on [0, L]). */
int el__fit_feet_elsewhere(fit_objective *o, const double *x, double v[2][FIT_NP], double *d, double *fs,
                           size_t *moved);
/* fit_refit.c: the distances d and feet fs of the points to the curve v[0] (normalised
 * parameters; x: its variables in ob's map, v evaluated again from them), the feet afresh
 * from the chord fractions, then el__fit_feet_elsewhere's (a member of a family searched
 * whole: fit_natural.c, fit_g1_family.c); EL_EDOM where v is not in the map. */
int el__fit_curve_feet(fit_objective *ob, double v[2][FIT_NP], double *x, double *d, double *fs);
/* fit_refit.c, the kept fit's nearest points (distances d, feet fs, n of them) against it
 * (length L, objective f, its feet s): el__fit_feet_moved, its inner feet on [0, L] moved to
 * the nearest by more than 1e-3 L; el__fit_nearer_than, the distances below its fit (its
 * feet gone: a later run's in ob); el__fit_feet_set, ob's feet fs, a paired end's at the
 * curve's end (fit.c's settle_feet rounds and fit_choose.c's settle_early). */
int el__fit_feet_moved(const double *s, const double *fs, size_t n, double L);
int el__fit_nearer_than(const double *d, size_t n, double f);
void el__fit_feet_set(fit_objective *ob, const double *fs, double L);
/* fit_refit.c, one smooth curve v: unproven[i] = 1 for the inner points whose feet fs
 * (distances d, Newton's) the proof of el__fit_feet_elsewhere does not show the nearest points
 * (their count *nopen; 0 at the ends), and mark[j] = 1 for the FIT_PIECES pieces of
 * length L / FIT_PIECES that can hold a point nearer to one of them. */
int el__fit_feet_unproven(const fit_objective *o, double v[2][FIT_NP], const double *d, const double *fs,
                          unsigned char *unproven, size_t *nopen, unsigned char mark[FIT_PIECES]);

/* Normalisation shared with guess.c: centroid and rms radius of the points;
 * EL_ESINGULAR (all equal), EL_EDOM (a spread below ~1e-292 or beyond double's range). */
int el__fit_normalisation(const double *xy, size_t n, double *cx, double *cy, double *sc);
/* A parameter j of a model in input units <-> normalised (the smooth mu <-> w). */
double el__fit_norm_param(int model, int j, double v, double cx, double cy, double sc);
double el__fit_denorm_param(int model, int j, double v, double cx, double cy, double sc);
/* The rms noise of the points from third differences, in normalised units, at any
 * spacing (guess.c); _plain: the plain differences alone (equal spacing). */
double el__fit_noise_rms(const double *xy, size_t n, double sc);
double el__fit_noise_plain(const double *xy, size_t n, double sc);
int el__fit_check_points(const double *xy, size_t n, size_t nmin);

/* ------------------------------------------------------------------ results */

/* A fit's result in input units, before it is published: params and initial in the
 * parameter vector order, which is also the field order of el_discrete_params and
 * el_smooth_params. */
typedef struct fit_out {
    double params[FIT_NP], initial[FIT_NP];
    double rms, max_error;
    double f;    /* the objective (normalised units) of the kept fit (its best candidate) */
    int iterations, candidates, ipopt_status, used_ipopt, status, mode, distance, constraint;
    fit_seen seen;    /* for the report: el__fit_run sets it, a refit that may replace the fit clears follows */
} fit_out;

/* Write fit_out fo into the public result *res (el_fit_discrete_result or
 * el_fit_smooth_result: the same fields), ParamT its parameter struct. */
#define FIT_PUBLISH(res, fo, ParamT)                                                      \
    do {                                                                                \
        const double *p_ = (fo).params, *q_ = (fo).initial;                             \
        (res)->params = (ParamT){p_[0], p_[1], p_[2], p_[3], p_[4], p_[5], p_[6]};      \
        (res)->initial = (ParamT){q_[0], q_[1], q_[2], q_[3], q_[4], q_[5], q_[6]};     \
        (res)->rms = (fo).rms; (res)->max_error = (fo).max_error;                       \
        (res)->iterations = (fo).iterations; (res)->candidates = (fo).candidates;       \
        (res)->ipopt_status = (fo).ipopt_status; (res)->status = (fo).status;           \
        (res)->used_ipopt = (fo).used_ipopt; (res)->distance = (fo).distance;           \
        (res)->constraint = (fo).constraint;                                            \
    } while (0)

/* ------------------------------------------------------------------ solvers */

typedef struct fit_solution {
    double x[FIT_MAXX];
    fit_value val;               /* at x, with normal equations */
    int iters;
    int certified;               /* the first-order condition holds */
} fit_solution;

/* f at which a fit is exact to rounding: rms residual 1e-11 of the rms radius. */
#define FIT_EXACT_F 5e-23

/* Levenberg-Marquardt from x; fills sol (best point seen). EL_OK, or an error of the
 * objective at the start point. */
int el__fit_lm(fit_objective *o, const double *x, int max_iter, fit_solution *sol);
/* The first-order condition: g^T H^-1 g <= tol 2f (fit_lm.c), or f at rounding level. */
int el__fit_first_order(const fit_value *v, int nx, double tol);
/* The same on the tangent space of met constraint rows of derivative A (m x nx; fit_lm.c). */
int el__fit_first_order_rows(const fit_value *v, const double *A, int m, int nx, double tol);

/* Constraints (normalised units), the bits of enum el_fit_constraint. */
typedef struct fit_constraints {
    int mask;
    double start_xy[2], end_xy[2], start_theta, end_theta, start_kappa, end_kappa;
} fit_constraints;

typedef struct fit_ipopt_out {
    int ran;             /* Ipopt ran (else the rest is 0, f HUGE_VAL: e.g. constraints not evaluable) */
    int ipopt_status, iters;
    int certified;       /* L-BFGS stopped at a point of the first-order condition (fit_lm.c) */
    double f;
} fit_ipopt_out;
/* One initial guess's result (fit_candidate.c): its point x, f, status, iterations, Ipopt's run. */
typedef struct fit_candidate {
    double x[FIT_MAXX], f;
    int status, iters, used_ipopt, ipopt_status;
} fit_candidate;
/* A candidate with rows that loops (fit_starts.c's conjugate starts), refitted by Ipopt from
 * where it is from its curve's nearest points (el__fit_feet_start) while that lowers f and
 * meets con and the bounds lo, hi, at most REFEET_ROUNDS times: its feet followed the curve
 * by Newton steps from its start's nearest points and can rest on another pass than the
 * nearest (measured, the conjugate starts of three sine scans held at an inflection: f 0.049
 * -> 0.017, 0.085 -> 0.010, 0.032 -> 0.007 in 2-3 rounds). *stale: ob's feet are a rejected
 * refit's. EL_OK, or el__fit_solve_candidate's error. */
enum { REFEET_ROUNDS = 3 };
int el__fit_refeet(fit_objective *ob, const el_fit_options *o, const fit_constraints *rows,
                   const fit_constraints *con, const double *lo, const double *hi, const double *xl,
                   const double *xu, int no_polish, fit_candidate *r, int *stale, double *tmp);
/* 1 when a candidate's Ipopt run ended at its iteration limit (Maximum_Iterations_Exceeded). */
/* Ipopt's run ended at max_iter, or (5, User_Requested_Stop: with rows only ob->rows_cap's
 * stop, fit_ipopt.c) was stopped by the kept fit's cap where the plain path's ran on: counted
 * as none, every further guess ran (each stopped) where the plain path's stop_rule had ended
 * the search (a noisy hand sketch of 200 points held G1: 13585 iterations against 7771) */
static inline int el__fit_ran_out(const fit_candidate *r)
{
    return r->used_ipopt && (r->ipopt_status == -1 || r->ipopt_status == 5);
}
/* One initial guess x0 (fit_candidate.c): Levenberg-Marquardt, then Ipopt when something
 * needs it (rows, the point outside the bounds xl, xu; without them, the point left
 * uncertified unless no_polish); best_f, the best earlier candidate's f (a later one that
 * cannot reach it is stopped); near_start: x0 is near the constrained optimum already
 * (el__fit_held_start's continuation) or the fit to polish, Ipopt from there; warm: x0
 * is a fit already and the feet are set (el__fit_run's refit): no paired start.
 * EL_OK with *r (its status the fit's), or EL_ENOMEM / EL_EINTERNAL. */
int el__fit_solve_candidate(fit_objective *ob, const el_fit_options *o, const fit_constraints *con,
                            const double *xl, const double *xu, int need_ipopt, int no_polish,
                            const double *x0, double best_f, fit_candidate *r, double *tmp, int near_start,
                            int warm);
/* A fit that only starts another (the keyline's side fits): el_fit_discrete /
 * el_fit_smooth by Levenberg-Marquardt alone, no Ipopt fallback (an uncertified result
 * is EL_EMAXITER / EL_ENOCONV with its parameters). v: the parameters in input units
 * (the model's Jacobian order); *iters += the iterations; foot: as el_fit_smooth's. */
int el__fit_start(int model, const double *xy, size_t n, const el_fit_options *opt, double *v, int *mode,
                  int *iters, double *foot);
/* A run's status (fit_out.status, el__fit_run's return) for a kept fit that misses a
 * constraint (res->constraint names it) after its Ipopt run stopped at max_iter: the cap,
 * not the constraint, stopped it. Inside, no fit (as EL_EDOM: not EL_OK, EL_ENOCONV or
 * EL_EMAXITER); the public wrappers return it as EL_EMAXITER, the constraint still named
 * (--max-iter 1 on a feasible start curvature was refused as impossible, EL_EDOM, QA). */
enum { FIT_ECAPPED = 256 };
static inline int fit_public_status(int st) { return st == FIT_ECAPPED ? EL_EMAXITER : st; }

/* One fit of the points (fit.c): el_fit_discrete / el_fit_smooth into *res (status -1
 * until a result exists), opt NULL = defaults, init the caller's initial parameters
 * (opt->use_initial); flags: FIT_RUN_LM_ONLY, no Ipopt fallback and no further start
 * (el__fit_start); FIT_RUN_ROWS, both end points as Ipopt's rows, not the ends chart;
 * FIT_RUN_NO_OTHER, no start from the other model's fit (el__fit_follow_points: the
 * fit that start runs); FIT_RUN_POLISH, Ipopt polishes a fit without rows that
 * Levenberg-Marquardt leaves uncertified (el__fit_fallback's run; otherwise the fit
 * kept is polished by that run); FIT_RUN_INNER, a fit inside another
 * (el__fit_follow_points'), whose result the outer one polishes if it keeps it;
 * FIT_RUN_ENDS_HELD, pinned at both ends with a zero start curvature: the ends chart with
 * that curvature held (el__fit_ends_held's run); FIT_RUN_NO_CONJUGATE, without the conjugate
 * starts (el__fit_smooth_start's run: the discrete fit has its own); FIT_RUN_FREE_ENDS, smooth by
 * distance with no point tied to an end (el__fit_free_ends' first run). */
enum { FIT_RUN_LM_ONLY = 1, FIT_RUN_ROWS = 2, FIT_RUN_NO_OTHER = 4, FIT_RUN_POLISH = 8, FIT_RUN_INNER = 16,
       FIT_RUN_ENDS_HELD = 32, FIT_RUN_NO_CONJUGATE = 64, FIT_RUN_FREE_ENDS = 128 };
int el__fit_run(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                const double *init, fit_out *res, double *dist, double *foot);
/* One run of el__fit_run: what its stages (fit.c, fit_choose.c) hand on to each other.
 * Normalised units (the normalisation cx, cy, sc) but for the call's own arrays. */
enum {
    FIT_MAXCAND = 6,        /* initial guesses at most (el_guess_*) */
    FIT_G1_STARTS = 3,      /* G1 family members fitted at most (fit_g1_family.c) */
    FIT_G1_WAVES = 8,       /* and waves along nearly collinear ends (fit_g1_family.c) */
    /* fewer points are a sketch's (bench_fit_sparse.py draws 6-59), whose noise figure
     * holds their curve's bending too (fit_starts.c: ob.f_direct) */
    FIT_SKETCH_POINTS = 60
};
typedef struct fit_run_state {
    /* the call: el__fit_run's arguments; o the options in force (the caller's or the
     * defaults; a held start point as x0, y0 fixed) */
    int model, flags, lm_only;
    const double *xy, *init;
    size_t n;
    const el_fit_options *opt;
    fit_out *res;
    el_fit_options o;
    double cx, cy, sc, norm[3];
    /* bounds (the model's, the caller's, the constraints'), the constraints (con_rows:
     * those left to Ipopt's rows) and the distance (enum fit_kind) */
    double lo[FIT_NP], hi[FIT_NP];
    fit_constraints con, con_rows;
    int kind;
    /* the charts (fit.c, choose_charts): sl the slots of (phi, w or z, k, q), held the
     * constraint bits a chart holds exactly, staged those held by continuation */
    int sl[4], ik, jl, chart_ok, held, ends_ok, ends_chart, zero_k0, natural, need_ipopt, staged;
    int determined;                          /* as many rows as variables (alloc_work) */
    double chord[2];
    fit_map map, free_map;                   /* free_map: the held chart variables free */
    double xl[FIT_MAXX], xu[FIT_MAXX];       /* the variables' bounds */
    /* work: fractions t (smooth), scratch, distances and feet d, fs (the caller's or dbuf),
     * the kept fit's feet before the G1 family members' pass */
    double *t, *tmp, *dbuf, *d, *fs, *kept_feet;
    fit_objective ob;
    int mode;                                /* the smooth fractions' el_param_mode */
    /* the starts (fit_starts.c): cand[0..ncand), the index of each further start in it
     * ((size_t)-1: none), the first nconj conjugate and nfamily family starts */
    double cand[FIT_MAXCAND + 4 + FIT_G1_STARTS + FIT_G1_WAVES][FIT_NP];
    size_t ncand, free_ci, smooth_ci, natural_ci, nconj, nfamily;
    int caller_twice, caller_start, free_start, smooth_start, sketch_rows;
    int natural_ok, natural_evals, deferred, no_polish, polish_run, refit_no_polish;
    int family_pass, family_won, kept_last;
    double noise_rms, data_noise, noise;     /* the noise figures (fit_starts.c) */
    /* the kept fit: its candidate and start, what is known of it (-1: not yet), the
     * counts; then its curve v, status and the constraint it violates, ok: evaluable */
    fit_candidate best;
    double best_init[FIT_NP];
    int best_strays, best_loops, best_meets, wander_kept;
    int iters, tried, last_is_best, ipopt_spent;
    int unshared;         /* a held start's continuation ended far above its free fit (fit_choose.c) */
    double settle_tried_f;   /* the kept fit's objective settle_early last refitted (0: none) */
    double v[2][FIT_NP];
    int status, constraint, ok;
} fit_run_state;
/* fit_pairing.c: whether the points are spaced evenly along the data (the paired
 * distance's condition, seed 000 (4.6)); the first point where they turn back and run
 * back over a stretch (a retraced scan: not one pass), 0 where none does. */
int el__fit_evenly_spaced(const double *xy, size_t n);
size_t el__fit_retrace(const double *xy, size_t n);
/* fit_starts.c: the run's starts: the guesses (or the caller's start), the noise rule, and
 * the further starts fitted first; EL_OK, else the run's error. */
int el__fit_starts(fit_run_state *R);
/* fit_choose.c: every start fitted in turn, the best kept (R->best, best_init), then the G1
 * ends' family members; EL_OK, else the run's error. */
int el__fit_choose(fit_run_state *R);
/* fit_restart.c: el__fit_run (flags as there) on the points in reverse order when the end
 * holds more constraints than the start, else as they are (the public entry points). */
int el__fit_run_either_way(int model, const double *xy, size_t n, const el_fit_options *opt,
                           int flags, const double *init, fit_out *res, double *dist, double *foot);
/* fit_frame.c: el__fit_run_either_way in the frame of a held start (else end) tangent where
 * the constraints and fixed parameters are as many as the parameters: the points turned
 * about the held start point (else the first point) so that tangent is 0, the result turned
 * back (not where x0, y0 or phi are fixed or bounded). */
int el__fit_run_framed(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                       const double *init, fit_out *res, double *dist, double *foot);
/* fit_restart.c: a constrained fit's last start, the unconstrained fit's curve
 * (normalised by cx, cy, sc into v) when its objective is 1 % below best_f; EL_EDOM:
 * none, EL_ENOMEM. */
int el__fit_unconstrained_start(int model, const double *xy, size_t n, const el_fit_options *opt, double cx,
                                double cy, double sc, double f_below, double *v);
/* fit_restart.c: a discrete fit's last start where its constraints are rows: the smooth
 * fit with the same constraints as the discrete model's continuum limit (normalised by
 * cx, cy, sc into v); EL_EDOM: none, EL_ENOMEM. */
int el__fit_smooth_start(const double *xy, size_t n, const el_fit_options *opt, int flags,
                         double cx, double cy, double sc, double *v);
/* fit_restart.c: the conjugate of a smooth inflectional curve p (input units) at its start:
 * the same start point, tangent and zero curvature, the force reversed (phi + pi,
 * k' = sqrt(1 - k^2)), so that between its inflections it turns the other way round, through
 * the directions p does not take (its inflections' tangents the same mod 2 pi); w scaled by
 * K(k') / K(k), its inflections as far apart (tests/c/test_fit_ends_held.c). EL_EDOM where p
 * has no inflection at its start. */
int el__fit_conjugate(el_smooth_params *p);
/* fit_restart.c: a smooth fit held at an inflection at its start (start tangent and zero
 * curvature) with a tangent row at its end: the conjugate of its fit without rows (the same
 * start state, the force reversed: it turns between its inflections the other way round,
 * through the directions the held fit does not take), as it is in v[0], scaled up to the
 * held fit's chord in v[1] (normalised by cx, cy, sc); EL_EDOM: none, EL_ENOMEM. */
int el__fit_conjugate_start(const double *xy, size_t n, const el_fit_options *opt, double cx,
                            double cy, double sc, double v[2][FIT_NP]);
/* fit_natural.c: a smooth fit by distance pinned at both ends (ob's ends chart) with both end
 * curvatures 0: the member of that one-parameter family of curves nearest the points among
 * those that do not cross themselves (normalised parameters v; noise: el__fit_noise_rms,
 * normalised); *certified: a minimum along the family; *evals: the members evaluated.
 * EL_EDOM: none, EL_ENOMEM. */
int el__fit_natural_fit(fit_objective *ob, double noise, double *v, int *certified, int *evals);
/* fit_g1_family.c: a smooth fit by distance joined G1 at both ends (ob's map: the start
 * state chart, the start tangent held; con: the normalised end points and tangents): the
 * el_hermite_solve solutions of those ends nearest the points over a scan of the tension
 * whose objective is below f_below (the fit's, |r|^2 / 2n): at most *count (in: > 0; out:
 * how many), the lowest objectives of other families (*count - 1) and the lowest that
 * follows the points (el__fit_stray), then the lowest again while there is room
 * (normalised parameters v[j]; noise: el__fit_noise_rms, normalised); then, between
 * nearly collinear ends, up to `waves` small waves along the chord (v[*count] on, *count
 * counts them too). EL_EDOM: none, EL_ENOMEM. ob's feet are left at the last member's. */
int el__fit_g1_family_start(fit_objective *ob, const fit_constraints *con, double noise, double f_below,
                            double (*v)[FIT_NP], int *count, int waves);
/* fit_natural.c: the moduli bounding the natural batten's family: k* (2E = K, the figure
 * eight) and k_t (lobes j and j + 2 touch). */
int el__natural_moduli(double *kstar, double *ktouch);
/* fit_restart.c: the curve's length of a fit's result. */
double el__fit_out_length(int model, size_t n, const fit_out *r);
/* fit_restart.c: a fit by distance whose result *res (d, fs its distances and feet,
 * input units) strays from its points by stray (el__fit_stray) fitted again from the
 * paired fit's curve, which replaces it when it follows them or strays less than half
 * as far, and (a free fit, flags without FIT_RUN_NO_OTHER) from the other model's fit,
 * which replaces it when it follows them at a lower rms; EL_OK (replaced or not) or
 * EL_ENOMEM. */
int el__fit_follow_points(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, double noise,
                          double scale, double stray, fit_out *res, double *d, double *fs);

/* fit_follow.c: el__fit_follow_points on a copy of the smooth fit *res (d, fs), kept when it
 * returns lower and not crossing itself (el__fit_loops in ob's map; norm: the fit's
 * normalisation cx, cy, sc); EL_OK (replaced or not) or EL_ENOMEM. */
int el__fit_follow_unless_loops(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                                double noise, double stray, fit_objective *ob, const double norm[3], fit_out *res,
                                double *d, double *fs);
/* fit_follow.c: a sketch's free smooth fit (fewer than SKETCH_POINTS points, fit.c) in *res
 * (d, fs: its distances and feet; noise: the data's figure, input units; ob, norm: as
 * el__fit_follow_unless_loops) that wanders (strays from its points or crosses itself where
 * their polygon does not): the guesses fitted from their own feet, the lowest that does
 * neither kept (*replaced = 1) when its rms is at most FIT_SKETCH_TOL of the data's size
 * above *res's (a sketch is drawn to about that). res->status, or EL_ENOMEM. */
enum { FIT_SKETCH_GUESSES = 6 };
#define FIT_SKETCH_TOL 0.01
int el__fit_sketch_follows(const double *xy, size_t n, const el_fit_options *opt, double noise,
                           fit_objective *ob, const double norm[3], fit_out *res, double *d,
                           double *fs, int *replaced);
/* fit_follow.c: the same for a sketch's constrained smooth fit: its constraints fitted from
 * the free fit's curve and the guesses, each from its own feet; kept as there, when it meets
 * them too. res->status, or EL_ENOMEM. */
int el__fit_sketch_follows_held(const double *xy, size_t n, const el_fit_options *opt, double noise,
                                fit_objective *ob, const double norm[3], fit_out *res, double *d,
                                double *fs);
/* fit_follow.c: el__fit_fallback, undone where its result crosses itself (el__fit_loops);
 * its status, or the kept fit's. */
int el__fit_fallback_unless_loops(int model, const double *xy, size_t n, const el_fit_options *opt, int flags,
                                  fit_objective *ob, const double norm[3], fit_out *res, double *d, double *fs);
/* fit_restart.c: an uncertified fit fitted again from its result by Ipopt (flags
 * FIT_RUN_POLISH; FIT_RUN_ROWS: pinned at both ends, the end point as Ipopt's rows), which replaces *res
 * (d, fs) when certified or, without rows, lower; EL_OK when replaced by a certified fit,
 * else res->status, or EL_ENOMEM. */
int el__fit_fallback(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, fit_out *res,
                     double *d, double *fs);
/* fit_restart.c: a discrete fit paired by the spacing test alone (*res, d, fs) whose points
 * slip along its polygon from their vertices, fitted again by distance to the polygon from
 * its result (when it converged); whose points jump a vertex (el__fit_skips), slip from an
 * unconverged fit, or that lies farther from its points than PAIRED_FAR x their noise
 * (noise: el__fit_noise_rms, input units), fitted by distance afresh (the fit
 * distance="orthogonal" gives); the refit replaces it when lower; res->status, or EL_ENOMEM. */
int el__fit_unpaired(int model, const double *xy, size_t n, const el_fit_options *opt, double noise, fit_out *res,
                     double *d, double *fs);
/* fit_pairing.c: whether the points slip along a paired fit's polygon (segment h, their
 * feet fs and rms distance to it, one units; a free fit's distances d, else NULL) by more
 * than PAIRING_SLIP times the noise across it; whether their mean slip steps by PAIRING_STEP vertices or more from one
 * stretch of points to the next (el__fit_unpaired's tests). */
int el__fit_slips(size_t n, double h, double rms, const double *d, const double *fs);
int el__fit_skips(size_t n, double h, double rms, const double *fs);
/* fit_pairing.c: whether a paired fit's polygon (segment h, feet fs, input units) runs past
 * its points at an end by more than FIT_RETRACE_PAST (fit_ends.h) x noise (input units) and 3 h. */
int el__fit_overruns(size_t n, double h, double noise, const double *fs);
/* fit_restart.c: a fit pinned at both ends with a zero start curvature (*res, d, fs, from the
 * start-state chart with the end point as Ipopt's rows) fitted again in the ends chart with
 * that curvature held (FIT_RUN_ENDS_HELD), which replaces it when certified and lower or
 * where it gave no fit that meets the constraints; res->status, or EL_ENOMEM. */
int el__fit_ends_held(int model, const double *xy, size_t n, const el_fit_options *opt, fit_out *res, double *d,
                      double *fs);
/* fit_restart.c: *res (d, fs its distances and feet; d may be NULL) replaced by the refit alt
 * (buf: its distances, then its feet), the iterations and candidates of both counted. */
void el__fit_replace(fit_out *res, fit_out *alt, const double *buf, size_t n, double *d, double *fs);
/* fit_restart.c: a fit with constraint rows whose start-state chart is off (bounds or fixed
 * values on its slots) fitted again by the other optimiser (Ipopt's L-BFGS from each guess),
 * which replaces *res (d, fs) when it meets the constraints at a lower rms (by more than 1e-9
 * of it); res->status, or EL_ENOMEM. */
int el__fit_other_path(int model, const double *xy, size_t n, const el_fit_options *opt, fit_out *res,
                       double *d, double *fs);
/* fit_restart.c: el__fit_run afresh (opt, flags | FIT_RUN_INNER), which replaces *res (d, fs)
 * when certified and below res->rms (1 - margin), or where *res is no curve; res->status, or
 * EL_ENOMEM (el__fit_ends_held, el__fit_other_path). */
int el__fit_refit_lower(int model, const double *xy, size_t n, const el_fit_options *opt, int flags, double margin,
                        fit_out *res, double *d, double *fs);

/* Ipopt from x (in place; the best point seen on return) with bounds xl, xu (+-HUGE_VAL:
 * none) and constraints con (NULL: none). */
int el__fit_ipopt(fit_objective *o, const double *xl, const double *xu, const fit_constraints *con,
                  const el_fit_options *opt, double *x, fit_ipopt_out *out, double *tmp);
/* Constraint values c (rows in the order of the mask bits; the start point is held
 * parameters, the length and k ranges bounds, so neither has rows), their kinds which[]
 * and, when J != NULL, their derivative in x (rows x nx); returns the row count, -1
 * when the curve cannot be evaluated. tmp: FIT_WORK doubles. */
int el__fit_constraint_rows(const fit_objective *o, const fit_constraints *con, const double *x,
                            double *c, double *J, int *which, double *tmp);

/* ---- the end constraints (fit_constraints.c) */

/* The slots of the length and of k in the parameter vector of each model. */
static inline int fit_length_slot(int model) { return model == FIT_DISCRETE ? 2 : 6; }
static inline int fit_k_slot(int model) { return model == FIT_DISCRETE ? 6 : 4; }
/* The options' check (el_fit_smooth's EL_EINVAL cases; which: the constraint bit at
 * fault, 0 for others). */
int el__fit_check_options(const el_fit_options *o, int model, int *which);
/* The options' constraints in normalised units (centre cx, cy, scale sc) into con, and
 * the bounds on the length and k they add to lo, hi. */
void el__fit_setup_constraints(const el_fit_options *o, int model, size_t n, double cx, double cy,
                               double sc, fit_constraints *con, double *lo, double *hi);
/* The constraint bit the normalised parameters v violate most (0: none). */
int el__fit_violated(const fit_objective *ob, const fit_constraints *con, const double *v,
                     const double *lo, const double *hi, double *tmp);
/* fit_constraints.c: the point x of a fit (map's variables) meets the constraints con and
 * the bounds lo, hi (normalised parameters). */
int el__fit_meets(fit_objective *ob, const fit_map *map, const fit_constraints *con,
                  const double *x, const double *lo, const double *hi, double *tmp);
/* A start for a fit with a start tangent or curvature (bits) by continuation in the
 * start-state chart; x: out's variables; fs: the free fit's f and the last stage's (0, 0
 * where a stage failed). Returns the iterations spent. */
int el__fit_held_start(fit_objective *ob, const fit_map *out, const fit_map *free_map, int bits,
                       const fit_constraints *con, int max_iter, const double *p0, double *x,
                       double *fs);
/* How many of one end's constraints a fit would hold exactly at its start (weighted). */
int el__fit_held_score(const el_fit_options *o, int model, int at_end);
/* p (input units, n points) replaced by the same curve run backwards, canonical. */
int el__fit_reverse_params(int model, size_t n, double *p);

#endif
