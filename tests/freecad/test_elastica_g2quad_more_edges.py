"""freecadcmd -t tests: a source the G2 quadratic takes at more Edges than asked is made all
the same, in error, its Edges to edit (QA gui F2: the closed Elastic spline through a
hand-drawn oval, 24 points with 0.3 mm jitter, was refused in a 'Wrong selection' box saying
'give more edges ... Select one open edge', with no feature and no panel to give them in)."""

import math

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import g2quad as Q
from freecad.elastica import spline as SP


def jittered_oval(doc, noise=0.3):
    """QA gui F2's sketch: 24 points, uneven, on an oval 300 x 180 mm at (1500, -800)."""
    import numpy as np
    rng = np.random.default_rng(3)
    th = np.sort(rng.uniform(0, 2 * np.pi, 24))
    sk = doc.addObject("Sketcher::SketchObject", "Outline")
    for t in th:
        x = 1500 + 150 * math.cos(t) + rng.normal(0, noise)
        y = -800 + 90 * math.sin(t) + rng.normal(0, noise)
        sk.addGeometry(Part.Point(App.Vector(float(x), float(y), 0)), False)
    doc.recompute()
    return sk


def jittered_spline(test):
    """QA gui F2's source: the closed Elastic spline through jittered_oval's points, solved
    ('ok'), in ``test``'s document."""
    sk = jittered_oval(test.doc)
    s = SP.make(test.doc, [(sk, [])], Closed=True)
    test.doc.recompute()
    test.assertTrue(s.Status.startswith("ok"), s.Status)
    return s


class G2QuadMoreEdgesTest(S.DocTest):
    doc_name = "ElasticaG2QuadMoreEdges"

    def test_a_closed_jittered_outline_is_made_with_its_edges_to_edit(self):
        s = jittered_spline(self)
        said = []

        def wrong(text, selection=True):
            said.append((text, selection))
        wrong.shapes = True
        q = C.g2quad_sources([(s, [])], open_panel=False, wrong=wrong)
        self.assertEqual(said, [])               # no box
        self.assertIsNotNone(q)
        self.assertEqual(q.Edges, 24)
        self.assertIn("Invalid", q.State)
        self.assertRegex(q.Status, r"^error: no G2 quadratic B-spline with Edges = 24: its "
                         r"turns need more edges .*: Edges = \d+ builds it$")
        more = int(q.Status.split("Edges = ")[-1].split(" ")[0])
        self.assertGreater(more, 24)
        q.Edges = more                            # what it named builds it
        self.doc.recompute()
        # built, but its pieces (one per wiggle of the jitter) meet kinked: the verdict
        # first, not "ok" (QA gui3 G2)
        self.assertTrue(q.Status.startswith("built, not G2: "), q.Status)
        self.assertNotIn("Invalid", q.State)
        self.assertTrue(Part.Wire(q.Shape.Edges).isClosed())
        for e in q.Shape.Edges:
            for p in e.discretize(50):
                self.assertLess(s.Shape.distToShape(Part.Vertex(p))[0], q.Deviation + 0.01)

    def test_a_straight_source_is_still_refused(self):
        """No count builds a line: refused as before, the document unchanged."""
        line = self.doc.addObject("Part::Feature", "Line")
        line.Shape = Part.makeLine(App.Vector(0, 0, 0), App.Vector(50, 10, 0))
        self.doc.recompute()
        before = S.doc_state(self.doc)
        del C.MESSAGES[:]
        self.assertIsNone(C.g2quad_sources([(line, ["Edge1"])], open_panel=False))
        self.assertIn("a straight stretch of the source has no affine arc length",
                      C.MESSAGES[-1])
        self.assertEqual(S.doc_state(self.doc), before)

    def test_the_command_says_what_it_takes(self):
        """It said 'Select one open edge or sketch curve' though closed ones are taken."""
        self.assertNotIn("open edge", C.G2QuadCommand.needs)
        self.assertIn("closed", C.G2QuadCommand.needs)

    def test_the_count_is_searched_once_and_one_undo_removes_it(self):
        """The command's check found the count (a search of up to cover_search_limit builds,
        2-4 s on the oval): the feature's first recompute takes that outcome, the error,
        instead of searching again; the feature made in error is one Undo step."""
        s = jittered_spline(self)
        self.doc.UndoMode = 1
        calls, search = [], Q._more_edges

        def counted(*args):
            calls.append(args[3])
            return search(*args)
        Q._more_edges = counted
        try:
            q = C.g2quad_sources([(s, [])], open_panel=False, wrong=lambda *a: None)
        finally:
            Q._more_edges = search
        self.assertEqual(calls, [24])
        self.assertRegex(q.Status, r"^error: .*Edges = \d+ builds it$")
        name = q.Name
        self.assertEqual(self.doc.UndoNames[0], "G2 quadratic B-spline")
        self.doc.undo()
        self.assertNotIn(name, [o.Name for o in self.doc.Objects])
