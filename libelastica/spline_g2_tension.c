/*
 * Tension mode's G2 battens by their length (spline.c): where no G2 batten is reached at
 * the tension asked by bending the G1 sibling's ends (spline_guide.c, solve_g2), the
 * length whose G2 batten, as length mode finds it, has that tension. A ladder of lengths
 * brackets the tension, GSL's Brent narrows the bracket on the length, and Newton at the
 * tension from the batten there finishes (so the result is tension mode's, to tol).
 * Why the guided path fails: it needs the G1 sibling at that tension, and at sigma = 0
 * that is the free batten with the G2 ends clamped, which need not exist where the G2
 * batten does: walls (tangents opposite, normal to the chord) have no free clamped batten
 * (it slides off its ducks: el_hermite_solve finds none), but the guides hold the G2 one;
 * by length its tension crosses 0 (QA: (100, 35) up to (0, 30) down, curvature 0 at
 * both: sigma 218.5 -> -3.9e-5, 219.5 -> +7.0e-6; 219.3 long at 0).
 * Measured (two points, G2 ends of curvature 0 or an arc's; 153 end pairs: walls 50 .. 200
 * apart at heights -50 .. 50, tilted 15 .. 30 deg, line to arc R 50 .. 200; sigma 0, 1e-5,
 * 1e-4, 5e-4, 1e-3): solved 482 -> 586 of 765 (sigma 0: walls 5 -> 45 of 45, tilted 30 ->
 * 69 of 72, arc 11 -> 34 of 36), every piece at the tension asked (to 4e-11 / d^2), the 482
 * solved before bit for bit the same (this runs only where they failed); 9 of the 104 new
 * ones loop (said so). CPU of a search: 0.08 .. 0.26 s (median 0.15), and as much where it
 * finds none (was 3 ms): most of it the ladder's short lengths, where length mode fails.
 * NO_TENSION: where none is found, the rungs' tensions nearest the one asked, below and above,
 * and their lengths, for the error (el_spline_result's ladder and reach; spline.c keeps the
 * nearer of these and where the free batten's family followed in tension stopped). A 90 deg
 * arc of radius 20 from the origin into a line from (90, 60) heading +x at tension 0.003 or
 * 0.01: an independent shooting solver's continuation of its three free battens (230, 143, 156
 * long: their branches meet, both sheets) spans tensions -4.43e-3 .. 1.708e-3 (the top 207
 * long), the next family by length 0.023 .. 0.074 (QA): none found between; the error names
 * 1.70e-3 (length 208) and 0.0305 (161), was "no spline through the points was reached".
 */
#include "internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

/* The ladder: multiples of the polygon's length, shortest first (the first bracket met is
 * tried first). A G2 batten's tension along its family rises from a push (short) through 0
 * towards an asymptote as it lengthens (walls: sigma d^2 ~ 24 from ~5 x their distance d),
 * then falls (spline_guide.c). */
static const double LADDER[] = {1.02, 1.05, 1.1, 1.2, 1.35, 1.5, 1.75, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0};
enum { NLADDER = sizeof LADDER / sizeof LADDER[0], BRENT_ITER = 60 };
/* Brent stops at this relative width on the length, or this gap in sigma h^2 (mean chord):
 * polish's Newton takes it from there */
static const double BRENT_REL = 1e-10, BRENT_GAP = 1e-9;

typedef struct {
    el__g2_length_solve solve;
    void *ctx;
    double target;   /* sigma (internal) */
    double last;     /* the length last solved (g holds its batten), NAN: none */
    double lastf;    /* its gap */
    int status;      /* the last solve's */
    double known[2][2];   /* the bracket's ends (length, gap): GSL's set evaluates them again */
} gap_problem;

/* sigma(L) - target of the G2 batten of length L; NAN where none (GSL's Brent stops) */
static double gap(double L, void *par)
{
    gap_problem *p = par;
    for (int i = 0; i < 2; i++)
        if (p->known[i][0] == L) return p->known[i][1];
    double sigma = NAN;
    p->status = p->solve(p->ctx, L, &sigma);
    p->last = p->status ? NAN : L;
    p->lastf = p->status ? NAN : sigma - p->target;
    return p->lastf;
}

/* Newton at the target from the batten in g (gap's last): EL_OK, EL_ENOCONV (g->near:
 * within EL__SP_NEAR) */
static int polish(el__spchain *g, double target)
{
    g->lmode = 0;
    g->near = 0;
    g->sigma = target;
    const int st = el__chain_newton(g, EL__SP_DIRECT_ITER, g->aim, g->tol);
    if (st && g->resid <= EL__SP_NEAR) g->near = 1;
    return st ? EL_ENOCONV : EL_OK;
}

/* Brent on (lo, hi) (gaps flo, fhi of opposite signs), then polish at its root: EL_OK,
 * EL_ENOCONV (g->near: within EL__SP_NEAR), EL_ENOMEM */
static int narrow(el__spchain *g, gap_problem *p, double lo, double flo, double hi, double fhi)
{
    gsl_function fn = {gap, p};
    gsl_root_fsolver *r = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!r) return EL_ENOMEM;
    p->known[0][0] = lo; p->known[0][1] = flo;
    p->known[1][0] = hi; p->known[1][1] = fhi;
    int st = gsl_root_fsolver_set(r, &fn, lo, hi) == GSL_SUCCESS ? EL_ENOCONV : EL_EINTERNAL;
    for (int it = 0; it < BRENT_ITER && st == EL_ENOCONV; it++) {
        if (gsl_root_fsolver_iterate(r) != GSL_SUCCESS) { st = EL_EINTERNAL; break; }
        const double a = gsl_root_fsolver_x_lower(r), b = gsl_root_fsolver_x_upper(r);
        if (gsl_root_test_interval(a, b, 0.0, BRENT_REL) == GSL_SUCCESS ||
            (p->last == gsl_root_fsolver_root(r) && fabs(p->lastf) <= BRENT_GAP))
            st = EL_OK;
    }
    const double L = gsl_root_fsolver_root(r);
    gsl_root_fsolver_free(r);
    p->known[0][0] = p->known[1][0] = NAN;
    g->near = 0;
    if (p->status == EL_ENOMEM) return EL_ENOMEM;
    if (st) return EL_ENOCONV;
    if (p->last != L) gap(L, p);
    g->near = 0;
    if (p->status) return p->status == EL_ENOMEM ? EL_ENOMEM : EL_ENOCONV;
    return polish(g, p->target);
}

int el__spline_g2_tension_by_length(el__spchain *g, el__g2_length_solve solve, void *ctx, double Lp,
                                    double sigma, double nearest[4])
{
    gap_problem p = {solve, ctx, sigma, NAN, NAN, EL_OK, {{NAN, NAN}, {NAN, NAN}}};
    double L0 = NAN, f0 = NAN;   /* the last rung solved, its gap */
    for (int i = 0; i < 4; i++) nearest[i] = NAN;
    for (int i = 0; i < NLADDER; i++) {
        const double L = LADDER[i] * Lp, f = gap(L, &p);
        if (p.status == EL_ENOMEM) return EL_ENOMEM;
        if (p.status) continue;
        /* the rungs' tensions nearest the target below and above it (NO_TENSION) */
        const int up = f > 0.0;
        if (!(fabs(f) >= fabs(nearest[2 * up] - sigma))) {
            nearest[2 * up] = sigma + f;
            nearest[2 * up + 1] = L;
        }
        /* g->near only as polish sets it (a near batten by length is not one at sigma) */
        g->near = 0;
        int st = EL_ENOCONV;
        if (f == 0.0) st = polish(g, sigma);
        else if (isfinite(f0) && (f0 < 0.0) != (f < 0.0)) st = narrow(g, &p, L0, f0, L, f);
        if (st == EL_OK || st == EL_ENOMEM || g->near) return st;
        L0 = L;   /* else on up the ladder (a bracket across two families, or a gap) */
        f0 = f;
    }
    g->near = 0;
    return EL_ENOCONV;
}
