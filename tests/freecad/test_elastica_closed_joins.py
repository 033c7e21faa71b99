"""A closed edge (a full circle or ellipse) picked as a join edge: its seam (parameter
0) is no end. The spline meets it at its point nearest the end duck; a blend and a fit's
G1 / G2 join refuse it, naming it; a fit's tangent takes its tangent nearest the points'
end. (QA: joined at the seam, a spline crossed the circle at 90 degrees, a fit's join
started 28 mm away and looped, a blend ran seam to seam.) Run with
`freecadcmd -t test_elastica_closed_joins`."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from elastica_samples import curvature_vector
from freecad.elastica import blend as Bl
from freecad.elastica import commands as C
from freecad.elastica import fit as Fi
from freecad.elastica import spline as Sp
from freecad.elastica import units as U

V = App.Vector


class ClosedJoinTest(S.DocTest):
    doc_name = "ElasticaClosedJoins"

    def setUp(self):
        super().setUp()
        sk = self.doc.addObject("Sketcher::SketchObject", "Closed")
        sk.Placement = S.SKETCH_PLACEMENT
        sk.addGeometry(Part.Circle(V(-40, 10, 0), V(0, 0, 1), 20), False)   # seam at (-20, 10)
        sk.addGeometry(Part.Ellipse(V(40, 10, 0), 25, 12), False)
        self.doc.recompute()
        self.sk = sk

    def test_a_spline_meets_a_full_circle_and_ellipse_where_its_ducks_are(self):
        # the first duck on the circle's top, the last on the ellipse's top
        pts = S.points_sketch(self.doc, [(-40, 30), (-15, 34), (10, 30), (40, 22)], "OnClosed")
        self.doc.recompute()
        s = Sp.make(self.doc, [(pts, [])], StartCondition="G2", StartEdge=(self.sk, "Edge1"),
                    EndCondition="G2", EndEdge=(self.sk, "Edge2"), Tolerance=1e-6)
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        self.assertEqual(list(s.Warnings), [])
        c = s.Shape.Edges[0].Curve
        for name, u, edge in (("circle", c.FirstParameter, self.sk.Shape.Edges[0]),
                              ("ellipse", c.LastParameter, self.sk.Shape.Edges[1])):
            p = c.value(u)
            self.assertLess(edge.distToShape(Part.Vertex(p))[0], 1e-6, name)
            ue = edge.Curve.parameter(p)
            t, te = App.Vector(c.tangent(u)[0]).normalize(), edge.tangentAt(ue).normalize()
            self.assertLess(1 - abs(t.dot(te)), 1e-12, f"{name}: tangent")
            k, ke = curvature_vector(c, u), edge.normalAt(ue) * edge.curvatureAt(ue)
            self.assertLess((k - ke).Length, 1e-6 * ke.Length, f"{name}: curvature vector")

    def test_a_spline_joined_at_the_seam_by_an_earlier_version_says_it_changed(self):
        # the rule before 4a0ae84 (the closed edge joined at its seam): the spline as that
        # workbench stored it, then recomputed by this one, once with the note, then without
        pts = S.points_sketch(self.doc, [(-40, 30), (-15, 34), (10, 30), (40, 22)], "OnCircle")
        self.doc.recompute()
        nearest = Sp.nearest_parameter
        Sp.nearest_parameter = lambda edge, point: None
        try:
            s = Sp.make(self.doc, [(pts, [])], StartCondition="G2", StartEdge=(self.sk, "Edge1"),
                        Tolerance=1e-6)
            self.doc.recompute()
        finally:
            Sp.nearest_parameter = nearest
        seam = s.Shape.Length
        self.assertNotIn("earlier version", s.Status)
        # as that version saved it: reopened, its outcome is no kept one (kept.py)
        s, = S.reopened(self, "seam.FCStd", s.Name)
        printed = []
        warn = App.Console.PrintWarning
        App.Console.PrintWarning = lambda msg: printed.append(msg)
        try:
            s.touch()
            self.doc.recompute()
            now = s.Shape.Length
            self.assertGreater(abs(now - seam), 1.0)
            self.assertIn("joined to it at its seam by an earlier version", s.Status)
            self.assertIn(f"(length {U.number_text(seam)} -> {U.number_text(now)} mm)", s.Status)
            from freecad.elastica.proxy import said   # a panel opened under Imperial decimal
            schema = App.Units.getSchema()
            try:
                App.Units.setSchema(3)
                inches = said(s, "Status")
                App.Units.setSchema(2)          # US customary: '"', as FreeCAD writes inches
                marked = said(s, "Status")      # there and this text its other lengths
            finally:
                App.Units.setSchema(schema)
            self.assertIn(f"(length {U.number_text(seam / 25.4)} -> {U.number_text(now / 25.4)} in)",
                          inches)
            self.assertIn(f'(length {U.number_text(seam / 25.4)} -> {U.number_text(now / 25.4)} ")',
                          marked)
            self.assertEqual(len([m for m in printed if "earlier version" in m]), 1, printed)
            s.touch()                   # the same input: its outcome stands, said once
            self.doc.recompute()
            self.assertIn("earlier version", s.Status)
            s.Tolerance = 2e-6          # computed again: the shape it has is this version's
            self.doc.recompute()
            self.assertNotIn("earlier version", s.Status)
            self.assertEqual(len([m for m in printed if "earlier version" in m]), 1, printed)
            self.assertAlmostEqual(s.Shape.Length, now, 4)
        finally:
            App.Console.PrintWarning = warn

    def test_a_spline_off_a_full_circle_warns_with_its_nearest_point(self):
        pts = S.points_sketch(self.doc, [(-40, 33), (-15, 34), (10, 30), (40, 22)], "OffClosed")
        self.doc.recompute()
        s = Sp.make(self.doc, [(pts, [])], StartCondition="tangent", StartEdge=(self.sk, "Edge1"))
        self.doc.recompute()
        self.assertEqual(len(s.Warnings), 1, s.Warnings)
        self.assertIn("the start edge (closed) is 3.00 mm from the first point", s.Warnings[0])
        c = s.Shape.Edges[0].Curve   # the circle's tangent at its top: along the x axis
        x = S.SKETCH_PLACEMENT.Rotation.multVec(V(1, 0, 0))
        self.assertLess(1 - abs(App.Vector(c.tangent(c.FirstParameter)[0]).normalize().dot(x)),
                        1e-12)

    def test_a_blend_refuses_a_closed_edge_naming_it(self):
        for cont in ("G1", "G2"):
            b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Continuity=cont)
            self.doc.recompute()
            self.assertTrue(b.Status.startswith("error"), b.Status)
            self.assertIn("Edge1 (Closed.Edge1) is a closed edge (a full circle)", b.Status)
            self.doc.removeObject(b.Name)
            self.doc.recompute()

    def test_the_blend_command_refuses_a_closed_edge_with_a_message(self):
        """QA: the command made an invalid feature, opened its panel on the error, and the
        report view showed a Python traceback for this input error. Now it is bad input as
        any other: the message alone, nothing made (a panel could not help: no tension or
        length gives a circle an end)."""
        for picks, first in ((("Edge1", "Edge2"), "Edge1 is a closed edge (a full circle)"),
                             (("Edge2", "Edge1"), "Edge2 is a closed edge (a full ellipse)")):
            before = S.doc_state(self.doc)
            del C.MESSAGES[:]
            self.assertIsNone(C.blend_sources([(self.sk, [p]) for p in picks], open_panel=False))
            self.assertEqual(C.MESSAGES, [f"Closed.{first}: a blend leaves an edge at an end "
                                          "vertex and it has none; use an arc of it (trim or "
                                          "split it), or an elastic spline with an end on it"])
            self.assertEqual(S.doc_state(self.doc), before)

    def test_a_fit_joins_no_closed_edge_but_takes_its_tangent_nearest(self):
        # points leaving the circle's top to the right
        xy = [(-40 + 5 * i, 30 + 0.02 * i * i) for i in range(12)]
        pts = S.points_sketch(self.doc, xy, "Data")
        self.doc.recompute()
        for join in ("G1", "G2"):
            f = Fi.make(self.doc, [(pts, [])], StartTangent=(self.sk, ["Edge1"]),
                        StartContinuity=join)
            self.doc.recompute()
            self.assertTrue(f.Status.startswith("error"), f.Status)
            self.assertIn(f"Start join {join}: the start edge is closed", f.Status)
            self.doc.removeObject(f.Name)
            self.doc.recompute()
        f = Fi.make(self.doc, [(pts, [])], StartTangent=(self.sk, ["Edge1"]))
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        e = f.Shape.Edges[0]
        t = e.tangentAt(e.FirstParameter).normalize()
        x = S.SKETCH_PLACEMENT.Rotation.multVec(V(1, 0, 0))   # the circle's top, not its seam
        self.assertLess(math.acos(min(1.0, abs(t.dot(x)))), 1e-9)


if __name__ == "__main__":
    unittest.main()
