"""freecadcmd -t test of the Elastic blend with Continuity G2 between two walls at tension 0
(QA): no G1 curve joins them at tension 0 (the clamped free batten slides off its ducks),
yet the G2 batten held by its guide ducks exists; the blend is that batten (the library's,
el.elastic_spline, which solves it by length), tangent and curvature 0 at both walls."""
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
