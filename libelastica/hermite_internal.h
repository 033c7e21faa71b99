/*
 * Internal declarations shared by the Hermite solver's files (seed 004):
 *   hermite_objective.c  the normalised problem: curvature data (Theorem 6), the
 *                        curve through two curvature states (Theorem 7) and the objective;
 *   hermite_tension.c    all solutions for a given tension (seed 004 §4);
 *   hermite_poly.c       the polynomials (18), (40), (45), their real roots, the separatrix
 *                        crossings and the analysis (el_hermite_analyse);
 *   hermite_length.c     all solutions for a given length (hermite_length_trace.c: its
 *                        tracing; hermite_length_chart.c: its points in the charts;
 *                        hermite_length_internal.h);
 *   hermite_chain.c      a solution near the separatrix as a chain split at its saddles;
 *   hermite_near.c       the near-straight solution under tension, from the linear beam;
 *   hermite_case3.c      the solutions next to case 3 (the U-turn), polished from case 3's;
 *   hermite_chord.c      the separatrix loops between tangents along the chord;
 *   hermite_polish.c     a solution's end residual and its polish onto the data;
 *   hermite.c            the public entry points: normalisation, world-frame solutions.
 */
#ifndef EL_HERMITE_INTERNAL_H
#define EL_HERMITE_INTERNAL_H

#include "internal.h"
#include <stddef.h>

/* 4 sqrt(2) K(1/sqrt 2): the period times kappa_m of the sigma = 0 elastica. */
#define C0_PERIOD 10.4882572784299

/* The normalised problem: x(0) = 0, x'(0) = (0, 1), end point P (|P| = 1), end tangent V. */
typedef struct hprob {
    double P1, P2, V1, V2, sigma;
    int hcase;        /* 1, 2, 3 (Theorem 6) */
    double Lmin;      /* lower bound of the length: 1 (tension mode) or L (length mode) */
    double B;         /* kappa_m bound (Theorem 9); < 0: no solution */
    /* 1 / P2 and 1 / (2 V1) (el__hermite_set_case): (19), (20), (22) multiply by them, a
     * division fewer on the way from the unknown to the objective */
    double iP2, i2V1;
} hprob;

/* Curvature data at both ends and the values derived from it. */
typedef struct hstate {
    double k0, k0p, k1, k1p;   /* kappa0, kappa0', kappa1, kappa1' */
    int infl;                  /* inflectional (k < 1) */
    double s0, c0, s1, c1;     /* inflectional: sn, cn of u at both ends */
    int big;                   /* inflectional: u(L) - u(0) exceeds half a period (2 Kc) */
    double L, E;               /* length, energy */
    double f;                  /* objective */
    int has_sep;               /* sep = |F| - sigma given exactly (the separatrix chart) */
    double sep;
} hstate;

/* The kind of curve a curvature state starts (Theorem 7), |F| into *Fn.
 * CLASS_NONE: none the objective covers: F = 0 (the circle kappa_m^2 = sigma,
 * singular, (45)), kappa_m = 0 (straight, handled apart), or non-inflectional with
 * kappa0 kappa1 <= 0 against (44); CLASS_MIXED: see el__hermite_piece_classes. */
enum { CLASS_NONE, CLASS_INFL, CLASS_NONINFL, CLASS_MIXED };

/* Theorem 6, 7: the curvature data for the unknown x on branch b, the curve they
 * start, its length, energy and objective (hermite_objective.c). */
double el__hermite_case3_kappa0(const hprob *pr, int fam);
int el__hermite_curvdata(const hprob *pr, double x, int b, hstate *st);
int el__hermite_state_class(const hprob *pr, const hstate *st, double *Fn);
/* The class of the state at x on branch b (CLASS_NONE where el__hermite_curvdata fails):
 * the two calls inlined into one. */
int el__hermite_x_class(const hprob *pr, double x, int b);
int el__hermite_shape_eval(const hprob *pr, double qs, hstate *st);
/* The same, continued to double precision (qs = 1) where |f| <= fine_below at qs; *fine
 * (may be NULL) says whether the values are double precision. The same values as
 * el__hermite_shape_eval with qs, then with 1, without preparing the state twice. */
int el__hermite_shape_eval_to(const hprob *pr, double qs, double fine_below, hstate *st, int *fine);
/* f alone in the x chart: el__hermite_curvdata then el__hermite_shape_eval's st.f, the same
 * bits (test_hermite_tension.c); NAN and the status where they fail. */
int el__hermite_x_objective(const hprob *pr, double x, int b, double qs, double *f);
/* el__hermite_x_objective at the n abscissae x[0..n) (hermite_lanes.c), four at a time
 * where the processor has AVX2, else two: the same bits, NAN where it fails. */
void el__hermite_x_objectives(const hprob *pr, const double *x, int n, int b, double qs, double *f);
/* The same two at a time (SSE2), and four at a time (AVX2: only where
 * el__lanes4_available(), lanes.h) */
void el__hermite_x_objectives2(const hprob *pr, const double *x, int n, int b, double qs, double *f);
void el__hermite_x_objectives4(const hprob *pr, const double *x, int n, int b, double qs, double *f);
/* el__hermite_x_class at the n abscissae x[0..n) into cls (hermite_lanes.c), four at a time
 * where the processor has AVX2, else two (the scalar class in case 3): the same classes
 * (test_hermite_tension.c); each width by itself */
void el__hermite_x_classes(const hprob *pr, const double *x, int n, int b, int *cls);
void el__hermite_x_classes2(const hprob *pr, const double *x, int n, int b, int *cls);
void el__hermite_x_classes4(const hprob *pr, const double *x, int n, int b, int *cls);
/* The kind of curve on each of the n - 1 pieces between the ascending split points
 * x[0..n) of branch b (n - 1 < HERMITE_GATHER_MAX / 2) into cls[0..n-1): the class at the
 * piece's midpoint; where it has no curve, CLASS_NONE if both quarter points agree, else
 * CLASS_MIXED (a split point missed by rounding: the piece searched as it is). All
 * midpoints classified together, then the quarter points (el__hermite_x_classes). */
void el__hermite_piece_classes(const hprob *pr, int b, const double *x, int n, int *cls);
/* A piece of a branch searched in the x chart (hermite_tension.c): its ends, the separatrix
 * crossings at them (NAN: none), its sample count ns (ns + 1 samples), its kind of curve
 * (CLASS_*). */
typedef struct { double a, b, sep_lo, sep_hi; int ns, cls; } hpiece;
/* cos(pi / ns) for ns < HERMITE_NCOS, cached per solve in cosn (NAN: not yet) */
#define HERMITE_NCOS 32
#define HERMITE_GATHER_MAX 1024
/* The bracketing samples of the np pieces (hermite_lanes.c): piece i's ns + 1 abscissae
 * (Chebyshev spacing, the ends nudged inside: the split points are where the objective is
 * singular or not differentiable) at xs + off[i], room free places after each (the sum of
 * ns + 1 + room at most HERMITE_GATHER_MAX), off[i] = -1 for a piece too narrow to sample;
 * the objective there with Carlson's precision qs into fs, by el__hermite_x_objectives on
 * the samples of all pieces of one kind of curve together. */
void el__hermite_sample_pieces(const hprob *pr, int b, const hpiece *pc, int np, int room, double qs, double *cosn,
                               double *xs, double *fs, int *off);
int el__hermite_full_eval(const hprob *pr, double x, int b, hstate *st);
void el__hermite_set_case(hprob *pr);
/* el__hermite_full_eval with the gradient of L, E and f (and sigma, and |F| - sigma)
 * with respect to the unknown x and sigma on branch b: [0] = d/dx, [1] = d/dsigma;
 * w: the separatrix chart's replaced coordinate (el__hermite_sep_eval). */
typedef struct { double L[2], E[2], f[2], s[2], sep[2], w[2]; } hgrad;
int el__hermite_eval_grad(const hprob *pr, double x, int b, hstate *st, hgrad *g);
/* The same in a chart (u, v; b) of the curvature data (hermite_objective.c): HCHART_X is
 * (x, sigma), HCHART_K1 (kappa1, sigma) in case 1, HCHART_C3 (kappa0, kappa0') in case 3;
 * the gradient is in (u, v); *sigma (may be NULL) gets the state's tension. */
enum { HCHART_X, HCHART_K1, HCHART_C3 };
int el__hermite_chart_eval(const hprob *pr, int chart, double u, double v, int b, hstate *st,
                           hgrad *g, double *sigma);
/* The separatrix chart of a base chart near a state with |F| = sigma (k = 1): the base
 * coordinate number fi (0: u, 1: v) is replaced by y = ln(side (|F| - sigma)), side = +1
 * (inflectional) or -1 (not); other is the base's other coordinate, *w the replaced one
 * (a starting guess in, the state's value out, by Newton on |F| - sigma = side e^y along
 * it; any guess on the same crossing of the separatrix gives the same state). qs: Carlson's
 * precision as el__hermite_shape_eval's; g may be NULL (the state only). The state carries |F| - sigma exactly (hstate.sep), so k'^2 = (|F| - sigma) / (2 |F|)
 * keeps its relative precision however small: the length depends on ln k', which the base
 * coordinates alone cannot carry. The gradient is in the base chart's order with y in
 * place of the replaced coordinate. */
int el__hermite_sep_eval(const hprob *pr, int base, int fi, int b, int side, double y,
                         double other, double qs, double *w, hstate *st, hgrad *g, double *sigma);
/* The derivatives of the curvature data in a chart's coordinates (u [0], v [1]), and
 * sep_point, the state of a base chart at w (the separatrix chart's replaced coordinate)
 * with |F| - sigma there, d, and its derivative dd along w (hermite_objective.c). */
typedef struct {
    double k0[2], k0p[2], k1[2], k1p[2], s[2];
    int has_dsep;
    double dsep[2];   /* d(|F| - sigma), given by the separatrix chart (else from the others) */
} curv_grad;
typedef struct {
    double w, d, dd;
    hprob q;
    hstate st;
    curv_grad cg;
} sep_point;
/* el__hermite_sep_eval with the last call's point kept in *cache (valid = 0 before the
 * first call): a call whose guess *w is the w the last one returned starts its Newton from
 * that point's state instead of evaluating it again: the guess is then that point's w,
 * a few ulps from *w (before sep_exact_state's refinement), and the state the plain
 * call's from there (test_hermite_tension.c). Every call with one cache has the same pr,
 * base, fi, b, other and g = NULL (the state only). */
typedef struct {
    sep_point pt[2];
    int cur, valid;
    double w;
} hsep_cache;
int el__hermite_sep_eval_from(const hprob *pr, int base, int fi, int b, int side, double y, double other,
                              double qs, double *w, hstate *st, hgrad *g, double *sigma, hsep_cache *cache);
/* F(mu, k) and D(mu, k) for the amplitude given by its sine S, cosine C and big = (mu > pi) */
int el__hermite_ell_fd(double S, double C, int big, double k2, double kc2, double qs,
                       double *F, double *D);
double el__hermite_wrap_pi(double a);

/* Real roots of sum c[i] x^i: degree <= 2 (gsl_poly_solve_quadratic), and degree <= 8 in
 * [lo, hi], ascending, to the relative precision tol (hermite_poly.c). */
int el__poly_real_roots(const double *c, int deg, double *roots, int *nroots);
void el__poly_roots_in(const double *c, int deg, double lo, double hi, double tol, double *roots,
                       int *nroots);
/* The same by the roots of the derivatives (the plain counterpart, and the fallback). */
void el__poly_roots_in_plain(const double *c, int deg, double lo, double hi, double tol,
                             double *roots, int *nroots);
/* The coefficients (low to high) of (40), its degree returned; the special values (45)
 * (at most four); the coefficients of (18) in kappa0 (case 1). */
int el__hermite_poly40(const hprob *pr, double c[9]);
int el__hermite_special_values(const hprob *pr, double *out, int *n);
void el__hermite_disc_coeffs(const hprob *pr, double a[3]);

/* The kappa_m bound of Theorem 9 for sigma and the length bound Lmin, *B < 0: no curve
 * (hermite_tension.c). The roots of (40) in [-B, B] ascending, by Bernstein isolation up to
 * SEP_SIGMA and the plain method above; the branch of (17) of such a root (case 1); the
 * root refined on the curvature data of its branch (hermite_poly.c). */
#define SEP_SIGMA 100.0
int el__hermite_kappa_bound(double sigma, double Lmin, double *B);
void el__hermite_poly40_roots(const hprob *pr, double *r, int *nr);
int el__hermite_root_branch(const hprob *pr, double x);
/* The same by el__hermite_curvdata's states on both branches (the tests' reference). */
int el__hermite_root_branch_plain(const hprob *pr, double x);
double el__hermite_crossing_refine(const hprob *pr, int b, double x);

/* Raw solutions of the normalised problem. */
typedef struct { double x; int b; double sigma; hstate st; } hroot;
typedef struct { hroot *v; size_t n, cap; } hrootlist;
/* el__hermite_roots_push's first block: 7 roots, 1008 bytes, within glibc's per-thread cache
 * of small blocks (tcache, up to 1032 bytes), whose malloc and free take a few instructions
 * where a larger block's take the general path (2.5 roots per problem on bench_hermite.py's) */
#define EL__ROOTS_FIRST (sizeof(hroot) <= 504 ? 1008 / sizeof(hroot) : 2)
hroot el__hermite_mkroot(double x, int b, double sigma);
int el__hermite_roots_push(hrootlist *l, const hroot *r);

/* All roots for the tension pr->sigma (hermite_tension.c), for the length Lt
 * (hermite_length.c): samples per search interval ns, sigma lines ng. */
int el__hermite_solve_tension(hprob *pr, int ns, hrootlist *out);
/* The same for the length mode's seed lines: the same roots with fewer samples of the
 * separatrix pieces where the objective is affine there (hermite_tension.c), those pieces
 * searched only above sep_sigma (at least SEP_SIGMA; below, the x chart's roots). */
int el__hermite_seed_tension(hprob *pr, int ns, double sep_sigma, hrootlist *out);
int el__hermite_solve_length(hprob *pr, double Lt, int ng, int ns, hrootlist *out);
/* The same within max_evals objective evaluations of the tracing (EL_EMAXITER beyond, with
 * the solutions found); el__hermite_solve_length's limit is EL__HERMITE_MAX_EVALS. */
#define EL__HERMITE_MAX_EVALS 100000L
int el__hermite_solve_length_limited(hprob *pr, double Lt, int ng, int ns, long max_evals, hrootlist *out);
/* el_hermite_solve with the length mode's work limit max_evals (el_hermite_solve's is
 * EL__HERMITE_MAX_EVALS), the limit of the inner case-3 solve (hermite_case3.c) too: EL_EMAXITER
 * where either tracing stopped at it (the tests' way to reach the limit; hermite.c). */
int el__hermite_solve_limited(const double p0[2], const double t0[2], const double p1[2],
                              const double t1[2], const el_hermite_options *opt, long max_evals,
                              el_hermite_result *res);
/* The same with every trace followed as far as the former search did (the tests' reference). */
int el__hermite_solve_length_thorough(hprob *pr, double Lt, int ng, int ns, hrootlist *out);
/* Every solution of tension sigma > 0 and length L has sigma (L - 1)^2 <= HLEN_SIGMA_E2
 * (|P| = 1; derivation in hermite_length.c, checked in test_hermite_length.c). */
#define HLEN_SIGMA_E2 130.13

/* The near-straight solution under tension (hermite_near.c): the linear beam between
 * tangents t0, t1 (rad from the chord, normalised sigma > 0): theta = c + alpha e^(-g s) +
 * beta e^(-g (1 - s)), g = sqrt(sigma / 2); its start state k0, k0p, length L and
 * |F| - sigma = side e^lnsep. Its root in the separatrix chart appended to out where the
 * tangents lie within NEAR_CHORD rad of the chord, the end point ahead (none else). */
/* (1e-2 and the rounding of an angle measured from the chord: chord at 0.3 rad, tangents
 * 1e-2 rad off it, 0.01000000000000001 from the world's angles: the curve lost) */
#define NEAR_CHORD (1e-2 + 1e-15)
typedef struct { double g, alpha, beta, c, k0, k0p, L, lnsep, amax; int side; } hbeam;
/* below (max |t0|, |t1|), the beam's states stand for the curve's (O(theta^2) relative) */
#define NEAR_EXACT 1e-6
int el__hermite_near_beam(double sigma, double t0, double t1, hbeam *bm);
int el__hermite_near_roots(const hprob *pr, hrootlist *out);

/* The world frame of a problem: the ends, their tangent angles, d = |p1 - p0|, e =
 * 2^ilogb(d) (the exact scaling of the solutions' states, make_solution), and rot, the
 * angle that turns the normalised frame into the world's. Built by el__hermite_normalise. */
typedef struct {
    double p0[2], p1[2], psi0, psi1, d, e, rot;
} hframe;

/* The solution s (one piece, from the root: its curve, length, scalars), whose curve
 * no single el_smooth_params carries to tol, as a chain split at its saddles
 * (hermite_chain.c): sep = |F| - sigma of the curve (exact; in the frame scaled by 2^-ilogb(|p1 - p0|):
 * divided by |p1 - p0|^2 it can underflow), mode and
 * target as el_hermite_solve's (the given sigma or length). EL_OK with s replaced by
 * the chain when its residual is below s's (s->npieces > 1); EL_EDOM when the curve
 * passes no saddle or the chain cannot be built (s unchanged). */
int el__hermite_chain(const hframe *fr, int mode, double target, double sep, double tol,
                      el_hermite_solution *s);

/* hermite.c's: a curve from its start state (theta, kappa, kappa') at tension sigma, length L
 * (sep: |F| - sigma when known exactly); a solution's end residual (hermite_polish.c); whether
 * two solutions are one (length, tension, end curvatures and turning; d the chord). */
int el__hermite_params_from_state(double x0, double y0, double theta, double kappa,
                                  double dkappa, double sigma, double L, const double *sep,
                                  el_smooth_params *p);
int el__hermite_residual(const hframe *fr, const el_hermite_solution *s, double *res);
int el__hermite_same_solution(const el_hermite_solution *a, const el_hermite_solution *b,
                              double d);
/* hermite.c's normalisation (seed 004 §4) of the data p0, u0, p1, u1 (unit tangents, from
 * el__hermite_unit: EL_EINVAL where t has no direction): the world frame fr and the normalised
 * problem's P, V and case in pr; EL_EDOM outside the scales el_hermite_solve takes. The one
 * normalisation of el_hermite_solve and of hermite_case3.c's test of its inner problem. */
int el__hermite_unit(const double t[2], double u[2]);
int el__hermite_normalise(const double p0[2], const double u0[2], const double p1[2],
                          const double u1[2], hframe *fr, hprob *pr);
/* hermite_polish.c: one Newton polish on (phi, mu, k, q, length) kept where the residual
 * improves, and the Gauss-Newton polish with k held at its nearest doubles, in either mode
 * (target: the mode's sigma or length); */
void el__hermite_polish_newton(const hframe *fr, int mode, double target, el_hermite_solution *s);
void el__hermite_polish_fixed_k(const hframe *fr, int mode, double target, el_hermite_solution *s);
/* hermite_polish.c's polish (Newton on the parameters, then with k held at its nearest doubles)
 * and the end curvatures from the curve; hermite_near.c's near-straight curve from the
 * world-frame linear beam where |sigma| |p1 - p0|^2 <= 10 (EL_EDOM: none; else EL_OK with
 * its residual, which can be above tol). */
int el__hermite_polish(const hframe *fr, double sigma, double tol, el_hermite_solution *s);
int el__hermite_near_straight(const hframe *fr, double sigma, double tol, el_hermite_solution *s);
/* el__hermite_polish in either mode (target: the mode's sigma or length): once, then again
 * while it improves and misses tol. */
int el__hermite_polish_to(const hframe *fr, int mode, double target, double tol, el_hermite_solution *s);
/* Whether p is at most one curvature period long (the solution set's bound), to 1e-12 relative,
 * the period as the evaluator's, and, where rounding, to the period's uncertainty from the double
 * k too (hermite_polish.c). */
int el__hermite_within_period(const el_smooth_params *p, int rounding);
/* hermite_near.c: a near-straight root's solution s checked against the root's state st (its
 * end curvatures within 10 % of it: EL_OK, with s's end curvatures and inflection set). */
int el__hermite_near_check(const hframe *fr, const hstate *st, el_hermite_solution *s);
/* hermite_symmetry.c: the solution list closed under the problem's symmetries. */
int el__hermite_add_images(const hframe *fr, const el_hermite_options *opt, double Ln,
                           el_hermite_solution **sol, size_t *n, size_t *cap);

/* hermite_case3.c: where max(|P2|, |V1|) <= EL__HERMITE_CASE3_NEAR (case 1 or 2 next to
 * case 3), the solutions of the case-3 problem (solved within the length mode's work limit
 * max_evals) polished onto the data, each added to the list (*sol, *n, capacity *cap) unless
 * there (el__hermite_same_solution); u0 the unit t0. EL_EMAXITER where the case-3 solve
 * stopped at the work limit (its solutions so far added: the caller's result is incomplete
 * too); EL_ENOMEM (the list freed) where it cannot grow. */
#define EL__HERMITE_CASE3_NEAR 1e-3
/* hermite_chord.c: by tension (sigma > 0) or by length, between tangents along the chord
 * (|P1|, |V1| <= 1e-2, P2, V2 > 0), the whole-period separatrix loops of the exactly symmetric problem (P1 = V1 = 0),
 * each and its mirror image polished onto the data, added at residual <= tol (replacing the
 * same curve found by the roots); a loop that no piece meets to tol only by the rounding of its
 * k (residual <= 1e3 eps / k') appended to unrep (*nunrep, room for 2 more); EL_ENOMEM (the
 * list freed) where it cannot grow. */
int el__hermite_chord_loops(const hframe *fr, const hprob *pr, const el_hermite_options *opt,
                            el_hermite_solution **sol, size_t *n, size_t *cap,
                            el_hermite_solution *unrep, size_t *nunrep);
/* hermite_chord.c: a and b the same chord loop: el__hermite_same_solution, or the same length,
 * energy (1e-7) and sense (a representation of it whose end curvatures are its far tails'
 * rounding: a chain beside the closed form) */
int el__hermite_same_loop(const el_hermite_solution *a, const el_hermite_solution *b, double d);
int el__hermite_near_case3(const hframe *fr, const double u0[2], const hprob *pr,
                           const el_hermite_options *opt, long max_evals, el_hermite_solution **sol,
                           size_t *n, size_t *cap);

#endif
