"""Display checks of the GUI smoke test (gui_smoke.py calls run_all):

- a bound field's f(x) mark opens FreeCAD's expression editor, as a Pad's Length's does
  (it did nothing): its OK sets the expression (the box shows its value, marked), its
  Clear removes it (the box writable again, unmarked), and the panel's Cancel undoes both;
- a fit moved into a placed App::Part is drawn on its points, its overlay (the fitted
  points' markers) too: its Shape was global, drawn again under the Part's placement;
- Fit elastica to CSV file asks how '.' is meant in a file of d.ddd numbers (it refused
  the file naming the Thousands property of a fit it did not make).

Screenshots: gui_expression_editor.png (the editor open over the Tension box),
gui_fit_in_placed_part.png (the fit, its markers and its points, the Part moved and turned)."""
import math

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, ...)
PTS = [(x, 25 * math.sin(x / 40.0) + 0.002 * x * x) for x in range(0, 130, 10)]


def _editor(box):
    """FreeCAD's expression editor open over ``box``, or None."""
    found = [d for d in box.findChildren(QtGui.QDialog)
             if d.metaObject().className() == "Gui::Dialog::DlgExpressionInput"
             and d.isVisible()]
    return found[0] if found else None


def expression_mark(doc):
    """The spline's Tension bound to a spreadsheet cell; its mark clicked."""
    from freecad.elastica import commands as C, taskpanels as T
    ss = doc.addObject("Spreadsheet::Sheet", "Sheet")
    ss.set("A1", "0.001")
    ss.setAlias("A1", "sigma")
    dots = S.points_sketch(doc, PTS, "MarkDots", App.Placement())
    App.setActiveDocument(doc.Name)
    sp = C.spline_sources([(dots, [])], open_panel=False)
    sp.setExpression("Tension", "Sheet.sigma")
    doc.recompute()
    G.check(abs(sp.Tension - 0.001) < 1e-15, f"the bound tension ({sp.Tension})")
    Gui.ActiveDocument.setEdit(sp.Name)
    G.wait()
    panel = T.CURRENT[0]
    box = panel.tension
    marks = box.lineEdit().actions()
    G.check(box.isReadOnly() and len(marks) == 1 and _editor(box) is None,
            "a bound Tension: read-only, marked, no editor open yet")
    marks[0].trigger()
    G.pump(10)
    editor = _editor(box)
    G.check(editor is not None, "its f(x) mark opens FreeCAD's expression editor")
    line = editor.findChild(QtGui.QLineEdit, "expression")
    G.check(line is not None and line.text() == "Sheet.sigma",
            f"the editor holds the expression ({line.text() if line else None!r})")
    line.setText("Sheet.sigma * 3")
    G.pump(10)
    G.screenshot("gui_expression_editor.png")
    editor.findChild(QtGui.QPushButton, "okBtn").click()
    G.wait()
    G.check(dict(sp.ExpressionEngine).get("Tension") == "Sheet.sigma * 3"
            and abs(sp.Tension - 0.003) < 1e-15 and box.text() == "0.0030 1/mm\u00b2"
            and box.isReadOnly() and "Sheet.sigma * 3" in box.toolTip()
            and len(box.lineEdit().actions()) == 1,
            f"its OK binds the new expression, the box shows it ({box.text()!r}, "
            f"{sp.Tension}, {dict(sp.ExpressionEngine)})")
    box.lineEdit().actions()[0].trigger()
    G.pump(10)
    editor = _editor(box)
    G.check(editor is not None, "the mark opens the editor again")
    editor.findChild(QtGui.QPushButton, "discardBtn").click()
    G.wait()
    G.check("Tension" not in dict(sp.ExpressionEngine) and not box.isReadOnly()
            and len(box.lineEdit().actions()) == 0 and "Bound" not in box.toolTip(),
            f"its Clear unbinds: the box writable, unmarked ({dict(sp.ExpressionEngine)})")
    panel.reject()
    G.wait()
    G.check(dict(sp.ExpressionEngine).get("Tension") == "Sheet.sigma"
            and abs(sp.Tension - 0.001) < 1e-15,
            f"Cancel undoes the panel's expression edits ({dict(sp.ExpressionEngine)}, "
            f"{sp.Tension})")


def fit_in_placed_part(doc):
    """A fit and its overlay in a Part moved and turned, against its points as drawn."""
    from freecad.elastica import commands as C
    dots = S.points_sketch(doc, PTS, "PartDots", App.Placement())
    App.setActiveDocument(doc.Name)
    fit = C.fit_sources([(dots, [])], open_panel=False, Model="smooth")
    doc.recompute()
    part = doc.addObject("App::Part", "Part")
    part.Placement = App.Placement(App.Vector(80, -60, 30), App.Rotation(App.Vector(1, 1, 0), 50))
    part.addObject(fit)
    doc.recompute()
    G.pump(10)
    plc = part.getGlobalPlacement()
    shape = fit.Shape.copy()
    shape.transformShape(plc.toMatrix(), True)
    drawn = [dots.getGlobalPlacement().multVec(App.Vector(x, y, 0)) for x, y in PTS]
    off = S.distance_to_shape([tuple(p) for p in drawn], shape)
    G.check(off < 0.5, f"a fit in a placed Part is drawn on its points ({off:.3g} mm)")
    # the markers: the overlay's coordinates, under the Part's placement, are the points
    group = fit.ViewObject.Proxy._groups[0]
    marks = [plc.multVec(App.Vector(*group["coords"].point[i].getValue()))
             for i in range(group["points"].numPoints.getValue())]
    worst = max(min((m - p).Length for p in drawn) for m in marks) if marks else 1e9
    G.check(len(marks) == len(PTS) and worst < 1e-4,
            f"its point markers are drawn on the points ({len(marks)}, {worst:.3g} mm)")
    Gui.ActiveDocument.ActiveView.viewIsometric()
    Gui.SendMsgToActiveView("ViewFit")
    G.screenshot("gui_fit_in_placed_part.png")


def csv_thousands_question(doc):
    """Fit elastica to CSV file of a ';' file of d.ddd numbers: the command asks how '.'
    is meant (it refused the file naming a fit's Thousands property, no fit made) and the
    answer "'.' groups thousands" makes a fit with Thousands '.' reading 1.000 as 1000."""
    import os
    import tempfile
    from freecad.elastica import commands as C, taskpanels as T
    fd, path = tempfile.mkstemp(suffix=".csv")
    with os.fdopen(fd, "w") as fh:
        fh.write("x;y\n" + "".join(f"{x}.000;{2 + 0.5 * math.sin(x):.3f}\n"
                                   for x in range(1, 10)))
    App.setActiveDocument(doc.Name)
    n0 = len(doc.Objects)
    chooser = QtGui.QFileDialog.getOpenFileName
    QtGui.QFileDialog.getOpenFileName = staticmethod(lambda *a, **k: (path, ""))
    try:
        said = G.answer_modal("'.' groups thousands (1.000 = 1000)")
        C.FitCsvCommand().Activated()
        G.pump(10)
    finally:
        QtGui.QFileDialog.getOpenFileName = chooser
    fits = [o for o in doc.Objects[n0:] if o.Name.startswith("ElasticaFit")]
    G.check(len(said) == 1 and "do not" in said[0][1] and len(fits) == 1
            and fits[0].Thousands == "." and not fits[0].Status.startswith("error")
            and abs(fits[0].DataPoints[0].x - 1000.0) < 1e-9,
            f"Fit to CSV asks how '.' is meant and reads as answered ({said}, "
            f"{[(f.Thousands, f.Status[:60]) for f in fits]})")
    # its panel shows and edits what a point file's fit has: the file and its Thousands
    panel = T.CURRENT[0] if T.CURRENT else None
    fit = fits[0] if fits else None
    G.check(panel is not None and getattr(panel, "csv", None) is not None
            and panel.csv.text() == path and panel.thousands.currentIndex() == 1
            and panel.thousands.isEnabled(),
            f"the CSV fit's panel shows its file and Thousands '.' "
            f"({getattr(getattr(panel, 'csv', None), 'text', lambda: None)()!r})")
    if panel is not None and getattr(panel, "thousands", None) is not None:
        G.screenshot("gui_fit_csv_panel.png")
        panel.thousands.setCurrentIndex(2)          # "'.' is decimal": 1.000 is 1
        G.wait()
        G.check(fit.Thousands == "none" and abs(fit.DataPoints[0].x - 1.0) < 1e-9
                and not fit.Status.startswith("error"),
                f"its Thousands row set to '.' is decimal reads 1.000 as 1 "
                f"({fit.Thousands}, {fit.DataPoints[0].x if fit.DataPoints else None})")
        fd, other = tempfile.mkstemp(suffix=".csv")
        with os.fdopen(fd, "w") as fh:
            fh.write("x,y\n" + "".join(f"{x + 500},{1 + 0.3 * math.sin(x):.4f}\n"
                                       for x in range(12)))
        panel.csv.setText(other)
        panel.csv.editingFinished.emit()
        G.wait()
        G.check(fit.CsvFile == other and len(fit.DataPoints) == 12
                and abs(fit.DataPoints[0].x - 500.0) < 1e-9,
                f"a path typed in its Points file row is fitted ({fit.CsvFile}, "
                f"{len(fit.DataPoints)} points)")
        os.remove(other)
    if T.CURRENT:
        T.CURRENT[0].reject()
        G.wait()
    os.remove(path)


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaPartMarks")
    expression_mark(doc)
    fit_in_placed_part(doc)
    csv_thousands_question(doc)
    App.closeDocument(doc.Name)
