/* Every fast path of the evaluation core against its plain counterpart (issue 12):
 * el_smooth_eval / el_smooth_jacobian on equally spaced, sorted scattered and
 * unsorted s (addition-theorem walks, jacobi_walk.c) against one-point calls, whose
 * n = 1 path is a fresh AGM + Carlson evaluation; el_discrete_* against the
 * vertex recursion rebuilt here from el_jacobi_eval at every u_n; the smooth
 * positions also against a quadrature of the angle. Over the whole range: sparse
 * samples over many periods, dense grids, k across 1 (+-1 exactly, 1 +- 1e-15,
 * 1 +- 1e-8), tiny and huge k, mu 1e-8 .. 1e8, lengths to 1e6, |x0| 1e6.
 *
 * Tolerance: the closed form's own conditioning. Positions are differences of
 * rounded Jacobi values divided by sqrt(mu), so both paths are exact to a multiple
 * of eps (1 + max|u|)(1 + |k|)/sqrt(mu) (about eps L on ordinary curves, where
 * sqrt(mu) L >> 1 + |q|); the walks add at most 32 addition steps of rounding (the
 * bound in jacobi_walk.c), so TOL_ROUNDINGS = 64 of them are allowed. */
#include "testutil.h"
#include "internal.h" /* WALK_MIN_POINTS: fewer samples get a fresh evaluation each */
#include <float.h>
#include <stdio.h>
#include <string.h>

enum { TOL_ROUNDINGS = 64, NMAX = 4000 };

/* ck_assert in forked mode reports every passing assertion through a pipe: the
 * inner loops (millions of comparisons) check with a plain if instead. */
#define require(cond, ...) do { if (!(cond)) ck_abort_msg(__VA_ARGS__); } while (0)

/* worst error / allowed error seen, and worst position error / length, for the report */
static double worst_ratio, worst_rel_length;

static void note(double err, double allowed, const char *what, const el_smooth_params *p, size_t i)
{
    const double r = err / allowed;
    if (r > worst_ratio) worst_ratio = r;
    require(err <= allowed, "%s at sample %zu: |fast - plain| = %.3g > %.3g (k=%.17g mu=%.17g q=%.17g L=%.17g)",
                  what, i, err, allowed, p->k, p->mu, p->q, p->length);
}

/* Largest |d/dk| of sn, cn, dn, D over the samples' u and u = q: the scale of the k column. */
static double dk_scale(const el_smooth_params *p, size_t n, const double *s)
{
    double g = 0.0;
    for (size_t i = 0; i <= n; i++) {
        el_jacobi v, d;
        const double u = i < n ? sqrt(p->mu) * s[i] + p->q : p->q;
        require(el_jacobi_eval(u, fabs(p->k), &v, NULL, &d) == EL_OK, "el_jacobi_eval failed");
        g = fmax(g, fabs(d.sn) + fabs(d.cn) + fabs(d.dn) + fabs(d.D));
    }
    return g;
}

/* Whether every element of a[count] is NaN (the EL_EDOM contract). */
static int all_nan(const double *a, size_t count)
{
    for (size_t i = 0; i < count; i++)
        if (!isnan(a[i])) return 0;
    return 1;
}

/* el_smooth_eval and el_smooth_jacobian on all n samples at once against n one-point calls. */
static void smooth_matches_pointwise(const el_smooth_params *p, size_t n, const double *s)
{
    static double xy[2 * NMAX], th[NMAX], ka[NMAX], jac[14 * NMAX], jxy[2 * NMAX];
    ck_assert(n <= NMAX);
    const double w = sqrt(p->mu), ka1 = 1.0 + fabs(p->k);
    double umax = fabs(p->q), smax = 0.0;
    for (size_t i = 0; i < n; i++) {
        umax = fmax(umax, fabs(w * s[i] + p->q));
        smax = fmax(smax, fabs(s[i]));
    }
    ck_assert_int_eq(el_smooth_eval(p, n, s, xy, th, ka), EL_OK);
    /* at |k| = 1 the k column grows like e^|u| / 4: past |u| ~ 710 it overflows, and
     * both paths say so */
    const int k_overflows = fabs(p->k) == 1.0 && umax > 700.0;
    const int jst = el_smooth_jacobian(p, n, s, jxy, jac);
    if (k_overflows) {
        ck_assert_int_eq(jst, EL_EDOM);
        ck_assert(all_nan(jac, 14 * n) && all_nan(jxy, 2 * n));
    } else {
        ck_assert_int_eq(jst, EL_OK);
    }
    const double e = TOL_ROUNDINGS * DBL_EPSILON, u1 = 1.0 + umax;
    const double pos = e * (u1 * ka1 / w + fabs(p->x0) + fabs(p->y0));
    /* per column: x0, y0 exact; phi as the positions; mu = (s T - X) / (2 mu) (the tangent
     * T to a phase error ~ |u| eps, times s ~ |u| / sqrt(mu)); k through
     * the k-derivatives; q and length through the tangent (header; error analysis in
     * jacobi_walk.c: every Jacobi value to TOL_ROUNDINGS roundings of its phase) */
    const double col[7] = {0.0, 0.0, pos, e * u1 * u1 * ka1 * ka1 / (w * w * w) + pos * ka1 / (w * w),
                           e * u1 * ka1 * ka1 * (1.0 + (k_overflows ? 0.0 : dk_scale(p, n, s))) / w,
                           e * u1 * ka1 * ka1 / w,
                           e * u1 * ka1 * ka1 * (1.0 + (p->length > 0.0 ? smax / p->length : 0.0))};
    for (size_t i = 0; i < n; i++) {
        double one[2], t1, k1, j1[14], jone[2];
        require(el_smooth_eval(p, 1, &s[i], one, &t1, &k1) == EL_OK, "one-point evaluation failed");
        for (int c = 0; c < 2; c++) {
            const double err = fabs(one[c] - xy[2 * i + c]);
            note(err, pos, "position", p, i);
            if (p->length > 0.0 && err / p->length > worst_rel_length) worst_rel_length = err / p->length;
        }
        note(fabs(t1 - th[i]), e * u1 * ka1, "theta", p, i);
        note(fabs(k1 - ka[i]), e * u1 * ka1 * fabs(p->k) * w, "kappa", p, i);
        if (k_overflows) continue;
        require(el_smooth_jacobian(p, 1, &s[i], jone, j1) == EL_OK, "one-point Jacobian failed");
        for (int c = 0; c < 2; c++) note(fabs(jone[c] - jxy[2 * i + c]), pos, "position beside the Jacobian", p, i);
        for (int r = 0; r < 14; r++) {
            static const char *names[7] = {"d/dx0", "d/dy0", "d/dphi", "d/dmu", "d/dk", "d/dq", "d/dlength"};
            note(fabs(j1[r] - jac[14 * i + r]), col[r % 7], names[r % 7], p, i);
        }
    }
}

/* FEET: the feet of noisy points on a curve passing close to itself, the order the
 * orthogonal fit evaluates (jacobi_walk.c's chunk sort and kept anchors): a grid
 * jittered by up to 4 steps, every other sample from a stretch half the length on */
typedef enum { GRID, SORTED, UNSORTED, FEET } layout;

static void fill_samples(layout how, size_t n, double length, unsigned long long *rng, double *s)
{
    for (size_t i = 0; i < n; i++)
        s[i] = how == GRID ? length * (double)i / (double)(n - 1)
             : how == FEET ? fmod(length * ((double)i + test_uniform(rng, -4.0, 4.0)) / (double)(n - 1) +
                                  (i % 2 ? 0.5 * length : 0.0), length)
             : test_uniform(rng, -0.05 * length, length);
    if (how == SORTED) /* insertion sort: n is small */
        for (size_t i = 1; i < n; i++) {
            const double x = s[i];
            size_t j = i;
            for (; j > 0 && s[j - 1] > x; j--) s[j] = s[j - 1];
            s[j] = x;
        }
}

/* k values where the walks are hardest, beside random ones */
static double special_k(int i, unsigned long long *rng)
{
    const double ks[] = {1.0, -1.0, 1.0 - 1e-15, 1.0 + 1e-15, -(1.0 - 1e-8), 1.0 + 1e-8, 1.0 - 1e-4,
                         1e-300, 0.0, -1e-8, 0.952, 30.0, -250.0};
    const int nk = sizeof ks / sizeof *ks;
    return i % 2 ? ks[(i / 2) % nk] : test_uniform(rng, -5.0, 5.0);
}

static void report(const char *what)
{
    printf("%s: worst |fast - plain| = %.3g of the allowed, %.3g of the length\n", what, worst_ratio,
           worst_rel_length);
    worst_ratio = worst_rel_length = 0.0;
}

/* count ordinary curves as the issue drew them (|k| <= 5, mu in [0.01, 100], length
 * <= 60; every other k from special_k), nmin..nmax samples laid out as how */
static void random_curves(const char *what, layout how, int count, size_t nmin, size_t nmax, unsigned long long seed)
{
    static double s[NMAX];
    unsigned long long rng = seed;
    for (int t = 0; t < count; t++) {
        el_smooth_params p = {test_uniform(&rng, -3, 3), test_uniform(&rng, -3, 3), test_uniform(&rng, -3, 3),
                              pow(10.0, test_uniform(&rng, -2, 2)), special_k(t, &rng), test_uniform(&rng, -5, 5),
                              test_uniform(&rng, 0.5, 60)};
        const size_t n = nmin + (size_t)test_uniform(&rng, 0, (double)(nmax - nmin + 1));
        fill_samples(how, n, p.length, &rng, s);
        smooth_matches_pointwise(&p, n, s);
    }
    report(what);
}

/* sparse: 2-80 samples over up to ~100 periods, steps in u of 0.01 .. 50 */
START_TEST(equally_spaced_matches_pointwise_sparse) { random_curves("grid, sparse", GRID, 600, 2, 80, 0x5ca77e1ULL); }
END_TEST
START_TEST(equally_spaced_matches_pointwise_dense) { random_curves("grid, dense", GRID, 40, 500, NMAX, 0xde75eULL); }
END_TEST
START_TEST(sorted_scattered_matches_pointwise_sparse) { random_curves("sorted, sparse", SORTED, 600, 2, 80, 0x50f7edULL); }
END_TEST
START_TEST(sorted_scattered_matches_pointwise_dense) { random_curves("sorted, dense", SORTED, 40, 500, NMAX, 0xd0dULL); }
END_TEST
START_TEST(unsorted_matches_pointwise) { random_curves("unsorted", UNSORTED, 200, 2, 600, 0xa11ULL); }
END_TEST
START_TEST(feet_order_matches_pointwise) { random_curves("feet order", FEET, 40, 500, NMAX, 0xfee7ULL); }
END_TEST

START_TEST(walks_match_pointwise_across_k_equal_1_at_every_step)
{
    /* k across the separatrix, step in u from 1e-3 to 20: the cases of issue 12 (NaN
     * with EL_OK at k = +-1, 45 L off) and the issue's own curve */
    static double s[400];
    const double ks[] = {1.0, -1.0, 1.0 - 1e-15, 1.0 + 1e-15, 1.0 - 1e-8, -(1.0 + 1e-8), 0.999, 1.001};
    const double zs[] = {1e-3, 0.05, 0.1, 0.3, 1.0, 2.5, 7.0, 20.0};
    for (size_t a = 0; a < sizeof ks / sizeof *ks; a++)
        for (size_t b = 0; b < sizeof zs / sizeof *zs; b++)
            for (int how = GRID; how <= SORTED; how++) {
                const size_t n = 40;
                el_smooth_params p = {0.2, -0.4, 0.5, 2.0, ks[a], -3.1, zs[b] * (n - 1) / sqrt(2.0)};
                unsigned long long rng = 17 + a + 100 * b;
                fill_samples((layout)how, n, p.length, &rng, s);
                smooth_matches_pointwise(&p, n, s);
            }
    el_smooth_params issue = {0, 0, 0, 6.9, 0.952, 0, 16.7};
    for (size_t i = 0; i < 31; i++) s[i] = issue.length * (double)i / 30.0;
    smooth_matches_pointwise(&issue, 31, s);
    report("k across 1");
}
END_TEST

/* el__jacobi_values (el__smooth_ends' evaluations: no am, no derivatives) against
 * el__jacobi_eval_mod: the same status and sn, cn, dn, D, E bits, for k from 0 to 1e6
 * across 1 (k < 1, k = 1, k > 1 and 1 -+ 1e-15), u sparse (random over +-1e4 / max(1, k))
 * and dense (a fine grid around the half periods), up to the phase limit. */
START_TEST(jacobi_values_equal_the_full_evaluation)
{
    unsigned long long st = 0x7ac0b1ULL;
    const double kfix[] = {0.0, 0.3, 0.999, 1.0 - 1e-15, 1.0, 1.0 + 1e-15, 1.001, 3.0, 1e6};
    long nok = 0, nedom = 0;
    for (int t = 0; t < 4000; t++) {
        const double k = t < 9 * 50 ? kfix[t / 50] : pow(10.0, test_uniform(&st, -3.0, 3.0));
        el__modulus mod;
        if (el__modulus_init(k, 0, &mod)) continue;
        const double reach = (t % 7 == 0 ? EL__PHASE_MAX * 1.01 : 1e4) / (k > 1.0 ? k : 1.0);
        for (int i = 0; i < 60; i++) {
            const double u = t % 2 ? test_uniform(&st, -reach, reach)
                                   : (i - 30) * (2.0 * mod.K / (k > 1.0 ? k : 1.0)) / 8.0 + 1e-3 * (t % 5);
            el_jacobi a, b;
            const int r0 = el__jacobi_eval_mod(&mod, u, &a, NULL, NULL), r1 = el__jacobi_values(&mod, u, &b);
            ck_assert_int_eq(r0, r1);
            if (r0) { nedom++; continue; }
            ck_assert(isnan(b.am));
            ck_assert_msg(memcmp(&a.sn, &b.sn, sizeof a.sn) == 0 && memcmp(&a.cn, &b.cn, sizeof a.cn) == 0 &&
                          memcmp(&a.dn, &b.dn, sizeof a.dn) == 0 && memcmp(&a.D, &b.D, sizeof a.D) == 0 &&
                          memcmp(&a.E, &b.E, sizeof a.E) == 0, "k %.17g u %.17g", k, u);
            nok++;
        }
    }
    ck_assert(nok > 100000 && nedom > 1000);   /* both outcomes covered */
}
END_TEST

/* el__smooth_point on a prepared curve (Newton's steps of the nearest-point search,
 * fit_nearest.c) against el_smooth_eval at the one s: the same status and, where EL_OK, the
 * same bits of xy, theta and kappa (each output may be NULL), NaN where both fail; s at
 * 0 (the base point), at the length, beyond both ends and far enough for EL_EDOM, not
 * finite (EL_EINVAL); curves of every kind: |k| < 1, near and at 1, > 1 (theta's branch),
 * 0 and negative, mu from 1e-12 to 1e12, |x0| to 1e6, phases past EL__PHASE_MAX; bad
 * parameters (the preparation's EL_EINVAL, el_smooth_eval's at every s). */
START_TEST(prepared_point_equals_el_smooth_eval)
{
    unsigned long long st = 0x9e1a7ULL;
    long nok = 0, nedom = 0, ninval = 0;
    for (int t = 0; t < 20000; t++) {
        const int kind = t % 8;
        double sg;
        el_smooth_params p = test_smooth_of_kind(kind, &st, &sg);
        p.length = pow(10.0, test_uniform(&st, -3.0, 2.0)) / sqrt(p.mu);
        if (t % 101 == 0) p.mu = t % 2 ? 0.0 : NAN;
        el__smooth_curve c;
        const int prep = el__smooth_prepare(&p, &c);
        for (int i = 0; i < 12; i++) {
            double s = i == 0 ? 0.0 : i == 1 ? p.length : i == 2 ? NAN : i == 3 ? INFINITY
                     : i == 4 ? sg * 1e20 * (p.length + 1.0) : p.length * test_uniform(&st, -1.0, 2.0);
            double xy0[2], th0, ka0, xy1[2], th1, ka1;
            const int mask = i % 8;     /* which outputs: xy, theta, kappa */
            const int rc0 = el_smooth_eval(&p, 1, &s, mask & 1 ? NULL : xy0, mask & 2 ? NULL : &th0, mask & 4 ? NULL : &ka0);
            if (prep) {
                require(rc0 == prep || (prep == EL_EDOM && rc0 == EL_EINVAL && !isfinite(s)),
                        "prepared %d, evaluated %d (k %.17g q %.17g)", prep, rc0, p.k, p.q);
                ninval += prep == EL_EINVAL;
                nedom += prep == EL_EDOM;
                continue;
            }
            const int rc1 = el__smooth_point(&c, s, mask & 1 ? NULL : xy1, mask & 2 ? NULL : &th1, mask & 4 ? NULL : &ka1);
            require(rc0 == rc1, "status %d against %d (k %.17g q %.17g s %.17g)", rc1, rc0, p.k, p.q, s);
            if (rc0 == EL_EINVAL) { ninval++; continue; }
            if (rc0 == EL_EDOM) {
                require((mask & 1 || (isnan(xy1[0]) && isnan(xy1[1]))) && (mask & 2 || isnan(th1)) &&
                        (mask & 4 || isnan(ka1)), "EL_EDOM without NaN outputs");
                nedom++;
                continue;
            }
            require((mask & 1 || memcmp(xy0, xy1, sizeof xy0) == 0) && (mask & 2 || memcmp(&th0, &th1, sizeof th0) == 0) &&
                    (mask & 4 || memcmp(&ka0, &ka1, sizeof ka0) == 0),
                    "different bits (k %.17g q %.17g mu %.17g s %.17g)", p.k, p.q, p.mu, s);
            nok++;
        }
    }
    ck_assert(nok > 100000 && nedom > 10000 && ninval > 20000);   /* every outcome covered */
}
END_TEST

START_TEST(walks_match_pointwise_at_extreme_scales)
{
    /* valid but extreme: mu 1e-8 .. 1e8, lengths to 1e6, |x0| = 1e6, k from 1e-300 to 1e5 */
    static double s[2000];
    const double mus[] = {1e-8, 1e-3, 1.0, 1e4, 1e8};
    const double lengths[] = {1e-3, 1.0, 1e3, 1e6};
    const double ks[] = {1e-300, 0.7, 1.0, -3.0, 1e5};
    const size_t ns[] = {2, 9, 300, 2000};
    unsigned long long rng = 0xe7e3eULL;
    int run = 0;
    for (size_t a = 0; a < sizeof mus / sizeof *mus; a++)
        for (size_t b = 0; b < sizeof lengths / sizeof *lengths; b++)
            for (size_t c = 0; c < sizeof ks / sizeof *ks; c++) {
                const size_t n = ns[(a + b + c) % 4];
                el_smooth_params p = {1e6, -1e6, 0.3, mus[a], ks[c], 0.4, lengths[b]};
                if (fabs(p.k) * (sqrt(p.mu) * p.length + 1.0) > 1e14) continue; /* no digits: EL_EDOM (test_core) */
                fill_samples((layout)(run++ % 3), n, p.length, &rng, s);
                smooth_matches_pointwise(&p, n, s);
            }
    report("extreme scales");
}
END_TEST

/* s = 0 in a few-point call (the end-residual checks: s = {0, L}) takes the values
 * of the base point u = q instead of evaluating there again (smooth.c): the start,
 * its tangent and curvature must be those of el_jacobi_eval at q, sparse and with
 * other samples before and after it, k across 1 and beyond. */
START_TEST(start_sample_takes_the_base_point_values)
{
    unsigned long long rng = 0x5ba5eULL;
    for (int t = 0; t < 600; t++) {
        el_smooth_params p = {test_uniform(&rng, -3, 3), test_uniform(&rng, -3, 3), test_uniform(&rng, -3, 3),
                              pow(10.0, test_uniform(&rng, -4, 4)), special_k(t, &rng), test_uniform(&rng, -5, 5),
                              test_uniform(&rng, 0.5, 60)};
        const size_t n = 1 + (size_t)(t % (WALK_MIN_POINTS - 1)), i0 = (size_t)t % n;
        double s[WALK_MIN_POINTS], xy[2 * WALK_MIN_POINTS], th[WALK_MIN_POINTS], ka[WALK_MIN_POINTS];
        for (size_t i = 0; i < n; i++) s[i] = p.length * ((double)i - (double)i0) / (double)n;
        require(el_smooth_eval(&p, n, s, xy, th, ka) == EL_OK, "evaluation failed");
        el_jacobi v;
        ck_assert_int_eq(el_jacobi_eval(p.q, fabs(p.k), &v, NULL, NULL), EL_OK);
        const double w = sqrt(p.mu), k = p.k, e = 4.0 * DBL_EPSILON;
        require(xy[2 * i0] == p.x0 && xy[2 * i0 + 1] == p.y0, "start (%.17g, %.17g) is not (x0, y0)",
                xy[2 * i0], xy[2 * i0 + 1]);
        require(fabs(ka[i0] - 2.0 * k * w * v.cn) <= e * fabs(k) * w, "kappa(0) = %.17g, not %.17g", ka[i0],
                2.0 * k * w * v.cn);
        /* the tangent in the frame rotated by phi: (1 - 2 k^2 sn^2, 2 k sn dn) */
        const double c = 1.0 - 2.0 * k * k * v.sn * v.sn, sn2 = 2.0 * k * v.sn * v.dn;
        const double et = e * (1.0 + fabs(p.phi) + fabs(th[i0]) + k * k);   /* theta - phi rounded */
        require(fabs(cos(th[i0] - p.phi) - c) <= et && fabs(sin(th[i0] - p.phi) - sn2) <= et,
                "theta(0) = %.17g off the tangent at q (k = %.17g)", th[i0], k);
    }
}
END_TEST

/* Gauss-Legendre nodes and weights on [-1, 1], 8 points */
static const double GL_X[8] = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
                               0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
static const double GL_W[8] = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
                               0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

/* Compensated running sum (Neumaier): the quadrature adds ~3e4 terms. */
typedef struct { double sum, carry; } ksum;
static void ksum_add(ksum *a, double v)
{
    const double t = a->sum + v;
    a->carry += fabs(a->sum) >= fabs(v) ? (a->sum - t) + v : (v - t) + a->sum;
    a->sum = t;
}

/* int_a^b (cos theta, sin theta) ds by 8-point Gauss-Legendre, theta from one-point calls */
static void gauss_panel(const el_smooth_params *p, double a, double b, ksum *x, ksum *y)
{
    for (int g = 0; g < 8; g++) {
        double s = 0.5 * (a + b) + 0.5 * (b - a) * GL_X[g], th;
        require(el_smooth_eval(p, 1, &s, NULL, &th, NULL) == EL_OK, "one-point evaluation failed");
        ksum_add(x, 0.5 * (b - a) * GL_W[g] * cos(th));
        ksum_add(y, 0.5 * (b - a) * GL_W[g] * sin(th));
    }
}

START_TEST(smooth_positions_match_quadrature_of_angle)
{
    /* gamma(s) - gamma(0) = int_0^s (cos theta, sin theta): theta from one-point sn and dn,
     * the positions from D and cn, so this checks the closed form itself; the grid,
     * sorted scattered and unsorted walks against the same integrals */
    const double cases[][3] = {{0.8, 1.0, 50.0}, {0.952, 6.9, 16.7}, {1.0, 2.0, 20.0}, {-2.5, 0.3, 30.0},
                               {1.0 - 1e-8, 1.0, 25.0}, {0.3, 100.0, 4.0}};
    enum { PANELS = 4000, N = 33 };
    static double cx[PANELS + 1], cy[PANELS + 1];
    double worst = 0.0;
    for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
        el_smooth_params p = {0.5, -0.25, 0.4, cases[c][1], cases[c][0], 0.37, cases[c][2]};
        const double hp = p.length / PANELS, w = sqrt(p.mu);
        ksum x = {p.x0, 0}, y = {p.y0, 0};
        cx[0] = p.x0; cy[0] = p.y0;
        for (int j = 0; j < PANELS; j++) {
            gauss_panel(&p, hp * j, hp * (j + 1), &x, &y);
            cx[j + 1] = x.sum + x.carry; cy[j + 1] = y.sum + y.carry;
        }
        unsigned long long rng = 99 + c;
        for (int how = GRID; how <= UNSORTED; how++) {
            double s[N], xy[2 * N];
            fill_samples((layout)how, N, p.length, &rng, s);
            for (int i = 0; i < N; i++) s[i] = fmax(s[i], 0.0);
            ck_assert_int_eq(el_smooth_eval(&p, N, s, xy, NULL, NULL), EL_OK);
            const double tol = TOL_ROUNDINGS * DBL_EPSILON * ((1.0 + fabs(p.q) + w * p.length) * (1.0 + fabs(p.k)) / w + p.length);
            for (int i = 0; i < N; i++) {
                const int j = (int)fmin(floor(s[i] / hp), PANELS - 1);
                ksum rx = {cx[j], 0}, ry = {cy[j], 0};
                gauss_panel(&p, hp * j, s[i], &rx, &ry);
                const double err = fmax(fabs(xy[2 * i] - rx.sum - rx.carry), fabs(xy[2 * i + 1] - ry.sum - ry.carry));
                worst = fmax(worst, err / p.length);
                require(err <= tol, "case %zu layout %d s = %.17g: %.3g off the quadrature (allowed %.3g)", c, how,
                              s[i], err, tol);
            }
        }
    }
    printf("positions against quadrature of the angle: worst %.3g of the length\n", worst);
}
END_TEST

/* ------------------------------------------------------------ discrete */

/* The vertex recursion rebuilt from one-point Jacobi values (and k-derivatives) at
 * every u_n = z n + q: the plain counterpart of el_discrete_eval / _jacobian / _curvature. */
static void discrete_reference(const el_discrete_params *p, size_t n, double *xy, double *jac, double *kappa)
{
    const double k = p->k, h = p->h, c = cos(p->phi), s = sin(p->phi);
    double x = p->x0, y = p->y0, dz[2] = {0, 0}, dq[2] = {0, 0}, dk[2] = {0, 0};
    el_jacobi a, ak, b, bk, before, zv;
    require(el_jacobi_eval(p->q, k, &a, NULL, &ak) == EL_OK, "el_jacobi_eval failed");
    require(el_jacobi_eval(p->z, k, &zv, NULL, NULL) == EL_OK, "el_jacobi_eval failed");
    before = a;
    for (size_t i = 0; i < n; i++) {
        double *rx = jac + 14 * i, *ry = rx + 7;
        rx[0] = 1; rx[1] = 0; rx[2] = (x - p->x0) / h; rx[3] = -(y - p->y0);
        ry[0] = 0; ry[1] = 1; ry[2] = (y - p->y0) / h; ry[3] = x - p->x0;
        rx[4] = dz[0]; rx[5] = dq[0]; rx[6] = dk[0];
        ry[4] = dz[1]; ry[5] = dq[1]; ry[6] = dk[1];
        xy[2 * i] = x; xy[2 * i + 1] = y;
        if (i + 1 == n) break;
        require(el_jacobi_eval(p->q + p->z * (double)(i + 1), k, &b, NULL, &bk) == EL_OK, "el_jacobi_eval failed");
        if (i >= 1 && fabs(zv.dn) >= DBL_MIN) /* interior vertex i: tan(K_i/2) = k sn(z) cn(u_i) / dn(z) */
            kappa[i - 1] = 2.0 / h * (k * zv.sn / zv.dn * a.cn);
        else if (i >= 1) { /* K_i = a_{i+1} - a_{i-1} (discrete.c where dn(z) underflows) */
            const double sinK = k * (b.sn * before.dn - b.dn * before.sn), cosK = b.dn * before.dn + k * k * b.sn * before.sn;
            kappa[i - 1] = 2.0 / h * sinK / (1.0 + cosK);
        }
        const double tx = a.dn * b.dn - k * k * a.sn * b.sn, ty = k * (a.sn * b.dn + a.dn * b.sn);
        const double Tx = c * tx - s * ty, Ty = s * tx + c * ty;
        /* d a/du = k cn, d a/dk = dn (sn + k sn_k) - k sn dn_k */
        const double az = k * ((double)i * a.cn + (double)(i + 1) * b.cn), aq = k * (a.cn + b.cn);
        const double akk = a.dn * (a.sn + k * ak.sn) - k * a.sn * ak.dn + b.dn * (b.sn + k * bk.sn) - k * b.sn * bk.dn;
        x += h * Tx; y += h * Ty;
        dz[0] -= h * Ty * az; dz[1] += h * Tx * az;
        dq[0] -= h * Ty * aq; dq[1] += h * Tx * aq;
        dk[0] -= h * Ty * akk; dk[1] += h * Tx * akk;
        before = a;
        a = b; ak = bk;
    }
}

static void discrete_matches_pointwise(const el_discrete_params *p, size_t n)
{
    static double xy[2 * NMAX], jxy[2 * NMAX], jac[14 * NMAX], ka[NMAX];
    static double rxy[2 * NMAX], rjac[14 * NMAX], rka[NMAX];
    ck_assert(n <= NMAX && n >= 3);
    ck_assert_int_eq(el_discrete_eval(p, n, xy), EL_OK);
    ck_assert_int_eq(el_discrete_curvature(p, n, ka), EL_OK);
    if (p->k == 1.0 && fmax(fabs(p->q), fabs(p->q + p->z * (double)(n - 1))) > 700.0) {
        /* the k column overflows (d cn/dk ~ e^|u| / 4 at k = 1) */
        ck_assert_int_eq(el_discrete_jacobian(p, n, jxy, jac), EL_EDOM);
        ck_assert(all_nan(jac, 14 * n) && all_nan(jxy, 2 * n));
        return;
    }
    ck_assert_int_eq(el_discrete_jacobian(p, n, jxy, jac), EL_OK);
    discrete_reference(p, n, rxy, rjac, rka);
    /* each vertex sums i steps of h (cos, sin) of angles made of Jacobi values exact to
     * TOL_ROUNDINGS roundings: positions to that times h n (1 + k^2); the Jacobian's
     * columns are sums of such steps times the u- or k-derivatives of the angles */
    const double e = TOL_ROUNDINGS * DBL_EPSILON, k1 = 1.0 + p->k * p->k, umax = fmax(fabs(p->q), fabs(p->q + p->z * n));
    const double pos = e * (k1 * p->h * n * (1.0 + umax) + fabs(p->x0) + fabs(p->y0));
    double cmax[7] = {0};
    for (size_t i = 0; i < 14 * n; i++) cmax[i % 7] = fmax(cmax[i % 7], fabs(rjac[i]));
    for (size_t i = 0; i < 2 * n; i++) {
        require(fabs(xy[i] - rxy[i]) <= pos && fabs(jxy[i] - rxy[i]) <= pos,
                      "vertex coordinate %zu: %.3g off (z=%g q=%g k=%.17g)", i, fabs(xy[i] - rxy[i]), p->z, p->q, p->k);
        worst_ratio = fmax(worst_ratio, fabs(xy[i] - rxy[i]) / pos);
    }
    for (size_t i = 0; i < 14 * n; i++) {
        const double tol = e * (1.0 + umax) * k1 * (cmax[i % 7] + pos);
        require(fabs(jac[i] - rjac[i]) <= tol, "Jacobian entry %zu (column %zu): %.17g vs %.17g (z=%g k=%.17g)", i,
                      i % 7, jac[i], rjac[i], p->z, p->k);
        worst_ratio = fmax(worst_ratio, fabs(jac[i] - rjac[i]) / tol);
    }
    for (size_t i = 0; i + 2 < n; i++) {
        const double tol = e * (1.0 + umax) * k1 * (fabs(rka[i]) + 1.0 / p->h) * (1.0 + fabs(rka[i]) * p->h);
        require(fabs(ka[i] - rka[i]) <= tol, "curvature %zu: %.17g vs %.17g (z=%g k=%.17g)", i, ka[i], rka[i], p->z, p->k);
    }
}

START_TEST(discrete_walk_matches_pointwise_dense_and_sparse)
{
    /* z from 1e-3 (dense) to 40 (a vertex every few periods), k across 1 */
    unsigned long long rng = 0xd15c7eULL;
    const double ks[] = {0.0, 1e-300, 0.5, 0.952, 1.0 - 1e-15, 1.0, 1.0 + 1e-15, 1.0 + 1e-8, 2.0, 40.0};
    for (int t = 0; t < 400; t++) {
        const double k = t % 2 ? ks[(t / 2) % 10] : test_uniform(&rng, 0.0, 5.0);
        const double z = (t % 3 == 0 ? 1.0 : -1.0) * pow(10.0, test_uniform(&rng, -3.0, 1.6));
        el_discrete_params p = {test_uniform(&rng, -2, 2), test_uniform(&rng, -2, 2), pow(10.0, test_uniform(&rng, -2, 1)),
                                test_uniform(&rng, -3, 3), z, test_uniform(&rng, -4, 4), k};
        const size_t n = t % 10 == 0 ? 3000 : 3 + (size_t)test_uniform(&rng, 0, 200);
        discrete_matches_pointwise(&p, n);
    }
    printf("discrete: worst |fast - plain| = %.3g of the allowed\n", worst_ratio);
    worst_ratio = 0.0;
}
END_TEST

int main(void)
{
    Suite *s = suite_create("fastpath");
    TCase *sm = tcase_create("smooth"), *d = tcase_create("discrete");
    tcase_set_timeout(sm, 300);
    tcase_set_timeout(d, 300);
    tcase_add_test(sm, equally_spaced_matches_pointwise_sparse);
    tcase_add_test(sm, equally_spaced_matches_pointwise_dense);
    tcase_add_test(sm, sorted_scattered_matches_pointwise_sparse);
    tcase_add_test(sm, sorted_scattered_matches_pointwise_dense);
    tcase_add_test(sm, unsorted_matches_pointwise);
    tcase_add_test(sm, feet_order_matches_pointwise);
    tcase_add_test(sm, walks_match_pointwise_across_k_equal_1_at_every_step);
    tcase_add_test(sm, walks_match_pointwise_at_extreme_scales);
    tcase_add_test(sm, jacobi_values_equal_the_full_evaluation);
    tcase_add_test(sm, prepared_point_equals_el_smooth_eval);
    tcase_add_test(sm, smooth_positions_match_quadrature_of_angle);
    tcase_add_test(sm, start_sample_takes_the_base_point_values);
    tcase_add_test(d, discrete_walk_matches_pointwise_dense_and_sparse);
    suite_add_tcase(s, sm);
    suite_add_tcase(s, d);
    return test_run_suite(s);
}
