"""Elastic spline (issue 14): the batten through N ducks. A chain of elasticae of one
tension through picked points (sketch points or vertices, a Points object, a Draft
wire or polyline), curvature continuous at every duck; each open end natural
(curvature 0), tangent or G2 to a picked edge (a G2 end holds a guide duck in
its end span, at the same tension); or closed; by tension or by total length.
The feature keeps the energy, tension, length, largest curvature and the force
each duck holds; its shape is ONE G2 B-spline (ElasticSpline.to_bspline). It
follows its points; writing it into a sketch is a copy."""
from __future__ import annotations

import json
import math

import FreeCAD as App

from . import defaults
from .containers import set_shape
from .geometry import (binding_module, edge_end, el, ends_meet, nearest_parameter, np, part_bspline,
                       plane_coordinates, plane_curvature, to_3d)
from .kept import call_key, checked_call
from .links import followed_edge, followed_reader
from .units import coordinate_mark, length_mark, length_unit_mark, say, tension_mark
from .proxy import (FeatureProxy, InputProblem, add_edge_end, add_enum,
                    add_geometry_index, add_length, add_link, add_per_area, add_property,
                    check_degree, check_number, check_tolerance, edge_end_choice, new_feature,
                    read_only, set_said, source_list)
from .sources import gather_vertices
from .spline_solve import (MAX_ITER, DoublesBack, NoSpline, _library_message, _solve,
                           quiet_spline)

MODES = ["tension", "length"]
END_CONDITIONS = ["natural", "tangent", "G2"]
BSPLINE_DEGREE = 5          # one B-spline of few poles at the preference tolerance
DUCKS_NEED = ("points: sketch points or vertices, a sketch of points, a Points object, or a "
              "Draft wire / polyline")


def end_condition(edge, condition, point, neighbour, arriving, seam=False, at_end=None):
    """What an end of the spline at ``point`` (3D; ``neighbour`` the next duck
    inwards) takes from ``edge`` at the edge's end nearest the point: (edge, at_end,
    3D unit direction of travel, gap, turn). The spline leaves a start edge continuing it
    and arrives at an end edge running into it: at an open edge's start vertex along the
    edge's own direction, at its end vertex against it, whether or not the point lies on
    that vertex (an edge short of the point lends that direction as it is: turned to run
    along the spline's last span it arrived reversed, a hook 180 deg off the edge, QA
    qagui F1). A closed edge (a full circle or ellipse: its seam is no end) is met at its
    point nearest the point (u: its parameter there, else None), in the direction that
    runs along the spline (its point has no 'into'); ``seam``: at its seam instead, the
    rule before 4a0ae84 (seam_changes). ``at_end`` (open edges): True / False joins its
    end / start vertex (the end clicked), None the end nearest the point. 'turn': the
    angle (deg) between the end span's chord and the direction taken."""
    u = nearest_parameter(edge, point) if edge.isClosed() and not seam else None
    if u is None:
        if at_end is None:
            at_end = (edge_end(edge, True)[0] - point).Length < \
                (edge_end(edge, False)[0] - point).Length
        p, leaving = edge_end(edge, at_end)
    else:
        at_end, p, leaving = False, edge.valueAt(u), App.Vector(edge.tangentAt(u)).normalize()
    direction = -leaving if arriving else leaving
    gap = (p - point).Length
    inward = (point - neighbour) if arriving else (neighbour - point)
    if u is not None and direction.dot(inward) < 0:
        direction = -direction
    turn = math.degrees(direction.getAngle(inward)) if inward.Length > 0.0 else 0.0
    return {"edge": edge, "at_end": at_end, "u": u, "direction": direction, "gap": gap,
            "condition": condition, "turn": turn}


def gap_caution(c, j, what):
    """The warning for an end ``c`` (end_condition; ``j`` 0 the start, 1 the end, ``what``
    'the start edge' / 'the end edge') whose edge does not touch its point: which of the
    edge's points lends what, in which sense, that the spline does not meet it, and where
    the spline bends more than a right angle from its end span to take that sense (the
    edge's end lies back or aside of the points: the bend is the edge's, never a reversal),
    and, for an open edge, that joined at its other vertex it runs the other way (a guide beside
    the points, nearest at its far end: its nearest vertex turns the batten back on itself)."""
    point = "first" if j == 0 else "last"
    taken = "direction and curvature" if c["condition"] == "G2" else "direction"
    if c["u"] is None:
        vertex = "end vertex" if c["at_end"] else "start vertex"
        where, on = f"{what}'s end", "that vertex"
        sense = (f"leaves the {point} point continuing the edge as from its {vertex}"
                 if j == 0 else f"arrives at the {point} point running into the edge as at "
                 f"its {vertex}")
        vertex = f" (its {vertex})"
    else:                          # closed: met at its nearest point, not an end
        where, on, vertex = f"{what} (closed)", "a point on the edge", ""
        sense = f"takes its {taken} at its nearest point"
        taken = ""
    bend = (f"; to do so it bends {c['turn']:.3g} deg away from its {point} span"
            if c["turn"] > 90.0 else "")
    if bend and c["u"] is None:    # the other vertex lends the other sense (a guide beside)
        other = "start vertex" if c["at_end"] else "end vertex"
        bend += (f" (joined at its {other} it runs the other way: "
                 f"{'Start' if j == 0 else 'End'}EdgeAt = {other})")
    return (f"{where} is {length_mark(c['gap'])} from the {point} point{vertex}: the spline "
            f"{sense}{f' (its {taken})' if taken else ''} but does not meet it{bend}; to join, "
            f"make the {point} point {on} (pick it, or constrain them coincident)")


# an open batten's first and last points "nearly meet" (closing_hint) where their gap is no
# longer than the longest span between the points and at most this part of the outline's size,
# and the polygon through them turns at least GOES_ROUND deg (a hairpin, 175 deg, is no outline)
NEAR_CLOSE = 0.2
GOES_ROUND = 270.0


def closing_hint(xy, sp):
    """The warning for an open natural batten through plane points ``xy`` (n, 2) whose first
    and last points nearly meet (an outline drawn round without repeating its first point,
    QA qagui F9: 24 points of an oval 300 x 180 mm, the ends 16.2 mm apart, their tangents
    37.5 deg): their gap no longer than the longest span between the points and at most
    NEAR_CLOSE of the outline's size (its diameter), the polygon through them
    turning GOES_ROUND deg or more (the QA's oval 311; a hairpin's 175: not). Sketcher's
    B-spline by points asks periodic or not as it is drawn; here Closed says it: [the hint]
    or []."""
    n = np()
    if len(xy) < 4:
        return []
    gap = float(n.hypot(*(xy[-1] - xy[0])))
    longest = float(n.max(n.hypot(*n.diff(xy, axis=0).T)))
    # the outline's size "across": its diameter (largest distance between two points), as
    # the largest width over 180 directions 1 deg apart (low by at most 1 - cos 0.5 deg,
    # 4e-5; O(n) memory where the pairwise distances take O(n^2)); the box's diagonal
    # said 349 mm for the QA's 300 x 180 oval and changed as the sketch turned
    heads = n.radians(n.arange(180.0))
    widths = xy @ n.vstack([n.cos(heads), n.sin(heads)])
    size = float(n.max(widths.max(axis=0) - widths.min(axis=0)))
    d = n.diff(xy, axis=0)
    heading = n.arctan2(d[:, 1], d[:, 0])
    round_ = abs(math.degrees(float(n.sum(n.remainder(n.diff(heading) + math.pi, 2 * math.pi)
                                          - math.pi))))
    if not (gap <= longest and gap <= NEAR_CLOSE * size and round_ >= GOES_ROUND):
        return []
    a = sp.angle(2)
    turn = abs(math.degrees(math.remainder(float(a[-1] - a[0]), 2 * math.pi)))
    return [f"the first and last points are {length_mark(gap)} apart (the outline "
            f"{length_mark(size)} across) but Closed is off: the open batten leaves that gap "
            f"and its ends run {turn:.3g} deg apart; if the points go round an outline, set "
            "Closed for a closed batten through them"]


def duck_forces(sp):
    """(n, 2) force each duck (point) exerts on the batten (units of EI/2, 1/mm^2):
    with F_i the constant force of piece i (the batten after a section pulling on the
    batten before it), the duck at knot i holds F_{i-1} - F_i; an open end's duck
    holds -F_0 or F_{m-1} (the library's convention, header section spline). The
    guide ducks' forces (knots sp.guide_pieces) are sp.guide_forces; with them the
    forces sum to zero."""
    n = np()
    f = n.asarray(sp.forces, dtype=float)
    if sp.closed:
        return n.roll(f, 1, axis=0) - f
    return n.delete(n.vstack([-f[:1], f[:-1] - f[1:], f[-1:]]), sp.guide_pieces, axis=0)


def ends_at_start(points):
    """Whether more than three 3D points end where they start (geometry.ends_meet): a closed
    wire's vertices (its first again), or picks back to the first."""
    return len(points) > 3 and ends_meet(points)


def spline_core(points, plane=None, mode="tension", tension=0.0, length=0.0, closed=False,
                start=None, end=None, tol=1e-3, degree=BSPLINE_DEGREE, advise=True, shown=None,
                max_iter=MAX_ITER):
    """The elastic spline through 3D ``points`` (in ``plane``, a sketch's placement,
    when they lie in it, else their best plane). ``start`` / ``end``: None (natural)
    or (condition 'tangent' / 'G2', Part edge[, at_end: which end, end_condition]).
    Tension mode: ``tension`` >= 0
    (1/mm^2; 0 = the free batten); length mode: ``length`` mm (0 = the free
    batten's length). Returns a dict: 'spline' (el.ElasticSpline, plane
    coordinates), 'bspline', 'placement', 'forces' (duck_forces), 'notes'.
    ``advise`` False: no cautions for a batten that loops or is unstable (batten_cautions:
    the ladder's solves), for starting_tension's rungs, which say them once chosen.
    ``shown``: (Curves JSON, length, tension, switched, kept) of the spline on screen, kept
    by tension mode where it passes these points at this tension (kept_shown); 'kept' in the
    result: the spline is a kept one, not the library's own (KeptShown). ``max_iter``: the
    solver's Newton iterations per solve (MaxIter; its work budget grows with it). Raises
    InputProblem with a user message."""
    n = np()
    if mode not in MODES:
        raise InputProblem(f"unknown mode {mode!r} (tension or length)")
    for i, p in enumerate(points):
        if not all(math.isfinite(c) for c in p):
            raise InputProblem(f"point {i + 1} is not finite ({p.x:g}, {p.y:g}, {p.z:g})")
    pts = list(points)
    extent = max(((a - pts[0]).Length for a in pts), default=0.0)
    if len(pts) > 1 and not extent > 0.0:        # all of them, counted before the drop below
        raise InputProblem(f"the {len(pts)} points coincide")
    returns = ends_at_start(pts)
    if closed and returns:
        pts = pts[:-1]                     # a closed wire's first vertex, repeated
    need = 3 if closed else 2
    if len(pts) < need:
        raise InputProblem(f"{len(pts)} point{'s' if len(pts) != 1 else ''}: an elastic spline "
                           f"needs at least {need}{' (closed)' if closed else ''}")
    value = check_number("Tension", tension, 0.0, None, "1/mm^2", why="0 is the free batten; to "
                         "push the batten together give a length") if mode == "tension" \
        else check_number("Length", length, 0.0, None, "mm", why="0 is the free batten's length")
    tol, degree = check_tolerance(tol), check_degree(degree)
    ends = [None, None]
    if not closed:
        for j, spec in enumerate((start, end)):
            if spec is not None:
                i, inner = (0, 1) if j == 0 else (-1, -2)
                ends[j] = end_condition(spec[1], spec[0], pts[i], pts[inner], arriving=j == 1,
                                        at_end=spec[2] if len(spec) > 2 else None)
                if ends[j]["u"] is not None:      # the direction the seam's rule took
                    ends[j]["seam"] = end_condition(spec[1], spec[0], pts[i], pts[inner],
                                                    arriving=j == 1, seam=True)["direction"]
    # the plane holds the points and the end tangents
    h = extent / max(len(pts) - 1, 1) or 1.0
    probes = [pts[0 if j == 0 else -1] + c["direction"] * h for j, c in enumerate(ends) if c]
    try:
        loc, plane = plane_coordinates(pts + probes, plane, flat=1e-6,
                                       what="points (with the end edges' tangents)")
    except InputProblem:
        raise
    except (ValueError, ArithmeticError) as exc:
        raise InputProblem(f"no plane through the points: {exc}") from None
    xy = n.ascontiguousarray(loc[:len(pts)])
    specs, notes, cautions, k = [None, None], [], [], len(pts)
    for j, c in enumerate(ends):
        if c is None:
            continue
        t = (loc[k] - xy[0 if j == 0 else -1]) / h
        k += 1
        t = t / n.hypot(*t)
        what = "the start edge" if j == 0 else "the end edge"
        if c["condition"] == "G2":
            specs[j] = {"tangent": (float(t[0]), float(t[1])),
                        "curvature": plane_curvature(c["edge"], c["at_end"], t, plane, what,
                                                     u=c["u"])}
        else:
            specs[j] = (float(t[0]), float(t[1]))
        if c["gap"] > 1e-7 * (1.0 + extent):   # a gap is not a join: said, not moved
            cautions.append(gap_caution(c, j, what))
    if mode == "length":
        polygon = float(n.sum(n.hypot(*n.diff(n.vstack([xy, xy[:1]]) if closed else xy,
                                               axis=0).T)))
        if value == 0.0:
            free, _ = _solve(xy, "tension", 0.0, closed, *specs, max_iter=max_iter)
            value = free.length
        elif value <= polygon:
            raise InputProblem(f"Length = {value:.6g} mm is not longer than the polygon through "
                               f"the points ({polygon:.6g} mm): any length above it is possible")
    returns = returns and not closed      # an open batten through the first point twice
    try:
        sp, note = _solve(xy, mode, value, closed, *specs, max_iter=max_iter)
    except NoSpline as exc:
        if returns:
            raise type(exc)(f"the points end where they start (a closed wire) but Closed is off, "
                           f"so an open batten must pass the first point twice: {exc}; or set "
                           "Closed for a closed batten") from None
        raise
    if note:
        notes.append(note)
    lost = ""
    own = sp
    if mode == "tension" and shown and not closed:
        sp, note, lost = kept_shown(xy, value, specs, sp, *shown)
        if note:
            notes.append(note)
    if returns:                           # its two ends meet at a corner: never silent
        a = sp.angle(2)
        corner = abs(math.degrees(math.remainder(float(a[-1] - a[0]), 2 * math.pi)))
        cautions.append(f"the points end where they start (a closed wire) but Closed is off: "
                        f"the open batten's ends meet at the first point at a {corner:.3g} deg "
                        "corner; set Closed for a closed batten through them")
    if not closed and not returns and start is None and end is None:
        cautions.extend(closing_hint(xy, sp))
    if advise:
        cautions.extend(batten_cautions(sp, mode))
    for j, name in ((0, "first"), (-1, "last")):
        if isinstance(specs[j], dict):     # its force: GuideForces
            notes.append(f"G2 {'start' if j == 0 else 'end'}: a guide duck a quarter into the "
                         f"{name} span holds the batten there")
    try:
        bs = sp.to_bspline(tol, degree)
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"B-spline: {_library_message(exc)}") from None
    seams = [(j, c["seam"], c["direction"]) for j, c in enumerate(ends) if c and "seam" in c]
    return {"spline": sp, "bspline": bs, "placement": plane, "forces": duck_forces(sp),
            "notes": notes, "warnings": cautions, "seams": seams, "lost": lost,
            "kept": sp is not own}


def kept_shown(xy, tension, specs, sp, curves, length, shown_tension, switched=False,
               kept=False):
    """(spline, note, lost) for tension mode given the spline on screen (``curves``: its Curves
    JSON, ``length``, ``shown_tension``), as a switch of Solve for promises (QA23gui F2):
    the library's own start may reach another spline of the same tension (ducks by length
    272.1 mm, tension 6.26e-4 /mm^2: 225.6 mm, the energy falls beyond ~242 mm: a second
    branch), so where the shown one passes these very points at this tension, the solve
    starts from its pieces (el.elastic_spline initial=: Newton on its branch) and keeps it.
    A shown spline pushed together (tension < 0, by length) has no tension-mode twin: said
    (note and lost, the report view says it too). Where the solve from the shown pieces does
    not reach it again right after a switch of Solve for (``switched``), that is said too;
    else ``sp`` and no note: the shown curve was another problem's (other ducks, another
    tension typed, other end conditions) or the solve found it anyway. Where the shown
    spline was a kept one (``kept``: KeptShown) and only the ducks moved, followed_kept."""
    e = el()
    if not curves or abs(float(sp.length) - length) <= 1e-9 * length:
        return sp, "", ""
    curve_from_dict = binding_module("io").curve_from_dict
    try:
        pieces = [curve_from_dict(d) for d in json.loads(curves)]
    except ValueError:
        return sp, "", ""
    extent = float(np().max(np().abs(xy))) + 1.0
    if len(pieces) != len(xy) - 1:
        return sp, "", ""                   # other ducks: not this problem's curve
    if any(math.hypot(p.x0 - x, p.y0 - y) > 1e-9 * extent for p, (x, y) in zip(pieces, xy)):
        if not kept or shown_tension != tension:
            return sp, "", ""               # a drag of the library's own: no extra solve
        return followed_kept(xy, tension, specs, sp, length)
    if shown_tension < 0.0:
        lost = (f"the spline shown by length ({length_mark(length, 6)}) was pushed together "
                f"(tension {tension_mark(shown_tension, length, 3)}): a tension is >= 0, so "
                f"tension mode cannot keep it and solved at Tension = "
                f"{tension_mark(tension, length, 3)} instead (Solve for a length keeps it)")
        return sp, lost, lost
    if shown_tension != tension:
        return sp, "", ""
    try:
        kept = quiet_spline(xy, tension=tension, start=specs[0], end=specs[1], initial=pieces)
    except (ValueError, ArithmeticError, RuntimeError, e.ElasticaError):
        kept = None
    if kept is None or abs(float(kept.length) - length) > 1e-6 * length:
        lost = (f"the spline shown ({length_mark(length, 6)}) was not found again at this "
                f"tension (solved from it), so another spline of this tension through the "
                f"points is shown, {length_mark(sp.length, 6)} long (Solve for a length keeps "
                "the one shown)") if switched else ""
        return sp, lost, lost
    # one sentence: Status's "; " parts are the panel's lines
    return kept, (f"the spline shown kept ({length_mark(kept.length, 6)}), though another "
                  f"spline of this tension through the points is {length_mark(sp.length, 6)} "
                  "long"), ""


def followed_kept(xy, tension, specs, sp, length):
    """(spline, note, lost) where a kept spline's ducks moved (revB F2: a 0.01 mm nudge
    jumped 272.104 -> 225.578 mm, 'ok'): continuation, by the shown length through the new
    ducks (that branch: tension near the kept one's), then at the tension from its pieces;
    the 0.01 / 0.5 / 2 / 10 mm nudges of the QA's duck 5 give 272.10 / 271.87 / 271.21 /
    278.02 mm. Where either solve fails, the library's own (``sp``) is shown and said."""
    e = el()
    try:
        by_length = quiet_spline(xy, length=length, start=specs[0], end=specs[1])
        kept = quiet_spline(xy, tension=tension, start=specs[0], end=specs[1],
                            initial=by_length.pieces)
    except (ValueError, ArithmeticError, RuntimeError, e.ElasticaError) as exc:
        lost = (f"the spline kept at the switch of Solve for ({length_mark(length, 6)}) "
                f"could not be followed to the moved points ({_library_message(exc)}), so "
                f"another spline of this tension through them is shown, "
                f"{length_mark(sp.length, 6)} long (Solve for a length keeps a length)")
        return sp, lost, lost
    if abs(float(kept.length) - float(sp.length)) <= 1e-6 * float(sp.length):
        return sp, "", ""                   # the two branches met: the library's own
    return kept, (f"the spline kept at the switch of Solve for followed to the moved points "
                  f"({length_mark(length, 6)} -> {length_mark(kept.length, 6)}), though "
                  f"another spline of this tension through them is "
                  f"{length_mark(sp.length, 6)} long"), ""


def batten_cautions(sp, mode):
    """The cautions of a batten that loops or is an unstable equilibrium, with the way out:
    by tension, the least larger tension of the ladder that holds (the binding's
    ElasticSpline.holding_text: solved once, kept with the spline), or, where none does
    (the needle: every tension loops or would snap), the points either side of the
    sharpest turn to move apart; by length, another length or a tension."""
    out = []
    if mode == "tension" and (sp.loops or sp.unstable):
        m, _, polygon = sp.holding()
        fix = ("raise the tension to " if m is not None else "") + sp.holding_text(
            lambda t: f"Tension = {tension_mark(t, polygon, 6)}", "a length")
    if sp.loops:
        where = sp.crossing_text()   # the places, as the library's LoopWarning says them
        out.append("the batten loops away from its points (it crosses itself, or is longer "
                   "than 4 x their polygon" + (f"; it crosses itself {where}, points counted "
                                               "from 0" if where else "") +
                   "): no fair batten at this " + (f"tension; {fix}" if mode == "tension" else
                                                   "length; give a shorter length or a tension"))
    if not sp.loops:                      # a micro-loop without a crossing: HookWarning's words
        hooked = binding_module("spline_hook").hook_text(sp, length_mark, noun="batten")
        if hooked:
            out.append(hooked)
    if sp.unstable:                       # no minimum: the library's UnstableWarning's words
        out.append(sp.unstable_text(fix if mode == "tension" else
                                    "try another length, or a tension", said="", noun="batten"))
    return out


def _parallel(a, b):
    return a.Length > 0.0 and b.Length > 0.0 and a.getAngle(b) <= 1e-6


def seam_changes(shape, seams):
    """The notes for a stored spline (``shape``, before this recompute) joined to a closed
    edge by the rule before 4a0ae84, at the edge's seam (parameter 0), which this recompute
    joins at its point nearest the end duck instead (spline_core's 'seams': (end, the
    seam's direction, the one taken)): its end ran in the seam's direction, not in this
    one's. Else none."""
    if shape is None or shape.isNull() or len(shape.Edges) != 1:
        return []
    e = shape.Edges[0]
    out = []
    for j, seam, now in seams:
        stored = App.Vector(e.tangentAt(e.FirstParameter if j == 0 else e.LastParameter))
        if _parallel(stored, seam) and not _parallel(seam, now):
            out.append(f"the {'start' if j == 0 else 'end'} edge is closed: this spline was "
                       "joined to it at its seam by an earlier version of the workbench and now "
                       "meets it at its point nearest the "
                       f"{'first' if j == 0 else 'last'} point, as a new one does: its shape changed")
    return out


# sigma P^2 (P: the polygon through the points; the binding's spline.HOLD_MULTIPLES, the list
# el.holding_tension solves): where no free batten passes the points,
# the Elastic spline command starts at the least of these whose batten does not loop and
# holds (is no unstable equilibrium: el_spline_result.unstable); the QA's spike, P = 390 mm:
# loops up to 5, unstable at 10 .. 50 (1.33 P long at 10), holds from 100 (1.17 P); a
# zigzag: 1.35 P at 1
def tension_multiples():
    return binding_module("spline").HOLD_MULTIPLES


def starting_tension(points, plane=None, closed=False, tol=1e-3, degree=BSPLINE_DEGREE,
                     hand=None):
    """A tension to start a spline by, where the free batten does not pass the points: the
    least of tension_multiples() / P^2 (3 digits) whose batten does not loop and holds (not
    ElasticSpline.unstable); where none holds, the least whose batten does not loop (its
    Warnings say it is unstable). Each tension is solved once (the one returned is not
    solved again: ``hand``). Returns (tension, note for the user: its figures marked,
    units.say); raises NoSpline when none of them gives one. ``hand``: a list given its
    spline (kept.checked_call), for the feature made at that tension (FeatureProxy.handed:
    computed once)."""
    pts = list(points) + (list(points[:1]) if closed else [])
    polygon = sum((b - a).Length for a, b in zip(pts, pts[1:]))
    multiples = tension_multiples()
    ladder = f"{multiples[0]:g} to {multiples[-1]:g}"
    fallback = None                      # the least without loops, unstable
    for m in multiples:
        tension = float(f"{m / polygon ** 2:.3g}")
        try:
            checked = checked_call(spline_core, points, plane, "tension", tension,
                                   closed=closed, tol=tol, degree=degree, advise=False)
        except DoublesBack:
            raise
        except NoSpline:
            continue
        sp = checked[1]["spline"]
        if sp.loops:
            continue
        if not sp.unstable:
            fallback = (m, tension, checked, "whose batten does not loop and holds (a stable "
                        "equilibrium)")
            break
        if fallback is None:
            fallback = (m, tension, checked, "whose batten does not loop: none of them gives "
                        "one that holds (a stable equilibrium) without loops")
    if fallback is None:
        raise NoSpline("no free batten (tension 0) passes these points (it slides off its ducks), "
                       f"nor one without loops at {ladder} / the polygon through them squared: "
                       "give a length")
    m, tension, checked, which = fallback
    sp = checked[1]["spline"]
    if sp.unstable:     # every rung above it was solved: none holds (ElasticSpline.holding's
        n = np()        # answer, kept with the spline, not solved again)
        ring = n.vstack([sp.data, sp.data[:1]]) if sp.closed else sp.data
        sp._holding = (None, None, float(n.sum(n.hypot(*n.diff(ring, axis=0).T))))
    checked[1]["warnings"].extend(batten_cautions(sp, "tension"))
    try:                # keyed as the feature's recompute calls it (advise True: said above)
        key = call_key(spline_core, points, plane, "tension", tension, closed=closed, tol=tol,
                       degree=degree)
    except TypeError:
        key = None
    checked = (key, checked[1])
    if hand is not None:
        hand.append(checked)
    return tension, (f"no free batten (tension 0) passes these points (it slides off "
                     f"its ducks): solved at Tension = {tension_mark(tension, polygon, 6)} "
                     f"instead ({m:g} / the {length_mark(polygon, 4)} polygon through "
                     f"them squared, the least of {ladder} {which}); change it, or give a length")


class SplineProxy(FeatureProxy):
    """The elastic spline through the linked points."""

    kind = "Spline"
    note_props = ("Mode", "Tension")    # a tension where the free batten loops
    followed_links = {"Points": "PointsGeometry", "StartEdge": "StartEdgeGeometry",
                      "EndEdge": "EndEdgeGeometry"}

    def setup(self, obj):
        tol, _, _ = defaults()
        add_link(obj, "App::PropertyLinkSubList", "Points", "Input",
                 "The ducks, in order: " + DUCKS_NEED)
        add_geometry_index(obj, "PointsGeometry", "Points")
        add_enum(obj, "Mode", "Spline", "Solve for a given tension (default 0: the free "
                 "batten) or a given total length (the tension follows)", MODES, "tension")
        add_per_area(obj, "Tension", "Spline",
                     "Tension sigma in tension mode (1/mm^2, >= 0): 0 = the free batten, "
                     "larger pulls the batten straighter between the ducks", 0.0)
        add_length(obj, "Length", "Spline",
                   "Total length in length mode, longer than the polygon through the "
                   "points; 0 = the free batten's length", 0.0)
        add_property(obj, "App::PropertyBool", "Closed", "Spline",
                     "A closed batten through the points (the end conditions do not apply); "
                     "follows the points' wire when it is closed or opened", False)
        add_property(obj, "App::PropertyBool", "SourceClosed", "Spline",
                     "Whether the points ended where they start (a closed wire's) at the last "
                     "recompute: Closed follows a change of it (follow_source)", obj.Closed)
        obj.setEditorMode("SourceClosed", 2)
        for end, which in (("Start", "first"), ("End", "last")):
            add_enum(obj, f"{end}Condition", "Spline",
                     f"At the {which} point: natural (curvature 0, a free end), tangent to "
                     f"{end}Edge, or G2 to it (tangent and curvature; a guide duck a quarter "
                     "into that end's span, free to move across it, holds the batten there)",
                     END_CONDITIONS, "natural")
            add_link(obj, "App::PropertyLinkSub", f"{end}Edge", "Spline",
                     f"The edge the {which} point follows (tangent or G2) at the end "
                     f"{end}EdgeAt says (nearest: its end nearest that point)")
            add_geometry_index(obj, f"{end}EdgeGeometry", f"{end}Edge")
            add_edge_end(obj, f"{end}EdgeAt", "Spline", f"{end}Edge")
        add_property(obj, "App::PropertyFloat", "Stiffness", "Spline",
                     "Bending stiffness EI of the batten (N mm^2): the duck forces in newtons; "
                     "0 = in units of EI/2 (1/mm^2)", 0.0)
        add_length(obj, "Tolerance", "BSpline",
                   "Largest distance of the B-spline from the elastic spline", tol)
        add_property(obj, "App::PropertyInteger", "Degree", "BSpline",
                     "Degree of the B-spline (3 to 7): one B-spline, G2 at the points",
                     BSPLINE_DEGREE)
        add_property(obj, "App::PropertyInteger", "MaxIter", "Spline",
                     "Newton iterations per solve of the elastic spline (1 to 1000): the "
                     "solver's work budget grows with it; raise it where the status says the "
                     "solver stopped at its work budget", MAX_ITER)
        for name, tip in (
                ("SplineLength", "Length of the spline (mm)"),
                ("SplineTension", "Tension sigma of the spline (1/mm^2): the given one, or the "
                                  "one the length needs (< 0: pushed together)"),
                ("Energy", "Bending energy: the integral of kappa^2 ds (1/mm)"),
                ("MaxCurvature", "Largest |curvature| (1/mm)"),
                ("BSplineDeviation", "Certified distance of the B-spline from the spline (mm)")):
            if name == "SplineTension":
                add_per_area(obj, name, "Result", tip)
            else:
                add_property(obj, "App::PropertyFloat", name, "Result", tip)
        if "SpanTensions" in obj.PropertiesList:   # version 1: a G2 end span's own tension
            obj.removeProperty("SpanTensions")
        add_property(obj, "App::PropertyVectorList", "Ducks", "Result",
                     "The points the spline passes through (global coordinates)")
        add_property(obj, "App::PropertyVectorList", "DuckForces", "Result",
                     "The force each duck exerts on the batten (global directions, units of "
                     "EI/2: 1/mm^2; times EI/2 in N mm^2 gives newtons); with the guide "
                     "ducks' they sum to zero")
        add_property(obj, "App::PropertyVectorList", "GuideDucks", "Result",
                     "G2 ends: the guide duck in each end span (global coordinates, the "
                     "start's first), a quarter of the span's chord from the end and moved "
                     "across the chord until the end has the edge's curvature")
        add_property(obj, "App::PropertyVectorList", "GuideForces", "Result",
                     "The force each guide duck exerts on the batten (as DuckForces; normal "
                     "to the batten)")
        add_property(obj, "App::PropertyInteger", "Poles", "Result", "Poles of the B-spline")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last solve")
        add_property(obj, "App::PropertyStringList", "Warnings", "Result",
                     "What the designer should know: an end edge that the spline does not meet, "
                     "a batten that loops away from its points, ducks taken in another order "
                     "than drawn (empty: none)")
        add_property(obj, "App::PropertyString", "Curves", "Result",
                     "The spline's pieces (JSON, plane coordinates)")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result", "The plane of the spline")
        add_property(obj, "App::PropertyBool", "KeptShown", "Result",
                     "The spline shown is one a switch of Solve for kept, not the library's "
                     "own of this tension: a duck move follows it (followed_kept)", False)
        obj.setEditorMode("KeptShown", 2)
        read_only(obj, "SplineLength", "SplineTension", "Energy", "MaxCurvature",
                  "BSplineDeviation", "Ducks", "DuckForces", "GuideDucks", "GuideForces",
                  "Poles", "Status", "Warnings", "Curves", "Plane")

    def end_specs(self, obj):
        """(start, end): None or (condition, Part edge, at_end) from the end properties."""
        out = []
        for end in ("Start", "End"):
            cond, link = getattr(obj, f"{end}Condition"), getattr(obj, f"{end}Edge")
            if cond == "natural" or obj.Closed:
                out.append(None)
                continue
            edge = None if link and link[1] and not link[1][0].startswith("Edge") else \
                followed_edge(obj, f"{end}Edge")
            if edge is None:
                raise InputProblem(f"{end}Condition = {cond} needs an edge: pick one "
                                   f"({end.lower()} edge)")
            out.append((cond, edge, edge_end_choice(obj, f"{end}EdgeAt")))
        return out

    def compute(self, obj):
        check_number("Stiffness", obj.Stiffness, 0.0, None, "N mm^2", why="0 shows the duck "
                     "forces in units of EI/2")
        element = followed_reader(obj, "Points")      # renames Points: read it after
        said = []                                     # ducks taken in another order
        pts, plane = gather_vertices(obj.Points, DUCKS_NEED, edge_means_object=True,
                                     curve_ordered=True, link="Points", element=element,
                                     said=said)
        followed = self.follow_source(obj, pts)
        try:
            switched, self._switched = getattr(self, "_switched", False), False
            # the curve on screen: the last good one, also after a recompute that failed
            # (its results and shape are kept, drawn dashed): skipping it then showed the
            # library's own spline, silently, once a duck dragged where no spline exists
            # came back (kept_shown keeps, follows or says the kept one)
            shown = (obj.Curves, float(obj.SplineLength), float(obj.SplineTension), switched,
                     obj.KeptShown) if obj.Ducks else None
            r = self.handed(spline_core, pts, plane, obj.Mode, obj.Tension, float(obj.Length),
                            obj.Closed, *self.end_specs(obj), tol=float(obj.Tolerance),
                            degree=obj.Degree, shown=shown, max_iter=obj.MaxIter)
        except InputProblem as exc:
            if followed:
                raise type(exc)(f"{followed}: {exc}") from None
            raise
        r["warnings"] = said + r["warnings"]
        if r["lost"]:                 # the curve shown lost by a mode switch: said as it is
            App.Console.PrintWarning(f"Elastica {obj.Label}: {say(r['lost'])}\n")
        if followed:                  # said once, as it happens (an error says it in its line)
            App.Console.PrintWarning(f"Elastica {obj.Label}: {followed}\n")
            r["notes"].insert(0, followed)
        return r

    @staticmethod
    def follow_source(obj, points):
        """Closed follows the points' wire, as the command sets it for a closed one: where
        they have come to end where they start (the wire closed) or no longer (opened) since
        the last recompute, Closed is set to match (a closed Draft wire gave an open batten
        through its first point twice: a corner, or no batten). The note saying so, or ''."""
        returns = ends_at_start(points)
        if returns == obj.SourceClosed:
            return ""
        obj.SourceClosed = returns
        if obj.Closed == returns:
            return ""
        obj.Closed = returns
        return (f"its points' wire is {'closed' if returns else 'open'}: the spline follows "
                f"it (Closed = {returns})")

    def apply(self, obj, r):
        sp, plc, bs = r["spline"], r["placement"], r["bspline"]
        old = obj.Shape.copy() if not obj.Shape.isNull() else None
        changed = seam_changes(old, r.get("seams", []))
        set_shape(obj, part_bspline(bs, plc).toShape())
        if changed:                       # marks: in the schema's length unit (units.say)
            length = (f" (length {coordinate_mark(old.Length, 6)} -> "
                      f"{coordinate_mark(obj.Shape.Length, 6)} {length_unit_mark(written=True)})")
            changed = [w + length for w in changed]
            for w in changed:                 # once: the next recompute finds the new shape
                App.Console.PrintWarning(f"Elastica {obj.Label}: {say(w)}\n")
        obj.SplineLength = sp.length
        obj.SplineTension = sp.tension
        obj.Energy = sp.energy
        obj.MaxCurvature = sp.max_curvature
        obj.BSplineDeviation = float(bs.max_deviation)
        obj.Ducks = to_3d(plc, sp.data)
        obj.GuideDucks = to_3d(plc, sp.guides)
        obj.GuideForces = [plc.Rotation.multVec(App.Vector(float(x), float(y), 0.0))
                           for x, y in sp.guide_forces]
        obj.DuckForces = [plc.Rotation.multVec(App.Vector(float(x), float(y), 0.0))
                          for x, y in r["forces"]]
        obj.Poles = int(bs.npoles)
        obj.Plane = plc
        obj.KeptShown = r.get("kept", False)
        curve_to_dict = binding_module("io").curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(c) for c in sp.pieces])
        cautions = r["warnings"]          # marked (units.say): said again in a panel
        if say(cautions) != list(obj.Warnings):
            # once per change of the warnings, not on every recompute (as ellblend's)
            for w in say(cautions):
                App.Console.PrintWarning(f"Elastica {obj.Label}: {w}\n")
        set_said(obj, "Warnings", cautions)
        set_said(obj, "Status", "; ".join(["ok"] + [f"warning: {w}" for w in cautions] + changed
                                          + r["notes"]))

    def onChanged(self, obj, prop):
        super().onChanged(obj, prop)
        if prop == "Mode" and "Restore" not in obj.State and not obj.Document.Transacting:
            self._switched = True       # kept_shown says a shown spline it cannot keep

    def plane_curves(self, obj):
        from .fit import stored_curves
        return stored_curves(obj)


def make(doc, sources=(), **props):
    """A new elastic spline through the picked points ``sources`` [(obj, [subnames])];
    props set Mode, Tension, Length, Closed, StartCondition, StartEdge (obj, ['EdgeN']),
    EndCondition, EndEdge, Stiffness, Tolerance, Degree."""
    for end in ("StartEdge", "EndEdge"):
        if end in props and props[end] is not None:
            o, sub = props[end]
            props[end] = (o, [sub] if isinstance(sub, str) else list(sub))
    return new_feature(doc, "ElasticaSpline", SplineProxy,
                       Points=source_list(sources), **props)


__all__ = ["SplineProxy", "NoSpline", "spline_core", "starting_tension", "make", "duck_forces",
           "ends_at_start", "MODES", "END_CONDITIONS"]
