/* Hermite interpolation (seed 004): median time for all solutions of one
 * problem, over 10 000 random problems (tension mode, sigma |p1-p0|^2 uniform in
 * [-10, 40], random points and tangents), and the length mode (L / |p1-p0| uniform
 * in [1.05, 3]) against the tension mode on the same 1000 problems, the two solved
 * alternately problem by problem; at high tension (sigma |p1-p0|^2 in five bands up to
 * 1e4) the solutions, how many are chains (hermite_chain.c) and unrepresentable. One
 * JSON line per figure; "readme"/"value" mark the README's figures. */
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

typedef struct { double p1[2], t0[2], t1[2], sigma, length; } problem;

static problem draw(unsigned long long *s)
{
    const double pi = 3.14159265358979324;
    problem q;
    q.p1[0] = uni(s, -1, 1);
    q.p1[1] = uni(s, -1, 1);
    const double a = uni(s, -pi, pi), b = uni(s, -pi, pi), d = hypot(q.p1[0], q.p1[1]);
    q.t0[0] = cos(a); q.t0[1] = sin(a);
    q.t1[0] = cos(b); q.t1[1] = sin(b);
    q.sigma = uni(s, -10, 40) / (d * d);
    q.length = d * uni(s, 1.05, 3.0);
    return q;
}

/* time of all solutions of q in the mode; *count += their number */
static double solve(const problem *q, int mode, size_t *count, int *fail)
{
    const double p0[2] = {0, 0};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = mode;
    o.sigma = q->sigma;
    o.length = q->length;
    el_hermite_result r;
    const double t0 = now_us();
    const int rc = el_hermite_solve(p0, q->t0, q->p1, q->t1, &o, &r);
    const double t = now_us() - t0;
    if (rc) { ++*fail; return t; }
    *count += r.count;
    el_hermite_result_free(&r);
    return t;
}

int main(void)
{
    enum { NT = 10000, NL = 1000 };
    double *t = malloc(sizeof(double) * NT), *tl = malloc(sizeof(double) * NL);
    if (!t || !tl) return 1;
    unsigned long long s = 2024;
    size_t nsol = 0, nsl = 0, nst = 0;
    int fail = 0;
    for (int i = 0; i < NT; i++) {
        const problem q = draw(&s);
        t[i] = solve(&q, EL_HERMITE_TENSION, &nsol, &fail);
    }
    qsort(t, NT, sizeof *t, cmp);
    printf("{\"bench\": \"hermite_tension_c\", \"problems\": %d, \"median_us\": %.1f, \"p90_us\": %.1f, "
           "\"mean_solutions\": %.2f, \"failures\": %d, \"readme\": \"all Hermite solutions of one problem, by tension\", "
           "\"value\": \"%.0f us (%.1f solutions on average)\"}\n",
           NT, t[NT / 2], t[(NT * 9) / 10], (double)nsol / NT, fail, t[NT / 2], (double)nsol / NT);
    /* length against tension on the same problems, alternately */
    s = 7;
    fail = 0;
    for (int i = 0; i < NL; i++) {
        const problem q = draw(&s);
        t[i] = solve(&q, EL_HERMITE_TENSION, &nst, &fail);
        tl[i] = solve(&q, EL_HERMITE_LENGTH, &nsl, &fail);
    }
    qsort(t, NL, sizeof *t, cmp);
    qsort(tl, NL, sizeof *tl, cmp);
    const double ratio = tl[NL / 2] / t[NL / 2];
    printf("{\"bench\": \"hermite_length_c\", \"problems\": %d, \"median_us\": %.1f, \"p90_us\": %.1f, "
           "\"mean_solutions\": %.2f, \"tension_median_us\": %.1f, \"ratio_to_tension\": %.2f, \"target\": 4, "
           "\"failures\": %d, \"readme\": \"all Hermite solutions by length (the same problems by tension)\", "
           "\"value\": \"%.0f us (%.1f solutions); %.1fx the by-tension solve\"}\n",
           NL, tl[NL / 2], tl[(NL * 9) / 10], (double)nsl / NL, t[NL / 2], ratio, fail, tl[NL / 2],
           (double)nsl / NL, ratio);
    /* high tension (issue 12): every solution returned, none unrepresentable; the chains */
    const double bands[6] = {0.0, 100.0, 300.0, 1e3, 3e3, 1e4};
    for (int k = 0; k < 5; k++) {
        size_t n = 0, chains = 0, unrep = 0;
        double ts = 0.0;
        s = 99 + (unsigned long long)k;
        for (int i = 0; i < 300; i++) {
            const double pi = 3.14159265358979324, a = uni(&s, -pi, pi), b = uni(&s, -pi, pi);
            const double p0[2] = {0, 0}, t0[2] = {0, 1}, p1[2] = {cos(a), sin(a)}, t1[2] = {cos(b), sin(b)};
            el_hermite_options o;
            el_hermite_options_defaults(&o);
            o.sigma = uni(&s, bands[k], bands[k + 1]);
            el_hermite_result r;
            const double t1us = now_us();
            if (el_hermite_solve(p0, t0, p1, t1, &o, &r)) continue;
            ts += now_us() - t1us;
            n += r.count;
            unrep += r.unrepresentable;
            for (size_t j = 0; j < r.count; j++) chains += r.solutions[j].npieces > 1;
            el_hermite_result_free(&r);
        }
        printf("{\"bench\": \"hermite_high_tension\", \"sigma_d2\": [%g, %g], \"problems\": 300, "
               "\"solutions\": %zu, \"chains\": %zu, \"unrepresentable\": %zu, \"mean_us\": %.1f}\n",
               bands[k], bands[k + 1], n, chains, unrep, ts / 300.0);
    }
    free(t);
    free(tl);
    return 0;
}
