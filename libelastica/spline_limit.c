/*
 * The largest tension that solves (el_spline_result's largest; elastica.h, Accuracy): the
 * highest the search below solved, no bound: near it the solve is not monotone in the
 * tension (examples/ducks.csv x 100 at sigma h^2 700: 0.0088357 found; of 41 tensions
 * within 1 % of it 12 fail, 0.993 .. 0.9995 and 1.0065 .. 1.009 of it).
 * where tension mode fails (EL_ENOCONV) at sigma h^2 >= EL__SP_STIFF_SH2 on the longest
 * span h, the failure is looked at as the limit of what a double resolves: the nearly
 * straight runs' pieces have their modulus k within ~exp(-sqrt(sigma / 2) h) of 1, a
 * double k resolves 1 - k^2 only in steps of 2 |k| ulp(k) ~ 4.4e-16, so the far boundary
 * layer's curvature only to ~4.4e-16 / |1 - k^2| of itself (the separatrix bound,
 * resolution), ~2.3 x per +50 of sigma h^2 (examples/ducks.csv: 1.2e-7 at 450, 2.9e-7 at
 * 500, 4e-7 at 520, none from 560). The search: sigma h^2 = min(asked, 1024) x 2^(-j/4),
 * j = 1, 2, ..., down to 100, the first that solves without loops, then 3 bisections in
 * log above it (was the Python binding's, which now reads the result). The rungs are not
 * tried from the top down but from the one just below LIKELY (the limit mostly lies at
 * sigma h^2 ~400 .. 560: the separatrix bound above), up until two in a row fail, else
 * down to the first that solves: a rung above the limit costs a whole failing solve (a G2
 * one's search by length too, ~5 x a tension solve). The same rung as from the top where
 * none solves above two failing in a row (above the limit the ladder is not monotone where
 * pieces reach k = 1 exactly and solve at a resolution > 1: F ok F ok ok on three of 62).
 */
#include "internal.h"

/* Tension mode at sigma h^2 = sh2 (h2: h^2): 1 where it solves without loops, with that
 * spline's resolution and least |1 - k^2| over its pieces in got; 0 where not; -1 out of
 * memory */
static int solves(const double *xy, size_t n, const el_spline_options *opt, double h2, double sh2,
                  double got[2], el__spwork *work)
{
    el_spline_options o = *opt;
    o.sigma = sh2 / h2;
    el_spline_result r;
    const int st = el__spline_solve_within(xy, n, &o, work, &r);
    if (st == EL_ENOMEM) return -1;
    const int ok = st == EL_OK && !r.loops;
    if (ok) {
        double kp2 = HUGE_VAL;
        for (size_t j = 0; j < r.npieces; j++) kp2 = fmin(kp2, fabs(1.0 - r.pieces[j].k * r.pieces[j].k));
        got[0] = r.resolution;
        got[1] = kp2;
    }
    el_spline_result_free(&r);
    return ok;
}

/* Rung j of the ladder from top: top x 2^(-j/4) */
static double rung(double top, int j)
{
    return top * pow(2.0, -(double)j / 4.0);
}

/* Where the rungs are first tried: the one just below (sigma h^2 on the longest span) */
#define LIKELY 510.0

int el__spline_largest(const double *xy, size_t n, const el_spline_options *opt, double h,
                       double largest[3], int *nsolves, el__spwork *work)
{
    largest[0] = largest[1] = largest[2] = 0.0;
    *nsolves = 0;
    if (opt->mode != EL_SPLINE_TENSION || !(opt->sigma > 0.0)) return EL_OK;
    const double h2 = h * h, asked = opt->sigma * h2;
    if (!(asked >= EL__SP_STIFF_SH2)) return EL_OK;
    /* spans of ~1e300 (h2 inf): every rung's tension 100 .. 1024 / h2 is 0, none a tension
     * (the fuzz's 14 points at 1e300, G2 ends: ten identical solves at sigma 0, 6.6 s) */
    if (!(100.0 / h2 > 0.0) || !isfinite(1024.0 / h2)) return EL_OK;
    const double top = fmin(asked, 1024.0);
    /* rung j: top x 2^(-j/4), j = 1 .. jmax (>= 100); j0: the first at or below LIKELY */
    int jmax = 15;
    while (jmax >= 1 && rung(top, jmax) < 100.0) jmax--;
    if (jmax < 1) return EL_OK;
    int j0 = 1;
    while (j0 < jmax && rung(top, j0) > LIKELY) j0++;
    /* up from j0 until two rungs in a row fail (the highest that solved: best), else down
     * from below j0 to the first that solves */
    double got[2] = {0.0, 0.0}, g[2];
    int best = 0, fails = 0, s;
    /* the call's budget (spline.c's WORK_BUDGET) spent: no further solve is begun */
    for (int j = j0; j >= 1 && fails < 2 && !el__spwork_spent(work); j--) {
        (*nsolves)++;
        if ((s = solves(xy, n, opt, h2, rung(top, j), g, work)) < 0) return EL_ENOMEM;
        fails = s ? 0 : fails + 1;
        if (s) { best = j; got[0] = g[0]; got[1] = g[1]; }
    }
    for (int j = j0 + 1; !best && j <= jmax && !el__spwork_spent(work); j++) {
        (*nsolves)++;
        if ((s = solves(xy, n, opt, h2, rung(top, j), got, work)) < 0) return EL_ENOMEM;
        if (s) best = j;
    }
    if (!best) return EL_OK;
    double lo = rung(top, best), hi = lo * pow(2.0, 0.25);
    for (int i = 0; i < 3 && !el__spwork_spent(work); i++) {
        const double mid = pow(lo * hi, 0.5);
        (*nsolves)++;
        if ((s = solves(xy, n, opt, h2, mid, g, work)) < 0) return EL_ENOMEM;
        if (s) { lo = mid; got[0] = g[0]; got[1] = g[1]; } else hi = mid;
    }
    largest[0] = lo / h2;
    largest[1] = got[0];
    largest[2] = got[1];
    return EL_OK;
}
