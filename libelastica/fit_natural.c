/*
 * The natural batten: a smooth fit pinned at both ends with both end curvatures 0 (a
 * batten free to turn at two pins). Its feasible set is one-dimensional: kappa = 0 only
 * at an inflection, cn u = 0, so both ends are inflections, u(0) = q = K and
 * u(L) = q + 2 m K for m half-waves, sqrt(mu) L = 2 m K. Seed 000 (4.3) puts every
 * inflection on the axis: gamma(L) - gamma(0) = R(phi) (2 m (2E - K), 0) / sqrt(mu)
 * (E(u + 2K) = E(u) + 2E, cn vanishing at both ends), so the axis is the chord, and for
 * the chord c:
 *   sqrt(mu) = 2 m |2E - K| / c,   L = c K / |2E - K|   (the same for every m),
 *   phi = the chord's direction (+ pi where 2E < K),  k of either sign (the mirror image
 *   in the chord);
 * k = 0 is the straight segment. A batten cannot pass through itself: the members that
 * cross themselves are left out. With 2E < K (k > k*, the figure eight's 0.9089, where
 * 2E = K and the ends meet) the ends have passed each other and the curve crosses itself;
 * for 2E > K it does once lobes j and j + 2 (one side of the axis) overlap, m >= 3: the
 * lobe's width 2 (2 E(phi1) - F(phi1)) / sqrt(mu) between its vertical tangents
 * (dn^2 = 1/2, sin phi1 = 1 / (sqrt2 k)) reaches their distance 4 (2E - K) / sqrt(mu) at
 * k_t = 0.8551 (tests/c/test_fit_natural.c checks both bounds on sampled curves).
 * So each m is a curve of curves in k in (0, k*) (m <= 2) or (0, k_t], here in the
 * length ratio tau = ln(L / c - 1), which rises with k from -infinity (the segment).
 * Every fit that meets the constraints is a member, so the fit is this search: samples of
 * tau for each (m, mirror), GSL's Brent minimiser from the lowest sampled minima, of the
 * objective the fit minimises (the inner points' squared distances to their nearest
 * points on the curve, el__fit_feet_elsewhere; the end points' residuals are the pins',
 * the same for every member). Written here rather than left to Ipopt from the guesses with
 * kappa1 = 0 as a row: the family has a basin per m and mirror at least, and Ipopt's runs
 * crawled between them into loops (measured: fit.c).
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The samples of tau: from L / c = 1 + e^-40 in steps of e^4 to 1 + e^-8, then of e^0.5
 * (at most NTAU_MAX in all) up to 1 + e^4, three times the points' polygon or the
 * touching lobes; half-waves from 1 to
 * the points' crossings of the chord + 4 (at least 6, at most MMAX); Brent's minimiser
 * from the NREFINE lowest sampled minima of each kind (following the points or not).
 * The samples and the minimiser see NSCAN of the points at most (spread by index, the ends
 * among them), Gauss-Newton and the certificate all of them: ~600 members evaluated over
 * all of 20 000 noisy points along a member took 6 s, where the former fits of the guesses
 * by Ipopt took 0.54 s; so 0.26 s (2000 points: 0.057 s, Ipopt's 0.092; 200: 0.050 s,
 * Ipopt's 0.020), the same rms. */
enum { NTAU_MAX = 128, MMAX = 64, NREFINE = 3, NSCAN = 64 };
#define TAU0 (-8.0)
#define TAU_STEP 0.5
/* below TAU0 (members within ~k^2 of the segment: nearly straight battens) in steps of 4
 * from TAU_LOW: the minimum of noisy nearly collinear points lies there (k ~ 1e-3,
 * tau ~ -14), and the segment is a minimum only where f keeps rising towards it */
#define TAU_LOW (-40.0)
#define NLOW 8
static double tau_at(int j) { return j < NLOW ? TAU_LOW + 4.0 * j : TAU0 + TAU_STEP * (j - NLOW); }

typedef struct {
    fit_objective *ob;
    int m, mirror;             /* half-waves (0: the straight segment), k < 0 */
    double *d, *fs, *fs_in;    /* n each: distances and feet, the feet in input units */
    double *r;                 /* 3 n: gauss_newton's distances */
    double noise, poly;        /* el__fit_noise_rms and the points' polygon length (normalised) */
    int classify;              /* member_f sets strays (the scan, a refined minimum) */
    int strays;                /* member_f's last member winds where there are no points: it
                                  strays from them (el__fit_stray) and is longer than 1.25 poly */
    int evals, err;            /* member_f's evaluations; EL_ENOMEM seen */
    double target;             /* tau_gap's */
} family;

/* K and g = 2E - K at modulus k, and tau = ln(L / c - 1) = ln(2 k^2 D / g) without the
 * cancellation of K / g - 1 (D = (K - E) / k^2, el__ellint_complete); EL_EDOM for g <= 0 */
static int member_shape(double k, double *K, double *g, double *tau)
{
    double D;
    if (el__ellint_complete(k, (1.0 - k) * (1.0 + k), K, &D)) return EL_EDOM;
    *g = *K - 2.0 * k * k * D;
    *tau = log(2.0 * k * k * D / *g);
    return *g > 0.0 && isfinite(*tau) ? EL_OK : EL_EDOM;
}

static double g_of(double k, void *p)
{
    (void)p;
    double K, D;
    if (el__ellint_complete(k, (1.0 - k) * (1.0 + k), &K, &D)) return NAN;
    return K - 2.0 * k * k * D;
}

/* lobes j and j + 2 touch: 2 E(phi1) - F(phi1) - 2 (2E - K), sin phi1 = 1 / (sqrt2 k) */
static double touch_gap(double k, void *p)
{
    (void)p;
    const double phi1 = asin(1.0 / (M_SQRT2 * k));
    gsl_sf_result E1, F1;
    if (gsl_sf_ellint_E_e(phi1, k, GSL_PREC_DOUBLE, &E1) || gsl_sf_ellint_F_e(phi1, k, GSL_PREC_DOUBLE, &F1))
        return NAN;
    return 2.0 * E1.val - F1.val - 2.0 * g_of(k, NULL);
}

static double tau_gap(double k, void *p)
{
    const family *fm = p;
    double K, g, tau;
    return member_shape(k, &K, &g, &tau) ? NAN : tau - fm->target;
}

/* The root of fn on [lo, hi] (a sign change) by GSL's Brent to the rounding of k */
static int root(gsl_function *fn, double lo, double hi, double *x)
{
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    int st = gsl_root_fsolver_set(s, fn, lo, hi) == GSL_SUCCESS ? EL_OK : EL_EDOM;
    for (int it = 0; it < 200 && !st; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) st = EL_EDOM;
        else if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-15) ==
                 GSL_SUCCESS)
            break;
    }
    *x = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    return st;
}

int el__natural_moduli(double *kstar, double *ktouch)
{
    el__gsl_quiet();
    gsl_function g = {g_of, NULL}, t = {touch_gap, NULL};
    int st = root(&g, 0.5, 0.99, kstar);
    return st ? st : root(&t, 0.75, *kstar, ktouch);
}

/* The member at tau into v (normalised parameters): k from tau (GSL's Brent on
 * [1e-12, kmax], tau from -55); EL_EDOM beyond */
static int member(family *fm, double tau, double kmax, double *v)
{
    const fit_map *map = &fm->ob->map;
    const double c = fit_norm(map->chord[0], map->chord[1]), alpha = atan2(map->chord[1], map->chord[0]);
    v[0] = map->fixed[0];
    v[1] = map->fixed[1];
    v[2] = alpha;
    if (fm->m == 0) {           /* the straight segment: k = 0, sqrt(mu) L = 2K = pi */
        const double rest[4] = {M_PI / c, 0.0, 0.5 * M_PI, c};
        memcpy(v + 3, rest, sizeof rest);
        return EL_OK;
    }
    fm->target = tau;
    gsl_function fn = {tau_gap, fm};
    double k = kmax, K, g, t;
    const double gap_hi = tau_gap(kmax, fm);     /* 0 at the touching lobes' own tau_t */
    if (!(tau_gap(1e-12, fm) < 0.0 && gap_hi >= 0.0)) return EL_EDOM;
    const int st = gap_hi == 0.0 ? EL_OK : root(&fn, 1e-12, kmax, &k);
    if (st == EL_ENOMEM) fm->err = st;
    if (st || member_shape(k, &K, &g, &t)) return EL_EDOM;
    v[3] = 2.0 * fm->m * g / c;
    v[4] = fm->mirror ? -k : k;
    v[5] = K;
    v[6] = c * K / g;
    return EL_OK;
}

/* The objective of the member at tau (sum of the inner points' squared distances);
 * HUGE_VAL where there is none */
typedef struct { family *fm; double kmax; } member_at;
static double member_f(double tau, void *p)
{
    const member_at *ma = p;
    family *fm = ma->fm;
    fit_objective *ob = fm->ob;
    double v[2][FIT_NP], x[FIT_MAXX];
    fm->strays = 1;
    if (fm->err || member(fm, tau, ma->kmax, v[0])) return HUGE_VAL;
    fm->evals++;
    const int st = el__fit_curve_feet(ob, v, x, fm->d, fm->fs);
    if (st == EL_ENOMEM) fm->err = st;
    if (st) return HUGE_VAL;
    double f = 0.0;
    for (size_t i = 1; i + 1 < ob->n; i++) f += fm->d[i] * fm->d[i];
    if (!isfinite(f)) return HUGE_VAL;
    if (!fm->classify) return f;     /* Brent's and Gauss-Newton's steps need f alone */
    for (size_t i = 0; i < ob->n; i++) fm->fs_in[i] = fm->fs[i] * ob->sc;
    const double stray = el__fit_stray(ob->xy, ob->n, fm->fs_in, v[0][6] * ob->sc, fm->noise * ob->sc, ob->sc);
    if (stray < 0.0) { fm->err = EL_ENOMEM; return HUGE_VAL; }
    fm->strays = stray > FIT_STRAY && v[0][6] > 1.25 * fm->poly;
    return f;
}

/* A candidate: a sampled minimum (tau between its neighbours lo, hi), or (bound) the
 * touching lobes' tau_t or the segment, a minimum by its place (no Brent) */
typedef struct { double f, tau, lo, flo, hi, fhi, kmax; int m, mirror, bound, follows; } candidate;

/* those that follow their points first, then by f */
static int by_follows_f(const void *a, const void *b)
{
    const candidate *p = a, *q = b;
    if (p->follows != q->follows) return q->follows - p->follows;
    return (p->f > q->f) - (p->f < q->f);
}

/* Gauss-Newton on tau from Brent's minimum, the distances' derivative by central
 * differences; returns whether it converged (the certificate along the family). Brent's
 * minimiser stops at 1e-3 in tau here and could not go below ~1e-8 |tau| (GSL's
 * tolerance), which leaves a curve through exact points 1e-8 of its size off them; these
 * steps take it to rounding (the distances vanish there: quadratic convergence) */
static int gauss_newton(family *fm, const member_at *ma, candidate *c)
{
    const size_t n = fm->ob->n;
    double *r = fm->r, *rp = fm->r + n, *rm = fm->r + 2 * n;
    for (int it = 0; it < 12 && !fm->err; it++) {
        const double h = 1e-5 * (1.0 + fabs(c->tau));
        const double f0 = member_f(c->tau, (void *)ma);
        memcpy(r, fm->d, sizeof(double) * n);
        const double fp = member_f(c->tau + h, (void *)ma);
        memcpy(rp, fm->d, sizeof(double) * n);
        const double fmn = member_f(c->tau - h, (void *)ma);
        memcpy(rm, fm->d, sizeof(double) * n);
        if (!(f0 < HUGE_VAL && fp < HUGE_VAL && fmn < HUGE_VAL)) return 0;
        c->f = f0;
        double jr = 0.0, jj = 0.0;
        for (size_t i = 1; i + 1 < n; i++) {
            const double J = (rp[i] - rm[i]) / (2.0 * h);
            jr += J * r[i];
            jj += J * J;
        }
        const double step = -jr / jj;
        if (!isfinite(step)) return 0;
        /* converged: the step at the resolution of tau, or the decrease it promises
         * (jr step / 2 of the sum of squares) at the rounding of f */
        const int conv = fabs(step) <= 1e-12 * (1.0 + fabs(c->tau)) || -0.5 * jr * step <= 1e-14 * f0;
        const double f1 = member_f(c->tau + step, (void *)ma);
        if (!(f1 < c->f)) return conv;
        c->tau += step;
        c->f = f1;
        if (conv) return 1;
    }
    return 0;
}

/* Brent's minimiser on the candidate's bracket to tol in tau (1e-3 for the candidates:
 * gauss_newton polishes the one kept); returns whether it converged there */
static int refine(family *fm, candidate *c, double tol)
{
    fm->m = c->m;
    fm->mirror = c->mirror;
    member_at ma = {fm, c->kmax};
    if (c->bound || !(c->flo > c->f && c->fhi > c->f)) return 0;
    gsl_function fn = {member_f, &ma};
    gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent);
    if (!s) { fm->err = EL_ENOMEM; return 0; }
    int conv = 0;
    if (gsl_min_fminimizer_set_with_values(s, &fn, c->tau, c->f, c->lo, c->flo, c->hi, c->fhi) == GSL_SUCCESS) {
        for (int it = 0; it < 100 && !conv; it++) {
            if (gsl_min_fminimizer_iterate(s) != GSL_SUCCESS) break;
            conv = gsl_min_test_interval(gsl_min_fminimizer_x_lower(s), gsl_min_fminimizer_x_upper(s), tol, 0.0) ==
                   GSL_SUCCESS;
        }
        if (gsl_min_fminimizer_f_minimum(s) <= c->f) {
            c->f = gsl_min_fminimizer_f_minimum(s);
            c->tau = gsl_min_fminimizer_x_minimum(s);
        }
    }
    gsl_min_fminimizer_free(s);
    fm->classify = 1;
    member_f(c->tau, &ma);      /* whether the minimum follows its points */
    fm->classify = 0;
    c->follows = !fm->strays;
    return conv;
}

/* The half-waves to try: the points' crossings of the chord (changes of their side
 * beyond 3 noise levels) + 4, at least 6. More fit the noise: 30 noisy collinear points
 * are 1.5 % closer to a member of 9 half-waves of amplitude 3e-4 of the length than to
 * the best of 6 (test_fit_natural.c) */
static int max_halfwaves(const fit_objective *ob, double noise)
{
    const double *c = ob->map.chord, cn = fit_norm(c[0], c[1]);
    int side = 0, cross = 0;
    for (size_t i = 0; i < ob->n; i++) {
        double P[2];
        fit_point(ob, i, P);
        const double e = (c[0] * (P[1] - ob->map.fixed[1]) - c[1] * (P[0] - ob->map.fixed[0])) / cn;
        const int sd = e > 3.0 * noise ? 1 : e < -3.0 * noise ? -1 : 0;
        if (sd && side && sd != side) cross++;
        if (sd) side = sd;
    }
    return cross + 4 < 6 ? 6 : cross + 4 > MMAX ? MMAX : cross + 4;
}

/* The sampled minima over tau of every (m, mirror) into cs (*nc), and the straight
 * segment where it is below the nearest samples. Interior minima, and for m >= 3 the
 * touching lobes' end tau_t where f falls towards it (the members beyond cross: a minimum
 * under that bound); the other ends are limits (the segment, the figure
 * eight's infinite loop) */
static void scan(family *fm, int mmax, double kstar, double ktouch, candidate *cs, int *nc)
{
    /* up to L / c = 1 + e^4, or 3 times the points' polygon (pins close together) */
    const double c = fit_norm(fm->ob->map.chord[0], fm->ob->map.chord[1]), r = 3.0 * fm->poly / c;
    const double tau_hi = r > 1.0 + exp(4.0) ? log(r - 1.0) : 4.0;
    const int nt = NLOW + 1 + (int)ceil((tau_hi - TAU0) / TAU_STEP), ntau = nt < NTAU_MAX ? nt : NTAU_MAX;
    double K, g, tau_t;
    if (member_shape(ktouch, &K, &g, &tau_t)) tau_t = HUGE_VAL;
    fm->m = 0;
    member_at straight = {fm, kstar};
    const double f0 = member_f(0.0, &straight);
    const int seg_follows = !fm->strays;
    int seg_min = f0 < HUGE_VAL;
    for (int m = 1; m <= mmax && !fm->err; m++)
        for (int mir = 0; mir < 2; mir++) {
            fm->m = m;
            fm->mirror = mir;
            const double kmax = m <= 2 ? kstar * (1.0 - 1e-12) : ktouch;
            member_at ma = {fm, kmax};
            double t[NTAU_MAX + 1], f[NTAU_MAX + 1];
            int ns = 0, fol[NTAU_MAX + 1];
            for (int j = 0; j < ntau; j++) {
                const double tj = tau_at(j);
                if (m >= 3 && tj >= tau_t) break;
                t[ns] = tj;
                f[ns] = member_f(tj, &ma);
                fol[ns++] = !fm->strays;
            }
            const int edge = m >= 3 && ns < ntau;
            if (edge) {
                t[ns] = tau_t;
                f[ns] = member_f(tau_t, &ma);
                fol[ns++] = !fm->strays;
            }
            if (ns > 0) seg_min &= !(f[0] < f0);
            for (int j = 1; j < ns; j++) {
                if (!(f[j] < f[j - 1])) continue;
                if (j + 1 < ns && f[j] <= f[j + 1])
                    cs[(*nc)++] = (candidate){f[j], t[j], t[j - 1], f[j - 1], t[j + 1], f[j + 1], kmax, m, mir, 0,
                                              fol[j]};
                else if (j + 1 == ns && edge)
                    cs[(*nc)++] = (candidate){f[j], t[j], t[j - 1], f[j - 1], t[j], f[j], kmax, m, mir, 1, fol[j]};
            }
        }
    /* both mirror images of every m tend to the segment as k -> 0 (smoothly in the signed
     * k): a minimum where none of their first samples (k ~ 2e-9) is lower */
    if (seg_min) cs[(*nc)++] = (candidate){f0, 0.0, 0.0, f0, 0.0, f0, kstar, 0, 0, 1, seg_follows};
}

/* The length of the points' polygon (normalised) */
static double polygon_length(const fit_objective *ob)
{
    double poly = 0.0;
    for (size_t i = 0; i + 1 < ob->n; i++) {
        double P[2], Q[2];
        fit_point(ob, i, P);
        fit_point(ob, i + 1, Q);
        poly += fit_norm(Q[0] - P[0], Q[1] - P[1]);
    }
    return poly;
}

int el__fit_natural_fit(fit_objective *ob, double noise, double *v, int *certified, int *evals)
{
    el__gsl_quiet();
    double kstar, ktouch;
    int st = el__natural_moduli(&kstar, &ktouch);
    if (st) return st;
    family fm;
    memset(&fm, 0, sizeof fm);
    fm.ob = ob;
    fm.noise = noise;
    fm.poly = polygon_length(ob);
    const int mmax = max_halfwaves(ob, noise);
    double *buf = malloc(sizeof(double) * 6 * ob->n), *sxy = malloc(sizeof(double) * 3 * NSCAN);
    candidate *cs = malloc(sizeof *cs * (size_t)(2 * mmax * (NTAU_MAX + 1) + 1));
    st = EL_ENOMEM;
    if (!buf || !sxy || !cs) goto out;
    fm.d = buf;
    fm.fs = buf + ob->n;
    fm.fs_in = buf + 2 * ob->n;
    fm.r = buf + 3 * ob->n;
    /* the scan and the minimiser on NSCAN of the points at most (their own objective, the
     * same map), Gauss-Newton and the certificate on all */
    fit_objective sub;
    int have_sub = 0;
    if (ob->n > NSCAN) {
        for (size_t i = 0; i < NSCAN; i++) {
            const size_t j = (size_t)((double)i * (double)(ob->n - 1) / (double)(NSCAN - 1) + 0.5);
            sxy[2 * i] = ob->xy[2 * j];
            sxy[2 * i + 1] = ob->xy[2 * j + 1];
            sxy[2 * NSCAN + i] = ob->t[j];
        }
        if (el__fit_objective_init(&sub, ob->kind, &ob->map, sxy, NSCAN, ob->cx, ob->cy, ob->sc, sxy + 2 * NSCAN))
            goto out;
        have_sub = 1;
        sub.exact_ends = ob->exact_ends;
        fm.ob = &sub;
        fm.poly = polygon_length(&sub);
    }
    int nc = 0;
    fm.classify = 1;
    scan(&fm, mmax, kstar, ktouch, cs, &nc);
    fm.classify = 0;
    /* the lowest sampled minima refined, NREFINE of those that follow their points and
     * NREFINE of the others (a snake wound across the points comes closer to more of them:
     * member_f); the lowest that follows, else the lowest */
    qsort(cs, (size_t)nc, sizeof *cs, by_follows_f);
    int pick = -1, done[2] = {0, 0};
    for (int i = 0; i < nc && !fm.err; i++) {
        const int cls = cs[i].follows;     /* the sample's; the minimum's after refine */
        if (done[cls]++ >= NREFINE) continue;
        refine(&fm, &cs[i], 1e-3);
        if (pick < 0 || by_follows_f(&cs[i], &cs[pick]) < 0) pick = i;
    }
    if (have_sub) {
        el__fit_objective_free(&sub);
        fm.ob = ob;
        fm.poly = polygon_length(ob);
    }
    st = fm.err ? fm.err : pick < 0 ? EL_EDOM : EL_OK;
    if (!st) {
        candidate *c = &cs[pick];
        fm.m = c->m;
        fm.mirror = c->mirror;
        const member_at ma = {&fm, c->kmax};
        c->f = member_f(c->tau, (void *)&ma);     /* of all the points (the scan's: of NSCAN) */
        int conv = c->m > 0 && gauss_newton(&fm, &ma, c);
        if (c->m > 0 && !c->bound && !conv) {
            /* Gauss-Newton did not settle (a minimum where a foot changes pass, a kink of f):
             * a minimum along the family all the same where Brent's minimiser closes on it */
            c->lo = c->tau - 1e-2;
            c->hi = c->tau + 1e-2;
            c->flo = member_f(c->lo, (void *)&ma);
            c->fhi = member_f(c->hi, (void *)&ma);
            conv = refine(&fm, c, 1e-6);
        }
        st = fm.err ? fm.err : member(&fm, c->tau, c->kmax, v);
        *certified = c->bound || conv;
        *evals = fm.evals;
    }
out:
    ob->rest_ok = 0;
    ob->have_base = 0;
    free(buf);
    free(sxy);
    free(cs);
    return st;
}
