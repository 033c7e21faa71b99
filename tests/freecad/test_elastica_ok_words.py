"""freecadcmd -t test of what a failed OK says (okcopy.Attempt.said), per what OK was to do
(review revB 3): every case ended 'Choose another sketch, or Cancel', also with no copy
(where 'nothing was written' is false: the panel's edits stay set) and for a new sketch
(there is no other new sketch to choose)."""
import unittest

import elastica_samples as S
from freecad.elastica import okcopy
from test_elastica_copy_into import _waves_quad


class OkWordsTest(S.DocTest):
    doc_name = "OkWords"

    def setUp(self):
        super().setUp()
        _src, self.q = _waves_quad(self.doc, 1.5)
        self.prof = self.doc.addObject("Sketcher::SketchObject", "Prof")
        self.prof.Label = "Profile"
        self.doc.recompute()

    def said(self, target, exc):
        return okcopy.Attempt(self.doc, self.q, target).said(exc)

    def test_into_a_sketch(self):
        self.assertEqual(self.said("Prof", ValueError("Sketcher refused a constraint")),
                         "Copy into Profile failed, nothing was written: Sketcher refused "
                         "a constraint. Choose another sketch, or Cancel")

    def test_into_a_sketch_gone(self):
        attempt = okcopy.Attempt(self.doc, self.q, "Prof")
        self.doc.removeObject("Prof")
        said = attempt.said(AttributeError("'NoneType' object has no attribute 'InList'"))
        self.assertEqual(said, "Copy into Prof failed, nothing was written: that sketch is "
                         "no longer in the document. Choose another sketch, or Cancel")

    def test_into_a_new_sketch(self):
        said = self.said("*new*", ValueError("no plane"))
        self.assertEqual(said, "Copy into a new sketch failed, no sketch was made: no plane. "
                         "Choose a sketch or '(no copy)', or Cancel")
        self.assertNotIn("another sketch", said)

    def test_no_copy(self):
        said = self.said("", ValueError("Step: must be positive"))
        self.assertEqual(said, "OK failed: Step: must be positive. The panel's edits stay "
                         "set: change them, or Cancel to drop them")
        self.assertNotIn("nothing was written", said)

    def test_recompute_failed(self):
        self.assertEqual(self.said("", okcopy.Unsolved("2 points: a fit needs at least 6")),
                         "OK failed: the curve's recompute failed: 2 points: a fit needs at "
                         "least 6. The panel's edits stay set: fix the curve's input, or Cancel "
                         "to drop them")
        self.assertEqual(self.said("Prof", okcopy.Unsolved("2 points")),
                         "Copy into Profile failed, nothing was written: the curve's "
                         "recompute failed: 2 points. Fix its input, or Cancel")


if __name__ == "__main__":
    unittest.main()
