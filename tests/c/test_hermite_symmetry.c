/* Hermite interpolation on problems with a symmetry (hermite.c, symmetries): every
 * solution's image is a solution too (the solution set, curves of at most one curvature
 * period, is closed under an isometry mapping the end data to themselves: the period
 * depends on |kappa| alone), so the returned set must be closed under it, in both modes.
 * The images are formed from sampled points (el_smooth_eval), not from the solver's
 * states: the chord's mirror R_c x; the perpendicular bisector's mirror R_b of the
 * reversed curve, R_b x(L - s); the half turn p0 + p1 - x(L - s). And the pitchfork of
 * the straight batten: its buckled pair at sigma |p1 - p0|^2 -> -8 pi^2 as L -> |p1 - p0|. */
#include "testutil.h"
#include "hermite_check.h"
#include <stdio.h>

#define NS 41
enum { IM_CHORD, IM_BISECT, IM_TURN };

/* NS points of a solution (its pieces in order) at equal arc-length steps. */
static void sample(const el_hermite_solution *s, double xy[2 * NS])
{
    const el_smooth_params *pc[3];
    const int np = pieces_of(s, pc);
    for (int i = 0; i < NS; i++) {
        double t = s->length * i / (NS - 1);
        int j = 0;
        while (j + 1 < np && t > pc[j]->length) t -= pc[j++]->length;
        ck_assert_int_eq(el_smooth_eval(pc[j], 1, &t, &xy[2 * i], NULL, NULL), EL_OK);
    }
}

/* The image of the points under `im` for ends p0, p1. */
static void image(int im, const double p0[2], const double p1[2], const double xy[2 * NS],
                  double out[2 * NS])
{
    const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    const double u[2] = {(p1[0] - p0[0]) / d, (p1[1] - p0[1]) / d};
    const double m[2] = {0.5 * (p0[0] + p1[0]), 0.5 * (p0[1] + p1[1])};
    for (int i = 0; i < NS; i++) {
        const double *x = &xy[2 * (im == IM_CHORD ? i : NS - 1 - i)];
        const double a = (x[0] - m[0]) * u[0] + (x[1] - m[1]) * u[1];
        const double b = -(x[0] - m[0]) * u[1] + (x[1] - m[1]) * u[0];
        const double a2 = im == IM_BISECT ? -a : im == IM_TURN ? -a : a;
        const double b2 = im == IM_CHORD ? -b : im == IM_TURN ? -b : b;
        out[2 * i] = m[0] + a2 * u[0] - b2 * u[1];
        out[2 * i + 1] = m[1] + a2 * u[1] + b2 * u[0];
    }
}

/* Solve, check every solution (ends, tangents, length or tension: hermite_check.h), and
 * that each solution's image under every symmetry in ims (bit IM_*) is in the set (its
 * points within 1e-6 |p1 - p0|); the number of solutions. */
static size_t solve_closed(const double p0[2], const double t0[2], const double p1[2],
                           const double t1[2], const el_hermite_options *o, int ims)
{
    el_hermite_result r;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, o, &r), EL_OK);
    check_result(p0, t0, p1, t1, &r, o->tol);
    const double d = hypot(p1[0] - p0[0], p1[1] - p0[1]);
    double (*xy)[2 * NS] = malloc((r.count + 1) * sizeof *xy), im[2 * NS];
    ck_assert_ptr_nonnull(xy);
    for (size_t i = 0; i < r.count; i++) {
        const el_hermite_solution *s = &r.solutions[i];
        if (o->mode == EL_HERMITE_LENGTH)
            ck_assert(fabs(s->length - o->length) <= 1e-12 * o->length);
        sample(s, xy[i]);
    }
    for (size_t i = 0; i < r.count; i++) {
        for (int k = IM_CHORD; k <= IM_TURN; k++) {
            /* at the separatrix (|k| = 1) between tangents along the chord the loop slides
             * along straight arms whose curvature is below rounding: a continuum, one
             * member of which the solver returns; its reversed images are others */
            if (!(ims & (1 << k)) || (k != IM_CHORD && fabs(r.solutions[i].curve.k) == 1.0))
                continue;
            image(k, p0, p1, xy[i], im);
            int found = 0;
            for (size_t j = 0; j < r.count && !found; j++) {
                double e = 0.0;
                for (int q = 0; q < 2 * NS; q++) e = fmax(e, fabs(xy[j][q] - im[q]));
                found = e <= 1e-6 * d;
            }
            ck_assert_msg(found, "image %d of solution %zu of %zu missing (%s %g, t0 (%g, %g), "
                          "t1 (%g, %g), energy %.6g, kappa0 %.6g)", k, i, r.count,
                          o->mode == EL_HERMITE_LENGTH ? "length" : "tension",
                          o->mode == EL_HERMITE_LENGTH ? o->length : o->sigma, t0[0], t0[1],
                          t1[0], t1[1], r.solutions[i].energy, r.solutions[i].kappa0);
        }
    }
    free(xy);
    const size_t n = r.count;
    el_hermite_result_free(&r);
    return n;
}

/* End data in the frame of the chord (p0 + d R(beta) (0, 0) -> (1, 0)) with the tangents
 * at angles a0, a1 to it. */
typedef struct { double p0[2], p1[2], t0[2], t1[2]; } ends;
static ends frame(double beta, double d, double a0, double a1)
{
    ends e = {{0.3, -1.7}, {0.0, 0.0}, {cos(beta + a0), sin(beta + a0)},
              {cos(beta + a1), sin(beta + a1)}};
    e.p1[0] = e.p0[0] + d * cos(beta);
    e.p1[1] = e.p0[1] + d * sin(beta);
    return e;
}

/* The tangent pairs of the test: collinear ones (the chord's mirror; parallel ones the
 * half turn, and with it the bisector's), and with either of the other two alone; buckles:
 * at least the buckled batten's pair at every length (parallel, within 1e-6 rad of the
 * chord: the whole period from sn u0 = sin(a / 2) / k, k ~ sqrt(L / d - 1)). */
static const struct { double a0, a1; int ims, buckles; } pairs[] = {
    {0.0, 0.0, 7, 1}, {M_PI, M_PI, 7, 0}, {0.0, M_PI, 1, 0}, {M_PI, 0.0, 1, 0},
    {0.3, -0.3, 2, 0}, {1.2, -1.2, 2, 0}, {2.5, -2.5, 2, 0}, {0.4, 0.4, 4, 0}, {2.0, 2.0, 4, 0},
    {-1.0, -1.0, 4, 0}, {1e-6, 1e-6, 4, 1}, {-1e-9, -1e-9, 4, 1},
};
static const double betas[] = {0.0, 0.7, -2.1}, ds[] = {2.0, 0.37};

/* Lengths from 1 + 1e-7 to 3 chords (the buckled batten's pair from the first). */
START_TEST(length_mode_returns_every_solution_with_its_images)
{
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_LENGTH;
    size_t total = 0, problems = 0;
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++)
        for (int b = 0; b < 3; b++)
            for (int e = -7; e <= 1; e++) {
                const double Ln = e <= 0 ? 1.0 + pow(10.0, e) : 3.0;
                const double d = ds[(b + e + 7) % 2];
                const ends x = frame(betas[b], d, pairs[p].a0, pairs[p].a1);
                o.length = Ln * d;
                const size_t n = solve_closed(x.p0, x.t0, x.p1, x.t1, &o, pairs[p].ims);
                if (pairs[p].buckles)
                    ck_assert_msg(n >= 2, "tangents %g rad from the chord, length %.9g chords: "
                                  "%zu solutions", pairs[p].a0, Ln, n);
                total += n;
                problems++;
            }
    printf("length mode: %zu solutions of %zu symmetric problems, every image present\n",
           total, problems);
}
END_TEST

START_TEST(tension_mode_returns_every_solution_with_its_images)
{
    static const double sd2[] = {-300.0, -8.0 * M_PI * M_PI - 1e-3, -50.0, -1.0, 0.5, 2.0, 35.0,
                                 400.0};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_TENSION;
    size_t total = 0, problems = 0;
    for (size_t p = 0; p < sizeof pairs / sizeof pairs[0]; p++)
        for (int b = 0; b < 3; b++)
            for (size_t i = 0; i < sizeof sd2 / sizeof sd2[0]; i++) {
                const double d = ds[(b + i) % 2];
                const ends x = frame(betas[b], d, pairs[p].a0, pairs[p].a1);
                o.sigma = sd2[i] / (d * d);
                total += solve_closed(x.p0, x.t0, x.p1, x.t1, &o, pairs[p].ims);
                problems++;
            }
    printf("tension mode: %zu solutions of %zu symmetric problems, every image present\n",
           total, problems);
}
END_TEST

/* Tangents along the chord: the straight batten buckles (linearised 2 kappa'' = sigma kappa,
 * theta(0) = theta(d) = 0, int theta = 0: theta = sin(2 pi s / d) at sigma d^2 = -8 pi^2,
 * the one mode within a period). Its branch is the whole period from a curvature extremum:
 * L = 4 K / sqrt(mu), d = L (2 E / K - 1), sigma = 2 mu (2 m - 1); at L = d (1 + eps),
 * m = eps + O(eps^2) (2 E / K - 1 = 1 - m + O(m^2)) and K = pi / 2 (1 + m / 4 + O(m^2)) give
 * sigma d^2 = -8 pi^2 + 28 pi^2 eps + O(eps^2): the two least-energy solutions, a mirror pair
 * (kappa0 of opposite signs), on it. */
START_TEST(length_mode_buckled_pair_leaves_the_straight_batten_at_the_euler_load)
{
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = EL_HERMITE_LENGTH;
    double worst = 0.0;
    for (int e = -7; e <= -4; e++) {
        const double eps = pow(10.0, e), d = 2.0;
        const ends x = frame(0.7, d, 0.0, 0.0);   /* t0 = t1 along the chord */
        o.length = d * (1.0 + eps);
        el_hermite_result r;
        ck_assert_int_eq(el_hermite_solve(x.p0, x.t0, x.p1, x.t1, &o, &r), EL_OK);
        ck_assert_msg(r.count >= 2, "eps %g: %zu solutions", eps, r.count);
        const el_hermite_solution *a = &r.solutions[0], *b = &r.solutions[1];
        for (int i = 0; i < 2; i++) {
            const double sd2 = r.solutions[i].sigma * d * d;
            const double g = (sd2 + 8.0 * M_PI * M_PI) / (28.0 * M_PI * M_PI * eps) - 1.0;
            worst = fmax(worst, fabs(g));
            ck_assert_msg(fabs(g) <= 1e-3, "eps %g: (sigma d^2 + 8 pi^2) / (28 pi^2 eps) - 1 = %g",
                          eps, g);
        }
        ck_assert(fabs(a->kappa0 + b->kappa0) <= 1e-6 * fabs(a->kappa0) && a->kappa0 != 0.0);
        el_hermite_result_free(&r);
    }
    printf("buckled pair: (sigma d^2 + 8 pi^2) / (28 pi^2 eps) within %.2g of 1\n", worst);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite_symmetry");
    TCase *tc = tcase_create("hermite_symmetry");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, length_mode_returns_every_solution_with_its_images);
    tcase_add_test(tc, tension_mode_returns_every_solution_with_its_images);
    tcase_add_test(tc, length_mode_buckled_pair_leaves_the_straight_batten_at_the_euler_load);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
