"""The order of points along the curve they sample, for points without one of their own
(a scanner's export, a point picker's clicks): :func:`curve_order`, and :func:`out_of_order`,
whether points given in an order lie in it along a curve. :func:`fit` warns of points that
do not (OrderWarning) and fits them in curve order with ``order="curve"``; the CLI's and
FreeCAD's fits use the same two.

>>> import numpy as np, libelastica as el
>>> t = np.linspace(0, 3, 40); P = np.c_[t, np.sin(t)]
>>> Q = P[np.random.default_rng(1).permutation(40)]
>>> el.out_of_order(Q).order is not None, el.out_of_order(P).order is None
(True, True)
>>> x = Q[el.curve_order(Q)][:, 0]
>>> bool((np.diff(x) > 0).all() or (np.diff(x) < 0).all())
True
"""
from __future__ import annotations

from typing import NamedTuple, Optional

import numpy as np

from ._ffi import as_points, check, dptr, ffi, lib, transpose_hint
from ._portable import PortableTuple
from ._text import LengthFormat, lengths
from ._values import ValueEquality
from .prep import pca_normalize, plane_fit


def polyline_length(xy) -> float:
    """The length of the polyline through the rows of xy (sqrt of the sides' squares: a
    third faster than hypot on (n, 2) rows; out_of_order runs on every fit)."""
    d = xy[1:] - xy[:-1]
    return float(np.sqrt(np.einsum("ij,ij->i", d, d)).sum())


def _plane_points(points, name: str) -> np.ndarray:
    pts = as_points(points, f"{name}: points", None)
    if pts.shape[1] not in (2, 3):
        raise ValueError(f"{name}: points must have shape (n, 2) or (n, 3), got {pts.shape}"
                         f"{transpose_hint(pts.shape, (2, 3))}")
    return plane_fit(pts)[0] if pts.shape[1] == 3 else pts


# Points from SCAN_POINTS on are a scan's cloud: their noise band is many points wide, and
# a nearest-neighbour chain zigzags across it and leaves stragglers it joins at the end by
# long jumps, shorter still than the curve's order (a 300 deg curl of 1500 points, 0.2 mm
# noise: fitted 580 mm long for 224 mm; 2500 and 8000 points: rms 8.3 mm, not converged).
# They are ordered along their skeleton (_skeleton_order); fewer points (a sketch's, each
# its own) by their chain, which takes m^2 distances at once (0.3 MB at SCAN_POINTS).
SCAN_POINTS = 200
# The skeleton's cells: about SKELETON_CELLS of them at most (its minimum spanning tree
# takes their m^2 distances: 0.7 MB), CELL_POINTS points each at least, and NOISE_CELLS
# times the noise rms wide at least (the band within a cell or two across).
SKELETON_CELLS, CELL_POINTS, NOISE_CELLS = 300, 8, 4.0


def curve_order(points) -> np.ndarray:
    """The order of points without one of their own (points (n, 2): a scan's cloud, clicks
    in any order; (n, 3): in their best-fit plane, :func:`plane_fit`), as indices: the
    shortest polyline of three, as stored (a sketch's in the order its points were made:
    the first of equals, so Pin start means the first point made), along their first
    principal axis, and their nearest-neighbour chain (below SCAN_POINTS) or their order
    along their skeleton (a scan's cloud, from SCAN_POINTS on). Along the axis suits a
    scan that does not double back; a curl past 180 deg does (sorted along the axis it
    zigzags across: a fit's rms 3.6 mm against 6e-7, no free batten through them); one
    point of a curl added last, the stored order jumps (a fit 338 mm long for 188 mm of
    curl)."""
    xy = _plane_points(points, "curve_order")
    if len(xy) < 3:
        return np.arange(len(xy))
    xn, _ = pca_normalize(xy)
    orders = [np.arange(len(xy)), np.argsort(xn[:, 0], kind="stable")]
    orders.append(_chain_order(xy) if len(xy) < SCAN_POINTS else _skeleton_order(xy))
    best = min(orders, key=lambda o: polyline_length(xy[o]))
    return orders[0] if _moved_stray(xy, best) else best


def _moved_stray(xy, order) -> bool:
    """Whether ``order`` is the given order but for one point taken from inside it to an end,
    a point that lies farther from every other than the others' longest step: a stray one
    (QA25gui F1: one of 18 hand-sketched points mis-dragged 150 mm off became the chain's
    first point, and a 608 mm hook was fitted from it along a 330 mm curve, rms 1.36, no
    word). The given order is kept then, and el.fit names the point (stray.py); a point that
    belongs at an end and was only made last lies a step from its neighbour, and is moved."""
    n = len(order)
    if n < 4 or np.array_equal(order, np.arange(n)) or np.array_equal(order, np.arange(n)[::-1]):
        return False
    for end in (0, n - 1):
        i = int(order[end])
        rest, others = np.delete(order, end), np.delete(np.arange(n), i)
        if not 0 < i < n - 1 or not (np.array_equal(rest, others)
                                     or np.array_equal(rest, others[::-1])):
            continue
        step = float(np.max(np.hypot(*np.diff(xy[others], axis=0).T)))
        gaps = np.hypot(*(xy[others] - xy[i]).T)
        # a point nearest an end of the others and ahead of it, within 45 degrees of the
        # others' last step, belongs beyond that end (sparse offsets whose last step is their
        # longest, the end row listed among the others), and is moved there
        j = int(np.argmin(gaps))
        if j in (0, n - 2):
            last = xy[others[j]] - xy[others[1 if j == 0 else n - 3]]
            ahead = xy[i] - xy[others[j]]
            if float(np.dot(last, ahead)) > np.sqrt(0.5) * np.hypot(*last) * np.hypot(*ahead):
                return False
        return bool(gaps[j] > step)
    return False


# Points in an order whose polyline is more than ORDER_RATIO times as long as curve_order's
# are no curve's (a scanner's unsorted export, QA: 800 points of 0.2 mm noise along 200 mm,
# 54 m back and forth for 318 mm, fitted 1180 mm long at rms 6.9 mm, status converged); a
# digitiser's in order zigzags across its noise where the skeleton does less: 1.5 to 1.8
# times as long for 2000 points of 0.3 to 1 mm noise.
ORDER_RATIO = 3.0


# A fit's check of SCAN_POINTS points or more looks first at the polyline through about
# SCREEN_POINTS of them, every k-th: a scan in order (its noise wider than its spacing: the
# QA's 30 m sheer line, its polyline 4.6 times its extent) runs along its curve there, and
# curve_order's time is spared (the sheer's 2500 points: 37 ms, its fit 3 ms).
SCREEN_POINTS = 64
# ... and flags only a polyline that turns more than TURN_PER_VERTEX rad a vertex on average:
# a coil of few points in order (bench_fit.py's suite: 20 points on 3 pieces of k 4-26, their
# polyline 3.0-3.1 times curve_order's, which cuts across the loops) turns 0.90-0.98 rad a
# vertex, all one way; shuffled points about pi/2 (the suite's and QA10's, 3 shuffles each:
# 1525 flagged, 1.44 rad at least). The screen's points of a noisy scan turn with its noise
# too: a polyline flagged is looked at again through the means of runs of k points
# (_run_means_turn; bench_fit.py's suite in order, 200 points and more: 0.37 rad at most,
# the 7 its screen flags 0.35; shuffled, with test_order.py's sets: 1.73 at least, 1155
# shuffles, all flagged).
TURN_PER_VERTEX = 1.2


class Ordering(NamedTuple):
    """:func:`out_of_order`'s answer: ``order`` (curve_order's indices, None when the given
    order is a curve's), ``given`` (the length of the points' polyline in their order),
    ``along`` (in curve order; nan where not measured: the polyline, or the screen's, within
    the ratio times the points' extent, which no order's polyline is shorter than; ``given``
    too where the screen answered)."""
    order: Optional[np.ndarray]
    given: float
    along: float

    def _values(self):
        return tuple(self)

    __eq__ = ValueEquality.__eq__      # by value (_values.same: along nan equals nan)

    def __ne__(self, other):
        eq = self.__eq__(other)
        return eq if eq is NotImplemented else not eq

    __hash__ = tuple.__hash__
    # pickles that cross numpy versions (_portable.py), copies as before
    __reduce__, __copy__, __deepcopy__ = PortableTuple.reduce, PortableTuple.copy, PortableTuple.deepcopy


def out_of_order(points, ratio: float = ORDER_RATIO, screen: bool = True) -> Ordering:
    """Whether points (n, 2 or 3) given in an order are not in order along a curve: their
    polyline more than ``ratio`` times as long as the one through them in curve order
    (:func:`curve_order`). Not measured where the polyline is within ``ratio`` times the
    points' extent, nor (``screen``, SCAN_POINTS points or more) where the polyline
    through every k-th point, about SCREEN_POINTS of them, is: O(n) time there, else
    curve_order's (1e5 points: about 0.5 s); ``screen`` also keeps the order of a polyline
    that turns less than TURN_PER_VERTEX rad a vertex on average (a coil of few points)."""
    return ordering(_plane_points(points, "out_of_order"), ratio, screen)


def ordering(xy, ratio: float = ORDER_RATIO, screen: bool = True, screened=None) -> Ordering:
    """:func:`out_of_order` of points xy already checked (as_points: (n, 2) float64,
    C-contiguous, finite): fit's, which has checked them; screened: the screen's
    el_order_screen_result (its step and turn as here) where computed already (_fit_call.py)."""
    n = len(xy)
    if n < 3:
        return Ordering(None, polyline_length(xy), float("nan"))
    step = _screen_step(n) if screen else 1
    # the screen first (every k-th point; no longer than the polyline): a screen within the
    # ratio, or one that turns as a curve does (a coil, a spiral: longer than ratio times
    # its extent however ordered; shuffled points' screen turns ~pi/2 a vertex), answers in
    # order without the whole polyline's length (given nan) nor curve_order (bench_fit.py's
    # 1000 noisy points on k = 1.3 paid its 16 ms in a 1 ms fit; el.fit runs this each time)
    sc = _screen(xy, step, step > 1) if screened is None else screened
    if step > 1:
        if (not sc.length > ratio * sc.extent or not sc.turn > TURN_PER_VERTEX
                or not _run_means_turn(xy, step) > TURN_PER_VERTEX):
            return Ordering(None, float("nan"), float("nan"))
        given = _screen(xy, 1, False).length
    else:
        given = sc.length
    if not given > ratio * sc.extent:
        return Ordering(None, given, float("nan"))
    order = curve_order(xy)
    along = polyline_length(xy[order])
    if screen and given > ratio * along and not _screen(xy, 1, True).turn > TURN_PER_VERTEX:
        return Ordering(None, given, along)
    return Ordering(order if given > ratio * along else None, given, along)


def _screen_step(n: int) -> int:
    """The screen's step on n points: every k-th, about SCREEN_POINTS of them, from
    SCAN_POINTS points on, else 1 (every point): :func:`ordering`'s, and _fit_call.py's,
    whose screen ordering then takes as its own (screened=)."""
    return n // SCREEN_POINTS if n >= SCAN_POINTS else 1


def _run_means_turn(xy, step: int) -> float:
    """The mean |turn| a vertex (rad) of the polyline through the means of runs of step
    consecutive points: the screen's second look, asked only where the first flagged. A
    dense noisy scan in order turns there as its curve does, its noise averaged out
    (bench_fit.py's 1000 points at 1 % noise on k = 8: 1.23-1.36 rad at every step-th
    point, 0.22-0.35 here; they paid curve_order's 12-20 ms to be found in order);
    shuffled points' means crowd about their centroid and turn 1.7 rad and more."""
    m = len(xy) // step
    means = xy[:m * step].reshape(m, step, 2).mean(axis=1)
    return _screen(np.ascontiguousarray(means), 1, True).turn


def _screen(xy, step: int, turn: bool):
    """el_order_screen of the polyline through every step-th point of xy (as_points'):
    the points' extent, its length and (turn) its mean |turn| a vertex, rad."""
    out = ffi.new("el_order_screen_result *")
    check(lib.el_order_screen(dptr(xy), len(xy), step, turn, out), "out_of_order")
    return out


def order_summary(o: Ordering, unit: str = "", length: Optional[LengthFormat] = None) -> str:
    """What a warning of points out of order says (:func:`fit`'s, fit_keyline's, the CLI's):
    ``unit`` after each length, or ``length(value, digits)`` writing each (cost_summary's)."""
    fmt = lengths(unit, length)
    return (f"the points are not in order along a curve: their polyline is {fmt(o.given, 4)} long, "
            f"{o.given / o.along:.3g} times the {fmt(o.along, 4)} of the points in curve order")


class Retrace(NamedTuple):
    """:func:`run_back`'s answer: the points ``first``..``last`` (counted from 0) run back along
    the fitted curve, from arc length ``s_first`` to ``s_last`` (< s_first; > where fit
    kept its fit in curve order and that runs from the points' far end)."""
    first: int
    last: int
    s_first: float
    s_last: float

    __reduce__, __copy__, __deepcopy__ = PortableTuple.reduce, PortableTuple.copy, PortableTuple.deepcopy


def run_back(points, foot_s, rms: float, near: bool = True) -> Optional[Retrace]:
    """Where points (n, 2) in order along a curve turn and run back over it (a scan passed
    back and forth), from a fit's feet ``foot_s`` (n,) and rms: the largest fall of their
    mean over runs of w = max(3, (n-1)/16) consecutive points (which evens out the feet's
    jitter along the curve, about the noise, by sqrt(w)) below the highest mean before it,
    where it exceeds 5 x rms and 2 x the feet's median step (sketched points without
    noise); its first and last points those of the feet's highest and lowest within w of
    the two runs' middles, at least w apart, where the points turn back: their chords to
    the points k before and k after the first point opposite (dot < 0) at every k up to w
    (the discrete fit's test, fit_pairing.c; feet that fall only by landing on another
    pass of a curve that loops near itself, or on a noise cloud's jitter, are no turn: 64
    of bench_fit.py's 441 default fits fall so, none turns; ``near`` False: at every k from
    w / 2 up to w). None where no mean falls so. Measured: QA18's scan passed s 0 -> 12 -> 8 -> 30
    (188 points, noise 0.05) named as points 59 to 78, its fall 80 x rms; 60 evenly spaced
    scans in order (200 points, spacing 0.15, noise 0.05, 0-2 dropouts), both models: no
    fall at all."""
    s = np.asarray(foot_s, dtype=float)
    n = len(s)
    w = max(3, (n - 1) // 16)
    if n < 2 * w:
        return None
    c = np.concatenate(([0.0], np.cumsum(s)))
    m = (c[w:] - c[:-w]) / w                               # m[j]: points j..j+w-1
    fall = np.maximum.accumulate(m) - m
    j = int(np.argmax(fall))
    if not (fall[j] > 5.0 * rms and fall[j] > 2.0 * float(np.median(np.abs(np.diff(s))))):
        return None
    i = int(np.argmax(m[:j + 1]))
    a0, b0 = max(i + w // 2 - w, 0), min(j + w // 2 + w, n - 1)
    first = a0 + int(np.argmax(s[a0:i + w // 2 + w + 1]))
    last = first + int(np.argmin(s[first:b0 + 1]))
    if last - first < w or first < w or first + w >= n:
        return None
    # near False: the chords at k from w / 2 only, whose points a noisy turn's first does not
    # straddle (fit.py's check of its fit in curve order, where the first of feet that rise
    # within the noise at the turn may be a point or two past it: QA20's scan back over
    # 500 of 1500, 3 x as dense as out, turned at point 299, its feet highest at 301)
    k = np.arange(1 if near else max(1, w // 2), w + 1)
    P = np.asarray(points, dtype=float)
    back, on = P[first] - P[first - k], P[first + k] - P[first]
    if not np.all(np.einsum("ij,ij->i", back, on) < 0.0):
        return None
    return Retrace(first, last, float(s[first]), float(s[last]))


def turn_back(points) -> int:
    """The first point where points (n, 2) in order turn back on themselves (their chords to
    the points k before and k after opposite, dot < 0, at every k = 1..w, w = max(3,
    (n-1)/16)), 0 where none does: el_fit_turn_back, the discrete fit's own test of a scan
    passed back and forth (its distance="auto" pairs no such points; fit_pairing.c: its rule
    and its measurements), as run_back asks it of the first point it names."""
    P, first = as_points(points, "turn_back: points", 2, 1), ffi.new("size_t *")
    check(lib.el_fit_turn_back(dptr(P), len(P), first), "turn_back")
    return int(first[0])


# the pass before the turn that data_run_back measures along: its polyline through at most
# PASS_VERTICES of its points (every k-th and the turn; each point's foot found on each
# segment: n x PASS_VERTICES work)
PASS_VERTICES = 256


def data_run_back(points, rms: float) -> Optional[Retrace]:
    """run_back of points (n, 2) in order with their feet taken on the polyline of their own
    pass up to the first turn (:func:`turn_back`), not on a fitted curve: a scan passed
    back and forth over its whole length (QA20 F4: 300 points out, 300 back) fits no
    elastica in that order, and a fit that coils through them (the discrete model's:
    status 6, rms 37 where the noise is 0.4) has feet that do not fall where the points
    run back. None where the points turn nowhere or their feet there do not fall as
    run_back asks (5 x rms, 2 x their median step, the turn's chords)."""
    P = np.asarray(points, dtype=float)
    first = turn_back(P)
    if not first:
        return None
    return run_back(P, _pass_feet(P, first)[0], rms)


def _pass_feet(P: np.ndarray, first: int):
    """(arc lengths, distances) of points P's feet on the polyline of their pass up to point
    ``first`` (through PASS_VERTICES of its points at most): data_run_back's, and
    passed_over's."""
    step = max(1, -(-first // (PASS_VERTICES - 1)))
    V = P[np.r_[np.arange(0, first, step), first]]
    a, d = V[:-1], np.diff(V, axis=0)
    seg = np.hypot(d[:, 0], d[:, 1])
    at = np.concatenate(([0.0], np.cumsum(seg)))
    dd = np.maximum(seg * seg, np.finfo(float).tiny)
    s, dist = np.empty(len(P)), np.empty(len(P))
    for lo in range(0, len(P), 4096):       # (a block of points against every segment)
        q = P[lo:lo + 4096, None, :] - a[None]
        t = np.clip(np.einsum("psj,sj->ps", q, d) / dd, 0.0, 1.0)
        e = q - t[..., None] * d[None]
        e2 = np.einsum("psj,psj->ps", e, e)
        j = np.argmin(e2, axis=1)
        k = np.arange(len(j))
        s[lo:lo + 4096] = at[j] + t[k, j] * seg[j]
        dist[lo:lo + 4096] = np.sqrt(e2[k, j])
    return s, dist


def passed_over(points, r: Retrace, near: float) -> bool:
    """Whether points (n, 2) that run back (``r``: :func:`run_back`'s or
    :func:`data_run_back`'s) pass over their own pass before: the median distance of points
    r.first..r.last to the polyline of the points up to r.first within ``near`` (a scan
    passed back and forth: about the noise; a stroke that only comes near its start, a
    letter 'e''s arc over its bar, QA24 F3: far from it)."""
    P = np.asarray(points, dtype=float)
    if r.first < 1 or r.last <= r.first:
        return False
    return bool(np.median(_pass_feet(P[:r.last + 1], r.first)[1][r.first:]) <= near)


def retrace_summary(r: Retrace, unit: str = "", length: Optional[LengthFormat] = None) -> str:
    """What a warning of points that run back says (:func:`fit`'s, the CLI's)."""
    fmt = lengths(unit, length)
    return (f"points {r.first} to {r.last} (counted from 0) run back along the curve, from its "
            f"arc length {fmt(r.s_first, 4)} to {fmt(r.s_last, 4)}, and the points after them "
            "pass there again (a scan passed back and forth?): the curve passes there once, "
            "fitted by its distance to each point")


def _chain_order(xy):
    """The points' nearest-neighbour chain: from the closest pair, the nearest point not yet
    in it joined at whichever end it is nearer, until all are in (O(n^2))."""
    m = len(xy)
    if m < 3:
        return np.arange(m)
    d = np.hypot(*(xy[:, None, :] - xy[None, :, :]).transpose(2, 0, 1))
    np.fill_diagonal(d, np.inf)
    a, b = np.unravel_index(np.argmin(d), d.shape)
    chain, free = [int(a), int(b)], np.ones(m, dtype=bool)
    free[[a, b]] = False
    while free.any():
        head, tail = d[chain[0]], d[chain[-1]]
        i, j = int(np.argmin(np.where(free, head, np.inf))), int(np.argmin(np.where(free, tail, np.inf)))
        if head[i] < tail[j]:
            chain.insert(0, i)
            free[i] = False
        else:
            chain.append(j)
            free[j] = False
    return np.array(chain)


def _skeleton_order(xy):
    """A scan's cloud (xy, at least SCAN_POINTS points) ordered along its skeleton: the
    points binned into square cells (_cell_size: SKELETON_CELLS of them at most), the
    heaviest path of their centroids' minimum spanning tree (_heaviest_path: side branches
    of the noise band and stray points are left off), the points sorted by where their
    feet lie along it (_along), then the skeleton redrawn through their medians in runs
    along that order and the points sorted along it again. Cells narrower than
    NOISE_CELLS times the points' noise (their median distance from the skeleton) are
    widened once to that. O(n log n) time, O(n) memory: 1e5 points in about 0.5 s, 50 MB. A
    skeleton of fewer than 3 cells (the points lie in a cell or two) leaves the stored
    order."""
    m = len(xy)
    target = max(3, min(SKELETON_CELLS, m // CELL_POINTS))
    h = _cell_size(xy, target)
    order = np.arange(m)
    if not h > 0.0:
        return order
    for _ in range(2):
        cell, cells = _cells(xy, h)
        count = np.bincount(cell, minlength=cells).astype(float)
        centroids = np.column_stack([np.bincount(cell, xy[:, 0], cells),
                                    np.bincount(cell, xy[:, 1], cells)]) / count[:, None]
        path = _heaviest_path(centroids, count)
        if len(path) < 3:
            return order
        order = _along(xy, centroids[path], cell, centroids)[0]
        k = max(1, m // len(path))
        runs = np.median(xy[order[:m // k * k]].reshape(-1, k, 2), axis=1)
        if len(runs) < 2:
            return order
        order, dist = _along(xy, runs, cell, centroids)
        noise = 1.4826 * float(np.median(dist))     # the rms of normal noise
        if h >= NOISE_CELLS * noise:
            break
        h = NOISE_CELLS * noise
    return order


def _cells(xy, h):
    """(the index of each point's cell of side h, the number of cells holding points)."""
    q = np.floor((xy - xy.min(axis=0)) / h).astype(np.int64)
    _, cell = np.unique(q[:, 0] * (int(q[:, 1].max()) + 1) + q[:, 1], return_inverse=True)
    cell = cell.ravel()
    return cell, int(cell.max()) + 1


def _cell_size(xy, target):
    """The side of square cells of which about ``target`` hold points (a curve's
    count goes as 1 / side, a cloud's as its square), and never more than 1.5 x target."""
    h = float(np.ptp(xy, axis=0).max()) / target
    if not h > 0.0:
        return h
    for _ in range(8):
        cells = _cells(xy, h)[1]
        if abs(cells - target) <= 0.15 * target:
            break
        h *= (cells / target) ** 0.7
    while _cells(xy, h)[1] > 1.5 * target:
        h *= 1.25
    return h


def _heaviest_path(nodes, weight):
    """The path of the nodes' Euclidean minimum spanning tree (Prim, O(m^2)) that holds
    the most weight (the tree's diameter by node weight: from any node the heaviest path's
    far end, then from there the heaviest path), as indices from one end to the other.
    Written here: FreeCAD's Python has numpy, not necessarily scipy's csgraph, and the
    skeleton's few hundred cells need no more than this."""
    m = len(nodes)
    if m < 3:
        return np.arange(m)
    d = np.hypot(*(nodes[:, None, :] - nodes[None, :, :]).transpose(2, 0, 1))
    near, parent = d[0].copy(), np.zeros(m, dtype=int)
    free = np.ones(m, dtype=bool)
    free[0] = False
    adjacent = [[] for _ in range(m)]
    for _ in range(m - 1):
        j = int(np.argmin(np.where(free, near, np.inf)))
        free[j] = False
        adjacent[j].append(int(parent[j]))
        adjacent[parent[j]].append(j)
        closer = d[j] < near
        near, parent = np.where(closer, d[j], near), np.where(closer, j, parent)

    def heaviest_from(start):
        held, came = np.full(m, -1.0), np.full(m, -1)
        held[start], stack = weight[start], [start]
        while stack:
            u = stack.pop()
            for v in adjacent[u]:
                if held[v] < 0.0:
                    held[v], came[v] = held[u] + weight[v], u
                    stack.append(v)
        return int(np.argmax(held)), came

    a, _ = heaviest_from(0)
    b, came = heaviest_from(a)
    path = [b]
    while path[-1] != a:
        path.append(int(came[path[-1]]))
    return np.array(path)


def _along(xy, skeleton, cell, centroids, window=3):
    """(the points' order along the polyline ``skeleton``, their distances from it): by
    the arc length of each point's foot on it (its end segments run on beyond its ends),
    then (the points whose foot is one vertex) along the foot's segment. A point's foot is
    sought on the 2 x window segments about the vertex nearest its cell's centroid (cells
    and vertices are about as far apart), O(n)."""
    A, D = skeleton[:-1], np.diff(skeleton, axis=0)
    L2 = np.maximum(np.sum(D * D, axis=1), 1e-300)
    seg_len = np.sqrt(L2)
    s0 = np.concatenate([[0.0], np.cumsum(seg_len)])
    last = len(A) - 1
    nearest = np.argmin(np.hypot(*(centroids[:, None, :] - skeleton[None, :, :]).transpose(2, 0, 1)),
                       axis=1)[cell]
    j = np.clip(nearest[:, None] + np.arange(-window, window), 0, last)     # (n, 2 window)
    r = xy[:, None, :] - A[j]
    u = np.clip(np.sum(r * D[j], axis=2) / L2[j], np.where(j == 0, -np.inf, 0.0),
               np.where(j == last, np.inf, 1.0))
    e = r - u[:, :, None] * D[j]
    k = np.argmin(np.sum(e * e, axis=2), axis=1)
    i = np.arange(len(xy))
    j, u, e = j[i, k], u[i, k], e[i, k]
    s = s0[j] + u * seg_len[j]
    t = np.sum(xy * D[j], axis=1) / seg_len[j]
    dist = np.hypot(e[:, 0], e[:, 1])
    return np.lexsort((t, s)), dist


