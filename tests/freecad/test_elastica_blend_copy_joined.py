"""freecadcmd -t tests of the Elastic blend's copy into its edges' sketch (QA gui F4): the copy
is joined to both edges as Sketcher_CreateFillet joins its arc (an endpoint-to-endpoint
Tangent at each end: coincident and G1 there), the sketch solves with them moving nothing,
and an edge moved later drags the copy's ends along (G2 is not held: FreeCAD 0.20 has no
curvature constraint for B-splines)."""
import math

import FreeCAD as App
import Part
import Sketcher

import elastica_samples as S
from freecad.elastica import blend as Bl


def _bspline(sk, pts):
    b = Part.BSplineCurve()
    b.interpolate([App.Vector(x, y, 0) for x, y in pts])
    return sk.addGeometry(b, False)


def _probe(sk):
    out = []
    for g in sk.Geometry:
        a, b = g.FirstParameter, g.LastParameter
        out += [g.value(a), g.value(0.5 * (a + b)), g.value(b)]
        if hasattr(g, "getPoles"):
            out += list(g.getPoles())
    return out


class CopyJoinedTest(S.DocTest):
    doc_name = "ElasticaBlendCopyJoined"

    def _copied(self, sk, continuity="G1", edges=("Edge1", "Edge2"), **props):
        b = Bl.make(self.doc, (sk, edges[0]), (sk, edges[1]), Continuity=continuity, **props)
        self.doc.recompute()
        self.assertFalse(b.Status.startswith("error"), b.Status)
        n, before = len(sk.Constraints), _probe(sk)

        def copy():
            gi = Bl.copy_into_sketch(b)
            self.doc.recompute()
            sk.solve()
            return gi
        said, gi = S.console_output(copy)
        # FreeCAD 0.20's solver says a joint it cannot use (the copy's end 1e-13 off the
        # edge's: a B-spline's end tangent is taken only at a point equal to its end)
        self.assertNotIn("redundant", said)
        self.assertNotIn("onflicting", said)
        new = sk.Constraints[n:]
        # one endpoint-to-endpoint Tangent at each joint, as Sketcher_CreateFillet adds
        self.assertEqual([c.Type for c in new], ["Tangent", "Tangent"], [
            (c.Type, c.First, c.FirstPos, c.Second, c.SecondPos) for c in new])
        g1, g2 = b.SketchGeometry1, b.SketchGeometry2
        self.assertEqual({(c.First, c.Second) for c in new}, {(g1, gi), (g2, gi)})
        self.assertEqual(sorted(c.SecondPos for c in new), [1, 2])
        self.assertTrue(all(c.FirstPos in (1, 2) for c in new))
        # solves cleanly (no conflicting / redundant constraint) and moves nothing
        self.assertEqual(sk.solve(), 0)
        self.doc.recompute()
        self.assertEqual(sk.solve(), 0)
        moved = max((p - q).Length for p, q in zip(before, _probe(sk)))
        self.assertLess(moved, 1e-9)
        # a Coincident beside a joint's Tangent would be redundant: the Tangent holds both
        c = new[0]
        sk.addConstraint(Sketcher.Constraint("Coincident", c.First, c.FirstPos, c.Second,
                                             c.SecondPos))
        self.assertEqual(sk.solve(), -2)
        sk.delConstraint(len(sk.Constraints) - 1)
        self.assertEqual(sk.solve(), 0)
        return b, gi, new

    def _follows(self, sk, gi, g, pos, to):
        """Move the end ``pos`` of geometry ``g`` far from the copy to ``to``: the copy's end
        joined to it follows, tangent there."""
        joint = next(c for c in sk.Constraints if c.Type == "Tangent" and c.Second == gi
                     and c.First != g)
        sk.movePoint(g, 3 - pos if joint.First == g else pos, to)
        self.doc.recompute()
        self.assertEqual(sk.solve(), 0)
        for c in sk.Constraints:
            if c.Type != "Tangent" or c.Second != gi:
                continue
            e, cp = sk.Geometry[c.First], sk.Geometry[gi]
            u = e.FirstParameter if c.FirstPos == 1 else e.LastParameter
            v = cp.FirstParameter if c.SecondPos == 1 else cp.LastParameter
            self.assertLess((e.value(u) - cp.value(v)).Length, 1e-6)
            cross = e.tangent(u)[0].cross(cp.tangent(v)[0]).Length
            self.assertLess(cross, 1e-6)

    def test_line_and_arc_g1_and_g2(self):
        for continuity in ("G1", "G2"):
            doc_sk = self.doc.addObject("Sketcher::SketchObject", "Profile" + continuity)
            S.f4_line_arc(doc_sk)
            self.doc.recompute()
            b, gi, _ = self._copied(doc_sk, continuity)
            # the line's start dragged: its end joined to the copy stays on the copy
            self._follows(doc_sk, gi, 0, 2, App.Vector(1490, -780, 0))

    def test_inclined_body_plane(self):
        """QA e6: a Body placed and turned, a datum plane inclined 35 deg, the sketch on it."""
        sk = S.inclined_body_sketch(self.doc, "Profile")
        S.f4_line_arc(sk)
        self.doc.recompute()
        for continuity in ("G2", "G1"):
            b, gi, _ = self._copied(sk, continuity)
            self.doc.removeObject(b.Name)
            sk.delGeometry(gi)          # its joints go with it
            self.doc.recompute()
            self.assertEqual(len(sk.Constraints), 0)

    def test_arc_to_arc_ends_either_way(self):
        """Two arcs, the blend leaving the first at its start and entering the second at its
        end: the Tangent's ends are the arcs' PosId 1 and 2, the senses opposite."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Arcs")
        c1 = Part.Circle(App.Vector(0, 0, 0), App.Vector(0, 0, 1), 40)
        sk.addGeometry(Part.ArcOfCircle(c1, math.radians(100), math.radians(200)), False)
        c2 = Part.Circle(App.Vector(150, -10, 0), App.Vector(0, 0, 1), 30)
        sk.addGeometry(Part.ArcOfCircle(c2, math.radians(0), math.radians(90)), False)
        self.doc.recompute()
        for continuity in ("G1", "G2"):
            b, gi, new = self._copied(sk, continuity, AtEnd1=False, AtEnd2=True)
            self.assertEqual({(c.First, c.FirstPos) for c in new}, {(0, 1), (1, 2)})
            self.doc.removeObject(b.Name)
            sk.delGeometry(gi)
            self.doc.recompute()

    def test_bspline_edges(self):
        """B-splines as the edges: their ends are PosId 1 / 2 (checked on FreeCAD 0.20.2;
        their end knots are no separate vertices unless the Sketcher shows them)."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Splines")
        _bspline(sk, [(0, 0), (30, 8), (60, 5), (90, 12)])
        _bspline(sk, [(150, 60), (180, 50), (210, 62), (240, 40)])
        self.doc.recompute()
        for continuity in ("G1", "G2"):
            b, gi, new = self._copied(sk, continuity)
            self.assertEqual({(c.First, c.FirstPos) for c in new}, {(0, 2), (1, 1)})
            if continuity == "G2":
                self._follows(sk, gi, 1, 1, App.Vector(245, 30, 0))
            self.doc.removeObject(b.Name)
            sk.delGeometry(gi)
            self.doc.recompute()

    def test_line_to_bspline_and_copy_again(self):
        """A line and a B-spline; Copy into again (the line moved, the blend re-solved)
        replaces the copy in place and adds no second joint."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Mixed")
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(60, 0, 0)), False)
        _bspline(sk, [(140, 50), (170, 40), (200, 55), (230, 45)])
        self.doc.recompute()
        b, gi, _ = self._copied(sk, "G2")
        n = len(sk.Constraints)
        sk.movePoint(0, 1, App.Vector(-5, -8, 0))      # the line's free end
        self.doc.recompute()

        def again():
            self.assertEqual(Bl.copy_into_sketch(b), gi)
            self.doc.recompute()
            return sk.solve()
        said, solved = S.console_output(again)
        self.assertEqual((solved, len(sk.Constraints)), (0, n))
        self.assertNotIn("redundant", said)
        copy = sk.Geometry[gi].toShape()
        self.assertLess(max(b.Shape.distToShape(Part.Vertex(p))[0]
                            for p in copy.discretize(25)), 1e-6)   # the re-solved blend's

    def test_a_copy_into_another_sketch_is_not_joined(self):
        """Copy into a sketch that does not hold the edges: nothing to join."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        S.f4_line_arc(sk)
        other = self.doc.addObject("Sketcher::SketchObject", "Other")
        self.doc.recompute()
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"))
        self.doc.recompute()
        Bl.copy_into_sketch(b, other)
        self.doc.recompute()
        self.assertEqual((len(other.Geometry), len(other.Constraints)), (1, 0))

    def _dimensioned(self, name):
        """F4's profile fully dimensioned (line ends, arc centre, radius, angle; the arc may
        still turn about its centre), its G2 blend written into it unjoined, the copy's start
        dimensioned by the designer (DistanceX, DistanceY): a joint there is redundant, the
        one at the copy's end is not."""
        sk = self.doc.addObject("Sketcher::SketchObject", name)
        S.f4_line_arc(sk)
        for c in (Sketcher.Constraint("DistanceX", -1, 1, 0, 1, 1500),
                  Sketcher.Constraint("DistanceY", -1, 1, 0, 1, -800),
                  Sketcher.Constraint("DistanceX", -1, 1, 0, 2, 1620),
                  Sketcher.Constraint("DistanceY", -1, 1, 0, 2, -800),
                  Sketcher.Constraint("Radius", 1, 60),
                  Sketcher.Constraint("DistanceX", -1, 1, 1, 3, 1830),
                  Sketcher.Constraint("DistanceY", -1, 1, 1, 3, -710),
                  Sketcher.Constraint("Angle", 1, math.radians(130))):
            sk.addConstraint(c)
        self.doc.recompute()
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2")
        self.doc.recompute()
        from freecad.elastica import geometry as G
        gi = G.write_to_sketch(b, sk)[0]
        p0 = sk.Geometry[gi].StartPoint
        sk.addConstraint(Sketcher.Constraint("DistanceX", -1, 1, gi, 1, p0.x))
        sk.addConstraint(Sketcher.Constraint("DistanceY", -1, 1, gi, 1, p0.y))
        self.doc.recompute()
        self.assertEqual(sk.solve(), 0)
        return sk, b, gi

    def test_a_joint_the_sketch_refuses_leaves_the_other(self):
        """join_ends' guard (review of F4): the joint at the copy's dimensioned start is
        redundant and taken back; the one at its end stays (on main both were thrown away),
        the sketch solving as before and nothing moved; the report view says which end is
        not joined and what holds it (the copy's start by its DistanceX, DistanceY, the
        line's end by the designer's: not 'its edges' ends are held otherwise')."""
        from freecad.elastica import geometry as G
        sk, b, gi = self._dimensioned("Dimensioned")
        n, before = len(sk.Constraints), _probe(sk)
        said, added = S.console_output(lambda: G.join_ends(sk, [gi], Bl._joint_ends(b, sk)))
        self.assertEqual(len(added), 1, said)
        self.assertEqual(len(sk.Constraints), n + 1)
        c = sk.Constraints[added[0]]
        # the copy's end (PosId 2) on the arc's start (Edge2's, geometry 1, PosId 1)
        self.assertEqual((c.Type, c.First, c.FirstPos, c.Second, c.SecondPos),
                         ("Tangent", 1, 1, gi, 2))
        self.assertEqual(sk.solve(), 0)
        self.assertLess(max((p - q).Length for p, q in zip(before, _probe(sk))), 1e-9)
        self.assertIn("the copy's start is not joined to Edge1's end by a Tangent constraint: "
                      "the sketch would not solve with it (the copy's start is held by "
                      "DistanceX, DistanceY and the edge's end is held by DistanceX, "
                      "DistanceY); its other end is joined", said)
        self.assertNotIn("edges' ends are held otherwise", said)
        # the joint kept holds: the arc turned about its centre drags the copy's end along
        self.doc.recompute()
        self.assertEqual(sk.solve(), 0)

    def test_joints_the_sketch_refuses_are_taken_back_whole(self):
        """Both joints refused (the arc's start dimensioned as well): both taken back, the
        geometry as it was, each said in the report view."""
        from freecad.elastica import geometry as G
        sk, b, gi = self._dimensioned("Dimensioned")
        a = sk.Geometry[1].StartPoint
        sk.addConstraint(Sketcher.Constraint("DistanceX", -1, 1, 1, 1, a.x))
        sk.addConstraint(Sketcher.Constraint("DistanceY", -1, 1, gi, 2,
                                             sk.Geometry[gi].EndPoint.y))
        self.doc.recompute()
        self.assertEqual(sk.solve(), 0)
        n, before = len(sk.Constraints), _probe(sk)
        said, added = S.console_output(lambda: G.join_ends(sk, [gi], Bl._joint_ends(b, sk)))
        self.assertEqual((added, len(sk.Constraints), sk.solve()), ([], n, 0))
        self.assertEqual(max((p - q).Length for p, q in zip(before, _probe(sk))), 0.0)
        self.assertIn("the copy's start is not joined to Edge1's end", said)
        self.assertIn("the copy's end is not joined to Edge2's end by a Tangent constraint", said)
        self.assertNotIn("other end is joined", said)
