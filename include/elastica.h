/*
 * libelastica — Euler's elastica as a CAD tool.
 *
 * One public header, C99. Every fallible function returns an int status
 * (EL_OK = 0) and writes results through pointers; arrays are caller-owned
 * double arrays with explicit counts, points interleaved x0,y0,x1,y1,...
 * Nothing here aborts, prints or keeps global mutable state: every function
 * may be called from several threads at once.
 *
 * GSL's error handler: GSL reports errors through one process-wide handler
 * that aborts by default. At its first GSL call the library turns that default
 * off (gsl_set_error_handler_off) once, and checks the status of every GSL call
 * itself, mapping failures to EL_ codes; it validates arguments before GSL sees
 * them, so GSL has no error to report on any input (the fuzzer installs a
 * handler and counts every call of it as a finding). A program's own handler,
 * installed before or after the first call, stays in place: it would be called
 * only for an allocation failure inside GSL (the function then returns
 * EL_ENOMEM if the handler returns). A program that wants GSL's abort back for
 * its own GSL calls sets gsl_set_error_handler(NULL) after the library's first
 * call. `make fuzz` checks this on every entry point.
 *
 * Sections follow the files in libelastica/: status, jacobi, smooth,
 * discrete, guess, fit, prep, order, hermite, spline, affine, bspline, blend.
 *
 * This header is parsed by the Python binding (cffi cdef) after the
 * preprocessor lines are removed: no macros inside declarations.
 */
#ifndef ELASTICA_H
#define ELASTICA_H

#include <stddef.h>

/* The version of this header, the one source of it: el_version() returns the library's
 * at run time, the Makefile's VERSION (the shared object's name, pkg-config's Version) and
 * the Python binding's __version__ are these (test_abi.c, test_abi.py). */
#define EL_VERSION_MAJOR 0
#define EL_VERSION_MINOR 1
#define EL_VERSION_PATCH 0
#define EL_VERSION_STRING "0.1.0"

#ifdef __cplusplus
extern "C" {
#endif

/* ------------------------------------------------------------------ status */

/* Status codes returned by every fallible function. */
enum el_status {
    EL_OK = 0,
    EL_EINVAL = 1,     /* invalid argument: NULL, NaN/inf, out of range, too few points */
    EL_ENOMEM = 2,     /* allocation failed */
    EL_EDOM = 3,       /* input is valid but outside the domain the method covers */
    EL_ENOCONV = 4,    /* iteration did not converge; the best result seen is returned */
    EL_ESINGULAR = 5,  /* singular or degenerate system (collinear data, zero spread, ...) */
    EL_EMAXITER = 6,   /* iteration limit reached; the best result seen is returned */
    EL_EINTERNAL = 7,  /* an internal numerical routine (GSL, Ipopt) failed unexpectedly */
    EL_ERANGE = 8      /* a target beyond the range of solutions the method reached (the
                          length of el_spline_solve: el_spline_result's reach says which) */
};

/* A static, human-readable message for a status (never NULL). */
const char *el_strerror(int status);

/* Library version as "MAJOR.MINOR.PATCH" (static string): the EL_VERSION_STRING the
 * library was built with (a program compiled with another header may compare). */
const char *el_version(void);

/*
 * The header the library was built from: the CRC-32 (zlib's) of this header's
 * declarations, i.e. the file without its C++ guard and preprocessor lines, as
 * the Python binding's cffi reads it. A library built from another header lays out
 * its structs otherwise (a struct that grew is written past its end by the library).
 * The build writes the same number to elastica_abi.h (installed beside this file):
 *     #include <elastica_abi.h>
 *     if (el_abi_digest() != EL_ABI_DIGEST) ... this program and the loaded library
 *         disagree: rebuild the program against the library's header;
 * the Python binding compares it with its own header's at import (ImportError).
 */
unsigned long el_abi_digest(void);

/* ------------------------------------------------------------------ jacobi */

/*
 * Jacobi elliptic functions of argument u and modulus k, for every k >= 0.
 * k > 1 uses the reciprocal-modulus transformation
 *   sn(u,k) = sn(ku,1/k)/k,  cn(u,k) = dn(ku,1/k),  dn(u,k) = cn(ku,1/k);
 * k = 1 gives sn = tanh, cn = dn = sech. The AGM and Carlson's R_D inside (jacobi.c).
 *   am  amplitude: for k <= 1 the continuous angle with sn = sin am, cn = cos am
 *       (increasing, am(u+2K) = am(u)+pi); for k > 1, atan2(sn, cn), in (-pi/2, pi/2);
 *   E   Jacobi epsilon E(u) = integral_0^u dn^2(t,k) dt (= E(am u, k) for k <= 1);
 *   D   integral_0^u sn^2(t,k) dt, so that E = u - k^2 D (kept because it has no
 *       cancellation as k -> 0).
 */
typedef struct el_jacobi {
    double sn, cn, dn, am, E, D;
} el_jacobi;

/*
 * Values at (u, k); when d_du / d_dk are not NULL, also the partial
 * derivatives of every field with respect to u and to k (analytic: Carlson's
 * R_D for the k-derivative of the amplitude, no finite differences).
 * At k = 1 exactly, the k-derivatives are the limits k -> 1.
 * Errors: EL_EINVAL for NULL val, NaN/inf u or k, k < 0; EL_EDOM when double
 * precision has no digits of the result: max(1, k)|u| > 2^50 (k != 1; the period
 * 4K is known to a rounding, so reducing u loses |u| 2^-53 of the phase), or a
 * k-derivative overflows (k = 1 and |u| > ~710, where d cn/dk ~ e^|u|/4; k > ~1e154).
 * Outputs are untouched on error. Work is O(1) for every u and k.
 */
int el_jacobi_eval(double u, double k, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk);

/* ------------------------------------------------------------------ smooth */

/*
 * Smooth elastica segment, seed 000 (4.3) with one formula for every real k:
 *   u(s) = sqrt(mu) s + q,  sin((theta-phi)/2) = k sn(u;|k|),  cos((theta-phi)/2) = dn(u;|k|),
 *   kappa = theta' = 2 k sqrt(mu) cn(u;|k|),  gamma(0) = (x0, y0),  s in [0, length].
 * |k| < 1: inflectional (wave-like); |k| = 1: the separatrix; |k| > 1:
 * non-inflectional (loops), turning counter-clockwise for k > 1 and clockwise
 * for k < -1. k = 0 is the straight line. Changing the sign of k mirrors the
 * curve in the line through (x0, y0) at angle phi; for |k| < 1 that is the same
 * curve as q + 2K(|k|), so only loops need negative k (with k >= 0 alone a
 * clockwise loop has no parameters). Positions in closed form:
 *   gamma(s) = (x0,y0) + R(phi) ( (2(E(u)-E(q)) - (u-q)) / sqrt(mu),
 *                                 -2k (cn(u) - cn(q)) / sqrt(mu) ).
 * The parameter vector order, used by every Jacobian, is
 *   p = (x0, y0, phi, mu, k, q, length).
 */
typedef struct el_smooth_params {
    double x0, y0;   /* start point gamma(0) */
    double phi;      /* rotation (rad) */
    double mu;       /* > 0: scale, mu = lambda/(2k^2-1) of seed 000 (2.23) */
    double k;        /* elliptic modulus |k| (shape) with the orientation as its sign */
    double q;        /* phase: u(0) = q */
    double length;   /* >= 0: arc length of the segment */
} el_smooth_params;

enum { EL_SMOOTH_NPARAMS = 7 };

/* EL_OK when every field is finite, mu > 0, length >= 0; else EL_EINVAL. */
int el_smooth_check(const el_smooth_params *p);

/*
 * Evaluate at n arc lengths s[i] (any real values in any order; [0, length] is the
 * segment). Any output pointer may be NULL. xy: 2n (interleaved), theta: n (tangent
 * angle, continuous in s), kappa: n (signed curvature, + = counter-clockwise).
 * Equally spaced s (sampling grids) and sorted s (chord parameters, foot points)
 * take the addition theorems from a few fresh evaluations: ~40 and ~50 ns per point
 * where unsorted s costs ~400 (bench/bench_core.c). Every path agrees with one-point
 * evaluation to ~64 eps (1 + max|u|)(1 + |k|)/sqrt(mu), u = sqrt(mu) s + q (about
 * 1e-14 length on ordinary curves). Work is O(n) whatever the values; no allocation.
 * Errors (nothing is returned that is not finite and valid):
 *   EL_EINVAL  bad params (el_smooth_check), NULL s with n > 0, a non-finite s[i],
 *              n > SIZE_MAX / 112 (no 14 n-double Jacobian fits in memory);
 *              the outputs are untouched;
 *   EL_EDOM    double precision cannot resolve the samples: max(1, |k|)|u| > 2^50 for
 *              u = q or some sqrt(mu) s_i + q (|k| != 1: the phase has no digits), or
 *              fewer than three digits left, 2^-52 (1 + max|u|)(1 + |k|) / sqrt(mu) >
 *              1e-3 max(length, max|s_i|) (the closed form divides differences of
 *              rounded values by sqrt(mu)), or a result overflows; every element of
 *              every non-NULL output is then NaN.
 */
int el_smooth_eval(const el_smooth_params *p, size_t n, const double *s,
                   double *xy, double *theta, double *kappa);

/*
 * Jacobian of the points: jac[(i*2 + c)*7 + j] = d gamma_c(s_i) / d p_j, with
 * p = (x0, y0, phi, mu, k, q, length). The length column is the derivative
 * with the sample held at the same fraction t = s/length of the curve
 * (d/dL gamma(t L) = t T(s)); it is 0 when length = 0. xy may be NULL.
 * Paths, accuracy, work and errors as el_smooth_eval (EL_EINVAL also for NULL jac;
 * EL_EDOM also when the k column overflows: |k| = 1 and |u| > ~710).
 */
int el_smooth_jacobian(const el_smooth_params *p, size_t n, const double *s,
                       double *xy, double *jac);

/*
 * The same segment run backwards: out starts at p's end gamma(length) with the
 * opposite tangent and runs to p's start, gamma_out(s) = gamma_p(length - s) and
 * kappa_out(s) = -kappa_p(length - s). With u = sqrt(mu) s + q, u(length - s) = -u_out(s)
 * for q_out = -(sqrt(mu) length + q); sn odd, dn even and theta_out = theta + pi give
 * k_out = -k, phi_out = phi + pi, mu and length kept. out may equal p.
 * Errors: EL_EINVAL (bad params, NULL out; out untouched), EL_EDOM (the end point as
 * el_smooth_eval; out untouched).
 */
int el_smooth_reverse(const el_smooth_params *p, el_smooth_params *out);

/* Bending energy integral_0^length kappa^2 ds, in closed form. Errors: EL_EINVAL (bad
 * params, NULL energy; *energy untouched), EL_EDOM (as el_smooth_eval with the one
 * sample s = length, or the energy overflows; *energy = NaN). */
int el_smooth_energy(const el_smooth_params *p, double *energy);

/* ---------------------------------------------------------------- discrete */

/*
 * Bobenko–Suris discrete elastica, seed 000 (4.3)–(4.4), one formula for k > 0:
 *   u_n = z n + q,  sin((theta_n-phi)/2) = k sn(u_n;k),  cos((theta_n-phi)/2) = dn(u_n;k)
 * (theta_n is the potential function), segment angle
 *   Theta_n = (theta_n + theta_{n+1})/2,
 *   gamma_0 = (x0, y0),  gamma_{n+1} = gamma_n + h (cos Theta_n, sin Theta_n).
 * n vertices, n-1 segments, all of length h. Parameter order for Jacobians:
 *   p = (x0, y0, h, phi, z, q, k)   (seed 000 (4.5)).
 * The vertices satisfy the McMillan map (3.9) for kappa_n = (2/h) tan(K_n/2),
 * K_n = Theta_n - Theta_{n-1}, and its conserved quantity (3.18).
 */
typedef struct el_discrete_params {
    double x0, y0;   /* first vertex */
    double h;        /* > 0: segment length */
    double phi;      /* rotation (rad) */
    double z;        /* step of the elliptic argument per vertex */
    double q;        /* phase: u_0 = q */
    double k;        /* >= 0: elliptic modulus, shape */
} el_discrete_params;

enum { EL_DISCRETE_NPARAMS = 7 };

/* EL_OK when every field is finite, h > 0, k >= 0; else EL_EINVAL. */
int el_discrete_check(const el_discrete_params *p);

/*
 * The n >= 2 vertices (xy: 2n, interleaved), from the addition theorems at a few
 * flops per vertex (a fresh evaluation every 32 vertices; for max(1, k)|z| > 0.1
 * the anchored walk of el_smooth_eval, a fresh evaluation per vertex once |z| is
 * past a period); they agree with the recursion from one-point evaluations of every
 * u_n to ~64 roundings. Work O(n), no allocation. Errors:
 *   EL_EINVAL  bad params, n < 2, NULL xy, n > SIZE_MAX / 112; xy untouched;
 *   EL_EDOM    max(1, k)|z i + q| > 2^50 for some vertex i (k != 1: no digits of
 *              the phase), or a result overflows; every element of xy is NaN.
 */
int el_discrete_eval(const el_discrete_params *p, size_t n, double *xy);

/*
 * Discrete curvature at the n-2 interior vertices,
 * kappa[i] = (2/h) tan(K_{i+1}/2), seed 000 (3.4), = (2/h) k sn(z) cn(u_{i+1}) / dn(z):
 * exact to a few roundings of cn's phase however small z (the relative digits of kappa
 * ~ 2 k z cn(u) / h kept down to z = 1e-12). n >= 3.
 * Errors as el_discrete_eval (EL_EINVAL for n < 3; EL_EDOM also for a turning angle
 * K = pi, where the curvature is infinite; kappa is then all NaN).
 */
int el_discrete_curvature(const el_discrete_params *p, size_t n, double *kappa);

/*
 * Vertices (xy may be NULL) and their Jacobian,
 * jac[(i*2 + c)*7 + j] = d gamma_{i,c} / d p_j, p = (x0, y0, h, phi, z, q, k),
 * by the recursion (4.10). n >= 2. Errors as el_discrete_eval (EL_EINVAL also for
 * NULL jac; on EL_EDOM every element of jac and of a non-NULL xy is NaN).
 */
int el_discrete_jacobian(const el_discrete_params *p, size_t n, double *xy, double *jac);

/* ------------------------------------------------------------------- guess */

/*
 * Which arc length the smooth model assigns to data point i (the discrete
 * model always pairs data point i with vertex i):
 *   EL_PARAM_UNIFORM  s_i = i r, r = length/(n-1): equilateral data (point i
 *                     at arc length i r of the fitted curve);
 *   EL_PARAM_CHORD    s_i = t_i length, t_i = (chord length from point 0 to
 *                     point i) / (total chord length): the chord-length parameter,
 *                     each side's noise taken out: sqrt(max(d^2 - 2 nu^2, d^2/100))
 *                     for a side d, nu the points' noise level as the fit estimates
 *                     it (rms per point; noise lengthens a side to sqrt(d^2 + 2 nu^2)
 *                     on average, and plain chords gave a cluster of close noisy
 *                     points too much of the curve); for n > 40 points with nu >
 *                     0.1 x the mean side whose 32
 *                     block means turn by < 0.3 rad at each, measured along the
 *                     polygon of those means between the blocks' middle points
 *                     (the points' chords sharing each stretch out);
 *   EL_PARAM_AUTO     UNIFORM when the data are equilateral in the large: the
 *                     sides of the polygon of the means of 32 blocks of
 *                     consecutive points (of the points themselves when n <= 40)
 *                     have lengths with a coefficient of variation <= 0.5 (so
 *                     noisy, uniformly sampled data count as equilateral); for
 *                     n > 40 where those means turn by < 0.3 rad at each, the
 *                     sides per point between the blocks' middles within a
 *                     coefficient of variation of 0.05 + 3 nu sqrt(32/n) / (mean
 *                     side) instead (what the noise alone gives; scanner-density
 *                     points, spacing 1:2 between blocks, are CHORD);
 *                     CHORD otherwise.
 */
enum el_param_mode { EL_PARAM_AUTO = 0, EL_PARAM_UNIFORM = 1, EL_PARAM_CHORD = 2 };

/*
 * The fractions t_i = s_i/length (t_0 = 0, t_{n-1} = 1, non-decreasing) the
 * smooth fit uses for n >= 2 points xy (2n) under mode; *mode_used (may be
 * NULL) receives UNIFORM or CHORD. Errors: EL_EINVAL (NULL, n < 2, NaN/inf,
 * bad mode), EL_ESINGULAR (all points equal), EL_EDOM (the data's scale outside what
 * double precision represents: differences below ~1e-292 or beyond ~1e308).
 * Outputs untouched on error.
 */
int el_fit_fractions(const double *xy, size_t n, int mode, double *t, int *mode_used);

/*
 * Automatic initial parameters (seed 000 §4.3) for the discrete model from
 * n >= 4 points xy (2n), vertex i <-> point i. Up to cap candidates are
 * written to cand, best first (by the rms distance of their vertices to the
 * points, x0 and y0 by least squares (4.55)); *count receives their number
 * (>= 1). Method: curvature is affine in the position, (4.25); the version
 * integrated once, theta(s) = theta_0 + mu2 X(s) - mu1 Y(s) + A s with
 * X = int x ds, Y = int y ds, is solved by gsl_multifit_linear on the polygon
 * of block means (tangent angles instead of second differences, so noise is
 * not amplified); phi and mu from (mu1, mu2) (4.34); B by (4.35); k by (4.37)
 * (one formula for every k > 0: (4.36) is (4.37) for the reciprocal modulus);
 * q and z by inverting the Jacobi functions with gsl_sf_ellint_F along the
 * whole curve (the amplitude atan2(sn, cn), with sn from the tangent and cn
 * from the curvature, unwrapped, which counts the monotone pieces m of (4.38)
 * from the data) and a straight-line fit of u_n = z n + q (4.54). Candidates
 * (at most 6): this guess, the same with one monotone piece less and more
 * (m -/+ 1), the guess on the other side of k = 1 when k is near 1, a
 * circular-arc / straight-line guess from the tangent angles, and the arc of the
 * circle fitted to the points themselves (algebraic least squares: no tangents, so
 * points clustered closer than their noise do not spoil it); with n <= 40 also those
 * of the polygon whose sides shorter than two noise levels are merged (noisy short
 * sides' tangents are noise), ranked together with the first.
 * With more than 128 points, x0, y0 and the ranking use every stride-th point (at most
 * 128; the discrete candidate evaluated there as its continuum limit, O(h^2) apart).
 * Errors: EL_EINVAL (NULL, cap = 0, n < 4, NaN/inf), EL_ESINGULAR (all points
 * equal), EL_EDOM (the data's scale as el_fit_fractions, or parameters that double
 * cannot hold: the smooth mu ~ 1/size^2 needs sizes within ~1e-154 .. 1e154),
 * EL_ENOMEM, EL_EINTERNAL. cand and *count are untouched on error.
 */
int el_guess_discrete(const double *xy, size_t n, el_discrete_params *cand, size_t cap,
                      size_t *count);

/*
 * The same for the smooth model (Brander et al.: curvature affine in the
 * position), data point i at s_i = t_i length with t from el_fit_fractions(mode).
 * Loops (|k| > 1) get the sign of k from the data's sense of turning (k < -1:
 * clockwise); inflectional guesses have k > 0.
 * Errors as el_guess_discrete, plus EL_EINVAL for a bad mode.
 */
int el_guess_smooth(const double *xy, size_t n, int mode, el_smooth_params *cand, size_t cap,
                    size_t *count);

/* ------------------------------------------------------------------- fit */

/*
 * How a fit measures the distance of a point to the model (el_fit_options.distance):
 *   EL_DISTANCE_AUTO        orthogonal, but paired for the discrete model on equally
 *                           spaced points (the mean segment of runs of w = max(3, (n-1)/16)
 *                           segments within 1.3 x of each other: an equilateral polygon,
 *                           e.g. el_resample_equilateral's, or samples at equal steps) in
 *                           one pass (no point whose chords to the points 1..w back and on
 *                           point opposite ways: a scan passed back and forth) where the
 *                           paired fit's points stay at their vertices: where they slip
 *                           along the polygon by more than 1.3 x their distance from it
 *                           (rms; a slowly changing step, points at random places) or, a
 *                           fit without constraints or fixed values, by more than a segment
 *                           and 1.3 x the noise across it (the distances' point-to-point
 *                           part: dense points at random places, whose pull on the polygon
 *                           raises the rms), fitted again by distance from that fit; where their mean slip over w
 *                           points steps by more than half a vertex and 4 x its noise (a
 *                           point missing from, or doubled in, the scan), fitted by
 *                           distance afresh, as EL_DISTANCE_ORTHOGONAL fits them;
 *   EL_DISTANCE_ORTHOGONAL  the distance of each point to the curve (smooth) or to the
 *                           polygon of the n vertices (discrete), its foot free; the
 *                           smooth curve starts and ends at the feet of the first and last
 *                           points, the polygon at those points;
 *   EL_DISTANCE_PAIRED      point i <-> vertex i (the discrete model's definition, seed
 *                           000 (4.6)) or <-> gamma(t_i L), t_i from el_fit_fractions
 *                           (smooth; right for equilateral data).
 */
enum el_fit_distance { EL_DISTANCE_AUTO = 0, EL_DISTANCE_ORTHOGONAL = 1, EL_DISTANCE_PAIRED = 2 };

/*
 * Constraints of a fit: bits of el_fit_options.constraints, each with its value in the
 * options. Tangents are directions (angle of the unit tangent, rad, the direction of
 * travel from the first point to the last); curvatures signed (+ = turning
 * counter-clockwise, 0 = an inflection or a free end), in 1/input units. For the discrete
 * model the start/end point is vertex 0 / n-1, the tangent that vertex's theta_j = phi +
 * 2 a(q + j z) with sin a = k sn, cos a = dn (seed 000 (4.4): segment j runs at the mean
 * of theta_j and theta_j+1; theta_j is the smooth elastica's tangent angle with the same
 * phi, k, q, mu = 1, at s = j z; a B-spline through the vertices clamped to it is the
 * curve's G1 join), the curvature (2/h) tan(K/2) at the end vertex of the curve extended
 * by one vertex (seed 000 (3.4)), the length (n-1) h. Met to 1e-10 of the data's size
 * (1e-10 rad for angles), or the fit fails with EL_EDOM naming the constraint.
 * Held exactly, without Ipopt, at the one end that has more of them (the end's by
 * fitting the points in reverse order): the point and the tangent; smooth, the
 * curvature; discrete, a zero curvature. Both end points, with no other constraint,
 * are held exactly together (the fitted shape turned and scaled about the start point
 * onto the end point: no Ipopt). The others are Ipopt's constraint rows, but for the
 * natural batten: el_fit_smooth with both end points and both end curvatures 0 (and no
 * other constraint, fixed parameter or bound on phi, mu, k, q, length) searches the
 * curves that meet them (both ends inflections on the chord: per number of half-waves a
 * family in k alone) without Ipopt, leaves out those that cross themselves, and keeps the
 * nearest that follows the points (as below), else the nearest; certified when it is a
 * minimum along its family (or where its lobes touch), else EL_ENOCONV; el_fit_discrete
 * starts from that curve (its polygon meets both zero curvatures exactly) and keeps the
 * end one as Ipopt's row.
 */
enum el_fit_constraint {
    EL_CONSTRAIN_START_POINT = 1,
    EL_CONSTRAIN_END_POINT = 2,
    EL_CONSTRAIN_START_TANGENT = 4,
    EL_CONSTRAIN_END_TANGENT = 8,
    EL_CONSTRAIN_START_CURVATURE = 16,
    EL_CONSTRAIN_END_CURVATURE = 32,
    EL_CONSTRAIN_LENGTH = 64,    /* length_range[0] <= length <= length_range[1] */
    EL_CONSTRAIN_K = 128         /* k_range[0] <= k <= k_range[1] */
};

/*
 * Options of el_fit_discrete / el_fit_smooth; initialise with
 * el_fit_options_defaults. Parameter indices j follow the model's Jacobian
 * order: discrete p = (x0, y0, h, phi, z, q, k), smooth p = (x0, y0, phi, mu,
 * k, q, length).
 */
typedef struct el_fit_options {
    int fixed[7];        /* 1: hold p_j at value[j] (x0, y0 pinned to a point, seed 000 §5.4; h fixed);
                            0: free; any other value: EL_EINVAL */
    double value[7];     /* values of the fixed parameters (input units); h, mu > 0, length >= 0 */
    double lower[7];     /* bounds on p_j in input units; -HUGE_VAL / HUGE_VAL: none. Defaults: */
    double upper[7];     /*   none (the model's domain, h, mu, length > 0, discrete k >= 0, is kept internally) */
    double tol;          /* Ipopt's tol on the normalised problem (default 1e-12) */
    int max_iter;        /* iterations per initial guess (default 200) */
    int limited_memory;  /* 1: Ipopt with its L-BFGS Hessian (the paper's setting, for comparison;
                            the variables scaled by sqrt of the Gauss-Newton diagonal at the start,
                            20 update pairs; without constraint rows stopped by the default path's
                            first-order certificate, ipopt_status 5 (User_Requested_Stop) then;
                            the smooth orthogonal fit starts from a paired one by the same L-BFGS) */
    int max_candidates;  /* initial guesses fitted at most (default 6, all the guess gives; 1 = the best
                            guess only); fitting stops at the first within 1.5 noise levels of the data */
    int param_mode;      /* smooth model: enum el_param_mode (default EL_PARAM_AUTO) */
    int use_initial;     /* 1: start from the caller's initial parameters instead of the guess
                            (smooth by distance, no constraints: from the points' nearest
                            points on that curve); a curve that runs against the points'
                            order is run backwards first (the same curve, el_smooth_reverse) */
    int distance;        /* enum el_fit_distance (default EL_DISTANCE_AUTO) */
    int constraints;     /* bits of enum el_fit_constraint (default 0: none) */
    double start_point[2], end_point[2];     /* input units */
    double start_tangent, end_tangent;       /* rad */
    double start_curvature, end_curvature;   /* 1/input units */
    double length_range[2];                  /* [lo, hi], 0 <= lo <= hi (hi may be HUGE_VAL) */
    double k_range[2];                       /* [lo, hi]; the smooth k is signed (orientation) */
    int exhaustive;      /* 1: with constraint rows, every start's Ipopt run goes to its own end (the plain
                            path, for comparison); 0 (default): a later start's run is stopped once it is near
                            the rows and cannot reach the kept fit's objective at its recent rate */
} el_fit_options;

/* Fill *opt with the defaults above. */
void el_fit_options_defaults(el_fit_options *opt);

/*
 * Result of a fit. params are finite even when status is not EL_OK: on
 * EL_ENOCONV / EL_EMAXITER they are the best parameters seen.
 * rms and max_error are point-to-curve distances (whatever distance was minimised):
 * smooth, to the curve over [0, length]; discrete, to the polygon of its vertices.
 */
typedef struct el_fit_discrete_result {
    el_discrete_params params;    /* fitted */
    el_discrete_params initial;   /* the initial guess the kept fit started from */
    double rms;                   /* sqrt(mean distance^2), input units */
    double max_error;             /* max |distance|, input units */
    int iterations;               /* iterations, all initial guesses */
    int candidates;               /* initial guesses fitted */
    int ipopt_status;             /* Ipopt's ApplicationReturnStatus of the kept fit when used_ipopt */
    int status;                   /* library status, as returned */
    int used_ipopt;               /* 1: Ipopt ran for the kept fit (bounds, constraints, fallback) */
    int distance;                 /* the enum el_fit_distance used */
    int constraint;               /* the enum el_fit_constraint bit not met or contradictory, else 0 */
    long wander_gap;              /* i: the curve wanders between points i and i+1 (below), -1: it
                                     follows its points (keyline sides: -1, not judged) */
} el_fit_discrete_result;

typedef struct el_fit_smooth_result {
    el_smooth_params params;
    el_smooth_params initial;
    double rms, max_error;
    int iterations, candidates, ipopt_status, status, used_ipopt, distance, constraint;
    int param_mode;               /* EL_PARAM_UNIFORM or EL_PARAM_CHORD: paired s_i / first feet */
    long wander_gap;              /* as el_fit_discrete_result's */
} el_fit_smooth_result;

/*
 * Least-squares fairing (4.6)-(4.8): the discrete elastica of n vertices nearest the
 * n >= 4 points xy (2n): by orthogonal distance (each point's distance to the polygon,
 * its foot free; vertex 0 and n-1 tied to the first and last points) or, on evenly
 * spaced points (EL_DISTANCE_AUTO) or with EL_DISTANCE_PAIRED, vertex i nearest the
 * point P_i (seed 000 (4.6)); over every k > 0 (the
 * optimiser crosses k = 1), with the analytic gradient (4.9)-(4.12) and the
 * Gauss-Newton Hessian J^T J. Coordinates are normalised internally (centroid,
 * rms radius), so the fit is invariant under similarity transforms.
 * initial is read only when opt->use_initial (else it may be NULL); opt NULL =
 * defaults. Up to opt->max_candidates initial guesses (el_guess_discrete) are
 * fitted and the best kept. Where no constraint needs Ipopt's rows (no constraint, or
 * those held exactly: the start point, and the smooth start tangent and curvature):
 * a constrained fit whose guesses all end above the data's noise also starts from the
 * unconstrained fit's curve (guesses started under the constraints can all miss the
 * data's basin); and by distance to the polygon or curve, a fit must follow the points:
 * one that strays from them (a loop or a pass where there is no point, or the points
 * passed out of order: more than a tenth of the points' polygon length of curve
 * unaccounted for by the arcs between feet, 1.6 times their chord plus 4 noise levels
 * each) is fitted again from the paired fit's curve, which passes them in order, and
 * that fit is kept when it follows the points or strays less than half as far, even at
 * a higher rms (without this, 41 noisy points along an arc of length 1 were fitted at a
 * lower rms by a curve of length 4.5 looping twice round them). With constraints, a fit
 * that crosses itself where the points' polygon does not, or strays, does not replace
 * one that does neither, even at a lower rms (a smooth fit of fewer than 60 points kept
 * that still does either is fitted again from the free fit's curve and the guesses, each
 * from its own feet, and gives way to the lowest that does neither and is at most 1 % of
 * the data's size higher; one that swings between two points, turning there by over 1.8 rad
 * more than their polygon and 0.1 of their chord off it, is fitted again with its length at
 * most 1-1.2 x the polygon's and gives way to the lowest such fit that follows them,
 * within the same 1 %); a discrete fit with rows or a held start state starts first
 * from the smooth fit's curve (its guesses ended on polygons 25 x the data's length,
 * crossing themselves hundreds of times). Free fits of 6-59 sparse
 * points take up to ~0.1 s of CPU (bench/bench_fit_sparse.py; a few hard sketches up to
 * ~0.8 s), those with Ipopt's rows up to ~1 s. With Ipopt's rows, its iterations over
 * the guesses (once one meets the constraints) and the refits of one fit stop at twice
 * opt->max_iter, at once opt->max_iter where a held start state's continuation ends far
 * from the free fit (over 10 x its rms: conditions the data do not share).
 * Solver: Levenberg-Marquardt, its result certified by the first-order condition
 * (the residual vector orthogonal to every column of the Jacobian to 1e-8, or zero to
 * rounding); Ipopt runs only for bounds that are active, constraints it cannot hold
 * exactly, the fit kept when it is left uncertified (once, from it: noisy data whose
 * decrease stalls, reported as EL_OK once Ipopt's acceptable level is reached; not each
 * guess so left on the way), or opt->limited_memory. Work: a few Jacobian evaluations, O(n)
 * each, per candidate; with limited_memory up to opt->max_iter Ipopt iterations per
 * candidate (~0.5 ms each for n <= 1000, mostly Debian 12's MUMPS; on 144 fits of
 * sketched, uneven and noisy points, 20-1000 of them, free or constrained, a median of 65
 * iterations in all, 90 % <= 273, 24 ms, 90 % <= 84 ms). Memory:
 * O(n) for the result's distances, the Jacobian is never stored. Thread safety:
 * concurrent fits run at once; only their Ipopt solves are serialised by a
 * process-wide lock (Debian's MUMPS, Ipopt's linear solver, is not reentrant). Ipopt
 * reads no options file (an ipopt.opt in the working directory is ignored) and
 * prints nothing.
 * distances, foot_s (caller-sized, n each, may be NULL): each point's signed distance
 * to the polygon of the vertices (+ = left of it) and its foot as arc length along it
 * from vertex 0, input units; rms and max_error are computed from them.
 * res->wander_gap: where no refit above follows the points, the fit kept says where it
 * wanders, its distances small all the same (the points lie on it): i, the gap between
 * points i and i+1 (where the curve passes them out of order, the gap between two feet
 * adjacent along it, of points a < b, is the gap b - 1), by the tests above in their order: it strays
 * (the gap holding the most curve no point accounts for; the noise level of fewer than 60
 * points the lower of the data's and the fit's rms; a held start or end point allowed the
 * curve to it as a gap); then, fewer than 60 points (a sketch's: more are judged by the
 * stray test alone, as the fit's own rule), passes point i + 1 before point i and not after
 * it as well (its foot behind by more than half their distance and 8 noise levels: the
 * first such i), crosses itself where the points' polygon does not (the gap of the loop's
 * middle), or swings between two of them (the first such gap; the discrete polygon judged
 * at its vertices); else -1. A point added in that gap,
 * or the length bounded (EL_CONSTRAIN_LENGTH), holds the curve there. Reporting only: the
 * fit is the same whatever it says.
 * Returns (and stores in res->status):
 *   EL_OK;
 *   EL_ENOCONV / EL_EMAXITER with the best parameters seen;
 *   EL_EDOM: a constraint cannot be met (res->constraint names it; the best parameters
 *     seen are returned), or the data's scale is outside what double precision
 *     represents (differences below ~1e-292, or beyond ~1e308; res untouched) or the
 *     fitted parameters are (res written, params the best finite ones seen);
 *   EL_EINVAL: NULL, n < 4, NaN/inf, bad options (a fixed[j] other than 0 or 1, a fixed
 *     h <= 0, mu <= 0 or length < 0,
 *     a value outside its bounds, inconsistent bounds, an unknown constraint bit, a
 *     non-finite constraint value, a constraint contradicting a fixed parameter: then
 *     res->constraint names it and nothing else of res is written);
 *   EL_ESINGULAR (all points equal), EL_ENOMEM, EL_EINTERNAL (Ipopt could not start).
 * On EL_EINVAL, EL_ESINGULAR, EL_ENOMEM and the scale EL_EDOM, *res (but for
 * res->constraint as said) and the arrays are untouched; on every other status they
 * are written in full.
 */
int el_fit_discrete(const double *xy, size_t n, const el_fit_options *opt,
                    const el_discrete_params *initial, el_fit_discrete_result *res,
                    double *distances, double *foot_s);

/*
 * The same for the smooth elastica, by default by orthogonal distance
 * (opt->distance): minimise the sum of squared distances of the points to the curve
 * over the curve's parameters and each point's foot on it; the first and last points
 * are tied to gamma(0) and gamma(length) by full residual vectors, and since the start
 * and the length are free the curve begins and ends at their feet. A free fit (no
 * constraints, fixed parameters or bounds) where three or more other points lie beyond
 * an end (their feet at it: a scan dense there, its first point inside the cloud) is
 * fitted again with the ends tied to the points farthest along the curve instead, and that
 * fit returned when its rms is lower. Paired
 * (EL_DISTANCE_PAIRED): point i at arc length t_i length (el_fit_fractions with
 * opt->param_mode); the reported distances are point-to-curve distances either way.
 * The optimiser works over every real k (the sign of k is the orientation, smooth
 * section): loops turning clockwise are fitted with k < -1 and keep that sign;
 * inflectional results (|k| < 1) are handed out with k >= 0 (the same curve as -k with
 * q + 2K(|k|)) unless k or q is fixed, or the caller's bounds exclude that form.
 * distances, foot_s: signed distance to the curve over [0, length] (+ = left) and the
 * foot's arc length s; the foot is the nearest point near the point's place along the
 * data (Newton's method from the fit's own foot). Statuses and outputs as
 * el_fit_discrete; its parameter mu ~ 1 / extent^2 narrows the scale EL_EDOM (res
 * untouched) to data whose extent lies outside ~1e-150 .. 1e150.
 */
int el_fit_smooth(const double *xy, size_t n, const el_fit_options *opt,
                  const el_smooth_params *initial, el_fit_smooth_result *res,
                  double *distances, double *foot_s);

/*
 * The points' own noise level, from the points alone (no fit): *noise, the rms of a noisy
 * point's distance to the smooth curve under it (its normal part: sigma for noise of sigma
 * per coordinate), input units; the median over up to 65536 third differences, in which a
 * smooth curve's turning cancels, in the frame of each stencil's chord where the spacing is
 * uneven, of every k-th point where they see more noise (points sorted along their curve,
 * spacing below the noise: a dense scan in curve order, k doubled until their stencils span
 * the noise band, 0.85-1.15 x the noise at spacing 1/100 .. 2 x it; a polygon resampled
 * densely along noisy points) (el_fit_* stop at 1.5 x the figure of consecutive points and
 * every (n / 1000)-th point, which is this one but on such sorted scans). The fit's rms on noisy elasticae is
 * 0.9-1.1 x it on dense scans, 0.5-2.1 x on sketches of 15-30 points, whose bending enters
 * it (bench/bench_fit.py's 504 curves, tests/python/fit_data.py's sets); points along a curve
 * that is not one elastica lie farther from its fit: a line meeting an elastica at a corner,
 * 400 points, noise 0.3: rms 10.9 = 24 x this figure (the binding's MisfitWarning, from 4 x
 * the larger of this figure and its cubics through 15 points, which see noise correlated from
 * point to point: a polygon resampled along noisy points, 4-6 x below the noise here).
 * Repeated points (a scanner writing each point twice, a pen at rest) carry no noise and
 * count once: a point whose coordinates lie within 1e-12 of the points' rms radius plus 4
 * rounding units of the first point's |x| + |y| of the last one kept is left out (el_fit_distinct's
 * points), and the figure is that of the points without their repeats, to the bit (repeats
 * apart in the order are no neighbours there).
 * Errors: EL_EINVAL (NULL, n < 4 or fewer than 4 points once repeats count once, NaN/inf),
 * EL_ESINGULAR (all points equal to rounding: their spread about the first within 32 eps x
 * the largest |coordinate|, as el_plane_fit's; the fits' likewise), EL_EDOM (the data's
 * scale outside what double precision represents), EL_ENOMEM; *noise untouched.
 */
int el_fit_noise(const double *xy, size_t n, double *noise);

/*
 * el_fit_noise's figure of consecutive points' stencils alone: never above el_fit_noise's
 * (the same on evenly and unevenly spaced points in their order; below it on points sorted
 * densely along their curve, or resampled densely along noisy points), at a fraction of its
 * cost, so that a verdict raised only where a fit's rms is far above the noise can test this
 * figure first and pay for el_fit_noise's only where this one raises it. Errors as
 * el_fit_noise's.
 */
int el_fit_noise_quick(const double *xy, size_t n, double *noise);

/*
 * The points xy (n >= 1) with each run of repeats kept once, in their order: el_fit_noise's
 * rule (a point whose coordinates lie within 1e-12 of the points' rms radius plus 4 rounding
 * units of the first point's |x| + |y| of the last point kept is left out; all points equal
 * to rounding, as el_fit_noise's EL_ESINGULAR: the first alone), so that figures of the
 * points computed elsewhere (the binding's noise_level: cubics through windows of 15 points)
 * see the points el_fit_noise sees. out (2n doubles, caller-owned; xy itself, or not
 * overlapping it) receives the *m points kept (the first always; *m = n where none repeats).
 * O(n), no allocation. Errors: EL_EINVAL (NULL, n = 0, NaN/inf), EL_EDOM (the data's scale
 * outside what double precision represents, as el_fit_noise's); out, *m untouched.
 */
int el_fit_distinct(const double *xy, size_t n, double *out, size_t *m);

/*
 * The first point where points xy (n) in order turn back on themselves and run back over
 * their stretch (a scan passed back and forth): *first = the least i, w <= i < n - w, whose
 * chords to the points k before and k after point opposite ways, (P_i - P_{i-k}) .
 * (P_{i+k} - P_i) < 0, at every k = 1..w, w = max(3, (n - 1) / 16); 0 where none does (n < 7
 * always). It is el_fit_discrete's own test (distance = EL_DISTANCE_AUTO does not pair such
 * points: they are not one pass), for a binding that judges a fit's points the same way (a
 * smooth curve's polygon turns by less than 90 degrees at a vertex; a noise cloud far denser
 * than its noise turns so at a few k only). Computed as written: a dot that overflows (points
 * ~1e154 apart) counts as no turn. O(n w) at most, no allocation. Errors: EL_EINVAL (NULL,
 * n = 0, NaN/inf); *first untouched.
 */
int el_fit_turn_back(const double *xy, size_t n, size_t *first);

/*
 * A keyline as one problem (seed 000 §5.4, one G2 curve): two elasticae that start at
 * a common joint J with opposite tangents and zero curvature there, `first` running
 * from J towards point 0, `second` towards point n-1. Both are inflectional (|k| < 1)
 * with u(0) = K(|k|) at J. The joint moves along the data: split (0 < split < n-1,
 * >= 3 points each side) is its initial place, the index of the point nearest the
 * estimated inflection; it is refined first (each side fitted alone, the zeros of their
 * curvature; and, as a second start whose joint fit is kept when better, one elastica of
 * all the points split at its inflection) and then, smooth: each point's foot lies on
 * either curve and J is free; discrete: the data are an equilateral polygon (seed 000
 * §5.3), vertex j of `first` <-> point split - j, vertex j of `second` <-> point
 * split + j, and the split index is moved while the joint fit improves; *joint (may be NULL) receives the final index
 * (first has joint + 1 vertices, second n - joint). The discrete h of each side is
 * free (§5.4 Table 1), or held at opt->value[2] for both with opt->fixed[2].
 * opt: max_iter, tol and (discrete) fixed h are read; other fixed parameters, bounds,
 * constraints or use_initial: EL_EINVAL. Each side's result has the rms / max error of
 * its own points; iterations, status alike.
 * distances, foot_s, side (caller-sized, n each, may be NULL): signed distance of each
 * point to its side's curve (+ = left of the keyline run from point 0 to point n-1, so
 * right of `first`, which runs the other way), the foot (arc length from J along its
 * side) and the side (0 first, 1 second).
 * Statuses as el_fit_discrete, plus EL_EDOM when a side is not inflectional, and when the
 * fit does not converge on points whose polygon shows no inflection (el_find_inflection's
 * EL_EDOM: an arc; first / second untouched then).
 */
int el_fit_keyline_smooth(const double *xy, size_t n, size_t split, const el_fit_options *opt,
                          el_fit_smooth_result *first, el_fit_smooth_result *second,
                          double *distances, double *foot_s, int *side);
int el_fit_keyline_discrete(const double *xy, size_t n, size_t split, const el_fit_options *opt,
                            el_fit_discrete_result *first, el_fit_discrete_result *second,
                            size_t *joint, double *distances, double *foot_s, int *side);

/* ------------------------------------------------------------------- prep */

/*
 * Keyline preparation, seed 000 §5.3: PCA plane fit of a 3D polyline, the
 * equilateral open-polygon resampling, PCA re-normalisation of the 2D
 * polygon, and the RDP-style inflection estimate. Pipeline:
 *   el_plane_fit -> el_resample_equilateral -> el_pca_normalize -> el_find_inflection.
 */

/*
 * Orthonormal frame of a PCA plane fit, seed 000 §5.3: origin = the centroid
 * p_bar (5.1); e1, e2, e3 the unit eigenvectors of the covariance matrix
 * C = (1/m) sum (p_k - p_bar)(p_k - p_bar)^t for lambda[0] >= lambda[1] >= lambda[2]
 * (the plane's normal is e3). Local coordinates p' = (e1 e2 e3)^t (p - p_bar).
 * Deterministic signs: e1 points from the first to the last point
 * (e1 . (p_last - p_first) >= 0); e3 has a positive z component (if it is
 * ~0, positive y, then positive x); e2 = e3 x e1, so (e1, e2, e3) is
 * right-handed and a curve in the xy-plane keeps its orientation.
 */
typedef struct el_frame {
    double origin[3];   /* centroid p_bar (input units) */
    double e1[3];       /* x' axis: first principal direction */
    double e2[3];       /* y' axis */
    double e3[3];       /* z' axis: plane normal */
    double lambda[3];   /* eigenvalues of C, decreasing (units^2) */
} el_frame;

/*
 * Fit the plane of n >= 3 points xyz (3n, interleaved x,y,z) by PCA
 * (gsl_eigen_symmv) and project them onto it. Outputs (each may be NULL):
 * frame; xy_out (2n) the plane coordinates x'_k = e1.(p_k - p_bar),
 * y'_k = e2.(p_k - p_bar); rms_out_of_plane = sqrt(mean (e3.(p_k - p_bar))^2).
 * Collinear points are accepted (y' = 0; e2, e3 then any orthonormal
 * completion, still deterministic). Any scale works: the sums are formed in
 * units of a power of two near the largest coordinate, the covariance in units
 * of the largest deviation (rms likewise), so 1e-300 and 1e300 data are alike.
 * Errors: EL_EINVAL (NULL xyz, n < 3, NaN/inf), EL_ESINGULAR (all points
 * equal to rounding: spread <= 32 eps |largest coordinate|), EL_EDOM (a spread
 * beyond ~1e154: the eigenvalues, units^2, overflow), EL_ENOMEM, EL_EINTERNAL
 * (GSL). Outputs untouched on error.
 */
int el_plane_fit(const double *xyz, size_t n, el_frame *frame, double *xy_out,
                 double *rms_out_of_plane);

/*
 * Local coordinates of n points xyz (3n) in frame: xy (2n) = (x', y') and,
 * when z is not NULL, z (n) = z' (signed distance from the plane).
 * Errors: EL_EINVAL (NULL frame/xyz/xy with n > 0, NaN/inf), EL_EDOM (a
 * coordinate beyond double's range; the points before it are written).
 */
int el_frame_project(const el_frame *frame, size_t n, const double *xyz, double *xy,
                     double *z);

/*
 * Inverse map of the plane coordinates: xyz (3n) = p_bar + x' e1 + y' e2 for
 * the n points xy (2n). Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (a
 * coordinate beyond double's range; the points before it are written).
 */
int el_frame_to_3d(const el_frame *frame, size_t n, const double *xy, double *xyz);

/*
 * Equilateral open polygon A_1..A_n of segment r approximating a planar
 * polyline, seed 000 §5.3 ("Equilateral open polygon approximation"):
 * A_1 is the left end (the end point with the smaller x; the first point on a
 * tie); A_{k+1} is a point of the polyline at distance exactly r from A_k
 * that lies further along the polyline than A_k (does not return towards
 * A_{k-1}); when several do, the one nearest the far end along the polyline
 * (largest arc-length position) is taken, so a hairpin narrower than r is
 * jumped across. When no such point exists, A_k is the stop point A_n.
 * Every vertex lies on the input polyline, |A_{k+1} - A_k| = r to rounding,
 * and (n-1) r <= the polyline's length.
 * The library allocates xy and s; release them with el_resample_free.
 */
typedef struct el_resample_result {
    size_t n;           /* vertices, >= 2 */
    double *xy;         /* 2n, interleaved, A_1 first */
    double *s;          /* n: arc-length position of A_k along the input, measured from A_1's end */
    int reversed;       /* 1 when A_1 is the input's last point (the polyline was walked backwards) */
    double remainder;   /* length of the input left after the stop point A_n */
} el_resample_result;

/* The most vertices el_resample_equilateral builds (bounded work). */
enum { EL_RESAMPLE_MAX_VERTICES = 1000000 };

/*
 * Resample the polyline xy (2n, n >= 2) with segment r > 0 into *out (which
 * the caller then frees with el_resample_free). Consecutive repeated points
 * are allowed (zero-length pieces are skipped). Every scale works (the walk
 * runs in units of a power of two near the length); the stop point is never a
 * truncation: the input's far end is within r of it.
 * Bounded work: r < length / (EL_RESAMPLE_MAX_VERTICES - 1) (length = the
 * polyline's) is refused at once with EL_EDOM; else O(m log n) for m vertices.
 * Errors: EL_EINVAL (NULL, n < 2, NaN/inf, r <= 0 or not finite, r larger than
 * the distance from A_1 to every point of the polyline), EL_ESINGULAR (all
 * points equal), EL_EDOM (the limit above; a length beyond double's range),
 * EL_ENOMEM. *out is untouched on error.
 */
int el_resample_equilateral(const double *xy, size_t n, double r, el_resample_result *out);

/* Release what el_resample_equilateral allocated and zero *res; NULL is a no-op. */
void el_resample_free(el_resample_result *res);

/*
 * 2D PCA frame, seed 000 §5.3 ("Coordinate conversion ... by principal
 * component analysis"): origin = q_bar, f1, f2 the unit eigenvectors of
 * D = (1/n) sum (q_k - q_bar)(q_k - q_bar)^t for mu[0] >= mu[1], signed so
 * that the diagonal of (f1 f2) is positive (f1.x > 0, f2.y > 0; f2 is f1
 * turned by +90 degrees, a rotation). Local coordinates q'' = (f1 f2)^t (q - q_bar).
 */
typedef struct el_frame2d {
    double origin[2];   /* centroid q_bar */
    double f1[2];       /* x'' axis */
    double f2[2];       /* y'' axis */
    double mu[2];       /* eigenvalues of D, decreasing (units^2) */
} el_frame2d;

/*
 * PCA re-normalisation of n >= 2 points xy (2n): frame (may be NULL) and
 * xy_out (2n, may be NULL; may equal xy) the coordinates q''_k. Any scale, as
 * el_plane_fit.
 * Errors: EL_EINVAL (NULL xy, n < 2, NaN/inf), EL_ESINGULAR (all points equal),
 * EL_EDOM (a spread beyond ~1e154), EL_ENOMEM, EL_EINTERNAL (GSL). Outputs
 * untouched on error.
 */
int el_pca_normalize(const double *xy, size_t n, el_frame2d *frame, double *xy_out);

/* Map n points from the parent (x'y') coordinates to the frame's x''y'' (2n each;
 * in-place allowed). Errors: EL_EINVAL (NULL with n > 0, NaN/inf), EL_EDOM (a
 * coordinate beyond double's range; the points before it are written). */
int el_frame2d_to_local(const el_frame2d *frame, size_t n, const double *xy, double *xy_local);

/* Inverse: parent coordinates q = q_bar + x'' f1 + y'' f2 (2n each; in-place
 * allowed). Errors as el_frame2d_to_local. */
int el_frame2d_to_parent(const el_frame2d *frame, size_t n, const double *xy_local,
                         double *xy);

/*
 * Result of the RDP-style inflection estimate, seed 000 §5.3 steps (1)-(4).
 * The paper's point numbers are vertex indices of the polygon.
 */
typedef struct el_inflection {
    size_t index;       /* the estimate: point P+2 when it became adjacent to P+1, step (4) */
    size_t neighbor;    /* point P+1: the curvature changes sign on the edge index-neighbor */
    size_t apex;        /* point 3: the vertex farthest from the chord of the end points */
    size_t end;         /* point 2: the end point on the inflection side (0 or n-1) */
    int iterations;     /* step (3) repetitions */
} el_inflection;

/*
 * Estimate the one global inflection of an open polygon xy (2n, n >= 4),
 * seed 000 §5.3 steps (1)-(4), on the resampled, re-normalised polygon.
 * side chooses point 2 of step (1), which the paper picks by eye: +1 the
 * last vertex, -1 the first, 0 automatic: the end whose sub-polygon from point 3
 * is not a convex arc, i.e. has vertices on the side of its chord opposite to
 * point 3 (looked for by descending from point 3 to the farthest vertex on
 * point 3's side; the shallower, then the larger, evidence wins).
 * "Upper side" in step (3) is taken relative to each chord oriented by
 * increasing vertex index (the same as the paper's for x-monotone polygons,
 * and rotation invariant). The switch rule of step (3) is also applied to
 * point 4 of step (2), using the side of point 3 relative to chord 1-2. This
 * changes nothing when point 4 lies beyond the inflection (the paper's case),
 * and it keeps an inflection near end 2 inside the search interval (without
 * it, 5% of noise-free cubics were missed by up to 80 r).
 * Noise moves the estimate (the curve is nearly straight there): on
 * generated curves the error grows about like sqrt(noise), ~1.5 r at noise
 * 1e-5 of the length and ~5 r at 1e-4 (r = length/200).
 * Scale invariant (a polygon of extent outside [1e-150, 1e150] is handled as a
 * copy scaled by a power of two). Cost: O(n^2) in the worst case (each step of
 * (3) scans its interval).
 * Errors: EL_EINVAL (NULL, n < 4, NaN/inf, side not in {-1,0,1}),
 * EL_ESINGULAR (all points equal), EL_EDOM (no inflection: collinear or
 * convex polygon, or coincident end points; an extent beyond double's range),
 * EL_ENOMEM. *out untouched on error.
 */
int el_find_inflection(const double *xy, size_t n, int side, el_inflection *out);

/* ------------------------------------------------------------------- order */

/*
 * The screen of a check of points' order (the binding's out_of_order: points whose
 * polyline is many times their extent, its sides turning about pi/2 a vertex, are
 * no curve's): what the polyline through n points xy (2n) measures, in O(n).
 * extent: max over x and y of (largest - smallest coordinate), over all n points;
 * length and turn: of the polyline through every step-th point (xy[0], xy[step],
 * xy[2 step], ...: m = (n - 1) / step + 1 of them), its length sum |d_i|
 * (d_i = p_{i+1} - p_i; step 1: the whole polyline's) and its mean |turn| a
 * vertex, (1/(m-2)) sum |atan2(d_i x d_{i+1}, d_i . d_{i+1})| (rad, in [0, pi]).
 * Sums are pairwise, in numpy's order (the binding's former numpy formulas, bit for
 * bit but the turn's atan2: within a few ulps of numpy's vectorised one). Computed
 * as written, no rescaling: coordinates beyond ~1e154 give +inf lengths (the
 * squares overflow) and may give a NaN turn.
 */
typedef struct el_order_screen_result {
    double extent;      /* units */
    double length;      /* the step-th points' polyline (units; 0 for m = 1) */
    double turn;        /* its mean |turn| a vertex (rad); NaN for m < 3 or not asked */
} el_order_screen_result;

/*
 * Screen the polyline xy (2n, n >= 1) through every step-th point (step >= 1) into
 * *out as above; turn != 0 measures the turn (else NaN: it costs an atan2 a vertex).
 * No allocation. Errors: EL_EINVAL (NULL, n = 0, step = 0, NaN/inf). *out
 * untouched on error.
 */
int el_order_screen(const double *xy, size_t n, size_t step, int turn,
                    el_order_screen_result *out);


/* ------------------------------------------------------------------- hermite */

/*
 * Hermite interpolation by elastic curves (seed 004): every curve x(s) of
 * length L at most one period of its curvature with x(0) = p0, x'(0) = t0,
 * x(L) = p1, x'(L) = t1 whose curvature solves 2 kappa'' + kappa^3 - sigma kappa = 0
 * (critical points of integral kappa^2 + sigma ds; lambda = sigma/2 in seed 000 (2.6)).
 *   EL_HERMITE_TENSION: sigma given (any real; sigma < 0 is compression), L is an output;
 *   EL_HERMITE_LENGTH:  L given (Euler's strip clamped at both ends), sigma is an output.
 * Units: positions in length units, sigma in 1/length^2.
 */
enum el_hermite_mode { EL_HERMITE_TENSION = 0, EL_HERMITE_LENGTH = 1 };

typedef struct el_hermite_options {
    int mode;              /* EL_HERMITE_TENSION (default) or EL_HERMITE_LENGTH */
    double sigma;          /* tension, 1/length^2 (tension mode); default 0 (pure bending) */
    double length;         /* prescribed arc length > 0 (length mode); default 0 (unset) */
    double tol;            /* accepted end residual: position / |p1-p0| and tangent angle (rad), > 0; default 1e-10 */
    int samples;           /* bracketing samples over the whole search interval (each subinterval gets its share + 2, then refinement), 4..1000; default 12 */
    int grid;              /* length mode: sigma lines whose tension solutions start the tracing, 1..256; default 6 */
    size_t max_solutions;  /* at most this many solutions are kept (lowest energy), >= 1; default 64 */
} el_hermite_options;

/*
 * One solution: a valid el_smooth_params (el_smooth_eval works on it) running from
 * p0 (curve(0) = p0, tangent t0) to p1 (curve(length) = p1, tangent t1), or, near
 * the separatrix where no single el_smooth_params meets opt->tol (see
 * el_hermite_solve), a chain of npieces = 2 or 3 pieces of the same elastica: curve
 * (from p0), then rest[0] (and rest[1]), each starting where the one before ends,
 * with its tangent (position and tangent continuous to rounding), the last ending at
 * p1. The pieces split the curve at its saddles (the near-straight stretches
 * between two loops); each piece has its own start point and its phase q measured
 * from its own loop (curvature extremum). Unused rest[] entries are zero. Old
 * callers that read only curve get a valid curve from p0 (the first piece).
 * Inflectional curves have 0 < k < 1 (a chain's pieces alternate the sign of k); a
 * non-inflectional loop has k > 1 when it turns counter-clockwise and k < -1 when it
 * turns clockwise (kappa < 0); a circular arc (below) has k = +-1e4. A straight
 * segment is k = 0. length, energy, kappa0, kappa1, has_inflection and residual are
 * of the whole curve (chain): kappa0, kappa1 the curvatures at p0 and p1; residual =
 * max(position error / |p1-p0|, tangent angle error) measured with el_smooth_eval at
 * both ends, the curve moved to start at the origin (the coordinates' own rounding,
 * up to ~ulp(max(|p0|, |p1|)) / |p1-p0|, comes on top: 2e-10 at 1e6 |p1-p0| from the origin).
 */
typedef struct el_hermite_solution {
    el_smooth_params curve;    /* the curve, or its first piece when npieces > 1 */
    double length;             /* arc length L (of the whole curve) */
    double sigma;              /* tension (given or, in length mode, computed; 0 for a straight segment there) */
    double energy;             /* bending energy integral kappa^2 ds */
    int has_inflection;        /* 1 if kappa changes sign inside (0, L) */
    double kappa0, kappa1;     /* curvature at p0 and at p1 */
    double residual;           /* end-condition error, see above */
    int npieces;               /* 1, or 2..3 for a chain */
    el_smooth_params rest[2];  /* pieces 2..npieces of a chain, in order */
} el_hermite_solution;

/* Solutions sorted by increasing energy; released by el_hermite_result_free.
 * unrepresentable: curves that exist (found and exact in the solver's variables) but
 * that neither one el_smooth_params nor a chain of them meets to opt->tol, so they are
 * not in solutions: a circular arc (an elastica for sigma = curvature^2, which
 * el_smooth_params reaches only in the limit k -> infinity, meeting the ends to ~1e-8)
 * when tol is below that; a near-straight curve at sigma |p1-p0|^2 = 0 or within ~1e-10 of it
 * between tangents within ~1e-6 rad of the chord (see el_hermite_solve); no other met in tests up to
 * sigma |p1-p0|^2 = 1e4 at the default tol. */
typedef struct el_hermite_result {
    size_t count;
    el_hermite_solution *solutions; /* count entries, library-owned */
    size_t unrepresentable;
} el_hermite_result;

/* Defaults: tension mode, sigma = 0, tol 1e-10, samples 12, grid 6, max_solutions 64. */
void el_hermite_options_defaults(el_hermite_options *opt);

/* The tension range el_hermite_solve covers: sigma |p1 - p0|^2 at most this (1e5). */
enum { EL_HERMITE_SIGMA_D2_MAX = 100000 };

/*
 * All elastic curves from (p0, t0) to (p1, t1) (t0, t1: nonzero tangent
 * directions, normalised inside), length <= one curvature period.
 * Tension mode follows seed 004 §4: normalisation (p0 = 0, t0 = (0,1),
 * |p1 - p0| = 1), the three cases of Theorem 6, the kappa_m bound of Theorem 9
 * (computed for every sigma), subintervals split at the real roots of (40),
 * at the special values (45) where the objective is singular and at the ends of
 * (18) and (44), bracketing and a root finder on each. Length mode: the tension
 * solutions form curves in the plane of the unknown and sigma; they are found on
 * opt->grid sigma lines and followed by continuation with the analytic gradient, and
 * the points of length L are solved for where the length crosses L (hermite_length.c).
 * The lines span the tension range the length allows (sigma (L/|p1 - p0| - 1)^2 |p1 - p0|^2
 * <= 130.13, up to sigma |p1 - p0|^2 = 1e5), both ends included, a little closer towards
 * its bottom (where a tension solve is cheap);
 * the curves are followed through that range and on up to 1e6 (the solutions up there
 * are returned too). It can miss a curve of solutions that crosses none of the grid
 * lines (a pair born and ending between two lines), and near the separatrix (|k| ~ 1)
 * the stretch of one that a continuation step passes over onto a branch running close
 * beside it (a step is refused where its change of length disagrees with the length's
 * slopes, which catches the branches seen so far): against 32 lines on 1000 random
 * problems (any ends, L within 0.1 % to 5 % of |p1 - p0|, L up to 8 |p1 - p0|, nearly
 * opposite and nearly aligned tangents) it misses none of 2536 solutions up to 1e5
 * (test_hermite_length.c); of 19 175 tension-mode solutions (L from 1.01 to 3 |p1 - p0|,
 * sigma |p1 - p0|^2 from -10 to 1000) solved again by their length it misses none with
 * grid 6, 12, 32, 48 or 64 (before that test, 35 at grids 12 to 64).
 * A count of 0 with EL_OK means no such curve exists (e.g. sigma very negative).
 * Completeness: the bracketing samples each subinterval, then bisects where the
 * samples leave room for two zeros of a convex objective (seed 004 §5 observes
 * convexity between two zeros), and checks local minima of |f| by minimisation;
 * two zeros closer than that can still be missed, mostly next to a piece end
 * where the objective is steep (against 300 samples, sigma |p1-p0|^2 uniform in
 * [-10, 40]: none of the 25 265 solutions of the 10 000 bench problems the
 * defaults were tuned on, 2 of 25 250 on another 10 000; with sigma |p1-p0|^2 in
 * [0, 5]: 18 of 26 810 and 22 of 26 770. Raise opt->samples where completeness
 * matters more than time). Nearly collinear tangents with the end point ahead: within
 * opt->tol of collinear the straight segment is returned; beyond, the near-straight curve
 * starts from a state next to the saddle (sigma > 0) or the centre (sigma < 0) of the
 * curvature's phase plane, which the solver's unknown resolves only to ~1e-16 absolute:
 * with tangents within 1e-2 rad of the chord it is also solved from the linear beam
 * (hermite_near.c) and added where the roots missed it (none listed twice): for sigma > 0
 * its root in the separatrix chart, y = ln(|F| - sigma) from the beam, then as one
 * el_smooth_params or a chain (below); for sigma |p1-p0|^2 in (-8 pi^2, 10] (from the
 * clamped beam's buckling load, where it stops existing) Newton on its start state. It is
 * returned only where its end curvatures are those of the root (within 10 %: a chain's are
 * ~1e-8 kappa_m off), else counted in unrepresentable. Measured (tangents 1e-9 to 1e-2 rad
 * off the chord, parallel, symmetric and one-sided, both signs; test_hermite_near.c): for
 * sigma |p1-p0|^2 from 1 to 1e5 it is returned or counted in every problem (counted in 30 %
 * of them at 1e-9 rad, 8 % at 3e-8, none from 1e-7: no representation meets tol, or its
 * curvature is not the curve's); below 0 (down to -70) for tangents from opt->tol (kappa_m^2 =
 * |F| + sigma taken as (|F|^2 - sigma^2) / (|F| - sigma) where it cancels). Towards the
 * buckling load the curve folds into a buckled one and stops existing (tangents -+1e-3 rad:
 * between sigma |p1-p0|^2 = -77.9 and -78). At sigma = 0 a curve whose tangents lie within
 * ~1e-6 rad of the chord is a sliver of a huge elastica that el_smooth_params meets only to
 * ~1e-16 / angle (counted in unrepresentable where that is above tol), and so at tensions
 * |sigma| |p1-p0|^2 below ~1e-10 (sqrt(mu) L ~ max(angle, sqrt|sigma| |p1-p0|)): measured over
 * tangents 1e-12 to 1e-2 rad (parallel, symmetric, one-sided, both signs, mirrored) and
 * sigma |p1-p0|^2 from -70 to 1e5 (0 and tiny ones, 1e-14 up, of either sign, included; chords
 * at 0.3, -0.3 and 1 rad, lengths 1 and 2): returned or counted in each of 41 472 problems
 * (test_hermite_near.c).
 * Every solution is verified with el_smooth_eval and returned only if its residual
 * is <= opt->tol (after a Newton polish on the parameters when it misses by a
 * little, then a second one with k held at each of its nearest doubles).
 * High tension: near the separatrix (|F| = sigma, |k| = 1) the solutions lie
 * exponentially close to it (1 - |k| ~ exp(-sqrt(2 sigma) L') for the length L'
 * spent near the saddle, the near-straight stretch between two loops): the solver
 * searches there in ln(|F| - sigma), where they are well conditioned, and finds them
 * all (tested against a dense scan for sigma |p1-p0|^2 up to 1e4). But
 * el_smooth_params stores the modulus as k, and one ulp of k moves the end of a curve
 * through a saddle by about 1e-16 / (1 - |k|) (the distance 2K between its loops grows
 * like ln 1/(1 - |k|)): from sigma |p1-p0|^2 ~ 200 (~60 % of the solutions at 600,
 * all above ~3000) no single el_smooth_params meets tol. Such a curve is returned
 * as a chain (el_hermite_solution.npieces = 2 or 3) split at its saddles, each
 * piece with its own start point and phase measured from its own loop, so that the
 * loops' distance is carried by the phases instead of the rounded k
 * (hermite_chain.c); the phases are corrected until the chain meets the ends.
 * The pieces are the same elastica up to the rounding of k: position and tangent
 * continuous at the joints, curvature to ~1e-8 of kappa_m = 2 |k| sqrt(mu), the loops'
 * peak (kappa' jumps by as little at a loop's joint; a two-piece chain that would jump
 * by more, or by more than 5e-8 of its own largest curvature, has its joint moved until
 * the curvature is continuous), and the chain lies within ~5e-10 |p1 - p0| of the
 * exact curve (against a 90-digit evaluation, sigma |p1-p0|^2 up to 1e4; no
 * el_smooth_params can come closer where 1 - |k| ~ 1e-17); a near-straight chain
 * (tangents within ~1e-5 rad of the chord) within ~3e-9, its curvature, ~k' kappa_m, a
 * few % off where k' < 1e-7. A chain is returned only where one piece cannot meet tol, and
 * only where its pieces' force directions phi agree to 1e-7 rad (the correction's phases can
 * turn a piece's F: up to 0.9 rad, tangents -1e-6, +1e-6 rad at sigma |p1-p0|^2 = 1e5;
 * else counted in unrepresentable).
 * A circular arc (sigma = kappa^2, where the parametrisation needs |k| = inf) is
 * returned with k = 1e4 (counter-clockwise) or -1e4 (clockwise), accurate to ~1e-8
 * only: it appears when opt->tol allows.
 * Range: coordinates and |p1 - p0| at most 1e100, |p1 - p0| at least 1e-100 (the
 * curvature scales as 1/|p1 - p0|, mu as its square); the same problem scaled (sigma
 * by 1/scale^2) and moved gives the same solutions in units of |p1 - p0| (within 3.3e-9,
 * chains, on 342 solutions at scales 1e-90..1e90 and up to 1e6 |p1 - p0| from the origin:
 * test_hermite_scale.c); sigma |p1 - p0|^2 at most
 * EL_HERMITE_SIGMA_D2_MAX = 1e5 (above, solutions lie closer to the separatrix than the
 * search reaches, |F| - sigma
 * below 1e-300 sigma); any sigma below (very negative: no curve,
 * count 0). Length mode seeds its search in the same range of tension and follows the
 * curves of solutions on up to sigma |p1 - p0|^2 = 1e6: solutions between 1e5 and 1e6
 * (possible only for length < ~1.06 |p1 - p0|) are returned where such a curve reaches
 * them, with no completeness claim; none above 1e6.
 * Work, bounded by the options: tension mode evaluates the objective about
 * samples + 14 times per piece between split points (at most 65 pieces per branch,
 * two separatrix pieces of 11 samples at most per piece), plus at most 100
 * root-finder iterations per sign change; a chain (near the separatrix) at most 10
 * correction steps of 2 (m + 1) + 5 evaluations of its m + 1 unknowns; length mode solves grid tension problems
 * (with samples / 2, at least 4) and at most 1e5 evaluations for the tracing (EL_EMAXITER beyond).
 * res is overwritten (not freed first). EL_EINVAL leaves res untouched; EL_EMAXITER
 * returns the solutions found; other errors leave it empty (count 0).
 * Errors: EL_EINVAL (NULL, non-finite, zero tangent, mode not one of the two, tol not
 * > 0, samples outside 4..1000, grid outside 1..256, max_solutions 0, length not > 0
 * in length mode), EL_EDOM (p0 = p1, outside the range above, or length < |p1 - p0|
 * in length mode), EL_EMAXITER (length mode: the tracing's work limit reached, its own or
 * that of the case-3 problem solved inside next to a U-turn),
 * EL_ENOMEM, EL_EINTERNAL (a bracket of the kappa_m bound that should not fail did).
 */
int el_hermite_solve(const double p0[2], const double t0[2], const double p1[2],
                     const double t1[2], const el_hermite_options *opt,
                     el_hermite_result *res);

/* Release res->solutions and zero res; NULL is a no-op. */
void el_hermite_result_free(el_hermite_result *res);

/*
 * el_hermite_solve into the caller's memory, for a caller that solves many problems
 * into one reusable array (the Python binding: one call per problem, no allocation or
 * free crossing it). The solutions el_hermite_solve returns are copied to
 * solutions[0 .. min(*count, cap)), lowest energy first; *count is how many there are
 * (> cap: only the first cap are written; call again with an array of *count) and
 * *unrepresentable as el_hermite_result's. Nothing to free; solutions may be NULL when
 * cap is 0. Statuses as el_hermite_solve's: EL_EINVAL (also count or unrepresentable
 * NULL, or solutions NULL with cap > 0) writes nothing; EL_EMAXITER writes the
 * solutions found; other errors set *count = *unrepresentable = 0.
 */
int el_hermite_solve_into(const double p0[2], const double t0[2], const double p1[2],
                          const double t1[2], const el_hermite_options *opt,
                          el_hermite_solution *solutions, size_t cap, size_t *count,
                          size_t *unrepresentable);

/*
 * Diagnostics of the normalised tension problem (seed 004 §4-5): data
 * P = x(L), V = x'(L) after the normalisation x(0) = 0, x'(0) = (0,1), |P| = 1.
 * hcase: 1, 2 or 3 (Theorem 6); kappa_bound: |kappa_m| <= kappa_bound for all
 * solutions (Theorem 9 with the exact period, any sigma; -1 if no solution can
 * exist); interval: the search set I~ = [-bound, bound] intersected with (18),
 * ninterval <= 2 pairs [lo, hi] (case 2: one pair; case 3, where the unknown is
 * kappa0' for each of the four kappa0 of (24): ninterval = 0); root: real roots of the
 * polynomial (40) (case 1, 2) inside I~ sorted, root_branch: which root of
 * (17) reaches kappa_m^2 = 2 sigma there (0: kappa1 = (-V1 + sqrt)/P2,
 * 1: (-V1 - sqrt)/P2); special: the values (45), kappa0^2 = sigma and
 * kappa0' = 0, sorted. Errors: EL_EINVAL (NULL, non-finite, |P| != 1, |V| != 1
 * to 1e-9), EL_EDOM (sigma > 1e5, the range of el_hermite_solve), EL_ENOMEM, EL_EINTERNAL.
 */
typedef struct el_hermite_analysis {
    int hcase;
    double kappa_bound;
    size_t ninterval;
    double interval[4];
    size_t nroot;
    double root[8];
    int root_branch[8];
    size_t nspecial;
    double special[4];
} el_hermite_analysis;

int el_hermite_analyse(const double P[2], const double V[2], double sigma,
                       el_hermite_analysis *a);

/* ------------------------------------------------------------------- spline */

/*
 * Elastic splines (issue 14): the shape of a thin batten through N ducks. A
 * chain of smooth elasticae, piece i from point i to point i+1, each of the one
 * tension sigma (curvature 2 kappa'' + kappa^3 - sigma kappa = 0, seed 004),
 * with position, tangent and curvature continuous at every point; kappa' jumps
 * there (the duck's force). It is a critical point of
 * integral kappa^2 + sigma ds among the curves through the points, its pieces
 * started on the branch of least energy and followed from there (no loops where
 * the points are a gentle curve; on coarse or strange data another equilibrium
 * can be found, the solution need not be unique).
 *   EL_SPLINE_TENSION: sigma >= 0 given (1/length^2); sigma = 0 is the
 *       free-sliding batten, which need not exist (EL_EDOM);
 *   EL_SPLINE_LENGTH: the total length given; sigma (any sign: < 0 is a
 *       batten pushed together) is computed.
 * Forces: with the bending energy written (EI/2) integral kappa^2 ds, each piece
 * carries the constant force (seed 004 (9)-(10); derived in spline.c)
 *   F = (sigma - kappa^2) T - 2 kappa' N     (T, N: unit tangent and normal),
 * in units of EI/2: the force the batten after a section exerts on the batten
 * before it (tension positive along T). The duck at an interior point i holds
 * F_{i-1} - F_i (normal to the batten, as for a frictionless duck, because the
 * tension is common).
 */
enum el_spline_mode { EL_SPLINE_TENSION = 0, EL_SPLINE_LENGTH = 1 };

/* End conditions of an open spline. */
enum el_spline_end_kind {
    EL_SPLINE_NATURAL = 0,   /* a free end: kappa = 0 there */
    EL_SPLINE_TANGENT = 1,   /* a clamped end: the tangent direction is given */
    EL_SPLINE_G2 = 2         /* tangent and curvature given (meets other geometry G2); see below */
};

typedef struct el_spline_end {
    int kind;              /* el_spline_end_kind; default EL_SPLINE_NATURAL */
    double tangent[2];     /* TANGENT, G2: the direction of travel there (at the last point: the
                              direction the curve arrives in); nonzero, normalised inside */
    double curvature;      /* G2: the signed curvature there (+ = counter-clockwise), 1/length */
} el_spline_end;

typedef struct el_spline_options {
    int mode;              /* EL_SPLINE_TENSION (default) or EL_SPLINE_LENGTH */
    double sigma;          /* tension mode: sigma >= 0 (1/length^2); default 0 */
    double length;         /* length mode: total length > the polygon's; default 0 (unset) */
    int closed;            /* 1: a closed curve through the points (start/end ignored); default 0 */
    el_spline_end start;   /* end condition at the first point; default natural */
    el_spline_end end;     /* end condition at the last point; default natural */
    double tol;            /* accepted residual: position / chord, tangent (rad), curvature jump
                              times the local chord, length / length; 1e-14..1e-3, default 1e-10 */
    int max_iter;          /* Newton iterations per solve (at most), 1..1000; default 60 */
    int max_steps;         /* continuation steps (each family), 1..1000; default 60 */
    const el_smooth_params *initial;   /* NULL (default), or ninitial = npoints - 1 pieces of
                              an open spline through the points with these ends (G2 ends only
                              clamped; its tension the given one in tension mode), e.g. the
                              el_hermite_solve solution a G2 blend between two edges should
                              follow: the solve starts from it (Newton) instead of its own
                              start, so it keeps that branch; caller-owned, read only */
    size_t ninitial;
} el_spline_options;

/*
 * The spline: a chain of pieces from knot to knot, the knots being the points
 * and, next to each G2 end, its guide duck (el_spline_solve: G2 ends). Open:
 * npieces = npoints - 1 + nguides; closed: npieces = npoints (the last piece
 * runs from the last point back to the first; a last point equal to the first
 * is dropped first). Without guides pieces[i] runs from point i to point i+1;
 * a guide duck at the start ends piece 0 and starts piece 1 (guide_pieces[0] =
 * 1), one at the end starts the last piece. A piece starts exactly at its point
 * (x0, y0 are the given coordinates; at a guide, the guide's position) and
 * ends at the next knot within the residual. Straight pieces (collinear data)
 * have k = 0: kappa = 0 solves the curvature equation for every sigma.
 */
typedef struct el_spline_result {
    size_t npoints;        /* points used (closed: without a repeated first point) */
    size_t npieces;
    el_smooth_params *pieces;  /* npieces, library-owned */
    double *forces;        /* 2 npieces: each piece's constant force F (see above) */
    double *angles;        /* npoints: tangent angle at each point (rad, continuous along the curve) */
    double *curvatures;    /* npoints: curvature at each point */
    double sigma;          /* the tension (given or computed) */
    double length;         /* total arc length */
    double energy;         /* bending energy integral kappa^2 ds of the whole curve */
    double max_curvature;  /* max |kappa| over the whole curve */
    double residual;       /* largest of the accepted residuals (see tol), measured at the end */
    int iterations;        /* Newton iterations spent, over all continuation steps */
    size_t nguides;        /* guide ducks: one per G2 end (0, 1 or 2), the start's first */
    size_t guide_pieces[2];    /* the piece each guide duck starts */
    double guides[4];      /* their positions (x, y) */
    double guide_forces[4];    /* the force each exerts on the batten (x, y; units of EI/2,
                              as forces): F of the piece before minus F of the piece after,
                              normal to the batten */
    int loops;             /* 1: the spline crosses itself where the polygon of its knots does
                              not (where that polygon crosses itself: between two pieces with
                              no crossing of the polygon between their spans or a neighbour
                              of each), or (tension mode) is longer than 4 x that polygon: it loops
                              away from its ducks; no fair batten was found at this tension
                              (spline_fair.c; tension mode follows the family from the taut
                              batten before it settles for one). 0: it follows its ducks */
    double reach[3];       /* length mode, where the family of tension solutions was followed
                              (el_spline_solve): the least and the greatest length of the
                              splines met on it, the greatest of those that do not cross
                              themselves (where none was followed: of tension mode's splines
                              met looking for a bracket, spline_bracket.c); all 0 where none
                              was met. Tension mode with G2 ends, EL_ENOCONV: reach[0],
                              reach[1] the lengths of ladder's two G2 battens (below).
                              Set on EL_OK, EL_ENOCONV and EL_ERANGE (res otherwise empty) */
    double resolution;     /* the residual double precision allows this spline's pieces near
                              the separatrix (Accuracy, el_spline_solve), where that exceeds
                              tol: the largest piece's bound; 0: none past tol */
    double ladder[2];      /* length mode: the least and greatest tension (1/units^2) of
                              tension mode's splines reached looking for two that bracket
                              the length (spline_bracket.c); 0 where it did not run or
                              reached none. Set where reach is. Tension mode with G2 ends,
                              EL_ENOCONV: of the G2 battens met (the free batten's family
                              followed in tension, the search by length; spline_g2_tension.c)
                              the greatest tension below the one asked and the least above
                              it (reach: their lengths; 0 where none) */
    double largest[3];     /* tension mode, EL_ENOCONV at sigma x (longest span h)^2 >= 300:
                              the highest tension (1/units^2) the search solved these points at
                              without loops (no bound: near it the solve is not monotone, a
                              tension a little below can fail; spline_limit.c), sigma h^2 = min(asked, 1024) x 2^(-j/4) down to 100 then 3
                              bisections in log above it (up to 18 solves, ~0.3-0.5 s,
                              within the call's work budget: stopped; spline_limit.c), that spline's resolution and the least |1 - k^2|
                              of its pieces (why none above it: Accuracy, el_spline_solve);
                              all 0 where not looked for or none solves */
    int slides;            /* tension 0, EL_EDOM: 1 where a batten through the points was found
                              but is no minimum, an unstable equilibrium (its second variation
                              reduced to the knot angles has a negative eigenvalue,
                              spline_stable.c): it slides off its ducks at span slide_span (from
                              point slide_span to slide_span + 1, counted from 0: the span whose
                              length grows most along that mode); 0 otherwise */
    size_t slide_span;     /* also where unstable: the span moving most along that mode (where
                              only the spans' lengths are the mode: of the spans past their
                              force-free length the one whose energy falls fastest in its own
                              length, the most negative d2/dl2 = 1 / gamma_j; by tension too,
                              where such spans are the only cause, spline_stable.c's
                              TENSION_COUNT) */
    int unstable;          /* EL_OK, tension > 0 or length mode, open without G2 ends: 1 where
                              the spline returned is an equilibrium but no minimum of integral
                              kappa^2 + sigma ds with its ducks held (by length: under its
                              length; spline_stable.c): a batten bent so would snap to another
                              shape (QA19 W2's 5 ducks turning 170 deg at sigma 1e-4 .. 0.05).
                              Returned as found (fair, G2 through the ducks), only flagged;
                              by tension (no initial pieces) only once the family followed
                              from a ladder of tensions reached no stable one of less energy
                              (spline_stable.c's STABLE_FAMILY; tension 0 likewise before it
                              refuses). 0: a minimum, or not judged (closed, G2 ends, a circle piece
                              |k| >= 1e3 at sigma = kappa^2, by length a singular reduced
                              Hessian; tension 0: slides above) */
    unsigned long work;    /* the call's work: evaluations of the whole chain (each evaluates
                              every piece once; each start of the pieces counted as one)
                              over every solve el_spline_solve made, the
                              G2 ends' search by length and the largest's solves above
                              included (none of those where its tensions sigma h^2 / h^2 are
                              not doubles > 0: spans of ~1e300) */
    int stopped;           /* 1: the call stopped at its work budget, one for the whole call
                              shared by all its solves and searches: max_steps x max_iter x
                              (16 + 64 / m) chain evaluations for m pieces (57 600 + 230 400 / m
                              at the defaults: 61 038 for 68 points, 96 000 for 7, 288 000 for
                              2; measured on the tests' calls, not derived); no search goes
                              past it, every path ends at its next evaluation, and only a
                              solution already found is evaluated again past it (a few
                              evaluations: work may exceed the budget by those). The status
                              is then what the call had reached (mostly EL_ENOCONV, or
                              EL_ERANGE with reach; EL_OK only for a spline solved to tol
                              before, its figures and unstable those of its own pieces) and
                              largest is the largest tension solved before it ended (0 where
                              none). The fuzz's 7 ducks at sigma 49.5 with a G2 start: 805 120
                              evaluations, 9.7 s, when each solve had a budget of its own; now
                              96 000, 1.3 s. No call of the library's tests or bench comes
                              near it (the most: 9.82 x max_steps x max_iter for 68 points by
                              length, 35 364, 5 s; 55.2 x for a 2-point G2 batten, 198 716,
                              0.4 s). Set with reach, and on EL_EDOM */
} el_spline_result;

/* Defaults: tension mode, sigma 0, open, natural ends, tol 1e-10, max_iter 60, max_steps 60. */
void el_spline_options_defaults(el_spline_options *opt);

/*
 * The elastic spline through the n points xy (2n, interleaved).
 * Method (spline_chain.c, spline_path.c, with the derivations): Newton on the
 * tangent angles at the points (and sigma in length mode) with the curvature
 * jumps as equations; each piece is the Hermite elastica from (point i, angle
 * i) to (point i+1, angle i+1) at its tension, its own five parameters
 * eliminated in the same Newton step (implicit function theorem), so it
 * continues the previous iterate's branch; the knot system is tridiagonal
 * (cyclic when closed, bordered in length mode), solved by GSL in O(n) per
 * iteration; steps halved until the residual decreases. Start: tangents of the
 * circles through three consecutive points, pieces from the linearised batten
 * or, where the tangents are far from the chord, the least-energy Hermite
 * elastica (el_hermite_solve). If Newton fails there: continuation in sigma
 * from sigma h^2 = 40 (solved directly) to sigma. Length mode: the tension
 * solution of that length on the family through the free batten (or as near
 * sigma = 0 as continuation gets), the first one met following it: Newton with
 * the length as an equation from the start, then from the free batten, each
 * trusted only while it contracts (no fold crossed); else pseudo-arclength
 * continuation in (angles, sigma) until the length is bracketed, then that
 * Newton (where the continuation to sigma = 0 stopped at a fold in sigma, from the
 * fold's other side on: t48 of the QA's random ducks failed at every length from 1.2 x
 * its polygon); where that stalls, the path again leaping once over the stall and with
 * the length as a coordinate of the path (a fold in sigma where the knot angles stand
 * still: ducks whose symmetry fixes every tangent, a star, a ring on a circle), the one
 * that does not cross itself kept, then the least integral kappa^2; where all of those fail,
 * the plain path again refusing a step whose length moves against the secant's prediction
 * by more than it predicted (another branch: QA21's 40 ducks stopped at 1.0499 x their
 * polygon, the family goes on through a second free batten at 1.07 x) (spline_path.c).
 * Where none of that reaches the length: tension mode's splines at sigma h^2 = 40 x 2^j
 * on the mean chord (down to j = -16, or up to 6 while they converge) until two bracket
 * it (up without a bracket, again from 40 by continuation in sigma, x 2^(1/4) a step, while
 * the length falls: a rung solved afresh can leave the family, QA14's sketch at 80; where 40
 * has no solution, from the bracket's long rung: ring77 at 1.1 x its polygon), the bracket narrowed along either's family by continuation in sigma, then the
 * length as above, the one that does not cross itself kept (spline_bracket.c: QA13's
 * 8-point walk, without a free batten, reached no length 1.03 .. 15 x its polygon; now
 * every one that its tensions sigma h^2 = 0.01 .. 200 give, at those tensions); where each
 * of those crosses itself, the same from the rungs that do not and from 7 finer rungs
 * between the bracket's two. A spline by length that crosses itself (loops) where its
 * ducks' polygon does not is tried so too, and kept (loops 1) only where no fair one is
 * reached (ring77 at the length of its fair spline at sigma h^2 20 on the longest span:
 * one crossing itself at 35.7 before).
 * A length not reached where splines were met following the family is EL_ERANGE, res->reach
 * giving the lengths met and the longest without a crossing, res->ladder the tensions
 * of tension mode's splines met looking for a bracket (a length within the lengths met
 * too: QA14's sketch at sigma h^2 450 said EL_ENOCONV, "no spline reached"). Work is bounded:
 * the whole call by its work budget (res->stopped: max_steps x max_iter x (16 + 64 / m) chain
 * evaluations for m pieces, shared by every solve and search it makes); each path at most
 * max_steps continuation steps (4 x in LONG_PATH, below) of at most
 * max_iter Newton iterations (20 for a first attempt, 12 for a step), each with
 * at most 12 step halvings (4 in a continuation step), each O(n); 100 points
 * take about 1.5 ms of CPU, 1000 about 12 ms, in either mode when the length is
 * near the free batten's (bench/); lengths far from it (a batten pushed into
 * waves between its ducks, or pulled nearly straight) take tens of continuation
 * steps.
 * End conditions (open curves): natural or tangent at either end: a batten
 * with given tension has exactly one degree of freedom per end.
 * G2 end (tangent and curvature given, to meet other geometry G2). Counting,
 * with sigma given: n points have n knot angles, and n - 2 interior curvature
 * conditions plus one per natural end; a clamped end fixes its angle and drops
 * its condition; a G2 end fixes the angle and keeps a condition, so it needs
 * one unknown more. A frictionless duck pushes only normal to the batten
 * (that is the common sigma: F . T is continuous where theta, kappa and sigma
 * are), so the unknown is a duck, not a tension of the end span's own (a duck
 * with friction); and least energy cannot place a free duck (at a minimum its
 * force vanishes: the G1 curve). So each G2 end has a guide duck in its end
 * span, a quarter of the span's chord from the end (two G2 ends of a
 * two-point spline: at 1/4 and 3/4), free to move only along the chord's
 * normal, frictionless like the others (theta, kappa continuous, kappa'
 * jumps): unknowns its offset and its angle, equations the end's curvature and
 * its curvature jump. A quarter: in the linearised span it is where the
 * curvature's change is fairest (least integral kappa'^2, spline_guide.c).
 * Every piece has the common sigma, in either mode, for any n >= 2 (two points
 * with G2 ends: the G2 blend between two edges, three pieces). The guides are
 * in the result (nguides, guides, guide_forces, guide_pieces). Method: the
 * spline with the G2 ends only clamped (its G1 sibling) is solved first; the
 * guides are placed on it (it is then a solution for its own end curvatures,
 * with no force on the guides) and the end curvatures moved to the given ones
 * by continuation. Length mode: the sibling of that length bent at that length,
 * else the free batten's sibling bent and followed in length. Tension mode, where
 * none is found so (no sibling at that tension: at sigma = 0 the clamped free batten
 * of two walls slides off its ducks, the guided one does not), the length whose G2
 * batten (as length mode finds it) has that tension: a ladder of 1.02 .. 10 x the
 * polygon brackets it, GSL's Brent narrows it, Newton at the tension finishes
 * (spline_g2_tension.c; not with initial). With initial,
 * the sibling is Newton's from it (no other start is tried). A G2 batten is
 * hardly shorter under tension than free (its guides end up on the end
 * tangents: 1-2 % at most, some get longer): a length below that is not found
 * (EL_ENOCONV). Measured against the former rule (the end span with a tension
 * of its own) on 300 random battens: solved 100 % vs 80 % (in length mode 97 %
 * vs 73 %), energy over the clamped spline's 1.014 vs 1.028 (median), no end
 * span in compression (the former: sigma h^2 < -10 in 131 of 240); on 200
 * designer's ducks 100 % vs 74 %; two-point blends 400 of 400.
 * Degenerate data: collinear points in order along the line with natural (or
 * along-the-line tangent, or G2 of curvature 0: the guides on the line, holding
 * nothing) ends give the straight line (k = 0 pieces; in length
 * mode when the length is the polygon's; longer, the batten buckled in its
 * first mode, the least energy at a small excess, with its largest bow to the
 * left of the line's direction, then followed in length: equal spans bow
 * alternately, uneven ones mostly in the longest span); two points with
 * natural ends are the straight segment, with both
 * tangents the least-energy Hermite elastica of that tension or length (by length: the
 * chain started from el_hermite_solve's least-energy solution). Ducks near a line
 * (each within 5 % of the first-to-last chord from it, every chord advancing along it,
 * tangent ends within 0.05 rad of it, no G2 end) pushed longer: the buckled batten of the
 * ducks projected onto the line (its first mode, either side), moved to the ducks by
 * continuation in their positions, or the path from the free batten where that ends at a
 * lower energy. Tension mode: a solution that crosses itself where its ducks' polygon
 * does not, or is longer than 1.5 x it, is not taken as it is: the family of tension
 * solutions is followed by pseudo-arclength from the taut batten (sigma h^2 = 40, 10, 4 or
 * 1 on the mean chord, the first that converges fair) down to sigma, through its folds,
 * and of those found the one that follows its ducks is kept, then the least
 * integral kappa^2 + sigma ds (the functional the equations make stationary; QA's spike
 * ducks at sigma 1.25: a figure eight, now the batten, itself no minimum: unstable); where none follows its ducks,
 * loops says so (spline_fair.c); at sigma h^2 <= 40 on the mean chord first from tension
 * mode's fair solutions at 0.9, 1.1, 0.75, 1.3 x sigma, by continuation in sigma (spline_path.c
 * NEIGHBOURS: QA's ring77 looped at sigma h^2 95 .. 120 on its longest side and reached
 * nothing at 200, fair at 90 and 150), and where nothing was reached, from those that loop
 * (the least integral kappa^2 + sigma ds of those reaching sigma, loops 1: QA's rw15 at
 * sigma h^2 2 .. 5, where every spline found loops). Every search judges "follows its ducks"
 * by loops' own rule, a polygon that crosses itself included. Before that: a solution of the direct Newton longer
 * than 1.5 x the ducks' polygon (it winds away from them) is replaced by the free batten pulled
 * to that tension, or the batten brought down from sigma h^2 = 40, where that converges
 * shorter; where neither the direct Newton nor the batten from sigma h^2 = 40 converges,
 * the free batten pulled to that tension (small tensions: the least-energy Hermite piece
 * the start takes can be a curve at the tension's scale 1 / sqrt(sigma)). Without a free
 * batten (a closed ring of ducks; a zigzag that slides off) length mode follows the
 * length from the batten under sigma h^2 = 40, 4 or 0.4 (the first that converges). Two
 * consecutive points that coincide are EL_EINVAL (the batten cannot pass a duck twice in no
 * length); a closed curve needs 3 distinct points.
 * Accuracy: the residual (see tol) reaches ~1e-14 for moderate tensions. Two
 * configurations are resolved only as far as el_smooth_params can:
 *   - circular arcs: a piece with kappa^2 = sigma and no force (|k| = infinity),
 *     e.g. ducks on a circle of radius R with sigma = 1/R^2, closed or with
 *     tangent or G2 ends on the circle. It is the arc with |k| ~ 1e4 (as
 *     el_hermite_solve's circles), ~1e-8 from the circle; a spline is accepted
 *     (EL_OK) when what does not touch such a piece is within tol and its
 *     residual is at most 1e-7. Pieces near a circle (sigma within ~1e-5 of
 *     kappa^2, |k| in the hundreds) count as such when el_smooth_eval resolves
 *     them to less than tol: 64 eps (1 + max|u|)(1 + |k|) / sqrt(mu) > tol length.
 *   - high tension, pieces near the separatrix (1 - k^2 -> 0: a nearly straight
 *     run between two ducks' boundary layers, the batten pulled tight, or a G2
 *     blend between nearly collinear edges): a double k gives 1 - k^2 only in
 *     steps of delta = 2|k| ulp(k) (2.2e-16 near 1), and the first integral
 *     kappa^2 = 4 mu (c^2 - (1 - k^2)), c = cos((theta - phi)/2), ties the state to
 *     it. A piece's bound b (in the residual's units, h its chord) is
 *     min(1, delta / |1 - k^2|) kappa_max h (a sinh boundary layer
 *     A e^{-w s} + B e^{w (s - L)} has A B proportional to 1 - k^2: the far end's
 *     curvature known to delta / |1 - k^2| of itself) plus 2 delta / (sqrt(c^2 +
 *     delta) + c) (the angle theta = phi + 2 acos c at fixed kappa, c at the piece's
 *     better resolved end); a joint carries the sum of its two pieces' b, an end or
 *     a piece's end point its own. Where some b exceeds tol, res->resolution is the
 *     largest such sum, and the spline is accepted (EL_OK) when what touches no
 *     such piece (nor a circle piece) is within tol and its residual is at most
 *     min(res->resolution, 1e-7); else EL_ENOCONV with the spline in res and the
 *     same resolution. A circle piece is judged by the circle rule only. Measured
 *     on G2 blends between edges d = +-1e-12 .. 0.1 rad apart, end curvatures 0,
 *     chord h = 1e-3, 40, 4e4, sigma h^2 0 .. 1e4: solved 81 of 96 at each h (61
 *     before), accepted residuals up to 5.3e-8, each within its resolution
 *     (curvature jumps x h up to 1.4e-7); refused: d = +-1e-9 at sigma h^2 = 0.16
 *     (residual 5.55e-9 against 5.46e-9), -1e-12 at 1e4 (3e-7, a longer branch),
 *     and none reached (res empty) for |d| >= 1e-6 at sigma h^2 = 1600 .. 1e4 (the
 *     clamped sibling is not found); end curvatures 0.001, -0.002 at h = 40: 77 (70
 *     before), 5 at sigma h^2 = 1600 refused within their resolution but above
 *     1e-7 (1.2e-7 .. 9.4e-7). Natural ends keep their accuracy (each piece's u
 *     is placed with its larger curvature near u = 0). Where the direct Newton and the
 *     continuations fail, Newton from the taut batten's tangents (the chords'
 *     bisectors, spline_path.c's TAUT_START): on 31 random and hand-placed sets of ducks
 *     at tension x (longest span)^2 = 100 / 200 / 300 / 500 / 1000, 29 / 26 / 20 / 4 / 1
 *     solved (to 1e-8; before 18 / 13 / 10 / 2 / 1). Where that fails too, the
 *     continuation from sigma h^2 = 40 again with 4 x max_steps (spline_path.c's
 *     LONG_PATH: it crawls there and ran out of steps): on 23 random walks and
 *     sketches at 300 / 450 / 500 / 700 / 1000, 19 / 11 / 8 / 2 / 0 solved without
 *     loops (to 1e-8; before 17 / 3 / 1 / 0 / 0; examples/ducks.csv at 450 and 500 to
 *     2.5e-8, 3.6e-8, within its resolution). Beyond ~500 on the longest span
 *     mostly no spline is found (EL_ENOCONV, res empty): a piece's tail
 *     multiplies a change at its start by ~exp(sqrt(sigma / 2) h): its modulus k is
 *     within ~exp(-sqrt(sigma / 2) h) of 1 (examples/ducks.csv's longest span: 1 - k^2 =
 *     -7e-9 at sigma h^2 500), its far end known to ~4.4e-16 / |1 - k^2| of its curvature
 *     (resolution 1.2e-7 at 450, 2.9e-7 at 500, 4e-7 at 520, none reached from 560).
 *     res->largest then holds the highest tension the search solved (spline_limit.c;
 *     not a bound: near it the solve is not monotone), which the
 *     Python binding's error names. In length mode
 *     these are lengths within ~1/5 of the free batten's excess over the
 *     polygon's length (0.1 - 0.2 % of it on hand-placed points).
 * res is overwritten (not freed first): on EL_OK it holds the spline (residual
 * <= tol, or <= 1e-7 from circle pieces, or <= resolution <= 1e-7 from pieces
 * near the separatrix); on EL_ENOCONV the spline reached when
 * it is one to within 1e-6 (see Accuracy), else it is empty; on every other
 * error it is empty (npieces = 0, NULL arrays).
 * Errors: EL_EINVAL (NULL, n < 2, non-finite or coincident consecutive points,
 * bad options: sigma < 0 or non-finite in tension mode, zero tangent, closed with
 * fewer than 3 points, initial with ninitial != n - 1, closed, or a piece that
 * fails el_smooth_check or starts off its point by more than 1e-6 of its chord), EL_EDOM (length mode with length < the polygon's length;
 * before any search, what the spline's units (the mean chord S) cannot represent: S
 * outside [1e-150, 1e150], or in tension mode sigma S^2 > 1e150, in length mode
 * length / S > 1e150, or a G2 end's
 * |curvature| S > 1e150 (their squares must stay finite; spline.c's UNITS);
 * tension 0 when no free-sliding batten is found: continuation from a high
 * tension cannot reach sigma = 0, the family folds back, the batten slides off
 * its ducks; or the one found is no minimum and would slide off: res->slides), EL_ERANGE (length mode: no spline of the length reached where splines of
 * res->reach[0..1] were met following the family, mostly a length outside them;
 * res otherwise empty), EL_ENOCONV (Newton and continuation did not reach tol; with G2
 * ends also when the continuation in the end curvatures stops; a search ending near a chain
 * with a piece of non-positive length or non-finite unknowns), EL_ENOMEM,
 * EL_EINTERNAL.
 */
int el_spline_solve(const double *xy, size_t n, const el_spline_options *opt,
                    el_spline_result *res);

/* Release the arrays of res and zero it; NULL is a no-op. */
void el_spline_result_free(el_spline_result *res);

/*
 * One B-spline for the whole spline (planar, degree 3..7, clamped) within tol
 * of it: each piece by el_smooth_to_bspline_g2 (end point, unit tangent and
 * curvature exact, arc-length parameter), joined with knot multiplicity
 * degree - 2 at the points, so the B-spline is C2 in its parameter, which is
 * the arc length of the spline from point 0 at the points (between them it is not:
 * the certified distance is geometric, b(s) and the spline at arc length s can lie
 * farther apart than tol) (closed: the joint at point 0 stays
 * a clamped end, G2 by the same end conditions). out->max_deviation is the
 * largest certified distance of the pieces (plus the rounding of the joins).
 * Errors: EL_EINVAL (NULL, res empty, tol <= 0, degree outside 3..7, pieces that do
 * not meet within tol as el_smooth_chain_to_bspline says: an unconverged result's),
 * EL_EDOM (tol below what double precision resolves, see el_smooth_to_bspline),
 * EL_EMAXITER (some piece did not reach tol: the B-spline is returned with its
 * honest certified distance), EL_ENOMEM, EL_ESINGULAR. out untouched on errors
 * other than EL_EMAXITER.
 */
struct el_bspline;   /* defined in the bspline section below */
int el_spline_to_bspline(const el_spline_result *res, double tol, int degree, struct el_bspline *out);

/* ------------------------------------------------------------------- affine */

/*
 * Affine arc-length polylines, seed 002 (Kaeferboeck). A polyline x_0..x_N
 * (npts = N+1 points, interleaved x,y) has edges v_i = x_{i+1} - x_i and the
 * affine polyline coordinates (1)
 *   A_i = det(v_{i-1}, v_i)  (i = 1..N-1),   B_i = det(v_{i-1}, v_{i+1})  (i = 1..N-2).
 * It is an affine arc-length polyline when A_i = A != 0 for all i; then (and only
 * then) the uniform quadratic B-spline with that control polygon is curvature
 * continuous (seed 002 §2.5). Units: A, B are areas (length^2).
 * Range: the planar functions below multiply edge vectors, so they need the
 * largest edge component m in [1e-150, 1e150] (or all points equal): EL_EDOM
 * otherwise (products beyond double's range); no output is written then.
 */

/* el_bspline is defined in the bspline section below. */
struct el_bspline;

/* A[i-1] = A_i (npts-2 values) and B[i-1] = B_i (npts-3 values; B may be NULL,
 * and is not written when npts = 3). npts >= 3. Errors: EL_EINVAL, EL_EDOM (range). */
int el_affine_coords(size_t npts, const double *xy, double *A, double *B);

/* Affine length (3) L2 = sum_{i=1}^{N-1} cbrt(A_i) (real cube root, so a
 * clockwise polyline has negative length). npts >= 3. Errors: EL_EINVAL,
 * EL_EDOM (range). */
int el_affine_length(size_t npts, const double *xy, double *L2);

/*
 * Discrete affine curvature (4) k_i = det(n_i, n_{i+1}) / A with the affine
 * normals n_i = x_{i-1} - 2 x_i + x_{i+1}; for an affine arc-length polyline
 * this is k_i = 2 - B_i / A. For a general polyline A is replaced by
 * (A_i + A_{i+1}) / 2. k[i-1] = k_i for i = 1..N-2 (npts-3 values, dimensionless;
 * invariant under every affine map). npts >= 4.
 * Errors: EL_EINVAL (bad input), EL_EDOM (range), EL_ESINGULAR (A_i + A_{i+1} = 0;
 * the values before it are written).
 */
int el_affine_curvature(size_t npts, const double *xy, double *k);

/* The three discrete osculating conics of Theorem 2. */
enum el_affine_conic_kind {
    EL_CONIC_OUTER = 0,   /* centre xi_i, through x_{i-1}, x_i, x_{i+1}, x_{i+2} */
    EL_CONIC_INNER = 1,   /* centre xi_i, tangent to the three edges at their midpoints */
    EL_CONIC_MIDDLE = 2   /* centre xi_i, geometric mean of inner and outer */
};

/*
 * One osculating conic of the quadruple x_{i-1}..x_{i+2}:
 *   coef[0] x^2 + coef[1] x y + coef[2] y^2 + coef[3] x + coef[4] y + coef[5] = 0
 * (world coordinates, scale arbitrary); type = +1 ellipse (k_i > 0), 0 parabola
 * (k_i = 0), -1 hyperbola (k_i < 0), (6); center = affine evolute point (5)
 * xi_i = x_i + n_i / k_i (set to (0,0) for a parabola); kappa = its smooth affine
 * curvature (7): outer A^(-2/3) k (1-k/4)^(1/3), inner A^(-2/3) k (1-k/4)^(-1/3),
 * middle A^(-2/3) k (units length^(-4/3)).
 */
typedef struct el_affine_conic {
    int type;
    double center[2];
    double coef[6];
    double kappa;
} el_affine_conic;

/*
 * The npts-3 osculating conics of kind `kind` (enum el_affine_conic_kind) of an
 * affine arc-length polyline, out[i-1] for the quadruple x_{i-1}..x_{i+2}.
 * npts >= 4. Each quadruple must be equal-area, |A_i - A_{i+1}| <= 1e-6 |A_i|
 * (else EL_EDOM: the conics need x_{i+1}-x_i || x_{i+2}-x_{i-1}), and k_i < 4 for
 * the inner and middle conics (else EL_EDOM). Errors: EL_EINVAL, EL_EDOM (also
 * range, or a conic coefficient beyond double's range), EL_ESINGULAR (A = 0).
 * Everything is checked before out is written: out untouched on error.
 */
int el_affine_osculating_conics(size_t npts, const double *xy, int kind, el_affine_conic *out);

/*
 * Chaikin subdivision (§2.5): each edge x_i x_{i+1} gives 3/4 x_i + 1/4 x_{i+1}
 * and 1/4 x_i + 3/4 x_{i+1}; out has 2(npts-1) points. Keeps L2 and maps an
 * affine arc-length polyline with constant A to one with A/8. npts >= 2.
 * Errors: EL_EINVAL.
 */
int el_affine_chaikin(size_t npts, const double *xy, double *out);

/*
 * Degree-n Lane–Riesenfeld refinement (Theorem 5) of npts points in R^dim:
 * x' = mu^degree (x_0, x_0, x_1, x_1, ..., x_N, x_N), mu the averaging operator;
 * out has 2 npts - degree points of dim coordinates. degree = 2 is Chaikin.
 * Every affine length element det(dx_i..dx_{i+n-1}) of x (n = dim = degree) gives
 * two elements of x' with 2^(-n(n+1)/2) of its value, so L_n halves per element (10).
 * 1 <= degree, dim >= 1, npts >= 1 and 2 npts > degree. Errors: EL_EINVAL
 * (also when 2 dim npts doubles exceed the address space), EL_ENOMEM.
 */
int el_affine_lane_riesenfeld(int dim, int degree, size_t npts, const double *x, double *out);

/*
 * Affine length elements in R^n, Definition 3 (8): D[i] = det(dx_i, ..., dx_{i+n-1})
 * for i = 0..npts-1-n (npts-n values), n = dim >= 2, points with dim coordinates.
 * The polyline is an affine arc-length polyline when all D[i] are equal (9).
 * Ln (may be NULL) = sum_i sign(D_i) |D_i|^(2/(n(n+1))). npts >= dim + 1.
 * D may be NULL. Each determinant is formed by GSL's LU on columns scaled by
 * powers of two, so entries near 1e+-300 neither overflow nor underflow inside
 * it; a determinant that is exactly singular (a repeated point, collinear
 * edges in R^2) is 0; one below double's range underflows to 0 (Ln is formed
 * from its logarithm, so it keeps such elements).
 * Errors: EL_EINVAL; EL_EDOM (a D_i beyond double's range, or an edge that
 * overflows; checked before anything is written); EL_ENOMEM; EL_EINTERNAL
 * (GSL LU failed).
 */
int el_affine_elements_nd(int dim, size_t npts, const double *x, double *D, double *Ln);

/*
 * The uniform B-spline of degree `degree` in R^dim with control polygon x
 * (npts points, npts >= degree + 1), Theorem 4: its Frenet curvatures are all
 * continuous iff x is an affine arc-length polyline (dim = degree).
 * clamped = 0: poles = x, knots 0, 1, ..., npts+degree, all multiplicity 1
 *   (usable parameter range [degree, npts]);
 * clamped != 0: the SAME curve (the part over [degree, npts], which starts at
 *   (x_0+x_1)/2 and ends at (x_{N-1}+x_N)/2 for degree 2) as a clamped B-spline:
 *   knots 0, 1, ..., npts-degree, end multiplicities degree+1, npts poles; the
 *   first and last degree-1 poles are the blossoms of the end segments, the
 *   others are x. Interior knots stay uniform, so every joint is a joint of
 *   the uniform spline.
 * The library allocates out's arrays (free with el_bspline_free);
 * out->max_deviation = 0 (exact). Errors: EL_EINVAL, EL_EDOM (clamped: an end
 * pole, a blossom extrapolated from x, beyond double's range), EL_ENOMEM; out
 * untouched on error.
 */
int el_affine_uniform_bspline(int dim, int degree, size_t npts, const double *x,
                              int clamped, struct el_bspline *out);

/* el_affine_uniform_bspline with dim = degree = 2 (seed 002 §2.5): G2 iff xy is an
 * affine arc-length polyline. npts >= 3. Errors as el_affine_uniform_bspline. */
int el_affine_quadratic_bspline(size_t npts, const double *xy, int clamped, struct el_bspline *out);

/*
 * The curvature-continuous quadratic B-spline of an affine arc-length polyline
 * x_0..x_m (npts = m+1 >= 4) that starts exactly at `start` and ends exactly at
 * `end` (e.g. the source curve's end points; NULL: the uniform spline's own end
 * (x_0+x_1)/2, resp. (x_{m-1}+x_m)/2). The uniform spline's first segment is
 * replaced by the parabola from `start` to m_2 = (x_1+x_2)/2 with the uniform
 * spline's tangent (x_2 - x_1) and curvature A_2/|x_2 - x_1|^3 there, so the joint
 * stays G2; the last segment likewise. Every other joint is the uniform spline's
 * (G2 iff A_{i-1} = A_i). Clamped, npts poles: start, c_0, x_2, ..., x_{m-2}, c_1,
 * end; knots 0, lambda, lambda+1, ..., lambda+m-3, lambda+m-3+mu (multiplicity 3
 * at the ends), c_0 = m_2 - (lambda/2)(x_2 - x_1) with
 * lambda^2 = 2 det(m_2 - start, x_2 - x_1) / A_2 (sqrt 2 when start = x_0),
 * mirrored at the end with A_{m-2}. The end tangents follow (the end parabola
 * has no freedom left); out->max_deviation = -1 (the caller measures it against
 * its source). Errors: EL_EINVAL (NULL xy/out, npts < 4, non-finite input),
 * EL_ESINGULAR (A_2 or A_{m-2} = 0), EL_EDOM (an end point not on the turning
 * side of its joint's tangent line: no such parabola; or so far from the
 * polyline that the knots or poles overflow), EL_ENOMEM; out untouched
 * on error.
 */
int el_affine_g2_bspline(size_t npts, const double *xy, const double *start, const double *end,
                         struct el_bspline *out);

/*
 * Length of the parabolic arcs of the replacement curve f~ (§4.2) through
 * samples p_0..p_N: arc j (p_j to p_{j+1}) is the parabola with tangent
 * p_{j+1}-p_{j-1} at p_j and p_{j+2}-p_j at p_{j+1} (ghost end points
 * p_{-1} = 3p_0-3p_1+p_2, p_{N+1} = 3p_N-3p_{N-1}+p_{N-2}, the end tangents of the
 * interpolating parabola). S[j] (N values) is its signed affine length (15)
 *   S_j = cbrt(4 A*_j A*_{j+1} / (A*_j + B*_j + A*_{j+1})),
 * sign = turning sense; S_j = 0 when no such convex parabola exists (the
 * tangents don't meet ahead: an inflection inside the arc; the arc is then a
 * straight segment). nsamples >= 3. Errors: EL_EINVAL, EL_EDOM (range), EL_ENOMEM.
 */
int el_affine_parabolic_lengths(size_t nsamples, const double *samples, double *S);

/* The most edges el_affine_polyline builds (bounded work; more: EL_EDOM at once). */
enum { EL_AFFINE_MAX_EDGES = 1000000 };

/* Options of el_affine_polyline; el_affine_options_defaults fills them. */
typedef struct el_affine_options {
    int split_inflections; /* 1: split at inflections (§4.4); 0: an inflection -> EL_EDOM */
    int skip;              /* l of §4.4: k_i of the l vertices next to an inflection are
                              left out of psi (default 2) */
    double skip_frac;      /* l = max(skip, ceil(skip_frac * piece edges)), in [0, 0.5)
                              (default 0, the paper). Near an inflection k_i ~ 1/j^2 at the
                              j-th vertex whatever n is, so a fixed l lets those terms
                              dominate psi; a fraction (e.g. 0.2) keeps k_i A^(-2/3)
                              converging away from the inflections. */
    int fit_ends;          /* 1: adjust each piece's A (secant on log|A|, t1 re-optimised
                              each time; where that misses, each of psi's 4 lowest minima
                              in t1 followed through A, |log(A/A0)| <= 0.5) until its last
                              vertex lands on the piece end (inflection or curve end), the
                              polyline's end within half a sample (none: EL_EDOM), as §4.4
                              allows; 0 (default): the paper's
                              A = (S/n)^3, the last vertex lands near the end */
    int optimise;          /* 1 (default): t1 minimises psi; 0: t1 stays at its start value
                              (affine length cbrt|A| along f~), the simple construction of
                              Craizer et al. the paper improves on (for comparison) */
    int max_iter;          /* golden-section iterations (default 100) */
    double t1_tol;         /* stop when the t1 bracket is shorter (sample units, 1e-10); the
                              result is then polished by Gauss-Newton on psi's residuals,
                              so t1 moves with the input as its conditioning says */
} el_affine_options;

void el_affine_options_defaults(el_affine_options *opt);

/*
 * Result of el_affine_polyline. Vertex j is xy[2j..2j+1], at parameter t[j] of
 * the replacement curve f~ (f~(j) = p_j; t beyond a piece's end means the
 * vertex is on the extrapolated last parabola of that piece). Pieces
 * p = 0..npieces-1 span vertices piece_start[p]..piece_start[p+1]
 * (piece_start has npieces+1 entries, piece_start[0] = 0, last = npts-1); in
 * piece p every det(x_j - x_{j-1}, x_{j+1} - x_j) = A[p] (signed: + counter-
 * clockwise); psi[p] = the minimised sum (delta k_i)^2; S_total = affine length
 * of f~ (sum |S_j|); infl_param: the npieces-1 inflection parameters of f~.
 */
typedef struct el_affine_result {
    size_t npts;
    double *xy;
    double *t;
    size_t npieces;
    size_t *piece_start;
    double *A;
    double *psi;
    double *infl_param;
    double S_total;
} el_affine_result;

/*
 * Seed 002 §4: approximate the curve through samples p_0..p_N (nsamples >= 4;
 * about 20 samples per vertex wanted) by a polyline x_0..x_n (n edges, n+1
 * vertices, n >= 3) that is an affine arc-length polyline on each inflection-
 * free piece: x_0 = p_0; per piece A = sign * (S_piece / n_piece)^3 with S from
 * (15); x_{i+1} = the next intersection of f~ with {z: det(x_i - x_{i-1}, z - x_i) = A};
 * t1 (the first free vertex of the piece; start value where the affine length
 * of f~ reaches cbrt|A|) minimising psi(t1) = sum (k_{i+1} - k_i)^2: a 24-point
 * grid over (start, start + 2 (t1 - start)] brackets the minimum, GSL's
 * gsl_min_fminimizer_goldensection refines it. Inflections: the caller's sample indices
 * infl[0..ninfl-1] (strictly increasing, in 1..N-1; the sample there is the
 * inflection point, e.g. known exactly from an elastica's parameters), or, when
 * ninfl = 0, where the turning sense of the arcs of f~ changes (§4.4); vertex
 * counts per piece proportional to the affine lengths, >= 3 each.
 * tangents: NULL for the paper's f~ (tangent p_{j+1} - p_{j-1} at p_j, ghost
 * points at the ends, as el_affine_parabolic_lengths), or nsamples forward
 * tangent vectors of the curve at the samples (interleaved; only directions
 * matter), e.g. exact ones of an elastica: each arc is then the parabola with
 * those end tangents (deviation O(h^4) instead of O(h^3), which keeps the
 * k_i A^(-2/3) of fine polylines accurate; an arc whose tangents don't meet
 * ahead is straight).
 * Errors: EL_EINVAL (bad input, n < 3, nsamples < 4); EL_EDOM (an inflection
 * while opt->split_inflections = 0, or inside a piece the caller gave as
 * inflection-free; n too small for the pieces; a straight piece;
 * the construction left the curve: n too small for the curve, e.g. fewer than
 * about 3 vertices per turn of the tangent; with fit_ends, no A lands a piece's
 * last vertex within half a sample of the piece end with none before it past
 * the end (past it: the vertices ran on along f~'s last parabola continued), or
 * the polyline's last vertex more than half a sample short of its end (the last
 * sample, or the inflection where the end piece is left out: n edges cannot turn
 * as far, e.g. 8 on a circle turning 4.2 times end at t = 99.7 of 159; an inner
 * piece may end short of its inflection: the next starts at that vertex);
 * n > EL_AFFINE_MAX_EDGES, refused
 * at once; samples out of range (above), or a tangent whose largest component
 * is outside [1e-150, 1e150] and not 0); EL_ENOMEM; EL_EINTERNAL (GSL).
 * Cost: about (opt->max_iter + 25) (n + nsamples) steps (x 30 with fit_ends).
 * An end piece worth less than 1.5 edges of affine length (an inflection next
 * to an end) is left out: the polyline then starts / ends at that inflection
 * (t[0] > 0 / t[n] near it), and infl_param lists only the inner inflections.
 * Far from the origin (survey coordinates: a 3 m curve at (512345.678, 5012345.432)) the
 * samples are taken relative to a local origin, a multiple of the power of two >= their
 * extent (exact: a curve 16 extents or more from (0, 0) in x or y; nearer, none), and the
 * vertices returned with it added back: t, A, psi as of the curve near (0, 0), the vertices
 * rounded once to the offset's ulps (el_affine_end_pieces alike).
 * opt may be NULL (defaults). res is filled only on success; free it with
 * el_affine_result_free.
 */
int el_affine_polyline(size_t nsamples, const double *samples, const double *tangents,
                       size_t ninfl, const size_t *infl, size_t n,
                       const el_affine_options *opt, el_affine_result *res);

/* Release what el_affine_polyline allocated and zero *res; NULL is a no-op. */
void el_affine_result_free(el_affine_result *res);

/*
 * The pieces el_affine_polyline splits these samples into (§4.4, the same inputs and
 * options: only split_inflections matters here) and the edge counts that keep its end
 * pieces: at n edges an end piece worth less than 1.5 edges of affine length,
 * n S_end / S_total < 1.5, is left out (the polyline then starts / stops at the
 * inflection). *npieces: the pieces of f~; ends[0]: the sample index where the first ends,
 * ends[1]: where the last starts (0 and nsamples-1 for one piece); n_min[0]: the fewest n
 * in [3, EL_AFFINE_MAX_EDGES] keeping the first piece, n_min[1]: keeping both end pieces
 * (0 where none up to EL_AFFINE_MAX_EDGES does). Exact: el_affine_polyline's own test, and
 * monotone in n (every n >= n_min keeps them, every n below leaves one out), so a caller
 * searching edge counts over the same samples skips the counts below at no risk.
 * Errors: EL_EINVAL, EL_EDOM (as el_affine_polyline's for these samples), EL_ENOMEM.
 */
int el_affine_end_pieces(size_t nsamples, const double *samples, const double *tangents,
                         size_t ninfl, const size_t *infl, const el_affine_options *opt,
                         size_t *npieces, size_t ends[2], size_t n_min[2]);


/* ------------------------------------------------------------------- bspline */

/*
 * A non-rational B-spline curve in R^dim (dim = 2 for planar curves).
 * Result type of every function that emits B-splines: the library allocates
 * poles, knots and mults; the caller releases them with el_bspline_free
 * (which also zeroes the struct). Knots are the distinct knot values, each
 * with its multiplicity (FreeCAD/OpenCASCADE convention); the flat knot
 * vector has npoles + degree + 1 entries.
 */
typedef struct el_bspline {
    int degree;            /* >= 1 */
    int dim;               /* coordinates per pole */
    size_t npoles;
    double *poles;         /* dim * npoles, interleaved */
    size_t nknots;         /* distinct knots */
    double *knots;         /* nknots, increasing */
    int *mults;            /* nknots multiplicities */
    double max_deviation;  /* certified distance to the source curve (0 if exact, -1 if unknown) */
} el_bspline;

/*
 * The most poles el_smooth_to_bspline builds (bounded work: a curve or a
 * tolerance that needs more is refused or answered with the best spline at the
 * limit, see there).
 */
enum { EL_BSPLINE_MAX_POLES = 10000 };

/* Release what the library allocated in b and zero it; NULL is a no-op. */
void el_bspline_free(el_bspline *b);

/*
 * Fill b with zeroed, malloc'ed arrays: poles (dim*npoles), knots and mults
 * (nknots each); max_deviation = -1. For code that builds B-splines (release
 * with el_bspline_free). Errors: EL_EINVAL (NULL b, degree < 1, dim < 1,
 * nknots < 2, npoles < degree+1), EL_ENOMEM (also when dim*npoles doubles
 * exceed the address space); b untouched on error.
 */
int el_bspline_alloc(el_bspline *b, int degree, int dim, size_t npoles, size_t nknots);

/*
 * EL_OK when b is a valid B-spline: degree >= 1, dim >= 1, knots finite and
 * strictly increasing with a finite range knots[nknots-1] - knots[0], end
 * multiplicities in 1..degree+1, interior ones in 1..degree, sum of mults =
 * npoles + degree + 1, finite poles, array sizes (npoles + degree + 1 knots,
 * dim*npoles poles) that fit in memory; else EL_EINVAL.
 */
int el_bspline_check(const el_bspline *b);

/* The flat knot vector (npoles + degree + 1 values) into flat. Errors: EL_EINVAL
 * (invalid b, NULL flat). */
int el_bspline_flat_knots(const el_bspline *b, double *flat);

/*
 * Points B(t_i) (de Boor's algorithm), pts: dim*n interleaved. t must lie in
 * [knots[0], knots[nknots-1]] (values outside by less than 1e-12 of |knots[0]| +
 * |knots[nknots-1]| + the knot range, the rounding of t there, are clamped to it;
 * beyond that EL_EDOM: no extrapolation).
 * Errors: EL_EINVAL (invalid b, NULL arrays with n > 0, non-finite t), EL_EDOM
 * (a t outside, checked before anything is written; or a value beyond double's
 * range, which only derivatives can reach, the values before it written), EL_ENOMEM.
 */
int el_bspline_eval(const el_bspline *b, size_t n, const double *t, double *pts);

/*
 * Derivative of order `order` >= 0 (0 = the points; orders above the degree
 * give 0) with respect to the B-spline parameter at the n values t,
 * out: dim*n interleaved. At a knot the right-hand derivative is returned
 * (the left-hand one at the last knot). Errors as el_bspline_eval.
 */
int el_bspline_derivative(const el_bspline *b, int order, size_t n, const double *t, double *out);

/*
 * Signed curvature det(B', B'') / |B'|^3 (positive = turning counter-clockwise)
 * of a planar (dim = 2) B-spline of degree >= 2, kappa: n values.
 * Errors: EL_EINVAL (dim != 2, degree < 2, ...), EL_EDOM (t outside: nothing
 * written; a curvature beyond double's range: the values before it written),
 * EL_ESINGULAR (B' = 0 at some t; the values before it are written), EL_ENOMEM.
 */
int el_bspline_curvature(const el_bspline *b, size_t n, const double *t, double *kappa);

/*
 * The natural C2 cubic (B'' = 0 at both ends) through the n >= 2 vertices xy
 * (2n, interleaved) of a polyline or discrete elastica, chord-length
 * parametrised: the knots are u_0 = 0, u_i = u_{i-1} + |xy_i - xy_{i-1}|
 * (multiplicity 4 at both ends, 1 inside), B(u_i) = xy_i, n + 2 poles.
 * out->max_deviation = -1 (no distance to the polyline is claimed).
 * Errors: EL_EINVAL (NULL, n < 2, non-finite), EL_ESINGULAR (two consecutive
 * vertices coincide), EL_EDOM (the polyline's length or a pole beyond double's
 * range), EL_ENOMEM. out is untouched on error.
 */
int el_bspline_interpolate_c2(const double *xy, size_t n, el_bspline *out);

/* An end condition of el_bspline_interpolate_c2_ends, in the chord-length parameter u:
 * order 1: B'(u) = value (a clamped end: a unit tangent there makes the speed 1);
 * order 2: B''(u) = value (value = 0 is the natural end; kappa N for a curvature
 * kappa with unit normal N when the speed there is ~1);
 * order 3: B'(u) = value and B''(u) = value2 (a G2 end: a unit tangent T and kappa N,
 * N the left normal of T, give the curvature kappa exactly). */
typedef struct el_bspline_end {
    int order;
    double value[2];
    double value2[2];   /* order 3 only */
} el_bspline_end;

/*
 * el_bspline_interpolate_c2 with end conditions: start and end each NULL (natural,
 * B'' = 0) or an el_bspline_end. An order-3 end has one more knot, in the middle of
 * its end span (B(u_i) = xy_i still at the chord-length u_i; n + 2 poles plus one per
 * order-3 end). Errors as el_bspline_interpolate_c2, plus EL_EINVAL for an order other
 * than 1, 2 or 3 or a non-finite value.
 */
int el_bspline_interpolate_c2_ends(const double *xy, size_t n, const el_bspline_end *start,
                                   const el_bspline_end *end, el_bspline *out);

/*
 * A clamped non-rational planar B-spline of degree 3..7 (simple interior
 * knots, so C^{degree-1}) whose distance to the smooth elastica segment p is
 * at most tol (same units as the coordinates) everywhere; its parameter is the
 * elastica's arc length s in [0, length]. End conditions (for tangent joins to
 * other geometry): B(0) and B(length) are the end points exactly as
 * el_smooth_eval gives them, and B'(0), B'(length) are the exact unit tangents
 * (cos theta, sin theta) of el_smooth_eval (speed 1, as the parameter is the
 * arc length), to the rounding of the first and last two poles, which they
 * fix: P_1 = P_0 + (u_1 / degree) T(0), P_{n-2} = P_{n-1} - ((length -
 * u_{N-1}) / degree) T(length), 0 = u_0 < u_1 < .. < u_N = length the
 * distinct knots (about 1e-14 rad when |x0|, |y0| are of the order of length). The
 * other poles by linear least squares on exact samples, knots by error
 * equidistribution with as few spans as the method finds. The distance is
 * certified: the upper bound max_t |B(t) - gamma(s1(t))| of the Hausdorff
 * distance (s1 = Newton foot point, a continuous map onto [0, length]),
 * computed on a dense grid and maximised locally with Brent's method, plus
 * 16 eps (|x0| + |y0| + length) for rounding; it is stored in
 * out->max_deviation (<= tol on success). Near a self-crossing of a looping
 * (k > 1) segment it is the distance to the corresponding branch, which can
 * exceed the distance to the point set. length = 0 gives p+1
 * coincident poles on [0, 1] with max_deviation 0 (B' = 0: no tangent).
 * Bounded work: at most EL_BSPLINE_MAX_POLES poles, and refused at once
 * (EL_EDOM, nothing computed) when tol < 1e-14 (length + |x0| + |y0| +
 * |q|/sqrt(mu)) (below what double precision resolves: the phase q carries an
 * absolute rounding of 1e-16 |q| into u), when the curve turns through more than
 * EL_BSPLINE_MAX_POLES radians (bound 2 |k| sqrt(mu) length), or when the first
 * estimate of the spans needed (from the knot density) exceeds twice the limit.
 * Cost: about linear in the poles built (~1 ms for 50 poles at 1e-6 length).
 * Errors: EL_EINVAL (bad params, tol <= 0 or non-finite, degree outside 3..7,
 * NULL out), EL_EDOM (the limits above), EL_EMAXITER (tol not reached within
 * the pole or iteration limits: the best B-spline found is returned in out with
 * its certified distance, max_deviation > tol; release it with el_bspline_free),
 * EL_ENOMEM, EL_ESINGULAR (a least-squares system failed). out is untouched on
 * errors other than EL_EMAXITER.
 */
int el_smooth_to_bspline(const el_smooth_params *p, double tol, int degree, el_bspline *out);

/*
 * el_smooth_to_bspline with G2 ends: also B''(0) and B''(length) are the exact
 * curvature vectors kappa N of el_smooth_eval (the third pole from each end
 * fixed by them: P_2 = P_1 + u_2 (T/p + u_1 kappa N / (p (p-1))), u_1 < u_2 the
 * first distinct knots, and its mirror image at the end), so with the
 * arc-length parameter the ends carry position, unit tangent and curvature:
 * pieces that meet G2 join C2 (el_spline_to_bspline). At least 2 * 3 - degree
 * spans. Same certification, statuses and outputs as el_smooth_to_bspline.
 * Exact in the construction, not in the stored poles: P_2 - 2 P_1 + P_0 is of
 * order kappa u_1 u_2, so a pole rounded to its coordinates' ulp moves the end
 * curvature by about eps |P| / (kappa u_1 u_2) relative (QA24: poles 5190 mm from
 * the origin, kappa 3.7e-4 /mm, end span 0.2 mm: 1.5e-7, one ulp of P_1 alone
 * 1e-7 to 5e-7; the piece's own curvature there 7e-14; the same spline with its
 * end point moved to the origin: 7.8e-13). For nearer ends, move the points
 * near the origin first.
 */
int el_smooth_to_bspline_g2(const el_smooth_params *p, double tol, int degree, el_bspline *out);

/*
 * One B-spline (planar, degree 3..7, clamped) within tol of a chain of n >= 1
 * smooth elastica segments that meet G2 (each starting where the one before ends,
 * with its tangent and curvature: an elastic spline's pieces, a Hermite chain):
 * each piece by el_smooth_to_bspline_g2, joined with knot multiplicity degree - 2,
 * so the B-spline is C2 in its parameter, the arc length from the first piece's
 * start. out->max_deviation is the largest certified distance of the pieces plus
 * the rounding of the joins (and what a joint's curvature mismatch costs); when that
 * sum alone exceeds tol the pieces are fitted again within tol less twice the joins'
 * rounding (at most twice).
 * Errors: EL_EINVAL (NULL, n = 0, tol <= 0, degree outside 3..7, a piece
 * el_smooth_check refuses, or one that does not start within tol of where the one
 * before ends, its tangent within tol / (the shorter piece's length) of that end's),
 * EL_EDOM (tol below what double precision resolves, see
 * el_smooth_to_bspline), EL_EMAXITER (some piece did not reach tol: the B-spline is
 * returned with its honest certified distance), EL_ENOMEM, EL_ESINGULAR. out
 * untouched on errors other than EL_EMAXITER.
 */
int el_smooth_chain_to_bspline(const el_smooth_params *pieces, size_t n, double tol, int degree,
                               el_bspline *out);

/* ------------------------------------------------------------------- blend */

/*
 * Blending-function curves of seed 003 (Miura et al.), built the way Eck's
 * MQ-curves are. A segment is a curve in the 4-dimensional span of
 *   f_0 = 1 - t,  f_1(t),  f_2(t) = f_1(1 - t),  f_3 = t,      t in [0, 1],
 * with  MQ (2.1):        f_1 = sqrt(c^2 + (1-t)^2),  f_2 = sqrt(c^2 + t^2);
 *       elliptic (2.16): f_1 = sn((1-t)K, k),        f_2 = sn(K t, k),  K = K(k).
 * Blending functions (2.13): h_0 = sum a_j f_j, h_1 = sum b_j f_j,
 * h_2(t) = h_1(1-t), h_3(t) = h_0(1-t) (the paper's 'h_3 = h_1(c,1-t)' is a
 * slip), determined by the 8x8 system (2.17) of the conditions (2.14)-(2.15):
 *   h_0(0) = 1, h_0(1) = 0, h_0'(1) = 0, h_0'(0) = -d,
 *   h_1(0) = 0, h_1(1) = 0, h_1'(1) = 0,  a_1 + a_2 + b_1 + b_2 = 0
 * (the ninth condition a_0 + a_3 + b_0 + b_3 = 1 follows; the paper's
 * 'a_0 + a_3 + b_0 + b_1' is a slip). Then sum h_i = 1, a curve
 * phi(t) = sum q_i h_i(t) starts at q_0 with phi'(0) = d (q_1 - q_0) and
 * ends at q_3 with phi'(1) = d (q_3 - q_2) (2.8)/(2.11): d is the free
 * end-derivative parameter. Eck's MQ basis (2.4) is d = 1/alpha(c) (2.5).
 *
 * Convention for k: here k is the elliptic MODULUS, as everywhere in this
 * library (sn(u, k) = sin am(u, k), K(k) = integral_0^{pi/2} dtheta /
 * sqrt(1 - k^2 sin^2 theta)). The paper's numbers use the PARAMETER m = k^2:
 * its rope example "k = 0.3" (q_1 = (0.5, 0.856945) = (1/d, K/d) with
 * K = 1.713889 = K(m = 0.3)) is modulus k = sqrt(0.3) here.
 *
 * Matrix M (row i = coefficients of h_i on f_0..f_3): a curve with control
 * points q_i has coefficient points p_j = sum_i q_i M[i][j] (2.18), and
 * q = p M^-1 (2.19).
 */
enum el_blend_kind { EL_BLEND_MQ = 0, EL_BLEND_ELLIPTIC = 1 };

typedef struct el_blend_basis {
    int kind;          /* EL_BLEND_MQ or EL_BLEND_ELLIPTIC */
    double c;          /* MQ: shape parameter, != 0 (the span depends on c^2); elliptic: 0 */
    double k;          /* elliptic: modulus in [0, 1); MQ: 0 */
    double K;          /* elliptic: complete integral K(k); MQ: 0 */
    double d;          /* > 0: end-derivative parameter, h_0'(0) = -d */
    double M[16];      /* row-major: M[4*i + j] = coefficient of f_j in h_i */
    double Minv[16];   /* row-major inverse of M */
    double G[16];      /* the same h_i on (f_0, B_1, B_2, f_3), B_1 = f_1 - f_1(0) f_0 - f_1(1) f_3,
                          B_2(t) = B_1(1-t): the cancellation-free form used for evaluation */
    double cond;       /* 1-norm condition number of the 8x8 system (2.17), solved for G */
    /* How the basis behaves on [0, 1]:                                        */
    double basis_min;  /* min over t and i of h_i(t) (<= 0: h_i(0) = 0 for i > 0), exact
                          to rounding: branch and bound on the exact range of h_i'', the
                          minima as zeros of h_i' (GSL Brent); it finds the dips within
                          0.01 of an end that samples miss (m >= 0.99: -1.05e-6 at
                          m = 0.99, d = 2) */
    int convex_hull;   /* 1 when basis_min >= -1e-12 (rounding): every h_i >= 0, so a
                          segment stays in the convex hull of its control points
                          (elliptic, d = 2: up to m = k^2 ~ 0.6, and again from
                          m ~ 1 - 1e-4, where the dip is below 1e-12) */
    double lebesgue;   /* max over t of sum_i |h_i(t)| (>= 1; 1 with the convex hull):
                          a curve point moves by at most this times the largest move
                          of a control point (64 samples, then Brent; and at least its
                          value where basis_min is reached) */
} el_blend_basis;

/*
 * Elliptic bases whose system (2.17) has cond > EL_BLEND_COND_MAX are refused
 * (EL_ESINGULAR). The matrix of (2.17) does not depend on d; cond ~ 6/|2 - K(k)|,
 * so the refused neighbourhood is |K(k) - 2| < ~0.006: k in (0.79932, 0.80544),
 * m = k^2 in (0.63891, 0.64874). There the basis is not
 * determined to any use: it grows like |K - d| / |2 - K| (at m = 0.6438, d = 2:
 * basis_min = -221, lebesgue = 443; at the threshold, d = 2: about -2.5 and 6).
 */
enum { EL_BLEND_COND_MAX = 1000 };

/*
 * Fill b for the MQ span with parameter c and end-derivative d (d = 1/alpha(c)
 * gives Eck's Omega_i). Errors: EL_EINVAL (NULL b, NaN/inf, d <= 0),
 * EL_EDOM (c = 0: the span degenerates), EL_ESINGULAR (the system (2.17) is
 * singular to working precision, condition > 1e13: |c| beyond ~1e3, where the
 * span tends to the quadratics), EL_ENOMEM, EL_EINTERNAL. b untouched on error.
 */
int el_blend_init_mq(el_blend_basis *b, double c, double d);

/*
 * Fill b for the elliptic span {1-t, sn((1-t)K,k), sn(Kt,k), t} with modulus
 * k (see the convention above) and end-derivative d > 0.
 * Errors: EL_EINVAL (NULL, NaN/inf, k < 0, d <= 0), EL_EDOM (k >= 1: K is
 * infinite, the basis does not exist), EL_ESINGULAR (the neighbourhood of
 * K(k) = 2, k = 0.80241, where the end conditions (2.14) do not determine h_0:
 * cond > EL_BLEND_COND_MAX, above), EL_ENOMEM, EL_EINTERNAL (GSL). b untouched
 * on error.
 */
int el_blend_init_elliptic(el_blend_basis *b, double k, double d);

/* Eck's d = 1/alpha(c) = (2c^2 + 1 + c s)/(c s), s = sqrt(c^2+1) (2.5), for |c|.
 * Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (c = 0, or |c| so small that d
 * overflows). */
int el_blend_eck_d(double c, double *d);

/*
 * Eck's MQ blending functions in closed form (2.4)-(2.5), as corrected:
 *   Omega_1 = (s+c)^2 beta/alpha (t + c sqrt(c^2+(1-t)^2) - s sqrt(c^2+t^2)),
 *   Omega_2(t) = Omega_1(1-t),  Omega_3 = t - alpha Omega_1 + (alpha-1) Omega_2,
 *   Omega_0(t) = Omega_3(1-t)   (for |c|; the printed Omega_1 swaps the roots).
 * omega[4*i + j] = Omega_j(t_i). Independent of el_blend_init_mq (a check of it).
 * Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (c = 0; a value beyond double's
 * range, for tiny |c| or t far outside [0, 1]: the rows before it are written).
 */
int el_blend_eck_omega(double c, size_t n, const double *t, double *omega);

/* The span functions f_j(t_i) and their t-derivatives: f[4*i + j]; any of
 * f, df, d2f may be NULL. Any finite t (the segment is [0, 1]). Errors: EL_EINVAL,
 * EL_EDOM (a value beyond double's range, t far outside [0, 1]: the rows before
 * it are written), EL_EINTERNAL (GSL). */
int el_blend_span_eval(const el_blend_basis *b, size_t n, const double *t,
                       double *f, double *df, double *d2f);

/* The blending functions h_j(t_i) (2.13) and t-derivatives: h[4*i + j]; any of
 * h, dh, d2h may be NULL. Errors as el_blend_span_eval. */
int el_blend_basis_eval(const el_blend_basis *b, size_t n, const double *t,
                        double *h, double *dh, double *d2h);

/* Control points q (4 points, 8 doubles) of the curve sum_j p_j f_j with
 * coefficient points p (8 doubles): q = p M^-1 (2.19). Errors: EL_EINVAL, EL_EDOM
 * (a result beyond double's range; q untouched). */
int el_blend_control_points(const el_blend_basis *b, const double *p, double *q);

/* The inverse: coefficient points p = q M (2.18). Errors: EL_EINVAL, EL_EDOM
 * (as above; p untouched). */
int el_blend_coefficients(const el_blend_basis *b, const double *q, double *p);

/* Curve points phi(t_i) = sum_j q_j h_j(t_i) (xy: 2n) and derivatives
 * dxy: 2n (may be NULL). Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (a point
 * beyond double's range: control points near DBL_MAX or t far outside [0, 1];
 * the points before it are written), EL_EINTERNAL (GSL). */
int el_blend_eval(const el_blend_basis *b, const double *q, size_t n, const double *t,
                  double *xy, double *dxy);

/* How el_blend_from_points reads four picked points. */
enum el_blend_pick {
    EL_BLEND_PICK_CONTROL = 0,      /* the points are the control points q_0..q_3 */
    EL_BLEND_PICK_INTERPOLATE = 1   /* the curve passes through them at chord-length
                                       parameters t = 0, t_1, t_2, 1 */
};

/*
 * Control points q (8 doubles) of a segment from four points pts (8 doubles).
 * EL_BLEND_PICK_INTERPOLATE solves sum_j q_j h_j(t_i) = pts_i, with
 * t_i = (chord length from pts_0 to pts_i) / (total chord length).
 * Errors: EL_EINVAL (NULL, NaN/inf, unknown mode), EL_ESINGULAR (coincident
 * consecutive points, or the 4x4 collocation system is singular), EL_EDOM (the
 * chord lengths or a control point beyond double's range: coordinates near
 * DBL_MAX; q untouched), EL_ENOMEM, EL_EINTERNAL.
 */
int el_blend_from_points(const el_blend_basis *b, const double *pts, int mode, double *q);

/*
 * Composite curve of nseg >= 1 segments with shared ends: q holds 3*nseg + 1
 * points (6*nseg + 2 doubles); segment s uses q_{3s}..q_{3s+3}. It is G1 at
 * the joins when q_{3s-1}, q_{3s}, q_{3s+1} are collinear in this order, and
 * C1 (in the global parameter) when q_{3s} is their midpoint. Global parameter
 * t in [0, nseg]: segment s = floor(t) (clamped to [0, nseg-1]), local t - s.
 * xy: 2n, dxy: 2n or NULL. Errors as el_blend_eval.
 */
int el_blend_composite_eval(const el_blend_basis *b, size_t nseg, const double *q,
                            size_t n, const double *t, double *xy, double *dxy);

/*
 * C1 composite through npts >= 2 points (pts: 2*npts): node i at t = i,
 * tangents T_i = (P_{i+1} - P_{i-1})/2 inside, (-3P_0 + 4P_1 - P_2)/2 and its
 * mirror at the ends (P_1 - P_0 when npts = 2), inner control points
 * q_{3i+-1} = P_i +- T_i/d. q: 3*(npts-1) + 1 points (6*npts - 4 doubles).
 * Errors: EL_EINVAL, EL_EDOM (a coordinate beyond 1e300, checked first; or a
 * control point beyond double's range for a tiny d, q then written).
 */
int el_blend_composite_through(const el_blend_basis *b, size_t npts, const double *pts,
                               double *q);

/*
 * The closed C1 composite through npts >= 3 points (pts: 2*npts, the first not
 * repeated at the end): npts segments, the last from P_{npts-1} back to P_0,
 * node i at t = i, every tangent T_i = (P_{i+1} - P_{i-1})/2 with the indices
 * taken cyclically, so the seam at P_0 is a joint like the others (C1; the
 * open composite's one-sided end tangents leave a corner there). q: 3*npts + 1
 * points (6*npts + 2 doubles), q_{3 npts} = P_0. Errors as
 * el_blend_composite_through (EL_EINVAL also for npts < 3).
 */
int el_blend_composite_closed(const el_blend_basis *b, size_t npts, const double *pts, double *q);

/*
 * Clamped cubic B-spline approximating the composite curve (nseg >= 1, q as in
 * el_blend_composite_eval; nseg = 1 is one segment) in the same parameter
 * t in [0, nseg]. Each segment is fitted on its own: uniform knots inside it,
 * its end points and end derivatives interpolated (so the spline is G1/C1
 * wherever the curve is), inner poles by GSL linear least squares on dense
 * samples; its number of spans grows (1, 2, 3, 4, 6, 8, ... 256) until the
 * certified deviation max_t |phi(t) - B(t)| (dense sampling, then Brent
 * maximisation around every sampled local maximum) is <= tol. Segments are
 * joined with triple knots. out->max_deviation is the largest segment figure.
 * The caller frees out with el_bspline_free (also after EL_ENOCONV).
 * Bounded work: nseg <= 100000 (more: EL_EINVAL), at most 15 fits of <= 256
 * spans per segment.
 * Errors: EL_EINVAL (NULL, NaN/inf, tol <= 0, nseg outside 1..100000),
 * EL_ENOMEM, EL_EDOM (tol < 64 eps lebesgue max|q|, below what the coordinates
 * resolve, refused at once; control points near DBL_MAX: a deviation or a pole
 * beyond double's range), EL_EINTERNAL (GSL), EL_ENOCONV (tol not reached with 256
 * spans in some segment: the best spline is returned in out). out is untouched
 * on the errors other than EL_ENOCONV.
 */
int el_blend_to_bspline(const el_blend_basis *b, size_t nseg, const double *q, double tol,
                        el_bspline *out);

#ifdef __cplusplus
}
#endif

#endif /* ELASTICA_H */
