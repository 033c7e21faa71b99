"""Elliptic blend curve (seed 003): the curve with Jacobi elliptic blending functions
{1-t, sn((1-t)K), sn(Kt), t} through four picked coplanar points (or with them as
control points), through three or more as the C1 composite (open or closed), as a
certified B-spline.

The basis is not always a partition of unity with positive functions: from about
m = k^2 = 0.6 (d = 2) a blending function goes negative, the curve can leave the
convex hull of its control points and moves further than they do (the Lebesgue
factor), and near K(k) = 2 the system defining the basis is ill-conditioned; through
the points, the collocation system can put the control points far away (Spread) and
the curve swings wide. The feature keeps those figures (BasisMin, Lebesgue,
Condition, ConvexHull, Spread), words them in Warnings, and says them once in the
report view when they change."""
from __future__ import annotations

import math

import FreeCAD as App

from . import defaults
from .containers import set_shape
from .geometry import binding_module, el, ends_meet, np, part_bspline, plane_coordinates, to_3d
from .links import followed_reader
from .proxy import (FeatureProxy, InputProblem, add_enum, add_geometry_index, add_length, add_link,
                    add_property, check_number, check_tolerance, new_feature, read_only, set_said,
                    source_list)
from .sources import gather_vertices
from .units import exact_mark, say

MODES = ["interpolate", "control"]
K_CONVENTIONS = ["modulus", "parameter"]
D_THROUGH = 2.0     # the d of a blend through the points: the curve does not depend on it


def _check_points(points, mode, closed):
    """InputProblem unless the points make a blend: four (one segment); through the points
    (interpolate) three or more, the C1 composite (closed: back to the first, a repeated
    first point at the end dropped); control points 3 n + 1 (n segments)."""
    n = len(points)
    if mode == "control" and (n < 4 or (n - 1) % 3):
        raise InputProblem(f"{n} control points: a blend of n segments has 3 n + 1 (4, 7, "
                           "10, ...); through the points (Mode interpolate) any number >= 3")
    if n < 3:
        raise InputProblem(f"{n} point{'' if n == 1 else 's'}: an elliptic blend passes "
                           "through three or more")
    extent = max((a - b).Length for a in points for b in points)
    if n == 4 and not closed:
        pairs = [(i, j) for i in range(4) for j in range(i + 1, 4)]
    else:       # the composite: consecutive points (closed: the repeated first one dropped)
        if closed and ends_meet(points):
            points = points[:-1]
        pairs = [(i, i + 1) for i in range(len(points) - 1)] + (
            [(0, len(points) - 1)] if closed else [])
    for i, j in pairs:
        if (points[i] - points[j]).Length <= 1e-9 * (1.0 + extent):
            closing = (i, j) == (0, n - 1) and not closed
            raise InputProblem(f"points {i + 1} and {j + 1} coincide" + (
                ": an open curve cannot close on itself smoothly (its ends would meet "
                "at a corner): set Closed" if closing else ""))
    if closed and len(points) < 3:
        raise InputProblem("Closed: a closed blend passes through three or more distinct points")
    return points


def ellblend_core(points, plane=None, mode="interpolate", k=0.5, d=2.0, tol=1e-3,
                  convention="modulus", closed=False):
    """The elliptic blending-function curve of coplanar 3D points: four make one
    segment; through the points (``mode`` 'interpolate') three or more make the C1
    composite, ``closed`` back to the first (seed 003 §2.4: libelastica's blend_curve).

    ``mode`` 'interpolate' (the curve passes through the points) or 'control' (they
    are its control points: 3 n + 1 for n segments; ``closed`` not used); ``k`` the
    elliptic modulus, or with ``convention`` 'parameter' m = k^2 (the paper's 'k'); ``d``
    the end-derivative
    parameter, control points only: through the points d scales the inner control
    points and not the curve, so the basis of d = 2 is used and described.
    Returns a dict with 'curve' (libelastica BlendCurve, plane coordinates),
    'bspline' (certified within ``tol``), 'placement', 'control' (3D control
    points), 'spread' (control points' diameter / points', 1 for control points:
    BlendCurve.spread, warned above libelastica's SPREAD_MAX), 'warnings' (the basis'
    and the interpolation's, in words: BlendCurve.warnings). Raises InputProblem."""
    if mode not in MODES:
        raise InputProblem(f"unknown mode {mode!r} (interpolate or control)")
    if convention not in K_CONVENTIONS:
        raise InputProblem(f"unknown k convention {convention!r} (modulus or parameter)")
    closed = bool(closed) and mode == "interpolate"   # control points shape their own seam
    points = _check_points(list(points), mode, closed)
    name = "k" if convention == "modulus" else "m"
    if not (math.isfinite(k) and (0.0 <= k < 1.0)):
        raise InputProblem(f"{name} = {k:g}: the elliptic basis needs 0 <= {name} < 1")
    if mode == "control":
        d = check_number("d", d, 0.0, None, lo_open=True, why="the end-derivative parameter")
    else:       # not used through the points: the default's basis (QA17 P4)
        d = D_THROUGH
    tol = check_tolerance(tol)
    try:
        xy, plane = plane_coordinates(points, plane, flat=1e-6, what="points")
        kw = {"k": float(k)} if convention == "modulus" else {"m": float(k)}
        # in curve.warnings(), said once by the feature (this thread's only: _quiet.py)
        with binding_module("_quiet").quiet(el().ConditionWarning, el().BlendLoopWarning):
            curve = el().blend_curve(np().ascontiguousarray(xy), d=float(d), mode=mode,
                                     closed=bool(closed), **kw)
        bs = curve.to_bspline(float(tol))
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        hint = ""
        if "singular" in str(exc).lower() and "K(k) = 2" not in str(exc):
            hint = " (in interpolate mode: the points may be degenerate)"
        raise InputProblem(f"elliptic blend failed: {exc}{hint}") from None
    return {"curve": curve, "bspline": bs, "placement": plane,
            "control": to_3d(plane, curve.q), "spread": curve.spread(),
            "warnings": curve.warnings(length=exact_mark)}     # said by units.say


class EllipticBlendProxy(FeatureProxy):
    """Elliptic blending-function curve (seed 003) through / controlled by picked points."""

    kind = "EllipticBlend"
    followed_links = {"Points": "PointsGeometry"}

    def setup(self, obj):
        add_link(obj, "App::PropertyLinkSubList", "Points", "Input",
                 "Coplanar points, in order: vertices of sketches or shapes, or a sketch "
                 "holding sketch points. Four make one segment; through the points, three or "
                 "more make a C1 chain of segments; control points: 3 n + 1 for n segments")
        add_geometry_index(obj, "PointsGeometry", "Points")
        add_enum(obj, "Mode", "Blend",
                 "interpolate: the curve passes through the points (chord-length "
                 "parameters); control: the points are its control points", MODES)
        add_property(obj, "App::PropertyBool", "Closed", "Blend",
                     "Through the points (interpolate): the curve closes back to the first "
                     "point, smooth (C1) there too; a repeated first point at the end is "
                     "dropped", False)
        add_property(obj, "App::PropertyFloat", "K", "Blend",
                     "Elliptic modulus k in [0, 1) of the basis {1-t, sn((1-t)K), sn(Kt), t} "
                     "(or m = k^2, see KConvention); k = 0 gives sines", 0.5)
        add_enum(obj, "KConvention", "Blend",
                 "modulus: K is the modulus k; parameter: K is m = k^2 (the paper's "
                 "convention: its rope example 'k = 0.3' is m = 0.3)", K_CONVENTIONS)
        add_property(obj, "App::PropertyFloat", "D", "Blend",
                     "End-derivative parameter d > 0: the curve leaves q0 with velocity "
                     "d (q1 - q0) and ends with d (q3 - q2). Control points only: through the "
                     "points the curve does not depend on d (read-only there)", 2.0)
        add_length(obj, "Tolerance", "BSpline",
                   "Largest distance of the B-spline from the blending curve", defaults()[0])
        add_property(obj, "App::PropertyFloat", "BSplineDeviation", "Result",
                     "Certified distance of the B-spline from the blending curve (mm)")
        add_property(obj, "App::PropertyVectorList", "ControlPoints", "Result",
                     "The curve's control points q0..q3 (global coordinates; 3 n + 1 for n "
                     "segments)")
        add_property(obj, "App::PropertyFloat", "BasisMin", "Result",
                     "Smallest value of a blending function on [0, 1]: negative, the curve can "
                     "leave the convex hull of its control points")
        add_property(obj, "App::PropertyBool", "ConvexHull", "Result",
                     "Every blending function is >= 0: the curve stays inside the convex hull "
                     "of its control points")
        add_property(obj, "App::PropertyFloat", "Lebesgue", "Result",
                     "Largest sum of |blending functions| (1 with the convex hull): a curve "
                     "point moves at most this many times as far as a control point")
        add_property(obj, "App::PropertyFloat", "Condition", "Result",
                     "Condition number of the system (2.17) that defines the basis (bases above "
                     "1000, k near 0.80241, are refused)")
        add_property(obj, "App::PropertyFloat", "Spread", "Result",
                     "Through the points: how many times as far apart as the points the "
                     f"control points lie (over {el().SPREAD_MAX:g}: ill-conditioned); 1 for "
                     "control points")
        add_property(obj, "App::PropertyStringList", "Warnings", "Result",
                     "What the designer should know about this basis (empty: none)")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last update")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result", "The plane of the curve")
        read_only(obj, "BSplineDeviation", "ControlPoints", "BasisMin", "ConvexHull", "Lebesgue",
                  "Condition", "Spread", "Warnings", "Status", "Plane")
        self.mode_editors(obj)

    @staticmethod
    def mode_editors(obj):
        """D (control points only) and Closed (through the points only) read-only in the
        property editor where the Mode does not use them, as the panel greys them out."""
        through = obj.Mode == "interpolate"
        obj.setEditorMode("D", 1 if through else 0)
        obj.setEditorMode("Closed", 0 if through else 1)

    def onChanged(self, obj, prop):
        super().onChanged(obj, prop)
        if prop == "Mode" and "Closed" in obj.PropertiesList:
            self.mode_editors(obj)

    def compute(self, obj):
        """ellblend_core's dict for the linked points; raises InputProblem."""
        element = followed_reader(obj, "Points")      # renames Points: read it after
        pts, plane = gather_vertices(obj.Points, link="Points", element=element)
        return self.handed(ellblend_core, pts, plane, obj.Mode, obj.K, obj.D,
                           float(obj.Tolerance), obj.KConvention, obj.Closed)

    def apply(self, obj, r):
        set_shape(obj, part_bspline(r["bspline"], r["placement"]).toShape())
        obj.BSplineDeviation = float(r["bspline"].max_deviation)
        obj.ControlPoints = r["control"]
        obj.Plane = r["placement"]
        basis = r["curve"].basis
        obj.BasisMin = float(basis.basis_min)
        obj.ConvexHull = bool(basis.convex_hull)
        obj.Lebesgue = float(basis.lebesgue)
        obj.Condition = float(basis.condition)
        obj.Spread = float(r["spread"])
        warnings = r["warnings"]                # lengths marked: said again by a panel
        if say(warnings) != list(obj.Warnings):
            # once per change of the warnings, not on every recompute of the same basis
            for w in say(warnings):
                App.Console.PrintWarning(f"Elastica {obj.Label}: {w}\n")
        set_said(obj, "Warnings", warnings)
        set_said(obj, "Status", "; ".join(["ok"] + [f"warning: {w}" for w in warnings]))


def make(doc, sources=(), **props):
    """A new elliptic blend curve of picked points; ``sources`` [(obj, [subnames])];
    props set Mode, Closed, K, KConvention, D, Tolerance."""
    return new_feature(doc, "ElasticaEllipticBlend", EllipticBlendProxy,
                       Points=source_list(sources), **props)


__all__ = ["EllipticBlendProxy", "ellblend_core", "make", "MODES", "K_CONVENTIONS"]
