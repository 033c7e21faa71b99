"""freecadcmd -t tests of the notes and warnings said again in the unit schema of now, without
a recompute (units.say): the spline's starting-tension note and the blend's starting length
(the panel's warning line), the elliptic blend's loop warning, the comb's scale."""
import unittest

import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as Bl, blend_start as Bs, ellblend as El, spline as Sp
from freecad.elastica.proxy import said
from freecad.elastica.units import say


class SaidNotesTest(S.DocTest):
    doc_name = "ElasticaSaidNotesTest"
    schema = 0

    def test_starting_tension_note_follows_the_schema(self):
        """The spike's ducks (no free batten): the note made under Standard, said under
        Imperial decimal (the panel says it at each refresh), gives the tension and the
        polygon in inches; it kept 1/mm\u00b2 and mm."""
        spike = [App.Vector(x, y, 0) for x, y in
                 [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]]
        tension, note = Sp.starting_tension(spike)
        self.assertEqual(tension, 6.57e-4)   # the least that holds
        self.assertIn("Tension = 0.000657 1/mm\u00b2 instead (100 / the 390.25 mm polygon",
                      say(note))
        App.Units.setSchema(3)
        # 6.57e-4 / mm^2 x 25.4^2 = 0.42387 / in^2; 390.25 mm = 15.36 in
        self.assertIn("Tension = 0.42387 1/in\u00b2 instead (100 / the 15.36 in polygon",
                      say(note))

    def test_starting_length_note_follows_the_schema(self):
        """A line's end and an arc's end no free batten joins: by 1.5 x their 75 mm; the
        note (the blend panel's warning line) said under Imperial decimal in inches."""
        sk = S.line_and_arc_sketch(self.doc)
        e1, e2 = sk.Shape.Edges
        a, b = Bl.nearest_ends(e1, e2)
        length, note = Bs.free_or_length(e1, a, e2, b)
        self.assertEqual(length, 112.0)
        self.assertIn("solved for a length instead, 112.00 mm (1.5 \u00d7 the 75.00 mm between",
                      say(note))
        App.Units.setSchema(3)
        self.assertIn("instead, 4.41 in (1.5 \u00d7 the 2.95 in between", say(note))

    def test_elliptic_blend_loop_said_again(self):
        """A looping interpolation recomputed under Standard: its panel opened under
        Imperial decimal says the loop's chord and width in inches (they kept mm's
        figures: 'chord 100'), from the exact figures, with the unit (they had none:
        'chord 3.94, a loop 1.3 wide'); back in mm under Standard."""
        pts = [(0.0, 0.0), (30.0, 80.0), (70.0, 90.0), (100.0, 0.0)]
        sk = S.points_sketch(self.doc, pts, "Looping")
        f = El.make(self.doc, [(sk, [])], K=0.52, KConvention="parameter")
        self.doc.recompute()
        before = list(f.Warnings)
        self.assertIn("between points 0 and 3 (counted from 0; chord 100", before[1])
        App.Units.setSchema(3)
        shown = said(f, "Warnings")
        self.assertIn("between points 0 and 3 (counted from 0; chord 3.94 in", shown[1])
        self.assertRegex(shown[1], r"a loop [0-9.]+ in wide\)")
        self.assertNotIn("mm", shown[1])
        self.assertEqual(shown[0], before[0])           # ratios: no length
        self.assertEqual(said(f, "Status"), "; ".join(["ok"] + [f"warning: {w}" for w in shown]))
        App.Units.setSchema(0)
        self.assertEqual(said(f, "Warnings"), before)

    def g2_blend_edited_under_imperial(self):
        """A G2 blend recomputed under Standard, then edited (Length 250 mm) and recomputed
        under Imperial decimal, each in an Undo step; returns (blend, its Status before the
        edit, as a recompute under Imperial writes it)."""
        self.doc.UndoMode = 1
        sk = S.two_lines_sketch(self.doc)
        self.doc.openTransaction("Blend")
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2", Mode="length")
        self.doc.recompute()
        self.doc.commitTransaction()
        App.Units.setSchema(3)
        b.touch()
        self.doc.recompute()
        before = b.Status
        App.Units.setSchema(0)
        b.touch()
        self.doc.recompute()
        self.assertIn("length 49.86 mm", b.Status)
        App.Units.setSchema(3)
        self.doc.openTransaction("Edit")
        b.Length = 250.0
        self.doc.recompute()
        self.doc.commitTransaction()
        self.assertIn("length 9.84 in", b.Status)
        return b, before

    def test_undo_says_the_state_undone_to_in_the_schema_of_now(self):
        """Edit > Undo restores the Status of the state before, as stored: said in the schema
        of now, as a recompute of that state writes it (the marked texts lived in the proxy,
        which Undo does not restore: a panel said 'length 49.86 mm' beside boxes in inches);
        Redo says the edit's again."""
        from freecad.elastica.proxy import SAID
        b, before = self.g2_blend_edited_under_imperial()
        edited = b.Status
        self.doc.undo()
        self.assertEqual(b.Length.Value, 0.0)
        self.assertIn("length 49.86 mm", b.Status)         # as stored, under Standard
        self.assertEqual(said(b, "Status"), before)
        self.assertIn("length 1.96 in", before)
        self.doc.redo()
        self.assertEqual(said(b, "Status"), edited)
        self.assertEqual(b.getEditorMode(SAID), ["Hidden"])

    def test_a_document_made_before_says_its_texts_again(self):
        """A document saved before the marked texts had their property (the proxy's state
        kept them): reopened, its Status said in the schema of now, and kept in SAID."""
        import json
        from freecad.elastica.proxy import SAID
        sk = S.two_lines_sketch(self.doc)
        b = Bl.make(self.doc, (sk, "Edge1"), (sk, "Edge2"), Continuity="G2")
        self.doc.recompute()
        b.Proxy._said = json.loads(getattr(b, SAID))
        b.removeProperty(SAID)
        (b,) = S.reopened(self, "before.FCStd", b.Name)
        App.Units.setSchema(3)
        self.assertIn("length 1.96 in", said(b, "Status"))
        self.assertEqual(list(json.loads(getattr(b, SAID))), ["Status"])
        self.assertFalse(b.Proxy._said)

    def test_the_commands_note_is_kept_with_the_feature(self):
        """The spike's ducks, no free batten: the Elastic spline command's note (why a
        tension) is saved with the feature (proxy.saved_note; it lived only while its panel
        was open), saved with the document, and said while Mode and Tension are the
        command's; a tension of the designer's has none."""
        import json
        from freecad.elastica import commands as C
        from freecad.elastica.proxy import NOTE, saved_note
        spike = [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]
        sk = S.points_sketch(self.doc, spike, "Spike")
        f = C.spline_sources([(sk, [])], open_panel=False)
        self.assertEqual(f.Tension, 6.57e-4)
        note = saved_note(f)
        self.assertIn("Tension = 0.000657 1/mm\u00b2 instead (100 / the 390.25 mm polygon",
                      say(note))
        self.assertEqual(json.loads(getattr(f, NOTE))["values"],
                         {"Mode": "tension", "Tension": 6.57e-4})
        self.assertEqual(f.getEditorMode(NOTE), ["Hidden"])
        (f,) = S.reopened(self, "note.FCStd", f.Name)
        self.assertEqual(saved_note(f), note)
        f.Tension = 1e-4
        self.assertEqual(saved_note(f), "")

    def test_comb_scale_in_the_schema(self):
        """The comb panel's 'scale ... mm\u00b2' line in the square of the schema's unit."""
        from freecad.elastica.units import area_text
        self.assertEqual(area_text(645.16), "645.16 mm\u00b2")
        App.Units.setSchema(3)
        self.assertEqual(area_text(645.16), "1.00 in\u00b2")


if __name__ == "__main__":
    unittest.main()
