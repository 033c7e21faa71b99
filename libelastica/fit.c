/*
 * Least-squares fairing, seed 000 (4.6)-(4.8), through Ipopt's C interface.
 *
 *   minimise L(p) = (1/2N) sum_i |gamma_i(p) - P_i|^2        ((4.8) divided by N)
 *
 * over the free parameters, in normalised coordinates (centroid at the origin,
 * rms radius 1) so that the tolerances mean the same at every scale. Gradient
 * (4.9) = J^T r / N with J from el_discrete_jacobian ((4.10)-(4.12)) or
 * el_smooth_jacobian; eval_h returns the Gauss-Newton Hessian J^T J / N (lower
 * triangle, dense), or Ipopt's L-BFGS approximation when asked (the paper's
 * setting, kept for the benchmark). There are no constraints (m = 0) but Ipopt
 * 3.11 wants every callback, so eval_g / eval_jac_g are trivial.
 * The discrete h and z are O(1/N): the optimiser sees (N-1) h and (N-1) z.
 * Further variable changes (shape variables near circles, k and sqrt(mu)
 * continued through 0) are described at v_to_p() and canonical().
 * Each solve starts with plain Gauss-Newton steps (gauss_newton(), same
 * objective, no bounds), so Ipopt mostly just certifies the solution: its
 * per-iteration cost (a MUMPS factorisation) dominates small fits.
 * Several initial guesses (guess.c) may be fitted, in the order of their
 * initial rms; the next is tried only while the best rms is above both the
 * exact level and 1.5 x the noise level estimated from second differences.
 * There are no bounds unless the caller sets some: near a zero-residual
 * solution the objective is far below any barrier term, which would then
 * decide the solution; outside the model's domain the evaluation fails and
 * Ipopt shortens the step.
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <IpStdCInterface.h>
#include <gsl/gsl_sf_ellint.h>
#include <gsl/gsl_statistics_double.h>
#include <gsl/gsl_linalg.h>

enum { NP = 7, MAXCAND = 6 };


void el_fit_options_defaults(el_fit_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    for (int j = 0; j < NP; j++) { opt->lower[j] = -HUGE_VAL; opt->upper[j] = HUGE_VAL; }
    opt->tol = 1e-12;
    opt->max_iter = 200;
    opt->limited_memory = 0;
    opt->max_candidates = 3;
    opt->param_mode = EL_PARAM_AUTO;
    opt->use_initial = 0;
}

/* ------------------------------------------------------------ problem data */

typedef struct fitctx {
    int model;                 /* 0 discrete, 1 smooth */
    size_t n;
    const double *P;           /* normalised points, 2n */
    const double *t;           /* smooth: fractions t_i */
    double *s;                 /* smooth: s_i = t_i length (n) */
    double *xy, *jac;          /* 2n, 2n*7 */
    double xkey[NP], jkey[NP]; /* x at which xy / jac are valid */
    int have_xy, have_jac;
    int nfree, idx[NP];
    double vs[NP];             /* variable scaling: v_j = p_j * vs[j] */
    double full[NP];           /* current parameters (normalised) */
    int transform;             /* optimise in the shape variables (below) */
    int ik, iz, iq, imu;       /* columns of k, z, q, mu (-1: absent) */
    double v[NP];              /* current variables (before the vs scaling) */
    double dk, dz, dq, dmu, gi, gi2;  /* derivatives of the transform at v */
    double best_f, best_p[NP];
    int iters;
    int f_no_grad;             /* the last objective point has not had its gradient asked for */
    int have_gh;               /* g, H below valid for the Jacobian at jkey */
    double g[NP], H[NP][NP];   /* gradient J^T r / N and J^T J / N in the optimiser's x */
} fitctx;

/*
 * Shape variables. Near a circle (|k| >> 1) the curve depends on k only through
 * 1/k^2 and on z, q (mu) through k z, k q (k^2 mu): the argument of
 * am(k u; 1/k). In (k, z, q) the valley of the objective is curved and
 * Gauss-Newton steps overshoot, so the optimiser sees instead
 *   f with k = f / sqrt(2 - |f|)   (f in (-2, 2): f ~ k near 0, 2 - |f| ~ 4/k^2
 *                                   near |k| = oo, |f| = 1 at |k| = 1; odd, C^1
 *                                   at 0, smooth elsewhere),
 *   z g, q g, mu g^2 with g = sqrt(1 + k^2).
 * Used when k, q and z (mu) are all free and unbounded. The smooth model
 * takes every real k (the sign is the orientation), the discrete model
 * k > -1 (below, model_eval).
 */
static double k_of_f(double f) { return f / sqrt(2.0 - fabs(f)); }
static double f_of_k(double k)
{
    const double a = fabs(k);
    return copysign(0.5 * (a * sqrt(a * a + 8.0) - a * a), k);
}

static void v_to_p(fitctx *c, const double *v, double *p)
{
    memcpy(p, v, sizeof(double) * NP);
    if (!c->transform) return;
    const double f = v[c->ik], af = fabs(f);
    const double k = k_of_f(f), g2 = 1.0 + k * k, g = sqrt(g2);
    const double dk = (4.0 - af) / (2.0 * (2.0 - af) * sqrt(2.0 - af));   /* even in f */
    p[c->ik] = k;
    p[c->iq] = v[c->iq] / g;
    c->dk = dk;
    c->gi = 1.0 / g;
    c->dq = -p[c->iq] * (k / g2) * dk;
    if (c->iz >= 0) { p[c->iz] = v[c->iz] / g; c->dz = -p[c->iz] * (k / g2) * dk; }
    if (c->imu >= 0) { p[c->imu] = v[c->imu] / g2; c->gi2 = 1.0 / g2; c->dmu = -2.0 * p[c->imu] * (k / g2) * dk; }
}

static void p_to_v(const fitctx *c, const double *p, double *v)
{
    memcpy(v, p, sizeof(double) * NP);
    if (!c->transform) return;
    const double k = p[c->ik], g2 = 1.0 + k * k, g = sqrt(g2);
    v[c->ik] = f_of_k(k);
    v[c->iq] = p[c->iq] * g;
    if (c->iz >= 0) v[c->iz] = p[c->iz] * g;
    if (c->imu >= 0) v[c->imu] = p[c->imu] * g2;
}

/* d gamma / d v from d gamma / d p, in place (chain rule through v_to_p). */
static void jac_to_v(const fitctx *c)
{
    if (!c->transform) return;
    for (size_t i = 0; i < 2 * c->n; i++) {
        double *r = c->jac + i * NP;
        double colk = r[c->ik] * c->dk + r[c->iq] * c->dq;
        r[c->iq] *= c->gi;
        if (c->iz >= 0) { colk += r[c->iz] * c->dz; r[c->iz] *= c->gi; }
        if (c->imu >= 0) { colk += r[c->imu] * c->dmu; r[c->imu] *= c->gi2; }
        r[c->ik] = colk;
    }
}

static void unpack(fitctx *c, const double *x)
{
    for (int j = 0; j < c->nfree; j++) c->v[c->idx[j]] = x[j] / c->vs[c->idx[j]];
    v_to_p(c, c->v, c->full);
}

static void as_discrete(const double *v, el_discrete_params *p)
{
    p->x0 = v[0]; p->y0 = v[1]; p->h = v[2]; p->phi = v[3]; p->z = v[4]; p->q = v[5]; p->k = v[6];
}

static void from_discrete(const el_discrete_params *p, double *v)
{
    v[0] = p->x0; v[1] = p->y0; v[2] = p->h; v[3] = p->phi; v[4] = p->z; v[5] = p->q; v[6] = p->k;
}

static void as_smooth(const double *v, el_smooth_params *p)
{
    p->x0 = v[0]; p->y0 = v[1]; p->phi = v[2]; p->mu = v[3]; p->k = v[4]; p->q = v[5]; p->length = v[6];
}

static void from_smooth(const el_smooth_params *p, double *v)
{
    v[0] = p->x0; v[1] = p->y0; v[2] = p->phi; v[3] = p->mu; v[4] = p->k; v[5] = p->q; v[6] = p->length;
}

/* K'(k) for 0 <= k < 1 (times 2), and 2K(k). */
static int twoK(double k, double *K2, double *dK2)
{
    if (!(k >= 0.0 && k < 1.0)) return EL_EDOM;
    gsl_sf_result K, E;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) || gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &E))
        return EL_EDOM;
    *K2 = 2.0 * K.val;
    /* dK/dk = (E - (1 - k^2) K) / (k (1 - k^2)) = pi k / 4 + O(k^3) */
    *dK2 = 2.0 * (k < 1e-4 ? M_PI * k / 4.0 : (E.val - (1.0 - k * k) * K.val) / (k * (1.0 - k * k)));
    return EL_OK;
}

/*
 * Internal parameters (normalised): the model's, except that the smooth
 * model carries w = sqrt(mu) in slot 3, and k (and w) may be negative:
 *  smooth: every real k is the model's own (the sign of k is the orientation:
 *      clockwise loops are k < -1); w < 0 (u decreasing) is the same curve as
 *      (|w|, -k, -q): sn(-u) = -sn u, dn(-u) = dn u, so k sn u is unchanged
 *      ((S) below);
 *  discrete: k >= 0 is the model's (z < 0 covers both senses of turning);
 *      -1 < k < 0 is the analytic continuation through the straight line
 *      k = 0, sin a = k sn(u; |k|), cos a = dn(u; |k|), which is the curve with
 *      |k| and q + 2K(|k|) (sn(u + 2K) = -sn u, dn(u + 2K) = dn u) ((A) below);
 *      k <= -1 is outside the domain.
 * So a Gauss-Newton step may cross k = 0 or mu = 0 (nearly straight data)
 * instead of stalling at a bound; results are mapped back by canonical().
 */

/* (S): w < 0 -> (|w|, -k, -q), smooth only. */
static void flip_w(double *v)
{
    v[3] = -v[3]; v[4] = -v[4]; v[5] = -v[5];
}

/*
 * The parameters handed out: smooth w < 0 flipped by (S); then, when allowed
 * (may_shift: k and q free and the shifted values within the caller's bounds,
 * see fit_run), -1 < k < 0 as the same curve with |k| and q + 2K(|k|) (A), so
 * inflectional results have k >= 0 as before; |k| > 1 keeps its sign.
 */
static int canonical(int model, double *v, int may_shift)
{
    const int ik = model == 0 ? 6 : 4;
    double K2, dK2;
    if (model == 1 && v[3] < 0.0) flip_w(v);
    if (v[ik] < 0.0 && v[ik] > -1.0 && (may_shift || model == 0)) {      /* (A) */
        if (twoK(-v[ik], &K2, &dK2)) return EL_EDOM;
        v[ik] = -v[ik];
        v[5] += K2;
    }
    return model == 0 && v[ik] < 0.0 ? EL_EDOM : EL_OK;
}

/* Points (and Jacobian when jac) at the internal parameter vector v0. */
static int model_eval(fitctx *c, const double *v0, int want_jac)
{
    double v[NP], KA = 0.0, dKA = 0.0;
    memcpy(v, v0, sizeof v);
    const int ik = c->model == 0 ? 6 : 4;
    const int negk = c->model == 0 && v[ik] < 0.0, negw = c->model == 1 && v[3] < 0.0;
    int st;
    if (negk) {
        if ((st = twoK(-v[ik], &KA, &dKA))) return st;
        v[ik] = -v[ik];
        v[5] += KA;
    }
    if (negw) flip_w(v);
    if (c->model == 0) {
        el_discrete_params p;
        as_discrete(v, &p);
        st = want_jac ? el_discrete_jacobian(&p, c->n, c->xy, c->jac)
                      : el_discrete_eval(&p, c->n, c->xy);
    } else {
        el_smooth_params p;
        as_smooth(v, &p);
        p.mu = v[3] * v[3];
        if (!(p.mu > 0.0)) return EL_EDOM;
        for (size_t i = 0; i < c->n; i++) c->s[i] = c->t[i] * p.length;
        st = want_jac ? el_smooth_jacobian(&p, c->n, c->s, c->xy, c->jac)
                      : el_smooth_eval(&p, c->n, c->s, c->xy, NULL, NULL);
    }
    if (st || !want_jac) return st;
    for (size_t i = 0; i < 2 * c->n; i++) {
        double *r = c->jac + i * NP;
        if (c->model == 1) {
            r[3] *= 2.0 * v[3];                         /* d/dw = 2 w d/dmu */
            if (negw) { r[3] = -r[3]; r[4] = -r[4]; r[5] = -r[5]; }   /* undo (S) */
        }
        if (negk) r[ik] = -(r[ik] + dKA * r[5]);        /* undo (A) */
    }
    return EL_OK;
}

static int ensure(fitctx *c, const double *x, int want_jac)
{
    unpack(c, x);
    size_t sz = sizeof(double) * (size_t)c->nfree;
    if (want_jac) {
        if (c->have_jac && !memcmp(c->jkey, x, sz)) return EL_OK;
    } else if ((c->have_xy && !memcmp(c->xkey, x, sz)) || (c->have_jac && !memcmp(c->jkey, x, sz))) {
        return EL_OK;
    }
    c->have_xy = c->have_jac = c->have_gh = 0;
    int st = model_eval(c, c->full, want_jac);
    if (st || el__all_finite(c->xy, 2 * c->n)) return st ? st : EL_EDOM;
    if (want_jac) {
        if (el__all_finite(c->jac, 2 * c->n * NP)) return EL_EDOM;
        jac_to_v(c);
        memcpy(c->jkey, x, sz);
        c->have_jac = 1;
    }
    memcpy(c->xkey, x, sz);
    c->have_xy = 1;
    return EL_OK;
}

static double objective(const fitctx *c)
{
    double f = 0.0;
    for (size_t i = 0; i < 2 * c->n; i++) {
        double r = c->xy[i] - c->P[i];
        f += r * r;
    }
    return 0.5 * f / (double)c->n;
}

/* Gradient J^T r / N and Gauss-Newton matrix J^T J / N (lower triangle) in
 * the optimiser's variables x_j = v_idx[j] vs[idx[j]], one pass over the
 * Jacobian that ensure(c, x, 1) left; cached until the next evaluation. */
static void normal_eq(fitctx *c)
{
    if (c->have_gh) return;
    const int nf = c->nfree;
    double g[NP] = {0}, H[NP][NP] = {{0}}, row[NP];
    for (size_t i = 0; i < 2 * c->n; i++) {
        const double *r = c->jac + i * NP, res = c->xy[i] - c->P[i];
        for (int a = 0; a < nf; a++) row[a] = r[c->idx[a]];
        for (int a = 0; a < nf; a++) {
            g[a] += res * row[a];
            for (int b = 0; b <= a; b++) H[a][b] += row[a] * row[b];
        }
    }
    for (int a = 0; a < nf; a++) {
        const double sa = 1.0 / c->vs[c->idx[a]];
        c->g[a] = g[a] * sa / (double)c->n;
        for (int b = 0; b <= a; b++) c->H[a][b] = H[a][b] * sa / (c->vs[c->idx[b]] * (double)c->n);
    }
    c->have_gh = 1;
}

static Bool cb_f(Index n, Number *x, Bool new_x, Number *obj, UserDataPtr ud)
{
    (void)n; (void)new_x;
    fitctx *c = ud;
    /* the Jacobian costs about one evaluation more and Ipopt asks for the
     * gradient at the same point next when it accepts the point (full
     * Gauss-Newton steps, the rule); after a rejected trial point (the line
     * search backtracks) the next trial is likely rejected too: values only */
    const int want_jac = !c->f_no_grad;
    c->f_no_grad = 1;
    if (ensure(c, x, want_jac)) return FALSE;
    double f = objective(c);
    if (!isfinite(f)) return FALSE;
    if (f < c->best_f) { c->best_f = f; memcpy(c->best_p, c->full, sizeof c->best_p); }
    *obj = f;
    return TRUE;
}

static Bool cb_grad(Index n, Number *x, Bool new_x, Number *g, UserDataPtr ud)
{
    (void)n; (void)new_x;
    fitctx *c = ud;
    c->f_no_grad = 0;
    if (ensure(c, x, 1)) return FALSE;
    normal_eq(c);
    memcpy(g, c->g, sizeof(double) * (size_t)c->nfree);
    return TRUE;
}

static Bool cb_g(Index n, Number *x, Bool new_x, Index m, Number *g, UserDataPtr ud)
{
    (void)n; (void)x; (void)new_x; (void)m; (void)g; (void)ud;
    return TRUE;
}

static Bool cb_jac_g(Index n, Number *x, Bool new_x, Index m, Index nele, Index *iRow, Index *jCol,
                     Number *values, UserDataPtr ud)
{
    (void)n; (void)x; (void)new_x; (void)m; (void)nele; (void)iRow; (void)jCol; (void)values; (void)ud;
    return TRUE;
}

/* Gauss-Newton Hessian J^T J / N, lower triangle row by row. (An adaptive
 * Levenberg-Marquardt damping driven from cb_iter was tried: it led noisy,
 * nearly straight fits into regions where they stalled, 2-3x more iterations.) */
static Bool cb_h(Index n, Number *x, Bool new_x, Number obj_factor, Index m, Number *lambda,
                 Bool new_lambda, Index nele, Index *iRow, Index *jCol, Number *values,
                 UserDataPtr ud)
{
    (void)new_x; (void)m; (void)lambda; (void)new_lambda; (void)nele;
    fitctx *c = ud;
    if (!values) {
        Index e = 0;
        for (Index r = 0; r < n; r++)
            for (Index q = 0; q <= r; q++) { iRow[e] = r; jCol[e] = q; e++; }
        return TRUE;
    }
    if (ensure(c, x, 1)) return FALSE;
    normal_eq(c);
    Index e = 0;
    for (int a = 0; a < c->nfree; a++)
        for (int b = 0; b <= a; b++) values[e++] = obj_factor * c->H[a][b];
    return TRUE;
}

static Bool cb_iter(Index alg_mod, Index iter, Number obj, Number inf_pr, Number inf_du, Number mu,
                    Number d_norm, Number reg, Number alpha_du, Number alpha_pr, Index ls,
                    UserDataPtr ud)
{
    (void)alg_mod; (void)obj; (void)inf_pr; (void)inf_du; (void)mu; (void)d_norm; (void)reg;
    (void)alpha_du; (void)alpha_pr; (void)ls;
    fitctx *c = ud;
    c->iters = iter;
    return TRUE;
}

/* ------------------------------------------------------------ one solve */

/* Debian's MUMPS (dmumps_seq, Ipopt's only linear solver here) keeps Fortran
 * module state and crashes when two solves run at once (checked: 4 threads
 * abort in DMUMPS_LOAD_INIT). The one piece of process-wide state in the
 * library is therefore this lock: concurrent fits are safe, their Ipopt
 * solves run one at a time. */
static pthread_mutex_t ipopt_lock = PTHREAD_MUTEX_INITIALIZER;

typedef struct solve_out {
    double p[NP];
    double f;
    int iters, ipopt_status;
} solve_out;

/*
 * Gauss-Newton steps before Ipopt, on the same objective and variables:
 * H d = -g (H = J^T J / N, g = J^T r / N) by GSL's Cholesky decomposition
 * (a tiny ridge when H is singular), then a backtracking line search along d
 * (halving, Armijo), as Ipopt's own iteration does without bounds. Why by
 * hand: each Ipopt iteration costs a MUMPS factorisation whose fixed cost
 * (~0.1-0.3 ms) is far above this <= 7 x 7 solve; from a good guess a
 * zero-residual fit converges here in a few steps and Ipopt then only
 * certifies the point (its convergence test, usually at iteration 0), noisy
 * fits arrive near the stall Ipopt detects. Unbounded problems only (bounds
 * are Ipopt's business). Returns the steps taken; x is updated in place.
 */
static int gauss_newton(fitctx *c, double *x, int max_steps)
{
    const int nf = c->nfree;
    if (ensure(c, x, 1)) return 0;
    double f = objective(c);
    if (!isfinite(f)) return 0;
    if (f < c->best_f) { c->best_f = f; memcpy(c->best_p, c->full, sizeof c->best_p); }
    int steps = 0;
    while (steps < max_steps && f > 0.0) {
        normal_eq(c);
        double A[NP * NP], d[NP], xt[NP], ridge = 1e-14, slope = 0.0;
        int ok = 0;
        for (int attempt = 0; attempt < 6 && !ok; attempt++, ridge *= 1e3) {
            for (int a = 0; a < nf; a++) {
                for (int q = 0; q <= a; q++) A[a * nf + q] = A[q * nf + a] = c->H[a][q];
                A[a * nf + a] += ridge * (c->H[a][a] + 1e-300);
                d[a] = -c->g[a];
            }
            gsl_matrix_view Am = gsl_matrix_view_array(A, (size_t)nf, (size_t)nf);
            gsl_vector_view dv = gsl_vector_view_array(d, (size_t)nf);
            ok = !gsl_linalg_cholesky_decomp1(&Am.matrix) &&
                 !gsl_linalg_cholesky_svx(&Am.matrix, &dv.vector);
        }
        if (!ok) break;
        double dmax = 0.0, xmax = 0.0;
        for (int a = 0; a < nf; a++) {
            slope += c->g[a] * d[a];
            dmax = fmax(dmax, fabs(d[a]));
            xmax = fmax(xmax, fabs(x[a]));
        }
        if (!isfinite(dmax) || !(slope < 0.0)) break;
        steps++;
        double alpha = 1.0, ft = HUGE_VAL;
        for (int ls = 0; ls < 30; ls++, alpha *= 0.5) {
            for (int a = 0; a < nf; a++) xt[a] = x[a] + alpha * d[a];
            /* the full step is usually taken: evaluate its Jacobian at once */
            ft = ensure(c, xt, ls == 0) == EL_OK ? objective(c) : HUGE_VAL;
            if (ft <= f + 1e-4 * alpha * slope) break;       /* Armijo */
        }
        if (!(ft < f)) { ensure(c, x, 1); break; }        /* no progress: Ipopt's turn */
        memcpy(x, xt, sizeof(double) * (size_t)nf);
        if (ensure(c, x, 1)) break;
        if (ft < c->best_f) { c->best_f = ft; memcpy(c->best_p, c->full, sizeof c->best_p); }
        const double rel = (f - ft) / f;
        f = ft;
        /* converged (a full step at rounding level) or stalling on noisy data */
        if ((alpha == 1.0 && dmax <= 1e-12 * (1.0 + xmax)) || rel < 1e-12) break;
    }
    return steps;
}

/* lo/hi: normalised bounds of all 7 parameters; p0 the normalised start. */
static int solve(fitctx *c, const el_fit_options *o, const double *lo, const double *hi,
                 const double *p0, solve_out *out)
{
    double xL[NP], xU[NP], x[NP], v0[NP];
    p_to_v(c, p0, v0);
    for (int j = 0; j < c->nfree; j++) {
        int col = c->idx[j];
        double v = fmin(fmax(v0[col], lo[col]), hi[col]);
        xL[j] = isfinite(lo[col]) ? lo[col] * c->vs[col] : -1e20;
        xU[j] = isfinite(hi[col]) ? hi[col] * c->vs[col] : 1e20;
        x[j] = v * c->vs[col];
    }
    memcpy(c->v, v0, sizeof c->v);
    memcpy(c->full, p0, sizeof c->full);
    c->have_xy = c->have_jac = 0;
    c->best_f = HUGE_VAL;
    c->iters = 0;
    c->f_no_grad = 0;
    int nf = c->nfree, bounded = 0;
    for (int j = 0; j < nf; j++) bounded |= xL[j] > -1e20 || xU[j] < 1e20;
    const int pre = bounded || o->limited_memory ? 0 : gauss_newton(c, x, o->max_iter < 20 ? o->max_iter : 20);
    if (pthread_mutex_lock(&ipopt_lock)) return EL_EINTERNAL;
    IpoptProblem pr = CreateIpoptProblem(nf, xL, xU, 0, NULL, NULL, 0, nf * (nf + 1) / 2, 0,
                                         cb_f, cb_g, cb_grad, cb_jac_g, cb_h);
    if (!pr) { pthread_mutex_unlock(&ipopt_lock); return EL_EINTERNAL; }
    int ok = AddIpoptIntOption(pr, "print_level", 0)
          && AddIpoptStrOption(pr, "sb", "yes")
          && AddIpoptNumOption(pr, "tol", o->tol)
          && AddIpoptIntOption(pr, "max_iter", o->max_iter - pre)
          && AddIpoptNumOption(pr, "bound_relax_factor", 0.0)
          && AddIpoptStrOption(pr, "mu_strategy", "monotone")
          && AddIpoptNumOption(pr, "mu_init", 1e-9)
          /* each MUMPS call has a fixed cost far above the solve of this tiny
           * system: no second-order corrections (there are no constraints to
           * correct) and iterative refinement only when the residual asks */
          && AddIpoptIntOption(pr, "max_soc", 0)
          && AddIpoptIntOption(pr, "min_refinement_steps", 0)
          /* noisy data: Gauss-Newton converges linearly on a non-zero residual;
           * stop once the objective stalls (relative change < 1e-10 twice).
           * Zero-residual fits converge quadratically and never stall first. */
          && (o->limited_memory  /* L-BFGS: Ipopt's defaults, the paper's setting */
              || (AddIpoptNumOption(pr, "acceptable_tol", 1e-3)
                  && AddIpoptNumOption(pr, "acceptable_obj_change_tol", 1e-10)
                  && AddIpoptIntOption(pr, "acceptable_iter", 2)))
          && AddIpoptStrOption(pr, "hessian_approximation",
                               o->limited_memory ? "limited-memory" : "exact")
          && SetIntermediateCallback(pr, cb_iter);
    enum ApplicationReturnStatus rs = Internal_Error;
    double obj = HUGE_VAL;
    if (ok) rs = IpoptSolve(pr, x, NULL, &obj, NULL, NULL, NULL, c);
    FreeIpoptProblem(pr);
    pthread_mutex_unlock(&ipopt_lock);
    if (!ok) return EL_EINTERNAL;
    out->ipopt_status = (int)rs;
    out->iters = c->iters + pre;
    /* the final point, unless a better one was seen */
    double fin[NP], vf[NP];
    memcpy(vf, v0, sizeof vf);
    for (int j = 0; j < nf; j++) vf[c->idx[j]] = x[j] / c->vs[c->idx[j]];
    v_to_p(c, vf, fin);
    double ffin = HUGE_VAL;
    if (el__all_finite(fin, NP) == EL_OK && model_eval(c, fin, 0) == EL_OK &&
        el__all_finite(c->xy, 2 * c->n) == EL_OK)
        ffin = objective(c);
    if (ffin <= c->best_f) { memcpy(out->p, fin, sizeof fin); out->f = ffin; }
    else { memcpy(out->p, c->best_p, sizeof fin); out->f = c->best_f; }
    if (!isfinite(out->f)) { memcpy(out->p, p0, sizeof fin); out->f = HUGE_VAL; }
    return EL_OK;
}

static int ipopt_to_status(int rs)
{
    switch (rs) {
    case Solve_Succeeded: case Solved_To_Acceptable_Level: return EL_OK;
    case Maximum_Iterations_Exceeded: case Maximum_CpuTime_Exceeded: return EL_EMAXITER;
    case Insufficient_Memory: return EL_ENOMEM;
    case Invalid_Option: case Invalid_Problem_Definition: case Internal_Error:
    case NonIpopt_Exception_Thrown: case Unrecoverable_Exception: return EL_EINTERNAL;
    default: return EL_ENOCONV;
    }
}

/* ------------------------------------------------------------ driver */

/* Noise level of the points (rms per point) from second differences:
 * |P_{i+1} - 2P_i + P_{i-1}|^2 has mean 12 sigma^2 = 6 rms^2, median ln 2 of the mean. */
static double noise_rms(const double *P, size_t n)
{
    size_t m = n - 2;
    double *d = malloc(sizeof(double) * m);
    if (!d) return 0.0;
    for (size_t i = 1; i + 1 < n; i++) {
        double dx = P[2 * i + 2] - 2 * P[2 * i] + P[2 * i - 2];
        double dy = P[2 * i + 3] - 2 * P[2 * i + 1] + P[2 * i - 1];
        d[i - 1] = dx * dx + dy * dy;
    }
    double med = gsl_stats_median(d, 1, m);   /* quickselect; reorders d */
    free(d);
    return sqrt(med / (6.0 * 0.69314718055994531));
}

/* Model bounds (normalised) the evaluation needs. */
static void model_bounds(int model, double *lo, double *hi)
{
    for (int j = 0; j < NP; j++) { lo[j] = -HUGE_VAL; hi[j] = HUGE_VAL; }
    (void)model;   /* none: see the file comment */
}

/* Normalise a parameter value j (input units -> normalised). */
static double norm_param(int model, int j, double v, double cx, double cy, double sc)
{
    if (j == 0) return (v - cx) / sc;
    if (j == 1) return (v - cy) / sc;
    if (model == 0 && j == 2) return v / sc;       /* h */
    if (model == 1 && j == 3) return v >= 0.0 ? sqrt(v) * sc : NAN;  /* mu -> w = sqrt(mu) */
    if (model == 1 && j == 6) return v / sc;       /* length */
    return v;
}

static double denorm_param(int model, int j, double v, double cx, double cy, double sc)
{
    if (j == 0) return cx + sc * v;
    if (j == 1) return cy + sc * v;
    if (model == 0 && j == 2) return v * sc;
    if (model == 1 && j == 3) return (v / sc) * (v / sc);
    if (model == 1 && j == 6) return v * sc;
    return v;
}

typedef struct fit_out {
    double params[NP], initial[NP];
    double rms, max_error;
    int iterations, candidates, ipopt_status, status, mode;
} fit_out;

static int check_options(const el_fit_options *o)
{
    if (!(o->tol > 0.0) || !isfinite(o->tol) || o->max_iter < 1 || o->max_candidates < 1)
        return EL_EINVAL;
    if (o->param_mode < EL_PARAM_AUTO || o->param_mode > EL_PARAM_CHORD) return EL_EINVAL;
    for (int j = 0; j < NP; j++) {
        if (isnan(o->lower[j]) || isnan(o->upper[j]) || o->lower[j] > o->upper[j]) return EL_EINVAL;
        if (o->fixed[j] && !isfinite(o->value[j])) return EL_EINVAL;
    }
    return EL_OK;
}

static int fit_run(int model, const double *xy, size_t n, const el_fit_options *opt,
                   const double *init, fit_out *res)
{
    el_fit_options o;
    if (opt) o = *opt; else el_fit_options_defaults(&o);
    if (!xy || n < 4 || !res || el__all_finite(xy, 2 * n) || check_options(&o)) return EL_EINVAL;
    if (o.use_initial && (!init || el__all_finite(init, NP))) return EL_EINVAL;
    el__gsl_quiet();

    /* normalisation: centroid and rms radius, guarded against overflow */
    double cx = 0.0, cy = 0.0, amax = 0.0, r2 = 0.0;
    for (size_t i = 0; i < n; i++) { cx += xy[2 * i] / (double)n; cy += xy[2 * i + 1] / (double)n; }
    for (size_t i = 0; i < n; i++)
        amax = fmax(amax, fmax(fabs(xy[2 * i] - cx), fabs(xy[2 * i + 1] - cy)));
    if (!(amax > 0.0) || !isfinite(amax)) return EL_ESINGULAR;
    for (size_t i = 0; i < n; i++) {
        double dx = (xy[2 * i] - cx) / amax, dy = (xy[2 * i + 1] - cy) / amax;
        r2 += dx * dx + dy * dy;
    }
    const double sc = amax * sqrt(r2 / (double)n);
    if (!(sc > 0.0) || !isfinite(sc)) return EL_ESINGULAR;

    /* normalised bounds: the model's and the caller's */
    double lo[NP], hi[NP];
    model_bounds(model, lo, hi);
    for (int j = 0; j < NP; j++) {
        double a = norm_param(model, j, o.lower[j], cx, cy, sc);
        double b = norm_param(model, j, o.upper[j], cx, cy, sc);
        if (isnan(a)) a = -HUGE_VAL;
        if (isnan(b)) b = HUGE_VAL;
        lo[j] = fmax(lo[j], fmin(a, b));
        hi[j] = fmin(hi[j], fmax(a, b));
        if (o.fixed[j]) {
            double v = norm_param(model, j, o.value[j], cx, cy, sc);
            if (!isfinite(v) || v < lo[j] || v > hi[j]) return EL_EINVAL;
        }
        if (lo[j] > hi[j]) return EL_EINVAL;
    }

    /* discrete k < 0 is used internally by shifting q (canonical()): not when
     * q is fixed; smooth w < 0 flips k and q: not when either is fixed or bounded */
    const int ik = model == 0 ? 6 : 4;
    if (model == 0 && o.fixed[5] && !o.fixed[ik]) lo[ik] = fmax(lo[ik], 0.0);
    if (model == 1 && (o.fixed[ik] || o.fixed[5] || isfinite(lo[ik]) || isfinite(hi[ik]) ||
                       isfinite(lo[5]) || isfinite(hi[5])))
        lo[3] = fmax(lo[3], 0.0);

    int st = EL_ENOMEM;
    double *buf = malloc(sizeof(double) * (n * (2 + 1 + 1 + 2 + 2 * NP)));
    if (!buf) return EL_ENOMEM;
    double *P = buf, *t = P + 2 * n, *s = t + n, *xyb = s + n, *jac = xyb + 2 * n;
    for (size_t i = 0; i < n; i++) {
        P[2 * i] = (xy[2 * i] - cx) / sc;
        P[2 * i + 1] = (xy[2 * i + 1] - cy) / sc;
    }
    int mode = EL_PARAM_UNIFORM;
    if (model == 1 && (st = el_fit_fractions(P, n, o.param_mode, t, &mode))) goto done;

    /* candidates (normalised) */
    double cand[MAXCAND][NP];
    size_t ncand = 0;
    if (o.use_initial) {
        for (int j = 0; j < NP; j++) cand[0][j] = norm_param(model, j, init[j], cx, cy, sc);
        ncand = 1;
    } else if (model == 0) {
        el_discrete_params g[MAXCAND];
        if ((st = el_guess_discrete(P, n, g, MAXCAND, &ncand))) goto done;
        for (size_t c = 0; c < ncand; c++) from_discrete(&g[c], cand[c]);
    } else {
        el_smooth_params g[MAXCAND];
        if ((st = el_guess_smooth(P, n, mode, g, MAXCAND, &ncand))) goto done;
        for (size_t c = 0; c < ncand; c++) { from_smooth(&g[c], cand[c]); cand[c][3] = sqrt(cand[c][3]); }
    }
    if ((size_t)o.max_candidates < ncand) ncand = (size_t)o.max_candidates;

    fitctx c;
    memset(&c, 0, sizeof c);
    c.model = model; c.n = n; c.P = P; c.t = t; c.s = s; c.xy = xyb; c.jac = jac;
    for (int j = 0; j < NP; j++) {
        c.vs[j] = (model == 0 && (j == 2 || j == 4)) ? (double)(n - 1) : 1.0;
        if (!o.fixed[j]) c.idx[c.nfree++] = j;
    }
    c.ik = model == 0 ? 6 : 4; c.iq = 5; c.iz = model == 0 ? 4 : 3; c.imu = -1;
    {
        const int ia = c.ik, ib = c.iq, ic = c.iz;
        c.transform = !o.fixed[ia] && !o.fixed[ib] && !o.fixed[ic];
        for (int j = 0; j < NP; j++)
            if ((j == ia || j == ib || j == ic) && (isfinite(lo[j]) || isfinite(hi[j]))) c.transform = 0;
    }
    const double noise = noise_rms(P, n);
    solve_out best;
    best.f = HUGE_VAL; best.iters = 0; best.ipopt_status = Solve_Succeeded;
    double best_init[NP];
    memcpy(best.p, cand[0], sizeof best.p);
    memcpy(best_init, cand[0], sizeof best_init);
    int iters = 0, tried = 0;
    for (size_t ci = 0; ci < ncand; ci++) {
        double p0[NP];
        memcpy(p0, cand[ci], sizeof p0);
        for (int j = 0; j < NP; j++) {
            if (!o.fixed[j]) continue;
            double v = norm_param(model, j, o.value[j], cx, cy, sc);
            if (model == 0 && j == 2 && !o.fixed[4]) p0[4] *= v / p0[2];   /* keep u(s) */
            p0[j] = v;
        }
        if (c.nfree == 0) {     /* nothing to optimise */
            if (model_eval(&c, p0, 0) == EL_OK) {
                best.f = objective(&c); memcpy(best.p, p0, sizeof p0); memcpy(best_init, p0, sizeof p0);
            }
            break;
        }
        solve_out so;
        if ((st = solve(&c, &o, lo, hi, p0, &so))) goto done;
        tried++;
        iters += so.iters;
        if (so.f < best.f) { best = so; memcpy(best_init, p0, sizeof p0); }
        const double rms = sqrt(2.0 * best.f);
        if (rms <= 1e-10 || (rms <= 1.5 * noise && ipopt_to_status(best.ipopt_status) == EL_OK)) break;
    }
    if (!isfinite(best.f)) { st = EL_ENOCONV; best.f = HUGE_VAL; }

    /* errors in input units */
    double rms = HUGE_VAL, emax = HUGE_VAL;
    if (model_eval(&c, best.p, 0) == EL_OK) {
        double s2 = 0.0, m2 = 0.0;
        for (size_t i = 0; i < n; i++) {
            double dx = xyb[2 * i] - P[2 * i], dy = xyb[2 * i + 1] - P[2 * i + 1];
            double d2 = dx * dx + dy * dy;
            s2 += d2; m2 = fmax(m2, d2);
        }
        rms = sc * sqrt(s2 / (double)n);
        emax = sc * sqrt(m2);
    }
    {   /* smooth -1 < k < 0 as k >= 0 with q + 2K when k, q are free and may move so */
        double shifted[NP];
        memcpy(shifted, best.p, sizeof shifted);
        int may_shift = model == 1 && !o.fixed[ik] && !o.fixed[5] &&
                        canonical(model, shifted, 1) == EL_OK &&
                        shifted[ik] >= lo[ik] && shifted[ik] <= hi[ik] &&
                        shifted[5] >= lo[5] && shifted[5] <= hi[5];
        if (canonical(model, best.p, may_shift)) {  /* cannot happen for points the model evaluated */
            memcpy(best.p, best_init, sizeof best.p);
            best.ipopt_status = Internal_Error;
        }
    }
    for (int j = 0; j < NP; j++) {
        res->params[j] = o.fixed[j] ? o.value[j] : denorm_param(model, j, best.p[j], cx, cy, sc);
        res->initial[j] = o.use_initial ? init[j] : denorm_param(model, j, best_init[j], cx, cy, sc);
        if (!o.use_initial && o.fixed[j]) res->initial[j] = o.value[j];
    }
    res->rms = rms; res->max_error = emax;
    res->iterations = iters; res->candidates = tried;
    res->ipopt_status = best.ipopt_status;
    res->mode = mode;
    st = isfinite(best.f) ? (c.nfree == 0 ? EL_OK : ipopt_to_status(best.ipopt_status)) : EL_ENOCONV;
    /* a zero-residual fit that Ipopt could not certify (its step became tiny) is a fit */
    if (st == EL_ENOCONV && sqrt(2.0 * best.f) <= 1e-10) st = EL_OK;
    if (st == EL_EINTERNAL) st = EL_ENOCONV;
    if (el__all_finite(res->params, NP)) {   /* never hand out NaN */
        for (int j = 0; j < NP; j++) res->params[j] = res->initial[j];
        st = EL_ENOCONV;
    }
    res->status = st;
done:
    free(buf);
    return st;
}

int el_fit_discrete(const double *xy, size_t n, const el_fit_options *opt,
                    const el_discrete_params *initial, el_fit_discrete_result *res)
{
    if (!res) return EL_EINVAL;
    double init[NP];
    if (initial) from_discrete(initial, init);
    fit_out fo;
    fo.status = -1;
    int st = fit_run(0, xy, n, opt, initial ? init : NULL, &fo);
    if (fo.status == -1) return st;    /* failed before a result existed: *res untouched */
    memset(res, 0, sizeof *res);
    as_discrete(fo.params, &res->params);
    as_discrete(fo.initial, &res->initial);
    res->rms = fo.rms; res->max_error = fo.max_error;
    res->iterations = fo.iterations; res->candidates = fo.candidates;
    res->ipopt_status = fo.ipopt_status; res->status = fo.status;
    return fo.status;
}

int el_fit_smooth(const double *xy, size_t n, const el_fit_options *opt,
                  const el_smooth_params *initial, el_fit_smooth_result *res)
{
    if (!res) return EL_EINVAL;
    double init[NP];
    if (initial) from_smooth(initial, init);
    fit_out fo;
    fo.status = -1;
    int st = fit_run(1, xy, n, opt, initial ? init : NULL, &fo);
    if (fo.status == -1) return st;
    memset(res, 0, sizeof *res);
    as_smooth(fo.params, &res->params);
    as_smooth(fo.initial, &res->initial);
    res->rms = fo.rms; res->max_error = fo.max_error;
    res->iterations = fo.iterations; res->candidates = fo.candidates;
    res->ipopt_status = fo.ipopt_status; res->status = fo.status;
    res->param_mode = fo.mode;
    return fo.status;
}
