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


def refined_deviation(splines, samples: np.ndarray, curve=None, per_span: int = 16) -> float:
    """The largest distance of ``splines`` (quadratic BSplines) from the source: ``curve`` (a
    SmoothElastica, whose samples ``samples`` (m, 2) are at equal arc length from 0 to its
    length) or, where it is None, the polyline through ``samples`` (points' source). Each
    spline is sampled at ``per_span`` points a knot span, its REFINED_PEAKS largest local
    maxima of the distance maximised by golden section over the parameter between their
    neighbouring samples (every peak of every spline at once); the distance to the curve is
    to its nearest point (nearest.curve_feet from ``samples``, at every point tried: a
    foot followed from the last one stays on its branch where a looping curve's nearest
    passes to another, 0.0288 stated for 0.0268 at 12 edges of a k = 1.82 loop), to
    points' polyline exact. A maximum where the distance has one peak between samples (a
    bound it is not: a narrower peak between two samples can be missed)."""
    from .nearest import curve_feet
    from .report import closest_points
    samples = np.asarray(samples, dtype=float)

    def dist(xy):
        if curve is None:
            return np.linalg.norm(closest_points(xy, samples) - xy, axis=1)
        # the curve's own distance: the polyline's is off by up to its sagitta, which
        # moves the peaks (the tile S at 24 edges: 0.159979 against 0.160009 true)
        return curve_feet(curve, xy, samples)[0]

    found = []                   # (spline, u, d) of every spline's samples
    for b in splines:
        K = np.asarray(b.knots, dtype=float)
        u = np.concatenate([np.linspace(K[i], K[i + 1], per_span, endpoint=False)
                            for i in range(len(K) - 1)] + [K[-1:]])
        found.append((b, u, dist(b(u))))
    worst = max(float(np.max(d)) for _, _, d in found)    # the sampled maximum
    peaks = []                   # (spline, lo, hi) of the peaks that can beat it
    for b, u, d in found:
        peak = np.flatnonzero(np.r_[d[0] >= d[1], (d[1:-1] >= d[:-2]) & (d[1:-1] >= d[2:]),
                                    d[-1] >= d[-2]])
        lo, hi = np.maximum(peak - 1, 0), np.minimum(peak + 1, len(u) - 1)
        # a peak's maximum lies within half a step of its sample, above it by at most an
        # eighth of its second difference where the distance is a parabola there; PEAK_MARGIN
        # times that must reach the sampled maximum (an end sample: always refined)
        top = d[peak] + PEAK_MARGIN * (2.0 * d[peak] - d[lo] - d[hi]) / 8.0
        keep = np.flatnonzero((top >= worst) | (peak == 0) | (peak == len(u) - 1))
        keep = keep[np.argsort(-d[peak[keep]])][:REFINED_PEAKS]
        if len(keep):
            peaks.append((b, u[lo[keep]], u[hi[keep]]))
    cut = np.cumsum([0] + [len(q[1]) for q in peaks])
    lo, hi = np.concatenate([q[1] for q in peaks]), np.concatenate([q[2] for q in peaks])

    def at(x):
        return dist(np.concatenate([b(x[cut[i]:cut[i + 1]]) for i, (b, *_) in enumerate(peaks)]))

    r = (math.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
    f1, f2 = at(x1), at(x2)
    for _ in range(GOLDEN_STEPS):       # every peak at once, maximised
        left = f1 >= f2
        hi = np.where(left, x2, hi)
        lo = np.where(left, lo, x1)
        x1, x2 = np.where(left, hi - r * (hi - lo), x2), np.where(left, x1, lo + r * (hi - lo))
        fx = at(np.where(left, x1, x2))
        f1, f2 = np.where(left, fx, f2), np.where(left, f1, fx)
    return max(worst, float(np.max(np.maximum(f1, f2))))
