"""freecadcmd -t test of a blend asked between edges of two documents (QA19gui F5): the
command says in words that both edges must be in one document, the active one (it printed
FreeCAD's raw exception dict, 'PropertyLinkSub does not support external object'), and
leaves both documents unchanged; so do the other commands that link what they read (an
elastic spline through another document's points printed the same raw exception)."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import commands as C


class BlendDocumentsTest(unittest.TestCase):
    def setUp(self):
        self.a, self.b = App.newDocument("BlendDocA"), App.newDocument("BlendDocB")
        self.la = self._line(self.a, "LA", (0, 0, 0), (40, 0, 0))
        self.lb = self._line(self.b, "LB", (80, 25, 0), (120, 35, 0))
        self.lb2 = self._line(self.b, "LB2", (0, 0, 0), (40, 0, 0))
        App.setActiveDocument(self.a.Name)

    def tearDown(self):
        for d in (self.a, self.b):
            App.closeDocument(d.Name)

    @staticmethod
    def _line(doc, name, p, q):
        line = doc.addObject("Part::Line", name)
        line.X1, line.Y1, line.Z1 = p
        line.X2, line.Y2, line.Z2 = q
        doc.recompute()
        return line

    def _said(self, sources, command=C.blend_sources):
        said = []
        before = [len(d.Objects) for d in (self.a, self.b)]
        made = command(sources, open_panel=False, wrong=said.append)
        self.assertIsNone(made)
        self.assertEqual([len(d.Objects) for d in (self.a, self.b)], before)
        return said

    def test_two_documents_are_refused_in_words(self):
        said = self._said([(self.la, ["Edge1"]), (self.lb, ["Edge1"])])
        a, b = self.a.Label, self.b.Label
        self.assertEqual(said, [f"the two edges are in documents '{a}' and '{b}': a blend "
                                "links both edges, so they must be in one document, the active "
                                f"one ('{a}'); copy an edge into it (Edit > Copy, Paste)"])

    def test_edges_of_another_document_than_the_active_one_too(self):
        said = self._said([(self.lb2, ["Edge1"]), (self.lb, ["Edge1"])])
        a, b = self.a.Label, self.b.Label
        self.assertEqual(said, [f"the two edges are in document '{b}': a blend links both "
                                "edges, so they must be in one document, the active one "
                                f"('{a}'); copy an edge into it (Edit > Copy, Paste)"])

    def test_a_spline_through_another_documents_points_too(self):
        pts = S.points_sketch(self.b, S.keyline_xy(8)[0])
        self.b.recompute()
        App.setActiveDocument(self.a.Name)
        said = self._said([(pts, [])], C.spline_sources)
        a, b = self.a.Label, self.b.Label
        # main: no word said, FreeCAD's 'PropertyLinkSubList does not support external
        # object' printed
        self.assertEqual(said, [f"the selection is in document '{b}': the new feature links "
                                "what it reads, so that must be in the active document "
                                f"('{a}'); copy it there (Edit > Copy, Paste)"])


if __name__ == "__main__":
    unittest.main()
