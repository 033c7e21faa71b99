"""freecadcmd -t test: the elliptic blend's input messages read as sentences (QA21gui F5: "the
the points are not coplanar (rms distance 5 mm ...)" for a whole Box, "1 points: an elliptic
blend passes through three or more")."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import ellblend as El


class EllipticBlendWordsTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("EllWords")

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def test_messages(self):
        box = self.doc.addObject("Part::Box", "Box")
        one = S.points_sketch(self.doc, [(0.0, 0.0)], "One")
        self.doc.recompute()
        f = El.make(self.doc, [(box, [])])
        g = El.make(self.doc, [(one, [])])
        self.doc.recompute()
        self.assertTrue(f.Status.startswith("error: the points are not coplanar (rms distance "),
                        f.Status)
        self.assertEqual(g.Status, "error: 1 point: an elliptic blend passes through three or "
                         "more")


if __name__ == "__main__":
    unittest.main()
