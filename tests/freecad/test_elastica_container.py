"""freecadcmd -t tests of sources inside a container placed off the origin (a PartDesign
Body at z = 100 tilted 30 deg, the sketch placed in it): every feature reads them where
the 3D view draws them. A sketch's Shape is in its Body's coordinates while its plane is
its global placement: a fit of a sketch edge lay 89 mm from the edge drawn (Rms 5e-5
reported), a blend started 89 / 77 mm from the lines' ends, the G2 quadratic lay 89 mm
off, and every feature warned 'Link(s) ... go out of the allowed scope' (QA). Each test
measures against the sketch as drawn: its Shape placed by the Body's placement, taken
here from the Body itself, not from the workbench."""
import os
import sys
import tempfile
import unittest
from contextlib import contextmanager

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import geometry as G
from freecad.elastica import proxy as X

BODY_PLACEMENT = App.Placement(App.Vector(30, -20, 100), App.Rotation(App.Vector(1, 0.3, 0), 30))
SKETCH_IN_BODY = App.Placement(App.Vector(7, 4, 0), App.Rotation(App.Vector(0, 0, 1), 15))


@contextmanager
def console_output():
    """What FreeCAD's console prints meanwhile (its warnings go to the process's stdout /
    stderr; 0.20's Python has no console observer): a list holding the text at the end."""
    out = []
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with tempfile.TemporaryFile() as f:
        os.dup2(f.fileno(), 1)
        os.dup2(f.fileno(), 2)
        try:
            yield out
        finally:
            sys.stdout.flush()
            sys.stderr.flush()
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])
            f.seek(0)
            out.append(f.read().decode(errors="replace"))


def scope_warnings(text):
    """The lines of console text that warn of links out of their allowed scope."""
    return [line.strip() for line in text.replace("\r", "\n").split("\n")
            if "allowed scope" in line]


def sample(shape, n=60):
    """n points along each edge of a shape."""
    return [tuple(p) for e in shape.Edges for p in e.discretize(n)]


class ContainerTest(S.DocTest):
    doc_name = "ElasticaContainer"

    def setUp(self):
        super().setUp()
        self.body = self.doc.addObject("PartDesign::Body", "Body")
        self.body.Placement = BODY_PLACEMENT
        sk = self.body.newObject("Sketcher::SketchObject", "Sketch")
        sk.Placement = SKETCH_IN_BODY
        xy, _ = S.keyline_xy(20, length=150)
        bs = Part.BSplineCurve()
        bs.interpolate([App.Vector(x, y, 0) for x, y in xy])
        sk.addGeometry(bs, False)                                                   # Edge1
        sk.addGeometry(Part.LineSegment(App.Vector(-60, 0, 0), App.Vector(-20, 0, 0)), False)
        sk.addGeometry(Part.LineSegment(App.Vector(0, -60, 0), App.Vector(0, -20, 0)), False)
        self.sk = sk
        self.doc.recompute()

    def drawn(self, sketch=None):
        """The sketch's shape where the 3D view draws it: placed by the Body."""
        shape = (sketch or self.sk).Shape.copy()
        shape.Placement = self.body.Placement.multiply(shape.Placement)
        return shape

    def assertOnEachOther(self, result, drawn, tol):
        """Result and drawn curve within tol of each other, both ways."""
        self.assertLess(S.distance_to_shape(sample(result), drawn), tol)
        self.assertLess(S.distance_to_shape(sample(drawn), result), tol)

    def test_a_fit_of_a_sketch_edge_in_a_body_lies_on_the_edge_drawn(self):
        f = C.fit_sources([(self.sk, ["Edge1"])], open_panel=False, Model="smooth")
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertLess(f.Rms, 1e-3)
        edge = self.drawn().Edges[0]
        self.assertOnEachOther(f.Shape, edge, 1e-3)
        plane = self.sk.getGlobalPlacement()
        self.assertLess((f.Plane.Base - plane.Base).Length, 1e-9)
        self.assertLess(f.Plane.Rotation.multiply(plane.Rotation.inverted()).Angle, 1e-9)

    def test_a_blend_between_sketch_lines_in_a_body_starts_and_ends_at_them(self):
        b = C.blend_sources([(self.sk, ["Edge2"]), (self.sk, ["Edge3"])], open_panel=False)
        self.assertIsNotNone(b)
        self.doc.recompute()
        self.assertFalse(b.Status.startswith("error"), b.Status)
        drawn = self.drawn()
        e2, e3 = drawn.Edges[1], drawn.Edges[2]
        c = b.Shape.Edges[0]
        start, end = c.valueAt(c.FirstParameter), c.valueAt(c.LastParameter)
        # the lines' inner ends (x = -20 on Edge2, y = -20 on Edge3) are the nearest pair
        self.assertLess((start - e2.Vertexes[1].Point).Length, 1e-7)
        self.assertLess((end - e3.Vertexes[1].Point).Length, 1e-7)
        # leaving along Edge2's direction, arriving along Edge3's
        self.assertLess(c.tangentAt(c.FirstParameter).normalize().getAngle(
            e2.tangentAt(e2.LastParameter)), 1e-7)
        self.assertLess(c.tangentAt(c.LastParameter).normalize().getAngle(
            e3.tangentAt(e3.FirstParameter) * -1), 1e-7)

    def test_a_spline_through_sketch_vertices_in_a_body_passes_them_as_drawn(self):
        """Picked vertices of a polyline sketch (VertexN), and the whole sketch (its one
        wire's vertices); a sketch of sketch points was read placed already."""
        poly = self.body.newObject("Sketcher::SketchObject", "Polyline")
        poly.Placement = SKETCH_IN_BODY
        ducks = [(0, 0), (30, 12), (60, 15), (90, 5), (120, -10)]
        for (x0, y0), (x1, y1) in zip(ducks, ducks[1:]):
            poly.addGeometry(Part.LineSegment(App.Vector(x0, y0, 0), App.Vector(x1, y1, 0)))
        dots = self.body.newObject("Sketcher::SketchObject", "Dots")
        dots.Placement = SKETCH_IN_BODY
        for x, y in ducks:
            dots.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
        self.doc.recompute()
        drawn = [v.Point for v in self.drawn(poly).Wires[0].OrderedVertexes]
        plc = self.body.Placement.multiply(SKETCH_IN_BODY)
        self.assertLess(max((plc.multVec(App.Vector(x, y, 0)) - p).Length
                            for (x, y), p in zip(ducks, drawn)), 1e-9)
        n = len(poly.Shape.Vertexes)
        picked = [(poly, [f"Vertex{i + 1}" for i in range(n)])]
        for name, sources in (("picked", picked), ("whole", [(poly, [])]),
                              ("points", [(dots, [])])):
            with self.subTest(name):
                sp = C.spline_sources(sources, open_panel=False)
                self.assertIsNotNone(sp)
                self.doc.recompute()
                self.assertFalse(sp.Status.startswith("error"), sp.Status)
                self.assertLess(max(sp.Shape.distToShape(Part.Vertex(p))[0] for p in drawn),
                                1e-6)

    def test_a_g2_quadratic_of_a_sketch_edge_in_a_body_lies_on_the_edge_drawn(self):
        g = C.g2quad_sources([(self.sk, ["Edge1"])], open_panel=False)
        self.assertIsNotNone(g)
        self.doc.recompute()
        self.assertFalse(g.Status.startswith("error"), g.Status)
        self.assertLess(S.distance_to_shape(sample(g.Shape), self.drawn().Edges[0]),
                        max(0.05, 2 * g.Deviation))
        ends = [g.Shape.Vertexes[0].Point, g.Shape.Vertexes[-1].Point]
        drawn_ends = [v.Point for v in self.drawn().Edges[0].Vertexes]
        self.assertLess(max(min((a - b).Length for b in drawn_ends) for a in ends), 1e-6)

    def test_a_comb_of_a_sketch_edge_in_a_body_stands_on_the_edge_drawn(self):
        App.setActiveDocument(self.doc.Name)
        C.comb_sources([(self.sk, ["Edge1"])])
        self.doc.recompute()
        comb = [o for o in self.doc.Objects if o.Name.startswith("ElasticaComb")]
        self.assertEqual(len(comb), 1)
        self.assertFalse(comb[0].Status.startswith("error"), comb[0].Status)
        feet = [s.Vertexes[0].Point for s in comb[0].Shape.childShapes() if s.ShapeType == "Edge"]
        self.assertGreater(len(feet), 10)
        self.assertLess(S.distance_to_shape([tuple(p) for p in feet], self.drawn().Edges[0]),
                        1e-7)

    def test_a_points_object_in_a_placed_part_is_fitted_where_it_is_drawn(self):
        """Points.Points carry the object's own Placement, not its App::Part's."""
        xy, _ = S.keyline_xy(40, length=150)
        cloud = S.points_object(self.doc, xy, placement=SKETCH_IN_BODY)
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = BODY_PLACEMENT
        part.addObject(cloud)
        self.doc.recompute()
        drawn = [BODY_PLACEMENT.multVec(p) for p in cloud.Points.Points]
        f = C.fit_sources([(cloud, [])], open_panel=False, Model="smooth")
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertLess(S.distance_to_shape([tuple(p) for p in drawn], f.Shape), 1e-3)

    def test_a_copy_into_the_sketch_in_a_body_lands_on_the_result(self):
        f = C.fit_sources([(self.sk, ["Edge1"])], open_panel=False, Model="smooth")
        self.doc.recompute()
        ids = G.write_to_sketch(f, self.sk)
        self.doc.recompute()
        self.assertEqual(len(ids), 1)
        copied = self.drawn().Edges[-1]
        self.assertOnEachOther(copied, f.Shape, 1e-7)
        self.assertOnEachOther(copied, self.drawn().Edges[0], 1e-3)

    def test_features_reading_a_sketch_in_a_body_warn_of_no_link_scope(self):
        with console_output() as out:
            made = [C.fit_sources([(self.sk, ["Edge1"])], open_panel=False),
                    C.blend_sources([(self.sk, ["Edge2"]), (self.sk, ["Edge3"])],
                                    open_panel=False),
                    C.g2quad_sources([(self.sk, ["Edge1"])], open_panel=False)]
            self.doc.recompute()
        self.assertNotIn(None, made)
        self.assertEqual(scope_warnings(out[0]), [])
        for f in made:
            self.assertFalse(f.Status.startswith("error"), f.Status)
            self.assertIsNone(f.getParentGeoFeatureGroup())      # at document level

    def test_a_document_with_local_links_reopens_with_global_ones(self):
        """Documents made before kept links of local scope: on reopening they become
        global, their values kept, and the warning is gone."""
        f = C.fit_sources([(self.sk, ["Edge1"])], open_panel=False)
        self.doc.recompute()
        value = f.Source
        f.removeProperty("Source")                      # as documents made before stored it
        f.addProperty("App::PropertyLinkSubList", "Source", "Input", "old")
        f.Source = value
        with console_output() as out:
            f.touch()
            self.doc.recompute()
        self.assertEqual(len(scope_warnings(out[0])), 1)     # the warning this is about
        path, name = S.temp_path(self, "local_links.FCStd"), f.Name
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        with console_output() as out:
            self.doc = App.openDocument(path)
            f = self.doc.getObject(name)
            f.touch()
            self.doc.recompute()
        self.assertEqual(scope_warnings(out[0]), [])
        self.assertEqual(f.getTypeIdOfProperty("Source"), "App::PropertyLinkSubListGlobal")
        self.assertEqual([(o.Name, list(s)) for o, s in f.Source], [("Sketch", ["Edge1"])])
        self.assertFalse(f.Status.startswith("error"), f.Status)

    def test_global_shape_is_where_freecad_draws_the_sub_element(self):
        """geometry.global_shape agrees with FreeCAD's own path from the document's root:
        Part.getShape(Body, 'Sketch.Edge1')."""
        for name in ("Edge1", "Edge3", "Vertex2"):
            mine = G.global_shape(self.sk, name)
            root = Part.getShape(self.body, f"Sketch.{name}", needSubElement=True)
            self.assertEqual(mine.ShapeType, root.ShapeType)
            self.assertLess(max((a.Point - b.Point).Length
                                for a, b in zip(mine.Vertexes, root.Vertexes)), 1e-9)
            if mine.Edges:
                self.assertLess(S.distance_to_shape(sample(mine), root), 1e-9)
        with self.assertRaises(X.InputProblem):
            G.global_element(self.sk, "Edge99")


if __name__ == "__main__":
    unittest.main()
