"""freecadcmd -t tests of copying a result's B-spline into an existing sketch
(geometry.write_to_sketch, what the panels' "Copy into" runs on OK): a sketch in the
curve's plane takes the curve as it is, one in another plane is refused with a message and
left as it was (it kept only the curve's shadow on its plane, flattened)."""
import math
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica import geometry as G
from freecad.elastica.proxy import InputProblem


def _sine_fit(doc):
    """A smooth fit of ten points on a sine, recomputed: the curve these tests copy."""
    xy = [(x, 10 * math.sin(x / 30.0)) for x in range(0, 100, 10)]
    fit = Fi.make(doc, [(S.points_sketch(doc, xy), [])], Model="smooth")
    doc.recompute()
    return fit


def _outline(doc, fit):
    """An empty sketch named Outline in the fit's plane (a sketch the fit does not read)."""
    sk = doc.addObject("Sketcher::SketchObject", "Outline")
    sk.Placement = fit.Plane
    return sk


class CopyIntoSketchTest(S.DocTest):
    doc_name = "ElasticaSketchCopy"

    def setUp(self):
        super().setUp()
        self.fit = _sine_fit(self.doc)
        self.assertFalse(self.fit.Status.startswith("error"), self.fit.Status)

    def _sketch(self, placement, name):
        sk = self.doc.addObject("Sketcher::SketchObject", name)
        sk.Placement = placement
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(10, 0, 0)), False)
        self.doc.recompute()
        return sk

    def test_a_copy_again_replaces_the_earlier_copy_in_a_closed_profile(self):
        """QA20gui F4: a fit copied into a sketch, the profile closed there with three lines
        joined by coincidences, a source point moved, the fit copied again into that sketch:
        the earlier copy is replaced in place (one B-spline, the same index), the lines
        follow its new ends, the profile stays one closed wire that makes a solid. It added a
        second B-spline beside the first (two wires; a Pocket of it failed)."""
        import Sketcher
        xy = [(x, 12 * math.sin(x / 25.0) + 0.3 * ((x * 7) % 3)) for x in range(0, 110, 10)]
        src = S.points_sketch(self.doc, xy, "Scan")
        fit = Fi.make(self.doc, [(src, [])], Model="smooth")
        self.doc.recompute()
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.Placement = fit.Plane
        self.assertEqual(G.write_to_sketch(fit, sk), [0])
        self.doc.recompute()
        a, b = sk.Geometry[0].StartPoint, sk.Geometry[0].EndPoint
        down = App.Vector(0, -40, 0)
        for p, q in ((b, b + down), (b + down, a + down), (a + down, a)):
            sk.addGeometry(Part.LineSegment(p, q), False)
        for g0, p0, g1, p1 in ((0, 2, 1, 1), (1, 2, 2, 1), (2, 2, 3, 1), (3, 2, 0, 1)):
            sk.addConstraint(Sketcher.Constraint("Coincident", g0, p0, g1, p1))
        self.doc.recompute()
        self.assertEqual(len(sk.Shape.Wires), 1)
        self.assertTrue(sk.Shape.Wires[0].isClosed())
        x, y = xy[5]
        src.movePoint(5, 1, App.Vector(x, y + 4.0, 0))
        self.doc.recompute()
        self.assertFalse(fit.Status.startswith("error"), fit.Status)
        moved = [tuple(p) for p in sk.Shape.Edges[0].discretize(40)]
        self.assertGreater(S.distance_to_shape(moved, fit.Shape), 0.5)   # the copy is old
        self.assertEqual(G.write_to_sketch(fit, sk), [0])
        self.doc.recompute()
        self.assertEqual([g.TypeId for g in sk.Geometry],
                         ["Part::GeomBSplineCurve"] + ["Part::GeomLineSegment"] * 3)
        self.assertEqual(len(sk.Constraints), 4)
        wires = sk.Shape.Wires
        self.assertEqual(len(wires), 1)
        self.assertTrue(wires[0].isClosed())
        solid = Part.Face(wires[0]).extrude(fit.Plane.Rotation.multVec(App.Vector(0, 0, 5)))
        self.assertTrue(solid.isValid())
        self.assertGreater(solid.Volume, 0)
        curve = [tuple(p) for p in sk.Shape.Edges[0].discretize(40)]
        self.assertLess(S.distance_to_shape(curve, fit.Shape), 1e-6)  # the copy of now
        # the copy into another sketch is another copy (not replaced): two sketches, two
        other = self.doc.addObject("Sketcher::SketchObject", "Other")
        other.Placement = fit.Plane
        self.assertEqual(G.write_to_sketch(fit, other), [0])
        self.assertEqual(len(sk.Geometry), 4)
        # the earlier copy deleted in the Sketcher: a copy is added again
        sk.delGeometry(0)
        self.doc.recompute()
        self.assertEqual(G.write_to_sketch(fit, sk), [3])

    def test_a_sketch_in_another_plane_is_refused_untouched(self):
        plane = S.SKETCH_PLACEMENT
        tilted = App.Placement(plane.Base, plane.Rotation.multiply(
            App.Rotation(App.Vector(1, 0, 0), 90)))
        lifted = App.Placement(plane.multVec(App.Vector(0, 0, 2)), plane.Rotation)
        for placement, name in ((tilted, "Front"), (lifted, "Parallel")):
            sk = self._sketch(placement, name)
            with self.assertRaises(InputProblem) as cm:
                G.write_to_sketch(self.fit, sk)
            msg = str(cm.exception)
            self.assertIn(f"{name} does not lie in the plane of {self.fit.Label}", msg)
            self.assertIn("mm off the sketch's plane", msg)
            self.assertEqual(len(sk.Geometry), 1)          # nothing half-written
            self.assertEqual(len(sk.Shape.Edges), 1)

    def test_a_sketch_in_the_curve_plane_takes_the_curve(self):
        # the fit's plane, its origin moved and turned within it
        plane = S.SKETCH_PLACEMENT
        moved = App.Placement(plane.multVec(App.Vector(-30, 12, 0)), plane.Rotation.multiply(
            App.Rotation(App.Vector(0, 0, 1), 40)))
        sk = self._sketch(moved, "Same")
        ids = G.write_to_sketch(self.fit, sk)
        self.doc.recompute()
        self.assertEqual(len(ids), 1)
        e = sk.Shape.Edges[-1]
        pts = [tuple(p) for p in e.discretize(40)]
        self.assertLess(S.distance_to_shape(pts, self.fit.Shape), 1e-7)
        self.assertAlmostEqual(e.Length, self.fit.Shape.Length, delta=1e-7)

    def test_a_sketch_another_feature_reads_whole_is_refused_untouched(self):
        """Two stations of points, each fitted: Copy into the other station's sketch made
        that fit fail ('holds 20 points and 1 edge', QA); the sketch is now refused, its
        fit unchanged."""
        xy = [(x, 30 + 10 * math.sin(x / 30.0)) for x in range(0, 100, 10)]
        station = S.points_sketch(self.doc, xy)
        other = Fi.make(self.doc, [(station, [])], Model="smooth")
        self.doc.recompute()
        rms = other.Rms
        with self.assertRaises(InputProblem) as cm:
            G.write_to_sketch(self.fit, station)
        self.assertIn(f"{station.Label} is read whole by {other.Label}", str(cm.exception))
        self.assertEqual(len(station.Shape.Edges), 0)
        station.touch()
        self.doc.recompute()
        self.assertFalse(other.Status.startswith("error"), other.Status)
        self.assertEqual(other.Rms, rms)


if __name__ == "__main__":
    unittest.main()


class CopyDriftTest(S.DocTest):
    """QA22gui F1: a blend copied into its sketch, Tangent-joined there; the designer moves
    the line: the blend re-solves G2 but the Sketcher bends the copy (26.2 mm off), and
    nothing said so. Now the blend's recompute measures its copy and says it in its Status
    and the report view, without touching the sketch; Copy into again clears it.

    The copy is joined here by Coincident constraints, not QA's Tangent ones: FreeCAD
    0.20.2's Sketcher solves the Tangent-joined B-spline differently from run to run (the
    same sketch without any Elastica object: 4 different copies out of 16 runs, and then
    the setDatum below refused as 'conflicting constraints' in ~1 run in 4), so the test
    failed at random in the Sketcher. The Coincident-joined copy is solved the same every
    run and bent all the same (27.8 mm off); what the blend says does not depend on which
    constraint bent it."""
    doc_name = "ElasticaCopyDrift"

    def test_a_copy_the_sketcher_bent_is_said_and_cleared_by_copying_again(self):
        import Sketcher
        from freecad.elastica import blend as B
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(0, 120, 0)), False)
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(80, 300, 0), App.Vector(0, 0, 1),
                                                    40), math.pi / 2, math.pi), False)
        for c in (("Vertical", 0), ("DistanceX", -1, 1, 0, 1, 0.0),
                  ("DistanceY", -1, 1, 0, 1, 0.0), ("DistanceY", 0, 1, 0, 2, 120.0),
                  ("Radius", 1, 40.0), ("DistanceX", -1, 1, 1, 3, 80.0),
                  ("DistanceY", -1, 1, 1, 3, 300.0), ("Angle", 1, math.pi / 2)):
            sk.addConstraint(Sketcher.Constraint(*c))
        self.doc.recompute()
        b = B.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2")
        self.doc.recompute()
        ok = b.Status
        self.assertNotIn("copy", ok)
        i = G.write_to_sketch(b, sk)[0]
        b.touch()
        self.doc.recompute()
        self.assertEqual(b.Status, ok)           # a faithful copy: nothing said
        sk.addConstraint(Sketcher.Constraint("Coincident", 0, 2, i, 1))
        sk.addConstraint(Sketcher.Constraint("Coincident", 1, 2, i, 2))
        a0 = sk.Geometry[1].StartPoint          # the outline closed as QA did
        n = sk.addGeometry(Part.LineSegment(a0, App.Vector(150, a0.y, 0)), False)
        m = sk.addGeometry(Part.LineSegment(App.Vector(150, a0.y, 0), App.Vector(150, 0, 0)), False)
        o = sk.addGeometry(Part.LineSegment(App.Vector(150, 0, 0), App.Vector(0, 0, 0)), False)
        for c in ((1, 1, n, 1), (n, 2, m, 1), (m, 2, o, 1), (o, 2, 0, 1)):
            sk.addConstraint(Sketcher.Constraint("Coincident", *c))
        self.doc.recompute()
        sk.setDatum(1, App.Units.Quantity("-20 mm"))
        sk.setDatum(3, App.Units.Quantity("150 mm"))
        tags = [g.Tag for g in sk.Geometry]
        self.doc.recompute()
        self.assertEqual([o.Name for o in self.doc.Objects if "Touched" in o.State], [])  # settles
        copy, own = Part.Edge(sk.Geometry[i]), b.Shape.Edges[0]
        off = max(max(copy.distToShape(Part.Vertex(p))[0] for p in own.discretize(200)),
                  max(own.distToShape(Part.Vertex(p))[0] for p in copy.discretize(200)))
        self.assertGreater(off, 1.0)            # QA: 26.2 mm (Tangent-joined)
        ok = b.Status.split(". The copy in ")[0]         # the blend re-solved, G2 again
        self.assertTrue(b.Status.startswith(ok + ". The copy in Sketch 'Profile' is "),
                        b.Status)
        said = float(b.Status.split(" is ", 1)[1].split(" mm")[0])
        self.assertAlmostEqual(said, off, delta=0.02 * off)
        self.assertTrue(b.Status.endswith("Copy into again"), b.Status)
        self.assertEqual([g.Tag for g in sk.Geometry], tags)   # the sketch's geometry kept
        G.write_to_sketch(b, sk)
        self.doc.recompute()
        b.touch()
        self.doc.recompute()
        self.assertEqual(b.Status, ok)

    def test_the_figure_said_is_the_farthest_point_between_samples(self):
        """The copy 39.3 mm off in the Status where it was 40.3 mm off (1 run of 20 of the
        test above, when the Sketcher bent it otherwise): the figure came from 33 points
        equally spaced along each curve, and the copy's farthest point lay between two of
        them. A copy with a bump 2 mm high, 1.5 mm wide (sigma), centred half-way between two
        samples: the figure said is the bump's height (the samples alone: ~1.1 mm)."""
        from freecad.elastica import copies
        fit = _sine_fit(self.doc)
        sk = _outline(self.doc, fit)
        G.write_to_sketch(fit, sk)
        self.doc.recompute()
        own = fit.Shape.Edges[0]
        length = own.Length
        s0 = 10.5 * length / (copies.SAMPLES - 1)
        pts = []
        for k in range(601):
            s = length * k / 600
            u = own.getParameterByLength(s)
            t = own.tangentAt(u)
            n = fit.Plane.Rotation.multVec(App.Vector(0, 0, 1)).cross(t)
            pts.append(own.valueAt(u) + n * (2.0 * math.exp(-((s - s0) / 1.5) ** 2 / 2)))
        bent = Part.BSplineCurve()
        bent.interpolate(pts)
        saved = copies._copy_edges
        copies._copy_edges = lambda feature: {sk: [bent.toShape()]}
        try:
            found = copies.drift(fit)
        finally:
            copies._copy_edges = saved
        dense = max(own.distToShape(Part.Vertex(p))[0] for p in bent.toShape().discretize(4001))
        self.assertGreater(dense, 1.99)
        self.assertEqual(len(found), 1)
        self.assertAlmostEqual(found[0][1], dense, delta=1e-3)

    def test_a_copy_moved_in_a_sketch_the_feature_does_not_read_is_said(self):
        """The copy in a sketch of its own (the feature reads another): the designer moves
        the copy's start in the Sketcher; that sketch's recompute has the feature measure
        it and say it, the feature not touched (nothing recomputes after: one pass)."""
        fit = _sine_fit(self.doc)
        ok = fit.Status
        sk = _outline(self.doc, fit)
        i = G.write_to_sketch(fit, sk)[0]
        self.doc.recompute()
        self.assertEqual(fit.Status, ok)
        start = sk.Geometry[i].StartPoint
        sk.movePoint(i, 1, start + App.Vector(0, 3, 0))
        self.doc.recompute()
        self.assertEqual([o.Name for o in self.doc.Objects if "Touched" in o.State], [])
        self.assertTrue(fit.Status.startswith(ok + ". The copy in Sketch 'Outline' is "),
                        fit.Status)
        said = float(fit.Status.split(" is ", 1)[1].split(" mm")[0])
        copy, own = Part.Edge(sk.Geometry[i]), fit.Shape.Edges[0]
        copy.transformShape(sk.Placement.toMatrix())
        off = max(max(copy.distToShape(Part.Vertex(p))[0] for p in own.discretize(200)),
                  max(own.distToShape(Part.Vertex(p))[0] for p in copy.discretize(200)))
        self.assertGreater(off, 2.5)            # the start moved 3 mm across
        self.assertAlmostEqual(said, off, delta=0.02 * off)
        G.write_to_sketch(fit, sk)              # Copy into again: said no more
        self.doc.recompute()
        self.assertEqual(fit.Status, ok)

    def test_a_copy_is_found_again_in_a_reopened_document(self):
        """FreeCAD 0.20 gives a sketch's geometry new Tags when a document is opened (they
        are not saved), and the copy was known by its Tag only: after a reopen a moved copy
        was said by nothing, and Copy into added a second copy beside the first (the
        overlap of QA20gui F4). The copy's saved mark finds it: said, replaced in place."""
        fit = _sine_fit(self.doc)
        ok = fit.Status
        sk = _outline(self.doc, fit)
        sk.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(10, 0, 0)), False)
        i = G.write_to_sketch(fit, sk)[0]
        self.doc.recompute()
        start = sk.Geometry[i].StartPoint
        sk.movePoint(i, 1, start + App.Vector(0, 3, 0))
        self.doc.recompute()
        fit, sk = S.reopened(self, "copy.FCStd", fit.Name, sk.Name)
        fit.touch()
        self.doc.recompute()
        self.assertTrue(fit.Status.startswith(ok + ". The copy in Sketch 'Outline' is "),
                        fit.Status)
        n = len(sk.Geometry)
        self.assertEqual(G.write_to_sketch(fit, sk), [i])        # in place, not beside it
        self.doc.recompute()
        self.assertEqual(len(sk.Geometry), n)
        self.assertEqual(fit.Status, ok)


class CopyDriftSaidOnceTest(S.DocTest):
    """Note 54: the drift was said in the report view at every recompute: one stretch of the
    designer's work recomputing twice before the GUI was idle again gave two lines (11.4 mm
    then 26.3 mm), and a recompute that moved nothing said the same line again. Now under the GUI the line waits for the event loop
    to be idle (copies._scheduler; stood in for here) and says the last figure once, and
    a line that reads as the last one said is not said again; the Status always carries
    the present figure."""
    doc_name = "ElasticaCopyDriftOnce"

    def setUp(self):
        super().setUp()
        from freecad.elastica import copies
        self.copies, self.queued, self.printed = copies, [], []
        self.saved = getattr(copies, "_scheduler", None), App.Console.PrintWarning
        copies._scheduler = lambda: self.queued.append
        App.Console.PrintWarning = self.printed.append

    def tearDown(self):
        self.copies._scheduler, App.Console.PrintWarning = self.saved
        super().tearDown()

    def idle(self):
        """The event loop idle again: what waited for it runs; the copy lines said."""
        while self.queued:
            self.queued.pop(0)()
        said = [t for t in self.printed if "The copy in" in t or "the copy in" in t]
        self.printed[:] = []
        return said

    def test_one_line_per_user_action_with_the_last_figure(self):
        fit = _sine_fit(self.doc)
        sk = _outline(self.doc, fit)
        i = G.write_to_sketch(fit, sk)[0]
        self.doc.recompute()
        self.assertEqual(self.idle(), [])
        # one stretch of work, two recomputes before the GUI is idle again (the copy's start
        # dragged 3 mm, then on to 6 mm as the move settles)
        start = sk.Geometry[i].StartPoint
        figures = []
        for dy in (3, 6):
            sk.movePoint(i, 1, start + App.Vector(0, dy, 0))
            self.doc.recompute()
            figures.append(fit.Status.split(" is ", 1)[1].split(" mm")[0])
        self.assertNotEqual(figures[0], figures[1])     # the Status says each
        said = self.idle()
        self.assertEqual(len(said), 1, said)
        self.assertIn(f"is {figures[1]} mm off this curve", said[0])
        fit.touch()                                 # nothing moved: not said again
        self.doc.recompute()
        self.assertIn(f"is {figures[1]} mm off", fit.Status)
        self.assertEqual(self.idle(), [])
        sk.movePoint(i, 1, start + App.Vector(0, 9, 0))     # the next action: its own line
        self.doc.recompute()
        said = self.idle()
        self.assertEqual(len(said), 1, said)
        self.assertIn(fit.Status.split(" is ", 1)[1].split(" (")[0], said[0])
        G.write_to_sketch(fit, sk)                  # Copy into again: in line, said no more
        self.doc.recompute()
        fit.touch()
        self.doc.recompute()
        self.assertNotIn("The copy in", fit.Status)
        self.assertEqual(self.idle(), [])
        sk.movePoint(i, 1, start + App.Vector(0, 9, 0))     # off again: news again
        self.doc.recompute()
        self.assertEqual(len(self.idle()), 1)

    def test_without_the_gui_each_changed_figure_is_said_at_once(self):
        """A script's recompute is its own step: said at once, but not again unchanged."""
        self.copies._scheduler = lambda: None
        fit = _sine_fit(self.doc)
        sk = _outline(self.doc, fit)
        i = G.write_to_sketch(fit, sk)[0]
        self.doc.recompute()
        start = sk.Geometry[i].StartPoint
        sk.movePoint(i, 1, start + App.Vector(0, 3, 0))
        self.doc.recompute()
        self.assertEqual(len(self.idle()), 1)
        fit.touch()
        self.doc.recompute()
        self.assertTrue(fit.Status.split(". The copy in ")[1])
        self.assertEqual(self.idle(), [])
        sk.movePoint(i, 1, start + App.Vector(0, 6, 0))
        self.doc.recompute()
        self.assertEqual(len(self.idle()), 1)


class CopyDriftIdleHookTest(S.DocTest):
    """5a18fb0: the drift line's idle scheduler comes through proxy.IDLE_HOOK (set by
    init_gui), CopyDriftSaidOnceTest replacing copies._scheduler as a whole: nothing held the
    real one to using the hook under the GUI only. Under the GUI (App.GuiUp) the hook's
    function defers the line; without it (freecadcmd, a script) the line comes at once even
    where a hook is set (no event loop would run it: the drift never said)."""
    doc_name = "ElasticaCopyDriftHook"

    def setUp(self):
        super().setUp()
        from freecad.elastica import copies, proxy
        self.copies, self.proxy, self.queued, self.printed = copies, proxy, [], []
        self.saved = list(proxy.IDLE_HOOK), App.GuiUp, App.Console.PrintWarning
        App.Console.PrintWarning = self.printed.append

    def tearDown(self):
        self.proxy.IDLE_HOOK[:], App.GuiUp, App.Console.PrintWarning = self.saved
        super().tearDown()

    def test_the_gui_hook_defers_and_without_the_gui_the_line_comes_at_once(self):
        hook = self.queued.append
        self.proxy.IDLE_HOOK[:] = [hook]
        App.GuiUp = 1
        try:
            self.assertIs(self.copies._scheduler(), hook)
            self.proxy.IDLE_HOOK[:] = []            # a GUI without the workbench's hook
            self.assertIsNone(self.copies._scheduler())
        finally:
            App.GuiUp = 0
        self.proxy.IDLE_HOOK[:] = [hook]
        self.assertIsNone(self.copies._scheduler())
        fit = _sine_fit(self.doc)
        sk = _outline(self.doc, fit)
        i = G.write_to_sketch(fit, sk)[0]
        self.doc.recompute()
        sk.movePoint(i, 1, sk.Geometry[i].StartPoint + App.Vector(0, 3, 0))
        self.doc.recompute()
        said = [t for t in self.printed if "the copy in" in t.lower()]
        self.assertEqual(len(said), 1, self.printed)   # at once, with the hook set
        self.assertEqual(self.queued, [])
