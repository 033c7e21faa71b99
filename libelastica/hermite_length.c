/*
 * Hermite interpolation for a given length: the tension solutions followed along sigma.
 */
#include "hermite_internal.h"
#include <stdlib.h>

/* ------------------------------------------------------------ length mode */

/* Newton on (x, sigma) for f = 0, L = Lt with a finite-difference Jacobian. */
static int newton_length(hprob *pr, int b, double Lt, double x, double sg, hroot *res)
{
    hprob q = *pr;
    hstate st;
    double r0 = INFINITY;
    for (int it = 0; it < 30; it++) {
        q.sigma = sg;
        if (el__hermite_full_eval(&q, x, b, &st)) return EL_EDOM;
        const double g0 = st.f, h0 = (st.L - Lt) / Lt, r = fabs(g0) + fabs(h0);
        if (r < 1e-14) break;
        if (it > 0 && r >= r0 && r < 1e-11) break;
        r0 = r;
        const double hx = 1e-7 * (1.0 + fabs(x)), hs = 1e-7 * (1.0 + fabs(sg));
        hstate a, c;
        if (el__hermite_full_eval(&q, x + hx, b, &a)) { if (el__hermite_full_eval(&q, x - hx, b, &a)) return EL_EDOM; a.f = 2 * g0 - a.f; a.L = 2 * st.L - a.L; }
        q.sigma = sg + hs;
        if (el__hermite_full_eval(&q, x, b, &c)) return EL_EDOM;
        q.sigma = sg;
        const double J11 = (a.f - g0) / hx, J12 = (c.f - g0) / hs;
        const double J21 = (a.L - st.L) / (Lt * hx), J22 = (c.L - st.L) / (Lt * hs);
        const double det = J11 * J22 - J12 * J21;
        if (!(fabs(det) > 0.0) || !isfinite(det)) return EL_EDOM;
        double dx = -(J22 * g0 - J12 * h0) / det, ds = -(-J21 * g0 + J11 * h0) / det;
        /* trust region: the objective is only piecewise smooth (class changes, branch ends) */
        const double lim = fmax(fabs(dx) / (0.2 * (1.0 + fabs(x))), fabs(ds) / (0.2 * (1.0 + fabs(sg))));
        if (lim > 1.0) { dx /= lim; ds /= lim; }
        /* damping: halve until the residual decreases */
        int accepted = 0;
        for (int h = 0; h < 12; h++) {
            q.sigma = sg + ds;
            hstate t;
            if (!el__hermite_full_eval(&q, x + dx, b, &t) && fabs(t.f) + fabs((t.L - Lt) / Lt) < r) {
                x += dx;
                sg += ds;
                accepted = 1;
                break;
            }
            dx *= 0.5;
            ds *= 0.5;
        }
        q.sigma = sg;
        if (!accepted) break;
    }
    q.sigma = sg;
    if (el__hermite_full_eval(&q, x, b, &st)) return EL_EDOM;
    if (!(fabs(st.f) < 1e-9 && fabs(st.L - Lt) < 1e-9 * Lt)) return EL_ENOCONV;
    res->x = x;
    res->b = b;
    res->sigma = sg;
    res->st = st;
    return EL_OK;
}

/* sigma range of length-mode solutions (normalised |P| = 1, length Lt > 1):
 * sigma >= -(C0/Lt)^2 (Theorem 9 bound, sigma <= 0 case); and since
 * |P| >= <P, -F/|F|> = L - 2 int dn^2(u) ds >= L - 2 I / sqrt(mu) with I <= 2 pi the
 * integral of dn^2 over one period, mu <= (4 pi / (Lt - 1))^2 and
 * sigma = 2 mu (2k^2 - 1) <= 2 mu for k <= 1; for k > 1 likewise with
 * nu = k^2 mu <= (4 / (Lt - 1))^2 and sigma <= 4 nu. */
static void sigma_range(double Lt, double *lo, double *hi)
{
    const double c = C0_PERIOD / Lt, e = Lt - 1.0;
    *lo = -c * c;
    *hi = fmax(32.0 * M_PI * M_PI / (e * e), 64.0 / (e * e));
}

static int cmp_root(const void *a, const void *b)
{
    const hroot *x = a, *y = b;
    if (x->b != y->b) return x->b - y->b;
    return (x->x > y->x) - (x->x < y->x);
}

/* All tension solutions on the line sigma = sinh(t), sorted by branch and x. */
static int sigma_line(const hprob *pr, double t, int ns, hrootlist *l)
{
    hprob q = *pr;
    q.sigma = sinh(t);
    q.Lmin = 1.0;
    l->n = 0;
    int rc = el__hermite_solve_tension(&q, ns, l);
    if (!rc && l->n > 1) qsort(l->v, l->n, sizeof *l->v, cmp_root);
    return rc;
}

/* Neighbours on one line with L - Lt of opposite signs (a fold of the curve
 * between lines): Newton from their midpoint. */
static int line_pairs(hprob *pr, double Lt, const hrootlist *l, hrootlist *out)
{
    int rc = EL_OK;
    for (size_t a = 0; a + 1 < l->n && !rc; a++) {
        const hroot *ra = &l->v[a], *rb = &l->v[a + 1];
        if ((ra->st.L - Lt) * (rb->st.L - Lt) > 0.0) continue;
        hroot r;
        if (!newton_length(pr, ra->b, Lt, 0.5 * (ra->x + rb->x), ra->sigma, &r)) rc = el__hermite_roots_push(out, &r);
        if (!rc && rb->b != ra->b && !newton_length(pr, rb->b, Lt, 0.5 * (ra->x + rb->x), ra->sigma, &r))
            rc = el__hermite_roots_push(out, &r);
    }
    return rc;
}

/* Between the lines ta < tb: where the number of solutions changes (folds) the
 * strip is halved (depth <= 6); then every pair (root on a, root on b) with
 * L - Lt of opposite signs starts Newton from the interpolated point (the two
 * roots of (17) join where (18) vanishes, so a curve may change branch). */
static int strip_pairs(hprob *pr, double Lt, int ns, double ta, const hrootlist *A,
                       double tb, const hrootlist *B, int depth, hrootlist *out)
{
    int rc = EL_OK;
    if (A->n != B->n && depth < 6) {
        hrootlist M = {NULL, 0, 0};
        const double tm = 0.5 * (ta + tb);
        if (!(rc = sigma_line(pr, tm, ns, &M)) && !(rc = line_pairs(pr, Lt, &M, out)) &&
            !(rc = strip_pairs(pr, Lt, ns, ta, A, tm, &M, depth + 1, out)))
            rc = strip_pairs(pr, Lt, ns, tm, &M, tb, B, depth + 1, out);
        free(M.v);
        return rc;
    }
    for (size_t a = 0; a < A->n && !rc; a++)
        for (size_t c = 0; c < B->n && !rc; c++) {
            const hroot *ra = &A->v[a], *rb = &B->v[c];
            const double ha = ra->st.L - Lt, hb = rb->st.L - Lt;
            if (ha * hb > 0.0) continue;
            const double t = ha == hb ? 0.5 : ha / (ha - hb);
            const double x0 = ra->x + t * (rb->x - ra->x), s0 = ra->sigma + t * (rb->sigma - ra->sigma);
            hroot r;
            /* from the interpolated point, else from the nearer of the two roots (on the curve) */
            if (!newton_length(pr, ra->b, Lt, x0, s0, &r)) rc = el__hermite_roots_push(out, &r);
            else if (!newton_length(pr, ra->b, Lt, t < 0.5 ? ra->x : rb->x, t < 0.5 ? ra->sigma : rb->sigma, &r))
                rc = el__hermite_roots_push(out, &r);
            if (!rc && rb->b != ra->b && !newton_length(pr, rb->b, Lt, x0, s0, &r))
                rc = el__hermite_roots_push(out, &r);
        }
    return rc;
}

/* Length mode: on ng + 1 lines sigma_j (asinh-spaced over sigma_range) all tension
 * solutions are computed (above); the solution curves are continuous in sigma, so
 * a curve crossing L = Lt shows as a sign change of L - Lt between lines (or
 * between neighbours on one line near a fold), and starts Newton on (x, sigma). */
int el__hermite_solve_length(hprob *pr, double Lt, int ng, int ns, hrootlist *out)
{
    double slo, shi;
    sigma_range(Lt, &slo, &shi);
    const double tlo = asinh(slo), thi = asinh(shi);
    hrootlist prev = {NULL, 0, 0}, cur = {NULL, 0, 0};
    int rc = EL_OK;
    double tprev = tlo;
    for (int j = 0; j <= ng && !rc; j++) {
        const double t = tlo + (thi - tlo) * j / ng;
        if ((rc = sigma_line(pr, t, ns, &cur)) || (rc = line_pairs(pr, Lt, &cur, out))) break;
        if (j > 0 && (rc = strip_pairs(pr, Lt, ns, tprev, &prev, t, &cur, 0, out))) break;
        hrootlist tmp = prev;
        prev = cur;
        cur = tmp;
        tprev = t;
    }
    free(prev.v);
    free(cur.v);
    return rc;
}

