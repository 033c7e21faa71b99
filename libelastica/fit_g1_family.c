/*
 * A smooth fit joined G1 at both ends (start and end points and tangents given): every
 * curve that meets those four conditions is an elastic curve of Hermite data (seed 004),
 * and those form one-parameter families, each met by el_hermite_solve at the tensions
 * sigma along it. A scan of sigma over its range (SIGMA_D2, times 1 / |p1 - p0|^2) meets
 * every family; the members nearest the points (the sum of their squared distances, feet
 * as the fit's: el__fit_feet_elsewhere) of other families, and the nearest that follows
 * them (el__fit_stray), are the fit's further starts (members alike in length and end
 * curvatures are taken for one family). Written because the fit's guesses are fitted
 * to the points first and then moved onto the constraints, which can lead far from every
 * good member when the points are clustered: 6 points, 5 within the first fifth of a
 * 130 mm curve with 0.02 mm noise and its far end, ended at rms 3.0 where the curve they
 * came from has 0.024 (QA); from these starts 0.0218.
 */
#include "fit_internal.h"
#include "fit_wander.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* sigma |p1 - p0|^2: compression and tension in steps of 10^(1/2), and 0 (steps of
 * 10^(1/4), 32 solves, found no better starts on fit.c's clustered sketches in an earlier
 * form of these starts) */
static const double SIGMA_D2[] = {
    -100.0, -31.6, -10.0, -3.16, -1.0, -0.316, -0.1, 0.0, 0.1, 0.316,
    1.0, 3.16, 10.0, 31.6, 100.0, 316.0, 1e3, 3.16e3, 1e4,
};
enum { MAX_SOLUTIONS = 16 };

typedef struct { double f, len, k0, k1; int follows; } member;

/* Members alike enough to be taken for one family: lengths within 25 %, end curvatures
 * (times |p1 - p0|) within a half of their size. Not tuned: one family's members a grid
 * step apart can differ more (a length 19.4 -> 11.1 from sigma |p1 - p0|^2 = 0.1 to 0.32
 * on a looping sketch), and two of the starts kept may then be one family's */
static int alike(const member *a, const member *b)
{
    const double dk = fabs(a->k0 - b->k0) + fabs(a->k1 - b->k1);
    return fabs(a->len - b->len) <= 0.25 * fmin(a->len, b->len) &&
           dk <= 0.5 * (1.0 + fabs(a->k0) + fabs(a->k1));
}

/* Between nearly collinear ends (both tangents within WAVE_ENDS rad of the chord) the
 * near-straight member is a line in all but its last bits, and where the points wave about
 * it the fit's waves are decided by the rounding of Ipopt's path from there, not by the
 * points: 16 sketched points clustered along the first quarter of a 130 mm chord ended at
 * rms 1.3137 (OpenBLAS's SkylakeX kernels), 1.2806 (reference BLAS), 1.1955 (Nehalem),
 * 1.1729 (Haswell), each not even a local minimum. Waves of amplitude WAVE_K (the modulus,
 * q = 0: leaving along phi) and periods the chord over powers of sqrt 2 are further
 * starts: from a grid of 156 such starts (periods 8-116, k 0.05-0.2, four phases) the fits
 * no longer than 1.1 x the chord ended in five minima (rms 1.0743 - 1.3550), the lowest,
 * 1.0743 (period 20.7), from 46 of them, among them every start of period 19.5. */
static const double WAVE_ENDS = 0.05, WAVE_K = 0.1;

static int wave_starts(const fit_constraints *con, double (*v)[FIT_NP], int room)
{
    const double *a = con->start_xy, *b = con->end_xy;
    const double dx = b[0] - a[0], dy = b[1] - a[1], dn = hypot(dx, dy), chord = atan2(dy, dx);
    const double e0 = remainder(con->start_theta - chord, 2.0 * M_PI);
    const double e1 = remainder(con->end_theta - chord, 2.0 * M_PI);
    if (!(dn > 0.0) || !(fabs(e0) <= WAVE_ENDS && fabs(e1) <= WAVE_ENDS)) return 0;
    int nw = 0;
    for (double period = dn; nw < room; period *= 0.70710678118654752, nw++) {
        /* curvature period 4 K(k) / sqrt(mu), K(k) = pi / 2 (1 + k^2 / 4 + 9 k^4 / 64 + ...):
         * K(0.1) = 1.00252 pi / 2 (a start: 1.0025) */
        const double sqmu = 2.0 * M_PI * 1.0025 / period;
        const double w[FIT_NP] = {a[0], a[1], con->start_theta, sqmu, WAVE_K, 0.0,
                                  dn * (1.0 + WAVE_K * WAVE_K)};
        memcpy(v[nw], w, sizeof w);
    }
    return nw;
}

int el__fit_g1_family_start(fit_objective *ob, const fit_constraints *con, double noise, double f_below,
                            double (*v)[FIT_NP], int *count, int waves)
{
    const size_t n = ob->n;
    const int kmax = *count;
    if (kmax < 1) return EL_EINVAL;
    const double *a = con->start_xy, *b = con->end_xy;
    const double t0[2] = {cos(con->start_theta), sin(con->start_theta)};
    const double t1[2] = {cos(con->end_theta), sin(con->end_theta)};
    const double d2 = (b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]), dn = sqrt(d2);
    enum { MAX_MEMBERS = (int)(sizeof SIGMA_D2 / sizeof SIGMA_D2[0]) * MAX_SOLUTIONS };
    double *buf = malloc(sizeof(double) * 3 * n), (*mv)[FIT_NP] = malloc(sizeof *mv * MAX_MEMBERS);
    el_hermite_solution *sol = malloc(sizeof *sol * MAX_SOLUTIONS);
    member *all = malloc(sizeof *all * MAX_MEMBERS);
    *count = 0;
    if (!buf || !mv || !sol || !all) { free(buf); free(mv); free(sol); free(all); return EL_ENOMEM; }
    double *d = buf, *fs = buf + n, *fs_in = buf + 2 * n;
    el_hermite_options ho;
    el_hermite_options_defaults(&ho);
    ho.max_solutions = MAX_SOLUTIONS;
    int st = EL_OK, nm = 0;
    for (size_t g = 0; g < sizeof SIGMA_D2 / sizeof SIGMA_D2[0] && st != EL_ENOMEM; g++) {
        ho.sigma = SIGMA_D2[g] / d2;
        size_t ns = 0, unrep = 0;
        st = el_hermite_solve_into(a, t0, b, t1, &ho, sol, MAX_SOLUTIONS, &ns, &unrep);
        if (st) continue;    /* none at this tension (EL_EDOM beyond the range) */
        for (size_t c = 0; c < ns && c < MAX_SOLUTIONS; c++) {
            if (sol[c].npieces != 1) continue;   /* a chain (near the separatrix): no one curve */
            const el_smooth_params *p = &sol[c].curve;
            double vv[2][FIT_NP] = {{p->x0, p->y0, p->phi, sqrt(p->mu), p->k, p->q, p->length}}, x[FIT_MAXX];
            const int fst = el__fit_curve_feet(ob, vv, x, d, fs);
            if (fst == EL_ENOMEM) { st = fst; break; }
            if (fst) continue;
            member m = {0.0, p->length / dn, sol[c].kappa0 * dn, sol[c].kappa1 * dn, 0};
            for (size_t i = 0; i < n; i++) m.f += d[i] * d[i];
            if (!(m.f < f_below * 2.0 * (double)n)) continue;    /* NaN too */
            for (size_t i = 0; i < n; i++) fs_in[i] = fs[i] * ob->sc;
            const double stray = el__fit_stray(ob->xy, n, fs_in, vv[0][6] * ob->sc, noise * ob->sc, ob->sc);
            if (stray < 0.0) { st = EL_ENOMEM; break; }
            m.follows = stray <= FIT_STRAY;
            all[nm] = m;
            memcpy(mv[nm++], vv[0], sizeof mv[0]);
        }
    }
    /* the lowest objectives of other families (kmax - 1 of them), then the lowest of
     * another family that follows the points, then the lowest again while there is room:
     * a true curve that loops in a gap between clustered points has the lowest; between
     * nearly collinear ends the near-straight member follows them, the lowest loop away */
    int chosen[MAX_MEMBERS], nk = 0;
    for (int pass = 0; pass < 3 && st != EL_ENOMEM; pass++) {
        const int want = pass == 0 && kmax > 1 ? kmax - 1 : kmax;
        while (nk < want) {
            int pick = -1;
            for (int i = 0; i < nm; i++) {
                int taken = pass == 1 && !all[i].follows;
                for (int j = 0; j < nk && !taken; j++) taken = chosen[j] == i || alike(&all[i], &all[chosen[j]]);
                if (!taken && (pick < 0 || all[i].f < all[pick].f)) pick = i;
            }
            if (pick < 0) break;
            chosen[nk++] = pick;
            if (pass == 1) break;   /* one that follows */
        }
    }
    for (int j = 0; j < nk; j++) memcpy(v[j], mv[chosen[j]], sizeof v[j]);
    if (st != EL_ENOMEM) nk += wave_starts(con, v + nk, waves);
    *count = nk;
    ob->rest_ok = 0;
    ob->have_base = 0;
    free(buf);
    free(mv);
    free(sol);
    free(all);
    return st == EL_ENOMEM ? st : nk > 0 ? EL_OK : EL_EDOM;
}
