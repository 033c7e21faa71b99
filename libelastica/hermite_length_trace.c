/*
 * The length mode's tracing (hermite_length.c: the method; the seed lines and the search):
 * a curve C of tension solutions followed from a seed by pseudo-arclength continuation (a
 * cubic predictor, Newton's corrector along the gradient of f), and the events of each
 * accepted step: the solutions L = Lt it brackets (Newton on (f, L - Lt)) and the seed
 * lines it crosses (their seeds marked visited).
 */
#include "hermite_length_internal.h"

/* Newton steps along the gradient of f to the curve f = 0 (|f| below tol, or at a
 * distance |f| / |grad f| below 1e-13 where f is steep); at most maxit evaluations,
 * the count into *its. A step that does not decrease |f| ends it (EL_ENOCONV, as the
 * limit does): Newton converges quadratically from the trace's predictors, so such a
 * start is off its basin and the callers' fallbacks (a shorter step, another chart)
 * take over without the remaining evaluations (0.5 % of the bench's instructions). */
static int correct(tracer *T, cpt *q, double tol, int maxit, int *its)
{
    double last = INFINITY;
    cpt buf[2], *cur = q;   /* the iterates alternate in buf; the last good one into *q once */
    int rc;
    for (*its = 0;; ++*its) {
        const double g2 = cur->fg[0] * cur->fg[0] + cur->fg[1] * cur->fg[1], af = fabs(cur->st.f);
        if (!(g2 > 0.0)) { rc = EL_EDOM; break; }
        if (af <= tol || af <= 1e-13 * sqrt(g2)) { rc = EL_OK; break; }
        if (*its >= maxit || !(af < last)) { rc = EL_ENOCONV; break; }
        last = af;
        const double c = cur->st.f / g2;
        cpt *n = &buf[*its % 2];
        if ((rc = el__hlen_eval(T, cur, cur->U - c * cur->fg[0], cur->V - c * cur->fg[1], n))) break;
        cur = n;
    }
    if (cur != q) *q = *cur;
    return rc;
}

/* The unit tangent of C at p, oriented along (d0, d1). */
static void tangent(const cpt *p, double d0, double d1, double tau[2])
{
    const double n = el__hlen_norm(p->fg[0], p->fg[1]);
    tau[0] = -p->fg[1] / n;
    tau[1] = p->fg[0] / n;
    if (tau[0] * d0 + tau[1] * d1 < 0.0) { tau[0] = -tau[0]; tau[1] = -tau[1]; }
}

/* Newton on (f, G - target) (G: L, or t when which = 1) from the evaluated point *r,
 * steps at most span long and damped to decrease |f| + |G - target|. */
#define NEWTON2_STALLS 4
static int converged2(const cpt *r, int which, double target, double scale)
{
    return fabs(r->st.f) <= 1e-11 && fabs((which ? r->t : r->st.L) - target) <= 1e-11 * scale;
}

static int newton2(tracer *T, int which, double target, double span, cpt *r)
{
    const double scale = fmax(1.0, fabs(target));
    int stalls = 0;
    for (int it = 0; it < 12 + NEWTON2_STALLS; it++) {
        const double *G = which ? r->tg : r->Lg;
        const double res0 = r->st.f, res1 = (which ? r->t : r->st.L) - target;
        if (fabs(res0) <= 1e-14 && fabs(res1) <= 1e-14 * scale) return EL_OK;
        const double det = r->fg[0] * G[1] - r->fg[1] * G[0];
        if (!(fabs(det) > 0.0)) return EL_EDOM;
        double d0 = -(G[1] * res0 - r->fg[1] * res1) / det, d1 = -(-G[0] * res0 + r->fg[0] * res1) / det;
        const double n = el__hlen_norm(d0, d1);
        if (n > span) { d0 *= span / n; d1 *= span / n; }
        cpt s, full;
        int ok = 0, full_ok = 0;
        /* r within the tolerance already (converged2): the residual is at its rounding
         * level, where a full step that does not decrease it is not helped by shorter
         * ones (the halvings below cost 5 evaluations and end the iteration the same way:
         * 489 such iterations, 2934 evaluations on the bench's 1000 problems) */
        const int conv = converged2(r, which, target, scale);
        for (int h = 0; h < 6 && !ok && !(conv && full_ok); h++, d0 *= 0.5, d1 *= 0.5) {
            const int rc = el__hlen_eval(T, r, r->U + d0, r->V + d1, &s);
            if (rc == EL_EMAXITER) return rc;
            if (rc) continue;
            if (h == 0) { full = s; full_ok = 1; }
            const double r0 = s.st.f, r1 = (which ? s.t : s.st.L) - target;
            ok = fabs(r0) + fabs(r1) / scale < fabs(res0) + fabs(res1) / scale;
        }
        if (!ok) {
            /* no step decreases the residual: at its rounding level (high tension, sigma L
             * large against f), which lies near the tolerance; there (residuals below 1e-9)
             * the full Newton steps, each a fresh draw of the rounding, a few more times (a
             * solution at sigma 3574 was lost at |f| = 4e-11) */
            if (converged2(r, which, target, scale) || !full_ok || stalls++ >= NEWTON2_STALLS ||
                !(fabs(res0) <= 1e-9 && fabs(res1) <= 1e-9 * scale))
                break;
            s = full;
        }
        *r = s;
    }
    return converged2(r, which, target, scale) ? EL_OK : EL_ENOCONV;
}

/* newton2, and where it stops at its rounding level above the tolerance (residuals
 * below 1e-8: a chart near its fold amplifies the rounding of the state, 3e-10 at
 * sigma 9940 in a separatrix chart over x), newton2 again in the point's other charts. */
static int newton2_charts(tracer *T, int which, double target, double span, cpt *r)
{
    int rc = newton2(T, which, target, span, r);
    if (rc != EL_ENOCONV || !(fabs(r->st.f) <= 1e-8 && fabs((which ? r->t : r->st.L) - target) <= 1e-8 * fmax(1.0, fabs(target))))
        return rc;
    for (int k = 0; k < NALT; k++) {
        cpt alt;
        int r2 = el__hlen_alt_chart(T, r, k, &alt);
        if (!r2) r2 = newton2(T, which, target, span, &alt);
        if (r2 == EL_EMAXITER) return r2;
        if (!r2) { *r = alt; return EL_OK; }
    }
    return rc;
}

/* Newton's start for the crossing L = target of the step p -> q (one chart; unit tangents
 * tp, tq; L - target of opposite signs at the ends): the point of the step's cubic Hermite
 * interpolant (the trace's predictor, ends and tangents over the chord length D) at the
 * parameter x where the cubic Hermite interpolant of L along it (its slopes Lg . t D)
 * crosses the target, by safeguarded Newton from the linear interpolate w. The curve's
 * error is fourth order in D where the chord's is second: newton2 starts closer to C
 * (0.6 % fewer instructions in the length mode; the same solutions on 16 x 1000 random
 * problems in each of three ranges of L / |p1 - p0|, up to 2e-8 relative in sigma and
 * kappa0 at sigma |p1 - p0|^2 ~ 2000, where both curves meet the ends to 1e-14).
 * Hand-written rather than gsl_poly_solve_cubic: the cubic may have three real roots in
 * [0, 1], and the start wanted is the one Newton reaches from the linear interpolate w
 * within the bracket [lo, hi] it keeps (a degenerate cubic, a quadratic or a line, needs
 * no special case). */
static void hermite_start(const cpt *p, const double tp[2], const cpt *q, const double tq[2], double target,
                          double w, double *sU, double *sV)
{
    const double D = el__hlen_norm(q->U - p->U, q->V - p->V);
    const double a = p->st.L - target, b = q->st.L - target;
    const double m0 = (p->Lg[0] * tp[0] + p->Lg[1] * tp[1]) * D, m1 = (q->Lg[0] * tq[0] + q->Lg[1] * tq[1]) * D;
    double lo = 0.0, hi = 1.0, x = w;
    if (!(a * b <= 0.0) || !(x >= 0.0 && x <= 1.0)) return;
    for (int it = 0; it < 40; it++) {
        const double x2 = x * x, x3 = x2 * x;
        const double H = (2 * x3 - 3 * x2 + 1) * a + (x3 - 2 * x2 + x) * m0 + (3 * x2 - 2 * x3) * b + (x3 - x2) * m1;
        const double dH = (6 * x2 - 6 * x) * (a - b) + (3 * x2 - 4 * x + 1) * m0 + (3 * x2 - 2 * x) * m1;
        if (H == 0.0) break;
        if ((H > 0.0) == (a > 0.0)) lo = x; else hi = x;
        double xn = x - H / dH;
        if (!(xn > lo && xn < hi)) xn = 0.5 * (lo + hi);
        const double dx = fabs(xn - x);
        x = xn;
        if (dx <= 1e-14) break;
    }
    const double x2 = x * x, x3 = x2 * x;
    const double h00 = 2 * x3 - 3 * x2 + 1, h10 = (x3 - 2 * x2 + x) * D, h01 = 3 * x2 - 2 * x3, h11 = (x3 - x2) * D;
    const double U = h00 * p->U + h10 * tp[0] + h01 * q->U + h11 * tq[0];
    const double V = h00 * p->V + h10 * tp[1] + h01 * q->V + h11 * tq[1];
    if (isfinite(U) && isfinite(V)) { *sU = U; *sV = V; }
}

/* The point of the step p -> q of C where G (L, or t when which = 1) is target: Newton
 * (newton2) from the linear interpolate, for L with the step's unit tangents tp, tq from
 * the point of its cubic Hermite interpolant there (hermite_start; the chord's where
 * T->chord_start), or, when p and q lie in different charts or branches (C passed the
 * fold of (17) within the step), from each end in its own. */
static int cross(tracer *T, const cpt *p, const double *tp, const cpt *q, const double *tq, int which,
                 double target, cpt *r)
{
    const double gp = which ? p->t : p->st.L, gq = which ? q->t : q->st.L;
    const double w = gp == gq ? 0.5 : (gp - target) / (gp - gq);
    const double dU = q->U - p->U, dV = q->V - p->V, span = el__hlen_norm(dU, dV) + 1e-12;
    const int same = p->chart == q->chart && p->base == q->base && p->fi == q->fi && p->b == q->b && p->side == q->side;
    if (same) {
        double sU = p->U + w * dU, sV = p->V + w * dV;
        if (tp && tq && !T->chord_start) hermite_start(p, tp, q, tq, target, w, &sU, &sV);
        const int rc = el__hlen_eval(T, q, sU, sV, r);
        return rc ? rc : newton2_charts(T, which, target, span, r);
    }
    int rc = EL_ENOCONV;
    for (int e = 0; e < 2 && rc && rc != EL_EMAXITER; e++) {
        *r = (w < 0.5) == (e == 0) ? *p : *q;
        rc = newton2_charts(T, which, target, span, r);
    }
    return rc;
}

static int push_solution(tracer *T, const cpt *r)
{
    for (size_t i = 0; i < T->out->n; i++)
        if (el__hlen_same_hstate(T->out->v[i].sigma, &T->out->v[i].st, r->sigma, &r->st)) return EL_OK;
    hroot h = el__hermite_mkroot(T->pr->hcase == 3 ? r->st.k0p : r->st.k0, r->b, r->sigma);
    h.st = r->st;
    return el__hermite_roots_push(T->out, &h);
}

/* Whether r, a point of C found from the step p -> q, lies on the step (Newton can
 * reach the neighbour of a close pair): its projection on the chord within slack of
 * [0, 1]; a step across charts takes it as it is. */
static int on_step(const cpt *p, const cpt *q, const cpt *r, double slack)
{
    const int same = p->chart == q->chart && p->base == q->base && p->fi == q->fi;
    const double dU = q->U - p->U, dV = q->V - p->V;
    const double lam = same && r->chart == p->chart && r->base == p->base && r->fi == p->fi
                           ? ((r->U - p->U) * dU + (r->V - p->V) * dV) / (dU * dU + dV * dV) : 0.5;
    return lam >= -slack && lam <= 1.0 + slack;
}

/* A solution r found from the step p -> q: kept (any point of C with L = Lt is a
 * solution) where it lies near the step; 1 in *inside when it lies on the step itself,
 * the crossing the step brackets (one just beyond an end is the neighbour of a close
 * pair, and the bracketed one is still to be found). In a separatrix chart that also
 * needs r on the step's sheet: the coordinates (other, ln(|F| - sigma)) have a state on
 * each sheet of the replaced coordinate, and Newton can change sheet (it went from a
 * step at sigma 500 to a solution at sigma -9 with coordinates on the step); the chart
 * continued from an end of the step, as the trace does, gives r's state at r's. */
static int keep_crossing(tracer *T, const cpt *p, const cpt *q, const cpt *r, int *inside)
{
    *inside = on_step(p, q, r, 1e-6);
    if (*inside && p->chart == CHART_SEP && el__hlen_same_chart(p, r)) {
        int on = 0;
        for (int e = 0; e < 2 && !on; e++) {
            cpt c;
            const int rc = el__hlen_eval(T, e ? q : p, r->U, r->V, &c);
            if (rc == EL_EMAXITER) return rc;
            on = !rc && el__hlen_same_state(&c, r);
        }
        *inside = on;
    }
    return on_step(p, q, r, 0.05) ? push_solution(T, r) : EL_OK;
}

/* The solutions L = Lt on the step p -> q of C (both in one chart; tp, tq the unit
 * tangents along it): a sign change of L - Lt, or two crossings that the cubic Hermite
 * interpolant of L along the step reveals (an extremum of L beyond Lt between two
 * points on one side): the point of C near that extremum splits the step, at most
 * depth times. */
static int length_crossings(tracer *T, const cpt *p, const double tp[2], const cpt *q,
                            const double tq[2], int depth)
{
    int rc;
    cpt r;
    const double a = p->st.L - T->Lt, b = q->st.L - T->Lt;
    if (a * b <= 0.0) {
        rc = cross(T, p, tp, q, tq, 0, T->Lt, &r);
        if (rc == EL_EMAXITER) return rc;
        int inside = 0;
        if (rc == EL_OK && (rc = keep_crossing(T, p, q, &r, &inside))) return rc;
        if (inside) return EL_OK;
        /* Newton from the step's interpolate failed (off C where C bends away from its
         * chord, say) or reached the neighbour: from each end of the step, points of C */
        for (int e = 0; e < 2 && el__hlen_same_chart(p, q); e++) {
            r = e ? *q : *p;
            rc = newton2_charts(T, 0, T->Lt, el__hlen_norm(q->U - p->U, q->V - p->V) + 1e-12, &r);
            if (rc == EL_EMAXITER) return rc;
            if (rc == EL_OK && (rc = keep_crossing(T, p, q, &r, &inside))) return rc;
            if (inside) return EL_OK;
        }
        /* still none (a long step, one across the branches of (17), or one that holds a
         * close pair): the point of C in the middle halves the bracket */
        if (depth == 0 || p->chart != q->chart || p->base != q->base || p->fi != q->fi) return EL_OK;
        /* the chord's midpoint, corrected; where that fails (it lies outside the chart's
         * domain where C runs along its edge, the x chart near the fold where the branches
         * of (17) meet), the midpoint of the step's cubic Hermite interpolant,
         * (p + q) / 2 + D (tp - tq) / 8 (D the chord's length), which follows C's bend,
         * and for a step across the branches both again on the other end's branch */
        const double D = el__hlen_norm(q->U - p->U, q->V - p->V);
        const cpt *ends[2] = {p->b == q->b ? p : q, p->b == q->b ? NULL : p};
        cpt m;
        rc = EL_EDOM;
        for (int k = 0; k < 4 && rc && ends[k / 2]; k++) {
            const double bend = k % 2 ? 0.125 * D : 0.0;
            int its;
            rc = el__hlen_eval(T, ends[k / 2], 0.5 * (p->U + q->U) + bend * (tp[0] - tq[0]),
                               0.5 * (p->V + q->V) + bend * (tp[1] - tq[1]), &m);
            if (!rc) rc = correct(T, &m, 1e-9, 6, &its);
            if (rc == EL_EMAXITER) return rc;
        }
        if (rc) return EL_OK;
        double tm[2];
        tangent(&m, q->U - p->U, q->V - p->V, tm);
        if ((m.st.L - T->Lt) * a <= 0.0) return length_crossings(T, p, tp, &m, tm, depth - 1);
        return length_crossings(T, &m, tm, q, tq, depth - 1);
    }
    if (depth == 0) return EL_OK;
    const double dU = q->U - p->U, dV = q->V - p->V, ds = el__hlen_norm(dU, dV);
    const double m0 = (p->Lg[0] * tp[0] + p->Lg[1] * tp[1]) * ds;
    const double m1 = (q->Lg[0] * tq[0] + q->Lg[1] * tq[1]) * ds;
    /* H(x) = a h00 + m0 h10 + b h01 + m1 h11 on [0, 1]; H'(x) = c2 x^2 + c1 x + m0 */
    const double c2 = 6.0 * a + 3.0 * m0 - 6.0 * b + 3.0 * m1, c1 = -6.0 * a - 4.0 * m0 + 6.0 * b - 2.0 * m1;
    double xs[2];
    int n = 0;
    if (fabs(c2) > 1e-300) {
        const double disc = c1 * c1 - 4.0 * c2 * m0;
        if (disc >= 0.0) {
            const double sq = copysign(sqrt(disc), c1), qq = -0.5 * (c1 + sq);
            if (qq != 0.0) { xs[n++] = qq / c2; xs[n++] = m0 / qq; }
        }
    } else if (c1 != 0.0) {
        xs[n++] = -m0 / c1;
    }
    for (int i = 0; i < n; i++) {
        const double x = xs[i];
        if (!(x > 0.0 && x < 1.0)) continue;
        const double H = (2 * x * x * x - 3 * x * x + 1) * a + (x * x * x - 2 * x * x + x) * m0 +
                         (-2 * x * x * x + 3 * x * x) * b + (x * x * x - x * x) * m1;
        if (H * a > 0.0) continue;
        /* two crossings likely: the point of C there splits the step */
        cpt m;
        int its;
        if ((rc = el__hlen_eval(T, p, p->U + x * dU, p->V + x * dV, &m)) == EL_EMAXITER) return rc;
        if (!rc) rc = correct(T, &m, 1e-9, 6, &its);
        if (rc == EL_EMAXITER) return rc;
        if (rc) return EL_OK;
        double tm[2];
        tangent(&m, dU, dV, tm);
        if ((rc = length_crossings(T, p, tp, &m, tm, depth - 1))) return rc;
        return length_crossings(T, &m, tm, q, tq, depth - 1);
    }
    return EL_OK;
}

/* Whether seed s is near the crossing of its line by the step p -> q, the state linearly
 * interpolated to the line (far from the seed, no need for the exact crossing). */
static int near_crossing(const cpt *p, const cpt *q, const cpt *s)
{
    const double w = (s->t - p->t) / (q->t - p->t);
    const double k0 = p->st.k0 + w * (q->st.k0 - p->st.k0), k0p = p->st.k0p + w * (q->st.k0p - p->st.k0p);
    return fabs(k0 - s->st.k0) <= 0.1 * (1.0 + fabs(s->st.k0) + fabs(q->st.k0 - p->st.k0)) &&
           fabs(k0p - s->st.k0p) <= 0.1 * (1.0 + fabs(s->st.k0p) + fabs(q->st.k0p - p->st.k0p));
}

/* The seed the step p -> q (one chart, unit tangents tp, tq, in which t is the coordinate
 * V) crosses on the line t = ts, without evaluations: the cubic Hermite interpolant of
 * the step meets the line at U; the crossing is one of the line's seeds (all the tension
 * solutions there), so where exactly one seed near the crossing (near_crossing) lies
 * within 1 % of the step's length of U, all others (visited or not) farther than the
 * step's length, it is that one (the interpolant's error is below 1e-3 of the step in
 * 97 % of 41 000 crossings, above 0.1 in 1). A seed in another chart is measured by its
 * coordinates in the step's (el__hlen_coords_in; in the step's chart V is t there too):
 * 80 % of the crossings Newton decided were of steps near a seed of another chart (the
 * x chart's seeds against the K1 chart's steps, separatrix charts of another base or
 * replaced coordinate). The seed's number, or -1 where that does not decide (then
 * Newton does, step_events). */
static int seed_by_interpolation(const tracer *T, const cpt *p, const double tp[2], const cpt *q,
                                 const double tq[2], double ts)
{
    const int t_is_V = p->chart == HCHART_X || p->chart == HCHART_K1 ||
                       (p->chart == CHART_SEP && p->fi == 0 && p->base != HCHART_C3);
    if (!t_is_V || !el__hlen_same_chart(p, q) || !(q->V != p->V)) return -1;
    const double D = el__hlen_norm(q->U - p->U, q->V - p->V);
    double x = (ts - p->V) / (q->V - p->V);
    for (int it = 0; it < 30; it++) {   /* V(x) = ts by Newton (V the cubic of x below) to |dx| <= 1e-15 */
        const double V = (2 * x * x * x - 3 * x * x + 1) * p->V + (x * x * x - 2 * x * x + x) * D * tp[1] +
                         (-2 * x * x * x + 3 * x * x) * q->V + (x * x * x - x * x) * D * tq[1] - ts;
        const double dV = (6 * x * x - 6 * x) * (p->V - q->V) + (3 * x * x - 4 * x + 1) * D * tp[1] +
                          (3 * x * x - 2 * x) * D * tq[1];
        if (!(fabs(dV) > 0.0)) return -1;
        const double dx = V / dV;
        x -= dx;
        if (fabs(dx) <= 1e-15) break;
    }
    if (!(x >= 0.0 && x <= 1.0)) return -1;
    const double U = (2 * x * x * x - 3 * x * x + 1) * p->U + (x * x * x - 2 * x * x + x) * D * tp[0] +
                     (-2 * x * x * x + 3 * x * x) * q->U + (x * x * x - x * x) * D * tq[0];
    int best = -1, close = 0;
    for (int j = 0; j < T->nseed; j++) {
        const cpt *s = &T->seed[j];
        if (fabs(s->t - ts) > 1e-12 * (1.0 + fabs(ts)) || !near_crossing(p, q, s)) continue;
        double sU = s->U, sV;
        if (!el__hlen_same_chart(s, p)) el__hlen_coords_in(T->pr, s, p, &sU, &sV);
        const double d = fabs(sU - U);
        if (d < D) close++;
        if (d <= 0.01 * D) best = j;
    }
    return close == 1 ? best : -1;
}

/* Whether the length of r, a point of C Newton found from the step p -> q, fits the
 * step: within the range of the ends' lengths widened by their difference on both
 * sides (room for an extremum of L inside the step). Newton on a seed line can reach
 * another branch of C close in (kappa0, kappa0') but not in L (L / Lt 0.888 from a
 * step between 0.617 and 0.569, the seed the step crossed at 0.598 a neighbour): the
 * seed taken for visited was then never traced and its solution lost. A crossing
 * refused here leaves the seed to be traced (more work, never a lost solution). */
static int length_fits(const cpt *p, const cpt *q, const cpt *r)
{
    const double lo = fmin(p->st.L, q->st.L), hi = fmax(p->st.L, q->st.L), m = hi - lo;
    return r->st.L >= lo - m && r->st.L <= hi + m;
}

/* The events of an accepted step p -> q (unit tangents tp, tq): solutions (L = Lt),
 * seed lines crossed (seeds on C are marked visited; the trace's own seed means C
 * closed: *closed = 1). A seed another trace visited ends the trace too (*closed = 1)
 * unless T->retrace: that trace's origin was followed both ways, so the trace has
 * entered the stretch of C they covered, and the rest of it up to where they ended
 * has been searched (5.4 % of the tracing's evaluations on the bench's 1000 problems
 * went there; 2.0 % fewer instructions in all, net of the Newton crossings of the
 * visited seeds' lines; the same solutions on 10 x 1000 and 10 x 3000 random problems,
 * and retrace as the plain counterpart, test_hermite_length.c). */
static int step_events(tracer *T, int origin, const cpt *p, const double tp[2], const cpt *q,
                       const double tq[2], int *closed)
{
    int rc, have = 0, rcr = EL_OK, fast = -1;
    double tr = NAN;
    cpt r;
    if ((rc = length_crossings(T, p, tp, q, tq, 6))) return rc;
    const double smin = fmin(p->t, q->t), smax = fmax(p->t, q->t);
    for (int j = 0, i = 0; j < T->nline; i = T->line[j++].end) {
        /* a line whose seeds all lie outside [smin, smax]: none of them is crossed (below) */
        if (T->line[j].thi < smin || T->line[j].tlo > smax) continue;
        for (; i < T->line[j].end; i++) {
            const cpt *s = &T->seed[i];
            /* strictly crossed (the trace starts on its own seed's line) */
            if ((T->visited[i] && i != origin && T->retrace) || !((p->t - s->t) * (q->t - s->t) < 0.0 || q->t == s->t))
                continue;
            if (!near_crossing(p, q, s)) continue;
            /* the crossing of the line, once for the seeds of one line: by interpolation
             * where that decides, else by Newton */
            if (!have || fabs(s->t - tr) > 1e-12 * (1.0 + fabs(tr))) {
                have = 1;
                tr = s->t;
                fast = T->newton_seeds ? -1 : seed_by_interpolation(T, p, tp, q, tq, s->t);
                rcr = EL_OK;
                if (fast < 0 && (rcr = cross(T, p, NULL, q, NULL, 1, s->t, &r)) == EL_EMAXITER) return rcr;
                if (fast < 0 && !rcr && !length_fits(p, q, &r)) rcr = EL_ENOCONV;
            }
            if (fast >= 0 ? fast != i : rcr || !el__hlen_same_state(&r, s)) continue;
            if (i == origin || T->visited[i]) *closed = 1;
            T->visited[i] = 1;
        }
    }
    return EL_OK;
}

#define TRACE_STEPS 400
/* how closely the trace follows C (|f|, a position error relative to |P|): the
 * solutions themselves are found to rounding by cross() */
#define TRACE_TOL 1e-7
/* the largest change of ln L over one step: where L varies fast along C a close pair of
 * crossings of L = Lt hides in one long step (0.7 missed two of the 3528 solutions of
 * 1000 random problems; the cost is 0.3 % more evaluations) */
#define LRATIO 0.35
#define LRATIO_LO 0.7046880897187134  /* exp(-LRATIO) */
#define LRATIO_HI 1.4190675485932571  /* exp(LRATIO) */
/* The step's change of ln L against its slopes g0, g1 at the ends (along the step, over
 * its length): |ln(Lq / Lp) - (g0 + g1) / 2| (the trapezoid rule's error: L''' / 12 of the
 * cubic Hermite interpolant cross() and length_crossings() take for L along the step) at
 * most LDEF_ABS + LDEF_REL |g1 - g0|. Near the separatrix two branches of C run 0.02 apart
 * in the x and K1 charts (one more pass near the saddle: L 1.58 and 2.49 at sigma 40.5),
 * and a step 1.28 long corrected onto the other one passed every test above (tangent 1
 * degree, corrector 0.004, L ratio 1.2) with ln L up 0.18 where both slopes said down 0.27
 * (defect 0.45); the seeds it crossed on the branch it left were taken for visited and
 * ended the traces coming back along it short of a solution (19 175 tension solutions of
 * random problems solved again by length: 2, 10, 7, 16 lost at grid 12, 32, 48, 64; none
 * now). It refuses 31 of 24 794 steps of 400 problems at grid 6, 28 of them with ln L
 * against both slopes; on 40 000 problems the same solutions and 3 more; 1.0 % fewer
 * instructions on 1000. */
#define LDEF_ABS 0.1
#define LDEF_REL 0.5
/* A step shorter than FOLD_H whose evaluation fails: the point's other charts are tried,
 * at most CHART_FALLBACKS times per trace */
#define FOLD_H 1e-2
#define CHART_FALLBACKS 8
/* A trace that has taken CRAWL_STEPS steps in a row shorter than FOLD_H (no chart makes
 * longer ones) ends: C runs into a state where it ends (kappa0 -> 0 on the separatrix,
 * say), approached geometrically with L and sigma frozen; such traces ran on to
 * TRACE_STEPS (up to 2000 evaluations each) and found nothing there. */
#define CRAWL_STEPS 40
/* Follow C from seed number origin in the direction dir (+-1 along its tangent). */
int el__hlen_trace(tracer *T, int origin, double dir)
{
    const double hmin = 1e-7, hmax = 1.5;
    cpt p = T->seed[origin], prev;
    double tau[2], h = 0.3;
    /* the last step (from prev to p) in p's chart: its start, unit tangent there, length */
    int have_prev = 0, fallbacks = 0, have_last = 0, crawl = 0;
    double lastP[2] = {0.0, 0.0}, lastT[2] = {0.0, 0.0}, lastD = 1.0;
    tangent(&p, -dir * p.fg[1], dir * p.fg[0], tau);
    for (int step = 0; step < TRACE_STEPS;) {
        /* predictor: the cubic Hermite interpolant of the last step (ends and unit tangents,
         * parameter x in [0, 1] over its length D) continued to x = 1 + h / D, h beyond p,
         * or along the tangent where there is none (the trace's start, a chart switch). Its
         * error is fourth order in h where the tangent bent by the last step's change of
         * tangent (the former predictor) is third: 4.6 % fewer instructions in the length
         * mode on bench-like problems, the same solutions on 16 x 1000 random problems
         * (three ranges of L / |p1 - p0|) with length_fits (step_events); the solutions
         * its first versions lost are test_hermite_length.c's cubic predictor cases. */
        double pU = p.U + h * tau[0], pV = p.V + h * tau[1];
        if (have_last) {
            const double x = 1.0 + h / lastD, x2 = x * x, x3 = x2 * x;
            const double a0 = 2 * x3 - 3 * x2 + 1, a1 = (x3 - 2 * x2 + x) * lastD, a2 = 3 * x2 - 2 * x3,
                         a3 = (x3 - x2) * lastD;
            pU = a0 * lastP[0] + a1 * lastT[0] + a2 * p.U + a3 * tau[0];
            pV = a0 * lastP[1] + a1 * lastT[1] + a2 * p.V + a3 * tau[1];
        }
        cpt q;
        int its = 0, rc = el__hlen_eval(T, &p, pU, pV, &q);
        if (rc == EL_EMAXITER) return rc;
        /* a predictor whose tangent has turned by more than 45 degrees (cos < 0.7) is
         * rejected before its corrector: the corrected point, within 0.3 h of it, would
         * fail the 25-degree test below (0.6 % of the bench's instructions) */
        int turned = 0;
        if (!rc) {
            double tp[2];
            tangent(&q, tau[0], tau[1], tp);
            turned = tau[0] * tp[0] + tau[1] * tp[1] < 0.7;
        }
        if (!rc && !turned) rc = correct(T, &q, TRACE_TOL, 4, &its);
        if (rc && rc != EL_EMAXITER && T->pr->hcase == 1 && p.chart == HCHART_X) {
            /* where C passes from one branch of (17) to the other in the x chart */
            cpt other = p;
            other.b = 1 - p.b;
            rc = el__hlen_eval(T, &other, pU, pV, &q);
            if (!rc) rc = correct(T, &q, TRACE_TOL, 4, &its);
        }
        if (rc == EL_EMAXITER) return rc;
        double tq[2], cosang = 0.0, err = INFINITY;
        int ok = !rc && !turned;
        if (ok) {
            const double dU = q.U - p.U, dV = q.V - p.V;
            tangent(&q, tau[0], tau[1], tq);
            cosang = tau[0] * tq[0] + tau[1] * tq[1];
            err = el__hlen_norm(q.U - pU, q.V - pV);
            /* |ln(Lq / Lp)| <= LRATIO without the logarithm (the ratio between its exponentials) */
            const double lr = q.st.L / p.st.L;
            ok = err <= 0.3 * h && cosang >= 0.9 && lr >= LRATIO_LO && lr <= LRATIO_HI &&
                 dU * tau[0] + dV * tau[1] > 0.0;
            if (ok) {
                const double D = el__hlen_norm(dU, dV);
                const double g0 = (p.Lg[0] * tau[0] + p.Lg[1] * tau[1]) * D / p.st.L;
                const double g1 = (q.Lg[0] * tq[0] + q.Lg[1] * tq[1]) * D / q.st.L;
                ok = fabs(log(lr) - 0.5 * (g0 + g1)) <= LDEF_ABS + LDEF_REL * fabs(g1 - g0);
            }
        }
        if (!ok) {
            h *= 0.5;
            /* a failed evaluation on a short step: the chart folds there (the x chart
             * where the branches of (17) meet, a separatrix chart whose replaced
             * coordinate turns back along ln(|F| - sigma) = y) while C goes on; the
             * other charts of the point (el__hlen_alt_chart) are tried, the first that makes the
             * step is kept (traces crawled to hmin there and lost the solutions beyond) */
            if (rc && h < FOLD_H && have_prev && fallbacks < CHART_FALLBACKS) {
                fallbacks++;
                int found = 0;
                for (int k = 0; k < NALT && !found; k++) {
                    cpt alt, trial;
                    double pu, pv, ta[2];
                    int its2, r2 = el__hlen_alt_chart(T, &p, k, &alt);
                    if (r2 == EL_EMAXITER) return r2;
                    if (r2) continue;
                    el__hlen_coords_in(T->pr, &prev, &alt, &pu, &pv);
                    tangent(&alt, alt.U - pu, alt.V - pv, ta);
                    r2 = el__hlen_eval(T, &alt, alt.U + FOLD_H * ta[0], alt.V + FOLD_H * ta[1], &trial);
                    if (!r2) r2 = correct(T, &trial, TRACE_TOL, 4, &its2);
                    if (r2 == EL_EMAXITER) return r2;
                    if (r2) continue;
                    p = alt;
                    have_last = 0;
                    tau[0] = ta[0];
                    tau[1] = ta[1];
                    h = FOLD_H;
                    found = 1;
                }
                if (found) continue;
            }
            if (h < hmin) return EL_OK;                 /* C ends (or is not smooth) here */
            continue;
        }
        step++;
        crawl = h < FOLD_H ? crawl + 1 : 0;
        int closed = 0;
        if ((rc = step_events(T, origin, &p, tau, &q, tq, &closed))) return rc;
        /* C leaves the sigma range of the solutions (past SIGMA_TRACE_MAX with L < Lt),
         * closes, or runs to the curves of unbounded length near sigma = 0 (F -> 0, a
         * straight line's limit). A tail climbing in sigma with L < Lt and falling is
         * followed to the range's end: such tails take a fifth of the tracing's
         * evaluations on the bench's 1000 problems, but cut at their first step, the top
         * line's seeds they would have passed start traces of their own that follow them
         * down again (344k -> 568k evaluations). */
        if (closed || crawl > CRAWL_STEPS || q.t < T->tlo || q.t > T->thi_bound || (q.t > T->thi_trace && q.st.L < T->Lt) ||
            (q.st.L > T->long_curves * T->Lt && q.st.L > p.st.L))
            return EL_OK;
        prev = p;
        have_prev = 1;
        p = q;
        if ((rc = el__hlen_rechart(T, &p))) return rc == EL_EMAXITER ? rc : EL_OK;
        double pu, pv;
        el__hlen_coords_in(T->pr, &prev, &p, &pu, &pv);
        const double ds = el__hlen_norm(q.U - prev.U, q.V - prev.V);
        have_last = el__hlen_same_chart(&p, &q) && el__hlen_same_chart(&prev, &q) && ds > 0.0;
        lastP[0] = prev.U;
        lastP[1] = prev.V;
        lastT[0] = tau[0];
        lastT[1] = tau[1];
        lastD = ds;
        tangent(&p, p.U - pu, p.V - pv, tau);
        if (cosang > 0.98 && its <= 2) h = fmin(1.5 * h, hmax);
    }
    return EL_OK;
}
