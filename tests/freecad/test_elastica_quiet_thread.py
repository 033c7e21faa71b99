"""freecadcmd -t tests that the workbench keeps the binding's warnings quiet in its own
thread only (libelastica._quiet.quiet), as the binding does since f2eb6db: each of the six
places that asked warnings.catch_warnings + simplefilter('ignore', ...) put an 'ignore'
filter into the process's warnings.filters while the library ran, so another thread's
LoopWarning, ConvergenceWarning ... was dropped meanwhile. A spy in place of the library
call checks, as it is called, that the process's filters hold none of the categories and
that this thread's quiet scope takes each; then it stops the call."""
import json
import unittest
import warnings

import FreeCAD as App
import numpy as np

import elastica_samples  # noqa: F401  (puts the source tree's binding on sys.path)
import libelastica as el
from libelastica import _quiet
from libelastica.io import curve_to_dict

from freecad.elastica import blend_g2, ellblend, fit_core, g2quad, spline, spline_solve


class Stop(BaseException):
    """Ends the spied call (a BaseException: no workbench handler takes it)."""


class QuietThreadTest(unittest.TestCase):
    def spy(self, name, *categories):
        original = getattr(el, name)
        seen = []

        def spied(*args, **kwargs):
            seen.append(([f for f in warnings.filters if f[2] in categories],
                         [c for c in categories if not _quiet.quieted(c)]))
            raise Stop
        setattr(el, name, spied)
        self.addCleanup(setattr, el, name, original)
        return seen

    def check(self, seen):
        self.assertEqual(seen, [([], [])])      # no process-wide filter; this thread quiet

    def test_spline_solves_quiet_this_thread_only(self):
        xy = np.array([[0.0, 0.0], [10.0, 4.0], [20.0, 0.0], [30.0, 5.0]])
        sp = el.elastic_spline(xy, tension=0.01)
        curves = json.dumps([curve_to_dict(p) for p in sp.pieces])
        for call in (lambda: blend_g2.quiet_g2(xy[:2], {}, length=12.0),
                     lambda: spline_solve._solve(xy, "tension", 0.01, False, None, None),
                     lambda: spline.followed_kept(xy, 0.01, (None, None), sp, sp.length),
                     lambda: spline.kept_shown(xy, 0.01, (None, None), sp, curves,
                                               1.1 * sp.length, 0.01)):
            seen = self.spy("elastic_spline", el.LoopWarning, el.UnstableWarning)
            with self.assertRaises(Stop):
                call()
            self.check(seen)

    def test_blend_g2quad_and_keyline_quiet_this_thread_only(self):
        pts = [App.Vector(x, y, 0.0) for x, y in ((0, 0), (10, 4), (20, 0), (30, 5))]
        seen = self.spy("blend_curve", el.ConditionWarning, el.BlendLoopWarning)
        with self.assertRaises(Stop):
            ellblend.ellblend_core(pts)
        self.check(seen)
        t = np.linspace(0.0, 3.0, 40)
        xy = np.column_stack([10.0 * t, np.sin(t)])
        tan = np.column_stack([10.0 * np.ones_like(t), np.cos(t)])
        seen = self.spy("g2_quadratic", el.CoverageWarning, el.EndTangentWarning)
        with self.assertRaises(Stop):
            g2quad._g2quad([], None, 12, samples=(xy, tan / np.hypot(*tan.T)[:, None], None))
        self.check(seen)
        seen = self.spy("fit_keyline", el.ConvergenceWarning, el.OrderWarning, el.MisfitWarning,
                        el.SparseWarning)
        with self.assertRaises(Stop):
            fit_core._keyline(xy, "smooth", 1.0)
        self.check(seen)


if __name__ == "__main__":
    unittest.main()
