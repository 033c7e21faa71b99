/*
 * Seed 002 §4.4 fit_ends: the piece's A "redone with adjusted value for A if the resulting
 * x_ni is too far from the inflection point": a secant on log|A|, and where it finds no
 * landing, each of psi's lowest minima in t1 followed through A (piece_land_branches).
 */
#include "affine_piece.h"
#include <gsl/gsl_min.h>
#include <stdlib.h>

/* fit_ends' landing (§4.4 "redone with adjusted value for A if the resulting x_ni is too
 * far from the inflection point, but an exact coincidence is not necessary"): no vertex
 * past the piece end Tb, the last within half a sample of it; the polyline's last piece
 * (`last`: it ends at the curve's end, or at an inflection where the end piece was left
 * out) within half a sample on the short side too (the nearest sample is its end:
 * g2_quadratic rounds t to it). Else no A lands it: past the end, the vertices ran on
 * along the last parabola continued (§4.3), up to next_vertex's bound; short of it, m
 * edges of the largest area the turning allows stop before the end (a circle turning 4.2
 * times at 8 edges: t = 99.7 of 159; det(v, v') = A peaks at 2 pi / 3 a vertex on a
 * circle). Both: too few edges for the turning. An inner piece's end is the next piece's
 * first vertex, so a stop short there leaves nothing of the curve out (60 noisy points at
 * 20 edges: an inner piece 1.07 samples short, no A closer); the paper lets it be. */
static int piece_landed(const piece *P, int last)
{
    for (size_t i = 1; i < P->m; i++)
        if (P->t[i] > (double)P->Tb) return 0;
    double miss = P->t[P->m] - (double)P->Tb;
    return !(miss > 0.5 || (last && miss < -0.5));
}

/* ------------------- fit_ends' landing along one minimum of psi (the secant's fallback) */

/* The local minimum of psi(t1) at P's A reached from t downhill in steps of h (at most
 * 64 steps, staying above Ta), refined by GSL's golden section to `tol` and, at the
 * landing's tol (o->t1_tol), polished as piece_optimise's; P left built there, *t moved
 * to it. EL_EDOM: no minimum on the way (a build failed, the
 * walk reached Ta or ran out). P->r must be allocated. */
static int piece_local_min(piece *P, const el_affine_options *o, double *t, double h, double tol)
{
    const double lo = (double)P->Ta;
    double tb = *t, ta = tb - h, tc = tb + h;
    if (!(ta > lo)) return EL_EDOM;
    double fa = el__piece_psi(ta, P), fb = el__piece_psi(tb, P), fc = el__piece_psi(tc, P);
    for (int k = 0; k < 64 && !(fb < fa && fb < fc); k++) {
        if (fa < fc) {
            tc = tb; fc = fb; tb = ta; fb = fa; ta = tb - h;
            if (!(ta > lo)) return EL_EDOM;
            fa = el__piece_psi(ta, P);
        } else {
            ta = tb; fa = fb; tb = tc; fb = fc; tc = tb + h;
            fc = el__piece_psi(tc, P);
        }
    }
    if (!(fb < fa && fb < fc && fb < 1e300)) return EL_EDOM;
    el__gsl_quiet();
    gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_goldensection);
    if (!s) return EL_ENOMEM;
    gsl_function F = {el__piece_psi, P};
    int st = gsl_min_fminimizer_set_with_values(s, &F, tb, fb, ta, fa, tc, fc) ? EL_EDOM : EL_OK;
    for (int it = 0; !st && it < o->max_iter; it++) {
        if (gsl_min_fminimizer_iterate(s)) break;
        if (gsl_min_fminimizer_x_upper(s) - gsl_min_fminimizer_x_lower(s) < tol) break;
    }
    if (!st) *t = gsl_min_fminimizer_x_minimum(s);
    if (!st && tol <= o->t1_tol) *t = el__piece_polish(P, *t, h);   /* the landing's tol */
    gsl_min_fminimizer_free(s);
    if (!st) st = el__piece_build(P, *t);
    return st;
}

/* The landing miss f = t_m - Tb at A = A0 e^l on one branch: t1 the minimum of psi
 * reached from *t (piece_local_min; *t follows it), or without optimisation t1 from the
 * affine length (el__piece_solve: f continuous in l). P left built there. */
static int branch_miss(piece *P, const el_affine_options *o, int optimisable, double A0,
                       double l, double *t, double h, double tol, double *f)
{
    P->A = A0 * exp(l);
    int st;
    if (optimisable) {
        st = piece_local_min(P, o, t, h, tol);
    } else {
        double *keep = P->r, psi;   /* el__piece_solve allocates and frees its own */
        st = el__piece_solve(P, o, &psi);
        P->r = keep;
    }
    *f = P->t[P->m] - (double)P->Tb;
    return st ? st : (isfinite(*f) ? EL_OK : EL_EDOM);
}

/*
 * fit_ends when the secant on log|A| found no landing. psi(t1) can have several near-equal
 * minima (a batten's curvature has a corner at each duck, and is 0 at its free ends), the
 * global one jumps between them as A moves, and the miss t_m - Tb jumps with it, over 0
 * (exact samples of a 12-duck batten, 192 edges: -13.4 -> +11.1 samples for a change of
 * 2e-4 in log A). Along one minimum the miss is continuous in A. So: from each of the NS
 * lowest minima of psi's grid at A0 (piece_optimise's grid), follow it (piece_local_min
 * from the last t1) both ways in log(A/A0), in steps of 0.02 up to +-0.5, all branches a
 * step at a time; where a branch's miss changes sign, bisect on that branch (a jump that
 * stays > 0.5 samples after 12 halvings is no root). The first step with a landed polyline
 * (piece_landed) ends the search: of its landings, the least psi (A nearest the paper's
 * first, then the fairest). Without optimisation t1 has one branch. Bounded work: at most
 * 2 NS K branch steps. Leaves P built at the landing; EL_EDOM when no branch lands.
 */
static int piece_land_branches(piece *P, const el_affine_options *o, double A0, int last,
                               double *psi)
{
    enum { G = 24, K = 25, NS = 4 };
    const double dl = 0.02, scan_tol = 1e-4;
    const int optimisable = o->optimise && P->m >= 4 + (size_t)P->skip_lo + (size_t)P->skip_hi;
    P->A = A0;
    const double lo = (double)P->Ta, t1i = el__piece_t1_start(P);
    const double hi = fmin(lo + 2.0 * (t1i - lo), (double)P->Tb), h = 0.25 * (hi - lo) / G;
    if (optimisable && !(hi > lo)) return EL_EDOM;
    P->r = malloc(3 * (P->m + 1) * sizeof *P->r);
    if (!P->r) return EL_ENOMEM;
    double tb[2 * NS], fb[2 * NS], fg[G + 1];   /* branch b: start b / 2, direction b % 2 */
    int alive[2 * NS];
    size_t nb = 0;
    if (optimisable) {
        for (size_t g = 1; g <= G; g++) fg[g] = el__piece_psi(lo + (double)g * 4.0 * h, P);
        int taken[G + 1] = {0};
        for (int k = 0; k < NS; k++) {   /* the NS lowest minima of the grid */
            size_t gb = 0;
            for (size_t g = 2; g < G; g++)
                if (!taken[g] && fg[g] < fg[g - 1] && fg[g] < fg[g + 1] && fg[g] < 1e300 &&
                    (gb == 0 || fg[g] < fg[gb]))
                    gb = g;
            if (gb == 0) break;
            taken[gb] = 1;
            tb[nb] = tb[nb + 1] = lo + (double)gb * 4.0 * h;
            nb += 2;
        }
    } else {
        tb[0] = tb[1] = t1i;
        nb = 2;
    }
    for (size_t b = 0; b < nb; b += 2) {
        alive[b] = alive[b + 1] =
            !branch_miss(P, o, optimisable, A0, 0.0, &tb[b], h, scan_tol, &fb[b]);
        tb[b + 1] = tb[b];
        fb[b + 1] = fb[b];
    }
    double best_l = 0.0, best_t = 0.0, best_psi = HUGE_VAL;
    for (int k = 1; k <= K && best_psi == HUGE_VAL; k++) {
        for (size_t b = 0; b < nb; b++) {
            if (!alive[b]) continue;
            const double dir = (b % 2) ? 1.0 : -1.0, l = dir * (k - 1) * dl, l2 = dir * k * dl;
            double t2 = tb[b], f2;
            if (branch_miss(P, o, optimisable, A0, l2, &t2, h, scan_tol, &f2)) {
                alive[b] = 0;
                continue;
            }
            if ((fb[b] < 0.0) != (f2 < 0.0)) {   /* bisect on this branch */
                double a = l, ta = tb[b], fa = fb[b], c = l2, tc = t2, fc = f2;
                for (int it = 0; it < 40 && fabs(fa) > 1e-7 && fabs(fc) > 1e-7; it++) {
                    if (it >= 12 && fmin(fabs(fa), fabs(fc)) > 0.5) break;  /* a jump, no root */
                    double mid = 0.5 * (a + c), tm = fabs(fa) < fabs(fc) ? ta : tc, fm;
                    if (branch_miss(P, o, optimisable, A0, mid, &tm, h, scan_tol, &fm)) break;
                    if ((fm < 0.0) == (fa < 0.0)) { a = mid; ta = tm; fa = fm; }
                    else { c = mid; tc = tm; fc = fm; }
                }
                double lz = fabs(fa) < fabs(fc) ? a : c, tz = fabs(fa) < fabs(fc) ? ta : tc, fz;
                if (!branch_miss(P, o, optimisable, A0, lz, &tz, h, o->t1_tol, &fz) &&
                    piece_landed(P, last)) {
                    double pz = el__piece_psi_built(P);
                    if (pz < best_psi) { best_psi = pz; best_l = lz; best_t = tz; }
                }
            }
            tb[b] = t2;
            fb[b] = f2;
        }
    }
    int st = EL_EDOM;
    if (best_psi < HUGE_VAL) {
        double f;
        st = branch_miss(P, o, optimisable, A0, best_l, &best_t, h, o->t1_tol, &f);
        if (!st && !piece_landed(P, last)) st = EL_EDOM;
        if (!st) *psi = el__piece_psi_built(P);
    }
    free(P->r);
    P->r = NULL;
    return st;
}

/* ------------------------------------------------ §4.4: the secant, then the branches */

int el__piece_fit_ends(piece *P, const el_affine_options *o, int last, double *psi)
{
    /* §4.4: "redone with adjusted A": secant on log|A| so that the last vertex
     * lands at the piece end (the inflection / the curve end), t1 re-optimised. */
    double A0 = P->A, l0 = 0.0, f0 = P->t[P->m] - (double)P->Tb;
    /* first guess: the steps scale like cbrt|A|, so t_end - Ta ~ |A|^(1/3) */
    double l1 = -3.0 * log1p(f0 / ((double)(P->Tb - P->Ta) + 1.0)), f1;
    l1 = fmax(-1.0, fmin(1.0, l1));
    double bestf = f0, bestl = 0.0;
    for (int it = 0; it < 30 && fabs(bestf) > 1e-7; it++) {
        P->A = A0 * exp(l1);
        if (el__piece_solve(P, o, psi)) { l1 = 0.5 * (l0 + l1); continue; }
        f1 = P->t[P->m] - (double)P->Tb;
        if (fabs(f1) < fabs(bestf)) { bestf = f1; bestl = l1; }
        double l2 = (f1 != f0) ? l1 - f1 * (l1 - l0) / (f1 - f0) : l1;
        if (!isfinite(l2) || fabs(l2 - l1) > 1.0) l2 = l1 + (l2 > l1 ? 1.0 : -1.0) * 0.5;
        l0 = l1; f0 = f1; l1 = l2;
    }
    P->A = A0 * exp(bestl);
    int st = el__piece_solve(P, o, psi);
    if (!st && !piece_landed(P, last)) st = EL_EDOM;   /* n too small */
    if (st == EL_EDOM) st = piece_land_branches(P, o, A0, last, psi);
    return st;
}
