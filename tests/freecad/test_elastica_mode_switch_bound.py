"""freecadcmd -t test of a switch of 'Solve for' on a blend whose Solution is bound to an
expression (revB's review of QA23gui F2's fix): the expression alone sets Solution
(FreeCAD's rule, QA19gui F6), so the shape drawn and Status are the expression's solution,
not the one of the shape shown before the switch (_kept_shown)."""
import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import taskpanels as T
from test_elastica_blend_redo import chain_sketch
from test_elastica_mode_switch import switch


class BoundSolutionSwitchTest(S.DocTest):
    doc_name = "ElasticaBoundSolutionSwitchTest"

    def test_a_bound_solution_is_drawn_after_a_switch(self):
        """It was: Solution = '1 + 1' at Length 120 -> tension mode: Solution 2 but solution 4
        drawn (the 120 mm curve), Status 'solution 4 of 4 (solution 2 before the edges
        moved)' though no edge moved."""
        sk = chain_sketch(self.doc)
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="length", Length=120.0)
        self.doc.recompute()
        b.setExpression("Solution", "1 + 1")
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (2, "solution 2 of 4"))
        switch(T.BlendPanel, b, "tension")
        self.assertEqual(b.Solution, 2)
        self.assertEqual(b.Status, f"solution 2 of {len(b.Lengths)}")
        self.assertEqual(b.BlendLength, b.Lengths[1])     # the shape drawn is solution 2's
        drawn = b.Shape.Edges[0].Length
        self.assertAlmostEqual(drawn, b.Lengths[1], delta=1e-3 * b.Lengths[1])
