"""freecadcmd -t tests of features whose sources lie in a container that moves: a
PartDesign Body placed and tilted, its sketches on its XZ plane (an attachment offset
turned 25 deg) and on a side face of a Pad, the Body alone or inside an App::Part. Every
feature reads its sources where the 3D view draws them (test_elastica_container), but
depended on the sketch only: moving or turning the Body left every one where it was,
Up-to-date, through a forced recompute and a reopen (QA19gui F1: 70.6 / 70.7 mm from the
points as drawn, 151 mm once the Body was back at the origin). Each test measures a
feature in the coordinates of its sketch, which move with the Body: a feature that
follows is where it was there, to 1e-9 mm."""
import math
import re
import unittest

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import containers

BODY = App.Placement(App.Vector(100, -50, 30), App.Rotation(App.Vector(1, 1, 0), 35))
OFFSET = App.Placement(App.Vector(10, 5, 0), App.Rotation(App.Vector(0, 0, 1), 25))
PTS = [(x, 25 * math.sin(x / 40.0) + 0.002 * x * x) for x in range(0, 130, 10)]
FOLLOWS = 1e-9          # mm: a feature that follows its sketch, in the sketch's coordinates


def moved(plc):
    """``plc`` moved by (50, 40, -30) and turned 20 deg about y: where a designer puts a
    Body next."""
    return App.Placement(plc.Base + App.Vector(50, 40, -30),
                         App.Rotation(App.Vector(0, 1, 0), 20).multiply(plc.Rotation))


def in_sketch(feature, sketch):
    """Points along the feature's edges (a comb's teeth too) in ``sketch``'s coordinates."""
    inv = sketch.getGlobalPlacement().inverse()
    return [inv.multVec(p) for e in feature.Shape.Edges for p in e.discretize(Number=20)]


def drawn(sketch, xy):
    """The sketch points ``xy`` where the 3D view draws them."""
    return [sketch.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in xy]


def printed(text):
    """The console text but FreeCAD's recompute progress ('Recompute......(10 %)')."""
    text = re.sub(r"Recompute\.*|\(\s*\d+ %\)", "", text)
    return [line.strip() for line in text.replace("\r", "\n").split("\n") if line.strip()]


def every_feature_from(test, sketch, comb_scale=None):
    """[(feature, its sketch)] of every kind the workbench makes: fit (smooth and discrete),
    spline, elliptic blend, G2 quadratic, blend and comb (at ``comb_scale``, else the
    automatic scale), from three sketches ``sketch(name)`` makes: Dots (PTS as points), Curve
    (a B-spline through PTS), Lines (two segments); each made and not in error (``test``
    asserts it). The scene of the container, recompute-kept and placed-Part tests."""
    dots = sketch("Dots")
    for x, y in PTS:
        dots.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
    curve = sketch("Curve")
    bs = Part.BSplineCurve()
    bs.interpolate([App.Vector(x, y, 0) for x, y in PTS])
    curve.addGeometry(bs, False)
    lines = sketch("Lines")
    lines.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(40, 0, 0)), False)
    lines.addGeometry(Part.LineSegment(App.Vector(80, 25, 0), App.Vector(120, 35, 0)), False)
    test.doc.recompute()
    App.setActiveDocument(test.doc.Name)
    said = []
    made = [(C.fit_sources([(dots, [])], False, Model="smooth", wrong=said.append), dots),
            (C.fit_sources([(curve, ["Edge1"])], False, Model="discrete", wrong=said.append),
             curve),
            (C.spline_sources([(dots, [])], False, wrong=said.append), dots),
            (C.ellblend_sources([(dots, [])], False, wrong=said.append), dots),
            (C.g2quad_sources([(curve, ["Edge1"])], False, Edges=96, wrong=said.append), curve),
            (C.blend_sources([(lines, ["Edge1"]), (lines, ["Edge2"])], False,
                             wrong=said.append), lines)]
    C.comb_sources([(curve, ["Edge1"])], wrong=said.append)
    made.append((next(o for o in test.doc.Objects if o.Name.startswith("ElasticaComb")), curve))
    if comb_scale is not None:
        made[-1][0].Scale = comb_scale
    test.doc.recompute()
    for f, _ in made:
        test.assertIsNotNone(f, said)
        test.assertFalse(f.Status.startswith("error"), f"{f.Name}: {f.Status}")
    return made


class ContainerMoveTest(S.DocTest):
    doc_name = "ElasticaContainerMoves"

    def setUp(self):
        super().setUp()
        self.body = self.doc.addObject("PartDesign::Body", "Body")
        self.body.Placement = BODY
        self.doc.recompute()

    def sketch(self, name, support=None):
        """A sketch in the Body on ``support`` (its XZ plane by default), turned by OFFSET."""
        if support is None:
            support = (next(o for o in self.body.Origin.OriginFeatures
                            if o.Role == "XZ_Plane"), [""])
        sk = self.body.newObject("Sketcher::SketchObject", name)
        sk.Support = support
        sk.MapMode = "FlatFace"
        sk.AttachmentOffset = OFFSET
        return sk

    def dots(self, support=None, name="Dots"):
        sk = self.sketch(name, support)
        for x, y in PTS:
            sk.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
        return sk

    def every_feature(self):
        """[(feature, its sketch)] of every kind the workbench makes, from sketches in the
        Body (every_feature_from)."""
        return every_feature_from(self, self.sketch)

    def assertFollow(self, made, before, what):
        """Each feature where it was ``before`` in its sketch's coordinates, to FOLLOWS."""
        for (f, sk), old in zip(made, before):
            now = in_sketch(f, sk)
            self.assertEqual(len(now), len(old), f"{f.Name} {what}")
            off = max((a - b).Length for a, b in zip(now, old))
            self.assertLess(off, FOLLOWS, f"{f.Name} {what}: {off:.3g} mm from where it was "
                                          "on its sketch")

    def move(self, obj, plc, made, before, what):
        """Set ``obj``'s Placement, recompute: every feature follows, nothing said."""
        obj.Placement = plc
        out, _ = S.console_output(self.doc.recompute)
        self.assertEqual(printed(out), [], what)
        self.assertFollow(made, before, what)

    def test_every_feature_follows_its_body_moved_and_turned(self):
        made = self.every_feature()
        before = [in_sketch(f, sk) for f, sk in made]
        dots = made[0][1]
        fit, spline = made[0][0], made[2][0]
        fit_off = S.distance_to_shape(drawn(dots, PTS), fit.Shape)
        self.move(self.body, moved(BODY), made, before, "Body moved and turned")
        self.move(self.body, App.Placement(), made, before, "Body back at the origin")
        # against the points as drawn, read from the sketch, not from the features' frames
        self.assertLess(S.distance_to_shape(drawn(dots, PTS), spline.Shape), FOLLOWS)
        self.assertLess(abs(S.distance_to_shape(drawn(dots, PTS), fit.Shape) - fit_off),
                        FOLLOWS)
        for f, _ in made:
            self.assertEqual(f.State, ["Up-to-date"], f.Name)

    def test_features_follow_a_body_inside_a_moved_part(self):
        part = self.doc.addObject("App::Part", "Part")
        part.Placement = App.Placement(App.Vector(-40, 70, 20), App.Rotation(App.Vector(0, 0, 1),
                                                                             60))
        part.addObject(self.body)
        made = self.every_feature()
        before = [in_sketch(f, sk) for f, sk in made]
        self.move(part, moved(part.Placement), made, before, "Part moved and turned")
        self.move(self.body, moved(BODY), made, before, "Body in the Part moved")
        for f, _ in made:
            self.assertEqual(list(f.Containers), [self.body, part], f.Name)

    def test_a_sketch_on_a_pad_face_moves_with_the_body(self):
        """A sketch attached to a side face of a Pad: its Support moves with the Body."""
        base = self.sketch("Base")
        corners = [(0, 0), (60, 0), (60, 40), (0, 40)]
        for (x0, y0), (x1, y1) in zip(corners, corners[1:] + corners[:1]):
            base.addGeometry(Part.LineSegment(App.Vector(x0, y0, 0), App.Vector(x1, y1, 0)))
        pad = self.body.newObject("PartDesign::Pad", "Pad")
        pad.Profile = base
        pad.Length = 30
        self.doc.recompute()
        side = next(f"Face{i + 1}" for i, face in enumerate(pad.Shape.Faces)
                    if abs(face.normalAt(0, 0).dot(base.Placement.Rotation.multVec(
                        App.Vector(0, 0, 1)))) < 1e-9)
        dots = self.dots((pad, [side]), "OnFace")
        self.doc.recompute()
        App.setActiveDocument(self.doc.Name)
        made = [(C.fit_sources([(dots, [])], open_panel=False, Model="smooth"), dots),
                (C.spline_sources([(dots, [])], open_panel=False), dots)]
        self.doc.recompute()
        before = [in_sketch(f, sk) for f, sk in made]
        self.move(self.body, moved(BODY), made, before, "Body moved and turned")
        self.assertLess(S.distance_to_shape(drawn(dots, PTS), made[1][0].Shape), FOLLOWS)

    def test_a_document_saved_before_the_link_follows_once_reopened(self):
        """A document saved before the features linked their containers, after its Body
        moved (its features then stayed where they were, as saved): reopened and
        recomputed, they are back on their sketches, and follow the next move."""
        made = self.every_feature()
        before = [in_sketch(f, sk) for f, sk in made]
        names = [(f.Name, sk.Name) for f, sk in made]
        for f, _ in made:
            if "Containers" in f.PropertiesList:
                f.removeProperty("Containers")          # as documents saved before had none
        self.body.Placement = moved(BODY)
        self.doc.recompute()
        f, sk = made[0]
        stale = max((a - b).Length for a, b in zip(in_sketch(f, sk), before[0]))
        self.assertGreater(stale, 10.0)                # the old document's fault, as saved
        reopened = S.reopened(self, "before_containers.FCStd", *[n for pair in names
                                                                  for n in pair])
        made = list(zip(reopened[0::2], reopened[1::2]))
        self.body = self.doc.getObject("Body")
        out, _ = S.console_output(self.doc.recompute)
        self.assertEqual(printed(out), [])
        self.assertFollow(made, before, "reopened, recomputed")
        self.move(self.body, BODY, made, before, "reopened, Body moved back")

    def test_a_feature_moved_into_the_part_holding_its_sketch_makes_no_cycle(self):
        """A feature put into the App::Part that holds the Body of its sketch (the tree's
        drag and drop: Part.addObject): its link to the Part would close a cycle (the Part
        holds it) and FreeCAD would recompute nothing ('The graph must be a DAG'); it
        follows the Body moved in the Part, the document recomputes without a word."""
        part = self.doc.addObject("App::Part", "Part")
        part.addObject(self.body)
        dots = self.dots()
        self.doc.recompute()
        fit = C.fit_sources([(dots, [])], open_panel=False, Model="smooth")
        self.doc.recompute()
        before = [in_sketch(fit, dots)]
        part.addObject(fit)
        out, _ = S.console_output(self.doc.recompute)
        self.assertEqual(printed(out), [])
        self.move(self.body, moved(BODY), [(fit, dots)], before, "Body in the Part moved")
        self.assertEqual(fit.State, ["Up-to-date"])
        self.assertEqual(list(fit.Containers), [self.body])

    def test_a_sketch_moved_into_a_placed_body_is_read_there(self):
        """A sketch at document level moved into the Body after a feature read it: the
        feature reads it placed by the Body, and follows the Body from then on."""
        sk = S.points_sketch(self.doc, PTS, "Loose", App.Placement())
        spline = C.spline_sources([(sk, [])], open_panel=False)
        self.doc.recompute()
        self.body.addObject(sk)
        out, _ = S.console_output(self.doc.recompute)
        self.assertEqual(printed(out), [])
        self.assertLess(S.distance_to_shape(drawn(sk, PTS), spline.Shape), FOLLOWS)
        self.body.Placement = moved(BODY)
        self.doc.recompute()
        self.assertLess(S.distance_to_shape(drawn(sk, PTS), spline.Shape), FOLLOWS)

    def test_a_group_change_relinks_only_the_features_it_concerns(self):
        """A Body's Group changing (Body.newObject, a sketch dropped in) links again the
        features reading what moved in or out, not the others: containers_of
        (InListRecursive) ran for every feature of the document at every change."""
        fit = C.fit_sources([(self.dots(), [])], open_panel=False, Model="smooth")
        other = self.doc.addObject("PartDesign::Body", "Other")
        other.Placement = moved(BODY)
        theirs = other.newObject("Sketcher::SketchObject", "Theirs")
        for x, y in PTS:
            theirs.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
        loose = S.points_sketch(self.doc, PTS, "Loose", App.Placement())
        blend = C.ellblend_sources([(theirs, [])], open_panel=False)
        spline = C.spline_sources([(loose, [])], open_panel=False)
        self.doc.recompute()
        asked = []
        real = containers.containers_of
        self.addCleanup(setattr, containers, "containers_of", real)
        containers.containers_of = lambda obj: asked.append(obj.Name) or real(obj)
        other.newObject("Sketcher::SketchObject", "New")
        self.assertEqual(asked, [], "Body.newObject")
        other.addObject(loose)
        self.assertEqual(asked, [spline.Name], "a sketch moved into a Body")
        self.assertEqual([list(f.Containers) for f in (fit, blend, spline)],
                         [[self.body], [other], [other]])
        out, _ = S.console_output(self.doc.recompute)
        self.assertEqual(printed(out), [])
        self.assertLess(S.distance_to_shape(drawn(loose, PTS), spline.Shape), FOLLOWS)


if __name__ == "__main__":
    unittest.main()
