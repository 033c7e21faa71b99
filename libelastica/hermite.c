/*
 * Hermite interpolation by elastic curves, seed 004: all curves of length at
 * most one curvature period from (p0, t0) to (p1, t1).
 *
 * Relations (rederived; the OCR lost them). With T = x', N = J T the constant
 * force vector of 2 kappa'' + kappa^3 - sigma kappa = 0 is
 *   F = (kappa^2 - sigma) T + 2 kappa' N,      |F| = kappa_m^2 - sigma,    (8)
 * (d/ds F = (2 kappa'' + kappa^3 - sigma kappa) N = 0), and
 *   kappa(s) - kappa(0) = det(x(s) - x(0), F) / 2,                        (10)
 *   E(s) = int_0^s kappa^2 = <F, x(s) - x(0)> + sigma s.                   (12)
 * In the normalised frame x(0) = 0, T(0) = (0,1), N(0) = (-1,0),
 * F = (-2 kappa0', kappa0^2 - sigma); F in the frame of V = x'(L) gives
 *   kappa1' = kappa0' V2 + (kappa0^2 - sigma) V1 / 2,                      (14)
 *   kappa1^2 = -2 kappa0' V1 + (kappa0^2 - sigma) V2 + sigma,              (15)
 *   kappa1 = kappa0' P2 + (kappa0^2 - sigma) P1 / 2 + kappa0.              (16)
 * Eliminating kappa0' with (16): P2 kappa1^2 + 2 V1 kappa1 - 2 V1 C - A P2 = 0
 * (17) with A = (kappa0^2 - sigma) V2 + sigma, C = (kappa0^2 - sigma) P1/2 + kappa0.
 *
 * In the library's parametrisation (header, seed 000 (4.3)): kappa_m^2 = 4 k^2 mu,
 * |F| = 2 mu, sigma = 2 mu (2k^2 - 1), phi = angle of F, and with
 * h = (theta - phi)/2: k < 1: sn u = sin h / k, cn u = kappa / kappa_m, so the
 * amplitude of u is atan2(sqrt(2|F|) sin h, kappa); k > 1: am(k u; 1/k) = h.
 *
 * Objective (35): given the curvature data at both ends the curve meets the
 * tangent V and the component of P across F (Theorem 8); the remaining
 * condition is the component along F, which by (12) is
 *   f = (E(L) - sigma L - <F, P>) / |F|     (the position error along F).
 * This is the paper's x1(L) - P1 rotated into the frame of F; unlike x1 it
 * stays a valid objective where F is parallel to x1 (kappa0^2 = sigma).
 */
#include "hermite_internal.h"
#include <float.h>
#include <gsl/gsl_math.h>   /* M_PI_2 */
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------ world-frame solutions */

/* el_smooth_params of the elastica starting at (x0, y0) with tangent angle theta,
 * curvature kappa, kappa' = dkappa, tension sigma, length L (the inverse of the
 * header's parametrisation, see the top of this file). A non-inflectional curve
 * (kappa != 0 throughout) gets the sign of kappa as the sign of k: k < -1 is the
 * clockwise loop, the mirror image of the k > 1 loop in the line through (x0, y0)
 * along F. The mirror R maps T -> R T, N -> -R N, kappa -> -kappa, kappa' -> -kappa',
 * so F = (kappa^2 - sigma) T + 2 kappa' N -> R F = F: phi and mu are those of the
 * mirrored curve, and with a = theta - phi over 2, sin a = k sn(u;|k|) =
 * sign(k) sn(|k| u; 1/|k|), cos a = dn(u;|k|) = cn(|k| u; 1/|k|), so
 * am(|k| q; 1/|k|) = sign(k) a. */
int el__hermite_params_from_state(double x0, double y0, double theta, double kappa,
                                  double dkappa, double sigma, double L, const double *sep,
                                  el_smooth_params *p)
{
    const double T[2] = {cos(theta), sin(theta)}, N[2] = {-T[1], T[0]};
    const double w = kappa * kappa - sigma;
    const double F[2] = {w * T[0] + 2.0 * dkappa * N[0], w * T[1] + 2.0 * dkappa * N[1]};
    /* |F| - sigma exactly when the separatrix chart gave it (its relative precision is
     * what the modulus complement needs) */
    const double Fn = sep ? sigma + *sep : hypot(F[0], F[1]), dsep = sep ? *sep : Fn - sigma;
    p->x0 = x0;
    p->y0 = y0;
    p->length = L;
    /* kappa_m^2 = |F| + sigma; below sigma = 0 next to the centre (kappa, kappa' ~ theta
     * sqrt|sigma|) that cancels to ~eps |sigma| absolute (tangents 1e-9 rad off the chord at
     * sigma |p1 - p0|^2 = -10: km2 rounded to 0, the near-straight curve lost): there
     * (|F|^2 - sigma^2) / (|F| - sigma) = (kappa^2 (kappa^2 - 2 sigma) + 4 kappa'^2) / (|F| - sigma),
     * a sum of positive terms (|F|^2 from (8)) */
    double km2 = Fn + sigma;
    if (sigma < 0.0 && !sep && km2 < 1e-3 * Fn)
        km2 = (kappa * kappa * (kappa * kappa - 2.0 * sigma) + 4.0 * dkappa * dkappa) / dsep;
    if (!(Fn > 0.0) || !(km2 > 0.0)) return EL_EDOM;
    const double k2 = km2 / (2.0 * Fn), kc2 = dsep / (2.0 * Fn);
    const double h = 0.5 * el__hermite_wrap_pi(theta - atan2(F[1], F[0]));
    p->mu = 0.5 * Fn;
    p->phi = atan2(F[1], F[0]);
    double Fq, Dq;
    int rc;
    /* q = F(amplitude): F is odd in the amplitude, which lies in (-pi, pi] */
    if (kc2 > 0.0) {
        const double y = sqrt(2.0 * Fn) * sin(h), r = hypot(y, kappa);
        if ((rc = el__hermite_ell_fd(fabs(y) / r, kappa / r, 0, k2, kc2, 1.0, &Fq, &Dq))) return rc;
        p->k = sqrt(k2);
        p->q = copysign(Fq, y);
    } else {
        const double k = sqrt(k2), m2 = 2.0 * Fn / km2, mc2 = -dsep / km2;
        const double eps = kappa > 0.0 ? 1.0 : -1.0;
        if (!(kappa != 0.0)) return EL_EDOM;
        if ((rc = el__hermite_ell_fd(fabs(sin(h)), cos(h), 0, m2, mc2, 1.0, &Fq, &Dq))) return rc;
        p->k = eps * k;
        p->q = copysign(Fq, eps * h) / k;
    }
    return EL_OK;
}

/* |F| - sigma of a root (normalised; exact where the separatrix chart gave it), and
 * |F| + |sigma|, its scale. */
static double root_sep(const hroot *r, double *scale)
{
    const hstate *st = &r->st;
    const double F1 = -2.0 * st->k0p, F2 = st->k0 * st->k0 - r->sigma, Fn = hypot(F1, F2);
    *scale = Fn + fabs(r->sigma);
    return st->has_sep ? st->sep : Fn - r->sigma;
}

/* A root whose curve the smooth parameters cannot carry to tol: a root bracket_root
 * keeps (|f| <= 1e-8) so close to the separatrix (|F| - sigma below 1e-6 of
 * |F| + sigma) that the double k (whose complement k'^2 = 1 - k^2 sets the length near
 * the saddle) moves the end by more than tol. The gate on f is bracket_root's, not the
 * rounding level: in the separatrix chart a near-straight curve's root can sit where one
 * ulp of y moves f by 1e-11..1e-8 (aligned tangents, sigma |p1-p0|^2 ~ 300..1000: its
 * bracket closes between f = 1.1e-10 and -2.8e-11), and the chain corrects the phases by
 * its own Gauss-Newton; whatever it returns is accepted only at residual <= tol. (At
 * |f| <= 1e-11, 12 of 4000 random aligned problems lost such a chain.) */
static int representation_limited(const hroot *r)
{
    double scale;
    const double sep = root_sep(r, &scale);
    return fabs(r->st.f) <= 1e-8 && fabs(sep) <= 1e-6 * scale;
}

static int make_solution(const hframe *fr, const hroot *r, el_hermite_solution *s)
{
    const hstate *st = &r->st;
    const double d = fr->d;
    memset(s, 0, sizeof *s);
    s->npieces = 1;
    s->length = st->L * d;
    s->sigma = r->sigma / (d * d);
    s->energy = st->E / d;
    s->kappa0 = st->k0 / d;
    s->kappa1 = st->k1 / d;
    s->has_inflection = 0;
    if (st->infl) {
        /* kappa = kappa_m cn(u): a zero inside iff the amplitude am u passes an odd
         * multiple of pi/2 between its values a0, a0 + d at the ends, d in (0, 2 pi]
         * (am(u + 2 Kc) = am u + pi): d > pi iff u(L) - u(0) > 2 Kc, which decides d
         * where rounding leaves it open (a whole period, d = 2 pi, has two zeros) */
        const double a0 = atan2(st->s0, st->c0);
        double d = atan2(st->s1, st->c1) - a0;
        d -= 2.0 * M_PI * floor(d / (2.0 * M_PI));
        if (st->big && d <= M_PI) d += 2.0 * M_PI;
        if (!st->big && d > 1.5 * M_PI) d -= 2.0 * M_PI;
        const double a = (a0 - M_PI_2) / M_PI + 1e-9, b = (a0 + d - M_PI_2) / M_PI - 1e-9;
        /* zeros of cn strictly inside: integers n with a < n < b (a zero at an end is no inflection) */
        s->has_inflection = ceil(b) - floor(a) - 1.0 > 0.5;
    }
    /* scaled by e = 2^ilogb(d) (exactly; d / e in [1, 2)): |F| - sigma (to 1e-300) would
     * underflow divided by d^2 (length 1.01 d at d = 1e40: solutions lost) */
    const double e = fr->e, dn = d / e, dn2 = dn * dn, sep = st->sep / dn2;
    const int rc = el__hermite_params_from_state(fr->p0[0], fr->p0[1], fr->psi0, st->k0 / dn, st->k0p / dn2,
                                                 r->sigma / dn2, st->L * dn, st->has_sep ? &sep : NULL, &s->curve);
    s->curve.mu /= e * e;
    s->curve.length = s->length;
    return rc;
}

static int straight_solution(const hframe *fr, double sigma, el_hermite_solution *s)
{
    memset(s, 0, sizeof *s);
    s->npieces = 1;
    s->curve.x0 = fr->p0[0];
    s->curve.y0 = fr->p0[1];
    s->curve.phi = fr->psi0;
    s->curve.mu = 1.0 / (fr->d * fr->d);
    s->curve.k = 0.0;
    s->curve.q = 0.0;
    s->curve.length = s->length = fr->d;
    s->sigma = sigma;
    return EL_OK;
}


/* The circular arc from (p0, t0) through p1, if it ends with tangent t1: curvature
 * c = 2 det(t0, P) / |P|^2 (P = p1 - p0), turning angle 2 beta (beta: from t0 to P).
 * A circle is an elastica for sigma = c^2 (kappa_m^2 = sigma, F = 0), where the
 * objective (35) is singular (Theorem 8 excludes it), so it is checked apart. The
 * parametrisation reaches it only as k -> infinity (k^2 mu fixed): k = 1e4 is used,
 * with kappa = 2 k sqrt(mu) dn(k u; 1/k) constant to 1/(2 k^2) = 5e-9 relative, and
 * el_smooth_eval's closed form loses about eps k^2 to cancellation, so the arc
 * meets the ends only to ~1e-8: it is returned when that is within opt->tol. */
static int circle_arc(const hframe *fr, const double u0[2], double *c, double *L)
{
    const double P[2] = {fr->p1[0] - fr->p0[0], fr->p1[1] - fr->p0[1]};
    const double beta = atan2(u0[0] * P[1] - u0[1] * P[0], u0[0] * P[0] + u0[1] * P[1]);
    if (fabs(beta) < 1e-8) return 0;                       /* straight, handled apart */
    /* fr->psi1: the end tangent's angle, atan2(u1[1], u1[0]) of el__hermite_normalise */
    if (fabs(el__hermite_wrap_pi(fr->psi0 + 2.0 * beta - fr->psi1)) > 1e-12) return 0;
    *c = 2.0 * sin(beta) / fr->d;
    *L = 2.0 * beta / *c;
    return 1;
}

static int circle_solution(const hframe *fr, double c, double L, el_hermite_solution *s)
{
    const double k = 1e4;
    memset(s, 0, sizeof *s);
    s->npieces = 1;
    s->curve.x0 = fr->p0[0];
    s->curve.y0 = fr->p0[1];
    s->curve.phi = fr->psi0;
    s->curve.k = c < 0.0 ? -k : k;              /* clockwise: kappa = 2 k sqrt(mu) dn < 0 */
    s->curve.mu = c * c / (4.0 * k * k);
    s->curve.q = 0.0;
    s->curve.length = s->length = L;
    s->sigma = c * c;
    s->energy = c * c * L;
    s->kappa0 = s->kappa1 = c;
    return EL_OK;
}

static int cmp_energy(const void *a, const void *b)
{
    const el_hermite_solution *x = a, *y = b;
    return (x->energy > y->energy) - (x->energy < y->energy);
}

/* theta(L) - theta(0) of a solution, summed over a chain's pieces. */
static int turning(const el_hermite_solution *s, double *w)
{
    int rc = EL_OK;
    *w = 0.0;
    for (int i = 0; i < s->npieces && !rc; i++) {
        const el_smooth_params *q = i ? &s->rest[i - 1] : &s->curve;
        const double h[2] = {0.0, q->length};
        double t[2];
        if (!(rc = el_smooth_eval(q, 2, h, NULL, t, NULL))) *w += t[1] - t[0];
    }
    return rc;
}

/* Same length, tension, end curvatures and turning of the first pieces (theta(l) - theta(0),
 * l the shorter) and, a chain's, of the whole curves: a mirror pair whose end curvatures
 * vanish (loops at the separatrix between tangents along the chord, kappa0 ~ 1e-13 / |p1 - p0|)
 * differs only in its turning, +-2 pi. */
int el__hermite_same_solution(const el_hermite_solution *a, const el_hermite_solution *b, double d)
{
    const double tk = 1e-6 / d;
    if (!(fabs(a->length - b->length) <= 1e-7 * (a->length + b->length) &&
          fabs(a->kappa0 - b->kappa0) <= tk * (1.0 + fabs(a->kappa0) * d) &&
          fabs(a->kappa1 - b->kappa1) <= tk * (1.0 + fabs(a->kappa1) * d) &&
          fabs(a->sigma - b->sigma) * d * d <= 1e-6 * (1.0 + fabs(a->sigma) * d * d)))
        return 0;
    const double h[2] = {0.0, fmin(a->curve.length, b->curve.length)};
    double ta[2], tb[2];
    if (el_smooth_eval(&a->curve, 2, h, NULL, ta, NULL) ||
        el_smooth_eval(&b->curve, 2, h, NULL, tb, NULL))
        return 1;
    if (!(fabs((ta[1] - ta[0]) - (tb[1] - tb[0])) <= 1e-6)) return 0;
    /* a chain's first piece can end before its loop, where the mirror image turns alike */
    if (a->npieces == 1 && b->npieces == 1) return 1;
    double wa, wb;
    if (turning(a, &wa) || turning(b, &wb)) return 1;
    return fabs(wa - wb) <= 1e-6;
}

void el_hermite_options_defaults(el_hermite_options *opt)
{
    if (!opt) return;
    opt->mode = EL_HERMITE_TENSION;
    opt->sigma = 0.0;
    opt->length = 0.0;
    opt->tol = 1e-10;
    opt->samples = 12;
    opt->grid = 6;
    opt->max_solutions = 64;
}

void el_hermite_result_free(el_hermite_result *res)
{
    if (!res) return;
    free(res->solutions);
    res->solutions = NULL;
    res->count = 0;
    res->unrepresentable = 0;
}

int el__hermite_unit(const double t[2], double u[2])
{
    const double n = hypot(t[0], t[1]);
    if (!(n > 0.0) || !isfinite(n)) return EL_EINVAL;
    u[0] = t[0] / n;
    u[1] = t[1] / n;
    return EL_OK;
}

/* The range the solver covers (header): coordinates and |p1 - p0| up to 1e100 and
 * |p1 - p0| down to 1e-100 (the curvature ~ 1/d, mu = |F|/2 ~ 1/d^2 and the energy stay
 * in double range); sigma |p1 - p0|^2 up to EL_HERMITE_SIGMA_D2_MAX (the separatrix search
 * reaches |F| - sigma = 1e-300 sigma, and the solutions lie within exp(-sqrt(2 sigma) L') of
 * it). */
#define SCALE_MAX 1e100

/* The normalisation of seed 004 §4 (p0 = 0, t0 = (0, 1), |p1 - p0| = 1) of the data p0, u0,
 * p1, u1 (u0, u1 unit): fr the world frame, pr's P, V and case (el__hermite_set_case); EL_EDOM
 * outside the scales above. fr too has p0 = 0, added back at the end: residuals without
 * ulp(|p0|) / d (2e-10 at |p0| = 1e6 d). hermite_case3.c's inner problem is normalised by
 * the same steps, to know that el_hermite_solve will take it for case 3 (no recursion). */
int el__hermite_normalise(const double p0[2], const double u0[2], const double p1[2],
                          const double u1[2], hframe *fr, hprob *pr)
{
    fr->p0[0] = fr->p0[1] = 0.0;
    fr->p1[0] = p1[0] - p0[0];
    fr->p1[1] = p1[1] - p0[1];
    fr->psi0 = atan2(u0[1], u0[0]);
    fr->psi1 = atan2(u1[1], u1[0]);
    fr->d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    fr->rot = fr->psi0 - M_PI_2;
    if (!(fr->d >= 1.0 / SCALE_MAX && fr->d <= SCALE_MAX) || fabs(p0[0]) > SCALE_MAX ||
        fabs(p0[1]) > SCALE_MAX || fabs(p1[0]) > SCALE_MAX || fabs(p1[1]) > SCALE_MAX)
        return EL_EDOM;
    fr->e = ldexp(1.0, ilogb(fr->d));   /* once per problem, not per solution */
    const double cr = cos(fr->rot), sr = sin(fr->rot);
    const double dx = (p1[0] - p0[0]) / fr->d, dy = (p1[1] - p0[1]) / fr->d;
    pr->P1 = cr * dx + sr * dy;
    pr->P2 = -sr * dx + cr * dy;
    pr->V1 = cr * u1[0] + sr * u1[1];
    pr->V2 = -sr * u1[0] + cr * u1[1];
    el__hermite_set_case(pr);
    return EL_OK;
}

int el_hermite_solve(const double p0[2], const double t0[2], const double p1[2],
                     const double t1[2], const el_hermite_options *opt,
                     el_hermite_result *res)
{
    return el__hermite_solve_limited(p0, t0, p1, t1, opt, EL__HERMITE_MAX_EVALS, res);
}

int el__hermite_solve_limited(const double p0[2], const double t0[2], const double p1[2],
                              const double t1[2], const el_hermite_options *opt, long max_evals,
                              el_hermite_result *res)
{
    if (!p0 || !t0 || !p1 || !t1 || !opt || !res) return EL_EINVAL;
    const double all[8] = {p0[0], p0[1], t0[0], t0[1], p1[0], p1[1], t1[0], t1[1]};
    double u0[2], u1[2];
    if (el__all_finite(all, 8) || el__hermite_unit(t0, u0) || el__hermite_unit(t1, u1)) return EL_EINVAL;
    if (opt->mode != EL_HERMITE_TENSION && opt->mode != EL_HERMITE_LENGTH) return EL_EINVAL;
    if (!isfinite(opt->sigma) || !isfinite(opt->length) || !(opt->tol > 0.0) ||
        opt->samples < 4 || opt->samples > 1000 || opt->grid < 1 || opt->grid > 256 ||
        opt->max_solutions == 0)
        return EL_EINVAL;
    if (opt->mode == EL_HERMITE_LENGTH && !(opt->length > 0.0)) return EL_EINVAL;
    el__gsl_quiet();
    res->count = 0;
    res->solutions = NULL;
    res->unrepresentable = 0;

    /* normalisation (seed 004 §4): p0 = 0, t0 = (0, 1), |p1 - p0| = 1, sigma d^2 */
    hframe fr;
    hprob pr;
    if (el__hermite_normalise(p0, u0, p1, u1, &fr, &pr)) return EL_EDOM;
    /* the straight segment meets the ends to tol (its residual is checked below): p1 ahead
     * on the line of t0 and t1 along t0, each to tol. Near-straight curves between nearly
     * collinear tangents lie next to the saddle of the curvature's phase plane, where the
     * x chart's states lose their relative precision (tangents 1e-9 rad from collinear at
     * sigma |p1 - p0|^2 = 10: f off by 0.3 at the curve's state, the curve lost; 1e-12 at
     * 10 to 1e4 too); within tol the segment is one */
    int collinear = fabs(pr.P1) <= opt->tol && pr.P2 > 0.0 && fabs(pr.V1) <= opt->tol && pr.V2 > 0.0;
    /* ... where the segment meets them: a tangent tol off the chord passes the test above or
     * not by rounding, and the segment's residual ~tol the check below (tangents 1e-10 rad off
     * at tol 1e-10: the segment dropped and the near-straight curve not looked for) */
    if (collinear) {
        el_hermite_solution line;
        straight_solution(&fr, 0.0, &line);
        collinear = !el__hermite_residual(&fr, &line, &line.residual) && line.residual <= opt->tol;
    }

    hrootlist roots = {NULL, 0, 0};
    size_t nsolver = (size_t)-1;   /* roots from nsolver on: hermite_near.c's */
    int rc;
    double Ln = 0.0;
    if (opt->mode == EL_HERMITE_TENSION) {
        pr.sigma = opt->sigma * fr.d * fr.d;
        pr.Lmin = 1.0;
        if (pr.sigma > EL_HERMITE_SIGMA_D2_MAX) return EL_EDOM;
        rc = el__hermite_solve_tension(&pr, opt->samples, &roots);
        /* the near-straight curve next to the saddle, which the bracketing can miss */
        nsolver = roots.n;
        if (!rc && !collinear && pr.sigma > 0.0) rc = el__hermite_near_roots(&pr, &roots);
    } else {
        Ln = opt->length / fr.d;
        if (Ln < 1.0 - 1e-12 || !isfinite(Ln)) return EL_EDOM;
        pr.sigma = 0.0;
        pr.Lmin = Ln;
        rc = Ln > 1.0 + 1e-12 ? el__hermite_solve_length_limited(&pr, Ln, opt->grid, opt->samples, max_evals, &roots) : EL_OK;
    }
    /* the length mode's work limit: the solutions found so far, with EL_EMAXITER */
    if (rc && rc != EL_EMAXITER) { free(roots.v); return rc; }
    int status = rc;

    size_t cap = roots.n + 2;
    el_hermite_solution *sol = malloc(cap * sizeof *sol);
    if (!sol) { free(roots.v); return EL_ENOMEM; }
    size_t n = 0;
    if (collinear && (opt->mode == EL_HERMITE_TENSION || Ln <= 1.0 + 1e-12)) {
        straight_solution(&fr, opt->mode == EL_HERMITE_TENSION ? opt->sigma : 0.0, &sol[n]);
        if (!el__hermite_residual(&fr, &sol[n], &sol[n].residual) && sol[n].residual <= opt->tol)
            n++;
    }
    el_hermite_solution nearly;     /* added below unless the roots hold it */
    const int near_ok = opt->mode == EL_HERMITE_TENSION && !collinear &&
                        el__hermite_near_straight(&fr, opt->sigma, opt->tol, &nearly) == EL_OK;
    /* not met to tol only by the parameters' resolution: unrepresentable. A sliver of a huge
     * elastica, sqrt(mu) L ~ |theta| at sigma = 0, or ~ sqrt(|sigma|) |p1 - p0| at tensions
     * below theta^2 / |p1 - p0|^2 (sigma |p1 - p0|^2 = 1e-12 with the bow's tangents -+1e-6
     * rad), whose closed form loses ~eps / (sqrt(mu) L); or a curve through a saddle, whose
     * end an ulp of k moves by ~eps / ||k| - 1| (hermite.c's header; k rounded to +-1 with the
     * bow's tangents -+1e-10 rad at sigma |p1 - p0|^2 = 1e-4: residual 1.2e-8) */
    const double near_floor = near_ok ? DBL_EPSILON / fmin(sqrt(nearly.curve.mu) * nearly.curve.length,
                                                           fabs(fabs(nearly.curve.k) - 1.0)) : 0.0;
    const int near_unrep = near_ok && !(nearly.residual <= opt->tol) && nearly.residual <= 1e3 * near_floor;
    double cc, cL;
    int circle_unrep = 0;
    if (circle_arc(&fr, u0, &cc, &cL) &&
        (opt->mode == EL_HERMITE_TENSION ? fabs(opt->sigma - cc * cc) <= 1e-12 * cc * cc
                                         : fabs(opt->length - cL) <= 1e-12 * cL)) {
        circle_solution(&fr, cc, cL, &sol[n]);
        /* the arc meets the ends only to ~1e-8 (circle_arc): counted, not dropped, above tol */
        if (!el__hermite_residual(&fr, &sol[n], &sol[n].residual) && sol[n].residual <= opt->tol)
            n++;
        else circle_unrep = 1;
    }
    /* found, exact in the solver's variables, but not representable to tol (below) */
    /* (on the stack for the usual few roots: no malloc and free per problem) */
    /* (+2: the chord loops' pair, hermite_chord.c) */
    el_hermite_solution ubuf[10], *unrep = roots.n <= 8 ? ubuf : malloc((roots.n + 2) * sizeof *unrep);
    size_t nunrep = 0, near_u = (size_t)-1;   /* near_u: the near-straight root's entry */
    int near_found = 0;
    if (!unrep) { free(sol); free(roots.v); return EL_ENOMEM; }
    for (size_t i = 0; i < roots.n; i++) {
        el_hermite_solution s;
        if (make_solution(&fr, &roots.v[i], &s)) continue;
        /* the mode's given value is exact, not the root finder's approximation of it */
        if (opt->mode == EL_HERMITE_TENSION) s.sigma = opt->sigma;
        else s.length = s.curve.length = opt->length;
        if (el__hermite_residual(&fr, &s, &s.residual)) continue;
        if (s.residual > opt->tol && s.residual < 1e-5) {
            const double target = opt->mode == EL_HERMITE_TENSION ? opt->sigma : opt->length;
            el__hermite_polish_newton(&fr, opt->mode, target, &s);
            if (s.residual > opt->tol) el__hermite_polish_fixed_k(&fr, opt->mode, target, &s);
        }
        /* a near-straight root's chain from the root's curve: the polish can move k off 1 onto
         * another curve (tangents -+1e-6 rad at sigma |p1 - p0|^2 = 1e4: length 1.11 |p1 - p0|) */
        if (i >= nsolver && !(s.residual <= opt->tol)) {
            if (make_solution(&fr, &roots.v[i], &s)) continue;
            s.sigma = opt->sigma;
            if (el__hermite_residual(&fr, &s, &s.residual)) continue;
        }
        /* (and one whose piece meets the ends but, its k rounded to 1, not its curvature) */
        if (i >= nsolver && s.residual <= opt->tol && s.npieces == 1) {
            el_hermite_solution t = s;
            if (el__hermite_near_check(&fr, &roots.v[i].st, &t)) s.residual = INFINITY;
        }
        /* near the separatrix a curve through a saddle that one piece cannot carry:
         * the chain split at its saddles (hermite_chain.c) */
        if (!(s.residual <= opt->tol) && representation_limited(&roots.v[i])) {
            double scale;
            const double dn = fr.d / fr.e, sep = root_sep(&roots.v[i], &scale) / (dn * dn);
            const double target = opt->mode == EL_HERMITE_TENSION ? opt->sigma : opt->length;
            el__hermite_chain(&fr, opt->mode, target, sep, opt->tol, &s);
            if (!(s.residual <= opt->tol)) {
                /* the near-straight curve counted once (its roots on both branches) */
                if (i >= nsolver && near_u != (size_t)-1) continue;
                if (i >= nsolver) near_u = nunrep;
                unrep[nunrep++] = s;
                continue;
            }
        }
        /* a near-straight curve whose representation's curvature is not its own (below) */
        if (i >= nsolver && s.residual <= opt->tol && el__hermite_near_check(&fr, &roots.v[i].st, &s)) {
            if (near_u == (size_t)-1) unrep[near_u = nunrep++] = s;
            continue;
        }
        if (!(s.residual <= opt->tol)) continue;
        /* a near-straight root whose chain's correction wandered to another curve */
        if (i >= nsolver && !(fabs(s.length - roots.v[i].st.L * fr.d) <= 1e-6 * fr.d)) continue;
        near_found |= i >= nsolver;
        /* a near-straight curve's energy from its parameters: the root's state loses it to
         * cancellation (tangents 1e-4 rad off the chord at sigma |p1 - p0|^2 = 7.3: 2e-5 of
         * it, 7.5e-5 where polished); its few ulps elsewhere are kept as they are */
        if (s.npieces == 1 && s.energy * fr.d < 1e-2 && el_smooth_energy(&s.curve, &s.energy)) continue;
        int dup = 0;
        for (size_t j = 0; j < n && !dup; j++) {
            /* (a near-straight root's: the one near-straight curve, told by its length where a
             * chain's end curvatures are ~1e-3 off a single piece's: tangents 1e-3 rad off the
             * chord, parallel, sigma |p1 - p0|^2 = 60: listed twice, the chain's curvature
             * jumping by 3e-3 of its largest at its joint) */
            if (el__hermite_same_solution(&s, &sol[j], fr.d) ||
                (i >= nsolver && fabs(s.length - sol[j].length) <= 1e-6 * fr.d)) {
                dup = 1;
                /* a near-straight root replaces the roots' curve only where that one's
                 * curvature is not the curve's (el__hermite_near_check) */
                if (i < nsolver) {
                    if (s.residual < sol[j].residual) sol[j] = s;
                } else {
                    el_hermite_solution t = sol[j];
                    if (el__hermite_near_check(&fr, &roots.v[i].st, &t)) sol[j] = s;
                }
            }
        }
        if (!dup) sol[n++] = s;
    }
    free(roots.v);
    if (near_found && near_u != (size_t)-1) { unrep[near_u] = unrep[--nunrep]; near_u = (size_t)-1; }
    size_t nu = (size_t)circle_unrep;
    if (near_ok && (nearly.residual <= opt->tol || near_unrep)) {
        int dup = 0;
        /* (the one near-straight curve: told by its length too, as the near roots' above) */
        for (size_t j = 0; j < n && !dup; j++)
            dup = el__hermite_same_solution(&nearly, &sol[j], fr.d) ||
                  fabs(nearly.length - sol[j].length) <= 1e-6 * fr.d;
        /* (counted once: a near-straight root's curve can be counted below too) */
        /* (no curve is shorter than its chord: a root that says so is the near-straight
         * curve's, its length the x chart's rounding: tangents 8e-8 and -4e-8 rad off the
         * chord at sigma |p1 - p0|^2 = 6.9, L = 0.993 |p1 - p0|) */
        for (size_t j = 0; j < nunrep && !dup && near_unrep; j++)
            dup = el__hermite_same_solution(&nearly, &unrep[j], fr.d) ||
                  fabs(nearly.length - unrep[j].length) <= 1e-6 * fr.d || unrep[j].length < fr.d;
        if (!dup && near_unrep) {
            nu++;
        } else if (!dup) {
            if (n == cap) {
                el_hermite_solution *more = realloc(sol, (cap + 1) * sizeof *sol);
                if (!more) { free(sol); if (unrep != ubuf) free(unrep); return EL_ENOMEM; }
                sol = more;
                cap++;
            }
            sol[n++] = nearly;
        }
    }
    /* next to case 3 (P2 = V1 = 0: the U-turn), where the x chart's solutions crowd into
     * O(|P2|) of the case's four kappa0 (hermite_case3.c) */
    if (fabs(pr.P2) <= EL__HERMITE_CASE3_NEAR && fabs(pr.V1) <= EL__HERMITE_CASE3_NEAR && pr.hcase != 3) {
        const int c3 = el__hermite_near_case3(&fr, u0, &pr, opt, max_evals, &sol, &n, &cap);
        if (c3 == EL_ENOMEM) {
            if (unrep != ubuf) free(unrep);
            return EL_ENOMEM;
        }
        if (c3 == EL_EMAXITER) status = EL_EMAXITER;   /* the case-3 curves' search incomplete */
    }
    /* between tangents along the chord, the separatrix loops the roots cannot see (hermite_chord.c) */
    const size_t nroot_unrep = nunrep;   /* (the chord loops' from here on) */
    if (el__hermite_chord_loops(&fr, &pr, opt, &sol, &n, &cap, unrep, &nunrep)) {
        if (unrep != ubuf) free(unrep);
        return EL_ENOMEM;
    }
    if (el__hermite_add_images(&fr, opt, Ln, &sol, &n, &cap)) {
        if (unrep != ubuf) free(unrep);
        return EL_ENOMEM;
    }
    /* each unrepresentable curve once, and not when another root of it was representable */
    for (size_t i = 0; i < nunrep; i++) {
        int dup = 0;
        /* a chord loop's (hermite_chord.c: the closed form) against the list completed by the
         * images: the tracer's chain of one side, its mirror added by el__hermite_add_images
         * after the chord loops were counted (L 1.1 |p1 - p0| at a = -2.5, d = 1e-3: the other
         * side counted beside its returned chain) */
        for (size_t j = 0; j < n && !dup; j++)
            dup = i >= nroot_unrep ? el__hermite_same_loop(&unrep[i], &sol[j], fr.d)
                                   : el__hermite_same_solution(&unrep[i], &sol[j], fr.d);
        /* the near-straight root's: the one near-straight curve (the linear beam's is unique),
         * returned by the roots as one piece, where its own representation (a chain whose
         * pieces' phi disagree, hermite_chain.c) was refused: its length (the root's, exact)
         * tells it, not its end curvatures (the refused chain's) */
        for (size_t j = 0; j < n && !dup && i == near_u; j++)
            dup = fabs(sol[j].length - unrep[i].length) <= 1e-6 * fr.d;
        /* (one curve's two representations: a root's, its end curvatures the rounding of its
         * far tails, and the chord loops' closed form that replaced another root's entry: L 1.113
         * |p1 - p0| on the chord, both loops counted besides a root's ccw one, 3 for 2); not
         * across the separatrix (|k| above 1 and below: two loops of one sense or of both, the
         * same length and energy to 1e-7 at sigma d^2 33 331) */
        for (size_t j = 0; j < i && !dup; j++)
            dup = el__hermite_same_solution(&unrep[i], &unrep[j], fr.d) ||
                  (el__hermite_same_loop(&unrep[i], &unrep[j], fr.d) &&
                   !((fabs(unrep[i].curve.k) - 1.0) * (fabs(unrep[j].curve.k) - 1.0) < 0.0));
        nu += !dup;
    }
    if (unrep != ubuf) free(unrep);
    for (size_t i = 0; i < n; i++)          /* p0 back into every piece (fr has p0 = 0) */
        for (int j = 0; j < sol[i].npieces; j++) {
            el_smooth_params *pc = j ? &sol[i].rest[j - 1] : &sol[i].curve;
            pc->x0 += p0[0];
            pc->y0 += p0[1];
        }
    /* by energy: insertion sort, stable as glibc's qsort (a merge sort) on the same
     * comparison; the lists are a few solutions long (qsort's indirect calls and
     * buffer cost more than the sort) */
    for (size_t i = 1; i < n; i++) {
        const el_hermite_solution t = sol[i];
        size_t j = i;
        for (; j > 0 && cmp_energy(&sol[j - 1], &t) > 0; j--) sol[j] = sol[j - 1];
        sol[j] = t;
    }
    if (n > opt->max_solutions) n = opt->max_solutions;
    if (n == 0) { free(sol); sol = NULL; }
    res->count = n;
    res->solutions = sol;
    res->unrepresentable = nu;
    return status;
}

int el_hermite_solve_into(const double p0[2], const double t0[2], const double p1[2],
                          const double t1[2], const el_hermite_options *opt,
                          el_hermite_solution *solutions, size_t cap, size_t *count,
                          size_t *unrepresentable)
{
    if (!count || !unrepresentable || (cap > 0 && !solutions)) return EL_EINVAL;
    el_hermite_result res;
    const int status = el_hermite_solve(p0, t0, p1, t1, opt, &res);
    if (status == EL_EINVAL) return status;   /* res untouched */
    const size_t n = res.count < cap ? res.count : cap;
    if (n > 0) memcpy(solutions, res.solutions, n * sizeof *solutions);
    *count = res.count;
    *unrepresentable = res.unrepresentable;
    el_hermite_result_free(&res);
    return status;
}
