"""Whether a feature's copies in sketches (geometry.write_to_sketch, the panels' Copy into)
are still its curve. A copy does not follow the feature, and the Sketcher's solver bends it
where it is joined to moved geometry (QA22gui F1: 26.2 mm off the re-solved blend after
the line it is Tangent to moved; F4: a hook of curvature 2.1/mm where the elastica has
0.025/mm, from a Tangent and Coincident added in the Sketcher): the feature measures each
copy on its recompute and says it, without touching the sketch."""
import FreeCAD as App
import Part

from .geometry import COPIES, MARK, copy_moved, earlier_copy, written_points

SAMPLES = 33            # per copy and per feature edge: a few dozen distToShape calls
REFINE = 1e-3           # mm: the largest distance's bracket refined to this (below 3 digits)
GOLDEN = 0.6180339887498949     # (sqrt(5) - 1) / 2
OFF = 1e-4              # mm: a copy written is the feature's B-spline (~1e-12 mm off)
KAPPA_OFF = 1e-3        # relative to the larger end curvature (+ 1e-6/mm)
NOTE = ". The copy in "  # where a Status's copy note starts (drift_status strips it)


def _global(shape, placement):
    s = shape.copy()
    s.transformShape(placement.toMatrix())
    return s


def _copy_edges(feature):
    """{sketch: [copy edges in global coordinates]} of the feature's copies still whole
    (geometry.earlier_copy: by their Tags, or their mark after a reopen)."""
    out = {}
    names = [e.split(" ", 1)[0] for e in getattr(feature, COPIES, ())] \
        if COPIES in feature.PropertiesList else []
    for name in dict.fromkeys(names):
        sk = feature.Document.getObject(name)
        if sk is None or not hasattr(sk, "Geometry"):
            continue
        ids = earlier_copy(feature, sk)
        if not ids:
            continue        # deleted since: nothing to measure
        geometry, gp = sk.Geometry, sk.getGlobalPlacement()
        out[sk] = [_global(Part.Edge(geometry[i]), gp) for i in ids]
    return out


def _farthest(edge, other):
    """The largest distance (mm) from ``edge``'s points to the shape ``other``: SAMPLES
    points equally spaced along the edge, then the largest of them refined by golden-section
    search on the edge's parameter between the samples either side of it, until their points
    are REFINE apart. The samples alone said 39.3 mm of a copy 40.3 mm off (its farthest
    point between two samples: the figure wrong in its second digit). The distance is
    1-Lipschitz along the edge, so a bracket REFINE long leaves at most REFINE / 2 mm (at a
    smooth maximum, far less). Hand-written: scipy (its minimize_scalar) is not in FreeCAD's
    Python, and Part has no curve-to-shape largest distance."""
    def dist(p):
        return other.distToShape(Part.Vertex(p))[0]

    pts = edge.discretize(SAMPLES)
    d = [dist(p) for p in pts]
    j = max(range(len(d)), key=d.__getitem__)
    curve = edge.Curve
    a = curve.parameter(pts[j - 1]) if j > 0 else edge.FirstParameter
    b = curve.parameter(pts[j + 1]) if j + 1 < len(pts) else edge.LastParameter
    if not a < b:       # (a seam between them: the samples' figure stands)
        return d[j]
    c, e = b - GOLDEN * (b - a), a + GOLDEN * (b - a)
    dc, de = dist(edge.valueAt(c)), dist(edge.valueAt(e))
    while (edge.valueAt(b) - edge.valueAt(a)).Length > REFINE:
        if dc >= de:
            b, e, de = e, c, dc
            c = b - GOLDEN * (b - a)
            dc = dist(edge.valueAt(c))
        else:
            a, c, dc = c, e, de
            e = a + GOLDEN * (b - a)
            de = dist(edge.valueAt(e))
    return max(d[j], dc, de)


def _end_kappas(edge):
    return [edge.curvatureAt(edge.FirstParameter), edge.curvatureAt(edge.LastParameter)]


def drift(feature):
    """[(sketch label, largest distance mm, largest end-curvature difference 1/mm, which
    moved)] of the copies that are no longer the feature's curve: distances both ways, the
    largest on each edge (_farthest), curvature at each copy piece's ends against its feature
    edge's nearest end; which moved: moved_words."""
    if feature.Shape.isNull() or not feature.Shape.Edges:
        return []
    own = feature.Shape.copy()
    try:        # the Shape is in its container's coordinates (a Body's, a Part's)
        up = feature.getGlobalPlacement().multiply(feature.Placement.inverse())
        own.transformShape(up.toMatrix())
    except (AttributeError, Part.OCCError):
        pass
    out = []
    for sk, edges in _copy_edges(feature).items():
        copy = Part.Compound(edges)
        far = max([_farthest(e, own) for e in edges] + [_farthest(e, copy) for e in own.Edges])
        jump = 0.0
        for k, e in enumerate(edges):
            # piece k is the copy of the feature's edge k (written in order); where pieces
            # meet with a curvature jump (a G2 quadratic's), the nearest end was the other
            # piece's: 5.69e-05/mm 'off' said of an exact copy (QA24gui F2). A copy in another
            # number of pieces: the nearest end of any
            mine = own.Edges[k:k + 1] if len(edges) == len(own.Edges) else own.Edges
            ends = [(f.valueAt(t), f.curvatureAt(t)) for f in mine
                    for t in (f.FirstParameter, f.LastParameter)]
            for t in (e.FirstParameter, e.LastParameter):
                p = e.valueAt(t)
                kf = min(ends, key=lambda pk: (pk[0] - p).Length)[1]
                k = e.curvatureAt(t)
                if abs(k - kf) > KAPPA_OFF * max(abs(k), abs(kf)) + 1e-6:
                    jump = max(jump, abs(k - kf))
        if far > OFF or jump > 0.0:
            out.append((sk.Label, far, jump, moved_words(own, sk, feature)))
    return out


def forget_absent(feature):
    """After a restore: the copies COPIES names that are not in the feature's document (the
    sketch missing, or holding no copy of it) forgotten, and the Status's copy note judged
    again (say_drift). A spline pasted into another document (Std_Copy, Std_Paste) kept
    'The copy in Sketch 'Profile' is 5.99 mm off' though that document has no such
    sketch, through its recomputes (its inputs unchanged: it does not recompute), QA24gui
    F3. A document reopened has its copies where they were: nothing to do."""
    if COPIES not in feature.PropertiesList:
        return
    names = [e.split(" ", 1)[0] for e in feature.SketchCopies]
    here = {n for n in names if _holds_copy(feature, feature.Document.getObject(n))}
    if len(here) == len(set(names)):
        return
    feature.SketchCopies = [e for e, n in zip(feature.SketchCopies, names) if n in here]
    say_drift(feature)


def _holds_copy(feature, sketch):
    """Whether ``sketch`` holds the feature's copy: found (earlier_copy) and marked with its
    name (MARK; a copy written before marks: found is enough). A feature pasted into its
    own document has a new Name and the Tags of the first one's copy: not its copy."""
    if sketch is None or not hasattr(sketch, "Geometry"):
        return False
    ids = earlier_copy(feature, sketch)
    geometry = sketch.Geometry
    return bool(ids) and all(
        not geometry[i].hasExtensionOfName(MARK) or
        geometry[i].getExtensionOfName(MARK).Value.rpartition(" ")[0] == feature.Name
        for i in ids)


def moved_words(own, sketch, feature):
    """Which moved since the copy in ``sketch`` was written, from the points it was written
    at (geometry.WRITTEN): the copy (the Sketcher's solver, a drag), this curve (``own``,
    global: an input edited, a duck dragged), or both; QA23gui F3: 'the Sketcher moved it'
    was said when a duck was dragged and the copy was untouched. A copy written before the
    points were kept: either."""
    geometry = sketch.Geometry
    ids = earlier_copy(feature, sketch)
    moved = [copy_moved(geometry[i]) for i in ids]
    if not ids or None in moved:
        return "the copy does not follow this curve, and the Sketcher may move it"
    gp = sketch.getGlobalPlacement()
    changed = max((own.distToShape(Part.Vertex(gp.multVec(p)))[0]
                   for i in ids for p in written_points(geometry[i])), default=0.0) > OFF
    copy = max(moved) > OFF
    if copy and changed:
        return "the Sketcher moved it, and this curve changed since it was copied"
    if copy:
        return "the Sketcher moved it"
    return "this curve changed since it was copied, the copy is where it was written"


def note(found):
    """The words for drift()'s findings ('' for none), '<number> mm' as units.mm_marked
    marks them."""
    from .units import per_length_mark
    parts = []
    for label, far, jump, which in found:
        t = f"the copy in Sketch '{label}' is {far:.3g} mm off this curve"
        if jump > 0.0:
            t += f", its end curvature {per_length_mark(jump)} off"
        parts.append(t + f" ({which}): Copy into again")
    return "; ".join(parts)


def say_drift(obj):
    """After a recompute that succeeded: each copy measured; those off said in the report
    view and after the Status ('ok. The copy in ...'); a Status with no copy off loses an
    earlier note. Reads the sketches only (no recompute of them)."""
    from .proxy import _said_texts, set_said
    from .units import mm_marked, say
    if "Status" not in obj.PropertiesList:
        return
    try:
        found = drift(obj)
    except Part.OCCError:
        return
    marked = _said_texts(obj).get("Status", [None, obj.Status])[1]
    if not isinstance(marked, str) or marked.startswith("error"):
        return
    base = marked.split(NOTE, 1)[0]
    text = note(found)
    proxy = getattr(obj, "Proxy", None)
    if text:
        text = mm_marked(text)
        if not getattr(proxy, "previewing", False):   # as report()
            _tell(obj, proxy, f"Elastica {obj.Label}: {say(text)}\n")
        set_said(obj, "Status", base + NOTE + text[len("the copy in "):])
    else:
        _tell(obj, proxy, None)
        if base != marked:
            set_said(obj, "Status", base)


def _scheduler():
    """Where the GUI runs: a function running its argument once the event loop is idle again
    (after the user action whose recomputes are running; proxy.IDLE_HOOK, the GUI's: this
    module imports no Qt), else None (a script's recompute is its own step: said at once)."""
    from .proxy import IDLE_HOOK
    return IDLE_HOOK[0] if App.GuiUp and IDLE_HOOK else None


def _tell(obj, proxy, line):
    """The report view's line for a feature's copies off (``line``; None: none off now).
    Once per user action: one drag or datum change recomputes the feature more than once
    as the sketch settles (11.4 mm, then 26.3 mm: two lines for one move), so under the GUI
    the line waits for the event loop to be idle and only the last one is said; and not
    again while it reads the same (a recompute that moved nothing). The Status always
    carries the present figure. Kept on the proxy (not saved: a reopened document says it
    once more)."""
    if proxy is None:
        if line:
            App.Console.PrintWarning(line)
        return
    if line is None:
        proxy._drift_said = None                # in line again: a later drift is news
        if getattr(proxy, "_drift_pending", None) is not None:
            proxy._drift_pending = ""           # nothing to say at the idle point
        return
    later = _scheduler()
    if later is None:
        _say_once(proxy, line)
        return
    waiting = getattr(proxy, "_drift_pending", None) is not None
    proxy._drift_pending = line
    if not waiting:
        later(lambda: _flush(proxy))


def _flush(proxy):
    line, proxy._drift_pending = getattr(proxy, "_drift_pending", None), None
    if line:
        _say_once(proxy, line)


def _say_once(proxy, line):
    if line != getattr(proxy, "_drift_said", None):
        App.Console.PrintWarning(line)
        proxy._drift_said = line


class CopyWatch:
    """A sketch holding a feature's copy recomputed (the designer moved its geometry, added
    a constraint): the features that do not read that sketch (those that do recompute after
    it, and their execute measures) measure their copies there and say it, their Status set
    as by their own recompute (not touched: no recompute follows, the outcome kept)."""

    def slotRecomputedObject(self, obj):
        if obj.TypeId != "Sketcher::SketchObject":
            return
        doc = obj.Document
        if doc.Restoring or doc.Transacting:
            return
        prefix = obj.Name + " "
        for f in doc.Objects:
            if COPIES not in f.PropertiesList or \
                    not any(e.startswith(prefix) for e in getattr(f, COPIES)):
                continue
            if obj in f.OutListRecursive or "Touched" in f.State or \
                    "Invalid" in f.State or "Error" in f.State:
                continue        # its own recompute follows, or it has no curve to measure
            proxy = getattr(f, "Proxy", None)
            was = getattr(proxy, "_executing", False)
            if proxy is not None:
                proxy._executing = True      # its result, as its execute sets it (drop_kept)
            try:
                say_drift(f)
            finally:
                if proxy is not None:
                    proxy._executing = was
            f.purgeTouched()


App.addDocumentObserver(CopyWatch())        # once: Python imports a module once
