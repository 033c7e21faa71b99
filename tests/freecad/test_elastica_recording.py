"""freecadcmd -t tests of what a panel's OK records (QA18gui F5): the lines that set each
property the edit changed (recording.edit_lines, which Panel.accept runs through
Gui.doCommand), after the command's make() line, replay in a fresh document from the same
source to the same feature: its properties, its results and its shape. An edit that
changes nothing records nothing."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import commands as C
from freecad.elastica.recording import code_of, edit_lines, edit_state


class RecordingTest(S.DocTest):
    doc_name = "ElasticaRecordingTest"

    def made(self, command):
        """The feature ``command()`` makes and the code the command recorded for it."""
        codes, run = [], C._run
        C._run = lambda code: codes.append(code) or run(code)
        try:
            obj = command()
        finally:
            C._run = run
        self.assertIsNotNone(obj)
        # the creation and the recompute (two lines, as Fit's: the check's outcome is handed
        # to the feature between them, commands._hand)
        self.assertEqual(len(codes), 2, codes)
        self.assertTrue(codes[1].endswith(".recompute()"), codes)
        return obj, "\n".join(codes)

    def replayed(self, source, code, lines):
        """The feature of the same name made in a fresh document of the same name, whose
        ``source(doc)`` draws the same source, by the recorded ``code`` and ``lines``."""
        App.closeDocument(self.doc.Name)
        self.doc = S.new_doc(self.doc_name)
        source(self.doc)
        exec("\n".join([code] + lines), {"App": App, "FreeCAD": App})
        self.doc.recompute()
        return self.doc

    def check_same(self, obj, replayed):
        """``replayed`` (its name) in the replayed document is ``obj`` as it was (a dict of
        its state, results and shape taken before the replay)."""
        got = replayed.getObject(obj["name"])
        self.assertIsNotNone(got)
        self.assertEqual(edit_state(got), obj["state"])
        for prop, value in obj["results"].items():
            self.assertEqual(getattr(got, prop), value, prop)
        self.assertEqual([tuple(p) for p in got.Shape.Edges[0].Curve.getPoles()], obj["poles"])

    def test_blend_edits_replay_to_the_same_blend(self):
        """QA18gui F5: a blend made, Tension 0.001 typed, solution 2 picked, Degree 6: the
        console held the make() line only, so a macro replayed gave the free batten,
        solution 1. The edit's lines, the pick after the tension (an edit of the problem
        resets Solution), replay to the same blend."""
        sk = S.two_lines_sketch(self.doc)
        b, code = self.made(lambda: C.blend_sources([(sk, ["Edge1", "Edge2"])],
                                                    open_panel=False))
        self.doc.recompute()
        before = edit_state(b)
        self.assertEqual(edit_lines(b, before), ([], []))       # nothing changed: nothing
        b.Tension = b.Tension          # set to what it was: nothing either
        self.doc.recompute()
        self.assertEqual(edit_lines(b, before), ([], []))
        b.Tension = 0.001
        self.doc.recompute()
        self.assertGreater(len(b.Lengths), 1, b.Status)
        b.Solution = 2                  # as the list numbers it
        b.Degree = 6
        self.doc.recompute()
        self.assertTrue(b.Status.startswith("solution 2 of"), b.Status)
        lines, view = edit_lines(b, before)
        ref = f"App.getDocument({self.doc.Name!r}).getObject({b.Name!r})"
        self.assertEqual(lines, [f"{ref}.Degree = 6", f"{ref}.Tension = 0.001",
                                 f"{ref}.Solution = 2"])
        self.assertEqual(view, [])
        was = S.taken(b)
        self.check_same(was, self.replayed(S.two_lines_sketch, code, lines))

    def test_spline_edits_replay_to_the_same_spline(self):
        """An Elastic spline switched to a length (its length a double of many digits, the
        Tolerance a Quantity): replayed exactly, bit for bit."""
        def source(doc):
            return S.points_sketch(doc, [(0, 0), (30, 10), (60, 5), (90, 20), (120, 0)],
                                   "Ducks")
        sk = source(self.doc)
        s, code = self.made(lambda: C.spline_sources([(sk, [])], open_panel=False))
        self.doc.recompute()
        before = edit_state(s)
        s.Mode = "length"
        s.Length = s.SplineLength * 1.0123456789
        s.Tolerance = 0.0125
        self.doc.recompute()
        self.assertTrue(s.Status.startswith("ok"), s.Status)
        lines, _ = edit_lines(s, before)
        self.assertEqual(sorted(line.split(" = ")[0].rsplit(".", 1)[1] for line in lines),
                         ["Length", "Mode", "Tolerance"], lines)
        was = S.taken(s)
        self.check_same(was, self.replayed(source, code, lines))

    def test_values_are_written_to_evaluate_back(self):
        """Links, vectors, placements, lengths (Quantity) and floats of all their digits
        evaluate back to the same values."""
        sk = S.two_lines_sketch(self.doc)
        values = [(sk, ["Edge1"]), [(sk, ("Edge1", "Edge2"))], App.Vector(0.1, -2.5e-17, 3),
                  S.SKETCH_PLACEMENT, 0.1 + 0.2, "length", None, True, {"a": "b"}]
        for v in values:
            back = eval(code_of(v), {"App": App})
            self.assertEqual(back, v, code_of(v))
        self.assertEqual(eval(code_of(App.Units.Quantity("2 in")), {"App": App}), 50.8)
        self.assertIsNone(code_of(float("nan")))
        self.assertIsNone(code_of(object()))
