"""freecadcmd -t tests of a Hermite blend's Solution picked by the designer (property
editor, macro) after the document was saved and opened again (QA17 W0): the pick is shown,
not read as an edge move, while a real move still follows the picked shape; a picked loop
is followed only into a curve turning as many times (QA18gui F1)."""
import math

import FreeCAD as App
import Part

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
        """It was (counted from 0): Solution = 2 -> Solution 0, 'solution 1 of 4 (solution 3
        before the edges moved)' and solution 1's shape drawn, though no edge moved. The pick then
        follows its shape as the arc moves (1, 5, 20 mm), and where that is gone (60 mm
        more) the lowest energy is shown."""
        import numpy as np
        b, sk = self.reopened()
        b.Solution = 3
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (3, "solution 3 of 4"))
        self.assertAlmostEqual(self.shown_energy(b), b.Energies[2], delta=1e-6 * b.Energies[2])
        for dx in (1, 5, 20, 60):
            shown = Bl.turning(b.Proxy.plane_curves(b)[0])
            c = sk.Geometry[1].Center
            sk.movePoint(1, 3, App.Vector(c.x + dx, c.y, 0))
            self.doc.recompute()
            if dx < 60:
                self.assertEqual((b.Solution, b.Status), (3, "solution 3 of 4"), dx)
                d = Bl.turning(b.Proxy.plane_curves(b)[0]) - shown
                self.assertLess(float(np.sqrt(np.mean((d - d.mean()) ** 2))), Bl.SAME_SHAPE)
        self.assertEqual((b.Solution, b.Status), (1, "solution 1 of 4 (the lowest energy: "
                                                     "solution 3's shape is gone with the "
                                                     "edges' move)"))

    def test_a_pick_out_of_range_after_reopening_is_refused(self):
        """It was silently solution 1, '(solution 100 before the edges moved)'."""
        b, _ = self.reopened()
        b.Solution = 99
        self.doc.recompute()
        self.assertEqual(b.Solution, 99)
        self.assertEqual(b.Status, "error: Solution = 99: there are 4 solutions (1 to 4)")


class BlendLoopFollowTest(S.DocTest):
    """QA18gui F1: a blend under tension from a smooth fit's end to a line, the designer's
    pick a clockwise near-full loop (solution 2, 448 mm, turning -5.38 rad), the fit's
    last sketch point moved."""
    doc_name = "ElasticaBlendLoopFollowTest"

    def setUp(self):
        from freecad.elastica import commands as C
        super().setUp()
        xy = S.keyline_xy(14)[0]
        self.sk = S.points_sketch(self.doc, xy, "Src")
        fit = C.fit_sources([(self.sk, [])], open_panel=False, Model="smooth")
        self.doc.recompute()
        end = fit.Shape.Edges[-1].Vertexes[-1].Point
        to_sketch = self.sk.Placement.inverse()
        a = to_sketch.multVec(end + App.Vector(60, 40, 0))
        b = to_sketch.multVec(end + App.Vector(110, 50, 0))
        line = self.doc.addObject("Sketcher::SketchObject", "Line")
        line.Placement = self.sk.Placement
        line.addGeometry(Part.LineSegment(App.Vector(a.x, a.y, 0), App.Vector(b.x, b.y, 0)),
                         False)
        self.doc.recompute()
        self.b = C.blend_sources([(fit, ["Edge1"]), (line, ["Edge1"])], open_panel=False)
        self.b.Mode, self.b.Tension = "tension", 0.0002
        self.doc.recompute()
        self.b.Solution = 2
        self.doc.recompute()
        self.last = len(xy) - 1
        self.start = App.Vector(self.sk.Geometry[self.last].X, self.sk.Geometry[self.last].Y, 0)
        self.assertEqual(self.b.Status, "solution 2 of 4")
        self.assertAlmostEqual(self.shown_turn(), -5.383, delta=1e-3)
        self.assertEqual(self.b.Loops[1], 0)
        self.assertIn("0 loops, turns 308.40\u00b0 clockwise,", self.b.Descriptions[1])

    def shown_turn(self):
        return Bl.total_turn(self.b.Proxy.plane_curves(self.b)[0])

    def move(self, dx, dy):
        self.sk.movePoint(self.last, 1, self.start + App.Vector(dx, dy, 0))
        self.doc.recompute()

    def followed_or_gone(self, turn, change):
        """After a move: the curve shown turns within ``change`` of ``turn`` (the pick
        followed), or where no solution turns within pi of it, the lowest energy, said gone.
        The solver decides which: el.hermite returns no curve turning past a full turn
        (a clockwise loop turning -6.6 rad is missing, its mirror +5.97 returned), so here
        the clockwise loop leaves the solutions as it turns past -2 pi; the counter-
        clockwise loop then listed is never shown for it."""
        same = [i + 1 for i, t in enumerate(self.b.Turns) if abs(t - turn) < math.pi]
        if same:
            self.assertIn(self.b.Solution, same, self.b.Status)
            self.assertNotIn("gone", self.b.Status)
            self.assertLess(abs(self.shown_turn() - turn), change)
        else:
            self.assertEqual((self.b.Solution, self.b.Status),
                             (1, "solution 1 of 4 (the lowest energy: solution 2's shape is "
                                 "gone with the edges' move)"))
        mirror = [i for i, t in enumerate(self.b.Turns) if t > math.pi]
        self.assertEqual(len(mirror), 1, list(self.b.Turns))
        self.assertNotEqual(self.b.Solution, mirror[0] + 1)
        self.assertIn("1 loop, turns ", self.b.Descriptions[mirror[0]])
        self.assertIn("\u00b0 counter-clockwise,", self.b.Descriptions[mirror[0]])
        return same

    def test_a_loop_is_not_followed_into_an_s(self):
        """In one move of (25, 30) mm the clockwise loop is gone (its mirror, turning
        +6.03 rad, is the only loop left): the lowest energy, said so. It was 'solution 3
        of 4 (solution 2 before the edges moved)', a 655.7 mm S turning -0.25 rad (turning
        rms 0.955 from the loop, within SAME_SHAPE), and the features downstream followed
        that."""
        self.move(25, 30)
        self.followed_or_gone(-5.383, 1.5)          # the ends' tangents turn 1.15 rad

    def test_a_loop_moved_step_by_step_is_followed_while_it_turns_as_many_times(self):
        """In steps the loop is followed (452.4, 451.9, 453.9 mm), its turn changing by
        0.3 rad at most a step and its self-crossings from 0 to 1 (no invariant of a
        solution followed); at (20, 24) mm its turn would pass -2 pi: gone from the
        solutions (followed_or_gone), the counter-clockwise loop listed is not shown."""
        turn, loops = self.shown_turn(), []
        for step, length in zip(((5, 8), (10, 12), (15, 18)), (452.4, 451.9, 453.9)):
            self.move(*step)
            self.assertEqual((self.b.Solution, self.b.Status), (2, "solution 2 of 4"), step)
            self.assertAlmostEqual(self.b.Lengths[1], length, delta=0.05)
            self.assertLess(abs(self.shown_turn() - turn), 0.3)
            turn = self.shown_turn()
            loops.append(self.b.Loops[1])
        self.assertEqual(loops, [0, 0, 1])
        self.move(20, 24)
        self.followed_or_gone(turn, 0.3)
