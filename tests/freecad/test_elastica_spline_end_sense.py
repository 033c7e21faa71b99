"""freecadcmd -t tests of the sense an Elastic spline's tangent / G2 end takes from an open
edge whose end does not touch the end duck (QA qagui F1): the spline leaves a start edge
continuing it and runs into an end edge, as it does when the duck lies on the edge's vertex,
never turned to the opposite sense by the end span (before: 180 deg off the arc, a hook),
and its warning says which vertex lends what, and the bend it takes."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import spline as Sp

# the QA's profile (f1.py): a line, then an arc r 60 from 200 to 330 deg; its ducks by eye,
# the first 21.5 mm past the line's end, the last 31 mm short of the arc's start
LINE = ((0.0, 0.0), (120.0, 0.0))
CENTRE, RADIUS, ARC = (330.0, 90.0), 60.0, (200.0, 330.0)
DUCKS = [(140.0, 8.0), (190.0, 30.0), (225.0, 40.0), (248.0, 52.0)]


def arc_point(deg):
    return (CENTRE[0] + RADIUS * math.cos(math.radians(deg)),
            CENTRE[1] + RADIUS * math.sin(math.radians(deg)))


class SplineEndSenseTest(S.DocTest):
    doc_name = "ElasticaSplineEndSense"

    def setUp(self):
        super().setUp()
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.Placement = S.SKETCH_PLACEMENT       # an inclined plane, off the origin
        sk.addGeometry(Part.LineSegment(App.Vector(*LINE[0], 0), App.Vector(*LINE[1], 0)), False)
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(*CENTRE, 0), App.Vector(0, 0, 1),
                                                    RADIUS), *map(math.radians, ARC)), False)
        self.doc.recompute()
        self.profile = sk
        self.line, self.arc = sk.Shape.Edges

    def spline(self, ducks, condition, **props):
        pts = S.points_sketch(self.doc, ducks, "Ducks")
        s = Sp.make(self.doc, [(pts, [])], StartCondition=condition,
                    StartEdge=(self.profile, "Edge1"), EndCondition=condition,
                    EndEdge=(self.profile, "Edge2"), **props)
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        return s

    def ends(self, s):
        e = s.Shape.Edges[0]
        return (App.Vector(e.tangentAt(e.FirstParameter)), App.Vector(e.tangentAt(e.LastParameter)),
                e.Curve.curvature(e.LastParameter))

    def test_an_end_short_of_the_arc_runs_into_it(self):
        """The QA's ducks, Tangent then G2: the start runs on along the line (0 deg), the end
        runs into the arc as at its start vertex (0 deg: 180 on main), G2 with the arc's
        curvature; the same as with the last duck on that vertex. The warning names the
        vertex and the 97.6 deg bend from the last span that running into it takes."""
        into = self.arc.tangentAt(self.arc.FirstParameter)
        along = self.line.tangentAt(self.line.LastParameter)
        on_vertex = DUCKS[:-1] + [arc_point(ARC[0])]
        for condition in ("tangent", "G2"):
            for ducks, gap in ((DUCKS, True), (on_vertex, False)):
                s = self.spline(ducks, condition)
                t0, t1, k1 = self.ends(s)
                self.assertLess(math.degrees(t0.getAngle(along)), 1e-7, condition)
                self.assertLess(math.degrees(t1.getAngle(into)), 1e-7, (condition, gap))
                if condition == "G2":
                    self.assertAlmostEqual(k1, 1.0 / RADIUS, delta=1e-6 / RADIUS)
                said = " ".join(s.Warnings)
                if gap:
                    self.assertIn("31.01 mm from the last point (its start vertex)", said)
                    self.assertIn("running into the edge as at its start vertex", said)
                    self.assertIn("bends 97.6 deg away from its last span", said)
                    self.assertIn("21.54 mm from the first point (its end vertex)", said)
                    self.assertIn("does not meet it", said)
                else:
                    self.assertNotIn("the end edge", said.lower())

    def test_the_sense_holds_as_the_last_duck_leaves_the_vertex(self):
        """A sweep of the last duck from the arc's start vertex back along the end span's
        chord, 0 to 40 mm, and across it, +-20 mm (tangent ends): the end tangent stays the
        arc's own at that vertex, never its opposite (on main it turned at the first gap)."""
        into = self.arc.tangentAt(self.arc.FirstParameter)
        a0 = App.Vector(*arc_point(ARC[0]), 0)
        back = (App.Vector(*DUCKS[2], 0) - a0).normalize()
        across = App.Vector(-back.y, back.x, 0)
        pts = S.points_sketch(self.doc, DUCKS, "Ducks")
        s = Sp.make(self.doc, [(pts, [])], StartCondition="tangent",
                    StartEdge=(self.profile, "Edge1"), EndCondition="tangent",
                    EndEdge=(self.profile, "Edge2"), Tension=1e-4)
        worst, n = 0.0, 0
        for d in (0.0, 1e-3, 1.0, 5.0, 15.0, 31.0, 40.0):
            for c in (-20.0, 0.0, 20.0):
                p = a0 + back * d + across * c
                pts.movePoint(3, 1, p)
                self.doc.recompute()
                if not s.Status.startswith("ok"):     # no batten there: not this test's
                    continue
                t1 = self.ends(s)[1]
                worst = max(worst, math.degrees(t1.getAngle(into)))
                n += 1
        self.assertGreater(n, 15)
        self.assertLess(worst, 1e-7)

    def test_the_end_vertex_clicked_lends_its_own_sense(self):
        """EndEdgeAt = end vertex (the arc's far end, 330 deg): the spline arrives running
        into the arc from there, against the arc's direction, said with that vertex."""
        into = -self.arc.tangentAt(self.arc.LastParameter)
        s = self.spline(DUCKS, "tangent", EndEdgeAt="end vertex", Tension=1e-4)
        self.assertLess(math.degrees(self.ends(s)[1].getAngle(into)), 1e-7)
        self.assertIn("as at its end vertex", " ".join(s.Warnings))


    def test_a_start_short_of_the_arc_leaves_out_of_it(self):
        """The QA's case mirrored (review revB): the ducks reversed, the arc the START edge,
        31 mm from the first duck. The spline leaves the first point continuing the arc out
        of its start vertex (0 deg off -t(200 deg); on 2c350ef^ the chord turned it 180), G2
        with the arc's curvature run backwards (signed -1/60 about the sketch's normal), with
        and without the gap."""
        arc = self.arc
        n = self.profile.Placement.Rotation.multVec(App.Vector(0, 0, 1))
        out = -App.Vector(arc.tangentAt(arc.FirstParameter))

        def signed(e, u):
            d1, d2 = e.derivative1At(u), e.derivative2At(u)
            return d1.cross(d2).dot(n) / d1.Length ** 3
        on_vertex = [arc_point(ARC[0])] + DUCKS[::-1][1:]
        for ducks in (DUCKS[::-1], on_vertex):
            for condition in ("tangent", "G2"):
                pts = S.points_sketch(self.doc, ducks, "Ducks")
                s = Sp.make(self.doc, [(pts, [])], StartCondition=condition,
                            StartEdge=(self.profile, "Edge2"))
                self.doc.recompute()
                self.assertTrue(s.Status.startswith("ok"), s.Status)
                e = s.Shape.Edges[0]
                t0 = App.Vector(e.tangentAt(e.FirstParameter))
                self.assertLess(math.degrees(t0.getAngle(out)), 1e-7, (condition, ducks[0]))
                if condition == "G2":
                    self.assertAlmostEqual(signed(e, e.FirstParameter), -1.0 / RADIUS,
                                           delta=1e-6 / RADIUS)

    def test_a_guide_beside_the_points_names_its_other_vertex(self):
        """A straight guide edge beside the ducks, parallel to their run, nearest at its far
        end (100, 20) to the last duck (100, 0): running into it there turns the batten back
        176 deg; the warning says that joined at its other vertex it runs the other way, and
        that end (EndEdgeAt) gives the edge's own direction, +x, without a bend (review revB)."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Guide")
        sk.addGeometry(Part.LineSegment(App.Vector(0, 20, 0), App.Vector(100, 20, 0)), False)
        self.doc.recompute()
        pts = S.points_sketch(self.doc, [(0, 0), (30, 5), (60, 3), (100, 0)], "Ducks",
                              placement=App.Placement())
        s = Sp.make(self.doc, [(pts, [])], EndCondition="tangent", EndEdge=(sk, "Edge1"),
                    Tension=1e-4)
        self.doc.recompute()
        said = " ".join(s.Warnings)
        self.assertIn("bends 176 deg away from its last span (joined at its start vertex it "
                      "runs the other way: EndEdgeAt = start vertex)", said)
        s.EndEdgeAt = "start vertex"
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        self.assertLess(math.degrees(self.ends(s)[1].getAngle(App.Vector(1, 0, 0))), 1e-7)
        said = " ".join(s.Warnings)
        self.assertIn("running into the edge as at its start vertex", said)
        self.assertNotIn("bends", said)
        self.assertNotIn("loops", said)


if __name__ == "__main__":
    unittest.main()
