"""freecadcmd -t test that a Tension bound to an expression of another unit is refused, naming
the unit (QA19gui F9: a cell '=5 mm' was taken as 5 1/mm^2: Tension is a float property, and
FreeCAD 0.20's PropertyQuantity takes no unit of 1/length^2), while '=0.002 / in^2' and a plain
number still drive it."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend, spline


class TensionUnitTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("TensionUnit")
        self.sheet = self.doc.addObject("Spreadsheet::Sheet", "Sheet")
        self.sheet.set("A1", "=5 mm")
        self.sheet.set("A2", "=0.002 / in^2")
        self.sheet.set("A3", "0.001")
        self.sk = S.two_lines_sketch(self.doc)
        self.pts = S.points_sketch(self.doc, S.keyline_xy(8)[0])
        self.doc.recompute()

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _features(self):
        b = blend.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="tension")
        s = spline.make(self.doc, [(self.pts, [])], Mode="tension")
        self.doc.recompute()
        return b, s

    def test_a_length_is_refused_naming_the_unit(self):
        for f in self._features():
            f.setExpression("Tension", "Sheet.A1")
            self.doc.recompute()
            self.assertIn("Invalid", f.State, f.Label)     # main: 5 1/mm^2, solved
            said = App.Units.Quantity("5 mm").UserString          # (the schema's)
            self.assertEqual(f.Status, f"error: Tension is bound to Sheet.A1 = {said}: a tension "
                             "is in 1/length^2 (e.g. '=0.002 / mm^2') or a plain number "
                             "(1/mm^2)", f.Label)

    def test_a_per_area_or_a_number_drives_it(self):
        for f in self._features():
            for cell, value in (("A2", 0.002 / 25.4 ** 2), ("A3", 0.001)):
                f.setExpression("Tension", "Sheet." + cell)
                self.doc.recompute()
                self.assertNotIn("Invalid", f.State, (f.Label, cell, f.Status))
                self.assertAlmostEqual(f.Tension, value, delta=1e-15)


if __name__ == "__main__":
    unittest.main()
