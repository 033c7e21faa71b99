"""freecadcmd -t tests of the hint an open Elastic spline gives where its first and last
points nearly meet (QA qagui F9: a closed outline of sketch points, Closed off, gave an open
batten with a 16.2 mm gap and its ends 37.5 deg apart, and no word): the Warnings say that
Closed closes it; an open curve, or an outline opened wide, says nothing."""
import math
import unittest

import numpy as np

import elastica_samples as S
from freecad.elastica import spline as Sp


def oval(n=24, seed=3, jitter=0.3):
    """The QA's outline (f9.py): n points of an oval 300 x 180 mm, uneven, hand jitter."""
    rng = np.random.default_rng(seed)
    th = np.sort(rng.uniform(0, 2 * np.pi, n))
    return [(150 * math.cos(t) + rng.normal(0, jitter), 90 * math.sin(t) + rng.normal(0, jitter))
            for t in th]


def hints(s):
    return [w for w in s.Warnings if "set Closed" in w]


class SplineOutlineTest(S.DocTest):
    doc_name = "ElasticaSplineOutline"

    def spline(self, xy, **props):
        s = Sp.make(self.doc, [(S.points_sketch(self.doc, xy, "Outline"), [])], **props)
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        return s

    def test_a_nearly_closed_outline_says_closed_closes_it(self):
        """The QA's oval: one hint with the gap and the ends' angle, on the Status too;
        Closed set: a closed batten, no hint."""
        s = self.spline(oval())
        said = hints(s)
        self.assertEqual(len(said), 1, s.Warnings)
        self.assertIn("first and last points are 16.24 mm apart", said[0])
        self.assertIn("its ends run 37.5 deg apart", said[0])
        self.assertIn("(the outline 299.1", said[0])   # its diameter 299.11, not the box 348.89
        turned = [(x * 0.6 - y * 0.8, x * 0.8 + y * 0.6) for x, y in oval()]
        self.assertIn("(the outline 299.1", hints(self.spline(turned))[0])
        self.assertIn("set Closed for a closed batten", s.Status)
        s.Closed = True
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        self.assertEqual(hints(s), [])
        self.assertTrue(s.Shape.Edges[0].isClosed())

    def test_open_curves_and_wide_openings_say_nothing(self):
        """The oval's points dropped from its end one by one: the hint while the gap is no
        longer than the longest span and at most a fifth of the outline's size (2 of 8: 16.2
        and 26.3 mm), then none (133.6 mm and on); an open batten (the test ducks) and a
        hairpin say nothing."""
        xy = oval()
        said = []
        for drop in range(0, 8):
            pts = np.array(xy[:len(xy) - drop])
            gap = float(np.hypot(*(pts[-1] - pts[0])))
            longest = float(np.max(np.hypot(*np.diff(pts, axis=0).T)))
            size = max(math.dist(a, b) for a in pts for b in pts)    # the diameter
            d = np.diff(pts, axis=0)
            h = np.arctan2(d[:, 1], d[:, 0])
            turning = abs(math.degrees(np.sum(np.remainder(np.diff(h) + math.pi, 2 * math.pi)
                                              - math.pi)))
            s = self.spline(list(map(tuple, pts)))
            said.append(bool(hints(s)))
            self.assertEqual(said[-1], gap <= longest and gap <= 0.2 * size and turning >= 270.0,
                             (drop, gap, longest, turning))
        self.assertTrue(said[0])
        self.assertFalse(said[-1])
        self.assertEqual(hints(self.spline([(0, 0), (30, 10), (60, 5), (90, 20), (120, 0)])), [])
        # a hairpin (test_elastica_spline's sharp ducks, 16.8 mm apart at its ends in 101 mm):
        # its polygon turns 175 deg, it goes round nothing
        self.assertEqual(hints(self.spline([(0, 0), (50, 0), (100, 3), (55, 12), (5, 16)],
                                           Tension=1e-4)), [])

    def test_a_hooked_outline_says_so(self):
        """QA gui3 G4: 30 points round an egg, 0.4 mm jitter, point 7 moved 5 mm, Closed: the
        batten hooks (radius 0.52 mm between points 2 and 3, 0.66 mm apart) without crossing
        itself; one warning says where, on the Status too. Without the jitter: none."""
        rng = np.random.default_rng(11)
        t = np.sort(rng.uniform(0, 2 * math.pi, 30))
        egg = np.c_[150 * np.cos(t) + 0.15 * 150 * np.cos(2 * t), 90 * np.sin(t)]
        jitter = rng.normal(0, 0.4, (30, 2))
        for j, want in ((1.0, 1), (0.0, 0)):
            xy = egg + j * jitter
            xy[7] += [5, 5]
            s = self.spline(list(map(tuple, xy + [600, 300])), Closed=True)
            said = [w for w in s.Warnings if "hooks" in w]
            self.assertEqual(len(said), want, s.Warnings)
            if want:
                self.assertIn("the batten hooks between points 2 and 3 (counted from 0): it bends "
                              "to radius 0.52 mm there", said[0])
                self.assertIn("warning: the batten hooks", s.Status)


if __name__ == "__main__":
    unittest.main()
