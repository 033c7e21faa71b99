"""freecadcmd -t tests that a feature's recompute takes its input key (kept.input_key, the
sha256 of its inputs and of the geometry it reads: ~26 ms on a 50 000-point Points object)
once: before it computes, and again after only where the computation set an input of its own
(a link renamed after its sketch's geometry, a spline's Closed following its wire), so that
the key kept is always that of the input the outcome is of. Before, every computation took
it twice (before, to compare with the kept one, and after)."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import kept, proxy

from test_elastica_container_moves import every_feature_from


class KeyOnceTest(S.DocTest):
    doc_name = "ElasticaKeyOnce"

    def setUp(self):
        super().setUp()
        self.keys = []
        original = proxy.input_key

        def spy(obj):
            self.keys.append(obj.Name)
            return original(obj)
        proxy.input_key = spy
        self.addCleanup(setattr, proxy, "input_key", original)

    def sketch(self, name):
        sk = self.doc.addObject("Sketcher::SketchObject", name)
        sk.Placement = App.Placement(App.Vector(3000, -1200, 40), App.Rotation(10, 20, 0))
        return sk

    def assertKeptIsNow(self, f):
        """The key kept is the input's as it is after the recompute."""
        self.assertEqual(f.Proxy._kept[0], kept.input_key(f), f.Name)

    def test_every_kind_takes_its_key_once_a_computation(self):
        made = [f for f, _ in every_feature_from(self, self.sketch)]
        for f in made:
            self.assertKeptIsNow(f)
        for f in made:                  # a typed input: computed again, one key
            del self.keys[:]
            f.Label2 = "x"              # no input: nothing
            f.touch()
            self.doc.recompute()
            self.assertEqual(self.keys, [f.Name], f"{f.Name} kept")
            del self.keys[:]
            if "Tolerance" in f.PropertiesList:
                f.Tolerance = float(f.Tolerance) * 2
            elif "Edges" in f.PropertiesList:      # the G2 quadratic
                f.Edges = f.Edges + 8
            else:                                  # the comb
                f.Scale = float(f.Scale) * 2 if f.Scale else 100.0
            self.doc.recompute()
            self.assertEqual(self.keys, [f.Name], f"{f.Name} computed")   # main: 2
            self.assertKeptIsNow(f)

    def test_a_points_scan_refitted_takes_its_key_once(self):
        """50 000 noisy points of a Points object, a Tolerance typed: one key."""
        from freecad.elastica import commands as C
        import numpy as np
        xy, _ = S.keyline_xy(50000)
        xy = xy * 40 + np.random.default_rng(5).normal(0.0, 0.05, xy.shape)
        pts = S.points_object(self.doc, xy)
        App.setActiveDocument(self.doc.Name)
        f = C.fit_sources([(pts, [])], open_panel=False, Model="smooth")
        del self.keys[:]
        f.Tolerance = 0.01
        self.doc.recompute()
        self.assertEqual(self.keys, [f.Name])                          # main: 2
        self.assertKeptIsNow(f)

    def test_an_input_set_by_the_computation_takes_the_key_again(self):
        """A spline whose wire was closed when last computed: its recompute sets SourceClosed
        (an input) as its points are open now; the key kept is that of after."""
        made = dict((f.Name, f) for f, _ in every_feature_from(self, self.sketch))
        sp = next(f for n, f in made.items() if n.startswith("ElasticaSpline"))
        sp.SourceClosed = True
        del self.keys[:]
        self.doc.recompute()
        self.assertFalse(sp.SourceClosed)
        self.assertEqual(self.keys, [sp.Name, sp.Name])
        self.assertKeptIsNow(sp)


if __name__ == "__main__":
    unittest.main()


class CallKeyTest(unittest.TestCase):
    """kept.call_key (a command's check handed to its feature) keyed a Part.Vertex as
    ('shape', 'Vertex', ()): every vertex one key, the hand of one taken for another; a Face
    by its edges only; any other object by repr() ('<BSplineCurve object>' for all). Now a
    vertex keys by its point, a shape with faces or an unknown type has no key (TypeError)
    and checked_call / handed compute."""

    def core(self, value):
        return ("computed", repr(value))

    def test_two_vertices_have_two_keys(self):
        import Part
        a, b = Part.Vertex(0, 0, 0), Part.Vertex(1, 2, 3)
        self.assertNotEqual(kept.call_key(self.core, a), kept.call_key(self.core, b))
        self.assertEqual(kept.call_key(self.core, a), kept.call_key(self.core, Part.Vertex(0, 0, 0)))
        ca, cb = Part.Compound([a]), Part.Compound([b])
        self.assertNotEqual(kept.call_key(self.core, ca), kept.call_key(self.core, cb))

    def test_unkeyable_values_are_computed(self):
        import Part
        face = Part.makePlane(1, 1)
        curve = Part.LineSegment(App.Vector(0, 0, 0), App.Vector(1, 0, 0))
        for value in (face, curve, {"a": 1}):
            with self.assertRaises(TypeError):
                kept.call_key(self.core, value)
            key, outcome = kept.checked_call(self.core, value)
            self.assertIsNone(key)
            p = proxy.FeatureProxy.__new__(proxy.FeatureProxy)
            p.checked = (key, ("handed", None))
            self.assertEqual(p.handed(self.core, value)[0], "computed")
