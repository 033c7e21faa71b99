"""GUI commands of the Elastica workbench. Thin: read the selection, check it with
the feature's core (so bad input leaves the document untouched and only prints a
message), create the feature through ``Gui.doCommandGui`` (recorded in the Python
console and macros), open its task panel."""
from __future__ import annotations

import FreeCAD as App
import FreeCADGui as Gui

from . import defaults, icon

translate = App.Qt.translate if hasattr(App, "Qt") else (lambda ctx, txt: txt)


MESSAGES = []   # the last messages shown (tests read them); at most 50 kept


def message(text, error=True):
    """Report-view message (and the status bar), never an exception."""
    MESSAGES.append(text)
    del MESSAGES[:-50]
    (App.Console.PrintError if error else App.Console.PrintMessage)(f"Elastica: {text}\n")
    try:
        Gui.getMainWindow().statusBar().showMessage(f"Elastica: {text}", 8000)
    except Exception:  # no main window (tests without GUI)
        pass


def _guarded(command):
    """Run ``command(selection)``; whatever goes wrong becomes a message."""
    try:
        return command(selection_sources())
    except Exception as exc:
        message(f"{type(exc).__name__}: {exc}")
        return None


def _ref(obj):
    return f"App.getDocument({obj.Document.Name!r}).getObject({obj.Name!r})"


def selection_sources():
    """[(obj, [subnames])] of the current selection."""
    return [(s.Object, list(s.SubElementNames)) for s in Gui.Selection.getSelectionEx()]


def _run(code):
    """Execute ``code`` recorded as a GUI command (run directly without the GUI);
    return the last created object."""
    if App.GuiUp:
        Gui.doCommandGui(code)
    else:
        exec(code, {"App": App, "FreeCAD": App})
    return getattr(App.ActiveDocument, "ActiveObject", None)


def _create(doc, title, code):
    """``_run(code)`` in one undo transaction; on failure the transaction is undone."""
    doc.openTransaction(title)
    names = {o.Name for o in doc.Objects}
    try:
        obj = _run(code)
    except Exception as exc:
        doc.abortTransaction()
        for o in list(doc.Objects):          # without undo (freecadcmd) abort keeps them
            if o.Name not in names:
                doc.removeObject(o.Name)
        message(f"{title} failed: {type(exc).__name__}: {exc}")
        return None
    doc.commitTransaction()
    return obj


def _check_and_create(title, what, check, code, open_panel):
    """Run ``check()`` (the feature's core on the input; InputProblem = bad input),
    then create the feature by the recorded ``code`` and open its task panel.
    Returns the new feature or None (message printed, document unchanged)."""
    from . import features as F
    try:
        check()
    except F.InputProblem as exc:
        message(str(exc))
        return None
    except Exception as exc:  # anything unexpected: report, never escape
        message(f"{what} failed: {type(exc).__name__}: {exc}")
        return None
    obj = _create(App.ActiveDocument, title, code)
    if open_panel and App.GuiUp and obj is not None:
        obj.Proxy.fresh = True
        Gui.ActiveDocument.setEdit(obj.Name, 0)
    return obj


class _Command:
    """A toolbar command: ``run(selection)``, guarded; active with a document."""

    pixmap = menu = tip = ""

    def GetResources(self):
        return {"Pixmap": icon(self.pixmap), "MenuText": self.menu, "ToolTip": self.tip}

    def IsActive(self):
        return App.ActiveDocument is not None

    def Activated(self):
        _guarded(type(self).run)


# ------------------------------------------------------------------ fit

def fit_sources(sources, csv_file="", open_panel=True, **options):
    """Check the fit input, create the Fit feature (recorded), open its task panel.
    ``options`` override the preferences: Model, SplitAtInflection, PinEnds,
    ResampleStep, Tolerance, Degree. Returns the new feature or None (message
    printed, document unchanged)."""
    from . import features as F
    doc = App.ActiveDocument
    if doc is None:
        message("no active document")
        return None
    tol, deg, model = defaults()
    opts = {"Model": model, "Tolerance": tol, "Degree": deg}
    opts.update(options)
    def check():
        pts, plane, ordered, closed = F.gather_points(sources, csv_file)
        F.fit_core(pts, plane, ordered, closed, model=opts["Model"],
                   split=opts.get("SplitAtInflection", False), pin_ends=opts.get("PinEnds", False),
                   step=opts.get("ResampleStep", 0.0), tol=opts["Tolerance"], degree=opts["Degree"])

    src = ", ".join(f"({_ref(o)}, {list(s)!r})" for o, s in sources)
    return _check_and_create("Fit elastica", "fit", check, "from freecad.elastica import features\n"
                             f"_fit = features.make_fit({_ref_doc(doc)}, [{src}], csv_file={csv_file!r}, "
                             + ", ".join(f"{k}={v!r}" for k, v in opts.items()) + ")\n"
                             f"{_ref_doc(doc)}.recompute()", open_panel)


def _ref_doc(doc):
    return f"App.getDocument({doc.Name!r})"


class FitCommand(_Command):
    """Fit an elastica to the selected sketch edges / vertices, Points object or wire."""

    pixmap, menu = "fit", "Fit elastica"
    tip = ("Fit an elastica (discrete or smooth) to the selected sketch edges or "
           "vertices, a Points object or a 3D polyline; output a parametric feature "
           "and/or a B-spline in a sketch")
    run = staticmethod(fit_sources)


class FitCsvCommand(_Command):
    """Fit an elastica to the points of a CSV file."""

    pixmap, menu = "fit_csv", "Fit elastica to CSV file..."
    tip = ("Fit an elastica to x,y[,z] points read from a CSV / text file "
           "(3D points are plane-fitted)")

    def Activated(self):
        from PySide import QtGui
        path, _ = QtGui.QFileDialog.getOpenFileName(
            Gui.getMainWindow(), "Points to fit", "", "Point files (*.csv *.txt *.xyz);;All (*)")
        if path:
            _guarded(lambda _sel: fit_sources([], csv_file=path))


# ------------------------------------------------------------------ blend

def _two_edges(sources):
    edges = [(o, s) for o, subs in sources for s in subs if s.startswith("Edge")]
    if len(edges) != 2:
        return None
    return edges


def blend_sources(sources, open_panel=True):
    """Check two selected edges, create the Blend feature (recorded), open its panel."""
    from . import features as F
    doc = App.ActiveDocument
    if doc is None:
        message("no active document")
        return None
    edges = _two_edges(sources)
    if edges is None:
        message("select exactly two edges (their nearest ends are joined)")
        return None
    def check():
        e1 = edges[0][0].Shape.getElement(edges[0][1])
        e2 = edges[1][0].Shape.getElement(edges[1][1])
        a, b = F.nearest_ends(e1, e2)
        plane = None
        if edges[0][0] == edges[1][0] and F._is_sketch(edges[0][0]):
            plane = edges[0][0].getGlobalPlacement()
        F.blend_core(e1, a, e2, b, plane)

    return _check_and_create("Elastic blend", "blend", check, "from freecad.elastica import features\n"
                             f"_blend = features.make_blend({_ref_doc(doc)}, ({_ref(edges[0][0])}, "
                             f"{edges[0][1]!r}), ({_ref(edges[1][0])}, {edges[1][1]!r}))\n"
                             f"{_ref_doc(doc)}.recompute()", open_panel)


class BlendCommand(_Command):
    """Elastic Hermite blend between the nearest ends of two selected edges."""

    pixmap, menu = "blend", "Elastic blend"
    tip = ("Join the nearest ends of two selected coplanar edges by an elastica (all "
           "Hermite solutions, by length or tension); in a sketch, a B-spline "
           "tangent to both edges")
    run = staticmethod(blend_sources)


# ------------------------------------------------------------------ elliptic blend

def ellblend_sources(sources, open_panel=True, **options):
    """Check four picked points, create the elliptic blend curve (recorded), open its
    task panel. ``options`` set Mode (interpolate / control), K, KConvention (modulus /
    parameter), D, Tolerance. Returns the new feature or None (message printed,
    document unchanged)."""
    from . import features as F
    doc = App.ActiveDocument
    if doc is None:
        message("no active document")
        return None
    opts = {"Mode": "interpolate", "K": 0.5, "KConvention": "modulus", "D": 2.0,
            "Tolerance": defaults()[0]}
    opts.update(options)
    def check():
        pts, plane = F.gather_vertices(sources)
        F.ellblend_core(pts, plane, opts["Mode"], opts["K"], opts["D"], opts["Tolerance"],
                        opts["KConvention"])

    src = ", ".join(f"({_ref(o)}, {list(s)!r})" for o, s in sources)
    return _check_and_create("Elliptic blend curve", "elliptic blend", check,
                             "from freecad.elastica import features\n"
                             f"_ellblend = features.make_ellblend({_ref_doc(doc)}, [{src}], "
                             + ", ".join(f"{k}={v!r}" for k, v in opts.items()) + ")\n"
                             f"{_ref_doc(doc)}.recompute()", open_panel)


class EllipticBlendCommand(_Command):
    """Elliptic blending-function curve (seed 003) from four picked points."""

    pixmap, menu = "ellblend", "Elliptic blend curve"
    tip = ("A curve with Jacobi elliptic blending functions through four picked "
           "coplanar points (or with them as control points); select four vertices "
           "in order, or a sketch of four points")
    run = staticmethod(ellblend_sources)


# ------------------------------------------------------------------ comb

def comb_sources(sources):
    """Curvature combs of the selected results / edges (recorded)."""
    from . import features as F
    doc = App.ActiveDocument
    if doc is None or not sources:
        message("select an Elastica result or some edges")
        return []
    made = []
    for obj, subs in sources:
        subs = [s for s in subs if s.startswith("Edge")]
        try:
            F.comb_core(obj, subs, 8)
        except F.InputProblem as exc:
            message(f"{obj.Label}: {exc}")
            continue
        except Exception as exc:
            message(f"{obj.Label}: comb failed: {type(exc).__name__}: {exc}")
            continue
        c = _create(doc, "Curvature comb", "from freecad.elastica import features\n"
                    f"_comb = features.make_comb({_ref_doc(doc)}, {_ref(obj)}, {subs!r})\n"
                    f"{_ref_doc(doc)}.recompute()")
        if c is not None:
            made.append(c)
    return made


class CombCommand(_Command):
    """Curvature comb of the selected Elastica results or edges."""

    pixmap, menu = "comb", "Curvature comb"
    tip = ("A parametric curvature comb along the selected Elastica results or edges")
    run = staticmethod(comb_sources)


COMMANDS = {"Elastica_Fit": FitCommand, "Elastica_FitCsv": FitCsvCommand,
            "Elastica_Blend": BlendCommand, "Elastica_EllipticBlend": EllipticBlendCommand,
            "Elastica_Comb": CombCommand}


def register():
    for name, cls in COMMANDS.items():
        Gui.addCommand(name, cls())
    return list(COMMANDS)
