"""freecadcmd -t tests of the Elastic spline command given scan points, too many and too
noisy for a batten through each (QA23gui F8): it was refused in a 'Wrong selection' box
ending 'Select the points to pass through ...' (they were selected) and quoting the Python
and CLI names 'el.fit (`elastica fit`)'; it is said under the command's name, in the
designer's words, naming the Fit elastica command."""
import math

import FreeCAD as App
import Part

import elastica_samples as S
from freecad.elastica import commands as C


class SplineScanTest(S.DocTest):
    doc_name = "ElasticaSplineScanTest"

    def said(self, sources):
        """What the command says (text, whether as a 'Wrong selection'), as _guarded's."""
        out = []

        def wrong(text, selection=True):
            out.append((text, selection))
        wrong.shapes = True
        before = S.doc_state(self.doc)
        self.assertIsNone(C.spline_sources(sources, open_panel=False, wrong=wrong))
        self.assertEqual(S.doc_state(self.doc), before)
        self.assertEqual(len(out), 1, out)
        return out[0]

    def check_words(self, text):
        self.assertIn("double back on themselves", text)
        self.assertIn("Fit elastica command", text)
        for api in ("el.fit", "elastica fit", "points[::", "`"):
            self.assertNotIn(api, text)

    def test_a_noisy_sketch_of_5000_points(self):
        """QA's case: 5000 sketch points of a 12 m sweep, noise larger than their spacing."""
        import numpy
        rng = numpy.random.default_rng(23)
        x = numpy.linspace(0.0, 1200.0, 5000)
        xy = numpy.column_stack([x, 80 * numpy.sin(x / 300)]) + rng.normal(0, 0.5, (5000, 2))
        sk = S.points_sketch(self.doc, xy.tolist(), "Scan")
        text, selection = self.said([(sk, [])])
        self.assertFalse(selection, text)       # not 'Wrong selection ... Select the points'
        self.check_words(text)

    def test_a_closed_noisy_outline(self):
        """A closed outline (the library's advice for it named el.fit and points[::k])."""
        import numpy
        rng = numpy.random.default_rng(5)
        t = numpy.linspace(0.0, 2 * math.pi, 400, endpoint=False)
        xy = numpy.column_stack([50 * numpy.cos(t), 30 * numpy.sin(t)]) + \
            rng.normal(0, 0.4, (400, 2))
        pts = [App.Vector(x, y, 0) for x, y in xy]
        wire = self.doc.addObject("Part::Feature", "Outline")
        wire.Shape = Part.makePolygon(pts + pts[:1])
        self.doc.recompute()
        text, selection = self.said([(wire, [])])
        self.assertFalse(selection, text)
        self.check_words(text)
        self.assertIn("the Fit elastica command fits open curves only", text)
