"""Messages for input a command cannot take name what was selected (QA: a sketch of one
30 mm line through Fit said '2 points: a fit needs at least 6', a circle through Elastic
spline '1 point: an elastic spline needs at least 2': points nobody selected). Run with
`freecadcmd -t test_elastica_input_messages`."""
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C


class InputMessageTest(S.DocTest):
    doc_name = "ElasticaInputMessages"

    def rejected(self, make, sources):
        """The one message of a command refusing ``sources``, the document unchanged."""
        before = S.doc_state(self.doc)
        del C.MESSAGES[:]
        self.assertIsNone(make(sources, open_panel=False))
        self.assertEqual(len(C.MESSAGES), 1, C.MESSAGES)
        self.assertEqual(S.doc_state(self.doc), before)
        return C.MESSAGES[0]

    def line_sketch(self, *segments):
        sk = self.doc.addObject("Sketcher::SketchObject", "OneLine")
        for a, b in segments:
            sk.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*b, 0)), False)
        self.doc.recompute()
        return sk

    def test_a_fit_of_one_line_names_the_line_and_what_a_fit_takes(self):
        sk = self.line_sketch(((0, -20), (30, -20)))
        msg = self.rejected(C.fit_sources, [(sk, [])])
        self.assertNotIn("2 points", msg)
        self.assertIn("OneLine holds one straight line (30 mm)", msg)
        self.assertIn("a fit takes 6 points or more", msg)
        self.assertIn("curved edge", msg)
        # picked edges are named as a selection
        sk2 = self.line_sketch(((0, 0), (10, 0)), ((10, 0), (20, 5)))
        msg = self.rejected(C.fit_sources, [(sk2, ["Edge1", "Edge2"])])
        self.assertIn("the selection is 2 straight lines", msg)
        self.assertIn("3 end points", msg)

    def test_a_polyline_of_enough_lines_is_still_fitted(self):
        zig = [(10.0 * i, 3.0 * (i % 2)) for i in range(7)]
        sk = self.line_sketch(*zip(zig[:-1], zig[1:]))
        del C.MESSAGES[:]
        self.assertIsNotNone(C.fit_sources([(sk, [])], open_panel=False), C.MESSAGES)

    def test_a_circle_is_no_points_for_a_spline_or_an_elliptic_blend(self):
        circ = S.circle_sketch(self.doc, 15.0)
        msg = self.rejected(C.spline_sources, [(circ, [])])
        self.assertNotIn("1 point", msg)
        self.assertIn("Circle holds a circle, without points to go through: select points", msg)
        msg = self.rejected(C.ellblend_sources, [(circ, [])])
        self.assertIn("Circle holds a circle, without points to go through: select vertices in "
                      "order", msg)

    def test_a_command_failing_before_any_change_leaves_no_undo_step(self):
        # abortTransaction has nothing to abort then and FreeCAD kept the name pending: the
        # user's next change became an Undo step named after the failed command
        self.doc.UndoMode = 1
        box = self.doc.addObject("App::FeaturePython", "Box")
        box.addProperty("App::PropertyFloat", "X")
        del C.MESSAGES[:]
        self.assertIsNone(C._create(self.doc, "Elastic spline", "raise RuntimeError('boom')"))
        self.assertIn("Elastic spline failed: RuntimeError: boom", C.MESSAGES[0])
        self.assertFalse(App.getActiveTransaction())
        self.doc.openTransaction("Set X")
        box.X = 5.0
        self.doc.commitTransaction()
        self.assertEqual(self.doc.UndoNames[:1], ["Set X"])
        self.assertNotIn("Elastic spline", self.doc.UndoNames)


if __name__ == "__main__":
    unittest.main()
