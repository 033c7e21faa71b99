/*
 * Seed 002 §4: the approximation of a curve by an affine arc-length polyline:
 * parabolic replacement curve, affine arc length (15), line intersections,
 * golden-section search on t1, splitting at inflections (§4.4). The polyline's
 * own invariants are in affine.c; fit_ends' landing of a piece's end in affine_landing.c.
 */
#include "affine_piece.h"
#include <gsl/gsl_min.h>
#include <gsl/gsl_poly.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------- §4.2: the parabolic replacement f~ */

/* Arc j of f~ as a quadratic Bezier b0, b1, b2 (f~(j + tau), tau in [0,1]). */
typedef struct arc {
    double b0[2], b1[2], b2[2];
    int sgn;    /* turning sense: +1, -1, 0 (straight) */
    double S;   /* |affine length| (15) */
} arc;

static void sample_pt(size_t N, const double *p, long j, double out[2])
{
    if (j < 0) {        /* ghost p_{-1} = 3p_0 - 3p_1 + p_2 (from edges: no overflow) */
        for (int c = 0; c < 2; c++) out[c] = p[4 + c] + 3.0 * (p[c] - p[2 + c]);
    } else if ((size_t)j > N) {
        for (int c = 0; c < 2; c++)
            out[c] = p[2 * (N - 2) + c] + 3.0 * (p[2 * N + c] - p[2 * (N - 1) + c]);
    } else {
        out[0] = p[2 * j];
        out[1] = p[2 * j + 1];
    }
}

static void arc_straight(arc *a)
{
    a->b1[0] = 0.5 * (a->b0[0] + a->b2[0]);
    a->b1[1] = 0.5 * (a->b0[1] + a->b2[1]);
    a->sgn = 0;
    a->S = 0.0;
}

/*
 * (15) and the control point: with v_{j-1}, v_j, v_{j+1} the sample edges, the
 * tangent lines p_j + a (v_{j-1} + v_j) and p_{j+1} - b (v_j + v_{j+1}) meet at
 * a = A*_{j+1}/D, b = A*_j/D, D = A*_j + B*_j + A*_{j+1}; the parabola has
 * det(f', f'') = 4 det(b1-b0, b2-b1) = 4 A*_j A*_{j+1} / D, constant.
 */
/* Arcs from caller-given tangents T_j: b1 = p_j + a T_j = p_{j+1} - b T_{j+1} with
 * a = det(v, T_{j+1}) / det(T_j, T_{j+1}), b = det(T_j, v) / det(T_j, T_{j+1});
 * det(f', f'') = 4 a det(T_j, v). Convex iff a > 0 and b > 0. */
static void build_arcs_tangents(size_t N, const double *p, const double *T, arc *arcs)
{
    for (size_t j = 0; j < N; j++) {
        arc *a = &arcs[j];
        a->b0[0] = p[2 * j];
        a->b0[1] = p[2 * j + 1];
        a->b2[0] = p[2 * j + 2];
        a->b2[1] = p[2 * j + 3];
        double v[2] = {a->b2[0] - a->b0[0], a->b2[1] - a->b0[1]};
        const double *T0 = T + 2 * j, *T1 = T + 2 * j + 2;
        double d = det2(T0[0], T0[1], T1[0], T1[1]);
        double aa = d != 0.0 ? det2(v[0], v[1], T1[0], T1[1]) / d : 0.0;
        double bb = d != 0.0 ? det2(T0[0], T0[1], v[0], v[1]) / d : 0.0;
        if (aa > 0.0 && bb > 0.0) {
            a->b1[0] = a->b0[0] + aa * T0[0];
            a->b1[1] = a->b0[1] + aa * T0[1];
            double D = aa * det2(T0[0], T0[1], v[0], v[1]);
            a->sgn = D > 0 ? 1 : (D < 0 ? -1 : 0);
            a->S = cbrt(4.0 * fabs(D));
            if (a->sgn == 0) arc_straight(a);
        } else {
            arc_straight(a);
        }
    }
}

static void build_arcs(size_t N, const double *p, arc *arcs)
{
    for (size_t j = 0; j < N; j++) {
        double pm[2], p0[2], p1[2], p2[2];
        sample_pt(N, p, (long)j - 1, pm);
        sample_pt(N, p, (long)j, p0);
        sample_pt(N, p, (long)j + 1, p1);
        sample_pt(N, p, (long)j + 2, p2);
        double vm[2] = {p0[0] - pm[0], p0[1] - pm[1]}, v0[2] = {p1[0] - p0[0], p1[1] - p0[1]},
               vp[2] = {p2[0] - p1[0], p2[1] - p1[1]};
        double Aj = det2(vm[0], vm[1], v0[0], v0[1]), Aj1 = det2(v0[0], v0[1], vp[0], vp[1]);
        double Bj = det2(vm[0], vm[1], vp[0], vp[1]), D = Aj + Bj + Aj1;
        arc *a = &arcs[j];
        memcpy(a->b0, p0, sizeof p0);
        memcpy(a->b2, p1, sizeof p1);
        int s = Aj > 0 ? 1 : (Aj < 0 ? -1 : 0);
        if (s != 0 && Aj1 * s > 0 && D * s > 0) {
            double t = Aj1 / D;
            a->b1[0] = p0[0] + t * (p1[0] - pm[0]);
            a->b1[1] = p0[1] + t * (p1[1] - pm[1]);
            a->sgn = s;
            a->S = fabs(cbrt(4.0 * Aj * Aj1 / D));   /* (15) */
        } else {
            arc_straight(a);
        }
    }
}

int el_affine_parabolic_lengths(size_t nsamples, const double *samples, double *S)
{
    if (points_ok(nsamples, samples, 3) || !S) return EL_EINVAL;
    if (edges_in_range(nsamples, samples)) return EL_EDOM;
    size_t N = nsamples - 1;
    arc *arcs = el__alloc(N, 1, sizeof *arcs);
    if (!arcs) return EL_ENOMEM;
    build_arcs(N, samples, arcs);
    for (size_t j = 0; j < N; j++) S[j] = arcs[j].sgn * arcs[j].S;
    free(arcs);
    return EL_OK;
}

/* ------------------------- §4.1–4.3: one inflection-free piece (its type: affine_piece.h) */

static void arc_eval(const arc *a, double tau, double out[2])
{
    for (int c = 0; c < 2; c++)
        out[c] = a->b0[c] + 2.0 * tau * (a->b1[c] - a->b0[c])
                 + tau * tau * (a->b2[c] - 2.0 * a->b1[c] + a->b0[c]);
}

static void piece_eval(const piece *P, double t, double out[2])
{
    double fl = floor(t);
    size_t j = fl < (double)P->Ta ? P->Ta : (size_t)fl;
    if (j > P->Tb - 1) j = P->Tb - 1;
    arc_eval(&P->arcs[j], t - (double)j, out);
}

/* Next vertex: the first t > t_i with sigma det(v, f~(t) - x_i) = |A|, the
 * intersection of f~ with the line of §4.3, solved arc by arc as a quadratic
 * (GSL) — beyond Tb on the extrapolated last parabola. */
static int next_vertex(const piece *P, const double v[2], const double x[2], double ti,
                       double *tn, double xn[2])
{
    double fl = floor(ti);
    size_t j = fl < (double)P->Ta ? P->Ta : (size_t)fl;
    if (j > P->Tb - 1) j = P->Tb - 1;
    double tlo = ti - (double)j, absA = fabs(P->A), s = (double)P->sigma;
    for (;; j++, tlo = 0.0) {
        const arc *a = &P->arcs[j];
        double c1[2] = {2.0 * (a->b1[0] - a->b0[0]), 2.0 * (a->b1[1] - a->b0[1])};
        double c2[2] = {a->b2[0] - 2.0 * a->b1[0] + a->b0[0], a->b2[1] - 2.0 * a->b1[1] + a->b0[1]};
        double q0 = s * det2(v[0], v[1], a->b0[0] - x[0], a->b0[1] - x[1]) - absA;
        double q1 = s * det2(v[0], v[1], c1[0], c1[1]);
        double q2 = s * det2(v[0], v[1], c2[0], c2[1]);
        int last = (j + 1 >= P->Tb);
        double r[2];
        int nr = gsl_poly_solve_quadratic(q2, q1, q0, &r[0], &r[1]);
        double best = HUGE_VAL;      /* the first crossing after tlo */
        for (int i = 0; i < nr; i++)
            if (r[i] > tlo && r[i] < best) best = r[i];
        if (!last) {
            if (best > 1.0 && q0 + q1 + q2 >= 0.0) best = 1.0;  /* h(1) >= 0: rounding */
            if (best > 1.0) continue;                           /* not in this arc */
        }
        if (!isfinite(best) || best > 1e3 + (double)(P->Tb - P->Ta)) return EL_EDOM;
        *tn = (double)j + best;
        arc_eval(a, best, xn);
        return EL_OK;
    }
}

int el__piece_build(piece *P, double t1)
{
    P->xy[0] = P->x0[0];
    P->xy[1] = P->x0[1];
    P->t[0] = (double)P->Ta;
    P->t[1] = t1;
    piece_eval(P, t1, P->xy + 2);
    for (size_t i = 1; i < P->m; i++) {
        double v[2] = {P->xy[2 * i] - P->xy[2 * i - 2], P->xy[2 * i + 1] - P->xy[2 * i - 1]};
        if (v[0] == 0.0 && v[1] == 0.0) return EL_EDOM;
        int st = next_vertex(P, v, P->xy + 2 * i, P->t[i], &P->t[i + 1], P->xy + 2 * (i + 1));
        if (st) return st;
    }
    return EL_OK;
}

/* The residuals r_j = k_{j+1} - k_j over the allowed local range, k_j = 2 - B_j / A (4),
 * into r (room for m + 1); their count. */
static size_t piece_resid_built(const piece *P, double *r)
{
    size_t m = P->m, nr = 0;
    if (m < 4) return 0;
    size_t lo = 1 + (size_t)P->skip_lo;
    if (m < 3 + (size_t)P->skip_hi + lo) return 0;
    size_t hi = m - 3 - (size_t)P->skip_hi;
    double kprev = 0.0;
    for (size_t j = lo; j <= hi + 1; j++) {
        double vm[2], vp[2];
        edge(P->xy, j - 1, vm);
        edge(P->xy, j + 1, vp);
        double k = 2.0 - det2(vm[0], vm[1], vp[0], vp[1]) / P->A;
        if (j > lo) r[nr++] = k - kprev;
        kprev = k;
    }
    return nr;
}

static double sum_sq(const double *r, size_t n)
{
    double sum = 0.0;
    for (size_t i = 0; i < n; i++) sum += r[i] * r[i];
    return sum;
}

/* psi = sum r_j^2 (4), the residuals in the piece's workspace P->r. */
double el__piece_psi_built(piece *P)
{
    return sum_sq(P->r, piece_resid_built(P, P->r));
}

/* Polish the golden-section minimiser by Gauss-Newton on the residuals: comparing
 * values of psi locates its minimum only to ~sqrt(eps) of the bracket, and which side
 * wins a comparison there is decided by rounding, so inputs moved by 1e-13 moved t1 (and
 * every vertex) by ~1e-8; the root of sum r_j r_j' = 0 moves by what the problem's
 * conditioning says (~eps |r| / |r'|). r' by central differences (step 1e-6 sample units:
 * the vertices are C^1 in t1). A step is taken only while it stays within the bracket
 * half-width `w` and psi does not rise by more than its rounding. */
double el__piece_polish(piece *P, double t, double w)
{
    size_t cap = P->m + 1;
    double *r = P->r, *rp = P->r + cap, *rm = P->r + 2 * cap;
    const double d = 1e-6;
    for (int it = 0; it < 4; it++) {
        if (el__piece_build(P, t + d)) break;
        size_t np_ = piece_resid_built(P, rp);
        if (el__piece_build(P, t - d)) break;
        size_t nm = piece_resid_built(P, rm);
        if (el__piece_build(P, t)) break;
        size_t n0 = piece_resid_built(P, r);
        if (n0 == 0 || np_ != n0 || nm != n0) break;
        double g = 0.0, H = 0.0, psi0 = 0.0;
        for (size_t i = 0; i < n0; i++) {
            double dr = (rp[i] - rm[i]) / (2.0 * d);
            g += r[i] * dr;
            H += dr * dr;
            psi0 += r[i] * r[i];
        }
        if (!(H > 0.0) || !isfinite(g)) break;
        double step = -g / H;
        if (!(fabs(step) <= w)) break;
        double tn = t + step;
        if (el__piece_build(P, tn)) break;
        size_t n1 = piece_resid_built(P, r);
        double psi1 = sum_sq(r, n1);
        if (n1 != n0 || !(psi1 <= psi0 * (1.0 + 1e-8) + 1e-300)) break;
        t = tn;
        if (fabs(step) <= 1e-15 * fmax(1.0, fabs(t))) break;
    }
    return t;
}

double el__piece_psi(double t1, void *params)
{
    piece *P = params;
    if (el__piece_build(P, t1)) return 1e300;
    double v = el__piece_psi_built(P);
    return isfinite(v) ? v : 1e300;
}

/* Optimise t1 of one piece (§4.2): a grid over (Ta, Ta + 2 (t1_0 - Ta)] finds a
 * bracket, GSL's golden-section minimiser refines it. Leaves P built at the best t1. */
static int piece_optimise(piece *P, double t1_init, const el_affine_options *o, double *psi)
{
    double lo = (double)P->Ta, hi = fmin(lo + 2.0 * (t1_init - lo), (double)P->Tb);
    int optimisable = o->optimise && P->m >= 4 + (size_t)P->skip_lo + (size_t)P->skip_hi;
    double best_t = t1_init;
    int st = EL_OK;
    P->r = malloc(3 * (P->m + 1) * sizeof *P->r);
    if (!P->r) return EL_ENOMEM;
    if (optimisable && hi > lo) {
        enum { G = 24 };
        double tg[G + 1], fg[G + 1];
        size_t gbest = 0;
        double h = (hi - lo) / G;
        for (size_t g = 1; g <= G; g++) {
            tg[g] = lo + (double)g * h;
            fg[g] = el__piece_psi(tg[g], P);
            if (gbest == 0 || fg[g] < fg[gbest]) gbest = g;
        }
        tg[0] = lo + 1e-3 * h;
        fg[0] = el__piece_psi(tg[0], P);
        best_t = tg[gbest];
        if (gbest < G && fg[gbest] < fg[gbest - 1] && fg[gbest] < fg[gbest + 1] &&
            fg[gbest] < 1e300) {
            el__gsl_quiet();
            gsl_min_fminimizer *s = gsl_min_fminimizer_alloc(gsl_min_fminimizer_goldensection);
            gsl_function F = {el__piece_psi, P};
            if (!s) st = EL_ENOMEM;
            else if (gsl_min_fminimizer_set_with_values(s, &F, tg[gbest], fg[gbest], tg[gbest - 1],
                                                        fg[gbest - 1], tg[gbest + 1], fg[gbest + 1]))
                st = EL_EINTERNAL;
            for (int it = 0; !st && it < o->max_iter; it++) {
                if (gsl_min_fminimizer_iterate(s)) break;
                double a = gsl_min_fminimizer_x_lower(s), b = gsl_min_fminimizer_x_upper(s);
                if (b - a < o->t1_tol) break;
            }
            if (!st) best_t = el__piece_polish(P, gsl_min_fminimizer_x_minimum(s), h);
            gsl_min_fminimizer_free(s);
        }
    }
    if (!st) st = el__piece_build(P, best_t);
    if (!st) *psi = el__piece_psi_built(P);
    free(P->r);
    P->r = NULL;
    return st;
}

/* t1 from the affine length cbrt|A| along f~ (interpolated, not integral). */
double el__piece_t1_start(const piece *P)
{
    const arc *arcs = P->arcs;
    double a13 = cbrt(fabs(P->A)), acc = 0.0, t1 = (double)P->Tb;
    for (size_t j = P->Ta; j < P->Tb; j++) {
        if (acc + arcs[j].S >= a13 && arcs[j].S > 0.0) {
            t1 = (double)j + (a13 - acc) / arcs[j].S;
            break;
        }
        acc += arcs[j].S;
    }
    if (!(t1 > (double)P->Ta)) t1 = (double)P->Ta + 0.5;
    return t1;
}

/* A = sign (S/m)^3 given: t1 from the affine length cbrt|A| along f~, then optimised. */
int el__piece_solve(piece *P, const el_affine_options *o, double *psi)
{
    return piece_optimise(P, el__piece_t1_start(P), o, psi);
}

/* ----------------------------------------------- a local origin (far from (0, 0)) */

/* The reference point R subtracted from the samples before any arithmetic and added back
 * to the vertices. Survey coordinates lost digits: at (512345.678, 5012345.432) the arcs'
 * control points, the vertices on them and the line intersections were rounded in the
 * offset's ulps (9.3e-10), and the minimiser t1 of a flat psi amplified that: a 4-unit
 * curve's vertices 2e-8 .. 5e-7 off its translate's, A 3e-9 .. 4e-8 relative (test_affine_
 * offset.c; 5e-12 and 4e-13 now). Per coordinate c, R[c] is the multiple of G (the power of
 * two >= the samples' extent) nearest their first, and 0 unless every sample is 16 G or
 * more from 0 in c (losing 4 bits or more): a curve nearer the origin is computed as before,
 * the same bits. x - R is exact (both multiples of the smaller ulp, |x - R| <= 1.5 G <= |x|),
 * checked all the same; so a translation by a multiple of G gives the same t, A, psi. */
static void local_origin(size_t nsamples, const double *p, double R[2])
{
    double lo[2] = {p[0], p[1]}, hi[2] = {p[0], p[1]}, amin[2] = {fabs(p[0]), fabs(p[1])};
    for (size_t j = 1; j < nsamples; j++)
        for (int c = 0; c < 2; c++) {
            double x = p[2 * j + c];
            lo[c] = fmin(lo[c], x);
            hi[c] = fmax(hi[c], x);
            amin[c] = fmin(amin[c], fabs(x));
        }
    double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    int e = 0;
    R[0] = R[1] = 0.0;
    if (!(ext > 0.0) || !isfinite(ext)) return;
    frexp(ext, &e);
    double G = ldexp(1.0, e);                       /* G >= ext > G / 2 */
    for (int c = 0; c < 2; c++) {
        if (!(amin[c] >= 16.0 * G)) continue;
        double r = G * nearbyint(p[c] / G);
        int exact = 1;
        for (size_t j = 0; j < nsamples && exact; j++)
            exact = (p[2 * j + c] - r) + r == p[2 * j + c];
        if (exact) R[c] = r;
    }
}

/* The samples less R (local_origin) into a new array *out, or *out = the samples themselves
 * where R = 0 (nothing to free: *own 0). EL_ENOMEM. */
static int samples_local(size_t nsamples, const double *samples, double R[2],
                         const double **out, double **own)
{
    local_origin(nsamples, samples, R);
    *own = NULL;
    *out = samples;
    if (R[0] == 0.0 && R[1] == 0.0) return EL_OK;
    double *q = el__alloc(nsamples, 2, sizeof *q);
    if (!q) return EL_ENOMEM;
    for (size_t j = 0; j < nsamples; j++)
        for (int c = 0; c < 2; c++) q[2 * j + c] = samples[2 * j + c] - R[c];
    *out = *own = q;
    return EL_OK;
}

/* ------------------------------------- §4.4: the pieces of f~ and the end pieces kept */

/* §4.4 step 1 and the pieces' affine lengths: f~'s arcs (from the caller's tangents, else
 * (15)), split at the inflections (the caller's sample indices, else where the arcs'
 * turning sense changes) into *np pieces bnd[p]..bnd[p+1] of sense sig[p] and affine
 * length Sp[p] (its arcs' S; a wrong-sense arc is allowed only next to a piece end, and
 * straightened there), *Stot their sum (in piece order). arcs (N), bnd (N + 2), Sp and
 * sig (N + 1) are the caller's. EL_EDOM: f~ straight, an inflection with `split` off, a
 * piece without turning or with an inflection inside. */
static int pieces_split(size_t N, const double *samples, const double *tangents, size_t ninfl,
                        const size_t *infl, int split, arc *arcs, size_t *bnd, size_t *np_out,
                        double *Sp, int *sig, double *Stot_out)
{
    if (tangents) build_arcs_tangents(N, samples, tangents, arcs);
    else build_arcs(N, samples, arcs);
    size_t nb = 0;
    bnd[nb++] = 0;
    if (ninfl > 0) {
        for (size_t i = 0; i < ninfl; i++) bnd[nb++] = infl[i];
    } else {
        long jprev = -1;
        for (size_t j = 0; j < N; j++) {
            if (arcs[j].sgn == 0) continue;
            if (jprev >= 0 && arcs[j].sgn != arcs[jprev].sgn) {
                size_t a = (size_t)jprev + 1, b = j;
                bnd[nb++] = (a == b) ? a : (size_t)floor(0.5 * (double)(a + b) + 0.5);
            }
            jprev = (long)j;
        }
        if (jprev < 0) return EL_EDOM;                  /* f~ is straight */
        if (nb > 1 && !split) return EL_EDOM;
    }
    bnd[nb++] = N;
    size_t np = nb - 1;
    double Stot = 0.0;
    for (size_t p = 0; p < np; p++) {
        double sum = 0.0;
        for (size_t j = bnd[p]; j < bnd[p + 1]; j++) sum += arcs[j].sgn * arcs[j].S;
        sig[p] = sum > 0 ? 1 : (sum < 0 ? -1 : 0);
        if (sig[p] == 0) return EL_EDOM;
        Sp[p] = 0.0;
        for (size_t j = bnd[p]; j < bnd[p + 1]; j++) {
            if (arcs[j].sgn == -sig[p]) {
                if (j != bnd[p] && j + 1 != bnd[p + 1]) return EL_EDOM;  /* inflection inside */
                arc_straight(&arcs[j]);
            }
            Sp[p] += arcs[j].S;
        }
        Stot += Sp[p];
    }
    *np_out = np;
    *Stot_out = Stot;
    return EL_OK;
}

/* An end piece worth less than 1.5 edges of affine length at n edges (an inflection right
 * next to an end of the curve: n Sp / Stot < 1.5) is left out: its 3 forced edges would
 * have to be far longer than the piece. The polyline then starts / stops at the
 * inflection. The first end first, then the last against what is left: returns the pieces
 * kept, from *p0 on, *Stot less the ones left out. */
static size_t pieces_kept(size_t n, const double *Sp, size_t np, size_t *p0_out, double *Stot)
{
    size_t p0 = 0;
    while (np > 1 && (double)n * Sp[p0] / *Stot < 1.5) {
        *Stot -= Sp[p0];
        p0++;
        np--;
    }
    while (np > 1 && (double)n * Sp[p0 + np - 1] / *Stot < 1.5) {
        *Stot -= Sp[p0 + np - 1];
        np--;
    }
    *p0_out = p0;
    return np;
}

/* The fewest n in [3, EL_AFFINE_MAX_EDGES] at which pieces_kept keeps the first piece
 * (`both` 0) or both end pieces (`both` 1), 0 where none does. Bisection is exact: the
 * tests n Sp / Stot < 1.5 are monotone in n in floating point too (rounding is monotone:
 * fl(n Sp) does not decrease as n grows, nor fl(x / Stot) as x does, Sp >= 0, Stot > 0), and
 * both ends are kept iff n Sp[0] / Stot >= 1.5 and n Sp[np-1] / Stot >= 1.5 at the full
 * Stot (the second loop runs against the full Stot when the first left nothing out). */
static int keeps_ends(size_t n, const double *Sp, size_t np, double Stot, int both)
{
    size_t p0 = 0, kept = pieces_kept(n, Sp, np, &p0, &Stot);
    return p0 == 0 && (!both || kept == np);
}

static size_t fewest_keeping(const double *Sp, size_t np, double Stot, int both)
{
    size_t lo = 3, hi = EL_AFFINE_MAX_EDGES;
    if (!keeps_ends(hi, Sp, np, Stot, both)) return 0;
    if (keeps_ends(lo, Sp, np, Stot, both)) return lo;
    while (hi - lo > 1) {       /* keeps at hi, not at lo */
        size_t mid = lo + (hi - lo) / 2;
        if (keeps_ends(mid, Sp, np, Stot, both)) hi = mid; else lo = mid;
    }
    return hi;
}

/* The checks el_affine_end_pieces and el_affine_polyline share, after each one's own EL_EINVAL
 * checks and before its own EL_EDOM ones (so either returns the status it did with them inline):
 * EL_EINVAL for samples missing, fewer than 4 or not finite (points_ok), tangents not finite,
 * inflections missing or not strictly increasing inside 1 .. nsamples - 2; EL_EDOM for
 * inflections with split_inflections 0 and (bounded work: their products) edges or tangents
 * whose largest component lies outside [1e-150, 1e150] and is not 0; EL_OK otherwise. */
static int samples_checked(size_t nsamples, const double *samples, const double *tangents,
                           size_t ninfl, const size_t *infl, int split_inflections)
{
    if (points_ok(nsamples, samples, 4) || (ninfl > 0 && !infl)) return EL_EINVAL;
    if (tangents && el__all_finite(tangents, 2 * nsamples)) return EL_EINVAL;
    const size_t N = nsamples - 1;
    for (size_t i = 0; i < ninfl; i++)
        if (infl[i] < 1 || infl[i] >= N || (i > 0 && infl[i] <= infl[i - 1])) return EL_EINVAL;
    if (ninfl > 0 && !split_inflections) return EL_EDOM;
    if (edges_in_range(nsamples, samples)) return EL_EDOM;
    for (size_t j = 0; tangents && j < nsamples; j++) {
        const double m = fmax(fabs(tangents[2 * j]), fabs(tangents[2 * j + 1]));
        if (m > 1e150 || (m > 0.0 && m < 1e-150)) return EL_EDOM;
    }
    return EL_OK;
}

int el_affine_end_pieces(size_t nsamples, const double *samples, const double *tangents,
                         size_t ninfl, const size_t *infl, const el_affine_options *opt,
                         size_t *npieces, size_t ends[2], size_t n_min[2])
{
    el_affine_options o;
    if (opt) o = *opt; else el_affine_options_defaults(&o);
    if (!npieces || !ends || !n_min) return EL_EINVAL;
    const int bad = samples_checked(nsamples, samples, tangents, ninfl, infl, o.split_inflections);
    if (bad) return bad;
    size_t N = nsamples - 1;
    double R[2], *own = NULL;
    const double *loc = samples;
    int st = samples_local(nsamples, samples, R, &loc, &own);
    arc *arcs = el__alloc(N, 1, sizeof *arcs);
    size_t *bnd = el__alloc(N + 2, 1, sizeof *bnd);
    double *Sp = el__alloc(N + 1, 1, sizeof *Sp);
    int *sig = el__alloc(N + 1, 1, sizeof *sig);
    if (!arcs || !bnd || !Sp || !sig) st = EL_ENOMEM;
    size_t np = 0;
    double Stot = 0.0;
    if (!st) st = pieces_split(N, loc, tangents, ninfl, infl, o.split_inflections, arcs,
                               bnd, &np, Sp, sig, &Stot);
    if (!st) {
        *npieces = np;
        ends[0] = bnd[1];
        ends[1] = bnd[np - 1];
        n_min[0] = fewest_keeping(Sp, np, Stot, 0);
        n_min[1] = fewest_keeping(Sp, np, Stot, 1);
    }
    free(own);
    free(arcs);
    free(bnd);
    free(Sp);
    free(sig);
    return st;
}

/* ------------------------------------------------------------ §4: the driver */

void el_affine_options_defaults(el_affine_options *opt)
{
    if (!opt) return;
    opt->split_inflections = 1;
    opt->skip = 2;
    opt->skip_frac = 0.0;
    opt->fit_ends = 0;
    opt->optimise = 1;
    opt->max_iter = 100;
    opt->t1_tol = 1e-10;
}

void el_affine_result_free(el_affine_result *res)
{
    if (!res) return;
    free(res->xy);
    free(res->t);
    free(res->piece_start);
    free(res->A);
    free(res->psi);
    free(res->infl_param);
    memset(res, 0, sizeof *res);
}

int el_affine_polyline(size_t nsamples, const double *samples, const double *tangents,
                       size_t ninfl, const size_t *infl, size_t n,
                       const el_affine_options *opt, el_affine_result *res)
{
    el_affine_options o;
    if (opt) o = *opt; else el_affine_options_defaults(&o);
    if (!res || n < 3 || o.skip < 0 || o.max_iter < 0 || !(o.t1_tol > 0.0) ||
        !(o.skip_frac >= 0.0 && o.skip_frac < 0.5))
        return EL_EINVAL;
    const int bad = samples_checked(nsamples, samples, tangents, ninfl, infl, o.split_inflections);
    if (bad) return bad;
    if (n > EL_AFFINE_MAX_EDGES) return EL_EDOM;   /* bounded work: the vertex count */
    size_t N = nsamples - 1;

    double R[2], *own = NULL;       /* the local origin: vertices - R computed, R added */
    const double *loc = samples;
    int st = samples_local(nsamples, samples, R, &loc, &own);
    arc *arcs = el__alloc(N, 1, sizeof *arcs);
    size_t *bnd = el__alloc(N + 2, 1, sizeof *bnd);     /* piece boundaries in f~ */
    size_t *cnt = NULL;
    double *work_xy = NULL, *work_t = NULL;
    el_affine_result r;
    memset(&r, 0, sizeof r);
    if (st || !arcs || !bnd) { st = EL_ENOMEM; goto done; }
    double *Sp = el__alloc(N + 1, 1, sizeof *Sp);
    int *sig = el__alloc(N + 1, 1, sizeof *sig);
    cnt = el__alloc(N + 1, 1, sizeof *cnt);
    if (!Sp || !sig || !cnt) { free(Sp); free(sig); st = EL_ENOMEM; goto done; }
    size_t np = 0, p0 = 0;
    double Stot = 0.0;
    st = pieces_split(N, loc, tangents, ninfl, infl, o.split_inflections, arcs, bnd, &np,
                      Sp, sig, &Stot);
    if (!st) np = pieces_kept(n, Sp, np, &p0, &Stot);
    if (p0 > 0) {
        memmove(Sp, Sp + p0, np * sizeof *Sp);
        memmove(sig, sig + p0, np * sizeof *sig);
        memmove(bnd, bnd + p0, (np + 1) * sizeof *bnd);
    }
    if (!st && n < 3 * np) st = EL_EDOM;
    if (!st) { /* vertex counts proportional to the affine lengths, >= 3 each */
        size_t total = 0;
        for (size_t p = 0; p < np; p++) {
            double c = floor((double)n * Sp[p] / Stot + 0.5);
            cnt[p] = c < 3.0 ? 3 : (size_t)c;
            total += cnt[p];
        }
        while (total != n) {   /* adjust the piece whose count is furthest off its share */
            size_t pb = np;
            double bestv = 0.0;
            for (size_t p = 0; p < np; p++) {
                double v = (double)cnt[p] - (double)n * Sp[p] / Stot;
                if (total > n && cnt[p] <= 3) continue;
                if (pb == np || (total > n && v > bestv) || (total < n && v < bestv)) {
                    pb = p;
                    bestv = v;
                }
            }
            if (total > n) { cnt[pb]--; total--; } else { cnt[pb]++; total++; }
        }
    }
    if (st) { free(Sp); free(sig); goto done; }

    r.npts = n + 1;
    r.npieces = np;
    r.S_total = Stot;
    r.xy = malloc(2 * (n + 1) * sizeof *r.xy);
    r.t = malloc((n + 1) * sizeof *r.t);
    r.piece_start = malloc((np + 1) * sizeof *r.piece_start);
    r.A = malloc(np * sizeof *r.A);
    r.psi = malloc(np * sizeof *r.psi);
    r.infl_param = malloc((np > 1 ? np - 1 : 1) * sizeof *r.infl_param);
    size_t mmax = 0;
    for (size_t p = 0; p < np; p++) if (cnt[p] > mmax) mmax = cnt[p];
    work_xy = malloc(2 * (mmax + 1) * sizeof *work_xy);
    work_t = malloc((mmax + 1) * sizeof *work_t);
    if (!r.xy || !r.t || !r.piece_start || !r.A || !r.psi || !r.infl_param || !work_xy || !work_t) {
        free(Sp); free(sig); st = EL_ENOMEM; goto done;
    }
    for (size_t p = 0; p + 1 < np; p++) r.infl_param[p] = (double)bnd[p + 1];

    /* §4.4 step 2: the pieces one after another */
    size_t g = 0;
    r.xy[0] = loc[2 * bnd[0]];
    r.xy[1] = loc[2 * bnd[0] + 1];
    r.t[0] = (double)bnd[0];
    r.piece_start[0] = 0;
    for (size_t p = 0; p < np && !st; p++) {
        piece P;
        P.arcs = arcs;
        P.Ta = bnd[p];
        P.Tb = bnd[p + 1];
        P.sigma = sig[p];
        P.m = cnt[p];
        double a13 = Sp[p] / (double)P.m;
        P.A = sig[p] * a13 * a13 * a13;                  /* A = (S/n)^3 */
        P.x0[0] = r.xy[2 * g];
        P.x0[1] = r.xy[2 * g + 1];
        double lf = ceil(o.skip_frac * (double)P.m);
        int l = o.skip > (int)lf ? o.skip : (int)lf;
        P.skip_lo = P.Ta > 0 ? l : 0;       /* only next to inflections */
        P.skip_hi = P.Tb < N ? l : 0;
        P.xy = work_xy;
        P.t = work_t;
        P.r = NULL;                         /* piece_optimise's */
        double psi = 0.0;
        st = el__piece_solve(&P, &o, &psi);
        if (st) break;
        if (o.fit_ends) {   /* §4.4 "redone with adjusted value for A": affine_landing.c */
            st = el__piece_fit_ends(&P, &o, p + 1 == np, &psi);
            if (st) break;
        }
        for (size_t i = 1; i <= P.m; i++) {
            r.xy[2 * (g + i)] = P.xy[2 * i];
            r.xy[2 * (g + i) + 1] = P.xy[2 * i + 1];
            r.t[g + i] = P.t[i];
        }
        g += P.m;
        r.piece_start[p + 1] = g;
        r.A[p] = P.A;
        r.psi[p] = psi;
    }
    free(Sp);
    free(sig);
    if (!st && (R[0] != 0.0 || R[1] != 0.0))
        for (size_t j = 0; j <= n; j++)
            for (int c = 0; c < 2; c++) r.xy[2 * j + c] += R[c];
    if (!st && (el__all_finite(r.xy, 2 * (n + 1)) || el__all_finite(r.t, n + 1) ||
                el__all_finite(r.A, np) || el__all_finite(r.psi, np) || !isfinite(r.S_total)))
        st = EL_EDOM;

done:
    free(own);
    free(arcs);
    free(bnd);
    free(cnt);
    free(work_xy);
    free(work_t);
    if (st) el_affine_result_free(&r);
    else *res = r;
    return st;
}
