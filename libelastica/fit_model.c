/*
 * The fit's view of the two models (fit_internal.h): internal parameter vectors,
 * the map from the optimiser's variables to them, model points and Jacobians block
 * by block, and the states at a curve's ends (for constraints and the keyline joint).
 */
#include "fit_internal.h"
#include <string.h>
#include <gsl/gsl_sf_ellint.h>

/* 2K(k) and its derivative for 0 <= k < 1. */
static int twoK(double k, double *K2, double *dK2)
{
    if (!(k >= 0.0 && k < 1.0)) return EL_EDOM;
    gsl_sf_result K, E;
    if (gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &K) || gsl_sf_ellint_Ecomp_e(k, GSL_PREC_DOUBLE, &E))
        return EL_EDOM;
    *K2 = 2.0 * K.val;
    /* dK/dk = (E - (1 - k^2) K) / (k (1 - k^2)) = pi k / 4 + O(k^3) */
    *dK2 = 2.0 * (k < 1e-4 ? M_PI * k / 4.0 : (E.val - (1.0 - k * k) * K.val) / (k * (1.0 - k * k)));
    return EL_OK;
}

/* Discrete: -1 < k < 0 is |k| with q + 2K(|k|); *dq_dk (may be NULL) receives
 * d(2K(|k|))/d|k| when that shift applies, else 0. */
int el__fit_to_discrete(const double *v, el_discrete_params *p, double *dq_dk)
{
    double K2 = 0.0, dK2 = 0.0;
    p->x0 = v[0]; p->y0 = v[1]; p->h = v[2]; p->phi = v[3]; p->z = v[4]; p->q = v[5]; p->k = v[6];
    if (v[6] < 0.0) {
        int st = twoK(-v[6], &K2, &dK2);
        if (st) return st;
        p->k = -v[6];
        p->q += K2;
    }
    if (dq_dk) *dq_dk = dK2;
    return el_discrete_check(p) ? EL_EDOM : EL_OK;
}

/* Smooth: w < 0 is (|w|, -k, -q); mu = w^2. */
int el__fit_to_smooth(const double *v, el_smooth_params *p)
{
    const double s = v[3] < 0.0 ? -1.0 : 1.0;
    p->x0 = v[0]; p->y0 = v[1]; p->phi = v[2]; p->mu = v[3] * v[3];
    p->k = s * v[4]; p->q = s * v[5]; p->length = v[6];
    return el_smooth_check(p) ? EL_EDOM : EL_OK;
}

/*
 * The parameters handed out: smooth w < 0 flipped; then, when allowed (may_shift),
 * -1 < k < 0 as the same curve with |k| and q + 2K(|k|), so inflectional results
 * have k >= 0; the discrete model always shifts (its k is >= 0). |k| > 1 keeps its sign.
 */
int el__fit_canonical(int model, double *v, int may_shift)
{
    const int ik = model == FIT_DISCRETE ? 6 : 4;
    double K2, dK2;
    if (model == FIT_SMOOTH && v[3] < 0.0) { v[3] = -v[3]; v[4] = -v[4]; v[5] = -v[5]; }
    if (v[ik] < 0.0 && v[ik] > -1.0 && (may_shift || model == FIT_DISCRETE)) {
        if (twoK(-v[ik], &K2, &dK2)) return EL_EDOM;
        v[ik] = -v[ik];
        v[5] += K2;
    }
    return model == FIT_DISCRETE && v[ik] < 0.0 ? EL_EDOM : EL_OK;
}

int el__fit_smooth_rows(const double *v, size_t m, const double *s, double *xy, double *jac)
{
    el_smooth_params p;
    int st = el__fit_to_smooth(v, &p);
    if (st) return st;
    if (!jac) return el_smooth_eval(&p, m, s, xy, NULL, NULL);
    if ((st = el_smooth_jacobian(&p, m, s, xy, jac))) return st;
    const double w = fabs(v[3]), sg = v[3] < 0.0 ? -1.0 : 1.0;
    for (size_t i = 0; i < 2 * m; i++) {
        double *r = jac + i * FIT_NP;
        r[3] *= 2.0 * w * sg;              /* d/dw = 2 w d/dmu, then (w, k, q) -> -(...) */
        r[4] *= sg;
        r[5] *= sg;
    }
    return EL_OK;
}

void el__fit_walk_start(const double *v, fit_walk *w)
{
    memset(w, 0, sizeof *w);
    w->xy[0] = v[0]; w->xy[1] = v[1];
    w->d[0][0] = 1.0; w->d[1][1] = 1.0;
}

/*
 * Vertices w->next .. w->next + m - 1. The block is the discrete elastica that starts
 * at vertex a = w->next with u_0 = q + a z: gamma_{a+j}(p) = gamma_a(p) + S_j(h, phi, z,
 * q + a z, k), so d gamma_{a+j} = d gamma_a + dS_j with the z column of S gaining a
 * times its q column. One vertex more is evaluated: the next block's start.
 */
int el__fit_discrete_rows(const double *v, fit_walk *w, size_t m, double *xy, double *jac, size_t cstride,
                          double *tmp)
{
    el_discrete_params p;
    double dq_dk;
    int st = el__fit_to_discrete(v, &p, &dq_dk);
    if (st) return st;
    const double a = (double)w->next;
    p.x0 = w->xy[0]; p.y0 = w->xy[1];
    p.q += a * p.z;
    double *txy = tmp, *tj = tmp + 2 * (m + 1);
    if (!jac) {
        if ((st = el_discrete_eval(&p, m + 1, txy))) return st;
        memcpy(xy, txy, sizeof(double) * 2 * m);
    } else {
        if ((st = el_discrete_jacobian(&p, m + 1, txy, tj))) return st;
        /* the block's rows moved to the whole curve's, written straight to jac (vertex m,
         * the next block's start, to w->d after the others have used the old w->d) */
        double next[2][FIT_NP];
        const int negative = v[6] < 0.0;
        for (size_t i = 0; i <= m; i++) {
            for (int c = 0; c < 2; c++) {
                const double *r = tj + (2 * i + c) * FIT_NP, *d = w->d[c];
                const double d2 = r[2] + d[2], d3 = r[3] + d[3];
                const double d4 = (r[4] + a * r[5]) + d[4];      /* u_0 = q + a z: dz gains a dq */
                const double d5 = r[5] + d[5], d6 = r[6] + d[6];
                /* d/dk of (|k|, q + 2K(|k|)) as a function of k < 0 (not for the next block's
                 * start, whose derivative the walk carries) */
                const double dk = i < m && negative ? -(d6 + dq_dk * d5) : d6;
                if (i < m && cstride) {
                    double *out = jac + 2 * i + c;
                    out[2 * cstride] = d2; out[3 * cstride] = d3; out[4 * cstride] = d4;
                    out[5 * cstride] = d5; out[6 * cstride] = dk;
                } else {
                    double *out = i < m ? jac + (2 * i + c) * FIT_NP : next[c];
                    out[0] = r[0]; out[1] = r[1];
                    out[2] = d2; out[3] = d3; out[4] = d4; out[5] = d5; out[6] = dk;
                }
            }
        }
        if (xy) memcpy(xy, txy, sizeof(double) * 2 * m);
        memcpy(w->d, next, sizeof w->d);
    }
    w->xy[0] = txy[2 * m]; w->xy[1] = txy[2 * m + 1];
    w->next += m;
    return EL_OK;
}

/* ------------------------------------------------------------ end states */

/* a = atan2(k sn u, dn u) (signed k, Jacobi functions at |k|) with da/du = k cn and
 * da/dk = dn sn + |k| (dn sn_k - sn dn_k) (dn^2 + k^2 sn^2 = 1); cn and its
 * derivatives for the curvature. */
typedef struct half_angle {
    double a, a_u, a_k, cn, cn_u, cn_k;
} half_angle;

static int half_angle_at(double u, double k, half_angle *h)
{
    el_jacobi J, Ju, Jk;
    const double ka = fabs(k);
    int st = el_jacobi_eval(u, ka, &J, &Ju, &Jk);
    if (st) return st == EL_EINVAL ? EL_EDOM : st;
    h->a = atan2(k * J.sn, J.dn);
    h->a_u = k * J.cn;
    h->a_k = J.dn * J.sn + ka * (J.dn * Jk.sn - J.sn * Jk.dn);
    h->cn = J.cn;
    h->cn_u = Ju.cn;
    h->cn_k = copysign(1.0, k) * Jk.cn;     /* d cn(u; |k|) / dk */
    return EL_OK;
}

static int smooth_end(const double *v, int at_end, fit_end *e)
{
    const double s = at_end ? v[6] : 0.0, w = v[3], k = v[4];
    double jac[2 * FIT_NP];
    int st = el__fit_smooth_rows(v, 1, &s, e->xy, jac);
    if (st) return st;
    memcpy(e->dxy, jac, sizeof e->dxy);
    half_angle h;
    if ((st = half_angle_at(w * s + v[5], k, &h))) return st;
    /* theta = phi + 2a, kappa = 2 k w cn, u = w s + q (s = L moves with L) */
    e->theta = v[2] + 2.0 * h.a;
    e->kappa = 2.0 * k * w * h.cn;
    memset(e->dtheta, 0, sizeof e->dtheta);
    memset(e->dkappa, 0, sizeof e->dkappa);
    e->dtheta[2] = 1.0;
    e->dtheta[3] = 2.0 * h.a_u * s;
    e->dtheta[4] = 2.0 * h.a_k;
    e->dtheta[5] = 2.0 * h.a_u;
    e->dtheta[6] = at_end ? 2.0 * h.a_u * w : 0.0;
    e->dkappa[3] = 2.0 * k * h.cn + 2.0 * k * w * h.cn_u * s;
    e->dkappa[4] = 2.0 * w * (h.cn + k * h.cn_k);
    e->dkappa[5] = 2.0 * k * w * h.cn_u;
    e->dkappa[6] = at_end ? 2.0 * k * w * h.cn_u * w : 0.0;
    return EL_OK;
}

/* Discrete, vertex j0 = 0 (at_end 0) or n-1: the vertex's tangent angle theta_j0 = phi +
 * 2 a_j0 (seed 000 (4.4): the segment between vertices j and j+1 runs at the mean of
 * theta_j and theta_j+1; theta_j0 is the smooth elastica's tangent at u_j0 = z j0 + q,
 * the start-state chart's theta0 at j0 = 0), and the extended curvature
 * kappa = (2/h) tan((a_{j0+1} - a_{j0-1})/2) (seed 000 (3.4) at the end vertex). */
static int discrete_end(const double *v, size_t n, int at_end, fit_end *e, double *tmp)
{
    const double h = v[2], z = v[4], q = v[5], k = v[6];
    const double j0 = at_end ? (double)(n - 1) : 0.0;
    const double js[3] = {j0 - 1.0, j0, j0 + 1.0};
    half_angle ha[3];
    int st;
    for (int i = 0; i < 3; i++)
        if ((st = half_angle_at(z * js[i] + q, k, &ha[i]))) return st;
    memset(e, 0, sizeof *e);
    if (!at_end) {
        e->xy[0] = v[0]; e->xy[1] = v[1];
        e->dxy[0][0] = 1.0; e->dxy[1][1] = 1.0;
    } else {
        fit_walk w;
        el__fit_walk_start(v, &w);
        double *xy = tmp, *jac = xy + 2 * FIT_BLOCK, *t2 = jac + 2 * FIT_BLOCK * FIT_NP;
        size_t left = n;
        while (left > 0) {
            const size_t m = left < FIT_BLOCK ? left : FIT_BLOCK;
            if ((st = el__fit_discrete_rows(v, &w, m, xy, jac, 0, t2))) return st;
            left -= m;
            if (left == 0) {
                memcpy(e->xy, xy + 2 * (m - 1), sizeof e->xy);
                memcpy(e->dxy, jac + 2 * (m - 1) * FIT_NP, sizeof e->dxy);
            }
        }
    }
    e->theta = v[3] + 2.0 * ha[1].a;
    e->dtheta[3] = 1.0;
    e->dtheta[4] = 2.0 * ha[1].a_u * js[1];
    e->dtheta[5] = 2.0 * ha[1].a_u;
    e->dtheta[6] = 2.0 * ha[1].a_k;
    const double D = ha[2].a - ha[0].a, tn = tan(0.5 * D);
    e->kappa = 2.0 / h * tn;
    const double dD = (1.0 + tn * tn) / h;          /* d kappa / d D */
    e->dkappa[2] = -e->kappa / h;
    e->dkappa[4] = dD * (ha[2].a_u * js[2] - ha[0].a_u * js[0]);
    e->dkappa[5] = dD * (ha[2].a_u - ha[0].a_u);
    e->dkappa[6] = dD * (ha[2].a_k - ha[0].a_k);
    return EL_OK;
}

int el__fit_end_state(int model, const double *v, size_t n, int at_end, fit_end *e, double *tmp)
{
    return model == FIT_SMOOTH ? smooth_end(v, at_end, e) : discrete_end(v, n, at_end, e, tmp);
}

/* ------------------------------------------------------------ the map x -> v */

/*
 * The start-state chart (one curve; phi, k, q and w (smooth) or z (discrete) free and
 * unbounded). The optimiser sees, instead of (phi, w, k, q), the curve's state at its
 * start and the force on it:
 *   theta0 = phi + 2 a(q)      the tangent angle at s = 0 (a = atan2(k sn q, dn q));
 *   kappa0 = 2 k W cn q        the curvature there;
 *   F = W^2 (cos phi, sin phi) the force: theta'' = F_y cos theta - F_x sin theta,
 * with W = w (smooth) or W = (n-1) z (discrete, per unit of the index range; kappa0 and
 * F are then per that unit too). The curve is the solution of that pendulum equation
 * from (theta0, kappa0), analytic in these variables everywhere, while (phi, w, k, q)
 * are singular at the circle (k -> oo, F = 0), the straight line (k = 0, q
 * undetermined) and along valleys where phi, q and k trade off (measured on
 * near-circular arcs, gently curved arcs and sketched S curves: scipy's MINPACK
 * Levenberg-Marquardt took 40-2600 evaluations in (phi, w, k, q) and 11-58 in this
 * chart; this library's took 30-400 iterations with the earlier shape variables).
 * The inverse, x -> v: phi = arg F, |W| = sqrt|F| with the sign of kappa0,
 * Delta = theta0 - phi reduced to [-pi, pi], S = sin(Delta/2), C = |kappa0| / (2 |W|),
 *   k = hypot(S, C) > 0,   q = (S / k) R_F((C/k)^2, cos^2(Delta/2), 1)
 * (k < 1: sn q = S/k, cn q = C/k >= 0, q = F(asin(S/k) | k); k > 1: am(k q | 1/k) =
 * Delta/2 (sn(u, k) = sn(k u, 1/k)/k, cn(u, k) = dn(k u, 1/k) > 0), q = F(Delta/2 | 1/k)/k;
 * Carlson's F(psi | m) = sin psi R_F(cos^2 psi, 1 - m^2 sin^2 psi, 1) makes both the one
 * symmetric formula, continuous through k = 1). kappa0 < 0 is W < 0 with k > 0 (the
 * smooth w < 0 is (|w|, -k, -q), the discrete z < 0 runs u backwards). d v / d x is the
 * inverse of d x / d v (half_angle_at), solved as the 2 x 2 system of (k, q) after phi
 * and W; it is singular only at k = 0 (the straight line, where q has no meaning).
 */
typedef struct chart_slots { int phi, w, k, q; } chart_slots;

static chart_slots chart_of(int model)
{
    chart_slots c = {model == FIT_DISCRETE ? 3 : 2, model == FIT_DISCRETE ? 4 : 3,
                     model == FIT_DISCRETE ? 6 : 4, 5};
    return c;
}

/* The position in x of parameter slot j (free), -1 if held. */
static int x_pos(const fit_map *m, int j)
{
    for (int a = 0; a < m->nx; a++)
        if (m->idx[a] == j) return a;
    return -1;
}

/* (theta0, kappa0, Fx, Fy) of the parameters v (W = v[w] scale[w]). */
static int chart_from_v(const fit_map *m, const double *v, double *c)
{
    const chart_slots sl = chart_of(m->model);
    half_angle h;
    int st = half_angle_at(v[sl.q], v[sl.k], &h);
    if (st) return st;
    const double W = v[sl.w] * m->scale[sl.w], mu = W * W;
    c[0] = v[sl.phi] + 2.0 * h.a;
    c[1] = 2.0 * v[sl.k] * W * h.cn;
    c[2] = mu * cos(v[sl.phi]);
    c[3] = mu * sin(v[sl.phi]);
    return EL_OK;
}

/* v's (phi, w, k, q) from the chart c and, when D != NULL, d (phi, w, k, q) / d c
 * (D[r][col], r in the slot order phi, w, k, q; w unscaled). */
static int chart_to_v(const fit_map *m, const double *c, double *v, double D[4][4])
{
    const chart_slots sl = chart_of(m->model);
    const double Fx = c[2], Fy = c[3], mu = hypot(Fx, Fy);
    if (!(mu > 0.0) || !isfinite(mu) || !isfinite(c[0]) || !isfinite(c[1])) return EL_EDOM;
    const double phi = atan2(Fy, Fx), sw = sqrt(mu), W = c[1] < 0.0 ? -sw : sw;
    const double delta = remainder(c[0] - phi, 2.0 * M_PI), S = sin(0.5 * delta), cc = cos(0.5 * delta);
    const double C = fabs(c[1]) / (2.0 * sw), k = hypot(S, C);
    double q = 0.0;
    if (k > 0.0) {
        const double ck = C / k;
        double rf, rd;
        if (el__carlson_fd(ck * ck, cc * cc, 1.0, 1.0, &rf, &rd)) return EL_EDOM;
        q = S / k * rf;
    }
    if (!isfinite(q) || !isfinite(k)) return EL_EDOM;
    v[sl.phi] = phi;
    v[sl.w] = W / m->scale[sl.w];
    v[sl.k] = k;
    v[sl.q] = q;
    if (!D) return EL_OK;
    /* x = (theta0, kappa0, Fx, Fy) as functions of (phi, W, k, q), inverted */
    half_angle h;
    int st = half_angle_at(q, k, &h);
    if (st) return st;
    const double m2 = mu * mu;
    const double dphi[4] = {0.0, 0.0, -Fy / m2, Fx / m2};
    const double dW[4] = {0.0, 0.0, W * Fx / (2.0 * m2), W * Fy / (2.0 * m2)};
    /* theta0 = phi + 2 a(q, k), kappa0 = 2 k W cn(q, k): the (k, q) block */
    const double a11 = 2.0 * h.a_k, a12 = 2.0 * h.a_u;
    const double a21 = 2.0 * W * (h.cn + k * h.cn_k), a22 = 2.0 * k * W * h.cn_u;
    const double det = a11 * a22 - a12 * a21;
    if (!(fabs(det) > 0.0) || !isfinite(det)) return EL_EDOM;
    for (int col = 0; col < 4; col++) {
        const double r1 = (col == 0) - dphi[col], r2 = (col == 1) - 2.0 * k * h.cn * dW[col];
        D[0][col] = dphi[col];
        D[1][col] = dW[col] / m->scale[sl.w];
        D[2][col] = (a22 * r1 - a12 * r2) / det;
        D[3][col] = (a11 * r2 - a21 * r1) / det;
    }
    return EL_OK;
}

/*
 * The ends chart (both end points held, fit.c): x = (a, Gx, Gy) is the start state of
 * the curve's shape at unit length, the curve of the start-state chart with theta0 = 0,
 * kappa0 = a, F = (Gx, Gy) and length 1 (smooth L = 1; discrete h = 1, whose chart is per
 * unit of the index range already). With e its end point relative to its start, that curve
 * is turned by alpha = arg D - arg e and scaled by lambda = |D| / |e| about the held start
 * point (D = chord: end - start): smooth phi += alpha, w /= lambda, L = lambda; discrete
 * phi += alpha, h = lambda. Its end lands on the held end to rounding, with no constraint
 * row (Ipopt crept along the two end-point rows for up to 5000 iterations: fit.c). The
 * similarity leaves (a, G) three free shape variables, the analytic start-state chart's
 * (theta0, kappa0, F, L) less the four a turn and a scale about the start take; singular
 * only where e = 0 (a closed curve). The inverse: a = kappa0 L, G = F L^2 turned by
 * -theta0 (discrete: L = 1), the same shape whatever its ends. A zero start curvature is
 * a = 0 at every scale: held in fixed[] (el__fit_ends_held), x = (Gx, Gy); x holds the free
 * ones of (a, Gx, Gy) in this order.
 */
enum { ENDS_BLOCK = 64 };   /* vertices per block of the discrete end's walk */

/* e: the end point of u relative to its start (smooth at s = L, discrete vertex n - 1 of
 * n = scale[2] + 1); de (may be NULL): d e / d u (k >= 0: the chart's). */
static int end_offset(const fit_map *m, const double *u, double e[2], double de[2][FIT_NP])
{
    if (m->model == FIT_SMOOTH) {
        double xy[2], jac[2 * FIT_NP];
        const int st = el__fit_smooth_rows(u, 1, &u[6], xy, de ? jac : NULL);
        if (st) return st;
        if (de) memcpy(de, jac, sizeof jac);
        e[0] = xy[0] - u[0];
        e[1] = xy[1] - u[1];
        return EL_OK;
    }
    /* the walk over vertices 0 .. n-2 carries vertex n-1 (and, with the blocks' Jacobian
     * rows, its derivative; without de the points alone) */
    double xy[2 * ENDS_BLOCK], jac[2 * ENDS_BLOCK * FIT_NP], t2[2 * (ENDS_BLOCK + 1) * (FIT_NP + 1)];
    fit_walk w;
    el__fit_walk_start(u, &w);
    for (size_t left = (size_t)m->scale[2]; left > 0;) {
        const size_t b = left < ENDS_BLOCK ? left : ENDS_BLOCK;
        const int st = el__fit_discrete_rows(u, &w, b, xy, de ? jac : NULL, 0, t2);
        if (st) return st;
        left -= b;
    }
    e[0] = w.xy[0] - u[0];
    e[1] = w.xy[1] - u[1];
    if (de) memcpy(de, w.d, sizeof w.d);
    return EL_OK;
}

static int ends_to_v(const fit_map *m, const double *x, double *v, double *M)
{
    const chart_slots sl = chart_of(m->model);
    const int jl = fit_length_slot(m->model);
    const int slot[4] = {sl.phi, sl.w, sl.k, sl.q};
    /* c: the chart (theta0 = 0, a, Gx, Gy), x its free coordinates in this order; a held
     * (a zero start curvature) is in fixed[] */
    double c[4] = {0.0, 0.0, 0.0, 0.0};
    int col[FIT_MAXX];     /* the chart column of x_j */
    for (int a = 1, p = 0; a < 4; a++) {
        const int free = x_pos(m, slot[a]) >= 0;
        c[a] = free ? x[p] : m->fixed[slot[a]];
        if (free) col[p++] = a;
    }
    double u[FIT_NP] = {0.0}, D[4][4], e[2], de[2][FIT_NP];
    u[jl] = 1.0;
    int st = chart_to_v(m, c, u, M ? D : NULL);
    if (st || (st = end_offset(m, u, e, M ? de : NULL))) return st;
    const double e2 = e[0] * e[0] + e[1] * e[1], lam = fit_norm(m->chord[0], m->chord[1]) / sqrt(e2);
    if (!(e2 > 0.0) || !isfinite(lam)) return EL_EDOM;
    memcpy(v, u, sizeof u);
    v[0] = m->fixed[0];
    v[1] = m->fixed[1];
    v[sl.phi] = u[sl.phi] + atan2(m->chord[1], m->chord[0]) - atan2(e[1], e[0]);
    v[jl] = lam;
    if (m->model == FIT_SMOOTH) v[sl.w] = u[sl.w] / lam;
    if (!M) return EL_OK;
    memset(M, 0, sizeof(double) * FIT_NP * m->nx);
    for (int j = 0; j < m->nx; j++) {
        /* d u / d x_j (the chart's column col[j]: theta0 held at 0), carried to e */
        double du[FIT_NP] = {0.0}, dei[2] = {0.0, 0.0};
        for (int r = 0; r < 4; r++) du[slot[r]] = D[r][col[j]];
        for (int r = 0; r < FIT_NP; r++) {
            dei[0] += de[0][r] * du[r];
            dei[1] += de[1][r] * du[r];
        }
        const double dalpha = -(e[0] * dei[1] - e[1] * dei[0]) / e2;
        const double dlam = -lam * (e[0] * dei[0] + e[1] * dei[1]) / e2;
        for (int r = 0; r < 4; r++) M[slot[r] * m->nx + j] = du[slot[r]];
        M[sl.phi * m->nx + j] += dalpha;
        M[jl * m->nx + j] = dlam;
        if (m->model == FIT_SMOOTH) M[sl.w * m->nx + j] = (du[sl.w] - v[sl.w] * dlam) / lam;
    }
    return EL_OK;
}

/* x of the ends chart for the parameters v: the shape of v's curve, whatever its ends (a
 * held variable left out). */
static void ends_from_v(const fit_map *m, const double *v, double *x)
{
    const chart_slots sl = chart_of(m->model);
    const int slot[4] = {sl.phi, sl.w, sl.k, sl.q};
    double c[4], shape[4] = {0.0, NAN, NAN, NAN};
    if (!chart_from_v(m, v, c)) {          /* unevaluable: NaN, left for the caller's check */
        const double L = m->model == FIT_SMOOTH ? v[6] : 1.0, cs = cos(c[0]), sn = sin(c[0]);
        shape[1] = c[1] * L;
        shape[2] = (cs * c[2] + sn * c[3]) * L * L;
        shape[3] = (cs * c[3] - sn * c[2]) * L * L;
    }
    for (int a = 1, p = 0; a < 4; a++)
        if (x_pos(m, slot[a]) >= 0) x[p++] = shape[a];
}

int el__fit_map_eval(const fit_map *m, const double *x, double v[2][FIT_NP], double *M)
{
    if (m->ncurves == 2) return el__fit_keyline_map(m, x, v, M);
    if (m->chart == FIT_CHART_ENDS) {
        const int st = ends_to_v(m, x, v[0], M);
        return st ? st : el__all_finite(v[0], FIT_NP) ? EL_EDOM : EL_OK;
    }
    double u[FIT_NP];
    memcpy(u, m->fixed, sizeof u);
    for (int j = 0; j < m->nx; j++) u[m->idx[j]] = x[j] / m->scale[m->idx[j]];
    memcpy(v[0], u, sizeof u);
    if (M)
        for (int r = 0; r < FIT_NP; r++)
            for (int j = 0; j < m->nx; j++) M[r * m->nx + j] = r == m->idx[j] ? 1.0 / m->scale[r] : 0.0;
    if (m->chart) {
        /* a chart variable held (a start tangent or curvature constraint) is in fixed[] */
        const chart_slots sl = chart_of(m->model);
        const int slot[4] = {sl.phi, sl.w, sl.k, sl.q}, pos[4] = {x_pos(m, sl.phi), x_pos(m, sl.w),
                                                                  x_pos(m, sl.k), x_pos(m, sl.q)};
        double c[4], D[4][4];
        for (int a = 0; a < 4; a++) c[a] = pos[a] >= 0 ? x[pos[a]] : m->fixed[slot[a]];
        int st = chart_to_v(m, c, v[0], M ? D : NULL);
        if (st) return st;
        if (M)
            for (int r = 0; r < 4; r++)
                for (int col = 0; col < 4; col++)
                    if (pos[col] >= 0) M[slot[r] * m->nx + pos[col]] = D[r][col];
    }
    return el__all_finite(v[0], FIT_NP) ? EL_EDOM : EL_OK;
}

void el__fit_map_inverse(const fit_map *m, const double *v, double *x)
{
    if (m->chart == FIT_CHART_ENDS) {
        ends_from_v(m, v, x);
        return;
    }
    for (int j = 0; j < m->nx; j++) x[j] = v[m->idx[j]] * m->scale[m->idx[j]];
    if (!m->chart) return;
    const chart_slots sl = chart_of(m->model);
    double c[4];
    if (chart_from_v(m, v, c)) {           /* unevaluable: left for the caller's check */
        for (int a = 0; a < 4; a++) c[a] = NAN;
    }
    const int slot[4] = {sl.phi, sl.w, sl.k, sl.q};
    for (int a = 0; a < 4; a++) {
        const int p = x_pos(m, slot[a]);
        if (p >= 0) x[p] = c[a];
    }
}

/*
 * The largest alpha <= 1 for which x + alpha d keeps the variables inside the model's
 * open domain, with a fraction-to-the-boundary rule (as Ipopt's): a step may go at most
 * half the way to the boundary (farther, the Gauss-Newton model is not to be trusted).
 * The domains: the discrete h > 0 and, outside the start-state chart (whose variables
 * are unbounded), k > -1; the discrete keyline's |k| < 1 and h > 0 (the smooth one's
 * variable is atanh k).
 */
double el__fit_map_step_limit(const fit_map *m, const double *x, const double *d)
{
    double alpha = 1.0;
    for (int j = 0; j < m->nx; j++) {
        double lo = -HUGE_VAL, hi = HUGE_VAL;
        if (m->ncurves == 2) {
            const int slot = m->nx == 9 ? (j >= 3 ? (j - 3) % 3 : -1) : (j >= 3 ? (j - 3) % 2 + 1 : -1);
            if (slot == 2 && m->model == FIT_DISCRETE) { lo = -1.0; hi = 1.0; }     /* k (smooth: atanh k) */
            else if (slot == 0 && m->model == FIT_DISCRETE) lo = 0.0;               /* h */
        } else if (m->model == FIT_DISCRETE) {
            const int col = m->idx[j];
            if (col == 2) lo = 0.0;
            else if (col == 6 && !m->chart) lo = -m->scale[6];
        }
        const double t = x[j] + d[j];
        if (d[j] < 0.0 && t < x[j] - 0.5 * (x[j] - lo)) alpha = fmin(alpha, 0.5 * (lo - x[j]) / d[j]);
        if (d[j] > 0.0 && t > x[j] + 0.5 * (hi - x[j])) alpha = fmin(alpha, 0.5 * (hi - x[j]) / d[j]);
    }
    return alpha > 0.0 ? alpha : 0.0;
}
