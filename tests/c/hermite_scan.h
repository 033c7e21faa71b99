/* The dense scan of the Hermite objective (tension mode, case 1) that the completeness
 * tests compare the solver with: plain sampling and bisection, independent of the
 * solver's split points, sampling, refinement and root finding. For the test programs
 * that include hermite_internal.h. */
#ifndef EL_HERMITE_SCAN_H
#define EL_HERMITE_SCAN_H

#include "testutil.h"
#include "hermite_internal.h"
#include <string.h>

/* A dense scan of the objective of the normalised problem, independent of the solver's
 * bracketing (split points, sampling, refinement): every sign change of f between
 * neighbours of a uniform grid of nx <= NX points per branch that bisection closes to |f| <=
 * 1e-9 (a jump of f where L wraps at a period stays large), and, at every crossing of
 * the separatrix the same grid shows (a sign change of |F| - sigma, computed from the
 * curvature data alone), the same in y = ln| |F| - sigma | on both sides, NY points
 * from |F| - sigma = 1e-3 sigma down to 1e-300 sigma, denser near the top. */
typedef struct { double k0, L; int sep; } scan_root;
enum { NX = 3000, NY = 240, MAXSCAN = 64 };

static double scan_f(const hprob *pr, int b, int side, double u, double *w, hstate *st)
{
    hgrad g;
    if (side == 0) return el__hermite_full_eval(pr, u, b, st) ? NAN : st->f;
    double ww = *w;
    if (el__hermite_sep_eval(pr, HCHART_X, 0, b, side, u, pr->sigma, 1.0, &ww, st, &g, NULL)) return NAN;
    return st->f;
}

static void scan_add(scan_root *r, int *n, const hstate *st, int sep)
{
    for (int i = 0; i < *n; i++)
        if (fabs(r[i].k0 - st->k0) <= 1e-6 * (1.0 + fabs(st->k0)) && fabs(r[i].L - st->L) <= 1e-6 * st->L) return;
    if (*n < MAXSCAN) r[(*n)++] = (scan_root){st->k0, st->L, sep};
}

/* the roots on the grid us[0..m-1] (x, or y on side side of the crossing near w) */
static void scan_grid(const hprob *pr, int b, int side, double w, const double *us, int m,
                      scan_root *r, int *n)
{
    hstate st;
    double fp = NAN;
    for (int i = 0; i < m; i++) {
        const double f = scan_f(pr, b, side, us[i], &w, &st);
        if (f * fp < 0.0) {
            double lo = us[i - 1], hi = us[i], flo = fp;
            for (int it = 0; it < 80; it++) {
                const double mid = 0.5 * (lo + hi), fm = scan_f(pr, b, side, mid, &w, &st);
                if (!isfinite(fm)) break;
                if (fm * flo > 0.0) { lo = mid; flo = fm; } else hi = mid;
            }
            if (isfinite(scan_f(pr, b, side, 0.5 * (lo + hi), &w, &st)) && fabs(st.f) <= 1e-9) scan_add(r, n, &st, side != 0);
        }
        fp = f;
    }
}

/* |F| - sigma at x on branch b from the curvature data alone (NaN outside (18)) */
static double scan_sep(const hprob *pr, int b, double x)
{
    hstate st;
    if (el__hermite_curvdata(pr, x, b, &st)) return NAN;
    const double F1 = -2.0 * st.k0p, F2 = st.k0 * st.k0 - pr->sigma;
    return sqrt(F1 * F1 + F2 * F2) - pr->sigma;
}

static int dense_scan(const hprob *pr0, double sigma, int nx, scan_root *r)
{
    hprob pr = *pr0;
    pr.sigma = sigma;
    el_hermite_analysis an;
    const double P[2] = {pr.P1, pr.P2}, V[2] = {pr.V1, pr.V2};
    ck_assert_int_eq(el_hermite_analyse(P, V, sigma, &an), EL_OK);
    int n = 0;
    if (an.kappa_bound < 0.0) return 0;
    static double xs[NX], ys[NY];
    for (int i = 0; i < nx; i++) xs[i] = -an.kappa_bound + 2.0 * an.kappa_bound * i / (nx - 1);
    for (int i = 0; i < NY; i++) {
        const double t = (double)(NY - 1 - i) / (NY - 1);
        ys[i] = log(1e-3 * sigma) - 690.0 * t * t;
    }
    for (int b = 0; b < 2; b++) {
        scan_grid(&pr, b, 0, 0.0, xs, nx, r, &n);
        if (!(sigma > 0.0)) continue;
        double dp = NAN;
        for (int i = 0; i < nx; i++) {
            const double d = scan_sep(&pr, b, xs[i]);
            /* the crossings between this grid point and the last: at an end of the domain
             * (18), where |F| - sigma can turn between the end and the grid point, the end
             * is located by bisection and the stretch sampled 200 times */
            double seg[202];
            int ns = 0;
            if (i > 0 && isnan(d) != isnan(dp)) {
                double in = isnan(d) ? xs[i - 1] : xs[i], out = isnan(d) ? xs[i] : xs[i - 1];
                for (int it = 0; it < 60; it++) {
                    const double mid = 0.5 * (in + out);
                    if (isnan(scan_sep(&pr, b, mid))) out = mid; else in = mid;
                }
                const double other = isnan(d) ? xs[i - 1] : xs[i];
                for (int k = 0; k <= 200; k++) seg[ns++] = in + (other - in) * k / 200.0;
            } else if (i > 0) {
                seg[ns++] = xs[i - 1];
                seg[ns++] = xs[i];
            }
            for (int k = 0; k + 1 < ns; k++) {
                double lo = seg[k], hi = seg[k + 1];
                if (!(scan_sep(&pr, b, lo) * scan_sep(&pr, b, hi) < 0.0)) continue;
                for (int it = 0; it < 60; it++) {     /* the crossing, by bisection */
                    const double mid = 0.5 * (lo + hi);
                    if (scan_sep(&pr, b, mid) * scan_sep(&pr, b, lo) > 0.0) lo = mid; else hi = mid;
                }
                const double w = 0.5 * (lo + hi);
                scan_grid(&pr, b, 1, w, ys, NY, r, &n);
                scan_grid(&pr, b, -1, w, ys, NY, r, &n);
            }
            dp = d;
        }
    }
    return n;
}

/* The scan and the solve of one problem p0 = 0, t0 = (0, 1), p1, t1 (unit) at sigma: 0
 * when the problem is not case 1 (nothing done), else 1 with the scan's roots in r[0..*n)
 * and the solver's result in *res (EL_OK asserted; the caller frees it). */
static int scan_and_solve(const double p1[2], const double t1[2], double sigma, int nx, scan_root *r,
                          int *n, el_hermite_result *res)
{
    const double p0[2] = {0, 0}, t0[2] = {0, 1};
    hprob pr;
    memset(&pr, 0, sizeof pr);
    pr.P1 = p1[0]; pr.P2 = p1[1]; pr.V1 = t1[0]; pr.V2 = t1[1]; pr.Lmin = 1.0;
    el__hermite_set_case(&pr);
    if (pr.hcase != 1) return 0;
    *n = dense_scan(&pr, sigma, nx, r);
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = sigma;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &o, res), EL_OK);
    return 1;
}

/* Whether the scan's root r is among the solutions (kappa0 and length to 1e-6). */
static int scan_root_found(const scan_root *r, const el_hermite_result *res)
{
    for (size_t j = 0; j < res->count; j++)
        if (fabs(res->solutions[j].kappa0 - r->k0) <= 1e-6 * (1.0 + fabs(r->k0)) &&
            fabs(res->solutions[j].length - r->L) <= 1e-6 * r->L)
            return 1;
    return 0;
}

/* A random problem at high tension: P, V unit at random angles, sigma log-uniform in
 * [100, 1e4], its normalised form *pr and el_hermite_analyse's analysis (EL_OK asserted). */
static void high_tension_problem(unsigned long long *st, double P[2], double V[2], double *sigma, hprob *pr,
                                 el_hermite_analysis *an)
{
    const double a = test_uniform(st, -M_PI, M_PI), c = test_uniform(st, -M_PI, M_PI);
    *sigma = 100.0 * pow(100.0, test_uniform(st, 0.0, 1.0));
    P[0] = cos(a); P[1] = sin(a); V[0] = cos(c); V[1] = sin(c);
    memset(pr, 0, sizeof *pr);
    pr->P1 = P[0]; pr->P2 = P[1]; pr->V1 = V[0]; pr->V2 = V[1]; pr->Lmin = 1.0; pr->sigma = *sigma;
    el__hermite_set_case(pr);
    ck_assert_int_eq(el_hermite_analyse(P, V, *sigma, an), EL_OK);
}

#endif
