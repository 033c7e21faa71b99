"""Preference page (Edit > Preferences > Elastica): default B-spline tolerance,
B-spline degree and fit model, stored under
User parameter:BaseApp/Preferences/Mod/Elastica."""
import FreeCAD as App

from . import PREF_PATH, defaults


class PreferencePage:
    """A Python preference page: ``form`` plus loadSettings / saveSettings."""

    def __init__(self, parent=None):
        from PySide import QtGui
        self.form = QtGui.QWidget(parent)
        self.form.setWindowTitle("Elastica")
        layout = QtGui.QFormLayout(self.form)
        self.tol = QtGui.QDoubleSpinBox()
        self.tol.setRange(1e-7, 100.0)
        self.tol.setDecimals(7)
        self.tol.setSuffix(" mm")
        self.tol.setToolTip("Largest distance of a B-spline from its elastica")
        layout.addRow("Default B-spline tolerance", self.tol)
        self.degree = QtGui.QSpinBox()
        self.degree.setRange(3, 7)
        self.degree.setToolTip("Degree of the B-splines written into sketches")
        layout.addRow("Default B-spline degree", self.degree)
        self.model = QtGui.QComboBox()
        self.model.addItems(["discrete", "smooth"])
        self.model.setToolTip("discrete: Bobenko-Suris discrete elastica; smooth: smooth elastica")
        layout.addRow("Default fit model", self.model)

    def loadSettings(self):
        tol, deg, model = defaults()
        self.tol.setValue(tol)
        self.degree.setValue(deg)
        self.model.setCurrentIndex(["discrete", "smooth"].index(model))

    def saveSettings(self):
        p = App.ParamGet(PREF_PATH)
        p.SetFloat("Tolerance", float(self.tol.value()))
        p.SetInt("Degree", int(self.degree.value()))
        p.SetString("Model", self.model.currentText())


def register():
    import FreeCADGui as Gui
    Gui.addPreferencePage(PreferencePage, "Elastica")
