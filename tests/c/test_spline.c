/* Elastic splines (issue 14): every spline is checked with the evaluator of
 * smooth.c (through the points, G1 and G2 at them, one tension, the end
 * conditions, energy and length), the derivatives of spline_piece.c by finite
 * differences and by Hermite solutions (el_hermite_solve), the spline as a
 * critical point of integral kappa^2 + sigma ds, the forces by their defining
 * identities, the B-spline by its joins, and the degenerate and bad inputs. */
#include "testutil.h"
#include "internal.h"
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_eigen.h>
#include <gsl/gsl_sort_vector.h>

static double wrap(double a) { return a - 2.0 * M_PI * nearbyint(a / (2.0 * M_PI)); }

/* Point, tangent angle, curvature and kappa' (central difference) of a piece at s. */
static void state_at(const el_smooth_params *p, double s, double xy[2], double *th, double *ka,
                     double *dka)
{
    ck_assert_int_eq(el_smooth_eval(p, 1, &s, xy, th, ka), EL_OK);
    if (dka) {
        const double h = 1e-5 * (p->length + 1e-300), sv[2] = {s - h, s + h};
        double kk[2];
        ck_assert_int_eq(el_smooth_eval(p, 2, sv, NULL, NULL, kk), EL_OK);
        *dka = (kk[1] - kk[0]) / (2.0 * h);
    }
}

/*
 * The properties issue 14 lists, measured with el_smooth_eval at the piece
 * ends: through the points (tol times the extent), tangent continuity (tol rad),
 * curvature jump <= 1e-7 max |kappa|, each piece's tension 2 mu (2k^2 - 1) equal
 * to res->sigmas (and to res->sigma away from G2 spans, k = 0 straight pieces
 * exempt: kappa = 0 solves every tension), the end conditions, energy and length
 * as sums over the pieces, the force constant along each piece.
 */
static void check_spline(const double *xy, size_t n, const el_spline_options *o,
                         const el_spline_result *r, double tol)
{
    const size_t m = r->npieces;
    ck_assert_uint_eq(m, o->closed ? r->npoints : r->npoints - 1);
    double ext = 0.0;
    for (size_t i = 0; i < r->npoints; i++) ext = fmax(ext, fmax(fabs(xy[2 * i]), fabs(xy[2 * i + 1])));
    for (size_t j = 0; j + 1 < n; j++) ext = fmax(ext, hypot(xy[2 * j + 2] - xy[2 * j], xy[2 * j + 3] - xy[2 * j + 1]));
    const double kmax = r->max_curvature;
    double E = 0.0, L = 0.0, kseen = 0.0;
    for (size_t j = 0; j < m; j++) {
        const el_smooth_params *p = &r->pieces[j];
        const size_t e = (j + 1) % r->npoints;
        ck_assert_int_eq(el_smooth_check(p), EL_OK);
        ck_assert_msg(p->x0 == xy[2 * j] && p->y0 == xy[2 * j + 1], "piece %zu does not start at its point", j);
        double a[2], b[2], tha, thb, ka, kb, dka, dkb;
        state_at(p, 0.0, a, &tha, &ka, &dka);
        state_at(p, p->length, b, &thb, &kb, &dkb);
        ck_assert_msg(hypot(b[0] - xy[2 * e], b[1] - xy[2 * e + 1]) <= tol * ext,
                      "piece %zu misses point %zu by %g", j, e, hypot(b[0] - xy[2 * e], b[1] - xy[2 * e + 1]));
        ck_assert_close(tha, r->angles[j], 1e-12 * (1.0 + fabs(tha)));
        ck_assert_close(ka, r->curvatures[j], 1e-9 * (1.0 + kmax));
        kseen = fmax(kseen, fmax(fabs(ka), fabs(kb)));
        /* one tension: sigma = 2 mu (2k^2 - 1) (seed 004 / smooth section) */
        if (p->k != 0.0) {
            const double sg = 2.0 * p->mu * (2.0 * p->k * p->k - 1.0);
            ck_assert_msg(fabs(sg - r->sigmas[j]) <= 1e-8 * (fabs(r->sigmas[j]) + 4.0 * p->mu),
                          "piece %zu tension %.17g, spline %.17g", j, sg, r->sigmas[j]);
        }
        const int g2span = !o->closed && ((j == 0 && o->start.kind == EL_SPLINE_G2) ||
                                          (j == m - 1 && o->end.kind == EL_SPLINE_G2));
        if (!g2span) ck_assert_close(r->sigmas[j], r->sigma, 1e-12 * (1.0 + fabs(r->sigma)));
        /* the force F = (sigma - kappa^2) T - 2 kappa' N, constant along the piece */
        const double s = r->sigmas[j], Fs = 1.0 + fabs(s) + kmax * kmax;
        const double Fb[2] = {(s - kb * kb) * cos(thb) + 2.0 * dkb * sin(thb),
                              (s - kb * kb) * sin(thb) - 2.0 * dkb * cos(thb)};
        const double Fa[2] = {(s - ka * ka) * cos(tha) + 2.0 * dka * sin(tha),
                              (s - ka * ka) * sin(tha) - 2.0 * dka * cos(tha)};
        ck_assert_msg(hypot(Fa[0] - r->forces[2 * j], Fa[1] - r->forces[2 * j + 1]) <= 1e-6 * Fs,
                      "piece %zu force at 0 %g %g vs %g %g", j, Fa[0], Fa[1], r->forces[2 * j], r->forces[2 * j + 1]);
        ck_assert_msg(hypot(Fb[0] - r->forces[2 * j], Fb[1] - r->forces[2 * j + 1]) <= 1e-6 * Fs,
                      "piece %zu force not constant: %g %g vs %g %g", j, Fb[0], Fb[1], r->forces[2 * j], r->forces[2 * j + 1]);
        /* G1 and G2 at the next point */
        if (o->closed || j + 1 < m) {
            const el_smooth_params *q = &r->pieces[e % m];
            double c[2], thc, kc;
            state_at(q, 0.0, c, &thc, &kc, NULL);
            ck_assert_msg(fabs(wrap(thb - thc)) <= tol, "tangent jump %g at point %zu", wrap(thb - thc), e);
            ck_assert_msg(fabs(kb - kc) <= 1e-7 * kmax + 1e-300, "curvature jump %g at point %zu (max %g)",
                          fabs(kb - kc), e, kmax);
            /* a frictionless duck: its load F_j - F_{j+1} is normal to the batten
             * (the tension is common) */
            if (!g2span && !(e == m - 1 && !o->closed && o->end.kind == EL_SPLINE_G2) &&
                !(o->closed ? 0 : (e == 1 && o->start.kind == EL_SPLINE_G2))) {
                const double D[2] = {r->forces[2 * j] - r->forces[2 * (e % m)],
                                     r->forces[2 * j + 1] - r->forces[2 * (e % m) + 1]};
                ck_assert_msg(fabs(D[0] * cos(thc) + D[1] * sin(thc)) <= 1e-6 * Fs,
                              "duck %zu pushes along the batten: %g", e, D[0] * cos(thc) + D[1] * sin(thc));
            }
        } else {
            ck_assert_close(thb, r->angles[r->npoints - 1], 1e-12 * (1.0 + fabs(thb)));
            ck_assert_close(kb, r->curvatures[r->npoints - 1], 1e-9 * (1.0 + kmax));
        }
        double En;
        ck_assert_int_eq(el_smooth_energy(p, &En), EL_OK);
        E += En;
        L += p->length;
    }
    ck_assert_close(r->energy, E, 1e-12 * (1.0 + E));
    ck_assert_close(r->length, L, 1e-12 * L);
    ck_assert_msg(kseen <= kmax * (1.0 + 1e-12), "curvature %g above max_curvature %g", kseen, kmax);
    ck_assert_msg(r->residual <= o->tol, "residual %g", r->residual);
    if (o->mode == EL_SPLINE_LENGTH) ck_assert_close(L, o->length, 1e-9 * o->length);
    if (!o->closed) {
        const el_spline_end *ends[2] = {&o->start, &o->end};
        const size_t at[2] = {0, r->npoints - 1};
        for (int i = 0; i < 2; i++) {
            const double k = r->curvatures[at[i]];
            if (ends[i]->kind == EL_SPLINE_NATURAL)
                ck_assert_msg(fabs(k) <= 1e-9 * (1.0 + kmax), "natural end %d has kappa %g", i, k);
            if (ends[i]->kind != EL_SPLINE_NATURAL) {
                const double ta = atan2(ends[i]->tangent[1], ends[i]->tangent[0]);
                ck_assert_msg(fabs(wrap(r->angles[at[i]] - ta)) <= tol, "end %d tangent off by %g", i,
                              wrap(r->angles[at[i]] - ta));
            }
            if (ends[i]->kind == EL_SPLINE_G2)
                ck_assert_close(k, ends[i]->curvature, 1e-9 * (1.0 + kmax));
        }
    }
}

static int solve(const double *xy, size_t n, const el_spline_options *o, el_spline_result *r)
{
    return el_spline_solve(xy, n, o, r);
}

static el_spline_options opts(int mode, double v)
{
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.mode = mode;
    if (mode == EL_SPLINE_TENSION) o.sigma = v;
    else o.length = v;
    return o;
}

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
        double J[25], g0[5], g1[5], M[25], d[9];
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

/* The implicit-function derivatives d(kappa(0), kappa(L), L)/d(ta, tb, sigma) of a
 * Hermite piece against Hermite solutions (el_hermite_solve) of perturbed data:
 * the solution continuing the piece (nearest kappa0) on either side. */
START_TEST(implicit_derivatives_match_hermite_solutions)
{
    for (size_t c = 0; c < 3; c++) {
        const el_smooth_params p = test_pieces[c];
        double J[25], g0[5], g1[5], M[25], d[9];
        ck_assert_int_eq(el__spline_piece_jacobians(&p, J, g0, g1, M, d), EL_OK);
        const double sv[2] = {0.0, p.length};
        double xy[4], th[2], ka[2];
        ck_assert_int_eq(el_smooth_eval(&p, 2, sv, xy, th, ka), EL_OK);
        const double sigma = 2.0 * p.mu * (2.0 * p.k * p.k - 1.0);
        for (int v = 0; v < 3; v++) {
            double out[2][3];
            for (int sgn = 0; sgn < 2; sgn++) {
                const double e = (sgn ? 1.0 : -1.0) * 1e-5;
                const double ta = th[0] + (v == 0 ? e : 0.0), tb = th[1] + (v == 1 ? e : 0.0);
                const double t0[2] = {cos(ta), sin(ta)}, t1[2] = {cos(tb), sin(tb)};
                el_hermite_options ho;
                el_hermite_options_defaults(&ho);
                ho.sigma = sigma + (v == 2 ? e : 0.0);
                ho.samples = 100;
                el_hermite_result hr;
                ck_assert_int_eq(el_hermite_solve(xy, t0, xy + 2, t1, &ho, &hr), EL_OK);
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
                ck_assert_msg(fabs(fd - d[3 * r + v]) <= 1e-4 * (1.0 + fabs(fd)),
                              "piece %zu d[%d][%d] %.10g vs hermite %.10g", c, r, v, d[3 * r + v], fd);
            }
        }
    }
}
END_TEST

/* ------------------------------------------------------------------ splines */

/* hand-placed, unevenly spaced points of a fair curve (a designer's sketch) */
static const double sketch[] = {0.0, 0.0, 0.7, 0.45, 1.1, 0.62, 2.6, 0.9, 3.0, 0.85,
                                4.8, 0.2, 5.5, -0.3, 7.9, -0.6, 8.2, -0.55};
enum { NSKETCH = 9 };

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

/* E(angles) = sum of integral kappa^2 + sigma ds over the Hermite pieces through
 * the points with those tangent angles; its derivative in the angle at point i
 * is 2 (kappa_i^- - kappa_i^+) (the first variation's boundary terms), zero at
 * the spline: checked by finite differences of E (pieces by el_hermite_solve)
 * at the spline and, as a control, away from it. */
static double hermite_energy(const double *xy, size_t n, const double *th, double sigma,
                             const el_spline_result *near, double *kjump, size_t at)
{
    double E = 0.0, k_end = 0.0;
    for (size_t j = 0; j + 1 < n; j++) {
        const double t0[2] = {cos(th[j]), sin(th[j])}, t1[2] = {cos(th[j + 1]), sin(th[j + 1])};
        el_hermite_options ho;
        el_hermite_options_defaults(&ho);
        ho.sigma = sigma;
        ho.samples = 60;
        el_hermite_result hr;
        ck_assert_int_eq(el_hermite_solve(xy + 2 * j, t0, xy + 2 * j + 2, t1, &ho, &hr), EL_OK);
        size_t best = hr.count;
        for (size_t i = 0; i < hr.count; i++)   /* the one continuing the spline's piece */
            if (best == hr.count || fabs(hr.solutions[i].length - near->pieces[j].length) <
                                    fabs(hr.solutions[best].length - near->pieces[j].length))
                best = i;
        ck_assert_uint_lt(best, hr.count);
        E += hr.solutions[best].energy + sigma * hr.solutions[best].length;
        if (j + 1 == at) k_end = hr.solutions[best].kappa1;
        if (j == at && kjump) *kjump = k_end - hr.solutions[best].kappa0;
        el_hermite_result_free(&hr);
    }
    return E;
}

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

START_TEST(length_mode_meets_the_length_and_the_tension_mode)
{
    el_spline_options t = opts(EL_SPLINE_TENSION, 0.0);
    el_spline_result r0;
    ck_assert_int_eq(solve(sketch, NSKETCH, &t, &r0), EL_OK);
    const double Lfree = r0.length;
    el_spline_result_free(&r0);
    double polygon = 0.0;
    for (int i = 0; i + 1 < NSKETCH; i++)
        polygon += hypot(sketch[2 * i + 2] - sketch[2 * i], sketch[2 * i + 3] - sketch[2 * i + 1]);
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
        el_spline_options o = opts(EL_SPLINE_TENSION, sig[i]);
        o.closed = 1;
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
    el_spline_options o = opts(EL_SPLINE_LENGTH, 10.0);
    o.closed = 1;
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
    ck_assert_msg(fabs(r.sigmas[0] - 1.0) > 1e-6, "the G2 span keeps sigma %g", r.sigmas[0]);
    el_spline_result_free(&r);
    /* G2 at both ends, in length mode */
    o.end.kind = EL_SPLINE_G2;
    o.end.curvature = -0.3;
    o.mode = EL_SPLINE_LENGTH;
    o.length = 9.2;
    ck_assert_int_eq(solve(sketch, NSKETCH, &o, &r), EL_OK);
    check_spline(sketch, NSKETCH, &o, &r, 1e-9);
    el_spline_result_free(&r);
    /* two points, G2 at one end, a tangent at the other: the span's tension */
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

/*
 * A tight batten with natural ends (sigma h^2 = 40..70 on the mean chord of
 * 33 scanned-like points): the end pieces run from an inflection at the free
 * end into the boundary layer at the next duck, with 1 - k^2 down to 1e-8.
 * Each piece's u is put with its larger-curvature end near u = 0, where its
 * curvature does not hang on K(k), which k's last bit moves by 1e-16 / (1 - k^2):
 * the residual stays below tol (it was 2e-10..4e-9 with u near 2K).
 */
static const double scan33[] = {
    0, 0.142, 0.315, 0.182, 0.604, 0.152, 0.866, 0.208, 1.101, 0.364, 1.309, 0.541, 1.494, 0.673,
    1.659, 0.737, 1.809, 0.743, 1.949, 0.71, 2.086, 0.66, 2.225, 0.61, 2.373, 0.579, 2.534, 0.587,
    2.713, 0.648, 2.914, 0.748, 3.139, 0.83, 3.389, 0.806, 3.663, 0.64, 3.96, 0.429, 4.277, 0.345,
    4.611, 0.393, 4.955, 0.347, 5.306, 0.075, 5.655, -0.22, 5.999, -0.304, 6.329, -0.263, 6.643,
    -0.326, 6.934, -0.529, 7.2, -0.725, 7.438, -0.802, 7.648, -0.769, 7.831, -0.692};

START_TEST(natural_ends_under_high_tension_reach_tol)
{
    double Lp = 0.0;
    for (int i = 0; i + 1 < 33; i++) Lp += hypot(scan33[2 * i + 2] - scan33[2 * i], scan33[2 * i + 3] - scan33[2 * i + 1]);
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
    /* G2 without a span of its own */
    o = opts(EL_SPLINE_TENSION, 1.0);
    o.start.kind = o.end.kind = EL_SPLINE_G2;
    o.start.tangent[0] = o.end.tangent[0] = 1.0;
    ck_assert_int_eq(solve(sketch, 2, &o, &r), EL_EDOM);
    o.mode = EL_SPLINE_LENGTH;
    o.length = 20.0;
    ck_assert_int_eq(solve(sketch, 3, &o, &r), EL_EDOM);
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
    tcase_add_test(tc, spline_is_a_critical_point_of_the_energy);
    tcase_add_test(tc, length_mode_meets_the_length_and_the_tension_mode);
    tcase_add_test(tc, length_mode_newton_equals_the_continuation);
    tcase_add_test(tc, closed_curves);
    tcase_add_test(tc, clamped_and_g2_ends);
    tcase_add_test(tc, degenerate_inputs);
    tcase_add_test(tc, buckled_collinear_batten_takes_its_first_mode);
    tcase_add_test(tc, extreme_scales);
    tcase_add_test(tc, many_points);
    tcase_add_test(tc, natural_ends_under_high_tension_reach_tol);
    tcase_add_test(tc, free_batten_that_does_not_exist);
    tcase_add_test(tc, bad_input_and_clear_statuses);
    tcase_add_test(tc, bspline_is_one_g2_curve_within_tol);
    tcase_add_test(tc, smooth_to_bspline_g2_has_exact_ends);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
