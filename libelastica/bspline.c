/*
 * B-splines: the el_bspline type (evaluation, derivatives, curvature), the
 * natural C2 cubic interpolating a polyline, and C2 joins of B-splines by knot
 * removal (el_smooth_chain_to_bspline's pieces). The certified approximation of
 * an elastica is in bspline_approx.c, the shared basis functions in
 * bspline_basis.h.
 *
 * Why hand-written evaluation: GSL 2.7's gsl_bspline builds clamped knot
 * vectors only from distinct breakpoints (no multiplicities) and evaluates
 * scalar basis functions, not curves, so de Boor's algorithm (Piegl & Tiller,
 * The NURBS Book, A2.1/A2.2/A3.2, derivative poles (3.8)) is written here.
 * The interpolation's tridiagonal solve is by hand too (see there).
 */
#include "internal.h"
#include "bspline_basis.h"
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ type */

void el_bspline_free(el_bspline *b)
{
    if (!b) return;
    free(b->poles);
    free(b->knots);
    free(b->mults);
    memset(b, 0, sizeof *b);
}

int el_bspline_alloc(el_bspline *b, int degree, int dim, size_t npoles, size_t nknots)
{
    if (!b || degree < 1 || dim < 1 || nknots < 2 || npoles < (size_t)degree + 1)
        return EL_EINVAL;
    if (el__too_many(npoles, (size_t)dim, sizeof(double)) || el__too_many(nknots, 1, sizeof(double)))
        return EL_ENOMEM;   /* no such array fits in memory */
    el_bspline t;
    memset(&t, 0, sizeof t);
    t.degree = degree;
    t.dim = dim;
    t.npoles = npoles;
    t.nknots = nknots;
    t.max_deviation = -1.0;
    t.poles = calloc((size_t)dim * npoles, sizeof *t.poles);
    t.knots = calloc(nknots, sizeof *t.knots);
    t.mults = calloc(nknots, sizeof *t.mults);
    if (!t.poles || !t.knots || !t.mults) {
        el_bspline_free(&t);
        return EL_ENOMEM;
    }
    *b = t;
    return EL_OK;
}

int el_bspline_check(const el_bspline *b)
{
    if (!b || b->degree < 1 || b->dim < 1 || b->nknots < 2 || !b->poles || !b->knots ||
        !b->mults || b->npoles < (size_t)b->degree + 1)
        return EL_EINVAL;
    /* sizes the caller claims to hold: the flat knot vector and the poles must fit
     * in memory (and the evaluation's workspace, flat knots + (degree+1) dim) */
    size_t flat, work;
    if (el__size_add(b->npoles, (size_t)b->degree + 1, &flat) ||
        el__too_many(flat, 1, sizeof(double)) ||
        el__too_many(b->npoles, (size_t)b->dim, sizeof(double)) ||
        el__size_mul((size_t)b->degree + 1, (size_t)b->dim, &work) ||
        el__size_add(flat, work, &work) || el__too_many(work, 1, sizeof(double)))
        return EL_EINVAL;
    size_t total = 0;
    for (size_t i = 0; i < b->nknots; i++) {
        const long m = b->mults[i];
        const long mmax = (i == 0 || i + 1 == b->nknots) ? (long)b->degree + 1 : b->degree;
        if (m < 1 || m > mmax || !isfinite(b->knots[i])) return EL_EINVAL;
        if (i > 0 && !(b->knots[i] > b->knots[i - 1])) return EL_EINVAL;
        if (el__size_add(total, (size_t)m, &total)) return EL_EINVAL;
    }
    if (total != flat) return EL_EINVAL;
    /* knot differences (the evaluation divides by them) must be doubles */
    if (!isfinite(b->knots[b->nknots - 1] - b->knots[0])) return EL_EINVAL;
    return el__all_finite(b->poles, (size_t)b->dim * b->npoles);
}

int el_bspline_flat_knots(const el_bspline *b, double *flat)
{
    int st = el_bspline_check(b);
    if (st) return st;
    if (!flat) return EL_EINVAL;
    size_t j = 0;
    for (size_t i = 0; i < b->nknots; i++)
        for (int m = 0; m < b->mults[i]; m++) flat[j++] = b->knots[i];
    return EL_OK;
}

/* ------------------------------------------------------------------ evaluation */

/*
 * Derivative of order r (0 <= r <= p) at t on span k: the level-r derivative
 * poles P^(r)_i = (p-r+1)(P^(r-1)_{i+1} - P^(r-1)_i) / (U_{i+p+1} - U_{i+r}),
 * i = k-p..k-r (Piegl & Tiller (3.8)/A3.3), then de Boor's algorithm of degree
 * p-r on the knots U_{i+r}. w holds (p+1)*dim doubles.
 */
static void deboor_deriv(const double *U, const double *P, int p, int dim, size_t k,
                         double t, int r, double *w, double *out)
{
    const size_t base = k - (size_t)p;
    for (int j = 0; j <= p; j++)
        memcpy(w + (size_t)j * (size_t)dim, P + (base + (size_t)j) * (size_t)dim,
               (size_t)dim * sizeof *w);
    for (int l = 1; l <= r; l++)           /* differencing: w[j] <- P^(l)_{base+j} */
        for (int j = 0; j <= p - l; j++) {
            const size_t i = base + (size_t)j;
            const double f = (double)(p - l + 1) / (U[i + (size_t)p + 1] - U[i + (size_t)l]);
            for (int c = 0; c < dim; c++)
                w[(size_t)j * dim + c] = f * (w[(size_t)(j + 1) * dim + c] - w[(size_t)j * dim + c]);
        }
    const int d = p - r;                    /* de Boor, degree d, knots U'_i = U_{i+r} */
    const double *V = U + r;
    const size_t kk = k - (size_t)r, b2 = kk - (size_t)d;   /* b2 == base */
    for (int l = 1; l <= d; l++)
        for (int j = d; j >= l; j--) {
            const double a0 = V[b2 + (size_t)j], a1 = V[b2 + (size_t)j + (size_t)(d - l) + 1];
            const double alpha = (t - a0) / (a1 - a0);
            for (int c = 0; c < dim; c++)
                w[(size_t)j * dim + c] = (1.0 - alpha) * w[(size_t)(j - 1) * dim + c] +
                                         alpha * w[(size_t)j * dim + c];
        }
    memcpy(out, w + (size_t)d * (size_t)dim, (size_t)dim * sizeof *out);
}

static size_t flat_count(const el_bspline *b) { return b->npoles + (size_t)b->degree + 1; }

int el_bspline_derivative(const el_bspline *b, int order, size_t n, const double *t, double *out)
{
    int st = el_bspline_check(b);
    if (st || order < 0 || (n > 0 && (!t || !out)) || el__too_many(n, (size_t)b->dim, sizeof *out))
        return EL_EINVAL;
    if (n == 0) return EL_OK;
    if ((st = el__all_finite(t, n))) return st;
    const double a = b->knots[0], z = b->knots[b->nknots - 1];
    const double slack = 1e-12 * (fabs(a) + fabs(z) + (z - a));   /* rounding of t, clamped */
    for (size_t i = 0; i < n; i++)
        if (t[i] < a - slack || t[i] > z + slack) return EL_EDOM;
    const int p = b->degree, dim = b->dim;
    if (order > p) {
        memset(out, 0, n * (size_t)dim * sizeof *out);
        return EL_OK;
    }
    /* sizes checked by el_bspline_check */
    double *U = malloc((flat_count(b) + (size_t)(p + 1) * (size_t)dim) * sizeof *U);
    if (!U) return EL_ENOMEM;
    double *w = U + flat_count(b);
    el_bspline_flat_knots(b, U);
    for (size_t i = 0; i < n && !st; i++) {
        const double ti = fmin(fmax(t[i], a), z);
        const size_t k = find_span(U, b->npoles, p, ti);
        deboor_deriv(U, b->poles, p, dim, k, ti, order, w, out + i * (size_t)dim);
        /* differences of poles far apart, over knots close together, can leave
         * double's range (derivatives; de Boor's convex combinations cannot) */
        if (el__all_finite(out + i * (size_t)dim, (size_t)dim)) st = EL_EDOM;
    }
    free(U);
    return st;
}

int el_bspline_eval(const el_bspline *b, size_t n, const double *t, double *pts)
{
    return el_bspline_derivative(b, 0, n, t, pts);
}

int el_bspline_curvature(const el_bspline *b, size_t n, const double *t, double *kappa)
{
    int st = el_bspline_check(b);
    if (st || b->dim != 2 || b->degree < 2 || (n > 0 && (!t || !kappa))) return EL_EINVAL;
    if (n == 0) return EL_OK;
    double *d = el__alloc(n, 4, sizeof *d);
    if (!d) return EL_ENOMEM;
    if ((st = el_bspline_derivative(b, 1, n, t, d)) ||
        (st = el_bspline_derivative(b, 2, n, t, d + 2 * n))) {
        free(d);
        return st;
    }
    for (size_t i = 0; i < n && !st; i++) {
        const double x1 = d[2 * i], y1 = d[2 * i + 1];
        const double x2 = d[2 * n + 2 * i], y2 = d[2 * n + 2 * i + 1];
        const double v = hypot(x1, y1);
        if (!(v > 0.0)) { st = EL_ESINGULAR; break; }
        /* det(B', B'') / |B'|^3 with B' normalised first (no overflow of |B'|^3) */
        kappa[i] = ((x1 / v) * y2 - (y1 / v) * x2) / v / v;
        if (!isfinite(kappa[i])) st = EL_EDOM;
    }
    free(d);
    return st;
}

/* ------------------------------------------------------------------ C2 interpolation */

/*
 * C2 cubic with chord-length parameters u_0 = 0, u_i = u_{i-1} + |D_i - D_{i-1}|;
 * flat knots u_0 x4, u_1..u_{n-2}, u_{n-1} x4 (and the midpoint of the end span next
 * to an order-3 end), m poles, P_0 = D_0, P_{m-1} = D_{n-1}. Unknowns P_1..P_{m-2}.
 * With the derivative poles of Piegl & Tiller (3.8), Q_i = 3 (P_{i+1} - P_i) /
 * (U_{i+4} - U_{i+1}), B'(u_0) = Q_0 and B''(u_0) = 2 (Q_1 - Q_0) / (U_4 - U_2), so with
 * a = U_4 - U_1, c = U_5 - U_2, e = U_4 - U_2:
 *   B'(u_0) = V   <=> P_1 = P_0 + a V / 3,
 *   B''(u_0) = A  <=> (a + c) P_1 - a P_2 = c P_0 - a c e A / 6
 * (A = 0: the natural end), both (order 3) <=> P_1 as above and
 *   P_2 - P_1 = c (V + e A / 2) / 3,
 * mirrored at u_{n-1} (the parameter reversed: V changes sign, A does not); between
 * them B(u_i) = D_i (i = 1..n-2; three non-zero basis functions): a tridiagonal
 * system, totally positive in its interpolation rows, solved without pivoting.
 */
/* One end's rows (two for order 3: rows[0] next to the end, then rows[1]): diagonal,
 * the coefficient of the unknown one further in, of the one nearer the end (order 3's
 * second row), right-hand side (x, y); in the parameter t = u / len (derivatives in u
 * times len, len^2). a: the knot span next to the end; c: the one after; e: the
 * second-derivative span. Returns the number of rows. */
typedef struct { double diag, in, out, rx, ry; } end_row_t;
static int end_rows(const el_bspline_end *end, double a, double c, double e, double len,
                    const double *P, end_row_t rows[2])
{
    if (end && (end->order == 1 || end->order == 3)) {
        const double vx = len * end->value[0], vy = len * end->value[1];
        rows[0] = (end_row_t){1.0, 0.0, 0.0, P[0] + a * vx / 3.0, P[1] + a * vy / 3.0};
        if (end->order == 1) return 1;
        const double ax = len * len * end->value2[0], ay = len * len * end->value2[1];
        rows[1] = (end_row_t){1.0, 0.0, -1.0, c * (vx + 0.5 * e * ax) / 3.0, c * (vy + 0.5 * e * ay) / 3.0};
        return 2;
    }
    const double w = end ? a * c * e * len * len / 6.0 : 0.0;
    rows[0] = (end_row_t){a + c, -a, 0.0, c * P[0] - (end ? w * end->value[0] : 0.0),
                          c * P[1] - (end ? w * end->value[1] : 0.0)};
    return 1;
}

static int bad_end(const el_bspline_end *end)
{
    return end && ((end->order < 1 || end->order > 3) || el__all_finite(end->value, 2) ||
                   (end->order == 3 && el__all_finite(end->value2, 2)));
}

int el_bspline_interpolate_c2(const double *xy, size_t n, el_bspline *out)
{
    return el_bspline_interpolate_c2_ends(xy, n, NULL, NULL, out);
}

int el_bspline_interpolate_c2_ends(const double *xy, size_t n, const el_bspline_end *start,
                                   const el_bspline_end *end, el_bspline *out)
{
    if (!xy || !out || n < 2 || el__too_many(n, 2, sizeof(double))) return EL_EINVAL;
    if (el__all_finite(xy, 2 * n)) return EL_EINVAL;
    if (bad_end(start) || bad_end(end)) return EL_EINVAL;
    /* es, ee: the extra knot of an order-3 end; nu unknowns P_1..P_{m-2}, m = nu + 2 */
    const size_t es = start && start->order == 3, ee = end && end->order == 3;
    const size_t nk = n + es + ee, m = n + 2 + es + ee, nu = m - 2;
    el_bspline b;
    int st = el_bspline_alloc(&b, 3, 2, m, nk);
    if (st) return st;
    double *U = el__alloc(nk + 1, 7, sizeof *U);   /* m + 4 flat knots, 6 nu for the solve */
    if (!U) { el_bspline_free(&b); return EL_ENOMEM; }
    double *diag = U + m + 4, *sup = diag + nu, *sub = sup + nu, *rx = sub + nu, *ry = rx + nu;
    double *sol = ry + nu;
    /* the vertices' chord-length parameters into U first, then the distinct knots with
     * the extra ones: an end span's midpoint (its thirds when one span has both) */
    U[0] = 0.0;
    for (size_t i = 1; i < n; i++) {
        const double h = hypot(xy[2 * i] - xy[2 * i - 2], xy[2 * i + 1] - xy[2 * i - 1]);
        U[i] = U[i - 1] + h;
        if (!isfinite(U[i])) { st = EL_EDOM; goto done; }   /* length beyond double's range */
        if (!(U[i] > U[i - 1])) { st = EL_ESINGULAR; goto done; }
    }
    for (size_t i = 0; i < n; i++) b.knots[i + es + (ee && i + 1 == n)] = U[i];
    const double share = es && ee && n == 2 ? 1.0 / 3.0 : 0.5;
    if (es) b.knots[1] = U[0] + share * (U[1] - U[0]);
    if (ee) b.knots[nk - 2] = U[n - 1] - share * (U[n - 1] - U[n - 2]);
    for (size_t i = 0; i < nk; i++) b.mults[i] = (i == 0 || i + 1 == nk) ? 4 : 1;
    el_bspline_flat_knots(&b, U);
    /* the system in the parameter u / length (the same curve; no underflow of the
     * knot differences' products for tiny coordinates, no overflow for huge ones) */
    const double len = b.knots[nk - 1];
    for (size_t i = 0; i < m + 4; i++) U[i] /= len;
    const double P0x = xy[0], P0y = xy[1], Pnx = xy[2 * n - 2], Pny = xy[2 * n - 1];
    for (size_t i = 0; i < nu; i++) sub[i] = sup[i] = 0.0;
    end_row_t rows[2];
    const int ns = end_rows(start, U[4] - U[1], U[5] - U[2], U[4] - U[2], len, xy, rows);
    for (int r = 0; r < ns; r++) {
        diag[r] = rows[r].diag;
        sup[r] = rows[r].in;
        if (r) sub[r - 1] = rows[r].out;
        rx[r] = rows[r].rx;
        ry[r] = rows[r].ry;
    }
    for (size_t i = 1; i + 1 < n; i++) {   /* interpolation rows: P_{i+es}, P_{i+es+1}, P_{i+es+2} */
        double N[4];
        const size_t r = i + es;
        basis_funs(U, 3 + r, 3, U[3 + r], N);   /* N_{r..r+3}; N_{r+3}(u_i) = 0 */
        sub[r - 1] = N[0]; diag[r] = N[1]; sup[r] = N[2];
        rx[r] = xy[2 * i]; ry[r] = xy[2 * i + 1];
    }
    {   /* the end's rows, from the last unknown inwards; its derivative runs backwards */
        el_bspline_end back;
        if (end) {
            back = *end;
            if (back.order != 2) { back.value[0] = -back.value[0]; back.value[1] = -back.value[1]; }
        }
        const int ne = end_rows(end ? &back : NULL, U[m + 2] - U[m - 1], U[m + 1] - U[m - 2],
                                U[m + 1] - U[m - 1], len, xy + 2 * n - 2, rows);
        for (int r = 0; r < ne; r++) {
            const size_t j = nu - 1 - (size_t)r;
            diag[j] = rows[r].diag;
            sub[j - 1] = rows[r].in;
            if (r) sup[j] = rows[r].out;
            rx[j] = rows[r].rx;
            ry[j] = rows[r].ry;
        }
    }
    /* Gaussian elimination without pivoting (the Thomas algorithm), both right-hand
     * sides at once. By hand: GSL's gsl_linalg_solve_tridiag is the same
     * elimination, but reports a zero pivot to the process-wide error handler,
     * which a caller may have set to abort. sol holds the eliminated sup. */
    for (size_t i = 0; i < nu; i++) {
        const double piv = i ? diag[i] - sub[i - 1] * sol[i - 1] : diag[0];
        if (!(fabs(piv) > 0.0) || !isfinite(piv)) { st = EL_ESINGULAR; goto done; }
        sol[i] = i + 1 < nu ? sup[i] / piv : 0.0;
        rx[i] = (rx[i] - (i ? sub[i - 1] * rx[i - 1] : 0.0)) / piv;
        ry[i] = (ry[i] - (i ? sub[i - 1] * ry[i - 1] : 0.0)) / piv;
    }
    for (size_t i = nu - 1; i-- > 0;) {
        rx[i] -= sol[i] * rx[i + 1];
        ry[i] -= sol[i] * ry[i + 1];
    }
    for (size_t j = 0; j < nu; j++) {
        b.poles[2 * (j + 1)] = rx[j];
        b.poles[2 * (j + 1) + 1] = ry[j];
    }
    if (el__all_finite(b.poles + 2, 2 * nu)) { st = EL_EDOM; goto done; }   /* overflow */
    b.poles[0] = P0x; b.poles[1] = P0y;
    b.poles[2 * (m - 1)] = Pnx; b.poles[2 * (m - 1) + 1] = Pny;
done:
    free(U);
    if (st) { el_bspline_free(&b); return st; }
    b.max_deviation = -1.0;   /* interpolates the vertices; no distance to the polyline claimed */
    *out = b;
    return EL_OK;
}

/* ------------------------------------------------------------------ C2 joins */

/*
 * Remove the knot U[r] (multiplicity s, r its last index) num times from the
 * planar curve (poles P, *np of them, flat knots U), Piegl & Tiller, The NURBS
 * Book, A5.8, always: returns the largest of its removability distances (0 to
 * rounding when the curve is C^{p-s+num} there).
 */
static double remove_knot(double *U, double *P, size_t *np, int p, size_t r, int s, int num)
{
    const long n = (long)*np - 1, m = n + p + 1, ord = p + 1;
    const double u = U[r];
    long first = (long)r - p, last = (long)r - s;
    const long fout = (2 * (long)r - s - p) / 2;
    double temp[2 * (2 * MAXDEG_FIT + 4)], emax = 0.0;
    for (int t = 0; t < num; t++) {
        const long off = first - 1;
        temp[0] = P[2 * off]; temp[1] = P[2 * off + 1];
        temp[2 * (last + 1 - off)] = P[2 * (last + 1)];
        temp[2 * (last + 1 - off) + 1] = P[2 * (last + 1) + 1];
        long i = first, j = last, ii = 1, jj = last - off;
        while (j - i > t) {
            const double ai = (u - U[i]) / (U[i + ord + t] - U[i]);
            const double aj = (u - U[j - t]) / (U[j + ord] - U[j - t]);
            for (int c = 0; c < 2; c++) {
                temp[2 * ii + c] = (P[2 * i + c] - (1.0 - ai) * temp[2 * (ii - 1) + c]) / ai;
                temp[2 * jj + c] = (P[2 * j + c] - aj * temp[2 * (jj + 1) + c]) / (1.0 - aj);
            }
            i++; ii++; j--; jj--;
        }
        double d;
        if (j - i < t) {
            d = hypot(temp[2 * (ii - 1)] - temp[2 * (jj + 1)], temp[2 * (ii - 1) + 1] - temp[2 * (jj + 1) + 1]);
        } else {
            const double ai = (u - U[i]) / (U[i + ord + t] - U[i]);
            d = hypot(P[2 * i] - (ai * temp[2 * (ii + t + 1)] + (1.0 - ai) * temp[2 * (ii - 1)]),
                      P[2 * i + 1] - (ai * temp[2 * (ii + t + 1) + 1] + (1.0 - ai) * temp[2 * (ii - 1) + 1]));
        }
        emax = fmax(emax, d);
        i = first; j = last;
        while (j - i > t) {
            P[2 * i] = temp[2 * (i - off)]; P[2 * i + 1] = temp[2 * (i - off) + 1];
            P[2 * j] = temp[2 * (j - off)]; P[2 * j + 1] = temp[2 * (j - off) + 1];
            i++; j--;
        }
        first--; last++;
    }
    for (long k = (long)r + 1; k <= m; k++) U[k - num] = U[k];
    long j = fout, i = fout;
    for (int k = 1; k < num; k++) { if (k % 2 == 1) i++; else j--; }
    for (long k = i + 1; k <= n; k++, j++) { P[2 * j] = P[2 * k]; P[2 * j + 1] = P[2 * k + 1]; }
    *np -= (size_t)num;
    return emax;
}

int el__bspline_join_c2(const el_bspline *parts, size_t count, el_bspline *out, double *err)
{
    if (!parts || !count || !out || !err) return EL_EINVAL;
    const int p = parts[0].degree;
    if (p < 3 || p > MAXDEG_FIT) return EL_EINVAL;
    size_t np = 0, nu = 0;
    for (size_t j = 0; j < count; j++) {
        const el_bspline *b = &parts[j];
        if (el_bspline_check(b) || b->degree != p || b->dim != 2 || b->mults[0] != p + 1 ||
            b->mults[b->nknots - 1] != p + 1)
            return EL_EINVAL;
        np += b->npoles;
        nu += b->npoles + (size_t)p + 1;
    }
    double *U = malloc(nu * sizeof *U), *P = malloc(2 * np * sizeof *P);
    if (!U || !P) { free(U); free(P); return EL_ENOMEM; }
    /* the C0 chain: joint knots of multiplicity p, one pole per joint (the next
     * part's first), then two removals per joint */
    size_t ku = 0, kp = 0;
    double s0 = 0.0, gap = 0.0;
    for (size_t j = 0; j < count; j++) {
        const el_bspline *b = &parts[j];
        const size_t fl = b->npoles + (size_t)p + 1;
        double *flat = malloc(fl * sizeof *flat);
        if (!flat) { free(U); free(P); return EL_ENOMEM; }
        el_bspline_flat_knots(b, flat);
        const double a = flat[0];
        const size_t k0 = j ? (size_t)p + 1 : 0, k1 = j + 1 < count ? fl - 1 : fl;
        for (size_t k = k0; k < k1; k++) U[ku++] = s0 + (flat[k] - a);
        if (j) {
            gap = fmax(gap, hypot(P[2 * kp - 2] - b->poles[0], P[2 * kp - 1] - b->poles[1]));
            kp--;
        }
        memcpy(P + 2 * kp, b->poles, 2 * b->npoles * sizeof *P);
        kp += b->npoles;
        s0 += flat[fl - 1] - a;
        free(flat);
    }
    /* each joint: its value is the last of its run of p equal knots */
    double e = gap;
    for (size_t r = (size_t)p + 1; r + (size_t)p + 1 < kp + (size_t)p + 1;) {
        size_t q = r;
        while (U[q + 1] == U[r]) q++;
        if (q - r + 1 == (size_t)p) {
            e = fmax(e, remove_knot(U, P, &kp, p, q, p, 2));
            r = q - 1;   /* the knot now has p - 2 copies ending at q - 2 */
        } else {
            r = q + 1;
        }
    }
    if (kp < (size_t)p + 1 || kp > np) { free(U); free(P); return EL_EINVAL; }
    /* distinct knots */
    const size_t nflat = kp + (size_t)p + 1;
    size_t nk = 1;
    for (size_t i = 1; i < nflat; i++) nk += U[i] != U[i - 1];
    el_bspline b;
    int st = el_bspline_alloc(&b, p, 2, kp, nk);
    if (!st) {
        for (size_t i = 0; i < 2 * kp; i++) b.poles[i] = P[i];
        size_t d = 0;
        b.knots[0] = U[0]; b.mults[0] = 1;
        for (size_t i = 1; i < nflat; i++) {
            if (U[i] == U[i - 1]) b.mults[d]++;
            else { b.knots[++d] = U[i]; b.mults[d] = 1; }
        }
        b.max_deviation = -1.0;
        *out = b;
        *err = e;
    }
    free(U); free(P);
    return st;
}
