"""freecadcmd -t tests of what a feature says when the sketch geometry a link follows is
replaced at its index (QA24gui F4): what is in its place is said ('was deleted; a line
segment is in its place'), not only 'was deleted'; a geometry deleted (those after it moved
down) is said deleted."""
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend as Bl


class FollowedReplacedTest(S.DocTest):
    doc_name = "FollowedReplaced"

    def setUp(self):
        super().setUp()
        self.sk = S.line_and_arc_sketch(self.doc)
        self.b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="length",
                         Length=120)
        self.doc.recompute()
        self.assertFalse(self.b.Status.startswith("error"), self.b.Status)

    def test_an_arc_replaced_by_a_line_at_its_index_says_what_is_in_its_place(self):
        g = self.sk.Geometry
        arc = g[1]
        g[1] = Part.LineSegment(arc.StartPoint, arc.EndPoint)
        self.sk.Geometry = g
        self.doc.recompute()
        self.assertEqual(self.b.Status, "error: Edge2: the sketch geometry it followed "
                         "(LineArc.Edge2, an arc) was deleted; a line segment is in its place: "
                         "relink Edge2")           # main: '... (LineArc.Edge2) was deleted'

    def test_a_line_replaced_by_a_line_says_another_is_in_its_place(self):
        g = self.sk.Geometry
        g[0] = Part.LineSegment(App.Vector(-30, -12, 0), App.Vector(0, 0, 0))
        self.sk.Geometry = g
        self.doc.recompute()
        self.assertEqual(self.b.Status, "error: Edge1: the sketch geometry it followed "
                         "(LineArc.Edge1, a line segment) was deleted; another line segment is "
                         "in its place: relink Edge1")

    def test_a_deleted_edge_is_still_said_deleted(self):
        self.sk.delGeometry(0)
        self.doc.recompute()
        self.assertEqual(self.b.Status, "error: Edge1: the sketch geometry it followed "
                         "(LineArc.Edge1) was deleted: relink Edge1")


if __name__ == "__main__":
    unittest.main()
