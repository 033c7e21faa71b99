"""freecadcmd -t tests of what a G2 blend pulled beyond its reach says (QA12): the
largest tension found, to 6 significant digits and rounded down to one that solved; a
tension asked named to 6 digits (split from test_elastica_blend.py, over 800 lines)."""
import re

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend as Bl


class G2ReachTest(S.DocTest):
    doc_name = "ElasticaG2ReachTest"

    def test_g2_reach_said_is_one_that_solves_told_apart_from_its_neighbours(self):
        """QA12 (U walls, tops): the reach was said to 3 digits, "0.00177 at most"; the
        tension by length was 0.0017682x, none solved at 0.00176823 and its error said "no
        G2 blend at tension 0.00177" as well. Now 6 significant digits, rounded down to a
        tension that solved ("about", "the largest found"): typed back exactly it solves;
        a tension asked is named to 6 digits."""
        sk = self.doc.addObject("Sketcher::SketchObject", "U")
        sk.addGeometry(Part.LineSegment(App.Vector(100, 0, 0), App.Vector(100, 20, 0)), False)
        sk.addGeometry(Part.LineSegment(App.Vector(0, 30, 0), App.Vector(0, 0, 0)), False)
        self.doc.recompute()
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), True, False, Continuity="G2",
                    Mode="tension", Tension=0.003)
        self.doc.recompute()
        found = re.search("the largest tension a G2 batten was found at is about ([0-9.e-]+) "
                          r"1/mm\u00b2 \(there can be gaps below it\)", b.Status)
        self.assertIsNotNone(found, b.Status)
        self.assertNotIn("at most", b.Status)
        text = found.group(1)
        b.Tension = float(text)
        self.doc.recompute()
        self.assertEqual(b.State, ["Up-to-date"], b.Status)
        self.assertAlmostEqual(float(b.BlendTension), float(text), delta=1e-12)
        b.Tension = 0.00300123          # beyond the reach: named as typed, not "0.003"
        self.doc.recompute()
        self.assertTrue(b.Status.startswith("error: no G2 blend at tension 0.00300123 1/mm"),
                        b.Status)
