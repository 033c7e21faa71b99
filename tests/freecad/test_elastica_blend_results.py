"""freecadcmd -t tests of what an Elastic blend's result lists say: a tension at rounding
noise is 0 (QA18gui F9), and which way a solution turning half a turn or more goes, so a
loop and its mirror image read differently (QA18gui F1's note)."""
import math

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl


class BlendResultsTest(S.DocTest):
    doc_name = "ElasticaBlendResultsTest"

    def setUp(self):
        super().setUp()
        self.sk = S.two_lines_sketch(self.doc)

    def test_by_the_free_battens_own_length_the_tension_is_0(self):
        """Solved for the free batten's own length (0, or the length shown typed back) the
        solver's tension is rounding noise, 1.1e-16/mm^2: Tensions and BlendTension say 0
        (the panel's Tension box showed 1.106e-16 1/mm^2, and a switch to tension mode took
        it as the tension asked); the other solutions' tensions are the solver's."""
        free = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"))
        self.doc.recompute()
        for length in (0.0, free.BlendLength):
            b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="length",
                        Length=length)
            self.doc.recompute()
            e1, e2 = b.Proxy.ends(b)
            r = Bl.blend_core(e1, b.AtEnd1, e2, b.AtEnd2, b.Proxy.sketch_plane(b), "length",
                              length)
            sigma = [float(c.sigma) for c in r["curves"]]
            self.assertNotEqual(sigma[0], 0.0)
            self.assertLess(abs(sigma[0]) * b.Lengths[0] ** 2, 1e-12)
            self.assertEqual((b.BlendTension, b.Tensions[0]), (0.0, 0.0), length)
            self.assertEqual(list(b.Tensions[1:]), sigma[1:])
            self.assertTrue(all(abs(t) * L ** 2 > 1e-3 for t, L in zip(sigma[1:], b.Lengths[1:])))

    def test_a_loop_says_which_way_it_turns(self):
        """Tension 0.0002: solution 2 is a clockwise near-full loop (no self-crossing);
        with the first line turned 20 degrees it is gone and its mirror image, of nearly
        the same length, turns counter-clockwise (QA18gui p6c: the list read the same but
        for '1 loop'). Turns: each solution's angle at its end less at its start (with the
        sign of the curvature of a curve without inflection); the texts name the way for
        turns of half a turn or more only, and the panel's texts (blend.descriptions) are
        the same."""
        import numpy as np
        b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Tension=0.0002)
        self.doc.recompute()
        seen = []
        for deg in (0, 20):
            a = math.radians(deg)
            self.sk.movePoint(0, 1, App.Vector(40 - 40 * math.cos(a), -40 * math.sin(a), 0))
            self.doc.recompute()
            e1, e2 = b.Proxy.ends(b)
            r = Bl.blend_core(e1, b.AtEnd1, e2, b.AtEnd2, b.Proxy.sketch_plane(b), "tension",
                              0.0002)
            for c, turn, infl, text in zip(r["curves"], b.Turns, b.Inflections, b.Descriptions):
                th = c.angle(np.linspace(0.0, c.length, 4001))
                self.assertAlmostEqual(turn, th[-1] - th[0], delta=1e-9)
                self.assertLess(float(np.max(np.abs(np.diff(th)))), 0.1)   # continuous
                if infl == 0:
                    self.assertTrue(np.all(np.sign(c.curvature(np.linspace(0, c.length, 9)))
                                           == np.sign(turn)))
                self.assertEqual("turns" in text, abs(turn) >= math.pi, text)
            self.assertEqual(Bl.descriptions(b), list(b.Descriptions))
            seen.append(b.Descriptions[1])
        self.assertEqual(seen, [
            "2: 448.74 mm, energy 0.17/mm, 0 inflections, 0 loops, turns 345.96\u00b0 "
            "clockwise, max curvature 0.018/mm",
            "2: 454.27 mm, energy 0.18/mm, 0 inflections, 1 loop, turns 354.04\u00b0 "
            "counter-clockwise, max curvature 0.017/mm"])
        # a file saved before Turns (none until its first recompute): the texts without it
        b.Turns = []
        self.assertEqual(Bl.descriptions(b)[1], "2: 454.27 mm, energy 0.18/mm, 0 inflections, "
                         "1 loop, max curvature 0.017/mm")
