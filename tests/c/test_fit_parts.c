/* The pieces of the fit (libelastica/fit_internal.h) against their plain counterparts:
 * the blocked walk over a discrete curve against one Jacobian call, the end states'
 * derivatives and the keyline map's against finite differences, the start's search for
 * nearer branches against the full one. */
#include "fit_check.h"
#include <string.h>

/* Vertices and d gamma / d v walked in blocks of every size equal one call over the
 * whole curve, for k across 1 and the continuation -1 < k < 0; by columns (the paired
 * fit's layout) the same numbers as by rows. */
/* The map m at x moved by +-h in variable j: vp, vm (the central differences' points). */
static void map_at_offsets(const fit_map *m, const double *x, int j, double h, double vp[2][FIT_NP],
                           double vm[2][FIT_NP])
{
    double xp[FIT_MAXX], xm[FIT_MAXX];
    memcpy(xp, x, sizeof xp); memcpy(xm, x, sizeof xm);
    xp[j] += h; xm[j] -= h;
    ck_assert_int_eq(el__fit_map_eval(m, xp, vp, NULL), EL_OK);
    ck_assert_int_eq(el__fit_map_eval(m, xm, vm, NULL), EL_OK);
}

START_TEST(test_blocked_discrete_walk_equals_one_call)
{
    const size_t sizes[] = {2, 3, 17, 255, 256, 257, 600};
    const double ks[] = {0.3, 0.999, 1.0, 1.7, 25.0, -0.4};
    double tmp[FIT_WORK];
    for (size_t a = 0; a < sizeof sizes / sizeof sizes[0]; a++)
        for (size_t b = 0; b < sizeof ks / sizeof ks[0]; b++) {
            const size_t n = sizes[a];
            const double v[7] = {0.3, -0.7, 2.0 / (double)n, 0.4, 3.0 / (double)n, 0.25, ks[b]};
            el_discrete_params p;
            double dq;
            ck_assert_int_eq(el__fit_to_discrete(v, &p, &dq), EL_OK);
            double *xy = malloc(sizeof(double) * 2 * n), *jac = malloc(sizeof(double) * 14 * n);
            double *wxy = malloc(sizeof(double) * 2 * n), *wjac = malloc(sizeof(double) * 14 * n);
            ck_assert_int_eq(el_discrete_jacobian(&p, n, xy, jac), EL_OK);
            if (v[6] < 0.0)        /* the continuation's k column: d/dk of (|k|, q + 2K(|k|)) */
                for (size_t i = 0; i < 2 * n; i++) jac[i * 7 + 6] = -(jac[i * 7 + 6] + dq * jac[i * 7 + 5]);
            for (size_t blk = 1; blk <= 300; blk = blk * 3 + 1) {
                fit_walk w, wc;
                el__fit_walk_start(v, &w);
                el__fit_walk_start(v, &wc);
                double *col = malloc(sizeof(double) * 14 * blk), cxy[2 * 300];
                for (size_t s = 0; s < n; s += blk) {
                    const size_t m = n - s < blk ? n - s : blk;
                    ck_assert_int_eq(el__fit_discrete_rows(v, &w, m, wxy + 2 * s, wjac + 14 * s, 0, tmp), EL_OK);
                    ck_assert_int_eq(el__fit_discrete_rows(v, &wc, m, cxy, col, 2 * blk, tmp), EL_OK);
                    for (size_t r = 0; r < 2 * m; r++) {
                        ck_assert(cxy[r] == wxy[2 * s + r]);
                        for (int j = 2; j < 7; j++) ck_assert(col[(size_t)j * 2 * blk + r] == wjac[(2 * s + r) * 7 + j]);
                    }
                }
                free(col);
                double scale = 1.0, e = 0.0;
                for (size_t i = 0; i < 14 * n; i++) {
                    scale = fmax(scale, fabs(jac[i]));
                    e = fmax(e, fabs(wjac[i] - jac[i]));
                }
                for (size_t i = 0; i < 2 * n; i++) e = fmax(e, fabs(wxy[i] - xy[i]));
                ck_assert_msg(e <= 1e-12 * scale, "n %zu k %g block %zu: %g", n, ks[b], blk, e / scale);
            }
            free(xy); free(jac); free(wxy); free(wjac);
        }
}
END_TEST

/* Point, tangent angle and curvature at both ends, and their derivatives in v, against
 * central differences, both models, inflectional and looping, w < 0 and k < 0. */
START_TEST(test_end_state_derivatives)
{
    double tmp[FIT_WORK];
    const double smooth[][7] = {{0.3, -0.2, 0.4, 1.3, 0.7, 0.2, 2.5}, {0.3, -0.2, 0.4, -1.3, -0.4, 0.2, 2.5},
                                {0.1, 0.5, -1.0, 0.8, 2.5, -0.3, 4.0}, {0.1, 0.5, -1.0, 0.8, -1.7, 0.9, 3.0}};
    const double discrete[][7] = {{0.3, -0.2, 0.01, 0.4, 0.02, 0.3, 0.6}, {0.3, -0.2, 0.01, 0.4, -0.03, 0.3, -0.4},
                                  {0.0, 0.0, 0.05, 1.0, 0.05, -0.2, 2.0}};
    for (int model = 0; model < 2; model++) {
        const size_t cnt = model == FIT_SMOOTH ? 4 : 3;
        for (size_t a = 0; a < cnt; a++)
            for (int at_end = 0; at_end < 2; at_end++) {
                const double *v = model == FIT_SMOOTH ? smooth[a] : discrete[a];
                const size_t n = 60;
                fit_end e, ep, em;
                ck_assert_int_eq(el__fit_end_state(model, v, n, at_end, &e, tmp), EL_OK);
                for (int j = 0; j < 7; j++) {
                    const double h = 1e-6 * (1.0 + fabs(v[j]));
                    double vp[7], vm[7];
                    memcpy(vp, v, sizeof vp); memcpy(vm, v, sizeof vm);
                    vp[j] += h; vm[j] -= h;
                    ck_assert_int_eq(el__fit_end_state(model, vp, n, at_end, &ep, tmp), EL_OK);
                    ck_assert_int_eq(el__fit_end_state(model, vm, n, at_end, &em, tmp), EL_OK);
                    const double fd[4] = {(ep.xy[0] - em.xy[0]) / (2 * h), (ep.xy[1] - em.xy[1]) / (2 * h),
                                          remainder(ep.theta - em.theta, 2 * M_PI) / (2 * h),
                                          (ep.kappa - em.kappa) / (2 * h)};
                    const double an[4] = {e.dxy[0][j], e.dxy[1][j], e.dtheta[j], e.dkappa[j]};
                    for (int q = 0; q < 4; q++)
                        ck_assert_msg(fabs(fd[q] - an[q]) <= 1e-6 * (1.0 + fabs(fd[q])),
                                      "model %d case %zu end %d v%d quantity %d: %g vs %g", model, a,
                                      at_end, j, q, an[q], fd[q]);
                }
            }
    }
    /* the states themselves: the smooth curve's own evaluation */
    el_smooth_params p;
    ck_assert_int_eq(el__fit_to_smooth(smooth[2], &p), EL_OK);
    double s[2] = {0.0, p.length}, xy[4], th[2], ka[2];
    ck_assert_int_eq(el_smooth_eval(&p, 2, s, xy, th, ka), EL_OK);
    for (int at_end = 0; at_end < 2; at_end++) {
        fit_end e;
        ck_assert_int_eq(el__fit_end_state(FIT_SMOOTH, smooth[2], 0, at_end, &e, tmp), EL_OK);
        ck_assert_close(e.xy[0], xy[2 * at_end], 1e-13);
        ck_assert_close(e.kappa, ka[at_end], 1e-13);
        ck_assert(fabs(remainder(e.theta - th[at_end], 2 * M_PI)) <= 1e-13);
    }
}
END_TEST

/* The discrete end tangent is the vertex tangent theta_j = phi + 2 a_j (a tangent
 * constraint's meaning): checked by its defining identity, seed 000 (4.4), segment j
 * running at the mean of theta_j and theta_j+1 (both from el__fit_end_state, the end
 * vertex of the polygon cut after vertex j and j+1), at every segment of 30-vertex
 * polygons, k across 1 and k < 0 (the internal sign, |k| with q + 2K). */
START_TEST(test_discrete_vertex_tangents)
{
    double tmp[FIT_WORK];
    const double cases[][7] = {{0.3, -0.2, 0.01, 0.4, 0.02, 0.3, 0.6}, {0.3, -0.2, 0.01, 0.4, -0.03, 0.3, -0.4},
                               {0.0, 0.0, 0.05, 1.0, 0.05, -0.2, 2.0}, {0.0, 0.0, 0.05, -2.0, 0.08, 0.4, 0.999},
                               {0.0, 0.0, 0.05, -2.0, 0.08, 0.4, 1.0}, {0.0, 0.0, 0.05, -2.0, 0.08, 0.4, 1.001},
                               {1.0, 2.0, 3.0, 0.5, 0.2, -1.0, 0.1}};
    enum { N = 30 };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const double *v = cases[c];
        el_discrete_params p;
        ck_assert_int_eq(el__fit_to_discrete(v, &p, NULL), EL_OK);
        double V[2 * N];
        ck_assert_int_eq(el_discrete_eval(&p, N, V), EL_OK);
        fit_end e0, e1, s0;
        ck_assert_int_eq(el__fit_end_state(FIT_DISCRETE, v, N, 0, &s0, tmp), EL_OK);
        ck_assert_int_eq(el__fit_end_state(FIT_DISCRETE, v, 1, 1, &e0, tmp), EL_OK);   /* vertex 0 as an end */
        ck_assert(fabs(remainder(s0.theta - e0.theta, 2 * M_PI)) <= 1e-14);
        for (size_t j = 0; j + 1 < N; j++) {
            ck_assert_int_eq(el__fit_end_state(FIT_DISCRETE, v, j + 1, 1, &e0, tmp), EL_OK);
            ck_assert_int_eq(el__fit_end_state(FIT_DISCRETE, v, j + 2, 1, &e1, tmp), EL_OK);
            const double mean = e0.theta + 0.5 * remainder(e1.theta - e0.theta, 2 * M_PI);
            const double seg = atan2(V[2 * j + 3] - V[2 * j + 1], V[2 * j + 2] - V[2 * j]);
            ck_assert_msg(fabs(remainder(seg - mean, 2 * M_PI)) <= 1e-12, "case %zu segment %zu: %.17g vs %.17g", c, j,
                          seg, mean);
        }
    }
}
END_TEST

/* The keyline's joint variables: every point of them is a G2 joint (zero curvature on
 * both sides, opposite tangents: discrete, the first segments), and d v / d x matches
 * central differences. */
START_TEST(test_keyline_map_is_g2_with_its_derivative)
{
    double tmp[FIT_WORK];
    for (int model = 0; model < 2; model++)
        for (int held = 0; held < 1 + (model == FIT_DISCRETE); held++) {
            fit_map m;
            memset(&m, 0, sizeof m);
            m.model = model; m.ncurves = 2;
            m.nx = held ? 7 : 9;
            m.fixed_h = held ? 0.02 : 0.0;
            m.scale[0] = 40.0; m.scale[1] = 60.0;
            const double xs[9] = {0.2, -0.1, 0.7, model ? 1.3 : 0.8, model ? 0.45 : 1.2, model ? 2.0 : -0.35,
                                  model ? 0.9 : 1.0, model ? -0.3 : 0.9, model ? 3.0 : 0.5};
            double x[FIT_MAXX];
            if (held) { const int cols[7] = {0, 1, 2, 4, 5, 7, 8}; for (int j = 0; j < 7; j++) x[j] = xs[cols[j]]; }
            else memcpy(x, xs, sizeof xs);
            double v[2][FIT_NP], M[2 * FIT_NP * FIT_MAXX];
            ck_assert_int_eq(el__fit_map_eval(&m, x, v, M), EL_OK);
            fit_end e[2];
            for (int c = 0; c < 2; c++) {
                ck_assert_int_eq(el__fit_end_state(model, v[c], 50, 0, &e[c], tmp), EL_OK);
                ck_assert_msg(fabs(e[c].kappa) <= 1e-12, "model %d side %d kappa %g", model, c, e[c].kappa);
            }
            ck_assert(fabs(e[0].xy[0] - e[1].xy[0]) == 0.0 && fabs(e[0].xy[1] - e[1].xy[1]) == 0.0);
            /* discrete: the polygon runs straight through the joint, its first segments
             * opposite (the vertex tangents of el__fit_end_state need not be) */
            double th[2] = {e[0].theta, e[1].theta};
            for (int c = 0; c < 2 && model == FIT_DISCRETE; c++) {
                el_discrete_params p;
                double V[4];
                ck_assert_int_eq(el__fit_to_discrete(v[c], &p, NULL), EL_OK);
                ck_assert_int_eq(el_discrete_eval(&p, 2, V), EL_OK);
                th[c] = atan2(V[3] - V[1], V[2] - V[0]);
            }
            ck_assert_msg(fabs(remainder(th[0] - th[1] - M_PI, 2 * M_PI)) <= 1e-13,
                          "model %d tangents %g %g", model, th[0], th[1]);
            for (int j = 0; j < m.nx; j++) {
                const double h = 1e-6 * (1.0 + fabs(x[j]));
                double vp[2][FIT_NP], vm[2][FIT_NP];
                map_at_offsets(&m, x, j, h, vp, vm);
                for (int c = 0; c < 2; c++)
                    for (int r = 0; r < FIT_NP; r++) {
                        const double fd = (vp[c][r] - vm[c][r]) / (2 * h), an = M[c * FIT_NP * FIT_MAXX + r * m.nx + j];
                        ck_assert_msg(fabs(fd - an) <= 1e-6 * (1.0 + fabs(fd)), "model %d x%d v%d%d: %g vs %g",
                                      model, j, c, r, an, fd);
                    }
            }
        }
}
END_TEST

/* The start-state chart (theta0, kappa0, F) of fit_model.c: x -> v -> x gives back the
 * same curve (points, tangent and curvature at both ends), and d v / d x carried to
 * the end point matches central differences in x; both models, k across 1 (the
 * chart's one formula for q), both signs of the curvature at the start (w or z < 0),
 * and the continuations k < 0. */
START_TEST(test_start_chart_same_curve_and_derivative)
{
    double tmp[FIT_WORK], worst = 0.0;
    const double ks[] = {0.05, 0.3, 0.9, 0.999, 1.0, 1.001, 1.5, 4.0, 30.0, -0.4, -2.0};
    for (int model = 0; model < 2; model++) {
        fit_map m;
        memset(&m, 0, sizeof m);
        m.model = model; m.ncurves = 1; m.chart = 1;
        for (int j = 0; j < FIT_NP; j++) {
            m.scale[j] = (model == FIT_DISCRETE && (j == 2 || j == 4)) ? 40.0 : 1.0;
            m.idx[m.nx++] = j;
        }
        for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++)
            for (int sgn = -1; sgn <= 1; sgn += 2)
                for (int qi = 0; qi < 3; qi++) {
                    if (model == FIT_DISCRETE && ks[a] <= -1.0) continue;
                    const double q = -0.8 + 0.7 * qi;
                    const double vs[7] = {0.3, -0.2, 0.7, sgn * 1.3, ks[a], q, 2.0};
                    const double vd[7] = {0.3, -0.2, 0.05, 0.7, sgn * 0.03, q, ks[a]};
                    const double *v = model == FIT_SMOOTH ? vs : vd;
                    double x[FIT_MAXX], w[2][FIT_NP], M[2 * FIT_NP * FIT_MAXX];
                    el__fit_map_inverse(&m, v, x);
                    ck_assert_int_eq(el__fit_map_eval(&m, x, w, M), EL_OK);
                    for (int at_end = 0; at_end < 2; at_end++) {
                        fit_end e0, e1;
                        ck_assert_int_eq(el__fit_end_state(model, v, 50, at_end, &e0, tmp), EL_OK);
                        ck_assert_int_eq(el__fit_end_state(model, w[0], 50, at_end, &e1, tmp), EL_OK);
                        const double d = fmax(fmax(fabs(e0.xy[0] - e1.xy[0]), fabs(e0.xy[1] - e1.xy[1])),
                                              fmax(fabs(remainder(e0.theta - e1.theta, 2 * M_PI)),
                                                   fabs(e0.kappa - e1.kappa)));
                        ck_assert_msg(d <= 1e-10, "model %d k %g sign %d q %g end %d: %g", model, ks[a], sgn,
                                      q, at_end, d);
                    }
                    fit_end e;
                    ck_assert_int_eq(el__fit_end_state(model, w[0], 50, 1, &e, tmp), EL_OK);
                    for (int j = 0; j < m.nx; j++) {
                        const double h = 1e-6 * (1.0 + fabs(x[j]));
                        double vp[2][FIT_NP], vm[2][FIT_NP];
                        fit_end ep, em;
                        map_at_offsets(&m, x, j, h, vp, vm);
                        ck_assert_int_eq(el__fit_end_state(model, vp[0], 50, 1, &ep, tmp), EL_OK);
                        ck_assert_int_eq(el__fit_end_state(model, vm[0], 50, 1, &em, tmp), EL_OK);
                        for (int c = 0; c < 2; c++) {
                            double an = 0.0;
                            for (int r = 0; r < FIT_NP; r++) an += e.dxy[c][r] * M[r * m.nx + j];
                            const double fd = (ep.xy[c] - em.xy[c]) / (2 * h), err = fabs(fd - an) / (1.0 + fabs(fd));
                            worst = fmax(worst, err);
                            ck_assert_msg(err <= 1e-6, "model %d k %g sign %d q %g x%d: %g vs %g", model, ks[a],
                                          sgn, q, j, an, fd);
                        }
                    }
                }
    }
    ck_assert(worst > 0.0);
}
END_TEST

/* The ends chart (a, G) of fit_model.c: the curve of a v that meets the held ends comes
 * back from x = inverse(v) (points, tangents and curvatures at both ends), x -> v lands
 * on the held end for any x, and d v / d x matches central differences in x in all seven
 * parameters; both models, k across 1, both signs of the start curvature, the
 * continuations k < 0, chords from 1e-4 to 1e4. */
START_TEST(test_ends_chart_same_curve_and_derivative)
{
    double tmp[FIT_WORK], worst = 0.0;
    const double ks[] = {0.05, 0.3, 0.9, 0.999, 1.0, 1.001, 1.5, 4.0, 30.0, -0.4, -2.0};
    const double scales[] = {1e-4, 1.0, 1e4};
    const size_t n = 50;
    for (int model = 0; model < 2; model++)
        for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++)
            for (int sgn = -1; sgn <= 1; sgn += 2)
                for (int qi = 0; qi < 3; qi++)
                    for (int si = 0; si < 3; si++) {
                        if (model == FIT_DISCRETE && ks[a] <= -1.0) continue;
                        const double q = -0.8 + 0.7 * qi, S = scales[si];
                        const double vs[7] = {0.3 * S, -0.2 * S, 0.7, sgn * 1.3 / S, ks[a], q, 2.0 * S};
                        const double vd[7] = {0.3 * S, -0.2 * S, 0.05 * S, 0.7, sgn * 0.03, q, ks[a]};
                        const double *v = model == FIT_SMOOTH ? vs : vd;
                        fit_end s0, s1;
                        ck_assert_int_eq(el__fit_end_state(model, v, n, 0, &s0, tmp), EL_OK);
                        ck_assert_int_eq(el__fit_end_state(model, v, n, 1, &s1, tmp), EL_OK);
                        fit_map m;
                        memset(&m, 0, sizeof m);
                        m.model = model; m.ncurves = 1; m.chart = FIT_CHART_ENDS;
                        for (int j = 0; j < FIT_NP; j++)
                            m.scale[j] = (model == FIT_DISCRETE && (j == 2 || j == 4)) ? (double)(n - 1) : 1.0;
                        const int slots[3] = {model == FIT_DISCRETE ? 4 : 3, fit_k_slot(model), 5};
                        for (int j = 0; j < 3; j++) m.idx[m.nx++] = slots[j];
                        m.fixed[0] = v[0]; m.fixed[1] = v[1];
                        m.chord[0] = s1.xy[0] - s0.xy[0]; m.chord[1] = s1.xy[1] - s0.xy[1];
                        double x[FIT_MAXX], w[2][FIT_NP], M[2 * FIT_NP * FIT_MAXX];
                        el__fit_map_inverse(&m, v, x);
                        ck_assert_int_eq(el__fit_map_eval(&m, x, w, M), EL_OK);
                        for (int at_end = 0; at_end < 2; at_end++) {
                            fit_end e1;
                            const fit_end *e0 = at_end ? &s1 : &s0;
                            ck_assert_int_eq(el__fit_end_state(model, w[0], n, at_end, &e1, tmp), EL_OK);
                            const double d = fmax(fmax(fabs(e0->xy[0] - e1.xy[0]), fabs(e0->xy[1] - e1.xy[1])) / S,
                                                  fmax(fabs(remainder(e0->theta - e1.theta, 2 * M_PI)),
                                                       fabs(e0->kappa - e1.kappa) * S));
                            ck_assert_msg(d <= 1e-10, "model %d k %g sign %d q %g scale %g end %d: %g", model,
                                          ks[a], sgn, q, S, at_end, d);
                        }
                        for (int j = 0; j < m.nx; j++) {
                            const double h = 1e-6 * (1.0 + fabs(x[j]));
                            double vp[2][FIT_NP], vm[2][FIT_NP];
                            map_at_offsets(&m, x, j, h, vp, vm);
                            /* a shape moved by x: its end still on the held end */
                            fit_end ep;
                            ck_assert_int_eq(el__fit_end_state(model, vp[0], n, 1, &ep, tmp), EL_OK);
                            ck_assert_msg(fmax(fabs(ep.xy[0] - s1.xy[0]), fabs(ep.xy[1] - s1.xy[1])) <= 1e-12 * S,
                                          "model %d k %g: end moved", model, ks[a]);
                            for (int r = 0; r < FIT_NP; r++) {
                                const double diff = r == (model == FIT_DISCRETE ? 3 : 2)
                                                  ? remainder(vp[0][r] - vm[0][r], 2 * M_PI) : vp[0][r] - vm[0][r];
                                const double fd = diff / (2 * h), an = M[r * m.nx + j];
                                const double ref = fabs(w[0][r]) / (1.0 + fabs(x[j])) + 1.0;
                                const double err = fabs(fd - an) / (ref + fabs(fd));
                                worst = fmax(worst, err);
                                ck_assert_msg(err <= 1e-6, "model %d k %g sign %d q %g scale %g x%d v%d: %g vs %g",
                                              model, ks[a], sgn, q, S, j, r, an, fd);
                            }
                        }
                    }
    ck_assert(worst > 0.0);
}
END_TEST

/* The ends chart with a zero start curvature held (a = 0 in fixed[], x = (Gx, Gy):
 * el__fit_ends_held): every shape it gives starts with curvature 0 exactly and ends on the
 * held end, x comes back from its curve (el__fit_map_inverse), and d v / d x matches central
 * differences; both models, G in 16 directions (k = |sin(delta / 2)| from 0.02 to 1, both
 * signs of the start's turn) and three magnitudes, chords from 1e-4 to 1e4. */
START_TEST(test_ends_chart_held_zero_start_curvature)
{
    double tmp[FIT_WORK], worst = 0.0;
    const double mags[] = {0.3, 4.0, 60.0}, scales[] = {1e-4, 1.0, 1e4};
    const size_t n = 50;
    for (int model = 0; model < 2; model++)
        for (int di = 0; di < 16; di++)
            for (size_t gi = 0; gi < sizeof mags / sizeof mags[0]; gi++)
                for (size_t si = 0; si < sizeof scales / sizeof scales[0]; si++) {
                    const double ang = -M_PI + (di + 0.5) * (2.0 * M_PI / 16.0), S = scales[si];
                    const int wslot = model == FIT_DISCRETE ? 4 : 3;
                    fit_map m;
                    memset(&m, 0, sizeof m);
                    m.model = model; m.ncurves = 1; m.chart = FIT_CHART_ENDS;
                    for (int j = 0; j < FIT_NP; j++)
                        m.scale[j] = (model == FIT_DISCRETE && (j == 2 || j == 4)) ? (double)(n - 1) : 1.0;
                    m.idx[m.nx++] = fit_k_slot(model);
                    m.idx[m.nx++] = 5;
                    m.fixed[0] = 0.3 * S; m.fixed[1] = -0.2 * S; m.fixed[wslot] = 0.0;
                    m.chord[0] = 0.8 * S; m.chord[1] = 0.5 * S;
                    const double x[FIT_MAXX] = {mags[gi] * cos(ang), mags[gi] * sin(ang)};   /* map_at_offsets' size */
                    double w[2][FIT_NP], M[2 * FIT_NP * FIT_MAXX], xi[FIT_MAXX];
                    if (el__fit_map_eval(&m, x, w, M) != EL_OK) continue;    /* a closed shape (e = 0) */
                    fit_end e0, e1;
                    ck_assert_int_eq(el__fit_end_state(model, w[0], n, 0, &e0, tmp), EL_OK);
                    ck_assert_int_eq(el__fit_end_state(model, w[0], n, 1, &e1, tmp), EL_OK);
                    ck_assert_msg(fabs(e0.kappa) * S <= 1e-12, "model %d dir %d |G| %g scale %g: kappa0 %g", model, di,
                                  mags[gi], S, e0.kappa);
                    ck_assert(fmax(fabs(e1.xy[0] - e0.xy[0] - m.chord[0]), fabs(e1.xy[1] - e0.xy[1] - m.chord[1])) <=
                              1e-12 * S);
                    el__fit_map_inverse(&m, w[0], xi);
                    for (int j = 0; j < 2; j++)
                        ck_assert_msg(fabs(xi[j] - x[j]) <= 1e-9 * (1.0 + fabs(x[j])), "model %d dir %d: x%d %g back as %g",
                                      model, di, j, x[j], xi[j]);
                    for (int j = 0; j < m.nx; j++) {
                        const double h = 1e-6 * (1.0 + fabs(x[j]));
                        double vp[2][FIT_NP], vm[2][FIT_NP];
                        map_at_offsets(&m, x, j, h, vp, vm);
                        for (int r = 0; r < FIT_NP; r++) {
                            const double diff = r == (model == FIT_DISCRETE ? 3 : 2)
                                              ? remainder(vp[0][r] - vm[0][r], 2 * M_PI) : vp[0][r] - vm[0][r];
                            const double fd = diff / (2 * h), an = M[r * m.nx + j];
                            const double err = fabs(fd - an) / (fabs(w[0][r]) / (1.0 + fabs(x[j])) + 1.0 + fabs(fd));
                            worst = fmax(worst, err);
                            ck_assert_msg(err <= 1e-6, "model %d dir %d |G| %g scale %g x%d v%d: %g vs %g", model, di,
                                          mags[gi], S, j, r, an, fd);
                        }
                    }
                }
    ck_assert(worst > 0.0);
}
END_TEST

/* The discrete orthogonal objective's gradient J^T r / n (the distances to the polygon,
 * feet held: variable projection) against central differences of f, on unevenly spaced
 * noisy points over three blocks of the walk (the next block's first vertex enters the
 * last segment of a block), for k < 1, k > 1 and the continuation -1 < k < 0. */
START_TEST(test_discrete_orthogonal_gradient)
{
    enum { N = 2 * FIT_BLOCK + 40 };
    static double xy[2 * N];
    unsigned long long rng = 7;
    const double ks[] = {0.4, 1.6, -0.5};
    double worst = 0.0;
    for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++) {
        const double v[FIT_NP] = {0.1, -0.2, 0.004, 0.4, 0.006, 0.3, ks[a]};
        el_discrete_params p;
        ck_assert_int_eq(el__fit_to_discrete(v, &p, NULL), EL_OK);
        static double V[2 * N];
        ck_assert_int_eq(el_discrete_eval(&p, N, V), EL_OK);
        /* points along the polygon at uneven places, off it by noise */
        for (size_t i = 0; i < N; i++) {
            const double t = (double)i / (N - 1);
            double u = (N - 1) * (t + 0.15 * sin(2 * M_PI * t) / (2 * M_PI) * 3.0 * t * (1 - t));
            if (i >= FIT_BLOCK - 40 && i < FIT_BLOCK - 10)    /* 30 points on a block's last segment */
                u = FIT_BLOCK - 1 + (double)(i - (FIT_BLOCK - 40)) / 30.0;
            const size_t j = (size_t)fmin(fmax(floor(u), 0.0), N - 2.0);
            const double f = fmin(fmax(u - (double)j, 0.0), 1.0);
            for (int c = 0; c < 2; c++)
                xy[2 * i + c] = V[2 * j + c] + f * (V[2 * j + 2 + c] - V[2 * j + c]) + 2e-3 * test_uniform(&rng, -1, 1);
            if (i >= FIT_BLOCK - 40 && i < FIT_BLOCK - 10) {   /* large residuals there, along the normal */
                const double sx = V[2 * j + 2] - V[2 * j], sy = V[2 * j + 3] - V[2 * j + 1], l = hypot(sx, sy);
                xy[2 * i] -= 3.0 * v[2] * sy / l;
                xy[2 * i + 1] += 3.0 * v[2] * sx / l;
            }
        }
        fit_map m;
        memset(&m, 0, sizeof m);
        m.model = FIT_DISCRETE; m.ncurves = 1;
        for (int j = 0; j < FIT_NP; j++) {
            m.scale[j] = (j == 2 || j == 4) ? (double)(N - 1) : 1.0;
            m.idx[m.nx++] = j;
        }
        fit_objective o;
        ck_assert_int_eq(el__fit_objective_init(&o, FIT_ORTHOGONAL, &m, xy, N, 0.0, 0.0, 1.0, NULL), EL_OK);
        double x[FIT_MAXX];
        double vp[FIT_NP];
        memcpy(vp, v, sizeof vp);
        vp[3] += 1e-4;
        el__fit_map_inverse(&m, vp, x);
        fit_value val;
        ck_assert_int_eq(el__fit_objective_eval(&o, x, 1, &val), EL_OK);
        for (int j = 0; j < m.nx; j++) {
            const double h = 1e-7 * (1.0 + fabs(x[j]));
            double xp[FIT_MAXX], xm[FIT_MAXX];
            fit_value fp, fm;
            memcpy(xp, x, sizeof xp); memcpy(xm, x, sizeof xm);
            xp[j] += h; xm[j] -= h;
            ck_assert_int_eq(el__fit_objective_eval(&o, xp, 0, &fp), EL_OK);
            ck_assert_int_eq(el__fit_objective_eval(&o, xm, 0, &fm), EL_OK);
            const double fd = (fp.f - fm.f) / (2 * h);
            double gmax = 0.0;
            for (int i = 0; i < m.nx; i++) gmax = fmax(gmax, fabs(val.g[i]));
            const double err = fabs(fd - val.g[j]) / gmax;
            worst = fmax(worst, err);
            ck_assert_msg(err <= 1e-5, "k %g x%d: %g vs %g", ks[a], j, val.g[j], fd);
        }
        el__fit_objective_free(&o);
    }
    ck_assert(worst > 0.0);
}
END_TEST

/* The discrete paired objective's normal equations (fold_paired: the x0, y0 columns not
 * stored, their products as sums of every other entry and counts of ones) against the
 * plain g = J^T r / n and H = J^T J / n from el_discrete_jacobian, over three blocks of
 * the walk on noisy points, for k < 1, k > 1 and -1 < k < 0 (v's k is then -|k| with
 * q + 2K(|k|): the chain rule dk/dv = -1, dq/dv = -d2K/d|k|). */
START_TEST(test_discrete_paired_normal_equations_equal_plain_ones)
{
    enum { N = 2 * FIT_BLOCK + 37 };
    static double xy[2 * N], V[2 * N], J[2 * N * FIT_NP];
    unsigned long long rng = 11;
    const double ks[] = {0.4, 1.6, -0.5};
    for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++) {
        const double v[FIT_NP] = {0.1, -0.2, 0.004, 0.4, 0.006, 0.3, ks[a]};
        el_discrete_params p;
        double dq_dk;
        ck_assert_int_eq(el__fit_to_discrete(v, &p, &dq_dk), EL_OK);
        ck_assert_int_eq(el_discrete_jacobian(&p, N, V, J), EL_OK);
        for (size_t i = 0; i < 2 * N; i++)   /* noise up to 50 % of a segment */
            xy[i] = V[i] + 2e-3 * test_uniform(&rng, -1, 1);
        if (v[6] < 0.0)                      /* d/dv6 = -d/dk - d2K/d|k| d/dq */
            for (size_t r = 0; r < 2 * N; r++)
                J[r * FIT_NP + 6] = -J[r * FIT_NP + 6] - dq_dk * J[r * FIT_NP + 5];
        const fit_map m = all_free_unscaled(FIT_DISCRETE);
        fit_objective o;
        ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, N, 0.0, 0.0, 1.0, NULL), EL_OK);
        double x[FIT_MAXX];
        el__fit_map_inverse(&m, v, x);
        fit_value val;
        ck_assert_int_eq(el__fit_objective_eval(&o, x, 1, &val), EL_OK);
        /* and the sums of the terms' magnitudes, the scale of their rounding */
        double f = 0.0, g[FIT_NP] = {0}, H[FIT_NP][FIT_NP] = {{0}}, ga[FIT_NP] = {0}, Ha[FIT_NP][FIT_NP] = {{0}};
        for (size_t r = 0; r < 2 * N; r++) {
            const double res = V[r] - xy[r], *row = J + r * FIT_NP;
            f += res * res;
            for (int i = 0; i < FIT_NP; i++) {
                g[i] += row[i] * res;
                ga[i] += fabs(row[i] * res);
                for (int j = 0; j <= i; j++) {
                    H[i][j] += row[i] * row[j];
                    Ha[i][j] += fabs(row[i] * row[j]);
                }
            }
        }
        ck_assert_msg(fabs(val.f - f / (2 * N)) <= 1e-12 * val.f, "k %g f %g vs %g", ks[a], val.f, f / (2 * N));
        for (int i = 0; i < FIT_NP; i++) {
            ck_assert_msg(fabs(val.g[i] - g[i] / N) <= 1e-12 * ga[i] / N, "k %g g%d %.17g vs %.17g",
                          ks[a], i, val.g[i], g[i] / N);
            for (int j = 0; j <= i; j++)
                ck_assert_msg(fabs(val.H[i * m.nx + j] - H[i][j] / N) <= 1e-12 * Ha[i][j] / N,
                              "k %g H%d%d %.17g vs %.17g", ks[a], i, j, val.H[i * m.nx + j], H[i][j] / N);
        }
        el__fit_objective_free(&o);
    }
}
END_TEST

/* The refit's cheap search for feet on another pass (el__fit_feet_elsewhere, from the
 * curve's samples) against the search everywhere (el__fit_nearest_everywhere), both from the
 * feet projected from the points' own places: on looping curves (k > 1, and an
 * inflectional one of several periods; k = 9 over 8 loops), noisy and on the curve, 20 to 1200 points, in
 * the caller's units at scales 1e-6 .. 1e6 (normalised as the fit does), it finds the
 * same nearest point for every point, to 1e-12 in (normalised) distance and 1e-6 of the
 * length in foot; it moves some (it is exercised). */
START_TEST(test_sampled_search_equals_full_search)
{
    enum { NMAX = 1200 };
    static double xy[2 * NMAX], s[NMAX], d0[NMAX], f0[NMAX], d1[NMAX], f1[NMAX], local[NMAX];
    unsigned long long rng = 17;
    const double ks[] = {1.3, 2.5, 9.0, 0.7}, lens[] = {14.0, 14.0, 3.0, 14.0};
    const double scales[] = {1e-6, 1.0, 1e6}, noises[] = {0.0, 0.02, 0.08};
    const size_t ns[] = {20, 300, NMAX};
    size_t moved = 0, cases = 0;
    for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++)
        for (size_t b = 0; b < sizeof scales / sizeof scales[0]; b++)
            for (size_t c = 0; c < sizeof noises / sizeof noises[0]; c++)
                for (size_t e = 0; e < sizeof ns / sizeof ns[0]; e++) {
                    /* the curve in normalised units, the points in the caller's (scale sc,
                     * centre c): the fit's view */
                    const size_t N = ns[e];
                    const double sc = scales[b], cx = 3.0 * sc, cy = -2.0 * sc;
                    const double v[FIT_NP] = {0.2, -0.1, 0.3, 1.0, ks[a], 0.2, lens[a]};
                    fit_objective o;
                    double x[FIT_MAXX], vv[2][FIT_NP];
                    noisy_smooth_objective(v, N, noises[c], cx, cy, sc, &rng, s, xy, &o, x, vv);
                    const double *V[2] = {NULL, NULL};
                    const size_t nv[2] = {N, 0};
                    ck_assert_int_eq(el__fit_feet_distances(&o, x, d0, f0, NULL), EL_OK);
                    memcpy(local, f0, sizeof(double) * N);
                    ck_assert_int_eq(el__fit_nearest_everywhere(&o, vv, V, nv, d0, f0, NULL), EL_OK);
                    size_t mv = 0;
                    ck_assert_int_eq(el__fit_feet_elsewhere(&o, x, vv, d1, f1, &mv), EL_OK);
                    size_t count = 0;
                    for (size_t i = 1; i + 1 < N; i++) {
                        ck_assert_msg(fabs(fabs(d1[i]) - fabs(d0[i])) <= 1e-12,
                                      "k %g scale %g noise %g n %zu point %zu: distance %.17g vs %.17g", ks[a], sc,
                                      noises[c], N, i, d1[i], d0[i]);
                        ck_assert_msg(fabs(f1[i] - f0[i]) <= 1e-6 * v[6], "k %g scale %g noise %g n %zu point %zu: foot %.15g vs %.15g",
                                      ks[a], sc, noises[c], N, i, f1[i], f0[i]);
                        count += fabs(f1[i] - local[i]) > 1e-3 * v[6];
                    }
                    ck_assert_uint_eq(mv, count);          /* every foot of o.s lies on [0, L] */
                    moved += mv;
                    cases++;
                    el__fit_objective_free(&o);
                }
    ck_assert_uint_eq(cases, 108);
    ck_assert_uint_gt(moved, 0);
}
END_TEST

/* el__fit_feet_unproven's proof against the search everywhere: every foot it proves is the
 * nearest point; a nearer point of an unproven one lies on a marked piece; and
 * el__fit_feet_elsewhere keeps proven feet as they are. Open arcs (short lengths: all proven, no
 * sample taken) to loops, k across 1, scales 1e-6 .. 1e6, 20 .. 1200 points, noise 0 .. 0.08. */
START_TEST(test_proven_feet_are_nearest)
{
    enum { NMAX = 1200 };
    static double xy[2 * NMAX], s[NMAX], d0[NMAX], f0[NMAX], dF[NMAX], fF[NMAX], d1[NMAX], f1[NMAX];
    static unsigned char unproven[NMAX];
    unsigned char mark[FIT_PIECES];
    unsigned long long rng = 23;
    const double ks[] = {0.3, 0.9, 0.999999, 1.000001, 1.5, 9.0}, lens[] = {0.4, 3.0, 14.0};
    const double scales[] = {1e-6, 1.0, 1e6}, noises[] = {0.0, 0.02, 0.08};
    const size_t ns[] = {20, 300, NMAX};
    size_t cases = 0, all = 0, some = 0, proven_feet = 0;
    for (size_t a = 0; a < sizeof ks / sizeof ks[0]; a++)
        for (size_t l = 0; l < sizeof lens / sizeof lens[0]; l++)
            for (size_t b = 0; b < sizeof scales / sizeof scales[0]; b++)
                for (size_t c = 0; c < sizeof noises / sizeof noises[0]; c++)
                    for (size_t e = 0; e < sizeof ns / sizeof ns[0]; e++) {
                        const size_t N = ns[e];
                        const double sc = scales[b], cx = -sc, cy = 5.0 * sc, q = test_uniform(&rng, -2.0, 2.0);
                        const double v[FIT_NP] = {0.1, 0.2, -0.4, 1.0, ks[a], q, lens[l]};
                        fit_objective o;
                        double x[FIT_MAXX], vv[2][FIT_NP];
                        noisy_smooth_objective(v, N, noises[c] * fmin(1.0, v[6]), cx, cy, sc, &rng, s, xy, &o, x, vv);
                        const double *V[2] = {NULL, NULL};
                        const size_t nv[2] = {N, 0};
                        ck_assert_int_eq(el__fit_feet_distances(&o, x, d0, f0, NULL), EL_OK);
                        memcpy(dF, d0, sizeof(double) * N);
                        memcpy(fF, f0, sizeof(double) * N);
                        ck_assert_int_eq(el__fit_nearest_everywhere(&o, vv, V, nv, dF, fF, NULL), EL_OK);
                        size_t nopen = 0;
                        ck_assert_int_eq(el__fit_feet_unproven(&o, vv, d0, f0, unproven, &nopen, mark), EL_OK);
                        size_t count = 0;
                        for (size_t i = 1; i + 1 < N; i++) {
                            count += unproven[i];
                            if (unproven[i]) {
                                if (fabs(dF[i]) < fabs(d0[i])) {
                                    const double jq = fF[i] / (v[6] / FIT_PIECES);
                                    const int j = (int)fmin(jq, FIT_PIECES - 1.0);
                                    ck_assert_msg(mark[j] || (j > 0 && jq == j && mark[j - 1]),
                                                  "k %g L %g point %zu: nearer point on an unmarked piece", ks[a], v[6], i);
                                }
                                continue;
                            }
                            ck_assert_msg(fabs(fabs(dF[i]) - fabs(d0[i])) <= 1e-12 && fabs(fF[i] - f0[i]) <= 1e-6 * v[6],
                                          "k %g L %g scale %g noise %g n %zu point %zu: proven foot %.15g (%.17g), "
                                          "nearest %.15g (%.17g)", ks[a], v[6], sc, noises[c], N, i, f0[i], d0[i], fF[i],
                                          dF[i]);
                        }
                        ck_assert_uint_eq(count, nopen);
                        proven_feet += N - 2 - nopen;
                        all += nopen == 0;
                        some += nopen > 0 && nopen < N - 2;
                        size_t mv = 0;
                        ck_assert_int_eq(el__fit_feet_elsewhere(&o, x, vv, d1, f1, &mv), EL_OK);
                        /* a proven foot stays; an unproven one moves only nearer (the samples'
                         * search may miss a pass: test_sampled_search_equals_full_search) */
                        for (size_t i = 1; i + 1 < N; i++) {
                            ck_assert(fabs(d1[i]) <= fabs(d0[i]));
                            if (!unproven[i]) ck_assert(d1[i] == d0[i] && f1[i] == f0[i]);
                        }
                        if (nopen == 0) ck_assert_uint_eq(mv, 0);
                        cases++;
                        el__fit_objective_free(&o);
                    }
    ck_assert_uint_eq(cases, 486);
    ck_assert_uint_gt(all, 0);
    ck_assert_uint_gt(some, 0);
    ck_assert_uint_gt(proven_feet, 0);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit parts");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_blocked_discrete_walk_equals_one_call);
    tcase_add_test(tc, test_end_state_derivatives);
    tcase_add_test(tc, test_discrete_vertex_tangents);
    tcase_add_test(tc, test_keyline_map_is_g2_with_its_derivative);
    tcase_add_test(tc, test_start_chart_same_curve_and_derivative);
    tcase_add_test(tc, test_ends_chart_same_curve_and_derivative);
    tcase_add_test(tc, test_ends_chart_held_zero_start_curvature);
    tcase_add_test(tc, test_discrete_orthogonal_gradient);
    tcase_add_test(tc, test_discrete_paired_normal_equations_equal_plain_ones);
    tcase_add_test(tc, test_sampled_search_equals_full_search);
    tcase_add_test(tc, test_proven_feet_are_nearest);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
