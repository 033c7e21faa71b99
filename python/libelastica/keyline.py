"""The keyline pipeline (seed 000 §5): a keyline fitted as one G2 curve of two elasticae
that start at its inflection with opposite tangents and zero curvature (:func:`fit_keyline`,
:class:`KeylineFit`); the single-curve fit is :mod:`libelastica.fit`'s."""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ._ffi import (DomainError, as_int, as_point_array, as_positive, as_real, check,
                   dptr, ffi, lib, transpose_hint)
from ._interrupt import call
from ._quiet import quiet, say
from ._values import ValueEquality
from .core import SmoothElastica
from .cubic import SPARSE_POINTS, SparseWarning, smooth_fits_better
from .fit import (_MODE_NAMES, ConvergenceWarning, FitResult, OrderWarning, _make_curve,
                  judging_fit)
from .misfit import MisfitWarning, misfit, misfit_summary
from .order import order_summary, out_of_order

@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class KeylineFit(ValueEquality):
    """Result of :func:`fit_keyline`, the keyline as one G2 curve of two elasticae that
    start at the joint (the inflection) with opposite tangents and zero curvature.

    In the input's coordinates (3D for 3D input), as `elastica fit --keyline` and FreeCAD
    write them: :meth:`to_bspline`, ``joint`` (where the halves meet), ``ends`` (discrete:
    where the keyline ends), :meth:`side_points`; :meth:`side_curve` in the input's plane.
    In the fit's own frame x''y'' (``prepared``'s PCA frame: centroid at the origin,
    rotated; ``to_input`` maps it back): ``first`` (joint -> the polygon's first vertex)
    and ``second`` (joint -> its last; the resampling may run the points backwards), the
    sides' FitResults, whose ``points`` are the points of that side (from the joint
    outwards); ``joint_local``, ``ends_local``; ``prepared`` (a
    PreparedKeyline: polygon, frames). ``inflection``: the polygon vertex nearest the joint;
    ``inflection_estimate``: the RDP-style estimate of the preparation
    (``prepared.inflection``) the fit started from; ``input_distances``: each input
    point's signed distance (in its plane, + left of the keyline's direction of travel) to
    the keyline (``input_rms``, ``input_max_error``); ``misfit``: a :class:`libelastica.misfit.Misfit` where the
    input points lie far farther from it than their noise, else None; ``sparse``: a
    discrete keyline of few points far from them, the smooth keyline's input_rms
    (SparseWarning), else None; ``outliers``: the input points far from the keyline
    (el.fit's rule, OutlierWarning), counted from 0 in the input's order, () when none.
    """
    prepared: object
    inflection: int
    first: FitResult
    second: FitResult
    inflection_estimate: Optional[int] = None
    joint: Optional[np.ndarray] = None
    # each input point's signed distance (in its plane; + left of the keyline's direction of
    # travel, first point to last, as FitResult.distances; np.abs for the plain distances)
    # to the keyline: the polygon of both
    # discrete halves, or the smooth curve the points themselves were fitted to; the
    # sides' rms / max_error are the fitted points' (a discrete keyline's: the resampled
    # polygon's vertices, paired: 0.116 / 0.277 where the file's points lie 0.132 / 0.344)
    input_distances: Optional[np.ndarray] = None
    # discrete: where the keyline ends (2, dim), the feet of the input's end points on the
    # halves continued by their recursion (the polygon stops up to a step short, §5.3)
    ends: Optional[np.ndarray] = None
    joint_local: Optional[np.ndarray] = None      # joint, ends in x''y'' (the sides' frame)
    ends_local: Optional[np.ndarray] = None
    # the input points far farther from the keyline than their own noise: not one keyline
    # (libelastica.misfit.Misfit; its corner an index into the input points), else None
    misfit: Optional[object] = None
    # a discrete keyline of fewer than SPARSE_POINTS points far farther from them than the
    # smooth keyline: the smooth keyline's input_rms (SparseWarning), else None
    sparse: Optional[float] = None
    # the input points far from the keyline, standing apart from the others (el.fit's rule,
    # far_points of input_distances: spikes): indices into the input points, in their order
    # (a file's rows), as OutlierWarning.indices; () when none
    outliers: tuple = ()

    def __repr__(self) -> str:
        """A summary (the arrays are the data's size: print them by name)."""
        kind = "smooth" if isinstance(self.first.curve, SmoothElastica) else "discrete"
        n = len(self.input_distances) if self.input_distances is not None else None
        rms = f", input rms {self.input_rms:.3g}" if n else ""
        state = "converged" if self.first.converged and self.second.converged else \
            f"not converged (status {self.first.status or self.second.status})"
        return (f"KeylineFit({kind}, {n} points, inflection at vertex {self.inflection}{rms}, "
                f"sides rms {self.first.rms:.3g} / {self.second.rms:.3g}, {state}"
                f"{', misfit' if self.misfit is not None else ''})")

    @property
    def input_rms(self) -> float:
        return float(np.sqrt(np.mean(self.input_distances ** 2)))

    @property
    def input_max_error(self) -> float:
        return float(np.max(np.abs(self.input_distances)))

    def to_input(self, xy) -> np.ndarray:
        """x''y'' points ``xy`` (the sides' frame, (n, 2)) in the input's coordinates
        (PreparedKeyline.to_input)."""
        return self.prepared.to_input(xy)

    def side_points(self, which: str = "second", input_coords: bool = True) -> np.ndarray:
        """The fitted model points of one side, ``which`` "first" or "second" (default)
        (paired vertices or feet), in the input's coordinates (3D for 3D input;
        ``input_coords`` True, default) or in x''y'' (False)."""
        pts = self._side(which).model_points()
        return self.to_input(pts) if input_coords else pts

    def side_curve(self, which: str = "second", input_coords: bool = True):
        """The elastica of one side (from the joint outwards), moved into the input's
        coordinates (3D input: its plane's x'y', which ``prepared.frame.to_3d`` maps), or
        as fitted in x''y'' (``input_coords=False``): the start point mapped, phi turned by
        the frame's angle (x''y'' is a rotation and shift of the plane, Frame2D)."""
        c = self._side(which).curve
        if not input_coords:
            return c
        f = self.prepared.frame2d
        x0, y0 = f.to_parent(np.array([c.x0, c.y0]))
        turn = math.atan2(f.f1[1], f.f1[0])
        return dataclasses.replace(c, x0=float(x0), y0=float(y0), phi=float(c.phi + turn))

    def _side(self, which: str) -> FitResult:
        if which not in ("first", "second"):
            raise ValueError(f"KeylineFit: which must be 'first' or 'second', got {which!r}")
        return self.first if which == "first" else self.second

    def to_bspline(self, tol: Optional[float] = None, degree: int = 3, input_coords: bool = True):
        """The keyline as ONE B-spline for CAD, from the first point to the last through
        the joint: :func:`keyline_bspline` of the halves (smooth: within ``tol``, default
        1e-6 of its length, G2 at the joint exactly; discrete: the C2 cubic through both
        halves' vertices, to ``ends``), in the input's coordinates (3D poles for 3D input:
        the x''y'' B-spline's poles mapped by :meth:`to_input`, exact) as `elastica fit
        --keyline --dxf` and FreeCAD write it, or in x''y'' (``input_coords=False``).
        ``degree``: the smooth B-spline's, 3..7 (default 3; discrete: a cubic always)."""
        from .bspline import keyline_bspline
        b = keyline_bspline(self.first.curve, self.second.curve, tol, degree, self.ends_local)
        return b.mapped(self.to_input) if input_coords else b


def _polyline_distances(points, vertices, chunk_pairs: int = 1 << 21,
                        signed: bool = False) -> np.ndarray:
    """Each point's distance to the polyline through vertices (m >= 2), every segment
    looked at (no order assumed), points taken in chunks of chunk_pairs / (m - 1);
    ``signed``: + left of the nearest segment's direction (vertex i to i + 1), - right."""
    ax, ay = vertices[:-1, 0], vertices[:-1, 1]
    dx, dy = np.diff(vertices[:, 0]), np.diff(vertices[:, 1])
    inv = 1.0 / np.maximum(dx * dx + dy * dy, 1e-300)
    out = np.empty(len(points))
    step = max(1, chunk_pairs // len(ax))
    for i in range(0, len(points), step):     # x and y apart: a third of the temporaries
        wx = points[i:i + step, 0, None] - ax
        wy = points[i:i + step, 1, None] - ay
        u = np.clip((wx * dx + wy * dy) * inv, 0.0, 1.0)
        wx -= u * dx
        wy -= u * dy
        d2 = wx * wx + wy * wy
        out[i:i + step] = np.sqrt(np.min(d2, axis=1))
        if signed:
            j = np.argmin(d2, axis=1)
            rows = np.arange(len(j))
            left = dx[j] * wy[rows, j] - dy[j] * wx[rows, j] >= 0.0
            out[i:i + step] = np.where(left, out[i:i + step], -out[i:i + step])
    return out


def _keyline_options(model: str, kwargs: dict):
    fixed = dict(kwargs.pop("fixed", None) or {})
    max_iter, tol = kwargs.pop("max_iter", None), kwargs.pop("tol", None)
    if kwargs:
        raise ValueError(f"fit_keyline: unknown arguments {sorted(kwargs)} (the keyline is one "
                         "G2 curve: fixed={'h': ...} (discrete), max_iter and tol apply)")
    o = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(o)
    for name, value in fixed.items():
        if model != "discrete" or name != "h":
            raise ValueError(f"fit_keyline: only the discrete h can be fixed (both sides), "
                             f"got {name!r}: the joint's G2 conditions tie the other parameters")
        v = as_real(value, "fit_keyline: fixed h")
        if not v > 0:
            raise ValueError(f"fit_keyline: fixed h must be > 0, got {value!r}")
        o.fixed[2] = 1
        o.value[2] = v
    if max_iter is not None:
        o.max_iter = as_int(max_iter, "fit_keyline: max_iter", 1)
    if tol is not None:
        o.tol = as_positive(tol, "fit_keyline: tol")
    return o


# A keyline is checked against one elastica through all its points: where that one turns
# one way and the keyline does not halve its rms (KEYLINE_GAIN), the points show no
# inflection. Measured on 60 noisy arcs (radius 50, turning 0.3-3 rad, noise 0.05-1 % of the
# length, both models): the estimate split 112 of the 120 at an inflection of noise, 74
# within 3 vertices of an end (a ValueError then), 38 fitted, at 0.96 to 74 x the one-piece
# rms (47.5 for 0.64); on 600 keylines of keyline_data.py (inflection at 15 % to 85 % of the
# length) the one-piece fit turned one way 50 times, the keyline at most 0.19 x its rms
# (where it turns both ways, it may fit sparse noisy sides better than the keyline: no
# verdict). A side left with fewer than MIN_SIDE points (the joint slid to an end) is no
# keyline either.
KEYLINE_GAIN = 0.5
MIN_SIDE = 4


def _solve_keyline(model: str, data, split: int, o):
    """el_fit_keyline_{model} of data split at vertex / point split: (status, the two
    results, each side's indices into data from the joint outwards, distances, feet)."""
    n = len(data)
    dist, foot, sides = np.empty(n), np.empty(n), np.empty(n, dtype=np.intc)
    res = [ffi.new(f"el_fit_{model}_result *") for _ in range(2)]
    if model == "discrete":
        joint = ffi.new("size_t *")
        st = call(lib.el_fit_keyline_discrete, dptr(data), n, split, o, res[0], res[1], joint,
                  dptr(dist), dptr(foot), ffi.cast("int *", ffi.from_buffer(sides)),
                  keep=(data, dist, foot, sides))      # Ctrl-C: the CLI's (_interrupt)
    else:
        st = call(lib.el_fit_keyline_smooth, dptr(data), n, split, o, res[0], res[1], dptr(dist),
                  dptr(foot), ffi.cast("int *", ffi.from_buffer(sides)), keep=(data, dist, foot, sides))
    if st == lib.EL_EDOM:     # el_fit_keyline_*: a side is not inflectional
        raise DomainError(lib.EL_EDOM, "fit_keyline: a side of the joint fit is not "
                          "inflectional: the points show no inflection a keyline can split "
                          "at; fit them as one curve")
    if st not in (lib.EL_OK, lib.EL_ENOCONV, lib.EL_EMAXITER):
        check(st, "fit_keyline")
    if model == "discrete":
        js = int(joint[0])
        idx = [np.arange(js, -1, -1), np.arange(js, n)]
    else:
        idx = [np.nonzero(sides == c)[0] for c in range(2)]
        idx = [i[np.argsort(foot[i], kind="stable")] for i in idx]      # from the joint outwards
    return st, res, idx, dist, foot


def _check_keyline_split(polygon, side_points, split: int, keyline_rms: Optional[float] = None) -> None:
    """DomainError when the keyline's joint slid to an end or its two elasticae do not fit
    the points twice as well as one elastica turning one way (an inflection of noise). The
    verdict is the data's, by the discrete model on the prepared polygon: keyline_rms, its
    discrete keyline's (fitted here from the vertex split when None: the smooth one-piece
    fit of an S of 1000 points took 37 ms, where the smooth keyline takes 3)."""
    if min(side_points) < MIN_SIDE:
        raise DomainError(lib.EL_EDOM, f"fit_keyline: the joint slid to an end ({min(side_points)} of "
                          f"{sum(side_points)} points on one side): the points show no inflection a "
                          "keyline can split at; fit them as one curve")
    polygon = np.ascontiguousarray(polygon)
    one = judging_fit(polygon, model="discrete")     # a verdict only: no back-and-forth gate
    kappa = one.curve.curvature()
    if kappa.min() < 0.0 < kappa.max():
        return
    if keyline_rms is None:
        o = ffi.new("el_fit_options *")
        lib.el_fit_options_defaults(o)
        _, _, _, dist, _ = _solve_keyline("discrete", polygon, split, o)
        keyline_rms = float(np.sqrt(np.mean(dist ** 2)))
    if keyline_rms > KEYLINE_GAIN * one.rms:
        raise DomainError(lib.EL_EDOM, f"fit_keyline: no inflection the points show: two elasticae "
                          f"joined at one fit them at rms {keyline_rms:.3g}, one elastica turning one way "
                          f"at {one.rms:.3g}; fit them as one curve")


def fit_keyline(points, r: Optional[float] = None, model: str = "discrete", side: int = 0,
                *, _inner: bool = False, **kwargs) -> KeylineFit:
    """Seed 000 §5 as one problem: plane fit (3D input), equilateral resampling with
    segment ``r`` (default None: the polyline through the medians of runs of the points,
    cut into KEYLINE_STEPS segments, prep.keyline_runs / keyline_step: noise-robust),
    PCA re-normalisation, the
    inflection estimate, then one G2 curve of two elasticae sharing the joint, its
    tangent and zero curvature there. The joint starts at the refined inflection
    estimate (each side fitted alone, the zeros of their curvature) and moves along the
    data: smooth, the points themselves (in x''y'') are fitted by orthogonal distance,
    each point on either side; discrete, the polygon's vertex i pairs with vertex i of
    its side and the split vertex moves while the fit improves; h is free on both sides
    (§5.4, Table 1) or held with ``fixed={"h": r}``. ``model``: "discrete" (default) or
    "smooth", as above. ``side``: where the inflection estimate's step (1) takes its
    second point (:func:`find_inflection`): +1 the last point, -1 the first, 0 automatic.
    ``max_iter``, ``tol`` apply.
    The result's B-spline, joint and ends are in the input's coordinates, its sides'
    FitResults in the PCA frame x''y'' (:class:`KeylineFit`).
    Raises DomainError when the points show no inflection: none found, or one of their
    noise (the joint within MIN_SIDE points of an end, or two elasticae fitting the
    polygon less than twice as well as one turning one way: _check_keyline_split). Warns
    (MisfitWarning, ``misfit``) where the points lie far farther from the keyline than their
    own noise (:func:`libelastica.misfit.misfit`: a corner, which no G2 joint fits), and
    (SparseWarning, ``sparse``) where a discrete keyline of fewer than SPARSE_POINTS points
    lies far farther from them than the smooth keyline (:func:`smooth_fits_better`),
    (OutlierWarning, ``outliers``) where input points lie far from it, standing apart (el.fit's
    rule: spikes), and (MisfitWarning) where a side's points show an inflection of their
    own (a 3-piece profile; ``_inner``, private: that check's own fits, not checked again)."""
    from .prep import prepare_keyline
    if model not in ("discrete", "smooth"):
        raise ValueError(f"fit_keyline: model must be 'discrete' or 'smooth', got {model!r}")
    pts = as_point_array(points, "fit_keyline: points")
    if pts.ndim != 2 or pts.shape[1] not in (2, 3) or len(pts) < 4:
        raise ValueError("fit_keyline: points must have shape (n, 2) or (n, 3), n >= 4, got "
                         f"{pts.shape}{transpose_hint(pts.shape, (2, 3))}")
    if not np.all(np.isfinite(pts)):
        raise ValueError("fit_keyline: points must be finite (no NaN/inf)")
    unordered = out_of_order(pts)    # resampled along their polyline: a cloud's is no curve's
    if unordered.order is not None:
        say(f"fit_keyline: {order_summary(unordered)}: resampled in their order; "
            "fit points[el.curve_order(points)]", OrderWarning, stacklevel=2)
    side = as_int(side, "fit_keyline: side (-1 the first point, +1 the last, 0 automatic)", -1, 1)
    if r is not None:
        r = as_positive(r, "fit_keyline: r (the resampling segment, None: automatic)")
    o = _keyline_options(model, dict(kwargs))
    prep = prepare_keyline(pts, r, side)
    try:
        a, b = prep.sides()                    # DomainError when there is no inflection
        if len(a) < MIN_SIDE or len(b) < MIN_SIDE:
            raise DomainError(lib.EL_EDOM, f"fit_keyline: the inflection estimate lies {min(len(a), len(b)) - 1} "
                              f"of the resampled polygon's {len(prep.polygon) - 1} segments from an end: "
                              "no inflection a keyline "
                              "can split at (noise near an end of points that turn one way?); fit them as one curve")
    except DomainError:
        from .misfit import _nearly_closed
        from .prep import _no_inflection_reason
        xy = prep.frame.project(pts) if prep.frame is not None else pts[:, :2]
        if _nearly_closed(xy) is not None:   # (QA F1: its resampled polygon is no outline's)
            raise DomainError(lib.EL_EDOM, "fit_keyline: no inflection found: "
                              + _no_inflection_reason(xy)) from None
        if unordered.order is None:
            raise
        # resampled in an order that is no curve's, the polygon's turns are the shuffle's:
        # 'fit them as one curve' was wrong advice (QA20 F9: in curve order, rms 0.128)
        raise DomainError(lib.EL_EDOM, "fit_keyline: no inflection found along the points in their "
                          f"order, which is no curve's (their polyline {unordered.given / unordered.along:.3g} "
                          "times as long as in curve order); fit them in curve order: "
                          "el.fit_keyline(points[el.curve_order(points)]) (the command line: "
                          "--order curve)") from None
    i0 = int(prep.inflection)
    if model == "discrete":
        data = np.ascontiguousarray(prep.polygon)
        split = i0
    else:
        xy = prep.frame.project(pts) if prep.frame is not None else pts[:, :2]
        data = np.ascontiguousarray(prep.frame2d.to_local(xy))
        split = int(np.argmin(np.linalg.norm(data - prep.polygon[i0], axis=1)))
        split = min(max(split, 3), len(data) - 4)
    n = len(data)
    if n < 7:
        raise ValueError("fit_keyline: fewer than 7 points")
    st, res, idx, dist, foot = _solve_keyline(model, data, split, o)
    fits = []
    for c in range(2):
        sp = data[idx[c]]
        s = foot[idx[c]].copy() if model == "smooth" else None
        fits.append(FitResult(
            curve=_make_curve(model, res[c].params, len(idx[c])),
            initial=_make_curve(model, res[c].initial, len(idx[c])),
            rms=float(res[c].rms), max_error=float(res[c].max_error),
            iterations=int(res[c].iterations), status=int(st), ipopt_status=int(res[c].ipopt_status),
            candidates=1, s=s, param_mode=_MODE_NAMES.get(int(res[c].param_mode)) if model == "smooth" else None,
            # per side: + = left of that side's curve, which runs away from the joint
            distances=dist[idx[c]] * (-1.0 if c == 0 else 1.0), foot_s=foot[idx[c]].copy(),
            distance="orthogonal" if model == "smooth" else "paired",
            used_ipopt=bool(res[c].used_ipopt), points=sp))
    _check_keyline_split(prep.polygon, [len(f.points) for f in fits], i0,
                         float(np.sqrt(np.mean(dist ** 2))) if model == "discrete" else None)
    J = np.array([fits[1].curve.x0, fits[1].curve.y0])
    infl = int(np.argmin(np.linalg.norm(prep.polygon - J, axis=1)))
    if model == "discrete":
        xy = prep.frame.project(pts) if prep.frame is not None else pts[:, :2]
        local = prep.frame2d.to_local(xy)
        tails, ends = _keyline_tails([f.curve for f in fits], local[[0, -1]])
        polygon = np.vstack([tails[0][::-1], fits[0].curve.points()[::-1],
                             fits[1].curve.points()[1:], tails[1]])
        inputs = _polyline_distances(local, polygon, signed=True)
        # (+ left of the input's travel: the resampling may walk from its last point)
        if np.linalg.norm(local[0] - polygon[0]) > np.linalg.norm(local[0] - polygon[-1]):
            inputs = -inputs
    else:
        inputs, ends, local = dist.copy(), None, data    # the input points themselves were fitted
    # the points' noise against the keyline's distances to them (a held h: its own cost)
    # (no stray points tried: the others' fit would be one elastica's, not a keyline's)
    m = misfit(local, inputs, strays=False) if not kwargs.get("fixed") else None
    if m is not None:
        said = misfit_summary(m, what="one keyline (its joint is an inflection, G2)")
        say(f"fit_keyline: {said}", MisfitWarning, stacklevel=2)
    if m is None and not _inner and not kwargs.get("fixed"):   # (a corner: misfit said it)
        _second_inflection(fits, local)
    # spikes: el.fit's OutlierWarning, the input's own numbering (the sides' FitResults
    # number their own points; QA23: a scan's 3 spikes were never said)
    far = _input_outliers(local, inputs)
    sparse = None
    if model == "discrete":   # a polygon resampled from few points cuts their bends (QA17 W4)
        rms = float(np.sqrt(np.mean(inputs ** 2)))
        sparse = smooth_fits_better(pts, rms, keyline={"r": r, "side": side})
        if sparse is not None:
            say(f"fit_keyline: the discrete keyline lies {rms:.3g} from the {len(pts)} "
                f"points (rms), the smooth keyline {sparse:.3g}: fewer than "
                f"{SPARSE_POINTS} points resample to a polygon that cuts their bends; "
                "use model='smooth'", SparseWarning, stacklevel=2)
    if st != lib.EL_OK:     # as fit's (QA: both sides at status 6, silently); not before a refusal
        say(f"fit_keyline: not converged: {ffi.string(lib.el_strerror(st)).decode()} "
            f"(status {st})", ConvergenceWarning, stacklevel=2)
    return KeylineFit(prepared=prep, inflection=infl, first=fits[0], second=fits[1],
                      inflection_estimate=i0, joint=prep.to_input(J), input_distances=inputs,
                      ends=None if ends is None else prep.to_input(ends), joint_local=J,
                      ends_local=ends, misfit=m, sparse=sparse, outliers=far)


def _second_inflection(fits, local) -> None:
    """MisfitWarning where a side's points show an inflection of their own: a profile of 3
    pieces, of which the keyline fits 2 (QA23: 4 of 20 three-piece mouldings, rms 1.8-3.3 x
    the true curve's, were said nothing). A side is judged as misfit.split_hint judges few
    points: its one elastica above SPLIT_RATIO x the points' noise level, and a keyline of
    that side's points within SPLIT_GAIN x its rms (the discrete one, fitted to their
    resampled polygon: the smooth one took 0.3-0.9 s of a side of 2000 points). ``local``: the input
    points in x''y'', the side's joint named as the input point nearest it."""
    from ._ffi import as_points
    from .misfit import SPLIT_GAIN, SPLIT_RATIO, _Figures
    for c, f in enumerate(fits):
        pts = np.ascontiguousarray(f.points)
        if len(pts) < 4 * MIN_SIDE:
            continue
        try:
            # the cheap conditions first (the noise level's windows, judged on every side,
            # cost a smooth 1000-point keyline 8 -> 20 ms): the side's own inflection, then
            from .prep import prepare_keyline
            prep = prepare_keyline(pts)           # (no keyline fit)
            i = prep.inflection
            if i is None or min(i, len(prep.polygon) - 1 - i) < MIN_SIDE:
                continue
            # el_fit_noise's figure (C), never above noise_level's (its max), each once
            fig = _Figures(as_points(pts, "points", 2, 4))
            if not f.rms > SPLIT_RATIO * fig.plain:
                continue
            if len(fig.seen) < 4 or not f.rms > SPLIT_RATIO * fig.level:   # (noise_level's)
                continue
            with quiet():     # (this thread's warnings only: _quiet.py)
                kf = fit_keyline(pts, _inner=True)   # (discrete: a polygon of ~60 vertices)
        except (ValueError, ArithmeticError, RuntimeError):
            continue
        if not kf.input_rms <= SPLIT_GAIN * f.rms:
            continue
        at = int(np.argmin(np.linalg.norm(local - np.asarray(kf.joint)[:2], axis=1)))
        say(MisfitWarning(
            f"fit_keyline: the points show a second inflection, near input point {at} "
            f"(counted from 0) on the {('first', 'second')[c]} side: two elasticae joined there "
            f"fit that side's {len(pts)} points at rms {kf.input_rms:.3g}, the keyline's one "
            f"at {f.rms:.3g}; a keyline fits 2 pieces, these points are 3: split them at "
            f"point {at} and fit each part"), stacklevel=3)


def _input_outliers(local, inputs) -> tuple:
    """The input points far from the keyline (el.fit's rule: far_points of their distances
    ``inputs``, ``local`` their x''y''), warned as el.fit warns them (OutlierWarning, the
    points counted from 0 in the input's order); their indices. A spiky roof-tile scan
    (QA23): fit warned points 26, 141, 698, fit_keyline nothing."""
    from .fit import far_points
    from .misfit import OutlierWarning, outliers_summary
    far = tuple(int(i) for i in far_points(inputs, local))
    if far:
        say(OutlierWarning("fit_keyline: " + outliers_summary(inputs, list(far)), far),
            stacklevel=3)
    return far


def _keyline_tails(halves, end_points):
    """Each discrete half continued to the foot of the input's end point nearer its far
    end (DiscreteElastica.continued_to), and those feet (2, 2): the halves fit the
    resampled polygon, which stops up to a step short of the points (seed 000 §5.3)."""
    tails, ends = [], []
    for c in halves:
        far = c.points()[-1]
        e = end_points[int(np.argmin(np.linalg.norm(end_points - far, axis=1)))]
        tails.append(c.continued_to(e))
        ends.append(tails[-1][-1] if len(tails[-1]) else far)
    return tails, np.array(ends)


__all__ = ["KeylineFit", "fit_keyline"]
