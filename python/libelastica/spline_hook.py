"""A spline that hooks: bends to a radius far below its points' spacing where points close
together zig-zag (their scatter larger than their spacing). It need not cross itself, so
ElasticSpline.loops (a self-crossing) misses it: QA gui3 G4, a closed outline of 30 points
with 0.4 mm jitter, two 0.66 and 1.33 mm apart, hooked at radius 0.52 mm (points about 30 mm
apart) with no warning, and every wiggle became a piece of the G2 quadratic built on it."""
from __future__ import annotations

from typing import Callable, Optional, Tuple

import numpy as np

from .spline import LoopWarning

__all__ = ["HOOK_RATIO", "HookWarning", "hook", "hook_text"]

#: a spline hooks where its radius of curvature is below 1 / HOOK_RATIO of its points' median
#: spacing. Through evenly spaced points a fair curve bends to a radius of at least about
#: the spacing / (2 pi / 3) (a circle through 3 points); 20 leaves a corner drawn with a few
#: close points alone and flags the QA outline's 0.52 mm against 30 mm (ratio 57).
HOOK_RATIO = 20.0


class HookWarning(LoopWarning):
    """:func:`elastic_spline`'s warning that the spline hooks (:func:`hook`): it bends to a
    radius under 1 / :data:`HOOK_RATIO` of its points' median spacing, where points close
    together zig-zag; it passes every point, but a designer sees a micro-loop there. A
    :class:`LoopWarning`, so filters of loops take it too."""


def hook(sp) -> Optional[Tuple[int, float, float]]:
    """The tightest bend of the spline ``sp`` (an :class:`ElasticSpline`) where it hooks:
    (the piece, its least radius of curvature, the points' median spacing), or None where
    every radius is at least 1 / :data:`HOOK_RATIO` of that spacing."""
    pts = np.asarray(sp.data, dtype=np.float64)
    poly = np.vstack([pts, pts[:1]]) if sp.closed else pts
    spacing = float(np.median(np.hypot(*np.diff(poly, axis=0).T))) if len(poly) > 1 else 0.0
    # sp.max_curvature (the C result's, exact per piece) bounds the samples' below: a spline
    # that does not hook, the common case, is told without sampling its pieces (a C call
    # each: 4.8 ms for 30 pieces, more than the spline's own 3.8 ms)
    if not (spacing > 0.0 and sp.max_curvature * spacing > HOOK_RATIO):
        return None
    kappa = [float(np.abs(p.curvature(np.linspace(0.0, p.length, 65))).max()) for p in sp.pieces]
    j = int(np.argmax(kappa))
    if not kappa[j] * spacing > HOOK_RATIO:
        return None
    return j, 1.0 / kappa[j], spacing


def hook_text(sp, length: Optional[Callable[[float, int], str]] = None,
              noun: str = "spline") -> str:
    """What is said of a spline that hooks (:func:`hook`), '' where it does not: the
    library's HookWarning and FreeCAD's Elastic spline say it alike. ``length(value,
    digits)`` writes each length (None: the number alone); ``noun``: its subject."""
    h = hook(sp)
    if h is None:
        return ""
    length = length or (lambda v, d: f"{v:.{d}g}")
    j, radius, spacing = h
    p = sp.pieces[j]
    a, b = p.points(np.array([0.0, p.length]))
    if sp.guide_pieces:
        where = f"between ({a[0]:.6g}, {a[1]:.6g}) and ({b[0]:.6g}, {b[1]:.6g})"
    else:
        n = len(sp.data)
        where = f"between points {j} and {(j + 1) % n} (counted from 0)"
    return (f"the {noun} hooks {where}: it bends to radius {length(radius, 3)} there, under "
            f"1/{HOOK_RATIO:g} of the points' median spacing {length(spacing, 4)}, the points "
            f"{length(float(np.hypot(*(b - a))), 3)} apart: a micro-loop where close points "
            "zig-zag (their scatter larger than their spacing); remove or move one of them, "
            "or fit the points (Fit elastica) instead of passing through each")
