"""freecadcmd -t test: every input of every feature kind bound to a spreadsheet cell of another
unit is refused, the message naming the cell's value and the unit expected (QA21gui F1: a blend's
Length bound to '=0.002 / mm^2' was solved as 0.002 mm, "length 2 um is not longer than the
47.17 mm between the ends"; the fit's ResampleStep '=3 s' taken as 3 mm, silently), and a length
property never keeps a foreign unit: the cell set back to a plain number shows it in mm
(FreeCAD's PropertyQuantity had kept "120.0 1/mm^2") and the feature solves as typed."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend, comb, ellblend, fit, g2quad, spline
from freecad.elastica.bound import expected, said as said_q
from freecad.elastica.kept import is_input

LENGTH = App.Units.Unit(1)


class BoundUnitsTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("BoundUnits")
        self.sheet = self.doc.addObject("Spreadsheet::Sheet", "Params")
        lines = S.two_lines_sketch(self.doc)
        pts = S.points_sketch(self.doc, S.keyline_xy(12)[0])
        quad = S.points_sketch(self.doc, [(0.0, 0.0), (20.0, 35.0), (55.0, 40.0), (80.0, 5.0)],
                               "Quad")
        curve = S.bspline_sketch(self.doc, S.keyline_xy(40)[0])
        self.doc.recompute()
        self.features = [
            blend.make(self.doc, (lines, "Edge1"), (lines, "Edge2"), Mode="length"),
            blend.make(self.doc, (lines, "Edge1"), (lines, "Edge2"), Mode="tension",
                       Tension=0.001),
            spline.make(self.doc, [(pts, [])], Mode="tension", Tension=0.001),
            fit.make(self.doc, [(pts, [])]),
            ellblend.make(self.doc, [(quad, [])], Mode="control"),
            g2quad.make(self.doc, [(curve, ["Edge1"])]),
            comb.make(self.doc, curve, ["Edge1"], Samples=20, Scale=500.0)]
        self.doc.recompute()
        for f in self.features:
            self.assertNotIn("Invalid", f.State, (f.Label, f.Status))

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _inputs(self, f):
        """The inputs with a unit or a plain number (every length, tension, float, integer)."""
        # (not the elliptic blend's K: FreeCAD 0.20 reads the path 'K' as the unit kelvin,
        # "Expression can not evaluate to a value", its own limit)
        return [p for p in f.PropertiesList if is_input(f, p) and expected(f, p) is not None
                and f.getEditorMode(p) == [] and p != "K"]

    def test_every_bound_input_of_another_unit_is_refused_and_no_unit_is_kept(self):
        seen = set()
        for f in self.features:
            shape, status = f.Shape.Length, f.Status
            for p in self._inputs(f):
                unit, words, _, plain = expected(f, p)
                value = getattr(f, p)
                number = float(value)
                if isinstance(value, int):
                    number = int(value)
                wrong = "=5 mm" if plain in ("1/mm^2", "mm^2", "1/mm") else "=0.002 / mm^2"
                if unit is None:
                    wrong = "=2 mm"
                self.sheet.set("A1", wrong)
                self.doc.recompute()
                try:
                    f.setExpression(p, "Params.A1")
                except Exception as exc:
                    raise AssertionError((f.Label, p, wrong, f.getTypeIdOfProperty(p))) from exc
                self.doc.recompute()
                said = said_q(App.Units.Quantity(wrong[1:]))
                why = (f"{p} is a plain number (no unit)" if unit is None else
                       f"{words} (e.g. ")
                self.assertIn("Invalid", f.State, (f.Label, p, f.Status))
                self.assertTrue(f.Status.startswith(f"error: {p} is bound to Params.A1 = {said}: "),
                                (f.Label, p, f.Status))
                self.assertIn(why, f.Status, (f.Label, p))
                if unit is not None:
                    self.assertIn(f"or a plain number ({plain})", f.Status, (f.Label, p))
                # the cell back to a plain number: the feature solves as before, a length in mm
                self.sheet.set("A1", repr(number))
                self.doc.recompute()
                self.assertEqual(f.State, ["Up-to-date"], (f.Label, p, f.Status))
                self.assertEqual(f.Status, status, (f.Label, p))
                self.assertAlmostEqual(f.Shape.Length, shape, delta=1e-9, msg=(f.Label, p))
                if unit == LENGTH:
                    # (its unit on screen stays the cell's until reopened: FreeCAD's own,
                    # test_elastica_bound_undo)
                    self.assertEqual(float(getattr(f, p)), float(number), (f.Label, p))
                    self.assertEqual(f.ExpressionEngine, [(p, "Params.A1")], (f.Label, p))
                f.setExpression(p, None)
                self.doc.recompute()
                seen.add((f.TypeId, f.Proxy.kind, p))
        names = {p for _, _, p in seen}
        for p in ("Length", "Tension", "Tolerance", "ResampleStep", "StartCurvature", "D",
                  "Edges", "Samples", "Scale", "Stiffness"):
            self.assertIn(p, names)

    def test_a_right_unit_drives_it(self):
        f = self.features[0]
        length = float(f.Length)
        self.sheet.set("A1", f"={length / 10} cm")
        self.sheet.set("B1", "=3 s")
        self.sheet.recompute()
        f.setExpression("Length", "Params.A1")
        self.doc.recompute()
        self.assertNotIn("Invalid", f.State, f.Status)
        self.assertAlmostEqual(float(f.Length), length, delta=1e-12)
        g = self.features[3]
        g.setExpression("ResampleStep", "Params.B1")
        self.doc.recompute()
        self.assertEqual(g.Status, "error: ResampleStep is bound to Params.B1 = "
                         "3.00 s: a resample step is in a "
                         "unit of length (e.g. '=12 cm') or a plain number (mm)")


if __name__ == "__main__":
    unittest.main()
