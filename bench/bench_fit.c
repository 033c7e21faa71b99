#define _DEFAULT_SOURCE /* clock_gettime, fork, wait4 */
/* Fits in C (issues 13 and 16): one JSON line per figure, baselines in the same run.
 *   fit_threads                 two threads fitting at once against the same fits in turn
 *   fit_memory                  peak RSS of a process fitting 10^6 points (and of one that
 *                               only holds them)
 *   fit_scaling                 time per fit for n = 10^2 .. 10^6, the slope of log t / log n
 *   fit_orthogonal_formulation  the smooth orthogonal fit of 1000 noisy points as the
 *                               library does it (variable projection, Levenberg-Marquardt)
 *                               against the feet as Ipopt variables (the arrow-shaped
 *                               problem of n + 7 variables with MUMPS), same data, same start;
 *                               the library's paired fit of the same points for scale
 * BENCH_FIT_QUICK=1: fewer repeats. */
#include "elastica.h"
#include "bench_util.h"
#include <IpStdCInterface.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Gaussian noise (Box-Muller on a xorshift). */
static double gauss(unsigned long long *s)
{
    double u[2];
    for (int i = 0; i < 2; i++) {
        unsigned long long x = *s;
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        *s = x;
        u[i] = ((double)(x >> 11) + 0.5) / 9007199254740992.0;
    }
    return sqrt(-2.0 * log(u[0])) * cos(2.0 * M_PI * u[1]);
}

/* n points of a discrete elastica of length 10 with noise sigma (per coordinate). */
static void discrete_points(size_t n, double sigma, unsigned long long seed, double *xy)
{
    el_discrete_params p = {0.0, 0.0, 10.0 / (double)(n - 1), 0.3, 4.0 / (double)(n - 1), 0.2, 0.8};
    el_discrete_eval(&p, n, xy);
    for (size_t i = 0; i < 2 * n; i++) xy[i] += sigma * gauss(&seed);
}

static void smooth_points(size_t n, double sigma, unsigned long long seed, double *xy)
{
    el_smooth_params p = {1.0, 2.0, 0.3, 1.0, 0.8, 0.2, 5.0};
    double *s = malloc(sizeof(double) * n);
    for (size_t i = 0; i < n; i++) s[i] = p.length * (double)i / (double)(n - 1);
    el_smooth_eval(&p, n, s, xy, NULL, NULL);
    for (size_t i = 0; i < 2 * n; i++) xy[i] += sigma * gauss(&seed);
    free(s);
}

/* ------------------------------------------------------------ threads */

typedef struct tjob {
    int fits, first;
    const double *xy;
    size_t n;
} tjob;

static void *fit_many(void *arg)
{
    const tjob *j = arg;
    el_fit_discrete_result r;
    for (int k = 0; k < j->fits; k++)
        el_fit_discrete(j->xy + 2 * j->n * (size_t)((j->first + k) % 8), j->n, NULL, NULL, &r, NULL, NULL);
    return NULL;
}

static void bench_threads(int quick)
{
    const size_t n = 1000;
    const int fits = quick ? 20 : 100, reps = quick ? 3 : 7;
    double *xy = malloc(sizeof(double) * 2 * n * 8);
    for (int c = 0; c < 8; c++) discrete_points(n, 0.01, 77 + (unsigned long long)c, xy + 2 * n * (size_t)c);
    double ratio[16];
    for (int r = 0; r < reps; r++) {
        tjob a = {fits, 0, xy, n}, b = {fits, 4, xy, n};
        double t0 = bench_now();
        fit_many(&a);
        fit_many(&b);
        const double serial = bench_now() - t0;
        pthread_t ta, tb;
        t0 = bench_now();
        pthread_create(&ta, NULL, fit_many, &a);
        pthread_create(&tb, NULL, fit_many, &b);
        pthread_join(ta, NULL);
        pthread_join(tb, NULL);
        ratio[r] = (bench_now() - t0) / serial;
    }
    const double m = bench_median(ratio, reps);
    printf("{\"bench\": \"fit_threads\", \"n\": %zu, \"fits_per_thread\": %d, \"two_threads_over_serial\": %.3f, "
           "\"note\": \"1.0 = serialised, 0.5 = two cores fully used (the machine is shared)\", "
           "\"readme\": \"two threads fitting at once (1000 points each)\", "
           "\"value\": \"%.2f x the time of the same fits in turn\"}\n", n, fits, m, m);
    free(xy);
}

/* ------------------------------------------------------------ memory, scaling */

/* Peak RSS (MiB) of a child that makes n points and, when fit, fits them. */
static double child_rss(size_t n, int fit, int smooth)
{
    fflush(stdout);
    pid_t pid = fork();
    if (pid == 0) {
        double *xy = malloc(sizeof(double) * 2 * n), *d = malloc(sizeof(double) * n), *f = malloc(sizeof(double) * n);
        if (smooth) smooth_points(n, 1e-3, 5, xy); else discrete_points(n, 1e-3, 5, xy);
        memset(d, 0, sizeof(double) * n);
        memset(f, 0, sizeof(double) * n);
        int st = 0;
        if (fit && smooth) { el_fit_smooth_result r; st = el_fit_smooth(xy, n, NULL, NULL, &r, d, f); }
        else if (fit) { el_fit_discrete_result r; st = el_fit_discrete(xy, n, NULL, NULL, &r, d, f); }
        _exit(st == EL_OK ? 0 : 1);
    }
    int status;
    struct rusage ru;
    if (wait4(pid, &status, 0, &ru) < 0 || !WIFEXITED(status) || WEXITSTATUS(status)) return -1.0;
    return ru.ru_maxrss / 1024.0;
}

static void bench_memory(void)
{
    const size_t n = 1000000;
    const double base = child_rss(n, 0, 0), disc = child_rss(n, 1, 0), smo = child_rss(n, 1, 1);
    printf("{\"bench\": \"fit_memory\", \"n\": %zu, \"peak_rss_mib_discrete\": %.1f, \"peak_rss_mib_smooth\": %.1f, "
           "\"peak_rss_mib_points_only\": %.1f, \"target_mib\": 80, "
           "\"readme\": \"peak memory of a 10^6-point fit (points, distances and feet included)\", "
           "\"value\": \"%.0f MiB discrete, %.0f MiB smooth orthogonal (the process holding the points: %.0f MiB)\"}\n",
           n, disc, smo, base, disc, smo, base);
}

static void bench_scaling(int quick)
{
    const size_t sizes[] = {100, 1000, 10000, 100000, 1000000};
    const int count = quick ? 4 : 5;
    double lt[5], ln[5], ms[5];
    for (int a = 0; a < count; a++) {
        const size_t n = sizes[a];
        const int reps = n >= 100000 ? 3 : 9;
        double *xy = malloc(sizeof(double) * 2 * n), t[9];
        discrete_points(n, 1e-3, 9, xy);
        for (int r = 0; r < reps; r++) {
            el_fit_discrete_result res;
            const double t0 = bench_now();
            el_fit_discrete(xy, n, NULL, NULL, &res, NULL, NULL);
            t[r] = bench_now() - t0;
        }
        ms[a] = 1e3 * bench_median(t, reps);
        lt[a] = log(ms[a]);
        ln[a] = log((double)n);
        free(xy);
    }
    /* slope of log t against log n over the last three sizes (above the fixed costs) */
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const int k0 = count - 3;
    for (int a = k0; a < count; a++) { sx += ln[a]; sy += lt[a]; sxx += ln[a] * ln[a]; sxy += ln[a] * lt[a]; }
    const double slope = (3 * sxy - sx * sy) / (3 * sxx - sx * sx);
    printf("{\"bench\": \"fit_scaling\", \"model\": \"discrete\", \"noise\": 0.001, \"median_ms\": {");
    for (int a = 0; a < count; a++) printf("%s\"%zu\": %.3f", a ? ", " : "", sizes[a], ms[a]);
    printf("}, \"slope_log_t_log_n\": %.3f, \"readme\": \"fit time against n (10^2 .. 10^6 points)\", "
           "\"value\": \"%.2f ms at 10^4, %.0f ms at 10^6; slope of log t / log n %.2f\"}\n",
           slope, ms[2], ms[count - 1], slope);
}

/* ------------------------------------------------------------ the arrow formulation */

/*
 * The orthogonal fit with the feet as Ipopt variables: x = (p (7, the smooth model's,
 * mu as w^2), s_1 .. s_{n-2}), f = (1/2n) (|gamma(0) - P_0|^2 + sum |gamma(s_i) - P_i|^2
 * + |gamma(L) - P_{n-1}|^2), the Gauss-Newton Hessian (arrow-shaped: the 7 x 7 block,
 * a 7-vector and 1 per foot), MUMPS. Same objective as the library's, same start.
 */
typedef struct arrow {
    size_t n;
    const double *P;
    double *s, *xy, *jac, *th;
} arrow;

static int arrow_eval(arrow *a, const double *x, int want)
{
    el_smooth_params p = {x[0], x[1], x[2], x[3] * x[3], x[4], x[5], x[6]};
    const size_t n = a->n;
    a->s[0] = 0.0;
    a->s[n - 1] = p.length;
    for (size_t i = 1; i + 1 < n; i++) a->s[i] = x[6 + i];
    if (el_smooth_check(&p)) return 0;
    if (want) return el_smooth_jacobian(&p, n, a->s, a->xy, a->jac) == EL_OK &&
                     el_smooth_eval(&p, n, a->s, NULL, a->th, NULL) == EL_OK;
    return el_smooth_eval(&p, n, a->s, a->xy, NULL, NULL) == EL_OK;
}

static Bool ar_f(Index nv, Number *x, Bool nx, Number *obj, UserDataPtr ud)
{
    (void)nv; (void)nx;
    arrow *a = ud;
    if (!arrow_eval(a, x, 0)) return FALSE;
    double f = 0.0;
    for (size_t i = 0; i < 2 * a->n; i++) f += (a->xy[i] - a->P[i]) * (a->xy[i] - a->P[i]);
    *obj = 0.5 * f / (double)a->n;
    return TRUE;
}

/* d gamma_i / d x: the Jacobian's columns (d/dw = 2 w d/dmu; the length column only at
 * the last point, whose s is L) and T_i for its own foot. */
static void arrow_row(const arrow *a, const double *x, size_t i, int c, double *dp, double *ds)
{
    const double *r = a->jac + (2 * i + c) * 7;
    for (int j = 0; j < 7; j++) dp[j] = r[j];
    dp[3] *= 2.0 * x[3];
    if (i + 1 < a->n) dp[6] = 0.0;
    *ds = (i > 0 && i + 1 < a->n) ? (c ? sin(a->th[i]) : cos(a->th[i])) : 0.0;
}

static Bool ar_grad(Index nv, Number *x, Bool nx, Number *g, UserDataPtr ud)
{
    (void)nx;
    arrow *a = ud;
    if (!arrow_eval(a, x, 1)) return FALSE;
    memset(g, 0, sizeof(double) * (size_t)nv);
    for (size_t i = 0; i < a->n; i++)
        for (int c = 0; c < 2; c++) {
            double dp[7], ds;
            arrow_row(a, x, i, c, dp, &ds);
            const double r = (a->xy[2 * i + c] - a->P[2 * i + c]) / (double)a->n;
            for (int j = 0; j < 7; j++) g[j] += r * dp[j];
            if (i > 0 && i + 1 < a->n) g[6 + i] += r * ds;
        }
    return TRUE;
}

static Bool ar_g(Index nv, Number *x, Bool nx, Index m, Number *g, UserDataPtr ud)
{
    (void)nv; (void)x; (void)nx; (void)m; (void)g; (void)ud;
    return TRUE;
}

static Bool ar_jg(Index nv, Number *x, Bool nx, Index m, Index ne, Index *ir, Index *jc, Number *v, UserDataPtr ud)
{
    (void)nv; (void)x; (void)nx; (void)m; (void)ne; (void)ir; (void)jc; (void)v; (void)ud;
    return TRUE;
}

/* Lower triangle: the 28 entries of the 7 x 7 block, then per foot 7 + 1. */
static Bool ar_h(Index nv, Number *x, Bool nx, Number of, Index m, Number *lam, Bool nl, Index ne,
                 Index *ir, Index *jc, Number *v, UserDataPtr ud)
{
    (void)nv; (void)nx; (void)m; (void)lam; (void)nl; (void)ne;
    arrow *a = ud;
    const size_t n = a->n;
    if (!v) {
        Index e = 0;
        for (int r = 0; r < 7; r++)
            for (int q = 0; q <= r; q++) { ir[e] = r; jc[e] = q; e++; }
        for (size_t i = 1; i + 1 < n; i++) {
            for (int q = 0; q < 7; q++) { ir[e] = (Index)(6 + i); jc[e] = q; e++; }
            ir[e] = (Index)(6 + i); jc[e] = (Index)(6 + i); e++;
        }
        return TRUE;
    }
    if (!arrow_eval(a, x, 1)) return FALSE;
    double H[7][7] = {{0}};
    Index e = 28;
    for (size_t i = 0; i < n; i++) {
        double B[7] = {0}, D = 0.0;
        for (int c = 0; c < 2; c++) {
            double dp[7], ds;
            arrow_row(a, x, i, c, dp, &ds);
            for (int r = 0; r < 7; r++) {
                for (int q = 0; q <= r; q++) H[r][q] += dp[r] * dp[q];
                B[r] += ds * dp[r];
            }
            D += ds * ds;
        }
        if (i > 0 && i + 1 < n) {
            for (int q = 0; q < 7; q++) v[e++] = of * B[q] / (double)n;
            v[e++] = of * D / (double)n;
        }
    }
    e = 0;
    for (int r = 0; r < 7; r++)
        for (int q = 0; q <= r; q++) v[e++] = of * H[r][q] / (double)n;
    return TRUE;
}

static int ar_iters;
static Bool ar_cb(Index am, Index it, Number o, Number ip, Number id, Number mu, Number dn, Number rg,
                  Number ad, Number ap, Index ls, UserDataPtr ud)
{
    (void)am; (void)o; (void)ip; (void)id; (void)mu; (void)dn; (void)rg; (void)ad; (void)ap; (void)ls; (void)ud;
    ar_iters = it;
    return TRUE;
}

/* One arrow solve from the smooth guess with feet at the fractions' places; returns f. */
static double arrow_fit(const double *P, size_t n, const el_smooth_params *g0, int *iters)
{
    const size_t nv = 7 + (n - 2);
    arrow a = {n, P, malloc(sizeof(double) * n), malloc(sizeof(double) * 2 * n),
               malloc(sizeof(double) * 14 * n), malloc(sizeof(double) * n)};
    double *x = malloc(sizeof(double) * nv), *xl = malloc(sizeof(double) * nv), *xu = malloc(sizeof(double) * nv);
    double *t = malloc(sizeof(double) * n);
    el_fit_fractions(P, n, EL_PARAM_AUTO, t, NULL);
    x[0] = g0->x0; x[1] = g0->y0; x[2] = g0->phi; x[3] = sqrt(g0->mu); x[4] = g0->k; x[5] = g0->q; x[6] = g0->length;
    for (size_t i = 1; i + 1 < n; i++) x[6 + i] = t[i] * g0->length;
    for (size_t j = 0; j < nv; j++) { xl[j] = -1e20; xu[j] = 1e20; }
    const Index nh = 28 + (Index)(8 * (n - 2));
    IpoptProblem pr = CreateIpoptProblem((Index)nv, xl, xu, 0, NULL, NULL, 0, nh, 0, ar_f, ar_g, ar_grad, ar_jg, ar_h);
    AddIpoptStrOption(pr, "option_file_name", "");
    AddIpoptIntOption(pr, "print_level", 0);
    AddIpoptStrOption(pr, "sb", "yes");
    AddIpoptNumOption(pr, "tol", 1e-10);
    AddIpoptIntOption(pr, "max_iter", 500);
    AddIpoptNumOption(pr, "acceptable_tol", 1e-3);
    AddIpoptNumOption(pr, "acceptable_obj_change_tol", 1e-10);
    AddIpoptIntOption(pr, "acceptable_iter", 2);
    SetIntermediateCallback(pr, ar_cb);
    double obj = HUGE_VAL;
    ar_iters = 0;
    IpoptSolve(pr, x, NULL, &obj, NULL, NULL, NULL, &a);
    FreeIpoptProblem(pr);
    *iters = ar_iters;
    free(a.s); free(a.xy); free(a.jac); free(a.th); free(x); free(xl); free(xu); free(t);
    return obj;
}

static void bench_formulation(int quick)
{
    const size_t n = 1000;
    const int reps = quick ? 3 : 7;
    double *xy = malloc(sizeof(double) * 2 * n), ta[16], tl[16], tp[16];
    double fa = 0.0, fl = 0.0;
    int ia = 0, il = 0;
    for (int r = 0; r < reps; r++) {
        smooth_points(n, 0.01, 31 + (unsigned long long)r, xy);
        el_smooth_params g[6];
        size_t cnt;
        el_guess_smooth(xy, n, EL_PARAM_AUTO, g, 6, &cnt);
        el_fit_options o;
        el_fit_options_defaults(&o);
        o.max_candidates = 1;
        el_fit_smooth_result res;
        double t0 = bench_now();
        el_fit_smooth(xy, n, &o, NULL, &res, NULL, NULL);
        tl[r] = bench_now() - t0;
        il = res.iterations;
        fl = 0.5 * res.rms * res.rms;
        o.distance = EL_DISTANCE_PAIRED;
        t0 = bench_now();
        el_fit_smooth(xy, n, &o, NULL, &res, NULL, NULL);
        tp[r] = bench_now() - t0;
        t0 = bench_now();
        fa = arrow_fit(xy, n, &g[0], &ia);
        ta[r] = bench_now() - t0;
    }
    const double mt = bench_median(tl, reps), ma = bench_median(ta, reps), mp = bench_median(tp, reps);
    printf("{\"bench\": \"fit_orthogonal_formulation\", \"n\": %zu, \"noise\": 0.01, "
           "\"library_ms\": %.3f, \"library_iterations\": %d, \"library_f\": %.6g, "
           "\"ipopt_arrow_ms\": %.3f, \"ipopt_arrow_iterations\": %d, \"ipopt_arrow_f\": %.6g, "
           "\"arrow_over_library\": %.1f, \"library_paired_ms\": %.3f}\n",
           n, 1e3 * mt, il, fl, 1e3 * ma, ia, fa, ma / mt, 1e3 * mp);
    free(xy);
}

int main(void)
{
    const int quick = getenv("BENCH_FIT_QUICK") && !strcmp(getenv("BENCH_FIT_QUICK"), "1");
    bench_formulation(quick);
    bench_threads(quick);
    bench_scaling(quick);
    bench_memory();
    return 0;
}
