"""Hermite interpolation by elastic curves (seed 004): every elastica from a
point with a tangent to a point with a tangent, by tension or by length."""
from __future__ import annotations

import struct
import threading
import warnings
from typing import List, Optional

import numpy as np

from ._ffi import as_int, as_real, as_size, as_vector, check, ffi, lib
from .core import SMOOTH_PARAMS, SmoothElastica

__all__ = ["hermite", "hermite_analyse", "HermiteSolutions"]


class HermiteSolutions(list):
    """The solutions of :func:`hermite` (a list of :class:`SmoothElastica`), with
    ``unrepresentable``: the number of curves that exist but that no set of smooth
    parameters meets to ``tol`` (they lie too close to the separatrix, |k| = 1, for a
    double k: see the header's el_hermite_solve); a larger ``tol`` returns them."""
    unrepresentable: int = 0


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


# Per-thread C buffers, allocated once (two threads may solve at once).
_local = threading.local()


def _buffers():
    b = getattr(_local, "buffers", None)
    if b is None:
        opt = ffi.new("el_hermite_options *")
        lib.el_hermite_options_defaults(opt)
        b = _local.buffers = (opt, ffi.new("el_hermite_result *"), ffi.new("double[8]"))
    return b


# el_hermite_solution unpacked in one go by a struct format built from cffi's layout
def _solution_struct():
    curve = ffi.offsetof("el_hermite_solution", "curve")
    fields = [(curve + ffi.offsetof("el_smooth_params", n), "d") for n in SMOOTH_PARAMS]
    fields += [(ffi.offsetof("el_hermite_solution", n), "i" if n == "has_inflection" else "d")
               for n in ("length", "sigma", "energy", "has_inflection", "kappa0", "kappa1", "residual")]
    fmt, pos = "=", 0
    for off, code in sorted(fields):
        fmt += f"{off - pos}x{code}" if off > pos else code
        pos = off + struct.calcsize("=" + code)
    size = ffi.sizeof("el_hermite_solution")
    return struct.Struct(fmt + (f"{size - pos}x" if size > pos else "")), size


_SOL_STRUCT, _SOL_SIZE = _solution_struct()


def _solution(row) -> SmoothElastica:
    """A SmoothElastica from one unpacked el_hermite_solution; the library returns
    valid parameters, so the constructor's checks are skipped."""
    x0, y0, phi, mu, k, q, length, _, sigma, energy, infl, kappa0, kappa1, residual = row
    e = SmoothElastica.__new__(SmoothElastica)
    e.__dict__.update(x0=x0, y0=y0, phi=phi, mu=mu, k=k, q=q, length=length, sigma=sigma,
                      energy_value=energy, has_inflection=bool(infl), kappa0=kappa0,
                      kappa1=kappa1, residual=residual)
    return e


def hermite(p0, t0, p1, t1, tension: Optional[float] = None,
            length: Optional[float] = None, *, tol: float = 1e-10,
            samples: int = 12, grid: int = 6, max_solutions: int = 64) -> List[SmoothElastica]:
    """All elastic curves (2 kappa'' + kappa^3 - sigma kappa = 0) from ``p0`` with
    tangent direction ``t0`` to ``p1`` with tangent direction ``t1`` whose length is
    at most one period of the curvature, sorted by bending energy.

    Give exactly one of ``tension`` (sigma, 1/length^2; any real, negative is
    compression) or ``length`` (the arc length; sigma is then computed).

    Returns a :class:`HermiteSolutions` list of :class:`SmoothElastica`; each carries
    extra attributes:

    - ``sigma``: the tension; ``energy_value``: integral of kappa^2 ds;
    - ``has_inflection``: whether the curvature changes sign;
    - ``kappa0``, ``kappa1``: curvature at p0 and p1; ``residual``: end error.

    Every curve runs from ``p0`` (s = 0, tangent ``t0``) to ``p1`` (s = length,
    tangent ``t1``). The sign of ``k`` is the orientation: a loop (``|k| > 1``)
    turns counter-clockwise for ``k > 1`` and clockwise for ``k < -1``. Curves that
    exist but cannot be represented to ``tol`` (high tension, next to the
    separatrix) are counted in the list's ``unrepresentable``, with a RuntimeWarning.

    Raises ``ValueError`` (an :class:`ElasticaError`) for bad input, and
    :class:`DomainError` when ``p0 == p1`` or ``length < |p1 - p0|``.
    """
    if (tension is None) == (length is None):
        raise ValueError("hermite: give exactly one of tension= or length=")
    opt, res, buf = _buffers()
    buf[0:8] = _vec2(p0, "p0") + _vec2(t0, "t0") + _vec2(p1, "p1") + _vec2(t1, "t1")
    if tension is not None:
        opt.mode = lib.EL_HERMITE_TENSION
        opt.sigma = as_real(tension, "hermite: tension")
    else:
        opt.mode = lib.EL_HERMITE_LENGTH
        opt.length = as_real(length, "hermite: length")
    # the options that rarely change are set only when they do
    rest = (as_real(tol, "hermite: tol"), as_int(samples, "hermite: samples"),
            as_int(grid, "hermite: grid"), as_size(max_solutions, "hermite: max_solutions"))
    if rest != getattr(_local, "rest", None):
        opt.tol, opt.samples, opt.grid, opt.max_solutions = rest
        _local.rest = rest
    check(lib.el_hermite_solve(buf, buf + 2, buf + 4, buf + 6, opt, res), "hermite")
    out = HermiteSolutions()
    try:
        n = res.count
        if n:
            raw = ffi.buffer(res.solutions, n * _SOL_SIZE)
            out.extend(_solution(r) for r in _SOL_STRUCT.iter_unpack(raw))
        out.unrepresentable = int(res.unrepresentable)
    finally:
        lib.el_hermite_result_free(res)
    if out.unrepresentable:
        warnings.warn(f"hermite: {out.unrepresentable} more curve(s) exist that no smooth "
                      f"parameters meet to tol={tol:g} (too close to the separatrix |k| = 1); "
                      "a larger tol returns them", RuntimeWarning, stacklevel=2)
    return out


def hermite_analyse(P, V, sigma: float) -> dict:
    """Diagnostics of the normalised tension problem of seed 004 §4-5 (data
    after x(0) = 0, x'(0) = (0, 1), |P| = 1): case of Theorem 6, the kappa_m
    bound, the search intervals (18), the real roots of the polynomial (40)
    with their branch, and the special values (45)."""
    P, V = _vec2(P, "P"), _vec2(V, "V")
    a = ffi.new("el_hermite_analysis *")
    check(lib.el_hermite_analyse(ffi.new("double[2]", list(P)), ffi.new("double[2]", list(V)),
                                 as_real(sigma, "hermite_analyse: sigma"), a), "hermite_analyse")
    return {
        "case": int(a.hcase),
        "kappa_bound": float(a.kappa_bound),
        "intervals": [(a.interval[2 * i], a.interval[2 * i + 1]) for i in range(a.ninterval)],
        "roots": [float(a.root[i]) for i in range(a.nroot)],
        "root_branch": [int(a.root_branch[i]) for i in range(a.nroot)],
        "special": [float(a.special[i]) for i in range(a.nspecial)],
    }
