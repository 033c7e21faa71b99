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

import elastica_samples as S
from freecad.elastica import fit as Fi


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

    def test_a_points_line_is_an_editors(self):
        pts = S.outlier_xy()
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
                                      S.outlier_said(self, f, model))
                        self.doc.removeObject(f.Name)


if __name__ == "__main__":
    unittest.main()
