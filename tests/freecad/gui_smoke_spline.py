"""The Elastic spline's panel, checked by the GUI smoke test (gui_smoke.py's run calls run_all
after the blend's, on its ElasticaSmoke document): tension and length modes, its G2 start, the
loops' warning line, OK and Cancel; then the spike without a free batten, whose command starts
at a tension that holds. Screenshots: gui_spline_panel.png, gui_spline_g2.png,
gui_spline_loops.png, gui_spline_spike.png."""
import math

import FreeCAD as App
import FreeCADGui as Gui

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def run_all(smoke, doc, S):
    global G
    G = smoke
    spline_panel(doc, S)
    spline_panel_spike(doc, S)


def spline_panel(doc, S):
    import Part
    from freecad.elastica import panelbase, taskpanels as T
    ducks = [(0, -100), (30, -90), (60, -95), (90, -80), (120, -100)]
    sk = S.points_sketch(doc, ducks, "Ducks")
    line = doc.addObject("Sketcher::SketchObject", "Lead")      # a line into the first duck
    line.Placement = S.SKETCH_PLACEMENT
    line.addGeometry(Part.LineSegment(App.Vector(-40, -112, 0), App.Vector(0, -100, 0)), False)
    doc.recompute()
    panel = G.open_panel(doc, "Elastica_Spline", [(sk, "")], "Elastic spline")
    s = panel.obj
    G.fits_combo_view(panel, "spline")
    text = panel.result.text()
    G.check(s.Status == "ok" and "free batten" in text and "energy" in text and "max curvature"
            in text and "duck forces" in text, f"spline panel: the free batten described ({text})")
    vp = s.ViewObject.Proxy
    G.check(vp.overlay_counts(0) == (5, 0) and vp.overlay_counts(1)[1] > 200 and
            vp.overlay_counts(2)[1] == 5 * 3, f"spline: ducks, comb and force arrows drawn "
                                            f"{[vp.overlay_counts(i) for i in range(3)]}")
    G.check(panel.tension.isEnabled() and not panel.length.isEnabled() and
            abs(panel.length.value() - s.SplineLength) < 1e-6,
            "spline, tension mode: length disabled, showing the spline's length")
    l0 = s.SplineLength
    G.click_arrow(panel.tension, up=True)
    G.wait()
    G.check(s.Tension > 0 and s.Status == "ok" and s.SplineLength < l0 and
            abs(panel.length.value() - s.SplineLength) < 1e-6,
            f"spline: an arrow click pulls the batten (tension {s.Tension:g}, length "
            f"{l0:.4f} -> {s.SplineLength:.4f})")
    panel.mode.setCurrentIndex(1)               # solve for a length
    G.wait()
    G.check(s.Mode == "length" and panel.length.isEnabled() and not panel.tension.isEnabled()
            and abs(s.Length.Value - s.SplineLength) < 1e-6 and s.Status == "ok",
            "spline mode switch: length mode starts from the length on screen")
    G.click_arrow(panel.length, up=True)
    G.wait()
    G.check(abs(s.SplineLength - s.Length.Value) < 1e-6 and s.SplineTension < s.Tension and
            abs(panel.tension.value() - s.SplineTension) < 1e-12,
            f"spline: a longer batten is pushed (tension {s.SplineTension:.3g} shown)")
    G.type_into(panel.length, "100")
    G.wait()
    G.check(s.Status.startswith("error") and "any length above" in G.error_line(panel) and
            s.ViewObject.DrawStyle == "Dashed" and not panel.accept() and T.CURRENT,
            f"spline: a too short length says which are possible ({s.Status})")
    G.type_into(panel.length, "140")
    G.wait()
    G.check(s.Status == "ok" and abs(s.Shape.Length - 140) < 1e-3, "spline: typed length 140")
    panel.mode.setCurrentIndex(0)
    G.wait()
    # the 140 mm batten is pushed together (tension < 0): tension mode cannot keep it, said
    G.check(s.Mode == "tension" and s.Status.startswith("ok; the spline shown by length (140.00 mm) "
                                                        "was pushed together")
            and panel.tension.minimum() == 0.0, f"spline: back to tension mode ({s.Status})")
    # a G2 start to the line: pick the edge, then the condition
    start_combo, start_btn = panel.ends[0]
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, line.Name, "Edge1")
    start_btn.click()
    G.wait()
    G.check(s.StartEdge and s.StartCondition == "tangent" and start_combo.currentIndex() == 1
            and s.Status == "ok" and "Lead.Edge1" in start_btn.text(),
            f"spline: a picked edge makes the start tangent ({s.Status})")
    k = 1.2 * s.Proxy.plane_curves(s)[0][0].curvature([0.0])[0]   # the tangent batten's, more
    start_combo.setCurrentIndex(2)
    G.wait()
    G.check(s.StartCondition == "G2" and s.Status.startswith("ok") and "guide duck" in
            panel.result.text() and len(s.GuideDucks) == 1
            and s.ViewObject.Proxy.overlay_counts(3) == (1, 3),
            f"spline: a G2 start to a line holds a guide duck, drawn apart ({s.Status})")
    G.screenshot("gui_spline_g2.png")
    # the user draws an arc into the first duck instead, bending a little more than the
    # tangent batten starts: G2 to it
    p, d = App.Vector(0, -100, 0), App.Vector(40, 12, 0).normalize()
    centre = p + App.Vector(-d.y, d.x, 0) * (1.0 / k)
    a = math.atan2(p.y - centre.y, p.x - centre.x)
    line.delGeometry(0)
    line.addGeometry(Part.ArcOfCircle(Part.Circle(centre, App.Vector(0, 0, 1), abs(1 / k)),
                                      *((a - 0.8, a) if k > 0 else (a, a + 0.8))), False)
    doc.recompute()
    panel.refresh()
    # the line it followed is deleted: it says so (not the arc now named Edge1) till relinked
    G.check(s.Status == f"error: StartEdge: the sketch geometry it followed ({line.Label}.Edge1, "
            "a line segment) was deleted; an arc is in its place: relink StartEdge" and "relink StartEdge" in G.error_line(panel),
            f"spline: its start edge deleted, it says so ({s.Status})")
    G.screenshot("gui_spline_edge_deleted.png")
    s.StartEdge = (line, ["Edge1"])
    doc.recompute()
    panel.refresh()
    G.check(s.Status.startswith("ok") and "guide duck" in panel.result.text(),
            f"spline: G2 to an arc: its guide duck holds the batten ({s.Status})")
    panel.closed.setChecked(True)
    G.wait()
    G.check(s.Closed and not start_combo.isEnabled() and not start_btn.isEnabled() and
            s.Status == "ok", "spline: closed, the ends disabled")
    panel.closed.setChecked(False)
    start_combo.setCurrentIndex(1)
    G.wait()
    panel.stiffness.setValue(2e6)
    G.wait()
    G.check("duck forces (N)" in panel.result.text(), "spline: forces in newtons given EI")
    Gui.Selection.clearSelection()
    Gui.ActiveDocument.ActiveView.setCameraOrientation(s.Plane.Rotation)
    panelbase.show_box(s.Shape.BoundBox)
    G.screenshot("gui_spline_panel.png")
    G.check(panel.accept(), "spline panel accepts")
    G.pump()
    # Cancel reverts an edit of an existing feature
    before = (s.Mode, s.Tension, s.StartCondition, s.Closed, round(s.Shape.Length, 9))
    panel = G.double_click(s)
    G.check(panel is not None and panel.obj is s, "spline: double-click opens its panel")
    panel.mode.setCurrentIndex(1)
    G.click_arrow(panel.length, up=True)
    G.wait()
    G.check(round(s.Shape.Length, 9) != before[4], "spline edit previews")
    panel.reject()
    G.pump()
    G.check((s.Mode, s.Tension, s.StartCondition, s.Closed, round(s.Shape.Length, 9)) == before,
            "spline Cancel reverts the edits")
    # moving a duck re-solves
    sk.movePoint(2, 1, App.Vector(60, -70, 0))
    doc.recompute()
    G.check(s.Status == "ok" and s.Shape.distToShape(Part.Vertex(
        S.SKETCH_PLACEMENT.multVec(App.Vector(60, -70, 0))))[0] < s.Tolerance,
        f"spline re-solves when a duck moves ({s.Status})")
    return s


def spline_panel_spike(doc, S):
    """A spike of ducks no free batten passes (QA: the command made nothing, and its
    message asked for a tension or a length in fields the user could not reach): the
    feature is made at a tension, its panel opens with the note on the warning line; a
    lower tension where the batten loops puts that on the warning line (it was in the
    Status only). Screenshots gui_spline_spike.png, gui_spline_loops.png. Cancel."""
    from freecad.elastica import panelbase, taskpanels as T
    sk = S.points_sketch(doc, [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)], "Spike",
                         App.Placement(App.Vector(0, 0, -150), App.Rotation()))
    names = [o.Name for o in doc.Objects]
    panel = G.open_panel(doc, "Elastica_Spline", [(sk, "")], "Spline without a free batten")
    s = panel.obj
    said = panel.warning[1].text()
    # the least tension of the command's whose batten does not loop and holds (stable)
    G.check(s.Status == "ok" and s.Tension == 6.57e-4 and abs(panel.tension.value() - s.Tension)
            < 1e-12 and panel.warning[0].isVisible() and "No free batten" in said and
            "0.000657" in said, f"spline without a free batten: made at a tension, the panel "
            f"says why ({s.Status}; {said})")
    Gui.Selection.clearSelection()
    Gui.ActiveDocument.ActiveView.setCameraOrientation(s.Plane.Rotation)
    panelbase.show_box(s.Shape.BoundBox)
    G.screenshot("gui_spline_spike.png")
    panel.tension.setValue(1.25e-5)
    G.wait()
    said = panel.warning[1].text()
    G.check(s.Status.startswith("ok; warning:") and "loops away" in said and
            panel.warning[0].isVisible() and "No free batten" not in said,
            f"spline that loops: on the warning line, not the note naming the command's tension "
            f"({said})")
    panelbase.show_box(s.Shape.BoundBox)
    G.screenshot("gui_spline_loops.png")
    panel.reject()
    G.pump()
    G.check([o.Name for o in doc.Objects] == names and not T.CURRENT,
            "spline without a free batten: Cancel removes it")
