"""freecadcmd -t test of a blend's Solution bound to a Spreadsheet cell (QA19gui F6): FreeCAD's
rule, a bound property is written by its expression only: neither an edit of the blend's
parameters (which resets a picked Solution to 0) nor its follow of a picked shape as the
edges move writes it; an index out of range is refused in both numberings."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend


class BoundSolutionTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("BlendBound")
        self.cell = self.doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
        self.cell.set("A1", "2")
        self.sk = S.two_lines_sketch(self.doc)
        self.b = blend.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="tension",
                            Tension=0.001)
        self.doc.recompute()
        self.assertEqual(len(self.b.Lengths), 4)          # QA's e4: four solutions
        self.b.setExpression("Solution", "Spreadsheet.A1")
        self.doc.recompute()

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def test_the_cell_picks_and_an_edit_does_not_reset_it(self):
        b = self.b
        self.assertEqual((b.Solution, b.Status), (2, "solution 3 of 4"))
        self.assertAlmostEqual(b.Shape.Length, b.Lengths[2], delta=1e-3)
        b.Tension = 0.0011                 # main: reset to 0 over the cell's 2
        self.assertEqual(b.Solution, 2)
        self.doc.recompute()
        self.assertEqual(b.Solution, 2)
        self.assertEqual(dict(b.ExpressionEngine)["Solution"], "Spreadsheet.A1")

    def test_an_edge_move_keeps_the_bound_index_and_says_why_it_is_refused(self):
        b = self.b
        self.sk.movePoint(1, 1, App.Vector(85, 28, 0))      # two solutions left
        self.doc.recompute()
        # main: Solution 0 written over the cell's 2, "solution 1 of 2"
        self.assertEqual(b.Solution, 2)
        self.assertIn("Invalid", b.State)
        self.assertEqual(b.Status, "error: Solution = 2 names solution 3: there are 2 "
                                   "solutions (Solution 0 to 1 for solutions 1 to 2)")
        self.cell.set("A1", "1")
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (1, "solution 2 of 2"))
        self.assertNotIn("Invalid", b.State)


if __name__ == "__main__":
    unittest.main()
