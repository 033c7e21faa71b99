/*
 * libelastica — Euler's elastica as a CAD tool.
 *
 * One public header, C99. Every fallible function returns an int status
 * (EL_OK = 0) and writes results through pointers; arrays are caller-owned
 * double arrays with explicit counts, points interleaved x0,y0,x1,y1,...
 * Nothing here aborts, prints or keeps global mutable state: every function
 * may be called from several threads at once.
 *
 * Sections follow the files in libelastica/: status, jacobi, smooth,
 * discrete, guess, fit, prep, hermite, affine, bspline, blend.
 *
 * This header is parsed by the Python binding (cffi cdef) after the
 * preprocessor lines are removed: no macros inside declarations.
 */
#ifndef ELASTICA_H
#define ELASTICA_H

#include <stddef.h>

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
    EL_EINTERNAL = 7   /* an internal numerical routine (GSL, Ipopt) failed unexpectedly */
};

/* A static, human-readable message for a status (never NULL). */
const char *el_strerror(int status);

/* Library version as "MAJOR.MINOR.PATCH" (static string). */
const char *el_version(void);

/* ------------------------------------------------------------------ jacobi */

/*
 * Jacobi elliptic functions of argument u and modulus k, for every k >= 0.
 * k > 1 uses the reciprocal-modulus transformation
 *   sn(u,k) = sn(ku,1/k)/k,  cn(u,k) = dn(ku,1/k),  dn(u,k) = cn(ku,1/k);
 * k = 1 gives sn = tanh, cn = dn = sech. GSL (parameter m = k^2 <= 1) inside.
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
 * Errors: EL_EINVAL for NULL val, NaN/inf u or k, k < 0; EL_EINTERNAL if GSL fails.
 * Outputs are untouched on error.
 */
int el_jacobi_eval(double u, double k, el_jacobi *val, el_jacobi *d_du, el_jacobi *d_dk);

/* ------------------------------------------------------------------ smooth */

/*
 * Smooth elastica segment, seed 000 (4.3) with one formula for every k > 0:
 *   u(s) = sqrt(mu) s + q,  sin((theta-phi)/2) = k sn(u;k),  cos((theta-phi)/2) = dn(u;k),
 *   kappa = theta' = 2 k sqrt(mu) cn(u;k),  gamma(0) = (x0, y0),  s in [0, length].
 * k < 1: inflectional (wave-like); k = 1: the separatrix; k > 1: non-inflectional
 * (loops). k = 0 is the straight line. Positions in closed form:
 *   gamma(s) = (x0,y0) + R(phi) ( (2(E(u)-E(q)) - (u-q)) / sqrt(mu),
 *                                 -2k (cn(u) - cn(q)) / sqrt(mu) ).
 * The parameter vector order, used by every Jacobian, is
 *   p = (x0, y0, phi, mu, k, q, length).
 */
typedef struct el_smooth_params {
    double x0, y0;   /* start point gamma(0) */
    double phi;      /* rotation (rad) */
    double mu;       /* > 0: scale, mu = lambda/(2k^2-1) of seed 000 (2.23) */
    double k;        /* >= 0: elliptic modulus, shape */
    double q;        /* phase: u(0) = q */
    double length;   /* >= 0: arc length of the segment */
} el_smooth_params;

enum { EL_SMOOTH_NPARAMS = 7 };

/* EL_OK when every field is finite, mu > 0, k >= 0, length >= 0; else EL_EINVAL. */
int el_smooth_check(const el_smooth_params *p);

/*
 * Evaluate at n arc lengths s[i] (any real values; [0, length] is the segment).
 * Any output pointer may be NULL. xy: 2n (interleaved), theta: n (tangent
 * angle, continuous in s), kappa: n (signed curvature, + = counter-clockwise).
 * Equally spaced s (as in sampling) is detected and evaluated with the
 * addition theorems, about 5x faster; results agree to ~1e-14.
 * Errors: EL_EINVAL (bad params, NULL s with n > 0, non-finite s).
 */
int el_smooth_eval(const el_smooth_params *p, size_t n, const double *s,
                   double *xy, double *theta, double *kappa);

/*
 * Jacobian of the points: jac[(i*2 + c)*7 + j] = d gamma_c(s_i) / d p_j, with
 * p = (x0, y0, phi, mu, k, q, length). The length column is the derivative
 * with the sample held at the same fraction t = s/length of the curve
 * (d/dL gamma(t L) = t T(s)); it is 0 when length = 0. xy may be NULL.
 * Errors as el_smooth_eval.
 */
int el_smooth_jacobian(const el_smooth_params *p, size_t n, const double *s,
                       double *xy, double *jac);

/* Bending energy integral_0^length kappa^2 ds, in closed form. */
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
 * The n >= 2 vertices (xy: 2n, interleaved). Errors: EL_EINVAL.
 */
int el_discrete_eval(const el_discrete_params *p, size_t n, double *xy);

/*
 * Discrete curvature at the n-2 interior vertices,
 * kappa[i] = (2/h) tan(K_{i+1}/2), seed 000 (3.4). n >= 3.
 */
int el_discrete_curvature(const el_discrete_params *p, size_t n, double *kappa);

/*
 * Vertices (xy may be NULL) and their Jacobian,
 * jac[(i*2 + c)*7 + j] = d gamma_{i,c} / d p_j, p = (x0, y0, h, phi, z, q, k),
 * by the recursion (4.10). n >= 2. Errors: EL_EINVAL.
 */
int el_discrete_jacobian(const el_discrete_params *p, size_t n, double *xy, double *jac);

/* ------------------------------------------------------------------- guess */

/* ------------------------------------------------------------------- fit */

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
 * completion, still deterministic).
 * Errors: EL_EINVAL (NULL xyz, n < 3, NaN/inf), EL_ESINGULAR (all points
 * equal), EL_ENOMEM, EL_EINTERNAL (GSL). Outputs untouched on error.
 */
int el_plane_fit(const double *xyz, size_t n, el_frame *frame, double *xy_out,
                 double *rms_out_of_plane);

/*
 * Local coordinates of n points xyz (3n) in frame: xy (2n) = (x', y') and,
 * when z is not NULL, z (n) = z' (signed distance from the plane).
 * Errors: EL_EINVAL (NULL frame/xyz/xy with n > 0, NaN/inf).
 */
int el_frame_project(const el_frame *frame, size_t n, const double *xyz, double *xy,
                     double *z);

/*
 * Inverse map of the plane coordinates: xyz (3n) = p_bar + x' e1 + y' e2 for
 * the n points xy (2n). Errors: EL_EINVAL (NULL, NaN/inf).
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

/*
 * Resample the polyline xy (2n, n >= 2) with segment r > 0 into *out (which
 * the caller then frees with el_resample_free). Consecutive repeated points
 * are allowed (zero-length pieces are skipped).
 * Errors: EL_EINVAL (NULL, n < 2, NaN/inf, r <= 0 or not finite, r larger than
 * the distance from A_1 to every point of the polyline), EL_ESINGULAR (all
 * points equal), EL_ENOMEM. *out is untouched on error.
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
 * xy_out (2n, may be NULL; may equal xy) the coordinates q''_k.
 * Errors: EL_EINVAL (NULL xy, n < 2, NaN/inf), EL_ESINGULAR (all points equal),
 * EL_ENOMEM, EL_EINTERNAL (GSL). Outputs untouched on error.
 */
int el_pca_normalize(const double *xy, size_t n, el_frame2d *frame, double *xy_out);

/* Map n points from the parent (x'y') coordinates to the frame's x''y'' (2n each; in-place allowed). */
int el_frame2d_to_local(const el_frame2d *frame, size_t n, const double *xy, double *xy_local);

/* Inverse: parent coordinates q = q_bar + x'' f1 + y'' f2 (2n each; in-place allowed). */
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
 * last vertex, -1 the first, 0 automatic (the end whose sub-polygon from point 3
 * strays farther to the side of its chord opposite to point 3, i.e. the one
 * that is not a convex arc). "Upper side" of steps (3) is taken relative to
 * each chord oriented by increasing vertex index (the same as the paper's for
 * x-monotone polygons, and rotation invariant); the switch rule of step (3)
 * is also applied to point 4 of step (2) with the side of point 3 relative to
 * chord 1-2 (no change when point 4 lies beyond the inflection, the paper's
 * case; it keeps an inflection near end 2 inside the search interval).
 * Errors: EL_EINVAL (NULL, n < 4, NaN/inf, side not in {-1,0,1}),
 * EL_ESINGULAR (all points equal), EL_EDOM (no inflection: collinear or
 * convex polygon, or coincident end points). *out untouched on error.
 */
int el_find_inflection(const double *xy, size_t n, int side, el_inflection *out);


/* ------------------------------------------------------------------- hermite */

/* ------------------------------------------------------------------- affine */

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

/* Release what the library allocated in b and zero it; NULL is a no-op. */
void el_bspline_free(el_bspline *b);

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
    double cond;       /* 1-norm condition number of the 8x8 system (2.17) */
} el_blend_basis;

/*
 * Fill b for the MQ span with parameter c and end-derivative d (d = 1/alpha(c)
 * gives Eck's Omega_i). Errors: EL_EINVAL (NULL b, NaN/inf, d <= 0),
 * EL_EDOM (c = 0: the span degenerates), EL_ESINGULAR (the system (2.17) is
 * singular to working precision, condition > 1e13). b untouched on error.
 */
int el_blend_init_mq(el_blend_basis *b, double c, double d);

/*
 * Fill b for the elliptic span {1-t, sn((1-t)K,k), sn(Kt,k), t} with modulus
 * k (see the convention above) and end-derivative d > 0.
 * Errors: EL_EINVAL (NULL, NaN/inf, k < 0, d <= 0), EL_EDOM (k >= 1: K is
 * infinite, the basis does not exist), EL_ESINGULAR (K(k) = 2, near k = 0.80241:
 * there the end conditions (2.14) do not determine h_0; detected as
 * condition > 1e13), EL_EINTERNAL (GSL). b untouched on error.
 */
int el_blend_init_elliptic(el_blend_basis *b, double k, double d);

/* Eck's d = 1/alpha(c) = (2c^2 + 1 + c s)/(c s), s = sqrt(c^2+1) (2.5), for |c|.
 * Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (c = 0). */
int el_blend_eck_d(double c, double *d);

/*
 * Eck's MQ blending functions in closed form (2.4)-(2.5), as corrected:
 *   Omega_1 = (s+c)^2 beta/alpha (t + c sqrt(c^2+(1-t)^2) - s sqrt(c^2+t^2)),
 *   Omega_2(t) = Omega_1(1-t),  Omega_3 = t - alpha Omega_1 + (alpha-1) Omega_2,
 *   Omega_0(t) = Omega_3(1-t)   (for |c|; the printed Omega_1 swaps the roots).
 * omega[4*i + j] = Omega_j(t_i). Independent of el_blend_init_mq (a check of it).
 * Errors: EL_EINVAL (NULL, NaN/inf), EL_EDOM (c = 0).
 */
int el_blend_eck_omega(double c, size_t n, const double *t, double *omega);

/* The span functions f_j(t_i) and their t-derivatives: f[4*i + j]; any of
 * f, df, d2f may be NULL. Any finite t (the segment is [0, 1]). Errors: EL_EINVAL. */
int el_blend_span_eval(const el_blend_basis *b, size_t n, const double *t,
                       double *f, double *df, double *d2f);

/* The blending functions h_j(t_i) (2.13) and t-derivatives: h[4*i + j]; any of
 * h, dh, d2h may be NULL. Errors: EL_EINVAL. */
int el_blend_basis_eval(const el_blend_basis *b, size_t n, const double *t,
                        double *h, double *dh, double *d2h);

/* Control points q (4 points, 8 doubles) of the curve sum_j p_j f_j with
 * coefficient points p (8 doubles): q = p M^-1 (2.19). Errors: EL_EINVAL. */
int el_blend_control_points(const el_blend_basis *b, const double *p, double *q);

/* The inverse: coefficient points p = q M (2.18). Errors: EL_EINVAL. */
int el_blend_coefficients(const el_blend_basis *b, const double *q, double *p);

/* Curve points phi(t_i) = sum_j q_j h_j(t_i) (xy: 2n) and derivatives
 * dxy: 2n (may be NULL). Errors: EL_EINVAL (NULL, NaN/inf). */
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
 * consecutive points, or the 4x4 collocation system is singular).
 */
int el_blend_from_points(const el_blend_basis *b, const double *pts, int mode, double *q);

/*
 * Composite curve of nseg >= 1 segments with shared ends: q holds 3*nseg + 1
 * points (6*nseg + 2 doubles); segment s uses q_{3s}..q_{3s+3}. It is G1 at
 * the joins when q_{3s-1}, q_{3s}, q_{3s+1} are collinear in this order, and
 * C1 (in the global parameter) when q_{3s} is their midpoint. Global parameter
 * t in [0, nseg]: segment s = floor(t) (clamped to [0, nseg-1]), local t - s.
 * xy: 2n, dxy: 2n or NULL. Errors: EL_EINVAL.
 */
int el_blend_composite_eval(const el_blend_basis *b, size_t nseg, const double *q,
                            size_t n, const double *t, double *xy, double *dxy);

/*
 * C1 composite through npts >= 2 points (pts: 2*npts): node i at t = i,
 * tangents T_i = (P_{i+1} - P_{i-1})/2 inside, (-3P_0 + 4P_1 - P_2)/2 and its
 * mirror at the ends (P_1 - P_0 when npts = 2), inner control points
 * q_{3i+-1} = P_i +- T_i/d. q: 3*(npts-1) + 1 points (6*npts - 4 doubles).
 * Errors: EL_EINVAL.
 */
int el_blend_composite_through(const el_blend_basis *b, size_t npts, const double *pts,
                               double *q);

/*
 * Clamped cubic B-spline approximating the composite curve (nseg >= 1, q as in
 * el_blend_composite_eval; nseg = 1 is one segment) in the same parameter
 * t in [0, nseg]: uniform knots inside each segment, double knots at the joins,
 * end points and end derivatives interpolated, inner poles by GSL linear least
 * squares on dense samples; the number of spans doubles until the certified
 * deviation max_t |phi(t) - B(t)| (dense sampling, then Brent maximisation
 * around every sampled local maximum) is <= tol. out->max_deviation is that
 * figure. The caller frees out with el_bspline_free.
 * Errors: EL_EINVAL (NULL, NaN/inf, tol <= 0), EL_ENOMEM, EL_ENOCONV (tol not
 * reached with 256 spans per segment: the best spline is returned in out).
 */
int el_blend_to_bspline(const el_blend_basis *b, size_t nseg, const double *q, double tol,
                        el_bspline *out);

#ifdef __cplusplus
}
#endif

#endif /* ELASTICA_H */
