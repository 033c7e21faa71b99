"""View providers of the Elastica features (GUI only; this module imports no GUI
code at load time, so old documents naming ``features.ViewProvider`` load
headless too).

Each feature gets its icon, a colour of its own (fits cycle through a palette, a
comb takes its source's colour), double-click opens its task panel, and a
feature whose last recompute failed is drawn dashed (it shows the last good
shape). A fit also draws the points it fitted (markers) and, optionally, the
residual segments to their points on the curve; a G2 quadratic B-spline its
affine arc-length polyline, an elliptic blend its control polygon (optionally); an
elastic spline its ducks, comb and forces, and the guide ducks of G2 ends (also a
G2 blend's) in orange, larger than the curve is wide."""
from __future__ import annotations

import FreeCAD as App

from . import icon
from .containers import to_holder

PALETTE = [("red", (0.84, 0.15, 0.16)), ("blue", (0.12, 0.47, 0.71)),
           ("green", (0.17, 0.63, 0.17)), ("purple", (0.58, 0.40, 0.74)),
           ("orange", (1.0, 0.50, 0.05)), ("brown", (0.55, 0.34, 0.29)),
           ("teal", (0.09, 0.75, 0.81))]
ICONS = {"Fit": "fit", "Blend": "blend", "Comb": "comb", "EllipticBlend": "ellblend",
         "G2Quad": "g2quad", "Spline": "spline"}
WIDTHS = {"Fit": 3.0, "Blend": 3.0, "Comb": 1.0, "EllipticBlend": 3.0, "G2Quad": 3.0,
          "Spline": 3.0}
# overlays drawn beside a feature's shape: groups of (colour, markers, segments), each
# drawn with its (line width, marker size in pixels, in front of the curve or not); a
# guide duck sits on the curve through it: its marker is larger than the curve is wide
# and drawn in front, or the curve hides it
GUIDES = (2.5, 11.0, True)
OVERLAY_GROUPS = {"Fit": ((1.0, 6.0, False),), "G2Quad": ((1.0, 6.0, False),),
                  "EllipticBlend": ((1.0, 7.0, False),),
                  "Spline": ((1.0, 6.0, False), (1.0, 6.0, False), (2.5, 6.0, False), GUIDES),
                  "Blend": (GUIDES,)}
GUIDE_RGB = (0.95, 0.5, 0.0)  # the guide ducks of G2 ends (orange), apart from the user's ducks
FORCE_RGB = (0.85, 0.1, 0.6)  # duck forces: magenta, apart from every palette colour of the curve
SPLINE_COMB_TEETH = 150     # teeth along a whole spline
ARROW_SHARE = 0.1           # the longest duck-force arrow: this share of the spline's size
ARROW_FLOOR = 0.3           # no arrow shorter than this share of the longest: its direction
                            # shows (the panel gives the values)


def when_idle(fn):
    """Run ``fn`` once the event loop is idle again, after the user action under way
    (proxy.IDLE_HOOK: copies' report line said once per action)."""
    from PySide import QtCore
    QtCore.QTimer.singleShot(0, fn)


def _kind(obj):
    return getattr(getattr(obj, "Proxy", None), "kind", "")


def _rgb(c):
    return tuple(float(x) for x in tuple(c)[:3])


def colour_name(obj):
    """The palette name of a feature's line colour ('' when not from the palette)."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None:
        return ""
    rgb = _rgb(vobj.LineColor)
    return next((name for name, c in PALETTE if max(abs(a - b) for a, b in zip(c, rgb)) < 0.01),
                "")


def _next_colour(obj):
    """The first palette colour no other Elastica feature of the document uses."""
    used = {colour_name(o) for o in obj.Document.Objects if o is not obj and _kind(o)}
    return next((c for name, c in PALETTE if name not in used), PALETTE[0][1])


def _lighter(c, amount=0.45):
    return tuple(x + (1.0 - x) * amount for x in c)


def attach(obj):
    """Give an Elastica feature its view provider (once) and its default look."""
    vobj = getattr(obj, "ViewObject", None)
    if vobj is None or isinstance(getattr(vobj, "Proxy", None), ViewProvider):
        return
    kind = _kind(obj)
    ViewProvider(vobj, ICONS.get(kind, "elastica"))
    if kind == "Comb":
        src = obj.Source[0] if getattr(obj, "Source", None) else None
        base = _rgb(src.ViewObject.LineColor) if src is not None and _kind(src) and \
            getattr(src, "ViewObject", None) is not None else (0.17, 0.63, 0.17)
        colour = _lighter(base)
    else:
        colour = _next_colour(obj)
    vobj.LineColor = colour
    vobj.PointColor = colour
    vobj.LineWidth = WIDTHS.get(kind, 2.0)
    vobj.PointSize = 1.0


def attach_missing(doc):
    """View providers for the Elastica features of a document made without the GUI."""
    for o in doc.Objects:
        if _kind(o):
            attach(o)


def saved_visibility(path):
    """{object name: visibility} as saved in an .FCStd without GUI data (a document
    made by freecadcmd), or None when the file has its GuiDocument.xml."""
    import zipfile
    import xml.etree.ElementTree as ET
    try:
        with zipfile.ZipFile(path) as z:
            if "GuiDocument.xml" in z.namelist():
                return None
            root = ET.fromstring(z.read("Document.xml"))
    except (OSError, KeyError, zipfile.BadZipFile, ET.ParseError):
        return None
    out = {}
    for o in root.iter("Object"):
        for p in o.iter("Property"):
            if p.get("name") == "Visibility":
                b = p.find("Bool")
                if b is not None and o.get("name"):
                    out[o.get("name")] = b.get("value") == "true"
    return out


_OPENING = set()


def finish_opening(doc):
    """After FreeCAD has opened a document made without the GUI (which shows only
    some objects): the view providers of its Elastica features and the visibility
    its objects were saved with; the features saved out of date recomputed (stale_on_open)."""
    if doc.Restoring:           # (an event loop run during the restore: once it is over)
        from PySide import QtCore
        name = doc.Name
        QtCore.QTimer.singleShot(50, lambda: name in App.listDocuments() and
                                 finish_opening(App.getDocument(name)))
        return
    _OPENING.discard(doc.Name)
    stale_on_open(doc)
    attach_missing(doc)
    vis = saved_visibility(doc.FileName) if doc.FileName else None
    for name, shown in (vis or {}).items():
        o = doc.getObject(name)
        if o is not None and getattr(o, "ViewObject", None) is not None:
            o.ViewObject.Visibility = shown
            if o.isDerivedFrom("Points::Feature"):     # data points: seen, not specks
                o.ViewObject.PointSize = 4.0
                o.ViewObject.ShapeColor = (0.1, 0.1, 0.1)


def stale_on_open(doc):
    """Recompute, with what follows them, the features a document opened with that must
    execute (FeatureProxy.mustExecute): saved by an older build, their Shape where it drew
    them (QA20gui F2: an Elastic blend of lines in a placed Body saved at 76874aa opened
    130 mm off its lines, Up-to-date, no mark in the tree, until Ctrl+R); a fit's point file
    changed on disk. FreeCAD purges a touch made while it restores (onDocumentRestored), and
    0.20's document observers have no end-of-restore slot: the GUI does it here, once open."""
    from .proxy import FeatureProxy
    stale = [o for o in doc.Objects if isinstance(getattr(o, "Proxy", None), FeatureProxy)
             and o.Proxy.mustExecute(o)]
    if not stale:
        return
    names = {o.Name for o in stale}
    App.Console.PrintMessage(f"Elastica: {doc.Label}: {', '.join(o.Label for o in stale)} "
                             "saved out of date (an older build): recomputed\n")
    for o in stale:
        o.touch()
    follow = [o for o in stale] + [d for o in stale for d in o.InListRecursive
                                   if d.Name not in names]
    doc.recompute(list({o.Name: o for o in follow}.values()))


def restored(obj):
    """An Elastica feature was restored: its view provider now, the rest of the
    document once FreeCAD has finished opening it."""
    attach(obj)
    doc = obj.Document
    if doc.Name not in _OPENING:
        _OPENING.add(doc.Name)
        from PySide import QtCore
        name = doc.Name
        QtCore.QTimer.singleShot(0, lambda: name in App.listDocuments() and
                                 finish_opening(App.getDocument(name)))


def _arrows(tips, vectors, length, big=None):
    """Segment pairs of arrows along ``vectors`` ending at ``tips`` (a force drawn
    pushing on its point), the longest (or one of size ``big``) ``length`` long, none
    shorter than ARROW_FLOOR of that, each with a two-stroke head; plane coordinates
    (z = 0)."""
    big = big or max((v.Length for v in vectors), default=0.0)
    out = []
    if big <= 0:
        return out
    for tip, v in zip(tips, vectors):
        if v.Length <= 1e-9 * big:
            continue
        tail = tip - v * (length * max(v.Length / big, ARROW_FLOOR) / v.Length)
        shaft = (tail - tip).Length
        back = (tail - tip) * (min(0.25 * length, 0.5 * shaft) / shaft)   # heads alike
        side = App.Vector(-back.y, back.x, 0.0)
        out += [tail, tip, tip, tip + back + side * 0.5, tip, tip + back - side * 0.5]
    return out


def _force_arrows(obj, points, forces, size, big=None):
    """Arrows (segment pairs, global) of the forces at points of a feature's plane (the
    longest, or one of size ``big``, a tenth of ``size``)."""
    if not points or len(forces) != len(points):
        return []
    rot = obj.Plane.Rotation
    inv = rot.inverted()
    local = [inv.multVec(v) for v in forces]
    tips = [inv.multVec(p - obj.Plane.Base) for p in points]
    return [rot.multVec(p) + obj.Plane.Base for p in _arrows(tips, local, ARROW_SHARE * size, big)]


def _guide_overlay(obj, size, arrows=True, big=None):
    """The guide ducks of G2 ends (orange markers) and their forces (orange arrows)."""
    guides = list(getattr(obj, "GuideDucks", []))
    forces = list(getattr(obj, "GuideForces", []))
    return (GUIDE_RGB, guides, _force_arrows(obj, guides, forces, size, big) if arrows else [])


def _extent(obj):
    """The size of a feature's shape, whatever its orientation (comb.shape_extent): what
    its comb and arrows are scaled to (the axis-aligned box's diagonal changed as the
    feature turned)."""
    if obj.Shape.isNull():
        return 0.0
    from .comb import shape_extent
    return shape_extent(obj.Shape)


def _spline_overlay(vobj, rgb):
    """Ducks (markers), the curvature comb (teeth and envelope), the duck forces
    (arrows) of an elastic spline, and its guide ducks (G2 ends) apart, in orange."""
    obj = vobj.Object
    ducks = list(obj.Ducks) if getattr(vobj, "ShowDucks", True) else []
    comb, arrows = [], []
    size = _extent(obj)
    stored = obj.Proxy.plane_curves(obj) if getattr(vobj, "ShowComb", True) else None
    if stored and size > 0:
        from .comb import chain_teeth
        for teeth in chain_teeth(stored[0], stored[1], SPLINE_COMB_TEETH, size):
            comb += [p for pair in teeth for p in pair]
            tips = [b for _, b in teeth]
            comb += [p for a, b in zip(tips, tips[1:]) for p in (a, b)]
    forces = getattr(vobj, "ShowForces", True)
    # one scale for the ducks' and the guides' arrows
    big = max((v.Length for v in list(obj.DuckForces) + list(getattr(obj, "GuideForces", []))),
              default=0.0)
    if forces:
        arrows = _force_arrows(obj, list(obj.Ducks), list(obj.DuckForces), size, big)
    guides = _guide_overlay(obj, size, forces, big) if getattr(vobj, "ShowDucks", True) else \
        (GUIDE_RGB, [], [])
    return [((0.15, 0.15, 0.15), ducks, []), (_lighter(rgb), [], comb),
            (FORCE_RGB, [], arrows), guides]


def overlay_content(vobj):
    """[(rgb, markers, segments)] per overlay group of a feature's view."""
    obj = vobj.Object
    rgb = _rgb(vobj.LineColor)
    kind = _kind(obj)
    if kind == "Fit":
        data = list(obj.DataPoints) if getattr(vobj, "ShowData", True) else []
        res = []
        if getattr(vobj, "ShowResiduals", False) and len(obj.FootPoints) == len(obj.DataPoints):
            for a, b in zip(obj.DataPoints, obj.FootPoints):
                res += [a, b]
        return [(tuple(0.55 * x for x in rgb), data, res)]
    if kind == "G2Quad":
        data = list(obj.Polyline) if getattr(vobj, "ShowPolyline", True) else []
        return [((0.35, 0.35, 0.35), data, [p for a, b in zip(data, data[1:]) for p in (a, b)])]
    if kind == "Spline":
        return _spline_overlay(vobj, rgb)
    if kind == "EllipticBlend":
        q = list(obj.ControlPoints) if getattr(vobj, "ShowControlPolygon", True) else []
        return [(_lighter(rgb), q, [p for a, b in zip(q, q[1:]) for p in (a, b)])]
    if kind == "Blend":      # G2: its guide ducks; two arrows alone, twice a spline's
        return [_guide_overlay(obj, 2.0 * _extent(obj))]
    return []


class ViewProvider:
    """Icon, colours, overlays, the task panel on double-click."""

    def __init__(self, vobj, icon_name):
        self.icon_name = icon_name
        vobj.Proxy = self
        self._add_properties(vobj)

    # ---------------------------------------------------------------- properties

    def _add_properties(self, vobj):
        kind = _kind(vobj.Object)
        props = []
        if kind == "Fit":
            props = [("ShowData", "Fitted points: markers at the points the fit used", True),
                     ("ShowResiduals", "Fitted points: a segment from each point to the curve "
                                       "point it was measured to", False)]
        elif kind == "G2Quad":
            props = [("ShowPolyline", "The affine arc-length polyline (the B-spline's "
                                      "control polygon inside each piece)", True)]
        elif kind == "EllipticBlend":
            props = [("ShowControlPolygon", "The control points and their polygon (a "
                                            "basis with negative functions lets the curve "
                                            "leave their convex hull)", True)]
        elif kind == "Spline":
            props = [("ShowDucks", "Markers at the points the spline passes through (grey) and "
                                   "at the guide ducks of G2 ends (orange)", True),
                     ("ShowComb", "The curvature comb (teeth outside the bend)", True),
                     ("ShowForces", "An arrow at each duck: the force it exerts on the "
                                    "batten (the longest a tenth of the spline's size)", True)]
        for name, tip, value in props:
            if name not in vobj.PropertiesList:
                vobj.addProperty("App::PropertyBool", name, "Elastica", tip)
                setattr(vobj, name, value)

    # ---------------------------------------------------------------- scene

    def attach(self, vobj):
        self.Object = vobj.Object
        self._overlay, self._groups = None, []
        widths = OVERLAY_GROUPS.get(_kind(vobj.Object), ())
        if not widths:
            return
        from pivy import coin
        root = coin.SoSeparator()
        pick = coin.SoPickStyle()
        pick.style = coin.SoPickStyle.UNPICKABLE
        root.addChild(pick)
        for width, size, in_front in widths:
            # one group: a colour, markers and line segments
            sep = coin.SoSeparator()
            if in_front:
                depth = coin.SoDepthBuffer()
                depth.test = False
                sep.addChild(depth)
            g = {"colour": coin.SoBaseColor(), "coords": coin.SoCoordinate3(),
                 "points": coin.SoPointSet(), "line_coords": coin.SoCoordinate3(),
                 "lines": coin.SoLineSet()}
            style = coin.SoDrawStyle()
            style.pointSize = size
            style.lineWidth = width
            for node in (g["colour"], style, g["coords"], g["points"]):
                sep.addChild(node)
            lines = coin.SoSeparator()
            for node in (g["line_coords"], g["lines"]):
                lines.addChild(node)
            sep.addChild(lines)
            root.addChild(sep)
            self._groups.append(g)
        # beside the display modes, shown with the feature (onChanged: Visibility)
        self._overlay = coin.SoSwitch()
        self._overlay.addChild(root)
        vobj.RootNode.addChild(self._overlay)
        self._show(vobj)
        self._refresh(vobj)

    def _show(self, vobj):
        if getattr(self, "_overlay", None) is not None:
            self._overlay.whichChild = 0 if vobj.Visibility else -1

    def overlay_counts(self, group=None):
        """(markers, segments) drawn now, in all groups or in one (tests)."""
        groups = getattr(self, "_groups", [])
        if group is not None:
            groups = groups[group:group + 1]
        return (sum(g["points"].numPoints.getValue() for g in groups),
                sum(g["lines"].numVertices.getNum() for g in groups))

    def _refresh(self, vobj):
        if getattr(self, "_overlay", None) is None:
            return
        for g, (rgb, markers, segments) in zip(self._groups, overlay_content(vobj)):
            # global points, drawn under the placement of the container holding the feature
            # (as its Shape: containers.set_shape)
            markers, segments = to_holder(vobj.Object, markers), to_holder(vobj.Object, segments)
            g["colour"].rgb.setValue(*rgb)
            g["coords"].point.setNum(0)
            g["coords"].point.setValues(0, len(markers), [tuple(p) for p in markers])
            g["points"].numPoints = len(markers)
            g["line_coords"].point.setNum(0)
            g["line_coords"].point.setValues(0, len(segments), [tuple(p) for p in segments])
            g["lines"].numVertices.setNum(0)
            g["lines"].numVertices.setValues(0, len(segments) // 2, [2] * (len(segments) // 2))

    def updateData(self, obj, prop):
        if prop in ("DataPoints", "FootPoints", "Polyline", "Curves", "DuckForces", "GuideForces",
                    "ControlPoints"):
            self._refresh(obj.ViewObject)
        elif prop == "Status":
            vobj = obj.ViewObject
            if "DrawStyle" in vobj.PropertiesList:
                vobj.DrawStyle = "Dashed" if obj.Status.startswith("error") else "Solid"

    def onChanged(self, vobj, prop):
        if prop in ("ShowData", "ShowResiduals", "ShowPolyline", "ShowDucks", "ShowComb",
                    "ShowForces", "ShowControlPolygon", "LineColor"):
            self._refresh(vobj)
        elif prop == "Visibility":
            self._show(vobj)

    # ---------------------------------------------------------------- tree, editing

    def getIcon(self):
        return icon(getattr(self, "icon_name", "elastica"))

    def claimChildren(self):
        return []

    def setEdit(self, vobj, mode=0):
        if mode != 0:
            return None
        from . import taskpanels
        return taskpanels.open_for(vobj.Object)

    def unsetEdit(self, vobj, mode=0):
        import FreeCADGui as Gui
        from .panelbase import CURRENT
        panel = CURRENT[0] if CURRENT else None
        if panel is not None and not panel.closing and getattr(panel, "obj", None) is vobj.Object:
            # FreeCAD ended it: its document is closing, or another object's edit starts
            # (a sketch double-clicked: the Sketcher opens, as it does over a Pad's panel)
            panel.lost("its edit ended")
            panel.dialog_closed = True      # its later close leaves the next edit's alone
        Gui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        import FreeCADGui as Gui
        from .panelbase import CURRENT
        # its panel already open: it stays (setEdit would end the edit first, closing the
        # dialog without OK or Cancel, its transaction left pending)
        if not (CURRENT and getattr(CURRENT[0], "obj", None) is vobj.Object):
            Gui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    # ---------------------------------------------------------------- state

    def __getstate__(self):
        return {"icon": getattr(self, "icon_name", "elastica")}

    def __setstate__(self, state):
        self.icon_name = (state or {}).get("icon", "elastica")
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return self.__setstate__(state)


__all__ = ["ViewProvider", "attach", "attach_missing", "colour_name", "PALETTE"]
