/*
 * Elastic splines: the result (el_spline_result) from a solved chain, in user units: the
 * pieces (x0, y0 the given points or guide ducks exactly), forces, angles and curvatures at
 * the points, length, energy, max |kappa|, the residual measured at the end, and what
 * el_smooth_params resolves near the separatrix (circle pieces, separatrix_bound). Moved
 * from spline.c, which keeps the API and the paths of the solve.
 */
#include "internal.h"
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* max |kappa| on a piece: the ends, or 2|k| sqrt(mu) if u passes a maximum of
 * |cn|: u = 2 j K(k) (|k| < 1), |k| u = 2 j K(1/|k|) (|k| > 1); Kq = K(min(|k|, 1/|k|)). */
static double piece_max_curvature(const el_smooth_params *p, double Kq, double k0, double k1)
{
    double m = fmax(fabs(k0), fabs(k1));
    const double ka = fabs(p->k), w = sqrt(p->mu);
    if (ka == 0.0) return m;
    const double per = ka < 1.0 ? 2.0 * Kq : 2.0 * Kq / ka;
    const double u0 = p->q, u1 = p->q + w * p->length;
    if (floor(u1 / per) > floor(u0 / per) || fmod(u0, per) == 0.0) m = fmax(m, 2.0 * ka * w);
    return m;
}

/* A piece that is a circular arc to what el_smooth_params resolves: |k| this large
 * (piece_from_state keeps |k| <~ 1e4 there, as el_hermite_solve), or a piece near one
 * (sigma near kappa^2, |k| in the hundreds) whose points el_smooth_eval resolves only
 * to more than tol of its length: 64 eps (1 + max|u|)(1 + |k|) / sqrt(mu) (header),
 * ~128 eps k^2 per radian of turning. Without the second test ducks on a unit circle
 * were accepted at sigma = 1 + 1e-8 (|k| 5000, residual 2e-8) but refused at
 * sigma = 1 + 1e-6 (|k| ~ 700, residual 3.7e-10 > tol 1e-10). */
int el__spline_circle_piece(const el_smooth_params *p, double tol)
{
    if (fabs(p->k) >= 1e3) return 1;
    const double w = sqrt(p->mu), umax = fmax(fabs(p->q), fabs(p->q + w * p->length));
    return p->length > 0.0 && 64.0 * DBL_EPSILON * (1.0 + umax) * (1.0 + fabs(p->k)) > tol * w * p->length;
}

/* What one ulp of k moves on a piece near the separatrix (1 - k^2 -> 0: a nearly
 * straight run under tension), in the residual's units. Its first integral
 * kappa^2 = 4 mu (c^2 - (1 - k^2)), c = cos((theta - phi)/2) = dn(u) (seed 000 (4.2),
 * kappa = 2 k sqrt(mu) cn), has 1 - k^2 only in steps of delta = 2|k| ulp(k):
 * - curvature: a sinh boundary layer kappa = A e^{-w s} + B e^{w (s - L)} has
 *   A B proportional to 1 - k^2, so with A set by one end, B (the other end's
 *   curvature) is known to delta / |1 - k^2| of itself: that times kappa_max h;
 *   at k = 1 exactly (1 - k^2 below delta) all of it, kappa_max h;
 * - angle: at fixed kappa, c^2 moves by delta, so c by sqrt(c^2 + delta) - c
 *   (<= delta / 2c, <= sqrt(delta)) and theta = phi + 2 acos(c) by twice that, c at
 *   the better resolved end.
 * The sum of both (the solver cannot choose where the step lands); a joint's
 * jump carries both its pieces' (make_result). ~eps for a piece away from the
 * separatrix; |k| > 1 (past it): the same expression with |1 - k^2|. */
double el__spline_separatrix_bound(const el_smooth_params *p, const double th[2], double kmax, double h)
{
    const double ka = fabs(p->k);
    if (!(ka > 0.0) || !isfinite(ka)) return 0.0;
    const double delta = 2.0 * ka * (nextafter(ka, INFINITY) - ka), kp2 = fabs(1.0 - ka * ka);
    const double c = fmax(fabs(cos(0.5 * (th[0] - p->phi))), fabs(cos(0.5 * (th[1] - p->phi))));
    return fmin(1.0, delta / fmax(kp2, delta)) * kmax * h + 2.0 * delta / (sqrt(c * c + delta) + c);
}

/* Knot i's position in user units (xy: the points, S: the unit): a point, or a
 * guide duck at its chord fraction plus its offset along the span's normal. */
static void knot_position(const el__spchain *w, const double *xy, double S, size_t i, double *p)
{
    const long g = w->guide_at[i];
    if (g < 0) {
        size_t pt = i;   /* the point: the knots before i that are not guides */
        for (int k = 0; k < w->ng; k++) pt -= w->guide[k].knot < i;
        p[0] = xy[2 * pt];
        p[1] = xy[2 * pt + 1];
        return;
    }
    const el__spguide *gd = &w->guide[g];
    const double *a = xy + 2 * gd->pa, d = w->x[gd->slot] * S;
    p[0] = a[0] + gd->f * (a[2] - a[0]) + d * gd->nx;
    p[1] = a[1] + gd->f * (a[3] - a[1]) + d * gd->ny;
}

/* Whether every piece of the chain is one: finite unknowns and a positive length. */
int el__spline_pieces_drawn(const el__spchain *w)
{
    for (size_t j = 0; j < w->m; j++) {
        const double *v = w->pc[j].v;
        for (int i = 0; i < EL__NV; i++)
            if (!isfinite(v[i])) return 0;
        if (!(v[EL__SP_L] > 0.0)) return 0;
    }
    return 1;
}

/* Fill res from the solved chain (original units), measuring the residual;
 * *other: the part of it from joints and ends without a circle piece or a piece
 * whose separatrix_bound exceeds tol; *sep: the largest such bound (0: none). */
int el__spline_make_result(const el__spchain *w, const double *xy, size_t npoints, double S, double tol,
                           el_spline_result *res, double *other, double *sep)
{
    const size_t n = w->n, m = w->m;
    el_spline_result r;
    memset(&r, 0, sizeof r);
    r.npoints = npoints;
    r.npieces = m;
    r.pieces = malloc(m * sizeof *r.pieces);
    r.forces = malloc(2 * m * sizeof *r.forces);
    r.angles = malloc(npoints * sizeof *r.angles);
    r.curvatures = malloc(npoints * sizeof *r.curvatures);
    double *ends = malloc(2 * m * sizeof *ends);   /* theta, kappa at each piece's end */
    double *knot = malloc(4 * n * sizeof *knot);   /* positions, then theta, kappa at each knot */
    double *bnd = malloc(m * sizeof *bnd);         /* each piece's separatrix_bound */
    char *unres = malloc(m);                       /* 1: a circle piece or one past tol's bound */
    if (!r.pieces || !r.forces || !r.angles || !r.curvatures || !ends || !knot || !bnd || !unres) {
        el_spline_result_free(&r);
        free(ends);
        free(knot);
        free(bnd);
        free(unres);
        return EL_ENOMEM;
    }
    *sep = 0.0;
    double *kth = knot + 2 * n, *kka = knot + 3 * n;
    for (size_t i = 0; i < n; i++) knot_position(w, xy, S, i, knot + 2 * i);
    double resid = 0.0, rest = 0.0;
    /* tension mode: the given sigma exactly (not through the unit S) */
    r.sigma = w->lmode ? w->sigma / (S * S) : w->sigma_user;
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        el_smooth_params *p = &r.pieces[j];
        p->x0 = knot[2 * j];
        p->y0 = knot[2 * j + 1];
        p->phi = pc->v[EL__SP_PHI];
        p->mu = exp(pc->v[EL__SP_NU]) / (S * S);
        p->k = pc->v[EL__SP_K];
        p->q = pc->v[EL__SP_Q];
        p->length = pc->v[EL__SP_L] * S;
        /* the residual is measured on the output, with el_smooth_eval */
        const double s2[2] = {0.0, p->length};
        double pt[4], th[2], ka[2];
        const int st = el_smooth_eval(p, 2, s2, pt, th, ka);
        if (st) { el_spline_result_free(&r); free(ends); free(knot); free(bnd); free(unres); return st; }
        const double *e = knot + 2 * ((j + 1) % n);
        const double h = hypot(e[0] - p->x0, e[1] - p->y0);
        const double rp = hypot(pt[2] - e[0], pt[3] - e[1]) / h;
        const double kmax = piece_max_curvature(p, pc->Kq, ka[0], ka[1]);
        /* a circle piece is judged by the circle rule alone */
        const int circle = el__spline_circle_piece(p, tol);
        bnd[j] = circle ? 0.0 : el__spline_separatrix_bound(p, th, kmax, h);
        if (bnd[j] > tol) *sep = fmax(*sep, bnd[j]);
        unres[j] = circle || bnd[j] > tol;
        resid = fmax(resid, rp);
        if (!unres[j]) rest = fmax(rest, rp);
        kth[j] = th[0];
        kka[j] = ka[0];
        ends[2 * j] = th[1];
        ends[2 * j + 1] = ka[1];
        if (!w->closed && j == m - 1) { kth[n - 1] = th[1]; kka[n - 1] = ka[1]; }
        /* F = (sigma - kappa^2) T - 2 kappa' N at s = 0 */
        const double dk = pc->dkap0 / (S * S), T[2] = {cos(th[0]), sin(th[0])};
        const double a = r.sigma - ka[0] * ka[0];
        r.forces[2 * j] = a * T[0] + 2.0 * dk * T[1];
        r.forces[2 * j + 1] = a * T[1] - 2.0 * dk * T[0];
        r.energy += pc->energy / S;
        r.length += p->length;
        r.max_curvature = fmax(r.max_curvature, kmax);
    }
    /* the joints and the end conditions; the points' angles and curvatures */
    for (size_t i = 0, pt = 0; i < n; i++) {
        const double lr = w->ell[i] * S;
        double ri = 0.0;
        int circle;
        if (!w->closed && (i == 0 || i == n - 1)) {
            const int e = i == 0 ? 0 : 1;
            const double kap = kka[i];
            if (w->kind[e] == EL_SPLINE_NATURAL) ri = fabs(kap) * lr;
            if (w->kind[e] == EL_SPLINE_G2) ri = fabs(kap - w->kg[e] / S) * lr;
            if (w->kind[e] != EL_SPLINE_NATURAL)
                ri = fmax(ri, fabs(el__wrap_pi(kth[i] - w->th_end[e])));
            const size_t j = i == 0 ? 0 : m - 1;
            circle = unres[j];
            if (bnd[j] > tol) *sep = fmax(*sep, bnd[j]);
        } else {
            const size_t jm = (i + m - 1) % m;
            ri = fmax(fabs(el__wrap_pi(ends[2 * jm] - kth[i])), fabs(ends[2 * jm + 1] - kka[i]) * lr);
            circle = unres[jm] || unres[i % m];
            /* a joint's jump: both pieces' steps */
            if (bnd[jm] > tol || bnd[i % m] > tol) *sep = fmax(*sep, bnd[jm] + bnd[i % m]);
        }
        resid = fmax(resid, ri);
        if (!circle) rest = fmax(rest, ri);
        const long g = w->guide_at[i];
        if (g < 0) {
            r.angles[pt] = kth[i];
            r.curvatures[pt++] = kka[i];
            continue;
        }
        /* a guide duck: its position, and its force F_{i-1} - F_i */
        r.guide_pieces[g] = i;
        r.guides[2 * g] = knot[2 * i];
        r.guides[2 * g + 1] = knot[2 * i + 1];
        r.guide_forces[2 * g] = r.forces[2 * (i - 1)] - r.forces[2 * i];
        r.guide_forces[2 * g + 1] = r.forces[2 * (i - 1) + 1] - r.forces[2 * i + 1];
    }
    r.nguides = (size_t)w->ng;
    free(ends);
    free(knot);
    free(bnd);
    free(unres);
    if (w->lmode == EL__BORDER_LENGTH) {
        const double rl = fabs(r.length - w->Lt * S) / (w->Lt * S);
        resid = fmax(resid, rl);
        rest = fmax(rest, rl);
    }
    r.residual = resid;
    r.resolution = *sep;
    *other = rest;
    r.iterations = w->iterations;
    *res = r;
    return EL_OK;
}
