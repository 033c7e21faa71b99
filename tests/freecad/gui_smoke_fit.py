"""The Fit's panel, checked by the GUI smoke test (gui_smoke.py's run calls run_all after the
spline's, on its ElasticaSmoke document): a fit of sketched points, its model, constraints at
the ends (the warning line), a G2 join to an arc, Undo during an edit; a sparse sketch fitted
by the discrete model; points far from the origin with a scan's glitches named. Screenshots:
gui_fit_panel.png, gui_fit_ends.png, gui_fit_g2.png, gui_fit_undo.png, gui_fit_sparse.png,
gui_fit_outliers.png. The keyline sketch the fit writes is returned: the G2 quadratic of
gui_smoke_tools is made from it."""
import math

import FreeCAD as App
import FreeCADGui as Gui

from freecad.elastica import units as U

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def run_all(smoke, doc, S):
    global G
    G = smoke
    ksk = fit_panel(doc, S)
    fit_panel_sparse(doc, S)
    fit_panel_far_points(doc, S)
    return ksk


def fit_panel(doc, S):
    import Part
    from freecad.elastica import taskpanels as T
    xy, curve = S.keyline_xy(30)
    ksk = S.bspline_sketch(doc, xy)
    # a line beside the data's start, for the start tangent (issue 13 point 3)
    lines = doc.addObject("Sketcher::SketchObject", "TangentLine")
    lines.Placement = S.SKETCH_PLACEMENT
    d = xy[0] - xy[2]
    a = math.atan2(d[1], d[0]) + 0.1
    p = App.Vector(*xy[0], 0) + App.Vector(math.cos(a), math.sin(a), 0) * 8.0
    lines.addGeometry(Part.LineSegment(p, p + App.Vector(math.cos(a), math.sin(a), 0) * 40.0),
                      False)
    # and an arc ending at the data's start, tangent to it there and curving 1.5 times as
    # much (the data's own start curvature is 0.0123/mm, turning left): for a G2 join
    th, k0 = float(curve.angle([0.0])[0]), 1.5 * float(curve.curvature([0.0])[0])
    p0 = App.Vector(*xy[0], 0)
    centre = p0 + App.Vector(-math.sin(th), math.cos(th), 0) / k0
    a0 = math.atan2(p0.y - centre.y, p0.x - centre.x)
    lines.addGeometry(Part.ArcOfCircle(Part.Circle(centre, App.Vector(0, 0, 1), 1 / k0),
                                       a0 - 0.5, a0), False)
    doc.recompute()
    panel = G.open_panel(doc, "Elastica_Fit", [(ksk, "Edge1")], "Fit elastica")
    f = panel.obj
    G.fits_combo_view(panel, "fit")
    G.check("rms" in panel.result.text() and "point to curve" in panel.result.text() and "k =" in
            panel.result.text() and "end \u03ba" in panel.result.text() and
            "-1 mm" not in panel.result.text(),
            "fit panel shows point-to-curve rms, max error, k, end curvatures, the B-spline (no "
            f"'-1 mm'): {panel.result.text()}")
    from PySide import QtCore
    G.check(panel.model.currentText() == "Discrete" and panel.model.itemData(
        0, QtCore.Qt.ToolTipRole).startswith("Discrete elastica"),
        "fit: human model names (short, in full in the tooltip: gui_fc_behaviour)")
    G.check(not panel.degree.isEnabled() and not panel.tol.isEnabled() and
            not panel.distance.isEnabled(),
            "fit, discrete model: B-spline degree, tolerance and distance disabled")
    G.check(panel.pin_start.isEnabled() and panel.pin_end.isEnabled() and
            all(b.isEnabled() for b in panel.tangent_buttons) and
            panel.start_curvature[0].isEnabled() and not panel.start_curvature[1].isEnabled(),
            "fit: pins, tangents and curvature boxes enabled; a curvature value only when checked")
    panel.model.setCurrentIndex(1)
    G.wait()
    G.check(f.Model == "smooth" and panel.degree.isEnabled() and panel.distance.isEnabled() and
            "converged" in f.Status, f"fit panel: smooth model ({f.Status})")
    t0 = f.Tolerance.Value
    G.click_arrow(panel.tol, up=True)
    shown = App.Units.Quantity(panel.tol.text()).Value   # mm, shown in the schema's unit
    G.check(abs(f.Tolerance.Value - 10 * t0) < 1e-12 * t0 and abs(shown - 10 * t0) < 1e-9 * t0,
            f"fit: tolerance arrow steps a decade ({t0:g} -> {panel.tol.text()})")
    G.click_arrow(panel.tol, up=False)
    G.click_arrow(panel.tol, up=False)
    G.wait()
    G.check(abs(f.Tolerance.Value - t0 / 10) < 1e-12 * t0 and "error" not in f.Status,
            f"fit: tolerance {f.Tolerance.Value:g} applied")
    panel.pin_end.click()                   # a mouse click on the check box
    G.wait()
    e = f.Shape.Edges[0]
    G.check(f.PinEnd and (e.valueAt(e.LastParameter) - f.DataPoints[-1]).Length < 1e-9,
            "fit: pin end puts the curve's end on the last point")
    panel.pin_end.click()
    G.wait()
    G.type_into(panel.step, "2")
    G.wait()
    panel.split.setChecked(True)
    G.wait()
    G.check(f.ResampleStep == 2.0 and len(f.Shape.Edges) == 1 and len(f.K) == 2 and
            not panel.pin_start.isEnabled() and not panel.distance.isEnabled() and
            "G2" in panel.result.text(), "fit panel: keyline as one G2 curve, ends disabled")
    G.check(len(f.DataPoints) == len(f.FootPoints) > 20, "fit: fitted points and their feet kept")
    vp = f.ViewObject.Proxy
    G.check(vp.overlay_counts() == (len(f.DataPoints), 0), f"fit: markers drawn {vp.overlay_counts()}")
    panel.show_res.setChecked(True)
    G.check(f.ViewObject.ShowResiduals and vp.overlay_counts() == (len(f.DataPoints),) * 2,
            "fit: residual segments drawn")
    panel.show_data.setChecked(False)
    G.check(vp.overlay_counts()[0] == 0, "fit: markers hidden on request")
    panel.show_data.setChecked(True)
    G.type_into(panel.step, "5000")               # longer than the curve: bad input
    G.wait()
    G.check("error" in G.error_line(panel) and not panel.accept() and T.CURRENT,
            "fit panel shows the error and stays open")
    G.type_into(panel.step, "2")
    G.wait()
    G.check(not G.error_line(panel) and "rms" in panel.result.text(), "fit panel recovers")
    # the sketched B-spline's points fit to ~3e-4 mm: no "outliers?" line for a misfit of
    # 1e-3 mm on a 330 mm curve (it named 6 of 60)
    G.check(not panel.warning[0].isVisible() and not [w for w in f.Warnings if "outliers?" in w],
            f"fit of a sketched curve: no far points named ({list(f.Warnings)})")
    G.screenshot("gui_fit_panel.png")
    # Copy into: only sketches in the fit's plane (another one flattened the copy onto it)
    offered = [panel.sketch.itemData(i) for i in range(panel.sketch.count())]
    G.check("TangentLine" in offered and "Lines2" not in offered and "KeylineSketch" not in offered,
            f"fit: Copy into offers the sketches in the fit plane, not its source ({offered})")
    panel.sketch.setCurrentIndex(panel.sketch.count() - 1)   # new sketch
    G.check(panel.accept(), "fit panel accepts")
    G.pump()
    out = [o for o in doc.Objects if o.Name.startswith("ElasticaSketch")]
    G.check(len(out) == 1 and len(out[0].Geometry) == 1,
            "fit: the keyline copied into a new sketch as ONE B-spline")
    fit_panel_ends(doc, f, lines, k0)
    return ksk


def fit_panel_ends(doc, f, lines, k0):
    """Editing a fit's ends in its panel (double-click): pin end, a start tangent
    picked from an edge, a G2 join to the arc of curvature k0 (lines' Edge2), a start
    curvature the model cannot meet (its message names the field, the shape stays), and
    Cancel reverting all of it."""
    import elastica_samples as S
    before = (f.Model, f.SplitAtInflection, f.PinEnd, f.StartTangent, round(f.Rms, 12),
              round(f.Shape.Length, 9))
    panel = G.double_click(f)
    panel.split.setChecked(False)
    G.wait()
    panel.pin_end.click()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, f.Name, "Edge1")         # its own edge: refused
    panel.tangent_buttons[0].click()
    G.check(not f.StartTangent and "another object" in panel.result.text(),
            "fit: a tangent from the fit's own edge is refused")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, lines.Name, "Edge1")
    panel.tangent_buttons[0].click()                              # the user's pick
    G.wait()
    e = f.Shape.Edges[0]
    line = lines.Shape.Edges[0]
    t = App.Vector(e.tangentAt(e.FirstParameter)).normalize()
    # resampled (step 2 mm): the pinned end is the last of the points given (DataPoints),
    # where the resampled polygon ends
    pinned = f.DataPoints[-1]
    G.check(f.StartTangent and f.StartTangent[0] is lines and panel.tangent_buttons[0].text() ==
            f"{lines.Label}.Edge1" and t.cross(line.tangentAt(0)).Length < 1e-9 and
            (e.valueAt(e.LastParameter) - pinned).Length < 1e-9,
            f"fit: start tangent from a picked edge, end pinned ({f.Status})")
    # the line is 0.1 rad off the exact data's start: the warning line says what it costs
    # (the free rms in the unit FreeCAD's Standard schema picks for it: µm below 0.1 mm)
    free = U.length_text(f.FreeRms)
    G.check(f.Warnings and panel.warning[0].isVisible() and "Start tangent" in
            panel.warning[1].text() and free in panel.warning[1].text() and
            f.Rms > 2 * f.FreeRms and not [w for w in f.Warnings if "outliers?" in w] and
            not [w for w in f.Warnings if "resampled polygon" in w],
            f"fit: the end conditions' cost on the warning line, no outliers named ({f.Warnings})")
    f.ViewObject.ShowResiduals = True
    view = Gui.ActiveDocument.ActiveView
    view.setCameraOrientation(f.Plane.Rotation)
    from freecad.elastica.panelbase import show_box
    box = App.BoundBox(lines.Shape.BoundBox)         # the start: the tangent line, residuals
    for p in f.DataPoints[:len(f.DataPoints) // 4]:
        box.add(p)
    show_box(box)
    G.screenshot("gui_fit_ends.png")
    # joined G2 to the arc: freeing the line sets its join back to Tangent only; the G2
    # join starts the curve at the arc's end (the data's first point) with the arc's
    # tangent and curvature, and a typed start curvature and Pin start give way
    G.check(panel.joins[0].isEnabled() and not panel.joins[1].isEnabled(),
            "fit: the start join applies (its edge picked), the end join not (no end edge)")
    panel.joins[0].setCurrentIndex(2)
    G.wait()
    G.check(f.StartContinuity == "G2" and not panel.start_curvature[0].isEnabled() and
            not panel.pin_start.isEnabled() and "error" not in f.Status,
            f"fit: start join G2, start curvature and Pin start disabled ({f.Status})")
    panel.tangent_buttons[0].click()                              # free the line
    G.wait()
    G.check(not f.StartTangent and f.StartContinuity == "tangent" and
            panel.joins[0].currentIndex() == 0 and not panel.joins[0].isEnabled() and
            "error" not in f.Status,
            f"fit: freeing the start tangent sets its join back to Tangent only ({f.Status})")
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, lines.Name, "Edge2")
    panel.tangent_buttons[0].click()
    panel.joins[0].setCurrentIndex(2)
    G.wait()
    start, _, kappa = S.travel_ends(f)[0]
    arc_end = lines.Shape.Edges[1].Vertexes[1].Point
    G.check(f.StartContinuity == "G2" and abs(kappa - k0) < 1e-9 and
            (start - arc_end).Length < 1e-9 and "error" not in f.Status,
            f"fit: G2 to the picked arc: starts at its end, curvature {kappa:.6g}/mm, the arc's "
            f"{k0:.6g}/mm ({f.Status})")
    G.check(abs(panel.start_curvature[1].value() - k0) < 1e-9 and f"end \u03ba {U.number_text(k0)}" in
            panel.result.text(), "fit: the G2 join's curvature in its (disabled) field and the "
            f"result ({panel.start_curvature[1].text()})")
    box = App.BoundBox(lines.Shape.Edges[1].BoundBox)          # the arc and the join
    for q in f.DataPoints[:len(f.DataPoints) // 6]:
        box.add(q)
    show_box(box)
    from PySide import QtGui
    scroll = panel.joins[0]
    while scroll is not None and not isinstance(scroll, QtGui.QScrollArea):
        scroll = scroll.parentWidget()
    if scroll is not None:                  # the Ends box in sight (scrolled down only)
        from PySide import QtCore
        y = panel.joins[0].mapTo(scroll.widget(), QtCore.QPoint(0, 0)).y()
        scroll.verticalScrollBar().setValue(y - 150)
    G.screenshot("gui_fit_g2.png")
    if scroll is not None:
        scroll.verticalScrollBar().setValue(0)
    panel.model.setCurrentIndex(0)              # the discrete model's cubic joins G2 too
    G.wait()
    start, _, kappa = S.travel_ends(f)[0]
    G.check(f.Model == "discrete" and panel.joins[0].isEnabled() and abs(kappa - k0) < 1e-9
            and (start - arc_end).Length < 1e-9 and "error" not in f.Status,
            f"fit: discrete, G2 to the arc: start curvature {kappa:.6g}/mm ({f.Status})")
    panel.model.setCurrentIndex(1)
    panel.joins[0].setCurrentIndex(0)
    G.wait()
    G.check(panel.start_curvature[1].value() == f.StartCurvature and panel.pin_start.isEnabled(),
            "fit: back to Tangent only, the curvature field shows its own value again, Pin "
            "start applies")
    # a start curvature of 1000/mm (radius 1 um): the smooth model meets it with a
    # separatrix curl (a poor fit, but a fit); the discrete one of 2 mm segments cannot
    panel.model.setCurrentIndex(0)
    G.wait()
    shape = f.Shape.copy()
    panel.start_curvature[0].click()
    G.type_into(panel.start_curvature[1], "1000")
    G.wait()
    G.check("Start curvature cannot be met" in G.error_line(panel) and
            abs(f.Shape.Length - shape.Length) < 1e-12,
            "fit: a start curvature the model cannot meet: the panel names it, the shape stays "
            f"({f.Status})")
    G.check(not panel.warning[0].isVisible(), "fit: no warning line beside an error")
    panel.reject()
    G.pump()
    after = (f.Model, f.SplitAtInflection, f.PinEnd, f.StartTangent, round(f.Rms, 12),
             round(f.Shape.Length, 9))
    G.check(after == before and panel.tangent_buttons, f"fit Cancel reverts ({after} vs {before})")
    G.undo_during_edit(doc, f, "tol", "Tolerance", "0.1", "1", "fit")


def fit_panel_sparse(doc, S):
    """A sketch of 7 points fitted by the default (discrete) model: the warning line
    says its polygon of 6 segments lies far from them and names the smooth model; with
    Model set to smooth the warning goes. Cancel removes the new feature."""
    psk = S.points_sketch(doc, [(x + 140.0, y - 60.0) for x, y in (
        (10.007, 5.016), (16.543, 11.151), (28.999, 29.244), (34.834, 43.041),
        (41.322, 66.133), (44.22, 78.81), (48.429, 95.26))], "SevenPoints")
    panel = G.open_panel(doc, "Elastica_Fit", [(psk, "")], "Fit elastica on 7 points")
    f = panel.obj
    G.wait()
    text = panel.warning[1].text()
    G.check(f.Model == "discrete" and panel.warning[0].isVisible() and "7 points" in text and
            "Smooth elastica" in text and U.length_text(f.Rms) in text,
            f"fit of 7 points, discrete: the warning line names the smooth model ({text})")
    view = Gui.ActiveDocument.ActiveView
    view.setCameraOrientation(f.Plane.Rotation)
    from freecad.elastica.panelbase import show_box
    show_box(App.BoundBox(psk.Shape.BoundBox))
    G.screenshot("gui_fit_sparse.png")
    rms = f.Rms
    panel.model.setCurrentIndex(1)
    G.wait()
    G.check(f.Model == "smooth" and not panel.warning[0].isVisible() and f.Rms < 0.1 * rms,
            f"fit of 7 points, smooth: no warning, rms {f.Rms:.3g} mm (discrete {rms:.3g} mm)")
    n0 = len(doc.Objects)
    panel.reject()
    G.pump()
    G.check(len(doc.Objects) == n0 - 1, "fit of 7 points: Cancel removes the new feature")


def fit_panel_far_points(doc, S):
    """A scan's sketch of 40 noisy points with two glitches (15 and 25 mm off): the warning
    line counts them, with their distances; the residual segments run out to them."""
    import numpy as np
    xy, _ = S.keyline_xy(40)
    xy = xy + np.random.default_rng(4).normal(0.0, 0.1, xy.shape) + [0.0, -160.0]
    xy[[10, 25]] += [[12.0, -9.0], [-20.0, 15.0]]
    psk = S.points_sketch(doc, xy, "Glitches")
    panel = G.open_panel(doc, "Elastica_Fit", [(psk, "")], "Fit elastica of a scan with glitches")
    f = panel.obj
    G.wait()
    text = panel.warning[1].text()
    G.check(panel.warning[0].isVisible() and "2 of 40 points lie" in text and "outliers?" in text,
            f"fit of a scan with glitches: the warning line counts them ({text})")
    view = Gui.ActiveDocument.ActiveView
    view.setCameraOrientation(f.Plane.Rotation)
    from freecad.elastica.panelbase import show_box
    show_box(App.BoundBox(psk.Shape.BoundBox))
    G.screenshot("gui_fit_outliers.png")
    panel.reject()
    G.pump()
