"""freecadcmd -t tests of a spline kept by a switch of 'Solve for' when a duck moves next
(revB F2): it was kept only while the ducks were bit-identical, so a 0.01 mm nudge of duck 5
showed the library's own 225.578 mm spline instead of the 272.104 mm one, Status 'ok',
nothing in the report view, and moving the duck back kept 225.578 mm. Now the kept spline
is followed (KeptShown, saved), or Status and the report view say why not."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import spline as Sp
from freecad.elastica import taskpanels as T
from test_elastica_mode_switch import DUCKS, refuse_spline_solves, switch


def nudge(sk, i, dx):
    sk.movePoint(i, 1, sk.getPoint(i, 1) + App.Vector(dx, 0, 0))
    sk.Document.recompute()


class SplineKeptNudgeTest(S.DocTest):
    doc_name = "ElasticaSplineKeptNudgeTest"

    def kept(self):
        sk = S.points_sketch(self.doc, DUCKS)
        s = Sp.make(self.doc, [(sk, [])], Mode="length", Length=272.104)
        self.doc.recompute()
        switch(T.SplinePanel, s, "tension")
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        self.assertTrue(s.KeptShown)
        return sk, s

    def test_a_nudged_duck_follows_the_kept_spline(self):
        sk, s = self.kept()
        tension = float(s.Tension)
        said, _ = S.console_output(lambda: nudge(sk, 5, 0.01))
        self.assertEqual(float(s.Tension), tension)
        self.assertAlmostEqual(s.SplineTension, tension, delta=1e-12)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=0.05)
        self.assertIn("the spline kept at the switch of Solve for followed to the moved points "
                      "(272.10 mm -> 272.", s.Status)
        self.assertIn("another spline of this tension through them is 225.5", s.Status)
        self.assertTrue(s.KeptShown)
        # back where it was: the same curve as before the nudge
        nudge(sk, 5, -0.01)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        # a larger move, and the file reopened: still followed (KeptShown is saved)
        nudge(sk, 5, 2.0)
        self.assertAlmostEqual(s.SplineLength, 271.21, delta=0.05)
        s, sk = S.reopened(self, "nudge.FCStd", s.Name, sk.Name)
        self.assertTrue(s.KeptShown)
        nudge(sk, 5, -2.0)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)

    def test_a_kept_spline_not_followed_is_said(self):
        """The by-length solve on the moved ducks refused (a stand-in): the library's own is
        shown, and Status and the report view say so; KeptShown is cleared."""
        sk, s = self.kept()
        refuse_spline_solves(self, "length")
        said, _ = S.console_output(lambda: nudge(sk, 5, 0.01))
        self.assertAlmostEqual(s.SplineLength, 225.58, delta=0.05)
        words = "the spline kept at the switch of Solve for (272.10 mm) could not be followed"
        self.assertIn(words, s.Status)
        self.assertIn(words, said)
        self.assertFalse(s.KeptShown)

    def test_a_drag_of_the_librarys_own_spline_is_a_fresh_solve(self):
        """A tension-mode spline never switched: each drag gives what a new spline at those
        ducks gives (no continuation from the shown one), KeptShown stays off."""
        sk = S.points_sketch(self.doc, DUCKS)
        s = Sp.make(self.doc, [(sk, [])], Mode="tension", Tension=6.2555e-4)
        self.doc.recompute()
        for dx in (0.01, 0.5, 2.0, 10.0):
            nudge(sk, 5, dx)
            fresh = Sp.make(self.doc, [(sk, [])], Mode="tension", Tension=6.2555e-4)
            self.doc.recompute()
            self.assertFalse(s.KeptShown)
            self.assertEqual(s.Curves, fresh.Curves, dx)
            self.assertEqual(s.Status, fresh.Status, dx)
            self.doc.removeObject(fresh.Name)

    def test_the_kept_spline_comes_back_after_a_recompute_that_failed(self):
        """A duck of the kept spline dragged onto its neighbour (no spline: the recompute
        fails, the last good curve kept on screen), then back: the next recompute took the
        failed one's Status to mean no curve was shown, solved afresh and showed the
        library's own 225.578 mm spline, Status 'ok', KeptShown cleared, nothing said. The
        curve on screen is still the kept one: it is kept again (or followed, or said)."""
        sk, s = self.kept()
        where = sk.getPoint(5, 1)
        sk.movePoint(5, 1, sk.getPoint(4, 1))
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("error"), s.Status)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)   # still shown
        sk.movePoint(5, 1, where)
        self.doc.recompute()
        self.assertFalse(s.Status.startswith("error"), s.Status)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        self.assertTrue(s.KeptShown)
        self.assertIn("the spline shown kept (272.10 mm)", s.Status)
        # dragged away and to a point near where it was: followed from the curve on screen
        sk.movePoint(5, 1, sk.getPoint(4, 1))
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("error"), s.Status)
        sk.movePoint(5, 1, where + App.Vector(0.5, 0, 0))
        self.doc.recompute()
        self.assertAlmostEqual(s.SplineLength, 271.87, delta=0.05)
        self.assertIn("the spline kept at the switch of Solve for followed to the moved points",
                      s.Status)
        self.assertTrue(s.KeptShown)

    def test_a_kept_spline_lost_after_a_failed_recompute_is_said(self):
        """As above, where the kept spline cannot be followed from the curve on screen (the
        by-length solve refused, a stand-in): the library's own is shown and it is said."""
        sk, s = self.kept()
        where = sk.getPoint(5, 1)
        sk.movePoint(5, 1, sk.getPoint(4, 1))
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("error"), s.Status)
        refuse_spline_solves(self, "length")
        said, _ = S.console_output(lambda: nudge_to(sk, 5, where + App.Vector(0.01, 0, 0)))
        self.assertAlmostEqual(s.SplineLength, 225.58, delta=0.05)
        words = "the spline kept at the switch of Solve for (272.10 mm) could not be followed"
        self.assertIn(words, s.Status)
        self.assertIn(words, said)
        self.assertFalse(s.KeptShown)


def nudge_to(sk, i, p):
    sk.movePoint(i, 1, p)
    sk.Document.recompute()
