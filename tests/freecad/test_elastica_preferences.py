"""freecadcmd -t tests of the preference page (Edit > Preferences > Elastica), built
offscreen: what its fields say they set is what the commands take."""
import os
import sys
import unittest

import FreeCAD as App

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")      # freecadcmd: no display
from PySide import QtGui  # noqa: E402

from freecad.elastica import PREF_PATH, blend, defaults, spline  # noqa: E402
from freecad.elastica import preferences as P  # noqa: E402

APP = QtGui.QApplication.instance() or QtGui.QApplication([])


class PreferencePageTest(unittest.TestCase):
    def test_the_degree_field_says_what_it_is_used_for(self):
        """QA22gui F8: with 'Default B-spline degree' 7 a new fit took 7, a new blend and
        spline 5 (their own degree, few poles at the tolerance): the label said B-spline
        generally. The preference is a smooth fit's (defaults()); its label says so, its
        tooltip names the degree blends and splines start at, as their modules have it."""
        p = App.ParamGet(PREF_PATH)
        old = p.GetInt("Degree", 3)
        self.addCleanup(p.SetInt, "Degree", old)
        page = P.PreferencePage()
        page.loadSettings()
        page.degree.setValue(7)
        page.saveSettings()
        self.assertEqual(defaults()[1], 7)                  # what a new fit takes
        label = page.form.layout().labelForField(page.degree).text()
        self.assertIn("smooth fit", label)
        self.assertEqual(blend.BSPLINE_DEGREE, spline.BSPLINE_DEGREE)
        self.assertIn(f"Blends and elastic splines start at degree {blend.BSPLINE_DEGREE}",
                      page.degree.toolTip())


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
