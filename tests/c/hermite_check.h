/* The checks every Hermite test applies to a returned curve: measured with the
 * evaluator of smooth.c (ends, tangents, energy, curvatures, inflections, chains' joins),
 * for test_hermite.c and test_hermite_edge.c. */
#ifndef EL_HERMITE_CHECK_H
#define EL_HERMITE_CHECK_H

#include "testutil.h"
#include <math.h>

static double wrap(double a)
{
    a = fmod(a, 2.0 * M_PI);
    if (a > M_PI) a -= 2.0 * M_PI;
    if (a < -M_PI) a += 2.0 * M_PI;
    return a;
}

/* The pieces of a solution: curve, then rest[0..npieces-2]. */
static int pieces_of(const el_hermite_solution *s, const el_smooth_params **p)
{
    ck_assert_msg(s->npieces >= 1 && s->npieces <= 3, "npieces %d", s->npieces);
    p[0] = &s->curve;
    for (int i = 1; i < s->npieces; i++) p[i] = &s->rest[i - 1];
    for (int i = s->npieces; i < 3; i++) ck_assert(s->rest[i - 1].length == 0.0);
    return s->npieces;
}

/* Both ends met in the direction p0 -> p1 (position / |p1 - p0| and tangent
 * angle to tol), the orientation in the sign of k (a loop, |k| > 1, turns with
 * the sign of k), energy by el_smooth_energy, has_inflection by sampled
 * curvature, length = the sum of the pieces'. A chain's pieces follow each other
 * (position and tangent to 1e-12) and are the same elastica: the solution's tension
 * and the same |F| = 2 mu in every piece, force directions phi equal (mod 2 pi) and
 * curvature continuous to 1e-7 of the largest, or to 1e-8 of kappa_m = 2 |k| sqrt(mu)
 * (the loops' peak; el_hermite_solve's bound, what the doubles' k allow, hermite_chain.c)
 * on a near-straight chain, whose largest curvature ~k' kappa_m is no scale for it: a
 * chain between parallel tangents 1e-6 rad off the chord at sigma |p1 - p0|^2 = 35
 * jumps by 3e-4 of its own (2.9e-10 of kappa_m), its G2 chain lies 2.5 times further
 * from the exact curve in kappa0, 6 times in position (90 digits). */
static void check_solution(const double p0[2], const double t0[2], const double p1[2],
                           const double t1[2], const el_hermite_solution *s, double tol)
{
    const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    const double ta = atan2(t0[1], t0[0]), tb = atan2(t1[1], t1[0]);
    const el_smooth_params *pc[3];
    const int n = pieces_of(s, pc);
    double Lsum = 0.0, E = 0.0, xy[4], th[2], kap[2], prev[3] = {p0[0], p0[1], ta}, kprev = 0.0;
    double kend[3][2];
    for (int i = 0; i < n; i++) {
        ck_assert_int_eq(el_smooth_check(pc[i]), EL_OK);
        ck_assert(pc[i]->length > 0.0);
        const double sv[2] = {0.0, pc[i]->length};
        ck_assert_int_eq(el_smooth_eval(pc[i], 2, sv, xy, th, kap), EL_OK);
        const double gap = hypot(xy[0] - prev[0], xy[1] - prev[1]), turn = fabs(wrap(th[0] - prev[2]));
        if (i == 0) {
            ck_assert_msg(gap <= tol * d, "start point off by %g", gap);
            ck_assert_msg(turn <= tol, "start tangent off by %g", turn);
        } else {
            ck_assert_msg(gap <= 1e-12 * d && turn <= 1e-12, "joint %d: gap %g, turn %g", i, gap, turn);
            /* the same elastica: tension, |F| and its direction */
            const double si = 2.0 * pc[i]->mu * (2.0 * pc[i]->k * pc[i]->k - 1.0);
            ck_assert_close(si, s->sigma, 1e-12 * fabs(s->sigma));
            ck_assert_close(pc[i]->mu, pc[0]->mu, 1e-12 * pc[0]->mu);
            ck_assert_msg(fabs(wrap(pc[i]->phi - pc[0]->phi)) <= 1e-7, "joint %d: phi %.17g, %.17g", i,
                          pc[i]->phi, pc[0]->phi);
            kend[i - 1][1] = kap[0];
            kend[i - 1][0] = kprev;
        }
        prev[0] = xy[2]; prev[1] = xy[3]; prev[2] = th[1];
        kprev = kap[1];
        if (i == 0) ck_assert_close(kap[0], s->kappa0, fmax(1e-8, 100.0 * tol) * (1.0 + fabs(kap[0])));
        double e;
        ck_assert_int_eq(el_smooth_energy(pc[i], &e), EL_OK);
        E += e;
        Lsum += pc[i]->length;
    }
    ck_assert_msg(hypot(prev[0] - p1[0], prev[1] - p1[1]) <= tol * d, "end point off by %g (k %g, %d pieces)",
                  hypot(prev[0] - p1[0], prev[1] - p1[1]), s->curve.k, n);
    ck_assert_msg(fabs(wrap(prev[2] - tb)) <= tol, "end tangent off by %g", wrap(prev[2] - tb));
    ck_assert_close(Lsum, s->length, 1e-14 * s->length);
    if (n == 1) ck_assert_close(s->curve.length, s->length, 0.0);
    /* the end curvatures as reported, to 1e-8 (relative; looser with a looser tol) */
    const double ktol = fmax(1e-8, 100.0 * tol);
    ck_assert_close(kprev, s->kappa1, ktol * (1.0 + fabs(kprev)));
    ck_assert_close(E, s->energy, ktol * (1.0 + E));
    /* inflection: sign change of kappa on a fine grid of every piece; a loop's
     * curvature has the sign of k everywhere */
    enum { NS = 2001 };
    static double ss[NS], kk[3][NS];
    double kmax = 0.0, km = 0.0;
    for (int i = 0; i < n; i++) {
        km = fmax(km, 2.0 * fabs(pc[i]->k) * sqrt(pc[i]->mu));
        for (int j = 0; j < NS; j++) ss[j] = pc[i]->length * j / (NS - 1);
        ck_assert_int_eq(el_smooth_eval(pc[i], NS, ss, NULL, NULL, kk[i]), EL_OK);
        for (int j = 0; j < NS; j++) kmax = fmax(kmax, fabs(kk[i][j]));
        if (fabs(pc[i]->k) > 1.0) {
            ck_assert_msg(pc[i]->k * kk[i][0] > 0.0 && pc[i]->k * kk[i][NS - 1] > 0.0,
                          "loop k %g with kappa0 %g, kappa1 %g", pc[i]->k, kk[i][0], kk[i][NS - 1]);
            ck_assert_int_eq(s->has_inflection, 0);
        }
    }
    for (int i = 0; i + 1 < n; i++)
        ck_assert_msg(fabs(kend[i][0] - kend[i][1]) <= fmax(1e-7 * kmax, 1e-8 * km),
                      "joint %d: curvature %g, %g (max %g, kappa_m %g)", i + 1, kend[i][0], kend[i][1], kmax, km);
    int change = 0;
    double last = 0.0; /* sign changes among the samples that are not ~0 (ends may be zeros) */
    for (int i = 0; i < n; i++)
        for (int j = 0; j < NS; j++) {
            if (fabs(kk[i][j]) <= 1e-7 * kmax) continue;
            if (last * kk[i][j] < 0.0) change = 1;
            last = kk[i][j];
        }
    ck_assert_msg(change == s->has_inflection, "has_inflection %d, sampled %d (k %g, L %g, kappa0 %g, kappa1 %g)",
                  s->has_inflection, change, s->curve.k, s->length, s->kappa0, s->kappa1);
}

static void check_result(const double p0[2], const double t0[2], const double p1[2],
                         const double t1[2], const el_hermite_result *r, double tol)
{
    for (size_t i = 0; i < r->count; i++) {
        check_solution(p0, t0, p1, t1, &r->solutions[i], tol);
        if (i > 0) ck_assert(r->solutions[i - 1].energy <= r->solutions[i].energy);
    }
}

#endif
