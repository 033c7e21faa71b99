/*
 * Elastic splines (issue 14): a chain of smooth elasticae of one tension
 * through N points, G2 at every point. The files:
 *   spline.c        the API: checks, units, the degenerate cases, the paths a solve
 *                   tries and its verdict, the B-spline of the whole chain;
 *   spline_result.c the result from a solved chain (user units, the residual, circle
 *                   pieces and the separatrix bound);
 *   spline_chain.c  the unknowns and equations, Newton on the whole chain, its start;
 *   spline_path.c   the paths to tension mode's solution, the length mode;
 *   spline_continuation.c continuation along a family: snapshots, predictor, steps;
 *   spline_g2_bend.c G2 ends: the end curvatures bent from the G1 sibling's, past folds;
 *   spline_bracket.c length mode from tension mode's splines that bracket the length,
 *                   where following the family failed;
 *   spline_buckle.c the buckled strip: collinear ducks, ducks near a line;
 *   spline_guide.c  G2 ends: the guide ducks (why, and where);
 *   spline_piece.c  one piece: residuals, Jacobians, its state, its start;
 *   spline_fair.c   does the spline follow its ducks (no self-crossing).
 *   spline_stable.c is the spline a minimum (its second variation at the knots): free,
 *                   by tension, by length.
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
 * Internal units: lengths divided by the mean chord (S), so sigma h^2 and the
 * residuals are scale-free; pieces are rescaled on output with x0, y0 the
 * given points exactly.
 */
#include "internal.h"
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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
    free(res->pieces); free(res->forces); free(res->angles); free(res->curvatures);
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
    if (o->initial && o->closed) return EL_EINVAL;
    return EL_OK;
}

/*
 * The sibling from the caller's pieces (opt->initial): each piece's parameters
 * in the internal units, phi moved by whole turns so that the angles continue
 * along the chain and meet a clamped start; the knot angles from them (a
 * clamped end's angle takes the winding the pieces give it); sigma from the
 * first piece in length mode; then Newton on the chain (its own start is not
 * tried: the caller chose the branch). EL_EINVAL for pieces that do not fit.
 */
static int sibling_from_initial(el__spchain *w, const double *xy, const el_spline_options *opt,
                                double S)
{
    const size_t n = w->n, m = w->m;
    if (opt->ninitial != m) return EL_EINVAL;
    double prev = w->kind[0] != EL_SPLINE_NATURAL ? w->th_end[0] : NAN;
    for (size_t j = 0; j < m; j++) {
        const el_smooth_params *p = &opt->initial[j];
        if (el_smooth_check(p) || !(p->length > 0.0) ||
            hypot(p->x0 - xy[2 * j], p->y0 - xy[2 * j + 1]) > 1e-6 * w->pc[j].h * S)
            return EL_EINVAL;
        const double s2[2] = {0.0, p->length};
        double th[2];
        int st = el_smooth_eval(p, 2, s2, NULL, th, NULL);
        if (st) return st;
        const double turn = isfinite(prev) ? 2.0 * M_PI * nearbyint((prev - th[0]) / (2.0 * M_PI)) : 0.0;
        el__spiece *pc = &w->pc[j];
        pc->v[EL__SP_PHI] = p->phi + turn;
        pc->v[EL__SP_NU] = log(p->mu * S * S);
        pc->v[EL__SP_K] = p->k;
        pc->v[EL__SP_Q] = p->q;
        pc->v[EL__SP_L] = p->length / S;
        if (w->slot[j] == EL__SLOT_ANGLE) w->x[j] = th[0] + turn;
        prev = th[1] + turn;
        if (j == 0 && w->lmode) w->sigma = 2.0 * p->mu * (2.0 * p->k * p->k - 1.0) * S * S;
    }
    if (w->slot[n - 1] == EL__SLOT_ANGLE) w->x[n - 1] = prev;
    else w->th_end[1] = prev + el__wrap_pi(w->th_end[1] - prev);
    /* straight (k = 0), J is singular: the line through collinear points is a solution at
     * every tension (kappa = 0), kept as solve_sibling's; other straight pieces start from
     * the linearised batten, as in el__spline_bend_ends */
    int straight = !w->lmode && isfinite(el__chain_eval(w, 0));
    for (size_t j = 0; j < m && straight; j++)
        straight = w->pc[j].v[EL__SP_K] == 0.0 && el__max_abs(w->pc[j].R, 4) <= w->aim;
    for (size_t i = 0; i < n && straight; i++) straight = fabs(w->F[i]) <= w->aim;
    if (straight) return EL_OK;
    for (size_t j = 0; j < m; j++) {
        if (w->pc[j].v[EL__SP_K] != 0.0) continue;
        el__sptargets t;
        el__chain_targets(w, j, &t);
        if (el__spiece_start(&w->pc[j], &t)) return EL_ENOCONV;
    }
    return el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol);
}

/* The spline of the chain w (its G2 ends clamped only): tension, length,
 * buckled or straight. st: EL_OK, or EL_ENOCONV with w->near (a solution to
 * what the parametrisation resolves), or an error. *straight: the line. */
static int solve_sibling(el__spchain *w, const double *xy, size_t n, const el_spline_options *opt,
                         double Lp, double S, int *straight)
{
    const int lmode = w->lmode;
    double dir;
    *straight = 0;
    if (el__spline_straight_line(xy, n, opt, &dir) && (!lmode || opt->length <= Lp * (1.0 + 1e-14))) {
        for (size_t i = 0; i < n; i++) if (w->slot[i] == EL__SLOT_ANGLE) w->x[i] = dir;
        for (size_t j = 0; j < w->m; j++) {
            el__spiece *pc = &w->pc[j];
            pc->v[EL__SP_PHI] = dir; pc->v[EL__SP_NU] = log(1.0 / (pc->h * pc->h));
            pc->v[EL__SP_K] = 0.0; pc->v[EL__SP_Q] = 0.0; pc->v[EL__SP_L] = pc->h;
        }
        if (lmode) { w->sigma = 0.0; w->Lt = Lp / S; }
        el__chain_reeval(w, 0);
        *straight = 1;
        return EL_OK;
    }
    if (!lmode) {
        w->neighbours = 1;
        const int st = el__spline_solve_tension(w, opt->max_steps, 1);
        w->neighbours = 0;
        return st;
    }
    if (el__spline_straight_line(xy, n, opt, &dir))   /* longer than the line */
        return el__spline_solve_buckled(w, opt->max_steps, dir, Lp / S, opt->length / S, 0);
    const int st = el__spline_near_line(xy, n, opt, &dir)   /* buckled near it, or from the free batten */
                       ? el__spline_solve_near_line(w, opt->max_steps, dir, opt->length / S)
                       : el__spline_solve_length(w, opt->max_steps, opt->length / S);
    /* neither reached the length: from the tension solutions that bracket it (spline_bracket.c) */
    return st == EL_ENOCONV && !w->near ? el__spline_length_by_tension(w, opt->max_steps, opt->length / S, 0) : st;
}

/* Of a G2 batten reached through a fold (first) and the one by the other path (g, its
 * status st), the fairer (el__g2_fairer) into g, the other freed: EL_OK, or EL_ENOMEM.
 * tie_first: first kept where g is not fairer beyond el__g2_fairer's 1e-9 (else g) */
static int keep_fairer(el__spchain *first, el__spchain *g, int st, int tie_first)
{
    const int f = st || g->near ? 0 : tie_first ? el__g2_fairer(g, first) : el__g2_fairer(first, g);
    if (f < 0 || st == EL_ENOMEM) { el__chain_free(first); return EL_ENOMEM; }
    const int keep_g = !st && !g->near && (tie_first ? !f : f);
    if (!keep_g) { el__chain_free(g); *g = *first; g->near = 0; } else el__chain_free(first);
    return EL_OK;
}

/*
 * G2 ends (spline_guide.c): from the sibling w (its G2 ends clamped only;
 * sib: the status of its solve) into g, the guides placed on it and the end
 * curvatures bent to kg at its tension or length. In length mode (Lt: the
 * length; 0: tension mode, or a sibling the caller chose), when the sibling or
 * that continuation fails (the length can be nearly flat in sigma,
 * as between two points: sigma then runs far for a small change of the ends),
 * again from the free batten's sibling, bent at its tension and followed in
 * length as any spline (spline_path.c). In tension mode (sigma_t: the tension,
 * NAN for a sibling the caller chose) likewise, followed in sigma: bending the
 * ends of a taut sibling can fail where the free batten bends them (the ducks
 * of examples/ducks.csv, start tangent (0, 1) with curvature -0.5, end (0, 1)
 * with 0.3: EL_ENOCONV from sigma = 0.05, converged at 0).
 * fair: the bends pass folds (spline_g2_bend.c), and one reached so is compared with the
 * free batten's path, the fairer kept; 0 (the rungs of tension mode's search by length,
 * which is compared so itself): as before, neither.
 * FREE_FAMILY (fair, length mode): a G2 batten the sibling's bend reached directly is compared
 * with the free batten's path too, and kept unless that one is fairer (beyond 1e-9): bending a
 * sibling at a fixed length can land on another branch than the G2 free batten's family. A 90
 * deg arc of radius 20 from the origin into a line from (90, 60) heading +x: by length 175 /
 * 180 / 182.5 bending 0.217 / 0.411 / 0.219 (sigma +0.026, -0.0049, +0.024) where the free
 * batten's family (230.05 long at sigma 0) has 0.1587 / 0.1604 / 0.1613 (QA16's shooting
 * solver: 0.16044 at 180, sigma -1.52e-3). The free family is followed in length without
 * el__spline_length_from's retries (g->plain): with them 4 more were fairer, at up to 25 x the
 * instructions. Measured on 1687 G2 solves by length (arcs of radius 10 .. 40 into lines, 160
 * end pairs x 7 lengths; walls, tilted walls, line to arc, 153 x 3; sketches of 3 .. 5 ducks,
 * 36 x 3): 34 fairer (bending 38.3 -> 0.236 the most; one that looped now does not), the rest
 * as before bit for bit (1134 solved, 515 failing with the same status), none lost.
 * Instructions per solve on 36 of the 1134: 1.64 x the median (quartiles 1.05 .. 1.95, at
 * most 8.4 x), 1.35 x in all (the free batten's family followed in length).
 */
static int solve_g2(el__spchain *w, el__spchain *g, int sib, int max_steps, const double kg[2],
                    double Lt, double sigma_t, int fair, double reached[2])
{
    int st = sib;
    if (!st || w->near) {
        st = el__guides_setup(g, w);
        if (!st) st = el__spline_bend_ends(g, max_steps, kg, fair);
        if ((!st && !g->bent_arc && !(fair && Lt != 0.0)) || g->near) return st;
    }
    if (st == EL_ENOMEM || (Lt == 0.0 && !(isfinite(sigma_t) && sigma_t != 0.0))) return st;
    /* reached through a fold (spline_g2_bend.c): the path below too, the fairer kept */
    el__spchain first = *g;
    const int arc = !st, direct = arc && !g->bent_arc;   /* FREE_FAMILY */
    if (!arc) el__chain_free(&first);
    memset(g, 0, sizeof *g);
    w->near = 0;
    if (!(st = el__spline_free_batten(w, max_steps)) && !(st = el__guides_setup(g, w))) {
        g->plain = direct;   /* FREE_FAMILY: a comparison only */
        if (!(st = el__spline_bend_ends(g, max_steps, kg, fair)) || g->near) {
            g->near = 0;
            st = Lt != 0.0 ? el__spline_length_from(g, max_steps, Lt) : el__spline_tension_from(g, max_steps, sigma_t);
            if (st == EL_ENOCONV && Lt == 0.0 && reached) {   /* where the G2 free batten's family stopped */
                reached[0] = g->sigma;
                reached[1] = 0.0;
                for (size_t j = 0; j < g->m; j++) reached[1] += g->pc[j].v[EL__SP_L];
            }
        }
    }
    if (!arc) return st;
    return keep_fairer(&first, g, st, direct);
}

/* WORK_BUDGET: chain evaluations one el_spline_solve CALL may spend, shared by every solve
 * and search it makes (the paths of the solve, tension mode's G2 search by length with its
 * up to NLADDER + BRENT_ITER solves, el__spline_largest's up to 18 solves): max_steps x
 * max_iter x (WORK_FAMILIES + WORK_SHORT / m) for m pieces. el__chain_eval counts each
 * evaluation and makes none past it (spline_chain.c), so every path ends at its next one, and
 * el__chain_start_pieces begins no start (each counted as one); el__chain_reeval, a known
 * state evaluated again after a search, is let through and counted: a few past it at most.
 * A budget for each solve (8 x max_steps x max_iter, cee94bf) bounded a solve, not a call:
 * the fuzz's 7 ducks at sigma 49.5 with a G2 start (9291f637) spent 805 120 evaluations
 * (9.7 s of CPU) over the search by length's solves, each within its own; now 96 000.
 * MEASURED, NOT DERIVED: sized on the work of every el_spline_solve call of
 * tests/c/test_spline*.c, test_bspline, bench_spline and tests/python (1379 calls, none
 * bounded, a logging build not committed; ffdd424's message). The most for m >= 2: QA16's
 * shipline, 68 points by length 1.5 x, 35 364 = 9.82 x max_steps x max_iter (5.0 s), within
 * 61 038 (margin 1.73); for one piece: test_spline_g2's 2-point G2 batten by tension through
 * its search by length, 198 716 = 55.2 x (an evaluation of one piece being cheap, 0.42 s),
 * within 288 000 (margin 1.45). WORK_SHORT / m is fitted to those two points (m = 67 and
 * m = 1) only: it lets the short chains' many cheap evaluations through without giving a
 * long chain's expensive ones as many. */
#define WORK_FAMILIES 16
#define WORK_SHORT 64
static unsigned long work_budget(const el_spline_options *opt, size_t n)
{
    const size_t m = opt->closed ? n : n > 1 ? n - 1 : 1;
    const unsigned long si = (unsigned long)opt->max_steps * (unsigned long)opt->max_iter;
    return si * WORK_FAMILIES + si * WORK_SHORT / (m ? m : 1);
}

/* Tension mode's G2 batten by its length (spline_g2_tension.c): one solve by length as
 * el__spline_solve_paths's (solve_sibling, then solve_g2), into the sibling w and the
 * guided chain g */
typedef struct {
    el__spchain *w, *g;
    const double *xy, *kg;
    size_t n;
    const el_spline_options *opt;
    double Lp, S;
} g2_length;

static int g2_at_length(void *par, double L, double *sigma)
{
    const g2_length *c = par;
    el__spchain *w = c->w, *g = c->g;
    el_spline_options o = *c->opt;
    o.mode = EL_SPLINE_LENGTH;
    o.length = L * c->S;
    o.initial = NULL;
    o.ninitial = 0;
    el__chain_free(g);
    memset(g, 0, sizeof *g);
    w->lmode = EL__BORDER_LENGTH;
    w->sigma = 1.0;
    w->Lt = L;
    w->near = 0;
    memset(w->reach, 0, sizeof w->reach);
    memset(w->ladder, 0, sizeof w->ladder);
    /* the call's budget (WORK_BUDGET): spent, no further solve is begun */
    if (el__spwork_spent(w->work)) return EL_ENOCONV;
    int straight;
    int st = solve_sibling(w, c->xy, c->n, &o, c->Lp, c->S, &straight);
    if (st != EL_ENOMEM && st != EL_EINVAL) st = solve_g2(w, g, st, o.max_steps, c->kg, L, NAN, 0, NULL);
    if (st == EL_ENOMEM || st == EL_EINVAL) return st;
    if (st && !g->near) return EL_ENOCONV;
    *sigma = g->sigma;
    return EL_OK;
}

/* The lengths the family followed in length mode met (w or the G2 chain g; spline_path.c's
 * note_reach) into res->reach, user units; 0 when none was met */
static int reach_of(const el__spchain *w, const el__spchain *g, double S, el_spline_result *res)
{
    const el__spchain *c = g->reach[1] > w->reach[1] ? g : w;
    for (int i = 0; i < 3; i++) res->reach[i] = c->reach[i] * S;
    for (int i = 0; i < 2; i++) res->ladder[i] = w->ladder[i] / (S * S);
    return c->reach[1] > 0.0;
}

/* The solve's verdict on a result: within tol, or a circle piece / one near the
 * separatrix within what el_smooth_params resolves (header) */
static int accepted(const el_spline_result *res, double tol, double other, double sep)
{
    return res->residual <= tol ||
                   (other <= tol && res->residual <= EL__SP_CIRCLE_RESID && (sep == 0.0 || res->residual <= sep))
               ? EL_OK : EL_ENOCONV;
}

/* Length mode again by the tension (el__spline_length_by_tension, the near spline of least
 * residual) into *r: EL_OK for a spline accepted and not crossing itself, EL_ENOMEM, else EL_ENOCONV (r empty) */
static int by_tension_again(el__spchain *w, const double *xy, size_t n, const el_spline_options *opt,
                            double S, el_spline_result *r)
{
    memset(r, 0, sizeof *r);
    w->near = 0;
    int st = el__spline_length_by_tension(w, opt->max_steps, opt->length / S, 1);
    if (st == EL_ENOMEM) return st;
    if (st && !w->near) return EL_ENOCONV;
    double other, sep;
    if ((st = el__spline_make_result(w, xy, n, S, opt->tol, r, &other, &sep))) return st;
    const int cr = el__spline_loops(r->pieces, r->npieces, opt->closed);
    st = cr < 0 ? EL_ENOMEM : cr ? EL_ENOCONV : accepted(r, opt->tol, other, sep);
    if (st) el_spline_result_free(r);
    return st;
}

/* STABLE_FAMILY: res from w (tension mode's own solve, accepted) an equilibrium that is no
 * minimum: the stable one el__spline_stable_family finds instead, made anew into res where
 * make_result accepts it, looping no more (*cr its loops; Lp the polygon); else res as it was (w then holds the other, which
 * el__spline_unstable_result loads res back over: its length differs). EL_OK or EL_ENOMEM. */
static int stable_instead(el__spchain *w, const double *xy, size_t n, const el_spline_options *opt, double S,
                          double Lp, el_spline_result *res, int *cr)
{
    int found;
    int st = el__spline_stable_family(w, opt->max_steps, &found);
    if (st == EL_ENOMEM) { el_spline_result_free(res); return st; }
    if (!found) return EL_OK;
    el_spline_result r2;
    double other, sep;
    st = el__spline_make_result(w, xy, n, S, opt->tol, &r2, &other, &sep);
    if (st == EL_ENOMEM) { el_spline_result_free(res); return st; }
    if (st) return EL_OK;
    const int c2 = el__spline_loops(r2.pieces, r2.npieces, opt->closed);
    if (c2 < 0) { el_spline_result_free(&r2); el_spline_result_free(res); return EL_ENOMEM; }
    if (c2 > *cr || accepted(&r2, opt->tol, other, sep)) { el_spline_result_free(&r2); return EL_OK; }
    r2.loops = c2 || r2.length > 4.0 * Lp;
    el_spline_result_free(res);
    *res = r2;
    *cr = c2;
    return EL_OK;
}

/*
 * UNITS: the spline works in units of the mean chord S (lengths / S, sigma S^2, kappa S);
 * what those units cannot represent is refused before any search (EL_EDOM): S outside
 * [1e-150, 1e150] (as el_fit's extent, prep.c, and el_affine_polyline's edges), and a
 * tension sigma S^2, a length L / S or a G2 end's curvature |kappa| S above UNITS_MAX. Why 1e150: the
 * pieces' equations carry the squares of these (mu = (kappa_m^2 - sigma) / 4 in the
 * internal units, the force |F| = kappa_m^2 - sigma, sigma h^2 in the pieces' starts,
 * the energy's integral kappa^2), so at 1e150 they stay within 1e300 < DBL_MAX, and
 * S^2 and 1 / S^2 (the result's forces and tension back in user units) do too. Such a
 * batten is no batten (a bend of 1e150 radians per chord): the searches only spent the
 * call's budget on it (the fuzz's 36 collinear ducks with a G2 end of curvature 1.8e308
 * x the chord: 1 s for EL_ERANGE; 14 ducks at 1e300 with sigma 42.3, sigma S^2
 * overflowing: 0.7 s for EL_ENOCONV). Closed splines have no ends to check.
 */
#define UNITS_MAX 1e150
static int outside_units(const el_spline_options *opt, double S)
{
    if (!(S >= 1.0 / UNITS_MAX && S <= UNITS_MAX)) return 1;
    if (opt->mode == EL_SPLINE_TENSION && !(opt->sigma * S * S <= UNITS_MAX)) return 1;
    /* the length L / S too: past DBL_MAX (points at 1e-20, length 1e300) the length's
     * equation read inf and the free batten, 1e-320 of the length, came back EL_OK */
    if (opt->mode == EL_SPLINE_LENGTH && !(opt->length / S <= UNITS_MAX)) return 1;
    if (opt->closed) return 0;
    const el_spline_end *e[2] = {&opt->start, &opt->end};
    for (int i = 0; i < 2; i++)
        if (e[i]->kind == EL_SPLINE_G2 && !(fabs(e[i]->curvature) * S <= UNITS_MAX)) return 1;
    return 0;
}

/* el__spline_solve_paths, with the longest span h (user units) into *longest once the
 * chords are valid (el__spline_largest's h) */
static int solve_paths(const double *xy, size_t n, const el_spline_options *opt, int newton_first,
                       el__spwork *shared, el_spline_result *res, double *longest)
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
    double Lp = 0.0, scale = 0.0, hmax = 0.0;
    for (size_t i = 0; i < n; i++) scale = fmax(scale, fmax(fabs(xy[2 * i]), fabs(xy[2 * i + 1])));
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % n;
        const double h = hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        if (!(h > 4.0 * DBL_EPSILON * scale) || !isfinite(h)) return EL_EINVAL;
        Lp += h;
        hmax = fmax(hmax, h);
    }
    *longest = hmax;
    if (!isfinite(Lp)) return EL_EINVAL;
    const int lmode = opt->mode == EL_SPLINE_LENGTH;
    if (lmode && opt->length < Lp * (1.0 - 1e-14)) return EL_EDOM;
    if (outside_units(opt, Lp / (double)m)) return EL_EDOM;

    el__spchain w, g;
    memset(&g, 0, sizeof g);
    el__spchain *sol = &w;   /* the chain the result comes from */
    el__spwork own = {0, work_budget(opt, n), 0}, *wk = shared ? shared : &own;   /* the call's */
    int st = el__chain_alloc(&w, n, m);
    w.work = wk;
    if (st) goto done;
    const double S = Lp / (double)m;   /* the unit: mean chord */
    w.closed = closed; w.lmode = lmode; w.newton_first = newton_first;
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
        w.slot[i] = EL__SLOT_ANGLE;
    }
    double kg[2] = {0.0, 0.0};   /* G2 ends' curvatures (internal units) */
    if (!closed) {
        /* the chord angles at both ends, the last one unwrapped along the chain
         * (as the knot angles are): a clamped end is within pi of its chord */
        double chord[2] = {atan2(w.pc[0].dy, w.pc[0].dx), 0.0};
        chord[1] = chord[0];
        for (size_t j = 1; j < m; j++)
            chord[1] += el__wrap_pi(atan2(w.pc[j].dy, w.pc[j].dx) - atan2(w.pc[j - 1].dy, w.pc[j - 1].dx));
        const el_spline_end *e[2] = {&opt->start, &opt->end};
        for (int i = 0; i < 2; i++) {
            w.kind[i] = e[i]->kind;
            if (e[i]->kind == EL_SPLINE_NATURAL) continue;
            const double c = chord[i];
            w.th_end[i] = c + el__wrap_pi(atan2(e[i]->tangent[1], e[i]->tangent[0]) - c);
            if (e[i]->kind == EL_SPLINE_G2) kg[i] = e[i]->curvature * S;
            w.slot[i ? n - 1 : 0] = EL__SLOT_FIXED;   /* G2: clamped in the sibling */
        }
    }

    /* two points clamped at both ends, by length: Newton from the least-energy Hermite
     * elastica of that length (el_hermite_solve), the curve the header promises; the chain's
     * own start and its continuation from the free batten failed beyond 1.06 x the free
     * batten's length ((0,0) -> (3,1), both tangents (1,0): EL_ENOCONV from 3.4 where four
     * solutions exist) and at 3.3 followed a branch of 6 % more energy */
    el_hermite_result hermite;
    memset(&hermite, 0, sizeof hermite);
    el_spline_options with_start;
    if (lmode && !closed && n == 2 && !opt->initial && w.kind[0] == EL_SPLINE_TANGENT &&
        w.kind[1] == EL_SPLINE_TANGENT) {
        el_hermite_options ho;
        el_hermite_options_defaults(&ho);
        ho.mode = EL_HERMITE_LENGTH;
        ho.length = opt->length;
        st = el_hermite_solve(xy, opt->start.tangent, xy + 2, opt->end.tangent, &ho, &hermite);
        if (st == EL_ENOMEM) goto done;
        if (!st && hermite.count > 0 && hermite.solutions[0].npieces == 1) {
            with_start = *opt;
            with_start.initial = &hermite.solutions[0].curve;
            with_start.ninitial = 1;
            opt = &with_start;
        }
    }
    int straight = 0;
    st = opt->initial ? sibling_from_initial(&w, xy, opt, S) : solve_sibling(&w, xy, n, opt, Lp, S, &straight);
    if (st == EL_EINVAL) goto done;
    const int sibling = !st || w.near;   /* the free batten exists (for sigma = 0's EL_EDOM) */
    double nearest[4] = {NAN, NAN, NAN, NAN};   /* spline_g2_tension.c's NO_TENSION */
    if (st != EL_ENOMEM && !closed && (w.kind[0] == EL_SPLINE_G2 || w.kind[1] == EL_SPLINE_G2)) {
        /* from an initial sibling: its branch only (no free batten's) */
        st = solve_g2(&w, &g, st, opt->max_steps, kg, lmode && !opt->initial ? opt->length / S : 0.0,
                      lmode || opt->initial ? NAN : opt->sigma * S * S, 1, nearest);
        sol = &g;
        /* none at that tension: the length whose G2 batten has it (spline_g2_tension.c);
         * one reached through a fold (spline_g2_bend.c): that too, the fairer kept */
        const int arc = !st && g.bent_arc;
        if (((st && st != EL_ENOMEM && !g.near) || arc) && !lmode && !opt->initial) {
            el__spchain first = g;
            if (arc) memset(&g, 0, sizeof g);
            g2_length c = {&w, &g, xy, kg, n, opt, Lp, S};
            double rungs[4];
            st = el__spline_g2_tension_by_length(&g, g2_at_length, &c, Lp / S, opt->sigma * S * S, rungs);
            for (int i = 0; i < 2; i++)   /* nearest[0..1]: the free family's end; the nearer kept */
                if (isfinite(rungs[2 * i]) && !(fabs(rungs[2 * i] - opt->sigma * S * S) >=
                                                fabs(nearest[2 * i] - opt->sigma * S * S))) {
                    nearest[2 * i] = rungs[2 * i];
                    nearest[2 * i + 1] = rungs[2 * i + 1];
                }
            if (arc) st = keep_fairer(&first, &g, st, 0);
        }
    }
    if (st == EL_ENOMEM) goto done;
    /* a solution, or one to what the parametrisation resolves: a near chain only of pieces
     * (a failed search's may hold a negative length: QA16's shipline rows 179..246 by
     * length, -6.81, which make_result refused as EL_EINVAL for valid points) */
    if (!st || (sol->near && el__spline_pieces_drawn(sol))) {
        double other, sep;
        const int st2 = el__spline_make_result(sol, xy, n, S, opt->tol, res, &other, &sep);
        if (st2) { st = st2; goto done; }
        /* does it follow its ducks (spline_fair.c)? */
        int cr = el__spline_loops(res->pieces, res->npieces, closed);
        if (cr < 0) { el_spline_result_free(res); st = EL_ENOMEM; goto done; }
        res->loops = cr || (!lmode && res->length > 4.0 * Lp);
        if (lmode) reach_of(&w, &g, S, res);
        if (straight && lmode) { res->sigma = 0.0; goto done; }
        if (straight) goto done;
        /* circle pieces and pieces near the separatrix are accepted at what
         * el_smooth_params resolves (header); the latter within their bound */
        st = accepted(res, opt->tol, other, sep);
        /* the free batten found is no minimum: it slides off its ducks (spline_stable.c;
         * QA19: 5 ducks turning 163-172 deg, one negative eigenvalue each); by tension > 0 or
         * length: returned, res->unstable saying so (below) */
        /* an equilibrium that is no minimum: a stable one on the family from a tension ladder
         * instead where one is found (spline_stable.c's STABLE_FAMILY) */
        if (!st && !lmode && sol == &w && !opt->initial) {
            st = stable_instead(&w, xy, n, opt, S, Lp, res, &cr);
            if (st) goto done;
        }
        if (!st && opt->sigma == 0.0 && sol == &w) {
            size_t span;
            if (el__spline_unstable(&w, &span) > 0) {
                el_spline_result_free(res);
                res->slides = 1;
                res->slide_span = span;
                st = EL_EDOM;
            }
        }
        /* a near spline short of tol: from the tension splines that bracket the length
         * (spline_bracket.c; QA14's sheer at sigma h^2 300: 1.1e-7 at tol 1e-10 where
         * tension mode's spline is within 1.04e-9) */
        /* a spline by length that crosses itself where its ducks' polygon does not: the
         * bracket's (spline_bracket.c) where it reaches one that does not (ring77 at the
         * length of its fair spline at sigma h^2 20: a crossing one at 35.7) */
        if ((st == EL_ENOCONV || (st == EL_OK && cr)) && lmode && sol == &w && !opt->initial) {
            const int st0 = st;
            el_spline_result r2;
            st = by_tension_again(&w, xy, n, opt, S, &r2);
            if (st == EL_OK) {
                reach_of(&w, &g, S, &r2);
                el_spline_result_free(res);
                *res = r2;
            } else if (st == EL_ENOMEM) {
                el_spline_result_free(res);
            } else {
                st = st0;   /* the crossing one, res->loops saying so */
            }
        }
        if (!st && sol == &w && (lmode || opt->sigma > 0.0))
            res->unstable = el__spline_unstable_result(&w, res, S, lmode, &res->slide_span) > 0;
        goto done;
    }
    /* no solution found: for sigma = 0 the free-sliding batten slides off its ducks; a
     * length beyond those met following the family (REACH) */
    /* not where the call's budget ended the free batten's solve (WORK_BUDGET): whether it
     * slides is then unknown, EL_ENOCONV with stopped (1 x 1 steps said EL_EDOM) */
    st = !lmode && opt->sigma == 0.0 && !sibling && !wk->stopped ? EL_EDOM : EL_ENOCONV;
    if (lmode && reach_of(&w, &g, S, res)) st = EL_ERANGE;   /* within reach too (QA14) */
    /* G2 ends by tension: the tensions nearest it of the G2 battens the search by length met */
    for (int i = 0; i < 2 && !lmode; i++)
        if (isfinite(nearest[2 * i])) {
            res->ladder[i] = nearest[2 * i] / (S * S);
            res->reach[i] = nearest[2 * i + 1] * S;
        }
done:
    /* EL_EDOM too: a batten that slides off its ducks says what finding that cost */
    if (st == EL_OK || st == EL_ENOCONV || st == EL_ERANGE || st == EL_EDOM) {
        res->work = wk->evals;
        res->stopped = wk->stopped;
    }
    el_hermite_result_free(&hermite);
    el__chain_free(&w);
    el__chain_free(&g);
    return st;
}

int el__spline_solve_paths(const double *xy, size_t n, const el_spline_options *opt,
                           int newton_first, el_spline_result *res)
{
    double h;
    return solve_paths(xy, n, opt, newton_first, NULL, res, &h);
}

int el__spline_solve_within(const double *xy, size_t n, const el_spline_options *opt,
                            el__spwork *work, el_spline_result *res)
{
    double h;
    return solve_paths(xy, n, opt, 1, work, res, &h);
}

int el_spline_solve(const double *xy, size_t n, const el_spline_options *opt,
                    el_spline_result *res)
{
    double h = 0.0;
    /* one budget for the whole call (WORK_BUDGET), the largest's solves included */
    el__spwork call = {0, opt ? work_budget(opt, n) : 0, 0};
    const int st = solve_paths(xy, n, opt, 1, &call, res, &h);
    if (st != EL_ENOCONV) return st;
    /* a high tension that fails: the largest that solves (spline_limit.c), its solves
     * counted into res->work, within what the call has left */
    double largest[3];
    int nsolves;
    if (el__spline_largest(xy, n, opt, h, largest, &nsolves, &call)) { el_spline_result_free(res); return EL_ENOMEM; }
    for (int i = 0; i < 3; i++) res->largest[i] = largest[i];
    res->work = call.evals;
    res->stopped = call.stopped;
    return st;
}

/* ------------------------------------------------------------------ B-spline */

int el_spline_to_bspline(const el_spline_result *res, double tol, int degree, el_bspline *out)
{
    if (!res) return EL_EINVAL;
    return el_smooth_chain_to_bspline(res->pieces, res->npieces, tol, degree, out);
}
