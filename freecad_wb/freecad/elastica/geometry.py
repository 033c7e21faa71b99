"""FreeCAD geometry <-> the library's plane coordinates: placements of planes,
plane coordinates of 3D points (the sketch's plane or a fitted one), Part
B-splines of library B-splines, and writing results into sketches."""
from __future__ import annotations

import importlib
import math

import FreeCAD as App
import Part

from . import ensure_binding
from .proxy import InputProblem


def el():
    """The libelastica binding (imported on first use)."""
    return ensure_binding()


def binding_module(name):
    """The binding's submodule ``libelastica.<name>``, the binding imported first: only
    ensure_binding puts the source tree's python/ on sys.path (a document reopened in a
    fresh FreeCAD draws its features before anything else imported the binding)."""
    ensure_binding()
    return importlib.import_module("libelastica." + name)


def np():
    import numpy
    return numpy


def polyline_length(xy):
    """The length of the polyline through the rows of xy."""
    return float(np().sum(np().hypot(*np().diff(xy, axis=0).T)))


def confusion(extent):
    """The distance (mm) below which points of geometry ``extent`` mm across are one point:
    FreeCAD's Precision.confusion() (1e-7 mm: a closed sketch's ends meet to it, Part closes
    a wire through them) plus 1e-9 of the extent (never less than points coincide to,
    ellblend's pairs)."""
    return Part.Precision.confusion() + 1e-9 * extent


def ends_meet(points):
    """Whether three or more 3D points (mm) end where they start: the last within
    confusion() of their extent of the first."""
    if len(points) < 3:
        return False
    box = App.BoundBox()
    for p in points:
        box.add(p)
    return (points[0] - points[-1]).Length <= confusion(box.DiagonalLength)


def is_sketch(obj):
    return obj is not None and obj.isDerivedFrom("Sketcher::SketchObject")


def dedup(vecs, tol=1e-9):
    """The list ``vecs`` without consecutive repeats (the vectors kept_indices names)."""
    return [vecs[k] for k in kept_indices(vecs, tol)]


def kept_indices(vecs, tol=1e-9):
    """Indices of the vectors dedup keeps (a repeat merged into the first; sources' names)."""
    out = []
    for k, v in enumerate(vecs):
        if not out or (v - vecs[out[-1]]).Length > tol:
            out.append(k)
    return out


# ----------------------------------------------------------- where a source is drawn

def container_placement(obj):
    """The placement of the containers ``obj`` lies in (a PartDesign Body, an App::Part,
    nested ones): what takes its Shape, its Points, its vertices (all in the container's
    coordinates) to where the 3D view draws them. The identity at document level."""
    if not (hasattr(obj, "getGlobalPlacement") and hasattr(obj, "Placement")):
        return App.Placement()
    return obj.getGlobalPlacement().multiply(obj.Placement.inverse())


def global_shape(obj, name=""):
    """``obj``'s shape, or its sub-element ``name`` ('Edge3', 'Vertex2'), in global
    coordinates: where it is drawn, the placement of its containers applied (FreeCAD's
    Part.getShape given their matrix: obj.Shape is in its container's coordinates, a
    sketch's in its Body's). A copy; a null shape when there is none."""
    try:
        return Part.getShape(obj, name, needSubElement=bool(name),
                             mat=container_placement(obj).toMatrix())
    except (Part.OCCError, ValueError, IndexError, RuntimeError):
        return Part.Shape()


def global_element(obj, name):
    """The sub-element ``name`` of ``obj`` in global coordinates (global_shape), or
    InputProblem when it has none of that name."""
    e = global_shape(obj, name)
    if e.isNull():
        raise InputProblem(f"{obj.Label} has no {name}")
    return e


def global_points(obj):
    """A Points object's points in global coordinates: Points.Points carries its own
    Placement (the kernel's transform), not its containers'."""
    pts = list(obj.Points.Points)
    plc = container_placement(obj)
    return pts if plc.isIdentity() else [plc.multVec(p) for p in pts]


# ----------------------------------------------------------- placements <-> frames

def placement_from_frame(frame):
    """App.Placement of a libelastica prep.Frame (origin, e1, e2, e3 = normal)."""
    e1, e2, e3 = (App.Vector(*map(float, v)) for v in (frame.e1, frame.e2, frame.e3))
    m = App.Matrix(e1.x, e2.x, e3.x, 0, e1.y, e2.y, e3.y, 0, e1.z, e2.z, e3.z, 0)
    return App.Placement(App.Vector(*map(float, frame.origin)), App.Rotation(m))


def to_3d(plc, xy):
    """Global 3D vectors of plane points (n, 2) in the frame ``plc``."""
    return [plc.multVec(App.Vector(float(x), float(y), 0.0)) for x, y in xy]


def to_plane(plc, vectors):
    """(n, 3) local coordinates of global vectors in the frame ``plc``."""
    inv = plc.inverse()
    return np().array([tuple(inv.multVec(App.Vector(v))) for v in vectors], dtype=float)


def plane_coordinates(points, plane=None, flat=1e-9, what="points"):
    """(xy (n, 2), placement) of 3D points: in ``plane`` (a sketch's placement) when
    they all lie in it, else in their best-fitting plane. ``flat``: relative
    distance from the fitted plane allowed (None: any, a plane fit of scan data)."""
    n = np()
    extent = max(((a - points[0]).Length for a in points), default=0.0)
    if plane is not None:
        local = to_plane(plane, points)
        if n.max(n.abs(local[:, 2])) <= 1e-9 * (1.0 + extent):
            return n.ascontiguousarray(local[:, :2]), plane
    if not extent > 0.0:
        raise InputProblem(f"the {what} coincide")
    if len(points) < 3:
        raise InputProblem("two points lie in many planes: put them in a sketch (its plane), or "
                           "add a third point or an end tangent")
    xyz = n.array([tuple(p) for p in points], dtype=float)
    xy, frame = el().plane_fit(xyz)
    if flat is not None and frame.rms > flat * (1.0 + extent):
        raise InputProblem(f"the {what} are not coplanar (rms distance {frame.rms:.3g} mm from "
                           "their best plane)")
    return n.ascontiguousarray(xy), placement_from_frame(frame)


# ----------------------------------------------------------- edge ends

def edge_end(edge, at_end):
    """(point, direction leaving the edge) at its start or end vertex."""
    if at_end:
        u = edge.LastParameter
        t = edge.tangentAt(u)
    else:
        u = edge.FirstParameter
        t = -edge.tangentAt(u)
    return edge.valueAt(u), App.Vector(t).normalize()


def nearest_parameter(edge, point):
    """The parameter of ``edge``'s point nearest ``point`` (Part's distToShape): where a
    closed edge (a full circle or ellipse: its seam is no end) is joined."""
    info = edge.distToShape(Part.Vertex(point))[2][0]
    return float(info[2] if info[0] == "Edge" else info[5])


def curvature_vector(edge, u):
    """kappa N of an edge at parameter u (N towards the centre of curvature; the zero
    vector where the edge is straight)."""
    try:
        return App.Vector(edge.normalAt(u)) * float(edge.curvatureAt(u))
    except Part.OCCError:           # a line, or an inflection: OCC has no normal there
        return App.Vector(0, 0, 0)


def plane_curvature(edge, at_end, direction, plane, what="the edge", u=None):
    """The signed curvature, in ``plane``, of ``edge`` at its start or end (or at the
    parameter ``u``) travelled along the unit plane vector ``direction`` (tx, ty):
    positive when the curve turns left (counter-clockwise seen from the plane's normal),
    as the library counts it. InputProblem when the edge curves out of the plane there
    (no G2 join in it)."""
    if u is None:
        u = edge.LastParameter if at_end else edge.FirstParameter
    k = plane.Rotation.inverted().multVec(curvature_vector(edge, u))
    if abs(k.z) > 1e-6 * k.Length + 1e-12:
        raise InputProblem(f"{what} curves out of the plane there: no curvature-continuous "
                           "join in the plane")
    return float(direction[0] * k.y - direction[1] * k.x)


# ----------------------------------------------------------- B-splines

def curve_bspline(curve, tol, degree):
    """libelastica BSpline (plane coordinates) of a fitted / Hermite curve: a smooth
    elastica within ``tol``; a discrete one as the C2 cubic through its vertices."""
    e = el()
    if isinstance(curve, e.SmoothElastica):
        return curve.to_bspline(tol=tol, degree=degree)
    return binding_module("bspline").interpolate_c2(curve.points())


def chain_bspline(pieces, tol, degree, keyline=False, ends=None):
    """ONE libelastica BSpline of smooth elasticae that continue each other G2
    (el.smooth_chain_to_bspline: the pieces keep their end points, unit tangents and
    curvatures exactly and join C2), or with ``keyline`` of a keyline's two halves, each
    from the joint outwards, smooth or discrete (el.keyline_bspline; ``ends``: where
    discrete halves end, KeylineFit.ends). InputProblem when ``tol`` is not reached."""
    e = el()
    try:
        if keyline:
            return e.keyline_bspline(pieces[0], pieces[1], float(tol), int(degree), ends)
        return e.smooth_chain_to_bspline(pieces, float(tol), int(degree))
    except e.NotConvergedError as exc:
        raise InputProblem(f"the B-spline does not reach the tolerance {tol:g} mm: {exc}: "
                           "raise Tolerance") from None
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"no B-spline at tolerance {tol:g} mm: {exc}") from None


def part_bspline(bs, plc):
    """Part.BSplineCurve in 3D of a libelastica BSpline in the plane of ``plc``."""
    poles = to_3d(plc, bs.poles[:, :2])
    c = Part.BSplineCurve()
    c.buildFromPolesMultsKnots(poles, [int(m) for m in bs.mults], [float(k) for k in bs.knots],
                               False, int(bs.degree))
    return c


def bspline_edges(bsplines, plc):
    """The Part edges of library B-splines in the plane ``plc``."""
    return [part_bspline(b, plc).toShape() for b in bsplines]


# ----------------------------------------------------------- sketches

def link_edge(obj, name, geo_index=-1):
    """The global edge of a link: a sketch's geometry ``geo_index`` when >= 0 (stable
    when the sketch changes), else ``obj``'s sub-element ``name`` (global_element)."""
    if is_sketch(obj) and 0 <= geo_index < len(obj.Geometry):
        e = obj.Geometry[geo_index].toShape()
        e.transformShape(obj.getGlobalPlacement().toMatrix())
        return e
    return global_element(obj, name)


def read_whole_by(sketch):
    """The Elastica features that read ``sketch`` whole (a link without sub-elements):
    an edge copied into it changes what they read (a fit of its points refuses points
    with edges)."""
    users = []
    for user in sketch.InList:
        if not getattr(getattr(user, "Proxy", None), "kind", ""):
            continue
        for prop in ("Source", "Points"):
            links = getattr(user, prop, None)
            if isinstance(links, list) and any(o is sketch and not any(subs) for o, subs in links):
                users.append(user)
                break
    return users


def sketch_curves(feature, sketch):
    """The feature's B-spline curve(s) in ``sketch``'s coordinates. InputProblem when they
    do not lie in its plane (the sketch would keep only their shadow on it, flattened) or
    when another Elastica feature reads the sketch whole (the copy would change its input:
    a fit of the sketch's points stopped with 'points and an edge')."""
    readers = [u.Label for u in read_whole_by(sketch) if u is not feature]
    if readers:
        raise InputProblem(f"{sketch.Label} is read whole by {', '.join(readers)}: a curve "
                           "copied into it would change what they read; copy it into another "
                           "sketch, or a new one")
    inv = sketch.getGlobalPlacement().inverse()
    curves = []
    for e in global_shape(feature).Edges:
        c = e.Curve.copy()
        if not isinstance(c, Part.BSplineCurve):
            c = e.toNurbs().Edges[0].Curve
        c.transform(inv.toMatrix())
        curves.append(c)
    poles = [p for c in curves for p in c.getPoles()]
    if not poles:
        raise InputProblem(f"{feature.Label} has no curve to copy")
    # a B-spline lies in the hull of its poles: all of them in the plane put it there
    extent = max((p - poles[0]).Length for p in poles)
    off = max(abs(p.z) for p in poles)
    if off > confusion(extent):
        raise InputProblem(f"{sketch.Label} does not lie in the plane of {feature.Label} (its "
                           f"curve reaches {off:.3g} mm off the sketch's plane): copy it into a "
                           "sketch in the curve's plane, or a new one")
    return curves


# what a sketch's attachment is (Part::AttachExtension's properties)
ATTACHMENT = ("Support", "MapMode", "MapReversed", "MapPathParameter", "AttachmentOffset")


def new_copy_sketch(feature, body=None):
    """A new sketch for Copy into '(new sketch ...)', in ``body`` (a PartDesign Body: the
    sources') or at the document's root: attached as the first sketch the feature reads in
    that container that is attached (its ATTACHMENT: Support, MapMode, AttachmentOffset) and
    whose plane holds the curve, as Sketcher's new sketch is attached to a face or plane; so it
    moves as that sketch does (QA24gui F5: an unattached copy of a spline drawn on a Pad's top
    face stayed at z = 10 when the Pad grew to 15 mm, its Pocket a hidden void, and Copy into
    again refused). Without one: in a Body, attached to the Body's XY plane (Origin) with
    the curve's plane (feature.Plane, the Body's placement taken out) as its attachment
    offset, as Sketcher's new sketch in a Body; at the root, unattached in that plane."""
    from .containers import read_objects
    doc = feature.Document
    sk = body.newObject("Sketcher::SketchObject", "ElasticaSketch") if body is not None \
        else doc.addObject("Sketcher::SketchObject", "ElasticaSketch")
    for src in dict.fromkeys(read_objects(feature)):
        if not is_sketch(src) or src.getParentGeoFeatureGroup() != body or \
                src.MapMode == "Deactivated" or not src.Support:
            continue
        for prop in ATTACHMENT:
            setattr(sk, prop, getattr(src, prop))       # the attacher places it at once
        try:
            sketch_curves(feature, sk)
            return sk
        except (InputProblem, Part.OCCError):           # a plane apart: not this one
            sk.MapMode = "Deactivated"
            sk.Support = None
    plane = feature.Plane
    if body is None:
        sk.Placement = plane
        return sk
    # in a Body: attached to its Origin's XY plane, the curve's plane its offset, as
    # Sketcher's new sketch in a Body is attached to a plane: it was unattached (MapMode
    # Deactivated, a fixed Placement) when no source sketch was attached
    offset = body.getGlobalPlacement().inverse().multiply(plane)
    xy = [o for o in getattr(body.Origin, "OriginFeatures", ()) if o.Role == "XY_Plane"] \
        if getattr(body, "Origin", None) is not None else []
    if not xy:
        sk.Placement = offset
        return sk
    sk.Support, sk.MapMode, sk.AttachmentOffset = [(xy[0], "")], "FlatFace", offset
    return sk


def write_to_sketch(feature, sketch, constrain_to=None):
    """Add the feature's B-spline edge(s) to ``sketch``, mapped into its plane: a copy,
    which no longer follows the feature. ``constrain_to`` [(geo index, pos), (geo index,
    pos)] adds endpoint tangency of the new curve's start and end to those sketch
    geometries (join_ends: a blend's copy into its edges' sketch, as Sketcher_CreateFillet
    joins its arc), also where an earlier copy is replaced (a joint it has already is not
    added twice). Returns the new geometry indices.
    InputProblem, with nothing added, when the sketch is not in the curve's plane.

    A sketch that holds an earlier copy of the same feature (its geometry Tags, kept in
    the feature's hidden COPIES) gets it replaced in place, at its indices: the
    constraints joining it to the rest of the profile stay and the solver moves their
    ends onto the new copy, as when a curve is edited in the Sketcher. A second copy
    beside the first (what the panel's Copy into did) overlapped it, and a Pocket of the
    sketch failed with only 'Recompute failed!' (QA20gui F4). The report view names it.
    An earlier copy in another number of pieces (a G2 quadratic's, 2 -> 3) is replaced
    too (_replace_copy: written beside it, 5 -> 8 geometries, left the profile open and its
    Pad invalid, QA24gui F1), the constraints at its ends kept."""
    curves = sketch_curves(feature, sketch)
    earlier = earlier_copy(feature, sketch)
    if earlier and len(earlier) == len(curves):
        geometry = sketch.Geometry
        for k, (i, c) in enumerate(zip(earlier, curves)):
            geometry[i] = _marked(c, feature, k)
        _follow_ends(sketch, geometry, earlier)
        sketch.Geometry = geometry          # (Sketcher's own constraints keep their indices)
        ids = earlier
        App.Console.PrintMessage(
            f"Elastica: {sketch.Label}: its earlier copy of {feature.Label} (geometry "
            f"{', '.join(str(i + 1) for i in ids)}) replaced by the curve of now\n")
    elif earlier:
        ids, lost = _replace_copy(sketch, earlier, [_marked(c, feature, k)
                                                    for k, c in enumerate(curves)])
        App.Console.PrintMessage(
            f"Elastica: {sketch.Label}: its earlier copy of {feature.Label} in "
            f"{len(earlier)} pieces (geometry {', '.join(str(i + 1) for i in earlier)}) "
            f"replaced by the curve of now in {len(curves)} (geometry "
            f"{', '.join(str(i + 1) for i in ids)}), the constraints at its ends kept"
            + (f"; not kept (they named its pieces): {'; '.join(lost)}" if lost else "") + "\n")
    else:
        ids = [sketch.addGeometry(_marked(c, feature, k), False) for k, c in enumerate(curves)]
    _remember_copy(feature, sketch, ids)
    if constrain_to and ids:
        join_ends(sketch, ids, constrain_to)
    return ids


# how far (sketch units, relative to the copy's size) a joint's two ends may be apart and
# what the solver may move them for a joint to be added (join_ends): written exact, ~1e-13
JOINT_TOL = 1e-9


def _joined(sketch, a, b):
    """Whether a Coincident or Tangent constraint already joins the points ``a`` and ``b``
    ((geo index, pos) each)."""
    for c in sketch.Constraints:
        if c.Type in ("Coincident", "Tangent") and \
                {(c.First, c.FirstPos), (c.Second, c.SecondPos)} == {a, b}:
            return True
    return False


def join_ends(sketch, ids, ends):
    """Join the copy ``ids`` (its pieces in order) to the sketch geometry ``ends`` [(geo
    index, pos) at its start, (geo index, pos) at its end; pos None: that geometry's end
    nearer the copy's; geo index None: no joint there] by one endpoint-to-endpoint
    Tangent at each: what Sketcher_CreateFillet adds at both ends of its arc (checked on
    FreeCAD 0.20.2: two Tangent constraints, edge end to arc end, no Coincident). Such a
    Tangent holds the two ends together AND their tangents in line (the Sketcher draws it
    as one constraint, coincidence included); a Coincident beside it is redundant (the
    solver's -2). A B-spline's ends are its PosId 1 (start) and 2 (end) there, as a line's.
    The angle is locked to the ends' sense as written (the Sketcher's own autolock), so
    solving moves nothing. A joint already held by a Coincident or Tangent is left as it
    is (Copy into again). The sketch is solved: where it does not solve cleanly (conflicting
    or redundant constraints: an end held otherwise) or would move the copy, each joint is
    tried alone and the one the sketch takes kept (one refused joint does not take the other
    with it); each refused is said in the report view with the end held and by what (the
    copy's end dimensioned, or the edge's). Returns the constraints added (their indices)."""
    import Sketcher
    original, geometry = sketch.Geometry, sketch.Geometry
    start, end = (ids[0], 1), (ids[-1], 2)
    before = [_probe(g) for g in geometry]
    size = max([1.0] + [abs(v) for pts in before for p in pts for v in (p.x, p.y)])
    joints, snapped = [], False
    for (g, pos), mine in ((ends[0], start), (ends[1], end)):
        if g is None or not 0 <= g < len(geometry) or not hasattr(geometry[g], "FirstParameter"):
            continue
        b = _end_point(geometry[mine[0]], mine[1])
        if pos is None:         # the end nearer the copy's
            pos = min((1, 2), key=lambda k: (_end_point(geometry[g], k) - b).Length)
        at = _end_point(geometry[g], pos)
        if (at - b).Length > JOINT_TOL * size:
            continue            # not at that end
        # the copy's end put on the edge's end bit for bit: FreeCAD 0.20's solver takes a
        # B-spline's end tangent (BSpline::CalculateNormal, from its last two poles) only
        # where the joint's point EQUALS its end point, else a zero normal: a copy 1.2e-13
        # off an arc's end was 'partially redundant' and the solver moved it 6.8 mm
        copy = geometry[mine[0]]
        copy.setPole(1 if mine[1] == 1 else copy.NbPoles, at)
        snapped = True
        if not _joined(sketch, (g, pos), mine):     # (Copy into again: joined already)
            joints.append((g, pos, *mine))
    if snapped:
        sketch.Geometry = geometry      # the snapped ends (Tags, extensions kept)
    if not joints:
        return []
    was = sketch.solve()        # a sketch redundant already stays so: not the joints' doing
    n0 = len(sketch.Constraints)

    def clean():
        """The sketch solves as before and moves nothing: (True, why not)."""
        status = sketch.solve()
        moved = max(((p - q).Length for g0, g1 in zip(before, sketch.Geometry)
                     for p, q in zip(g0, _probe(g1))), default=0.0)
        if status == was and moved <= JOINT_TOL * size:
            return True, ""
        return False, ("would not solve with it" if status != was else
                       f"would move the geometry {moved:.3g} mm")

    snapped_geometry = sketch.Geometry
    added = [sketch.addConstraint(Sketcher.Constraint("Tangent", *j)) for j in joints]
    if clean()[0]:
        return added
    # one joint the sketch refuses does not take the other with it (review of F4): each
    # tried alone, the good one kept
    _take_back(sketch, n0, snapped_geometry)
    added, refused = [], []
    for j in joints:
        n = len(sketch.Constraints)
        c = sketch.addConstraint(Sketcher.Constraint("Tangent", *j))
        ok, why = clean()
        if ok:
            added.append(c)
            snapped_geometry = sketch.Geometry
            continue
        _take_back(sketch, n, snapped_geometry)
        refused.append(f"the copy's {'start' if j[3] == 1 else 'end'} is not joined to Edge"
                       f"{j[0] + 1}'s end by a Tangent constraint: the sketch {why}"
                       + (f" ({_held(sketch, j, n0)})" if why.startswith("would not") else ""))
    if not added:
        sketch.Geometry = original
    App.Console.PrintWarning(f"Elastica: {sketch.Label}: " + "; ".join(refused) + (
        "; its other end is joined" if added else "") + "\n")
    return added


def _take_back(sketch, n, geometry):
    """Delete the constraints from index ``n`` on, put ``geometry`` back (join_ends)."""
    for k in reversed(range(n, len(sketch.Constraints))):
        sketch.delConstraint(k)
    sketch.Geometry = geometry


def _held(sketch, joint, n0):
    """Which end of the refused ``joint`` is held otherwise, by which constraints (those on
    that point or on its whole geometry, the joints themselves left out): the copy's end
    dimensioned by the designer is not the edge's end (review of F4)."""
    g, pos, mine, mine_pos = joint

    def on(geo, point):
        types = []
        for c in sketch.Constraints[:n0]:
            refs = [(c.First, c.FirstPos), (c.Second, c.SecondPos), (c.Third, c.ThirdPos)]
            if any(r == geo and p in (point, 0) for r, p in refs):
                types.append(c.Type)
        return types
    said = [f"{who} by {', '.join(held)}" for who, held in (
        (f"the copy's {'start' if mine_pos == 1 else 'end'} is held", on(mine, mine_pos)),
        ("the edge's end is held", on(g, pos))) if held]
    return " and ".join(said) or "its ends are held through other geometry"


def _probe(g):
    """Points that show whether the sketch geometry ``g`` moved: its ends and middle, a
    B-spline's poles too, a point itself."""
    if not hasattr(g, "FirstParameter"):
        return [App.Vector(g.X, g.Y, g.Z)] if hasattr(g, "X") else []
    a, b = g.FirstParameter, g.LastParameter
    pts = [g.value(a), g.value(0.5 * (a + b)), g.value(b)]
    return pts + (list(g.getPoles()) if hasattr(g, "getPoles") else [])


def _end_point(curve, pos):
    return curve.value(curve.FirstParameter if pos == 1 else curve.LastParameter)


# the Tags of the geometry each earlier copy of a feature wrote ("<sketch name> <tag>"): a
# copy into the same sketch replaces it (write_to_sketch)
COPIES = "SketchCopies"


# A copy's geometry also carries a Part.GeometryStringExtension MARK, "<feature Name> <piece>":
# FreeCAD 0.20 gives every geometry a new Tag when a document is opened (they are not saved),
# so after a reopen the Tags in COPIES named nothing (Copy into added a second copy beside the
# first, QA20gui F4's overlap again; copies.py measured none); the extension is saved with
# the sketch and kept by its solver.
MARK = "ElasticaCopy"


# and a second, WRITTEN, where the copy was written: "u x y" at WRITTEN_AT points along it
# (sketch coordinates, repr: exact), so that copies.drift tells a copy the Sketcher moved from
# a feature that changed since (QA23gui F3: 'the Sketcher moved it' when a duck was dragged)
WRITTEN = "ElasticaCopyWritten"
WRITTEN_AT = 9


def _marked(curve, feature, k):
    ext = Part.GeometryStringExtension(f"{feature.Name} {k}")
    ext.Name = MARK
    curve.setExtension(ext)
    a, b = curve.FirstParameter, curve.LastParameter
    at = []
    for j in range(WRITTEN_AT):
        u = a + (b - a) * j / (WRITTEN_AT - 1)
        p = curve.value(u)
        at.append(f"{u!r} {p.x!r} {p.y!r}")
    written = Part.GeometryStringExtension(";".join(at))
    written.Name = WRITTEN
    curve.setExtension(written)
    return curve


def written_points(geometry):
    """The points (sketch coordinates) the copy piece ``geometry`` was written through
    (WRITTEN), or []."""
    if not geometry.hasExtensionOfName(WRITTEN):
        return []
    return [App.Vector(float(x), float(y), 0.0) for _, x, y in
            (item.split() for item in geometry.getExtensionOfName(WRITTEN).Value.split(";"))]


def copy_moved(geometry):
    """How far (mm, in its sketch) the copy piece ``geometry`` is from where it was written
    (its WRITTEN points), or None for a copy written before they were kept."""
    if not geometry.hasExtensionOfName(WRITTEN):
        return None
    far = 0.0
    for item in geometry.getExtensionOfName(WRITTEN).Value.split(";"):
        u, x, y = (float(v) for v in item.split())
        p = geometry.value(u)
        far = max(far, math.hypot(p.x - x, p.y - y))
    return far


def earlier_copy(feature, sketch):
    """The indices in ``sketch`` of the feature's earlier copy there (in the order written),
    or [] (none, or a piece of it deleted since): by the Tags kept in COPIES, else (a
    document reopened: new Tags) by the geometry's MARK."""
    tags = [e.split(" ", 1)[1] for e in getattr(feature, COPIES, ())
            if e.split(" ", 1)[0] == sketch.Name]
    if not tags:
        return []
    geometry = sketch.Geometry
    at = {g.Tag: i for i, g in enumerate(geometry)}
    ids = [at.get(t) for t in tags]
    if ids and None not in ids:
        return ids
    pieces = {}
    for i, g in enumerate(geometry):
        if g.hasExtensionOfName(MARK):
            name, _, k = g.getExtensionOfName(MARK).Value.rpartition(" ")
            if name == feature.Name and k.isdigit():
                pieces[int(k)] = i
    ids = [pieces.get(k) for k in range(len(tags))]
    return ids if len(pieces) == len(tags) and None not in ids else []


def _follow_ends(sketch, geometry, ids):
    """The line segments joined to the ends of ``ids`` by Coincident constraints moved onto
    the new ends in ``geometry``: the solver then has nothing to move (it moved the copy's
    poles, 0.21 mm off the feature, as much as the lines); those joined by an end-to-end
    Tangent turned onto the new tangent there too (_line_onto)."""
    old = sketch.Geometry
    for c in sketch.Constraints:
        if c.Type not in ("Coincident", "Tangent"):
            continue
        for (g, pos), (h, hpos) in (((c.First, c.FirstPos), (c.Second, c.SecondPos)),
                                    ((c.Second, c.SecondPos), (c.First, c.FirstPos))):
            if g in ids and pos in (1, 2) and h not in ids and hpos in (1, 2) \
                    and 0 <= h < len(geometry) and isinstance(geometry[h], Part.LineSegment):
                # in place: its Tag and construction mode kept (not a new segment)
                if not _blocked(sketch, h):
                    _line_onto(geometry[h], hpos, _end_frame(old[g], pos),
                               _end_frame(geometry[g], pos),
                               c.Type == "Tangent" and _far_end_free(sketch, h, hpos))


# the constraints naming a line as a whole that turning it about an end keeps: its length
_TURN_KEEPS = ("Distance", "Equal")
_GEO_UNDEF = -2000      # Sketcher's GeoUndef: no second element (a line's own Distance)


def _far_end_free(sketch, line, lpos):
    """Whether the segment ``line``, joined at its end ``lpos`` (1 start, 2 end) to a copy's
    end, may be turned about that end (_line_onto): its far end free. Free means that no
    driving, active constraint of ``sketch`` names the far end (a Coincident to other
    geometry or to the copy's other end, a DistanceX / DistanceY / PointOnObject / Symmetric
    pinning it, a Block) or holds the line's direction or place (Horizontal, Vertical,
    Angle, Parallel, Perpendicular, a Tangent along it, a point on it, a DistanceX / Y of
    it): only its length (Distance, Equal) and constraints at the joined end itself. Else
    the line's far end is held elsewhere: turned, the solver pulled the turn back by
    bending the copy (a pinned far end: 2.74 mm off) or dragged what holds it (a chain to a
    Vertical line: 12.4 mm), and a line closing the profile came out by constraint order;
    such a line's near end is moved only and the Sketcher's solver decides, as before."""
    far = 3 - lpos
    for c in sketch.Constraints:
        if not getattr(c, "Driving", True) or not getattr(c, "IsActive", True):
            continue        # a reference dimension or a deactivated one holds nothing
        refs = [(c.First, c.FirstPos), (c.Second, c.SecondPos), (c.Third, c.ThirdPos)]
        mine = [pos for g, pos in refs if g == line]
        if not mine or all(pos == lpos for pos in mine):
            continue
        if far in mine or c.Type not in _TURN_KEEPS or \
                (c.Type == "Distance" and c.Second != _GEO_UNDEF):
            return False
    return True


def _blocked(sketch, line):
    """Whether ``line`` is held by a Block constraint: left where it is (set into the
    geometry, moved onto the copy's new end, the Block held it there, 6.9 mm off)."""
    return any(c.Type == "Block" and c.First == line and getattr(c, "IsActive", True)
               for c in sketch.Constraints)


def _end_frame(curve, pos):
    """(point, unit tangent along the curve) at its start (pos 1) or end (pos 2)."""
    u = curve.FirstParameter if pos == 1 else curve.LastParameter
    return curve.value(u), curve.tangent(u)[0]


def _line_onto(line, lpos, old, new, tangent):
    """The end ``lpos`` (1 start, 2 end) of the segment ``line``, joined to a copy's end at
    ``old`` (point, tangent: _end_frame), moved onto the new copy's end ``new``; joined by
    an end-to-end Tangent (``tangent``), the segment also turned about that end onto the new
    tangent, its length and its side (along the curve or back over it) kept. Moved only,
    its Tangent no longer held, the solver turned it by bending the copy (a copy again
    with the line's far end free: the copy off the feature, the drift said so). ``tangent``
    is False, the line moved only, where its far end is held (_far_end_free). A Tangent
    to an arc or another curve is left to the solver."""
    t0, (p1, t1) = old[1], new
    near, far = (line.StartPoint, line.EndPoint) if lpos == 1 else (line.EndPoint, line.StartPoint)
    if tangent:
        d = far - near
        side = 1.0 if d.dot(t0) >= 0 else -1.0
        far = p1 + t1 * (side * d.Length)
    start, end = (p1, far) if lpos == 1 else (far, p1)
    try:
        line.StartPoint, line.EndPoint = start, end
    except RuntimeError:
        # the new start on the old end (a segment of no length between): Part raises
        # RuntimeError 'Both points are equal' there, not its OCCError (a subclass)
        line.EndPoint, line.StartPoint = end, start


def _replace_copy(sketch, earlier, curves):
    """The copy pieces at ``earlier`` replaced by ``curves`` (Part curves, sketch
    coordinates) in another number of pieces: the old ones deleted (the Sketcher renumbers
    the geometry after them, their constraints with it), the new added. A constraint that
    names the old copy only at its start (first piece, start point) or end (last piece, end
    point) joins it to the rest of the profile: it is added again at the new copy's start or
    end, the line segments it joins moved onto that end first (_follow_ends' reason); one
    joint constraint every joint between the old pieces had (Coincident, Tangent) is added at
    every new joint. The others name a piece or a joint that is no more. Returns (the new
    pieces' indices, the words for the constraints not kept)."""
    import Sketcher
    first, last = earlier[0], earlier[-1]
    olds = set(earlier)
    geometry = sketch.Geometry
    slots = (("First", "FirstPos"), ("Second", "SecondPos"), ("Third", "ThirdPos"))
    kept, lost = [], []
    joints = [None] * (len(earlier) - 1)    # per old joint: the constraint types joining it
    for n, c in enumerate(sketch.Constraints):
        refs = [(getattr(c, g), getattr(c, pos)) for g, pos in slots]
        mine = [r for r in refs if r[0] in olds]
        if not mine or c.Type == "InternalAlignment":
            continue        # a pole shown (the Sketcher's own: it goes with its B-spline)
        at = {r: ("start" if r == (first, 1) else "end" if r == (last, 2) else None)
              for r in mine}
        if None not in at.values():
            kept.append((n, c, refs, at))
            continue
        pair = sorted(mine, key=lambda r: earlier.index(r[0]))
        k = earlier.index(pair[0][0])
        if len(mine) == 2 and c.Type in ("Coincident", "Tangent") and k + 1 < len(earlier) \
                and pair == [(earlier[k], 2), (earlier[k + 1], 1)]:
            joints[k] = (joints[k] or set()) | {c.Type}
            continue
        lost.append(f"{c.Type} {n + 1}" + (f" '{c.Name}'" if c.Name else ""))
    common = set.intersection(*joints) if joints and None not in joints else set()
    for k, j in enumerate(joints):
        for t in sorted((j or set()) - common):
            lost.append(f"{t} at the joint of pieces {k + 1} and {k + 2}")
    # the line segments joined to the ends follow them (in place: Tag, construction kept),
    # those joined by Tangent turned onto the new tangent (_line_onto)
    for _n, c, refs, at in kept:
        if c.Type not in ("Coincident", "Tangent"):
            continue
        for r in refs:
            if r[0] >= 0 and r[0] not in olds and r[1] in (1, 2) and \
                    isinstance(geometry[r[0]], Part.LineSegment) and not _blocked(sketch, r[0]):
                was, now = ((_end_frame(geometry[first], 1), _end_frame(curves[0], 1))
                            if "start" in at.values() else
                            (_end_frame(geometry[last], 2), _end_frame(curves[-1], 2)))
                _line_onto(geometry[r[0]], r[1], was, now,
                           c.Type == "Tangent" and _far_end_free(sketch, r[0], r[1]))
    sketch.Geometry = geometry
    tags = [g.Tag for g in sketch.Geometry]
    # the constraints naming the old pieces deleted first: delGeometries moves those at a
    # point of theirs onto the geometry Coincident there (a DistanceX of the copy's ends
    # onto the lines' ends), and added again below they stood twice: the sketch redundant,
    # its Pad failed. Their InternalAlignment go with the poles they hold
    for n in reversed(range(len(sketch.Constraints))):
        c = sketch.Constraints[n]
        if c.Type != "InternalAlignment" and {c.First, c.Second, c.Third} & olds:
            sketch.delConstraint(n)
    sketch.delGeometries(sorted(olds))
    ids = [sketch.addGeometry(c, False) for c in curves]
    now = {g.Tag: i for i, g in enumerate(sketch.Geometry)}
    for n, c, refs, at in kept:
        if any(g >= 0 and (g, pos) not in at and tags[g] not in now for g, pos in refs):
            # it named a pole of the old copy too (gone with it): a KeyError here left
            # the sketch half-replaced, COPIES stale, the next Copy into beside it
            lost.append(f"{c.Type} {n + 1}" + (f" '{c.Name}'" if c.Name else ""))
            continue
        for (g, pos), (gname, posname) in zip(refs, slots):
            if (g, pos) in at:
                setattr(c, gname, ids[0] if at[(g, pos)] == "start" else ids[-1])
                setattr(c, posname, 1 if at[(g, pos)] == "start" else 2)
            elif g >= 0:
                setattr(c, gname, now[tags[g]])
        sketch.addConstraint(c)
    for k in range(len(ids) - 1):
        for t in sorted(common):
            sketch.addConstraint(Sketcher.Constraint(t, ids[k], 2, ids[k + 1], 1))
    return ids, lost


def _remember_copy(feature, sketch, ids):
    # its CopyWatch (registered on import) measures the copies as their sketch recomputes
    importlib.import_module(".copies", __package__)
    if COPIES not in feature.PropertiesList:
        feature.addProperty("App::PropertyStringList", COPIES, "Output",
                            "The sketch geometry of the last copy into each sketch (a copy "
                            "into it again replaces it)", 4 | 8)     # hidden, output
    geometry = sketch.Geometry
    feature.SketchCopies = [e for e in feature.SketchCopies
                            if e.split(" ", 1)[0] != sketch.Name] + \
        [f"{sketch.Name} {geometry[i].Tag}" for i in ids]
