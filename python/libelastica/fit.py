"""Least-squares fairing by elasticae (seed 000 §4) and the keyline pipeline (§5).

>>> import numpy as np, libelastica as el
>>> d = el.DiscreteElastica(x0=1, y0=2, h=0.1, phi=0.3, z=0.08, q=0.2, k=0.7, n=40)
>>> r = el.fit(d.points(), model="discrete")
>>> bool(r.rms < 1e-9)
True
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Mapping, Optional, Union

import numpy as np

from ._ffi import (NotConvergedError, as_int, as_points, as_real, as_real_array, check, dptr, ffi,
                   lib)
from .core import DISCRETE_PARAMS, SMOOTH_PARAMS, DiscreteElastica, SmoothElastica

_MODES = {"auto": 0, "uniform": 1, "chord": 2}
_MODE_NAMES = {v: k for k, v in _MODES.items()}

Curve = Union[DiscreteElastica, SmoothElastica]


@dataclass(frozen=True)
class FitResult:
    """Result of :func:`fit`.

    ``curve``: the fitted elastica (a DiscreteElastica with ``n`` = the number of
    points, or a SmoothElastica); ``initial``: the automatic initial guess the
    kept fit started from; ``rms`` / ``max_error``: distances of the points to
    their model points (input units); ``iterations``: Ipopt iterations (all
    candidates); ``status``: 0 when converged, else the C status (EL_ENOCONV /
    EL_EMAXITER: ``curve`` is the best seen); ``ipopt_status``: Ipopt's return
    code; ``s``: for the smooth model, the arc length of each point on
    ``curve`` (None for discrete); ``param_mode``: "uniform" or "chord".
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

    @property
    def converged(self) -> bool:
        return self.status == lib.EL_OK

    def model_points(self) -> np.ndarray:
        """The model points paired with the data points, shape (n, 2)."""
        if isinstance(self.curve, DiscreteElastica):
            return self.curve.points()
        return self.curve.points(self.s)


def _options(model: str, fixed: Optional[Mapping[str, float]], bounds, tol, max_iter,
             limited_memory, max_candidates, param, initial):
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
    o.use_initial = 1 if initial is not None else 0
    return o


def fit(points, model: str = "discrete", fixed: Optional[Mapping[str, float]] = None, *,
        bounds: Optional[Mapping[str, tuple]] = None, tol: Optional[float] = None,
        max_iter: Optional[int] = None, limited_memory: bool = False,
        max_candidates: Optional[int] = None, param: str = "auto",
        initial: Optional[Curve] = None, strict: bool = False) -> FitResult:
    """Fit an elastica to the points (n, 2), n >= 4, by least squares (seed 000 (4.6)).

    model: "discrete" (vertex i <-> point i) or "smooth" (point i at arc length
    i*length/(n-1) for equilateral data, the chord-length parameter otherwise;
    ``param`` = "auto" | "uniform" | "chord"). fixed: parameters held at given
    values, e.g. ``{"x0": 0, "y0": 0}`` (pinned start, §5.4) or ``{"h": r}``.
    bounds: ``{name: (lo, hi)}`` (None = unbounded). initial: start from this
    curve instead of the automatic guess. A fit that does not converge returns
    the best curve seen with ``status`` != 0 (raises NotConvergedError if
    ``strict``). Bad input (NaN, too few points, all points equal) raises
    ValueError / ElasticaError subclasses.
    """
    if not isinstance(model, str) or model not in ("discrete", "smooth"):
        raise ValueError(f"fit: model must be 'discrete' or 'smooth', got {model!r}")
    pts = as_points(points, "points", 2)
    n = pts.shape[0]
    if n < 4:
        raise ValueError(f"fit: need at least 4 points, got {n}")
    if not np.all(np.isfinite(pts)):
        raise ValueError("fit: points must be finite (no NaN/inf)")
    try:   # options of the wrong shape (not a mapping, bounds not pairs, ...): ValueError
        o = _options(model, fixed, bounds, tol, max_iter, limited_memory, max_candidates, param,
                     initial)
        init = initial._c() if initial is not None else ffi.NULL
    except (TypeError, AttributeError) as exc:
        raise ValueError(f"fit: invalid option ({exc})") from None
    smooth = model == "smooth"
    res = ffi.new(f"el_fit_{model}_result *")
    st = (lib.el_fit_smooth if smooth else lib.el_fit_discrete)(dptr(pts), n, o, init, res)
    if st not in (lib.EL_OK, lib.EL_ENOCONV, lib.EL_EMAXITER):
        check(st, "fit")
    if smooth:
        def mk(p):
            return SmoothElastica(**{k: getattr(p, k) for k in SMOOTH_PARAMS})
        t = np.empty(n)
        check(lib.el_fit_fractions(dptr(pts), n, res.param_mode, dptr(t), ffi.NULL), "fit")
        s = t * res.params.length
        mode = _MODE_NAMES[res.param_mode]
    else:
        def mk(p):
            return DiscreteElastica(**{k: getattr(p, k) for k in DISCRETE_PARAMS}, n=n)
        s, mode = None, None
    if strict and st != lib.EL_OK:
        check(st, "fit")
    return FitResult(curve=mk(res.params), initial=mk(res.initial), rms=float(res.rms),
                     max_error=float(res.max_error), iterations=int(res.iterations),
                     status=int(st), ipopt_status=int(res.ipopt_status),
                     candidates=int(res.candidates), s=s, param_mode=mode)


@dataclass(frozen=True)
class KeylineFit:
    """Result of :func:`fit_keyline`: the prepared keyline (``prepared``, a
    PreparedKeyline: polygon in x''y'' coordinates, frames), the inflection
    vertex ``inflection`` (index into ``prepared.polygon``; refined, see
    :func:`fit_keyline`) and the fits of the two sides, each starting at the
    inflection: ``first`` (inflection -> first vertex) and ``second``
    (inflection -> last vertex), in x''y'' coordinates. ``inflection_estimate``:
    the RDP-style estimate of the preparation (``prepared.inflection``) the
    refinement started from."""
    prepared: object
    inflection: int
    first: FitResult
    second: FitResult
    inflection_estimate: Optional[int] = None

    def side_points(self, which: str = "second", input_coords: bool = True) -> np.ndarray:
        """The fitted model points of one side, in the input's coordinates (3D for
        3D input) or in x''y''."""
        r = self.first if which == "first" else self.second
        pts = r.model_points()
        return self.prepared.to_input(pts) if input_coords else pts


def _curvature_zero(res: FitResult, m: int) -> Optional[float]:
    """The zero of the fitted curve's curvature nearest its start, in units of
    the point spacing (vertex offsets from the start, negative = before it: the
    curve extended), searched within +-m; None when there is none there."""
    c = res.curve
    if isinstance(c, DiscreteElastica):
        # kappa_n depends on (h, z, q, k) only: vertex j of the curve extended by
        # m + 1 vertices at each end is vertex j - (m + 1) of c
        ext = DiscreteElastica(x0=0.0, y0=0.0, h=c.h, phi=c.phi, z=c.z, q=c.q - (m + 1) * c.z,
                               k=c.k, n=c.n + 2 * m + 2)
        kap = ext.curvature()                     # interior vertices 1 .. n' - 2
        j = np.arange(1, ext.n - 1, dtype=float) - (m + 1)
        sel = np.abs(j) <= m
        j, kap = j[sel], kap[sel]
    else:
        ds = c.length / (len(res.s) - 1)
        j = np.linspace(-m, m, 8 * m + 1)
        kap = c.curvature(j * ds)
    idx = np.nonzero(kap[1:] * kap[:-1] <= 0.0)[0]
    if len(idx) == 0:
        return None
    zs = [j[a] if kap[a + 1] == kap[a] else j[a] - kap[a] * (j[a + 1] - j[a]) / (kap[a + 1] - kap[a])
          for a in idx]
    return float(min(zs, key=abs))


def _refine_inflection(poly: np.ndarray, i0: int, model: str, r: float, fixed: dict,
                       kwargs: dict, iterations: int = 4) -> int:
    """Move the split vertex to where the fitted elasticae have their inflection.

    The RDP-style estimate (prep.c) is noisy (tens of segments at 0.1 % noise),
    and the total residual of the two pinned fits is nearly flat in the split
    (an inflectional elastica fits either side of its own inflection; for data
    that are one elastica it is exactly flat), so it cannot locate the
    inflection. The fitted curvature can: each side is fitted without the pin
    (the noise of the pinned vertex would tilt the curvature near it), the
    zeros of both curves' curvature nearest the split (the curves extended
    beyond it) estimate the inflection, and their mean, rounded to a vertex,
    is the next split; repeated until it stays (at most ``iterations`` times).
    The split moves at most a quarter of the polygon and keeps >= 4 vertices a side.
    """
    n = len(poly)
    m = max(4, n // 4)
    free = {k: v for k, v in fixed.items() if k not in ("x0", "y0")}
    i = i0
    for _ in range(iterations):
        est = []
        for sgn, side in ((-1, poly[i::-1]), (1, poly[i:])):
            res = fit(side, model=model, fixed=free, **kwargs)
            d = _curvature_zero(res, m)
            if d is not None:
                est.append(i + sgn * d)
        if not est:
            break
        inew = int(np.clip(round(float(np.mean(est))), max(3, i0 - m), min(n - 4, i0 + m)))
        if inew == i:
            break
        i = inew
    return i


def fit_keyline(points, r: Optional[float] = None, model: str = "discrete", side: int = 0,
                refine: bool = True, **kwargs) -> KeylineFit:
    """Seed 000 §5.3–5.4: plane fit (3D input), equilateral resampling with
    segment ``r`` (default: 1/100 of the polyline's length), PCA
    re-normalisation, the inflection estimate, then one elastica per side with
    (x0, y0) pinned at the inflection vertex (and h = r for the discrete model).
    ``refine`` (default): the split vertex is first moved to where the fitted
    elasticae of both sides have zero curvature (see ``_refine_inflection``;
    a few more fits), which is much closer to the true inflection than the
    RDP-style estimate on noisy data. Raises DomainError when no inflection is
    found. Extra keyword arguments go to :func:`fit` (``fixed`` to both sides;
    its values win over the pinning)."""
    from .prep import prepare_keyline
    pts = as_real_array(points, "fit_keyline: points")
    if pts.ndim != 2 or pts.shape[1] not in (2, 3) or len(pts) < 4:
        raise ValueError("fit_keyline: points must have shape (n, 2) or (n, 3), n >= 4")
    if not np.all(np.isfinite(pts)):
        raise ValueError("fit_keyline: points must be finite (no NaN/inf)")
    if r is None:
        r = float(np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1))) / 100.0
    prep = prepare_keyline(pts, r, side)
    a, b = prep.sides()
    if len(a) < 4 or len(b) < 4:
        raise ValueError("fit_keyline: a side of the inflection has fewer than 4 vertices")
    user_fixed = dict(kwargs.pop("fixed", None) or {})     # once, for both sides
    base = {"h": float(r)} if model == "discrete" else {}
    base.update(user_fixed)
    poly = prep.polygon
    i0 = int(prep.inflection)
    i = _refine_inflection(poly, i0, model, float(r), base, kwargs) if refine else i0
    fits = []
    for side_poly in (poly[i::-1], poly[i:]):
        fixed = {"x0": side_poly[0, 0], "y0": side_poly[0, 1]}
        fixed.update(base)                # the caller's values win
        fits.append(fit(side_poly, model=model, fixed=fixed, **kwargs))
    return KeylineFit(prepared=prep, inflection=i, first=fits[0], second=fits[1],
                      inflection_estimate=i0)


__all__ = ["FitResult", "KeylineFit", "fit", "fit_keyline", "NotConvergedError"]
