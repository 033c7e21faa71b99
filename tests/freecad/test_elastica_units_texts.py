"""freecadcmd -t tests of the lengths in the workbench's texts, written as its length boxes
write them (units.plain): in the unit FreeCAD's schema picks for each value, from the exact
value (a check's typed length is not its '%g' text in mm said again: rounded twice), in
fixed notation down to 1e-6 of the unit (the Fit panel said 'B-spline within 2.27e-05 in'
under Imperial decimal beside a Tolerance box of '0.0000394 in'); a measured length at
rounding noise as FreeCAD writes it at its precision ('0 mm', not '1.82e-11 mm'); numbers
written without their unit followed by it."""
import re
import sys
import unittest
from decimal import Decimal

import FreeCAD as App
import numpy as np

import elastica_samples as S
from freecad.elastica import fit as Fi, units as U
from freecad.elastica.proxy import InputProblem, check_number, check_tolerance, said

STANDARD, MKS, US_CUSTOMARY, IMPERIAL_DECIMAL = 0, 1, 2, 3


def reported(check, *args, **kw):
    """The text report() writes for the InputProblem ``check`` raises (mm_marked, say)."""
    try:
        check(*args, **kw)
    except InputProblem as exc:
        return U.say(U.mm_marked(str(exc)))
    raise AssertionError(f"{check.__name__}{args} raised nothing")


class UnitsTextsTest(unittest.TestCase):
    def setUp(self):
        self.schema = App.Units.getSchema()

    def tearDown(self):
        App.Units.setSchema(self.schema)

    def test_a_checked_length_is_rounded_once(self):
        """Resampling step = -0.0012345678 mm under Imperial decimal: -0.000049 in, its
        value / 25.4 to the Decimals preference (2: units.number_text's 2 significant digits
        where FreeCAD writes '0.00 in'); on the old code '-4.86051e-05 in', the
        '-0.00123457 mm' of '%g' divided again (a last digit off, and an exponent)."""
        App.Units.setSchema(IMPERIAL_DECIMAL)
        text = reported(check_number, "Resampling step", -0.0012345678, 0.0, None, "mm")
        self.assertEqual(text, "Resampling step = -0.000049 in is not usable: it must be "
                               ">= 0.00 in", text)
        self.assertEqual(f"{-0.0012345678 / 25.4:.6g}", "-4.8605e-05")
        App.Units.setSchema(MKS)
        self.assertEqual(reported(check_number, "Length", -12345.6789, 0.0, None, "mm"),
                         "Length = -12.35 m is not usable: it must be >= 0.00 m")   # FreeCAD's
        App.Units.setSchema(STANDARD)          # as before
        self.assertEqual(reported(check_number, "Length", -2.5, 0.0, None, "mm"),
                         "Length = -2.50 mm is not usable: it must be >= 0.00 mm")
        self.assertEqual(reported(check_number, "Length", float("nan"), 0.0, None, "mm"),
                         "Length = nan mm is not usable: it must be >= 0.00 mm")
        self.assertEqual(reported(check_number, "Tension", -1.0, 0.0, None, "1/mm^2"),
                         "Tension = -1.00 1/mm\u00b2 is not usable: it must be >= 0.00 1/mm\u00b2")

    def test_the_tolerance_check_says_its_bound_exactly(self):
        """check_tolerance's bound 1e-9 mm and a typed 1.2345678e-10 mm in the unit FreeCAD
        picks for each, from the exact values (old: '4.86051e-12 in', rounded twice)."""
        App.Units.setSchema(IMPERIAL_DECIMAL)
        text = reported(check_tolerance, 1.2345678e-10)
        self.assertTrue(text.startswith("Tolerance = 4.9e-12 in is not usable: it must be >= "
                                        "3.9e-11 in ("), text)     # below 1e-6: an exponent

    def test_rounding_to_digits_brackets_the_value(self):
        """floor_digits(x, d) <= x <= ceil_digits(x, d), each of at most d significant
        digits (its %g text is itself), one unit of the d-th digit apart at most; for
        values of 1e-12 .. 1e12 of either sign and reaches typed back (0.001707, 0.03046).
        A value of at most d digits is its own floor and ceil: old floor_digits(0.001707, 7)
        was 0.001706999 (0.001707 / 1e-9 is 1706999.9999999998 in floats), as 23682 of
        3.46 M (x, d) cases (/tmp/polish/floor_compare.py); the reach a G2 blend said was
        one unit below the tension that solved (g2_tension_reach rounds its 6-digit
        tensions again)."""
        rng = np.random.default_rng(5)
        xs = [float(x) for x in 10.0 ** rng.uniform(-12, 12, 400)]
        xs += [0.001707, 0.03046, 0.0017068, 1.0, 9.999999999, 12345.0, 0.1 + 0.2,
               0.00176823, 100.0, 0.3, 1e-5]
        rng = np.random.default_rng(7)
        xs += [float(f"{m}e{e}") for m, e in zip(rng.integers(1, 10 ** 8, 600),
                                                  rng.integers(-20, 12, 600))]
        for x in xs + [-x for x in xs]:
            for d in range(1, 9):
                lo, hi = U.floor_digits(x, d), U.ceil_digits(x, d)
                what = (x, d, lo, hi)
                self.assertTrue(lo <= x <= hi, what)
                for y in (lo, hi):
                    self.assertEqual(float(f"{y:.{d}g}"), y, what)
                unit = Decimal(10) ** (Decimal(abs(x)).adjusted() - d + 1)
                self.assertLessEqual(Decimal(hi) - Decimal(lo),   # floats of decimals: 1e-15
                                     unit + Decimal(abs(x)) * Decimal("1e-15"), what)
                if d >= len(Decimal(repr(x)).as_tuple().digits):
                    self.assertEqual((lo, hi), (x, x), what)

    def test_result_line_lengths_are_plain_decimals(self):
        """A result line's length (length_text: 'B-spline within ...') in the unit FreeCAD
        picks for the value, in fixed notation as the boxes: 0.000577 mm is '0.000023 in'
        under Imperial decimal (was '2.27e-05 in') and '577.00 nm' under Standard;
        1234 mm '1234.00 mm' (was '1.23e+03 mm'); below 1e-6 of the unit an exponent."""
        App.Units.setSchema(IMPERIAL_DECIMAL)
        self.assertEqual(U.length_text(0.000577), "0.000023 in")
        self.assertEqual(U.length_text(151.0), "5.94 in")
        self.assertEqual(U.say(U.exact_mark(0.0004)), "0.000016 in")
        self.assertEqual(U.say(U.length_mark(0.000577)), "0.000023 in")
        self.assertEqual(U.length_text(1e-5), "3.9e-07 in")
        App.Units.setSchema(STANDARD)
        self.assertEqual(U.length_text(0.000577), "577.00 nm")
        self.assertEqual(U.length_text(0.0227), "22.70 \u00b5m")
        self.assertEqual(U.length_text(1234.0), "1234.00 mm")
        self.assertEqual(U.length_text(1234.0, 4), "1234.00 mm")        # (a mark's digits)
        self.assertEqual(U.length_text(151.0), "151.00 mm")             # FreeCAD's UserString
        for schema in range(8):
            App.Units.setSchema(schema)
            for mm in (1e-4, 0.000577, 0.01, 0.5, 151.0, 1234.0, 9999.0, 2.5e6):
                with self.subTest(schema=schema, mm=mm):
                    number = U.length_text(mm).split(" ")[0]
                    for text in (number, U.say(U.exact_mark(mm)).split(" ")[0]):
                        self.assertEqual("e" in text, abs(float(text)) < 1e-6, text)


def zero_unit():
    """The unit FreeCAD's schema of now writes a length of 0 in ('0.00 mm', '0.00 in')."""
    return App.Units.Quantity(0.0, App.Units.Length).getUserPreferred()[2]


class MeasuredTextsTest(S.DocTest):
    doc_name = "ElasticaMeasuredTexts"
    schema = STANDARD          # (the user's restored after each test)

    def test_rounding_noise_is_written_as_freecad_writes_it(self):
        """Seven points on the sample elastica fitted by the discrete model: its warning in
        the panel (proxy.said, figures) says the smooth model's curve lies '0.00 mm' from
        them, as FreeCAD writes a length under its Confusion (1e-7 mm) at its precision
        ('0.00 in' under Imperial decimal): it said 'lies 1.82e-11 mm'. The Warnings
        property (and the report view) keep the figure; a measured length from 1e-7 mm on
        is written as before, and an input (exact_mark: a tolerance of 1e-9 mm) as it is."""
        xy, _ = S.keyline_xy(7)
        f = Fi.make(self.doc, [(S.points_sketch(self.doc, xy, "Seven"), [])], Model="discrete")
        self.doc.recompute()
        self.assertIn("converged", f.Status)
        kept = [w for w in f.Warnings if "Smooth elastica" in w]
        self.assertEqual(len(kept), 1, list(f.Warnings))
        figure = re.search("the smooth model's curve lies (\\S+) mm from them", kept[0])
        self.assertTrue(figure and 0.0 < float(figure.group(1)) < 1e-7, kept[0])
        for schema, zero in ((STANDARD, "0.00 mm"), (IMPERIAL_DECIMAL, "0.00 in")):
            App.Units.setSchema(schema)
            panel = [w for w in said(f, "Warnings", figures=True) if "Smooth elastica" in w]
            self.assertIn(f"the smooth model's curve lies {zero} from them", panel[0])
        for schema in range(8):
            App.Units.setSchema(schema)
            with self.subTest(schema=schema):
                zero = f"{U.number_text(0.0)} {zero_unit()}"
                for noise in (1.82e-11, -7.1e-15, 0.0, 9.99e-8):
                    self.assertEqual(U.figure_text(noise), zero)
                    self.assertEqual(U.say(U.figure_mark(noise, 3), figures=True), zero)
                    self.assertEqual(U.say(U.figure_mark(noise, 3)),
                                     U.say(U.exact_mark(noise, 3)))
                for mm in (1e-7, 0.000577, 151.0):
                    self.assertEqual(U.figure_text(mm), U.length_text(mm))
                    self.assertEqual(U.say(U.figure_mark(mm, 3), figures=True),
                                     U.say(U.exact_mark(mm, 3)))
                self.assertNotEqual(U.say(U.exact_mark(1e-9), figures=True), zero)

    def test_a_place_names_its_unit(self):
        """40 scanned points, noise 1 \u00b5m, two glitches 0.1 and 0.2 mm off: the warning
        gives the farthest's place with its unit, the schema's length unit as FreeCAD writes
        it after a number. Without it the place read in the unit named last: 'the others
        within 24.7 \u00b5m (the farthest at (232.7, 24.03, -13.55))' under Standard (mm read
        as \u00b5m), '0.974 thou (... (9.161, ...))' under US customary (inches as thou),
        '2.56 mm (... (0.2128, ...))' under MKS (metres as mm)."""
        xy, _ = S.keyline_xy(40)
        xy = xy + np.random.default_rng(4).normal(0.0, 0.001, xy.shape)
        xy[[10, 25]] += [[0.12, -0.09], [-0.20, 0.15]]
        f = Fi.make(self.doc, [(S.points_sketch(self.doc, xy, "Glitches"), [])], Model="smooth")
        self.doc.recompute()
        top = xy[25]                                  # in the sketch (QA qagui F6)
        for schema, unit, factor in ((STANDARD, "mm", 1.0), (MKS, "m", 1000.0),
                                     (US_CUSTOMARY, '"', 25.4), (IMPERIAL_DECIMAL, "in", 25.4)):
            App.Units.setSchema(schema)
            said_now = [w for w in said(f, "Warnings") if "outliers?" in w]
            self.assertEqual(len(said_now), 1, list(f.Warnings))
            place = ", ".join(U.number_text(v / factor) for v in top)
            self.assertIn(f"the farthest, 26-Point, in the sketch at ({place}) {unit}): ",
                          said_now[0])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
