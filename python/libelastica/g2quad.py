"""One curvature-continuous quadratic B-spline per inflection-free piece of a curve
(seed 002 §4-5): :func:`g2_quadratic` and its result :class:`G2Quadratic`, built on the
affine arc-length polylines of affine.py; the ends matched to the source's curvature, the
reports (deviation, joints, end errors, what is left out).
"""
from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass
from typing import Optional, Tuple

import numpy as np

from ._ffi import DomainError, as_points, as_size, lib
from ._values import ValueEquality
from .affine import (AffinePolyline, EdgeCountError, EndPieces, _curve_samples, _is_curve,
                     affine_end_pieces, affine_polyline, elastica_inflections, g2_bspline, quadratic_joint_curvatures)
from .g2dev import refined_deviation
from .g2quad_points import (StrayWarning, _built_locally, _say, _end_curvatures, _local_source,
                            _noisy_points_error, _repeated_points, _seam_duck, _stray_warning)
from .g2ends import (_end_curvature, _held_joints, _hold_joints, _matched_ends, _menger_max, _rel_err,
                     _seam_estimate, _joins, _seam_rounding, _tangent_alone, _unheld_joints)

__all__ = ["G2Quadratic", "CoverageError", "CoverageWarning", "EndTangentWarning", "StrayWarning",
           "covering_edges", "g2_quadratic"]


@dataclass(eq=False)
class G2Quadratic(ValueEquality):
    """Result of :func:`g2_quadratic`.

    bsplines: one curvature-continuous quadratic B-spline per inflection-free piece,
    piece p running exactly from ends[p] to ends[p+1] (the source's ends and its
    inflection points); polyline: the affine arc-length polyline (seed 002 §4) they
    come from; deviation: the largest distance of the splines from the source: a curve's
    true distance (its foot on the curve), points' to their polyline, its sampled maximum
    refined by golden section (g2dev.refined_deviation: a maximum, not a bound);
    curvature_jump: the largest relative curvature jump at any joint inside a piece (0 up
    to rounding: G2); end_tangent_error: the largest angle (radians) between a piece's end tangent and the source's there (None when the
    source's tangents are unknown; at the inflections as inflection_tangent_error);
    source_end_tangent_error: the same (radians) at the source's own ends that the splines reach
    (~1e-13: x_1, x_2 placed for the tangent and the curvature, see g2_quadratic; O(edge)
    where that is not done: an end piece of fewer than 7 edges, or a farther spline);
    inflection_tangent_error: the same (radians) at the pieces' ends at inflections (None: no
    such end, or tangents unknown): ~1e-13 where both pieces there hold it (see g2_quadratic:
    they meet G1), else O(edge) (unheld_joints); covers_source: False when an end piece
    next to an inflection was too short to keep, so the splines
    start / stop at that inflection (§4.4), or (fit_ends=False) when the polyline's last
    vertex stops more than half a sample short of the source's end, so the splines stop
    there (the paper's A need not reach it; fit_ends=True lands it or raises); ends_covered: (start, end), which of the two
    ends is kept (covers_source: both); fit: with ``fit=True`` the FitResult of the
    smooth elastica fitted to the points (the source then; its rms / max_error are the
    points' distances to it), else None.
    join_angle (radians) / join_curvature_jump: where two pieces meet (at the source's inflections;
    the pieces are G2 inside, not there) the largest angle (radians) between their tangents
    (~1e-15 where the ends hold the source's tangent: G1) and the largest jump of their
    signed curvature (1/length; never 0: no G2 quadratic ends with the inflection's curvature
    0, each side ends with its own sign, ~ the source's kappa' x an edge); 0 with one piece.
    unheld_joints: the joints not G1, ((j, angle (radians), why), ...), j where piece j starts.
    end_curvature_error: at the source's own ends that the splines reach, the largest
    curvature error relative to the source's curvature scale, |k - k_src| / max(|k_src|,
    max |kappa| of the source over that end piece's span) (of point data: k_src from a
    cubic fitted to the end's samples, the maximum of their three-point curvature; at an
    end of zero curvature, e.g. an inflection, |k - k_src| / max(|k|, |k_src|) read ~1 at
    every n); None when neither end is
    reached. ~1e-12 where the end vertex could be placed (see g2_quadratic), else what the
    uniform construction gives (~0.29 on an arc at any n).
    dropped: the source's arc length left out at (start, end) (0, 0 when covers_source).
    seam_angle (radians) / seam_curvature_jump (relative to the source's curvature scale, as
    end_curvature_error): of a closed source (a closed ElasticSpline, opened at its point 0;
    or samples whose last is their first, each end then as its own tangents= give), the
    angle between the last spline's end tangent and the first's start tangent and the jump
    of their curvature where the outline closes (~1e-13: G2 there); None for an open source or
    one not covered. seam_bound: the (angle, jump) G2 bound, SEAM_G2 or the poles' rounding.
    A source far from (0, 0) (16 extents or more in x or y: survey coordinates) is built in a
    local frame and moved back (g2quad_points._local_origin): the figures are the local
    build's, the poles, polyline and ends its own rounded once to the offset's ulps."""
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
    source_end_tangent_error: Optional[float] = None
    seam_angle: Optional[float] = None
    seam_curvature_jump: Optional[float] = None
    inflection_tangent_error: Optional[float] = None
    seam_bound: Optional[Tuple[float, float]] = None
    unheld_joints: tuple = ()

    @property
    def seam_is_g2(self) -> bool:
        """The seam G2 within seam_bound: SEAM_G2 or what the poles resolve (_seam_rounding)."""
        a, k = self.seam_bound or (SEAM_G2, SEAM_G2)
        return self.seam_angle is not None and self.seam_angle <= a and self.seam_curvature_jump <= k

    def g2_summary(self) -> str:
        """Which joints are G2, in words (the CLI's and FreeCAD's line): the joints inside
        a piece by curvature_jump; where pieces meet (inflections) by their angle and jump."""
        inside = f"largest relative curvature jump at a joint inside a piece: " \
                 f"{self.curvature_jump:.2g} (G2 inside each piece)"
        if self.seam_angle is not None:     # a closed source: where the outline closes
            inside += (f"; where the outline closes (point 0): tangents "
                       f"{math.degrees(self.seam_angle):.2g} deg apart, relative curvature jump "
                       f"{self.seam_curvature_jump:.2g}"
                       + (" (G2)" if self.seam_is_g2 else " (not G2)"))
        if len(self.bsplines) < 2:
            return inside
        return (f"{inside}; where the {len(self.bsplines)} pieces meet (inflections): tangents "
                f"{math.degrees(self.join_angle):.3g} deg apart, curvature jump "
                f"{self.join_curvature_jump:.3g} (" + ("G1, " if self.join_angle <= SEAM_G2 else "")
                + "not G2 there" + "".join(f"; not G1 where piece {j} starts, {math.degrees(a):.3g} "
                                           f"deg: {why}" for j, a, why in self.unheld_joints) + ")")

    @property
    def npoles(self) -> int:
        return int(sum(b.npoles for b in self.bsplines))

    def __repr__(self) -> str:
        """A summary (the splines and polyline: print them by name)."""
        tan = "" if self.end_tangent_error is None else \
            f", end_tangent_error {self.end_tangent_error:.3g}"
        return (f"G2Quadratic({len(self.bsplines)} piece(s), {len(self.polyline.points) - 1} "
                f"edges, {self.npoles} poles, deviation {self.deviation:.3g}, curvature_jump "
                f"{self.curvature_jump:.2g}{tan}"
                f"{'' if self.covers_source else f', leaves out {self.dropped}'})")


def _spline_deviation(bs, samples: np.ndarray, lo: float, hi: float, spans=None) -> float:
    """Largest distance of one piece's spline from the source polyline ``samples``,
    sample range [lo, hi] (f~ parameters; 16 points per knot span); ``spans``: only the
    knot spans i with spans[0] <= i < spans[1] (the last knot with the last span)."""
    from .report import closest_points
    K = np.asarray(bs.knots)
    i0, i1 = spans if spans is not None else (0, len(K) - 1)
    if i1 <= i0:
        return 0.0
    u = np.concatenate([np.linspace(K[i], K[i + 1], 16, endpoint=False) for i in range(i0, i1)]
                       + ([K[-1:]] if i1 == len(K) - 1 else []))
    xy = bs(u)
    a, b = max(0, int(math.floor(lo)) - 1), min(len(samples), int(math.ceil(hi)) + 2)
    src = samples[a:b]
    worst = 0.0
    for chunk in range(0, len(xy), 256):    # bounded memory: 256 points x the piece's samples
        p = xy[chunk:chunk + 256]
        worst = max(worst, float(np.max(np.linalg.norm(closest_points(p, src) - p, axis=1))))
    return worst


def _edge_count_error(exc: EdgeCountError, n: int, build) -> EdgeCountError:
    """affine_polyline's EdgeCountError in g2_quadratic's name, with the fewest count
    that works (:func:`covering_edges` of ``build``) or None."""
    more = covering_edges(build, n)     # (its _plain builds: silent)
    return EdgeCountError(exc.status, f"g2_quadratic: {exc.cause}; " + (
        f"n = {more} works, the fewest above {n}" if more else
        f"no count up to {cover_search_limit(n)} works"), exc.cause, more)


def _past_the_end(t: np.ndarray, nsamples: int, n: int, landing: bool = False,
                  curve: bool = False, points: Optional[np.ndarray] = None,
                  inflection: Optional[float] = None, more: Optional[str] = None) -> str:
    """g2_quadratic's reason for points whose polyline ran past their last sample: its
    vertices ran on along f~'s last parabola continued (seed 002 §4.3): too few edges for
    the turning, unless the ``points`` turn less than n / 3 times (then said as what happened:
    the polyline left their curve at a vertex, or its last vertex lands part of an edge past)
    (``landing``: fit_ends found no A landing it, C's EL_EDOM, ``t`` of the
    paper's A, said as such: fit_ends' own best may have stopped short). ``curve``: the
    same for an elastica's samples (f~'s t, the curve's end at nsamples - 1), whose
    polyline is the paper's A (fit_ends=False); ``inflection``: f~'s t of the inflection
    where the polyline stops instead (the end piece beyond it left out), which it runs past;
    ``more``: the edge counts that work, in words (_paper_a_counts)."""
    if curve:
        end = nsamples - 1 if inflection is None else inflection
        past = int(np.sum(t > end))
        where = ("the curve's end" if inflection is None else
                 f"the inflection at sample {end:.0f} where it stops (the end piece beyond it "
                 "too short for 3 edges, left out)")
        return (f"g2_quadratic: {n} edges of the paper's A = (S/n)^3 (fit_ends=False) run "
                f"past {where}: {past} of the affine polyline's vertices beyond it "
                f"(the last at sample {float(t[-1]):.1f} of {nsamples - 1}, on f~'s last "
                "parabola continued, off the curve), so no spline through them ends there; "
                + (f"{more}; " if more else "") + "fit_ends=True (the default) lands the last "
                "vertex on it or names the edge count that does")
    last = nsamples - 1
    past = int(np.sum(t > last))
    first = int(np.argmax(t > last))        # the first vertex past their last sample
    paper = ("no A lands the affine polyline on their last sample; with the paper's A = "
             "(S/n)^3 " if landing else "")
    if first < len(t) - 1:
        # the §4.3 intersection has no solution on the curve: the line of area A through
        # the vertex before meets f~ nowhere ahead (a k = 2.69 elastica's 400 points turning
        # 5.9 times at 24 edges: vertex 2 at t = 455 of 399, 4 edges a turn; 26 build)
        what = (f"{paper}the affine polyline leaves the points' curve at vertex {first} of "
                f"{n}: the line of area A through vertex {first - 1} (seed 002 §4.3) meets "
                f"it nowhere ahead, so that vertex and the {past - 1} after it lie on f~'s "
                f"last parabola continued (the last at {float(t[-1]):.1f} of {last})")
    else:
        # only the last vertex past, by part of its edge: the paper's A lands it near the
        # end, not on it (fit_ends=False at 24-30 edges of a curve turning 4.3 rad: 1.0
        # sample past, 1/16 of its edge; 'too few edges' said before, fit_ends=True lands)
        what = (f"{paper}the affine polyline's last vertex lands "
                f"{float(t[-1]) - last:.3g} samples past their last sample "
                f"({(float(t[-1]) - last) / max(float(t[-1] - t[-2]), 1e-300):.2g} of its "
                "last edge)")
    turns = _turns(points) if points is not None else None
    if turns is not None and n >= 3 * max(turns, 1.0):
        # not said 'too few' (the turning allows the count): what happened, in figures
        why = (f"{n} edges, {n / max(turns, 1e-300):.3g} a turn of the points' tangent "
               f"({turns:.3g} turns; about 3 a turn are needed at least)")
        way = ("fit_ends=True (the default) adjusts A to land it, or pass another count"
               if not landing else "pass another count")
    else:
        why = (f"{n} edges are too few for the points' turning (about 3 per turn of the "
               f"tangent at least" + (f"; {turns:.3g} turns" if turns is not None else "") + ")")
        way = "pass more edges"
    return f"g2_quadratic: {why}: {what}; {way}"


def _turns(points: np.ndarray) -> float:
    """The turning of the points' polyline, in turns (sum |edge angle change| / 2 pi)."""
    d = np.diff(points, axis=0)
    d = d[np.any(d != 0, axis=1)]
    if len(d) < 2:
        return 0.0
    a = np.arctan2(d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0],
                   d[:-1, 0] * d[1:, 0] + d[:-1, 1] * d[1:, 1])
    return float(np.sum(np.abs(a)) / (2.0 * math.pi))


def _paper_a_counts(n: int, build) -> str:
    """The words naming the fewest edge count above n whose G2 quadratic of the paper's A
    (fit_ends=False, ``build(m)``: partial, _plain) covers the source (covering_edges, every
    count in turn), or that none up to cover_search_limit(n) does."""
    more = covering_edges(build, n)     # (its _plain builds: silent)
    return (f"n = {more} works with fit_ends=False, the fewest above {n}" if more else
            f"no count up to {cover_search_limit(n)} works with fit_ends=False")


def _short_of_the_end(t: np.ndarray, nsamples: int, n: int) -> str:
    """g2_quadratic's reason for points whose polyline fit_ends could not land (C's EL_EDOM)
    and whose paper's A (``t``) stops short of their last sample: n edges of the largest
    area the turning allows end before it (8 on a circle turning 4.2 times: 2.7 turns)."""
    return (f"g2_quadratic: {n} edges are too few for the points' turning (about 3 per turn "
            f"of the tangent at least): no A lands the affine polyline on their last sample, "
            f"it stops short of it (the paper's A = (S/n)^3: its last vertex at "
            f"{float(t[-1]):.1f} of {nsamples - 1}); pass more edges")


def _left_out(dropped, length: float, n: int, inflection: bool, short: Optional[str]) -> str:
    """g2_quadratic's words for splines that leave part of the source out (CoverageWarning,
    CoverageError): how much, at which end, and why: an end piece beyond an inflection too
    short for 3 edges (``inflection``: the splines stop at the inflection), and / or
    ``short``, the polyline's own stop short of the end (fit_ends=False: the paper's A need
    not reach it)."""
    gone = " and ".join(f"{d:.4g} at its {w}" for d, w in zip(dropped, ("start", "end"))
                        if d > 0)
    why = ([f"an end piece beyond an inflection is too short for 3 of the {n} edges, so "
            "they stop at the inflection"] if inflection else []) + ([short] if short else [])
    return (f"g2_quadratic: the splines leave out {gone} of the source (length {length:.4g}): "
            + "; ".join(why))


class CoverageWarning(RuntimeWarning):
    """:func:`g2_quadratic`'s warning (``partial=True``) that its splines leave part of the
    source out (an end piece next to an inflection too short for 3 edges:
    ``G2Quadratic.dropped``)."""


class EndTangentWarning(RuntimeWarning):
    """:func:`g2_quadratic`'s warning that an end of the source whose tangent it tried to
    hold (_hold_start: an end piece of 7 edges or more, the source's tangent known) is not
    held: ``misses`` ((end, angle in radians), ...) with end "start" / "end", as
    ``G2Quadratic.source_end_tangent_error`` reads them, or "seam": a closed source's
    outline closing at a corner (``G2Quadratic.seam_angle``, above SEAM_G2)."""

    def __init__(self, message: str = "", misses: Tuple[Tuple[str, float], ...] = ()):
        super().__init__(message)
        self.misses = tuple(misses)


# a curve's end curvature below ZERO_END_K x its largest |kappa| is a zero (a free end's)
# evaluated with rounding (1.4e-16 .. 7.1e-13 relative over 45 free splines' ends), which no
# G2 quadratic end can match
ZERO_END_K = 1e-9

# the seam of a closed source counts as G2 (seam_angle in radians, seam_curvature_jump
# relative) below this: held ends meet to ~1e-13 (rounding of the Newton's 1e-12 residual)
SEAM_G2 = 1e-9

# samples close where their last point is their first to RING_TOL x their extent (rounding);
# a seam's end, or one of curvature < NEAR_FREE_K x the largest, whose G2 hold failed or was
# given up holds its tangent alone (an open one if the deviation stays < TANGENT_ALONE_DEV x)
RING_TOL, TANGENT_ALONE_DEV, NEAR_FREE_K = 1e-9, 1.0 + 1e-6, 1e-3

# EndTangentWarning's reason where _hold_start found no end holding the source's tangent
NO_G2_END = "no G2 end found that holds it with the source's curvature"


class CoverageError(ValueError):
    """:func:`g2_quadratic`'s error that its splines would leave part of the source out
    (an end piece next to an inflection too short for 3 edges). result: that partial
    G2Quadratic (its ``dropped``); edges: the fewest edges found that cover the source
    (:func:`covering_edges`), or None; tried: the largest count tried."""

    def __init__(self, message: str, result: "G2Quadratic", edges: Optional[int], tried: int):
        super().__init__(message)
        self.result, self.edges, self.tried = result, edges, tried


# covering_edges tries counts up to this many times the given one, at least up to
# COVER_SEARCH_LEAST (a few edges given for a curve that turns several times: 6 for 26), and
# not past MAX_EDGES
COVER_SEARCH = 4
COVER_SEARCH_LEAST = 64
MAX_EDGES = 5000


def cover_search_limit(n: int) -> int:
    """The largest edge count :func:`covering_edges` tries above ``n``."""
    return min(max(COVER_SEARCH * int(n), COVER_SEARCH_LEAST), MAX_EDGES)


def covering_edges(build, n: int, errors=(ValueError, ArithmeticError),
                   leaves_out=None) -> Optional[int]:
    """The fewest edge count above ``n`` whose G2 quadratic covers the source, or None:
    ``build(m)`` gives the G2Quadratic of m edges (raising one of ``errors`` where m has
    none); tries every count n+1, n+2, ... in turn, one build each, up to
    :func:`cover_search_limit`, and stops at the first that covers. Every count, not steps:
    a count between can fail where a larger one works and a still larger fails again (a
    stretch without affine arc length: the 330 mm S covered at 3 and 6 edges, not 4 or 5;
    a k = 1.82 elastica from 6 edges: 26 works, 30 not, steps of 1/4 above 22 named 27).
    Cost: one build per count tried (6 edges, nothing covering: 58 builds to 64), but for
    the counts ``leaves_out(m)`` says True of: counts whose build is known not to cover
    (an end piece left out, :func:`end_piece_left_out`), skipped unbuilt (the answer the
    same: only counts that cannot be it are skipped)."""
    for m in range(int(n) + 1, cover_search_limit(n) + 1):
        if leaves_out is not None and leaves_out(m):
            continue
        try:
            if build(m).covers_source:
                return m
        except errors:
            continue
    return None


def end_piece_left_out(ends: EndPieces, n: int, nsamples: int) -> bool:
    """Whether :func:`g2_quadratic` of point data (``nsamples`` samples whose
    :func:`affine_end_pieces` are ``ends``; fit_ends=True, the default) at n edges is known
    not to cover the source, without building it: affine_polyline leaves an end piece out
    (seed 002 §4.4: n S_end / S_total < 1.5). The first left out: the polyline starts at
    sample ends[0] >= 1, not 0. The last (the first kept): fit_ends lands the last vertex
    within half a sample of ends[1] (or raises), which rounds short of the last sample only
    where ends[1] is 2 samples or more before it; a last piece of one arc is not judged."""
    if ends.npieces < 2:
        return False
    if ends.n_start is None or n < ends.n_start:
        return True
    return (ends.n_both is None or n < ends.n_both) and nsamples - 1 - ends.ends[1] >= 2


def g2_quadratic(curve_or_points, n: int, samples_per_vertex: int = 20, tangents=None,
                 fit: bool = False, partial: bool = False, *, end_curvatures=None,
                 _plain: bool = False, _said: Optional[list] = None,
                 **options) -> G2Quadratic:
    """Seed 002 end to end: approximate ``curve_or_points``, a SmoothElastica, a
    HermiteChain or an ElasticSpline (its pieces; a closed one opened at its point 0, its
    first duck, both ends held to its tangent and curvature there so the outline closes G2:
    ``seam_angle``, ``seam_curvature_jump``, EndTangentWarning where it does not; sampled with
    ``samples_per_vertex`` x n arcs, default 20) or a sampled curve (N+1, 2),
    by an affine arc-length polyline with n edges (:func:`affine_polyline`, each
    piece's A adjusted so its last vertex lands on the piece end), then build one
    curvature-continuous uniform quadratic B-spline per inflection-free piece that
    ends exactly on the source: at its end points and at its inflections
    (:func:`g2_bspline`; only the two end segments of a piece are not uniform).
    ``tangents`` (N+1, 2) of point data (nonzero: ValueError naming a (0, 0) row) sharpen
    the replacement curve and give the end tangent error; ``end_curvatures`` (k_start, k_end) of point data, the source's own
    signed curvature at the first and last point (None for either: estimated from that
    end's samples, _end_curvature), held there instead: closed samples (the last point the
    first) given one tangent and one curvature at both ends close G2 (a FreeCAD closed wire
    of a C2 source: the estimates from each side differ by ~5e-5 relative, a corner);
    ``options`` go to :func:`affine_polyline`.
    Measured points are rarely accurate enough for the construction (801 samples of a
    300 mm S rounded to 1e-4 mm fail): ``fit=True`` fits one smooth elastica to them
    (:func:`fit`, point-to-curve distance) and builds from that curve (``fit`` of the
    result: the points' distances to it; ``deviation``: the splines' from it).
    Raises ValueError / DomainError (straight source, noisy points: the message counts
    the sign changes of their discrete curvature, ...; n too small for an elastica:
    :class:`EdgeCountError`, with the fewest count that works; ``_plain``, private: as
    affine_polyline raised it, and silent, for the search's builds; ``_said``, private: a
    list its warnings go to instead, _say), and
    :class:`CoverageError` when the splines would leave part of the source out (an end
    piece beyond an inflection too short for 3 edges), naming how much and the fewest
    edges that cover it (:func:`covering_edges`); ``partial=True`` returns that result
    instead (``covers_source`` False, ``dropped``) with a :class:`CoverageWarning`; point
    data whose splines stray more than STRAY_EDGE x length / n from them (their noise built
    on, not their curve) warn a :class:`StrayWarning` naming the piece and fit=True.
    The ends' curvature is the source's (end_curvature_error ~1e-12): the uniform end
    parabola from the exact end point ends with ~0.71 x it at every n (the polyline's
    vertices lie on the source, the spline runs inside it by ~kappa h^2/8, and the parabola
    bridging over ~1.5 h bends differently), so each end piece's x_1 (x_{m-1}) is moved
    along the line that keeps A_2 = A, to where the end parabola starts with the source's
    curvature (_match_start; the polyline returned has it). The bridge then shows as a dip
    inside: on an arc the curvature along the spline stays within 7.5 % of the source's
    (0.71 at the ends before) at every n; where no such place exists (few edges for the
    turning: 6 on a k = 1.5 elastica) the end is left uniform and the error says so.
    Where the source's tangents are known (a curve, or ``tangents``) and an end piece has
    7 edges or more, x_1 and x_2 are placed (_hold_start) for the source's end tangent as
    well: exact there too (it was O(edge): 0.66 deg at 24 edges of an S), still G2 at every
    joint, unless that spline strays farther from the source (then the curvature alone, a
    k = 1.5 loop at 12 edges); the curvature then departs up to ~10 % from an arc's just
    inside the ends (7.4 % with the curvature alone).
    Where two pieces meet (an inflection) both ends hold the source's tangent there (point
    data without tangents: the two uniform ends' mean one; g2ends._joint_end: x_1, x_2 slid
    keeping the uniform end's curvature, x_1 alone at 4 to 6 edges), so the pieces meet G1
    (they were O(edge) apart: 0.0037 deg at 24 edges of an S), unless a piece has fewer
    than 4 edges or the splines would stray farther from the source (both ends or neither;
    unheld_joints names those joints and their angles). Not G2: no G2 quadratic
    ends with the inflection's curvature 0; a smaller end curvature than the uniform end's
    is reached only through a bump in the curvature just inside.
    Far from (0, 0) (survey coordinates) it builds the source moved by a local origin
    (exactly: points less it, an elastica's start(s) moved) and moves the result back, so the
    result is the origin's translated to rounding of the source's size (main: 1e-7 of it,
    curvature jumps 1e-7), the warnings and errors the same."""
    is_curve = _is_curve(curve_or_points, "g2_quadratic")
    # a closed ElasticSpline: opened at its point 0 (its arc lengths start there), both ends
    # held to the spline's own tangent and curvature there, so the outline closes G2 (QA25
    # F3: refused before, and its samples' splines closed at a corner, 4.8 deg at 24 edges)
    closed = is_curve and bool(getattr(curve_or_points, "closed", False))
    n = as_size(n, "g2_quadratic: n (the polyline's edges)", 3)   # the user's call named
    if fit:
        if is_curve or tangents is not None or end_curvatures is not None:
            raise ValueError("g2_quadratic: fit=True fits point data (without tangents or "
                             "end curvatures); a curve is built from as it is")
        from .fit import fit as fit_points
        fitted = fit_points(as_points(curve_or_points, "points"), model="smooth")
        said = []           # the curve's build's warnings: said at this call's caller
        try:
            g = g2_quadratic(fitted.curve, n, samples_per_vertex, partial=partial,
                             _said=said, **options)
        except CoverageError as exc:
            exc.result.fit = fitted
            raise
        finally:
            for w in said:
                _say(_said, _plain, w)
        g.fit = fitted
        return g
    k_given = _end_curvatures(end_curvatures, is_curve)
    if tangents is not None and not is_curve:
        # a tangent of no direction: normalised where a piece ends it was NaN (the figures
        # NaN, review revC), elsewhere C's f~ takes the arcs beside it straight
        zero = np.flatnonzero(~np.any(as_points(tangents, "tangents") != 0.0, axis=1))
        if len(zero):
            raise ValueError(f"g2_quadratic: tangents[{zero[0]}] is (0, 0): every sample's "
                             "tangent needs a direction (the curve's own there)")
    local = _local_source(curve_or_points, is_curve)
    if local is not None:   # far from (0, 0): built in a local frame, moved back (exactly)
        return _built_locally(lambda src, said: g2_quadratic(
            src, n, samples_per_vertex, tangents, partial=partial, end_curvatures=k_given,
            _plain=_plain, _said=said, **options), *local, CoverageError, _said)
    options.setdefault("fit_ends", True)
    if not is_curve:    # doubled rows: the real cause, not the C status's list (QA23)
        said = _repeated_points(as_points(curve_or_points, "points"))
        if said:
            raise DomainError(lib.EL_EDOM, said)
    try:
        ap = affine_polyline(curve_or_points, n, samples_per_vertex=samples_per_vertex,
                             tangents=None if is_curve else tangents, **options)
    except EdgeCountError as exc:   # (covering_edges' builds, _plain: as it is)
        if _plain:
            raise
        raise _edge_count_error(exc, n, lambda m: g2_quadratic(
            curve_or_points, m, samples_per_vertex, partial=True, _plain=True, **options)) from None
    except DomainError as exc:      # an elastica's other causes: affine_polyline's words
        if is_curve:
            raise
        points = as_points(curve_or_points, "points")
        if options["fit_ends"]:     # no landing on the last sample (C's EL_EDOM)? The
            try:                    # paper's A then shows the polyline running past it
                ap = affine_polyline(points, n, tangents=tangents,
                                     **dict(options, fit_ends=False))
            except DomainError:
                ap = None
            if ap is not None and round(float(ap.t[-1])) > len(points) - 1:
                raise DomainError(exc.status, _past_the_end(ap.t, len(points), n, True,
                                                          points=points)) from None
            if ap is not None and round(float(ap.t[-1])) < len(points) - 1:
                raise DomainError(exc.status, _short_of_the_end(ap.t, len(points), n)) from None
        raise _noisy_points_error(exc, points) from None
    npieces = len(ap.A)
    short = None        # why the polyline stops short of the source's end, if it does
    seam_dir = None     # closed samples without tangents: the one tangent both ends hold
    seam_given = False  # closed samples given one tangent and curvature at both ends
    if is_curve:
        c = curve_or_points
        infl_s = elastica_inflections(c)
        bounds = np.concatenate([[0.0], infl_s, [c.length]])
        first = int(np.argmin(np.abs(bounds - ap.s[0])))
        s_ends = bounds[first:first + npieces + 1].copy()
        # its last vertex more than half a sample short of its piece end (f~'s t, as the
        # points' round(t) below and C's fit_ends landing): the paper's A (fit_ends=False)
        # stopped there, and the splines stop with it (they ran on to the end before, over
        # one stretched end parabola: a 4.3-turn elastica at 10 edges, its vertices to s =
        # 4.0 of 5.74, deviation 0.151, covers_source True)
        s_samp, infl_t = _curve_samples(c, infl_s, n, samples_per_vertex)
        t_end = ([0] + list(infl_t) + [len(s_samp) - 1])[first + npieces]
        past_end = float(ap.t[-1]) > len(s_samp) - 0.5
        # the end piece left out and the last vertex more than half a sample past its
        # inflection, on f~'s last parabola continued, off the curve (seed 002 §4.4: x_ni
        # "close to the inflection point", A "redone" if too far: fit_ends): refused as past
        # the end (splines forced onto the inflection before: 0.61 .. 5.1 samples past)
        past_infl = (not past_end and first + npieces < len(bounds) - 1
                     and float(ap.t[-1]) > t_end + 0.5)
        if past_end or past_infl:
            # past the curve's end by more than half a sample (the paper's A, fit_ends=False):
            # refused as the points' polyline is (_past_the_end); the splines were forced back
            # onto the end before and said covers_source True (583 of 768 fit_ends=False builds
            # of /tmp/affshort's sweep, median 11.6 samples past); the counts that work named
            more = None if _plain else _paper_a_counts(
                n, lambda m: g2_quadratic(c, m, samples_per_vertex, partial=True, _plain=True,
                                          **options))
            raise DomainError(lib.EL_EDOM, _past_the_end(
                ap.t, len(s_samp), n, curve=True, inflection=t_end if past_infl else None,
                more=more))
        if float(ap.t[-1]) < t_end - 0.5:
            s_ends[-1] = float(ap.s[-1])
            short = (f"the polyline stops short of its end, its last vertex at s = "
                     f"{s_ends[-1]:.4g} (the paper's A = (S/n)^3, fit_ends=False, need not "
                     "reach it; fit_ends=True lands it or names the count)")
        ends = c.points(s_ends)
        theta = c.angle(s_ends)
        ends_dir = np.c_[np.cos(theta), np.sin(theta)]
        total = max(int(samples_per_vertex) * int(n), 4 * (len(bounds) - 1))
        samples = c.points(np.linspace(0.0, c.length, total + 1))
        t_ends = s_ends / c.length * total
        covers = first == 0, first + npieces == len(bounds) - 1 and short is None
        inflection = first > 0 or first + npieces < len(bounds) - 1
        k_src = [float(k) for k in c.curvature(np.array([0.0, c.length]))]
        # a free end's curvature 0 evaluates as rounding (a natural-end batten: -2.6e-18 of
        # max 0.011): held as a curvature, no G2 end met it (_match_tangent says why) and
        # every open stroke warned (QA25 F4); taken as 0: the tangent is held alone
        kmax = float(np.max(np.abs(c.curvature(np.linspace(0.0, c.length, 401)))))
        k_src = [0.0 if abs(k) <= ZERO_END_K * kmax else k for k in k_src]
        if closed and all(covers):
            # the seam's two ends the same point, tangent and curvature, to the bit (the last
            # piece's end evaluates them ~1e-14 apart): the outline closes on itself
            ends[-1], ends_dir[-1], k_src[1] = ends[0], ends_dir[0], k_src[0]
        dropped = float(s_ends[0]), float(c.length - s_ends[-1])
        length = float(c.length)
    else:
        samples = as_points(curve_or_points, "points")
        if round(float(ap.t[-1])) > len(samples) - 1:   # t: sample indices, f~(j) = p_j
            raise DomainError(lib.EL_EDOM, _past_the_end(ap.t, len(samples), n,
                                                          points=samples))
        t_ends = np.concatenate([[ap.t[0]], ap.infl_param, [round(float(ap.t[-1]))]])
        idx = t_ends.astype(int)
        ends = samples[idx]
        # samples of a closed outline (the last the first to RING_TOL of their extent, revA 7):
        # the splines close there, at a corner unless both ends hold one tangent (QA25 F3)
        ring = len(samples) > 2 and bool(np.linalg.norm(samples[-1] - samples[0]) <= RING_TOL
                                         * np.max(np.ptp(samples, axis=0)))
        if ring and idx[-1] == len(samples) - 1:
            ends[-1] = ends[0]
        ends_dir = None
        if tangents is not None:
            tan = as_points(tangents, "tangents")
            ends_dir = tan[idx] / np.linalg.norm(tan[idx], axis=1)[:, None]
        covers = idx[0] == 0, idx[-1] == len(samples) - 1
        if not covers[1] and not options["fit_ends"]:   # (fit_ends lands every piece end)
            short = (f"the polyline stops at sample {idx[-1]} of {len(samples) - 1}: an end "
                     f"piece beyond an inflection too short for 3 of the {n} edges, or the "
                     "paper's A = (S/n)^3 (fit_ends=False) stopping short of the end")
        inflection = not covers[0] or (not covers[1] and short is None)
        tan = None if tangents is None else as_points(tangents, "tangents")
        k_src = [_end_curvature(samples, e, tan) if k_given[e] is None else k_given[e]
                 for e in (0, 1)]
        # closed samples with the source's own tangent and curvature at their seam, both ends
        # one (a FreeCAD closed wire's, C2 there): both held whatever the deviation, as a
        # closed ElasticSpline's, so the outline closes G2
        seam_given = (ring and tan is not None and all(covers) and k_given[0] is not None
                      and k_given[0] == k_given[1] and np.array_equal(tan[0], tan[-1]))
        if ring and tan is None and all(covers) and len(samples) > 17:
            # closed samples without tangents: both ends held to one tangent and curvature,
            # the samples' own across the seam, so the splines close G2 there (QA25 F3)
            seam_dir, kappa = _seam_estimate(samples)
            k_src = [kappa, kappa]
        seg, kmax = np.linalg.norm(np.diff(samples, axis=0), axis=1), _menger_max(samples)
        dropped = float(seg[:idx[0]].sum()), float(seg[idx[-1]:].sum())
        length = float(seg.sum())
    splines, jump, dev, terr, serr, ierr, missed = [], 0.0, 0.0, 0.0, [], [], []
    poly = ap.points.copy()
    joints, built = _held_joints(ap.points, ap.piece_start, ends, ends_dir), []
    for p in range(npieces):
        a, b = ap.piece_start[p], ap.piece_start[p + 1]
        first, last = p == 0 and covers[0], p == npieces - 1 and covers[1]
        held = ends_dir is not None and (first or last)
        dirs = (ends_dir[p], ends_dir[p + 1]) if held else (seam_dir, seam_dir)
        x, xt, holds = _matched_ends(ap.points[a:b + 1], ends[p], ends[p + 1],
                              k_src[0] if first else None, k_src[1] if last else None,
                              dirs[0] if first else None, dirs[1] if last else None)
        held = held or (seam_dir is not None and (first or last))
        at_seam = held and ((closed and all(covers)) or seam_dir is not None   # never given up
                            or seam_given)
        gave_up = [None, None]  # why each held end was given up, if it was
        try:
            bs = g2_bspline(x, ends[p], ends[p + 1])
        except DomainError as exc:       # an end beside its joint's tangent: noisy points
            if is_curve:
                raise
            raise _noisy_points_error(exc, samples) from None
        if not held:
            pdev = _spline_deviation(bs, samples, t_ends[p], t_ends[p + 1])
        else:
            # (spans 0..2 / the last 3 are the ones _matched_ends' moves of x_1, x_2 change:
            # the middle one measured once for both candidates)
            nspan = len(bs.knots) - 1
            mid = (3, nspan - 3) if nspan >= 6 else (0, 0)
            parts = [(0, nspan)] if mid == (0, 0) else [(0, 3), (nspan - 3, nspan)]
            pmid = _spline_deviation(bs, samples, t_ends[p], t_ends[p + 1], mid)
            devof = lambda b: max([pmid] + [_spline_deviation(  # noqa: E731
                b, samples, t_ends[p], t_ends[p + 1], q) for q in parts])
            pdev = devof(bs)
            # the source's end tangents held too, unless that takes the piece farther from
            # the source (a loop at 12 edges: 0.0277 against 0.0214, its ends 8.8 deg off)
            if at_seam and not np.array_equal(xt, x):
                x, bs = xt, g2_bspline(xt, ends[p], ends[p + 1])   # (revA 1: 4.94 deg at 64)
                pdev = devof(bs)
            elif not np.array_equal(xt, x):
                # both held ends, else (farther) each alone: one end's held parabola can
                # take the spline farther where the other's does not (the spans they move
                # are apart), and was given up with it
                cands = [xt]
                if holds[0] and holds[1]:
                    one = x.copy()
                    one[1:3] = xt[1:3]
                    other = x.copy()
                    other[-3:-1] = xt[-3:-1]
                    cands += [one, other]
                best, tried = None, []
                for ci, xc in enumerate(cands):
                    bt = g2_bspline(xc, ends[p], ends[p + 1])
                    tdev = devof(bt)
                    tried.append(tdev)
                    if tdev <= pdev * (1.0 + 1e-6):      # (1e-12 apart by rounding alone)
                        best = (ci, xc, bt, tdev)
                        break
                if best is not None:
                    ci, x, bs, pdev = best
                if best is None or best[0] > 0:          # given up: said as missed
                    kept = {None: -1, 1: 0, 2: 1}[None if best is None else best[0]]
                    for e in (0, 1):
                        if holds[e] and e != kept:
                            # the figure of this end held alone where it was tried alone
                            # and neither is kept; else of both held (against the one kept)
                            own = tried[1 + e] if best is None and len(tried) == 3 else tried[0]
                            gave_up[e] = (f"holding it takes the spline farther from the "
                                          f"source ({own:.3g} against {pdev:.3g})")
            lost = [e for e in (0, 1) if (holds[e] is False or gave_up[e]) and (
                at_seam or abs(k_src[e] or 0.0) <= NEAR_FREE_K * kmax)]
            xa = _tangent_alone(ap.points[a:b + 1], x, ends[p], ends[p + 1], *dirs, lost)
            if lost and xa is not None:     # their tangents alone, before any warning
                ba = g2_bspline(xa, ends[p], ends[p + 1])
                adev = devof(ba)
                if at_seam or adev <= pdev * TANGENT_ALONE_DEV:
                    x, bs, pdev = xa, ba, adev
                    for e in lost:
                        holds[e], gave_up[e] = True, None
        built.append((x, bs, pdev, first, last, holds, gave_up))
    # the ends at inflections hold the source's tangent there, both pieces or neither (G1; QA gui
    # F3: 0.023 deg apart), where the splines stray no farther for it (g2ends._hold_joints)
    kept = _hold_joints(built, joints, ends, TANGENT_ALONE_DEV, lambda p, b: _spline_deviation(
        b, samples, t_ends[p], t_ends[p + 1]))
    for p, (x, bs, pdev, first, last, holds, gave_up) in enumerate(built):
        a, b = ap.piece_start[p], ap.piece_start[p + 1]
        poly[a:b + 1] = x
        kl, kr = quadratic_joint_curvatures(bs)
        if len(kl):
            jump = max(jump, float(np.max(np.abs(kl - kr) / np.maximum(np.abs(kl), np.abs(kr)))))
        dev = max(dev, pdev)
        if ends_dir is not None:
            d = bs.derivative(np.array([bs.knots[0], bs.knots[-1]]))
            for vec, ref, own, j in ((d[0], ends_dir[p], first, 0),
                                     (d[1], ends_dir[p + 1], last, 1)):
                err = abs(math.atan2(vec[0] * ref[1] - vec[1] * ref[0],
                                     vec[0] * ref[0] + vec[1] * ref[1]))
                terr = max(terr, err)
                if own:
                    serr.append(err)
                    why = {True: gave_up[j], False: NO_G2_END}.get(holds[j])
                    if why:
                        missed.append((("start", "end")[j], err, why))
                else:           # a piece's end at an inflection
                    ierr.append(err)
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
    angle, kjump = _joins(splines)
    seam, seam_bound = None, (SEAM_G2, SEAM_G2)
    if (closed or (not is_curve and ring)) and all(covers):   # last spline's end vs first's start
        seam_a, seam_k = _joins([splines[-1], splines[0]])
        kref = max(abs(k_src[0] or 0.0), max(kscale), 1e-300)
        seam = (seam_a, seam_k / kref)
        seam_bound = tuple(max(SEAM_G2, r) for r in _seam_rounding(splines[0], splines[-1], kref))
    ap = dataclasses.replace(ap, points=poly)
    if splines and not _plain:   # the stated figure: refined (g2dev.py; the choices above sampled)
        dev = refined_deviation(splines, samples, c if is_curve else None)
    g = G2Quadratic(splines, ap, np.asarray(ends), dev, jump,
                    terr if ends_dir is not None else None, bool(all(covers)),
                    ends_covered=(bool(covers[0]), bool(covers[1])), join_angle=angle,
                    join_curvature_jump=kjump,
                    end_curvature_error=max(kerr) if kerr else None, dropped=dropped,
                    source_end_tangent_error=max(serr) if serr else None,
                    seam_angle=seam and seam[0], seam_curvature_jump=seam and seam[1],
                    inflection_tangent_error=max(ierr) if ierr else None, seam_bound=seam_bound,
                    unheld_joints=_unheld_joints(splines, ap.piece_start, joints, kept, SEAM_G2))
    if seam is not None and closed and not g.seam_is_g2:
        duck = _seam_duck(curve_or_points)
        other = ("another one (np.roll), away from an inflection and with room for 7 edges to "
                 "the next" if duck is None or duck[0] == 0 or duck[1] <= duck[2] else
                 f"duck {duck[0]} (np.roll(points, -{duck[0]}, axis=0)): {duck[1]:.3g} of the length "
                 f"from the nearest inflection, duck 0 {duck[2]:.3g}")
        missed.append(("seam", seam[0], (
            f"the closed outline has a corner where it closes (point 0), relative "
            f"curvature jump {seam[1]:.3g}: more edges, or the ducks started at {other}")))
    elif seam is not None and seam[0] > seam_bound[0]:    # closed samples: their two ends' own
        missed.append(("seam", seam[0], (              # tangents, estimated apart
            f"the points close on themselves (the last is the first) and the splines close "
            f"there at a corner (relative curvature jump {seam[1]:.3g}): " + (
                "their tangents at the first and last point differ" if tangents is not None
                else "pass tangents= (the curve's own at the samples: both ends then hold "
                "one), or the closed curve itself (a closed ElasticSpline closes G2)"))))
    if missed:
        said = "; ".join((f"the splines' tangents where the outline closes are "
                          f"{math.degrees(err):.3g} deg apart: {why}") if end == "seam" else
                         f"the spline's {end} tangent is {math.degrees(err):.3g} deg off the "
                         f"source's: {why}" for end, err, why in missed)
        _say(_said, _plain, EndTangentWarning(f"g2_quadratic ({n} edges): {said}",
                                              tuple((end, err) for end, err, _ in missed)))
    if not is_curve and (stray := _stray_warning(   # the points' noise built on, not their curve
            samples, n, length, dev, [b[2] for b in built], ap.piece_start, t_ends)):
        _say(_said, _plain, stray)
    if not all(covers):
        what = _left_out(dropped, length, n, inflection, short)
        if partial:
            _say(_said, _plain, CoverageWarning(f"{what}; more edges cover it"))
            return g
        leaves_out = None
        if not is_curve and options["fit_ends"]:
            # the samples are the same at every count: their end pieces once, and the counts
            # that leave one out skipped unbuilt (a wavy sketch curve's 2 mm end piece needs
            # ~500 edges: every build to 4 n refused it, 13 s)
            try:
                ends_at = affine_end_pieces(samples, tangents, options.get("inflections"),
                                            options.get("split_inflections", True))
                leaves_out = lambda m: end_piece_left_out(ends_at, m, len(samples))  # noqa: E731
            except (ValueError, ArithmeticError):
                pass
        # the counts tried: said by the error (their _plain builds silent)
        more = covering_edges(lambda m: g2_quadratic(
            curve_or_points, m, samples_per_vertex, tangents, partial=True,
            end_curvatures=k_given, _plain=True,
            **options), n, leaves_out=leaves_out)
        top = cover_search_limit(n)
        raise CoverageError(f"{what}: " + (f"n = {more} covers it" if more else
                                           f"none of n = {n + 1} to {top} covers it (try more)")
                            + " (partial=True keeps this result)", g, more, top)
    return g
