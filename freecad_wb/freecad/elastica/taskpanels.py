"""The task panels of the Elastica features (their machinery, ``Panel``, is in
panelbase.py; the Elastic blend's, BlendPanel, in blend_panel.py) and open_for: like
FreeCAD's own Part and Sketcher panels, every change (arrow, wheel, typing) updates the
feature after a short pause; Cancel reverts everything
through the document's undo transaction (a feature a command has just made
disappears); every field has a tooltip with its unit; fields that do not apply are
disabled; the layout fits a 260 px Combo View. The panels edit the features'
properties only: what a value means and whether it is usable is the feature's
business (its Status, shown in red when it is an error)."""
from __future__ import annotations

import FreeCADGui as Gui
from PySide import QtGui

from . import blend as B
from . import ellblend as E
from . import spline as Sp
from .blend_panel import BlendPanel
from .fit_core import DISTANCE_NAMES, DISTANCES, MODEL_NAMES, MODEL_TIPS, MODELS
from .fit_ends import CONTINUITIES, CONTINUITY_NAMES
from .g2quad import join_words
from .sources import THOUSANDS
from .panelbase import CURRENT, Panel, _fmt, said_now
from .units import (area_text, figure_text, length_unit, number_text, per_length, tension_text,
                    tension_unit)



class FitPanel(Panel):
    title = "Fit elastica"
    icon_name = "fit"

    def build(self):
        o = self.obj
        g = self.box("Fit elastica")
        if o.CsvFile:                   # a point file's fit: the file and how it is read
            self.csv_rows(g)
        self.model = self.choice(g, "Model", "Model", MODELS,
                                 [MODEL_NAMES[m] for m in MODELS],
                                 "Discrete: the Bobenko-Suris discrete elastica, one vertex per "
                                 "(resampled) point; smooth: the smooth elastica",
                                 tips=[MODEL_TIPS[m] for m in MODELS])
        self.distance = self.choice(g, "Distance", "Distance", DISTANCES,
                                    [DISTANCE_NAMES[d] for d in DISTANCES],
                                    "What the smooth fit minimises: each point's distance to "
                                    "the curve (any spacing), or point i against arc length "
                                    "i L/(n-1) (equilateral data). A discrete fit minimises the "
                                    "distance to its polygon on uneven points, pairs point i "
                                    "with vertex i on equally spaced ones",
                                    when=lambda: o.Model == "smooth" and not o.SplitAtInflection)
        self.step = self.number(g, "Resample", "ResampleStep", 0.0, 1e6, 0.5, "mm",
                                "Equilateral resampling step before fitting (mm); 0 keeps the "
                                "points (a split keyline then cuts the polyline through the "
                                "medians of runs of its points into 100 segments: scan noise "
                                "does not lengthen it)")
        self.split = self.check(g, "Split at the inflection", "SplitAtInflection",
                                "Fit a keyline as one G2 curve of two elasticae meeting at its "
                                "inflection (seed 000 §5); its ends stay free")
        r = self.box("Result")
        self.row(r, "", self.result)
        self.warning_row(r)             # end conditions that cost accuracy
        vo = o.ViewObject
        self.show_data = self.check(r, "Show the fitted points", "ShowData",
                                    "Markers at the points the fit used", target=vo)
        self.show_res = self.check(r, "Show residual segments", "ShowResiduals",
                                   "A segment from each point to its nearest point on the curve",
                                   target=vo)
        e = self.box("Ends")
        # the end conditions apply to one-piece fits; a set one stays editable after a
        # split so that the user can clear what the split refuses
        row = e.rowCount()
        # a pin gives way to a G1 / G2 join at that end (which starts at the edge's end)
        # short labels and join boxes: the Ends box beside the task view's vertical scroll
        # bar (the Fit panel is the tallest) fits 1280 x 1024 (it was cut off by 19 px)
        self.pin_start = self.check(e, "Pin start", "PinStart",
                                    "The curve starts exactly at the first point (one-piece "
                                    "fits)", when=lambda: o.PinStart or (
                                        self.one_piece() and o.StartContinuity == "tangent"),
                                    at=(row, 0))
        self.pin_end = self.check(e, "Pin end", "PinEnd",
                                  "The curve ends exactly at the last point (one-piece fits)",
                                  when=lambda: o.PinEnd or (
                                      self.one_piece() and o.EndContinuity == "tangent"),
                                  at=(row, 1))
        self.tangent_buttons, self.joins = [], []
        for prop, text in (("StartTangent", "Start"), ("EndTangent", "End")):
            self.tangent_buttons.append(self.edge_button(
                e, f"{text} tangent", prop,
                f"{text} tangent: select an edge and click to follow its tangent (at its end "
                f"nearer where you clicked the edge; selected by a script, at its end nearest "
                f"the data's {text.lower()}; projected into the fit plane); click again to free "
                "it (one-piece fits)",
                when=lambda prop=prop: self.one_piece() or bool(getattr(o, prop)),
                freed=lambda i=len(self.joins): self.joins[i].setCurrentIndex(0)))
            join = self.choice(e, f"{text} join", f"{text}Continuity", CONTINUITIES,
                               [CONTINUITY_NAMES[c] for c in CONTINUITIES],
                               f"How the curve meets the {text.lower()} tangent's edge: its "
                               "tangent only, or joined to the edge's end: G1 starts there "
                               "with its tangent, G2 with its curvature too (the edge's end in "
                               "the fit plane)",
                               when=lambda prop=prop, text=text:
                               getattr(o, f"{text}Continuity") != "tangent" or
                               (self.one_piece() and bool(getattr(o, prop))))
            # a join takes the edge's point (G1, G2) and curvature (G2): a pin or a typed
            # curvature at that end is cleared
            join.currentIndexChanged.connect(lambda _, text=text: self.joined(text))
            join.setMinimumContentsLength(4)
            self.joins.append(join)
        self.start_curvature, self.end_curvature = (
            # "curvature" in full does not fit the 260 px Combo View beside its value
            self.checked_number(e, f"{text} \u03ba", f"Use{text}Curvature", f"{text}Curvature",
                                -1e6, 1e6, 1e-3, "1/mm",
                                f"{text} curvature \u03ba (1/mm), held when checked: 0 = a "
                                "free end or an inflection; + turns left seen from the fit "
                                "plane's normal (one-piece fits; a G2 join takes its edge's)",
                                when=lambda text=text: getattr(o, f"Use{text}Curvature")
                                or (self.one_piece() and getattr(o, f"{text}Continuity") != "G2"))
            for text in ("Start", "End"))
        self.bspline_box("the smooth elastica", "Degree of the smooth fit's B-spline (3 to 7); a "
                         "discrete fit's vertices are joined by the C2 cubic through them",
                         when=lambda: o.Model == "smooth")
        out = self.box("Output")
        # not into a source sketch: writing there would feed the fit its own output
        self.output_rows(out, [s.Name for s, _ in o.Source], "(new sketch in the fit plane)")

    def csv_rows(self, g):
        """The point file (CsvFile: its path, '...' choosing another, as FreeCAD's own
        Gui::FileChooser rows) and how '.' is read in it (Thousands, the question the Fit to
        CSV command asks where the file does not show it)."""
        o = self.obj
        w = QtGui.QWidget()
        line = QtGui.QHBoxLayout(w)
        line.setContentsMargins(0, 0, 0, 0)
        self.csv = QtGui.QLineEdit(o.CsvFile)
        self.csv.setToolTip("The CSV / text file of x,y[,z] points fitted (mm, or the unit its "
                            "header names: x [m],y [m]); read again at a recompute once it "
                            "changed on disk")
        self.csv.setCursorPosition(len(o.CsvFile))     # the file's name in sight
        self.csv.editingFinished.connect(self.csv_typed)
        pick = QtGui.QPushButton("...")
        pick.setFixedWidth(pick.fontMetrics().width(" ... ") + 12)
        pick.setToolTip("Choose another point file")
        pick.clicked.connect(self.csv_pick)
        line.addWidget(self.csv)
        line.addWidget(pick)
        self.row(g, "Points file", w, self.csv.toolTip())
        self.thousands = self.choice(
            g, "Thousands", "Thousands", list(THOUSANDS),
            ["auto", "1.000 = 1000", "1.000 = 1", "1,000 = 1000"],
            "How the file's '.' and ',' are meant: auto = as the file shows it (a ';' or tab "
            "separated file of a decimal-comma locale: 1.250,5 groups by '.'; an English tab "
            "export: 1,250.5 groups by ','); '.' groups thousands (1.000 = 1000); none: '.' "
            "is a decimal point, ',' a decimal comma (1.000 = 1,000 = 1); ',' groups "
            "thousands (1,000 = 1000)",
            tips=["as the file shows it (refused where it does not)",
                  "'.' groups thousands (1.000 = 1000)",
                  "'.' is a decimal point, ',' a decimal comma (1.000 = 1,000 = 1)",
                  "',' groups thousands, '.' is the decimal point (1,000.5 = 1000.5)"])

    def csv_typed(self):
        """The path typed: the file read from there; emptied: the file kept (a point file's
        fit has no Source to fall back on)."""
        text = self.csv.text().strip()
        if not text:
            self.csv.setText(self.obj.CsvFile)
        elif text != self.obj.CsvFile:
            self.set("CsvFile", text)

    def csv_pick(self):
        import os
        path, _ = QtGui.QFileDialog.getOpenFileName(
            Gui.getMainWindow(), "Points to fit", os.path.dirname(self.obj.CsvFile),
            "Point files (*.csv *.txt *.xyz);;All (*)")
        if path:
            self.csv.setText(path)
            self.csv_typed()

    def one_piece(self):
        return not self.obj.SplitAtInflection

    def joined(self, where):
        """A join at ``where`` (Start / End) takes the edge's end (G1, G2) and its
        curvature (G2): a pin and a typed curvature there are unchecked."""
        o = self.obj
        join = getattr(o, f"{where}Continuity")
        pin = self.pin_start if where == "Start" else self.pin_end
        curvature = (self.start_curvature if where == "Start" else self.end_curvature)[0]
        if join != "tangent" and getattr(o, f"Pin{where}"):
            pin.setChecked(False)
        if join == "G2" and getattr(o, f"Use{where}Curvature"):
            curvature.setChecked(False)

    def view_objects(self):
        """The data and the tangent edges stay in view with the fit."""
        o = self.obj
        return [s for s, _ in o.Source] + [link[0] for link in (o.StartTangent, o.EndTangent)
                                           if link]

    def result_text(self):
        o = self.obj
        ks = ", ".join(number_text(k) for k in o.K)
        n = len(o.DataPoints)
        if o.Model == "smooth":
            bs = f"B-spline within {figure_text(o.BSplineDeviation)} (degree {o.Degree})"
        else:
            # what the drawn curve adds to the polygon's distances
            bs = ("B-spline: the C2 cubic through the vertices, up to "
                  f"{figure_text(o.BSplineDeviation)} off the polygon")
        curve = "one G2 curve of two elasticae, " if len(o.K) == 2 else ""
        ends = ""
        if len(o.EndCurvatures) == 2:
            # rounding noise (below 1e-9 of 1/length: a natural end's) shown as 0
            size = o.Shape.Length if not o.Shape.isNull() else 0.0
            k0, k1 = (0.0 if abs(k) * size < 1e-9 else k for k in o.EndCurvatures)
            ends = f"<br>end \u03ba {number_text(k0 * length_unit()[0])}, {per_length(k1)}"
        # measured lengths: rounding noise as 0 (figure_text; the properties keep the figures)
        numbers = list(getattr(o, "PointNumbers", ()))
        if numbers and numbers != list(range(1, len(numbers) + 1)):
            # QA22gui F3: the lists run along the curve, the points were given otherwise
            n = (f"{n} points taken along the curve, not in the order given (DataPoints "
                 "and Distances in the fit's order; PointNumbers: each one's number as given)")
        else:
            n = f"{n} points"
        return (f"{n}, {o.ErrorMeasure}:<br>rms {figure_text(o.Rms)}, "
                f"max {figure_text(o.MaxError)}"
                f"<br>{curve}k = {ks}{ends}<br>{bs}<br>{said_now(o, 'Status')}")

    def refresh(self):
        """As every panel's; a G2 join's curvature field (disabled) shows the edge's, the
        others their property's value."""
        super().refresh()
        o = self.obj
        for i, (where, box) in enumerate((("Start", self.start_curvature),
                                          ("End", self.end_curvature))):
            g2 = getattr(o, f"{where}Continuity") == "G2" and not getattr(o, f"Use{where}Curvature")
            value = o.EndCurvatures[i] if g2 and len(o.EndCurvatures) == 2 else \
                getattr(o, f"{where}Curvature")
            if box[1].value() != value:
                self.show_value(box[1], value)


class SplinePanel(Panel):
    title = "Elastic spline"
    icon_name = "spline"
    MAX_DUCK_LINES = 8          # the duck forces listed in the panel (all are in DuckForces)

    def build(self):
        o = self.obj
        g = self.box("Elastic spline")
        self.warning_row(g)             # an end edge the spline does not meet
        self.mode = self.choice(g, "Solve for", "Mode", Sp.MODES, ["a tension", "a length"],
                                "A tension (0: the free batten, the fairest curve through the "
                                "points) or a total length (the tension follows)")
        self.tension = self.number(g, "Tension", "Tension", -1e6, 1e6, self.tension_step(),
                                   "1/mm\u00b2", "Tension sigma (1/mm\u00b2, >= 0): 0 = the free "
                                   "batten, larger pulls it straighter between the points. In "
                                   "length mode: the tension the length needs",
                                   when=lambda: o.Mode == "tension")
        self.length = self.number(g, "Length", "Length", 0.0, 1e7, 1.0, "mm",
                                  "Total length (mm), longer than the polygon through the "
                                  "points; 0 = the free batten's. In tension mode: the "
                                  "spline's length", when=lambda: o.Mode == "length")
        self.closed = self.check(g, "Closed", "Closed",
                                 "A closed batten through the points (no ends)")
        ends = self.box("Ends")
        is_open = lambda: not o.Closed  # noqa: E731
        self.ends = []
        for end, which in (("Start", "first"), ("End", "last")):
            combo = self.choice(ends, end, f"{end}Condition", Sp.END_CONDITIONS,
                                ["natural", "tangent to edge", "G2 to edge"],
                                f"At the {which} point: natural (curvature 0), tangent to the "
                                f"{end.lower()} edge, or G2 to it (tangent and curvature: a guide "
                                "duck in that end's span, drawn in orange, holds it)", when=is_open)
            btn = self.edge_button(ends, f"{end} edge", f"{end}Edge",
                                   f"Select an edge, then click: the {which} point follows it "
                                   "(at its end nearer where you clicked the edge; selected by "
                                   "a script, at its end nearest the point); click again to "
                                   "free it",
                                   empty="pick an edge", when=is_open,
                                   picked=lambda e=end: self.edge_picked(e))
            self.ends.append((combo, btn))
        r = self.box("Result")
        self.row(r, "", self.result)
        vo = o.ViewObject
        self.show_comb = self.check(r, "Show the curvature comb", "ShowComb",
                                    "Teeth outside the bend, as long as the curvature", target=vo)
        self.show_forces = self.check(r, "Show the duck forces", "ShowForces",
                                      "An arrow at each point: the force its duck exerts on the "
                                      "batten", target=vo)
        self.stiffness = self.number(r, "Stiffness EI", "Stiffness", 0.0, 1e15, 1e4,
                                     "N\u00b7mm\u00b2", "Bending stiffness EI of the batten "
                                     "(N\u00b7mm\u00b2): the duck forces in newtons; 0 = in "
                                     "units of EI/2")
        self.bspline_box("the spline", "Degree of the one B-spline (3 to 7), G2 at the points")
        out = self.box("Output")
        self.output_rows(out, [s.Name for s, _ in o.Points], "(new sketch in the spline's plane)")

    def tension_step(self):
        """An arrow step of the tension scale 1/h^2 (h: the mean distance between
        the points: sigma h^2 = 1 bends a span visibly less)."""
        ducks = list(self.obj.Ducks)
        h = sum((a - b).Length for a, b in zip(ducks, ducks[1:])) / max(len(ducks) - 1, 1)
        return float(f"{1.0 / h ** 2:.0e}") if h > 0 else 1e-4

    def view_objects(self):
        o = self.obj
        return [src for src, _ in o.Points] + [link[0] for link in (o.StartEdge, o.EndEdge)
                                               if link]

    def edge_picked(self, end):
        """A picked edge for a natural end makes it tangent (the user may ask for G2)."""
        prop = f"{end}Condition"
        if getattr(self.obj, prop) == "natural":
            self.set(prop, "tangent")
            combo = self.ends[0 if end == "Start" else 1][0]
            combo.blockSignals(True)
            combo.setCurrentIndex(Sp.END_CONDITIONS.index("tangent"))
            combo.blockSignals(False)

    def changed(self, prop):
        o = self.obj
        if prop == "Mode" and o.Ducks and not o.Status.startswith("error"):
            # the new mode starts from the spline on screen
            if o.Mode == "length":
                o.Length = o.SplineLength
            elif o.SplineTension >= 0:
                o.Tension = o.SplineTension

    def refresh(self):
        o = self.obj
        tension_mode = o.Mode == "tension"
        # a tension given must be >= 0; a length's tension may be negative (pushed)
        self.tension.blockSignals(True)
        self.tension.setMinimum(0.0 if tension_mode else -1e6)
        self.tension.blockSignals(False)
        given, shown = (self.tension, self.length) if tension_mode else (self.length, self.tension)
        value = float(getattr(o, "Tension" if tension_mode else "Length"))
        if given.value() != value or given.specialValueText():
            self.show_value(given, value)
        if o.Ducks and not o.Status.startswith("error"):
            self.show_value(shown, o.SplineLength if tension_mode else o.SplineTension)
        else:   # the dashed curve is the last good one's: no value for the failed solve
            self.show_no_value(shown)
        super().refresh()

    def forces_text(self):
        o = self.obj
        forces = [v.Length for v in o.DuckForces]
        if not forces:
            return ""
        ei = o.Stiffness
        per, per_unit = tension_unit()
        unit, scale = ("N", 0.5 * ei) if ei > 0 else (f"{per_unit} \u00d7 EI/2", per)
        order = sorted(range(len(forces)), key=lambda i: -forces[i])[:self.MAX_DUCK_LINES]
        more = len(forces) - len(order)
        items = ", ".join(f"{i + 1}: {number_text(forces[i] * scale)}" for i in sorted(order))
        guides = ", ".join(number_text(v.Length * scale) for v in o.GuideForces)
        return (f"duck forces ({unit}): {items}"
                + (f" (the {len(order)} largest of {len(forces)})" if more else "")
                + (f"; guide ducks (orange): {guides}" if guides else ""))

    def result_text(self):
        o = self.obj
        radius = f" (radius {_fmt(1 / o.MaxCurvature)})" if o.MaxCurvature > 0 else ""
        notes = said_now(o, 'Status').split("; ")[1:]
        tension = tension_text(o.SplineTension, o.SplineLength)
        lines = [f"length {_fmt(o.SplineLength)}, tension {tension}"
                 + (" (free batten)" if not B.tension_or_zero(o.SplineTension, o.SplineLength)
                    else ""),
                 f"energy \u222b\u03ba\u00b2 {per_length(o.Energy)}, max curvature "
                 f"{per_length(o.MaxCurvature)}{radius}",
                 self.forces_text(),
                 f"B-spline: {o.Poles} poles, degree {o.Degree}, within "
                 f"{figure_text(o.BSplineDeviation)}"] + notes
        return "<br>".join(line for line in lines if line)


class EllipticBlendPanel(Panel):
    title = "Elliptic blend curve"
    icon_name = "ellblend"

    def build(self):
        g = self.box("Elliptic blend curve")
        self.mode = self.choice(g, "Points", "Mode", E.MODES,
                                ["on the curve", "control points"],
                                "On the curve: the curve passes through the points (three or "
                                "more; four make one segment); control points: they shape it "
                                "like a Bezier polygon (3 n + 1 for n segments)")
        self.closed = self.check(g, "Closed", "Closed",
                                 "Through the points: the curve closes back to the first point, "
                                 "smooth there too", when=lambda: self.obj.Mode == "interpolate")
        self.conv = self.choice(g, "Elliptic", "KConvention", E.K_CONVENTIONS,
                                ["modulus k", "parameter m = k\u00b2"],
                                "How K is read: the modulus k, or the parameter m = k\u00b2 (the "
                                "paper's 'k')")
        self.k = self.number(g, "k or m", "K", 0.0, 0.999999, 0.05, "",
                             "Elliptic modulus k (or m) in [0, 1); 0 gives sines, the basis is "
                             "singular near k = 0.80241 (m = 0.64386)")
        self.d = self.number(g, "End factor d", "D", 1e-6, 1e3, 0.1, "",
                             "End-derivative parameter d > 0: the curve leaves the first point "
                             "with velocity d (q1 - q0). Control points only: through the "
                             "points the curve does not depend on d",
                             when=lambda: self.obj.Mode == "control")
        self.tol = self.number(g, "Tolerance", "Tolerance", 1e-9, 1e3, 1e-3, "mm",
                               "Largest distance of the B-spline from the blending curve (mm); "
                               "arrows step by a factor of 10", decade=True)
        r = self.box("Result")
        self.row(r, "", self.result)
        self.warning_row(r)
        self.show_q = self.check(r, "Show the control polygon", "ShowControlPolygon",
                                 "The control points and their polygon: with a negative "
                                 "basis the curve can leave their convex hull",
                                 target=self.obj.ViewObject)
        out = self.box("Output")
        self.output_rows(out, (), "(new sketch in the curve's plane)")

    def result_text(self):
        o = self.obj
        hull = "stays inside" if o.ConvexHull else "can leave"
        return (f"B-spline within {figure_text(o.BSplineDeviation)} of the curve (tolerance "
                f"{_fmt(o.Tolerance)})<br>basis min {number_text(o.BasisMin)}, condition "
                f"{number_text(o.Condition)}: the curve {hull} the hull of its control points"
                + (f"<br>control points {number_text(o.Spread)} times as far apart as the points"
                   if o.Mode == "interpolate" else ""))


class G2QuadPanel(Panel):
    title = "G2 quadratic B-spline"
    icon_name = "g2quad"

    def build(self):
        g = self.box("G2 quadratic B-spline")
        self.edges = self.integer(g, "Edges", "Edges", 3, 5000,
                                  "Edges of the affine arc-length polyline: about as many poles; "
                                  "the distance from the source falls like 1/Edges\u00b2; "
                                  "each inflection-free piece needs 3 (fewer is an error "
                                  "naming the Edges that cover the source)")
        self.polyline = self.check(g, "Show the polyline", "ShowPolyline",
                                   "The affine arc-length polyline: the control polygon inside "
                                   "each piece", target=self.obj.ViewObject)
        r = self.box("Result")
        self.row(r, "", self.result)
        out = self.box("Output")
        self.output_rows(out, [s.Name for s, _ in self.obj.Source],
                         "(new sketch in the curve's plane)")

    def result_text(self):
        o = self.obj
        # "-" until computed: a missing EndCurvatureError (a document from before it) or an
        # object not recomputed yet (no poles) is not an error of 0 (QA12)
        ek = getattr(o, "EndCurvatureError", None)
        ek = (f"{number_text(ek)} (relative to the source's largest curvature over the end piece)"
              if ek is not None and o.Poles > 0 else "-")
        return (f"{o.Pieces} piece{'s' if o.Pieces != 1 else ''} (split at inflections), "
                f"{o.Poles} poles, degree 2<br>distance from the source: "
                f"{figure_text(o.Deviation)}<br>"
                f"curvature jump at joints inside the pieces: {number_text(o.CurvatureJump)} (G2)<br>"
                + (f"where the pieces meet: tangents {number_text(o.JoinAngle)}\u00b0 apart, curvature "
                   f"jump {per_length(o.JoinCurvatureJump)} ({join_words(o.JoinAngle)})<br>"
                   if o.Pieces > 1 else "")
                + f"tangent off the source's at its ends by {number_text(o.SourceEndTangentError)}\u00b0"
                + (f", at any piece's end (the inflections) by at most "
                   f"{number_text(o.EndTangentError)}\u00b0" if o.Pieces > 1 else "")
                + f"; end curvature by {ek}<br>{said_now(o, 'Status')}")


class CombPanel(Panel):
    title = "Curvature comb"
    icon_name = "comb"

    def build(self):
        g = self.box("Curvature comb")
        self.samples = self.integer(g, "Teeth", "Samples", 2, 5000, "Teeth per curve")
        self.scale = self.number(g, "Scale", "Scale", 0.0, 1e12, 0.0, "mm\u00b2",
                                 "Tooth length per unit curvature (mm\u00b2); 0 = automatic (the "
                                 "longest tooth 12 % of the curve's size); arrows step by 10 %")
        # 0 is no scale of 0 mm² (QA24gui F6: 'Scale 0 mm²' over 'scale 979.4 mm²'): as
        # FreeCAD's own boxes show a value that means 'automatic'
        self.scale.setSpecialValueText("automatic")
        self.scale.stepBy = lambda steps: self.scale.setValue(
            (self.obj.Scale or self.obj.UsedScale) * 1.1 ** steps)
        self.row(g, "", self.result)

    def result_text(self):
        return f"scale {area_text(self.obj.UsedScale)}; {said_now(self.obj, 'Status')}"


PANELS = {"Fit": FitPanel, "Blend": BlendPanel, "Spline": SplinePanel,
          "EllipticBlend": EllipticBlendPanel, "G2Quad": G2QuadPanel, "Comb": CombPanel}


def open_for(obj, created=False, note=""):
    """Show the task panel of an Elastica feature. ``created``: a command has just
    made it inside a still open transaction (OK commits it, Cancel removes it);
    ``note``: why the command chose the values it did (the panel's warning line)."""
    panel = PANELS.get(getattr(getattr(obj, "Proxy", None), "kind", ""))
    if panel is None:
        return False
    if Gui.Control.activeDialog():
        # as FreeCAD's own edit: the open dialog stays (closing it dropped its edits without
        # OK or Cancel); its own feature's panel is already there
        from .commands import DIALOG_OPEN, message
        if CURRENT and getattr(CURRENT[0], "obj", None) is obj:
            return True
        message(DIALOG_OPEN)
        return False
    if created:
        # as Part_Offset2D's panel: the selection the command read is cleared (Delete took
        # the source sketch away under the new feature)
        Gui.Selection.clearSelection()
    p = panel(obj, created or bool(getattr(obj.Proxy, "fresh", False)), note=note)
    obj.Proxy.fresh = False
    CURRENT[:] = [p]
    Gui.Control.showDialog(p)
    gdoc = Gui.getDocument(obj.Document.Name)
    if created and gdoc.getInEdit() is None:
        # a command's new feature in edit, as FreeCAD's commands put theirs (setEdit after
        # making it): Std_Delete deletes nothing then, and closing the document ends the
        # edit and the panel (the view provider's setEdit finds this panel open)
        gdoc.setEdit(obj.Name, 0)
    return True
