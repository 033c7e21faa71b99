"""freecadcmd -t tests of a Hermite blend's picked Solution through Undo and Redo (QA23gui
F1): Redo restores every property of the step, the picked solution with the length it was
picked at, as a Pad's Redo restores its Length and Type alike."""
import math

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend as Bl


def chain_sketch(doc):
    """QA23gui's chain: a line ending at (0, 0) and an arc R25 about (60, 30) from 180 to
    300 degrees (no free G1 batten joins them: the command starts by length)."""
    sk = doc.addObject("Sketcher::SketchObject", "Chain")
    sk.addGeometry(Part.LineSegment(App.Vector(-60, 0, 0), App.Vector(0, 0, 0)), False)
    sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(60, 30, 0), App.Vector(0, 0, 1), 25),
                                    math.radians(180), math.radians(300)), False)
    doc.recompute()
    return sk


class BlendRedoPickTest(S.DocTest):
    doc_name = "ElasticaBlendRedoTest"

    def step(self, name, **props):
        """One Undo step, as the panel's OK makes it: the properties set, recomputed."""
        self.doc.openTransaction(name)
        for k, v in props.items():
            setattr(self.b, k, v)
            self.doc.recompute()
        self.doc.commitTransaction()

    def setUp(self):
        super().setUp()
        self.doc.UndoMode = 1
        self.sk = chain_sketch(self.doc)
        self.doc.openTransaction("Blend")
        self.b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="length",
                         Length=69.1)
        self.doc.recompute()
        self.doc.commitTransaction()

    def shown(self):
        return Bl.bending_energy(self.b.Proxy.plane_curves(self.b)[0][0])

    def test_redo_restores_the_picked_solution(self):
        """It was: after Undo, Redo, Solution = 1 while Status said 'solution 2 of 4' and
        the Shape was solution 2's; the next recompute drew solution 1 (onChanged's reset on
        the Length Redo restores after Solution)."""
        b = self.b
        self.step("Edit blend", Length=120.0, Solution=2)
        self.assertGreater(len(b.Energies), 2, b.Status)
        self.assertEqual((b.Solution, b.Status), (2, f"solution 2 of {len(b.Energies)}"))
        poles = [tuple(p) for p in b.Shape.Edges[0].Curve.getPoles()]
        picked = self.shown()
        self.assertAlmostEqual(picked, b.Energies[1], delta=1e-9 * picked)
        self.doc.undo()
        self.assertEqual((b.Solution, float(b.Length)), (1, 69.1))
        self.doc.redo()
        self.assertEqual((b.Solution, float(b.Length)), (2, 120.0))
        self.assertEqual([tuple(p) for p in b.Shape.Edges[0].Curve.getPoles()], poles)
        # the next recompute (an edit upstream) draws the same solution
        self.sk.touch()
        self.doc.recompute()
        self.assertEqual((b.Solution, b.Status), (2, f"solution 2 of {len(b.Energies)}"))
        self.assertAlmostEqual(self.shown(), picked, delta=1e-9 * picked)

    def test_an_edit_after_redo_still_resets_the_pick(self):
        """The reset stays for the designer's own edit after Redo (a new problem: lowest
        energy)."""
        b = self.b
        self.step("Edit blend", Length=120.0, Solution=2)
        self.doc.undo()
        self.doc.redo()
        self.step("Length 130", Length=130.0)
        self.assertEqual(b.Solution, 1)
        self.assertTrue(b.Status.startswith("solution 1 of"), b.Status)
