"""freecadcmd -t tests of a Hermite blend's Solution picked by the designer (property
editor, macro) after the document was saved and opened again (QA17 W0): the pick is shown,
not read as an edge move, while a real move still follows the picked shape."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl


class BlendPickTest(S.DocTest):
    doc_name = "ElasticaBlendPickTest"

    def setUp(self):
        super().setUp()
        # line -> arc, 113 mm: 4 solutions (the command's length for these edges)
        sk = S.line_and_arc_sketch(self.doc)
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="length", Length=113.0)
        self.doc.recompute()
        self.assertEqual(len(b.Energies), 4, b.Status)

    def reopened(self):
        b, sk = S.reopened(self, "pick.FCStd", "ElasticaBlend", "LineArc")
        # the reopened edges differ from the saved ones by an ulp (the arc's end), so do the
        # solutions' energies: the mistaken 'edges moved'
        self.assertEqual(b.State, ["Up-to-date"])
        sk.solve()                  # the sketch's solver set up (movePoint), nothing touched
        return b, sk

    def shown_energy(self, b):
        return Bl.bending_energy(b.Proxy.plane_curves(b)[0][0])

    def test_a_pick_after_reopening_is_shown_and_follows_the_edges(self):
        """It was: Solution = 2 -> Solution 0, 'solution 1 of 4 (solution 3 before the
        edges moved)' and solution 1's shape drawn, though no edge moved. The pick then
        follows its shape as the arc moves (1, 5, 20 mm), and where that is gone (60 mm
        more) the lowest energy is shown."""
        import numpy as np
        b, sk = self.reopened()
        b.Solution = 2
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (2, "solution 3 of 4"))
        self.assertAlmostEqual(self.shown_energy(b), b.Energies[2], delta=1e-6 * b.Energies[2])
        for dx in (1, 5, 20, 60):
            shown = Bl.turning(b.Proxy.plane_curves(b)[0])
            c = sk.Geometry[1].Center
            sk.movePoint(1, 3, App.Vector(c.x + dx, c.y, 0))
            self.doc.recompute()
            if dx < 60:
                self.assertEqual((b.Solution, b.Status), (2, "solution 3 of 4"), dx)
                d = Bl.turning(b.Proxy.plane_curves(b)[0]) - shown
                self.assertLess(float(np.sqrt(np.mean((d - d.mean()) ** 2))), Bl.SAME_SHAPE)
        self.assertEqual((b.Solution, b.Status), (0, "solution 1 of 4 (the lowest energy: "
                                                     "solution 3's shape is gone with the "
                                                     "edges' move)"))

    def test_a_pick_out_of_range_after_reopening_is_refused(self):
        """It was silently solution 1, '(solution 100 before the edges moved)'."""
        b, _ = self.reopened()
        b.Solution = 99
        self.doc.recompute()
        self.assertEqual(b.Solution, 99)
        self.assertEqual(b.Status, "error: Solution = 99: there are 4 solutions (0 to 3)")
