"""freecadcmd -t tests of what the panels' boxes (spinboxes.NumberBox) do with '=' and with
a text they refuse, as FreeCAD's own Quantity boxes (QA25gui F2, F3; the panels are driven
under xvfb in gui_typed_expressions.py):

- '=' typed in a box tied to a property opens the expression editor (the panel's
  ``open_editor``) and is not typed: '=2*3' was read once as 6 mm, no expression kept;
- '1/0' is a division by zero, not 'above the largest, 1000 m' (FreeCAD's parser reads it
  as inf), '0/0' too, 'log(0)' and '1e400' not finite numbers;
- a refused text keeps ``settled``, the value of the box's last text that stood, which the
  panel puts back on the feature (Qt's value is that of the text's last good prefix);
- a text the box takes stands when the typing pauses (TYPING_MS, no Enter or Tab), and the
  box says so (``paused``: the panel's error line says a refused one then): '4 mm' typed
  and left, then 'abc' put back the value before '4 mm' (QA gui F11);
- a cell's name typed as a value says how a field is bound to it."""
import os
import unittest

import FreeCAD as App

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")      # freecadcmd: no display
from PySide import QtCore, QtGui  # noqa: E402

from freecad.elastica.spinboxes import TYPING_MS, NumberBox  # noqa: E402

STANDARD = 0
APP = QtGui.QApplication.instance() or QtGui.QApplication([])


def _type(box, text):
    box.selectAll()
    for ch in text:
        for kind in (QtCore.QEvent.KeyPress, QtCore.QEvent.KeyRelease):
            QtGui.QApplication.sendEvent(box, QtGui.QKeyEvent(kind, 0, QtCore.Qt.NoModifier, ch))


def _pause(box):
    """The user stops typing: the event loop runs past the box's typing pause."""
    loop = QtCore.QEventLoop()
    QtCore.QTimer.singleShot(2 * TYPING_MS, loop.quit)   # after the box's pause timer
    loop.exec_()


class BoxExpressionsTest(unittest.TestCase):
    def setUp(self):
        self.schema = App.Units.getSchema()
        App.Units.setSchema(STANDARD)
        self.box = NumberBox(0.0, 1e6, 0.5, "mm", "Resample")
        self.box.setValue(6.0)

    def tearDown(self):
        App.Units.setSchema(self.schema)

    def test_a_division_by_zero_is_said_so(self):
        for text in ("1/0", "0/0", "1/0 mm", "(2+3)/(1-1) cm"):
            _type(self.box, text)
            self.assertEqual(self.box.problem(), f"{text}: a division by zero")
        for text in ("log(0)", "1e400"):
            _type(self.box, text)
            self.assertEqual(self.box.problem(), f"{text}: not a finite number")

    def test_a_refused_text_keeps_the_value_that_stood(self):
        _type(self.box, "1/0")
        self.assertEqual(self.box.text(), "1/0")
        self.assertEqual(self.box.value(), 1.0)       # Qt's: the prefix '1'
        self.assertEqual(self.box.settled, 6.0)       # what the panel puts back
        _type(self.box, "8")
        self.box.editingFinished.emit()               # Enter: '8' stands
        self.assertEqual(self.box.settled, 8.0)
        _type(self.box, "3 deg")
        self.assertEqual(self.box.settled, 8.0)

    def test_a_text_left_through_the_typing_pause_stands(self):
        paused = []
        self.box.paused.connect(lambda: paused.append((self.box.text(), self.box.settled)))
        _type(self.box, "4 mm")
        self.assertEqual(self.box.settled, 6.0)       # typing: not yet
        _pause(self.box)
        self.assertEqual(paused, [("4 mm", 4.0)])     # stood: what the panel puts back
        for text in ("abc", "5 kg", "-2", "1/0", "3O0"):
            _type(self.box, text)
            _pause(self.box)
            self.assertEqual(paused[-1], (text, 4.0))   # refused: the panel says why
        self.assertEqual(len(paused), 6)
        _type(self.box, "2 cm")
        _pause(self.box)
        self.assertEqual(paused[-1], ("2 cm", 20.0))
        _type(self.box, "12")                         # a prefix typed on, never left: it
        _type(self.box, "12 kg")                      # does not stand
        _pause(self.box)
        self.assertEqual(paused[-1], ("12 kg", 20.0))

    def test_enter_or_focus_out_ends_the_typing_pause(self):
        paused = []
        self.box.paused.connect(lambda: paused.append(self.box.text()))
        _type(self.box, "4 mm")
        self.box.editingFinished.emit()               # Enter or Tab: '4 mm' stands now
        self.assertEqual(self.box.settled, 4.0)
        self.assertFalse(self.box.pause.isActive())   # nothing left to wait for
        _pause(self.box)
        self.assertEqual(paused, [])

    def test_equals_opens_the_expression_editor_and_is_not_typed(self):
        opened = []
        self.box.open_editor = lambda: opened.append(True)
        before = self.box.text()
        _type(self.box, "=")
        self.assertEqual((opened, self.box.text()), ([True], before))
        self.box.setReadOnly(True)                    # bound: '=' opens it too
        _type(self.box, "=")
        self.assertEqual(len(opened), 2)

    def test_a_cells_name_says_how_to_bind_it(self):
        _type(self.box, "Sheet.step")
        self.assertEqual(self.box.problem(), "Sheet.step: not a number or quantity")
        self.box.open_editor = lambda: None           # a panel's box, tied to a property
        self.assertEqual(self.box.problem(), "Sheet.step: not a number or quantity; to bind "
                                             "the field to an expression, type = in it")


if __name__ == "__main__":
    unittest.main()
