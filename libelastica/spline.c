/*
 * Elastic splines (issue 14): a chain of smooth elasticae of one tension
 * through N points, G2 at every point.
 *
 * Unknowns. Each piece j (from P_j to P_{j+1}) has its start point fixed and
 * five parameters v = (phi, nu = ln mu, k, q, L) of the smooth elastica
 * (header, smooth section; ln mu keeps mu > 0). Its residuals, for the target
 * tangent angles ta at P_j, tb at P_{j+1} and tension s,
 *   R = ( (gamma(L) - P_{j+1}) / h,  theta(0) - ta,  theta(L) - tb,
 *         (2 mu (2k^2 - 1) - s) h^2 )                     (h = |P_{j+1} - P_j|)
 * vanish for the Hermite elastica of tension s (seed 004; sigma = 2 mu (2k^2 - 1)
 * is the tension of the curvature equation 2 kappa'' + kappa^3 - sigma kappa = 0).
 * The knot unknowns x_i are the tangent angles at the points, except at a
 * clamped end (fixed) and at a G2 end, where x is the tension of the end span.
 * The knot equations are the curvature jumps
 *   F_i = (kappa_i^- - kappa_i^+) l_i,   l_i = mean chord at P_i,
 * with kappa^- = the given curvature (0: natural) at the first point and
 * kappa^+ = the given one at the last; in length mode also
 *   G = (sum L_j - L) / L   with the common sigma unknown.
 *
 * Newton on (x, sigma, all v) at once, eliminating every piece's own five
 * unknowns (the implicit function theorem step): with J = dR/dv (5x5),
 * dR/dta = -e2, dR/dtb = -e3, dR/ds = -h^2 e4,
 *   dv = -J^{-1} R + J^{-1} e2 dta + J^{-1} e3 dtb + h^2 J^{-1} e4 ds,
 * so d kappa(0) = g0 . dv and d kappa(L) = g1 . dv (g = gradients of the end
 * curvatures in v, spline_piece.c) are linear in the x and sigma of the two
 * knots the piece joins: the knot system is tridiagonal (cyclic when closed,
 * bordered by the sigma column and the length row in length mode), solved by GSL
 * in O(n). At R = 0 the coefficients are exactly d kappa / d(angle) of the
 * Hermite piece (implicit function theorem); with R != 0 this is Newton on the
 * whole system, so pieces follow the previous iterate's branch with no inner
 * loop. Each piece's step dv is taken in its state (theta0, kappa0, kappa0',
 * sigma, L) (spline_piece.c: regular where phi, mu are polar coordinates of a
 * vanishing force). Globalisation: steps limited to a fraction of the state and
 * 0.5 rad in the angles, then halved until the merit |F|^2 + |R|^2 + G^2
 * decreases (Armijo), at most 12 halvings.
 *
 * Forces (seed 004 (9)-(10)): for the Lagrangian integral kappa^2 + sigma ds
 * with the constraint gamma' = T, the multiplier F_EL satisfies
 * 2 kappa' = F_EL . N and kappa^2 - F_EL . T = sigma (its derivative is
 * 2 kappa kappa' - kappa F_EL . N = 0; differentiating again gives the curvature
 * equation), so F_EL = (kappa^2 - sigma) T + 2 kappa' N is constant, |F_EL| = 2 mu
 * = kappa_m^2 - sigma, along phi. The batten's internal force (Kirchhoff:
 * EI kappa' = -n . N, the part after a section on the part before, EI = 2 in
 * these units) is n = -F_EL: the header's F. The first variation of the
 * energy in the angle at a point is 2 (kappa^- - kappa^+): the equations F_i = 0
 * make the spline a critical point of it (tested by finite differences).
 *
 * Start: angles of the circles through three consecutive points (natural ends:
 * the cubic's alpha = -beta/2), each piece from the linearised batten or the
 * least-energy Hermite elastica (start_pieces). If the spline's Newton fails
 * there: continuation in sigma from a high tension (the pieces are then short
 * and near the polygon) down to sigma. Length mode: pseudo-arclength
 * continuation of the tension solutions in (angles, sigma) from the free batten
 * (solve_length), since neither sigma nor the length parametrises the family
 * (flat in sigma for moderate tension, folding back when buckled).
 *
 * Internal units: lengths divided by the mean chord (S), so sigma h^2 and the
 * residuals are scale-free; pieces are rescaled on output with x0, y0 the
 * given points exactly.
 */
#include "internal.h"
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

enum { SLOT_ANGLE, SLOT_FIXED, SLOT_TENSION };
/* Newton iterations of a first attempt and of a continuation step (a solve that
 * needs more is better served by smaller steps) */
enum { DIRECT_ITER = 20, STEP_ITER = 12 };

typedef struct spline_ws {
    size_t n, m;             /* points, pieces */
    int closed;
    int lmode;               /* sigma unknown, with the border equation: */
#define BORDER_LENGTH 1      /*   the total length */
#define BORDER_ARC 2         /*   the pseudo-arclength step of solve_length */
    int kind[2];             /* open: end kinds */
    double th_end[2], kg[2]; /* clamped angles, G2 curvatures (internal units) */
    double wind;             /* closed: 2 pi times the turning number */
    double sigma, Lt;        /* common tension, target length (internal) */
    double sigma_user;       /* tension mode: the sigma asked for (user units) */
    double *x, *ell;         /* slot values, local chord per knot */
    int *slot;
    el__spiece *pc;
    double *F, *dg, *up, *lo, *b, *y, *z, *col, *row;   /* Newton work, n each */
    double *xs;              /* backup of x */
    el__spstep *ps;               /* the pieces' Newton steps */
    double Gres;             /* length residual */
    double *snapbuf;         /* the two snapshots' arrays */
    double *arc_a, *arc_x0;  /* BORDER_ARC: arc_a . (x - arc_x0) + arc_b (sigma - arc_s0) = arc_h */
    double arc_b, arc_s0, arc_h;
    double resid;            /* max residual of the last evaluation */
    int iterations, max_iter;
    double tol, aim;         /* accepted and aimed-at residual */
    int near;                /* the state is a solution to what the parametrisation resolves */
} spline_ws;

/* ------------------------------------------------------------------ the chain */

static void piece_targets(const spline_ws *w, size_t j, el__sptargets *t)
{
    const size_t n = w->n;
    t->s = w->sigma;
    t->is = w->lmode ? -2 : -1;
    /* start knot j */
    if (w->slot[j] == SLOT_ANGLE) { t->ta = w->x[j]; t->ia = (long)j; }
    else { t->ta = w->th_end[0]; t->ia = -1; }
    if (!w->closed && j == 0 && w->slot[0] == SLOT_TENSION) { t->s = w->x[0]; t->is = 0; }
    /* end knot */
    const size_t e = (j + 1) % n;
    if (w->closed && e == 0) { t->tb = w->x[0] + w->wind; t->ib = 0; }
    else if (w->slot[e] == SLOT_ANGLE) { t->tb = w->x[e]; t->ib = (long)e; }
    else { t->tb = w->th_end[1]; t->ib = -1; }
    if (!w->closed && e == n - 1 && w->slot[e] == SLOT_TENSION) { t->s = w->x[e]; t->is = (long)e; }
}

/* Evaluate every piece and the knot residuals; returns the merit (or INFINITY). */
static double chain_eval(spline_ws *w, int jac)
{
    const size_t n = w->n, m = w->m;
    double merit = 0.0, rmax = 0.0, Lsum = 0.0;
    for (size_t j = 0; j < m; j++) {
        el__sptargets t;
        piece_targets(w, j, &t);
        if (el__spiece_eval(&w->pc[j], &t, jac)) return INFINITY;
        for (int i = 0; i < EL__NV; i++) merit += w->pc[j].R[i] * w->pc[j].R[i];
        rmax = fmax(rmax, el__max_abs(w->pc[j].R, EL__NV));
        Lsum += w->pc[j].v[EL__SP_L];
    }
    for (size_t i = 0; i < n; i++) {
        if (w->slot[i] == SLOT_FIXED) { w->F[i] = 0.0; continue; }
        double km, kp;
        if (w->closed) { km = w->pc[(i + m - 1) % m].kap1; kp = w->pc[i].kap0; }
        else {
            km = i == 0 ? w->kg[0] : w->pc[i - 1].kap1;
            kp = i == n - 1 ? w->kg[1] : w->pc[i].kap0;
        }
        w->F[i] = (km - kp) * w->ell[i];
        merit += w->F[i] * w->F[i];
        rmax = fmax(rmax, fabs(w->F[i]));
    }
    w->Gres = 0.0;
    if (w->lmode == BORDER_ARC) {
        double a = w->arc_b * (w->sigma - w->arc_s0) - w->arc_h;
        for (size_t i = 0; i < n; i++) a += w->arc_a[i] * (w->x[i] - w->arc_x0[i]);
        w->Gres = a;
        merit += a * a;
        rmax = fmax(rmax, fabs(a));
    } else if (w->lmode) {
        w->Gres = (Lsum - w->Lt) / w->Lt;
        merit += w->Gres * w->Gres;
        rmax = fmax(rmax, fabs(w->Gres));
    }
    w->resid = rmax;
    return isfinite(merit) ? merit : INFINITY;
}

/* A(i, j) += v in the (cyclic) tridiagonal storage: up[i] = A(i, i+1), lo[i] = A(i+1, i),
 * and when closed up[n-1] = A(n-1, 0), lo[n-1] = A(0, n-1) (GSL's cyclic layout). */
static void tri_add(spline_ws *w, long i, long j, double v)
{
    const long last = (long)w->n - 1;
    if (j == i) w->dg[i] += v;
    else if (j == i + 1 || (w->closed && i == last && j == 0)) w->up[i] += v;
    else if (i == j + 1 || (w->closed && j == last && i == 0)) w->lo[j] += v;
}

static int tri_solve(spline_ws *w, const double *rhs, double *x)
{
    const size_t n = w->n;
    if (n == 1) { x[0] = rhs[0] / w->dg[0]; return isfinite(x[0]) ? EL_OK : EL_ESINGULAR; }
    gsl_vector_const_view d = gsl_vector_const_view_array(w->dg, n);
    gsl_vector_const_view b = gsl_vector_const_view_array(rhs, n);
    gsl_vector_view xv = gsl_vector_view_array(x, n);
    int st;
    if (w->closed) {
        gsl_vector_const_view e = gsl_vector_const_view_array(w->up, n);
        gsl_vector_const_view f = gsl_vector_const_view_array(w->lo, n);
        st = gsl_linalg_solve_cyc_tridiag(&d.vector, &e.vector, &f.vector, &b.vector, &xv.vector);
    } else {
        gsl_vector_const_view e = gsl_vector_const_view_array(w->up, n - 1);
        gsl_vector_const_view f = gsl_vector_const_view_array(w->lo, n - 1);
        st = gsl_linalg_solve_tridiag(&d.vector, &e.vector, &f.vector, &b.vector, &xv.vector);
    }
    if (st) return st == GSL_ENOMEM ? EL_ENOMEM : EL_ESINGULAR;
    return el__all_finite(x, n) ? EL_ESINGULAR : EL_OK;
}

/* One Newton direction: dx in w->y, dsigma returned in *ds. */
static int chain_direction(spline_ws *w, double *ds)
{
    const size_t n = w->n, m = w->m;
    memset(w->dg, 0, n * sizeof *w->dg);
    memset(w->up, 0, n * sizeof *w->up);
    memset(w->lo, 0, n * sizeof *w->lo);
    memset(w->col, 0, n * sizeof *w->col);
    memset(w->row, 0, n * sizeof *w->row);
    double d = 0.0, gr = -w->Gres;
    for (size_t i = 0; i < n; i++) w->b[i] = -w->F[i];
    for (size_t i = 0; i < n; i++)
        if (w->slot[i] == SLOT_FIXED) w->dg[i] = 1.0;
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        el__sptargets t;
        piece_targets(w, j, &t);
        const long rows[2] = {(long)j, (long)((j + 1) % n)};
        const double *cc[2] = {pc->c0, pc->c1};
        for (int e = 0; e < 2; e++) {   /* kappa(0) enters row j with -l, kappa(L) row j+1 with +l */
            const long r = rows[e];
            if (w->slot[r] == SLOT_FIXED) continue;
            const double sg = (e ? 1.0 : -1.0) * w->ell[r];
            const double *c = cc[e];
            w->b[r] += sg * c[0];
            if (t.ia >= 0) tri_add(w, r, t.ia, sg * c[1]);
            if (t.ib >= 0) tri_add(w, r, t.ib, sg * c[2]);
            if (t.is >= 0) tri_add(w, r, t.is, sg * c[3]);
            else if (t.is == -2) w->col[r] += sg * c[3];
        }
        if (w->lmode == BORDER_LENGTH) {
            const double iL = 1.0 / w->Lt;
            gr += pc->cL[0] * iL;
            if (t.ia >= 0) w->row[t.ia] += pc->cL[1] * iL;
            if (t.ib >= 0) w->row[t.ib] += pc->cL[2] * iL;
            if (t.is >= 0) w->row[t.is] += pc->cL[3] * iL;
            else if (t.is == -2) d += pc->cL[3] * iL;
        }
    }
    if (w->lmode == BORDER_ARC) {
        memcpy(w->row, w->arc_a, n * sizeof *w->row);
        d = w->arc_b;
    }
    int st = tri_solve(w, w->b, w->y);
    if (st) return st;
    *ds = 0.0;
    if (w->lmode) {
        if ((st = tri_solve(w, w->col, w->z))) return st;
        double ry = 0.0, rz = 0.0;
        for (size_t i = 0; i < n; i++) { ry += w->row[i] * w->y[i]; rz += w->row[i] * w->z[i]; }
        const double den = d - rz;
        if (!(fabs(den) > 1e-300)) return EL_ESINGULAR;
        *ds = (gr - ry) / den;
        for (size_t i = 0; i < n; i++) w->y[i] -= w->z[i] * *ds;
        if (!isfinite(*ds) || el__all_finite(w->y, n)) return EL_ESINGULAR;
    }
    return EL_OK;
}

/* Newton on the whole chain from the current state until the residual is at
 * most aim (or stalls), at most cap iterations (and the options' max_iter);
 * EL_OK when it ends at most accept. */
static int chain_newton(spline_ws *w, int cap, double aim, double accept)
{
    const size_t n = w->n, m = w->m;
    double merit = chain_eval(w, 1);
    if (!isfinite(merit)) return EL_ENOCONV;
    const int limit = cap < w->max_iter ? cap : w->max_iter;
    for (int it = 0; it < limit; it++) {
        if (w->resid <= aim) return EL_OK;
        double ds;
        if (chain_direction(w, &ds)) break;
        w->iterations++;
        /* step limits */
        double al = 1.0, dxm = 0.0;
        for (size_t i = 0; i < n; i++)
            if (w->slot[i] == SLOT_ANGLE) dxm = fmax(dxm, fabs(w->y[i]));
        if (dxm > 0.5) al = 0.5 / dxm;
        for (size_t i = 0; i < n; i++)
            if (w->slot[i] == SLOT_TENSION) {
                const double r = fabs(w->x[i]) + 1.0;
                if (fabs(w->y[i]) > r) al = fmin(al, r / fabs(w->y[i]));
            }
        /* piece steps dv = -D0 + D1 dta + D2 dtb + D3 ds, taken in the state */
        memcpy(w->xs, w->x, n * sizeof *w->x);
        for (size_t j = 0; j < m; j++) {
            el__spiece *pc = &w->pc[j];
            el__sptargets t;
            piece_targets(w, j, &t);
            const double dta = t.ia >= 0 ? w->y[t.ia] : 0.0, dtb = t.ib >= 0 ? w->y[t.ib] : 0.0;
            const double dsj = t.is >= 0 ? w->y[t.is] : t.is == -2 ? ds : 0.0;
            double dv[EL__NV];
            for (int i = 0; i < EL__NV; i++)
                dv[i] = -pc->D[0][i] + pc->D[1][i] * dta + pc->D[2][i] * dtb + pc->D[3][i] * dsj;
            al = el__spiece_step_prepare(pc, dv, &w->ps[j], al);
        }
        const double sigma0 = w->sigma;
        int ok = 0;
        double mnew = INFINITY;
        /* already accepted: a step that does not help is rounding, not worth halving */
        const int halvings = w->resid <= accept ? 0 : EL__SP_HALVINGS;
        for (int hv = 0; hv <= halvings; hv++, al *= 0.5) {
            for (size_t i = 0; i < n; i++) w->x[i] = w->xs[i] + al * w->y[i];
            w->sigma = sigma0 + al * ds;
            int bad = 0;
            for (size_t j = 0; j < m && !bad; j++) bad = el__spiece_step_apply(&w->pc[j], &w->ps[j], al);
            mnew = bad ? INFINITY : chain_eval(w, 1);
            if (mnew <= (1.0 - 2e-4 * al) * merit) { ok = 1; break; }
        }
        if (!ok && halvings == 0 && w->resid <= accept) break;   /* rounding: the trial is as good */
        if (!ok) {   /* restore the last accepted state */
            memcpy(w->x, w->xs, n * sizeof *w->x);
            w->sigma = sigma0;
            for (size_t j = 0; j < m; j++) memcpy(w->pc[j].v, w->ps[j].v0, sizeof w->pc[j].v);
            chain_eval(w, 1);
            break;
        }
        merit = mnew;
    }
    return w->resid <= accept ? EL_OK : EL_ENOCONV;
}

/* ------------------------------------------------------------------ start */

static double wrap_pi(double a) { return a - 2.0 * M_PI * nearbyint(a / (2.0 * M_PI)); }

/* Tangent angles: circles through three consecutive points (file comment). */
static void start_angles(spline_ws *w)
{
    const size_t n = w->n, m = w->m;
    double *c = w->b;   /* chord angles, unwrapped along the chain (m values) */
    for (size_t j = 0; j < m; j++) {
        c[j] = atan2(w->pc[j].dy, w->pc[j].dx);
        if (j) c[j] = c[j - 1] + wrap_pi(c[j] - c[j - 1]);
    }
    for (size_t i = 0; i < n; i++) {
        if (!w->closed && (i == 0 || i == n - 1)) continue;
        const el__spiece *a = &w->pc[(i + m - 1) % m], *b = &w->pc[i];
        const double A = a->h * a->h, B = b->h * b->h;
        double tx = B * a->dx + A * b->dx, ty = B * a->dy + A * b->dy;
        if (!(hypot(tx, ty) > 1e-12 * A * B)) { tx = -a->dy; ty = a->dx; }   /* a reversal */
        const double ref = i == 0 ? c[0] : c[i - 1];
        w->x[i] = ref + wrap_pi(atan2(ty, tx) - ref);
    }
    if (w->closed) {
        const double cn = c[m - 1] + wrap_pi(atan2(w->pc[0].dy, w->pc[0].dx) - c[m - 1]);
        w->wind = 2.0 * M_PI * nearbyint((cn - c[0]) / (2.0 * M_PI));
        /* the angle at point 0 seen from the last chord, then moved to chord 0's turn */
        w->x[0] = c[0] + wrap_pi(w->x[0] - c[0]);
        return;
    }
    if (w->kind[0] != EL_SPLINE_NATURAL) w->x[0] = w->th_end[0];
    if (w->kind[1] != EL_SPLINE_NATURAL) w->x[n - 1] = w->th_end[1];
    const double t1 = n > 2 ? w->x[1] : w->kind[1] != EL_SPLINE_NATURAL ? w->th_end[1] : c[0];
    const double tm = n > 2 ? w->x[n - 2] : w->kind[0] != EL_SPLINE_NATURAL ? w->th_end[0] : c[0];
    if (w->kind[0] == EL_SPLINE_NATURAL) w->x[0] = c[0] - 0.5 * (t1 - c[0]);
    if (w->kind[1] == EL_SPLINE_NATURAL) w->x[n - 1] = c[m - 1] - 0.5 * (tm - c[m - 1]);
    if (w->slot[0] == SLOT_TENSION) w->x[0] = w->sigma;
    if (w->slot[n - 1] == SLOT_TENSION) w->x[n - 1] = w->sigma;
}

/* The angles (rad) between the chord and the target tangents of a piece. */
static double chord_angle(const el__spiece *pc, const el__sptargets *t)
{
    const double c = atan2(pc->dy, pc->dx);
    return fmax(fabs(wrap_pi(t->ta - c)), fabs(wrap_pi(t->tb - c)));
}

/*
 * Every piece: where its tangents are within 0.75 rad of its chord, from the
 * linearised batten (kept if close, R <= 1e-2: the spline's Newton corrects it;
 * else solved alone, to 1e-8, or 1e-6 where nearly straight pieces under tension
 * stop, see NEAR_RESID); where they are not, or that fails, the least-energy
 * Hermite elastica with that turning (el_hermite_solve): the branch a batten
 * takes, where the linearisation can lead Newton to a loop.
 */
static int start_pieces(spline_ws *w)
{
    for (size_t j = 0; j < w->m; j++) {
        el__spiece *pc = &w->pc[j];
        el__sptargets t;
        piece_targets(w, j, &t);
        if (chord_angle(pc, &t) <= 0.75) {
            if (!el__spiece_start(pc, &t) && !el__spiece_eval(pc, &t, 0) && el__max_abs(pc->R, EL__NV) <= 1e-2) continue;
            if (!el__spiece_start(pc, &t) && (!el__spiece_newton(pc, &t, 1e-8) || el__max_abs(pc->R, EL__NV) <= 1e-6))
                continue;
        }
        int st = el__spiece_hermite(pc, &t);
        if (st == EL_ENOMEM) return st;
        if (st && chord_angle(pc, &t) > 0.75 && !el__spiece_start(pc, &t) &&
            (!el__spiece_newton(pc, &t, 1e-8) || el__max_abs(pc->R, EL__NV) <= 1e-6))
            st = EL_OK;
        if (st) return EL_ENOCONV;
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ continuation */

/* A solved state of the chain (to restore after a failed step, and the two
 * last ones for the secant predictor). */
typedef struct snapshot {
    double *x, *v, *st, sigma;
} snapshot;

static void snap_save(const spline_ws *w, snapshot *s)
{
    memcpy(s->x, w->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) {
        memcpy(s->v + j * EL__NV, w->pc[j].v, sizeof w->pc[j].v);
        memcpy(s->st + j * EL__NV, w->pc[j].st, sizeof w->pc[j].st);
    }
    s->sigma = w->sigma;
}

static void snap_load(spline_ws *w, const snapshot *s)
{
    memcpy(w->x, s->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].v, s->v + j * EL__NV, sizeof w->pc[j].v);
    w->sigma = s->sigma;
}

/* The state at f = (t - tb)/(tb - ta) beyond b on the line through a and b
 * (knot values, sigma, el__spiece states); b itself if a piece state is invalid. */
static void predict(spline_ws *w, const snapshot *a, const snapshot *b, double f)
{
    for (size_t i = 0; i < w->n; i++) w->x[i] = b->x[i] + f * (b->x[i] - a->x[i]);
    w->sigma = b->sigma + f * (b->sigma - a->sigma);
    for (size_t j = 0; j < w->m; j++) {
        double st[EL__NV];
        for (int i = 0; i < EL__NV; i++) st[i] = b->st[j * EL__NV + i] + f * (b->st[j * EL__NV + i] - a->st[j * EL__NV + i]);
        if (el__spiece_set_state(&w->pc[j], st)) { snap_load(w, b); return; }
    }
}

/* Residual of a state that is a solution up to what the parametrisation resolves
 * (header: near the separatrix, near a circle), accepted on the way. */
#define NEAR_RESID 1e-6

/*
 * Follow a one-parameter family from t = 0 (solved, in w) to t = 1: set(w, t)
 * moves the target (sigma or length); each step starts from the secant
 * predictor of the last two solutions and is corrected by Newton to NEAR_RESID
 * (the last one to aim, accepted at accept). The first step is dt; it doubles
 * after an easy success, grows by 1.3 after a slow one and halves after a
 * failure (state restored); at most max_steps steps, giving up below 1e-6.
 */
static int continuation(spline_ws *w, snapshot sv[2], int max_steps, double dt,
                        void (*set)(spline_ws *, double, const double *), const double *par,
                        double aim, double accept)
{
    double t = 0.0, tp = -1.0;
    snapshot *cur = &sv[0], *prev = &sv[1];
    snap_save(w, cur);
    for (int step = 0; step < max_steps; step++) {
        const double tn = fmin(1.0, t + dt);
        const int last = tn >= 1.0;
        if (tp >= 0.0) predict(w, prev, cur, (tn - t) / (t - tp));
        set(w, tn, par);
        const int it0 = w->iterations;
        const int st = last ? chain_newton(w, STEP_ITER, aim, accept)
                            : chain_newton(w, STEP_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
        if (st == EL_OK) {
            if (last) return EL_OK;
            snapshot *tmp = prev; prev = cur; cur = tmp;
            snap_save(w, cur);
            tp = t;
            t = tn;
            dt *= w->iterations - it0 <= 3 ? 2.0 : 1.3;
            continue;
        }
        if (last && w->resid <= NEAR_RESID) { w->near = 1; return EL_ENOCONV; }
        snap_load(w, cur);
        set(w, t, par);
        dt *= 0.5;
        if (dt < 1e-6) break;
    }
    snap_load(w, cur);
    return EL_ENOCONV;
}

/* sigma(t) between par[0] (t = 0) and par[1] geometrically in sigma + par[2]. */
static void set_sigma(spline_ws *w, double t, const double *par)
{
    const double a = par[0] + par[2], b = par[1] + par[2];
    w->sigma = t >= 1.0 ? par[1] : a * pow(b / a, t) - par[2];
}

/* L(t) from par[0] (t = 0) to par[1], geometrically in L - par[2] (the polygon's
 * length, near which the bow is small). */
static void set_length(spline_ws *w, double t, const double *par)
{
    const double a = par[0] - par[2], b = par[1] - par[2];
    w->Lt = t >= 1.0 ? par[1] : par[2] + a * pow(b / a, t);
}

/* sigma(t) linear from par[0] to par[1]. */
static void set_sigma_linear(spline_ws *w, double t, const double *par)
{
    w->sigma = t >= 1.0 ? par[1] : par[0] + t * (par[1] - par[0]);
}

static double total_length(const spline_ws *w)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[EL__SP_L];
    return L;
}

/* From the tension solution in w to the one at sigma (to NEAR_RESID); EL_OK or EL_ENOCONV. */
static int move_sigma(spline_ws *w, snapshot sv[2], int *steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    const int st = continuation(w, sv, *steps, 1.0, set_sigma_linear, par,
                                1e-3 * NEAR_RESID, NEAR_RESID);
    (*steps)--;
    return st;
}

/* Points of the pseudo-arclength path: knot values and sigma, the norm
 * weighting sigma by 1/rho. */
static double arc_dist(const spline_ws *w, const snapshot *a, const snapshot *b, double rho)
{
    double s2 = (b->sigma - a->sigma) * (b->sigma - a->sigma) / (rho * rho);
    for (size_t i = 0; i < w->n; i++) s2 += (b->x[i] - a->x[i]) * (b->x[i] - a->x[i]);
    return sqrt(s2);
}

/*
 * Length mode from a tension solution (w, at w->sigma). The length L(sigma) of
 * the tension solutions is nearly flat for moderate sigma and turns back at
 * folds (a buckled batten, sigma < 0): neither sigma nor the length is a good
 * parameter of the family, so it is followed by pseudo-arclength continuation
 * in (knot values, sigma): each step fixes the projection on the secant of
 * the last two solutions (the border row of the Newton system, instead of the
 * length), towards the target length, until the length brackets it; then
 * Newton with the length as the border equation from the interpolated state.
 * Step: doubled after an easy success, halved after a failure, at most
 * max_steps steps.
 */
static int solve_length(spline_ws *w, snapshot sv[3], int max_steps, double Lt)
{
    int steps = max_steps;
    snapshot *B = &sv[2], *C = &sv[0];   /* the base point and the next one */
    const double rho = 1.0 + fabs(w->sigma);
    double gb = total_length(w) - Lt, gc;
    snap_save(w, B);
    if (fabs(gb) > 1e-9 * Lt) {
        /* a second point: sigma moved towards the length */
        const double s1 = w->sigma + (gb < 0.0 ? -0.05 : 0.05) * rho;
        if (move_sigma(w, sv, &steps, s1)) return EL_ENOCONV;
        snap_save(w, C);
        gc = total_length(w) - Lt;
        double N = arc_dist(w, B, C, rho), h = 2.0 * N;
        while (gc * gb > 0.0 || !(N > 0.0)) {
            if (steps-- <= 0 || !(N > 0.0) || !(h > 1e-9)) return EL_ENOCONV;
            /* the secant B -> C is the tangent; C is the base of the next step */
            for (size_t i = 0; i < w->n; i++) {
                w->arc_a[i] = (C->x[i] - B->x[i]) / N;
                w->arc_x0[i] = C->x[i];
            }
            w->arc_b = (C->sigma - B->sigma) / (N * rho * rho);
            w->arc_s0 = C->sigma;
            w->arc_h = h;
            predict(w, B, C, h / N);
            w->lmode = BORDER_ARC;
            const int it0 = w->iterations;
            const int st = chain_newton(w, STEP_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
            w->lmode = 0;
            if (st) { snap_load(w, C); h *= 0.5; continue; }
            const double gn = total_length(w) - Lt;
            if (gn * gc <= 0.0) {
                /* bracketed between C and the new point D: Newton on the length from
                 * the interpolated state; if that fails, a shorter step from C */
                snapshot *D = B;
                snap_save(w, D);
                predict(w, C, D, gn / (gc - gn));
                w->lmode = BORDER_LENGTH;
                w->Lt = Lt;
                if (chain_newton(w, DIRECT_ITER, w->aim, w->tol) == EL_OK) return EL_OK;
                w->lmode = 0;
                if (steps-- <= 0) return EL_ENOCONV;
                /* B (overwritten by D) must again be the point before C: C - (D - C) scaled */
                const double back = -1.0;
                for (size_t i = 0; i < w->n; i++) D->x[i] = C->x[i] + back * (D->x[i] - C->x[i]);
                D->sigma = C->sigma + back * (D->sigma - C->sigma);
                for (size_t i = 0; i < EL__NV * w->m; i++) D->st[i] = C->st[i] + back * (D->st[i] - C->st[i]);
                N = arc_dist(w, B, C, rho);
                snap_load(w, C);
                h *= 0.25;
                continue;
            }
            snapshot *tmp = B; B = C; C = tmp;
            snap_save(w, C);
            gb = gc;
            gc = gn;
            N = arc_dist(w, B, C, rho);
            if (w->iterations - it0 <= 3) h *= 2.0;
        }
    }
    w->lmode = BORDER_LENGTH;
    w->Lt = Lt;
    return chain_newton(w, DIRECT_ITER, w->aim, w->tol);
}

/* The tension solution at w->sigma: directly, else by continuation from a high
 * tension. final: to tol (else to NEAR_RESID, as a start for the length mode). */
static int solve_tension(spline_ws *w, snapshot sv[2], int max_steps, int final)
{
    const double target = w->sigma;
    const double aim = final ? w->aim : 1e-3 * NEAR_RESID, accept = final ? w->tol : NEAR_RESID;
    start_angles(w);
    int st = start_pieces(w);
    if (st == EL_ENOMEM) return st;
    if (!st) {
        if (chain_newton(w, DIRECT_ITER, aim, accept) == EL_OK) return EL_OK;
        if (final && w->resid <= NEAR_RESID) { w->near = 1; return EL_ENOCONV; }
    }
    /* from a high tension: sigma h^2 = 40 on the mean chord (the unit here) */
    const double hi = fmax(40.0, 4.0 * target);
    w->sigma = hi;
    start_angles(w);
    if ((st = start_pieces(w))) return st == EL_ENOMEM ? st : EL_ENOCONV;
    if (chain_newton(w, DIRECT_ITER, 1e-3 * NEAR_RESID, NEAR_RESID) != EL_OK) return EL_ENOCONV;
    const double par[3] = {hi, target, 1.0};
    return continuation(w, sv, max_steps, 0.25, set_sigma, par, aim, accept);
}

/* ------------------------------------------------------------------ API */

void el_spline_options_defaults(el_spline_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    opt->mode = EL_SPLINE_TENSION;
    opt->start.kind = opt->end.kind = EL_SPLINE_NATURAL;
    opt->tol = 1e-10;
    opt->max_iter = 60;
    opt->max_steps = 60;
}

void el_spline_result_free(el_spline_result *res)
{
    if (!res) return;
    free(res->pieces); free(res->sigmas); free(res->forces); free(res->angles); free(res->curvatures);
    memset(res, 0, sizeof *res);
}

static int check_end(const el_spline_end *e)
{
    if (e->kind == EL_SPLINE_NATURAL) return EL_OK;
    if (e->kind != EL_SPLINE_TANGENT && e->kind != EL_SPLINE_G2) return EL_EINVAL;
    if (!isfinite(e->tangent[0]) || !isfinite(e->tangent[1]) ||
        !(hypot(e->tangent[0], e->tangent[1]) > 0.0))
        return EL_EINVAL;
    if (e->kind == EL_SPLINE_G2 && !isfinite(e->curvature)) return EL_EINVAL;
    return EL_OK;
}

static int check_options(const el_spline_options *o)
{
    if (o->mode == EL_SPLINE_TENSION) {
        if (!isfinite(o->sigma) || o->sigma < 0.0) return EL_EINVAL;
    } else if (o->mode == EL_SPLINE_LENGTH) {
        if (!isfinite(o->length) || !(o->length > 0.0)) return EL_EINVAL;
    } else {
        return EL_EINVAL;
    }
    if (!(o->tol >= 1e-14 && o->tol <= 1e-3) || o->max_iter < 1 || o->max_iter > 1000 ||
        o->max_steps < 1 || o->max_steps > 1000 || (o->closed != 0 && o->closed != 1))
        return EL_EINVAL;
    if (!o->closed && (check_end(&o->start) || check_end(&o->end))) return EL_EINVAL;
    return EL_OK;
}

static void ws_free(spline_ws *w)
{
    free(w->x); free(w->ell); free(w->slot); free(w->pc); free(w->F); free(w->dg); free(w->up);
    free(w->lo); free(w->b); free(w->y); free(w->z); free(w->col); free(w->row); free(w->xs);
    free(w->ps); free(w->snapbuf); free(w->arc_a); free(w->arc_x0);
}

static int ws_alloc(spline_ws *w, size_t n, size_t m)
{
    if (n > SIZE_MAX / (EL__NV * sizeof(double)) || m > SIZE_MAX / sizeof(el__spiece)) return EL_ENOMEM;
    double **arr[] = {&w->x, &w->ell, &w->F, &w->dg, &w->up, &w->lo, &w->b, &w->y, &w->z,
                      &w->col, &w->row, &w->xs, &w->arc_a, &w->arc_x0};
    for (size_t i = 0; i < sizeof arr / sizeof arr[0]; i++)
        if (!(*arr[i] = calloc(n, sizeof(double)))) return EL_ENOMEM;
    if (!(w->slot = calloc(n, sizeof *w->slot)) || !(w->pc = calloc(m, sizeof *w->pc)) ||
        !(w->ps = calloc(m, sizeof *w->ps)))
        return EL_ENOMEM;
    return EL_OK;
}

/* Collinear points in order along the line, with ends that allow the straight line. */
static int straight_line(const double *xy, size_t n, const el_spline_options *o, double *dir)
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
        if (e[i]->kind == EL_SPLINE_G2 && e[i]->curvature != 0.0) return 0;
    }
    dir[0] = atan2(uy, ux);
    return 1;
}

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

/* Fill res from the solved chain (original units), measuring the residual. */
static int make_result(const spline_ws *w, const double *xy, double S, el_spline_result *res)
{
    const size_t n = w->n, m = w->m;
    el_spline_result r;
    memset(&r, 0, sizeof r);
    r.npoints = n;
    r.npieces = m;
    r.pieces = malloc(m * sizeof *r.pieces);
    r.sigmas = malloc(m * sizeof *r.sigmas);
    r.forces = malloc(2 * m * sizeof *r.forces);
    r.angles = malloc(n * sizeof *r.angles);
    r.curvatures = malloc(n * sizeof *r.curvatures);
    double *ends = malloc(2 * m * sizeof *ends);   /* theta, kappa at each piece's end */
    if (!r.pieces || !r.sigmas || !r.forces || !r.angles || !r.curvatures || !ends) {
        el_spline_result_free(&r);
        free(ends);
        return EL_ENOMEM;
    }
    double resid = 0.0;
    /* tension mode: the given sigma exactly (not through the unit S) */
    r.sigma = w->lmode ? w->sigma / (S * S) : w->sigma_user;
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        el__sptargets t;
        piece_targets(w, j, &t);
        el_smooth_params *p = &r.pieces[j];
        p->x0 = xy[2 * j];
        p->y0 = xy[2 * j + 1];
        p->phi = pc->v[EL__SP_PHI];
        p->mu = exp(pc->v[EL__SP_NU]) / (S * S);
        p->k = pc->v[EL__SP_K];
        p->q = pc->v[EL__SP_Q];
        p->length = pc->v[EL__SP_L] * S;
        r.sigmas[j] = t.is == -1 ? r.sigma : t.s / (S * S);
        /* the residual is measured on the output, with el_smooth_eval */
        const double s2[2] = {0.0, p->length};
        double pt[4], th[2], ka[2];
        const int st = el_smooth_eval(p, 2, s2, pt, th, ka);
        if (st) { el_spline_result_free(&r); free(ends); return st; }
        const size_t e = (j + 1) % n;
        const double h = hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        resid = fmax(resid, hypot(pt[2] - xy[2 * e], pt[3] - xy[2 * e + 1]) / h);
        r.angles[j] = th[0];
        r.curvatures[j] = ka[0];
        ends[2 * j] = th[1];
        ends[2 * j + 1] = ka[1];
        if (!w->closed && j == m - 1) { r.angles[n - 1] = th[1]; r.curvatures[n - 1] = ka[1]; }
        /* F = (sigma - kappa^2) T - 2 kappa' N at s = 0 */
        const double dk = pc->dkap0 / (S * S), T[2] = {cos(th[0]), sin(th[0])};
        const double a = r.sigmas[j] - ka[0] * ka[0];
        r.forces[2 * j] = a * T[0] + 2.0 * dk * T[1];
        r.forces[2 * j + 1] = a * T[1] - 2.0 * dk * T[0];
        r.energy += pc->energy / S;
        r.length += p->length;
        r.max_curvature = fmax(r.max_curvature, piece_max_curvature(p, pc->Kq, ka[0], ka[1]));
    }
    /* the joints and the end conditions */
    for (size_t i = 0; i < n; i++) {
        const double lr = w->ell[i] * S;
        if (!w->closed && (i == 0 || i == n - 1)) {
            const int e = i == 0 ? 0 : 1;
            const double kap = r.curvatures[i];
            if (w->kind[e] == EL_SPLINE_NATURAL) resid = fmax(resid, fabs(kap) * lr);
            if (w->kind[e] == EL_SPLINE_G2) resid = fmax(resid, fabs(kap - w->kg[e] / S) * lr);
            if (w->kind[e] != EL_SPLINE_NATURAL)
                resid = fmax(resid, fabs(wrap_pi(r.angles[i] - w->th_end[e])));
            continue;
        }
        const size_t jm = (i + m - 1) % m;
        resid = fmax(resid, fabs(wrap_pi(ends[2 * jm] - r.angles[i])));
        resid = fmax(resid, fabs(ends[2 * jm + 1] - r.curvatures[i]) * lr);
    }
    free(ends);
    if (w->lmode == BORDER_LENGTH) resid = fmax(resid, fabs(r.length - w->Lt * S) / (w->Lt * S));
    r.residual = resid;
    r.iterations = w->iterations;
    *res = r;
    return EL_OK;
}

int el_spline_solve(const double *xy, size_t n, const el_spline_options *opt,
                    el_spline_result *res)
{
    if (!res) return EL_EINVAL;
    memset(res, 0, sizeof *res);
    if (!xy || !opt || n < 2 || check_options(opt)) return EL_EINVAL;
    if (n > SIZE_MAX / 4 || el__all_finite(xy, 2 * n)) return EL_EINVAL;
    el__gsl_quiet();
    const int closed = opt->closed;
    if (closed && xy[0] == xy[2 * n - 2] && xy[1] == xy[2 * n - 1]) n--;   /* a repeated start */
    if (closed && n < 3) return EL_EINVAL;
    const size_t m = closed ? n : n - 1;
    /* chords; coincident consecutive points are invalid */
    double Lp = 0.0, scale = 0.0;
    for (size_t i = 0; i < n; i++) scale = fmax(scale, fmax(fabs(xy[2 * i]), fabs(xy[2 * i + 1])));
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % n;
        const double h = hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        if (!(h > 4.0 * DBL_EPSILON * scale) || !isfinite(h)) return EL_EINVAL;
        Lp += h;
    }
    if (!isfinite(Lp)) return EL_EINVAL;
    const int lmode = opt->mode == EL_SPLINE_LENGTH;
    if (lmode && opt->length < Lp * (1.0 - 1e-14)) return EL_EDOM;
    int nten = 0;   /* G2 ends */
    if (!closed) nten = (opt->start.kind == EL_SPLINE_G2) + (opt->end.kind == EL_SPLINE_G2);
    if ((size_t)nten > m || (lmode && (size_t)nten >= m)) return EL_EDOM;

    spline_ws w;
    memset(&w, 0, sizeof w);
    int st = ws_alloc(&w, n, m);
    snapshot sv[3];
    const size_t ns = n + 2 * EL__NV * m;   /* doubles per snapshot */
    if (!st && !(w.snapbuf = malloc(3 * ns * sizeof *w.snapbuf))) st = EL_ENOMEM;
    if (st) goto done;
    for (int i = 0; i < 3; i++) {
        sv[i].x = w.snapbuf + i * ns;
        sv[i].v = sv[i].x + n;
        sv[i].st = sv[i].v + EL__NV * m;
    }
    const double S = Lp / (double)m;   /* the unit: mean chord */
    w.n = n; w.m = m; w.closed = closed; w.lmode = lmode;
    w.tol = opt->tol; w.max_iter = opt->max_iter;
    w.aim = fmax(1e-14, 0.1 * opt->tol);
    w.sigma = lmode ? 1.0 : opt->sigma * S * S;
    w.sigma_user = opt->sigma;
    w.Lt = lmode ? opt->length / S : 0.0;
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % n;
        el__spiece *pc = &w.pc[j];
        pc->dx = (xy[2 * e] - xy[2 * j]) / S;
        pc->dy = (xy[2 * e + 1] - xy[2 * j + 1]) / S;
        pc->h = hypot(pc->dx, pc->dy);
    }
    for (size_t i = 0; i < n; i++) {
        const double hl = closed || i > 0 ? w.pc[(i + m - 1) % m].h : w.pc[0].h;
        const double hr = closed || i < n - 1 ? w.pc[i % m].h : w.pc[m - 1].h;
        w.ell[i] = 0.5 * (hl + hr);
        w.slot[i] = SLOT_ANGLE;
    }
    if (!closed) {
        const el_spline_end *e[2] = {&opt->start, &opt->end};
        for (int i = 0; i < 2; i++) {
            w.kind[i] = e[i]->kind;
            if (e[i]->kind == EL_SPLINE_NATURAL) continue;
            const double c = atan2(w.pc[i ? m - 1 : 0].dy, w.pc[i ? m - 1 : 0].dx);
            w.th_end[i] = c + wrap_pi(atan2(e[i]->tangent[1], e[i]->tangent[0]) - c);
            w.kg[i] = e[i]->kind == EL_SPLINE_G2 ? e[i]->curvature * S : 0.0;
            w.slot[i ? n - 1 : 0] = e[i]->kind == EL_SPLINE_G2 ? SLOT_TENSION : SLOT_FIXED;
        }
    }

    double dir;
    if (straight_line(xy, n, opt, &dir) && (!lmode || opt->length <= Lp * (1.0 + 1e-14))) {
        for (size_t i = 0; i < n; i++) if (w.slot[i] == SLOT_ANGLE) w.x[i] = dir;
        for (size_t j = 0; j < m; j++) {
            el__spiece *pc = &w.pc[j];
            pc->v[EL__SP_PHI] = dir; pc->v[EL__SP_NU] = log(1.0 / (pc->h * pc->h));
            pc->v[EL__SP_K] = 0.0; pc->v[EL__SP_Q] = 0.0; pc->v[EL__SP_L] = pc->h;
        }
        if (w.slot[0] == SLOT_TENSION) w.x[0] = w.sigma;
        if (w.slot[n - 1] == SLOT_TENSION) w.x[n - 1] = w.sigma;
        if (lmode) { w.sigma = 0.0; w.Lt = Lp / S; }
        chain_eval(&w, 0);
        st = make_result(&w, xy, S, res);
        if (!st && lmode) res->sigma = 0.0;
        goto done;
    }

    if (!lmode) {
        st = solve_tension(&w, sv, opt->max_steps, 1);
    } else if (straight_line(xy, n, opt, &dir)) {
        /* longer than the line: Euler's buckled strip (first mode, bowed to the
         * left), theta = dir + Theta cos(pi s / D), L / D - 1 ~ Theta^2 / 4,
         * sigma = -2 (pi / D)^2 (the linearised 2 kappa'' = sigma kappa), solved
         * with a small bow (where that is accurate), then followed in length */
        const double L1 = fmin(opt->length, Lp * (1.0 + 1e-3));
        const double D = Lp / S, Th = 2.0 * sqrt(L1 / Lp - 1.0);
        double sx = 0.0;
        for (size_t i = 0; i < n; i++) {
            if (w.slot[i] == SLOT_ANGLE) w.x[i] = dir + Th * cos(M_PI * sx / D);
            if (i < m) sx += w.pc[i].h;
        }
        w.sigma = -2.0 * M_PI * M_PI / (D * D);
        if (w.slot[0] == SLOT_TENSION) w.x[0] = w.sigma;
        if (w.slot[n - 1] == SLOT_TENSION) w.x[n - 1] = w.sigma;
        st = start_pieces(&w);
        w.lmode = BORDER_LENGTH;
        w.Lt = L1 / S;
        if (!st) st = chain_newton(&w, DIRECT_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
        if (!st && opt->length > L1) {
            const double par[3] = {L1 / S, opt->length / S, Lp / S};
            st = continuation(&w, sv, opt->max_steps, 0.25, set_length, par, w.aim, w.tol);
        }
        if (st == EL_ENOCONV && w.resid <= NEAR_RESID) w.near = 1;
    } else {
        /* a tension solution, then sigma free with the length as its equation
         * (solve_length): the free batten, or where the continuation towards it
         * stopped (it need not exist) */
        w.lmode = 0;
        w.sigma = 0.0;
        st = solve_tension(&w, sv, opt->max_steps, 0);
        if (st == EL_ENOCONV && isfinite(chain_eval(&w, 1)) && w.resid <= NEAR_RESID) st = EL_OK;
        if (!st) st = solve_length(&w, sv, opt->max_steps, opt->length / S);
        if (st == EL_ENOCONV && w.lmode && w.resid <= NEAR_RESID) w.near = 1;
    }
    if (st == EL_ENOMEM) goto done;
    if (!st || w.near) {   /* a solution, or one to what the parametrisation resolves */
        const int st2 = make_result(&w, xy, S, res);
        if (st2) { st = st2; goto done; }
        if (!(res->residual <= opt->tol)) st = EL_ENOCONV;
        goto done;
    }
    /* no solution found: for sigma = 0 the free-sliding batten slides off its ducks */
    st = !lmode && opt->sigma == 0.0 ? EL_EDOM : EL_ENOCONV;
done:
    ws_free(&w);
    return st;
}

/* ------------------------------------------------------------------ B-spline */

int el_spline_to_bspline(const el_spline_result *res, double tol, int degree, el_bspline *out)
{
    if (!res) return EL_EINVAL;
    return el_smooth_chain_to_bspline(res->pieces, res->npieces, tol, degree, out);
}
