/* Elastic splines (issue 14) in length mode and at the ends of the tension
 * range: the length mode's Newton against its continuation, the buckled batten
 * on collinear ducks (its first mode), tight battens with natural ends, and
 * ducks placed by hand (a sheer line, a chair's back) in every mode. */
#include "spline_check.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_sort_vector.h>

START_TEST(length_mode_meets_the_length_and_the_tension_mode)
{
    el_spline_options t = opts(EL_SPLINE_TENSION, 0.0);
    el_spline_result r0;
    ck_assert_int_eq(solve(sketch, NSKETCH, &t, &r0), EL_OK);
    const double Lfree = r0.length;
    el_spline_result_free(&r0);
    const double polygon = polygon_length(sketch, NSKETCH);
    const double Ls[] = {Lfree * 1.002, Lfree, Lfree * 0.999, polygon + 0.3 * (Lfree - polygon)};
    for (size_t i = 0; i < sizeof Ls / sizeof Ls[0]; i++) {
        el_spline_options o = opts(EL_SPLINE_LENGTH, Ls[i]);
        el_spline_result r;
        ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
        check_spline(sketch, NSKETCH, &o, &r, 1e-9);
        /* shorter is tighter */
        if (Ls[i] < Lfree) ck_assert_double_gt(r.sigma, 0.0);
        if (Ls[i] > Lfree) ck_assert_double_lt(r.sigma, 0.0);
        /* the tension solution at that sigma is the same spline */
        if (r.sigma >= 0.0) {
            el_spline_options ot = opts(EL_SPLINE_TENSION, r.sigma);
            el_spline_result rt;
            ck_assert_int_eq(solve(sketch, NSKETCH, &ot, &rt), EL_OK);
            ck_assert_close(rt.length, Ls[i], 1e-8 * Ls[i]);
            el_spline_result_free(&rt);
        }
        el_spline_result_free(&r);
    }
}
END_TEST

/*
 * Length mode tries Newton with the length as an equation first (from the
 * start, then from the free batten), trusted only while it contracts; its
 * plain counterpart is the continuation along the tension solutions from the
 * free batten (el__spline_solve_paths with newton_first = 0). Over smooth,
 * unevenly sampled curves (open with natural, clamped and G2 ends, closed),
 * lengths from near the polygon to well past the free batten: the same
 * status and the same spline (angles, curvatures, energy; sigma to its
 * conditioning), and Newton is what solved the near targets (fewer iterations).
 */
/* Two points clamped at both ends, by length: the least-energy Hermite elastica of that
 * length (header). (0,0) -> (3,1), tangents (1,0): EL_ENOCONV from 1.06 x the free batten's
 * length, a branch of 6 % more energy below (QA); then 300 random such problems (chord
 * ratio 1.02-3, any tangents) against el_hermite_solve's least-energy solution */
START_TEST(two_clamped_points_by_length_are_the_least_energy_hermite)
{
    unsigned long long seed = 11;
    int compared = 0;
    for (int c = 0; c < 305; c++) {
        double xy[4] = {0.0, 0.0, 3.0, 1.0}, a = 0.0, b = 0.0, L = 3.3 + 0.4 * c;
        if (c >= 5) {
            xy[2] = test_uniform(&seed, -1.0, 1.0);
            xy[3] = test_uniform(&seed, -1.0, 1.0);
            a = test_uniform(&seed, -M_PI, M_PI);
            b = test_uniform(&seed, -M_PI, M_PI);
            L = hypot(xy[2], xy[3]) * test_uniform(&seed, 1.02, 3.0);
        }
        el_spline_options o = opts(EL_SPLINE_LENGTH, L);
        o.start.kind = o.end.kind = EL_SPLINE_TANGENT;
        o.start.tangent[0] = cos(a); o.start.tangent[1] = sin(a);
        o.end.tangent[0] = cos(b); o.end.tangent[1] = sin(b);
        el_hermite_options ho;
        el_hermite_options_defaults(&ho);
        ho.mode = EL_HERMITE_LENGTH;
        ho.length = L;
        el_hermite_result h;
        ck_assert_int_eq(el_hermite_solve(xy, o.start.tangent, xy + 2, o.end.tangent, &ho, &h), EL_OK);
        if (h.count > 0 && h.solutions[0].npieces == 1) {
            el_spline_result r;
            ck_assert_msg(solve(xy, 2, &o, &r) == EL_OK, "case %d: L %g", c, L);
            check_spline(xy, 2, &o, &r, 1e-9);
            ck_assert_msg(fabs(r.energy - h.solutions[0].energy) <= 1e-8 * (1.0 + h.solutions[0].energy),
                          "case %d: energy %.12g, least Hermite %.12g", c, r.energy, h.solutions[0].energy);
            el_spline_result_free(&r);
            compared++;
        }
        el_hermite_result_free(&h);
    }
    ck_assert_int_ge(compared, 290);
}
END_TEST

START_TEST(length_mode_newton_equals_the_continuation)
{
    unsigned long long seed = 20240611ULL;
    int solved = 0, by_newton = 0;
    for (int trial = 0; trial < 48; trial++) {
        const size_t n = 4 + (size_t)test_uniform(&seed, 0, 30);
        const double a1 = test_uniform(&seed, 0.2, 1.2), w1 = test_uniform(&seed, 0.3, 1.5);
        const double a2 = test_uniform(&seed, 0.0, 0.4), w2 = test_uniform(&seed, 1.0, 3.0);
        const double X = test_uniform(&seed, 4.0, 12.0), ph = test_uniform(&seed, 0.0, 3.0);
        const double un = test_uniform(&seed, 0.2, 1.0);
        el_spline_options o = opts(EL_SPLINE_TENSION, 0.0);
        o.closed = trial % 8 == 7;
        double xy[2 * 40];
        for (size_t i = 0; i < n; i++) {
            double t = (double)i / (double)(n - 1);
            t += 0.4 * un * t * (1.0 - t) * sin(ph + 5.0 * t);   /* uneven spacing */
            if (o.closed) {
                const double u = 2.0 * M_PI * t * (double)(n - 1) / (double)n;
                xy[2 * i] = 0.3 * X * cos(u) * (1.0 + a2 * cos(3.0 * u));
                xy[2 * i + 1] = 0.2 * X * sin(u);
            } else {
                xy[2 * i] = X * t;
                xy[2 * i + 1] = a1 * sin(w1 * X * t) + a2 * cos(w2 * X * t);
            }
        }
        if (trial % 4 == 1) {
            o.start.kind = EL_SPLINE_TANGENT;
            o.start.tangent[0] = 1.0; o.start.tangent[1] = test_uniform(&seed, -1.0, 1.0);
        }
        if (trial % 6 == 2 && n > 4) {
            o.end.kind = EL_SPLINE_G2;
            o.end.tangent[0] = 1.0; o.end.tangent[1] = test_uniform(&seed, -1.0, 1.0);
            o.end.curvature = test_uniform(&seed, -0.5, 0.5);
        }
        el_spline_result r, rc;
        if (solve(xy, n, &o, &r) != EL_OK) { el_spline_result_free(&r); continue; }
        const double Lfree = r.length;
        el_spline_result_free(&r);
        double Lp = 0.0;
        for (size_t j = 0; j < (o.closed ? n : n - 1); j++) {
            const size_t e = (j + 1) % n;
            Lp += hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        }
        const double f = test_uniform(&seed, -1.0, 1.0);
        o.mode = EL_SPLINE_LENGTH;
        o.length = f < 0.0 ? Lfree + 0.5 * f * (Lfree - Lp) : Lfree * (1.0 + 0.06 * f * f);
        const int st = solve(xy, n, &o, &r), stc = el__spline_solve_paths(xy, n, &o, 0, &rc);
        ck_assert_msg(st == stc, "trial %d: status %d, by continuation %d", trial, st, stc);
        if (st == EL_OK) {
            check_spline(xy, n, &o, &r, 1e-9);
            check_spline(xy, n, &o, &rc, 1e-9);
            for (size_t i = 0; i < r.npoints; i++) {
                ck_assert_msg(fabs(r.angles[i] - rc.angles[i]) <= 1e-9, "trial %d angle %zu: %.17g %.17g",
                              trial, i, r.angles[i], rc.angles[i]);
                ck_assert_close(r.curvatures[i], rc.curvatures[i], 1e-8 * (1.0 + r.max_curvature));
            }
            ck_assert_close(r.energy, rc.energy, 1e-9 * r.energy);
            ck_assert_close(r.sigma, rc.sigma, 1e-6 * (1.0 + fabs(r.sigma)));
            solved++;
            by_newton += r.iterations < rc.iterations;
        }
        el_spline_result_free(&r);
        el_spline_result_free(&rc);
    }
    ck_assert_int_ge(solved, 30);
    ck_assert_int_ge(by_newton, solved / 3);
}
END_TEST

/* ------------------------------------------------------------------ buckling */

/* The least two eigenvalues lambda of the batten on the line, linearised
 * (integral w''^2 = lambda integral w'^2 at a critical point, w = 0 at the
 * ducks xs[0..n-1], slope free at the ends or zero where clamped), by cubic
 * Hermite finite elements, 8 per span, and GSL's dense generalised symmetric
 * eigensolver: independent of spline_path.c's stability functions. */
static void fe_buckling(const double *xs, int n, int clamp0, int clamp1, double lam[2])
{
    enum { SUB = 8 };
    const int ne = SUB * (n - 1), nd = 2 * (ne + 1);
    int *map = malloc(nd * sizeof *map), nf = 0;
    for (int d = 0; d < nd; d++) {
        const int node = d / 2, slope = d % 2;
        const int duck = node % SUB == 0;
        const int fixed = (!slope && duck) || (slope && ((node == 0 && clamp0) || (node == ne && clamp1)));
        map[d] = fixed ? -1 : nf++;
    }
    gsl_matrix *K = gsl_matrix_calloc(nf, nf), *G = gsl_matrix_calloc(nf, nf);
    for (int e = 0; e < ne; e++) {
        const int span = e / SUB;
        const double h = (xs[span + 1] - xs[span]) / SUB;
        const double k[4][4] = {{12, 6 * h, -12, 6 * h}, {6 * h, 4 * h * h, -6 * h, 2 * h * h},
                                {-12, -6 * h, 12, -6 * h}, {6 * h, 2 * h * h, -6 * h, 4 * h * h}};
        const double g[4][4] = {{36, 3 * h, -36, 3 * h}, {3 * h, 4 * h * h, -3 * h, -h * h},
                                {-36, -3 * h, 36, -3 * h}, {3 * h, -h * h, -3 * h, 4 * h * h}};
        for (int a = 0; a < 4; a++)
            for (int b = 0; b < 4; b++) {
                const int ia = map[2 * e + a], ib = map[2 * e + b];
                if (ia < 0 || ib < 0) continue;
                *gsl_matrix_ptr(K, ia, ib) += k[a][b] / (h * h * h);
                *gsl_matrix_ptr(G, ia, ib) += g[a][b] / (30.0 * h);
            }
    }
    gsl_vector *ev = gsl_vector_alloc(nf);
    gsl_eigen_gensymm_workspace *ws = gsl_eigen_gensymm_alloc(nf);
    ck_assert_int_eq(gsl_eigen_gensymm(K, G, ev, ws), 0);
    gsl_sort_vector(ev);
    lam[0] = gsl_vector_get(ev, 0);
    lam[1] = gsl_vector_get(ev, 1);
    gsl_eigen_gensymm_free(ws);
    gsl_vector_free(ev);
    gsl_matrix_free(K);
    gsl_matrix_free(G);
    free(map);
}

/* Side of the line y = 0 a piece bows to: the sign of y at its middle. */
static double bow(const el_smooth_params *p)
{
    double xy[2], s = 0.5 * p->length;
    ck_assert_int_eq(el_smooth_eval(p, 1, &s, xy, NULL, NULL), EL_OK);
    return xy[1];
}

/*
 * Collinear points and a length longer than the line: the batten buckles in
 * its first mode, the one of least energy, its largest bow to the left.
 * Equal spans: the pinned Euler strip of one span repeated with alternating
 * sides (kappa = 0 at every duck), so each span is the two-point spline of a
 * third of the length. Uneven spans: at a small excess, -sigma / 2 is the
 * least eigenvalue of the linearised batten (finite elements, well apart
 * from the second) and the energy 2 lambda (L - Lp). Two points clamped along
 * the line: the least-energy Hermite elastica of that length.
 */
START_TEST(buckled_collinear_batten_takes_its_first_mode)
{
    const double eq[] = {0, 0, 1, 0, 2, 0, 3, 0};
    el_spline_options o = opts(EL_SPLINE_LENGTH, 3.5);
    el_spline_result r, r1;
    ck_assert_int_eq(solve(eq, 4, &o, &r), EL_OK);
    check_spline(eq, 4, &o, &r, 1e-9);
    o.length = 3.5 / 3.0;
    ck_assert_int_eq(solve(eq, 2, &o, &r1), EL_OK);
    ck_assert_close(r.sigma, r1.sigma, 1e-8 * fabs(r1.sigma));
    ck_assert_close(r.energy, 3.0 * r1.energy, 1e-8 * r.energy);
    for (size_t i = 0; i < 4; i++) ck_assert_msg(fabs(r.curvatures[i]) <= 1e-8 * r.max_curvature, "kappa %g at duck %zu", r.curvatures[i], i);
    for (size_t j = 0; j < 3; j++) {
        ck_assert_close(r.pieces[j].length, 3.5 / 3.0, 1e-9);
        ck_assert_close(bow(&r.pieces[j]), (j % 2 ? -1.0 : 1.0) * bow(&r1.pieces[0]), 1e-8);
    }
    ck_assert_double_gt(bow(&r.pieces[0]), 0.0);
    el_spline_result_free(&r);
    el_spline_result_free(&r1);

    /* uneven spans, natural or clamped ends */
    const double xs[] = {0.0, 0.5, 2.0, 2.3, 4.0};
    double un[10];
    for (int i = 0; i < 5; i++) { un[2 * i] = xs[i]; un[2 * i + 1] = 0.0; }
    for (int clamp = 0; clamp < 3; clamp++) {
        double lam[2];
        fe_buckling(xs, 5, clamp == 2, clamp >= 1, lam);
        ck_assert_msg(lam[1] > 1.05 * lam[0], "modes too close %g %g", lam[0], lam[1]);
        o = opts(EL_SPLINE_LENGTH, 4.0 * (1.0 + 1e-4));
        if (clamp >= 1) { o.end.kind = EL_SPLINE_TANGENT; o.end.tangent[0] = 1.0; }
        if (clamp == 2) { o.start.kind = EL_SPLINE_TANGENT; o.start.tangent[0] = 1.0; }
        ck_assert_int_eq(solve(un, 5, &o, &r), EL_OK);
        check_spline(un, 5, &o, &r, 1e-9);
        ck_assert_msg(fabs(-0.5 * r.sigma - lam[0]) <= 2e-3 * lam[0], "clamp %d: -sigma/2 %g, first mode %g, second %g",
                      clamp, -0.5 * r.sigma, lam[0], lam[1]);
        ck_assert_close(r.energy, 2.0 * lam[0] * 4e-4, 2e-3 * r.energy);
        double big = 0.0;
        for (size_t j = 0; j < 4; j++) if (fabs(bow(&r.pieces[j])) > fabs(big)) big = bow(&r.pieces[j]);
        ck_assert_double_gt(big, 0.0);
        el_spline_result_free(&r);
    }

    /* many uneven spans: the first mode is localised in the longest span, the
     * slopes far from it exponentially small (none may start exactly straight) */
    {
        unsigned long long seed = 7ULL;
        double many[2 * 50], x = 0.0;
        for (int i = 0; i < 50; i++) {
            many[2 * i] = x; many[2 * i + 1] = 0.0;
            x += test_uniform(&seed, 0.005, 0.8);
        }
        o = opts(EL_SPLINE_LENGTH, 1.001 * many[98]);
        ck_assert_int_eq(solve(many, 50, &o, &r), EL_OK);
        check_spline(many, 50, &o, &r, 1e-9);
        ck_assert_double_lt(r.sigma, 0.0);
        el_spline_result_free(&r);
    }

    /* one long span between many short ones, which clamp it: its clamped
     * bump, lambda just below (2 pi / 1)^2, a bow with small end slopes */
    {
        double x = 0.0, lng[2 * 122];
        for (int i = 0; i < 122; i++) {
            lng[2 * i] = x; lng[2 * i + 1] = 0.0;
            x += i == 60 ? 1.0 : 0.01;
        }
        const double Lp = lng[2 * 121];
        o = opts(EL_SPLINE_LENGTH, Lp + 1e-4);
        ck_assert_int_eq(solve(lng, 122, &o, &r), EL_OK);
        check_spline(lng, 122, &o, &r, 1e-9);
        const double lam = -0.5 * r.sigma;
        ck_assert_msg(lam < 4.0 * M_PI * M_PI && lam > 0.95 * 4.0 * M_PI * M_PI, "lambda %g", lam);
        ck_assert_close(r.energy, 2.0 * lam * 1e-4, 1e-2 * r.energy);
        ck_assert_double_gt(bow(&r.pieces[60]), 0.9 * 2.0 * sqrt(1e-4) / M_PI);   /* 2 A, L - Lp = (pi A)^2 */
        el_spline_result_free(&r);
    }

    /* two points clamped along the line: the least-energy Hermite elastica */
    o = opts(EL_SPLINE_LENGTH, 3.5);
    o.start.kind = o.end.kind = EL_SPLINE_TANGENT;
    o.start.tangent[0] = o.end.tangent[0] = 1.0;
    const double two[] = {0, 0, 3, 0};
    ck_assert_int_eq(solve(two, 2, &o, &r), EL_OK);
    check_spline(two, 2, &o, &r, 1e-9);
    el_hermite_options ho;
    el_hermite_options_defaults(&ho);
    ho.mode = EL_HERMITE_LENGTH;
    ho.length = 3.5;
    el_hermite_result hr;
    ck_assert_int_eq(el_hermite_solve(two, o.start.tangent, two + 2, o.end.tangent, &ho, &hr), EL_OK);
    ck_assert_uint_gt(hr.count, 0);
    ck_assert_close(r.energy, hr.solutions[0].energy, 1e-8 * r.energy);
    ck_assert_double_gt(bow(&r.pieces[0]), 0.0);
    el_hermite_result_free(&hr);
    el_spline_result_free(&r);
}
END_TEST

/*
 * A tight batten with natural ends (sigma h^2 = 40..70 on the mean chord of
 * 33 scanned-like points): the end pieces run from an inflection at the free
 * end into the boundary layer at the next duck, with 1 - k^2 down to 1e-8.
 * Each piece's u is put with its larger-curvature end near u = 0, where its
 * curvature does not hang on K(k), which k's last bit moves by 1e-16 / (1 - k^2):
 * the residual stays below tol (it was 2e-10..4e-9 with u near 2K).
 */
/* Ducks near a line pushed longer (QA: 7 ducks along 6.6, one raised): every raise from
 * 1e-9 to 1e-3 gives the spline of that length (none before: the path from the free batten
 * met the line's buckling), and raising that duck from 0.05 to 0.27 in steps of 0.01 moves
 * the batten smoothly in its first mode (it jumped between modes of 2.6-10 x the energy) */
START_TEST(ducks_near_a_line_buckle_in_their_first_mode)
{
    const double x[7] = {0.0, 1.0, 1.5, 3.5, 4.8, 5.5, 6.6};
    double xy[14];
    for (int i = 0; i < 7; i++) { xy[2 * i] = x[i]; xy[2 * i + 1] = 0.0; }
    const double raise[] = {1e-9, 1e-6, 1e-3};
    for (size_t r = 0; r < 3; r++)
        for (int k = 0; k < 2; k++) {
            xy[7] = raise[r];
            const double poly = polygon_length(xy, 7);
            el_spline_options o = opts(EL_SPLINE_LENGTH, (k ? 1.2 : 1.05) * poly);
            el_spline_result res;
            ck_assert_msg(solve(xy, 7, &o, &res) == EL_OK, "raised by %g, %g x", raise[r], k ? 1.2 : 1.05);
            check_spline(xy, 7, &o, &res, 1e-9);
            el_spline_result_free(&res);
        }
    double last = 0.0;
    for (int step = 0; step <= 22; step++) {
        xy[7] = 0.05 + 0.01 * step;
        el_spline_options o = opts(EL_SPLINE_LENGTH, 7.92);
        el_spline_result res;
        ck_assert_int_eq(solve(xy, 7, &o, &res), EL_OK);
        check_spline(xy, 7, &o, &res, 1e-9);
        ck_assert_msg(step == 0 || fabs(res.energy - last) <= 0.01 * last, "duck at %g: energy %g after %g", xy[7],
                      res.energy, last);
        last = res.energy;
        el_spline_result_free(&res);
    }
}
END_TEST

/* A closed spline by length where no free batten exists (a ring of ducks: without tension
 * it swells without bound): the lengths that tensions 0.3, 1, 3 give are reached, at those
 * tensions (none was, QA) */
START_TEST(closed_length_without_a_free_batten)
{
    static const double blob[] = {4.288, 1.7064, 2.6029, 1.1654, 1.498, 1.5679, 0.2344, 1.881, -2.3731, 0.7068,
                                  -2.3464, 0.2071, -2.4051, -0.9101, -0.3182, -2.1825, 0.9045, -1.8066};
    const double sigma[] = {0.3, 1.0, 3.0};
    for (size_t i = 0; i < 3; i++) {
        el_spline_options o = closed_opts(EL_SPLINE_TENSION, sigma[i]);
        el_spline_result t, l;
        ck_assert_int_eq(solve(blob, 9, &o, &t), EL_OK);
        el_spline_options ol = closed_length(t.length);
        ck_assert_msg(solve(blob, 9, &ol, &l) == EL_OK, "length %g (tension %g)", t.length, sigma[i]);
        check_spline(blob, 9, &ol, &l, 1e-9);
        ck_assert_close(l.sigma, sigma[i], 1e-6 * sigma[i]);
        el_spline_result_free(&t);
        el_spline_result_free(&l);
    }
}
END_TEST

/* TAUT_START (spline_path.c): 6 ducks of a random walk with reversals under tension x
 * (longest span)^2 = 100, 200, 300: no spline before (the start's pieces stepped ~1e-3 a
 * Newton iteration, the continuation from sigma h^2 = 40 stalled); now from the taut
 * batten's tangents. Each G2 at its ducks to 1e-8 (check_spline, on the pieces), and the
 * polygon's limit approached as a boundary layer of width ~ 1/sqrt(sigma) at each duck:
 * the length's excess over the polygon and the largest angle between a duck's tangent and
 * its chords' bisector fall with the tension, the excess about as 1/sqrt(sigma) */
START_TEST(random_walk_under_high_tension_from_the_taut_start)
{
    static const double walk[] = {-0.525, -0.926, 2.168, -1.906, 1.594, -1.869, 2.078, -0.84,
                                  2.469, -1.713, 2.975, -1.463};
    const size_t n = 6;
    const double poly = polygon_length(walk, n), hmax = longest_side(walk, n);
    const double sh2[] = {100.0, 200.0, 300.0};
    double excess[3], dev[3];
    for (int t = 0; t < 3; t++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sh2[t] / (hmax * hmax));
        o.tol = 1e-9;
        el_spline_result r;
        ck_assert_msg(solve(walk, n, &o, &r) == EL_OK, "sigma h^2 %g", sh2[t]);
        check_spline(walk, n, &o, &r, 1e-8);
        ck_assert_int_eq(r.loops, 0);
        excess[t] = r.length / poly - 1.0;
        dev[t] = 0.0;
        for (size_t i = 1; i + 1 < n; i++) {
            const double a = atan2(walk[2 * i + 1] - walk[2 * i - 1], walk[2 * i] - walk[2 * i - 2]);
            const double b = atan2(walk[2 * i + 3] - walk[2 * i + 1], walk[2 * i + 2] - walk[2 * i]);
            const double bis = a + 0.5 * wrap(b - a);
            dev[t] = fmax(dev[t], fabs(wrap(r.angles[i] - bis)));
        }
        el_spline_result_free(&r);
    }
    for (int t = 1; t < 3; t++) {
        ck_assert_msg(excess[t] < excess[t - 1] && dev[t] < dev[t - 1], "%g: excess %g dev %g", sh2[t],
                      excess[t], dev[t]);
        const double ratio = excess[t - 1] / excess[t], expect = sqrt(sh2[t] / sh2[t - 1]);
        ck_assert_msg(fabs(ratio / expect - 1.0) < 0.1, "excess ratio %g, sqrt of the tensions' %g", ratio,
                      expect);
    }
}
END_TEST

static const double scan33[] = {
    0, 0.142, 0.315, 0.182, 0.604, 0.152, 0.866, 0.208, 1.101, 0.364, 1.309, 0.541, 1.494, 0.673,
    1.659, 0.737, 1.809, 0.743, 1.949, 0.71, 2.086, 0.66, 2.225, 0.61, 2.373, 0.579, 2.534, 0.587,
    2.713, 0.648, 2.914, 0.748, 3.139, 0.83, 3.389, 0.806, 3.663, 0.64, 3.96, 0.429, 4.277, 0.345,
    4.611, 0.393, 4.955, 0.347, 5.306, 0.075, 5.655, -0.22, 5.999, -0.304, 6.329, -0.263, 6.643,
    -0.326, 6.934, -0.529, 7.2, -0.725, 7.438, -0.802, 7.648, -0.769, 7.831, -0.692};

START_TEST(natural_ends_under_high_tension_reach_tol)
{
    const double Lp = polygon_length(scan33, 33);
    const double hm = Lp / 32.0, sh2[] = {40.0, 55.0, 70.0};
    for (size_t c = 0; c < 3; c++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sh2[c] / (hm * hm));
        el_spline_result r;
        ck_assert_int_eq(solve(scan33, 33, &o, &r), EL_OK);
        check_spline(scan33, 33, &o, &r, 1e-9);
        ck_assert_double_lt(1.0 - r.pieces[0].k * r.pieces[0].k, 1e-6);   /* near the separatrix */
        el_spline_result_free(&r);
    }
}
END_TEST

/* ------------------------------------------------------------------ hand-placed ducks */

/*
 * Ducks a designer places by hand, unevenly: a boat's sheer line (side view,
 * metres: high at the stern, lowest just aft of amidships, highest at the bow)
 * and a chair's back rail (side view, metres: up from the seat, leaning back).
 * In tension 0 (the free batten), a moderate tension and length mode (a little
 * longer than the free batten, and tighter): every property of issue 14
 * (check_spline), no loop (the length within 2 % of the polygon's), the energy
 * stationary in the knot angles (the first variation, by finite differences of
 * Hermite pieces), the sheer line fair (its curvature one-signed away from the
 * natural ends' inflections), and length mode equal to tension mode at its sigma.
 */
static const double sheer[] = {0.0, 1.35, 0.8, 1.22, 2.1, 1.08, 3.0, 1.01, 4.6, 0.95, 5.5, 0.94,
                               6.9, 0.97, 7.6, 1.02, 8.8, 1.14, 9.5, 1.26, 10.2, 1.42};
static const double chair[] = {0.0, 0.0, 0.012, 0.11, 0.018, 0.24, 0.01, 0.37, -0.015, 0.47,
                               -0.05, 0.58, -0.095, 0.7, -0.13, 0.79, -0.15, 0.86};

static void check_stationary(const double *xy, size_t n, const el_spline_result *r, size_t at)
{
    double th[16], Ep, Em, jump = 0.0;
    const double e = 1e-5;
    memcpy(th, r->angles, n * sizeof *th);
    th[at] += e;
    Ep = hermite_energy(xy, n, th, r->sigma, r, NULL, at);
    th[at] -= 2.0 * e;
    Em = hermite_energy(xy, n, th, r->sigma, r, NULL, at);
    th[at] += e;
    hermite_energy(xy, n, th, r->sigma, r, &jump, at);
    const double dE = (Ep - Em) / (2.0 * e), scale = r->energy + fabs(r->sigma) * r->length;
    ck_assert_msg(fabs(dE) <= 1e-6 * scale, "not stationary at duck %zu: dE/dtheta %g", at, dE);
    ck_assert_msg(fabs(jump) <= 1e-7 * (1.0 + r->max_curvature), "curvature jump %g", jump);
}

START_TEST(hand_placed_ducks)
{
    const struct { const double *xy; size_t n; double sigma; } cases[] = {
        {sheer, 11, 0.05}, {chair, 9, 20.0}};
    for (size_t c = 0; c < 2; c++) {
        const double *xy = cases[c].xy;
        const size_t n = cases[c].n;
        const double Lp = polygon_length(xy, n);
        const double sig[2] = {0.0, cases[c].sigma};
        double Lfree = 0.0;
        for (int t = 0; t < 2; t++) {
            el_spline_options o = opts(EL_SPLINE_TENSION, sig[t]);
            el_spline_result r;
            ck_assert_int_eq(solve(xy, n, &o, &r), EL_OK);
            check_spline(xy, n, &o, &r, 1e-9);
            ck_assert_double_lt(r.length, 1.02 * Lp);
            check_stationary(xy, n, &r, n / 2);
            check_stationary(xy, n, &r, 1);
            if (t == 0) Lfree = r.length;
            if (xy == sheer) {   /* fair: no inflection between the second and the last but one duck */
                const double *k = r.curvatures;
                for (size_t i = 1; i + 1 < n; i++) ck_assert_msg(k[i] > 0.0, "sheer kappa %g at %zu", k[i], i);
            }
            el_spline_result_free(&r);
        }
        const double Ls[2] = {Lfree * 1.001, Lp + 0.5 * (Lfree - Lp)};
        for (int t = 0; t < 2; t++) {
            el_spline_options o = opts(EL_SPLINE_LENGTH, Ls[t]);
            el_spline_result r, rt;
            ck_assert_int_eq(solve(xy, n, &o, &r), EL_OK);
            check_spline(xy, n, &o, &r, 1e-9);
            check_stationary(xy, n, &r, n / 2);
            ck_assert(t == 0 ? r.sigma < 0.0 : r.sigma > 0.0);   /* longer: pushed; shorter: pulled */
            if (r.sigma > 0.0) {
                el_spline_options ot = opts(EL_SPLINE_TENSION, r.sigma);
                ck_assert_int_eq(solve(xy, n, &ot, &rt), EL_OK);
                ck_assert_close(rt.length, Ls[t], 1e-8 * Ls[t]);
                ck_assert_close(rt.energy, r.energy, 1e-7 * r.energy);
                el_spline_result_free(&rt);
            }
            el_spline_result_free(&r);
        }
    }
}
END_TEST

/* QA16's shipline.csv rows 179..246 (68 points doubling back): by length the search's near
 * chain held a piece el_smooth_params cannot, and the valid input was EL_EINVAL; now the
 * status of a search that reached no spline (EL_ENOCONV, or EL_ERANGE with the reach) */
static const double shipline[] = {
    25.1319,33.9972, 25.1285,34.5080, 25.1319,34.1866,
    25.7770,34.8537, 26.2724,35.9926, 27.0896,36.7320,
    30.1841,42.1815, 33.6682,49.5295, 36.4448,53.6620,
    39.8851,59.4761, 40.1023,60.9480, 39.9068,62.2924,
    40.5781,62.6377, 49.6806,83.9767, 52.4531,90.0752,
    52.2259,89.7099, 52.8481,92.5453, 52.9551,94.9552,
    53.4644,94.8512, 55.5306,100.1636, 57.2213,107.5007,
    60.4759,115.7312, 59.5193,117.8512, 60.9387,119.1679,
    60.7133,119.9707, 60.7878,119.9187, 60.2864,120.9258,
    61.3975,125.1030, 62.5121,126.4591, 62.0078,126.3428,
    63.6356,133.7255, 63.1522,134.2041, 64.3849,136.1374,
    64.2055,138.9321, 64.4315,142.6488, 65.7650,144.3611,
    65.1494,145.0180, 65.7649,147.8331, 65.7906,148.3318,
    66.1534,149.4939, 66.1605,151.6041, 66.8765,152.7984,
    66.7214,156.2468, 67.0598,157.2369, 66.8418,158.2853,
    66.8846,158.8856, 67.1235,164.5165, 67.4181,166.7247,
    68.6777,173.8210, 68.5540,175.4377, 68.7536,177.5000,
    68.3943,179.0177, 68.7415,184.1481, 69.3458,189.1715,
    69.3874,205.1982, 68.8388,204.7826, 68.9278,205.6881,
    69.3292,207.4017, 68.9414,209.2027, 69.4916,210.5697,
    69.1520,210.6092, 69.2456,212.7728, 68.8315,220.1622,
    68.8345,222.3818, 68.2973,223.1170, 68.2918,228.4374,
    67.5244,236.2058, 67.4128,239.5596,
};

START_TEST(shipline_by_length_is_not_einval)
{
    const size_t n = sizeof shipline / sizeof shipline[0] / 2;
    ck_assert_uint_eq(n, 68);
    double poly = 0.0;
    for (size_t i = 0; i + 1 < n; i++)
        poly += hypot(shipline[2 * i + 2] - shipline[2 * i], shipline[2 * i + 3] - shipline[2 * i + 1]);
    const double f[2] = {1.05, 1.5};
    for (int j = 0; j < 2; j++) {
        el_spline_options o;
        el_spline_options_defaults(&o);
        o.mode = EL_SPLINE_LENGTH;
        o.length = f[j] * poly;
        el_spline_result r;
        const int st = el_spline_solve(shipline, n, &o, &r);
        ck_assert_int_ne(st, EL_EINVAL);
        ck_assert(st == EL_OK || st == EL_ENOCONV || st == EL_ERANGE);
        if (st == EL_OK) ck_assert_double_eq_tol(r.length, o.length, 1e-8 * o.length);
        if (st == EL_ERANGE) ck_assert(r.reach[1] > 0.0);
        el_spline_result_free(&r);
    }
}
END_TEST

/* Its lengths 1.5 and 2 x the polygon: splines exist there (loops round its doubling back,
 * found from tension mode's at sigma h^2 = 1.75 (1.565 x) and 1 (2.096 x) on the mean chord
 * as opt.initial: sigma h^2 2.1098, 1.1516), where the search ended on a chain with a piece
 * of length -2.05 (a secant predictor's, now refused by el__spiece_set_state) and then none
 * (the bracket's rungs: NEIGHBOURS_RUNGS). The same spline as from the initial pieces. */
START_TEST(shipline_by_length_reaches_its_looping_splines)
{
    const size_t n = sizeof shipline / sizeof shipline[0] / 2;
    const double poly = polygon_length(shipline, n), S = poly / (double)(n - 1);
    const double f[2] = {1.5, 2.0}, sh2[2] = {1.75, 1.0};
    for (int j = 0; j < 2; j++) {
        el_spline_options o;
        el_spline_options_defaults(&o);
        o.sigma = sh2[j] / (S * S);
        el_spline_result t;
        ck_assert_int_eq(el_spline_solve(shipline, n, &o, &t), EL_OK);
        o.mode = EL_SPLINE_LENGTH;
        o.length = f[j] * poly;
        el_spline_result a, b;
        ck_assert_msg(el_spline_solve(shipline, n, &o, &a) == EL_OK, "%g x", f[j]);
        o.initial = t.pieces;
        o.ninitial = t.npieces;
        ck_assert_int_eq(el_spline_solve(shipline, n, &o, &b), EL_OK);
        o.initial = NULL;
        o.ninitial = 0;
        check_spline(shipline, n, &o, &a, 1e-8);
        ck_assert_double_eq_tol(a.length, o.length, 1e-8 * o.length);
        for (size_t i = 0; i < a.npieces; i++) ck_assert(a.pieces[i].length > 0.0);
        ck_assert_double_eq_tol(a.sigma, b.sigma, 1e-6 * fabs(b.sigma));
        ck_assert_double_eq_tol(a.energy, b.energy, 1e-6 * b.energy);
        ck_assert_int_eq(a.loops, 1);
        el_spline_result_free(&a);
        el_spline_result_free(&b);
        el_spline_result_free(&t);
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline_length");
    TCase *tc = tcase_create("spline_length");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, length_mode_meets_the_length_and_the_tension_mode);
    tcase_add_test(tc, two_clamped_points_by_length_are_the_least_energy_hermite);
    tcase_add_test(tc, length_mode_newton_equals_the_continuation);
    tcase_add_test(tc, buckled_collinear_batten_takes_its_first_mode);
    tcase_add_test(tc, ducks_near_a_line_buckle_in_their_first_mode);
    tcase_add_test(tc, closed_length_without_a_free_batten);
    tcase_add_test(tc, natural_ends_under_high_tension_reach_tol);
    tcase_add_test(tc, hand_placed_ducks);
    tcase_add_test(tc, random_walk_under_high_tension_from_the_taut_start);
    tcase_add_test(tc, shipline_by_length_is_not_einval);
    tcase_add_test(tc, shipline_by_length_reaches_its_looping_splines);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}

