"""Each point's nearest point on a B-spline, and its signed distance (+ = left of the
travel): a discrete fit's exported cubic measured against the points (FitResult.
cubic_distances, the CLI's report, the FreeCAD Fit feature's Rms, MaxError, Distances and
FootPoints). Not through FreeCAD's Part: its Curve.parameter and distToShape give the same
feet but search every span for every point (6.3 / 16.7 s for 5000 points, 159 s for
20000); the B-spline's evaluation and derivatives are the library's."""
from __future__ import annotations

import numpy

__all__ = ["drawn_distances", "nearest_on"]


def np():
    return numpy


# The one foot search of the binding: coarse samples (a B-spline's sieved spans,
# _nearest_feet; a curve's equal arc-length samples, curve_feet; the nearest of a few,
# nearest_samples), then each foot refined in the bracket its samples give (refine_feet).
# Written here, not scipy's minimize_scalar or GSL's gsl_min: the binding depends on numpy
# alone (FreeCAD's Python has no scipy), the C library's feet (fit_feet.c) are internal
# to its fits, and one vectorised search refines every point's foot at once.

# refine_feet's iterations at most: its bisections halve a bracket to rounding in ~55
FOOT_STEPS = 64
# a Newton step this small against the bracket it began in ends the search (quadratic
# convergence: the next would be ~1e-20 of it)
FOOT_TOL = 1e-10
# a Newton step this small is taken whether or not the point comes nearer: the squared
# distances it changes by (~1e-14 of it) are the curve's evaluation's rounding, the slope
# it follows is not (a foot kept to nearer points only stopped ~1e-7 off, slope 1e-7)
FOOT_TRUST = 1e-6


def bspline_at(bspline):
    """refine_feet's ``at`` of a B-spline: B(t), and with ``derivatives`` B'(t), B''(t)."""
    def at(t, derivatives=False):
        P = bspline.evaluate(t)
        return (P, bspline.derivative(t, 1), bspline.derivative(t, 2)) if derivatives else P
    return at


def curve_at(curve):
    """refine_feet's ``at`` of a curve of arc length s (points / angle / curvature: a
    SmoothElastica, HermiteChain, ElasticSpline): gamma(s), and with ``derivatives`` its unit
    tangent T and kappa N."""
    n = np()

    def at(s, derivatives=False):
        P = curve.points(s)
        if not derivatives:
            return P
        th = curve.angle(s)
        T = n.c_[n.cos(th), n.sin(th)]
        return P, T, curve.curvature(s)[:, None] * n.c_[-T[:, 1], T[:, 0]]
    return at


def refine_feet(at, data, t, lo, hi):
    """Each point's foot on a curve (``at``: bspline_at, curve_at) refined in its bracket:
    the nearest point of data[i] in [lo[i], hi[i]] from t[i], where the squared distance
    has one minimum in the bracket (a dip of coarse samples and its neighbours; elsewhere
    the local minimum downhill of t). Safeguarded Newton on (C(t) - p) . C'(t) = 0 (its
    derivative |C'|^2 + (C - p) . C''): each step's sign of the slope halves the bracket's
    uphill side away, a step that leaves the bracket (or where the derivative is not
    positive) is a bisection of the downhill side instead, and a trial point not nearer
    bounds the bracket on its side (the next step from the same foot: a bisection). The
    foot moves only where nearer, or by a Newton step below FOOT_TRUST of the bracket
    (where the distances differ by rounding), so the result is never farther than t but
    by rounding. Ends where a Newton step is below FOOT_TOL of the bracket, or the bracket
    is rounding wide. Returns (t, C(t), squared distances)."""
    n = np()
    data = n.asarray(data, dtype=float)
    lo = n.array(lo, dtype=float, copy=True) * n.ones(len(data))
    hi = n.array(hi, dtype=float, copy=True) * n.ones(len(data))
    t = n.clip(n.asarray(t, dtype=float), lo, hi)
    P, D1, D2 = at(t, True)
    d2 = n.sum((P - data) ** 2, axis=1)
    width = hi - lo
    tol = FOOT_TOL * width
    live = n.arange(len(t))
    failed = n.zeros(len(t), dtype=bool)     # the last trial from t was not nearer
    for _ in range(FOOT_STEPS):
        if not len(live):
            break
        tl, ll, hl = t[live], lo[live], hi[live]
        r = P[live] - data[live]
        g = n.sum(r * D1[live], axis=1)
        h = n.sum(D1[live] ** 2, axis=1) + n.sum(r * D2[live], axis=1)
        ll, hl = n.where(g < 0.0, tl, ll), n.where(g > 0.0, tl, hl)
        tn = tl - g / n.where(h > 0.0, h, 1.0)
        newton = (h > 0.0) & (tn >= ll) & (tn <= hl) & ~failed[live]
        tn = n.where(newton, tn, n.where(g > 0.0, 0.5 * (ll + tl), 0.5 * (tl + hl)))
        Pn, D1n, D2n = at(tn, True)
        dn = n.sum((Pn - data[live]) ** 2, axis=1)
        closer = dn < d2[live]
        moved = closer | (newton & (n.abs(tn - tl) <= FOOT_TRUST * width[live]))
        hl = n.where(~moved & (tn > tl), tn, hl)
        ll = n.where(~moved & (tn < tl), tn, ll)
        c = live[moved]
        t[c], P[c], D1[c], D2[c], d2[c] = tn[moved], Pn[moved], D1n[moved], D2n[moved], dn[moved]
        lo[live], hi[live], failed[live] = ll, hl, ~moved
        done = ((newton & (n.abs(tn - tl) <= tol[live])) | (tn == tl)
                | (hl - ll <= 4.0 * n.spacing(n.maximum(n.abs(ll), n.abs(hl)))))
        live = live[~done]
    return t, P, d2


def centred_table(samples):
    """The squared distances of points from ``samples`` (k, 2) about the samples' centre o
    (no cancellation at large offsets): a function of points q (m, 2) giving (its (m, k)
    table |s - o|^2 - 2 (q - o) . (s - o), the points' |q - o|^2), one matrix product
    (4 x faster than the differences' squares summed); the table plus |q - o|^2 is the
    squared distance."""
    n = np()
    o = samples.mean(axis=0)
    sm = samples - o
    n2 = n.einsum("ij,ij->i", sm, sm)

    def table(data):
        q = data - o
        return n2[None, :] - 2.0 * (q @ sm.T), n.einsum("ij,ij->i", q, q)
    return table


def nearest_samples(data, samples):
    """Each point's nearest of ``samples`` (k, 2), its index: the argmin of
    :func:`centred_table`'s, 1024 points at a time (bounded memory)."""
    n = np()
    table = centred_table(samples)
    out = n.empty(len(data), dtype=n.intp)
    for a in range(0, len(data), 1024):
        out[a:a + 1024] = n.argmin(table(data[a:a + 1024])[0], axis=1)
    return out


# curve_feet's samples where the caller has none: at least CURVE_SAMPLES, and enough that
# no step turns the tangent more than STEP_TURN rad (the samples are at equal arc length,
# so the step's turning at the largest curvature counts: max |kappa| x length, the turning
# of the whole length at its tightest curl, at least its total turning). 257 samples of a
# k = 0.9 .. 3 elastica of length 40 turning up to 19 rad a step (mu 25 .. 400) missed
# feet, 0.0337 too far (rel. 0.0016 of its size) at k = 0.999; 33 of a k = 1.8 loop 0.136.
# At most MAX_SAMPLES (2^16 + 1: the samples 1 MB, the tables 8 MB): a fitted elastica of
# length 1 at mu = 1e12 asked 4e6 samples (3.2 s and 314 MB for 3 points), at mu = 1e20
# 4e10 (out of memory). Capped, a distance is still within half a step, length / 2^17, of
# the true one (|gamma'| = 1: a sample lies that near the foot along the curve).
CURVE_SAMPLES = 257
STEP_TURN = 0.5
MAX_SAMPLES = (1 << 16) + 1


def turning_samples(curve) -> int:
    """curve_feet's default sample count for ``curve``: CURVE_SAMPLES, or more where
    max |kappa| x length / STEP_TURN asks (the exact largest curvature of its SmoothElastica
    pieces, shape.py; of another curve, the largest of 4097 samples), at most MAX_SAMPLES."""
    import math
    from .shape import _piece_max_curvature
    n, L = np(), float(curve.length)
    try:
        kmax = max(_piece_max_curvature(p) for p in getattr(curve, "pieces", [curve]))
    except AttributeError:
        kmax = float(n.max(n.abs(curve.curvature(n.linspace(0.0, L, 4097)))))
    want = kmax * L / STEP_TURN
    if not want < MAX_SAMPLES - 1:      # also inf / NaN (int() of them raises)
        return MAX_SAMPLES
    return max(CURVE_SAMPLES, int(math.ceil(want)) + 1)


# curve_feet's sieve (where points x samples exceed FEET_TABLE): blocks of FEET_BLOCK,
# FEET_BLOCK^2, ... consecutive samples, their boxes
FEET_BLOCK = 8
FEET_TABLE = 1 << 17


def _feet_d2(qc, qq, sm, n2, p, j):
    """curve_feet's squared distances of points p from samples j (index arrays that
    broadcast), about the samples' centre (qc, sm: centred; qq, n2: their squared norms) and
    elementwise, so a table and a list of pairs round alike (a BLAS product's FMA does not:
    one row of it, a matrix-vector product, rounds otherwise than the same row of many)."""
    n = np()
    return n.maximum(n2[j] - 2.0 * (qc[p, 0] * sm[j, 0] + qc[p, 1] * sm[j, 1]) + qq[p], 0.0)


def _table_dips(qc, qq, sm, n2, step):
    """curve_feet's candidate (point, sample) pairs from the full (points x samples) table,
    (rows, samples) at a time: every sample within one step of the nearest (squared: no square
    root of the table) that is nearer than both its neighbours. Sorted by point and sample."""
    n = np()
    k = len(sm)
    rows = max(1, min(1024, (1 << 20) // k))    # bounded (rows, k) tables
    who, at_j = [], []
    cols = n.arange(k)
    for a in range(0, len(qc), rows):
        d2 = _feet_d2(qc, qq, sm, n2, n.arange(a, min(a + rows, len(qc)))[:, None], cols[None, :])
        near = n.sqrt(d2.min(axis=1)) + step
        r, j = n.nonzero(d2 <= (near * near)[:, None])
        here = d2[r, j]
        dip = ((j == 0) | (here <= d2[r, n.maximum(j - 1, 0)])) & \
            ((j == k - 1) | (here <= d2[r, n.minimum(j + 1, k - 1)]))
        who.append(r[dip] + a)
        at_j.append(j[dip])
    return n.concatenate(who), n.concatenate(at_j)


def _sieved_dips(qc, qq, sm, n2, step):
    """_table_dips' pairs, the same to the bit, without the table: blocks of FEET_BLOCK
    consecutive samples and coarser blocks of FEET_BLOCK of those, their boxes; from the
    coarsest level down, a point keeps the blocks whose box lies within one step of an
    upper bound of its nearest distance (its nearest block middle sample so far), then the
    samples of the finest blocks it keeps. The nearest sample's blocks are always kept (their
    boxes lie nearer than it), so are all within one step of it; the bound's margin covers the
    distances' rounding. Sorted by point and sample, as the table's."""
    n = np()
    k, B = len(sm), FEET_BLOCK
    levels = [(n.minimum.reduceat(sm, n.arange(0, k, B), axis=0),
               n.maximum.reduceat(sm, n.arange(0, k, B), axis=0))]
    while len(levels[-1][0]) > B:
        lo, hi = levels[-1]
        s = n.arange(0, len(lo), B)
        levels.append((n.minimum.reduceat(lo, s, axis=0), n.maximum.reduceat(hi, s, axis=0)))
    slack = 1e-12 * (qq + float(n2.max()))      # the distances' rounding, generously
    nfine = len(levels[0][0])
    rows = max(16, min(4096, (1 << 18) // nfine))  # bounded: (rows x nfine) pairs at most
    who, at_j = [], []
    inner = n.arange(-1, B + 1)
    for a in range(0, len(qc), rows):
        pts = n.arange(a, min(a + rows, len(qc)))
        U = n.full(len(pts), n.inf)
        pj, bj = None, None
        size = B ** len(levels)                 # samples a block of the coarsest level
        for lo, hi in levels[::-1]:
            if pj is not None and not len(pj):
                break
            if pj is None:
                pj, bj = n.repeat(pts, len(lo)), n.tile(n.arange(len(lo)), len(pts))
            else:
                pj = n.repeat(pj, B)
                bj = (bj[:, None] * B + n.arange(B)[None, :]).ravel()
                keep = bj < len(lo)
                pj, bj = pj[keep], bj[keep]
            first = n.flatnonzero(n.r_[True, pj[1:] != pj[:-1]])
            dm = _feet_d2(qc, qq, sm, n2, pj, n.minimum(bj * size + size // 2, k - 1))
            U[pj[first] - a] = n.minimum(U[pj[first] - a], n.minimum.reduceat(dm, first))
            far = n.sqrt(U[pj - a]) + step
            gap = n.maximum(n.maximum(lo[bj] - qc[pj], qc[pj] - hi[bj]), 0.0)
            keep = n.sum(gap * gap, axis=1) <= far * far * (1.0 + 1e-12) + slack[pj]
            pj, bj = pj[keep], bj[keep]
            size //= B
        if not len(pj):
            continue
        cols = bj[:, None] * B + inner[None, :]
        d2 = _feet_d2(qc, qq, sm, n2, pj[:, None], n.clip(cols, 0, k - 1))
        d2[(cols < 0) | (cols >= k)] = n.inf
        mid = d2[:, 1:-1]
        first = n.flatnonzero(n.r_[True, pj[1:] != pj[:-1]])
        near = n.sqrt(n.minimum.reduceat(mid.min(axis=1), first)) + step
        reach = n.repeat(near * near, n.diff(n.r_[first, len(pj)]))
        r, i = n.nonzero((mid <= reach[:, None]) & (mid <= d2[:, :-2]) & (mid <= d2[:, 2:]))
        who.append(pj[r])
        at_j.append(bj[r] * B + i)
    if not who:
        return n.zeros(0, dtype=n.intp), n.zeros(0, dtype=n.intp)
    return n.concatenate(who), n.concatenate(at_j)


def curve_feet(curve, data, samples=None):
    """Each point's nearest point on a curve of arc length (a SmoothElastica, HermiteChain,
    ElasticSpline: points / angle / curvature / length): (distances, feet's s). Coarse
    samples (``samples``, (k, 2) at equal arc length over [0, length], else
    :func:`turning_samples` of them: no step turning more than STEP_TURN), and every sample
    nearer the point than both its neighbours and within one sample step of the nearest
    (|gamma(s) - p| moves at most |ds|: the nearest point lies within half a step of a
    sample that near) refined in the bracket of its neighbours (refine_feet); the nearest
    of those feet wins. The samples are found from the (points x samples) table where it
    has at most FEET_TABLE entries, else through a sieve of blocks of samples (the same
    samples, without the table: _sieved_dips)."""
    n = np()
    data = n.asarray(data, dtype=float)
    L = float(curve.length)
    if samples is None:
        samples = curve.points(n.linspace(0.0, L, turning_samples(curve)))
    samples = n.asarray(samples, dtype=float)
    k = len(samples)
    step = L / (k - 1)
    o = samples.mean(axis=0)                     # about the centre: no cancellation at offsets
    sm, qc = samples - o, data - o
    n2, qq = n.einsum("ij,ij->i", sm, sm), n.einsum("ij,ij->i", qc, qc)
    dips = _table_dips if len(data) * k <= FEET_TABLE else _sieved_dips
    p, j = dips(qc, qq, sm, n2, step)
    s, _, d2 = refine_feet(curve_at(curve), data[p], j * step, n.maximum(j - 1, 0) * step,
                           n.minimum(j + 1, k - 1) * step)
    order = n.lexsort((d2, p))                   # each point's nearest foot first
    first = order[n.unique(p[order], return_index=True)[1]]
    return n.sqrt(d2[first]), s[first]


SPAN_SAMPLES = 16       # sample intervals per span that may hold a nearer point


def _spans(bspline):
    """Each knot span's parameter interval and two bounds of where it lies (in the convex
    hull of the poles that shape it): their box, and the chord between the first and the
    last of them with the largest distance of the others from it. Returns (t0, t1, lo,
    hi, a, b, w): lo / hi / a / b (spans, 2), w (spans,)."""
    n = np()
    p, poles = bspline.degree, n.asarray(bspline.poles, dtype=float)[:, :2]
    flat = n.repeat(n.asarray(bspline.knots, dtype=float), n.asarray(bspline.mults))
    i = n.nonzero(flat[p:len(poles)] < flat[p + 1:len(poles) + 1])[0] + p
    window = n.stack([poles[i - p + j] for j in range(p + 1)])   # (p + 1, spans, 2)
    a, b = window[0], window[-1]
    w = n.max([_segment_distance(q, a, b) for q in window[1:-1]], axis=0) if p > 1 \
        else n.zeros(len(i))
    return flat[i], flat[i + 1], window.min(axis=0), window.max(axis=0), a, b, w


def _segment_distance(x, a, b):
    """Distances of points x from segments a-b, row by row (all (k, 2))."""
    n = np()
    ab, ax = b - a, x - a
    L2 = n.sum(ab * ab, axis=1)
    u = n.clip(n.sum(ax * ab, axis=1) / n.where(L2 > 0.0, L2, 1.0), 0.0, 1.0)
    return n.hypot(*(ax - u[:, None] * ab).T)


def _box_distance2(data, lo, hi):
    """Squared distances of points (m, 2) from boxes (k, 2): (m, k)."""
    n = np()
    gap = n.maximum(n.maximum(lo - data[:, None, :], data[:, None, :] - hi), 0.0)
    return n.sum(gap * gap, axis=2)


SIEVE = 8               # the nearest-point search's sieve: blocks of 8, 64, 512, ... spans


def _sieve_levels(lo, hi):
    """The boxes of blocks of SIEVE ** L consecutive spans, L = 1, 2, ..., up to the first
    level of at most SIEVE ** 2 blocks: [(lo, hi)], finest first."""
    n = np()
    levels, size = [], SIEVE
    while -(-len(lo) // (size // SIEVE)) > SIEVE ** 2:      # the level below: too many
        starts = n.arange(0, len(lo), size)
        levels.append((n.minimum.reduceat(lo, starts, axis=0),
                       n.maximum.reduceat(hi, starts, axis=0)))
        size *= SIEVE
    return levels


def _nearer_spans(data, d2, spans, levels, margin):
    """The (point, span) pairs where the span may come nearer a point than its d2 (less
    the margin), sorted by point and span: the coarsest blocks whose box does, then their
    SIEVE parts whose box does, down to the spans, and of those the ones whose chord, less
    the poles' distance from it, does."""
    n = np()
    _, _, lo, hi, a, b, w = spans
    boxes = levels[::-1] + [(lo, hi)]
    pj, bj = n.nonzero(_box_distance2(data, *boxes[0]) < (d2 - margin)[:, None])
    for blo, bhi in boxes[1:]:
        pj = n.repeat(pj, SIEVE)
        bj = (bj[:, None] * SIEVE + n.arange(SIEVE)[None, :]).ravel()
        keep = bj < len(blo)
        pj, bj = pj[keep], bj[keep]
        gap = n.maximum(n.maximum(blo[bj] - data[pj], data[pj] - bhi[bj]), 0.0)
        keep = n.sum(gap * gap, axis=1) < d2[pj] - margin
        pj, bj = pj[keep], bj[keep]
    low = n.maximum(_segment_distance(data[pj], a[bj], b[bj]) - w[bj], 0.0)
    keep = low * low < d2[pj] - margin
    return pj[keep], bj[keep]


def _nearest_feet(bspline, data, t0):
    """Each point's NEAREST point on a B-spline (globally: not only the local minimum
    found from ``t0``, which on a looping curve can be far from it, QA: 13.0 mm
    reported where the curve passes 2.25 mm from the point). The foot downhill of t0
    (refine_feet over the domain) gives a distance the nearest point is within; only a
    span whose poles' hull lies nearer can hold a nearer point (on a smooth curve: the
    foot's own span or two, unless the curve comes back near the point). Those spans,
    sieved by ever smaller blocks of spans (_nearer_spans), are the coarse samples
    (SPAN_SAMPLES + 1 a span), and each sample nearer than its neighbours is refined in
    their bracket (refine_feet); the nearest foot wins. Returns (t, B(t), squared
    distances); Part's distToShape gives the same feet to rounding (test_elastica_fit)."""
    n = np()
    at = bspline_at(bspline)
    a, b = bspline.domain
    t, P, d2 = refine_feet(at, data, t0, a, b)
    spans = _spans(bspline)
    t0s, t1s, lo, hi = spans[:4]
    # a nearer point must beat the local one by more than rounding (its own span passes)
    margin = 1e-12 * (1.0 + float(n.max(n.abs(data))) ** 2)
    levels = _sieve_levels(lo, hi)
    u = n.arange(SPAN_SAMPLES + 1) / SPAN_SAMPLES
    seed_p, seed_t, seed_lo, seed_hi = [], [], [], []
    for c in range(0, len(data), 8192):            # bounded (8192, 64) tables
        pj, sj = _nearer_spans(data[c:c + 8192], d2[c:c + 8192], spans, levels, margin)
        pj += c
        for k in range(0, len(pj), 65536):         # bounded (65536, samples) tables
            p, sp = pj[k:k + 65536], sj[k:k + 65536]
            ts = t0s[sp][:, None] + (t1s[sp] - t0s[sp])[:, None] * u[None, :]
            S = bspline.evaluate(ts.ravel()).reshape(len(p), len(u), 2)
            dd = n.sum((S - data[p][:, None, :]) ** 2, axis=2)
            # a run of a point's consecutive spans is one sampled stretch of the curve (a
            # span's last sample is the next one's first): seeds where it is nearer the
            # point than both neighbours, one per dip, not one per span
            go_on = n.zeros(len(p), dtype=bool)
            go_on[:-1] = (p[1:] == p[:-1]) & (sp[1:] == sp[:-1] + 1)
            before = n.full(len(p), n.inf)
            before[1:] = n.where(go_on[:-1], dd[:-1, -2], n.inf)
            after = n.full(len(p), n.inf)
            after[:-1] = n.where(go_on[:-1], dd[1:, 1], n.inf)
            pad = n.column_stack([before, dd, after])
            low = (dd <= pad[:, :-2]) & (dd <= pad[:, 2:])
            low[:, -1] &= ~go_on                   # the next span's first sample
            # each sample's neighbours' parameters (across a run's spans; a run's end: its
            # own): a dip's bracket
            tb, ta = ts[:, 0].copy(), ts[:, -1].copy()
            tb[1:] = n.where(go_on[:-1], ts[:-1, -2], ts[1:, 0])
            ta[:-1] = n.where(go_on[:-1], ts[1:, 1], ts[:-1, -1])
            tpad = n.column_stack([tb, ts, ta])
            # every dip, the found foot's too: within a sample of it may lie another, nearer
            # minimum (a discrete fit's cubic of 12 spans 107 mm long: 14.584 mm reported
            # where the curve passes 14.343 mm from the point, 6 mm along it)
            r, i = n.nonzero(low)
            seed_p.append(p[r])
            seed_t.append(ts[r, i])
            seed_lo.append(tpad[r, i])
            seed_hi.append(tpad[r, i + 2])
    if not seed_p or not sum(len(x) for x in seed_p):
        return t, P, d2
    q = n.concatenate(seed_p)
    tq, Pq, dq = refine_feet(at, data[q], n.concatenate(seed_t), n.concatenate(seed_lo),
                             n.concatenate(seed_hi))
    order = n.lexsort((dq, q))                     # each point's nearest foot first
    first = order[n.unique(q[order], return_index=True)[1]]
    better = first[dq[first] < d2[q[first]]]
    t[q[better]], P[q[better]], d2[q[better]] = tq[better], Pq[better], dq[better]
    return t, P, d2


def _signed(bspline, data, t, P, d2):
    """The feet and signed distances (+ = left of the travel)."""
    n = np()
    D1, r = bspline.derivative(t, 1), data - P
    left = D1[:, 0] * r[:, 1] - D1[:, 1] * r[:, 0] >= 0.0
    return P, n.where(left, 1.0, -1.0) * n.sqrt(d2)


def drawn_distances(bspline, data, t0):
    """Each point's nearest point on a discrete fit's drawn cubic and its signed distance
    (+ = left of the travel): the curve the designer gets, where the library measures to
    the polygon (9 exact points on the sample S, uneven: rms 0.099 mm to the polygon, 0.22
    to the cubic). _nearest_feet from t0, each point's polygon foot: the cubic runs through
    the vertices by chord length, so a foot's arc length along the polygon is its parameter
    there."""
    t, P, d2 = _nearest_feet(bspline, data, np().asarray(t0, dtype=float) + bspline.domain[0])
    return _signed(bspline, data, t, P, d2)


def nearest_on(bspline, data, seeds=256, with_t=False):
    """Each point's nearest point on a B-spline and its signed distance (+ = left of the
    travel), as drawn_distances, from the nearest of up to ``seeds`` knots spread along
    it: for points the fit did not use (the user's, where it fitted a resampled polygon).
    ``with_t``: also each foot's parameter from the spline's start (a fit's to_bspline:
    the arc length of a smooth curve, of a discrete one's polygon)."""
    n = np()
    t0s, t1s = _spans(bspline)[:2]
    k = n.append(t0s, t1s[-1:])
    k = k[n.unique(n.linspace(0, len(k) - 1, min(seeds, len(k))).round().astype(int))]
    t, P, d2 = _nearest_feet(bspline, data, k[nearest_samples(data, bspline.evaluate(k))])
    if with_t:
        return _signed(bspline, data, t, P, d2) + (t - bspline.domain[0],)
    return _signed(bspline, data, t, P, d2)
