/*
 * Jacobi sn, cn, dn and D = int sn^2 (with their k-derivatives) at many arguments
 * u_i, at a few flops per point: the addition theorems carry values from one
 * argument to the next instead of one AGM and one Carlson R_D per point (jacobi.c).
 *
 * Why the steps must be short (the bug of issue 12). One addition step from a to
 * a + b, with den = 1 - k^2 sa^2 sb^2,
 *   sn(a+b) = (sa cb db + sb ca da)/den,  cn(a+b) = (ca cb - sa sb da db)/den,
 *   dn(a+b) = (da db - k^2 sa sb ca cb)/den,  D(a+b) = D(a) + D(b) + sa sb sn(a+b),
 * is the exact flow u -> u + b on the curve sn^2 + cn^2 = 1, dn^2 + k^2 sn^2 = 1, so
 * an error along the curve (a phase error) is carried unchanged. An error off the
 * curve is not: with e1 = sa^2 + ca^2 - 1 and e2 = da^2 + k^2 sa^2 - 1 for the
 * rounded state (b exact), the identity
 *   (e1', e2') den = (e1 + sb^2 e2, k^2 sb^2 e1 + e2)
 * (expand the formulas; first order in e) multiplies those errors by up to
 *   g = (1 + max(1, k^2) sb^2) / den <= (1 + x^2) / (1 - x^2),  x = max(1, k) |b|
 * per step (the matrix's row sums; |sn b| <= |b|, and den >= 1 - x^2 since
 * k^2 sa^2 <= 1 for every k), and the errors of the values are those of e. Over many
 * steps that compounds: at x ~ 1 it is 10^16 within 30 steps (issue 12: k = 0.952,
 * 31 samples, 1.5 off; at k = 1 also 0/0). Here every chain of steps is short and
 * made of short steps: x <= X_GRID = 0.1 and at most RESEED = 32 steps from a fresh
 * evaluation give g^32 <= 1.9, so the values keep ~32 roundings of accuracy.
 *
 * Two walks:
 * - a grid u_i = u0 + z i with x = max(1, k)|z| <= X_GRID: one step per point (the
 *   discrete elastica's vertices, sampling grids);
 * - any u_i (any order; fast when sorted): anchors spaced H = X_ANCHOR / max(1, k)
 *   are reached by steps of H outwards from a fresh evaluation (anchor j by |j|
 *   steps), and each u_i from its nearest anchor by a step over |delta| <= H/2 whose
 *   sn, cn, dn, D come from their Maclaurin series (offset_series). The anchors are
 *   kept, so points going back and forth (the feet of noisy points along a curve:
 *   nearly sorted) reuse them instead of stepping again (measured: the orthogonal
 *   fit's feet took a fresh evaluation every 4 points when each return to an anchor
 *   was a step). A point more than RESEED anchors from the fresh evaluation, or more
 *   than MAX_JUMP past the anchors computed, gets a fresh evaluation: work per point
 *   stays O(1). Grids with larger steps take this walk too.
 */
#include "internal.h"

enum {
    RESEED = WALK_RESEED, /* addition steps after a fresh evaluation, at most */
    MAX_JUMP = 16         /* anchors stepped over before a fresh evaluation is cheaper */
};
#define X_GRID 0.1          /* grids step by the theorem when max(1, k)|z| <= X_GRID */
#define X_ANCHOR (1.0 / 16) /* anchor spacing max(1, k) H: offsets max(1, k)|delta| <= 1/32 */

/*
 * One addition step r = a + b (formulas above; algebraic identities, so they hold
 * for k > 1 as well). With ak, bk non-NULL the k-derivatives are carried by
 * differentiating the same formulas. Fills sn, cn, dn, D (E and am are not carried).
 * The walk's inner loop, one step a vertex: inlined into its callers (the same
 * arithmetic; the 42 discrete bench fits: 1.3 % fewer instructions).
 */
EL__INLINE void add_step(double k, const el_jacobi *a, const el_jacobi *ak,
                     const el_jacobi *b, const el_jacobi *bk, el_jacobi *r, el_jacobi *rk)
{
    const double m = k * k, ss = a->sn * b->sn, den = 1.0 - m * ss * ss, id = 1.0 / den;
    const double ns = a->sn * b->cn * b->dn + b->sn * a->cn * a->dn;
    const double nc = a->cn * b->cn - ss * a->dn * b->dn;
    const double nd = a->dn * b->dn - m * ss * a->cn * b->cn;
    r->sn = ns * id;
    r->cn = nc * id;
    r->dn = nd * id;
    r->D = a->D + b->D + ss * r->sn;
    if (rk) {
        const double ssk = ak->sn * b->sn + a->sn * bk->sn;
        const double denk = -2.0 * k * ss * ss - 2.0 * m * ss * ssk;
        const double nsk = ak->sn * b->cn * b->dn + a->sn * bk->cn * b->dn + a->sn * b->cn * bk->dn
                         + bk->sn * a->cn * a->dn + b->sn * ak->cn * a->dn + b->sn * a->cn * ak->dn;
        const double cc = a->cn * b->cn, cck = ak->cn * b->cn + a->cn * bk->cn;
        const double dd = a->dn * b->dn, ddk = ak->dn * b->dn + a->dn * bk->dn;
        const double nck = cck - ssk * dd - ss * ddk;
        const double ndk = ddk - 2.0 * k * ss * cc - m * (ssk * cc + ss * cck);
        rk->sn = (nsk - r->sn * denk) * id;
        rk->cn = (nck - r->cn * denk) * id;
        rk->dn = (ndk - r->dn * denk) * id;
        rk->D = ak->D + bk->D + ssk * r->sn + ss * rk->sn;
    }
}

/* Values (and k-derivatives) at -u from those at u: sn and D are odd, cn and dn even. */
static void negate(const el_jacobi *v, el_jacobi *r)
{
    r->sn = -v->sn; r->cn = v->cn; r->dn = v->dn; r->D = -v->D;
    r->am = -v->am; r->E = -v->E;
}

/* A fresh evaluation at u (jacobi.c); without k-derivatives by el__jacobi_values (the
 * walk's values carry no am: the same bits, without its atan2). */
static int fresh(const el__walk *wk, double u, el_jacobi *val, el_jacobi *dk)
{
    return wk->with_dk ? el__jacobi_eval_mod(&wk->mod, u, val, NULL, dk) : el__jacobi_values(&wk->mod, u, val);
}

/*
 * The Maclaurin coefficients of sn, cn, dn, D (and of their k-derivatives) from the
 * differential equations sn' = cn dn, cn' = -sn dn, dn' = -k^2 sn cn, D' = sn^2 by
 * Cauchy products, t_{n+1} = (product)_n / (n+1). Every product sums terms of one
 * sign (the coefficients alternate in the powers of u^2 like those of sin and cos),
 * so they are exact to a few roundings.
 *
 * Truncation (why these degrees): the coefficients of u^n / n! are polynomials in
 * k^2 of degree <= n/2 with nonnegative coefficients (Dumont 1979), so for
 * x = max(1, k)|delta| each term is bounded by the same term at k = 1 (tan for sn,
 * sec for cn and dn, tan - x for D) in the variable x, times max(1, k)^(-1) for sn
 * and ^(-3) for D; the k-derivative of a degree-d polynomial in k^2 adds at most a
 * factor 2d. At x <= 1/32 the first omitted terms (sn, D: x^11; cn, dn: x^12)
 * are below 1382/155925 x^11 = 2.5e-19 and 2702765/479001600 x^12 = 4.9e-21, times
 * at most 12 for the k-derivatives: far below the rounding of the sums they enter.
 */
enum { NT = 11 }; /* Taylor coefficients t_0..t_10 */

static void offset_series_init(el__walk *wk)
{
    const double k = wk->k, m = k * k;
    double s[NT] = {0}, c[NT] = {1}, d[NT] = {1}, D[NT] = {0};
    double sk[NT] = {0}, ck[NT] = {0}, dk[NT] = {0}, Dk[NT] = {0};
    for (int n = 0; n + 1 < NT; n++) {
        double cd = 0, sd = 0, sc = 0, ss = 0, cdk = 0, sdk = 0, sck = 0, ssk = 0;
        for (int i = 0; i <= n; i++) {
            const int j = n - i;
            cd += c[i] * d[j];
            sd += s[i] * d[j];
            sc += s[i] * c[j];
            ss += s[i] * s[j];
            cdk += ck[i] * d[j] + c[i] * dk[j];
            sdk += sk[i] * d[j] + s[i] * dk[j];
            sck += sk[i] * c[j] + s[i] * ck[j];
            ssk += 2.0 * s[i] * sk[j];
        }
        const double f = 1.0 / (n + 1);
        s[n + 1] = cd * f;
        c[n + 1] = -sd * f;
        d[n + 1] = -m * sc * f;
        D[n + 1] = ss * f;
        sk[n + 1] = cdk * f;
        ck[n + 1] = -sdk * f;
        dk[n + 1] = -(2.0 * k * sc + m * sck) * f;
        Dk[n + 1] = ssk * f;
    }
    for (int j = 0; j < 5; j++) {       /* sn: u^1..u^9, D: u^3..u^9 (j < 4) */
        wk->ser[0][j] = s[2 * j + 1];
        wk->ser[4][j] = sk[2 * j + 1];
        if (j < 4) { wk->ser[3][j] = D[2 * j + 3]; wk->ser[7][j] = Dk[2 * j + 3]; }
    }
    for (int j = 0; j < 6; j++) {       /* cn, dn: u^0..u^10 */
        wk->ser[1][j] = c[2 * j];
        wk->ser[2][j] = d[2 * j];
        wk->ser[5][j] = ck[2 * j];
        wk->ser[6][j] = dk[2 * j];
    }
    wk->have_series = 1;
}

/* Horner in t = delta^2 over the n coefficients of one series. */
static double horner(const double *a, int n, double t)
{
    double r = a[n - 1];
    for (int j = n - 2; j >= 0; j--) r = r * t + a[j];
    return r;
}

static void offset_series(const el__walk *wk, double delta, el_jacobi *b, el_jacobi *bk)
{
    const double t = delta * delta;
    b->sn = delta * horner(wk->ser[0], 5, t);
    b->cn = horner(wk->ser[1], 6, t);
    b->dn = horner(wk->ser[2], 6, t);
    b->D = delta * t * horner(wk->ser[3], 4, t);
    if (bk) {
        bk->sn = delta * horner(wk->ser[4], 5, t);
        bk->cn = horner(wk->ser[5], 6, t);
        bk->dn = horner(wk->ser[6], 6, t);
        bk->D = delta * t * horner(wk->ser[7], 4, t);
    }
}

int el__walk_init(el__walk *wk, double k, int with_dk, size_t n)
{
    int st = el__modulus_init(k, with_dk, &wk->mod);
    if (st) return st;
    wk->k = k;
    wk->with_dk = with_dk;
    wk->kappa = k > 1.0 ? k : 1.0;
    wk->mode = n < WALK_MIN_POINTS ? WALK_PLAIN : WALK_ANCHORED;
    wk->from_grid = 0;
    wk->jlo = 1; /* no anchor yet */
    wk->jhi = 0;
    wk->have_hstep = wk->have_series = 0;
    wk->H = X_ANCHOR / wk->kappa;
    return EL_OK;
}

int el__walk_grid(el__walk *wk, double u0, double z)
{
    wk->u0 = u0;
    wk->z = z;
    wk->next = 0;
    wk->from_grid = 1;
    if (wk->mode == WALK_PLAIN || !(wk->kappa * fabs(z) <= X_GRID)) return EL_OK;
    wk->mode = WALK_GRID;
    el_jacobi zk = {0, 0, 0, 0, 0, 0};
    int st = fresh(wk, z, &wk->zstep, &zk);
    wk->zstepk = zk;
    return st;
}

/* Steps of +H and -H, evaluated when first needed. */
static int hstep_init(el__walk *wk)
{
    el_jacobi h, hk = {0, 0, 0, 0, 0, 0};
    int st = fresh(wk, wk->H, &h, &hk);
    if (st) return st;
    wk->hstep[0] = h;
    wk->hstepk[0] = hk;
    negate(&h, &wk->hstep[1]);
    negate(&hk, &wk->hstepk[1]);
    wk->have_hstep = 1;
    return EL_OK;
}

/* Values at one arbitrary u from the nearest anchor (or a fresh evaluation). */
static int anchored(el__walk *wk, double u, el_jacobi *val, el_jacobi *vk)
{
    const double d = u - wk->ua; /* exact near the anchors (Sterbenz) */
    const double dj = d / wk->H;
    int st;
    if (wk->jlo > wk->jhi || !(fabs(dj) <= RESEED - 0.5) ||
        dj > wk->jhi + MAX_JUMP + 0.5 || dj < wk->jlo - MAX_JUMP - 0.5) {
        el_jacobi *a = &wk->anc[RESEED], *a_k = &wk->anck[RESEED];
        if ((st = fresh(wk, u, a, a_k))) return st;
        wk->ua = u;
        wk->jlo = wk->jhi = 0;
        *val = *a;
        if (vk) *vk = *a_k;
        return EL_OK;
    }
    const int j = (int)nearbyint(dj);
    if ((j > wk->jhi || j < wk->jlo) && !wk->have_hstep && (st = hstep_init(wk))) return st;
    el_jacobi *anc = wk->anc + RESEED, *anck = wk->anck + RESEED;
    const int with_dk = wk->with_dk;
    for (; wk->jhi < j; wk->jhi++)
        add_step(wk->k, &anc[wk->jhi], &anck[wk->jhi], &wk->hstep[0], &wk->hstepk[0], &anc[wk->jhi + 1],
                 with_dk ? &anck[wk->jhi + 1] : NULL);
    for (; wk->jlo > j; wk->jlo--)
        add_step(wk->k, &anc[wk->jlo], &anck[wk->jlo], &wk->hstep[1], &wk->hstepk[1], &anc[wk->jlo - 1],
                 with_dk ? &anck[wk->jlo - 1] : NULL);
    const double delta = d - j * wk->H;
    if (delta == 0.0) {
        *val = anc[j];
        if (vk) *vk = anck[j];
        return EL_OK;
    }
    if (!wk->have_series) offset_series_init(wk);
    el_jacobi b, bk;
    offset_series(wk, delta, &b, vk ? &bk : NULL);
    add_step(wk->k, &anc[j], &anck[j], &b, &bk, val, vk);
    return EL_OK;
}

/* The grid walk: one addition step per point, a fresh evaluation every RESEED. */
static int grid_values(el__walk *wk, size_t count, el_jacobi *val, el_jacobi *vk)
{
    const el_jacobi *prev = &wk->cur, *prevk = &wk->curk;
    for (size_t i = 0; i < count; i++, wk->next++) {
        if (wk->next % RESEED == 0) {
            int st = fresh(wk, wk->u0 + wk->z * (double)wk->next, &val[i], vk ? &vk[i] : NULL);
            if (st) return st;
        } else {
            add_step(wk->k, prev, prevk, &wk->zstep, &wk->zstepk, &val[i], vk ? &vk[i] : NULL);
        }
        prev = &val[i];
        prevk = vk ? &vk[i] : NULL;
    }
    if (count > 0) { /* the last value starts the next call */
        wk->cur = val[count - 1];
        if (vk) wk->curk = vk[count - 1];
    }
    return EL_OK;
}

/* The order in which the anchored walk visits the m <= SORT_CHUNK points u: by
 * increasing u, unless u is monotone already (insertion sort: nearly sorted points
 * cost a few moves each). Feet of noisy points on a curve passing close to itself
 * alternate between two stretches of it (measured: 7,600 fresh evaluations for
 * 10,000 points of one bench curve in data order, 2 per chunk sorted). */
enum { SORT_CHUNK = 64 };

static int visit_order(const double *u, size_t m, unsigned char *order)
{
    int up = 1, down = 1;
    for (size_t i = 1; i < m; i++) {
        up &= u[i] >= u[i - 1];
        down &= u[i] <= u[i - 1];
    }
    if (up || down) return 0;
    for (size_t i = 0; i < m; i++) {
        size_t j = i;
        for (; j > 0 && u[order[j - 1]] > u[i]; j--) order[j] = order[j - 1];
        order[j] = (unsigned char)i;
    }
    return 1;
}

int el__walk_values(el__walk *wk, size_t count, const double *u, el_jacobi *val, el_jacobi *dk)
{
    el_jacobi *vk = wk->with_dk ? dk : NULL;
    if (wk->mode == WALK_GRID) return grid_values(wk, count, val, vk);
    if (wk->mode == WALK_ANCHORED && !wk->from_grid) {
        for (size_t a = 0; a < count; a += SORT_CHUNK) {
            const size_t m = count - a < SORT_CHUNK ? count - a : SORT_CHUNK;
            unsigned char order[SORT_CHUNK];
            const int sorted = visit_order(u + a, m, order);
            for (size_t r = 0; r < m; r++) {
                const size_t i = a + (sorted ? order[r] : r);
                int st = anchored(wk, u[i], &val[i], vk ? &vk[i] : NULL);
                if (st) return st;
            }
        }
        wk->next += count;
        return EL_OK;
    }
    for (size_t i = 0; i < count; i++, wk->next++) {
        const double ui = wk->from_grid ? wk->u0 + wk->z * (double)wk->next : u[i];
        int st = wk->mode == WALK_PLAIN ? fresh(wk, ui, &val[i], vk ? &vk[i] : NULL)
                                        : anchored(wk, ui, &val[i], vk ? &vk[i] : NULL);
        if (st) return st;
    }
    return EL_OK;
}
