/*
 * Hermite solutions between tangents along the chord (seed 004, case 1 with P1 = V1 = 0 in
 * the normalised frame: p1 ahead on the line of t0, t1 = t0): the separatrix loops.
 *
 * There the two sheets of (17) are kappa0' = 0, kappa1 = kappa0 and kappa0' = -2 kappa0,
 * kappa1 = -kappa0; on the first, |F| - sigma = -kappa0^2 ((8) with F = (0, kappa0^2 - sigma)),
 * so the branch touches the separatrix at kappa0 = 0 ((40) has a multiple root there) and the
 * loops turning once (one period of a k > 1 elastica, from its curvature minimum kappa0 to the
 * next) sit at kappa0 ~ 2 sqrt(2 sigma) exp(-sqrt(sigma / 2) / 2): 7.5e-10 at sigma |p1 - p0|^2
 * = 5000, where |F| - sigma = -5.7e-19 is 1e-22 of sigma. The x chart rounds it to 0, and the
 * separatrix chart is opened only at a crossing of the separatrix that the frame's rounding
 * removes (/tmp/hermloop/NOTES.md, mechanism 1: the library returned the segment alone above
 * sigma |p1 - p0|^2 ~ 600). The loop's mirror image (kappa0 < 0) is not a root of the
 * objective at all on data that are not exactly symmetric (mechanism 2: near the saddle the
 * rounding of its end angle reads as a short arc).
 *
 * On the first sheet a whole period is in closed form (the header's parametrisation, k > 1,
 * m = 1 / k^2, mc = 1 - m = k'^2 of the modulus 1 / k; K, E = K - m D of m): it displaces the
 * start by <F, x(L) - x(0)> / |F| along F ((12), (10): det(x(L) - x(0), F) = 0), which is P =
 * (0, 1) where
 *   E_p - sigma L_p = -|F|,  L_p = 2 K / (k sqrt(mu)),  E_p = 8 k sqrt(mu) E,  |F| = 2 mu,
 *   sigma = 2 mu (2 k^2 - 1),
 * i.e. sqrt(mu) = 2 (2 k^2 - 1) K / k - 4 k E, and kappa0^2 = 4 mu (k^2 - 1) = 4 mu mc / m:
 * one equation in t = ln mc (the separatrix chart's coordinate: |F| - sigma = -kappa0^2) for
 * the given sigma, each root a loop and (kappa0 -> -kappa0) its mirror, built from the closed
 * form (loop_solution), not from the state (whose phase the rounding of theta - phi = pi
 * loses). Where the data are only near P1 = V1 = 0 (|P1|, |V1| <= CHORD_NEAR) each is polished
 * onto them (el__hermite_polish_to) and kept at the data's residual <= tol, still a loop
 * (turning 2 pi, its length within 1e-2) and within one period (the move can take a whole
 * period past it on one side). A loop the roots found too is replaced by this one. Where no
 * piece meets tol by tension (sigma |p1 - p0|^2 ~ 1300 .. 4000: k = 1 + a few ulps, residual
 * ~1e-9) the loop is counted unrepresentable, once, unless the roots returned it (as a chain).
 * By length (hermite_length.c's tracing missed them below ~1.1 |p1 - p0|) the same closed form
 * gives L(t) = 2 K / (k sqrt(mu)), one equation in t for the given length (chord_loops_length,
 * below), each root's loop and mirror kept the same way.
 * By length too, a loop no piece meets to tol (k - 1 below an ulp, the tails e^-(sqrt(mu) L / 2)
 * above tol: sqrt(mu) |p1 - p0| ~ 25 .. 45, L ~ 1.09 .. 1.16 |p1 - p0|) is counted
 * unrepresentable unless the tracer returned it (as a chain).
 * Not covered: the two-loop chains (one period of an inflectional elastica), and on data moved off the chord the
 * loop that slides off centre beyond the polish's reach (p1 or t1 moved by 1e-12 .. 1e-2 by
 * tension, 1e-10 .. 1e-2 by length: one of the pair found in about half of the problems, as before).
 */
#include "hermite_internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_math.h>

/* how far from P1 = V1 = 0 the symmetric problem's loops are tried as starts */
#define CHORD_NEAR 1e-2
/* data on the chord to rounding: |P1|, |V1| up to ~1e-12 where p0 lies 3000 |p1 - p0| from the
 * origin (the rounding of p1 - p0) */
#define CHORD_EXACT 1e-11
/* t = ln mc searched over [T_LO, T_HI]: mc from 1e-300 (sigma |p1 - p0|^2 ~ 1e6) to 0.99; sigma
 * falls with mc (sigma |p1 - p0|^2 = 23.8 at mc = 0.01, 0.31 at 0.5, 0.16 at 0.6), down to 0 at
 * the circle's limit mc -> 1 (k -> infinity), where sqrt(mu) cancels (4 k (K - E) ~ k m): the
 * large loops of lower tensions are the x chart's (found, exact data, sigma |p1 - p0|^2 1e-6 .. 20) */
#define T_LO (-690.0)
#define T_HI (-0.01005033585350145)   /* ln 0.99 */
#define T_SAMPLES 48

typedef struct { double sigma, L, E, x2; } whole_loop;

/* The whole-period loop at t = ln mc: its tension, length, energy and kappa0^2 (normalised).
 * EL_EDOM where sqrt(mu) <= 0 (no such loop). */
static int loop_at(double t, whole_loop *w)
{
    const double mc = exp(t), m = 1.0 - mc, g = sqrt(m);   /* g = 1 / k */
    double K, D;
    if (el__ellint_complete(g, mc, &K, &D)) return EL_EDOM;
    const double E = K - m * D, k = 1.0 / g, k2m1 = mc / m, twok2m1 = (1.0 + mc) / m;
    const double smu = 2.0 * twok2m1 * K / k - 4.0 * k * E;
    if (!(smu > 0.0)) return EL_EDOM;
    const double mu = smu * smu;
    w->sigma = 2.0 * mu * twok2m1;
    w->L = 2.0 * K / (k * smu);
    w->E = 8.0 * k * smu * E;
    w->x2 = 4.0 * mu * k2m1;
    return EL_OK;
}

typedef struct { double sigma; } loop_target;

static double sigma_gap(double t, void *p)
{
    whole_loop w;
    if (loop_at(t, &w)) return NAN;   /* (no loop there: no bracket ends at t) */
    return log(w.sigma / ((const loop_target *)p)->sigma);
}

/* The loop at t (kappa0 of the sign side) as a solution in the world frame of fr, its
 * parameters in closed form: k = side / g (g = 1 / |k|), phi = psi0 + pi (F = (kappa0^2 - sigma)
 * T0, against t0), and the start at the curvature minimum half a period before the loop's
 * peak at u = 0, |k| u = -K(g): q = -K / |k| (the loop centred, and inside the curve where k
 * rounds to +-1, the separatrix, which has its one loop at u = 0; the state's phase, from the
 * angle theta - phi = pi, would lose it to the rounding of pi: a loop 0.23 of the length off
 * centre at sigma |p1 - p0|^2 = 51 200). */
static int loop_solution(const hframe *fr, double sigma, double t, int side, el_hermite_solution *s)
{
    const double mc = exp(t), m = 1.0 - mc, g = sqrt(m);
    double K;
    whole_loop w;
    if (loop_at(t, &w) || el__ellint_complete(g, mc, &K, NULL)) return EL_EDOM;
    const double d = fr->d, k = 1.0 / g;
    memset(s, 0, sizeof *s);
    s->npieces = 1;
    s->curve.x0 = fr->p0[0];
    s->curve.y0 = fr->p0[1];
    s->curve.phi = el__hermite_wrap_pi(fr->psi0 + M_PI);
    s->curve.mu = (w.sigma / (2.0 * (1.0 + mc) / m)) / (d * d);
    s->curve.k = side * k;
    s->curve.q = -K / k;
    s->curve.length = s->length = w.L * d;
    s->sigma = sigma;
    s->energy = w.E / d;
    /* the end curvatures of the curve as it is represented (its k rounded), as a polished
     * solution's: the closed form's side sqrt(x2) / d differs by ~eps / k'^2 */
    const double ends[2] = {0.0, s->length};
    double kappa[2];
    int rc = el_smooth_check(&s->curve);
    if (!rc) rc = el_smooth_eval(&s->curve, 2, ends, NULL, NULL, kappa);
    if (!rc) {
        s->kappa0 = kappa[0];
        s->kappa1 = kappa[1];
    }
    return rc;
}
static int chord_loops_length(const hframe *fr, const hprob *pr, const el_hermite_options *opt,
                              el_hermite_solution **sol, size_t *n, size_t *cap,
                              el_hermite_solution *unrep, size_t *nunrep);
/* a and b the same loop: el__hermite_same_solution, or (a representation of it the roots gave,
 * whose end curvatures are its far tails' rounding: a chain's kappa0 2.9e-6 where the loop's is
 * 1.7e-7 at a = 0.3, off (3000, -2100) d, sigma d^2 2773) the same length, energy and sense */
int el__hermite_same_loop(const el_hermite_solution *a, const el_hermite_solution *b, double d)
{
    return el__hermite_same_solution(a, b, d) ||
           (fabs(a->length - b->length) <= 1e-7 * (a->length + b->length) &&
            fabs(a->energy - b->energy) <= 1e-7 * (a->energy + b->energy) && a->curve.k * b->curve.k > 0.0);
}

/* GSL's Brent (s, the caller's) on F over the bracket [lo, hi], to 4 eps in t at most 200
 * iterations: *root is the last iterate's estimate (left as the caller set it where the first
 * iteration fails); the status of gsl_root_fsolver_set (nonzero: F does not change sign over
 * [lo, hi], *root untouched) */
static int brent_root(gsl_root_fsolver *s, gsl_function *F, double lo, double hi, double *root)
{
    const int status = gsl_root_fsolver_set(s, F, lo, hi);
    if (status != GSL_SUCCESS) return status;
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(s)) break;
        *root = gsl_root_fsolver_root(s);
        lo = gsl_root_fsolver_x_lower(s);
        hi = gsl_root_fsolver_x_upper(s);
        if (gsl_root_test_interval(lo, hi, 0.0, 4.0 * DBL_EPSILON) == GSL_SUCCESS) break;
    }
    return GSL_SUCCESS;
}

int el__hermite_chord_loops(const hframe *fr, const hprob *pr, const el_hermite_options *opt,
                            el_hermite_solution **sol, size_t *n, size_t *cap,
                            el_hermite_solution *unrep, size_t *nunrep)
{
    if (opt->mode == EL_HERMITE_LENGTH) return chord_loops_length(fr, pr, opt, sol, n, cap, unrep, nunrep);
    if (opt->mode != EL_HERMITE_TENSION || !(pr->sigma > 0.0) || !(fabs(pr->P1) <= CHORD_NEAR) ||
        !(fabs(pr->V1) <= CHORD_NEAR) || !(pr->P2 > 0.0) || !(pr->V2 > 0.0))
        return EL_OK;
    loop_target tg = {pr->sigma};
    gsl_function F = {sigma_gap, &tg};
    double tprev = T_LO, gprev = sigma_gap(T_LO, &tg);
    gsl_root_fsolver *s = NULL;
    int rc = EL_OK, counted = 0;   /* (the caller's room in unrep: one bracket, sigma(t) monotone) */
    for (int i = 1; i <= T_SAMPLES && !rc; i++) {
        const double t = T_LO + (T_HI - T_LO) * i / T_SAMPLES, g = sigma_gap(t, &tg);
        if (gprev > 0.0 && g <= 0.0) {   /* (NAN on either side: no bracket) */
            if (!s && !(s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent))) return EL_ENOMEM;
            double root = 0.5 * (tprev + t);
            if (brent_root(s, &F, tprev, t, &root) == GSL_SUCCESS) {
                for (int side = 1; side >= -1 && !rc; side -= 2) {
                    el_hermite_solution x;
                    if (loop_solution(fr, opt->sigma, root, side, &x) || el__hermite_residual(fr, &x, &x.residual))
                        continue;
                    const double L0 = x.length;
                    if (x.residual > opt->tol && el__hermite_polish_to(fr, EL_HERMITE_TENSION, opt->sigma, opt->tol, &x))
                        continue;
                    /* (and still the loop: a polish can slide it out of the curve, onto the segment) */
                    double th[2];
                    const double h[2] = {0.0, x.curve.length};
                    /* (one period at most: the data's move can take a whole period past it) */
                    if (!(fabs(x.length - L0) <= 1e-2 * L0) ||
                        (x.length != L0 && !el__hermite_within_period(&x.curve, 1)) ||
                        el_smooth_eval(&x.curve, 2, h, NULL, th, NULL) ||
                        !(fabs(fabs(th[1] - th[0]) - 2.0 * M_PI) <= 1e-3))
                        continue;
                    /* a loop no piece meets to tol: k - 1 a few ulps (mc ~ 1e-13 .. 1e-17 at sigma
                     * |p1 - p0|^2 ~ 1300 .. 4000), where one ulp of k moves the end by ~eps / k'
                     * (hermite_chain.c; polished residual 1.1e-9 at 2000, k' = sqrt(mc) = e^(t/2)): the
                     * curve exists (the closed form is exact in t), counted unrepresentable
                     * (hermite.c drops it where the roots returned it, as a chain) */
                    if (!(x.residual <= opt->tol)) {
                        if (!(x.residual <= 1e3 * DBL_EPSILON / exp(0.5 * root)) || counted == 2) continue;
                        /* once: not where the roots returned it (a chain), and replacing a root's
                         * representation counted already (its chain not met: residual 0.11,
                         * kappa0 twice the loop's, at a = 0.3, off (3000, -2100) d, sigma d^2 2476) */
                        int kept = 0;
                        for (size_t j = 0; j < *n && !kept; j++) kept = el__hermite_same_loop(&x, &(*sol)[j], fr->d);
                        if (kept) continue;
                        size_t j = 0;
                        while (j < *nunrep && !el__hermite_same_loop(&x, &unrep[j], fr->d)) j++;
                        unrep[j] = x;
                        if (j == *nunrep) { (*nunrep)++; counted++; }
                        continue;
                    }
                    /* a root's representation of it counted unrepresentable is not counted: it
                     * becomes this loop, which hermite.c finds returned (the roots' piece at
                     * residual 0.086 beside both loops at a = -2.5, d = 1e-3, sigma d^2 4363) */
                    for (size_t j = 0; j < *nunrep; j++)
                        if (el__hermite_same_loop(&x, &unrep[j], fr->d)) unrep[j] = x;
                    /* the exact loop replaces a representation of it the roots gave (a chain or
                     * a piece whose loop the rounding of its phase moved off centre), whatever
                     * their residuals: the roots' piece can meet the ends better with its loop
                     * off centre (kept, it peaks at 0.15 of L at a = 2, d = 1e3, sigma d^2 9e4) */
                    int dup = 0;
                    for (size_t j = 0; j < *n && !dup; j++)
                        if (el__hermite_same_solution(&x, &(*sol)[j], fr->d)) { dup = 1; (*sol)[j] = x; }
                    if (dup) continue;
                    if (*n == *cap) {
                        el_hermite_solution *more = realloc(*sol, 2 * (*cap + 1) * sizeof *more);
                        if (!more) { free(*sol); *sol = NULL; rc = EL_ENOMEM; break; }
                        *sol = more;
                        *cap = 2 * (*cap + 1);
                    }
                    (*sol)[(*n)++] = x;
                }
            }
        }
        if (isnan(g)) continue;   /* (a sample without a loop: the bracket spans it) */
        tprev = t;
        gprev = g;
    }
    if (s) gsl_root_fsolver_free(s);
    return rc;
}

/* ---- by length ---- */

typedef struct { double logl; } length_target;

/* log(L(t) - 1) - log(Ln - 1): the whole-period loop's length beyond the chord against the
 * given one (normalised); the log keeps the relative resolution of L - 1 (5.8e-3 at T_LO) */
static double length_gap(double t, void *p)
{
    whole_loop w;
    if (loop_at(t, &w) || !(w.L > 1.0)) return NAN;
    return log(w.L - 1.0) - ((const length_target *)p)->logl;
}

/* The loop at t of the sign side kept by length, as the tension path keeps its own (above):
 * the closed form's curve with the given length (its L(t) to the root's rounding), polished
 * onto the data where they are only near the chord (el__hermite_polish_to in length mode:
 * phi, mu, k, q move, L stays), kept at residual <= tol, still turning 2 pi, sqrt(mu) within
 * 1e-2 of the closed form's (not slid onto another curve) and within one period; a curve of
 * the list that is the same (el__hermite_same_solution: the tracer's representation of the
 * loop, found above ~1.1 |p1 - p0|) is replaced by it, as by tension. Where no piece meets tol
 * only by the rounding of k (sqrt(mu) |p1 - p0| ~ 25 .. 45, L ~ 1.09 .. 1.16 |p1 - p0|: k - 1
 * below an ulp, the tails e^-(sqrt(mu) L / 2) above tol; the closed form's residual ~1e-9 at
 * tol 1e-10, <= 1e3 eps / k' as by tension) and the data are on the chord to rounding
 * (|P1|, |V1| <= CHORD_EXACT), the loop is counted unrepresentable (unrep, once per side) unless
 * the list holds it (the tracer's chain, found from ~1.125 |p1 - p0| on).
 * hermite_chain.c cannot carry it: its pieces split at a saddle inside the curve, and this
 * loop's saddles are its ends. */
static int keep_length_loop(const hframe *fr, const hprob *pr, const el_hermite_options *opt, double t, int side,
                            el_hermite_solution **sol, size_t *n, size_t *cap,
                            el_hermite_solution *unrep, size_t *nunrep)
{
    whole_loop w;
    el_hermite_solution x;
    if (loop_at(t, &w) || loop_solution(fr, w.sigma / (fr->d * fr->d), t, side, &x)) return EL_OK;
    /* the mode's given value is exact, not the root's approximation of it (hermite.c's roots) */
    x.length = x.curve.length = opt->length;
    const double ends[2] = {0.0, x.length};
    double kappa[2];
    if (el_smooth_check(&x.curve) || el_smooth_eval(&x.curve, 2, ends, NULL, NULL, kappa)) return EL_OK;
    x.kappa0 = kappa[0];
    x.kappa1 = kappa[1];
    if (el__hermite_residual(fr, &x, &x.residual)) return EL_OK;
    const el_smooth_params c0 = x.curve;
    const el_hermite_solution closed = x;
    if (x.residual > opt->tol && el__hermite_polish_to(fr, EL_HERMITE_LENGTH, opt->length, opt->tol, &x))
        x.residual = INFINITY;
    if (!(x.residual <= opt->tol)) {
        /* only on the chord to rounding (the closed form's curve then is the data's, met to
         * its residual ~1e-9): off it by more the loop slides off centre, another curve, which
         * this one does not stand for (make hermite-sets set 7, moves 1e-8 .. 1e-2: counted
         * beside the tracer's own) */
        if (!(closed.residual <= 1e3 * DBL_EPSILON / exp(0.5 * t)) || !(fabs(pr->P1) <= CHORD_EXACT) ||
            !(fabs(pr->V1) <= CHORD_EXACT))
            return EL_OK;
        for (size_t j = 0; j < *n; j++)
            if (el__hermite_same_loop(&closed, &(*sol)[j], fr->d)) return EL_OK;
        size_t j = 0;
        while (j < *nunrep && !el__hermite_same_loop(&closed, &unrep[j], fr->d)) j++;
        unrep[j] = closed;
        if (j == *nunrep) (*nunrep)++;
        return EL_OK;
    }
    const int moved = memcmp(&c0, &x.curve, sizeof c0) != 0;
    double th[2];
    if (!(x.residual <= opt->tol) || !(fabs(sqrt(x.curve.mu) - sqrt(c0.mu)) <= 1e-2 * sqrt(c0.mu)) ||
        (moved && !el__hermite_within_period(&x.curve, 1)) ||
        el_smooth_eval(&x.curve, 2, ends, NULL, th, NULL) ||
        !(fabs(fabs(th[1] - th[0]) - 2.0 * M_PI) <= 1e-3))
        return EL_OK;
    /* a root's representation of it counted unrepresentable becomes this loop (hermite.c then
     * finds it returned), as by tension */
    for (size_t j = 0; j < *nunrep; j++)
        if (el__hermite_same_loop(&x, &unrep[j], fr->d)) unrep[j] = x;
    for (size_t j = 0; j < *n; j++)
        if (el__hermite_same_solution(&x, &(*sol)[j], fr->d)) {
            (*sol)[j] = x;
            return EL_OK;
        }
    if (*n == *cap) {
        el_hermite_solution *more = realloc(*sol, 2 * (*cap + 1) * sizeof *more);
        if (!more) { free(*sol); *sol = NULL; return EL_ENOMEM; }
        *sol = more;
        *cap = 2 * (*cap + 1);
    }
    (*sol)[(*n)++] = x;
    return EL_OK;
}

/* By length: the same whole-period loops, their t = ln mc from L(t) = 2 K / (k sqrt(mu)) =
 * Ln = L / |p1 - p0| (the closed form above). L(t) rises strictly from 1 + 5.8e-3 at T_LO
 * (sigma |p1 - p0|^2 = 9.5e5) to 796 at T_HI (6.2e-5): checked in double on 2 000 000
 * equally spaced t of [T_LO, T_HI] (/tmp/hermlen/mono.c: every sample > the one before, none
 * without a loop), the closed form's limits 1 + 4 / sqrt(mu) as mc -> 0 (the separatrix loop,
 * sqrt(mu) ~ ln(16 / mc) - 4 -> infinity) and ~ 2 pi k / sqrt(mu) -> infinity as mc -> 1 (the
 * circle). So [T_LO, T_HI] brackets every root, and there is one where log(L - 1) - log(Ln - 1)
 * changes sign between its ends: GSL's Brent on it, to 4 eps in t; the loop and its mirror
 * kept as by tension. Lengths below 1 + 5.8e-3 (tensions past 9.5 times
 * EL_HERMITE_SIGMA_D2_MAX) and above 796 (the x chart's large loops, which the tracer follows)
 * are not looked for here. */
static int chord_loops_length(const hframe *fr, const hprob *pr, const el_hermite_options *opt,
                              el_hermite_solution **sol, size_t *n, size_t *cap,
                              el_hermite_solution *unrep, size_t *nunrep)
{
    const double Ln = opt->length / fr->d;
    if (!(Ln > 1.0) || !(fabs(pr->P1) <= CHORD_NEAR) || !(fabs(pr->V1) <= CHORD_NEAR) || !(pr->P2 > 0.0) ||
        !(pr->V2 > 0.0))
        return EL_OK;
    length_target tg = {log(Ln - 1.0)};
    gsl_function F = {length_gap, &tg};
    const double glo = length_gap(T_LO, &tg), ghi = length_gap(T_HI, &tg);
    if (!(glo < 0.0 && ghi > 0.0)) return EL_OK;   /* (L(t) rises: no root, or NAN) */
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    double root = NAN;
    brent_root(s, &F, T_LO, T_HI, &root);   /* (a refused bracket leaves root NAN: no loop) */
    gsl_root_fsolver_free(s);
    int rc = EL_OK;
    for (int side = 1; side >= -1 && !rc && isfinite(root); side -= 2)
        rc = keep_length_loop(fr, pr, opt, root, side, sol, n, cap, unrep, nunrep);
    return rc;
}
