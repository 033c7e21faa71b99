/*
 * G2 ends (spline_guide.c): the guided chain's end curvatures bent from the G1
 * sibling's to the ones asked, at its tension or length.
 *
 * First by continuation in them, linearly, the whole step first (el__spline_continuation).
 * Along that path the family can fold: the end curvature turns back while the batten
 * goes on (lengthens), and a step in the curvature then finds nothing. Measured (QA16):
 * a 90 deg arc of radius 20 from the origin heading +x, blended G2 at sigma 0 into a line
 * from (90, 60) heading +x: its sibling starts with curvature 0.040; along the family the
 * start curvature rises to 0.0402 (length 157), falls to 0.0355 (257) and rises through
 * 1/20 at length 230.3, the free G2 batten (bending 0.1749, an independent shooting solver
 * agrees). Where the first path fails, the bend parameter tau (kg = kg0 + tau (kg - kg0))
 * becomes an unknown of the chain's Newton (spline_chain.c) with the pseudo-arclength
 * row: its step along the secant of the last two solutions fixed in (knot values, tau).
 * The path turns at the folds; where tau passes 1, Newton at the curvatures asked from the
 * state interpolated there. Reached so, the batten is compared with the one the paths
 * after a failure find (the free batten's sibling bent and followed, spline.c's solve_g2;
 * tension mode's search by length, spline_g2_tension.c), and the fairer kept (that one
 * within 1e-9: its bits as before).
 * Measured on 160 end pairs (arcs of radius 10 .. 40 to lines from 5 points at 4 headings;
 * tension 0, 1e-4 and length 1.4 x the chord: 480 solves): 70 newly solved (R = 18 .. 23 at
 * (90, 60) among them, the free batten 230.05 long at R = 20), 299 the same bit for bit,
 * 2 fairer (bending 0.62 -> 0.25, 2.60 -> 1.30), none lost or less fair. Instructions on
 * the 283 solved in < 10 ms: +0.13 % (median) where the first path solves, 1.5 .. 2.5 x on
 * the 8 it does not (both paths are followed there).
 */
#include "internal.h"
#include <string.h>

/* The end curvatures kg from par[0..1] (t = 0) to par[2..3], linearly. */
static void set_end_curvature(el__spchain *w, double t, const double *par)
{
    for (int e = 0; e < 2; e++) w->kg[e] = t >= 1.0 ? par[2 + e] : par[e] + t * (par[2 + e] - par[e]);
}

/* The distance of two points of the path: knot values and tau. */
static double bend_dist(const el__spchain *w, const el__spsnap *a, double ta, const el__spsnap *b, double tb)
{
    double s2 = (tb - ta) * (tb - ta);
    for (size_t i = 0; i < w->n; i++) s2 += (b->x[i] - a->x[i]) * (b->x[i] - a->x[i]);
    return sqrt(s2);
}

/* The first step in tau (halved until Newton converges there), the largest step along the path. */
static const double BEND_DT = 0.125, BEND_HMAX = 0.5;

/* Pseudo-arclength in (knot values, tau) from the sibling's state in w->snap[2] (tau = 0)
 * to tau = 1, where kg = the curvatures asked: EL_OK, else EL_ENOCONV (w->near: a state
 * within EL__SP_NEAR there). Steps as el__spline_follow_family's. */
static int bend_arc(el__spchain *w, int max_steps, const double kg[2])
{
    el__spsnap *B = &w->snap[2], *C = &w->snap[0], *D = &w->snap[1];
    double tB = 0.0, tC = 0.0;
    int st = EL_ENOCONV, steps = max_steps;
    for (double dt = BEND_DT; st && dt >= 1e-3 && steps > 0; dt *= 0.5, steps--) {
        el__snap_load(w, B);
        for (int e = 0; e < 2; e++) w->kg[e] = w->bend_k[e] + dt * w->bend_dk[e];
        st = el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
        tC = dt;
    }
    if (st) return EL_ENOCONV;
    el__snap_save(w, C);
    double N = bend_dist(w, B, tB, C, tC), h = N;
    while (steps-- > 0 && N > 0.0 && h > 1e-6) {
        for (size_t i = 0; i < w->n; i++) {
            w->arc_a[i] = (C->x[i] - B->x[i]) / N;
            w->arc_x0[i] = C->x[i];
        }
        w->bend_c = (tC - tB) / N;
        w->bend_t0 = tC;
        w->arc_h = h;
        el__snap_predict(w, B, C, h / N);
        w->tau = tC + h / N * (tC - tB);
        w->bend = 1;
        const int it0 = w->iterations;
        st = el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
        w->bend = 0;
        if (st) { el__snap_load(w, C); h *= 0.5; continue; }
        const double tD = w->tau;
        if ((tD - 1.0) * (tC - 1.0) <= 0.0) {   /* tau = 1 between C and D */
            el__snap_save(w, D);
            el__snap_predict(w, C, D, (1.0 - tC) / (tD - tC) - 1.0);
            w->kg[0] = kg[0];
            w->kg[1] = kg[1];
            if (el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol) == EL_OK) return EL_OK;
            if (w->resid <= EL__SP_NEAR) { w->near = 1; return EL_ENOCONV; }
            el__snap_load(w, C);
            h *= 0.25;
            continue;
        }
        el__spsnap *t = B; B = C; C = t;
        el__snap_save(w, C);
        tB = tC;
        tC = tD;
        N = bend_dist(w, B, tB, C, tC);
        if (w->iterations - it0 <= 3) h = fmin(2.0 * h, BEND_HMAX);
    }
    return EL_ENOCONV;
}

/*
 * From the guided G1 sibling in w (el__guides_setup: a solution for its own end
 * curvatures w->kg) to the end curvatures kg (file comment). A straight sibling's
 * pieces (k = 0, where q is undefined and J singular) start from the linearised
 * batten first. Already there (kg equal to the sibling's): EL_OK. arc: past folds too.
 */
int el__spline_bend_ends(el__spchain *w, int max_steps, const double kg[2], int arc)
{
    if (w->kg[0] == kg[0] && w->kg[1] == kg[1]) return EL_OK;
    for (size_t j = 0; j < w->m; j++) {
        if (w->pc[j].v[EL__SP_K] != 0.0) continue;
        el__sptargets t;
        el__chain_targets(w, j, &t);
        if (el__spiece_start(&w->pc[j], &t)) return EL_ENOCONV;
    }
    const double par[4] = {w->kg[0], w->kg[1], kg[0], kg[1]};
    w->bent_arc = 0;
    el__snap_save(w, &w->snap[2]);
    const int st = el__spline_continuation(w, w->snap, max_steps, 1.0, set_end_curvature, par, w->aim, w->tol);
    if (st != EL_ENOCONV || w->near || !arc) return st;
    for (int e = 0; e < 2; e++) { w->bend_k[e] = par[e]; w->bend_dk[e] = kg[e] - par[e]; }
    const int sa = bend_arc(w, max_steps, kg);
    w->bent_arc = sa == EL_OK;
    if (sa == EL_OK || w->near) return sa;
    el__snap_load(w, &w->snap[2]);   /* as the first path left it: the sibling's */
    for (int e = 0; e < 2; e++) w->kg[e] = par[e];
    el__chain_reeval(w, 1);
    return EL_ENOCONV;
}

/* integral kappa^2 + sigma ds; in length mode (the length given) integral kappa^2 */
static double lagrangian(const el__spchain *w)
{
    double e = 0.0;
    for (size_t j = 0; j < w->m; j++) e += w->pc[j].energy + (w->lmode ? 0.0 : w->sigma * w->pc[j].v[EL__SP_L]);
    return e;
}

int el__g2_fairer(const el__spchain *a, const el__spchain *b)
{
    const int ca = el__chain_crosses(a), cb = el__chain_crosses(b);
    if (ca < 0 || cb < 0) return -1;
    const double la = lagrangian(a), lb = lagrangian(b);
    return cb != ca ? cb < ca : lb <= la + 1e-9 * fabs(la);
}
