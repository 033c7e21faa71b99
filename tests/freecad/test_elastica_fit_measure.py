"""freecadcmd -t tests of what a fit's Rms, MaxError and Distances measure: the user's
own points (never a resampled polygon's vertices) to the curve drawn, in 3D (a point's
distance from the fit plane included), checked against Part's distToShape; and the
warnings when points lie off their plane or beyond the ends of a resampled fit."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi


def measured(f, points):
    """The points' distances to the feature's shape, by Part (distToShape)."""
    return [f.Shape.distToShape(Part.Vertex(p))[0] for p in points]


class FitMeasureTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("ElasticaFitMeasure")

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _check_figures(self, f, points, delta):
        """Rms, MaxError, Distances and DataPoints are the points' own, in 3D."""
        self.assertFalse(f.Status.startswith("error"), f.Status)
        d = measured(f, points)
        self.assertEqual(len(f.DataPoints), len(points))
        self.assertLess(max((a - b).Length for a, b in zip(f.DataPoints, points)), 1e-9)
        self.assertLess(max(abs(abs(a) - b) for a, b in zip(f.Distances, d)), delta)
        self.assertAlmostEqual(f.Rms, math.sqrt(sum(x * x for x in d) / len(d)), delta=delta)
        self.assertAlmostEqual(f.MaxError, max(d), delta=delta)

    def test_points_off_their_plane_are_measured_in_3d(self):
        # a scanned keyline, its points alternately 0.5 mm either side of the plane
        pts = [App.Vector(x, 15 * math.sin(x / 40.0), 0.5 if i % 2 else -0.5)
               for i, x in enumerate(range(0, 121, 6))]
        wire = self.doc.addObject("Part::Feature", "Scan")
        wire.Shape = Part.makePolygon(pts)
        self.doc.recompute()
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(wire, [])], Model=model)
            self.doc.recompute()
            # a smooth fit's distances are the library's, to the elastica: the B-spline lies
            # within its Tolerance of that
            self._check_figures(f, pts, f.Tolerance.Value if model == "smooth" else 1e-6)
            self.assertGreater(f.Rms, 0.45)            # in the plane alone: 0.02 mm
            self.assertIn("in 3D", f.ErrorMeasure)
            said = [w for w in f.Warnings if "off their plane" in w]
            self.assertEqual(len(said), 1, list(f.Warnings))
            # (the best plane of the zigzag is a little tilted: 0.59 mm, rms 0.497 mm)
            self.assertRegex(said[0], r"up to 0\.[56]\d* mm \(rms 0\.[45]\d* mm\) off their "
                                      r"plane, the fit's: Rms and MaxError include that")

    def test_points_in_their_plane_give_no_plane_warning(self):
        xy, _ = S.keyline_xy(40)
        f = Fi.make(self.doc, [(S.polyline_3d(self.doc, xy), [])], Model="smooth")
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertEqual(list(f.Warnings), [])
        self.assertNotIn("3D", f.ErrorMeasure)
        self.assertLess(f.Rms, 1e-3)

    def test_a_resampled_fit_is_measured_from_the_points_given(self):
        # 15 points, the last at x = 98: an equilateral polygon of 5 mm stops 3.7 mm short
        xy = [(x, 0.004 * x * x - 0.00003 * x ** 3) for x in range(0, 101, 7)]
        sk = S.points_sketch(self.doc, xy)
        pts = [sk.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(sk, [])], Model=model, ResampleStep=5.0)
            self.doc.recompute()
            self._check_figures(f, pts, 1e-6)
            self.assertGreater(f.MaxError, 3.0)       # the last point, beyond the curve's end
            self.assertIn("not the resampled polygon", f.ErrorMeasure)
            said = [w for w in f.Warnings if "beyond the curve's ends" in w]
            self.assertEqual(len(said), 1, list(f.Warnings))
            self.assertIn(f"1 of 15 points lies beyond the curve's ends, up to {f.MaxError:.3g} mm",
                          said[0])
            self.assertIn("Resample = 5 mm", said[0])
            self.assertFalse([w for w in f.Warnings if "outliers?" in w], list(f.Warnings))
        # points the polygon covers: no such warning
        f = Fi.make(self.doc, [(sk, [])], Model="smooth")
        self.doc.recompute()
        self.assertFalse([w for w in f.Warnings if "beyond" in w], list(f.Warnings))


if __name__ == "__main__":
    unittest.main()
