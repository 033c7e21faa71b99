"""freecadcmd -t test: a fit of a points file reads the unit its header names and converts
it to FreeCAD's mm (sources.gather_points read every file as mm: 'x [m],y [m]' fitted
1000 x too small, 'x [in],y [in]' 25.4 x): m, in, um and a file without a unit (mm, as
before) give the same points in mm; a unit that is no length (px) reads as mm, said once
in the report view."""

import elastica_samples as S
from freecad.elastica import fit as Fi

# mm in one of each header's unit (None: no unit in the header; pt: the typographic point,
# 1/72 in, which FreeCAD's units do not know)
UNITS = {"m": 1000.0, "in": 25.4, "um": 1e-3, "pt": 25.4 / 72, None: 1.0}


class FitCsvUnitTest(S.DocTest):
    doc_name = "ElasticaFitCsvUnit"

    def _file(self, name, unit, xy_mm):
        """The points ``xy_mm`` written in ``unit`` (17 digits: read back exactly) under the
        header 'x [unit],y [unit]' (none: 'x,y')."""
        path = S.temp_path(self, name)
        head = "x,y" if unit is None else f"x [{unit}],y [{unit}]"
        per = UNITS.get(unit, 1.0)
        with open(path, "w") as fh:
            fh.write(head + "\n" + "".join(f"{x / per!r},{y / per!r}\n" for x, y in xy_mm))
        return path

    def test_a_header_unit_is_read_as_mm(self):
        xy, _ = S.keyline_xy(30)
        for unit in UNITS:
            with self.subTest(unit=unit):
                f = Fi.make(self.doc, [], csv_file=self._file(f"scan_{unit}.csv", unit, xy),
                            Model="smooth")
                self.doc.recompute()
                self.assertFalse(f.Status.startswith("error"), f.Status)
                self.assertEqual(len(f.DataPoints), len(xy))
                for p, (x, y) in zip(f.DataPoints, xy):
                    # the file's numbers are x / per: back to mm within rounding
                    self.assertLess(max(abs(p.x - x), abs(p.y - y), abs(p.z)),
                                    1e-9 * max(1.0, abs(x), abs(y)), (unit, p, x, y))
                self.assertFalse([w for w in f.Warnings if "header" in w], f.Warnings)

    def test_a_unit_of_no_length_reads_as_mm_said_once(self):
        xy, _ = S.keyline_xy(30)
        path = self._file("picture.csv", "px", xy)
        with S.Said() as w:
            f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
            self.doc.recompute()
            f.touch()
            self.doc.recompute()
        self.assertFalse(f.Status.startswith("error"), f.Status)
        for p, (x, y) in zip(f.DataPoints, xy):
            self.assertLess(max(abs(p.x - x), abs(p.y - y)), 1e-9 * max(1.0, abs(x), abs(y)))
        note = [s for s in w.said if "px" in s]
        self.assertEqual(note, [f"Elastica {f.Label}: picture.csv's header names its "
                                "coordinates in px, which is no length: read as mm\n"], w.said)


class FitCsvUnitSaidTest(S.DocTest):
    """The conversion is said: '; scan.csv read in m, converted to mm' in the Status (one
    line), once in the report view per change of the unit; and a document saved before the
    unit was read (CsvUnit '?', its DataPoints the file's numbers as mm) is told once that
    its fit changed size at this recompute."""
    doc_name = "ElasticaFitCsvUnitSaid"

    def _fit(self, unit):
        xy, _ = S.keyline_xy(30)
        path = FitCsvUnitTest._file(self, f"scan_{unit}.csv", unit, xy)
        with S.Said() as w, S.Said("PrintMessage") as m:
            f = Fi.make(self.doc, [], csv_file=path, Model="smooth")
            self.doc.recompute()
            f.touch()
            self.doc.recompute()
        return f, m.said, w.said

    def test_the_conversion_is_said_in_the_status_and_once_in_the_report(self):
        for unit in ("m", "in", "um"):
            with self.subTest(unit=unit):
                f, said, warned = self._fit(unit)
                self.assertEqual(f.Status, f"converged; scan_{unit}.csv read in {unit}, "
                                           "converted to mm")
                self.assertEqual([t for t in said if "converted" in t],
                                 [f"Elastica {f.Label}: scan_{unit}.csv read in {unit}, "
                                  "converted to mm\n"], said)
                self.assertFalse([t for t in warned if "converted" in t], warned)
        f, said, _ = self._fit(None)
        self.assertEqual(f.Status, "converged")
        self.assertFalse([t for t in said if "converted" in t], said)

    def test_a_document_saved_before_is_told_its_fit_changed_once(self):
        f, _, _ = self._fit("m")
        # as a document saved before c48294f holds it: the file's numbers read as mm
        f.CsvUnit = "?"
        f.DataPoints = [p * 1e-3 for p in f.DataPoints]
        with S.Said() as w:
            f.touch()
            self.doc.recompute()
            f.touch()
            self.doc.recompute()
        said = [t for t in w.said if "saved before" in t]
        self.assertEqual(said, [f"Elastica {f.Label}: this document, saved before a points "
                                "file's header unit was read, fitted scan_m.csv's numbers as "
                                "mm; its header names m: scan_m.csv read in m, converted to "
                                "mm now, so the fit is 1000 x the size it was\n"], w.said)
        self.assertEqual(f.CsvUnit, "m")
        self.assertTrue(f.Status.endswith("; scan_m.csv read in m, converted to mm"), f.Status)
        # a document saved after, or one whose fit was of the mm points: nothing said
        f.CsvUnit = "?"
        with S.Said() as w:
            f.touch()
            self.doc.recompute()
        self.assertFalse([t for t in w.said if "saved before" in t], w.said)
