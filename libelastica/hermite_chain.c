/*
 * A Hermite solution near the separatrix as a chain of pieces split at its saddles
 * (issue 12).
 *
 * Near the separatrix (|k| -> 1) a curve that passes a saddle (the near-straight
 * stretch between two loops, u = K mod 2K for inflectional curves, v = |k| u = K(1/|k|)
 * mod 2K(1/|k|) for loops) depends on the distance 2K between the loops, which grows
 * like ln(1/k'): one ulp of the double k moves its end by about 1e-16 / (1 - |k|)
 * (hermite.c). Split at the saddles, each piece has its own start point and its phase
 * measured from its own loop (u -> u - 2K: sn, cn -> -sn, -cn, carried by -k; a
 * loop's period 2K(1/|k|) in v leaves its geometry unchanged), so the distance between
 * loops is no longer the rounded K but the pieces' own phases. A piece is not exact
 * either: its formula also carries the far loop's tail, whose size at the split point
 * depends on the rounded k, so its end moves by about 1e-16 / k' per ulp (checked
 * against a 90-digit evaluation: up to ~3e-8 |p1 - p0| at k'^2 ~ 1e-16; 1/(1-|k|) has
 * become 1/sqrt(1-|k|)). The chain therefore starts from the exact phases of the
 * solver's root (|F| - sigma exact, so k' and K are), places every piece at the end
 * and with the end tangent of the one before (G1 by construction), and corrects the
 * phases by Gauss-Newton until the last piece meets p1, t1. What is left is a jump of
 * curvature (inflectional; ~1e-8 of kappa_m at k'^2 ~ 1e-16) or of kappa' (loops) at
 * the joint, and the chain lies within ~5e-10 |p1 - p0| of the exact curve (measured,
 * sigma |p1 - p0|^2 up to 1e4). For a loop the far tails of both pieces bend the same
 * way, so their errors would add: its two pieces take the doubles on either side of
 * the exact |k| and the joint moves to where the two errors cancel (below).
 * Where the chain's curvature still jumps at its joint by more than those doubles must
 * leave (el__hermite_chain: near-straight curves, whose own curvature ~k' kappa_m is far
 * below the loops' peak), the joint is moved with the phases until it is continuous.
 */
#include "hermite_internal.h"
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>
#include <string.h>

enum { MAXPIECES = 3, MAXUNK = MAXPIECES + 1 };
/* the pieces' force directions agree to this (rad; hermite_check.h's bound) */
#define CHAIN_PHI 1e-7

/* The chain and the unknowns of its correction: the phase q of every piece and the
 * last piece's length (tension mode) or the common mu (length mode, where the total
 * length is given); every piece but the last keeps its end phase uend. */
typedef struct {
    int n, mode;
    double sigma, L;              /* tension mode: the given sigma; the total length */
    el_smooth_params p[MAXPIECES];
    double uend[MAXPIECES];
} chain;

static double wrap(double a) { return el__hermite_wrap_pi(a); }

static int nunknowns(const chain *c) { return c->n + 1; }

static void get_unknowns(const chain *c, double *x)
{
    for (int i = 0; i < c->n; i++) x[i] = c->p[i].q;
    x[c->n] = c->mode == EL_HERMITE_TENSION ? c->p[c->n - 1].length : c->p[0].mu;
}

/* The chain for the unknowns x: phases, lengths, mu; then each piece placed at the end
 * of the one before with its end tangent (the first at p0 with t0): *end gets the last
 * piece's end (x, y, theta). */
static int set_unknowns(const hframe *fr, chain *c, const double *x, double end[3])
{
    double used = 0.0;
    for (int i = 0; i < c->n; i++) {
        el_smooth_params *p = &c->p[i];
        p->q = x[i];
        if (c->mode == EL_HERMITE_LENGTH) p->mu = x[c->n];
        if (!(p->mu > 0.0)) return EL_EDOM;
        if (i + 1 < c->n) {
            p->length = (c->uend[i] - p->q) / sqrt(p->mu);
            used += p->length;
        } else {
            p->length = c->mode == EL_HERMITE_TENSION ? x[c->n] : c->L - used;
        }
        if (!(p->length > 0.0)) return EL_EDOM;
    }
    double x0 = fr->p0[0], y0 = fr->p0[1], th = fr->psi0;
    for (int i = 0; i < c->n; i++) {
        /* the piece at the origin with phi = 0, then turned and moved into place */
        el_smooth_params p = c->p[i];
        p.x0 = p.y0 = p.phi = 0.0;
        const double sv[2] = {0.0, p.length};
        double xy[4], t[2];
        const int rc = el_smooth_eval(&p, 2, sv, xy, t, NULL);
        if (rc) return rc;
        const double phi = th - t[0], cs = cos(phi), sn = sin(phi);
        c->p[i].x0 = x0;
        c->p[i].y0 = y0;
        c->p[i].phi = phi;
        x0 += cs * xy[2] - sn * xy[3];
        y0 += sn * xy[2] + cs * xy[3];
        th = t[1] + phi;
    }
    end[0] = x0;
    end[1] = y0;
    end[2] = th;
    return EL_OK;
}

static int chain_res(const hframe *fr, chain *c, const double *x, double r[3])
{
    double e[3];
    const int rc = set_unknowns(fr, c, x, e);
    if (rc) return rc;
    r[0] = (e[0] - fr->p1[0]) / fr->d;
    r[1] = (e[1] - fr->p1[1]) / fr->d;
    r[2] = wrap(e[2] - fr->psi1);
    return EL_OK;
}

static double maxabs3(const double r[3]) { return fmax(fabs(r[0]), fmax(fabs(r[1]), fabs(r[2]))); }

/* Gauss-Newton on the unknowns for the three end conditions (the minimum-norm step
 * J^T (J J^T)^-1 r when there are four unknowns: three pieces), central differences,
 * a step kept only when it reduces the largest end error (halved up to four times).
 * The last unknown is taken in the normalised frame's units (length / d, mu d^2), as
 * the phases are: J J^T squares the columns, and a column of mu ~ 1 / d^2 fell below
 * the phases' rounding there (the loop of a U at |p1 - p0| = 1e-3: the step missed mu
 * and the chain stopped at 7e-9, the curve counted unrepresentable). */
static int correct(const hframe *fr, chain *c, double tol)
{
    const int m = nunknowns(c);
    const double xs = c->mode == EL_HERMITE_TENSION ? fr->d : 1.0 / (fr->d * fr->d);
    double x[MAXUNK], r[3];
    get_unknowns(c, x);
    int rc = chain_res(fr, c, x, r);
    if (rc) return rc;
    for (int it = 0; it < 10 && maxabs3(r) > 1e-3 * tol; it++) {
        double J[3 * MAXUNK];
        for (int j = 0; j < m; j++) {
            const double h = 1e-7 * (fabs(x[j]) + (j < c->n ? 1.0 : 0.0)), v = x[j];
            double rp[3], rm[3];
            x[j] = v + h;
            int e1 = chain_res(fr, c, x, rp);
            x[j] = v - h;
            int e2 = chain_res(fr, c, x, rm);
            x[j] = v;
            if (e1 || e2) return e1 ? e1 : e2;
            for (int i = 0; i < 3; i++) J[i * m + j] = (rp[i] - rm[i]) / (2.0 * h) * (j == c->n ? xs : 1.0);
        }
        /* (J J^T) y = -r, dx = J^T y (LU) */
        double A[9], y[3], b[3];
        for (int i = 0; i < 3; i++) {
            b[i] = -r[i];
            for (int k = 0; k < 3; k++) {
                double sum = 0.0;
                for (int j = 0; j < m; j++) sum += J[i * m + j] * J[k * m + j];
                A[i * 3 + k] = sum;
            }
        }
        int perm[3];
        if (el__lu_factor(A, 3, perm)) break;
        memcpy(y, b, sizeof y);
        el__lu_solve(A, 3, perm, y);
        double dx[MAXUNK];
        for (int j = 0; j < m; j++) {
            dx[j] = 0.0;
            for (int i = 0; i < 3; i++) dx[j] += J[i * m + j] * y[i];
            if (j == c->n) dx[j] *= xs;
        }
        int better = 0;
        for (int h = 0; h < 5 && !better; h++) {
            double xn[MAXUNK], rn[3];
            for (int j = 0; j < m; j++) xn[j] = x[j] + dx[j];
            if (!chain_res(fr, c, xn, rn) && maxabs3(rn) < maxabs3(r)) {
                memcpy(x, xn, sizeof x);
                memcpy(r, rn, sizeof r);
                better = 1;
            }
            for (int j = 0; j < m; j++) dx[j] *= 0.5;
        }
        if (!better) break;
    }
    return chain_res(fr, c, x, r);   /* leaves the chain at x */
}

/* (k~'^2 - k'^2) / k'^2 for the double kt, k'^2 = kc2 exact: how much stronger than the
 * exact one the far loop's tail is in an inflectional piece of modulus kt (-1 at kt = 1). */
static double tail_error_infl(double kt, double kc2) { return ((1.0 - kt) * (1.0 + kt) - kc2) / kc2; }

/* The double n steps (-1, 0, 1) from k. */
static double step_double(double k, int n) { return n > 0 ? nextafter(k, 2.0 * k) : n < 0 ? nextafter(k, 0.0) : k; }

/* The pieces of an inflectional curve (k = |p.k| rounded, its quarter period K exact):
 * the saddles u = (2j + 1) K inside (q, q + sqrt(mu) L) split it; a piece whose
 * loop is the j-th (centre u = 2 j K) has phase q - 2 j K and k (-1)^j |k|.
 * off (the G2 chain, two pieces; NULL: none): the pieces' moduli are off[0], off[1]
 * doubles from the nearest to the exact |k| (complement kc2). About the saddle
 * (cn(K + v) = -k' sd v) the first piece's curvature is off by -(kA'^2 - k'^2) e^(u - K)
 * kappa_m / 8, growing towards the joint, the second's by (kB'^2 - k'^2) e^(K - u)
 * kappa_m / 8, falling from it: where the two errors (tail_error_infl) have opposite
 * signs they are equal at e^(2 t) = -dB / dA, t past the saddle, where the joint starts
 * (g2_joint moves it on). */
static int split_inflectional(const el_smooth_params *p, double K, double kc2, const int *off, chain *c)
{
    const double u0 = p->q, u1 = u0 + sqrt(p->mu) * p->length, eps = 1e-9 * (u1 - u0);
    double b[MAXPIECES + 1];
    int nb = 0;
    b[nb++] = u0;
    for (double j = ceil((u0 / K - 1.0) / 2.0); (2.0 * j + 1.0) * K < u1 - eps; j++) {
        if ((2.0 * j + 1.0) * K <= u0 + eps) continue;
        if (nb == MAXPIECES) return EL_EDOM;          /* more than a period: not a solution */
        b[nb++] = (2.0 * j + 1.0) * K;
    }
    b[nb] = u1;
    double km[2] = {fabs(p->k), fabs(p->k)}, bm[MAXPIECES + 1];
    memcpy(bm, b, sizeof bm);
    if (off) {
        if (nb != 2 || !(kc2 > 0.0)) return EL_EDOM;
        const double k0 = sqrt(1.0 - kc2);
        double kn = k0;
        for (int i = -1; i <= 1; i += 2)
            if (fabs(tail_error_infl(step_double(k0, i), kc2)) < fabs(tail_error_infl(kn, kc2))) kn = step_double(k0, i);
        km[0] = step_double(kn, off[0]);
        km[1] = step_double(kn, off[1]);
        if (km[0] > 1.0 || km[1] > 1.0) return EL_EDOM;
        const double t = 0.5 * log(-tail_error_infl(km[1], kc2) / tail_error_infl(km[0], kc2));
        if (isfinite(t) && b[1] + t > b[0] + eps && b[1] + t < b[2] - eps) bm[1] = b[1] + t;
    }
    c->n = nb;
    for (int i = 0; i < nb; i++) {
        const double ctr = 2.0 * K * nearbyint((b[i] + b[i + 1]) / (4.0 * K));
        const int odd = fmod(fabs(nearbyint((b[i] + b[i + 1]) / (4.0 * K))), 2.0) == 1.0;
        c->p[i] = *p;
        c->p[i].k = odd ? -km[i % 2] : km[i % 2];
        c->p[i].q = bm[i] - ctr;
        c->uend[i] = bm[i + 1] - ctr;
        c->p[i].length = (bm[i + 1] - bm[i]) / sqrt(p->mu);
    }
    return nb > 1 ? EL_OK : EL_EDOM;
}

/* e^(2 (K - K~)) - 1 for a loop piece of modulus |kt| (the double), K the exact quarter
 * period (parameter 1/|k|): how much stronger than the exact one the far loop's tail
 * is at the same distance in that piece's formula (-1 for the separatrix, no tail). */
static double tail_error(double kt, double K)
{
    const double mc2 = (kt - 1.0) * (kt + 1.0) / (kt * kt);
    double Kt, D;
    if (!(mc2 > 0.0) || el__ellint_complete(1.0 / kt, mc2, &Kt, &D)) return -1.0;
    return expm1(2.0 * (K - Kt));
}

/* The two pieces of a loop passing one saddle v = (2j + 1) K (v = |k| u, K of the
 * parameter 1/|k|, exact with mc2 = 1 - 1/k^2): the pieces' curvature error is the far
 * tail's, c e^-(distance to the far loop) with c = tail_error; both bend the same way,
 * so with the doubles on either side of |k| (c of opposite signs) the joint at
 * v = (2j + 1) K + ln(-c_B / c_A) / 2 balances their integrals (the turning error). */
static int split_loop(const el_smooth_params *p, double K, double mc2, const int *off, chain *c)
{
    const double ak = fabs(p->k), sg = p->k > 0.0 ? 1.0 : -1.0;
    const double v0 = ak * p->q, v1 = v0 + ak * sqrt(p->mu) * p->length, eps = 1e-9 * (v1 - v0);
    const double j = ceil((v0 / K - 1.0) / 2.0), vs = (2.0 * j + 1.0) * K;
    if (!(vs > v0 + eps && vs < v1 - eps)) return EL_EDOM;
    /* the double on the other side of the exact |k| (mc2 of the double above mc2: above |k|) */
    const double kd = (ak - 1.0) * (ak + 1.0) / (ak * ak) > mc2 ? nextafter(ak, 0.0) : nextafter(ak, 2.0);
    const double dA = tail_error(ak, K), dB = tail_error(kd, K), r = -dB / dA;
    /* the balanced pair leaves errors of the size sqrt(|dA dB|) at the joint, which
     * bend nothing further; the nearest double alone, 2 |dA| in the turning, which the
     * distance to the end (~K) multiplies. Far below the doubles' spacing (k' << 1e-8)
     * dB is huge and the nearest, k = 1, is better. */
    const int balance = r > 0.0 && isfinite(r) && fabs(dB) < fabs(dA) * K * K;
    double kA = ak, kB = balance ? kd : ak, vj = balance ? vs + 0.5 * log(r) : vs;
    if (off) {
        /* the G2 chain: off[0], off[1] doubles from the nearest to the exact |k|; the far
         * tails' errors, dA e^(v - vs) and dB e^(vs - v), equal at e^(2 t) = dB / dA */
        double kn = ak;
        for (int i = -1; i <= 1; i += 2)
            if (fabs(tail_error(step_double(ak, i), K)) < fabs(tail_error(kn, K))) kn = step_double(ak, i);
        kA = step_double(kn, off[0]);
        kB = step_double(kn, off[1]);
        if (kA < 1.0 || kB < 1.0) return EL_EDOM;
        const double t = 0.5 * log(tail_error(kB, K) / tail_error(kA, K));
        vj = isfinite(t) ? vs + t : vs;
    }
    if (!(vj > v0 + eps && vj < v1 - eps)) vj = vs;
    const double cA = 2.0 * j * K, cB = cA + 2.0 * K;
    c->n = 2;
    c->p[0] = c->p[1] = *p;
    c->p[0].k = sg * kA;
    c->p[0].q = (v0 - cA) / kA;
    c->uend[0] = (vj - cA) / kA;
    c->p[0].length = (vj - v0) / (kA * sqrt(p->mu));
    c->p[1].k = sg * kB;
    c->p[1].q = (vj - cB) / kB;
    c->p[1].length = p->length - c->p[0].length;
    return EL_OK;
}

/* The curvature's largest value on the chain (kappa_m = 2 |k| sqrt(mu) where a piece
 * holds its own loop's centre, u = 0, else the largest at the pieces' ends) and the
 * jump at its first joint. */
static int joint_jump(const chain *c, double *jump, double *kmax)
{
    double ka[MAXPIECES][2];
    *kmax = 0.0;
    for (int i = 0; i < c->n; i++) {
        const el_smooth_params *p = &c->p[i];
        const double sv[2] = {0.0, p->length};
        const int rc = el_smooth_eval(p, 2, sv, NULL, NULL, ka[i]);
        if (rc) return rc;
        *kmax = fmax(*kmax, fmax(fabs(ka[i][0]), fabs(ka[i][1])));
        if (p->q <= 0.0 && p->q + sqrt(p->mu) * p->length >= 0.0) *kmax = fmax(*kmax, 2.0 * fabs(p->k) * sqrt(p->mu));
    }
    if (!(*kmax > 0.0)) return EL_EDOM;
    *jump = ka[1][0] - ka[0][1];
    return EL_OK;
}

/* The two-piece chain with its joint moved by t (in u) from c->base's, then corrected
 * (correct, the joint's end phase held): its curvature jump over the largest. */
typedef struct {
    const hframe *fr;
    chain base, c;
} g2_ctx;

static double moved_jump(double t, void *params)
{
    g2_ctx *g = params;
    g->c = g->base;
    chain *c = &g->c;
    c->uend[0] += t;
    c->p[0].length += t / sqrt(c->p[0].mu);
    c->p[1].q += t;
    c->p[1].length -= t / sqrt(c->p[1].mu);
    double jump, kmax;
    if (!(c->p[0].length > 0.0) || !(c->p[1].length > 0.0) || correct(g->fr, c, 0.0) ||
        joint_jump(c, &jump, &kmax))
        return NAN;
    return jump / kmax;
}

/* A two-piece chain (pieces of different moduli, split_inflectional's, or the same,
 * split_loop's with g2) made G2: its joint moved where the curvature's jump, with the
 * ends met at each position, changes sign (stepping out from the start, 0.05 to 6.4 in
 * u each way), then by GSL's Brent to the rounding of the jump. *c gets the chain. */
static int g2_joint(const hframe *fr, chain *c)
{
    g2_ctx g = {fr, *c, *c};
    const double lo = -0.9 * (c->uend[0] - c->p[0].q), hi = 0.9 * sqrt(c->p[1].mu) * c->p[1].length;
    const double j0 = moved_jump(0.0, &g);
    if (!isfinite(j0)) return EL_EDOM;
    if (j0 == 0.0) { *c = g.c; return EL_OK; }
    double a = NAN, b = NAN;
    for (double h = 0.05; h < 7.0 && isnan(a); h *= 2.0)
        for (int sg = -1; sg <= 1 && isnan(a); sg += 2) {
            const double t = sg * h;
            if (!(t > lo && t < hi)) continue;
            const double jt = moved_jump(t, &g);
            if (isfinite(jt) && (jt < 0.0) != (j0 < 0.0)) { a = fmin(0.0, t); b = fmax(0.0, t); }
        }
    if (isnan(a)) return EL_EDOM;
    gsl_function fn = {moved_jump, &g};
    gsl_root_fsolver *s = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
    if (!s) return EL_ENOMEM;
    int st = gsl_root_fsolver_set(s, &fn, a, b) == GSL_SUCCESS ? EL_OK : EL_EDOM;
    for (int it = 0; it < 100 && !st; it++) {
        if (gsl_root_fsolver_iterate(s) != GSL_SUCCESS) st = EL_EDOM;
        else if (gsl_root_test_interval(gsl_root_fsolver_x_lower(s), gsl_root_fsolver_x_upper(s), 1e-14, 0.0) ==
                 GSL_SUCCESS)
            break;
    }
    const double t = gsl_root_fsolver_root(s);
    gsl_root_fsolver_free(s);
    if (st || !isfinite(moved_jump(t, &g))) return EL_EDOM;
    *c = g.c;
    return EL_OK;
}

/* The G2 chain's moduli tried, in doubles from the nearest to the exact |k| (first,
 * second piece). */
enum { G2_TRIES = 9 };
static const int G2_MODULI[G2_TRIES][2] = {{0, 0}, {0, 1}, {0, -1}, {1, 0}, {-1, 0}, {1, 1}, {-1, -1}, {1, -1}, {-1, 1}};

/* The chain of s, its joints at the saddles (g2 = 0), or (g2 = 1..G2_TRIES, two pieces of
 * the moduli G2_MODULI[g2 - 1]) moved until the curvature is continuous there too
 * (g2_joint), into *out, *jump its curvature jump (two pieces, else 0) and *kmax its
 * largest curvature (joint_jump); EL_EDOM where it is no better than s. */
static int build_chain(const hframe *fr, int mode, double target, double sep, double tol, int g2,
                       const el_hermite_solution *s, el_hermite_solution *out, double *jump, double *kmax)
{
    const el_smooth_params *p = &s->curve;
    /* in sep's frame, scaled by 2^-ilogb(d) (exactly): fr->e^2 = 2^(2 ilogb(d)), a power of two
     * as ldexp's (and rounded as it where it underflows or overflows) */
    const double e2 = fr->e * fr->e, Fn = 2.0 * p->mu * e2, sigma = s->sigma * e2, km2 = Fn + sigma;
    if (!(Fn > 0.0) || !(km2 > 0.0) || !(sep != 0.0)) return EL_EDOM;
    chain c;
    memset(&c, 0, sizeof c);
    c.mode = mode;
    c.L = p->length;
    int rc;
    double K, D;
    if (sep > 0.0) {                                  /* inflectional: k'^2 = (|F| - sigma) / (2 |F|) */
        if ((rc = el__ellint_complete(fmin(fabs(p->k), 1.0), sep / (2.0 * Fn), &K, &D))) return rc;
        rc = split_inflectional(p, K, sep / (2.0 * Fn), g2 ? G2_MODULI[g2 - 1] : NULL, &c);
    } else {                                          /* loop: 1 - 1/k^2 = (sigma - |F|) / kappa_m^2 */
        const double mc2 = -sep / km2;
        if ((rc = el__ellint_complete(fmin(1.0 / fabs(p->k), 1.0), mc2, &K, &D))) return rc;
        rc = split_loop(p, K, mc2, g2 ? G2_MODULI[g2 - 1] : NULL, &c);
    }
    if (rc) return rc;
    if (g2 && c.n != 2) return EL_EDOM;
    /* tension mode: each piece's mu gives the tension exactly with its own k */
    for (int i = 0; i < c.n && mode == EL_HERMITE_TENSION; i++)
        c.p[i].mu = target / (2.0 * (2.0 * c.p[i].k * c.p[i].k - 1.0));
    if ((rc = g2 ? g2_joint(fr, &c) : correct(fr, &c, tol))) return rc;
    /* one elastica: one force F, its direction phi in every piece. set_unknowns places each
     * piece by the tangent (G1), so a phase the correction moved far turns the piece's F:
     * on near-straight chains (tangents -1e-6, +1e-6 rad off a chord at 0.3 rad, sigma
     * |p1 - p0|^2 = 1e5) phi 22.29 and 46.88, 6.3 rad apart mod 2 pi, the ends met */
    for (int i = 1; i < c.n; i++)
        if (!(fabs(wrap(c.p[i].phi - c.p[0].phi)) <= CHAIN_PHI)) return EL_EDOM;
    *jump = *kmax = 0.0;
    if (c.n == 2 && (rc = joint_jump(&c, jump, kmax))) return rc;
    /* the result, measured: start of the first piece, end of the last, and the joints */
    el_hermite_solution t = *s;
    t.npieces = c.n;
    t.curve = c.p[0];
    memset(t.rest, 0, sizeof t.rest);
    double res = 0.0, prev[3] = {fr->p0[0], fr->p0[1], fr->psi0}, E = 0.0;
    t.length = 0.0;
    for (int i = 0; i < c.n; i++) {
        if (i > 0) t.rest[i - 1] = c.p[i];
        const double sv[2] = {0.0, c.p[i].length};
        double xy[4], th[2], ka[2], e;
        if ((rc = el_smooth_eval(&c.p[i], 2, sv, xy, th, ka)) || (rc = el_smooth_energy(&c.p[i], &e)))
            return rc;
        res = fmax(res, fmax(hypot(xy[0] - prev[0], xy[1] - prev[1]) / fr->d, fabs(wrap(th[0] - prev[2]))));
        prev[0] = xy[2];
        prev[1] = xy[3];
        prev[2] = th[1];
        if (i == 0) t.kappa0 = ka[0];
        t.kappa1 = ka[1];
        E += e;
        t.length += c.p[i].length;
    }
    res = fmax(res, fmax(hypot(prev[0] - fr->p1[0], prev[1] - fr->p1[1]) / fr->d, fabs(wrap(prev[2] - fr->psi1))));
    if (!(res < s->residual)) return EL_EDOM;
    t.residual = res;
    t.energy = E;
    if (mode == EL_HERMITE_LENGTH) {
        t.length = target;
        t.sigma = 2.0 * c.p[0].mu * (2.0 * c.p[0].k * c.p[0].k - 1.0);
    }
    *out = t;
    return EL_OK;
}

/* The chain split at the saddles, or where its curvature jumps at the joint by more than
 * both OWN_JUMP of the chain's largest curvature and KM_JUMP of kappa_m = 2 |k| sqrt(mu)
 * (the doubles' k leave a piece's far tail off by ~1e-16 / k' of kappa_m, at most ~1e-8
 * where k rounds to 1; on a near-straight curve, whose largest curvature is ~k' kappa_m,
 * that is 1e-3 of it and more), the G2 chain (g2_joint) if it meets tol with a smaller
 * jump. Measured on near-straight curves (tangents 1e-9 to 1e-3 rad off the chord, sigma
 * |p1 - p0|^2 10 to 3000): split_loop's pairs jumped by up to 2.3e-7 of kappa_m (0.6 of
 * their own largest curvature), the inflectional chains by up to 2.9e-8. Against 90-digit
 * solutions both lie up to ~3e-9 |p1 - p0| off the exact curve there, their curvature a
 * few % off (the far tail is not resolved): of 8 replaced chains the G2 one had the
 * smaller largest curvature error in 5, the smaller distance in 3. Below the bound the
 * chain split at the saddles is kept: a G2 chain there lies further from the exact curve
 * (kappa0 2 to 500 times, the points up to 10 times, up to 5e-9 |p1 - p0|). */
#define OWN_JUMP 5e-8
#define KM_JUMP 1e-8
int el__hermite_chain(const hframe *fr, int mode, double target, double sep, double tol,
                      el_hermite_solution *s)
{
    el_hermite_solution a = *s, b;
    double ja = 0.0, jb = 0.0, ka = 0.0, kb;
    const int ra = build_chain(fr, mode, target, sep, tol, 0, s, &a, &ja, &ka);
    const double allowed = fmax(OWN_JUMP * ka, KM_JUMP * 2.0 * fabs(a.curve.k) * sqrt(a.curve.mu));
    if (!ra && fabs(ja) <= allowed) { *s = a; return EL_OK; }
    int best = ra ? 0 : -1;   /* 0: none; -1: a; 1: b */
    for (int g2 = 1; g2 <= G2_TRIES && !(best == 1 && fabs(ja) <= 1e-3 * allowed); g2++) {
        el_hermite_solution t;
        if (!build_chain(fr, mode, target, sep, tol, g2, s, &t, &jb, &kb) && t.residual <= tol &&
            (best == 0 || fabs(jb) < fabs(ja))) {
            b = t;
            ja = jb;
            best = 1;
        }
    }
    if (best == 0) return ra;
    *s = best == 1 ? b : a;
    return EL_OK;
}
