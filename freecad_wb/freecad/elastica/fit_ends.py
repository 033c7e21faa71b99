"""End conditions of a Fit elastica: the library's constraints from the Fit's fields
(pinned ends, tangents of picked edges at their ends nearest the points, end curvatures,
G1 / G2 joins to an edge's end), the field that set each (messages name it), and the
points' direction the picked edges say."""
from __future__ import annotations

import math

import FreeCAD as App
import Part

from .geometry import confusion, nearest_parameter, np, plane_curvature
from .proxy import InputProblem, check_number

# the library's constraint names -> the fields that set them (messages name the field)
CONSTRAINT_FIELDS = {"start_point": "Pin start", "end_point": "Pin end",
                     "start_tangent": "Start tangent", "end_tangent": "End tangent",
                     "start_curvature": "Start curvature", "end_curvature": "End curvature"}
# How an end meets its tangent edge: its tangent only, or joined to the edge's end (the
# CAD sense: G1 = the point and the tangent, G2 = the curvature too)
CONTINUITIES = ["tangent", "G1", "G2"]
CONTINUITY_NAMES = {"tangent": "Tangent only", "G1": "G1", "G2": "G2"}


# an edge whose tangent leaves the fit plane by more than this (degrees) is said to be
# projected (QA21gui F7): below it, the tilt of a plane fitted to scanned points
TILT_SAID = 0.1


def tangent_angle(edge, at, forward, plane, at_end=None):
    """(angle, at_end, tilt): the angle in ``plane`` of ``edge``'s tangent at its end nearest
    to ``at`` (``at_end`` True / False: at its end / start vertex, the end clicked; projected
    into the plane), signed so it points along ``forward`` (a plane vector), whether
    that end is the edge's last, and the angle (degrees) by which the tangent leaves the
    plane (0: in it)."""
    n = np()
    a, b = edge.FirstParameter, edge.LastParameter
    if at_end is None:
        at_end = (edge.valueAt(a) - at).Length > (edge.valueAt(b) - at).Length
    u = nearest_parameter(edge, at) if edge.isClosed() else b if at_end else a   # no ends
    t = plane.Rotation.inverted().multVec(App.Vector(edge.tangentAt(u)))
    if math.hypot(t.x, t.y) < 1e-9 * max(t.Length, 1e-300):
        raise InputProblem("the tangent edge is perpendicular to the fit plane")
    if t.x * forward[0] + t.y * forward[1] < 0:
        t = -t
    tilt = math.degrees(math.atan2(abs(t.z), math.hypot(t.x, t.y)))
    return float(n.arctan2(t.y, t.x)), at_end, tilt


def end_constraints(xy, plane, pin_start=False, pin_end=False, start_edge=None, end_edge=None,
                    start_curvature=None, end_curvature=None, start_join="tangent",
                    end_join="tangent", tol=1e-3, start_at=None, end_at=None):
    """el.fit's constraints for plane points xy (in their order): pinned ends at the
    first / last point, tangents of Part edges at their ends nearest those points
    (the direction of travel), curvatures (1/mm, + turning left seen from the plane's
    normal, 0 = a free end or an inflection). ``start_join`` / ``end_join`` (CONTINUITIES):
    how that end meets its edge: its tangent only, or joined to the edge's end (G1: its
    point, in the fit plane, and tangent; G2: its curvature there too, signed by the
    direction of travel); the edge's end may lie off the fit plane by up to ``tol`` (mm,
    the B-spline's tolerance: a plane fitted to scanned points is not the sketch's).
    Returns (constraints, warnings: a join whose edge leaves its joined end back towards
    the points, which the curve meets only by turning back; then a tangent's edge leaving
    the plane, projected into it)."""
    c, warnings, tilted = {}, [], []
    if pin_start:
        c["start_point"] = (float(xy[0][0]), float(xy[0][1]))
    if pin_end:
        c["end_point"] = (float(xy[-1][0]), float(xy[-1][1]))
    for name, value in (("start_curvature", start_curvature), ("end_curvature", end_curvature)):
        if value is not None:
            c[name] = check_number(CONSTRAINT_FIELDS[name], value, unit="1/mm")
    extent = float(np().ptp(xy, axis=0).max())
    # the direction of travel near each end: over an eighth of the points (noise-proof)
    m = max(1, len(xy) // 8)
    for where, edge, join, i, forward, which in (
            ("start", start_edge, start_join, 0, xy[m] - xy[0], start_at),
            ("end", end_edge, end_join, -1, xy[-1] - xy[-1 - m], end_at)):
        End = where.capitalize()
        if join not in CONTINUITIES:
            raise InputProblem(f"{End}Continuity = {join!r}: one of {', '.join(CONTINUITIES)}")
        if join != "tangent" and edge is None:
            raise InputProblem(f"{End} join {join} joins the {where} tangent's edge: pick one "
                               f"({End} tangent), or set Tangent only")
        if join != "tangent" and f"{where}_point" in c:
            raise InputProblem(f"Pin {where} and {where} join {join} both set the {where} point: "
                               f"clear Pin {where} (the join starts at the edge's end)")
        if join == "G2" and f"{where}_curvature" in c:
            raise InputProblem(f"{End} curvature and {where} join G2 both set the curvature "
                               f"there: clear {End} curvature (G2 takes the edge's)")
        if edge is None:
            continue
        at = plane.multVec(App.Vector(float(xy[i][0]), float(xy[i][1]), 0.0))
        angle, at_end, tilt = tangent_angle(edge, at, forward, plane, which)
        c[f"{where}_tangent"] = angle
        if tilt > TILT_SAID:
            # its projection is used, said: a designer may mean a 3D edge's direction in the
            # plane (a Box edge), but not silently (QA21gui F7: 55.6 deg, the curve bent at
            # its start, said only as a higher rms); a blend's edges must be coplanar, a
            # fit's tangent is a direction only
            tilted.append(f"{End} tangent: its edge leaves the fit plane by {tilt:.1f}\u00b0; "
                             "its direction projected into the plane is used")
        if join == "tangent":
            continue
        if edge.isClosed():   # its seam is no end: the join was 28 mm off, the fit looped
            raise InputProblem(f"{End} join {join}: the {where} edge is closed (a full circle or "
                               "ellipse), it has no end to join; join an arc of it, or set "
                               "Tangent only (its tangent nearest the points' end)")
        u = edge.LastParameter if at_end else edge.FirstParameter
        p = plane.inverse().multVec(edge.valueAt(u))
        if abs(p.z) > max(tol, confusion(extent)):
            raise InputProblem(f"the {where} edge's end lies {abs(p.z):.3g} mm off the fit plane, "
                               f"more than the Tolerance {tol:g} mm: no {join} join in it "
                               "(Tangent only follows its direction)")
        c[f"{where}_point"] = (float(p.x), float(p.y))
        # the edge from its joined end, in the plane: a continuation of the curve at its end,
        # behind it at its start; else the curve turns back into it (a cusp), and a fit meets
        # that by looping (QA: a G2 end join on an arc leaving back over its points, a fit
        # looping 130 mm above points 20 mm high, status converged)
        into = plane.Rotation.inverted().multVec(App.Vector(edge.tangentAt(u)) * (-1 if at_end else 1))
        ahead = into.x * forward[0] + into.y * forward[1]
        if ahead < 0 if where == "end" else ahead > 0:
            # the joined end is the edge's nearer the points' own end: an edge nearer their
            # other end is the other end's (QA: 'join the edge's other end' was no way out)
            other = "end" if where == "start" else "start"
            near = math.hypot(p.x - xy[-1 - i][0], p.y - xy[-1 - i][1]) < \
                math.hypot(p.x - xy[i][0], p.y - xy[i][1])
            way_out = (f"it lies nearer the points' {other}: pick it as {other.capitalize()} "
                       "tangent" if near else "pick an edge that the points continue" if
                       where == "start" else "pick an edge that continues the points")
            warnings.append(f"{End} join {join}: the edge leaves its joined end back along the "
                            f"points, so the curve turns back into it (a cusp) and loops to do "
                            f"so: {way_out}, or set Tangent only")
        if join == "G2":
            c[f"{where}_curvature"] = plane_curvature(
                edge, at_end, (math.cos(angle), math.sin(angle)), plane, f"the {where} edge")
    return c, warnings + tilted


def constraint_fields(start_join="tangent", end_join="tangent"):
    """The field each library constraint comes from: a G1 / G2 join's point, tangent and
    (G2) curvature are the join's."""
    fields = dict(CONSTRAINT_FIELDS)
    for where, join in (("start", start_join), ("end", end_join)):
        if join in ("G1", "G2"):
            for what in ("point", "tangent") + (("curvature",) if join == "G2" else ()):
                fields[f"{where}_{what}"] = f"{where.capitalize()} join {join}"
    return fields


def constraint_problem(exc, fields=CONSTRAINT_FIELDS):
    """InputProblem naming the field of a constraint the library could not meet."""
    field = fields.get(exc.constraint, exc.constraint or "a constraint")
    why = str(exc).replace("fit: ", "", 1)
    return InputProblem(f"{field} cannot be met: {why}; free it or change it")


def field_names(constraints, fields):
    """The fields that set ``constraints`` (constraint_fields), each once, in the panel's order."""
    return ", ".join(dict.fromkeys(fields[c] for c in CONSTRAINT_FIELDS if c in constraints))


def facing_the_edges(xy, plane, start_edge, end_edge):
    """The points in the direction whose start lies nearer the start tangent's edge and
    whose end nearer the end's: the edges say which end the user means. Points without an
    order are sorted along their principal axis, whichever way it points; a wire or a
    file drawn from the other end runs away from its start edge, which a start join then
    meets only by turning back (QA: a wire drawn right to left, its lead-in line at the
    left joined G1, fitted as a curve 4e-12 mm long, rms 53 mm). xy: plane coordinates,
    and the distance from the plane as a third column if any."""
    def dist(edge, i):
        return edge.distToShape(Part.Vertex(plane.multVec(App.Vector(*map(float, xy[i])))))[0]

    votes = [dist(e, -1) - dist(e, 0) if w == "start" else dist(e, 0) - dist(e, -1)
             for w, e in (("start", start_edge), ("end", end_edge)) if e is not None]
    return xy[::-1].copy() if votes and sum(v < 0 for v in votes) > len(votes) / 2 else xy


__all__ = ["CONSTRAINT_FIELDS", "CONTINUITIES", "CONTINUITY_NAMES", "tangent_angle",
           "end_constraints", "constraint_fields", "constraint_problem", "field_names",
           "facing_the_edges"]
