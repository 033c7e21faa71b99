"""The containers a feature reads its sources through, linked so that moving them
recomputes it.

A feature reads a sketch, a Points object or an edge where the 3D view draws it
(geometry.global_shape: the placement of the PartDesign Bodies and App::Parts holding it
applied), but its links name only the object: a Body moved or turned left the feature
where it was, Up-to-date, through Ctrl+R, a forced recompute and a reopen (QA19gui F1:
70 to 151 mm off). FreeCAD recomputes an object when one it links to is recomputed
(Document::recompute marks the InList of each object it recomputed), and a container
moved is recomputed; so each feature keeps the hidden link list CONTAINERS to the
containers (nested ones too) of what it reads, as FreeCAD's own dependencies are links.
The link is of global scope (proxy.add_link: the features are at document level, the
containers anywhere); a hidden-scope link (App::PropertyLinkListHidden) is no dependency
in 0.20 (not in the OutList), so it would not do. A container that depends on the
feature (one holding it) is left out: linking it would close a cycle. Objects moved into
or out of a container (its Group changed: the tree's drag and drop, addObject) change
both at once, before any recompute (GroupWatch).
"""
from __future__ import annotations

import FreeCAD as App

CONTAINERS = "Containers"


def add_containers(obj):
    """The hidden link list CONTAINERS (output: setting it, in execute, touches nothing).
    Whether it was added (a new feature, or a document saved before it)."""
    if CONTAINERS in obj.PropertiesList:
        return False
    obj.addProperty("App::PropertyLinkListGlobal", CONTAINERS, "Input",
                    "The Bodies / Parts holding what the feature reads: moving one recomputes "
                    "it (set at each recompute)", 4 | 8)
    return True


def _objects(value):
    """The document objects of a link property's value: an object, (object, subs), or a
    list of either."""
    if isinstance(value, App.DocumentObject):
        return [value]
    if isinstance(value, tuple) and value and isinstance(value[0], App.DocumentObject):
        return [value[0]]
    if isinstance(value, list):
        return [o for v in value for o in _objects(v)]
    return []


def link_properties(obj):
    """The names of ``obj``'s link properties but CONTAINERS."""
    return [p for p in obj.PropertiesList
            if obj.getTypeIdOfProperty(p).startswith("App::PropertyLink") and p != CONTAINERS]


def read_objects(obj):
    """The objects ``obj`` reads: those of the link properties its proxy's read_links
    names (FeatureProxy.read_links), or of every one (link_properties) when its proxy did
    not load (None: its module missing)."""
    proxy = getattr(obj, "Proxy", None)
    names = link_properties(obj) if proxy is None else proxy.read_links(obj)
    return [o for p in names for o in _objects(getattr(obj, p, None))]


def containers_of(obj):
    """The containers placing what ``obj`` reads, innermost first, each once; those
    depending on ``obj`` (holding it: a cycle) left out."""
    out = []
    for o in read_objects(obj):
        parent = o.getParentGeoFeatureGroup()
        while parent is not None:
            if parent not in out:
                out.append(parent)
            parent = parent.getParentGeoFeatureGroup()
    if out:
        depending = set(obj.InListRecursive) | {obj}
        out = [c for c in out if c not in depending]
    return out


def follow_containers(obj):
    """Link CONTAINERS to the containers of what ``obj`` reads (containers_of), when it
    does not already. Whether it changed."""
    if CONTAINERS not in obj.PropertiesList:
        return False
    now = containers_of(obj)
    if list(getattr(obj, CONTAINERS)) == now:
        return False
    setattr(obj, CONTAINERS, now)
    return True


def restore_containers(obj):
    """On reopening: a document saved before CONTAINERS gets it linked. Whether the
    feature reads through a container then: it may have been saved after its container
    moved, in the wrong place, and must be recomputed (FeatureProxy.mustExecute: a touch
    here would not last, the document purges it once restored)."""
    added = add_containers(obj)
    return follow_containers(obj) and added


# ---------------------------------------------------------------- where a feature is drawn

# A feature's results are global (it reads its sources where they are drawn), but FreeCAD
# draws a Part::Feature's Shape, and its view provider's nodes, under the placements of
# the App::Parts / Bodies holding it (its Shape is local to them, as a Part::Box's in a
# Part): a feature moved into a placed Part was drawn off by the Part's placement (QA). Its
# Shape is written in its holder's coordinates (set_shape), its overlays drawn so
# (to_holder), and a holder moved since makes it execute again (moved_holder): what it
# reads may lie outside the holder, which it cannot link (the holder depends on it).

def holder_placement(obj):
    """The global placement of the container holding ``obj`` (its innermost App::Part or
    Body, getGlobalPlacement: nested ones composed), under which FreeCAD draws it; the
    identity at document level."""
    parent = obj.getParentGeoFeatureGroup() if hasattr(obj, "getParentGeoFeatureGroup") \
        else None
    return App.Placement() if parent is None else parent.getGlobalPlacement()


def _key(plc):
    return tuple(plc.Base) + tuple(plc.Rotation.Q)


def set_shape(obj, shape):
    """Set ``obj.Shape`` to ``shape``, given in global coordinates, in the coordinates of
    its holder (holder_placement): drawn where it is; remembered for moved_holder. At
    document level the shape as given (bit for bit)."""
    plc = holder_placement(obj)
    if not plc.isIdentity():
        shape = shape.copy()
        shape.transformShape(plc.inverse().toMatrix(), True)     # copied: the geometry moved
    obj.Shape = shape
    proxy = getattr(obj, "Proxy", None)
    if proxy is not None:
        proxy._held = _key(plc)


def keep_in_place(obj):
    """After a failed recompute, which keeps the last Shape: where its holder moved since the
    Shape was set, write it again under the holder of now (set_shape), so the old curve stays
    where it was drawn, on its sources, and moved_holder no longer asks to execute (review
    revfc 4: a failed spline drawn 123 mm off once its Part moved, mustExecute True)."""
    held = getattr(getattr(obj, "Proxy", None), "_held", None)
    if held is None or held == _key(holder_placement(obj)):
        return
    if obj.Shape.isNull():
        remember_holder(obj)
        return
    was = App.Placement(App.Vector(*held[:3]), App.Rotation(*held[3:]))
    shape = obj.Shape.copy()
    shape.transformShape(was.toMatrix(), True)          # global again, as set_shape takes it
    set_shape(obj, shape)


def remember_holder(obj):
    """Take ``obj``'s Shape as set where its holder is now (a document reopened)."""
    proxy = getattr(obj, "Proxy", None)
    if proxy is not None:
        proxy._held = _key(holder_placement(obj))


def to_holder(obj, points):
    """Global points in the coordinates ``obj``'s view is drawn in (its holder's)."""
    plc = holder_placement(obj)
    if plc.isIdentity():
        return list(points)
    inv = plc.inverse()
    return [inv.multVec(p) for p in points]


def moved_holder(obj):
    """Whether ``obj``'s holder is placed otherwise than when its Shape was set (set_shape;
    unknown, as after a reopen: no)."""
    held = getattr(getattr(obj, "Proxy", None), "_held", None)
    return held is not None and held != _key(holder_placement(obj))


class GroupWatch:
    """A document observer: when a container's Group changes, the features it concerns
    link the containers of now (follow_containers) and, if they changed, are touched (what
    they read is placed otherwise: a sketch moved into a Body), before any recompute: a
    feature moved into a container it linked would close a cycle, and FreeCAD would
    recompute nothing ('The graph must be a DAG'). The features concerned are an object
    moved in or out, those it depends on (its contents too) and those linking one of
    these (reading it): only their containers or the containers depending on them change;
    not every feature at every Body.newObject. Not while a document is restored or undone
    (the links are restored with it)."""

    def __init__(self):
        self.before = {}        # {container: its Group before the change under way}

    def slotBeforeChangeObject(self, obj, prop):
        if _group_changing(obj, prop):
            self.before[obj] = list(obj.Group)

    def slotChangedObject(self, obj, prop):
        if not _group_changing(obj, prop):
            return
        moved = set(self.before.pop(obj, ())) ^ set(obj.Group)
        if not moved:
            return
        # and what they depend on: getDependentObjects without DepSort takes the cycle a
        # feature moved into a container it links has just closed (OutListRecursive raises)
        reach = set(App.getDependentObjects(list(moved)))
        concerned = reach.union(*(o.InList for o in reach))     # and what links them
        for f in obj.Document.Objects:
            # (a feature moved in or out is drawn under other placements: moved_holder)
            if f in concerned and (follow_containers(f) or (f in moved and moved_holder(f))):
                f.touch()


def _group_changing(obj, prop):
    """Whether ``prop`` is the Group of a container (App::GeoFeatureGroupExtension: a Body,
    a Part), neither restored nor undone."""
    if prop != "Group" or not obj.hasExtension("App::GeoFeatureGroupExtension"):
        return False
    doc = obj.Document
    return not (doc.Restoring or doc.Transacting or "Restore" in obj.State)


App.addDocumentObserver(GroupWatch())        # once: Python imports a module once
