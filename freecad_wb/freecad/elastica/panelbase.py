"""The machinery of the Elastica task panels, modelled on FreeCAD's own Part and
Sketcher panels: ``Panel`` (fields bound live to a feature's properties, the
delayed recompute, enabled fields, result text, the view kept on the feature, OK
and Cancel through the document's undo transaction); its spin boxes are in
spinboxes.py, its fields bound to expressions (the f(x) mark) in panelexpressions.py, its
document observer in panelwatch.py, the panels of the features in taskpanels.py."""
from __future__ import annotations

import FreeCAD as App
import FreeCADGui as Gui
import Part
from PySide import QtCore, QtGui

from . import icon
from .containers import CONTAINERS
from .geometry import global_shape, is_sketch, sketch_curves
from .okcopy import Attempt, Unsolved, copy_code
from .panelexpressions import ExpressionFields
from .panelwatch import Watch
from .proxy import (EDGE_ENDS, InputProblem, abort_transaction, note_changes, note_values,
                    save_note, saved_note, said as proxy_said)
from .recording import edit_lines, edit_state
from .spinboxes import BAD_RGB, TYPING_MS, DecadeBox, IntBox, NumberBox
from .units import length_text, number_text, say, unit_names

CURRENT = []        # the open panel, if any (scripts and the GUI smoke test drive it)
DELAY_MS = 150      # recompute after this pause in editing (arrows, wheel, choices)
WARNING_RGB = "#b36200"   # the amber of FreeCAD's report-view warnings, dark enough to read
ERROR_RGB = BAD_RGB


def said_now(obj, prop):
    """A feature's text property as its panel says it (proxy.said): in the schema of now,
    a measured length at rounding noise as 0 (the property and the report view keep it)."""
    return proxy_said(obj, prop, figures=True)


def _sketches(doc, exclude=()):
    return [o for o in doc.Objects if is_sketch(o) and o.Name not in exclude]


def _narrow(box):
    """A combo box that may be narrower than its longest entry (the 260 px Combo View)."""
    box.setSizeAdjustPolicy(QtGui.QComboBox.AdjustToMinimumContentsLengthWithIcon)
    box.setMinimumContentsLength(8)
    return box


def _buttons(*names):
    flags = QtGui.QDialogButtonBox.NoButton
    for n in names:
        flags |= getattr(QtGui.QDialogButtonBox, n)
    try:
        return int(flags)
    except TypeError:          # PySide6 enums: the flag value
        return flags.value


class Panel(ExpressionFields):
    """Shared machinery: bound fields, the delayed recompute, result text, the undo
    transaction. Subclasses build their boxes in ``build`` and return the result
    text of a successful recompute from ``result_text``."""

    title = ""
    icon_name = "elastica"
    gone = ""           # why the panel lost its feature or its transaction (``lost``)
    error = None        # the error line at the top of the first box (``box``)
    _note, _note_for = "", None

    @property
    def note(self):
        """Why the command (or the panel) chose the values it did: the warning line's first
        sentence, saved with the feature (proxy.save_note, in the panel's transaction) with
        the values it explains, and said while they hold, as by a panel opened later (a
        length typed over the one it named left it naming the old one)."""
        return self._note if note_values(self.obj) == self._note_for else ""

    @note.setter
    def note(self, text):
        self._note, self._note_for = text, note_values(self.obj)
        if not self.gone and note_changes(self.obj, text):
            self.hold()
            save_note(self.obj, text)

    def __init__(self, obj, created=True, note=""):
        self.obj = obj
        self.opened_with = edit_state(obj)      # OK records what the edit changed
        self.previewed = self.opened_with       # what the feature shows was solved from
        self.previewed_touched = True           # (not known before its first preview)
        # why the command chose what it did (warning line): given by the command, or saved
        # with the feature while its values hold (proxy.save_note)
        self._note, self._note_for = note or saved_note(obj), note_values(obj)
        self.doc = obj.Document
        self.name, self.doc_name = obj.Name, obj.Document.Name
        self.watch = Watch(self)
        App.addDocumentObserver(self.watch)
        self.created = created          # a command made it: its transaction is still open
        # the panel's transaction (the command's, or this edit's) and how many of its pieces
        # another command committed (Cancel undoes them: committed_by_other)
        self.txn = (doc_undo_top(self.doc) if created and self.doc.HasPendingTransaction
                    else "") or f"Edit {obj.Label}"
        self.orphans = 0
        self.closing = False
        self.enablers = []              # (widget, callable -> bool)
        self.numbers = []               # (label, NumberBox): their typed text (bad_input)
        self.edge_buttons = []          # (edge link property, button, text when empty)
        self.timer = QtCore.QTimer()
        self.timer.setSingleShot(True)
        self.timer.setInterval(DELAY_MS)
        self.timer.timeout.connect(self.update)
        if not created:
            self.doc.openTransaction(f"Edit {obj.Label}")
        self.result = QtGui.QLabel()
        self.result.setWordWrap(True)
        self.result.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.warning = None             # the warning line, when the panel has one
        self.form = []
        self.build()
        for w in self.form[:1]:     # its dialog closed by closeDialog (dropped)
            w.destroyed.connect(self.dropped)
        self.refresh()
        self.refit()

    # ---------------------------------------------------------------- building

    def box(self, title):
        """A new task box (a QWidget with a two-column grid) appended to the form."""
        w = QtGui.QWidget()
        w.setWindowTitle(title)
        w.setWindowIcon(QtGui.QIcon(icon(self.icon_name)))
        grid = QtGui.QGridLayout(w)
        grid.setColumnStretch(1, 1)
        if not self.form:   # a failed solve says why first, as Sketcher's solver messages
            self.error = self.message_row(grid, QtGui.QStyle.SP_MessageBoxCritical, ERROR_RGB)
        self.form.append(w)
        return grid

    @staticmethod
    def row(grid, label, widget, tip=""):
        r = grid.rowCount()
        if label:
            lab = QtGui.QLabel(label)
            lab.setToolTip(tip or widget.toolTip())
            grid.addWidget(lab, r, 0)
            grid.addWidget(widget, r, 1)
        else:
            grid.addWidget(widget, r, 0, 1, 2)
        if tip:
            widget.setToolTip(tip)
        return widget

    def warning_row(self, grid):
        """A warning line (hidden while there is nothing to say): the standard warning
        icon and amber text, as FreeCAD's dialogs and report view show warnings."""
        self.warning = self.message_row(grid, QtGui.QStyle.SP_MessageBoxWarning, WARNING_RGB)
        return self.warning[0]

    def message_row(self, grid, sign_icon, rgb):
        """A hidden row of its own: a standard icon and wrapped text in ``rgb``; (row, text)."""
        w = QtGui.QWidget()
        lay = QtGui.QHBoxLayout(w)
        lay.setContentsMargins(0, 0, 0, 0)
        sign = QtGui.QLabel()
        size = w.style().pixelMetric(QtGui.QStyle.PM_SmallIconSize)
        sign.setPixmap(w.style().standardIcon(sign_icon).pixmap(size))
        sign.setAlignment(QtCore.Qt.AlignTop)
        text = QtGui.QLabel()
        text.setWordWrap(True)
        text.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        text.setStyleSheet(f"color: {rgb}")
        lay.addWidget(sign)
        lay.addWidget(text, 1)
        self.row(grid, "", w)
        w.setVisible(False)
        return w, text

    def warnings(self):
        """What the warning line says (a list of sentences; none: hidden): the command's
        note, then the feature's Warnings, capitalised."""
        said = ([say(self.note)] if self.note else []) + (      # its marks in the schema of now
            said_now(self.obj, "Warnings") if "Warnings" in self.obj.PropertiesList else [])
        return [w[0].upper() + w[1:] for w in said]

    def number(self, grid, label, prop, lo, hi, step, unit, tip, decade=False, when=None):
        """A spin box bound live to the float property prop."""
        tip = unit_names(tip)           # '(mm)' in the tooltip: the unit the box shows
        box = (DecadeBox if decade else NumberBox)(lo, hi, step, unit, tip)
        box.blockSignals(True)
        box.setValue(float(getattr(self.obj, prop)))
        box.blockSignals(False)
        box.valueChanged.connect(lambda v: self.set(prop, float(v)))
        self.typed_in(box)
        self.watch_text(label, box)
        self.row(grid, label, box, tip)
        self.mark_bound(box, prop)
        if when:
            self.enablers.append((box, when))
        return box

    def checked_number(self, grid, text, check_prop, prop, lo, hi, step, unit, tip, when=None):
        """A check box (the boolean check_prop) beside a spin box (the float prop), which
        applies only while the box is checked: an optional value."""
        tip = unit_names(tip)
        box = QtGui.QCheckBox(text)
        box.setChecked(bool(getattr(self.obj, check_prop)))
        box.setToolTip(tip)
        box.toggled.connect(lambda v: self.set(check_prop, bool(v)))
        value = NumberBox(lo, hi, step, unit, tip)
        value.blockSignals(True)
        value.setValue(getattr(self.obj, prop))
        value.blockSignals(False)
        value.valueChanged.connect(lambda v: self.set(prop, float(v)))
        self.typed_in(value)
        self.watch_text(text, value)
        self.mark_bound(value, prop)
        r = grid.rowCount()
        grid.addWidget(box, r, 0)
        grid.addWidget(value, r, 1)
        self.enablers.append((box, when or (lambda: True)))
        self.enablers.append((value, lambda: bool(getattr(self.obj, check_prop))
                              and (when is None or when())))
        return box, value

    def integer(self, grid, label, prop, lo, hi, tip, when=None):
        """A spin box bound live to the integer property prop ('=' opens the expression
        editor on it, as FreeCAD's integer boxes: spinboxes.IntBox)."""
        box = IntBox(lo, hi)
        box.blockSignals(True)
        box.setValue(max(lo, min(hi, int(getattr(self.obj, prop)))))
        box.blockSignals(False)
        box.valueChanged.connect(lambda v: self.set(prop, int(v)))
        self.typed_in(box)
        self.row(grid, label, box, tip)
        self.mark_bound(box, prop)
        if when:
            self.enablers.append((box, when))
        return box

    _typed = False      # the value being set was typed (typed_in)

    def typed_in(self, box):
        """A spin box's typed text waits TYPING_MS (its textEdited comes just before its
        valueChanged), its arrows DELAY_MS; Enter or focus out (editingFinished: the value
        stands, as FreeCAD's boxes without keyboard tracking take it) solves now."""
        edit = box.findChild(QtGui.QLineEdit)

        def typed(_text):
            self._typed = True
            QtCore.QTimer.singleShot(0, self._typed_done)   # a text that set no value
        edit.textEdited.connect(typed)
        box.editingFinished.connect(self.flush)

    def _typed_done(self):
        self._typed = False

    _input_said = ""    # the bad text the error line says (Enter, focus out, OK)
    _ok_said = ""       # why OK could not finish (ok_failed), until the next edit

    def watch_text(self, label, box):
        """A number box whose text the panel checks: a text it cannot take ('3 deg' in a
        length box) is marked in the box as typed (NumberBox.problem) and kept past focus-out;
        Enter, leaving the box, the typing pause (NumberBox.paused) and OK say it on the error
        line, naming the field, and OK refuses it (Qt kept the value of its last good prefix,
        3 mm, and OK took it)."""
        box.keep_bad_text = True
        self.numbers.append((label, box))
        box.lineEdit().textChanged.connect(lambda _t: self._input_said and self.say_bad_input())
        box.editingFinished.connect(self.say_bad_input)
        box.paused.connect(self.say_bad_input)

    def bad_input(self):
        """'Field: why' for the first field that applies whose text it cannot take, or ''."""
        for label, box in self.numbers:
            why = box.isEnabled() and not box.isReadOnly() and box.problem()
            if why:
                return f"{label}: {why}"
        return ""

    def say_bad_input(self):
        if not self.gone:
            self._input_said = self.bad_input()
            self.show_error()

    def check(self, grid, text, prop, tip, when=None, target=None, at=None):
        """A check box bound live to the boolean property prop (of ``target``, default
        the feature; a view property when target is the ViewObject), on a row of its
        own or in the grid cell ``at`` = (row, column)."""
        target = target if target is not None else self.obj
        box = QtGui.QCheckBox(text)
        box.setChecked(bool(getattr(target, prop)))
        box.toggled.connect(lambda v: self.set(prop, bool(v), target))
        if at is None:
            self.row(grid, "", box, tip)
        else:
            box.setToolTip(tip)
            grid.addWidget(box, *at)
        if when:
            self.enablers.append((box, when))
        return box

    def choice(self, grid, label, prop, values, texts, tip, when=None, tips=()):
        """A combo box bound live to the enumeration property prop (``tips``: each item's
        tooltip, its text in full)."""
        box = _narrow(QtGui.QComboBox())
        box.addItems(list(texts))
        for i, item_tip in enumerate(tips):
            box.setItemData(i, item_tip, QtCore.Qt.ToolTipRole)
        box.setCurrentIndex(list(values).index(getattr(self.obj, prop)))
        box.currentIndexChanged.connect(lambda i: self.set(prop, values[i]))
        self.row(grid, label, box, tip)
        if when:
            self.enablers.append((box, when))
        return box

    def edge_button(self, grid, label, prop, tip, empty="free", when=None, picked=None,
                    freed=None):
        """A button bound to the edge link prop: a click with an edge selected links it,
        a click on a linked one frees it; ``picked()`` runs after a pick, ``freed()``
        after a free."""
        btn = QtGui.QPushButton()
        btn.clicked.connect(lambda _=False: self.pick_edge(prop, picked, freed))
        self.row(grid, label, btn, tip)
        if when:
            self.enablers.append((btn, when))
        self.edge_buttons.append((prop, btn, empty))
        self.show_edges()
        return btn

    def pick_edge(self, prop, picked=None, freed=None):
        """Link the selected edge to ``prop`` (free it if linked); a feature that joins an
        end of it (its ``prop + 'At'``, proxy.EDGE_ENDS) joins the end nearer where the edge
        was clicked, as the Elastic blend command does (blend.picked_end); a scripted
        selection (no click) keeps the nearest end."""
        at = prop + "At"
        if getattr(self.obj, prop):
            self.set(prop, None)
            if at in self.obj.PropertiesList:
                self.set(at, "nearest")
            if freed:
                freed()
        else:
            sel = [(s.Object, n, App.Vector(p)) for s in Gui.Selection.getSelectionEx()
                   for n, p in zip(s.SubElementNames, s.PickedPoints) if n.startswith("Edge")]
            if not sel:
                self.result.setText("<b style='color:#b00'>select an edge first</b>")
                return
            if sel[0][0] is self.obj or self.obj in sel[0][0].OutListRecursive:
                # a link to the feature's own result would be a dependency loop
                why = ("this is the feature itself" if sel[0][0] is self.obj
                       else f"{sel[0][0].Label} depends on this feature")
                self.result.setText("<b style='color:#b00'>pick an edge of another object "
                                    f"({why})</b>")
                return
            if at in self.obj.PropertiesList:
                from .blend import picked_end
                from .geometry import global_element
                end = picked_end(global_element(sel[0][0], sel[0][1]), sel[0][2])
                self.set(at, "nearest" if end is None else EDGE_ENDS[1 + bool(end)])
            self.set(prop, (sel[0][0], [sel[0][1]]))
            if picked:
                picked()
        self.show_edges()

    def show_edges(self):
        for prop, btn, empty in self.edge_buttons:
            link = getattr(self.obj, prop)
            btn.setText(f"{link[0].Label}.{link[1][0]}" if link and link[1] else empty)

    @staticmethod
    def show_value(box, value):
        """Show a result in a box the user does not edit now (no signal, no selection)."""
        box.blockSignals(True)
        box.setSpecialValueText("")
        box.setValue(value)
        box.blockSignals(False)
        box.lineEdit().deselect()

    NO_RESULT = "\u2014 (no result)"

    @classmethod
    def show_no_value(cls, box):
        """A result box while the solve fails: no value, not the last good curve's (Qt
        shows the special value text at the minimum; show_value clears it)."""
        box.blockSignals(True)
        box.setSpecialValueText(cls.NO_RESULT)
        box.setValue(box.minimum())
        box.blockSignals(False)

    def bspline_box(self, of, degree_tip, when=None):
        """The B-spline box: Tolerance (decades) and Degree fields (self.tol, self.degree)."""
        b = self.box("B-spline")
        self.tol = self.number(b, "Tolerance", "Tolerance", 1e-9, 1e3, 1e-3, "mm",
                               f"Largest distance of the B-spline from {of} (mm); arrows step by "
                               "a factor of 10", decade=True, when=when)
        self.degree = self.integer(b, "Degree", "Degree", 3, 7, degree_tip, when=when)

    def output_rows(self, grid, exclude, new_label):
        """Keep the feature or not; copy its B-spline into a sketch (not those in exclude)."""
        self.keep = self.check(grid, "Keep the parametric feature", "_keep",
                               "Unchecked: OK removes the feature and keeps only its copy in the "
                               "sketch chosen under Copy into (choose one first: without a copy "
                               "OK would keep nothing)", target=self,
                               when=lambda: bool(self.copy_target()))
        self.sketch = _narrow(QtGui.QComboBox())
        self.sketch_exclude, self.sketch_new = list(exclude), new_label
        self.offer_sketches()
        self.sketch.currentIndexChanged.connect(self.copy_chosen)
        self.row(grid, "Copy into", self.sketch,
                 "OK copies the B-spline into this sketch: a copy, which does not follow later "
                 "edits (the feature does); only sketches in the curve's plane are offered")

    _keep = True

    def offer_sketches(self):
        """The Copy into choices: the sketches in the curve's plane (another one would
        flatten the copy onto itself), kept up to date as the curve moves; the choice made
        stays while it is offered."""
        offered = []
        for sk in _sketches(self.doc, self.sketch_exclude):
            try:
                sketch_curves(self.obj, sk)
            except (InputProblem, Part.OCCError):
                continue
            offered.append((sk.Label, sk.Name))
        items = [("(no copy)", "")] + offered + [(self.sketch_new, "*new*")]
        box = self.sketch
        if [(box.itemText(i), box.itemData(i)) for i in range(box.count())] == items:
            return
        chosen = box.itemData(box.currentIndex()) if box.count() else ""
        box.blockSignals(True)
        box.clear()
        for text, name in items:
            box.addItem(text, name)
        box.setCurrentIndex(max(0, box.findData(chosen)))
        box.blockSignals(False)

    # ---------------------------------------------------------------- live update

    def set(self, prop, value, target=None):
        if self.gone:               # closing: no edit outside the panel's transaction
            return
        target = target if target is not None else self.obj
        if target is self.obj and self.expression(prop):
            return                  # bound: the expression sets it (the box is read-only)
        self._ok_said = ""
        if getattr(target, prop) != value:
            if target is not self and not self.doc.HasPendingTransaction:
                self.doc.openTransaction(self.txn)   # its own was committed by a command
            setattr(target, prop, value)
            self.changed(prop)
            if target is self.obj:
                self.timer.start(TYPING_MS if self._typed else DELAY_MS)
        self._typed = False
        self.refresh_enabled()

    def changed(self, prop):
        """A property was edited (before the recompute)."""

    def flush(self):
        """Run a pending recompute now (OK, tests)."""
        if self.timer.isActive():
            self.timer.stop()
            self.update()

    def update(self):
        """The live preview: the feature first, alone and quiet (proxy.report), as FreeCAD's
        own panels recompute their feature (TaskFeatureParameters::recomputeFeature): a
        failure is said on the panel's error line only. A document recompute printed it
        with 'Recompute failed!', which popped the report view up, for every prefix of a
        number typed that could not be solved. Its dependents follow a success (a document
        recompute marks them so after a feature: Document::recompute)."""
        o = self.obj
        try:
            o.Proxy.previewing = True
            try:
                ok = o.recompute()
            finally:
                o.Proxy.previewing = False
            if ok:
                o.purgeTouched()        # not solved twice
                for d in o.InList:
                    d.touch()
                self.doc.recompute()
        except Exception as exc:  # never let a preview escape
            App.Console.PrintError(f"Elastica: {exc}\n")
        self.previewed = edit_state(o)      # (panelexpressions.hold_back)
        self.previewed_touched = "Touched" in o.State
        self.refresh()
        self.refit()

    view_box = None

    def view_objects(self):
        """The objects besides the feature the view keeps in sight; None: the panel
        leaves the view alone."""
        return None

    def refit(self):
        """Fit the view to the feature and its view_objects when it leaves what was in
        view at the last fit, or shrinks to a small part of it."""
        others = self.view_objects()
        if others is None or self.obj.Shape.isNull() or Gui.ActiveDocument is None:
            return
        bb = global_shape(self.obj).BoundBox     # where drawn: a Part's placement applied
        if self.view_box is not None and self.view_box.isInside(bb) and \
                bb.DiagonalLength >= 0.25 * self.view_box.DiagonalLength:
            return
        box = App.BoundBox(bb)
        for o in others:
            shape = global_shape(o) if hasattr(o, "Shape") else None
            if shape is not None and not shape.isNull():
                box.add(shape.BoundBox)
        self.view_box = box
        show_box(box)

    def refresh(self):
        """Result text (an error on the error line, at the top) and which fields apply."""
        o = self.obj
        failed = o.Status.startswith("error")
        self.show_error()
        self.result.setText("" if failed else self.result_text())
        if hasattr(self, "sketch"):
            self.offer_sketches()
        if self.warning is not None:
            said = [] if o.Status.startswith("error") else self.warnings()
            self.warning[1].setText("<br>".join(said))
            self.warning[0].setVisible(bool(said))
        self.refresh_enabled()

    def show_error(self):
        """The error line: a field's text it cannot take (say_bad_input), else why the
        solve failed, else hidden."""
        if self.error is not None:
            o = self.obj
            text = self._input_said or self._ok_said or (
                said_now(o, "Status") if o.Status.startswith("error") else "")
            self.error[1].setText(text)
            self.error[0].setVisible(bool(text))

    def refresh_enabled(self):
        if not self._keep and not self.copy_target():
            # no copy chosen (or the one chosen no longer offered): OK would keep nothing,
            # and left an Undo step that did nothing (QA); the feature is kept
            self.keep.setChecked(True)
        for w, when in self.enablers:
            w.setEnabled(bool(when()))

    def copy_chosen(self, _index=None):
        if self._ok_said:           # another choice after OK failed (ok_failed)
            self._ok_said = ""
            self.show_error()
        self.refresh_enabled()

    def copy_target(self):
        """Copy into's choice: a sketch's name, '*new*', or '' (no copy)."""
        return self.sketch.itemData(self.sketch.currentIndex()) if hasattr(self, "sketch") else ""

    def result_text(self):
        return f"status: {said_now(self.obj, 'Status')}"

    # ---------------------------------------------------------------- OK / Cancel

    def getStandardButtons(self):
        return _buttons("Ok", "Cancel")

    def copy_code(self):
        """Python of OK's copy into a sketch (recorded), or '' (okcopy.copy_code)."""
        return copy_code(self.doc, self.obj, self.copy_target(), self.sources_body)

    def sources_body(self):
        """The PartDesign Body holding the first of the feature's sources in one (a sketch
        in a Body), or None: the first in its containers (innermost first)."""
        for c in getattr(self.obj, CONTAINERS, ()):
            if c.isDerivedFrom("PartDesign::Body"):
                return c
        return None

    def committed_by_other(self):
        """A command run during the edit committed the panel's transaction (every command
        that opens a transaction does: Std_Delete, even when it deletes nothing, for the
        object in edit refuses deletions): its edits so far are an Undo step of their own,
        which Cancel undoes, and the next edit opens the transaction again (``set``)."""
        if not self.closing and doc_undo_top(self.doc) == self.txn:
            self.orphans += 1

    def lost(self, why):
        """The feature left the document, or an undo / redo took the panel's transaction
        (_Watch): no more edits, and the panel closes once the undo has finished, the
        document as it left it."""
        self.timer.stop()
        if not self.gone:
            self.gone = why
            QtCore.QTimer.singleShot(0, self.gone_away)

    def gone_away(self):
        """The panel closes without OK or Cancel (``lost``)."""
        self.timer.stop()
        self.closing = True
        try:
            App.removeDocumentObserver(self.watch)
        except Exception:  # already removed
            pass
        if CURRENT and CURRENT[0] is self:
            App.Console.PrintWarning(f"Elastica: {self.name}: {self.gone or 'undone or deleted'}; "
                                     "its panel closes\n")
            self._close()

    def dropped(self, *_):
        """Its widgets deleted, not by OK, Cancel or its edit ending (``lost``):
        Gui.Control.closeDialog() from a macro or the console closed its dialog. Its
        document observer stayed, and the next recompute's refresh touched a deleted QLabel
        (a Traceback in the report view, revR): the panel lets go of the document now
        (_let_go, queued: no call into FreeCAD while it deletes the dialog)."""
        if self.closing or self.gone:
            return
        self.closing = True
        self.timer.stop()
        QtCore.QTimer.singleShot(0, self._let_go)

    def _let_go(self):
        """After ``dropped``: no observer, not CURRENT, its edit ended; the feature kept as
        the dialog left it, its edits one Undo step (committed), as said in the report view."""
        try:
            App.removeDocumentObserver(self.watch)
        except Exception:  # already removed
            pass
        if CURRENT and CURRENT[0] is self:
            CURRENT[:] = []
        if self.doc_name not in App.listDocuments():
            return
        App.Console.PrintWarning(f"Elastica: {self.name}: its panel closed without OK or "
                                 "Cancel; the feature kept as it is\n")
        if self.doc.HasPendingTransaction:
            self.doc.commitTransaction()
        gdoc = Gui.getDocument(self.doc_name)
        if gdoc is not None and gdoc.getInEdit() is not None:
            gdoc.resetEdit()

    def accept(self):
        if self.gone or self.name not in [o.Name for o in self.doc.Objects]:
            self.gone_away()
            return True
        self.flush()
        self.say_bad_input()
        if self._input_said:        # on the error line; the panel stays open to fix it
            return False
        if self.obj.Status.startswith("error"):
            # the preview said it on the panel's error line only: OK says it in the report
            # view too, and the panel stays open, the user fixes the input or cancels
            App.Console.PrintError(f"Elastica {self.obj.Label}: "
                                   f"{proxy_said(self.obj, 'Status').removeprefix('error: ')}\n")
            return False
        code = self.copy_code()
        if not code and not self._keep:   # refresh_enabled keeps this from happening
            self.keep.setChecked(True)
        self.closing = True
        # the properties the edit changed, set again by the lines recorded (Gui.doCommand:
        # a macro replays them; doCommandGui's are comments there), as FreeCAD's own panels
        # do at OK; the view's as Gui lines (comments in a macro, as FreeCAD records them)
        edits, view_edits = edit_lines(self.obj, self.opened_with)
        if code or not self._keep or edits:
            self.hold()
        attempt, failed = Attempt(self.doc, self.obj, self.copy_target()), None
        if attempt.target not in ("", "*new*") and attempt.sketch is None:
            # the sketch gone: no line recorded (revB 2: a macro's replay stopped at it)
            self.ok_failed(attempt, LookupError(attempt.target))
            return False
        try:
            for line in edits:
                Gui.doCommand(line)
            if edits or code:   # solved before a copy of it is made, in a macro replayed too
                Gui.doCommand(f"App.getDocument({self.doc.Name!r}).recompute()")
            if self.obj.Status.startswith("error"):   # a source changed since the preview
                raise Unsolved(proxy_said(self.obj, "Status").removeprefix("error: "))
            for line in view_edits:
                Gui.doCommandGui(line)
            if code:
                Gui.doCommand(code)
            if not self._keep:
                Gui.doCommand(f"App.getDocument({self.doc.Name!r}).removeObject({self.obj.Name!r})")
        except Exception as exc:    # (any: TaskDialogPython would close the panel on it)
            failed = exc
        if failed is not None:      # undone out of the handler: a feature in error recomputed
            self.ok_failed(attempt, failed)     # in it printed a Traceback
            return False
        self.doc.recompute()
        self.doc.commitTransaction()
        self._close()
        return True

    def ok_failed(self, attempt, exc):
        """OK's lines raised: what they wrote taken back (okcopy), the panel kept open on
        its edit, why said in the report view and on its error line."""
        attempt.undo()
        self.closing = False
        self._ok_said = attempt.said(exc)
        App.Console.PrintError(f"Elastica {self.obj.Label}: {self._ok_said}\n")
        self.refresh()

    def hold(self):
        """The panel's transaction open (a command may have committed it)."""
        if not self.doc.HasPendingTransaction:
            self.doc.openTransaction(self.txn)

    def reject(self):
        self.timer.stop()
        if self.gone:               # nothing of the panel's left to revert
            self.gone_away()
            return True
        self.closing = True
        try:
            App.removeDocumentObserver(self.watch)   # its own undo below closes nothing
        except Exception:  # already removed
            pass
        name = self.obj.Name
        # closed even when the edit changed nothing: a failed feature's recompute below
        # would become an Undo step 'Edit <Label>' that undid nothing visible (QA16 F3)
        abort_transaction(self.doc, self.txn)
        # the pieces of the edit another command committed (committed_by_other), while they
        # are the last Undo steps
        while self.orphans and doc_undo_top(self.doc) == self.txn:
            self.doc.undo()
            self.orphans -= 1
        if self.orphans:
            App.Console.PrintWarning(
                f"Elastica: {name}: Cancel could not revert the edit before "
                f"'{doc_undo_top(self.doc)}' (Edit > Undo reverts both)\n")
        # without undo (UndoMode 0) the abort keeps a fresh feature: remove it
        if self.created and name in [o.Name for o in self.doc.Objects]:
            self.doc.removeObject(name)
        self.doc.recompute()
        self._close()
        return True

    dialog_closed = False   # its edit ended (the view provider's unsetEdit closed it)

    def _close(self):
        CURRENT[:] = []
        try:
            App.removeDocumentObserver(self.watch)
        except Exception:  # already removed (a second close)
            pass
        if self.dialog_closed:
            # the edit that ended it may be another's now (a sketch double-clicked): its
            # dialog and edit mode stay (this closed the Sketcher as it opened)
            return
        Gui.Control.closeDialog()
        if self.doc_name in App.listDocuments():    # not a document closed under it
            gdoc = Gui.getDocument(self.doc_name)
            if gdoc is not None and gdoc.getInEdit() is not None:
                gdoc.resetEdit()


def doc_undo_top(doc):
    """The name of a document's last Undo step (its pending transaction's when one is
    open), or ''."""
    names = doc.UndoNames
    return names[0] if names else ""


def show_box(box):
    """Fit the active 3D view to a bounding box (with a margin for combs and arrows)."""
    view = Gui.ActiveDocument.ActiveView
    try:
        from pivy import coin
        w, h = view.getSize()
        d = 0.15 * box.DiagonalLength
        view.getCameraNode().viewBoundingBox(
            coin.SbBox3f(box.XMin - d, box.YMin - d, box.ZMin - d,
                         box.XMax + d, box.YMax + d, box.ZMax + d), w / max(h, 1), 1.0)
    except Exception:  # a view without a Coin camera: fit everything
        Gui.SendMsgToActiveView("ViewFit")


def _fmt(v, unit="mm"):
    """A value with its unit to the Decimals preference (number_text); a length (mm) in the
    user's schema (length_text)."""
    if unit == "mm":
        return length_text(v)
    return f"{number_text(v)} {unit}".strip()
