"""freecadcmd -t tests of the notes and warnings said again in the unit schema of now, without
a recompute (units.say): the spline's starting-tension note and the blend's starting length
(the panel's warning line), the elliptic blend's loop warning, the comb's scale."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl, ellblend as El, spline as Sp
from freecad.elastica.proxy import said
from freecad.elastica.units import say


class SaidNotesTest(unittest.TestCase):
    def setUp(self):
        self.doc = S.new_doc("ElasticaSaidNotesTest")
        self.schema = App.Units.getSchema()
        App.Units.setSchema(0)

    def tearDown(self):
        App.Units.setSchema(self.schema)
        App.closeDocument(self.doc.Name)

    def test_starting_tension_note_follows_the_schema(self):
        """The spike's ducks (no free batten): the note made under Standard, said under
        Imperial decimal (the panel says it at each refresh), gives the tension and the
        polygon in inches; it kept 1/mm\u00b2 and mm."""
        spike = [App.Vector(x, y, 0) for x, y in
                 [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]]
        tension, note = Sp.starting_tension(spike)
        self.assertEqual(tension, 6.57e-5)
        self.assertIn("Tension = 6.57e-05 1/mm\u00b2 instead (10 / the 390.2 mm polygon",
                      say(note))
        App.Units.setSchema(3)
        # 6.57e-5 / mm^2 x 25.4^2 = 0.042387 / in^2; 390.25 mm = 15.36 in
        self.assertIn("Tension = 0.042387 1/in\u00b2 instead (10 / the 15.36 in polygon",
                      say(note))

    def test_starting_length_note_follows_the_schema(self):
        """A line's end and an arc's end no free batten joins: by 1.5 x their 75 mm; the
        note (the blend panel's warning line) said under Imperial decimal in inches."""
        sk = S.line_and_arc_sketch(self.doc)
        e1, e2 = sk.Shape.Edges
        a, b = Bl.nearest_ends(e1, e2)
        length, note = Bl.free_or_length(e1, a, e2, b)
        self.assertEqual(length, 112.0)
        self.assertIn("solved for a length instead, 112 mm (1.5 \u00d7 the 75 mm between",
                      say(note))
        App.Units.setSchema(3)
        self.assertIn("instead, 4.40945 in (1.5 \u00d7 the 2.953 in between", say(note))

    def test_elliptic_blend_loop_said_again(self):
        """A looping interpolation recomputed under Standard: its panel opened under
        Imperial decimal says the loop's chord and width in inches (they kept mm's
        figures: 'chord 100'), from the exact figures; back in mm under Standard."""
        pts = [(0.0, 0.0), (30.0, 80.0), (70.0, 90.0), (100.0, 0.0)]
        sk = S.points_sketch(self.doc, pts, "Looping")
        f = El.make(self.doc, [(sk, [])], K=0.52, KConvention="parameter")
        self.doc.recompute()
        before = list(f.Warnings)
        self.assertIn("between points 0 and 3 (counted from 0; chord 100", before[1])
        App.Units.setSchema(3)
        shown = said(f, "Warnings")
        self.assertIn("between points 0 and 3 (counted from 0; chord 3.94", shown[1])
        self.assertEqual(shown[0], before[0])           # ratios: no length
        self.assertEqual(said(f, "Status"), "; ".join(["ok"] + [f"warning: {w}" for w in shown]))
        App.Units.setSchema(0)
        self.assertEqual(said(f, "Warnings"), before)

    def test_comb_scale_in_the_schema(self):
        """The comb panel's 'scale ... mm\u00b2' line in the square of the schema's unit."""
        from freecad.elastica.units import area_text
        self.assertEqual(area_text(645.16), "645.2 mm\u00b2")
        App.Units.setSchema(3)
        self.assertEqual(area_text(645.16), "1 in\u00b2")


if __name__ == "__main__":
    unittest.main()
