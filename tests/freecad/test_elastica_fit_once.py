"""freecadcmd -t test that the Fit command fits its input once: its check's fit is the new
feature's first recompute's (QA19gui F3: a 50 000-point Points object was fitted twice, the
GUI frozen 16 s), while every later recompute fits again."""
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
            # a recompute after the command fits again (nothing kept from it)
            del self.calls[:]
            f.touch()
            self.doc.recompute()
            self.assertEqual(self.calls, [model])
            self.assertEqual(f.Rms, again["rms"])

    def test_a_changed_input_is_fitted_not_the_checked_one(self):
        """Within the command's block a different input is fitted anew."""
        pts = [App.Vector(x, 0.01 * x * x, 0) for x in range(0, 60, 3)]
        other = [App.Vector(x, 0.012 * x * x, 0) for x in range(0, 60, 3)]
        with core.fitted_once():
            a = core.fit_gathered((pts, None, True, False), [])
            b = core.fit_gathered((other, None, True, False), [])
            c = core.fit_gathered((pts, None, True, False), [], model="smooth")
        self.assertEqual(len(self.calls), 3)
        self.assertNotEqual(a["rms"], b["rms"])
        self.assertNotEqual(a["bspline_deviation"], c["bspline_deviation"])

    def _gathered(self, f):
        from freecad.elastica import fit, sources
        notes = []
        return (sources.gather_points(f.Source, f.CsvFile, f.SamplesPerEdge, link="Source",
                                      notes=notes), notes, fit.core_options(f))


if __name__ == "__main__":
    unittest.main()
