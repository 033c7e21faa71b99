"""What g2_quadratic's source points say of themselves where its polyline cannot be built
(g2quad.py): noise (the sign changes of their discrete curvature), a flat stretch without
affine arc length, repeated points."""
from __future__ import annotations

import copy
import dataclasses
import math
from typing import Optional

import numpy as np

from ._ffi import DomainError, as_points, as_real
from ._quiet import say
from .bspline import BSpline
from .core import SmoothElastica


def _sign_changes(points: np.ndarray) -> int:
    """How often the discrete curvature det(x_i - x_{i-1}, x_{i+1} - x_i) of the points
    changes sign (zeros skipped): a curve's inflections, and as many again as noise or
    rounding adds (801 samples of an S: 1 exact, 19 rounded to 1e-4, 245 to 1e-3)."""
    d = np.diff(points, axis=0)
    a = np.sign(d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0])
    a = a[a != 0]
    return int(np.count_nonzero(a[1:] != a[:-1]))


# the splines of point data straying more than STRAY_EDGE x the mean edge (length / n) from
# the points: the affine polyline built on their noise, not their curve (review revC: a 360 mm
# hand stroke, 40 points, 0.3 mm noise, 24 edges: 74-102 mm, 5-7 mean edges, one end parabola's
# knot interval 20-25 where sqrt(2) is usual). Clean sources stay below 0.063 (the 560 builds of
# /tmp/g2qinfl's sweep, curves and samples, 12-96 edges), sane noisy strokes below 0.33.
STRAY_EDGE = 0.5


# StrayWarning's way out, in the binding's words (the CLI says its own: cli_g2quad)
STRAY_FIX = ("fit=True (`elastica g2quad FILE --fit`) or el.fit(points, model='smooth') and "
             "build from its curve")


class StrayWarning(RuntimeWarning):
    """:func:`g2_quadratic`'s warning that its splines stray from the source points by more
    than STRAY_EDGE x the mean edge (their length / n): the points are too noisy for the
    affine arc length, whose vertices crowd where the noise bends the points and leave long
    edges between. ``piece``: the piece (0-based) that strays farthest, ``deviation``: its
    distance from the points, ``edge``: the mean edge (length / n)."""

    def __init__(self, message: str = "", piece: int = 0, deviation: float = 0.0,
                 edge: float = 0.0):
        super().__init__(message)
        self.piece, self.deviation, self.edge = int(piece), float(deviation), float(edge)


def _stray_warning(points: np.ndarray, n: int, length: float, deviation: float,
                   piece_devs, piece_start, t_ends) -> Optional[StrayWarning]:
    """g2_quadratic's StrayWarning for point data whose splines stray more than
    STRAY_EDGE x length / n from them (``deviation``: the stated one, ``piece_devs`` each
    piece's, its vertices ``piece_start``, its ends ``t_ends`` (sample indices)), else None."""
    edge = length / n
    if not deviation > STRAY_EDGE * edge:
        return None
    p = int(np.argmax(piece_devs))
    npieces = len(piece_devs)
    return StrayWarning(
        f"g2_quadratic ({n} edges): the splines stray {deviation:.3g} from the points, "
        f"{deviation / edge:.3g} x the mean edge {edge:.3g} (length / n); piece {p} of {npieces} "
        f"(points {int(round(float(t_ends[p])))} to {int(round(float(t_ends[p + 1])))}, "
        f"{int(piece_start[p + 1] - piece_start[p])} edges) strays {piece_devs[p]:.3g} from its "
        f"own points: its affine polyline follows the points' noise (their discrete curvature "
        f"changes sign {_sign_changes(points)} times over {len(points)} points), not their "
        f"curve. Fit the points first: {STRAY_FIX}; more edges do not help noisy points",
        p, piece_devs[p], edge)


# More sign changes of the points' discrete curvature than a piecewise-convex profile's few
# inflections: noise (_sign_changes), named as such in g2_quadratic's DomainError.
NOISY_SIGN_CHANGES = 3


def _noisy_points_error(exc: DomainError, points: np.ndarray) -> DomainError:
    """g2_quadratic's DomainError for point data: the cause, how noisy the points are, and
    the way out (fit=True)."""
    flips = _sign_changes(points)
    why = str(exc)
    flat = _flat_stretch(points)
    if flips > NOISY_SIGN_CHANGES and flat is not None:
        # exact samples of a straight stretch: their sign changes are rounding, not noise
        # (QA23: a batten's straight middle span, "too noisy ... 1912 sign changes")
        a, b, nflat = flat
        return DomainError(exc.status, (
            f"{why.split(':')[0]}: the points run (nearly) straight from point {a} to {b} "
            f"(counted from 0), turning less than {FLAT_TURN:g} x their median turn a step, "
            f"so the smallest error of the points flips the sign of their discrete curvature "
            f"there: {nflat} of its {flips} sign changes are there; a straight stretch has "
            "(almost) no affine arc length (seed 002 (1)): build the curved parts either side "
            "of it apart, or pass the curve itself (an ElasticSpline, a SmoothElastica)"))
    if flips > NOISY_SIGN_CHANGES:   # the C status's list of causes is beside the point
        why = (f"{why.split(':')[0]}: the points are too noisy for the construction: their "
               f"discrete curvature changes sign {flips} times over {len(points)} points; its "
               "affine arc length takes their second and third differences (seed 002 (1), "
               "(15)), so it needs a piecewise-convex curve to high accuracy")
    return DomainError(exc.status, f"{why}; fit=True (`elastica g2quad FILE --fit`) fits one "
                       "smooth elastica to the points first and builds from it, or pass a fitted "
                       "SmoothElastica (`elastica fit --model smooth --json`, then `elastica "
                       "g2quad fit.json`)")


# a vertex turning less than FLAT_TURN x the median turn of the points is on a (nearly)
# straight stretch: QA23's batten sampled 1000 a piece (39001 points, median turn 2.2e-5 rad)
# turns 8.5e-9 rad a step on its straight span (kappa 2.7e-9 / mm), and its points there
# carry the evaluation's rounding (eps |q| / sqrt(mu) ~ 4e-7 mm, bspline.resolvable_tol),
# far above kappa h^2 / 2: all its 848 sign changes lie there, turning 1.1e-8..2.4e-7
FLAT_TURN = 1e-2


def _flat_stretch(points: np.ndarray):
    """(first, last, sign changes there) of the longest run of points turning less than
    FLAT_TURN x their median turn, where most (3/4) of the discrete curvature's sign changes
    are; else None."""
    d = np.diff(points, axis=0)
    h = np.hypot(d[:, 0], d[:, 1])
    if len(d) < 3 or not np.all(h > 0):
        return None
    cross = d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0]
    turn = cross / (h[:-1] * h[1:])
    tiny = np.abs(turn) < FLAT_TURN * float(np.median(np.abs(turn)))
    sgn = np.sign(cross)
    flip = np.zeros(len(cross), bool)
    nz = np.flatnonzero(sgn)
    flip[nz[1:][sgn[nz[1:]] != sgn[nz[:-1]]]] = True
    if not flip.any() or np.count_nonzero(flip & tiny) < 0.75 * np.count_nonzero(flip):
        return None
    edges = np.diff(np.concatenate([[0], tiny.astype(np.int8), [0]]))
    starts, stops = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1)
    j = int(np.argmax(stops - starts))
    return int(starts[j]) + 1, int(stops[j]), int(np.count_nonzero(flip & tiny))


def _repeated_points(points: np.ndarray) -> Optional[str]:
    """The words for consecutive points that coincide (doubled rows: a chain's pieces each
    sampled with both ends), else None: the construction takes differences along the
    points (seed 002 (15)) and a zero step breaks them."""
    same = np.flatnonzero(np.all(np.diff(points, axis=0) == 0.0, axis=1))
    if not len(same):
        return None
    named = ", ".join(str(int(i) + 1) for i in same[:5]) + (", ..." if len(same) > 5 else "")
    return (f"g2_quadratic: {len(same)} point(s) repeat the one before (points {named}, counted "
            "from 0): the construction takes differences along the points (seed 002 (15)), "
            "which a zero step breaks; drop the repeats, e.g. points[np.r_[True, np.any("
            "np.diff(points, axis=0) != 0, axis=1)]]")


# a source every point of which lies LOCAL_FAR x (the power of two >= its extent) or more
# from 0 in x or y is built relative to a local origin there (C's affine_polyline.c
# local_origin, the same rule): 4 bits of its coordinates or more would be lost
LOCAL_FAR = 16.0


def _local_origin(xy: np.ndarray) -> np.ndarray:
    """The reference point R that g2_quadratic subtracts from a source far from (0, 0) and
    adds back to its result (survey coordinates: a 3 m curve at (512345.678, 5012345.432)
    came back with its poles 7.6e-7 off the origin's translate, curvature jumps 1e-7 against
    5e-14): per coordinate the multiple of G (the power of two >= the points' extent) nearest
    the first point, 0 unless every point is LOCAL_FAR G or more from 0 there, and only where
    x - R is exact for every point (it is: both multiples of the smaller ulp, checked)."""
    xy = np.asarray(xy, dtype=np.float64)
    R = np.zeros(2)
    ext = float(np.max(np.ptp(xy, axis=0)))
    if not (ext > 0.0 and math.isfinite(ext)):
        return R
    G = math.ldexp(1.0, math.frexp(ext)[1])     # G >= ext > G / 2
    for c in (0, 1):
        col = xy[:, c]
        if not float(np.min(np.abs(col))) >= LOCAL_FAR * G:
            continue
        r = G * round(float(col[0]) / G)
        if np.all((col - r) + r == col):
            R[c] = r
    return R


def _local_source(source, is_curve: bool):
    """(the source moved by -R, R) for a source far from (0, 0) (_local_origin), else None:
    point data less R (exact); a SmoothElastica, or a chain of them (ElasticSpline,
    HermiteChain: a copy with its pieces moved), with its start(s) less R, so that it is
    evaluated in the local frame (its samples' rounding that of its size, not of R)."""
    if not is_curve:
        try:        # (a table with named columns too, as g2_quadratic reads it)
            xy = as_points(source, "points")
        except (ValueError, TypeError):
            return None         # (g2_quadratic's own checks say what is wrong)
        if len(xy) < 2 or not np.all(np.isfinite(xy)):
            return None
        R = _local_origin(xy)
        return (xy - R, R) if np.any(R) else None
    pieces = [source] if isinstance(source, SmoothElastica) else getattr(source, "pieces", None)
    if not isinstance(pieces, list) or not all(isinstance(p, SmoothElastica) for p in pieces):
        return None
    R = _local_origin(source.points(np.linspace(0.0, source.length, 257)))
    starts = np.array([[p.x0, p.y0] for p in pieces])
    if not np.any(R) or not np.all((starts - R) + R == starts):
        return None
    moved = [dataclasses.replace(p, x0=float(p.x0 - R[0]), y0=float(p.y0 - R[1]))
             for p in pieces]
    if isinstance(source, SmoothElastica):
        return moved[0], R
    chain = copy.copy(source)
    chain.pieces = moved
    return chain, R


def _moved(g, R: np.ndarray):
    """A G2Quadratic built in a local frame moved back by R: its poles, polyline and ends;
    a closed one's seam_bound widened to what the poles moved back resolve (_seam_rounding,
    relative to the seam's own curvature): the seam figures are the local build's (~1e-14),
    but the poles handed back carry the offset's rounding (a 1.3 x 1 oval at (512345.678,
    5012345.432), 64 edges: their seam's curvature jump 6.4e-9 relative against a bound of
    1e-9 before)."""
    from .g2ends import _seam_rounding      # (g2ends -> affine -> here: not at import)
    bs = [BSpline(b.degree, b.poles + R, b.knots, b.mults, b.max_deviation) for b in g.bsplines]
    poly = dataclasses.replace(g.polyline, points=g.polyline.points + R)
    bound = g.seam_bound
    if g.seam_angle is not None and bound is not None:
        k = abs(float(g.bsplines[0].curvature(g.bsplines[0].knots[:1])[0]))
        bound = tuple(max(b, r) for b, r in zip(bound, _seam_rounding(bs[0], bs[-1], k)))
    return dataclasses.replace(g, bsplines=bs, polyline=poly, ends=np.asarray(g.ends) + R,
                               seam_bound=bound)


def _built_locally(build, source, R: np.ndarray, coverage_error, said=None):
    """build(source, collected) (a G2Quadratic of the source moved by -R, its warnings put
    in the list ``collected``) moved back by R; those warnings said again at the caller of
    g2_quadratic, or put in ``said`` where that caller collects them (_say), a
    ``coverage_error``'s result moved back too."""
    collected = []
    try:
        return _moved(build(source, collected), R)
    except coverage_error as exc:
        exc.result = _moved(exc.result, R)
        raise
    finally:
        for w in collected:     # (said at g2_quadratic's caller: one level up)
            _say(said, False, w, 4)


def _say(said: Optional[list], plain: bool, warning: Warning, stacklevel: int = 3) -> None:
    """g2_quadratic's ``warning``: none from a ``plain`` build (covering_edges' searches:
    the error names the count), put in ``said`` where its caller collects them (a build in
    a local frame, _built_locally, said again at g2_quadratic's caller), else warned at
    g2_quadratic's caller (``stacklevel`` for _quiet.say: 3 from g2_quadratic). A flag and
    a list passed down, not warnings.catch_warnings: that swaps the process's filters and
    showwarning, so another thread's warnings were caught and said again or dropped (revA:
    365 of a thread's 3000 said from g2quad_points)."""
    if plain:
        return
    if said is not None:
        said.append(warning)
    else:                   # (1 say, 2 here, 3 g2_quadratic, 4 its caller)
        say(warning, stacklevel=stacklevel)


def _end_curvatures(given, is_curve: bool):
    """g2_quadratic's ``end_curvatures`` read: (k_start, k_end), each a finite float or None
    (estimated from the samples); (None, None) when not given. Point data only."""
    if given is None or (isinstance(given, tuple) and given == (None, None)):
        return (None, None)
    if is_curve:
        raise ValueError("g2_quadratic: end_curvatures is for point data (a curve's own "
                         "curvature is used)")
    try:
        pair = tuple(given)
    except TypeError:
        pair = ()
    if len(pair) != 2:
        raise ValueError(f"g2_quadratic: end_curvatures must be (k_start, k_end), got {given!r}")
    # (as_real: a finite real each, ValueError naming it for a string, complex, bool, array)
    return tuple(None if k is None else as_real(k, f"g2_quadratic: end_curvatures[{i}]")
                 for i, k in enumerate(pair))


def _seam_duck(c):
    """For a closed spline (its pieces duck to duck) with inflections: (j, d_j, d_0), the
    duck farthest (along the outline) from an inflection and its distance and duck 0's,
    as fractions of the length; None without inflections. Where duck 0 lies near one, the
    end pieces beside the seam are short and the outline closes at a corner at every count
    tried (a bean of 10 ducks, duck 3 at 0.078 L: 8.3, 2.5, 0.33 deg at 24, 48, 96 edges);
    the farthest closes G2 from 48 edges on (bean duck 9 at 0.188 L, a letter D duck 3 at
    0.205 L, a stiff 7-duck oval duck 4 at 0.156 L; /tmp/g2quad/item3c.py)."""
    pieces = getattr(c, "pieces", None)
    data = getattr(c, "data", None)
    if not pieces or data is None or len(pieces) != len(data):
        return None
    infl = np.asarray(c.inflections(), dtype=np.float64)
    if not len(infl):
        return None
    L = float(c.length)
    ducks = np.concatenate([[0.0], np.cumsum([p.length for p in pieces])[:-1]])
    gap = np.abs(ducks[:, None] - infl[None, :])
    near = np.min(np.minimum(gap, L - gap), axis=1) / L
    j = int(np.argmax(near))
    return j, float(near[j]), float(near[0])
