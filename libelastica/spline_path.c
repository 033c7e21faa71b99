/*
 * The paths of an elastic spline's solve (spline.c): from the start to the
 * tension solution, and along the family of tension solutions to a length.
 *
 * Tension mode: Newton on the chain (spline_chain.c) from its start; if that
 * fails, continuation in sigma from a high tension (sigma h^2 = 40: the pieces
 * are then short and near the polygon) down to sigma; a solution that does not follow
 * its ducks, or none, is then checked against the family followed by pseudo-arclength
 * from the taut batten (spline_fair.c, el__spline_refair).
 * Length mode: Newton with the length as an equation where it contracts, else
 * pseudo-arclength continuation of the tension solutions in (angles, sigma)
 * from the free batten (follow_length), since neither sigma nor the length
 * parametrises the family (flat in sigma for moderate tension, folding back
 * when buckled) (el__spline_solve_length). Collinear points: the buckled
 * strip, followed in length (el__spline_solve_buckled).
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_linalg.h>

/* ------------------------------------------------------------------ continuation */

/* Snapshots: to restore after a failed step, and the two last ones for the
 * secant predictor. */
void el__snap_save(const el__spchain *w, el__spsnap *s)
{
    memcpy(s->x, w->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) {
        memcpy(s->v + j * EL__NV, w->pc[j].v, sizeof w->pc[j].v);
        memcpy(s->st + j * EL__NV, w->pc[j].st, sizeof w->pc[j].st);
    }
    s->sigma = w->sigma;
}

void el__snap_load(el__spchain *w, const el__spsnap *s)
{
    memcpy(w->x, s->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].v, s->v + j * EL__NV, sizeof w->pc[j].v);
    w->sigma = s->sigma;
}

/* The state at f = (t - tb)/(tb - ta) beyond b on the line through a and b
 * (knot values, sigma, el__spiece states); b itself if a piece state is invalid. */
static void predict(el__spchain *w, const el__spsnap *a, const el__spsnap *b, double f)
{
    for (size_t i = 0; i < w->n; i++) w->x[i] = b->x[i] + f * (b->x[i] - a->x[i]);
    w->sigma = b->sigma + f * (b->sigma - a->sigma);
    for (size_t j = 0; j < w->m; j++) {
        double st[EL__NV];
        for (int i = 0; i < EL__NV; i++) st[i] = b->st[j * EL__NV + i] + f * (b->st[j * EL__NV + i] - a->st[j * EL__NV + i]);
        if (el__spiece_set_state(&w->pc[j], st)) { el__snap_load(w, b); return; }
    }
}

/*
 * Follow a one-parameter family from t = 0 (solved, in w) to t = 1: set(w, t)
 * moves the target (sigma or length); each step starts from the secant
 * predictor of the last two solutions and is corrected by Newton to EL__SP_NEAR
 * (the last one to aim, accepted at accept). The first step is dt; it doubles
 * after an easy success, grows by 1.3 after a slow one and halves after a
 * failure (state restored); at most max_steps steps, giving up below 1e-3.
 * A step whose Newton needs more than EL__SP_STEP_HALVINGS halvings fails: a
 * shorter step serves better, and where none does (a fold in t: the free
 * batten that does not exist) the path ends sooner (a 1000-point zigzag says
 * EL_EDOM in ~1 s, was ~5 s; the results elsewhere are the same).
 */
static int continuation(el__spchain *w, el__spsnap sv[2], int max_steps, double dt,
                        void (*set)(el__spchain *, double, const double *), const double *par,
                        double aim, double accept)
{
    double t = 0.0, tp = -1.0;
    el__spsnap *cur = &sv[0], *prev = &sv[1];
    el__snap_save(w, cur);
    for (int step = 0; step < max_steps; step++) {
        const double tn = fmin(1.0, t + dt);
        const int last = tn >= 1.0;
        if (tp >= 0.0) predict(w, prev, cur, (tn - t) / (t - tp));
        set(w, tn, par);
        const int it0 = w->iterations;
        w->halvings = EL__SP_STEP_HALVINGS;
        const int st = last ? el__chain_newton(w, EL__SP_STEP_ITER, aim, accept)
                            : el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
        w->halvings = EL__SP_HALVINGS;
        if (st == EL_OK) {
            if (last) return EL_OK;
            el__spsnap *tmp = prev; prev = cur; cur = tmp;
            el__snap_save(w, cur);
            tp = t;
            t = tn;
            dt *= w->iterations - it0 <= 3 ? 2.0 : 1.3;
            continue;
        }
        if (last && w->resid <= EL__SP_NEAR) { w->near = 1; return EL_ENOCONV; }
        el__snap_load(w, cur);
        set(w, t, par);
        dt *= 0.5;
        if (dt < 1e-3) break;
    }
    el__snap_load(w, cur);
    return EL_ENOCONV;
}

/* sigma(t) between par[0] (t = 0) and par[1] geometrically in sigma + par[2]. */
static void set_sigma(el__spchain *w, double t, const double *par)
{
    const double a = par[0] + par[2], b = par[1] + par[2];
    w->sigma = t >= 1.0 ? par[1] : a * pow(b / a, t) - par[2];
}

/* L(t) from par[0] (t = 0) to par[1], geometrically in L - par[2] (the polygon's
 * length, near which the bow is small). */
static void set_length(el__spchain *w, double t, const double *par)
{
    const double a = par[0] - par[2], b = par[1] - par[2];
    w->Lt = t >= 1.0 ? par[1] : par[2] + a * pow(b / a, t);
}

/* sigma(t) linear from par[0] to par[1]. */
static void set_sigma_linear(el__spchain *w, double t, const double *par)
{
    w->sigma = t >= 1.0 ? par[1] : par[0] + t * (par[1] - par[0]);
}

static double total_length(const el__spchain *w)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[EL__SP_L];
    return L;
}

/* From the tension solution in w to the one at sigma (to EL__SP_NEAR); EL_OK or EL_ENOCONV. */
static int move_sigma(el__spchain *w, el__spsnap sv[2], int *steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    const int st = continuation(w, sv, *steps, 1.0, set_sigma_linear, par,
                                1e-3 * EL__SP_NEAR, EL__SP_NEAR);
    (*steps)--;
    return st;
}

/* Points of the pseudo-arclength path: knot values and sigma, the norm
 * weighting sigma by 1/rho. */
static double arc_dist(const el__spchain *w, const el__spsnap *a, const el__spsnap *b, double rho)
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
 * max_steps steps. by_sigma: the target is the tension Lt instead (the gap sigma - Lt,
 * then Newton at that sigma): the family followed through its folds in sigma, where
 * continuation in sigma itself turns back or jumps to another branch (follow_sigma).
 */
static double family_gap(const el__spchain *w, double target, int by_sigma)
{
    return by_sigma ? w->sigma - target : total_length(w) - target;
}

int el__spline_follow_family(el__spchain *w, int max_steps, double Lt, int by_sigma)
{
    el__spsnap *sv = w->snap;
    int steps = max_steps;
    el__spsnap *B = &sv[2], *C = &sv[0];   /* the base point and the next one */
    const double rho = 1.0 + fabs(w->sigma);
    double gb = family_gap(w, Lt, by_sigma), gc;
    el__snap_save(w, B);
    if (fabs(gb) > 1e-9 * Lt) {
        /* a second point: sigma moved towards the length (a batten is shorter
         * under more tension, but one whose guide ducks end on its end
         * tangents is longer: the other way when the length moved away) */
        const double s1 = w->sigma + ((gb < 0.0) != by_sigma ? -0.05 : 0.05) * rho;
        if (move_sigma(w, sv, &steps, s1)) {
            /* no solution that way: the start is at a fold in sigma (el__spline_free_batten
             * stops at one where the family turns back before sigma = 0: t48 of the QA's
             * random ducks, sigma h^2 0.36, 1.11 x the polygon; every longer length failed).
             * A point on the other side, and the secant from it through the fold point leads
             * on past the fold */
            el__spsnap *T = &sv[1];
            el__snap_load(w, B);
            if (move_sigma(w, sv, &steps, 2.0 * B->sigma - s1)) return EL_ENOCONV;
            el__snap_save(w, T);
            gc = gb;
            gb = family_gap(w, Lt, by_sigma);
            C = B;
            B = T;
            el__snap_load(w, C);
            el__chain_eval(w, 1);
        } else {
            gc = family_gap(w, Lt, by_sigma);
        }
        if (fabs(gc) > fabs(gb) && C != &sv[2]) {
            el__snap_load(w, B);
            if (move_sigma(w, sv, &steps, 2.0 * B->sigma - s1)) return EL_ENOCONV;
            gc = family_gap(w, Lt, by_sigma);
        }
        el__snap_save(w, C);
        double N = arc_dist(w, B, C, rho), h = 2.0 * N, hgood = h;   /* the largest step that worked */
        int leapt = 0;
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
            w->lmode = EL__BORDER_ARC;
            const int it0 = w->iterations;
            const int st = el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
            w->lmode = 0;
                    if (st) {
                el__snap_load(w, C);
                h *= 0.5;
                if (w->leap && h < 1e-3 * hgood && !leapt) { leapt = 1; h = 4.0 * hgood; }
                continue;
            }
            hgood = fmax(hgood, h);
            leapt = 0;
            const double gn = family_gap(w, Lt, by_sigma);
            if (by_sigma == 2 && fabs(gn - gc) > 0.5 * fabs(gc) && fabs(gn) > 1e-3 * (1.0 + fabs(Lt)) && h > 1e-6) {
                /* a tension at most half way to the target per step: a longer one can pass
                 * it twice about a fold unseen (t71: down and back up within one step) */
                el__snap_load(w, C);
                h *= 0.5;
                continue;
            }
            if (gn * gc <= 0.0) {
                /* bracketed between C and the new point D: Newton on the length from
                 * the interpolated state; if that fails, a shorter step from C */
                el__spsnap *D = B;
                el__snap_save(w, D);
                predict(w, C, D, gn / (gc - gn));
                if (by_sigma) w->sigma = Lt; else { w->lmode = EL__BORDER_LENGTH; w->Lt = Lt; }
                if (el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol) == EL_OK) return EL_OK;
                w->lmode = 0;
                if (steps-- <= 0) return EL_ENOCONV;
                /* B (overwritten by D) must again be the point before C: C - (D - C) scaled */
                const double back = -1.0;
                for (size_t i = 0; i < w->n; i++) D->x[i] = C->x[i] + back * (D->x[i] - C->x[i]);
                D->sigma = C->sigma + back * (D->sigma - C->sigma);
                for (size_t i = 0; i < EL__NV * w->m; i++) D->st[i] = C->st[i] + back * (D->st[i] - C->st[i]);
                N = arc_dist(w, B, C, rho);
                el__snap_load(w, C);
                h *= 0.25;
                continue;
            }
            el__spsnap *tmp = B; B = C; C = tmp;
            el__snap_save(w, C);
            gb = gc;
            gc = gn;
            N = arc_dist(w, B, C, rho);
            if (w->iterations - it0 <= 3) h *= 2.0;
        }
    }
    if (by_sigma) w->sigma = Lt; else { w->lmode = EL__BORDER_LENGTH; w->Lt = Lt; }
    return el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol);
}

static int follow_length(el__spchain *w, int max_steps, double Lt)
{
    return el__spline_follow_family(w, max_steps, Lt, 0);
}

/* A tension solution longer than EL__SP_WANDER x its ducks' polygon winds away from them; the high
 * tension (sigma h^2 on the mean chord) the continuations start from where the direct
 * Newton fails */

/* From the tension solution at sigma0 (Newton from the chain's start there, to start_aim,
 * accepted at start_accept) along the tension to target, geometrically in sigma + 1:
 * EL_OK, EL_ENOCONV or EL_ENOMEM */
static int from_sigma(el__spchain *w, int max_steps, double sigma0, double target, double start_aim,
                      double start_accept, double aim, double accept)
{
    w->sigma = sigma0;
    el__chain_start_angles(w);
    const int st = el__chain_start_pieces(w);
    if (st) return st == EL_ENOMEM ? st : EL_ENOCONV;
    if (el__chain_newton(w, EL__SP_DIRECT_ITER, start_aim, start_accept) != EL_OK) return EL_ENOCONV;
    const double par[3] = {sigma0, target, 1.0};
    return continuation(w, w->snap, max_steps, 0.25, set_sigma, par, aim, accept);
}

/* The batten pulled from sigma0 to w->sigma (from_sigma), kept when it converges shorter
 * than the solution in w, which w->snap[2] holds meanwhile */
static void pull_from(el__spchain *w, int max_steps, double aim, double accept, double sigma0)
{
    const double target = w->sigma, was = total_length(w);
    el__snap_save(w, &w->snap[2]);
    if (from_sigma(w, max_steps, sigma0, target, aim, accept, aim, accept) || !(total_length(w) < was)) {
        el__snap_load(w, &w->snap[2]);
        el__chain_eval(w, 0);
    }
}

/* A direct solution (at sigma = target) that winds away from its ducks, longer than EL__SP_WANDER
 * x their polygon: the batten pulled from the free one (sigma = 0) to target instead, or
 * (where the free batten slides off its ducks, or winds too) brought down from sigma h^2 =
 * EL__SP_HIGH_SIGMA, the shortest kept. Measured: 10 sketched ducks of a top hat (polygon 11.9)
 * at sigma 0.01, 0.043, 0.1: the direct Newton's loops 210, 101, 66 long, crossing
 * themselves, the pulled batten 12.45 as the free one (QA); 120 sketches (waves, steps,
 * zigzags, arcs of 5-13 ducks) at 4 tensions, natural and clamped ends: 331 of 960 longer
 * than 1.5 x their polygon (up to 240 x) -> 105, none longer than before (the rest: 78 with
 * clamped ends, mostly arcs clamped against their bend; 20 zigzags whose free batten
 * slides off), CPU of the 960 1.4 -> 2.0 s */
static void unwind(el__spchain *w, int max_steps, double aim, double accept)
{
    double poly = 0.0;
    for (size_t j = 0; j < w->m; j++) poly += w->pc[j].h;
    if (w->sigma != 0.0 && total_length(w) > EL__SP_WANDER * poly) pull_from(w, max_steps, aim, accept, 0.0);
    if (w->sigma < EL__SP_HIGH_SIGMA && total_length(w) > EL__SP_WANDER * poly)
        pull_from(w, max_steps, aim, accept, EL__SP_HIGH_SIGMA);
}

/*
 * FREE_START: under a small tension el_hermite_solve's least-energy piece (the chain's
 * start where a piece's tangents are far from its chord) can be a curve at the tension's
 * own length scale 1/sqrt(sigma), nearly closed through its two close ducks: its energy
 * ~ sqrt(sigma) vanishes as sigma -> 0 (as it runs off to infinity), below the batten's
 * ~ 1/h. Measured: 7 sketched ducks (DUCKS7 in tests/c/test_spline.c) at sigma 1.4e-7
 * (internal), the first piece 22313 long for its chord of 1.85 (energy 0.0031; the
 * free piece 2.04, energy 1.34): the direct Newton stalls (merit 7.60 -> 7.58 in 20
 * iterations) and at sigma h^2 = 40 it does not converge either (18.5 -> 12.5): no
 * spline for user tensions 1e-12 .. 1e-5, 1e-14 and 0 solved (none for 0.3 .. 10 either:
 * now 0.3 solves and 1 reaches 3e-9, EL_ENOCONV with the spline). The
 * piece is not replaced where it is found: without a free batten (a closed ring) the
 * spline itself lies at that scale (taking the free piece there changed the energy of 154
 * of 2659 solved cases below). So where both paths fail, the free batten pulled to sigma,
 * the continuation unwind takes too. 90 sketches (walks, steps, arcs; natural, clamped,
 * closed) x sigma 0, 1e-14 .. 1e-3: failures where the free batten exists 77 -> 4 (near
 * straight pieces, whose 1 - k^2 a double does not resolve: EL_ENOCONV with the
 * spline), none solved before changed; at sigma 1e-2 .. 10 6 more solved, none changed,
 * CPU 4.1 -> 6.1 s (failures try one path more); bench_spline unchanged (6.46 ms).
 */

/* The tension solution at w->sigma: directly (one that winds away from its ducks: another
 * path to it, unwind), else by continuation from a high tension, else from the free batten.
 * final: to tol (else to EL__SP_NEAR, as a start for the length mode). */
int el__spline_solve_tension(el__spchain *w, int max_steps, int final)
{
    const double target = w->sigma;
    const double aim = final ? w->aim : 1e-3 * EL__SP_NEAR, accept = final ? w->tol : EL__SP_NEAR;
    el__chain_start_angles(w);
    int st = el__chain_start_pieces(w);
    if (st == EL_ENOMEM) return st;
    if (!st) {
        if (el__chain_newton(w, EL__SP_DIRECT_ITER, aim, accept) == EL_OK) {
            unwind(w, max_steps, aim, accept);
            return final ? el__spline_refair(w, max_steps, EL_OK, target) : EL_OK;
        }
        if (final && w->resid <= EL__SP_NEAR) { w->near = 1; return EL_ENOCONV; }
    }
    /* from a high tension on the mean chord (the unit here) */
    st = from_sigma(w, max_steps, EL__SP_HIGH_SIGMA, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim, accept);
    if (final && st == EL_OK) return el__spline_refair(w, max_steps, st, target);
    if (st != EL_ENOCONV || w->near || !final || !(target > 0.0)) return st;
    /* else the free batten pulled to target (FREE_START) */
    st = from_sigma(w, max_steps, 0.0, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim, accept);
    return w->near ? st : el__spline_refair(w, max_steps, st, target);
}

int el__spline_tension_from(el__spchain *w, int max_steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    return continuation(w, w->snap, max_steps, 1.0, set_sigma_linear, par, w->aim, w->tol);
}

/* Newton in length mode (the length as the border equation, sigma unknown),
 * trusted only while it contracts (el__chain_newton). */
static int length_newton(el__spchain *w, double Lt)
{
    w->lmode = EL__BORDER_LENGTH;
    w->Lt = Lt;
    w->contract = 1;
    const int st = el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol);
    w->contract = 0;
    return st;
}

/*
 * Length mode. The solution is the tension solution of the family through the
 * free batten (sigma = 0) whose length is Lt, the first one met following the
 * family from the free batten (follow_length). Cheaper, in this order:
 *  1. Newton on (angles, sigma) with the length equation from the start
 *     (el__chain_start_angles at sigma = 0);
 *  2. the free batten (or as near sigma = 0 as continuation gets: it need not
 *     exist), then the same Newton from it: its first step is the tangent
 *     predictor of the family, sigma moved by (Lt - L) / (dL/dsigma);
 *  3. follow_length from the free batten.
 * 1 and 2 are accepted only if Newton contracts all the way, without crossing
 * a fold (el__chain_newton's w->contract): the solution is then the one
 * nearest the start, the one the continuation reaches (checked against it on
 * random data); a target far along the family, past a fold or where the
 * length is far from linear in sigma, falls through to 3.
 */
int el__spline_solve_length(el__spchain *w, int max_steps, double Lt)
{
    if (w->newton_first) {
        w->lmode = 0;
        w->sigma = 0.0;
        el__chain_start_angles(w);
        const int st = el__chain_start_pieces(w);
        if (st == EL_ENOMEM) return st;
        if (!st && length_newton(w, Lt) == EL_OK) return EL_OK;
    }
    int st = el__spline_free_batten(w, max_steps);
    if (st == EL_ENOCONV) {
        /* no free batten (ducks in a ring: a closed batten without tension swells without
         * bound; a zigzag slides off): from a batten under tension instead, the first of
         * these that converges, followed in length as the free one is (9 ducks of a blob,
         * closed: no spline at the lengths its tensions 0.3, 1, 3 give, QA; its tension
         * sigma h^2 = 40 has none either) */
        const double sigmas[3] = {EL__SP_HIGH_SIGMA, 4.0, 0.4};   /* sigma h^2 on the mean chord */
        for (int i = 0; i < 3 && st == EL_ENOCONV; i++) {
            w->near = 0;
            w->lmode = 0;
            w->sigma = sigmas[i];
            st = el__spline_solve_tension(w, max_steps, 0);
        }
    }
    return st ? st : el__spline_length_from(w, max_steps, Lt);
}

/* The free batten: the tension solution at sigma = 0, or as near it as the
 * continuation from a high tension gets (to EL__SP_NEAR). */
int el__spline_free_batten(el__spchain *w, int max_steps)
{
    w->lmode = 0;
    w->sigma = 0.0;
    int st = el__spline_solve_tension(w, max_steps, 0);
    if (st == EL_ENOCONV && isfinite(el__chain_eval(w, 1)) && w->resid <= EL__SP_NEAR) st = EL_OK;
    return st;
}

/* Steps 2 (its Newton) and 3 from the tension solution in w. */
int el__spline_length_from(el__spchain *w, int max_steps, double Lt)
{
    if (w->newton_first) {
        el__spsnap *free_batten = &w->snap[2];
        el__snap_save(w, free_batten);
        if (length_newton(w, Lt) == EL_OK) return EL_OK;
        w->lmode = 0;
        el__snap_load(w, free_batten);
        el__chain_eval(w, 1);   /* the pieces' states, which follow_length's snapshots keep */
    }
    /* the start kept for a second attempt (below) */
    const size_t n = w->n, m = w->m;
    double *buf = malloc(sizeof(double) * (n + 2 * EL__NV * m));
    if (!buf) return EL_ENOMEM;
    el__spsnap start = {buf, buf + n, buf + n + EL__NV * m, 0.0};
    el__snap_save(w, &start);
    int st = follow_length(w, max_steps, Lt);
    if (st == EL_ENOCONV && w->lmode && w->resid <= EL__SP_NEAR) w->near = 1;
    if (st == EL_ENOCONV && !w->near) {
        /* Newton stalls where a piece passes the separatrix (k^2 = 1, its parameters
         * singular there: K(k) infinite), e.g. all 8 pieces of a closed ring of 8 ducks on
         * a circle at 1.115 x the polygon (every longer length failed): again, leaping
         * once over a stall (steps down to 1e-3 of the largest that worked) by 4 x that
         * step; the predictor interpolates the pieces' states, smooth there. Only after a
         * failure: leaping where the plain path succeeds changed 6 of 1809 results (QA's
         * random ducks), to higher energies or failures */
        el__snap_load(w, &start);
        w->lmode = 0;
        el__chain_eval(w, 1);
        w->leap = 1;
        st = follow_length(w, max_steps, Lt);
        w->leap = 0;
        if (st == EL_ENOCONV && w->lmode && w->resid <= EL__SP_NEAR) w->near = 1;
    }
    free(buf);
    return st;
}
/* ------------------------------------------------------------------ G2 ends */

/* The end curvatures kg from par[0..1] (t = 0) to par[2..3], linearly. */
static void set_end_curvature(el__spchain *w, double t, const double *par)
{
    for (int e = 0; e < 2; e++) w->kg[e] = t >= 1.0 ? par[2 + e] : par[e] + t * (par[2 + e] - par[e]);
}

/*
 * G2 ends: from the guided G1 sibling in w (el__guides_setup: a solution for
 * its own end curvatures w->kg) to the end curvatures kg, by continuation in
 * them (the whole step first), at the tension or length of w. A straight
 * sibling's pieces (k = 0, where q is undefined and J singular) start from the
 * linearised batten first. Already there (kg equal to the sibling's): EL_OK.
 */
int el__spline_bend_ends(el__spchain *w, int max_steps, const double kg[2])
{
    if (w->kg[0] == kg[0] && w->kg[1] == kg[1]) return EL_OK;
    for (size_t j = 0; j < w->m; j++) {
        if (w->pc[j].v[EL__SP_K] != 0.0) continue;
        el__sptargets t;
        el__chain_targets(w, j, &t);
        if (el__spiece_start(&w->pc[j], &t)) return EL_ENOCONV;
    }
    const double par[4] = {w->kg[0], w->kg[1], kg[0], kg[1]};
    return continuation(w, w->snap, max_steps, 1.0, set_end_curvature, par, w->aim, w->tol);
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

/* K(lambda) on the free knots i0..i1 (their slopes; the curvature jumps as
 * equations: symmetric tridiagonal, diagonal dg, off-diagonal up); returns the
 * number of its negative eigenvalues (Sylvester: the negative pivots of
 * L D L^T; GSL has no inertia count). */
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
    int neg = 0;
    double d = 0.0;
    for (size_t i = i0; i <= i1; i++) {
        d = i == i0 ? w->dg[i] : w->dg[i] - w->up[i - 1] * w->up[i - 1] / d;
        if (d == 0.0) d = -1e-300;
        neg += d < 0.0;
    }
    return neg;
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
    const size_t nf = i1 - i0 + 1;
    buckling_matrix(w, i0, i1, hi * (1.0 - 1e-12));
    for (size_t i = i0; i <= i1; i++) w->z[i] = 1.0;
    gsl_vector_view d = gsl_vector_view_array(w->dg + i0, nf), b = gsl_vector_view_array(w->b + i0, nf);
    gsl_vector_view x = gsl_vector_view_array(w->z + i0, nf);
    for (int it = 0; it < 3; it++) {
        double norm = 0.0;
        for (size_t i = i0; i <= i1; i++) norm = fmax(norm, fabs(w->z[i]));
        for (size_t i = i0; i <= i1; i++) w->b[i] = w->z[i] / norm;
        if (nf == 1) { w->z[i0] = w->b[i0] / w->dg[i0]; continue; }
        gsl_vector_view e = gsl_vector_view_array(w->up + i0, nf - 1);
        if (gsl_linalg_solve_symm_tridiag(&d.vector, &e.vector, &b.vector, &x.vector)) return EL_ENOCONV;
    }
    return el__all_finite(w->z + i0, nf) ? EL_ENOCONV : EL_OK;
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
    if (i0 <= i1 && i1 < n) {
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
        st = continuation(w, w->snap, max_steps, 0.25, set_length, par, w->aim, w->tol);
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
        if (!sm) sm = continuation(w, w->snap, max_steps, 0.25, set_ducks, par, w->aim, w->tol);
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
            el__chain_eval(w, 0);
        }
    }
    free(par);
    return st;
}
