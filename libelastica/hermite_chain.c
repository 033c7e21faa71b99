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
 */
#include "hermite_internal.h"
#include <gsl/gsl_linalg.h>
#include <string.h>

enum { MAXPIECES = 3, MAXUNK = MAXPIECES + 1 };

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
 * a step kept only when it reduces the largest end error (halved up to four times). */
static int correct(const hframe *fr, chain *c, double tol)
{
    const int m = nunknowns(c);
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
            for (int i = 0; i < 3; i++) J[i * m + j] = (rp[i] - rm[i]) / (2.0 * h);
        }
        /* (J J^T) y = -r, dx = J^T y (LU, GSL) */
        double A[9], y[3], b[3];
        for (int i = 0; i < 3; i++) {
            b[i] = -r[i];
            for (int k = 0; k < 3; k++) {
                double sum = 0.0;
                for (int j = 0; j < m; j++) sum += J[i * m + j] * J[k * m + j];
                A[i * 3 + k] = sum;
            }
        }
        gsl_matrix_view Am = gsl_matrix_view_array(A, 3, 3);
        gsl_vector_view bv = gsl_vector_view_array(b, 3), yv = gsl_vector_view_array(y, 3);
        size_t perm_data[3];
        gsl_permutation perm = {3, perm_data};
        int signum;
        /* a zero pivot: singular, which LU_solve would report to GSL's error handler */
        if (gsl_linalg_LU_decomp(&Am.matrix, &perm, &signum) != GSL_SUCCESS ||
            A[0] == 0.0 || A[4] == 0.0 || A[8] == 0.0 ||
            gsl_linalg_LU_solve(&Am.matrix, &perm, &bv.vector, &yv.vector) != GSL_SUCCESS)
            break;
        double dx[MAXUNK];
        for (int j = 0; j < m; j++) {
            dx[j] = 0.0;
            for (int i = 0; i < 3; i++) dx[j] += J[i * m + j] * y[i];
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

/* The pieces of an inflectional curve (k = |p.k| rounded, its quarter period K exact):
 * the saddles u = (2j + 1) K inside (q, q + sqrt(mu) L) split it; a piece whose
 * loop is the j-th (centre u = 2 j K) has phase q - 2 j K and k (-1)^j |k|. */
static int split_inflectional(const el_smooth_params *p, double K, chain *c)
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
    c->n = nb;
    for (int i = 0; i < nb; i++) {
        const double ctr = 2.0 * K * nearbyint((b[i] + b[i + 1]) / (4.0 * K));
        const int odd = fmod(fabs(nearbyint((b[i] + b[i + 1]) / (4.0 * K))), 2.0) == 1.0;
        c->p[i] = *p;
        c->p[i].k = odd ? -fabs(p->k) : fabs(p->k);
        c->p[i].q = b[i] - ctr;
        c->uend[i] = b[i + 1] - ctr;
        c->p[i].length = (b[i + 1] - b[i]) / sqrt(p->mu);
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
static int split_loop(const el_smooth_params *p, double K, double mc2, chain *c)
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
    const double kA = ak, kB = balance ? kd : ak;
    double vj = balance ? vs + 0.5 * log(r) : vs;
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

int el__hermite_chain(const hframe *fr, int mode, double target, double sep, double tol,
                      el_hermite_solution *s)
{
    const el_smooth_params *p = &s->curve;
    const double Fn = 2.0 * p->mu, sigma = s->sigma, km2 = Fn + sigma;
    if (!(Fn > 0.0) || !(km2 > 0.0) || !(sep != 0.0)) return EL_EDOM;
    chain c;
    memset(&c, 0, sizeof c);
    c.mode = mode;
    c.L = p->length;
    int rc;
    double K, D;
    if (sep > 0.0) {                                  /* inflectional: k'^2 = (|F| - sigma) / (2 |F|) */
        if ((rc = el__ellint_complete(fmin(fabs(p->k), 1.0), sep / (2.0 * Fn), &K, &D))) return rc;
        rc = split_inflectional(p, K, &c);
    } else {                                          /* loop: 1 - 1/k^2 = (sigma - |F|) / kappa_m^2 */
        const double mc2 = -sep / km2;
        if ((rc = el__ellint_complete(fmin(1.0 / fabs(p->k), 1.0), mc2, &K, &D))) return rc;
        rc = split_loop(p, K, mc2, &c);
    }
    if (rc) return rc;
    /* tension mode: each piece's mu gives the tension exactly with its own k */
    for (int i = 0; i < c.n && mode == EL_HERMITE_TENSION; i++)
        c.p[i].mu = target / (2.0 * (2.0 * c.p[i].k * c.p[i].k - 1.0));
    if ((rc = correct(fr, &c, tol))) return rc;
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
    *s = t;
    return EL_OK;
}
