"""freecadcmd -t test: a Fit's warnings name a point as the designer finds it in the Sketcher
(QA qagui F6, F7). F6: 40 noisy points of an S on a datum plane inclined 35 deg in a Body
placed off the origin, point 24 moved 4 mm across the curve: the outlier warning gave the
global '(1835, 8.736, -278) mm', which appears nowhere in the sketch, and no number; now
'point 24 as given, in the sketch at (1556, -624.2) mm', now "Scan's 24-Point" as the
Sketcher's Elements panel lists it (test_elastica_fit_sketcher_names). F7: 40
points of a sine-like S (no elastica's shape), point 18 moved 9 mm: the misfit warning said
'a corner, or curves of more than one piece' of a curve with no corner and did not name the
point; now it says no corner stands out and names point 18, not the cause (rms 2.51 mm
without it)."""
import math
import unittest

import numpy as np

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi, units as U
from freecad.elastica.units import say


class FitPointNamesTest(S.DocTest):
    doc_name = "ElasticaFitPointNames"

    def _inclined_sketch(self, xy):
        sk = S.inclined_body_sketch(self.doc, "Scan")
        for x, y in xy:
            sk.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
        self.doc.recompute()
        return sk

    def test_an_outlier_is_named_by_number_and_sketch_coordinates(self):
        import libelastica as el
        rng = np.random.default_rng(7)
        c = el.SmoothElastica(x0=0, y0=0, phi=0.3, mu=(1 / 120.0) ** 2, k=0.6, q=0.2,
                              length=380.0)
        s = np.sort(rng.uniform(0, 380, 40))
        xy = c.points(s) + rng.normal(0, 0.25, (40, 2))
        th = float(c.angle([s[23]])[0])
        xy[23] += 4.0 * np.array([-math.sin(th), math.cos(th)])
        xy = xy + [1500, -800]
        sk = self._inclined_sketch(xy)
        g = sk.getGlobalPlacement().multVec(App.Vector(xy[23][0], xy[23][1], 0))
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            said = [w for w in say(list(f.Warnings)) if "outliers?" in w]
            self.assertEqual(len(said), 1, (model, list(f.Warnings)))
            self.assertIn(f"(Scan's 24-Point, in the sketch at ({U.number_text(xy[23][0])}, "
                          f"{U.number_text(xy[23][1])}) mm)", said[0])
            self.assertNotIn(U.number_text(g.x), said[0])     # no global coordinates

    def test_a_stray_point_in_a_shape_of_no_elastica_is_named_and_no_corner_guessed(self):
        rng = np.random.default_rng(1)
        rng.normal(0, 0.4, 12)
        s = np.sort(rng.uniform(0, 1, 40))
        ys = 80 * np.sin(2.2 * s * np.pi) + rng.normal(0, 0.3, 40)
        ys[17] += 9.0
        xy = np.column_stack([400 * s + 1500, ys - 500])
        sk = S.points_sketch(self.doc, [tuple(p) for p in xy], "Scan40")
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            said = [w for w in say(list(f.Warnings)) if "not one elastica" in w]
            self.assertEqual(len(said), 1, (model, list(f.Warnings)))
            self.assertNotIn("a corner", said[0])
            self.assertIn("no corner stands out, and the farthest point is not the cause "
                          f"(Scan40's 18-Point, in the sketch at ({U.number_text(xy[17][0])}, "
                          f"{U.number_text(xy[17][1])}) mm, 7.4", said[0])   # 7.44 / 7.48 mm
            self.assertIn(" mm from the curve; without it rms 2.51 mm)", said[0])
            self.assertIn("elastic spline", said[0])


if __name__ == "__main__":
    unittest.main()
