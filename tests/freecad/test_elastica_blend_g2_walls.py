"""freecadcmd -t test of the Elastic blend with Continuity G2 between two walls at tension 0
(QA): no G1 curve joins them at tension 0 (the clamped free batten slides off its ducks),
yet the G2 batten held by its guide ducks exists; the blend is that batten (the library's,
el.elastic_spline, which solves it by length), tangent and curvature 0 at both walls."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend as Bl


class BlendG2WallsTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("ElasticaBlendG2WallsTest")

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def test_g2_between_walls_at_tension_zero(self):
        sk = self.doc.addObject("Sketcher::SketchObject", "Walls")
        sk.Placement = S.SKETCH_PLACEMENT
        for a, c in (((0, 0), (0, 30)), ((100, 35), (100, 0))):
            sk.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*c, 0)), False)
        self.doc.recompute()
        # from the higher wall's top (100, 35) to the lower one's (0, 30): no G1 curve at
        # tension 0 this way (from the lower one there is one, 218.8 mm)
        b = Bl.make(self.doc, (sk, "Edge2"), (sk, "Edge1"), False, True, Continuity="G2",
                    Mode="tension", Tension=0.0)
        self.doc.recompute()
        self.assertTrue(b.Status.startswith("G2 from the library's own start"), b.Status)
        import libelastica as el
        ref = el.elastic_spline([(100, 35), (0, 30)], tension=0.0,
                                start={"tangent": (0, 1), "curvature": 0.0},
                                end={"tangent": (0, -1), "curvature": 0.0})
        self.assertEqual(b.BlendTension, 0.0)
        self.assertAlmostEqual(b.BlendLength, ref.length, delta=1e-9 * ref.length)
        self.assertTrue(219.0 < b.BlendLength < 219.5, b.BlendLength)
        self.assertEqual(len(b.GuideDucks), 2)
        self.assertAlmostEqual(b.Shape.Length, ref.length, delta=b.Tolerance)
        wall = sk.Shape.Edges[0]
        up = (wall.Vertexes[1].Point - wall.Vertexes[0].Point).normalize()
        c = b.Shape.Edges[0].Curve
        for u in (c.FirstParameter, c.LastParameter):       # G2 to straight walls
            self.assertLess(c.curvature(u), 1e-6)
            self.assertLess(App.Vector(c.tangent(u)[0]).normalize().cross(up).Length, 1e-9)

    def test_no_g2_blend_says_so_in_length_mode(self):
        """QA gui3 G3: a Sketcher B-spline into an arc, G2 by length (228 mm, the G1 blend's):
        no G2 batten at tension 0 nor at 1.25 to 10 x the distance between the ends; the
        error said "pick a tension, or G1", while the Tension box is disabled in length mode.
        It says plainly that none was found and what was tried, and to use G1."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Deck")
        b = Part.BSplineCurve()
        b.interpolate([App.Vector(0, 0, 0), App.Vector(40, 30, 0), App.Vector(90, 20, 0),
                       App.Vector(130, 45, 0)])
        sk.addGeometry(b, False)
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(260, 40, 0), App.Vector(0, 0, 1), 40),
                                        math.radians(120), math.radians(300)), False)
        self.doc.recompute()
        o = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2", Mode="length",
                    Length=228.0)
        self.doc.recompute()
        self.assertNotIn("pick a tension", o.Status)
        self.assertIn("no G2 blend found between these edges (tried: tension 0, and lengths "
                      "1.25 to 10 \u00d7 the 113.92 mm between the ends): use G1", o.Status)
