"""Fit elastica: an elastica, or a keyline as one G2 curve of two elasticae meeting at
its inflection, fitted to sketch edges / vertices, a Points object, a wire or 3D
polyline (plane fit) or a CSV file, with optional end conditions (pinned ends, end
tangents from picked edges, end curvatures). Its shape is ONE B-spline of the fitted
curve; it keeps the fitted points, their point-to-curve distances and their feet on
the curve, which the view provider draws as markers and residual segments. The feature
is here; the fit itself in fit_core.py (its end conditions: fit_ends.py, its B-spline:
fit_shape.py)."""
from __future__ import annotations

import json
import os

import FreeCAD as App

from . import defaults
from .containers import set_shape
from .fit_core import DISTANCES, MODELS, fit_gathered
from .fit_ends import CONTINUITIES
from .geometry import binding_module, el, part_bspline, to_3d
from .links import followed_edge, followed_reader
from .proxy import (FeatureProxy, InputProblem, add_edge_end, add_enum, add_geometry_index,
                    add_length, add_link, add_property, edge_end_choice, new_feature, read_only,
                    set_said, source_list)
from .sources import THOUSANDS, gather_points
from .units import say


class FitProxy(FeatureProxy):
    """Elastica fitted to sketch edges / vertices, a Points object, a wire or a CSV file."""

    kind = "Fit"
    followed_links = {"Source": "SourceGeometry", "StartTangent": "StartTangentGeometry",
                      "EndTangent": "EndTangentGeometry"}

    def setup(self, obj):
        tol, deg, model = defaults()
        add_link(obj, "App::PropertyLinkSubList", "Source", "Input",
                 "Sketch edges or vertices, a Points object, or a wire / 3D polyline to fit")
        add_property(obj, "App::PropertyFile", "CsvFile", "Input",
                     "A CSV / text file of x,y[,z] points (mm, or the unit its header names: "
                     "x [m],y [m]), used instead of Source when set; "
                     "read again at a recompute once it changed on disk (its modification "
                     "time or size)")
        if "CsvStamp" not in obj.PropertiesList:     # hidden output: setting it touches nothing
            obj.addProperty("App::PropertyString", "CsvStamp", "Input", "The CSV file's "
                            "modification time (ns) and size when it was last read", 4 | 8)
        if "CsvUnit" not in obj.PropertiesList:
            obj.addProperty("App::PropertyString", "CsvUnit", "Input", "The unit the CSV "
                            "file's header named when it was last read ('' none; '?' not "
                            "known: a document saved before it, which read every file as mm)",
                            4 | 8)
            obj.CsvUnit = "?" if getattr(self, "_restoring", False) else ""
        add_enum(obj, "Thousands", "Input",
                 "How CsvFile groups thousands, as the command line's --thousands: auto = "
                 "what the file shows (';' and tab separated files of decimal-comma locales: "
                 "1.250,5 or 980;1.000 group by '.'; a file that does not show it is "
                 "refused); . = '.' groups thousands (1.250 is 1250); none = '.' is a decimal "
                 "point, ',' a decimal comma (1.250 and 1,250 are 1.25); , = ',' groups "
                 "thousands, '.' the decimal point (English #,##0: 1,250.5 is 1250.5)",
                 list(THOUSANDS), "auto")
        if obj.getEnumerationsOfProperty("Thousands") != list(THOUSANDS):
            kept = obj.Thousands      # an older file's list, without ',': the choice kept
            obj.Thousands = list(THOUSANDS)
            obj.Thousands = kept
        add_property(obj, "App::PropertyInteger", "SamplesPerEdge", "Input",
                     "Points sampled on each curved source edge (4 to 10000)", 60)
        add_enum(obj, "Model", "Fit",
                 "discrete: Bobenko-Suris discrete elastica through the (resampled) points; "
                 "smooth: the smooth elastica", MODELS, model)
        add_enum(obj, "Distance", "Fit",
                 "What a smooth one-piece fit minimises: orthogonal = each point's distance "
                 "to the curve (any spacing); paired = point i against arc length i L/(n-1), "
                 "for equilateral data (e.g. resampled). A discrete fit minimises the distance "
                 "to its polygon on unevenly spaced points and pairs point i with vertex i on "
                 "equally spaced ones; rms and max error are point-to-curve distances either way",
                 DISTANCES, "orthogonal")
        add_property(obj, "App::PropertyBool", "SplitAtInflection", "Fit",
                     "Fit a keyline as one G2 curve of two elasticae meeting at its inflection "
                     "(seed 000 §5: same point, tangent and zero curvature there); free ends",
                     False)
        add_property(obj, "App::PropertyBool", "PinStart", "Fit",
                     "The curve starts exactly at the first data point (one-piece fits)",
                     bool(getattr(obj, "PinEnds", False)))
        add_property(obj, "App::PropertyBool", "PinEnd", "Fit",
                     "The curve ends exactly at the last data point (one-piece fits)", False)
        add_link(obj, "App::PropertyLinkSub", "StartTangent", "Fit",
                 "An edge whose tangent (at the end StartTangentAt says: nearest = its end "
                 "nearest the data's start; projected into the fit plane) the curve follows "
                 "there (one-piece fits; empty: free)")
        add_link(obj, "App::PropertyLinkSub", "EndTangent", "Fit",
                 "An edge whose tangent (at the end EndTangentAt says: nearest = its end "
                 "nearest the data's end; projected into the fit plane) the curve follows "
                 "there (one-piece fits; empty: free)")
        for link, index in self.followed_links.items():
            add_geometry_index(obj, index, link)
        for link in ("StartTangent", "EndTangent"):
            add_edge_end(obj, f"{link}At", "Fit", link)
        for where in ("Start", "End"):
            add_enum(obj, f"{where}Continuity", "Fit",
                     f"How the curve meets its {where}Tangent edge: tangent = follows its "
                     f"tangent (at the end nearest the data's {where.lower()}); G1 = joins "
                     "the edge there (starts at that end, in the fit plane, with its tangent); "
                     "G2 = and its curvature", CONTINUITIES, "tangent")
            add_property(obj, "App::PropertyBool", f"Use{where}Curvature", "Fit",
                         f"Hold the curve's curvature at its {where.lower()} at "
                         f"{where}Curvature (one-piece fits)", False)
            add_property(obj, "App::PropertyFloat", f"{where}Curvature", "Fit",
                         f"Curvature (1/mm) at the curve's {where.lower()} when "
                         f"Use{where}Curvature: 0 = a free end or an inflection; + turns left "
                         "seen from the fit plane's normal (a sketch's normal)", 0.0)
        if "PinEnds" in obj.PropertiesList:            # documents of version 1
            obj.removeProperty("PinEnds")
        add_length(obj, "ResampleStep", "Fit",
                   "Equilateral resampling step before fitting; 0 keeps the points. A "
                   "split keyline: the step of its preparation (0 = the polyline through the "
                   "medians of runs of the points, cut into 100 segments: scan noise does "
                   "not lengthen it); the discrete one fits that polygon, the smooth one the "
                   "points themselves", 0.0)
        add_length(obj, "Tolerance", "BSpline",
                   "Largest distance of the B-spline from the fitted smooth elastica", tol)
        add_property(obj, "App::PropertyInteger", "Degree", "BSpline",
                     "Degree of the B-spline (3 to 7) of a smooth fit; a discrete fit's vertices "
                     "are joined by the C2 cubic through them (natural at free ends)", deg)
        for name, tip in (("Rms", "Root mean square distance of the points given (never "
                                  "resampled ones) from the curve, in 3D (mm; see ErrorMeasure)"),
                          ("MaxError", "Largest distance of a point given from the curve, in "
                                       "3D (mm)"),
                          ("BSplineDeviation", "Certified distance of the B-spline from the "
                                               "smooth elastica (mm); of a discrete fit's cubic "
                                               "through the vertices, its largest distance from "
                                               "the polygon (sampled)")):
            add_property(obj, "App::PropertyFloat", name, "Result", tip)
        add_property(obj, "App::PropertyFloat", "FreeRms", "Result",
                     "Rms of the same fit with free ends (mm; -1 without end conditions, or "
                     "when that fit fails): what the end conditions cost")
        add_property(obj, "App::PropertyStringList", "Warnings", "Result",
                     "What the designer should know about this fit (empty: none)")
        add_property(obj, "App::PropertyFloatList", "K", "Result", "Elliptic modulus k of each curve")
        add_property(obj, "App::PropertyFloatList", "EndCurvatures", "Result",
                     "Curvature (1/mm) of the shape at its start and end, + turning left seen "
                     "from the fit plane's normal (a G2 join's: its edge's)")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last fit")
        add_property(obj, "App::PropertyString", "ErrorMeasure", "Result",
                     "What Rms and MaxError measure")
        add_property(obj, "App::PropertyFloatList", "Distances", "Result",
                     "Signed distance (mm) of each fitted point from the curve, + = left of it "
                     "seen from the fit plane's normal, in the order of DataPoints (the fit's, "
                     "along the curve; PointNumbers: each one's number in the order given)")
        add_property(obj, "App::PropertyString", "Curves", "Result",
                     "The fitted curves' parameters (JSON, plane coordinates); a split "
                     "keyline's two halves each run from the joint")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result",
                     "The plane of the fit (sketch placement or PCA plane)")
        add_property(obj, "App::PropertyVectorList", "DataPoints", "Result",
                     "The points given (never the resampled ones), global coordinates, in the "
                     "order fitted: along the curve from its start, which is not the order given "
                     "where a sketch's points or a file's rows lie otherwise (PointNumbers)")
        add_property(obj, "App::PropertyIntegerList", "PointNumbers", "Result",
                     "For each of DataPoints (and Distances, FootPoints), its number in the "
                     "order given, from 1: a sketch's points as drawn, a file's rows, vertices "
                     "as picked (1, 2, 3, ... where the fit kept that order; empty until the "
                     "first recompute of a document saved before it)")
        add_property(obj, "App::PropertyVectorList", "FootPoints", "Result",
                     "Each data point's nearest point on the curve (its polygon for a discrete "
                     "fit), global coordinates")
        read_only(obj, "Rms", "MaxError", "BSplineDeviation", "FreeRms", "Warnings", "K",
                  "EndCurvatures", "Status",
                  "ErrorMeasure",
                  "Distances", "Curves", "Plane", "DataPoints", "FootPoints", "PointNumbers")

    def compute(self, obj):
        """The fit as a dict (see fit_core); raises InputProblem."""
        if not 4 <= obj.SamplesPerEdge <= 10000:
            raise InputProblem(f"SamplesPerEdge = {obj.SamplesPerEdge} is not usable: 4 to 10000")
        # renames Source: read it after; a CSV file is read instead of Source, not its geometry
        element = None if obj.CsvFile else followed_reader(obj, "Source")
        stamp = csv_stamp(obj.CsvFile) if obj.CsvFile else ""   # before it is read
        notes, names, unit = [], [], []   # (names: each point's in the warnings, the Sketcher's)
        gathered = gather_points(obj.Source, obj.CsvFile, obj.SamplesPerEdge, link="Source",
                                 element=element, notes=notes,
                                 thousands=THOUSANDS[obj.Thousands], names=names, unit=unit)
        edges = {}
        for key, prop in (("start", "StartTangent"), ("end", "EndTangent")):
            edge = followed_edge(obj, prop)
            if edge is not None:
                edges[f"{key}_edge"] = edge
                edges[f"{key}_at"] = edge_end_choice(obj, f"{prop}At")
        # a command's check of this input (commands.fit_sources): its fit, once
        checked, self.checked = getattr(self, "checked", None), None
        r = fit_gathered(gathered, notes, checked, names=names, **core_options(obj), **edges)
        r["csv_stamp"] = stamp
        r["csv_unit"] = unit[0] if unit else (None, 1.0)
        return r

    def read_links(self, obj):
        """The links a recompute reads (containers.read_objects): not Source when a CSV
        file is read instead."""
        return [p for p in super().read_links(obj) if not (p == "Source" and obj.CsvFile)]

    def mustExecute(self, obj):
        """A recompute reads the CSV file again once it changed on disk (QA17 P10: the old
        points kept, State up to date, until the feature was touched), as FreeCAD asks a
        feature whether it must execute besides its touched properties
        (FeaturePythonImp::mustExecute); and FeatureProxy's reasons."""
        # (FreeCAD may ask before onDocumentRestored's setup added CsvStamp to an old file's)
        return super().mustExecute(obj) or (
            bool(obj.CsvFile) and "CsvStamp" in obj.PropertiesList and
            csv_stamp(obj.CsvFile) != obj.CsvStamp)

    def _said_unit(self, obj, r, before):
        """The Status's words for a CSV file read in the unit its header names ('; scan.csv
        read in m, converted to mm'; '' for mm, none or px: its note), said in the report
        view once per change of that unit; and once, where a document saved before the unit
        was read (CsvUnit '?') fitted the file's numbers as mm (its DataPoints ``before``
        that size), that its fit changed."""
        unit, mm = r["csv_unit"]
        old, now = obj.CsvUnit, unit or ""
        if old != now:
            obj.CsvUnit = now
        if not obj.CsvFile or mm is None or mm == 1.0:
            return ""
        name = os.path.basename(obj.CsvFile)
        said = f"{name} read in {unit}, converted to mm"
        if old == "?" and before and len(before) == len(obj.DataPoints):
            size = lambda pts: max((p - pts[0]).Length for p in pts)  # noqa: E731
            ratio = size(obj.DataPoints) / size(before) if size(before) > 0 else 0.0
            if abs(ratio / mm - 1.0) < 1e-6:
                App.Console.PrintWarning(
                    f"Elastica {obj.Label}: this document, saved before a points file's "
                    f"header unit was read, fitted {name}'s numbers as mm; its header names "
                    f"{unit}: {said} now, so the fit is {mm:g} x the size it was\n")
                return "; " + said
        if old not in (now, "?"):
            App.Console.PrintMessage(f"Elastica {obj.Label}: {said}\n")
        return "; " + said

    def apply(self, obj, r):
        before = list(obj.DataPoints)    # (a document of before CsvUnit: _said_unit)
        plc = r["placement"]
        set_shape(obj, part_bspline(r["bspline"], plc).toShape())
        obj.Rms = r["rms"]
        obj.MaxError = r["max_error"]
        obj.ErrorMeasure = r["measure"]
        obj.K = r["k"]
        obj.EndCurvatures = r["end_curvatures"]
        obj.BSplineDeviation = r["bspline_deviation"]
        obj.Plane = plc
        obj.DataPoints = [plc.multVec(App.Vector(*map(float, p))) for p in r["data"]]
        obj.FootPoints = to_3d(plc, r["feet"])
        obj.Distances = [float(d) for d in r["distances"]]
        obj.PointNumbers = r["numbers"]
        curve_to_dict = binding_module("io").curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(c) for c in r["curves"]])
        old = obj.CsvStamp     # (setup added it, at creation or restore)
        if r["csv_stamp"] and old and r["csv_stamp"] != old and "Restore" not in obj.State:
            App.Console.PrintMessage(f"Elastica {obj.Label}: {obj.CsvFile} changed on disk: "
                                     "read again\n")
        if old != r["csv_stamp"]:
            obj.CsvStamp = r["csv_stamp"]
        # lengths marked (units.exact_mark), said again when a panel opens (proxy.said)
        set_said(obj, "Status", (r["status"] or "ok") + self._said_unit(obj, r, before))
        obj.FreeRms = r["free_rms"]
        warnings = r["warnings"]
        if say(warnings) != list(obj.Warnings):
            # once per change of the warnings, not on every recompute of the same fit
            for w in say(warnings):
                App.Console.PrintWarning(f"Elastica {obj.Label}: {w}\n")
        set_said(obj, "Warnings", warnings)

    def plane_curves(self, obj):
        """(curves, placement) of the last successful fit, or None: the curves along
        its shape from the first point to the last (a smooth keyline's first half
        reversed; Curves keeps the library's halves, each from the joint)."""
        stored = stored_curves(obj)
        if stored and len(stored[0]) == 2 and isinstance(stored[0][0], el().SmoothElastica):
            first, second = stored[0]
            return [first.reversed(), second], stored[1]
        return stored


def csv_stamp(path):
    """'modification time (ns) size' of the file at ``path``, '' where it cannot be read."""
    try:
        st = os.stat(path)
    except OSError:
        return ""
    return f"{st.st_mtime_ns} {st.st_size}"


def stored_curves(obj):
    """(curves, plane) from a feature's Curves JSON, or None."""
    if not getattr(obj, "Curves", ""):
        return None
    curve_from_dict = binding_module("io").curve_from_dict
    try:
        return [curve_from_dict(d) for d in json.loads(obj.Curves)], obj.Plane
    except ValueError:
        return None


def core_options(props):
    """fit_core's keyword arguments (but the tangent edges) from Fit property values:
    a feature, or a dict of them (a command's options; missing ones take the
    defaults of a new feature)."""
    if isinstance(props, dict):
        get = props.get
    else:
        def get(name, default=None):
            return getattr(props, name, default)
    return dict(model=get("Model", "discrete"), split=get("SplitAtInflection", False),
                distance=get("Distance", "orthogonal"), pin_start=get("PinStart", False),
                pin_end=get("PinEnd", False),
                start_curvature=get("StartCurvature", 0.0) if get("UseStartCurvature") else None,
                end_curvature=get("EndCurvature", 0.0) if get("UseEndCurvature") else None,
                start_join=get("StartContinuity", "tangent"),
                end_join=get("EndContinuity", "tangent"), step=float(get("ResampleStep", 0.0)),
                tol=float(get("Tolerance", 1e-3)), degree=get("Degree", 3))


def make(doc, sources=(), csv_file="", **props):
    """A new Fit feature in ``doc``; ``sources`` [(obj, [subnames])]; props set Model,
    Distance, SplitAtInflection, PinStart, PinEnd, UseStartCurvature, StartCurvature,
    StartContinuity ("tangent" / "G1" / "G2"), ResampleStep, Tolerance, Degree, ..."""
    if "PinEnds" in props:                       # the version-1 name (recorded macros)
        props["PinStart"] = props.pop("PinEnds")
    return new_feature(doc, "ElasticaFit", FitProxy,
                       Source=source_list(sources),
                       CsvFile=csv_file or "", **props)


__all__ = ["FitProxy", "core_options", "make", "stored_curves"]
