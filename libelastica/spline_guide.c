/*
 * G2 ends of an elastic spline (spline.c): the guide ducks.
 *
 * Counting. With the tension given, a spline through n points has n knot
 * angles as unknowns, and as equations the n - 2 interior curvature jumps and
 * one end condition per natural end (kappa = 0); a clamped end fixes its angle
 * and has no equation. A G2 end fixes the angle and asks the curvature too: one
 * equation more than unknowns, so each G2 end needs one unknown more.
 * A frictionless duck pushes only normal to the batten, which is exactly what a
 * common sigma means: with theta, kappa and sigma continuous at a knot, the
 * tangential part (sigma - kappa^2) of the force F (spline.c) is continuous, so
 * only the normal part 2 kappa' jumps. A span with a tension of its own is held
 * lengthwise by a duck with friction. And the extra unknown cannot be a free
 * duck placed by least energy: a minimum over its position would make its
 * force vanish, and a duck without force adds no condition (the G1 curve), so
 * a rule has to place it.
 * The rule: each G2 end has a guide duck inside its end span, a quarter of the
 * span's chord from that end (GUIDE_FRACTION; two G2 ends of one span: at 1/4
 * and 3/4), free to move only along the chord's normal; frictionless like the
 * others (theta and kappa continuous there, kappa' jumps). Unknowns: the
 * guide's offset along the normal and its tangent angle; equations: the given
 * curvature at the end and the curvature jump at the guide. The system stays
 * square, with the common sigma on every piece; the offsets border the
 * tridiagonal knot system (spline_chain.c).
 * Why a quarter. Linearised (small slopes, sigma h^2 small), a span [0, h]
 * clamped at both ends whose end curvature changes by D, with a guide at f h,
 * changes by w'' piecewise linear (w'''' = 0 on each side, w, w', w''
 * continuous): D at the end, -2 D f at the guide, D f / (1 - f) at the far
 * point (from int w'' = int (h - s) w'' = 0: the far end's tangent and
 * position). The bending energy adds int w''^2 = D^2 h (f/3 + O(f^2)), least
 * as f -> 0 (no minimum: the limit is a curvature jump at the end, as above);
 * the fairness int (w''')^2 = (D^2 / h) ((1 + 2f)^2 / f + f^2 (3 - 2f)^2 /
 * (1 - f)^3) is least at f = 0.262 (1/4: 0.2 % more; 1/2: 61 % more, and the
 * curvature swings D, -D, D there: extra inflections). Both ends of one span
 * G2: the least lies between f = 0.18 and 0.34 depending on the ratio of the
 * two changes (1/4 and 3/4 within 10 % of it). Measured on random battens
 * against 1/2 (header, G2 end): 1/4 solves more, in length mode too, with less
 * energy and fewer inflections.
 *
 * Path. The spline with its G2 ends only clamped (the G1 sibling, the same
 * points, tension or length) is solved first. On it each guide is placed where
 * the normal through its chord point meets the end span, splitting that piece
 * in two sub-arcs of the same elastica: the sibling is then an exact solution
 * of the guided system for the end curvatures it has, with no force on the
 * guides. The end curvatures are then moved to the given ones by continuation
 * (spline_g2_bend.c), which starts with the whole step and passes folds by pseudo-arclength. Tension mode where that finds
 * none (no G1 sibling at that tension: walls at sigma 0): by the length whose G2 batten
 * has the tension (spline_g2_tension.c).
 * Under tension. The guides' offsets are set by the end curvatures, not by least energy,
 * so along a family in sigma they do work: d(integral kappa^2 + sigma ds)/d sigma =
 * L + sum f . dg/d sigma (f: a guide's force, g: its place), not L (seed 004 (9)-(10) with
 * moving ducks), and the G2 batten need not shorten when pulled. As sigma h^2 grows a G2
 * end, its curvature given, has no boundary layer to turn in: the batten leaves it along
 * its tangent to the guide's line, tending to the polygon through the guides. Measured
 * (QA9 w5): ends (0, 0) up and (100, 0) down, curvature 0 (two walls), guides on x = 25,
 * 75: 231 long at sigma 0.0005, 319 at 0.002, 397 at 0.0023, none beyond ~0.0024 (by
 * length the tension tends to it as the batten rises without end); tilted ends (0.5, 1),
 * (0.5, -1): 139.5 at 0.002, 150 at 0.05, towards the polygon's 161.8. Each the least
 * integral kappa^2 + sigma ds of the battens bent from every G1 solution at that sigma.
 */
#include "internal.h"
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

/* A guide duck's place: this fraction of its span's chord from its G2 end (file comment). */
static const double GUIDE_FRACTION = 0.25;

/* The projection of a piece's point at arc length s on the chord direction u,
 * minus the target: the guide's foot is its root. */
typedef struct { el_smooth_params p; double ux, uy, target; } foot_problem;

static double foot_residual(double s, void *par)
{
    const foot_problem *f = par;
    double xy[2];
    if (el_smooth_eval(&f->p, 1, &s, xy, NULL, NULL)) return NAN;
    return xy[0] * f->ux + xy[1] * f->uy - f->target;
}

/* The arc length in (lo, hi) where the piece crosses the normal through the
 * chord's point at `target` along u (a sign change there: GSL's Brent). */
static int guide_foot(const foot_problem *f, double lo, double hi, double *s)
{
    gsl_function fn = {foot_residual, (void *)f};
    gsl_root_fsolver *r = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!r) return EL_ENOMEM;
    int st = gsl_root_fsolver_set(r, &fn, lo, hi) == GSL_SUCCESS ? EL_ENOCONV : EL_EINTERNAL;
    for (int it = 0; it < 100 && st == EL_ENOCONV; it++) {
        if (gsl_root_fsolver_iterate(r) != GSL_SUCCESS) { st = EL_EINTERNAL; break; }
        const double a = gsl_root_fsolver_x_lower(r), b = gsl_root_fsolver_x_upper(r);
        if (b - a <= 1e-15 * hi) st = EL_OK;
    }
    *s = gsl_root_fsolver_root(r);
    gsl_root_fsolver_free(r);
    return st;
}

/* Piece v from arc length a to b of the elastica v (the same phi, mu, k; u shifted). */
static void sub_arc(const double *v, double a, double b, double *out)
{
    memcpy(out, v, EL__NV * sizeof *out);
    out[EL__SP_Q] = v[EL__SP_Q] + sqrt(exp(v[EL__SP_NU])) * a;
    out[EL__SP_L] = b - a;
}

/*
 * The guided chain g of the solved sibling w (open, ng G2 ends clamped in w):
 * the knots of w with the guide ducks inserted (after point 0, before the last
 * point), the end spans split at them, the G2 ends' slots holding the guides'
 * offsets, kg[] the sibling's own end curvatures (g solves exactly). g is
 * allocated here (free it with el__chain_free also on failure).
 */
int el__guides_setup(el__spchain *g, const el__spchain *w)
{
    const size_t n0 = w->n, m0 = w->m;
    const int gs = w->kind[0] == EL_SPLINE_G2, ge = w->kind[1] == EL_SPLINE_G2, ng = gs + ge;
    const size_t n = n0 + (size_t)ng, m = m0 + (size_t)ng;
    int st = el__chain_alloc(g, n, m);
    if (st) return st;
    g->lmode = w->lmode; g->newton_first = w->newton_first;
    g->tol = w->tol; g->max_iter = w->max_iter; g->aim = w->aim;
    g->sigma = w->sigma; g->sigma_user = w->sigma_user; g->Lt = w->Lt;
    g->iterations = w->iterations;
    g->work = w->work;
    g->ng = ng;
    for (int e = 0; e < 2; e++) { g->kind[e] = w->kind[e]; g->th_end[e] = w->th_end[e]; }
    g->kg[0] = w->pc[0].kap0;
    g->kg[1] = w->pc[m0 - 1].kap1;
    /* knots: point i of w is knot i + (i > 0 ? gs : 0) + (i == n0 - 1 ? ge : 0) */
    for (size_t i = 0; i < n0; i++) {
        const size_t k = i + (i > 0 ? (size_t)gs : 0) + (i == n0 - 1 ? (size_t)ge : 0);
        g->x[k] = w->x[i];
        g->slot[k] = w->slot[i];
    }
    /* the guides: fractions of their span's chord */
    int count = 0;
    for (int e = 0; e < 2; e++) {
        if (w->kind[e] != EL_SPLINE_G2) continue;
        el__spguide *gd = &g->guide[count];
        const size_t span = e == 0 ? 0 : m0 - 1;
        const el__spiece *pc = &w->pc[span];
        gd->knot = e == 0 ? 1 : n - 2;
        gd->slot = e == 0 ? 0 : n - 1;
        gd->pa = span;
        gd->f = e == 0 ? GUIDE_FRACTION : 1.0 - GUIDE_FRACTION;
        gd->h = pc->h;
        gd->nx = -pc->dy / pc->h;
        gd->ny = pc->dx / pc->h;
        g->slot[gd->slot] = EL__SLOT_GUIDE;
        g->border[gd->slot] = count;
        g->guide_at[gd->knot] = count;
        g->slot[gd->knot] = EL__SLOT_ANGLE;
        count++;
    }
    /* the pieces: w's, the end spans split at the guides' feet */
    size_t j = 0;
    for (size_t i = 0; i < m0; i++) {
        const el__spiece *pc = &w->pc[i];
        const int cuts = (i == 0 && gs) + (i == m0 - 1 && ge);
        if (!cuts) { g->pc[j].dx = pc->dx; g->pc[j].dy = pc->dy; g->pc[j].h = pc->h;
                     memcpy(g->pc[j].v, pc->v, sizeof pc->v); j++; continue; }
        foot_problem f;
        f.p.x0 = f.p.y0 = 0.0;
        f.p.phi = pc->v[EL__SP_PHI]; f.p.mu = exp(pc->v[EL__SP_NU]); f.p.k = pc->v[EL__SP_K];
        f.p.q = pc->v[EL__SP_Q]; f.p.length = pc->v[EL__SP_L];
        f.ux = pc->dx / pc->h; f.uy = pc->dy / pc->h;
        double s[4] = {0.0, 0.0, 0.0, 0.0}, fr[4] = {0.0, 0.0, 0.0, 0.0};   /* cuts: arc length, chord fraction */
        int c = 0;
        for (int gi = 0; gi < ng; gi++) {
            el__spguide *gd = &g->guide[gi];
            if (gd->pa != i) continue;
            f.target = gd->f * pc->h;
            if ((st = guide_foot(&f, s[c], f.p.length, &s[c + 1]))) return st;
            double xy[2], th;
            if ((st = el_smooth_eval(&f.p, 1, &s[c + 1], xy, &th, NULL))) return st;
            g->x[gd->slot] = xy[0] * gd->nx + xy[1] * gd->ny;   /* the offset */
            g->x[gd->knot] = th;
            fr[++c] = gd->f;
        }
        s[c + 1] = f.p.length;
        fr[c + 1] = 1.0;
        for (int p = 0; p <= c; p++, j++) {
            el__spiece *q = &g->pc[j];
            sub_arc(pc->v, s[p], s[p + 1], q->v);
            /* the chord with the guides on their bases, the scale, the span's normal */
            q->cx0 = (fr[p + 1] - fr[p]) * pc->dx;
            q->cy0 = (fr[p + 1] - fr[p]) * pc->dy;
            q->h = (fr[p + 1] - fr[p]) * pc->h;
            q->gn[0] = -pc->dy / pc->h;
            q->gn[1] = pc->dx / pc->h;
        }
    }
    /* local chords at the knots (with the guides on their bases) */
    for (size_t i = 0; i < n; i++) {
        const double hl = i > 0 ? g->pc[i - 1].h : g->pc[0].h;
        const double hr = i < n - 1 ? g->pc[i].h : g->pc[m - 1].h;
        g->ell[i] = 0.5 * (hl + hr);
    }
    return isfinite(el__chain_eval(g, 0)) ? EL_OK : EL_ENOCONV;
}
