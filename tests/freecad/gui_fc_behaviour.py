"""The Elastica commands and panels next to FreeCAD's own, checked by the GUI smoke test
(gui_smoke.py calls run_all); QA18gui's findings:

- F6: a number typed at a person's pace (250 ms a key) is solved once, not at every
  prefix ('1', '15', '150'), and a value that cannot be solved is said on the panel's
  error line only: no red report-view lines and 'Recompute failed!' (which popped the
  report view up) while typing; OK says it in the report view, the panel stays open;
- F7: with nothing selected the commands are greyed out (Part_Offset2D), the blend until
  two edges are (Part_Section, Part_Fuse); a selection a command cannot use opens
  FreeCAD's modal 'Wrong selection' box (Part_RuledSurface), no report-view line;
- F8: the Fit panel's Model box shows its item whole ('Discrete elastica (' was cut), the
  full name in the item's tooltip, the preference page the same names;
- F4: the source sketch double-clicked while a panel is open opens the Sketcher (the
  panel closes, its edits kept), as over PartDesign Pad's panel: it needed a second
  double-click.

Screenshots: gui_typing_error_line.png (a typed length too short: the error line),
gui_fit_model_names.png (the Model box), gui_sketch_over_panel.png (the Sketcher open)."""

import time
from contextlib import contextmanager

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)
KEY_GAP_MS = 250    # a person's pace


def slow_type(box, text):
    """Type ``text`` into a spin box a key every KEY_GAP_MS, as a person does (the event
    loop running between keys; G.wait would wait for the panel's pending recompute)."""
    box.setFocus()
    box.selectAll()
    for ch in text:
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtGui.QApplication.sendEvent(box, QtGui.QKeyEvent(kind, 0, QtCore.Qt.NoModifier, ch))
        end = time.time() + KEY_GAP_MS / 1000.0
        while time.time() < end:
            QtGui.QApplication.processEvents()
            time.sleep(0.01)


@contextmanager
def counting_solves(obj):
    """The feature's solves (its proxy's compute, which its execute calls: FreeCAD keeps
    the execute it found when the proxy was set) counted in the list given."""
    proxy = obj.Proxy
    compute = proxy.compute

    def counted(o):
        solves.append(o.Name)
        return compute(o)
    solves = []
    proxy.compute = counted
    try:
        yield solves
    finally:
        del proxy.compute


def typing_pace():
    from freecad.elastica import taskpanels as T
    doc = S.new_doc("ElasticaTyping")
    sk = S.two_lines_sketch(doc)
    panel = G.open_panel(doc, "Elastica_Blend", [(sk, "Edge1"), (sk, "Edge2")], "Typing")
    b = panel.obj
    panel.mode.setCurrentIndex(0)           # a length
    G.wait()
    r0 = len(G.report_text())
    with counting_solves(b) as solves:
        slow_type(panel.length, "150")
        G.wait()              # a pause: the value stands
    said = G.report_text()[r0:].strip()
    G.check(solves == [b.Name] and b.Length.Value == 150.0 and not b.Status.startswith("error")
            and not said,
            f"F6: '150' typed at {KEY_GAP_MS} ms a key: solved once ({solves}), not at every "
            f"prefix; the report view says nothing ({said!r})")
    slow_type(panel.length, "15")           # shorter than the gap between the ends
    G.wait()              # a pause: the value stands
    line = G.error_line(panel)
    said = G.report_text()[r0:].strip()
    G.screenshot("gui_typing_error_line.png")
    G.check(b.Status.startswith("error") and "15.00 mm" in line and not said,
            f"F6: a typed length that cannot be solved: on the panel's error line ({line!r}) "
            f"only, not in the report view ({said!r})")
    r1 = len(G.report_text())
    accepted = panel.accept()
    G.wait()                             # the report view takes it from an event
    said = G.report_text()[r1:].strip()
    G.check(not accepted and T.CURRENT and T.CURRENT[0] is panel and said.count("\n") == 0
            and "Elastica ElasticaBlend: length 15.00 mm" in said and "Recompute failed" not in said,
            f"F6: OK on it says it once in the report view ({said!r}); the panel stays open")
    panel.reject()
    G.pump()
    App.closeDocument(doc.Name)


ELASTICA = ("Elastica_Fit", "Elastica_Blend", "Elastica_Spline", "Elastica_EllipticBlend",
            "Elastica_G2Quad", "Elastica_Comb")


def active(names):
    return {n: Gui.Command.get(n).isActive() for n in names}


def wrong_selection():
    doc = S.new_doc("ElasticaWrongSelection")
    box = doc.addObject("Part::Box", "Box")
    sk = S.two_lines_sketch(doc)
    doc.recompute()
    G.select(doc, [])
    G.pump()
    now = active(ELASTICA + ("Elastica_FitCsv",))
    G.check(not any(now[n] for n in ELASTICA) and now["Elastica_FitCsv"],
            f"F7: nothing selected: the commands are greyed out as Part_Offset2D (the CSV fit, "
            f"which asks for its file, is not) {now}")
    G.select(doc, [(sk, "Edge1")])
    G.pump()
    one = active(["Elastica_Blend", "Elastica_G2Quad"])
    G.select(doc, [(sk, "Edge1"), (sk, "Edge2")])
    G.pump()
    two = active(["Elastica_Blend"])
    G.check(not one["Elastica_Blend"] and one["Elastica_G2Quad"] and two["Elastica_Blend"],
            f"F7: the blend is greyed out until two edges are selected, as Part_Section "
            f"(one edge: {one}, two: {two})")
    from freecad.elastica import commands as C
    polling = [True]
    found = G.answer_modal("OK", keep=lambda: polling)
    try:
        for name in ("Elastica_Fit", "Elastica_Spline", "Elastica_EllipticBlend",
                     "Elastica_G2Quad", "Elastica_Comb"):
            del found[:]
            del C.MESSAGES[:]
            G.select(doc, [(box, "Face1")])
            G.pump()
            before, r0 = S.doc_state(doc), len(G.report_text())
            Gui.runCommand(name)
            G.wait()
            said = G.report_text()[r0:].strip()
            menu = C.COMMANDS[name].menu
            G.check(len(found) == 1 and found[0][0] == "Wrong selection" and "Face1" in found[0][1]
                    and found[0][1].startswith(f"{menu}: ")
                    and f"Select {C.COMMANDS[name].needs}." in found[0][1]
                    and not said and S.doc_state(doc) == before and not Gui.Control.activeDialog(),
                    f"F7: {name} on a box's face: FreeCAD's modal 'Wrong selection' box "
                    f"naming the command and what to select (QA21gui F5) ({found}), no "
                    f"report-view line ({said!r}), the document unchanged")
    finally:
        polling.clear()
    App.closeDocument(doc.Name)


def model_names():
    from freecad.elastica import fit_core, preferences as P
    doc = S.new_doc("ElasticaModelNames")
    sk = S.points_sketch(doc, S.keyline_xy(14)[0], "Points")
    panel = G.open_panel(doc, "Elastica_Fit", [(sk, "")], "Fit for its model names")
    G.wait()
    combo = panel.model
    cut = []
    for i in range(combo.count()):
        combo.blockSignals(True)
        combo.setCurrentIndex(i)
        combo.blockSignals(False)
        G.pump()
        opt = QtGui.QStyleOptionComboBox()
        combo.initStyleOption(opt)
        field = combo.style().subControlRect(QtGui.QStyle.CC_ComboBox, opt,
                                             QtGui.QStyle.SC_ComboBoxEditField, combo)
        need = combo.fontMetrics().boundingRect(combo.itemText(i)).width()
        if need > field.width():
            cut.append((combo.itemText(i), need, field.width()))
        if i == 0:
            G.screenshot("gui_fit_model_names.png")
    combo.blockSignals(True)
    combo.setCurrentIndex(fit_core.MODELS.index(panel.obj.Model))
    combo.blockSignals(False)
    tips = [combo.itemData(i, QtCore.Qt.ToolTipRole) for i in range(combo.count())]
    page = P.PreferencePage()
    names = [page.model.itemText(i) for i in range(page.model.count())]
    G.check(not cut, f"F8: the Fit panel's Model box shows its items whole (cut: {cut})")
    G.check(tips[0] and tips[0].startswith("Discrete elastica (Bobenko-Suris)")
            and names == [combo.itemText(i) for i in range(combo.count())],
            f"F8: the full name in each item's tooltip ({tips}); the preference page names the "
            f"models as the panel ({names})")
    panel.reject()
    G.pump()
    App.closeDocument(doc.Name)


def sketch_during_panel(new):
    """The source sketch double-clicked (its view provider's setEdit) while the blend's
    panel is open, a tension typed: a new blend's (``new``) or an edit's."""
    from freecad.elastica import taskpanels as T
    doc = S.new_doc("ElasticaSketchOverPanel")
    sk = S.two_lines_sketch(doc)
    panel = G.open_panel(doc, "Elastica_Blend", [(sk, "Edge1"), (sk, "Edge2")], "Blend")
    b = panel.obj
    if not new:
        panel.accept()
        G.pump()
        panel = G.double_click(b)
    panel.mode.setCurrentIndex(1)               # a tension
    G.wait()
    G.type_into(panel.tension, "0.001")
    G.wait()
    Gui.getDocument(doc.Name).setEdit(sk.Name)
    G.wait()
    ine = Gui.getDocument(doc.Name).getInEdit()
    what = "a new blend's" if new else "an edit's"
    if not new:
        G.screenshot("gui_sketch_over_panel.png")
    G.check(ine is not None and ine.Object is sk and Gui.Control.activeDialog() and not T.CURRENT
            and abs(b.Tension - 0.001) < 1e-15,
            f"F4: the source sketch double-clicked over {what} panel opens the Sketcher (in "
            f"edit: {ine.Object.Name if ine else None}), the panel closed, its tension kept "
            f"({b.Tension})")
    Gui.getDocument(doc.Name).resetEdit()
    G.pump()
    App.closeDocument(doc.Name)


def enter_is_ok():
    """QA21gui F4: Enter in a panel's number box is OK, as in FreeCAD's own task panels (its
    task view clicks the default button): the value typed is solved and the panel closes,
    the feature kept in one undo step; the READMEs said a typed value is solved "at Enter"
    as if the panel stayed open."""
    from freecad.elastica import taskpanels as T
    doc = S.new_doc("ElasticaEnter")
    lines = S.two_lines_sketch(doc)
    doc.recompute()
    G.run_on(doc, "Elastica_Blend", [(lines, "Edge1"), (lines, "Edge2")])
    G.wait()
    panel = T.CURRENT[0]
    name = panel.obj.Name
    if panel.obj.Mode != "tension":
        panel.mode.setCurrentIndex(1)
        G.wait()
    G.type_into(panel.tension, "0.003")
    # (its press closes the panel: no box is left for the release)
    QtGui.QApplication.sendEvent(panel.tension, QtGui.QKeyEvent(
        QtCore.QEvent.KeyPress, QtCore.Qt.Key_Return, QtCore.Qt.NoModifier, "\r"))
    G.pump(20)
    b = doc.getObject(name)
    G.check(not T.CURRENT and Gui.Control.activeDialog() is False and b is not None
            and b.Tension == 0.003 and not b.Status.startswith("error")
            and doc.UndoNames[:1] == ["Elastic blend"] and not doc.HasPendingTransaction,
            f"F4: Enter in the Tension box is OK, as FreeCAD's own panels: 0.003 solved, the "
            f"panel closed, one undo step ({bool(T.CURRENT)}, {b and b.Tension}, "
            f"{doc.UndoNames[:2]})")
    App.closeDocument(doc.Name)


def run_all(smoke):
    global G
    G = smoke
    typing_pace()
    enter_is_ok()
    wrong_selection()
    model_names()
    sketch_during_panel(new=True)
    sketch_during_panel(new=False)
