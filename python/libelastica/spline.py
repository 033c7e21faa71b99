"""Elastic splines: the shape of a thin batten through N ducks (issue 14).

A chain of smooth elasticae of one tension through the points, G2 at every
point (the C library's el_spline_solve); one certified G2 B-spline for the
whole chain (el_spline_to_bspline).
"""
from __future__ import annotations

import math
import warnings
from typing import List, Optional

import numpy as np

from ._ffi import (DomainError, ElasticaError, LengthRangeError, NotConvergedError, as_int,
                   as_points, as_real, check, dptr, ffi, lib)
from ._quiet import quiet, quieted, say
from ._values import ValueEquality
from .bspline import smooth_chain_to_bspline
from .core import SMOOTH_PARAMS, SmoothElastica, arc_lengths, chain_eval, chain_starts
from .spline_ends import _end, _g2_end_text, _units_problem

__all__ = ["DoublesBackError", "ElasticSpline", "LoopWarning", "SeamWarning", "UnstableWarning",
           "holding_tension",
           "back_steps", "elastic_spline"]

# A back-step (back_steps) shorter than this fraction of the points' extent is below any
# feature a batten through them is drawn to: every back-step of the splines the tests and
# QA sketches solve is >= 0.06 of it, scan jitter's <= 0.014 (QA16 handdrawn.csv, 55 of
# them; shipline.csv <= 0.002, 14)
BACK_STEP = 0.02
# this many or more: noise no batten follows, refused before the solve (windows of 30-160
# of those points with 3 or more: none of 24 gave a spline without loops at tension 0,
# 10 or 100 / polygon^2, length 1.05 or 1.5 x it; with 1 to 3, some solve by length
# 1.05 x); fewer are named where the solve fails
BACK_STEPS_MANY = 5


class DoublesBackError(DomainError):
    """:func:`elastic_spline`'s error for points that double back on themselves within
    their noise (``places``: :func:`back_steps`, at least BACK_STEPS_MANY of them):
    a batten through them must turn back and forth at each; fair them
    (:func:`libelastica.fit`) or thin them instead."""


class SeamWarning(RuntimeWarning):
    """:func:`elastic_spline`'s warning that an open spline's last point is its first (a
    closed outline given open, QA20 F8): its ends meet there at a corner, where
    ``closed=True`` makes a G2 joint."""


# said where the last point of an open spline is its first (the warning, and each error's hint)
_SEAM_TEXT = ("; the last point is the first: closed=True (CLI: --closed) makes the closed "
              "spline, G2 at that point too")


class LoopWarning(RuntimeWarning):
    """:func:`elastic_spline`'s warning that the spline returned loops away from its
    ducks (``ElasticSpline.loops``: it crosses itself where the ducks' polygon does
    not (a polygon that crosses itself: between spans whose polygon's segments, or their
    neighbours, do not cross), or, by tension, is longer than 4 x that polygon): no fair
    batten was found at that tension (the family from the taut batten folds before it). By
    tension it names the least larger tension of HOLD_MULTIPLES / P^2 seen to hold
    (:meth:`ElasticSpline.holding`, solved when the warning is shown), or, where none does
    (a needle: a sharp turn between close points), the points either side of the sharpest
    turn to move apart."""


class UnstableWarning(RuntimeWarning):
    """:func:`elastic_spline`'s warning that the spline returned (by a tension > 0, or by
    length) is an equilibrium but no minimum of its energy with the ducks held
    (``ElasticSpline.unstable``; elastica.h's el_spline_result.unstable): it passes every
    duck G2 and is fair to draw, but a real batten bent so would not stay: it would snap
    to another shape. By tension it names the larger tension seen to hold, or the points
    to move apart where none does (as :class:`LoopWarning`); by length, another length.
    At tension 0 such a batten is refused instead (it slides off its ducks)."""


class ElasticSpline(ValueEquality):
    """An elastic spline: ``pieces`` (SmoothElastica from knot to knot, see below;
    closed: the last from the last point back to the first),
    ``tension`` (sigma, 1/length^2), ``length``, ``energy`` (integral of kappa^2 ds),
    ``forces`` ((npieces, 2): each piece's constant force F = (sigma - kappa^2) T
    - 2 kappa' N in units of EI/2, the batten after a section pulling on the
    batten before it; the duck at an inner knot i holds forces[i-1] - forces[i]),
    ``angles`` (tangent angles, radians) and ``curvatures`` at the points, ``max_curvature``,
    ``residual`` (largest end-condition error reached: position / chord, tangent angle in radians, curvature
    jump x local chord; the G2 error of a G2 end too), ``resolution`` (0, or where pieces
    nearly straight under tension resolve less than ``tol``: the residual double
    precision allows them, within which ``residual`` is accepted), ``closed`` and ``loops`` (True: it crosses
    itself where its ducks' polygon does not, or by tension is longer than 4 x it:
    :class:`LoopWarning`), ``unstable`` (True: an equilibrium but no minimum, a batten bent
    so would snap to another shape, ``unstable_span`` the span moving most that way, piece
    i from point i to i + 1: :class:`UnstableWarning`; open splines without G2 ends are
    judged, others read False), ``iterations`` (Newton iterations over every continuation step),
    ``work`` (the call's chain evaluations, each of every piece once, over every solve and
    search it made) and ``stopped`` (True: the call ended at its work budget, one for the whole
    call, max_steps x max_iter x (16 + 64 / m) evaluations for m pieces, and this is what it
    had reached by then; el_spline_result's work / stopped).

    The pieces run from knot to knot: the points and, next to each G2 end, its
    guide duck (the ducks that make a G2 end possible at the common tension,
    see :func:`elastic_spline`): ``guides`` ((g, 2) positions, the start's
    first), ``guide_forces`` ((g, 2): the force each exerts on the batten,
    normal to it, units of EI/2 as ``forces``) and ``guide_pieces`` (the index
    of the piece each starts). Without G2 ends piece i runs from point i to
    point i+1. Made by :func:`elastic_spline` (``res``: the C el_spline_result read, the
    ``points`` and ``closed`` it was asked for).
    """

    def __init__(self, res, points: np.ndarray, closed: bool):
        m, n = int(res.npieces), int(res.npoints)
        self.pieces: List[SmoothElastica] = [
            SmoothElastica(**{k: getattr(res.pieces[i], k) for k in SMOOTH_PARAMS})
            for i in range(m)]
        self.data = points[:n].copy()
        self.closed = bool(closed)
        self.tension = float(res.sigma)
        self.length = float(res.length)
        self.energy = float(res.energy)
        self.max_curvature = float(res.max_curvature)
        self.residual = float(res.residual)
        self.resolution = float(res.resolution)
        self.iterations = int(res.iterations)
        self.work = int(res.work)
        self.stopped = bool(res.stopped)
        self.loops = bool(res.loops)
        self.unstable = bool(res.unstable)
        self.unstable_span = int(res.slide_span) if self.unstable else None
        g = int(res.nguides)
        self.guides = np.array(list(res.guides)[:2 * g], dtype=np.float64).reshape(g, 2)
        self.guide_forces = np.array(list(res.guide_forces)[:2 * g], dtype=np.float64).reshape(g, 2)
        self.guide_pieces = [int(res.guide_pieces[i]) for i in range(g)]
        self.forces = np.frombuffer(ffi.buffer(res.forces, 16 * m),
                                    dtype=np.float64).reshape(m, 2).copy()
        self.angles = np.frombuffer(ffi.buffer(res.angles, 8 * n), dtype=np.float64).copy()
        self.curvatures = np.frombuffer(ffi.buffer(res.curvatures, 8 * n),
                                        dtype=np.float64).copy()
        self._starts = chain_starts(self.pieces)

    def __repr__(self) -> str:
        return (f"ElasticSpline({len(self.pieces)} pieces, tension={self.tension:.6g}, "
                f"length={self.length:.6g}, energy={self.energy:.6g}, "
                f"max_curvature={self.max_curvature:.6g}{', closed' if self.closed else ''})")

    def arclengths(self, n: int = 200) -> np.ndarray:
        """n arc lengths equally spaced over the whole spline, from point 0."""
        if int(n) < 2:
            raise ValueError(f"ElasticSpline: n must be >= 2, got {n}")
        return np.linspace(0.0, self.length, int(n))

    def _eval(self, where, what: str, extrapolate: bool = False) -> np.ndarray:
        """At ``where`` by :func:`core.arc_lengths`'s rule: an int n equally spaced, or arc
        lengths (floats, arrays) along the spline from point 0, within [0, length] (any
        finite s with ``extrapolate``: the end pieces continued, as HermiteChain's)."""
        s, scalar = arc_lengths(where, self.length, f"ElasticSpline.{what}", extrapolate)
        out = chain_eval(self.pieces, self._starts,
                         s if extrapolate else np.clip(s, 0.0, self.length), what,
                         clip=not extrapolate)
        return out[0] if scalar else out

    def points(self, n=200, extrapolate: bool = False) -> np.ndarray:
        """(n, 2) points at n (an int) arc lengths equally spaced over the whole spline; or,
        given arc lengths s along the spline (floats, an array; from point 0, in [0, length]
        unless ``extrapolate``), the points there, as SmoothElastica.points(s) (a float:
        shape (2,))."""
        return self._eval(n, "points", extrapolate)

    def curvature(self, n=200, extrapolate: bool = False) -> np.ndarray:
        """Signed curvature at the same n arc lengths as :meth:`points` (or at arc lengths s;
        ``extrapolate`` as there)."""
        return self._eval(n, "curvature", extrapolate)

    def angle(self, n=200, extrapolate: bool = False) -> np.ndarray:
        """Tangent angle (rad, continuous) at the same n arc lengths as :meth:`points` (or
        at arc lengths s; ``extrapolate`` as there)."""
        return self._eval(n, "angle", extrapolate)

    def comb(self, n=200, scale: Optional[float] = None) -> np.ndarray:
        """The curvature comb: (n, 2) tips p - scale kappa N at the arc lengths of
        :meth:`points` (n, or arc lengths s; teeth outside the bend, as CAD combs are
        drawn); ``scale`` defaults to 15 % of the extent over the largest curvature."""
        if scale is not None:
            scale = as_real(scale, "ElasticSpline.comb: scale")
        if np.ndim(n) == 0 and not isinstance(n, (int, np.integer)):   # one arc length
            return self.comb(np.reshape(n, 1), scale)[0]
        xy, k, th = self.points(n), self.curvature(n), self.angle(n)
        if scale is None:
            ext = float(np.ptp(xy, axis=0).max())
            scale = 0.15 * ext / self.max_curvature if self.max_curvature > 0 else 0.0
        normal = np.column_stack([-np.sin(th), np.cos(th)])
        return xy - scale * k[:, None] * normal

    def crossings(self, per_piece: int = 64) -> List[tuple]:
        """Where the spline crosses itself: the pairs (i, j), i < j, of points between
        which its two crossing stretches run (stretch i from point i to point i + 1, the last
        of a closed spline back to point 0; a G2 end's guide duck inside its stretch), each
        pair once, sorted; [] for a spline that does not cross itself. Its pieces sampled
        at ``per_piece`` points each (shape.crossing_pairs)."""
        from .shape import crossing_pairs
        m = len(self.pieces)
        t = np.linspace(0.0, 1.0, int(per_piece) + 1)[:-1]
        xy = [p.points(t * p.length) for p in self.pieces]
        xy.append(self.pieces[0].points(np.zeros(1)) if self.closed else
                  self.pieces[-1].points(np.full(1, self.pieces[-1].length)))
        piece = np.repeat(np.arange(m), len(t))   # the piece of each sample segment
        # the point each piece starts after: its index less the guide ducks before it
        point = np.array([j - sum(g <= j for g in self.guide_pieces) for j in range(m)])
        pairs = {tuple(sorted((int(point[piece[a]]), int(point[piece[b]]))))
                 for a, b in crossing_pairs(np.vstack(xy))}
        return sorted(pairs)

    def crossing_text(self) -> str:
        """The crossings in words (counted from 0), for the loop warnings; those between
        spans whose segments of the points' polygon do not cross first."""
        from .shape import crossing_pairs
        n = len(self.data)
        poly = self.data if not self.closed else np.vstack([self.data, self.data[:1]])
        own = {tuple(int(v) for v in p) for p in crossing_pairs(poly)}
        said = [f"within the span from point {i} to {(i + 1) % n}" if i == j else
                f"where the spans from point {i} to {(i + 1) % n} and from point {j} to "
                f"{(j + 1) % n} cross" for i, j in sorted(self.crossings(), key=lambda c: c in own)]
        return ", ".join(said[:3]) + (f" and {len(said) - 3} more" if len(said) > 3 else "")

    def unstable_text(self, fix: str, said: Optional[str] = None, noun: str = "spline") -> str:
        """What an unstable spline is (``unstable``), in the one summary its every caller says:
        UnstableWarning, the CLI's warning, the FreeCAD batten's caution ('' when it holds).
        ``fix``: the way to a shape a batten holds, in the caller's terms (a keyword, a flag,
        a property); ``said``: what goes in brackets after 'equilibrium' (None: the tension,
        '': nothing, as where the caller's unit system writes it); ``noun``: its subject."""
        if not self.unstable:
            return ""
        j = self.unstable_span
        said = f"tension {self.tension:.6g}" if said is None else said
        return (f"the {noun} is an unstable equilibrium" + (f" ({said})" if said else "") +
                ": it passes every point and is fair to draw, but a real batten bent so would "
                f"not stay, it would snap to another shape (moving most between points {j} and "
                f"{j + 1}, counted from 0); for a shape a batten holds, {fix}")

    def holding(self):
        """Tension mode's way out of a spline that loops or would not hold: (multiple,
        tension, polygon) from :func:`holding_tension` over the rungs of HOLD_MULTIPLES / P^2
        above this spline's tension, with its ends ((None, None, polygon) where none of them
        holds). Solved on the first call only (up to 10 solves), kept with the spline: the
        warnings, the CLI and the FreeCAD batten ask it, and walk the ladder once."""
        if getattr(self, "_holding", None) is None:
            start, end = getattr(self, "_ends", (None, None))
            m, tension, _, polygon = holding_tension(self.data, start, end, self.closed,
                                                     above=self.tension)
            self._holding = (m, tension, polygon)
        return self._holding

    def holding_text(self, say=lambda t: f"tension {t:.3g}", length: str = "a length") -> str:
        """:meth:`holding` in words: the tension that holds (``say(tension)``, the caller's
        terms; ``length``: how to say 'a length') or, where no larger one of the ladder does (the needle of the tests: every
        tension loops or would snap), the points either side of the polygon's sharpest turn
        to move apart (widening the needle's 2 mm tip to 10 mm, it holds at 100 / P^2)."""
        m, tension, polygon = self.holding()
        if m is not None:
            return f"{say(tension)} ({m:g} / the polygon squared, solved: it holds)"
        i, deg = sharpest_turn(self.data, self.closed)
        n = len(self.data)
        above = [k for k in HOLD_MULTIPLES if k / polygon ** 2 > self.tension]
        tried = (f"no larger tension of {ladder_words()} / the polygon squared holds (each "
                 "loops, would snap or is not found)" if above else "")
        return ((tried + ": " if tried else "") + f"move apart points {(i - 1) % n} and "
                f"{(i + 1) % n}, either side of the sharpest turn (at point {i}, {deg:.3g} deg, "
                f"counted from 0), or try {length}")

    def to_bspline(self, tol: Optional[float] = None, degree: int = 3):
        """ONE clamped B-spline (degree 3..7) for the whole spline within ``tol``
        (coordinate units; default 1e-6 of its length, or 4 x what double precision
        resolves where that is larger: bspline.default_tol) of it: every point of the B-spline within ``tol`` of the
        spline (``max_deviation``, the certified distance, is geometric: from b(t) to
        the nearest point of the spline). Its parameter runs over [0, length] and is the
        arc length at the points (the knots); between them it is not: b(s) and the
        spline at arc length s can lie farther apart than ``tol``. Each
        piece with exact end point, unit tangent and curvature
        (el_spline_to_bspline = el_smooth_chain_to_bspline), joined C2 (so G2) at the
        points."""
        return smooth_chain_to_bspline(self.pieces, tol, degree)

    def inflections(self, margin: float = 1e-9) -> np.ndarray:
        """Arc lengths from point 0 of the inflections in (0, length): the pieces' own
        (:func:`elastica_inflections`, ``margin`` x each piece's length from its ends left
        out), and the joints where the curvature changes sign (kappa = 0 there: the
        curvature is continuous), told by its sign half-way between each side's last
        inflection and the joint. As HermiteChain.inflections: g2_quadratic of a spline."""
        from .affine import elastica_inflections
        own = [elastica_inflections(p, margin) for p in self.pieces]
        out = [s0 + f for s0, f in zip(self._starts, own)]
        for i in range(1, len(self.pieces)):
            a, b = self.pieces[i - 1], self.pieces[i]
            ka = a.curvature(np.array([0.5 * ((own[i - 1][-1] if len(own[i - 1]) else 0.0) + a.length)]))[0]
            kb = b.curvature(np.array([0.5 * (own[i][0] if len(own[i]) else b.length)]))[0]
            if ka * kb < 0.0:
                out.append(np.array([self._starts[i]]))
        return np.sort(np.concatenate(out)) if out else np.empty(0)


def back_steps(points, closed: bool = False) -> List[int]:
    """Where the polygon through ``points`` goes forward, back and forward again (a Z)
    within a span too short to be drawn: the indices i whose span from point i to point
    i + 1 turns by more than 90 deg from both the span before and the span after it, and
    is shorter than BACK_STEP of the points' extent (the larger side of their bounding
    box). Scan points whose jitter exceeds their spacing do this; a batten through them
    must turn back and forth at each."""
    pts = as_points(points, "points")
    q = np.vstack([pts[-1:], pts, pts[:2]]) if closed else pts   # closed: every span inside
    d = np.diff(q, axis=0)
    if len(d) < 3:
        return []
    back = np.einsum("ij,ij->i", d[:-1], d[1:]) < 0.0          # span j+1 turns back from j
    short = np.hypot(*d.T) < BACK_STEP * float(np.ptp(pts, axis=0).max())
    k = np.flatnonzero(back[:-1] & back[1:] & short[1:-1]) + 1   # spans of q
    return [int(i) - 1 if closed else int(i) for i in k]


def _fair_advice(pts: np.ndarray, closed: bool) -> str:
    """What to do with scan points that double back (DoublesBackError's advice). Open: fair
    them with el.fit. Closed: el.fit fits open curves only (QA20 F10: its advice for a
    noisy 400-point cam scan could not be taken); the library's closed curves pass through
    their points (elastic_spline, blend_curve), so thin them to ducks farther apart than
    their noise, with the first every-k-th that doubles back nowhere named (the cam's every
    20th point: a spline 0.139 from the true cam)."""
    if not closed:
        return ("fair the points with el.fit (`elastica fit`) instead, or thin them to points "
                "farther apart than their noise")
    said = ("el.fit fits open curves only: for a closed outline thin the points to fewer ducks "
            "farther apart than their noise (or fit its open arcs with el.fit)")
    for k in range(2, len(pts) // 4 + 1):
        if not back_steps(pts[::k], True):
            m = len(pts[::k])
            return said + (f"; one point in every {k} (points[::{k}], {m} points) is the first such "
                           "thinning that doubles back nowhere")
    return said


# sigma P^2 (P: the polygon through the points) tried where no free batten passes the
# points: the FreeCAD Elastic spline command's ladder (freecad_wb spline.starting_tension reads this list)
HOLD_MULTIPLES = (1, 2, 5, 10, 20, 50, 100, 200, 500, 1000)


def sharpest_turn(points, closed: bool = False):
    """The point where the polygon through ``points`` turns most (open: an inner one), as
    (index, turning angle in degrees): where a batten through them bends hardest."""
    pts = as_points(points, "points")
    q = np.vstack([pts[-1:], pts, pts[:1]]) if closed else pts
    d = np.diff(q, axis=0)
    turn = np.abs(np.arctan2(d[:-1, 0] * d[1:, 1] - d[:-1, 1] * d[1:, 0],
                             np.einsum("ij,ij->i", d[:-1], d[1:])))
    j = int(np.argmax(turn))
    return (j if closed else j + 1), float(np.degrees(turn[j]))


def ladder_words(shown: int = 1) -> str:
    """HOLD_MULTIPLES in words, for every text naming them (none types them): its first
    ``shown``, ', '-joined, then '..' and its last; all of them ', '-joined where that
    leaves none out (the last said twice before: '... 1000 .. 1000')."""
    words = [f"{m:g}" for m in HOLD_MULTIPLES]
    if shown >= len(words) - 1:
        return ", ".join(words)
    return ", ".join(words[:shown]) + " .. " + words[-1]


# the advice of the DomainError at tension 0 (no free batten) for the API's user (the CLI
# says its own: cli_common.holding_advice)
SMALL_TENSION_TEXT = (" (a small tension may give a spline that loops, LoopWarning, or one a real "
                      "batten would not hold, UnstableWarning: raise it until neither is warned; "
                      f"el.holding_tension(points) tries {ladder_words()} / polygon^2 for one that "
                      "holds)")


def holding_tension(points, start=None, end=None, closed=False, above=0.0):
    """For points no free batten passes: the least of HOLD_MULTIPLES / P^2 (3 digits; P the
    polygon through the points) whose spline neither loops (:class:`LoopWarning`) nor is an
    unstable equilibrium (:class:`UnstableWarning`), with ``start``, ``end`` and ``closed`` as
    :func:`elastic_spline` takes them, as (multiple, tension, spline, P), each
    solved here, so the tension named is one seen to hold; (None, None, None, P) where none
    does. Up to 10 solves (the spike of the FreeCAD tests: 7, ~0.1-0.7 s): advice for an
    error (the CLI's spline at tension 0), not part of every DomainError. Small tensions
    typically give a spline that loops or one a real batten would not hold: such ducks'
    least tension without loops is often unstable (that spike: 10 / P^2, 1.33 P long, would
    snap; 100 / P^2, 1.17 P, holds). ``above``: only the rungs of larger tension
    (:meth:`ElasticSpline.holding`, from a spline's own tension)."""
    pts = as_points(points, "points")
    ring = np.vstack([pts, pts[:1]]) if closed else pts
    polygon = float(np.sum(np.hypot(*np.diff(ring, axis=0).T)))
    if not polygon > 0:
        raise ValueError("holding_tension: the points coincide (the polygon through them has "
                         "length 0): a spline needs two distinct points")
    for m in HOLD_MULTIPLES:
        tension = float(f"{m / polygon ** 2:.3g}")
        if not tension > above:
            continue
        try:
            with quiet(LoopWarning, UnstableWarning, SeamWarning):   # (this thread's)
                sp = elastic_spline(pts, tension=tension, start=start, end=end, closed=closed)
        except DoublesBackError:      # the points', at every tension: said as it is
            raise
        except ElasticaError:         # the solve's status: none at this tension (bad input,
            continue                  # elastic_spline's plain ValueError, is raised: not "none")
        if not sp.loops and not sp.unstable:
            return m, tension, sp, polygon
    return None, None, None, polygon


def _shown(category) -> bool:
    """Whether say(category) would be shown: not in a quiet scope of this thread, and as far
    as the filters without a message or module pattern tell (the first one matching decides,
    as in warnings; one with a pattern is taken as showing): a hand-written look at
    warnings.filters, which has no public query, to spare the ladder's solves."""
    if quieted(category):
        return False
    for action, msg, cat, mod, _ in warnings.filters:
        if issubclass(category, cat) and msg is None and mod is None:
            return action != "ignore"
        if issubclass(category, cat):
            return True
    return True


def _back_step_text(places, n) -> str:
    said = ", ".join(f"{i} to {(i + 1) % n}" for i in places[:4])
    return said + (f" and {len(places) - 4} more" if len(places) > 4 else "")


def _largest_text(res, span2) -> tuple:
    """Where tension mode failed at a high tension, the highest tension at which the
    library's search solved these points without loops (el_spline_result's largest,
    spline_limit.c; not a bound: near it the solve is not monotone): (tension, its text),
    (None, '') where it did not look or found none."""
    sigma, resolution, kp2 = (float(res.largest[i]) for i in range(3))
    if not sigma > 0.0:
        return None, ""
    lo = sigma * span2
    return sigma, (f"; the highest tension the search solved them at is ~{sigma:.3g} (x "
            f"(longest span)^2 = {lo:.3g}; it found none above it, and near it the solve is "
            f"not monotone: a tension a little below can fail, one a little above solve, so "
            f"this is no bound): beyond it the nearly straight runs between the ducks are pieces "
            f"whose elliptic modulus k lies within ~exp(-sqrt(tension / 2) x span) of 1 "
            f"(|1 - k^2| = {kp2:.2g} there), which a double resolves only in steps of "
            f"~4.4e-16, so the far end of such a piece is known only to ~4.4e-16 / |1 - k^2| "
            f"of its curvature (its resolution there {resolution:.2g}, a residual within the "
            f"lesser of it and 1e-7 accepted; ~2.3 x per +50 of tension x span^2): give "
            f"that tension (largest_tension) or a lower one")


def _digits_apart(x, *others):
    """Significant digits (4 .. 12) that write x apart from each of others that differs."""
    for d in range(4, 13):
        if all(f"{x:.{d}g}" != f"{y:.{d}g}" for y in others if y != x):
            return d
    return 12


def _coinciding_text(pts: np.ndarray) -> str:
    """'; points 1 and 3 coincide ...' for points that are not neighbours yet equal (the
    neighbours' are refused), named where no spline is found (QA17 P3); else ''."""
    _, first, inverse = np.unique(pts, axis=0, return_index=True, return_inverse=True)
    twice = np.flatnonzero(first[inverse.ravel()] != np.arange(len(pts)))
    if not len(twice):
        return ""
    pairs = [f"{first[inverse.ravel()[j]]} and {j}" for j in twice[:3]]
    return (f"; points {', '.join(pairs)}{' and more' if len(twice) > 3 else ''} coincide "
            "(counted from 0): a batten through one place twice must cross itself there")


def elastic_spline(points, tension: Optional[float] = None, length: Optional[float] = None,
                   start=None, end=None, closed: bool = False, *, tol: float = 1e-10,
                   max_iter: int = 60, max_steps: int = 60, initial=None) -> ElasticSpline:
    """The elastic spline (a batten) through ``points`` ((n, 2), n >= 2; closed:
    n >= 3, a repeated first point is dropped).

    Give ``tension`` (sigma >= 0, 1/length^2; 0 = the free-sliding batten, the
    default when neither is given) or ``length`` (the total length, longer than
    the polygon; sigma is then computed and may be negative: pushed together).
    ``start`` / ``end`` (open curves): None = natural (curvature 0), a tangent
    (tx, ty) = clamped, or {"tangent": (tx, ty), "curvature": k} = G2 to other
    geometry: a G2 end asks one condition more than a batten of given tension
    can meet, so its end span holds a guide duck, a quarter of its chord from the end
    (at 1/4 and 3/4 when both ends of two points are G2), free to move along the
    chord's normal (``guides``, ``guide_forces``); the tension stays common.
    Of the equilibria the batten that follows its ducks is returned: under tension,
    where the direct solve crosses itself or winds into loops (longer than 1.5 x the
    ducks' polygon), the family of tension solutions followed from the taut batten,
    the least integral kappa^2 + sigma ds among those that follow their ducks; where
    none does, the spline found with ``loops`` True and a :class:`LoopWarning`; pushed longer through ducks near a line, their line's
    buckled batten moved onto them (elastica.h, el_spline_solve).

    Unstable: by tension > 0, or by length, the spline returned may be an equilibrium
    that is no minimum of its energy with the ducks held (its second variation has a
    negative direction): it passes every duck G2 and is fair to draw, but a real batten
    bent so would not stay, it would snap to another shape. It is returned as it is, with
    ``unstable`` True, ``unstable_span`` the span moving most, and an
    :class:`UnstableWarning`. What to do: for a shape a batten holds, raise the tension
    (or try another length, or ease the sharpest turn near that span); where no free
    batten passes the points (tension 0 raises :class:`DomainError`), the least tension
    just above where the spline stops looping is often unstable (the spike of the FreeCAD
    tests: 10 / P^2, P the polygon) and a few times more holds (100 / P^2):
    :func:`holding_tension` finds the least of :data:`HOLD_MULTIPLES` / P^2 that holds, solved.
    At tension 0 an unstable free batten is not returned: it slides off its ducks
    (DomainError, naming the span).

    ``initial`` (open curves): the spline to start from instead of the library's own
    start, n - 1 SmoothElastica through the points with these ends (G2 ends only
    tangent), e.g. the ``el.hermite`` solution a G2 blend between two edges should
    follow: the solve keeps that branch (Newton from it, no other start tried).

    ``tol``: the accepted end-condition residual (1e-14..1e-3, default 1e-10; see
    ``ElasticSpline.residual``). ``max_iter``: Newton iterations per solve (1..1000,
    default 60); ``max_steps``: continuation steps of each family followed (1..1000,
    default 60): raise them where a solve stops short (NotConvergedError). The call's
    work is bounded (``ElasticSpline.work`` / ``stopped``): an error raised from a solve
    (:class:`NotConvergedError`, :class:`LengthRangeError`, the tension-0
    :class:`DomainError`) has ``stopped`` (True: the budget ended the call before it could
    say more, so raise max_iter or max_steps rather than change the points, tension, length
    or ends) and ``work`` (its chain evaluations), so callers need not read the message.
    (el_spline_options, elastica.h.)

    Raises ``ValueError`` for bad input (coincident consecutive points, NaN, ``start`` /
    ``end`` given with ``closed=True``: a closed curve has no ends, ...),
    :class:`DomainError` when no such spline exists (a length not longer than
    the polygon; tension 0 when the free batten would slide off its ducks, its message
    saying that a small tension may give a spline that loops or is unstable, and
    :func:`holding_tension` finds one that holds; points that
    double back within their noise, :class:`DoublesBackError`: BACK_STEPS_MANY or more
    :func:`back_steps`, refused before solving, naming them; fewer are named in the error
    where no spline is found) and
    :class:`NotConvergedError` when the solver stops short of ``tol`` (its
    ``spline`` attribute holds the spline reached, if any: an arc of a circle, or
    pieces nearly straight under tension, resolve only to ~1e-10..1e-7; the message names
    the dimensionless tension x (longest span)^2: on 24 random sketches, sheers and ovals
    (QA14) all solve up to 100, 22 at 200, 19 at 300 (to ~1e-9), 5 at 450, and tol 1e-7
    instead of 1e-10 solves no more of them at 450 (the rest reach nothing, or stay at
    ~2e-7 .. 6e-7 on nearly straight runs); from tension x (longest span)^2 = 300 on, where
    none was accepted, its ``largest_tension`` (else None) and message name the highest
    tension the library's search solved these points at (el_spline_result's largest: a
    few solves below the one asked, ~0.3-0.5 s; that tension solves, but it is no bound:
    near it the solve is not monotone, a tension a little below can fail) and why
    none it tried above it did: the modulus k of the nearly straight runs' pieces is then within
    ~exp(-sqrt(tension / 2) span) of 1, which a double resolves only in steps of ~4.4e-16;
    with G2 ends by tension, its ``g2_met`` (below, above) names the G2 battens met nearest
    the tension asked, each (tension, length) or None (el_spline_result's ladder, reach),
    as its message does);
    by length, :class:`LengthRangeError`
    (a NotConvergedError) where no spline of the length was reached though splines were
    met following the family of splines through the points (mostly a length beyond
    them), its message and ``shortest``, ``longest``,
    ``longest_fair`` (without loops) and ``polygon`` saying how far that one family reached
    (the range it met, not a bound: other splines may be shorter or longer; tension mode
    reaches others, and a spline's ``pieces`` as ``initial`` start length mode on their
    family). ``tension`` is in 1/units^2 of the points: the same batten in mm takes 1e-6 x its tension in m.
    """
    pts = as_points(points, "points")
    if not np.all(np.isfinite(pts)):
        raise ValueError("elastic_spline: points must be finite")
    n = len(pts)
    if closed and n >= 2 and np.array_equal(pts[0], pts[-1]):
        pts, n = pts[:-1], n - 1
    if n < (3 if closed else 2):
        raise ValueError(f"elastic_spline: needs at least {3 if closed else 2} distinct points "
                         f"{'for a closed curve ' if closed else ''}(got {n})")
    chords = np.hypot(*np.diff(np.vstack([pts, pts[:1]]) if closed else pts, axis=0).T)
    scale = np.abs(pts).max()
    bad = np.flatnonzero(~(chords > 4.0 * np.finfo(float).eps * scale))
    if len(bad):
        i = int(bad[0])
        raise ValueError(f"elastic_spline: points {i} and {(i + 1) % n} coincide "
                         "(a batten cannot pass one duck twice)")
    if tension is not None and length is not None:
        raise ValueError("elastic_spline: give tension= or length=, not both")
    opt = ffi.new("el_spline_options *")
    lib.el_spline_options_defaults(opt)
    if length is None:
        sigma = 0.0 if tension is None else float(tension)
        if not np.isfinite(sigma) or sigma < 0.0:
            raise ValueError(f"elastic_spline: tension must be finite and >= 0, got {tension!r}")
        opt.mode, opt.sigma = lib.EL_SPLINE_TENSION, sigma
    else:
        L = float(length)
        polygon = float(chords.sum())
        if not np.isfinite(L) or not L > 0.0:
            raise ValueError(f"elastic_spline: length must be finite and > 0, got {length!r}")
        if L < polygon * (1.0 - 1e-14):
            raise DomainError(lib.EL_EDOM, f"elastic_spline: length {L:.12g} is shorter than "
                                           f"the polygon through the points ({polygon:.12g})")
        opt.mode, opt.length = lib.EL_SPLINE_LENGTH, L
    opt.closed = 1 if closed else 0
    if closed and (start is not None or end is not None):
        raise ValueError("elastic_spline: start/end: a closed curve has no ends")
    if not closed:
        _end(start, "start", opt.start)
        _end(end, "end", opt.end)
    # the ranges of el_spline_options (elastica.h), named here (the library's EL_EINVAL
    # cannot say which)
    tol = as_real(tol, "elastic_spline: tol")
    if not 1e-14 <= tol <= 1e-3:
        raise ValueError(f"elastic_spline: tol must be in [1e-14, 1e-3], got {tol!r}")
    opt.tol = tol
    opt.max_iter = as_int(max_iter, "elastic_spline: max_iter", 1, 1000)
    opt.max_steps = as_int(max_steps, "elastic_spline: max_steps", 1, 1000)
    if initial is not None:
        pieces = list(initial)
        if closed or len(pieces) != n - 1 or not all(isinstance(p, SmoothElastica) for p in pieces):
            raise ValueError(f"elastic_spline: initial must be {n - 1} SmoothElastica pieces of an "
                             "open spline through the points")
        arr = ffi.new("el_smooth_params[]", len(pieces))   # alive until the solve returns
        for i, p in enumerate(pieces):
            for k in SMOOTH_PARAMS:
                setattr(arr[i], k, float(getattr(p, k)))
        opt.initial, opt.ninitial = arr, len(pieces)
    mean_chord = float(chords.sum()) / len(chords)
    units = _units_problem(mean_chord, opt, closed, pts, chords)
    if units:   # el_spline_solve's EL_EDOM before any search (spline.c's UNITS)
        raise DomainError(lib.EL_EDOM, "elastic_spline: " + units)
    places = back_steps(pts, closed)
    if len(places) >= BACK_STEPS_MANY:   # noise: refused before a solve that cannot succeed
        err = DoublesBackError(lib.EL_EDOM, (
            f"elastic_spline: the points double back on themselves {len(places)} times, as "
            "scan points do where their jitter exceeds their spacing: the polygon runs back "
            "against both neighbouring spans from point " + _back_step_text(places, n) +
            f" (counted from 0; spans under {BACK_STEP:g} of the points' extent): a batten "
            "through them must turn back and forth at each, at every tension and length "
            "(the free batten slides off, under tension it loops); " + _fair_advice(pts, closed)))
        err.places = places
        raise err
    # fewer: named where no spline is found (a likely cause, not a proven one)
    hint = (f"; their polygon doubles back (runs back against both neighbouring spans, one "
            f"under {BACK_STEP:g} of the points' extent) from point {_back_step_text(places, n)} "
            "(counted from 0), where a batten must turn back and forth: for scan points, "
            + _fair_advice(pts, closed)) if places else ""
    hint += _coinciding_text(pts)
    seam = not closed and n >= 4 and bool(np.array_equal(pts[0], pts[-1]))
    if seam:
        hint += _SEAM_TEXT
    res = ffi.new("el_spline_result *")
    st = lib.el_spline_solve(dptr(pts), n, opt, res)
    try:
        if st in (lib.EL_ENOCONV, lib.EL_ERANGE) and res.stopped:
            # the call's work budget ended it (el_spline_result's stopped): what it says is what
            # it had reached, not what these points allow (7 sketched ducks at max_iter =
            # max_steps = 3 by length 22: EL_ERANGE, "lengths met ..", solved at the defaults)
            hint = (f"; the solver stopped at its work budget ({int(res.work)} chain evaluations, "
                    "max_steps x max_iter x (16 + 64 / pieces)) before it could say more: raise "
                    "max_iter or max_steps") + hint
        if st == lib.EL_OK:
            sp = ElasticSpline(res, pts, closed)
            sp._ends = (start, end)
            # the ladder above this tension (ElasticSpline.holding), solved only where a
            # warning of tension mode is shown: Python has no public query of its filters,
            # so the first filter of the category decides; callers saying their own words
            # (CLI, FreeCAD, holding_tension) ignore these and ask sp.holding_text once
            advise = length is None and (
                (sp.loops and _shown(LoopWarning)) or (sp.unstable and _shown(UnstableWarning)))
            if sp.loops:
                # length mode: the length asked is what makes it loop (QA: the advice
                # "a larger tension, or a length" to a user who had given a length)
                fair = res.reach[2]
                fix = f"tension {sp.tension:.4g}; " + (
                    ("one holds at " if sp.holding()[0] is not None else "") + sp.holding_text()
                    if advise else "a larger tension may give one "
                    "(el.holding_tension)") if length is None else \
                    f"length {length:.4g} (tension {sp.tension:.4g}); a shorter length gives one" + (
                        f" (the longest met without loops: {fair / polygon:.4g} x the polygon, "
                        f"{fair:.6g})" if fair > 0.0 else "")
                where = sp.crossing_text()
                say("elastic_spline: the spline loops away from its ducks (it crosses "
                    "itself where their polygon does not, or is longer than 4 x it, "
                    f"{sp.length:.4g}" + (f"; it crosses itself {where}, points counted from 0"
                                          if where else "") +
                    f"): no fair batten was found at {fix}",
                    LoopWarning, stacklevel=2)
            from .spline_hook import HookWarning, hook_text   # (it imports LoopWarning from here)
            hooked = not sp.loops and _shown(HookWarning) and hook_text(sp)
            if hooked:
                say("elastic_spline: " + hooked, HookWarning, stacklevel=2)
            if sp.unstable:
                fix = ((("try " if sp.holding()[0] is not None else "") + sp.holding_text())
                       if advise else "try a larger tension (el.holding_tension), or ease the "
                       "sharpest turn there") if length is None else \
                    f"try another length than {length:.6g} (or a tension), or ease the sharpest turn there"
                said = None if length is None else \
                    f"by length {length:.6g}, tension {sp.tension:.6g}"
                say("elastic_spline: " + sp.unstable_text(fix, said), UnstableWarning,
                    stacklevel=2)
            if seam:
                a = sp.pieces[-1].angle(np.array([sp.pieces[-1].length]))[0] - sp.pieces[0].angle(np.zeros(1))[0]
                corner = abs(math.degrees(math.remainder(a, 2 * math.pi)))
                say(f"elastic_spline: an open spline with a {corner:.3g} deg corner at "
                    f"point 0{_SEAM_TEXT}", SeamWarning, stacklevel=2)
            return sp
        if st == lib.EL_EDOM:   # the cases above are checked: the free batten
            # res.slides: one was found but is no minimum (elastica.h), its span named
            where = (f" (the one through them is an unstable equilibrium, no minimum: it slides "
                     f"off at the span from point {res.slide_span} to {res.slide_span + 1}, "
                     "counted from 0)") if res.slides else ""
            err = DomainError(st, "elastic_spline: no free-sliding batten (tension 0) passes "
                                  "these points: it slides off its ducks" + where + hint +
                                  ("; else" if hint else ";") + " give a tension > 0 or a length"
                                  + SMALL_TENSION_TEXT)
            err.stopped, err.work = bool(res.stopped), int(res.work)
            raise err
        if st == lib.EL_ERANGE:
            lo, hi, fair = (float(res.reach[i]) for i in range(3))
            within = lo <= L <= hi
            side = "longest" if L > hi else "shortest"
            # reach is what the one family the solver followed met (elastica.h), not a
            # bound on the splines through the points (QA13's 8-point walk met one spline,
            # 11.28 x, while tension mode gives fair ones of 1.03 .. 1.8 x: now reached from
            # tension mode's splines, spline_bracket.c); the ratios to as many digits as
            # tell L from the nearest length met (QA14: "1.004 x" for both)
            d = _digits_apart(L / polygon, lo / polygon, hi / polygon)
            lad = [float(res.ladder[i]) for i in range(2)]
            span2 = float(chords.max()) ** 2
            ladder = (f"the solver also started from tension mode's splines, reached at "
                      f"tension {lad[0]:.3g} .. {lad[1]:.3g} (x (longest span)^2 "
                      f"{lad[0] * span2:.3g} .. {lad[1] * span2:.3g}), none of them brought to "
                      "this length" if lad[1] > 0.0 else
                      "tension mode's splines the solver also tried did not bracket this length")
            err = LengthRangeError(st, (
                f"elastic_spline: no spline of length {L:.{d + 2}g} ({L / polygon:.{d}g} x the "
                f"polygon, {polygon:.6g}) was reached: the family of splines the solver followed "
                f"(continuation in the tension) met lengths {lo / polygon:.{d}g} .. "
                f"{hi / polygon:.{d}g} x the polygon ({lo:.{d + 2}g} .. {hi:.{d + 2}g})" + (
                    f", without loops up to {fair / polygon:.{d}g} x ({fair:.{d + 2}g})"
                    if fair > 0.0 else ", every one with loops")
                + (" around it, yet not this one" if within else
                   f"; the {side} it met is not a bound") +
                f": other splines through these points may exist ({ladder}); tension mode "
                "reaches others (a larger tension gives a shorter "
                "spline; by tension x (longest span)^2 it solves all of 24 random sketches up "
                "to 100, 19 at 300, 5 at 450, elastica.h: Accuracy), and its pieces as initial= start length mode on "
                "their family" + hint))
            err.shortest, err.longest, err.longest_fair, err.polygon = lo, hi, fair, polygon
            err.spline = None
            err.stopped, err.work = bool(res.stopped), int(res.work)
            raise err
        if st == lib.EL_ENOCONV:
            why, largest = "", None
            g2 = [(float(res.ladder[i]), float(res.reach[i])) for i in range(2)]
            by_tension = length is None and sigma > 0.0
            # G2 ends: the G2 battens met nearest this tension (elastica.h: ladder), or None
            met = tuple(m if by_tension and m[1] > 0.0 else None for m in g2)
            if met[0] or met[1]:
                said = " and ".join(f"{'up to' if i == 0 else 'from'} {t:.3g} (length {Lg:.5g})"
                                    for i, (t, Lg) in enumerate(g2) if met[i])
                why = (f"; with G2 ends the solver reached blends of tension {said}, none at "
                       f"{sigma:g}: the families of G2 blends need not cover every tension "
                       "(between such tensions there may be none), so give a tension it "
                       "reached, or a length")
            if by_tension:
                # the solver's reach is in the dimensionless tension (elastica.h: Accuracy);
                # not where it reached a G2 blend of a higher tension
                sh2 = sigma * float(chords.max()) ** 2
                if sh2 > 50.0 and met[1] is None:
                    why = (f"; tension x (longest span)^2 = {sh2:.3g}: of 24 random sketches, "
                           "sheers and ovals the solver solves all up to 100, 22 at 200, 19 at "
                           "300 (to ~1e-9), 5 at 450, whether tol is 1e-10 or 1e-7 (nearly "
                           "straight runs stay at ~2e-7 .. 6e-7); tension is in 1/units^2 of the "
                           "points (in mm, "
                           "1e-6 x the same tension in m)")
                largest, text = _largest_text(res, float(chords.max()) ** 2)
                why += text
            if res.npieces and res.resolution > 0.0:
                # pieces near the separatrix: accepted within what a double resolves (elastica.h)
                why = (f"; its pieces nearly straight under tension resolve only "
                       f"{min(res.resolution, 1e-7):.3g} in double precision, and it exceeds that") + why
            if not res.npieces:
                why += _g2_end_text(opt, chords)
            err = NotConvergedError(st, "elastic_spline: did not converge: " + (
                f"residual {res.residual:.3g} > tol {tol:g} (the spline reached is kept in "
                "the exception)" if res.npieces else "no spline through the points was reached")
                + why + hint)
            err.spline = ElasticSpline(res, pts, closed) if res.npieces else None
            err.largest_tension = largest
            err.g2_met = met
            err.stopped, err.work = bool(res.stopped), int(res.work)
            raise err
        check(st, "elastic_spline")   # raises: st is an error
        raise AssertionError(st)
    finally:
        lib.el_spline_result_free(res)
