"""One stray point among a hand sketch's few points: a point whose removal lets the others
fit far closer, judged by the noise the OTHER points show about their own fit.

QA25gui F1: 18 points drawn along a 330 mm curve (0.4 mm noise), one mis-dragged 150 mm
off. :func:`libelastica.fit.far_points` names glitches among OUTLIER_MIN_POINTS = 20
points or more only (its typical distance, the median, needs them), and the misfit verdict
did not fire either: noise_level read 4.93 from the points, the stray one among them (rms
18.4, 3.7 x that, under MISFIT_RATIO). Nothing named the point; in curve order it became
the curve's first point and a 608 mm hook was drawn at rms 1.36.

Here, for 8 to 19 points (:data:`STRAY_MIN_POINTS`, the fit's OUTLIER_MIN_POINTS), a few
candidates (the farthest two from the fit, the one farthest off the chord of its two
neighbours) are each left out and the rest fitted again (the same model, quietly); the
candidate is a stray point where its distance to the rest's curve exceeds
:data:`STRAY_FACTOR` times the rest's own noise about that curve.
"""
from __future__ import annotations

from typing import Optional

import numpy as np

__all__ = ["STRAY_FACTOR", "STRAY_MIN_POINTS", "stray_point"]

# The rest's noise is the rms of their distances to their own curve, corrected for the
# curve's fitted shape (STRAY_DOF: offset across the points, direction, mu, k, q; the
# distances measured across the curve, so position along it and length take none):
# sqrt(sum d^2 / (m - STRAY_DOF)) over the m others. It is the others' noise, not
# inflated by the stray point (noise_level of all the points read 4.93 for 0.4 mm of noise
# where one lay 150 mm off: it is what hid it). With fewer than STRAY_STEADY_DOF degrees of
# freedom left (under 12 points) that figure is unsteady (clean 8-point sketches: a point
# 34 x it off the others' curve), and noise_level of the others (their third differences,
# from the points alone) is taken where larger: it reads a few uneven points' bends as
# noise too (0.48 to 0.96 for 0.1 at 8 points), so fewer strays are named there. Below
# STRAY_MIN_POINTS nothing is said.
STRAY_DOF = 5
STRAY_STEADY_DOF = 6
STRAY_MIN_POINTS = 8
# How far, in the rest's noise, a left-out point must lie from the rest's curve. Measured on
# 202 clean sets of 8 to 19 points (fit_data.sketched_s x 40 seeds at 8, 12, 18 points;
# 60 of QA25gui's 330 mm curve; /tmp/wander's clicked sets under 20 points), both models,
# both orders (808 fits): from 12 points on, at most 7.2 x where the others came more than
# 1.3 x nearer (13.4 x a loop's tip among 16 clicks, 8.0 x an end click among 14: the
# others no nearer, STRAY_GAIN's cases); at 8 points 7.4 x (noise_level's figure). Points
# dragged 20 x the noise off 12 and 18 points lie 12.5 to 26 x; off 8 points, 60 x the
# noise lie 5.8 to 13 x, 300 x 16 to 42 x.
STRAY_FACTOR = 9.0
# and its removal must bring the others STRAY_GAIN times nearer their curve (rms) than the
# smooth curve through all the points lies from them: a loop's tip among 16 clicks lay
# 13 x the others' noise off their curve (the loop gone without it), but the curve through
# all of them passed every one within 0.2 px: no point pulled it.
STRAY_GAIN = 1.5
# and beyond STRAY_FLOOR of the points' extent: points on a curve to rounding (the model's
# own small misfit) have no noise to measure by
STRAY_FLOOR = 1e-4
# The smooth curve's distances are measured to its polygon through STRAY_SAMPLES samples:
# its sag between samples, L^2 kappa / (8 STRAY_SAMPLES^2), is below 1e-6 of L for kappa L
# up to 8 (a curl of a turn and a quarter), far under STRAY_FACTOR x any noise it judges.
STRAY_SAMPLES = 1024
# A point alone in a stretch STRAY_GAP times longer than the others' median step (its
# neighbours' chord) is not judged: left out, the others' curve wanders through the gap, and
# its distance to it measures the gap, not a drag (revD: 8 uneven clicks of a sine, 1 px
# noise, the one click between t 0.37 and 1.0 lay 34 px = 26 x 'their noise' off it; a dragged
# point's neighbours lie about two steps apart).
STRAY_GAP = 3.0


def _polygon_distances(q: np.ndarray, V: np.ndarray) -> np.ndarray:
    """Distance of each point q (m, 2) to the polygon V (k, 2) (the discrete model's own
    curve; the smooth one's dense samples, STRAY_SAMPLES)."""
    A, AB = V[:-1], np.diff(V, axis=0)
    ab2 = np.maximum(np.sum(AB * AB, 1), np.finfo(float).tiny)
    t = np.clip(np.einsum("mij,ij->mi", q[:, None, :] - A[None], AB) / ab2, 0.0, 1.0)
    return np.linalg.norm(q[:, None, :] - A[None] - t[..., None] * AB[None], axis=2).min(axis=1)


def _curve_polygon(curve, ext: float = 0.0) -> np.ndarray:
    """A smooth curve's polygon through STRAY_SAMPLES samples, continued ``ext`` past both
    ends (extrapolate: a point left out at an end lies beyond the others' curve, not off
    it); a discrete curve's own."""
    from .core import SmoothElastica
    if isinstance(curve, SmoothElastica):
        return curve.points(np.linspace(-ext, curve.length + ext, STRAY_SAMPLES), extrapolate=True)
    return curve.points()


def _candidates(pts: np.ndarray, d: np.ndarray) -> list:
    """The points to leave out: the two farthest from the fit, and the one farthest off the
    chord of its neighbours (the fit may pass near a stray point and far from the points
    it pulled)."""
    order = [int(i) for i in np.argsort(-d, kind="stable")[:2]]
    A, B, P = pts[:-2], pts[2:], pts[1:-1]
    AB = B - A
    off = np.abs(AB[:, 0] * (P - A)[:, 1] - AB[:, 1] * (P - A)[:, 0]) / \
        np.maximum(np.hypot(AB[:, 0], AB[:, 1]), np.finfo(float).tiny)
    j = int(np.argmax(off)) + 1
    return order + ([j] if j not in order else [])


def _as_given(order) -> bool:
    """Whether the order is the points' own, run either way."""
    k = np.arange(len(order))
    return bool(np.array_equal(order, k) or np.array_equal(order, k[::-1]))


def stray_point(r, model: Optional[str] = None):
    """The one stray point of fit result ``r`` as (index into ``r.points``, its distance to
    the curve of the others, their noise, gain: how many times nearer their curve they lie
    than the smooth curve through all lies from them); None where there is none, or the
    points are fewer than STRAY_MIN_POINTS or OUTLIER_MIN_POINTS or more (far_points judges
    those), or the fit holds end conditions, or was made in a curve order that is not the
    points' own (``r.order``; FreeCAD asks only of points in their order).
    model: the fit's ("discrete" / "smooth"), default r.curve's."""
    from .fit import OUTLIER_MIN_POINTS, judging_fit
    from .core import SmoothElastica
    from .misfit import noise_level
    pts = np.asarray(r.points, dtype=float)
    n = len(pts)
    if r.distances is None or not STRAY_MIN_POINTS <= n < OUTLIER_MIN_POINTS or r.constraints:
        return None
    if r.order is not None and not _as_given(r.order):
        # a cloud's curve order is a guess, and a point off it may be the order's fault: a
        # loop of 12 clicks in curve order (cut across) left one 12 x the others' noise off
        return None
    if model is None:
        model = "smooth" if isinstance(r.curve, SmoothElastica) else "discrete"
    extent = float(np.max(np.ptp(pts, axis=0)))
    # a smooth fit by distance measured its points' distances itself (exact feet): the
    # polygon's 1024 samples only where it did not (a paired fit's, a discrete polygon's)
    # (the polygon distances were 42 % of this function's time on 12-point fits, revD 4)
    smooth_by_distance = model == "smooth" and r.distance == "orthogonal"
    d = np.abs(r.distances) if smooth_by_distance else _polygon_distances(pts, _curve_polygon(r.curve))
    full = d
    if not smooth_by_distance:
        try:
            full = np.abs(judging_fit(pts, model="smooth").distances)
        except (ValueError, ArithmeticError, RuntimeError):
            return None
    best = None
    for i in _candidates(pts, d):
        rest = np.delete(pts, i, axis=0)
        if 0 < i < n - 1 and np.hypot(*(pts[i + 1] - pts[i - 1])) > \
                STRAY_GAP * np.median(np.hypot(*np.diff(rest, axis=0).T)):
            continue
        try:
            fr = judging_fit(rest, model="smooth")
        except (ValueError, ArithmeticError, RuntimeError):
            continue
        dr = np.abs(fr.distances)
        noise = float(np.sqrt(np.sum(dr * dr) / (len(rest) - STRAY_DOF)))
        if len(rest) - STRAY_DOF < STRAY_STEADY_DOF:
            noise = max(noise, noise_level(rest))
        # points on one curve to rounding (exact CAD points, one moved) have no noise: their
        # floor, not 1e-14 ('2.8e+15 x their noise', and a division by zero at 0)
        noise = max(noise, STRAY_FLOOR * extent)
        gap = float(np.min(np.hypot(*(rest[[0, -1]] - pts[i]).T)))
        di = float(_polygon_distances(pts[i:i + 1], _curve_polygon(fr.curve, gap))[0])
        gain = float(np.sqrt(np.mean(np.delete(full, i) ** 2) /
                             max(float(np.mean(dr * dr)), (STRAY_FLOOR * extent) ** 2)))
        if di > STRAY_FACTOR * noise and di > STRAY_FLOOR * extent and gain > STRAY_GAIN and \
                (best is None or di / noise > best[1] / best[2]):
            best = (i, di, noise, gain)
    return best
