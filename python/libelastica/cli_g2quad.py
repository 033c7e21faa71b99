"""The ``elastica g2quad`` command: seed 002's G2 quadratic B-splines of a curve (points, or
a smooth elastica from ``fit --json``), with their distance from it, which joints are G2
(inside each piece) and which are not (where pieces meet, at inflections), and the ends'
tangent and curvature errors."""
from __future__ import annotations

import sys

import numpy as np

from ._quiet import quiet
from ._text import coordinates
from .cli_common import EXIT_OK, PROG, _plane_record, dxf_units, thousands
from .g2quad_points import STRAY_FIX
from .io import (InputError, curve_from_dict, curve_to_dict, looks_like_json, read_input,
                 read_json, read_points_unit, write_dxf_spline, write_json)

__all__ = ["cmd_g2quad"]

# a StrayWarning's way out (STRAY_FIX, the binding's words) in the command's words
CLI_STRAY_FIX = "--fit, or `elastica fit --model smooth --json` and pass the JSON"


def cmd_g2quad(args) -> int:
    """Seed 002: a curve (points, or a smooth elastica from 'fit --json') -> one G2
    quadratic B-spline per inflection-free piece, ending exactly on the curve."""
    import libelastica as el
    from .bspline import BSpline
    from .core import SmoothElastica
    from .spline import ElasticSpline
    from .report import Layer, curves_picture, save_picture
    source, frame, plane = args.file, None, None
    if args.edges is not None and args.edges < 3:
        raise InputError(f"--edges must be at least 3, got {args.edges}")
    # '-': points or a JSON (a fit's, piped: fit --json - | g2quad -), told by its first byte
    given = read_input("-") if args.file == "-" else None
    if args.file.lower().endswith(".json") or (given is not None and looks_like_json(given)):
        doc = read_json(args.file, data=given)
        unit = doc.get("unit") if isinstance(doc, dict) else None    # a fit's: its header's
        items = doc.get("sides") if isinstance(doc, dict) and "sides" in doc else [doc]
        if len(items) != 1:
            raise InputError(f"{args.file}: {len(items)} curves; give one (e.g. one side's JSON)")
        curve = _spline_of(items[0], args.file) or curve_from_dict(items[0], name=args.file)
        src = curve if isinstance(curve, (SmoothElastica, ElasticSpline)) else curve.points()
        if args.fit and src is curve:
            raise InputError(f"--fit: {args.file} is a fitted smooth elastica already")
        curve_source = src is curve
        data = curve.points(np.linspace(0.0, curve.length, 400)) if curve_source else src
        n = args.edges or 40
    else:
        pts, unit = read_points_unit(args.file, min_points=4, data=given,
                                     thousands=thousands(args))
        if pts.shape[1] == 3:
            src, frame = el.plane_fit(pts)
            plane = _plane_record(frame)
        else:
            src = pts
        data, curve_source = src, False
        # seed 002 §4.2: ~20 samples per vertex; a curve fitted to them (--fit) as a fit's
        # JSON (QA: 150 points -> 7 edges, the B-spline 0.51 off a fit of rms 0.047)
        n = args.edges or (40 if args.fit else max(6, (len(src) - 1) // 20))
    units = dxf_units(args.file, unit, args) if args.dxf else None   # (before the build)
    try:
        with quiet(el.EndTangentWarning, el.StrayWarning, into=[]) as caught:   # said below
            g = el.g2_quadratic(src, n, fit=args.fit)
    except el.CoverageError as exc:     # an error, nothing written (as FreeCAD's feature)
        raise InputError(_coverage_message(exc, n, args.edges is None,
                                           exc.result.fit is not None or curve_source)) from None
    except el.EdgeCountError as exc:    # too few edges for an elastica: the count that works
        if exc.edges is None:
            raise
        raise InputError(f"g2_quadratic: {exc.cause}; --edges {exc.edges} works, the fewest "
                         f"above {n}") from None
    for w in caught:    # 'g2_quadratic (n edges): ...', the way out in the CLI's words
        said = str(w).partition('): ')[2].replace(STRAY_FIX, CLI_STRAY_FIX)
        print(f"{PROG} g2quad: warning: {said}", file=sys.stderr)
    jumps = f"{g.curvature_jump:.2g}"
    rec = {"file": str(source), "unit": unit, "edges": int(n), "pieces": len(g.bsplines), "plane": plane,
           "ends": g.ends, "covers_source": g.covers_source, "ends_covered": g.ends_covered,
           "deviation": g.deviation,
           # "end_tangent_error_rad": the source's ends', what the report's 'end tangents'
           # line says (QA qapy F5: it held the max over every piece end, the inflections'
           # 0.0213 deg beside the ends' 8e-13); that max under its own name
           "curvature_jump": g.curvature_jump, "end_tangent_error_rad": g.source_end_tangent_error,
           "piece_end_tangent_error_rad": g.end_tangent_error,
           "source_end_tangent_error_rad": g.source_end_tangent_error,
           "inflection_tangent_error_rad": g.inflection_tangent_error,
           "end_curvature_error": g.end_curvature_error,
           "join_angle_rad": g.join_angle, "join_curvature_jump": g.join_curvature_jump,
           # the joints not G1, each with why (G2Quadratic.unheld_joints; joint j: where
           # bsplines[j] starts), where join_angle_rad gives only the largest angle
           "unheld_joints": [{"joint": j, "angle_rad": a, "why": why}
                             for j, a, why in g.unheld_joints],
           "dropped": g.dropped,
           "seam_angle_rad": g.seam_angle, "seam_curvature_jump": g.seam_curvature_jump,
           "polyline": g.polyline.points, "A": g.polyline.A,
           "bsplines": [b.to_dict() for b in g.bsplines]}
    if g.fit is not None:      # --fit: the elastica built from, the points' distances to it
        rec["fit"] = {"curve": curve_to_dict(g.fit.curve), "rms": g.fit.rms,
                      "max_error": g.fit.max_error, "status": int(g.fit.status)}
    if args.json:
        write_json(rec, args.outputs.path(args.json))
    pieces = len(g.bsplines)
    split = f"{pieces} pieces split at {pieces - 1} inflection(s)" if pieces > 1 else \
        "1 inflection-free piece"
    print(f"G2 quadratic B-spline: {split}, {n} edges, {g.npoles} poles (degree 2, "
          "uniform inside)")
    if g.fit is not None:
        print(f"  source: a smooth elastica fitted to the {len(src)} points (--fit), rms "
              f"{g.fit.rms:.3g}, max error {g.fit.max_error:.3g} from them")
    # in the input's coordinates, as the DXF (QA17 P6: 3D points printed the plane's 2D)
    ends = [g.ends[0], g.ends[-1]] if frame is None else frame.to_3d(np.array([g.ends[0], g.ends[-1]]))
    size = float(np.ptp(g.polyline.points, axis=0).max())
    start, end = (coordinates(e, size) for e in ends)     # (QA18 P1: %g wrote 500000, 5e+06)
    print(f"  starts at ({start}), ends at ({end}), exactly on the source")
    print(f"  {g.g2_summary()}")
    print(f"  largest distance from the source: {g.deviation:.3g}")
    # the source's own ends (what the words and the EndTangentWarning say), and apart the
    # pieces' ends at the inflections, O(edge) there (QA25 F9: 'end tangents off ... 0.313
    # deg' was the inflection's, the warning said 0.147 / 0.178 deg at the ends)
    if g.source_end_tangent_error is not None:
        print(f"  end tangents off the source's by at most "
              f"{np.degrees(g.source_end_tangent_error):.3g} deg")
    if g.inflection_tangent_error is not None:
        print(f"  tangents at the inflections (where the pieces meet) off the source's by at "
              f"most {np.degrees(g.inflection_tangent_error):.3g} deg")
    if g.end_curvature_error is not None:
        print(f"  end curvature off the source's by at most {g.end_curvature_error:.3g} "
              "(relative to the source's curvature scale: |k - k_src| / max(|k_src|, "
              "max |kappa| of the source over the end piece))")
    for spec in (args.svg, args.png):
        if spec:
            curves = []
            for b in g.bsplines:
                u = np.linspace(b.knots[0], b.knots[-1], 200 * (len(b.knots) - 1) + 1)
                xy, kappa = b(u), b.curvature(u)
                s = np.r_[0.0, np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))]
                curves.append((xy, s + (curves[-1][1][-1] if curves else 0.0), kappa))
            pic = curves_picture(curves, [f"G2 piece {i + 1}" for i in range(len(curves))],
                                 title="G2 quadratic B-spline (seed 002)",
                                 params=[f"{n} edges, {g.npoles} poles",
                                         f"deviation {g.deviation:.3g}",
                                         f"curvature jump {jumps}"])
            pic.layers[:0] = [
                Layer(data, "source", "#000000", line=True) if curve_source else
                Layer(data[::max(1, len(data) // 100)], "source", "#000000", marker="s", size=3.0),
                Layer(g.polyline.points, "affine arc-length polyline", "#7f7f7f", marker="o",
                      line=True, size=3.0)]
            save_picture(pic, args.outputs.path(spec))
    if args.dxf:
        splines = g.bsplines if frame is None else [
            BSpline(b.degree, frame.to_3d(b.poles), b.knots, b.mults) for b in g.bsplines]
        write_dxf_spline(splines, args.outputs.path(args.dxf), units=units)
    return EXIT_OK


def _spline_of(doc, name: str):
    """The ElasticSpline of `elastica spline --json`'s record (its pieces and 'closed'),
    None for any other JSON. It was refused as "no elastica curve" (QA23 F10): g2_quadratic
    takes the spline; a closed one opened at its point 0 and closed G2 there (QA25 F3: it
    was refused, "no ends for the G2 quadratic splines")."""
    from .core import SmoothElastica, chain_starts
    from .spline import ElasticSpline
    if not (isinstance(doc, dict) and "pieces" in doc and "closed" in doc and "type" not in doc):
        return None
    pieces = doc["pieces"]
    if not isinstance(pieces, list) or not pieces:
        raise InputError(f"{name}: a spline's 'pieces' must be a list of smooth elasticae")
    curves = [curve_from_dict(p, f"{name} piece {i}") for i, p in enumerate(pieces)]
    if not all(isinstance(c, SmoothElastica) for c in curves):
        raise InputError(f"{name}: a spline's pieces must be smooth elasticae")

    class _ReadSpline(ElasticSpline):
        """The spline read back: its pieces' evaluation and inflections, no C result."""

        def __init__(self):     # (ElasticSpline's own reads the C el_spline_result)
            self.pieces, self.closed = curves, bool(doc["closed"])
            self._starts = chain_starts(curves)
            self.length = float(self._starts[-1])

    return _ReadSpline()


def _coverage_message(exc, n: int, default: bool, smooth: bool) -> str:
    """el.g2_quadratic's CoverageError in the CLI's words: which ends are left out, how
    much, and the fewest --edges that cover them (el.covering_edges, FreeCAD's too)."""
    g = exc.result
    left = "its start's and its end's pieces beyond their inflections" \
        if not any(g.ends_covered) else \
        f"its {'end' if g.ends_covered[0] else 'start'}'s piece beyond an inflection"
    gone = " + ".join(f"{d:.4g}" for d in g.dropped if d > 0)
    given = f"{n} edges (the default for these points) leave" if default else \
        f"--edges {n} leaves"
    more = f"--edges {exc.edges} covers it" if exc.edges else \
        f"none of --edges {n + 1} to {exc.tried} covers it (try more)"
    # noise makes inflections of points (QA: the advice named --fit to a user who had given it)
    noisy = "" if smooth else "; noisy points: --fit, or fit first (elastica fit --model " \
        "smooth --json) and pass the JSON"
    return (f"{given} out {left} ({gone} of the source's length; too short for 3 "
            f"edges): {more}{noisy}")
