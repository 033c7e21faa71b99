/*
 * The buckled batten (spline.c, spline_path.c): collinear ducks pushed longer than their
 * line (el__spline_solve_buckled: its first mode, followed in length) and ducks near a
 * line (el__spline_solve_near_line), and which ducks those are (el__spline_straight_line,
 * el__spline_near_line: moved unchanged from spline.c). Split from spline_path.c, whose
 * continuation (el__spline_continuation) it uses.
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>

/* L(t) from par[0] (t = 0) to par[1], geometrically in L - par[2] (the polygon's
 * length, near which the bow is small). */
static void set_length(el__spchain *w, double t, const double *par)
{
    const double a = par[0] - par[2], b = par[1] - par[2];
    w->Lt = t >= 1.0 ? par[1] : par[2] + a * pow(b / a, t);
}

/* ------------------------------------------------------------------ buckling */

/*
 * A span of chord h under compression, linearised about the line: the
 * deflection w(s) with w'''' + lambda w'' = 0 (2 kappa'' = sigma kappa with
 * kappa = w'', sigma = -2 lambda) and w = 0 at both ducks has end curvatures
 * linear in its end slopes va, vb:
 *   -w''(0) = (s va + c vb) / h,   w''(h) = (c va + s vb) / h,
 * with phi = sqrt(lambda) h and D = 2 - 2 cos phi - phi sin phi,
 *   s = phi (sin phi - phi cos phi) / D,   c = phi (phi - sin phi) / D
 * (Timoshenko's stability functions s and s c; from w = A + B s + C cos + D sin
 * and the four end conditions, checked against that solve; s = 4, c = 2 at
 * phi = 0, the cubic's, and series below phi = 0.1 where D cancels).
 */
static void span_stiffness(double phi, double *s, double *c)
{
    const double p2 = phi * phi;
    if (phi < 0.1) {
        *s = 4.0 - 2.0 * p2 / 15.0 - 11.0 * p2 * p2 / 6300.0;
        *c = 2.0 + p2 / 30.0 + 13.0 * p2 * p2 / 12600.0;
        return;
    }
    const double D = 2.0 - 2.0 * cos(phi) - phi * sin(phi);
    *s = phi * (sin(phi) - phi * cos(phi)) / D;
    *c = phi * (phi - sin(phi)) / D;
}

/* Sylvester's law of inertia: the negative pivots of L D L^T (GSL has no inertia count) */
int el__tridiag_negatives(const double *dg, const double *up, size_t i0, size_t i1, double shift)
{
    int neg = 0;
    double d = 0.0;
    for (size_t i = i0; i <= i1; i++) {
        d = i == i0 ? dg[i] - shift : dg[i] - shift - up[i - 1] * up[i - 1] / d;
        if (d == 0.0) d = -1e-300;
        neg += d < 0.0;
    }
    return neg;
}

/* Three steps of inverse iteration from z = 1 (GSL's symmetric tridiagonal solve) */
int el__tridiag_inverse_iter(el__spchain *w, size_t i0, size_t i1)
{
    const size_t nf = i1 - i0 + 1;
    double *z = w->z + i0, *b = w->b + i0;
    if (nf == 1) {   /* the three steps z = (z / |z|) / dg from 1 end exactly at 1 / dg */
        z[0] = 1.0 / w->dg[i0];
        return isfinite(z[0]) ? EL_OK : EL_ENOCONV;
    }
    for (size_t i = 0; i < nf; i++) z[i] = 1.0;
    gsl_vector_view d = gsl_vector_view_array(w->dg + i0, nf), e = gsl_vector_view_array(w->up + i0, nf - 1);
    gsl_vector_view bv = gsl_vector_view_array(b, nf), x = gsl_vector_view_array(z, nf);
    for (int it = 0; it < 3; it++) {
        const double norm = el__max_abs(z, nf);
        for (size_t i = 0; i < nf; i++) b[i] = z[i] / norm;
        if (gsl_linalg_solve_symm_tridiag(&d.vector, &e.vector, &bv.vector, &x.vector)) return EL_ENOCONV;
    }
    return el__all_finite(z, nf) ? EL_ENOCONV : EL_OK;
}

/* K(lambda) on the free knots i0..i1 (their slopes; the curvature jumps as
 * equations: symmetric tridiagonal, diagonal dg, off-diagonal up); returns the
 * number of its negative eigenvalues (el__tridiag_negatives). */
static int buckling_matrix(el__spchain *w, size_t i0, size_t i1, double lambda)
{
    memset(w->dg, 0, w->n * sizeof *w->dg);
    memset(w->up, 0, w->n * sizeof *w->up);
    for (size_t j = 0; j < w->m; j++) {
        const double h = w->pc[j].h;
        double s, c;
        span_stiffness(sqrt(lambda) * h, &s, &c);
        if (j >= i0 && j <= i1) w->dg[j] += s / h;
        if (j + 1 >= i0 && j + 1 <= i1) w->dg[j + 1] += s / h;
        if (j >= i0 && j + 1 <= i1) w->up[j] += c / h;
    }
    return el__tridiag_negatives(w->dg, w->up, i0, i1, 0.0);
}

/*
 * The first buckling mode of the chain on the line (slopes z at the knots,
 * zero where fixed) and its lambda: the least lambda where K(lambda) is
 * singular, by bisection on the inertia count of K (which gains one negative
 * eigenvalue at each buckling load as lambda grows), between 0 and the clamped
 * load (2 pi / h_max)^2 of the longest span, which bounds it (Rayleigh: that
 * span's clamped mode, zero elsewhere); then the null vector by inverse
 * iteration just below it. The least lambda is the least energy at a given
 * small excess length: integral kappa^2 = 2 lambda (L - Lp) to first order.
 */
static int buckling_mode(el__spchain *w, size_t i0, size_t i1, double *lambda)
{
    double hmax = 0.0;
    for (size_t j = 0; j < w->m; j++) hmax = fmax(hmax, w->pc[j].h);
    double lo = 0.0, hi = 4.0 * M_PI * M_PI / (hmax * hmax) * (1.0 - 1e-12);
    for (int it = 0; it < 60; it++) {
        const double mid = 0.5 * (lo + hi);
        if (buckling_matrix(w, i0, i1, mid)) hi = mid; else lo = mid;
    }
    *lambda = hi;
    buckling_matrix(w, i0, i1, hi * (1.0 - 1e-12));
    return el__tridiag_inverse_iter(w, i0, i1);
}

/*
 * Collinear points, a length Lt longer than the line (Lp): the batten buckles
 * in its first mode (buckling_mode), its largest bow (the first of equal ones)
 * to the left (mirror: to the right), started with the small excess L1 = Lp (1 +
 * 1e-3), less if that makes the mean square slope on a span more than 0.05^2 (where the
 * linearisation is accurate): slopes theta = dir + Theta z with integral w'^2 =
 * 2 (L1 - Lp), sigma = -2 lambda, each piece the linearised batten of its span;
 * then followed in length. Two points clamped at both ends have no free slope:
 * the span's own clamped mode w = A (1 - cos(2 pi s / h)), its start state
 * (dir, A (2 pi / h)^2, 0) with integral w'^2 = A^2 (2 pi / h)^2 h / 2.
 */
int el__spline_solve_buckled(el__spchain *w, int max_steps, double dir, double Lp, double Lt, int mirror)
{
    const size_t n = w->n, m = w->m;
    double L1 = fmin(Lt, Lp * (1.0 + 1e-3));
    const size_t i0 = w->slot[0] == EL__SLOT_ANGLE ? 0 : 1;
    const size_t i1 = w->slot[n - 1] == EL__SLOT_ANGLE ? n - 1 : n - 2;
    int st = EL_OK;
    memset(w->z, 0, n * sizeof *w->z);
    if (i0 <= i1) {
        double lambda;
        if ((st = buckling_mode(w, i0, i1, &lambda))) return st;
        /* integral w'^2 = -d/dlambda of the span's form (s a^2 + 2 c a b + s b^2) / h,
         * which is integral w''^2 - lambda integral w'^2 = [w' w''] for a
         * solution (integrating by parts), stationary in the interior values
         * (the envelope theorem); by central differences */
        double g = 0.0, gmax = 0.0, bow = 0.0;
        for (size_t j = 0; j < m; j++) {
            const double a = w->z[j], b = w->z[j + 1], h = w->pc[j].h, phi = sqrt(lambda) * h;
            double form[2];
            for (int e = 0; e < 2; e++) {
                double sj, cj;
                span_stiffness(phi * sqrt(1.0 + (e ? 1e-5 : -1e-5)), &sj, &cj);
                form[e] = (sj * (a * a + b * b) + 2.0 * cj * a * b) / h;
            }
            const double gj = -(form[1] - form[0]) / (2e-5 * lambda);
            g += gj;
            gmax = fmax(gmax, gj / h);
            /* the mid deflection: (a - b) / 2 tan(phi / 4) / sqrt(lambda), from
             * the symmetric part w = A + C cos(sqrt(lambda) (s - h / 2)) */
            const double mid = 0.5 * (a - b) * tan(0.25 * phi) * h / phi;
            if (fabs(mid) > fabs(bow) * (1.0 + 1e-9)) bow = mid;
        }
        const double sign = (bow < 0.0) != (mirror != 0) ? -1.0 : 1.0;
        /* small: a mean square slope at most 0.05^2 on every span (a mode
         * localised in one long span takes the whole excess there) */
        const double zmax = el__max_abs(w->z, n);
        L1 = fmin(L1, Lp + 0.5 * g * 0.05 * 0.05 / gmax);
        const double Th = sign * sqrt(2.0 * (L1 - Lp) / g);
        /* far from a localised bow the slopes decay exponentially: at least
         * 1e-6 of the largest (alternating, as the mode's), so that no piece
         * starts exactly straight, where its k = 0 leaves q undefined */
        for (size_t i = 0; i < n; i++) {
            if (w->slot[i] != EL__SLOT_ANGLE) continue;
            const double z = w->z[i], floor = 1e-6 * zmax * (i % 2 ? -1.0 : 1.0);
            w->x[i] = dir + Th * (fabs(z) >= 1e-6 * zmax ? z : floor);
        }
        w->sigma = -2.0 * lambda;
        /* each piece the linearised batten of its span (el__spiece_start), not
         * corrected alone: near a span's clamped load its bow at fixed sigma
         * is ill-posed, the length of the whole chain fixes it */
        for (size_t j = 0; j < m && !st; j++) {
            el__sptargets t;
            el__chain_targets(w, j, &t);
            if (el__spiece_start(&w->pc[j], &t)) st = EL_ENOCONV;
        }
    } else {   /* two points, both ends clamped along the line */
        const double h = w->pc[0].h, om = 2.0 * M_PI / h, A = sqrt(4.0 * (L1 - Lp) / (om * om * h));
        w->sigma = -2.0 * om * om;
        const double state[EL__NV] = {w->th_end[0], A * om * om, 0.0, w->sigma, L1};
        st = el__spiece_set_state(&w->pc[0], state) ? EL_ENOCONV : EL_OK;
    }
    w->lmode = EL__BORDER_LENGTH;
    w->Lt = L1;
    if (!st) st = el__chain_newton(w, EL__SP_DIRECT_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
    if (!st && Lt > L1) {
        const double par[3] = {L1, Lt, Lp};
        st = el__spline_continuation(w, w->snap, max_steps, 0.25, set_length, par, w->aim, w->tol);
    }
    if (st == EL_ENOCONV && w->resid <= EL__SP_NEAR) w->near = 1;
    return st;
}

/* The chords at t between the line's (par[0 .. 2m), dx, dy pairs) and the ducks'
 * (par[2m .. 4m)), with their lengths and the knots' half sums of them */
static void set_ducks(el__spchain *w, double t, const double *par)
{
    const size_t m = w->m;
    const double u = t >= 1.0 ? 1.0 : t, *line = par, *ducks = par + 2 * m;
    for (size_t j = 0; j < m; j++) {
        el__spiece *pc = &w->pc[j];
        pc->dx = line[2 * j] + u * (ducks[2 * j] - line[2 * j]);
        pc->dy = line[2 * j + 1] + u * (ducks[2 * j + 1] - line[2 * j + 1]);
        pc->h = hypot(pc->dx, pc->dy);
    }
    for (size_t i = 0; i < w->n; i++)   /* as el__spline_solve_paths sets them (open) */
        w->ell[i] = 0.5 * (w->pc[i > 0 ? i - 1 : 0].h + w->pc[i < m ? i : m - 1].h);
}

/* The chain's bending energy (its pieces', internal units) */
static double chain_energy(const el__spchain *w)
{
    double e = 0.0;
    for (size_t j = 0; j < w->m; j++) e += w->pc[j].energy;
    return e;
}

/*
 * Ducks near a line (open, no guide ducks; dir: the line's direction, along which
 * every chord advances), a length Lt longer than their polygon: the batten through the
 * ducks projected onto the line buckled to Lt (el__spline_solve_buckled: its first
 * mode), then the ducks moved from there to their places (continuation in their
 * chords), or the length mode's own path (el__spline_solve_length) where that gives a
 * lower energy. Written because the length mode's path from the free batten meets the
 * buckling bifurcation there: 7 ducks on a line with one raised by 1e-9 .. 1e-3 of
 * their 6.6, pushed 5-20 % longer, gave no spline (the line itself buckles); raised
 * by 0.05 .. 0.27, the batten jumped between modes of 2.6 .. 10 x the energy as that
 * duck moved by 0.01 (QA).
 */
int el__spline_solve_near_line(el__spchain *w, int max_steps, double dir, double Lt)
{
    const size_t n = w->n, m = w->m;
    double *par = malloc(sizeof(double) * (4 * m + n + 2 * EL__NV * m));
    if (!par) return EL_ENOMEM;
    el__spsnap kept = {par + 4 * m, par + 4 * m + n, par + 4 * m + n + EL__NV * m, 0.0};
    const double ux = cos(dir), uy = sin(dir);
    double Lp = 0.0;
    for (size_t j = 0; j < m; j++) {
        const double along = w->pc[j].dx * ux + w->pc[j].dy * uy;
        par[2 * j] = along * ux;
        par[2 * j + 1] = along * uy;
        par[2 * m + 2 * j] = w->pc[j].dx;
        par[2 * m + 2 * j + 1] = w->pc[j].dy;
        Lp += along;
    }
    /* both mirror images of the mode (the ducks off the line prefer a side), the lower
     * energy kept */
    int st = EL_ENOCONV;
    double low = HUGE_VAL;
    for (int mirror = 0; mirror < 2 && st != EL_ENOMEM; mirror++) {
        set_ducks(w, 0.0, par);
        w->near = 0;
        int sm = el__spline_solve_buckled(w, max_steps, dir, Lp, Lt, mirror);
        if (!sm) sm = el__spline_continuation(w, w->snap, max_steps, 0.25, set_ducks, par, w->aim, w->tol);
        if (sm == EL_ENOMEM) st = sm;
        if (sm || !(chain_energy(w) < low)) continue;
        low = chain_energy(w);
        el__snap_save(w, &kept);
        st = EL_OK;
    }
    set_ducks(w, 1.0, par);   /* the ducks' own chords */
    /* the length mode's own path too, kept where it is lower (ducks farther off the line:
     * 2 of 900 random such problems reached a mode of 1.3-2.7 x its energy from the line) */
    if (st != EL_ENOMEM) {
        w->near = 0;
        const int sl = el__spline_solve_length(w, max_steps, Lt);
        if (sl == EL_ENOMEM || (sl == EL_OK && !(chain_energy(w) >= low)) || st) {
            st = sl;
        } else {
            el__snap_load(w, &kept);
            w->lmode = EL__BORDER_LENGTH;
            w->Lt = Lt;
            w->near = 0;
            el__chain_reeval(w, 0);
        }
    }
    free(par);
    return st;
}

/* ------------------------------------------------------------------ which ducks (moved from spline.c) */

/* Collinear points in order along the line, with ends that allow the straight
 * line (G2 ends as clamped: the sibling's, el_spline_solve). */
int el__spline_straight_line(const double *xy, size_t n, const el_spline_options *o, double *dir)
{
    if (o->closed) return 0;
    const double dx = xy[2 * n - 2] - xy[0], dy = xy[2 * n - 1] - xy[1], D = hypot(dx, dy);
    if (!(D > 0.0)) return 0;
    const double ux = dx / D, uy = dy / D;
    for (size_t i = 0; i + 1 < n; i++) {
        const double ax = xy[2 * i + 2] - xy[2 * i], ay = xy[2 * i + 3] - xy[2 * i + 1];
        const double h = hypot(ax, ay);
        if (fabs(ux * ay - uy * ax) > 1e-14 * h || ux * ax + uy * ay <= 0.0) return 0;
    }
    const el_spline_end *e[2] = {&o->start, &o->end};
    for (int i = 0; i < 2; i++) {
        if (e[i]->kind == EL_SPLINE_NATURAL) continue;
        const double tn = hypot(e[i]->tangent[0], e[i]->tangent[1]);
        const double tx = e[i]->tangent[0] / tn, ty = e[i]->tangent[1] / tn;
        if (fabs(ux * ty - uy * tx) > 1e-14 || ux * tx + uy * ty <= 0.0) return 0;
    }
    dir[0] = atan2(uy, ux);
    return 1;
}

/* Points near the line through the first and the last (dir: its direction): each within
 * NEAR_LINE of their distance from it, each chord advancing along it, clamped ends within
 * NEAR_LINE rad of it (not G2: their guide ducks are placed on a solved sibling) */
#define NEAR_LINE 0.05
int el__spline_near_line(const double *xy, size_t n, const el_spline_options *o, double *dir)
{
    if (o->closed || n < 3 || o->start.kind == EL_SPLINE_G2 || o->end.kind == EL_SPLINE_G2) return 0;
    const double dx = xy[2 * n - 2] - xy[0], dy = xy[2 * n - 1] - xy[1], D = hypot(dx, dy);
    if (!(D > 0.0)) return 0;
    const double ux = dx / D, uy = dy / D;
    for (size_t i = 0; i + 1 < n; i++) {
        const double ax = xy[2 * i + 2] - xy[2 * i], ay = xy[2 * i + 3] - xy[2 * i + 1];
        const double off = ux * (xy[2 * i + 3] - xy[1]) - uy * (xy[2 * i + 2] - xy[0]);
        if (!(fabs(off) <= NEAR_LINE * D) || !(ux * ax + uy * ay > 0.0)) return 0;
    }
    const el_spline_end *e[2] = {&o->start, &o->end};
    for (int i = 0; i < 2; i++)
        if (e[i]->kind == EL_SPLINE_TANGENT &&
            !(fabs(el__wrap_pi(atan2(e[i]->tangent[1], e[i]->tangent[0]) - atan2(uy, ux))) <= NEAR_LINE))
            return 0;
    *dir = atan2(uy, ux);
    return 1;
}
