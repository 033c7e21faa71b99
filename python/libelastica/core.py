"""Smooth and discrete elasticae (seed 000 (4.3)/(4.4)) over the C library."""
from __future__ import annotations

import math
from dataclasses import dataclass, fields
from typing import Optional

import numpy as np

from ._ffi import (DomainError, as_int, as_real, as_size, as_vector, check, dptr, ffi, invalid,
                   lib, require)
from ._portable import PortablePickle
from .shape import ShapeDescriptors

SMOOTH_PARAMS = ("x0", "y0", "phi", "mu", "k", "q", "length")
DISCRETE_PARAMS = ("x0", "y0", "h", "phi", "z", "q", "k")
# el_smooth_check's / el_discrete_check's ranges (elastica.h), named in Python's message
_SMOOTH_RULES = {"mu": (lambda v: v > 0, "> 0"), "length": (lambda v: v >= 0, ">= 0")}
_DISCRETE_RULES = {"h": (lambda v: v > 0, "> 0"), "k": (lambda v: v >= 0, ">= 0")}
# el_smooth_eval's output that each evaluating method asks for (_at's ``what``)
_WHAT = {"points": "xy", "angle": "theta", "curvature": "kappa"}


def _check_fields(cls: str, p, names, rules) -> None:
    """ValueError naming the first field of the C params ``p`` that el_*_check refuses."""
    for n in names:
        v = getattr(p, n)
        require(math.isfinite(v), f"{cls}: {n}", "finite", v)
        if n in rules:
            require(rules[n][0](v), f"{cls}: {n}", rules[n][1], v)


@dataclass
class SmoothElastica(PortablePickle, ShapeDescriptors):
    """A smooth elastica segment: u = sqrt(mu) s + q, sin((theta-phi)/2) = k sn(u;k),
    cos((theta-phi)/2) = dn(u;k), curvature 2 k sqrt(mu) cn(u;k), start (x0, y0),
    arc length s in [0, length]. |k| < 1 has inflections, |k| > 1 none (a loop turning
    counter-clockwise for k > 1, clockwise for k < -1), k = 0 is a line; -k is the
    mirror image in the line through (x0, y0) at angle phi (radians, as every angle of the
    binding: theta from :meth:`angle` too). ``loops``, ``crosses_itself``
    and ``max_curvature`` describe its shape (shape.py).

    >>> c = SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=0.8, q=0.0, length=5.0)
    >>> c.points(np.linspace(0, c.length, 100)).shape
    (100, 2)
    """
    x0: float = 0.0
    y0: float = 0.0
    phi: float = 0.0
    mu: float = 1.0
    k: float = 0.5
    q: float = 0.0
    length: float = 1.0

    def __post_init__(self):
        for f in fields(self):
            v = getattr(self, f.name)
            if type(v) is not float:   # (floats are checked by el_smooth_check)
                setattr(self, f.name, as_real(v, f"SmoothElastica: {f.name}"))
        check(lib.el_smooth_check(self._c()), "SmoothElastica")

    def _c(self):
        p = ffi.new("el_smooth_params *")
        for n in SMOOTH_PARAMS:   # (checked again: an attribute may have been reassigned)
            v = getattr(self, n)
            setattr(p, n, v if type(v) is float else
                    as_real(v, f"SmoothElastica: {n}", finite=False))
        _check_fields("SmoothElastica", p, SMOOTH_PARAMS, _SMOOTH_RULES)
        return p

    @property
    def params(self) -> np.ndarray:
        """The parameter vector (x0, y0, phi, mu, k, q, length) of the Jacobian."""
        return np.array([getattr(self, n) for n in SMOOTH_PARAMS])

    def _eval(self, s, what: str, extrapolate: bool = False) -> np.ndarray:
        s, scalar = arc_lengths(101 if s is None else s, self.length,
                                f"SmoothElastica.{what}", extrapolate)
        out = self._at(s, _WHAT[what])
        return out[0] if scalar else out

    def _at(self, s: np.ndarray, what: str) -> np.ndarray:
        """Values at the float64 arc lengths ``s`` as given (a chain's pieces: chain_eval)."""
        shape = (len(s), 2) if what == "xy" else (len(s),)
        out = np.empty(shape)
        args = {"xy": ffi.NULL, "theta": ffi.NULL, "kappa": ffi.NULL}
        args[what] = dptr(out)
        check(lib.el_smooth_eval(self._c(), len(s), dptr(s), args["xy"], args["theta"],
                                 args["kappa"]), "SmoothElastica")
        return out

    def points(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Points gamma(s), shape (n, 2), at arc lengths s in [0, length] (floats, an array;
        a float or 0-d array gives shape (2,)); an int n: n equally spaced over [0, length]
        (default 101). s outside [0, length]: ValueError (:func:`arc_lengths`), unless
        ``extrapolate``: the elastica (4.3) continued past its ends (a foot point's Newton
        step may need it)."""
        return self._eval(s, "points", extrapolate)

    def angle(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Tangent angle theta(s) (radians, continuous in s); s and ``extrapolate`` as
        :meth:`points` takes them."""
        return self._eval(s, "angle", extrapolate)

    def curvature(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Signed curvature kappa(s) (1/length, positive = turning counter-clockwise); s and
        ``extrapolate`` as :meth:`points` takes them."""
        return self._eval(s, "curvature", extrapolate)

    def energy(self) -> float:
        """Bending energy: the integral of kappa^2 over [0, length]."""
        e = ffi.new("double *")
        check(lib.el_smooth_energy(self._c(), e), "SmoothElastica.energy")
        return float(e[0])

    def jacobian(self, s=None) -> np.ndarray:
        """d gamma(s_i) / d p, shape (n, 2, 7), p = (x0, y0, phi, mu, k, q, length); the length
        column holds s/length fixed (d/dL gamma(t L) = t T); s as :meth:`points` takes it
        (a float: shape (2, 7))."""
        s, scalar = arc_lengths(101 if s is None else s, self.length,
                                "SmoothElastica.jacobian")
        jac = np.empty((len(s), 2, 7))
        check(lib.el_smooth_jacobian(self._c(), len(s), dptr(s), ffi.NULL, dptr(jac)),
              "SmoothElastica.jacobian")
        return jac[0] if scalar else jac

    def reversed(self) -> "SmoothElastica":
        """The same segment run backwards (el_smooth_reverse): it starts at this one's end
        with the opposite tangent; points(s) = self.points(length - s), curvature negated."""
        out = ffi.new("el_smooth_params *")
        check(lib.el_smooth_reverse(self._c(), out), "SmoothElastica.reversed")
        return SmoothElastica(**{n: float(getattr(out, n)) for n in SMOOTH_PARAMS})

    def to_bspline(self, tol: Optional[float] = None, degree: int = 3):
        """Clamped non-rational B-spline of the given degree (3..7) within ``tol`` (absolute,
        coordinate units; default 1e-6 of its length) of this segment everywhere, parametrised by arc length on
        [0, length]; the certified distance is its ``max_deviation`` (bspline.py)."""
        from .bspline import smooth_to_bspline
        return smooth_to_bspline(self, tol, degree)


def arc_lengths(where, length: float, who: str, extrapolate: bool = False,
                param: str = "arc length s"):
    """(s, scalar): the arc lengths a curve's points/angle/curvature(where) evaluate at,
    one rule for every curve of arc length [0, length]: an int n (Python or numpy
    integer) is a count, n >= 2 equally spaced; a float or an array (0-d included) holds
    arc lengths, each within [0, length] (1e-12 length of rounding allowed), else
    ValueError naming the range (``extrapolate``: any finite s, the elastica continued past
    its ends); scalar: a float or 0-d array (numpy's shapes: (2,), ()). ``who``: the
    method called, named in the messages; ``param``: what the values are and their name,
    for a curve whose natural parameter is not arc length (BlendCurve's "parameter t" over
    [0, nseg])."""
    if isinstance(where, (int, np.integer)) and not isinstance(where, (bool, np.bool_)):
        n = as_int(where, f"{who}: the number of points n", 2, None)
        return np.linspace(0.0, length, n), False
    return within(where, 0, length, who, param, None if extrapolate else 1e-12 * length,
                  "the curve,", "an int n asks for n points")


def within(where, lo: float, hi: float, who: str, param: str, slack: Optional[float],
           place: str, hint: str, error=invalid):
    """(values, scalar): ``where`` (a float, an array, 0-d included: scalar) as a finite
    float64 vector, each within [lo, hi] give or take ``slack`` (None: any), else
    ``error(message)`` naming ``who``, the value and the range: "{who}: parameter t[1] =
    -1.0 is outside {place} [lo, hi] ({hint})". arc_lengths' rule, and BSpline's over
    its domain (an int a parameter there)."""
    scalar = type(where) is float or np.ndim(where) == 0
    what, name = param.rsplit(" ", 1)
    s = as_vector(where, f"{who}: {name}", finite=True)
    if slack is not None and len(s) and (s.min() < lo - slack or s.max() > hi + slack):
        i = int(np.argmax((s < lo - slack) | (s > hi + slack)))
        raise error(f"{who}: {what} {name if scalar else f'{name}[{i}]'} = {float(s[i])!r} "
                    f"is outside {place} [{lo!r}, {hi!r}] ({hint})")
    return s, scalar


def chain_starts(pieces) -> np.ndarray:
    """The arc length at which each piece of a chain starts, then the chain's length."""
    return np.concatenate([[0.0], np.cumsum([p.length for p in pieces])])


def chain_eval(pieces, starts, s, what: str, offsets=None, clip: bool = False) -> np.ndarray:
    """A chain of SmoothElastica pieces (each starting where the one before ends;
    ``starts`` from :func:`chain_starts`) evaluated at arc lengths ``s`` over the whole
    chain: ``what`` is "points", "angle" or "curvature"; ``offsets[i]`` is added to
    piece i's values (whole turns that make the angle continuous); ``clip`` holds each
    local arc length to its piece (no extrapolation past the chain's ends)."""
    j = np.clip(np.searchsorted(starts, s, side="right") - 1, 0, len(pieces) - 1)
    out = np.empty((len(s), 2) if what == "points" else len(s))
    for i in np.unique(j):
        sel = j == i
        local = s[sel] - starts[i]
        if clip:
            local = np.clip(local, 0.0, pieces[i].length)
        out[sel] = pieces[i]._at(local, _WHAT[what])
        if offsets is not None:
            out[sel] += offsets[i]
    return out


@dataclass
class DiscreteElastica(PortablePickle):
    """A Bobenko–Suris discrete elastica: n vertices, segments of length h, potential
    sin((theta_n-phi)/2) = k sn(z n + q; k), cos((theta_n-phi)/2) = dn(z n + q; k),
    segment angle (theta_n + theta_{n+1})/2, first vertex (x0, y0); phi and theta in
    radians. ``points``, ``angle`` and ``curvature`` take the one rule of every curve
    (:func:`arc_lengths`) along the polygon, of ``length`` (n - 1) h: the vertices' own
    values interpolated linearly in arc length; without an argument, the vertices'.

    >>> d = DiscreteElastica(x0=0, y0=0, h=0.1, phi=0, z=0.1, q=0.0, k=0.8, n=50)
    >>> d.points().shape
    (50, 2)
    """
    x0: float = 0.0
    y0: float = 0.0
    h: float = 0.1
    phi: float = 0.0
    z: float = 0.1
    q: float = 0.0
    k: float = 0.5
    n: int = 50

    def __post_init__(self):
        for name in DISCRETE_PARAMS:
            v = getattr(self, name)
            if type(v) is not float:   # (floats are checked by el_discrete_check)
                setattr(self, name, as_real(v, f"DiscreteElastica: {name}"))
        # n vertices of 2 doubles each must fit in memory
        self.n = as_size(self.n, "DiscreteElastica: n", lo=2, hi=2 ** 59)
        check(lib.el_discrete_check(self._c()), "DiscreteElastica")

    def _c(self):
        p = ffi.new("el_discrete_params *")
        for name in DISCRETE_PARAMS:   # (checked again: an attribute may have been reassigned)
            v = getattr(self, name)
            setattr(p, name, v if type(v) is float else
                    as_real(v, f"DiscreteElastica: {name}", finite=False))
        self.n = as_size(self.n, "DiscreteElastica: n", lo=2, hi=2 ** 59)
        _check_fields("DiscreteElastica", p, DISCRETE_PARAMS, _DISCRETE_RULES)
        return p

    @property
    def params(self) -> np.ndarray:
        """The parameter vector (x0, y0, h, phi, z, q, k) of the Jacobian (seed 000 (4.5))."""
        return np.array([getattr(self, name) for name in DISCRETE_PARAMS])

    @property
    def length(self) -> float:
        """The polygon's length, (n - 1) h: vertex i lies at arc length s = i h."""
        return (self.n - 1) * self.h

    def _along(self, s, values: np.ndarray, method: str) -> np.ndarray:
        """The vertices' ``values`` interpolated linearly along the polygon's arc length at
        ``s`` by :func:`arc_lengths`' rule (QA19 M1: every curve's points, angle and
        curvature take one rule)."""
        s, scalar = arc_lengths(s, self.length, f"DiscreteElastica.{method}")
        t = s / self.h
        i = np.clip(np.floor(t), 0, self.n - 2).astype(np.intp)
        f = t - i
        if values.ndim == 2:
            f = f[:, None]
        out = (1.0 - f) * values[i] + f * values[i + 1]
        return out[0] if scalar else out

    def points(self, s=None) -> np.ndarray:
        """The n vertices, shape (n, 2); given ``s``, points on the polygon by the rule every
        curve's points take (:func:`arc_lengths`): an int m, m points equally spaced along
        it; floats or an array, arc lengths in [0, length] (a float: shape (2,))."""
        p = self._c()
        out = np.empty((self.n, 2))
        check(lib.el_discrete_eval(p, self.n, dptr(out)), "DiscreteElastica")
        return out if s is None else self._along(s, out, "points")

    def angle(self, s=None) -> np.ndarray:
        """The potential theta_i at the n vertices (radians, continuous: a loop's turns
        counted), sin((theta_i - phi)/2) = k sn(z i + q; k), cos = dn (seed 000 (4.4));
        each segment's direction is its ends' mean, (theta_i + theta_{i+1})/2. Given ``s``
        (as :meth:`points` takes it), theta interpolated linearly along the polygon: at a
        segment's midpoint, the segment's direction."""
        u = self.z * np.arange(self.n, dtype=np.float64)   # (4.3) at mu = 1, s = z i: u_i
        smooth = SmoothElastica(x0=0.0, y0=0.0, phi=self.phi, mu=1.0, k=self.k, q=self.q,
                                length=float(abs(u[-1])))
        try:
            theta = smooth._at(u, "theta")
        except DomainError:        # |z| (n - 1) below what (4.3)'s closed form resolves
            half = np.empty(self.n)
            val = ffi.new("el_jacobi *")
            for i, ui in enumerate(u):
                check(lib.el_jacobi_eval(float(ui) + self.q, self.k, val, ffi.NULL, ffi.NULL),
                      "DiscreteElastica.angle")
                half[i] = math.atan2(self.k * val.sn, val.dn)
            theta = self.phi + 2.0 * np.unwrap(half, period=2.0 * math.pi)
        return theta if s is None else self._along(s, theta, "angle")

    def vertex_curvature(self) -> np.ndarray:
        """The discrete curvature (2/h) tan(K_i/2) at all n vertices (seed 000 (3.4)): the
        interior ones' as :meth:`curvature`, the ends' of the polygon continued one vertex
        past each by its own recursion (u_{-1} = q - z, u_n = z n + q)."""
        p = self._c()   # that polygon of n + 2 vertices: its interior n
        p.q = self.q - self.z
        out = np.empty(self.n)
        check(lib.el_discrete_curvature(p, self.n + 2, dptr(out)), "DiscreteElastica")
        return out

    def continued_to(self, point) -> np.ndarray:
        """The polygon continued past its last vertex by its own recursion (seed 000 (4.4),
        u_m = z m + q for m >= n) to the foot of ``point`` on it: (m, 2), the vertices after
        the last one, the foot last; (0, 2) when that foot is not beyond the last vertex.
        A keyline's resampled polygon stops up to a step short of its points (§5.3): this
        reaches their end. A foot within 1e-3 h of a vertex is that vertex (a shorter last
        chord would only bend the cubic through the vertices)."""
        P = as_vector(point, "DiscreteElastica.continued_to: point")
        if P.shape != (2,) or not np.all(np.isfinite(P)):
            raise ValueError("DiscreteElastica.continued_to: point must be finite (x, y), "
                             f"got {point!r}")
        V = self.points()
        steps = int(np.ceil(np.hypot(*(P - V[-1])) / self.h)) + 2   # a straight run's, and 2
        W = DiscreteElastica(**{k: getattr(self, k) for k in DISCRETE_PARAMS},
                             n=self.n + steps).points()
        for j in range(self.n - 1, len(W) - 1):
            t = float(np.dot(P - W[j], W[j + 1] - W[j])) / self.h ** 2
            if t < 1.0:
                tail = W[self.n:j + 1]
                return tail if t <= 1e-3 else np.vstack([tail, W[j] + t * (W[j + 1] - W[j])])
        return np.empty((0, 2))        # the point beyond the continuation's reach: none

    def curvature(self, s=None) -> np.ndarray:
        """Discrete curvature (2/h) tan(K/2) at the n-2 interior vertices (seed 000 (3.4));
        given ``s`` (as :meth:`points` takes it), :meth:`vertex_curvature` interpolated
        linearly along the polygon."""
        if s is not None:
            return self._along(s, self.vertex_curvature(), "curvature")
        p = self._c()
        if self.n < 3:
            raise ValueError("DiscreteElastica.curvature needs n >= 3")
        out = np.empty(self.n - 2)
        check(lib.el_discrete_curvature(p, self.n, dptr(out)), "DiscreteElastica")
        return out

    def to_bspline(self):
        """The C2 cubic B-spline interpolating the vertices (natural ends, chord-length
        parameter); it passes through every vertex exactly (bspline.py)."""
        from .bspline import interpolate_c2
        return interpolate_c2(self.points())

    def jacobian(self) -> np.ndarray:
        """d gamma_i / d p, shape (n, 2, 7), p = (x0, y0, h, phi, z, q, k)."""
        p = self._c()
        jac = np.empty((self.n, 2, 7))
        check(lib.el_discrete_jacobian(p, self.n, ffi.NULL, dptr(jac)),
              "DiscreteElastica.jacobian")
        return jac
