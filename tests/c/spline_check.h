/* Shared by the elastic-spline tests (test_spline*.c): the properties issue 14 lists,
 * checked on a result (check_spline), the options of a closed spline, the unit ring of 8
 * ducks, a designer's sketch, and the energy of the Hermite pieces through given knot
 * angles. */
#ifndef SPLINE_CHECK_H
#define SPLINE_CHECK_H
#include "testutil.h"
#include "internal.h"
#include <stdlib.h>
#include <string.h>

/* The length of the polygon through the n points xy, and its longest side. */
static inline double polygon_length(const double *xy, size_t n)
{
    double L = 0.0;
    for (size_t i = 0; i + 1 < n; i++) L += hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]);
    return L;
}

static inline double longest_side(const double *xy, size_t n)
{
    double h = 0.0;
    for (size_t i = 0; i + 1 < n; i++) h = fmax(h, hypot(xy[2 * i + 2] - xy[2 * i], xy[2 * i + 3] - xy[2 * i + 1]));
    return h;
}

static inline double wrap(double a) { return a - 2.0 * M_PI * nearbyint(a / (2.0 * M_PI)); }

/* Point, tangent angle, curvature and kappa' (central difference) of a piece at s. */
static inline void state_at(const el_smooth_params *p, double s, double xy[2], double *th,
                            double *ka, double *dka)
{
    ck_assert_int_eq(el_smooth_eval(p, 1, &s, xy, th, ka), EL_OK);
    if (dka) {
        const double h = 1e-5 * (p->length + 1e-300), sv[2] = {s - h, s + h};
        double kk[2];
        ck_assert_int_eq(el_smooth_eval(p, 2, sv, NULL, NULL, kk), EL_OK);
        *dka = (kk[1] - kk[0]) / (2.0 * h);
    }
}

/* The knots of a result: the points, with its guide ducks inserted (a guide
 * starts piece guide_pieces[g]); kxy: 2 knots, pt: the point of each knot or -1. */
static inline size_t result_knots(const double *xy, const el_spline_options *o,
                                  const el_spline_result *r, double *kxy, long *pt)
{
    const size_t nk = o->closed ? r->npieces : r->npieces + 1;
    size_t p = 0;
    for (size_t i = 0; i < nk; i++) {
        long g = -1;
        for (size_t k = 0; k < r->nguides; k++) if (r->guide_pieces[k] == i) g = (long)k;
        kxy[2 * i] = g >= 0 ? r->guides[2 * g] : xy[2 * p];
        kxy[2 * i + 1] = g >= 0 ? r->guides[2 * g + 1] : xy[2 * p + 1];
        pt[i] = g >= 0 ? -1 : (long)p++;
    }
    ck_assert_uint_eq(p, r->npoints);
    return nk;
}

/*
 * The properties issue 14 lists, measured with el_smooth_eval at the piece
 * ends: through the knots (tol times the extent), tangent continuity (tol rad),
 * curvature jump <= 1e-7 max |kappa|, each piece's tension 2 mu (2k^2 - 1) equal
 * to res->sigma (k = 0 straight pieces exempt: kappa = 0 solves every tension),
 * every duck's load normal to the batten (frictionless, the guide ducks too),
 * the end conditions, energy and length as sums over the pieces, the force
 * constant along each piece; one guide duck per G2 end, a quarter of its end
 * span's chord from the end, its force that of the pieces it joins.
 */
static inline void check_spline(const double *xy, size_t n, const el_spline_options *o,
                                const el_spline_result *r, double tol)
{
    const size_t m = r->npieces;
    const size_t g2 = o->closed ? 0 : (size_t)(o->start.kind == EL_SPLINE_G2) + (o->end.kind == EL_SPLINE_G2);
    ck_assert_uint_eq(r->nguides, g2);
    ck_assert_uint_eq(m, o->closed ? r->npoints : r->npoints - 1 + g2);
    double *kxy = malloc(2 * (m + 1) * sizeof *kxy);
    long *pt = malloc((m + 1) * sizeof *pt);
    ck_assert_ptr_nonnull(kxy);
    ck_assert_ptr_nonnull(pt);
    const size_t nk = result_knots(xy, o, r, kxy, pt);
    double ext = 0.0;
    for (size_t i = 0; i < r->npoints; i++) ext = fmax(ext, fmax(fabs(xy[2 * i]), fabs(xy[2 * i + 1])));
    ext = fmax(ext, longest_side(xy, n));
    const double kmax = r->max_curvature;
    double E = 0.0, L = 0.0, kseen = 0.0;
    for (size_t j = 0; j < m; j++) {
        const el_smooth_params *p = &r->pieces[j];
        const size_t e = (j + 1) % nk;
        ck_assert_int_eq(el_smooth_check(p), EL_OK);
        ck_assert_msg(p->x0 == kxy[2 * j] && p->y0 == kxy[2 * j + 1], "piece %zu does not start at its knot", j);
        double a[2], b[2], tha, thb, ka, kb, dka, dkb;
        state_at(p, 0.0, a, &tha, &ka, &dka);
        state_at(p, p->length, b, &thb, &kb, &dkb);
        ck_assert_msg(hypot(b[0] - kxy[2 * e], b[1] - kxy[2 * e + 1]) <= tol * ext,
                      "piece %zu misses knot %zu by %g", j, e, hypot(b[0] - kxy[2 * e], b[1] - kxy[2 * e + 1]));
        if (pt[j] >= 0) {
            ck_assert_close(tha, r->angles[pt[j]], 1e-12 * (1.0 + fabs(tha)));
            ck_assert_close(ka, r->curvatures[pt[j]], 1e-9 * (1.0 + kmax));
        }
        kseen = fmax(kseen, fmax(fabs(ka), fabs(kb)));
        /* one tension: sigma = 2 mu (2k^2 - 1) (seed 004 / smooth section) */
        if (p->k != 0.0) {
            const double sg = 2.0 * p->mu * (2.0 * p->k * p->k - 1.0);
            ck_assert_msg(fabs(sg - r->sigma) <= 1e-8 * (fabs(r->sigma) + 4.0 * p->mu),
                          "piece %zu tension %.17g, spline %.17g", j, sg, r->sigma);
        }
        /* the force F = (sigma - kappa^2) T - 2 kappa' N, constant along the piece */
        const double s = r->sigma, Fs = 1.0 + fabs(s) + kmax * kmax;
        const double Fb[2] = {(s - kb * kb) * cos(thb) + 2.0 * dkb * sin(thb),
                              (s - kb * kb) * sin(thb) - 2.0 * dkb * cos(thb)};
        const double Fa[2] = {(s - ka * ka) * cos(tha) + 2.0 * dka * sin(tha),
                              (s - ka * ka) * sin(tha) - 2.0 * dka * cos(tha)};
        ck_assert_msg(hypot(Fa[0] - r->forces[2 * j], Fa[1] - r->forces[2 * j + 1]) <= 1e-6 * Fs,
                      "piece %zu force at 0 %g %g vs %g %g", j, Fa[0], Fa[1], r->forces[2 * j], r->forces[2 * j + 1]);
        ck_assert_msg(hypot(Fb[0] - r->forces[2 * j], Fb[1] - r->forces[2 * j + 1]) <= 1e-6 * Fs,
                      "piece %zu force not constant: %g %g vs %g %g", j, Fb[0], Fb[1], r->forces[2 * j], r->forces[2 * j + 1]);
        /* G1 and G2 at the next knot */
        if (o->closed || j + 1 < m) {
            const el_smooth_params *q = &r->pieces[e % m];
            double c[2], thc, kc;
            state_at(q, 0.0, c, &thc, &kc, NULL);
            ck_assert_msg(fabs(wrap(thb - thc)) <= tol, "tangent jump %g at knot %zu", wrap(thb - thc), e);
            ck_assert_msg(fabs(kb - kc) <= 1e-7 * kmax + 1e-300, "curvature jump %g at knot %zu (max %g)",
                          fabs(kb - kc), e, kmax);
            /* a frictionless duck: its load F_j - F_{j+1} is normal to the batten
             * (the tension is common) */
            const double D[2] = {r->forces[2 * j] - r->forces[2 * (e % m)],
                                 r->forces[2 * j + 1] - r->forces[2 * (e % m) + 1]};
            ck_assert_msg(fabs(D[0] * cos(thc) + D[1] * sin(thc)) <= 1e-6 * Fs,
                          "duck %zu pushes along the batten: %g", e, D[0] * cos(thc) + D[1] * sin(thc));
            if (pt[e] < 0) {   /* a guide duck: its reported force */
                size_t g = 0;
                while (r->guide_pieces[g] != e) g++;
                ck_assert_msg(hypot(r->guide_forces[2 * g] - D[0], r->guide_forces[2 * g + 1] - D[1]) <= 1e-12 * Fs,
                              "guide %zu force %g %g, pieces say %g %g", g, r->guide_forces[2 * g],
                              r->guide_forces[2 * g + 1], D[0], D[1]);
            }
        } else {
            ck_assert_close(thb, r->angles[r->npoints - 1], 1e-12 * (1.0 + fabs(thb)));
            ck_assert_close(kb, r->curvatures[r->npoints - 1], 1e-9 * (1.0 + kmax));
        }
        double En;
        ck_assert_int_eq(el_smooth_energy(p, &En), EL_OK);
        E += En;
        L += p->length;
    }
    free(kxy);
    free(pt);
    ck_assert_close(r->energy, E, 1e-12 * (1.0 + E));
    ck_assert_close(r->length, L, 1e-12 * L);
    ck_assert_msg(kseen <= kmax * (1.0 + 1e-12), "curvature %g above max_curvature %g", kseen, kmax);
    ck_assert_msg(r->residual <= o->tol, "residual %g", r->residual);
    if (o->mode == EL_SPLINE_LENGTH) ck_assert_close(L, o->length, 1e-9 * o->length);
    if (!o->closed) {
        const el_spline_end *ends[2] = {&o->start, &o->end};
        const size_t at[2] = {0, r->npoints - 1};
        for (int i = 0, g = 0; i < 2; i++) {
            const double k = r->curvatures[at[i]];
            if (ends[i]->kind == EL_SPLINE_NATURAL)
                ck_assert_msg(fabs(k) <= 1e-9 * (1.0 + kmax), "natural end %d has kappa %g", i, k);
            if (ends[i]->kind != EL_SPLINE_NATURAL) {
                const double ta = atan2(ends[i]->tangent[1], ends[i]->tangent[0]);
                ck_assert_msg(fabs(wrap(r->angles[at[i]] - ta)) <= 1e-9, "end %d tangent off by %g", i,
                              wrap(r->angles[at[i]] - ta));
            }
            if (ends[i]->kind != EL_SPLINE_G2) continue;
            ck_assert_msg(fabs(k - ends[i]->curvature) <= 1e-7 * fmax(fabs(ends[i]->curvature), kmax) + 1e-300,
                          "G2 end %d curvature %.17g, asked %.17g", i, k, ends[i]->curvature);
            /* its guide: a quarter of the end span's chord from the end, on the chord's normal */
            const double *a = xy + 2 * (i ? r->npoints - 2 : 0), *gp = r->guides + 2 * g++;
            const double h = hypot(a[2] - a[0], a[3] - a[1]);
            const double along = ((gp[0] - a[0]) * (a[2] - a[0]) + (gp[1] - a[1]) * (a[3] - a[1])) / (h * h);
            ck_assert_msg(fabs(along - (i ? 0.75 : 0.25)) <= 1e-9, "guide %d at %.12g of its chord", g - 1, along);
        }
    }
}

static inline int solve(const double *xy, size_t n, const el_spline_options *o, el_spline_result *r)
{
    return el_spline_solve(xy, n, o, r);
}

static inline el_spline_options opts(int mode, double v)
{
    el_spline_options o;
    el_spline_options_defaults(&o);
    o.mode = mode;
    if (mode == EL_SPLINE_TENSION) o.sigma = v;
    else o.length = v;
    return o;
}

/* options of a closed spline (as opts) */
static inline el_spline_options closed_opts(int mode, double v)
{
    el_spline_options o = opts(mode, v);
    o.closed = 1;
    return o;
}

static inline el_spline_options closed_length(double L)
{
    return closed_opts(EL_SPLINE_LENGTH, L);
}

/* 8 ducks on the unit circle, a closed ring (xy: 16); returns its polygon's length */
static inline double unit_ring8(double *xy)
{
    for (int i = 0; i < 8; i++) { xy[2 * i] = cos(M_PI * i / 4.0); xy[2 * i + 1] = sin(M_PI * i / 4.0); }
    return 16.0 * sin(M_PI / 8.0);
}

/* hand-placed, unevenly spaced points of a fair curve (a designer's sketch) */
static const double sketch[] = {0.0, 0.0, 0.7, 0.45, 1.1, 0.62, 2.6, 0.9, 3.0, 0.85,
                                4.8, 0.2, 5.5, -0.3, 7.9, -0.6, 8.2, -0.55};
enum { NSKETCH = 9 };

/* 12 random ducks closed into a ring (QA's ring77: no free batten, and no batten under
 * sigma h^2 = 40, 4 or 0.4 from the chain's start) */
static const double ring77[] = {1.114871201483529, 0.06296179947823506, 0.5268930130627169, 0.14471682098931363,
                                0.7002262459798201, 0.22878727946245084, 1.171136186509111, 0.7625165256147413,
                                -0.6232201739649377, 0.0006386487226305472, -1.0328428299768375, -0.02805207981902149,
                                -0.4487961745896451, -0.31801768649958634, -0.7908416001295514, -1.202444892387523,
                                -0.31667086307954834, -0.592213679706269, -0.09621596250118901, -0.9049211859109808,
                                -0.08974183254317604, -1.042927207910349, 0.9393609599573067, -0.7763458991267597};


/* E(angles) = sum of integral kappa^2 + sigma ds over the Hermite pieces through
 * the points with those tangent angles; its derivative in the angle at point i
 * is 2 (kappa_i^- - kappa_i^+) (the first variation's boundary terms), zero at
 * the spline: checked by finite differences of E (pieces by el_hermite_solve)
 * at the spline and, as a control, away from it. */
static inline double hermite_energy(const double *xy, size_t n, const double *th, double sigma,
                                    const el_spline_result *near, double *kjump, size_t at)
{
    double E = 0.0, k_end = 0.0;
    for (size_t j = 0; j + 1 < n; j++) {
        const double t0[2] = {cos(th[j]), sin(th[j])}, t1[2] = {cos(th[j + 1]), sin(th[j + 1])};
        el_hermite_options ho;
        el_hermite_options_defaults(&ho);
        ho.sigma = sigma;
        ho.samples = 60;
        el_hermite_result hr;
        ck_assert_int_eq(el_hermite_solve(xy + 2 * j, t0, xy + 2 * j + 2, t1, &ho, &hr), EL_OK);
        size_t best = hr.count;
        for (size_t i = 0; i < hr.count; i++)   /* the one continuing the spline's piece */
            if (best == hr.count || fabs(hr.solutions[i].length - near->pieces[j].length) <
                                    fabs(hr.solutions[best].length - near->pieces[j].length))
                best = i;
        ck_assert_uint_lt(best, hr.count);
        E += hr.solutions[best].energy + sigma * hr.solutions[best].length;
        if (j + 1 == at) k_end = hr.solutions[best].kappa1;
        if (j == at && kjump) *kjump = k_end - hr.solutions[best].kappa0;
        el_hermite_result_free(&hr);
    }
    return E;
}

#endif
