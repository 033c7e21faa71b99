#define _POSIX_C_SOURCE 199309L /* clock_gettime */
/* Core evaluation cost: ns per point for discrete / smooth elasticae with and
 * without Jacobian, at uniform, sorted scattered (chord parameters, foot points)
 * and unsorted s, against one bare gsl_sf_elljac_e call in the same run.
 * Prints one JSON line per figure (median of repeats, the cases interleaved so
 * that machine noise hits them alike); lines with "readme" feed the README table. */
#include "elastica.h"
#include "bench_util.h"
#include <gsl/gsl_sf_elljac.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

enum { REPS = 21, NCASE = 9 };
static volatile double sink;

/* what one timed run does */
typedef struct job {
    int what;
    size_t n;
    el_discrete_params dp;
    el_smooth_params sp;
    const double *s;
    double *xy, *jac;
} job;

static void run(const job *j)
{
    double a, b, c, acc = 0;
    switch (j->what) {
    case 0:
        for (size_t i = 0; i < j->n; i++) { gsl_sf_elljac_e(0.2 + 20.0 * i / j->n, 0.64, &a, &b, &c); acc += a; }
        sink = acc;
        break;
    case 1: el_discrete_eval(&j->dp, j->n, j->xy); break;
    case 2: el_discrete_jacobian(&j->dp, j->n, j->xy, j->jac); break;
    case 3: el_smooth_eval(&j->sp, j->n, j->s, j->xy, NULL, NULL); break;
    case 4: el_smooth_jacobian(&j->sp, j->n, j->s, j->xy, j->jac); break;
    }
}

static double ns_per_point(const job *j)
{
    double a = bench_now();
    run(j);
    return (bench_now() - a) * 1e9 / (double)j->n;
}

int main(void)
{
    const size_t sizes[2] = {1000, 100000};
    const char *names[NCASE] = {"gsl_sf_elljac_e", "discrete_vertices", "discrete_jacobian",
                                "smooth_points_uniform_s", "smooth_jacobian_uniform_s",
                                "smooth_points_sorted_scattered_s", "smooth_jacobian_sorted_scattered_s",
                                "smooth_points_unsorted_s", "smooth_jacobian_unsorted_s"};
    const int what[NCASE] = {0, 1, 2, 3, 4, 3, 4, 3, 4};
    for (int z = 0; z < 2; z++) {
        const size_t n = sizes[z];
        double *xy = malloc(2 * n * sizeof *xy), *jac = malloc(14 * n * sizeof *jac);
        double *s = malloc(n * sizeof *s), *ss = malloc(n * sizeof *ss), *sr = malloc(n * sizeof *sr);
        el_discrete_params dp = {0, 0, 10.0 / n, 0.3, 20.0 / n, 0.2, 0.8};
        el_smooth_params sp = {0, 0, 0.3, 1.0, 0.8, 0.2, 10.0};
        srand(12345);
        for (size_t i = 0; i < n; i++) {
            s[i] = sp.length * i / (n - 1.0);
            sr[i] = ss[i] = sp.length * rand() / (double)RAND_MAX;
        }
        qsort(ss, n, sizeof *ss, bench_cmp); /* sorted scattered: chord parameters, foot points */
        const double *grid[NCASE] = {s, s, s, s, s, ss, ss, sr, sr};
        static double t[NCASE][REPS];
        for (int r = 0; r < REPS; r++)
            for (int i = 0; i < NCASE; i++) {
                job j = {what[i], n, dp, sp, grid[i], xy, jac};
                t[i][r] = ns_per_point(&j);
            }
        double v[NCASE];
        for (int i = 0; i < NCASE; i++) {
            qsort(t[i], REPS, sizeof t[i][0], bench_cmp);
            v[i] = t[i][REPS / 2];
        }
        for (int i = 0; i < NCASE; i++)
            printf("{\"bench\": \"core\", \"what\": \"%s\", \"n\": %zu, \"median_ns_per_point\": %.1f, "
                   "\"ratio_to_elljac\": %.2f}\n", names[i], n, v[i], v[i] / v[0]);
        printf("{\"bench\": \"core\", \"what\": \"sorted_scattered_over_uniform\", \"n\": %zu, "
               "\"points_ratio\": %.2f, \"jacobian_ratio\": %.2f}\n", n, v[5] / v[3], v[6] / v[4]);
        if (n == 1000) {
            printf("{\"bench\": \"core\", \"what\": \"readme_discrete\", \"n\": %zu, "
                   "\"readme\": \"discrete vertices + full 7-parameter Jacobian\", "
                   "\"value\": \"%.0f ns/point (bare `gsl_sf_elljac_e`: %.0f ns)\"}\n", n, v[2], v[0]);
            printf("{\"bench\": \"core\", \"what\": \"readme_smooth\", \"n\": %zu, "
                   "\"readme\": \"smooth points + Jacobian, uniform / scattered s\", "
                   "\"value\": \"%.0f / %.0f ns/point (scattered sorted, %.1fx uniform; unsorted: %.0f)\"}\n",
                   n, v[4], v[6], v[6] / v[4], v[8]);
        }
        free(xy); free(jac); free(s); free(ss); free(sr);
    }
    return 0;
}
