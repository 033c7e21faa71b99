"""freecadcmd -t test that every command computes its feature once at creation: the outcome
its check computed to judge the input (kept.checked_call) is handed to the new feature,
whose first recompute takes it (FeatureProxy.handed), as the Fit command's fit is
(test_elastica_fit_once). Before, the Elastic spline, the Elastic and elliptic blends and the
G2 quadratic B-spline were computed twice at creation: in the command's check and at the
feature's first recompute. The library's own functions are counted (the binding's, wrapped
here), and the feature made so is compared with one recomputed afresh. The sketches are
placed (S.SKETCH_PLACEMENT): the command reads a sketch's edge as its feature does
(links.element_as_followed), not 1 ulp off through Part.getShape (computed again)."""
import math
import sys
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica.geometry import el
from freecad.elastica.proxy import FeatureProxy

# hand-sketched dots along a wave (unevenly spaced, off the origin)
PTS = [(1200.0 + x, -300.0 + 25 * math.sin(x / 40.0) + 0.002 * x * x)
       for x in (0, 9, 21, 30, 42, 49, 61, 70, 83, 90, 101, 110, 122)]
SPIKE = [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]     # no free batten


class CreateOnceTest(S.DocTest):
    doc_name = "ElasticaCreateOnce"

    def setUp(self):
        super().setUp()
        self.calls, self.wrapped, self.executing = [], [], []
        execute = FeatureProxy.execute

        def spy(proxy, obj):
            self.executing.append(obj.Name)
            try:
                return execute(proxy, obj)
            finally:
                self.executing.pop()
        FeatureProxy.execute = spy
        self.execute = execute

    def tearDown(self):
        FeatureProxy.execute = self.execute
        for owner, name, fn in self.wrapped:
            setattr(owner, name, fn)
        super().tearDown()

    def _count(self, name):
        """Count the calls of the binding's el.<name> (the workbench calls el().<name>)."""
        owner = el()                    # el.fit is the function: its module's (fit_core's)
        owner = sys.modules["libelastica.fit"] if name == "fit" else owner
        fn = getattr(owner, name)
        self.wrapped.append((owner, name, fn))

        def spy(*args, **kwargs):
            self.calls.append(tuple(self.executing))      # in a feature's recompute
            return fn(*args, **kwargs)
        setattr(owner, name, spy)

    def _dots(self, name, pts):
        return S.points_sketch(self.doc, pts, name)

    def _created_once(self, binding, make):
        """The feature ``make()`` creates: its creation calls el.<binding> as often as one
        recompute of the same input does afresh, and gives the very same outcome."""
        self._count(binding)
        App.setActiveDocument(self.doc.Name)
        f = make()
        self.assertIsNotNone(f)
        self.assertFalse(f.Status.startswith("error"), f.Status)
        created = len(self.calls)
        self.assertEqual([c for c in self.calls if c], [])      # in the check only
        self.assertIsNone(getattr(f.Proxy, "checked", None))        # taken, kept nowhere
        outcome = self._result_of(f)
        del self.calls[:]
        f.Proxy._kept = None            # no kept outcome (kept.py): the feature computes
        f.touch()
        self.doc.recompute()
        once = len(self.calls)
        self.assertGreater(once, 0)
        self.assertEqual(created, once, f"{f.Name}: {created} calls of el.{binding} at "
                         f"creation, {once} in a recompute")      # main: twice
        self.assertEqual(self._result_of(f), outcome)
        return f

    @staticmethod
    def _result_of(f):
        """The feature's shape (its BRep) and every result property, exactly."""
        props = {p: repr(getattr(f, p)) for p in f.PropertiesList
                 if f.getGroupOfProperty(p) == "Result"}
        return f.Shape.exportBrepToString(), props

    def test_spline_is_solved_once(self):
        dots = self._dots("Dots", PTS)
        self._created_once("elastic_spline", lambda: C.spline_sources([(dots, [])], False))

    def test_spline_at_its_starting_tension_is_solved_once(self):
        """No free batten through the spike: the command's search for a tension ends in the
        spline the feature shows, not solved again at its first recompute."""
        dots = self._dots("Spike", SPIKE)
        self._count("elastic_spline")
        App.setActiveDocument(self.doc.Name)
        f = C.spline_sources([(dots, [])], False)
        self.assertEqual(f.Tension, 6.57e-4)   # the least that holds
        self._first_recompute_took_it(f, "elastic_spline")

    def test_elliptic_blend_is_computed_once(self):
        dots = self._dots("Dots", PTS[::3])
        self._created_once("blend_curve", lambda: C.ellblend_sources([(dots, [])], False))

    def test_g2_quadratic_is_computed_once(self):
        sk = S.bspline_sketch(self.doc, PTS, "Curve")
        self._created_once("g2_quadratic",
                           lambda: C.g2quad_sources([(sk, ["Edge1"])], False, Edges=51))

    def test_fit_of_a_placed_sketch_edge_is_fitted_once(self):
        """The Fit command's check is its feature's fit for a picked edge of a placed sketch
        too (its sampled points were 1 ulp off the feature's: fitted twice)."""
        sk = S.bspline_sketch(self.doc, PTS, "Curve")
        self._created_once("fit", lambda: C.fit_sources([(sk, ["Edge1"])], False,
                                                         Model="smooth"))

    def test_blend_is_solved_once(self):
        sk = self.doc.addObject("Sketcher::SketchObject", "Lines")
        sk.Placement = S.SKETCH_PLACEMENT
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(40, 0, 0)), False)
        sk.addGeometry(Part.LineSegment(App.Vector(80, 25, 0), App.Vector(120, 35, 0)), False)
        self.doc.recompute()
        self._created_once("hermite", lambda: C.blend_sources(
            [(sk, ["Edge1"]), (sk, ["Edge2"])], False))

    def test_blend_at_its_starting_length_is_solved_once(self):
        """A line's end and an arc's no free batten joins: the command's search for a
        length ends in the blend the feature shows, not solved again."""
        sk = S.line_and_arc_sketch(self.doc)
        self._count("hermite")
        App.setActiveDocument(self.doc.Name)
        f = C.blend_sources([(sk, ["Edge1"]), (sk, ["Edge2"])], False)
        self.assertEqual((f.Mode, float(f.Length)), ("length", 112.0))
        self._first_recompute_took_it(f, "hermite")

    def _first_recompute_took_it(self, f, binding):
        """The feature's first recompute (by the command) called no el.<binding> (the
        command's search did, in its check); the feature recomputed afresh is the same."""
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertGreater(len(self.calls), 0)
        self.assertEqual([c for c in self.calls if c], [])      # main: the search's winner
        self.assertIsNone(getattr(f.Proxy, "checked", None))
        outcome = self._result_of(f)
        del self.calls[:]
        f.Proxy._kept = None
        f.touch()
        self.doc.recompute()
        self.assertGreater(len(self.calls), 0)
        self.assertEqual(self._result_of(f), outcome)


if __name__ == "__main__":
    unittest.main()
