"""freecadcmd -t test of a blend's Solution bound to a Spreadsheet cell (QA19gui F6): it counts
as the panel's list and Status do, from 1 (a cell's 2 picked the list's '3: ...'); FreeCAD's
rule, a bound property is written by its expression only: neither an edit of the blend's
parameters (which resets a picked Solution to 1) nor its follow of a picked shape as the
edges move writes it; a document of version 3 (Solution from 0) opens with its value and
expression one up."""
import base64
import json
import re
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend, proxy as X
from test_elastica_fit import rewrite_document


class BoundSolutionTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("BlendBound")
        self.cell = self.doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
        self.cell.set("A1", "3")
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
        self.assertEqual((b.Solution, b.Status), (3, "solution 3 of 4"))   # main: 4 of 4
        self.assertAlmostEqual(b.Shape.Length, b.Lengths[2], delta=1e-3)
        b.Tension = 0.0011                 # main: reset to 0 over the cell's value
        self.assertEqual(b.Solution, 3)
        self.doc.recompute()
        self.assertEqual(b.Solution, 3)
        self.assertEqual(dict(b.ExpressionEngine)["Solution"], "Spreadsheet.A1")

    def test_an_edge_move_keeps_the_bound_index_and_says_why_it_is_refused(self):
        b = self.b
        self.sk.movePoint(1, 1, App.Vector(85, 28, 0))      # two solutions left
        self.doc.recompute()
        # main: Solution 0 written over the cell's value, "solution 1 of 2"
        self.assertEqual(b.Solution, 3)
        self.assertIn("Invalid", b.State)
        self.assertEqual(b.Status, "error: Solution = 3: there are 2 solutions (1 to 2)")
        self.cell.set("A1", "2")
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (2, "solution 2 of 2"))
        self.assertNotIn("Invalid", b.State)

    def test_a_document_counting_from_0_opens_counting_from_1(self):
        """A file as version 3 saved it (its proxies' version 3; Solution 2 and
        'Spreadsheet.A1 - 1' for the list's solution 3, Solution 1 for its solution 2),
        reopened: counting from 1, its expression kept naming the cell's solution,
        untouched."""
        other = blend.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="tension",
                           Tension=0.001)
        self.doc.recompute()
        other.Solution = 2
        self.doc.recompute()
        self.assertEqual((self.b.Status, other.Status), ("solution 3 of 4", "solution 2 of 4"))
        shapes = [f.Shape.Length for f in (self.b, other)]
        names = (self.b.Name, other.Name)
        path = S.temp_path(self, "saved.FCStd")
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        old = path.replace("saved", "older")
        rewrite_document(path, old, self._as_version_3)
        self.doc = App.openDocument(old)
        b, other = (self.doc.getObject(n) for n in names)
        for f in (b, other):
            self.assertNotIn("Touched", f.State, f.Label)
        self.assertEqual(dict(b.ExpressionEngine)["Solution"], "Spreadsheet.A1 - 1 + 1")
        self.assertEqual((b.Solution, other.Solution), (3, 2))
        for f in (b, other):
            f.touch()
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (3, "solution 3 of 4"))
        self.assertEqual((other.Solution, other.Status), (2, "solution 2 of 4"))
        for f, length in zip((b, other), shapes):     # the reopened edges' ulps
            self.assertAlmostEqual(f.Shape.Length, length, delta=1e-12 * length)
        path = S.temp_path(self, "again.FCStd")         # once: saved counting from 1
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        self.doc = App.openDocument(path)
        b, other = (self.doc.getObject(n) for n in names)
        self.assertEqual((b.Solution, other.Solution), (3, 2))
        self.assertEqual(dict(b.ExpressionEngine)["Solution"], "Spreadsheet.A1 - 1 + 1")

    def _as_version_3(self, text):
        """Document.xml as version 3 wrote it: the blends' proxies of version 3, Solution
        (and its expression) counting from 0."""
        def proxy(m):
            state = json.loads(base64.b64decode(m.group(1)))
            self.assertEqual(state["version"], X.VERSION)       # written by this code
            state["version"] = 3
            return m.group(0).replace(m.group(1), base64.b64encode(
                json.dumps(state).encode()).decode())

        def solution(m):
            return m.group(1) + str(int(m.group(2)) - 1) + '"'
        text, n = re.subn(r'<Python value="([^"]*)" encoded="yes" '
                          r'module="freecad.elastica.blend"', proxy, text)
        self.assertEqual(n, 2)
        text, n = re.subn(r'(<Property name="Solution" type="App::PropertyInteger"[^>]*>\s*'
                          r'<Integer value=")(\d+)"', solution, text)
        self.assertEqual(n, 2)
        old = '<Expression path="Solution" expression="Spreadsheet.A1"/>'
        self.assertEqual(text.count(old), 1)
        return text.replace(old, old.replace("A1", "A1 - 1"))


if __name__ == "__main__":
    unittest.main()
