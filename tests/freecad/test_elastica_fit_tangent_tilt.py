"""freecadcmd -t test: a fit's tangent edge that leaves the fit plane is said, with its angle,
to be projected into it (QA21gui F7: a Box edge 55.6 deg out of the plane was projected
silently, the curve bent at its start, the only word a higher rms); an edge in the plane
says nothing."""
import math
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import fit


class FitTangentTiltTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("FitTilt")
        self.pts = S.points_sketch(self.doc, S.keyline_xy(40)[0])
        self.box = self.doc.addObject("Part::Box", "Box")
        self.box.Placement.Base = App.Vector(300, 0, 0)
        self.lines = S.two_lines_sketch(self.doc)
        self.doc.recompute()

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _tilt(self, edge):
        """The angle (degrees) between the edge's direction and the points' plane."""
        n = self.pts.getGlobalPlacement().Rotation.multVec(App.Vector(0, 0, 1))
        d = edge.tangentAt(edge.FirstParameter)
        return math.degrees(math.asin(min(1.0, abs(d.normalize().dot(n)))))

    def test_an_edge_out_of_the_plane_is_said_projected(self):
        said = []
        for i in range(1, 13):
            e = self.box.Shape.Edges[i - 1]
            tilt = self._tilt(e)
            if not 1.0 < tilt < 89.0:
                continue
            f = fit.make(self.doc, [(self.pts, [])], StartTangent=(self.box, [f"Edge{i}"]))
            self.doc.recompute()
            self.assertNotIn("Invalid", f.State, f.Status)
            text = (f"Start tangent: its edge leaves the fit plane by {tilt:.1f}\u00b0; its "
                    "direction projected into the plane is used")
            self.assertIn(text, list(f.Warnings), (i, tilt, f.Warnings))
            said.append(tilt)
        self.assertTrue(said, "no Box edge out of the plane")

    def test_an_edge_in_the_plane_says_nothing(self):
        e = self.lines.Shape.Edges[0]
        self.assertLess(self._tilt(e), 1e-6)
        f = fit.make(self.doc, [(self.pts, [])], StartTangent=(self.lines, ["Edge1"]))
        self.doc.recompute()
        self.assertNotIn("Invalid", f.State, f.Status)
        self.assertFalse([w for w in f.Warnings if "leaves the fit plane" in w], f.Warnings)


if __name__ == "__main__":
    unittest.main()
