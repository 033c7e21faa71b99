"""Least-squares fairing by elasticae (seed 000 §4); the keyline pipeline (§5) is
:mod:`libelastica.keyline`'s.

Both models are fitted by orthogonal distance (each point's distance to the curve,
or to the discrete model's polygon) by default; on equally spaced points the
discrete model pairs vertex i with point i (seed 000 (4.6)).
Every result reports point-to-curve distances: ``distances`` (signed, + = left of the
curve), ``foot_s`` (arc length of each point's foot), ``rms`` and ``max_error``.

>>> import numpy as np, libelastica as el
>>> d = el.DiscreteElastica(x0=1, y0=2, h=0.1, phi=0.3, z=0.08, q=0.2, k=0.7, n=40)
>>> r = el.fit(d.points(), model="discrete")
>>> bool(r.rms < 1e-9)
True
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Mapping, Optional, Union

import numpy as np

from ._ffi import (DomainError, NotConvergedError, SingularError, as_int, as_point_array, as_real,
                   as_real_array, check, checked_points, dptr, ffi, lib, warn_if_degrees)
from ._interrupt import call
from ._median import median
from ._quiet import quiet, say
from .core import DISCRETE_PARAMS, SMOOTH_PARAMS, DiscreteElastica, SmoothElastica
from .cubic import SPARSE_POINTS, SparseWarning, smooth_fits_better
from ._text import LengthFormat, lengths
from ._values import ValueEquality
from .fit_cost import EndConditionWarning, checked_ends
from ._fit_call import one_call
from .fit_input import _is_number, _pair, explain_input_status, require_distinct
from .misfit import (MISFIT_RATIO, MisfitWarning, OutlierWarning, _Figures, _none_far, _places,
                     _verdict, _warn_outliers, misfit_summary)
from .fit_retrace import retrace_gate
from .fit_uncertainty import Uncertain
from .order import (Retrace, curve_order, data_run_back, order_summary, ordering, passed_over,
                    retrace_summary, run_back, turn_back)

_MODES = {"auto": 0, "uniform": 1, "chord": 2}
_MODE_NAMES = {v: k for k, v in _MODES.items()}
_DISTANCES = {"orthogonal": 1, "paired": 2}
_DISTANCE_NAMES = {v: k for k, v in _DISTANCES.items()}
# constraint name -> (C bit, value kind)
_CONSTRAINTS = {
    "start_point": (1, "point"), "end_point": (2, "point"),
    "start_tangent": (4, "angle"), "end_tangent": (8, "angle"),
    "start_curvature": (16, "number"), "end_curvature": (32, "number"),
    "length": (64, "range"), "k": (128, "range"),
}
_CONSTRAINT_NAMES = {bit: name for name, (bit, _) in _CONSTRAINTS.items()}

Curve = Union[DiscreteElastica, SmoothElastica]


class ConstraintError(DomainError):
    """A fit's constraint contradicts the options or another constraint, or the model
    cannot meet it; ``constraint`` names it (a key of ``fit(constraints=...)``)."""

    def __init__(self, status: int, message: str, constraint: Optional[str]):
        super().__init__(status, message)
        self.constraint = constraint


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class FitResult(ValueEquality, Uncertain):
    """Result of :func:`fit`.

    ``curve``: the fitted elastica (a DiscreteElastica with ``n`` = the number of
    points, or a SmoothElastica); ``initial``: the initial guess the kept fit started
    from; ``distances`` (n,): each point's signed distance to the curve (+ = left of
    its direction of travel at the point's foot, - right; ``np.abs`` for the plain
    distances; smooth: the curve over [0, length]; discrete: the polygon of its vertices);
    ``foot_s`` (n,): arc length along the curve of each point's nearest point;
    ``rms`` / ``max_error``: from ``distances`` (input units), to ``curve`` (a discrete
    one's polygon, not its exported cubic: :meth:`cubic_distances`); ``distance``:
    "orthogonal" (what was minimised: the points' distances to the curve / polygon)
    or "paired" (point i <-> vertex i, seed 000 (4.6), the discrete default on equally
    spaced points; or the smooth paired arc lengths); ``iterations``; ``candidates``: the
    initial guesses fitted (fit's max_candidates at most); ``status``: 0 when
    converged, else the C status (EL_ENOCONV / EL_EMAXITER: ``curve`` is the best
    seen); ``ipopt_status`` / ``used_ipopt``: whether Ipopt ran for the kept fit
    (bounds, constraints, its polish when left uncertified) and its return code;
    ``s``: for the smooth model the curve parameter each point was fitted at (its
    foot, or for a paired fit its paired arc length;
    None for discrete); ``param_mode``: "uniform" or "chord" (smooth: the paired arc
    lengths, or the first feet); ``points``: the fitted points; ``constraints``: the
    fit's constraints as given (tangents in radians; :meth:`to_bspline` keeps the ends' on a
    discrete curve);
    ``wander_gap``: i where the curve wanders away from its points between points i and
    i + 1 (it strays there, loops, or swings between them: the C result's ``wander_gap``,
    :func:`fit` warns of it), -1 where it follows them; ``order``: fitted with
    ``order="curve"``, the indices of the caller's points in ``points``' order, else None;
    ``free``: the fit with free ends where :func:`fit` checked what its end conditions cost;
    ``misfit``: where :func:`fit` judged it (``check_misfit``) and found it far farther from
    the points than their noise, a :class:`libelastica.misfit.Misfit` (the points are not one
    elastica; its ``corner`` an index into ``points``), else None; ``sparse``: where
    :func:`fit` checked it (``check_sparse``), a discrete fit of fewer than SPARSE_POINTS
    points far farther from them than the smooth model's fit: that fit's rms, else None;
    ``retrace``: where :func:`fit` warned of points that run back along the curve (an
    OrderWarning), the :class:`libelastica.order.Retrace` it named, else None; ``fixed``: :func:`fit`'s
    ``fixed``; :meth:`uncertainty`, ``covariance``, ``stderr``: fit_uncertainty.py.
    """
    curve: Curve
    initial: Curve
    rms: float
    max_error: float
    iterations: int
    status: int
    ipopt_status: int
    candidates: int
    s: Optional[np.ndarray] = None
    param_mode: Optional[str] = None
    distances: Optional[np.ndarray] = None
    foot_s: Optional[np.ndarray] = None
    distance: str = "paired"
    used_ipopt: bool = False
    points: Optional[np.ndarray] = None
    constraints: Optional[Mapping[str, object]] = None
    wander_gap: int = -1
    order: Optional[np.ndarray] = None
    free: Optional["FitResult"] = None
    misfit: Optional[object] = None
    sparse: Optional[float] = None
    retrace: Optional[Retrace] = None
    fixed: Optional[Mapping[str, float]] = None

    @property
    def converged(self) -> bool:
        return self.status == lib.EL_OK

    def __repr__(self) -> str:
        """A summary (the arrays are the data's size: print them by name)."""
        n = next((len(a) for a in (self.points, self.distances) if a is not None), None)
        state = "converged" if self.converged else f"not converged (status {self.status})"
        kind = "smooth" if isinstance(self.curve, SmoothElastica) else "discrete"
        return (f"FitResult({kind}, {n} points, {self.distance}, rms {self.rms:.3g}, max "
                f"{self.max_error:.3g}, {state}{', misfit' if self.misfit is not None else ''}, "
                f"curve={self.curve!r})")

    def to_bspline(self, tol: Optional[float] = None, degree: int = 3):
        """The fitted curve as one B-spline for CAD: a smooth elastica's within ``tol``
        (default 1e-6 of its length; certified; its end points, tangents and curvatures exact, so the constraints hold
        on it); a discrete one's C2 cubic through its vertices (:func:`cubic_through`)
        with the fit's constrained end tangents and curvatures (G2 where both), natural
        ends elsewhere (``tol`` and ``degree`` unused, ``max_deviation`` NaN). That cubic
        runs elsewhere than the polygon between the vertices: ``rms`` / ``max_error`` are
        the polygon's, not its (7 sketched points: 0.316 / 0.561, the cubic 0.647 / 1.487);
        :meth:`cubic_distances` measures it."""
        from .bspline import fitted_bspline
        return fitted_bspline(self.curve, tol, degree, self.constraints)

    def cubic_distances(self, bspline=None):
        """``(feet, distances)`` (by name too): a discrete fit's points' feet on its exported cubic
        (:meth:`to_bspline`, or ``bspline``), signed distances: :func:`.cubic.cubic_distances`."""
        from .cubic import cubic_distances
        return cubic_distances(self, bspline)

    def model_points(self) -> np.ndarray:
        """The model points the fit used for the data points, shape (n, 2): the feet
        (orthogonal), the paired curve points or the vertices (paired)."""
        if self.distance == "orthogonal":
            return self.foot_points()
        if isinstance(self.curve, DiscreteElastica):
            return self.curve.points()
        return self.curve.points(self.s)

    def outliers(self, factor: Optional[float] = None, free_distances=None) -> np.ndarray:
        """Indices of the points far from the fitted curve (:func:`far_points`: beyond
        ``factor`` times their typical distance, default OUTLIER_FACTOR = 6;
        ``free_distances``: a constrained fit's points' distances without its constraints)."""
        return far_points(self.distances, self.points,
                          OUTLIER_FACTOR if factor is None else factor, free_distances)

    def foot_points(self) -> np.ndarray:
        """Each data point's nearest point on the curve (the other end of its
        distance), shape (n, 2)."""
        c = self.curve
        if isinstance(c, SmoothElastica):
            return c.points(self.foot_s)
        V = c.points()
        j = np.clip(np.floor(self.foot_s / c.h).astype(int), 0, len(V) - 2)
        t = (self.foot_s / c.h - j)[:, None]
        return V[j] + t * (V[j + 1] - V[j])


OUTLIER_FACTOR = 6.0
OUTLIER_MIN_POINTS = 20
OUTLIER_FLOOR = 1e-4
OUTLIER_GAP = 1.5


def far_points(distances, points, factor: float = OUTLIER_FACTOR,
               free_distances=None) -> np.ndarray:
    """Indices of the points whose distance to a fitted curve exceeds ``factor`` times the
    typical distance, 1.4826 x the median |distance| (for normal noise its standard
    deviation, which a few far points hardly move), standing apart from the others (a step
    of more than OUTLIER_GAP between them and the next nearer), and OUTLIER_FLOOR of the
    points' extent (on nearly exact data the distances are the model's own small misfit: 60 points
    of a sketched B-spline fitted to 0.00026 mm on 330 mm had 6 "outliers" at 0.0004-0.0012
    mm under a floor of 1e-6): scan glitches, points of other geometry, each pulling a
    least-squares fit towards itself. None among fewer than OUTLIER_MIN_POINTS points (too
    few for a typical distance). ``free_distances``: for a constrained fit, the same points'
    distances to the fit without its constraints; a point is far only when far from both
    (a length held short of the data's left its two end points 2.2 off, the others within
    0.5: no glitches, the constraint's cost)."""
    d = np.abs(as_real_array(distances, "far_points: distances"))
    pts = as_point_array(points, "far_points: points")
    if d.ndim != 1 or pts.ndim != 2 or len(pts) != len(d):
        raise ValueError("far_points: distances (n,) and points (n, 2 or 3) are needed")
    if free_distances is not None:
        free = far_points(free_distances, pts, factor)
        return np.intersect1d(far_points(d, pts, factor), free)
    if len(d) < OUTLIER_MIN_POINTS:
        return np.empty(0, dtype=np.intp)
    med = median(d)                     # (np.median's value, by one np.partition: _median.py)
    if _none_far(med, d.max(), factor):     # none far (el.fit asks this of every fit): no extent
        return np.empty(0, dtype=np.intp)
    typical = 1.4826 * med
    extent = float(np.max(np.ptp(pts, axis=0)))
    m = int(np.count_nonzero((d > factor * typical) & (d > OUTLIER_FLOOR * extent)))
    if m == 0 or m == len(d):
        return np.empty(0, dtype=np.intp)
    # and apart from the others: the far points are the largest distances down to the last
    # step of more than OUTLIER_GAP among them (a misfit rising towards an end condition the
    # data do not follow is no glitch: one of 165 points at 7.02 mm, the next at 5.13)
    order = np.argsort(-d, kind="stable")
    top = d[order[:m + 1]]
    steps = np.nonzero(top[:-1] > OUTLIER_GAP * top[1:])[0]
    return np.sort(order[:steps[-1] + 1]) if len(steps) else np.empty(0, dtype=np.intp)


def far_points_summary(distances, far, unit: str = "", free_distances=None,
                       length: Optional[LengthFormat] = None) -> str:
    """What a warning of far points says (the CLI's and FreeCAD's): how many of the points
    lie how far from the curve and how near the others are, "3 of 60 points lie 9.05 to 16
    from the curve, the others within 1.69" (``unit`` after the distances, e.g. " mm", or
    ``length(value, digits)`` writing each: cost_summary's); far: their indices
    (:func:`far_points`), at least one. ``free_distances`` (a constrained fit's, as
    far_points took them): the figures are from the fit with free ends, where the
    far points stand apart (from the constrained curve a glitch 6 off lay 2.34, "the others
    within 2.56": the constraint's cost)."""
    where = "from the curve"
    if free_distances is not None:
        distances, where = free_distances, "from the curve with free ends"
    d = np.abs(np.asarray(distances, dtype=float))
    far = np.asarray(far, dtype=np.intp)
    if d.ndim != 1 or far.ndim != 1 or not len(far) or len(far) >= len(d):
        raise ValueError("far_points_summary: distances (n,) and 1 to n - 1 indices of far points are needed")
    rest, fmt = np.delete(d, far), lengths(unit, length)
    lie = (f"lies {fmt(d[far][0], 3)}" if len(far) == 1 else
           f"lie {fmt(d[far].min(), 3, False)} to {fmt(d[far].max(), 3)}")
    return f"{len(far)} of {len(d)} points {lie} {where}, the others within {fmt(rest.max(), 3)}"


class ConvergenceWarning(RuntimeWarning):
    """:func:`fit`'s warning that the fit did not converge (``FitResult.status`` != 0):
    the best curve seen is returned (``strict=True`` raises NotConvergedError instead)."""


class WanderWarning(RuntimeWarning):
    """:func:`fit`'s warning that the fitted curve wanders away from its points between
    two of them (``FitResult.wander_gap``), where their distances do not show it."""


class OrderWarning(WanderWarning):
    """:func:`fit`'s warning that the points are not in order along a curve (an unordered
    cloud: :func:`out_of_order`): the curve passes them in their order, and may coil
    through their noise band at a lower rms than the true curve's (QA: a 30 m line's 2500
    points shuffled, fitted 1.1 km long at rms 20.6 mm against 30.0 mm); ``order="curve"``
    fits them in curve order. Also points in order that run back over part of the curve (a
    scan passed back and forth: :func:`libelastica.order.run_back` on the fit's feet, or,
    where the fit does not follow the points (not converged, or MISFIT_RATIO times their
    noise away), on their own pass before they turn, :func:`libelastica.order.data_run_back`:
    both models alike), named, instead of the WanderWarning such a fit may raise."""


def wander_summary(gap: int, points=None, unit: str = "", numbered: bool = True,
                   length: Optional[LengthFormat] = None) -> str:
    """What a warning of a curve that wanders says (:func:`fit`'s, the CLI's and FreeCAD's):
    "the curve wanders away from its points between points 3 and 4 (counted from 0; at
    (x, y) and (x, y)): ...". gap: ``FitResult.wander_gap`` (>= 0); points: the fitted
    points, to name the two's places (4 digits of their size: the CLI's coordinates; unit
    after each coordinate, or ``length(value, digits)`` writing each: cost_summary's);
    numbered False: by their places alone ("between the points at (x, y) and (x, y)"),
    where the numbers are the fit's order, not the user's."""
    gap = int(gap)
    if gap < 0 or (points is None and not numbered):
        raise ValueError("wander_summary: the gap of a curve that wanders (>= 0) is needed, and "
                         "the points to name them by their places")
    places = ""
    if points is not None:
        p = as_point_array(points, "wander_summary: points")
        if p.ndim != 2 or gap + 1 >= len(p):
            raise ValueError("wander_summary: points (n, 2 or 3) with n > gap + 1 are needed")
        places = " and ".join(_places(p, (gap, gap + 1), lengths(unit, length)))
    where = (f"points {gap} and {gap + 1} (counted from 0{'; at ' + places if places else ''})"
             if numbered else f"the points at {places}")
    return (f"the curve wanders away from its points between {where}: it loops, strays, swings "
            "or passes them out of order where no point holds it, its distances to the points small all the same")


def _set_constraints(o, model: str, n: int, constraints: Optional[Mapping[str, object]]):
    """Fill the constraint fields of the C options from the dict."""
    for name, value in (constraints or {}).items():
        if name not in _CONSTRAINTS:
            raise ValueError(f"fit: unknown constraint {name!r}; one of {tuple(_CONSTRAINTS)}")
        bit, kind = _CONSTRAINTS[name]
        where = name.split("_")[0]
        if kind == "point":
            x, y = _pair(value, name)
            if x is None or y is None or not (math.isfinite(x) and math.isfinite(y)):
                raise ValueError(f"fit: constraint {name!r} must be a finite point, got {value!r}")
            getattr(o, f"{where}_point")[0] = x
            getattr(o, f"{where}_point")[1] = y
        elif kind in ("angle", "number"):
            if kind == "angle" and np.ndim(value) == 1 and np.size(value) == 2:   # hermite's (tx, ty)
                raise ValueError(f"fit: constraint {name!r} is an angle in radians (the direction of "
                                 f"travel), got the pair {value!r}: for (tx, ty) give math.atan2(ty, tx)")
            v = as_real(value, f"fit: constraint {name!r}")
            if kind == "angle":   # (stack: _options, _fit, fit, its caller)
                warn_if_degrees(v, f"fit: constraint {name!r}", stacklevel=5)
            setattr(o, f"{where}_{'tangent' if kind == 'angle' else 'curvature'}", v)
        else:   # "length": L alone is (L, L), the CLI's --length L
            lo, hi = (value, value) if name == "length" and _is_number(value) else _pair(value, name)
            lo = (0.0 if name == "length" else -math.inf) if lo is None else lo
            hi = math.inf if hi is None else hi
            if math.isnan(lo) or math.isnan(hi) or lo > hi or (name == "length" and lo < 0):
                raise ValueError(f"fit: constraint {name!r} must be "
                                 f"{'a length L >= 0 or ' if name == 'length' else ''}a range "
                                 f"(lo, hi) with {'0 <= ' if name == 'length' else ''}lo <= hi, "
                                 f"got {value!r}")
            rng = o.length_range if name == "length" else o.k_range
            rng[0], rng[1] = lo, hi
        o.constraints |= bit


def _options(model: str, n: int, fixed: Optional[Mapping[str, float]], bounds, tol, max_iter,
             limited_memory, max_candidates, param, initial, distance, constraints):
    names = DISCRETE_PARAMS if model == "discrete" else SMOOTH_PARAMS
    o = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(o)
    for name, value in (fixed or {}).items():
        if name not in names:
            raise ValueError(f"fit: unknown parameter {name!r} for model {model!r}; one of {names}")
        v = as_real(value, f"fit: fixed {name}")
        j = names.index(name)
        o.fixed[j] = 1
        o.value[j] = v
    for name, (lo, hi) in (bounds or {}).items():
        if name not in names:
            raise ValueError(f"fit: unknown parameter {name!r} in bounds")
        j = names.index(name)
        o.lower[j] = -np.inf if lo is None else as_real(lo, f"fit: lower bound of {name}", finite=False)
        o.upper[j] = np.inf if hi is None else as_real(hi, f"fit: upper bound of {name}", finite=False)
    if tol is not None:
        o.tol = as_real(tol, "fit: tol")
    if max_iter is not None:
        o.max_iter = as_int(max_iter, "fit: max_iter")
    o.limited_memory = 1 if limited_memory else 0
    if max_candidates is not None:
        o.max_candidates = as_int(max_candidates, "fit: max_candidates")
    if param not in _MODES:
        raise ValueError(f"fit: param must be one of {tuple(_MODES)}, got {param!r}")
    o.param_mode = _MODES[param]
    if distance is not None:
        if distance not in _DISTANCES:
            raise ValueError(f"fit: distance must be one of {tuple(_DISTANCES)}, got {distance!r}")
        o.distance = _DISTANCES[distance]
    o.use_initial = 1 if initial is not None else 0
    if fixed or bounds or tol is not None or max_iter is not None or max_candidates is not None:
        _check_option_ranges(o, model, names)   # (el_fit_options_defaults' are in range)
    _set_constraints(o, model, n, constraints)
    return o


def _check_option_ranges(o, model: str, names) -> None:
    """The C library's ranges of the options (el_fit_*: EL_EINVAL), named: its own
    message names neither the option nor the range."""
    for j, name in enumerate(names):
        lo, hi = o.lower[j], o.upper[j]
        if math.isnan(lo) or math.isnan(hi) or lo > hi:
            raise ValueError(f"fit: bounds of {name} must be (lo, hi) with lo <= hi, got ({lo:g}, {hi:g})")
        if not o.fixed[j]:
            continue
        v = o.value[j]
        positive = name == ("h" if model == "discrete" else "mu")
        if (positive and not v > 0.0) or (model == "smooth" and name == "length" and v < 0.0):
            raise ValueError(f"fit: fixed {name} must be {'> 0' if positive else '>= 0'}, got {v:g}")
        if not lo <= v <= hi:
            raise ValueError(f"fit: fixed {name} = {v:g} lies outside its bounds ({lo:g}, {hi:g})")
    for what, ok in (("tol must be > 0", o.tol > 0.0), ("max_iter must be >= 1", o.max_iter >= 1),
                     ("max_candidates must be >= 1", o.max_candidates >= 1)):
        if not ok:
            raise ValueError(f"fit: {what}, got {getattr(o, what.split()[0]):g}")


def _conditions(constraints: Optional[Mapping[str, object]], fixed: Optional[Mapping[str, float]]) -> int:
    """The equations the constraints and fixed parameters impose on the curve's 7 parameters
    (a point 2, a tangent or curvature 1, a fixed parameter 1; x0, y0 are the start point's)."""
    dims = {"point": 2, "angle": 1, "number": 1, "range": 0}
    held = set(fixed or ())
    if "start_point" in (constraints or {}):
        held -= {"x0", "y0"}
    return sum(dims[_CONSTRAINTS[name][1]] for name in (constraints or {})) + len(held)


def _raise_constraint(status: int, constraint: int, conditions: int, constraints=None) -> None:
    name = _CONSTRAINT_NAMES.get(constraint)
    if status == lib.EL_EINVAL:
        msg = f"fit: constraint {name!r} contradicts the options or another constraint"
    else:
        msg = f"fit: no elastica of the model meets constraint {name!r} (to 1e-10 of the data's size)"
        if conditions > 7:
            # e.g. point, tangent and curvature at both ends (a G2 join of two edges): a
            # curve of 7 parameters meets 8 equations only where they come from one elastica
            msg += (f"; the constraints are {conditions} equations on the 7 parameters of one "
                    "elastica, met together only by values taken from one elastica's ends")
            if all(f"{e}_{c}" in (constraints or {}) for e in ("start", "end")
                   for c in ("point", "tangent", "curvature")):
                # (QA24 F7: G2 at both ends, 120/120 refused, without the way that joins them)
                msg += ("; to join G2 at both ends, el.elastic_spline(points, start={'tangent': "
                        "(tx, ty), 'curvature': k}, end={...}) passes through points taken "
                        "along these (a spline of elasticae, G2 at its ends)")
    raise ConstraintError(status, msg, name)


def _make_curve(model: str, p, n: int, ptr=None) -> Curve:
    """The curve of the C parameters p (a struct of C doubles, read as floats), checked
    by the model's C check on p itself (ptr: p's address, when the caller has it), as the
    constructor checks the struct it builds from the same floats; the constructor's
    conversions and second struct are left out (measured: a third of el.fit's Python time
    after a 1000-point fit; test_fit_result_curves_are_constructed_ones compares)."""
    discrete = model == "discrete"
    cls, names = (DiscreteElastica, DISCRETE_PARAMS) if discrete else (SmoothElastica, SMOOTH_PARAMS)
    check((lib.el_discrete_check if discrete else lib.el_smooth_check)(
        ffi.addressof(p) if ptr is None else ptr), cls.__name__)
    curve = object.__new__(cls)
    curve.__dict__.update({k: getattr(p, k) for k in names})
    if discrete:
        curve.n = n
    return curve


# a fit result's params' and initial's addresses: a pointer cast (ffi.addressof: 5 % of el.fit's Python time)
_PARAMS = {m: (ffi.typeof(f"el_{m}_params *"),
               ffi.offsetof(f"el_fit_{m}_result", "params"), ffi.offsetof(f"el_fit_{m}_result", "initial"))
           for m in ("discrete", "smooth")}
_BYTES = ffi.typeof("char *")


def _result(model: str, res, st: int, pts: np.ndarray, dist: np.ndarray, foot: np.ndarray,
            s: Optional[np.ndarray] = None, constraints=None, order=None,
            retrace: Optional[Retrace] = None, fixed=None) -> FitResult:
    n = len(pts)
    ptr, a, b = _PARAMS[model]
    base = ffi.cast(_BYTES, res)
    return _fit_result(curve=_make_curve(model, res.params, n, ffi.cast(ptr, base + a)),
                       initial=_make_curve(model, res.initial, n, ffi.cast(ptr, base + b)),
                       rms=float(res.rms), max_error=float(res.max_error),
                       iterations=int(res.iterations), status=int(st),
                       ipopt_status=int(res.ipopt_status), candidates=int(res.candidates), s=s,
                       param_mode=_MODE_NAMES.get(int(res.param_mode)) if model == "smooth" else None,
                       distances=dist, foot_s=foot, distance=_DISTANCE_NAMES[int(res.distance)],
                       used_ipopt=bool(res.used_ipopt), points=pts, order=order, retrace=retrace,
                       constraints=dict(constraints) if constraints else None,
                       wander_gap=int(res.wander_gap), fixed=dict(fixed) if fixed else None)


_RESULT_FIELDS = tuple(f.name for f in dataclasses.fields(FitResult))
_RESULT_DEFAULTS = {f.name: f.default for f in dataclasses.fields(FitResult)
                    if f.default is not dataclasses.MISSING}


def _fit_result(**given) -> FitResult:
    """FitResult(**given) without the frozen dataclass's __init__ (an object.__setattr__ a field:
    a sixth of el.fit's Python time), defaults where not given (test_fit_result_is_a_constructed_one)."""
    r = object.__new__(FitResult)
    r.__dict__.update({k: given[k] if k in given else _RESULT_DEFAULTS[k] for k in _RESULT_FIELDS})
    return r


def fit(points, model: str = "discrete", fixed: Optional[Mapping[str, float]] = None, *,
        constraints: Optional[Mapping[str, object]] = None, distance: Optional[str] = None,
        bounds: Optional[Mapping[str, tuple]] = None, tol: Optional[float] = None,
        max_iter: Optional[int] = None, limited_memory: bool = False,
        max_candidates: Optional[int] = None, param: str = "auto", initial: Optional[Curve] = None,
        strict: bool = False, order: str = "given", check_ends: bool = True,
        check_misfit: bool = True, check_sparse: bool = True) -> FitResult:
    """Fit an elastica to the points (n, 2), n >= 4, in their order along the curve.

    model: "discrete" (a polygon of n vertices, one per point) or "smooth". distance:
    "orthogonal" (the distances of the points to the curve or polygon, each point's
    foot free; the curve starts and ends at the first and last points' feet, the
    polygon at those points) or "paired" (discrete: vertex i <-> point i, seed 000
    (4.6); smooth: point i at arc length i*length/(n-1) for equilateral data, the
    chord-length parameter, the points' estimated noise taken out of each chord,
    otherwise; ``param`` = "auto" | "uniform" | "chord").
    Default: orthogonal, except the discrete model on equally spaced points (an
    equilateral polygon, e.g. from :func:`resample_equilateral`, or samples at equal
    steps: runs of max(3, (n-1)/16) segments of means within 1.3 x) in one pass (not a
    scan passed back and forth) whose paired fit keeps each point at its vertex (they
    slip along the polygon by at most 1.3 x their distance from it, rms, a free fit's
    points by at most a segment or 1.3 x the noise across it, as dense points at random
    places do not, and skip no vertex, as at a point missing from the scan): paired.
    Sketched or unevenly scanned points need no resampling. A fit by distance to the
    curve follows the points: one that strays from them (a loop or a pass where there is
    no point, the points passed out of order) is fitted again from the paired fit and
    replaced when that one follows them, even at a higher rms (free fits and those whose
    constraints are held exactly: the start point and tangent, the smooth start
    curvature). A fit kept that still loops, strays, swings or passes its points out of order between two (its
    distances small all the same) warns (WanderWarning) naming that gap, also
    ``FitResult.wander_gap``. The result's ``distances`` are signed: + where the point lies
    left of the curve's direction of travel at its foot (from near the first point to near
    the last), - right; ``np.abs`` gives the plain distances, as ``rms`` / ``max_error``
    take them. order: "given" (the points' order is the curve's: points
    not in order along a curve, their polyline more than 3 times as long as in curve order
    (:func:`out_of_order`: a shuffled scan or clicks), warn (OrderWarning, a WanderWarning)
    and are fitted as given) or "curve" (fitted in :func:`curve_order`'s order; the result's
    ``points``, ``distances`` and ``foot_s`` in it, ``FitResult.order`` its indices).
    Points in their order that run back over the curve (a scan passed back and forth,
    :func:`libelastica.order.run_back`), or whose fit in their order is far off or not
    converged, are fitted in curve order too (free fits by distance), and that fit is kept
    where its feet show the points run back and it lies nearer them: the curve passing
    there once, its ``distances`` and ``foot_s`` in the points' order (OrderWarning, ``retrace``;
    a smooth curve runs from the end of the first point, a discrete one as curve order does).
    max_candidates: initial
    guesses fitted at most (default 6; fitting stops at the first that reaches the
    data's noise level). max_iter: Ipopt iterations per initial guess (default 200).
    tol: Ipopt's tol on the normalised problem (default 1e-12). limited_memory: True runs
    the paper's setting, Ipopt with its L-BFGS Hessian (for comparison; the default,
    False, is the library's exact-Hessian path; README: "limited_memory=True").
    constraints: any of ``{"start_point": (x, y), "end_point": (x, y),
    "start_tangent": angle, "end_tangent": angle, "start_curvature": kappa,
    "end_curvature": kappa, "length": (lo, hi), "k": (lo, hi)}`` (angles in radians,
    the direction of travel from the first point to the last; curvature signed, +
    turning left, 0 an inflection; ranges with None for no limit; ``"length": L``, one
    number, is the exact length (L, L), as the CLI's --length), met to 1e-10 of the
    data's size or ConstraintError naming the one that cannot be met. The discrete
    model's tangent at vertex j is theta_j = phi + 2 a(q + j z), the tangent of the
    smooth elastica with its phi, k, q and mu = 1 at s = j z (segment j runs at the mean
    of theta_j and theta_j+1, seed 000 (4.4)). Both end points with both curvatures 0
    (the natural batten): the smooth fit searches every curve that meets them (no
    Ipopt), leaves out those that cross themselves and keeps the nearest that follows the
    points; the discrete fit starts from it.
    fixed: parameters held at given values, e.g. ``{"x0": 0, "y0": 0}`` or ``{"h": r}``.
    bounds: ``{name: (lo, hi)}`` (None = unbounded). initial: start from this curve
    instead of the automatic guess (a smooth fit by distance without constraints: from the
    points' nearest points on it, so points exactly on it give it back); a curve that runs
    against the points' order is run backwards first (the same curve). A fit that does not
    converge returns the best curve seen with ``status`` != 0 and warns (ConvergenceWarning;
    raises NotConvergedError if ``strict``). Bad input (NaN, too few points, all points equal) raises ValueError /
    ElasticaError subclasses. check_ends: with constraints or fixed, fit with free ends too
    (``FitResult.free``) and warn (EndConditionWarning, fit_cost.py) where they cost accuracy;
    that free fit is not capped by ``max_iter`` (a capped one misprices the ends: 10.2 for
    9.24, QA). check_misfit: judge the fit (with end conditions or bounds: the free fit,
    where check_ends made one; not a fit asked to be paired) against the points' own noise
    (:func:`libelastica.misfit.misfit`) and warn (MisfitWarning, ``FitResult.misfit``) where
    it lies far above it: the points are not one elastica (a corner, named where one stands
    out); points far from the curve, :func:`far_points` (a constrained fit's: far from its
    free fit too), warn OutlierWarning naming them. check_sparse: a discrete fit of fewer than SPARSE_POINTS points (a polygon of as
    few segments, which cuts their bends) is compared with the smooth model's fit of them
    with the same constraints (:func:`smooth_fits_better`, on the larger of the polygon's
    rms and its exported cubic's, :meth:`FitResult.cubic_distances`) and warns
    (SparseWarning, ``FitResult.sparse``) where that one lies far nearer.
    """
    return _fit(points, model, fixed, constraints=constraints, distance=distance, bounds=bounds,
                tol=tol, max_iter=max_iter, limited_memory=limited_memory,
                max_candidates=max_candidates, param=param, initial=initial, strict=strict,
                order=order, check_ends=check_ends, check_misfit=check_misfit,
                check_sparse=check_sparse)


def _fit(points, model: str = "discrete", fixed: Optional[Mapping[str, float]] = None, *,
         constraints: Optional[Mapping[str, object]] = None, distance: Optional[str] = None,
         bounds: Optional[Mapping[str, tuple]] = None, tol: Optional[float] = None,
         max_iter: Optional[int] = None, limited_memory: bool = False,
         max_candidates: Optional[int] = None, param: str = "auto", initial: Optional[Curve] = None,
         strict: bool = False, order: str = "given", check_ends: bool = True,
         check_misfit: bool = True, check_sparse: bool = True, gate: bool = True) -> FitResult:
    """:func:`fit`'s work (its warnings one frame deeper: stacklevel 3 names fit's caller);
    gate False: without the back-and-forth gate (fit_retrace.py), :func:`judging_fit`'s."""
    if not isinstance(model, str) or model not in ("discrete", "smooth"):
        raise ValueError(f"fit: model must be 'discrete' or 'smooth', got {model!r}")
    pts = as_point_array(points, "points")
    if pts.ndim == 2 and pts.shape[1] == 3:   # what the CLI and FreeCAD do with 3D points
        raise ValueError(f"fit: points must have shape (n, 2), got {pts.shape}: 3D points are "
                         "fitted in their plane, xy, frame = el.plane_fit(points), then "
                         "el.fit(xy) (frame.to_3d maps back), or el.fit_keyline(points); a third "
                         "column that is no coordinate (an id, an intensity): pass "
                         "points[:, :2]")
    smooth, one = model == "smooth", None
    if order == "given" and initial is None and not constraints:    # one crossing (_fit_call.py)
        one = one_call(pts, model, lambda n: _options(model, n, fixed, bounds, tol, max_iter, limited_memory,
                                                      max_candidates, param, None, distance, None))
    if one is not None:
        idx, (pts, n, unordered, fig, o, res, st, dist, foot, screened) = None, one
    else:
        screened = None
        pts = checked_points(pts, "points", 2)
        n = pts.shape[0]
        require_distinct(pts)       # 4 or more, repeats counted once (QA qapy F6)
        if order not in ("given", "curve"):
            raise ValueError(f"fit: order must be 'given' or 'curve', got {order!r}")
        idx, unordered = None, None
        if order == "curve":
            idx = curve_order(pts)
            pts = np.ascontiguousarray(pts[idx])
        else:
            unordered = ordering(pts)
        # the points' noise figures, computed once where a test below asks them: the check of a
        # fit in the points' order, of points that turn back, the misfit verdict (its points are
        # these: the result's, or its free fit's, a fit of the same points)
        fig = _Figures(pts)
        kind = SmoothElastica if model == "smooth" else DiscreteElastica
        if initial is not None and not isinstance(initial, kind):
            raise ValueError(f"fit: initial must be a {kind.__name__} for the {model} model, got "
                             f"{type(initial).__name__}")
        try:   # options of the wrong shape (not a mapping, bounds not pairs, ...): ValueError
            o = _options(model, n, fixed, bounds, tol, max_iter, limited_memory, max_candidates, param,
                         initial, distance, constraints)
            init = initial._c() if initial is not None else ffi.NULL
        except (TypeError, AttributeError) as exc:
            raise ValueError(f"fit: invalid option ({exc})") from None
        res = ffi.new(f"el_fit_{model}_result *")
        dist, foot = np.empty(n), np.empty(n)
        st = call(lib.el_fit_smooth if smooth else lib.el_fit_discrete, dptr(pts), n, o, init, res,
                  dptr(dist), dptr(foot), keep=(pts, dist, foot, initial))     # Ctrl-C: the CLI's
    explain_input_status(st, pts)       # NaN / inf, an extent out of range: named (QA25 F5)
    if res.constraint and st in (lib.EL_EINVAL, lib.EL_EDOM):
        _raise_constraint(st, res.constraint, _conditions(constraints, fixed), constraints)
    if st == lib.EL_ESINGULAR and bool(np.all(pts == pts[0])):   # the CLI's words (QA20 F8)
        raise SingularError(st, f"fit: all points are equal ({n} x ({pts[0, 0]:.10g}, "
                            f"{pts[0, 1]:.10g})): no curve passes them")
    if st not in (lib.EL_OK, lib.EL_ENOCONV, lib.EL_EMAXITER):
        check(st, "fit")
    s = None
    if smooth:
        if res.distance == _DISTANCES["paired"]:
            t = np.empty(n)
            check(lib.el_fit_fractions(dptr(pts), n, res.param_mode, dptr(t), ffi.NULL), "fit")
            s = t * res.params.length
        else:
            s = foot.copy()
    back, given_rms, tried, flip = None, None, None, False
    if (gate and unordered is not None and unordered.order is None
            and res.distance != _DISTANCES["paired"] and not (constraints or fixed or bounds)
            and initial is None):
        res, st, dist, foot, s, back, given_rms, tried, flip = retrace_gate(
            model, pts, o, res, st, dist, foot, s, fig)
    if strict and st != lib.EL_OK:
        check(st, "fit")
    if st != lib.EL_OK:     # a status 6 went unnoticed unless the caller read it (QA)
        say(f"fit: not converged: {ffi.string(lib.el_strerror(st)).decode()} (status {st}); "
            "strict=True raises instead", ConvergenceWarning, stacklevel=3)
    if unordered is not None and unordered.order is not None:
        say(f"fit: {order_summary(unordered)}: fitted in their order, the curve may coil "
            "through them; order='curve' fits them in curve order (el.curve_order)",
            OrderWarning, stacklevel=3)
    elif given_rms is not None:
        say(f"fit: {retrace_summary(back)}: fitted in curve order (as order='curve'; "
            f"el.curve_order) at rms {res.rms:.3g}, against {given_rms:.3g} in the "
            "points' order, distances and feet given in the points' order",
            OrderWarning, stacklevel=3)
    else:
        # points that run back: the fit's feet fall there when it follows them (the smooth
        # model's, by distance); a fit that coils or wanders through a scan passed back and
        # forth over its whole length does not (QA20 F4: the discrete model's, status 6,
        # rms 37 at noise 0.4, said no OrderWarning; a smooth one said a WanderWarning):
        # the feet on the points' own pass before their turn then (data_run_back), the
        # cause said instead of the wander it makes
        # a misfit in curve order (order='curve') or that it fits no closer than half, its points
        # off their pass before (passed_over): no scan passed back and forth (QA24 F3: an 'e',
        # "points 80 to 206 run back", rms 2.00 either order; a square passed back and forth: said)
        shape = ((idx is not None or (tried is not None and not tried < 0.5 * res.rms))
                 and _verdict(fig, dist, float(res.rms), False) is not None)
        if back is None and res.wander_gap < 0 and res.distance != _DISTANCES["paired"]:
            back = run_back(pts, foot, res.rms)
        # (only where the points turn back and the fit does not follow them: not converged
        # or MISFIT_RATIO times their noise away; a coil of 20 sketched points turns back as
        # a scan passed back and forth does: 1 of bench_fit.py's 504 point sets, its fit at
        # 0.07 x their noise, wandering, was named so without this gate)
        # (the cheap tests first: el_fit_noise_quick's figure is never above noise_level's, so
        # a converged fit within MISFIT_RATIO of it is within it of noise_level's too; the
        # figures are those the misfit verdict takes, computed once; noise_level's stride
        # search 12 ms on 1000 points)
        if back is None and (st != lib.EL_OK or res.rms > MISFIT_RATIO * fig.quick) \
                and turn_back(pts) and (st != lib.EL_OK or res.rms > MISFIT_RATIO * fig.level):
            back = data_run_back(pts, res.rms)
        if back is not None and shape and not passed_over(pts, back, MISFIT_RATIO * fig.level):
            back = None
        if back is not None:
            hint = ("order='curve' fits them in curve order (el.curve_order)" if tried is None else
                    f"in curve order (order='curve') the rms is {tried:.3g}, against {res.rms:.3g}")
            say(f"fit: {retrace_summary(back)}; {hint}", OrderWarning, stacklevel=3)
        elif res.wander_gap >= 0:
            say(f"fit: {wander_summary(res.wander_gap)}: add a point between them to hold it "
                "there, or bound the curve's length (constraints={'length': (lo, hi)})",
                WanderWarning, stacklevel=3)
    r = _result(model, res, st, pts.copy(), dist, foot, s, constraints, idx, back, fixed)
    if flip:     # the same curve run from the end of point 0 (curve order ran from the other)
        r = _fit_result(**dict(r.__dict__, curve=r.curve.reversed(), initial=r.initial.reversed()))
    if check_ends and (constraints or fixed):
        r = checked_ends(r, fixed, dict(model=model, distance=distance, bounds=bounds, tol=tol,
                         limited_memory=limited_memory, max_candidates=max_candidates, param=param),
                         stacklevel=4)
    if check_misfit:
        r = _judged(r, judged_fit(r, constraints or fixed or bounds, distance), fig)
        _warn_outliers(r, screened)
    if check_sparse and not smooth and n < SPARSE_POINTS:
        r = _sparse(r, constraints)
    return r


def _sparse(r: FitResult, constraints) -> FitResult:
    """r with its ``sparse`` (:func:`smooth_fits_better` on the larger of its polygon's rms
    and its exported cubic's, the same constraints) and a SparseWarning where the smooth
    model's fit lies far nearer the points; r where it does not."""
    try:
        cubic = float(np.sqrt(np.mean(r.cubic_distances()[1] ** 2)))
    except (ValueError, ArithmeticError, RuntimeError):
        cubic = 0.0
    rms = max(float(r.rms), cubic)
    smooth = smooth_fits_better(r.points, rms, constraints)
    if smooth is None:
        return r
    n = len(r.points)
    say(f"fit: the discrete model's polygon of {n - 1} segments lies {r.rms:.3g} from "
        f"the {n} points (rms), its cubic {cubic:.3g}, the smooth model's curve "
        f"{smooth:.3g}: fewer than {SPARSE_POINTS} points; use model='smooth'",
        SparseWarning, stacklevel=4)
    return dataclasses.replace(r, sparse=smooth)


def judged_fit(r: FitResult, held, distance: Optional[str] = None) -> Optional[FitResult]:
    """The fit whose misfit :func:`fit` judges (check_misfit; FreeCAD's fit judges the same):
    r, or where it holds something (held: its end conditions, fixed parameters or bounds,
    any truthy value) the fit with free ends it made (``r.free``: their cost is
    EndConditionWarning's); None where there is none, it has no distances, or the fit was
    asked to be paired (distance: :func:`fit`'s argument; its rms is the pairing's)."""
    if distance == "paired":
        return None
    judged = r.free if held else r
    return None if judged is None or judged.distances is None else judged


def _judged(r: FitResult, judged: Optional[FitResult], fig: _Figures) -> FitResult:
    """r with its ``misfit`` (:func:`libelastica.misfit.misfit` of judged, :func:`judged_fit`,
    its points as fitted: those of fig, the noise figures :func:`fit` computed once for its
    tests) and a MisfitWarning where it lies far above the points' noise."""
    if judged is None:
        return r
    m = _verdict(fig, judged.distances, judged.rms)
    if m is None:
        return r
    if m.corner >= 0 and judged.retrace is not None:   # a scan's turn back is no corner (QA20)
        w = max(3, (len(judged.points) - 1) // 16)
        if min(abs(m.corner - judged.retrace.first), abs(m.corner - judged.retrace.last)) <= w:
            m = dataclasses.replace(m, corner=-1, parts=None)
    said = misfit_summary(m, judged.points, numbered=judged.order is None)   # curve order: by place
    say(f"fit: {said}", MisfitWarning, stacklevel=4)
    return dataclasses.replace(r, misfit=m)


def quiet_fit(points, *args, **kwargs) -> FitResult:
    """:func:`fit` without its warnings (ConvergenceWarning, WanderWarning, EndConditionWarning,
    MisfitWarning, SparseWarning), check_ends, check_misfit and check_sparse off unless asked:
    for a fit said in its caller's words (status, wander_gap, free, misfit, sparse): the
    user's own fit (the CLI's, FreeCAD's), or one that stands for it (check_ends' free fit,
    resampled_fits_worse's)."""
    return _quietly(fit, points, args, kwargs)


def judging_fit(points, *args, **kwargs) -> FitResult:
    """:func:`quiet_fit` without el.fit's back-and-forth gate (fit_retrace.py): a fit made
    only to judge or compare (fit_keyline's one-elastica check, misfit's corner parts), not
    returned to the user or quoted to them as el.fit's (the sparse check's smooth fit and
    resampled_reference's start are: they stay quiet_fit's). Such
    a fit can be a misfit by design (an S fitted by one elastica), which the gate refitted
    in curve order (curve_order ~3 ms of a 1000-point scan's keyline, 5.7 -> 23.8 ms)."""
    return _quietly(_fit, points, args, dict(kwargs, gate=False))


def _quietly(fit_by, points, args, kwargs) -> FitResult:
    with quiet(ConvergenceWarning, WanderWarning, EndConditionWarning, MisfitWarning,
               OutlierWarning, SparseWarning):     # (this thread's only: _quiet.py)
        return fit_by(points, *args, **dict(dict(check_ends=False, check_misfit=False,
                                                 check_sparse=False), **kwargs))


__all__ = ["ConstraintError", "FitResult", "fit", "NotConvergedError"]
