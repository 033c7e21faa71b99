/*
 * Length mode by the tension (spline.c, spline_path.c): where following the family from the
 * free batten (or from a batten under tension when there is none) does not reach the length,
 * the tension solutions themselves, as tension mode finds them, bracket it: the length of
 * the solutions along a family falls as the tension grows (a batten is shorter pulled
 * harder), so a ladder of tensions from the taut batten (sigma h^2 = EL__SP_HIGH_SIGMA on
 * the mean chord) up (x 2) or down (/ 2) meets one longer and one shorter than the length;
 * from the nearer of the two in length the bracket is narrowed along its family by
 * continuation in sigma, and the length followed from there as from the free batten
 * (el__spline_length_from), else from the other. Tried only where the other paths failed:
 * no result they reach changes.
 * Measured: QA13's 8-point walk (no free batten: it slides off its ducks) reached no length
 * 1.03 .. 15 x its polygon, tension mode 1.04 .. 13 x (sigma h^2 200 .. 0.01 on the longest
 * span): now every one of those, at those tensions; the 12 closed ducks of a random ring
 * (QA's ring77) none at any length, now the 11 lengths 1.23 .. 40 x of its tensions 0.03 ..
 * 100. On 3300 random problems (300 walks, sketches, rings, ducks near a line, tangent and
 * G2 ends; 5 tensions, 6 lengths 1.001 .. 4 x) 80 failures by length solved, the 3219 other
 * results bit for bit the same; the 323 lengths still beyond reach take ~2 x the CPU to say
 * so (22 -> 44 ms each). FAIR_RUNGS (below): of 923 problems (27 sets of ducks: walks, a
 * sketch, rings, a star, examples/ducks.csv; 13 tensions, their lengths and 9 lengths 1.001
 * .. 3 x) 4 lengths that gave a spline crossing itself now give a fair one (ring77 at 1.27,
 * 1.39, 1.5 x, ring41 at 1.5 x), the 919 others bit for bit the same; the 75 that still
 * cross themselves take ~4 x the CPU to say so (32 -> 122 ms each), the rest as before.
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>

/* The ladder: at most LADDER_UP tensions above EL__SP_HIGH_SIGMA, LADDER_DOWN below (sigma
 * h^2 on the mean chord: 40 x 2^6 = 2560 at the top, where a piece's tail multiplies a
 * change at its start by ~exp(sqrt(sigma / 2) h) (elastica.h, Accuracy); 40 / 2^16 ~ 6e-4
 * at the bottom, a batten ~ 40 x its polygon when it has no free batten) */
enum { LADDER_UP = 6, LADDER_DOWN = 16 };

static double total_length(const el__spchain *w)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[EL__SP_L];
    return L;
}

/* RUNG_MEMO: the first ladder's solves (without NEIGHBOURS), each rung's status and chain
 * (where one was reached), from which the second ladder's solve at that rung goes on
 * (el__spline_tension_neighbours: NEIGHBOURS begins with that same solve) instead of making
 * it again, and which serves the first ladder's own second solve at the taut batten (up
 * without a bracket); its results bit for bit the same. At most one a rung (40 x 2^-16 ..
 * 2^6). */
enum { MEMO = LADDER_UP + LADDER_DOWN + 1 };
typedef struct {
    int n;
    double sigma[MEMO], resid[MEMO], den[MEMO], gres[MEMO];
    int st[MEMO], near[MEMO];
    el__spsnap s[MEMO];
} rung_memo;

static void memo_save(el__spchain *w, rung_memo *mm, int st)
{
    const int i = mm->n++;
    mm->sigma[i] = w->sigma;
    mm->st[i] = st;
    mm->near[i] = w->near;
    mm->resid[i] = w->resid;
    mm->den[i] = w->den;
    mm->gres[i] = w->Gres;
    if (st == EL_OK || w->near) el__snap_save(w, &mm->s[i]);
}

static void memo_load(el__spchain *w, const rung_memo *mm, int i)
{
    if (mm->st[i] == EL_OK || mm->near[i]) el__snap_load_states(w, &mm->s[i]);
    w->sigma = mm->sigma[i];
    w->near = mm->near[i];
    w->resid = mm->resid[i];
    w->den = mm->den[i];
    w->Gres = mm->gres[i];
}

/* Tension mode's solution at sigma into w (el__spline_solve_tension, to tol; mm: the
 * RUNG_MEMO, or NULL): 1 when one was reached (or one to what the parametrisation
 * resolves), 0 when none, -1 out of memory */
static int tension_at(el__spchain *w, int max_steps, double sigma, rung_memo *mm)
{
    w->lmode = 0;
    w->near = 0;
    w->sigma = sigma;
    int i = 0;
    while (mm && i < mm->n && mm->sigma[i] != sigma) i++;
    int st;
    if (mm && i < mm->n) {
        memo_load(w, mm, i);
        st = w->neighbours ? el__spline_tension_neighbours(w, max_steps, mm->st[i], sigma) : mm->st[i];
    } else {
        st = el__spline_solve_tension(w, max_steps, 1);
        if (mm && !w->neighbours && i == mm->n && i < MEMO && st != EL_ENOMEM) memo_save(w, mm, st);
    }
    if (st == EL_ENOMEM) return -1;
    const int ok = st == EL_OK || w->near;
    w->near = 0;
    w->lmode = 0;
    return ok && isfinite(el__chain_eval(w, 1));
}

/* a rung at sigma reached: into w->ladder */
static void note_rung(el__spchain *w, double sigma)
{
    w->ladder[0] = w->ladder[0] > 0.0 ? fmin(w->ladder[0], sigma) : sigma;
    w->ladder[1] = fmax(w->ladder[1], sigma);
}

/* sigma(t) geometrically from par[0] (t = 0) to par[1] */
static void set_sigma(el__spchain *w, double t, const double *par)
{
    w->sigma = t >= 1.0 ? par[1] : par[0] * pow(par[1] / par[0], t);
}

/*
 * The bracket narrowed along the family of the solution in w (its length La; the bracket's
 * other end at sb, Lb): the tension where the secant of log sigma against the length says
 * Lt (kept REFINE_IN inside the bracket) is reached by continuation in sigma from w's and
 * replaces the end on its side; w stays at the last one reached. At most REFINE steps,
 * until the length is within rtol of Lt. EL_OK, or EL_ENOMEM.
 */
enum { REFINE = 30 };
#define REFINE_IN 0.1
static int narrow(el__spchain *w, int max_steps, double Lt, double La, double sb, double Lb, double rtol)
{
    double sa = w->sigma;
    for (int it = 0; it < REFINE && fabs(La - Lt) > rtol * Lt && sa > 0.0 && sb > 0.0; it++) {
        const double f = fmin(fmax((Lt - La) / (Lb - La), REFINE_IN), 1.0 - REFINE_IN);
        const double par[2] = {sa, sa * pow(sb / sa, f)};
        const int st = el__spline_continuation(w, w->snap, max_steps, 1.0, set_sigma, par,
                                               1e-3 * EL__SP_NEAR, EL__SP_NEAR);
        if (st == EL_ENOMEM) return st;
        if (st) break;   /* w at the last tension it reached: a start as good */
        const double L = total_length(w);
        if ((L - Lt) * (La - Lt) <= 0.0) { sb = sa; Lb = La; }
        sa = par[1];
        La = L;
    }
    w->lmode = 0;
    w->near = 0;
    el__chain_reeval(w, 1);
    return EL_OK;
}

/*
 * The two ways from a rung (end[e]) to the length: narrowed to COARSE (Newton on the length
 * is then mostly in its basin: the rungs at 42 and 58 about 55 on the walk failed from
 * either), then el__spline_length_from; else narrowed to a tenth of tol (at high tension
 * the length's Newton step leaves the pieces' basin: a random walk of 5 ducks at sigma h^2
 * = 50 on the mean chord, the length 3e-4 of it away, its first step left a knot residual
 * of 0.76), then Newton with the length as the equation from there.
 */
#define COARSE 1e-3
static int from_state(el__spchain *w, int max_steps, double Lt, double sb, double Lb, int fine)
{
    w->lmode = 0;
    w->near = 0;
    el__chain_reeval(w, 1);
    int st = narrow(w, max_steps, Lt, total_length(w), sb, Lb, fine ? 0.1 * w->tol : COARSE);
    if (st) return st;
    if (!fine) return el__spline_length_from(w, max_steps, Lt);
    w->lmode = EL__BORDER_LENGTH;
    w->Lt = Lt;
    st = el__chain_newton(w, EL__SP_DIRECT_ITER, w->aim, w->tol);
    if (st == EL_ENOCONV && w->resid <= EL__SP_NEAR) w->near = 1;
    return st;
}

/* A spline reached (st, w) ranked: 3 not crossing itself, 2 crossing, 1 near (w->near), 0
 * none; -1 out of memory */
static int rank(el__spchain *w, int st)
{
    if (st == EL_ENOMEM) return -1;
    if (st != EL_OK) return w->near;
    const int c = el__chain_crosses(w);
    return c < 0 ? -1 : 3 - c;
}

/* The spline in w (length L, on side of the bracket) kept as its side's fair rung where it
 * does not cross itself (FAIR_RUNGS): el__chain_crosses's answer, -1 out of memory */
static int keep_if_fair(el__spchain *w, double L, int side, el__spsnap fair[2], double flen[2], int hfair[2])
{
    const int c = el__chain_crosses(w);
    if (c == 0) {
        el__snap_save(w, &fair[side]);
        flen[side] = L;
        hfair[side] = 1;
    }
    return c;
}

/*
 * FAIR_RUNGS: the ways from the rungs that do not cross themselves (fair[e], hfair[e]; the
 * other end: its side's fair rung, else its rung), where the ways from the bracket's own
 * rungs reached only splines crossing themselves: ring77 (12 closed ducks) at the length
 * of its fair spline at sigma h^2 20 on the longest span (2.75 on the mean chord, 1.266 x
 * its polygon) had rungs 10 (fair, 1.152 x), 5 (crossing, 1.260 x) and 2.5 (crossing,
 * 1.562 x), and the family through each crosses itself at that length (sigma h^2 35.7).
 * Into kept (its rank *best) where a way ranks higher. The status of the last way.
 */
static int fair_ways(el__spchain *w, int max_steps, double Lt, const el__spsnap end[2], const double len[2],
                     const el__spsnap fair[2], const double flen[2], const int hfair[2], el__spsnap *kept,
                     int *best)
{
    int st = EL_ENOCONV;
    for (int k = 0; k < 4 && *best < 3 && !el__spwork_spent(w->work); k++) {   /* (below) */
        const int e = k % 2;
        const int ofair = hfair[1 - e] && fair[1 - e].sigma != end[1 - e].sigma;
        if (!hfair[e] || (fair[e].sigma == end[e].sigma && !ofair)) continue;   /* a way tried */
        el__snap_load(w, &fair[e]);
        const el__spsnap *o = hfair[1 - e] ? &fair[1 - e] : &end[1 - e];
        st = from_state(w, max_steps, Lt, o->sigma, hfair[1 - e] ? flen[1 - e] : len[1 - e], k >= 2);
        const int r = rank(w, st);
        if (r < 0) return EL_ENOMEM;
        if (r > *best) { el__snap_save(w, kept); *best = r; }
    }
    return st;
}

/*
 * FINE_RUNGS: tension mode's splines at FINE - 1 tensions between the bracket's rungs
 * (geometrically), each solved afresh: one that does not cross itself replaces its side's
 * fair rung where its length is nearer Lt. Tension mode's fair branches can lie between
 * two rungs: ring77's at sigma h^2 19 .. 27.5 on the longest span (1.296 .. 1.227 x),
 * between rungs crossing themselves at 18.2 and 36.4. 1 where a rung was replaced, 0 where
 * none, -1 out of memory.
 */
enum { FINE = 8 };
#define NEAR_RUNG 2.01   /* a rung of the ladder (x 2) and rounding */
static int fine_rungs(el__spchain *w, int max_steps, double Lt, const el__spsnap end[2], el__spsnap fair[2],
                      double flen[2], int hfair[2])
{
    const double s0 = end[0].sigma, s1 = end[1].sigma;
    if (!(s0 > 0.0) || !(s1 > 0.0)) return 0;
    int fresh = 0;
    for (int j = 1; j < FINE; j++) {
        const double sigma = s0 * pow(s1 / s0, (double)j / FINE);
        const int r = tension_at(w, max_steps, sigma, NULL);
        if (r < 0) return -1;
        if (!r) continue;
        note_rung(w, sigma);
        const double L = total_length(w);
        const int side = L >= Lt ? 0 : 1, c = el__chain_crosses(w);
        if (c < 0) return -1;
        if (c || (hfair[side] && fabs(flen[side] - Lt) <= fabs(L - Lt))) continue;
        el__snap_save(w, &fair[side]);
        flen[side] = L;
        hfair[side] = 1;
        fresh = 1;
    }
    return fresh;
}

/* The rungs: end[0] longer than Lt (a lower tension), end[1] shorter (have[e]: reached);
 * fair[e]: the last on each side that does not cross itself (FAIR_RUNGS); met: the rungs'
 * lengths, the least, the greatest, the greatest not crossing itself (REACH). -1 out of
 * memory, else 0 */
static int ladder(el__spchain *w, int max_steps, double Lt, el__spsnap end[2], double len[2], int have[2],
                  el__spsnap fair[2], double flen[2], int hfair[2], double met[3], rung_memo *mm)
{
    /* down from the taut batten until a rung says which way (up, from above it, when the
     * first is longer than Lt) */
    double sigma = EL__SP_HIGH_SIGMA, top = EL__SP_HIGH_SIGMA * (double)(1 << LADDER_UP);
    double bottom = EL__SP_HIGH_SIGMA / (double)(1 << LADDER_DOWN);
    int up = -1;
    while (sigma >= bottom && sigma <= top) {
        const int r = tension_at(w, max_steps, sigma, mm);
        if (r < 0) return -1;
        if (r) {
            const double L = total_length(w);
            note_rung(w, sigma);
            const int side = L >= Lt ? 0 : 1;
            met[0] = fmin(met[0], L);
            met[1] = fmax(met[1], L);
            const int c = keep_if_fair(w, L, side, fair, flen, hfair);
            if (c < 0) return -1;
            if (!c) met[2] = fmax(met[2], L);
            el__snap_save(w, &end[side]);   /* the last on its side: the nearest to the other */
            len[side] = L;
            have[side] = 1;
            if (have[0] && have[1]) break;
            if (up < 0 && side == 0 && sigma < EL__SP_HIGH_SIGMA) sigma = EL__SP_HIGH_SIGMA;
            if (up < 0) up = side == 0;
        } else if (up == 1) {
            break;   /* up, a failed rung ends it: a higher tension fails the more */
        }
        sigma = up == 1 ? 2.0 * sigma : 0.5 * sigma;
    }
    /* up without a bracket: a rung solved from scratch can land on another family (QA14's
     * 14 sketched clicks: 40 -> 13.0716, 80 -> 14.3157, longer, 160 none), so again from the
     * taut batten, each rung by continuation in sigma from the last (its family) */
    if (up == 1 && !have[1]) {
        const double STEP = 1.189207115002721;   /* 2^(1/4) */
        const int r0 = tension_at(w, max_steps, EL__SP_HIGH_SIGMA, mm);
        if (r0 < 0) return -1;
        if (r0) note_rung(w, EL__SP_HIGH_SIGMA);
        if (r0 && total_length(w) >= Lt) {   /* the bracket's long end on this family */
            el__snap_save(w, &end[0]);
            len[0] = total_length(w);
        }
        /* TAUT_FAILS: no taut batten (ring77: none at 40, its fair rung at 20 of 1.116 x its
         * polygon longer than 1.1 x, 80 none): from the long end's rung up its family */
        const int r1 = !r0 && have[0];
        sigma = EL__SP_HIGH_SIGMA;
        if (r1) {
            el__snap_load(w, &end[0]);
            w->lmode = 0;
            w->near = 0;
            sigma = end[0].sigma;
        }
        if (r1 && !isfinite(el__chain_eval(w, 1))) sigma = top;
        for (; (r0 || r1) && len[0] == total_length(w) && sigma < top;) {
            const double par[2] = {sigma, STEP * sigma};
            const int sc = el__spline_continuation(w, w->snap, max_steps, 1.0, set_sigma, par,
                                                   1e-3 * EL__SP_NEAR, EL__SP_NEAR);
            if (sc == EL_ENOMEM) return -1;
            if (sc) break;
            sigma = par[1];
            note_rung(w, sigma);
            w->lmode = 0;
            w->near = 0;
            if (!isfinite(el__chain_eval(w, 1))) break;
            const double L = total_length(w);
            const int side = L >= Lt ? 0 : 1;
            met[0] = fmin(met[0], L);
            if (side == 0 && L > len[0]) break;   /* not shorter: not the family's way */
            if (keep_if_fair(w, L, side, fair, flen, hfair) < 0) return -1;
            el__snap_save(w, &end[side]);
            len[side] = L;
            have[side] = 1;
            if (side) break;
        }
    }
    return 0;
}

int el__spline_length_by_tension(el__spchain *w, int max_steps, double Lt, int least)
{
    if (!(Lt > 0.0)) return EL_ENOCONV;
    const size_t n = w->n, m = w->m, ns = n + 2 * EL__NV * m;
    double *buf = malloc((5 + MEMO) * ns * sizeof *buf);
    if (!buf) return EL_ENOMEM;
    rung_memo mm;
    mm.n = 0;
    for (int i = 0; i < MEMO; i++) {
        double *b = buf + (5 + i) * ns;
        mm.s[i] = (el__spsnap){b, b + n, b + n + EL__NV * m, 0.0};
    }
    /* the bracket: end[0] longer than Lt (a lower tension), end[1] shorter; kept: the
     * best spline reached from them */
    el__spsnap end[2] = {{buf, buf + n, buf + n + EL__NV * m, 0.0},
                         {buf + ns, buf + ns + n, buf + ns + n + EL__NV * m, 0.0}};
    el__spsnap kept = {buf + 2 * ns, buf + 2 * ns + n, buf + 2 * ns + n + EL__NV * m, 0.0};
    /* FAIR_RUNGS: the last rung on each side that does not cross itself */
    el__spsnap fair[2] = {{buf + 3 * ns, buf + 3 * ns + n, buf + 3 * ns + n + EL__NV * m, 0.0},
                          {buf + 4 * ns, buf + 4 * ns + n, buf + 4 * ns + n + EL__NV * m, 0.0}};
    double len[2] = {0.0, 0.0}, flen[2] = {0.0, 0.0};
    int have[2] = {0, 0}, hfair[2] = {0, 0};
    /* the rungs' lengths: the least, the greatest, the greatest not crossing itself (REACH) */
    double met[3] = {HUGE_VAL, 0.0, 0.0};
    if (ladder(w, max_steps, Lt, end, len, have, fair, flen, hfair, met, &mm)) { free(buf); return EL_ENOMEM; }
    /* NEIGHBOURS_RUNGS: no bracket, again with tension mode's NEIGHBOURS at each rung (spline_path.c:
     * the solve el_spline_solve makes at that tension; from the first ladder's solve at the rungs
     * it made, RUNG_MEMO); its rungs and lengths kept only where it reaches a spline (below) */
    double met0[3] = {0.0, 0.0, 0.0}, ladder0[2] = {0.0, 0.0};
    const int again = !(have[0] && have[1]);
    if (again) {
        memcpy(met0, met, sizeof met0);
        memcpy(ladder0, w->ladder, sizeof ladder0);
        have[0] = have[1] = hfair[0] = hfair[1] = 0;
        len[0] = len[1] = flen[0] = flen[1] = 0.0;
        w->neighbours = 1;
        const int r = ladder(w, max_steps, Lt, end, len, have, fair, flen, hfair, met, &mm);
        w->neighbours = 0;
        if (r) { free(buf); return EL_ENOMEM; }
    }
    /* the ways from the rungs (from_state) until one reaches a spline that does not cross
     * itself; else the first that crosses itself, else the first near one */
    int st = EL_ENOCONV, best = 0;
    double kept_resid = HUGE_VAL;
    if (have[0] && have[1]) {
        const int first = fabs(len[0] - Lt) <= fabs(len[1] - Lt) ? 0 : 1;   /* the nearer in length */
        /* no way begun once the call's budget is spent (WORK_BUDGET, spline.c): each would only
         * re-evaluate its rung (from_state, narrow, el__spline_length_from: up to 7 past the
         * budget) and fail; ring77 by length went 21 past it (revA) */
        for (int k = 0; k < 4 && best < 3 && !el__spwork_spent(w->work); k++) {
            const int e = k % 2 ? 1 - first : first;
            el__snap_load(w, &end[e]);
            st = from_state(w, max_steps, Lt, end[1 - e].sigma, len[1 - e], k >= 2);
            const int r = rank(w, st);
            if (r < 0) { st = EL_ENOMEM; break; }
            if (r > best || (least && r == 1 && best == 1 && w->resid < kept_resid)) {
                el__snap_save(w, &kept);
                best = r;
                kept_resid = w->resid;
            }
        }
        /* FAIR_RUNGS: where the ways reached splines crossing themselves and none that does
         * not, the same ways from the rungs that do not cross themselves, then from finer
         * rungs between the bracket's two (FINE_RUNGS); only where the ladder's fair splines
         * reach the bracket (a fair rung on its long side, or its short side's within a rung
         * of it): beyond them (ring77 at 3 .. 22 x its polygon) the search costs 2-5 x the
         * CPU to end crossing itself all the same */
        const int near_fair =
            best == 2 && (hfair[0] || (hfair[1] && fair[1].sigma <= NEAR_RUNG * end[1].sigma));
        if (st != EL_ENOMEM && near_fair) st = fair_ways(w, max_steps, Lt, end, len, fair, flen, hfair, &kept, &best);
        if (st != EL_ENOMEM && near_fair && best < 3) {
            const int fresh = fine_rungs(w, max_steps, Lt, end, fair, flen, hfair);
            if (fresh < 0) st = EL_ENOMEM;
            else if (fresh) st = fair_ways(w, max_steps, Lt, end, len, fair, flen, hfair, &kept, &best);
        }
        if (st != EL_ENOMEM && best > 0) {
            el__snap_load(w, &kept);
            w->lmode = EL__BORDER_LENGTH;
            w->Lt = Lt;
            el__chain_reeval(w, 1);
            w->near = best == 1;
            st = best == 1 ? EL_ENOCONV : EL_OK;
        }
    }
    if (again && st != EL_OK && st != EL_ENOMEM && !w->near) {   /* as without NEIGHBOURS_RUNGS */
        memcpy(met, met0, sizeof met0);
        memcpy(w->ladder, ladder0, sizeof ladder0);
    }
    /* REACH: where no family was followed (w->reach empty: ring77, its tension mode's fair
     * splines ending at 1.11 x its polygon, said "no spline reached" at 1.1 x), the lengths
     * of the rungs, for the EL_ERANGE a length beyond them gets (spline.c) */
    if (st != EL_OK && st != EL_ENOMEM && !w->near && w->reach[1] == 0.0 && met[1] > 0.0)
        for (int i = 0; i < 3; i++) w->reach[i] = met[i];
    free(buf);
    return st;
}
