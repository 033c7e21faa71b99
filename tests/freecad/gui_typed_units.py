"""Panel wording checks of the GUI smoke test (gui_smoke.py calls run_all); QA20gui's findings:

- F5: a quantity of another kind typed in a length box ('3 deg', '2 kg') kept the value of
  its prefix (3 mm, 2 mm) with no mark, and OK kept it; FreeCAD's own Quantity boxes refuse
  it. Now the box shows the text red, why in its tooltip, keeps it past focus-out (Qt went
  back to '3 mm' silently), Enter and OK say it on the panel's error line naming the field,
  and OK refuses it until the text is one the box takes; '5 km' is read as 5e6 mm (a
  length: taken by a box up to 1e7 mm, beyond the Resample box's 1e6 mm, said so);
- F6: the Fit panel's Start tangent pressed with the fit's own edge selected said
  "ElasticaFit depends on this feature": it is that feature.

Screenshot: gui_typed_wrong_unit.png (the Fit panel refusing '3 deg' in Resample)."""
import math

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)
PTS = [(x, 25 * math.sin(x / 40.0) + 0.002 * x * x) for x in range(0, 130, 10)]


def _leave(box):
    """Focus out of the box, as clicking OK does (Xvfb's window may hold no focus to lose)."""
    from PySide import QtCore
    QtGui.QApplication.sendEvent(box, QtGui.QFocusEvent(QtCore.QEvent.FocusOut,
                                                        QtCore.Qt.MouseFocusReason))
    box.clearFocus()
    G.pump(10)


def _red(box):
    return box.lineEdit().palette().color(QtGui.QPalette.Text).name() == "#bb0000"


def wrong_units():
    from freecad.elastica import taskpanels as T
    doc = S.new_doc("ElasticaTypedUnits")
    dots = S.points_sketch(doc, PTS, "Dots", App.Placement())
    panel = G.open_panel(doc, "Elastica_Fit", [(dots, "")], "F5: the fit")
    fit = panel.obj
    box = panel.step
    for text, kind in (("3 deg", "an angle"), ("2 kg", "a mass")):
        G.type_into(box, text)
        G.wait()
        G.check(box.text() == text and _red(box) and kind in box.lineEdit().toolTip(),
                f"F5: '{text}' in Resample: kept as typed, red, why in its tooltip "
                f"({box.text()!r}, {box.lineEdit().toolTip()!r})")
        _leave(box)                 # OK clicked with the mouse takes the focus first
        line = G.error_line(panel)
        G.check(box.text() == text and _red(box)
                and line == f"Resample: {text} is {kind}, not a length (mm)",
                f"F5: leaving the box keeps '{text}' (not Qt's silent '{text[0]} mm') and the "
                f"error line names the field and why ({box.text()!r}, {line!r})")
        if text == "3 deg":
            G.screenshot("gui_typed_wrong_unit.png")
        G.check(not panel.accept() and T.CURRENT and T.CURRENT[0] is panel,
                f"F5: OK refuses '{text}': the panel stays open")
    G.type_into(box, "5 km")
    G.wait()
    _leave(box)
    line = G.error_line(panel)
    G.check(_red(box) and box._number("5 km") == 5e6 and "5 km is above the largest" in line,
            f"F5: '5 km' is 5e6 mm, beyond Resample's range: said so ({line!r})")
    G.type_into(box, "2 cm")
    G.wait()
    G.check(not _red(box) and G.error_line(panel) == "" and fit.ResampleStep.Value == 20.0,
            f"F5: '2 cm' typed over it: unmarked, the error line gone, 20 mm "
            f"({fit.ResampleStep}, {G.error_line(panel)!r})")
    G.check(panel.accept() and not T.CURRENT and fit.ResampleStep.Value == 20.0,
            f"F5: then OK takes 20 mm ({fit.ResampleStep})")
    G.pump()
    # a box whose range holds 5 km (an elastic blend's Length reaches 1e7 mm) takes it
    from freecad.elastica.spinboxes import NumberBox
    big = NumberBox(0.0, 1e7, 1.0, "mm", "a length")
    big.setValue(20.0)
    big.show()
    G.type_into(big, "5 km")
    _leave(big)
    G.check(big.value() == 5e6 and not big.problem() and not _red(big),
            f"F5: '5 km' in a box up to 1e7 mm is 5e6 mm ({big.value()}, {big.problem()!r})")
    big.close()
    return doc, fit


def own_edge(doc, fit):
    """Start tangent pressed with the fit's own edge selected."""
    Gui.ActiveDocument.setEdit(fit.Name)
    G.wait()
    from freecad.elastica import taskpanels as T
    panel = T.CURRENT[0]
    G.select(doc, [(fit, "Edge1")])
    panel.tangent_buttons[0].click()
    G.pump()
    said = panel.result.text()
    G.check("this is the feature itself" in said and "depends on" not in said
            and not fit.StartTangent,
            f"F6: the fit's own edge for its tangent: 'this is the feature itself' ({said!r})")
    panel.reject()
    G.pump()


def preference_tolerance():
    """The preference page's tolerance box (a DecadeBox in mm), '3 deg' typed: as the task
    panels' boxes, it stays as typed, red, why in its tooltip past focus-out (it went back
    to '3 mm' silently), and OK (saveSettings) stores no tolerance from it, saying so in
    the report view; '0.02 mm' typed over it is stored."""
    import os
    from freecad.elastica import PREF_PATH
    from freecad.elastica.preferences import PreferencePage
    p = App.ParamGet(PREF_PATH)
    had = p.GetFloat("Tolerance", -1.0)
    p.SetFloat("Tolerance", 0.005)
    page = PreferencePage()
    page.loadSettings()
    page.form.show()
    box = page.tol
    G.type_into(box, "3 deg")
    _leave(box)
    G.check(box.text() == "3 deg" and _red(box) and "an angle" in box.lineEdit().toolTip(),
            f"preferences: '3 deg' in the tolerance box stays after focus-out, red, why in "
            f"its tooltip ({box.text()!r}, {box.lineEdit().toolTip()!r})")
    page.form.grab().save(os.path.join(G.OUT, "gui_pref_wrong_unit.png"))
    warned, warn = [], App.Console.PrintWarning
    App.Console.PrintWarning = warned.append
    try:
        page.saveSettings()
    finally:
        App.Console.PrintWarning = warn
    said = "".join(warned)
    G.check(p.GetFloat("Tolerance") == 0.005 and "3 deg is an angle" in said
            and "not saved" in said,
            f"preferences: OK stores no tolerance from '3 deg' and says why "
            f"({p.GetFloat('Tolerance')}, {said!r})")
    G.type_into(box, "0.02 mm")
    _leave(box)
    page.saveSettings()
    G.check(not _red(box) and p.GetFloat("Tolerance") == 0.02,
            f"preferences: '0.02 mm' typed over it is stored ({p.GetFloat('Tolerance')})")
    page.form.close()
    if had < 0:
        p.RemFloat("Tolerance")
    else:
        p.SetFloat("Tolerance", had)


def run_all(smoke):
    global G
    G = smoke
    doc, fit = wrong_units()
    own_edge(doc, fit)
    App.closeDocument(doc.Name)
    preference_tolerance()
