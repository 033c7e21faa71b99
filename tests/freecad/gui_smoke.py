"""GUI smoke test, run as `xvfb-run -a freecad tests/freecad/gui_smoke.py` by
tests/freecad/freecad.mk: the Elastica workbench used as a user would.

- the demo document (made headless by examples/demo.py) opens with the features'
  view providers, icons and colours named in their labels; double-click opens a panel;
- each command runs from a selection and its task panel is driven like a user does
  it: mouse clicks on spin-box arrows, typing, mode switches, picking a solution,
  OK, and Cancel (which must revert an edited feature and remove a new one);
- panels fit the 264 px Combo View, every field has a tooltip, fields that do not
  apply are disabled;
- the preference page loads, saves and has its icon; commands are recorded.

This file is the harness (check, wait, pump, screenshot, the helpers that drive a panel), the
demo document and run(), which calls each part in turn with this module (their G): each
tool's panel in gui_smoke_blend.py, gui_smoke_spline.py, gui_smoke_fit.py and
gui_smoke_tools.py (elliptic blend, G2 quadratic, comb), on one document; then the parts by
concern (gui_panel_lifecycle.py, gui_blend_panel.py, gui_edge_clicks.py, ...).

Screenshots (whole window, 3D view included) stay in $ELASTICA_TEST_OUT
(build/freecad/): gui_demo.png, gui_blend_panel.png (a G2 blend by length, its
guide ducks), gui_fit_panel.png, gui_fit_ends.png (its warning line), gui_fit_g2.png
(joined G2 to an arc), gui_fit_sparse.png (a sketch of 7 points fitted by the
discrete model: its warning line), gui_fit_outliers.png (a scan's two glitches on
the warning line), gui_spline_g2.png (a G2 start),
gui_spline_panel.png, gui_ellblend_panel.png (its warning line), gui_g2quad_panel.png,
gui_comb_panel.png, gui_blend_no_free_batten.png (the note why by length),
gui_spline_spike.png (the note why at a tension), gui_spline_loops.png (its warning line),
gui_blend_undo.png and gui_fit_undo.png (Edit > Undo during an edit:
the panel closed); gui_panel_lifecycle.py's gui_close_with_panel.png,
gui_delete_during_panel.png and gui_keep_needs_copy.png; gui_blend_panel.py's
gui_blend_picked_tops.png, gui_blend_ends_by_length.png, gui_blend_bound.png,
gui_blend_imperial.png and the others its docstring names; gui_schema_texts.py's
gui_ellblend_loop_imperial.png, gui_fit_result_imperial.png; gui_decimals.py's
gui_decimals_2.png, gui_decimals_6.png, gui_decimals_property_view.png; gui_fc_behaviour.py's, which
its docstring names; gui_typed_units.py's gui_typed_wrong_unit.png; gui_typed_expressions.py's
gui_typed_equals_editor.png, gui_typed_bound.png and gui_typed_division_by_zero.png;
gui_reopen_old.py's gui_reopen_old.png; gui_recording.py's gui_recorded_blend.png. The outcome goes
to gui_smoke.result (first line PASS or FAIL); FreeCAD is then ended with os._exit
because its exit status says nothing about a script. Only APIs present in FreeCAD
0.20 and 1.0 are used (PySide through FreeCAD's shim)."""
import os
import sys
import time
import traceback
from contextlib import contextmanager

import FreeCAD as App
import FreeCADGui as Gui

OUT = os.environ.get("ELASTICA_TEST_OUT", os.getcwd())
DEMO = os.environ.get("ELASTICA_TEST_DEMO", os.path.join(OUT, "demo", "demo.FCStd"))
HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else \
    os.path.join(os.getcwd(), "tests", "freecad")
sys.path.insert(0, HERE)
lines = []


def check(cond, what):
    lines.append(("ok   " if cond else "FAIL ") + what)
    if not cond:
        raise AssertionError(what)


@contextmanager
def user_schema(schema):
    """The unit schema ``schema`` as a user sets it (the preference the panels read and the
    running schema), the user's restored after the block."""
    prefs = App.ParamGet("User parameter:BaseApp/Preferences/Units")
    old = prefs.GetInt("UserSchema", 0)
    prefs.SetInt("UserSchema", schema)
    App.Units.setSchema(schema)
    try:
        yield
    finally:
        prefs.SetInt("UserSchema", old)
        App.Units.setSchema(old)


def pump(n=5):
    from PySide import QtGui
    for _ in range(n):
        QtGui.QApplication.processEvents()


WAIT_LIMIT_S = 60.0   # generous: a loaded 2-core box; a wait that runs out fails the smoke
QUIET_ROUNDS = 3      # event-loop round trips in a row with nothing pending


def pending():
    """What the workbench has set going and not yet run, in words (None: nothing): the
    open panel's recompute (its timer: panelbase.DELAY_MS after an edit, TYPING_MS after a
    typed key), its boxes' typing pause (NumberBox.pause: a text stands or is said refused
    then), a document still restoring or not yet finished opening (viewproviders'
    finish_opening, polled every 50 ms while FreeCAD restores it), an answer_modal poll
    waiting for its dialog (_POLLS)."""
    from freecad.elastica import taskpanels as T, viewproviders as V
    if T.CURRENT and T.CURRENT[0].timer.isActive():
        return "the open panel's pending recompute"
    if T.CURRENT and any(box.pause.isActive() for _, box in T.CURRENT[0].numbers):
        return "the typing pause of a box of the open panel"
    if V._OPENING:
        return f"documents {sorted(V._OPENING)} still opening"
    restoring = [d.Name for d in App.listDocuments().values() if d.Restoring]
    if restoring:
        return f"documents {restoring} still restoring"
    if _POLLS:
        return ", ".join(_POLLS)
    return None


def wait():
    """Run the event loop until what the last action set going has run, polling (no fixed
    time): the open panel's pending recompute, a document's opening (``pending``), and the
    calls queued behind them (the workbench's QTimer.singleShot(0, ...): a panel following
    a recompute, closing when its feature left, the expression editor's result). Settled
    when QUIET_ROUNDS round trips of the event loop in a row (a zero timer queued after
    everything queued before it, run) find nothing pending. Fails the smoke, naming what
    was pending, after WAIT_LIMIT_S."""
    from PySide import QtCore, QtGui
    end = time.time() + WAIT_LIMIT_S
    quiet = 0
    while quiet < QUIET_ROUNDS:
        ran = []
        QtCore.QTimer.singleShot(0, lambda: ran.append(True))
        while not ran:
            QtGui.QApplication.processEvents()
            if time.time() > end:
                check(False, f"wait: the event loop did not come round in {WAIT_LIMIT_S:g} s")
        what = pending()
        if what is None:
            quiet += 1
        else:
            quiet = 0
            time.sleep(0.005)
        if what is not None and time.time() > end:
            check(False, f"wait: {what} still pending after {WAIT_LIMIT_S:g} s")


def screenshot(name):
    """The whole main window as the screen shows it (3D view included)."""
    from PySide import QtGui
    pump(20)
    path = os.path.join(OUT, name)
    mw = Gui.getMainWindow()
    QtGui.QApplication.primaryScreen().grabWindow(mw.winId()).save(path)
    return path


def drawn(path, region=None):
    """(fraction of pixels that are drawn geometry, number of distinct drawn colours)
    in the image (or its region (x0, y0, x1, y1)): a pixel is drawn when it differs
    clearly from its row's most common colour (the background is a vertical gradient)."""
    from collections import Counter
    from PySide import QtGui
    img = QtGui.QImage(path)
    if img.isNull():
        return 0.0, 0
    x0, y0, x1, y1 = region or (0, 0, img.width(), img.height())
    n, total, colours = 0, 0, Counter()
    for y in range(y0, y1, 2):
        row = [img.pixel(x, y) for x in range(x0, x1, 2)]
        bg = Counter(row).most_common(1)[0][0]
        br, bgc, bb = (bg >> 16) & 255, (bg >> 8) & 255, bg & 255
        for p in row:
            total += 1
            d = abs(((p >> 16) & 255) - br) + abs(((p >> 8) & 255) - bgc) + abs((p & 255) - bb)
            if d > 60:
                n += 1
                colours[p & 0xE0E0E0] += 1
    # colours covering a few pixels at least (not antialiasing mixtures)
    return n / max(total, 1), sum(1 for c in colours.values() if c >= 8)


def view_region():
    """The 3D view's rectangle in window coordinates."""
    from PySide import QtGui
    mw = Gui.getMainWindow()
    mdi = mw.findChild(QtGui.QMdiArea)
    top_left = mdi.mapTo(mw, mdi.rect().topLeft())
    return (top_left.x(), top_left.y(), top_left.x() + mdi.width(), top_left.y() + mdi.height())


def click_arrow(box, up=True):
    """A mouse click on a spin box's up or down arrow (where the style draws it)."""
    from PySide import QtCore, QtGui
    opt = QtGui.QStyleOptionSpinBox()
    box.initStyleOption(opt)
    sub = QtGui.QStyle.SC_SpinBoxUp if up else QtGui.QStyle.SC_SpinBoxDown
    pos = box.style().subControlRect(QtGui.QStyle.CC_SpinBox, opt, sub, box).center()
    for kind in (QtCore.QEvent.MouseButtonPress, QtCore.QEvent.MouseButtonRelease):
        ev = QtGui.QMouseEvent(kind, QtCore.QPointF(pos), QtCore.Qt.LeftButton,
                               QtCore.Qt.LeftButton, QtCore.Qt.NoModifier)
        QtGui.QApplication.sendEvent(box, ev)
    pump()


def type_into(box, text):
    """Select a spin box's text and type ``text`` key by key."""
    from PySide import QtCore, QtGui
    box.setFocus()
    box.selectAll()
    for ch in text:
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtGui.QApplication.sendEvent(box, QtGui.QKeyEvent(kind, 0, QtCore.Qt.NoModifier, ch))
    pump()


def fits_combo_view(panel, what):
    """Every task box fits a 264 px Combo View, and the panel fits the task view's
    viewport beside its vertical scroll bar (FreeCAD's task view has no horizontal one:
    the Fit panel's boxes were cut off by 19 px at 1280 x 1024); every input has a
    tooltip."""
    from PySide import QtGui
    widest = max(f.minimumSizeHint().width() for f in panel.form)
    check(widest <= 240, f"{what} panel fits the Combo View (widest box {widest} px)")
    pump()
    areas = [a for a in Gui.getMainWindow().findChildren(QtGui.QScrollArea)
             if a.isVisible() and a.widget() is not None and a.isAncestorOf(panel.form[0])]
    need = areas and areas[0].widget().minimumSizeHint().width()
    check(areas and need <= areas[0].viewport().width(),
          f"{what} panel fits the task view (needs {need} px of "
          f"{areas[0].viewport().width() if areas else '?'})")
    kinds = (QtGui.QAbstractSpinBox, QtGui.QComboBox, QtGui.QCheckBox, QtGui.QPushButton,
             QtGui.QListWidget)
    bare = [type(w).__name__ for f in panel.form for w in f.findChildren(QtGui.QWidget)
            if isinstance(w, kinds) and not w.toolTip()]
    check(not bare, f"{what} panel: every field has a tooltip (missing: {bare})")


def error_line(panel):
    """The text of the panel's error line ('' while hidden), checked to be where the user
    looks first: at the top of its first box, above every field (it was under the blend's
    Solutions box, out of sight: QA16 P4)."""
    from PySide import QtCore, QtGui
    row, text = panel.error
    if not row.isVisible():
        return ""
    box = panel.form[0]
    kinds = (QtGui.QAbstractSpinBox, QtGui.QComboBox, QtGui.QCheckBox, QtGui.QPushButton)
    tops = [w.mapTo(box, QtCore.QPoint(0, 0)).y() for w in box.findChildren(QtGui.QWidget)
            if isinstance(w, kinds)]
    check(box.isAncestorOf(row) and all(row.y() < y for y in tops),
          f"the error line heads the panel ({row.y()} px, fields from {min(tops, default=0)})")
    # as read: units.unbroken's no-break spaces and word joiners (the blend's) plain
    return text.text().replace("\u00a0", " ").replace("\u2060", "")


def select(doc, picks):
    """Select picks ([(object, subelement or "")]) of ``doc``, nothing else."""
    Gui.Selection.clearSelection()
    for obj, sub in picks:
        if sub:
            Gui.Selection.addSelection(doc.Name, obj.Name, sub)
        else:
            Gui.Selection.addSelection(doc.Name, obj.Name)


def report_view():
    """FreeCAD's report view (Gui::DockWnd::ReportOutput), None where none is found."""
    from PySide import QtGui
    for w in Gui.getMainWindow().findChildren(QtGui.QTextEdit):
        if type(w).__name__ == "ReportOutput" or w.objectName() == "Report view" or \
                "ReportOutput" in w.metaObject().className():
            return w
    return None


def report_text():
    """The report view's text ("" where none is found: report_view)."""
    view = report_view()
    return view.toPlainText() if view is not None else ""


# answer_modal's one-dialog polls (no ``keep``) not yet done, in words: pending() names them,
# so wait() returns only once each has answered its dialog or given up; a poll that found
# no dialog then cannot outlive the wait and answer a later dialog unseen (it was so from
# 046b1e9, whose wait() returns after 3 quick round trips, until the 100 ms polls were in
# pending()).
_POLLS = []


def answer_modal(button, tries=20, keep=None):
    """Answer the next modal dialog with ``button`` (else close it), polling every 100 ms;
    gives up after ``tries`` polls, before the next wait() returns (_POLLS), so it never
    answers a later one. ``keep`` (a callable): every modal dialog is answered, the polling
    going on while keep() is true (not in _POLLS: the caller ends it). Returns the list
    each dialog's (title, text) is appended to: empty if it gave up."""
    from PySide import QtCore, QtGui
    said = []
    live = f"answer_modal's poll waiting for a dialog to press {button!r}"
    if keep is None:
        _POLLS.append(live)

    def done():
        if live in _POLLS:
            _POLLS.remove(live)

    def poll(left):
        if keep is not None and not keep():
            return
        w = QtGui.QApplication.activeModalWidget()
        if w is not None:
            said.append((w.windowTitle(), w.text() if hasattr(w, "text") else ""))
            if keep is None:
                done()          # before the click: the dialog's own loop runs it
            for b in w.findChildren(QtGui.QAbstractButton):
                if b.text().replace("&", "") == button:
                    b.click()
                    break
            else:
                w.reject()
            if keep is None:
                return
        if left or keep is not None:
            QtCore.QTimer.singleShot(100, lambda: poll(left - 1))
        else:
            done()              # gave up: ``said`` stays empty, for the caller to check
    QtCore.QTimer.singleShot(100, lambda: poll(tries))
    return said


def check_no_stray_answer():
    """A poll that found no dialog must not answer a later one: answer_modal('Yes') with
    nothing to answer, wait(), then a Yes/No box that answer_modal('No') answers. Fails the
    smoke (no 'ok' line: the smoke's count stays) where the first poll outlived the wait and
    pressed Yes (seen so on 046b1e9's wait)."""
    from PySide import QtGui
    stray = answer_modal("Yes", tries=5)
    wait()
    box = QtGui.QMessageBox(QtGui.QMessageBox.Question, "Elastica smoke", "A later dialog",
                            QtGui.QMessageBox.Yes | QtGui.QMessageBox.No)
    meant = answer_modal("No")
    got = box.exec_()
    wait()
    if stray or not meant or got != QtGui.QMessageBox.No or _POLLS:
        check(False, "answer_modal: a poll that found no dialog outlived wait() and answered "
              f"a later one (stray {stray}, meant {meant}, box answered {got}, live {_POLLS})")


def run_on(doc, command, picks):
    """Select picks ([(object, subelement or "")]) and run command; the number of
    document objects before."""
    select(doc, picks)
    n0 = len(doc.Objects)
    Gui.runCommand(command)
    pump()
    return n0


def open_panel(doc, command, picks, what):
    """run_on, then check that one feature was made and its panel opened; the panel."""
    from freecad.elastica import commands as C, taskpanels as T
    del C.MESSAGES[:]
    n0 = run_on(doc, command, picks)
    check(len(doc.Objects) == n0 + 1 and T.CURRENT,
          f"{what} creates a feature and opens its panel {C.MESSAGES}")
    return T.CURRENT[0]


def double_click(obj):
    """What a double-click in the tree does; the panel that opened."""
    from freecad.elastica import taskpanels as T
    obj.ViewObject.Proxy.doubleClicked(obj.ViewObject)
    pump()
    return T.CURRENT[0] if T.CURRENT else None


def undo_during_edit(doc, obj, field, prop, first, second, what):
    """The user's sequence: the feature's edit panel open (double-click), ``first``
    typed into the panel's ``field``, Edit > Undo (Std_Undo: active during a task dialog
    in FreeCAD 0.20) with the panel still open, ``second`` typed, Cancel. The undo took
    the panel's transaction back but left the panel open on the first value: the second
    escaped every transaction and Cancel kept it, nothing left to undo it with. Undo now
    closes the panel (as it does a new feature's), the document as before the edit; the
    user's next edit opens the panel again and its Cancel reverts it. Screenshot
    gui_<what>_undo.png: the state after the undo."""
    from freecad.elastica import taskpanels as T

    def state():
        v = getattr(obj, prop)
        shape = [(round(e.Length, 9), getattr(e.Curve, "NbPoles", 0)) for e in obj.Shape.Edges]
        return (getattr(v, "Value", v), shape, list(doc.UndoNames), doc.UndoCount,
                doc.HasPendingTransaction)

    before = state()
    panel = double_click(obj)
    type_into(getattr(panel, field), first)
    wait()
    previewed = state()
    check(previewed[0] != before[0] and previewed[1] != before[1] and doc.HasPendingTransaction
          and doc.UndoNames[0] == f"Edit {obj.Label}",
          f"{what} edit: {prop} {first} previewed in the panel's transaction ({previewed} vs "
          f"{before}; {obj.Status})")
    Gui.runCommand("Std_Undo")
    wait()
    screenshot(f"gui_{what}_undo.png")
    closed = not T.CURRENT and not Gui.Control.activeDialog() and \
        Gui.ActiveDocument.getInEdit() is None
    undone = state()
    panel = T.CURRENT[0] if T.CURRENT else double_click(obj)    # the user carries on
    type_into(getattr(panel, field), second)
    wait()
    held = doc.HasPendingTransaction and state()[0] != before[0]
    panel.reject()
    pump()
    check(state() == before and not T.CURRENT and not Gui.Control.activeDialog(),
          f"{what}: Undo during an edit, an edit, Cancel: the document as before the edit "
          f"({state()} vs {before})")
    check(closed and undone == before,
          f"{what}: Undo during an edit closes the panel, the document as before the edit "
          f"({undone})")
    check(held, f"{what}: the edit after the Undo is in a transaction (Cancel reverts it)")


def double_click_during_edit(doc, obj, field, prop, value, what):
    """A second double-click on the feature whose panel is open (the tree's): the panel
    stays, with its edit and its transaction, and Cancel reverts them. FreeCAD's setEdit
    ended the edit first (unsetEdit closed the dialog without OK or Cancel) and a new
    panel opened: the first one's transaction stayed pending, its observer kept, and
    Cancel reverted only what came after."""
    from freecad.elastica import taskpanels as T
    before = (getattr(getattr(obj, prop), "Value", getattr(obj, prop)), list(doc.UndoNames))
    panel = double_click(obj)
    type_into(getattr(panel, field), value)
    wait()
    again = double_click(obj)
    check(again is panel and Gui.Control.activeDialog() and doc.HasPendingTransaction,
          f"{what}: a second double-click keeps the open panel and its transaction")
    panel.reject()
    pump()
    after = (getattr(getattr(obj, prop), "Value", getattr(obj, prop)), list(doc.UndoNames))
    check(after == before and not T.CURRENT and not doc.HasPendingTransaction,
          f"{what}: Cancel after a second double-click reverts the edit ({after} vs {before})")


# ------------------------------------------------------------------ the demo

def demo_document():
    from freecad.elastica import viewproviders as V
    check(os.path.isfile(DEMO), f"demo document {DEMO} exists (made headless)")
    doc = App.openDocument(DEMO)
    pump(20)
    feats = [o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "kind", "")]
    check(len(feats) >= 5 and all(isinstance(o.ViewObject.Proxy, V.ViewProvider) for o in feats),
          f"demo: all {len(feats)} Elastica features got their view providers")
    names = [V.colour_name(o) for o in feats if o.Proxy.kind != "Comb"]
    check(all(names) and len(set(names)) == len(names),
          f"demo: each fit / curve has a colour of its own ({names})")
    check(all(V.colour_name(o) in o.Label for o in feats if o.Proxy.kind != "Comb"),
          "demo: the labels name the colours (legend in the tree)")
    comb = next(o for o in feats if o.Proxy.kind == "Comb")
    check(comb.ViewObject.LineColor[1] > comb.Source[0].ViewObject.LineColor[1],
          "demo: the comb is a lighter shade of its fit's colour")
    pts = next(o for o in doc.Objects if o.isDerivedFrom("Points::Feature"))
    sketch = next(o for o in doc.Objects if o.isDerivedFrom("Sketcher::SketchObject"))
    check(pts.ViewObject.Visibility and pts.ViewObject.PointSize >= 4,
          "demo: the scan points are visible as points")
    check(sketch.ViewObject.Visibility, "demo: the keyline B-spline sketch is visible")
    fit = next(o for o in feats if o.Proxy.kind == "Fit" and o.ViewObject.Visibility)
    check(len(fit.DataPoints) > 50 and fit.ViewObject.ShowData,
          f"demo: the fit shows its {len(fit.DataPoints)} fitted points")
    view = Gui.ActiveDocument.ActiveView
    view.setCameraOrientation(fit.Plane.Rotation)
    view.fitAll()
    path = screenshot("gui_demo.png")
    frac, ncol = drawn(path, view_region())
    check(frac > 0.005 and ncol >= 4, f"demo screenshot {path}: {100 * frac:.2f}% drawn, "
                                      f"{ncol} colours")
    panel = double_click(fit)
    check(panel is not None and panel.obj is fit, "demo: double-click opens the fit's panel")
    rms = fit.Rms
    panel.reject()
    pump()
    check(fit.Rms == rms and fit.Name in [o.Name for o in doc.Objects],
          "demo: Cancel leaves the fit as it was")
    App.closeDocument(doc.Name)


def run():
    import elastica_samples as S
    Gui.getMainWindow().showMaximized()
    Gui.activateWorkbench("ElasticaWorkbench")
    pump()
    check(Gui.activeWorkbench().name() == "ElasticaWorkbench", "workbench activates")
    check_no_stray_answer()
    cmds = Gui.listCommands()
    for c in ("Elastica_Fit", "Elastica_FitCsv", "Elastica_Blend", "Elastica_Spline",
              "Elastica_EllipticBlend", "Elastica_G2Quad", "Elastica_Comb"):
        check(c in cmds, f"command {c} registered")
    from freecad.elastica import preferences as P
    demo_document()

    # each tool's panel in one document, in this order: the comb is made on the blend, the
    # G2 quadratic from the fit's keyline sketch (one module per tool: gui_smoke_*.py)
    import gui_smoke_blend
    import gui_smoke_spline
    import gui_smoke_fit
    import gui_smoke_tools
    me = sys.modules[__name__]
    doc = S.new_doc("ElasticaSmoke")
    blend = gui_smoke_blend.run_all(me, doc, S)
    gui_smoke_spline.run_all(me, doc, S)
    ksk = gui_smoke_fit.run_all(me, doc, S)
    gui_smoke_tools.run_all(me, doc, S, ksk, blend)

    # empty selection: the commands are greyed out (gui_fc_behaviour: a wrong selection)
    Gui.Selection.clearSelection()
    pump()
    check(not any(Gui.Command.get(c).isActive() for c in (
        "Elastica_Fit", "Elastica_Blend", "Elastica_Comb", "Elastica_EllipticBlend",
        "Elastica_G2Quad", "Elastica_Spline")), "empty selection: the commands are greyed out")

    # the preference page, and its icon
    from freecad.elastica import defaults
    icon = Gui.getIcon("preferences-elastica")
    check(icon is not None and not icon.isNull(), "preference page icon found")
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

    # the commands were recorded (Gui.doCommand): they show in the Python console
    from PySide import QtGui
    consoles = [w for w in Gui.getMainWindow().findChildren(QtGui.QPlainTextEdit)
                if "elastica_blend.make" in w.toPlainText()]
    check(bool(consoles), "commands recorded in the Python console")

    # the whole session's 3D view is drawn
    Gui.Selection.clearSelection()
    view = Gui.ActiveDocument.ActiveView
    view.viewIsometric()
    view.fitAll()
    screenshot("gui_smoke.png")
    pump(20)
    path = os.path.join(OUT, "gui_view.png")            # the 3D view alone
    view.saveImage(path, 800, 600, "Current")
    frac, ncol = drawn(path)
    empty = App.newDocument("ElasticaEmpty")
    pump(10)
    blank = os.path.join(OUT, "gui_view_empty.png")
    Gui.getDocument(empty.Name).ActiveView.saveImage(blank, 800, 600, "Current")
    efrac, _ = drawn(blank)
    check(efrac < 0.002, f"an empty view is judged blank ({100 * efrac:.3f}% drawn)")
    App.closeDocument(empty.Name)
    check(frac > 0.003 and ncol >= 3, f"screenshot {path}: {100 * frac:.2f}% drawn, "
                                      f"{ncol} colours")

    # a panel open while the user deletes, closes the document, or asks to keep nothing
    import gui_panel_lifecycle
    gui_panel_lifecycle.run_all(sys.modules[__name__])

    # the blend's picked ends, new ends without a free batten, a bound field, unit schemas
    import gui_blend_panel
    gui_blend_panel.run_all(sys.modules[__name__])

    # the spline's and the fit's edge buttons read where the edge was clicked
    import gui_edge_clicks
    gui_edge_clicks.run_all(sys.modules[__name__])

    # texts in the unit schema: the elliptic blend's loop sizes
    import gui_schema_texts
    gui_schema_texts.run_all(sys.modules[__name__])

    # the panels' numbers at FreeCAD's Decimals preference (2 and 6), the property view's
    import gui_decimals
    gui_decimals.run_all(sys.modules[__name__])

    # typing, wrong selections, the Model box, a sketch double-clicked: as FreeCAD's own
    import gui_fc_behaviour
    gui_fc_behaviour.run_all(sys.modules[__name__])

    # a panel's OK records the properties its edit changed: replayed, the same blend
    import gui_recording
    gui_recording.run_all(sys.modules[__name__])

    # a bound field's f(x) mark opens the expression editor; a fit in a placed Part drawn on
    # its points
    import gui_part_marks
    gui_part_marks.run_all(sys.modules[__name__])

    # a wrong unit typed in a box is marked and refused by OK; the fit's own edge named so
    import gui_typed_units
    gui_typed_units.run_all(sys.modules[__name__])

    # '=' in a box opens FreeCAD's expression editor and binds; '1/0' never reaches the feature
    import gui_typed_expressions
    gui_typed_expressions.run_all(sys.modules[__name__])

    # an open panel follows its feature's recompute (a cell it is bound to changed)
    import gui_bound_follow
    gui_bound_follow.run_all(sys.modules[__name__])

    # a document saved by an older build with a feature out of date opens recomputed
    import gui_reopen_old
    gui_reopen_old.run_all(sys.modules[__name__])


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
