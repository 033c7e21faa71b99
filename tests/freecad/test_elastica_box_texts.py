"""freecadcmd -t tests of the text the panels' boxes that are not lengths write (Tension,
curvatures, plain numbers: spinboxes.NumberBox): in fixed notation, in the unit the schema
gives them, as the length boxes (units.box_text): a
Tension box showed '1.51519e-05 1/mm\u00b2'; FreeCAD's own Quantity box shows '0.00
1/mm^2'. To the Decimals preference (units.number_text; FreeCAD's default 2 here, 2 and 6
in test_elastica_decimals). The text is only shown: the value stays the property's, every bit."""
import os
import sys
import unittest

import FreeCAD as App

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")      # freecadcmd: no display
from PySide import QtGui  # noqa: E402

from freecad.elastica.spinboxes import NumberBox  # noqa: E402

STANDARD, IMPERIAL_DECIMAL = 0, 3
APP = QtGui.QApplication.instance() or QtGui.QApplication([])


class BoxTextsTest(unittest.TestCase):
    def setUp(self):
        self.schema = App.Units.getSchema()

    def tearDown(self):
        App.Units.setSchema(self.schema)

    def shown(self, unit, value):
        box = NumberBox(-1e6, 1e6, 1e-5, unit)
        box.setValue(value)
        text = box.text()
        box.interpretText()         # what leaving the box reads back from its text
        self.assertEqual(box.value(), value, text)       # not the rounded text's number
        return text

    def test_tension_and_curvature_in_fixed_notation(self):
        """At FreeCAD's default 2 decimals: 2 places, at least 2 significant digits below 1
        (units.number_text: FreeCAD's own box writes 0.0000152 1/mm^2 '0.00 1/mm^2')."""
        App.Units.setSchema(STANDARD)
        self.assertEqual(self.shown("1/mm\u00b2", 1.515190123e-05), "0.000015 1/mm\u00b2")
        self.assertEqual(self.shown("1/mm\u00b2", 6.57e-05), "0.000066 1/mm\u00b2")
        self.assertEqual(self.shown("1/mm", -0.0012345678), "-0.0012 1/mm")
        self.assertEqual(self.shown("1/mm\u00b2", 0.409), "0.41 1/mm\u00b2")
        self.assertEqual(self.shown("1/mm\u00b2", 0.0), "0.00 1/mm\u00b2")
        self.assertEqual(self.shown("", 1234567.0 / 4), "308641.75")               # no '3.08642e+05'
        self.assertEqual(self.shown("N\u00b7mm\u00b2", 1234567.0 / 4), "308641.75 N\u00b7mm\u00b2")
        self.assertEqual(self.shown("", 0.0012345678), "0.0012")
        # a range's end as before (Qt sizes a box by its range's texts: the panels' widths)
        self.assertEqual(self.shown("1/mm", -1e6), "-1e+06 1/mm")
        App.Units.setSchema(IMPERIAL_DECIMAL)       # 1/in^2: 645.16 x the value in 1/mm^2
        text = self.shown("1/mm\u00b2", 1.515190123e-05)
        self.assertEqual(text, "0.0098 1/in\u00b2")     # 0.00977540 to 2 digits
        self.assertEqual(self.shown("1/mm", 1.5e-05), "0.00038 1/in")

    def test_exponent_below_a_millionth(self):
        """Below 1e-6 of the unit an exponent (as box_text: FreeCAD's Imperial decimal
        schema turns to it there, and 0.0000000x is unreadable), and from 1e6."""
        App.Units.setSchema(STANDARD)
        self.assertEqual(self.shown("1/mm\u00b2", 2.7e-07), "2.7e-07 1/mm\u00b2")
        self.assertEqual(self.shown("", 2.5e-07), "2.5e-07")


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
