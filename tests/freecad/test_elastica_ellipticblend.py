"""freecadcmd -t tests of the Elliptic blend curve (seed 003): creation from a sketch
of four points and from 3D vertices, parametric update when a point moves, save /
reopen / recompute, B-spline into a sketch, bad input (document unchanged), and the
warnings (a basis that loses the convex hull, an ill-conditioned interpolation): set,
said once in the report view, cleared.

The shape is checked against the library's own blending curve: through the four
points in interpolate mode, from q0 to q3 with the picked control points otherwise."""
import math
import warnings

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import ellblend as El
from freecad.elastica import geometry as G

XY = [(0.0, 0.0), (20.0, 35.0), (55.0, 40.0), (80.0, 5.0)]
ZIGZAG = [(0.0, 0.0), (40.0, 40.0), (0.0, 40.0), (40.0, 0.0)]    # a Z: the curve must swing
# control points whose curve leaves their hull where h_1 < 0 (m = 0.62, d = 2: h_1(0.27)
# = -0.18 pulls the curve below the base line q0 q3)
HIGH_Q1 = [(0.0, 0.0), (40.0, 40.0), (40.0, 0.0), (80.0, 0.0)]


def _hull(xy):
    """Convex hull (counter-clockwise) of 2D points (monotone chain)."""
    pts = sorted(set(xy))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1]) -
                                     (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]
    return half(pts) + half(pts[::-1])


def _outside(hull, p):
    """How far p lies outside the convex polygon hull (<= 0: inside)."""
    out = -math.inf
    for (ax, ay), (bx, by) in zip(hull, hull[1:] + hull[:1]):
        ex, ey = bx - ax, by - ay
        out = max(out, ((p[0] - ax) * ey - (p[1] - ay) * ex) / math.hypot(ex, ey))
    return out


def _vertices(doc, pts3d, prefix="P"):
    """Part::Vertex objects at the given global points."""
    out = []
    for i, p in enumerate(pts3d):
        v = doc.addObject("Part::Vertex", f"{prefix}{i}")
        v.X, v.Y, v.Z = p.x, p.y, p.z
        out.append(v)
    doc.recompute()
    return out


class EllipticBlendTest(S.DocTest):
    doc_name = "ElasticaEllBlendTest"

    def setUp(self):
        super().setUp()
        self.sk = S.points_sketch(self.doc, XY)
        self.pts = [S.SKETCH_PLACEMENT.multVec(App.Vector(x, y, 0)) for x, y in XY]

    def _ok(self, obj):
        # "ok", or "ok; warning: ..." with each of its Warnings
        self.assertEqual(obj.Status, "; ".join(["ok"] + [f"warning: {w}" for w in obj.Warnings]))
        self.assertEqual(len(obj.Shape.Edges), 1)
        self.assertIsInstance(obj.Shape.Edges[0].Curve, Part.BSplineCurve)
        self.assertTrue(0 < obj.BSplineDeviation <= obj.Tolerance)
        self.assertEqual(len(obj.ControlPoints), 4)

    def _through(self, obj, pts):
        """The shape passes through the points (within the B-spline tolerance), in order
        along the curve, and ends on the first and last one."""
        e = obj.Shape.Edges[0]
        params = []
        for p in pts:
            dist = e.distToShape(Part.Vertex(p))[0]
            self.assertLess(dist, obj.Tolerance.Value + 1e-9)
            params.append(e.Curve.parameter(p))
        self.assertEqual(params, sorted(params))
        self.assertLess((e.valueAt(e.FirstParameter) - pts[0]).Length, 1e-7)
        self.assertLess((e.valueAt(e.LastParameter) - pts[-1]).Length, 1e-7)

    def test_picked_vertices_follow_their_geometry(self):
        """Four vertices picked in a sketch stay those points as an earlier helper line turns
        construction or is deleted; their geometry deleted, it says so."""
        sk = S.helper_and_curve_sketch(self.doc, XY, pieces=3)
        picked = [(1, "start"), (1, "end"), (2, "end"), (3, "end")]
        f = El.make(self.doc, [(sk, S.sketch_names(sk, picked))])
        self.doc.recompute()
        for change in (lambda: sk.toggleConstruction(0), lambda: sk.delGeometry(0)):
            change()
            self.doc.recompute()
            self._ok(f)
            self._through(f, self.pts)
        name = f.Points[0][1][3]
        sk.delGeometry(2)                                # the last point's line
        self.doc.recompute()
        self.assertEqual(f.Status, f"error: Points: the sketch geometry it followed (Chain."
                         f"{name}) was deleted: relink Points")

    def test_from_sketch_points_interpolates(self):
        f = El.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        self._ok(f)
        self._through(f, self.pts)
        # the curve lies in the sketch plane, which is its plane
        n = S.SKETCH_PLACEMENT.Rotation.multVec(App.Vector(0, 0, 1))
        for p in f.Shape.Edges[0].discretize(20):
            self.assertLess(abs((p - self.pts[0]).dot(n)), 1e-9)
        self.assertLess((f.Plane.Base - S.SKETCH_PLACEMENT.Base).Length, 1e-12)

    def test_shape_is_the_librarys_curve(self):
        import numpy as np
        import libelastica as el
        f = El.make(self.doc, [(self.sk, [])], K=0.3, KConvention="parameter", D=1.5)
        self.doc.recompute()
        self._ok(f)
        # through the points D is not used (QA17 P4): the curve of any d, described by the
        # basis (and control points) of d = 2
        for d in (1.5, 2.0):
            curve = el.blend_curve(np.array(XY), m=0.3, d=d)
            on = G.to_3d(S.SKETCH_PLACEMENT, curve.points(np.linspace(0, 1, 41)))
            self.assertLess(S.distance_to_shape([tuple(p) for p in on], f.Shape),
                            f.BSplineDeviation + 1e-9)
        for q, q3 in zip(G.to_3d(S.SKETCH_PLACEMENT, curve.q), f.ControlPoints):
            self.assertLess((q - q3).Length, 1e-9)
        # interpolate mode: the inner control points are not the picked points
        self.assertGreater((f.ControlPoints[1] - self.pts[1]).Length, 1.0)

    def test_control_mode_uses_the_points(self):
        f = El.make(self.doc, [(self.sk, [])], Mode="control")
        self.doc.recompute()
        self._ok(f)
        for q, p in zip(f.ControlPoints, self.pts):
            self.assertLess((q - p).Length, 1e-9)
        e = f.Shape.Edges[0]
        self.assertLess((e.valueAt(e.FirstParameter) - self.pts[0]).Length, 1e-7)
        self.assertLess((e.valueAt(e.LastParameter) - self.pts[3]).Length, 1e-7)
        # end tangents along q1 - q0 and q3 - q2
        t0 = e.tangentAt(e.FirstParameter).normalize()
        t1 = e.tangentAt(e.LastParameter).normalize()
        self.assertGreater(t0.dot((self.pts[1] - self.pts[0]).normalize()), 1 - 1e-6)
        self.assertGreater(t1.dot((self.pts[3] - self.pts[2]).normalize()), 1 - 1e-6)
        # the inner points are not on the curve
        self.assertGreater(e.distToShape(Part.Vertex(self.pts[1]))[0], 1.0)

    def test_from_3d_vertices_follows_a_moved_point(self):
        plc = App.Placement(App.Vector(5, 7, -3), App.Rotation(App.Vector(0.3, -1, 0.5), 70))
        pts = [plc.multVec(App.Vector(x, y, 0)) for x, y in XY]
        verts = _vertices(self.doc, pts)
        f = C.ellblend_sources([(v, ["Vertex1"]) for v in verts], open_panel=False)
        self.assertIsNotNone(f)
        self.assertEqual(f.Proxy.kind, "EllipticBlend")
        self._ok(f)
        self._through(f, pts)
        before = f.Shape.copy()
        moved = plc.multVec(App.Vector(30, 50, 0))        # stays in the plane
        verts[1].X, verts[1].Y, verts[1].Z = moved.x, moved.y, moved.z
        self.doc.recompute()
        self._ok(f)
        self.assertGreater(abs(f.Shape.Length - before.Length), 1e-3)
        self._through(f, [pts[0], moved, pts[2], pts[3]])

    def test_vertices_of_a_shape_and_sketch_vertices(self):
        wire = S.polyline_3d(self.doc, XY)
        f = El.make(self.doc, [(wire, ["Vertex1", "Vertex2", "Vertex3", "Vertex4"])])
        lines = S.two_lines_sketch(self.doc)
        g = El.make(self.doc, [(lines, ["Vertex1", "Vertex2", "Vertex3", "Vertex4"])])
        self.doc.recompute()
        self._ok(f)
        self._through(f, self.pts)
        self._ok(g)
        self._through(g, [v.Point for v in lines.Shape.Vertexes[:4]])

    def test_sketch_point_moved_recomputes(self):
        f = El.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        before = f.Shape.copy()
        self.sk.movePoint(2, 1, App.Vector(50, 60, 0))
        self.doc.recompute()
        self._ok(f)
        self.assertGreater(abs(f.Shape.Length - before.Length), 1e-3)
        self._through(f, [self.pts[0], self.pts[1],
                          S.SKETCH_PLACEMENT.multVec(App.Vector(50, 60, 0)), self.pts[3]])

    def test_write_into_sketch(self):
        f = El.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        out = S.write_into_new_sketch(self, f)
        samples = [tuple(p) for p in f.Shape.Edges[0].discretize(30)]
        self.assertLess(S.distance_to_shape(samples, out.Shape), 1e-9)

    def test_save_reopen_recompute_same_result(self):
        f = El.make(self.doc, [(self.sk, [])], K=0.7, D=3.0, Tolerance=1e-5)
        self.doc.recompute()
        self._ok(f)
        q = [App.Vector(v) for v in f.ControlPoints]
        samples = [tuple(p) for p in f.Shape.Edges[0].discretize(50)]
        name = f.Name
        path = S.temp_path(self, "ellblend.FCStd")
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        self.doc = App.openDocument(path)
        f2 = self.doc.getObject(name)
        self.assertEqual(f2.Proxy.kind, "EllipticBlend")
        self.assertEqual((f2.Mode, f2.K, f2.D, f2.KConvention), ("interpolate", 0.7, 3.0, "modulus"))
        f2.Shape = Part.Shape()               # the recompute must rebuild it
        f2.touch()
        self.doc.recompute()
        self._ok(f2)
        for a, b in zip(q, f2.ControlPoints):
            self.assertLess((a - b).Length, 1e-9)
        self.assertLess(S.distance_to_shape(samples, f2.Shape), 1e-9)
        self.assertEqual(f2.getGroupOfProperty("K"), "Blend")
        self.assertTrue(f2.getDocumentationOfProperty("K"))

    def test_bad_input_leaves_document_unchanged(self):
        three = S.points_sketch(self.doc, XY[:3], "Three")
        five = S.points_sketch(self.doc, XY + [(90.0, -10.0)], "Five")
        same = S.points_sketch(self.doc, [XY[0], XY[1], XY[1], XY[3]], "Same")
        flat = [App.Vector(x, y, 0) for x, y in XY]
        skew = _vertices(self.doc, flat[:3] + [App.Vector(80, 5, 10)], "Skew")
        lines = S.two_lines_sketch(self.doc)
        before = S.doc_state(self.doc)
        cases = [
            ([], {}, "nothing selected"),
            ([(three, [])], {"Mode": "control"}, "3 control points"),
            ([(five, [])], {"Mode": "control"}, "5 control points"),
            ([(three, [])], {"Mode": "control", "Closed": True}, "3 control points"),
            ([(same, [])], {}, "coincide"),
            ([(same, [])], {"Mode": "control"}, "coincide"),
            ([(v, ["Vertex1"]) for v in skew], {}, "not coplanar"),
            ([(lines, ["Edge1", "Edge2"])], {}, "select vertices"),
            ([(self.sk, [])], {"K": 1.0}, "0 <= k < 1"),
            ([(self.sk, [])], {"K": -0.2}, "0 <= k < 1"),
            ([(self.sk, [])], {"K": 1.5, "KConvention": "parameter"}, "0 <= m < 1"),
            ([(self.sk, [])], {"D": 0.0, "Mode": "control"}, "d = 0"),
        ]
        for sources, opts, text in cases:
            del C.MESSAGES[:]
            self.assertIsNone(C.ellblend_sources(sources, open_panel=False, **opts), text)
            self.assertTrue(C.MESSAGES and text in C.MESSAGES[-1], (text, C.MESSAGES))
            self.assertEqual(S.doc_state(self.doc), before, text)

    def test_a_deleted_source_is_named(self):
        """QA: a feature whose source was deleted said 'nothing selected: select ...', the
        command's words."""
        f = El.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        self.assertEqual(S.status_once_deleted(f, self.sk), "error: its source was deleted: "
                         "relink Points (vertices in order, or a sketch of points)")

    def test_bad_property_keeps_shape_and_reports(self):
        f = El.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        length = f.Shape.Length
        f.K = 1.2
        self.doc.recompute()
        self.assertTrue(f.Status.startswith("error") and "k < 1" in f.Status, f.Status)
        self.assertAlmostEqual(f.Shape.Length, length, delta=1e-12)
        f.K = 0.5
        self.doc.recompute()
        self.assertEqual(f.Status, "ok")

    def _plane_xy(self, f, points):
        inv = f.Plane.inverse()
        return [(p.x, p.y) for p in (inv.multVec(v) for v in points)]

    def test_basis_off_the_convex_hull_is_warned_once_and_cleared(self):
        self.sk = S.points_sketch(self.doc, HIGH_Q1, "HighQ1")
        f = El.make(self.doc, [(self.sk, [])], Mode="control", K=0.3, KConvention="parameter")
        with S.Said() as w:
            self.doc.recompute()
            self.assertEqual(f.Status, "ok")
            self.assertTrue(f.ConvexHull and f.BasisMin > -1e-12 and not f.Warnings)
            self.assertAlmostEqual(f.Lebesgue, 1.0, delta=1e-9)
            self.assertEqual(f.Spread, 1.0)
            self.assertEqual(w.said, [])
            f.K = 0.62                      # m = 0.62 > 0.6: a blending function goes negative
            self.doc.recompute()
            self.assertFalse(f.ConvexHull)
            self.assertLess(f.BasisMin, -0.1)
            self.assertGreater(f.Lebesgue, 1.3)
            self.assertGreater(f.Condition, 100)
            self.assertEqual(len(f.Warnings), 1)
            self.assertIn("convex hull", f.Warnings[0])
            self.assertTrue(f.Status.startswith("ok; warning: the basis is negative"), f.Status)
            self.assertEqual(len(w.said), 1)
            self.assertIn(f.Label, w.said[0])
            # what it says is true: the curve leaves its control points' convex hull
            hull = _hull(self._plane_xy(f, f.ControlPoints))
            far = max(_outside(hull, p) for p in
                      self._plane_xy(f, f.Shape.Edges[0].discretize(400)))
            self.assertGreater(far, 0.01 * f.Shape.BoundBox.DiagonalLength)
            # the same basis again (a recompute, a moved point): not said again
            f.touch()
            self.doc.recompute()
            self.sk.movePoint(1, 1, App.Vector(42, 40, 0))
            self.doc.recompute()
            self.assertFalse(f.ConvexHull)
            self.assertEqual(len(w.said), 1)
            f.K = 0.3                       # back inside: cleared, silently
            self.doc.recompute()
            self.assertEqual(f.Status, "ok")
            self.assertTrue(f.ConvexHull and not f.Warnings)
            self.assertEqual(len(w.said), 1)
            f.K = 0.62                      # a new change: said again
            self.doc.recompute()
            self.assertEqual(len(w.said), 2)

    def test_basis_dip_next_to_the_end_is_warned(self):
        """QA11: at m = 0.99 (d = 2) the basis dips to -1.05e-6 within 0.008 of t = 1;
        the feature said ConvexHull with BasisMin 0 and no warning."""
        self.sk = S.points_sketch(self.doc, HIGH_Q1, "HighQ1")
        f = El.make(self.doc, [(self.sk, [])], Mode="control", K=0.99, KConvention="parameter")
        self.doc.recompute()
        self.assertFalse(f.ConvexHull)
        self.assertAlmostEqual(f.BasisMin, -1.054e-6, delta=1e-9)
        self.assertEqual(len(f.Warnings), 1)
        self.assertIn("moving up to 1.000002 times", f.Warnings[0])

    def test_first_and_last_point_coinciding_is_explained(self):
        loop = S.points_sketch(self.doc, XY[:3] + [XY[0]], "Loop")
        del C.MESSAGES[:]
        self.assertIsNone(C.ellblend_sources([(loop, [])], open_panel=False))
        self.assertIn("points 1 and 4 coincide: an open curve cannot close on itself smoothly",
                      C.MESSAGES[-1])
        self.assertIn("set Closed", C.MESSAGES[-1])

    def test_ill_conditioned_interpolation_is_warned(self):
        zig = S.points_sketch(self.doc, ZIGZAG, "Zigzag")
        f = El.make(self.doc, [(zig, [])], K=0.3)
        with S.Said() as w:
            self.doc.recompute()
            self.assertEqual(f.Status, "ok")
            self.assertTrue(f.ConvexHull and not f.Warnings and f.Spread < G.el().SPREAD_MAX)
            f.K = 0.7                       # the basis keeps the hull, the collocation does not
            self.doc.recompute()
            self.assertTrue(f.ConvexHull)
            self.assertGreater(f.Spread, G.el().SPREAD_MAX)
            self.assertEqual(len(f.Warnings), 1)
            self.assertIn("ill-conditioned", f.Warnings[0])
            self.assertEqual(len(w.said), 1)
            # what it says is true: the curve swings far outside the points it goes through
            pts = [S.SKETCH_PLACEMENT.multVec(App.Vector(x, y, 0)) for x, y in ZIGZAG]
            size = max((a - b).Length for a in pts for b in pts)
            on = f.Shape.Edges[0].discretize(400)
            swing = max((a - b).Length for a in on for b in on[::10])
            self.assertGreater(swing, 2.0 * size)
            self.assertEqual(len(f.Warnings), 1)
            f.Mode = "control"              # the points as control points: no collocation
            self.doc.recompute()
            self.assertEqual((f.Status, f.Spread, list(f.Warnings)), ("ok", 1.0, []))

    def test_looping_interpolation_is_warned_as_in_python(self):
        """The library's rule and words (BlendCurve.warnings): points whose interpolation
        at m = 0.52 spreads 40 times and loops; each said once, no Python warning leaks."""
        pts = [(0.0, 0.0), (30.0, 80.0), (70.0, 90.0), (100.0, 0.0)]
        sk = S.points_sketch(self.doc, pts, "Looping")
        f = El.make(self.doc, [(sk, [])], K=0.52, KConvention="parameter")
        with S.Said() as w, warnings.catch_warnings():
            warnings.simplefilter("error")
            self.doc.recompute()
        want = G.el().blend_curve(pts, m=0.52)
        self.assertEqual(len(f.Warnings), 2)
        self.assertIn("ill-conditioned", f.Warnings[0])
        self.assertIn("the curve loops", f.Warnings[1])
        self.assertIn("between points 0 and 3 (counted from 0; chord 100.00 mm", f.Warnings[1])
        # where, and the loop's width, in the schema's length unit (they had none)
        # (the binding's words, its lengths as the workbench writes them: units.number_text)
        from freecad.elastica.units import number_text
        self.assertEqual(list(f.Warnings), want.warnings(
            length=lambda v, digits=None, with_unit=True:
            number_text(v) + (" mm" if with_unit else "")))
        self.assertRegex(f.Warnings[1], r"a loop [0-9.]+ mm wide\)")
        self.assertAlmostEqual(f.Spread / want.spread(), 1.0, places=9)
        self.assertEqual(len(w.said), 2)

    def test_warnings_kept_when_reopened(self):
        f = El.make(self.doc, [(self.sk, [])], Mode="control", K=0.62, KConvention="parameter")
        self.doc.recompute()
        warnings = list(f.Warnings)
        self.assertEqual(len(warnings), 1)
        path = S.temp_path(self, "warned.FCStd")
        self.doc.saveAs(path)
        name = f.Name
        App.closeDocument(self.doc.Name)
        self.doc = App.openDocument(path)
        f = self.doc.getObject(name)
        self.assertEqual(list(f.Warnings), warnings)
        with S.Said() as w:
            f.touch()
            self.doc.recompute()
        self.assertEqual((list(f.Warnings), w.said), (warnings, []))

    def test_d_is_not_used_through_the_points(self):
        """QA17 P4: through the points D changed nothing in the curve, yet D = 5 added
        'warning: the basis is negative' to Status; the property editor took it while the
        panel greyed it out. Now read-only there, and no warning from it."""
        f = El.make(self.doc, [(self.sk, [])], D=5.0)
        self.doc.recompute()
        self._ok(f)
        self.assertEqual((f.Status, list(f.Warnings)), ("ok", []))
        self.assertIn("ReadOnly", f.getEditorMode("D"))
        length = f.Shape.Length
        f.D = 2.0
        self.doc.recompute()
        self.assertAlmostEqual(f.Shape.Length, length, delta=1e-9 * length)
        f.Mode, f.D = "control", 5.0        # control points: D shapes the curve, and warns
        self.doc.recompute()
        self.assertEqual(f.getEditorMode("D"), [])
        self.assertIn("ReadOnly", f.getEditorMode("Closed"))
        self.assertTrue(f.Status.startswith("ok; warning: the basis is negative"), f.Status)
        f.Closed = True                     # not used by control points either
        self.doc.recompute()
        self.assertTrue(f.Status.startswith("ok; warning: the basis"), f.Status)
        self.assertFalse(f.Shape.Edges[0].isClosed())

    def test_three_five_and_closed_points_are_the_librarys_composite(self):
        """QA17 P5: the feature took exactly four points and had no Closed, while the CLI
        and blend_curve make the C1 composite through 3 or more, open or closed."""
        import numpy as np
        import libelastica as el
        five = XY + [(60.0, -30.0)]
        pts = [S.SKETCH_PLACEMENT.multVec(App.Vector(x, y, 0)) for x, y in five]
        for xy in (five[:3], five):
            for closed in (False, True):
                sk = S.points_sketch(self.doc, xy, f"P{len(xy)}{int(closed)}")
                f = El.make(self.doc, [(sk, [])], Closed=closed)
                self.doc.recompute()
                self.assertEqual(f.Status, "ok", (len(xy), closed))
                curve = el.blend_curve(np.array(xy), closed=closed)
                on = G.to_3d(S.SKETCH_PLACEMENT, curve.points(
                    np.linspace(0, curve.nseg, 40 * curve.nseg + 1)))
                self.assertLess(S.distance_to_shape([tuple(p) for p in on], f.Shape),
                                f.BSplineDeviation + 1e-9)
                self.assertEqual(len(f.ControlPoints), 3 * curve.nseg + 1)
                e = f.Shape.Edges[0]
                for p in pts[:len(xy)]:
                    self.assertLess(e.distToShape(Part.Vertex(p))[0], f.Tolerance.Value + 1e-9)
                self.assertEqual(e.isClosed(), closed)
                if closed:     # smooth at the seam: one tangent
                    t0 = e.tangentAt(e.FirstParameter).normalize()
                    t1 = e.tangentAt(e.LastParameter).normalize()
                    self.assertGreater(t0.dot(t1), 1 - 1e-9)
        # seven control points: two segments
        seven = S.points_sketch(self.doc, five + [(90.0, -50.0), (120.0, -20.0)], "Seven")
        f = El.make(self.doc, [(seven, [])], Mode="control")
        self.doc.recompute()
        self.assertEqual(f.Status, "ok")
        e = f.Shape.Edges[0]
        self.assertLess((e.valueAt(e.LastParameter) -
                         S.SKETCH_PLACEMENT.multVec(App.Vector(120, -20, 0))).Length, 1e-7)
