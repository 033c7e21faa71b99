"""The Elastica commands and panels next to FreeCAD's own, checked by the GUI smoke test
(gui_smoke.py calls run_all); QA18gui's findings:

- F6: a number typed at a person's pace (250 ms a key) is solved once, not at every
  prefix ('1', '15', '150'), and a value that cannot be solved is said on the panel's
  error line only: no red report-view lines and 'Recompute failed!' (which popped the
  report view up) while typing; OK says it in the report view, the panel stays open.

Screenshot: gui_typing_error_line.png (a typed length too short: the error line)."""

import time
from contextlib import contextmanager

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)
KEY_GAP_MS = 250    # a person's pace


def report_text():
    """The report view's text."""
    for w in Gui.getMainWindow().findChildren(QtGui.QTextEdit):
        if "ReportOutput" in w.metaObject().className():
            return w.toPlainText()
    return ""


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
    G.wait(600)
    r0 = len(report_text())
    with counting_solves(b) as solves:
        slow_type(panel.length, "150")
        G.wait(1000)              # a pause: the value stands
    said = report_text()[r0:].strip()
    G.check(solves == [b.Name] and b.Length.Value == 150.0 and not b.Status.startswith("error")
            and not said,
            f"F6: '150' typed at {KEY_GAP_MS} ms a key: solved once ({solves}), not at every "
            f"prefix; the report view says nothing ({said!r})")
    slow_type(panel.length, "15")           # shorter than the gap between the ends
    G.wait(1000)              # a pause: the value stands
    line = G.error_line(panel)
    said = report_text()[r0:].strip()
    G.screenshot("gui_typing_error_line.png")
    G.check(b.Status.startswith("error") and "15 mm" in line and not said,
            f"F6: a typed length that cannot be solved: on the panel's error line ({line!r}) "
            f"only, not in the report view ({said!r})")
    r1 = len(report_text())
    accepted = panel.accept()
    G.wait(300)                             # the report view takes it from an event
    said = report_text()[r1:].strip()
    G.check(not accepted and T.CURRENT and T.CURRENT[0] is panel and said.count("\n") == 0
            and "Elastica ElasticaBlend: length 15 mm" in said and "Recompute failed" not in said,
            f"F6: OK on it says it once in the report view ({said!r}); the panel stays open")
    panel.reject()
    G.pump()
    App.closeDocument(doc.Name)


def run_all(smoke):
    global G
    G = smoke
    typing_pace()
