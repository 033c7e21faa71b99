"""freecadcmd -t test: the scripting makes take a picked object's subelement as one name string
as well as a list of names (QA21gui F6: g2quad.make(doc, [(sketch, "Edge1")]) read the string
letter by letter: "error: KeylineSketch has no E"); "" is the whole object, as before."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import comb, ellblend, fit, g2quad, spline


class MakeNamesTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("MakeNames")
        self.curve = S.bspline_sketch(self.doc, S.keyline_xy(40)[0])
        self.pts = S.points_sketch(self.doc, S.keyline_xy(6)[0])
        self.doc.recompute()

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _same(self, one, listed):
        self.doc.recompute()
        for f in (one, listed):
            self.assertNotIn("Invalid", f.State, (f.Label, f.Status))
        self.assertEqual(one.Status, listed.Status)
        self.assertEqual(one.Shape.Length, listed.Shape.Length)

    def test_one_name_string_is_one_subelement(self):
        d = self.doc
        self._same(g2quad.make(d, [(self.curve, "Edge1")]),
                   g2quad.make(d, [(self.curve, ["Edge1"])]))
        self._same(fit.make(d, [(self.curve, "Edge1")]), fit.make(d, [(self.curve, ["Edge1"])]))
        self._same(comb.make(d, self.curve, "Edge1"), comb.make(d, self.curve, ["Edge1"]))
        for make in (spline.make, ellblend.make):
            self._same(make(d, [(self.pts, "")]), make(d, [(self.pts, [])]))
        f = g2quad.make(d, [(self.curve, "Edge1")])
        self.assertEqual(f.Source, [(self.curve, ("Edge1",))])


if __name__ == "__main__":
    unittest.main()
