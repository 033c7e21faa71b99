"""What a user sees of a curve's shape, to pick the fair one among several (Hermite
solutions): its self-crossings (loops) and its largest curvature. The same numbers
in Python (properties of SmoothElastica and HermiteChain), the ``elastica hermite``
table and JSON, and FreeCAD's Elastic blend panel."""
from __future__ import annotations

import math

import numpy as np

__all__ = ["self_crossings", "crossing_pairs", "ShapeDescriptors"]

#: Samples of a curve whose polyline is tested for self-crossings (as FreeCAD's blend
#: panel always drew and counted them).
CROSSING_SAMPLES = 400
#: Segments per run in self_crossings: the runs whose bounding boxes overlap are tested
#: pairwise (a run's segments against the other's).
CROSSING_BLOCK = 64


def self_crossings(xy) -> int:
    """Crossings of a polyline with itself (neighbouring segments excluded): the
    number of loops a user sees (see :func:`crossing_pairs`)."""
    return len(crossing_pairs(xy))


def crossing_pairs(xy) -> np.ndarray:
    """Where a polyline crosses itself: (count, 2) segment indices i < j - 1 whose
    segments xy[i]-xy[i+1] and xy[j]-xy[j+1] cross, sorted by i. The segments in runs of
    CROSSING_BLOCK, and only pairs of runs whose bounding boxes overlap tested, so a
    polyline of many points (a sketch's ducks, a long composite curve) needs O(n) memory
    and about O(n) time, not O(n^2)."""
    xy = np.asarray(xy, dtype=np.float64)
    a, b = xy[:-1], xy[1:]

    # segments i < j - 1 cross when each one's end points lie on both sides of the other
    def side(p, q, r):
        return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - \
               (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])
    starts = np.arange(0, len(a), CROSSING_BLOCK)
    lo = np.array([xy[i:i + CROSSING_BLOCK + 1].min(0) for i in starts]).reshape(-1, 2)
    hi = np.array([xy[i:i + CROSSING_BLOCK + 1].max(0) for i in starts]).reshape(-1, 2)
    # runs r <= c whose boxes overlap (apart: no segment of one crosses the other's)
    near = ~((lo[:, None] > hi[None]).any(2) | (lo[None] > hi[:, None]).any(2))
    found = []
    for r, c in zip(*np.nonzero(np.triu(near))):
        i0, j0 = starts[r], starts[c]
        A, B = a[i0:i0 + CROSSING_BLOCK, None], b[i0:i0 + CROSSING_BLOCK, None]
        C, D = a[None, j0:j0 + CROSSING_BLOCK], b[None, j0:j0 + CROSSING_BLOCK]
        s1, s2 = side(A, B, C), side(A, B, D)
        s3, s4 = side(C, D, A), side(C, D, B)
        cross = (s1 * s2 < 0) & (s3 * s4 < 0)
        i, j = np.indices(cross.shape)
        i, j = np.nonzero(cross & (j + j0 > i + i0 + 1))   # the pairs' local indices
        found.append(np.c_[i + i0, j + j0])
    out = np.vstack(found) if found else np.empty((0, 2), dtype=np.intp)
    return out[np.lexsort((out[:, 1], out[:, 0]))].astype(np.intp)


def _piece_max_curvature(p) -> float:
    """The largest |kappa| of one SmoothElastica, exactly: kappa^2 = 4 mu (k^2 -
    sin^2((theta - phi)/2)) (seed 000 (4.3): kappa = 2 k sqrt(mu) cn, sin((theta-phi)/2)
    = k sn), so |kappa| peaks at 2 |k| sqrt(mu) where theta - phi is a whole turn, and
    is otherwise largest at an end (theta's extremes are at the ends and inflections,
    where kappa = 0)."""
    from .affine import _ellipk, elastica_inflections
    ends = np.abs(p.curvature(np.array([0.0, p.length])))
    if p.k == 0.0:
        return float(ends.max())
    if abs(p.k) < 1.0 and math.sqrt(p.mu) * p.length >= 2.0 * _ellipk(abs(p.k)):
        # u spans 2K, so it holds a u = 2jK, |cn| = 1: the peak, without listing the
        # inflections (sqrt(mu) length / 2K of them: 1e10 at mu = 1e20, length 1)
        return 2.0 * abs(p.k) * math.sqrt(p.mu)
    theta = p.angle(np.concatenate([[0.0, p.length], elastica_inflections(p, 0.0)]))
    lo, hi = (theta.min() - p.phi) / (2 * math.pi), (theta.max() - p.phi) / (2 * math.pi)
    peak = 2.0 * abs(p.k) * math.sqrt(p.mu) if math.floor(hi) >= math.ceil(lo) else 0.0
    return float(max(peak, ends.max()))


class ShapeDescriptors:
    """``loops``, ``crosses_itself`` and ``max_curvature`` of a curve with ``points(s)``,
    ``length`` and either SmoothElastica parameters or ``pieces`` of them (computed on
    each access: a curve's parameters may be reassigned)."""

    @property
    def loops(self) -> int:
        """Self-crossings of the curve (of its polyline of 400 points evenly spaced in
        arc length): 0 for a fair curve, one per loop a user sees."""
        return self_crossings(self.points(np.linspace(0.0, self.length, CROSSING_SAMPLES)))

    @property
    def crosses_itself(self) -> bool:
        """Whether the curve crosses itself (``loops > 0``): a batten cannot."""
        return self.loops > 0

    @property
    def max_curvature(self) -> float:
        """The largest |curvature| along the curve (1/length units; exact, not sampled)."""
        return max(_piece_max_curvature(p) for p in getattr(self, "pieces", [self]))
