/* The work of el__fit_polygon_distances (the discrete model's point-to-polygon search),
 * counted (el__fit_polygon_distances_counted: segments measured by the walks and scanned
 * ranges, the tree's builds, its searches), held to O(n) where the points' feet lie far
 * along the polygon from their own vertices: a polygon below TREE_EAGER (4096 vertices)
 * builds its segment tree only once the long ranges and walks measured pass its segments
 * (11f2d97, 5e45aff). Before the walks were counted (5e45aff) a 4000-vertex circle whose
 * points all slipped a third of the way along it walked ~n/3 segments a point, 130 M
 * instructions (revfit's slip.c): here 566 segments a point (the walks' count switched
 * off), 18.9 with it (the spiral 44.3, no slip 3-4); a change that breaks the amortisation
 * shows here as a count, not a time. The feet must be the linear scan's (accelerate 0),
 * bit for bit. */
#include "testutil.h"
#include "fit_internal.h"
#include <math.h>
#include <string.h>

enum { NV = 4000 };

static unsigned long long rs;
static double unif(void)
{
    rs = rs * 6364136223846793005ULL + 1442695040888963407ULL;
    return (double)(rs >> 11) / 9007199254740992.0;
}
static double gauss(void)
{
    const double u = unif() + 1e-300, v = unif();
    return sqrt(-2.0 * log(u)) * cos(2.0 * M_PI * v);
}

/* A polygon of NV vertices of segment h = 1 / NV (shape 0: a circle; 1: a spiral turning
 * 6 times, tighter along it), its points each near the vertex a fraction slip along it
 * (noise 0.1 h), the first nfar of them 3000 h off; the work counted, and the feet checked
 * against the scan's. */
static long work(int shape, double slip, int nfar)
{
    static double V[2 * NV], xy[2 * NV], d[NV], f[NV], d0[NV], f0[NV];
    const double h = 1.0 / (double)NV;
    double x = 0.0, y = 0.0, th = 0.0;
    rs = 17;
    for (size_t j = 0; j < NV; j++) {
        V[2 * j] = x; V[2 * j + 1] = y;
        th += shape ? 12.0 * M_PI / NV * (1.0 + 2.0 * (double)j / NV) : 2.0 * M_PI / NV;
        x += h * cos(th); y += h * sin(th);
    }
    for (size_t i = 0; i < NV; i++) {
        const size_t k = (i + (size_t)(slip * NV)) % NV;
        const double s = (int)i < nfar ? 3000.0 * h : 0.1 * h;
        xy[2 * i] = V[2 * k] + s * gauss();
        xy[2 * i + 1] = V[2 * k + 1] + s * gauss();
    }
    const fit_map m = {.model = FIT_DISCRETE, .ncurves = 1};
    fit_objective o;
    ck_assert_int_eq(el__fit_objective_init(&o, FIT_PAIRED, &m, xy, NV, 0.0, 0.0, 1.0, NULL), EL_OK);
    long visited = -1, scan = -1;
    el__fit_polygon_distances_counted(&o, V, NV, h, 0, 1, d, f, 1, &visited);
    el__fit_polygon_distances_counted(&o, V, NV, h, 0, 1, d0, f0, 0, &scan);
    ck_assert(memcmp(d, d0, sizeof d) == 0 && memcmp(f, f0, sizeof f) == 0);
    el__fit_objective_free(&o);
    ck_assert(visited > 0 && scan > 0);
    return visited;
}

START_TEST(test_polygon_search_work_is_linear)
{
    /* shape, slip, far points: (the revfit case) a circle slipped a third with one far
     * point; without it (the walks alone); the spiral; no slip (the walks short) */
    const struct { int shape; double slip; int nfar; } c[] = {
        {0, 1.0 / 3.0, 1}, {0, 1.0 / 3.0, 0}, {1, 1.0 / 3.0, 1}, {0, 0.0, 1}, {0, 0.0, 0}};
    for (size_t a = 0; a < sizeof c / sizeof c[0]; a++) {
        const long v = work(c[a].shape, c[a].slip, c[a].nfar);
        ck_assert_msg(v <= 64L * NV, "shape %d slip %g far %d: %ld segments visited, %.1f a point",
                      c[a].shape, c[a].slip, c[a].nfar, v, (double)v / NV);
    }
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("fit_polygon_work");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, test_polygon_search_work_is_linear);
    suite_add_tcase(s, tc);
    return s;
}

int main(void) { return test_run_suite(suite()); }
