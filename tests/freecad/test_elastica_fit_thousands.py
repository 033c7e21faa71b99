"""freecadcmd -t test: a fit of a ';' separated point file whose numbers do not show whether
'.' groups thousands (every one d.ddd: Excel's #.##0 in a decimal-comma locale, or three
decimals) is refused naming the fit's Thousands property (it named the command line's
--thousands and read_points' thousands=, which the workbench has not: QA), and read as the
property says: '.' groups thousands, none reads decimal points, auto what the file shows."""
import math
import unittest

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica import fit as Fi

XS = range(1, 10)


def _ys(x):
    return 2.0 + 0.5 * math.sin(x)


class FitThousandsTest(S.DocTest):
    doc_name = "ElasticaFitThousands"

    def assertPoints(self, f, xy):
        """The fit's DataPoints are ``xy`` (to 1e-9 mm: they pass through its plane)."""
        self.assertEqual(len(f.DataPoints), len(xy))
        for p, (x, y) in zip(f.DataPoints, xy):
            self.assertLess(max(abs(p.x - x), abs(p.y - y), abs(p.z)), 1e-9, (p, x, y))

    def _file(self, rows):
        path = S.temp_path(self, "scan.csv")
        with open(path, "w") as fh:
            fh.write("x;y\n" + "".join(f"{r}\n" for r in rows))
        return path

    def test_an_ambiguous_file_names_the_property_and_reads_as_it_says(self):
        path = self._file(f"{x}.000;{_ys(x):.3f}" for x in XS)
        f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
        self.assertEqual(f.getEnumerationsOfProperty("Thousands"), ["auto", ".", "none", ","])
        self.assertEqual(f.Thousands, "auto")
        self.doc.recompute()
        self.assertTrue(f.Status.startswith("error") and "Thousands property" in f.Status,
                        f.Status)
        self.assertNotIn("--thousands", f.Status)
        self.assertNotIn("read_points", f.Status)
        f.Thousands = "."
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertPoints(f, [(1000.0 * x, float(f"{_ys(x):.3f}") * 1000) for x in XS])
        f.Thousands = "none"
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertPoints(f, [(float(x), float(f"{_ys(x):.3f}")) for x in XS])

    def test_the_command_reads_the_file_as_its_thousands_option_says(self):
        """commands.fit_sources(..., Thousands='.') checks the file read so and makes the
        fit with that property (its check read the file as auto and refused it: no fit
        made whose property could be set)."""
        path = self._file(f"{x}.000;{_ys(x):.3f}" for x in XS)
        said = []
        f = C.fit_sources([], csv_file=path, open_panel=False, wrong=said.append,
                          Model="smooth", Thousands=".")
        self.assertIsNotNone(f, said)
        self.assertEqual(f.Thousands, ".")
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertPoints(f, [(1000.0 * x, float(f"{_ys(x):.3f}") * 1000) for x in XS])

    def test_the_csv_command_asks_where_the_file_does_not_show_it(self):
        """The Fit-to-CSV command (commands.csv_thousands) asks how to read a file that does
        not show it and passes the answer as Thousands: it had no way to (the check refused
        the file, no fit was made whose property could be set); it does not ask where the
        file shows it, and a cancelled question makes nothing."""
        asked = []

        def answer(choice):
            return lambda p, sep: asked.append((p, sep)) or choice

        path = self._file(f"{x}.000;{_ys(x):.3f}" for x in XS)
        opts = C.csv_thousands(path, answer("none"))
        self.assertEqual((opts, asked), ({"Thousands": "none"}, [(path, ".")]))
        f = C.fit_sources([], csv_file=path, open_panel=False, Model="smooth", **opts)
        self.assertIsNotNone(f)
        self.assertPoints(f, [(float(x), float(f"{_ys(x):.3f}")) for x in XS])
        self.assertIsNone(C.csv_thousands(path, answer(None)))
        asked.clear()
        shown = self._file(f"{x}.000,5;{x * x},25" for x in XS)
        self.assertEqual((C.csv_thousands(shown, answer(".")), asked), ({}, []))
        self.assertEqual(C.csv_thousands(path + ".missing", answer(".")), {})

    def test_auto_reads_what_the_file_shows(self):
        """A decimal comma shows the grouping (1.000,5): auto reads it so, as the command
        line does."""
        path = self._file(f"{x}.000,5;{x * x},25" for x in XS)
        f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertPoints(f, [(1000.0 * x + 0.5, x * x + 0.25) for x in XS])

    def test_english_thousands_between_tabs(self):
        """A tab export whose every number is d,ddd (English #,##0 of whole mm, or decimal
        commas with 3 decimals) is refused naming the property, which now has ',' (the
        library reads ',' grouping: read_points(thousands=','); the panel offered only '.'
        or none, both reading 1,250 as 1.25): ',' reads 1250, none 1.25; the Fit-to-CSV
        command asks about ',' (it asked whether '.' groups thousands); a 1,250.5 shows it."""
        path = S.temp_path(self, "scan.txt")
        with open(path, "w") as fh:
            fh.write("".join(f"{1000 + 10 * x:,}\t{2000 + x * x:,}\n" for x in XS))
        f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
        self.doc.recompute()
        self.assertTrue(f.Status.startswith("error") and "Thousands property: '.', ',' or none"
                        in f.Status and "'1,010' is 1.01 or 1010" in f.Status, f.Status)
        f.Thousands = ","
        self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        self.assertPoints(f, [(1000.0 + 10 * x, 2000.0 + x * x) for x in XS])
        f.Thousands = "none"
        self.doc.recompute()
        self.assertPoints(f, [(1.0 + x / 100, 2.0 + x * x / 1000) for x in XS])
        asked = []
        opts = C.csv_thousands(path, lambda p, sep: asked.append(sep) or sep)
        self.assertEqual((opts, asked), ({"Thousands": ","}, [","]))
        shown = S.temp_path(self, "shown.txt")
        with open(shown, "w") as fh:
            fh.write("".join(f"{1000 + 10 * x:,.1f}\t{2000 + x * x:,}\n" for x in XS))
        self.assertEqual(C.csv_thousands(shown, lambda p, sep: asked.append(sep) or sep), {})
        self.assertEqual(asked, [","])


    def test_a_document_saved_before_the_comma_choice_keeps_its_choice(self):
        """A fit saved before ',' was a Thousands choice holds the 3-value list in its file:
        reopened, the list has ',' (else the panel's 4th row and the property editor could
        not choose it) and the saved choice is kept, reading the file as before, the fit
        not touched by the opening (a reopened document needs no recompute)."""
        path = self._file(f"{x}.000;{_ys(x):.3f}" for x in XS)
        for choice, xy in ((".", [(1000.0 * x, float(f"{_ys(x):.3f}") * 1000) for x in XS]),
                           ("none", [(float(x), float(f"{_ys(x):.3f}")) for x in XS])):
            f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
            f.Thousands = ["auto", ".", "none"]          # the list a document before held
            f.Thousands = choice
            self.doc.recompute()
            self.assertPoints(f, xy)
            f, = S.reopened(self, f"old_{choice}.FCStd", f.Name)
            self.assertEqual(f.getEnumerationsOfProperty("Thousands"), ["auto", ".", "none", ","])
            self.assertEqual(f.Thousands, choice)
            self.assertNotIn("Touched", f.State)
            f.touch()
            self.doc.recompute()
            self.assertFalse(f.Status.startswith("error"), f.Status)
            self.assertPoints(f, xy)

if __name__ == "__main__":
    unittest.main()
