"""freecadcmd -t tests of copying a result's B-spline into an existing sketch
(geometry.write_to_sketch, what the panels' "Copy into" runs on OK): a sketch in the
curve's plane takes the curve as it is, one in another plane is refused with a message and
left as it was (it kept only the curve's shadow on its plane, flattened)."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica import geometry as G
from freecad.elastica.proxy import InputProblem


class CopyIntoSketchTest(S.DocTest):
    doc_name = "ElasticaSketchCopy"

    def setUp(self):
        super().setUp()
        xy = [(x, 10 * math.sin(x / 30.0)) for x in range(0, 100, 10)]
        self.fit = Fi.make(self.doc, [(S.points_sketch(self.doc, xy), [])], Model="smooth")
        self.doc.recompute()
        self.assertFalse(self.fit.Status.startswith("error"), self.fit.Status)

    def _sketch(self, placement, name):
        sk = self.doc.addObject("Sketcher::SketchObject", name)
        sk.Placement = placement
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(10, 0, 0)), False)
        self.doc.recompute()
        return sk

    def test_a_copy_again_replaces_the_earlier_copy_in_a_closed_profile(self):
        """QA20gui F4: a fit copied into a sketch, the profile closed there with three lines
        joined by coincidences, a source point moved, the fit copied again into that sketch:
        the earlier copy is replaced in place (one B-spline, the same index), the lines
        follow its new ends, the profile stays one closed wire that makes a solid. It added a
        second B-spline beside the first (two wires; a Pocket of it failed)."""
        import Sketcher
        xy = [(x, 12 * math.sin(x / 25.0) + 0.3 * ((x * 7) % 3)) for x in range(0, 110, 10)]
        src = S.points_sketch(self.doc, xy, "Scan")
        fit = Fi.make(self.doc, [(src, [])], Model="smooth")
        self.doc.recompute()
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.Placement = fit.Plane
        self.assertEqual(G.write_to_sketch(fit, sk), [0])
        self.doc.recompute()
        a, b = sk.Geometry[0].StartPoint, sk.Geometry[0].EndPoint
        down = App.Vector(0, -40, 0)
        for p, q in ((b, b + down), (b + down, a + down), (a + down, a)):
            sk.addGeometry(Part.LineSegment(p, q), False)
        for g0, p0, g1, p1 in ((0, 2, 1, 1), (1, 2, 2, 1), (2, 2, 3, 1), (3, 2, 0, 1)):
            sk.addConstraint(Sketcher.Constraint("Coincident", g0, p0, g1, p1))
        self.doc.recompute()
        self.assertEqual(len(sk.Shape.Wires), 1)
        self.assertTrue(sk.Shape.Wires[0].isClosed())
        x, y = xy[5]
        src.movePoint(5, 1, App.Vector(x, y + 4.0, 0))
        self.doc.recompute()
        self.assertFalse(fit.Status.startswith("error"), fit.Status)
        moved = [tuple(p) for p in sk.Shape.Edges[0].discretize(40)]
        self.assertGreater(S.distance_to_shape(moved, fit.Shape), 0.5)   # the copy is old
        self.assertEqual(G.write_to_sketch(fit, sk), [0])
        self.doc.recompute()
        self.assertEqual([g.TypeId for g in sk.Geometry],
                         ["Part::GeomBSplineCurve"] + ["Part::GeomLineSegment"] * 3)
        self.assertEqual(len(sk.Constraints), 4)
        wires = sk.Shape.Wires
        self.assertEqual(len(wires), 1)
        self.assertTrue(wires[0].isClosed())
        solid = Part.Face(wires[0]).extrude(fit.Plane.Rotation.multVec(App.Vector(0, 0, 5)))
        self.assertTrue(solid.isValid())
        self.assertGreater(solid.Volume, 0)
        curve = [tuple(p) for p in sk.Shape.Edges[0].discretize(40)]
        self.assertLess(S.distance_to_shape(curve, fit.Shape), 1e-6)  # the copy of now
        # the copy into another sketch is another copy (not replaced): two sketches, two
        other = self.doc.addObject("Sketcher::SketchObject", "Other")
        other.Placement = fit.Plane
        self.assertEqual(G.write_to_sketch(fit, other), [0])
        self.assertEqual(len(sk.Geometry), 4)
        # the earlier copy deleted in the Sketcher: a copy is added again
        sk.delGeometry(0)
        self.doc.recompute()
        self.assertEqual(G.write_to_sketch(fit, sk), [3])

    def test_a_sketch_in_another_plane_is_refused_untouched(self):
        plane = S.SKETCH_PLACEMENT
        tilted = App.Placement(plane.Base, plane.Rotation.multiply(
            App.Rotation(App.Vector(1, 0, 0), 90)))
        lifted = App.Placement(plane.multVec(App.Vector(0, 0, 2)), plane.Rotation)
        for placement, name in ((tilted, "Front"), (lifted, "Parallel")):
            sk = self._sketch(placement, name)
            with self.assertRaises(InputProblem) as cm:
                G.write_to_sketch(self.fit, sk)
            msg = str(cm.exception)
            self.assertIn(f"{name} does not lie in the plane of {self.fit.Label}", msg)
            self.assertIn("mm off the sketch's plane", msg)
            self.assertEqual(len(sk.Geometry), 1)          # nothing half-written
            self.assertEqual(len(sk.Shape.Edges), 1)

    def test_a_sketch_in_the_curve_plane_takes_the_curve(self):
        # the fit's plane, its origin moved and turned within it
        plane = S.SKETCH_PLACEMENT
        moved = App.Placement(plane.multVec(App.Vector(-30, 12, 0)), plane.Rotation.multiply(
            App.Rotation(App.Vector(0, 0, 1), 40)))
        sk = self._sketch(moved, "Same")
        ids = G.write_to_sketch(self.fit, sk)
        self.doc.recompute()
        self.assertEqual(len(ids), 1)
        e = sk.Shape.Edges[-1]
        pts = [tuple(p) for p in e.discretize(40)]
        self.assertLess(S.distance_to_shape(pts, self.fit.Shape), 1e-7)
        self.assertAlmostEqual(e.Length, self.fit.Shape.Length, delta=1e-7)

    def test_a_sketch_another_feature_reads_whole_is_refused_untouched(self):
        """Two stations of points, each fitted: Copy into the other station's sketch made
        that fit fail ('holds 20 points and 1 edge', QA); the sketch is now refused, its
        fit unchanged."""
        xy = [(x, 30 + 10 * math.sin(x / 30.0)) for x in range(0, 100, 10)]
        station = S.points_sketch(self.doc, xy)
        other = Fi.make(self.doc, [(station, [])], Model="smooth")
        self.doc.recompute()
        rms = other.Rms
        with self.assertRaises(InputProblem) as cm:
            G.write_to_sketch(self.fit, station)
        self.assertIn(f"{station.Label} is read whole by {other.Label}", str(cm.exception))
        self.assertEqual(len(station.Shape.Edges), 0)
        station.touch()
        self.doc.recompute()
        self.assertFalse(other.Status.startswith("error"), other.Status)
        self.assertEqual(other.Rms, rms)


if __name__ == "__main__":
    unittest.main()
