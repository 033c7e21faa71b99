"""GUI commands of the Elastica workbench. Thin: read the selection, check it with
the feature's core (so bad input leaves the document untouched: a script gets a
message, a toolbar command FreeCAD's own modal 'Wrong selection' box; a command whose
selection cannot fit is greyed out), create the feature through
``Gui.doCommand`` (recorded in the Python console and macros) inside an undo
transaction, and open its task panel, whose OK records the properties the edit changed
and commits the transaction, and Cancel
aborts it."""
from __future__ import annotations

import FreeCAD as App
import FreeCADGui as Gui

from . import defaults, icon, library_problem
from .kept import checked_call
from .links import as_followed, element_as_followed
from .proxy import InputProblem, ShapeProblem, abort_transaction, save_note
from .recording import _ref
from .units import say

MESSAGES = []   # the last messages shown (tests read them); at most 50 kept


def _kept(text):
    """``text`` with its marks said in the unit schema (units.say), kept in MESSAGES."""
    text = say(text)
    MESSAGES.append(text)
    del MESSAGES[:-50]
    return text


def message(text, error=True):
    """Report-view message (and the status bar), never an exception; its marks (a
    feature's message) said in the unit schema (units.say)."""
    text = _kept(text)
    (App.Console.PrintError if error else App.Console.PrintMessage)(f"Elastica: {text}\n")
    try:
        Gui.getMainWindow().statusBar().showMessage(f"Elastica: {text}", 8000)
    except Exception:  # no main window (tests without GUI)
        pass


def wrong_selection(text, command="", needs="", selection=True):
    """Input a command cannot use, as FreeCAD's own commands say it (Part_RuledSurface,
    the Sketcher's constraints): a modal 'Wrong selection' box, not a red report-view
    line (which popped the report view up); without the GUI a message. The box names the
    command and what it takes (QA21gui F5: "Box.Face1: select edges, not Face1" named
    neither). ``selection`` False: the selection was what the command takes, its shape is
    not (proxy.ShapeProblem): the box titled by the command, no 'Select ...' (QA22gui F6:
    'Select one open edge' to a designer who had)."""
    if not App.GuiUp:
        return message(text)
    from PySide import QtGui
    text = _kept(text)
    text = text[:1].upper() + text[1:]
    if command and selection:
        text = f"{command}: {text}" + (f"\n\nSelect {needs}." if needs else "")
    QtGui.QMessageBox.warning(Gui.getMainWindow(),
                              "Wrong selection" if selection else command or "Elastica", text)


def say_wrong(wrong, exc):
    """An InputProblem said by a command's ``wrong``: a ShapeProblem as not the selection's
    where ``wrong`` tells them apart (its ``selection`` keyword: _guarded's)."""
    if isinstance(exc, ShapeProblem) and getattr(wrong, "shapes", False):
        wrong(str(exc), selection=False)
    else:
        wrong(str(exc))


def _guarded(command, menu="", needs=""):
    """Run ``command(selection, wrong=...)`` (a toolbar command; its 'Wrong selection' box
    names ``menu`` and what it ``needs``); whatever goes wrong otherwise becomes a message."""
    problem = library_problem()
    if problem:
        message(problem)
        return None
    try:
        def wrong(text, selection=True):
            wrong_selection(text, menu, needs, selection)
        wrong.shapes = True             # a ShapeProblem said as such (say_wrong)
        return command(selection_sources(), wrong=wrong)
    except Exception as exc:
        message(f"{type(exc).__name__}: {exc}")
        return None


def _ref_doc(doc):
    return f"App.getDocument({doc.Name!r})"


def _src(sources):
    return "[" + ", ".join(f"({_ref(o)}, {list(s)!r})" for o, s in sources) + "]"


def _kw(opts):
    return ", ".join(f"{k}={v!r}" for k, v in opts.items())


def selection_sources():
    """[(obj, [subnames])] of the current selection."""
    return [(s.Object, list(s.SubElementNames)) for s in Gui.Selection.getSelectionEx()]


def selection_picks():
    """{(object name, subname): the point clicked on it (global)} of the current selection
    (Gui.Selection's PickedPoints; a scripted selection's are (0, 0, 0): no pick)."""
    return {(s.Object.Name, n): App.Vector(p) for s in Gui.Selection.getSelectionEx()
            for n, p in zip(s.SubElementNames, s.PickedPoints)}


def _run(code):
    """Execute ``code`` recorded as a document command (run directly without the GUI):
    in the Python console and a recorded macro (Gui.doCommandGui's lines are comments
    there: a macro replayed made nothing); return the last created object."""
    if App.GuiUp:
        Gui.doCommand(code)
    else:
        exec(code, {"App": App, "FreeCAD": App})
    return getattr(App.ActiveDocument, "ActiveObject", None)


def _create(doc, title, code, keep_open=False, prepare=None):
    """``_run(code)`` in an undo transaction (left open for a task panel when
    ``keep_open``); on failure the transaction is undone and nothing is left. ``code`` may be
    (creation, recompute), run apart with ``prepare(obj)`` between them (obj: the object
    created)."""
    doc.openTransaction(title)
    names = {o.Name for o in doc.Objects}
    try:
        if isinstance(code, tuple):
            obj = _run(code[0])
            if prepare is not None and obj is not None:
                prepare(obj)
            obj = _run(code[1]) or obj
        else:
            obj = _run(code)
    except Exception as exc:
        abort_transaction(doc, title)
        for o in list(doc.Objects):          # without undo (freecadcmd) abort keeps them
            if o.Name not in names:
                doc.removeObject(o.Name)
        message(f"{title} failed: {type(exc).__name__}: {exc}")
        return None
    if not keep_open:
        doc.commitTransaction()
    return obj


def _check_and_create(title, what, check, code, open_panel, wrong=message, prepare=None):
    """Run ``check()`` (the feature's core on the input; InputProblem = bad input, said by
    ``wrong``),
    then create the feature by the recorded ``code`` (a string, or a function giving
    it after the check) and open its task panel. ``check`` may return a note (why the
    command chose other values than the usual defaults): said in the report view and at
    the top of the panel. Returns the new feature or None (message printed, document
    unchanged). ``prepare``: _create's, given the object created before its recompute."""
    if open_panel and dialog_open():
        message(DIALOG_OPEN)
        return None
    try:
        note = check()
    except InputProblem as exc:
        say_wrong(wrong, exc)
        return None
    except Exception as exc:  # anything unexpected: report, never escape
        message(f"{what} failed: {type(exc).__name__}: {exc}")
        return None
    doc = App.ActiveDocument
    panel = open_panel and App.GuiUp
    obj = _create(doc, title, code() if callable(code) else code, keep_open=panel,
                  prepare=prepare)
    if obj is not None and note:
        message(f"{obj.Label}: {note}", error=False)
        save_note(obj, note)            # its panel says it later too, while it holds
    if panel and obj is not None:
        from . import taskpanels
        taskpanels.open_for(obj, created=True, note=note or "")
    return obj


def _hand(checked):
    """_create's ``prepare``: the check's outcome (kept.checked_call, the last in the list
    ``checked``) handed to the new feature, whose first recompute takes it where it makes
    the same call (FeatureProxy.handed): creation computes once."""
    def prepare(obj):
        if checked:
            obj.Proxy.checked = checked[-1]
    return prepare


def _doc():
    doc = App.ActiveDocument
    if doc is None:
        message("no active document")
    return doc


def _in_active_document(objs, doc, wrong, said=None):
    """Whether every object of ``objs`` is in ``doc``, the active one, where the feature is
    made: it links them, and FreeCAD 0.20's links take no object of another document (its
    raw exception, 'PropertyLinkSubList does not support external object'); else ``wrong``
    says so in words (``said(where)``, where = "document(s) '...'") and False."""
    docs = [o.Document for o in objs]
    if all(d == doc for d in docs):
        return True
    where = (("documents " if len(set(docs)) > 1 else "document ")
             + " and ".join(dict.fromkeys(f"'{d.Label}'" for d in docs)))
    wrong(said(where) if said else
          f"the selection is in {where}: the new feature links what it reads, so that must be "
          f"in the active document ('{doc.Label}'); copy it there (Edit > Copy, Paste)")
    return False


def dialog_open():
    """A task dialog is open (ours or FreeCAD's, e.g. the Sketcher's edit)."""
    return bool(App.GuiUp and Gui.Control.activeDialog())


DIALOG_OPEN = "a task dialog is open: finish it (OK or Cancel) first"


def _selected_edges():
    return sum(n.startswith("Edge") for s in Gui.Selection.getSelectionEx()
               for n in s.SubElementNames)


class _Command:
    """A toolbar command: ``run(selection, wrong=...)``, guarded; active with a document, no
    task dialog open (as FreeCAD's own commands that open one: a second panel replaced the
    first without its OK or Cancel, and left a sketch in edit mode) and a selection it may
    take (``fits``: something selected, as Part_Offset2D; a selection it cannot use opens
    the 'Wrong selection' box, as Part_RuledSurface's)."""

    pixmap = menu = tip = needs = ""       # needs: what to select ('Wrong selection' box)

    def GetResources(self):
        return {"Pixmap": icon(self.pixmap), "MenuText": self.menu, "ToolTip": self.tip}

    @staticmethod
    def fits():
        return bool(Gui.Selection.getSelection())

    def IsActive(self):
        return App.ActiveDocument is not None and not dialog_open() and self.fits()

    def Activated(self):
        _guarded(type(self).run, self.menu, self.needs)


# ------------------------------------------------------------------ fit

def fit_sources(sources, csv_file="", open_panel=True, wrong=message, **options):
    """Check the fit input, create the Fit feature (recorded), open its task panel.
    ``options`` override the preferences: Model, Distance, SplitAtInflection, PinStart,
    PinEnd, UseStartCurvature, StartCurvature, UseEndCurvature, EndCurvature,
    StartContinuity, EndContinuity,
    ResampleStep, Tolerance, Degree, Thousands (how csv_file is read, by the check too).
    Returns the new feature or None (``wrong`` said why, document unchanged)."""
    from . import fit, fit_core, sources as src_mod
    doc = _doc()
    if doc is None or not _in_active_document([o for o, _ in sources], doc, wrong):
        return None
    tol, deg, model = defaults()
    opts = {"Model": model, "Tolerance": tol, "Degree": deg}
    opts.update(options)

    checked = []

    def check():
        notes, names = [], []
        # the file read as the feature will read it (a Thousands option: its property)
        thousands = src_mod.THOUSANDS[opts.get("Thousands", "auto")]
        checked.append(fit_core.check_fit(
            src_mod.gather_points(sources, csv_file, notes=notes, thousands=thousands,
                                  element=as_followed(), names=names), notes,
            names=names, **fit.core_options(opts)))

    def prepare(obj):
        """The check's fit is the new feature's first recompute's (fit_core.fit_gathered
        takes it where the feature reads the same input)."""
        obj.Proxy.checked = checked[-1]

    return _check_and_create(
        "Fit elastica", "fit", check,
        ("from freecad.elastica import fit as elastica_fit\n"
         f"_fit = elastica_fit.make({_ref_doc(doc)}, {_src(sources)}, csv_file={csv_file!r}, "
         f"{_kw(opts)})", f"{_ref_doc(doc)}.recompute()"), open_panel, wrong, prepare)


class FitCommand(_Command):
    pixmap, menu = "fit", "Fit elastica"
    needs = "sketch edges or vertices, a Points object or a 3D polyline (Draft wire, B-spline)"
    tip = ("Fit an elastica (discrete or smooth) to the selected sketch edges or "
           "vertices, a Points object or a 3D polyline; output a parametric feature "
           "and/or a B-spline in a sketch")
    run = staticmethod(fit_sources)


class FitCsvCommand(_Command):
    pixmap, menu = "fit_csv", "Fit elastica to CSV file..."
    tip = ("Fit an elastica to x,y[,z] points read from a CSV / text file "
           "(3D points are plane-fitted)")
    fits = staticmethod(lambda: True)       # it asks for its file

    def Activated(self):
        from PySide import QtGui
        path, _ = QtGui.QFileDialog.getOpenFileName(
            Gui.getMainWindow(), "Points to fit", "", "Point files (*.csv *.txt *.xyz);;All (*)")
        if path:
            opts = csv_thousands(path, _ask_thousands)
            if opts is not None:                # None: the question cancelled
                _guarded(lambda _sel, wrong: fit_sources([], csv_file=path, wrong=wrong,
                                                         **opts), self.menu)


def csv_thousands(path, ask):
    """fit_sources' Thousands option for the point file ``path``: {} where the file shows
    how '.' and ',' are meant (or is unreadable either way: the fit's check says why); where
    it does not (read_points refuses it as auto and reads it both ways: every number d.ddd,
    or in a tab file d,ddd), ``ask(path, sep)``'s answer for that separator, '.' or ','
    ('.', ',' or 'none'; None = cancelled, returned)."""
    from .geometry import binding_module
    read_points = binding_module("io").read_points

    def reads(thousands):
        try:
            return read_points(path, min_points=1, thousands=thousands)
        except ValueError:
            return None

    if reads(None) is not None:
        return {}
    grouped, dot, comma = reads("."), reads(""), reads(",")
    if dot is None:
        return {}
    if grouped is not None and not (grouped.shape == dot.shape and (grouped == dot).all()):
        sep = "."                       # 1.250: 1250 or 1.25
    elif comma is not None and not (comma.shape == dot.shape and (comma == dot).all()):
        sep = ","                       # 1,250: 1250 or 1.25
    else:
        return {}
    choice = ask(path, sep)
    return None if choice is None else {"Thousands": choice}


def _ask_thousands(path, sep="."):
    """The user's answer for csv_thousands: ``sep`` ('.' or ','), 'none' or None (cancelled)."""
    import os
    from PySide import QtGui
    point = "a decimal point" if sep == "." else "a decimal comma"
    box = QtGui.QMessageBox(QtGui.QMessageBox.Question, "Points to fit",
                            f"{os.path.basename(path)}: its numbers (1{sep}000, 2{sep}421 ...) do "
                            f"not show whether '{sep}' groups thousands or is {point}.",
                            QtGui.QMessageBox.Cancel, Gui.getMainWindow())
    grouped = box.addButton(f"'{sep}' groups thousands (1{sep}000 = 1000)",
                            QtGui.QMessageBox.AcceptRole)
    decimal = box.addButton(f"'{sep}' is {point} (1{sep}000 = 1)", QtGui.QMessageBox.AcceptRole)
    box.exec_()
    return {grouped: sep, decimal: "none"}.get(box.clickedButton())


# ------------------------------------------------------------------ blend

def _two_edges(sources):
    edges = [(o, s) for o, subs in sources for s in subs if s.startswith("Edge")]
    return edges if len(edges) == 2 else None


def blend_sources(sources, open_panel=True, picks=None, wrong=message):
    """Check two selected edges, create the Blend feature (recorded), open its panel.
    ``picks``: {(object name, subname): point clicked} (selection_picks): each edge is
    left at its end nearer the click (blend.chosen_ends); without: the nearest ends."""
    from . import blend, blend_start
    from .geometry import is_sketch
    doc = _doc()
    if doc is None:
        return None
    edges = _two_edges(sources)
    if edges is None:
        wrong("select exactly two edges (each is joined at its end nearer where it was "
              "clicked)")
        return None
    if not _in_active_document(
            [o for o, _ in edges], doc, wrong,
            lambda where: f"the two edges are in {where}: a blend links both edges, so they "
            f"must be in one document, the active one ('{doc.Label}'); copy an edge into it "
            "(Edit > Copy, Paste)"):
        return None

    opts, checked = {}, []

    def check():
        """The free batten (the default); where none joins the ends (good ends all the
        same), a length that gives blends (blend_start.starting_length): the feature is made
        by it and its panel opens, where the designer changes it. The blend solved is the
        new feature's first recompute's (``checked``: handed)."""
        e1, e2 = element_as_followed(*edges[0]), element_as_followed(*edges[1])
        for (obj, sub), e in zip(edges, (e1, e2)):   # bad input: no feature, a message
            blend.check_open(e, f"{obj.Label}.{sub}")
        a, b = blend.chosen_ends(e1, e2, *((picks or {}).get((o.Name, sub))
                                           for o, sub in edges))
        opts.update(at_end1=a, at_end2=b)
        plane = None
        if edges[0][0] == edges[1][0] and is_sketch(edges[0][0]):
            plane = edges[0][0].getGlobalPlacement()
        start = blend_start.free_or_length(e1, a, e2, b, plane, hand=checked)
        if start is None:
            return None
        opts.update(Mode="length", Length=start[0])
        return start[1]

    return _check_and_create(
        "Elastic blend", "blend", check,
        lambda: ("from freecad.elastica import blend as elastica_blend\n"
                 f"_blend = elastica_blend.make({_ref_doc(doc)}, ({_ref(edges[0][0])}, "
                 f"{edges[0][1]!r}), ({_ref(edges[1][0])}, {edges[1][1]!r})"
                 f"{', ' + _kw(opts) if opts else ''})", f"{_ref_doc(doc)}.recompute()"),
        open_panel, wrong, _hand(checked))


class BlendCommand(_Command):
    pixmap, menu = "blend", "Elastic blend"
    needs = "two coplanar edges, each clicked near the end to join"
    tip = ("Join two selected coplanar edges of the active document by an elastica, each "
           "at its end nearer where you clicked it: the free batten, or every Hermite "
           "solution for a tension or a length")
    run = staticmethod(blend_sources)

    @staticmethod
    def fits():
        """Two edges selected, as Part_Section and Part_Fuse wait for two shapes."""
        return _selected_edges() == 2

    def Activated(self):
        _guarded(lambda sel, wrong: blend_sources(sel, picks=selection_picks(), wrong=wrong),
                 self.menu, self.needs)


# ------------------------------------------------------------------ elastic spline

def spline_sources(sources, open_panel=True, wrong=message, **options):
    """Check the picked points, create the Elastic spline (recorded), open its task
    panel. ``options`` set Mode, Tension, Length, Closed (default: closed when the
    points are a closed wire's), Tolerance, Degree, ..."""
    from . import spline, sources as src_mod
    doc = _doc()
    if doc is None or not _in_active_document([o for o, _ in sources], doc, wrong):
        return None
    opts, checked = {"Tolerance": defaults()[0]}, []
    opts.update(options)

    def check():
        """The free batten (the default); where none passes the points, a tension whose
        batten does not loop and holds (spline.starting_tension): the feature is made at it
        and its panel opens, where the designer changes it. A mode or tension given: as given. The
        spline solved is the new feature's first recompute's (``checked``: handed)."""
        pts, plane = src_mod.gather_vertices(sources, spline.DUCKS_NEED, edge_means_object=True,
                                             curve_ordered=True, element=as_followed())
        if "Closed" not in opts:
            opts["Closed"] = spline.ends_at_start(pts)     # the feature follows it after
        degree = opts.get("Degree", spline.BSPLINE_DEGREE)
        try:
            checked.append(checked_call(
                spline.spline_core, pts, plane, opts.get("Mode", "tension"),
                opts.get("Tension", 0.0), opts.get("Length", 0.0), opts["Closed"],
                tol=opts["Tolerance"], degree=degree))
            return None
        except spline.NoSpline:
            if "Mode" in options or "Tension" in options:     # asked for: said as it is
                raise
            tension, note = spline.starting_tension(pts, plane, opts["Closed"],
                                                    opts["Tolerance"], degree, hand=checked)
        opts["Tension"] = tension
        return note

    return _check_and_create(
        "Elastic spline", "elastic spline", check,
        lambda: ("from freecad.elastica import spline as elastica_spline\n"
                 f"_spline = elastica_spline.make({_ref_doc(doc)}, {_src(sources)}, {_kw(opts)})",
                 f"{_ref_doc(doc)}.recompute()"), open_panel, wrong, _hand(checked))


class SplineCommand(_Command):
    pixmap, menu = "spline", "Elastic spline"
    needs = "the points to pass through: sketch points or vertices, a Points object or a Draft wire"
    tip = ("The batten through the selected points (sketch points or vertices, a Points "
           "object, a Draft wire): elasticae of one tension, curvature continuous at every "
           "point; natural, tangent or G2 ends; closed; by tension or length")
    run = staticmethod(spline_sources)


# ------------------------------------------------------------------ elliptic blend

def ellblend_sources(sources, open_panel=True, wrong=message, **options):
    """Check the picked points, create the elliptic blend curve (recorded), open its
    task panel. ``options`` set Mode (interpolate / control), Closed, K, KConvention
    (modulus / parameter), D, Tolerance."""
    from . import ellblend, sources as src_mod
    doc = _doc()
    if doc is None or not _in_active_document([o for o, _ in sources], doc, wrong):
        return None
    opts = {"Mode": "interpolate", "K": 0.5, "KConvention": "modulus", "D": 2.0,
            "Tolerance": defaults()[0]}
    opts.update(options)
    checked = []

    def check():
        pts, plane = src_mod.gather_vertices(sources, element=as_followed())
        checked.append(checked_call(ellblend.ellblend_core, pts, plane, opts["Mode"], opts["K"],
                                    opts["D"], opts["Tolerance"], opts["KConvention"],
                                    opts.get("Closed", False)))

    return _check_and_create(
        "Elliptic blend curve", "elliptic blend", check,
        ("from freecad.elastica import ellblend as elastica_ellblend\n"
         f"_ellblend = elastica_ellblend.make({_ref_doc(doc)}, {_src(sources)}, {_kw(opts)})",
         f"{_ref_doc(doc)}.recompute()"), open_panel, wrong, _hand(checked))


class EllipticBlendCommand(_Command):
    pixmap, menu = "ellblend", "Elliptic blend curve"
    needs = "three or more coplanar points in order (vertices), or a sketch of points"
    tip = ("A curve with Jacobi elliptic blending functions through picked coplanar "
           "points (or with them as control points): four make one segment, three or "
           "more a smooth chain of segments, open or closed; select vertices in order, "
           "or a sketch of points")
    run = staticmethod(ellblend_sources)


# ------------------------------------------------------------------ G2 quadratic

def g2quad_sources(sources, open_panel=True, wrong=message, **options):
    """Check the picked curve, create the G2 quadratic B-spline (recorded), open its panel."""
    from . import g2quad, sources as src_mod
    doc = _doc()
    if doc is None or not _in_active_document([o for o, _ in sources], doc, wrong):
        return None
    opts = {"Edges": 24}
    opts.update(options)
    checked = []

    def check():
        edges, plane = src_mod.gather_edges(sources, element=as_followed())
        # EdgesProblem (another Edges builds it): the feature made all the same, in error (its
        # Status names the count), with its panel's Edges box to type it in, as FreeCAD's own
        # features are (QA gui F2: refused in a box whose advice had nowhere to go); its first
        # recompute raises the check's error again (kept.Raised), not the search once more
        checked.append(checked_call(g2quad.g2quad_core, edges, plane, opts["Edges"],
                                    raises=g2quad.EdgesProblem))

    return _check_and_create(
        "G2 quadratic B-spline", "G2 quadratic B-spline", check,
        ("from freecad.elastica import g2quad as elastica_g2quad\n"
         f"_g2 = elastica_g2quad.make({_ref_doc(doc)}, {_src(sources)}, {_kw(opts)})",
         f"{_ref_doc(doc)}.recompute()"), open_panel, wrong, _hand(checked))


class G2QuadCommand(_Command):
    pixmap, menu = "g2quad", "G2 quadratic B-spline"
    needs = "an edge or sketch curve, or a chain of them (open or closed)"
    tip = ("A curvature-continuous uniform quadratic B-spline (seed 002) of the selected "
           "edge or sketch curve, ending exactly on it, split at its inflections")
    run = staticmethod(g2quad_sources)


# ------------------------------------------------------------------ comb

def comb_sources(sources, wrong=message):
    """ONE curvature comb of the selected results / edges (recorded), on one scale: a blend
    and the edges it joins selected together are combed as one, so equal curvature gives
    equal teeth across the joint (QA gui F5: two combs on scales 946 and 1670, their teeth
    1.76 x apart where they met); a single source's comb as before. ``wrong`` says why a
    source cannot be combed (it is left out)."""
    from . import comb
    doc = App.ActiveDocument
    if doc is None or not sources:
        wrong("select an Elastica result or some edges")
        return []
    good = []
    for obj, subs in sources:
        other = [s for s in subs if not s.startswith("Edge")]
        if other:      # as the other commands refuse a face (it combed every edge of its object)
            wrong(f"{obj.Label}.{other[0]}: select edges or the whole object, not {other[0]}")
            continue
        try:
            comb.comb_core(obj, subs, 8)
        except InputProblem as exc:
            wrong(f"{obj.Label}: {exc}")
            continue
        except Exception as exc:
            message(f"{obj.Label}: comb failed: {type(exc).__name__}: {exc}")
            continue
        good.append((obj, subs))
    if not good:
        return []
    (obj, subs), more = good[0], good[1:]
    also = ", more=[" + ", ".join(f"({_ref(o)}, {s!r})" for o, s in more) + "]" if more else ""
    c = _create(doc, "Curvature comb", "from freecad.elastica import comb as elastica_comb\n"
                f"_comb = elastica_comb.make({_ref_doc(doc)}, {_ref(obj)}, {subs!r}{also})\n"
                f"{_ref_doc(doc)}.recompute()")
    return [c] if c is not None else []


class CombCommand(_Command):
    pixmap, menu = "comb", "Curvature comb"
    needs = "Elastica results or edges"
    tip = ("A parametric curvature comb along the selected Elastica results or edges: one "
           "comb on one scale for all of them (equal curvature, equal teeth)")
    run = staticmethod(comb_sources)


COMMANDS = {"Elastica_Fit": FitCommand, "Elastica_FitCsv": FitCsvCommand,
            "Elastica_Blend": BlendCommand, "Elastica_Spline": SplineCommand,
            "Elastica_EllipticBlend": EllipticBlendCommand,
            "Elastica_G2Quad": G2QuadCommand, "Elastica_Comb": CombCommand}


def register():
    # FreeCAD names a command's module after the file that calls Gui.addCommand and writes
    # 'import <it>' into a macro recorded as the command runs: 'import commands', no module
    # outside this package, so a recorded macro stopped at its first line; added by code
    # named FreeCADGui, the macro imports FreeCADGui
    add = compile("Gui.addCommand(name, command)", "FreeCADGui", "exec")
    for name, cls in COMMANDS.items():
        exec(add, {"Gui": Gui, "name": name, "command": cls()})
    return list(COMMANDS)
