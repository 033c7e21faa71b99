"""freecadcmd -t tests of the panels' numbers at FreeCAD's Decimals preference (Edit >
Preferences > General > Units > Number of decimals; User parameter:BaseApp/Preferences/Units,
Decimals), at 2 and 6, the user's restored after: every text and box writes through one
helper, units.number_text, as FreeCAD's Base::Quantity::getUserString writes a quantity
(its own UserString, compared here, where it keeps the digits); the panels wrote '%.3g'
whatever the preference said. And an integer box opens the expression editor on '=' as
FreeCAD's Gui::IntSpinBox (spinboxes.IntBox)."""
import os
import re
import sys
import unittest

import FreeCAD as App
import numpy as np

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")      # freecadcmd: no display
from PySide import QtCore, QtGui  # noqa: E402

import elastica_samples as S  # noqa: E402
from freecad.elastica import spline as Sp, units as U  # noqa: E402
from freecad.elastica.proxy import said  # noqa: E402
from freecad.elastica.spinboxes import IntBox, NumberBox  # noqa: E402

APP = QtGui.QApplication.instance() or QtGui.QApplication([])
STANDARD, MKS, IMPERIAL_DECIMAL = 0, 1, 3


def user_string(mm, d):
    """FreeCAD's own text of a length at ``d`` decimals (Quantity.UserString)."""
    q = App.Units.Quantity(float(mm), App.Units.Length)
    q.Format = {"Precision": d}
    return q.UserString


class DecimalsTest(unittest.TestCase):
    def setUp(self):
        self.schema = App.Units.getSchema()
        self.prefs = App.ParamGet(U.UNITS_PREFERENCES)
        self.kept = self.prefs.GetInt("Decimals", -1)

    def tearDown(self):
        App.Units.setSchema(self.schema)
        if self.kept < 0:
            self.prefs.RemInt("Decimals")
        else:
            self.prefs.SetInt("Decimals", self.kept)

    def at(self, d):
        self.prefs.SetInt("Decimals", d)
        self.assertEqual(U.decimals(), d)

    def test_a_number_rounded_past_its_decade_keeps_the_format(self):
        """Review of F10: the G2 blend's row printed energy 0.100 for 0.0997 (its lead digit
        taken before rounding) and 0.10 for 0.1002: one format, the lead digit as written."""
        for d, want in ((2, ("0.10", "0.10", "0.099", "1.00", "0.0000010")),
                        (6, ("0.0997000", "0.100200", "0.0990000", "0.999000", "9.99600e-07"))):
            self.at(d)
            self.assertEqual(tuple(U.number_text(x) for x in
                                   (0.0997, 0.1002, 0.099, 0.999, 9.996e-7)), want)
        self.at(2)
        self.assertEqual(U.number_text(0.0995, bound="up"), "0.10")
        self.assertEqual(U.number_text(0.0995, bound="down"), "0.099")

    def test_numbers_as_freecad_writes_them(self):
        want = {2: ("151.00", "0.50", "0.0012", "-0.00066", "0.00", "2.7e-07", "1234.57"),
                6: ("151.000000", "0.500000", "0.00123457", "-0.000657000", "0.000000",
                    "2.70000e-07", "1234.567800")}
        for d in (2, 6):
            self.at(d)
            self.assertEqual(tuple(U.number_text(x) for x in
                                   (151.0, 0.5, 0.0012345678, -0.000657, 0.0, 2.7e-7, 1234.5678)),
                             want[d])
            self.assertEqual(U.number_text(0.00203109, 6), "0.00203109")   # typed back
            self.assertEqual(U.number_text(0.000657, 6), "0.000657" + "000"[:max(0, d - 3)])

    def test_lengths_are_freecads_user_string(self):
        """A length of at least 0.1 in the unit FreeCAD picks (where its d places keep d
        digits) is its UserString, under Standard, MKS and Imperial decimal; the length boxes
        show the same text."""
        for d in (2, 6):
            self.at(d)
            for schema in (STANDARD, MKS, IMPERIAL_DECIMAL):
                App.Units.setSchema(schema)
                for mm in (5.0, 24.2, 151.0, 1234.5678, 2.5e6):
                    with self.subTest(d=d, schema=schema, mm=mm):
                        self.assertEqual(U.length_text(mm), user_string(mm, d))
                        self.assertEqual(U.say(U.exact_mark(mm)), user_string(mm, d))
                        box = NumberBox(0.0, 1e7, 1.0, "mm")
                        box.setValue(mm)
                        self.assertEqual(box.text(), user_string(mm, d))
        App.Units.setSchema(STANDARD)
        self.at(6)
        self.assertEqual(U.box_text(0.001), "1.000000 \u00b5m")
        self.assertEqual(U.figure_text(1e-11), "0.000000 mm")          # rounding noise

    def test_tension_and_curvature_boxes_and_texts(self):
        want = {2: ("0.00066 1/mm\u00b2", "0.033/mm", "0.0012 1/mm", "12.50 mm\u00b2"),
                6: ("0.000657000 1/mm\u00b2", "0.0327000/mm", "0.00123457 1/mm",
                    "12.500000 mm\u00b2")}
        for d in (2, 6):
            self.at(d)
            box = NumberBox(-1.0, 1.0, 1e-5, "1/mm")
            box.setValue(0.0012345678)
            self.assertEqual((U.tension_text(0.000657, 100.0), U.per_length(0.0327),
                              box.text(), U.area_text(12.5)), want[d])
            box.interpretText()
            self.assertEqual(box.value(), 0.0012345678)        # the text is only shown

    def test_a_feature_text_said_at_the_preference_of_now(self):
        """A spline's Status (its marks) in a panel at 2 and at 6 decimals, without a
        recompute: the lengths as FreeCAD writes them at each."""
        doc = S.new_doc("Decimals")
        try:
            sk = S.points_sketch(doc, S.keyline_xy(8)[0])
            s = Sp.make(doc, [(sk, [])], Mode="length", Length=50.0)
            doc.recompute()
            for d in (2, 6):
                self.at(d)
                text = said(s, "Status", figures=True)
                self.assertTrue(text.startswith(f"error: Length = {user_string(50.0, d)} is not "
                                                "longer than the polygon"), text)
                polygon = text.split("points (")[1].split(" mm)")[0]
                # the library's lower bound ('any length above it') keeps its written
                # digits: '328.182', not '328.18' (below the polygon's 328.1817...)
                self.assertEqual(len(polygon.split(".")[1]), max(d, 3), text)
                self.assertTrue(polygon.startswith("328.182"), text)
        finally:
            App.closeDocument(doc.Name)

    def test_bounds_rounded_to_their_safe_side(self):
        """A figure a text says to stay above (a step of at least) is written rounded up,
        one to stay below (a step under) rounded down, at every Decimals; a '<n> mm' of a
        library message keeps the digits it was written with (its 'raise tol to 0.00123 mm
        or more' was '0.0012 mm' at 2: below the tol it asks for); Decimals 0 writes a
        number below 1 with 1 significant digit, not '0'."""
        from freecad.elastica import fit_core as F
        most = F.el().RESAMPLE_MAX_VERTICES
        for d in (0, 2, 6):
            self.at(d)
            for length in (3.29756e-4 * (most - 1), 123.4561 * (most - 1), 0.0712341 * 29):
                xy = np.column_stack([np.linspace(0.0, length, 40), np.zeros(40)])
                length = F.polyline_length(xy)             # as the message takes it
                least = length / (most - 1)
                with self.assertRaises(F.InputProblem) as e:
                    F._resampled(xy, least / 2)
                text = U.say(str(e.exception))
                shown = re.search(r"at least ([-\d.e+]+) (\S+),", text)
                factor, unit = U.user_length(least)        # as said computes it
                self.assertEqual(shown.group(2), unit)
                self.assertGreaterEqual(float(shown.group(1)), least / factor, (d, text))
                under = U.say(F._step_advice(length))
                shown = re.search(r"a step under ([-\d.e+]+) (\S+);", under)
                factor, unit = U.user_length(length / (F.MIN_POINTS - 1))
                self.assertEqual(shown.group(2), unit)
                self.assertLessEqual(float(shown.group(1)),
                                     length / (F.MIN_POINTS - 1) / factor, (d, under))
            said = U.say(U.mm_marked("raise tol to 0.00123 mm or more"))
            self.assertRegex(said, "to 1\\.230* \u00b5m or", d)      # Standard: in µm
            said = U.say(U.mm_marked("raise tol to 0.0123 mm or more"))
            self.assertRegex(said, "to 12\\.30* \u00b5m or", d)
            self.assertNotEqual(U.number_text(0.4), "0", d)
            self.assertEqual(U.number_text(0.4), "0.4" + "0" * max(0, d - 1), d)

    def test_integer_box_equals_opens_the_editor(self):
        """'=' in an integer box calls its editor (the panel's: FreeCAD's expression editor
        on the property, panelexpressions), not typed; without one it is a key as any."""
        box = IntBox(3, 7)
        box.setValue(4)
        opened = []
        box.open_editor = lambda: opened.append(box.value())
        event = QtGui.QKeyEvent(QtCore.QEvent.KeyPress, QtCore.Qt.Key_Equal,
                                QtCore.Qt.NoModifier, "=")
        box.keyPressEvent(event)
        self.assertEqual((opened, box.text()), ([4], "4"))
        box.bind_mark("Sheet.order")
        self.assertTrue(box.isReadOnly())
        self.assertIn("Sheet.order", box.toolTip())
        self.assertEqual(len(box.lineEdit().actions()), 1)
        box.unbind_mark()
        self.assertFalse(box.isReadOnly())
        self.assertEqual(len(box.lineEdit().actions()), 0)
        box.setValue(5.6)                  # an expression's float: rounded as FreeCAD does
        self.assertEqual(box.value(), 6)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
