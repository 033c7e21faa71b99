"""Affine arc-length polylines and curvature-continuous quadratic B-splines (seed 002).

A polyline x_0..x_N with A_i = det(x_i - x_{i-1}, x_{i+1} - x_i) constant is an
*affine arc-length polyline*; exactly then the uniform quadratic B-spline with
that control polygon has continuous curvature (G2). This module wraps
libelastica/affine.c and affine_polyline.c: polyline coordinates, discrete affine curvature,
osculating conics, Chaikin / Lane–Riesenfeld refinement, the R^n affine length,
uniform B-splines of such polygons, and the approximation algorithm of §4
(:func:`affine_polyline`) for a :class:`SmoothElastica` or point data, and
:func:`g2_quadratic`: a curve -> one G2 quadratic B-spline per inflection-free
piece, ending exactly on the curve's ends and inflections.
"""
from __future__ import annotations

import dataclasses
import math
import warnings
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

import numpy as np

from ._ffi import (DomainError, as_int, as_points, as_real, as_real_array, as_size, as_vector,
                   bspline_from_c, check, dptr, ffi, invalid, lib, require)

__all__ = ["affine_coords", "affine_length", "affine_curvature", "osculating_conics",
           "OsculatingConics", "chaikin", "lane_riesenfeld", "affine_elements",
           "uniform_bspline", "quadratic_bspline", "parabolic_lengths", "AffinePolyline",
           "affine_polyline", "affine_curvature_exact", "elastica_affine_curvature",
           "elastica_inflections", "g2_bspline", "quadratic_joint_curvatures", "G2Quadratic",
           "CoverageWarning", "g2_quadratic"]

_KINDS = {"outer": 0, "inner": 1, "middle": 2}


def _pts(points, minimum: int, dim: int = 2) -> np.ndarray:
    arr = as_points(points, "polyline", dim)
    if len(arr) < minimum:
        raise ValueError(f"polyline needs at least {minimum} vertices, got {len(arr)}")
    return arr


def affine_coords(polyline) -> tuple[np.ndarray, np.ndarray]:
    """Affine polyline coordinates (1): A_i = det(v_{i-1}, v_i) (i = 1..N-1) and
    B_i = det(v_{i-1}, v_{i+1}) (i = 1..N-2), v_i = x_{i+1} - x_i."""
    x = _pts(polyline, 3)
    A = np.empty(len(x) - 2)
    B = np.empty(max(len(x) - 3, 0))
    check(lib.el_affine_coords(len(x), dptr(x), dptr(A), dptr(B) if len(B) else ffi.NULL),
          "affine_coords")
    return A, B


def affine_length(polyline) -> float:
    """Affine length L2 = sum cbrt(A_i) (3)."""
    x = _pts(polyline, 3)
    out = ffi.new("double *")
    check(lib.el_affine_length(len(x), dptr(x), out), "affine_length")
    return float(out[0])


def affine_curvature(polyline) -> np.ndarray:
    """Discrete affine curvatures k_i = det(n_i, n_{i+1}) / A (4), i = 1..N-2
    (= 2 - B_i / A on an affine arc-length polyline; A = (A_i + A_{i+1})/2 otherwise)."""
    x = _pts(polyline, 4)
    k = np.empty(len(x) - 3)
    check(lib.el_affine_curvature(len(x), dptr(x), dptr(k)), "affine_curvature")
    return k


@dataclass
class OsculatingConics:
    """Discrete osculating conics (Theorem 2) of the quadruples x_{i-1}..x_{i+2}.

    coef[i] = (a, b, c, d, e, f) of a x^2 + b x y + c y^2 + d x + e y + f = 0;
    type +1 ellipse / 0 parabola / -1 hyperbola; center = affine evolute point (5);
    kappa = smooth affine curvature (7)."""
    kind: str
    type: np.ndarray
    center: np.ndarray
    coef: np.ndarray
    kappa: np.ndarray


def osculating_conics(polyline, kind: str = "middle") -> OsculatingConics:
    """The outer, inner or middle osculating conics of an affine arc-length polyline."""
    if not isinstance(kind, str) or kind not in _KINDS:
        raise ValueError(f"kind must be one of {sorted(_KINDS)}, got {kind!r}")
    x = _pts(polyline, 4)
    m = len(x) - 3
    out = ffi.new("el_affine_conic[]", m)
    check(lib.el_affine_osculating_conics(len(x), dptr(x), _KINDS[kind], out), "osculating_conics")
    return OsculatingConics(kind=kind,
                            type=np.array([out[i].type for i in range(m)]),
                            center=np.array([[out[i].center[0], out[i].center[1]] for i in range(m)]),
                            coef=np.array([[out[i].coef[j] for j in range(6)] for i in range(m)]),
                            kappa=np.array([out[i].kappa for i in range(m)]))


def chaikin(polyline, iterations: int = 1) -> np.ndarray:
    """Chaikin subdivision (§2.5), `iterations` times; keeps L2, maps A to A/8."""
    x = _pts(polyline, 2)
    iterations = as_int(iterations, "chaikin: iterations", 0)
    if (len(x) - 1) * 2.0 ** iterations > 1e8:
        raise ValueError(f"chaikin: {iterations} iterations of {len(x)} points would make more "
                         "than 1e8 points")
    for _ in range(iterations):
        y = np.empty((2 * (len(x) - 1), 2))
        check(lib.el_affine_chaikin(len(x), dptr(x), dptr(y)), "chaikin")
        x = y
    return x


def lane_riesenfeld(points, degree: int) -> np.ndarray:
    """Degree-n Lane–Riesenfeld refinement mu^n(x0,x0,x1,x1,...) of points (N+1, dim)
    (Theorem 5); returns 2(N+1) - degree points."""
    x = as_points(points, "points", None)
    dim = x.shape[1]
    degree = as_int(degree, "lane_riesenfeld: degree", 1)
    if 2 * len(x) <= degree:
        raise ValueError("need degree >= 1 and 2 * len(points) > degree")
    y = np.empty((2 * len(x) - degree, dim))
    check(lib.el_affine_lane_riesenfeld(dim, int(degree), len(x), dptr(x), dptr(y)), "lane_riesenfeld")
    return y


def affine_elements(points) -> tuple[np.ndarray, float]:
    """Affine length elements in R^n (Definition 3): D_i = det(dx_i..dx_{i+n-1}) and the
    total affine length L_n = sum sign(D_i)|D_i|^(2/(n(n+1))) (8). points: (N+1, n), n >= 2."""
    x = as_points(points, "points", None)
    if x.shape[1] < 2 or len(x) < x.shape[1] + 1:
        raise ValueError("points must have shape (N+1, n) with n >= 2 and N >= n")
    n = x.shape[1]
    D = np.empty(len(x) - n)
    L = ffi.new("double *")
    check(lib.el_affine_elements_nd(n, len(x), dptr(x), dptr(D), L), "affine_elements")
    return D, float(L[0])


def uniform_bspline(points, degree: Optional[int] = None, clamped: bool = True):
    """The uniform B-spline of degree `degree` (default: the dimension, Theorem 4) with
    control polygon `points` (N+1, dim). clamped=True: the same curve as clamped
    B-spline (knots 0..N+1-degree, end multiplicities degree+1); clamped=False: poles
    = points, knots 0..N+degree+1 (all simple). Returns a BSpline."""
    x = as_points(points, "points", None)
    deg = x.shape[1] if degree is None else as_int(degree, "uniform_bspline: degree", 1)
    require(len(x) >= deg + 1, "uniform_bspline: the number of points",
            f">= degree + 1 = {deg + 1}", len(x))
    b = ffi.new("el_bspline *")
    check(lib.el_affine_uniform_bspline(x.shape[1], deg, len(x), dptr(x), int(bool(clamped)), b),
          "uniform_bspline")
    return bspline_from_c(b)


def quadratic_bspline(polyline, clamped: bool = True):
    """The uniform quadratic B-spline with control polygon `polyline` (seed 002 §2.5);
    curvature continuous (G2) iff the polyline is an affine arc-length polyline.
    clamped=True (default): the curve from (x0+x1)/2 to (x_{N-1}+x_N)/2 as a clamped
    B-spline, poles (x0+x1)/2, x1, ..., x_{N-1}, (x_{N-1}+x_N)/2, knots 0..N-1;
    clamped=False: poles = polyline, knots 0..N+3, all simple (range [2, N+1])."""
    x = _pts(getattr(polyline, "points", polyline), 3)
    b = ffi.new("el_bspline *")
    check(lib.el_affine_quadratic_bspline(len(x), dptr(x), int(bool(clamped)), b), "quadratic_bspline")
    return bspline_from_c(b)


def parabolic_lengths(samples) -> np.ndarray:
    """Signed affine lengths (15) of the parabolic arcs of the replacement curve (§4.2)."""
    p = _pts(samples, 3)
    S = np.empty(len(p) - 1)
    check(lib.el_affine_parabolic_lengths(len(p), dptr(p), dptr(S)), "parabolic_lengths")
    return S


# ------------------------------------------------------------------ exact affine curvature

def affine_curvature_exact(kappa, dkappa, ddkappa) -> np.ndarray:
    """Smooth affine curvature of a planar curve from its Euclidean curvature and its
    arc-length derivatives: k = kappa^(4/3) - (5/9) kappa^(-8/3) kappa'^2
    + (1/3) kappa^(-5/3) kappa'' (real cube roots; needs kappa != 0)."""
    kappa, dkappa, ddkappa = (as_real_array(a, n) for a, n in
                              ((kappa, "kappa"), (dkappa, "dkappa"), (ddkappa, "ddkappa")))
    for a, n in ((kappa, "kappa"), (dkappa, "dkappa"), (ddkappa, "ddkappa")):
        if not np.all(np.isfinite(a)):     # (NaN in, NaN out would pass in silence)
            raise invalid(f"affine_curvature_exact: {n} must be finite, got "
                          f"{float(a[~np.isfinite(a)].flat[0])}")
    c = np.cbrt(kappa)
    return c ** 4 - (5.0 / 9.0) * dkappa ** 2 / c ** 8 + ddkappa / (3.0 * c ** 5)


def _jacobi(u: float, k: float):
    val = ffi.new("el_jacobi *")
    check(lib.el_jacobi_eval(as_real(u, "u"), as_real(k, "k"), val, ffi.NULL, ffi.NULL), "jacobi")
    return val.sn, val.cn, val.dn


def elastica_affine_curvature(curve, s) -> np.ndarray:
    """Exact affine curvature of a SmoothElastica at arc lengths s, from
    kappa = 2k sqrt(mu) cn u, kappa' = -2k mu sn dn, kappa'' = -2k mu^(3/2) cn (dn^2 - k^2 sn^2)."""
    s = as_vector(s, "elastica_affine_curvature: s", finite=True)
    k, mu = as_real(curve.k, "curve.k"), as_real(curve.mu, "curve.mu")
    rm = math.sqrt(mu)
    out = np.empty((3, len(s)))
    for i, si in enumerate(s):
        sn, cn, dn = _jacobi(rm * si + curve.q, k)
        out[:, i] = (2 * k * rm * cn, -2 * k * mu * sn * dn, -2 * k * mu * rm * cn * (dn * dn - k * k * sn * sn))
    return affine_curvature_exact(*out)


def _ellipk(k: float) -> float:
    """Complete elliptic integral K(k) = pi / (2 AGM(1, sqrt(1-k^2))), 0 <= k < 1."""
    a, b = 1.0, math.sqrt(1.0 - k * k)
    for _ in range(60):
        a, b = 0.5 * (a + b), math.sqrt(a * b)
        if abs(a - b) <= 1e-16 * a:
            break
    return math.pi / (2.0 * a)


def elastica_inflections(curve, margin: float = 1e-9) -> np.ndarray:
    """Arc lengths of the inflections of a SmoothElastica in (0, length): cn(u;k) = 0,
    u = sqrt(mu) s + q = (2j+1) K(k) for 0 < |k| < 1 (the curvature 2 k sqrt(mu) cn(u; k),
    whose modulus enters as k^2: a curve run backwards has -k); none for |k| >= 1 or k = 0.
    A Hermite chain answers for itself (HermiteChain.inflections)."""
    if hasattr(curve, "inflections"):
        return curve.inflections(margin)
    k = abs(as_real(getattr(curve, "k", None), "elastica_inflections: curve.k"))
    if not 0.0 < k < 1.0:
        return np.empty(0)
    K = _ellipk(k)
    rm = math.sqrt(curve.mu)
    u0, u1 = curve.q, rm * curve.length + curve.q
    j0 = math.ceil((u0 / K - 1.0) / 2.0)
    out = []
    j = j0
    while (2 * j + 1) * K < u1:
        s = ((2 * j + 1) * K - curve.q) / rm
        if margin * curve.length < s < (1 - margin) * curve.length:
            out.append(s)
        j += 1
    return np.array(out)


# ------------------------------------------------------------------ §4: approximation

@dataclass
class AffinePolyline:
    """Result of :func:`affine_polyline`.

    points (n+1, 2); t: parameters on the replacement curve f~ (f~(j) = sample j);
    s: arc lengths of the vertices' foot points on the elastica (None for point data);
    piece_start: first vertex of each inflection-free piece (+ the last vertex);
    A: signed area constant per piece; psi: minimised sum (delta k)^2 per piece;
    infl_param: inflections (f~ parameters); S_total: affine length of f~."""
    points: np.ndarray
    t: np.ndarray
    s: Optional[np.ndarray]
    piece_start: np.ndarray
    A: np.ndarray
    psi: np.ndarray
    infl_param: np.ndarray
    S_total: float

    def quadruples(self) -> tuple[np.ndarray, np.ndarray]:
        """Indices i of the quadruples x_{i-1}..x_{i+2} lying inside one piece, and their A."""
        idx, areas = [], []
        for p in range(len(self.A)):
            a, b = self.piece_start[p], self.piece_start[p + 1]
            for i in range(a + 1, b - 1):
                idx.append(i)
                areas.append(self.A[p])
        return np.array(idx, dtype=int), np.array(areas)

    def affine_curvature(self) -> tuple[np.ndarray, np.ndarray]:
        """(i, k_i) for the quadruples inside a piece: k_i = 2 - B_i / A (4)."""
        idx, areas = self.quadruples()
        _, B = affine_coords(self.points)
        return idx, 2.0 - B[idx - 1] / areas

    def middle_curvature(self) -> tuple[np.ndarray, np.ndarray]:
        """(i, k_i A^(-2/3)): the middle osculating conic's affine curvature (7), an
        approximation of the curve's affine curvature near x_i..x_{i+1}."""
        idx, areas = self.quadruples()
        _, k = self.affine_curvature()
        return idx, k / np.cbrt(areas) ** 2

    def bspline(self, clamped: bool = True):
        """The uniform quadratic B-spline of the polyline (G2 inside every piece)."""
        return quadratic_bspline(self.points, clamped=clamped)


def _run(samples: np.ndarray, tangents: Optional[np.ndarray], infl: Sequence[int], n: int,
         split: bool, skip: int, max_iter: int, skip_frac: float = 0.0, fit_ends: bool = False,
         optimise: bool = True):
    opt = ffi.new("el_affine_options *")
    lib.el_affine_options_defaults(opt)
    opt.split_inflections = int(bool(split))
    opt.skip = as_int(skip, "affine_polyline: skip", 0)
    opt.skip_frac = as_real(skip_frac, "affine_polyline: skip_frac")
    require(0 <= opt.skip_frac < 0.5, "affine_polyline: skip_frac", "in [0, 0.5)", skip_frac)
    opt.fit_ends = int(bool(fit_ends))
    opt.optimise = int(bool(optimise))
    opt.max_iter = as_int(max_iter, "affine_polyline: max_iter", 0)
    res = ffi.new("el_affine_result *")
    infl = [as_size(i, "affine_polyline: inflections") for i in infl]
    require(all(a < b for a, b in zip([0] + infl, infl + [len(samples) - 1])),
            "affine_polyline: inflections", f"sample indices in 1..{len(samples) - 2}, strictly "
            "increasing", infl)
    infl_arr = ffi.new("size_t[]", infl) if len(infl) else ffi.NULL
    tan = dptr(tangents) if tangents is not None else ffi.NULL
    st = lib.el_affine_polyline(len(samples), dptr(samples), tan, len(infl), infl_arr, int(n), opt,
                                res)
    if st == lib.EL_EDOM:   # the header's causes (the range checks are the caller's, above)
        raise DomainError(st, "affine_polyline: input outside the domain the method covers: a "
                              "straight piece (no affine arc length), an inflection where none is "
                              "allowed (split_inflections off, or inside a piece given as "
                              "inflection-free), or too few edges for the curve's turning (about 3 "
                              "per turn of the tangent at least)")
    check(st, "affine_polyline")
    try:
        m = res.npts
        pts = np.frombuffer(ffi.buffer(res.xy, 16 * m), dtype=np.float64).reshape(m, 2).copy()
        t = np.frombuffer(ffi.buffer(res.t, 8 * m), dtype=np.float64).copy()
        np_ = res.npieces
        ps = np.array([res.piece_start[i] for i in range(np_ + 1)], dtype=int)
        A = np.array([res.A[i] for i in range(np_)])
        psi = np.array([res.psi[i] for i in range(np_)])
        ip = np.array([res.infl_param[i] for i in range(np_ - 1)])
        S = float(res.S_total)
    finally:
        lib.el_affine_result_free(res)
    return pts, t, ps, A, psi, ip, S


def affine_polyline(curve_or_points, n: int, samples_per_vertex: int = 20,
                    split_inflections: bool = True, skip: int = 2, max_iter: int = 100,
                    inflections: Optional[Sequence[int]] = None, exact_tangents: bool = True,
                    tangents=None, skip_frac: float = 0.0, fit_ends: bool = False,
                    optimise: bool = True) -> AffinePolyline:
    """Approximate a curve by an affine arc-length polyline with n edges (n+1 vertices),
    seed 002 §4: parabolic replacement curve, A = (S/n)^3 from (15), line intersections,
    golden-section search on t1 minimising sum (delta k_i)^2, and (§4.4) one piece per
    inflection-free part with its own A, skipping max(skip, ceil(skip_frac * piece edges))
    vertices next to each inflection (skip_frac > 0 keeps k_i A^(-2/3) converging as n grows).
    fit_ends=True adjusts each piece's A until its last vertex lands on the inflection / the
    curve's end (§4.4 "redone with adjusted A"); by default A = (S/n)^3 as in the paper.
    optimise=False keeps t1 at its start value (the simple construction, for comparison).

    curve_or_points: a SmoothElastica (sampled with samples_per_vertex * n arcs, its
    inflections taken exactly from the parameters and made sample points) or point data
    (N+1, 2) (the samples themselves; about 20 per vertex wanted; `inflections` optionally
    gives their sample indices, otherwise they are detected).
    The replacement curve's tangents: the paper's p_{j+1} - p_{j-1}, or for an elastica with
    exact_tangents=True (default) its exact tangents, or for points the given `tangents`
    (N+1, 2): its deviation is then O(h^4) instead of O(h^3), which the k_i A^(-2/3) of
    fine polylines need (their error grows like h^3/H^4 otherwise). Raises ValueError /
    DomainError (inflection with split_inflections=False, n too small) on bad input."""
    n = as_size(n, "affine_polyline: n", 3)
    if n > lib.EL_AFFINE_MAX_EDGES:   # bounded work, and before sampling n points
        raise DomainError(lib.EL_EDOM, f"affine_polyline: n = {n} edges asked; at most "
                          f"{lib.EL_AFFINE_MAX_EDGES} (EL_AFFINE_MAX_EDGES) are built")
    samples_per_vertex = as_int(samples_per_vertex, "affine_polyline: samples_per_vertex", 1)
    if samples_per_vertex * n > 10 ** 8:
        raise ValueError(f"affine_polyline: {samples_per_vertex} samples per vertex for {n} "
                         "vertices are more than 1e8 samples")
    if hasattr(curve_or_points, "curvature") and hasattr(curve_or_points, "length"):
        c = curve_or_points
        if not c.length > 0:
            raise ValueError("the elastica has zero length")
        infl_s = elastica_inflections(c)
        if len(infl_s) and not split_inflections:
            raise DomainError(lib.EL_EDOM, "affine_polyline: the elastica has an inflection")
        bounds = np.concatenate([[0.0], infl_s, [c.length]])
        total = max(samples_per_vertex * n, 4 * (len(bounds) - 1))
        lens = np.diff(bounds)
        counts = np.maximum(3, np.round(total * lens / c.length).astype(int))
        s_parts, idx = [], []
        start = 0
        for p in range(len(lens)):
            seg = np.linspace(bounds[p], bounds[p + 1], counts[p] + 1)
            s_parts.append(seg if p == 0 else seg[1:])
            start += counts[p]
            if p + 1 < len(lens):
                idx.append(start)
        s_samp = np.concatenate(s_parts)
        samples = np.ascontiguousarray(c.points(s_samp))
        tangents = None
        if exact_tangents:
            theta = c.angle(s_samp)
            tangents = np.ascontiguousarray(np.c_[np.cos(theta), np.sin(theta)])
        pts, t, ps, A, psi, ip, S = _run(samples, tangents, idx, n, split_inflections, skip,
                                         max_iter, skip_frac, fit_ends, optimise)
        j = np.clip(np.floor(t).astype(int), 0, len(s_samp) - 2)
        s = s_samp[j] + (t - j) * (s_samp[j + 1] - s_samp[j])
        for _ in range(3):   # project the vertices onto the elastica (Newton on the foot point)
            th = c.angle(s)
            s = s + np.einsum("ij,ij->i", pts - c.points(s), np.c_[np.cos(th), np.sin(th)])
        return AffinePolyline(pts, t, s, ps, A, psi, ip, S)
    samples = as_points(curve_or_points, "points")
    if len(samples) < 4:
        raise ValueError(f"need at least 4 points, got {len(samples)}")
    tan = None
    if tangents is not None:
        tan = as_points(tangents, "tangents")
        if len(tan) != len(samples):
            raise ValueError("tangents must have one row per sample")
    infl = [] if inflections is None else list(as_vector(inflections, "inflections"))
    pts, t, ps, A, psi, ip, S = _run(samples, tan, infl, n, split_inflections,
                                     skip, max_iter, skip_frac, fit_ends, optimise)
    return AffinePolyline(pts, t, None, ps, A, psi, ip, S)


# ------------------------------------------------------------------ G2 quadratic B-splines

def g2_bspline(polyline, start=None, end=None):
    """The curvature-continuous quadratic B-spline of an affine arc-length polyline
    (m+1 >= 4 vertices) that starts exactly at ``start`` and ends exactly at ``end``
    (None: the uniform spline's own ends (x0+x1)/2, (x_{m-1}+x_m)/2): the end
    segments are replaced by the parabolas through those points that meet the next
    joint G2 (el_affine_g2_bspline). Raises DomainError when an end point lies on
    the wrong side of its joint's tangent line."""
    x = _pts(getattr(polyline, "points", polyline), 4)
    ends = []
    for name, v in (("start", start), ("end", end)):
        if v is None:
            ends.append(ffi.NULL)
            continue
        a = np.asarray(v, dtype=np.float64).reshape(-1)
        if a.shape != (2,) or not np.all(np.isfinite(a)):
            raise ValueError(f"{name} must be two finite numbers, got {v!r}")
        ends.append(ffi.new("double[2]", list(a)))
    b = ffi.new("el_bspline *")
    check(lib.el_affine_g2_bspline(len(x), dptr(x), ends[0], ends[1], b), "g2_bspline")
    return bspline_from_c(b)


def _quadratic_beziers(bs) -> np.ndarray:
    """The Bezier control points (nseg, 3, 2) of a clamped quadratic B-spline with
    simple interior knots (the joint between poles i, i+1 divides them in the ratio
    of the knot intervals either side)."""
    P, K = np.asarray(bs.poles), np.asarray(bs.knots)
    if bs.degree != 2 or len(K) < 2 or bs.mults[0] != 3 or bs.mults[-1] != 3 \
            or np.any(np.asarray(bs.mults[1:-1]) != 1):
        raise ValueError("a clamped quadratic B-spline with simple interior knots is needed")
    dk = np.diff(K)                                  # knot intervals, one per segment
    joints = (dk[1:, None] * P[1:-2] + dk[:-1, None] * P[2:-1]) / (dk[:-1] + dk[1:])[:, None]
    starts = np.vstack([P[:1], joints])
    ends = np.vstack([joints, P[-1:]])
    return np.stack([starts, P[1:-1], ends], axis=1)


def quadratic_joint_curvatures(bs) -> tuple[np.ndarray, np.ndarray]:
    """Curvature just before and just after every interior joint of a clamped
    quadratic B-spline, (left, right), from its Bezier segments: a segment (b0, b1,
    b2) has curvature det(b1-b0, b2-b1) / (2|b1-b0|^3) at b0 and / (2|b2-b1|^3) at b2.
    G2 means left == right."""
    B = _quadratic_beziers(bs)
    d0, d1 = B[:, 1] - B[:, 0], B[:, 2] - B[:, 1]
    area = d0[:, 0] * d1[:, 1] - d0[:, 1] * d1[:, 0]
    k_start = area / (2.0 * np.linalg.norm(d0, axis=1) ** 3)
    k_end = area / (2.0 * np.linalg.norm(d1, axis=1) ** 3)
    return k_end[:-1], k_start[1:]


@dataclass
class G2Quadratic:
    """Result of :func:`g2_quadratic`.

    bsplines: one curvature-continuous quadratic B-spline per inflection-free piece,
    piece p running exactly from ends[p] to ends[p+1] (the source's ends and its
    inflection points); polyline: the affine arc-length polyline (seed 002 §4) they
    come from; deviation: the largest distance of the splines from the source (its
    sample polyline); curvature_jump: the largest relative curvature jump at any
    joint inside a piece (0 up to rounding: G2); end_tangent_error: the largest angle
    (radians) between a piece's end tangent and the source's there (None when the
    source's tangents are unknown; a quadratic end segment that meets its joint G2
    has no freedom left for the tangent, the error is O(edge)); covers_source: False
    when an end piece next to an inflection was too short to keep, so the splines
    start / stop at that inflection (§4.4); ends_covered: (start, end), which of the two
    ends is kept (covers_source: both); fit: with ``fit=True`` the FitResult of the
    smooth elastica fitted to the points (the source then; its rms / max_error are the
    points' distances to it), else None.
    join_angle / join_curvature_jump: where two pieces meet (at the source's inflections;
    the pieces are G2 inside, not there) the largest angle (radians) between their tangents
    and the largest jump of their signed curvature (1/length); 0 with one piece.
    end_curvature_error: at the source's own ends that the splines reach, the largest
    curvature error relative to the source's curvature scale, |k - k_src| / max(|k_src|,
    max |kappa| of the source over that end piece's span) (of point data: k_src from a
    cubic fitted to the end's samples, the maximum of their three-point curvature; at an
    end of zero curvature, e.g. an inflection, |k - k_src| / max(|k|, |k_src|) read ~1 at
    every n); None when neither end is
    reached. ~1e-12 where the end vertex could be placed (see g2_quadratic), else what the
    uniform construction gives (~0.29 on an arc at any n).
    dropped: the source's arc length left out at (start, end) (0, 0 when covers_source)."""
    bsplines: list
    polyline: AffinePolyline
    ends: np.ndarray
    deviation: float
    curvature_jump: float
    end_tangent_error: Optional[float]
    covers_source: bool
    fit: Optional[object] = None
    ends_covered: Tuple[bool, bool] = (True, True)
    join_angle: float = 0.0
    join_curvature_jump: float = 0.0
    end_curvature_error: Optional[float] = None
    dropped: Tuple[float, float] = (0.0, 0.0)

    def g2_summary(self) -> str:
        """Which joints are G2, in words (the CLI's and FreeCAD's line): the joints inside
        a piece by curvature_jump; where pieces meet (inflections) by their angle and jump."""
        inside = f"largest relative curvature jump at a joint inside a piece: " \
                 f"{self.curvature_jump:.2g} (G2 inside each piece)"
        if len(self.bsplines) < 2:
            return inside
        return (f"{inside}; where the {len(self.bsplines)} pieces meet (inflections): tangents "
                f"{math.degrees(self.join_angle):.3g} deg apart, curvature jump "
                f"{self.join_curvature_jump:.3g} (not G2 there)")

    @property
    def npoles(self) -> int:
        return int(sum(b.npoles for b in self.bsplines))


def _spline_deviation(bs, samples: np.ndarray, lo: float, hi: float) -> float:
    """Largest distance of one piece's spline from the source polyline ``samples``,
    sample range [lo, hi] (f~ parameters; 16 points per knot span)."""
    from .report import closest_points
    K = np.asarray(bs.knots)
    u = np.concatenate([np.linspace(a, b, 16, endpoint=False) for a, b in zip(K[:-1], K[1:])]
                       + [K[-1:]])
    xy = bs(u)
    a, b = max(0, int(math.floor(lo)) - 1), min(len(samples), int(math.ceil(hi)) + 2)
    src = samples[a:b]
    worst = 0.0
    for chunk in range(0, len(xy), 256):    # bounded memory: 256 points x the piece's samples
        p = xy[chunk:chunk + 256]
        worst = max(worst, float(np.max(np.linalg.norm(closest_points(p, src) - p, axis=1))))
    return worst


def _sign_changes(points: np.ndarray) -> int:
    """How often the discrete curvature det(x_i - x_{i-1}, x_{i+1} - x_i) of the points
    changes sign (zeros skipped): a curve's inflections, and as many again as noise or
    rounding adds (801 samples of an S: 1 exact, 19 rounded to 1e-4, 245 to 1e-3)."""
    d = np.diff(points, axis=0)
    a = np.sign(d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0])
    a = a[a != 0]
    return int(np.count_nonzero(a[1:] != a[:-1]))


# More sign changes of the points' discrete curvature than a piecewise-convex profile's few
# inflections: noise (_sign_changes), named as such in g2_quadratic's DomainError.
NOISY_SIGN_CHANGES = 3


def _noisy_points_error(exc: DomainError, points: np.ndarray) -> DomainError:
    """g2_quadratic's DomainError for point data: the cause, how noisy the points are, and
    the way out (fit=True)."""
    flips = _sign_changes(points)
    why = str(exc)
    if flips > NOISY_SIGN_CHANGES:   # the C status's list of causes is beside the point
        why = (f"{why.split(':')[0]}: the points are too noisy for the construction: their "
               f"discrete curvature changes sign {flips} times over {len(points)} points; its "
               "affine arc length takes their second and third differences (seed 002 (1), "
               "(15)), so it needs a piecewise-convex curve to high accuracy")
    return DomainError(exc.status, f"{why}; fit=True (`elastica g2quad FILE --fit`) fits one "
                       "smooth elastica to the points first and builds from it, or pass a fitted "
                       "SmoothElastica (`elastica fit --model smooth --json`, then `elastica "
                       "g2quad fit.json`)")


class CoverageWarning(RuntimeWarning):
    """:func:`g2_quadratic`'s warning that its splines leave part of the source out (an end
    piece next to an inflection too short for 3 edges: ``G2Quadratic.dropped``)."""


def _end_curvature(samples: np.ndarray, reverse: bool, tangents=None) -> Optional[float]:
    """Signed curvature at the first (reverse: the last) of dense samples of a curve, in
    the direction of travel, from the 8 samples at that end (chord length s): with their
    tangents, theta'(0) of a cubic theta(s) by least squares (first differences: the
    samples' rounding counts ~1/s less); without, det(x', x'') / |x'|^3 of x(s), y(s)
    cubics. None for fewer than 5 samples."""
    q = samples[::-1] if reverse else samples
    q = q[:8] - q[0]
    if len(q) < 5:
        return None
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))])
    if not s[-1] > 0:
        return None
    V = np.vander(s / s[-1], 4, increasing=True)
    if tangents is not None:
        t = (tangents[::-1] if reverse else tangents)[:8]
        theta = np.unwrap(np.arctan2(t[:, 1], t[:, 0]))
        k = np.linalg.lstsq(V, theta - theta[0], rcond=None)[0][1] / s[-1]
    else:
        c = np.linalg.lstsq(V, q, rcond=None)[0]
        d1, d2 = c[1] / s[-1], 2.0 * c[2] / s[-1] ** 2
        k = (d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(*d1) ** 3
    return float(-k if reverse else k)      # (backwards from the end: the sign turns)


def _start_curvature(bs) -> float:
    """Curvature at the start of a clamped quadratic B-spline: det(b1-b0, b2-b1) / (2|b1-b0|^3)
    of its first Bezier segment (b2 the joint of poles 1, 2)."""
    P, K = bs.poles, bs.knots
    j = ((K[2] - K[1]) * P[1] + (K[1] - K[0]) * P[2]) / (K[2] - K[0])
    d0, d1 = P[1] - P[0], j - P[1]
    return float((d0[0] * d1[1] - d0[1] * d1[0]) / (2.0 * np.linalg.norm(d0) ** 3))


def _match_start(x: np.ndarray, start, end, kappa: float) -> Optional[np.ndarray]:
    """The polyline x (>= 6 vertices) with x_1 moved so that g2_bspline(x, start, end) starts
    with curvature kappa, or None (no such place within 0.5..1.5 x its edge).
    Why: the vertices lie on the source, so the uniform spline runs inside it by ~kappa h^2/8
    and the end parabola (start, c, m_2) bridging to it over ~1.5 h ends with ~0.71 kappa on
    a circle (legs 0.793 h and h/sqrt 2: (0.707/0.793)^3). x_1 slides on the line
    det(x_2 - x_1, v_2) = A (v_1 = t u + (A/|v_2|) w, u = v_2/|v_2|, det(w, u) = 1), which keeps
    A_2 = A and so every joint G2; t moves m_2, v_1 and the end parabola's legs, and the root
    of its start curvature - kappa is taken nearest the polyline's own t (bisection)."""
    v2 = x[3] - x[2]
    A = float(v2[1] * (x[2] - x[1])[0] - v2[0] * (x[2] - x[1])[1])
    n2 = float(np.hypot(*v2))
    u = v2 / n2
    w = np.array([u[1], -u[0]])
    t0 = float((x[2] - x[1]) @ u)

    def f(t):
        y = x.copy()
        y[1] = x[2] - (t * u + (A / n2) * w)
        try:
            return _start_curvature(g2_bspline(y, start, end)) - kappa, y
        except DomainError:
            return math.nan, y
    ts = t0 * np.linspace(0.5, 1.5, 41)
    fs = np.array([f(t)[0] for t in ts])
    ok = np.isfinite(fs[:-1]) & np.isfinite(fs[1:]) & (np.sign(fs[:-1]) != np.sign(fs[1:]))
    if not ok.any():
        return None
    i = int(np.nonzero(ok)[0][np.argmin(np.abs(np.nonzero(ok)[0] - 20))])
    lo, hi, flo = ts[i], ts[i + 1], fs[i]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        fm = f(mid)[0]
        if not math.isfinite(fm):
            return None
        if np.sign(fm) == np.sign(flo):
            lo, flo = mid, fm
        else:
            hi = mid
    return f(lo if abs(flo) <= abs(f(hi)[0]) else hi)[1]


def _matched_ends(x: np.ndarray, start, end, k_start: Optional[float],
                  k_end: Optional[float]) -> np.ndarray:
    """The piece's polyline with x_1 / x_{m-1} moved so its G2 spline's ends have the
    curvatures k_start / k_end (None, 0 or no such place: that end as it was). The two
    moves are independent for m >= 5 (x_1 depends on x_2, x_3 only; x_{m-1} on x_{m-2},
    x_{m-3}); fewer vertices are left as they are."""
    if len(x) < 6:
        return x
    y = x.copy()
    if k_start:
        z = _match_start(x, start, end, k_start)
        if z is not None:
            y[1] = z[1]
    if k_end:     # the same at the end, travelled backwards (its curvature changes sign)
        z = _match_start(x[::-1].copy(), end, start, -k_end)
        if z is not None:
            y[-2] = z[1]
    return y


def _rel_err(a: float, b: float, scale: float = 0.0) -> float:
    """|a - b| / max(|a|, |b|) (scale 0), or |a - b| / max(|b|, scale): relative to the
    source's curvature scale (end_curvature_error; QA13: near an end of zero curvature the
    first read ~1 whatever the size of the error)."""
    m = max(abs(a), abs(b)) if scale <= 0.0 else max(abs(b), scale)
    return abs(a - b) / m if m > 0 else 0.0


def _menger_max(x: np.ndarray) -> float:
    """Largest discrete (three-point) curvature of sampled points, 0 for fewer than 3."""
    if len(x) < 3:
        return 0.0
    a, b = x[1:-1] - x[:-2], x[2:] - x[1:-1]
    cross = np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    den = np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1) * np.linalg.norm(x[2:] - x[:-2], axis=1)
    ok = den > 0
    return float(np.max(2.0 * cross[ok] / den[ok])) if ok.any() else 0.0


def _joins(splines) -> Tuple[float, float]:
    """Largest tangent angle (radians) and signed-curvature jump where consecutive
    pieces meet."""
    angle = jump = 0.0
    for a, b in zip(splines, splines[1:]):
        ta, tb = a.derivative(a.knots[-1:])[0], b.derivative(b.knots[:1])[0]
        angle = max(angle, abs(math.atan2(ta[0] * tb[1] - ta[1] * tb[0], ta @ tb)))
        jump = max(jump, abs(float(a.curvature(a.knots[-1:])[0] - b.curvature(b.knots[:1])[0])))
    return angle, jump


def g2_quadratic(curve_or_points, n: int, samples_per_vertex: int = 20, tangents=None,
                 fit: bool = False, **options) -> G2Quadratic:
    """Seed 002 end to end: approximate a SmoothElastica or a sampled curve (N+1, 2)
    by an affine arc-length polyline with n edges (:func:`affine_polyline`, each
    piece's A adjusted so its last vertex lands on the piece end), then build one
    curvature-continuous uniform quadratic B-spline per inflection-free piece that
    ends exactly on the source: at its end points and at its inflections
    (:func:`g2_bspline`; only the two end segments of a piece are not uniform).
    ``tangents`` (N+1, 2) of point data sharpen the replacement curve and give the
    end tangent error; ``options`` go to :func:`affine_polyline`.
    Measured points are rarely accurate enough for the construction (801 samples of a
    300 mm S rounded to 1e-4 mm fail): ``fit=True`` fits one smooth elastica to them
    (:func:`fit`, point-to-curve distance) and builds from that curve (``fit`` of the
    result: the points' distances to it; ``deviation``: the splines' from it).
    Raises ValueError / DomainError (straight source, n too small, noisy points: the
    message counts the sign changes of their discrete curvature, ...); warns
    (:class:`CoverageWarning`) when part of the source is left out, saying how much.
    The ends' curvature is the source's (end_curvature_error ~1e-12): the uniform end
    parabola from the exact end point ends with ~0.71 x it at every n (the polyline's
    vertices lie on the source, the spline runs inside it by ~kappa h^2/8, and the parabola
    bridging over ~1.5 h bends differently), so each end piece's x_1 (x_{m-1}) is moved
    along the line that keeps A_2 = A, to where the end parabola starts with the source's
    curvature (_match_start; the polyline returned has it). The bridge then shows as a dip
    inside: on an arc the curvature along the spline stays within 7.5 % of the source's
    (0.71 at the ends before) at every n; where no such place exists (few edges for the
    turning: 6 on a k = 1.5 elastica) the end is left uniform and the error says so."""
    is_curve = hasattr(curve_or_points, "curvature") and hasattr(curve_or_points, "length")
    if fit:
        if is_curve or tangents is not None:
            raise ValueError("g2_quadratic: fit=True fits point data (without tangents); "
                             "a curve is built from as it is")
        from .fit import fit as fit_points
        fitted = fit_points(as_points(curve_or_points, "points"), model="smooth")
        g = g2_quadratic(fitted.curve, n, samples_per_vertex, **options)
        g.fit = fitted
        return g
    options.setdefault("fit_ends", True)
    try:
        ap = affine_polyline(curve_or_points, n, samples_per_vertex=samples_per_vertex,
                             tangents=None if is_curve else tangents, **options)
    except DomainError as exc:
        if is_curve:
            raise
        raise _noisy_points_error(exc, as_points(curve_or_points, "points")) from None
    npieces = len(ap.A)
    if is_curve:
        c = curve_or_points
        bounds = np.concatenate([[0.0], elastica_inflections(c), [c.length]])
        first = int(np.argmin(np.abs(bounds - ap.s[0])))
        s_ends = bounds[first:first + npieces + 1]
        ends = c.points(s_ends)
        theta = c.angle(s_ends)
        ends_dir = np.c_[np.cos(theta), np.sin(theta)]
        total = max(int(samples_per_vertex) * int(n), 4 * (len(bounds) - 1))
        samples = c.points(np.linspace(0.0, c.length, total + 1))
        t_ends = s_ends / c.length * total
        covers = first == 0, first + npieces == len(bounds) - 1
        k_src = [float(k) for k in c.curvature(np.array([0.0, c.length]))]
        dropped = float(s_ends[0]), float(c.length - s_ends[-1])
        length = float(c.length)
    else:
        samples = as_points(curve_or_points, "points")
        t_ends = np.concatenate([[ap.t[0]], ap.infl_param, [round(float(ap.t[-1]))]])
        idx = t_ends.astype(int)
        ends = samples[idx]
        ends_dir = None
        if tangents is not None:
            tan = as_points(tangents, "tangents")
            ends_dir = tan[idx] / np.linalg.norm(tan[idx], axis=1)[:, None]
        covers = idx[0] == 0, idx[-1] == len(samples) - 1
        tan = None if tangents is None else as_points(tangents, "tangents")
        k_src = [_end_curvature(samples, False, tan), _end_curvature(samples, True, tan)]
        seg = np.linalg.norm(np.diff(samples, axis=0), axis=1)
        dropped = float(seg[:idx[0]].sum()), float(seg[idx[-1]:].sum())
        length = float(seg.sum())
    splines, jump, dev, terr = [], 0.0, 0.0, 0.0
    poly = ap.points.copy()
    for p in range(npieces):
        a, b = ap.piece_start[p], ap.piece_start[p + 1]
        x = _matched_ends(ap.points[a:b + 1], ends[p], ends[p + 1],
                          k_src[0] if p == 0 and covers[0] else None,
                          k_src[1] if p == npieces - 1 and covers[1] else None)
        poly[a:b + 1] = x
        try:
            bs = g2_bspline(x, ends[p], ends[p + 1])
        except DomainError as exc:       # an end beside its joint's tangent: noisy points
            if is_curve:
                raise
            raise _noisy_points_error(exc, samples) from None
        kl, kr = quadratic_joint_curvatures(bs)
        if len(kl):
            jump = max(jump, float(np.max(np.abs(kl - kr) / np.maximum(np.abs(kl), np.abs(kr)))))
        dev = max(dev, _spline_deviation(bs, samples, t_ends[p], t_ends[p + 1]))
        if ends_dir is not None:
            d = bs.derivative(np.array([bs.knots[0], bs.knots[-1]]))
            for vec, ref in ((d[0], ends_dir[p]), (d[1], ends_dir[p + 1])):
                terr = max(terr, abs(math.atan2(vec[0] * ref[1] - vec[1] * ref[0],
                                                vec[0] * ref[0] + vec[1] * ref[1])))
        splines.append(bs)
    # the source's curvature scale over each end piece's span: max |kappa| there
    if is_curve:
        kscale = [float(np.max(np.abs(c.curvature(np.linspace(s_ends[p], s_ends[p + 1], 201)))))
                  for p in (0, npieces - 1)]
    else:
        kscale = [_menger_max(samples[idx[p]:idx[p + 1] + 1]) for p in (0, npieces - 1)]
    kerr = [_rel_err(float(b.curvature(b.knots[[j]])[0]), k, ks) for b, j, k, ks, kept in
            ((splines[0], 0, k_src[0], kscale[0], covers[0]),
             (splines[-1], -1, k_src[1], kscale[1], covers[1]))
            if kept and k is not None]
    if not all(covers):
        gone = " and ".join(f"{d:.4g} at its {w}" for d, w in zip(dropped, ("start", "end"))
                            if d > 0)
        warnings.warn(f"g2_quadratic: the splines leave out {gone} of the source (length "
                      f"{length:.4g}): an end piece beyond an inflection is too short for 3 of "
                      f"the {n} edges, so they stop at the inflection; more edges cover it",
                      CoverageWarning,
                      stacklevel=2)
    angle, kjump = _joins(splines)
    ap = dataclasses.replace(ap, points=poly)
    return G2Quadratic(splines, ap, np.asarray(ends), dev, jump,
                       terr if ends_dir is not None else None, bool(all(covers)),
                       ends_covered=(bool(covers[0]), bool(covers[1])), join_angle=angle,
                       join_curvature_jump=kjump,
                       end_curvature_error=max(kerr) if kerr else None, dropped=dropped)
