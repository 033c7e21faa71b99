"""freecadcmd -t test: a Fit's warnings name a point as the Sketcher shows it. The Sketcher's
Elements panel numbers a sketch's geometry from 1 in the order drawn, lines, arcs and
construction geometry included ('1-Line', '2-Arc', '3-Point', checked on FreeCAD 0.20.2 under
xvfb); the warnings named a point by its place among the sketch's points alone ('point 11 as
given'), which is not the panel's number where the sketch also holds edges, or where
coincident points were merged. Now: "Mixed's 14-Point"; a file's point by its line in the file
("line 17 of scan.csv"), titles, headers, comments and blank lines counted."""
import os
import tempfile
import unittest

import numpy as np

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica import fit_core
from freecad.elastica import sources as So


class FitSketcherNamesTest(S.DocTest):
    doc_name = "ElasticaFitSketcherNames"

    def _mixed(self, pts, twice=()):
        """A sketch drawn as a designer does: a line and an arc first, half the points, a
        construction line, the other half (points ``twice`` drawn twice on the spot: merged
        by the fit). Returns it and each point's geometry index."""
        sk = self.doc.addObject("Sketcher::SketchObject", "Mixed")
        sk.Placement = S.SKETCH_PLACEMENT
        sk.addGeometry(Part.LineSegment(App.Vector(1400, -900, 0), App.Vector(1450, -900, 0)),
                       False)
        sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(1400, -950, 0),
                                                    App.Vector(0, 0, 1), 30), 0.0, 2.0), False)
        at = []
        for k, (x, y) in enumerate(pts):
            if k == len(pts) // 2:
                sk.addGeometry(Part.LineSegment(App.Vector(1400, -1000, 0),
                                                App.Vector(1450, -1010, 0)), True)
            at.append(sk.addGeometry(Part.Point(App.Vector(x, y, 0)), False))
            if k in twice:
                sk.addGeometry(Part.Point(App.Vector(x, y, 0)), False)
        self.doc.recompute()
        return sk, at

    def test_a_stray_among_a_line_an_arc_and_20_points_is_named_as_the_elements_panel(self):
        pts = S.outlier_xy()
        sk, at = self._mixed(pts)
        self.assertEqual(at[11], 14)      # 2 edges and a construction line drawn before it
        for model in ("discrete", "smooth"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            said = S.outlier_said(self, f, model)
            # main: '(point 12 as given, ...)', the Elements panel's 12-Point another
            self.assertIn("(Mixed's 15-Point, in the sketch at (", said)
            self.assertNotIn("as given", said)

    def test_points_drawn_twice_are_merged_and_the_names_kept(self):
        pts = S.outlier_xy()
        sk, at = self._mixed(pts, twice=(3, 8))
        self.assertEqual(at[11], 16)
        for model in ("discrete", "smooth"):
            f = Fi.make(self.doc, [(sk, [])], Model=model)
            self.doc.recompute()
            self.assertEqual(len(f.DataPoints), 20)
            self.assertIn("(Mixed's 17-Point, in the sketch at (", S.outlier_said(self, f, model))

    def test_the_names_read_the_sketchs_geometry_once(self):
        """point_names reads sketch.Geometry once (review of e6f2667: once per point, each
        read copying every geometry: a 10 000-point sketch's names took 32 s, its points
        0.04 s, at each recompute and at the command's check): the reads counted, the names
        the Elements panel's."""
        sk, at = self._mixed(S.outlier_xy())

        class Counted:
            """The sketch, its Geometry reads counted."""
            Label = sk.Label

            def __init__(self):
                self.reads = 0

            @property
            def Geometry(self):
                self.reads += 1
                return sk.Geometry
        counted = Counted()
        self.assertEqual(So.point_names(counted), [f"Mixed's {i + 1}-Point" for i in at])
        self.assertEqual(counted.reads, 1)

    def test_a_label_holding_an_apostrophe_is_said_once(self):
        """Several points of one object share its label, said once, also where the label
        holds "'s " (review of e6f2667: "Bob's sketch's 11-Point, sketch's 26-Point")."""
        said, short = fit_core._listed(["Bob's sketch's 11-Point", "Bob's sketch's 26-Point"])
        self.assertEqual(said, "Bob's sketch's 11-Point, 26-Point")
        self.assertEqual(short("Bob's sketch's 26-Point"), "26-Point")
        said, _ = fit_core._listed(["Bob's wire's Vertex2", "Bob's part's Vertex5"])
        self.assertEqual(said, "Bob's wire's Vertex2, Bob's part's Vertex5")

    def test_picked_vertices_are_named_as_picked(self):
        """Vertices picked one by one: a wire's by its vertex name, a sketch's polyline's
        with the element the Elements panel lists it under (the first drawn ending there)."""
        pts = S.outlier_xy()
        wire = S.polyline_3d(self.doc, pts, name="Wire")
        sk = self.doc.addObject("Sketcher::SketchObject", "Profile")
        sk.Placement = S.SKETCH_PLACEMENT
        for a, b in zip(pts[:-1], pts[1:]):
            sk.addGeometry(Part.LineSegment(App.Vector(*a, 0), App.Vector(*b, 0)), False)
        self.doc.recompute()

        def vertex(obj, p):
            at = S.SKETCH_PLACEMENT.multVec(App.Vector(*p, 0))      # both placed by it
            return next(f"Vertex{k + 1}" for k, v in enumerate(obj.Shape.Vertexes)
                        if (v.Point - at).Length < 1e-6)
        for obj, name in ((wire, "Wire's "), (sk, "Profile's ")):
            subs = [vertex(obj, p) for p in pts]
            picked = name + subs[11] + (", the end of 11-Line" if obj is sk else "")
            for model in ("discrete", "smooth"):
                f = Fi.make(self.doc, [(obj, subs)], Model=model)
                self.doc.recompute()
                self.assertIn(f"({picked}, ", S.outlier_said(self, f, model))

    def test_a_files_point_is_named_by_its_line(self):
        pts = S.outlier_xy()
        rows = ["# hand sketch, mm", "Profile 7", "x,y", ""]
        for k, (x, y) in enumerate(pts):
            rows.append(f"{x:.4f},{y:.4f}")
            if k == 4:
                rows += ["", "# a second stroke"]
        line = 1 + rows.index(f"{pts[11][0]:.4f},{pts[11][1]:.4f}")
        self.assertEqual(line, 18)
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "scan.csv")
            with open(path, "w") as fh:
                fh.write("\n".join(rows) + "\n")
            for model in ("discrete", "smooth"):
                f = Fi.make(self.doc, csv_file=path, Model=model)
                self.doc.recompute()
                self.assertIn("(line 18 of scan.csv, at (", S.outlier_said(self, f, model))

    def test_a_npy_files_point_is_named_by_its_row(self):
        """A .npy array has rows, no lines (review of e6f2667: 'line 12 of scan.npy'); several
        listed as a file's lines are ("rows 3, 12 of scan.npy")."""
        pts = S.outlier_xy()
        with tempfile.TemporaryDirectory() as tmp:
            path = os.path.join(tmp, "scan.npy")
            np.save(path, pts)
            for model in ("discrete", "smooth"):
                f = Fi.make(self.doc, csv_file=path, Model=model)
                self.doc.recompute()
                self.assertIn("(row 12 of scan.npy, at (", S.outlier_said(self, f, model))
        said, short = fit_core._listed(["row 3 of scan.npy", "row 12 of scan.npy"])
        self.assertEqual(said, "rows 3, 12 of scan.npy")
        self.assertEqual(short("row 12 of scan.npy"), "row 12")


if __name__ == "__main__":
    unittest.main()
