"""freecadcmd -t tests of what a G2 blend pulled beyond its reach says (QA12): the
largest tension found, to 6 significant digits and rounded down to one that solved; a
tension asked named to 6 digits (split from test_elastica_blend.py, over 800 lines)."""
import math
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

    def test_below_the_reach_the_error_says_a_batten_can_be_missed(self):
        """QA16 F5: an arc of radius 20 mm (from the origin heading +x, 90 deg) into a line from
        (90, 60) heading +x: a free G2 batten exists (230 mm, by an independent shooting solve)
        but the solver does not reach it, and the error said "the largest tension a G2 batten
        was found at is about 0.03 (there can be gaps below it)", as if tension 0 should work.
        Now, where it fails below the tension reached, it says a batten can be missed."""
        sk = self.doc.addObject("Sketcher::SketchObject", "ArcLine")
        r = 20.0
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(0, r, 0), App.Vector(0, 0, 1), r),
                                        -math.pi / 2, 0.0), False)
        sk.addGeometry(Part.LineSegment(App.Vector(90, 60, 0), App.Vector(150, 60, 0)), False)
        self.doc.recompute()
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2", Tension=0.0)
        self.doc.recompute()
        if "Invalid" not in b.State:    # the solver reaches it: then it joins G2
            self.assertAlmostEqual(b.BlendTension, 0.0, delta=1e-12)
            return
        self.assertNotIn("gaps below it", b.Status)
        found = re.search("G2 battens were found at tensions up to about ([0-9.e-]+) 1/mm\u00b2, "
                          "but none at this one: the solver bends the G1 blend into G2 and can "
                          "miss a batten that exists", b.Status)
        self.assertIsNotNone(found, b.Status)
        b.Tension = float(found.group(1))    # the tension said solves
        self.doc.recompute()
        self.assertEqual(b.State, ["Up-to-date"], b.Status)

    def test_g2_by_length_that_fails_names_lengths_that_solve(self):
        """QA17 M1: line into an arc 75 mm apart (the command's 113 mm, G1) switched to G2:
        "no G2 blend of length 113 mm ...; pick another tension or length, or G1", and the
        designer guessed (80 .. 130 mm fail; the family followed folds at 135.5 mm by an
        independent shooting solve). Now it names the lengths at which G2 blends were found,
        and each of them, typed back, solves."""
        sk = S.line_and_arc_sketch(self.doc)
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="length", Length=113,
                    Continuity="G2")
        self.doc.recompute()
        self.assertIn("Invalid", b.State, b.Status)
        self.assertTrue(b.Status.startswith("error: no G2 blend of length 113 mm"), b.Status)
        found = re.search(r"G2 blends were found at the lengths ([0-9., mm]+) \(tried: 1.25 to "
                          "10 \u00d7 the 75 mm between the ends\\): try one of those, or G1",
                          b.Status)
        self.assertIsNotNone(found, b.Status)
        lengths = [float(t) for t in re.findall(r"([0-9.]+) mm", found.group(1))]
        self.assertGreaterEqual(len(lengths), 2, b.Status)
        for length in (lengths[0], lengths[-1]):
            b.Length = length
            self.doc.recompute()
            self.assertEqual(b.State, ["Up-to-date"], (length, b.Status))
            self.assertAlmostEqual(b.BlendLength, length, delta=1e-9 * length)
