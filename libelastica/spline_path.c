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

/* sigma(t) between par[0] (t = 0) and par[1] geometrically in sigma + par[2]. */
static void set_sigma(el__spchain *w, double t, const double *par)
{
    const double a = par[0] + par[2], b = par[1] + par[2];
    w->sigma = t >= 1.0 ? par[1] : a * pow(b / a, t) - par[2];
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

/* Longer than 4 x its ducks' polygon (el_spline_result's loops says so) */
static int too_long(const el__spchain *w)
{
    double poly = 0.0;
    for (size_t j = 0; j < w->m; j++) poly += w->pc[j].h;
    return total_length(w) > 4.0 * poly;
}

/* From the tension solution in w to the one at sigma (to EL__SP_NEAR); EL_OK or EL_ENOCONV. */
static int move_sigma(el__spchain *w, el__spsnap sv[2], int *steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    const int st = el__spline_continuation(w, sv, *steps, 1.0, set_sigma_linear, par,
                                1e-3 * EL__SP_NEAR, EL__SP_NEAR);
    (*steps)--;
    return st;
}

/* The chain's bending energy (its pieces', internal units) */
static double chain_energy(const el__spchain *w)
{
    double e = 0.0;
    for (size_t j = 0; j < w->m; j++) e += w->pc[j].energy;
    return e;
}

static double snap_length(const el__spchain *w, const el__spsnap *a)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += a->v[j * EL__NV + EL__SP_L];
    return L;
}

/* Points of the pseudo-arclength path: knot values and sigma, the norm
 * weighting sigma by 1/rho; with w->arc_len also the length (arc_len_coordinate). */
static double arc_dist(const el__spchain *w, const el__spsnap *a, const el__spsnap *b, double rho)
{
    double s2 = (b->sigma - a->sigma) * (b->sigma - a->sigma) / (rho * rho);
    for (size_t i = 0; i < w->n; i++) s2 += (b->x[i] - a->x[i]) * (b->x[i] - a->x[i]);
    if (w->arc_len) { const double dL = snap_length(w, b) - snap_length(w, a); s2 += dL * dL; }
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

/* The lengths met along the family (w->reach), for the error a length beyond them gets
 * (spline.c); -1 when out of memory */
static int note_reach(el__spchain *w)
{
    const double L = total_length(w);
    if (w->reach[1] == 0.0) w->reach[0] = w->reach[1] = L;
    w->reach[0] = fmin(w->reach[0], L);
    w->reach[1] = fmax(w->reach[1], L);
    if (L > w->reach[2]) {
        const int c = el__chain_crosses(w);
        if (c < 0) return -1;
        if (!c) w->reach[2] = L;
    }
    return 0;
}

int el__spline_follow_family(el__spchain *w, int max_steps, double Lt, int by_sigma)
{
    el__spsnap *sv = w->snap;
    int steps = max_steps;
    el__spsnap *B = &sv[2], *C = &sv[0];   /* the base point and the next one */
    const double rho = 1.0 + fabs(w->sigma);
    double gb = family_gap(w, Lt, by_sigma), gc;
    if (!by_sigma && note_reach(w)) return EL_ENOMEM;
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
            el__chain_reeval(w, 1);
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
            if (w->arc_len) {
                w->arc_L0 = snap_length(w, C);
                w->arc_c = (w->arc_L0 - snap_length(w, B)) / N;
            }
            w->arc_h = h;
            /* the change of length the secant predicts (JUMP, below) */
            const double dLp = by_sigma ? 0.0 : h / N * (snap_length(w, C) - snap_length(w, B));
            el__snap_predict(w, B, C, h / N);
            w->lmode = EL__BORDER_ARC;
            const int it0 = w->iterations;
            const int st = el__chain_newton(w, EL__SP_STEP_ITER, 1e-3 * EL__SP_NEAR, EL__SP_NEAR);
            w->lmode = 0;
                    if (st) {
                el__snap_load(w, C);
                h *= 0.5;
                if (h < 1e-3 * hgood && !leapt) {
                    if (w->leap) { leapt = 1; h = 4.0 * hgood; } else w->would_leap = 1;
                }
                continue;
            }
            hgood = fmax(hgood, h);
            leapt = 0;
            if (!by_sigma && note_reach(w)) return EL_ENOMEM;
            const double gn = family_gap(w, Lt, by_sigma);
            const int jumped = !by_sigma && h >= 0.75 * N && (gn - gc) * dLp < 0.0 && fabs(gn - gc) > fabs(dLp);
            if (jumped && !w->jump) w->would_jump = 1;
            if (jumped && w->jump) {
                /* JUMP: the length moved against the secant's prediction by more than it
                 * predicted: the corrector landed on another branch of the pieces, not on
                 * the family. QA21's 40 ducks at 1.05 x their polygon: one step from sigma
                 * h^2 = -0.90 (1.0499 x) to +2.32 (1.008 x, the taut branch), every length
                 * past 1.0499 x refused (EL_ERANGE); the family goes on through a second
                 * free batten (1.07 x). Only for a step not much shorter than the secant
                 * it extrapolates (h >= 0.75 N): for a quadratic L(s) the rule needs the
                 * fold in the length between (N - h) / 4 and N / 2 behind C, or up to
                 * (h - N) / 4 ahead of it (dLp = h (N + 2 s_f), the step's h (2 s_f - h)),
                 * so at most two halvings end it (h <= 2 N: one from h < 1.5 N; below 0.75
                 * N a fold there would halve to nothing: a 12-duck wave at 1.02 x). Before
                 * the bracket test: a step that brackets the target so is refused too (its
                 * bracket is on the other branch). w->jump: el__spline_length_from's last
                 * path */
                el__snap_load(w, C);
                h *= 0.5;
                continue;
            }
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
                el__snap_predict(w, C, D, gn / (gc - gn));
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
static int from_sigma_start(el__spchain *w, int max_steps, double sigma0, double target, double start_aim,
                            double start_accept, double aim, double accept, int taut, el__cont_rest *rest)
{
    const double par[3] = {sigma0, target, 1.0};
    if (rest && rest->valid)   /* where its first try ran out of steps */
        return el__spline_follow(w, w->snap, max_steps, 0.25, set_sigma, par, aim, accept, rest);
    w->sigma = sigma0;
    if (taut) el__chain_taut_angles(w); else el__chain_start_angles(w);
    const int st = el__chain_start_pieces(w);
    if (st) return st == EL_ENOMEM ? st : EL_ENOCONV;
    if (el__chain_newton(w, EL__SP_DIRECT_ITER, start_aim, start_accept) != EL_OK) return EL_ENOCONV;
    return el__spline_follow(w, w->snap, max_steps, 0.25, set_sigma, par, aim, accept, rest);
}

static int from_sigma(el__spchain *w, int max_steps, double sigma0, double target, double start_aim,
                      double start_accept, double aim, double accept)
{
    return from_sigma_start(w, max_steps, sigma0, target, start_aim, start_accept, aim, accept, 0, NULL);
}

/* The batten pulled from sigma0 to w->sigma (from_sigma), kept when it converges shorter
 * than the solution in w, which w->snap[2] holds meanwhile */
static void pull_from(el__spchain *w, int max_steps, double aim, double accept, double sigma0)
{
    const double target = w->sigma, was = total_length(w);
    el__snap_save(w, &w->snap[2]);
    if (from_sigma(w, max_steps, sigma0, target, aim, accept, aim, accept) || !(total_length(w) < was)) {
        el__snap_load(w, &w->snap[2]);
        el__chain_reeval(w, 0);
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

/*
 * TAUT_START: under a high tension the batten is its ducks' polygon with a boundary layer
 * at each duck (sinh / cosh, width ~ 1 / sqrt(sigma)), its tangent there the bisector of
 * the two chords (the layer is symmetric), along the chord at a natural end. The chain's
 * own start (the circles through three ducks) is far from that, and the pieces' steps
 * from it are cut to ~1e-3 .. 1e-2 (el__spiece_step_prepare): 20 iterations move the
 * residual from 7.6 to 7.0, and the continuation from sigma h^2 = 40 (or from the free
 * batten) stops in steps too short. From the bisectors Newton converges (damped, then
 * quadratically: 21 iterations at sigma x (longest span)^2 = 200 on 8 random ducks,
 * hence its own cap). Tried only where every other path failed (no result changes).
 * Measured on 30 random walks of 4-11 ducks and examples/ducks.csv, tol 1e-8, tension x
 * (longest span)^2 100 / 200 / 300 / 500 / 1000: solved 18 / 13 / 10 / 2 / 1 -> 29 / 26 /
 * 20 / 4 / 1 (one more at 100 ended crossing itself: refused). Beyond ~500 the pieces'
 * own conditioning stops it (elastica.h, Accuracy: a piece's tail multiplies a change at
 * its start by ~exp(sqrt(sigma / 2) h)).
 */
static int taut_start(el__spchain *w, int max_steps, double target, double aim, double accept, int loose)
{
    if (w->ng || !(target > 0.0)) return EL_ENOCONV;
    w->near = 0;
    w->sigma = target;
    el__chain_taut_angles(w);
    int st = el__chain_start_pieces(w);
    if (st) return st == EL_ENOMEM ? st : EL_ENOCONV;
    st = el__chain_newton(w, EL__SP_TAUT_ITER, aim, accept);
    if (st && w->resid <= EL__SP_NEAR) w->near = 1;
    else if (st)   /* else from the taut start at sigma h^2 = EL__SP_HIGH_SIGMA, followed to target */
        st = from_sigma_start(w, max_steps, EL__SP_HIGH_SIGMA, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim,
                              accept, 1, NULL);
    if (st == EL_ENOMEM || (st && !w->near)) return st;
    /* the taut batten, or nothing: a solution that winds away from its ducks is not it (2 closed
     * rings of random ducks at sigma h^2 ~ 30 ended crossing themselves); loose (TAUT_LOOPS): one
     * that loops is kept unless longer than 4 x its polygon (el_spline_result's loops says so) */
    const int wd = loose ? too_long(w) : el__chain_wanders(w);
    if (wd) w->near = 0;
    return wd ? EL_ENOCONV : st;
}

/*
 * LONG_PATH: under a high tension the continuation from sigma h^2 = EL__SP_HIGH_SIGMA to
 * the target crawls (a piece's tail multiplies a change at its start by ~exp(sqrt(sigma /
 * 2) h): Newton's steps are cut, continuation steps fail and halve) and runs out of steps
 * before it gets there: examples/ducks.csv at sigma x (longest span)^2 = 450 and 500 (on
 * the mean chord ~150, 170) had no spline at the default 60 steps; with 4 x as many (200
 * suffice) they are solved within their resolution (residual 2.5e-8, 3.6e-8; elastica.h:
 * Accuracy), 700 at no budget. On 23 random walks and sketches at 300 / 450 / 500 / 700:
 * 17 / 3 / 1 / 0 -> 19 / 11 / 8 / 2 solved without loops (tol 1e-8), the failures' CPU
 * ~2 x. Tried last, where every other path failed (no result changes). It goes on from
 * where the first continuation from EL__SP_HIGH_SIGMA ran out of steps (el__cont_rest: its two
 * snapshots, t and dt), instead of taking those steps again to the same state: every
 * failing rung near the limit ran out of them there.
 */
enum { LONG_PATH = 4 };

/* solve_tension_once's paths after its direct Newton (rest: LONG_PATH going on from where
 * the first continuation ran out of steps, or NULL) */
static int from_paths(el__spchain *w, int max_steps, int final, double aim, double accept, el__cont_rest *rest)
{
    const double target = w->sigma;
    /* from a high tension on the mean chord (the unit here) */
    int st = from_sigma_start(w, max_steps, EL__SP_HIGH_SIGMA, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim,
                              accept, 0, rest);
    if (final && st == EL_OK) return el__spline_refair(w, max_steps, st, target);
    if (st != EL_ENOCONV || w->near || !final || !(target > 0.0)) return st;
    /* else the free batten pulled to target (FREE_START) */
    st = from_sigma(w, max_steps, 0.0, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim, accept);
    st = w->near ? st : el__spline_refair(w, max_steps, st, target);
    if (st == EL_ENOCONV && !w->near) st = taut_start(w, max_steps, target, aim, accept, 0);
    /* above the high tension, last: its continuation again with LONG_PATH x the steps */
    if (st == EL_ENOCONV && !w->near && target > EL__SP_HIGH_SIGMA) {
        const int steps = max_steps < 1000 / LONG_PATH ? LONG_PATH * max_steps : 1000;
        st = from_sigma_start(w, steps, EL__SP_HIGH_SIGMA, target, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, aim, accept,
                              0, rest);
    }
    return st;
}

/* The tension solution at w->sigma: directly (one that winds away from its ducks: another
 * path to it, unwind), else by continuation from a high tension, else from the free batten.
 * final: to tol (else to EL__SP_NEAR, as a start for the length mode). */
static int solve_tension_once(el__spchain *w, int max_steps, int final)
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
    if (!final || !(target > EL__SP_HIGH_SIGMA)) return from_paths(w, max_steps, final, aim, accept, NULL);
    /* LONG_PATH may follow the first continuation: its state where it runs out of steps */
    const size_t nx = w->n, nv = EL__NV * w->m, ns = nx + 2 * nv;
    double *rb = malloc(2 * ns * sizeof *rb);
    if (!rb) return EL_ENOMEM;
    el__cont_rest rest = {{rb, rb + nx, rb + nx + nv, 0.0}, {rb + ns, rb + ns + nx, rb + ns + nx + nv, 0.0},
                      0.0, 0.0, 0.0, 0, 0};
    st = from_paths(w, max_steps, final, aim, accept, &rest);
    free(rb);
    return st;
}

/*
 * NEIGHBOURS (tension mode's own solve only, w->neighbours): where the tension solution
 * loops away from its ducks (loops_away) or none was reached, tension mode's fair
 * solutions at nearby tensions (x NEAR_TENSIONS, each solved as above) followed by
 * continuation in sigma to the tension asked: the paths from the taut batten and the free
 * batten jump family or stop at folds between fair branches (ring77: fair at sigma h^2 90
 * and 150 on the longest span, looping at 95 .. 120). The first that reaches it without
 * looping is kept; else the first result, as it was. Where none was reached, the
 * neighbours that loop are followed too (a second pass from the first's solutions, so the
 * first is as it was) and of those reaching it the least integral kappa^2 + sigma ds kept,
 * loops and all (el_spline_result's loops says so): QA's rw15 (a polygon crossing itself 5
 * times) at sigma h^2 2 .. 5 on the longest span, where every spline found loops round duck
 * 7 (fair ones only from ~18 up) and no path reached one.
 */
static const double NEAR_TENSIONS[] = {0.9, 1.1, 0.75, 1.3};
enum { NNEAR = sizeof NEAR_TENSIONS / sizeof NEAR_TENSIONS[0] };

/* Loops away from its ducks as el_spline_result's loops says (crossing itself where its
 * polygon does not, or longer than 4 x it: a batten longer than EL__SP_WANDER x that is
 * no reason to look further); -1 out of memory */
static int loops_away(const el__spchain *w)
{
    return too_long(w) ? 1 : el__chain_crosses(w);
}

/* The neighbour i solved (its loops_away into *l) and followed to target: EL_OK there,
 * EL_ENOMEM, else EL_ENOCONV (loopy: follow one that loops too, from its solution kept in
 * *nb by the pass that was not loopy; else *l 1 stops, its solution into *nb) */
static int from_neighbour(el__spchain *w, int max_steps, double target, size_t i, int loopy, int *l,
                          el__spsnap *nb)
{
    w->near = 0;
    w->lmode = 0;
    w->sigma = target * NEAR_TENSIONS[i];
    *l = 0;
    if (loopy) {   /* the same solve again would reach the same solution (a fresh start) */
        el__snap_load_states(w, nb);
        *l = 1;
    } else {
        const int sn = solve_tension_once(w, max_steps, 1);
        if (sn == EL_ENOMEM) return sn;
        if (sn != EL_OK || w->near) return EL_ENOCONV;
        if ((*l = loops_away(w)) < 0) return EL_ENOMEM;
        if (*l) { el__snap_save(w, nb); return EL_ENOCONV; }
    }
    const double par[2] = {w->sigma, target};
    const int sc = el__spline_continuation(w, w->snap, max_steps, 1.0, set_sigma_linear, par, w->aim, w->tol);
    return sc == EL_ENOMEM || sc == EL_OK ? sc : EL_ENOCONV;
}

/*
 * TAUT_LOOPS (tension mode's own solve, where every path failed): the taut start's solution
 * that loops, which taut_start refuses as a start, is the answer, flagged by the result's
 * loops. QA's random walks 46, 193, 195 (10 ducks, the polygon crossing itself) at sigma x
 * (longest span)^2 = 100 said EL_ENOCONV once the searches took the result's loop rule
 * (el__chain_crosses = el__spline_loops): every spline they reached loops.
 */
static int taut_loops(el__spchain *w, int max_steps, double target)
{
    w->lmode = 0;
    const int st = taut_start(w, max_steps, target, w->aim, w->tol, 1);
    return st == EL_OK || w->near ? st : EL_ENOCONV;
}

int el__spline_solve_tension(el__spchain *w, int max_steps, int final)
{
    const double target = w->sigma;
    const int st = solve_tension_once(w, max_steps, final);
    return final && w->neighbours ? el__spline_tension_neighbours(w, max_steps, st, target) : st;
}

int el__spline_tension_neighbours(el__spchain *w, int max_steps, int st, double target)
{
    if (w->near || !(target > 0.0) || (st != EL_OK && st != EL_ENOCONV)) return st;
    if (target > EL__SP_HIGH_SIGMA) return st == EL_ENOCONV ? taut_loops(w, max_steps, target) : st;
    const int la = st == EL_OK ? loops_away(w) : 1;
    if (la <= 0) return la < 0 ? EL_ENOMEM : st;
    const size_t n = w->n, m = w->m;
    const size_t ns = n + 2 * EL__NV * m;
    double *buf = malloc(sizeof(double) * (1 + NNEAR) * ns);
    if (!buf) return EL_ENOMEM;
    el__spsnap first = {buf, buf + n, buf + n + EL__NV * m, 0.0}, nb[NNEAR];
    for (size_t i = 0; i < NNEAR; i++) nb[i] = (el__spsnap){buf + (1 + i) * ns, buf + (1 + i) * ns + n,
                                                            buf + (1 + i) * ns + n + EL__NV * m, 0.0};
    if (st == EL_OK) el__snap_save(w, &first);
    w->neighbours = 0;
    int found = 0, looped[NNEAR] = {0};
    for (size_t i = 0; i < NNEAR && !found; i++) {
        const int sc = from_neighbour(w, max_steps, target, i, 0, &looped[i], &nb[i]);
        if (sc == EL_ENOMEM) { st = sc; break; }
        if (sc != EL_OK) continue;
        const int l = loops_away(w);
        if (l < 0) { st = EL_ENOMEM; break; }
        found = !l;
    }
    /* none reached: the neighbours that loop, followed to the tension asked; of those
     * reaching it the least integral kappa^2 + sigma ds (spline_fair.c's lagrangian) */
    int kept = 0;
    double low = HUGE_VAL;
    for (size_t i = 0; i < NNEAR && !found && st == EL_ENOCONV; i++) {
        if (!looped[i]) continue;
        int l;
        const int sc = from_neighbour(w, max_steps, target, i, 1, &l, &nb[i]);
        if (sc == EL_ENOMEM) { st = sc; break; }
        const double lag = chain_energy(w) + target * total_length(w);
        if (sc == EL_OK && lag < low) { el__snap_save(w, &first); low = lag; kept = 1; }
    }
    w->neighbours = 1;
    w->near = 0;
    w->lmode = 0;
    if (found) {
        st = EL_OK;
    } else if (st != EL_ENOMEM) {
        w->sigma = target;
        if (st == EL_OK || kept) { el__snap_load(w, &first); el__chain_reeval(w, 0); st = EL_OK; }
    }
    free(buf);
    if (st == EL_ENOCONV) st = taut_loops(w, max_steps, target);
    return st;
}

int el__spline_tension_from(el__spchain *w, int max_steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    return el__spline_continuation(w, w->snap, max_steps, 1.0, set_sigma_linear, par, w->aim, w->tol);
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
        if (st == EL_ENOCONV) {
            /* the taut batten from its own start (TAUT_START): 3 of 4 closed random rings
             * that failed at every length 1.02 .. 2 x now solve from 1.1 x (8 of their 12
             * lengths; those past ~1.5 x mostly loop, and say so) */
            w->lmode = 0;
            st = taut_start(w, max_steps, EL__SP_HIGH_SIGMA, 1e-3 * EL__SP_NEAR, EL__SP_NEAR, 0);
            w->near = 0;
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
        el__chain_reeval(w, 1);   /* the pieces' states, which follow_length's snapshots keep */
    }
    /* the start kept for a second attempt (below), and the first fallback's solution */
    const size_t n = w->n, m = w->m;
    double *buf = malloc(sizeof(double) * 2 * (n + 2 * EL__NV * m));
    if (!buf) return EL_ENOMEM;
    el__spsnap start = {buf, buf + n, buf + n + EL__NV * m, 0.0};
    double *b2 = buf + n + 2 * EL__NV * m;
    el__spsnap leapt = {b2, b2 + n, b2 + n + EL__NV * m, 0.0};
    el__snap_save(w, &start);
    w->would_leap = w->would_jump = 0;
    const int stopped0 = w->work->stopped;
    int st = follow_length(w, max_steps, Lt);
    if (st == EL_ENOMEM) { free(buf); return st; }
    /* SAME_PATH: the leap's and the jump's paths below start where this plain one did and
     * take its steps until their rule acts; where this path met no step at which it would
     * (w->would_leap, w->would_jump) and the call's budget did not end it, theirs are this
     * path step for step (el__spline_follow_family is deterministic in its start), to the
     * same failure: not run again. The 36 collinear ducks with G2 ends by length 6.9 x
     * (test_spline_work): 8 of the 12 paths of the bracket's ways and 2 of the free batten's
     * 4 were such copies */
    const int same_leap = !w->would_leap && !(w->work->stopped && !stopped0);
    const int same_jump = !w->would_jump && !(w->work->stopped && !stopped0);
    if (st == EL_ENOCONV && w->lmode && w->resid <= EL__SP_NEAR) w->near = 1;
    if (st == EL_ENOCONV && !w->near && !w->plain) {
        /* Newton stalls where a piece passes the separatrix (k^2 = 1, its parameters
         * singular there: K(k) infinite): again, leaping once over a stall (steps down to
         * 1e-3 of the largest that worked) by 4 x that step; the predictor interpolates the
         * pieces' states, smooth there. Only after a failure: leaping where the plain path
         * succeeds changed 6 of 1809 results (QA's random ducks), to higher energies or
         * failures */
        if (!same_leap) {
            el__snap_load(w, &start);
            w->lmode = 0;
            el__chain_reeval(w, 1);
            w->leap = 1;
            st = follow_length(w, max_steps, Lt);
            w->leap = 0;
            if (st == EL_ENOMEM) { free(buf); return st; }
        }
        int near = st == EL_ENOCONV && w->lmode && w->resid <= EL__SP_NEAR;
        /* ARC_LEN: the path stalls too where the knot angles stand still along the family
         * and only the pieces move: ducks with a symmetry that fixes every tangent (a ring of
         * ducks on a circle, a star), where sigma folds back: the path in (angles, sigma)
         * turns on the spot. With the length a coordinate of the path it passes the fold.
         * The star of 10 ducks (radii 20/8, closed) stalled at 1.242 x its polygon (sigma h^2
         * -19.39; no spline at 1.25..2 x), now reaches 2 x without loops; the ring of 8 ducks
         * on a circle leapt to a higher mode from 1.25 x (integral kappa^2 221 at 1.25 x, 241
         * at 1.3 x, 644 at 1.5 x), now 72.9, 85.9, 124.3 on its first mode. Of the two the
         * one that does not cross itself, then the lower integral kappa^2 (the length is
         * the same: the functional the length mode makes stationary; the leap's where they
         * are the same curve) */
        double e_leap = HUGE_VAL;
        int c_leap = 2;
        const int lm = w->lmode;
        if (st == EL_OK || near) {
            el__snap_save(w, &leapt);
            e_leap = chain_energy(w);
            if (st == EL_OK && (c_leap = el__chain_crosses(w)) < 0) { free(buf); return EL_ENOMEM; }
        }
        el__snap_load(w, &start);
        w->lmode = 0;
        w->near = 0;
        el__chain_reeval(w, 1);
        w->arc_len = 1;
        const int sa = follow_length(w, max_steps, Lt);
        w->arc_len = 0;
        if (sa == EL_ENOMEM) { free(buf); return sa; }
        int ca = 2;
        if (sa == EL_OK && (ca = el__chain_crosses(w)) < 0) { free(buf); return EL_ENOMEM; }
        if (sa == EL_OK && (st != EL_OK || ca < c_leap || (ca == c_leap && chain_energy(w) < e_leap * (1.0 - 1e-9)))) {
            st = EL_OK;
        } else if (st == EL_OK || near) {   /* the leap's */
            el__snap_load(w, &leapt);
            w->lmode = lm;
            w->Lt = Lt;
            el__chain_reeval(w, 0);
            w->near = near;
        } else if (sa == EL_ENOCONV && w->lmode && w->resid <= EL__SP_NEAR) {
            w->near = 1;
        }
        if (st != EL_OK && !w->near && !same_jump) {
            /* JUMP (el__spline_follow_family): the plain path again, refusing a step whose
             * length moves against the secant by more than it predicted (a leap onto
             * another branch). Only after every path failed: the rule halves steps of
             * paths that succeed without it, most to the same spline by other steps (on
             * every path 32 of 848 sweep results changed, the star of 10 ducks by length
             * met 1.12 .. 5.49 x its polygon without it, 4.57 x with it); a failure keeps
             * its state, its reach grown by the lengths this path met */
            el__snap_save(w, &leapt);
            const int lm0 = w->lmode;
            el__snap_load(w, &start);
            w->lmode = 0;
            el__chain_reeval(w, 1);
            w->jump = 1;
            const int sj = follow_length(w, max_steps, Lt);
            w->jump = 0;
            if (sj == EL_ENOMEM) { free(buf); return sj; }
            if (sj == EL_OK) {
                st = EL_OK;
            } else {
                el__snap_load(w, &leapt);
                w->lmode = lm0;
                w->Lt = Lt;
                el__chain_reeval(w, 0);
            }
        }
    }
    free(buf);
    return st;
}
