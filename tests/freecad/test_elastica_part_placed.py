"""freecadcmd -t tests of features moved into a placed App::Part (moved and turned), into a
Part nested in another, and into the Part holding the Body of their sketches. FreeCAD draws
an object in an App::Part under the Part's placement: a Part::Feature's Shape is local to
its Part. The features computed their Shape in global coordinates (they read their sources
where they are drawn), and a feature dropped into a placed Part was drawn off by the
Part's placement (QA: the fit 120 mm from its points). Each test measures where FreeCAD
draws a feature: its Shape placed by its Part's global placement, taken from the Part
itself (getParentGeoFeatureGroup().getGlobalPlacement()), not from the workbench; a feature
in a Part must lie where it lay at document level, on its sketch, to 1e-9 mm."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import geometry as G
from freecad.elastica import proxy as X

from test_elastica_container_moves import PTS, every_feature_from

SKETCH = App.Placement(App.Vector(20, -10, 5), App.Rotation(App.Vector(0.2, 1, 0.3), 40))
PART = App.Placement(App.Vector(150, -80, 40), App.Rotation(App.Vector(1, 0.5, 0.2), 50))
INNER = App.Placement(App.Vector(-30, 45, 10), App.Rotation(App.Vector(0, 0, 1), 70))
ON = 1e-9           # mm: where a feature is drawn, against where it was at document level


def drawn(feature):
    """Points along the feature's edges (a comb's teeth too) where FreeCAD draws them:
    its Shape under the global placement of the container holding it."""
    parent = feature.getParentGeoFeatureGroup()
    plc = parent.getGlobalPlacement() if parent is not None else App.Placement()
    return [plc.multVec(p) for e in feature.Shape.Edges for p in e.discretize(Number=20)]


def sketch_points(sketch, xy):
    """The sketch points ``xy`` where the 3D view draws them."""
    return [sketch.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]


def moved(plc):
    """``plc`` moved by (60, -35, 25) and turned 30 deg about (1, 1, 0)."""
    return App.Placement(plc.Base + App.Vector(60, -35, 25),
                         App.Rotation(App.Vector(1, 1, 0), 30).multiply(plc.Rotation))


class PlacedPartTest(S.DocTest):
    doc_name = "ElasticaPlacedPart"

    def every_feature(self, holder=None):
        """[feature] of every kind the workbench makes (every_feature_from), from sketches at
        document level (or in ``holder``, a Body)."""
        def sketch(name):
            sk = (holder.newObject if holder is not None else
                  lambda t, n: self.doc.addObject(t, n))("Sketcher::SketchObject", name)
            sk.Placement = SKETCH
            return sk
        made = every_feature_from(self, sketch)
        self.dots = made[0][1]
        return [f for f, _ in made]

    def assertAt(self, made, before, what):
        """Each feature drawn where it was ``before`` (global points), to ON, up to date."""
        for f, old in zip(made, before):
            now = drawn(f)
            self.assertEqual(len(now), len(old), f"{f.Name} {what}")
            off = max((a - b).Length for a, b in zip(now, old))
            self.assertLess(off, ON, f"{f.Name} {what}: drawn {off:.3g} mm from its place")
            self.assertEqual(f.State, ["Up-to-date"], f"{f.Name} {what}")

    def assertSplineOnDots(self, made, what):
        """The spline's curve as drawn passes through its sketch points (the ducks)."""
        spline = made[2]
        parent = spline.getParentGeoFeatureGroup()
        plc = parent.getGlobalPlacement() if parent is not None else App.Placement()
        curve = spline.Shape.copy()
        curve.transformShape(plc.toMatrix(), True)
        self.assertLess(S.distance_to_shape(sketch_points(self.dots, PTS), curve), ON, what)

    def test_every_feature_moved_into_a_placed_part_is_drawn_where_it_was(self):
        made = self.every_feature()
        before = [drawn(f) for f in made]
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = PART
        for f in made:
            part.addObject(f)
        self.assertTrue(all("Touched" in f.State for f in made))      # to be drawn again
        self.doc.recompute()
        self.assertAt(made, before, "moved into the Part")
        self.assertSplineOnDots(made, "in the Part")
        part.Placement = moved(PART)          # its sketches stay: the features do too
        self.doc.recompute()
        self.assertAt(made, before, "Part moved and turned")
        self.assertSplineOnDots(made, "Part moved")
        for f in made:                        # and back out
            part.removeObject(f)
        self.doc.recompute()
        self.assertAt(made, before, "back at document level")

    def test_every_feature_in_a_part_in_a_placed_part_is_drawn_where_it_was(self):
        made = self.every_feature()
        before = [drawn(f) for f in made]
        outer = self.doc.addObject("App::Part", "Outer")
        outer.Placement = PART
        inner = self.doc.addObject("App::Part", "Inner")
        inner.Placement = INNER
        outer.addObject(inner)
        for f in made:
            inner.addObject(f)
        self.doc.recompute()
        self.assertAt(made, before, "moved into the inner Part")
        outer.Placement = moved(PART)
        self.doc.recompute()
        self.assertAt(made, before, "outer Part moved")
        inner.Placement = moved(INNER)
        self.doc.recompute()
        self.assertAt(made, before, "inner Part moved")
        self.assertSplineOnDots(made, "nested Parts moved")

    def test_features_in_the_placed_part_holding_their_sketches_body_move_with_it(self):
        """The sketches in a Body in a placed Part, the features dropped into the Part:
        on their sketches, and moving with the Part as its Body does."""
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = PART
        body = self.doc.addObject("PartDesign::Body", "Body")
        body.Placement = INNER
        part.addObject(body)
        made = self.every_feature(holder=body)

        def on_sketch():       # the features' points in the coordinates of their Body
            inv = body.getGlobalPlacement().inverse()
            return [[inv.multVec(p) for p in drawn(f)] for f in made]
        before = on_sketch()
        for f in made:
            part.addObject(f)
        self.doc.recompute()
        for what in ("dropped into the Part", "Part moved and turned"):
            for f, old, now in zip(made, before, on_sketch()):
                off = max((a - b).Length for a, b in zip(now, old))
                self.assertLess(off, ON, f"{f.Name} {what}: {off:.3g} mm off its sketch")
                self.assertEqual(f.State, ["Up-to-date"], f"{f.Name} {what}")
            part.Placement = moved(PART)
            self.doc.recompute()
        self.assertSplineOnDots(made, "Part moved")

    def test_a_copy_into_a_sketch_from_a_feature_in_a_placed_part_lands_on_it(self):
        made = self.every_feature()
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = PART
        fit = made[0]
        part.addObject(fit)
        self.doc.recompute()
        target = self.doc.addObject("Sketcher::SketchObject", "Target")
        target.Placement = fit.Plane
        ids = G.write_to_sketch(fit, target)
        self.doc.recompute()
        self.assertEqual(len(ids), 1)
        copied = G.global_shape(target).Edges[-1]
        self.assertLess(S.distance_to_shape([tuple(p) for p in drawn(fit)], copied), 1e-7)

    def test_a_document_saved_before_reopens_its_features_where_they_belong(self):
        """A document saved by version 4 with features in a placed Part (their Shape
        global, drawn off by the Part): reopened, they execute once and are drawn on their
        sketches."""
        self.reopen_version4(saved_again=False)

    def test_a_document_saved_before_and_saved_again_unrecomputed_reopens_right(self):
        """The same document opened and saved at once (no recompute: the Shapes still
        global), then reopened: its features execute once and are drawn on their sketches
        (they were taken as local to the Part and left 170 mm off)."""
        self.reopen_version4(saved_again=True)

    def reopen_version4(self, saved_again):
        """Features in a placed Part saved by version 4 (and, ``saved_again``, that file
        opened and saved by this version before a recompute), reopened and recomputed."""
        made = self.every_feature()
        before = [drawn(f) for f in made]
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = PART
        for f in made:
            part.addObject(f)
        self.doc.recompute()
        for f in made:                         # as version 4 left them: global shapes
            shape = f.Shape.copy()
            shape.transformShape(PART.toMatrix(), True)
            f.Shape = shape
        self.assertGreater(max((a - b).Length for a, b in zip(drawn(made[0]), before[0])), 10)
        current = X.VERSION
        self.addCleanup(setattr, X, "VERSION", current)
        X.VERSION = 4
        names = [f.Name for f in made]
        made = S.reopened(self, "version4_part.FCStd", *names)
        if saved_again:
            X.VERSION = current
            made = S.reopened(self, "version4_saved_again.FCStd", *names)
        self.doc.recompute()
        self.assertAt(made, before, "reopened")

    def test_a_failed_features_kept_curve_stays_on_its_sources_as_the_part_moves(self):
        """A failed recompute keeps the last Shape (drawn dashed); its Part moved since, it is
        drawn where it was, on its sketch, and the feature is not left to execute again
        (review revfc 4: the old spline drawn 123 mm off, mustExecute True, until it computed
        again)."""
        made = self.every_feature()
        spline, comb = made[2], made[6]
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = PART
        part.addObject(spline)
        part.addObject(comb)
        self.doc.recompute()
        before = [drawn(spline), drawn(comb)]
        spline.Degree = 1                   # an error: said, the last shape kept
        comb.Samples = 1
        self.doc.recompute()
        self.assertTrue(spline.Status.startswith("error"), spline.Status)
        self.assertTrue(comb.Status.startswith("error"), comb.Status)
        for _ in range(2):
            part.Placement = moved(part.Placement)
            self.doc.recompute()
            for f, old in zip((spline, comb), before):
                off = max((a - b).Length for a, b in zip(drawn(f), old))
                self.assertLess(off, ON, f"{f.Name}: drawn {off:.3g} mm from its sketch")
                self.assertFalse(f.Proxy.mustExecute(f), f.Name)
                self.assertTrue(f.Status.startswith("error"), f.Status)


if __name__ == "__main__":
    unittest.main()
