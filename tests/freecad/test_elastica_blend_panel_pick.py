"""freecadcmd -t tests of a blend's Solution picked in an earlier panel session, then a
length typed in a panel opened again (QA23gui F5): the pick was dropped ('solution 1 of 4'
at 130 mm) while one made in the same session is re-applied; it is kept the same way.
The panel runs without its widgets (BlendPanel.__new__, as test_elastica_new_sketch_body's
OK code): its build's pick and its live update are what is tested."""

import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import taskpanels as T
from test_elastica_blend_redo import chain_sketch


def reopened_panel(b):
    """A BlendPanel on ``b`` as build() starts it, without widgets."""
    p = T.BlendPanel.__new__(T.BlendPanel)
    p.obj, p.doc = b, b.Document
    p.refresh = p.refit = lambda: None
    p.picked = p.saved_pick()           # build()'s
    return p


class BlendPanelPickTest(S.DocTest):
    doc_name = "ElasticaBlendPanelPickTest"

    def setUp(self):
        super().setUp()
        sk = chain_sketch(self.doc)
        self.b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="length", Length=120.0)
        self.doc.recompute()
        self.b.Solution = 2             # picked in an earlier panel session, OK
        self.doc.recompute()
        self.assertEqual(self.b.Status, "solution 2 of 4")

    def test_a_pick_of_an_earlier_session_survives_a_typed_length(self):
        b = self.b
        p = reopened_panel(b)
        b.Length = 130.0                # typed (set, then the live update)
        p.update()
        self.assertEqual((b.Solution, b.Status), (2, f"solution 2 of {len(b.Energies)}"))
        b.Length = 125.0
        p.update()
        self.assertEqual(b.Solution, 2)

    def test_the_lowest_or_a_bound_solution_is_no_pick(self):
        b = self.b
        b.setExpression("Solution", "1 + 1")
        self.doc.recompute()
        self.assertIsNone(reopened_panel(b).picked)
        b.setExpression("Solution", None)
        b.Solution = 1
        self.doc.recompute()
        self.assertIsNone(reopened_panel(b).picked)
