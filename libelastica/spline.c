/*
 * Elastic splines (issue 14): a chain of smooth elasticae of one tension
 * through N points, G2 at every point.
 *
 * Unknowns. Each piece j (from P_j to P_{j+1}) has its start point fixed and
 * five parameters v = (phi, nu = ln mu, k, q, L) of the smooth elastica
 * (header, smooth section; ln mu keeps mu > 0). Its residuals, for the target
 * tangent angles ta at P_j, tb at P_{j+1} and tension s,
 *   R = ( (gamma(L) - P_{j+1}) / h,  theta(0) - ta,  theta(L) - tb,
 *         (2 mu (2k^2 - 1) - s) h^2 )                     (h = |P_{j+1} - P_j|)
 * vanish for the Hermite elastica of tension s (seed 004; sigma = 2 mu (2k^2 - 1)
 * is the tension of the curvature equation 2 kappa'' + kappa^3 - sigma kappa = 0).
 * The knot unknowns x_i are the tangent angles at the points, except at a
 * clamped end (fixed) and at a G2 end, where x is the tension of the end span.
 * The knot equations are the curvature jumps
 *   F_i = (kappa_i^- - kappa_i^+) l_i,   l_i = mean chord at P_i,
 * with kappa^- = the given curvature (0: natural) at the first point and
 * kappa^+ = the given one at the last; in length mode also
 *   G = (sum L_j - L) / L   with the common sigma unknown.
 *
 * Newton on (x, sigma, all v) at once, eliminating every piece's own five
 * unknowns (the implicit function theorem step): with J = dR/dv (5x5),
 * dR/dta = -e2, dR/dtb = -e3, dR/ds = -h^2 e4,
 *   dv = -J^{-1} R + J^{-1} e2 dta + J^{-1} e3 dtb + h^2 J^{-1} e4 ds,
 * so d kappa(0) = g0 . dv and d kappa(L) = g1 . dv (g = gradients of the end
 * curvatures in v, below) are linear in the x and sigma of the two knots the
 * piece joins: the knot system is tridiagonal (cyclic when closed, bordered by
 * the sigma column and the length row in length mode), solved by GSL in O(n).
 * At R = 0 the coefficients are exactly d kappa / d(angle) of the Hermite
 * piece (implicit function theorem); with R != 0 this is Newton on the whole
 * system, so pieces follow the previous iterate's branch with no inner loop.
 * Globalisation: steps limited in nu, L, k and the angles, then halved until
 * the merit |F|^2 + |R|^2 + G^2 decreases (Armijo), at most 12 halvings.
 *
 * Derivatives (u = sqrt(mu) s + q, w = sqrt(mu), the Jacobi functions at
 * modulus |k|, d/d|k| from el_jacobi_eval, identities d sn/du = cn dn,
 * d cn/du = -sn dn, dn^2 + k^2 sn^2 = 1 for every real k):
 *   a = (theta - phi)/2 = atan2(k sn, dn):  da/du = k cn,
 *       da/dk = dn (sn + |k| sn_|k|) - |k| sn dn_|k|;
 *   kappa = 2 k w cn:  d/dnu = kappa/2 - k w^2 s sn dn, d/dk = 2 w (cn + |k| cn_|k|),
 *       d/dq = -2 k w sn dn, d/ds = -2 k w^2 sn dn;
 *   theta(L) = phi + 2 a(u1): d/dnu = k cn w L, d/dq = 2 k cn, d/dL = kappa(L);
 *   gamma(L) = P + R(phi)(X, Y), X = (u1 - q - 2k^2 (D(u1) - D(q)))/w,
 *       Y = -2k (cn u1 - cn q)/w: d/dphi = R(phi)(-Y, X), d/dnu = R(phi)(L T - (X,Y))/2
 *       with T = (1 - 2k^2 sn^2, 2k sn dn)(u1) (the unit tangent in the frame), as
 *       el_smooth_jacobian (the tests compare every column with it and with
 *       finite differences).
 * Forces (seed 004 (9)-(10)): for the Lagrangian integral kappa^2 + sigma ds
 * with the constraint gamma' = T, the multiplier F_EL satisfies
 * 2 kappa' = F_EL . N and kappa^2 - F_EL . T = sigma (its derivative is
 * 2 kappa kappa' - kappa F_EL . N = 0; differentiating again gives the curvature
 * equation), so F_EL = (kappa^2 - sigma) T + 2 kappa' N is constant, |F_EL| = 2 mu
 * = kappa_m^2 - sigma, along phi. The batten's internal force (Kirchhoff:
 * EI kappa' = -n . N, the part after a section on the part before, EI = 2 in
 * these units) is n = -F_EL: the header's F.
 *
 * Start: angles of the circles through three consecutive points (natural ends:
 * the cubic's alpha = -beta/2), each piece from the linearised batten at its
 * tension (w'''' = (sigma/2) w'' with the end slopes; the elastica through its
 * midpoint state, as in seed 004 (13)), solved alone by the same Newton, and
 * by el_hermite_solve (least energy, same turning) where that fails. If the
 * spline Newton fails there: continuation in sigma from a high tension (the
 * pieces are then short arcs near the polygon) down to sigma; length mode
 * continues from a tension solution in sigma (bordered Newton), then in length.
 *
 * Internal units: lengths divided by the mean chord (S), so sigma h^2 and the
 * residuals are scale-free; pieces are rescaled on output with x0, y0 the
 * given points exactly.
 */
#include "internal.h"
#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

enum { NV = 5 };                      /* piece unknowns: phi, nu, k, q, L */
enum { V_PHI, V_NU, V_K, V_Q, V_L };
enum { SLOT_ANGLE, SLOT_FIXED, SLOT_TENSION };
enum { MAX_HALVINGS = 12, PIECE_ITER = 40 };
/* Newton iterations of a first attempt and of a continuation step (a solve that
 * needs more is better served by smaller steps) */
enum { DIRECT_ITER = 20, STEP_ITER = 12 };

typedef struct piece {
    double v[NV];
    double dx, dy, h;        /* chord (internal units) */
    double R[NV];            /* residuals at v */
    double th0, th1, kap0, kap1, dkap0;
    double energy, Kq;       /* integral kappa^2 ds; K of the modulus min(|k|, 1/|k|) */
    double st[NV];           /* its start state (theta0, kappa0, kappa0', sigma, L) */
    double M[NV * NV];       /* d st / d v */
    double D[4][NV];         /* J^{-1} R, J^{-1} e2, J^{-1} e3, h^2 J^{-1} e4 */
    double c0[4], c1[4], cL[4];  /* g0 . D[r], g1 . D[r], D[r][L] */
} piece;

/* A piece's Newton step (pstep_prepare). */
typedef struct pstep {
    double v0[NV], s0[NV], ds[NV];   /* parameters and state before, state step */
} pstep;

/* Which unknowns a piece's targets ta, tb, s depend on (slot index, -1: none, -2: sigma). */
typedef struct targets {
    double ta, tb, s;
    long ia, ib, is;
} targets;

typedef struct spline_ws {
    size_t n, m;             /* points, pieces */
    int closed;
    int lmode;               /* sigma unknown, with the border equation: */
#define BORDER_LENGTH 1      /*   the total length */
#define BORDER_ARC 2         /*   the pseudo-arclength step of solve_length */
    int kind[2];             /* open: end kinds */
    double th_end[2], kg[2]; /* clamped angles, G2 curvatures (internal units) */
    double wind;             /* closed: 2 pi times the turning number */
    double sigma, Lt;        /* common tension, target length (internal) */
    double sigma_user;       /* tension mode: the sigma asked for (user units) */
    double *x, *ell;         /* slot values, local chord per knot */
    int *slot;
    piece *pc;
    double *F, *dg, *up, *lo, *b, *y, *z, *col, *row;   /* Newton work, n each */
    double *xs;              /* backup of x */
    pstep *ps;               /* the pieces' Newton steps */
    double Gres;             /* length residual */
    double *snapbuf;         /* the two snapshots' arrays */
    double *arc_a, *arc_x0;  /* BORDER_ARC: arc_a . (x - arc_x0) + arc_b (sigma - arc_s0) = arc_h */
    double arc_b, arc_s0, arc_h;
    double resid;            /* max residual of the last evaluation */
    int iterations, max_iter;
    double tol, aim;         /* accepted and aimed-at residual */
    int near;                /* the state is a solution to what the parametrisation resolves */
} spline_ws;

/* ------------------------------------------------------------------ small dense systems */

/*
 * LU with partial pivoting of the n x n row-major a (n <= NV), in place, and
 * its solve. Written out because GSL's LU sends every triangular solve through
 * BLAS (dtrsv with OpenBLAS's locking), about ten times the arithmetic of a
 * 5 x 5 system, and the spline factors one per piece per Newton iteration.
 * EL_ESINGULAR on a zero (or non-finite) pivot.
 */
static int lu_factor(double *a, int n, int *perm)
{
    for (int c = 0; c < n; c++) {
        int p = c;
        for (int r = c + 1; r < n; r++)
            if (fabs(a[r * n + c]) > fabs(a[p * n + c])) p = r;
        perm[c] = p;
        if (!(fabs(a[p * n + c]) > 1e-300) || !isfinite(a[p * n + c])) return EL_ESINGULAR;
        if (p != c)
            for (int j = 0; j < n; j++) { const double t = a[c * n + j]; a[c * n + j] = a[p * n + j]; a[p * n + j] = t; }
        const double inv = 1.0 / a[c * n + c];
        for (int r = c + 1; r < n; r++) {
            const double f = a[r * n + c] *= inv;
            for (int j = c + 1; j < n; j++) a[r * n + j] -= f * a[c * n + j];
        }
    }
    return EL_OK;
}

static void lu_solve(const double *a, int n, const int *perm, double *b)
{
    for (int c = 0; c < n; c++) {   /* the row exchanges, in order */
        const double t = b[perm[c]]; b[perm[c]] = b[c]; b[c] = t;
    }
    for (int r = 1; r < n; r++)
        for (int c = 0; c < r; c++) b[r] -= a[r * n + c] * b[c];
    for (int r = n - 1; r >= 0; r--) {
        double sum = b[r];
        for (int j = r + 1; j < n; j++) sum -= a[r * n + j] * b[j];
        b[r] = sum / a[r * n + r];
    }
}

/* ------------------------------------------------------------------ one piece */

/* theta - phi = 2a, continuous in u (smooth.c's branch for |k| > 1). */
static double half_angle(double u, double k, double K_reciprocal, const el_jacobi *v)
{
    const double ka = fabs(k);
    double a = atan2(ka * v->sn, v->dn);
    if (ka > 1.0) {
        double npi = M_PI * nearbyint(ka * u / (2.0 * K_reciprocal));
        a += 2.0 * M_PI * nearbyint((npi - a) / (2.0 * M_PI));
    }
    return copysign(1.0, k) * a;
}

/* da/dk of a = atan2(k sn(u;|k|), dn(u;|k|)) (file comment). */
static double half_angle_dk(double k, const el_jacobi *v, const el_jacobi *vk)
{
    const double ka = fabs(k);
    return v->dn * (v->sn + ka * vk->sn) - ka * v->sn * vk->dn;
}

/* Residuals, end angles and curvatures of piece pc for the targets t; with jac,
 * also J, its LU and the eliminated columns D and coefficients c0, c1, cL. */
static int piece_eval_raw(piece *pc, const targets *t, int jac, double *raw);

static int piece_eval(piece *pc, const targets *t, int jac)
{
    return piece_eval_raw(pc, t, jac, NULL);
}

/* piece_eval; raw (when not NULL, with jac): J before its factorisation, then
 * g0, g1 (35 values), for el__spline_piece_jacobians. */
static int piece_eval_raw(piece *pc, const targets *t, int jac, double *raw)
{
    const double phi = pc->v[V_PHI], nu = pc->v[V_NU], k = pc->v[V_K], q = pc->v[V_Q],
                 L = pc->v[V_L];
    if (!isfinite(phi) || !isfinite(nu) || !isfinite(k) || !isfinite(q) || !isfinite(L) ||
        !(L > 0.0) || nu > 700.0 || nu < -700.0)
        return EL_EDOM;
    const double mu = exp(nu), w = sqrt(mu), ka = fabs(k), u1 = w * L + q;
    el__modulus mod;
    el_jacobi a0, a1, k0, k1;
    int st;
    if ((st = el__modulus_init(ka, jac, &mod))) return st;
    if ((st = el__jacobi_eval_mod(&mod, q, &a0, NULL, jac ? &k0 : NULL))) return st;
    if ((st = el__jacobi_eval_mod(&mod, u1, &a1, NULL, jac ? &k1 : NULL))) return st;
    const double c = cos(phi), sp = sin(phi), k2 = k * k;
    const double X = ((u1 - q) - 2.0 * k2 * (a1.D - a0.D)) / w, Y = -2.0 * k * (a1.cn - a0.cn) / w;
    const double gx = c * X - sp * Y - pc->dx, gy = sp * X + c * Y - pc->dy;
    const double h = pc->h, h2 = h * h;
    pc->th0 = phi + 2.0 * half_angle(q, k, mod.K, &a0);
    pc->th1 = phi + 2.0 * half_angle(u1, k, mod.K, &a1);
    pc->kap0 = 2.0 * k * w * a0.cn;
    pc->kap1 = 2.0 * k * w * a1.cn;
    pc->dkap0 = -2.0 * k * mu * a0.sn * a0.dn;
    pc->energy = 4.0 * k2 * w * ((u1 - q) - (a1.D - a0.D));   /* el_smooth_energy */
    pc->Kq = mod.K;
    pc->st[0] = pc->th0;
    pc->st[1] = pc->kap0;
    pc->st[2] = pc->dkap0;
    pc->st[3] = 2.0 * mu * (2.0 * k2 - 1.0);
    pc->st[4] = L;
    pc->R[0] = gx / h;
    pc->R[1] = gy / h;
    pc->R[2] = pc->th0 - t->ta;
    pc->R[3] = pc->th1 - t->tb;
    pc->R[4] = (2.0 * mu * (2.0 * k2 - 1.0) - t->s) * h2;
    for (int i = 0; i < NV; i++)
        if (!isfinite(pc->R[i])) return EL_EDOM;
    if (!jac) return EL_OK;

    const double tx = 1.0 - 2.0 * k2 * a1.sn * a1.sn, ty = 2.0 * k * a1.sn * a1.dn;
    double lx[NV], ly[NV];   /* d(X, Y)/dv in the frame; phi column apart */
    lx[V_PHI] = -Y; ly[V_PHI] = X;
    lx[V_NU] = 0.5 * (L * tx - X); ly[V_NU] = 0.5 * (L * ty - Y);
    lx[V_K] = (-4.0 * k * (a1.D - a0.D) - 2.0 * k * ka * (k1.D - k0.D)) / w;
    ly[V_K] = (-2.0 * (a1.cn - a0.cn) - 2.0 * ka * (k1.cn - k0.cn)) / w;
    lx[V_Q] = -2.0 * k2 * (a1.sn * a1.sn - a0.sn * a0.sn) / w;
    ly[V_Q] = 2.0 * k * (a1.sn * a1.dn - a0.sn * a0.dn) / w;
    lx[V_L] = tx; ly[V_L] = ty;
    double J[NV * NV];
    for (int j = 0; j < NV; j++) {
        J[0 * NV + j] = (c * lx[j] - sp * ly[j]) / h;
        J[1 * NV + j] = (sp * lx[j] + c * ly[j]) / h;
    }
    const double sd0 = a0.sn * a0.dn, sd1 = a1.sn * a1.dn;
    const double th0[NV] = {1.0, 0.0, 2.0 * half_angle_dk(k, &a0, &k0), 2.0 * k * a0.cn, 0.0};
    const double th1[NV] = {1.0, k * a1.cn * w * L, 2.0 * half_angle_dk(k, &a1, &k1),
                            2.0 * k * a1.cn, pc->kap1};
    const double g0[NV] = {0.0, 0.5 * pc->kap0, 2.0 * w * (a0.cn + ka * k0.cn),
                           -2.0 * k * w * sd0, 0.0};
    const double g1[NV] = {0.0, 0.5 * pc->kap1 - k * mu * L * sd1, 2.0 * w * (a1.cn + ka * k1.cn),
                           -2.0 * k * w * sd1, -2.0 * k * mu * sd1};
    const double ten[NV] = {0.0, 2.0 * mu * (2.0 * k2 - 1.0) * h2, 8.0 * mu * k * h2, 0.0, 0.0};
    /* kappa0' = -2 k mu sn dn (q): d/dk = -2 mu (sn dn + |k| (sn dn)_|k|), d/dq = -2 k mu cn (dn^2 - k^2 sn^2) */
    const double dk0[NV] = {0.0, pc->dkap0,
                            -2.0 * mu * (sd0 + ka * (k0.sn * a0.dn + a0.sn * k0.dn)),
                            -2.0 * k * mu * a0.cn * (a0.dn * a0.dn - k2 * a0.sn * a0.sn), 0.0};
    for (int j = 0; j < NV; j++) {
        pc->M[0 * NV + j] = th0[j];
        pc->M[1 * NV + j] = g0[j];
        pc->M[2 * NV + j] = dk0[j];
        pc->M[3 * NV + j] = ten[j] / h2;
        pc->M[4 * NV + j] = j == V_L;
    }
    memcpy(J + 2 * NV, th0, sizeof th0);
    memcpy(J + 3 * NV, th1, sizeof th1);
    memcpy(J + 4 * NV, ten, sizeof ten);

    if (raw) {
        memcpy(raw, J, sizeof J);
        memcpy(raw + NV * NV, g0, sizeof g0);
        memcpy(raw + NV * NV + NV, g1, sizeof g1);
    }
    int perm[NV];
    if (lu_factor(J, NV, perm)) return EL_ESINGULAR;
    for (int r = 0; r < 4; r++) {
        double rhs[NV] = {0};
        if (r == 0) memcpy(rhs, pc->R, sizeof rhs);
        else rhs[r + 1] = r == 3 ? h2 : 1.0;
        lu_solve(J, NV, perm, rhs);
        memcpy(pc->D[r], rhs, sizeof rhs);
        double s0 = 0.0, s1 = 0.0;
        for (int i = 0; i < NV; i++) { s0 += g0[i] * rhs[i]; s1 += g1[i] * rhs[i]; }
        pc->c0[r] = s0;
        pc->c1[r] = s1;
        pc->cL[r] = rhs[V_L];
        if (!isfinite(s0) || !isfinite(s1) || !isfinite(rhs[V_L])) return EL_ESINGULAR;
    }
    return EL_OK;
}

static double max_abs(const double *v, size_t n)
{
    double m = 0.0;
    for (size_t i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

/* Incomplete elliptic integral of the first kind F(psi | k) for |psi| <= pi,
 * 0 <= k <= 1 with kc2 = 1 - k^2 given without cancellation: Carlson,
 * F = sin psi R_F(cos^2 psi, 1 - k^2 sin^2 psi, 1) on |psi| <= pi/2 and
 * F(psi) = 2K - F(pi - psi) beyond (ellint.c; GSL's gsl_sf_ellint_F costs
 * about twice as much). k = 1: |psi| < pi/2 only, F = asinh(tan psi). NaN outside. */
static double ellint_F(double psi, double k, double kc2)
{
    if (!(fabs(psi) <= M_PI)) return NAN;
    if (!(kc2 > 0.0)) return fabs(psi) < 0.5 * M_PI ? asinh(tan(psi)) : NAN;
    const double a = fabs(psi), r = a > 0.5 * M_PI ? M_PI - a : a, sn = sin(r), cs = cos(r);
    double rf, rd, K = 0.0, D;
    if (el__carlson_fd(cs * cs, kc2 + k * k * cs * cs, 1.0, 1.0, &rf, &rd)) return NAN;
    if (a > 0.5 * M_PI && el__ellint_complete(k, kc2, &K, &D)) return NAN;
    const double F = a > 0.5 * M_PI ? 2.0 * K - sn * rf : sn * rf;
    return copysign(F, psi);
}

/* Parameters of the elastica of tension s through a state (theta, kappa,
 * kappa') at arc length sm from the piece's start, the start at u = q. */
static int piece_from_state(piece *pc, double theta, double kappa, double dkappa, double s,
                            double sm, double L)
{
    const double T[2] = {cos(theta), sin(theta)}, N[2] = {-T[1], T[0]};
    const double wv = kappa * kappa - s;
    double Fx = wv * T[0] + 2.0 * dkappa * N[0], Fy = wv * T[1] + 2.0 * dkappa * N[1];
    double Fn = hypot(Fx, Fy);
    /* 1 - k^2 = (Fn - s) / (2 Fn) = (kappa^2 (kappa^2 - 2 s) + 4 kappa'^2) / (2 Fn (Fn + s)),
     * the second form without the cancellation of Fn - s when s > 0 */
    double kc2 = s > 0.0 ? (kappa * kappa * (kappa * kappa - 2.0 * s) + 4.0 * dkappa * dkappa) /
                               (2.0 * Fn * (Fn + s))
                         : (Fn - s) / (2.0 * Fn);
    if (!(Fn > 1e-12 * (fabs(s) + kappa * kappa + 1e-300))) {   /* a circle or a line: a small force along T */
        Fn = 1e-6 * (fabs(s) + kappa * kappa) + 1e-12;
        Fx = -Fn * T[0];
        Fy = -Fn * T[1];
        kc2 = (Fn - s) / (2.0 * Fn);
    }
    if (!(Fn + s > 0.0)) return EL_EDOM;
    const double mu = 0.5 * Fn, phi0 = atan2(Fy, Fx);
    const double k2 = kc2 > 0.0 ? fmin((Fn + s) / (2.0 * Fn), 1.0) : fmax((Fn + s) / (2.0 * Fn), 1.0);
    double d = theta - phi0;
    d -= 2.0 * M_PI * nearbyint(d / (2.0 * M_PI));
    const double a = 0.5 * d, phi = theta - 2.0 * a;   /* theta = phi + 2a exactly */
    double k, u;
    if (kc2 > 0.0) {
        k = sqrt(k2);
        const double psi = atan2(sin(a) / k, kappa / (2.0 * k * sqrt(mu)));
        u = ellint_F(psi, k, kc2);
    } else {
        const double ka = sqrt(k2);
        k = kappa < 0.0 ? -ka : ka;
        /* k = 1 exactly: the separatrix, a = +-pi/2 is at u = infinity (a straight
         * state under tension); start a little inside, on its tail */
        const double am = ka < 1.0 + 1e-12 ? copysign(fmin(fabs(a), 0.5 * M_PI - 1e-8), a) : a;
        /* modulus 1/|k|: its complement 1 - 1/k^2 = -kc2 / k^2 */
        u = ellint_F(k < 0.0 ? -am : am, 1.0 / ka, -kc2 / k2) / ka;
    }
    if (!isfinite(u)) return EL_EDOM;
    pc->v[V_PHI] = phi;
    pc->v[V_NU] = log(mu);
    pc->v[V_K] = k;
    pc->v[V_Q] = u - sqrt(mu) * sm;
    pc->v[V_L] = L;
    return EL_OK;
}

static int piece_set_state(piece *pc, const double *st)
{
    return piece_from_state(pc, st[0], st[1], st[2], st[3], 0.0, st[4]);
}

/*
 * One Newton step of a piece, taken from (v0, st0) along the parameter step dv
 * in its state: st0 + al M dv, converted back in closed form (piece_from_state).
 * The state is a regular coordinate of the pieces, where phi and mu are the
 * polar coordinates of the force, singular at a circle (F = 0, |k| -> infinity):
 * a straight step in (phi, ln mu, k, q, L) crosses it badly. Prepare ps from the
 * piece and dv; return the largest fraction al of the step that keeps the length
 * positive and the state within a factor of its size (in units of the chord).
 */
static double pstep_prepare(const piece *pc, const double *dv, pstep *ps, double al)
{
    memcpy(ps->v0, pc->v, sizeof ps->v0);
    memcpy(ps->s0, pc->st, sizeof ps->s0);
    for (int i = 0; i < NV; i++) {
        double sum = 0.0;
        for (int j = 0; j < NV; j++) sum += pc->M[i * NV + j] * dv[j];
        ps->ds[i] = sum;
    }
    const double h = pc->h, *st = pc->st, *dst = ps->ds;
    const double lim[4] = {0.5, fmax(1.0, 2.0 * fabs(st[1]) * h) / h,
                           fmax(2.0, 2.0 * fabs(st[2]) * h * h) / (h * h),
                           fmax(4.0, 2.0 * fabs(st[3]) * h * h) / (h * h)};
    for (int i = 0; i < 4; i++)
        if (fabs(dst[i]) * al > lim[i]) al = lim[i] / fabs(dst[i]);
    if (dst[4] < 0.0 && -dst[4] * al > 0.75 * st[4]) al = 0.75 * st[4] / -dst[4];
    return al;
}

static int pstep_apply(piece *pc, const pstep *ps, double al)
{
    double sn[NV];
    for (int i = 0; i < NV; i++) sn[i] = ps->s0[i] + al * ps->ds[i];
    return piece_set_state(pc, sn);
}

/* The piece alone (fixed targets): Newton on R, stepping in the state. */
static int piece_newton(piece *pc, const targets *t, double tol)
{
    int st = piece_eval(pc, t, 1);
    if (st) return st;
    double r = max_abs(pc->R, NV);
    for (int it = 0; it < PIECE_ITER && r > tol; it++) {
        double dv[NV];
        pstep ps;
        for (int i = 0; i < NV; i++) dv[i] = -pc->D[0][i];
        double al = pstep_prepare(pc, dv, &ps, 1.0);
        int ok = 0;
        for (int hv = 0; hv <= MAX_HALVINGS; hv++, al *= 0.5) {
            if (pstep_apply(pc, &ps, al) || piece_eval(pc, t, 1)) continue;
            const double rn = max_abs(pc->R, NV);
            if (rn < (1.0 - 1e-4 * al) * r) { r = rn; ok = 1; break; }
        }
        if (!ok) {
            memcpy(pc->v, ps.v0, sizeof ps.v0);
            piece_eval(pc, t, 1);
            break;
        }
    }
    return r <= tol ? EL_OK : EL_ENOCONV;
}

/* The linearised batten on the chord: w'''' = (s/2) w'' with w = 0 at both ends
 * and slopes tan(alpha), tan(beta); its midpoint state starts the piece. */
static int piece_start(piece *pc, const targets *t)
{
    const double h = pc->h, c0 = atan2(pc->dy, pc->dx);
    const double c = c0 + 2.0 * M_PI * nearbyint((0.5 * (t->ta + t->tb) - c0) / (2.0 * M_PI));
    const double al = t->ta - c, be = t->tb - c;
    const double sa = tan(fmax(fmin(al, 1.3), -1.3)), sb = tan(fmax(fmin(be, 1.3), -1.3));
    const double om = t->s > 0.0 ? sqrt(0.5 * t->s) : 0.0;
    /* w = A + B s + C f1 + D f2: f = (e^{-om s}, e^{-om (h-s)}) or (s^2, s^3) */
    const int ex = om * h > 0.1;
    double M[16], rhs[4] = {0.0, 0.0, sa, sb};
    for (int e = 0; e < 2; e++) {
        const double s = e ? h : 0.0;
        double b1[4], b2[4];
        if (ex) {
            const double e1 = exp(-om * s), e2 = exp(-om * (h - s));
            for (int d = 0; d < 4; d++) {
                b1[d] = e1 * pow(-om, d);
                b2[d] = e2 * pow(om, d);
            }
        } else {
            b1[0] = s * s; b1[1] = 2.0 * s; b1[2] = 2.0; b1[3] = 0.0;
            b2[0] = s * s * s; b2[1] = 3.0 * s * s; b2[2] = 6.0 * s; b2[3] = 6.0;
        }
        M[(0 + e) * 4 + 0] = 1.0; M[(0 + e) * 4 + 1] = s; M[(0 + e) * 4 + 2] = b1[0]; M[(0 + e) * 4 + 3] = b2[0];
        M[(2 + e) * 4 + 0] = 0.0; M[(2 + e) * 4 + 1] = 1.0; M[(2 + e) * 4 + 2] = b1[1]; M[(2 + e) * 4 + 3] = b2[1];
    }
    int perm[4];
    if (lu_factor(M, 4, perm)) return EL_ESINGULAR;
    lu_solve(M, 4, perm, rhs);
    /* state at the midpoint */
    const double sm = 0.5 * h;
    double wd[4];
    if (ex) {
        const double e1 = exp(-om * sm), e2 = exp(-om * (h - sm));
        for (int d = 0; d < 4; d++)
            wd[d] = rhs[2] * e1 * pow(-om, d) + rhs[3] * e2 * pow(om, d);
    } else {
        wd[0] = rhs[2] * sm * sm + rhs[3] * sm * sm * sm;
        wd[1] = 2.0 * rhs[2] * sm + 3.0 * rhs[3] * sm * sm;
        wd[2] = 2.0 * rhs[2] + 6.0 * rhs[3] * sm;
        wd[3] = 6.0 * rhs[3];
    }
    wd[1] += rhs[1];
    /* arc length ~ h + 1/2 int w'^2 (Simpson on the slopes) */
    const double L = h + h / 12.0 * (sa * sa + 4.0 * wd[1] * wd[1] + sb * sb);
    const double g = 1.0 + wd[1] * wd[1];
    const double theta = c + atan(wd[1]), kappa = wd[2] / pow(g, 1.5);
    const double dkappa = wd[3] / (g * g) - 3.0 * wd[1] * wd[2] * wd[2] / (g * g * g);
    return piece_from_state(pc, theta, kappa, dkappa, t->s, 0.5 * L, L);
}

/* The piece by el_hermite_solve: the least-energy solution with the turning tb - ta. */
static int piece_hermite(piece *pc, const targets *t)
{
    const double p0[2] = {0.0, 0.0}, p1[2] = {pc->dx, pc->dy};
    const double t0[2] = {cos(t->ta), sin(t->ta)}, t1[2] = {cos(t->tb), sin(t->tb)};
    el_hermite_options o;
    el_hermite_options_defaults(&o);
    o.sigma = t->s;
    el_hermite_result r;
    int st = el_hermite_solve(p0, t0, p1, t1, &o, &r);
    if (st) return st;
    st = EL_ENOCONV;
    for (size_t i = 0; i < r.count; i++) {   /* sorted by energy */
        const el_smooth_params *p = &r.solutions[i].curve;
        double s2[2] = {0.0, p->length}, th[2];
        if (el_smooth_eval(p, 2, s2, NULL, th, NULL)) continue;
        const double shift = t->ta - th[0];
        if (fabs((th[1] - th[0]) - (t->tb - t->ta)) > 1e-6 || fabs(p->k) >= 1e3) continue;
        pc->v[V_PHI] = p->phi + shift;
        pc->v[V_NU] = log(p->mu);
        pc->v[V_K] = p->k;
        pc->v[V_Q] = p->q;
        pc->v[V_L] = p->length;
        st = EL_OK;
        break;
    }
    el_hermite_result_free(&r);
    return st;
}

/* ------------------------------------------------------------------ the chain */

static void piece_targets(const spline_ws *w, size_t j, targets *t)
{
    const size_t n = w->n;
    t->s = w->sigma;
    t->is = w->lmode ? -2 : -1;
    /* start knot j */
    if (w->slot[j] == SLOT_ANGLE) { t->ta = w->x[j]; t->ia = (long)j; }
    else { t->ta = w->th_end[0]; t->ia = -1; }
    if (!w->closed && j == 0 && w->slot[0] == SLOT_TENSION) { t->s = w->x[0]; t->is = 0; }
    /* end knot */
    const size_t e = (j + 1) % n;
    if (w->closed && e == 0) { t->tb = w->x[0] + w->wind; t->ib = 0; }
    else if (w->slot[e] == SLOT_ANGLE) { t->tb = w->x[e]; t->ib = (long)e; }
    else { t->tb = w->th_end[1]; t->ib = -1; }
    if (!w->closed && e == n - 1 && w->slot[e] == SLOT_TENSION) { t->s = w->x[e]; t->is = (long)e; }
}

/* Evaluate every piece and the knot residuals; returns the merit (or INFINITY). */
static double chain_eval(spline_ws *w, int jac)
{
    const size_t n = w->n, m = w->m;
    double merit = 0.0, rmax = 0.0, Lsum = 0.0;
    for (size_t j = 0; j < m; j++) {
        targets t;
        piece_targets(w, j, &t);
        if (piece_eval(&w->pc[j], &t, jac)) return INFINITY;
        for (int i = 0; i < NV; i++) merit += w->pc[j].R[i] * w->pc[j].R[i];
        rmax = fmax(rmax, max_abs(w->pc[j].R, NV));
        Lsum += w->pc[j].v[V_L];
    }
    for (size_t i = 0; i < n; i++) {
        if (w->slot[i] == SLOT_FIXED) { w->F[i] = 0.0; continue; }
        double km, kp;
        if (w->closed) { km = w->pc[(i + m - 1) % m].kap1; kp = w->pc[i].kap0; }
        else {
            km = i == 0 ? w->kg[0] : w->pc[i - 1].kap1;
            kp = i == n - 1 ? w->kg[1] : w->pc[i].kap0;
        }
        w->F[i] = (km - kp) * w->ell[i];
        merit += w->F[i] * w->F[i];
        rmax = fmax(rmax, fabs(w->F[i]));
    }
    w->Gres = 0.0;
    if (w->lmode == BORDER_ARC) {
        double a = w->arc_b * (w->sigma - w->arc_s0) - w->arc_h;
        for (size_t i = 0; i < n; i++) a += w->arc_a[i] * (w->x[i] - w->arc_x0[i]);
        w->Gres = a;
        merit += a * a;
        rmax = fmax(rmax, fabs(a));
    } else if (w->lmode) {
        w->Gres = (Lsum - w->Lt) / w->Lt;
        merit += w->Gres * w->Gres;
        rmax = fmax(rmax, fabs(w->Gres));
    }
    w->resid = rmax;
    return isfinite(merit) ? merit : INFINITY;
}

/* A(i, j) += v in the (cyclic) tridiagonal storage: up[i] = A(i, i+1), lo[i] = A(i+1, i),
 * and when closed up[n-1] = A(n-1, 0), lo[n-1] = A(0, n-1) (GSL's cyclic layout). */
static void tri_add(spline_ws *w, long i, long j, double v)
{
    const long last = (long)w->n - 1;
    if (j == i) w->dg[i] += v;
    else if (j == i + 1 || (w->closed && i == last && j == 0)) w->up[i] += v;
    else if (i == j + 1 || (w->closed && j == last && i == 0)) w->lo[j] += v;
}

static int tri_solve(spline_ws *w, const double *rhs, double *x)
{
    const size_t n = w->n;
    if (n == 1) { x[0] = rhs[0] / w->dg[0]; return isfinite(x[0]) ? EL_OK : EL_ESINGULAR; }
    gsl_vector_const_view d = gsl_vector_const_view_array(w->dg, n);
    gsl_vector_const_view b = gsl_vector_const_view_array(rhs, n);
    gsl_vector_view xv = gsl_vector_view_array(x, n);
    int st;
    if (w->closed) {
        gsl_vector_const_view e = gsl_vector_const_view_array(w->up, n);
        gsl_vector_const_view f = gsl_vector_const_view_array(w->lo, n);
        st = gsl_linalg_solve_cyc_tridiag(&d.vector, &e.vector, &f.vector, &b.vector, &xv.vector);
    } else {
        gsl_vector_const_view e = gsl_vector_const_view_array(w->up, n - 1);
        gsl_vector_const_view f = gsl_vector_const_view_array(w->lo, n - 1);
        st = gsl_linalg_solve_tridiag(&d.vector, &e.vector, &f.vector, &b.vector, &xv.vector);
    }
    if (st) return st == GSL_ENOMEM ? EL_ENOMEM : EL_ESINGULAR;
    return el__all_finite(x, n) ? EL_ESINGULAR : EL_OK;
}

/* One Newton direction: dx in w->y, dsigma returned in *ds. */
static int chain_direction(spline_ws *w, double *ds)
{
    const size_t n = w->n, m = w->m;
    memset(w->dg, 0, n * sizeof *w->dg);
    memset(w->up, 0, n * sizeof *w->up);
    memset(w->lo, 0, n * sizeof *w->lo);
    memset(w->col, 0, n * sizeof *w->col);
    memset(w->row, 0, n * sizeof *w->row);
    double d = 0.0, gr = -w->Gres;
    for (size_t i = 0; i < n; i++) w->b[i] = -w->F[i];
    for (size_t i = 0; i < n; i++)
        if (w->slot[i] == SLOT_FIXED) w->dg[i] = 1.0;
    for (size_t j = 0; j < m; j++) {
        const piece *pc = &w->pc[j];
        targets t;
        piece_targets(w, j, &t);
        const long rows[2] = {(long)j, (long)((j + 1) % n)};
        const double *cc[2] = {pc->c0, pc->c1};
        for (int e = 0; e < 2; e++) {   /* kappa(0) enters row j with -l, kappa(L) row j+1 with +l */
            const long r = rows[e];
            if (w->slot[r] == SLOT_FIXED) continue;
            const double sg = (e ? 1.0 : -1.0) * w->ell[r];
            const double *c = cc[e];
            w->b[r] += sg * c[0];
            if (t.ia >= 0) tri_add(w, r, t.ia, sg * c[1]);
            if (t.ib >= 0) tri_add(w, r, t.ib, sg * c[2]);
            if (t.is >= 0) tri_add(w, r, t.is, sg * c[3]);
            else if (t.is == -2) w->col[r] += sg * c[3];
        }
        if (w->lmode == BORDER_LENGTH) {
            const double iL = 1.0 / w->Lt;
            gr += pc->cL[0] * iL;
            if (t.ia >= 0) w->row[t.ia] += pc->cL[1] * iL;
            if (t.ib >= 0) w->row[t.ib] += pc->cL[2] * iL;
            if (t.is >= 0) w->row[t.is] += pc->cL[3] * iL;
            else if (t.is == -2) d += pc->cL[3] * iL;
        }
    }
    if (w->lmode == BORDER_ARC) {
        memcpy(w->row, w->arc_a, n * sizeof *w->row);
        d = w->arc_b;
    }
    int st = tri_solve(w, w->b, w->y);
    if (st) return st;
    *ds = 0.0;
    if (w->lmode) {
        if ((st = tri_solve(w, w->col, w->z))) return st;
        double ry = 0.0, rz = 0.0;
        for (size_t i = 0; i < n; i++) { ry += w->row[i] * w->y[i]; rz += w->row[i] * w->z[i]; }
        const double den = d - rz;
        if (!(fabs(den) > 1e-300)) return EL_ESINGULAR;
        *ds = (gr - ry) / den;
        for (size_t i = 0; i < n; i++) w->y[i] -= w->z[i] * *ds;
        if (!isfinite(*ds) || el__all_finite(w->y, n)) return EL_ESINGULAR;
    }
    return EL_OK;
}

/* Newton on the whole chain from the current state until the residual is at
 * most aim (or stalls), at most cap iterations (and the options' max_iter);
 * EL_OK when it ends at most accept. */
static int chain_newton(spline_ws *w, int cap, double aim, double accept)
{
    const size_t n = w->n, m = w->m;
    double merit = chain_eval(w, 1);
    if (!isfinite(merit)) return EL_ENOCONV;
    const int limit = cap < w->max_iter ? cap : w->max_iter;
    for (int it = 0; it < limit; it++) {
        if (w->resid <= aim) return EL_OK;
        double ds;
        if (chain_direction(w, &ds)) break;
        w->iterations++;
        /* step limits */
        double al = 1.0, dxm = 0.0;
        for (size_t i = 0; i < n; i++)
            if (w->slot[i] == SLOT_ANGLE) dxm = fmax(dxm, fabs(w->y[i]));
        if (dxm > 0.5) al = 0.5 / dxm;
        for (size_t i = 0; i < n; i++)
            if (w->slot[i] == SLOT_TENSION) {
                const double r = fabs(w->x[i]) + 1.0;
                if (fabs(w->y[i]) > r) al = fmin(al, r / fabs(w->y[i]));
            }
        /* piece steps dv = -D0 + D1 dta + D2 dtb + D3 ds, taken in the state */
        memcpy(w->xs, w->x, n * sizeof *w->x);
        for (size_t j = 0; j < m; j++) {
            piece *pc = &w->pc[j];
            targets t;
            piece_targets(w, j, &t);
            const double dta = t.ia >= 0 ? w->y[t.ia] : 0.0, dtb = t.ib >= 0 ? w->y[t.ib] : 0.0;
            const double dsj = t.is >= 0 ? w->y[t.is] : t.is == -2 ? ds : 0.0;
            double dv[NV];
            for (int i = 0; i < NV; i++)
                dv[i] = -pc->D[0][i] + pc->D[1][i] * dta + pc->D[2][i] * dtb + pc->D[3][i] * dsj;
            al = pstep_prepare(pc, dv, &w->ps[j], al);
        }
        const double sigma0 = w->sigma;
        int ok = 0;
        double mnew = INFINITY;
        /* already accepted: a step that does not help is rounding, not worth halving */
        const int halvings = w->resid <= accept ? 0 : MAX_HALVINGS;
        for (int hv = 0; hv <= halvings; hv++, al *= 0.5) {
            for (size_t i = 0; i < n; i++) w->x[i] = w->xs[i] + al * w->y[i];
            w->sigma = sigma0 + al * ds;
            int bad = 0;
            for (size_t j = 0; j < m && !bad; j++) bad = pstep_apply(&w->pc[j], &w->ps[j], al);
            mnew = bad ? INFINITY : chain_eval(w, 1);
            if (mnew <= (1.0 - 2e-4 * al) * merit) { ok = 1; break; }
        }
        if (!ok && halvings == 0 && w->resid <= accept) break;   /* rounding: the trial is as good */
        if (!ok) {   /* restore the last accepted state */
            memcpy(w->x, w->xs, n * sizeof *w->x);
            w->sigma = sigma0;
            for (size_t j = 0; j < m; j++) memcpy(w->pc[j].v, w->ps[j].v0, sizeof w->pc[j].v);
            chain_eval(w, 1);
            break;
        }
        merit = mnew;
    }
    return w->resid <= accept ? EL_OK : EL_ENOCONV;
}

/* ------------------------------------------------------------------ start */

static double wrap_pi(double a) { return a - 2.0 * M_PI * nearbyint(a / (2.0 * M_PI)); }

/* Tangent angles: circles through three consecutive points (file comment). */
static void start_angles(spline_ws *w)
{
    const size_t n = w->n, m = w->m;
    double *c = w->b;   /* chord angles, unwrapped along the chain (m values) */
    for (size_t j = 0; j < m; j++) {
        c[j] = atan2(w->pc[j].dy, w->pc[j].dx);
        if (j) c[j] = c[j - 1] + wrap_pi(c[j] - c[j - 1]);
    }
    for (size_t i = 0; i < n; i++) {
        if (!w->closed && (i == 0 || i == n - 1)) continue;
        const piece *a = &w->pc[(i + m - 1) % m], *b = &w->pc[i];
        const double A = a->h * a->h, B = b->h * b->h;
        double tx = B * a->dx + A * b->dx, ty = B * a->dy + A * b->dy;
        if (!(hypot(tx, ty) > 1e-12 * A * B)) { tx = -a->dy; ty = a->dx; }   /* a reversal */
        const double ref = i == 0 ? c[0] : c[i - 1];
        w->x[i] = ref + wrap_pi(atan2(ty, tx) - ref);
    }
    if (w->closed) {
        const double cn = c[m - 1] + wrap_pi(atan2(w->pc[0].dy, w->pc[0].dx) - c[m - 1]);
        w->wind = 2.0 * M_PI * nearbyint((cn - c[0]) / (2.0 * M_PI));
        /* the angle at point 0 seen from the last chord, then moved to chord 0's turn */
        w->x[0] = c[0] + wrap_pi(w->x[0] - c[0]);
        return;
    }
    if (w->kind[0] != EL_SPLINE_NATURAL) w->x[0] = w->th_end[0];
    if (w->kind[1] != EL_SPLINE_NATURAL) w->x[n - 1] = w->th_end[1];
    const double t1 = n > 2 ? w->x[1] : w->kind[1] != EL_SPLINE_NATURAL ? w->th_end[1] : c[0];
    const double tm = n > 2 ? w->x[n - 2] : w->kind[0] != EL_SPLINE_NATURAL ? w->th_end[0] : c[0];
    if (w->kind[0] == EL_SPLINE_NATURAL) w->x[0] = c[0] - 0.5 * (t1 - c[0]);
    if (w->kind[1] == EL_SPLINE_NATURAL) w->x[n - 1] = c[m - 1] - 0.5 * (tm - c[m - 1]);
    if (w->slot[0] == SLOT_TENSION) w->x[0] = w->sigma;
    if (w->slot[n - 1] == SLOT_TENSION) w->x[n - 1] = w->sigma;
}

/* The angles (rad) between the chord and the target tangents of a piece. */
static double chord_angle(const piece *pc, const targets *t)
{
    const double c = atan2(pc->dy, pc->dx);
    return fmax(fabs(wrap_pi(t->ta - c)), fabs(wrap_pi(t->tb - c)));
}

/*
 * Every piece: where its tangents are within 0.75 rad of its chord, from the
 * linearised batten (kept if close, R <= 1e-2: the spline's Newton corrects it;
 * else solved alone, to 1e-8, or 1e-6 where nearly straight pieces under tension
 * stop, see NEAR_RESID); where they are not, or that fails, the least-energy
 * Hermite elastica with that turning (el_hermite_solve): the branch a batten
 * takes, where the linearisation can lead Newton to a loop.
 */
static int start_pieces(spline_ws *w)
{
    for (size_t j = 0; j < w->m; j++) {
        piece *pc = &w->pc[j];
        targets t;
        piece_targets(w, j, &t);
        if (chord_angle(pc, &t) <= 0.75) {
            if (!piece_start(pc, &t) && !piece_eval(pc, &t, 0) && max_abs(pc->R, NV) <= 1e-2) continue;
            if (!piece_start(pc, &t) && (!piece_newton(pc, &t, 1e-8) || max_abs(pc->R, NV) <= 1e-6))
                continue;
        }
        int st = piece_hermite(pc, &t);
        if (st == EL_ENOMEM) return st;
        if (st && chord_angle(pc, &t) > 0.75 && !piece_start(pc, &t) &&
            (!piece_newton(pc, &t, 1e-8) || max_abs(pc->R, NV) <= 1e-6))
            st = EL_OK;
        if (st) return EL_ENOCONV;
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ continuation */

/* A solved state of the chain (to restore after a failed step, and the two
 * last ones for the secant predictor). */
typedef struct snapshot {
    double *x, *v, *st, sigma;
} snapshot;

static void snap_save(const spline_ws *w, snapshot *s)
{
    memcpy(s->x, w->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) {
        memcpy(s->v + j * NV, w->pc[j].v, sizeof w->pc[j].v);
        memcpy(s->st + j * NV, w->pc[j].st, sizeof w->pc[j].st);
    }
    s->sigma = w->sigma;
}

static void snap_load(spline_ws *w, const snapshot *s)
{
    memcpy(w->x, s->x, w->n * sizeof *w->x);
    for (size_t j = 0; j < w->m; j++) memcpy(w->pc[j].v, s->v + j * NV, sizeof w->pc[j].v);
    w->sigma = s->sigma;
}

/* The state at f = (t - tb)/(tb - ta) beyond b on the line through a and b
 * (knot values, sigma, piece states); b itself if a piece state is invalid. */
static void predict(spline_ws *w, const snapshot *a, const snapshot *b, double f)
{
    for (size_t i = 0; i < w->n; i++) w->x[i] = b->x[i] + f * (b->x[i] - a->x[i]);
    w->sigma = b->sigma + f * (b->sigma - a->sigma);
    for (size_t j = 0; j < w->m; j++) {
        double st[NV];
        for (int i = 0; i < NV; i++) st[i] = b->st[j * NV + i] + f * (b->st[j * NV + i] - a->st[j * NV + i]);
        if (piece_set_state(&w->pc[j], st)) { snap_load(w, b); return; }
    }
}

/* Residual of a state that is a solution up to what the parametrisation resolves
 * (header: near the separatrix, near a circle), accepted on the way. */
#define NEAR_RESID 1e-6

/*
 * Follow a one-parameter family from t = 0 (solved, in w) to t = 1: set(w, t)
 * moves the target (sigma or length); each step starts from the secant
 * predictor of the last two solutions and is corrected by Newton to NEAR_RESID
 * (the last one to aim, accepted at accept). The first step is dt; it doubles
 * after an easy success, grows by 1.3 after a slow one and halves after a
 * failure (state restored); at most max_steps steps, giving up below 1e-6.
 */
static int continuation(spline_ws *w, snapshot sv[2], int max_steps, double dt,
                        void (*set)(spline_ws *, double, const double *), const double *par,
                        double aim, double accept)
{
    double t = 0.0, tp = -1.0;
    snapshot *cur = &sv[0], *prev = &sv[1];
    snap_save(w, cur);
    for (int step = 0; step < max_steps; step++) {
        const double tn = fmin(1.0, t + dt);
        const int last = tn >= 1.0;
        if (tp >= 0.0) predict(w, prev, cur, (tn - t) / (t - tp));
        set(w, tn, par);
        const int it0 = w->iterations;
        const int st = last ? chain_newton(w, STEP_ITER, aim, accept)
                            : chain_newton(w, STEP_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
        if (st == EL_OK) {
            if (last) return EL_OK;
            snapshot *tmp = prev; prev = cur; cur = tmp;
            snap_save(w, cur);
            tp = t;
            t = tn;
            dt *= w->iterations - it0 <= 3 ? 2.0 : 1.3;
            continue;
        }
        if (last && w->resid <= NEAR_RESID) { w->near = 1; return EL_ENOCONV; }
        snap_load(w, cur);
        set(w, t, par);
        dt *= 0.5;
        if (dt < 1e-6) break;
    }
    snap_load(w, cur);
    return EL_ENOCONV;
}

/* sigma(t) between par[0] (t = 0) and par[1] geometrically in sigma + par[2]. */
static void set_sigma(spline_ws *w, double t, const double *par)
{
    const double a = par[0] + par[2], b = par[1] + par[2];
    w->sigma = t >= 1.0 ? par[1] : a * pow(b / a, t) - par[2];
}

/* L(t) from par[0] (t = 0) to par[1], geometrically in L - par[2] (the polygon's
 * length, near which the bow is small). */
static void set_length(spline_ws *w, double t, const double *par)
{
    const double a = par[0] - par[2], b = par[1] - par[2];
    w->Lt = t >= 1.0 ? par[1] : par[2] + a * pow(b / a, t);
}

/* sigma(t) linear from par[0] to par[1]. */
static void set_sigma_linear(spline_ws *w, double t, const double *par)
{
    w->sigma = t >= 1.0 ? par[1] : par[0] + t * (par[1] - par[0]);
}

static double total_length(const spline_ws *w)
{
    double L = 0.0;
    for (size_t j = 0; j < w->m; j++) L += w->pc[j].v[V_L];
    return L;
}

/* From the tension solution in w to the one at sigma (to NEAR_RESID); EL_OK or EL_ENOCONV. */
static int move_sigma(spline_ws *w, snapshot sv[2], int *steps, double sigma)
{
    const double par[2] = {w->sigma, sigma};
    const int st = continuation(w, sv, *steps, 1.0, set_sigma_linear, par,
                                1e-3 * NEAR_RESID, NEAR_RESID);
    (*steps)--;
    return st;
}

/* Points of the pseudo-arclength path: knot values and sigma, the norm
 * weighting sigma by 1/rho. */
static double arc_dist(const spline_ws *w, const snapshot *a, const snapshot *b, double rho)
{
    double s2 = (b->sigma - a->sigma) * (b->sigma - a->sigma) / (rho * rho);
    for (size_t i = 0; i < w->n; i++) s2 += (b->x[i] - a->x[i]) * (b->x[i] - a->x[i]);
    return sqrt(s2);
}

/*
 * Length mode from a tension solution (w, at w->sigma). The length L(sigma) of
 * the tension solutions is nearly flat for moderate sigma and turns back at
 * folds (a buckled batten, sigma < 0): neither sigma nor the length is a good
 * parameter of the family, so it is followed by pseudo-arclength continuation
 * in (knot values, sigma): each step fixes the projection on the secant of
 * the last two solutions (the border row of the Newton system, instead of the
 * length), towards the target length, until the length brackets it; then
 * Newton with the length as the border equation from the interpolated state.
 * Step: doubled after an easy success, halved after a failure, at most
 * max_steps steps.
 */
static int solve_length(spline_ws *w, snapshot sv[3], int max_steps, double Lt)
{
    int steps = max_steps;
    snapshot *B = &sv[2], *C = &sv[0];   /* the base point and the next one */
    const double rho = 1.0 + fabs(w->sigma);
    double gb = total_length(w) - Lt, gc;
    snap_save(w, B);
    if (fabs(gb) > 1e-9 * Lt) {
        /* a second point: sigma moved towards the length */
        const double s1 = w->sigma + (gb < 0.0 ? -0.05 : 0.05) * rho;
        if (move_sigma(w, sv, &steps, s1)) return EL_ENOCONV;
        snap_save(w, C);
        gc = total_length(w) - Lt;
        double N = arc_dist(w, B, C, rho), h = 2.0 * N;
        while (gc * gb > 0.0 || !(N > 0.0)) {
            if (steps-- <= 0 || !(N > 0.0) || !(h > 1e-9)) return EL_ENOCONV;
            /* the secant B -> C is the tangent; C is the base of the next step */
            for (size_t i = 0; i < w->n; i++) {
                w->arc_a[i] = (C->x[i] - B->x[i]) / N;
                w->arc_x0[i] = C->x[i];
            }
            w->arc_b = (C->sigma - B->sigma) / (N * rho * rho);
            w->arc_s0 = C->sigma;
            w->arc_h = h;
            predict(w, B, C, h / N);
            w->lmode = BORDER_ARC;
            const int it0 = w->iterations;
            const int st = chain_newton(w, STEP_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
            w->lmode = 0;
            if (st) { snap_load(w, C); h *= 0.5; continue; }
            const double gn = total_length(w) - Lt;
            if (gn * gc <= 0.0) {
                /* bracketed between C and the new point D: Newton on the length from
                 * the interpolated state; if that fails, a shorter step from C */
                snapshot *D = B;
                snap_save(w, D);
                predict(w, C, D, gn / (gc - gn));
                w->lmode = BORDER_LENGTH;
                w->Lt = Lt;
                if (chain_newton(w, DIRECT_ITER, w->aim, w->tol) == EL_OK) return EL_OK;
                w->lmode = 0;
                if (steps-- <= 0) return EL_ENOCONV;
                /* B (overwritten by D) must again be the point before C: C - (D - C) scaled */
                const double back = -1.0;
                for (size_t i = 0; i < w->n; i++) D->x[i] = C->x[i] + back * (D->x[i] - C->x[i]);
                D->sigma = C->sigma + back * (D->sigma - C->sigma);
                for (size_t i = 0; i < NV * w->m; i++) D->st[i] = C->st[i] + back * (D->st[i] - C->st[i]);
                N = arc_dist(w, B, C, rho);
                snap_load(w, C);
                h *= 0.25;
                continue;
            }
            snapshot *tmp = B; B = C; C = tmp;
            snap_save(w, C);
            gb = gc;
            gc = gn;
            N = arc_dist(w, B, C, rho);
            if (w->iterations - it0 <= 3) h *= 2.0;
        }
    }
    w->lmode = BORDER_LENGTH;
    w->Lt = Lt;
    return chain_newton(w, DIRECT_ITER, w->aim, w->tol);
}

/* The tension solution at w->sigma: directly, else by continuation from a high
 * tension. final: to tol (else to NEAR_RESID, as a start for the length mode). */
static int solve_tension(spline_ws *w, snapshot sv[2], int max_steps, int final)
{
    const double target = w->sigma;
    const double aim = final ? w->aim : 1e-3 * NEAR_RESID, accept = final ? w->tol : NEAR_RESID;
    start_angles(w);
    int st = start_pieces(w);
    if (st == EL_ENOMEM) return st;
    if (!st) {
        if (chain_newton(w, DIRECT_ITER, aim, accept) == EL_OK) return EL_OK;
        if (final && w->resid <= NEAR_RESID) { w->near = 1; return EL_ENOCONV; }
    }
    /* from a high tension: sigma h^2 = 40 on the mean chord (the unit here) */
    const double hi = fmax(40.0, 4.0 * target);
    w->sigma = hi;
    start_angles(w);
    if ((st = start_pieces(w))) return st == EL_ENOMEM ? st : EL_ENOCONV;
    if (chain_newton(w, DIRECT_ITER, 1e-3 * NEAR_RESID, NEAR_RESID) != EL_OK) return EL_ENOCONV;
    const double par[3] = {hi, target, 1.0};
    return continuation(w, sv, max_steps, 0.25, set_sigma, par, aim, accept);
}

/* ------------------------------------------------------------------ API */

void el_spline_options_defaults(el_spline_options *opt)
{
    if (!opt) return;
    memset(opt, 0, sizeof *opt);
    opt->mode = EL_SPLINE_TENSION;
    opt->start.kind = opt->end.kind = EL_SPLINE_NATURAL;
    opt->tol = 1e-10;
    opt->max_iter = 60;
    opt->max_steps = 60;
}

void el_spline_result_free(el_spline_result *res)
{
    if (!res) return;
    free(res->pieces); free(res->sigmas); free(res->forces); free(res->angles); free(res->curvatures);
    memset(res, 0, sizeof *res);
}

static int check_end(const el_spline_end *e)
{
    if (e->kind == EL_SPLINE_NATURAL) return EL_OK;
    if (e->kind != EL_SPLINE_TANGENT && e->kind != EL_SPLINE_G2) return EL_EINVAL;
    if (!isfinite(e->tangent[0]) || !isfinite(e->tangent[1]) ||
        !(hypot(e->tangent[0], e->tangent[1]) > 0.0))
        return EL_EINVAL;
    if (e->kind == EL_SPLINE_G2 && !isfinite(e->curvature)) return EL_EINVAL;
    return EL_OK;
}

static int check_options(const el_spline_options *o)
{
    if (o->mode == EL_SPLINE_TENSION) {
        if (!isfinite(o->sigma) || o->sigma < 0.0) return EL_EINVAL;
    } else if (o->mode == EL_SPLINE_LENGTH) {
        if (!isfinite(o->length) || !(o->length > 0.0)) return EL_EINVAL;
    } else {
        return EL_EINVAL;
    }
    if (!(o->tol >= 1e-14 && o->tol <= 1e-3) || o->max_iter < 1 || o->max_iter > 1000 ||
        o->max_steps < 1 || o->max_steps > 1000 || (o->closed != 0 && o->closed != 1))
        return EL_EINVAL;
    if (!o->closed && (check_end(&o->start) || check_end(&o->end))) return EL_EINVAL;
    return EL_OK;
}

static void ws_free(spline_ws *w)
{
    free(w->x); free(w->ell); free(w->slot); free(w->pc); free(w->F); free(w->dg); free(w->up);
    free(w->lo); free(w->b); free(w->y); free(w->z); free(w->col); free(w->row); free(w->xs);
    free(w->ps); free(w->snapbuf); free(w->arc_a); free(w->arc_x0);
}

static int ws_alloc(spline_ws *w, size_t n, size_t m)
{
    if (n > SIZE_MAX / (NV * sizeof(double)) || m > SIZE_MAX / sizeof(piece)) return EL_ENOMEM;
    double **arr[] = {&w->x, &w->ell, &w->F, &w->dg, &w->up, &w->lo, &w->b, &w->y, &w->z,
                      &w->col, &w->row, &w->xs, &w->arc_a, &w->arc_x0};
    for (size_t i = 0; i < sizeof arr / sizeof arr[0]; i++)
        if (!(*arr[i] = calloc(n, sizeof(double)))) return EL_ENOMEM;
    if (!(w->slot = calloc(n, sizeof *w->slot)) || !(w->pc = calloc(m, sizeof *w->pc)) ||
        !(w->ps = calloc(m, sizeof *w->ps)))
        return EL_ENOMEM;
    return EL_OK;
}

/* Collinear points in order along the line, with ends that allow the straight line. */
static int straight_line(const double *xy, size_t n, const el_spline_options *o, double *dir)
{
    if (o->closed) return 0;
    const double dx = xy[2 * n - 2] - xy[0], dy = xy[2 * n - 1] - xy[1], D = hypot(dx, dy);
    if (!(D > 0.0)) return 0;
    const double ux = dx / D, uy = dy / D;
    for (size_t i = 0; i + 1 < n; i++) {
        const double ax = xy[2 * i + 2] - xy[2 * i], ay = xy[2 * i + 3] - xy[2 * i + 1];
        const double h = hypot(ax, ay);
        if (fabs(ux * ay - uy * ax) > 1e-14 * h || ux * ax + uy * ay <= 0.0) return 0;
    }
    const el_spline_end *e[2] = {&o->start, &o->end};
    for (int i = 0; i < 2; i++) {
        if (e[i]->kind == EL_SPLINE_NATURAL) continue;
        const double tn = hypot(e[i]->tangent[0], e[i]->tangent[1]);
        const double tx = e[i]->tangent[0] / tn, ty = e[i]->tangent[1] / tn;
        if (fabs(ux * ty - uy * tx) > 1e-14 || ux * tx + uy * ty <= 0.0) return 0;
        if (e[i]->kind == EL_SPLINE_G2 && e[i]->curvature != 0.0) return 0;
    }
    dir[0] = atan2(uy, ux);
    return 1;
}

/* max |kappa| on a piece: the ends, or 2|k| sqrt(mu) if u passes a maximum of
 * |cn|: u = 2 j K(k) (|k| < 1), |k| u = 2 j K(1/|k|) (|k| > 1); Kq = K(min(|k|, 1/|k|)). */
static double piece_max_curvature(const el_smooth_params *p, double Kq, double k0, double k1)
{
    double m = fmax(fabs(k0), fabs(k1));
    const double ka = fabs(p->k), w = sqrt(p->mu);
    if (ka == 0.0) return m;
    const double per = ka < 1.0 ? 2.0 * Kq : 2.0 * Kq / ka;
    const double u0 = p->q, u1 = p->q + w * p->length;
    if (floor(u1 / per) > floor(u0 / per) || fmod(u0, per) == 0.0) m = fmax(m, 2.0 * ka * w);
    return m;
}

/* Fill res from the solved chain (original units), measuring the residual. */
static int make_result(const spline_ws *w, const double *xy, double S, el_spline_result *res)
{
    const size_t n = w->n, m = w->m;
    el_spline_result r;
    memset(&r, 0, sizeof r);
    r.npoints = n;
    r.npieces = m;
    r.pieces = malloc(m * sizeof *r.pieces);
    r.sigmas = malloc(m * sizeof *r.sigmas);
    r.forces = malloc(2 * m * sizeof *r.forces);
    r.angles = malloc(n * sizeof *r.angles);
    r.curvatures = malloc(n * sizeof *r.curvatures);
    double *ends = malloc(2 * m * sizeof *ends);   /* theta, kappa at each piece's end */
    if (!r.pieces || !r.sigmas || !r.forces || !r.angles || !r.curvatures || !ends) {
        el_spline_result_free(&r);
        free(ends);
        return EL_ENOMEM;
    }
    double resid = 0.0;
    /* tension mode: the given sigma exactly (not through the unit S) */
    r.sigma = w->lmode ? w->sigma / (S * S) : w->sigma_user;
    for (size_t j = 0; j < m; j++) {
        const piece *pc = &w->pc[j];
        targets t;
        piece_targets(w, j, &t);
        el_smooth_params *p = &r.pieces[j];
        p->x0 = xy[2 * j];
        p->y0 = xy[2 * j + 1];
        p->phi = pc->v[V_PHI];
        p->mu = exp(pc->v[V_NU]) / (S * S);
        p->k = pc->v[V_K];
        p->q = pc->v[V_Q];
        p->length = pc->v[V_L] * S;
        r.sigmas[j] = t.is == -1 ? r.sigma : t.s / (S * S);
        /* the residual is measured on the output, with el_smooth_eval */
        const double s2[2] = {0.0, p->length};
        double pt[4], th[2], ka[2];
        const int st = el_smooth_eval(p, 2, s2, pt, th, ka);
        if (st) { el_spline_result_free(&r); free(ends); return st; }
        const size_t e = (j + 1) % n;
        const double h = hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        resid = fmax(resid, hypot(pt[2] - xy[2 * e], pt[3] - xy[2 * e + 1]) / h);
        r.angles[j] = th[0];
        r.curvatures[j] = ka[0];
        ends[2 * j] = th[1];
        ends[2 * j + 1] = ka[1];
        if (!w->closed && j == m - 1) { r.angles[n - 1] = th[1]; r.curvatures[n - 1] = ka[1]; }
        /* F = (sigma - kappa^2) T - 2 kappa' N at s = 0 */
        const double dk = pc->dkap0 / (S * S), T[2] = {cos(th[0]), sin(th[0])};
        const double a = r.sigmas[j] - ka[0] * ka[0];
        r.forces[2 * j] = a * T[0] + 2.0 * dk * T[1];
        r.forces[2 * j + 1] = a * T[1] - 2.0 * dk * T[0];
        r.energy += pc->energy / S;
        r.length += p->length;
        r.max_curvature = fmax(r.max_curvature, piece_max_curvature(p, pc->Kq, ka[0], ka[1]));
    }
    /* the joints and the end conditions */
    for (size_t i = 0; i < n; i++) {
        const double lr = w->ell[i] * S;
        if (!w->closed && (i == 0 || i == n - 1)) {
            const int e = i == 0 ? 0 : 1;
            const double kap = r.curvatures[i];
            if (w->kind[e] == EL_SPLINE_NATURAL) resid = fmax(resid, fabs(kap) * lr);
            if (w->kind[e] == EL_SPLINE_G2) resid = fmax(resid, fabs(kap - w->kg[e] / S) * lr);
            if (w->kind[e] != EL_SPLINE_NATURAL)
                resid = fmax(resid, fabs(wrap_pi(r.angles[i] - w->th_end[e])));
            continue;
        }
        const size_t jm = (i + m - 1) % m;
        resid = fmax(resid, fabs(wrap_pi(ends[2 * jm] - r.angles[i])));
        resid = fmax(resid, fabs(ends[2 * jm + 1] - r.curvatures[i]) * lr);
    }
    free(ends);
    if (w->lmode == BORDER_LENGTH) resid = fmax(resid, fabs(r.length - w->Lt * S) / (w->Lt * S));
    r.residual = resid;
    r.iterations = w->iterations;
    *res = r;
    return EL_OK;
}

int el_spline_solve(const double *xy, size_t n, const el_spline_options *opt,
                    el_spline_result *res)
{
    if (!res) return EL_EINVAL;
    memset(res, 0, sizeof *res);
    if (!xy || !opt || n < 2 || check_options(opt)) return EL_EINVAL;
    if (n > SIZE_MAX / 4 || el__all_finite(xy, 2 * n)) return EL_EINVAL;
    el__gsl_quiet();
    const int closed = opt->closed;
    if (closed && xy[0] == xy[2 * n - 2] && xy[1] == xy[2 * n - 1]) n--;   /* a repeated start */
    if (closed && n < 3) return EL_EINVAL;
    const size_t m = closed ? n : n - 1;
    /* chords; coincident consecutive points are invalid */
    double Lp = 0.0, scale = 0.0;
    for (size_t i = 0; i < n; i++) scale = fmax(scale, fmax(fabs(xy[2 * i]), fabs(xy[2 * i + 1])));
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % n;
        const double h = hypot(xy[2 * e] - xy[2 * j], xy[2 * e + 1] - xy[2 * j + 1]);
        if (!(h > 4.0 * DBL_EPSILON * scale) || !isfinite(h)) return EL_EINVAL;
        Lp += h;
    }
    if (!isfinite(Lp)) return EL_EINVAL;
    const int lmode = opt->mode == EL_SPLINE_LENGTH;
    if (lmode && opt->length < Lp * (1.0 - 1e-14)) return EL_EDOM;
    int nten = 0;   /* G2 ends */
    if (!closed) nten = (opt->start.kind == EL_SPLINE_G2) + (opt->end.kind == EL_SPLINE_G2);
    if ((size_t)nten > m || (lmode && (size_t)nten >= m)) return EL_EDOM;

    spline_ws w;
    memset(&w, 0, sizeof w);
    int st = ws_alloc(&w, n, m);
    snapshot sv[3];
    const size_t ns = n + 2 * NV * m;   /* doubles per snapshot */
    if (!st && !(w.snapbuf = malloc(3 * ns * sizeof *w.snapbuf))) st = EL_ENOMEM;
    if (st) goto done;
    for (int i = 0; i < 3; i++) {
        sv[i].x = w.snapbuf + i * ns;
        sv[i].v = sv[i].x + n;
        sv[i].st = sv[i].v + NV * m;
    }
    const double S = Lp / (double)m;   /* the unit: mean chord */
    w.n = n; w.m = m; w.closed = closed; w.lmode = lmode;
    w.tol = opt->tol; w.max_iter = opt->max_iter;
    w.aim = fmax(1e-14, 0.1 * opt->tol);
    w.sigma = lmode ? 1.0 : opt->sigma * S * S;
    w.sigma_user = opt->sigma;
    w.Lt = lmode ? opt->length / S : 0.0;
    for (size_t j = 0; j < m; j++) {
        const size_t e = (j + 1) % n;
        piece *pc = &w.pc[j];
        pc->dx = (xy[2 * e] - xy[2 * j]) / S;
        pc->dy = (xy[2 * e + 1] - xy[2 * j + 1]) / S;
        pc->h = hypot(pc->dx, pc->dy);
    }
    for (size_t i = 0; i < n; i++) {
        const double hl = closed || i > 0 ? w.pc[(i + m - 1) % m].h : w.pc[0].h;
        const double hr = closed || i < n - 1 ? w.pc[i % m].h : w.pc[m - 1].h;
        w.ell[i] = 0.5 * (hl + hr);
        w.slot[i] = SLOT_ANGLE;
    }
    if (!closed) {
        const el_spline_end *e[2] = {&opt->start, &opt->end};
        for (int i = 0; i < 2; i++) {
            w.kind[i] = e[i]->kind;
            if (e[i]->kind == EL_SPLINE_NATURAL) continue;
            const double c = atan2(w.pc[i ? m - 1 : 0].dy, w.pc[i ? m - 1 : 0].dx);
            w.th_end[i] = c + wrap_pi(atan2(e[i]->tangent[1], e[i]->tangent[0]) - c);
            w.kg[i] = e[i]->kind == EL_SPLINE_G2 ? e[i]->curvature * S : 0.0;
            w.slot[i ? n - 1 : 0] = e[i]->kind == EL_SPLINE_G2 ? SLOT_TENSION : SLOT_FIXED;
        }
    }

    double dir;
    if (straight_line(xy, n, opt, &dir) && (!lmode || opt->length <= Lp * (1.0 + 1e-14))) {
        for (size_t i = 0; i < n; i++) if (w.slot[i] == SLOT_ANGLE) w.x[i] = dir;
        for (size_t j = 0; j < m; j++) {
            piece *pc = &w.pc[j];
            pc->v[V_PHI] = dir; pc->v[V_NU] = log(1.0 / (pc->h * pc->h));
            pc->v[V_K] = 0.0; pc->v[V_Q] = 0.0; pc->v[V_L] = pc->h;
        }
        if (w.slot[0] == SLOT_TENSION) w.x[0] = w.sigma;
        if (w.slot[n - 1] == SLOT_TENSION) w.x[n - 1] = w.sigma;
        if (lmode) { w.sigma = 0.0; w.Lt = Lp / S; }
        chain_eval(&w, 0);
        st = make_result(&w, xy, S, res);
        if (!st && lmode) res->sigma = 0.0;
        goto done;
    }

    if (!lmode) {
        st = solve_tension(&w, sv, opt->max_steps, 1);
    } else if (straight_line(xy, n, opt, &dir)) {
        /* longer than the line: Euler's buckled strip (first mode, bowed to the
         * left), theta = dir + Theta cos(pi s / D), L / D - 1 ~ Theta^2 / 4,
         * sigma = -2 (pi / D)^2 (the linearised 2 kappa'' = sigma kappa), solved
         * with a small bow (where that is accurate), then followed in length */
        const double L1 = fmin(opt->length, Lp * (1.0 + 1e-3));
        const double D = Lp / S, Th = 2.0 * sqrt(L1 / Lp - 1.0);
        double sx = 0.0;
        for (size_t i = 0; i < n; i++) {
            if (w.slot[i] == SLOT_ANGLE) w.x[i] = dir + Th * cos(M_PI * sx / D);
            if (i < m) sx += w.pc[i].h;
        }
        w.sigma = -2.0 * M_PI * M_PI / (D * D);
        if (w.slot[0] == SLOT_TENSION) w.x[0] = w.sigma;
        if (w.slot[n - 1] == SLOT_TENSION) w.x[n - 1] = w.sigma;
        st = start_pieces(&w);
        w.lmode = BORDER_LENGTH;
        w.Lt = L1 / S;
        if (!st) st = chain_newton(&w, DIRECT_ITER, 1e-3 * NEAR_RESID, NEAR_RESID);
        if (!st && opt->length > L1) {
            const double par[3] = {L1 / S, opt->length / S, Lp / S};
            st = continuation(&w, sv, opt->max_steps, 0.25, set_length, par, w.aim, w.tol);
        }
        if (st == EL_ENOCONV && w.resid <= NEAR_RESID) w.near = 1;
    } else {
        /* a tension solution, then sigma free with the length as its equation
         * (solve_length): the free batten, or where the continuation towards it
         * stopped (it need not exist) */
        w.lmode = 0;
        w.sigma = 0.0;
        st = solve_tension(&w, sv, opt->max_steps, 0);
        if (st == EL_ENOCONV && isfinite(chain_eval(&w, 1)) && w.resid <= NEAR_RESID) st = EL_OK;
        if (!st) st = solve_length(&w, sv, opt->max_steps, opt->length / S);
        if (st == EL_ENOCONV && w.lmode && w.resid <= NEAR_RESID) w.near = 1;
    }
    if (st == EL_ENOMEM) goto done;
    if (!st || w.near) {   /* a solution, or one to what the parametrisation resolves */
        const int st2 = make_result(&w, xy, S, res);
        if (st2) { st = st2; goto done; }
        if (!(res->residual <= opt->tol)) st = EL_ENOCONV;
        goto done;
    }
    /* no solution found: for sigma = 0 the free-sliding batten slides off its ducks */
    st = !lmode && opt->sigma == 0.0 ? EL_EDOM : EL_ENOCONV;
done:
    ws_free(&w);
    return st;
}

/* internal.h: the piece's Jacobians and implicit derivatives, for the tests. */
int el__spline_piece_jacobians(const el_smooth_params *p, double *J, double *g0, double *g1,
                               double *M, double *d)
{
    if (el_smooth_check(p) || !(p->length > 0.0) || !J || !g0 || !g1 || !M || !d) return EL_EINVAL;
    el__gsl_quiet();
    const double s[2] = {0.0, p->length};
    double xy[4], th[2];
    int st = el_smooth_eval(p, 2, s, xy, th, NULL);
    if (st) return st;
    piece pc;
    memset(&pc, 0, sizeof pc);
    pc.v[V_PHI] = p->phi; pc.v[V_NU] = log(p->mu); pc.v[V_K] = p->k; pc.v[V_Q] = p->q;
    pc.v[V_L] = p->length;
    pc.dx = xy[2] - xy[0];
    pc.dy = xy[3] - xy[1];
    pc.h = hypot(pc.dx, pc.dy);
    if (!(pc.h > 0.0)) return EL_EDOM;
    const targets t = {th[0], th[1], 2.0 * p->mu * (2.0 * p->k * p->k - 1.0), -1, -1, -1};
    double raw[NV * NV + 2 * NV];
    if ((st = piece_eval_raw(&pc, &t, 1, raw))) return st;
    memcpy(J, raw, NV * NV * sizeof *J);
    memcpy(g0, raw + NV * NV, NV * sizeof *g0);
    memcpy(g1, raw + NV * NV + NV, NV * sizeof *g1);
    memcpy(M, pc.M, sizeof pc.M);
    for (int r = 0; r < 3; r++) {
        d[r] = pc.c0[r + 1];
        d[3 + r] = pc.c1[r + 1];
        d[6 + r] = pc.cL[r + 1];
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ B-spline */

int el_spline_to_bspline(const el_spline_result *res, double tol, int degree, el_bspline *out)
{
    if (!res || !out || !res->npieces || !res->pieces || !isfinite(tol) || !(tol > 0.0) ||
        degree < 3 || degree > 7)
        return EL_EINVAL;
    const size_t m = res->npieces;
    el_bspline *parts = calloc(m, sizeof *parts);
    if (!parts) return EL_ENOMEM;
    int st = EL_OK, status = EL_OK;
    double dev = 0.0;
    for (size_t j = 0; j < m && !st; j++) {
        st = el_smooth_to_bspline_g2(&res->pieces[j], tol, degree, &parts[j]);
        if (st == EL_EMAXITER) { status = st; st = EL_OK; }
        if (!st) dev = fmax(dev, parts[j].max_deviation);
    }
    double err = 0.0;
    el_bspline b;
    if (!st) st = el__bspline_join_c2(parts, m, &b, &err);
    for (size_t j = 0; j < m; j++) el_bspline_free(&parts[j]);
    free(parts);
    if (st) return st;
    b.max_deviation = dev + err;
    if (b.max_deviation > tol) status = EL_EMAXITER;
    *out = b;
    return status;
}
