/* The fit's report (fit_nearest.c, fit_polygon.c). Discrete: each point's distance to the polygon and its
 * foot, by el__fit_polygon_distances (the search near the point's vertex) and
 * el__fit_nearest_everywhere (a nearer part elsewhere), against the brute-force nearest
 * point (every segment, the first of equal distances) on equilateral polygons: arcs,
 * loops, self-intersecting random walks, zigzags; sparse and dense polygons (spacing
 * from 10 x the noise down to 1/300 of it), far points, scales 1e-6 .. 1e6. The same
 * distance and foot, bit for bit. Smooth: against dense samples of the curve (below). */
#include "fit_check.h"
#include <string.h>

/* Whether (d, foot, side) is a nearest point of the polygons V[c] (nv[c] vertices,
 * segment h, c < nc) to P, over every segment by the library's formula for one
 * (fit_polygon.c): the signed distance (+ left of the segment's direction) and foot h (j + t)
 * on curve side of a segment at the least squared distance (exact ties: a foot at a
 * vertex is on two segments, each with its side). */
static int brute_nearest(const double *const V[2], const size_t nv[2], int nc, double h, const double *P, double d,
                         double foot, int side)
{
    double best = HUGE_VAL;
    int found = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int c = 0; c < nc; c++)
            for (size_t j = 0; j + 1 < nv[c]; j++) {
                const double *A = V[c] + 2 * j, *B = A + 2;
                const double ux = B[0] - A[0], uy = B[1] - A[1], l2 = ux * ux + uy * uy;
                const double px = P[0] - A[0], py = P[1] - A[1];
                double t = l2 > 0.0 ? (px * ux + py * uy) / l2 : 0.0;
                t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
                const double dx = px - t * ux, dy = py - t * uy, d2 = dx * dx + dy * dy;
                if (pass == 0) { if (d2 < best) best = d2; continue; }
                if (d2 != best || c != side) continue;
                const double ex = P[0] - A[0] - t * ux, ey = P[1] - A[1] - t * uy, r = sqrt(ex * ex + ey * ey);
                found |= (ux * ey - uy * ex < 0.0 ? -r : r) == d && h * ((double)j + t) == foot;
            }
    return found;
}

enum { ARC, RING, LOOPS, WALK, ZIGZAG, SPIKES, HAIRPIN, ELASTICA, SHAPES };
static const char *const shape_name[SHAPES] = {"arc", "ring", "loops", "walk", "zigzag", "spikes", "hairpin", "elastica"};

/* An equilateral polygon of nv vertices, segment h, scaled by sc: its turning per vertex
 * by shape (an arc of 80 degrees in all; a ring of 0.95 turns, whose points near the
 * centre have many local minima of distance; 2.5 loops; a random walk of turns up to 0.5;
 * alternate turns of +-2.5 with noise; spikes, alternate turns of +-(pi - 0.02), whose
 * sin(turning) / h is small: a search that took it for the polygon's curvature missed
 * the neighbouring spike; a hairpin: two straight arms about 2 h apart
 * joined by a turn of pi - 0.01 over 3 vertices, whose turning stays below pi: a search
 * that took directions within pi, not pi/2, as proof that a part cannot come back near
 * misses the other arm), or a discrete elastica (seed 000 (4.7)) of modulus k across 1,
 * elliptic argument 2 .. 12 in all. */
static void polygon(int shape, size_t nv, double h, double sc, unsigned long long *rng, double *V)
{
    double th = test_uniform(rng, -M_PI, M_PI), x = 0.0, y = 0.0;
    if (shape == ELASTICA) {
        static const double ks[] = {0.3, 0.999, 1.0, 1.001, 2.0, 30.0};
        const double k = ks[(size_t)test_uniform(rng, 0.0, 6.0)];
        const el_discrete_params p = {0.0, 0.0, sc * h, th, test_uniform(rng, 2.0, 12.0) / (double)nv,
                                      test_uniform(rng, -2.0, 2.0), k};
        ck_assert_int_eq(el_discrete_eval(&p, nv, V), EL_OK);
        return;
    }
    for (size_t j = 0; j < nv; j++) {
        V[2 * j] = sc * x; V[2 * j + 1] = sc * y;
        x += h * cos(th); y += h * sin(th);
        switch (shape) {
        case ARC: th += 1.4 / (double)nv; break;
        case RING: th += 0.95 * 2.0 * M_PI / (double)nv; break;
        case LOOPS: th += 5.0 * M_PI / (double)nv * (1.0 + 0.3 * test_uniform(rng, -1, 1)); break;
        case WALK: th += test_uniform(rng, -0.5, 0.5); break;
        case SPIKES: th += (j % 2 ? 1.0 : -1.0) * (M_PI - 0.02); break;
        case HAIRPIN: th += j + 2 >= nv / 2 && j + 2 < nv / 2 + 3 ? (M_PI - 0.01) / 3.0 : 0.0; break;
        default: th += (j % 2 ? 2.5 : -2.5) + test_uniform(rng, -0.3, 0.3); break;
        }
    }
}

enum { N_MAX = 1000 };
static const size_t sizes[] = {2, 3, 40, 300, N_MAX};
static const double noise[] = {0.1, 1.0, 7.0, 300.0};   /* in units of the spacing h */
static const double scales[] = {1e-6, 1.0, 1e6};

/* Points i <-> vertex i of W (n, segment h, scaled by sc), off it by the noise (noise h)
 * and one point in 50 far away (100 x the polygon's length). */
static void noisy_points(const double *W, size_t n, double noise_h, double sc, unsigned long long *rng, double *xy)
{
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 2; k++)
            xy[2 * i + k] = W[2 * i + k] + sc * (i % 50 == 7 ? 200.0 : noise_h) * test_normal(rng);
}

/* One polygon, point i <-> vertex i. */
START_TEST(test_polygon_report_equals_brute_force)
{
    static double V[2 * N_MAX], xy[2 * N_MAX], d[N_MAX], fs[N_MAX], local[N_MAX];
    unsigned long long rng = 7;
    long searched = 0, moved = 0;
    for (size_t a = 0; a < sizeof sizes / sizeof sizes[0]; a++)
        for (int shape = 0; shape < SHAPES; shape++)
            for (size_t b = 0; b < sizeof noise / sizeof noise[0]; b++)
                for (size_t c = 0; c < sizeof scales / sizeof scales[0]; c++) {
                    const size_t n = sizes[a];
                    const double h = 2.0 / (double)n, sc = scales[c];
                    polygon(shape, n, h, sc, &rng, V);
                    noisy_points(V, n, noise[b] * h, sc, &rng, xy);
                    const fit_map m = {.model = FIT_DISCRETE, .ncurves = 1};
                    fit_objective o;
                    ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, n, 0.0, 0.0, 1.0, NULL), EL_OK);
                    double v[2][FIT_NP] = {{0}};
                    v[0][2] = sc * h;
                    const double *Vc[2] = {V, NULL};
                    const size_t nv[2] = {n, 0};
                    el__fit_polygon_distances(&o, V, n, sc * h, 0, 1, d, fs);
                    memcpy(local, fs, sizeof(double) * n);
                    ck_assert_int_eq(el__fit_nearest_everywhere(&o, v, Vc, nv, d, fs, NULL), EL_OK);
                    for (size_t i = 0; i < n; i++) {
                        ck_assert_msg(brute_nearest(Vc, nv, 1, sc * h, xy + 2 * i, d[i], fs[i], 0),
                                      "%s n %zu noise %g scale %g point %zu: d %.17g foot %.17g not nearest",
                                      shape_name[shape], n, noise[b], sc, i, d[i], fs[i]);
                        moved += fs[i] != local[i];
                    }
                    searched += (long)n;
                    el__fit_objective_free(&o);
                }
    /* the search elsewhere is exercised: some feet are not where the local search ended */
    ck_assert_int_gt(moved, searched / 100);
}
END_TEST

/* A keyline's two polygons from the joint, vertex j of the first <-> point js - j, of
 * the second <-> point js + j, each point's foot first on its own side (as fit_keyline.c
 * does): the nearest point of both, and its side. */
START_TEST(test_keyline_report_equals_brute_force)
{
    static double W[2 * N_MAX], V0[2 * N_MAX], V1[2 * N_MAX], xy[2 * N_MAX], d[N_MAX], fs[N_MAX];
    static int sd[N_MAX];
    unsigned long long rng = 8;
    long searched = 0, crossed = 0;
    for (size_t a = 2; a < sizeof sizes / sizeof sizes[0]; a++)
        for (int shape = 0; shape < SHAPES; shape++)
            for (size_t b = 0; b < sizeof noise / sizeof noise[0]; b++)
                for (size_t c = 0; c < sizeof scales / sizeof scales[0]; c++) {
                    const size_t n = sizes[a], js = n / 3;
                    const double h = 2.0 / (double)n, sc = scales[c];
                    polygon(shape, n, h, sc, &rng, W);
                    for (size_t j = 0; j <= js; j++) { V0[2 * j] = W[2 * (js - j)]; V0[2 * j + 1] = W[2 * (js - j) + 1]; }
                    memcpy(V1, W + 2 * js, sizeof(double) * 2 * (n - js));
                    noisy_points(W, n, noise[b] * h, sc, &rng, xy);
                    const fit_map m = {.model = FIT_DISCRETE, .ncurves = 2};
                    fit_objective o;
                    ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, n, 0.0, 0.0, 1.0, NULL), EL_OK);
                    double v[2][FIT_NP] = {{0}};
                    v[0][2] = v[1][2] = sc * h;
                    const double *Vc[2] = {V0, V1};
                    const size_t nv[2] = {js + 1, n - js};
                    el__fit_polygon_distances(&o, V0, nv[0], sc * h, js, -1, d, fs);
                    const double dj = d[js], fj = fs[js];
                    el__fit_polygon_distances(&o, V1, nv[1], sc * h, js, 1, d, fs);
                    for (size_t i = 0; i < n; i++) sd[i] = i > js || (i == js && fabs(d[js]) < fabs(dj));
                    if (sd[js] == 0) { d[js] = dj; fs[js] = fj; }
                    ck_assert_int_eq(el__fit_nearest_everywhere(&o, v, Vc, nv, d, fs, sd), EL_OK);
                    for (size_t i = 0; i < n; i++) {
                        ck_assert_msg(brute_nearest(Vc, nv, 2, sc * h, xy + 2 * i, d[i], fs[i], sd[i]),
                                      "%s n %zu noise %g scale %g point %zu: d %.17g foot %.17g side %d not nearest",
                                      shape_name[shape], n, noise[b], sc, i, d[i], fs[i], sd[i]);
                        crossed += sd[i] != (i > js);
                    }
                    searched += (long)n;
                    el__fit_objective_free(&o);
                }
    /* some points are nearest the other side */
    ck_assert_int_gt(crossed, searched / 100);
}
END_TEST

/* The smooth model: each point's foot by Newton from where the curve was sampled
 * (el__fit_feet_distances) and then el__fit_nearest_everywhere, against the nearest of dense
 * samples (50001 per curve, which are never nearer than the nearest point): tight loops
 * (kappa_max up to 20 / length unit) and points scattered from 1/700 to 7 x the loops'
 * radius of curvature off the curve, scales 1e-3 .. 1e3. Every distance no larger
 * than the sampled nearest (and it is the distance of the foot's point). On the former
 * search (Newton from the middle of pieces that turn by up to 5 rad, the foot's
 * neighbourhood left out where the distance is not convex there) 329 of 9600 such points
 * were up to 0.2 % of the length too far. */
START_TEST(test_smooth_report_against_dense_samples)
{
    enum { N = 200, M = 50001 };
    static double xy[2 * N], d[N], fs[N], f0[N], s[N], S[M], C[2 * M];
    const double ks[] = {0.7, 1.3, 2.5, 5.0}, mus[] = {1.0, 4.0}, noises[] = {0.02, 0.3, 1.0}, scs[] = {1e-3, 1.0, 1e3};
    unsigned long long rng = 99;
    long moved = 0;
    for (size_t a = 0; a < 4; a++)
        for (size_t b = 0; b < 2; b++)
            for (size_t c = 0; c < 3; c++)
                for (size_t e = 0; e < 3; e++) {
                    const double sc = scs[e];
                    const double v[FIT_NP] = {0.2 * sc, -0.1 * sc, 0.3, sqrt(mus[b]) / sc, ks[a], 0.2, 14.0 * sc};
                    fit_objective o;
                    double x[FIT_MAXX], vv[2][FIT_NP];
                    noisy_smooth_objective(v, N, sc * noises[c], 0.0, 0.0, 1.0, &rng, s, xy, &o, x, vv);
                    el_smooth_params p;
                    ck_assert_int_eq(el__fit_to_smooth(v, &p), EL_OK);
                    for (size_t j = 0; j < M; j++) S[j] = v[6] * (double)j / (M - 1);
                    ck_assert_int_eq(el_smooth_eval(&p, M, S, C, NULL, NULL), EL_OK);
                    const double *V[2] = {NULL, NULL};
                    const size_t nv[2] = {N, 0};
                    ck_assert_int_eq(el__fit_feet_distances(&o, x, d, fs, NULL), EL_OK);
                    memcpy(f0, fs, sizeof fs);
                    ck_assert_int_eq(el__fit_nearest_everywhere(&o, vv, V, nv, d, fs, NULL), EL_OK);
                    for (size_t i = 0; i < N; i++) {
                        double best = HUGE_VAL, F[2];
                        for (size_t j = 0; j < M; j++) {
                            const double dx = C[2 * j] - xy[2 * i], dy = C[2 * j + 1] - xy[2 * i + 1];
                            best = fmin(best, dx * dx + dy * dy);
                        }
                        ck_assert_msg(fabs(d[i]) <= sqrt(best) + 1e-12 * sc,
                                      "k %g mu %g noise %g scale %g point %zu: d %.17g, a sample at %.17g",
                                      ks[a], mus[b], noises[c], sc, i, fabs(d[i]), sqrt(best));
                        ck_assert_int_eq(el_smooth_eval(&p, 1, &fs[i], F, NULL, NULL), EL_OK);
                        ck_assert_double_eq_tol(hypot(F[0] - xy[2 * i], F[1] - xy[2 * i + 1]), fabs(d[i]), 1e-12 * sc);
                        moved += fabs(fs[i] - f0[i]) > 1e-6 * v[6];
                    }
                    el__fit_objective_free(&o);
                }
    /* the search elsewhere is exercised: feet moved to another pass */
    ck_assert_int_gt(moved, 100);
}
END_TEST

/* A polygon longer than a direction window may be (65535 segments beyond its first):
 * an arc of 70000 segments turning 1.2 (one window, capped; the queue of its smallest
 * direction full), a hairpin, and the arc back 2 h inside it, with points 3 h off: a
 * sample of them against the brute-force nearest segment. */
START_TEST(test_long_polygon_report_equals_brute_force)
{
    enum { ARM = 70000, NV = 2 * ARM + 4 };
    double *V = malloc(sizeof(double) * 2 * NV), *xy = malloc(sizeof(double) * 2 * NV);
    double *d = malloc(sizeof(double) * NV), *fs = malloc(sizeof(double) * NV);
    const double h = 1e-4;
    double th = 0.3, x = 0.0, y = 0.0;
    for (size_t j = 0; j < NV; j++) {
        V[2 * j] = x; V[2 * j + 1] = y;
        x += h * cos(th); y += h * sin(th);
        th += j < ARM ? 1.2 / ARM : j < ARM + 3 ? (M_PI - 1e-3) / 3.0 : -1.2 / ARM;
    }
    unsigned long long rng = 11;
    noisy_points(V, NV, 3.0 * h, 1.0, &rng, xy);
    const fit_map m = {.model = FIT_DISCRETE, .ncurves = 1};
    fit_objective o;
    ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, NV, 0.0, 0.0, 1.0, NULL), EL_OK);
    double v[2][FIT_NP] = {{0}};
    v[0][2] = h;
    const double *Vc[2] = {V, NULL};
    const size_t nv[2] = {NV, 0};
    el__fit_polygon_distances(&o, V, NV, h, 0, 1, d, fs);
    ck_assert_int_eq(el__fit_nearest_everywhere(&o, v, Vc, nv, d, fs, NULL), EL_OK);
    for (size_t i = 0; i < NV; i += 701)
        ck_assert_msg(brute_nearest(Vc, nv, 1, h, xy + 2 * i, d[i], fs[i], 0), "point %zu: d %.17g foot %.17g not nearest",
                      i, d[i], fs[i]);
    el__fit_objective_free(&o);
    free(V); free(xy); free(d); free(fs);
}
END_TEST

/* The windows' directions (fit_polygon.c): within 2e-6 of atan2 all round the circle, at
 * every scale, on the axes and the diagonals (modulo 2 pi: the cut at -pi). */
START_TEST(test_direction_within_its_bound)
{
    unsigned long long rng = 3;
    double worst = 0.0;
    for (int i = 0; i < 400000; i++) {
        const double th = i < 16 ? i * M_PI / 8.0 : test_uniform(&rng, -M_PI, M_PI);
        const double r = pow(10.0, test_uniform(&rng, -300.0, 300.0));
        const double x = r * cos(th), y = r * sin(th);
        const double e = fabs(remainder(el__fit_direction(x, y) - atan2(y, x), 2.0 * M_PI));
        if (e > worst) worst = e;
    }
    ck_assert_msg(worst <= 2e-6, "direction off by %g", worst);
    ck_assert_double_eq(el__fit_direction(1.0, 0.0), 0.0);
    ck_assert_double_eq_tol(el__fit_direction(0.0, -1.0), -0.5 * M_PI, 1e-15);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_nearest");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_polygon_report_equals_brute_force);
    tcase_add_test(tc, test_keyline_report_equals_brute_force);
    tcase_add_test(tc, test_smooth_report_against_dense_samples);
    tcase_add_test(tc, test_long_polygon_report_equals_brute_force);
    tcase_add_test(tc, test_direction_within_its_bound);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
