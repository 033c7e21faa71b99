"""freecadcmd -t tests of the unit each length of a text or a length box is written in: the
one FreeCAD's schema picks for that value (Quantity.getUserPreferred, as its UserString and
Gui::QuantitySpinBox), with the workbench's exact digits (units.say's marks, units.box_text).
Under MKS the fit's warning said '0.00029 m' where FreeCAD writes '0.29 mm', and the
spline's, by length_text, '3.25 mm': one workbench, two rules."""
import re
import sys
import unittest
from decimal import Decimal

import FreeCAD as App
import numpy as np

import elastica_samples as S
from freecad.elastica import units as U
from freecad.elastica.fit_core import fit_core

SCHEMAS = range(8)      # Standard, MKS, US customary, Imperial decimal, Building Euro and US,
#                         Metric small parts, Imperial civil
FIGURE = re.compile("(-?\\d+\\.?\\d*(?:e[+-]?\\d+)?) (mm|m|\u00b5m|nm|km|in|thou|\"|ft|cm|yd|mi)")


def preferred(mm):
    """(factor, unit) FreeCAD's schema of now writes ``mm`` millimetres in."""
    _, factor, unit = App.Units.Quantity(float(mm), App.Units.Length).getUserPreferred()
    return float(factor), unit


def digits(number):
    return len(re.sub(r"e.*|[^0-9]", "", number).lstrip("0"))


class UnitsPerValueTest(unittest.TestCase):
    def setUp(self):
        self.schema = App.Units.getSchema()

    def tearDown(self):
        App.Units.setSchema(self.schema)

    def assert_written(self, text, mm, at_least=3):
        """``text`` ('<number> <unit>') is ``mm`` in the unit FreeCAD picks for it, rounded
        correctly to the digits it shows (as many as '%g' writes in mm, at least 3, where
        the unit is not mm), in whichever notation."""
        m = FIGURE.fullmatch(text)
        self.assertIsNotNone(m, text)
        factor, unit = preferred(mm)
        self.assertEqual(m.group(2), unit, (text, mm, App.Units.getSchema()))
        shown = float(m.group(1))
        n = max(at_least, digits(f"{mm:g}")) if factor != 1.0 else digits(f"{mm:g}")
        self.assertEqual(Decimal(m.group(1)), Decimal(f"{mm / factor:.{n}g}"), (text, mm))
        self.assertAlmostEqual(shown * factor, mm, delta=abs(mm) * 10.0 ** (1 - n))

    def test_marked_lengths_take_the_unit_freecad_picks_for_each(self):
        """Under every schema each exact mark and '<number> mm' mark is written in the unit
        getUserPreferred gives its value (MKS: 0.496 mm, 2.42 mm and 0.1192 m in one
        message), to its exact digits; on the old code one unit per schema (0.000496 m)."""
        values = (0.0004, 0.0496, 0.496, 2.42, 9.05, 115.6, 119.2, 4000.0, 2.5e6)
        for schema in SCHEMAS:
            App.Units.setSchema(schema)
            for mm in values:
                with self.subTest(schema=schema, mm=mm):
                    self.assert_written(U.say(U.exact_mark(mm)), mm)
                    self.assert_written(U.say(U.mm_marked(f"{mm:g} mm")), mm)
                    self.assert_written(U.say(U.exact_mark(mm, 4)), float(f"{mm:.4g}"), 4)

    def test_a_range_is_written_in_the_unit_of_its_end(self):
        """'9.05 to 160 mm' under MKS: both in m (FreeCAD's unit of 160 mm), the first not
        in the schema's unit beside the second's; coordinates named by the unit mark keep
        the schema's one unit."""
        App.Units.setSchema(1)
        self.assertEqual(U.say(U.mm_marked("lie 9.05 to 160 mm")), "lie 0.00905 to 0.16 m")
        self.assertEqual(U.say(U.mm_marked("lie 9.05 to 16 mm")), "lie 9.05 to 16 mm")
        self.assertEqual(U.say(f"lie {U.exact_mark(9.05, 3, False)} to "
                               f"{U.exact_mark(16.0, 3)} from"), "lie 9.05 to 16 mm from")
        self.assertEqual(U.say(f"at ({U.coordinate_mark(219.9)}, {U.coordinate_mark(-0.5)}) "
                               f"{U.length_unit_mark()}"), "at (0.2199, -0.0005) m")

    def test_fit_warning_under_mks_says_what_freecad_says(self):
        """A natural start where the noisy S curves (test_elastica_fit_cost's): under MKS the
        end-condition warning gives both rms in mm (0.289 and 1.65 mm, FreeCAD's '0.29 mm',
        '1.65 mm'), as the spline's gap warning does; it said '0.000289 m' and '0.00165 m'."""
        xy, _ = S.keyline_xy(40)
        xy = xy + np.random.default_rng(3).normal(0.0, 0.3, xy.shape)
        points = [App.Vector(float(x), float(y), 0.0) for x, y in xy]
        r = fit_core(points, model="smooth", start_curvature=0.0)
        App.Units.setSchema(1)
        said = [w for w in U.say(r["warnings"]) if "the end conditions" in w]
        self.assertEqual(len(said), 1, r["warnings"])
        free, rms = r["free_rms"], r["rms"]
        self.assertTrue(0.1 < free < rms < 100.0, (free, rms))   # mm under MKS
        self.assertTrue(said[0].startswith(
            f"the end conditions (Start curvature) raise the rms from {free:.3g} mm (free "
            f"ends) to {rms:.3g} mm: "), said[0])
        for number, unit in FIGURE.findall(said[0]):
            self.assertEqual(unit, "mm", said[0])
        App.Units.setSchema(0)
        self.assertEqual(U.say(r["warnings"])[0], said[0])      # Standard: the same text

    def test_length_box_text(self):
        """A length box (units.box_text) in the unit FreeCAD's box shows for the value, to
        the digits of its value in mm (at least 3 in another unit) and no more than 6, in
        fixed notation down to 1e-6 of that unit: Tolerance 0.001 mm under Imperial
        decimal '0.0000394 in' (it showed '3.93701e-05 in'; FreeCAD's box '0.00 in')."""
        App.Units.setSchema(3)
        self.assertEqual(U.box_text(0.001), "0.0000394 in")
        self.assertEqual(U.box_text(151.0), "5.94 in")
        self.assertEqual(U.box_text(177.8), "7 in")            # typed '7 in'
        self.assertEqual(U.box_text(150.01875), "5.90625 in")  # typed '5.90625 in'
        self.assertEqual(U.box_text(1e6), "39370 in")          # not '39400 in'
        for schema in SCHEMAS:
            App.Units.setSchema(schema)
            for mm in (1e-9, 1e-5, 0.001, 0.0254, 0.5, 2.42, 151.0, 177.8, 1234.5678, 1e6):
                with self.subTest(schema=schema, mm=mm):
                    text = U.box_text(mm)
                    number, unit = text.rsplit(" ", 1)
                    factor, want = preferred(mm)
                    self.assertEqual(unit, want, text)
                    x = mm / factor
                    self.assertEqual("e" in number, abs(x) < 1e-6, text)
                    self.assertLessEqual(digits(f"{float(number):g}"), 6, text)
                    n = digits(number.rstrip("0")) if "." in number else digits(number)
                    # correctly rounded to the digits it shows
                    self.assertLessEqual(abs(float(number) - x),
                                         0.5 * 10.0 ** (np.floor(np.log10(abs(x))) - n + 1)
                                         * (1 + 1e-9), text)
        App.Units.setSchema(0)
        self.assertEqual([U.box_text(v) for v in (0.0, 0.001, 151.0, 150.019)],
                         ["0 mm", "1 \u00b5m", "151 mm", "150.019 mm"])   # as before


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
