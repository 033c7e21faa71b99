"""Task-panel fields bound to expressions (the f(x) mark), as FreeCAD's own boxes show
and edit them (a Pad's Length): ``ExpressionFields``, the part of panelbase.Panel that
marks a box whose property an expression sets (spinboxes.Bindable.bind_mark: number and
integer boxes) and opens
FreeCAD's expression editor from its mark or '=' typed in the box; and keeps a text the
box refuses from reaching the property (hold_back)."""
from __future__ import annotations

import FreeCADGui as Gui
from PySide import QtCore, QtGui

from .proxy import bound_expression
from .recording import edit_state
from .spinboxes import PARSED_UNIT


class ExpressionFields:
    """A mixin of panelbase.Panel (its ``obj``, ``gone``, ``update`` and ``show_value``):
    the boxes of properties bound to expressions, read-only and marked, and the editor
    their mark opens."""

    def expression(self, prop):
        """The expression a property of the feature is bound to, or None."""
        return bound_expression(self.obj, prop)

    def mark_bound(self, box, prop):
        self.__dict__.setdefault("fields", []).append((box, prop))     # (follow_recompute)
        box.open_editor = lambda: self.edit_expression(box, prop)      # '=' or its mark
        box.lineEdit().textChanged.connect(lambda _text: self.hold_back(box, prop))
        expr = self.expression(prop)
        if expr:
            box.bind_mark(expr)

    def hold_back(self, box, prop):
        """The box's text changed: a text it refuses ('1/0', '3 deg', '5 km' in Resample)
        never reaches the feature, preview included: the property goes back to the value
        of the box's last text that stood (NumberBox.settled). Qt's keyboard tracking had
        sent on its last good prefix ('1' of '1/0': ResampleStep 6 -> 1 mm, previewed)
        while the box showed the refused text (QA25gui F3). A text it takes again sets its
        value: Qt says nothing when it is the value before ('7 in' after '7 i' put 151 mm
        back: its '7' had set 177.8 mm already). Put back, the feature's values are those its
        preview shows (Panel.previewed): the recompute the prefix set going is dropped ('5'
        of '5 kg' over 4 mm: the fit was redone at 4 mm, QA gui F11)."""
        if box.isReadOnly():
            return
        if not box.problem():
            self.set(prop, box.value())         # a float, an integer box's int
        elif box.settled is not None:
            self.set(prop, float(box.settled))
            if self.timer.isActive() and edit_state(self.obj) == self.previewed:
                self.timer.stop()
                if not self.previewed_touched:      # as its preview left it: OK's
                    self.obj.purgeTouched()         # recompute need not solve it again

    def edit_expression(self, box, prop):
        """FreeCAD's expression editor (Gui::Dialog::DlgExpressionInput) on ``prop``, as the
        f(x) mark of its own boxes opens it (a Pad's Length): its OK sets the expression,
        its Clear removes it, in the panel's transaction (Cancel undoes it); then the box
        follows (expression_edited). FreeCAD 0.20's Python has no call that opens the
        dialog (openFormulaDialog is no slot): a hidden Gui::QuantitySpinBox bound to the
        property (Gui.ExpressionBinding) is sent '=', on which FreeCAD's boxes open it."""
        if self.gone or self.closing or any(
                d.isVisible() for d in box.findChildren(QtGui.QDialog)):
            return                              # (one editor at a time)
        self.flush()
        self.hold()                             # its edit in the panel's transaction
        integer = isinstance(box, QtGui.QSpinBox)
        if integer:     # (0.20's ExpressionBinding opened no editor from a Gui::IntSpinBox)
            helper = Gui.UiLoader().createWidget("Gui::QuantitySpinBox", box)
            helper.setProperty("rawValue", float(getattr(self.obj, prop)))
        else:
            helper = Gui.UiLoader().createWidget("Gui::QuantitySpinBox", box)
            # the property's unit, as FreeCAD's box of it has: without it the editor said
            # 'Result: 8.00 mm (Warning: unit discarded)' of a length. Not a stiffness (N
            # mm^2, a plain number): FreeCAD's mass unit is kg, its N*mm^2 1000 of ours (1e6
            # N mm^2 was '1e9 mm^3*kg/s^2' there), and 0.20 has no unit of it to write
            unit = PARSED_UNIT.get(box.unit)
            if unit and "N" not in unit:
                helper.setProperty("unit", unit)
            # its value: FreeCAD's editor opens on an unbound box holding the box's text
            helper.setProperty("rawValue", float(getattr(self.obj, prop)))
        helper.setGeometry(box.rect())          # the dialog opens over the box
        helper.hide()
        self._binding = Gui.ExpressionBinding(helper)
        self._binding.bind(self.obj, prop)
        QtGui.QApplication.sendEvent(helper, QtGui.QKeyEvent(
            QtCore.QEvent.KeyPress, QtCore.Qt.Key_Equal, QtCore.Qt.NoModifier, "="))
        dialog = helper.findChild(QtGui.QDialog)
        if dialog is None:
            helper.deleteLater()
            return
        line = dialog.findChild(QtGui.QLineEdit, "expression")
        if integer and line is not None and not self.expression(prop):
            line.setText(str(getattr(self.obj, prop)))   # '3' as Gui::IntSpinBox, not '3.00'
        # after the helper's own slot (connected first) has set the expression
        dialog.finished.connect(lambda _result: QtCore.QTimer.singleShot(
            0, lambda: self.expression_edited(box, prop, helper)))

    def expression_edited(self, box, prop, helper):
        """The expression editor closed: the box marked with the expression of now, or
        writable again without one, and the preview recomputed with its value."""
        helper.deleteLater()
        if self.gone:
            return
        expr = self.expression(prop)
        if expr:
            box.bind_mark(expr)
        else:
            box.unbind_mark()
        self.obj.touch()
        self.update()
        self.show_value(box, float(getattr(self.obj, prop)))
        box._mark_input()           # the box's text is its own now (its signals were blocked)
        self.say_bad_input()        # the refused text it replaced no longer said

    def follow_recompute(self):
        """After a recompute of the document (panelwatch.Watch): the boxes of bound properties
        show their values of now and the results follow (refresh). A cell the feature is bound
        to changed while its panel was open: the feature was solved again but the panel kept
        the old tension, length and solutions (QA21gui F2). Its own preview's recompute too:
        nothing changes then."""
        if self.gone or self.closing:
            return
        try:
            for box, prop in self.__dict__.get("fields", ()):
                if self.expression(prop):
                    self.show_value(box, float(getattr(self.obj, prop)))
            self.refresh()
        except ReferenceError:      # its feature deleted meanwhile: the watch closes the panel
            pass
