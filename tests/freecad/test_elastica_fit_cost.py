"""freecadcmd -t test of what end conditions cost in the Fit's computation (fit_core): the
decision and figures are the binding's (el.costly on the free fit el.fit makes with its
check_ends, FitResult.free), and that one fit with free ends serves the warning and the
far points: fit_core fits the points free once, resampled or not."""
import math
import sys
import unittest

import FreeCAD as App
import numpy as np
import Part

import elastica_samples as S
from freecad.elastica.fit_core import fit_core
from freecad.elastica import units as U
from freecad.elastica.units import say


class FitCostTest(unittest.TestCase):
    def setUp(self):
        xy, _ = S.keyline_xy(40)     # the noisy 330 mm S of test_elastica_fit's cost test
        xy = xy + np.random.default_rng(3).normal(0.0, 0.3, xy.shape)
        self.points = [App.Vector(float(x), float(y), 0.0) for x, y in xy]
        self.module = sys.modules["libelastica.fit"]
        self.fit, self.calls = self.module.fit, []

        def spy(points, *args, **kwargs):
            r = self.fit(points, *args, **kwargs)
            self.calls.append((kwargs.get("constraints"), r))
            return r
        self.module.fit = spy

    def tearDown(self):
        self.module.fit = self.fit

    def test_one_free_fit_from_el_fit_serves_the_warning(self):
        """A natural start (curvature 0) where the S curves at 0.012/mm (rms 1.66 mm against
        0.29 free, resampled at 5 mm 1.64 against 0.22): warned of with the figures of the one
        fit with free ends fit_core ran, el.fit's own (results[0].free)."""
        for model in ("smooth", "discrete"):
            for step in (0.0, 5.0):
                del self.calls[:]
                r = fit_core(self.points, model=model, start_curvature=0.0, step=step)
                free = [f for c, f in self.calls if not c]
                self.assertEqual(len(free), 1, (model, step, len(self.calls)))
                self.assertIs(r["results"][0].free, free[0])
                if model == "smooth":     # a discrete one's: its drawn cubic's
                    self.assertEqual(r["free_rms"], free[0].rms)
                warned = say(r["warnings"])        # its lengths marked (units.exact_mark)
                said = [w for w in warned if "the end conditions" in w]
                self.assertEqual(said, [warned[0]])
                # (resampled: the polygon's figures, both fits' to it)
                rms = U.number_text(r["rms"]) if not step else ""
                self.assertTrue(said[0].startswith(
                    "the end conditions (Start curvature) raise the rms from "
                    f"{U.number_text(r['free_rms'])} mm (free ends) to {rms}"), said[0])
                self.assertTrue(said[0].endswith(" mm: check that they match the data"), said[0])

    def test_a_wrong_tangent_costly_near_its_end_only_is_warned_naming_it(self):
        """300 noisy points (0.5 mm) of a 120 mm S, the start following an edge 0.3 rad off
        its tangent: rms 1.46 x free overall, 2.84 x over the tenth of the points nearest
        the start: warned (el.end_costs), naming the start; the true tangent: silent."""
        el = sys.modules["libelastica"]
        length = 120.0
        truth = el.SmoothElastica(x0=3.0, y0=-2.0, phi=0.4, mu=(1.6 * math.pi / length) ** 2,
                                  k=0.8, q=0.6, length=length)
        xy = truth.points(np.linspace(0.0, length, 300))
        xy = xy + np.random.default_rng(3).normal(0.0, 0.5, xy.shape)
        points = [App.Vector(float(x), float(y), 0.0) for x, y in xy]
        start = App.Vector(float(xy[0, 0]), float(xy[0, 1]), 0.0)
        for off in (0.3, 0.0):
            a = float(truth.angle([0.0])[0]) + off
            edge = Part.LineSegment(start - App.Vector(20 * math.cos(a), 20 * math.sin(a), 0.0),
                                    start).toShape()
            for model in ("smooth", "discrete"):
                r = fit_core(points, model=model, start_edge=edge)
                said = [w for w in say(r["warnings"]) if "the end conditions" in w]
                self.assertLess(r["rms"], 2.0 * r["free_rms"], (off, model))
                if not off:
                    self.assertEqual(said, [], model)
                    continue
                self.assertEqual(len(said), 1, (model, r["warnings"]))
                self.assertTrue(said[0].startswith(
                    "the end conditions (Start tangent) raise the rms near the start "), said[0])
                self.assertTrue(said[0].endswith(" mm: check that they match the data"), said[0])


if __name__ == "__main__":
    unittest.main()
