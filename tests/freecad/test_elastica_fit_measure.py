"""freecadcmd -t tests of what a fit's Rms, MaxError and Distances measure: the user's
own points (never a resampled polygon's vertices) to the curve drawn, in 3D (a point's
distance from the fit plane included), checked against Part's distToShape; and the
warnings when points lie off their plane or beyond the ends of a resampled fit."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import units as U
from freecad.elastica import fit as Fi


def measured(f, points):
    """The points' distances to the feature's shape, by Part (distToShape)."""
    return [f.Shape.distToShape(Part.Vertex(p))[0] for p in points]


class FitMeasureTest(S.DocTest):
    doc_name = "ElasticaFitMeasure"

    def _check_figures(self, f, points, delta):
        """Rms, MaxError, Distances and DataPoints are the points' own, in 3D."""
        self.assertFalse(f.Status.startswith("error"), f.Status)
        d = measured(f, points)
        self.assertEqual(len(f.DataPoints), len(points))
        self.assertLess(max((a - b).Length for a, b in zip(f.DataPoints, points)), 1e-9)
        self.assertLess(max(abs(abs(a) - b) for a, b in zip(f.Distances, d)), delta)
        self.assertAlmostEqual(f.Rms, math.sqrt(sum(x * x for x in d) / len(d)), delta=delta)
        self.assertAlmostEqual(f.MaxError, max(d), delta=delta)

    def test_points_off_their_plane_are_measured_in_3d(self):
        # a scanned keyline, its points alternately 0.5 mm either side of the plane
        pts = [App.Vector(x, 15 * math.sin(x / 40.0), 0.5 if i % 2 else -0.5)
               for i, x in enumerate(range(0, 121, 6))]
        wire = self.doc.addObject("Part::Feature", "Scan")
        wire.Shape = Part.makePolygon(pts)
        self.doc.recompute()
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(wire, [])], Model=model)
            self.doc.recompute()
            # a smooth fit's distances are the library's, to the elastica: the B-spline lies
            # within its Tolerance of that
            self._check_figures(f, pts, f.Tolerance.Value if model == "smooth" else 1e-6)
            self.assertGreater(f.Rms, 0.45)            # in the plane alone: 0.02 mm
            self.assertIn("in 3D", f.ErrorMeasure)
            said = [w for w in f.Warnings if "off their plane" in w]
            self.assertEqual(len(said), 1, list(f.Warnings))
            # (the best plane of the zigzag is a little tilted: 0.59 mm, rms 0.497 mm)
            self.assertRegex(said[0], r"up to 0\.[56]\d* mm \(rms 0\.[45]\d* mm\) off their "
                                      r"plane, the fit's: Rms and MaxError include that")

    def test_point_numbers_say_which_point_each_figure_is(self):
        """QA22gui F3: a fit of hand-clicked sketch points lists Distances in DataPoints' order,
        the fit's along the curve: where two clicked neighbours lie close it is not the order
        drawn (15/16, 20/21, 26/27, 35/36 of 40 swapped), so Distances[i] was not the sketch's
        point i, and neither the panel nor the property view said so. PointNumbers gives each
        one's number as drawn, and the panel says the lists run along the curve."""
        import random
        import types
        from freecad.elastica import taskpanels as T
        rnd = random.Random(3)
        xy = [(3.0 * i + rnd.uniform(-0.8, 0.8), 12 * math.sin(i / 6.0) + rnd.uniform(-0.8, 0.8))
              for i in range(40)]
        for a in (6, 21, 33):                       # clicked out of turn: a neighbour first
            xy[a], xy[a + 1] = xy[a + 1], xy[a]
        sk = S.points_sketch(self.doc, xy, name="Clicks")
        points = [sk.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            numbers = list(f.PointNumbers)
            self.assertEqual(sorted(numbers), list(range(1, 41)))
            self.assertNotEqual(numbers, list(range(1, 41)))
            # DataPoints[i], Distances[i], FootPoints[i] are the drawn point PointNumbers[i]'s
            given = [points[i - 1] for i in numbers]
            self._check_figures(f, given, f.Tolerance.Value if model == "smooth" else 1e-6)
            for p, q, d in zip(given, f.FootPoints, f.Distances):
                self.assertAlmostEqual((p - q).Length, abs(d), delta=1e-6)
            text = T.FitPanel.result_text(types.SimpleNamespace(obj=f))
            self.assertTrue(text.startswith("40 points taken along the curve, not in the order "
                                            "given (DataPoints and Distances in the fit's order; "
                                            "PointNumbers: each one's number as given), "), text)
        # drawn in curve order: 1 .. n, and the panel as before
        line = S.points_sketch(self.doc, [(3.0 * i, 12 * math.sin(i / 6.0)) for i in range(20)],
                               name="InOrder")
        f = Fi.make(self.doc, [(line, [])], Model="smooth")
        self.doc.recompute()
        self.assertEqual(list(f.PointNumbers), list(range(1, 21)))
        text = T.FitPanel.result_text(types.SimpleNamespace(obj=f))
        self.assertTrue(text.startswith("20 points, point to curve"), text)

    def test_a_document_saved_before_point_numbers_opens(self):
        """A fit saved before PointNumbers (the property removed before saving) opens with
        it empty, the panel saying no order, and fills it at its next recompute."""
        import types
        from freecad.elastica import taskpanels as T
        sk = S.points_sketch(self.doc, [(3.0 * i, 12 * math.sin(i / 6.0)) for i in range(20)])
        f = Fi.make(self.doc, [(sk, [])], Model="smooth")
        self.doc.recompute()
        f.removeProperty("PointNumbers")
        f, = S.reopened(self, "before_numbers.FCStd", f.Name)
        self.assertIn("PointNumbers", f.PropertiesList)
        self.assertEqual(list(f.PointNumbers), [])
        self.assertTrue(T.FitPanel.result_text(types.SimpleNamespace(obj=f)).startswith(
            "20 points, point to curve"))
        f.touch()
        self.doc.recompute()
        self.assertEqual(list(f.PointNumbers), list(range(1, 21)))

    def test_a_sparse_discrete_keyline_warns_naming_the_smooth_model(self):
        """QA17 W4 (fc/f8): 8 sketched points on an S, split at the inflection: the discrete
        keyline lay 1.45 mm from them (the smooth one 0.042 mm) without a warning; it now
        names the smooth keyline and Model Smooth elastica, as a one-piece fit's does."""
        xy, _ = S.keyline_xy(8)
        xy = xy + S.np.random.default_rng(8).normal(0, 0.3, xy.shape)
        ps = S.points_sketch(self.doc, xy)
        rms, said = {}, {}
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(ps, [])], Model=model, SplitAtInflection=True)
            self.doc.recompute()
            self.assertFalse(f.Status.startswith("error"), f.Status)
            rms[model] = f.Rms
            said[model] = [w for w in f.Warnings if "smooth keyline" in w]
        self.assertGreater(rms["discrete"], 10 * rms["smooth"])
        self.assertEqual(said["smooth"], [])
        self.assertEqual(len(said["discrete"]), 1, said)
        self.assertRegex(said["discrete"][0], r"^the discrete keyline of 8 points lies 1\.\d+ mm "
                         r"from them \(rms\), where the smooth keyline lies .* choose Model "
                         r"Smooth elastica for so few points$")

    def test_points_in_their_plane_give_no_plane_warning(self):
        xy, _ = S.keyline_xy(40)
        f = Fi.make(self.doc, [(S.polyline_3d(self.doc, xy), [])], Model="smooth")
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertEqual(list(f.Warnings), [])
        self.assertNotIn("3D", f.ErrorMeasure)
        self.assertLess(f.Rms, 1e-3)

    def test_warnings_follow_the_unit_schema(self):
        """Noise-free points fitted resampled: the warning says the curve's rms in length
        where their own fit passes through them (it said '1.5e+13 x their own fit's
        7.74e-14 mm'); under Imperial decimal it and the errors give lengths in inches
        (they said mm beside boxes in inches) from the exact figures, not the mm text's, and
        a panel opened after a schema change says them in the new one (proxy.said)."""
        import numpy as np
        import libelastica as el
        from freecad.elastica.proxy import said
        c = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1e-3, k=0.8, q=0.0, length=150.0)
        sk = S.points_sketch(self.doc, c.points(np.linspace(0, c.length, 60)))
        f = Fi.make(self.doc, [(sk, [])], Model="discrete", ResampleStep=20.0)
        self.doc.recompute()
        warned = [w for w in f.Warnings if "resampled at" in w]
        self.assertEqual(len(warned), 1, list(f.Warnings))
        self.assertIn(f"resampled at 20.00 mm lies {U.number_text(f.Rms)} mm from them (rms), where their "
                      "own fit passes through them", warned[0])
        schema = App.Units.getSchema()
        try:
            App.Units.setSchema(3)
            shown = said(f, "Warnings")
            # the exact rms in inches (it said 0.0465 in: 1.18 mm, the mm text's, / 25.4)
            self.assertEqual(f"{f.Rms / 25.4:.3g}", "0.0464")
            self.assertIn("resampled at 0.79 in lies 0.046 in from them", shown[0])
            f.touch()
            self.doc.recompute()                   # what a recompute under Imperial writes
            self.assertEqual(list(f.Warnings), shown)
            self.assertFalse([w for w in f.Warnings if "mm" in w], list(f.Warnings))
            f.ResampleStep = 300.0                 # longer than the points reach
            self.doc.recompute()
            self.assertTrue(f.Status.startswith("error: Resample = 11.81 in is"), f.Status)
            self.assertNotIn("mm", f.Status)
            App.Units.setSchema(0)
            self.assertTrue(said(f, "Status").startswith("error: Resample = 300.00 mm is"),
                            said(f, "Status"))
        finally:
            App.Units.setSchema(schema)

    def test_errors_give_exact_lengths_in_the_schema(self):
        """The Resample errors write their lengths by the exact value in the schema's unit
        (units.exact_mark), not their 4-digit mm text converted afterwards: points reaching
        31.355792 mm = 1.23448 in from their start, refused a 5000 mm step under Imperial
        decimal, are 'all within 1.234 in' at 3 decimals (the text '31.36 mm' converted said
        1.235 in); at FreeCAD's default 2 '1.23 in'; under Standard the text is as before."""
        reach = 1.23448 * 25.4
        xy = [(reach * i / 19, 2.0 * math.sin(math.pi * i / 19)) for i in range(20)]
        f = Fi.make(self.doc, [(S.points_sketch(self.doc, xy), [])], ResampleStep=5000.0)
        schema = App.Units.getSchema()
        try:
            App.Units.setSchema(0)
            self.doc.recompute()
            self.assertIn("error: Resample = 5000.00 mm is longer than the points reach (all "
                          "within 31.36 mm of the end", f.Status)
            App.Units.setSchema(3)
            f.touch()
            self.doc.recompute()
            self.assertIn("error: Resample = 196.85 in is longer than the points reach (all "
                          "within 1.23 in of the end", f.Status)
            self.assertNotIn("mm", f.Status)
        finally:
            App.Units.setSchema(schema)

    def test_length_property_docs_name_no_unit(self):
        """The length properties (App::PropertyDistance) show their value in the user's
        schema in the property editor: their documentation says no '(mm)' beside it."""
        from freecad.elastica import blend as Bl, ellblend as Eb, spline as Sp
        sk = S.points_sketch(self.doc, [(0, 0), (30, 10), (60, 5), (90, 20)])
        lines = S.two_lines_sketch(self.doc)
        made = {"fit": Fi.make(self.doc, [(sk, [])]),
                "spline": Sp.make(self.doc, [(sk, [])]),
                "ellblend": Eb.make(self.doc, [(sk, [])]),
                "blend": Bl.make(self.doc, (lines, "Edge1"), (lines, "Edge2"))}
        self.assertTrue(all(any(o.getTypeIdOfProperty(p) == "App::PropertyDistance"
                                for p in o.PropertiesList) for o in made.values()))
        for what, obj in made.items():
            for prop in obj.PropertiesList:
                if obj.getTypeIdOfProperty(prop) == "App::PropertyDistance":
                    self.assertNotIn("(mm", obj.getDocumentationOfProperty(prop), (what, prop))

    def test_a_resampled_fit_is_measured_from_the_points_given(self):
        # 15 points, the last at x = 98: an equilateral polygon of 5 mm stops 3.7 mm short;
        # the library's resampled polygon (el.resampled_polygon) ends at the last point, so
        # the curve reaches it (before: MaxError 3.7 mm there, "beyond the curve's ends")
        xy = [(x, 0.004 * x * x - 0.00003 * x ** 3) for x in range(0, 101, 7)]
        sk = S.points_sketch(self.doc, xy)
        pts = [sk.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]
        for model in ("smooth", "discrete"):
            f = Fi.make(self.doc, [(sk, [])], Model=model, ResampleStep=5.0)
            self.doc.recompute()
            self._check_figures(f, pts, 1e-6)
            self.assertLess(f.MaxError, 0.05, model)
            self.assertIn("not the resampled polygon", f.ErrorMeasure)
            self.assertFalse([w for w in f.Warnings if "beyond" in w], list(f.Warnings))

    def test_a_resampled_noisy_scan_fits_as_close_as_the_points(self):
        """A 4 m elastica scanned by 1000 unevenly spaced points (noise 0.5 mm), resampled
        from below their spacing to 5 % of the length: the points lie within 1.2 x (rms) of
        the curve as of their own fit, or the feature says how far, with the figures (the
        QA's 2000 points: discrete at 2 mm rms 13.2, h held at the step bulged the curve
        through the noise's zigzag; at 50 mm rms 3.2, max 49 mm past the polygon's end)."""
        import numpy as np
        import libelastica as el
        ref = el.SmoothElastica(x0=0, y0=0, phi=0.25, mu=1.2e-6, k=0.6, q=0.3, length=4000.0)
        rng = np.random.default_rng(1)
        xy = ref.points(np.sort(rng.uniform(0.0, 4000.0, 1000))) + rng.normal(0.0, 0.5, (1000, 2))
        sk = S.points_sketch(self.doc, xy, "Scan")
        pts = [sk.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]
        for model in ("discrete", "smooth"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            own = f.Rms
            for step in (2.0, 10.0, 50.0, 200.0):
                f.ResampleStep = step
                self.doc.recompute()
                what = (model, step, f.Rms, own, list(f.Warnings))
                self.assertIn("converged", f.Status, what)
                self.assertFalse([w for w in f.Warnings if "beyond" in w], what)
                said = [w for w in f.Warnings if "resampled at" in w]
                if f.Rms > 1.2 * own:          # the discrete cubic of 21 vertices: 2.2 x
                    self.assertEqual(len(said), 1, what)
                    self.assertIn(f"lies {f.Rms:.3g} mm from them (rms)", said[0])
                else:
                    self.assertEqual(said, [], what)
                    self.assertLess(f.MaxError, 2.5, what)
            # Rms is the points' to the curve drawn (Part's distToShape; the points in curve order)
            d = measured(f, pts)
            self.assertAlmostEqual(f.Rms, math.sqrt(sum(x * x for x in d) / len(d)),
                                   delta=1e-6 if model == "discrete" else f.Tolerance.Value)


if __name__ == "__main__":
    unittest.main()
