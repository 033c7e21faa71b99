"""What a panel's OK records in the Python console and a recorded macro: each property
of the feature (and of its view) the edit changed, as a line of Python that sets it
("App.getDocument('D').getObject('ElasticaBlend').Tension = 0.001"), as FreeCAD's own
panels record theirs at OK (PartDesign Pad: "...getObject('Pad').Length = 7.000000"), so a
macro replays the command's make() line and then the panel's edits into the same feature.
The values are written exactly (repr of the doubles, lengths in mm); an edit that changes
nothing records nothing. No GUI: headless tests read the lines."""
from __future__ import annotations

import FreeCAD as App

# properties never recorded: results (read-only), the feature's own bookkeeping (hidden),
# FreeCAD's output and the proxy, the shape the recompute makes
_SKIPPED_TYPES = ("App::PropertyPythonObject", "Part::PropertyPartShape")
_SKIPPED_STATUS = ("ReadOnly", "Hidden", "Output", "Transient", "NoRecompute")


def _ref(obj, holder="App"):
    """Python naming ``obj`` (``holder`` "Gui": its view) in its document."""
    return f"{holder}.getDocument({obj.Document.Name!r}).getObject({obj.Name!r})"


def code_of(value):
    """Python that evaluates to ``value`` (a property's value) with App in scope, or None
    for a value it cannot write: numbers exactly (repr), a length (Quantity) in mm, vectors,
    placements, links to document objects, and lists / tuples / dicts of them."""
    if value is None or isinstance(value, (bool, int, str)):
        return repr(value)
    if isinstance(value, float):
        return repr(value) if value == value and abs(value) != float("inf") else None
    if isinstance(value, App.Units.Quantity):
        return code_of(float(value.Value))
    if isinstance(value, App.Vector):
        return f"App.Vector({value.x!r}, {value.y!r}, {value.z!r})"
    if isinstance(value, App.Rotation):
        return f"App.Rotation{tuple(float(q) for q in value.Q)!r}"
    if isinstance(value, App.Placement):
        return f"App.Placement({code_of(value.Base)}, {code_of(value.Rotation)})"
    if isinstance(value, App.DocumentObject):
        return _ref(value)
    if isinstance(value, (list, tuple)):
        items = [code_of(v) for v in value]
        if any(i is None for i in items):
            return None
        if isinstance(value, list):
            return "[" + ", ".join(items) + "]"
        return "(" + ", ".join(items) + ("," if len(items) == 1 else "") + ")"
    if isinstance(value, dict):
        items = [(code_of(k), code_of(v)) for k, v in value.items()]
        if any(k is None or v is None for k, v in items):
            return None
        return "{" + ", ".join(f"{k}: {v}" for k, v in items) + "}"
    return None


def _recorded(holder, prop):
    if holder.getTypeIdOfProperty(prop) in _SKIPPED_TYPES:
        return False
    status = [s for s in holder.getPropertyStatus(prop) if isinstance(s, str)]
    modes = holder.getEditorMode(prop)
    return not any(s in _SKIPPED_STATUS for s in status + list(modes))


def _state(holder, bound=()):
    out = {}
    for prop in holder.PropertiesList:
        if prop in bound or prop in ("Label", "Label2", "ExpressionEngine") or \
                not _recorded(holder, prop):
            continue
        try:
            out[prop] = code_of(getattr(holder, prop))
        except Exception:  # a property that cannot be read now: not recorded
            continue
    return out


def edit_state(obj):
    """What OK compares against: {(holder, property): its value as Python} of the feature
    ``obj`` ('App') and, in the GUI, its view ('Gui'), for the properties a designer sets:
    not read-only, hidden or output, nor bound to an expression (the expression sets it)."""
    bound = {p for p, _ in getattr(obj, "ExpressionEngine", [])}
    state = {("App", p): v for p, v in _state(obj, bound).items()}
    view = getattr(obj, "ViewObject", None) if App.GuiUp else None
    if view is not None:
        state.update({("Gui", p): v for p, v in _state(view).items()})
    return state


def edit_lines(obj, before):
    """The lines OK records for the edit of ``obj`` since ``before`` (edit_state): (the
    feature's, its view's), each 'App.getDocument(...).getObject(...).Prop = value' (the
    view's 'Gui.getDocument(...)'), in the order of its properties, those its proxy sets
    after the others (its SET_AFTER: the blend's Solution, which an edit of the problem
    resets) last."""
    now = edit_state(obj)
    after = tuple(getattr(getattr(obj, "Proxy", None), "SET_AFTER", ()))
    changed = [k for k in now if now[k] is not None and before.get(k) != now[k]]
    changed.sort(key=lambda k: (k[1] in after, after.index(k[1]) if k[1] in after else 0))
    lines = {"App": [], "Gui": []}
    for holder, prop in changed:
        lines[holder].append(f"{_ref(obj, holder)}.{prop} = {now[(holder, prop)]}")
    return lines["App"], lines["Gui"]
