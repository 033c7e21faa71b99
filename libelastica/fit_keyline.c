/*
 * A keyline as one problem (seed 000 §5.4; header el_fit_keyline_smooth): two
 * inflectional elasticae that start at a common joint J, `first` towards point 0 and
 * `second` towards point n-1, with opposite tangents and zero curvature there (G2).
 *
 * The joint conditions are built into the variables instead of being constraints:
 * zero curvature at the start is u(0) = K(|k|) (kappa = 2 k w cn u; discrete: the
 * potential symmetric about vertex 0, a_1 = a_{-1}, so the turning angle there is 0),
 * and then the start tangent is known in closed form, theta(0) = phi + 2 asin k
 * (discrete: Theta_0 = phi + a_0 + a_1, a_0 = asin k). So with psi the tangent of
 * `second` at J (the first one's is psi + pi) the variables are
 *   smooth   x = (xJ, yJ, psi, w1, t1, L1, w2, t2, L2),   k_c = tanh t_c, phi_c = psi_c - 2 asin k_c,
 *   discrete x = (xJ, yJ, psi, (m1-1) h1, (m1-1) z1, k1, (m2-1) h2, (m2-1) z2, k2),
 *            phi_c = psi_c - a_0 - a_1,
 * q_c = K(|k_c|) for both, and every point of the solution space is a G2 keyline: the
 * joint conditions hold to rounding, and Levenberg-Marquardt (fit_lm.c) solves the
 * problem without Ipopt. Smooth: each point's foot lies on either curve (fit_objective.c)
 * so J moves freely along the data; discrete: the split index moves while the joint fit
 * improves.
 *
 * The starts: (1) each side fitted alone from the caller's split, the zeros of their
 * curvature nearest the split (the curves extended past it) estimate the inflection,
 * and the joint curve starts there with each side's shape (k clipped to |k| <= 0.95,
 * its sign from the side's sense of turning after the zero); (2) one elastica of all
 * the points (smooth: of at most 64 of them, paired), split at its inflection
 * (whole_start). The better joint fit is kept. On QA's 40 tile profiles (1) alone was
 * > 2 x worse than one elastica in 9 smooth / 15 discrete fits: a split far from the
 * inflection leaves a side of a few points, whose fit alone lands at |k| ~ 1.
 */
#include "fit_internal.h"
#include "fit_ends.h"
#include <stdlib.h>
#include <string.h>
#include <float.h>
#include <gsl/gsl_sf_ellint.h>

/* The smooth keyline's shape variable t = atanh k of each side, |t| <= 12 (1 - |k| >=
 * 7.6e-11: K and the curve to ~1e-6 relative of 1 - |k|, rounded k's error). */
#define KEYLINE_T_MAX 12.0
static double smooth_t(double k) { return atanh(fmax(fmin(k, tanh(KEYLINE_T_MAX)), -tanh(KEYLINE_T_MAX))); }

/* K(|k|) and dK(|k|)/dk (odd in k) for |k| < 1. */
static int quarter_period(double k, double *K, double *dK)
{
    const double a = fabs(k);
    if (!(a < 1.0)) return EL_EDOM;
    gsl_sf_result Kr, Er;
    if (gsl_sf_ellint_Kcomp_e(a, GSL_PREC_DOUBLE, &Kr) || gsl_sf_ellint_Ecomp_e(a, GSL_PREC_DOUBLE, &Er))
        return EL_EDOM;
    *K = Kr.val;
    const double d = a < 1e-4 ? M_PI * a / 4.0 : (Er.val - (1.0 - a * a) * Kr.val) / (a * (1.0 - a * a));
    *dK = copysign(d, k);
    return EL_OK;
}

/* The full 9 joint variables from x (the free ones) and the fixed h. */
static void full_vars(const fit_map *m, const double *x, double *f)
{
    if (m->nx == 9) { memcpy(f, x, sizeof(double) * 9); return; }
    /* discrete with both h held: x = (xJ, yJ, psi, Z1, k1, Z2, k2) */
    f[0] = x[0]; f[1] = x[1]; f[2] = x[2];
    f[3] = m->fixed_h * m->scale[0]; f[4] = x[3]; f[5] = x[4];
    f[6] = m->fixed_h * m->scale[1]; f[7] = x[5]; f[8] = x[6];
}

int el__fit_keyline_map(const fit_map *m, const double *x, double v[2][FIT_NP], double *M)
{
    double f[9], Mf[2][FIT_NP][9];
    full_vars(m, x, f);
    memset(Mf, 0, sizeof Mf);
    for (int c = 0; c < 2; c++) {
        const double *y = f + 3 + 3 * c, psi = f[2] + (c == 0 ? M_PI : 0.0);
        double K, dK;
        int st;
        v[c][0] = f[0]; v[c][1] = f[1];
        Mf[c][0][0] = 1.0; Mf[c][1][1] = 1.0;
        if (m->model == FIT_SMOOTH) {
            /* k = tanh t (smooth_k): K(k) ~ |t| + log 2 as |k| -> 1, so a step of t reaches
             * the near-separatrix shapes a side may need instead of halving 1 - |k| at the
             * bound |k| < 1 step after step (the k = 1 trap) */
            const double w = y[0], t = y[1];
            if (!(fabs(t) <= KEYLINE_T_MAX)) return EL_EDOM;
            const double k = tanh(t), ch = cosh(t), dk = 1.0 / (ch * ch);
            if ((st = quarter_period(k, &K, &dK))) return st;
            /* v = (x0, y0, phi, w, k, q, L); asin k = atan(sinh t), d/dt = 1 / cosh t */
            v[c][2] = psi - 2.0 * atan(sinh(t));
            v[c][3] = w; v[c][4] = k; v[c][5] = K; v[c][6] = y[2];
            Mf[c][2][2] = 1.0; Mf[c][2][4 + 3 * c] = -2.0 / ch;
            Mf[c][3][3 + 3 * c] = 1.0;
            Mf[c][4][4 + 3 * c] = dk;
            Mf[c][5][4 + 3 * c] = dK * dk;
            Mf[c][6][5 + 3 * c] = 1.0;
        } else {
            const double s = m->scale[c], h = y[0] / s, z = y[1] / s, k = y[2];
            if ((st = quarter_period(k, &K, &dK))) return st;
            el_jacobi J, Jk;
            if (el_jacobi_eval(K + z, fabs(k), &J, NULL, &Jk)) return EL_EDOM;
            /* a_1 = atan2(k sn, dn) at u_1 = K + z: da/du = k cn, da/dk|u = dn sn + |k| (dn sn_k - sn dn_k) */
            const double a1 = atan2(k * J.sn, J.dn), a_u = k * J.cn;
            const double a_k = J.dn * J.sn + fabs(k) * (J.dn * Jk.sn - J.sn * Jk.dn);
            /* v = (x0, y0, h, phi, z, q, k) */
            v[c][2] = h;
            v[c][3] = psi - asin(k) - a1;
            v[c][4] = z; v[c][5] = K; v[c][6] = k;
            Mf[c][2][3 + 3 * c] = 1.0 / s;
            Mf[c][3][2] = 1.0;
            Mf[c][3][4 + 3 * c] = -a_u / s;
            Mf[c][3][5 + 3 * c] = -1.0 / sqrt(1.0 - k * k) - a_k - a_u * dK;
            Mf[c][4][4 + 3 * c] = 1.0 / s;
            Mf[c][5][5 + 3 * c] = dK;
            Mf[c][6][5 + 3 * c] = 1.0;
        }
        if (el__all_finite(v[c], FIT_NP)) return EL_EDOM;
    }
    if (M) {
        /* the free columns: all 9, or without the two h */
        static const int cols9[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8}, cols7[7] = {0, 1, 2, 4, 5, 7, 8};
        const int *cols = m->nx == 9 ? cols9 : cols7;
        for (int c = 0; c < 2; c++)
            for (int r = 0; r < FIT_NP; r++)
                for (int j = 0; j < m->nx; j++) M[c * FIT_NP * FIT_MAXX + r * m->nx + j] = Mf[c][r][cols[j]];
    }
    return EL_OK;
}

/* ------------------------------------------------------------ the start */

/* One side fitted alone (normalised, internal parameters), and the zero of its
 * curvature nearest its start: arc length (smooth) or vertex position (discrete) `at`,
 * the point and tangent there, and the sign of the curvature just beyond it (away from
 * the split). */
typedef struct side_fit {
    double v[FIT_NP];
    double at, xy[2], theta, after;
    int has_zero;
} side_fit;

static int side_zero(int model, side_fit *sf, size_t nv, double near)
{
    const double *v = sf->v;
    const int ik = model == FIT_DISCRETE ? 6 : 4;
    const double k = v[ik], step = model == FIT_DISCRETE ? v[4] : v[3], q = v[5];
    double K, dK;
    sf->has_zero = 0;
    if (quarter_period(k, &K, &dK) || step == 0.0) return EL_OK;
    /* u(at) = K (2m + 1), the m that brings `at` nearest `near` */
    const double m = nearbyint((q + step * near - K) / (2.0 * K) + 0.0);
    double best = HUGE_VAL, mm = 0.0;
    for (int d = -1; d <= 1; d++) {
        const double a = (K * (2.0 * (m + d) + 1.0) - q) / step;
        if (fabs(a - near) < fabs(best - near)) { best = a; mm = m + d; }
    }
    /* beyond the zero kappa ~ -k (-1)^m w^2 (s - at) (cn(u* + d) = -sn dn d, sn(u*) =
     * (-1)^m); the same for the discrete turning angle a_{j+1} - a_{j-1} = 2 z k cn u_j */
    const double parity = fmod(fabs(mm), 2.0) == 0.0 ? 1.0 : -1.0;
    sf->after = -copysign(1.0, k) * parity;
    sf->at = best;
    if (model == FIT_SMOOTH) {
        el_smooth_params p;
        double th;
        if (el__fit_to_smooth(v, &p) || el_smooth_eval(&p, 1, &best, sf->xy, &th, NULL)) return EL_OK;
        sf->theta = th;
    } else {
        /* the vertex nearest the zero, inside the side, and its segment's direction */
        const double j = fmin(fmax(nearbyint(best), 0.0), (double)nv - 2.0);
        el_discrete_params p;
        if (el__fit_to_discrete(v, &p, NULL)) return EL_OK;
        const size_t m2 = (size_t)j + 2;
        double *xy = malloc(sizeof(double) * 2 * m2);
        if (!xy) return EL_ENOMEM;
        if (el_discrete_eval(&p, m2, xy)) { free(xy); return EL_OK; }
        sf->xy[0] = xy[2 * (m2 - 2)]; sf->xy[1] = xy[2 * (m2 - 2) + 1];
        sf->theta = atan2(xy[2 * m2 - 1] - sf->xy[1], xy[2 * m2 - 2] - sf->xy[0]);
        free(xy);
    }
    sf->has_zero = 1;
    return EL_OK;
}

/* ------------------------------------------------------------ the driver */

/* The two sides' results (the fields of the whole problem in side[0]), the joint. */
typedef struct keyline_out {
    fit_out side[2];
    int status;
    size_t joint;
} keyline_out;

static int keyline_options(const el_fit_options *o, int model)
{
    if (!(o->tol > 0.0) || !isfinite(o->tol) || o->max_iter < 1 || o->max_candidates < 1) return EL_EINVAL;
    if (o->use_initial || o->constraints || o->limited_memory) return EL_EINVAL;
    if (o->param_mode < EL_PARAM_AUTO || o->param_mode > EL_PARAM_CHORD) return EL_EINVAL;
    if (o->distance != EL_DISTANCE_AUTO &&
        o->distance != (model == FIT_SMOOTH ? EL_DISTANCE_ORTHOGONAL : EL_DISTANCE_PAIRED)) return EL_EINVAL;
    for (int j = 0; j < FIT_NP; j++) {
        if (isfinite(o->lower[j]) || isfinite(o->upper[j]) || isnan(o->lower[j]) || isnan(o->upper[j]))
            return EL_EINVAL;
        if (o->fixed[j] && !(model == FIT_DISCRETE && j == 2 && o->value[j] > 0.0 && isfinite(o->value[j])))
            return EL_EINVAL;
    }
    return EL_OK;
}

/* Fit one side alone: the points split, split -/+ 1, ..., in input units. */
static int fit_side(int model, const double *xy, size_t n, size_t split, int dir, const el_fit_options *o,
                    double cx, double cy, double sc, side_fit *sf, double *foot, int *mode, int *iters)
{
    const size_t m = dir < 0 ? split + 1 : n - split;
    double *pts = malloc(sizeof(double) * 2 * m);
    if (!pts) return EL_ENOMEM;
    for (size_t j = 0; j < m; j++) {
        const size_t g = dir < 0 ? split - j : split + j;
        pts[2 * j] = xy[2 * g]; pts[2 * j + 1] = xy[2 * g + 1];
    }
    /* a start for the joint fit: 40 iterations of Levenberg-Marquardt at most, no Ipopt
     * (a side alone is part of a period, its parameters a flat valley that took up to
     * 200 iterations and then Ipopt; measured on 14 generated scans, both models: the
     * same joint fit to 1e-8 in k, 3x faster on the slowest) */
    el_fit_options so = *o;
    so.max_iter = so.max_iter < 40 ? so.max_iter : 40;
    double p[FIT_NP];
    int st = el__fit_start(model, pts, m, &so, p, mode, iters, foot);
    free(pts);
    /* written out, not fit_gave_curve: with it GCC 12 at -O1 -fsanitize=address (make
     * check-asan) takes pts for maybe-uninitialized at the call above */
    if (st != EL_OK && st != EL_ENOCONV && st != EL_EMAXITER) return st;
    for (int j = 0; j < FIT_NP; j++) sf->v[j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
    if (foot)
        for (size_t j = 0; j < m; j++) foot[j] /= sc;
    return side_zero(model, sf, m, 0.0);
}

/* The joint variables from the two side fits. */
static void joint_start(int model, const side_fit sf[2], const fit_map *map, const double *P_split,
                        double *x, double *L)
{
    double jx = 0.0, jy = 0.0, tx = 0.0, ty = 0.0;
    int cnt = 0;
    for (int c = 0; c < 2; c++) {
        if (!sf[c].has_zero) continue;
        jx += sf[c].xy[0]; jy += sf[c].xy[1];
        /* the second curve's direction at J; the first one's is opposite */
        const double th = sf[c].theta + (c == 0 ? M_PI : 0.0);
        tx += cos(th); ty += sin(th);
        cnt++;
    }
    if (cnt == 0) {
        jx = P_split[0]; jy = P_split[1];
        tx = cos(sf[1].v[model == FIT_DISCRETE ? 3 : 2]); ty = sin(sf[1].v[model == FIT_DISCRETE ? 3 : 2]);
        cnt = 1;
    }
    x[0] = jx / cnt; x[1] = jy / cnt; x[2] = atan2(ty, tx);
    for (int c = 0; c < 2; c++) {
        const double *v = sf[c].v;
        const double after = sf[c].has_zero ? sf[c].after : 1.0;
        const int ik = model == FIT_DISCRETE ? 6 : 4;
        const double k = -after * fmin(fabs(v[ik]), 0.95);
        double *y = x + 3 + 3 * c;
        if (model == FIT_SMOOTH) {
            const double Lc = v[6] - (sf[c].has_zero ? sf[c].at : 0.0);
            y[0] = fabs(v[3]); y[1] = smooth_t(k); y[2] = Lc > 0.1 * v[6] ? Lc : v[6];
            L[c] = y[2];
        } else {
            y[0] = v[2] * map->scale[c]; y[1] = fabs(v[4]) * map->scale[c]; y[2] = k;
        }
    }
}

enum { WHOLE_POINTS = 64 };

/* Point j of m taken evenly from n >= m by index (0 -> 0, m-1 -> n-1). */
static size_t whole_index(size_t j, size_t m, size_t n)
{
    return m < 2 ? 0 : (size_t)(((double)j * (double)(n - 1)) / (double)(m - 1) + 0.5);
}

/* The start from one elastica of all the points, split at a zero of its curvature
 * inside (the one nearest `near`: the caller's split, as arc length or vertex): an
 * inflectional elastica is point-symmetric about each inflection, so its two halves
 * there are a keyline with an exact G2 joint and both sides of the same k. The side fits
 * above start from the caller's split alone, and where that split is far from the
 * inflection (one side a few points) or a side alone fits near the separatrix (|k| ~ 1,
 * no zero, clipped to 0.95 with its w: a start of another shape) their joint fit stays
 * far above this one. x: the joint variables (map->nx), *split: the data index of the
 * joint (discrete), feet (smooth, n): each point's signed foot from J; *found = 0 when
 * the one elastica has no zero with 3 points (vertices) beyond it on both sides. */
static int whole_start(int model, const double *xy, size_t n, size_t split, const el_fit_options *o,
                       double cx, double cy, double sc, const fit_map *map, double *x, size_t *js,
                       double *feet, int *found, int *iters)
{
    el_fit_options wo;
    el_fit_options_defaults(&wo);
    wo.tol = o->tol;
    wo.max_iter = o->max_iter;
    double p[FIT_NP];
    int st;
    *found = 0;
    if (model == FIT_SMOOTH) {
        /* at most WHOLE_POINTS of the points, evenly by index (the start's fit of 1000
         * points took 37 ms, 10 x the keyline's own; 128 of them 2 ms), the others' feet
         * interpolated */
        const size_t m = n > WHOLE_POINTS ? WHOLE_POINTS : n;
        double *sub = malloc(sizeof(double) * 3 * m);
        if (!sub) return EL_ENOMEM;
        double *sfeet = sub + 2 * m;
        for (size_t j = 0; j < m; j++) {
            const size_t i = whole_index(j, m, n);
            sub[2 * j] = xy[2 * i]; sub[2 * j + 1] = xy[2 * i + 1];
        }
        int mode;
        wo.distance = EL_DISTANCE_PAIRED;
        wo.param_mode = EL_PARAM_CHORD;
        st = el__fit_start(model, sub, m, &wo, p, &mode, iters, sfeet);
        if (fit_gave_curve(st)) {
            for (size_t j = 0; j + 1 < m; j++) {
                const size_t a = whole_index(j, m, n), b = whole_index(j + 1, m, n);
                for (size_t i = a; i <= b; i++)
                    feet[i] = sfeet[j] + (sfeet[j + 1] - sfeet[j]) * (double)(i - a) / (double)(b - a);
            }
        }
        free(sub);
        if (!fit_gave_curve(st)) return st == EL_ENOMEM ? st : EL_OK;
    } else {
        wo.distance = EL_DISTANCE_PAIRED;
        if (map->fixed_h > 0.0) { wo.fixed[2] = 1; wo.value[2] = o->value[2]; }
        int mode;
        st = el__fit_start(model, xy, n, &wo, p, &mode, iters, NULL);
        if (!fit_gave_curve(st)) return st == EL_ENOMEM ? st : EL_OK;
    }
    side_fit sf;
    for (int j = 0; j < FIT_NP; j++) sf.v[j] = el__fit_norm_param(model, j, p[j], cx, cy, sc);
    if (el__all_finite(sf.v, FIT_NP)) return EL_OK;
    const double near = model == FIT_SMOOTH ? feet[split] / sc : (double)split;
    if ((st = side_zero(model, &sf, n, near)) || !sf.has_zero) return st;
    const int ik = model == FIT_DISCRETE ? 6 : 4;
    const double k = -sf.after * fmin(fabs(sf.v[ik]), 0.999);
    double xf[9];
    xf[0] = sf.xy[0]; xf[1] = sf.xy[1]; xf[2] = sf.theta;
    if (model == FIT_SMOOTH) {
        const double L = sf.v[6], at = sf.at, w = fabs(sf.v[3]);
        size_t before = 0, after = 0;
        for (size_t i = 0; i < n; i++) {
            feet[i] = feet[i] / sc - at;
            if (feet[i] < 0.0) before++; else if (feet[i] > 0.0) after++;
        }
        if (!(at > 0.0 && at < L) || before < 3 || after < 3) return EL_OK;
        feet[0] = -at;
        feet[n - 1] = L - at;
        xf[3] = w; xf[4] = smooth_t(k); xf[5] = at;
        xf[6] = w; xf[7] = smooth_t(k); xf[8] = L - at;
    } else {
        const double j0 = nearbyint(sf.at);
        if (!(j0 >= 3.0 && j0 + 4.0 <= (double)n)) return EL_OK;
        *js = (size_t)j0;
        for (int c = 0; c < 2; c++) {
            xf[3 + 3 * c] = sf.v[2] * map->scale[c];
            xf[4 + 3 * c] = fabs(sf.v[4]) * map->scale[c];
            xf[5 + 3 * c] = k;
        }
    }
    if (map->nx == 9) memcpy(x, xf, sizeof xf);
    else { x[0] = xf[0]; x[1] = xf[1]; x[2] = xf[2]; x[3] = xf[4]; x[4] = xf[5]; x[5] = xf[7]; x[6] = xf[8]; }
    *found = 1;
    return EL_OK;
}

/* Levenberg-Marquardt from x, then (discrete) the split moved while the joint fit
 * improves; *iters += the iterations. */
static int joint_lm(fit_objective *ob, const double *x, int max_iter, size_t n, fit_solution *sol, int *iters)
{
    int st = el__fit_lm(ob, x, max_iter, sol);
    if (st) return st;
    *iters += sol->iters;
    if (ob->map.model != FIT_DISCRETE) return EL_OK;
    for (int dir = -1; dir <= 1; dir += 2) {
        for (;;) {
            const size_t trial = ob->split + (size_t)dir;   /* wraps for dir = -1 at 0: caught below */
            if (dir < 0 ? ob->split <= 3 : ob->split + 5 > n) break;
            const size_t keep = ob->split;
            ob->split = trial;
            fit_solution s2;
            if (el__fit_lm(ob, sol->x, max_iter, &s2) != EL_OK || !(s2.val.f < sol->val.f)) {
                ob->split = keep;
                break;
            }
            *iters += s2.iters;
            *sol = s2;
        }
    }
    return EL_OK;
}

static int keyline_run(int model, const double *xy, size_t n, size_t split, const el_fit_options *opt,
                       keyline_out *out, double *dist, double *foot, int *side)
{
    el_fit_options o;
    if (opt) o = *opt; else el_fit_options_defaults(&o);
    if (!xy || n < 7 || split < 3 || split + 4 > n || el__all_finite(xy, 2 * n)) return EL_EINVAL;
    int st = keyline_options(&o, model);
    if (st) return st;
    el__gsl_quiet();
    double cx, cy, sc;
    if ((st = el__fit_normalisation(xy, n, &cx, &cy, &sc))) return st;
    const double fixed_h = model == FIT_DISCRETE && o.fixed[2] ? o.value[2] / sc : 0.0;

    double *feetA = NULL, *feetB = NULL, *feetW = NULL, *tmp = NULL;
    fit_objective ob;
    memset(&ob, 0, sizeof ob);
    st = EL_ENOMEM;
    if (!(tmp = malloc(sizeof(double) * FIT_WORK))) goto done;
    if (model == FIT_SMOOTH &&
        (!(feetA = malloc(sizeof(double) * (split + 1))) || !(feetB = malloc(sizeof(double) * (n - split)))))
        goto done;
    side_fit sf[2];
    int iters = 0, mode = EL_PARAM_UNIFORM;
    if ((st = fit_side(model, xy, n, split, -1, &o, cx, cy, sc, &sf[0], feetA, &mode, &iters)) ||
        (st = fit_side(model, xy, n, split, 1, &o, cx, cy, sc, &sf[1], feetB, &mode, &iters)))
        goto done;

    /* the discrete split: the mean of the two sides' zeros, as a data index */
    size_t i0 = split;
    if (model == FIT_DISCRETE) {
        double e = 0.0;
        int cnt = 0;
        if (sf[0].has_zero) { e += (double)split - sf[0].at; cnt++; }
        if (sf[1].has_zero) { e += (double)split + sf[1].at; cnt++; }
        if (cnt) i0 = (size_t)fmin(fmax(nearbyint(e / cnt), 3.0), (double)(n - 4));
    }
    fit_map map;
    memset(&map, 0, sizeof map);
    map.model = model; map.ncurves = 2;
    map.nx = fixed_h > 0.0 ? 7 : 9;
    map.fixed_h = fixed_h;
    map.scale[0] = model == FIT_DISCRETE ? (double)i0 : 1.0;
    map.scale[1] = model == FIT_DISCRETE ? (double)(n - 1 - i0) : 1.0;
    if ((st = el__fit_objective_init(&ob, FIT_KEYLINE, &map, xy, n, cx, cy, sc, NULL))) goto done;
    ob.split = i0;

    double xf[9], x[FIT_MAXX], L[2] = {0.0, 0.0}, P_split[2];
    P_split[0] = (xy[2 * split] - cx) / sc; P_split[1] = (xy[2 * split + 1] - cy) / sc;
    joint_start(model, sf, &map, P_split, xf, L);
    if (map.nx == 9) memcpy(x, xf, sizeof xf);
    else { x[0] = xf[0]; x[1] = xf[1]; x[2] = xf[2]; x[3] = xf[4]; x[4] = xf[5]; x[5] = xf[7]; x[6] = xf[8]; }
    double v0[2][FIT_NP];
    if ((st = el__fit_map_eval(&map, x, v0, NULL))) goto done;
    if (model == FIT_SMOOTH) {   /* the first feet: each side fit's, from its zero */
        for (size_t j = 0; j <= split; j++) ob.s[split - j] = -(feetA[j] - (sf[0].has_zero ? sf[0].at : 0.0));
        for (size_t j = 1; j < n - split; j++) ob.s[split + j] = feetB[j] - (sf[1].has_zero ? sf[1].at : 0.0);
        ob.s[0] = -L[0];
        ob.s[n - 1] = L[1];
    }

    fit_solution sol;
    if ((st = joint_lm(&ob, x, o.max_iter, n, &sol, &iters))) goto done;
    {
        /* the second start: one elastica of all the points split at its inflection; the
         * better of the two joint fits is kept */
        double xw[FIT_MAXX];
        size_t jw = ob.split;
        int found = 0;
        if (!(feetW = malloc(sizeof(double) * 2 * n))) { st = EL_ENOMEM; goto done; }
        if ((st = whole_start(model, xy, n, split, &o, cx, cy, sc, &map, xw, &jw, feetW, &found, &iters)))
            goto done;
        if (found) {
            const size_t keep_split = ob.split;
            double *keep_s = feetW + n;
            if (model == FIT_SMOOTH) { memcpy(keep_s, ob.s, sizeof(double) * n); memcpy(ob.s, feetW, sizeof(double) * n); }
            ob.split = jw;
            ob.have_base = 0; ob.rest_ok = 0;
            ob.f_ceiling = sol.val.f;
            fit_solution sw;
            const int stw = joint_lm(&ob, xw, o.max_iter, n, &sw, &iters);
            ob.f_ceiling = HUGE_VAL;
            if (stw == EL_ENOMEM) { st = stw; goto done; }
            if (stw == EL_OK && sw.val.f < sol.val.f) {
                sol = sw;
                el__fit_map_eval(&map, xw, v0, NULL);
            } else {
                if (model == FIT_SMOOTH) memcpy(ob.s, keep_s, sizeof(double) * n);
                ob.split = keep_split;
                ob.have_base = 0; ob.rest_ok = 0;
            }
        }
    }
    if (model == FIT_SMOOTH && (st = el__fit_keyline_ends(&ob, o.max_iter, &sol, &iters))) goto done;
    int certified = sol.certified, used_ipopt = 0, ipopt_status = 0;
    if (!certified) {
        fit_ipopt_out io;
        double xl[FIT_MAXX], xu[FIT_MAXX], xi[FIT_MAXX];
        for (int j = 0; j < FIT_MAXX; j++) { xl[j] = -HUGE_VAL; xu[j] = HUGE_VAL; }
        memcpy(xi, sol.x, sizeof xi);
        if (el__fit_ipopt(&ob, xl, xu, NULL, &o, xi, &io, tmp) == EL_OK) {
            used_ipopt = 1;
            ipopt_status = io.ipopt_status;
            iters += io.iters;
            if (io.f <= sol.val.f) memcpy(sol.x, xi, sizeof xi);
            certified = io.ipopt_status == 0 || io.ipopt_status == 1;
        }
    }
    out->status = certified ? EL_OK : sol.iters >= o.max_iter ? EL_EMAXITER : EL_ENOCONV;

    /* results: distances (+ = left of the keyline from point 0 to point n-1), sides */
    double v[2][FIT_NP];
    if ((st = el__fit_map_eval(&map, sol.x, v, NULL))) goto done;
    double *d = dist, *fs = foot, *buf = NULL;
    int *sd = side, *ibuf = NULL;
    if (!d || !fs || !sd) {
        buf = malloc(sizeof(double) * 2 * n);
        ibuf = malloc(sizeof(int) * n);
        if (!buf || !ibuf) { free(buf); free(ibuf); st = EL_ENOMEM; goto done; }
        if (!d) d = buf;
        if (!fs) fs = buf + n;
        if (!sd) sd = ibuf;
    }
    const size_t js = ob.split;
    const size_t nv[2] = {js + 1, n - js};
    double *V[2] = {NULL, NULL};
    if (model == FIT_SMOOTH) {
        st = el__fit_feet_distances(&ob, sol.x, d, fs, sd);
    } else {
        for (int c = 0; c < 2 && !st; c++) {
            if (!(V[c] = malloc(sizeof(double) * 2 * nv[c]))) { st = EL_ENOMEM; break; }
            fit_walk w;
            el__fit_walk_start(v[c], &w);
            for (size_t a = 0; a < nv[c] && !st; a += FIT_BLOCK) {
                const size_t m = nv[c] - a < FIT_BLOCK ? nv[c] - a : FIT_BLOCK;
                st = el__fit_discrete_rows(v[c], &w, m, V[c] + 2 * a, NULL, 0, tmp);
            }
        }
        if (!st) {
            el__fit_polygon_distances(&ob, V[0], nv[0], v[0][2], js, -1, d, fs);
            for (size_t i = 0; i <= js; i++) sd[i] = 0;
            /* the joint's point: its distance to the nearer side */
            const double d0 = d[js], f0 = fs[js];
            el__fit_polygon_distances(&ob, V[1], nv[1], v[1][2], js, 1, d, fs);
            for (size_t i = js; i < n; i++) sd[i] = 1;
            if (fabs(d0) <= fabs(d[js])) { d[js] = d0; fs[js] = f0; sd[js] = 0; }
        }
    }
    if (!st) {
        const double *Vc[2] = {V[0], V[1]};
        st = el__fit_nearest_everywhere(&ob, v, Vc, nv, d, fs, sd);
    }
    free(V[0]);
    free(V[1]);
    /* signs: + left of the keyline run from point 0 to point n-1 (the first curve runs
     * the other way) */
    for (size_t i = 0; i < n && !st; i++)
        if (sd[i] == 0) d[i] = -d[i];
    if (!st) {
        double s2[2] = {0.0, 0.0}, mx[2] = {0.0, 0.0};
        size_t cnt[2] = {0, 0};
        for (size_t i = 0; i < n; i++) {
            const int c = sd[i];
            s2[c] += d[i] * d[i];
            mx[c] = fmax(mx[c], fabs(d[i]));
            cnt[c]++;
            if (model == FIT_DISCRETE && i == js) {     /* the joint belongs to both sides */
                s2[1] += d[i] * d[i]; mx[1] = fmax(mx[1], fabs(d[i])); cnt[1]++;
            }
            d[i] *= sc;
            fs[i] *= sc;
        }
        for (int c = 0; c < 2; c++) {
            fit_out *so = &out->side[c];
            so->rms = cnt[c] ? sc * sqrt(s2[c] / (double)cnt[c]) : 0.0;
            so->max_error = sc * mx[c];
            double vc[FIT_NP], vi[FIT_NP];
            memcpy(vc, v[c], sizeof vc);
            memcpy(vi, v0[c], sizeof vi);
            el__fit_canonical(model, vc, 1);
            el__fit_canonical(model, vi, 1);
            for (int j = 0; j < FIT_NP; j++) {
                so->params[j] = el__fit_denorm_param(model, j, vc[j], cx, cy, sc);
                so->initial[j] = el__fit_denorm_param(model, j, vi[j], cx, cy, sc);
            }
            if (model == FIT_DISCRETE && fixed_h > 0.0) so->params[2] = o.value[2];
            int valid = !el__all_finite(so->params, FIT_NP) && !el__all_finite(so->initial, FIT_NP);
            valid = valid && so->params[model == FIT_DISCRETE ? 2 : 3] >= DBL_MIN;
            /* its distances in the input's units, as fit.c's */
            valid = valid && isfinite(so->rms) && isfinite(so->max_error);
            if (!valid) out->status = EL_EDOM;
        }
        if (el__all_finite(d, n) || el__all_finite(fs, n)) out->status = EL_EDOM;
    }
    free(buf);
    free(ibuf);
    if (st) goto done;
    for (int c = 0; c < 2; c++) {
        fit_out *so = &out->side[c];
        so->iterations = iters; so->candidates = 1;
        so->ipopt_status = ipopt_status; so->used_ipopt = used_ipopt;
        so->mode = mode; so->status = out->status; so->constraint = 0;
        so->distance = model == FIT_SMOOTH ? EL_DISTANCE_ORTHOGONAL : EL_DISTANCE_PAIRED;
    }
    out->joint = js;
    st = out->status;
done:
    el__fit_objective_free(&ob);
    free(feetA);
    free(feetB);
    free(feetW);
    free(tmp);
    return st;
}

/* EL_EDOM for a keyline fit that did not converge (status) on points whose polygon shows
 * no inflection (el_find_inflection: a convex arc), as the header says: an arc's keyline
 * returned EL_ENOCONV, which asks the caller for more iterations (QA20 F8); else status.
 * Only the unconverged are looked at: a converged fit stands, and noisy points, whose
 * polygon zigzags, show inflections and keep their status. */
static int no_inflection(const double *xy, size_t n, int status)
{
    if (status != EL_ENOCONV && status != EL_EMAXITER) return status;
    el_inflection inf;
    return el_find_inflection(xy, n, 0, &inf) == EL_EDOM ? EL_EDOM : status;
}

int el_fit_keyline_smooth(const double *xy, size_t n, size_t split, const el_fit_options *opt,
                          el_fit_smooth_result *first, el_fit_smooth_result *second,
                          double *distances, double *foot_s, int *side)
{
    if (!first || !second) return EL_EINVAL;
    keyline_out k;
    memset(&k, 0, sizeof k);
    k.status = -1;
    int st = keyline_run(FIT_SMOOTH, xy, n, split, opt, &k, distances, foot_s, side);
    if (k.status == -1 || (st != k.status)) return st;
    if ((st = no_inflection(xy, n, st)) == EL_EDOM) return st;
    FIT_PUBLISH(first, k.side[0], el_smooth_params);
    FIT_PUBLISH(second, k.side[1], el_smooth_params);
    first->wander_gap = second->wander_gap = -1;
    first->param_mode = second->param_mode = k.side[0].mode;
    return k.status;
}

int el_fit_keyline_discrete(const double *xy, size_t n, size_t split, const el_fit_options *opt,
                            el_fit_discrete_result *first, el_fit_discrete_result *second,
                            size_t *joint, double *distances, double *foot_s, int *side)
{
    if (!first || !second) return EL_EINVAL;
    keyline_out k;
    memset(&k, 0, sizeof k);
    k.status = -1;
    int st = keyline_run(FIT_DISCRETE, xy, n, split, opt, &k, distances, foot_s, side);
    if (k.status == -1 || (st != k.status)) return st;
    if ((st = no_inflection(xy, n, st)) == EL_EDOM) return st;
    FIT_PUBLISH(first, k.side[0], el_discrete_params);
    FIT_PUBLISH(second, k.side[1], el_discrete_params);
    first->wander_gap = second->wander_gap = -1;
    if (joint) *joint = k.joint;
    return k.status;
}
