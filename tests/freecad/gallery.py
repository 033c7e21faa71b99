"""`make gallery` (through tests/freecad/freecad.mk): screenshots of the Elastica
workbench for the README, under xvfb-run: the demo document (made headless by
examples/demo.py) opened in FreeCAD, seen along its plane,

  docs/gallery/freecad_workbench.png  the tree (colours named in the labels) and the
                                      keyline with its fit, comb, scan points and the
                                      G2 quadratic B-spline, the elastic spline;
  docs/gallery/freecad_fit_panel.png  the fit's task panel (double-click), zoomed in at
                                      the inflection: fitted points, the comb;
  docs/gallery/freecad_spline.png     the elastic spline's task panel: the batten through
                                      its ducks, its comb and the duck forces.

FreeCAD is ended with os._exit (its exit status says nothing about a script)."""
import os
import sys
import traceback

import FreeCAD as App
import FreeCADGui as Gui

OUT = os.environ.get("ELASTICA_GALLERY", os.path.join(os.getcwd(), "docs", "gallery"))
DEMO = os.path.join(os.environ.get("ELASTICA_TEST_OUT", os.getcwd()), "demo", "demo.FCStd")


def pump(n=20):
    from PySide import QtGui
    for _ in range(n):
        QtGui.QApplication.processEvents()


def grab(name, width=1100):
    """The main window as the screen shows it, scaled to ``width`` pixels."""
    import time
    from PySide import QtCore, QtGui
    end = time.time() + 1.0              # let recomputes and the status bar settle
    while time.time() < end:
        pump(5)
        time.sleep(0.05)
    # a document opened from a script leaves FreeCAD's "Loading ..." bar behind (0.20)
    bar = Gui.getMainWindow().statusBar()
    bar.clearMessage()
    for w in bar.findChildren(QtGui.QProgressBar):
        w.hide()
    for w in bar.findChildren(QtGui.QLabel):
        if w.text().startswith("Loading"):
            w.clear()
    pump(5)
    mw = Gui.getMainWindow()
    img = QtGui.QApplication.primaryScreen().grabWindow(mw.winId())
    img = img.scaledToWidth(width, QtCore.Qt.SmoothTransformation)
    path = os.path.join(OUT, name)
    if not img.save(path):
        raise RuntimeError(f"could not write {path}")
    print(path)


def run():
    from PySide import QtCore, QtGui
    mw = Gui.getMainWindow()
    mw.showMaximized()
    for dock in ("Report view", "Python console"):
        w = mw.findChild(QtGui.QDockWidget, dock)
        if w is not None:
            w.hide()
    combo = mw.findChild(QtGui.QDockWidget, "Combo View")
    if combo is not None:                # wide enough for the labels (the legend)
        mw.resizeDocks([combo], [380], QtCore.Qt.Horizontal)
    Gui.activateWorkbench("ElasticaWorkbench")
    doc = App.openDocument(DEMO)
    pump()
    fit = next(o for o in doc.Objects if getattr(getattr(o, "Proxy", None), "kind", "") == "Fit"
               and o.ViewObject.Visibility)
    view = Gui.ActiveDocument.ActiveView
    view.setCameraOrientation(fit.Plane.Rotation)
    view.fitAll()
    Gui.Selection.clearSelection()
    grab("freecad_workbench.png")
    from freecad.elastica import panelbase, taskpanels
    batten = next(o for o in doc.Objects
                  if getattr(getattr(o, "Proxy", None), "kind", "") == "Spline")
    batten.ViewObject.Visibility = False            # the keyline alone, centred
    view.fitAll()
    fit.ViewObject.Proxy.doubleClicked(fit.ViewObject)
    for _ in range(3):
        view.zoomIn()
    grab("freecad_fit_panel.png")
    taskpanels.CURRENT[0].reject()
    batten.ViewObject.Visibility = True
    batten.ViewObject.Proxy.doubleClicked(batten.ViewObject)
    pump()
    taskpanels.CURRENT[0].stiffness.setValue(6.7e4)     # a 2 x 10 mm pine strip: newtons
    pump()
    panelbase.show_box(batten.Shape.BoundBox)
    grab("freecad_spline.png")
    taskpanels.CURRENT[0].reject()


def main():
    ok = True
    try:
        os.makedirs(OUT, exist_ok=True)
        run()
    except Exception:
        ok = False
        traceback.print_exc()
    sys.stdout.flush()
    os._exit(0 if ok else 1)


from PySide import QtCore  # noqa: E402
QtCore.QTimer.singleShot(0, main)
