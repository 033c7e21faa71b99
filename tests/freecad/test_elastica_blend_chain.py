"""freecadcmd -t test of the Elastic blend at high tension, where the Hermite curves
near the separatrix come as chains of pieces (libelastica.HermiteChain, issue 12):
every solution gives a shape joining the edges tangentially, is described, stored
and survives save / reopen."""
import json
import math
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import geometry as G


class BlendChainTest(S.DocTest):
    doc_name = "ElasticaBlendChainTest"

    def setUp(self):
        super().setUp()
        self.sk = S.two_lines_sketch(self.doc)
        a, b = G.link_edge(self.sk, "", 0), G.link_edge(self.sk, "", 1)
        self.pa, self.da = a.valueAt(a.LastParameter), a.tangentAt(a.LastParameter)
        self.pb, self.db = b.valueAt(b.FirstParameter), b.tangentAt(b.FirstParameter)

    def _check_shape(self, blend):
        """The B-spline shape ends on the edges' ends, tangent to them."""
        e = blend.Shape.Edges[0]
        f = [e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)]
        tf = [e.tangentAt(e.FirstParameter), e.tangentAt(e.LastParameter)]
        if (f[0] - self.pa).Length > (f[1] - self.pa).Length:
            f, tf = f[::-1], [-tf[1], -tf[0]]
        self.assertLess((f[0] - self.pa).Length, blend.Tolerance)
        self.assertLess((f[1] - self.pb).Length, blend.Tolerance)
        self.assertGreater(tf[0].normalize().dot(self.da), 1 - 1e-5)
        self.assertGreater(tf[1].normalize().dot(self.db), 1 - 1e-5)

    def test_high_tension_blend_uses_chains(self):
        d = (self.pb - self.pa).Length
        b = Bl.make(self.doc, (self.sk, "Edge1"), (self.sk, "Edge2"), Mode="tension",
                    Tension=1500.0 / (d * d))
        self.doc.recompute()
        self.assertFalse(b.Status.startswith("error"), b.Status)
        n = len(b.Lengths)
        self.assertGreaterEqual(n, 2)
        self.assertEqual(len(b.Descriptions), n)
        kinds = []
        for i in range(n):
            b.Solution = i + 1
            self.doc.recompute()
            self.assertFalse(b.Status.startswith("error"), b.Status)
            self._check_shape(b)
            self.assertAlmostEqual(b.Shape.Length, b.Lengths[i], delta=1e-3 * b.Lengths[i])
            curves, plc = b.Proxy.plane_curves(b)
            kinds.append(json.loads(b.Curves)[0]["type"])
            c = curves[0]
            self.assertTrue(math.isfinite(c.energy()))
        self.assertIn("chain", kinds)
        # a chain stored, saved and reopened: the same curve and shape
        b.Solution = kinds.index("chain") + 1
        self.doc.recompute()
        stored, bname = b.Curves, b.Name
        path = S.temp_path(self, "blend_chain.FCStd")
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        self.doc = App.openDocument(path)
        b2 = self.doc.getObject(bname)
        b2.touch()
        self.doc.recompute()
        self.assertFalse(b2.Status.startswith("error"), b2.Status)
        a, c = json.loads(stored)[0], json.loads(b2.Curves)[0]
        self.assertEqual(c["type"], "chain")
        self.assertEqual(len(a["pieces"]), len(c["pieces"]))
        for p, q in zip(a["pieces"], c["pieces"]):
            for key in ("x0", "y0", "phi", "mu", "k", "q", "length"):
                self.assertAlmostEqual(p[key], q[key], delta=1e-9 * (1 + abs(p[key])))
        self._check_shape(b2)


if __name__ == "__main__":
    unittest.main()
