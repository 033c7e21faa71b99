/* The discrete fit's report (fit_feet.c): each point's distance to the polygon and its
 * foot, by fit_polygon_distances (the search near the point's vertex) and
 * fit_nearest_everywhere (a nearer part elsewhere), against the brute-force nearest
 * point (every segment, the first of equal distances) on equilateral polygons: arcs,
 * loops, self-intersecting random walks, zigzags; sparse and dense polygons (spacing
 * from 10 x the noise down to 1/300 of it), far points, scales 1e-6 .. 1e6. The same
 * distance and foot, bit for bit. */
#include "testutil.h"
#include "fit_internal.h"
#include <string.h>

/* Whether (d, foot) is a nearest point of the polygon V (nv vertices, segment h) to P,
 * over every segment by the library's formula for one (fit_feet.c): the signed distance
 * (+ left of the segment's direction) and foot h (j + t) of a segment at the least
 * squared distance (exact ties: a foot at a vertex is on two segments, each with its
 * side). *ties counts the points with more than one. */
static int brute_nearest(const double *V, size_t nv, double h, const double *P, double d, double foot, long *ties)
{
    double best = HUGE_VAL;
    int found = 0, count = 0;
    for (int pass = 0; pass < 2; pass++)
        for (size_t j = 0; j + 1 < nv; j++) {
            const double *A = V + 2 * j, *B = A + 2;
            const double ux = B[0] - A[0], uy = B[1] - A[1], l2 = ux * ux + uy * uy;
            const double px = P[0] - A[0], py = P[1] - A[1];
            double t = l2 > 0.0 ? (px * ux + py * uy) / l2 : 0.0;
            t = t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
            const double dx = px - t * ux, dy = py - t * uy, d2 = dx * dx + dy * dy;
            if (pass == 0) { if (d2 < best) best = d2; continue; }
            if (d2 != best) continue;
            const double ex = P[0] - A[0] - t * ux, ey = P[1] - A[1] - t * uy, r = sqrt(ex * ex + ey * ey);
            found |= (ux * ey - uy * ex < 0.0 ? -r : r) == d && h * ((double)j + t) == foot;
            count++;
        }
    *ties += count > 1;
    return found;
}

enum { ARC, LOOPS, WALK, ZIGZAG, SHAPES };
static const char *const shape_name[SHAPES] = {"arc", "loops", "walk", "zigzag"};

/* An equilateral polygon of nv vertices, segment h, scaled by sc: its turning per vertex
 * by shape (an arc of 80 degrees in all; 2.5 loops; a random walk of turns up to 0.5;
 * alternate turns of +-2.5 with noise). */
static void polygon(int shape, size_t nv, double h, double sc, unsigned long long *rng, double *V)
{
    double th = test_uniform(rng, -M_PI, M_PI), x = 0.0, y = 0.0;
    for (size_t j = 0; j < nv; j++) {
        V[2 * j] = sc * x; V[2 * j + 1] = sc * y;
        x += h * cos(th); y += h * sin(th);
        switch (shape) {
        case ARC: th += 1.4 / (double)nv; break;
        case LOOPS: th += 5.0 * M_PI / (double)nv * (1.0 + 0.3 * test_uniform(rng, -1, 1)); break;
        case WALK: th += test_uniform(rng, -0.5, 0.5); break;
        default: th += (j % 2 ? 2.5 : -2.5) + test_uniform(rng, -0.3, 0.3); break;
        }
    }
}

START_TEST(test_polygon_report_equals_brute_force)
{
    const size_t sizes[] = {2, 3, 40, 300, 1000};
    const double noise[] = {0.1, 1.0, 7.0, 300.0};   /* in units of the spacing h */
    const double scales[] = {1e-6, 1.0, 1e6};
    unsigned long long rng = 7;
    long searched = 0, moved = 0, ties = 0;
    for (size_t a = 0; a < sizeof sizes / sizeof sizes[0]; a++)
        for (int shape = 0; shape < SHAPES; shape++)
            for (size_t b = 0; b < sizeof noise / sizeof noise[0]; b++)
                for (size_t c = 0; c < sizeof scales / sizeof scales[0]; c++) {
                    const size_t n = sizes[a];
                    const double h = 2.0 / (double)n, sc = scales[c];
                    double *V = malloc(sizeof(double) * 2 * n), *xy = malloc(sizeof(double) * 2 * n);
                    double *d = malloc(sizeof(double) * n), *fs = malloc(sizeof(double) * n);
                    double *local = malloc(sizeof(double) * n);
                    polygon(shape, n, h, sc, &rng, V);
                    for (size_t i = 0; i < n; i++)
                        for (int k = 0; k < 2; k++) {
                            /* one point in 50 far away (100 x the polygon's length) */
                            const double e = i % 50 == 7 ? 200.0 : noise[b] * h;
                            xy[2 * i + k] = V[2 * i + k] + sc * e * test_normal(&rng);
                        }
                    const fit_map m = {.model = FIT_DISCRETE, .ncurves = 1};
                    fit_objective o;
                    ck_assert_int_eq(fit_objective_init(&o, FIT_PAIRED, &m, xy, n, 0.0, 0.0, 1.0, NULL), EL_OK);
                    double v[2][FIT_NP] = {{0}};
                    v[0][2] = sc * h;
                    const double *Vc[2] = {V, NULL};
                    const size_t nv[2] = {n, 0};
                    fit_polygon_distances(&o, V, n, sc * h, 0, 1, d, fs);
                    memcpy(local, fs, sizeof(double) * n);
                    ck_assert_int_eq(fit_nearest_everywhere(&o, v, Vc, nv, 0, d, fs, NULL), EL_OK);
                    for (size_t i = 0; i < n; i++) {
                        ck_assert_msg(brute_nearest(V, n, sc * h, xy + 2 * i, d[i], fs[i], &ties),
                                      "%s n %zu noise %g scale %g point %zu: d %.17g foot %.17g not nearest",
                                      shape_name[shape], n, noise[b], sc, i, d[i], fs[i]);
                        moved += fs[i] != local[i];
                    }
                    searched += (long)n;
                    fit_objective_free(&o);
                    free(V); free(xy); free(d); free(fs); free(local);
                }
    /* the search elsewhere is exercised: some feet are not where the local search ended */
    ck_assert_int_gt(moved, searched / 100);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_nearest");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_test(tc, test_polygon_report_equals_brute_force);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
