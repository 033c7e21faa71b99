"""What every Elastica feature shares: ``InputProblem`` (a message for the user), typed
properties with tooltips, checks of typed values that explain instead of clamping,
and ``FeatureProxy``, the base of the Part::FeaturePython proxies.

A proxy's ``execute`` calls its ``compute`` (gathers geometry, calls the library,
raises InputProblem for bad input) and then ``apply`` (writes shape and results).
Every failure becomes a message in the report view and in the ``Status``
property; the previous shape is kept (objects built on it keep working) and the
view provider draws it dashed. Nothing here imports GUI code: view providers are
attached through ``VIEW_HOOK``, which the GUI (init_gui) sets.
"""
from __future__ import annotations

import json
import math
import sys

import FreeCAD as App

from .containers import (add_containers, follow_containers, holder_placement, link_properties,
                         keep_in_place, moved_holder, remember_holder, restore_containers)
from .kept import Raised, call_key, input_key, is_input
from .units import exact_mark, mm_marked, per_area_mark, say, tension_unit_mark

VERSION = 5             # of the proxies' saved state (3: lengths typed with units;
                        # 4: a blend's Solution counts from 1, as its list; 5: a Shape in
                        # its container's coordinates, containers.set_shape)
VIEW_HOOK = []          # [attach(obj), restored(obj)] set by init_gui: view providers
IDLE_HOOK = []          # [later(fn)] set by init_gui: fn run once the GUI's event loop is idle


class InputProblem(ValueError):
    """Unusable input for a feature (a message for the user, not a bug)."""


class ShapeProblem(InputProblem):
    """Input selected as the command asks whose shape the feature cannot take (a G2
    quadratic's end piece beyond an inflection too short for its edges): a command says
    it under its own name, not as a 'Wrong selection' asking to select what was selected
    (QA22gui F6)."""


class RecomputeError(App.Base.FreeCADError):
    """A feature's failed recompute, raised to FreeCAD (FeatureProxy.execute)."""


def raise_reported(msg):
    """Fail a recompute whose message is already in the report view, without the Python
    traceback FreeCAD prints for an exception out of a Python feature's execute (0.20:
    FeaturePythonImp::execute -> Base::PyException::ThrowException -> ReportException).
    The exception carries FreeCAD's own exception dictionary, as its C++ exceptions cross
    Python (Base::Exception::getPyObject), with 'breported' set: PyException then takes it
    as reported and prints nothing, and FeaturePythonT::execute still returns its message
    as the feature's error (State 'Invalid', the tree's error mark, getStatusString()).
    Only an un-normalised exception keeps the dictionary (PyErr_SetObject; Python 3.12
    normalises at once): elsewhere RecomputeError, traceback and all."""
    if sys.version_info < (3, 12):
        import ctypes
        # a prototype of its own (not ctypes.pythonapi's shared function object, whose
        # argtypes other code may set); a PYFUNCTYPE call raises the error it set, as it
        # stands (it checks PyErr_Occurred)
        set_object = ctypes.PYFUNCTYPE(None, ctypes.py_object, ctypes.py_object)(
            ("PyErr_SetObject", ctypes.pythonapi))
        set_object(App.Base.FreeCADError, {"swhat": msg, "sErrMsg": msg, "breported": True})
    raise RecomputeError(msg)


def add_property(obj, kind, name, group, tip, value=None):
    """Add a property (with its tooltip) unless the object has it already."""
    if name not in obj.PropertiesList:
        obj.addProperty(kind, name, group, tip)
        if value is not None:
            setattr(obj, name, value)


# A length the designer types is an App::PropertyDistance: the property editor shows it
# with its unit and parses one ("6.5 cm"), as FreeCAD's own features' lengths. Not
# App::PropertyLength, which sets a negative value to 0 silently; the feature's check
# names the value typed instead (check_number).
LENGTH = "App::PropertyDistance"


def bound_expression(obj, name):
    """The expression property ``name`` of ``obj`` is bound to, or None."""
    return dict(getattr(obj, "ExpressionEngine", [])).get(name)


def _take_out(obj, name):
    """Remove property ``name`` (to be added again with another type): its (value,
    expression)."""
    value, expression = float(getattr(obj, name)), bound_expression(obj, name)
    if expression:
        obj.setExpression(name, None)
    obj.removeProperty(name)
    return value, expression


def add_length(obj, name, group, tip, value=None):
    """A length property (LENGTH). Documents of version 2 stored it as App::PropertyFloat:
    that property is replaced, its value and expression kept."""
    expression = None
    if name in obj.PropertiesList and obj.getTypeIdOfProperty(name) == "App::PropertyFloat":
        value, expression = _take_out(obj, name)
    add_property(obj, LENGTH, name, group, tip, value)
    if expression:
        obj.setExpression(name, expression)


# A tension (1/mm^2) the designer types is an App::PropertyPrecision: FreeCAD's property
# view shows a float property with 2 decimals (0.001 as "0.00", QA19gui F10), a precision one
# with 16 (FreeCAD 0.20 has no typed property of 1/length^2). Its bounds are opened to every
# double (its own, [0, max], clamp a compression to 0) and set again on restore: a file keeps
# no bounds.
PER_AREA = "App::PropertyPrecision"
_ANY = (-sys.float_info.max, sys.float_info.max, 1e-4)     # bounds, arrows' step


def add_per_area(obj, name, group, tip, value=0.0):
    """A tension property (PER_AREA). Documents of version 3 stored it as
    App::PropertyFloat: that property is replaced, its value and expression kept (as on
    every restore, its bounds set again)."""
    expression = None
    if name not in obj.PropertiesList:
        obj.addProperty(PER_AREA, name, group, tip)
    elif obj.getTypeIdOfProperty(name) != PER_AREA:
        value, expression = _take_out(obj, name)
        obj.addProperty(PER_AREA, name, group, tip)
    else:
        value = float(getattr(obj, name))
    setattr(obj, name, (value,) + _ANY)
    if expression:
        obj.setExpression(name, expression)


# What a feature reads is linked with global scope (App::PropertyLinkSubGlobal, ...), as
# Draft's path array links its path: a feature at document level reads a sketch inside a
# PartDesign Body or an App::Part, which a link of local scope may not reach (FreeCAD
# warned "Link(s) to object(s) 'Sketch' go out of the allowed scope 'ElasticaFit'" at each
# recompute). The features stay at document level, their shapes in global coordinates.
def add_link(obj, kind, name, group, tip):
    """A link property ``kind`` ('App::PropertyLinkSub', 'App::PropertyLinkSubList') of
    global scope. Documents made before stored it with local scope: that property is
    replaced, its value kept."""
    scoped = kind + "Global"
    if name in obj.PropertiesList and obj.getTypeIdOfProperty(name) == kind:
        value = getattr(obj, name)
        obj.removeProperty(name)
        add_property(obj, scoped, name, group, tip, value)
        return
    add_property(obj, scoped, name, group, tip)


def add_geometry_index(obj, name, link, several=False):
    """The hidden property ``name``: the indices of the sketch geometry the link ``link``
    follows (links.followed_elements): an integer for a one-edge link (-1 until the link is
    first resolved), a string list for a list or, ``several``, a PropertyLinkSub naming
    several sub-elements of its object, one entry per sub-element."""
    group = obj.getGroupOfProperty(link)
    if several or obj.getTypeIdOfProperty(link).startswith("App::PropertyLinkSubList"):
        add_property(obj, "App::PropertyStringList", name, group,
                     f"Index of the sketch geometry of each sub-element of {link}, followed as "
                     "the sketch changes: 'i' (its edge), 'i:start' / 'i:end' (a vertex; -1: "
                     "not resolved yet, -2: deleted)")
    else:
        add_property(obj, "App::PropertyInteger", name, group,
                     f"Index of {link}'s geometry in its sketch, followed as the sketch changes "
                     "(-1: not resolved yet, -2: deleted)", -1)
    obj.setEditorMode(name, 2)
    # links.TAGS: the Tags of what the links follow, in this session only (transient: not
    # saved; output: recording them touches nothing)
    if "FollowedTags" not in obj.PropertiesList:
        obj.addProperty("App::PropertyMap", "FollowedTags", group, "The sketch geometry the "
                        "links follow in this session: {link: its slots' Tags}", 2 | 4 | 8)


# Which end of an edge a feature joins (spline ends, fit tangents): the end nearest the points'
# end (a script's choice), or the vertex nearer where the designer clicked the edge in the
# panel (Gui.Selection's PickedPoints, as the Elastic blend reads a click: blend.picked_end)
EDGE_ENDS = ["nearest", "start vertex", "end vertex"]


def add_edge_end(obj, name, group, link):
    """The enumeration ``name`` (EDGE_ENDS) saying which end of the edge ``link`` is joined."""
    add_enum(obj, name, group, f"Which end of {link} is joined: nearest (the end nearest the "
             "points' end), or its start / end vertex (the end nearer where the edge was "
             "clicked when picked in the panel)", EDGE_ENDS, "nearest")


def edge_end_choice(obj, name):
    """None (the nearest end), False (the edge's start vertex) or True (its end vertex)."""
    value = getattr(obj, name, "nearest")
    return None if value == "nearest" else value == "end vertex"


def add_enum(obj, name, group, tip, values, value=None):
    """An enumeration property; when it has no values yet (new object) they are
    set, and the current one to value (default: the first)."""
    add_property(obj, "App::PropertyEnumeration", name, group, tip)
    if not obj.getEnumerationsOfProperty(name):
        setattr(obj, name, list(values))
        if value is not None:
            setattr(obj, name, value)


def read_only(obj, *names):
    for name in names:
        obj.setEditorMode(name, 1)


def check_number(name, value, lo=None, hi=None, unit="", lo_open=False, why=""):
    """``value`` as a float, or InputProblem saying what was typed and what is
    possible (NaN, infinities and out-of-range values are never clamped)."""
    v = float(value)
    ok = math.isfinite(v) and (lo is None or (v > lo if lo_open else v >= lo)) \
        and (hi is None or v <= hi)
    if ok:
        return v
    # a length (finite) from its exact value in the unit FreeCAD picks for it, each bound too
    # (units.exact_mark): not its '%g' text in mm said again by mm_marked (rounded twice)
    mark = unit == "mm"
    # a tension in the schema's 1/unit² as the panel's boxes and Status write it (QA23gui
    # F10: the report view said '-0.5 1/mm^2', the panel '1/mm²')
    area = unit == "1/mm^2"
    said = exact_mark if mark else (lambda x: f"{per_area_mark(x, 6)} {tension_unit_mark()}") \
        if area else (lambda x: f"{x:g}")
    rng = ""
    if lo is not None and hi is not None:
        rng = f"{'(' if lo_open else '['}{said(lo)}, {said(hi)}]"
    elif lo is not None:
        rng = f"{'>' if lo_open else '>='} {said(lo)}"
    typed = said(v) if (mark or area) and math.isfinite(v) else \
        f"{v:g}{' ' + (tension_unit_mark() if area else unit) if unit else ''}"
    raise InputProblem(f"{name} = {typed} is not usable: it must be {rng or 'finite'}"
                       f"{' ' + unit if unit and rng and not (mark or area) else ''}"
                       + (f" ({why})" if why else ""))


def check_tolerance(value, name="Tolerance"):
    """A B-spline tolerance in mm: finite, at least 1e-9 mm (below that nothing is
    measured, and a FreeCAD file stores 16 decimals)."""
    return check_number(name, value, 1e-9, None, "mm",
                        why="a B-spline closer than a nanometre is not measurable")


def check_degree(value, lo=3, hi=7, name="Degree"):
    v = int(value)
    if not lo <= v <= hi:
        raise InputProblem(f"{name} = {v} is not usable: B-splines here have degree {lo} to {hi}")
    return v


def report(obj, msg, error=True):
    """The message in the report view (not during a panel's live preview) and, as
    'error: ...', in obj.Status (its marks said in the schema of now, units.say; its marked
    text saved for said())."""
    msg = mm_marked(msg)          # '<number> mm' in the schema's length unit
    if not getattr(getattr(obj, "Proxy", None), "previewing", False):
        # a panel's live preview says it on its error line only (panelbase.Panel.update)
        (App.Console.PrintError if error else App.Console.PrintWarning)(
            f"Elastica {obj.Label}: {say(msg)}\n")
    if "Status" in obj.PropertiesList:
        set_said(obj, "Status", f"error: {msg}" if error else msg)


# The marked texts behind the said ones (set_said), in a hidden property beside them, so that
# Undo and Redo restore both together (a proxy's own state is no part of a transaction: after
# an Undo the panel said the older Status as stored, in the schema of its recompute), and a
# file keeps them: JSON {prop: [said text, marked text]} (its escapes keep the marks'
# control characters out of the file's XML).
SAID = "SaidTexts"


def add_said(obj):
    """The hidden property SAID (output: setting it touches nothing); a document saved
    before it kept the marked texts in the proxy's state ('said'): they move there."""
    if SAID in obj.PropertiesList:
        return
    obj.addProperty("App::PropertyString", SAID, "Result", "The texts of Status and Warnings "
                    "with their figures marked, said again in the unit schema of now", 4 | 8)
    proxy = getattr(obj, "Proxy", None)
    old = getattr(proxy, "_said", None)
    if old:
        setattr(obj, SAID, json.dumps(old, sort_keys=True))
        proxy._said = {}


def _said_texts(obj):
    """{prop: [said text, marked text]} that set_said wrote (SAID, or the proxy's 'said')."""
    text = getattr(obj, SAID, "") if SAID in obj.PropertiesList else ""
    return json.loads(text) if text else dict(getattr(getattr(obj, "Proxy", None), "_said", None)
                                              or {})


def set_said(obj, prop, marked):
    """Set the text (or list of texts) property ``prop`` to ``marked`` said in the schema of
    now (units.say), keeping the marked text for said() (in SAID)."""
    value = say(marked)
    old = getattr(obj, prop)
    if (list(old) if isinstance(old, (list, tuple)) else old) != value:   # unchanged: untouched
        setattr(obj, prop, value)
    texts = _said_texts(obj)
    texts[prop] = [value, list(marked) if isinstance(marked, (list, tuple)) else marked]
    if SAID in obj.PropertiesList:
        text = json.dumps(texts, sort_keys=True)
        if getattr(obj, SAID) != text:
            setattr(obj, SAID, text)
    elif getattr(obj, "Proxy", None) is not None:      # not an Elastica feature's: its proxy
        obj.Proxy._said = texts


def resay(obj):
    """The texts set_said wrote, said again in the unit schema of now where the properties
    still hold them (as a recompute's apply says them)."""
    for prop, (value, marked) in _said_texts(obj).items():
        if prop in obj.PropertiesList:
            now = getattr(obj, prop)
            if (list(now) if isinstance(now, (list, tuple)) else now) == value:
                set_said(obj, prop, marked)


def said(obj, prop, figures=False):
    """The text property ``prop`` in the user's schema of now: its marked text said again
    where the property still holds what set_said wrote (a schema changed since the
    recompute), else the property as it stands; ``figures``: as a panel says it (units.say)."""
    value = getattr(obj, prop)
    texts = _said_texts(obj).get(prop)
    now = list(value) if isinstance(value, (list, tuple)) else value
    if texts and texts[0] == now:
        return say(texts[1], figures)
    return now


# Why a command chose the values it did (the blend's length where no free batten joins the
# ends, the spline's tension where the free batten loops), in a hidden property saved and
# undone with the feature, beside the values it explains: a panel opened later says it while
# they still hold (it lived only while the command's panel was open). JSON {"note": marked
# text, "values": {prop: value}}, the props a proxy's note_props.
NOTE = "StartNote"


def add_note(obj):
    """The hidden property NOTE of a feature whose proxy has note_props."""
    if NOTE not in obj.PropertiesList and getattr(obj.Proxy, "note_props", ()):
        obj.addProperty("App::PropertyString", NOTE, "Result", "Why the command chose the "
                        "values it did, while they hold (its panel says it)", 4 | 8)


def note_values(obj):
    """The values of the feature's note_props, as save_note saves them beside a note."""
    def value(v):
        if hasattr(v, "Value"):         # a length (Quantity)
            return float(v.Value)
        return float(v) if isinstance(v, (int, float)) else str(v)
    return {p: value(getattr(obj, p)) for p in obj.Proxy.note_props}


def _note_text(obj, note):
    return json.dumps({"note": note, "values": note_values(obj)}, sort_keys=True) if note else ""


def note_changes(obj, note):
    """Whether save_note(obj, note) would change what the feature has saved."""
    return NOTE in obj.PropertiesList and getattr(obj, NOTE) != _note_text(obj, note)


def save_note(obj, note):
    """Save ``note`` (marked text; '' forgets it) with the values of note_props it explains."""
    if note_changes(obj, note):
        setattr(obj, NOTE, _note_text(obj, note))


def saved_note(obj):
    """The note saved (save_note) while the values it explains still hold, else ''."""
    text = getattr(obj, NOTE, "") if NOTE in obj.PropertiesList else ""
    if not text:
        return ""
    saved = json.loads(text)
    return saved["note"] if saved["values"] == note_values(obj) else ""


def abort_transaction(doc, name):
    """Abort ``doc``'s transaction ``name``. One that changed nothing has no document
    transaction to abort and FreeCAD keeps its name pending (App.getActiveTransaction):
    the next change, a recompute or the user's, would become an Undo step under it
    (QA16 F3), so the pending name is closed too."""
    doc.abortTransaction()
    if (App.getActiveTransaction() or ("",))[0] == name:
        App.closeActiveTransaction(True)


def sub_names(subs):
    """A picked object's subelement names as a tuple (("",): the whole object): a list of
    names, or one name as a string ("Edge1", "": taken letter by letter, "KeylineSketch has
    no E", QA21gui F6)."""
    names = (subs,) if isinstance(subs, str) else tuple(subs)
    return names or ("",)


def source_list(sources):
    """[(obj, subnames)] of a make's ``sources``, each one's subnames as sub_names reads."""
    return [(o, sub_names(s)) for o, s in sources]


def new_feature(doc, name, proxy_class, **props):
    """A Part::FeaturePython ``name`` in ``doc`` with a ``proxy_class`` proxy, its
    properties set in the order given, and its view provider (GUI)."""
    obj = doc.addObject("Part::FeaturePython", name)
    proxy_class(obj)
    for k, v in props.items():
        setattr(obj, k, v)
    attach_view(obj)
    return obj


def attach_view(obj, restored=False):
    """The feature's view provider, when the GUI has installed VIEW_HOOK."""
    if VIEW_HOOK:
        VIEW_HOOK[1 if restored else 0](obj)


# properties whose change outside a recompute leaves its outcome standing (drop_kept): the
# label, the visibility, the links to the containers (their placements are in the key), a
# command's note
KEEPING = frozenset(("Label", "Label2", "Visibility", "Proxy", "Containers", NOTE,
                     "SketchCopies"))       # geometry.COPIES: where it was copied


class FeatureProxy:
    """Common state handling. Pickled state: kind, version and the exact values of
    the float properties (a FreeCAD file keeps 16 decimals of a float property:
    1e-300 would come back as 0); the properties hold the rest, so files stay
    readable without this code. Subclasses define setup (properties), compute
    (raises InputProblem) and apply (writes the result)."""

    kind = ""
    note_props = ()     # the properties a command's note explains (save_note)
    # {link property: the property of the sketch geometry indices it follows}: a sketch edge's or
    # vertex's name shifts as the sketch changes, its geometry is followed
    # (links.followed_elements)
    followed_links = {}

    def __init__(self, obj):
        self.Object = obj
        self._exact = {}
        obj.Proxy = self
        self.setup(obj)
        add_said(obj)
        add_note(obj)
        add_containers(obj)

    # ---------------------------------------------------------------- recompute

    def execute(self, obj):
        """compute, then apply; a failure is said in one line (report), the last good shape
        kept (drawn dashed), and raised to FreeCAD as reported (raise_reported: no
        traceback), which marks the feature in error as its own (the tree's error mark,
        "Recompute failed!", its dependents not recomputed). What it reads may have moved
        into or out of a container since: its link to them is set first
        (containers.follow_containers). Where nothing the outcome depends on changed since
        the last recompute (kept.input_key: a Pad of its sketch's Body changed, which
        recomputes the Body and so the feature), that outcome stands: the shape and
        results on the feature (their texts said again in the unit schema of now), or the
        error said again; no library is called."""
        follow_containers(obj)
        self._unplaced = False
        self._executing = True            # what it sets is its outcome (drop_kept)
        try:
            msg = self._outcome(obj)
            if msg is None:
                from .copies import say_drift
                say_drift(obj)            # its copies in sketches still its curve? (QA22gui F1)
                return
            report(obj, msg)
            self.on_error(obj)
            keep_in_place(obj)            # the kept Shape where it was drawn
        finally:
            self._executing = False
        raise_reported(f"Elastica {obj.Label}: {say(mm_marked(msg))}")

    def _outcome(self, obj):
        """The kept outcome where the key holds (its texts said again), else compute and
        apply; the failure's message or None. The key is taken once a recompute (~26 ms for
        a 50 000-point Points object): before it, and again after it only where the
        computation set an input of its own (self._inputs_set: a link renamed after its
        sketch's geometry, Closed following the wire; drop_kept notes it)."""
        key = input_key(obj)
        last = getattr(self, "_kept", None)
        if last is not None and last[0] is not None and last[0] == key:
            if last[1] is None:
                resay(obj)
            return last[1]
        self._kept, self._inputs_set = None, False
        msg, kept = self._computed(obj)
        if kept:
            self._kept = (input_key(obj) if self._inputs_set else key, msg)
        return msg

    def _computed(self, obj):
        """compute and apply: (None, True), or (the failure's message, whether it is kept:
        an InputProblem, the input's, not a bug's)."""
        from .bound import check_bound_units
        try:
            check_bound_units(obj)      # a cell of another unit (QA19gui F9, QA21gui F1)
            r = self.compute(obj)
        except InputProblem as exc:
            return str(exc), True
        except Exception as exc:  # a bug or a kernel error: report it, keep the shape
            return f"{type(exc).__name__}: {exc}", False
        self.apply(obj, r)
        return None, True

    def handed(self, core, *args, **kwargs):
        """``core(*args, **kwargs)``, or the outcome a command's check handed to this new
        feature (``checked``: kept.checked_call, set before its first recompute) where it is
        of that very call: the command computed it to judge its input, so creation computes
        once. Taken once: a later recompute computes."""
        checked, self.checked = getattr(self, "checked", None), None
        if checked is not None and checked[0] is not None:
            try:
                same = checked[0] == call_key(core, *args, **kwargs)
            except TypeError:       # no key for an argument (kept._comparable): computed
                same = False
            if same:
                if isinstance(checked[1], Raised):   # the check's exception, raised again
                    raise checked[1].exc
                return checked[1]
        return core(*args, **kwargs)

    def setup(self, obj):
        pass

    def mustExecute(self, obj):
        """Whether a recompute must execute the feature, touched or not (FreeCAD asks,
        FeaturePythonImp::mustExecute): a document saved before its link to the containers
        of what it reads, which reads through one (containers.restore_containers), or
        before its Shape was local to a placed container holding it (VERSION 5); the
        container holding it moved since its Shape was set (containers.moved_holder: what it
        reads may lie outside, where it stayed)."""
        return bool(getattr(self, "_unplaced", False)) or moved_holder(obj)

    def on_error(self, obj):
        """Called after a failed recompute (the message is in Status already)."""

    def read_links(self, obj):
        """The link properties a recompute reads (containers.read_objects: the containers
        placing their objects are linked): every one but Containers."""
        return link_properties(obj)

    def onBeforeChange(self, obj, prop):
        if prop in self.followed_links:
            link = getattr(obj, prop, None)
            self._removing = isinstance(link, tuple) and bool(link[0].Removing)

    def onChanged(self, obj, prop):
        if prop in self.followed_links:
            self.link_changed(obj, prop)
        self.drop_kept(obj, prop)

    def drop_kept(self, obj, prop):
        """Forget the kept outcome (execute) when a result is set by anything but the
        feature's own recompute (Undo, Redo, a document restored: an outcome of other
        input). Subclasses overriding onChanged call it."""
        if getattr(self, "_executing", False):
            if prop != "Shape" and is_input(obj, prop):
                self._inputs_set = True      # the key before the recompute is gone (_outcome)
        elif getattr(self, "_kept", None) is not None \
                and prop not in KEEPING and (prop == "Shape" or not is_input(obj, prop)):
            self._kept = None

    def link_changed(self, obj, prop):
        """Whether the link ``prop`` that changed names other geometry than it followed
        (links.relinked): a link the designer changed, emptied as its object is deleted;
        not one restored (a document opened, Undo, Redo: its indices and Tags are restored
        with it), nor followed_elements' renaming."""
        if "Restore" in obj.State or obj.Document.Transacting or \
                getattr(self, "_restoring", False) or \
                getattr(self, "_renaming", False) or \
                self.followed_links[prop] not in obj.PropertiesList:
            return False
        from .links import relinked
        return relinked(obj, prop, deleted=getattr(self, "_removing", False))

    # ---------------------------------------------------------------- save / restore

    def _float_props(self, obj):
        return [p for p in obj.PropertiesList
                if obj.getTypeIdOfProperty(p) in ("App::PropertyFloat", LENGTH, PER_AREA)]

    def __getstate__(self):
        state = {"kind": self.kind, "version": VERSION}
        obj = getattr(self, "Object", None)
        try:
            state["exact"] = {p: repr(float(getattr(obj, p))) for p in self._float_props(obj)}
        except Exception:  # no object (yet) / being deleted: nothing exact to keep
            pass
        if getattr(self, "_said", None):       # a document before SAID, not restored yet
            state["said"] = self._said
        if getattr(self, "_shape_global", False) and getattr(self, "_held", None) is None:
            state["shape_global"] = True       # reopened from version < 5, not recomputed since
        return state

    def __setstate__(self, state):
        self._version = int((state or {}).get("version") or 1)    # of the file's proxy
        self._exact = dict((state or {}).get("exact") or {})
        self._said = dict((state or {}).get("said") or {})
        self._shape_global = bool((state or {}).get("shape_global"))
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return self.__setstate__(state)

    def onDocumentRestored(self, obj):
        self.Object = obj
        version = getattr(self, "_version", VERSION)      # of the file (setup may set it)
        self._restoring = True        # the links it replaces (add_link) are no new links
        try:
            self.setup(obj)           # properties added by newer versions
        finally:
            self._restoring = False
        add_said(obj)
        add_note(obj)
        from .links import remember_followed
        remember_followed(obj)
        changed = False
        for p, text in getattr(self, "_exact", {}).items():
            if p not in obj.PropertiesList:
                continue
            v, stored = float(text), float(getattr(obj, p))
            # the file's rounding of the exact value: put the exact one back
            if v != stored and (f"{v:.16f}" == f"{stored:.16f}" or math.isnan(v)):
                setattr(obj, p, v)
                changed = True
        if changed:
            obj.purgeTouched()
        self._exact = {}
        self._unplaced = restore_containers(obj)
        # its Shape saved global (version < 5, or such a document saved again before the
        # feature recomputed: __getstate__'s shape_global): drawn off by the holder
        self._shape_global = version < 5 or getattr(self, "_shape_global", False)
        if self._shape_global and not holder_placement(obj).isIdentity():
            self._unplaced = True
        else:
            remember_holder(obj)          # saved where it was drawn: a move from here on
        attach_view(obj, restored=True)   # a document made without the GUI, opened in it
        from .copies import forget_absent
        forget_absent(obj)                # pasted into another document: not its copies
