"""Hermite interpolation by elastic curves (seed 004): every elastica from a
point with a tangent to a point with a tangent, by tension or by length."""
from __future__ import annotations

import math
import struct
import threading
from typing import List, Optional

import numpy as np

from ._ffi import DomainError, as_int, as_real, as_size, as_vector, check, ffi, lib, require
from ._portable import PortablePickle
from ._quiet import say
from ._values import ValueEquality
from .bspline import smooth_chain_to_bspline
from .core import SMOOTH_PARAMS, SmoothElastica, arc_lengths, chain_eval, chain_starts
from .shape import ShapeDescriptors

__all__ = ["hermite", "hermite_analyse", "HermiteSolutions", "HermiteChain", "HERMITE_SIGMA_D2_MAX"]


class HermiteSolutions(PortablePickle, list):
    """The solutions of :func:`hermite` (a list of :class:`SmoothElastica`, or of
    :class:`HermiteChain` near the separatrix), with ``unrepresentable``: the number
    of curves that exist but that neither one set of smooth parameters nor a chain of
    them meets to ``tol`` (see the header's el_hermite_solve), and ``complete``: False
    when length mode stopped at its work limit (the solutions found so far, with a
    RuntimeWarning). Built like a list, from an ``iterable`` of the solutions."""
    unrepresentable: int = 0
    complete: bool = True


class HermiteChain(ValueEquality, ShapeDescriptors):
    """A Hermite solution near the separatrix (|k| -> 1) that no single
    :class:`SmoothElastica` carries to ``tol`` (one ulp of the double k moves the end of
    a curve through a saddle by ~1e-16 / (1 - |k|)): the same elastica as 2 or 3
    ``pieces`` (SmoothElastica) split at its saddles, each starting where the one before
    ends, with its tangent, the first at p0. Evaluation is by arc length over the
    whole curve, like a SmoothElastica's: ``points(s)``, ``angle(s)`` (continuous),
    ``curvature(s)``, ``energy()``, ``to_bspline(tol, degree)`` (one C2 B-spline), and
    ``length``, ``loops``, ``crosses_itself``, ``max_curvature`` (shape.py); ``k`` and ``mu`` are the first piece's (the pieces share |F| = 2 mu and
    |k| up to its rounding), ``sigma`` the tension; plus the Hermite attributes
    ``energy_value``, ``has_inflection``, ``kappa0``, ``kappa1``, ``residual`` (the keyword
    ``attrs`` el.hermite passes, set as given).
    """

    def __init__(self, pieces: List[SmoothElastica], **attrs):
        self.pieces = list(pieces)
        self.length = float(sum(p.length for p in self.pieces))
        self.k, self.mu = self.pieces[0].k, self.pieces[0].mu
        self.__dict__.update(attrs)
        self._starts = chain_starts(self.pieces)
        # each piece's angle offset (a multiple of 2 pi) that makes theta continuous
        self._turns = [0.0]
        for a, b in zip(self.pieces[:-1], self.pieces[1:]):
            end = float(a.angle([a.length])[0]) + self._turns[-1]
            start = float(b.angle([0.0])[0])
            self._turns.append(2.0 * np.pi * round((end - start) / (2.0 * np.pi)))

    def __repr__(self) -> str:
        return (f"HermiteChain({len(self.pieces)} pieces, k={self.k:.17g}, mu={self.mu:.6g}, "
                f"length={self.length:.6g})")

    def _eval(self, s, what: str, extrapolate: bool = False) -> np.ndarray:
        s, scalar = arc_lengths(101 if s is None else s, self.length, f"HermiteChain.{what}",
                                extrapolate)
        out = chain_eval(self.pieces, self._starts, s, what,
                         self._turns if what == "angle" else None)
        return out[0] if scalar else out

    def points(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Points at arc lengths s from p0, shape (n, 2), as SmoothElastica.points takes s
        (an int n: n equally spaced, default 101; a float: shape (2,); within [0, length]
        unless ``extrapolate``: the end pieces continued)."""
        return self._eval(s, "points", extrapolate)

    def angle(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Tangent angle theta(s) (radians, continuous in s); s and ``extrapolate`` as
        :meth:`points` takes them."""
        return self._eval(s, "angle", extrapolate)

    def curvature(self, s=None, extrapolate: bool = False) -> np.ndarray:
        """Signed curvature kappa(s) (1/length, + turning left); s and ``extrapolate`` as
        :meth:`points` takes them."""
        return self._eval(s, "curvature", extrapolate)

    def energy(self) -> float:
        """Bending energy: the integral of kappa^2 over the whole curve."""
        return float(sum(p.energy() for p in self.pieces))

    def inflections(self, margin: float = 1e-9) -> np.ndarray:
        """Arc lengths of the inflections in (0, length): the pieces' own, and the
        joints of an inflectional curve (its saddles are its inflections, kappa = 0);
        ``margin`` as :func:`elastica_inflections`' (default 1e-9 of each piece's length)."""
        from .affine import elastica_inflections
        out = []
        for i, p in enumerate(self.pieces):
            out.extend(self._starts[i] + elastica_inflections(p, margin))
            if i and abs(p.k) <= 1.0 and self.pieces[i - 1].k * p.k < 0.0:
                out.append(self._starts[i])
        return np.sort(np.array(out, dtype=float))

    def to_bspline(self, tol: Optional[float] = None, degree: int = 3):
        """ONE clamped B-spline (degree 3..7) within ``tol`` (coordinate units; default
        1e-6 of its length) of the whole curve, parametrised by arc length from p0 (el_smooth_chain_to_bspline:
        each piece G2 at its ends, joined C2); ``max_deviation`` is the certified distance."""
        return smooth_chain_to_bspline(self.pieces, tol, degree)


def _vec2(v, name: str):
    """Two finite floats: plain Python floats directly, anything else through
    as_vector (the binding's one validation path)."""
    if type(v) in (tuple, list) and len(v) == 2 and type(v[0]) is float and type(v[1]) is float:
        x, y = v
        if x - x == 0.0 and y - y == 0.0:            # finite (inf - inf and NaN are NaN)
            return x, y
    a = as_vector(v, name)
    if a.shape != (2,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be two finite numbers, got {v!r}")
    return float(a[0]), float(a[1])


_TENSION, _LENGTH = lib.EL_HERMITE_TENSION, lib.EL_HERMITE_LENGTH
_EINVAL, _EDOM, _EMAXITER = lib.EL_EINVAL, lib.EL_EDOM, lib.EL_EMAXITER

#: The tension range of el_hermite_solve (elastica.h): tension times |p1 - p0|^2 at most
#: this.
HERMITE_SIGMA_D2_MAX = float(lib.EL_HERMITE_SIGMA_D2_MAX)


def _out_of_range(x0, y0, x1, y1, mode, sigma, length):
    """Which of el_hermite_solve's ranges (elastica.h) the ends or the tension leave
    (its EL_EDOM), in words; None when none does."""
    d = math.hypot(x1 - x0, y1 - y0)
    if d == 0.0:
        return "hermite: p0 and p1 coincide"
    if not 1e-100 <= d <= 1e100 or max(abs(x0), abs(y0), abs(x1), abs(y1)) > 1e100:
        return (f"hermite: |p1 - p0| = {d:.3g} or a coordinate is outside the range the solver "
                "covers (|p1 - p0| from 1e-100 to 1e100, coordinates up to 1e100)")
    if mode == _TENSION and sigma * d * d > HERMITE_SIGMA_D2_MAX:
        return (f"hermite: tension {sigma:.6g} at |p1 - p0| = {d:.6g} makes sigma |p1 - p0|^2 = "
                f"{sigma * d * d:.3g}, past the {HERMITE_SIGMA_D2_MAX:g} the solver covers "
                f"(here a tension of at most {HERMITE_SIGMA_D2_MAX / (d * d):.6g})")
    if mode == _LENGTH and not length > d:
        return f"hermite: length {length:.6g} is not longer than |p1 - p0| = {d:.6g}"
    return None


# the classes of hermite()'s fast path: four tuples of two Python floats
_TUPLES_OF_FLOATS = (tuple,) * 4 + (float,) * 8


def _layout(fields, size: int = 0) -> struct.Struct:
    """The struct format of a C layout from its (byte offset, struct code) fields
    (offsets from cffi, so never retyped by hand); the bytes between them, and up to
    size, are padding. Native mode ("@": the library's own byte order and sizes, and
    struct's fastest conversions); the fields sit at the C offsets, so its alignment
    adds nothing (checked)."""
    fmt, pos = "@", 0
    for off, code in sorted(fields):
        fmt += f"{off - pos}x{code}" if off > pos else code
        pos = off + struct.calcsize("@" + code)
    layout = struct.Struct(fmt + (f"{size - pos}x" if size > pos else ""))
    if layout.size != max(size, pos):
        raise ImportError(f"libelastica: struct layout {fmt} does not match the C one")
    return layout


# el_hermite_solution unpacked in one go: curve and the scalars but length (curve's
# for one piece; a chain's, and its further pieces, rare, are read from the C struct)
_SOL_SIZE = ffi.sizeof("el_hermite_solution")
_SOL_STRUCT = _layout(
    [(ffi.offsetof("el_hermite_solution", "curve") + ffi.offsetof("el_smooth_params", n), "d")
     for n in SMOOTH_PARAMS] +
    [(ffi.offsetof("el_hermite_solution", n), "i" if n in ("has_inflection", "npieces") else "d")
     for n in ("sigma", "energy", "has_inflection", "kappa0", "kappa1", "residual", "npieces")],
    _SOL_SIZE)


# a call's varying inputs, written into this thread's block (below) by one pack_into:
# the eight floats of the ends, then the options' mode, sigma and length
_CALL_STRUCT = _layout([(8 * i, "d") for i in range(8)] +
                       [(8 * 8 + ffi.offsetof("el_hermite_options", n), c)
                        for n, c in (("mode", "i"), ("sigma", "d"), ("length", "d"))])
_OPT_WORDS = -(-ffi.sizeof("el_hermite_options") // 8)   # the options, in doubles
_COUNTS_AT = 8 * (8 + _OPT_WORDS)   # (bytes) the count and unrepresentable, after the options
_COUNTS = _layout([(_COUNTS_AT, "N"), (_COUNTS_AT + ffi.sizeof("size_t"), "N")])   # (N: size_t)
_solve_into = lib.el_hermite_solve_into

# Per-thread C memory, allocated once (two threads may solve at once): one block of
# doubles holding the ends p0, t0, p1, t1, then the options (a call writes both with
# one pack_into), then el_hermite_solve_into's count and unrepresentable; the array of
# solutions with a view of its first n for every n; and the options tol, samples, grid,
# max_solutions last set (the Python objects, kept alive: the same objects need no
# new check).
_local = threading.local()
_UNSET = object()
_new_object = object.__new__


def _new_state():
    """This thread's state, made on its first call."""
    block = ffi.new("double[]", 8 + _OPT_WORDS + 2 * -(-ffi.sizeof("size_t") // 8))
    opt = ffi.cast("el_hermite_options *", block + 8)
    lib.el_hermite_options_defaults(opt)
    counts = ffi.cast("size_t *", block + 8 + _OPT_WORDS)
    solve_args = (block, block + 2, block + 4, block + 6, opt, None, 0, counts, counts + 1)
    return _with_capacity((ffi.buffer(block), solve_args, None) + (_UNSET,) * 4, 64)


def _with_capacity(state, cap: int):
    """This thread's state with an array of cap solutions (64, the default max_solutions,
    then as many as a call returned)."""
    mem, solve_args, _, *last = state
    solutions = ffi.new("el_hermite_solution[]", cap)
    whole = memoryview(ffi.buffer(solutions))
    return (mem, solve_args[:5] + (solutions, cap) + solve_args[7:],
            [whole[:n * _SOL_SIZE] for n in range(cap + 1)], *last)


def _piece(values) -> SmoothElastica:
    """A SmoothElastica of valid parameters (the library's), without re-checking them."""
    e = SmoothElastica.__new__(SmoothElastica)
    e.__dict__.update(zip(SMOOTH_PARAMS, values))
    return e


def _chain(row, c) -> HermiteChain:
    """The HermiteChain of an unpacked row and its C struct c (for the further pieces)."""
    sigma, energy, infl, kappa0, kappa1, residual, npieces = row[7:]
    rest = [_piece([getattr(c.rest[i], n) for n in SMOOTH_PARAMS]) for i in range(npieces - 1)]
    return HermiteChain([_piece(row[:7])] + rest, sigma=sigma, energy_value=energy,
                        has_inflection=bool(infl), kappa0=kappa0, kappa1=kappa1, residual=residual)


def _general_ends(p0, t0, p1, t1):
    """The eight floats of ends that are not four tuples of two Python floats."""
    return _vec2(p0, "p0") + _vec2(t0, "t0") + _vec2(p1, "p1") + _vec2(t1, "t1")


def _invalid(tx0, ty0, tx1, ty1, mode, length, options) -> str:
    """What el_hermite_solve refused with EL_EINVAL (its header's list), named: a zero
    tangent, a length not > 0, an option out of its range; '' for none of these."""
    tol, samples, grid, max_solutions = options
    for name, tx, ty in (("t0", tx0, ty0), ("t1", tx1, ty1)):
        if tx == 0.0 and ty == 0.0:
            return f"the tangent {name} = (0, 0) has no direction"
    if mode == _LENGTH and not length > 0.0:
        return f"length must be > 0, got {length:g}"
    for what, ok in ((f"tol must be > 0, got {tol!r}", tol > 0), (f"samples must be 4..1000, got {samples!r}", 4 <= samples <= 1000),
                     (f"grid must be 1..256, got {grid!r}", 1 <= grid <= 256),
                     (f"max_solutions must be >= 1, got {max_solutions!r}", max_solutions >= 1)):
        if not ok:
            return what
    return ""


def hermite(p0, t0, p1, t1, tension: Optional[float] = None,
            length: Optional[float] = None, *, tol: float = 1e-10,
            samples: int = 12, grid: int = 6, max_solutions: int = 64) -> HermiteSolutions:
    """All elastic curves (2 kappa'' + kappa^3 - sigma kappa = 0) from ``p0`` with
    tangent direction ``t0`` to ``p1`` with tangent direction ``t1`` whose length is
    at most one period of the curvature, sorted by bending energy.

    Give exactly one of ``tension`` (sigma, 1/length^2; any real, negative is
    compression) or ``length`` (the arc length; sigma is then computed).
    ``tol``: the accepted end residual (position / |p1 - p0| and tangent angle, rad;
    default 1e-10). ``samples``: bracketing samples over the whole search interval
    (4..1000, default 12; more finds close pairs of solutions). ``grid``: length mode's
    tension lines whose solutions start the tracing (1..256, default 6).
    ``max_solutions``: at most this many solutions are kept, the lowest energy first
    (>= 1, default 64). (el_hermite_options, elastica.h.)

    Returns a :class:`HermiteSolutions` list of :class:`SmoothElastica` (near the
    separatrix, where no single one meets ``tol``, a :class:`HermiteChain` of two or
    three pieces of the same elastica, evaluated the same way); each carries extra
    attributes:

    - ``sigma``: the tension; ``energy_value``: integral of kappa^2 ds as the solve
      computed it (the list's order; ``energy()``, every curve's method, integrates the
      same again: use it for any curve, ``energy_value`` to read the solve's figure);
    - ``has_inflection``: whether the curvature changes sign;
    - ``kappa0``, ``kappa1``: curvature at p0 and p1; ``residual``: end error;
    - ``length``, and to pick the fair one (the order is by energy, and the least
      energy can belong to a curve that loops): ``loops`` (self-crossings),
      ``crosses_itself`` and ``max_curvature`` (largest |kappa|), computed on access.

    Every curve runs from ``p0`` (s = 0, tangent ``t0``) to ``p1`` (s = length,
    tangent ``t1``). The sign of ``k`` is the orientation: a loop (``|k| > 1``)
    turns counter-clockwise for ``k > 1`` and clockwise for ``k < -1``. Curves that
    exist but cannot be represented to ``tol`` (high tension, next to the
    separatrix) are counted in the list's ``unrepresentable``, with a RuntimeWarning.

    Raises ``ValueError`` (an :class:`ElasticaError`) for bad input, and
    :class:`DomainError` when ``p0 == p1`` or ``length < |p1 - p0|``. When length mode
    reaches its work limit the solutions found so far are returned with a
    RuntimeWarning and ``complete = False``.
    """
    # (This is the binding's hottest path, written for the interpreter: each line
    # below costs tens of instructions, a Python-level call hundreds.)
    try:
        mem, solve_args, views, last_tol, last_samples, last_grid, last_max = state = _local.state
    except (AttributeError, TypeError):   # this thread's first call, or a call made while
        # one runs in it (a finaliser or signal handler calling hermite): its own memory
        mem, solve_args, views, last_tol, last_samples, last_grid, last_max = state = _new_state()
    _local.state = None   # this call's until it returns: its results are read from it
    try:
        if length is None:
            if tension is None:
                raise ValueError("hermite: give exactly one of tension= or length=")
            mode, sigma, length = _TENSION, tension, 0.0
            if sigma.__class__ is not float or sigma - sigma != 0.0:   # (x - x: NaN for NaN, inf)
                sigma = as_real(sigma, "hermite: tension")
        else:
            if tension is not None:
                raise ValueError("hermite: give exactly one of tension= or length=")
            mode, sigma = _LENGTH, 0.0
            if length.__class__ is not float or length - length != 0.0:
                length = as_real(length, "hermite: length")
        # the ends: four tuples of two Python floats directly (el_hermite_solve refuses
        # non-finite values, and _vec2 then says which), anything else through _vec2
        try:
            (x0, y0), (tx0, ty0), (x1, y1), (tx1, ty1) = p0, t0, p1, t1
        except (TypeError, ValueError):   # not four pairs
            x0 = y0 = tx0 = ty0 = x1 = y1 = tx1 = ty1 = None
        if (p0.__class__, t0.__class__, p1.__class__, t1.__class__, x0.__class__, y0.__class__,
                tx0.__class__, ty0.__class__, x1.__class__, y1.__class__, tx1.__class__,
                ty1.__class__) != _TUPLES_OF_FLOATS:
            x0, y0, tx0, ty0, x1, y1, tx1, ty1 = _general_ends(p0, t0, p1, t1)
        _CALL_STRUCT.pack_into(mem, 0, x0, y0, tx0, ty0, x1, y1, tx1, ty1, mode, sigma, length)
        # the options that rarely change are checked and set only when they are not the
        # very objects set last time
        if tol is not last_tol or samples is not last_samples or grid is not last_grid \
                or max_solutions is not last_max:
            opt = solve_args[4]
            opt.tol, opt.samples, opt.grid, opt.max_solutions = (
                as_real(tol, "hermite: tol"), as_int(samples, "hermite: samples"),
                as_int(grid, "hermite: grid"), as_size(max_solutions, "hermite: max_solutions"))
            state = (mem, solve_args, views, tol, samples, grid, max_solutions)
        status = _solve_into(*solve_args)
        if status and status != _EMAXITER:
            if status == _EINVAL:   # say which end is not finite, or what else is refused
                _general_ends(p0, t0, p1, t1)
                why = _invalid(tx0, ty0, tx1, ty1, mode, length, state[3:])
                if why:
                    raise ValueError(f"hermite: {why}")
            if status == _EDOM:
                why = _out_of_range(x0, y0, x1, y1, mode, sigma, length)
                if why:
                    raise DomainError(status, why)
            check(status, "hermite")
        n, unrepresentable = _COUNTS.unpack_from(mem)
        if n >= len(views):   # more than this thread's array holds: a larger one, solved again
            mem, solve_args, views, *_ = state = _with_capacity(state, n)
            status = _solve_into(*solve_args)
        # one SmoothElastica per solution, its attributes stored in the same order every
        # time (the instances then share one key table)
        out = HermiteSolutions()
        for row in _SOL_STRUCT.iter_unpack(views[n]):
            e = _new_object(SmoothElastica)
            (e.x0, e.y0, e.phi, e.mu, e.k, e.q, e.length, e.sigma, e.energy_value, infl,
             e.kappa0, e.kappa1, e.residual, npieces) = row
            e.has_inflection = infl != 0
            out.append(e if npieces == 1 else _chain(row, solve_args[5][len(out)]))
        if unrepresentable:
            out.unrepresentable = unrepresentable
            say(f"hermite: {unrepresentable} more curve(s) exist that no smooth "
                f"parameters meet to tol={tol:g} (too close to the separatrix |k| = 1, "
                "or, at tension 0, so nearly straight that they are a sliver of a huge "
                "elastica); a larger tol returns them", RuntimeWarning, stacklevel=2)
        if status:
            out.complete = False
            say(f"hermite: length mode reached its work limit; the {len(out)} solution(s) "
                "found so far are returned (the list's complete is False)",
                RuntimeWarning, stacklevel=2)
        return out
    finally:
        _local.state = state


def hermite_analyse(P, V, sigma: float) -> dict:
    """Diagnostics of the normalised tension problem of seed 004 §4-5 (data
    after x(0) = 0, x'(0) = (0, 1), |P| = 1): case of Theorem 6, the kappa_m
    bound, the search intervals (18), the real roots of the polynomial (40)
    with their branch, and the special values (45). ``P`` = x(L) and ``V`` = x'(L), unit
    2-vectors (to 1e-9), ``sigma`` the tension (<= 1e5, el.hermite's range), in the
    normalised units (|P| = 1)."""
    P, V = _vec2(P, "hermite_analyse: P"), _vec2(V, "hermite_analyse: V")
    for name, v in (("P", P), ("V", V)):     # (the normalised data: unit vectors)
        require(abs(math.hypot(*v) - 1) <= 1e-9, f"hermite_analyse: |{name}|", "1 (to 1e-9)",
                math.hypot(*v))
    sigma = as_real(sigma, "hermite_analyse: sigma")
    if sigma > 1e5:
        raise DomainError(lib.EL_EDOM, f"hermite_analyse: sigma must be <= 1e5 (el.hermite's "
                                       f"range), got {sigma:g}")
    a = ffi.new("el_hermite_analysis *")
    check(lib.el_hermite_analyse(ffi.new("double[2]", list(P)), ffi.new("double[2]", list(V)),
                                 sigma, a), "hermite_analyse")
    return {
        "case": int(a.hcase),
        "kappa_bound": float(a.kappa_bound),
        "intervals": [(a.interval[2 * i], a.interval[2 * i + 1]) for i in range(a.ninterval)],
        "roots": [float(a.root[i]) for i in range(a.nroot)],
        "root_branch": [int(a.root_branch[i]) for i in range(a.nroot)],
        "special": [float(a.special[i]) for i in range(a.nspecial)],
    }
