"""Keyline preparation (seed 000 §5.3) over the C library: PCA plane fit of a 3D
polyline, equilateral open-polygon resampling, PCA re-normalisation of the 2D
polygon and the RDP-style inflection estimate.

Typical pipeline::

    xy, frame = plane_fit(xyz)                 # 3D keyline -> x'y' plane coordinates
    poly = resample_equilateral(xy, r)          # equilateral open polygon, segment r
    poly2, frame2 = pca_normalize(poly)         # x''y'' coordinates
    i = find_inflection(poly2)                  # vertex index of the inflection estimate
    p3d = frame.to_3d(frame2.to_parent(poly2[i]))
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Tuple

import numpy as np

from ._ffi import (DomainError, ElasticaError, as_int, as_point_array, as_points, as_real,
                   check, dptr, ffi, lib, transpose_hint)
from ._values import ValueEquality, field_summary

__all__ = ["Frame", "Frame2D", "Inflection", "PreparedKeyline", "plane_fit",
           "resample_equilateral", "RESAMPLE_MAX_VERTICES", "pca_normalize", "find_inflection",
           "find_inflection_info", "prepare_keyline", "KEYLINE_STEPS", "keyline_runs", "keyline_step",
           "ZIGZAG", "resampled_polygon"]


def _c_struct(ctype: str, obj, names) -> object:
    """A new C struct of ``ctype`` whose vector fields ``names`` are copied from ``obj``."""
    f = ffi.new(ctype)
    for name in names:
        field, v = getattr(f, name), getattr(obj, name)
        for j in range(len(field)):
            field[j] = float(v[j])
    return f


def _map_points(fn, frame, a, din: int, dout: int, what: str) -> np.ndarray:
    """fn(frame, n, in, out) on the points a (n, din) or one point (din,): (n, dout) or (dout,)."""
    single = np.ndim(a) == 1
    pts = _points(a, "xyz"[:din], din)
    out = np.empty((pts.shape[0], dout))
    check(fn(frame._c(), pts.shape[0], dptr(pts), dptr(out)), what)
    return out[0] if single else out


def _points(a, name: str, dim: int) -> np.ndarray:
    """(n, dim) float64 C-contiguous; a single point (dim,) is accepted as (1, dim)."""
    arr = as_point_array(a, name, dim)
    if arr.ndim == 1 and arr.shape[0] == dim:
        arr = arr[None, :]
    return as_points(arr, name, dim)


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class Frame(ValueEquality):
    """Orthonormal frame of a PCA plane fit (seed 000 §5.3).

    ``origin`` is the centroid, ``e1`` the first principal axis (x', pointing
    from the first to the last input point), ``e3`` the plane normal (z'), with
    ``e2 = e3 x e1``; ``eigenvalues`` of the covariance matrix, decreasing;
    ``rms`` the root-mean-square distance of the fitted points from the plane.
    """
    origin: np.ndarray
    e1: np.ndarray
    e2: np.ndarray
    e3: np.ndarray
    eigenvalues: np.ndarray
    rms: float

    @property
    def matrix(self) -> np.ndarray:
        """(3, 3) orthogonal matrix with columns e1, e2, e3."""
        return np.column_stack([self.e1, self.e2, self.e3])

    def _c(self):
        return _c_struct("el_frame *", self, ("origin", "e1", "e2", "e3"))

    def to_3d(self, xy) -> np.ndarray:
        """Map plane coordinates ``xy`` (n, 2) (or one point (2,)) to 3D: origin + x' e1 + y' e2."""
        return _map_points(lib.el_frame_to_3d, self, xy, 2, 3, "Frame.to_3d")

    def project(self, xyz, return_z: bool = False):
        """Plane coordinates (n, 2) of 3D points ``xyz`` (n, 3); with ``return_z`` also the
        signed distances z' (n,) from the plane."""
        single = np.ndim(xyz) == 1
        pts = _points(xyz, "xyz", 3)
        xy = np.empty((pts.shape[0], 2))
        z = np.empty(pts.shape[0])
        check(lib.el_frame_project(self._c(), pts.shape[0], dptr(pts), dptr(xy), dptr(z)),
              "Frame.project")
        if single:
            xy, z = xy[0], z[0]
        return (xy, z) if return_z else xy


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class Frame2D(ValueEquality):
    """2D PCA frame (seed 000 §5.3, x''y''): ``origin`` the centroid, ``f1`` the
    first principal axis with f1.x > 0, ``f2`` = f1 turned by +90 degrees
    (so f2.y > 0), ``eigenvalues`` decreasing."""
    origin: np.ndarray
    f1: np.ndarray
    f2: np.ndarray
    eigenvalues: np.ndarray

    def _c(self):
        return _c_struct("el_frame2d *", self, ("origin", "f1", "f2"))

    def to_local(self, xy) -> np.ndarray:
        """Parent (x'y') coordinates ``xy`` ((n, 2) or (2,)) -> this frame's x''y'' coordinates."""
        return _map_points(lib.el_frame2d_to_local, self, xy, 2, 2, "Frame2D.to_local")

    def to_parent(self, xy) -> np.ndarray:
        """This frame's x''y'' coordinates ``xy`` ((n, 2) or (2,)) -> parent (x'y') coordinates."""
        return _map_points(lib.el_frame2d_to_parent, self, xy, 2, 2, "Frame2D.to_parent")


def plane_fit(xyz) -> Tuple[np.ndarray, Frame]:
    """PCA plane fit of a 3D polyline ``xyz`` (n >= 3 points, shape (n, 3)).

    Returns ``(xy, frame)``: the (n, 2) coordinates x', y' of the points
    projected on the fitted plane, and the :class:`Frame` (``frame.to_3d(xy)``
    maps back). Raises ValueError for bad input, SingularError if all points
    are equal.
    """
    pts = as_points(xyz, "plane_fit: xyz", 3, min_rows=3)
    n = pts.shape[0]
    f = ffi.new("el_frame *")
    xy = np.empty((n, 2))
    rms = ffi.new("double *")
    check(lib.el_plane_fit(dptr(pts), n, f, dptr(xy), rms), "plane_fit")
    frame = Frame(origin=np.array(list(f.origin)), e1=np.array(list(f.e1)),
                  e2=np.array(list(f.e2)), e3=np.array(list(f.e3)),
                  eigenvalues=np.array(list(getattr(f, "lambda"))),
                  rms=float(rms[0]))
    return xy, frame


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class Resampled(ValueEquality):
    """Details of an equilateral resampling: ``s`` the arc-length position of each
    vertex along the input (from the start end), ``reversed`` True when the walk
    started at the input's last point, ``remainder`` the input length left after
    the stop point."""
    s: np.ndarray
    reversed: bool
    remainder: float

    __repr__ = field_summary


#: The most vertices resample_equilateral builds (EL_RESAMPLE_MAX_VERTICES): a segment r
#: below the polyline's length / (RESAMPLE_MAX_VERTICES - 1) is refused (DomainError).
RESAMPLE_MAX_VERTICES = int(lib.EL_RESAMPLE_MAX_VERTICES)


def resample_equilateral(xy, r: float, return_info: bool = False):
    """Equilateral open polygon of segment ``r`` approximating the polyline
    ``xy`` (n, 2), seed 000 §5.3: start at the left end (smaller x), each next
    vertex the point of the polyline at distance r further along it (the one
    nearest the far end when several), stop when there is none.

    Returns the (m, 2) vertices; with ``return_info`` also a :class:`Resampled`.
    Raises ValueError for r <= 0, r larger than the curve, NaN/inf, fewer than
    2 points; SingularError if all points are equal.
    """
    pts = as_points(xy, "xy", 2)
    r = as_real(r, "resample_equilateral: r")
    res = ffi.new("el_resample_result *")
    st = lib.el_resample_equilateral(dptr(pts), pts.shape[0], r, res)
    if st == lib.EL_EDOM:
        length = float(np.sum(np.hypot(*np.diff(pts, axis=0).T)))
        limit = lib.EL_RESAMPLE_MAX_VERTICES
        if np.isfinite(length) and length / r > limit - 1:
            raise DomainError(st, f"resample_equilateral: r = {r:.3g} would make up to "
                              f"{length / r:.3g} vertices on this {length:.6g}-long polyline; "
                              f"at most {limit} (EL_RESAMPLE_MAX_VERTICES): r >= "
                              f"{length / (limit - 1):.3g}")
        raise DomainError(st, "resample_equilateral: the polyline's coordinates or length are "
                          "beyond double's range")
    if st == lib.EL_EINVAL:      # which of the header's causes (NaN/inf points: as_points)
        why = None
        if pts.shape[0] < 2:
            why = f"{pts.shape[0]} point: a polyline needs at least 2"
        elif not r > 0.0:
            why = f"r = {r:g}: the segment length must be positive"
        else:
            # r beyond every point's distance from A_1 (the end of smaller x): no A_2
            start = pts[-1] if pts[-1, 0] < pts[0, 0] else pts[0]
            reach = float(np.max(np.hypot(pts[:, 0] - start[0], pts[:, 1] - start[1])))
            if reach < r:
                why = (f"r = {r:.6g} is longer than the polyline reaches: its points lie within "
                       f"{reach:.6g} of its start (the end of smaller x); a polygon needs a "
                       "smaller r")
        if why:
            raise ElasticaError(st, f"resample_equilateral: {why}")
    check(st, "resample_equilateral")
    try:
        m = int(res.n)
        out = np.frombuffer(ffi.buffer(res.xy, 16 * m), dtype=np.float64).reshape(m, 2).copy()
        info = Resampled(s=np.frombuffer(ffi.buffer(res.s, 8 * m), dtype=np.float64).copy(),
                         reversed=bool(res.reversed), remainder=float(res.remainder))
    finally:
        lib.el_resample_free(res)
    return (out, info) if return_info else out


# A resampled fit's polyline: the points' own, unless it is longer than ZIGZAG times the
# polyline through the medians of their runs (keyline_runs): then it is their noise's
# zigzag, and its equilateral polygon runs back and forth along the curve (3000 points,
# noise 2 % of a 4 m curve: the points' polyline 83 x the medians'; their polygon's fit
# lay 1.25 x the unresampled fit's rms from the points, the medians' 1.02 x). Below it
# the points' own (2000 points, noise 0.5 mm: 1.15 x; the medians' chords cost 5 % rms).
ZIGZAG = 1.5


def resampled_polygon(points, step: float) -> np.ndarray:
    """The polygon a fit of points (n, 2) resampled with segment ``step`` fits, in the
    points' order: the equilateral polygon (:func:`resample_equilateral`) of their own
    polyline, or of :func:`keyline_runs` where theirs zigzags (longer than ZIGZAG times
    that one), ended at the first and last point: the walk stops up to a step short of
    the far end (seed 000 §5.3), so that point is added (its side shorter), as the first
    where the medians' walk started elsewhere. A fit then covers the points to their ends."""
    pts = as_points(points, "resampled_polygon: points", 2, min_rows=2)
    step = as_real(step, "resampled_polygon: step")
    src = pts
    if len(pts) > 2 * KEYLINE_STEPS:
        runs = keyline_runs(pts)
        if _length(pts) > ZIGZAG * _length(runs):
            src = np.ascontiguousarray(runs)
    poly, info = resample_equilateral(src, step, return_info=True)
    if info.reversed:
        poly = poly[::-1]
    size = 1e-12 * (1.0 + float(np.abs(pts).max()))
    head = [pts[:1]] if np.hypot(*(poly[0] - pts[0])) > size else []
    tail = [pts[-1:]] if np.hypot(*(poly[-1] - pts[-1])) > size else []
    return np.ascontiguousarray(np.vstack(head + [poly] + tail))


def _length(xy) -> float:
    return float(np.sum(np.hypot(*np.diff(xy, axis=0).T)))


def pca_normalize(xy) -> Tuple[np.ndarray, Frame2D]:
    """PCA re-normalisation of 2D points ``xy`` (n >= 2, shape (n, 2)), seed 000 §5.3:
    returns the coordinates in the frame of their centroid and first principal
    axis (x''), and the :class:`Frame2D` (``frame.to_parent`` maps back)."""
    pts = as_points(xy, "pca_normalize: xy", 2, min_rows=2)
    f = ffi.new("el_frame2d *")
    out = np.empty_like(pts)
    check(lib.el_pca_normalize(dptr(pts), pts.shape[0], f, dptr(out)), "pca_normalize")
    return out, Frame2D(origin=np.array(list(f.origin)), f1=np.array(list(f.f1)),
                        f2=np.array(list(f.f2)), eigenvalues=np.array(list(f.mu)))


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class Inflection(ValueEquality):
    """RDP-style inflection estimate (seed 000 §5.3 steps (1)-(4)): ``index`` the
    estimated vertex (point P+2 of step (4)), ``neighbor`` the adjacent vertex
    (the curvature changes sign on the edge between them), ``apex`` point 3,
    ``end`` point 2, ``iterations`` of step (3)."""
    index: int
    neighbor: int
    apex: int
    end: int
    iterations: int


def find_inflection_info(xy, side: int = 0) -> Inflection:
    """Like :func:`find_inflection`, returning the full :class:`Inflection`."""
    pts = as_points(xy, "find_inflection: xy", 2, min_rows=4)
    side = as_int(side, "find_inflection: side", -1, 1)
    info = ffi.new("el_inflection *")
    try:
        check(lib.el_find_inflection(dptr(pts), pts.shape[0], int(side), info), "find_inflection")
    except DomainError:
        raise DomainError(lib.EL_EDOM, "find_inflection: no inflection found: "
                          + _no_inflection_reason(pts)) from None
    return Inflection(index=int(info.index), neighbor=int(info.neighbor), apex=int(info.apex),
                      end=int(info.end), iterations=int(info.iterations))


def _no_inflection_reason(xy) -> str:
    """Why the points ``xy`` (n, 2) in their order give no one inflection a keyline splits
    at, in words a user can act on (the refusals of :func:`find_inflection` and
    :func:`fit_keyline`): a closed outline (its ends meet: QA F1, a tile section turning
    both ways 4 times was told it 'turns one way'), points on a line, points that turn one
    way, or a turning that changes sign more than once (several inflections: noise, or
    more pieces), each with what to do."""
    from .misfit import _nearly_closed
    p = np.asarray(xy, dtype=float)
    e = np.diff(p, axis=0)
    e = e[np.hypot(*e.T) > 0]
    cross = e[:-1, 0] * e[1:, 1] - e[:-1, 1] * e[1:, 0]
    size = float(np.max(np.ptp(p, axis=0))) if len(p) else 0.0
    turn = np.sign(cross[np.abs(cross) > 1e-12 * size * size]) if size > 0 else cross[:0]
    changes = int(np.count_nonzero(np.diff(turn))) if len(turn) else 0
    closed = _nearly_closed(p) if size > 0 else None
    pieces = ("cut it into open pieces with one inflection each (e.g. points[i:j], in curve "
              "order) and fit each with el.fit_keyline, or pieces that turn one way with el.fit")
    if closed is not None:
        return (f"the points form a closed outline (their ends lie {closed[0]:.3g} apart, "
                f"{closed[1]:.0%} of their extent; their polyline's turning changes sign "
                f"{changes} times), which has no one inflection to split at: {pieces}")
    if len(turn) == 0:
        return "the points lie on a line (no turning): fit them as one curve (el.fit)"
    if changes == 0:
        return ("the points turn one way (their polyline turns "
                f"{'left' if turn[0] > 0 else 'right'} at every vertex): a keyline splits at "
                "its inflection; fit them as one curve (el.fit)")
    return (f"their polyline's turning changes sign {changes} times, but neither side of its "
            "farthest point from the chord shows an inflection beyond that point's neighbours "
            "(an inflection at an end, or noise?): fit them as one curve (el.fit); where they "
            f"hold several inflections, {pieces}")


def find_inflection(xy, side: int = 0) -> int:
    """Index of the vertex estimated as the one global inflection of the open
    polygon ``xy`` (n >= 4, best on the resampled and re-normalised polygon),
    by the RDP-style method of seed 000 §5.3 steps (1)-(4).

    ``side`` picks point 2 of step (1): +1 the last vertex, -1 the first, 0
    automatic. Raises DomainError when the polygon shows no inflection
    (convex, collinear, closed), ValueError for bad input.
    """
    return find_inflection_info(xy, side).index


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class PreparedKeyline(ValueEquality):
    """The §5.3 pipeline's result (see :func:`prepare_keyline`).

    ``polygon`` (m, 2): the equilateral polygon in x''y'' coordinates (segment
    ``r``); ``inflection``: index of the estimated inflection vertex in it, or
    None when the polygon shows none; ``frame``: the plane fit's :class:`Frame`
    (None for 2D input); ``frame2d``: the re-normalisation :class:`Frame2D`
    (x'y' -> x''y''); ``rms_out_of_plane`` (0 for 2D input).
    """
    polygon: np.ndarray
    inflection: "int | None"
    r: float
    frame: "Frame | None"
    frame2d: Frame2D
    rms_out_of_plane: float

    __repr__ = field_summary

    def to_input(self, xy) -> np.ndarray:
        """Map x''y'' points (n, 2) (or one point) back to the input's coordinates:
        3D (n, 3) for 3D input, 2D (n, 2) otherwise."""
        parent = self.frame2d.to_parent(xy)
        return self.frame.to_3d(parent) if self.frame is not None else parent

    def sides(self) -> "Tuple[np.ndarray, np.ndarray]":
        """The two sides of the polygon, both starting at the inflection vertex:
        (inflection -> first vertex, inflection -> last vertex). Raises
        DomainError when there is no inflection."""
        if self.inflection is None:
            raise DomainError(lib.EL_EDOM, "prepare_keyline: no inflection found: "
                              + _no_inflection_reason(self.polygon))
        i = self.inflection
        return self.polygon[i::-1].copy(), self.polygon[i:].copy()


# A keyline's default resampling: the polyline through the medians of runs of n //
# KEYLINE_STEPS points (and the two end points), cut into KEYLINE_STEPS segments. The
# polyline through the points themselves is their noise's zigzag: an S tile 300 long,
# 3000 unevenly spaced points, noise 1 % of its size, ran 14845 (a step of 148: 2
# segments, "no inflection found"); a scan of 20 000 points, 0.3 mm noise, 7689 mm along
# a 330 mm curve. Resampled at 1/100 of the medians' run, the points' zigzag still threw
# the discrete joint up to 53 off the inflection at s = 150 (6 seeds, 1500 / 3000 points,
# 0.5 / 1 % noise); the medians' polygon kept it within 19 (the smooth keyline's, which
# fits the points themselves: within 10). Up to 2 KEYLINE_STEPS points, runs of one: the
# points' own polyline, as before.
KEYLINE_STEPS = 100


def keyline_runs(points) -> np.ndarray:
    """The polyline a keyline's default step is taken on and resampled from: the
    coordinate-wise medians of runs of n // KEYLINE_STEPS consecutive points (the last
    n mod that left out), between the first and the last point; (m, d) for points (n, d)
    in their order (up to 2 KEYLINE_STEPS points: the points themselves)."""
    pts = as_point_array(points, "keyline_runs: points")
    if pts.ndim != 2 or pts.shape[1] not in (2, 3) or len(pts) < 2:
        raise ValueError("keyline_runs: points must have shape (n, 2) or (n, 3), n >= 2, got "
                         f"{pts.shape}{transpose_hint(pts.shape, (2, 3))}")
    k = max(1, len(pts) // KEYLINE_STEPS)
    if k == 1:
        return pts.copy()
    runs = np.median(pts[:len(pts) // k * k].reshape(-1, k, pts.shape[1]), axis=1)
    return np.vstack([pts[:1], runs, pts[-1:]])


def keyline_step(points) -> float:
    """A keyline's default resampling step (fit_keyline's, `elastica fit --keyline`'s,
    the workbench's Resample 0): 1/KEYLINE_STEPS of the length of :func:`keyline_runs`
    (noise-robust: not of the points' own zigzag)."""
    runs = keyline_runs(points)
    return float(np.sum(np.linalg.norm(np.diff(runs, axis=0), axis=1))) / KEYLINE_STEPS


def prepare_keyline(points, r=None, side: int = 0) -> PreparedKeyline:
    """Seed 000 §5.3 in one call: PCA plane fit (3D input (n, 3) only),
    equilateral resampling with segment ``r``, PCA re-normalisation and the
    RDP-style inflection estimate (``side`` as in :func:`find_inflection`;
    ``inflection`` is None when the polygon shows none, e.g. a convex arc).
    ``r`` None: the default, :func:`keyline_runs` of the (plane) points resampled
    with segment :func:`keyline_step` of them."""
    pts = as_point_array(points, "points")
    frame, rms = None, 0.0
    if pts.ndim == 2 and pts.shape[1] == 3:
        xy, frame = plane_fit(pts)
        rms = frame.rms
    else:
        xy = as_points(pts, "points", 2)
    if r is None:
        xy = np.ascontiguousarray(keyline_runs(xy))
        r = keyline_step(xy)
    r = as_real(r, "prepare_keyline: r")
    poly = resample_equilateral(xy, r)
    poly2, f2 = pca_normalize(poly)
    try:
        infl = find_inflection(poly2, side) if len(poly2) >= 4 else None
    except DomainError:
        infl = None
    return PreparedKeyline(polygon=poly2, inflection=infl, r=float(r), frame=frame, frame2d=f2,
                           rms_out_of_plane=float(rms))
