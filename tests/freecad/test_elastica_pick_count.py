"""freecadcmd -t test: picking n vertices of a sketch polyline reads the sketch's Geometry a
fixed number of times and compares O(n) points, not O(n^2) (QA: 201 vertices took ~20 s to
gather: each vertex's name and element scanned every geometry, each scan step reading
sketch.Geometry, which copies every geometry: O(n^3)). The work is counted, not timed (bench/
times it): links.read_geometry (the one place links and sources read sketch.Geometry) and
links._same_points (each point compared), for 41 and 201 vertices; the names, the points and
the feature's result are what the plain scan gives."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica import links as L
from freecad.elastica import sources as So


class _Counted:
    """links.read_geometry's and links._same_points' calls counted while active."""

    def __enter__(self):
        self.reads = self.compared = 0
        self.saved = L.read_geometry, L._same_points

        def read(sketch):
            self.reads += 1
            return self.saved[0](sketch)

        def same(p, q):
            self.compared += 1
            return self.saved[1](p, q)
        L.read_geometry, L._same_points = read, same
        return self

    def __exit__(self, *exc):
        L.read_geometry, L._same_points = self.saved


def _plain_geo_at(sketch, point, plc):
    """links._geo_at as it scanned before: the first drawn geometry (in order, its start
    before its end) with an end at ``point``."""
    g = sketch.Geometry
    for i in range(len(g)):
        if sketch.getConstruction(i) or g[i].TypeId == "Part::GeomPoint":
            continue
        e = g[i].toShape()
        for pos, u in ((L.START, e.FirstParameter), (L.END, e.LastParameter)):
            q = e.valueAt(u)
            if L._same_points([point], [plc.multVec(q) if plc is not None else q]):
                return i, pos
    return None


class PickCountTest(S.DocTest):
    doc_name = "ElasticaPickCount"

    def _polyline(self, n):
        """A sketch polyline of n - 1 segments (n vertices) placed off the origin, a
        construction line and a point drawn among them (they have no vertices to pick)."""
        sk = self.doc.addObject("Sketcher::SketchObject", f"Poly{n}")
        sk.Placement = S.SKETCH_PLACEMENT
        pts = [App.Vector(1500 + 10.0 * i, -800 + 30 * math.sin(i / 20.0), 0) for i in range(n)]
        half = n // 2
        sk.addGeometry([Part.LineSegment(a, b) for a, b in zip(pts[:half], pts[1:half + 1])],
                       False)
        sk.addGeometry(Part.LineSegment(pts[0], pts[3]), True)
        sk.addGeometry(Part.Point(App.Vector(1400, -900, 0)), False)
        sk.addGeometry([Part.LineSegment(a, b) for a, b in zip(pts[half:-1], pts[half + 1:])],
                       False)
        self.doc.recompute()
        return sk, [f"Vertex{k + 1}" for k in range(len(sk.Shape.Vertexes))]

    def test_picked_vertices_read_the_sketch_once(self):
        counts = {}
        for n in (41, 201):
            sk, subs = self._polyline(n)
            self.assertEqual(len(subs), n)
            with _Counted() as c:
                names = []
                pts = So.gather_points([(sk, subs)], names=names, element=L.as_followed())[0]
            counts[n] = (c.reads, c.compared)
            # names and points as the plain scan gives them
            for k, (s, name, p) in enumerate(zip(subs, names, pts)):
                at = _plain_geo_at(sk, sk.Shape.getElement(s).Point, sk.Placement)
                self.assertIsNotNone(at)
                kind = "start" if at[1] == L.START else "end"
                self.assertEqual(name, f"Poly{n}'s {s}, the {kind} of {at[0] + 1}-Line")
                self.assertLess((p - sk.getGlobalPlacement().multVec(
                    sk.Geometry[at[0]].toShape().valueAt(
                        sk.Geometry[at[0]].toShape().FirstParameter if at[1] == L.START
                        else sk.Geometry[at[0]].toShape().LastParameter))).Length, 1e-9)
        # a fixed number of reads (one per gather's and per element reader's look at the
        # sketch), the same for 41 and 201 vertices; each vertex compared with a few ends
        self.assertEqual(counts[41][0], counts[201][0], counts)
        self.assertLessEqual(counts[201][0], 2, counts)
        for n, (_, compared) in counts.items():
            self.assertLessEqual(compared, 6 * n, counts)

    def test_a_fit_of_picked_vertices_reads_the_sketch_a_few_times(self):
        """The feature made (its link followed: relinked) and recomputed (followed_elements,
        gather_points' names): Geometry reads the same for 41 and 201 vertices."""
        counts = {}
        for n in (41, 201):
            sk, subs = self._polyline(n)
            with _Counted() as c:
                f = Fi.make(self.doc, [(sk, subs)], Model="smooth")
                self.doc.recompute()
            self.assertFalse(f.Status.startswith("error"), f.Status)
            self.assertEqual(len(f.DataPoints), n)
            counts[n] = (c.reads, c.compared)
        self.assertEqual(counts[41][0], counts[201][0], counts)
        for n, (_, compared) in counts.items():
            self.assertLessEqual(compared, 12 * n, counts)


if __name__ == "__main__":
    unittest.main()
