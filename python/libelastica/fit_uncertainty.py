"""How well a fit determines its numbers: the parameters' covariance and standard errors
at the solution (Gauss-Newton, as scipy's ``curve_fit`` pcov and lmfit's ``stderr``), and
those of the quantities a scientist reads off the curve, by the delta method.

Residuals (what :func:`libelastica.fit` minimised):

- orthogonal fits: each point's distance to the curve, r_i = e_i . (p_i - gamma(s_i)), e_i
  the unit normal at its foot. Its derivative in the parameters is -e_i . d gamma(s_i)/d p
  with the foot held: first order exact, since at an orthogonal foot the tangential part,
  (e_i . T) d s_i / d p, is zero. A foot clamped to an end of the curve (a point beyond it),
  or on a corner of the discrete polygon, is not orthogonal: there e_i is the direction
  from the foot to the point and the foot stays at the end (s = length moves with the
  length: the Jacobian's length column at t = s/length = 1 is the end tangent).
  A smooth orthogonal fit's curve is trimmed to the least and greatest feet (fit_ends.c, the
  points p_a, p_b they belong to; often the first and last): two
  conditions, (p_a - gamma(0)) . T(0) = 0 and (p_b - gamma(L)) . T(L) = 0, held as
  constraints below (they fix where the curve starts along itself, x0, y0 with q, and its
  length, which no distance sees).
  The discrete polygon's first and last vertices are tied to the first and last points by the
  full vectors V_0 - p_0, V_n-1 - p_n-1 (fit_objective.c): 2 residuals each, n + 2 in all.
- paired fits: the vector p_i - gamma(s_i) (smooth: s_i = t_i length, t_i held) or
  p_i - vertex_i (discrete, seed 000 (4.6)): 2 residuals per point.

The trimming conditions hold each end's point exactly along the curve: its noise along the
curve (variance s^2, as across it) moves the ends, added to the covariance by the constrained
least-squares step it makes (the length's standard error is mostly that).

s^2 = RSS / (N - p): N the residuals of the points the fit fitted (``r.points``, unweighted,
as :func:`fit` weighs none: n, n + 2 for the discrete polygon by distance, or 2n paired; a
keyline side's resampled polygon: its vertices, medians of runs of the scan, whose scatter
their own s^2 measures); p the parameters the fit
really had: 7 less the fixed ones, the active constraints (held end points, tangents,
curvatures, an exact length, a range's bound reached) and the trimming above. The covariance is
s^2 Z (Z' J' J Z)^-1 Z' (plus the trimming's term) with Z a basis of the null space of the
active constraints' gradients (a held end tangent has zero variance, a fixed parameter zero).
Directions the points do not determine (the reduced Jacobian's condition beyond 1 / RCOND
after scaling its columns) are not inverted: the parameters and derived quantities that move
along them get an infinite standard error and ``note`` says why; so do the bend's (phi, mu, k,
q, the force) where the points show no bend beyond their noise (:func:`_straight`: near k = 0
the linearisation no longer holds and a noisy line read mu = 1.48 +- 0.22).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, Mapping, Optional, Tuple

import numpy as np

from ._ffi import DomainError, check, ffi, lib
from .core import DISCRETE_PARAMS, SMOOTH_PARAMS, DiscreteElastica, SmoothElastica

RCOND = 1e-8      # column-scaled reduced Jacobian: singular values below RCOND x the largest undetermined
_NULL_TOL = 1e-6  # a (scaled) parameter's component in such a direction above this: it moves along it
STRAIGHT_CHI2 = 16.27   # chi-square's 99.9 % quantile at 3 degrees of freedom (no scipy in the library)
_BEND_PARAMS = ("phi", "mu", "k", "q")
_SIZES = ("mu", "k", "z", "h", "length", "energy")
_FD_STEP = 1e-6   # relative step of the central differences below


@dataclass(frozen=True)
class FitUncertainty:
    """The uncertainty of a :class:`libelastica.FitResult` (:meth:`FitResult.uncertainty`).

    ``names``: the curve's parameters in ``curve.params`` order (smooth: x0, y0, phi, mu, k,
    q, length; discrete: x0, y0, h, phi, z, q, k); ``values``: theirs; ``covariance``: (7, 7),
    as scipy's pcov (rows and columns of undetermined parameters inf; fixed and constrained
    directions 0); ``stderr``: (7,), sqrt of its diagonal; ``s2``: RSS / ``dof``, the residual
    variance (NaN where dof <= 0); ``dof``: residuals - fitted parameters; ``n_residuals``;
    ``rank``: the parameters the points determine; ``condition``: the column-scaled reduced
    Jacobian's condition number; ``note``: '' or why some standard errors are inf / NaN;
    ``derived``: {name: (value, stderr)} of what :func:`derived_quantities` computes
    (smooth: length, energy, force_x, force_y, start_curvature, end_curvature; discrete:
    length, start_curvature, end_curvature); ``gradients``: {name: d value / d params}."""
    names: Tuple[str, ...]
    values: np.ndarray
    covariance: np.ndarray
    stderr: np.ndarray
    s2: float
    dof: int
    n_residuals: int
    rank: int
    condition: float
    note: str
    derived: Dict[str, Tuple[float, float]]
    gradients: Dict[str, np.ndarray]

    def as_dict(self) -> Dict[str, float]:
        """{name: standard error} of the parameters and the derived quantities."""
        out = {n: float(v) for n, v in zip(self.names, self.stderr)}
        out.update({n: float(se) for n, (_, se) in self.derived.items()})
        return out

    def undetermined(self, ratio: float = 1.0) -> Tuple[str, ...]:
        """Names (parameters, then derived quantities) whose standard error is inf / NaN, or
        of a size (mu, k, z, h, length, energy; not a place or an angle) at least ``ratio``
        times the value's (default 1: not even the sign is known, e.g. a gentle bend's mu,
        the tension)."""
        vals = dict(zip(self.names, self.values))
        vals.update({n: v for n, (v, _) in self.derived.items()})
        ses = self.as_dict()
        return tuple(n for n in ses if not np.isfinite(ses[n]) or (
            n in _SIZES and not ses[n] < ratio * abs(vals[n])))


def _central(fun, curve, i: int, scale: float) -> np.ndarray:
    """d fun(curve) / d param i by a central difference of step _FD_STEP x scale (one-sided
    where the other side is outside the parameter's domain, e.g. mu < 0)."""
    names = SMOOTH_PARAMS if isinstance(curve, SmoothElastica) else DISCRETE_PARAMS
    kind = type(curve)
    base = {n: getattr(curve, n) for n in names}
    if kind is DiscreteElastica:
        base["n"] = curve.n
    h = _FD_STEP * scale

    def at(v):
        return np.asarray(fun(kind(**dict(base, **{names[i]: v}))), dtype=float)

    v0 = base[names[i]]
    try:
        lo = at(v0 - h)
    except (ValueError, DomainError):
        return (at(v0 + h) - np.asarray(fun(curve), dtype=float)) / h
    return (at(v0 + h) - lo) / (2 * h)


def _scales(curve) -> np.ndarray:
    """Each parameter's size for the difference steps (lengths the curve's length)."""
    L = max(curve.length, 1e-300)
    if isinstance(curve, SmoothElastica):
        return np.array([L, L, 1.0, max(abs(curve.mu), 1.0 / L ** 2), max(abs(curve.k), 1e-2),
                         1.0, L])
    return np.array([L, L, max(abs(curve.h), 1e-300), 1.0, max(abs(curve.z), 1e-3), 1.0,
                     max(abs(curve.k), 1e-2)])


def gradient(fun, curve) -> np.ndarray:
    """d fun(curve) / d params (7,) or (7, m) by central differences: the library has no
    parameter derivative of the discrete model's tangent angle or curvature (el_discrete_jacobian
    gives the vertices' only), so they are taken from its exact evaluators; the smooth model's
    are analytic (:func:`end_gradients`), checked against these in test_fit_uncertainty."""
    sc = _scales(curve)
    return np.array([_central(fun, curve, i, sc[i]) for i in range(7)])


def _end_value(kind: str, end: int):
    """fun(curve) -> the tangent angle ('angle') or curvature at the start (0) / end (1)."""
    def fun(c):
        if isinstance(c, SmoothElastica):
            s = np.array([0.0 if end == 0 else c.length])
            return (c.angle(s) if kind == "angle" else c.curvature(s))[0]
        # the three vertices at that end (theta_i and the curvature there depend on z i + q
        # alone, seed 000 (4.4)): O(1) for a polygon of any size
        p = {n: getattr(c, n) for n in DISCRETE_PARAMS}
        if end:
            p["q"] = c.q + c.z * (c.n - 3)
        e = DiscreteElastica(**p, n=3) if c.n > 3 else c
        v = e.angle() if kind == "angle" else e.vertex_curvature()
        return v[0 if end == 0 else -1]
    return fun


def end_gradients(c: SmoothElastica, end: int) -> Tuple[np.ndarray, np.ndarray]:
    """d theta / d params and d kappa / d params (7,) of curve ``c`` at its start (end 0) or end (1,
    s = length moving with it, as the Jacobian's length column), analytic from seed 000 (4.3)
    and el_jacobi_eval's u- and k-derivatives: u = sqrt(mu) s + q, theta - phi =
    2 atan2(k sn, dn), d theta/du = 2 k cn, kappa = 2 k sqrt(mu) cn; sn, cn, dn depend on k^2
    (el_jacobi_eval takes |k|). mu = 0 (no u-dependence left): central differences."""
    if not c.mu > 0:
        return (gradient(_end_value("angle", end), c), gradient(_end_value("curvature", end), c))
    rm = math.sqrt(c.mu)
    s = c.length if end else 0.0
    k, ka = c.k, abs(c.k)
    sg = -1.0 if c.k < 0 else 1.0
    val, du, dk = (ffi.new("el_jacobi *") for _ in range(3))
    check(lib.el_jacobi_eval(rm * s + c.q, ka, val, du, dk), "fit_uncertainty")
    sn, cn, dn = val.sn, val.cn, val.dn
    th_u = 2 * k * cn
    th_k = 2 * (dn * (sn + k * sg * dk.sn) - k * sn * sg * dk.dn) / (k * k * sn * sn + dn * dn)
    kap = 2 * k * rm * cn
    ka_u = 2 * k * rm * du.cn
    ka_k = 2 * rm * (cn + k * sg * dk.cn)
    L = rm if end else 0.0
    g_th = np.array([0, 0, 1, th_u * s / (2 * rm), th_k, th_u, th_u * L])
    g_ka = np.array([0, 0, 0, kap / (2 * c.mu) + ka_u * s / (2 * rm), ka_k, ka_u, ka_u * L])
    return g_th, g_ka


def energy_gradient(c: SmoothElastica) -> np.ndarray:
    """d E / d (x0, y0, phi, mu, k, q, length) of curve ``c``'s E = int_0^L kappa^2 ds
    = 4 k^2 sqrt(mu) int_q^(q + sqrt(mu) L) cn^2 du (kappa = 2 k sqrt(mu) cn, seed 000 (4.3)):
    dE/dL = kappa(L)^2, dE/dq = (kappa(L)^2 - kappa(0)^2) / sqrt(mu), dE/dmu = E / (2 mu) +
    L kappa(L)^2 / (2 mu); dE/dk by a central difference of el_smooth_energy's closed form
    (the library has no d/dk of its energy)."""
    k0, kL = c.curvature(np.array([0.0, c.length]))
    E = c.energy()
    g = np.zeros(7)
    g[6] = kL ** 2
    if c.mu > 0:
        g[5] = (kL ** 2 - k0 ** 2) / math.sqrt(c.mu)
        g[3] = E / (2 * c.mu) + c.length * kL ** 2 / (2 * c.mu)
    else:
        g[3] = _central(lambda x: x.energy(), c, 3, _scales(c)[3])
    g[4] = _central(lambda x: x.energy(), c, 4, _scales(c)[4])
    return g


def derived_quantities(curve) -> Dict[str, Tuple[float, np.ndarray]]:
    """{name: (value, d value / d params)} of what a scientist reads off the curve: length;
    smooth: the bending energy int kappa^2 ds, the load (force) vector mu (cos phi, sin phi)
    (per unit bending stiffness; theta'' = -mu sin(theta - phi), mu the tension), the end
    curvatures; discrete: length (n - 1) h and the end vertices' curvature
    (:meth:`DiscreteElastica.vertex_curvature`)."""
    out = {}
    e = np.zeros(7)
    if isinstance(curve, SmoothElastica):
        e[6] = 1.0
        out["length"] = (curve.length, e)
        out["energy"] = (curve.energy(), energy_gradient(curve))
        cp, sp = math.cos(curve.phi), math.sin(curve.phi)
        gx, gy = np.zeros(7), np.zeros(7)
        gx[3], gx[2] = cp, -curve.mu * sp
        gy[3], gy[2] = sp, curve.mu * cp
        out["force_x"] = (curve.mu * cp, gx)
        out["force_y"] = (curve.mu * sp, gy)
    else:
        e[2] = curve.n - 1.0
        out["length"] = (curve.length, e)
    for end, name in ((0, "start_curvature"), (1, "end_curvature")):
        f = _end_value("curvature", end)
        g = end_gradients(curve, end)[1] if isinstance(curve, SmoothElastica) else gradient(f, curve)
        out[name] = (float(f(curve)), g)
    return out


def _beyond_end(c: SmoothElastica, P: np.ndarray, end: int) -> bool:
    """Whether point P lies off curve c's start (end 0) / end (1) along its tangent there: the
    curve is not trimmed to its foot (a point beyond the end: its residual holds the end)."""
    s = np.array([0.0 if end == 0 else c.length])
    th = float(c.angle(s)[0])
    off = P - c.points(s)[0]
    return abs(off[0] * math.cos(th) + off[1] * math.sin(th)) > 1e-6 * max(c.length, 1e-300)


def _residual_jacobian(r) -> Tuple[np.ndarray, float]:
    """(J, RSS): d residual / d params (N, 7) at the solution, and the residuals' sum of squares."""
    c, P = r.curve, r.points
    smooth = isinstance(c, SmoothElastica)
    if r.distance != "orthogonal":
        if smooth:
            J, G = c.jacobian(r.s), c.points(r.s)
        else:
            J, G = c.jacobian(), c.points()
        return -J.reshape(-1, 7), float(np.sum((P - G) ** 2))
    if smooth:
        s = np.clip(r.foot_s, 0.0, c.length)
        J, G, th = c.jacobian(s), c.points(s), c.angle(s)
        nrm = np.column_stack([-np.sin(th), np.cos(th)])
        at_end = (s <= 1e-9 * c.length) | (s >= (1 - 1e-9) * c.length)   # (a foot 1 ulp short: there)
    else:
        Jv, V = c.jacobian(), c.points()
        t = r.foot_s / c.h
        j = np.clip(np.floor(t).astype(np.intp), 0, c.n - 2)
        t = np.clip(t - j, 0.0, 1.0)
        J = (1 - t)[:, None, None] * Jv[j] + t[:, None, None] * Jv[j + 1]
        G = (1 - t)[:, None] * V[j] + t[:, None] * V[j + 1]
        d = V[j + 1] - V[j]
        nrm = np.column_stack([-d[:, 1], d[:, 0]]) / np.maximum(np.hypot(d[:, 0], d[:, 1]), 1e-300)[:, None]
        at_end = (t <= 1e-9) | (t >= 1 - 1e-9)     # a foot on a vertex: a corner or an end
    off = P - G
    dist = np.hypot(off[:, 0], off[:, 1])
    clamp = at_end & (dist > 0)
    e = nrm.copy()
    e[clamp] = off[clamp] / dist[clamp, None]
    rows = -np.einsum("ic,icj->ij", e, J)
    if smooth or len(P) < 3:
        return rows, float(np.sum(np.asarray(r.distances) ** 2))
    # the discrete fit ties its end vertices to the first and last points by the full vectors
    # V_0 - P_0, V_n-1 - P_n-1 (fit_objective.c discrete_orthogonal; 2 residuals each, their
    # part along the polygon the only one that sees its length and start), the others by distance
    ends = np.r_[V[0] - P[0], V[-1] - P[-1]]
    return (np.vstack([-Jv[0], rows[1:-1], -Jv[-1]]),
            float(np.sum(dist[1:-1] ** 2) + np.sum(ends ** 2)))


def _constraint_rows(r, fixed: Optional[Mapping[str, float]]) -> Tuple[np.ndarray, list]:
    """Gradients (m, 7) of the conditions the fit held, and their names."""
    c = r.curve
    smooth = isinstance(c, SmoothElastica)
    names = SMOOTH_PARAMS if smooth else DISCRETE_PARAMS
    rows, why = [], []

    def unit(name):
        e = np.zeros(7)
        e[names.index(name)] = 1.0
        return e

    for n in (fixed or {}):
        if n in names:
            rows.append(unit(n)), why.append(f"fixed {n}")
    con = dict(r.constraints or {})
    if "start_point" in con:
        rows += [unit("x0"), unit("y0")]
        why += ["start_point"] * 2
    if "end_point" in con:
        Je = c.jacobian(np.array([c.length]))[0] if smooth else c.jacobian()[-1]
        rows += list(Je)
        why += ["end_point"] * 2
    for key, kind, end in (("start_tangent", "angle", 0), ("end_tangent", "angle", 1),
                           ("start_curvature", "curvature", 0), ("end_curvature", "curvature", 1)):
        if key in con:
            rows.append(end_gradients(c, end)[kind == "curvature"] if smooth else
                        gradient(_end_value(kind, end), c)), why.append(key)
    for key in ("length", "k"):
        if key not in con:
            continue
        lim = con[key]
        lo, hi = (lim, lim) if np.isscalar(lim) else lim
        val = c.length if key == "length" else c.k
        g = (unit("length") if smooth else unit("h")) if key == "length" else unit("k")
        tol = 1e-9 * max(abs(val), 1.0)
        if any(b is not None and abs(val - float(b)) <= tol for b in (lo, hi)):
            rows.append(g), why.append(key)
    if smooth and r.distance == "orthogonal":
        held_start = "start_point" in con or {"x0", "y0"} <= set(fixed or {})
        held_end = "end_point" in con or "length" in why or "length" in (fixed or {})
        for end, held in ((0, held_start), (1, held_end)):
            if held:
                continue
            s = 0.0 if end == 0 else c.length
            # fit_ends.c el__fit_trim_to_feet cuts the curve to the least and greatest feet,
            # whichever points they are (an uneven scan's second point may lie before its first)
            P = r.points[int(np.argmin(r.foot_s) if end == 0 else np.argmax(r.foot_s))]
            G, th = c.points(np.array([s]))[0], float(c.angle(np.array([s]))[0])
            T, N = np.array([math.cos(th), math.sin(th)]), np.array([-math.sin(th), math.cos(th)])
            if _beyond_end(c, P, end):
                continue          # the point lies beyond the end: its residual holds the end
            Je = c.jacobian(np.array([s]))[0]
            rows.append(-T @ Je + np.dot(P - G, N) * end_gradients(c, end)[0])
            why.append("trimmed to the first foot" if end == 0 else "trimmed to the last foot")
    return (np.array(rows) if rows else np.zeros((0, 7))), why


def _singular(B: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """B's singular values (descending) and right singular vectors (rows): from the Gram
    matrix B'B (0.9 ms for 20000 x 7, where numpy's SVD took 20) where its condition is below
    1e12 (B's 1e6: 4 digits of 16 lost at most), else from the SVD of B's R factor (QR)."""
    w, V = np.linalg.eigh(B.T @ B)
    if w[0] > 1e-12 * w[-1]:
        return np.sqrt(w[::-1]), V[:, ::-1].T
    _, S, Vt = np.linalg.svd(np.linalg.qr(B, mode="r"))
    return np.r_[S, np.zeros(B.shape[1] - len(S))], Vt     # (fewer rows than columns: zeros)


def _straight(r, rss: float, s2: float) -> Optional[str]:
    """Why the bend's parameters mean nothing, where the points show no bend beyond their
    noise: the straight line nearest them (total least squares, numpy's eigh of their scatter)
    leaves an RSS within STRAIGHT_CHI2 s^2 of the fit's (a chi-square test of the elastica's 3
    parameters more than a line's, 5 against 2 once both are trimmed to the end points' feet),
    else None. There k -> 0 and mu, q, phi drop out of the curve (k = 0: gamma no longer depends
    on them; near it the linearisation holds no more: a noisy line fitted k = 4.6e-4, mu
    1.48 +- 0.22 by it)."""
    if r.distance != "orthogonal" or not np.isfinite(s2) or s2 <= 0:
        return None
    P = r.points - r.points.mean(axis=0)
    # (eigh's least eigenvalue of exactly collinear points may round below 0, and the line
    # can be no worse than the fit there: said as 0, not as -9.71e+06 s^2, revC 2)
    rss_line = max(0.0, float(np.linalg.eigh(P.T @ P)[0][0]))
    excess = max(0.0, (rss_line - rss) / s2)
    if excess >= STRAIGHT_CHI2:
        return None
    return (f"the points show no bend beyond their noise (a straight line's RSS only {excess:.3g} s^2 "
            f"above the fit's, < {STRAIGHT_CHI2}): phi, mu, k, q and the force undetermined, inf")


def fit_uncertainty(r, fixed: Optional[Mapping[str, float]] = None) -> FitUncertainty:
    """The :class:`FitUncertainty` of FitResult ``r`` (module docstring: the method);
    ``fixed``: the parameters the fit held (default: ``r.fixed``, what :func:`fit` was given)."""
    if r.points is None or r.distances is None:
        raise ValueError("fit_uncertainty: the result has no points / distances to judge it by")
    c = r.curve
    names = SMOOTH_PARAMS if isinstance(c, SmoothElastica) else DISCRETE_PARAMS
    fixed = getattr(r, "fixed", None) if fixed is None else fixed
    J, rss = _residual_jacobian(r)
    A, why = _constraint_rows(r, fixed)
    trim = np.array([w.startswith("trimmed") for w in why], dtype=bool)
    if len(A):
        # the null space of the held conditions' gradients, each row scaled to unit length
        An = A / np.maximum(np.linalg.norm(A, axis=1), 1e-300)[:, None]
        _, sa, vt = np.linalg.svd(An)
        m = int(np.sum(sa > 1e-10 * sa[0]))
        Z = vt[m:].T
    else:
        Z = np.eye(7)
    colnorm = np.linalg.norm(J, axis=0)
    cs = np.where(colnorm > 0, colnorm, 1.0)       # parameters in units of their effect
    note = []
    N = J.shape[0]
    cov = np.zeros((7, 7))
    undet = np.zeros(7, dtype=bool)
    nulls = np.zeros((0, 7))
    rank, cond = 0, 1.0
    if Z.shape[1]:
        B = J @ Z
        d = np.linalg.norm(B, axis=0)
        d = np.where(d > 0, d, 1.0)
        S, Vt = _singular(B / d)
        keep = S > RCOND * S[0] if S[0] > 0 else np.zeros(len(S), dtype=bool)
        rank = int(np.sum(keep))
        cond = float(S[0] / S[-1]) if S[-1] > 0 else math.inf
        W = (Vt[keep].T / S[keep]) / d[:, None]   # reduced coords -> Z: B+ = W W' (scaled back)
        W = Z @ W
        cov = W @ W.T
        nulls = (Z @ (Vt[~keep].T / d[:, None])).T * cs    # undetermined directions, scaled params
        if len(nulls):
            nulls /= np.linalg.norm(nulls, axis=1)[:, None]
            undet = np.any(np.abs(nulls) > _NULL_TOL, axis=0)
            note.append(f"{', '.join(n for n, u in zip(names, undet) if u)} undetermined by the points "
                        f"(rank {rank} of {Z.shape[1]}, condition {cond:.3g} > 1/RCOND): their "
                        "standard errors are inf")
    dof = N - rank
    if dof > 0:
        s2 = rss / dof
    else:
        s2 = math.nan
        npts = len(r.points)
        why = (f"{npts} points give {N} residuals" + (", the end points 2 each," if N == npts + 2
                                                     else "") + f" for {rank} parameters")
        note.append(f"no degrees of freedom left ({why}): no standard errors (NaN)")
    if trim.any() and Z.shape[1]:
        # the trimming conditions hold the end points' feet at the curve's ends: their
        # tangential noise (variance s^2, as across) moves the solution by the constrained
        # least-squares step Q A+ eps, Q = I - cov0 J'J (A delta = eps, the rest refitted)
        Q = np.eye(7) - cov @ (J.T @ J)
        Ap = np.linalg.pinv(A)[:, trim]
        cov = cov + (Q @ Ap) @ (Q @ Ap).T
    cov = cov * s2
    held = [names.index(n) for n in (fixed or {}) if n in names]
    cov[held, :] = 0.0            # exactly: a fixed parameter has no variance
    cov[:, held] = 0.0
    cov[undet, :] = math.inf
    cov[:, undet] = math.inf
    straight = _straight(r, rss, s2) if isinstance(c, SmoothElastica) else None
    if straight is not None:
        flat = np.array([n in _BEND_PARAMS for n in names])
        undet |= flat
        cov[flat, :] = math.inf
        cov[:, flat] = math.inf
        note.append(straight)
    se = np.sqrt(np.diag(cov))
    derived, grads = {}, {}
    for name, (val, g) in derived_quantities(c).items():
        grads[name] = g
        gs = g / cs
        if straight is not None and name in ("force_x", "force_y"):
            sd = math.inf
        elif len(nulls) and np.any(np.abs(nulls @ gs) > _NULL_TOL * max(np.linalg.norm(gs), 1e-300)):
            sd = math.inf
        else:
            fin = ~undet
            sd = float(np.sqrt(max(g[fin] @ cov[np.ix_(fin, fin)] @ g[fin], 0.0)))
        derived[name] = (float(val), sd)
    return FitUncertainty(names=tuple(names), values=c.params, covariance=cov, stderr=se,
                          s2=float(s2), dof=int(dof), n_residuals=int(N), rank=rank,
                          condition=cond, note="; ".join(note), derived=derived, gradients=grads)


class Uncertain:
    """FitResult's methods for its uncertainty (fit_uncertainty.py)."""

    def uncertainty(self, fixed: Optional[Mapping[str, float]] = None) -> FitUncertainty:
        """The parameters' covariance and standard errors at the solution and those of the
        derived quantities (:class:`FitUncertainty`; method: :mod:`libelastica.fit_uncertainty`);
        ``fixed``: the parameters held (default those the fit was given)."""
        return fit_uncertainty(self, fixed)

    @property
    def covariance(self) -> np.ndarray:
        """The parameters' covariance (7, 7) in ``curve.params`` order, as scipy's pcov:
        ``uncertainty().covariance``."""
        return self.uncertainty().covariance

    @property
    def stderr(self) -> Dict[str, float]:
        """{name: standard error} of the curve's parameters and the derived quantities
        (length, energy, force_x, force_y, start_curvature, end_curvature):
        ``uncertainty().as_dict()``; inf where the points do not determine it."""
        return self.uncertainty().as_dict()


__all__ = ["FitUncertainty", "fit_uncertainty", "derived_quantities", "RCOND", "STRAIGHT_CHI2"]
