/* el__fit_polygon_distances' bounding-box search (fit_polygon.c: seg_tree, tree_search) against
 * the linear scan it replaces on long stretches (el__fit_polygon_distances_by, accelerate 0):
 * the same distance and foot of every point, bit for bit, on random walks, spirals,
 * self-approaching hairpins, polygons with duplicate vertices and collinear runs, a
 * polygon with a vertex that is not finite, points from 1/10 to 3000 segments off their
 * polygon (dense scans: the stretch spans thousands of segments), offsets up to 1e7 of
 * the polygon's size, both directions of the point order (the keyline's step -1). */
#include "testutil.h"
#include "fit_internal.h"
#include <string.h>

enum { SHAPES = 6 };
static const char *shape_name[SHAPES] = {"random walk", "spiral", "hairpins", "duplicates", "collinear", "not finite"};

/* nv vertices of shape at spacing about h, offset by off */
static void shape_polygon(int shape, size_t nv, double h, double off, unsigned long long *rng, double *V)
{
    double x = 0.0, y = 0.0, th = 0.0;
    for (size_t j = 0; j < nv; j++) {
        V[2 * j] = x + off; V[2 * j + 1] = y - 0.7 * off;
        switch (shape) {
        case 0: th += test_uniform(rng, -0.6, 0.6); break;
        case 1: th += 12.0 * M_PI / (double)nv * (1.0 + 2.0 * (double)j / (double)nv); break;
        case 2: th += (j / (nv / 8 + 1)) % 2 ? 0.0 : (j % (nv / 8 + 1) == 0 ? M_PI - 1e-3 : 0.0); break;
        case 3: th += test_uniform(rng, -0.05, 0.05); break;
        case 4: th += j % 97 == 0 ? 1.0 : 0.0; break;
        default: th += 0.01; break;
        }
        double step = h;
        if (shape == 3 && j % 5 == 2) step = 0.0;                   /* duplicate vertices */
        if (shape == 0) step = h * test_uniform(rng, 0.2, 1.8);
        x += step * cos(th); y += step * sin(th);
    }
    if (shape == 5) V[2 * (nv / 3)] = NAN;
}

START_TEST(test_tree_search_equals_linear_scan)
{
    enum { NV = 6000 };
    static double V[2 * NV], xy[2 * NV], d0[NV], f0[NV], d1[NV], f1[NV];
    static const size_t sizes[] = {40, 700, NV};
    static const double noise[] = {0.1, 3.0, 300.0, 3000.0};     /* in segments */
    static const double offset[] = {0.0, 1e3, 1e7};              /* in polygon lengths */
    unsigned long long rng = 17;
    long points = 0, far = 0;
    for (int shape = 0; shape < SHAPES; shape++)
        for (size_t a = 0; a < sizeof sizes / sizeof sizes[0]; a++)
            for (size_t b = 0; b < sizeof noise / sizeof noise[0]; b++)
                for (size_t c = 0; c < sizeof offset / sizeof offset[0]; c++)
                    for (int dir = 0; dir < 4; dir++) {
                        const size_t n = sizes[a];
                        const double h = 1.0 / (double)n, off = offset[c];
                        shape_polygon(shape, n, h, off, &rng, V);
                        /* points along the polygon, noisy, some far off (a curve far from its points) */
                        for (size_t i = 0; i < n; i++) {
                            const double s = noise[b] * h * (i % 11 == 0 ? 10.0 : 1.0);
                            /* dir 2, 3: point i at vertex i + n / 3 (a curve slipped along
                             * its points: the walks from the points' vertices are long) */
                            const size_t k = dir >= 2 ? (i + n / 3) % n : i;
                            const size_t j = dir % 2 ? n - 1 - k : k;
                            xy[2 * i] = (isfinite(V[2 * j]) ? V[2 * j] : off) + s * test_normal(&rng);
                            xy[2 * i + 1] = V[2 * j + 1] + s * test_normal(&rng);
                        }
                        const fit_map m = {.model = FIT_DISCRETE, .ncurves = 1};
                        fit_objective o;
                        ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, n, 0.0, 0.0, 1.0, NULL), EL_OK);
                        const size_t first = dir % 2 ? n - 1 : 0;
                        const long step = dir % 2 ? -1 : 1;
                        el__fit_polygon_distances_by(&o, V, n, h, first, step, d0, f0, 0);
                        el__fit_polygon_distances_by(&o, V, n, h, first, step, d1, f1, 1);
                        for (size_t i = 0; i < n; i++)
                            ck_assert_msg(memcmp(d0 + i, d1 + i, sizeof(double)) == 0 &&
                                              memcmp(f0 + i, f1 + i, sizeof(double)) == 0,
                                          "%s n %zu noise %g offset %g dir %d point %zu: scan d %.17g foot %.17g, "
                                          "tree d %.17g foot %.17g",
                                          shape_name[shape], n, noise[b], off, dir, i, d0[i], f0[i], d1[i], f1[i]);
                        points += (long)n;
                        for (size_t i = 0; i < n; i++) far += fabs(d0[i]) > 64.0 * h;
                        el__fit_objective_free(&o);
                    }
    /* the tree's ranges (>= 64 segments) are exercised */
    ck_assert_int_gt(far, points / 10);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_polygon_tree");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 120);
    tcase_add_test(tc, test_tree_search_equals_linear_scan);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
