/*
 * The tolerance-certified B-spline approximation of a smooth elastica segment
 * (issue 4): el_smooth_to_bspline, its G2 variant and el_smooth_chain_to_bspline
 * (pieces joined C2 by bspline.c's knot removal). This file chooses the knots and
 * drives the search; bspline_approx_fit.c fits the poles on a grid of exact samples
 * and certifies the distance (its file comment).
 *
 * Approximation of an elastica (el_smooth_to_bspline):
 *  - the B-spline is parametrised by the arc length s of the elastica on
 *    [0, length], clamped, simple interior knots (C^{p-1});
 *  - poles by linear least squares on a uniform grid of exact samples, both ends
 *    interpolated with the elastica's tangent (and curvature for the G2 variant)
 *    (el__approx_poles);
 *  - knots: a degree-p spline's error on a span h is about c h^{p+1}
 *    |gamma^(p+1)|, so knots equidistribute the integral of
 *    g = |gamma^(p+1)|^{1/(p+1)}, computed exactly from the pendulum equation
 *    of the tangent angle (density()); the number of spans N is found by
 *    scaling with the error ratio and bisection; then the knots are moved by
 *    the measured span errors (correction(), accumulated over the tries, which
 *    also gives the end spans the extra density their fixed end poles need),
 *    from the smallest failing N downwards by the error ratio and bisection;
 *  - the result is certified (el__approx_certify: an upper bound of the Hausdorff
 *    distance within rounding of it), reported as max_deviation. If it exceeds
 *    tol, the search is redone with a lower target for the sampled error, and
 *    knots are inserted as a last resort.
 * Cost (issue 4 asks <= 1 ms at 1e-6 L, degree 3): about seven least-squares
 * fits on ~1000 samples dominate (bspline_approx_fit.c says how they are kept
 * cheap); the final certified fit reuses the poles of the search's last passing
 * fit when knots and grid are the same (no refit).
 */
#include "bspline_approx.h"
#include <stdlib.h>
#include <string.h>

/*
 * Knot density from the curve itself. With psi = theta - phi the elastica is
 * the pendulum psi'' = -mu sin psi (kappa' = -2k mu sn dn = -mu sin(theta-phi),
 * from k sn = sin a, dn = cos a, a = psi/2). Taylor coefficients at s0 by the
 * recurrences of automatic differentiation (S = sin psi, C = cos psi):
 *   S_j = (1/j) sum_{m=1..j} m psi_m C_{j-m},  C_j = -(1/j) sum m psi_m S_{j-m},
 *   (j+2)(j+1) psi_{j+2} = -mu S_j,  psi_0 = theta - phi, psi_1 = kappa;
 * gamma' = e^{i phi} (C + i S), so |gamma^(p+1)(s0)| = p! |C_p + i S_p|. A
 * degree-p spline's error on a span h is about c h^{p+1} |gamma^(p+1)|, so
 * knots equidistributing the integral of g = |gamma^(p+1)|^{1/(p+1)} (plus 5 %
 * of its mean so that no span becomes huge where it vanishes) make the span
 * errors about equal. g: M+1 values of the density, G: M+1 cumulative values
 * (trapezoid rule).
 */
static void cumulate(const fit_ws *w, const double *g, const double *corr, double *G);

FIT_INLINE void density_p(const fit_ws *w, double *g, const int p)
{
    double fact = 1.0;
    for (int j = 2; j <= p; j++) fact *= j;
    const double cphi = cos(w->par->phi), sphi = sin(w->par->phi);
    for (size_t i = 0; i <= w->M; i++) {
        double psi[MAXDEG_FIT + 3], S[MAXDEG_FIT + 3], C[MAXDEG_FIT + 3];   /* +1: unrolling */
        psi[1] = w->ka[i];
        /* sin, cos of psi_0 = theta - phi from the grid's cos, sin theta */
        S[0] = w->cs[2 * i + 1] * cphi - w->cs[2 * i] * sphi;
        C[0] = w->cs[2 * i] * cphi + w->cs[2 * i + 1] * sphi;
        FIT_UNROLL for (int j = 1; j <= p; j++) {
            if (j + 1 <= p) psi[j + 1] = -w->par->mu * S[j - 1] / ((double)(j + 1) * j);
            double sa = 0.0, ca = 0.0;
            FIT_UNROLL for (int m = 1; m <= j; m++) {
                sa += m * psi[m] * C[j - m];
                ca -= m * psi[m] * S[j - m];
            }
            S[j] = sa / j;
            C[j] = ca / j;
        }
        const double d = fact * sqrt(C[p] * C[p] + S[p] * S[p]);
        g[i] = p == 3 ? sqrt(sqrt(d)) : pow(d, 1.0 / (p + 1));
    }
}

/* Returns 1 for a line (g = 0: no scale of its own, the knots uniform). */
static int density(const fit_ws *w, double *g, double *G)
{
    if (w->p == 3) density_p(w, g, 3);
    else density_p(w, g, w->p);
    double mean = 0.0;
    for (size_t i = 0; i <= w->M; i++) mean += g[i];
    mean /= (double)(w->M + 1);
    for (size_t i = 0; i <= w->M; i++) g[i] = mean > 0.0 ? g[i] + 0.05 * mean : 1.0;   /* 0: a line */
    cumulate(w, g, NULL, G);
    return !(mean > 0.0);
}

/* G = cumulative integral of g, times the per-grid-point factor cm[i] when cm
 * is given (the accumulated corrections of the knot moving). */
static void cumulate(const fit_ws *w, const double *g, const double *cm, double *G)
{
    const double h = w->L / (double)w->M;
    double acc = 0.0, prev = g[0] * (cm ? cm[0] : 1.0);
    G[0] = 0.0;
    for (size_t i = 1; i <= w->M; i++) {
        const double gi = g[i] * (cm ? cm[i] : 1.0);
        acc += 0.5 * (prev + gi) * h;
        prev = gi;
        G[i] = acc;
    }
}

/*
 * Correction of the density by the last fit's span errors: the density of span
 * j is multiplied by (e_j / mean e)^{1/(p+1)}, clamped to [1/2, 2], so that
 * equidistribution moves knots towards the spans with the larger errors.
 */
static void correction(const fit_ws *w, size_t N, double *corr)
{
    const double ex = 1.0 / (w->p + 1);
    double mean = 0.0;
    for (size_t j = 0; j < N; j++) mean += pow(w->err[j], ex);
    mean /= (double)N;
    for (size_t j = 0; j < N; j++)
        corr[j] = mean > 0.0 ? fmin(fmax(pow(w->err[j], ex) / mean, 0.5), 2.0) : 1.0;
}

/* breaks[0..N] equidistributing G on the grid; EL_ESINGULAR if two coincide. */
static int breaks_for(const fit_ws *w, const double *G, size_t N, double *breaks)
{
    const double tot = G[w->M];
    breaks[0] = 0.0;
    breaks[N] = w->L;
    size_t i = 0;
    for (size_t j = 1; j < N; j++) {
        const double target = tot * (double)j / (double)N;
        while (i + 1 < w->M && G[i + 1] < target) i++;
        const double f = fmin(fmax((target - G[i]) / (G[i + 1] - G[i]), 0.0), 1.0);
        breaks[j] = w->s[i] + f * (w->s[i + 1] - w->s[i]);
        if (!(breaks[j] > breaks[j - 1])) return EL_ESINGULAR;
    }
    return breaks[N] > breaks[N - 1] ? EL_OK : EL_ESINGULAR;
}

static int emit(const fit_ws *w, size_t N, const double *breaks, const double *poles,
                double dev, el_bspline *out)
{
    const size_t n = N + (size_t)w->p;
    el_bspline b;
    int st = el_bspline_alloc(&b, w->p, 2, n, N + 1);
    if (st) return st;
    memcpy(b.poles, poles, 2 * n * sizeof *poles);
    for (size_t j = 0; j <= N; j++) { b.knots[j] = breaks[j]; b.mults[j] = 1; }
    b.knots[N] = w->L;
    b.mults[0] = b.mults[N] = w->p + 1;
    b.max_deviation = dev;
    *out = b;
    return EL_OK;
}

/* el_smooth_to_bspline with nfix poles fixed at each end (2: G1 ends, 3: G2 ends). */
static int smooth_to_bspline(const el_smooth_params *par_in, double tol, int degree, int nfix,
                             el_bspline *out)
{
    if (!out || el_smooth_check(par_in) || !isfinite(tol) || !(tol > 0.0) || degree < 3 ||
        degree > MAXDEG_FIT)
        return EL_EINVAL;
    el__gsl_quiet();
    /* A huge angle phi: the same curve with phi in [-pi, pi]. el_smooth_eval rotates the
     * points by cos, sin phi (exact for any phi) but returns the tangent angle as phi plus
     * the shape's own turning, which rounds to ~1e-16 |phi| (phi = -3e305: a constant
     * tangent), and the approximation steers by it (fuzz: 12 s of CPU, 92 poles for a
     * curve that takes 65). atan2(sin, cos) keeps cos and sin phi to rounding; below
     * 1e6 (turning exact to 1e-10) phi is kept, so the end poles stay el_smooth_eval's
     * end points bit for bit. */
    el_smooth_params reduced = *par_in;
    if (fabs(reduced.phi) > 1e6) reduced.phi = atan2(sin(reduced.phi), cos(reduced.phi));
    const el_smooth_params *par = &reduced;
    const int p = degree;
    const double L = par->length;
    if (L == 0.0) {   /* a point: every pole there, exact */
        el_bspline b;
        int st = el_bspline_alloc(&b, p, 2, (size_t)p + 1, 2);
        if (st) return st;
        for (int i = 0; i <= p; i++) { b.poles[2 * i] = par->x0; b.poles[2 * i + 1] = par->y0; }
        b.knots[0] = 0.0; b.knots[1] = 1.0; b.mults[0] = b.mults[1] = p + 1;
        b.max_deviation = 0.0;
        *out = b;
        return EL_OK;
    }
    /* bounded work (header): below what double precision resolves (the phase q
     * carries an absolute rounding of eps |q| into u), or more turning than the
     * pole limit can follow, is refused at once */
    if (tol < 1e-14 * (L + fabs(par->x0) + fabs(par->y0) + fabs(par->q) / sqrt(par->mu)))
        return EL_EDOM;
    const double turn = 2.0 * fabs(par->k) * sqrt(par->mu) * L;   /* >= integral |kappa| */
    if (!(turn <= (double)EL_BSPLINE_MAX_POLES)) return EL_EDOM;
    const size_t Nmax = EL_BSPLINE_MAX_POLES - (size_t)p;   /* spans */
    fit_ws w;
    memset(&w, 0, sizeof w);
    w.par = par; w.p = p; w.L = L; w.tol = tol;
    w.nfix = nfix;
    w.nmin = 2 * nfix > p + 1 ? (size_t)(2 * nfix - p) : 1;
    double *breaks = NULL, *nb = NULL, *poles = NULL, *G = NULL;
    double *bestbr = NULL, *corr = NULL, *Gc = NULL, *cm = NULL;
    double *svp = NULL, *svb = NULL;   /* poles and breaks of the last passing fit */
    size_t svN = 0, svM = 0;           /* its spans and grid */
    double dev = INFINITY, tw = 0.0;
    int st, status = EL_OK;
#define GROW(ptr, cnt) do { double *q_ = realloc(ptr, (cnt) * sizeof *q_); \
        if (!q_) { st = EL_ENOMEM; goto done; } ptr = q_; } while (0)

    /* a first grid for the knot density: 16 points per radian of turning at
     * least (bound 2k sqrt(mu) L); el__approx_ensure_grid refines it for the knots */
    {
        const double M0 = fmax(16.0 * (p + 1), 16.0 * ceil(turn));
        if ((st = el__approx_grid(&w, (size_t)M0))) goto done;
    }
    size_t Mg = 0;   /* grid size G belongs to */
    int line = 0;    /* the curve is a line (density) */
    const double ex = 1.0 / (p + 1);
    /* the sampled error a fit must reach; lowered when the certified value
     * (which sees the peaks between grid points) exceeds tol */
    double accept = tol;
    size_t N = 0;
    for (int round = 0; round < 3; round++) {
        /* the number of spans: scale by the error ratio, then bisect between
         * the largest failing and the smallest passing N */
        size_t lo_fail = 0, hi_pass = 0;   /* hi_pass = 0: none yet */
        size_t Nlast = 0;                  /* spans of the last fit (w.err, w.kc) */
        size_t Nmoved = 0;                 /* bestbr holds passing moved knots for Nmoved */
        double e = 0.0;
        for (int it = 0; it < 40; it++) {
            if (Mg != w.M) {
                GROW(G, 2 * (w.M + 1));
                line = density(&w, G + w.M + 1, G);
                Mg = w.M;
            }
            if (N == 0) {
                /* a line: any N is exact; its unit density (G = L) gave N ~ L / tol^ex,
                 * more than the pole limit from L ~ 3e4 tol^ex on */
                double x = line ? (double)w.nmin : ceil(0.19 * G[w.M] / pow(accept, ex));
                /* the estimate is good to a factor ~1.5: twice the limit is out of reach */
                if (!(x <= 2.0 * (double)Nmax)) { st = EL_EDOM; goto done; }
                N = x < (double)w.nmin ? w.nmin : (x > (double)Nmax ? Nmax : (size_t)x);
            }
            if ((st = el__approx_reserve(&w, N))) goto done;
            GROW(breaks, N + 1);
            if ((st = breaks_for(&w, G, N, breaks))) goto done;
            if ((st = el__approx_ensure_grid(&w, N, breaks)) == EL_EMAXITER) { st = EL_OK; break; }
            if (st) goto done;
            if (Mg != w.M) { it--; continue; }   /* finer grid: recompute the density, same N */
            el__approx_set_knots(&w, N, breaks);
            GROW(poles, 2 * (N + (size_t)p));
            if ((st = el__approx_poles(&w, N, poles))) goto done;
            e = el__approx_errors(&w, N, poles);
            Nlast = N;
            if (e <= accept) {   /* kept: the final fit below reuses it when it is this one */
                GROW(svp, 2 * (N + (size_t)p));
                GROW(svb, N + 1);
                memcpy(svp, poles, 2 * (N + (size_t)p) * sizeof *poles);
                memcpy(svb, breaks, (N + 1) * sizeof *breaks);
                svN = N; svM = w.M;
            }
            if (e <= accept) { if (!hi_pass || N < hi_pass) hi_pass = N; }
            else if (N > lo_fail) lo_fail = N;
            if (hi_pass && hi_pass == lo_fail + 1) break;
            size_t Nn;
            const double r = pow(e / (0.96 * accept), ex) * (double)N;   /* aim just below */
            if (e > accept) Nn = !(r <= (double)Nmax) ? Nmax : (size_t)ceil(r);
            else Nn = r >= 0.0 ? (size_t)floor(r) : 0;   /* (r <= N here) */
            if (e > accept && N >= Nmax) break;   /* the pole limit: best effort below */
            if (e > accept && Nn <= N) Nn = N + 1;
            if (e <= accept && Nn >= N) Nn = N - 1;
            if (Nn <= lo_fail) Nn = lo_fail + 1;
            if (hi_pass && Nn >= hi_pass) Nn = hi_pass - 1;
            if (Nn < w.nmin || Nn == N) break;
            N = Nn;
        }

        /* fewer spans by moving knots: the density corrected by the span errors
         * of the last fit (any N) places the knots, first for N = lo_fail;
         * then N is lowered by the error ratio after a success (as above) and
         * bisected between the smallest moved success and the largest moved
         * failure. The corrections accumulate (cm, per grid point): the end
         * spans, whose first and last two poles are fixed by the end tangents
         * (el__approx_poles), need a lasting extra density that the curve's own
         * density() does not predict. */
        if (hi_pass && lo_fail && Mg == w.M) {
            size_t Nc = lo_fail, mfail = 0;   /* largest failing N with moved knots */
            int retried = 0;                  /* Nc is being retried */
            GROW(cm, w.M + 1);
            for (size_t i = 0; i <= w.M; i++) cm[i] = 1.0;
            for (int tries = 0; tries < 10 && Nc >= 1; tries++) {
                GROW(corr, Nlast);
                correction(&w, Nlast, corr);
                for (size_t i = 0; i <= w.M; i++) cm[i] *= corr[w.kc[i] - (size_t)p];
                GROW(nb, Nc + 1);
                if ((st = el__approx_reserve(&w, Nc))) goto done;
                int regrid = 0;
                for (;;) {   /* knots; a finer grid if they need one (cm carried over) */
                    GROW(Gc, w.M + 1);
                    cumulate(&w, G + w.M + 1, cm, Gc);
                    if (breaks_for(&w, Gc, Nc, nb)) { regrid = -1; break; }
                    const size_t M0 = w.M;
                    if ((st = el__approx_ensure_grid(&w, Nc, nb)) == EL_EMAXITER) { st = EL_OK; regrid = -1; break; }
                    if (st) goto done;
                    if (w.M == M0) break;
                    if (++regrid > 2) { regrid = -1; break; }   /* G is redone after the loop */
                    GROW(G, 2 * (w.M + 1));
                    density(&w, G + w.M + 1, G);
                    Mg = w.M;
                    double *c2 = malloc((w.M + 1) * sizeof *c2);
                    if (!c2) { st = EL_ENOMEM; goto done; }
                    for (size_t i = 0; i <= w.M; i++)   /* nearest old grid point */
                        c2[i] = cm[(size_t)floor((double)i * (double)M0 / (double)w.M + 0.5)];
                    free(cm);
                    cm = c2;
                }
                if (regrid < 0) break;
                el__approx_set_knots(&w, Nc, nb);
                GROW(poles, 2 * (Nc + (size_t)p));
                if ((st = el__approx_poles(&w, Nc, poles))) goto done;
                e = el__approx_errors(&w, Nc, poles);
                Nlast = Nc;
                if (e <= accept) {
                    GROW(svp, 2 * (Nc + (size_t)p));
                    GROW(svb, Nc + 1);
                    memcpy(svp, poles, 2 * (Nc + (size_t)p) * sizeof *poles);
                    memcpy(svb, nb, (Nc + 1) * sizeof *nb);
                    svN = Nc; svM = w.M;
                }
                size_t Nn;
                if (e <= accept) {
                    GROW(bestbr, Nc + 1);
                    memcpy(bestbr, nb, (Nc + 1) * sizeof *nb);
                    hi_pass = Nmoved = Nc;
                    if (mfail >= Nc) mfail = 0;
                    const double r = floor(pow(e / (0.96 * accept), ex) * (double)Nc);
                    Nn = r < (double)Nc ? (size_t)r : Nc - 1;
                    if (Nn <= mfail) Nn = mfail + (Nc - mfail) / 2;
                    if (Nn <= mfail) break;
                } else {
                    mfail = Nc;
                    if (!retried && !Nmoved) Nn = Nc;   /* once more, with the further correction */
                    else if (!Nmoved || (Nn = Nc + (Nmoved - Nc) / 2) == Nc) break;
                }
                if (Nn < w.nmin || (Nmoved && Nn >= Nmoved)) break;
                retried = Nn == Nc;
                Nc = Nn;
            }
        }
        if (hi_pass) N = hi_pass;
        else status = EL_EMAXITER;   /* best effort: the last N tried, certified honestly */
        if (Mg != w.M) { GROW(G, 2 * (w.M + 1)); density(&w, G + w.M + 1, G); Mg = w.M; }
        GROW(breaks, N + 1);
        if ((st = el__approx_reserve(&w, N))) goto done;
        if (Nmoved && Nmoved == N) memcpy(breaks, bestbr, (N + 1) * sizeof *breaks);
        else if ((st = breaks_for(&w, G, N, breaks))) goto done;
        /* knots finer than the grid limit: fewer spans (N = 1 always fits), best effort */
        while ((st = el__approx_ensure_grid(&w, N, breaks)) == EL_EMAXITER && N > 1) {
            status = EL_EMAXITER;
            N /= 2;
            if ((st = breaks_for(&w, G, N, breaks))) goto done;
        }
        if (st) goto done;
        el__approx_set_knots(&w, N, breaks);
        GROW(poles, 2 * (N + (size_t)p));
        if (svN == N && svM == w.M && !memcmp(svb, breaks, (N + 1) * sizeof *breaks)) {
            el__approx_basis(&w, N);   /* the same fit as the saved one: no refit */
            memcpy(poles, svp, 2 * (N + (size_t)p) * sizeof *poles);
        } else if ((st = el__approx_poles(&w, N, poles))) goto done;
        if ((st = el__approx_certify(&w, N, poles, &dev, &tw))) goto done;
        if (dev <= tol || status) break;
        accept *= 0.995 * tol / dev;
    }

    /* last resort: split the span holding the worst point until certified; at a
     * limit (iterations, poles, grid) the last certified spline is the answer */
    for (int it = 0; dev > tol && !status; it++) {
        if (it == 30 || N >= Nmax) { status = EL_EMAXITER; break; }
        size_t j = 0;
        while (j + 1 < N && tw >= breaks[j + 1]) j++;
        GROW(nb, N + 2);
        memcpy(nb, breaks, (j + 1) * sizeof *nb);
        nb[j + 1] = 0.5 * (breaks[j] + breaks[j + 1]);
        memcpy(nb + j + 2, breaks + j + 1, (N - j) * sizeof *nb);
        if ((st = el__approx_reserve(&w, N + 1))) goto done;
        if ((st = el__approx_ensure_grid(&w, N + 1, nb)) == EL_EMAXITER) {
            st = EL_OK;
            status = EL_EMAXITER;
            break;
        }
        if (st) goto done;
        double *tmp = breaks; breaks = nb; nb = tmp;
        N++;
        el__approx_set_knots(&w, N, breaks);
        GROW(poles, 2 * (N + (size_t)p));
        if ((st = el__approx_poles(&w, N, poles))) goto done;
        if ((st = el__approx_certify(&w, N, poles, &dev, &tw))) goto done;
    }
    st = emit(&w, N, breaks, poles, dev, out);
#undef GROW
done:
    free(breaks); free(nb); free(poles); free(G); free(bestbr); free(corr); free(Gc); free(cm);
    free(svp); free(svb);
    el__approx_free(&w);
    return st ? st : status;
}

int el_smooth_to_bspline(const el_smooth_params *par, double tol, int degree, el_bspline *out)
{
    return smooth_to_bspline(par, tol, degree, 2, out);
}

int el_smooth_to_bspline_g2(const el_smooth_params *par, double tol, int degree, el_bspline *out)
{
    return smooth_to_bspline(par, tol, degree, 3, out);
}

/* Whether each piece starts within tol of where the one before ends, with its tangent within
 * tol / (the shorter one's length) of that end's: a kink the C2 join smooths over the
 * joint's spans moves the curve by about its angle times their width, which the knot
 * removal's bound does not see (a 0.5 rad kink between pieces 2 long was certified at 0.0171
 * where the B-spline lay 0.0175 from them, QA). */
static int pieces_meet(const el_smooth_params *pieces, size_t m, double tol)
{
    double prev[4], th_prev[2];
    for (size_t j = 0; j < m; j++) {
        double xy[4], th[2];
        if (el__smooth_ends(&pieces[j], xy, th)) return 0;
        if (j) {
            const double gap = hypot(xy[0] - prev[2], xy[1] - prev[3]);
            const double kink = fabs(remainder(th[0] - th_prev[1], 2.0 * M_PI));
            const double shorter = fmin(pieces[j].length, pieces[j - 1].length);
            if (!(gap <= tol) || !(kink * shorter <= tol)) return 0;
        }
        memcpy(prev, xy, sizeof prev);
        memcpy(th_prev, th, sizeof th_prev);
    }
    return 1;
}

int el_smooth_chain_to_bspline(const el_smooth_params *pieces, size_t m, double tol, int degree,
                               el_bspline *out)
{
    if (!pieces || !m || !out || !isfinite(tol) || !(tol > 0.0) || degree < 3 || degree > 7)
        return EL_EINVAL;
    for (size_t j = 0; j < m; j++)   /* every piece checked before any work */
        if (el_smooth_check(&pieces[j])) return EL_EINVAL;
    if (!pieces_meet(pieces, m, tol)) return EL_EINVAL;
    el_bspline *parts = calloc(m, sizeof *parts);
    if (!parts) return EL_ENOMEM;
    /* the joins' rounding err adds to the pieces' distances: pieces that met tol but
     * not with err are fitted again within tol - 2 err (at 1e6 coordinates, tol 1e-6:
     * pieces at 9.998e-7 plus err 4.7e-10 failed, QA), at most twice */
    int st = EL_OK, status = EL_OK;
    double budget = tol;
    el_bspline b;
    for (int again = 0;; again++) {
        double dev = 0.0, err = 0.0;
        status = EL_OK;
        for (size_t j = 0; j < m && !st; j++) {
            st = el_smooth_to_bspline_g2(&pieces[j], budget, degree, &parts[j]);
            if (st == EL_EMAXITER) { status = st; st = EL_OK; }
            if (!st) dev = fmax(dev, parts[j].max_deviation);
        }
        if (!st) st = el__bspline_join_c2(parts, m, &b, &err);
        for (size_t j = 0; j < m; j++) el_bspline_free(&parts[j]);
        if (st) break;
        b.max_deviation = dev + err;
        if (b.max_deviation <= tol) break;
        status = EL_EMAXITER;
        if (again == 2 || dev > budget || !(2.0 * err < 0.5 * tol)) break;
        el_bspline_free(&b);
        budget = tol - 2.0 * err * (double)(again + 1);
    }
    free(parts);
    if (st) return st;
    *out = b;
    return status;
}
