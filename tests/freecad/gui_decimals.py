"""The panels' numbers at FreeCAD's Decimals preference (Edit > Preferences > General > Units >
Number of decimals), checked by the GUI smoke test (gui_smoke.py calls run_all) at the
preference it started with and at 2 and 6 (restored after):

- the spline panel's boxes (Tension, Tolerance) and its result line (length, tension,
  energy, B-spline deviation) and the fit panel's result line (rms, max, k) write their
  numbers as FreeCAD's Quantity boxes and UserString do at that preference (units.
  number_text): '151.00 mm' at 2, '151.000000 mm' at 6; they wrote '%.3g' whatever it said;
- FreeCAD's property view shows a spline's Tension with its digits (a precision property,
  '0.0006570000000000'), not to the Decimals preference: a float property's '0.00' at the
  default 2 hid every tension a designer types (QA19gui F10; FreeCAD 0.20 has no typed
  property of 1/length^2).

Screenshots: gui_decimals_2.png, gui_decimals_6.png (the spline panel at each), and
gui_decimals_property_view.png (the Tension row of the property view)."""
import re

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)
# a number with decimals in a text ('151.00', '-0.0012', not '2' of '1/mm²', '3.9e-07')
_NUMBER = re.compile(r"(?<![\w.^/\u00b2])-?\d+\.(\d+)(?![\d.e])")


def places_ok(text, d):
    """Every number written with decimals in ``text`` has at least ``d`` of them (a number
    below 1: d significant digits, which is more places), and at least one has exactly d;
    (ok, the numbers)."""
    found = _NUMBER.findall(text)
    return bool(found) and all(len(p) >= d for p in found) and any(len(p) == d for p in found), \
        found


def spline_panel_at(doc, sk, d):
    """The spline panel (tension mode) at ``d`` decimals: boxes and result line."""
    from freecad.elastica import commands as C, taskpanels as T
    from freecad.elastica import units as U
    sp = C.spline_sources([(sk, [])], open_panel=False)
    sp.Mode = "tension"
    sp.Tension = 0.000657
    doc.recompute()
    G.double_click(sp)
    G.wait()
    panel = T.CURRENT[0]
    tension = [b for label, b in panel.numbers if label.startswith("Tension")][0]
    G.check(tension.text() == f"{U.number_text(0.000657)} 1/mm\u00b2"
            and U.number_text(0.000657) == {2: "0.00066", 6: "0.000657000"}.get(d, U.number_text(0.000657)),
            f"at {d} decimals the Tension box writes {tension.text()!r}")
    G.check(panel.tol.text() == U.box_text(sp.Tolerance.Value)
            and panel.tol.text().split()[0].count(".") == 1,
            f"at {d} decimals the Tolerance box writes {panel.tol.text()!r}")
    said = panel.result.text()
    ok, found = places_ok(said.split("<br>")[0], d)
    length = U.number_text(sp.SplineLength)
    G.check(ok and f"length {length} mm" in said and len(length.split(".")[1]) == d,
            f"at {d} decimals the spline's result line: {said.split('<br>')[0]!r} {found}")
    G.screenshot(f"gui_decimals_{d}.png")
    panel.reject()
    G.wait()
    return sp


def fit_result_at(doc, sk, d):
    from freecad.elastica import taskpanels as T
    from freecad.elastica import units as U
    G.open_panel(doc, "Elastica_Fit", [(sk, "")], "Fit elastica")
    G.wait()
    panel = T.CURRENT[0]
    said = panel.result.text()
    fit = panel.obj
    rms = U.figure_text(fit.Rms)
    G.check(f"rms {rms}" in said and f"k = {U.number_text(fit.K[0])}" in said
            and places_ok(rms, d)[0],
            f"at {d} decimals the fit's result: {said[:160]!r}")
    panel.reject()
    G.wait()


def _number(text):
    """The float a property view's text reads as, or None."""
    try:
        return float(text.strip())
    except (AttributeError, ValueError):
        return None


def property_view_text(obj, prop):
    """The text FreeCAD's property view shows for ``prop`` of ``obj`` (selected), or None."""
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(obj)
    G.pump(20)
    for view in Gui.getMainWindow().findChildren(QtGui.QTreeView):
        model = view.model()
        if model is None or view.metaObject().className() != "Gui::PropertyEditor::PropertyEditor":
            continue
        stack = [QtCore.QModelIndex()]
        while stack:
            parent = stack.pop()
            for r in range(model.rowCount(parent)):
                name = model.index(r, 0, parent)
                if name.data() == prop:
                    view.scrollTo(name)
                    return model.index(r, 1, parent).data()
                stack.append(name)
    return None


def run_all(smoke):
    global G
    G = smoke
    from freecad.elastica import units as U
    doc = S.new_doc("ElasticaDecimals")
    dots = S.points_sketch(doc, S.keyline_xy(8)[0], "Dots")
    keyline = S.points_sketch(doc, S.keyline_xy(40)[0], "Keyline")
    doc.recompute()
    prefs = App.ParamGet(U.UNITS_PREFERENCES)
    started = U.decimals()          # FreeCAD's own boxes and property view: read at start
    sp = None
    try:
        for d in dict.fromkeys((started, 2, 6)):
            prefs.SetInt("Decimals", d)
            sp = spline_panel_at(doc, dots, d)
            fit_result_at(doc, keyline, d)
    finally:
        prefs.SetInt("Decimals", started)
    shown = property_view_text(sp, "Tension")
    G.screenshot("gui_decimals_property_view.png")
    value = _number(shown)
    G.check(value is not None and abs(value - sp.Tension) <= 1e-6 * abs(sp.Tension) and value != 0,
            f"the property view shows Tension {sp.Tension!r} with its digits: {shown!r}")
    Gui.Selection.clearSelection()
    App.closeDocument(doc.Name)
