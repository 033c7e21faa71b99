"""freecadcmd -t tests of the unit each length of a text or a length box is written in: the
one FreeCAD's schema picks for that value (Quantity.getUserPreferred, as its UserString and
Gui::QuantitySpinBox), written as FreeCAD writes it at the Decimals preference (units.say's
marks, units.box_text: units.number_text), tested at 2 and 6 decimals.
Under MKS the fit's warning said '0.00029 m' where FreeCAD writes '0.29 mm', and the
spline's, by length_text, '3.25 mm': one workbench, two rules."""
import re
import sys
import unittest

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


def freecad_number(mm, d):
    """The number FreeCAD writes ``mm`` millimetres as at ``d`` decimals (its UserString's,
    FreeCAD's own call), where that keeps d significant digits (at least 0.1 of the unit);
    below, d significant digits in fixed notation (units.number_text, where FreeCAD's
    '0.00' does not suffice), below 1e-6 of the unit with an exponent."""
    q = App.Units.Quantity(float(mm), App.Units.Length)
    q.Format = {"Precision": d}
    text, factor, _ = q.getUserPreferred()
    x = mm / factor
    if x == 0.0 or abs(x) >= 0.1:
        mine = f"{x:.{d}f}"
        if App.Units.getSchema() != 5:          # (Building US: feet and inches)
            assert text.rsplit(" ", 1)[0] == mine, (text, mine)
        return mine
    if abs(x) < 1e-6:                           # an exponent, as FreeCAD's Imperial schemas
        return f"{x:.{d - 1}e}"
    return f"{x:.{d - 1 - int(np.floor(np.log10(abs(x))))}f}"


class UnitsPerValueTest(unittest.TestCase):
    """Each test at the Decimals preference 2 (FreeCAD's default) and 6, restored after."""

    def setUp(self):
        self.schema = App.Units.getSchema()
        self.prefs = App.ParamGet(U.UNITS_PREFERENCES)
        self.decimals = self.prefs.GetInt("Decimals", -1)

    def tearDown(self):
        App.Units.setSchema(self.schema)
        if self.decimals < 0:
            self.prefs.RemInt("Decimals")
        else:
            self.prefs.SetInt("Decimals", self.decimals)

    def at_decimals(self):
        for d in (2, 6):
            self.prefs.SetInt("Decimals", d)
            self.assertEqual(U.decimals(), d)
            yield d

    def assert_written(self, text, mm, d):
        """``text`` ('<number> <unit>') is ``mm`` in the unit FreeCAD picks for it, written
        as FreeCAD writes it at ``d`` decimals (freecad_number)."""
        m = FIGURE.fullmatch(text)
        self.assertIsNotNone(m, text)
        factor, unit = preferred(mm)
        self.assertEqual(m.group(2), unit, (text, mm, App.Units.getSchema()))
        self.assertEqual(m.group(1), freecad_number(mm, d), (text, mm, d))

    def assert_kept(self, text, written, d):
        """``text`` is a '<number> mm' mark ``written`` in the unit FreeCAD picks for it: as
        FreeCAD writes it at ``d`` decimals where that keeps the written significant
        digits, else to those digits (in mm as written: a library's bound, 'any length
        above 328.182 mm', is not rounded below itself)."""
        m, mm = FIGURE.fullmatch(text), float(written)
        self.assertIsNotNone(m, text)
        factor, unit = preferred(mm)
        self.assertEqual(m.group(2), unit, (text, mm, App.Units.getSchema()))
        n = len(re.sub(r"e.*|[^0-9]", "", written).lstrip("0"))
        if unit == "mm":            # as written: not one digit lost
            self.assertEqual(float(f"{float(m.group(1)):.{n}g}"), mm, (text, d))
        fc = freecad_number(mm, d)
        if float(f"{float(fc) * factor:.{n}g}") == mm:
            self.assertEqual(m.group(1), fc, (text, mm, d))

    def test_marked_lengths_take_the_unit_freecad_picks_for_each(self):
        """Under every schema each exact mark and '<number> mm' mark is written in the unit
        getUserPreferred gives its value (MKS: 0.50 mm, 2.42 mm and 0.12 m in one message at
        2 decimals, 0.496000 mm, 2.420000 mm, 0.119200 m at 6), as FreeCAD writes it; on the
        old code one unit per schema (0.000496 m)."""
        values = (0.0004, 0.0496, 0.496, 2.42, 9.05, 115.6, 119.2, 4000.0, 2.5e6)
        for d in self.at_decimals():
            for schema in SCHEMAS:
                App.Units.setSchema(schema)
                for mm in values:
                    with self.subTest(schema=schema, mm=mm, d=d):
                        self.assert_written(U.say(U.exact_mark(mm)), mm, d)
                        self.assert_kept(U.say(U.mm_marked(f"{mm:g} mm")), f"{mm:g}", d)
                        self.assert_written(U.say(U.exact_mark(mm, 4)), mm, d)
                        self.assert_written(U.length_text(mm), mm, d)

    def test_a_range_is_written_in_the_unit_of_its_end(self):
        """'9.05 to 160 mm' under MKS: both in m (FreeCAD's unit of 160 mm), the first not
        in the schema's unit beside the second's; coordinates named by the unit mark keep
        the schema's one unit."""
        App.Units.setSchema(1)
        want = {2: ("lie 0.00905 to 0.16 m", "lie 9.05 to 16.00 mm", "at (0.22, -0.00050) m"),
                6: ("lie 0.00905000 to 0.160000 m", "lie 9.050000 to 16.000000 mm",
                    "at (0.219900, -0.000500000) m")}
        for d in self.at_decimals():
            self.assertEqual(U.say(U.mm_marked("lie 9.05 to 160 mm")), want[d][0])
            self.assertEqual(U.say(U.mm_marked("lie 9.05 to 16 mm")), want[d][1])
            self.assertEqual(U.say(f"lie {U.exact_mark(9.05, 3, False)} to "
                                   f"{U.exact_mark(16.0, 3)}"), want[d][1])
            self.assertEqual(U.say(f"at ({U.coordinate_mark(219.9)}, {U.coordinate_mark(-0.5)}) "
                                   f"{U.length_unit_mark()}"), want[d][2])

    def test_fit_warning_under_mks_says_what_freecad_says(self):
        """A natural start where the noisy S curves (test_elastica_fit_cost's): under MKS the
        end-condition warning gives both rms in mm as FreeCAD writes them ('0.29 mm',
        '1.65 mm' at 2 decimals), as the spline's gap warning does; it said '0.000289 m'
        and '0.00165 m'."""
        xy, _ = S.keyline_xy(40)
        xy = xy + np.random.default_rng(3).normal(0.0, 0.3, xy.shape)
        points = [App.Vector(float(x), float(y), 0.0) for x, y in xy]
        r = fit_core(points, model="smooth", start_curvature=0.0)
        free, rms = r["free_rms"], r["rms"]
        self.assertTrue(0.1 < free < rms < 100.0, (free, rms))   # mm under MKS
        for d in self.at_decimals():
            App.Units.setSchema(1)
            said = [w for w in U.say(r["warnings"]) if "the end conditions" in w]
            self.assertEqual(len(said), 1, r["warnings"])
            self.assertTrue(said[0].startswith(
                f"the end conditions (Start curvature) raise the rms from "
                f"{freecad_number(free, d)} mm (free ends) to {freecad_number(rms, d)} mm: "),
                said[0])
            for number, unit in FIGURE.findall(said[0]):
                self.assertEqual(unit, "mm", said[0])
            App.Units.setSchema(0)
            self.assertEqual(U.say(r["warnings"])[0], said[0])      # Standard: the same text

    def test_length_box_text(self):
        """A length box (units.box_text) in the unit FreeCAD's box shows for the value, as
        it writes it at the Decimals preference (freecad_number): '151.00 mm' at 2,
        '151.000000 mm' at 6; below 0.1 of the unit to d significant digits: Tolerance
        0.001 mm under Imperial decimal '0.000039 in' at 2 (FreeCAD's box '0.00 in')."""
        want = {2: ("0.000039 in", "5.94 in", "7.00 in"),
                6: ("0.0000393701 in", "5.944882 in", "7.000000 in")}
        for d in self.at_decimals():
            App.Units.setSchema(3)
            self.assertEqual((U.box_text(0.001), U.box_text(151.0), U.box_text(177.8)), want[d])
            for schema in SCHEMAS:
                App.Units.setSchema(schema)
                for mm in (1e-5, 0.001, 0.0254, 0.5, 2.42, 151.0, 177.8, 1234.5678, 1e6):
                    with self.subTest(schema=schema, mm=mm, d=d):
                        self.assert_written(U.box_text(mm), mm, d)
            App.Units.setSchema(0)
            self.assertEqual([U.box_text(v) for v in (0.0, 0.001, 151.0)],
                             [f"{0:.{d}f} mm", f"{1:.{d}f} \u00b5m", f"{151:.{d}f} mm"])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
