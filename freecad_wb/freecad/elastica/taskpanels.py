"""Task panels: edit a feature's properties with a live preview (the feature
itself recomputes), show the fit's rms / max error / k / status or the list of
Hermite solutions, and on OK optionally write the B-spline into a sketch.
Cancel on a freshly created feature removes it, leaving the document as it was."""
from __future__ import annotations

import FreeCAD as App
import FreeCADGui as Gui
from PySide import QtCore, QtGui

from . import features as F


CURRENT = []    # the open panel, if any (scripts and the GUI smoke test drive it)


def _sketches(doc, exclude=()):
    return [o for o in doc.Objects if F._is_sketch(o) and o.Name not in exclude]


class _Panel:
    title = ""

    def __init__(self, obj, created=True):
        self.obj = obj
        self.doc = obj.Document
        self.created = created
        self.form = QtGui.QWidget()
        self.form.setWindowTitle(self.title)
        self.layout = QtGui.QFormLayout(self.form)
        self.result = QtGui.QLabel()
        self.result.setWordWrap(True)
        self.result.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)

    def _check_row(self, L, text, prop):
        """A check box bound live to the boolean property prop."""
        box = QtGui.QCheckBox(text)
        box.setChecked(getattr(self.obj, prop))
        box.toggled.connect(lambda v: self._set(prop, bool(v)))
        L.addRow(box)
        return box

    def _choice_row(self, L, label, prop, values, texts=None):
        """A combo box bound live to the string property prop, one entry per allowed
        value (shown as texts, if given)."""
        box = QtGui.QComboBox()
        box.addItems(list(texts or values))
        box.setCurrentIndex(list(values).index(getattr(self.obj, prop)))
        box.currentIndexChanged.connect(lambda i: self._set(prop, values[i]))
        L.addRow(label, box)
        return box

    def _tolerance_row(self, L):
        """The B-spline tolerance, edited live."""
        self.tol = QtGui.QDoubleSpinBox()
        self.tol.setRange(1e-7, 100.0)
        self.tol.setDecimals(7)
        self.tol.setSuffix(" mm")
        self.tol.setValue(self.obj.Tolerance)
        self.tol.editingFinished.connect(lambda: self._set("Tolerance", self.tol.value()))
        L.addRow("B-spline tolerance", self.tol)

    def _output_rows(self, L, exclude, new_label):
        """Keep the feature or not; write its B-spline into a sketch (not those in exclude)."""
        self.keep = QtGui.QCheckBox("Keep the parametric feature")
        self.keep.setChecked(True)
        L.addRow(self.keep)
        self.sketch = QtGui.QComboBox()
        self.sketch.addItem("(none)", "")
        for sk in _sketches(self.doc, exclude):
            self.sketch.addItem(sk.Label, sk.Name)
        self.sketch.addItem(new_label, "*new*")
        L.addRow("Write B-spline into", self.sketch)

    def getStandardButtons(self):
        return int(QtGui.QDialogButtonBox.Ok | QtGui.QDialogButtonBox.Cancel)

    def _set(self, prop, value):
        if getattr(self.obj, prop) != value:
            setattr(self.obj, prop, value)
            self.update()

    def update(self):
        try:
            self.doc.recompute()
        except Exception as exc:  # never let a preview escape
            App.Console.PrintError(f"Elastica: {exc}\n")
        self.show_result()

    def show_result(self):
        """The feature's status in red when it is an error, else result_text()."""
        o = self.obj
        if o.Status.startswith("error"):
            self.result.setText(f"<b style='color:#b00'>{o.Status}</b>")
        else:
            self.result.setText(self.result_text())

    def result_text(self):
        return f"status: {self.obj.Status}"

    def _close(self):
        CURRENT[:] = []
        Gui.Control.closeDialog()
        if Gui.ActiveDocument is not None:
            Gui.ActiveDocument.resetEdit()

    def reject(self):
        if self.created and self.obj.Name in [o.Name for o in self.doc.Objects]:
            self.doc.removeObject(self.obj.Name)
            self.doc.recompute()
        self._close()
        return True


class FitPanel(_Panel):
    """Model, keyline split, pinned ends, resampling step, B-spline tolerance and
    degree, output; shows rms / max error / k / status."""

    title = "Fit elastica"

    def __init__(self, obj, created=True):
        super().__init__(obj, created)
        L = self.layout
        self.model = self._choice_row(L, "Model", "Model", ["discrete", "smooth"])
        self.split = self._check_row(L, "Split the keyline at its inflection", "SplitAtInflection")
        self.pin = self._check_row(L, "Pin the start to the first point", "PinEnds")
        self.step = QtGui.QDoubleSpinBox()
        self.step.setRange(0.0, 1e6)
        self.step.setDecimals(4)
        self.step.setSuffix(" mm")
        self.step.setSpecialValueText("no resampling")
        self.step.setValue(obj.ResampleStep)
        self.step.editingFinished.connect(lambda: self._set("ResampleStep", self.step.value()))
        L.addRow("Resampling step", self.step)
        self._tolerance_row(L)
        self.degree = QtGui.QSpinBox()
        self.degree.setRange(3, 7)
        self.degree.setValue(obj.Degree)
        self.degree.valueChanged.connect(lambda v: self._set("Degree", int(v)))
        L.addRow("B-spline degree", self.degree)
        # not into a source sketch: writing there would feed the fit its own output
        self._output_rows(L, [o.Name for o, _ in obj.Source], "(new sketch in the fit plane)")
        L.addRow(self.result)
        self.show_result()

    def result_text(self):
        o = self.obj
        ks = ", ".join(f"{k:.4g}" for k in o.K)
        return (f"rms {o.Rms:.4g} mm, max error {o.MaxError:.4g} mm<br>"
                f"k = {ks}<br>B-spline deviation {o.BSplineDeviation:.3g} mm<br>status: {o.Status}")

    def accept(self):
        if self.obj.Status.startswith("error"):
            App.Console.PrintError(f"Elastica: {self.obj.Status}\n")
            return False          # stay open: the user fixes the input or cancels
        target = self.sketch.itemData(self.sketch.currentIndex())
        if target:
            code = "from freecad.elastica import features\n"
            if target == "*new*":
                code += (f"_sk = App.getDocument({self.doc.Name!r}).addObject("
                         "'Sketcher::SketchObject', 'ElasticaSketch')\n"
                         f"_sk.Placement = App.getDocument({self.doc.Name!r})."
                         f"getObject({self.obj.Name!r}).Plane\n")
            else:
                code += f"_sk = App.getDocument({self.doc.Name!r}).getObject({target!r})\n"
            code += (f"features.write_to_sketch(App.getDocument({self.doc.Name!r})."
                     f"getObject({self.obj.Name!r}), _sk)\n")
            Gui.doCommandGui(code)
        if not self.keep.isChecked():
            Gui.doCommandGui(f"App.getDocument({self.doc.Name!r}).removeObject({self.obj.Name!r})")
        self.doc.recompute()
        self._close()
        return True


class BlendPanel(_Panel):
    """Length or tension, the list of all Hermite solutions (length, energy),
    previewed one by one; OK writes it into the sketch (with tangency) when both
    edges are in one sketch."""

    title = "Elastic blend"

    def __init__(self, obj, created=True):
        super().__init__(obj, created)
        L = self.layout
        self.mode = self._choice_row(L, "Solve by", "Mode", ["length", "tension"])
        self.value = QtGui.QDoubleSpinBox()
        self.value.setRange(-1e6, 1e6)
        self.value.setDecimals(6)
        self.value.setValue(obj.Length if obj.Mode == "length" else obj.Tension)
        self.value.editingFinished.connect(self._value)
        L.addRow("Length (0 = auto) / tension", self.value)
        self.end1 = self._check_row(
            L, "Leave the first edge at its end vertex (else its start)", "AtEnd1")
        self.end2 = self._check_row(
            L, "Enter the second edge at its end vertex (else its start)", "AtEnd2")
        self.list = QtGui.QListWidget()
        self.list.setToolTip("All elastic curves for these ends, by bending energy; pick one "
                             "to preview it")
        self.list.currentRowChanged.connect(self._pick)
        L.addRow(self.list)
        self.into_sketch = QtGui.QCheckBox("Write into the edges' sketch with tangency")
        sk = obj.Edge1[0] if obj.Edge1 else None
        same = bool(obj.Edge2) and sk is obj.Edge2[0] and F._is_sketch(sk)
        self.into_sketch.setEnabled(same)
        self.into_sketch.setChecked(same)
        L.addRow(self.into_sketch)
        L.addRow(self.result)
        self.show_result()

    def _value(self):
        self._set("Length" if self.obj.Mode == "length" else "Tension", self.value.value())

    def _pick(self, row):
        if row >= 0 and row != self.obj.Solution:
            self.obj.Solution = row
            self.doc.recompute()
            self.result.setText(f"status: {self.obj.Status}")

    def show_result(self):
        o = self.obj
        self.list.blockSignals(True)
        self.list.clear()
        for i, (L, E) in enumerate(zip(o.Lengths, o.Energies)):
            self.list.addItem(f"{i + 1}: length {L:.5g} mm, energy {E:.5g}")
        if o.Lengths:
            self.list.setCurrentRow(min(o.Solution, len(o.Lengths) - 1))
        self.list.blockSignals(False)
        self.result.setText(f"status: {o.Status}")

    def accept(self):
        o = self.obj
        if o.Status.startswith("error"):
            App.Console.PrintError(f"Elastica: {o.Status}\n")
            return False
        if self.into_sketch.isEnabled() and self.into_sketch.isChecked():
            sk = o.Edge1[0]
            g1 = o.SketchGeometry1 if o.SketchGeometry1 >= 0 else F.sketch_geo_of_edge(sk, o.Edge1[1][0])
            g2 = o.SketchGeometry2 if o.SketchGeometry2 >= 0 else F.sketch_geo_of_edge(sk, o.Edge2[1][0])
            if g1 is not None and g2 is not None:
                doc = f"App.getDocument({self.doc.Name!r})"
                Gui.doCommandGui(
                    "from freecad.elastica import features\n"
                    f"features.write_to_sketch({doc}.getObject({o.Name!r}), "
                    f"{doc}.getObject({sk.Name!r}), [({g1}, {2 if o.AtEnd1 else 1}), "
                    f"({g2}, {2 if o.AtEnd2 else 1})])\n"
                    # the sketch now holds the blend; the feature would depend on its own output
                    f"{doc}.removeObject({o.Name!r})")
        self.doc.recompute()
        self._close()
        return True


class EllipticBlendPanel(_Panel):
    """Mode (through / control points), k or m, d, B-spline tolerance, output;
    shows the certified B-spline deviation; on OK optionally writes the B-spline
    into a sketch."""

    title = "Elliptic blend curve"

    def __init__(self, obj, created=True):
        super().__init__(obj, created)
        L = self.layout
        self.mode = self._choice_row(L, "Curve", "Mode", F.ELLBLEND_MODES,
                                     ["through the points", "points are control points"])
        self.conv = self._choice_row(L, "Elliptic", "KConvention", F.K_CONVENTIONS,
                                     ["modulus k", "parameter m = k\u00b2"])
        self.k = QtGui.QDoubleSpinBox()
        self.k.setRange(0.0, 0.999999)
        self.k.setDecimals(6)
        self.k.setSingleStep(0.05)
        self.k.setValue(obj.K)
        self.k.editingFinished.connect(lambda: self._set("K", self.k.value()))
        L.addRow("k (or m)", self.k)
        self.d = QtGui.QDoubleSpinBox()
        self.d.setRange(1e-6, 1e3)
        self.d.setDecimals(6)
        self.d.setSingleStep(0.1)
        self.d.setValue(obj.D)
        self.d.editingFinished.connect(lambda: self._set("D", self.d.value()))
        L.addRow("End derivative d", self.d)
        self._tolerance_row(L)
        self._output_rows(L, (), "(new sketch in the curve's plane)")
        L.addRow(self.result)
        self.show_result()

    def result_text(self):
        o = self.obj
        return (f"B-spline deviation {o.BSplineDeviation:.3g} mm "
                f"(tolerance {o.Tolerance:.3g} mm)<br>status: {o.Status}")

    accept = FitPanel.accept      # the same output step: B-spline into a sketch, keep or not


def open_for(obj):
    """Show the task panel of an Elastica feature (from its view provider). A feature
    a command has just made (``Proxy.fresh``) is removed again by Cancel."""
    proxy = getattr(obj, "Proxy", None)
    panel = {"Fit": FitPanel, "Blend": BlendPanel,
             "EllipticBlend": EllipticBlendPanel}.get(getattr(proxy, "kind", ""))
    if panel is None:
        return False
    created = bool(getattr(proxy, "fresh", False))
    proxy.fresh = False
    p = panel(obj, created)
    CURRENT[:] = [p]
    Gui.Control.showDialog(p)
    return True
