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
int fit_to_discrete(const double *v, el_discrete_params *p, double *dq_dk)
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
int fit_to_smooth(const double *v, el_smooth_params *p)
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
int fit_canonical(int model, double *v, int may_shift)
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

int fit_smooth_rows(const double *v, size_t m, const double *s, double *xy, double *jac)
{
    el_smooth_params p;
    int st = fit_to_smooth(v, &p);
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

void fit_walk_start(const double *v, fit_walk *w)
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
int fit_discrete_rows(const double *v, fit_walk *w, size_t m, double *xy, double *jac, double *tmp)
{
    el_discrete_params p;
    double dq_dk;
    int st = fit_to_discrete(v, &p, &dq_dk);
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
        for (size_t i = 0; i <= m; i++) {
            for (int c = 0; c < 2; c++) {
                double *r = tj + (2 * i + c) * FIT_NP;
                r[4] += a * r[5];
                for (int j = 2; j < FIT_NP; j++) r[j] += w->d[c][j];
            }
        }
        if (xy) memcpy(xy, txy, sizeof(double) * 2 * m);
        memcpy(w->d, tj + 2 * m * FIT_NP, sizeof w->d);
        memcpy(jac, tj, sizeof(double) * 2 * m * FIT_NP);
        if (v[6] < 0.0)          /* d/dk of (|k|, q + 2K(|k|)) as a function of k < 0 */
            for (size_t i = 0; i < 2 * m; i++) {
                double *r = jac + i * FIT_NP;
                r[6] = -(r[6] + dq_dk * r[5]);
            }
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
    int st = fit_smooth_rows(v, 1, &s, e->xy, jac);
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

/* Discrete, vertex j0 = 0 (at_end 0) or n-1: the tangent of the adjacent segment,
 * Theta = phi + a_j + a_{j+1} (j = 0 or n-2), and the extended curvature
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
        fit_walk_start(v, &w);
        double *xy = tmp, *jac = xy + 2 * FIT_BLOCK, *t2 = jac + 2 * FIT_BLOCK * FIT_NP;
        size_t left = n;
        while (left > 0) {
            const size_t m = left < FIT_BLOCK ? left : FIT_BLOCK;
            if ((st = fit_discrete_rows(v, &w, m, xy, jac, t2))) return st;
            left -= m;
            if (left == 0) {
                memcpy(e->xy, xy + 2 * (m - 1), sizeof e->xy);
                memcpy(e->dxy, jac + 2 * (m - 1) * FIT_NP, sizeof e->dxy);
            }
        }
    }
    /* the segment: a_{j0} + a_{j0+1} at the start, a_{j0-1} + a_{j0} at the end */
    const half_angle *s0 = at_end ? &ha[0] : &ha[1], *s1 = at_end ? &ha[1] : &ha[2];
    const double j_s0 = at_end ? js[0] : js[1], j_s1 = at_end ? js[1] : js[2];
    e->theta = v[3] + s0->a + s1->a;
    e->dtheta[3] = 1.0;
    e->dtheta[4] = s0->a_u * j_s0 + s1->a_u * j_s1;
    e->dtheta[5] = s0->a_u + s1->a_u;
    e->dtheta[6] = s0->a_k + s1->a_k;
    const double D = ha[2].a - ha[0].a, tn = tan(0.5 * D);
    e->kappa = 2.0 / h * tn;
    const double dD = (1.0 + tn * tn) / h;          /* d kappa / d D */
    e->dkappa[2] = -e->kappa / h;
    e->dkappa[4] = dD * (ha[2].a_u * js[2] - ha[0].a_u * js[0]);
    e->dkappa[5] = dD * (ha[2].a_u - ha[0].a_u);
    e->dkappa[6] = dD * (ha[2].a_k - ha[0].a_k);
    return EL_OK;
}

int fit_end_state(int model, const double *v, size_t n, int at_end, fit_end *e, double *tmp)
{
    return model == FIT_SMOOTH ? smooth_end(v, at_end, e) : discrete_end(v, n, at_end, e, tmp);
}

/* ------------------------------------------------------------ the map x -> v */

/*
 * Shape variables (one curve, k, q and z (discrete) or w (smooth) free and unbounded).
 * Near a circle (|k| >> 1) the curve depends on k only through 1/k^2 and on z, q (w)
 * through k z, k q (k w): the argument of am(k u; 1/k). In (k, z, q) the valley of the
 * objective is curved and Gauss-Newton steps overshoot, so the optimiser sees instead
 *   f with k = f / sqrt(2 - |f|)   (f in (-2, 2): f ~ k near 0, 2 - |f| ~ 4/k^2 near
 *                                   |k| = oo, |f| = 1 at |k| = 1; odd, C^1 at 0),
 *   z g, q g (w g) with g = sqrt(1 + k^2).
 */
static double k_of_f(double f) { return f / sqrt(2.0 - fabs(f)); }
static double f_of_k(double k)
{
    const double a = fabs(k);
    return copysign(0.5 * (a * sqrt(a * a + 8.0) - a * a), k);
}

static void shape_slots(int model, int *ik, int *iq, int *iz)
{
    *ik = model == FIT_DISCRETE ? 6 : 4;
    *iq = 5;
    *iz = model == FIT_DISCRETE ? 4 : 3;
}

int fit_map_eval(const fit_map *m, const double *x, double v[2][FIT_NP], double *M)
{
    if (m->ncurves == 2) return fit_keyline_map(m, x, v, M);
    double u[FIT_NP];
    memcpy(u, m->fixed, sizeof u);
    for (int j = 0; j < m->nx; j++) u[m->idx[j]] = x[j] / m->scale[m->idx[j]];
    memcpy(v[0], u, sizeof u);
    double S[FIT_NP][FIT_NP] = {{0}};       /* d v / d u */
    for (int j = 0; j < FIT_NP; j++) S[j][j] = 1.0;
    if (m->shape) {
        int ik, iq, iz;
        shape_slots(m->model, &ik, &iq, &iz);
        const double f = u[ik], af = fabs(f);
        if (!(af < 2.0)) return EL_EDOM;
        const double k = k_of_f(f), g2 = 1.0 + k * k, g = sqrt(g2);
        const double dk = (4.0 - af) / (2.0 * (2.0 - af) * sqrt(2.0 - af));   /* even in f */
        v[0][ik] = k;
        v[0][iq] = u[iq] / g;
        v[0][iz] = u[iz] / g;
        S[ik][ik] = dk;
        S[iq][iq] = S[iz][iz] = 1.0 / g;
        S[iq][ik] = -v[0][iq] * (k / g2) * dk;
        S[iz][ik] = -v[0][iz] * (k / g2) * dk;
    }
    if (M)
        for (int r = 0; r < FIT_NP; r++)
            for (int j = 0; j < m->nx; j++)
                M[r * m->nx + j] = S[r][m->idx[j]] / m->scale[m->idx[j]];
    return el__all_finite(v[0], FIT_NP) ? EL_EDOM : EL_OK;
}

void fit_map_inverse(const fit_map *m, const double *v, double *x)
{
    double u[FIT_NP];
    memcpy(u, v, sizeof u);
    if (m->shape) {
        int ik, iq, iz;
        shape_slots(m->model, &ik, &iq, &iz);
        const double g = sqrt(1.0 + v[ik] * v[ik]);
        u[ik] = f_of_k(v[ik]);
        u[iq] = v[iq] * g;
        u[iz] = v[iz] * g;
    }
    for (int j = 0; j < m->nx; j++) x[j] = u[m->idx[j]] * m->scale[m->idx[j]];
}

/*
 * The largest alpha <= 1 for which x + alpha d keeps the variables inside the model's
 * open domain, with a fraction-to-the-boundary rule (as Ipopt's): a step may go at most
 * half the way to the boundary (k at most doubles towards a circle, the straight line
 * or the separatrix in one step; farther, the Gauss-Newton model is not to be
 * trusted). The domains: the shape variable |f| < 2; the discrete h > 0 and k > -1; the
 * keyline's |k| < 1 and discrete h > 0.
 */
double fit_map_step_limit(const fit_map *m, const double *x, const double *d)
{
    double alpha = 1.0;
    for (int j = 0; j < m->nx; j++) {
        double lo = -HUGE_VAL, hi = HUGE_VAL;
        if (m->ncurves == 2) {
            const int slot = m->nx == 9 ? (j >= 3 ? (j - 3) % 3 : -1) : (j >= 3 ? (j - 3) % 2 + 1 : -1);
            if (slot == 1 + (m->model == FIT_DISCRETE)) { lo = -1.0; hi = 1.0; }    /* k */
            else if (slot == 0 && m->model == FIT_DISCRETE) lo = 0.0;               /* h */
        } else {
            int ik, iq, iz;
            shape_slots(m->model, &ik, &iq, &iz);
            const int col = m->idx[j];
            if (m->shape && col == ik) { lo = -2.0; hi = 2.0; }
            else if (m->model == FIT_DISCRETE && col == 6) lo = -m->scale[6];
            else if (m->model == FIT_DISCRETE && col == 2) lo = 0.0;
        }
        const double t = x[j] + d[j];
        if (d[j] < 0.0 && t < x[j] - 0.5 * (x[j] - lo)) alpha = fmin(alpha, 0.5 * (lo - x[j]) / d[j]);
        if (d[j] > 0.0 && t > x[j] + 0.5 * (hi - x[j])) alpha = fmin(alpha, 0.5 * (hi - x[j]) / d[j]);
    }
    return alpha > 0.0 ? alpha : 0.0;
}
