/*
 * Keyline preparation, seed 000 §5.3: PCA plane fit of a 3D polyline, the
 * equilateral open-polygon resampling, the PCA re-normalisation of the 2D
 * polygon and the RDP-style inflection estimate (steps (1)-(4)).
 */
#include "internal.h"

#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

/* ------------------------------------------------------------------ PCA */

/*
 * Principal component analysis of n points of dimension dim (2 or 3),
 * interleaved in p: centroid (5.1), eigenvalues (decreasing) and unit
 * eigenvectors of the covariance matrix C = (1/n) sum (p_k - c)(p_k - c)^t
 * (gsl_eigen_symmv). axes[i*dim + j] = component j of eigenvector i.
 * The points are centred and scaled by their largest |coordinate - centroid|
 * before forming C, so 1e-9- and 1e9-sized data are treated alike.
 * Returns EL_ESINGULAR when every point equals the centroid to rounding.
 */
static int pca(const double *p, size_t n, int dim, double *centroid, double *axes, double *evals)
{
    double c[3] = {0, 0, 0}, corr[3] = {0, 0, 0}, big = 0.0, scale = 0.0;
    for (size_t k = 0; k < n; k++)
        for (int j = 0; j < dim; j++)
            if (fabs(p[k * dim + j]) > big) big = fabs(p[k * dim + j]);
    /* sums of p / 2^e (2^e ~ big, exact): no overflow near DBL_MAX, no precision
     * lost to denormals */
    const int e = big > 0.0 ? ilogb(big) : 0;
    for (size_t k = 0; k < n; k++)
        for (int j = 0; j < dim; j++) c[j] += ldexp(p[k * dim + j], -e);
    for (int j = 0; j < dim; j++) c[j] /= (double)n;
    /* second pass: corrected mean (the centroid of data far from the origin) */
    for (size_t k = 0; k < n; k++)
        for (int j = 0; j < dim; j++) corr[j] += ldexp(p[k * dim + j], -e) - c[j];
    for (int j = 0; j < dim; j++) c[j] = ldexp(c[j] + corr[j] / (double)n, e);
    for (size_t k = 0; k < n; k++)
        for (int j = 0; j < dim; j++) {
            double d = fabs(p[k * dim + j] - c[j]);
            if (d > scale) scale = d;
        }
    if (!isfinite(scale)) return EL_EDOM;   /* a spread beyond double's range */
    if (!(scale > 32.0 * DBL_EPSILON * big) || scale == 0.0) return EL_ESINGULAR;

    double a[9] = {0}, vec[9], val[3];
    for (size_t k = 0; k < n; k++) {
        double d[3];
        for (int j = 0; j < dim; j++) d[j] = (p[k * dim + j] - c[j]) / scale;
        for (int i = 0; i < dim; i++)
            for (int j = 0; j <= i; j++) a[i * dim + j] += d[i] * d[j];
    }
    for (int i = 0; i < dim; i++)
        for (int j = 0; j <= i; j++) {
            a[i * dim + j] /= (double)n;
            a[j * dim + i] = a[i * dim + j];
        }

    el__gsl_quiet();
    gsl_eigen_symmv_workspace *w = gsl_eigen_symmv_alloc((size_t)dim);
    if (!w) return EL_ENOMEM;
    gsl_matrix_view A = gsl_matrix_view_array(a, (size_t)dim, (size_t)dim);
    gsl_matrix_view V = gsl_matrix_view_array(vec, (size_t)dim, (size_t)dim);
    gsl_vector_view L = gsl_vector_view_array(val, (size_t)dim);
    int gs = gsl_eigen_symmv(&A.matrix, &L.vector, &V.matrix, w);
    gsl_eigen_symmv_free(w);
    if (gs == GSL_SUCCESS) gs = gsl_eigen_symmv_sort(&L.vector, &V.matrix, GSL_EIGEN_SORT_VAL_DESC);
    if (gs != GSL_SUCCESS) return EL_EINTERNAL;

    for (int i = 0; i < dim; i++) {
        /* C is positive semi-definite; its eigenvalues (units^2) must be doubles */
        if (!isfinite(fmax(val[i], 0.0) * scale * scale)) return EL_EDOM;
    }
    for (int i = 0; i < dim; i++) {
        centroid[i] = c[i];
        evals[i] = fmax(val[i], 0.0) * scale * scale;
        double nrm = 0.0;
        for (int j = 0; j < dim; j++) nrm += vec[j * dim + i] * vec[j * dim + i];
        nrm = sqrt(nrm);
        for (int j = 0; j < dim; j++) axes[i * dim + j] = vec[j * dim + i] / nrm;  /* column i */
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ plane fit */

static double dot3(const double *a, const double *b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void cross3(const double *a, const double *b, double *out)
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

int el_plane_fit(const double *xyz, size_t n, el_frame *frame, double *xy_out,
                 double *rms_out_of_plane)
{
    if (!xyz || n < 3 || n > SIZE_MAX / 3) return EL_EINVAL;
    if (el__all_finite(xyz, 3 * n) != EL_OK) return EL_EINVAL;

    double c[3], ax[9], ev[3];
    int st = pca(xyz, n, 3, c, ax, ev);
    if (st != EL_OK) return st;

    el_frame f;
    memcpy(f.origin, c, sizeof c);
    memcpy(f.e1, ax, 3 * sizeof(double));
    memcpy(f.e3, ax + 6, 3 * sizeof(double));
    memcpy(f.lambda, ev, sizeof ev);
    /* e1 from the first to the last point (seed 000 §5.3 fixes the signs by
     * the scanner's axes, Figure 9; we need a rule that depends on the data only) */
    double chord[3] = {xyz[3 * (n - 1)] - xyz[0], xyz[3 * (n - 1) + 1] - xyz[1],
                       xyz[3 * (n - 1) + 2] - xyz[2]};
    if (dot3(f.e1, chord) < 0)
        for (int j = 0; j < 3; j++) f.e1[j] = -f.e1[j];
    /* e3: positive z component, else positive y, else positive x */
    const double tiny = 1e-9;
    double sgn = fabs(f.e3[2]) > tiny ? f.e3[2] : fabs(f.e3[1]) > tiny ? f.e3[1] : f.e3[0];
    if (sgn < 0)
        for (int j = 0; j < 3; j++) f.e3[j] = -f.e3[j];
    cross3(f.e3, f.e1, f.e2);   /* right-handed: e1 x e2 = e3 */

    /* rms = zmax sqrt(mean (z/zmax)^2): no overflow of z^2 */
    double ss = 0.0, zmax = 0.0;
    for (size_t k = 0; k < n; k++) {
        double d[3] = {xyz[3 * k] - c[0], xyz[3 * k + 1] - c[1], xyz[3 * k + 2] - c[2]};
        zmax = fmax(zmax, fabs(dot3(f.e3, d)));
    }
    for (size_t k = 0; k < n && zmax > 0.0; k++) {
        double d[3] = {xyz[3 * k] - c[0], xyz[3 * k + 1] - c[1], xyz[3 * k + 2] - c[2]};
        double z = dot3(f.e3, d) / zmax;
        ss += z * z;
    }
    for (size_t k = 0; k < n && xy_out; k++) {
        double d[3] = {xyz[3 * k] - c[0], xyz[3 * k + 1] - c[1], xyz[3 * k + 2] - c[2]};
        xy_out[2 * k] = dot3(f.e1, d);
        xy_out[2 * k + 1] = dot3(f.e2, d);
    }
    if (rms_out_of_plane) *rms_out_of_plane = zmax * sqrt(ss / (double)n);
    if (frame) *frame = f;
    return EL_OK;
}

static int frame_ok(const el_frame *f)
{
    return el__all_finite(f->origin, 3) == EL_OK && el__all_finite(f->e1, 3) == EL_OK &&
           el__all_finite(f->e2, 3) == EL_OK && el__all_finite(f->e3, 3) == EL_OK;
}

int el_frame_project(const el_frame *frame, size_t n, const double *xyz, double *xy, double *z)
{
    if (!frame || (n > 0 && (!xyz || !xy)) || n > SIZE_MAX / 3 || !frame_ok(frame)) return EL_EINVAL;
    if (el__all_finite(xyz, 3 * n) != EL_OK) return EL_EINVAL;
    for (size_t k = 0; k < n; k++) {
        double d[3] = {xyz[3 * k] - frame->origin[0], xyz[3 * k + 1] - frame->origin[1],
                       xyz[3 * k + 2] - frame->origin[2]};
        /* p' = (e1 e2 e3)^t (p - p_bar), seed 000 §5.3 */
        double x = dot3(frame->e1, d), y = dot3(frame->e2, d);
        if (z) z[k] = dot3(frame->e3, d);
        xy[2 * k] = x;
        xy[2 * k + 1] = y;
        if (!isfinite(x) || !isfinite(y) || (z && !isfinite(z[k]))) return EL_EDOM;
    }
    return EL_OK;
}

int el_frame_to_3d(const el_frame *frame, size_t n, const double *xy, double *xyz)
{
    if (!frame || (n > 0 && (!xy || !xyz)) || n > SIZE_MAX / 3 || !frame_ok(frame)) return EL_EINVAL;
    if (el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;
    for (size_t k = n; k-- > 0;) {   /* backwards: harmless if xyz aliases xy's storage start */
        double x = xy[2 * k], y = xy[2 * k + 1];
        for (int j = 0; j < 3; j++)
            xyz[3 * k + j] = frame->origin[j] + x * frame->e1[j] + y * frame->e2[j];
        if (el__all_finite(xyz + 3 * k, 3)) return EL_EDOM;
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ 2D PCA */

int el_pca_normalize(const double *xy, size_t n, el_frame2d *frame, double *xy_out)
{
    if (!xy || n < 2 || n > SIZE_MAX / 2) return EL_EINVAL;
    if (el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;
    double c[2], ax[4], ev[2];
    int st = pca(xy, n, 2, c, ax, ev);
    if (st != EL_OK) return st;
    el_frame2d f;
    f.origin[0] = c[0];
    f.origin[1] = c[1];
    f.mu[0] = ev[0];
    f.mu[1] = ev[1];
    /* the diagonal of (f1 f2) positive: f1.x > 0 (f1.y > 0 if f1.x = 0), and
     * f2 = f1 turned by +90 degrees has f2.y = f1.x > 0 */
    double s = (ax[0] > 0 || (ax[0] == 0 && ax[1] > 0)) ? 1.0 : -1.0;
    f.f1[0] = s * ax[0];
    f.f1[1] = s * ax[1];
    f.f2[0] = -f.f1[1];
    f.f2[1] = f.f1[0];
    if (xy_out) {
        st = el_frame2d_to_local(&f, n, xy, xy_out);
        if (st != EL_OK) return st;
    }
    if (frame) *frame = f;
    return EL_OK;
}

static int frame2d_ok(const el_frame2d *f)
{
    return el__all_finite(f->origin, 2) == EL_OK && el__all_finite(f->f1, 2) == EL_OK &&
           el__all_finite(f->f2, 2) == EL_OK;
}

int el_frame2d_to_local(const el_frame2d *frame, size_t n, const double *xy, double *xy_local)
{
    if (!frame || (n > 0 && (!xy || !xy_local)) || n > SIZE_MAX / 2 || !frame2d_ok(frame))
        return EL_EINVAL;
    if (el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;
    for (size_t k = 0; k < n; k++) {
        /* q'' = (f1 f2)^t (q - q_bar), seed 000 §5.3 */
        double dx = xy[2 * k] - frame->origin[0], dy = xy[2 * k + 1] - frame->origin[1];
        xy_local[2 * k] = frame->f1[0] * dx + frame->f1[1] * dy;
        xy_local[2 * k + 1] = frame->f2[0] * dx + frame->f2[1] * dy;
        if (el__all_finite(xy_local + 2 * k, 2)) return EL_EDOM;
    }
    return EL_OK;
}

int el_frame2d_to_parent(const el_frame2d *frame, size_t n, const double *xy_local, double *xy)
{
    if (!frame || (n > 0 && (!xy || !xy_local)) || n > SIZE_MAX / 2 || !frame2d_ok(frame))
        return EL_EINVAL;
    if (el__all_finite(xy_local, 2 * n) != EL_OK) return EL_EINVAL;
    for (size_t k = 0; k < n; k++) {
        double u = xy_local[2 * k], v = xy_local[2 * k + 1];
        xy[2 * k] = frame->origin[0] + u * frame->f1[0] + v * frame->f2[0];
        xy[2 * k + 1] = frame->origin[1] + u * frame->f1[1] + v * frame->f2[1];
        if (el__all_finite(xy + 2 * k, 2)) return EL_EDOM;
    }
    return EL_OK;
}

/* ------------------------------------------------------------------ resampling */

/*
 * The resampling needs, for each vertex A_k, the intersection of the circle
 * |X - A_k| = r with the polyline that lies furthest along it. GSL has no
 * spatial search, so this is written by hand: a binary tree of bounding boxes
 * over contiguous runs of segments (a segment tree), searched right child
 * first and pruned when the circle cannot meet a box. A query then costs
 * O(log n) on ordinary curves instead of a scan of the whole polyline.
 */
typedef struct seg_tree {
    const double *p;    /* polyline points, 2 * (nseg + 1) */
    size_t nseg;
    double *box;        /* 4 per node (xmin, xmax, ymin, ymax); node i has children 2i+1, 2i+2 */
} seg_tree;

static void tree_build(seg_tree *t, size_t node, size_t lo, size_t hi)
{
    double *b = t->box + 4 * node;
    if (hi - lo == 1) {
        const double *p = t->p + 2 * lo;
        b[0] = fmin(p[0], p[2]);
        b[1] = fmax(p[0], p[2]);
        b[2] = fmin(p[1], p[3]);
        b[3] = fmax(p[1], p[3]);
        return;
    }
    size_t mid = lo + (hi - lo) / 2;
    tree_build(t, 2 * node + 1, lo, mid);
    tree_build(t, 2 * node + 2, mid, hi);
    const double *l = t->box + 4 * (2 * node + 1), *r = l + 4;
    b[0] = fmin(l[0], r[0]);
    b[1] = fmax(l[1], r[1]);
    b[2] = fmin(l[2], r[2]);
    b[3] = fmax(l[3], r[3]);
}

/*
 * Largest root t in [0, 1] of |P + t (Q - P) - A| = r with t > tmin; -1 if none.
 * With d = Q - P, f = P - A: the foot t0 = -(f.d)/|d|^2 and the roots
 * t0 +- sqrt(r^2 - (f x d)^2/|d|^2)/|d|. This form loses no precision when
 * |f| >> r (a long segment, a small r); |f|^2 - r^2 would lose all of r^2 once
 * |f| is ~1e8 r.
 */
static double seg_circle(const double *P, const double *Q, const double *A, double r, double tmin)
{
    double dx = Q[0] - P[0], dy = Q[1] - P[1];
    double fx = P[0] - A[0], fy = P[1] - A[1];
    double a = dx * dx + dy * dy;
    if (a == 0.0) return -1.0;                     /* repeated point: no segment */
    double t0 = -(fx * dx + fy * dy) / a;
    double cr = fx * dy - fy * dx;                 /* |f x d| = distance(A, line) |d| */
    double disc = r * r - cr * (cr / a);
    if (disc < 0.0) return -1.0;
    double del = sqrt(disc / a);
    double cand[2] = {t0 + del, t0 - del};
    for (int i = 0; i < 2; i++) {
        double t = cand[i];
        /* one Newton step on g(t) = |f + t d|^2 - r^2 so |X - A| = r to rounding */
        double gx = fx + t * dx, gy = fy + t * dy;
        double g = gx * gx + gy * gy - r * r, dg = 2.0 * (gx * dx + gy * dy);
        if (dg != 0.0) {
            double tn = t - g / dg;
            if (fabs(tn - t) < 1e-6) t = tn;
        }
        const double slack = 1e-12;   /* roots at a shared vertex: keep them, then clamp */
        if (t >= -slack && t <= 1.0 + slack) {
            t = fmin(fmax(t, 0.0), 1.0);
            if (t > tmin) return t;
        }
    }
    return -1.0;
}

/*
 * Search the subtree for the intersection (j, t) with the largest position,
 * restricted to j > jmin or (j == jmin and t > tmin). Returns 1 if found.
 */
static int tree_query(const seg_tree *tr, size_t node, size_t lo, size_t hi, const double *A,
                      double r, size_t jmin, double tmin, size_t *jout, double *tout)
{
    if (hi <= jmin) return 0;
    const double *b = tr->box + 4 * node;
    double ddx = fmax(fmax(b[0] - A[0], 0.0), A[0] - b[1]);
    double ddy = fmax(fmax(b[2] - A[1], 0.0), A[1] - b[3]);
    double r2 = r * r;
    if (ddx * ddx + ddy * ddy > r2 * (1.0 + 1e-9)) return 0;        /* box outside the circle */
    double fx = fmax(fabs(b[0] - A[0]), fabs(b[1] - A[0]));
    double fy = fmax(fabs(b[2] - A[1]), fabs(b[3] - A[1]));
    if (fx * fx + fy * fy < r2 * (1.0 - 1e-9)) return 0;            /* box inside the circle */
    if (hi - lo == 1) {
        double t = seg_circle(tr->p + 2 * lo, tr->p + 2 * lo + 2, A, r, lo == jmin ? tmin : -1.0);
        if (t < 0.0) return 0;
        *jout = lo;
        *tout = t;
        return 1;
    }
    size_t mid = lo + (hi - lo) / 2;
    if (tree_query(tr, 2 * node + 2, mid, hi, A, r, jmin, tmin, jout, tout)) return 1;
    return tree_query(tr, 2 * node + 1, lo, mid, A, r, jmin, tmin, jout, tout);
}

void el_resample_free(el_resample_result *res)
{
    if (!res) return;
    free(res->xy);
    free(res->s);
    memset(res, 0, sizeof *res);
}

int el_resample_equilateral(const double *xy, size_t n, double r, el_resample_result *out)
{
    if (!xy || !out || n < 2 || !isfinite(r) || !(r > 0.0)) return EL_EINVAL;
    if (el__too_many(n, 16, sizeof(double))) return EL_EINVAL;   /* the segment tree: 16 n */
    if (el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;

    size_t nseg = n - 1;
    double *p = el__alloc(n, 2, sizeof *p);
    double *cum = el__alloc(n, 1, sizeof *cum);
    double *box = el__alloc(nseg, 16, sizeof *box);
    double *vxy = NULL, *vs = NULL;
    int st = EL_OK;
    if (!p || !cum || !box) { st = EL_ENOMEM; goto done; }

    /* A_1 is the left end: the end point with the smaller x' (seed 000 §5.3) */
    int reversed = xy[2 * (n - 1)] < xy[0];
    cum[0] = 0.0;
    for (size_t k = 1; k < n; k++) {
        size_t a = reversed ? n - k : k - 1, b = reversed ? n - 1 - k : k;
        cum[k] = cum[k - 1] + hypot(xy[2 * b] - xy[2 * a], xy[2 * b + 1] - xy[2 * a + 1]);
    }
    const double length = cum[n - 1];
    if (!isfinite(length)) { st = EL_EDOM; goto done; }      /* beyond double's range */
    if (!(length > 0.0)) { st = EL_ESINGULAR; goto done; }   /* all points equal */
    /* bounded work: |A_{k+1} - A_k| = r and the positions increase by >= r */
    if (length / r > (double)(EL_RESAMPLE_MAX_VERTICES - 1)) { st = EL_EDOM; goto done; }
    /* the walk in units of 2^e ~ the length (exact scaling): r^2 and the squared
     * distances neither overflow nor underflow for any input scale */
    const int e = ilogb(length);
    const double rs = ldexp(r, -e);
    for (size_t k = 0; k < n; k++) {
        size_t src = reversed ? n - 1 - k : k;
        p[2 * k] = ldexp(xy[2 * src], -e);
        p[2 * k + 1] = ldexp(xy[2 * src + 1], -e);
        cum[k] = ldexp(cum[k], -e);
    }

    seg_tree tr = {p, nseg, box};
    tree_build(&tr, 0, 0, nseg);

    size_t cap = 64, m = 0;
    vxy = el__alloc(cap, 2, sizeof *vxy);
    vs = el__alloc(cap, 1, sizeof *vs);
    if (!vxy || !vs) { st = EL_ENOMEM; goto done; }
    vxy[0] = p[0];
    vxy[1] = p[1];
    vs[0] = 0.0;
    m = 1;
    size_t j = 0;
    double t = 0.0;
    for (;;) {
        size_t jn;
        double tn;
        const double A[2] = {vxy[2 * (m - 1)], vxy[2 * (m - 1) + 1]};
        /* A_{k+1}: at distance r, ahead of A_k, nearest the far end; none -> A_k is the stop point */
        if (!tree_query(&tr, 0, 0, nseg, A, rs, j, t, &jn, &tn)) break;
        if (m == EL_RESAMPLE_MAX_VERTICES) { st = EL_EDOM; goto done; }   /* (rounding only) */
        if (m == cap) {
            double *nx = el__realloc(vxy, 2 * cap, 2, sizeof *vxy);
            if (!nx) { st = EL_ENOMEM; goto done; }
            vxy = nx;
            double *ns = el__realloc(vs, 2 * cap, 1, sizeof *vs);
            if (!ns) { st = EL_ENOMEM; goto done; }
            vs = ns;
            cap *= 2;
        }
        const double *P = p + 2 * jn, *Q = P + 2;
        vxy[2 * m] = P[0] + tn * (Q[0] - P[0]);
        vxy[2 * m + 1] = P[1] + tn * (Q[1] - P[1]);
        vs[m] = cum[jn] + tn * (cum[jn + 1] - cum[jn]);
        m++;
        j = jn;
        t = tn;
    }
    if (m < 2) { st = EL_EINVAL; goto done; }   /* r larger than the curve */
    /* never a silent truncation: the walk stops only where every point further
     * along is within r of the stop point (else some would be at distance r), so
     * the far end is (checked to 1e-6 r) */
    {
        const double *E = p + 2 * nseg, *S = vxy + 2 * (m - 1);
        if (hypot(E[0] - S[0], E[1] - S[1]) > rs * (1.0 + 1e-6)) { st = EL_EDOM; goto done; }
    }
    for (size_t k = 0; k < m; k++) {   /* back to input units */
        vxy[2 * k] = ldexp(vxy[2 * k], e);
        vxy[2 * k + 1] = ldexp(vxy[2 * k + 1], e);
        vs[k] = ldexp(vs[k], e);
    }

    out->n = m;
    out->xy = vxy;
    out->s = vs;
    out->reversed = reversed;
    out->remainder = fmax(length - vs[m - 1], 0.0);
    vxy = vs = NULL;
done:
    free(vxy);
    free(vs);
    free(p);
    free(cum);
    free(box);
    return st;
}

/* ------------------------------------------------------------------ inflection */

/* Distance from X to the segment A-B. */
static double seg_dist(const double *X, const double *A, const double *B)
{
    double dx = B[0] - A[0], dy = B[1] - A[1];
    double wx = X[0] - A[0], wy = X[1] - A[1];
    double L2 = dx * dx + dy * dy;
    double t = L2 > 0 ? (wx * dx + wy * dy) / L2 : 0.0;
    t = fmin(fmax(t, 0.0), 1.0);
    return hypot(wx - t * dx, wy - t * dy);
}

/* Side of vertex x relative to the chord between vertices i and j, oriented
 * by increasing index: +1 left, -1 right, 0 on the line. */
static int side_of(const double *xy, size_t x, size_t i, size_t j)
{
    if (i > j) { size_t tmp = i; i = j; j = tmp; }
    const double *A = xy + 2 * i, *B = xy + 2 * j, *X = xy + 2 * x;
    double c = (B[0] - A[0]) * (X[1] - A[1]) - (B[1] - A[1]) * (X[0] - A[0]);
    return (c > 0) - (c < 0);
}

/* The vertex strictly between i and j farthest from segment i-j; its distance in *d. */
static size_t farthest(const double *xy, size_t i, size_t j, double *d)
{
    size_t lo = i < j ? i : j, hi = i < j ? j : i, best = lo + 1;
    double bd = -1.0;
    for (size_t k = lo + 1; k < hi; k++) {
        double dk = seg_dist(xy + 2 * k, xy + 2 * i, xy + 2 * j);
        if (dk > bd) { bd = dk; best = k; }
    }
    *d = bd;
    return best;
}

/*
 * Evidence of an inflection between the apex (point 3) and the end e: descend
 * from the apex towards e, each time to the vertex farthest from the chord on
 * the apex's side sigma, until some vertex between lies on the other side
 * (-sigma) of the current chord. A convex arc never shows one. *level is the
 * descent depth where it was found (INT_MAX if never), *wrong the largest
 * such distance there.
 */
static void side_evidence(const double *xy, size_t apex, size_t e, int sigma, double tol,
                          int *level, double *wrong)
{
    size_t a = apex;
    *level = INT_MAX;
    *wrong = 0.0;
    for (int lvl = 0;; lvl++) {
        size_t lo = a < e ? a : e, hi = a < e ? e : a, f = a;
        double w = 0.0, fd = 0.0;
        for (size_t k = lo + 1; k < hi; k++) {
            double d = seg_dist(xy + 2 * k, xy + 2 * a, xy + 2 * e);
            int sk = side_of(xy, k, a, e);
            if (sk == -sigma) w = fmax(w, d);
            else if (sk == sigma && d > fd) { fd = d; f = k; }
        }
        if (w > tol) { *level = lvl; *wrong = w; return; }
        if (f == a) return;                      /* nothing left on the apex's side */
        a = f;
    }
}

int el_find_inflection(const double *xy, size_t n, int side, el_inflection *out)
{
    if (!xy || !out || n < 4 || n > SIZE_MAX / 2 || side < -1 || side > 1) return EL_EINVAL;
    if (el__all_finite(xy, 2 * n) != EL_OK) return EL_EINVAL;

    double ext = 0.0, big = 0.0;
    for (size_t k = 0; k < n; k++)
        for (int c = 0; c < 2; c++) {
            ext = fmax(ext, fabs(xy[2 * k + c] - xy[c]));
            big = fmax(big, fabs(xy[2 * k + c]));
        }
    if (!isfinite(ext)) return EL_EDOM;   /* a spread beyond double's range */
    if (!(ext > 32.0 * DBL_EPSILON * big) || ext == 0.0) return EL_ESINGULAR;
    if (ext > 1e150 || ext < 1e-150) {
        /* the estimate is scale invariant: run it on a copy scaled by 2^-e (exact),
         * where the squared distances it compares neither overflow nor underflow */
        double *c = el__alloc(n, 2, sizeof *c);
        if (!c) return EL_ENOMEM;
        const int e = ilogb(ext);
        for (size_t k = 0; k < 2 * n; k++) c[k] = ldexp(xy[k], -e);
        int st = el_find_inflection(c, n, side, out);
        free(c);
        return st;
    }
    const double tol = 64.0 * DBL_EPSILON * (big + ext);
    size_t last = n - 1;
    if (hypot(xy[2 * last] - xy[0], xy[2 * last + 1] - xy[1]) <= tol) return EL_EDOM;

    /* (1) point 3: the vertex farthest from the segment joining the end points */
    double d3;
    size_t p3 = farthest(xy, 0, last, &d3);
    if (d3 <= tol) return EL_EDOM;                 /* collinear: no inflection */
    int sigma = side_of(xy, p3, 0, last);
    /* point 2: the end on the side with the inflection (the paper decides by eye) */
    size_t p2;
    if (side > 0) p2 = last;
    else if (side < 0) p2 = 0;
    else {
        int ll, lr;
        double wl, wr;
        side_evidence(xy, p3, 0, sigma, tol, &ll, &wl);
        side_evidence(xy, p3, last, sigma, tol, &lr, &wr);
        if (ll == INT_MAX && lr == INT_MAX) return EL_EDOM;   /* both sides convex arcs */
        p2 = (lr < ll || (lr == ll && wr >= wl)) ? last : 0;
    }
    if ((p2 > p3 ? p2 - p3 : p3 - p2) <= 1) return EL_EDOM;

    /* (2)-(3): interval (P, P+1) = (a, b); b's side relative to the previous chord is sigma */
    size_t a = p2, b = p3;
    int it = 0;
    for (;;) {
        double dc;
        size_t c = farthest(xy, a, b, &dc);        /* point P+2 */
        int sc = side_of(xy, c, a, b);
        if (sc != 0 && sc == sigma) {              /* same side as P+1 was: switch P and P+1 */
            size_t tmp = a; a = b; b = tmp;
        }
        a = b;                                     /* next: P <- P+1, P+1 <- P+2 */
        b = c;
        sigma = sc;
        it++;
        /* (4) P+1 and P+2 adjacent: the inflection is estimated at P+2 */
        if ((a > b ? a - b : b - a) <= 1) break;
    }
    out->index = b;
    out->neighbor = a;
    out->apex = p3;
    out->end = p2;
    out->iterations = it;
    return EL_OK;
}
