"""freecadcmd -t tests of what a copy's drift note says moved (QA23gui F3): after a duck was
dragged the spline's Status said 'The copy in Sketch ... is 33.5 mm off this curve (the
Sketcher moved it): Copy into again' though the copy was untouched and the FEATURE moved.
The copy keeps the points it was written through (geometry.WRITTEN, saved with the sketch):
the note says which moved, the copy, this curve or both."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import geometry as G
from freecad.elastica import spline as Sp

DUCKS = [(0, 0), (13.7, 4.1), (31.2, 7.9), (38.5, 9.4), (52.1, 12.3), (80.4, 10.2), (97.3, 3.1)]
CURVE = "(this curve changed since it was copied, the copy is where it was written): " \
    "Copy into again"
COPY = "(the Sketcher moved it): Copy into again"
BOTH = "(the Sketcher moved it, and this curve changed since it was copied): Copy into again"


class CopyDriftWordsTest(S.DocTest):
    doc_name = "ElasticaCopyDriftWords"

    def setUp(self):
        super().setUp()
        self.ducks = S.points_sketch(self.doc, DUCKS, "Ducks")
        self.sp = Sp.make(self.doc, [(self.ducks, [])])
        self.doc.recompute()
        self.ok = self.sp.Status
        self.copy = self.doc.addObject("Sketcher::SketchObject", "Outline")
        self.copy.Placement = self.sp.Plane
        self.i = G.write_to_sketch(self.sp, self.copy)[0]
        self.doc.recompute()
        self.assertEqual(self.sp.Status, self.ok)

    def drag_duck(self, k=3, dy=6.0):
        p = self.ducks.Geometry[k]
        self.ducks.movePoint(k, 1, App.Vector(p.X, p.Y + dy, 0))
        self.doc.recompute()

    def drag_copy(self, dy=3.0):
        start = self.copy.Geometry[self.i].StartPoint
        self.copy.movePoint(self.i, 1, start + App.Vector(0, dy, 0))
        self.doc.recompute()

    def said(self):
        self.assertIn(". The copy in Sketch 'Outline' is ", self.sp.Status)
        return "(" + self.sp.Status.rsplit(" (", 1)[1]     # after the figures

    def test_a_duck_dragged_says_this_curve_changed(self):
        """QA's case: the copy untouched, a duck dragged 6 mm."""
        self.drag_duck()
        self.assertEqual(self.said(), CURVE)
        self.assertNotIn("Sketcher", self.sp.Status)

    def test_the_copy_dragged_says_the_sketcher_moved_it(self):
        self.drag_copy()
        self.assertEqual(self.said(), COPY)

    def test_both_moved_says_both(self):
        self.drag_copy()
        self.drag_duck()
        self.assertEqual(self.said(), BOTH)

    def test_a_reopened_document_still_tells_them_apart(self):
        sp, ducks, copy = S.reopened(self, "words.FCStd", self.sp.Name, "Ducks", "Outline")
        self.sp, self.ducks, self.copy = sp, ducks, copy
        self.drag_duck()
        self.assertEqual(self.said(), CURVE)
        G.write_to_sketch(sp, copy)             # Copy into again: said no more
        self.doc.recompute()
        self.assertNotIn("The copy in", sp.Status)
        self.drag_copy()
        self.assertEqual(self.said(), COPY)
