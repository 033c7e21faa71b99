"""Expressions and refused texts typed in a panel's box, as in FreeCAD's own Quantity boxes
(gui_smoke.py calls run_all); QA25gui's findings:

- F2: '=' typed in a box opens FreeCAD's expression editor (Gui::Dialog::DlgExpressionInput),
  as in Part_Offset2D's Value box; its OK binds the property (the box read-only, marked,
  showing the expression's value), '=' or the mark open it again holding the expression,
  and the panel's Cancel unbinds what the panel bound. '=2*3' was read once as 6 mm (no
  expression kept) and '=Sheet.step' refused with no word of where binding is done; a
  cell's name typed as such says now how to bind it;
- F3: '1/0' typed in Resample was "above the largest, 1000 m" (it is a division by zero),
  and the live preview had taken its prefix '1' (ResampleStep 6 -> 1 mm) while the box
  showed the refused text: now the property stays at the box's last text that stood;
- QA gui F11: a refused text left in the box through the typing pause (no Tab, no Enter) had
  set the feature to the value before the last text that stood ('4 mm' typed and left, then
  'abc': Resample 0 mm, the fit redone; the blend's Length 300 typed, then '3O0': 149.8 mm,
  the command's), with no error line: now the text typed last stands at the pause, the
  feature keeps it and nothing recomputes, and the error line says why the text is refused.

And '=' in an integer box (Degree) opens the editor on its property as FreeCAD's
Gui::IntSpinBox does, bound to it with the same Cancel / OK / Undo (integer_editor).

Screenshots: gui_typed_equals_editor.png (the editor '=' opened over Resample),
gui_typed_division_by_zero.png (the Fit panel refusing '1/0'), gui_typed_bound.png (Resample
bound to Sheet.step by it: 8 mm, read-only, marked), gui_typed_integer_editor.png and
gui_typed_integer_bound.png (Degree bound to a cell), gui_typed_pause.png (the blend's Length
'3O0' left through the typing pause: 300 mm kept, the error line saying why)."""
import numpy as np

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide import QtCore, QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)


def _points():
    """A hand sketch: 16 unevenly spaced points, 0.4 mm of noise, far from the origin."""
    rng = np.random.default_rng(25)
    x = np.sort(rng.uniform(0.0, 150.0, 16))
    y = 30.0 * np.sin(x / 45.0) + rng.normal(0.0, 0.4, x.size)
    return [(1500.0 + a, -800.0 + b) for a, b in zip(x, y)]


def _key(box, text):
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(box, QtGui.QKeyEvent(kind, 0, QtCore.Qt.NoModifier, text))
    G.pump(10)


def _leave(box):
    QtGui.QApplication.sendEvent(box, QtGui.QFocusEvent(QtCore.QEvent.FocusOut,
                                                        QtCore.Qt.MouseFocusReason))
    box.clearFocus()
    G.pump(10)


def _editor(box):
    found = [d for d in box.findChildren(QtGui.QDialog)
             if d.metaObject().className() == "Gui::Dialog::DlgExpressionInput"
             and d.isVisible()]
    return found[0] if found else None


def _in_view(box):
    """The task panel scrolled to ``box`` (for a screenshot)."""
    area = box.parentWidget()
    while area is not None and not isinstance(area, QtGui.QScrollArea):
        area = area.parentWidget()
    if area is not None:
        area.ensureWidgetVisible(box)
    G.pump(10)


def _panel(fit):
    from freecad.elastica import taskpanels as T
    G.double_click(fit)
    G.wait()
    G.check(bool(T.CURRENT), "the fit's panel opens on a double click")
    return T.CURRENT[0]


def division_by_zero(doc, fit):
    """F3: '1/0' typed key by key in Resample never reaches the feature."""
    from freecad.elastica import taskpanels as T
    panel = _panel(fit)
    box = panel.step
    before = fit.ResampleStep.Value
    G.type_into(box, "1/0")
    G.wait()
    G.check(box.text() == "1/0" and fit.ResampleStep.Value == before,
            f"F3: '1/0' typed: the feature keeps Resample {before} mm, not its prefix's 1 mm "
            f"({fit.ResampleStep}, box {box.text()!r})")
    _leave(box)
    line = G.error_line(panel)
    G.check(line == "Resample: 1/0: a division by zero" and fit.ResampleStep.Value == before,
            f"F3: leaving the box, the error line says it is a division by zero ({line!r}, "
            f"{fit.ResampleStep})")
    G.screenshot("gui_typed_division_by_zero.png")
    G.check(not panel.accept() and T.CURRENT and T.CURRENT[0] is panel,
            "F3: OK refuses '1/0': the panel stays open")
    G.type_into(box, "10")
    _leave(box)
    G.wait()
    G.check(fit.ResampleStep.Value == 10.0 and G.error_line(panel) == "",
            f"F3: '10' typed over it is taken ({fit.ResampleStep}, {G.error_line(panel)!r})")
    G.type_into(box, "10 mm/0")
    G.wait()
    G.check(fit.ResampleStep.Value == 10.0,
            f"F3: '10 mm/0' typed after it: the feature keeps the 10 mm that stood "
            f"({fit.ResampleStep})")
    G.type_into(box, "0/0")
    _leave(box)
    G.check(G.error_line(panel) == "Resample: 0/0: a division by zero"
            and fit.ResampleStep.Value == 10.0,
            f"F3: '0/0' too ({G.error_line(panel)!r}, {fit.ResampleStep})")
    G.type_into(box, "8 x")
    G.wait()
    G.check(fit.ResampleStep.Value == 10.0, f"F3: '8 x' held back ({fit.ResampleStep})")
    for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
        QtGui.QApplication.sendEvent(box, QtGui.QKeyEvent(kind, QtCore.Qt.Key_Backspace,
                                                          QtCore.Qt.NoModifier))
    G.wait()
    G.check(box.text() == "8 " and fit.ResampleStep.Value == 8.0,
            f"F3: its x taken back, '8 ' sets 8 mm (Qt's value was 8 already: it said "
            f"nothing) ({box.text()!r}, {fit.ResampleStep})")
    panel.reject()
    G.wait()
    G.check(not T.CURRENT and fit.ResampleStep.Value == before,
            f"F3: Cancel restores Resample {before} mm ({fit.ResampleStep})")


class _Recomputes:
    """A document observer counting the recomputes of one feature (the panel's preview)."""

    def __init__(self, obj):
        self.name, self.count = obj.Name, 0

    def slotRecomputedObject(self, obj):
        if obj.Name == self.name:
            self.count += 1


def _paused_checks(panel, box, prop, label, stood, texts):
    """Each refused text typed over ``stood`` and left through the typing pause: the feature
    keeps ``stood``, nothing recomputes, the error line says why (as on Tab)."""
    obj = panel.obj
    watch = _Recomputes(obj)
    App.addDocumentObserver(watch)
    try:
        for text in texts:
            G.type_into(box, text)
            G.wait()                   # the typing pause passes: no Tab, no Enter
            line = G.error_line(panel)
            value = getattr(obj, prop).Value
            G.check(box.text() == text and value == stood and watch.count == 0
                    and line.startswith(f"{label}: {text}") and "Touched" not in obj.State,
                    f"F11: {text!r} left in {label} through the typing pause: the feature keeps "
                    f"the {stood} mm typed last, no recompute, not left touched (OK solved it "
                    f"again), the error line says why "
                    f"({value}, {watch.count} recomputes, {obj.State}, {line!r})")
    finally:
        App.removeDocumentObserver(watch)


def typing_pause(doc, fit):
    """F11: a text typed and left through the typing pause stands; a refused one left after
    it keeps it (the Fit's Resample, the blend's Length)."""
    from freecad.elastica import taskpanels as T
    panel = _panel(fit)
    box = panel.step
    G.type_into(box, "4 mm")
    G.wait()
    G.check(fit.ResampleStep.Value == 4.0 and G.error_line(panel) == "",
            f"F11: '4 mm' typed and left through the typing pause is taken ({fit.ResampleStep})")
    _paused_checks(panel, box, "ResampleStep", "Resample", 4.0,
                   ("abc", "5 kg", "-2", "1/0", "3O0"))
    G.type_into(box, "2 cm")
    G.wait()
    G.check(fit.ResampleStep.Value == 20.0 and G.error_line(panel) == "",
            f"F11: '2 cm' typed over it is taken, the error line cleared ({fit.ResampleStep}, "
            f"{G.error_line(panel)!r})")
    panel.reject()
    G.wait()
    lk = doc.addObject("Sketcher::SketchObject", "PauseProfile")
    lk.addGeometry(Part.LineSegment(App.Vector(1500, -900, 0), App.Vector(1620, -900, 0)), False)
    lk.addGeometry(Part.LineSegment(App.Vector(1760, -850, 0), App.Vector(1860, -820, 0)), False)
    doc.recompute()
    G.open_panel(doc, "Elastica_Blend", [(lk, "Edge1"), (lk, "Edge2")], "a blend of two lines")
    panel = T.CURRENT[0]
    panel.mode.setCurrentIndex(0)       # Solve for a length
    G.wait()
    G.type_into(panel.length, "300")
    G.wait()
    b = panel.obj
    G.check(b.Mode == "length" and b.Length.Value == 300.0,
            f"F11: the blend's Length '300' typed and left stands ({b.Mode}, {b.Length})")
    _paused_checks(panel, panel.length, "Length", "Length", 300.0, ("3O0", "abc", "5 kg", "-3"))
    G.type_into(panel.length, "3O0")
    G.wait()
    G.screenshot("gui_typed_pause.png")
    G.check(not panel.accept() and T.CURRENT and b.Length.Value == 300.0,
            f"F11: OK refuses '3O0', the panel stays open, Length 300 mm ({b.Length})")
    name = b.Name
    panel.reject()
    G.wait()
    G.check(not T.CURRENT and doc.getObject(name) is None,
            "F11: Cancel closes the blend's panel, the new blend removed")
    doc.removeObject(lk.Name)
    doc.recompute()


def equals_opens_the_editor(doc, fit):
    """F2: '=' in Resample opens FreeCAD's expression editor; its OK binds the property."""
    from freecad.elastica import taskpanels as T
    sheet = doc.addObject("Spreadsheet::Sheet", "Sheet")
    sheet.set("A1", "8 mm")
    sheet.setAlias("A1", "step")
    doc.recompute()
    before = fit.ResampleStep.Value
    panel = _panel(fit)
    box = panel.step
    G.type_into(box, "Sheet.step")
    _leave(box)
    line = G.error_line(panel)
    G.check(line.startswith("Resample: Sheet.step: not a number or quantity")
            and "to bind the field to an expression, type = in it" in line,
            f"F2: a cell's alias typed as a value says how to bind it ({line!r})")
    box.setFocus()
    box.selectAll()
    text = box.text()
    _key(box, "=")
    editor = _editor(box)
    G.check(editor is not None and box.text() == text,
            f"F2: '=' in the Resample box opens FreeCAD's expression editor, '=' not typed "
            f"({box.text()!r})")
    line = editor.findChild(QtGui.QLineEdit, "expression")
    G.check(line is not None and line.text().startswith("6") and line.text().endswith(" mm")
            and float(line.text()[:-3]) == 6.0,
            f"F2: the editor opens on an unbound field holding its value, as FreeCAD's "
            f"({line.text() if line else None!r})")
    line.setText("Sheet.step")
    G.pump(10)
    G.screenshot("gui_typed_equals_editor.png")
    said = editor.findChild(QtGui.QLabel, "msg")
    G.check(said is not None and said.text().startswith("8")
            and "discarded" not in said.text(),
            f"F2: the editor reads the cell as a length ({said.text() if said else None!r})")
    editor.findChild(QtGui.QPushButton, "okBtn").click()
    G.wait()
    G.check(dict(fit.ExpressionEngine).get("ResampleStep") == "Sheet.step"
            and fit.ResampleStep.Value == 8.0 and box.text() == "8.00 mm" and box.isReadOnly()
            and len(box.lineEdit().actions()) == 1 and "Sheet.step" in box.toolTip()
            and G.error_line(panel) == "",
            f"F2: its OK binds ResampleStep to Sheet.step: the box read-only, marked, showing "
            f"8 mm ({box.text()!r}, {fit.ResampleStep}, {dict(fit.ExpressionEngine)}, "
            f"{G.error_line(panel)!r})")
    G.screenshot("gui_typed_bound.png")
    G.check(not fit.Status.startswith("error"),
            f"F2: the preview solved with the bound 8 mm ({fit.Status[:60]!r})")
    box.setFocus()
    _key(box, "=")
    editor = _editor(box)
    line = editor and editor.findChild(QtGui.QLineEdit, "expression")
    G.check(line is not None and line.text() == "Sheet.step",
            f"F2: '=' in the bound box opens the editor holding its expression "
            f"({line.text() if line else None!r})")
    editor.reject()
    G.wait()
    box.lineEdit().actions()[0].trigger()
    G.pump(10)
    editor = _editor(box)
    G.check(editor is not None,
            "F2: the mark of a field bound in the panel opens the editor too")
    line = editor.findChild(QtGui.QLineEdit, "expression")
    line.setText("Sheet.step + 2 mm")
    G.pump(10)
    editor.findChild(QtGui.QPushButton, "okBtn").click()
    G.wait()
    G.check(dict(fit.ExpressionEngine).get("ResampleStep").replace(" ", "") == "Sheet.step+2mm"
            and fit.ResampleStep.Value == 10.0 and box.text() == "10.00 mm",
            f"F2: ... and its OK binds the new expression ({box.text()!r}, "
            f"{dict(fit.ExpressionEngine)})")
    panel.reject()
    G.wait()
    G.check(not T.CURRENT and "ResampleStep" not in dict(fit.ExpressionEngine)
            and fit.ResampleStep.Value == before,
            f"F2: the panel's Cancel unbinds what it bound: Resample {before} mm again "
            f"({fit.ResampleStep}, {dict(fit.ExpressionEngine)})")
    # bound in the panel and kept by OK: one Undo step takes it back
    panel = _panel(fit)
    box = panel.step
    box.setFocus()
    _key(box, "=")
    editor = _editor(box)
    editor.findChild(QtGui.QLineEdit, "expression").setText("Sheet.step")
    G.pump(10)
    editor.findChild(QtGui.QPushButton, "okBtn").click()
    G.wait()
    G.check(panel.accept() and not T.CURRENT
            and dict(fit.ExpressionEngine).get("ResampleStep") == "Sheet.step",
            f"F2: OK keeps the binding ({dict(fit.ExpressionEngine)})")
    G.wait()
    sheet.set("A1", "9 mm")
    doc.recompute()
    G.check(fit.ResampleStep.Value == 9.0,
            f"F2: the bound Resample follows its cell ({fit.ResampleStep})")
    doc.undo()      # the cell's edit is no transaction of its own here: the panel's edit
    doc.recompute()
    G.check("ResampleStep" not in dict(fit.ExpressionEngine),
            f"F2: Undo takes the panel's binding back ({dict(fit.ExpressionEngine)})")


def stiffness_editor(doc, dots):
    """'=' in the spline's Stiffness EI (N mm^2, a plain number: FreeCAD has no unit of it,
    its N*mm^2 is 1000 of ours): the editor holds the value as shown, its OK binds it."""
    from freecad.elastica import commands as C, taskpanels as T
    sp = C.spline_sources([(dots, [])], open_panel=False)
    sp.Stiffness = 2.5e6
    doc.recompute()
    G.double_click(sp)
    G.wait()
    panel = T.CURRENT[0]
    box = [b for label, b in panel.numbers if label.startswith("Stiffness")][0]
    box.setFocus()
    _key(box, "=")
    editor = _editor(box)
    line = editor and editor.findChild(QtGui.QLineEdit, "expression")
    G.check(line is not None and "kg" not in line.text()
            and float(line.text().split()[0]) == 2.5e6,
            f"F2: '=' in Stiffness EI opens the editor on 2.5e6 N mm^2 as shown, not in "
            f"FreeCAD's mm^3*kg/s^2 ({line.text() if line else None!r})")
    line.setText("3e6")
    G.pump(10)
    editor.findChild(QtGui.QPushButton, "okBtn").click()
    G.wait()
    G.check(float(dict(sp.ExpressionEngine).get("Stiffness", "nan")) == 3e6 and sp.Stiffness == 3e6
            and box.isReadOnly(),
            f"F2: its OK binds Stiffness to 3e6 N mm^2 ({sp.Stiffness}, "
            f"{dict(sp.ExpressionEngine)})")
    panel.reject()
    G.wait()
    G.check("Stiffness" not in dict(sp.ExpressionEngine) and sp.Stiffness == 2.5e6,
            f"F2: Cancel unbinds it ({sp.Stiffness}, {dict(sp.ExpressionEngine)})")


def integer_editor(doc, fit):
    """'=' in an integer box (the B-spline's Degree) opens the expression editor on its
    property, as FreeCAD's Gui::IntSpinBox: its OK binds Degree (the box read-only, marked,
    showing the cell's value), the panel's Cancel unbinds it, and a binding kept by OK is one
    Undo step. The box had typed nothing and bound nothing."""
    from freecad.elastica import taskpanels as T
    sheet = doc.addObject("Spreadsheet::Sheet", "Degrees")
    sheet.set("A1", "5")
    sheet.setAlias("A1", "order")
    model, fit.Model = fit.Model, "smooth"      # (a discrete fit's Degree does not apply)
    doc.recompute()
    before = fit.Degree
    for keep in (False, True):
        panel = _panel(fit)
        box = panel.degree
        _in_view(box)
        box.setFocus()
        box.selectAll()
        _key(box, "=")
        editor = _editor(box)
        G.check(editor is not None and box.text() == str(before),
                f"'=' in the Degree box opens FreeCAD's expression editor, '=' not typed "
                f"({box.text()!r})")
        line = editor.findChild(QtGui.QLineEdit, "expression")
        G.check(line is not None and line.text() == str(before),
                f"the editor opens holding Degree {before} ({line.text() if line else None!r})")
        line.setText("Degrees.order")
        G.pump(10)
        if not keep:
            G.screenshot("gui_typed_integer_editor.png")
        editor.findChild(QtGui.QPushButton, "okBtn").click()
        G.wait()
        G.check(dict(fit.ExpressionEngine).get("Degree") == "Degrees.order" and fit.Degree == 5
                and box.value() == 5 and box.isReadOnly() and len(box.lineEdit().actions()) == 1
                and "Degrees.order" in box.toolTip() and not fit.Status.startswith("error"),
                f"its OK binds Degree to the cell: 5, the box read-only and marked, solved "
                f"({fit.Degree}, {box.text()!r}, {dict(fit.ExpressionEngine)}, {fit.Status[:40]!r})")
        if not keep:
            G.screenshot("gui_typed_integer_bound.png")
            box.setFocus()
            _key(box, "=")
            editor = _editor(box)
            line = editor and editor.findChild(QtGui.QLineEdit, "expression")
            G.check(line is not None and line.text() == "Degrees.order",
                    f"'=' in the bound Degree box opens the editor holding its expression "
                    f"({line.text() if line else None!r})")
            editor.reject()
            G.wait()
            panel.reject()
            G.wait()
            G.check(not T.CURRENT and "Degree" not in dict(fit.ExpressionEngine)
                    and fit.Degree == before,
                    f"the panel's Cancel unbinds Degree: {before} again ({fit.Degree}, "
                    f"{dict(fit.ExpressionEngine)})")
        else:
            G.check(panel.accept() and not T.CURRENT
                    and dict(fit.ExpressionEngine).get("Degree") == "Degrees.order",
                    f"OK keeps Degree's binding ({dict(fit.ExpressionEngine)})")
            G.wait()
            doc.undo()
            doc.recompute()
            G.check("Degree" not in dict(fit.ExpressionEngine) and fit.Degree == before,
                    f"Undo takes the panel's binding of Degree back ({fit.Degree}, "
                    f"{dict(fit.ExpressionEngine)})")
    fit.Model = model
    doc.recompute()


def run_all(smoke):
    global G
    G = smoke
    from freecad.elastica import taskpanels as T
    doc = S.new_doc("ElasticaTypedExpressions")
    dots = S.points_sketch(doc, _points(), "HandDots", App.Placement())
    doc.recompute()
    G.open_panel(doc, "Elastica_Fit", [(dots, "")], "the fit of a hand sketch")
    G.check(T.CURRENT[0].accept(), "the fit kept")
    G.wait()
    fit = [o for o in doc.Objects if o.Name.startswith("ElasticaFit")][0]
    fit.ResampleStep = 6.0
    doc.recompute()
    division_by_zero(doc, fit)
    typing_pause(doc, fit)
    equals_opens_the_editor(doc, fit)
    integer_editor(doc, fit)
    stiffness_editor(doc, dots)
    Gui.Selection.clearSelection()
    App.closeDocument(doc.Name)
