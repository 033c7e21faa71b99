"""The Elastic blend's panel, checked by the GUI smoke test (gui_smoke.py's run calls run_all
first, on its ElasticaSmoke document): the default free batten, arrow clicks and typing in its
fields, the length mode, picking a solution, the guide ducks, OK and Cancel, Undo during an
edit. Screenshots: gui_blend_panel.png, gui_blend_undo.png and the others blend_panel takes.
The blend it makes is returned: the comb of gui_smoke_tools is made on it."""
import FreeCAD as App
import FreeCADGui as Gui

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def run_all(smoke, doc, S):
    global G
    G = smoke
    return blend_panel(doc, S)


def blend_panel(doc, S):
    from freecad.elastica import taskpanels as T
    sk = S.two_lines_sketch(doc)
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")
    panel = G.open_panel(doc, "Elastica_Blend", [(sk, "Edge1"), (sk, "Edge2")], "Elastic blend")
    b = panel.obj
    G.fits_combo_view(panel, "blend")
    G.check(b.Mode == "tension" and b.Tension == 0.0 and b.Solution == 1 and not
            b.Status.startswith("error"), "blend default: the free batten (tension 0)")
    G.check(list(b.Energies) == sorted(b.Energies) and panel.list.count() == len(b.Lengths) >= 1,
            f"blend panel lists {panel.list.count()} solutions, lowest energy first")
    G.check(all("inflection" in d and "loop" in d and "curvature" in d and "mm" in d
                for d in b.Descriptions), "blend solutions described (length, energy, "
                                        "inflections, loops, max curvature)")
    G.check(not panel.length.isEnabled() and panel.tension.isEnabled() and
            abs(panel.length.value() - b.Lengths[0]) < 1e-3 * b.Lengths[0],
            "blend, tension mode: length disabled, showing the solution's length")
    G.check(b.Poles <= 12, f"blend B-spline has few poles ({b.Poles})")
    G.click_arrow(panel.tension, up=True)
    G.wait()
    G.check(b.Tension > 0 and b.Solution == 1 and panel.list.count() == len(b.Lengths),
            f"blend: an arrow click raises the tension to {b.Tension:g} and re-solves")
    if panel.list.count() > 1:
        panel.list.setCurrentRow(1)            # the user picks the second solution
        G.pump()
        G.check(b.Solution == 2, "blend: picking a solution uses it (the list's 2: Solution 2)")
        G.click_arrow(panel.tension, up=True)
        G.wait()
        G.check(b.Solution == 2 or len(b.Lengths) < 2, "blend: the user's pick survives an edit")
    panel.continuity.setCurrentIndex(1)         # G2 by tension: >= 0 only
    G.wait()
    G.check(b.Continuity == "G2" and not b.Status.startswith("error") and
            panel.tension.minimum() == 0.0 and "guide ducks' forces" in panel.details.text(),
            f"blend: G2 by tension, the tension field from 0 ({b.Status})")
    # one line said, the why on demand (FreeCAD's panels): Details and the tooltip in full
    line = panel.result.text().replace("\u00a0", " ")     # (units.unbroken's spaces)
    G.check(line.startswith("G2 blend, ") and "<br>" not in line and len(line) < 80
            and panel.details.text().startswith("G2 from solution")
            and panel.result.toolTip() == panel.details.text() and panel.more.isVisible()
            and not panel.details.isVisible(),
            f"blend G2: one result line, the Status in full under Details ({line!r})")
    panel.more.setChecked(True)
    G.pump()
    G.check(panel.details.isVisible(), "blend G2: Details shows the full Status")
    panel.more.setChecked(False)
    panel.continuity.setCurrentIndex(0)
    G.wait()
    G.check(panel.tension.minimum() < 0, "blend: G1 takes a negative tension again")
    panel.picked = None
    panel.mode.setCurrentIndex(0)               # solve for a length
    G.wait()
    G.check(b.Mode == "length" and panel.length.isEnabled() and not panel.tension.isEnabled(),
            "blend mode switch: length enabled, tension disabled")
    G.type_into(panel.length, "20")
    G.wait()
    G.check(b.Status.startswith("error") and "above" in b.Status and "above" in G.error_line(panel)
            and not panel.result.text()
            and b.ViewObject.DrawStyle == "Dashed" and panel.list.count() == 0,
            f"blend: a too short length says which are possible ({b.Status})")
    # the length box as typed (no unit added while the user types, as FreeCAD's boxes)
    G.check(panel.tension.text() == panel.NO_RESULT and panel.length.text() == "20",
            f"blend: after the failed solve the greyed tension shows no value, not the last "
            f"good curve's ({panel.tension.text()!r}, {panel.length.text()!r})")
    G.check(not panel.accept() and T.CURRENT, "blend panel stays open on an error")
    G.type_into(panel.length, "70")
    G.wait()
    G.check(abs(b.Shape.Length - 70.0) < 1e-2 and b.ViewObject.DrawStyle == "Solid",
            f"blend typed length 70 -> {b.Shape.Length:.4f}")
    G.check(panel.tension.text() != panel.NO_RESULT and
            abs(panel.tension.value() - b.BlendTension) <= 1e-12 * abs(b.BlendTension),
            f"blend: solved again, the greyed tension shows the curve's ({panel.tension.text()})")
    # typed as in FreeCAD's own boxes: other units, an expression, a decimal comma ("7 cm"
    # was read as 7 mm, "=2*35" ignored)
    for text, mm in (("6.5 cm", 65.0), ("2.75 in", 69.85), ("=2*34", 68.0), ("70,5", 70.5), ("70", 70.0)):
        G.type_into(panel.length, text)
        G.wait()
        G.check(abs(b.Length.Value - mm) < 1e-9 and abs(b.Shape.Length - mm) < 1e-2,
                f"blend: typed {text!r} is {mm} mm (Length {b.Length.Value}, curve {b.Shape.Length:.4f})")
    panel.continuity.setCurrentIndex(1)         # G2
    G.wait()
    G.check(b.Continuity == "G2" and len(b.GuideDucks) == 2
            and panel.result.text().replace("\u00a0", " ").startswith("G2 blend, ")
            and "G2 from solution" in panel.details.text()
            and abs(b.Shape.Length - 70.0) < 1e-2
            and b.ViewObject.Proxy.overlay_counts() == (2, 2 * 3),
            f"blend: G2 from the chosen solution at the typed length, guide ducks drawn ({b.Status})")
    rows = [panel.list.item(r).text() for r in range(panel.list.count())]
    tips = [panel.list.item(r).toolTip() for r in range(panel.list.count())]
    G.check(rows and all(t.startswith("G1") for t in tips) and
            sum("\u2192 G2" in r for r in rows) == 1 and
            "\u2192 G2" in rows[b.Solution - 1] and "drawn: the G2 blend bent from it" in
            tips[b.Solution - 1].replace("\u00a0", " "),
            f"blend G2: the Solutions rows are the G1 solutions, the picked one says what is "
            f"drawn (QA gui F10) ({rows[b.Solution - 1] if rows else rows})")
    # each row one line in the 260 px Combo View (wrapped, the drawn row ran to three lines:
    # review revT), cut with an ellipsis where it ends, the drawn G2 length before the cut
    fm, view = panel.list.fontMetrics(), panel.list.viewport().width()
    heights = [panel.list.visualItemRect(panel.list.item(r)).height() for r in range(len(rows))]
    kept = rows[b.Solution - 1].split(",")[0] if rows else ""
    G.check(not panel.list.wordWrap() and not panel.list.horizontalScrollBar().isVisible()
            and heights and max(heights) < 2 * fm.height()
            and "\u2192 G2" in kept and fm.horizontalAdvance(kept) <= view,
            f"blend G2: each Solutions row one line, the drawn G2 length shown ({heights}, "
            f"{kept!r}: {fm.horizontalAdvance(kept)} px in {view} px)")
    G.screenshot("gui_blend_panel.png")
    # another Elastica command while this panel is open: inactive, and refused when called
    # (FreeCAD's own commands leave an open dialog alone; it was replaced without its OK
    # or Cancel, a sketch left in edit mode)
    from freecad.elastica import commands as C
    n_objects = len(doc.Objects)
    G.check(not C.FitCommand().IsActive() and C.fit_sources([(sk, ["Edge1", "Edge2"])]) is None
            and C.MESSAGES[-1] == C.DIALOG_OPEN and len(doc.Objects) == n_objects
            and T.CURRENT and T.CURRENT[0] is panel and Gui.Control.activeDialog()
            and T.open_for(b) and T.CURRENT[0] is panel,
            "blend panel open: another command is inactive and refused, the panel stays")
    panel.continuity.setCurrentIndex(0)
    G.wait()
    panel.into_sketch.setChecked(True)
    ng = len(sk.Geometry)
    G.check(panel.accept(), "blend panel accepts")
    G.pump()
    G.check(b.Name in [o.Name for o in doc.Objects] and len(sk.Geometry) == ng + 1,
            "blend OK: the feature stays, a copy goes into the sketch")
    joints = [(c.Type, c.Second, c.SecondPos) for c in sk.Constraints][-2:]
    G.check(sorted(joints) == [("Tangent", ng, 1), ("Tangent", ng, 2)] and sk.solve() == 0,
            f"blend OK: the copy is joined to both edges by a Tangent, as Sketcher's fillet, "
            f"and the sketch solves (QA gui F4) ({joints})")
    # Cancel reverts an edit of an existing feature
    before = (b.Mode, b.Length, b.Tension, round(b.Shape.Length, 9))
    panel = G.double_click(b)
    panel.mode.setCurrentIndex(1)
    G.click_arrow(panel.tension, up=True)
    G.wait()
    G.check(round(b.Shape.Length, 9) != before[3], "blend edit previews")
    panel.reject()
    G.pump()
    G.check((b.Mode, b.Length, b.Tension, round(b.Shape.Length, 9)) == before,
            "blend Cancel reverts the edits")
    # the feature stays parametric: moving an edge re-solves it
    sk.movePoint(1, 1, App.Vector(85, 40, 0))
    doc.recompute()
    G.check(not b.Status.startswith("error") and abs(b.Shape.Length - 70.0) < 1e-2,
            "blend re-solves when its edge moves")
    G.undo_during_edit(doc, b, "length", "Length", "71", "72", "blend")
    G.double_click_during_edit(doc, b, "length", "Length", "71", "blend")
    # a new blend cancelled: gone
    sk2 = S.two_lines_sketch(doc, "Lines2", App.Placement(App.Vector(0, 0, -30), App.Rotation()))
    doc.recompute()
    names = [o.Name for o in doc.Objects]
    G.open_panel(doc, "Elastica_Blend", [(sk2, "Edge1"), (sk2, "Edge2")], "Second blend")
    T.CURRENT[0].reject()
    G.pump()
    G.check([o.Name for o in doc.Objects] == names, "Cancel removes a new feature")
    # Undo while a new feature's panel is open: the feature goes and so does its panel (it
    # stayed open on nothing, and its OK reported success)
    G.open_panel(doc, "Elastica_Blend", [(sk2, "Edge1"), (sk2, "Edge2")], "Third blend")
    Gui.runCommand("Std_Undo")
    G.wait()
    G.check([o.Name for o in doc.Objects] == names and not T.CURRENT and not Gui.Control.activeDialog(),
            "Undo of a new feature closes its panel")
    # ends no free batten joins: the feature is made by length, its panel says why; Cancel
    sk3 = S.line_and_arc_sketch(doc, "LineArc", App.Placement(App.Vector(0, 0, -60),
                                                                 App.Rotation()))
    names = [o.Name for o in doc.Objects]
    panel = G.open_panel(doc, "Elastica_Blend", [(sk3, "Edge1"), (sk3, "Edge2")],
                         "Blend without a free batten")
    nb = panel.obj
    said = panel.warning[1].toolTip()
    G.check(nb.Mode == "length" and panel.mode.currentIndex() == 0 and panel.length.isEnabled()
            and not nb.Status.startswith("error") and panel.list.count() >= 1,
            f"blend without a free batten: by length {nb.Length}, {panel.list.count()} solutions "
            f"({nb.Status})")
    G.check(panel.warning[0].isVisible() and "No free batten" in said and "112.00 mm" in said,
            f"blend without a free batten: the panel says why it is by length ({said})")
    G.screenshot("gui_blend_no_free_batten.png")
    panel.reject()
    G.pump()
    G.check([o.Name for o in doc.Objects] == names and not T.CURRENT,
            "blend without a free batten: Cancel removes it")
    return b
