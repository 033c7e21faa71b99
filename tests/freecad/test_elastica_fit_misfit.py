"""freecadcmd -t test: a Fit whose points are not one elastica (QA16 F2: a straight run
meeting an elastica at a corner, fitted at rms 10.9 where the points' noise is 0.3, Status
"converged" and no word) warns so and names the corner's place; in one piece and split at
the inflection (a keyline's joint is no corner); noisy points of one elastica stay silent.
The verdict is the binding's (el.misfit)."""
import os
import re
import sys
import unittest

import FreeCAD as App
import numpy as np

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica.fit_core import fit_core
from freecad.elastica.units import say

sys.path.insert(0, os.path.join(S.ROOT, "tests", "python"))
try:
    from test_misfit import hand_drawn, ship_line
finally:
    sys.path.pop(0)


def _said(warnings):
    return [w for w in say(warnings) if "they are not one" in w]


class FitMisfitTest(S.DocTest):
    doc_name = "ElasticaFitMisfit"

    def test_a_corner_is_warned_at_its_place(self):
        pts = ship_line()
        points = [App.Vector(float(x), float(y), 0.0) for x, y in pts]
        for model in ("smooth", "discrete"):
            for split, what in ((False, "one elastica"), (True, "one keyline")):
                r = fit_core(points, model=model, split=split)
                said = _said(r["warnings"])
                self.assertEqual(len(said), 1, (model, split, say(r["warnings"])))
                self.assertIn(f"they are not {what}", said[0])
                at = re.search(r"a corner at \(([-0-9.e]+) mm, ([-0-9.e]+) mm", said[0])
                self.assertIsNotNone(at, said[0])
                # within 3 points (4 mm apart on the straight run) of the corner, point 160
                self.assertLess(np.hypot(float(at.group(1)) - pts[160, 0],
                                         float(at.group(2)) - pts[160, 1]), 13.0, said[0])

    def test_the_feature_shows_it_and_noisy_points_of_one_elastica_none(self):
        for name, pts, warned in (("Ship", ship_line(), True), ("Drawn", hand_drawn(), False)):
            path = S.temp_path(self, f"{name}.csv")
            np.savetxt(path, np.c_[pts, np.zeros(len(pts))], delimiter=",", header="x,y,z",
                       comments="")
            f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
            self.doc.recompute()
            self.assertIn("converged", f.Status)
            self.assertEqual(len(_said(list(f.Warnings))), int(warned), (name, list(f.Warnings)))


if __name__ == "__main__":
    unittest.main()
