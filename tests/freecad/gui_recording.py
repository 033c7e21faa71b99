"""What a panel's OK records (QA18gui F5), checked by the GUI smoke test (gui_smoke.py calls
run_all): the Elastic blend made by its command, Tension 0.001 typed in its panel, solution 2
picked, OK; then the blend's panel opened again, its Degree changed, OK; then opened and
OK'd without a change. Only the make() line was recorded, by Gui.doCommandGui, whose lines
a recorded macro holds as comments: a macro replayed made nothing, the console's lines the
free batten, solution 1. Now every line goes through Gui.doCommand (the console and a
macro, as FreeCAD's own panels record theirs), and those lines, run in a fresh document of
the same name on the same sketch, make the same blend: its properties, results and
B-spline; the OK without a change records nothing; OK leaves the blend as the panel showed
it. Screenshot: gui_recorded_blend.png."""
import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def run_all(smoke):
    global G
    G = smoke
    name = "ElasticaRecorded"
    doc = S.new_doc(name)
    sk = S.two_lines_sketch(doc)
    recorded, skipped, do, do_gui = [], [], Gui.doCommand, Gui.doCommandGui
    Gui.doCommand = lambda code: recorded.append(code) or do(code)
    Gui.doCommandGui = lambda code: skipped.append(code) or do_gui(code)
    try:
        panel = G.open_panel(doc, "Elastica_Blend", [(sk, "Edge1"), (sk, "Edge2")],
                             "recorded blend")
        b = panel.obj
        blend = b.Name
        G.type_into(panel.tension, "0.001")
        G.wait()
        panel.list.setCurrentRow(1)
        G.wait()
        G.check(b.Tension == 0.001 and b.Solution == 2,
                f"the blend edited ({b.Tension}, {b.Status})")
        shown = S.taken(b)
        panel.accept()
        G.pump()
        G.check(S.taken(b) == shown, "OK leaves the blend as the panel showed it "
                                    f"({b.Solution}, {b.Status})")
        panel = G.double_click(b)          # an edit of the existing blend: Degree 6
        panel.degree.setValue(6)
        G.wait()
        panel.accept()
        G.pump()
        n = len(recorded)
        panel = G.double_click(b)          # opened and OK'd: nothing changed, nothing recorded
        panel.accept()
        G.pump()
        G.check(len(recorded) == n, f"an edit that changes nothing records nothing: "
                                    f"{recorded[n:]}")
    finally:
        Gui.doCommand, Gui.doCommandGui = do, do_gui
    G.screenshot("gui_recorded_blend.png")
    ref = f"App.getDocument({name!r}).getObject({blend!r})"
    lines = [line for code in recorded for line in code.splitlines() if line.startswith(ref)]
    G.check(lines == [f"{ref}.Tension = 0.001", f"{ref}.Solution = 2", f"{ref}.Degree = 6"],
            f"OK records the properties each edit changed, once: {lines}")
    G.check(any("elastica_blend.make(" in code for code in recorded) and
            not any("elastica_blend.make(" in code for code in skipped),
            "the make() line is recorded for a macro (Gui.doCommand)")
    console = "\n".join(w.toPlainText() for w in Gui.getMainWindow().findChildren(
        QtGui.QPlainTextEdit) if "PythonConsole" in w.metaObject().className())
    G.check(all(line in console for line in lines), "the lines show in the Python console")
    was = S.taken(b)
    App.closeDocument(name)
    doc = S.new_doc(name)
    S.two_lines_sketch(doc)
    exec("\n".join(recorded), {"App": App, "FreeCAD": App, "Gui": Gui})
    doc.recompute()
    again = doc.getObject(blend)
    G.check(again is not None and S.taken(again) == was,
            "the recorded lines replayed make the same blend "
            f"({again and again.Status} / {was['results']['Status']})")
    App.closeDocument(name)
