"""The Elastica task panels through what else a user does while one is open, checked
by the GUI smoke test (gui_smoke.py calls run_all): FreeCAD's own panels
(Part_Offset2D's) are the model (QA defects of 0.20):

- File > Close (Discard) with a panel open closes the panel (it stayed on the Start
  page, its Cancel and OK raising ReferenceError on the deleted document);
- a new feature's panel clears the command's selection and puts the feature in edit,
  so Delete deletes nothing (it deleted the source sketch under the new feature);
- Delete during an edit commits the panel's transaction (every command that opens one
  does): Cancel still reverts the edit (it kept it);
- 'Keep the parametric feature' cannot be unchecked without a Copy into sketch (OK
  kept nothing and left an Undo step that did nothing);
- Cancel on the panel of a feature in error leaves the Undo stack as it was (it left
  an 'Edit <Label>' step that undid nothing).
- OK whose Copy into cannot finish (its sketch removed by a macro, a write failing half
  way) keeps the panel open with why on its error line, the sketch as before and no Undo
  step (FreeCAD's TaskDialogPython closed it on the exception, its transaction pending);
  so does OK whose recompute fails (a source broken since by a macro line): no copy made.

Screenshots: gui_close_with_panel.png (the task view empty after the close),
gui_delete_during_panel.png, gui_keep_needs_copy.png (the Keep box disabled),
gui_failed_blend_panel.png (a failed blend's panel: its error), gui_ok_fails_gone.png (OK's
failed copy said on the error line), gui_ok_unsolved.png."""
import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide import QtGui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, type_into, double_click)


def task_buttons():
    return [b.text().replace("&", "") for bb in Gui.getMainWindow().findChildren(QtGui.QDialogButtonBox)
            if bb.isVisible() for b in bb.buttons()]


def fit_doc(name):
    doc = S.new_doc(name)
    sk = S.points_sketch(doc, S.keyline_xy(14)[0], "Points")
    Gui.SendMsgToActiveView("ViewFit")
    return doc, sk


def run_fit(doc, sk):
    from freecad.elastica import taskpanels as T
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, sk.Name)
    Gui.runCommand("Elastica_Fit")
    G.wait()
    return T.CURRENT[0] if T.CURRENT else None


def close_with_panel(edit):
    """File > Close, Discard, with a new feature's panel (edit False) or an edit's open."""
    from freecad.elastica import taskpanels as T
    what = "an edit panel" if edit else "a new feature's panel"
    doc, sk = fit_doc("ElasticaClose")
    panel = run_fit(doc, sk)
    if edit:
        panel.accept()
        G.pump()
        panel = G.double_click(doc.getObject("ElasticaFit"))
    G.type_into(panel.step, "3")
    G.wait()
    G.check(panel is not None and Gui.Control.activeDialog(), f"close with {what}: panel open")
    name = doc.Name
    said = G.answer_modal("Discard")
    Gui.runCommand("Std_CloseActiveWindow")
    G.wait()
    if edit:
        G.screenshot("gui_close_with_panel.png")
    G.check(said and name not in App.listDocuments() and not T.CURRENT
            and not Gui.Control.activeDialog() and not task_buttons(),
            f"File > Close (Discard) with {what} open closes the panel ({said}, dialog "
            f"{Gui.Control.activeDialog()}, buttons {task_buttons()})")
    G.check(panel.gone and panel.reject() is True and panel.accept() is True,
            f"close with {what}: its Cancel or OK afterwards raises nothing")


def delete_during_new_panel():
    from freecad.elastica import taskpanels as T
    doc, sk = fit_doc("ElasticaDeleteNew")
    undo0 = list(doc.UndoNames)
    panel = run_fit(doc, sk)
    G.check(not Gui.Selection.getSelectionEx() and Gui.ActiveDocument.getInEdit() is not None,
            "a new feature's panel clears the selection and puts the feature in edit "
            f"({[s.ObjectName for s in Gui.Selection.getSelectionEx()]})")
    Gui.Selection.addSelection(doc.Name, sk.Name)
    said = G.answer_modal("Yes", tries=5)
    Gui.runCommand("Std_Delete")
    G.wait()
    G.screenshot("gui_delete_during_panel.png")
    names = [o.Name for o in doc.Objects]
    G.check(names == ["Points", "ElasticaFit"] and T.CURRENT and T.CURRENT[0] is panel,
            f"Delete during a new feature's panel deletes nothing ({names}, {said})")
    panel.reject()
    G.pump()
    names = [o.Name for o in doc.Objects]
    G.check(names == ["Points"] and list(doc.UndoNames) == undo0 and not T.CURRENT,
            f"Cancel after Delete removes the new feature, nothing else ({names}, "
            f"{doc.UndoNames})")
    App.closeDocument(doc.Name)


def delete_during_edit():
    from freecad.elastica import taskpanels as T
    doc, sk = fit_doc("ElasticaDeleteEdit")
    run_fit(doc, sk).accept()
    G.pump()
    fit = doc.getObject("ElasticaFit")
    undo0, shape0 = list(doc.UndoNames), round(fit.Shape.Length, 9)
    panel = G.double_click(fit)
    G.type_into(panel.step, "4")
    G.wait()
    Gui.Selection.clearSelection()
    Gui.Selection.addSelection(doc.Name, sk.Name)
    said = G.answer_modal("Yes", tries=5)
    Gui.runCommand("Std_Delete")
    G.wait()
    # (FreeCAD 0.20 asks nothing here, said is []: the poll gives up before wait() returns,
    # gui_smoke._POLLS, so it cannot answer the dialog of an edit below)
    G.check([o.Name for o in doc.Objects] == ["Points", "ElasticaFit"] and T.CURRENT,
            f"Delete during an edit deletes nothing ({said})")
    model0 = fit.Model
    panel.model.setCurrentIndex(1 - panel.model.currentIndex())   # an edit after its commit
    G.wait()
    panel.reject()
    G.pump()
    G.check(fit.ResampleStep.Value == 0 and fit.Model == model0 and
            round(fit.Shape.Length, 9) == shape0 and list(doc.UndoNames) == undo0,
            f"Cancel after Delete during an edit reverts the edit (step {fit.ResampleStep}, "
            f"model {fit.Model}, undo {doc.UndoNames})")
    App.closeDocument(doc.Name)


def keep_needs_a_copy():
    doc, sk = fit_doc("ElasticaKeep")
    panel = run_fit(doc, sk)
    areas = [a for a in Gui.getMainWindow().findChildren(QtGui.QScrollArea)
             if a.isVisible() and a.widget() is not None and a.isAncestorOf(panel.form[0])]
    if areas:
        areas[0].ensureWidgetVisible(panel.sketch)
    G.check(panel.sketch.currentIndex() == 0 and not panel.keep.isEnabled(),
            "Keep the parametric feature is disabled while Copy into is '(no copy)'")
    G.screenshot("gui_keep_needs_copy.png")
    panel.keep.setChecked(False)
    G.check(panel.keep.isChecked(), "Keep cannot be unchecked without a copy")
    panel.sketch.setCurrentIndex(panel.sketch.findData("*new*"))
    G.check(panel.keep.isEnabled(), "Keep is enabled once a sketch is chosen to copy into")
    panel.keep.setChecked(False)
    panel.sketch.setCurrentIndex(0)
    G.check(panel.keep.isChecked() and not panel.keep.isEnabled(),
            "Copy into back at '(no copy)' checks Keep again")
    panel.accept()
    G.pump()
    G.check(doc.getObject("ElasticaFit") is not None and list(doc.UndoNames) == ["Fit elastica"],
            "OK without a copy keeps the feature")
    App.closeDocument(doc.Name)


def cancel_on_failed_feature():
    """Cancel, touching nothing, on the panel of a healthy blend and of one a sketch edit
    broke: the Undo stack as before, and the user's one Undo reverts that edit. The failed
    blend's recompute after the abort left an 'Edit <Label>' step that undid nothing
    visible (QA16 F3: FreeCAD keeps an untouched transaction's name pending)."""
    from freecad.elastica import blend as B
    doc = S.new_doc("ElasticaCancelFailed")
    sk = S.two_lines_sketch(doc)
    doc.openTransaction("Elastic blend")
    b = B.make(doc, (sk, "Edge1"), (sk, "Edge2"))
    doc.commitTransaction()
    doc.recompute()
    Gui.SendMsgToActiveView("ViewFit")
    undo0 = list(doc.UndoNames)
    G.double_click(b).reject()
    G.pump()
    status0 = b.Status
    G.check(not status0.startswith("error") and list(doc.UndoNames) == undo0,
            f"Cancel on a healthy blend's panel leaves the Undo stack ({doc.UndoNames})")
    doc.openTransaction("Move line")
    sk.movePoint(1, 1, App.Vector(40, 0, 0))      # onto the first line's end: no blend
    doc.commitTransaction()
    doc.recompute()
    undo1 = list(doc.UndoNames)
    panel = G.double_click(b)
    G.wait()
    G.screenshot("gui_failed_blend_panel.png")
    failed = b.Status.startswith("error") and "coincide" in G.error_line(panel)
    panel.reject()
    G.pump()
    G.check(failed and list(doc.UndoNames) == undo1 == ["Move line"] + undo0
            and not doc.HasPendingTransaction and App.getActiveTransaction() is None,
            f"Cancel on a failed blend's panel leaves the Undo stack ({doc.UndoNames} vs "
            f"{undo1}; {b.Status[:60]})")
    Gui.runCommand("Std_Undo")
    G.pump()
    doc.recompute()
    start = sk.getPoint(1, 1)
    G.check(b.Status == status0 and (start - App.Vector(80, 25, 0)).Length < 1e-9
            and list(doc.UndoNames) == undo0,
            f"then one Undo reverts the sketch edit (blend {b.Status[:40]}, line from {start})")
    App.closeDocument(doc.Name)


def click_ok():
    """OK clicked in the task view: FreeCAD's TaskDialogPython calls the panel's accept
    (and reports an exception out of it, closing the dialog as if accepted)."""
    for bb in Gui.getMainWindow().findChildren(QtGui.QDialogButtonBox):
        ok = bb.button(QtGui.QDialogButtonBox.Ok)
        if bb.isVisible() and ok is not None:
            ok.click()
            return True
    return False


def _panel_into_gone(name):
    """A Fit panel (Resample 3) on a new document ``name`` with sketches Gone and Prof (one
    line), Copy into Gone chosen, then Gone removed by a macro's line: (doc, the points'
    sketch, Prof, the Undo names and Prof's geometry count before the panel, the panel)."""
    doc, sk = fit_doc(name)
    for name in ("Gone", "Prof"):
        o = doc.addObject("Sketcher::SketchObject", name)
        o.Placement = sk.Placement
    doc.recompute()
    prof = doc.getObject("Prof")
    prof.addGeometry(Part.LineSegment(App.Vector(0, 0, 0), App.Vector(50, 0, 0)), False)
    doc.recompute()
    undo0, geo0 = list(doc.UndoNames), len(prof.Geometry)
    panel = run_fit(doc, sk)
    G.type_into(panel.step, "3")
    G.wait()
    panel.sketch.setCurrentIndex(panel.sketch.findData("Gone"))
    Gui.doCommand(f"App.getDocument({doc.Name!r}).removeObject('Gone')")   # a macro's line
    G.pump()
    return doc, sk, prof, undo0, geo0, panel


def ok_that_fails():
    """OK whose Copy into cannot finish: the target sketch removed by a macro line (no
    recompute: still offered), then a write that fails half way (a line added, then the
    Sketcher's ValueError). The panel stays open on its edit with why on its error line
    and in the report view, the sketch as before, no Undo step; Cancel leaves the Undo stack
    as before the panel; OK into a sketch that takes it is one Undo step (revC 3: the
    exception closed the panel through TaskDialogPython, its transaction neither committed
    nor aborted, the sketch as the exception left it)."""
    from freecad.elastica import geometry as Ge, taskpanels as T
    doc, sk, prof, undo0, geo0, panel = _panel_into_gone("ElasticaOkFails")
    clicked = click_ok()
    G.pump()
    G.screenshot("gui_ok_fails_gone.png")
    still = bool(T.CURRENT) and T.CURRENT[0] is panel and Gui.Control.activeDialog()
    said = G.error_line(panel) if still else ""
    G.check(clicked and still and "Copy into Gone failed" in said
            and "no longer in the document" in said
            and "Copy into Gone failed" in G.report_text() and doc.HasPendingTransaction
            and list(doc.UndoNames)[1:] == undo0,
            f"OK into a sketch removed since: the panel stays open, why said ({said!r}; "
            f"undo {doc.UndoNames})")
    real = Ge.write_to_sketch

    def half(feature, sketch, constrain_to=None):
        sketch.addGeometry(Part.LineSegment(App.Vector(0, 5, 0), App.Vector(9, 5, 0)), False)
        raise ValueError("Sketcher refused a constraint")
    Ge.write_to_sketch = half
    try:
        panel.sketch.setCurrentIndex(panel.sketch.findData("Prof"))
        G.check(not G.error_line(panel), "another sketch chosen: the error line clears")
        click_ok()
        G.pump()
    finally:
        Ge.write_to_sketch = real
    still = bool(T.CURRENT) and T.CURRENT[0] is panel
    G.check(still and len(prof.Geometry) == geo0 and "Copy into Prof failed" in
            G.error_line(panel)
            and "SketchCopies" not in doc.getObject("ElasticaFit").PropertiesList,
            f"a write that fails half way: the sketch as before ({len(prof.Geometry)} geometries, "
            f"was {geo0}), the panel open")
    panel.reject()
    G.pump()
    G.check(not T.CURRENT and list(doc.UndoNames) == undo0 and not doc.HasPendingTransaction
            and doc.getObject("ElasticaFit") is None and len(prof.Geometry) == geo0,
            f"then Cancel: the Undo stack as before the panel ({doc.UndoNames} vs {undo0})")
    panel = run_fit(doc, sk)
    panel.sketch.setCurrentIndex(panel.sketch.findData("Prof"))
    click_ok()
    G.pump()
    G.check(not T.CURRENT and list(doc.UndoNames) == ["Fit elastica"] + undo0
            and len(prof.Geometry) == geo0 + 1,
            f"OK into a sketch that takes the copy: one Undo step ({doc.UndoNames}), "
            f"{len(prof.Geometry)} geometries")
    App.closeDocument(doc.Name)


def ok_fails_then_ok():
    """OK into a sketch a macro line removed fails, then OK in the SAME panel into a sketch
    that takes the copy (review revB 6: the test above cancels in between): the panel
    closes, one Undo step 'Fit elastica'; Undo takes all of it back: the fit removed, the
    target sketch as before, and the removed sketch (the macro's line ran in the panel's
    transaction) back; Redo does it again."""
    from freecad.elastica import taskpanels as T
    doc, sk, prof, undo0, geo0, panel = _panel_into_gone("ElasticaOkThenOk")
    recorded, do = [], Gui.doCommand
    Gui.doCommand = lambda code: recorded.append(code) or do(code)
    try:
        click_ok()
        G.pump()
    finally:
        Gui.doCommand = do
    # revB 2: the failed OK's lines stayed in the console and a recorded macro, whose
    # replay stopped at getObject('Gone')
    G.check(not recorded, f"the OK into a sketch gone records no line: {recorded}")
    said = G.error_line(panel) if T.CURRENT and T.CURRENT[0] is panel else ""
    G.check("Copy into Gone failed, nothing was written: that sketch is no longer" in said
            and said.endswith("Choose another sketch, or Cancel"),
            f"the first OK fails, the panel open, why said ({said!r})")
    panel.sketch.setCurrentIndex(panel.sketch.findData("Prof"))
    click_ok()
    G.pump()
    G.screenshot("gui_ok_fails_then_ok.png")
    fit = doc.getObject("ElasticaFit")
    G.check(not T.CURRENT and list(doc.UndoNames) == ["Fit elastica"] + undo0
            and len(prof.Geometry) == geo0 + 1 and fit is not None
            and [e.split()[0] for e in fit.SketchCopies] == ["Prof"],
            f"then OK into Prof in the same panel: closed, one Undo step ({doc.UndoNames}), "
            f"{len(prof.Geometry)} geometries")
    doc.undo()
    G.pump()
    G.check(doc.getObject("ElasticaFit") is None and len(prof.Geometry) == geo0
            and doc.getObject("Gone") is not None and list(doc.UndoNames) == undo0,
            f"Undo: the fit removed, Prof as before ({len(prof.Geometry)}), 'Gone' back "
            f"({doc.getObject('Gone')}), undo {doc.UndoNames}")
    doc.redo()
    G.pump()
    fit = doc.getObject("ElasticaFit")
    G.check(fit is not None and len(prof.Geometry) == geo0 + 1
            and doc.getObject("Gone") is None,
            f"Redo: the fit and its copy again ({len(prof.Geometry)} geometries)")
    App.closeDocument(doc.Name)


def ok_on_a_source_broken_since():
    """OK with Copy into after a macro line left the points' sketch with 2 points (no
    recompute: the preview still shows the fit): OK's recompute fails, so the panel stays
    open with why on its error line, nothing copied, no Undo step (revB: the copy was made
    from the shape of before, the fit committed Invalid and the panel closed)."""
    from freecad.elastica import taskpanels as T
    doc, sk = fit_doc("ElasticaOkUnsolved")
    prof = doc.addObject("Sketcher::SketchObject", "Prof")
    prof.Placement = sk.Placement
    doc.recompute()
    undo0 = list(doc.UndoNames)
    panel = run_fit(doc, sk)
    panel.sketch.setCurrentIndex(panel.sketch.findData("Prof"))
    Gui.doCommand(f"_s = App.getDocument({doc.Name!r}).getObject({sk.Name!r})\n"
                  "_s.delGeometries(list(range(2, len(_s.Geometry))))")
    G.pump()
    before = len(G.report_text())
    click_ok()
    G.pump()
    G.screenshot("gui_ok_unsolved.png")
    still = bool(T.CURRENT) and T.CURRENT[0] is panel and Gui.Control.activeDialog()
    said = G.error_line(panel) if still else ""
    f = doc.getObject("ElasticaFit")
    G.check(still and "recompute failed" in said and "2 points" in said
            and not prof.Geometry and f is not None and "SketchCopies" not in f.PropertiesList
            and "Traceback" not in G.report_text()[before:],
            f"OK on a source broken since: the panel stays open, nothing copied ({said!r}, "
            f"{len(prof.Geometry)} geometries in Prof)")
    panel.reject()
    G.pump()
    G.check(not T.CURRENT and list(doc.UndoNames) == undo0 and len(sk.Geometry) == 14,
            f"then Cancel: the Undo stack and the points as before ({doc.UndoNames})")
    App.closeDocument(doc.Name)


class _Stderr:
    """sys.stderr's text while active (a Traceback of a queued Qt call goes there, and so
    to the report view)."""

    def __enter__(self):
        import sys
        self.text, self.saved = [], sys.stderr
        outer = self

        class _Tee:
            def write(self, t):
                outer.text.append(t)
                return outer.saved.write(t)

            def flush(self):
                outer.saved.flush()
        sys.stderr = _Tee()
        return self

    def __exit__(self, *exc):
        import sys
        sys.stderr = self.saved


def dropped_by_close_dialog():
    """Gui.Control.closeDialog() (a macro, the console) closes a new Fit's panel without
    OK or Cancel: the panel lets go of the document (its observer, CURRENT, the edit), the
    feature kept, said once; a recompute after it printed a Traceback (show_error on a
    deleted QLabel: the observer stayed, revR)."""
    from freecad.elastica import taskpanels as T
    doc, sk = fit_doc("ElasticaDropped")
    panel = run_fit(doc, sk)
    G.check(panel is not None, "a Fit's panel opens")
    warned, saved = [], App.Console.PrintWarning
    App.Console.PrintWarning = lambda text: warned.append(text)
    try:
        with _Stderr() as err:
            Gui.Control.closeDialog()
            G.wait()
            g = sk.Geometry[3]
            sk.movePoint(3, 1, App.Vector(g.X + 1.0, g.Y, 0))
            doc.recompute()
            G.wait()
    finally:
        App.Console.PrintWarning = saved
    G.screenshot("gui_dropped_panel.png")
    names = [o.Name for o in doc.Objects]
    said = [t for t in warned if "without OK or Cancel" in t]
    G.check("Traceback" not in "".join(err.text) and not T.CURRENT and
            Gui.ActiveDocument.getInEdit() is None and names == ["Points", "ElasticaFit"] and
            len(said) == 1 and not doc.HasPendingTransaction,
            f"a panel closed by closeDialog lets go: no Traceback at the next recompute "
            f"({''.join(err.text)[-300:]!r}), not current ({T.CURRENT}), not in edit, the "
            f"feature kept ({names}), said once ({said})")
    App.closeDocument(doc.Name)


def run_all(smoke):
    global G
    G = smoke
    dropped_by_close_dialog()
    ok_that_fails()
    ok_fails_then_ok()
    ok_on_a_source_broken_since()
    cancel_on_failed_feature()
    delete_during_new_panel()
    delete_during_edit()
    keep_needs_a_copy()
    close_with_panel(edit=False)
    close_with_panel(edit=True)
