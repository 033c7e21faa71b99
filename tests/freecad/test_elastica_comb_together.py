"""freecadcmd -t tests of a curvature comb over several selected sources (QA gui F5): a G2
blend and the two sketch edges it joins, selected together, are ONE comb on one scale, so
equal curvature gives equal teeth across each joint (they were two combs, scales 946 and
1670, the teeth 1.76 x apart where they met); one source's comb is as before."""

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import comb as Co
from freecad.elastica import commands as C


def _teeth_at(comb, point, tol=1e-6):
    """The lengths of the comb's teeth with an end at ``point``."""
    out = []
    for e in comb.Shape.Edges:
        if len(e.Vertexes) != 2 or not isinstance(e.Curve, Part.Line):
            continue
        if min((v.Point - point).Length for v in e.Vertexes) <= tol:
            out.append(e.Length)
    return out


class CombTogetherTest(S.DocTest):
    doc_name = "ElasticaCombTogether"

    def setUp(self):
        super().setUp()
        sk = self.sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.Placement = App.Placement(App.Vector(0, 0, 10), App.Rotation(App.Vector(1, 1, 0), 25))
        S.f4_line_arc(sk)
        self.doc.recompute()
        self.b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2")
        self.doc.recompute()
        self.assertFalse(self.b.Status.startswith("error"), self.b.Status)

    def test_blend_and_its_edges_are_one_comb_on_one_scale(self):
        n = len(self.doc.Objects)
        made = C.comb_sources([(self.b, ()), (self.sk, ("Edge1", "Edge2"))])
        self.assertEqual(len(made), 1)
        self.assertEqual(len(self.doc.Objects), n + 1)
        comb = made[0]
        self.assertEqual(comb.Status, "ok")
        self.assertEqual(comb.Source[0], self.b)
        self.assertEqual([(o.Name, tuple(s)) for o, s in comb.MoreSources],
                         [(self.sk.Name, ("Edge1", "Edge2"))])
        # the scale: the longest tooth of all 12 % of the extent of all
        e = self.b.Shape.Edges[0]
        joint = e.valueAt(e.LastParameter)
        arc = self.sk.Shape.Edges[1]
        self.assertLess((arc.valueAt(arc.FirstParameter) - joint).Length, 1e-6)
        teeth = _teeth_at(comb, joint)
        self.assertEqual(len(teeth), 2, teeth)           # the blend's last, the arc's first
        # G2 there: equal curvature, equal teeth (60 x the scale / 60)
        self.assertLess(abs(teeth[0] - teeth[1]), 1e-7 * teeth[0], teeth)
        self.assertAlmostEqual(teeth[0], comb.UsedScale / 60.0, delta=1e-7 * teeth[0])
        # a comb alone of each has its own scale: the two differ (what QA saw)
        alone = [Co.comb_core(self.b)[1], Co.comb_core(self.sk, ("Edge1", "Edge2"))[1]]
        self.assertGreater(max(alone) / min(alone), 1.2, alone)
        # parametric: the arc's radius changed, the comb follows on one scale
        g = self.sk.Geometry[1]
        g.Radius = 70.0
        self.sk.Geometry = [self.sk.Geometry[0], g]
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        e = self.b.Shape.Edges[0]
        teeth = _teeth_at(comb, e.valueAt(e.LastParameter))
        self.assertEqual(len(teeth), 2, teeth)
        self.assertLess(abs(teeth[0] - teeth[1]), 1e-7 * teeth[0], teeth)

    def test_one_source_is_combed_as_before(self):
        """A single source's comb: MoreSources empty, the teeth and scale comb_core gives
        for it alone (an edge of a sketch: the whole sketch's extent, as before)."""
        for source, subs in ((self.b, ()), (self.sk, ("Edge2",))):
            made = C.comb_sources([(source, subs)])
            self.assertEqual(len(made), 1)
            comb = made[0]
            self.assertEqual(list(comb.MoreSources), [])
            teeth, scale = Co.comb_core(source, subs)
            self.assertEqual(comb.UsedScale, scale)
            ends = [p for chain in teeth for pair in chain for p in pair]
            self.assertLess(max(min((v.Point - p).Length for p in ends)
                                for v in comb.Shape.Vertexes), 1e-9)

    def test_reopened(self):
        comb = C.comb_sources([(self.b, ()), (self.sk, ("Edge1", "Edge2"))])[0]
        scale, name = comb.UsedScale, comb.Name
        path = S.temp_path(self, "together.FCStd")
        self.doc.saveAs(path)
        App.closeDocument(self.doc.Name)
        self.doc = App.openDocument(path)
        comb = self.doc.getObject(name)
        comb.touch()
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        self.assertAlmostEqual(comb.UsedScale, scale, delta=1e-9 * scale)
        self.assertEqual(len(comb.MoreSources), 1)

    def test_edges_first_then_the_whole_blend(self):
        """The selection in the other order: the sketch's edges are Source, the whole blend
        in MoreSources (no sub-element); the same teeth at the joint."""
        comb = C.comb_sources([(self.sk, ("Edge1", "Edge2")), (self.b, ())])[0]
        self.assertEqual(comb.Status, "ok")
        self.assertEqual(comb.MoreSources[0][0], self.b)
        e = self.b.Shape.Edges[0]
        teeth = _teeth_at(comb, e.valueAt(e.LastParameter))
        self.assertEqual(len(teeth), 2, teeth)
        self.assertLess(abs(teeth[0] - teeth[1]), 1e-7 * teeth[0], teeth)

    def _three_arcs_combed(self):
        """Sketches A, B, C (an arc each, 5, 10 and 3 mm high) and the comb of A with B and C
        as MoreSources, recomputed: (a, b, c, comb)."""
        sks = []
        for name, y, rise in (("A", 0.0, 5.0), ("B", 100.0, 10.0), ("C", 200.0, 3.0)):
            sk = self.doc.addObject("Sketcher::SketchObject", name)
            sk.addGeometry(Part.ArcOfCircle(App.Vector(0, y, 0), App.Vector(25, y + rise, 0),
                                            App.Vector(50, y, 0)), False)
            sks.append(sk)
        a, b, c = sks
        self.doc.recompute()
        comb = Co.make(self.doc, a, ["Edge1"], more=[(b, ["Edge1"]), (c, ["Edge1"])])
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        return a, b, c, comb

    def test_source_deleted_the_first_of_more_sources_takes_its_place(self):
        """Review of F5: the comb's Source object deleted while MoreSources holds two more:
        the first of them becomes the Source and the comb is the comb of the two left, on
        their own scale, said in Status and the report view (on main: 'error: ... nothing
        read' with sources left)."""
        a, b, c, comb = self._three_arcs_combed()
        # the comb of B and C alone, for reference
        ref = Co.make(self.doc, b, ["Edge1"], more=[(c, ["Edge1"])])
        self.doc.recompute()
        # promoted as A is deleted, before any recompute (it wrote Source and MoreSources
        # inside the recompute: on main the Source is still empty here)
        said, _ = S.console_output(lambda: self.doc.removeObject("A"))
        self.assertEqual((comb.Source[0].Name, list(comb.Source[1])), ("B", ["Edge1"]))
        self.assertNotIn("Invalid", comb.State)
        said += S.console_output(self.doc.recompute)[0]
        self.assertIn("its Source was deleted: B, the first of MoreSources, is the Source now",
                      said)
        self.assertEqual(comb.Status, "ok (its Source was deleted: B, the first of "
                         "MoreSources, is the Source now)")
        self.assertEqual((comb.Source[0].Name, list(comb.Source[1])), ("B", ["Edge1"]))
        self.assertEqual([(o.Name, list(s)) for o, s in comb.MoreSources], [("C", ["Edge1"])])
        self.assertAlmostEqual(comb.UsedScale, ref.UsedScale, delta=1e-9 * ref.UsedScale)
        self.assertEqual(len(comb.Shape.Edges), len(ref.Shape.Edges))
        # the next edit: the comb as it is now, nothing more to say
        comb.Samples = 40
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        # the last source deleted too, and C's: nothing left is still the error it was
        self.assertEqual(S.status_once_deleted(comb, b, c).split(":")[0], "error")

    def test_a_deletion_undone_before_a_recompute_says_nothing_of_it(self):
        """The Source's object deleted (promote: B the Source, said at once), then Undo before
        any recompute: Source and MoreSources are the step's again (A; B, C) and the next
        recompute's Status is 'ok', not 'ok (its Source was deleted: B ...)' of a deletion
        undone (review revT: promote's note outlived the Undo)."""
        self.doc.UndoMode = 1
        a, b, c, comb = self._three_arcs_combed()
        self.doc.openTransaction("Delete")
        self.doc.removeObject("A")
        self.doc.commitTransaction()
        self.assertEqual(comb.Source[0].Name, "B")
        self.doc.undo()
        self.assertEqual((comb.Source[0].Name, list(comb.Source[1])), ("A", ["Edge1"]))
        self.assertEqual([(o.Name, list(s)) for o, s in comb.MoreSources],
                         [("B", ["Edge1"]), ("C", ["Edge1"])])
        self.doc.recompute()
        self.assertEqual(comb.Status, "ok")
        self.assertEqual(comb.State, ["Up-to-date"])
        # Redo: B the Source again, the step's values; the deletion was said as it was done
        self.doc.redo()
        self.assertEqual((comb.Source[0].Name, list(comb.Source[1])), ("B", ["Edge1"]))
        self.doc.recompute()
        self.assertEqual(comb.State, ["Up-to-date"])
        self.assertEqual([(o.Name, list(s)) for o, s in comb.MoreSources], [("C", ["Edge1"])])
