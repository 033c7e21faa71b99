"""freecadcmd -t test of the tensions' properties: one bound to an expression of another unit
is refused, naming the unit (QA19gui F9: a cell '=5 mm' was taken as 5 1/mm^2: FreeCAD 0.20's
PropertyQuantity takes no unit of 1/length^2), while '=0.002 / in^2' and a plain number still
drive it; they are precision properties, which the property view shows with their digits (F10:
a float one's 0.001 as "0.00"), taking any double (a compression too), also once reopened, and
a document of version 3 (float tensions) opens with them, its values, expression and pick
kept, untouched."""
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
            self.assertEqual(f.Status, "error: Tension is bound to Sheet.A1 = 5.00 mm: a tension "
                             "is in 1/length^2 (e.g. '=0.002 / mm^2') or a plain number "
                             "(1/mm^2)", f.Label)

    def test_a_per_area_or_a_number_drives_it(self):
        for f in self._features():
            for cell, value in (("A2", 0.002 / 25.4 ** 2), ("A3", 0.001)):
                f.setExpression("Tension", "Sheet." + cell)
                self.doc.recompute()
                self.assertNotIn("Invalid", f.State, (f.Label, cell, f.Status))
                self.assertAlmostEqual(f.Tension, value, delta=1e-15)


    def test_tensions_are_precision_properties_and_old_documents_load(self):
        b, s = self._features()
        names = {b: ("Tension", "BlendTension"), s: ("Tension", "SplineTension")}
        for f, props in names.items():
            for p in props:
                self.assertEqual(f.getTypeIdOfProperty(p), "App::PropertyPrecision", (f.Label, p))
        b.Tension = -1e-5                               # compression: not clamped to 0
        self.assertEqual(b.Tension, -1e-5)
        b.Tension = 0.001
        self.doc.recompute()
        b.Solution = 3
        self.doc.recompute()
        self.assertEqual(b.Status, "solution 3 of 4")
        s.setExpression("Tension", "Sheet.A2")
        self.doc.recompute()
        figures = (b.BlendTension, b.Shape.Length, s.Tension, s.SplineTension, s.Shape.Length)

        def as_version_3(text):
            new = 'type="App::PropertyPrecision"'
            self.assertEqual(text.count(new), 4)
            return text.replace(new, 'type="App::PropertyFloat"')
        bname, sname = b.Name, s.Name
        for edit in (None, as_version_3):
            name = self.doc.Name
            path = S.temp_path(self, "saved.FCStd")
            self.doc.saveAs(path)
            App.closeDocument(name)
            if edit:
                from test_elastica_fit import rewrite_document
                old = path.replace("saved", "older")
                rewrite_document(path, old, edit)
                path = old
            self.doc = App.openDocument(path)
            b, s = self.doc.getObject(bname), self.doc.getObject(sname)
            for f, props in ((b, ("Tension", "BlendTension")), (s, ("Tension", "SplineTension"))):
                self.assertNotIn("Touched", f.State, f.Label)
                for p in props:
                    self.assertEqual(f.getTypeIdOfProperty(p), "App::PropertyPrecision")
            # exact: not the file's 16 decimals (the shapes: as the file's BRep keeps them)
            self.assertEqual((b.BlendTension, s.Tension, s.SplineTension),
                             (figures[0], figures[2], figures[3]))
            self.assertAlmostEqual(b.Shape.Length, figures[1], delta=1e-12 * figures[1])
            self.assertAlmostEqual(s.Shape.Length, figures[4], delta=1e-12 * figures[4])
            self.assertEqual((b.Tension, b.Solution), (0.001, 3))
            self.assertEqual(dict(s.ExpressionEngine).get("Tension"), "Sheet.A2")
            b.Tension = -1e-5                           # the bounds set again
            self.assertEqual(b.Tension, -1e-5)
            b.Tension = 0.001
            b.Solution = 3
            self.doc.recompute()
            self.assertEqual(b.Status, "solution 3 of 4")


if __name__ == "__main__":
    unittest.main()
