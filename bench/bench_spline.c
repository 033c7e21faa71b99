/*
 * Elastic splines against libspiro (Debian libspiro-dev), same points, same run.
 *
 * Points: a fair curve y = sin x + 0.3 cos 2.3x, x in [0, 12] unevenly spaced
 * (a designer's or a scanner's spacing), 100 and 1000 of them.
 * libspiro: the open spiro through them ('{' 'c' ... '}'), run_spiro0 (the
 * solve; the Bezier output is not timed). Its bending energy and length from
 * its own segments: each segment has curvature k(s) = ks0 + ks1 s + ks2 s^2/2 +
 * ks3 s^3/6 over s in [-1/2, 1/2] of a unit-length curve scaled to the chord
 * seg_ch, so its length is l = seg_ch / |int exp(i theta)| and its integral of
 * kappa^2 ds = (1/l) int k^2 ds (Gauss-Legendre; libspiro's internal units
 * scaled back by dm[0]).
 * The elastic spline of spiro's length (length mode) is the minimiser of
 * integral kappa^2 over curves of that length through the points, so its
 * energy must be no larger than spiro's: the ratio is printed (<= 1). Times:
 * the elastic spline in tension mode (sigma = 0, the free batten) and in length
 * mode, beside spiro's, medians of alternated runs, wall clock and CPU time.
 * One JSON line per figure; "readme"/"value" mark the README's figures.
 */
#define _POSIX_C_SOURCE 199309L
#include "elastica.h"
#include <math.h>
#include <bezctx.h>   /* spiro.h needs it first */
#include <spiro.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

/* The process's CPU time: on the shared 2-core machine the wall clock also
 * counts the time other processes hold the cores (both are printed). */
static double cpu(void)
{
    struct timespec t;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int cmp(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n)
{
    qsort(v, n, sizeof *v, cmp);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* 16-point Gauss-Legendre on [-1/2, 1/2] */
static const double GX[8] = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                             0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                             0.9445750230732326, 0.9894009349916499};
static const double GW[8] = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                             0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                             0.0622535239386479, 0.0271524594117541};

/* Energy and length of libspiro's curve from its segments (file comment). */
static void spiro_energy(const spiro_seg *s, int n, double scale, double *E, double *L)
{
    *E = *L = 0.0;
    for (int i = 0; i + 1 < n; i++) {
        const double *k = s[i].ks;
        double cx = 0.0, cy = 0.0, kk = 0.0;
        /* the chord of the unit-length curve by 64 Gauss panels */
        for (int p = 0; p < 64; p++) {
            const double a = -0.5 + p / 64.0, h = 1.0 / 64.0;
            for (int g = 0; g < 16; g++) {
                const double u = a + h * (0.5 + 0.5 * (g < 8 ? -GX[7 - g] : GX[g - 8]));
                const double w = 0.5 * h * (g < 8 ? GW[7 - g] : GW[g - 8]);
                const double th = k[0] * u + k[1] * u * u / 2 + k[2] * u * u * u / 6 + k[3] * u * u * u * u / 24;
                const double ku = k[0] + k[1] * u + k[2] * u * u / 2 + k[3] * u * u * u / 6;
                cx += w * cos(th);
                cy += w * sin(th);
                kk += w * ku * ku;
            }
        }
        const double l = s[i].seg_ch / hypot(cx, cy) * scale;
        *L += l;
        *E += kk / l;
    }
}

static void fair_points(int n, double *xy)
{
    for (int i = 0; i < n; i++) {
        const double t = (double)i / (n - 1);
        const double x = 12.0 * (t + 0.35 * t * (1.0 - t) * sin(5.0 * t));   /* uneven spacing */
        xy[2 * i] = x;
        xy[2 * i + 1] = sin(x) + 0.3 * cos(2.3 * x);
    }
}

static void run(int n, int reps)
{
    double *xy = malloc(2 * (size_t)n * sizeof *xy);
    spiro_cp *cp = malloc((size_t)n * sizeof *cp);
    double *ts = malloc(reps * sizeof *ts), *tt = malloc(reps * sizeof *tt), *tl = malloc(reps * sizeof *tl);
    double *cs = malloc(reps * sizeof *cs), *ct = malloc(reps * sizeof *ct), *cl = malloc(reps * sizeof *cl);
    fair_points(n, xy);
    for (int i = 0; i < n; i++) {
        cp[i].x = xy[2 * i];
        cp[i].y = xy[2 * i + 1];
        cp[i].ty = i == 0 ? '{' : i == n - 1 ? '}' : 'c';
    }
    double dm[6], Es = 0.0, Ls = 0.0;
    spiro_seg *seg = run_spiro0(cp, dm, 0, n);
    if (!seg) { printf("{\"bench\": \"spline_vs_spiro\", \"n\": %d, \"error\": \"libspiro failed\"}\n", n); return; }
    spiro_energy(seg, n, dm[0], &Es, &Ls);
    free_spiro(seg);

    el_spline_options ot, ol;
    el_spline_options_defaults(&ot);
    el_spline_options_defaults(&ol);
    ol.mode = EL_SPLINE_LENGTH;
    ol.length = Ls;
    el_spline_result r;
    int st_t = EL_OK, st_l = EL_OK;
    double El = NAN, sig = NAN;
    for (int k = 0; k < reps; k++) {   /* alternated: spiro, tension, length */
        double t0 = now(), c0 = cpu();
        seg = run_spiro0(cp, dm, 0, n);
        ts[k] = now() - t0;
        cs[k] = cpu() - c0;
        free_spiro(seg);
        t0 = now(), c0 = cpu();
        st_t = el_spline_solve(xy, (size_t)n, &ot, &r);
        tt[k] = now() - t0;
        ct[k] = cpu() - c0;
        el_spline_result_free(&r);
        t0 = now(), c0 = cpu();
        st_l = el_spline_solve(xy, (size_t)n, &ol, &r);
        tl[k] = now() - t0;
        cl[k] = cpu() - c0;
        if (k == 0 && st_l == EL_OK) { El = r.energy; sig = r.sigma; }
        el_spline_result_free(&r);
    }
    const double ms = 1e3 * median(ts, reps), mt = 1e3 * median(tt, reps), ml = 1e3 * median(tl, reps);
    const double cms = 1e3 * median(cs, reps), cmt = 1e3 * median(ct, reps), cml = 1e3 * median(cl, reps);
    const double ratio = El / Es;
    printf("{\"bench\": \"spline_vs_spiro\", \"n\": %d, \"status_tension\": %d, \"status_length\": %d, "
           "\"median_ms_tension\": %.3f, \"median_ms_length\": %.3f, \"spiro_median_ms\": %.3f, "
           "\"cpu_ms_tension\": %.3f, \"cpu_ms_length\": %.3f, \"spiro_cpu_ms\": %.3f, "
           "\"spiro_length\": %.9g, \"spiro_energy\": %.9g, \"spline_energy\": %.9g, "
           "\"energy_ratio\": %.6f, \"sigma\": %.6g, "
           "\"readme\": \"elastic spline through %d points (vs libspiro)\", "
           "\"value\": \"%.2f ms CPU free batten, %.2f ms at libspiro's length (libspiro %.2f ms); "
           "integral kappa^2 %.4f of libspiro's\"}\n",
           n, st_t, st_l, mt, ml, ms, cmt, cml, cms, Ls, Es, El, ratio, sig, n, cmt, cml, cms, ratio);
    free(xy); free(cp); free(ts); free(tt); free(tl); free(cs); free(ct); free(cl);
}

int main(void)
{
    run(100, 41);
    run(1000, 11);
    return 0;
}
