"""Curvature comb: teeth along a curve, each as long as the curvature there (times a
scale), on the convex side, with the envelope of their tips, one envelope per
chain of curves that continue each other (a keyline's halves, a spline's pieces;
separate edges are not joined). Smooth elasticae (fits,
blends) use the library's exact curvature; anything else, including a discrete
fit's B-spline, OpenCASCADE's curvature of the edges."""
from __future__ import annotations

import math

import FreeCAD as App
import Part

from .containers import set_shape
from .geometry import dedup, el, global_element, global_shape, np
from .links import followed_reader
from .proxy import (FeatureProxy, InputProblem, add_geometry_index, add_link, add_property,
                    new_feature, read_only, report, sub_names)
from .sources import nothing_read

SCALE_SHARE = 0.12    # automatic scale: the longest tooth is this share of the extent


def _hull_2d(xy):
    """The convex hull of the (n, 2) array ``xy``: its corners counter-clockwise as (x, y)
    tuples, without points on its edges (Andrew's monotone chain: scipy.spatial is not in
    FreeCAD's Python, and Part offers no planar hull of points)."""
    pts = sorted(set(tuple(p) for p in xy))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and _cross(out[-2], out[-1], p) <= 0:
                out.pop()
            out.append(p)
        return out[:-1]
    return pts if len(pts) < 3 else half(pts) + half(pts[::-1])


def _cross(o, a, b):
    """Twice the signed area of the triangle o, a, b (> 0: counter-clockwise)."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def _diameter_2d(hull):
    """The largest distance between two corners of a convex polygon (counter-clockwise,
    no three corners collinear) by rotating calipers: for each edge the corner farthest
    from its line, walked round once with the edges (Shamos 1978), O(corners): all pairs of
    a convex curve's 6000 samples took 0.9 s."""
    m = len(hull)
    if m < 3:
        return math.dist(hull[0], hull[-1]) if hull else 0.0
    best, j = 0.0, 1
    for i in range(m):
        a, b = hull[i], hull[(i + 1) % m]
        while _cross(a, b, hull[(j + 1) % m]) > _cross(a, b, hull[j]):
            j = (j + 1) % m
        best = max(best, math.dist(a, hull[j]), math.dist(b, hull[j]))
    return best


def _max_distance(pts):
    """The largest distance between two rows of ``pts``, compared a block of rows at a
    time (about 10^6 differences, not all n^2 at once)."""
    n = np()
    best = 0.0
    block = max(1, 1000000 // len(pts))
    for i in range(0, len(pts), block):
        d = pts[i:i + block, None, :] - pts[None, :, :]
        best = max(best, float(n.einsum("ijk,ijk->ij", d, d).max()))
    return math.sqrt(best)


def oriented_extent(points):
    """The diameter of ``points`` (App.Vectors): the largest distance between two of them,
    the curve's extent, defined without any axes so the same however the curve is turned
    (the axis-aligned box's diagonal changed as a curve turned: 1361.8 and 1351.7 at 45 deg,
    QA; the box along the principal axes did for a symmetric shape, whose axes are arbitrary:
    a rounded square's scale 172.1 .. 214.9 as it turned, review revfc 3). A planar set
    (the library's plane_fit, its points within 1e-9 of the extent off the plane): its
    convex hull in the plane by rotating calipers; any other: all pairs (no 3D hull here).
    0 for fewer than 2 points."""
    n = np()
    xyz = n.array([tuple(p) for p in points], dtype=float).reshape(-1, 3)
    if len(xyz) < 2:
        return 0.0
    xyz = xyz - xyz.mean(axis=0)
    size = float(n.abs(xyz).max())
    if size == 0.0:
        return 0.0
    if len(xyz) >= 3:
        try:
            xy, frame = el().plane_fit(xyz)
        except el().SingularError:          # collinear or equal points: all pairs
            xy = None
        if xy is not None and \
                float(n.abs((xyz - frame.origin) @ frame.e3).max()) <= 1e-9 * size:
            return _diameter_2d(_hull_2d(xy))
    return _max_distance(xyz)


def shape_extent(shape, samples=60):
    """oriented_extent of points along a shape's edges (``samples`` on each)."""
    return oriented_extent([p for e in shape.Edges for p in e.discretize(samples)])


def _elastica_teeth(curve, plc, samples):
    """(feet, left unit normals, signed curvatures) of a smooth elastica from the
    library; a tooth is foot - normal * kappa * scale (outside the turn)."""
    n = np()
    s = n.linspace(0.0, curve.length, samples)
    xy, theta, kappa = curve.points(s), curve.angle(s), curve.curvature(s)
    feet = [plc.multVec(App.Vector(x, y, 0)) for x, y in xy]
    # the left normal of the tangent (cos th, sin th) in the plane
    normals = [plc.Rotation.multVec(App.Vector(-math.sin(t), math.cos(t), 0)) for t in theta]
    return feet, normals, [float(k) for k in kappa]


def _edge_teeth(edge, samples):
    """The same from OpenCASCADE: normalAt points to the centre of curvature and
    curvatureAt is >= 0, so the tooth foot - normal * kappa * scale is outside too."""
    n = np()
    feet, normals, kappas = [], [], []
    for u in n.linspace(edge.FirstParameter, edge.LastParameter, samples):
        feet.append(edge.valueAt(u))
        try:
            normals.append(edge.normalAt(u))
            kappas.append(float(edge.curvatureAt(u)))
        except Part.OCCError:               # a straight piece: no normal, no tooth
            normals.append(App.Vector(0, 0, 0))
            kappas.append(0.0)
    return feet, normals, kappas


def comb_core(source, subs=(), samples=60, scale=0.0, element=global_element, more=()):
    """Teeth of a curvature comb: a list per curve of (foot, tip) vector pairs, and
    the scale used. ``samples`` teeth per curve; ``scale`` 0 = automatic (the longest
    tooth 12 % of the source's extent, shape_extent: the same however it is turned);
    ``element``: (obj, name) -> its global edge ``name`` (a feature's: the sketch geometry
    its link follows, links.followed_reader). ``more``: further (object, sub-element names)
    combed with it on the same scale (one comb over a blend and the edges it joins: equal
    curvature gives equal teeth across a joint, QA gui F5), the automatic scale then of all
    of them (the largest curvature of any, the extent of all together); each keeps its own
    envelopes."""
    if not 2 <= samples <= 5000:
        raise InputProblem(f"Samples = {samples} is not usable: 2 to 5000 teeth per curve")
    if not math.isfinite(scale):
        raise InputProblem(f"Scale = {scale}: must be a finite number (0 = automatic)")
    if scale < 0.0:
        raise InputProblem(f"Scale = {scale:g}: the tooth length per unit curvature must be "
                           ">= 0 (0 = automatic); the teeth already point to the side the "
                           "curve turns away from")
    per_curve, shapes = [], []
    for obj, names in [(source, subs)] + list(more):
        curves, shape = _source_teeth(obj, names, samples, element)
        per_curve += curves
        shapes.append(shape)
    shape = shapes[0] if len(shapes) == 1 else Part.makeCompound(shapes)
    return scaled_teeth(per_curve, shape_extent(shape), scale)


def _source_teeth(source, subs, samples, element):
    """(the (feet, normals, curvatures) of each chain of ``source``'s curves (chained, or of
    its edges ``subs``), the source's shape: what the automatic scale's extent is of, as
    before more sources could be combed with it); InputProblem."""
    shape = global_shape(source)              # where it is drawn (a sketch in a Body: placed)
    if shape.isNull():
        raise InputProblem("the comb's source has no geometry")
    proxy = getattr(source, "Proxy", None)
    stored = proxy.plane_curves(source) if hasattr(proxy, "plane_curves") else None
    if stored and all(isinstance(c, el().SmoothElastica) for c in stored[0]):
        per_curve = [_elastica_teeth(c, stored[1], samples) for c in stored[0]]
    else:
        edges = [element(source, s) for s in subs if s.startswith("Edge")] if subs \
            else shape.Edges
        if not edges:
            raise InputProblem("the comb's source has no edges")
        per_curve = [_edge_teeth(e, samples) for e in edges]
    return chained(per_curve, 1e-9 * shape.BoundBox.DiagonalLength), shape


def chained(per_curve, gap):
    """The (feet, normals, curvatures) of curves that continue each other (a curve's
    last foot within ``gap`` of the next one's first) joined into one: one envelope
    along a G2 chain such as a keyline fit or an elastic spline."""
    out = [per_curve[0]]
    for feet, normals, kappas in per_curve[1:]:
        f0, n0, k0 = out[-1]
        if (f0[-1] - feet[0]).Length <= gap:
            out[-1] = (f0 + feet[1:], n0 + normals[1:], k0 + kappas[1:])
        else:
            out.append((feet, normals, kappas))
    return out


def scaled_teeth(per_curve, extent, scale=0.0):
    """([[(foot, tip), ...] per curve], scale) of (feet, normals, curvatures) per
    curve; ``scale`` 0 = automatic: the longest tooth SCALE_SHARE of ``extent``."""
    kmax = max((abs(k) for _, _, ks in per_curve for k in ks), default=0.0)
    if scale <= 0:
        scale = SCALE_SHARE * extent / kmax if kmax > 0 else 1.0
    teeth = [[(f, f - nv * (k * scale)) for f, nv, k in zip(*c)] for c in per_curve]
    return teeth, scale


def chain_teeth(curves, plc, total, extent):
    """Comb teeth along a chain of smooth elasticae (an elastic spline's pieces):
    about ``total`` teeth in all, each piece's share by its length (at least 2),
    automatic scale (of ``extent``: shape_extent); a list per piece of (foot, tip) pairs."""
    whole = sum(c.length for c in curves) or 1.0
    per_curve = [_elastica_teeth(c, plc, max(2, int(round(total * c.length / whole))))
                 for c in curves]
    return scaled_teeth(per_curve, extent)[0]


class CombProxy(FeatureProxy):
    """Curvature comb along a Fit / Blend result or any edges."""

    kind = "Comb"
    # a sketch's edges combed are their geometry, followed as the sketch changes (QA: a comb
    # of Edge3 and Edge4 combed two other edges once an earlier line was made construction)
    followed_links = {"Source": "SourceGeometry", "MoreSources": "MoreSourcesGeometry"}

    def setup(self, obj):
        add_link(obj, "App::PropertyLinkSub", "Source", "Comb",
                 "An Elastica result, or an object (and optionally its edges)")
        add_geometry_index(obj, "SourceGeometry", "Source", several=True)
        # (added by a newer version: a comb of an older document gets it empty on restore)
        add_link(obj, "App::PropertyLinkSubList", "MoreSources", "Comb",
                 "Further Elastica results or edges combed with Source on the same scale "
                 "(one comb: equal curvature gives equal teeth across a joint)")
        add_geometry_index(obj, "MoreSourcesGeometry", "MoreSources")
        add_property(obj, "App::PropertyInteger", "Samples", "Comb",
                     "Teeth per curve (2 to 5000)", 60)
        add_property(obj, "App::PropertyFloat", "Scale", "Comb",
                     "Tooth length per unit curvature (mm^2); 0 = automatic", 0.0)
        add_property(obj, "App::PropertyFloat", "UsedScale", "Result", "The scale actually used (mm^2)")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last update")
        read_only(obj, "UsedScale", "Status")

    def compute(self, obj):
        """comb_core's (teeth per curve, scale); raises InputProblem."""
        if self._orphaned(obj):     # a file saved so (onChanged promotes as it is deleted)
            self.promote(obj)
        if not obj.Source:
            raise nothing_read("an Elastica result or some edges", "Source")
        element = followed_reader(obj, "Source")      # renames Source: read it after
        more = []
        if obj.MoreSources:
            others = followed_reader(obj, "MoreSources")   # renames MoreSources too
            for src, subs in obj.MoreSources:
                if src is None:
                    continue
                more.append((src, tuple(n for n in subs if n)))
            if any(src == obj.Source[0] for src, _ in more):
                raise InputProblem(f"{obj.Source[0].Label} is both Source and in MoreSources: "
                                   "name it once")

            def element(src, name, first=element, others=others, mine=obj.Source[0]):
                return first(src, name) if src == mine else others(src, name)
        return comb_core(obj.Source[0], obj.Source[1], obj.Samples, obj.Scale, element, more)

    _promoted = ""      # said in Status after the comb that promote made (report view: at once)

    @staticmethod
    def _orphaned(obj):
        return not obj.Source and any(src is not None for src, _ in obj.MoreSources)

    def onChanged(self, obj, prop):
        """Source emptied by its object's deletion: promote at once, outside a recompute (it
        wrote Source and MoreSources inside one: the recompute's own inputs changed under
        it); not as a file is restored or Undo/Redo restores a step (its values are the
        step's, and what a promote undone would have said in Status is forgotten)."""
        super().onChanged(obj, prop)
        if prop in ("Source", "MoreSources") and obj.Document.Transacting:
            self._promoted = ""     # Undo/Redo: the step's sources; a promote undone is not said
        if prop == "Source" and "Restore" not in obj.State and not obj.Document.Transacting \
                and not getattr(self, "_executing", False) and \
                "MoreSources" in obj.PropertiesList and self._orphaned(obj):
            self.promote(obj)

    def promote(self, obj):
        """Source emptied (its object deleted) while MoreSources still holds sources: the first
        of them becomes the Source, the comb recomputed over what remains and said in the
        report view (review of F5: the comb was in error 'nothing read' with sources left).
        Said in Status by the next recompute's apply, once."""
        followed_reader(obj, "MoreSources")     # their names as the geometry they follow now
        left = [(src, tuple(subs)) for src, subs in obj.MoreSources if src is not None]
        (src, subs), rest = left[0], left[1:]
        obj.MoreSources = rest
        obj.Source = (src, [n for n in subs if n])
        self._promoted = (f"its Source was deleted: {src.Label}, the first of MoreSources, is "
                          "the Source now")
        App.Console.PrintWarning(f"Elastica {obj.Label}: {self._promoted}\n")

    def apply(self, obj, r):
        teeth, scale = r
        shapes = []
        for curve in teeth:
            shapes += [Part.makeLine(a, b) for a, b in curve if (a - b).Length > 1e-12]
            env = dedup([b for _, b in curve])
            if len(env) > 1:
                shapes.append(Part.makePolygon(env))
        if not shapes:
            report(obj, "the source is straight: zero curvature everywhere")
            return
        set_shape(obj, Part.makeCompound(shapes))
        obj.UsedScale = scale
        obj.Status = f"ok ({self._promoted})" if self._promoted else "ok"
        self._promoted = ""         # said once: the next recompute's Status is its own


def make(doc, source, subs=(), more=(), **props):
    """A new curvature comb of ``source`` (optionally of its edges ``subs``), and of the
    further (object, sub-element names) ``more`` on the same scale (MoreSources)."""
    # a whole object is (obj, ('',)) in a link list: (obj, ()) is dropped by FreeCAD
    extra = {"MoreSources": [(o, tuple(n for n in sub_names(s) if n) or ("",))
                             for o, s in more]} if more else {}
    return new_feature(doc, "ElasticaComb", CombProxy,
                       Source=(source, [n for n in sub_names(subs) if n]), **extra, **props)


__all__ = ["CombProxy", "comb_core", "make", "oriented_extent", "shape_extent"]
