"""A panel's OK and Copy into (panelbase.Panel.accept): the Python OK records for the copy
into a sketch (copy_code), and what OK's lines write into the document (the properties the
edit changed, the copy, the feature removed when not kept) taken back whole when they fail
(Attempt), so that the panel stays open on its edit as FreeCAD's own panels do when their
OK cannot finish (Sketcher's, PartDesign's: the error said, the dialog kept).

An exception out of OK's recorded lines (the target sketch removed by a macro while the
panel was open; a Sketcher ValueError re-adding a constraint in geometry._replace_copy)
reached FreeCAD's TaskDialogPython, which reports it and closes the dialog as if OK had
succeeded: the panel's transaction neither committed nor aborted (the next command's
swallowed it), the sketch as the exception left it (revC 3). A transaction cannot be
partly aborted (FreeCAD 0.20 has no nested ones), so what the copy wrote is put back by
hand: the objects it added removed, the target sketch's Geometry and Constraints (Tags
kept: a sketch takes them back as they were) and the feature's SketchCopies restored."""
from __future__ import annotations

from .geometry import COPIES


def copy_code(doc, feature, target, sources_body):
    """Python of OK's copy of ``feature`` into the sketch named ``target`` ('*new*': a new
    one, in the Body ``sources_body()`` gives), or '' for no target."""
    if not target:
        return ""
    d = f"App.getDocument({doc.Name!r})"
    code = "from freecad.elastica import geometry as elastica_geometry\n"
    if target == "*new*":
        # in the sources' Body, as Sketcher's new sketch in the active Body: it moves
        # with the Body (QA19gui F8); attached as the source sketch is (QA24gui F5)
        body = sources_body()
        where = "None" if body is None else f"{d}.getObject({body.Name!r})"
        code += (f"_sk = elastica_geometry.new_copy_sketch({d}.getObject("
                 f"{feature.Name!r}), {where})\n")
    else:
        code += f"_sk = {d}.getObject({target!r})\n"
    f = f"{d}.getObject({feature.Name!r})"
    if not any(g is not None for g, _ in joint_ends(feature, None)):
        return code + f"elastica_geometry.write_to_sketch({f}, _sk)\n"
    return code + ("from freecad.elastica import okcopy as elastica_okcopy\n"
                   f"elastica_geometry.write_to_sketch({f}, _sk, "
                   f"constrain_to=elastica_okcopy.joint_ends({f}, _sk))\n")


# the links by which a Fit (its joins) and an Elastic spline (its end conditions) meet an
# edge's end, each with the property of its geometry index (the proxy's followed_links)
_JOIN_LINKS = (("StartTangent", "EndTangent"), ("StartEdge", "EndEdge"))


def joint_ends(feature, sketch):
    """[(geo index, None) at the copy's start, (geo index, None) at its end]: the edges of
    ``sketch`` (None: of any sketch) the feature's start and end are joined to (a Fit's
    StartTangent / EndTangent, an Elastic spline's StartEdge / EndEdge), None where there is
    none. A copy into that sketch is joined to them as the blend's is (geometry.join_ends:
    an endpoint Tangent where the copy's end is on the edge's, as Sketcher_CreateFillet
    joins its arc); it had no constraint at all (qagui3 F1: the profile held by equal
    floating-point ends only, the first edit of a line left the copy behind). join_ends
    adds a joint only where the copy's end is on that edge's end bit for bit (a free or a
    tangent-only end beside it is not joined)."""
    links = getattr(getattr(feature, "Proxy", None), "followed_links", {})
    for pair in _JOIN_LINKS:
        if all(p in links for p in pair):
            break
    else:
        return [(None, None), (None, None)]
    out = []
    for prop in pair:
        link, g = getattr(feature, prop, None), getattr(feature, links[prop], -1)
        ok = bool(link) and (sketch is None or link[0] == sketch) and isinstance(g, int) \
            and 0 <= g < len(getattr(link[0], "Geometry", ()))
        out.append((g if ok else None, None))
    return out


class Unsolved(Exception):
    """OK's recompute left the feature in error (its source sketch changed by a macro line
    since the preview): no copy made of the curve it no longer has. It was copied from the
    shape of before, the feature committed Invalid and the panel closed."""


class Attempt:
    """The state OK may change, taken before its lines run (``undo`` puts it back)."""

    def __init__(self, doc, feature, target):
        self.doc, self.feature, self.target = doc, feature, target
        self.names = {o.Name for o in doc.Objects}
        sk = doc.getObject(target) if target and target != "*new*" else None
        self.sketch = sk if sk is not None and hasattr(sk, "Geometry") else None
        self.state = (self.sketch.Geometry, self.sketch.Constraints) if self.sketch else None
        self.copies = list(getattr(feature, COPIES)) if COPIES in feature.PropertiesList \
            else None

    def undo(self):
        """The document as before OK's lines, but for the properties the panel had set
        (they were set already: the lines set them again)."""
        doc = self.doc
        for o in reversed(doc.Objects):        # the new sketch (inside out: a Body's last)
            if o.Name not in self.names:
                doc.removeObject(o.Name)
        # by its name: a sketch removed since is a deleted object (ReferenceError on .Name)
        sk = doc.getObject(self.target) if self.sketch is not None else None
        if sk is not None:
            geometry, constraints = self.state
            sk.Geometry = geometry              # first: the constraints name its indices
            sk.Constraints = constraints
        f = self.feature
        if f.Name in [o.Name for o in doc.Objects]:
            if self.copies is None and COPIES in f.PropertiesList:
                f.removeProperty(COPIES)
            elif self.copies is not None:
                setattr(f, COPIES, self.copies)
        doc.recompute()

    def said(self, exc):
        """Why OK failed, for the panel's error line and the report view, worded by what OK
        was to do (review revB 3: every case ended 'Choose another sketch, or Cancel'):
        - Copy into a sketch: 'Copy into Prof failed, nothing was written: ... Choose
          another sketch, or Cancel'; a sketch gone said so, not Python's words
          ("'NoneType' object has no attribute 'InList'");
        - Copy into a new sketch: 'no sketch was made', and the other choices named (there
          is no other new sketch to choose);
        - no copy: 'OK failed: ...', and that the panel's edits stay set (they were set
          before OK's lines ran: undo leaves them, Cancel takes them back), not 'nothing
          was written'."""
        target = self.target
        sk = self.doc.getObject(target) if self.sketch is not None else None
        if isinstance(exc, Unsolved):
            why = f"the curve's recompute failed: {exc}"
            advice = "Fix its input, or Cancel"
        else:
            why = "that sketch is no longer in the document" if sk is None and target and \
                target != "*new*" else str(exc) or type(exc).__name__
            advice = None
        if not target:
            return f"OK failed: {why}. The panel's edits stay set: " + \
                ("fix the curve's input" if advice else "change them") + ", or Cancel to drop them"
        if target == "*new*":
            return f"Copy into a new sketch failed, no sketch was made: {why}. " + \
                (advice or "Choose a sketch or '(no copy)', or Cancel")
        name = sk.Label if sk is not None else target
        return f"Copy into {name} failed, nothing was written: {why}. " + \
            (advice or "Choose another sketch, or Cancel")
