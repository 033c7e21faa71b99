"""freecadcmd -t tests of Copy into the sketch of the edges a Fit or an Elastic spline joins
(qagui3 F1): a Fit joined G2 to a line's end and G1 to an arc's, or a spline whose ends are
G2 to them, copied by OK into that sketch came with no constraint at all (the blend's copy
has had an endpoint Tangent at each joint since QA gui F4): the profile was held together by
equal floating-point ends only, and the first edit of the line left the copy behind. Now the
copy is joined as the blend's is (geometry.join_ends): one Tangent at each end that meets its
edge's end, the sketch solving with them and moving nothing, the copy following the line."""
import math
import unittest

import FreeCAD as App
import Part
import numpy as np

import elastica_samples as S
from freecad.elastica import fit, spline, taskpanels

V = App.Vector


def _profile_and_points(doc, n=40, noise=0.3):
    """A line (0,0)-(100,0), an elastica of 260 mm leaving its end with its direction and no
    curvature (an inflection there), an arc joining the elastica's end G2; ``n`` points of the
    elastica, uneven, with noise."""
    import libelastica as el
    import scipy.special as sp
    k = 0.55
    c = el.SmoothElastica(x0=100, y0=0, phi=-2 * math.asin(k), mu=(1 / 90.0) ** 2, k=k,
                          q=float(sp.ellipk(k * k)), length=260.0)
    p = c.points([260.0])[0]
    th, ke = float(c.angle([260.0])[0]), float(c.curvature([260.0])[0])
    r = 1 / abs(ke)
    ctr = p + r * np.sign(ke) * np.array([-math.sin(th), math.cos(th)])
    a = math.atan2(p[1] - ctr[1], p[0] - ctr[0])
    sk = doc.addObject("Sketcher::SketchObject", "Profile")
    sk.addGeometry(Part.LineSegment(V(0, 0, 0), V(100, 0, 0)), False)
    circle = Part.Circle(V(ctr[0], ctr[1], 0), V(0, 0, 1), r)
    sk.addGeometry(Part.ArcOfCircle(circle, a, a + 1.7) if ke > 0 else
                   Part.ArcOfCircle(circle, a - 1.7, a), False)
    rng = np.random.default_rng(3)
    s = np.sort(rng.uniform(4, 256, n))
    xy = c.points(s) + rng.normal(0, noise, (n, 2))
    pts = doc.addObject("Sketcher::SketchObject", "Scan")
    for x, y in xy:
        pts.addGeometry(Part.Point(V(float(x), float(y), 0)), False)
    doc.recompute()
    return sk, pts, c


def _ok_copy(doc, panel_class, feature, target):
    """The code the panel's OK records for Copy into ``target``, run as a macro runs it."""
    panel = panel_class.__new__(panel_class)
    panel.doc, panel.obj = doc, feature
    panel.copy_target = lambda: target.Name
    exec(panel.copy_code(), {"App": App, "FreeCAD": App})
    doc.recompute()


class FitCopyJoinedTest(S.DocTest):
    doc_name = "ElasticaFitCopyJoined"

    def _joints(self, sk, n_before):
        """{(edge index, its pos): copy's pos} of the Tangent constraints joining the copy."""
        copy = len(sk.Geometry) - 1
        out = {}
        for c in sk.Constraints:
            if c.Type == "Tangent" and copy in (c.First, c.Second):
                mine = (c.First, c.FirstPos) if c.First == copy else (c.Second, c.SecondPos)
                other = (c.Second, c.SecondPos) if c.First == copy else (c.First, c.FirstPos)
                out[other] = mine[1]
        self.assertEqual(len(sk.Geometry), n_before + 1)
        return out

    def _follows_the_line(self, sk):
        """The line's end moved 10 mm left (a dimension edited): the copy's start goes with it."""
        self.assertEqual(sk.solve(), 0)
        before = [g.value(g.LastParameter) for g in sk.Geometry]
        g = sk.Geometry
        line = g[0]
        g[0] = Part.LineSegment(line.StartPoint, line.EndPoint - V(10, 0, 0))
        sk.Geometry = g
        sk.solve()
        self.doc.recompute()
        copy = sk.Geometry[-1]
        self.assertLess((copy.value(copy.FirstParameter) - sk.Geometry[0].EndPoint).Length, 1e-6)
        # the arc's joint held too: the copy's end still on the arc's end
        arc_end = [sk.Geometry[1].value(sk.Geometry[1].FirstParameter),
                   sk.Geometry[1].value(sk.Geometry[1].LastParameter)]
        self.assertLess(min((copy.value(copy.LastParameter) - q).Length for q in arc_end),
                        1e-6)
        return before

    def test_a_fit_joined_g2_and_g1_is_copied_joined(self):
        sk, pts, _ = _profile_and_points(self.doc)
        f = fit.make(self.doc, [(pts, [])], Model="smooth", StartTangent=(sk, ["Edge1"]),
                     EndTangent=(sk, ["Edge2"]), StartContinuity="G2", EndContinuity="G1")
        self.doc.recompute()
        self.assertEqual(f.Status.split(".")[0], "converged", f.Status)
        self.assertLess(f.Rms, 1.0)
        _ok_copy(self.doc, taskpanels.FitPanel, f, sk)
        joints = self._joints(sk, 2)
        self.assertEqual(joints, {(0, 2): 1, (1, 2): 2}, [
            (c.Type, c.First, c.FirstPos, c.Second, c.SecondPos) for c in sk.Constraints])
        self.assertEqual(sk.solve(), 0)
        self._follows_the_line(sk)

    def test_a_fit_with_free_ends_is_copied_alone(self):
        """No join, no constraint: its ends are near the edges' but not on them."""
        sk, pts, _ = _profile_and_points(self.doc)
        f = fit.make(self.doc, [(pts, [])], Model="smooth")
        self.doc.recompute()
        _ok_copy(self.doc, taskpanels.FitPanel, f, sk)
        self.assertEqual(self._joints(sk, 2), {})

    def test_a_spline_g2_to_both_edges_is_copied_joined(self):
        sk, _, c = _profile_and_points(self.doc)
        ducks = self.doc.addObject("Sketcher::SketchObject", "Ducks")
        for x, y in c.points(np.array([0.0, 70.0, 150.0, 210.0, 260.0])):
            ducks.addGeometry(Part.Point(V(float(x), float(y), 0)), False)
        self.doc.recompute()
        sp = spline.make(self.doc, [(ducks, [])], StartCondition="G2", StartEdge=(sk, ["Edge1"]),
                         EndCondition="G2", EndEdge=(sk, ["Edge2"]))
        self.doc.recompute()
        self.assertTrue(sp.Status.startswith("ok"), sp.Status)
        _ok_copy(self.doc, taskpanels.SplinePanel, sp, sk)
        self.assertEqual(self._joints(sk, 2), {(0, 2): 1, (1, 2): 2})
        self._follows_the_line(sk)


if __name__ == "__main__":
    unittest.main()
