"""freecadcmd -t test of Copy into '(new sketch ...)' from a sketch inside a PartDesign Body
(QA19gui F8): the panel's OK (the code it records, run here as the macro runs it) makes the new
sketch in that Body, as Sketcher's new sketch goes into the active Body, so it moves with it;
its copy lies on the feature; a source at the document's root keeps the new sketch there."""
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit, spline, taskpanels


class NewSketchBodyTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("NewSketchBody")
        self.body = self.doc.addObject("PartDesign::Body", "Body")
        self.body.Placement = App.Placement(App.Vector(100, -50, 30),
                                            App.Rotation(App.Vector(1, 1, 0), 35))
        self.sk = self.body.newObject("Sketcher::SketchObject", "Pts")
        self.sk.Placement = App.Placement(App.Vector(5, 0, 0), App.Rotation(App.Vector(0, 0, 1), 25))
        for x in range(0, 130, 10):
            self.sk.addGeometry(Part.Point(App.Vector(x, 0.002 * x * x, 0)), False)
        self.doc.recompute()

    def tearDown(self):
        App.closeDocument(self.doc.Name)

    def _ok_copy(self, panel_class, feature, sources):
        """The code OK records for Copy into '(new sketch ...)', run: the new sketch."""
        panel = panel_class.__new__(panel_class)
        panel.doc, panel.obj, panel.sketch_exclude = self.doc, feature, [o.Name for o in sources]
        panel.copy_target = lambda: "*new*"
        before = {o.Name for o in self.doc.Objects}
        exec(panel.copy_code(), {"App": App, "FreeCAD": App})
        self.doc.recompute()
        new = [o for o in self.doc.Objects if o.Name not in before]
        self.assertEqual([o.TypeId for o in new], ["Sketcher::SketchObject"])
        return new[0]

    def _on_feature(self, sketch, feature):
        shape = sketch.Shape.copy()
        shape.Placement = sketch.getGlobalPlacement()
        self.assertEqual(len(shape.Edges), 1)
        self.assertLess(shape.distToShape(feature.Shape)[0], 1e-9)
        for p in (0.0, 0.5, 1.0):
            e = shape.Edges[0]
            at = e.valueAt(e.FirstParameter + p * (e.LastParameter - e.FirstParameter))
            self.assertLess(feature.Shape.distToShape(Part.Vertex(at))[0], 1e-9)

    def test_the_new_sketch_goes_into_the_sources_body_and_moves_with_it(self):
        f = fit.make(self.doc, [(self.sk, [])], Model="smooth")
        s = spline.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        for panel_class, feature in ((taskpanels.FitPanel, f), (taskpanels.SplinePanel, s)):
            new = self._ok_copy(panel_class, feature, [self.sk])
            self.assertIn(new, self.body.Group)             # main: at the document's root
            self.assertIs(new.getParentGeoFeatureGroup(), self.body)
            self.assertLess(_apart(new.getGlobalPlacement(), feature.Plane), 1e-9)
            self._on_feature(new, feature)
            # the Body moved and turned: the copy with it, as the points it was drawn from
            gap = _start(new).distanceToPoint(_point(self.sk))
            self.body.Placement = App.Placement(App.Vector(-20, 40, 0),
                                                App.Rotation(App.Vector(0, 1, 0), 70))
            self.doc.recompute()
            self.assertAlmostEqual(_start(new).distanceToPoint(_point(self.sk)), gap, delta=1e-9)
            self.body.Placement = App.Placement(App.Vector(100, -50, 30),
                                                App.Rotation(App.Vector(1, 1, 0), 35))
            self.doc.recompute()

    def test_a_new_sketch_in_the_body_is_attached_to_its_xy_plane_where_the_curve_is(self):
        # the points' sketch in the Body unattached (no attachment to take): the new sketch
        # attached as Sketcher's new sketch in a Body, to the Body's XY plane, the curve's
        # plane its offset (main: MapMode Deactivated, Support [])
        s = spline.make(self.doc, [(self.sk, [])])
        self.doc.recompute()
        new = self._ok_copy(taskpanels.SplinePanel, s, [self.sk])
        xy = [o for o in self.body.Origin.OriginFeatures if o.Role == "XY_Plane"][0]
        self.assertEqual(new.MapMode, "FlatFace")
        self.assertEqual([o for o, _ in new.Support], [xy])
        self.assertLess(_apart(new.getGlobalPlacement(), s.Plane), 1e-9)
        self._on_feature(new, s)
        self.body.Placement = App.Placement(App.Vector(-20, 40, 0),
                                            App.Rotation(App.Vector(0, 1, 0), 70))
        self.doc.recompute()
        self.assertLess(_apart(new.Placement, self.sk.Placement), 1e-9)   # in the Body
        self._on_feature(new, s)
        self.assertNotIn("Invalid", new.State)

    def test_a_source_at_the_root_keeps_the_new_sketch_there(self):
        root = S.points_sketch(self.doc, S.keyline_xy(12)[0], "Root")
        f = fit.make(self.doc, [(root, [])], Model="smooth")
        self.doc.recompute()
        new = self._ok_copy(taskpanels.FitPanel, f, [root])
        self.assertIsNone(new.getParentGeoFeatureGroup())
        self.assertEqual(_apart(new.Placement, f.Plane), 0.0)
        self._on_feature(new, f)


def _apart(p, q):
    """The largest difference of two placements' matrices."""
    return max(abs(a - b) for a, b in zip(p.toMatrix().A, q.toMatrix().A))


def _start(sketch):
    """The start of a sketch's first edge, global."""
    e = sketch.Shape.Edges[0]
    return sketch.getGlobalPlacement().multVec(
        sketch.Placement.inverse().multVec(e.valueAt(e.FirstParameter)))


def _point(sketch):
    """A sketch's first point geometry, global."""
    g = sketch.Geometry[0]
    return sketch.getGlobalPlacement().multVec(App.Vector(g.X, g.Y, g.Z))


if __name__ == "__main__":
    unittest.main()
