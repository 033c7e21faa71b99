"""freecadcmd -t test of the blend panel's Solutions rows (units.unbroken, what
BlendPanel.refresh lists): Qt may wrap a row only between quantities, never inside one
(QA24gui F6: 'energy 0.0483/' | 'mm' at 1024x768). Qt's own line breaking
(QTextBoundaryFinder, the rules its list items wrap by) says where a row may break."""
import re
import unittest

from PySide.QtCore import QTextBoundaryFinder

import elastica_samples as S
from freecad.elastica import blend as B
from freecad.elastica import units

# a number and its unit, as the rows write them (the spaces and joiner unbroken puts in)
QUANTITY = re.compile("[0-9.]+(?:e[-+]?[0-9]+)?(?:[ \u00a0]|/\u2060?)[^\\W\\d_][\\w\u00b2/\u2060]*")


def _breaks(text):
    f = QTextBoundaryFinder(QTextBoundaryFinder.Line, text)
    out, p = [], f.toNextBoundary()
    while 0 < p < len(text):
        out.append(p)
        p = f.toNextBoundary()
    return out


def _split_quantities(text):
    """The quantities of ``text`` a line break may fall inside."""
    return [m.group() for m in QUANTITY.finditer(text)
            if any(m.start() < p < m.end() for p in _breaks(text))]


class SolutionRowsTest(S.DocTest):
    doc_name = "SolutionRows"

    def test_no_row_may_break_inside_a_quantity(self):
        sk = S.two_lines_sketch(self.doc)
        b = B.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="tension", Tension=0.001)
        self.doc.recompute()
        rows = B.descriptions(b)
        self.assertTrue(rows)
        # the rows as main listed them: breaks inside '0.0483/mm', '48.16 mm'
        self.assertTrue(all(_split_quantities(r) for r in rows))
        for r in rows:
            shown = units.unbroken(r)
            self.assertEqual(_split_quantities(shown), [], shown)
            self.assertEqual(shown.replace("\u00a0", " ").replace("\u2060", ""), r)
            self.assertTrue(_breaks(shown), shown)              # it still wraps, between


if __name__ == "__main__":
    unittest.main()
