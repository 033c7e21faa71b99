"""Blending-function curves of seed 003 (Miura et al., "Curve modeling with Jacobi
elliptic functions"), built the way Eck's MQ-curves are.

A segment is ``phi(t) = sum_i q_i h_i(t)``, ``t in [0, 1]``, with control points
``q_0..q_3`` and blending functions ``h_i`` in the span of
``{1-t, f_1(t), f_2(t) = f_1(1-t), t}``:

* :class:`EllipticBlend`: ``f_1 = sn((1-t)K, k)``, ``f_2 = sn(Kt, k)``, ``K = K(k)``;
* :class:`MQBlend`: Eck's ``f_1 = sqrt(c^2 + (1-t)^2)``, ``f_2 = sqrt(c^2 + t^2)``.

The blending functions satisfy ``h_0(0) = 1``, ``h_0(1) = h_0'(1) = 0``,
``h_0'(0) = -d``, ``h_1(0) = h_1(1) = h_1'(1) = 0``, ``h_2(t) = h_1(1-t)``,
``h_3(t) = h_0(1-t)`` and sum to one, so the curve starts at ``q_0`` with
``phi'(0) = d (q_1 - q_0)`` and ends at ``q_3`` with ``phi'(1) = d (q_3 - q_2)``.

**Convention for k.** ``k`` is the elliptic *modulus*, as everywhere in
libelastica. The paper's numbers use the *parameter* ``m = k^2``: its rope
example "(k, d) = (0.3, 2)" is ``EllipticBlend(m=0.3, d=2)`` (modulus
``sqrt(0.3)``), with control points ``(0, 0), (0.5, K/2), (0.5, 1), (1, 1)``,
``K/2 = 0.856945``.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ._ffi import (DomainError, NotConvergedError, SingularError, as_points, as_positive, as_real,
                   as_vector,
                   bspline_from_c, check, dptr, ffi, lib, require, shown)
from ._quiet import say
from ._text import LengthFormat, lengths
from ._values import ValueEquality
from .core import arc_lengths
from .shape import crossing_pairs, self_crossings
from .spline import LoopWarning

__all__ = ["EllipticBlend", "MQBlend", "BlendCurve", "blend_curve", "eck_d", "eck_omega",
           "above_one", "ConditionWarning", "BlendLoopWarning", "SPREAD_MAX"]

#: Through the points, the control points solve a collocation system; when they spread
#: more than this many times as far as the points (:meth:`BlendCurve.spread`), the solve
#: amplifies every move of a point that much and the curve swings far outside them (the
#: Z (0, 0), (40, 40), (0, 40), (40, 0) at k = 0.7: 30 times, the curve 2.9 times the
#: points' size; at k = 0 the same Z gives 7.1 and 1.04): the interpolation is
#: ill-conditioned.
SPREAD_MAX = 20.0
#: Samples per segment of the polyline tested for self-crossings (:meth:`BlendCurve.loops`).
LOOP_SAMPLES = 101
#: Loops a warning names by place (the widest); it says how many more there are.
LOOPS_NAMED = 3


class ConditionWarning(RuntimeWarning):
    """:func:`blend_curve`'s warning that the interpolation through the points is
    ill-conditioned: the control points lie more than :data:`SPREAD_MAX` times as far
    apart as the points (:meth:`BlendCurve.spread`), so a point's move moves the curve
    that much more, and the curve swings far outside the points."""


class BlendLoopWarning(LoopWarning):
    """:func:`blend_curve`'s warning that the curve crosses itself where the polygon of
    its points does not (:meth:`BlendCurve.loops`): a loop between two points much
    closer together than their neighbours (the Catmull-Rom tangents there are those of
    the long chords), or a wide swing of an ill-conditioned interpolation."""

_PICK = {"control": lib.EL_BLEND_PICK_CONTROL, "interpolate": lib.EL_BLEND_PICK_INTERPOLATE}


def _t(t) -> np.ndarray:
    return np.linspace(0.0, 1.0, 101) if t is None else as_vector(t, "t", finite=True)


def _four(q, name: str) -> np.ndarray:
    q = as_points(q, name)
    if q.shape != (4, 2):
        raise ValueError(f"{name} must have shape (4, 2), got {q.shape}")
    return q


def _composite(q, name: str = "q") -> tuple[np.ndarray, int]:
    q = as_points(q, name)
    if len(q) < 4 or (len(q) - 1) % 3:
        raise ValueError(f"{name} must hold 3*nseg + 1 points (nseg >= 1), got {len(q)}")
    return q, (len(q) - 1) // 3


class _Blend(ValueEquality):
    """Common part of the MQ and elliptic bases (one el_blend_basis); == and hash by the
    parameters (those __reduce__ rebuilds it from)."""

    _b = None
    __copy__ = __deepcopy__ = None   # copy by __reduce__ (the parameters), as pickle does

    def _values(self):
        return self.__reduce__()[1]

    def __hash__(self) -> int:
        return hash((type(self), self._values()))

    def __repr__(self) -> str:
        return f"{type(self).__name__}({self._args()})"

    # -- basis ---------------------------------------------------------------
    @property
    def d(self) -> float:
        """End-derivative parameter: ``h_0'(0) = -d``, ``phi'(0) = d (q_1 - q_0)``."""
        return float(self._b.d)

    @property
    def matrix(self) -> np.ndarray:
        """``M`` (4, 4): row i holds the coefficients of ``h_i`` on ``(f_0, f_1, f_2, f_3)``."""
        return np.array(list(self._b.M)).reshape(4, 4)

    @property
    def condition(self) -> float:
        """1-norm condition number of the 8x8 system (2.17) that defined the basis
        (elliptic bases above ``EL_BLEND_COND_MAX`` = 1000 are refused: K(k) near 2)."""
        return float(self._b.cond)

    @property
    def basis_min(self) -> float:
        """The smallest value of any blending function on [0, 1] (<= 0; negative: the
        curve can leave the convex hull of its control points), exact to rounding: it
        finds the dips next to an end that samples miss (-1.05e-6 at m = 0.99, d = 2)."""
        return float(self._b.basis_min)

    @property
    def convex_hull(self) -> bool:
        """Whether every blending function is >= 0 on [0, 1] (basis_min >= -1e-12, rounding),
        so that each segment stays inside the convex hull of its control points."""
        return bool(self._b.convex_hull)

    @property
    def lebesgue(self) -> float:
        """max over t of sum_i |h_i(t)| (1 with the convex hull): a curve point moves by
        at most this times the largest move of a control point."""
        return float(self._b.lebesgue)

    def warnings(self) -> list:
        """Plain-language warnings about this basis (empty when the convex hull holds)."""
        if self.convex_hull:
            return []
        return [f"the basis is negative (down to {self.basis_min:.3g}): the curve can leave "
                f"the convex hull of its control points, moving up to "
                f"{above_one(self.lebesgue)} times as far as a control point moves "
                f"(condition {self.condition:.3g})"]

    def span(self, t=None, derivative: int = 0) -> np.ndarray:
        """The span functions ``f_j(t)`` (or their 1st/2nd t-derivative), shape (n, 4)."""
        t = _t(t)
        out = np.empty((len(t), 4))
        args = [ffi.NULL] * 3
        args[self._order(derivative)] = dptr(out)
        check(lib.el_blend_span_eval(self._b, len(t), dptr(t), *args), type(self).__name__)
        return out

    def basis(self, t=None, derivative: int = 0) -> np.ndarray:
        """Blending functions ``h_j(t)`` (or their 1st/2nd t-derivative), shape (n, 4)."""
        t = _t(t)
        out = np.empty((len(t), 4))
        args = [ffi.NULL] * 3
        args[self._order(derivative)] = dptr(out)
        check(lib.el_blend_basis_eval(self._b, len(t), dptr(t), *args), type(self).__name__)
        return out

    @staticmethod
    def _order(derivative: int) -> int:
        if isinstance(derivative, (bool, np.bool_)) or not isinstance(derivative, (int, np.integer)) \
                or derivative not in (0, 1, 2):
            raise ValueError(f"derivative must be 0, 1 or 2, got {derivative}")
        return derivative

    # -- control points ------------------------------------------------------
    def control_points(self, coeffs) -> np.ndarray:
        """Control points ``q = p M^-1`` (2.19), shape (4, 2), of the curve
        ``sum_j p_j f_j(t)`` with coefficient points ``coeffs`` = ``p`` (4, 2)."""
        p = _four(coeffs, "coeffs")
        q = np.empty((4, 2))
        check(lib.el_blend_control_points(self._b, dptr(p), dptr(q)), "control_points")
        return q

    def coefficients(self, q) -> np.ndarray:
        """Coefficient points ``p = q M`` (2.18) of the curve with control points q."""
        q = _four(q, "q")
        p = np.empty((4, 2))
        check(lib.el_blend_coefficients(self._b, dptr(q), dptr(p)), "coefficients")
        return p

    def from_points(self, points, mode: str = "interpolate") -> np.ndarray:
        """Control points (4, 2) from four picked points.

        ``mode="control"``: the points are the control points (a copy).
        ``mode="interpolate"``: the curve passes through the four points, at the
        chord-length parameters ``t = 0, t_1, t_2, 1``. Coincident consecutive
        points raise :class:`SingularError`.
        """
        if not isinstance(mode, str) or mode not in _PICK:
            raise ValueError(f"mode must be one of {sorted(_PICK)}, got {mode!r}")
        pts = _four(points, "points")
        q = np.empty((4, 2))
        st = lib.el_blend_from_points(self._b, dptr(pts), _PICK[mode], dptr(q))
        if st == lib.EL_ESINGULAR:
            same = [i for i in range(3) if (pts[i] == pts[i + 1]).all()]
            if same:
                raise SingularError(st, f"from_points: points {same[0] + 1} and {same[0] + 2} "
                                        "coincide")
        _overflow(st, "from_points", pts)
        check(st, "from_points")
        return q

    # -- curves --------------------------------------------------------------
    def evaluate(self, q, t=None, derivative: bool = False):
        """Points ``phi(t) = sum q_i h_i(t)`` (n, 2) of the segment with control points
        q (4, 2); with ``derivative=True`` also ``phi'(t)``: returns (points, tangents)."""
        q = _four(q, "q")
        return self._eval(q, 1, _t(t), derivative)

    def evaluate_composite(self, q, t=None, derivative: bool = False):
        """Points of a composite curve: q holds 3*nseg + 1 control points, segment s
        uses q[3s:3s+4], global parameter t in [0, nseg] (default 101 samples per segment)."""
        q, nseg = _composite(q)
        t = np.linspace(0.0, nseg, 100 * nseg + 1) if t is None else as_vector(t, "t")
        return self._eval(q, nseg, t, derivative)

    def _eval(self, q, nseg, t, derivative):
        xy = np.empty((len(t), 2))
        dxy = np.empty((len(t), 2)) if derivative else None
        check(lib.el_blend_composite_eval(self._b, nseg, dptr(q), len(t), dptr(t), dptr(xy),
                                          dptr(dxy) if derivative else ffi.NULL), "evaluate")
        return (xy, dxy) if derivative else xy

    def composite_through(self, points, closed: bool = False) -> np.ndarray:
        """Control points (3(n-1)+1, 2) of the C1 composite curve through n >= 2 points
        (node i at t = i, Catmull-Rom tangents, one-sided quadratic ones at the ends).

        ``closed=True``: the closed curve through n >= 3 distinct points (a last point
        equal to the first is dropped), one more segment back to the first point and
        the tangents taken cyclically, so the seam is C1 like the other joints:
        3n + 1 control points, the last equal to the first."""
        pts = as_points(points, "points")
        if closed:
            if len(pts) >= 2 and np.array_equal(pts[0], pts[-1]):
                pts = np.ascontiguousarray(pts[:-1])
            if len(pts) < 3:
                raise ValueError(f"composite_through: a closed curve needs at least 3 distinct "
                                 f"points (got {len(pts)})")
            q = np.empty((3 * len(pts) + 1, 2))
            st = lib.el_blend_composite_closed(self._b, len(pts), dptr(pts), dptr(q))
        else:
            if len(pts) < 2:
                raise ValueError("composite_through needs at least 2 points")
            q = np.empty((3 * (len(pts) - 1) + 1, 2))
            st = lib.el_blend_composite_through(self._b, len(pts), dptr(pts), dptr(q))
        _overflow(st, "composite_through", pts)
        check(st, "composite_through")
        return q

    def to_bspline(self, q, tol: Optional[float] = None):
        """A clamped cubic :class:`BSpline` within ``tol`` (default 1e-6 of the curve's
        length, or 4 times the smallest tol below, if larger) of the curve with control points q (4 points, or 3*nseg + 1 for a
        composite), in the same parameter; its ``max_deviation`` is the certified
        max_t |phi(t) - B(t)|. Raises NotConvergedError (with the tol that is reached)
        when 256 spans per segment do not reach tol, DomainError (with the smallest
        possible) for a tol below what the coordinates resolve."""
        from .bspline import at_least, default_tol
        q, nseg = _composite(q)
        # (the floor: el_blend_to_bspline's EL_EDOM for a tol below it)
        floor = 64.0 * np.finfo(float).eps * max(self.lebesgue, 1.0) * float(np.max(np.abs(q)))
        if tol is None:   # 1e-6 of the length, or FLOOR_MARGIN x the floor (QA23: survey coordinates)
            xy = self.evaluate_composite(q)
            tol = default_tol(None, np.sum(np.hypot(*np.diff(xy, axis=0).T)), floor=floor)
        tol = as_positive(tol, "to_bspline: tol")
        b = ffi.new("el_bspline *")
        st = lib.el_blend_to_bspline(self._b, nseg, dptr(q), tol, b)
        if st == lib.EL_ENOCONV:    # "did not converge" told nothing to do (QA)
            dev = float(b.max_deviation)
            lib.el_bspline_free(b)
            raise NotConvergedError(st, f"to_bspline: tolerance {tol:.6g} not reached with 256 "
                                    f"spans a segment: the best B-spline found is certified "
                                    f"within {dev:.6g}; raise tol to {at_least(dev)} or more "
                                    "(it is reached), or give more points (shorter segments)")
        if st == lib.EL_EDOM and tol < floor:
            raise DomainError(st, f"to_bspline: tol = {tol:.3g} is below what double precision "
                              f"resolves for these coordinates; the smallest possible is 64 eps "
                              f"max(lebesgue, 1) max|q| = {at_least(floor)}")
        if st != lib.EL_OK:
            lib.el_bspline_free(b)
            check(st, "to_bspline")
        return bspline_from_c(b)


class EllipticBlend(_Blend):
    """The elliptic basis of seed 003: span ``{1-t, sn((1-t)K, k), sn(Kt, k), t}``.

    ``k`` is the elliptic modulus in [0, 1); pass ``m=`` (= k^2) instead to use the
    paper's convention (its "k = 0.3" is ``m=0.3``). ``d > 0`` is the end-derivative
    parameter. Raises DomainError for k >= 1 and SingularError where the system
    (2.17) is singular (K(k) = 2, k ~ 0.80241).

    >>> b = EllipticBlend(m=0.3, d=2.0)
    >>> q = b.control_points([[0, 0], [0, 0], [0, 1], [1, 0]])   # C(t) = (t, sn(Kt))
    """

    def __init__(self, k: Optional[float] = None, d: float = 2.0, *, m: Optional[float] = None):
        if (k is None) == (m is None):
            raise ValueError("EllipticBlend: give exactly one of k (modulus) and m (= k^2)")
        if m is not None:
            m = as_real(m, "EllipticBlend: m")
            if m < 0.0:
                raise ValueError(f"EllipticBlend: m must be >= 0, got {m}")
            k = np.sqrt(m)
        k = as_real(k, "EllipticBlend: k")
        require(k >= 0, "EllipticBlend: k", ">= 0 (the modulus; m = k^2)", k)
        if k >= 1.0:   # (el_blend_init_elliptic's EL_EDOM: K(k) is infinite at k = 1)
            given = f"m = {shown(m)}" if m is not None else f"k = {shown(k)}"
            raise DomainError(lib.EL_EDOM, f"EllipticBlend: {given}: the elliptic basis needs "
                              "0 <= k < 1 (m = k^2 < 1)")
        self._b = ffi.new("el_blend_basis *")
        st = lib.el_blend_init_elliptic(self._b, k, as_positive(d, "EllipticBlend: d"))
        if st == lib.EL_ESINGULAR:
            raise SingularError(st, f"EllipticBlend: k = {k:.6g} (m = {k * k:.6g}) lies in the "
                                f"singular neighbourhood of K(k) = 2, where the basis is not "
                                f"determined (condition > {lib.EL_BLEND_COND_MAX}): choose k "
                                "outside (0.79932, 0.80544), m outside (0.63891, 0.64874)")
        check(st, "EllipticBlend")

    @property
    def k(self) -> float:
        """Elliptic modulus."""
        return float(self._b.k)

    @property
    def m(self) -> float:
        """Elliptic parameter m = k^2 (the paper's 'k')."""
        return float(self._b.k) ** 2

    @property
    def K(self) -> float:
        """Complete elliptic integral K(k)."""
        return float(self._b.K)

    def _args(self) -> str:
        return f"k={self.k!r}, d={self.d!r}"

    def __reduce__(self):     # pickle / copy by the parameters (the C basis is cffi data)
        return EllipticBlend, (self.k, self.d)


class MQBlend(_Blend):
    """Eck's MQ span ``{1-t, sqrt(c^2+(1-t)^2), sqrt(c^2+t^2), t}`` (2.1), c != 0, with
    the generalised blending functions of end-derivative d (default: Eck's
    ``d = 1/alpha(c)``, which gives Eck's Omega_i (2.4))."""

    def __init__(self, c: float, d: Optional[float] = None):
        c = _nonzero(c, "MQBlend: c")
        d = eck_d(c) if d is None else as_positive(d, "MQBlend: d")
        self._b = ffi.new("el_blend_basis *")
        check(lib.el_blend_init_mq(self._b, c, d), "MQBlend")

    @property
    def c(self) -> float:
        return float(self._b.c)

    def _args(self) -> str:
        return f"c={self.c!r}, d={self.d!r}"

    def __reduce__(self):     # pickle / copy by the parameters (the C basis is cffi data)
        return MQBlend, (self.c, self.d)


def _nonzero(c, name: str) -> float:
    """The MQ parameter c: c = 0 degenerates the span (the C library's EL_EDOM, named)."""
    c = as_real(c, name)
    if c == 0:
        raise DomainError(lib.EL_EDOM, f"{name} must be nonzero (c = 0: the MQ span "
                                       "degenerates), got 0")
    return c


def above_one(x: float) -> str:
    """x (>= 1) with the digits that show how far above 1 it is (1.002, not 1)."""
    for p in range(3, 18):
        txt = f"{x:.{p}g}"
        if x <= 1.0 or float(txt) > 1.0:
            return txt
    return repr(x)


def _overflow(st: int, name: str, pts: np.ndarray) -> None:
    """EL_EDOM from points with coordinates near double's limit: say it is an overflow."""
    if st == lib.EL_EDOM:
        raise DomainError(st, f"{name}: overflow: the points' coordinates (up to "
                              f"{np.abs(pts).max():.3g}) put their distances or the control "
                              "points beyond double's range (1.8e308): scale them down")


def eck_d(c: float) -> float:
    """Eck's end-derivative ``d = 1/alpha(c)`` (2.5)."""
    out = ffi.new("double *")
    c = _nonzero(c, "eck_d: c")
    check(lib.el_blend_eck_d(c, out), f"eck_d: c = {c:g}")
    return float(out[0])


def eck_omega(c: float, t=None) -> np.ndarray:
    """Eck's MQ blending functions Omega_0..Omega_3 (2.4) in closed form, shape (n, 4), of
    the MQ parameter ``c`` (nonzero) at ``t`` (n,) (default 101 points over [0, 1])."""
    t = _t(t)
    out = np.empty((len(t), 4))
    c = _nonzero(c, "eck_omega: c")
    check(lib.el_blend_eck_omega(c, len(t), dptr(t), dptr(out)), "eck_omega")
    return out


def _diameter(xy: np.ndarray) -> float:
    """The largest distance between two rows of xy (n, 2), in blocks of 256 rows."""
    return max(float(np.hypot(*(xy[i:i + 256, None] - xy[None]).transpose(2, 0, 1)).max())
               for i in range(0, len(xy), 256))


@dataclass(eq=False)
class BlendCurve(ValueEquality):
    """A (composite) blending-function curve: a ``basis`` (EllipticBlend or MQBlend) and
    ``q``, its 3*nseg + 1 control points ((3 nseg + 1, 2)); ``closed``: made closed (default
    False; the seam at q[0] a C1 joint); ``through``: the points it interpolates
    (:func:`blend_curve`'s, (m, 2)), else None."""
    basis: _Blend
    q: np.ndarray
    closed: bool = False     # made closed: the seam at q[0] is a C1 joint
    through: Optional[np.ndarray] = None   # the points it interpolates (blend_curve's)

    def __post_init__(self):
        if not isinstance(self.basis, _Blend):
            raise ValueError(f"BlendCurve: basis must be an EllipticBlend or MQBlend, got "
                             f"{type(self.basis).__name__}")
        self.q, _ = _composite(self.q)
        if self.through is not None:
            self.through = as_points(self.through, "through")

    @property
    def nseg(self) -> int:
        return (len(self.q) - 1) // 3

    def __repr__(self) -> str:
        through = "" if self.through is None else f", through {len(self.through)} points"
        return (f"BlendCurve({self.basis!r}, {self.nseg} segment(s){through}"
                f"{', closed' if self.closed else ''})")

    def seam_angle(self) -> float:
        """Where the curve ends at its start (q[-1] = q[0]): the angle between its tangents
        there in DEGREES (0..180; the binding's other angles are radians), 0 for a smooth
        seam; NaN when it does not close."""
        if not np.array_equal(self.q[0], self.q[-1]):
            return float("nan")
        _, d = self.basis.evaluate_composite(self.q, [0.0, float(self.nseg)], derivative=True)
        return float(np.degrees(abs(np.arctan2(d[1, 0] * d[0, 1] - d[1, 1] * d[0, 0],
                                               d[1, 0] * d[0, 0] + d[1, 1] * d[0, 1]))))

    def spread(self) -> float:
        """How many times as far apart as the points it interpolates (``through``) the
        control points lie (diameters): what a point's move is amplified by; 1 without
        such points (control points given)."""
        if self.through is None:
            return 1.0
        return _diameter(self.q) / _diameter(self.through)

    def loops(self) -> int:
        """Self-crossings of the curve (its polyline of LOOP_SAMPLES points per segment)
        beyond those of the polygon of the points it interpolates (closed: back to the
        first): 0 for a curve that follows its points; 0 without such points."""
        if self.through is None:
            return 0
        poly = np.vstack([self.through, self.through[:1]]) if self.closed else self.through
        xy = self.points(np.linspace(0.0, self.nseg, (LOOP_SAMPLES - 1) * self.nseg + 1))
        return max(0, self_crossings(xy) - self_crossings(poly))

    def loop_places(self) -> list:
        """Where the curve loops, widest first: one dict per pair of points between which
        the curve (its polyline of LOOP_SAMPLES points per segment) crosses itself where no
        crossing of the points' polygon (matched by its segments) accounts for it, with
        ``between`` [i, j] the points (as given, counted from 0) the loop lies between,
        ``width`` the loop's largest width, ``chord`` the distance from point i to point j
        and ``beside`` the chords before i and after j (None at an open end). Empty without
        points it interpolates. Noisy points whose polygon crosses itself may give more
        places than :meth:`loops` counts."""
        if self.through is None:
            return []
        pts, ns = self.through, LOOP_SAMPLES - 1
        n, npoly = len(pts), len(self.through) - (0 if self.closed else 1)
        xy = self.points(np.linspace(0.0, self.nseg, ns * self.nseg + 1))
        if self.nseg == npoly:     # a composite: node i at t = i
            at = np.arange(npoly + 1) * ns
        else:                      # one segment through 4 points: their nearest samples
            d = np.hypot(*(xy[None] - pts[:, None]).transpose(2, 0, 1))
            at = np.maximum.accumulate(np.argmin(d, axis=1))

        def seg(sample):           # the polygon's segment (points s, s + 1) of a sample
            return int(np.clip(np.searchsorted(at, sample, side="right") - 1, 0, npoly - 1))

        poly = np.vstack([pts, pts[:1]]) if self.closed else pts
        unmatched = {tuple(p) for p in crossing_pairs(poly).tolist()}
        chord = np.hypot(*np.diff(poly, axis=0).T)
        out = []
        for i, j in crossing_pairs(xy).tolist():
            if (seg(i), seg(j)) in unmatched:      # the polygon crosses itself there too
                unmatched.discard((seg(i), seg(j)))
                continue
            if self.closed and 2 * (j - i) > len(xy):   # the loop through the seam
                loop, a, b = np.vstack([xy[j + 1:], xy[:i + 1]]), seg(j), (seg(i) + 1) % n
            else:
                loop, a, b = xy[i + 1:j + 1], seg(i), seg(j) + 1
            before = chord[a - 1] if a > 0 else (chord[-1] if self.closed else None)
            after = chord[b % npoly] if self.closed or b < npoly else None
            out.append({"between": [a, b % n], "width": _diameter(loop),
                        "chord": float(np.hypot(*(pts[b % n] - pts[a]))),
                        "beside": [None if c is None else float(c) for c in (before, after)]})
        widest = {}                # one place per pair of points: its widest loop
        for p in sorted(out, key=lambda p: -p["width"]):
            widest.setdefault(tuple(p["between"]), p)
        return list(widest.values())

    def _loop_text(self, loops: int, length: Optional[LengthFormat] = None) -> str:
        """The loop warning: how many, the widest LOOPS_NAMED by their points and sizes
        (by ``length(value, digits)`` where given, with its unit; else numbers alone)."""
        fmt = lengths("", length)
        times = "once" if loops == 1 else f"{loops} times"
        places = self.loop_places()
        said = []
        for k, p in enumerate(places[:LOOPS_NAMED]):
            beside = " and ".join(fmt(c, 3) for c in p["beside"] if c is not None)
            said.append(f"between points {p['between'][0]} and {p['between'][1]} ("
                        + ("counted from 0; " if k == 0 else "")
                        + f"chord {fmt(p['chord'], 3)}"
                        + (f" beside {beside}" if beside else "")
                        + f", a loop {fmt(p['width'], 2)} wide)")
        more = len(places) - len(said)
        where = (", ".join(said[:-1]) + " and " + said[-1] if len(said) > 1 else
                 "".join(said)) + (f", and {more} more" if more > 0 else "")
        if not where:
            where = ("between two points much closer together than their neighbours, or where "
                     "it swings wide")
        return (f"the curve loops: it crosses itself {times} where the polygon of its points "
                f"does not; it loops {where}; points spaced more evenly there give a fair curve")

    def _interpolation_warnings(self, length: Optional[LengthFormat] = None) -> list:
        """(category, text) of an ill-conditioned interpolation and of loops (``length``:
        _loop_text's)."""
        out = []
        spread = self.spread()
        if spread > SPREAD_MAX:
            swing = _diameter(self.points()) / _diameter(self.through)
            out.append((ConditionWarning,
                        f"the interpolation is ill-conditioned: the control points lie up to "
                        f"{spread:.3g} times as far apart as the points and the curve spans "
                        f"{swing:.3g} times their size; a smaller k, other points or control "
                        "points give a tamer curve"))
        loops = self.loops()
        if loops:
            out.append((BlendLoopWarning, self._loop_text(loops, length)))
        return out

    def warnings(self, length: Optional[LengthFormat] = None) -> list:
        """The basis' warnings, a corner where the curve closes on itself, an
        ill-conditioned interpolation (:class:`ConditionWarning`) and loops
        (:class:`BlendLoopWarning`), in words; ``length(value, digits, with_unit)`` writes
        the loops' places and sizes (default: the numbers alone; FreeCAD's: in the user's
        unit schema)."""
        out = list(self.basis.warnings())
        angle = self.seam_angle()
        if angle > 1e-6:
            out.append(f"the curve closes on itself with a {angle:.3g} deg corner at its first "
                       "point (its ends are not a joint); closed=True (CLI: --closed) makes "
                       "that joint smooth like the others")
        return out + [text for _, text in self._interpolation_warnings(length)]

    def points(self, t=None) -> np.ndarray:
        """Points (n, 2) by the rule every curve's points take (:func:`core.arc_lengths`),
        over the curve's own parameter t in [0, nseg] (segment s runs over [s, s + 1]), not
        arc length: an int n gives n points at equal steps of t; floats or an array are
        values of t (a float or 0-d array: shape (2,)); t outside [0, nseg] raises
        ValueError. Default: 100 steps per segment (100 nseg + 1 points)."""
        if t is None:
            return self.basis.evaluate_composite(self.q)
        t, scalar = arc_lengths(t, float(self.nseg), "BlendCurve.points", param="parameter t")
        xy = self.basis.evaluate_composite(self.q, t)
        return xy[0] if scalar else xy

    def to_bspline(self, tol: Optional[float] = None):
        """Clamped cubic BSpline within tol, default 1e-6 of the curve's length (see
        :meth:`EllipticBlend.to_bspline`)."""
        return self.basis.to_bspline(self.q, tol)


def blend_curve(points, k: Optional[float] = None, d: float = 2.0, mode: str = "interpolate",
                *, m: Optional[float] = None, closed: bool = False) -> BlendCurve:
    """An elliptic blending curve from picked points (the CLI / FreeCAD entry point).

    Four points: ``mode="interpolate"`` (default) gives the segment through them at
    chord-length parameters, ``mode="control"`` uses them as control points. Three, or
    more than four, points with ``mode="interpolate"``: the C1 composite through them
    (3 points: 2 segments; fewer than 3 raise ValueError)
    (:meth:`EllipticBlend.composite_through`); with ``mode="control"`` they must be
    3*nseg + 1 control points. ``k`` is the modulus, 0 <= k < 1 (default 0.5), or
    ``m = k^2``. ``d`` > 0: the basis's end-derivative parameter (default 2.0,
    :class:`EllipticBlend`).
    ``closed=True`` (interpolate): the closed C1 composite through the points (>= 3
    distinct; a repeated first point at the end is dropped), smooth at the seam too.
    Without it, points that end where they start close with a corner, which
    :meth:`BlendCurve.warnings` names.

    Through the points, warns :class:`ConditionWarning` when the control points spread
    more than :data:`SPREAD_MAX` times as far as the points, and :class:`BlendLoopWarning`
    when the curve crosses itself where the points' polygon does not (naming the points
    each loop lies between and its width: :meth:`BlendCurve.loop_places`); both are in
    :meth:`BlendCurve.warnings` too.
    """
    if k is None and m is None:
        k = 0.5
    basis = EllipticBlend(k, d, m=m)
    pts = as_points(points, "points")
    if not isinstance(mode, str) or mode not in _PICK:
        raise ValueError(f"blend_curve: mode must be one of {sorted(_PICK)}, got {mode!r}")
    if mode == "interpolate" and len(pts) < 3:
        raise ValueError(f"blend_curve: at least 3 points to pass through, got {len(pts)}")
    if closed:
        if mode != "interpolate":
            raise ValueError("blend_curve: closed=True passes through the points (mode "
                             "'interpolate'); control points shape their seam themselves")
        if len(pts) >= 2 and np.array_equal(pts[0], pts[-1]):
            pts = pts[:-1]
        curve = BlendCurve(basis, basis.composite_through(pts, closed=True), closed=True,
                           through=pts)
    elif mode == "control":
        curve = BlendCurve(basis, basis.from_points(pts, mode) if len(pts) == 4 else pts)
    elif len(pts) == 4:
        curve = BlendCurve(basis, basis.from_points(pts, mode), through=pts)
    else:
        curve = BlendCurve(basis, basis.composite_through(pts), through=pts)
    for category, text in curve._interpolation_warnings():
        say(text, category, stacklevel=2)
    return curve
