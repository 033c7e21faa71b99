"""freecadcmd -t tests of the workbench's packaging and of the bundled sample:
package.xml for the Addon Manager, the namespace layout, icons, proxies' state
methods, and examples/keyline_3d.csv being what examples/make_keyline.py makes."""
import importlib.util
import os
import unittest
import xml.etree.ElementTree as ET

import elastica_samples as S

WB = os.path.join(S.ROOT, "freecad_wb")
PKG = os.path.join(WB, "freecad", "elastica")
NS = {"p": "https://wiki.freecad.org/Package_Metadata"}


class PackageTest(unittest.TestCase):
    def test_namespace_layout(self):
        self.assertFalse(os.path.exists(os.path.join(WB, "freecad", "__init__.py")))
        for f in ("__init__.py", "init_gui.py", "commands.py", "features.py", "taskpanels.py",
                  "preferences.py"):
            self.assertTrue(os.path.isfile(os.path.join(PKG, f)), f)

    def test_package_xml(self):
        root = ET.parse(os.path.join(WB, "package.xml")).getroot()
        self.assertEqual(root.tag, "{%s}package" % NS["p"])
        for tag in ("name", "description", "version", "maintainer", "license", "url"):
            self.assertTrue(root.find(f"p:{tag}", NS).text.strip(), tag)
        wb = root.find("p:content/p:workbench", NS)
        self.assertEqual(wb.find("p:classname", NS).text, "ElasticaWorkbench")
        with open(os.path.join(PKG, "init_gui.py")) as fh:
            self.assertIn("class ElasticaWorkbench(", fh.read())
        icon = os.path.join(WB, wb.find("p:icon", NS).text)
        self.assertTrue(os.path.isfile(icon), icon)
        from freecad import elastica
        self.assertEqual(root.find("p:version", NS).text, elastica.__version__)

    def test_icons_are_svg(self):
        from freecad.elastica import icon
        for name in ("elastica", "fit", "fit_csv", "blend", "comb"):
            root = ET.parse(icon(name)).getroot()
            self.assertEqual(root.tag, "{http://www.w3.org/2000/svg}svg", name)

    def test_proxies_keep_state_both_ways(self):
        from freecad.elastica import features as F
        for cls in (F.FitProxy, F.BlendProxy, F.CombProxy, F.ViewProvider):
            for m in ("__getstate__", "__setstate__", "dumps", "loads"):
                self.assertTrue(callable(getattr(cls, m, None)), (cls, m))
        p = F.FitProxy.__new__(F.FitProxy)
        state = p.dumps()
        self.assertEqual(state["kind"], "Fit")
        p.loads(state)
        self.assertEqual(p.kind, "Fit")


class SampleTest(unittest.TestCase):
    def test_keyline_csv_is_what_the_script_makes(self):
        import numpy as np
        spec = importlib.util.spec_from_file_location(
            "make_keyline", os.path.join(S.ROOT, "examples", "make_keyline.py"))
        mod = importlib.util.module_from_spec(spec)
        spec.loader.exec_module(mod)
        made = mod.make()
        data = np.loadtxt(os.path.join(S.ROOT, "examples", "keyline_3d.csv"), delimiter=",",
                          skiprows=2)
        self.assertEqual(data.shape, made.shape)
        self.assertLess(np.max(np.abs(data - made)), 0.0005 + 1e-9)   # written with 3 decimals

    def test_keyline_has_one_inflection_and_noise(self):
        import numpy as np
        import libelastica as el
        xyz = np.loadtxt(os.path.join(S.ROOT, "examples", "keyline_3d.csv"), delimiter=",",
                         skiprows=2)
        xy, frame = el.plane_fit(xyz)
        self.assertGreater(frame.rms, 0.05)          # measurement noise and warp ...
        self.assertLess(frame.rms, 0.5)              # ... of a nearly planar keyline
        poly = el.resample_equilateral(xy, 5.0)
        poly2, _ = el.pca_normalize(poly)
        i = el.find_inflection(poly2)
        self.assertTrue(0.2 * len(poly2) < i < 0.8 * len(poly2))
