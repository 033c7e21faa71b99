"""GUI smoke test, run as `xvfb-run -a freecad tests/freecad/gui_smoke.py` by
tests/freecad/freecad.mk: the Elastica workbench activates, each command runs
from the selection on a sample document (task panels opened and accepted), the
preference page loads and saves, and a screenshot of the 3D view is saved under
$ELASTICA_TEST_OUT (build/freecad/) and checked to be non-blank. The outcome goes
to gui_smoke.result (first line PASS or FAIL); FreeCAD is then ended with os._exit
because its exit status says nothing about a script."""
import os
import sys
import traceback

import FreeCAD as App
import FreeCADGui as Gui

OUT = os.environ.get("ELASTICA_TEST_OUT", os.getcwd())
HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else \
    os.path.join(os.getcwd(), "tests", "freecad")
sys.path.insert(0, HERE)
lines = []


def check(cond, what):
    lines.append(("ok   " if cond else "FAIL ") + what)
    if not cond:
        raise AssertionError(what)


def pump(n=5):
    from PySide import QtGui
    for _ in range(n):
        QtGui.QApplication.processEvents()


def nonblank(path):
    """(fraction of pixels that are drawn geometry, number of distinct drawn colours):
    a pixel is drawn when it differs clearly from its row's most common colour (the
    background is a vertical gradient)."""
    from collections import Counter
    from PySide import QtGui
    img = QtGui.QImage(path)
    if img.isNull():
        return 0.0, 0
    drawn, total, colours = 0, 0, set()
    for y in range(0, img.height(), 2):
        row = [img.pixel(x, y) for x in range(0, img.width(), 2)]
        bg = Counter(row).most_common(1)[0][0]
        br, bgc, bb = (bg >> 16) & 255, (bg >> 8) & 255, bg & 255
        for p in row:
            total += 1
            d = abs(((p >> 16) & 255) - br) + abs(((p >> 8) & 255) - bgc) + abs((p & 255) - bb)
            if d > 60:
                drawn += 1
                colours.add(p & 0xF0F0F0)
    return drawn / total, len(colours)


def run_on(doc, command, picks):
    """Select picks ([(object, subelement or "")]) and run command; the number of
    document objects before."""
    Gui.Selection.clearSelection()
    for obj, sub in picks:
        if sub:
            Gui.Selection.addSelection(doc.Name, obj.Name, sub)
        else:
            Gui.Selection.addSelection(doc.Name, obj.Name)
    n0 = len(doc.Objects)
    Gui.runCommand(command)
    pump()
    return n0


def open_panel(doc, command, picks, what):
    """run_on, then check that one feature was made and its panel opened; the panel."""
    from freecad.elastica import taskpanels as T
    n0 = run_on(doc, command, picks)
    check(len(doc.Objects) == n0 + 1 and T.CURRENT, f"{what} creates a feature and opens its panel")
    return T.CURRENT[0]


def run():
    import elastica_samples as S
    Gui.activateWorkbench("ElasticaWorkbench")
    pump()
    check(Gui.activeWorkbench().name() == "ElasticaWorkbench", "workbench activates")
    cmds = Gui.listCommands()
    for c in ("Elastica_Fit", "Elastica_FitCsv", "Elastica_Blend", "Elastica_EllipticBlend",
              "Elastica_Comb"):
        check(c in cmds, f"command {c} registered")
    from freecad.elastica import commands as C, taskpanels as T, preferences as P

    doc = S.new_doc("ElasticaSmoke")
    lines_sk = S.two_lines_sketch(doc)
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")

    # Elastic blend: select two edges, run, accept the panel
    panel = open_panel(doc, "Elastica_Blend", [(lines_sk, "Edge1"), (lines_sk, "Edge2")],
                       "Elastic blend")
    blend = panel.obj
    check(panel.list.count() == len(blend.Lengths) >= 1, "blend panel lists the solutions")
    # preview: switching to the other end of the second edge recomputes the blend
    l0 = blend.Shape.Length
    panel.end2.setChecked(not blend.AtEnd2)
    check(abs(blend.Shape.Length - l0) > 1.0 and panel.list.count() == len(blend.Lengths),
          "blend panel previews another end")
    panel.end2.setChecked(not panel.end2.isChecked())
    panel.value.setValue(70.0)
    panel.value.editingFinished.emit()
    check(abs(blend.Shape.Length - 70.0) < 1e-3, f"blend panel length 70 -> {blend.Shape.Length:.4f}")
    for row in range(panel.list.count()):
        panel.list.setCurrentRow(row)
        check(blend.Solution == row
              and blend.Status == f"solution {row + 1} of {panel.list.count()}",
              f"blend panel previews solution {row + 1}")
    panel.list.setCurrentRow(0)
    panel.into_sketch.setChecked(False)
    check(panel.accept(), "blend panel accepts")
    pump()
    check(not blend.Status.startswith("error"), f"blend status {blend.Status}")
    check(blend.SketchGeometry1 == 0 and blend.SketchGeometry2 == 1, "blend keeps geometry indices")

    # Curvature comb of the blend
    n0 = run_on(doc, "Elastica_Comb", [(blend, "")])
    comb = doc.Objects[-1]
    check(len(doc.Objects) == n0 + 1 and comb.Status == "ok", "Curvature comb creates a comb")

    # a second blend written into the sketch with tangency (the feature is then removed)
    ng, nc = len(lines_sk.Geometry), lines_sk.ConstraintCount
    run_on(doc, "Elastica_Blend", [(lines_sk, "Edge1"), (lines_sk, "Edge2")])
    T.CURRENT[0].into_sketch.setChecked(True)
    check(T.CURRENT[0].accept(), "blend into sketch accepts")
    doc.recompute()
    check(len(lines_sk.Geometry) == ng + 1 and lines_sk.ConstraintCount == nc + 2,
          "blend written into the sketch with two tangency constraints")
    check(not blend.Status.startswith("error"), f"first blend unaffected: {blend.Status}")

    # Fit elastica: a sketch B-spline through a keyline, panel options, B-spline into a new sketch
    xy, _ = S.keyline_xy(30)
    ksk = S.bspline_sketch(doc, xy)
    panel = open_panel(doc, "Elastica_Fit", [(ksk, "Edge1")], "Fit elastica")
    fit = panel.obj
    check("rms" in panel.result.text() and "k =" in panel.result.text(),
          "fit panel shows rms, max error, k, status")
    panel.model.setCurrentIndex(1)
    check(fit.Model == "smooth" and fit.Status == "converged",
          f"fit panel: smooth model {fit.Status}")
    panel.step.setValue(2.0)
    panel.step.editingFinished.emit()
    panel.split.setChecked(True)
    check(fit.ResampleStep == 2.0 and len(fit.Shape.Edges) == 2 and len(fit.K) == 2,
          "fit panel: keyline split into two elasticae")
    panel.step.setValue(5000.0)                 # longer than the curve: bad input
    panel.step.editingFinished.emit()
    check("error:" in panel.result.text() and not panel.accept() and T.CURRENT,
          "fit panel shows the error and stays open")
    panel.step.setValue(2.0)
    panel.step.editingFinished.emit()
    check("error:" not in panel.result.text(), "fit panel recovers")
    panel.sketch.setCurrentIndex(panel.sketch.count() - 1)   # new sketch
    check(panel.accept(), "fit panel accepts")
    pump()
    check(not fit.Status.startswith("error"), f"fit status {fit.Status}")
    check(any(o.Name.startswith("ElasticaSketch") for o in doc.Objects),
          "fit B-spline written into a new sketch")

    # Elliptic blend curve: a sketch of four points, panel options, B-spline into a new sketch
    psk = S.points_sketch(doc, [(0, -60), (20, -25), (55, -20), (80, -55)], "FourPoints")
    panel = open_panel(doc, "Elastica_EllipticBlend", [(psk, "")], "Elliptic blend curve")
    ell = panel.obj
    check(ell.Status == "ok" and "deviation" in panel.result.text(),
          f"elliptic blend panel shows the B-spline deviation ({ell.Status})")
    l0 = ell.Shape.Length
    panel.k.setValue(0.9)
    panel.k.editingFinished.emit()
    check(ell.K == 0.9 and ell.Status == "ok" and abs(ell.Shape.Length - l0) > 1e-3,
          "elliptic blend panel previews another k")
    panel.mode.setCurrentIndex(1)
    check(ell.Mode == "control" and ell.Status == "ok", "elliptic blend panel: control points")
    panel.conv.setCurrentIndex(1)
    panel.k.setValue(0.3)
    panel.k.editingFinished.emit()
    check(ell.KConvention == "parameter" and ell.Status == "ok", "elliptic blend panel: m = k^2")
    panel.sketch.setCurrentIndex(panel.sketch.count() - 1)   # new sketch
    n0 = len(doc.Objects)
    check(panel.accept(), "elliptic blend panel accepts")
    pump()
    check(len(doc.Objects) == n0 + 1 and doc.Objects[-1].isDerivedFrom("Sketcher::SketchObject")
          and len(doc.Objects[-1].Geometry) == 1, "elliptic blend B-spline written into a new sketch")

    # bad input through a command: empty selection, document unchanged
    Gui.Selection.clearSelection()
    before = S.doc_state(doc)
    del C.MESSAGES[:]
    Gui.runCommand("Elastica_Fit")
    Gui.runCommand("Elastica_Blend")
    Gui.runCommand("Elastica_Comb")
    Gui.runCommand("Elastica_EllipticBlend")
    pump()
    check(S.doc_state(doc) == before and len(C.MESSAGES) == 4,
          "empty selection: messages, document unchanged")

    # Cancel removes a fresh feature
    sk2 = S.two_lines_sketch(doc, "Lines2", App.Placement(App.Vector(0, 0, -30), App.Rotation()))
    Gui.Selection.addSelection(doc.Name, sk2.Name, "Edge1")
    Gui.Selection.addSelection(doc.Name, sk2.Name, "Edge2")
    before = [o.Name for o in doc.Objects]
    Gui.runCommand("Elastica_Blend")
    pump()
    T.CURRENT[0].reject()
    pump()
    check([o.Name for o in doc.Objects] == before, "Cancel removes the new feature")

    # the preference page
    from freecad.elastica import defaults
    page = P.PreferencePage()
    page.loadSettings()
    old = defaults()
    page.tol.setValue(0.0125)
    page.degree.setValue(5)
    page.model.setCurrentIndex(1)
    page.saveSettings()
    check(defaults() == (0.0125, 5, "smooth"), f"preference page saves {defaults()}")
    page.tol.setValue(old[0])
    page.degree.setValue(old[1])
    page.model.setCurrentIndex(["discrete", "smooth"].index(old[2]))
    page.saveSettings()
    check(defaults() == old, "preference page restores")

    # the commands were recorded (Gui.doCommandGui): they show in the Python console
    from PySide import QtGui
    consoles = [w for w in Gui.getMainWindow().findChildren(QtGui.QPlainTextEdit)
                if "make_blend" in w.toPlainText()]
    check(bool(consoles), "commands recorded in the Python console")

    # screenshot of the 3D view
    Gui.Selection.clearSelection()
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    pump(20)
    path = os.path.join(OUT, "gui_smoke.png")
    view.saveImage(path, 800, 600, "Current")
    frac, ncol = nonblank(path)
    # control: the same check calls an empty document's view blank
    empty = App.newDocument("ElasticaEmpty")
    pump(10)
    blank = os.path.join(OUT, "gui_smoke_empty.png")
    Gui.getDocument(empty.Name).ActiveView.saveImage(blank, 800, 600, "Current")
    efrac, _ = nonblank(blank)
    check(efrac < 0.0002, f"an empty view is judged blank ({100 * efrac:.3f}% drawn)")
    App.closeDocument(empty.Name)
    check(os.path.isfile(path) and frac > 0.001 and ncol >= 2,
          f"screenshot {path} non-blank ({100 * frac:.2f}% drawn, {ncol} colours)")


def main():
    ok = True
    try:
        run()
    except Exception:
        ok = False
        lines.append(traceback.format_exc())
    with open(os.path.join(OUT, "gui_smoke.result"), "w") as f:
        f.write(("PASS" if ok else "FAIL") + "\n" + "\n".join(lines) + "\n")
    sys.stdout.flush()
    os._exit(0 if ok else 1)


from PySide import QtCore  # noqa: E402
QtCore.QTimer.singleShot(0, main)
