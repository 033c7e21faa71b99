/* Internal helpers shared by the library's files (not installed). */
#ifndef EL_INTERNAL_H
#define EL_INTERNAL_H

#include "elastica.h"
#include <math.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A hot inner function inlined into its callers (where the compiler would not by itself:
 * the B-spline fit's loops with the degree a constant, the Jacobi walk's addition step, the
 * Hermite objective's shape_prepare). */
#ifdef __GNUC__
#define EL__INLINE static inline __attribute__((always_inline))
#else
#define EL__INLINE static inline
#endif

/* Turn GSL's aborting error handler off (once per process, thread-safe); every
 * entry point that calls GSL calls this first and maps GSL statuses to EL_ codes. */
void el__gsl_quiet(void);

/* EL_OK when all n values are finite. */
int el__all_finite(const double *v, size_t n);

/* Small dense systems (dense.c; no GSL error handler is ever called): LU with partial
 * pivoting of the n x n row-major a in place (EL_ESINGULAR on a zero pivot) and its
 * solve of b in place; A x = b for symmetric positive definite a by Cholesky
 * (EL_ESINGULAR when it is not, numerically). */
int el__lu_factor(double *a, int n, int *perm);
void el__lu_solve(const double *a, int n, const int *perm, double *b);
int el__cholesky_solve(double *a, int n, double *b);

/* Checked size arithmetic: every array size the library computes goes through
 * these, so none can wrap around. Return 0 and store the result, or 1 when it
 * would exceed SIZE_MAX (no such array can exist; callers answer EL_ENOMEM for
 * what they allocate, EL_EINVAL for a count the caller claims to hold). */
static inline int el__size_mul(size_t a, size_t b, size_t *out)
{
    if (b != 0 && a > (size_t)-1 / b) return 1;
    *out = a * b;
    return 0;
}

static inline int el__size_add(size_t a, size_t b, size_t *out)
{
    if (a > (size_t)-1 - b) return 1;
    *out = a + b;
    return 0;
}

/* 1 when count elements of per * elem bytes each do not fit in memory (the
 * product wraps around SIZE_MAX), e.g. el__too_many(n, 2, sizeof(double)) for n
 * interleaved points; 0 otherwise. */
static inline int el__too_many(size_t count, size_t per, size_t elem)
{
    size_t t;
    return el__size_mul(count, per, &t) || el__size_mul(t, elem, &t);
}

/* malloc of count * per elements of elem bytes; NULL when that wraps or fails. */
void *el__alloc(size_t count, size_t per, size_t elem);
/* realloc likewise; p is left untouched (still owned by the caller) on NULL. */
void *el__realloc(void *p, size_t count, size_t per, size_t elem);

/* Carlson's R_F(x, y, z) (when rf != NULL) and R_D(x, y, z) in one duplication loop
 * (ellint.c); x, y >= 0, not both 0, z > 0. qs = 1: double precision; qs < 1:
 * relative accuracy ~1e-16 qs^-8 (qs = 0.2: 4e-11), fewer duplication steps.
 * EL_EDOM on bad arguments, and where R_D's duplication sum (num / den) overflows: its
 * domain ends where the arguments spread over ~27 decades and more (measured at qs = 1:
 * EL_EDOM from (1, 1, 2.4e27), (0, 7.7e29, 1), (2.7e68, 2.7e68, 1); at qs = 0.1 from
 * (0, 2.8e34, 1)); the Hermite objective's arguments (x, y <= 1, z = 1) are inside it
 * (checked for k'^2 down to 1e-300). */
int el__carlson_fd(double x, double y, double z, double qs, double *rf, double *rd);
/* The complete integrals K(k) and D(k) = int_0^(pi/2) sin^2 / sqrt(1 - k^2 sin^2) =
 * (K - E)/k^2 for 0 <= k < 1, given kc2 = 1 - k^2 formed without cancellation
 * (ellint.c, AGM). EL_EDOM unless kc2 > 0. D = NULL: K alone (the same bits, cheaper). */
int el__ellint_complete(double k, double kc2, double *K, double *D);

/* What el_jacobi_eval precomputes for one modulus k: kg = min(k, 1/k), its
 * complementary modulus kp = sqrt(1 - kg^2) formed without cancellation, the
 * quarter period K(kg) and the complete integrals D, J over [0, pi/2]; J only
 * with_dk (it serves the k-derivatives alone; NaN otherwise). */
typedef struct el__modulus {
    double k, kg, kp, K, Dc, Jc;
} el__modulus;
int el__modulus_init(double k, int with_dk, el__modulus *mod);
/* el_jacobi_eval for a prepared modulus: the cheap path for many u at one k
 * (d_dk only if the modulus was prepared with_dk). */
int el__jacobi_eval_mod(const el__modulus *mod, double u, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk);
/* el__jacobi_eval_mod without am (val->am NaN) and derivatives: the other values and the
 * status the same bits, without am's atan2 (el__smooth_ends' two evaluations). */
int el__jacobi_values(const el__modulus *mod, double u, el_jacobi *val);

/* el_smooth_eval(p, 2, {0, p->length}, xy, th, NULL) for the two ends alone (smooth.c):
 * the same steps, bits and statuses without the set-up for many samples (the Hermite
 * solutions' end-residual checks, hermite.c). */
int el__smooth_ends(const el_smooth_params *p, double xy[4], double th[2]);

/* A smooth curve prepared for evaluation one s at a time (smooth.c: Newton's steps along
 * it, fit_nearest.c): the modulus, the base point's values and the rotation computed once.
 * el__smooth_point(c, s, ...) is el_smooth_eval(p, 1, &s, ...): the same steps, bits and
 * statuses (xy, theta, kappa may be NULL; NaN with EL_EDOM), without the per-call set-up
 * (a modulus and two Jacobi evaluations where the point needs one). el__smooth_prepare:
 * EL_EINVAL for bad parameters (el_smooth_check), EL_EDOM where the modulus or the base
 * point overflow (el_smooth_eval then fails at every s). */
typedef struct el__smooth_curve {
    el_smooth_params p;
    el__modulus mod;
    el_jacobi base;              /* the Jacobi values at u = q */
    double w, iw, c, s;          /* sqrt(mu), 1 / sqrt(mu), cos phi, sin phi */
} el__smooth_curve;
int el__smooth_prepare(const el_smooth_params *p, el__smooth_curve *c);
int el__smooth_point(const el__smooth_curve *c, double s, double xy[2], double *theta, double *kappa);

/* Jacobi sn, cn, dn, D (and k-derivatives) at many u_i at a few flops per point
 * (jacobi_walk.c; am and E are not filled). The caller keeps max(1, k)|u_i| <= EL__PHASE_MAX.
 *   el__walk wk;
 *   el__walk_init(&wk, k, with_dk, n);         any u_i (fast when sorted), or
 *   el__walk_grid(&wk, u0, z);                 after init: u_i = u0 + z i, u ignored;
 *   el__walk_values(&wk, count, u, val, dk);   the next count points (call repeatedly);
 * with n < WALK_MIN_POINTS every point gets a fresh el__jacobi_eval_mod (setup would
 * cost more). dk[count] only when with_dk. Statuses: those of el__jacobi_eval_mod. */
enum { WALK_PLAIN, WALK_GRID, WALK_ANCHORED, WALK_MIN_POINTS = 8,
       WALK_RESEED = 32 /* addition steps from a fresh evaluation, at most (jacobi_walk.c) */ };
typedef struct el__walk {
    el__modulus mod;
    double k, kappa;           /* k >= 0 and max(1, k) */
    int with_dk, mode, from_grid;
    double u0, z;              /* the grid u0 + z i, next = the index of the next point */
    size_t next;
    el_jacobi zstep, zstepk, cur, curk;
    double H, ua;              /* anchor spacing; where the anchors' fresh evaluation is */
    int jlo, jhi;              /* the anchors ua + j H computed, jlo <= j <= jhi; jlo > jhi: none */
    int have_hstep, have_series;
    /* anchor j at [WALK_RESEED + j], |j| <= WALK_RESEED */
    el_jacobi hstep[2], hstepk[2], anc[2 * WALK_RESEED + 1], anck[2 * WALK_RESEED + 1];
    double ser[8][6];          /* Maclaurin coefficients of sn cn dn D and their k-derivatives */
} el__walk;
int el__walk_init(el__walk *wk, double k, int with_dk, size_t n);
int el__walk_grid(el__walk *wk, double u0, double z);
int el__walk_values(el__walk *wk, size_t count, const double *u, el_jacobi *val, el_jacobi *dk);

/* The largest max(1, k)|u| whose Jacobi functions keep digits: 2K is known to a
 * rounding, so reducing u costs |u| 2^-53 of the phase (a quarter at this bound). */
#define EL__PHASE_MAX 0x1p50

/* Join count clamped planar B-splines of one degree p in 3..7, each on its own
 * parameter interval, end to end into *out (parameters shifted to follow each
 * other), C2 at the joints (knot multiplicity p - 2): each joint pole is the
 * next part's first, then the joint knot is removed twice (Piegl & Tiller A5.8),
 * which is exact when the parts meet with equal point, first and second
 * derivatives. *err: the largest gap between the parts' joint poles and removal
 * distance (a bound on how far *out is from the parts); out->max_deviation = -1.
 * bspline.c. Errors: EL_EINVAL, EL_ENOMEM. */
int el__bspline_join_c2(const el_bspline *parts, size_t count, el_bspline *out, double *err);

/* ---- seed 003 curves (blend.c, for blend_bspline.c) */

/* Whether b is an initialised basis (a known kind, d finite and positive). */
int el__blend_basis_ok(const el_blend_basis *b);
/* span_at / basis_at of blend.c: f_j (h_j) and derivatives at one t; NULL outputs skipped. */
int el__blend_span_at(const el_blend_basis *b, double t, double f[4], double df[4], double d2f[4]);
int el__blend_basis_at(const el_blend_basis *b, double t, double h[4], double dh[4], double d2h[4]);
/* blend_hull.c: the exact min over t in [0, 1] and i of h_i(t), and where (t). */
int el__blend_basis_min(const el_blend_basis *b, double *vmin, double *tmin);
/* blend_hull.c: -sn'' as a function of s = sn(u; m): S(s) = (1 + m) s - 2 m s^3. */
double el__blend_sn_S(double m, double s);
/* phi(t) and phi'(t) of one segment with control points q (8 doubles); xy or dxy
 * may be NULL. Errors: those of the basis evaluation. */
int el__blend_segment_at(const el_blend_basis *b, const double *q, double t, double xy[2], double dxy[2]);

/* ---- elastic spline pieces (spline_piece.c, for spline_chain.c) */

enum { EL__NV = 5 };                          /* piece unknowns v: phi, ln mu, k, q, L */
enum { EL__SP_PHI, EL__SP_NU, EL__SP_K, EL__SP_Q, EL__SP_L };
enum { EL__SP_HALVINGS = 12 };                /* step halvings of a Newton step */

/* One piece from (0, 0) to the chord (dx, dy) (spline_piece.c's comment). */
typedef struct el__spiece {
    double v[EL__NV];
    double dx, dy, h;            /* chord (spline.c's units); h: its length, the scale of R
                                    (next to a guide duck: the length with the duck on its base) */
    double cx0, cy0, gn[2];      /* next to a guide duck: the chord with every guide on its
                                    base, and the span's unit normal the guides move along
                                    (gn = 0: no guide duck at either end) */
    double R[EL__NV];            /* residuals at v */
    double th0, th1, kap0, kap1, dkap0;
    double energy, Kq;           /* integral kappa^2 ds; K of the modulus min(|k|, 1/|k|) */
    double st[EL__NV];           /* its start state (theta0, kappa0, kappa0', sigma, L) */
    double M[EL__NV * EL__NV];   /* d st / d v */
    double D[5][EL__NV];         /* J^{-1} R, J^{-1} e2, J^{-1} e3, h^2 J^{-1} e4 and, next to a
                                    guide duck, J^{-1} (gn / h, 0, 0, 0) (its end moved along gn) */
    double c0[5], c1[5], cL[5];  /* g0 . D[r], g1 . D[r], D[r][L] */
    double jv[EL__NV], jh;       /* v and h where D[1..3], c0, c1, cL were last computed */
    int jac_ok;                  /* 1: they were, and jv, jh say where (el__spiece_jac_current) */
} el__spiece;

/* A piece's Newton step (el__spiece_step_prepare). */
typedef struct el__spstep {
    double v0[EL__NV], s0[EL__NV], ds[EL__NV];   /* parameters and state before, state step */
} el__spstep;

/* A piece's targets: end angles ta, tb and tension s, and which of the spline's
 * unknowns they are (slot index, -1: none, -2: the common sigma); ga, gb: the
 * slot holding the offset of a guide duck at its start / end (-1: none). */
typedef struct el__sptargets {
    double ta, tb, s;
    long ia, ib, is, ga, gb;
} el__sptargets;

/* Residuals, end angles and curvatures, state, energy; with jac also M, the LU
 * of J and the eliminated columns D with c0, c1, cL. EL_EDOM, EL_ESINGULAR. */
int el__spiece_eval(el__spiece *pc, const el__sptargets *t, int jac);
/* 1 when the piece's D[1..3], c0[1..3], c1[1..3], cL[1..3] are those of its current v and h
 * (an evaluation with jac succeeded there since; they depend on nothing else: not on the
 * targets, which enter D[0] alone), else 0. */
int el__spiece_jac_current(const el__spiece *pc);
/* v from a state (theta0, kappa0, kappa0', sigma, L). EL_EDOM. */
int el__spiece_set_state(el__spiece *pc, const double *st);
/* A step dv taken in the state: prepare (returns the admissible fraction <= al), apply. */
double el__spiece_step_prepare(const el__spiece *pc, const double *dv, el__spstep *ps, double al);
int el__spiece_step_apply(el__spiece *pc, const el__spstep *ps, double al);
/* The piece alone (fixed targets) to max |R| <= tol: EL_OK or EL_ENOCONV. */
int el__spiece_newton(el__spiece *pc, const el__sptargets *t, double tol);
/* Start from the linearised batten; or from the least-energy Hermite elastica of that turning. */
int el__spiece_start(el__spiece *pc, const el__sptargets *t);
int el__spiece_hermite(el__spiece *pc, const el__sptargets *t);
/* max |v_i|. */
double el__max_abs(const double *v, size_t n);

/* ---- the elastic spline's chain (spline_chain.c), its paths (spline_path.c) */

/* A knot's unknown x_i: its tangent angle, none (a clamped end), or at a G2
 * end (angle fixed) the offset of its guide duck along its span's normal. */
enum { EL__SLOT_ANGLE, EL__SLOT_FIXED, EL__SLOT_GUIDE };
/* Unknowns beyond the tridiagonal knot system (spline_chain.c): the guide
 * offsets (at most two), sigma and the bend parameter (spline_g2_bend.c). */
enum { EL__MAX_BORDER = 4 };

/* A guide duck of a G2 end (spline_guide.c): knot `knot` on the span from point
 * `pa` to pa + 1, at the fraction f of its chord plus x[slot] times the span's
 * unit normal (nx, ny) (internal units; h: the span's chord). */
typedef struct el__spguide {
    size_t knot, slot, pa;
    double f, nx, ny, h;
} el__spguide;
/* With sigma unknown, the border equation: the total length, or the
 * pseudo-arclength step of spline_path.c. */
enum { EL__BORDER_NONE, EL__BORDER_LENGTH, EL__BORDER_ARC };
/* Newton iterations of a first attempt and of a continuation step (a solve that
 * needs more is better served by smaller steps). */
enum { EL__SP_DIRECT_ITER = 20, EL__SP_STEP_ITER = 12 };
/* Newton iterations from the taut batten's start (spline_path.c's TAUT_START). */
enum { EL__SP_TAUT_ITER = 60 };
/* Step halvings of a continuation step's Newton (EL__SP_HALVINGS elsewhere). */
enum { EL__SP_STEP_HALVINGS = 4 };
/* Residual of a state that is a solution up to what the parametrisation resolves
 * (header: near the separatrix, near a circle), accepted on the way. */
#define EL__SP_NEAR 1e-6
/* The residual a spline whose pieces are circular arcs (kappa^2 = sigma, no
 * force: |k| = infinity) reaches in el_smooth_params (|k| ~ 1e4: ~1e-8). */
#define EL__SP_CIRCLE_RESID 1e-7

/* A solved state of the chain: knot values, every piece's v and state, sigma. */
typedef struct el__spsnap {
    double *x, *v, *st, sigma;
} el__spsnap;

/* WORK_BUDGET (spline.c): chain evaluations (each evaluates every piece once) spent by one
 * el_spline_solve call over every solve and search it makes, and the most allowed; stopped:
 * the budget refused an evaluation (el__chain_eval then evaluates nothing, returns INFINITY) */
typedef struct el__spwork {
    unsigned long evals, budget;
    int stopped;
} el__spwork;

/* 1 where the call's budget is spent (no further evaluation will be made), stopped set */
static inline int el__spwork_spent(el__spwork *w)
{
    if (!w || w->evals < w->budget) return 0;
    w->stopped = 1;
    return 1;
}

typedef struct el__spchain {
    size_t n, m;             /* knots (the points and the guide ducks), pieces */
    int closed;
    int lmode;               /* sigma unknown: the EL__BORDER_ equation; 0: sigma given */
    int kind[2];             /* open: end kinds */
    double th_end[2], kg[2]; /* clamped angles, G2 curvatures (internal units) */
    double wind;             /* closed: 2 pi times the turning number */
    double sigma, Lt;        /* common tension, target length (internal) */
    double sigma_user;       /* tension mode: the sigma asked for (user units) */
    double *x, *ell;         /* slot values, local chord per knot */
    int *slot;
    int ng;                  /* guide ducks (G2 ends) */
    el__spguide guide[2];
    long *guide_at;          /* per knot: its index in guide[], or -1 */
    el__spiece *pc;
    double *F, *dg, *up, *lo, *b, *y, *z;               /* Newton work, n each */
    double *bcol, *brow, *bz;   /* the border (EL__MAX_BORDER n each, spline_chain.c) */
    double bmat[EL__MAX_BORDER * EL__MAX_BORDER], bg[EL__MAX_BORDER];
    int *border;             /* per knot: its border index (slot GUIDE), or -1; sigma's is ng */
    double *xs;              /* backup of x */
    el__spstep *ps;          /* the pieces' Newton steps */
    double Gres;             /* border residual */
    double gscale;           /* its weight in the merit (el__chain_newton) */
    double den;              /* d(border residual)/d sigma along the solutions, last iterate */
    int contract;            /* el__chain_newton: only while it contracts */
    int halvings;            /* el__chain_newton: step halvings at most */
    int newton_first;        /* length mode: try Newton before the continuation */
    double *snapbuf;         /* the snapshots' arrays */
    el__spsnap snap[3];
    double *arc_a, *arc_x0;  /* BORDER_ARC: arc_a . (x - arc_x0) + arc_b (sigma - arc_s0) = arc_h */
    double arc_b, arc_s0, arc_h;
    double arc_c, arc_L0;    /* + arc_c (L - arc_L0) when arc_len (spline_path.c) */
    int arc_len;             /* el__spline_follow_family: the length a coordinate of its path */
    int bend;                /* spline_g2_bend.c: tau unknown, kg = bend_k + tau bend_dk, the border
                                equation arc_a . (x - arc_x0) + bend_c (tau - bend_t0) = arc_h */
    double tau, dtau, bend_k[2], bend_dk[2], bend_c, bend_t0, Bres;
    int bent_arc;            /* el__spline_bend_ends reached kg only by that path */
    double reach[3];         /* length mode: the least and the greatest length of the solutions
                                el__spline_follow_family met, the greatest of those that do not
                                cross themselves (0: none met) */
    double ladder[2];        /* spline_bracket.c: the least and greatest sigma of tension
                                mode's splines its ladder reached (0: none) */
    double resid;            /* max residual of the last evaluation */
    int iterations, max_iter;
    double tol, aim;         /* accepted and aimed-at residual */
    int near;                /* the state is a solution to what the parametrisation resolves */
    int leap;                /* el__spline_follow_family: leap once over a stall (spline_path.c) */
    int jump;                /* el__spline_follow_family: refuse a step onto another branch (JUMP) */
    int would_leap, would_jump; /* el__spline_follow_family without leap / jump: a step where the
                                   rule would have acted was met (SAME_PATH, spline_path.c) */
    int neighbours;          /* el__spline_solve_tension: from fair nearby tensions (spline_path.c) */
    int plain;               /* el__spline_length_from: the plain follow only, no retries (spline.c's
                                FREE_FAMILY comparison) */
    el__spwork *work;        /* the call's work and budget (spline.c's WORK_BUDGET), shared by every
                                chain of its solves (a guided chain takes its sibling's); NULL: none */
} el__spchain;

/* The workspace for n knots and m pieces (zeroed, n, m set); free it also on failure. */
int el__chain_alloc(el__spchain *w, size_t n, size_t m);
void el__chain_free(el__spchain *w);
/* Piece j's targets from the knot values. */
void el__chain_targets(const el__spchain *w, size_t j, el__sptargets *t);
/* Every piece and the knot (and border) residuals; returns the merit, or INFINITY. */
double el__chain_eval(el__spchain *w, int jac);
/* el__chain_eval of a state already known (a snapshot just loaded, el__chain_newton's restore,
 * the straight line): made past the call's budget too, and counted (spline_chain.c) */
double el__chain_reeval(el__spchain *w, int jac);
/* 1 when every piece's Jacobian coefficients are current (el__spiece_jac_current) */
int el__chain_jac_current(const el__spchain *w);
/* Newton on the chain until max residual <= aim (or it stalls), at most cap
 * iterations; EL_OK when it ends <= accept, else EL_ENOCONV. */
int el__chain_newton(el__spchain *w, int cap, double aim, double accept);
/* The start: knot angles, then every piece (EL_OK, EL_ENOCONV, EL_ENOMEM). */
void el__chain_start_angles(el__spchain *w);
/* Tangent angles of the taut batten (sigma -> infinity): the bisectors of the chords,
 * natural ends along their chord (spline_path.c's TAUT_START). */
void el__chain_taut_angles(el__spchain *w);
/* Longer than EL__SP_WANDER x its polygon, or looping as el_spline_result's loops says
 * (el__chain_crosses, spline_fair.c): not the batten through its ducks */
int el__chain_wanders(const el__spchain *w);
int el__chain_start_pieces(el__spchain *w);
/* a - 2 pi j in [-pi, pi]. */
double el__wrap_pi(double a);

/* The tension solution at w->sigma (final: to w->tol, else to EL__SP_NEAR). */
int el__spline_solve_tension(el__spchain *w, int max_steps, int final);
/* Its NEIGHBOURS (spline_path.c) after the plain solve at target (w->neighbours 0, final)
 * gave st and the chain in w (w->near): el__spline_solve_tension's status with neighbours
 * (spline_bracket.c's NEIGHBOURS_RUNGS, from the plain solves its first ladder made). */
int el__spline_tension_neighbours(el__spchain *w, int max_steps, int st, double target);
/* Length mode: the solution of total length Lt (internal units): from the
 * start, else from the free batten (el__spline_free_batten: sigma = 0, or as
 * near as continuation gets) by el__spline_length_from (its tension solution
 * followed in length). */
int el__spline_solve_length(el__spchain *w, int max_steps, double Lt);
int el__spline_free_batten(el__spchain *w, int max_steps);
int el__spline_length_from(el__spchain *w, int max_steps, double Lt);
/* spline_bracket.c: length mode from the tension solutions (tension mode's, at a ladder of
 * tensions) that bracket the length Lt, where the paths above failed; least: of the near
 * splines reached, the one of least residual (else the first). */
int el__spline_length_by_tension(el__spchain *w, int max_steps, double Lt, int least);
/* From the tension solution in w to the one at sigma (internal units), by continuation
 * in sigma, to w->tol. */
int el__spline_tension_from(el__spchain *w, int max_steps, double sigma);
/* Length mode on collinear points: the buckled batten of length Lt (> the
 * polygon's Lp), the line's direction dir. */
int el__spline_solve_buckled(el__spchain *w, int max_steps, double dir, double Lp, double Lt, int mirror);
/* Ducks near the line of direction dir (every chord advancing along it), length Lt: the
 * buckled batten of the ducks projected onto it, moved to the ducks (spline_path.c). */
int el__spline_solve_near_line(el__spchain *w, int max_steps, double dir, double Lt);
/* spline_buckle.c: the points collinear, in order along their line, with ends that allow the
 * straight line (*dir its direction; G2 ends as clamped); the points near the line through
 * the first and the last (spline_buckle.c's NEAR_LINE), each chord advancing along it,
 * clamped ends near it, no G2 end. 1 or 0. */
int el__spline_straight_line(const double *xy, size_t n, const el_spline_options *o, double *dir);
int el__spline_near_line(const double *xy, size_t n, const el_spline_options *o, double *dir);

/* spline_limit.c: where tension mode failed at sigma h^2 >= EL__SP_STIFF_SH2 on the
 * longest span h (user units: the solve's, el_spline_solve), the largest tension (user
 * units) that solves without loops, its spline's resolution and least |1 - k^2|
 * (el_spline_result's largest), all 0 where not looked for or none of sigma h^2 >= 100
 * solves (or where the tensions sigma h^2 / h^2 are not positive finite doubles); *nsolves:
 * the tension solves it made, their work counted on into *work (el__spline_solve_within;
 * no solve begun once the budget *work carries is spent, spline.c's WORK_BUDGET); EL_OK or EL_ENOMEM */
int el__spline_largest(const double *xy, size_t n, const el_spline_options *opt, double h,
                       double largest[3], int *nsolves, el__spwork *work);
/* spline_stable.c: the Hessian of the chain's energy sum_j (E_j + sigma L_j) in its knot
 * angles, H = 2 (d kappa^- / d theta - d kappa^+ / d theta), into w->dg (diagonal) and w->up
 * (up[i]: H[i][i + 1]), every knot's (fixed ones too); from the pieces' c0, c1, so the chain
 * evaluated with its Jacobians (el__chain_eval(w, 1)) at a solution. */
void el__spline_hessian(el__spchain *w);
/* spline_stable.c: the number of negative eigenvalues of the second variation of a solved
 * open chain in tension mode without guide ducks, reduced to its knot angles (0 otherwise);
 * where > 0, *span the span lengthening most along the least one's vector. Re-evaluates the
 * chain with its Jacobians unless they are current (el__chain_jac_current); its Newton work
 * arrays used. */
int el__spline_unstable(el__spchain *w, size_t *span);
/* The same for any solved open chain without guide ducks, in tension mode (held 0: H's
 * negative count) or with its total length held (held 1: under that constraint, sigma the
 * chain's multiplier; spline_stable.c's file comment), whatever its lmode; *span from H's
 * least eigenvalue's vector (held, H positive definite: the span of the least gamma_j). */
int el__spline_unstable_as(el__spchain *w, int held, size_t *span);
/* STABLE_FAMILY (spline_stable.c): w's tension solution unstable (el__spline_unstable_as): the
 * family followed to its tension from the rungs of sigma h^2 1e-3 .. EL__SP_HIGH_SIGMA, the first
 * stable one of less integral kappa^2 + sigma ds not wandering more into w (*found 1); else w as it
 * was (*found 0). EL_OK or EL_ENOMEM. */
int el__spline_stable_family(el__spchain *w, int max_steps, int *found);
/* el__spline_unstable_as of the result res made from w (spline.c's make_result, the unit S),
 * res's pieces loaded into w first where w holds another chain (w used up); 0 (not judged)
 * where res has another piece count than w's, or a circle piece. */
int el__spline_unstable_result(el__spchain *w, const el_spline_result *res, double S, int held, size_t *span);
/* spline_stable.c: the negative count of the second variation on the length constraint from
 * H (k x k tridiagonal: dg, up; negH its negative count), g = dL / d theta (k) and the m
 * spans' gamma_j = -dL_j / d sigma; -1: not judged (H singular, a gamma_j 0, no memory) */
int el__spline_length_negatives(const double *dg, const double *up, const double *g, size_t k, int negH,
                                const double *gam, size_t m);
/* spline_result.c: 1 for a circle piece, or one near it resolved to more than tol (|k| >= 1e3, or
 * el_smooth_eval's bound past tol of its length: el__spline_make_result's rule) */
int el__spline_circle_piece(const el_smooth_params *p, double tol);
/* spline_buckle.c: the number of negative eigenvalues of T - shift I, T symmetric
 * tridiagonal on rows i0..i1 (diagonal dg, off-diagonal up[i] = T[i][i + 1]) */
int el__tridiag_negatives(const double *dg, const double *up, size_t i0, size_t i1, double shift);
/* spline_buckle.c: inverse iteration on w->dg, w->up (rows i0..i1, positive definite near
 * singular): three solves from 1, normalised by the max norm, into w->z[i0..i1] (w->b its
 * work); EL_OK, or EL_ENOCONV where a solve fails (w->z as it left) or z is not finite. */
int el__tridiag_inverse_iter(el__spchain *w, size_t i0, size_t i1);
/* spline_result.c: what one ulp of a piece's k moves its end state by near the separatrix, in
 * the residual's units (th: its end angles, kmax: its max |kappa|, h: its chord). */
double el__spline_separatrix_bound(const el_smooth_params *p, const double th[2], double kmax, double h);
/* spline_fair.c: 1 when the curve of the m pieces (closed: the last back to the first)
 * crosses itself where the polygon of their knots does not, else 0 (0 where that polygon
 * crosses itself); -1: no memory.
 * el__chain_crosses: el__spline_loops (below) for the chain w without guide ducks (internal
 * units): the one rule the solver's searches and el_spline_result's loops share. */
int el__spline_crosses(const el_smooth_params *p, size_t m, int closed);
int el__chain_crosses(const el__spchain *w);
/* 1 when the curve of the m pieces loops away from its knots (el_spline_result's loops):
 * as el__spline_crosses where their polygon does not cross itself; where it does, a
 * crossing of the curve between pieces (i, j) with none of the polygon's between i +- 1
 * and j +- 1 and, i and j not neighbours, no other of the curve's between i and j +- 1
 * or i +- 1 and j (a lens, not a loop); -1: no memory. */
int el__spline_loops(const el_smooth_params *p, size_t m, int closed);
/* The tension solution in w (st: its status; target: its sigma, internal) where it
 * wanders or failed: the family from the taut batten followed to target (spline_fair.c). */
int el__spline_refair(el__spchain *w, int max_steps, int st, double target);
/* spline_path.c: pseudo-arclength along the tension solutions from the one in w until
 * the length (by_sigma 0) or sigma (1; 2: sigma at most half way per step) is Lt, then
 * Newton there. Snapshots of a chain's state (spline_continuation.c). */
int el__spline_follow_family(el__spchain *w, int max_steps, double Lt, int by_sigma);
/* Follow a one-parameter family from t = 0 (solved, in w) to t = 1, set(w, t, par) moving
 * the target (spline_continuation.c) */
int el__spline_continuation(el__spchain *w, el__spsnap sv[2], int max_steps, double dt,
                            void (*set)(el__spchain *, double, const double *), const double *par,
                            double aim, double accept);
/* Where a continuation ran out of steps after a step that succeeded: its two snapshots
 * and t, dt, to go on from (spline_path.c's LONG_PATH) */
typedef struct {
    el__spsnap cur, prev;
    double t, tp, dt;
    int steps, valid;
} el__cont_rest;
/* el__spline_continuation; rest (or NULL): gone on from where it is valid, kept where the
 * steps run out */
int el__spline_follow(el__spchain *w, el__spsnap sv[2], int max_steps, double dt,
                      void (*set)(el__spchain *, double, const double *), const double *par,
                      double aim, double accept, el__cont_rest *rest);
void el__snap_save(const el__spchain *w, el__spsnap *s);
void el__snap_load(el__spchain *w, const el__spsnap *s);
void el__snap_load_states(el__spchain *w, const el__spsnap *s);
/* The chain set to the state f x (b - a) beyond b (secant predictor; b itself if a piece state is invalid). */
void el__snap_predict(el__spchain *w, const el__spsnap *a, const el__spsnap *b, double f);
/* A tension solution longer than EL__SP_WANDER x its ducks' polygon winds away from them;
 * the high tension (sigma h^2 on the mean chord) continuations start from */
#define EL__SP_WANDER 1.5
#define EL__SP_HIGH_SIGMA 40.0
/* sigma h^2 on the longest span from which a tension mode failure is looked at as the
 * limit of what a double resolves (spline_limit.c): below it other causes dominate */
#define EL__SP_STIFF_SH2 300.0

/* G2 ends (spline_guide.c): the guided chain g of the solved sibling w, its G2
 * ends clamped only (g allocated here; free it also on failure); then the end
 * curvatures moved to kg (spline_g2_bend.c; arc: past folds). */
int el__guides_setup(el__spchain *g, const el__spchain *w);
int el__spline_bend_ends(el__spchain *w, int max_steps, const double kg[2], int arc);
/* spline_g2_bend.c: of two solved guided chains, whether b is as fair as a (no self-crossing
 * before one, then integral kappa^2 + sigma ds (length mode: kappa^2) within 1e-9 of a's or
 * lower); -1: no memory. */
int el__g2_fairer(const el__spchain *a, const el__spchain *b);
/* spline_g2_tension.c: tension mode's G2 batten at sigma (internal units) by its length: a
 * ladder of multiples of Lp (the polygon's length, internal) brackets the length whose G2
 * batten has that tension, Brent narrows it, Newton at sigma finishes, in g. solve(ctx, L,
 * &sigma): the G2 batten of length L into g, as length mode finds it (EL_OK, or a status).
 * EL_OK, EL_ENOCONV (g->near: within EL__SP_NEAR), EL_ENOMEM. nearest: the tension of the
 * rung nearest sigma below it, its length, the same above it (internal units; NAN: none). */
typedef int (*el__g2_length_solve)(void *ctx, double L, double *sigma);
int el__spline_g2_tension_by_length(el__spchain *g, el__g2_length_solve solve, void *ctx, double Lp,
                                    double sigma, double nearest[4]);

/* el_spline_solve; newton_first = 0: length mode by the continuation alone
 * (follow_length, the plain counterpart of the Newton attempts), for the tests. */
int el__spline_solve_paths(const double *xy, size_t n, const el_spline_options *opt,
                           int newton_first, el_spline_result *res);
/* spline_result.c: 1 where every piece of the chain is one (finite unknowns, a positive
 * length) */
int el__spline_pieces_drawn(const el__spchain *w);
/* spline_result.c: res from the solved chain w (user units; xy the npoints points, S the
 * unit), the residual measured; *other: the part of it from joints and ends without a circle
 * piece or a piece whose separatrix bound exceeds tol; *sep: the largest such bound (0: none).
 * EL_OK, EL_ENOMEM, or el_smooth_eval's status for a piece it refuses (EL_EINVAL) */
int el__spline_make_result(const el__spchain *w, const double *xy, size_t npoints, double S, double tol,
                           el_spline_result *res, double *other, double *sep);
/* The same, its work counted on into *work within its budget (the call's, spline.c's
 * WORK_BUDGET: el__spline_largest's solves share el_spline_solve's) */
int el__spline_solve_within(const double *xy, size_t n, const el_spline_options *opt,
                            el__spwork *work, el_spline_result *res);

/* For the tests of spline.c: the piece p as the Hermite elastica of its own ends
 * (h = |gamma(L) - gamma(0)|), v = (phi, ln mu, k, q, L): J[25] = dR/dv with
 * R = ((gamma(L) - end)/h, theta(0) - ta, theta(L) - tb, (2 mu (2k^2-1) - sigma) h^2),
 * g0[5], g1[5] = d kappa(0)/dv, d kappa(L)/dv, M[25] = d(theta0, kappa0, kappa0', sigma, L)/dv,
 * d[12] = d(kappa(0), kappa(L), L)/d(ta, tb, sigma, e) by the implicit function theorem,
 * e: the end point moved along the chord's unit normal (a guide duck's offset). */
int el__spline_piece_jacobians(const el_smooth_params *p, double *J, double *g0, double *g1,
                               double *M, double *d);

#endif
