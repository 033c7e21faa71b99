"""A feature's links to sketch edges and vertices, followed by their geometry as the sketch
changes (its edge and vertex names shift), and said when that geometry is deleted."""
from __future__ import annotations

import json
import math

import FreeCAD as App
import Part

from .geometry import global_element, is_sketch, link_edge
from .proxy import InputProblem


def _ends_and_middle(edge, plc=None):
    """The points of ``edge`` at its first, middle and last parameter (its curve's, whatever
    its orientation in a wire), placed by ``plc``."""
    a, b = edge.FirstParameter, edge.LastParameter
    pts = [edge.valueAt(u) for u in (a, 0.5 * (a + b), b)]
    return [plc.multVec(p) for p in pts] if plc is not None else pts


def _same_points(p, q):
    return all((a - b).Length <= 1e-7 * (1.0 + a.Length) for a, b in zip(p, q))


def read_geometry(sketch):
    """``sketch.Geometry``: the one place links and sources read it (each read copies every
    geometry of the sketch: read per vertex, picking 201 vertices of a polyline took 20 s)."""
    return sketch.Geometry


class SketchRead:
    """A sketch as read once, for the lookups of one gather or one link's slots: its Geometry,
    construction flags and Shape read once, and its drawn geometries' ends and its shape's
    vertices each hashed once (_Near), so that naming and following n picked vertices takes
    O(n), not O(n^2) reads of O(n) each (QA: 201 vertices of a polyline, 20 s). Anything
    else is the sketch's own (attributes passed through). Read it again after the sketch
    changes."""

    def __init__(self, sketch):
        self.sketch = sketch
        self.Geometry = read_geometry(sketch)
        self._construction = [sketch.getConstruction(i) for i in range(len(self.Geometry))]
        self.Shape = sketch.Shape
        self.Placement = sketch.Placement
        self._ends, self._vertices, self._listed, self._tags = {}, None, {}, None

    def __getattr__(self, name):
        return getattr(self.sketch, name)

    def getConstruction(self, i):
        return self._construction[i]

    def ends(self, placed):
        """_Near of the drawn geometries' (index, START / END) at their ends, ``placed`` by
        the sketch's Placement or not."""
        if placed not in self._ends:
            plc = self.Placement if placed else None
            items = []
            for i, g in enumerate(self.Geometry):
                if _drawn(self, i):
                    a, _, b = _ends_and_middle(g.toShape(), plc)
                    items += [((i, START), a), ((i, END), b)]
            self._ends[placed] = _Near(items)
        return self._ends[placed]

    def element(self, name):
        """The shape's sub-element ``name`` ('Edge3', 'Vertex2'), as Shape.getElement gives
        it, from the shape's Edges / Vertexes listed once (getElement maps every sub-shape
        at each call); IndexError where it has none."""
        kind, n = ("Edges", name[4:]) if name.startswith("Edge") else ("Vertexes", name[6:])
        if kind not in self._listed:
            self._listed[kind] = getattr(self.Shape, kind)
        k = int(n) - 1 if n.isdigit() else -1
        if not 0 <= k < len(self._listed[kind]):
            raise IndexError(name)
        return self._listed[kind][k]

    def index_of_tag(self, tag):
        """The index of the geometry whose Tag is ``tag``, or None."""
        if self._tags is None:
            self._tags = {}
            for i, g in enumerate(self.Geometry):
                self._tags.setdefault(g.Tag, i)
        return self._tags.get(tag)

    def vertices(self):
        """_Near of the shape's vertices (their index from 0)."""
        if self._vertices is None:
            self._vertices = _Near([(k, self.element(f"Vertex{k + 1}").Point)
                                    for k in range(len(self.Shape.Vertexes))])
        return self._vertices


def geometry_of(sketch):
    """The Geometry of a SketchRead (read already) or of a sketch (read now)."""
    return sketch.Geometry if isinstance(sketch, SketchRead) else read_geometry(sketch)


def reads():
    """A function sketch -> its SketchRead, each sketch read once (at its first call): for
    the slots of one link, or the picked elements of one gather."""
    done = {}

    def read(sketch):
        if isinstance(sketch, SketchRead):
            return sketch
        key = (sketch.Document.Name, sketch.Name)
        if key not in done:
            done[key] = SketchRead(sketch)
        return done[key]
    return read


def sketch_read(sketch):
    """``sketch`` as a SketchRead (read once; one already is kept)."""
    return sketch if isinstance(sketch, SketchRead) else SketchRead(sketch)


class _Near:
    """Points hashed on a grid for _same_points: first(p) is the smallest key among those
    (key, q) with _same_points([p], [q]), as a scan in key order finds it. The cell is
    2e-7 (1 + the largest |q|): a q within 1e-7 (1 + |p|) of p is within one cell (|p| <= |q|
    + that distance), so the 27 cells around p's hold every match."""

    def __init__(self, items):
        self.cell = 2e-7 * (1.0 + max((q.Length for _, q in items), default=0.0))
        self.cells = {}
        for key, q in items:
            self.cells.setdefault(self._at(q), []).append((key, q))

    def _at(self, q):
        return tuple(math.floor(c / self.cell) for c in (q.x, q.y, q.z))

    def first(self, p):
        x, y, z = self._at(p)
        found = [key for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                 for key, q in self.cells.get((x + dx, y + dy, z + dz), ())
                 if _same_points([p], [q])]
        return min(found, default=None)


def _drawn(sketch, i):
    """Whether the sketch's geometry i is an edge of its shape (not construction, no point)."""
    g = geometry_of(sketch)
    return not sketch.getConstruction(i) and g[i].TypeId != "Part::GeomPoint"


def sketch_geo_of_edge(sketch, edge_name):
    """The index of the sketch geometry whose shape is the sketch edge 'EdgeN', or None."""
    sketch = sketch_read(sketch)
    try:
        edge = sketch.element(edge_name)
    except (Part.OCCError, ValueError, IndexError):
        return None
    at = _ends_and_middle(edge)
    return next((i for i, g in enumerate(sketch.Geometry) if _drawn(sketch, i) and
                 _same_points(at, _ends_and_middle(g.toShape(), sketch.Placement))), None)


def sketch_edge_name(sketch, i):
    """The name ('EdgeN') of the sketch's edge that draws its geometry i, or None (construction
    geometry, a point): the shape holds the drawn geometry only, sorted into wires (Edge3
    may draw geometry 4)."""
    sketch = sketch_read(sketch)
    if not _drawn(sketch, i):
        return None
    at = _ends_and_middle(sketch.Geometry[i].toShape(), sketch.Placement)
    return next((f"Edge{k + 1}" for k, e in enumerate(sketch.Shape.Edges)
                 if _same_points(at, _ends_and_middle(e))), None)


# What of a sketch geometry a link's sub-element is: its edge, or the vertex at its start or
# end (Sketcher's PointPos 1, 2). A link's 'VertexN' is a vertex of the sketch's Shape, as the
# 3D view picks it: the drawn geometry's ends, coincident ones merged, no centres and no sketch
# points (0.20 leaves them out of the Shape). Sketcher's getGeoVertexIndex counts other
# vertices: every geometry's, construction and centres included (its edit mode's VertexN).
EDGE, START, END = 0, 1, 2


def _vertex(sketch, i, pos, plc=None):
    """The point at the START or END of the sketch's geometry i, placed by ``plc``."""
    g = geometry_of(sketch)
    return _ends_and_middle(g[i].toShape(), plc)[0 if pos == START else 2]


def sketch_geo_of_element(sketch, name):
    """(geometry index, EDGE / START / END) of the sketch element ``name``: the geometry of the
    edge 'EdgeN'; the first drawn geometry with an end at the vertex 'VertexN'. None when
    the sketch has no such element."""
    if name.startswith("Edge"):
        i = sketch_geo_of_edge(sketch, name)
        return None if i is None else (i, EDGE)
    sketch = sketch_read(sketch)
    try:
        at = [sketch.element(name).Point]
    except (Part.OCCError, ValueError, IndexError):
        return None
    return _geo_at(sketch, at[0], sketch.Placement)


def _geo_at(sketch, point, plc=None):
    """(geometry index, START / END) of the first drawn geometry with an end at ``point``
    (placed by ``plc``: None or the sketch's Placement), or None."""
    return sketch_read(sketch).ends(plc is not None).first(point)


def sketch_element_name(sketch, i, pos):
    """The name ('EdgeN', 'VertexN') of the sketch's element that is (geometry i, pos) now, or
    None (construction geometry)."""
    if pos == EDGE:
        return sketch_edge_name(sketch, i)
    sketch = sketch_read(sketch)
    if not _drawn(sketch, i):
        return None
    k = sketch.vertices().first(_vertex(sketch, i, pos, sketch.Placement))
    return None if k is None else f"Vertex{k + 1}"


def _element(sketch, i, pos):
    """The global edge or vertex (geometry i, pos) of ``sketch``."""
    if pos == EDGE:
        return link_edge(sketch, "", i)
    return Part.Vertex(sketch.getGlobalPlacement().multVec(_vertex(sketch, i, pos)))


# A feature's link to sketch edges and vertices follows their geometry, not their names: the
# names shift when earlier geometry turns construction or is deleted (QA: a fit's G1 start,
# linked to Edge2, joined the run-out line once a helper line before it was made
# construction; a fit of Edge3 and Edge4 fitted two other edges; status converged). Each
# sub-element the link names (a slot: _slots) is known by its geometry's Tag and its position
# while the document is open (_tags) and by its geometry index, saved in the
# property the proxy's ``followed_links`` names (an integer for a one-edge link, a string list
# 'index' / 'index:start' / 'index:end' for a list or a PropertyLinkSub naming several
# elements, as a comb's Source): FreeCAD 0.20 gives sketch geometry new
# Tags when a document is opened, and saves no id of its own. The index is FREE until the slot
# is first resolved (a new link, a document of a version before), DELETED once its geometry is
# deleted, or a one-edge link's object (the feature says so until it is relinked).
FREE, DELETED = -1, -2
_POS_NAMES = {START: "start", END: "end"}
# The Tags are kept in a transient property (proxy.add_geometry_index), not in the proxy: Undo
# restores them with the link and its indices (QA: undoing a relink left the fit on the edge
# relinked to, the proxy's Tags said so).
TAGS = "FollowedTags"


def _tags(feature, prop, n=None):
    """The session record of each of the link ``prop``'s n slots (all it has: None): (Tag, pos)
    of its geometry, and a vertex's point in the sketch (x, y, z); or None (not followed)."""
    text = getattr(feature, TAGS).get(prop)
    tags = [tuple(t) if t else None for t in json.loads(text)] if text else []
    return tags if n is None or len(tags) == n else [None] * n


def _set_tags(feature, prop, tags):
    value = dict(getattr(feature, TAGS))
    value[prop] = json.dumps(tags) if any(tags) else ""
    if value != getattr(feature, TAGS):
        setattr(feature, TAGS, value)


def _slots(link):
    """The sub-elements a link's value names, in order: [(obj, name)]; whole objects left
    out. ``link``: a PropertyLinkSub's (obj, [name, ...]) or None, a PropertyLinkSubList's
    [(obj, (name, ...)), ...]."""
    if isinstance(link, list):
        return [(obj, s) for obj, subs in link for s in subs if s]
    return [(link[0], s) for s in link[1] if s] if link else []


def _followable(obj, name):
    return is_sketch(obj) and name.startswith(("Edge", "Vertex"))


def _saved(feature, prop, n):
    """The saved (index, pos) of each of the link ``prop``'s n slots (FREE where none)."""
    value = getattr(feature, feature.Proxy.followed_links[prop])
    if isinstance(value, int):
        saved = [(value, EDGE)]
    else:
        pos = {name: p for p, name in _POS_NAMES.items()}
        saved = [(int(i), pos.get(name, EDGE)) for i, _, name in (v.partition(":") for v in value)]
    return (saved + [(FREE, EDGE)] * n)[:n]


def _save(feature, prop, saved):
    """Write the slots' (index, pos) ``saved`` into the link ``prop``'s index property."""
    index_prop = feature.Proxy.followed_links[prop]
    if feature.getTypeIdOfProperty(index_prop) == "App::PropertyInteger":
        value = saved[0][0] if saved else FREE
    else:
        value = [f"{i}:{_POS_NAMES[pos]}" if i >= 0 and pos in _POS_NAMES else str(i)
                 for i, pos in saved]
    if getattr(feature, index_prop) != value:
        setattr(feature, index_prop, value)


def _locate(sketch, name, tag, saved):
    """(geometry index, pos) of the ``sketch`` element a slot follows: the geometry of its
    (Tag, pos) ``tag``, else its ``saved`` (index, pos), else (FREE) the element its name
    ``name`` is now; None when none. A vertex whose geometry is gone or construction is
    the drawn geometry ending at its point, if any."""
    if tag is not None:
        i = sketch_read(sketch).index_of_tag(tag[0])
        if tag[1] != EDGE and (i is None or not _drawn(sketch, i)):
            # a vertex other geometry ends at too (a polyline's joint) outlives its geometry
            return _geo_at(sketch, App.Vector(*tag[2:])) or (None if i is None else (i, tag[1]))
        return None if i is None else (i, tag[1])
    index, pos = saved
    if 0 <= index < len(geometry_of(sketch)):
        return index, pos
    return sketch_geo_of_element(sketch, name) if index == FREE else None


def _tag(sketch, at):
    """The session record (_tags) of (geometry index, pos) ``at``: (Tag, pos, x, y, z) of a
    vertex; (Tag, EDGE, TypeId, the next geometry's Tag or None, the geometry count) of an
    edge, so that geometry replaced at its index is told from geometry deleted (_replaced)."""
    if at is None:
        return None
    geometry = geometry_of(sketch)
    if at[1] == EDGE:
        after = geometry[at[0] + 1].Tag if at[0] + 1 < len(geometry) else None
        return (geometry[at[0]].Tag, EDGE, geometry[at[0]].TypeId, after, len(geometry))
    return (geometry[at[0]].Tag, at[1], *tuple(_vertex(sketch, *at)))


# what the Sketcher's geometry types are called in messages
_KINDS = {"Part::GeomLineSegment": "a line segment", "Part::GeomArcOfCircle": "an arc",
          "Part::GeomCircle": "a circle", "Part::GeomBSplineCurve": "a B-spline",
          "Part::GeomEllipse": "an ellipse", "Part::GeomArcOfEllipse": "an arc of ellipse",
          "Part::GeomArcOfHyperbola": "an arc of hyperbola",
          "Part::GeomArcOfParabola": "an arc of parabola", "Part::GeomPoint": "a point"}


def _kind(type_id):
    return _KINDS.get(type_id, type_id.replace("Part::Geom", "a "))


def _replaced(sketch, tag, saved):
    """The words for the geometry that took the place of the edge ``tag`` (its _tag record)
    followed ('an arc) was deleted; a line segment is in its place'), at its index
    ``saved``, when it was replaced there ('sketch.Geometry[i] = a line', or deleted and
    another drawn at the end: the same list): the sketch has as many geometries as then and
    the one after it is the one that was after it; else None (deleted: the ones after it
    moved down)."""
    if len(tag) < 5 or saved[0] < 0:
        return None
    i, geometry = saved[0], geometry_of(sketch)
    if len(geometry) != tag[4] or i >= len(geometry) or geometry[i].Tag == tag[0]:
        return None
    after = geometry[i + 1].Tag if i + 1 < len(geometry) else None
    if after != tag[3]:
        return None
    new = geometry[i].TypeId
    return (f"{_kind(tag[2])}) was deleted; "
            + (_kind(new) if new != tag[2] else "another " + _kind(new).split(" ", 1)[1])
            + " is in its place")


def remember_followed(feature):
    """Record the Tags of the sketch geometry an opened document's feature's links follow
    (their saved indices say which): a sketch edited before the first recompute is followed
    too."""
    for prop in feature.Proxy.followed_links:
        slots, read = _slots(getattr(feature, prop)), reads()
        tags = [_tag(read(obj), _locate(read(obj), name, None, saved))
                if _followable(obj, name) else None
                for (obj, name), saved in zip(slots, _saved(feature, prop, len(slots)))]
        _set_tags(feature, prop, tags)


def followed_elements(feature, prop):
    """The global sub-elements an Elastica feature's link ``prop`` names, in order (_slots).
    A sketch's edge or vertex is its geometry followed (see FREE, DELETED), the link renamed to
    the element that geometry is now; InputProblem naming ``prop`` when that geometry was
    deleted or made construction geometry (no edge of the sketch's shape, as for FreeCAD's
    own features)."""
    slots = _slots(getattr(feature, prop))
    tags = _tags(feature, prop, len(slots))
    saved = _saved(feature, prop, len(slots))
    shapes, names, problem = [], [], None
    read = reads()          # each sketch read once for all the slots (SketchRead)
    for k, (obj, name) in enumerate(slots):
        names.append(name)
        if not _followable(obj, name):
            shapes.append(global_element(obj, name))
            continue
        obj = read(obj)
        at = _locate(obj, name, tags[k], saved[k])
        if at is None:
            if saved[k][0] == DELETED or tags[k] is not None:
                # QA24gui F4: an arc replaced by a line at its index was said 'deleted'
                how = _replaced(obj, tags[k], saved[k]) if tags[k] is not None else None
                saved[k] = (DELETED, saved[k][1])
                problem = problem or (f"{prop}: the sketch geometry it followed ({obj.Label}."
                                      f"{name}" + (f", {how}" if how else ") was deleted") +
                                      f": relink {prop}")
            problem = problem or f"{prop}: {obj.Label} has no {name}"
            continue
        tags[k], saved[k] = _tag(obj, at), at
        if not _drawn(obj, at[0]):
            problem = problem or (f"{prop}: the sketch geometry it followed ({obj.Label}.{name})"
                                  f" is construction geometry now: make it normal geometry or "
                                  f"relink {prop}")
            continue
        shapes.append(_element(obj, *at))
        names[k] = sketch_element_name(obj, *at) or name
    _set_tags(feature, prop, tags)
    _save(feature, prop, saved)
    if problem:
        raise InputProblem(problem)
    if names != [name for _, name in slots]:
        _rename(feature, prop, names)
    return shapes


def _rename(feature, prop, names):
    """Give the link ``prop``'s slots the names ``names`` (what their geometry is now)."""
    link, it = getattr(feature, prop), iter(names)
    if isinstance(link, list):
        value = [(obj, tuple(next(it) if s else s for s in subs)) for obj, subs in link]
    else:
        value = (link[0], [next(it) if s else s for s in link[1]])
    feature.Proxy._renaming = True          # the same geometry: no new link (link_changed)
    try:
        setattr(feature, prop, value)
    finally:
        feature.Proxy._renaming = False


def followed_edge(feature, prop):
    """The global edge an Elastica feature's one-edge link ``prop`` (obj, ['EdgeN']) names
    (followed_elements), or None when the link is empty; InputProblem naming ``prop`` when
    what it followed was deleted, its geometry or its object."""
    if not _slots(getattr(feature, prop)):
        if getattr(feature, feature.Proxy.followed_links[prop]) == DELETED:
            raise InputProblem(f"{prop}: the object of its edge was deleted: relink {prop}")
        return None
    return followed_elements(feature, prop)[0]


def element_as_followed(obj, name, read=None):
    """The global sub-element ``name`` of ``obj`` as a feature linking it reads it
    (followed_elements): a sketch's edge or vertex from its geometry (_element), else
    global_element. A command's check reads its input so, bit for bit as the feature it makes
    (Part.getShape's edge of a placed sketch lies 1 ulp off its geometry transformed): the
    check's outcome is the feature's (FeatureProxy.handed, fit_core.fit_gathered).
    ``read``: reads()'s, each sketch read once over many calls (as_followed)."""
    sketch = (read or sketch_read)(obj) if _followable(obj, name) else None
    at = sketch_geo_of_element(sketch, name) if sketch is not None else None
    if at is None or not _drawn(sketch, at[0]):
        return global_element(obj, name)
    return _element(sketch, *at)


def as_followed():
    """element_as_followed for one gather: each sketch read once (SketchRead), however many
    of its elements are read (picking n vertices read its geometry n times, n^2 work)."""
    read = reads()
    return lambda obj, name: element_as_followed(obj, name, read)


def followed_reader(feature, prop):
    """For sources.gather_*: a function (obj, name) -> the global sub-element ``name`` of
    ``obj`` that the link ``prop`` follows (followed_elements, in the link's order); what the
    link does not name (a whole object's edges), global_element."""
    shapes = followed_elements(feature, prop)
    queues = {}
    for (obj, name), shape in zip(_slots(getattr(feature, prop)), shapes):
        queues.setdefault((obj.Name, name), []).append(shape)

    def element(obj, name):
        queue = queues.get((obj.Name, name))
        return queue.pop(0) if queue else global_element(obj, name)
    return element


def relinked(feature, prop, deleted=False):
    """After the link ``prop`` of ``feature`` changed: whether it now names other geometry
    than it followed (another element picked, one added, the link emptied); a slot naming
    geometry it followed keeps it, the others are forgotten (their names say which at the
    next recompute). ``deleted``: a one-edge link emptied because its object is being deleted
    (followed_edge then says so)."""
    link = getattr(feature, prop)
    slots = _slots(link)
    old = [t[:2] for t in _tags(feature, prop) if t]
    tags, saved = [], []
    read = reads()
    for obj, name in slots:
        obj = read(obj) if _followable(obj, name) else obj
        at = sketch_geo_of_element(obj, name) if _followable(obj, name) else None
        kept = at is not None and _tag(obj, at)[:2] in old
        tags.append(_tag(obj, at) if kept else None)
        saved.append(at if kept else (FREE, EDGE))
    _set_tags(feature, prop, tags)
    _save(feature, prop, [(DELETED, EDGE)] if deleted and link is None else saved)
    return len(slots) != len(old) or not all(tags)


def save_followed(doc):
    """Write what the links of ``doc``'s features follow in this session into their index
    properties, as ``doc`` is saved: a sketch edited after a feature's last recompute (QA:
    the helper line deleted, the document saved and opened: the fit fitted two other edges)."""
    for obj in doc.Objects:
        links = getattr(getattr(obj, "Proxy", None), "followed_links", {})
        for prop, index_prop in links.items():
            if not {prop, index_prop, TAGS} <= set(obj.PropertiesList):
                continue                    # a document of a version before, not restored yet
            slots = _slots(getattr(obj, prop))
            tags = _tags(obj, prop, len(slots))
            saved = _saved(obj, prop, len(slots))
            _save(obj, prop, [(_locate(sketch, name, tag, s) or (DELETED, s[1])) if tag else s
                              for (sketch, name), tag, s in zip(slots, tags, saved)])


class _SaveObserver:
    """save_followed as a document's save starts: a proxy's own dumps() comes too late (the
    properties are written in name order, the index properties before Proxy)."""

    def slotStartSaveDocument(self, doc, filename):
        save_followed(doc)


App.addDocumentObserver(_SaveObserver())      # once: Python imports a module once
