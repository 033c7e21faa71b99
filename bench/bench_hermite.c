/* Hermite interpolation (seed 004): median time for all solutions of one
 * problem, over 10 000 random problems (tension mode, sigma |p1-p0|^2 uniform in
 * [-10, 40], random points and tangents), and the length mode on 200 problems.
 * One JSON line per figure. */
#define _POSIX_C_SOURCE 199309L
#include "elastica.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double uni(unsigned long long *s, double lo, double hi)
{
    unsigned long long x = *s;
    x ^= x << 13; x ^= x >> 7; x ^= x << 17;
    *s = x;
    return lo + (hi - lo) * (double)(x >> 11) / 9007199254740992.0;
}

static double now_us(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec * 1e6 + t.tv_nsec * 1e-3;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void run(int mode, int n, const char *name)
{
    double *t = malloc(sizeof(double) * (size_t)n);
    if (!t) return;
    unsigned long long s = 2024;
    const double pi = 3.14159265358979324;
    size_t nsol = 0;
    int fail = 0;
    for (int i = 0; i < n; i++) {
        const double p0[2] = {0, 0}, p1[2] = {uni(&s, -1, 1), uni(&s, -1, 1)};
        const double a = uni(&s, -pi, pi), b = uni(&s, -pi, pi);
        const double t0[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
        const double d = hypot(p1[0], p1[1]);
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        o.mode = mode;
        if (mode == EL_HERMITE_TENSION) o.sigma = uni(&s, -10, 40) / (d * d);
        else o.length = d * uni(&s, 1.05, 3.0);
        el_hermite_result r;
        const double t_start = now_us();
        const int rc = el_hermite_solve(p0, t0, p1, t1, &o, &r);
        t[i] = now_us() - t_start;
        if (rc) { fail++; continue; }
        nsol += r.count;
        el_hermite_result_free(&r);
    }
    qsort(t, (size_t)n, sizeof *t, cmp);
    printf("{\"bench\": \"%s\", \"problems\": %d, \"median_us\": %.1f, \"p90_us\": %.1f, "
           "\"mean_solutions\": %.2f, \"failures\": %d}\n",
           name, n, t[n / 2], t[(n * 9) / 10], (double)nsol / n, fail);
    free(t);
}

int main(void)
{
    run(EL_HERMITE_TENSION, 10000, "hermite_tension_c");
    run(EL_HERMITE_LENGTH, 200, "hermite_length_c");
    return 0;
}
