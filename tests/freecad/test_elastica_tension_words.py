"""freecadcmd -t tests of a tension refused as the report view says it (QA23gui F10): the
property editor's Tension = -0.5 on a spline said 'Tension = -0.5 1/mm^2 is not usable: it
must be >= 0 ...' while the panel's boxes and Status write 1/mm\u00b2; it is said in the
schema's 1/unit\u00b2 as they are (1/in\u00b2 under Imperial decimal)."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl
from freecad.elastica import spline as Sp

STANDARD, IMPERIAL_DECIMAL = 0, 3


class TensionWordsTest(S.DocTest):
    doc_name = "ElasticaTensionWordsTest"

    def setUp(self):
        super().setUp()
        self.addCleanup(App.Units.setSchema, App.Units.getSchema())

    def refused(self, feature, value):
        """(report view text, Status) of feature.Tension = value recomputed."""
        feature.Tension = value
        said, _ = S.console_output(self.doc.recompute)
        return said, feature.Status

    def test_a_negative_tension_in_the_panels_unit(self):
        App.Units.setSchema(STANDARD)
        sk = S.points_sketch(self.doc, S.keyline_xy(8)[0])
        s = Sp.make(self.doc, [(sk, [])], Mode="tension")
        self.doc.recompute()
        said, status = self.refused(s, -0.5)
        self.assertIn("Tension = -0.50 1/mm\u00b2 is not usable: it must be >= 0.00 1/mm\u00b2", said)
        self.assertIn("Tension = -0.50 1/mm\u00b2 is not usable", status)
        self.assertNotIn("mm^2", said)
        App.Units.setSchema(IMPERIAL_DECIMAL)
        said, _ = self.refused(s, -0.25)
        self.assertIn(f"Tension = {-0.25 * 25.4 ** 2:.6g} 1/in\u00b2 is not usable: it must be "
                      ">= 0.00 1/in\u00b2", said)

    def test_a_g2_blend_pushed_by_tension(self):
        App.Units.setSchema(STANDARD)
        sk = S.line_and_arc_sketch(self.doc)
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Mode="tension", Continuity="G2")
        self.doc.recompute()
        said, status = self.refused(b, -0.001)
        self.assertIn("Tension = -0.0010 1/mm\u00b2: a G2 blend is solved for a tension >= 0", said)
        self.assertNotIn("mm^2", said)
