/*
 * Hermite solutions the problem's symmetries give (el_hermite_solve's last step): the images
 * of every solution found under the isometries that map the end data to themselves, and in
 * length mode between parallel tangents the curves one whole curvature period long. Both
 * lie where the searches (hermite_tension.c, hermite_length.c) are least sure: an image
 * pair whose one curve has exactly one period, so that rounding keeps one and drops the
 * other, and the pitchfork where the buckled branches leave the straight curve.
 */
#include "hermite_internal.h"
#include <gsl/gsl_math.h>
#include <stdlib.h>
#include <string.h>

/* The problem's symmetries: isometries that map the end data to themselves once the image
 * curve is traversed from p0 (the solution set, curves of at most one curvature period, is
 * closed under each: the period is a function of |kappa|):
 *   SYM_CHORD  the mirror in the chord, t0 and t1 along it;
 *   SYM_BISECT the mirror in the chord's perpendicular bisector with the curve reversed,
 *              t1 the mirror image of t0 in the chord;
 *   SYM_TURN   their product, the half turn about the chord's midpoint with the curve
 *              reversed, t1 = t0.
 * Tested to SYM_TOL rad: the solutions a whole period long (the buckled batten between
 * collinear tangents, the loop between parallel ones) lie where one of an image pair has
 * exactly one period, so that rounding kept one of them and dropped the other (QA: length 3
 * between (0, 0) and (2, 0), tangents (1, 0): the loop above the chord, not below). */
#define SYM_TOL 1e-14
enum { SYM_CHORD = 1, SYM_BISECT = 2, SYM_TURN = 4 };

static int symmetries(const hframe *fr)
{
    const double c = atan2(fr->p1[1] - fr->p0[1], fr->p1[0] - fr->p0[0]);
    const double a0 = el__hermite_wrap_pi(fr->psi0 - c), a1 = el__hermite_wrap_pi(fr->psi1 - c);
    int sym = 0;
    if (fabs(el__hermite_wrap_pi(2.0 * a0)) <= SYM_TOL &&
        fabs(el__hermite_wrap_pi(2.0 * a1)) <= SYM_TOL)
        sym |= SYM_CHORD;
    if (fabs(el__hermite_wrap_pi(a0 + a1)) <= SYM_TOL) sym |= SYM_BISECT;
    if (fabs(el__hermite_wrap_pi(a1 - a0)) <= SYM_TOL) sym |= SYM_TURN;
    return sym;
}

/* m + R (x - m), R the mirror in the line at angle c. */
static void mirror_point(const double m[2], double c, double x[2])
{
    const double a = x[0] - m[0], b = x[1] - m[1], c2 = cos(2.0 * c), s2 = sin(2.0 * c);
    x[0] = m[0] + c2 * a + s2 * b;
    x[1] = m[1] + s2 * a - c2 * b;
}

/* The image of the solution s under the symmetry `which`, with its residual (a chain's
 * its own: el__hermite_residual() measures one piece), exactly in the parameters. With
 * sin((theta - phi) / 2) = k sn(u; |k|), u = sqrt(mu) s + q
 * (el__hermite_params_from_state), -k mirrors
 * a piece in the line through its start along F: the mirror at angle c takes (start, phi,
 * k) to (R start, 2 c - phi, -k). The reversal x(L - s) has T -> -T, kappa -> -kappa,
 * kappa' -> kappa', so F -> -F (8): phi + pi, u -> -u, q -> -(sqrt(mu) L + q) (cn even, sn
 * odd), and k -> -k; with the mirror's, k is kept. Reversed images of one piece only: a
 * chain's reversal splits elsewhere, and el__hermite_same_solution (first pieces) would
 * keep it beside
 * the chain it repeats (10 such in test_hermite_symmetry.c). */
static int image_solution(const hframe *fr, const el_hermite_solution *s, int which,
                          el_hermite_solution *t)
{
    const double c = atan2(fr->p1[1] - fr->p0[1], fr->p1[0] - fr->p0[0]);
    const double mid[2] = {0.5 * (fr->p0[0] + fr->p1[0]), 0.5 * (fr->p0[1] + fr->p1[1])};
    *t = *s;
    if (which & (SYM_BISECT | SYM_TURN)) {
        if (s->npieces != 1) return EL_EDOM;
        double e[2];
        const int rc = el_smooth_eval(&s->curve, 1, &s->curve.length, e, NULL, NULL);
        if (rc) return rc;
        mirror_point(mid, c + M_PI_2, e);
        t->curve.x0 = e[0];
        t->curve.y0 = e[1];
        t->curve.phi = 2.0 * (c + M_PI_2) - s->curve.phi - M_PI;
        t->curve.q = -(sqrt(s->curve.mu) * s->curve.length + s->curve.q);
        t->kappa0 = s->kappa1;
        t->kappa1 = s->kappa0;
    }
    if (which & (SYM_CHORD | SYM_TURN)) {
        for (int i = 0; i < t->npieces; i++) {
            el_smooth_params *q = i ? &t->rest[i - 1] : &t->curve;
            double x[2] = {q->x0, q->y0};
            mirror_point(fr->p0, c, x);
            q->x0 = x[0];
            q->y0 = x[1];
            q->phi = 2.0 * c - q->phi;
            q->k = -q->k;
        }
        t->kappa0 = -t->kappa0;
        t->kappa1 = -t->kappa1;
    }
    return s->npieces == 1 ? el__hermite_residual(fr, t, &t->residual) : EL_OK;
}

/* Length mode, t1 = t0 (SYM_TURN): the inflectional curves one whole period long, F along
 * the chord. Between tangents along the chord these are the buckled branches of the
 * straight solution's pitchfork: along kappa = 0 the linearised 2 kappa'' = sigma kappa
 * (seed 004's curvature equation) with theta(0) = theta(d) = 0 and int theta = 0 has
 * theta = sin(2 pi s / d) at sigma d^2 = -8 pi^2 (the next mode, tan(w d / 2) = w d / 2,
 * spans 1.43 periods), and the branch is this family with L -> d (test_hermite_symmetry.c).
 * The tracer loses them near L = d, where C meets the singular state kappa = 0 (length
 * 1 + 5e-8 chords: none; tangents 1e-6 rad off the chord, parallel: none up to 1.0005).
 * theta - phi = 2 asin(k sn u), L = 4 K / sqrt(mu): over u in [u0, u0 + 4 K] the end moves
 * along F by int (2 dn^2 - 1) ds = L (2 E / K - 1). With F along dir (+-1) times the chord,
 * 2 m D(m) / K(m) = 1 - dir d / L (K - E = m D), increasing from 0 to 2 over m = k^2 in
 * (0, 1): bisection to the last bit. The start phase: sn u0 = sin(a / 2) / k, a = theta0 -
 * phi in (-pi, pi] (dn u0 = cos(a / 2) >= 0), cn u0 of either sign, kappa0 = kappa_m cn u0,
 * kappa0' = mu sin(phi - theta0) ((8), |F| = 2 mu). Up to 4 into w; their count. */
static int whole_period_solutions(const hframe *fr, double L, el_hermite_solution w[4])
{
    const double c = atan2(fr->p1[1] - fr->p0[1], fr->p1[0] - fr->p0[0]);
    int n = 0;
    for (int dir = 1; dir >= -1; dir -= 2) {
        const double tau = (L - dir * fr->d) / L;
        double lo = 0.0, hi = 1.0, K, D;
        for (;;) {
            const double m = 0.5 * (lo + hi);
            if (!(m > lo && m < hi)) break;
            if (el__ellint_complete(sqrt(m), 1.0 - m, &K, &D)) return n;
            if (2.0 * m * D / K < tau) lo = m; else hi = m;
        }
        if (!(hi < 1.0) || el__ellint_complete(sqrt(hi), 1.0 - hi, &K, NULL)) continue;
        const double k = sqrt(hi), mu = (4.0 * K / L) * (4.0 * K / L), phi = dir > 0 ? c : c + M_PI;
        const double sn0 = sin(0.5 * el__hermite_wrap_pi(fr->psi0 - phi)) / k;
        if (!(fabs(sn0) <= 1.0)) continue;
        const double cn0 = sqrt((1.0 - sn0) * (1.0 + sn0)), sigma = 2.0 * mu * (2.0 * hi - 1.0);
        for (int sg = 1; sg >= -1 && !(sg < 0 && cn0 == 0.0); sg -= 2) {
            el_hermite_solution *s = &w[n];
            memset(s, 0, sizeof *s);
            s->npieces = 1;
            s->length = L;
            s->sigma = sigma;
            s->kappa0 = s->kappa1 = sg * 2.0 * k * sqrt(mu) * cn0;
            s->has_inflection = 1;
            if (!el__hermite_params_from_state(fr->p0[0], fr->p0[1], fr->psi0, s->kappa0,
                                               mu * sin(phi - fr->psi0), sigma, L, NULL,
                                               &s->curve) &&
                !el_smooth_energy(&s->curve, &s->energy) &&
                !el__hermite_residual(fr, s, &s->residual))
                n++;
        }
    }
    return n;
}

/* s appended to the list (*sol, *n, capacity *cap) unless it misses the end conditions
 * (opt->tol) or is there already (el__hermite_same_solution); the list doubled when full.
 * EL_ENOMEM (the list freed) where it cannot grow. */
static int add_new(const hframe *fr, const el_hermite_options *opt, const el_hermite_solution *s,
                   el_hermite_solution **sol, size_t *n, size_t *cap)
{
    if (!(s->residual <= opt->tol)) return EL_OK;
    for (size_t j = 0; j < *n; j++)
        if (el__hermite_same_solution(s, &(*sol)[j], fr->d)) return EL_OK;
    if (*n == *cap) {
        el_hermite_solution *more = realloc(*sol, 2 * *cap * sizeof *more);
        if (!more) { free(*sol); *sol = NULL; return EL_ENOMEM; }
        *sol = more;
        *cap *= 2;
    }
    (*sol)[(*n)++] = *s;
    return EL_OK;
}

/* el_hermite_solve's list (*sol, *n, capacity *cap) closed under the problem's symmetries
 * (symmetries): the whole-period curves of length mode between parallel tangents (Ln: the
 * length over the chord) and each image not found, images of images too (the list grows as
 * it is read); each added once (add_new). EL_ENOMEM, the list freed, where it cannot grow. */
int el__hermite_add_images(const hframe *fr, const el_hermite_options *opt, double Ln,
                           el_hermite_solution **sol, size_t *n, size_t *cap)
{
    const int sym = symmetries(fr);
    el_hermite_solution w[4], t;
    const int nw = opt->mode == EL_HERMITE_LENGTH && Ln > 1.0 + 1e-12 && (sym & SYM_TURN)
                   ? whole_period_solutions(fr, opt->length, w) : 0;
    for (int i = 0; i < nw; i++)
        if (add_new(fr, opt, &w[i], sol, n, cap)) return EL_ENOMEM;
    for (size_t i = 0; sym && i < *n; i++)
        for (int which = SYM_CHORD; which <= SYM_TURN; which *= 2)
            if ((sym & which) && (*sol)[i].curve.k != 0.0 &&
                !image_solution(fr, &(*sol)[i], which, &t) && add_new(fr, opt, &t, sol, n, cap))
                return EL_ENOMEM;
    return EL_OK;
}
