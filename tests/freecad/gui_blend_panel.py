"""The Elastic blend command and its panel as FreeCAD's own tools behave (QA 9), checked by
the GUI smoke test (gui_smoke.py calls run_all):

- the two edges are joined at the ends nearer where they were clicked (PickedPoints), as
  Sketcher's trim and fillet read a click: a U profile's walls clicked near their tops
  were blended at their bottoms, already joined by the profile's bottom line;
- new ends no free batten joins (AtEnd toggled at tension 0) start by a length, as the
  command does, said on the warning line, and switching to length mode with no length
  fills one in: the panel showed an error, then Length 0 and "give a length";
- a field bound to an expression is read-only and marked (FreeCAD's bound-expression
  icon, the expression in its tooltip): typing in it showed a value the feature did not
  take, and OK kept the expression's silently;
- lengths show in the user's unit schema and take what is typed in any unit: the boxes
  showed mm under every schema and '7 in mm' while '7 in' was typed; a plain number is
  in the unit the box shows now, after its arrows changed it ('12' over '10 m'); under
  Building US lengths in feet and inches as FreeCAD writes them ('6"', '1\' 3/4"');
- the command's note (why by length) follows the length: typed over, it goes (it named the
  old length beside the new curve).

Screenshots: gui_blend_picked_tops.png, gui_blend_note_typed.png, gui_blend_ends_by_length.png,
gui_blend_bound.png, gui_blend_imperial.png, gui_blend_typed_after_step.png,
gui_blend_building_us.png, gui_blend_said_after_undo.png."""
import os

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import elastica_samples as S
from freecad.elastica.units import number_text

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def keys(widget, text):
    """Type ``text`` key by key into ``widget`` (what has focus gets them)."""
    for ch in text:
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, 0, QtCore.Qt.NoModifier, ch))
    G.pump()


def key(widget, k):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(widget, QtGui.QKeyEvent(kind, k, QtCore.Qt.NoModifier))
    G.pump()


def retype(box, text):
    """Select all of a spin box's text and type ``text`` (the unit too, if any)."""
    box.setFocus()
    G.pump()
    box.lineEdit().selectAll()
    key(box.lineEdit(), QtCore.Qt.Key_Delete)
    keys(box.lineEdit(), text)


def profile(doc):
    sk = S.u_profile_sketch(doc, placement=App.Placement())
    Gui.SendMsgToActiveView("ViewTop")
    Gui.SendMsgToActiveView("ViewFit")
    return sk, S.sketch_names(sk, [(1, "edge"), (2, "edge")])


def ends_of(b):
    e = b.Shape.Edges[0]
    return sorted(tuple(round(c, 6) + 0.0 for c in e.valueAt(u))
                  for u in (e.FirstParameter, e.LastParameter))


TOPS = [(0.0, 30.0, 0.0), (100.0, 20.0, 0.0)]
BOTTOMS = [(0.0, 0.0, 0.0), (100.0, 0.0, 0.0)]


def picked_ends(doc):
    """Walls clicked near their tops: blended top to top (by length: no free batten)."""
    from freecad.elastica import commands as C, taskpanels as T
    sk, (right, left) = profile(doc)
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, sk.Name, right, 100, 18, 0)
    Gui.Selection.addSelection(doc.Name, sk.Name, left, 0, 28, 0)
    del C.MESSAGES[:]
    Gui.runCommand("Elastica_Blend")
    G.wait()
    panel = T.CURRENT[0] if T.CURRENT else None
    G.check(panel is not None, f"picked walls: the blend's panel opens {C.MESSAGES}")
    b = panel.obj
    G.check(ends_of(b) == TOPS, f"picked near their tops: blended top to top {ends_of(b)}")
    G.check(b.Mode == "length" and b.Length.Value == 151.0 and panel.warning[0].isVisible(),
            f"no free batten joins the tops: by length {b.Length} with the note")
    G.screenshot("gui_blend_picked_tops.png")
    note_follows_the_length(panel)
    panel.accept()
    G.pump()
    note_kept(doc, b)
    return sk, right, left


def note_follows_the_length(panel):
    """The note names the length the command chose ('solved for a length instead, 151 mm'):
    a length typed over it ends it once the curve is built with the new one, as in a panel
    opened later (it stayed, naming 151 mm beside a 200 mm curve); the length typed back, the
    note holds again. Screenshot gui_blend_note_typed.png."""
    b = panel.obj
    retype(panel.length, "200 mm")
    G.wait()
    said = panel.warning[1].toolTip() if panel.warning[0].isVisible() else ""
    G.screenshot("gui_blend_note_typed.png")
    G.check(b.Length.Value == 200.0 and not b.Status.startswith("error") and
            "151.00 mm" not in said and "No free batten" not in said,
            f"a length typed over the command's: its note goes ({b.Length}, {said!r})")
    retype(panel.length, "151 mm")
    G.wait()
    G.check(b.Length.Value == 151.0 and panel.warning[0].isVisible() and
            "solved for a length instead, 151.00 mm" in panel.warning[1].toolTip(),
            f"the command's length typed back: its note again ({panel.warning[1].toolTip()!r})")


def note_kept(doc, b):
    """The command's note (why by length) is kept with the feature: the panel opened again
    says it, after a save and reopen too, while Mode and Length are the command's (it lived
    only while the command's panel was open); once the designer chose tension mode, not."""
    from freecad.elastica import taskpanels as T

    def reopened_note():
        Gui.ActiveDocument.setEdit(b.Name)
        G.wait()
        panel = T.CURRENT[0]
        return panel, (panel.warning[1].toolTip() if panel.warning[0].isVisible() else "")

    panel, said = reopened_note()
    G.check("No free batten (tension 0) joins these ends: solved for a length instead, 151.00 mm"
            in said, f"the note said again in a panel opened later: {said!r}")
    G.screenshot("gui_blend_note_kept.png")
    panel.reject()
    G.pump()
    path = os.path.join(G.OUT, "gui_note_kept.FCStd")
    doc.saveCopy(path)                                  # this document stays as it is
    name = b.Name
    doc2 = App.openDocument(path)
    Gui.SendMsgToActiveView("ViewFit")
    b2 = doc2.getObject(name)
    Gui.ActiveDocument.setEdit(b2.Name)
    G.wait()
    panel = T.CURRENT[0]
    said = panel.warning[1].toolTip() if panel.warning[0].isVisible() else ""
    G.check("solved for a length instead, 151.00 mm" in said, f"and after reopening: {said!r}")
    panel.mode.setCurrentIndex(1)                     # a tension: the designer's choice now
    G.wait()
    G.check(b2.Mode == "tension" and not panel.warning[0].isVisible(),
            f"tension mode: no note ({b2.Mode})")
    panel.accept()
    G.pump()
    Gui.ActiveDocument.setEdit(b2.Name)
    G.wait()
    panel = T.CURRENT[0]
    G.check(not panel.warning[0].isVisible(), f"nor later: {panel.warning[1].toolTip()!r}")
    panel.reject()
    G.pump()
    App.closeDocument(doc2.Name)
    G.pump()
    G.check(Gui.ActiveDocument.Document is doc, "back in the profile's document")


def ends_toggled(doc, sk, right, left):
    """A scripted selection (no click): the bottoms, the free batten; the AtEnd boxes
    toggled to the tops, where none exists: by length, said; switching back to the free
    batten's ends: the free batten again."""
    from freecad.elastica import taskpanels as T
    panel = G.open_panel(doc, "Elastica_Blend", [(sk, right), (sk, left)], "Scripted blend")
    b = panel.obj
    G.check(ends_of(b) == BOTTOMS and b.Mode == "tension" and b.Tension == 0.0,
            f"a selection without clicks: the nearest ends, the free batten {ends_of(b)}")
    panel.end1.click()
    G.wait()
    panel.end2.click()
    G.wait()
    said = panel.warning[1].toolTip()
    G.check(ends_of(b) == TOPS and b.Mode == "length" and b.Length.Value == 151.0
            and not b.Status.startswith("error") and panel.mode.currentIndex() == 0
            and panel.length.isEnabled() and panel.length.text() == "151.00 mm",
            f"ends no free batten joins: by length {b.Length}, box {panel.length.text()!r} "
            f"({b.Status})")
    G.check(panel.warning[0].isVisible() and "No free batten" in said and "151.00 mm" in said,
            f"ends no free batten joins: the panel says why by length ({said})")
    # the amber line short in the 260 px Combo View (seven lines before, /tmp/revT/
    # gui_blend_no_free_batten_crop.png: review revT; two now, the icon beside it), the note
    # in full its tooltip and the Details' head
    line, fm = panel.warning[1], panel.warning[1].fontMetrics()
    G.check(line.heightForWidth(line.width()) < 3 * fm.height() and
            line.text().startswith("No free batten") and panel.details.text().startswith(said),
            f"ends no free batten joins: the warning two lines at most ({line.text()!r}, "
            f"{line.heightForWidth(line.width())} px high)")
    note_said_again(panel)
    G.screenshot("gui_blend_ends_by_length.png")
    panel.end1.click()
    G.wait()
    panel.end2.click()
    G.wait()
    G.check(ends_of(b) == BOTTOMS and b.Mode == "tension" and b.Tension == 0.0 and
            panel.mode.currentIndex() == 1 and panel.tension.text() == "0.00 1/mm\u00b2" and
            not panel.warning[0].isVisible() and not b.Status.startswith("error"),
            f"back to ends the free batten joins: the free batten again ({b.Mode}, "
            f"{panel.tension.text()!r}, {b.Status})")
    # a length of the user's stays when the ends change
    panel.mode.setCurrentIndex(0)
    G.wait()
    retype(panel.length, "250")
    key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    panel.end1.click()
    G.wait()
    G.check(b.Mode == "length" and b.Length.Value == 250.0,
            f"a typed length stays when the ends change ({b.Mode}, {b.Length})")
    panel.reject()
    G.pump()
    # the feature made at the tops by tension 0 (a script): its error; 'a length' fills one
    doc.openTransaction("script")
    from freecad.elastica import blend as Bl
    b = Bl.make(doc, (sk, right), (sk, left), at_end1=None, at_end2=None)
    b.AtEnd1, b.AtEnd2 = not b.AtEnd1, not b.AtEnd2
    doc.commitTransaction()
    doc.recompute()
    G.check(b.Status.startswith("error"), f"tension 0 at the tops: an error ({b.Status})")
    Gui.ActiveDocument.setEdit(b.Name)
    G.wait()
    panel = T.CURRENT[0]
    panel.mode.setCurrentIndex(0)
    G.wait()
    G.check(b.Mode == "length" and b.Length.Value == 151.0 and panel.length.text() == "151.00 mm"
            and not b.Status.startswith("error") and "No free batten" in panel.warning[1].toolTip(),
            f"'a length' without one: the command's length, said ({b.Length}, {b.Status})")
    panel.accept()
    G.pump()
    return b


def bound_tension(doc, b):
    """Tension bound to a spreadsheet cell: read-only, marked, kept."""
    from freecad.elastica import taskpanels as T
    ss = doc.addObject("Spreadsheet::Sheet", "Spreadsheet")
    ss.set("A1", "0.001")
    ss.setAlias("A1", "sigma")
    doc.recompute()
    b.Mode = "tension"
    b.setExpression("Tension", "Spreadsheet.sigma")
    doc.recompute()
    Gui.ActiveDocument.setEdit(b.Name)
    G.wait()
    panel = T.CURRENT[0]
    box = panel.tension
    G.check(box.isReadOnly() and "Spreadsheet.sigma" in box.toolTip() and
            len(box.lineEdit().actions()) == 1,
            f"a bound tension: read-only, marked, its expression in the tooltip "
            f"({box.isReadOnly()}, {box.toolTip()[:60]!r})")
    retype(box, "0.003")
    key(box.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    G.check(box.text() == "0.0010 1/mm\u00b2" and b.Tension == 0.001,
            f"typing in a bound box changes nothing ({box.text()!r}, {b.Tension})")
    Gui.SendMsgToActiveView("ViewTop")
    G.screenshot("gui_blend_bound.png")
    panel.accept()
    G.pump()
    G.check(b.Tension == 0.001 and dict(b.ExpressionEngine).get("Tension") == "Spreadsheet.sigma",
            "OK keeps the expression")
    b.setExpression("Tension", None)
    doc.recompute()


def unit_schemas(doc, b):
    """US customary, Imperial decimal and Building Euro: lengths in inches (and thou, FreeCAD's
    marks '"' and 'thou' under US customary) and centimetres; typed '7 in' stays as typed
    and sets 177.8 mm; leaving a box without typing changes nothing."""
    from freecad.elastica import taskpanels as T
    prefs = App.ParamGet("User parameter:BaseApp/Preferences/Units")
    old = prefs.GetInt("UserSchema", 0)
    b.Mode, b.Length = "length", 151.0
    doc.recompute()
    try:
        said_in_the_schema_of_now(doc, b, prefs)
        said_after_undo(doc, b, prefs)
        # the Tolerance's 0.001 mm as FreeCAD's boxes write numbers at 2 decimals, fixed, to 2 digits
        # ('3.93701e-05 in' before; a Gui::QuantitySpinBox shows '0.00 in'), 151 mm as its
        # '5.94 in' (it showed '5.94488 in')
        for schema, length, tol in ((2, '5.94 "', "0.039 thou"),   # US customary: FreeCAD's marks
                                    (3, "5.94 in", "0.000039 in"),
                                    (4, "15.10 cm", "0.00010 cm"),
                                    (5, '6"', "0.000039 in")):
            prefs.SetInt("UserSchema", schema)
            App.Units.setSchema(schema)
            Gui.ActiveDocument.setEdit(b.Name)
            G.wait()
            panel = T.CURRENT[0]
            G.check(panel.length.text() == length and panel.tol.text() == tol,
                    f"schema {schema}: Length {panel.length.text()!r}, Tolerance "
                    f"{panel.tol.text()!r}")
            panel.length.setFocus()
            G.pump()
            key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)     # leaves it as shown
            G.wait()
            G.check(b.Length.Value == 151.0 and panel.length.text() == length,
                    f"schema {schema}: leaving the box keeps 151 mm ({b.Length.Value!r})")
            if schema == 3:
                panel.length.setFocus()
                panel.length.lineEdit().selectAll()
                key(panel.length.lineEdit(), QtCore.Qt.Key_Delete)
                G.wait()
                G.check(b.Length.Value == 151.0 and not b.Status.startswith("error"),
                        f"an emptied box sets nothing (FreeCAD reads '' as 2.2e-308): "
                        f"{b.Length.Value!r}")
                retype(panel.length, "7 in")
                typed = panel.length.text()
                G.wait()
                G.check(typed == "7 in" and abs(b.Length.Value - 177.8) < 1e-9,
                        f"typed '7 in': shows {typed!r}, Length {b.Length}")
                key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)
                G.wait()
                G.check(panel.length.text() == "7.00 in" and abs(b.Length.Value - 177.8) < 1e-9,
                        f"after Tab: {panel.length.text()!r}")
                imperial_texts_and_steps(b, panel)
                Gui.SendMsgToActiveView("ViewTop")
                G.screenshot("gui_blend_imperial.png")
                failed_quietly(b, panel)
                G.screenshot("gui_blend_failed.png")
            if schema == 4:
                before = b.Length.Value
                panel.length.setFocus()
                key(panel.length.lineEdit(), QtCore.Qt.Key_Up)
                G.wait()
                G.check(abs(b.Length.Value - before - 10.0) < 1e-9,
                        f"Building Euro: Up steps 1 cm as FreeCAD's Quantity boxes "
                        f"({before} -> {b.Length.Value})")
            if schema == 5:
                building_us_feet_inches(b, panel)
            panel.reject()
            G.pump()
    finally:
        prefs.SetInt("UserSchema", old)
        App.Units.setSchema(old)


def building_us_feet_inches(b, panel):
    """Building US: the Length box in feet and inches as FreeCAD 0.20's own Quantity boxes
    and property editor write it (measured: 300 mm '11+3/4"', Up '1\' 3/4"'; 151 mm '6"');
    it showed decimal inches ('5.94488 in'). Leaving it keeps 151 mm (the text is to 1/8
    in), Up steps 1 in, a typed '1\' 3/4"' is read, a plain '12' is 12 in, as there."""
    G.check(App.Units.Quantity(151.0, App.Units.Length).UserString == '6"',
            "FreeCAD writes 151 mm as 6\" under Building US")
    panel.length.setFocus()
    G.pump()
    key(panel.length.lineEdit(), QtCore.Qt.Key_Up)
    G.wait()
    want = App.Units.Quantity(176.4, App.Units.Length).UserString
    G.check(abs(b.Length.Value - 176.4) < 1e-9 and panel.length.text() == want,
            f"Building US: Up steps 1 in ({b.Length}), shows {panel.length.text()!r} "
            f"(FreeCAD: {want!r})")
    retype(panel.length, "1' 3/4\"")
    G.wait()
    G.check(abs(b.Length.Value - 323.85) < 1e-9, f"typed 1' 3/4\": Length {b.Length}")
    key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    retype(panel.length, "12")
    G.wait()
    G.check(abs(b.Length.Value - 304.8) < 1e-9, f"a plain '12' is 12 in: Length {b.Length}")
    key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    G.check(panel.length.text() == App.Units.Quantity(304.8, App.Units.Length).UserString,
            f"after Tab, as FreeCAD writes 12 in: {panel.length.text()!r}")
    G.screenshot("gui_blend_building_us.png")


def typed_after_a_step(doc, b):
    """A number typed after the arrows changed the unit a box shows is in the unit shown
    now, as FreeCAD 0.20's Gui::QuantitySpinBox reads it (measured: '12' after Up took
    '9999.00 mm' to '10.00 m' is 12000 mm): the Length box read it in the unit shown when
    it got focus (12 mm), the Tolerance box too (Down from '1 \u00b5m' to '100 nm', '200'
    was 200 \u00b5m)."""
    from freecad.elastica import taskpanels as T
    b.Mode, b.Length, b.Tolerance = "length", 9999.0, 0.001
    doc.recompute()
    Gui.ActiveDocument.setEdit(b.Name)
    G.wait()
    panel = T.CURRENT[0]
    try:
        panel.length.setFocus()
        G.pump()
        key(panel.length.lineEdit(), QtCore.Qt.Key_Up)
        G.wait()
        shown = panel.length.text()
        G.check(shown == "10.00 m" and b.Length.Value == 10000.0,
                f"Up from 9999 mm: {shown!r}, Length {b.Length}")
        panel.length.lineEdit().selectAll()
        key(panel.length.lineEdit(), QtCore.Qt.Key_Delete)
        keys(panel.length.lineEdit(), "12")
        G.wait()
        G.check(b.Length.Value == 12000.0, f"'12' over '10 m' is 12 m: Length {b.Length}")
        key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)      # '12' read in m stays shown
        G.wait()
        retype(panel.length, "20")
        G.wait()
        G.check(b.Length.Value == 20000.0, f"'20' over that '12' is 20 m: Length {b.Length}")
        panel.tol.setFocus()
        G.pump()
        key(panel.tol.lineEdit(), QtCore.Qt.Key_Down)
        G.wait()
        shown = panel.tol.text()
        panel.tol.lineEdit().selectAll()
        key(panel.tol.lineEdit(), QtCore.Qt.Key_Delete)
        keys(panel.tol.lineEdit(), "200")
        G.wait()
        G.check(shown == "100.00 nm" and abs(b.Tolerance.Value - 2e-4) < 1e-15,
                f"'200' over {shown!r} is 200 nm: Tolerance {b.Tolerance}")
        G.screenshot("gui_blend_typed_after_step.png")
    finally:
        panel.reject()
        G.pump()


def said_in_the_schema_of_now(doc, b, prefs):
    """A G2 blend recomputed under Standard, its panel opened under Imperial decimal: the
    Status lines (length, tension, energy, curvature, guide forces) in inches without a
    recompute (they kept mm until the next edit)."""
    from freecad.elastica import taskpanels as T
    prefs.SetInt("UserSchema", 0)
    App.Units.setSchema(0)
    b.Continuity = "G2"
    doc.recompute()
    before = b.Status
    prefs.SetInt("UserSchema", 3)
    App.Units.setSchema(3)
    Gui.ActiveDocument.setEdit(b.Name)
    G.wait()
    panel = T.CURRENT[0]
    text = panel.details.text()         # the Status in full (the result line says one line)
    G.check(before.startswith("G2") and " mm" in before and b.Status == before
            and "mm" not in text and " in, tension " in text and "/in" in text,
            f"a panel opened after a schema change says the Status in inches: {text!r}")
    G.screenshot("gui_blend_said_again.png")
    panel.reject()
    G.pump()
    prefs.SetInt("UserSchema", 0)
    App.Units.setSchema(0)
    b.Continuity = "G1"
    doc.recompute()


def said_after_undo(doc, b, prefs):
    """Edit > Undo of a panel's edit under Imperial decimal, the blend recomputed under
    Standard before it: the panel opened next says the Status of the state undone to in
    inches, as a recompute writes it (it said the stored 'length ... mm')."""
    from freecad.elastica import taskpanels as T
    prefs.SetInt("UserSchema", 0)
    App.Units.setSchema(0)
    b.Continuity, b.Mode, b.Length = "G2", "length", 151.0
    doc.recompute()
    doc.commitTransaction()
    stored = b.Status
    prefs.SetInt("UserSchema", 3)
    App.Units.setSchema(3)
    try:
        Gui.ActiveDocument.setEdit(b.Name)
        G.wait()
        panel = T.CURRENT[0]
        retype(panel.length, "7 in")
        G.wait()
        panel.accept()
        G.pump()
        Gui.runCommand("Std_Undo")
        G.wait()
        Gui.ActiveDocument.setEdit(b.Name)
        G.wait()
        panel = T.CURRENT[0]
        text = panel.details.text()     # the Status in full (the result line: one line)
        G.screenshot("gui_blend_said_after_undo.png")
        panel.reject()
        G.pump()
        b.touch()
        doc.recompute()
        G.check(b.Length.Value == 151.0 and " mm" in stored and "mm" not in text
                and b.Status.replace("; ", "<br>") in text, f"after Undo the panel says {text!r} (a recompute: "
                f"{b.Status!r}; stored {stored!r})")
    finally:
        prefs.SetInt("UserSchema", 0)
        App.Units.setSchema(0)
        b.Continuity = "G1"
        doc.recompute()


def note_said_again(panel):
    """The panel's note (why by length) follows a schema change without a recompute: in
    inches from the exact lengths under Imperial decimal (it kept '151 mm')."""
    before, old = panel.obj.Status, App.Units.getSchema()
    App.Units.setSchema(3)
    try:
        panel.refresh()
        said = panel.warning[1].toolTip()
        G.check("instead, 5.94 in (1.5 \u00d7 the 3.96 in between" in said and "mm" not in said
                and panel.obj.Status == before, f"the note said again in inches: {said!r}")
    finally:
        App.Units.setSchema(old)
        panel.refresh()


def comb_in_the_schema(doc, b):
    """A comb's panel opened under Imperial decimal: its scale line in in\u00b2 (it said
    mm\u00b2); its Scale box, 0, says 'automatic' (it said '0 in\u00b2' over the scale used,
    QA24gui F6)."""
    from freecad.elastica import comb as Cm, taskpanels as T
    comb = Cm.make(doc, b)
    doc.recompute()
    with G.user_schema(3):
        Gui.ActiveDocument.setEdit(comb.Name)
        G.wait()
        panel = T.CURRENT[0]
        text, box = panel.result.text(), panel.scale.text()
        want = f"scale {number_text(comb.UsedScale / 25.4 ** 2)} in\u00b2; ok"
        G.check(text == want and box == "automatic", f"comb under Imperial: {text!r} "
                f"(want {want!r}), Scale box {box!r}")
        G.screenshot("gui_comb_imperial.png")
        panel.reject()
        G.pump()
    doc.removeObject(comb.Name)


def imperial_texts_and_steps(b, panel):
    """Imperial decimal (QA12): the Tension box, the solutions and the result line in
    inches (they said mm and 1/mm\u00b2); a plain '6' is 6 in and the arrows step 1 in, as
    FreeCAD 0.20's own Quantity boxes under that schema (a Gui::QuantitySpinBox measured
    there: '6' over '5.94 in' gave 152.4 mm, Up from it +25.4 mm; here '6' was 6 mm and Up
    +1 mm)."""
    tension = panel.tension.text()
    G.check(tension.endswith(" 1/in\u00b2") and
            tension == f"{number_text(panel.tension.value() * 25.4 ** 2)} 1/in\u00b2"
            and "e" not in tension,
            f"the Tension box in 1/in\u00b2: {tension!r} ({panel.tension.value()} 1/mm\u00b2)")
    tips = (panel.length.toolTip(), panel.tension.toolTip(), panel.tol.toolTip())
    G.check("(in)" in tips[0] and "(1/in\u00b2)" in tips[1] and "(in)" in tips[2]
            and not any("mm" in t for t in tips),
            f"the boxes' tooltips name the units they show: {[t[:40] for t in tips]}")
    rows = [panel.list.item(i).text().replace("\u00a0", " ").replace("\u2060", "")
            for i in range(panel.list.count())]           # units.unbroken's, as read
    G.check(rows and all(" in, " in r and "/in" in r and "mm" not in r for r in rows),
            f"the solutions in inches: {rows[:2]}")
    G.check("mm" not in panel.result.text(), f"the result line: {panel.result.text()!r}")
    retype(panel.length, "6")
    G.wait()
    G.check(abs(b.Length.Value - 152.4) < 1e-9,
            f"a plain '6' over inches is 6 in: Length {b.Length}")
    key(panel.length.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    panel.length.setFocus()
    key(panel.length.lineEdit(), QtCore.Qt.Key_Up)
    G.wait()
    G.check(abs(b.Length.Value - 177.8) < 1e-9 and panel.length.text() == "7.00 in",
            f"Up steps 1 in: Length {b.Length}, box {panel.length.text()!r}")
    key(panel.length.lineEdit(), QtCore.Qt.Key_Down)
    key(panel.length.lineEdit(), QtCore.Qt.Key_Down)
    G.wait()
    G.check(abs(b.Length.Value - 127.0) < 1e-9, f"Down twice: 5 in ({b.Length})")


def failed_quietly(b, panel):
    """A failed recompute says its message in the report view as FreeCAD's own features
    do, without the Python traceback that followed it (QA12 gui/g2_4_schema3.png), and
    the feature is still marked in error (the tree's mark), its last shape kept. The
    panel's live preview says it on the panel's error line only (QA18gui F6: the report
    view popped up with it at every prefix typed); OK says it in the report view once."""
    shape = b.Shape.copy()
    before = G.report_text()
    retype(panel.length, "1 in")              # shorter than the ends are apart
    G.wait()
    after = G.report_text()
    said = after[len(before):] if G.report_view() is not None else None
    G.check(b.Status.startswith("error") and "Invalid" in b.State and not b.isValid()
            and abs(b.Shape.Length - shape.Length) < 1e-9,
            f"a failed recompute marks the feature (State {b.State}, {b.Status[:60]!r})")
    G.check(said == "" and "is not longer than" in G.error_line(panel),
            f"the preview says it on the panel's error line only: {said!r}")
    # OK on the feature in error keeps the panel open and says it in the report view once,
    # the message alone
    stays = not panel.accept()
    G.wait()
    again = G.report_text()
    more = again[len(after):] if G.report_view() is not None else None
    G.check(stays and more is not None and more.count("is not longer than") == 1
            and "Traceback" not in more and "RecomputeError" not in more,
            f"OK on a feature in error says the message alone, once: {more!r}")
    # a document's recompute (its edges moved, Recompute): the message alone too
    b.touch()
    b.Document.recompute()
    G.wait()
    last = G.report_text()[len(again):]
    G.check(last.count("is not longer than") == 1 and "Traceback" not in last
            and "RecomputeError" not in last,
            f"the report view says the message alone, once for one recompute: {last!r}")


def tension_mode_and_g2_reach(doc, sk, right, left):
    """QA12: 'a tension' after a blend by length kept the length mode's tension (it reset
    Tension to 0, which the panel had just said no batten joins these ends at); a G2 blend
    pulled beyond its reach names a tension that solves (it said 0.00177 to 3 digits, and
    0.00176823 failed as "no G2 blend at tension 0.00177")."""
    from freecad.elastica import taskpanels as T
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, sk.Name, right, 100, 18, 0)
    Gui.Selection.addSelection(doc.Name, sk.Name, left, 0, 28, 0)
    Gui.runCommand("Elastica_Blend")
    G.wait()
    panel = T.CURRENT[0]
    b = panel.obj
    sigma, length = b.BlendTension, b.BlendLength
    panel.mode.setCurrentIndex(1)
    G.wait()
    G.check(b.Mode == "tension" and sigma != 0.0 and b.Tension == sigma and
            not b.Status.startswith("error") and abs(b.BlendLength - length) < 1e-6 and
            panel.tension.text() != "0.00 1/mm\u00b2",
            f"'a tension' keeps the length mode's tension {sigma} ({b.Tension}, "
            f"{panel.tension.text()!r}, {b.Status})")
    G.screenshot("gui_blend_tension_kept.png")
    panel.continuity.setCurrentIndex(1)
    G.wait()
    retype(panel.tension, "0.003")
    key(panel.tension.lineEdit(), QtCore.Qt.Key_Tab)
    G.wait()
    import re
    found = re.search("the solver reached battens of tension up to ([0-9.e-]+) 1/mm", b.Status)
    G.check(b.Status.startswith("error: no G2 blend at tension 0.0030 1/mm") and found,
            f"G2 beyond its reach: the largest tension found said ({b.Status})")
    Gui.SendMsgToActiveView("ViewTop")
    G.screenshot("gui_blend_g2_reach.png")
    if found:
        retype(panel.tension, found.group(1))
        key(panel.tension.lineEdit(), QtCore.Qt.Key_Tab)
        G.wait()
        G.check(b.Tension == float(found.group(1)) and b.Status.startswith("G2 from"),
                f"the tension said, typed: a G2 blend ({b.Tension}, {b.Status})")
        G.screenshot("gui_blend_g2_reach_typed.png")
    panel.reject()
    G.pump()


def bound_length_toggled(doc, sk, right, left):
    """QA12: Length bound to a spreadsheet, the free batten (tension 0) asked and the ends
    toggled to ones no free batten joins: length mode at the bound length (the binding
    stays), said on the warning line; it stayed at tension 0 with the bare error."""
    from freecad.elastica import taskpanels as T
    ss = doc.addObject("Spreadsheet::Sheet", "LenSheet")
    ss.set("A1", "=160 mm")
    ss.setAlias("A1", "len")
    doc.recompute()
    panel = G.open_panel(doc, "Elastica_Blend", [(sk, right), (sk, left)], "Bound length")
    b = panel.obj
    panel.accept()
    G.pump()
    b.setExpression("Length", "LenSheet.len")
    doc.recompute()
    G.check(b.Mode == "tension" and b.Tension == 0.0 and ends_of(b) == BOTTOMS,
            f"the free batten at the bottoms, Length bound ({b.Mode}, {ends_of(b)})")
    Gui.ActiveDocument.setEdit(b.Name)
    G.wait()
    panel = T.CURRENT[0]
    panel.end1.click()
    G.wait()
    panel.end2.click()
    G.wait()
    said = panel.warning[1].toolTip()
    G.check(ends_of(b) == TOPS and b.Mode == "length" and b.Length.Value == 160.0 and
            panel.mode.currentIndex() == 0 and not b.Status.startswith("error") and
            dict(b.ExpressionEngine).get("Length") == "LenSheet.len",
            f"bound Length, ends no free batten joins: by the bound length ({b.Mode}, "
            f"{b.Length}, {b.ExpressionEngine}, {b.Status})")
    G.check(panel.warning[0].isVisible() and "No free batten" in said and "LenSheet.len" in said
            and "160.00 mm" in said, f"bound Length: the panel says why by length ({said})")
    Gui.SendMsgToActiveView("ViewTop")
    G.screenshot("gui_blend_bound_length_toggled.png")
    panel.accept()
    G.pump()
    G.check(b.Mode == "length" and dict(b.ExpressionEngine).get("Length") == "LenSheet.len",
            f"OK keeps the binding ({b.Mode}, {b.ExpressionEngine})")


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaBlendPanel")
    sk, right, left = picked_ends(doc)
    b = ends_toggled(doc, sk, right, left)
    bound_tension(doc, b)
    unit_schemas(doc, b)
    typed_after_a_step(doc, b)
    comb_in_the_schema(doc, b)
    tension_mode_and_g2_reach(doc, sk, right, left)
    bound_length_toggled(doc, sk, right, left)
    App.closeDocument(doc.Name)
