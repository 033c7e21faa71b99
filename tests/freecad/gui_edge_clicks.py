"""The spline's and the fit's edge buttons read where the edge was clicked, as the Elastic
blend command does (QA: they took the end nearest the points whatever was clicked), checked
by the GUI smoke test (gui_smoke.py calls run_all): an arc clicked near its end vertex is
followed there (StartEdgeAt / StartTangentAt 'end vertex'), near its start vertex there,
and a scripted selection (no click) keeps the nearest end; an end edge clicked that stops
31 mm short of the last duck (QA qagui F1) lends its sense into the edge, not the reverse,
said on the warning line. Screenshots: gui_spline_end_clicked.png, gui_spline_end_short.png."""
import math

import FreeCAD as App
import FreeCADGui as Gui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, ...)
DUCKS = [(0, 0), (30, 10), (60, 5), (90, 20), (120, 0)]


def arc_at_first_duck(doc):
    """An arc of radius 30 starting at the first duck and turning 1 rad away from it."""
    import Part
    sk = doc.addObject("Sketcher::SketchObject", "EndArc")
    sk.Placement = S.SKETCH_PLACEMENT
    sk.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(0, -30, 0), App.Vector(0, 0, 1), 30.0),
                                    0.5 * math.pi, 0.5 * math.pi + 1.0), False)
    doc.recompute()
    return sk


def click(doc, sk, fraction):
    """Select the arc as a click at ``fraction`` of it does (its PickedPoints); None: as a
    script does, without a point."""
    Gui.Selection.clearSelection()
    if fraction is None:
        Gui.Selection.addSelection(doc.Name, sk.Name, "Edge1")
        return
    e = sk.Shape.Edges[0]
    p = e.valueAt(e.FirstParameter + fraction * (e.LastParameter - e.FirstParameter))
    Gui.Selection.addSelection(doc.Name, sk.Name, "Edge1", p.x, p.y, p.z)


def start_tangent(feature):
    c = feature.Shape.Edges[0].Curve
    return App.Vector(c.tangent(c.FirstParameter)[0]).normalize()


def arc_tangent(sk, at_end):
    e = sk.Shape.Edges[0]
    return App.Vector(e.tangentAt(e.LastParameter if at_end else e.FirstParameter)).normalize()


def edge_button_clicks(doc, feature, button, prop, arc):
    """Click the edge button with the arc clicked near its end, its start, and selected by
    a script: ``prop + 'At'`` and the feature's start tangent follow."""
    for fraction, want in ((0.9, "end vertex"), (0.1, "start vertex"), (None, "nearest")):
        click(doc, arc, fraction)
        button.click()
        G.wait()
        t = start_tangent(feature)
        at_end = want == "end vertex"
        G.check(getattr(feature, prop + "At") == want and
                t.cross(arc_tangent(arc, at_end)).Length < 1e-6,
                f"{feature.Label}: the arc clicked at {fraction} -> {prop}At "
                f"{getattr(feature, prop + 'At')!r}, start tangent "
                f"{math.degrees(t.getAngle(arc_tangent(arc, at_end))):.3g} deg off its {want}'s")
        if fraction == 0.9 and prop == "StartEdge":
            G.screenshot("gui_spline_end_clicked.png")
        button.click()                      # free it: back to the nearest end
        G.wait()
        G.check(getattr(feature, prop + "At") == "nearest" and not getattr(feature, prop),
                f"{feature.Label}: freed, {prop}At {getattr(feature, prop + 'At')!r}")


def end_short_of_arc(doc):
    """The QA's profile (qagui f1.py): ducks climbing towards an arc r 60 (200 to 330 deg)
    whose start lies 31 mm past the last duck; the arc clicked near its start as the end
    edge, tangent then G2: the end runs into the arc as at that vertex (on main: 180 deg
    off, a hook back), G2 with its curvature, and the warning line says so."""
    import Part
    from freecad.elastica import taskpanels as T
    prof = doc.addObject("Sketcher::SketchObject", "ShortArc")
    prof.Placement = S.SKETCH_PLACEMENT
    prof.addGeometry(Part.ArcOfCircle(Part.Circle(App.Vector(330, 90, 0), App.Vector(0, 0, 1),
                                                  60.0), math.radians(200), math.radians(330)),
                     False)
    ducks = S.points_sketch(doc, [(140, 8), (190, 30), (225, 40), (248, 52)], "ShortDucks")
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")
    G.select(doc, [(ducks, "")])
    Gui.runCommand("Elastica_Spline")
    G.wait()
    panel = T.CURRENT[0]
    s = panel.obj
    click(doc, prof, 0.1)
    panel.ends[1][1].click()
    G.wait()
    arc = prof.Shape.Edges[0]
    into = App.Vector(arc.tangentAt(arc.FirstParameter))
    for index, condition in ((1, "tangent"), (2, "G2")):
        panel.ends[1][0].setCurrentIndex(index)
        G.wait()
        e = s.Shape.Edges[0]
        t = App.Vector(e.tangentAt(e.LastParameter))
        k = e.Curve.curvature(e.LastParameter)
        said = panel.warning[1].text() if panel.warning[0].isVisible() else ""
        G.check(s.EndCondition == condition and s.EndEdgeAt == "start vertex" and
                math.degrees(t.getAngle(into)) < 1e-7 and
                (condition == "tangent" or abs(k - 1 / 60.0) < 1e-8) and
                "running into the edge as at its start vertex" in said and "97.6 deg" in said,
                f"spline: an end 31 mm short of the arc runs into it ({condition}): "
                f"{math.degrees(t.getAngle(into)):.3g} deg off, curvature {k:.5g}; {said!r}")
    G.screenshot("gui_spline_end_short.png")
    panel.reject()
    G.wait()


def run_all(smoke):
    global G
    G = smoke
    from freecad.elastica import fit as Fi, spline as Sp, taskpanels as T
    doc = S.new_doc("ElasticaEdgeClicks")
    ducks = S.points_sketch(doc, DUCKS, "Ducks")
    arc = arc_at_first_duck(doc)
    Gui.SendMsgToActiveView("ViewFit")
    s = Sp.make(doc, [(ducks, [])], Tension=1e-4)
    doc.recompute()
    Gui.ActiveDocument.setEdit(s.Name)
    G.wait()
    panel = T.CURRENT[0]
    edge_button_clicks(doc, s, panel.ends[0][1], "StartEdge", arc)
    panel.reject()
    G.wait()
    end_short_of_arc(doc)
    xy, _ = S.keyline_xy(40)
    pts = S.points_sketch(doc, xy, "FitPoints")
    f = Fi.make(doc, [(pts, [])], Model="smooth")
    doc.recompute()
    arc2 = doc.addObject("Sketcher::SketchObject", "FitArc")
    arc2.Placement = S.SKETCH_PLACEMENT
    import Part
    import numpy as np
    d = xy[0] - xy[3]
    a = math.atan2(d[1], d[0])
    u = App.Vector(math.cos(a), math.sin(a), 0)
    p = App.Vector(*map(float, xy[0]), 0) + u * 5.0
    centre = p + App.Vector(-u.y, u.x, 0) * 30.0
    t0 = math.atan2(p.y - centre.y, p.x - centre.x)
    arc2.addGeometry(Part.ArcOfCircle(Part.Circle(centre, App.Vector(0, 0, 1), 30.0), t0, t0 + 0.3),
                     False)
    doc.recompute()
    del np
    Gui.ActiveDocument.setEdit(f.Name)
    G.wait()
    panel = T.CURRENT[0]
    for fraction, want in ((0.9, "end vertex"), (0.1, "start vertex"), (None, "nearest")):
        click(doc, arc2, fraction)
        panel.tangent_buttons[0].click()
        G.wait()
        G.check(f.StartTangentAt == want and not f.Status.startswith("error"),
                f"fit: the arc clicked at {fraction} -> StartTangentAt {f.StartTangentAt!r} "
                f"({f.Status[:60]!r})")
        if want != "nearest":
            t = App.Vector(start_tangent(f))
            G.check(t.cross(arc_tangent(arc2, want == "end vertex")).Length < 1e-6,
                    f"fit: its start follows the arc's {want} tangent")
        panel.tangent_buttons[0].click()
        G.wait()
    panel.reject()
    G.wait()
    Gui.Selection.clearSelection()
    App.closeDocument(doc.Name)
