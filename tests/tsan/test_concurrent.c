/*
 * Concurrent calls under ThreadSanitizer (`make check-tsan`, part of `make
 * check`): every job below runs first serially, then in 4 threads at once,
 * each thread doing every job several times in its own order. TSan reports
 * any data race (halt_on_error); the results must be bit-identical to the
 * serial ones (no hidden shared state). Jobs: smooth and discrete evaluation
 * and Jacobians (equally spaced and scattered s), Hermite by tension and by
 * length, the certified B-spline, B-spline evaluation, elliptic blends,
 * resampling, an elastic spline with its B-spline, and the fits that stay off
 * Ipopt (its solves are serialised by a lock: not what this test is about): free, and
 * pinned at both ends (the ends chart).
 */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "elastica.h"

enum { NS = 64, NOUT = 4096, THREADS = 4, ROUNDS = 3 };

typedef int (*job_fn)(double *out, size_t *nout);

static const el_smooth_params SP = {0.3, -0.2, 0.4, 1.7, 0.85, 0.3, 6.0};

static void scattered(double *s, size_t n, double L)
{
    unsigned long long x = 88172645463325252ull;
    for (size_t i = 0; i < n; i++) {
        x ^= x << 13; x ^= x >> 7; x ^= x << 17;
        s[i] = L * (double)(x >> 11) / 9007199254740992.0;
    }
}

static int job_smooth(double *out, size_t *nout)
{
    double s[NS];
    for (int i = 0; i < NS; i++) s[i] = SP.length * i / (NS - 1);
    int st = el_smooth_eval(&SP, NS, s, out, out + 2 * NS, out + 3 * NS);
    scattered(s, NS, SP.length);
    if (!st) st = el_smooth_jacobian(&SP, NS, s, NULL, out + 4 * NS);
    *nout = 4 * NS + 14 * NS;
    return st;
}

static int job_discrete(double *out, size_t *nout)
{
    const el_discrete_params p = {0.1, 0.2, 0.15, 0.3, 0.12, 0.4, 0.9};
    int st = el_discrete_eval(&p, NS, out);
    if (!st) st = el_discrete_jacobian(&p, NS, NULL, out + 2 * NS);
    *nout = 2 * NS + 14 * NS;
    return st;
}

static int hermite(int mode, double *out, size_t *nout)
{
    const double p0[2] = {0, 0}, t0[2] = {0, 1}, p1[2] = {2, 0}, t1[2] = {0, -1};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.mode = mode;
    if (mode == EL_HERMITE_LENGTH) o.length = 4.0;
    else o.sigma = 2.0;
    el_hermite_result r;
    int st = el_hermite_solve(p0, t0, p1, t1, &o, &r);
    *nout = 0;
    for (size_t i = 0; !st && i < r.count && *nout + 9 <= NOUT; i++) {
        memcpy(out + *nout, &r.solutions[i].curve, 7 * sizeof(double));
        out[*nout + 7] = r.solutions[i].sigma;
        out[*nout + 8] = r.solutions[i].energy;
        *nout += 9;
    }
    if (!st) el_hermite_result_free(&r);
    return st;
}

static int job_hermite_tension(double *out, size_t *nout) { return hermite(EL_HERMITE_TENSION, out, nout); }
static int job_hermite_length(double *out, size_t *nout) { return hermite(EL_HERMITE_LENGTH, out, nout); }

static int job_bspline(double *out, size_t *nout)
{
    el_bspline b;
    int st = el_smooth_to_bspline(&SP, 1e-7, 3, &b);
    *nout = 0;
    if (st) return st;
    double t[NS];
    for (int i = 0; i < NS; i++) t[i] = SP.length * i / (NS - 1);
    st = el_bspline_eval(&b, NS, t, out);
    out[2 * NS] = b.max_deviation;
    out[2 * NS + 1] = (double)b.npoles;
    *nout = 2 * NS + 2;
    el_bspline_free(&b);
    return st;
}

static int job_blend(double *out, size_t *nout)
{
    el_blend_basis b;
    const double pts[8] = {0, 0, 0.3, 0.8, 0.7, 0.9, 1, 0};
    double q[8], t[NS];
    int st = el_blend_init_elliptic(&b, 0.55, 2.0);
    if (!st) st = el_blend_from_points(&b, pts, EL_BLEND_PICK_INTERPOLATE, q);
    for (int i = 0; i < NS; i++) t[i] = (double)i / (NS - 1);
    if (!st) st = el_blend_eval(&b, q, NS, t, out, out + 2 * NS);
    out[4 * NS] = b.basis_min;
    *nout = 4 * NS + 1;
    return st;
}

static int job_resample(double *out, size_t *nout)
{
    double xy[2 * NS];
    el_smooth_params p = SP;
    p.x0 = p.y0 = 0.0;
    double s[NS];
    for (int i = 0; i < NS; i++) s[i] = p.length * i / (NS - 1);
    el_smooth_eval(&p, NS, s, xy, NULL, NULL);
    el_resample_result r;
    int st = el_resample_equilateral(xy, NS, 0.05, &r);
    *nout = 0;
    if (st) return st;
    *nout = 2 * r.n < NOUT ? 2 * r.n : NOUT;
    memcpy(out, r.xy, *nout * sizeof *out);
    el_resample_free(&r);
    return st;
}

static int job_spline(double *out, size_t *nout)
{
    const double xy[12] = {0, 0, 2, 1.2, 4.5, 1.6, 7, 0.9, 9.2, -0.3, 11, 0.4};
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.sigma = 0.05;
    o.end.kind = EL_SPLINE_TANGENT;
    o.end.tangent[0] = 1.0;
    el_spline_result r;
    el_bspline b;
    int st = el_spline_solve(xy, 6, &o, &r);
    if (!st) st = el_spline_to_bspline(&r, 1e-6, 5, &b);
    *nout = 0;
    if (!st) {
        for (size_t i = 0; i < r.npieces; i++) memcpy(out + 7 * i, &r.pieces[i], 7 * sizeof(double));
        *nout = 7 * r.npieces;
        const size_t nb = 2 * b.npoles < NOUT - *nout ? 2 * b.npoles : NOUT - *nout;
        memcpy(out + *nout, b.poles, nb * sizeof(double));
        *nout += nb;
        el_bspline_free(&b);
    }
    el_spline_result_free(&r);
    return st;
}

/* a noisy-free orthogonal smooth fit and a paired discrete fit of samples of SP:
 * the common path (Levenberg-Marquardt, no Ipopt) */
static int job_fit(double *out, size_t *nout)
{
    double s[NS], xy[2 * NS];
    for (int i = 0; i < NS; i++) s[i] = SP.length * (i + 0.3 * (i % 3)) / (NS + 1);
    int st = el_smooth_eval(&SP, NS, s, xy, NULL, NULL);
    el_fit_smooth_result rs;
    el_fit_discrete_result rd;
    if (!st) st = el_fit_smooth(xy, NS, NULL, NULL, &rs, out + 14, out + 14 + NS);
    if (!st) st = el_fit_discrete(xy, NS, NULL, NULL, &rd, NULL, NULL);
    if (!st) {
        memcpy(out, &rs.params, 7 * sizeof(double));
        memcpy(out + 7, &rd.params, 7 * sizeof(double));
    }
    *nout = 14 + 2 * NS;
    return st;
}

/* the same points pinned at both ends, both models: the ends chart, no Ipopt either
 * (EL_EINTERNAL here if a fit ran it) */
static int job_fit_pinned(double *out, size_t *nout)
{
    double s[NS], xy[2 * NS];
    for (int i = 0; i < NS; i++) s[i] = SP.length * (i + 0.3 * (i % 3)) / (NS + 1);
    int st = el_smooth_eval(&SP, NS, s, xy, NULL, NULL);
    el_fit_options o;
    el_fit_options_defaults(&o);
    o.constraints = EL_CONSTRAIN_START_POINT | EL_CONSTRAIN_END_POINT;
    memcpy(o.start_point, xy, 2 * sizeof(double));
    memcpy(o.end_point, xy + 2 * NS - 2, 2 * sizeof(double));
    el_fit_smooth_result rs;
    el_fit_discrete_result rd;
    if (!st) st = el_fit_smooth(xy, NS, &o, NULL, &rs, out + 14, out + 14 + NS);
    if (!st) st = el_fit_discrete(xy, NS, &o, NULL, &rd, NULL, NULL);
    if (!st && (rs.used_ipopt || rd.used_ipopt)) st = EL_EINTERNAL;
    if (!st) {
        memcpy(out, &rs.params, 7 * sizeof(double));
        memcpy(out + 7, &rd.params, 7 * sizeof(double));
    }
    *nout = 14 + 2 * NS;
    return st;
}

static const struct { const char *name; job_fn fn; } JOBS[] = {
    {"smooth", job_smooth}, {"discrete", job_discrete}, {"hermite tension", job_hermite_tension},
    {"hermite length", job_hermite_length}, {"bspline", job_bspline}, {"blend", job_blend},
    {"resample", job_resample}, {"spline", job_spline}, {"fit", job_fit}, {"fit pinned", job_fit_pinned},
};
enum { NJOBS = sizeof JOBS / sizeof *JOBS };

static double serial[NJOBS][NOUT];
static size_t serial_n[NJOBS];
static int failures;   /* written under the lock */
static pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;

static void *worker(void *arg)
{
    const int id = (int)(size_t)arg;
    double *out = malloc(NOUT * sizeof *out);
    for (int r = 0; r < ROUNDS; r++)
        for (int j = 0; j < NJOBS; j++) {
            const int job = (j + id + r) % NJOBS;   /* every thread its own order */
            size_t n = 0;
            memset(out, 0, NOUT * sizeof *out);
            const int st = JOBS[job].fn(out, &n);
            if (st || n != serial_n[job] || memcmp(out, serial[job], n * sizeof *out)) {
                pthread_mutex_lock(&lock);
                failures++;
                fprintf(stderr, "thread %d: %s differs from the serial run (status %d)\n", id,
                        JOBS[job].name, st);
                pthread_mutex_unlock(&lock);
            }
        }
    free(out);
    return NULL;
}

int main(void)
{
    for (int j = 0; j < NJOBS; j++)
        if (JOBS[j].fn(serial[j], &serial_n[j]) != EL_OK || serial_n[j] == 0) {
            fprintf(stderr, "serial %s failed\n", JOBS[j].name);
            return 1;
        }
    pthread_t th[THREADS];
    for (int i = 0; i < THREADS; i++) pthread_create(&th[i], NULL, worker, (void *)(size_t)i);
    for (int i = 0; i < THREADS; i++) pthread_join(th[i], NULL);
    printf("tsan: %d jobs x %d rounds in %d threads: %s\n", NJOBS, ROUNDS, THREADS,
           failures ? "DIFFERENT from serial" : "bit-identical to serial, no race reported");
    return failures ? 1 : 0;
}
