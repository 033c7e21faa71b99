"""freecadcmd -t test: a Fit's warnings name a file's point by its line as a text editor
numbers it: lines end at \\n, \\r\\n or \\r alone, and a quoted field holding a line end
spans two lines, as the csv module counts them. io's reading split the text with
str.splitlines, which also ends a line at a form feed, U+2028 (and \\v, \\x1c-\\x1e, \\x85,
U+2029), and numbered csv's records, not lines: every point after such a character or
field was named one line too far on, or one too near ("line 19 of scan.csv" for an editor's
line 18)."""
import os
import tempfile
import unittest

import numpy as np

import elastica_samples as S
from freecad.elastica import fit as Fi
from freecad.elastica.units import say


def _hand_points():
    """20 points along a 380 mm curve (0.25 mm noise), the 12th (index 11) 6 mm across it:
    the outlier the Fit names (as test_elastica_fit_sketcher_names' hand sketch)."""
    import libelastica as el
    rng = np.random.default_rng(7)
    c = el.SmoothElastica(x0=0, y0=0, phi=0.3, mu=(1 / 120.0) ** 2, k=0.6, q=0.2, length=380.0)
    s = np.linspace(0, 380, 20)
    pts = c.points(s) + rng.normal(0, 0.25, (20, 2))
    th = float(c.angle([s[11]])[0])
    pts[11] += 6.0 * np.array([-np.sin(th), np.cos(th)])
    return pts + [1500.0, -800.0]


# what stands before the data in each file: (its lines as an editor shows them, joined
# by \n; the outlier's line there)
HEADS = {
    # a page break (form feed) in a comment: one line, not two
    "form feed": ("# hand sketch\f page 2\nx,y", 2 + 12),
    # a Unicode line separator in a title: one line, not two
    "U+2028": ("Profile 7\u2028second stroke\nx,y", 2 + 12),
    # a title quoted across two lines: two lines, as csv counts them (not one record)
    "quoted line end": ('"Profile 7\nhand sketch",\nx,y', 3 + 12),
    # all three, and a lone \r ending a comment (classic Mac): a line end
    "all": ('# a\f b\r"Profile\n7",\n# c\u2028d\nx,y', 5 + 12),
}


class FitCsvLinesTest(S.DocTest):
    doc_name = "ElasticaFitCsvLines"

    def _stray_said(self, f, model):
        said = [w for w in say(list(f.Warnings)) if "outliers?" in w]
        self.assertEqual(len(said), 1, (model, list(f.Warnings)))
        return said[0]

    def test_a_points_line_is_an_editors(self):
        pts = _hand_points()
        with tempfile.TemporaryDirectory() as tmp:
            for case, (head, line) in HEADS.items():
                path = os.path.join(tmp, "scan.csv")
                with open(path, "w", newline="") as fh:
                    fh.write(head + "\n" + "".join(f"{x:.4f},{y:.4f}\n" for x, y in pts))
                with open(path, newline="") as fh:       # the editor's count: \n, \r\n, \r
                    text = fh.read()
                row = f"{pts[11][0]:.4f},{pts[11][1]:.4f}"
                editor = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
                self.assertEqual(editor.index(row) + 1, line, case)
                for model in ("discrete", "smooth"):
                    with self.subTest(case=case, model=model):
                        f = Fi.make(self.doc, csv_file=path, Model=model)
                        self.doc.recompute()
                        self.assertIn(f"(line {line} of scan.csv, at (",
                                      self._stray_said(f, model))
                        self.doc.removeObject(f.Name)


if __name__ == "__main__":
    unittest.main()
