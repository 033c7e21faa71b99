"""B-splines over the C library: the BSpline type, the natural C2 cubic through
a polyline, and the tolerance-certified B-spline of a smooth elastica (or a chain
of them)."""
from __future__ import annotations

from typing import Any

import math

import numpy as np

from ._ffi import (INT_MAX, DomainError, NotConvergedError, as_degree, as_int, as_points,
                   as_positive, as_real, as_vector, bspline_from_c, check, dptr, ffi, lib,
                   require, warn_if_degrees)
from ._portable import PortablePickle
from .core import within


RELATIVE_TOL = 1e-6
"""Every to_bspline's default tolerance: 1e-6 of the curve's length (README's rule), so the
default works at any scale (1e-6 absolute failed at 1e6 coordinates, QA), raised to
:data:`FLOOR_MARGIN` times what double precision resolves where that is larger (a curve
shorter than ~1e-8 of its coordinates: 40 mm at (4e8, 5.6e9) mm, QA23)."""

FLOOR_MARGIN = 4.0
"""How far above the smallest resolvable tol (:func:`resolvable_tol`) a default tol stays:
at the floor itself the certified distance, of the size of the rounding, can miss it
(NotConvergedError at 1.01 x the floor, 0.05 m at (4e5, 5.6e6) m, mu 400)."""


def resolvable_tol(curve) -> float:
    """The smallest tol el_smooth_to_bspline accepts for a SmoothElastica (or its C
    parameters): 1e-14 (length + |x0| + |y0| + |q| / sqrt(mu)), its header's rule: the
    points carry the rounding of their coordinates, the phase q an absolute eps |q| into
    u = sqrt(mu) s + q (seed 000 (3.9))."""
    return 1e-14 * (float(curve.length) + abs(float(curve.x0)) + abs(float(curve.y0))
                    + abs(float(curve.q)) / np.sqrt(float(curve.mu)))


def default_tol(tol, length: float, what: str = "to_bspline", floor: float = 0.0) -> float:
    """``tol`` (> 0) as given, or when None the larger of :data:`RELATIVE_TOL` times
    ``length`` (1e-6 for a curve of length 0, which any tol fits) and :data:`FLOOR_MARGIN`
    times ``floor``, the smallest tol double precision resolves for the curve (a tol
    given below it keeps its DomainError)."""
    if tol is None:
        length = float(length)
        rel = RELATIVE_TOL * length if length > 0.0 and np.isfinite(length) else RELATIVE_TOL
        return max(rel, FLOOR_MARGIN * float(floor)) if np.isfinite(floor) else rel
    return as_positive(tol, f"{what}: tol")


def at_least(x: float) -> str:
    """x written with 3 significant digits, rounded up (a tol that reaches x, which "%.3g"
    can write as the tol that missed it: "tolerance 1e-06 not reached (certified 1e-06)", QA)."""
    e = 10.0 ** (np.floor(np.log10(x)) - 2) if x > 0.0 else 1.0
    return f"{np.ceil(x / e * (1.0 - 1e-12)) * e:.3g}"


class BSpline(PortablePickle):
    """A non-rational B-spline curve: degree, poles (n, dim), distinct knots with
    multiplicities (FreeCAD/OpenCASCADE convention), and ``max_deviation``, the
    certified distance to the curve it approximates (0 exact, NaN unknown: a discrete fit's
    cubic through its vertices; -1 given, the C library's "unknown", reads NaN too).

    The flat knot vector has n + degree + 1 entries (:meth:`flat_knots`).
    Evaluation runs in C (de Boor); parameters outside [knots[0], knots[-1]]
    raise :class:`libelastica.DomainError`.

    >>> b = BSpline(degree=1, poles=[[0, 0], [1, 1]], knots=[0, 1], mults=[2, 2])
    >>> b.evaluate([0.5]).tolist()
    [[0.5, 0.5]]
    """

    def __init__(self, degree: int, poles, knots, mults, max_deviation: float = math.nan):
        self.degree = as_int(degree, "BSpline: degree", 1)
        self.poles = as_points(poles, "BSpline: poles", None)
        if self.poles.shape[1] > INT_MAX:
            raise ValueError("BSpline: too many coordinates per pole")
        self.knots = as_vector(knots, "BSpline: knots").copy()
        m = as_vector(mults, "BSpline: mults")
        if m.shape != self.knots.shape or np.any(m != np.round(m)) or np.any(np.abs(m) > INT_MAX):
            raise ValueError("BSpline: mults must be integers, one per knot")
        self.mults = m.astype(np.int64)
        dev = math.nan if max_deviation is None else \
            as_real(max_deviation, "BSpline: max_deviation", finite=False)
        if dev < 0 and dev != -1.0:     # -1: the C library's "unknown" (review revD: -0.5
            raise ValueError(f"BSpline: max_deviation must be >= 0, NaN or -1 (unknown), "
                             f"got {dev!r}")           # read NaN, a typo taken for unknown)
        self.max_deviation = dev if dev >= 0 else math.nan    # (QA qapy F11: -1 read as a number)
        self._check()
        self._c()  # validates (EL_EINVAL -> ElasticaError)

    def _check(self):
        """el_bspline_check's rules, each named with the value that breaks it."""
        p, kn, m = self.degree, self.knots, self.mults
        require(len(kn) >= 2, "BSpline: knots", "at least 2 distinct values", kn.tolist())
        require(np.all(np.isfinite(kn)), "BSpline: knots", "finite", kn.tolist())
        bad = np.flatnonzero(np.diff(kn) <= 0)
        require(not len(bad) and np.isfinite(kn[-1] - kn[0]), "BSpline: knots",
                "strictly increasing", kn[bad[0]:bad[0] + 2].tolist() if len(bad) else kn.tolist())
        require(1 <= m[0] <= p + 1 and 1 <= m[-1] <= p + 1, "BSpline: end mults",
                f"1..degree+1 = 1..{p + 1}", [int(m[0]), int(m[-1])])
        inner = m[1:-1]
        require(np.all((inner >= 1) & (inner <= p)), "BSpline: interior mults",
                f"1..degree = 1..{p}", inner.tolist())
        require(int(m.sum()) == self.npoles + p + 1, "BSpline: sum of mults",
                f"npoles + degree + 1 = {self.npoles + p + 1}", int(m.sum()))

    def __getstate__(self):
        """Without the cffi array of the last C view (it cannot be pickled or copied; _c
        makes one per call)."""
        return {k: v for k, v in self.__dict__.items() if k != "_cmults"}

    def __setstate__(self, state):
        """A pickle's or copy's state; one pickled before a5ff62c holds -1 for "unknown",
        read NaN as the constructor reads it (review revD: it compared unequal to its
        rebuilt self)."""
        self.__dict__.update(state)
        if not self.max_deviation >= 0:
            self.max_deviation = math.nan

    # -- C view -------------------------------------------------------------
    def _c(self):
        """An el_bspline pointing into this object's arrays (valid while self lives)."""
        b = ffi.new("el_bspline *")
        self._cmults = ffi.new("int[]", self.mults.tolist())
        b.degree = self.degree
        b.dim = self.poles.shape[1]
        b.npoles = self.poles.shape[0]
        b.poles = dptr(self.poles)
        b.nknots = len(self.knots)
        b.knots = dptr(self.knots)
        b.mults = self._cmults
        b.max_deviation = self.max_deviation if self.max_deviation >= 0 else -1.0   # C's unknown
        check(lib.el_bspline_check(b), "BSpline")
        return b

    @property
    def dim(self) -> int:
        """Coordinates per pole."""
        return int(self.poles.shape[1])

    @property
    def npoles(self) -> int:
        """Number of poles."""
        return int(self.poles.shape[0])

    @property
    def domain(self) -> tuple[float, float]:
        """The parameter interval (first knot, last knot)."""
        return float(self.knots[0]), float(self.knots[-1])

    def flat_knots(self) -> np.ndarray:
        """The flat knot vector, npoles + degree + 1 values (as scipy.interpolate.BSpline's t)."""
        return np.repeat(self.knots, self.mults)

    # -- evaluation -----------------------------------------------------------
    # evaluate / derivative / curvature take B-spline parameters t in the domain (knots[0],
    # knots[-1]), not arc lengths, and an int is a parameter there too, not a count (the
    # curves' points(n) rule, core.arc_lengths, is for arc length): n samples are
    # b.evaluate(np.linspace(*b.domain, n)). A scalar t (a float, an int, a 0-d array)
    # gives one value without the leading axis, as the curves' points(2.0) gives (2,).
    def _params(self, t, who: str):
        """(t as a vector, scalar): the parameters ``who`` evaluates at, each within the
        domain (the C library's 1e-12 slack), else DomainError naming ``who``, the value
        and the domain (core.within: the curves' arc-length rule, an int a parameter)."""
        a, z = self.domain              # (el_bspline_derivative's slack)
        return within(t, a, z, who, "parameter t", 1e-12 * (abs(a) + abs(z) + (z - a)),
                      "the B-spline's domain", "parameters, not arc lengths; an int is a "
                      "parameter too", lambda said: DomainError(lib.EL_EDOM, said))

    def derivative(self, t, order: int = 1) -> np.ndarray:
        """Derivative of the given order (0 = points) at parameters t in :attr:`domain`,
        shape (len(t), dim); a scalar t (float, int or 0-d): shape (dim,)."""
        return self._derivative(t, order, "BSpline.derivative")

    def _derivative(self, t, order, who: str) -> np.ndarray:
        order = as_int(order, f"{who}: order", 0)
        t, scalar = self._params(t, who)
        out = np.empty((len(t), self.dim))
        check(lib.el_bspline_derivative(self._c(), int(order), len(t), dptr(t), dptr(out)),
              who)
        return out[0] if scalar else out

    def evaluate(self, t) -> np.ndarray:
        """Points B(t) at parameters t in :attr:`domain` (not arc lengths: an int is a
        parameter, not a count), shape (len(t), dim); a scalar t: shape (dim,)."""
        return self._derivative(t, 0, "BSpline.evaluate")

    def __call__(self, t) -> np.ndarray:
        return self._derivative(t, 0, "BSpline")

    def curvature(self, t) -> np.ndarray:
        """Signed curvature det(B', B'')/|B'|^3 of a planar B-spline at parameters t in
        :attr:`domain`, shape (len(t),); a scalar t: shape ()."""
        t, scalar = self._params(t, "BSpline.curvature")
        require(self.dim == 2, "BSpline.curvature: dim", "2 (a planar curve)", self.dim)
        require(self.degree >= 2, "BSpline.curvature: degree", ">= 2", self.degree)
        out = np.empty(len(t))
        check(lib.el_bspline_curvature(self._c(), len(t), dptr(t), dptr(out)), "BSpline.curvature")
        return out[0] if scalar else out

    def mapped(self, fn) -> "BSpline":
        """This B-spline with its poles mapped by ``fn`` ((n, dim) -> (n, dim')), knots
        kept: an affine fn maps the curve exactly; an isometry (a rotation and shift, a
        plane's embedding in 3D: PreparedKeyline.to_input) keeps max_deviation too."""
        return BSpline(self.degree, fn(self.poles), self.knots, self.mults, self.max_deviation)

    # -- serialisation ------------------------------------------------------
    def to_dict(self) -> dict[str, Any]:
        """A JSON-ready dict (lists and numbers)."""
        return {"type": "bspline", "degree": self.degree, "poles": self.poles.tolist(),
                "knots": self.knots.tolist(), "mults": [int(m) for m in self.mults],
                "max_deviation": self.max_deviation}

    @classmethod
    def from_dict(cls, d: dict[str, Any]) -> "BSpline":
        """Inverse of :meth:`to_dict`: the BSpline of its dict ``d`` (degree, poles, knots,
        mults; max_deviation optional, NaN when absent, null or -1)."""
        try:
            return cls(degree=d["degree"], poles=d["poles"], knots=d["knots"], mults=d["mults"],
                       max_deviation=d.get("max_deviation"))
        except KeyError as exc:
            raise ValueError(f"BSpline.from_dict: missing key {exc}") from None

    def __repr__(self) -> str:
        return (f"BSpline(degree={self.degree}, npoles={self.npoles}, dim={self.dim}, "
                f"domain={self.domain}, max_deviation={self.max_deviation:.3g})")

    def __eq__(self, other) -> bool:
        if not isinstance(other, BSpline):
            return NotImplemented
        return (self.degree == other.degree and np.array_equal(self.poles, other.poles)
                and np.array_equal(self.knots, other.knots)
                and np.array_equal(self.mults, other.mults)
                and (self.max_deviation == other.max_deviation      # (NaN: both unknown)
                     or (math.isnan(self.max_deviation) and math.isnan(other.max_deviation))))


def _c2_end(spec, name: str):
    """An el_bspline_end from None (natural), {"d1": (x, y)}, {"d2": (x, y)} or both."""
    if spec is None:
        return ffi.NULL
    if not isinstance(spec, dict) or not spec or set(spec) - {"d1", "d2"}:
        raise ValueError(f"interpolate_c2: {name} must be None or a dict of 'd1' and / or "
                         f"'d2': (x, y), got {spec!r}")
    values = {}
    for key in ("d1", "d2"):
        if key in spec:
            v = as_vector(spec[key], f"interpolate_c2: {name} {key}")
            if v.shape != (2,):
                raise ValueError(f"interpolate_c2: {name} {key} must be two numbers, got "
                                 f"{spec[key]!r}")
            values[key] = list(v)
    if len(values) == 2:
        return ffi.new("el_bspline_end *", {"order": 3, "value": values["d1"],
                                            "value2": values["d2"]})
    key, v = next(iter(values.items()))
    return ffi.new("el_bspline_end *", {"order": 1 if key == "d1" else 2, "value": v})


def interpolate_c2(points, start=None, end=None) -> BSpline:
    """The C2 cubic B-spline through the vertices ``points`` of a polyline ((n, 2), n >= 2),
    chord-length parametrised (knots at the cumulative chord lengths). Each end, ``start``
    and ``end``, is natural (B'' = 0,
    None), or ``{"d1": (x, y)}`` (B' there: a unit tangent clamps the direction at speed
    1) or ``{"d2": (x, y)}`` (B'' there: kappa times the unit normal for a curvature), or
    both (a G2 end: a unit tangent and kappa times its left normal give the curvature
    kappa exactly; one more knot, mid-way along that end's span)."""
    xy = as_points(points, "interpolate_c2: points", min_rows=2)
    s, e = _c2_end(start, "start"), _c2_end(end, "end")
    b = ffi.new("el_bspline *")
    check(lib.el_bspline_interpolate_c2_ends(dptr(xy), len(xy), s, e, b), "interpolate_c2")
    return bspline_from_c(b)


def fitted_bspline(curve, tol=None, degree: int = 3, constraints=None) -> BSpline:
    """The B-spline of a fitted curve for CAD: a smooth elastica's (or a Hermite chain's)
    within ``tol`` (default 1e-6 of its length), certified, its end points, unit tangents and curvatures exact
    (:func:`smooth_chain_to_bspline`: G2 ends, so end curvature constraints hold on it;
    SmoothElastica.to_bspline keeps the tangents only); a discrete one's C2 cubic through
    its vertices (:func:`cubic_through`) with the end tangents and curvatures among the
    fit's ``constraints`` (el.fit's names; G2 where both), natural ends elsewhere (``tol``
    and ``degree`` unused). FitResult.to_bspline and `elastica bspline` of a fit's JSON."""
    from .core import DiscreteElastica, SmoothElastica
    if isinstance(curve, SmoothElastica):
        return smooth_chain_to_bspline([curve], tol, degree)
    if not isinstance(curve, DiscreteElastica):
        return curve.to_bspline(tol=tol, degree=degree)
    con = constraints or {}
    start, end = ({k: con[f"{w}_{k}"] for k in ("tangent", "curvature") if f"{w}_{k}" in con}
                  or None for w in ("start", "end"))
    return cubic_through(curve.points(), start=start, end=end)


def cubic_through(points, start=None, end=None) -> BSpline:
    """The C2 cubic through a polygon's vertices ``points`` ((n, 2), n >= 2; a discrete
    elastica's B-spline) with the end conditions of a fit's constraints: each end,
    ``start`` and ``end``, None (natural, curvature 0) or a dict
    of ``"tangent"`` (the unit tangent's angle, rad, in the direction of travel: clamped,
    speed 1) and / or ``"curvature"`` (signed, + turning left: kappa times the end
    segment's left normal as B'', the curvature kappa where the speed is ~1; with a
    tangent kappa times its left normal, the curvature kappa exactly: a G2 end)."""
    xy = as_points(points, "points")

    def condition(spec, which):
        if spec is None:
            return None
        if not isinstance(spec, dict) or not spec or set(spec) - {"tangent", "curvature"}:
            raise ValueError(f"cubic_through: {which} must be None or a dict of 'tangent' and / "
                             f"or 'curvature', got {spec!r}")
        kappa = as_real(spec.get("curvature", 0.0), f"cubic_through: {which} curvature")
        if "tangent" in spec:
            a = as_real(spec["tangent"], f"cubic_through: {which} tangent")
            warn_if_degrees(a, f"cubic_through: {which} tangent", stacklevel=4)
            t = (np.cos(a), np.sin(a))
            return {"d1": t} if "curvature" not in spec else \
                {"d1": t, "d2": (-kappa * t[1], kappa * t[0])}
        i, j = (0, 1) if which == "start" else (-2, -1)
        d = xy[j] - xy[i]
        n = float(np.hypot(*d))
        d = d / n if n > 0 else d
        return {"d2": (-kappa * d[1], kappa * d[0])}

    return interpolate_c2(xy, start=condition(start, "start"), end=condition(end, "end"))


def keyline_bspline(first, second, tol=None, degree: int = 3, ends=None) -> BSpline:
    """ONE B-spline of a keyline's two halves, each running from the joint outwards (as
    :func:`fit_keyline` gives them), from the first half's far end through the joint to
    the second's: smooth halves, the chain of the first reversed and the second
    (:func:`smooth_chain_to_bspline`: within ``tol``, default 1e-6 of their length, the joint's point, tangent and zero
    curvature exact); discrete ones, the C2 cubic through the vertices of both (the joint
    once), natural at the far ends (``tol``, ``degree`` unused), each half continued to
    the foot of its end point in ``ends`` (two points or None: KeylineFit.ends_local) by
    DiscreteElastica.continued_to. Two separate cubics would each leave the joint with
    its own end tangent."""
    from .core import DiscreteElastica, SmoothElastica
    if isinstance(first, SmoothElastica) and isinstance(second, SmoothElastica):
        return smooth_chain_to_bspline([first.reversed(), second], tol, degree)
    if isinstance(first, DiscreteElastica) and isinstance(second, DiscreteElastica):
        if ends is not None and len(ends) != 2:
            raise ValueError(f"keyline_bspline: ends must be two points or None, got {ends!r}")
        tails = [np.empty((0, 2))] * 2 if ends is None else \
            [c.continued_to(e) for c, e in zip((first, second), ends)]
        return cubic_through(np.vstack([tails[0][::-1], first.points()[::-1], second.points()[1:],
                                        tails[1]]))
    raise ValueError("keyline_bspline: two SmoothElastica or two DiscreteElastica halves are "
                     f"needed, got {type(first).__name__} and {type(second).__name__}")


def smooth_to_bspline(curve, tol=None, degree: int = 3) -> BSpline:
    """Clamped degree-3..7 B-spline within ``tol`` (absolute, coordinate units; default
    1e-6 of the curve's length) of a SmoothElastica everywhere, parametrised by its arc
    length; the certified distance is ``max_deviation``."""
    degree = as_degree(degree, "to_bspline: degree")
    p = ffi.new("el_smooth_params *")
    for name in ("x0", "y0", "phi", "mu", "k", "q", "length"):
        if not hasattr(curve, name):
            raise ValueError(f"to_bspline: a SmoothElastica is needed, got {type(curve).__name__}")
        setattr(p, name, as_real(getattr(curve, name), f"to_bspline: {name}", finite=False))
    tol = default_tol(tol, p.length, floor=resolvable_tol(p) if p.mu > 0 else 0.0)
    b = ffi.new("el_bspline *")
    st = lib.el_smooth_to_bspline(p, tol, degree, b)
    if st == lib.EL_EDOM:
        raise DomainError(st, "to_bspline: " + _beyond_limits(p, tol))
    if st == lib.EL_EMAXITER:   # the best spline is in b: free it before raising
        dev = float(b.max_deviation)
        lib.el_bspline_free(b)
        raise NotConvergedError(st, _not_reached(tol, dev))
    check(st, "to_bspline")
    return bspline_from_c(b)


def _not_reached(tol: float, dev: float) -> str:
    """A tol the certified distance dev exceeds, said with the tol that reaches it."""
    return (f"to_bspline: tolerance {tol:.6g} not reached: the best B-spline found is "
            f"certified within {dev:.6g}; raise tol to {at_least(dev)} or more")


def _beyond_limits(p, tol: float) -> str:
    """What el_smooth_to_bspline's EL_EDOM means for this curve (its header's rules):
    what was asked and what is possible."""
    floor = resolvable_tol(p)
    turn = 2.0 * abs(p.k) * np.sqrt(p.mu) * p.length
    limit = lib.EL_BSPLINE_MAX_POLES
    if tol < floor:
        phase = abs(p.q) / np.sqrt(p.mu)
        why = (f" (|q|/sqrt(mu) = {phase:.3g}, mu = {p.mu:.3g}: a piece this close to straight "
               "carries the rounding of its phase q)" if phase > p.length + abs(p.x0) + abs(p.y0)
               else "")
        return (f"tol = {tol:.3g} is below what double precision resolves for this curve; "
                f"the smallest possible is 1e-14 (length + |x0| + |y0| + |q|/sqrt(mu)) = "
                f"{at_least(floor)}{why}")
    if turn > limit:
        return (f"the curve turns through up to {turn:.3g} rad (2 |k| sqrt(mu) length); "
                f"at most {limit} rad can be followed with {limit} poles: split it into "
                f"pieces of at most {limit / (2 * abs(p.k) * np.sqrt(p.mu)):.4g} in length")
    return (f"tol = {tol:.3g} needs more than {limit} poles for this curve (the limit, "
            f"EL_BSPLINE_MAX_POLES): raise tol or split the curve")


def _first_beyond(arr, tol: float, degree: int) -> int:
    """The index of the piece el_smooth_chain_to_bspline's EL_EDOM came from: the first,
    in the chain's order, below the precision floor, turning more than the pole limit
    follows, or (built again to know) needing more poles than it. Not the piece that turns
    most: a batten's straight middle span below the floor (piece 19 of 39, |q| / sqrt(mu)
    1.7e9) was named as piece 39 needing more than 10000 poles (QA23)."""
    limit = lib.EL_BSPLINE_MAX_POLES
    for j, p in enumerate(arr):
        if tol < resolvable_tol(p) or 2.0 * abs(p.k) * np.sqrt(p.mu) * p.length > limit:
            return j
        b = ffi.new("el_bspline *")
        st = lib.el_smooth_to_bspline_g2(ffi.addressof(arr, j), tol, degree, b)
        if st in (lib.EL_OK, lib.EL_EMAXITER):
            lib.el_bspline_free(b)
        if st == lib.EL_EDOM:
            return j
    return len(arr) - 1   # (not met: the chain's budget below tol on a second pass)


def _check_joints(pieces, tol):
    """ValueError naming the first joint where a piece does not start within tol of where
    the one before ends, its tangent within tol / (the shorter's length) of that end's (the
    library's EL_EINVAL for such a chain)."""
    for j in range(1, len(pieces)):
        a, b = pieces[j - 1], pieces[j]
        end, start = a.points(np.array([a.length]))[0], b.points(np.array([0.0]))[0]
        kink = abs(np.remainder(b.angle(np.array([0.0]))[0] - a.angle(np.array([a.length]))[0] + np.pi,
                                2 * np.pi) - np.pi)
        gap = float(np.hypot(*(start - end)))
        if not (gap <= tol and kink * min(a.length, b.length) <= tol):
            raise ValueError(f"to_bspline: piece {j + 1} does not start where piece {j} ends "
                             f"(gap {gap:.3g}, tangents {kink:.3g} rad apart): a chain's pieces "
                             f"meet within tol = {tol:g}")


def smooth_chain_to_bspline(pieces, tol=None, degree: int = 3) -> BSpline:
    """ONE clamped degree-3..7 B-spline within ``tol`` (default 1e-6 of the chain's length)
    of a chain of SmoothElastica pieces that meet G2 (each starting where the one before
    ends), parametrised by arc length from the first piece's start: each piece with exact
    end point, unit tangent and curvature (el_smooth_chain_to_bspline), joined C2.
    ``max_deviation`` is the certified distance; NotConvergedError (with it and the tol
    that reaches it) when tol is not reached, DomainError (with the smallest possible)
    below what double precision resolves."""
    degree = as_degree(degree, "to_bspline: degree")
    require(len(pieces) >= 1, "to_bspline: the number of pieces", ">= 1", len(pieces))
    arr = ffi.new("el_smooth_params[]", len(pieces))
    for i, c in enumerate(pieces):
        for name in ("x0", "y0", "phi", "mu", "k", "q", "length"):
            setattr(arr[i], name, float(getattr(c, name)))
    tol = default_tol(tol, sum(p.length for p in arr),
                      floor=max(resolvable_tol(p) if p.mu > 0 else 0.0 for p in arr))
    b = ffi.new("el_bspline *")
    st = lib.el_smooth_chain_to_bspline(arr, len(pieces), tol, degree, b)
    if st == lib.EL_EINVAL and tol > 0 and 3 <= degree <= 7:
        # a tol below rounding first: the joints' gaps of ~1e-16 failed it and were named
        # as the cause ("piece 2 does not start where piece 1 ends (gap 9e-16)", QA)
        floor = [resolvable_tol(p) for p in arr]
        worst = int(np.argmax(floor))
        if tol < floor[worst]:
            why = _beyond_limits(arr[worst], tol)
            raise DomainError(lib.EL_EDOM, "to_bspline: " + (
                why if len(arr) == 1 else f"piece {worst + 1} of {len(arr)}: {why}"))
        _check_joints(pieces, tol)
    if st == lib.EL_EDOM:   # a piece beyond el_smooth_to_bspline's limits: say which and why
        n = len(pieces)
        first = _first_beyond(arr, tol, degree)
        why = _beyond_limits(arr[first], tol)
        floors = [resolvable_tol(p) for p in arr]
        top = int(np.argmax(floors))
        if n > 1 and tol < floors[first] and top != first:   # the tol the whole chain takes
            why += (f"; for all {n} pieces (piece {top + 1}'s the largest) the smallest "
                    f"possible is max over the pieces = {at_least(floors[top])}")
        raise DomainError(st, "to_bspline: " + (why if n == 1 else f"piece {first + 1} of {n}: {why}"))
    if st == lib.EL_EMAXITER:
        dev = float(b.max_deviation)
        lib.el_bspline_free(b)
        raise NotConvergedError(st, _not_reached(tol, dev))
    check(st, "to_bspline")
    return bspline_from_c(b)
