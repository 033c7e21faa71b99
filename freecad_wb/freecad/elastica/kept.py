"""A feature's last outcome, kept on its proxy while what it depends on holds, so that a
recompute that changed none of it calls no library.

A feature links the containers (Bodies, App::Parts) placing what it reads
(containers.py), so FreeCAD executes it whenever anything in such a container is
recomputed: a Pad's length changed refitted a 50 000-point scan (5-7 s, the GUI frozen).
Its outcome depends on its own input properties and on the geometry it reads where the 3D
view draws it; ``input_key`` digests both, and FeatureProxy.execute reuses the last outcome
(the shape and results already on the feature, or the error) while the key is the one left
by the last recompute. A placement of a container changed, a sketch edited, a property
typed: another key, computed again.

The key is taken after the recompute (its ``compute`` may rename a link following its
sketch's geometry, a spline's Closed follow its wire, a blend's Solution follow its shape:
their next recompute starts from there). The outcome lives on the proxy only (no module
state): it is no part of the file (a reopened document computes), nor of a copy, and is
dropped when anything but the feature's own recompute sets its results (Undo, Redo restore
them with an older outcome): FeatureProxy.onChanged.
"""
from __future__ import annotations

import hashlib
import inspect
import io
import os
import zipfile

import FreeCAD as App

from .containers import CONTAINERS, holder_placement, read_objects

# properties of the feature that are no input: FreeCAD's own (its label, its visibility, its
# shape and the shape's placement), the proxy, the links to the containers (their placements
# are in the read objects' own: _object_key); and the group "Result" (outputs, said texts)
NOT_INPUT = frozenset(("Label", "Label2", "Visibility", "Placement", "Shape", "Proxy",
                       CONTAINERS))
RESULT_GROUP = "Result"
# what an object read holds its geometry in (a sketch's Geometry: construction edges and
# vertices too; a Points object's Points; a Part feature's Shape; an Elastica feature's curves)
_CONTENT = ("Geometry", "Points", "Shape", "Curves", "Plane")


def is_input(obj, prop):
    """Whether property ``prop`` of the feature ``obj`` is one its outcome depends on."""
    return prop not in NOT_INPUT and obj.getGroupOfProperty(prop) != RESULT_GROUP


def _stable(value):
    """``value`` as a comparable, exactly written Python value (repr of floats: every bit)."""
    if isinstance(value, App.DocumentObject):
        return ("object", value.Document.Name, value.Name)
    if isinstance(value, (list, tuple)):
        return tuple(_stable(v) for v in value)
    if isinstance(value, App.Units.Quantity):
        return ("quantity", repr(float(value.Value)), str(value.Unit))
    if isinstance(value, App.Placement):
        return ("placement", tuple(repr(v) for v in value.toMatrix().A))
    if isinstance(value, App.Vector):
        return ("vector", repr(value.x), repr(value.y), repr(value.z))
    if isinstance(value, float):
        return repr(value)
    if value is None or isinstance(value, (bool, int, str)):
        return value
    return repr(value)


def _content(obj, prop):
    """Property ``prop`` of ``obj`` as FreeCAD saves it (its XML and its binary file: a
    shape's BRep, a point cloud's floats), without the zip's dates (dumpPropertyContent
    wraps them in a zip stamped with the time of the call)."""
    with zipfile.ZipFile(io.BytesIO(bytes(obj.dumpPropertyContent(prop)))) as z:
        return b"".join(i.filename.encode() + b"\0" + z.read(i.filename) for i in z.infolist())


def _object_key(obj, h):
    """Feed ``h`` with where ``obj`` is drawn: its global placement (its containers' and its
    own) and its geometry (_CONTENT); an object without any of it (an App::Link) by its
    shape in global coordinates."""
    from .geometry import container_placement, global_shape     # (geometry imports proxy)
    plc = obj.getGlobalPlacement() if hasattr(obj, "getGlobalPlacement") else \
        container_placement(obj)
    h.update(repr((obj.Document.Name, obj.Name, _stable(plc))).encode())
    props = [p for p in _CONTENT if p in obj.PropertiesList]
    for p in props:
        h.update(p.encode() + b"\0" + _content(obj, p))
    if not props:
        h.update(global_shape(obj).exportBrepToString().encode())


def input_key(obj):
    """A digest of what the outcome of ``obj``'s recompute depends on: its input properties
    (is_input; its expressions, and the date and size of a file it names), the placement of
    the container holding it (containers.holder_placement) and the geometry of the objects it
    reads (containers.read_objects) in global coordinates. None where it
    cannot be taken (a link to an object being deleted: FreeCAD raises ReferenceError): the
    feature computes. Any other exception is a bug and propagates (it was taken for no key:
    the feature computed at every recompute, unnoticed)."""
    h = hashlib.sha256()
    try:
        for p in sorted(obj.PropertiesList):
            if not is_input(obj, p):
                continue
            value = getattr(obj, p)
            h.update(repr((p, _stable(value))).encode())
            if obj.getTypeIdOfProperty(p) == "App::PropertyFile" and value:
                try:
                    st = os.stat(value)
                    h.update(repr((st.st_mtime_ns, st.st_size)).encode())
                except OSError:
                    h.update(b"no file")
        # the unit of each bound expression's value: a float input drops it (a cell '=2 mm'
        # and then a plain '2' give D = 2 both), and bound.check_bound_units refuses one
        for p, expr in sorted(dict(getattr(obj, "ExpressionEngine", [])).items()):
            try:
                unit = str(getattr(obj.evalExpression(expr), "Unit", ""))
            except Exception:           # FreeCAD's own error on the expression: said by it
                unit = "not evaluated"
            h.update(repr(("bound", p, expr, unit)).encode())
        # where its Shape is drawn: written in its container's coordinates (set_shape), it is
        # written again once that container moved
        h.update(repr(("holder", _stable(holder_placement(obj)))).encode())
        for o in read_objects(obj):
            _object_key(o, h)
    except ReferenceError:      # an object read was deleted: no key, the feature computes
        return None             # (anything else is a bug: raised, the recompute fails)
    return h.hexdigest()


def _edge_key(e):
    """A Part edge by its geometry where it lies: its curve's type and description (Content,
    in global coordinates: 6 digits), its range, orientation and its points at 9 parameters
    of it, every bit. Not its BRep: one edge read twice (a command's global_element, a
    feature's followed_edge) writes other nested locations."""
    first, last = e.FirstParameter, e.LastParameter
    at = [first + (last - first) * i / 8 for i in range(9)]
    return (e.Curve.TypeId, e.Curve.Content, e.Orientation, repr(first), repr(last),
            tuple(_stable(e.valueAt(u)) for u in at))


def _comparable(value):
    """``value`` as _stable, a Part shape by its edges' geometry (_edge_key) and its vertices'
    points (exact floats: a lone Vertex, a compound's loose ones), a numpy array by its exact
    values. A shape with faces (its surfaces are no part of such a key) or a value of another
    type (a Part.Geometry, a dict: _stable's repr() would make all of one type equal) raises
    TypeError: no key, the call is made (checked_call, handed)."""
    if hasattr(value, "Edges") and hasattr(value, "ShapeType"):
        if getattr(value, "Faces", None):
            raise TypeError(f"no call key for a shape with faces ({value.ShapeType})")
        return ("shape", value.ShapeType, tuple(_edge_key(e) for e in value.Edges),
                tuple(_stable(v.Point) for v in value.Vertexes))
    if hasattr(value, "tolist") and hasattr(value, "dtype"):
        return ("array", repr(value.tolist()))
    if isinstance(value, (list, tuple)):
        return tuple(_comparable(v) for v in value)
    if value is None or isinstance(value, (bool, int, float, str, App.Vector, App.Placement,
                                           App.Units.Quantity, App.DocumentObject)):
        return _stable(value)
    raise TypeError(f"no call key for a {type(value).__name__}")


def call_key(core, *args, **kwargs):
    """The call ``core(*args, **kwargs)`` as a comparable value: its arguments bound to its
    signature, defaults filled (a default given or left out is one call)."""
    bound = inspect.signature(core).bind(*args, **kwargs)
    bound.apply_defaults()
    return (core.__module__, core.__qualname__,
            tuple((k, _comparable(v)) for k, v in bound.arguments.items()))


class Raised:
    """A check's outcome that is an exception of checked_call's ``raises``: the feature's
    first recompute (FeatureProxy.handed) raises it again instead of computing it."""

    def __init__(self, exc):
        self.exc = exc


def checked_call(core, *args, raises=(), **kwargs):
    """A command's check: ``(call_key, core(*args, **kwargs))``, handed to the feature it
    creates (FeatureProxy.handed) so that its first recompute, making the same call, takes
    the outcome instead of computing it again. An exception of ``raises`` is the outcome
    too (Raised): the feature is made and fails with it (the G2 quadratic's EdgesProblem,
    whose count search took 2-4 s, not run twice)."""
    try:
        key = call_key(core, *args, **kwargs)
    except TypeError:           # an argument _comparable cannot key: no hand, the feature computes
        key = None
    try:
        return key, core(*args, **kwargs)
    except raises as exc:
        return key, Raised(exc)


__all__ = ["input_key", "is_input", "NOT_INPUT", "call_key", "checked_call", "Raised"]
