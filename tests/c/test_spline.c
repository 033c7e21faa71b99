/* Elastic splines (issue 14): every spline is checked with the evaluator of
 * smooth.c (through the points, G1 and G2 at them, one tension, the end
 * conditions, energy and length), the derivatives of spline_piece.c by finite
 * differences and by Hermite solutions (el_hermite_solve), the spline as a
 * critical point of integral kappa^2 + sigma ds, the forces by their defining
 * identities, the B-spline by its joins, and the degenerate and bad inputs.
 * Length mode, buckling, tight battens and hand-placed ducks: test_spline_length.c. */
#include "spline_check.h"
#include <float.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>

/* ------------------------------------------------------------------ derivatives */

static const el_smooth_params test_pieces[] = {
    {0.0, 0.0, 0.1, 0.8, 0.9, 0.3, 1.1},      /* inflectional */
    {1.0, -2.0, 2.0, 2.0, 0.5, -0.7, 0.9},
    {0.0, 0.0, -0.4, 1.5, 0.72, 1.2, 1.7},    /* tension ~ 0 */
    {0.0, 0.0, 0.3, 0.3, 1.3, 0.2, 1.5},      /* a loop, counter-clockwise */
    {0.0, 0.0, 0.3, 0.3, -1.3, 0.2, 1.5},     /* clockwise */
    {0.5, 0.5, 1.0, 4.0, 0.99, 1.5, 0.8},     /* near the separatrix */
    {0.0, 0.0, 0.0, 0.01, 6.0, 0.4, 2.0},     /* near a circle */
};

/* J, g0, g1, M of spline_piece.c against central differences of el_smooth_eval in
 * v = (phi, ln mu, k, q, L), and J's position rows against el_smooth_jacobian. */
START_TEST(piece_jacobians_match_finite_differences)
{
    for (size_t c = 0; c < sizeof test_pieces / sizeof test_pieces[0]; c++) {
        const el_smooth_params p = test_pieces[c];
        double J[25], g0[5], g1[5], M[25], d[12];
        ck_assert_int_eq(el__spline_piece_jacobians(&p, J, g0, g1, M, d), EL_OK);
        const double sv[2] = {0.0, p.length};
        double xy0[4];
        ck_assert_int_eq(el_smooth_eval(&p, 2, sv, xy0, NULL, NULL), EL_OK);
        const double h = hypot(xy0[2] - xy0[0], xy0[3] - xy0[1]);
        /* el_smooth_jacobian at s = L: columns mu (times mu: d/d ln mu), k, q, phi; L column is t T */
        double jac[14];
        ck_assert_int_eq(el_smooth_jacobian(&p, 1, &sv[1], NULL, jac), EL_OK);
        const int col[5] = {2, 3, 4, 5, 6};
        for (int v = 0; v < 5; v++) {
            const double f = v == 1 ? p.mu : 1.0;
            ck_assert_close(J[0 * 5 + v], jac[0 * 7 + col[v]] * f / h, 1e-9 * (1.0 + fabs(J[v])));
            ck_assert_close(J[1 * 5 + v], jac[1 * 7 + col[v]] * f / h, 1e-9 * (1.0 + fabs(J[5 + v])));
        }
        for (int v = 0; v < 5; v++) {
            double val[2][11];
            for (int sgn = 0; sgn < 2; sgn++) {
                el_smooth_params q = p;
                const double e = 1e-6 * (sgn ? 1.0 : -1.0);
                if (v == 0) q.phi += e;
                if (v == 1) q.mu *= exp(e);
                if (v == 2) q.k += e;
                if (v == 3) q.q += e;
                if (v == 4) q.length += e;
                const double s2[2] = {0.0, q.length};
                double xy[4], th[2], ka[2], dk0;
                ck_assert_int_eq(el_smooth_eval(&q, 2, s2, xy, th, ka), EL_OK);
                state_at(&q, 0.0, xy, &th[0], &ka[0], &dk0);
                double *o = val[sgn];
                o[0] = xy[2] / h; o[1] = xy[3] / h; o[2] = th[0]; o[3] = th[1];
                o[4] = 2.0 * q.mu * (2.0 * q.k * q.k - 1.0) * h * h;
                o[5] = ka[0]; o[6] = ka[1];
                o[7] = dk0; o[8] = 2.0 * q.mu * (2.0 * q.k * q.k - 1.0); o[9] = q.length;
            }
            for (int r = 0; r < 5; r++) {
                const double fd = (val[1][r] - val[0][r]) / 2e-6;
                ck_assert_msg(fabs(fd - J[r * 5 + v]) <= 1e-5 * (1.0 + fabs(fd)),
                              "piece %zu J[%d][%d] %.10g vs fd %.10g", c, r, v, J[r * 5 + v], fd);
            }
            const double f0 = (val[1][5] - val[0][5]) / 2e-6, f1 = (val[1][6] - val[0][6]) / 2e-6;
            ck_assert_msg(fabs(f0 - g0[v]) <= 1e-5 * (1.0 + fabs(f0)), "piece %zu g0[%d] %g vs %g", c, v, g0[v], f0);
            ck_assert_msg(fabs(f1 - g1[v]) <= 1e-5 * (1.0 + fabs(f1)), "piece %zu g1[%d] %g vs %g", c, v, g1[v], f1);
            /* M = d(theta0, kappa0, kappa0', sigma, L)/dv; kappa0' itself by differences in s */
            const int rows[5] = {2, 5, 7, 8, 9};
            for (int r = 0; r < 5; r++) {
                const double fd = (val[1][rows[r]] - val[0][rows[r]]) / 2e-6;
                const double tolm = r == 2 ? 1e-4 : 1e-5;
                ck_assert_msg(fabs(fd - M[r * 5 + v]) <= tolm * (1.0 + fabs(fd)),
                              "piece %zu M[%d][%d] %.10g vs fd %.10g", c, r, v, M[r * 5 + v], fd);
            }
        }
    }
}
END_TEST

/* The implicit-function derivatives d(kappa(0), kappa(L), L)/d(ta, tb, sigma, e) of a
 * Hermite piece against Hermite solutions (el_hermite_solve) of perturbed data
 * (e: the end point moved along the chord's normal, as a guide duck moves):
 * the solution continuing the piece (nearest kappa0) on either side. */
START_TEST(implicit_derivatives_match_hermite_solutions)
{
    for (size_t c = 0; c < 3; c++) {
        const el_smooth_params p = test_pieces[c];
        double J[25], g0[5], g1[5], M[25], d[12];
        ck_assert_int_eq(el__spline_piece_jacobians(&p, J, g0, g1, M, d), EL_OK);
        const double sv[2] = {0.0, p.length};
        double xy[4], th[2], ka[2];
        ck_assert_int_eq(el_smooth_eval(&p, 2, sv, xy, th, ka), EL_OK);
        const double sigma = 2.0 * p.mu * (2.0 * p.k * p.k - 1.0);
        const double h = hypot(xy[2] - xy[0], xy[3] - xy[1]);
        for (int v = 0; v < 4; v++) {
            double out[2][3];
            for (int sgn = 0; sgn < 2; sgn++) {
                const double e = (sgn ? 1.0 : -1.0) * 1e-5;
                const double ta = th[0] + (v == 0 ? e : 0.0), tb = th[1] + (v == 1 ? e : 0.0);
                const double t0[2] = {cos(ta), sin(ta)}, t1[2] = {cos(tb), sin(tb)};
                const double g = v == 3 ? e : 0.0;   /* the end along the normal (-dy, dx) / h */
                const double p1[2] = {xy[2] - g * (xy[3] - xy[1]) / h, xy[3] + g * (xy[2] - xy[0]) / h};
                el_hermite_options ho;
                el_hermite_options_defaults(&ho);
                ho.sigma = sigma + (v == 2 ? e : 0.0);
                ho.samples = 100;
                el_hermite_result hr;
                ck_assert_int_eq(el_hermite_solve(xy, t0, p1, t1, &ho, &hr), EL_OK);
                size_t best = hr.count;
                for (size_t i = 0; i < hr.count; i++)
                    if (best == hr.count || fabs(hr.solutions[i].kappa0 - ka[0]) < fabs(hr.solutions[best].kappa0 - ka[0]))
                        best = i;
                ck_assert_uint_lt(best, hr.count);
                out[sgn][0] = hr.solutions[best].kappa0;
                out[sgn][1] = hr.solutions[best].kappa1;
                out[sgn][2] = hr.solutions[best].length;
                el_hermite_result_free(&hr);
            }
            for (int r = 0; r < 3; r++) {
                const double fd = (out[1][r] - out[0][r]) / 2e-5;
                ck_assert_msg(fabs(fd - d[4 * r + v]) <= 1e-4 * (1.0 + fabs(fd)),
                              "piece %zu d[%d][%d] %.10g vs hermite %.10g", c, r, v, d[4 * r + v], fd);
            }
        }
    }
}
END_TEST

/* ------------------------------------------------------------------ splines */

START_TEST(through_points_g2_one_tension)
{
    const double sig[] = {0.0, 0.05, 0.5, 2.0, 10.0};
    for (size_t i = 0; i < sizeof sig / sizeof sig[0]; i++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sig[i]);
        el_spline_result r;
        ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
        check_spline(sketch, NSKETCH, &o, &r, 1e-9);
        ck_assert_close(r.sigma, sig[i], 0.0);
        /* a gentle curve: no loop, a length near the polygon's */
        for (size_t j = 0; j < r.npieces; j++) ck_assert_msg(fabs(r.pieces[j].k) < 1.5, "loop k %g", r.pieces[j].k);
        ck_assert_msg(r.length < 1.05 * 8.9, "length %g", r.length);
        el_spline_result_free(&r);
    }
}
END_TEST

START_TEST(random_points_and_tensions)
{
    unsigned long long seed = 88172645463325252ULL;
    int ok = 0;
    for (int trial = 0; trial < 40; trial++) {
        const size_t n = 3 + (size_t)(test_uniform(&seed, 0, 12));
        double xy[2 * 16], x = 0.0, y = 0.0;
        for (size_t i = 0; i < n; i++) {
            xy[2 * i] = x; xy[2 * i + 1] = y;
            x += test_uniform(&seed, 0.2, 2.0);
            y += test_uniform(&seed, -0.6, 0.6);
        }
        el_spline_options o = opts(EL_SPLINE_TENSION, test_uniform(&seed, 0.0, 5.0));
        el_spline_result r;
        const int st = solve(xy, n, &o, &r);
        if (st == EL_OK) { check_spline(xy, n, &o, &r, 1e-9); ok++; }
        else ck_assert_msg(st == EL_ENOCONV, "status %d", st);
        el_spline_result_free(&r);
    }
    ck_assert_int_ge(ok, 38);
}
END_TEST

/* Tension mode follows its ducks: sketched steps (a top hat, QA; three drawn like it) at
 * sigma = c / extent^2 for c from 0.01 to 10, natural ends: the direct Newton returned
 * loops up to 17 x the ducks' polygon (crossing themselves, status ok) where the free
 * batten pulled to that tension follows them */
START_TEST(tension_mode_follows_its_ducks)
{
    static const double top_hat[] = {0.95, 0.05, 2.424, -0.031, 3.179, 1.514, 4.304, 1.521, 4.973, 0.074,
                                     5.877, -0.025, 7.037, 1.587, 7.522, 1.509, 8.219, -0.01, 9.176, -0.034};
    static const double steps1[] = {0.794, -0.014, 2.413, 0.065, 3.158, 1.550, 4.175, 1.364, 4.616,
                                    -0.094, 5.542, -0.009, 6.108, 1.479, 6.780, 1.511, 8.331, 0.011};
    static const double steps2[] = {0.961, 0.044, 2.222, 0.034, 2.466, 1.468, 3.878, 1.500, 5.733, 0.022, 7.421,
                                    0.023, 9.215, 1.544, 10.604, 1.513, 11.246, -0.005, 12.829, -0.013,
                                    13.410, 1.553, 15.106, 1.387};
    static const double steps3[] = {0.700, 0.044, 2.543, -0.017, 3.670, 1.541, 4.417, 1.447, 4.931, 0.028,
                                    6.004, -0.025, 6.881, 1.534, 8.203, 1.550, 9.300, -0.037, 9.567, -0.003};
    const struct { const double *xy; size_t n; double extent; } sets[] = {
        {top_hat, 10, 8.226}, {steps1, 9, 7.537}, {steps2, 12, 14.145}, {steps3, 10, 8.867},
    };
    const double c[] = {0.01, 0.043, 0.1, 1.0, 10.0};
    for (size_t k = 0; k < sizeof sets / sizeof sets[0]; k++) {
        const double poly = polygon_length(sets[k].xy, sets[k].n);
        for (size_t j = 0; j < sizeof c / sizeof c[0]; j++) {
            el_spline_options o = opts(EL_SPLINE_TENSION, c[j] / (sets[k].extent * sets[k].extent));
            el_spline_result r;
            ck_assert_int_eq(solve(sets[k].xy, sets[k].n, &o, &r), EL_OK);
            check_spline(sets[k].xy, sets[k].n, &o, &r, 1e-9);
            ck_assert_msg(r.length <= 1.2 * poly, "set %zu, c %g: length %g, the ducks' polygon %g", k, c[j], r.length,
                          poly);
            el_spline_result_free(&r);
        }
    }
}
END_TEST

/* Small tensions: 7 sketched ducks (DUCKS7, spline_path.c's FREE_START) solved at 0 and
 * 1e-14 but not from 1e-12 to 1e-5 (EL_ENOCONV: the start's first piece a curve 22313
 * long at the tension's own scale, then neither path converged): the same batten as the
 * free one (energy 0.173144 to 3e-7, length 73.474 to 5e-5: pulled shorter), longer ones
 * winding away */
START_TEST(small_tensions_keep_the_free_batten)
{
    static const double ducks7[] = {44.9, 0.2, 51.6, 20.9, 61.7, 19.9, 76.8, 19.1, 83.7, 20.1,
                                    93.9, 20.1, 100.3, 19.4};
    const double sig[] = {0.0, 1e-14, 1e-12, 1e-10, 1e-8, 1e-6, 1e-5, 3e-5};
    double E0 = 0.0, L0 = 0.0, Eprev = 0.0, Lprev = 0.0;
    for (size_t i = 0; i < sizeof sig / sizeof sig[0]; i++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sig[i]);
        el_spline_result r;
        ck_assert_msg(solve(ducks7, 7, &o, &r) == EL_OK, "sigma %g: no spline", sig[i]);
        check_spline(ducks7, 7, &o, &r, 1e-9);
        ck_assert(r.residual <= o.tol);
        if (i == 0) { E0 = r.energy; L0 = r.length; Eprev = E0; Lprev = L0; }
        ck_assert_msg(fabs(r.energy - E0) <= 1e-6 * E0 && fabs(r.length - L0) <= 1e-4 * L0,
                      "sigma %g: energy %.9g, length %.9g (free batten %.9g, %.9g)", sig[i], r.energy, r.length,
                      E0, L0);
        /* more tension: more bending, shorter (the same branch) */
        ck_assert_msg(r.energy >= Eprev * (1.0 - 1e-12) && r.length <= Lprev * (1.0 + 1e-12),
                      "sigma %g: energy %.12g, length %.12g after %.12g, %.12g", sig[i], r.energy, r.length, Eprev,
                      Lprev);
        Eprev = r.energy;
        Lprev = r.length;
        el_spline_result_free(&r);
    }
}
END_TEST

START_TEST(spline_is_a_critical_point_of_the_energy)
{
    const double sigma = 0.5;
    el_spline_options o = opts(EL_SPLINE_TENSION, sigma);
    el_spline_result r;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    for (size_t i = 1; i + 1 < NSKETCH; i += 2) {
        for (int away = 0; away < 2; away++) {
            double th[NSKETCH], Ep, Em, jump = 0.0;
            memcpy(th, r.angles, sizeof th);
            th[i] += away ? 0.05 : 0.0;
            const double e = 1e-5;
            th[i] += e;
            Ep = hermite_energy(sketch, NSKETCH, th, sigma, &r, NULL, i);
            th[i] -= 2.0 * e;
            Em = hermite_energy(sketch, NSKETCH, th, sigma, &r, NULL, i);
            th[i] += e;
            hermite_energy(sketch, NSKETCH, th, sigma, &r, &jump, i);
            const double dE = (Ep - Em) / (2.0 * e);
            ck_assert_msg(fabs(dE - 2.0 * jump) <= 1e-5 * (1.0 + fabs(dE)),
                          "point %zu: dE/dtheta %g, 2 kappa jump %g", i, dE, 2.0 * jump);
            if (away) ck_assert_msg(fabs(dE) > 1e-3, "control: dE %g", dE);
            else ck_assert_msg(fabs(dE) <= 1e-6, "not stationary at point %zu: dE/dtheta %g", i, dE);
        }
    }
    el_spline_result_free(&r);
}
END_TEST

START_TEST(closed_curves)
{
    /* an ellipse sampled unevenly, and a rounded square */
    double xy[2 * 12];
    for (int i = 0; i < 12; i++) {
        const double t = 2.0 * M_PI * (i + 0.3 * sin(i)) / 12.0;
        xy[2 * i] = 2.0 * cos(t);
        xy[2 * i + 1] = sin(t);
    }
    const double sq[] = {0, 0, 1, 0, 1, 1, 0, 1, 0, 0};   /* a repeated first point is dropped */
    const double sig[] = {0.0, 0.5, 3.0};
    for (size_t i = 0; i < 3; i++) {
        el_spline_options o = closed_opts(EL_SPLINE_TENSION, sig[i]);
        el_spline_result r;
        ck_assert_int_eq(solve(xy, 12, &o, &r), EL_OK);
        ck_assert_uint_eq(r.npieces, 12);
        check_spline(xy, 12, &o, &r, 1e-9);
        el_spline_result_free(&r);
        if (sig[i] == 0.0) continue;   /* no free closed batten through a square */
        ck_assert_int_eq(solve(sq, 5, &o, &r), EL_OK);
        ck_assert_uint_eq(r.npoints, 4);
        check_spline(sq, 4, &o, &r, 1e-9);
        /* symmetric: four equal pieces */
        for (size_t j = 1; j < 4; j++) ck_assert_close(r.pieces[j].length, r.pieces[0].length, 1e-9);
        el_spline_result_free(&r);
    }
    el_spline_options o = closed_length(10.0);
    el_spline_result r;
    ck_assert_int_eq(solve(xy, 12, &o, &r), EL_OK);
    check_spline(xy, 12, &o, &r, 1e-9);
    el_spline_result_free(&r);
}
END_TEST

START_TEST(clamped_and_g2_ends)
{
    el_spline_options o = opts(EL_SPLINE_TENSION, 1.0);
    o.start.kind = EL_SPLINE_TANGENT;
    o.start.tangent[0] = 1.0; o.start.tangent[1] = 1.0;
    o.end.kind = EL_SPLINE_TANGENT;
    o.end.tangent[0] = 2.0; o.end.tangent[1] = 0.5;
    el_spline_result r;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    check_spline(sketch, NSKETCH, &o, &r, 1e-9);
    el_spline_result_free(&r);
    /* G2 at the start (meeting an arc of radius 2 tangentially), tangent at the end */
    o.start.kind = EL_SPLINE_G2;
    o.start.curvature = 0.5;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    check_spline(sketch, NSKETCH, &o, &r, 1e-9);
    el_spline_result_free(&r);
    /* G2 at both ends, in length mode */
    o.end.kind = EL_SPLINE_G2;
    o.end.curvature = -0.3;
    o.mode = EL_SPLINE_LENGTH;
    o.length = 9.2;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    check_spline(sketch, NSKETCH, &o, &r, 1e-9);
    el_spline_result_free(&r);
    /* two points, G2 at one end, a tangent at the other */
    o = opts(EL_SPLINE_TENSION, 0.0);
    o.start.kind = EL_SPLINE_G2;
    o.start.tangent[0] = 1.0; o.start.tangent[1] = 0.0; o.start.curvature = 0.8;
    ck_assert_int_eq(solve(sketch, 2, &o, &r), EL_OK);
    check_spline(sketch, 2, &o, &r, 1e-9);
    el_spline_result_free(&r);
}
END_TEST

START_TEST(degenerate_inputs)
{
    el_spline_options o = opts(EL_SPLINE_TENSION, 1.0);
    el_spline_result r;
    /* collinear points in order: the straight line, k = 0, energy 0 */
    const double line[] = {0.0, 0.0, 0.5, 1.0, 2.0, 4.0, 2.1, 4.2};
    ck_assert_int_eq(solve(line, 4, &o, &r), EL_OK);
    check_spline(line, 4, &o, &r, 1e-12);
    ck_assert_double_eq(r.energy, 0.0);
    for (size_t j = 0; j < 3; j++) ck_assert_double_eq(r.pieces[j].k, 0.0);
    el_spline_result_free(&r);
    /* two points, natural ends: the segment */
    ck_assert_int_eq(solve(line, 2, &o, &r), EL_OK);
    ck_assert_uint_eq(r.npieces, 1);
    ck_assert_double_eq(r.energy, 0.0);
    el_spline_result_free(&r);
    /* two points, both tangents: the least-energy Hermite elastica of that tension */
    o.start.kind = o.end.kind = EL_SPLINE_TANGENT;
    o.start.tangent[0] = 0.0; o.start.tangent[1] = 1.0;
    o.end.tangent[0] = 1.0; o.end.tangent[1] = -0.2;
    ck_assert_int_eq(solve(sketch, 2, &o, &r), EL_OK);
    check_spline(sketch, 2, &o, &r, 1e-9);
    el_hermite_options ho;
    el_hermite_options_defaults(&ho);
    ho.sigma = 1.0;
    el_hermite_result hr;
    ck_assert_int_eq(el_hermite_solve(sketch, o.start.tangent, sketch + 2, o.end.tangent, &ho, &hr), EL_OK);
    ck_assert_uint_gt(hr.count, 0);
    ck_assert_close(r.energy, hr.solutions[0].energy, 1e-8 * hr.solutions[0].energy);
    el_hermite_result_free(&hr);
    el_spline_result_free(&r);
    /* collinear points, a clamped end off the line: a curve, not the line */
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.start.kind = EL_SPLINE_TANGENT;
    o.start.tangent[0] = 1.0; o.start.tangent[1] = 0.5;
    const double flat[] = {0, 0, 1, 0, 2, 0, 3, 0};
    ck_assert_int_eq(solve(flat, 4, &o, &r), EL_OK);
    check_spline(flat, 4, &o, &r, 1e-9);
    el_spline_result_free(&r);
    /* collinear points, a length longer than the line: a buckled batten */
    o = opts(EL_SPLINE_LENGTH, 3.5);
    ck_assert_int_eq(solve(flat, 4, &o, &r), EL_OK);
    check_spline(flat, 4, &o, &r, 1e-9);
    ck_assert_double_lt(r.sigma, 0.0);
    el_spline_result_free(&r);
    /* the length of the line itself: the line */
    o = opts(EL_SPLINE_LENGTH, 3.0);
    ck_assert_int_eq(solve(flat, 4, &o, &r), EL_OK);
    ck_assert_double_eq(r.energy, 0.0);
    el_spline_result_free(&r);
}
END_TEST

START_TEST(extreme_scales)
{
    const double scales[] = {1e-6, 1e-3, 1e3, 1e6};
    el_spline_options o0 = opts(EL_SPLINE_TENSION, 0.7);
    el_spline_result r0;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o0, &r0), EL_OK);
    for (size_t i = 0; i < 4; i++) {
        const double c = scales[i];
        double xy[2 * NSKETCH];
        for (int j = 0; j < 2 * NSKETCH; j++) xy[j] = c * sketch[j] + (j % 2 ? -3.0 : 5.0) * c;
        el_spline_options o = opts(EL_SPLINE_TENSION, 0.7 / (c * c));
        el_spline_result r;
        ck_assert_int_eq(solve(xy, NSKETCH, &o, &r), EL_OK);
        check_spline(xy, NSKETCH, &o, &r, 1e-9);
        /* the same shape: scaled length, energy / c, curvature / c */
        ck_assert_close(r.length, c * r0.length, 1e-9 * c * r0.length);
        ck_assert_close(r.energy, r0.energy / c, 1e-8 * r0.energy / c);
        ck_assert_close(r.max_curvature, r0.max_curvature / c, 1e-8 * r0.max_curvature / c);
        el_spline_result_free(&r);
    }
    el_spline_result_free(&r0);
}
END_TEST

START_TEST(many_points)
{
    enum { N = 400 };
    static double xy[2 * N];
    for (int i = 0; i < N; i++) {
        const double x = 12.0 * i / (N - 1) + 0.01 * sin(7.0 * i);
        xy[2 * i] = x;
        xy[2 * i + 1] = sin(x) + 0.3 * cos(2.3 * x);
    }
    const double sig[] = {0.0, 1.0, 30.0};
    for (size_t i = 0; i < 3; i++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sig[i]);
        el_spline_result r;
        ck_assert_int_eq(solve(xy, N, &o, &r), EL_OK);
        check_spline(xy, N, &o, &r, 1e-9);
        el_spline_result_free(&r);
    }
}
END_TEST

/* sigma = 0: a zigzag the free batten cannot hold (the tension family folds
 * back before sigma = 0): EL_EDOM, quickly, and res empty */
START_TEST(free_batten_that_does_not_exist)
{
    double xy[20];
    for (int i = 0; i < 10; i++) { xy[2 * i] = i; xy[2 * i + 1] = i % 2; }
    el_spline_options o = opts(EL_SPLINE_TENSION, 0.0);
    el_spline_result r;
    ck_assert_int_eq(solve(xy, 10, &o, &r), EL_EDOM);
    ck_assert_uint_eq(r.npieces, 0);
    ck_assert_ptr_null(r.pieces);
    /* with some tension it exists */
    o.sigma = 0.5;
    ck_assert_int_eq(solve(xy, 10, &o, &r), EL_OK);
    check_spline(xy, 10, &o, &r, 1e-9);
    el_spline_result_free(&r);
}
END_TEST

/* A high tension: the designer's sketch (examples/ducks.csv) at sigma x (longest span)^2 =
 * 450 and 500 had no spline (EL_ENOCONV, res empty: the continuation from sigma h^2 = 40
 * ran out of its 60 steps, spline_path.c's LONG_PATH); now G2 through every duck within
 * its resolution (residual <= 1e-7, elastica.h: Accuracy), pulled shorter than at 300 */
START_TEST(taut_batten_under_a_high_tension)
{
    const double h = longest_side(sketch, NSKETCH);
    const double sh2[] = {300.0, 450.0, 500.0};
    double prev = HUGE_VAL;
    for (size_t i = 0; i < 3; i++) {
        el_spline_options o = opts(EL_SPLINE_TENSION, sh2[i] / (h * h));
        o.tol = 1e-7;
        el_spline_result r;
        ck_assert_msg(solve(sketch, NSKETCH, &o, &r) == EL_OK, "sigma h^2 %g", sh2[i]);
        check_spline(sketch, NSKETCH, &o, &r, 1e-7);
        ck_assert_int_eq(r.loops, 0);
        ck_assert_msg(r.length < prev, "sigma h^2 %g: length %.9g, %.9g before", sh2[i], r.length, prev);
        prev = r.length;
        el_spline_result_free(&r);
    }
}
END_TEST

/* The search for the largest tension (spline_limit.c) tries the rungs sigma h^2 = top x
 * 2^(-j/4) near where the limit lies first, not from the top down: the same rung as from
 * the top (every rung above it fails: checked here one by one), in fewer tension solves.
 * The sketch at 1000 (top-down: 841 .. 595 fail, 500 solves, then 3 bisections: 7 solves;
 * here 500, 595, 707, then the 3: 6) and QA16's 7 ducks with a G2 start at sigma h^2 17450
 * (top 1024: 861 .. 431 fail, 362 solves: 9 solves, the failing G2 ones each with its
 * search by length; here 431, 512, 362 and the 3: 6) */
static void check_largest_rung(const double *xy, size_t n, const el_spline_options *o, int most)
{
    const double h = longest_side(xy, n), top = fmin(o->sigma * h * h, 1024.0);
    double largest[3];
    int nsolves = -1;
    el__spwork work = {0, ULONG_MAX, 0};   /* no budget */
    ck_assert_int_eq(el__spline_largest(xy, n, o, h, largest, &nsolves, &work), EL_OK);
    const double sh2 = largest[0] * h * h;
    ck_assert_msg(nsolves >= 4 && nsolves <= most, "%d solves", nsolves);
    int j = 1;
    while (top * pow(2.0, -(double)j / 4.0) > sh2 * (1.0 + 1e-12)) j++;
    const double rung = top * pow(2.0, -(double)j / 4.0);
    ck_assert_msg(sh2 >= rung * (1.0 - 1e-12) && sh2 < rung * pow(2.0, 0.25), "sigma h^2 %g, rung %g", sh2, rung);
    for (int i = 1; i < j; i++) {   /* every rung above fails (or loops) */
        el_spline_options q = *o;
        q.sigma = top * pow(2.0, -(double)i / 4.0) / (h * h);
        el_spline_result r;
        const int st = el__spline_solve_paths(xy, n, &q, 1, &r);
        ck_assert_msg(st != EL_OK || r.loops, "rung %g solves", q.sigma * h * h);
        el_spline_result_free(&r);
    }
}

START_TEST(the_largest_tension_is_searched_near_the_limit_first)
{
    const double h = longest_side(sketch, NSKETCH);
    el_spline_options o = opts(EL_SPLINE_TENSION, 1000.0 / (h * h));
    check_largest_rung(sketch, NSKETCH, &o, 6);
    static const double qa16[] = {-70, 3, -85, 12, -95, 25, -98, 40, -93, 58, -80, 70, -62, 75};
    o = opts(EL_SPLINE_TENSION, 50.0);
    o.start.kind = EL_SPLINE_G2;
    o.start.tangent[0] = -1.0;
    o.start.tangent[1] = 0.0;
    o.start.curvature = 0.0;
    check_largest_rung(qa16, 7, &o, 6);
}
END_TEST

/* Beyond what a double resolves (the sketch at sigma x (longest span)^2 1000: EL_ENOCONV,
 * res empty) the solve gives the largest tension that solves the ducks (res->largest,
 * spline_limit.c; before, only the Python binding looked for it, with up to 18 solves of
 * its own): ~520, where the longest span's piece has |1 - k^2| ~ 5e-9 and a resolution of
 * ~4e-7, and that tension solves without loops within it; nothing where the solve succeeds,
 * nor by length */
START_TEST(too_high_a_tension_gives_the_largest_that_solves)
{
    const double h = longest_side(sketch, NSKETCH);
    el_spline_options o = opts(EL_SPLINE_TENSION, 1000.0 / (h * h));
    el_spline_result r;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_ENOCONV);
    const double largest = r.largest[0];
    ck_assert_msg(largest * h * h >= 450.0 && largest * h * h <= 560.0, "largest sigma h^2 %g", largest * h * h);
    ck_assert_msg(r.largest[1] > 1e-7 && r.largest[1] < 1e-6, "resolution %g", r.largest[1]);
    ck_assert_msg(r.largest[2] > 1e-10 && r.largest[2] < 1e-7, "|1 - k^2| %g", r.largest[2]);
    el_spline_result_free(&r);
    o.sigma = largest;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    ck_assert_int_eq(r.loops, 0);
    ck_assert_double_le(r.residual, 1e-7);
    ck_assert(r.largest[0] == 0.0 && r.largest[1] == 0.0 && r.largest[2] == 0.0);
    el_spline_result_free(&r);
}
END_TEST

START_TEST(bad_input_and_clear_statuses)
{
    el_spline_options o = opts(EL_SPLINE_TENSION, 1.0);
    el_spline_result r;
    const double dup[] = {0, 0, 1, 1, 1, 1, 2, 0};
    ck_assert_int_eq(solve(dup, 4, &o, &r), EL_EINVAL);   /* coincident consecutive points */
    ck_assert_uint_eq(r.npieces, 0);
    ck_assert_int_eq(solve(sketch, 1, &o, &r), EL_EINVAL);
    ck_assert_int_eq(solve(sketch, 0, &o, &r), EL_EINVAL);
    ck_assert_int_eq(solve(NULL, 3, &o, &r), EL_EINVAL);
    ck_assert_int_eq(el_spline_solve(sketch, 3, NULL, &r), EL_EINVAL);
    ck_assert_int_eq(el_spline_solve(sketch, 3, &o, NULL), EL_EINVAL);
    double nan_pts[] = {0, 0, NAN, 1, 2, 0};
    ck_assert_int_eq(solve(nan_pts, 3, &o, &r), EL_EINVAL);
    o.sigma = -1.0;
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EINVAL);
    o.sigma = INFINITY;
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EINVAL);
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.start.kind = EL_SPLINE_TANGENT;   /* zero tangent */
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EINVAL);
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.tol = 0.0;
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EINVAL);
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.closed = 1;
    ck_assert_int_eq(solve(sketch, 2, &o, &r), EL_EINVAL);
    const double tri[] = {0, 0, 1, 0, 0, 0};   /* closed: two distinct points */
    ck_assert_int_eq(solve(tri, 3, &o, &r), EL_EINVAL);
    /* a length not longer than the polygon */
    o = opts(EL_SPLINE_LENGTH, 1.0);
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_EDOM);
    /* a G2 end with a non-finite curvature */
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.start.kind = EL_SPLINE_G2;
    o.start.tangent[0] = 1.0;
    o.start.curvature = NAN;
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EINVAL);
    ck_assert_uint_eq(r.npieces, 0);
    el_spline_result_free(&r);
    el_spline_result_free(NULL);
    el_spline_options_defaults(NULL);
}
END_TEST

/* ------------------------------------------------------------------ B-spline */

/* Distance from c to the piece near arc length s0: the nearest of a grid over
 * +-5 % of the piece, refined by golden section. */
static double dist_at(const el_smooth_params *p, const double c[2], double u)
{
    double e[2];
    u = fmin(fmax(u, 0.0), p->length);
    ck_assert_int_eq(el_smooth_eval(p, 1, &u, e, NULL, NULL), EL_OK);
    return hypot(e[0] - c[0], e[1] - c[1]);
}

static double foot_distance(const el_smooth_params *p, const double c[2], double s0)
{
    const double L = p->length, h = 1e-3 * L;
    double ub = s0, db = INFINITY;
    for (int k = -50; k <= 50; k++) {
        const double d = dist_at(p, c, s0 + k * h);
        if (d < db) { db = d; ub = s0 + k * h; }
    }
    double a = ub - h, b = ub + h;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int it = 0; it < 80; it++) {
        const double x1 = b - g * (b - a), x2 = a + g * (b - a);
        if (dist_at(p, c, x1) < dist_at(p, c, x2)) b = x2; else a = x1;
    }
    return fmin(db, dist_at(p, c, 0.5 * (a + b)));
}

/* One B-spline for the whole spline: C2 joints (multiplicity degree - 2), so
 * the curvature measured on the B-spline on either side of each point agrees;
 * it equals each piece's own G2 B-spline, and its certified distance is
 * within tol and honest (sampled distance to the elastica below it). */
START_TEST(bspline_is_one_g2_curve_within_tol)
{
    for (int closed = 0; closed < 2; closed++) {
        for (int deg = 3; deg <= 7; deg += 2) {
            el_spline_options o = opts(EL_SPLINE_TENSION, 0.5);
            o.closed = closed;
            el_spline_result r;
            ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
            el_bspline b;
            const double tol = 1e-6;
            ck_assert_int_eq(el_spline_to_bspline(&r, tol, deg, &b), EL_OK);
            ck_assert_int_eq(el_bspline_check(&b), EL_OK);
            ck_assert_msg(b.max_deviation > 0.0 && b.max_deviation <= tol, "deviation %g", b.max_deviation);
            ck_assert_close(b.knots[b.nknots - 1], r.length, 1e-12 * r.length);
            double s0 = 0.0;
            for (size_t j = 0; j < r.npieces; j++) {
                const double L = r.pieces[j].length;
                /* the joint: multiplicity degree - 2, curvature continuous, = the spline's */
                if (j > 0) {
                    size_t kk = 0;
                    while (kk < b.nknots && fabs(b.knots[kk] - s0) > 1e-12 * r.length) kk++;
                    ck_assert_uint_lt(kk, b.nknots);
                    ck_assert_int_eq(b.mults[kk], deg - 2);
                    const double t[2] = {s0 - 1e-9 * r.length, s0 + 1e-9 * r.length};
                    double kap[2], d1[4];
                    ck_assert_int_eq(el_bspline_curvature(&b, 2, t, kap), EL_OK);
                    ck_assert_int_eq(el_bspline_derivative(&b, 1, 2, t, d1), EL_OK);
                    ck_assert_msg(fabs(kap[0] - kap[1]) <= 1e-6 * r.max_curvature, "B-spline curvature jump %g at point %zu",
                                  fabs(kap[0] - kap[1]), j);
                    ck_assert_close(kap[1], r.curvatures[j], 1e-6 * (1.0 + r.max_curvature));
                    /* the tangent turns by at most max kappa over the 2e-9 length apart */
                    ck_assert_close(atan2(d1[1], d1[0]), atan2(d1[3], d1[2]),
                                    2e-9 * r.length * r.max_curvature + 1e-10);
                }
                /* equal to the piece's own G2 B-spline */
                el_bspline pb;
                ck_assert_int_eq(el_smooth_to_bspline_g2(&r.pieces[j], tol, deg, &pb), EL_OK);
                for (int i = 0; i <= 20; i++) {
                    const double s = L * i / 20.0, t = s0 + s;
                    double a[2], c[2];
                    ck_assert_int_eq(el_bspline_eval(&pb, 1, &s, a), EL_OK);
                    ck_assert_int_eq(el_bspline_eval(&b, 1, &t, c), EL_OK);
                    ck_assert_msg(hypot(a[0] - c[0], a[1] - c[1]) <= 1e-12 * (1.0 + r.length), "join moved the curve");
                    /* and near the elastica: its distance (foot point by a grid and golden
                     * section) never above the certificate */
                    const double best = foot_distance(&r.pieces[j], c, s);
                    ck_assert_msg(best <= b.max_deviation + 1e-12 * (1.0 + r.length),
                                  "distance %g above the certificate %g", best, b.max_deviation);
                }
                el_bspline_free(&pb);
                s0 += L;
            }
            el_bspline_free(&b);
            el_spline_result_free(&r);
        }
    }
    el_spline_result empty;
    memset(&empty, 0, sizeof empty);
    el_bspline b;
    ck_assert_int_eq(el_spline_to_bspline(&empty, 1e-6, 3, &b), EL_EINVAL);
}
END_TEST

/* el_smooth_to_bspline_g2: end point, unit tangent and curvature exact (to the
 * rounding of the poles), certified within tol, at every degree. */
START_TEST(smooth_to_bspline_g2_has_exact_ends)
{
    for (size_t c = 0; c < sizeof test_pieces / sizeof test_pieces[0]; c++) {
        for (int deg = 3; deg <= 7; deg++) {
            const el_smooth_params *p = &test_pieces[c];
            el_bspline b;
            const int st = el_smooth_to_bspline_g2(p, 1e-7, deg, &b);
            ck_assert_int_eq(st, EL_OK);
            ck_assert_msg(b.max_deviation <= 1e-7, "deviation %g", b.max_deviation);
            const double t[2] = {0.0, p->length};
            double xy[4], d1[4], kap[2], sxy[4], th[2], ka[2];
            ck_assert_int_eq(el_bspline_eval(&b, 2, t, xy), EL_OK);
            ck_assert_int_eq(el_bspline_derivative(&b, 1, 2, t, d1), EL_OK);
            ck_assert_int_eq(el_bspline_curvature(&b, 2, t, kap), EL_OK);
            ck_assert_int_eq(el_smooth_eval(p, 2, t, sxy, th, ka), EL_OK);
            for (int e = 0; e < 2; e++) {
                ck_assert_close(xy[2 * e], sxy[2 * e], 1e-13 * (1.0 + fabs(sxy[2 * e])));
                ck_assert_close(xy[2 * e + 1], sxy[2 * e + 1], 1e-13 * (1.0 + fabs(sxy[2 * e + 1])));
                ck_assert_close(d1[2 * e], cos(th[e]), 1e-12);
                ck_assert_close(d1[2 * e + 1], sin(th[e]), 1e-12);
                ck_assert_msg(fabs(kap[e] - ka[e]) <= 1e-9 * (1.0 + fabs(ka[e])), "piece %zu degree %d end %d: kappa %.15g vs %.15g",
                              c, deg, e, kap[e], ka[e]);
            }
            el_bspline_free(&b);
        }
    }
}
END_TEST

int main(void)
{
    Suite *s = suite_create("spline");
    TCase *tc = tcase_create("spline");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, piece_jacobians_match_finite_differences);
    tcase_add_test(tc, implicit_derivatives_match_hermite_solutions);
    tcase_add_test(tc, through_points_g2_one_tension);
    tcase_add_test(tc, random_points_and_tensions);
    tcase_add_test(tc, tension_mode_follows_its_ducks);
    tcase_add_test(tc, small_tensions_keep_the_free_batten);
    tcase_add_test(tc, spline_is_a_critical_point_of_the_energy);
    tcase_add_test(tc, closed_curves);
    tcase_add_test(tc, clamped_and_g2_ends);
    tcase_add_test(tc, degenerate_inputs);
    tcase_add_test(tc, extreme_scales);
    tcase_add_test(tc, many_points);
    tcase_add_test(tc, free_batten_that_does_not_exist);
    tcase_add_test(tc, taut_batten_under_a_high_tension);
    tcase_add_test(tc, too_high_a_tension_gives_the_largest_that_solves);
    tcase_add_test(tc, the_largest_tension_is_searched_near_the_limit_first);
    tcase_add_test(tc, bad_input_and_clear_statuses);
    tcase_add_test(tc, bspline_is_one_g2_curve_within_tol);
    tcase_add_test(tc, smooth_to_bspline_g2_has_exact_ends);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
