"""freecadcmd -t test: a length input bound to a spreadsheet cell of another unit, then set
right, survives Undo and Redo: the feature keeps its Length property and its expression. Each
cell edit is made with its recompute inside one transaction (as a recompute runs inside an
open task panel's transaction, or a GUI command's that sets and recomputes).
bound.restore_unit removed and added Length again inside that transaction: one Undo then left
the feature with no Length at all ("'FeaturePython' object has no attribute 'Length'", every
later recompute failing)."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend


class BoundUndoTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("BoundUndo")
        self.doc.UndoMode = 1
        self.sheet = self.doc.addObject("Spreadsheet::Sheet", "Params")
        lines = S.two_lines_sketch(self.doc)
        self.doc.recompute()
        self.f = blend.make(self.doc, (lines, "Edge1"), (lines, "Edge2"), Mode="length")
        self.doc.recompute()
        self.length = float(self.f.Length)
        self.sheet.set("A1", repr(self.length))
        self.doc.recompute()
        self.f.setExpression("Length", "Params.A1")
        self.doc.recompute()
        self.status = self.f.Status

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def edit_cell(self, text, name):
        self.doc.openTransaction(name)
        self.sheet.set("A1", text)
        self.doc.recompute()
        self.doc.commitTransaction()

    def check(self, where, length, ok):
        f = self.f
        self.assertIn("Length", f.PropertiesList, where)
        self.assertEqual(f.ExpressionEngine, [("Length", "Params.A1")], where)
        self.doc.recompute()
        self.assertAlmostEqual(float(f.Length), length, delta=1e-12, msg=where)
        self.assertEqual(f.Status.startswith("error"), not ok, (where, f.Status))

    def test_undo_redo_after_a_wrong_unit(self):
        self.edit_cell("=0.002 / mm^2", "wrong")
        self.assertTrue(self.f.Status.startswith("error: Length is bound to"), self.f.Status)
        self.edit_cell(repr(self.length), "right")
        self.check("right", self.length, True)
        self.assertEqual(self.f.Status, self.status)
        self.doc.undo()                 # back to the wrong cell
        self.check("undo", 0.002, False)
        self.doc.redo()
        self.check("redo", self.length, True)
        self.doc.undo()
        self.doc.undo()                 # back to the cell before either edit
        self.check("undo x2", self.length, True)
        self.doc.redo()
        self.doc.redo()
        self.check("redo x2", self.length, True)
        self.assertEqual(self.f.Status, self.status)


if __name__ == "__main__":
    unittest.main()
