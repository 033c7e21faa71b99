"""Hermite interpolation by elastic curves (seed 004): every elastica from a
point with a tangent to a point with a tangent, by tension or by length."""
from __future__ import annotations

from typing import List, Optional

import numpy as np

from ._ffi import as_int, as_real, as_size, as_vector, check, ffi, lib
from .core import SmoothElastica

__all__ = ["hermite", "hermite_analyse"]


def _vec2(v, name: str) -> np.ndarray:
    a = as_vector(v, name)
    if a.shape != (2,) or not np.all(np.isfinite(a)):
        raise ValueError(f"{name} must be two finite numbers, got {v!r}")
    return a


def hermite(p0, t0, p1, t1, tension: Optional[float] = None,
            length: Optional[float] = None, *, tol: float = 1e-10,
            samples: int = 12, grid: int = 72, max_solutions: int = 64) -> List[SmoothElastica]:
    """All elastic curves (2 kappa'' + kappa^3 - sigma kappa = 0) from ``p0`` with
    tangent direction ``t0`` to ``p1`` with tangent direction ``t1`` whose length is
    at most one period of the curvature, sorted by bending energy.

    Give exactly one of ``tension`` (sigma, 1/length^2; any real, negative is
    compression) or ``length`` (the arc length; sigma is then computed).

    Returns a list of :class:`SmoothElastica`; each carries extra attributes:

    - ``sigma``: the tension; ``energy_value``: integral of kappa^2 ds;
    - ``has_inflection``: whether the curvature changes sign;
    - ``kappa0``, ``kappa1``: curvature at p0 and p1; ``residual``: end error.

    Every curve runs from ``p0`` (s = 0, tangent ``t0``) to ``p1`` (s = length,
    tangent ``t1``). The sign of ``k`` is the orientation: a loop (``|k| > 1``)
    turns counter-clockwise for ``k > 1`` and clockwise for ``k < -1``.

    Raises ``ValueError`` (an :class:`ElasticaError`) for bad input, and
    :class:`DomainError` when ``p0 == p1`` or ``length < |p1 - p0|``.
    """
    a0, d0, a1, d1 = (_vec2(p0, "p0"), _vec2(t0, "t0"), _vec2(p1, "p1"), _vec2(t1, "t1"))
    if (tension is None) == (length is None):
        raise ValueError("hermite: give exactly one of tension= or length=")
    opt = ffi.new("el_hermite_options *")
    lib.el_hermite_options_defaults(opt)
    if tension is not None:
        opt.mode = lib.EL_HERMITE_TENSION
        opt.sigma = as_real(tension, "hermite: tension")
    else:
        opt.mode = lib.EL_HERMITE_LENGTH
        opt.length = as_real(length, "hermite: length")
    opt.tol = as_real(tol, "hermite: tol")
    opt.samples = as_int(samples, "hermite: samples")
    opt.grid = as_int(grid, "hermite: grid")
    opt.max_solutions = as_size(max_solutions, "hermite: max_solutions")
    res = ffi.new("el_hermite_result *")
    buf = [ffi.new("double[2]", list(v)) for v in (a0, d0, a1, d1)]
    check(lib.el_hermite_solve(buf[0], buf[1], buf[2], buf[3], opt, res), "hermite")
    out = []
    try:
        for i in range(res.count):
            s = res.solutions[i]
            c = s.curve
            e = SmoothElastica(x0=c.x0, y0=c.y0, phi=c.phi, mu=c.mu, k=c.k, q=c.q, length=c.length)
            e.sigma = float(s.sigma)
            e.energy_value = float(s.energy)
            e.has_inflection = bool(s.has_inflection)
            e.kappa0 = float(s.kappa0)
            e.kappa1 = float(s.kappa1)
            e.residual = float(s.residual)
            out.append(e)
    finally:
        lib.el_hermite_result_free(res)
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
