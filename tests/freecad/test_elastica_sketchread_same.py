"""freecadcmd -t tests: links.SketchRead's grid lookups (_Near, d755723) give the element the
plain scan gave (the code before it, kept here as the reference): for every vertex of a
sketch's shape its (geometry, START / END), and for every geometry's end its VertexN, on a
sketch holding coincident ends (a polyline's joints, a line ending on an arc), arcs, a
B-spline, a circle, construction geometry and sketch points on drawn ends, and external
geometry (negative indices in the Sketcher, not in Geometry nor Shape), placed at the
origin, at a 1e6 mm offset, and at 1e-3 scale."""
import math

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import links as L

V = App.Vector


def plain_geo_at(sketch, point, plc=None):
    """The scan before SketchRead: the first drawn geometry with an end at ``point``."""
    return next(((i, pos) for i in range(len(sketch.Geometry)) if L._drawn(sketch, i)
                 for pos in (L.START, L.END)
                 if L._same_points([point], [L._vertex(sketch, i, pos, plc)])), None)


def plain_element_name(sketch, i, pos):
    if not L._drawn(sketch, i):
        return None
    at = [L._vertex(sketch, i, pos, sketch.Placement)]
    return next((f"Vertex{k + 1}" for k, v in enumerate(sketch.Shape.Vertexes)
                 if L._same_points(at, [v.Point])), None)


def mixed_sketch(doc, name, offset, scale, placement):
    sk = doc.addObject("Sketcher::SketchObject", name)
    sk.Placement = placement

    def p(x, y):
        return V(offset + scale * x, offset + scale * y, 0)
    pts = [p(0, 0), p(10, 2), p(20, -1), p(30, 4), p(40, 0)]
    for a, b in zip(pts, pts[1:]):                 # joints: two ends each
        sk.addGeometry(Part.LineSegment(a, b), False)
    arc = Part.ArcOfCircle(Part.Circle(p(40, 10), V(0, 0, 1), 10 * scale), -math.pi / 2, 0.0)
    sk.addGeometry(arc, False)                     # starts on the polyline's end
    sk.addGeometry(Part.LineSegment(p(50, 10), p(50, 30)), False)   # on the arc's end
    c = Part.BSplineCurve()
    c.interpolate([p(50, 30), p(45, 40), p(35, 38), p(30, 45)])
    sk.addGeometry(c, False)                       # starts on the line's end
    sk.addGeometry(Part.Circle(p(70, 70), V(0, 0, 1), 5 * scale), False)
    sk.addGeometry(Part.LineSegment(p(10, 2), p(30, 4)), True)     # construction, on joints
    sk.addGeometry(Part.Point(p(20, -1)), False)   # a sketch point on a joint
    sk.addGeometry(Part.LineSegment(p(20, -1), p(25, -20)), False)  # a third end at a joint
    sk.addGeometry(Part.LineSegment(p(0, 0), p(-10, -10)), True)    # construction, first
    for k in range(-3, 4):      # ends near the polyline's end, within _same_points' reach
        near = 0.3e-7 * k * (1.0 + placement.multVec(pts[-1]).Length)   # or just out of it
        sk.addGeometry(Part.LineSegment(pts[-1] + V(near, 0.7 * near, 0), p(45, -5 - k)), False)
    doc.recompute()
    return sk


class SketchReadSameTest(S.DocTest):
    doc_name = "ElasticaSketchReadSame"

    def check_same(self, sk):
        names = [f"Vertex{k + 1}" for k in range(len(sk.Shape.Vertexes))]
        self.assertGreaterEqual(len(names), 15)
        for name in names:
            plain = plain_geo_at(sk, sk.Shape.getElement(name).Point, sk.Placement)
            self.assertEqual(L.sketch_geo_of_element(sk, name), plain, name)
            self.assertEqual(L.sketch_geo_of_element(L.SketchRead(sk), name), plain, name)
        read = L.SketchRead(sk)
        for i in range(len(sk.Geometry)):
            for pos in (L.START, L.END):
                plain = plain_element_name(sk, i, pos)
                self.assertEqual(L.sketch_element_name(read, i, pos), plain, (i, pos))
                self.assertEqual(L.sketch_element_name(sk, i, pos), plain, (i, pos))
                if sk.Geometry[i].TypeId == "Part::GeomPoint":
                    continue
                at = L._vertex(sk, i, pos)          # unplaced, as _locate's tag points
                self.assertEqual(L._geo_at(read, at), plain_geo_at(sk, at), (i, pos))

    def test_the_grid_finds_what_the_scan_found(self):
        other = mixed_sketch(self.doc, "Other", 0.0, 1.0, App.Placement())
        cases = [(0.0, 1.0, S.SKETCH_PLACEMENT), (1e6, 1.0, App.Placement()),
                 (1e6, 1.0, S.SKETCH_PLACEMENT), (0.0, 1e-3, S.SKETCH_PLACEMENT),
                 (-3e5, 1e3, App.Placement(V(1e6, -1e6, 5e5), App.Rotation()))]
        for k, (offset, scale, plc) in enumerate(cases):
            with self.subTest(offset=offset, scale=scale, placed=plc != App.Placement()):
                sk = mixed_sketch(self.doc, f"Mixed{k}", offset, scale, plc)
                if k == 0:
                    sk.addExternal(other.Name, "Edge1")
                    sk.addExternal(other.Name, "Edge6")
                    self.doc.recompute()
                self.check_same(sk)


if __name__ == "__main__":
    import unittest
    unittest.main()
