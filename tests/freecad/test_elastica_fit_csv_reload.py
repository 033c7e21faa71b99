"""freecadcmd -t test: a fit of a CSV file reads the file again at a recompute once it
changed on disk (QA17 P10: the file re-exported, moved 100 mm, a recompute kept the old
points with State 'Up-to-date' until the feature was touched; after reopening too), says
so in the report view, and does not refit a file that did not change."""
import os

import elastica_samples as S
from freecad.elastica import fit as Fi


def _write(path, xy, dx=0.0, dy=0.0, later=0):
    """The points (shifted) as a CSV file, its modification time ``later`` s after the
    previous one (a re-export)."""
    before = os.stat(path).st_mtime_ns if os.path.exists(path) else None
    with open(path, "w") as fh:
        for x, y in xy:
            fh.write(f"{x + dx:.6f},{y + dy:.6f}\n")
    if before is not None:
        os.utime(path, ns=(before + later * 10**9, before + later * 10**9))


class FitCsvReloadTest(S.DocTest):
    doc_name = "ElasticaFitCsvReload"

    def test_a_changed_file_is_read_again(self):
        xy, _ = S.keyline_xy(30)
        path = S.temp_path(self, "scan.csv")
        _write(path, xy)
        f = Fi.make(self.doc, [], csv_file=path)
        self.doc.recompute()
        first = f.DataPoints[0]
        self.assertEqual(self.doc.recompute(), 0)          # unchanged: nothing refitted
        _write(path, xy, dx=100.0, later=1)                  # re-exported, moved 100 mm
        with S.Said("PrintMessage") as m:
            self.assertEqual(self.doc.recompute(), 1)
        self.assertAlmostEqual((f.DataPoints[0] - first).x, 100.0, delta=1e-9)
        self.assertNotIn("Invalid", f.State)
        self.assertEqual(m.said, [f"Elastica {f.Label}: {path} changed on disk: read again\n"])
        self.assertEqual(self.doc.recompute(), 0)
        # the same size (another scan of as many digits), a later time: read again
        _write(path, xy, dx=100.0, dy=0.5, later=2)
        self.doc.recompute()
        self.assertAlmostEqual((f.DataPoints[0] - first).y, 0.5, delta=1e-9)
        # changed while the document was closed: its recompute reads it
        f, = S.reopened(self, "csv.FCStd", f.Name)
        _write(path, xy, dy=50.0, later=3)
        self.doc.recompute()
        self.assertAlmostEqual((f.DataPoints[0] - first).y, 50.0, delta=1e-9)
        # deleted: an error at the recompute, not the old points as up to date
        os.remove(path)
        self.doc.recompute()
        self.assertIn("Invalid", f.State)
        self.assertIn("no such file", f.Status)
