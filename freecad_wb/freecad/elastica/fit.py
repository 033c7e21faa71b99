"""Fit elastica: an elastica (or a keyline split at its inflection into two) fitted
to sketch edges / vertices, a Points object, a wire or 3D polyline (plane fit) or a
CSV file. Its shape is the B-spline of the fitted curve(s); it keeps the fitted
points and their foot points on the curve, which the view provider draws as
markers and residual segments."""
from __future__ import annotations

import dataclasses
import inspect
import json
import math

import FreeCAD as App
import Part

from . import defaults
from .geometry import curve_bspline, el, link_edge, np, part_bspline, plane_coordinates, to_3d
from .proxy import (FeatureProxy, InputProblem, add_enum, add_property, check_degree,
                    check_number, check_tolerance, new_feature, read_only)
from .sources import gather_points

MIN_POINTS = 6          # fewer points cannot determine the 7 (5 shape) parameters of a fit
MODELS = ["discrete", "smooth"]
MODEL_NAMES = {"discrete": "Discrete elastica (Bobenko-Suris)", "smooth": "Smooth elastica"}


def _fit_module():
    """libelastica's fit module (el.fit / el.fit_keyline)."""
    import importlib
    el()
    return importlib.import_module("libelastica.fit")   # the package's `fit` is the function


def has_constraints():
    """True when the library's fit() takes ``constraints=`` (pin end, end tangents)."""
    return "constraints" in inspect.signature(_fit_module().fit).parameters


def _moved(curve, frame2d):
    """The same elastica in the parent coordinates of a (proper, rotation-only)
    Frame2D: the start point mapped, the tangent angle phi turned by the frame's
    angle; nothing else changes under a rigid motion."""
    x0, y0 = frame2d.to_parent(np().array([curve.x0, curve.y0]))
    turn = math.atan2(frame2d.f1[1], frame2d.f1[0])
    return dataclasses.replace(curve, x0=float(x0), y0=float(y0), phi=float(curve.phi + turn))


def _status_text(r):
    st = int(getattr(r, "status", 0))
    if st == 0:
        return "converged"
    from libelastica._ffi import ffi, lib
    return "not converged (best curve kept): " + ffi.string(lib.el_strerror(st)).decode()


def _distances(r, xy):
    """(distances of the points from the curve, their foot points (n, 2), what they
    measure). WIRING(fit API): FitResult.distances / foot_s (point-to-curve, issue 13)
    are used as soon as the library has them; until then the paired model points."""
    n = np()
    d = getattr(r, "distances", None)
    foot_s = getattr(r, "foot_s", None)
    if d is not None and foot_s is not None and isinstance(r.curve, el().SmoothElastica):
        return n.asarray(d, dtype=float), r.curve.points(n.asarray(foot_s)), "point to curve"
    feet = r.model_points()
    if len(feet) != len(xy):       # a fit that pairs other points than these
        from libelastica.report import closest_points
        c = r.curve
        feet = closest_points(xy, c.points(n.linspace(0, c.length, 2000))
                              if isinstance(c, el().SmoothElastica) else c.points())
    return n.linalg.norm(xy - feet, axis=1), feet, "to the paired model points"


def tangent_angle(edge, at, forward, plane):
    """The angle in ``plane`` of ``edge``'s tangent at its end nearest to ``at``,
    signed so it points along ``forward`` (a plane vector)."""
    n = np()
    a, b = edge.FirstParameter, edge.LastParameter
    u = a if (edge.valueAt(a) - at).Length <= (edge.valueAt(b) - at).Length else b
    t = plane.Rotation.inverted().multVec(App.Vector(edge.tangentAt(u)))
    if math.hypot(t.x, t.y) < 1e-9 * max(t.Length, 1e-300):
        raise InputProblem("the tangent edge is perpendicular to the fit plane")
    if t.x * forward[0] + t.y * forward[1] < 0:
        t = -t
    return float(n.arctan2(t.y, t.x))


def fit_core(points, plane=None, ordered=True, closed=False, model="discrete", split=False,
             pin_start=False, pin_end=False, start_edge=None, end_edge=None, step=0.0,
             tol=1e-3, degree=3):
    """Fit elastica(e) to 3D points. ``start_edge`` / ``end_edge``: Part edges whose
    tangents the curve's ends follow. Returns a dict: 'curves' (plane coordinates),
    'results', 'bsplines', 'placement', 'data' (the fitted points, plane
    coordinates), 'feet' (their points on the curve), 'distances', 'measure',
    'rms', 'max_error', 'k', 'status'. Raises InputProblem with a user message."""
    n = np()
    if model not in MODELS:
        raise InputProblem(f"unknown model {model!r} (discrete or smooth)")
    if closed:
        raise InputProblem("the input is a closed curve: an elastica fit needs an open one")
    if len(points) < MIN_POINTS:
        raise InputProblem(f"{len(points)} points: a fit needs at least {MIN_POINTS}")
    step = check_number("Resampling step", step, 0.0, None, "mm")
    tol = check_tolerance(tol)
    if model == "smooth":
        degree = check_degree(degree)
    fm = _fit_module()
    try:
        xy, plane = plane_coordinates(points, plane, flat=None)
        if not ordered:
            xn, _ = el().pca_normalize(xy)
            xy = n.ascontiguousarray(xy[n.argsort(xn[:, 0], kind="stable")])
        if split:
            kf = fm.fit_keyline(xy, r=step if step > 0 else None, model=model)
            results = [kf.first, kf.second]
            # the sides are fitted in the re-normalised x''y'' frame: back to the plane
            to_plane_xy = kf.prepared.frame2d.to_parent
            curves = [_moved(r.curve, kf.prepared.frame2d) for r in results]
            poly, i = kf.prepared.polygon, kf.inflection
            measured = [_distances(r, side) for r, side in zip(results, (poly[i::-1], poly[i:]))]
            datas = [to_plane_xy(poly[i::-1]), to_plane_xy(poly[i:])]
            feet = [to_plane_xy(m[1]) for m in measured]
            dists = [m[0] for m in measured]
            measure = measured[0][2]
        else:
            fixed = {}
            if step > 0:
                xy = el().resample_equilateral(xy, step)
                if model == "discrete":
                    fixed["h"] = step            # the polygon's segment (seed 000 §5.4)
            if len(xy) < MIN_POINTS:
                raise InputProblem(f"resampling leaves {len(xy)} points; a fit needs "
                                   f"{MIN_POINTS}: use a smaller step")
            if pin_start:
                fixed.update(x0=float(xy[0][0]), y0=float(xy[0][1]))
            constraints = {}
            if pin_end:
                constraints["end_point"] = (float(xy[-1][0]), float(xy[-1][1]))
            if start_edge is not None:
                constraints["start_tangent"] = tangent_angle(start_edge, points[0],
                                                             xy[1] - xy[0], plane)
            if end_edge is not None:
                constraints["end_tangent"] = tangent_angle(end_edge, points[-1],
                                                           xy[-1] - xy[-2], plane)
            kw = {}
            if constraints:
                # WIRING(fit API): el.fit(..., constraints={...}) of issue 13; this build
                # gets it as soon as the library's fit() takes the argument
                if not has_constraints():
                    raise InputProblem("pinning the end and end tangents need the fit "
                                       "library's constraints, which this libelastica lacks")
                kw["constraints"] = constraints
            results = [fm.fit(xy, model=model, fixed=fixed or None, **kw)]
            curves = [r.curve for r in results]
            d, f, measure = _distances(results[0], xy)
            datas, feet, dists = [xy], [f], [d]
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
    dist = n.concatenate(dists)
    if not n.all(n.isfinite(dist)):
        raise InputProblem("fit failed: non-finite error")
    return {
        "curves": curves, "results": results, "bsplines": bsplines, "placement": plane,
        "data": n.vstack(datas), "feet": n.vstack(feet), "distances": dist, "measure": measure,
        "rms": float(n.sqrt(n.mean(dist ** 2))), "max_error": float(dist.max()),
        "k": [float(c.k) for c in curves],
        "status": "; ".join(_status_text(r) for r in results),
    }


class FitProxy(FeatureProxy):
    """Elastica fitted to sketch edges / vertices, a Points object, a wire or a CSV file."""

    kind = "Fit"

    def setup(self, obj):
        tol, deg, model = defaults()
        add_property(obj, "App::PropertyLinkSubList", "Source", "Input",
                     "Sketch edges or vertices, a Points object, or a wire / 3D polyline to fit")
        add_property(obj, "App::PropertyFile", "CsvFile", "Input",
                     "A CSV / text file of x,y[,z] points (mm), used instead of Source when set")
        add_property(obj, "App::PropertyInteger", "SamplesPerEdge", "Input",
                     "Points sampled on each curved source edge (4 to 10000)", 60)
        add_enum(obj, "Model", "Fit",
                 "discrete: Bobenko-Suris discrete elastica through the (resampled) points; "
                 "smooth: the smooth elastica", MODELS, model)
        add_property(obj, "App::PropertyBool", "SplitAtInflection", "Fit",
                     "Fit a keyline as two elasticae, one each side of its inflection (seed 000 "
                     "§5); both halves start at the inflection", False)
        add_property(obj, "App::PropertyBool", "PinStart", "Fit",
                     "The curve starts exactly at the first data point (one-piece fits)",
                     bool(getattr(obj, "PinEnds", False)))
        add_property(obj, "App::PropertyBool", "PinEnd", "Fit",
                     "The curve ends exactly at the last data point (one-piece fits)", False)
        add_property(obj, "App::PropertyLinkSub", "StartTangent", "Fit",
                     "An edge whose tangent at its end nearest the data's start the curve "
                     "follows there (one-piece fits; empty: free)")
        add_property(obj, "App::PropertyLinkSub", "EndTangent", "Fit",
                     "An edge whose tangent at its end nearest the data's end the curve "
                     "follows there (one-piece fits; empty: free)")
        if "PinEnds" in obj.PropertiesList:            # documents of version 1
            obj.removeProperty("PinEnds")
        add_property(obj, "App::PropertyFloat", "ResampleStep", "Fit",
                     "Equilateral resampling step (mm) before fitting; 0 keeps the points "
                     "(a split keyline is always resampled: 0 = 1/100 of its length)", 0.0)
        add_property(obj, "App::PropertyFloat", "Tolerance", "BSpline",
                     "Largest distance (mm) of the B-spline from the fitted smooth elastica", tol)
        add_property(obj, "App::PropertyInteger", "Degree", "BSpline",
                     "Degree of the B-spline (3 to 7) of a smooth fit; a discrete fit's vertices "
                     "are joined by the natural C2 cubic through them", deg)
        for name, tip in (("Rms", "Root mean square distance of the data from the fit (mm)"),
                          ("MaxError", "Largest distance of the data from the fit (mm)"),
                          ("BSplineDeviation", "Certified distance of the B-spline from the "
                                               "smooth elastica (mm; -1 for a discrete fit, "
                                               "whose B-spline passes through its vertices)")):
            add_property(obj, "App::PropertyFloat", name, "Result", tip)
        add_property(obj, "App::PropertyFloatList", "K", "Result", "Elliptic modulus k of each curve")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last fit")
        add_property(obj, "App::PropertyString", "ErrorMeasure", "Result",
                     "What Rms and MaxError measure")
        add_property(obj, "App::PropertyString", "Curves", "Result",
                     "The fitted curves' parameters (JSON, plane coordinates)")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result",
                     "The plane of the fit (sketch placement or PCA plane)")
        add_property(obj, "App::PropertyVectorList", "DataPoints", "Result",
                     "The fitted points (after resampling), global coordinates")
        add_property(obj, "App::PropertyVectorList", "FootPoints", "Result",
                     "The curve point each data point was measured to, global coordinates")
        read_only(obj, "Rms", "MaxError", "BSplineDeviation", "K", "Status", "ErrorMeasure",
                  "Curves", "Plane", "DataPoints", "FootPoints")

    def compute(self, obj):
        """The fit as a dict (see fit_core); raises InputProblem."""
        if not 4 <= obj.SamplesPerEdge <= 10000:
            raise InputProblem(f"SamplesPerEdge = {obj.SamplesPerEdge} is not usable: 4 to 10000")
        pts, plane, ordered, closed = gather_points(obj.Source, obj.CsvFile, obj.SamplesPerEdge)
        ends = []
        for link in (obj.StartTangent, obj.EndTangent):
            ends.append(None)
            if link and link[1] and link[1][0]:
                ends[-1] = link_edge(link[0], link[1][0])
        one_piece_only = obj.PinEnd or obj.PinStart or any(e is not None for e in ends)
        if obj.SplitAtInflection and one_piece_only:
            raise InputProblem("pin start / pin end / end tangents apply to one-piece fits; a "
                               "split keyline's halves both start at the inflection")
        return fit_core(pts, plane, ordered, closed, model=obj.Model,
                        split=obj.SplitAtInflection, pin_start=obj.PinStart, pin_end=obj.PinEnd,
                        start_edge=ends[0], end_edge=ends[1], step=obj.ResampleStep,
                        tol=obj.Tolerance, degree=obj.Degree)

    def apply(self, obj, r):
        plc = r["placement"]
        edges = [part_bspline(b, plc).toShape() for b in r["bsplines"]]
        obj.Shape = Part.Wire(edges) if len(edges) > 1 else edges[0]
        obj.Rms = r["rms"]
        obj.MaxError = r["max_error"]
        obj.ErrorMeasure = r["measure"]
        obj.K = r["k"]
        devs = [b.max_deviation for b in r["bsplines"]]
        obj.BSplineDeviation = max(devs) if min(devs) >= 0 else -1.0
        obj.Plane = plc
        obj.DataPoints = to_3d(plc, r["data"])
        obj.FootPoints = to_3d(plc, r["feet"])
        from libelastica.io import curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(c) for c in r["curves"]])
        obj.Status = r["status"] or "ok"

    def plane_curves(self, obj):
        """(curves, placement) of the last successful fit, or None."""
        return stored_curves(obj)


def stored_curves(obj):
    """(curves, plane) from a feature's Curves JSON, or None."""
    if not getattr(obj, "Curves", ""):
        return None
    from libelastica.io import curve_from_dict
    try:
        return [curve_from_dict(d) for d in json.loads(obj.Curves)], obj.Plane
    except ValueError:
        return None


def make(doc, sources=(), csv_file="", **props):
    """A new Fit feature in ``doc``; ``sources`` [(obj, [subnames])]; props set Model,
    SplitAtInflection, PinStart, PinEnd, ResampleStep, Tolerance, Degree, ..."""
    if "PinEnds" in props:                       # the version-1 name (recorded macros)
        props["PinStart"] = props.pop("PinEnds")
    return new_feature(doc, "ElasticaFit", FitProxy,
                       Source=[(o, tuple(s) or ("",)) for o, s in sources],
                       CsvFile=csv_file or "", **props)


__all__ = ["FitProxy", "fit_core", "make", "stored_curves", "has_constraints", "MODELS",
           "MODEL_NAMES"]
