"""A fit of points resampled into an equilateral polygon (seed 000 §5.3), measured on the
points themselves: a fit is as good as its points' distances to the curve drawn.

The polygon is :func:`resampled_polygon`'s: of the points' polyline, or of their runs'
medians where that one is their noise's zigzag, ended at the first and last point. The
discrete edge h is fitted, not held at the step: a polygon through noisy points is longer
than their curve (2000 points 2 mm apart, noise 0.5 mm, a 4 m elastica: resampled at 2 mm,
4094 mm; h held at 2 mm bulged the curve to rms 13.2 from the points, h fitted 0.55 against
0.50 unresampled).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ._ffi import as_points, as_positive
from ._quiet import say
from ._text import LengthFormat, lengths
from ._values import ValueEquality, field_summary
from .fit import FitResult, quiet_fit
from .prep import resampled_polygon

__all__ = ["RESAMPLE_RATIO", "RESAMPLE_FLOOR", "ResampleWarning", "ResampledFit", "fit_resampled",
           "resampled_fits_worse", "resampled_reference", "resample_summary"]

# A resampled fit whose points lie more than RESAMPLE_RATIO times farther (rms) from it than
# from their own smooth fit, and by more than RESAMPLE_FLOOR of their extent, is worth a
# warning: its polygon is too coarse for the curve (the 4 m scan at 200 mm: the discrete
# fit's cubic through 21 vertices 1.54 x, the smooth fit 1.10 x).
RESAMPLE_RATIO = 1.2
RESAMPLE_FLOOR = 1e-5


class ResampleWarning(RuntimeWarning):
    """:func:`fit_resampled`'s warning that the curve fitted to the resampled polygon lies
    far farther from the points than their own fit (``ResampledFit.reference_rms``)."""


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class ResampledFit(ValueEquality):
    """Result of :func:`fit_resampled`: ``result`` the fit of the ``polygon`` (a FitResult:
    its rms / distances are the polygon's vertices'), ``bspline`` the curve drawn (smooth:
    within tol; discrete: the C2 cubic through its vertices), ``distances`` / ``feet`` the
    points' signed distances (+ = left) to it and their nearest points on it, ``rms`` /
    ``max_error`` from them: to ``bspline``, the curve drawn, which for the discrete model
    is not ``curve`` (its polygon, what :func:`fit`'s rms is to: :meth:`curve_distances`,
    ``curve_rms``, ``curve_max_error``; QA qapy F8: 0.49 to the cubic, 0.52 to the polygon
    at step 10 on a 300 mm tile; ``rms`` kept the cubic's, as the README, the CLI's
    ``--step`` and FreeCAD's Fit report it), ``foot_s`` each foot's arc length (the
    B-spline's parameter: a smooth curve's, a discrete one's polygon's, as
    FitResult.foot_s); ``points`` the
    points measured, ``step`` the resampling segment length asked; ``reference_rms``: the
    rms of the points' own smooth fit where this one lies beyond RESAMPLE_RATIO times it
    (a warning), else None."""
    result: FitResult
    polygon: np.ndarray
    points: np.ndarray
    step: float
    bspline: object
    distances: np.ndarray
    feet: np.ndarray
    rms: float
    max_error: float
    reference_rms: Optional[float] = None
    foot_s: Optional[np.ndarray] = None

    __repr__ = field_summary

    @property
    def curve(self):
        return self.result.curve

    def curve_distances(self) -> np.ndarray:
        """The ``points``' signed distances (+ = left of the travel) to ``curve``, as
        :func:`fit`'s ``distances`` are to its curve: a discrete fit's polygon's (nearest
        points on its segments, every segment a candidate: report.closest_points), a smooth
        fit's its B-spline's (``distances``: within its tol of the curve)."""
        return self._curve_d().copy()

    def _curve_d(self) -> np.ndarray:
        """:meth:`curve_distances`, measured once for the curve's parameters and the points
        as they are (kept in the instance's ``__dict__`` beside the frozen fields: not
        pickled, not compared; the curve and the points array are mutable: measured again
        where either changed), shared by curve_rms and curve_max_error."""
        from dataclasses import astuple
        from .core import DiscreteElastica
        if not isinstance(self.curve, DiscreteElastica):
            return self.distances           # a smooth fit's: its B-spline's, as measured
        key = (type(self.curve), astuple(self.curve), self.points.tobytes())
        kept = self.__dict__.get("_curve_distances")
        if kept is None or kept[0] != key:
            kept = self.__dict__["_curve_distances"] = (key, self._measured_curve_distances())
        return kept[1]

    def __getstate__(self):
        return {k: v for k, v in vars(self).items() if k != "_curve_distances"}

    def _measured_curve_distances(self) -> np.ndarray:
        from .report import closest_points
        poly = self.curve.points()
        feet, seg = closest_points(self.points, poly, segments=True)
        d = np.diff(poly, axis=0)[seg]
        e = self.points - feet
        dist = np.hypot(e[:, 0], e[:, 1])
        return np.where(d[:, 0] * e[:, 1] - d[:, 1] * e[:, 0] < 0.0, -dist, dist)

    @property
    def curve_rms(self) -> float:
        """The ``points``' rms distance to ``curve`` (:meth:`curve_distances`): :func:`fit`'s
        ``rms``; ``rms`` is to ``bspline``, the curve drawn."""
        return float(np.sqrt(np.mean(self._curve_d() ** 2)))

    @property
    def curve_max_error(self) -> float:
        """The ``points``' largest distance to ``curve`` (:meth:`curve_distances`)."""
        return float(np.abs(self._curve_d()).max())


def resampled_fits_worse(points, rms: float, start=None, constraints=None) -> Optional[float]:
    """The rms of the smooth fit of ``points`` themselves (with the same ``constraints``):
    the better of el.fit's (its automatic guess: what the points get unresampled) and, given
    the SmoothElastica ``start`` (e.g. the resampled smooth fit), the fit from it; where
    ``rms`` (a resampled fit's, on these points) exceeds RESAMPLE_RATIO times it and it by
    RESAMPLE_FLOOR of the points' extent, else None (also when both fits fail). A start far
    from the points alone led to a local minimum: 11 mm, not el.fit's 0.48, for a curly
    1 m elastica whose resampled fit lay 165 mm off."""
    pts = as_points(points, "resampled_fits_worse: points", 2, min_rows=4)
    fits = []
    for initial in (None, start) if start is not None else (None,):
        try:
            fits.append(quiet_fit(pts, model="smooth", constraints=constraints or None,
                                  initial=initial).rms)
        except (ValueError, ArithmeticError, RuntimeError):
            pass
    if not fits:
        return None
    own = min(fits)
    extent = _extent(pts)
    if rms > RESAMPLE_RATIO * own and rms - own > RESAMPLE_FLOOR * extent:
        return float(own)
    return None


def _extent(points) -> float:
    """The points' extent: their bounding box's longer side (RESAMPLE_FLOOR's scale)."""
    return float(np.ptp(np.asarray(points, dtype=float), axis=0).max())


def resampled_reference(points, rms: float, polygon, curve, constraints=None) -> Optional[float]:
    """:func:`resampled_fits_worse` of a fit of the resampled ``polygon`` whose ``curve``
    lies ``rms`` from ``points``: the points' own smooth fit, el.fit's or, where better, the
    one from that curve (smooth) or from the smooth fit of the polygon (discrete), all held
    to the fit's ``constraints`` (el.fit's, or None)."""
    from .core import SmoothElastica
    start = curve if isinstance(curve, SmoothElastica) else None
    if start is None:
        try:
            start = quiet_fit(polygon, model="smooth", constraints=constraints or None).curve
        except (ValueError, ArithmeticError, RuntimeError):
            start = None
    return resampled_fits_worse(points, rms, start, constraints)


def fit_resampled(points, step: float, model: str = "discrete", *, tol: float = 1e-6,
                  degree: int = 3, check: bool = True, **kwargs) -> ResampledFit:
    """Fit an elastica to points (n, 2) through their polygon resampled with segment ``step``
    (:func:`resampled_polygon`; the discrete edge h fitted unless ``fixed`` holds it) and
    measure it on the points: their distances to the curve drawn (``tol``, ``degree``: the
    smooth B-spline's). ``model``: "discrete" (default) or "smooth", as :func:`fit`'s;
    ``kwargs`` go to :func:`fit` (constraints, fixed, distance, ...).
    ``check``: compare with the points' own smooth fit and warn (ResampleWarning) where
    the resampled one lies beyond RESAMPLE_RATIO times its rms (a shorter step, or none,
    fits the points closer)."""
    from .nearest import nearest_on
    pts = as_points(points, "fit_resampled: points", 2, min_rows=4)
    step = as_positive(step, "fit_resampled: step")
    polygon = resampled_polygon(pts, step)
    if len(polygon) < 4:
        raise ValueError(f"fit_resampled: step {step:g} leaves {len(polygon)} vertices; a fit "
                         "needs 4")
    r = quiet_fit(polygon, model=model, **kwargs)
    bspline = r.to_bspline(tol, degree)
    feet, dist, foot_s = nearest_on(bspline, pts, with_t=True)
    rms = float(np.sqrt(np.mean(dist ** 2)))
    ref = None
    if check:
        ref = resampled_reference(pts, rms, polygon, r.curve, kwargs.get("constraints"))
        if ref is not None:
            say(resample_summary(step, rms, ref, extent=_extent(pts)), ResampleWarning,
                stacklevel=2)
    return ResampledFit(result=r, polygon=polygon, points=pts.copy(), step=float(step),
                        bspline=bspline, distances=dist, feet=feet, rms=rms,
                        max_error=float(np.abs(dist).max()), reference_rms=ref,
                        foot_s=foot_s)


def resample_summary(step: float, rms: float, reference: float, unit: str = "",
                     extent: Optional[float] = None, length: Optional[LengthFormat] = None) -> str:
    """What the warning of a resampled fit far from its points says (Python's, FreeCAD's):
    resampled at ``step``, lying ``rms`` from them, against their own fit's ``reference``.
    Given the points' ``extent``, a reference below RESAMPLE_FLOOR of it (their own fit
    passes through them: rounding) is said in length, not as a ratio to it. ``unit``
    follows each length, or ``length(value, digits)`` writes each (cost_summary's)."""
    fmt = lengths(unit, length)
    far = f"the curve fitted to the points resampled at {fmt(step, None)} lies {fmt(rms, 3)} "
    if extent is not None and reference < RESAMPLE_FLOOR * extent:
        return far + ("from them (rms), where their own fit passes through them: a shorter "
                      "step, or none, fits them closer")
    return far + (f"from them (rms), {rms / reference:.2f} x their own fit's {fmt(reference, 3)}: "
                  "a shorter step, or none, fits them closer")
