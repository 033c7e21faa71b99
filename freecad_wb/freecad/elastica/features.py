"""Parametric features of the Elastica workbench (Part::FeaturePython proxies).

- ``Fit``: an elastica fitted to sketch edges / sketch vertices / a Points object /
  a Draft wire or 3D polyline (plane fit) / a CSV file; its shape is the B-spline
  of the fitted curve(s), within ``Tolerance``.
- ``Blend``: an elastic Hermite curve between two edge ends (all solutions are
  computed; ``Solution`` picks one).
- ``EllipticBlend``: an elliptic blending-function curve (seed 003) through, or
  controlled by, four picked points.
- ``Comb``: a curvature comb of a Fit / Blend result (exact curvature from the
  library) or of any edge (OpenCASCADE's curvature).

Each proxy's ``execute`` gathers geometry from FreeCAD, calls the libelastica
binding, and builds Part geometry; nothing numerical is done here. Every core is
also a plain function (``fit_core``, ``blend_core``, ``comb_core``) so the
commands can validate input before touching the document, and tests can call
them headless. Failures never escape ``execute``: they go to the report view and
to the ``Status`` property, and the previous shape is kept.
"""
from __future__ import annotations

import json
import math

import FreeCAD as App
import Part

from . import defaults, ensure_binding

MIN_POINTS = 6          # fewer points cannot determine the 7 (5 shape) parameters of a fit
VERSION = 1             # of the proxies' saved state


class InputProblem(ValueError):
    """Unusable input for a command (a message for the user, not a bug)."""


def _el():
    return ensure_binding()


def _np():
    import numpy
    return numpy


# ----------------------------------------------------------- placements <-> frames

def placement_from_frame(frame):
    """App.Placement of a libelastica prep.Frame (origin, e1, e2, e3 = normal)."""
    e1, e2, e3 = (App.Vector(*map(float, v)) for v in (frame.e1, frame.e2, frame.e3))
    m = App.Matrix(e1.x, e2.x, e3.x, 0, e1.y, e2.y, e3.y, 0, e1.z, e2.z, e3.z, 0)
    return App.Placement(App.Vector(*map(float, frame.origin)), App.Rotation(m))


def to_3d(plc, xy):
    """Global 3D vectors of plane points (n, 2) in the frame ``plc``."""
    return [plc.multVec(App.Vector(float(x), float(y), 0.0)) for x, y in xy]


def to_plane(plc, vectors):
    """(n, 3) local coordinates of global vectors in the frame ``plc``."""
    inv = plc.inverse()
    return _np().array([tuple(inv.multVec(App.Vector(v))) for v in vectors], dtype=float)


# ----------------------------------------------------------- gathering points

def _is_sketch(obj):
    return obj is not None and obj.isDerivedFrom("Sketcher::SketchObject")


def _dedup(vecs, tol=1e-9):
    out = []
    for v in vecs:
        if not out or (v - out[-1]).Length > tol:
            out.append(v)
    return out


def _sample_edges(edges, samples_per_edge):
    """Ordered points along a chain of edges (sorted and oriented head to tail)."""
    groups = Part.sortEdges(edges) if len(edges) > 1 else [edges]
    if len(groups) != 1:
        raise InputProblem(f"the selected edges form {len(groups)} separate chains, not one curve")
    chain = groups[0]
    pts = []
    for e in chain:
        if isinstance(e.Curve, Part.Line) or e.Curve.TypeId == "Part::GeomLine":
            seg = [e.Vertexes[0].Point, e.Vertexes[-1].Point]
        else:
            seg = e.discretize(Number=samples_per_edge)
        if pts:
            if (seg[0] - pts[-1]).Length > (seg[-1] - pts[-1]).Length:
                seg = list(reversed(seg))
        elif len(chain) > 1:
            nxt = chain[1]
            ends = [nxt.Vertexes[0].Point, nxt.Vertexes[-1].Point]
            if min((seg[0] - p).Length for p in ends) < min((seg[-1] - p).Length for p in ends):
                seg = list(reversed(seg))
        pts.extend(seg)
    return _dedup(pts), Part.Wire(chain).isClosed() if len(chain) else False


def gather_points(sources, csv_file="", samples_per_edge=60):
    """Points of the fit's input, in 3D, with what is known about them.

    ``sources`` is a PropertyLinkSubList value: [(obj, (subname, ...)), ...].
    Returns (points: list[App.Vector], plane: App.Placement or None (a sketch's),
    ordered: bool, closed: bool). Raises InputProblem for unusable input.
    """
    _el()
    if csv_file:
        from libelastica.io import read_points
        try:
            arr = read_points(csv_file, min_points=1)
        except ValueError as exc:
            raise InputProblem(str(exc)) from None
        pts = [App.Vector(*(list(map(float, r)) + [0.0] * (3 - len(r)))) for r in arr]
        closed = len(pts) > 2 and (pts[0] - pts[-1]).Length < 1e-9
        return pts, None, True, closed
    if not sources:
        raise InputProblem("nothing selected: select sketch edges or vertices, a Points "
                           "object, a wire, or give a CSV file")
    edges, vertices, points = [], [], []
    plane = None
    sketches = set()
    for obj, subs in sources:
        subs = [s for s in (subs or ()) if s]
        if _is_sketch(obj):
            sketches.add(obj.Name)
            plane = obj.getGlobalPlacement()
            if not subs and (obj.Shape.isNull() or not obj.Shape.Edges):
                # a sketch of points only: its Shape is empty, read its point geometry
                # (0.20 reports every sketch point as construction geometry)
                pts = [plane.multVec(g.toShape().Point) for g in obj.Geometry
                       if g.TypeId == "Part::GeomPoint"]
                if not pts:
                    raise InputProblem(f"{obj.Label} holds no edges and no points")
                vertices.extend(pts)
                continue
        if obj.isDerivedFrom("Points::Feature"):
            plc = obj.Placement
            points.extend(plc.multVec(App.Vector(*p)) for p in obj.Points.Points)
            continue
        shape = getattr(obj, "Shape", None)
        if shape is None or shape.isNull():
            raise InputProblem(f"{obj.Label} has no geometry")
        if not subs:
            if shape.Edges:
                edges.extend(shape.Edges)
            else:
                vertices.extend(v.Point for v in shape.Vertexes)
            continue
        for s in subs:
            try:
                el_ = shape.getElement(s)
            except (Part.OCCError, ValueError, IndexError):
                raise InputProblem(f"{obj.Label} has no {s}") from None
            if s.startswith("Edge"):
                edges.append(el_)
            elif s.startswith("Vertex"):
                vertices.append(el_.Point)
            else:
                raise InputProblem(f"{obj.Label}.{s}: select edges or vertices")
    if len(sketches) > 1:
        plane = None
    if sum(bool(x) for x in (edges, vertices, points)) > 1:
        raise InputProblem("select either edges, or vertices, or a Points object, not a mix")
    if edges:
        pts, closed = _sample_edges(edges, samples_per_edge)
        return pts, plane, True, closed
    pts = _dedup(vertices or points)
    return pts, plane, False, False


# ----------------------------------------------------------- the fit core

def _fit_module():
    """libelastica's fit module (el.fit / el.fit_keyline), or None when not built."""
    import importlib
    _el()
    try:
        return importlib.import_module("libelastica.fit")
    except ImportError:
        return None


def _moved(curve, frame2d):
    """The same elastica in the parent coordinates of a (proper, rotation-only)
    Frame2D: the start point mapped, the tangent angle phi turned by the frame's
    angle; nothing else changes under a rigid motion."""
    import dataclasses
    np = _np()
    x0, y0 = frame2d.to_parent(np.array([curve.x0, curve.y0]))
    turn = math.atan2(frame2d.f1[1], frame2d.f1[0])
    return dataclasses.replace(curve, x0=float(x0), y0=float(y0), phi=float(curve.phi + turn))


def _status_text(r):
    st = int(getattr(r, "status", 0))
    if st == 0:
        return "converged"
    el = _el()
    from libelastica._ffi import ffi, lib
    del el
    return "not converged (best curve kept): " + ffi.string(lib.el_strerror(st)).decode()


def curve_bspline(curve, tol, degree):
    """libelastica BSpline (plane coordinates) of a fitted / Hermite curve."""
    el = _el()
    if isinstance(curve, el.SmoothElastica):
        if hasattr(curve, "to_bspline"):
            return curve.to_bspline(tol=tol, degree=degree)
        from libelastica.bspline import smooth_to_bspline
        return smooth_to_bspline(curve, tol=tol, degree=degree)
    # discrete elastica: its vertices are the curve; the C2 cubic through them
    from libelastica.bspline import interpolate_c2
    return interpolate_c2(curve.points())


def part_bspline(bs, plc):
    """Part.BSplineCurve in 3D of a libelastica BSpline in the plane of ``plc``."""
    poles = to_3d(plc, bs.poles[:, :2])
    c = Part.BSplineCurve()
    c.buildFromPolesMultsKnots(poles, [int(m) for m in bs.mults], [float(k) for k in bs.knots],
                               False, int(bs.degree))
    return c


def fit_core(points, plane=None, ordered=True, closed=False, model="discrete",
             split=False, pin_ends=False, step=0.0, tol=1e-3, degree=3):
    """Fit elastica(e) to 3D points. Returns a dict with 'curves' (libelastica curves
    in plane coordinates), 'bsplines', 'placement' (the plane), 'data' (plane
    coordinates of the fitted points), 'rms', 'max_error', 'k', 'status',
    'iterations'. Raises InputProblem with a user message for bad input or a
    failed fit."""
    el = _el()
    np = _np()
    if model not in ("discrete", "smooth"):
        raise InputProblem(f"unknown model {model!r} (discrete or smooth)")
    if closed:
        raise InputProblem("the input is a closed curve: an elastica fit needs an open one")
    if len(points) < MIN_POINTS:
        raise InputProblem(f"{len(points)} points: a fit needs at least {MIN_POINTS}")
    fm = _fit_module()
    if fm is None:
        raise InputProblem("this libelastica has no fit() yet")
    try:
        if plane is not None:
            local = to_plane(plane, points)
            xy = np.ascontiguousarray(local[:, :2])
            extent = float(np.ptp(xy, axis=0).max())
            if np.max(np.abs(local[:, 2])) > 1e-9 * (1.0 + extent):
                plane = None            # not all in the sketch's plane: fit a plane instead
        if plane is None:
            xyz = np.array([tuple(p) for p in points], dtype=float)
            xy, frame = el.plane_fit(xyz)
            plane = placement_from_frame(frame)
        if not ordered:
            xn, _ = el.pca_normalize(xy)
            xy = np.ascontiguousarray(xy[np.argsort(xn[:, 0], kind="stable")])
        if split:
            kf = fm.fit_keyline(xy, r=float(step) if step and step > 0 else None, model=model)
            results = [kf.first, kf.second]
            # the sides are fitted in the re-normalised x''y'' frame: back to the plane
            curves = [_moved(r.curve, kf.prepared.frame2d) for r in results]
        else:
            fixed = {}
            if step and step > 0:
                xy = el.resample_equilateral(xy, float(step))
                if model == "discrete":
                    fixed["h"] = float(step)          # the polygon's segment (seed 000 §5.4)
            if len(xy) < MIN_POINTS:
                raise InputProblem(f"resampling leaves {len(xy)} points; a fit needs "
                                   f"{MIN_POINTS}: use a smaller step")
            if pin_ends:
                fixed.update(x0=float(xy[0][0]), y0=float(xy[0][1]))
            results = [fm.fit(xy, model=model, fixed=fixed or None)]
            curves = [r.curve for r in results]
        bsplines = [curve_bspline(c, tol, degree) for c in curves]
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        hint = ""
        if split and "inflection" in str(exc):
            hint = " (no inflection: fit without splitting the keyline)"
        elif step and "resample" in str(exc):
            hint = f" (is the resampling step {step} longer than the curve?)"
        raise InputProblem(f"fit failed: {exc}{hint}") from None
    rms = [float(r.rms) for r in results]
    maxe = [float(r.max_error) for r in results]
    npts = [len(r.model_points()) for r in results]
    bad = [i for i, v in enumerate(rms + maxe) if not math.isfinite(v)]
    if bad:
        raise InputProblem("fit failed: non-finite error")
    return {
        "curves": curves, "results": results, "bsplines": bsplines, "placement": plane,
        "data": xy,
        "rms": float(np.sqrt(np.dot(np.square(rms), npts) / sum(npts))),
        "max_error": max(maxe) if maxe else 0.0,
        "k": [float(c.k) for c in curves],
        "status": "; ".join(_status_text(r) for r in results),
        "iterations": [int(getattr(r, "iterations", 0)) for r in results],
    }


# ----------------------------------------------------------- the blend core

def edge_end(edge, at_end):
    """(point, direction leaving the edge) at its start or end vertex."""
    if at_end:
        u = edge.LastParameter
        t = edge.tangentAt(u)
    else:
        u = edge.FirstParameter
        t = -edge.tangentAt(u)
    return edge.valueAt(u), App.Vector(t).normalize()


def nearest_ends(e0, e1):
    """(at_end0, at_end1): the pair of ends of two edges closest to each other."""
    best = None
    for a in (False, True):
        for b in (False, True):
            d = (edge_end(e0, a)[0] - edge_end(e1, b)[0]).Length
            if best is None or d < best[0]:
                best = (d, a, b)
    return best[1], best[2]


def blend_core(e0, at_end0, e1, at_end1, plane=None, mode="length", value=0.0):
    """All elastic Hermite curves from the chosen end of e0 to the chosen end of e1.

    The blend leaves e0 in its tangent direction and enters e1 along it. ``mode``
    'length' (value = arc length; 0 = 1.25 x the distance) or 'tension' (value =
    sigma). Returns a dict with 'curves' (sorted by energy, plane coordinates),
    'placement', 'p0', 't0', 'p1', 't1' (plane coordinates). Raises InputProblem.
    """
    el = _el()
    np = _np()
    p0, d0 = edge_end(e0, at_end0)
    p1, d1 = edge_end(e1, at_end1)
    d1 = -d1                       # arriving at e1: pointing into it
    dist = (p1 - p0).Length
    if dist < 1e-9:
        raise InputProblem("the two edge ends coincide: nothing to blend")
    try:
        if plane is None:
            pts = np.array([tuple(p0), tuple(p0 + d0 * dist), tuple(p1), tuple(p1 - d1 * dist)])
            _, frame = el.plane_fit(pts)
            if frame.rms > 1e-6 * max(dist, 1.0):
                raise InputProblem("the two edge ends are not coplanar (tangents included)")
            plane = placement_from_frame(frame)
        loc = to_plane(plane, [p0, p0 + d0, p1, p1 + d1])
        if np.max(np.abs(loc[:, 2])) > 1e-6 * max(dist, 1.0):
            raise InputProblem("the edge ends do not lie in the sketch plane")
        a0, a1 = loc[0, :2], loc[2, :2]
        t0, t1 = loc[1, :2] - a0, loc[3, :2] - a1
        if mode == "tension":
            sols = el.hermite(a0, t0, a1, t1, tension=float(value))
        elif mode == "length":
            L = float(value) if value and value > 0 else 1.25 * dist
            sols = el.hermite(a0, t0, a1, t1, length=L)
        else:
            raise InputProblem(f"unknown mode {mode!r} (length or tension)")
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"Hermite problem failed: {exc}") from None
    if not sols:
        raise InputProblem("no elastic curve joins these ends with this "
                           + ("length" if mode == "length" else "tension"))
    return {"curves": sols, "placement": plane, "p0": a0, "t0": t0, "p1": a1, "t1": t1}


# ----------------------------------------------------------- the comb core

def comb_core(source, subs=(), samples=60, scale=0.0):
    """Teeth of a curvature comb: list of (foot, tip) vector pairs, and the
    envelope points. Elastica features (Fit, Blend) use the library's exact
    curvature; any other edge OpenCASCADE's. ``scale`` 0 = automatic (the longest
    tooth a fifth of the curve's extent)."""
    np = _np()
    feet, normals, kappas = [], [], []
    proxy = getattr(source, "Proxy", None)
    curves = proxy.plane_curves(source) if hasattr(proxy, "plane_curves") else None
    if curves:
        plc = curves[1]
        for c in curves[0]:
            s, xy, theta, kappa = _curve_samples(c, samples)
            for (x, y), th, k in zip(xy, theta, kappa):
                feet.append(plc.multVec(App.Vector(x, y, 0)))
                # the left normal of the tangent (cos th, sin th) in the plane
                normals.append(plc.Rotation.multVec(App.Vector(-math.sin(th), math.cos(th), 0)))
                kappas.append(float(k))
        extent = source.Shape.BoundBox.DiagonalLength
    else:
        shape = getattr(source, "Shape", None)
        if shape is None or shape.isNull():
            raise InputProblem("the comb's source has no geometry")
        edges = [shape.getElement(s) for s in subs if s.startswith("Edge")] if subs else shape.Edges
        if not edges:
            raise InputProblem("the comb's source has no edges")
        for e in edges:
            for u in np.linspace(e.FirstParameter, e.LastParameter, samples):
                k = e.curvatureAt(u)
                feet.append(e.valueAt(u))
                try:
                    n = e.normalAt(u)      # towards the centre of curvature
                except Part.OCCError:
                    n = App.Vector(0, 0, 0)
                normals.append(n)
                kappas.append(float(k))
        extent = shape.BoundBox.DiagonalLength
    kmax = max((abs(k) for k in kappas), default=0.0)
    if scale <= 0:
        scale = 0.2 * extent / kmax if kmax > 0 else 1.0
    tips = [f - n * (k * scale) for f, n, k in zip(feet, normals, kappas)]
    return list(zip(feet, tips)), tips, scale


def _curve_samples(curve, n):
    """(s, xy, theta, kappa) of an elastica from the library."""
    np = _np()
    el = _el()
    if isinstance(curve, el.SmoothElastica):
        s = np.linspace(0.0, curve.length, n)
        return s, curve.points(s), curve.angle(s), curve.curvature(s)
    xy = curve.points()
    kap = curve.curvature()
    d = np.diff(xy, axis=0)
    seg = np.arctan2(d[:, 1], d[:, 0])
    theta = 0.5 * (seg[:-1] + seg[1:])   # vertex direction between its two segments
    return np.arange(1, len(xy) - 1) * curve.h, xy[1:-1], theta, kap


# ----------------------------------------------------------- the elliptic blend core

ELLBLEND_MODES = ["interpolate", "control"]
K_CONVENTIONS = ["modulus", "parameter"]


def gather_vertices(sources):
    """The picked points of an elliptic blend, in selection order, without merging
    coincident ones: sketch vertices or vertices of any shape ('VertexN'), a whole
    sketch (its sketch points), a whole Points object, or a whole shape (its
    vertices). Returns (points: list[App.Vector], plane: the sketch placement when
    all come from one sketch, else None). Raises InputProblem."""
    if not sources:
        raise InputProblem("nothing selected: select four vertices, or a sketch of four points")
    pts, sketches = [], set()
    for obj, subs in sources:
        subs = [s for s in (subs or ()) if s]
        if _is_sketch(obj):
            sketches.add(obj.Name)
            if not subs:
                plc = obj.getGlobalPlacement()
                pts.extend(plc.multVec(g.toShape().Point) for g in obj.Geometry
                           if g.TypeId == "Part::GeomPoint")
                continue
        if obj.isDerivedFrom("Points::Feature") and not subs:
            pts.extend(obj.Placement.multVec(App.Vector(*p)) for p in obj.Points.Points)
            continue
        shape = getattr(obj, "Shape", None)
        if shape is None or shape.isNull():
            raise InputProblem(f"{obj.Label} has no geometry")
        if not subs:
            pts.extend(v.Point for v in shape.Vertexes)
            continue
        for s in subs:
            if not s.startswith("Vertex"):
                raise InputProblem(f"{obj.Label}.{s}: select vertices (points), not {s}")
            try:
                pts.append(shape.getElement(s).Point)
            except (Part.OCCError, ValueError, IndexError):
                raise InputProblem(f"{obj.Label} has no {s}") from None
    plane = None
    if len(sketches) == 1 and all(o.Name in sketches for o, _ in sources):
        plane = next(o for o, _ in sources).getGlobalPlacement()
    return pts, plane


def ellblend_core(points, plane=None, mode="interpolate", k=0.5, d=2.0, tol=1e-3,
                  convention="modulus"):
    """The elliptic blending-function curve (seed 003) of four coplanar 3D points.

    ``mode`` 'interpolate' (the curve passes through the points) or 'control' (they
    are its control points); ``k`` the elliptic modulus, or with ``convention``
    'parameter' m = k^2 (the paper's 'k'); ``d`` the end-derivative parameter.
    Returns a dict with 'curve' (libelastica BlendCurve, plane coordinates),
    'bspline' (certified within ``tol``), 'placement', 'control' (3D control
    points). Raises InputProblem."""
    el = _el()
    np = _np()
    if len(points) != 4:
        raise InputProblem(f"{len(points)} points: an elliptic blend needs exactly four")
    if mode not in ELLBLEND_MODES:
        raise InputProblem(f"unknown mode {mode!r} (interpolate or control)")
    if convention not in K_CONVENTIONS:
        raise InputProblem(f"unknown k convention {convention!r} (modulus or parameter)")
    extent = max((a - b).Length for a in points for b in points)
    for i in range(4):
        for j in range(i + 1, 4):
            if (points[i] - points[j]).Length <= 1e-9 * (1.0 + extent):
                raise InputProblem(f"points {i + 1} and {j + 1} coincide")
    name = "k" if convention == "modulus" else "m"
    if not (math.isfinite(k) and (0.0 <= k < 1.0)):
        raise InputProblem(f"{name} = {k:g}: the elliptic basis needs 0 <= {name} < 1")
    if not (math.isfinite(d) and d > 0):
        raise InputProblem(f"d = {d:g}: the end-derivative parameter must be > 0")
    if not (math.isfinite(tol) and tol > 0):
        raise InputProblem(f"tolerance {tol:g} must be > 0")
    try:
        if plane is not None:
            loc = to_plane(plane, points)
            if np.max(np.abs(loc[:, 2])) > 1e-9 * (1.0 + extent):
                plane = None              # not in the sketch's plane: fit one
        if plane is None:
            xyz = np.array([tuple(p) for p in points], dtype=float)
            _, frame = el.plane_fit(xyz)
            if frame.rms > 1e-6 * (1.0 + extent):
                raise InputProblem(f"the four points are not coplanar (rms distance "
                                   f"{frame.rms:.3g} mm from their best plane)")
            plane = placement_from_frame(frame)
        xy = np.ascontiguousarray(to_plane(plane, points)[:, :2])
        kw = {"k": float(k)} if convention == "modulus" else {"m": float(k)}
        curve = el.blend_curve(xy, d=float(d), mode=mode, **kw)
        bs = curve.to_bspline(float(tol))
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        hint = ""
        if "singular" in str(exc).lower():
            hint = (" (the basis is singular near k = 0.80241, m = 0.64386; in interpolate "
                    "mode the points may be degenerate)")
        raise InputProblem(f"elliptic blend failed: {exc}{hint}") from None
    return {"curve": curve, "bspline": bs, "placement": plane,
            "control": to_3d(plane, curve.q)}


# ----------------------------------------------------------- proxies

def _add(obj, kind, name, group, tip, value=None):
    if name not in obj.PropertiesList:
        obj.addProperty(kind, name, group, tip)
        if value is not None:
            setattr(obj, name, value)


def _add_enum(obj, name, group, tip, values, value=None):
    """An enumeration property; when it has no values yet (new object) they are
    set, and the current one to value (default: the first)."""
    _add(obj, "App::PropertyEnumeration", name, group, tip)
    if not obj.getEnumerationsOfProperty(name):
        setattr(obj, name, list(values))
        if value is not None:
            setattr(obj, name, value)


def _report(obj, msg):
    App.Console.PrintError(f"Elastica {obj.Label}: {msg}\n")
    if "Status" in obj.PropertiesList:
        obj.Status = f"error: {msg}"


class _Proxy:
    """Common state handling: nothing but a version number is pickled; the
    properties hold the rest (so files stay readable without this code).
    Subclasses define setup (properties), compute (raises InputProblem) and
    apply (writes the result); execute reports every failure and keeps the shape."""

    kind = ""

    def __init__(self, obj):
        self._restoring = False
        obj.Proxy = self
        self.setup(obj)

    def execute(self, obj):
        try:
            r = self.compute(obj)
        except InputProblem as exc:
            _report(obj, str(exc))
            return
        except Exception as exc:  # a bug or a kernel error: report it, keep the shape
            _report(obj, f"{type(exc).__name__}: {exc}")
            return
        self.apply(obj, r)

    def __getstate__(self):
        return {"kind": self.kind, "version": VERSION}

    def __setstate__(self, state):
        self._restoring = False
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return self.__setstate__(state)

    def onDocumentRestored(self, obj):
        self._restoring = False
        self.setup(obj)

    def onChanged(self, obj, prop):
        if getattr(self, "_restoring", False) or "Restore" in obj.State:
            return
        self.validate(obj, prop)

    def validate(self, obj, prop):
        """Put a property edited out of range back (the B-spline Tolerance of the
        features that have one; subclasses add theirs)."""
        if prop == "Tolerance" and obj.Tolerance <= 0:
            obj.Tolerance = defaults()[0]

    def setup(self, obj):
        pass


class FitProxy(_Proxy):
    """Elastica fitted to sketch edges / vertices, a Points object, a wire or a CSV file."""

    kind = "Fit"

    def setup(self, obj):
        tol, deg, model = defaults()
        _add(obj, "App::PropertyLinkSubList", "Source", "Input",
             "Sketch edges or vertices, a Points object, or a wire / 3D polyline to fit")
        _add(obj, "App::PropertyFile", "CsvFile", "Input",
             "A CSV / text file of x,y[,z] points, used instead of Source when set")
        _add(obj, "App::PropertyIntegerConstraint", "SamplesPerEdge", "Input",
             "Points sampled on each curved source edge", (60, 4, 10000, 1))
        _add_enum(obj, "Model", "Fit",
                  "discrete: Bobenko-Suris discrete elastica through the (resampled) points; "
                  "smooth: the smooth elastica", ["discrete", "smooth"], model)
        _add(obj, "App::PropertyBool", "SplitAtInflection", "Fit",
             "Fit a keyline as two elasticae, one each side of its inflection (seed 000 §5)",
             False)
        _add(obj, "App::PropertyBool", "PinEnds", "Fit",
             "Pin the curve's start to the first data point (a split keyline always has "
             "both halves pinned at the inflection vertex)", False)
        _add(obj, "App::PropertyFloat", "ResampleStep", "Fit",
             "Equilateral resampling step (mm) before fitting; 0 keeps the points "
             "(a split keyline is always resampled: 0 = 1/100 of its length)", 0.0)
        _add(obj, "App::PropertyFloat", "Tolerance", "BSpline",
             "Largest distance (mm) of the B-spline from the fitted elastica", tol)
        _add(obj, "App::PropertyIntegerConstraint", "Degree", "BSpline",
             "Degree of the B-spline (3 to 7) of a smooth fit; a discrete fit's vertices are "
             "joined by the natural C2 cubic through them", (deg, 3, 7, 1))
        for name, tip in (("Rms", "Root mean square distance of the data from the fit (mm)"),
                          ("MaxError", "Largest distance of the data from the fit (mm)"),
                          ("BSplineDeviation", "Certified distance of the B-spline from the "
                                               "elastica (mm, -1 unknown)")):
            _add(obj, "App::PropertyFloat", name, "Result", tip)
            obj.setEditorMode(name, 1)
        _add(obj, "App::PropertyFloatList", "K", "Result", "Elliptic modulus k of each curve")
        _add(obj, "App::PropertyString", "Status", "Result", "Outcome of the last fit")
        _add(obj, "App::PropertyString", "Curves", "Result",
             "The fitted curves' parameters (JSON, plane coordinates)")
        _add(obj, "App::PropertyPlacement", "Plane", "Result",
             "The plane of the fit (sketch placement or PCA plane)")
        for name in ("K", "Status", "Curves", "Plane"):
            obj.setEditorMode(name, 1)

    def validate(self, obj, prop):
        super().validate(obj, prop)
        if prop == "ResampleStep" and obj.ResampleStep < 0:
            obj.ResampleStep = 0.0

    def compute(self, obj):
        """The fit as a dict (see fit_core); raises InputProblem."""
        pts, plane, ordered, closed = gather_points(obj.Source, obj.CsvFile, obj.SamplesPerEdge)
        return fit_core(pts, plane, ordered, closed, model=obj.Model,
                        split=obj.SplitAtInflection, pin_ends=obj.PinEnds,
                        step=obj.ResampleStep, tol=obj.Tolerance, degree=obj.Degree)

    def apply(self, obj, r):
        edges = [part_bspline(b, r["placement"]).toShape() for b in r["bsplines"]]
        obj.Shape = Part.Wire(edges) if len(edges) > 1 else edges[0]
        obj.Rms = r["rms"]
        obj.MaxError = r["max_error"]
        obj.K = r["k"]
        obj.BSplineDeviation = max(b.max_deviation for b in r["bsplines"])
        obj.Plane = r["placement"]
        from libelastica.io import curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(c) for c in r["curves"]])
        obj.Status = r["status"] or "ok"

    def plane_curves(self, obj):
        """(curves, placement) of the last successful fit, or None."""
        return _stored_curves(obj)


def _stored_curves(obj):
    if not getattr(obj, "Curves", ""):
        return None
    from libelastica.io import curve_from_dict
    try:
        return [curve_from_dict(d) for d in json.loads(obj.Curves)], obj.Plane
    except ValueError:
        return None


class BlendProxy(_Proxy):
    """Elastic Hermite curve between an end of one edge and an end of another."""

    kind = "Blend"

    def setup(self, obj):
        _add(obj, "App::PropertyLinkSub", "Edge1", "Input", "First edge (the blend leaves it)")
        _add(obj, "App::PropertyLinkSub", "Edge2", "Input", "Second edge (the blend enters it)")
        _add(obj, "App::PropertyBool", "AtEnd1", "Input",
             "Leave the first edge at its end vertex (else at its start)", True)
        _add(obj, "App::PropertyBool", "AtEnd2", "Input",
             "Enter the second edge at its end vertex (else at its start)", False)
        for i in (1, 2):
            _add(obj, "App::PropertyInteger", f"SketchGeometry{i}", "Input",
                 f"Index of Edge{i}'s geometry in its sketch (-1: use the edge name); sketch "
                 "edge names change when geometry is added, geometry indices do not", -1)
        _add_enum(obj, "Mode", "Blend",
                  "Solve the Hermite problem for a given arc length or a given tension",
                  ["length", "tension"])
        _add(obj, "App::PropertyFloat", "Length", "Blend",
             "Arc length of the blend (mm); 0 = 1.25 x the distance of the ends", 0.0)
        _add(obj, "App::PropertyFloat", "Tension", "Blend",
             "Tension sigma (1/mm^2; negative = compression)", 0.0)
        _add(obj, "App::PropertyInteger", "Solution", "Blend",
             "Which solution (0 = least bending energy)", 0)
        # a blend is about tangency: the B-spline's end tangents err by about tol / length
        _add(obj, "App::PropertyFloat", "Tolerance", "BSpline",
             "Largest distance (mm) of the B-spline from the elastica",
             min(defaults()[0], 1e-6))
        _add(obj, "App::PropertyIntegerConstraint", "Degree", "BSpline",
             "Degree of the B-spline (3 to 7)", (defaults()[1], 3, 7, 1))
        _add(obj, "App::PropertyFloatList", "Lengths", "Result", "Arc length of every solution")
        _add(obj, "App::PropertyFloatList", "Energies", "Result",
             "Bending energy (integral of kappa^2) of every solution")
        _add(obj, "App::PropertyString", "Status", "Result", "Outcome of the last solve")
        _add(obj, "App::PropertyString", "Curves", "Result",
             "The chosen curve's parameters (JSON, plane coordinates)")
        _add(obj, "App::PropertyPlacement", "Plane", "Result", "The plane of the blend")
        for name in ("Lengths", "Energies", "Status", "Curves", "Plane"):
            obj.setEditorMode(name, 1)

    def validate(self, obj, prop):
        super().validate(obj, prop)
        if prop == "Solution" and obj.Solution < 0:
            obj.Solution = 0

    def compute(self, obj):
        """blend_core's dict for the linked edges; raises InputProblem."""
        ends = []
        for link, gi in ((obj.Edge1, obj.SketchGeometry1), (obj.Edge2, obj.SketchGeometry2)):
            if not link or not link[1] or not link[1][0].startswith("Edge"):
                raise InputProblem("a blend needs two edges")
            ends.append(link_edge(link[0], link[1][0], gi))
        plane = None
        if obj.Edge1[0] == obj.Edge2[0] and _is_sketch(obj.Edge1[0]):
            plane = obj.Edge1[0].getGlobalPlacement()
        value = obj.Length if obj.Mode == "length" else obj.Tension
        return blend_core(ends[0], obj.AtEnd1, ends[1], obj.AtEnd2, plane, obj.Mode, value)

    def apply(self, obj, r):
        curves = r["curves"]
        i = min(max(obj.Solution, 0), len(curves) - 1)
        try:
            bs = curve_bspline(curves[i], obj.Tolerance, obj.Degree)
        except ValueError as exc:
            _report(obj, f"B-spline failed: {exc}")
            return
        obj.Shape = part_bspline(bs, r["placement"]).toShape()
        obj.Lengths = [float(c.length) for c in curves]
        obj.Energies = [float(getattr(c, "energy_value", c.energy())) for c in curves]
        obj.Plane = r["placement"]
        from libelastica.io import curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(curves[i])])
        obj.Status = f"solution {i + 1} of {len(curves)}"

    def plane_curves(self, obj):
        return _stored_curves(obj)


class CombProxy(_Proxy):
    """Curvature comb along a Fit / Blend result or any edges."""

    kind = "Comb"

    def setup(self, obj):
        _add(obj, "App::PropertyLinkSub", "Source", "Comb",
             "An Elastica result, or an object (and optionally its edges)")
        _add(obj, "App::PropertyIntegerConstraint", "Samples", "Comb",
             "Teeth per curve", (60, 3, 5000, 1))
        _add(obj, "App::PropertyFloat", "Scale", "Comb",
             "Tooth length per unit curvature (mm^2); 0 = automatic", 0.0)
        _add(obj, "App::PropertyFloat", "UsedScale", "Result", "The scale actually used")
        _add(obj, "App::PropertyString", "Status", "Result", "Outcome of the last update")
        obj.setEditorMode("UsedScale", 1)
        obj.setEditorMode("Status", 1)

    def compute(self, obj):
        """comb_core's (teeth, tips, scale); raises InputProblem."""
        if not obj.Source:
            raise InputProblem("no source")
        return comb_core(obj.Source[0], obj.Source[1], obj.Samples, obj.Scale)

    def apply(self, obj, r):
        teeth, tips, scale = r
        shapes = [Part.makeLine(a, b) for a, b in teeth if (a - b).Length > 1e-12]
        env = _dedup(tips)
        if len(env) > 1:
            shapes.append(Part.makePolygon(env))
        if not shapes:
            _report(obj, "the source is straight: zero curvature everywhere")
            return
        obj.Shape = Part.makeCompound(shapes)
        obj.UsedScale = scale
        obj.Status = "ok"


class EllipticBlendProxy(_Proxy):
    """Elliptic blending-function curve (seed 003) through / controlled by four points."""

    kind = "EllipticBlend"

    def setup(self, obj):
        _add(obj, "App::PropertyLinkSubList", "Points", "Input",
             "Four coplanar points, in order: vertices of sketches or shapes, or a sketch "
             "holding four sketch points")
        _add_enum(obj, "Mode", "Blend",
                  "interpolate: the curve passes through the four points (chord-length "
                  "parameters); control: the points are its control points", ELLBLEND_MODES)
        _add(obj, "App::PropertyFloat", "K", "Blend",
             "Elliptic modulus k in [0, 1) of the basis {1-t, sn((1-t)K), sn(Kt), t} "
             "(or m = k^2, see KConvention); k = 0 gives sines", 0.5)
        _add_enum(obj, "KConvention", "Blend",
                  "modulus: K is the modulus k; parameter: K is m = k^2 (the paper's "
                  "convention: its rope example 'k = 0.3' is m = 0.3)", K_CONVENTIONS)
        _add(obj, "App::PropertyFloat", "D", "Blend",
             "End-derivative parameter d > 0: the curve leaves q0 with velocity "
             "d (q1 - q0) and ends with d (q3 - q2)", 2.0)
        _add(obj, "App::PropertyFloat", "Tolerance", "BSpline",
             "Largest distance (mm) of the B-spline from the blending curve", defaults()[0])
        _add(obj, "App::PropertyFloat", "BSplineDeviation", "Result",
             "Certified distance of the B-spline from the blending curve (mm)")
        _add(obj, "App::PropertyVectorList", "ControlPoints", "Result",
             "The curve's four control points q0..q3 (global coordinates)")
        _add(obj, "App::PropertyString", "Status", "Result", "Outcome of the last update")
        _add(obj, "App::PropertyPlacement", "Plane", "Result", "The plane of the curve")
        for name in ("BSplineDeviation", "ControlPoints", "Status", "Plane"):
            obj.setEditorMode(name, 1)

    def compute(self, obj):
        """ellblend_core's dict for the linked points; raises InputProblem."""
        pts, plane = gather_vertices(obj.Points)
        return ellblend_core(pts, plane, obj.Mode, obj.K, obj.D, obj.Tolerance, obj.KConvention)

    def apply(self, obj, r):
        obj.Shape = part_bspline(r["bspline"], r["placement"]).toShape()
        obj.BSplineDeviation = float(r["bspline"].max_deviation)
        obj.ControlPoints = r["control"]
        obj.Plane = r["placement"]
        obj.Status = "ok"


# ----------------------------------------------------------- view providers

class ViewProvider:
    """Icon and claimed children; created only when the GUI is up."""

    def __init__(self, vobj, icon_name):
        self.icon_name = icon_name
        vobj.Proxy = self

    def attach(self, vobj):
        self.Object = vobj.Object

    def getIcon(self):
        from . import icon
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
        Gui.Control.closeDialog()
        return True

    def doubleClicked(self, vobj):
        import FreeCADGui as Gui
        Gui.ActiveDocument.setEdit(vobj.Object.Name, 0)
        return True

    def __getstate__(self):
        return {"icon": getattr(self, "icon_name", "elastica")}

    def __setstate__(self, state):
        self.icon_name = (state or {}).get("icon", "elastica")
        return None

    def dumps(self):
        return self.__getstate__()

    def loads(self, state):
        return self.__setstate__(state)


def _view(obj, icon_name, color=None, width=None):
    if App.GuiUp:
        ViewProvider(obj.ViewObject, icon_name)
        if color is not None:
            obj.ViewObject.LineColor = color
        if width is not None:
            obj.ViewObject.LineWidth = width


# ----------------------------------------------------------- makers (what commands record)

def make_fit(doc, sources=(), csv_file="", **props):
    """A new Fit feature in ``doc``; ``sources`` [(obj, [subnames])]; props set Model,
    SplitAtInflection, PinEnds, ResampleStep, Tolerance, Degree."""
    obj = doc.addObject("Part::FeaturePython", "ElasticaFit")
    FitProxy(obj)
    obj.Source = [(o, tuple(s) or ("",)) for o, s in sources]
    obj.CsvFile = csv_file or ""
    for k, v in props.items():
        setattr(obj, k, v)
    _view(obj, "fit", (0.84, 0.15, 0.16), 3.0)
    return obj


def link_edge(obj, name, geo_index=-1):
    """The global edge of a link: a sketch's geometry ``geo_index`` when >= 0 (stable
    when the sketch changes), else ``obj.Shape``'s sub-element ``name``."""
    if _is_sketch(obj) and 0 <= geo_index < len(obj.Geometry):
        e = obj.Geometry[geo_index].toShape()
        e.transformShape(obj.getGlobalPlacement().toMatrix())
        return e
    return obj.Shape.getElement(name)


def make_blend(doc, edge1, edge2, at_end1=None, at_end2=None, **props):
    """A new Blend feature; edge1/edge2 are (obj, 'EdgeN'); ends default to the
    nearest pair."""
    obj = doc.addObject("Part::FeaturePython", "ElasticaBlend")
    BlendProxy(obj)
    obj.Edge1 = (edge1[0], [edge1[1]])
    obj.Edge2 = (edge2[0], [edge2[1]])
    for i, (o, name) in ((1, edge1), (2, edge2)):
        if _is_sketch(o):
            gi = sketch_geo_of_edge(o, name)
            setattr(obj, f"SketchGeometry{i}", -1 if gi is None else gi)
    if at_end1 is None or at_end2 is None:
        a, b = nearest_ends(edge1[0].Shape.getElement(edge1[1]), edge2[0].Shape.getElement(edge2[1]))
        at_end1 = a if at_end1 is None else at_end1
        at_end2 = b if at_end2 is None else at_end2
    obj.AtEnd1, obj.AtEnd2 = bool(at_end1), bool(at_end2)
    for k, v in props.items():
        setattr(obj, k, v)
    _view(obj, "blend", (0.12, 0.47, 0.71), 3.0)
    return obj


def make_comb(doc, source, subs=(), **props):
    """A new curvature comb of ``source`` (optionally of its edges ``subs``)."""
    obj = doc.addObject("Part::FeaturePython", "ElasticaComb")
    CombProxy(obj)
    obj.Source = (source, list(subs))
    for k, v in props.items():
        setattr(obj, k, v)
    _view(obj, "comb", (0.17, 0.63, 0.17), 1.0)
    return obj


def make_ellblend(doc, sources=(), **props):
    """A new elliptic blend curve of four points; ``sources`` [(obj, [subnames])];
    props set Mode, K, KConvention, D, Tolerance."""
    obj = doc.addObject("Part::FeaturePython", "ElasticaEllipticBlend")
    EllipticBlendProxy(obj)
    obj.Points = [(o, tuple(s) or ("",)) for o, s in sources]
    for k, v in props.items():
        setattr(obj, k, v)
    _view(obj, "ellblend", (0.58, 0.40, 0.74), 3.0)
    return obj


def write_to_sketch(feature, sketch, constrain_to=None):
    """Add the feature's B-spline edge(s) to ``sketch`` (mapped into its plane).
    ``constrain_to`` [(geo index, pos), (geo index, pos)] adds endpoint tangency of the
    new curve's start and end to those sketch geometries (blends). Returns the new
    geometry indices."""
    inv = sketch.getGlobalPlacement().inverse()
    ids = []
    for e in feature.Shape.Edges:
        c = e.Curve.copy()
        if not isinstance(c, Part.BSplineCurve):
            c = e.toNurbs().Edges[0].Curve
        c.transform(inv.toMatrix())
        ids.append(sketch.addGeometry(c, False))
    if constrain_to and ids:
        import Sketcher
        (g0, pos0), (g1, pos1) = constrain_to
        first, last = ids[0], ids[-1]
        for g, pos, mine, mypos in ((g0, pos0, first, 1), (g1, pos1, last, 2)):
            try:
                sketch.addConstraint(Sketcher.Constraint("Tangent", g, pos, mine, mypos))
            except Exception as exc:  # the solver may refuse; keep the curve
                App.Console.PrintWarning(f"Elastica: tangency not added ({exc})\n")
                sketch.addConstraint(Sketcher.Constraint("Coincident", g, pos, mine, mypos))
    return ids


def sketch_geo_of_edge(sketch, edge_name):
    """(geometry index, pos 1=start / 2=end lookup helper) of a sketch edge 'EdgeN':
    the index of the sketch geometry whose shape is that edge."""
    edge = sketch.Shape.getElement(edge_name)
    inv = sketch.getGlobalPlacement().inverse()
    mid = inv.multVec(edge.valueAt(0.5 * (edge.FirstParameter + edge.LastParameter)))
    for i, g in enumerate(sketch.Geometry):
        if sketch.getConstruction(i):
            continue
        try:
            if g.toShape().distToShape(Part.Vertex(mid))[0] < 1e-7:
                return i
        except Part.OCCError:
            continue
    return None
