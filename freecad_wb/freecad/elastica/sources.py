"""Points, vertices and edges from what the user picked (a PropertyLinkSub(List)
value: [(obj, (subname, ...)), ...]): sketch edges and vertices, sketches of points,
Points objects, wires and 3D polylines, CSV files. Raises InputProblem with a
message for anything unusable.

Everything read here is in global coordinates, where the 3D view draws it: a source
inside a container (a PartDesign Body, an App::Part) placed off the origin has its
Shape in the container's coordinates, so shapes and sub-elements are read through
geometry.global_shape / global_element and Points through global_points, never
obj.Shape (a fit of a sketch edge in a Body at z = 100 tilted 30 deg lay 89 mm from the
edge drawn, its plane being the sketch's global placement)."""
from __future__ import annotations

import os
import re

import FreeCAD as App
import Part

from .geometry import (binding_module, dedup, el, ends_meet, global_element, global_points,
                       global_shape, is_sketch, kept_indices, np)
from .proxy import InputProblem
from .units import exact_mark


def _subs(subs):
    return [s for s in (subs or ()) if s]


def nothing_read(need, link=None):
    """InputProblem for sources that are none: nothing selected for a command (``need``: what
    to select), or a feature's link ``link`` emptied (FreeCAD empties a link to an object
    deleted; a feature reported that as 'nothing selected', QA)."""
    if link:
        return InputProblem(f"its source was deleted: relink {link} ({need})")
    return InputProblem(f"nothing selected: select {need}")


def sketch_points(sketch):
    """The global positions of a sketch's point geometries (0.20 reports every
    sketch point as construction geometry, so all are taken)."""
    from .links import read_geometry
    plc = sketch.getGlobalPlacement()
    return [plc.multVec(g.toShape().Point) for g in read_geometry(sketch)
            if g.TypeId == "Part::GeomPoint"]


def chain(edges):
    """The edges sorted head to tail into one chain; InputProblem if they form several."""
    groups = Part.sortEdges(edges) if len(edges) > 1 else [edges]
    if len(groups) != 1:
        raise InputProblem(f"the selected edges form {len(groups)} separate chains, not one curve")
    return groups[0]


def sample_edges(edges, samples_per_edge):
    """Ordered points along a chain of edges (sorted and oriented head to tail);
    lines give their two end points. Returns (points, closed)."""
    ch = chain(edges)
    pts = []
    for e in ch:
        if isinstance(e.Curve, Part.Line) or e.Curve.TypeId == "Part::GeomLine":
            seg = [e.Vertexes[0].Point, e.Vertexes[-1].Point]
        else:
            seg = e.discretize(Number=samples_per_edge)
        if pts:
            if (seg[0] - pts[-1]).Length > (seg[-1] - pts[-1]).Length:
                seg = list(reversed(seg))
        elif len(ch) > 1:
            nxt = ch[1]
            ends = [nxt.Vertexes[0].Point, nxt.Vertexes[-1].Point]
            if min((seg[0] - p).Length for p in ends) < min((seg[-1] - p).Length for p in ends):
                seg = list(reversed(seg))
        pts.extend(seg)
    return dedup(pts), Part.Wire(ch).isClosed()


# a CSV fit's Thousands property: its values and read_points' thousands for each
THOUSANDS = {"auto": None, ".": ".", "none": "", ",": ","}
THOUSANDS_HINT = "(the fit's Thousands property: '.', ',' or none)"
_CLI_THOUSANDS = re.compile(r"\(command line: --thousands[^()]*(\([^()]*\)[^()]*)*\)")


def file_unit_mm(unit):
    """mm in one ``unit`` of a points file's header (io.read_points_unit's: 'm' for
    'x [m],y [m]'), 1.0 for none (mm, as FreeCAD reads lengths); None for a unit that is no
    length (px: a picture's, of no size). FreeCAD's units convert them (App.Units.Quantity);
    'pt', which it does not know, is the typographic point, 1/72 in."""
    if unit is None:
        return 1.0
    if unit == "pt":
        return App.Units.Quantity("1 in").getValueAs("mm").Value / 72.0
    try:
        q = App.Units.Quantity(f"1 {unit}")
    except (ValueError, RuntimeError):     # (0.20 raises ValueError: 'syntax error')
        return None
    return q.getValueAs("mm").Value if q.Unit == App.Units.Unit("mm") else None


def gather_points(sources, csv_file="", samples_per_edge=60, link=None, element=None,
                  notes=None, thousands=None, names=None, unit=None):
    """Points of a fit's input, in 3D, with what is known about them; ``link``: the
    feature's property the sources come from (None: a selection; see nothing_read);
    ``element``: the function (obj, name) that reads a picked sub-element (global_element;
    a feature's: links.followed_reader, its sketch geometry followed); ``notes``: a list
    the user's notes on what was left out are appended to (a whole sketch's edges beside
    its points); ``thousands``: how a CSV file groups thousands, read_points' (None: the
    file decides, '.', ',', '' none; a file that does not show it is refused naming ``link``'s
    feature's Thousands property, THOUSANDS); ``names``: a list each point's name is appended
    to, as the designer finds it (point_names; none for points sampled along edges).

    Returns (points: list[App.Vector], plane: App.Placement or None (a sketch's),
    ordered: True (in curve order), False (none: curve_order's) or None (a file's order,
    which may be no curve's: file_order), closed: bool). A CSV file's points are read in
    the unit its header names (``x [m],y [m]``: file_unit_mm), converted to mm; a unit that
    is no length (px) reads as mm, said in ``notes``; ``unit``: a list (header unit or None,
    mm per unit or None) is appended to, for a CSV file."""
    said_unit = unit
    el()
    if csv_file:
        lines = []
        try:
            arr, header = binding_module("io").read_points_unit(csv_file, 1, None, thousands,
                                                                lines)
        except ValueError as exc:
            # the library's way out names its own options (--thousands, read_points'
            # thousands=): here it is the fit's property
            raise InputProblem(_CLI_THOUSANDS.sub(THOUSANDS_HINT, str(exc))) from None
        mm = file_unit_mm(header)
        if said_unit is not None:
            said_unit.append((header, mm))
        unit = header
        if mm is None:
            mm = 1.0
            if notes is not None:
                notes.append(f"{os.path.basename(csv_file)}'s header names its coordinates in "
                             f"{unit}, which is no length: read as mm")
        pts = [App.Vector(*(list(map(float, r)) + [0.0] * (3 - len(r)))) * mm for r in arr]
        closed = ends_meet(pts)
        # (a .npy array has rows, no lines)
        row = "row" if csv_file.lower().endswith(".npy") else "line"
        _named(names, [f"{row} {k} of {os.path.basename(csv_file)}" for k in lines])
        return pts, None, None, closed
    if not sources:
        raise nothing_read("sketch edges or vertices, a Points object, a wire, or give a CSV "
                           "file", link)
    element = element or global_element
    from .links import reads
    read = reads()          # a sketch's geometry read once for its picked vertices' names
    edges, vertices, points = [], [], []
    said = []               # each of vertices' or points' name (point_names)
    plane = None
    sketches = set()
    for obj, subs in sources:
        subs = _subs(subs)
        if is_sketch(obj):
            sketches.add(obj.Name)
            plane = obj.getGlobalPlacement()
            pts = [] if subs else sketch_points(obj)
            n_edges = 0 if obj.Shape.isNull() else len(obj.Shape.Edges)
            if not subs and not pts and not n_edges:
                raise InputProblem(f"{obj.Label} holds no edges and no points")
            if pts:
                # a whole sketch holding points stands for them, as for an Elastic spline: a
                # 0.20 sketch's shape has no vertices of its points, which cannot be picked,
                # and its edges can (QA: its points and a lead-in line to join refused, 'select
                # its points in the 3D view')
                vertices.extend(pts)
                said.extend(point_names(obj))
                if n_edges and notes is not None:
                    notes.append(_edges_left_out(obj.Label, len(pts), n_edges))
                continue
        if obj.isDerivedFrom("Points::Feature"):
            mine = global_points(obj)       # (each read of Points.Points copies them all)
            points.extend(mine)
            said.extend(f"{obj.Label}'s point {k + 1}" for k in range(len(mine)))
            continue
        shape = global_shape(obj)
        if shape.isNull():
            raise InputProblem(f"{obj.Label} has no geometry")
        if not subs:
            if shape.Edges:
                edges.extend(shape.Edges)
            else:
                vertices.extend(v.Point for v in shape.Vertexes)
                said.extend(f"{obj.Label}'s Vertex{k + 1}" for k in range(len(shape.Vertexes)))
            continue
        for s in subs:
            e = element(obj, s)
            if s.startswith("Edge"):
                edges.append(e)
            elif s.startswith("Vertex"):
                vertices.append(e.Point)
                said.append(_vertex_named(read(obj) if is_sketch(obj) else obj, s))
            else:
                raise InputProblem(f"{obj.Label}.{s}: select edges or vertices")
    if len(sketches) > 1:
        plane = None
    if sum(bool(x) for x in (edges, vertices, points)) > 1:
        raise InputProblem("select either edges, or vertices, or a Points object, not a mix")
    if edges:
        pts, closed = sample_edges(edges, samples_per_edge)
        _few_line_points(sources, edges, pts, closed)
        return pts, plane, True, closed
    pts = vertices or points
    kept = kept_indices(pts)
    _named(names, [said[k] for k in kept] if len(said) == len(pts) else [])
    return [pts[k] for k in kept], plane, False, False


def _named(names, said):
    """Append the points' names ``said`` to the list ``names`` (None: not asked for)."""
    if names is not None:
        names.extend(said)


# what the Sketcher's Elements panel calls each kind of geometry (FreeCAD 0.20's
# TaskSketcherElements: '3-Point', '1-Line', '2-Arc', checked on 0.20.2 under xvfb)
_ELEMENT_KINDS = {"Part::GeomPoint": "Point", "Part::GeomLineSegment": "Line",
                  "Part::GeomArcOfCircle": "Arc", "Part::GeomCircle": "Circle",
                  "Part::GeomEllipse": "Ellipse", "Part::GeomArcOfEllipse": "Elliptical Arc",
                  "Part::GeomArcOfHyperbola": "Hyperbolic Arc",
                  "Part::GeomArcOfParabola": "Parabolic Arc",
                  "Part::GeomBSplineCurve": "BSpline"}


def element_name(sketch, i, geometry=None):
    """Geometry i of ``sketch`` as the Sketcher's Elements panel lists it: its index from 1
    and its kind ('12-Point', '1-Line'), whatever else the sketch holds (lines, arcs,
    construction geometry count too); ``geometry``: sketch.Geometry read already (each read
    copies every geometry: read once per element, a 10 000-point sketch's names took 32 s)."""
    from .links import read_geometry
    g = (read_geometry(sketch) if geometry is None else geometry)[i]
    return f"{i + 1}-{_ELEMENT_KINDS.get(g.TypeId, 'Other')}"


def point_names(sketch):
    """The names of a sketch's point geometries (sketch_points' order) as the designer finds
    them in the Sketcher: '<label>'s 12-Point', the Elements panel's (element_name)."""
    from .links import read_geometry
    geometry = read_geometry(sketch)
    return [f"{sketch.Label}'s {element_name(sketch, i, geometry)}"
            for i, g in enumerate(geometry) if g.TypeId == "Part::GeomPoint"]


def _vertex_named(obj, sub):
    """A picked vertex ``sub`` of ``obj`` named as picked ("Wire's Vertex3"); a sketch's with
    the element it ends ("Profile's Vertex3, the start of 2-Arc"); ``obj``: a sketch read once
    (links.SketchRead) where many of its vertices are named."""
    said = f"{obj.Label}'s {sub}"
    if not is_sketch(obj):
        return said
    from .links import END, START, geometry_of, sketch_geo_of_element
    at = sketch_geo_of_element(obj, sub)
    if at is None or at[1] not in (START, END):
        return said
    return (f"{said}, the {'start' if at[1] == START else 'end'} of "
            f"{element_name(obj, at[0], geometry_of(obj))}")


def _is_line(e):
    return isinstance(e.Curve, Part.Line) or e.Curve.TypeId == "Part::GeomLine"


def _few_line_points(sources, edges, pts, closed):
    """InputProblem naming the straight lines a fit was given when their end points are too
    few to fit (a sketch of one 30 mm line was refused as '2 points: a fit needs at least 6',
    points nobody selected, QA)."""
    from .fit_core import MIN_POINTS
    if closed or len(pts) >= MIN_POINTS or not all(_is_line(e) for e in edges):
        return
    lines = "one straight line" if len(edges) == 1 else f"{len(edges)} straight lines"
    size = f" ({sum(e.Length for e in edges):.4g} mm)"
    whole = [o for o, subs in sources if not _subs(subs)]
    what = (f"{whole[0].Label} holds {lines}{size}" if len(sources) == 1 and whole else
            f"the selection is {lines}{size}")
    raise InputProblem(f"{what}, whose {len(pts)} end points are all a fit gets from "
                       f"{'it' if len(edges) == 1 else 'them'}: a fit "
                       f"takes {MIN_POINTS} points or more (sketch points or vertices, a polyline "
                       f"of {MIN_POINTS - 1} lines or more) or a curved edge, which it samples")


def _edges_left_out(label, n_pts, n_edges):
    """The note for a whole sketch's edges left out of a fit of its points."""
    edges, it, them = (("its edge", "it", "it") if n_edges == 1 else
                       (f"its {n_edges} edges", "one", "them"))
    return (f"{label}: its {n_pts} points are fitted and {edges} left out (a fit takes points "
            f"or edges, not both): pick {it} as Start or End tangent to join it, or pick "
            f"{them} in the 3D view to fit {them} instead")


def wire_points(shape):
    """The vertices of a shape that is one wire (a polyline, a Draft wire, a sketch
    of connected lines), in order along it; a closed wire repeats its first vertex
    at the end. None when the shape is not one wire."""
    wires = shape.Wires
    if len(wires) != 1 or len(wires[0].Edges) != len(shape.Edges):
        return None
    pts = [v.Point for v in wires[0].OrderedVertexes]
    if wires[0].isClosed() and len(pts) > 2:
        pts.append(pts[0])
    return pts


def curve_order(xy):
    """The order of points without one of their own (xy: their plane coordinates): the
    binding's el.curve_order (a sketch's stored order first among equals, so Pin start
    means the first point made)."""
    return el().curve_order(xy)


def file_order(xy):
    """(order, warnings) of a file's points (xy: their plane coordinates): (None, []) when
    the file's order is a curve's (el.out_of_order, every point measured), kept exactly,
    else curve_order's, said in a warning."""
    o = el().out_of_order(xy, screen=False)
    if o.order is None:
        return None, []
    return o.order, [f"the file's points are not in curve order (their polyline is "
                     f"{exact_mark(o.given, 4)} long, {o.given / o.along:.3g} times the "
                     f"{exact_mark(o.along, 4)} of the points in curve "
                     "order): fitted in curve order, as a Points object's"]


def in_curve_order(points):
    """A Points object's points (a scan's cloud: its stored order is the scanner's) in the
    order of curve_order in their best-fit plane. Fewer than 3 points, coincident or
    non-finite ones stay as stored (the caller says what is wrong with them)."""
    if len(points) < 3:
        return list(points)
    try:
        xy, _ = el().plane_fit(np().array([tuple(p) for p in points], dtype=float))
    except (ValueError, ArithmeticError):
        return list(points)
    return [points[i] for i in curve_order(xy)]


def duck_order(obj, pts, said):
    """A sketch's points as a spline's ducks: in the order drawn (geometry index), the
    designer's, unless its polygon crosses itself where curve_order's does not (a duck
    added later between two others, QA: the free batten slid off it); then in curve order,
    said in ``said``. Curve order alone took a spike's five ducks (0,0) (100,0) (105,100)
    (110,0) (200,0) as (0,0) (100,0) (110,0) (200,0) (105,100), a 902 mm teardrop (QA)."""
    if len(pts) < 4:
        return pts
    try:
        xy, _ = el().plane_fit(np().array([tuple(p) for p in pts], dtype=float))
    except (ValueError, ArithmeticError):
        return pts
    order = curve_order(xy)
    crossings = el().shape.self_crossings     # the binding's (the Hermite table's loops)
    if not crossings(xy) or crossings(xy[order]):
        return pts
    shown = ", ".join(str(i + 1) for i in order[:12]) + (", ..." if len(order) > 12 else "")
    said.append(f"{obj.Label}'s points are taken in the order along them ({shown}), not as "
                "drawn: the polygon through them in the order drawn crosses itself; to "
                "choose the order, pick the points one by one in that order")
    return [pts[i] for i in order]


def object_points(obj, curve_ordered=False, said=None):
    """The points of a whole object, in order: a sketch's sketch points (else the
    vertices of its one wire; ``curve_ordered``: as a spline's ducks, duck_order, its
    warning added to the list ``said``), a Points object's points in curve order
    (in_curve_order), the vertices of a wire along it, else a shape's vertices."""
    if is_sketch(obj):
        pts = sketch_points(obj)
        if pts or obj.Shape.isNull():
            return duck_order(obj, pts, [] if said is None else said) if curve_ordered else pts
    if obj.isDerivedFrom("Points::Feature"):
        # Points.Points are placed by the object's own Placement (the kernel's transform):
        # a scan moved by it was fitted twice as far (QA); global_points adds its containers'
        return in_curve_order(global_points(obj))
    shape = global_shape(obj)
    if shape.isNull():
        raise InputProblem(f"{obj.Label} has no geometry")
    return wire_points(shape) or [v.Point for v in shape.Vertexes]


_CLOSED_KINDS = {"Part::GeomCircle": "a circle", "Part::GeomEllipse": "an ellipse"}


def _closed_curves(obj):
    """What a whole object is when it is closed curves only, without points of its own
    ('a circle', '2 closed curves'), else '': its one seam vertex each was taken for the
    points to go through ('1 point: an elastic spline needs at least 2' for a circle, QA)."""
    if obj.isDerivedFrom("Points::Feature") or (is_sketch(obj) and sketch_points(obj)):
        return ""
    shape = global_shape(obj)
    if shape.isNull() or not shape.Edges or not all(e.isClosed() for e in shape.Edges):
        return ""
    if len(shape.Edges) > 1:
        return f"{len(shape.Edges)} closed curves"
    return _CLOSED_KINDS.get(shape.Edges[0].Curve.TypeId, "a closed curve")


def gather_vertices(sources, need="vertices in order, or a sketch of points",
                    edge_means_object=False, curve_ordered=False, link=None, element=None,
                    said=None):
    """Picked points in selection order, without merging coincident ones: vertices
    of sketches or shapes ('VertexN'), or whole objects (``object_points``: a
    sketch's points, a Points object, a wire's vertices in order). ``need`` says
    what to select when nothing is; ``edge_means_object``: a picked edge stands for
    its whole object (a click on a Draft wire picks one of its edges);
    ``curve_ordered``: a whole sketch's points as a spline's ducks (duck_order, its warning
    added to the list ``said``; an elliptic blend's control points keep the order they were
    made in); ``link``: the
    feature's property the sources come from (None: a selection; see nothing_read);
    ``element``: reads a picked vertex (as gather_points'). Returns (points, plane: the sketch
    placement when all come from one sketch, else None)."""
    if not sources:
        raise nothing_read(need, link)
    element = element or global_element
    pts, sketches = [], set()
    for obj, subs in sources:
        subs = _subs(subs)
        if is_sketch(obj):
            sketches.add(obj.Name)
        if edge_means_object and any(s.startswith("Edge") for s in subs):
            subs = []
        if not subs:
            closed = _closed_curves(obj)
            if closed:
                raise InputProblem(f"{obj.Label} holds {closed}, without points to go through: "
                                   f"select {need}")
            pts.extend(object_points(obj, curve_ordered, said))
            continue
        for s in subs:
            if not s.startswith("Vertex"):
                raise InputProblem(f"{obj.Label}.{s}: select vertices (points), not {s}")
            pts.append(element(obj, s).Point)
    plane = None
    if len(sketches) == 1 and all(o.Name in sketches for o, _ in sources):
        plane = next(o for o, _ in sources).getGlobalPlacement()
    return pts, plane


def gather_edges(sources, link=None, element=None):
    """The picked edges (a chain, sorted head to tail) and the sketch plane when they
    all come from one sketch: (edges, plane or None). A whole object gives all its
    edges. ``link``: the feature's property the sources come from (see nothing_read);
    ``element``: reads a picked edge (as gather_points')."""
    if not sources:
        raise nothing_read("an edge or a sketch curve", link)
    element = element or global_element
    edges, sketches, plane = [], set(), None
    for obj, subs in sources:
        subs = _subs(subs)
        shape = global_shape(obj)
        if shape.isNull() or not shape.Edges:
            raise InputProblem(f"{obj.Label} has no edges")
        if is_sketch(obj):
            sketches.add(obj.Name)
            plane = obj.getGlobalPlacement()
        if not subs:
            edges.extend(shape.Edges)
            continue
        for s in subs:
            if not s.startswith("Edge"):
                raise InputProblem(f"{obj.Label}.{s}: select edges, not {s}")
            edges.append(element(obj, s))
    if len(sketches) != 1 or any(not is_sketch(o) for o, _ in sources):
        plane = None
    return chain(edges), plane


def sample_chain(edges, n):
    """n + 1 points and unit tangents along a chain of edges, evenly spaced in arc
    length (each edge's share by its length), oriented head to tail."""
    import numpy as np
    total = sum(e.Length for e in edges)
    pts, tans = [], []
    prev = None
    for i, e in enumerate(edges):
        k = max(2, int(round(n * e.Length / total)) + 1)
        seg = e.discretize(Number=k)                     # even in arc length (OCC)
        tan = [App.Vector(e.tangentAt(e.Curve.parameter(p))).normalize() for p in seg]
        forward = True
        if prev is not None:
            forward = (seg[0] - prev).Length <= (seg[-1] - prev).Length
        elif len(edges) > 1:
            nxt = edges[1]
            ends = [nxt.Vertexes[0].Point, nxt.Vertexes[-1].Point]
            forward = min((seg[-1] - p).Length for p in ends) <= min((seg[0] - p).Length
                                                                      for p in ends)
        if not forward:
            seg, tan = seg[::-1], [-t for t in tan[::-1]]
        if pts:
            seg, tan = seg[1:], tan[1:]
        pts.extend(seg)
        tans.extend(tan)
        prev = pts[-1]
    return pts, np.array([tuple(t) for t in tans])
