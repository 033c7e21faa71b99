"""freecadcmd -t tests of the curvature comb's link: the sketch edges combed are their
geometry, followed as the sketch changes (QA: a comb of Chain.Edge3 and Edge4 combed two
other edges, status ok, once the helper line Edge1 was made construction or deleted), said
when deleted or made construction, through Undo, save / reopen and documents made before."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import comb as Co
from freecad.elastica import fit as Fi

DELETED = ("error: Source: the sketch geometry it followed (Chain.Edge3) was deleted: "
           "relink Source")


class CombLinkTest(S.DocTest):
    doc_name = "ElasticaCombLink"

    def setUp(self):
        super().setUp()
        self.xy, _ = S.keyline_xy(40)
        # geometry 0 the helper line (Edge1), 1..3 the curve's pieces (Edge2..Edge4)
        self.sk = S.helper_and_curve_sketch(self.doc, self.xy)

    def _comb(self, source, subs):
        """A comb of ``subs`` of ``source``, recomputed; a fixed scale: the automatic one
        follows the extent of the whole sketch, which the helper line changes."""
        comb = Co.make(self.doc, source, subs, Samples=12, Scale=200.0)
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        return comb

    def _same_teeth(self, comb, points):
        self.assertEqual(comb.Status, "ok")
        now = [v.Point for v in comb.Shape.Vertexes]
        self.assertEqual(len(now), len(points))
        self.assertLess(max((a - b).Length for a, b in zip(now, points)), 1e-9)

    def test_a_negative_scale_is_refused(self):
        """QA11: Scale = -500 was taken as automatic (status ok), silently."""
        comb = self._comb(self.sk, ["Edge2"])
        teeth = [v.Point for v in comb.Shape.Vertexes]
        comb.Scale = -500.0
        self.doc.recompute()
        self.assertTrue(comb.Status.startswith("error: Scale = -500") and ">= 0" in comb.Status,
                        comb.Status)
        self.assertEqual(len(comb.Shape.Vertexes), len(teeth))    # the last comb kept
        comb.Scale = 200.0
        self.doc.recompute()
        self._same_teeth(comb, teeth)

    def test_two_edges_follow_their_geometry(self):
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        points = [v.Point for v in comb.Shape.Vertexes]
        self.sk.toggleConstruction(0)
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source[1], ["Edge2", "Edge3"])
        self.sk.delGeometry(0)
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source[1], ["Edge2", "Edge3"])
        self.assertEqual(list(comb.SourceGeometry), ["1", "2"])

    def test_a_deleted_edge_is_named(self):
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        shape = comb.Shape.copy()
        self.sk.delGeometry(2)                          # Edge3 itself
        self.doc.recompute()
        self.assertEqual(comb.Status, DELETED)
        self.assertLess(abs(comb.Shape.Length - shape.Length), 1e-9)    # the last comb kept
        comb.Source = (self.sk, ["Edge3"])              # relinked: the last piece alone
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")

    def test_an_edge_made_construction_is_named(self):
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        points = [v.Point for v in comb.Shape.Vertexes]
        self.sk.toggleConstruction(3)                   # Edge4 itself
        self.doc.recompute()
        self.assertEqual(comb.Status, "error: Source: the sketch geometry it followed "
                         "(Chain.Edge4) is construction geometry now: make it normal geometry "
                         "or relink Source")
        self.sk.toggleConstruction(3)
        self.doc.recompute()
        self._same_teeth(comb, points)

    def test_undo_follows_what_was_followed(self):
        """Transactions as the GUI opens them: the helper line deleted, then Edge3; Undo
        twice brings the comb back on the same geometry under its first names."""
        self.doc.UndoMode = 1
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        points = [v.Point for v in comb.Shape.Vertexes]
        for geo in (0, 1):                              # the helper, then what was Edge3
            self.doc.openTransaction("delete geometry")
            self.sk.delGeometry(geo)
            self.doc.commitTransaction()
            self.doc.recompute()
        self.assertEqual(comb.Status, DELETED.replace("Edge3", "Edge2"))    # its name then
        self.doc.undo()
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source[1], ["Edge2", "Edge3"])
        self.doc.undo()
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source[1], ["Edge3", "Edge4"])

    def test_saved_reopened_and_edited_it_follows(self):
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        points = [v.Point for v in comb.Shape.Vertexes]
        self.sk, comb = S.reopened(self, "comb.FCStd", "Chain", comb.Name)
        self.sk.toggleConstruction(0)                   # before any recompute: new Tags
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.sk.delGeometry(0)                          # only the sketch recomputed, saved
        self.sk.recompute()
        self.sk, comb = S.reopened(self, "comb2.FCStd", "Chain", comb.Name)
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source[1], ["Edge2", "Edge3"])

    def test_a_document_of_a_version_before_follows_the_edges_it_names(self):
        comb = self._comb(self.sk, ["Edge3", "Edge4"])
        points = [v.Point for v in comb.Shape.Vertexes]
        comb.removeProperty("SourceGeometry")           # a document made before: no index
        self.sk, comb = S.reopened(self, "old.FCStd", "Chain", comb.Name)
        self.assertEqual(list(comb.SourceGeometry), [])
        self.sk.toggleConstruction(0)
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.assertEqual(list(comb.SourceGeometry), ["2", "3"])

    def test_a_comb_of_a_fit_follows_the_fit(self):
        """A comb of a whole Elastica result (no edges named) combs its curves as before; its
        deleted source is said as the other features say it (it said 'no source')."""
        f = Fi.make(self.doc, [(self.sk, ["Edge2", "Edge3", "Edge4"])], Model="smooth")
        self.doc.recompute()
        comb = self._comb(f, [])
        points = [v.Point for v in comb.Shape.Vertexes]
        self.sk.toggleConstruction(0)
        self.doc.recompute()
        self._same_teeth(comb, points)
        self.sk, f, comb = S.reopened(self, "fit.FCStd", "Chain", f.Name, comb.Name)
        self.sk.delGeometry(0)
        self.doc.recompute()
        self.assertEqual(f.Status, "converged")
        self._same_teeth(comb, points)
        self.assertEqual(comb.Source, (f, []))
        self.assertEqual(S.status_once_deleted(comb, f), "error: its source was deleted: "
                         "relink Source (an Elastica result or some edges)")



class CombScaleTest(S.DocTest):
    """The automatic scale does not change as the curve turns (QA: 12 % of the axis-aligned
    box's diagonal, 1361.8 for a curve and 1351.7 for it turned 45 deg)."""
    doc_name = "ElasticaCombScale"

    TURNS = [App.Placement(),
             App.Placement(App.Vector(0, 0, 0), App.Rotation(App.Vector(0, 0, 1), 45)),
             App.Placement(App.Vector(300, -40, 25), App.Rotation(App.Vector(0, 0, 1), 17)),
             App.Placement(App.Vector(-50, 80, 10), App.Rotation(App.Vector(1, 0.4, 0.2), 35))]

    def _combs(self, make_source):
        """(UsedScale, teeth in the source's plane coordinates) of the automatic comb of
        ``make_source(placement, name)`` at each of TURNS."""
        out = []
        for i, plc in enumerate(self.TURNS):
            source, subs = make_source(plc, f"Turned{i}")
            comb = Co.make(self.doc, source, subs, Samples=30)
            self.doc.recompute()
            self.assertEqual(comb.Status, "ok")
            inv = plc.inverse()
            out.append((comb.UsedScale, [inv.multVec(v.Point) for v in comb.Shape.Vertexes]))
        return out

    def assertTurnFree(self, combs):
        scale0, teeth0 = combs[0]
        for scale, teeth in combs[1:]:
            self.assertLess(abs(scale - scale0), 1e-9 * scale0, (scale, scale0))
            self.assertLess(max((a - b).Length for a, b in zip(teeth, teeth0)), 1e-7)

    def test_a_sketch_edge_turned_has_the_same_comb(self):
        xy, _ = S.keyline_xy(40)
        self.assertTurnFree(self._combs(
            lambda plc, name: (S.bspline_sketch(self.doc, xy, name, plc), ["Edge1"])))

    def test_a_fit_turned_has_the_same_comb(self):
        xy, _ = S.keyline_xy(40)

        def fit(plc, name):
            f = Fi.make(self.doc, [(S.points_sketch(self.doc, xy, name, plc), [])],
                        Model="smooth")
            self.doc.recompute()
            return f, []
        self.assertTurnFree(self._combs(fit))

    def test_a_symmetric_closed_shape_turned_has_the_same_scale(self):
        """A sketched rounded square (4 lines, 4 arcs: side 100, radius 10) has no principal
        axes (its covariance is isotropic): the box along them gave UsedScale 183.5, 191.2,
        173.4, 188.1, 214.9, 211.9, 172.1 at 0 .. 75 deg (review revfc 3). Its diameter, the
        square's diagonal between the arcs' far points (2 sqrt(2) 40 + 2 10), does not turn."""
        scales, extents = [], []
        for deg in (0, 10, 20, 30, 45, 60, 75):
            sk = self.doc.addObject("Sketcher::SketchObject", f"Square{deg}")
            sk.Placement = App.Placement(App.Vector(5, 3, 0),
                                         App.Rotation(App.Vector(0, 0, 1), deg))
            rounded_square(sk)
            self.doc.recompute()
            comb = Co.make(self.doc, sk, Samples=30)
            self.doc.recompute()
            self.assertEqual(comb.Status, "ok")
            scales.append(comb.UsedScale)
            extents.append(Co.shape_extent(sk.Shape))
        for deg, scale in zip((10, 20, 30, 45, 60, 75), scales[1:]):
            self.assertLess(abs(scale - scales[0]), 1e-9 * scales[0], (deg, scale, scales[0]))
        # 60 points per arc miss its far point by at most 10 (1 - cos(0.77 deg)) = 0.0009
        for extent in extents:
            self.assertLess(abs(extent - (2 * math.sqrt(2) * 40 + 20)), 0.002, extents)


def rounded_square(sk, a=40.0, r=10.0):
    """Four quarter arcs of radius ``r`` centred at (+-a, +-a) and the lines between them."""
    corners = [(a, a), (-a, a), (-a, -a), (a, -a)]
    for i, (x, y) in enumerate(corners):
        s = math.radians(90 * i)
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(x, y, 0), App.Vector(0, 0, 1), r),
                                        s, s + math.pi / 2))
        nx, ny = corners[(i + 1) % 4]
        e = math.radians(90 * (i + 1))
        sk.addGeometry(Part.LineSegment(
            App.Vector(x + r * math.cos(e), y + r * math.sin(e), 0),
            App.Vector(nx + r * math.cos(e), ny + r * math.sin(e), 0)))


if __name__ == "__main__":
    unittest.main()
