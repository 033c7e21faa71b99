"""g2_quadratic's stated deviation: the largest distance of its splines from the source,
its sampled maximum refined by a 1-D maximisation (QA qapy F4: sampled at 16 points a knot
span against the source's 20-a-vertex sample polyline it read 0.055093 where the splines lie
0.055300 from a 300 mm S fitted to tile.csv, 0.38 % under)."""
from __future__ import annotations

import math

import numpy as np

__all__ = []

# golden-section steps on a bracket of two sample steps: 0.618^16 ~ 5e-4 of it, the distance
# off its maximum by ~(5e-4)^2 of its second difference there (the tile S of QA F4: 1.2e-15 off 60
# steps')
GOLDEN_STEPS = 16
# the sampled distances' local maxima refined, largest first
REFINED_PEAKS = 8
# a peak is refined where its sample plus PEAK_MARGIN times the parabola's rise over it
# (an eighth of its second difference) reaches the sampled maximum: 4 x the parabola's
PEAK_MARGIN = 4.0
# Newton steps of a foot on the source curve from its sample polyline's (quadratic: the
# polyline's foot lies within a sample step, the curve's within its sagitta of it)
FOOT_STEPS = 4


def _curve_distance(c, p: np.ndarray, s0: np.ndarray, steps: int = FOOT_STEPS):
    """(distances, feet) of points p (m, 2) to the smooth curve c (points / angle / curvature
    of an arc length), each foot from its first estimate s0 (m,): Newton on (c(s) - p) . T(s)
    = 0, whose derivative is 1 + kappa (c(s) - p) . N(s); the foot held in [0, length]."""
    s = np.clip(np.asarray(s0, dtype=float), 0.0, c.length)
    for _ in range(steps):
        g, th, k = c.points(s), c.angle(s), c.curvature(s)
        t = np.c_[np.cos(th), np.sin(th)]
        d = g - p
        f = np.einsum("ij,ij->i", d, t)
        fp = 1.0 + k * np.einsum("ij,ij->i", d, np.c_[-t[:, 1], t[:, 0]])
        s = np.clip(s - np.where(fp > 0.1, f / np.where(fp > 0.1, fp, 1.0), f), 0.0, c.length)
    return np.linalg.norm(c.points(s) - p, axis=1), s


def _nearest_s(xy: np.ndarray, samples: np.ndarray, length: float) -> np.ndarray:
    """The arc length of each point's nearest sample (samples at equal arc length over
    [0, length]): argmin of |sample|^2 - 2 sample . point, about the samples' centre (no
    cancellation at large offsets), one matrix product for 1024 points (bounded memory;
    4 x faster than the differences' squares summed)."""
    o = samples.mean(axis=0)
    sm = samples - o
    n2 = np.einsum("ij,ij->i", sm, sm)
    out = np.empty(len(xy), dtype=np.intp)
    for a in range(0, len(xy), 1024):
        out[a:a + 1024] = np.argmin(n2[None, :] - 2.0 * ((xy[a:a + 1024] - o) @ sm.T), axis=1)
    return out * (length / (len(samples) - 1))


def refined_deviation(splines, samples: np.ndarray, curve=None, per_span: int = 16) -> float:
    """The largest distance of ``splines`` (quadratic BSplines) from the source: ``curve`` (a
    SmoothElastica, whose samples ``samples`` (m, 2) are at equal arc length from 0 to its
    length) or, where it is None, the polyline through ``samples`` (points' source). Each
    spline is sampled at ``per_span`` points a knot span, its REFINED_PEAKS largest local
    maxima of the distance maximised by golden section over the parameter between their
    neighbouring samples (every peak of every spline at once); the distance to the curve is
    to its true foot (Newton from the peak's nearest sample, then from the last foot), to
    points' polyline exact. A maximum where the distance has one peak between samples (a
    bound it is not: a narrower peak between two samples can be missed)."""
    from .report import closest_points
    samples = np.asarray(samples, dtype=float)
    found = []                   # (spline, u, d, feet) of every spline's samples
    for b in splines:
        K = np.asarray(b.knots, dtype=float)
        u = np.concatenate([np.linspace(K[i], K[i + 1], per_span, endpoint=False)
                            for i in range(len(K) - 1)] + [K[-1:]])
        xy = b(u)
        if curve is None:
            d, sf = np.linalg.norm(closest_points(xy, samples) - xy, axis=1), None
        else:   # the curve's own distance: the polyline's is off by up to its sagitta, which
            # moves the peaks (the tile S at 24 edges: 0.159979 against 0.160009 true)
            d, sf = _curve_distance(curve, xy, _nearest_s(xy, samples, curve.length))
        found.append((b, u, d, sf))
    worst = max(float(np.max(d)) for _, _, d, _ in found)    # the sampled maximum
    peaks = []                   # (spline, lo, hi, feet) of the peaks that can beat it
    for b, u, d, sf in found:
        peak = np.flatnonzero(np.r_[d[0] >= d[1], (d[1:-1] >= d[:-2]) & (d[1:-1] >= d[2:]),
                                    d[-1] >= d[-2]])
        lo, hi = np.maximum(peak - 1, 0), np.minimum(peak + 1, len(u) - 1)
        # a peak's maximum lies within half a step of its sample, above it by at most an
        # eighth of its second difference where the distance is a parabola there; PEAK_MARGIN
        # times that must reach the sampled maximum (an end sample: always refined)
        top = d[peak] + PEAK_MARGIN * (2.0 * d[peak] - d[lo] - d[hi]) / 8.0
        keep = (top >= worst) | (peak == 0) | (peak == len(u) - 1)
        peak = peak[keep][np.argsort(-d[peak[keep]])][:REFINED_PEAKS]
        if len(peak):
            peaks.append((b, u[np.maximum(peak - 1, 0)], u[np.minimum(peak + 1, len(u) - 1)],
                          None if sf is None else sf[peak]))
    cut = np.cumsum([0] + [len(q[1]) for q in peaks])
    lo, hi = np.concatenate([q[1] for q in peaks]), np.concatenate([q[2] for q in peaks])

    def at(x):
        return np.concatenate([b(x[cut[i]:cut[i + 1]]) for i, (b, *_) in enumerate(peaks)])

    if curve is not None:        # from the sampled peaks' feet
        sf = np.concatenate([q[3] for q in peaks])
        feet = [sf.copy(), sf.copy()]

    def dist(x, which):
        if curve is None:
            xy = at(x)
            return np.linalg.norm(closest_points(xy, samples) - xy, axis=1)
        dd, feet[which] = _curve_distance(curve, at(x), feet[which], 2)
        return dd

    r = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
    f1, f2 = dist(x1, 0), dist(x2, 1)
    for _ in range(GOLDEN_STEPS):       # every peak at once, maximised
        left = f1 >= f2
        hi = np.where(left, x2, hi)
        lo = np.where(left, lo, x1)
        x1, x2 = np.where(left, hi - r * (hi - lo), x2), np.where(left, x1, lo + r * (hi - lo))
        if curve is not None:           # the feet follow their points
            feet = [np.where(left, feet[0], feet[1]), np.where(left, feet[0], feet[1])]
        fx = dist(np.where(left, x1, x2), 0)
        f1, f2 = np.where(left, fx, f2), np.where(left, f1, fx)
    return max(worst, float(np.max(np.maximum(f1, f2))))
