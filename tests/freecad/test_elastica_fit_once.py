"""freecadcmd -t test that the Fit command fits its input once: its check's fit is the new
feature's first recompute's (QA19gui F3: a 50 000-point Points object was fitted twice, the
GUI frozen 16 s), handed to the new feature's proxy (no module state), while a later
recompute of other input fits again."""
import unittest

import FreeCAD as App
import numpy as np

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import fit_core as core


class FitOnceTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("FitOnce")
        self.fit_core, self.calls = core.fit_core, []

        def spy(*args, **kwargs):
            self.calls.append(kwargs.get("model"))
            return self.fit_core(*args, **kwargs)
        core.fit_core = spy

    def tearDown(self):
        core.fit_core = self.fit_core
        App.closeDocument(self.doc.Name)

    def _points(self):
        xy, _ = S.keyline_xy(60)
        xy = xy + np.random.default_rng(19).normal(0.0, 0.2, xy.shape)
        return S.points_object(self.doc, xy)

    def test_the_command_fits_once_and_later_recomputes_fit_again(self):
        for model in ("discrete", "smooth"):
            del self.calls[:]
            f = C.fit_sources([(self._points(), [])], open_panel=False, Model=model)
            self.assertIsNotNone(f)
            self.assertEqual(self.calls, [model])       # main: [model, model]
            self.assertEqual(f.Status, "converged")
            # the figures are the fit's own: a fit of the same input now gives them
            gathered, notes, opts = self._gathered(f)
            again = core.fit_gathered(gathered, notes, **opts)
            self.assertEqual(f.Rms, again["rms"])
            self.assertEqual(f.BSplineDeviation, again["bspline_deviation"])
            self.assertEqual(list(f.Distances), [float(d) for d in again["distances"]])
            # a recompute of the same input fits nothing (kept.py), one of another fits
            del self.calls[:]
            f.touch()
            self.doc.recompute()
            self.assertEqual(self.calls, [])
            self.assertEqual(f.Rms, again["rms"])
            f.Tolerance = 2e-4
            self.doc.recompute()
            self.assertEqual(self.calls, [model])

    def test_a_changed_input_is_fitted_not_the_checked_one(self):
        """A check's fit is taken for its own input alone: other points or options fit."""
        pts = [App.Vector(x, 0.01 * x * x, 0) for x in range(0, 60, 3)]
        other = [App.Vector(x, 0.012 * x * x, 0) for x in range(0, 60, 3)]
        checked = core.check_fit((pts, None, True, False), [])
        a = core.fit_gathered((pts, None, True, False), [], checked)
        self.assertEqual(len(self.calls), 1)
        b = core.fit_gathered((other, None, True, False), [], checked)
        c = core.fit_gathered((pts, None, True, False), [], checked, model="smooth")
        self.assertEqual(len(self.calls), 3)
        self.assertEqual(a["rms"], checked[1]["rms"])
        self.assertNotEqual(a["rms"], b["rms"])
        self.assertNotEqual(a["bspline_deviation"], c["bspline_deviation"])

    def test_the_check_is_handed_to_its_feature(self):
        """The check's fit goes to the feature it was made for, on its proxy, before its first
        recompute, which takes it (main: a module dict, fit_core._ONCE, while the command
        ran)."""
        from freecad.elastica import fit
        seen, compute = [], fit.FitProxy.compute

        def spy(proxy, obj):
            seen.append(getattr(proxy, "checked", None))
            return compute(proxy, obj)
        fit.FitProxy.compute = spy
        try:
            f = C.fit_sources([(self._points(), [])], open_panel=False, Model="smooth")
        finally:
            fit.FitProxy.compute = compute
        self.assertEqual(len(seen), 1)
        self.assertIsNotNone(seen[0])
        self.assertEqual(seen[0][1]["rms"], f.Rms)
        self.assertIsNone(getattr(f.Proxy, "checked", None))     # taken: kept nowhere

    def _gathered(self, f):
        from freecad.elastica import fit, sources
        notes = []
        return (sources.gather_points(f.Source, f.CsvFile, f.SamplesPerEdge, link="Source",
                                      notes=notes), notes, fit.core_options(f))


if __name__ == "__main__":
    unittest.main()
