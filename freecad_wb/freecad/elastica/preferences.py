"""Preference page (Edit > Preferences > Elastica): default B-spline tolerance,
smooth fits' B-spline degree and fit model, stored under
User parameter:BaseApp/Preferences/Mod/Elastica."""
import FreeCAD as App

from . import PREF_PATH, defaults
from .fit_core import MODEL_NAMES, MODEL_TIPS, MODELS


# The degree is a smooth fit's only (QA22gui F8: at 7 a new fit took 7 and a new blend or
# spline 5, under a label saying 'B-spline' generally): blends and elastic splines keep
# their own degree 5, few poles at the tolerance (blend.BSPLINE_DEGREE, spline's)
DEGREE_LABEL = "Default degree of smooth fits"
DEGREE_TIP = ("Degree of the B-spline of a new smooth fit (3 to 7). Blends and elastic "
              "splines start at degree 5, few poles at the tolerance: their Degree property "
              "sets it")


class PreferencePage:
    """A Python preference page: ``form`` plus loadSettings / saveSettings."""

    def __init__(self, parent=None):
        from PySide import QtCore, QtGui
        from .spinboxes import DecadeBox
        self.form = QtGui.QWidget(parent)
        self.form.setWindowTitle("Elastica")
        layout = QtGui.QFormLayout(self.form)
        self.tol = DecadeBox(1e-9, 1e3, 1e-3, "mm",
                             "Largest distance of a B-spline from its curve (mm); arrows step "
                             "by a factor of 10")
        # a text the box cannot take ('3 deg') stays, red, why in its tooltip, past focus-out
        # (Qt went back to its prefix's value silently), and is not saved (saveSettings), as
        # the task panels refuse it (panelbase.Panel.watch_text)
        self.tol.keep_bad_text = True
        layout.addRow("Default B-spline tolerance", self.tol)
        self.degree = QtGui.QSpinBox()
        self.degree.setRange(3, 7)
        self.degree.setToolTip(DEGREE_TIP)
        layout.addRow(DEGREE_LABEL, self.degree)
        self.model = QtGui.QComboBox()
        for i, m in enumerate(MODELS):
            self.model.addItem(MODEL_NAMES[m])
            self.model.setItemData(i, MODEL_TIPS[m], QtCore.Qt.ToolTipRole)
        self.model.setToolTip("The model new fits start with")
        layout.addRow("Default fit model", self.model)

    def loadSettings(self):
        tol, deg, model = defaults()
        self.tol.setValue(tol)
        self.degree.setValue(deg)
        self.model.setCurrentIndex(MODELS.index(model))

    def saveSettings(self):
        """Store the fields; a tolerance typed that the box cannot take is not stored (the
        last stored stays), said in the report view: FreeCAD's preference dialog closes on
        OK whatever a Python page holds."""
        p = App.ParamGet(PREF_PATH)
        why = self.tol.problem()
        if why:
            App.Console.PrintWarning(
                f"Elastica preferences: Default B-spline tolerance: {why}: not saved, it stays "
                f"{self.tol.textFromValue(defaults()[0])}\n")
        else:
            p.SetFloat("Tolerance", float(self.tol.value()))
        p.SetInt("Degree", int(self.degree.value()))
        p.SetString("Model", MODELS[self.model.currentIndex()])


def register():
    import FreeCADGui as Gui
    Gui.addPreferencePage(PreferencePage, "Elastica")
