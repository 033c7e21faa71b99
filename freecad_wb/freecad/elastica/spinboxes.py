"""The spin boxes of the Elastica task panels (panelbase.py) and preference page, as
FreeCAD's own Quantity boxes: ``NumberBox`` shows a value as typed, a length, curvature or
tension in the user's unit schema (units.py), and reads quantities in any unit and
expressions; ``DecadeBox`` steps by factors of 10 (tolerances)."""
from __future__ import annotations

import math

import FreeCAD as App
from PySide import QtCore, QtGui

from .units import (box_text, decimals, feet_inches, length_unit, number_text, tension_unit,
                    user_length)

BAD_RGB = "#b00"                         # panelbase.ERROR_RGB: the error line's red
# A typed text stands after this pause in typing (NumberBox.paused; the panels recompute then,
# panelbase.Panel.typed_in): a person types a key in about 250 ms, and every prefix of a
# number was solved ('1', '15', '150'); leaving the box solves at once, and Enter too before
# FreeCAD's task view takes it as OK (its default button), as in its own panels
TYPING_MS = 600


# a box's unit as FreeCAD's unit parser writes it (App.Units.Quantity)
PARSED_UNIT = {"mm": "mm", "1/mm": "1/mm", "1/mm\u00b2": "1/mm^2", "mm\u00b2": "mm^2",
               "N\u00b7mm\u00b2": "N*mm^2"}
# what a box of that unit takes, in a refusal ('3 deg is an angle, not a length')
_KIND = {"mm": "a length", "1/mm": "a curvature (1/length)", "1/mm\u00b2": "a tension (1/length\u00b2)",
         "mm\u00b2": "an area (length\u00b2)", "N\u00b7mm\u00b2": "a stiffness (force \u00b7 length\u00b2)"}


def _in_unit(text, unit, plain=1.0):
    """The number a typed quantity is in the box's unit, by FreeCAD's own parser (as its
    Quantity spin boxes read input): '7 cm' in a box of mm is 70, '2.75 in' 69.85,
    '=2*35' 70, '70,5' 70.5 where the decimal separator is a comma (a number without a unit
    times ``plain``: the box's factor of the unit it shows). ValueError for text it
    cannot read or a quantity of another kind ('7 kg' for a length)."""
    body = text[1:] if text.startswith("=") else text
    if not body.strip():    # FreeCAD reads '' as its 'no value', DBL_MIN: a box emptied
        raise ValueError(f"{text!r}: not a number or quantity")   # to type in took it
    try:
        q = App.Units.Quantity(body)
    except Exception:      # the parser's errors are of several kinds (syntax, 1/0, ...)
        raise ValueError(f"{text}: not a number or quantity") from None
    if not math.isfinite(q.Value):    # FreeCAD's parser gives inf for 1/0, nan for 0/0
        raise ValueError(f"{text.strip()}: " + (
            "a division by zero" if "/" in body else "not a finite number"))
    if q.Unit == App.Units.Quantity("1").Unit:
        return q.Value * plain
    ref = App.Units.Quantity(f"1 {PARSED_UNIT.get(unit, '?')}") if unit else None
    if ref is None or q.Unit != ref.Unit:
        kind = q.Unit.Type or "a quantity of another kind"     # FreeCAD's name: 'Angle', 'Mass'
        kind = kind if kind.startswith("a") and " " in kind else \
            f"a{'n' if kind[0].lower() in 'aeiou' else ''} {kind.lower()}"
        raise ValueError(f"{text.strip()} is {kind}, not {_KIND.get(unit, 'a plain number')}"
                         + (f" ({unit})" if unit else ""))
    return q.Value / ref.Value


class Bindable:
    """What a panel's box bound to a property shares with FreeCAD's boxes (Gui::
    ExpressionSpinBox, which its Quantity and integer boxes derive from): '=' opens the
    expression editor on the property, and a bound property's box is read-only and marked."""

    _mark = None                         # the bound-expression mark's action (bind_mark)
    # FreeCAD's expression editor on the property the box sets (panelexpressions: a box of
    # a panel bound to a property), or None
    open_editor = None

    def keyPressEvent(self, event):
        # '=' opens the expression editor, not typed, as in FreeCAD's boxes bound to a
        # property (Gui::ExpressionSpinBox::handleKeyEvent; read-only ones too): '=2*3'
        # was read once as 6 mm and '=Sheet.step' refused, the property bound to nothing;
        # an integer box ignored it (Gui::IntSpinBox opens the editor)
        if event.text() == "=" and self.open_editor is not None:
            event.accept()
            self.open_editor()
            return
        super().keyPressEvent(event)

    def bind_mark(self, expression, edit=None):
        """Bound to a property's ``expression``: read-only, FreeCAD's bound-expression
        mark in the box and the expression in its tooltip, as its own Quantity boxes show
        a bound property (the panel does not write it: set() skips bound properties).
        ``edit``: what clicking the mark does (FreeCAD's expression editor,
        panelexpressions.ExpressionFields.edit_expression),
        as the f(x) mark of FreeCAD's boxes."""
        if self._mark is None:
            self._tip = self.toolTip()
            self._mark = self.lineEdit().addAction(QtGui.QIcon(":/icons/bound-expression.svg"),
                                                   QtGui.QLineEdit.TrailingPosition)
            edit = edit or self.open_editor
            if edit is not None:
                self._mark.triggered.connect(edit)
        self.setReadOnly(True)
        self.setToolTip(f"Bound to the expression ={expression} (read-only here: click its "
                        "f(x) mark to change or clear it).\n" + self._tip)

    def unbind_mark(self):
        """No longer bound (its expression cleared): writable, unmarked, its own tooltip."""
        if self._mark is not None:
            self.lineEdit().removeAction(self._mark)
            self._mark = None
            self.setReadOnly(False)
            self.setToolTip(self._tip)




class NumberBox(Bindable, QtGui.QDoubleSpinBox):
    """A spin box that shows its value to the Decimals preference as FreeCAD's Quantity boxes
    (units.number_text: '151.00 mm' at 2, '151.000000 mm' at 6; a length as units.box_text
    writes it; a value below 1 to at least that many significant digits: Tension '0.000015
    1/mm²', Tolerance '0.000039 in', not FreeCAD's '0.00'; the value itself unrounded), a length,
    curvature or tension in the user's unit schema (units.py; the value itself stays in mm,
    1/mm, 1/mm^2), accepts scientific notation, quantities in other units and expressions as
    FreeCAD's own boxes do ('7 cm', '2.75 in', '2*35': _in_unit; '=' typed opens
    FreeCAD's expression editor on the panel's property: open_editor) and steps by
    ``singleStep``. As FreeCAD 0.20's Gui::QuantitySpinBox (measured under each schema), a
    plain number is in the unit the box shows, that of the text it last wrote ('6' in a box
    showing '5.94 in' is 6 in; '12' after Up took '9999 mm' to '10 m' is 12 m), and a length
    box's arrows step ``singleStep`` of that unit (1 in, 1 cm, 1 m). The unit is part of the
    text, not a suffix: a suffix stayed behind what was typed ('7 in mm')."""

    unit = ""                            # Qt calls validate() while __init__ runs
    # the typing paused (TYPING_MS after the last key): the text stood (``settled``) or is
    # refused, which the panel's error line says then (panelbase.Panel.watch_text)
    paused = QtCore.Signal()
    written = None                       # (factor, unit) of the text the box last wrote

    def __init__(self, lo, hi, step, unit="", tip=""):
        super().__init__()
        self.setDecimals(30)             # the box must not round 1e-7 to 0
        self.setRange(lo, hi)
        self.setSingleStep(step)
        self.setKeyboardTracking(True)
        self.unit = unit
        self.setToolTip(tip)
        # as narrow as its minimum, not the width of '-1e+06 1/mm' (its range's text): the
        # Fit panel's Ends box was 216 px wide for it
        self.setSizePolicy(QtGui.QSizePolicy.Preferred, QtGui.QSizePolicy.Fixed)
        self._palette = QtGui.QPalette(self.lineEdit().palette())
        self.lineEdit().textChanged.connect(self._mark_input)
        self.editingFinished.connect(self._settle)
        self.pause = QtCore.QTimer(self)
        self.pause.setSingleShot(True)
        self.pause.setInterval(TYPING_MS)
        self.pause.timeout.connect(self._paused)
        self.lineEdit().textEdited.connect(lambda _text: self.pause.start())
        self.editingFinished.connect(self.pause.stop)   # Enter / focus-out settled it now

    def shown(self, value):
        """(factor, unit): the box shows ``value`` as value / factor unit."""
        if self.unit == "mm":
            return user_length(value)
        if self.unit == "1/mm":
            factor, unit = length_unit()
            return 1.0 / factor, f"1/{unit}"
        if self.unit == "1/mm\u00b2":
            factor, unit = tension_unit()
            return 1.0 / factor, unit
        if self.unit == "mm\u00b2":               # the comb's scale
            factor, unit = length_unit()
            return factor * factor, f"{unit}\u00b2"
        return 1.0, self.unit

    def textFromValue(self, value):
        if self.unit == "mm":            # Building US: feet and inches, as FreeCAD's boxes
            return feet_inches(value) or box_text(value)
        factor, unit = self.shown(value)     # to the Decimals preference, as box_text the
        x = value / factor                   # lengths ('0.000015 1/mm²'; the value stays:
        number = number_text(x)              # valueFromText); '-1e+06' from 1e6: Qt sizes
        if abs(x) >= 1e6:                    # the box by its range's texts
            number = f"{x:.{max(1, decimals())}g}"
        return f"{number} {unit}" if unit else number

    def _wrote(self):
        """The box may have written its text (a value set, an arrow step, focus):
        when the text is its own text of its value, a number typed next is in its unit; a
        text being typed is not ('6' typed over '5.94 in' is 6 in, '62' too). (Qt writes the
        text with the line edit's signals blocked: its textChanged says nothing.)"""
        if self.lineEdit().text() == self.textFromValue(self.value()):
            self.written = self.shown(self.value())
            self.settled = self.value()

    def setValue(self, value):
        super().setValue(value)
        self._wrote()

    # The value of the box's last text that stood (written by the box, or typed and taken
    # by Enter, focus-out or the typing pause): a text it refuses never reaches the feature,
    # the panel sets this one back (panelexpressions.ExpressionFields.hold_back), not the
    # value of the refused text's last good prefix ('1' of '1/0', which Qt's keyboard
    # tracking sent on).
    settled = None

    _refused = ""                        # the refused text focus-out puts back (focusOutEvent)

    def _settle(self):
        if not self.problem() and not self._refused:
            self.settled = self.value()

    def _paused(self):
        """The typing paused: a text the box takes stands, as on Enter (the panel previewed
        it); the settled value stayed the one before it ('4 mm' typed and left there, then
        'abc': the panel put 0 mm back, the value before '4 mm', QA gui F11)."""
        self._settle()
        self.paused.emit()

    def focusInEvent(self, event):
        super().focusInEvent(event)
        self._wrote()

    def _number(self, text):
        v = self._read(text)
        if not math.isfinite(v):     # '1e400', '1e300 km': beyond any double
            raise ValueError(f"{text.strip()}: not a finite number")
        return v

    def _read(self, text):
        t = text.strip()
        factor, unit = self.written or self.shown(self.value())
        for u, f in ((unit, factor), (self.unit, 1.0)):
            if u and t.endswith(u):
                try:
                    return float(t[:-len(u)].strip()) * f
                except ValueError:
                    pass
        try:
            return float(t) * factor        # a plain number: in the unit shown
        except ValueError:
            return _in_unit(t, self.unit, factor)

    def valueFromText(self, text):
        if text == self.textFromValue(self.value()):
            return self.value()          # as shown (rounded in another unit): unchanged
        try:
            return self._number(text)
        except ValueError:
            return self.value()

    def stepBy(self, steps):
        if self.unit != "mm":           # tensions, curvatures: the problem's own scale
            super().stepBy(steps)
            return self._wrote()
        factor, _ = self.shown(self.value())
        self.setValue(self.value() + steps * self.singleStep() * factor)
        self.selectAll()

    def validate(self, text, pos):
        try:
            v = self._number(text)
            ok = self.minimum() <= v <= self.maximum()
            state = QtGui.QValidator.Acceptable if ok else QtGui.QValidator.Intermediate
        except ValueError:
            state = QtGui.QValidator.Intermediate
        return state, text, pos

    def fixup(self, text):
        return self.textFromValue(self.value())

    # A text the box cannot take ('3 deg', '2 kg' in a length box; '5 km' beyond its range)
    # is marked as FreeCAD's Quantity boxes mark invalid input: red, and why in its tooltip.
    # Qt keeps the value of its last acceptable prefix ('3' of '3 deg': 3 mm); a panel
    # (``keep_bad_text``) keeps such text past focus-out rather than Qt's silent return to
    # that value, and its OK refuses it, naming the field (panelbase.Panel.bad_input).
    keep_bad_text = False

    def problem(self):
        """Why the box's text is not a value it takes ('3 deg is an angle, not a length
        (mm)', '5 km is 5000000 mm, above the largest, 1000000 mm'), or ''."""
        text = self.lineEdit().text()
        if text == self.textFromValue(self.value()) or (
                self.specialValueText() and text == self.specialValueText()):
            return ""
        try:
            v = self._number(text)
        except ValueError as exc:
            if self.open_editor is not None and "not a number" in str(exc):
                # a cell or an alias ('Sheet.step') is no text a box takes: FreeCAD's
                # boxes bind their property to it in the expression editor, opened by '='
                return f"{exc}; to bind the field to an expression, type = in it"
            return str(exc)
        if v < self.minimum():
            return (f"{text.strip()} is below the smallest, "
                    f"{self.textFromValue(self.minimum())}")
        if v > self.maximum():
            return (f"{text.strip()} is above the largest, "
                    f"{self.textFromValue(self.maximum())}")
        return ""

    def _mark_input(self, _text=None):
        why = self.problem()
        edit = self.lineEdit()
        if why:
            pal = QtGui.QPalette(self._palette)
            pal.setColor(QtGui.QPalette.Text, QtGui.QColor(BAD_RGB))
            edit.setPalette(pal)
        else:
            edit.setPalette(self._palette)
        edit.setToolTip(why)            # over the text; the box's own tooltip elsewhere

    def focusOutEvent(self, event):
        text, why = self.lineEdit().text(), self.keep_bad_text and self.problem()
        self._refused = why and text        # Qt's editingFinished comes with its own text
        try:
            super().focusOutEvent(event)
        finally:
            self._refused = ""
        if why and self.lineEdit().text() != text:
            self.lineEdit().setText(text)      # still marked: OK says why and refuses it
            self.editingFinished.emit()        # Qt's came with its own text back


class DecadeBox(NumberBox):
    """A tolerance: each arrow step (or wheel notch) multiplies or divides by 10."""

    def stepBy(self, steps):
        self.setValue(self.value() * 10.0 ** steps)


class IntBox(Bindable, QtGui.QSpinBox):
    """An integer box (a B-spline's Degree, the comb's Teeth) as FreeCAD's Gui::IntSpinBox:
    '=' opens the expression editor on its property, bound it is read-only and marked
    (Bindable). Qt's validator takes only integers in its range: no text to refuse."""

    settled = None
    keep_bad_text = False

    def __init__(self, lo, hi, tip=""):
        super().__init__()
        self.setRange(lo, hi)
        self.setKeyboardTracking(True)
        self.setToolTip(tip)

    def setValue(self, value):
        """An integer property's value (a float from an expression: FreeCAD rounds it)."""
        super().setValue(int(round(value)))

    @staticmethod
    def problem():
        """'' (panelexpressions asks the boxes why their text is refused)."""
        return ""

    def _mark_input(self, _text=None):
        """Nothing to mark (problem)."""
