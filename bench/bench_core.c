#define _POSIX_C_SOURCE 199309L /* clock_gettime */
/* Core evaluation cost: ns per point for discrete / smooth elasticae with and
 * without Jacobian, against one bare gsl_sf_elljac_e call in the same run.
 * Prints one JSON line per figure (median of repeats). */
#include "elastica.h"
#include <gsl/gsl_sf_elljac.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

enum { REPS = 15 };
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

/* median ns per point over REPS runs */
static double median_ns(const job *j)
{
    double t[REPS];
    for (int r = 0; r < REPS; r++) {
        double a = now();
        run(j);
        t[r] = (now() - a) * 1e9 / (double)j->n;
    }
    qsort(t, REPS, sizeof *t, cmp);
    return t[REPS / 2];
}

int main(void)
{
    const size_t sizes[2] = {1000, 100000};
    for (int z = 0; z < 2; z++) {
        const size_t n = sizes[z];
        double *xy = malloc(2 * n * sizeof *xy), *jac = malloc(14 * n * sizeof *jac);
        double *s = malloc(n * sizeof *s), *sr = malloc(n * sizeof *sr);
        el_discrete_params dp = {0, 0, 10.0 / n, 0.3, 20.0 / n, 0.2, 0.8};
        el_smooth_params sp = {0, 0, 0.3, 1.0, 0.8, 0.2, 10.0};
        for (size_t i = 0; i < n; i++) {
            s[i] = sp.length * i / (n - 1.0);
            sr[i] = sp.length * rand() / (double)RAND_MAX;
        }
        job j = {0, n, dp, sp, s, xy, jac};
        double v[7];
        const int what[7] = {0, 1, 2, 3, 4, 3, 4};
        for (int i = 0; i < 7; i++) {
            j.what = what[i];
            j.s = i >= 5 ? sr : s;
            v[i] = median_ns(&j);
        }
        const double elljac = v[0];
        const char *names[7] = {"gsl_sf_elljac_e", "discrete_vertices", "discrete_jacobian", "smooth_points_uniform_s",
                                "smooth_jacobian_uniform_s", "smooth_points_scattered_s", "smooth_jacobian_scattered_s"};
        for (int i = 0; i < 7; i++) {
            /* the README's figures table (make bench writes it from "readme"/"value") */
            char readme[200] = "";
            if (z == 0 && i == 2)
                snprintf(readme, sizeof readme, ", \"readme\": \"discrete vertices + full 7-parameter "
                         "Jacobian\", \"value\": \"%.0f ns/point (bare `gsl_sf_elljac_e`: %.0f ns)\"",
                         v[2], elljac);
            if (z == 0 && i == 6)
                snprintf(readme, sizeof readme, ", \"readme\": \"smooth points + Jacobian, uniform / "
                         "scattered s\", \"value\": \"%.0f / %.0f ns/point\"", v[4], v[6]);
            printf("{\"bench\": \"core\", \"what\": \"%s\", \"n\": %zu, \"median_ns_per_point\": %.1f, \"ratio_to_elljac\": %.2f%s}\n",
                   names[i], n, v[i], v[i] / elljac, readme);
        }
        free(xy); free(jac); free(s); free(sr);
    }
    return 0;
}
