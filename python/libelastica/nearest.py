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


def _newton_feet(bspline, data, t, steps=30):
    """Each point's local nearest point on a B-spline from the parameters ``t``: Newton on
    (B(t) - p) . B'(t) = 0, a step kept only where it brings the point closer, t within
    the domain. Returns (t, B(t), squared distances)."""
    n = np()
    a, b = bspline.domain
    t = n.clip(n.asarray(t, dtype=float), a, b)
    P = bspline.evaluate(t)
    d2 = n.sum((P - data) ** 2, axis=1)
    for _ in range(steps):
        D1, D2 = bspline.derivative(t, 1), bspline.derivative(t, 2)
        r = P - data
        g = n.sum(r * D1, axis=1)
        h = n.sum(D1 * D1, axis=1)
        curv = h + n.sum(r * D2, axis=1)          # g's derivative: Newton where positive
        h = n.where(curv > 0.0, curv, h)
        tn = n.clip(t - g / n.maximum(h, 1e-300), a, b)
        Pn = bspline.evaluate(tn)
        dn = n.sum((Pn - data) ** 2, axis=1)
        closer = dn < d2
        if not closer.any():
            break
        t, P, d2 = n.where(closer, tn, t), n.where(closer[:, None], Pn, P), n.where(closer, dn, d2)
    return t, P, d2


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
    Newton finds from ``t0``, which on a looping curve can be far from it, QA: 13.0 mm
    reported where the curve passes 2.25 mm from the point). Newton from t0 gives a
    distance the nearest point is within; only a span whose poles' hull lies nearer can
    hold a nearer point (on a smooth curve: the foot's own span or two, unless the curve
    comes back near the point). Those spans, sieved by ever smaller blocks of spans
    (_nearer_spans), are sampled at SPAN_SAMPLES + 1 points, and Newton runs again
    from each sample nearer than its neighbours; the nearest foot wins. Returns (t, B(t), squared
    distances); Part's distToShape gives the same feet to rounding (test_elastica_fit)."""
    n = np()
    t, P, d2 = _newton_feet(bspline, data, t0)
    spans = _spans(bspline)
    t0s, t1s, lo, hi = spans[:4]
    # a nearer point must beat the local one by more than rounding (its own span passes)
    margin = 1e-12 * (1.0 + float(n.max(n.abs(data))) ** 2)
    levels = _sieve_levels(lo, hi)
    u = n.arange(SPAN_SAMPLES + 1) / SPAN_SAMPLES
    seed_p, seed_t = [], []
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
            # every dip, the found foot's too: within a sample of it may lie another, nearer
            # minimum (a discrete fit's cubic of 12 spans 107 mm long: 14.584 mm reported
            # where the curve passes 14.343 mm from the point, 6 mm along it)
            r, i = n.nonzero(low)
            seed_p.append(p[r])
            seed_t.append(ts[r, i])
    if not seed_p or not sum(len(x) for x in seed_p):
        return t, P, d2
    q = n.concatenate(seed_p)
    tq, Pq, dq = _newton_feet(bspline, data[q], n.concatenate(seed_t))
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
    K = bspline.evaluate(k)
    start = n.empty(len(data))
    for i in range(0, len(data), 1024):          # bounded (1024, seeds) tables
        d2 = n.sum((data[i:i + 1024, None, :] - K[None, :, :]) ** 2, axis=2)
        start[i:i + 1024] = k[n.argmin(d2, axis=1)]
    t, P, d2 = _nearest_feet(bspline, data, start)
    if with_t:
        return _signed(bspline, data, t, P, d2) + (t - bspline.domain[0],)
    return _signed(bspline, data, t, P, d2)
