"""freecadcmd -t tests of a switch of 'Solve for' (length <-> tension) in the spline's and
the blend's panels (QA23gui F2): the new mode starts from the curve on screen and keeps it,
as a Pad's Type switch keeps the shape, where the library has it; where it cannot (a
spline pushed together by length has no tension >= 0 twin) Status and the report view say so.
The panels' own changed() copies the value (called on a stand-in for the panel: the feature
is what recomputes)."""
import types

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import spline as Sp
from freecad.elastica import taskpanels as T
from test_elastica_blend_redo import chain_sketch

# QA23gui's ducks (len_sweep.py): by length the tension falls below 0 near 238 mm and rises
# again; by tension 6.26e-4 /mm^2 the library's own start reaches a 225.6 mm spline, not the
# 272.1 mm one of that tension
DUCKS = [(0, 0), (13.7, 4.1), (31.2, 7.9), (38.5, 9.4), (52.1, 12.3), (80.4, 60.0), (97.3, 3.1),
         (104.9, -1.8), (140.2, -9.6)]


def refuse_spline_solves(case, keyword):
    """For the rest of the test ``case``: el.elastic_spline refuses (NotConvergedError, a
    stand-in) every call given ``keyword`` (initial=, length=), solves the others."""
    from freecad.elastica import geometry as G
    e = G.el()
    solve = e.elastic_spline

    def refused(*args, **kw):
        if kw.get(keyword) is not None:
            raise e.NotConvergedError(e.lib.EL_ENOCONV if hasattr(e, "lib") else 3,
                                      "elastic_spline: no convergence (stand-in)")
        return solve(*args, **kw)
    e.elastic_spline = refused
    case.addCleanup(setattr, e, "elastic_spline", solve)


def switch(panel_class, obj, mode):
    """Solve for = mode as the panel sets it: the property, then the panel's changed()."""
    stand_in = types.SimpleNamespace(obj=obj, note="", auto=None, picked=None,
                                     show_mode=lambda: None,
                                     expression=lambda prop: "")
    obj.Mode = mode
    panel_class.changed(stand_in, "Mode")
    obj.Document.recompute()


class SplineModeSwitchTest(S.DocTest):
    doc_name = "ElasticaSplineModeSwitchTest"

    def spline(self, length):
        sk = S.points_sketch(self.doc, DUCKS)
        s = Sp.make(self.doc, [(sk, [])], Mode="length", Length=length)
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        self.assertAlmostEqual(s.SplineLength, length, delta=1e-9 * length)
        return s

    def test_length_to_tension_keeps_the_spline_on_screen(self):
        """It was: 272.104 mm by length -> tension mode at its tension 6.2555e-4: a 225.578 mm
        spline (another branch of that tension), the curve off its padded copy."""
        s = self.spline(272.104)
        poles = [tuple(p) for p in s.Shape.Edges[0].Curve.getPoles()]
        switch(T.SplinePanel, s, "tension")
        self.assertEqual(float(s.Tension), s.SplineTension)
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        self.assertIn("the spline shown kept (272.10 mm), though another spline of this "
                      "tension through the points is 225.58 mm long", s.Status)
        new = s.Shape.Edges[0].Curve.getPoles()
        self.assertEqual(len(new), len(poles))
        self.assertLess(max((a - App.Vector(*b)).Length for a, b in zip(new, poles)), 1e-6)
        # kept on the next recompute and in the file reopened (the library alone: 225.6 mm)
        s.touch()
        self.doc.recompute()
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        s, = S.reopened(self, "switch.FCStd", s.Name)
        s.touch()
        self.doc.recompute()
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)
        # back to length: the same length
        switch(T.SplinePanel, s, "length")
        self.assertAlmostEqual(s.SplineLength, 272.104, delta=1e-6 * 272.104)

    def test_a_typed_tension_is_a_new_problem(self):
        """A tension typed after the switch solves from the library's own start (as before)."""
        s = self.spline(272.104)
        switch(T.SplinePanel, s, "tension")
        s.Tension = 6.3e-4
        self.doc.recompute()
        self.assertNotIn("kept", s.Status)
        self.assertLess(s.SplineLength, 230.0)

    def test_a_pushed_spline_says_tension_mode_cannot_keep_it(self):
        """It was: 230 mm by length (tension -3.38e-4) -> tension mode solved at Tension 0,
        226.8 mm, nothing said."""
        s = self.spline(230.0)
        self.assertLess(s.SplineTension, 0.0)
        said, _ = S.console_output(lambda: switch(T.SplinePanel, s, "tension"))
        self.assertEqual(float(s.Tension), 0.0)
        self.assertIn("was pushed together", s.Status)
        self.assertIn(f"Elastica {s.Label}: the spline shown by length (230.00 mm) was pushed "
                      "together", said)           # the report view
        self.assertIn("tension mode cannot keep it and solved at Tension = 0.00 1/mm\u00b2 instead "
                      "(Solve for a length keeps it)", s.Status)
        self.assertAlmostEqual(s.SplineLength, 226.7535, delta=1e-3)


class BlendModeSwitchTest(S.DocTest):
    doc_name = "ElasticaBlendModeSwitchTest"

    def test_length_to_tension_keeps_the_solution_on_screen(self):
        """It was: G1, Length 120, solution 1 -> tension mode: 67.8 mm (onChanged's reset to
        the lowest energy of that tension); solution 2: 78.2 mm. The library lists the 120 mm
        curve at the shown tension: it is kept, and back by length too."""
        for picked in (1, 2):
            sk = chain_sketch(self.doc)
            b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="length", Length=120.0)
            self.doc.recompute()
            b.Solution = picked
            self.doc.recompute()
            shown = Bl.bending_energy(b.Proxy.plane_curves(b)[0][0])
            switch(T.BlendPanel, b, "tension")
            self.assertEqual(float(b.Tension), b.BlendTension)
            self.assertTrue(b.Status.startswith("solution"), b.Status)
            self.assertAlmostEqual(b.BlendLength, 120.0, delta=1e-6 * 120, msg=picked)
            self.assertAlmostEqual(Bl.bending_energy(b.Proxy.plane_curves(b)[0][0]), shown,
                                   delta=1e-6 * shown)
            self.assertEqual(b.Status, f"solution {b.Solution} of {len(b.Energies)}")
            switch(T.BlendPanel, b, "length")
            self.assertAlmostEqual(b.BlendLength, 120.0, delta=1e-6 * 120, msg=picked)
            self.assertEqual(b.Solution, picked)
            self.doc.removeObject(b.Name)
            self.doc.removeObject(sk.Name)


class SplineNotFoundAgainTest(S.DocTest):
    """Where the solve from the shown spline does not reach it again at its tension (the
    library's Newton from its pieces refused here by a stand-in), the switch says so in
    Status and the report view: it showed the other spline silently."""
    doc_name = "ElasticaSplineNotFoundAgainTest"

    def test_a_shown_spline_not_found_again_is_said(self):
        sk = S.points_sketch(self.doc, DUCKS)
        s = Sp.make(self.doc, [(sk, [])], Mode="length", Length=272.104)
        self.doc.recompute()
        refuse_spline_solves(self, "initial")
        said, _ = S.console_output(lambda: switch(T.SplinePanel, s, "tension"))
        self.assertAlmostEqual(s.SplineLength, 225.578, delta=1e-3)
        words = ("the spline shown (272.10 mm) was not found again at this tension (solved "
                 "from it), so another spline of this tension through the points is shown, "
                 "225.58 mm long (Solve for a length keeps the one shown)")
        self.assertIn(words, s.Status)
        self.assertIn(words, said)
        # a tension typed next is a new problem: nothing said
        s.Tension = 6.3e-4
        self.doc.recompute()
        self.assertNotIn("not found again", s.Status)
