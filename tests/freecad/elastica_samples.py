"""Sample documents for the workbench tests (freecadcmd -t and the GUI smoke test).

The data are elastica arcs evaluated by the library itself (an S-shaped keyline
with one inflection), placed in a tilted sketch plane, so a correct fit must
reproduce them closely; a few helpers build sketches, Points objects and 3D
polylines from them.
"""
import math
import os
import shutil
import sys
import tempfile
import unittest

import FreeCAD as App
import Part

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
for p in (os.path.join(ROOT, "python"), os.path.join(ROOT, "freecad_wb")):
    if p not in sys.path:
        sys.path.append(p)

import numpy as np  # noqa: E402

import libelastica as el  # noqa: E402

KEYLINE = dict(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65, q=0.25, length=330.0)
SKETCH_PLACEMENT = App.Placement(App.Vector(40, -25, 12), App.Rotation(App.Vector(1, 0.4, 0.2), 35))


def keyline_xy(n=40, length=None):
    """n points on the sample S-shaped elastica (plane coordinates, mm)."""
    p = dict(KEYLINE)
    if length is not None:
        p["length"] = length
    c = el.SmoothElastica(**p)
    return c.points(np.linspace(0.0, c.length, n)), c


def temp_path(test, name):
    """A path named name in a fresh temporary folder that test removes when it ends
    (tempfile.mkdtemp alone left a folder in /tmp per test and run)."""
    folder = tempfile.mkdtemp(prefix="elastica-test-")
    test.addCleanup(shutil.rmtree, folder, True)
    return os.path.join(folder, name)


def reopened(test, file, *names):
    """test.doc saved as ``file`` (in a temp_path), closed and opened again (test.doc the
    opened one): the objects of those names in it."""
    path = temp_path(test, file)
    test.doc.saveAs(path)
    App.closeDocument(test.doc.Name)
    test.doc = App.openDocument(path)
    return [test.doc.getObject(n) for n in names]


def new_doc(name):
    for d in list(App.listDocuments().values()):
        if d.Name == name:
            App.closeDocument(name)
    return App.newDocument(name)


class DocTest(unittest.TestCase):
    """A test in a new document of its own, ``doc_name``, closed after it (as self.doc is
    then: a test may reopen it); under the unit schema ``schema`` where set (the user's
    restored after it). Subclasses with more to set up call super().setUp() first."""

    doc_name = "ElasticaTest"
    schema = None

    def setUp(self):
        if self.schema is not None:
            self.addCleanup(App.Units.setSchema, App.Units.getSchema())
            App.Units.setSchema(self.schema)
        self.doc = new_doc(self.doc_name)

    def tearDown(self):
        App.closeDocument(self.doc.Name)


def bspline_sketch(doc, xy, name="KeylineSketch", placement=SKETCH_PLACEMENT):
    """A sketch holding one interpolating B-spline through the points ``xy``."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    c = Part.BSplineCurve()
    c.interpolate([App.Vector(x, y, 0) for x, y in xy])
    sk.addGeometry(c, False)
    doc.recompute()
    return sk


def points_sketch(doc, xy, name="PointSketch", placement=SKETCH_PLACEMENT):
    """A sketch holding the points ``xy`` as sketch points (vertices)."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    for x, y in xy:
        sk.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
    doc.recompute()
    return sk


def polyline_3d(doc, xy, placement=SKETCH_PLACEMENT, name="Polyline"):
    """A Part feature holding the 3D polyline of ``xy`` in ``placement``'s plane."""
    obj = doc.addObject("Part::Feature", name)
    obj.Shape = Part.makePolygon([placement.multVec(App.Vector(x, y, 0)) for x, y in xy])
    doc.recompute()
    return obj


def points_object(doc, xy, placement=SKETCH_PLACEMENT, name="Cloud"):
    """A Points::Feature of ``xy`` in ``placement``'s plane (unordered: reversed halves)."""
    import Points
    pts = [placement.multVec(App.Vector(x, y, 0)) for x, y in xy]
    half = len(pts) // 2
    pts = pts[half:][::-1] + pts[:half]
    obj = doc.addObject("Points::Feature", name)
    obj.Points = Points.Points(pts)
    doc.recompute()
    return obj


def two_lines_sketch(doc, name="Lines", placement=SKETCH_PLACEMENT):
    """Two line segments with a gap between them: end of Edge1 -> start of Edge2."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(40, 0, 0)), False)
    sk.addGeometry(Part.LineSegment(App.Vector(80, 25, 0), App.Vector(120, 35, 0)), False)
    doc.recompute()
    return sk


def lead_in_sketches(doc):
    """QA's sketches of an edge link (bug_edge_names): 'Edges' holds a helper line (geometry 0,
    Edge1), a lead-in line ending at (-2, 0) (geometry 1, Edge2) and a run-out line from
    (60, -5) (geometry 2, Edge3); 'Pts' six points from (0, 0.5) to (55, -4.5) between them.
    Returns (edges sketch, points sketch)."""
    sk = doc.addObject("Sketcher::SketchObject", "Edges")
    for a, b in (((-60, 40), (-30, 40)), ((-30, -10), (-2, 0)), ((60, -5), (90, -5))):
        sk.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*b, 0)), False)
    pts = doc.addObject("Sketcher::SketchObject", "Pts")
    for x, y in [(0, 0.5), (9, 3.0), (18, 4.5), (30, 3.0), (42, -1.0), (55, -4.5)]:
        pts.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
    doc.recompute()
    return sk, pts


def helper_and_curve_sketch(doc, xy, pieces=3, name="Chain"):
    """QA's sketch of picked sources (bug_source_names): a helper line (geometry 0, Edge1),
    then the curve through ``xy`` as ``pieces`` B-splines end to end (geometry 1, 2, ...; a
    piece through 2 points is a line): the helper made construction or deleted, every other
    edge and vertex name shifts."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = SKETCH_PLACEMENT
    sk.addGeometry(Part.LineSegment(App.Vector(-60, 200, 0), App.Vector(-30, 200, 0)), False)
    cuts = np.linspace(0, len(xy) - 1, pieces + 1).round().astype(int)
    for a, b in zip(cuts, cuts[1:]):
        pts = [App.Vector(x, y, 0) for x, y in xy[a:b + 1]]
        if len(pts) == 2:
            sk.addGeometry(Part.LineSegment(*pts), False)
            continue
        c = Part.BSplineCurve()
        c.interpolate(pts)
        sk.addGeometry(c, False)
    doc.recompute()
    return sk


def sketch_names(sketch, elements):
    """The names the sketch's elements [(geometry index, 'edge' / 'start' / 'end')] have now:
    'EdgeN' of the edge through the geometry's middle, 'VertexN' at its start or end."""
    out = []
    for i, what in elements:
        e = sketch.Geometry[i].toShape()
        u = {"start": e.FirstParameter, "end": e.LastParameter}.get(
            what, 0.5 * (e.FirstParameter + e.LastParameter))
        at = Part.Vertex(sketch.Placement.multVec(e.valueAt(u)))
        kind = sketch.Shape.Edges if what == "edge" else sketch.Shape.Vertexes
        out.append(next(f"{'Edge' if what == 'edge' else 'Vertex'}{k + 1}"
                        for k, x in enumerate(kind) if x.distToShape(at)[0] < 1e-7))
    return out


def line_and_arc_sketch(doc, name="LineArc", placement=SKETCH_PLACEMENT):
    """A line ending at (0, 0) heading 18 degrees up, and a quarter arc (radius 40 about
    (100, -45)) whose end (60, -45) is the nearest, 75 mm away: the blend must turn back
    up into it and no free batten (tension 0) joins them; by length, any length above
    75 mm does (QA)."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    sk.addGeometry(Part.LineSegment(App.Vector(-30, -10, 0), App.Vector(0, 0, 0)), False)
    sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(100, -45, 0), App.Vector(0, 0, 1), 40),
                                    math.pi / 2, math.pi), False)
    doc.recompute()
    return sk


def u_profile_sketch(doc, name="Profile", placement=SKETCH_PLACEMENT):
    """A U profile (QA 9): its bottom (0, 0)-(100, 0) (Edge1), the right wall (100, 0) up
    to (100, 20) (Edge2) and the left wall (0, 30) down to (0, 0) (Edge3). The walls'
    nearest ends are their bottoms, already joined by the bottom line."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    for a, b in (((0, 0), (100, 0)), ((100, 0), (100, 20)), ((0, 30), (0, 0))):
        sk.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*b, 0)), False)
    doc.recompute()
    return sk


def arc_sketch(doc, radius=20.0, name="Arc", placement=SKETCH_PLACEMENT):
    """A sketch with one circular arc of the given radius (a quarter turn)."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement
    circ = Part.Circle(App.Vector(0, 0, 0), App.Vector(0, 0, 1), radius)
    sk.addGeometry(Part.ArcOfCircle(circ, 0.0, math.pi / 2), False)
    doc.recompute()
    return sk


def f4_line_arc(sk, y=-800.0):
    """QA gui F4's profile drawn into ``sk``: a line (1500, y)-(1620, y) and an arc r 60
    centred (1830, y + 90), 200 deg .. 330 deg (a blend joins the line's end to the arc's
    start): test_elastica_blend_copy_joined's, _blend_g2_default's, _comb_together's."""
    sk.addGeometry(Part.LineSegment(App.Vector(1500, y, 0), App.Vector(1620, y, 0)), False)
    c = Part.Circle(App.Vector(1830, y + 90, 0), App.Vector(0, 0, 1), 60)
    sk.addGeometry(Part.ArcOfCircle(c, math.radians(200), math.radians(330)), False)


def inclined_body_sketch(doc, name):
    """An empty sketch on a datum plane inclined 35 deg in a Body placed at (200, 100, 50) and
    turned 15 deg (QA e6: a designer's Body sketch, neither the XY plane nor the origin)."""
    body = doc.addObject("PartDesign::Body", "Body")
    body.Placement = App.Placement(App.Vector(200, 100, 50), App.Rotation(App.Vector(0, 0, 1), 15))
    plane = body.newObject("PartDesign::Plane", "Inclined")
    plane.Support = [(body.Origin.OriginFeatures[3], "")]
    plane.MapMode = "FlatFace"
    plane.AttachmentOffset = App.Placement(App.Vector(0, 0, 30),
                                           App.Rotation(App.Vector(1, 0, 0), 35))
    doc.recompute()
    sk = body.newObject("Sketcher::SketchObject", name)
    sk.Support = [(plane, "")]
    sk.MapMode = "FlatFace"
    return sk


def circle_sketch(doc, radius=20.0, name="Circle"):
    """A sketch with one full circle (a closed curve)."""
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.addGeometry(Part.Circle(App.Vector(0, 0, 0), App.Vector(0, 0, 1), radius), False)
    doc.recompute()
    return sk


def write_into_new_sketch(test, feature):
    """Write ``feature``'s curve into a new sketch in its plane (features.write_to_sketch),
    check that it became one B-spline geometry, return the sketch."""
    from freecad.elastica import geometry as G
    doc = feature.Document
    out = doc.addObject("Sketcher::SketchObject", "Out")
    out.Placement = feature.Plane
    ids = G.write_to_sketch(feature, out)
    doc.recompute()
    test.assertEqual(len(ids), 1)
    test.assertEqual(out.Geometry[ids[0]].TypeId, "Part::GeomBSplineCurve")
    return out


def curvature_vector(curve, u):
    """kappa N of a Part curve at u (zero where it is straight)."""
    k = curve.curvature(u)
    return curve.normal(u) * k if k > 1e-12 else App.Vector(0, 0, 0)


def sides(bspline, u, span):
    """(unit tangent, curvature vector) just before and just after the knot u of a
    Part B-spline, each from the segment on its side (one-sided derivatives)."""
    out = []
    for a, b in ((u - span, u), (u, u + span)):
        c = bspline.copy()
        c.segment(a, b)
        out.append((App.Vector(c.tangent(u)[0]).normalize(), curvature_vector(c, u)))
    return out


def distance_to_shape(points, shape):
    """Largest distance of 3D points from a shape."""
    return max(shape.distToShape(Part.Vertex(App.Vector(*p)))[0] for p in points)


def status_once_deleted(feature, *sources):
    """The feature's Status once its source objects ``sources`` are deleted and the document
    recomputed (FreeCAD empties links to them)."""
    for obj in sources:
        feature.Document.removeObject(obj.Name)
    feature.Document.recompute()
    return feature.Status


def doc_state(doc):
    """What 'the document is unchanged' compares: names, types and shapes' sizes."""
    out = []
    for o in doc.Objects:
        sh = getattr(o, "Shape", None)
        size = (len(sh.Edges), round(sh.Length, 9)) if sh is not None and not sh.isNull() else None
        out.append((o.Name, o.TypeId, size))
    return out


# a feature's results a recorded edit, replayed, must give again (recording's tests)
RECORDED_RESULTS = {"ElasticaBlend": ("BlendTension", "BlendLength", "Solution", "Status"),
                    "ElasticaSpline": ("SplineTension", "SplineLength", "Energy", "Status")}


def taken(obj):
    """What a feature's replay is compared by: its name, the properties a panel edits
    (recording.edit_state), its results (RECORDED_RESULTS) and its B-spline's poles."""
    from freecad.elastica.recording import edit_state
    return {"name": obj.Name, "state": edit_state(obj),
            "results": {p: getattr(obj, p) for p in RECORDED_RESULTS[obj.Name]},
            "poles": [tuple(p) for p in obj.Shape.Edges[0].Curve.getPoles()]}


def travel_ends(f):
    """[(point, unit tangent, signed curvature)] at the start and the end of a fit's
    one B-spline, in the direction of travel (first point -> last), from Part's curve
    API: curvature() and normal() (towards the centre), signed + when the curve
    turns left seen from the fit plane's normal."""
    c = f.Shape.Edges[0].Curve
    up = f.Plane.Rotation.multVec(App.Vector(0, 0, 1))
    out = []
    for u in (c.FirstParameter, c.LastParameter):
        t = App.Vector(c.tangent(u)[0]).normalize()
        k = c.curvature(u)
        if k > 1e-13:
            k *= 1.0 if t.cross(App.Vector(c.normal(u))).dot(up) > 0 else -1.0
        out.append((c.value(u), t, k))
    return out


def console_output(run):
    """What FreeCAD's console prints (its C++ observers write to the process's stdout and
    stderr, not to Python's sys.stdout) while ``run()`` runs: (text, run's result)."""
    import os
    import sys
    import tempfile
    sys.stdout.flush()
    sys.stderr.flush()
    saved = [os.dup(1), os.dup(2)]
    with tempfile.TemporaryFile() as f:
        os.dup2(f.fileno(), 1)
        os.dup2(f.fileno(), 2)
        try:
            result = run()
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            for fd in saved:
                os.close(fd)
        f.seek(0)
        return f.read().decode("utf-8", "replace"), result


class Said:
    """What the report view is told through ``App.Console.<kind>`` (PrintWarning,
    PrintMessage, ...) while active, each text in ``said``."""

    def __init__(self, kind="PrintWarning"):
        self.kind, self.said = kind, []

    def __enter__(self):
        self.saved = getattr(App.Console, self.kind)
        setattr(App.Console, self.kind, self.said.append)
        return self

    def __exit__(self, *exc):
        setattr(App.Console, self.kind, self.saved)


def outlier_xy():
    """20 points along a 380 mm curve (0.25 mm noise) at (1500, -800), the 12th (index 11)
    6 mm across it: the outlier a Fit names (test_elastica_fit_sketcher_names' hand sketch,
    test_elastica_fit_csv_lines' file)."""
    rng = np.random.default_rng(7)
    c = el.SmoothElastica(x0=0, y0=0, phi=0.3, mu=(1 / 120.0) ** 2, k=0.6, q=0.2, length=380.0)
    s = np.linspace(0, 380, 20)
    pts = c.points(s) + rng.normal(0, 0.25, (20, 2))
    th = float(c.angle([s[11]])[0])
    pts[11] += 6.0 * np.array([-np.sin(th), np.cos(th)])
    return pts + [1500.0, -800.0]


def outlier_said(test, f, model):
    """The one Warnings line of Fit ``f`` naming an outlier ('outliers?'), as said."""
    from freecad.elastica.units import say
    said = [w for w in say(list(f.Warnings)) if "outliers?" in w]
    test.assertEqual(len(said), 1, (model, list(f.Warnings)))
    return said[0]
