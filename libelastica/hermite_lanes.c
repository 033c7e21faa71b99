/*
 * The objective of the x chart (hermite_objective.c's el__hermite_x_objective) at several
 * abscissae at once: the bracketing samples of a piece (hermite_tension.c) are known
 * before any is evaluated and are independent of each other. One evaluation is a chain
 * of square roots and divisions (the curvature data (19), |F|, the half angles at both
 * ends, the amplitude difference, its reduction, Carlson's duplication) whose latency is
 * its cost; two side by side (lanes.h, SSE2) share each operation, four (AVX2, where the
 * processor has it: hermite_lanes_avx2.c) twice as many. Every lane's operations are the
 * scalar evaluation's in the same order (no contraction, no reassociation), its branches
 * taken lane by lane as selections: the same bits whichever width runs
 * (test_hermite_tension.c compares them). A group whose lanes need both kinds of curve
 * (inflectional and not), and case 3, are left to the narrower evaluation.
 * The kind of curve at many abscissae (el__hermite_x_classes, and el__hermite_piece_classes:
 * every piece of a branch from its midpoint, confirmed at its quarter points where the
 * midpoint has no curve) goes the same way, lane by lane the scalar el__hermite_x_class's
 * (case 3: the scalar one itself); n - 1 < HERMITE_GATHER_MAX / 2 pieces (split_points'
 * MAXPTS bound it far below).
 */
#include "hermite_internal.h"
#include "lanes.h"

/* the narrower evaluation of two lanes: one by one */
static void objectives1(const hprob *pr, const double *x, int n, int b, double qs, double *f)
{
    for (int l = 0; l < n; l++) el__hermite_x_objective(pr, x[l], b, qs, f + l);
}

#define LANES_W 2
#define LANES_NARROWER objectives1
#include "hermite_lanes_body.h"

int el__lanes4_available(void)
{
#if EL__LANES4
    /* libgcc's (compiler-rt's) cpuid reading, made once at load: AVX2, and an OS that
     * saves the 256-bit registers */
    return __builtin_cpu_supports("avx2");
#else
    return 0;
#endif
}

void el__hermite_x_objectives(const hprob *pr, const double *x, int n, int b, double qs, double *f)
{
#if EL__LANES4
    if (__builtin_cpu_supports("avx2")) {
        el__hermite_x_objectives4(pr, x, n, b, qs, f);
        return;
    }
#endif
    el__hermite_x_objectives2(pr, x, n, b, qs, f);
}

void el__hermite_sample_pieces(const hprob *pr, int b, const hpiece *pc, int np, int room, double qs, double *cosn,
                               double *xs, double *fs, int *off)
{
    double tx[HERMITE_GATHER_MAX], tf[HERMITE_GATHER_MAX];
    int idx[HERMITE_GATHER_MAX];
    for (int i = 0, o = 0; i < np; o += pc[i].ns + 1 + room, i++) {
        const double a = pc[i].a, w = pc[i].b - pc[i].a, eps = 1e-10 * w + 1e-14 * (fabs(a) + fabs(pc[i].b));
        const int ns = pc[i].ns;
        off[i] = w > 4.0 * eps ? o : -1;
        if (off[i] < 0) continue;
        /* cos(pi j / ns) by the Chebyshev recurrence c_{j+1} = 2 c_1 c_j - c_{j-1} */
        double c1;
        if (ns < HERMITE_NCOS) {
            if (isnan(cosn[ns])) cosn[ns] = cos(M_PI / ns);
            c1 = cosn[ns];
        } else {
            c1 = cos(M_PI / ns);
        }
        double cprev = c1, cj = 1.0, *x = xs + o;
        for (int j = 0; j <= ns; j++) {
            x[j] = a + w * 0.5 * (1.0 - cj);
            if (j == 0) x[j] = a + eps;
            if (j == ns) x[j] = pc[i].b - eps;
            const double cnext = 2.0 * c1 * cj - cprev;
            cprev = cj;
            cj = cnext;
        }
    }
    /* by kind: inflectional, non-inflectional, mixed (a pair of an inflectional and a
     * non-inflectional sample is evaluated one by one) */
    static const int kinds[3] = {CLASS_INFL, CLASS_NONINFL, CLASS_MIXED};
    for (int k = 0; k < 3; k++) {
        int n = 0;
        for (int i = 0; i < np; i++)
            if (off[i] >= 0 && pc[i].cls == kinds[k])
                for (int j = 0; j <= pc[i].ns; j++) idx[n++] = off[i] + j;
        if (!n) continue;
        for (int j = 0; j < n; j++) tx[j] = xs[idx[j]];
        el__hermite_x_objectives(pr, tx, n, b, qs, tf);
        for (int j = 0; j < n; j++) fs[idx[j]] = tf[j];
    }
}

void el__hermite_x_classes(const hprob *pr, const double *x, int n, int b, int *cls)
{
    if (pr->hcase == 3) {   /* kappa0 fixed, x = kappa0': the scalar classes */
        for (int i = 0; i < n; i++) cls[i] = el__hermite_x_class(pr, x[i], b);
        return;
    }
#if EL__LANES4
    if (__builtin_cpu_supports("avx2")) {
        el__hermite_x_classes4(pr, x, n, b, cls);
        return;
    }
#endif
    el__hermite_x_classes2(pr, x, n, b, cls);
}

void el__hermite_piece_classes(const hprob *pr, int b, const double *x, int n, int *cls)
{
    double xm[HERMITE_GATHER_MAX], xq[HERMITE_GATHER_MAX];
    int cq[HERMITE_GATHER_MAX], iq[HERMITE_GATHER_MAX / 2], nq = 0;
    if (n < 2) return;
    /* the midpoints, as the plain piece class computes them */
    for (int i = 0; i + 1 < n; i++) xm[i] = 0.5 * (x[i] + x[i + 1]);
    el__hermite_x_classes(pr, xm, n - 1, b, cls);
    /* the quarter points of the pieces whose midpoint has no curve */
    for (int i = 0; i + 1 < n; i++)
        if (cls[i] == CLASS_NONE) {
            const double a = x[i], c = x[i + 1];
            iq[nq / 2] = i;
            xq[nq++] = a + 0.25 * (c - a);
            xq[nq++] = a + 0.75 * (c - a);
        }
    if (!nq) return;
    el__hermite_x_classes(pr, xq, nq, b, cq);
    for (int j = 0; j < nq; j += 2)
        cls[iq[j / 2]] = cq[j] == CLASS_NONE && cq[j + 1] == CLASS_NONE ? CLASS_NONE : CLASS_MIXED;
}
