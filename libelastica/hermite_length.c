/*
 * Hermite interpolation for a given length Lt (Euler's strip clamped at both ends).
 *
 * For a given tension the solutions are the zeros of the objective f(x; sigma) of
 * hermite_tension.c on each branch; as sigma varies they form curves C, the zero
 * set of one function of two unknowns (x, sigma), along which the length L varies.
 * The length-mode solutions are the points of C with L = Lt. C is found on a few
 * sigma lines (every tension solution there: the seeds) and followed from each seed
 * in both directions by pseudo-arclength continuation with the analytic gradient of
 * f and L (hermite_objective.c): a predictor along the tangent of C, a corrector of
 * Newton steps along the gradient of f. Where L - Lt changes sign between two points
 * of the trace, Newton on (f, L - Lt) gives the solution. A trace ends outside the
 * sigma range of the solutions (sigma_range), where C ends (a state without a curve,
 * a singular one), where it closes on itself or where it meets a seed another trace
 * passed (the rest was traced); a seed a trace passes is not traced again. The
 * coordinates are asinh of the chart's (hermite_objective.c): (x, sigma), in case 1
 * (kappa1, sigma) where the two branches of (17) meet (the x chart folds there), and
 * in case 3 (kappa0, kappa0'); near the separatrix one of them is replaced by
 * ln(|F| - sigma). Where a step fails in its chart at any length, the trace goes on in
 * another chart of the same point.
 *
 * What this misses: a piece of C that crosses no seed line (a closed curve, or one
 * whose both ends are singular states, between two lines), a solution where C
 * touches L = Lt without crossing it, and near the separatrix the stretch of C a step
 * passes over onto a branch close beside it whose length the step's test of L admits;
 * and the crossings next to a singular state where C branches: between parallel tangents
 * the whole-period curves leave the straight one (kappa = 0) at sigma |P|^2 = -8 pi^2, a
 * pitchfork, and a trace toward it ends before L = Lt when Lt is near 1 (1 + 5e-8: none
 * found); hermite.c adds them in closed form (whole_period_solutions).
 *
 * Where the work goes (issue 16 target 1, callgrind on bench_hermite's 1000 length problems,
 * 962 M instructions against 75 M by tension): traces 535 M, seed lines 275 M, the solutions'
 * polish 104 M. Neither half alone is within 4 x: without the lines 8.5 x, without the traces
 * 5 x (at L ~ 2 |p1 - p0|, the median: traces 7.9 x, lines 3.5 x). The traces: 7.7 per problem,
 * 54 accepted steps, 234 evaluations (2.3 k instructions each); 25 % of their steps' evaluations
 * in traces that find no solution and 26 % after a trace's last solution (the stretches that
 * only mark seeds visited). Their steps are bounded by C's bend (tangent and corrector tests),
 * not by the tests of L: at most 434 of 11 400 refused steps were refused by L (LRATIO, LDEF),
 * so a bound proving no L = Lt on a stretch would save < 1 %; hmax 3 or a growth of 2 do not
 * help. Along C, L has an extremum away from a fold of sigma in 54 of 45 926 consecutive step
 * pairs (sigma folds 1123). A 1-D reduction, {L = Lt} a graph sigma(x) in the x chart, fails:
 * dL/dsigma at fixed x takes both signs on C (34 k > 0, 23 k < 0 of its evaluations with
 * |f| < 1e-6). Fewer lines lose solutions: two (bottom and top) 11 of the bench's 3494 (-28 %
 * instructions); five without line 3 none of the bench's (-15 %) but make length-recovers misses
 * 10, 12, 7 (six lines: 0, 2, 0) and make hermite-sets' length sets lose 1; grid 4 misses 1, 4, 1.
 * The trace's corrector on f alone (secant Newton along x at the predictor's tension by
 * el__hermite_x_objective, ~740 instructions against ~1600 for a point with its gradient, then
 * one full evaluation where it stops) does not pay either: +0.7 % instructions (+0.5 % with
 * Carlson's qs 0.3), the same 3494 solutions; the steps are long (the slope at the step's start is
 * off by C's bend), so the secant takes ~2.5 evaluations of f where Newton with the gradient takes
 * ~1.4 more points. The constants are at their optimum within +-0.5 % (first 300 problems): the
 * trace's first step 0.2 / 0.5 / 0.8 (0.3 kept) +0.1 / +0.7 / +2.5 %, the separatrix chart
 * entered below 3e-4 / 3e-3 of |F| + sigma (1e-3 kept) +0.4 / +0.4 %, K1 past a fold ratio of
 * 2 / 8 (4 kept) -0.2 / +0.3 %.
 * The separatrix chart's Newton (sep_solve, hermite_objective.c; 78 k calls, 46 k from the traces,
 * 32 k from the seed lines' tension solves) evaluates 244 k points of ~283 instructions (69 M)
 * plus ~15 M in its loop: at most 9 % of the length mode, ~4 % if every call took one step. The
 * expensive calls are the predictor's (13 k with |dU| >= 0.05, 4.7 points each; the corrector's
 * 2.6): the target |F| - sigma lies orders below the step's change of the crossing w*, so the
 * start misses it by 1e2 .. 1e5 times the target. Not kept: a stop at 1e-10 of the target before
 * the rounding would save 8 k of the 225 k points (0.25 %, counted on the calls' iterates); the
 * start linear in e^y (exact where |F| - sigma is linear in w) instead of in y 961.9 -> 966.9 M
 * (+0.5 %), with the other coordinate through sinh 965.9 M; the predictor's start from w* = w -
 * (|F| - sigma) / d_w continued by the step's cubic Hermite interpolant 978.2 M (+1.7 %), the same
 * 3494 solutions each; the trace's points taken where Newton reaches 5 % of the target (their y
 * moved to the state's) find 96 fewer solutions, with 1e-3 on the corrector's points too 180
 * fewer. Of the traces' 234.5 k evaluations (stretches between events: solutions, seeds passed)
 * 31.7 % lead to a solution, 33.7 % to a seed with L within 20 % of Lt on the way, 16.7 % from a
 * seed to one on a neighbouring line with L over 20 % off (one side) all the way (2247 stretches,
 * 17 evaluations each), 3.5 % so back to the seed's own line, 6.7 % are tails so after the last
 * seed: a certificate joining neighbouring lines' seeds without tracing saves at most ~20 % of the
 * traces, ~11 % in all. Order alone is no such certificate: 1324 of those 2247 stretches join
 * lines with as many seeds, and 153 of them (3.4 k evaluations) end at a seed of another rank in
 * kappa0 than their start.
 */
#include "hermite_length_internal.h"
#include <stdlib.h>
#include <string.h>

/* sigma range of length-mode solutions (normalised |P| = 1, length Lt > 1):
 * sigma >= -(C0/Lt)^2 (Theorem 9 bound, sigma <= 0 case). Above, for k <= 1 (psi = theta - phi,
 * sin(psi/2) = k sn u, cos(psi/2) = dn u, u = sqrt(mu) s + q, seed 000 (4.2)): the tangent's
 * component along e_phi is cos psi = 2 dn^2 - 1, so L + <P, e_phi> = 2 J / sqrt(mu),
 * J = int dn^2 du over the curve's u-interval [u0, u1], and as <P, e_phi> >= -|P| = -1,
 * sqrt(mu) <= 2 J / (L - 1) and sigma = 2 mu (2k^2 - 1) <= 8 (2k^2 - 1) J^2 / (L - 1)^2.
 * The curve spans at most one curvature period (u1 - u0 <= 4K, seed 004), over which
 * int dn^2 du = 4 E(k); the rest of the period, from u1 on to u0 + 4K, runs from psi1 back to
 * psi0 (dpsi/du = 2k cn), so J <= 4 E(k) - |E(am u1) - E(am u0)| (E(am u, k) = int_0^u dn^2, the
 * incomplete integral of the second kind at sin(am u) = sin(psi/2) / k). The ends' tangents
 * fix psi1 - psi0 modulo 2 pi: psi1 = psi0 + delta wrapped into (-pi, pi], delta the turn from
 * t0 to t1; phi, so psi0, is free. Hence sigma (L - 1)^2 <= B(d), d = |delta| in [0, pi]
 * (the mirror image turns -delta):
 *   B(d) = sup over k in (1/sqrt 2, 1], psi0 of 8 (2k^2 - 1) (4 E(k) - |E(am u1) - E(am u0)|)^2,
 * at d = 0 128 max E^2 (2k^2 - 1) = HLEN_SIGMA_E2 (k^2 = 0.97136: the two-loop solutions near
 * the separatrix, whose ends' tangents are parallel); from d = 0.39 on the sup is the k -> 1
 * limit, E(am u) -> sin(psi/2), 8 (3 + cos(d/2))^2 (psi0 = pi - d: an end at the middle of a
 * loop, the other on an arm), 72 at d = pi. For k > 1 (modulus m = 1/k, nu = k^2 mu, psi/2 =
 * am(k u; m) monotone, one period a turn of 2 pi) likewise sigma (L - 1)^2 <= 8 (2 - m^2) J^2 with
 * J = int cos^2 a / sqrt(1 - m^2 sin^2 a) da over a window of psi/2 at most pi wide: J <= 2 (E(m) -
 * m'^2 K(m)) / m^2, so at most 8 * 2 * (pi/2)^2 = 39.5 < 72 for every d. sigma_bound_d2 holds B at
 * the left end of each of 32 bins of d (B decreases with d: the bin's largest), rounded up by
 * 1e-3 .. 2e-3 (the sup by a grid over (k^2, psi0) refined by Nelder-Mead, scipy's ellipe and
 * ellipeinc; test_hermite_length.c recomputes it with GSL and checks it against 40 000 tension-mode
 * solutions, which reach 0.98 of it in every quarter of [0, pi]: the bound is tight). Bin 0 is
 * HLEN_SIGMA_E2 itself (130.13, its sup 130.1275): near-parallel tangents keep their top line to
 * the ulp, as make hermite-sets' set 7 (tangents along the chord) loses one-loop solutions when
 * that line moves by one ulp (a trace's luck, not the bound's). The bound holds at every point of
 * C with L >= Lt, so a trace above it has L < Lt. Against the former d-free bound (HLEN_SIGMA_E2
 * for every d) it is 44 % lower at d = pi: the top seed line and the traces' end come down with
 * it (4.5 % fewer instructions on the bench's problems, seeds below). */
static const double sigma_bound_d2[32] = {
    HLEN_SIGMA_E2, 129.136, 128.219, 127.352, 126.775, 126.091, 125.261, 124.288, 123.176, 121.931, 120.556,
    119.058, 117.443, 115.717, 113.886, 111.959, 109.943, 107.844, 105.672, 103.434, 101.138, 98.793,
    96.406, 93.987, 91.542, 89.080, 86.609, 84.137, 81.670, 79.217, 76.783, 74.376};

double el__hlen_sigma_bound(const hprob *pr)
{
    const double d = fabs(atan2(-pr->V1, pr->V2));   /* the turn from t0 = (0, 1) to V */
    int i = (int)(d * (32.0 / M_PI));
    if (!(i >= 0)) i = 0;
    if (i > 31) i = 31;
    return sigma_bound_d2[i];
}

static void sigma_range(const hprob *pr, double Lt, double *lo, double *hi)
{
    const double c = C0_PERIOD / Lt, e = Lt - 1.0;
    *lo = -c * c;
    *hi = el__hlen_sigma_bound(pr) / (e * e);
}

/* The tension the search reaches (header: the same as tension mode's range; beyond it
 * the solutions lie closer to the separatrix than the separatrix chart reaches). */
#define SIGMA_MAX ((double)EL_HERMITE_SIGMA_D2_MAX)
/* Traces follow C up to the bound (sigma_range) or SIGMA_TRACE_MAX: a solution just
 * beyond SIGMA_MAX on a curve that leaves the range with L still above Lt (at
 * L / |p1 - p0| = 1.033, sigma |p1 - p0|^2 = 1.07e5; test_hermite_length.c) is found
 * whatever the step that passes SIGMA_MAX. Past SIGMA_TRACE_MAX a trace goes on while
 * L >= Lt, up to the bound, so the crossing of such a curve is found whatever the step
 * that passes SIGMA_TRACE_MAX too: near-straight ends (Lt / |p1 - p0| < 1.0114, where the
 * bound lies above 1e6) have 3-piece solutions at sigma |p1 - p0|^2 1e6..4e6 that were
 * found or not as the last step fell (347 and 1112 more in the solution-set dumps of
 * 10 x 1000 and 10 x 3000 random problems, none lost; the length mode's instructions on
 * such problems +8 %, on the bench's, whose bound lies below 1e6, unchanged). */
#define SIGMA_TRACE_MAX 1e6
/* the work limit: objective evaluations of the tracing (the bench problems need at
 * most ~5000; beyond it the solutions found so far are returned with EL_EMAXITER) */
#define MAX_EVALS EL__HERMITE_MAX_EVALS

/* The seed lines: every tension solution on nl lines over the sigma range in t = asinh(sigma)
 * (hermite_tension.c), ns samples each: the top line at the top of the range (the turn-dependent
 * bound B(d) / (Lt - 1)^2, sigma_range), the others at the fractions 1 - (1 - j / (nl - 1))^T->line_power
 * of [tlo, thi_lines], thi_lines the d-free bound's HLEN_SIGMA_E2 / (Lt - 1)^2 (where every line
 * lay before B(d): the lines below the top keep their places, which are tuned for where C's
 * pieces cross them; with them spread over the lower range too, make length-recovers' seed 7
 * lost one of 46 115 (L 1.078 |p1 - p0|, sigma |p1 - p0|^2 11.1) and gained two, and 3.7 % fewer
 * instructions on the bench's problems against 4.5 % this way). The top line meets both arms of the
 * curves that carry the pairs born near the top (two loops near the separatrix, sigma (Lt - 1)^2
 * near 128; on the bench's problems its traces alone find 605 of the 3494 solutions); below
 * it the lines lie a little closer towards the bottom, where a tension solve is cheap (without
 * the line below the top, or at power 0.5, make length-recovers loses solutions). The lines'
 * separatrix pieces (separatrix_end) are searched only above LINE_SEP_SIGMA (the x chart's
 * roots alone below, as the tension mode's below SEP_SIGMA = 100): between 100 and 300, where
 * the median problems' top line lies, they cost more than the rest of the line and their seeds
 * lie on pieces of C other seeds' traces meet (the same solutions in make hermite-sets, of
 * 12 000 random problems with L / |p1 - p0| in [1.4, 2.6] and of make length-recovers' 138 304;
 * at 1000 the sets lost one; el__hlen_solve_line_pieces). The lines cost 346k instructions per
 * bench problem (4.2 tension solves; 404k with the pieces down to 100), the traces 569k. */
#define LINE_SEP_SIGMA 300.0
static int seeds(tracer *T, int nl, int ns)
{
    const hprob *pr = T->pr;
    hrootlist l = {NULL, 0, 0};
    int rc = EL_OK, cap = 0;
    if (!(T->line = malloc((size_t)nl * sizeof *T->line))) return EL_ENOMEM;
    for (int j = 0; j < nl && !rc; j++) {
        hprob q = *pr;
        const double frac = nl == 1 ? 1.0 : 1.0 - pow(1.0 - (double)j / (nl - 1), T->line_power);
        /* none above the top one (a trace from a seed above thi_bound ends at its first step: the
         * lines all kept at their former places lost 272 of the bench's 3494 solutions); with many
         * lines and long curves (grid 12, Lt 20 |p1 - p0|, d near pi) the one below the top would lie
         * above it; the top line's t is written as before, tlo + (thi - tlo) * 1 (bin 0, above) */
        const double t = T->tlo + ((j == nl - 1 ? T->thi : T->thi_lines) - T->tlo) * frac;
        q.sigma = sinh(j == nl - 1 ? t : fmin(T->thi, t));
        q.Lmin = 1.0;
        l.n = 0;
        rc = T->lean_seeds ? el__hermite_seed_tension(&q, ns, T->line_sep, &l) : el__hermite_solve_tension(&q, ns, &l);
        if (rc) break;
        for (size_t i = 0; i < l.n && !rc; i++) {
            if (T->nseed == cap) {
                cap = cap ? 2 * cap : 16;
                cpt *v = realloc(T->seed, (size_t)cap * sizeof *v);
                char *w = realloc(T->visited, (size_t)cap);
                if (v) T->seed = v;
                if (w) T->visited = w;
                if (!v || !w) { rc = EL_ENOMEM; break; }
            }
            const hroot *r = &l.v[i];
            cpt *s = &T->seed[T->nseed];
            rc = el__hlen_seed_point(T, r, q.sigma, s);
            if (!rc) rc = el__hlen_rechart(T, s);
            if (rc == EL_EMAXITER) break;
            if (rc) { rc = EL_OK; continue; }
            /* a seed found twice (the tension solver's duplicates) is traced once */
            int dup = 0;
            for (int k = 0; k < T->nseed && !dup; k++) dup = el__hlen_same_state(&T->seed[k], s);
            if (!dup) T->visited[T->nseed++] = 0;
        }
        seed_line *ln = &T->line[T->nline];
        ln->tlo = INFINITY;
        ln->thi = -INFINITY;
        for (int i = T->nline ? T->line[T->nline - 1].end : 0; i < T->nseed; i++) {
            ln->tlo = fmin(ln->tlo, T->seed[i].t);
            ln->thi = fmax(ln->thi, T->seed[i].t);
        }
        ln->end = T->nseed;
        T->nline++;
    }
    free(l.v);
    return rc;
}

/* Where a trace towards the curves of unbounded length near sigma = 0 (near-circles of
 * radius ~ 1/sqrt(sigma) nearly closed, L ~ 2 pi / sqrt(sigma)) ends: L beyond 1.5 Lt and
 * increasing. None of the solutions of 5 x 1000 random problems (test_hermite_length.c's
 * five kinds) lies beyond on such a trace: the traces to 10 Lt find the same (at 3 Lt:
 * 17 % fewer evaluations than at 10; at 1.5 Lt 3.4 % fewer instructions in the length
 * mode than at 3, the same solutions in make hermite-sets and of 138 000 tension-mode
 * solutions solved again by length; 1.2 Lt lost some). el__hermite_solve_length_thorough
 * follows them to 10 Lt. */
#define LONG_CURVES 1.5
#define LONG_CURVES_THOROUGH 10.0
/* The seed lines' placement (seeds): spread evenly, a little closer towards the bottom.
 * Against the former 1.5 (closer towards the top): the same solutions on 7000 random
 * problems (six kinds), 12 % fewer instructions on the bench's; the thorough search
 * keeps 1.5 (its lines independent of the default's). */
#define LINE_POWER 0.8
#define LINE_POWER_THOROUGH 1.5

/* The samples of a seed line's pieces (the default search; the thorough one takes ns): half
 * the tension mode's (at least its minimum, 4). A piece of C needs one seed, on any line, and
 * the roots a line's sparser samples miss (close pairs: 50 of the 32 680 roots of the
 * bench-like problems' lines at ns 6 against 12) lie on pieces the traces from the other
 * seeds meet: 2.4 % fewer instructions in the length mode, the same solutions in make
 * hermite-sets and of 138 000 tension-mode solutions solved again by length; at ns 4 the
 * lines miss 188. */
static int lean_line_samples(int ns) { return ns / 2 > 4 ? ns / 2 : 4; }

static int solve_length(hprob *pr, double Lt, int nl, int ns, double long_curves, double line_power,
                        int lean_seeds, int retrace, int newton_seeds, int chord_start, double line_sep,
                        long max_evals, hrootlist *out)
{
    double slo, shi;
    sigma_range(pr, Lt, &slo, &shi);
    tracer T;
    memset(&T, 0, sizeof T);
    T.pr = pr;
    T.Lt = Lt;
    T.tlo = asinh(slo);
    T.thi = asinh(fmin(shi, SIGMA_MAX));
    T.thi_lines = asinh(fmin(HLEN_SIGMA_E2 / ((Lt - 1.0) * (Lt - 1.0)), SIGMA_MAX));
    T.thi_trace = asinh(fmin(shi, SIGMA_TRACE_MAX));
    T.thi_bound = asinh(shi);
    T.out = out;
    T.max_evals = max_evals;
    T.long_curves = long_curves;
    T.line_power = line_power;
    T.lean_seeds = lean_seeds;
    T.retrace = retrace;
    T.newton_seeds = newton_seeds;
    T.chord_start = chord_start;
    T.line_sep = line_sep;
    int rc = seeds(&T, nl, lean_seeds ? lean_line_samples(ns) : ns);
    for (int i = 0; i < T.nseed && !rc; i++) {
        if (T.visited[i]) continue;
        T.visited[i] = 1;
        rc = el__hlen_trace(&T, i, 1.0);
        if (!rc) rc = el__hlen_trace(&T, i, -1.0);
    }
    free(T.seed);
    free(T.visited);
    free(T.line);
    return rc;
}

/* Length mode, normalised: every point of C (above) with L = Lt; nl seed lines with
 * lean_line_samples(ns) bracketing samples each. */
int el__hermite_solve_length(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 0, 0, 0, LINE_SEP_SIGMA, MAX_EVALS, out);
}

/* The same within max_evals evaluations (el__hermite_solve_limited's work limit). */
int el__hermite_solve_length_limited(hprob *pr, double Lt, int nl, int ns, long max_evals, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 0, 0, 0, LINE_SEP_SIGMA, max_evals, out);
}

int el__hlen_solve_retracing(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 1, 0, 0, LINE_SEP_SIGMA, MAX_EVALS, out);
}

int el__hlen_solve_newton_seeds(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 0, 1, 0, LINE_SEP_SIGMA, MAX_EVALS, out);
}

int el__hlen_solve_chord_start(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 0, 0, 1, LINE_SEP_SIGMA, MAX_EVALS, out);
}

int el__hlen_solve_line_pieces(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES, LINE_POWER, 1, 0, 0, 0, SEP_SIGMA, MAX_EVALS, out);
}

int el__hermite_solve_length_thorough(hprob *pr, double Lt, int nl, int ns, hrootlist *out)
{
    return solve_length(pr, Lt, nl, ns, LONG_CURVES_THOROUGH, LINE_POWER_THOROUGH, 0, 1, 0, 0, SEP_SIGMA, MAX_EVALS, out);
}
