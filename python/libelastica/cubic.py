"""What a discrete fit's exported B-spline is to the points. A discrete fit's rms,
max_error and distances are the points' distances to its polygon; FitResult.to_bspline
exports the C2 cubic through the polygon's vertices, which runs elsewhere between them
(a 7-click sketch: polygon rms 0.316 / max 0.561, its cubic 0.647 / 1.487, the smooth
model's curve 0.031). :func:`cubic_distances` measures the points against that cubic;
:func:`smooth_fits_better` says when few points are better fitted by the smooth model
(el.fit's and fit_keyline's SparseWarning, which `elastica fit` and the FreeCAD Fit
feature say in their words)."""
from __future__ import annotations

from typing import NamedTuple, Optional

import numpy as np

from ._quiet import quiet

__all__ = ["SPARSE_POINTS", "SPARSE_RATIO", "SPARSE_FLOOR", "SparseWarning", "CubicDistances",
           "cubic_distances", "smooth_fits_better"]

# A discrete fit of few points is a polygon of as few segments, which cannot follow a
# curved run of points the smooth model follows (measured on 300 sparse noisy sketches of
# bench_fit_sparse.py's kind, free ends: with 6-9 points 7 of 19 discrete fits above twice
# the smooth one's rms, 5 above 4 times; with 10-14 points 5 of 18, with 15-24 3 of 72,
# with 25 or more none of 191). Below SPARSE_POINTS the smooth fit is run to compare (a
# smooth fit of so few points takes milliseconds); it fits far better when its rms is
# below 1 / SPARSE_RATIO of the discrete one's, by more than SPARSE_FLOOR of the extent.
# SPARSE_RATIO was 2.0 (QA qapy F2: a 30-point uneven ship line, 9000 mm, whose exported
# cubic lies 2.50 / 5.18 mm (rms / max) from the points, the smooth curve 1.49 / 2.35, and at
# 24 points 2.79 / 5.83 against 1.54 / 2.36: a ratio of 1.8, no warning). Measured
# (/tmp/fxpy/sweep2.py: 240 sets of bench_fit_sparse.py's kind with 8-40 points, free ends):
# at 1.5 the warning fires for 25 of 46 sets of 8-14 points (18 at 2.0), 8 of 75 of 15-24 (5),
# and for the ship line at 12 to 24 points. SPARSE_POINTS stays 25: at 40 (fxpy's first rule)
# every discrete fit of 25-39 points ran a smooth fit too, 5-6 ms against its own 0.5 (make
# bench's free sparse sketches, discrete median 0.7 -> 6.7 ms), to warn 7 of 119 such sets
# (the 30-point ship line among them), whose rms over the smooth one's is 1.01 at the median.
SPARSE_POINTS = 25
SPARSE_RATIO = 1.5
SPARSE_FLOOR = 1e-4


class CubicDistances(NamedTuple):
    """:func:`cubic_distances`' pair, by name or unpacked (QA qapy F10: a bare tuple read
    as distances): ``feet`` (n, 2) the points' nearest points on the cubic, ``distances``
    (n,) their signed distances (+ = left of the travel)."""
    feet: np.ndarray
    distances: np.ndarray


class SparseWarning(UserWarning):
    """:func:`libelastica.fit`'s and :func:`libelastica.fit_keyline`'s warning that a
    discrete fit or keyline of fewer than SPARSE_POINTS points lies far farther from them
    than the smooth model's (:func:`smooth_fits_better`; ``FitResult.sparse``,
    ``KeylineFit.sparse``): use model="smooth"."""


def cubic_distances(result, bspline=None) -> CubicDistances:
    """``(feet, distances)``, a :class:`CubicDistances`: the fitted points' nearest points
    (n, 2) on a discrete FitResult's exported cubic (``bspline``, default
    ``result.to_bspline()``) and their signed distances (n,), + = left of the travel
    (``cubic_distances(r).distances``; ``feet, d = ...``): what the exported curve is from
    the points, where ``result.distances`` are the polygon's. Searched from each point's polygon foot (the cubic runs
    through the vertices by chord length) and over every span that may come nearer."""
    from .core import DiscreteElastica
    from .nearest import drawn_distances
    if not isinstance(result.curve, DiscreteElastica):
        raise ValueError("cubic_distances: a discrete fit's result is needed (a smooth fit's "
                         "B-spline is within its tol of the curve its distances are to)")
    b = result.to_bspline() if bspline is None else bspline
    pts = np.ascontiguousarray(np.asarray(result.points, dtype=float)[:, :2])
    return CubicDistances(*drawn_distances(b, pts, result.foot_s))


def smooth_fits_better(points, rms: float, constraints=None, keyline=None) -> Optional[float]:
    """For a discrete fit of fewer than SPARSE_POINTS ``points`` lying ``rms`` from it
    (the polygon's, or its cubic's): the smooth model's rms on the same points with the
    same ``constraints`` when it is below rms / SPARSE_RATIO and rms - SPARSE_FLOOR x the
    points' extent, else None (also when the smooth fit fails: no verdict). ``keyline``:
    a discrete keyline's rms (KeylineFit.input_rms), compared with the smooth keyline's,
    fit_keyline(points, model="smooth", **keyline) (keyline: its r and side)."""
    from .fit import quiet_fit
    pts = np.asarray(points, dtype=float)
    if len(pts) >= SPARSE_POINTS:
        return None
    try:
        if keyline is None:
            smooth = quiet_fit(pts, model="smooth", constraints=constraints or None).rms
        else:
            from .keyline import fit_keyline
            with quiet():     # its verdict only (this thread's warnings: _quiet.py)
                smooth = fit_keyline(pts, model="smooth", **keyline).input_rms
    except (ValueError, ArithmeticError, RuntimeError):
        return None
    extent = float(np.ptp(pts, axis=0).max())
    if rms > SPARSE_RATIO * smooth and rms - smooth > SPARSE_FLOOR * extent:
        return float(smooth)
    return None
