/* The tension solve's completeness against a plain reference: every root of the dense
 * scan (hermite_scan.h: uniform samples and bisection, nothing of the solver's split
 * points, sampling, refinement, touch checks or root finding) is among the solutions
 * el_hermite_solve returns, on 2400 random problems in six families. Guards the
 * solver's fast paths (the touch check's early end, the search range of (40)) against
 * losing solutions, and (40) against the rounding of its printed form (family 2: 11 of
 * its 1027 scanned solutions were missing with that form). */
#include "testutil.h"
#include "hermite_internal.h"
#include "lanes.h"
#include "hermite_scan.h"
#include <float.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_ellint.h>
#include <stdio.h>
#include <string.h>

enum { NPROB = 400, NX_SET = 800 };

/* family 0: sigma |p1-p0|^2 uniform in [-10, 40] (the bench); 1: log-uniform in [40, 1e4]
 * (solutions near the separatrix, k across 1); 2: near-degenerate tangents, t0 within
 * 1e-12..1e-6 rad of the normal to the chord (P2 ~ 0) or t1 within that of t0 (V1 ~ 0),
 * sigma |p1-p0|^2 uniform in [-10, 200]; 3: negative, uniform in [-100, -10] (few
 * solutions); 4: the tangents within 0.05 rad of the chord's direction (aligned) or t1
 * within 0.05 rad of -t0 (opposite), sigma |p1-p0|^2 uniform in [-10, 100]; 5: the same
 * tangents at sigma |p1-p0|^2 uniform in [100, 1000], where the near-straight aligned
 * solutions (L ~ 1 + 1e-5) lie exponentially close to the separatrix: main (f540936) missed
 * 30 of its 1023 scanned solutions (el__hermite_sep_eval's Newton stopped at 4e-16 sigma,
 * far above the rounding of |F| - sigma there, so its w, and f with it (~1e-7), depended on
 * the guess, and the root finder's |f| stalled above what the solver keeps), none since.
 * p0 = 0, t0 = (0, 1), |p1| = 1. */
static void draw(unsigned long long *st, int family, double p1[2], double t1[2], double *sigma)
{
    double a = test_uniform(st, -M_PI, M_PI), c = test_uniform(st, -M_PI, M_PI);
    const double u = test_uniform(st, 0.0, 1.0);
    *sigma = family == 0 ? -10.0 + 50.0 * u : family == 1 ? 40.0 * pow(250.0, u) : family == 3 ? -100.0 + 90.0 * u
           : family == 4 ? -10.0 + 110.0 * u : family == 5 ? 100.0 + 900.0 * u : -10.0 + 210.0 * u;
    if (family == 2) {
        const double e = pow(10.0, test_uniform(st, -12.0, -6.0)) * (test_uniform(st, 0.0, 1.0) < 0.5 ? -1.0 : 1.0);
        if (test_uniform(st, 0.0, 1.0) < 0.5) a = (test_uniform(st, 0.0, 1.0) < 0.5 ? 0.0 : M_PI) + e;
        else c = M_PI / 2 + (test_uniform(st, 0.0, 1.0) < 0.5 ? 0.0 : M_PI) + e;
    }
    if (family >= 4) {
        /* t0 = (0, 1) at angle pi/2 from the x axis: the chord's angle a near pi/2, then t1 near
         * the chord's direction (aligned) or near -t0 */
        a = M_PI / 2 + test_uniform(st, -0.05, 0.05);
        c = test_uniform(st, 0.0, 1.0) < 0.5 ? a + test_uniform(st, -0.05, 0.05) : -M_PI / 2 + test_uniform(st, -0.05, 0.05);
    }
    p1[0] = cos(a);
    p1[1] = sin(a);
    t1[0] = cos(c);
    t1[1] = sin(c);
}

/* The solver's normalised problem (p0 = 0, t0 = (0, 1), |p1| = 1) of draw()'s data. */
static hprob normalised_problem(const double p1[2], const double t1[2], double sigma)
{
    hprob pr;
    memset(&pr, 0, sizeof pr);
    pr.P1 = p1[0]; pr.P2 = p1[1]; pr.V1 = t1[0]; pr.V2 = t1[1]; pr.Lmin = 1.0; pr.sigma = sigma;
    el__hermite_set_case(&pr);
    return pr;
}

/* Parallel end tangents (a blend between parallel lines): the problem is symmetric under the
 * half turn about the chord's midpoint with the curve reversed, so every solution's partner
 * (kappa0' = -kappa1, kappa1' = -kappa0, the same length and energy) is a solution too, and
 * the solutions do not depend on the samples (12 against 200). Before WHOLE_PERIOD one branch
 * of (17) had its end state equal to its start up to rounding, its length 0+ or a period at
 * random: 87 of 200 such problems gave other sets with other samples, losing the least-energy
 * solution in some. Tension and length mode. */
START_TEST(parallel_tangents_give_symmetric_complete_sets)
{
    unsigned long long st = 4242;
    int pairs = 0;
    for (int t = 0; t < 120; t++) {
        const double p0[2] = {0.0, 0.0}, a = test_uniform(&st, -M_PI, M_PI);
        const double p1[2] = {test_uniform(&st, -1.0, 1.0), test_uniform(&st, -1.0, 1.0)}, tg[2] = {cos(a), sin(a)};
        const double d2 = p1[0] * p1[0] + p1[1] * p1[1];
        el_hermite_options o;
        el_hermite_options_defaults(&o);
        if (t % 3 == 2) {
            o.mode = EL_HERMITE_LENGTH;
            o.length = sqrt(d2) * test_uniform(&st, 1.05, 3.0);
        } else {
            o.sigma = test_uniform(&st, -10.0, 40.0) / d2;
        }
        el_hermite_result r[2];
        for (int k = 0; k < 2; k++) {
            o.samples = k ? 200 : 12;
            ck_assert_int_eq(el_hermite_solve(p0, tg, p1, tg, &o, &r[k]), EL_OK);
        }
        ck_assert_msg(r[0].count == r[1].count, "problem %d: %zu solutions with 12 samples, %zu with 200", t,
                      r[0].count, r[1].count);
        for (size_t i = 0; i < r[0].count; i++) {
            const el_hermite_solution *s = &r[0].solutions[i];
            int partner = 0, same = 0;
            for (size_t j = 0; j < r[0].count; j++) {
                const el_hermite_solution *q = &r[0].solutions[j];
                partner |= fabs(q->length - s->length) <= 1e-8 * s->length &&
                           fabs(q->kappa0 + s->kappa1) <= 1e-6 * (1.0 + fabs(s->kappa1)) &&
                           fabs(q->kappa1 + s->kappa0) <= 1e-6 * (1.0 + fabs(s->kappa0));
            }
            for (size_t j = 0; j < r[1].count; j++)
                same |= fabs(r[1].solutions[j].length - s->length) <= 1e-8 * s->length &&
                        fabs(r[1].solutions[j].kappa0 - s->kappa0) <= 1e-6 * (1.0 + fabs(s->kappa0));
            ck_assert_msg(partner && same, "problem %d solution %zu (L %.10g, kappa0 %.6g, kappa1 %.6g): partner %d, "
                          "with 200 samples %d", t, i, s->length, s->kappa0, s->kappa1, partner, same);
            pairs++;
        }
        el_hermite_result_free(&r[0]);
        el_hermite_result_free(&r[1]);
    }
    ck_assert_int_gt(pairs, 200);
}
END_TEST

START_TEST(tension_solutions_contain_every_scanned_root)
{
    const int family = _i;
    unsigned long long st = 1601 + 7919 * (unsigned long long)family;
    int nscan = 0, nret = 0, nprob = 0, nmiss = 0;
    for (int t = 0; t < NPROB; t++) {
        double p1[2], t1[2], sigma;
        draw(&st, family, p1, t1, &sigma);
        scan_root r[MAXSCAN];
        el_hermite_result res;
        int n;
        if (!scan_and_solve(p1, t1, sigma, NX_SET, r, &n, &res)) continue;   /* the scan covers case 1 */
        for (int i = 0; i < n; i++) {
            const int found = scan_root_found(&r[i], &res);
            if (!found && nmiss++ < 10)
                fprintf(stderr, "family %d problem %d (P %.17g %.17g V %.17g %.17g sigma %.17g): the scan's "
                        "solution kappa0 %.10g, L %.10g is missing\n", family, t, p1[0], p1[1], t1[0], t1[1],
                        sigma, r[i].k0, r[i].L);
        }
        nscan += n;
        nret += (int)res.count;
        nprob++;
        el_hermite_result_free(&res);
    }
    ck_assert_msg(nmiss == 0, "family %d: %d of %d scanned solutions missing (the first above)", family, nmiss, nscan);
    ck_assert_int_gt(nprob, NPROB / 2);
    ck_assert_int_gt(nscan, family == 3 ? 0 : nprob);
    fprintf(stderr, "tension_solutions_contain_every_scanned_root (family %d): %d problems, %d scan roots, %d returned\n",
            family, nprob, nscan, nret);
}
END_TEST

/* The root finder (bracket_root: inverse quadratic interpolation and regula falsi in
 * ln|x - x_c| next to a separatrix crossing, in x elsewhere, and the stop where the secant step from a full-precision value
 * falls below the rounding of x) against its plain counterpart, the scan's bisection, on the
 * raw roots of the tension solve: each root in the x chart is exact to double precision
 * (|f| <= 1e-14, or f changes sign across x -+ 16 eps |x|: steep f rounds above 1e-14), and
 * its kappa0 equals that of the bisection's root of the same solution (kappa0, L within
 * 1e-6 of each other) to ROOT_AGREE relative, in all five families of draw() (largest
 * 2.6e-12, family 1, the same before the chart; L is not compared: next to the separatrix
 * one ulp of kappa0 moves it by up to ~1e-9). Main's root finder fails the first check
 * once in family 4 (|f| = 3.6e-14, no sign change within 16 eps |x|). */
#define ROOT_AGREE 1e-11
START_TEST(tension_roots_exact_and_equal_to_the_bisection)
{
    const int family = _i;
    unsigned long long st = 4409 + 7919 * (unsigned long long)family;
    int nroot = 0, nmatch = 0;
    double worst = 0.0;
    for (int t = 0; t < 200; t++) {
        double p1[2], t1[2], sigma;
        draw(&st, family, p1, t1, &sigma);
        hprob pr = normalised_problem(p1, t1, sigma);
        if (pr.hcase != 1) continue;
        scan_root r[MAXSCAN];
        const int n = dense_scan(&pr, sigma, NX_SET, r);
        hrootlist l = {NULL, 0, 0};
        ck_assert_int_eq(el__hermite_solve_tension(&pr, 12, &l), EL_OK);
        for (size_t i = 0; i < l.n; i++) {
            const hroot *q = &l.v[i];
            nroot++;
            if (!q->st.has_sep && !(fabs(q->st.f) <= 1e-14)) {
                const double d = 16.0 * DBL_EPSILON * fabs(q->x) + 1e-300;
                hstate sl, sr;
                ck_assert_int_eq(el__hermite_full_eval(&pr, q->x - d, q->b, &sl), EL_OK);
                ck_assert_int_eq(el__hermite_full_eval(&pr, q->x + d, q->b, &sr), EL_OK);
                ck_assert_msg(sl.f * sr.f <= 0.0, "family %d problem %d: root x %.17g f %.3e is no sign change "
                              "within 16 eps |x| (%.3e, %.3e)", family, t, q->x, q->st.f, sl.f, sr.f);
            }
            for (int j = 0; j < n; j++) {
                const double dk = fabs(q->st.k0 - r[j].k0) / (1.0 + fabs(r[j].k0)), dl = fabs(q->st.L - r[j].L) / r[j].L;
                if (!(dk <= 1e-6 && dl <= 1e-6)) continue;
                nmatch++;
                worst = fmax(worst, dk);
                break;
            }
        }
        free(l.v);
    }
    ck_assert_msg(worst <= ROOT_AGREE, "family %d: a root's kappa0 differs from the bisection's by %.3e", family, worst);
    ck_assert_int_gt(nmatch, nroot / 2);
    fprintf(stderr, "tension_roots_exact_and_equal_to_the_bisection (family %d): %d roots, %d matched by the "
            "bisection, largest difference %.3e\n", family, nroot, nmatch, worst);
}
END_TEST

/* Theorem 9's bound against the period from GSL's complete integral: for sigma > 0 the
 * period T(kappa_m) = 4 K(k) / sqrt(|F| / 2) (|F| = kappa_m^2 - sigma, k^2 = kappa_m^2 /
 * (2 |F|)) of the bound is below Lmin = 1 (a bound), and 0.2 % below it above 1 (tight,
 * the 1e-3 of kappa_bound's bracket), on 3000 tensions log-uniform in [1e-8, 1e5]; for
 * sigma <= 0 the closed form sqrt(C0^2 + sigma). */
static double period_gsl(double km, double sigma)
{
    const double Fn = km * km - sigma;
    return 4.0 * gsl_sf_ellint_Kcomp(sqrt(km * km / (2.0 * Fn)), GSL_PREC_DOUBLE) / sqrt(0.5 * Fn);
}

START_TEST(kappa_bound_bounds_the_period_tightly)
{
    unsigned long long st = 977;
    const double P[2] = {0.6, 0.8}, V[2] = {0.0, 1.0};
    int ntight = 0;
    for (int t = 0; t < 3000; t++) {
        const double sigma = t % 10 == 9 ? -test_uniform(&st, 0.0, 120.0) : pow(10.0, test_uniform(&st, -8.0, 5.0));
        el_hermite_analysis a;
        ck_assert_int_eq(el_hermite_analyse(P, V, sigma, &a), EL_OK);
        const double B = a.kappa_bound;
        if (sigma <= 0.0) {
            const double b2 = C0_PERIOD * C0_PERIOD + sigma;
            ck_assert(b2 > 0.0 ? fabs(B - sqrt(b2)) <= 1e-8 * sqrt(b2) : B < 0.0);
            continue;
        }
        ck_assert_msg(period_gsl(B, sigma) < 1.0, "sigma %.17g: T(B = %.17g) = %.17g not below 1", sigma, B,
                      period_gsl(B, sigma));
        const double below = B / (1.0 + 2e-3);
        if (below * below <= 2.0 * sigma) continue;             /* B at the separatrix */
        ck_assert_msg(period_gsl(below, sigma) > 1.0, "sigma %.17g: B = %.17g not within 0.2 %% of the root",
                      sigma, B);
        ntight++;
    }
    ck_assert_int_gt(ntight, 2000);
}
END_TEST

/* The kappa_m bound as it was computed before the solver moved to the stack and the
 * bracket's end periods were served from their first evaluation: a heap-allocated GSL
 * Brent solver over T(kappa_m) - Lmin, the period by the AGM with D (all of its sums). */
typedef struct { double sigma, Lmin; } plain_tp;
static double plain_period(double km, double sigma)
{
    const double Fn = km * km - sigma, k = sqrt(km * km / (2.0 * Fn));
    double K, D;
    if (el__ellint_complete(k, (Fn - sigma) / (2.0 * Fn), &K, &D)) return NAN;
    return 4.0 * K / sqrt(0.5 * Fn);
}
static double plain_gap(double km, void *p)
{
    const plain_tp *t = p;
    return plain_period(km, t->sigma) - t->Lmin;
}
static int plain_kappa_bound(double sigma, double Lmin, double *B)
{
    const double c = C0_PERIOD / Lmin;
    if (sigma <= 0.0) {
        const double b2 = c * c + sigma;
        *B = b2 > 0.0 ? sqrt(b2) * (1.0 + 1e-9) : -1.0;
        return EL_OK;
    }
    const double lo = sqrt(2.0 * sigma) * (1.0 + 1e-12);
    double hi = sqrt(2.0 * sigma) + c, Thi = plain_period(hi, sigma);
    for (int i = 0; i < 200 && !(Thi < Lmin); i++) Thi = plain_period(hi *= 2.0, sigma);
    if (!(Thi < Lmin)) return EL_EINTERNAL;
    if (!(plain_period(lo, sigma) > Lmin)) { *B = lo; return EL_OK; }
    plain_tp tp = {sigma, Lmin};
    gsl_function fn = {plain_gap, &tp};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    ck_assert_ptr_nonnull(s);
    ck_assert_int_eq(gsl_root_fsolver_set(s, &fn, lo, hi), GSL_SUCCESS);
    for (int it = 0; it < 200; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) break;
        if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 0.0, 1e-3) == GSL_SUCCESS)
            break;
    }
    *B = gsl_root_fsolver_x_upper(s) * (1.0 + 1e-9);
    gsl_root_fsolver_free(s);
    return EL_OK;
}

/* el__hermite_kappa_bound against the plain computation above: the same status and bits
 * for sigma from -120 to 1e5 (sparse and dense in the exponent) and Lmin from 1 (the
 * tension mode) to 10 (the length mode's seeds). */
START_TEST(kappa_bound_equals_the_plain_brent)
{
    unsigned long long st = 1979;
    const double Lmins[4] = {1.0, 1.001, 2.0, 10.0};
    for (int t = 0; t < 20000; t++) {
        const double sigma = t % 10 == 9 ? -test_uniform(&st, 0.0, 120.0)
                           : t % 2 ? pow(10.0, test_uniform(&st, -8.0, 5.0)) : pow(10.0, -8.0 + 13.0 * t / 20000.0);
        const double Lmin = Lmins[t % 4];
        double B0 = 0.0, B1 = 0.0;
        const int r0 = plain_kappa_bound(sigma, Lmin, &B0), r1 = el__hermite_kappa_bound(sigma, Lmin, &B1);
        ck_assert_int_eq(r0, r1);
        ck_assert_msg(memcmp(&B0, &B1, sizeof B0) == 0, "sigma %.17g Lmin %g: B %.17g / %.17g", sigma, Lmin, B0, B1);
    }
}
END_TEST

/* |F|^2 - sigma^2 = 4 kappa0'^2 + kappa0^2 (kappa0^2 - 2 sigma) at x on branch b. */
static double gap(const hprob *pr, int b, double x)
{
    hstate st;
    if (el__hermite_curvdata(pr, x, b, &st)) return NAN;
    return 4.0 * st.k0p * st.k0p + st.k0 * st.k0 * (st.k0 * st.k0 - 2.0 * pr->sigma);
}

/* At high tension the solutions hug the separatrix and the separatrix pieces start from
 * the crossings, the roots of (40): each root el_hermite_analyse reports is a sign
 * change of |F|^2 - sigma^2 on its branch within 1e-14 (1 + |kappa0|) (the polynomial's
 * own roots were up to 1.7e-10 off at sigma |p1-p0|^2 = 4000, and a solution was lost). */
START_TEST(separatrix_crossings_exact_at_high_tension)
{
    unsigned long long st = 3301;
    int nroot = 0;
    for (int t = 0; t < 300; t++) {
        double P[2], V[2], sigma;
        hprob pr;
        el_hermite_analysis an;
        high_tension_problem(&st, P, V, &sigma, &pr, &an);
        for (size_t i = 0; i < an.nroot; i++) {
            const int b = an.root_branch[i];
            const double x = an.root[i], d = 1e-14 * (1.0 + fabs(x));
            const double gl = gap(&pr, b, x - d), gr = gap(&pr, b, x + d);
            if (!isfinite(gl) || !isfinite(gr)) continue;   /* at an end of (18) */
            ck_assert_msg(gl * gr <= 0.0, "sigma %g: root %.17g of (40) is no crossing to %.3g (gap %g, %g)",
                          sigma, x, d, gl, gr);
            nroot++;
        }
    }
    ck_assert_int_gt(nroot, 300);
    fprintf(stderr, "separatrix_crossings_exact_at_high_tension: %d roots\n", nroot);
}
END_TEST

/* Roots of (40) (and of degree-8 polynomials with close roots and complex pairs near the
 * axis) by Bernstein isolation (el__poly_roots_in) against the plain method by the roots
 * of the derivatives (el__poly_roots_in_plain): the same number in the interval, each
 * within 64 times its condition, the rounding error of p at the root over |p'| (both are
 * roots only to that: 1e-9 relative at sigma |p1-p0|^2 = 4000), plus 1e-14 (1 + |x|).
 * Families: the bench's tensions, high tension up to sigma |p1-p0|^2 = 1e5 (coefficients
 * over thirty orders of magnitude), near-degenerate tangents (draw), and products of
 * (x - r_i) with a pair 1e-3..1e-2 apart, a complex pair 1e-3..1e-2 off the axis and
 * an interval ending at a root (closer pairs in [-8, 8] are lost in p's rounding: a pair
 * 1e-5 apart there dips below zero by about the rounding error, and either method may
 * find it or not depending on where it evaluates p). */
static void compare_roots(const double *c, int deg, double lo, double hi, int *nroot, double *worst)
{
    double rf[8], rp[8];
    int nf, np;
    el__poly_roots_in(c, deg, lo, hi, 4e-16, rf, &nf);
    el__poly_roots_in_plain(c, deg, lo, hi, 4e-16, rp, &np);
    ck_assert_msg(nf == np, "%d roots by isolation, %d by the plain method in [%.17g, %.17g]", nf, np, lo, hi);
    for (int i = 0; i < nf; i++) {
        const double x = rp[i];
        double v = c[deg], d = 0.0, ab = fabs(c[deg]);
        for (int j = deg - 1; j >= 0; j--) { d = d * x + v; v = v * x + c[j]; ab = ab * fabs(x) + fabs(c[j]); }
        const double cond = 2.0 * deg * DBL_EPSILON * ab / fabs(d);
        const double dist = fabs(rf[i] - x);
        ck_assert_msg(dist <= 64.0 * cond + 1e-14 * (1.0 + fabs(x)),
                      "root %.17g by isolation, %.17g by the plain method (condition %.3g)", rf[i], x, cond);
        ck_assert(i == 0 || rf[i] > rf[i - 1]);
        *worst = fmax(*worst, dist / (cond + 1e-16 * (1.0 + fabs(x))));
    }
    *nroot += nf;
}

START_TEST(poly40_isolated_roots_match_plain_method)
{
    unsigned long long st = 4409;
    int nroot = 0;
    double worst = 0.0;
    for (int t = 0; t < 3000; t++) {
        const int family = t % 3;
        double p1[2], t1[2], sigma;
        draw(&st, family, p1, t1, &sigma);
        if (t % 6 == 1) sigma = pow(10.0, test_uniform(&st, 1.5, 5.0));
        if (!(sigma > 0.0)) continue;
        hprob pr = normalised_problem(p1, t1, sigma);
        if (pr.hcase == 3) continue;
        double c[9];
        const int deg = el__hermite_poly40(&pr, c);
        const double X = sqrt(2.0 * sigma) * (1.0 + 1e-9);
        compare_roots(c, deg, -X, X, &nroot, &worst);
    }
    for (int t = 0; t < 3000; t++) {
        /* (x - r_0) ... (x - r_5) ((x - u)^2 + e^2), or eight real roots */
        double c[9] = {1.0}, r[8];
        int deg = 0;
        r[0] = test_uniform(&st, -5.0, 5.0);
        r[1] = r[0] + pow(10.0, -test_uniform(&st, 2.0, 3.0));
        for (int i = 2; i < 8; i++) r[i] = test_uniform(&st, -8.0, 8.0);
        for (int i = 0; i < 8; i++) {
            if (t % 2 && i == 6) {
                const double e = pow(10.0, -test_uniform(&st, 2.0, 3.0)), q[3] = {r[6] * r[6] + e * e, -2.0 * r[6], 1.0};
                double n[9] = {0};
                for (int j = 0; j <= deg; j++)
                    for (int k = 0; k < 3; k++) n[j + k] += c[j] * q[k];
                deg += 2;
                memcpy(c, n, sizeof c);
                break;
            }
            for (int j = deg + 1; j > 0; j--) c[j] = c[j - 1] - r[i] * c[j];
            c[0] *= -r[i];
            deg++;
        }
        compare_roots(c, deg, -8.0, t % 5 ? 8.0 : r[5], &nroot, &worst);
    }
    ck_assert_int_gt(nroot, 20000);
    fprintf(stderr, "poly40_isolated_roots_match_plain_method: %d roots, largest difference %.3g times the condition\n",
            nroot, worst);
}
END_TEST

/* At a subnormal tension the range of (40) is ~1e-155 wide and its Bernstein
 * coefficients underflow: isolation then counted more roots than the degree and wrote
 * past the caller's eight (the fuzz driver's finding, ASan). Now no more than the
 * degree, the plain method's roots, and el_hermite_analyse reports them. */
START_TEST(poly40_roots_never_exceed_the_degree_at_subnormal_tension)
{
    const double th = 6.3787289234760038, ph = 1.0000000000000011;
    const double sigmas[] = {1e-310, 1e-300, 4.9e-324, 1e-200};
    for (int k = 0; k < 4; k++) {
        hprob pr;
        memset(&pr, 0, sizeof pr);
        pr.P1 = cos(th); pr.P2 = sin(th); pr.V1 = cos(ph); pr.V2 = sin(ph); pr.Lmin = 1.0; pr.sigma = sigmas[k];
        el__hermite_set_case(&pr);
        double c[9], rf[16], rp[16];
        int nf, np;
        const int deg = el__hermite_poly40(&pr, c);
        const double X = sqrt(2.0 * pr.sigma) * (1.0 + 1e-9);
        el__poly_roots_in(c, deg, -X, X, 4e-16, rf, &nf);
        el__poly_roots_in_plain(c, deg, -X, X, 4e-16, rp, &np);
        ck_assert_int_le(nf, deg);
        ck_assert_int_eq(nf, np);
        const double P[2] = {pr.P1, pr.P2}, V[2] = {pr.V1, pr.V2};
        el_hermite_analysis an;
        ck_assert_int_eq(el_hermite_analyse(P, V, pr.sigma, &an), EL_OK);
        ck_assert_int_le((int)an.nroot, 8);
    }
}
END_TEST

/* The separatrix chart is a function of its coordinates: el__hermite_sep_eval from the
 * crossing itself (the scan's guess) and from the previous sample's w (the solver's)
 * gives the state or fails alike, and the same f and L, on every crossing of (40) of
 * family 5's problems (aligned tangents, sigma |p1-p0|^2 in [100, 1000]), NY samples per
 * side from |F| - sigma = 1e-3 sigma down to 1e-300 sigma. The former damped Newton
 * (f540936) fails the first check here; on 200 other problems of the family its f
 * differs by up to 1.2e-5 (Newton's
 * stop at 4e-16 sigma) and 4 samples succeed from one guess only (a step over a hump to a
 * neighbouring crossing). Now: largest difference 2.9e-10 here, 1.4e-9 on those 200 (the
 * resolution of kappa0 next to the saddle: both ends of a near-straight solution lie
 * there, and an ulp of kappa0 moves f by ~1e-9), none one-sided. */
START_TEST(separatrix_chart_independent_of_the_guess)
{
    unsigned long long st = 6007;
    int nsamples = 0;
    double worst = 0.0;
    for (int t = 0; t < 100; t++) {
        double p1[2], t1[2], sigma;
        draw(&st, 5, p1, t1, &sigma);
        hprob pr = normalised_problem(p1, t1, sigma);
        el_hermite_analysis an;
        ck_assert_int_eq(el_hermite_analyse(p1, t1, sigma, &an), EL_OK);
        for (size_t i = 0; i < an.nroot; i++)
            for (int side = -1; side <= 1; side += 2) {
                double warm = an.root[i];
                for (int j = 0; j < NY; j++) {
                    const double tt = (double)j / (NY - 1);
                    const double y = log(1e-3 * sigma) - 690.0 * (1.0 - tt) * (1.0 - tt);
                    hstate cold_st, warm_st;
                    double wc = an.root[i], ww = warm;
                    const int rc = el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma, 1.0,
                                                        &wc, &cold_st, NULL, NULL);
                    const int rw = el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma, 1.0,
                                                        &ww, &warm_st, NULL, NULL);
                    ck_assert_msg(!rc == !rw, "problem %d root %.17g side %d y %.17g: rc %d from the crossing, %d from "
                                  "the last w", t, an.root[i], side, y, rc, rw);
                    if (rc) continue;
                    nsamples++;
                    warm = ww;
                    const double d = fmax(fabs(warm_st.f - cold_st.f) / (1.0 + fabs(cold_st.f)),
                                          fabs(warm_st.L - cold_st.L) / cold_st.L);
                    worst = fmax(worst, d);
                    ck_assert_msg(d <= 1e-8, "problem %d y %.17g: f %.17g (warm) vs %.17g, L %.17g vs %.17g", t, y,
                                  warm_st.f, cold_st.f, warm_st.L, cold_st.L);
                }
            }
    }
    ck_assert_int_gt(nsamples, 100000);
    fprintf(stderr, "separatrix_chart_independent_of_the_guess: %d samples, largest difference %.3e\n", nsamples,
            worst);
}
END_TEST

/* The separatrix chart's cache (el__hermite_sep_eval_from: a call whose guess is the w the
 * last one returned starts from that call's point, hermite_tension.c's piece_eval) against
 * the plain el__hermite_sep_eval, on the crossings of family 1's and 5's problems
 * (sigma |p1-p0|^2 in [40, 1e4] and [100, 1000], both sides of the separatrix, k across 1),
 * NY samples from |F| - sigma = 1e-3 sigma down to 1e-300 sigma, visited in order and
 * alternating between the ends (the root finder's jumps), each from the last one's w:
 * - the plain call from the cached point's w (sep_solve's, before sep_exact_state refines
 *   it by a few ulps) gives the same status and bitwise the same state;
 * - the plain call from the returned w (the guess without the cache) the same f and L to
 *   the chart's independence of its guess (above) where both succeed. Where one fails
 *   (1 of 688k samples) it is the chart's, not the cache's: the plain call from the cached
 *   point fails alike (first check); piece_eval then starts again from the piece's guess. */
START_TEST(separatrix_cache_gives_the_plain_states)
{
    int nsamples = 0, nhit = 0, none_sided = 0;
    double worst = 0.0;
    for (int family = 1; family <= 5; family += 4) {
        unsigned long long st = 9001 + (unsigned long long)family;
        for (int t = 0; t < 60; t++) {
            double p1[2], t1[2], sigma;
            draw(&st, family, p1, t1, &sigma);
            hprob pr = normalised_problem(p1, t1, sigma);
            el_hermite_analysis an;
            ck_assert_int_eq(el_hermite_analyse(p1, t1, sigma, &an), EL_OK);
            for (size_t i = 0; i < an.nroot; i++)
                for (int side = -1; side <= 1; side += 2)
                    for (int order = 0; order < 2; order++) {
                        hsep_cache cache;
                        cache.valid = 0;
                        double w = an.root[i];
                        for (int j = 0; j < NY; j++) {
                            const int jj = order == 0 ? j : j % 2 ? NY - 1 - j / 2 : j / 2;
                            const double tt = (double)jj / (NY - 1);
                            const double y = log(1e-3 * sigma) - 690.0 * (1.0 - tt) * (1.0 - tt);
                            hstate cs, ps, qs;
                            /* wq: the cached point's w, where the call starts (a hit: valid, w equal) */
                            const int hit = cache.valid && cache.w == w;
                            double wc = w, wp = w, wq = hit ? cache.pt[cache.cur].w : w;
                            const int rc = el__hermite_sep_eval_from(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma,
                                                                     1.0, &wc, &cs, NULL, NULL, &cache);
                            const int rq = el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma,
                                                                1.0, &wq, &qs, NULL, NULL);
                            const int rp = el__hermite_sep_eval(&pr, HCHART_X, 0, an.root_branch[i], side, y, sigma,
                                                                1.0, &wp, &ps, NULL, NULL);
                            nhit += hit;
                            ck_assert_int_eq(rc, rq);
                            if (!rc) ck_assert_msg(wc == wq && cs.f == qs.f && cs.L == qs.L && cs.E == qs.E,
                                                   "family %d problem %d y %.17g: not the plain state", family, t, y);
                            if (!rc != !rp) {
                                none_sided++;
                                w = rc ? w : wc;
                                continue;
                            }
                            if (rc) continue;
                            nsamples++;
                            w = wc;
                            const double d = fmax(fabs(cs.f - ps.f) / (1.0 + fabs(ps.f)), fabs(cs.L - ps.L) / ps.L);
                            worst = fmax(worst, d);
                            ck_assert_msg(d <= 1e-8, "family %d problem %d y %.17g: f %.17g (cache) vs %.17g, L %.17g "
                                          "vs %.17g", family, t, y, cs.f, ps.f, cs.L, ps.L);
                        }
                    }
        }
    }
    ck_assert_int_gt(nsamples, 100000);
    fprintf(stderr, "separatrix_cache_gives_the_plain_states: %d samples (%d hits), largest difference %.3e, %d one-sided\n",
            nsamples, nhit, worst, none_sided);
}
END_TEST

/* A steep root: at sigma |p1-p0|^2 = 629 two solutions have kappa0 within 4e-9 of each
 * other, and f runs from 0.04 to -0.01 over 2e-7 of kappa0 next to the second; bracket_root
 * stopped as at a jump (L wrapping at a period: the bracket 1e-9 |x| wide with |f| >= 1e-4)
 * with |f| = 1.7e-4 on a bracket 3.1e-8 wide, one step before |f| fell below 1e-14, when
 * its steps were changed (inverse quadratic interpolation): the jump is now declared only
 * where a step also fails to halve |f|. All four solutions, the steep one among them. */
START_TEST(steep_root_next_to_a_close_pair_is_kept)
{
    const double p0[2] = {0.0, 0.0}, p1[2] = {0.29161144505791281, -0.2026611146185322};
    const double t0[2] = {-0.088068724982514612, 0.99611440089979331}, t1[2] = {0.90674630356147023, -0.42167658338780223};
    el_hermite_options opt;
    el_hermite_options_defaults(&opt);
    opt.sigma = 4987.6367385076646;
    el_hermite_result res;
    ck_assert_int_eq(el_hermite_solve(p0, t0, p1, t1, &opt, &res), EL_OK);
    int steep = 0;
    for (size_t i = 0; i < res.count; i++)
        steep |= fabs(res.solutions[i].length - 0.4923652212900993) <= 1e-9 &&
                 fabs(res.solutions[i].kappa0 - 88.338122366102297) <= 1e-6;
    ck_assert_int_eq((int)res.count, 4);
    ck_assert_msg(steep, "the steep solution (L 0.49236522129, kappa0 88.338122366) is missing");
    el_hermite_result_free(&res);
}
END_TEST


/* el__hermite_x_objective (the bracketing samples' f) and el__hermite_x_class against the
 * plain path, el__hermite_curvdata then el__hermite_shape_eval (el__hermite_state_class): the
 * same status and the same bits,
 * at the coarse and the full precision, on every branch over [-B, B] and a margin
 * beyond (no curve there), for the six families' problems. */
START_TEST(x_objective_and_class_equal_the_plain_evaluation)
{
    unsigned long long st = 4711;
    long nsame = 0, nfail = 0;
    for (int family = 0; family < 6; family++)
        for (int t = 0; t < 60; t++) {
            double p1[2], t1[2], sigma;
            draw(&st, family, p1, t1, &sigma);
            hprob pr = normalised_problem(p1, t1, sigma);
            if (el__hermite_kappa_bound(pr.sigma, pr.Lmin, &pr.B) || pr.B < 0.0) continue;
            for (int b = 0; b < 4; b++)
                for (int i = 0; i <= 400; i++) {
                    const double x = pr.B * (-1.1 + 2.2 * i / 400.0);
                    hstate cs;
                    double Fn;
                    const int cls = el__hermite_curvdata(&pr, x, b, &cs) ? CLASS_NONE : el__hermite_state_class(&pr, &cs, &Fn);
                    ck_assert_int_eq(cls, el__hermite_x_class(&pr, x, b));
                    for (int q = 0; q < 2; q++) {
                        const double qs = q ? 1.0 : 0.1;
                        hstate hs;
                        double f;
                        int rc0 = el__hermite_curvdata(&pr, x, b, &hs);
                        if (!rc0) rc0 = el__hermite_shape_eval(&pr, qs, &hs);
                        const int rc1 = el__hermite_x_objective(&pr, x, b, qs, &f);
                        ck_assert_int_eq(rc0, rc1);
                        if (rc0) { ck_assert(isnan(f)); nfail++; continue; }
                        ck_assert(memcmp(&f, &hs.f, sizeof f) == 0);
                        nsame++;
                    }
                }
        }
    ck_assert(nsame > 100000 && nfail > 1000);   /* both outcomes covered */
}
END_TEST

/* el__hermite_x_objectives (hermite_lanes.c: the bracketing samples four at a time where
 * the processor has AVX2, else two), and each width by itself, against
 * el__hermite_x_objective one by one: the same bits (NAN where it fails), at the coarse
 * and the full precision, on every branch of the six families' problems (cases 1, 2 and
 * 3), on runs of 1 to 13 abscissae across [-1.1 B, 1.1 B]: groups of inflectional,
 * non-inflectional, mixed (left to the narrower evaluation) and failing lanes, short last
 * groups. */
START_TEST(x_objectives_equal_the_scalar_objective)
{
    unsigned long long st = 1701;
    long nsame = 0, nfail = 0, ninfl = 0, nnon = 0, nwidth[3] = {0, 0, 0};
    const int four = EL__LANES4 && el__lanes4_available();
    if (!four) fprintf(stderr, "x_objectives_equal_the_scalar_objective: four lanes not run (no AVX2 here, or built without)\n");
    for (int family = 0; family < 6; family++)
        for (int t = 0; t < 60; t++) {
            double p1[2], t1[2], sigma;
            draw(&st, family, p1, t1, &sigma);
            hprob pr = normalised_problem(p1, t1, sigma);
            if (t % 10 == 0) {   /* case 3: P2 = 0, V1 = 0 */
                pr.P1 = 1.0; pr.P2 = 0.0; pr.V1 = 0.0; pr.V2 = t % 20 ? 1.0 : -1.0;
                el__hermite_set_case(&pr);
            }
            if (el__hermite_kappa_bound(pr.sigma, pr.Lmin, &pr.B) || pr.B < 0.0) continue;
            for (int b = 0; b < 4; b++)
                for (int r = 0; r < 60; r++) {
                    double x[13], f[13];
                    const int n = 1 + (int)test_uniform(&st, 0.0, 13.0);
                    const double c = pr.B * test_uniform(&st, -1.1, 1.1), w = pr.B * pow(10.0, test_uniform(&st, -6.0, 0.0));
                    for (int i = 0; i < n; i++) x[i] = c + w * test_uniform(&st, -1.0, 1.0);
                    const double qs = r % 2 ? 1.0 : 0.1;
                    /* the dispatch, then two lanes, then four (where they run) */
                    const int width = r % 3 == 0 ? 0 : r % 3 == 1 ? 2 : 4;
                    if (width == 0) el__hermite_x_objectives(&pr, x, n, b, qs, f);
                    else if (width == 2) el__hermite_x_objectives2(&pr, x, n, b, qs, f);
#if EL__LANES4
                    else if (four) el__hermite_x_objectives4(&pr, x, n, b, qs, f);
#endif
                    else continue;
                    nwidth[width / 2]++;
                    for (int i = 0; i < n; i++) {
                        double g;
                        hstate hs;
                        el__hermite_x_objective(&pr, x[i], b, qs, &g);
                        if (isnan(g)) { ck_assert(isnan(f[i])); nfail++; continue; }
                        ck_assert_msg(memcmp(&f[i], &g, sizeof g) == 0, "x %.17g b %d: %.17g, %.17g", x[i], b, f[i], g);
                        nsame++;
                        if (!el__hermite_curvdata(&pr, x[i], b, &hs) && !el__hermite_shape_eval(&pr, qs, &hs))
                            hs.infl ? ninfl++ : nnon++;
                    }
                }
        }
    ck_assert(nsame > 100000 && nfail > 10000 && ninfl > 10000 && nnon > 10000);   /* every outcome covered */
    ck_assert(nwidth[0] > 10000 && nwidth[1] > 10000 && (!four || nwidth[2] > 10000));
}
END_TEST

/* el__hermite_x_classes (hermite_lanes.c: four lanes where the processor has AVX2, else
 * two; each width by itself) against el__hermite_x_class one by one, and
 * el__hermite_piece_classes against the plain piece class (the midpoint's class; where it
 * has no curve, CLASS_NONE if both quarter points have none, else CLASS_MIXED), on every
 * branch of the six families' problems (cases 1, 2 and 3): runs of 1 to 13 abscissae and
 * ascending split points 2 to 66, dense (spans down to 1e-12 B) and sparse (up to 2.2 B,
 * beyond the bound where no curve is): every class met, mixed pieces too. */
START_TEST(piece_classes_equal_the_plain_classes)
{
    unsigned long long st = 2718;
    long ncls[4] = {0, 0, 0, 0}, nmixed = 0, nwidth[3] = {0, 0, 0};
    const int four = EL__LANES4 && el__lanes4_available();
    if (!four) fprintf(stderr, "piece_classes_equal_the_plain_classes: four lanes not run (no AVX2 here, or built without)\n");
    for (int family = 0; family < 6; family++)
        for (int t = 0; t < 60; t++) {
            double p1[2], t1[2], sigma;
            draw(&st, family, p1, t1, &sigma);
            hprob pr = normalised_problem(p1, t1, sigma);
            if (t % 10 == 0) {   /* case 3: P2 = 0, V1 = 0 */
                pr.P1 = 1.0; pr.P2 = 0.0; pr.V1 = 0.0; pr.V2 = t % 20 ? 1.0 : -1.0;
                el__hermite_set_case(&pr);
            }
            if (el__hermite_kappa_bound(pr.sigma, pr.Lmin, &pr.B) || pr.B < 0.0) continue;
            for (int b = 0; b < 4; b++)
                for (int r = 0; r < 60; r++) {
                    double x[66];
                    int cls[66];
                    const double c = pr.B * test_uniform(&st, -1.1, 1.1), w = pr.B * pow(10.0, test_uniform(&st, -12.0, 0.34));
                    if (r % 2) {
                        const int n = 1 + (int)test_uniform(&st, 0.0, 13.0), width = r % 3 == 0 ? 0 : r % 3 == 1 ? 2 : 4;
                        for (int i = 0; i < n; i++) x[i] = c + w * test_uniform(&st, -1.0, 1.0);
                        if (width == 0) el__hermite_x_classes(&pr, x, n, b, cls);
                        else if (width == 2 && pr.hcase != 3) el__hermite_x_classes2(&pr, x, n, b, cls);
#if EL__LANES4
                        else if (width == 4 && four && pr.hcase != 3) el__hermite_x_classes4(&pr, x, n, b, cls);
#endif
                        else continue;
                        nwidth[width / 2]++;
                        for (int i = 0; i < n; i++) {
                            ck_assert_msg(cls[i] == el__hermite_x_class(&pr, x[i], b), "x %.17g b %d width %d: class %d, plain %d",
                                          x[i], b, width, cls[i], el__hermite_x_class(&pr, x[i], b));
                            ncls[cls[i]]++;
                        }
                    } else {
                        const int n = 2 + (int)test_uniform(&st, 0.0, 65.0);
                        for (int i = 0; i < n; i++) x[i] = c - w + 2.0 * w * i / (n - 1) * (1.0 + 0.4 * test_uniform(&st, -1.0, 1.0) / n);
                        el__hermite_piece_classes(&pr, b, x, n, cls);
                        for (int i = 0; i + 1 < n; i++) {
                            const double a = x[i], e = x[i + 1];
                            int plain = el__hermite_x_class(&pr, 0.5 * (a + e), b);
                            if (plain == CLASS_NONE) {
                                const int c1 = el__hermite_x_class(&pr, a + 0.25 * (e - a), b);
                                const int c3 = el__hermite_x_class(&pr, a + 0.75 * (e - a), b);
                                plain = c1 == CLASS_NONE && c3 == CLASS_NONE ? CLASS_NONE : CLASS_MIXED;
                            }
                            ck_assert_msg(cls[i] == plain, "piece [%.17g, %.17g] b %d: class %d, plain %d", a, e, b, cls[i], plain);
                            nmixed += plain == CLASS_MIXED;
                        }
                    }
                }
        }
    ck_assert(ncls[CLASS_NONE] > 10000 && ncls[CLASS_INFL] > 10000 && ncls[CLASS_NONINFL] > 10000 && nmixed > 0);
    ck_assert(nwidth[0] > 1000 && nwidth[1] > 1000 && (!four || nwidth[2] > 1000));
}
END_TEST

/* el__smooth_ends (the end-residual checks' evaluation, smooth.c) against
 * el_smooth_eval at s = 0 and s = length: the same status and, where EL_OK, the same bits,
 * over curves of every kind: |k| < 1, near and at 1, > 1 (theta's branch), k = 0 and
 * negative; u = q at the end (length 0, tiny sqrt(mu) length); mu from 1e-12 to 1e12;
 * phases past EL__PHASE_MAX and lengths below rounding (EL_EDOM); invalid curves
 * (EL_EINVAL). */
START_TEST(smooth_ends_equal_el_smooth_eval)
{
    unsigned long long st = 2718;
    long nok = 0, nedom = 0, ninval = 0;
    for (int t = 0; t < 200000; t++) {
        const int kind = t % 8;
        double sg;
        el_smooth_params p = test_smooth_of_kind(kind, &st, &sg);
        if (t % 97 == 0) p.q = t % 2 ? 0.0 : -0.0;
        const double Lu = test_uniform(&st, 0.0, 1.0);
        p.length = kind == 6 ? (Lu < 0.3 ? 0.0 : pow(10.0, test_uniform(&st, -20.0, -8.0)))
                             : pow(10.0, test_uniform(&st, -3.0, 2.0)) / sqrt(p.mu);
        if (t % 101 == 0) p.mu = t % 2 ? 0.0 : NAN;
        if (t % 103 == 0) p.length = -1.0;
        const double sv[2] = {0.0, p.length};
        double xy0[4], th0[2], xy1[4], th1[2];
        const int rc0 = el_smooth_eval(&p, 2, sv, xy0, th0, NULL);
        const int rc1 = el__smooth_ends(&p, xy1, th1);
        ck_assert_int_eq(rc0, rc1);
        if (rc0 == EL_EDOM) { nedom++; continue; }
        if (rc0) { ninval++; continue; }
        ck_assert(memcmp(xy0, xy1, sizeof xy0) == 0 && memcmp(th0, th1, sizeof th0) == 0);
        nok++;
    }
    ck_assert(nok > 100000 && nedom > 1000 && ninval > 3000);   /* every outcome covered */
}
END_TEST

int main(void)
{
    Suite *s = suite_create("hermite_tension");
    TCase *tc = tcase_create("hermite_tension");
    tcase_set_timeout(tc, 300);
    tcase_add_test(tc, parallel_tangents_give_symmetric_complete_sets);
    tcase_add_loop_test(tc, tension_solutions_contain_every_scanned_root, 0, 6);
    tcase_add_loop_test(tc, tension_roots_exact_and_equal_to_the_bisection, 0, 6);
    tcase_add_test(tc, steep_root_next_to_a_close_pair_is_kept);
    tcase_add_test(tc, x_objective_and_class_equal_the_plain_evaluation);
    tcase_add_test(tc, x_objectives_equal_the_scalar_objective);
    tcase_add_test(tc, piece_classes_equal_the_plain_classes);
    tcase_add_test(tc, smooth_ends_equal_el_smooth_eval);
    tcase_add_test(tc, kappa_bound_bounds_the_period_tightly);
    tcase_add_test(tc, kappa_bound_equals_the_plain_brent);
    tcase_add_test(tc, separatrix_crossings_exact_at_high_tension);
    tcase_add_test(tc, separatrix_chart_independent_of_the_guess);
    tcase_add_test(tc, separatrix_cache_gives_the_plain_states);
    tcase_add_test(tc, poly40_isolated_roots_match_plain_method);
    tcase_add_test(tc, poly40_roots_never_exceed_the_degree_at_subnormal_tension);
    suite_add_tcase(s, tc);
    return test_run_suite(s);
}
