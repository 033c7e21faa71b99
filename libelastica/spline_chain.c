/*
 * The chain of an elastic spline (spline.c): its pieces and knots, evaluated
 * together, and Newton on all of them at once; its start.
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
 * kappa^+ = the given one at the last; with sigma unknown also a border
 * equation: the length G = (sum L_j - L) / L, or a pseudo-arclength step
 * (spline_path.c).
 *
 * Newton on (x, sigma, all v) at once, eliminating every piece's own five
 * unknowns (the implicit function theorem step): with J = dR/dv (5x5),
 * dR/dta = -e2, dR/dtb = -e3, dR/ds = -h^2 e4,
 *   dv = -J^{-1} R + J^{-1} e2 dta + J^{-1} e3 dtb + h^2 J^{-1} e4 ds,
 * so d kappa(0) = g0 . dv and d kappa(L) = g1 . dv (g = gradients of the end
 * curvatures in v, spline_piece.c) are linear in the x and sigma of the two
 * knots the piece joins: the knot system is tridiagonal (cyclic when closed,
 * bordered by the sigma column and the border row when sigma is unknown),
 * solved by GSL in O(n). At R = 0 the coefficients are exactly
 * d kappa / d(angle) of the Hermite piece (implicit function theorem); with
 * R != 0 this is Newton on the whole system, so pieces follow the previous
 * iterate's branch with no inner loop. Each piece's step dv is taken in its
 * state (theta0, kappa0, kappa0', sigma, L) (spline_piece.c: regular where
 * phi, mu are polar coordinates of a vanishing force). Globalisation: steps
 * limited to a fraction of the state and 0.5 rad in the angles, then halved
 * until the merit |F|^2 + |R|^2 + G^2 decreases (Armijo), at most 12 halvings.
 *
 * Start: angles of the circles through three consecutive points (natural ends:
 * the cubic's alpha = -beta/2), each piece from the linearised batten or the
 * least-energy Hermite elastica (el__chain_start_pieces).
 *
 * Units: lengths divided by the mean chord (spline.c), so sigma h^2 and the
 * residuals are scale-free.
 */
#include "internal.h"
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

double el__wrap_pi(double a) { return a - 2.0 * M_PI * nearbyint(a / (2.0 * M_PI)); }

void el__chain_targets(const el__spchain *w, size_t j, el__sptargets *t)
{
    const size_t n = w->n;
    t->s = w->sigma;
    t->is = w->lmode ? -2 : -1;
    /* start knot j */
    if (w->slot[j] == EL__SLOT_ANGLE) { t->ta = w->x[j]; t->ia = (long)j; }
    else { t->ta = w->th_end[0]; t->ia = -1; }
    /* end knot */
    const size_t e = (j + 1) % n;
    if (w->closed && e == 0) { t->tb = w->x[0] + w->wind; t->ib = 0; }
    else if (w->slot[e] == EL__SLOT_ANGLE) { t->tb = w->x[e]; t->ib = (long)e; }
    else { t->tb = w->th_end[1]; t->ib = -1; }
    t->ga = w->guide_at[j] >= 0 ? (long)w->guide[w->guide_at[j]].slot : -1;
    t->gb = w->guide_at[e] >= 0 ? (long)w->guide[w->guide_at[e]].slot : -1;
}

/* The chords of the pieces next to a guide duck, from the guides' offsets
 * (its chord's end moves along gn with a guide at its end, back with one at its start). */
static void guide_chords(el__spchain *w)
{
    for (int g = 0; g < w->ng; g++)
        for (size_t j = w->guide[g].knot - 1; j <= w->guide[g].knot; j++) {
            el__sptargets t;
            el__chain_targets(w, j, &t);
            const double d = (t.gb >= 0 ? w->x[t.gb] : 0.0) - (t.ga >= 0 ? w->x[t.ga] : 0.0);
            el__spiece *pc = &w->pc[j];
            pc->dx = pc->cx0 + d * pc->gn[0];
            pc->dy = pc->cy0 + d * pc->gn[1];
        }
}

/* Evaluate every piece and the knot residuals; returns the merit (or INFINITY). */
double el__chain_eval(el__spchain *w, int jac)
{
    const size_t n = w->n, m = w->m;
    double merit = 0.0, rmax = 0.0, Lsum = 0.0;
    /* the call's budget (spline.c's WORK_BUDGET): none made past it, the state not solved */
    if (el__spwork_spent(w->work)) { w->resid = INFINITY; return INFINITY; }
    if (w->work) w->work->evals++;
    if (w->bend)
        for (int e = 0; e < 2; e++) w->kg[e] = w->bend_k[e] + w->tau * w->bend_dk[e];
    guide_chords(w);
    for (size_t j = 0; j < m; j++) {
        el__sptargets t;
        el__chain_targets(w, j, &t);
        if (el__spiece_eval(&w->pc[j], &t, jac)) return INFINITY;
        for (int i = 0; i < EL__NV; i++) merit += w->pc[j].R[i] * w->pc[j].R[i];
        rmax = fmax(rmax, el__max_abs(w->pc[j].R, EL__NV));
        Lsum += w->pc[j].v[EL__SP_L];
    }
    for (size_t i = 0; i < n; i++) {
        if (w->slot[i] == EL__SLOT_FIXED) { w->F[i] = 0.0; continue; }
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
    if (w->lmode == EL__BORDER_ARC) {
        double a = w->arc_b * (w->sigma - w->arc_s0) - w->arc_h;
        for (size_t i = 0; i < n; i++) a += w->arc_a[i] * (w->x[i] - w->arc_x0[i]);
        if (w->arc_len) a += w->arc_c * (Lsum - w->arc_L0);
        w->Gres = a;
        merit += a * a;
        rmax = fmax(rmax, fabs(a));
    } else if (w->lmode) {
        w->Gres = (Lsum - w->Lt) / w->Lt;
        merit += w->Gres * w->Gres * w->gscale * w->gscale;
        rmax = fmax(rmax, fabs(w->Gres));
    }
    if (w->bend) {
        double a = w->bend_c * (w->tau - w->bend_t0) - w->arc_h;
        for (size_t i = 0; i < n; i++) a += w->arc_a[i] * (w->x[i] - w->arc_x0[i]);
        w->Bres = a;
        merit += a * a;
        rmax = fmax(rmax, fabs(a));
    }
    w->resid = rmax;
    return isfinite(merit) ? merit : INFINITY;
}

int el__chain_jac_current(const el__spchain *w)
{
    for (size_t j = 0; j < w->m; j++)
        if (!el__spiece_jac_current(&w->pc[j])) return 0;
    return 1;
}

/* A(i, j) += v in the (cyclic) tridiagonal storage: up[i] = A(i, i+1), lo[i] = A(i+1, i),
 * and when closed up[n-1] = A(n-1, 0), lo[n-1] = A(0, n-1) (GSL's cyclic layout). */
static void tri_add(el__spchain *w, long i, long j, double v)
{
    const long last = (long)w->n - 1;
    if (j == i) w->dg[i] += v;
    else if (j == i + 1 || (w->closed && i == last && j == 0)) w->up[i] += v;
    else if (i == j + 1 || (w->closed && j == last && i == 0)) w->lo[j] += v;
}

static int tri_solve(el__spchain *w, const double *rhs, double *x)
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

/*
 * The Newton system: T (the knot equations in the knot unknowns: tridiagonal,
 * cyclic when closed; identity at the other knots) bordered by nb <= 3 unknowns,
 * the guide offsets (border i at the knot guide[i].slot, whose equation, the
 * given curvature at that end, is the border row) and sigma (index ng, the
 * length or pseudo-arclength equation). Eliminated by the Schur complement:
 * T Y = b, T Z = C (nb columns), (B - R Z) dz = g - R Y, x = Y - Z dz: nb + 1
 * tridiagonal solves (one without a border), O(n). A piece after a guide duck
 * depends on its offset and on the angles at its two knots, so the offset
 * cannot join the tridiagonal part.
 * jac_add: A(r, c) += v, r and c a knot (routed to T, C, R or B by its border
 * index), or -1 - b for border b without a knot (sigma).
 */
static void jac_add(el__spchain *w, long r, long c, double v)
{
    const size_t n = w->n;
    const int rb = r < 0 ? (int)(-1 - r) : w->border[r], cb = c < 0 ? (int)(-1 - c) : w->border[c];
    if (rb < 0 && cb < 0) tri_add(w, r, c, v);
    else if (rb < 0) w->bcol[cb * n + r] += v;
    else if (cb < 0) w->brow[rb * n + c] += v;
    else w->bmat[rb * EL__MAX_BORDER + cb] += v;
}

/* The right-hand side of row r (a knot or -1 - b). */
static double *jac_rhs(el__spchain *w, long r)
{
    const int rb = r < 0 ? (int)(-1 - r) : w->border[r];
    return rb < 0 ? &w->b[r] : &w->bg[rb];
}

/* Determinant of the leading k x k block of the nb x nb border matrix S (row-major, stride EL__MAX_BORDER). */
static double det_lead(const double *S, int k)
{
    double a[EL__MAX_BORDER * EL__MAX_BORDER];
    int perm[EL__MAX_BORDER];
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++) a[i * k + j] = S[i * EL__MAX_BORDER + j];
    if (k == 0) return 1.0;
    if (el__lu_factor(a, k, perm)) return 0.0;
    double d = 1.0;
    for (int i = 0; i < k; i++) d *= perm[i] != i ? -a[i * k + i] : a[i * k + i];
    return d;
}

/* One Newton direction: dx in w->y (the guide offsets at their slots), dsigma in *ds. */
static int chain_direction(el__spchain *w, double *ds)
{
    const size_t n = w->n, m = w->m;
    const int nb = w->ng + (w->lmode != 0) + (w->bend != 0);
    const long SIG = -1 - w->ng;   /* sigma's column and border row */
    const long TAU = -1 - w->ng - (w->lmode != 0);   /* the bend parameter's */
    memset(w->dg, 0, n * sizeof *w->dg);
    memset(w->up, 0, n * sizeof *w->up);
    memset(w->lo, 0, n * sizeof *w->lo);
    memset(w->bcol, 0, nb * n * sizeof *w->bcol);
    memset(w->brow, 0, nb * n * sizeof *w->brow);
    memset(w->bmat, 0, sizeof w->bmat);
    for (size_t i = 0; i < n; i++) {
        w->b[i] = 0.0;
        *jac_rhs(w, (long)i) = -w->F[i];
        if (w->slot[i] != EL__SLOT_ANGLE) w->dg[i] = 1.0;   /* x_i is not in T */
    }
    if (w->lmode) w->bg[w->ng] = -w->Gres;
    if (w->bend) {   /* kg enters the end knots' rows (el__chain_eval); the pseudo-arclength row */
        w->bg[-1 - TAU] = -w->Bres;
        if (w->slot[0] != EL__SLOT_FIXED) jac_add(w, 0, TAU, w->ell[0] * w->bend_dk[0]);
        if (w->slot[n - 1] != EL__SLOT_FIXED) jac_add(w, (long)n - 1, TAU, -w->ell[n - 1] * w->bend_dk[1]);
        for (size_t i = 0; i < n; i++) jac_add(w, TAU, (long)i, w->arc_a[i]);
        jac_add(w, TAU, TAU, w->bend_c);
    }
    for (size_t j = 0; j < m; j++) {
        const el__spiece *pc = &w->pc[j];
        el__sptargets t;
        el__chain_targets(w, j, &t);
        const long rows[2] = {(long)j, (long)((j + 1) % n)};
        const double *cc[2] = {pc->c0, pc->c1};
        for (int e = 0; e < 3; e++) {   /* kappa(0) enters row j with -l, kappa(L) row j+1 with +l */
            long r;
            double sg;
            const double *c;
            if (e < 2) {
                r = rows[e];
                if (w->slot[r] == EL__SLOT_FIXED) continue;
                sg = (e ? 1.0 : -1.0) * w->ell[r];
                c = cc[e];
            } else {   /* the length, when it is the border equation */
                if (w->lmode != EL__BORDER_LENGTH && !(w->lmode == EL__BORDER_ARC && w->arc_len)) continue;
                r = SIG;
                sg = w->lmode == EL__BORDER_ARC ? w->arc_c : 1.0 / w->Lt;
                c = pc->cL;
            }
            *jac_rhs(w, r) += sg * c[0];
            if (t.ia >= 0) jac_add(w, r, t.ia, sg * c[1]);
            if (t.ib >= 0) jac_add(w, r, t.ib, sg * c[2]);
            if (t.is == -2) jac_add(w, r, SIG, sg * c[3]);
            if (t.ga >= 0) jac_add(w, r, t.ga, -sg * c[4]);
            if (t.gb >= 0) jac_add(w, r, t.gb, sg * c[4]);
        }
    }
    if (w->lmode == EL__BORDER_ARC) {
        for (size_t i = 0; i < n; i++) jac_add(w, SIG, (long)i, w->arc_a[i]);
        jac_add(w, SIG, SIG, w->arc_b);
    }
    int st = tri_solve(w, w->b, w->y);
    if (st) return st;
    *ds = 0.0;
    if (!nb) return EL_OK;
    double S[EL__MAX_BORDER * EL__MAX_BORDER], dz[EL__MAX_BORDER];
    for (int a = 0; a < nb; a++) {
        if ((st = tri_solve(w, w->bcol + a * n, w->bz + a * n))) return st;
        double ry = 0.0;
        for (size_t i = 0; i < n; i++) ry += w->brow[a * n + i] * w->y[i];
        dz[a] = w->bg[a] - ry;
    }
    for (int a = 0; a < nb; a++)
        for (int c = 0; c < nb; c++) {
            double rz = 0.0;
            for (size_t i = 0; i < n; i++) rz += w->brow[a * n + i] * w->bz[c * n + i];
            S[a * EL__MAX_BORDER + c] = w->bmat[a * EL__MAX_BORDER + c] - rz;
        }
    if (w->lmode) {   /* sigma's Schur complement: d(border residual)/d sigma along the solutions */
        const double dg = det_lead(S, w->ng);
        w->den = dg != 0.0 ? det_lead(S, w->ng + 1) / dg : 0.0;
    }
    double lu[EL__MAX_BORDER * EL__MAX_BORDER];
    int perm[EL__MAX_BORDER];
    for (int a = 0; a < nb; a++)
        for (int c = 0; c < nb; c++) lu[a * nb + c] = S[a * EL__MAX_BORDER + c];
    if (el__lu_factor(lu, nb, perm)) return EL_ESINGULAR;
    el__lu_solve(lu, nb, perm, dz);
    for (int a = 0; a < nb; a++)
        for (size_t i = 0; i < n; i++) w->y[i] -= w->bz[a * n + i] * dz[a];
    for (int g = 0; g < w->ng; g++) w->y[w->guide[g].slot] = dz[g];
    if (w->lmode) *ds = dz[w->ng];
    w->dtau = w->bend ? dz[-1 - TAU] : 0.0;
    if (!isfinite(*ds) || !isfinite(w->dtau) || el__all_finite(w->y, n)) return EL_ESINGULAR;
    return EL_OK;
}

/* The size of a Newton correction: the largest change of an angle (rad), of a
 * guide's offset over its span's chord, and of sigma relative to 1 + sigma. */
static double correction_size(const el__spchain *w, double ds)
{
    double th = fabs(ds) / (1.0 + fabs(w->sigma));
    for (size_t i = 0; i < w->n; i++)
        th = fmax(th, w->slot[i] == EL__SLOT_GUIDE ? fabs(w->y[i]) / w->guide[w->border[i]].h
                                                   : fabs(w->y[i]));
    return th;
}

/*
 * A known state evaluated again: a snapshot of a solution just loaded, el__chain_newton's
 * restore of its last accepted iterate. Its pieces' derived data (Kq, energy, dkap0, the
 * Jacobians) are the last evaluation's, of another state, until it is evaluated: refused
 * past the call's budget (WORK_BUDGET), the caller returned EL_OK with them stale, read by
 * make_result's max_curvature, energy and forces and the stability check (revF 4, 5). Made
 * past the budget, each counted in work->evals: one after each search, whose own next
 * evaluation the budget refuses, so a call spends a few evaluations past it at most.
 */
double el__chain_reeval(el__spchain *w, int jac)
{
    el__spwork *k = w->work;
    if (!k || !el__spwork_spent(k)) return el__chain_eval(w, jac);
    w->work = NULL;
    const double merit = el__chain_eval(w, jac);
    w->work = k;
    k->evals++;
    return merit;
}

/*
 * Newton on the whole chain from the current state until the residual is at
 * most aim (or stalls), at most cap iterations (and the options' max_iter);
 * EL_OK when it ends at most accept.
 * w->contract: Newton trusted only while it contracts (Deuflhard's restricted
 * monotonicity): each correction at most (1 - al/2) times the one before (al:
 * the fraction of it taken), no step halved for the merit, and the derivative
 * of the border equation in sigma along the solutions (the Schur complement
 * den) of one sign (no fold crossed); else EL_ENOCONV at once. In length mode
 * the length residual then enters the merit divided by |den| at the start (at
 * least 1): in units of sigma, the unknown it moves. A length nearly flat in
 * sigma (many points) otherwise weighs a change of sigma h^2 ~ 1 as 1e-10 and
 * Armijo refuses the step it needs.
 */
int el__chain_newton(el__spchain *w, int cap, double aim, double accept)
{
    const size_t n = w->n, m = w->m;
    w->gscale = 1.0;
    double merit = el__chain_eval(w, 1);
    if (!isfinite(merit)) return EL_ENOCONV;
    const int limit = cap < w->max_iter ? cap : w->max_iter;
    double bound = INFINITY, den0 = 0.0;
    for (int it = 0; it < limit; it++) {
        if (w->resid <= aim) return EL_OK;
        if (el__spwork_spent(w->work)) break;   /* WORK_BUDGET spent (spline.c): no iteration */
        double ds;
        if (chain_direction(w, &ds)) break;
        w->iterations++;
        double size = 0.0;
        if (w->contract) {
            size = correction_size(w, ds);
            if (it == 0) {
                den0 = w->den;
                if (w->lmode == EL__BORDER_LENGTH) {
                    merit -= w->Gres * w->Gres;
                    w->gscale = fmin(fmax(1.0, 1.0 / fabs(den0)), 1e8);
                    merit += w->Gres * w->Gres * w->gscale * w->gscale;
                }
            }
            if (size > bound || (w->lmode && !(w->den * den0 > 0.0))) break;
        }
        /* step limits */
        double al = 1.0, dxm = 0.0;
        for (size_t i = 0; i < n; i++)
            if (w->slot[i] == EL__SLOT_ANGLE) dxm = fmax(dxm, fabs(w->y[i]));
        if (dxm > 0.5) al = 0.5 / dxm;
        for (size_t i = 0; i < n; i++)   /* a guide moves at most a quarter of its span's chord */
            if (w->slot[i] == EL__SLOT_GUIDE) {
                const double r = 0.25 * w->guide[w->border[i]].h;
                if (fabs(w->y[i]) > r) al = fmin(al, r / fabs(w->y[i]));
            }
        /* piece steps dv = -D0 + D1 dta + D2 dtb + D3 ds, taken in the state */
        memcpy(w->xs, w->x, n * sizeof *w->x);
        for (size_t j = 0; j < m; j++) {
            el__spiece *pc = &w->pc[j];
            el__sptargets t;
            el__chain_targets(w, j, &t);
            const double dta = t.ia >= 0 ? w->y[t.ia] : 0.0, dtb = t.ib >= 0 ? w->y[t.ib] : 0.0;
            const double dsj = t.is == -2 ? ds : 0.0;
            const double dg = (t.gb >= 0 ? w->y[t.gb] : 0.0) - (t.ga >= 0 ? w->y[t.ga] : 0.0);
            double dv[EL__NV];
            for (int i = 0; i < EL__NV; i++)
                dv[i] = -pc->D[0][i] + pc->D[1][i] * dta + pc->D[2][i] * dtb + pc->D[3][i] * dsj +
                        (dg != 0.0 ? pc->D[4][i] * dg : 0.0);
            al = el__spiece_step_prepare(pc, dv, &w->ps[j], al);
        }
        const double sigma0 = w->sigma, tau0 = w->tau;
        int ok = 0;
        double mnew = INFINITY;
        /* already accepted: a step that does not help is rounding, not worth halving */
        const int halvings = w->resid <= accept || w->contract ? 0 : w->halvings;
        for (int hv = 0; hv <= halvings; hv++, al *= 0.5) {
            for (size_t i = 0; i < n; i++) w->x[i] = w->xs[i] + al * w->y[i];
            w->sigma = sigma0 + al * ds;
            if (w->bend) w->tau = tau0 + al * w->dtau;
            int bad = 0;
            for (size_t j = 0; j < m && !bad; j++) bad = el__spiece_step_apply(&w->pc[j], &w->ps[j], al);
            mnew = bad ? INFINITY : el__chain_eval(w, 1);
            if (mnew <= (1.0 - 2e-4 * al) * merit) { ok = 1; break; }
        }
        if (!ok && halvings == 0 && w->resid <= accept) break;   /* rounding: the trial is as good */
        if (!ok) {   /* restore the last accepted state */
            memcpy(w->x, w->xs, n * sizeof *w->x);
            w->sigma = sigma0;
            w->tau = tau0;
            for (size_t j = 0; j < m; j++) memcpy(w->pc[j].v, w->ps[j].v0, sizeof w->pc[j].v);
            el__chain_reeval(w, 1);
            break;
        }
        merit = mnew;
        bound = (1.0 - 0.5 * al) * size;
    }
    return w->resid <= accept ? EL_OK : EL_ENOCONV;
}

/* ------------------------------------------------------------------ start */

/* Tangent angles: circles through three consecutive points (file comment). */
void el__chain_start_angles(el__spchain *w)
{
    const size_t n = w->n, m = w->m;
    double *c = w->b;   /* chord angles, unwrapped along the chain (m values) */
    for (size_t j = 0; j < m; j++) {
        c[j] = atan2(w->pc[j].dy, w->pc[j].dx);
        if (j) c[j] = c[j - 1] + el__wrap_pi(c[j] - c[j - 1]);
    }
    for (size_t i = 0; i < n; i++) {
        if (!w->closed && (i == 0 || i == n - 1)) continue;
        const el__spiece *a = &w->pc[(i + m - 1) % m], *b = &w->pc[i];
        const double A = a->h * a->h, B = b->h * b->h;
        double tx = B * a->dx + A * b->dx, ty = B * a->dy + A * b->dy;
        if (!(hypot(tx, ty) > 1e-12 * A * B)) { tx = -a->dy; ty = a->dx; }   /* a reversal */
        const double ref = i == 0 ? c[0] : c[i - 1];
        w->x[i] = ref + el__wrap_pi(atan2(ty, tx) - ref);
    }
    if (w->closed) {
        const double cn = c[m - 1] + el__wrap_pi(atan2(w->pc[0].dy, w->pc[0].dx) - c[m - 1]);
        w->wind = 2.0 * M_PI * nearbyint((cn - c[0]) / (2.0 * M_PI));
        /* the angle at point 0 seen from the last chord, then moved to chord 0's turn */
        w->x[0] = c[0] + el__wrap_pi(w->x[0] - c[0]);
        return;
    }
    if (w->kind[0] != EL_SPLINE_NATURAL) w->x[0] = w->th_end[0];
    if (w->kind[1] != EL_SPLINE_NATURAL) w->x[n - 1] = w->th_end[1];
    const double t1 = n > 2 ? w->x[1] : w->kind[1] != EL_SPLINE_NATURAL ? w->th_end[1] : c[0];
    const double tm = n > 2 ? w->x[n - 2] : w->kind[0] != EL_SPLINE_NATURAL ? w->th_end[0] : c[0];
    if (w->kind[0] == EL_SPLINE_NATURAL) w->x[0] = c[0] - 0.5 * (t1 - c[0]);
    if (w->kind[1] == EL_SPLINE_NATURAL) w->x[n - 1] = c[m - 1] - 0.5 * (tm - c[m - 1]);
}

void el__chain_taut_angles(el__spchain *w)
{
    const size_t n = w->n, m = w->m;
    el__chain_start_angles(w);   /* the winding, clamped ends, and the unwrapping reference */
    for (size_t i = 0; i < n; i++) {
        if (!w->closed && (i == 0 || i == n - 1)) continue;
        const el__spiece *a = &w->pc[(i + m - 1) % m], *b = &w->pc[i];
        double tx = a->dx / a->h + b->dx / b->h, ty = a->dy / a->h + b->dy / b->h;
        if (!(hypot(tx, ty) > 1e-12)) { tx = -a->dy; ty = a->dx; }   /* a reversal */
        w->x[i] += el__wrap_pi(atan2(ty, tx) - w->x[i]);
    }
    if (w->closed) return;
    if (w->kind[0] == EL_SPLINE_NATURAL) w->x[0] = atan2(w->pc[0].dy, w->pc[0].dx);
    if (w->kind[1] == EL_SPLINE_NATURAL)
        w->x[n - 1] = w->x[n - 2] + el__wrap_pi(atan2(w->pc[m - 1].dy, w->pc[m - 1].dx) - w->x[n - 2]);
}

/* The angles (rad) between the chord and the target tangents of a piece. */
static double chord_angle(const el__spiece *pc, const el__sptargets *t)
{
    const double c = atan2(pc->dy, pc->dx);
    return fmax(fabs(el__wrap_pi(t->ta - c)), fabs(el__wrap_pi(t->tb - c)));
}

/*
 * Every piece: where its tangents are within 0.75 rad of its chord, from the
 * linearised batten (kept if close, R <= 1e-2: the spline's Newton corrects it;
 * else solved alone, to 1e-8, or 1e-6 where nearly straight pieces under tension
 * stop, see EL__SP_NEAR); where they are not, or that fails, the least-energy
 * Hermite elastica with that turning (el_hermite_solve): the branch a batten
 * takes, where the linearisation can lead Newton to a loop.
 * A start counts as one evaluation of the call's budget (WORK_BUDGET, spline.c) and none is
 * made once it is spent: its per-piece Newton and Hermite solves ran uncounted after it (the
 * fuzz's hang 9291f637: 5446 Hermite solves past the budget, 10 % of its time; revF 6).
 */
int el__chain_start_pieces(el__spchain *w)
{
    if (el__spwork_spent(w->work)) return EL_ENOCONV;
    if (w->work) w->work->evals++;
    for (size_t j = 0; j < w->m; j++) {
        el__spiece *pc = &w->pc[j];
        el__sptargets t;
        el__chain_targets(w, j, &t);
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

/* ------------------------------------------------------------------ workspace */

/* Release the workspace (also after a failed el__chain_alloc). */
void el__chain_free(el__spchain *w)
{
    free(w->x); free(w->ell); free(w->slot); free(w->pc); free(w->F); free(w->dg); free(w->up);
    free(w->lo); free(w->b); free(w->y); free(w->z); free(w->bcol); free(w->brow); free(w->bz);
    free(w->xs); free(w->ps); free(w->snapbuf); free(w->arc_a); free(w->arc_x0);
    free(w->guide_at); free(w->border);
}

/* The workspace of n knots and m pieces (zeroed first), with three snapshots
 * of n knot values and m pieces' v and state each. EL_ENOMEM. */
int el__chain_alloc(el__spchain *w, size_t n, size_t m)
{
    memset(w, 0, sizeof *w);
    if (n > SIZE_MAX / (8 * EL__NV * sizeof(double)) || m > n) return EL_ENOMEM;
    double **arr[] = {&w->x, &w->ell, &w->F, &w->dg, &w->up, &w->lo, &w->b, &w->y, &w->z,
                      &w->xs, &w->arc_a, &w->arc_x0};
    for (size_t i = 0; i < sizeof arr / sizeof arr[0]; i++)
        if (!(*arr[i] = calloc(n, sizeof(double)))) return EL_ENOMEM;
    double **border[] = {&w->bcol, &w->brow, &w->bz};
    for (size_t i = 0; i < 3; i++)
        if (!(*border[i] = calloc(EL__MAX_BORDER * n, sizeof(double)))) return EL_ENOMEM;
    if (!(w->guide_at = malloc(n * sizeof *w->guide_at)) || !(w->border = malloc(n * sizeof *w->border)))
        return EL_ENOMEM;
    for (size_t i = 0; i < n; i++) { w->guide_at[i] = -1; w->border[i] = -1; }
    const size_t ns = n + 2 * EL__NV * m;   /* doubles per snapshot */
    if (!(w->slot = calloc(n, sizeof *w->slot)) || !(w->pc = calloc(m, sizeof *w->pc)) ||
        !(w->ps = calloc(m, sizeof *w->ps)) || !(w->snapbuf = malloc(3 * ns * sizeof *w->snapbuf)))
        return EL_ENOMEM;
    for (int i = 0; i < 3; i++) {
        w->snap[i].x = w->snapbuf + i * ns;
        w->snap[i].v = w->snap[i].x + n;
        w->snap[i].st = w->snap[i].v + EL__NV * m;
    }
    w->n = n;
    w->m = m;
    w->resid = INFINITY;   /* not evaluated yet: no state is a solution */
    w->halvings = EL__SP_HALVINGS;
    return EL_OK;
}
