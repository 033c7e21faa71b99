"""freecadcmd -t tests of what a recompute computes. Every feature links the containers
placing what it reads (containers.py), so FreeCAD executes it whenever anything in its
Body is recomputed: a Pad's length changed refitted every fit of the Body's sketches (a
50 000-point scan: 5-7 s, the GUI frozen). A feature whose inputs (its properties, the
geometry it reads where it is drawn) did not change keeps its outcome and calls no library
(kept.py); a Body moved, a source point dragged, a property typed compute again, once.
The calls are counted where they are made: each feature class's compute, fit_core, and
the binding's el.fit, which every library fit goes through."""
import os
import sys
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import blend, comb, ellblend, fit, fit_core, g2quad, kept, spline

from test_elastica_container_moves import BODY, PTS, every_feature_from, in_sketch, moved

PROXIES = (fit.FitProxy, spline.SplineProxy, ellblend.EllipticBlendProxy, g2quad.G2QuadProxy,
           comb.CombProxy, blend.BlendProxy)
FOLLOWS = 1e-9          # mm: a feature that follows its sketch, in the sketch's coordinates


def samples(shape):
    """Points along every edge of ``shape`` (exact: two shapes alike give the same)."""
    return [tuple(p) for e in shape.Edges for p in e.discretize(Number=25)]


class KeptTest(S.DocTest):
    doc_name = "ElasticaKept"

    def setUp(self):
        super().setUp()
        self.computed, self.fits, self.cores = [], [], []
        for cls in PROXIES:
            self.spy(cls, "compute", lambda f, self_, obj, *a: (self.computed.append(obj.Name),
                                                                f(self_, obj, *a))[1])
        self.spy(sys.modules["libelastica.fit"], "fit",
                 lambda f, *a, **k: (self.fits.append(1), f(*a, **k))[1])
        self.spy(fit_core, "fit_core",
                 lambda f, *a, **k: (self.cores.append(k.get("model")), f(*a, **k))[1])
        self.body = self.doc.addObject("PartDesign::Body", "Body")
        self.body.Placement = BODY
        self.doc.recompute()

    def spy(self, owner, name, wrapper):
        """owner.name replaced by wrapper(original, ...) until the test ends."""
        original = getattr(owner, name)
        setattr(owner, name, lambda *a, **k: wrapper(original, *a, **k))
        self.addCleanup(setattr, owner, name, original)

    def clear(self):
        del self.computed[:], self.fits[:], self.cores[:]

    def sketch(self, name, plane="XZ_Plane"):
        sk = self.body.newObject("Sketcher::SketchObject", name)
        sk.Support = (next(o for o in self.body.Origin.OriginFeatures if o.Role == plane), [""])
        sk.MapMode = "FlatFace"
        return sk

    def pad(self):
        """A Pad of a rectangle in the Body (the solid the designer models beside)."""
        base = self.sketch("Base", "XY_Plane")
        corners = [(-200, -200), (-140, -200), (-140, -160), (-200, -160)]
        for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
            base.addGeometry(Part.LineSegment(App.Vector(x0, y0, 0), App.Vector(x1, y1, 0)))
        pad = self.body.newObject("PartDesign::Pad", "Pad")
        pad.Profile = base
        pad.Length = 30
        return pad

    def every_feature(self):
        """[(feature, its sketch)]: every kind (every_feature_from), from sketches in the
        Body beside a Pad, the comb at Scale 500."""
        self.pad_ = self.pad()
        return every_feature_from(self, self.sketch, comb_scale=500.0)

    def assertUnchanged(self, made, before, what):
        for f, _ in made:
            self.assertEqual(f.State, ["Up-to-date"], f"{f.Name} {what}")
            self.assertEqual(samples(f.Shape), before[f.Name], f"{f.Name} {what}: shape changed")

    def test_a_pad_change_in_the_body_computes_no_feature(self):
        """A Pad's length changed: the Body recomputes, and so every feature linking it; none
        calls the library (main: each computed, both fits fitted)."""
        made = self.every_feature()
        before = {f.Name: samples(f.Shape) for f, _ in made}
        volume = self.pad_.Shape.Volume
        for length in (45.0, 12.5):
            self.clear()
            self.pad_.Length = length
            self.doc.recompute()
            self.assertAlmostEqual(self.pad_.Shape.Volume, volume * length / 30.0, 6)
            self.assertEqual(self.computed, [], f"Pad {length} mm")
            self.assertEqual((self.fits, self.cores), ([], []), f"Pad {length} mm")
            self.assertUnchanged(made, before, f"Pad {length} mm")
        # nothing touched, a forced recompute of every object: the same
        self.clear()
        for f, _ in made:
            f.touch()
        self.doc.recompute()
        self.assertEqual((self.computed, self.fits), ([], []))
        self.assertUnchanged(made, before, "touched")

    def test_a_body_moved_computes_each_feature_once_where_it_is_drawn(self):
        made = self.every_feature()
        before = [in_sketch(f, sk) for f, sk in made]
        self.clear()
        self.body.Placement = moved(BODY)
        self.doc.recompute()
        self.assertEqual(sorted(self.computed), sorted(f.Name for f, _ in made))
        self.assertEqual(self.cores, ["smooth", "discrete"])
        for (f, sk), old in zip(made, before):
            off = max((a - b).Length for a, b in zip(in_sketch(f, sk), old))
            self.assertLess(off, FOLLOWS, f"{f.Name}: {off:.3g} mm from where it was on its "
                                          "sketch")
        self.clear()
        self.pad_.Length = 50
        self.doc.recompute()
        self.assertEqual(self.computed, [])

    def test_a_source_point_dragged_computes_its_readers_once(self):
        """A point of the Dots sketch moved: the fit, spline and elliptic blend reading it
        compute once (the fit fitted once); the G2 quadratic, comb, blend and the discrete fit
        of other sketches not at all (main: all of them)."""
        made = self.every_feature()
        dots = made[0][1]
        readers = {f.Name for f, sk in made if sk == dots}
        before = {f.Name: samples(f.Shape) for f, _ in made}
        self.clear()
        x, y = PTS[5]
        dots.movePoint(5, 1, App.Vector(x, y + 1.5, 0))
        self.doc.recompute()
        self.assertEqual(sorted(self.computed), sorted(readers))
        self.assertEqual(self.cores, ["smooth"])
        self.assertGreater(len(self.fits), 0)
        for f, _ in made:
            self.assertEqual(samples(f.Shape) == before[f.Name], f.Name not in readers, f.Name)
        self.clear()
        self.doc.recompute()
        self.pad_.Length = 20
        self.doc.recompute()
        self.assertEqual((self.computed, self.fits), ([], []))

    def test_a_property_typed_computes_again(self):
        made = self.every_feature()
        f = made[0][0]
        self.clear()
        f.Tolerance = 1e-4
        self.doc.recompute()
        self.assertEqual(self.computed, [f.Name])
        self.assertEqual(f.Tolerance.Value, 1e-4)
        self.assertLessEqual(f.BSplineDeviation, 1e-4)

    def test_a_failed_fit_stays_failed_without_fitting(self):
        """An error kept: a Pad change says it again (the feature stays in error, its shape
        the last good one) without fitting."""
        made = self.every_feature()
        f = made[0][0]
        shape = samples(f.Shape)
        f.Degree = 12
        self.doc.recompute()
        self.assertIn("Invalid", f.State)
        status = f.Status
        self.assertTrue(status.startswith("error: Degree = 12"), status)
        self.clear()
        self.pad_.Length = 33
        self.doc.recompute()
        self.assertEqual(self.computed, [])
        self.assertIn("Invalid", f.State)
        self.assertEqual(f.Status, status)
        self.assertEqual(samples(f.Shape), shape)
        f.Degree = 5
        self.doc.recompute()
        self.assertEqual(f.State, ["Up-to-date"])
        self.assertEqual(self.computed, [f.Name])

    def test_undo_and_the_same_edit_again_computes_the_edit(self):
        """Undo restores an older outcome on the feature: the one kept is dropped, so the
        edit made again computes (it must not take the undone outcome for the edit's)."""
        self.doc.UndoMode = 1
        made = self.every_feature()
        f, dots = made[0]
        original = samples(f.Shape)
        x, y = PTS[5]
        self.doc.openTransaction("drag")
        dots.movePoint(5, 1, App.Vector(x, y + 3.0, 0))
        self.doc.recompute()
        self.doc.commitTransaction()
        dragged = samples(f.Shape)
        self.assertNotEqual(dragged, original)
        self.doc.undo()
        self.assertEqual(samples(f.Shape), original)
        self.clear()
        dots.movePoint(5, 1, App.Vector(x, y + 3.0, 0))
        self.doc.recompute()
        self.assertEqual(self.cores, ["smooth"])
        self.assertEqual(samples(f.Shape), dragged)

    def test_a_reopened_document_computes(self):
        """The outcome is kept on the proxy, never in the file: a reopened document's forced
        recompute fits."""
        made = self.every_feature()
        name = made[0][0].Name
        f, = S.reopened(self, "kept.FCStd", name)
        self.clear()
        f.touch()
        self.doc.recompute()
        self.assertEqual(self.cores, ["smooth"])

    def test_a_bug_in_the_key_is_no_silent_recompute(self):
        """A bug in input_key (here: reading a sketch's geometry raises TypeError) fails the
        recompute, which FreeCAD marks; it was taken for no key, and the feature computed
        at every recompute, unnoticed (review revfc 7). A source being deleted (the one case
        the key cannot be taken: ReferenceError) still computes."""
        made = self.every_feature()
        f = made[0][0]

        def bug(*_):
            raise TypeError("a bug in the key")
        self.spy(kept, "_content", lambda original, *a: bug())
        self.clear()
        f.touch()
        self.doc.recompute()
        self.assertIn("Invalid", f.State)
        self.assertEqual(self.cores, [])

    def test_a_source_being_deleted_computes(self):
        made = self.every_feature()
        f = made[0][0]

        def gone(*_):
            raise ReferenceError("This object is already deleted")
        self.spy(kept, "_content", lambda original, *a: gone())
        self.clear()
        f.touch()
        self.doc.recompute()
        self.assertEqual(f.State, ["Up-to-date"])
        self.assertEqual(self.cores, ["smooth"])

    def test_a_csv_file_rewritten_on_disk_computes_again(self):
        """A fit of a CSV file: the file's modification time and size are in the key (a
        PropertyFile names it; the text of the name alone does not change). Rewritten with a
        later time and the same size, or with another size and the time it had (copied with
        its times kept: cp -p, rsync -t, an archive; or a file system stamping whole
        seconds), it is read and fitted again; untouched, not."""
        xy = [(x, y) for x, y in PTS]
        path = S.temp_path(self, "scan.csv")

        def write(dx, dy, ns):
            with open(path, "w") as fh:
                fh.writelines(f"{x + dx:.6f},{y + dy:.6f}\n" for x, y in xy)
            os.utime(path, ns=(ns, ns))
            return os.stat(path).st_size
        t0 = 1_700_000_000 * 10**9
        size = write(0.0, 0.0, t0)
        f = fit.make(self.doc, [], csv_file=path)
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        first = f.DataPoints[0]
        self.clear()
        f.touch()
        self.doc.recompute()
        self.assertEqual(self.cores, [])
        # the same size (a 3-mm shift keeps every figure's width), one second later
        self.assertEqual(write(3.0, 0.0, t0 + 10**9), size)
        self.doc.recompute()
        self.assertEqual(len(self.cores), 1)
        self.assertAlmostEqual((f.DataPoints[0] - first).x, 3.0, delta=1e-9)
        # another size (a 100-mm shift adds digits), the time it had
        self.assertNotEqual(write(100.0, 0.0, t0 + 10**9), size)
        self.doc.recompute()
        self.assertEqual(len(self.cores), 2)
        self.assertAlmostEqual((f.DataPoints[0] - first).x, 100.0, delta=1e-9)
        self.assertEqual(f.State, ["Up-to-date"])

    def test_an_app_link_source_computes_when_what_it_links_changes(self):
        """A comb of an App::Link to a sketch (a link has no geometry property of its own: the
        key takes its shape where it is drawn, as BRep): the linked sketch edited or the link
        moved computes the comb again, following it; a Pad change in the Body does not."""
        self.pad_ = self.pad()
        curve = self.sketch("Curve")
        bs = Part.BSplineCurve()
        bs.interpolate([App.Vector(x, y, 0) for x, y in PTS])
        curve.addGeometry(bs, False)
        self.doc.recompute()
        link = self.doc.addObject("App::Link", "CurveLink")
        link.LinkedObject = curve
        link.Placement = App.Placement(App.Vector(0, 0, 200), App.Rotation())
        self.doc.recompute()
        c = comb.make(self.doc, link, Samples=20, Scale=500.0)
        self.doc.recompute()
        self.assertEqual(c.Status, "ok")

        def teeth_on_link():
            inv = curve.getGlobalPlacement().inverse()
            return [inv.multVec(link.Placement.inverse().multVec(v.Point))
                    for v in c.Shape.Vertexes]
        before = teeth_on_link()
        self.clear()
        self.pad_.Length = 44
        self.doc.recompute()
        self.assertEqual(self.computed, [])
        link.Placement = App.Placement(App.Vector(30, -20, 250),
                                       App.Rotation(App.Vector(0, 0, 1), 40))
        self.doc.recompute()
        self.assertEqual(self.computed, [c.Name])
        self.assertLess(max((a - b).Length for a, b in zip(teeth_on_link(), before)), FOLLOWS)
        self.clear()
        curve.movePoint(0, 1, App.Vector(-5, 8, 0))       # its start moved
        self.doc.recompute()
        self.assertEqual(self.computed, [c.Name])
        self.assertNotEqual(teeth_on_link(), before)


if __name__ == "__main__":
    unittest.main()
