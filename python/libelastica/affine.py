"""Affine arc-length polylines and curvature-continuous quadratic B-splines (seed 002).

A polyline x_0..x_N with A_i = det(x_i - x_{i-1}, x_{i+1} - x_i) constant is an
*affine arc-length polyline*; exactly then the uniform quadratic B-spline with
that control polygon has continuous curvature (G2). This module wraps
libelastica/affine.c and affine_polyline.c: polyline coordinates, discrete affine curvature,
osculating conics, Chaikin / Lane–Riesenfeld refinement, the R^n affine length,
uniform B-splines of such polygons, and the approximation algorithm of §4
(:func:`affine_polyline`) for a :class:`SmoothElastica` or point data, and
:func:`g2_bspline`, the G2 quadratic B-spline of such a polyline. g2quad.py builds
:func:`g2_quadratic` on them: a curve -> one G2 quadratic B-spline per
inflection-free piece, ending exactly on the curve's ends and inflections.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ._ffi import (DomainError, as_int, as_points, as_real, as_real_array, as_size, as_vector,
                   bspline_from_c, check, dptr, ffi, invalid, lib, require)
from ._values import ValueEquality, field_summary
from .core import DiscreteElastica
from .g2quad_points import _local_source

__all__ = ["affine_coords", "affine_length", "affine_curvature", "osculating_conics",
           "OsculatingConics", "chaikin", "lane_riesenfeld", "affine_elements",
           "uniform_bspline", "quadratic_bspline", "parabolic_lengths", "AffinePolyline",
           "affine_polyline", "affine_curvature_exact", "elastica_affine_curvature",
           "elastica_inflections", "g2_bspline", "quadratic_joint_curvatures", "EdgeCountError",
           "EndPieces", "affine_end_pieces"]


class EdgeCountError(DomainError):
    """The DomainError of :func:`affine_polyline` (and :func:`g2_quadratic`) for an elastica
    with too few edges for its turning. cause: what is wrong, without the function's name;
    edges: the fewest count above n that works (g2_quadratic: :func:`covering_edges`), or
    None (none found, or affine_polyline, which does not search)."""

    def __init__(self, status: int, message: str, cause: str, edges: Optional[int] = None):
        super().__init__(status, message)
        self.cause, self.edges = cause, edges


def _turning(c) -> float:
    """The total turning of an elastica's tangent, int |kappa| ds (sampled densely)."""
    s = np.linspace(0.0, c.length, 4001)
    return float(np.sum(np.abs(np.diff(np.unwrap(c.angle(s))))))

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
    """Affine length L2 = sum cbrt(A_i) (3) of a ``polyline`` ((n, 2), n >= 3 vertices)."""
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


@dataclass(eq=False)
class OsculatingConics(ValueEquality):
    """Discrete osculating conics (Theorem 2) of the quadruples x_{i-1}..x_{i+2}.

    coef[i] = (a, b, c, d, e, f) of a x^2 + b x y + c y^2 + d x + e y + f = 0;
    type +1 ellipse / 0 parabola / -1 hyperbola; center = affine evolute point (5);
    kappa = smooth affine curvature (7); ``kind``: "outer", "inner" or "middle", as asked
    of :func:`osculating_conics`."""
    kind: str
    type: np.ndarray
    center: np.ndarray
    coef: np.ndarray
    kappa: np.ndarray

    __repr__ = field_summary


def osculating_conics(polyline, kind: str = "middle") -> OsculatingConics:
    """The outer, inner or middle (``kind``, default "middle") osculating conics of an
    affine arc-length ``polyline`` ((n, 2), n >= 4 vertices): one per quadruple."""
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
    """Chaikin subdivision (§2.5) of a ``polyline`` ((n, 2)), `iterations` times (default 1);
    keeps L2, maps A to A/8."""
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
    """Signed affine lengths (15) of the parabolic arcs of the replacement curve (§4.2)
    through ``samples`` ((N+1, 2), N >= 2: the curve's sample points)."""
    p = _pts(samples, 3)
    S = np.empty(len(p) - 1)
    check(lib.el_affine_parabolic_lengths(len(p), dptr(p), dptr(S)), "parabolic_lengths")
    return S


# ------------------------------------------------------------------ exact affine curvature

def affine_curvature_exact(kappa, dkappa, ddkappa) -> np.ndarray:
    """Smooth affine curvature of a planar curve from its Euclidean curvature and its
    arc-length derivatives: k = kappa^(4/3) - (5/9) kappa^(-8/3) kappa'^2
    + (1/3) kappa^(-5/3) kappa'' (real cube roots; needs kappa != 0): ``kappa``, ``dkappa`` =
    kappa' and ``ddkappa`` = kappa'' (1/length, 1/length^2, 1/length^3), arrays of one shape."""
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
    """Exact affine curvature of a SmoothElastica ``curve`` at arc lengths s, from
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
    A Hermite chain answers for itself (HermiteChain.inflections). ``curve``: a
    SmoothElastica or HermiteChain; ``margin``: inflections within margin x length of an
    end are left out (default 1e-9: the ends themselves)."""
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

@dataclass(eq=False)
class AffinePolyline(ValueEquality):
    """Result of :func:`affine_polyline`.

    points (n+1, 2); t: parameters on the replacement curve f~ (f~(j) = sample j);
    s: arc lengths of the vertices' foot points on the elastica (None for point data): the
    vertices lie on it, x_i = f(t_i) (seed 002 §4), s in [0, length], but for a last vertex
    past its end (t beyond f~'s last sample: the paper's A = (S/n)^3 lands it near the end,
    fit_ends=True on it), which lies on f~'s last parabola continued, not on the curve: its
    s is its foot's on the elastica continued, above length (curve.points(s,
    extrapolate=True));
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

    __repr__ = field_summary

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
        """The uniform quadratic B-spline of the polyline (G2 inside every piece); ``clamped``
        as :func:`quadratic_bspline`'s (True, default: from the first edge's midpoint to the
        last's; False: the vertices as poles, simple knots)."""
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


@dataclass(frozen=True)
class EndPieces:
    """Result of :func:`affine_end_pieces`: npieces, the inflection-free pieces of the
    samples' f~; ends, (where the first piece ends, where the last starts) as sample
    indices; n_start, the fewest edge count keeping the first piece; n_both, keeping both
    end pieces (None where no count up to EL_AFFINE_MAX_EDGES does)."""
    npieces: int
    ends: tuple
    n_start: Optional[int]
    n_both: Optional[int]

    def keeps_ends(self, n: int) -> bool:
        """Whether :func:`affine_polyline` of these samples keeps both end pieces at n edges
        (False: it leaves one out, so the polyline stops at an inflection)."""
        return self.n_both is not None and int(n) >= self.n_both


def _samples_checked(points, tangents, inflections):
    """The sample points (at least 4), their tangents (one row per sample, or None) and the
    inflection indices (a list, [] for None; not yet checked as indices) that
    affine_end_pieces and affine_polyline take, as arrays: the checks both make, in one place."""
    samples = as_points(points, "points")
    if len(samples) < 4:
        raise ValueError(f"need at least 4 points, got {len(samples)}")
    tan = None
    if tangents is not None:
        tan = as_points(tangents, "tangents")
        if len(tan) != len(samples):
            raise ValueError("tangents must have one row per sample")
    infl = [] if inflections is None else list(as_vector(inflections, "inflections"))
    return samples, tan, infl


def affine_end_pieces(points, tangents=None, inflections: Optional[Sequence[int]] = None,
                      split_inflections: bool = True) -> EndPieces:
    """The pieces :func:`affine_polyline` splits the samples ``points`` (with ``tangents`` and
    ``inflections`` as it takes them) into, and the edge counts at which it keeps the end
    pieces (seed 002 §4.4: at n edges an end piece worth less than 1.5 edges of affine
    length, n S_end / S_total < 1.5, is left out). Exact and monotone in n (C's own test:
    el_affine_end_pieces), so a search over edge counts of the same samples may skip every
    count below ``n_both`` (:meth:`EndPieces.keeps_ends`, as :func:`covering_edges`'s
    ``leaves_out``). ``split_inflections``: as affine_polyline's option of that name (False:
    given inflections are refused, as there)."""
    samples, tan, infl = _samples_checked(points, tangents, inflections)
    infl = [as_size(i, "affine_end_pieces: inflections") for i in infl]
    opt = ffi.new("el_affine_options *")
    lib.el_affine_options_defaults(opt)
    opt.split_inflections = int(bool(split_inflections))
    infl_arr = ffi.new("size_t[]", infl) if infl else ffi.NULL
    npieces, ends, n_min = ffi.new("size_t *"), ffi.new("size_t[2]"), ffi.new("size_t[2]")
    check(lib.el_affine_end_pieces(len(samples), dptr(samples),
                                   dptr(tan) if tan is not None else ffi.NULL, len(infl),
                                   infl_arr, opt, npieces, ends, n_min), "affine_end_pieces")
    return EndPieces(int(npieces[0]), (int(ends[0]), int(ends[1])), int(n_min[0]) or None,
                     int(n_min[1]) or None)


def _is_curve(c, name: str) -> bool:
    """Whether ``c`` is a curve to sample (it has a curvature and a length) rather than
    points; a DiscreteElastica, which has both, is refused naming ``name``: a polygon."""
    if isinstance(c, DiscreteElastica):
        raise ValueError(f"{name}: a DiscreteElastica is a polygon, not a curve to sample: "
                         "pass its vertices, curve.points(), or a SmoothElastica")
    return hasattr(c, "curvature") and hasattr(c, "length")


def _curve_samples(c, infl_s: np.ndarray, n: int, samples_per_vertex: int):
    """affine_polyline's samples of an elastica: the arc lengths s of f~'s samples (f~(j) =
    c(s[j])), about samples_per_vertex x n, >= 3 per inflection-free piece, each inflection
    (``infl_s``) a sample; and those samples' indices (f~'s inflections). The curve's end is
    f~'s t = len(s) - 1."""
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
    return np.concatenate(s_parts), idx


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
    optimise=False keeps t1 at its start value (the simple construction, for comparison);
    max_iter: the golden-section iterations on t1 (default 100, >= 0; Gauss-Newton then polishes).

    curve_or_points: a SmoothElastica (sampled with samples_per_vertex * n arcs, its
    inflections taken exactly from the parameters and made sample points) or point data
    (N+1, 2) (the samples themselves; about 20 per vertex wanted; `inflections` optionally
    gives their sample indices, otherwise they are detected).
    The replacement curve's tangents: the paper's p_{j+1} - p_{j-1}, or for an elastica with
    exact_tangents=True (default) its exact tangents, or for points the given `tangents`
    (N+1, 2): its deviation is then O(h^4) instead of O(h^3), which the k_i A^(-2/3) of
    fine polylines need (their error grows like h^3/H^4 otherwise). Raises ValueError /
    DomainError (inflection with split_inflections=False, a straight elastica; n too small
    for an elastica: :class:`EdgeCountError`) on bad input."""
    n = as_size(n, "affine_polyline: n", 3)
    is_curve = _is_curve(curve_or_points, "affine_polyline")
    if n > lib.EL_AFFINE_MAX_EDGES:   # bounded work, and before sampling n points
        raise DomainError(lib.EL_EDOM, f"affine_polyline: n = {n} edges asked; at most "
                          f"{lib.EL_AFFINE_MAX_EDGES} (EL_AFFINE_MAX_EDGES) are built")
    samples_per_vertex = as_int(samples_per_vertex, "affine_polyline: samples_per_vertex", 1)
    if samples_per_vertex * n > 10 ** 8:
        raise ValueError(f"affine_polyline: {samples_per_vertex} samples per vertex for {n} "
                         "vertices are more than 1e8 samples")
    if is_curve:
        c = curve_or_points
        if not c.length > 0:
            raise ValueError("the elastica has zero length")
        # far from (0, 0): sampled in a local frame (its start(s) moved exactly), the
        # vertices moved back (the C polyline computes relative to its own local origin,
        # but samples taken at (512345.678, 5012345.432) carry the offset's rounding)
        local = _local_source(c, True)
        if local is not None:
            c = local[0]
        infl_s = elastica_inflections(c)
        infl = len(infl_s)     # the C status's causes named (seed 002 (1), §4.4)
        if infl and not split_inflections:
            raise DomainError(lib.EL_EDOM, f"affine_polyline: the elastica has {infl} "
                              f"inflection{'s' * (infl > 1)} and split_inflections=False")
        if not np.any(c.curvature(np.linspace(0.0, c.length, 101))):
            raise DomainError(lib.EL_EDOM, "affine_polyline: the elastica is straight (no "
                              "affine arc length: seed 002 (1))")
        s_samp, idx = _curve_samples(c, infl_s, n, samples_per_vertex)
        samples = np.ascontiguousarray(c.points(s_samp))
        tangents = None
        if exact_tangents:
            theta = c.angle(s_samp)
            tangents = np.ascontiguousarray(np.c_[np.cos(theta), np.sin(theta)])
        try:
            pts, t, ps, A, psi, ip, S = _run(samples, tangents, idx, n, split_inflections, skip,
                                             max_iter, skip_frac, fit_ends, optimise)
        except DomainError as exc:      # the one cause left
            pieces = f"{infl + 1} inflection-free pieces, " if infl else ""
            cause = (f"{n} edges are too few for the elastica's turning ({pieces}"
                     f"{_turning(c):.3g} rad of tangent turning: about 3 edges per piece and "
                     "per turn at least)")
            raise EdgeCountError(exc.status, f"affine_polyline: {cause}", cause) from None
        j = np.clip(np.floor(t).astype(int), 0, len(s_samp) - 2)
        s = s_samp[j] + (t - j) * (s_samp[j + 1] - s_samp[j])
        for _ in range(3):   # project the vertices onto the elastica (Newton on the foot
            th = c.angle(s, extrapolate=True)   # point; the last may lie past its end)
            s = s + np.einsum("ij,ij->i", pts - c.points(s, extrapolate=True),
                              np.c_[np.cos(th), np.sin(th)])
        # a vertex on f~ (t up to its last sample, within fit_ends' landing, 1e-7 of a
        # sample) is on the curve: its foot in [0, length], not the Newton's rounding past
        # the end (fit_ends, 60 edges: 2.4e-11 past it, so that curve.points(s) raised)
        on = t <= len(s_samp) - 1 + 1e-7
        s = np.where(on, np.clip(s, 0.0, c.length), np.maximum(s, 0.0))
        if local is not None:
            pts = pts + local[1]
        return AffinePolyline(pts, t, s, ps, A, psi, ip, S)
    samples, tan, infl = _samples_checked(curve_or_points, tangents, inflections)
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
    b2) has curvature det(b1-b0, b2-b1) / (2|b1-b0|^3) at b0 and / (2|b2-b1|^3) at b2
    (``bs``: the BSpline, degree 2, clamped).
    G2 means left == right."""
    B = _quadratic_beziers(bs)
    d0, d1 = B[:, 1] - B[:, 0], B[:, 2] - B[:, 1]
    area = d0[:, 0] * d1[:, 1] - d0[:, 1] * d1[:, 0]
    k_start = area / (2.0 * np.linalg.norm(d0, axis=1) ** 3)
    k_end = area / (2.0 * np.linalg.norm(d1, axis=1) ** 3)
    return k_end[:-1], k_start[1:]
