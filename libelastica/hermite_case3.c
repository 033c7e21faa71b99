/*
 * Hermite solutions next to case 3 of seed 004's Theorem 6 (P2 = V1 = 0 in the normalised
 * frame: p1 - p0 across t0 and t1 along +-t0, the U-turn and its parallel twin).
 *
 * Case 1 takes kappa0 as its unknown x and reads kappa1 from (19) and kappa0' from (20),
 * both over P2 (or (15) over 2 V1). As P2, V1 -> 0 every solution's kappa0 tends to one of
 * case 3's four values (24), kappa0^2 = sigma or (P1 kappa0 + 2)^2 = sigma P1^2 + 4 V2, while
 * its kappa0' stays O(1): the solutions crowd into x-windows O(|P2| + |V1|) wide, across
 * which the objective sweeps O(1), and the bracketing's samples (12 over the whole interval)
 * step over them. QA21 F1: the U-turn p0 (0, 0) t0 (0, 1), p1 (1, 0) t1 (0, -1) at tension
 * 5 has 4 solutions; p1 moved by 1e-12, or t0 turned by 1e-12 rad, 0, silently; 1e-8: 1 or
 * 2; the same U-turn rotated by 0.5 rad and shifted by (3000, -2100), whose rounding is such
 * a move, 0 at every scale.
 *
 * Case 3's own chart (x = kappa0', kappa0 fixed by the family) is regular there. So within
 * max(|P2|, |V1|) <= EL__HERMITE_CASE3_NEAR the case-3 problem of the same p0, t0, |p1 - p0|
 * and mode (p1 moved onto the line across t0, t1 turned onto +-t0) is solved too, and each of
 * its curves is polished onto the true data (hermite.c's Newton on the curve's parameters,
 * from a start O(|P2| + |V1|) off): continuous in the data, as the solutions are where they
 * are simple (implicit function theorem), and accepted only at the true data's residual <=
 * tol and within one curvature period (the solution set's bound; a whole-period curve of the
 * case-3 problem moves past it on one side). The general path's solutions stay as they are
 * (a curve found by both is the general path's, el__hermite_same_solution).
 * Not covered: a case-3 curve at the separatrix (|k| within ~1e-5 of 1: a chain of pieces,
 * or a piece the polish cannot move onto the data), met in length mode below ~1.25 |p1 - p0|
 * (QA21's tight U): such a curve is still lost where the general path misses it (24 of 1502
 * random U-turns moved by 1e-14 .. 3e-3, all length mode).
 */
#include "hermite_internal.h"
#include <stdlib.h>

/* 1 where el_hermite_solve takes the data (0, 0) t0, p1, t1 for case 3 itself (its own
 * el__hermite_unit and el__hermite_normalise, hermite.c): the inner solve below then does not
 * come here again (hermite.c steps here only at hcase != 3) */
static int solved_as_case3(const double t0[2], const double p1[2], const double t1[2])
{
    const double z[2] = {0.0, 0.0};
    double u0[2], u1[2];
    hframe fr;
    hprob pr;
    if (el__hermite_unit(t0, u0) || el__hermite_unit(t1, u1) || el__hermite_normalise(z, u0, p1, u1, &fr, &pr))
        return 0;
    return pr.hcase == 3;
}

int el__hermite_near_case3(const hframe *fr, const double u0[2], const hprob *pr,
                           const el_hermite_options *opt, long max_evals, el_hermite_solution **sol,
                           size_t *n, size_t *cap)
{
    /* the case-3 data in the frame of fr (p0 = 0): the normalised frame's (+-1, 0) is
     * d (t0_y, -t0_x) in the world's, its (0, +-1) +-t0 */
    const double z[2] = {0.0, 0.0}, s1 = pr->P1 > 0.0 ? 1.0 : -1.0, s2 = pr->V2 > 0.0 ? 1.0 : -1.0;
    const double q1[2] = {s1 * fr->d * u0[1], -s1 * fr->d * u0[0]}, v1[2] = {s2 * u0[0], s2 * u0[1]};
    /* the inner problem is case 3 by construction (its P2, V1 round to ~1e-16, set_case's
     * threshold 1e-13): checked, so that no change to either recurses without bound through
     * the public entry; where it is not, none to add */
    if (!solved_as_case3(u0, q1, v1)) return EL_OK;
    el_hermite_result r3;
    const int rc = el__hermite_solve_limited(z, u0, q1, v1, opt, max_evals, &r3);
    if (rc == EL_ENOMEM) { free(*sol); *sol = NULL; return EL_ENOMEM; }
    /* none to add (the general path's stand); an incomplete inner solve (EL_EMAXITER, its
     * solutions so far) is used as it is, and said: the outer result is incomplete too (it
     * was returned as complete, EL_OK, whatever the inner solve had left out) */
    if (rc && rc != EL_EMAXITER) return EL_OK;
    const double target = opt->mode == EL_HERMITE_TENSION ? opt->sigma : opt->length;
    int status = EL_OK;
    for (size_t i = 0; i < r3.count && !status; i++) {
        el_hermite_solution t = r3.solutions[i];
        /* a chain's pieces are polished by no one here (hermite_chain.c's own correction) */
        if (t.npieces != 1 || el__hermite_residual(fr, &t, &t.residual)) continue;
        if (el__hermite_polish_to(fr, opt->mode, target, opt->tol, &t)) continue;
        if (!(t.residual <= opt->tol) || !el__hermite_within_period(&t.curve, 0)) continue;
        if (opt->mode == EL_HERMITE_TENSION) t.sigma = opt->sigma;
        int dup = 0;
        for (size_t j = 0; j < *n && !dup; j++) dup = el__hermite_same_solution(&t, &(*sol)[j], fr->d);
        if (dup) continue;
        if (*n == *cap) {
            el_hermite_solution *more = realloc(*sol, 2 * (*cap + 1) * sizeof *more);
            if (!more) { free(*sol); *sol = NULL; status = EL_ENOMEM; break; }
            *sol = more;
            *cap = 2 * (*cap + 1);
        }
        (*sol)[(*n)++] = t;
    }
    el_hermite_result_free(&r3);
    return status ? status : rc;
}
