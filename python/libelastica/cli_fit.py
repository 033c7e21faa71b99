"""``elastica fit``: fit elasticae to the points of one file or a batch of them, with
JSON, report pictures (SVG/PNG), B-splines and DXF (cli.py builds the parser)."""
from __future__ import annotations

import os
import sys
from pathlib import Path
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from ._ffi import ElasticaError, NotConvergedError
from ._quiet import quiet
from ._text import curve_values
from .cli_common import (ANGLE_UNITS, EXIT_BADINPUT, EXIT_INTERNAL, EXIT_NOCONV, EXIT_OK, PROG,
                         _converged, _finite, _float_list, _fmt, _mapped_bspline, _plane_record,
                         _Progress, _status_text, _table, angle, dxf_units, thousands,
                         tol_option)
from .cli_outputs import out_path
from .fit import quiet_fit
from .misfit import _fit_outliers
from .fit_cost import cost_summary, costly, end_costs, held_ends, local_cost_summary
from .order import order_summary
from .io import InputError, curve_to_dict, read_points_unit, write_dxf_spline, write_json


def _parse_fix(spec: Optional[str], data: np.ndarray, keyline: bool = False) -> Dict[str, float]:
    """--fix 'x0,y0' (the start pinned to the first data point) or 'x0=1,y0=2,phi=30'
    (explicit values; phi in degrees, or '0.5rad', as every angle of the command line: held
    in radians). With --keyline, x0/y0 are already pinned at the inflection, so
    bare 'x0'/'y0' are dropped."""
    fixed: Dict[str, float] = {}
    for item in (spec or "").split(","):
        item = item.strip()
        if not item:
            continue
        name, _, value = item.partition("=")
        name = name.strip()
        if value and name == "phi":
            try:
                fixed[name] = angle(value)
            except ValueError:
                raise InputError(f"--fix: phi={value!r} is not an angle ({ANGLE_UNITS})") from None
        elif value:
            try:
                fixed[name] = _finite(float(value), f"--fix {name}")
            except ValueError:
                raise InputError(f"--fix: {name}={value!r} is not a number") from None
        elif name in ("x0", "y0"):
            if not keyline:
                fixed[name] = float(data[0, 0 if name == "x0" else 1])
        else:
            raise InputError(f"--fix: give a value for {name} (e.g. {name}=0.5); only x0 and y0 "
                             "default to the first point")
    return fixed


def _fit_kwargs(args, fixed: Dict[str, float], constraints: Optional[Dict[str, Any]] = None
                ) -> Dict[str, Any]:
    kw: Dict[str, Any] = {"model": args.model}
    if fixed:
        kw["fixed"] = fixed
    if args.max_iter is not None:
        kw["max_iter"] = args.max_iter
    if constraints:
        kw["constraints"] = constraints
    if getattr(args, "distance", None):
        kw["distance"] = args.distance
    return kw


def _side_record(res, data: np.ndarray, model: str, free=None) -> Dict[str, Any]:
    """The JSON record of one fitted curve; ``free``: a constrained fit's points' distances
    to the fit without its constraints (points held off only by them are no outliers), kept
    as "free_distances"."""
    rec = {"model": model, "n_points": int(len(data)),
           "curve": curve_to_dict(res.curve),
           "initial": curve_to_dict(res.initial) if res.initial is not None else None,
           "rms": float(res.rms), "max_error": float(res.max_error),
           "iterations": int(res.iterations), "status": _status_text(res.status),
           "converged": _converged(res)}
    if getattr(res, "wander_gap", -1) >= 0:     # el.fit's WanderWarning, said by _warn_wanders
        rec["wander_gap"] = int(res.wander_gap)
        # the two points' rows (the file's under --order curve: _by_file_row)
        rec["wander_points"] = [int(res.wander_gap), int(res.wander_gap) + 1]
    if res.constraints:     # `elastica bspline` keeps a discrete fit's ends (fit_constraints)
        rec["constraints"] = constraints_record(res.constraints)
    if getattr(res, "distances", None) is not None:
        # point-to-curve distances (+ = left of the curve) and each foot's arc length
        far, stray = _fit_outliers(res, free)
        rec.update(distance=res.distance, distances=[float(v) for v in res.distances],
                   foot_s=[float(v) for v in res.foot_s], outliers=[int(i) for i in far])
        if stray is not None:   # one stray point among few (stray.py): its own figures
            rec["stray"] = dict(distance=stray[1], noise=stray[2], gain=stray[3])
        if free is not None:
            rec["free_distances"] = [float(v) for v in free]
    return rec


def uncertainty_record(res) -> Dict[str, Any]:
    """"uncertainty" of the JSON: the fit's standard errors (FitResult.uncertainty): "stderr"
    {name: se} of the curve's parameters and the derived quantities (null where the points do
    not determine it: inf), "values" {name: value} of the derived ones, "residual_sd" sqrt(s^2),
    "dof", "undetermined" (se >= |value|) and "note"; {} where it cannot be computed."""
    try:
        u = res.uncertainty()
    except (ValueError, ArithmeticError, ElasticaError):
        return {}

    def num(v):
        return float(v) if np.isfinite(v) else None
    return {"uncertainty": {"stderr": {k: num(v) for k, v in u.as_dict().items()},
                            "values": {k: float(v) for k, (v, _) in u.derived.items()},
                            "residual_sd": num(np.sqrt(u.s2)), "dof": u.dof,
                            "undetermined": list(u.undetermined()), "note": u.note}}


def _print_uncertainty(rec: Dict[str, Any]) -> None:
    """The report's standard errors: value +- se of what a scientist reads (uncertainty_record)."""
    u = rec.get("uncertainty")
    if not u:
        return
    vals = dict(rec["curve"], **u["values"])
    shown = [k for k in ("mu", "k", "z", "h", "length", "energy", "force_x", "force_y",
                         "start_curvature", "end_curvature") if k in u["stderr"] and k in vals]
    if u["dof"] <= 0:     # (QA F9: '+- inf' each, then 'standard errors NaN': one thing, said once)
        print("std errors  none: " + "; ".join(n.rpartition(": ")[0] for n in u["note"].split("; ")
                                              if n.startswith("no degrees of freedom")))
        return
    print("std errors  " + ", ".join(f"{k}={_fmt(vals[k])} +- " + ("inf" if u["stderr"][k] is None
                                     else f"{u['stderr'][k]:.2g}") for k in shown))
    if u["undetermined"]:
        print(f"            undetermined (se >= |value|): {', '.join(u['undetermined'])}"
              + (f"; {u['note']}" if u["note"] else ""))


def constraints_record(con) -> Dict[str, Any]:
    """el.fit's constraints as the JSON writes them: a tangent's angle under
    "start_tangent_rad" / "end_tangent_rad" (radians, as el.fit holds it; --start-tangent
    takes degrees), the others under el.fit's names."""
    return {(f"{k}_rad" if k.endswith("_tangent") else k): v for k, v in con.items()}


def fit_constraints(rec) -> Optional[Dict[str, Any]]:
    """el.fit's constraints of a JSON record's "constraints" (:func:`constraints_record`'s;
    a tangent without "_rad", as written before the unit was named, is radians too)."""
    if not isinstance(rec, dict):
        return None
    return {(k[:-4] if k.endswith("_tangent_rad") else k): v for k, v in rec.items()}


def _resampled_record(path, args, xy: np.ndarray, fixed, constraints, numbered: bool = True):
    """The record of a one-piece --step fit (el.fit_resampled): its figures are the file's
    points' (in the fit's plane) to the curve drawn (a discrete fit's C2 cubic through its
    vertices), not the polygon's vertices' to it ("distances_of"; the polygon's own kept as
    "polygon_rms" / "polygon_max_error"); a constrained fit's outliers judged by the
    points' distances to the resampled fit without its constraints, their cost by the
    one with free ends (_end_conditions), whether they are one elastica (_misfit) by the
    points' distances to it (numbered: the file's order). Returns the record, the polygon's
    FitResult and the points' feet."""
    import libelastica as el
    with quiet(el.ResampleWarning):     # the ResampleWarning said in the CLI's words
        rr = el.fit_resampled(xy, args.step, **_fit_kwargs(args, fixed, constraints))
        free = loose = None             # loose: free ends, nothing fixed
        if constraints or fixed:
            loose = el.fit_resampled(xy, args.step, check=False, **_fit_kwargs(args, {}))
        if constraints:
            free = (loose if not fixed else el.fit_resampled(
                xy, args.step, check=False, **_fit_kwargs(args, fixed))).distances
    res = rr.result
    rec = _side_record(res, xy, args.model)
    far = el.far_points(rr.distances, xy, free_distances=free)
    rec.update(rms=rr.rms, max_error=rr.max_error, fitted_points=int(len(rr.polygon)),
               polygon_rms=float(res.rms), polygon_max_error=float(res.max_error),
               distances_of="the file's points (in the fit's plane) to the curve drawn",
               distances=[float(v) for v in rr.distances],
               foot_s=[float(v) for v in rr.foot_s], outliers=[int(i) for i in far],
               resample_reference_rms=rr.reference_rms)
    if free is not None:
        rec["free_distances"] = [float(v) for v in free]
    else:
        rec.pop("free_distances", None)
    _end_conditions(rec, rr.rms, loose.rms if loose is not None else None, xy, constraints, fixed,
                    (rr.distances, loose.distances, loose.foot_s) if loose is not None else None)
    rec.update(_misfit(path, el.misfit(xy, (rr if loose is None else loose).distances), xy, numbered))
    return rec, res, rr.feet


def _end_conditions(rec: Dict[str, Any], rms: float, free_rms: Optional[float], points: np.ndarray,
                    constraints: Dict[str, Any], fixed: Dict[str, float], near=None) -> None:
    """What the end conditions cost, in the record: "free_rms", the same fit's with free
    ends and nothing fixed (like with like: the points' distances to the curves fitted, a
    --step's to the curves drawn), and where they raise the rms beyond el.costly's ratio,
    overall or near a held end (``near``: the fit's distances, the free fit's and its feet'
    arc lengths, for el.end_costs; then "end_condition_near": end, rms, free_rms there),
    "end_condition_warning" (said by _warn_end_conditions; el.fit's EndConditionWarning)."""
    if free_rms is None:
        return
    rec["free_rms"] = float(free_rms)
    extent = float(np.ptp(points[:, :2], axis=0).max())
    held = ", ".join([f"--{c.replace('_', '-')}" for c in constraints] +
                     ([f"--fix {','.join(fixed)}"] if fixed else []))
    if costly(rms, free_rms, extent):
        rec["end_condition_warning"] = cost_summary(held, free_rms, rms)
        return
    local = end_costs(held_ends(constraints, fixed), near[2], near[0], near[1], extent) \
        if near is not None else []
    if local:
        end, near_rms, near_free = local[0]
        rec["end_condition_near"] = {"end": end, "rms": near_rms, "free_rms": near_free}
        rec["end_condition_warning"] = local_cost_summary(held, end, near_free, near_rms)


def _warn_end_conditions(path, rec: Dict[str, Any]) -> None:
    """A warning on stderr when the end conditions raise the rms (_end_conditions)."""
    if rec.get("end_condition_warning"):
        print(f"{PROG} fit: warning: {path}: {rec['end_condition_warning']}", file=sys.stderr)


def _warn_far_points(path, rec: Dict[str, Any]) -> None:
    """A warning on stderr naming the points far from the fitted curve (the record's
    "outliers": indices into the fitted points, the file's rows unless resampled)."""
    from .misfit import outliers_summary, stray_summary
    far = rec.get("outliers")
    if not far:
        return
    side = f" (side {rec['side'] + 1})" if "side" in rec else ""
    # el.fit's OutlierWarning in the command's words (the same rule and text: el.fit_outliers,
    # el.outliers_summary), the path before it
    st = rec.get("stray")
    said = outliers_summary(rec["distances"], far, free_distances=rec.get("free_distances")) \
        if st is None else stray_summary(len(rec["distances"]), (far[0], st["distance"], st["noise"],
                                                                 st["gain"]), far[0])
    print(f"{PROG} fit: warning: {path}{side}: {said}", file=sys.stderr)


def _cubic_figures(doc: Dict[str, Any], res, bspline, pts: np.ndarray,
                   xy: Optional[np.ndarray] = None) -> None:
    """A discrete fit's exported cubic measured against the points, kept as the document's
    "bspline_rms" / "bspline_max_error": the fitted points' (one piece), the file's points'
    in the keyline's plane (a keyline; x''y'' as its B-spline) or in the fit's plane (``xy``,
    a one-piece --step: as its rms, which is already the cubic's). Its rms / max error are
    the polygon's, and the C2 cubic through the vertices runs elsewhere between them."""
    from .nearest import nearest_on
    if xy is not None:
        d = nearest_on(bspline, np.ascontiguousarray(xy))[1]
    elif hasattr(res, "prepared"):
        prep = res.prepared
        xy = prep.frame.project(pts) if prep.frame is not None else pts[:, :2]
        d = nearest_on(bspline, np.ascontiguousarray(prep.frame2d.to_local(xy)))[1]
    else:
        d = res.cubic_distances(bspline)[1]
    doc["bspline_rms"] = float(np.sqrt(np.mean(d ** 2)))
    doc["bspline_max_error"] = float(np.max(np.abs(d)))


def _warn_coarse_polygon(path, rec: Dict[str, Any], data: np.ndarray, res) -> None:
    """A warning on stderr when a discrete fit of few points (el.SPARSE_POINTS) lies far
    farther from them than the smooth model's curve: el.fit's verdict (FitResult.sparse,
    el.SparseWarning)."""
    smooth = res.sparse
    if smooth is None:
        return
    # the verdict in the JSON too, as "misfit" (QA20 F7: the JSON had none)
    rec["sparse"] = {"rms": float(res.rms), "bspline_rms": rec.get("bspline_rms"),
                     "smooth_rms": float(smooth)}
    cubic = (f", its B-spline {rec['bspline_rms']:.3g}" if "bspline_rms" in rec else "")
    print(f"{PROG} fit: warning: {path}: {len(data)} points give the discrete model a polygon "
          f"of {len(data) - 1} segments, {res.rms:.3g} from them (rms){cubic}, where the smooth "
          f"model's curve lies {smooth:.3g} from them: use --model smooth for so few points",
          file=sys.stderr)


def _verdict(rec: Dict[str, Any]) -> str:
    """A batch row's status: the fit's, and the warnings that judge it (QA20 F7: a fit at 46
    x the points' noise read 'ok'): 'ok; not one elastica: 46 x the noise' (the record's
    "misfit"), '...; discrete polygon too coarse: smooth 0.01' ("sparse")."""
    said = [str(rec["status"])]
    m = rec.get("misfit")
    if m:
        said.append(f"not one {'keyline' if 'side' in rec else 'elastica'}: {m['ratio']:.3g} x the noise")
    sp = rec.get("sparse")
    if sp:
        said.append(f"discrete polygon too coarse: smooth {sp['smooth_rms']:.3g}")
    return "; ".join(said)


def _warn_sparse_keyline(path, kres, n: int) -> None:
    """A warning on stderr when a discrete keyline of few points (el.SPARSE_POINTS) lies
    far farther from them than the smooth keyline (KeylineFit.sparse, el.SparseWarning)."""
    if kres.sparse is None:
        return
    print(f"{PROG} fit: warning: {path}: the discrete keyline lies {kres.input_rms:.3g} from "
          f"the {n} points (rms), where the smooth keyline lies {kres.sparse:.3g} from them: "
          "use --model smooth for so few points", file=sys.stderr)


def _by_file_row(rec: Dict[str, Any], order: np.ndarray) -> None:
    """A record of the file's points fitted in curve order (--order curve: ``order``, their
    file rows in it) put in the file's order: its per-point lists ("distances", "foot_s",
    "free_distances") row by row, its "outliers" the file's rows (QA17: the glitch at row 126
    was named as point 100, its place in curve order, a good point's row); the gap the
    curve wanders in by its two points' rows ("wander_points"; "wander_gap", a curve-order
    index, dropped)."""
    for key in ("distances", "foot_s", "free_distances"):
        if len(rec.get(key) or ()) == len(order):
            v = np.empty(len(order))
            v[order] = rec[key]
            rec[key] = [float(x) for x in v]
    if rec.get("outliers"):
        rec["outliers"] = sorted(int(order[i]) for i in rec["outliers"])
    if "wander_gap" in rec:     # a gap in curve order: its two points, rows apart in the file
        gap = rec.pop("wander_gap")
        rec["wander_points"] = [int(order[gap]), int(order[gap + 1])]


def _warn_wanders(path, rec: Dict[str, Any], data: np.ndarray, numbered: bool = True,
                  gap: int = -1) -> None:
    """A warning on stderr naming the gap ``gap`` between two fitted points (of ``data``)
    the curve wanders in (the record's "wander_gap" before _by_file_row, el.fit's
    WanderWarning), and what holds it there; by their places alone where not ``numbered``
    (--order curve: the fit's order is not the file's)."""
    from .fit import wander_summary
    if gap < 0:
        return
    side = f" (side {rec['side'] + 1})" if "side" in rec else ""
    print(f"{PROG} fit: warning: {path}{side}: {wander_summary(gap, data, numbered=numbered)}: add a point "
          "between them, or bound the length (--length LO,HI)", file=sys.stderr)


def _warn_retrace(path, rec: Dict[str, Any], back) -> None:
    """A warning on stderr naming the points that run back along the curve (el.fit's
    OrderWarning of a scan passed back and forth, ``FitResult.retrace``: back): a one-piece
    fit in the file's order (its caller's gates: no --step, no --order curve)."""
    from .order import retrace_summary
    if "side" in rec or back is None:
        return
    print(f"{PROG} fit: warning: {path}: {retrace_summary(back)}", file=sys.stderr)


def _misfit(path, m, points: np.ndarray, numbered: bool, what: str = "one elastica") -> Dict[str, Any]:
    """Points far farther from the fit than their own noise (el.misfit's Misfit m, or
    None): a warning on stderr naming the likely corner (a row of ``points``; by its place
    alone where not ``numbered``: the fit's order is not the file's), and the record's
    "misfit" (rms, noise, ratio, corner, parts)."""
    if m is None:
        return {}
    from .misfit import misfit_summary
    print(f"{PROG} fit: warning: {path}: {misfit_summary(m, points, numbered=numbered, what=what)}",
          file=sys.stderr)
    return {"misfit": {"rms": m.rms, "noise": m.noise, "ratio": m.ratio, "corner": m.corner,
                       "parts": list(m.parts) if m.parts else None}}


def _constraints(args, data: np.ndarray) -> Dict[str, Any]:
    """el.fit's constraints from the command line (its angles read in radians by cli.ANGLE)."""
    con: Dict[str, Any] = {}
    for end, idx, word in (("start", 0, "first"), ("end", -1, "last")):
        spec = getattr(args, f"{end}_point")
        if spec is not None:
            con[f"{end}_point"] = (tuple(float(v) for v in data[idx, :2]) if spec.strip() == word
                                   else tuple(_float_list(spec, 2, f"--{end}-point")))
        ang = getattr(args, f"{end}_tangent")
        if ang is not None:
            con[f"{end}_tangent"] = ang          # radians (cli.ANGLE)
        kap = getattr(args, f"{end}_curvature")
        if kap is not None:
            con[f"{end}_curvature"] = _finite(kap, f"--{end}-curvature")
    for name in ("length", "k"):
        spec = getattr(args, name if name == "length" else "k_range")
        if spec is not None:
            # one value is that value exactly, as hermite's and spline's --length L (QA:
            # `--length 95` was read as 95 or more and fitted 99.7 long, exit 0)
            lo, comma, hi = spec.partition(",")
            hi = hi if comma else lo
            try:
                con[name] = (float(lo) if lo.strip() else None, float(hi) if hi.strip() else None)
            except ValueError:
                raise InputError(f"--{name}: expected V or LO,HI (either may be empty), "
                                 f"got {spec!r}") from None
    return con


def _warn_turned_tangents(args) -> None:
    """A warning on stderr, in degrees, for an end tangent typed past a full turn
    (--start-tangent 400 is 40 deg turned once more): the direction is all an end tangent
    holds (the fit reads it modulo a turn), so it is fitted; a typing slip shows here. (The
    binding's own check of such an angle asks a Python caller whether he meant degrees:
    said_warnings keeps it off the command line, which reads every angle with its unit.)"""
    for end in ("start", "end"):
        a = getattr(args, f"{end}_tangent", None)
        if a is None or abs(a) <= 2 * np.pi:     # (warn_if_degrees' bound)
            continue
        deg = float(np.degrees(a))
        within = float(np.fmod(deg, 360.0))
        turns = round(abs(deg - within) / 360.0)
        times = {1: "once", 2: "twice"}.get(turns, f"{turns} times")
        deg, within = (f"{round(v, 4) + 0.0:.10g}" for v in (deg, within))   # (no '-0')
        print(f"{PROG} fit: warning: --{end}-tangent {deg} deg is {within} deg turned "
              f"{times} more: fitted as the direction {within} deg", file=sys.stderr)


def _in_order(path, pts: np.ndarray, order: str):
    """(the points, None) in the file's order, warned of on stderr when that is no curve's
    (el.out_of_order: a shuffled scan is fitted as a coil through its cloud); --order curve:
    (the points in el.curve_order's order, its indices)."""
    import libelastica as el
    if order == "curve":
        idx = el.curve_order(pts)
        return np.ascontiguousarray(pts[idx]), idx
    o = el.out_of_order(pts)
    if o.order is not None:
        print(f"{PROG} fit: warning: {path}: {order_summary(o)}: fitted in the file's "
              "order, the curve may coil through them; --order curve fits them in curve order",
              file=sys.stderr)
    return pts, None


def fit_file(path: str, args, batch: bool) -> Tuple[List[Dict[str, Any]], Dict[str, Any]]:
    """Fit one file; returns one record per fitted curve (two with --keyline) and the
    file's JSON document (the record; a keyline's {"file", "sides", "bspline"}), and
    writes the requested outputs. Raises InputError / ValueError for bad input."""
    import libelastica as el
    pts, unit = read_points_unit(path, min_points=4, thousands=thousands(args))
    units = dxf_units(path, unit, args) if args.dxf else None   # (before any fit)
    pts, order = _in_order(path, pts, getattr(args, "order", "given"))
    records: List[Dict[str, Any]] = []
    pictures = []       # (points (n,2), FitResult, their feet or None: the fit's) per record
    fitted = []         # the points each record's fit took (a --step: its polygon's)
    extra_info: Dict[str, Any] = {}
    if args.keyline:
        # seed 000 §5 as one G2 curve: plane fit, resampling (segment --step),
        # re-normalisation, inflection, two elasticae sharing the joint
        if _constraints(args, pts) or getattr(args, "distance", None):
            raise InputError("--keyline: the joint is the keyline's constraint; end constraints "
                             "and --distance apply to one-piece fits")
        fixed = _parse_fix(args.fix, pts[:, :2], keyline=True)
        # its status said in the CLI's words; OrderWarning: _in_order says it, MisfitWarning
        # _misfit, SparseWarning _warn_sparse_keyline, OutlierWarning below (the file's rows)
        with quiet(el.ConvergenceWarning, el.OrderWarning, el.MisfitWarning, el.SparseWarning,
                   el.OutlierWarning):
            kres = el.fit_keyline(pts, r=args.step, **_fit_kwargs(args, fixed))
        _warn_sparse_keyline(path, kres, len(pts))
        # the file's points far from the keyline (el.fit's rule), by their rows (QA23: the
        # sides' "outliers" counted each side's own points, and nothing was said)
        rows = [int(order[i]) if order is not None else int(i) for i in kres.outliers]
        if rows:
            from .misfit import outliers_summary
            said = outliers_summary(kres.input_distances, list(kres.outliers), sorted(rows))
            print(f"{PROG} fit: warning: {path} (keyline): {said}", file=sys.stderr)
        prep = kres.prepared
        plane = _plane_record(prep.frame)
        to_input = prep.to_input
        extra_info = {"input_rms": kres.input_rms, "input_max_error": kres.input_max_error,
                      "input_points": len(pts),
                      "input_outliers": sorted(rows),     # the file's rows
                      "inflection_index": int(kres.inflection),
                      "inflection_point": kres.joint,
                      "step": prep.r, "coordinates": "x''y'' (PCA frame of the resampled polygon; frame2d "
                                     "maps it to the input's, where the bspline and "
                                     "inflection_point are)",
                      "frame2d": {"origin": prep.frame2d.origin, "f1": prep.frame2d.f1,
                                  "f2": prep.frame2d.f2},
                      **_misfit(path, kres.misfit, pts, order is None, "one keyline")}
        for i, res in enumerate((kres.first, kres.second)):
            rec = _side_record(res, res.points, args.model)
            rec["side"] = i
            # the side in the file's coordinates (a 3D file's: its plane's x'y'), "curve"
            # the x''y'' frame's it was fitted in (QA qapy F7: the report showed those alone)
            rec["curve_input"] = curve_to_dict(kres.side_curve(("first", "second")[i]))
            if kres.ends_local is not None:   # where a discrete half ends (x''y'', as its
                rec["end"] = [float(v) for v in kres.ends_local[i]]     # curve): `bspline` again
            records.append(rec)
            pictures.append((res.points, res, None))
            fitted.append(res.points)
        data = prep.polygon
    else:
        plane, to_input = None, None
        if pts.shape[1] == 3:
            xy, frame = el.plane_fit(pts)
            plane = _plane_record(frame)
            to_input = frame.to_3d
        else:
            xy = pts
        data = xy
        if args.step is not None:
            # the library's rule and message (a positive step the points reach from the
            # polygon's start), as for --keyline; the polygon ends at the points' ends and
            # follows the medians of their runs where their polyline zigzags (noise)
            data = el.resampled_polygon(xy, args.step)
            if len(data) < 4:
                raise InputError(f"{path}: --step {args.step} leaves only {len(data)} points")
        fixed, constraints = _parse_fix(args.fix, data), _constraints(args, data)
        if args.step is not None:
            rec, res, feet = _resampled_record(path, args, xy, fixed, constraints, order is None)
            records.append(rec)
            pictures.append((xy, res, feet))
            fitted.append(data)
        else:
            # quietly: said in the CLI's words (_warn_wanders, _warn_end_conditions, _misfit,
            # the status)
            res = quiet_fit(data, check_ends=True, check_misfit=True, check_sparse=True,
                            **_fit_kwargs(args, fixed, constraints))
            free = None
            if constraints and getattr(res, "distances", None) is not None:
                # el.fit's fit with free ends, where nothing is fixed (--fix: held there too)
                free = (res.free if res.free is not None and not fixed else
                        quiet_fit(data, **_fit_kwargs(args, fixed))).distances
            records.append(_side_record(res, data, args.model, free))
            records[-1].update(_misfit(path, res.misfit, pts, order is None))
            records[-1].update(uncertainty_record(res))
            lf = res.free
            _end_conditions(records[-1], res.rms, lf.rms if lf is not None else None, data,
                            constraints, fixed,
                            (res.distances, lf.distances, lf.foot_s) if lf is not None else None)
            pictures.append((data, res, None))
            fitted.append(data)
    for rec, fitted_pts in zip(records, fitted):
        rec.update({"file": str(path), "unit": unit, "plane": plane, "step": args.step,
                    **extra_info})
        gap = rec.get("wander_gap", -1)      # in the fit's order, as fitted_pts
        if order is not None:
            rec["order"] = [int(i) for i in order]
            if not args.keyline:
                _by_file_row(rec, order)
        _warn_end_conditions(path, rec)
        if "side" not in rec:       # a keyline's: said above, by the file's rows
            _warn_far_points(path, rec)
        retrace = res.retrace if order is None and args.step is None else None
        if retrace is None or "side" in rec:    # (el.fit's order: the cause, said instead)
            _warn_wanders(path, rec, fitted_pts, order is None, gap)
        _warn_retrace(path, rec, retrace)
        if rec.get("resample_reference_rms") is not None:
            from .resampled import resample_summary
            print(f"{PROG} fit: warning: {path}: " + resample_summary(
                args.step, rec["rms"], rec["resample_reference_rms"],
                extent=float(np.ptp(fitted_pts, axis=0).max())), file=sys.stderr)
    doc = records[0] if len(records) == 1 else {"file": str(path), "unit": unit,
                                                "sides": records}
    splines = []
    if args.bspline_tol is not None or args.dxf:
        tol = args.bspline_tol      # > 0: the parser's; None: 1e-6 of the curve's length
        if args.keyline:       # ONE B-spline through the joint (x''y'', as the sides, here)
            with tol_option("--bspline-tol"):
                splines.append(kres.to_bspline(tol, args.degree, input_coords=False))
        else:
            with tol_option("--bspline-tol"):   # a discrete fit's: its ends
                splines.append(res.to_bspline(tol, args.degree))
        if args.model == "discrete":     # the cubic through the vertices is not the polygon
            _cubic_figures(doc, kres if args.keyline else res, splines[0], pts,
                           xy if args.step is not None and not args.keyline else None)
    if args.model == "discrete" and not args.keyline and args.step is None:
        # (a --step's polygon is judged by the file's points: the ResampleWarning)
        _warn_coarse_polygon(path, records[0], data, res)
    # the DXF and the JSON get the curves in the input's coordinates (3D for 3D input; a
    # keyline's as KeylineFit.to_bspline's); a 3D one-piece record keeps the fitted plane's
    # x'y' one (the curve's) as "bspline_local"
    mapped = [_mapped_bspline(b, to_input) for b in splines]
    if splines:
        doc["bspline"] = mapped[0].to_dict()
        if to_input is not None and not args.keyline:
            doc["bspline_local"] = splines[0].to_dict()
    splines = mapped
    _write_fit_outputs(path, args, batch, doc, records, pictures, splines, pts, units)
    return records, doc


def _write_fit_outputs(path, args, batch, doc, records, pictures, splines, points,
                       units) -> None:
    """JSON, pictures (in the fit's plane coordinates) and DXF (splines and points in the
    input's coordinates, its $INSUNITS ``units``: dxf_units) of one file."""
    from .report import fit_picture, save_picture
    jpath = out_path(args.json, path, ".json", batch) if args.json and args.json != "-" and not (
        batch and args.json.endswith(".json") and "{stem}" not in args.json) else None
    if jpath is not None:
        write_json(doc, args.outputs.path(jpath))
    for spec, ext in ((args.svg, ".svg"), (args.png, ".png")):
        out = out_path(spec, path, ext, batch)
        if out is None or not pictures:
            continue
        pic = None
        for i, ((d, res, feet), rec) in enumerate(zip(pictures, records)):
            extra = [f"rms = {rec['rms']:.4g}, max error = {rec['max_error']:.4g}",
                     f"iterations = {rec['iterations']}, status = {rec['status']}"]
            if rec.get("plane"):
                extra.append(f"plane fit rms = {rec['plane']['rms']:.4g}")
            p = fit_picture(d, res.curve, res.initial,
                            model_points=res.foot_points() if feet is None else feet,
                            title=f"{Path(path).name}: {args.model} elastica fit"
                                  + (" (keyline, x''y'' frame)" if args.keyline else ""),
                            extra=extra)
            if pic is None:
                pic = p
            else:              # keyline: second side into the same picture, other colours
                recolor = {"initial guess": "#bcbd22", "elastica": "#9467bd"}
                for L in p.layers:
                    if L.label == "data":
                        L.label = "data (2)"
                        L.color = "#555555"
                    else:
                        L.color = recolor.get(L.label, L.color)
                        L.label += f" ({i + 1})"
                    pic.layers.append(L)
                a0, b0 = pic.residuals
                pic.residuals = (np.vstack([a0, p.residuals[0]]), np.vstack([b0, p.residuals[1]]))
                for g in p.graphs:
                    g.label += f" ({i + 1})"
                    if g.primary:
                        g.color = "#9467bd"
                pic.graphs += p.graphs
                pic.params += [f"--- side {i + 1}"] + p.params
        save_picture(pic, args.outputs.path(out))
    if args.dxf and splines:
        write_dxf_spline(splines, args.outputs.path(out_path(args.dxf, path, ".dxf", batch)),
                         points=points, units=units)


def _unit(rec: Dict[str, Any]) -> str:
    """' mm' after a figure of a record whose points file's header names its unit (QA qapy
    F3; revD), '' where it names none."""
    return f" {rec['unit']}" if rec.get("unit") else ""


def _print_fit(rec: Dict[str, Any]) -> None:
    u = _unit(rec)
    print(f"file        {rec['file']}" + (f"   (coordinates in{u}: its header)" if u else ""))
    if rec.get("plane"):
        n = np.asarray(rec["plane"]["normal"])
        print(f"3D input    plane fit: normal ({n[0]:.4g}, {n[1]:.4g}, {n[2]:.4g}), "
              f"rms distance {rec['plane']['rms']:.4g}")
    if "side" in rec:
        print(f"side        {rec['side'] + 1}")
    if "fitted_points" in rec:      # --step: the polygon fitted, the file's points measured
        print(f"model       {rec['model']}  (the {rec['fitted_points']}-vertex polygon at step "
              f"{_fmt(rec['step'])}; rms, max error: the file's {rec['n_points']} points, "
              f"the polygon's rms {_fmt(rec['polygon_rms'])})")
    else:
        print(f"model       {rec['model']}  ({rec['n_points']} points)")
    if rec.get("curve"):
        # the start to the curve's size's digits (QA18 P1); a keyline side's in the file's
        # frame, its x''y'' one beside (the JSON's "curve")
        rows = [(rec["curve"], "")] if "curve_input" not in rec else [
            (rec["curve_input"], "   (the plane's x'y')" if rec.get("plane") else
             "   (the file's x, y)"), (rec["curve"], "   (x''y'': the keyline's PCA frame)")]
        for i, (curve, said) in enumerate(rows):
            print(("            " if i else "parameters  ")
                  + ", ".join(f"{k}={text}" for k, text in curve_values(curve)) + said)
        if "fitted_points" in rec:   # --step: whatever distance fitted the polygon (QA13)
            how = "point-to-curve: the file's points to the curve drawn"
        else:
            how = {"orthogonal": "point-to-curve distances",
                   "paired": "point-to-curve distances; fitted paired"}.get(rec.get("distance"), "")
        print(f"rms         {_fmt(rec['rms'])}{u}" + (f"   ({how})" if how else ""))
        print(f"max error   {_fmt(rec['max_error'])}{u}")
        print(f"iterations  {rec['iterations']}" + ("   (the one fit of both sides)"
                                                      if "side" in rec else ""))
        _print_uncertainty(rec)
    if rec.get("bspline"):
        _print_bspline(rec["bspline"], unit=u)
        if "fitted_points" not in rec:     # --step: the rms above is already the cubic's
            _print_cubic(rec, "points")
    print(f"status      {rec['status']}")


def _print_cubic(rec: Dict[str, Any], whose: str) -> None:
    """A discrete fit's B-spline's own distances to the points (_cubic_figures)."""
    if "bspline_rms" in rec:
        u = _unit(rec)
        print(f"            the {whose} lie rms {_fmt(rec['bspline_rms'])}{u}, max "
              f"{_fmt(rec['bspline_max_error'])}{u} from it (the rms and max error above "
              "are to the polygon)")


def _print_bspline(b: Dict[str, Any], what: str = "", unit: str = "") -> None:
    """The report's B-spline line; ``unit``: _unit's ' mm' after its max deviation."""
    dev = (f"max deviation {_fmt(b['max_deviation'])}{unit}"
           if b["max_deviation"] >= 0
           else "through the vertices (C2 cubic)")
    print(f"B-spline    {what}degree {b['degree']}, {len(b['poles'])} poles, {dev}")


def cmd_fit(args) -> int:
    files = args.files
    if not args.keyline:    # (a keyline refuses end conditions)
        _warn_turned_tangents(args)
    batch = len(files) > 1
    if not batch:
        recs, doc = fit_file(files[0], args, batch=False)
        if args.json == "-":
            write_json(doc, args.outputs.path(args.json))
        else:
            for i, r in enumerate(recs):
                if i:
                    print()
                _print_fit(r)
            if len(recs) > 1:       # a keyline: the file's own points to the whole curve
                print()
                r = recs[0]
                u = _unit(r)
                print(f"keyline     rms {_fmt(r['input_rms'])}{u}, max error "
                      f"{_fmt(r['input_max_error'])}{u}"
                      f"   (the file's {r['input_points']} points to the keyline, in its plane)")
                if doc.get("bspline"):
                    _print_bspline(doc["bspline"], "of the keyline: ", _unit(doc))
                    _print_cubic(doc, "file's points")
        return EXIT_OK if all(r["converged"] for r in recs) else EXIT_NOCONV
    progress = _Progress(len(files), args.progress or sys.stderr.isatty())
    rows, all_recs, docs, bad, internal = [], [], [], 0, 0
    for f in files:
        mark = args.outputs.mark()
        progress.clear()        # the file's warnings on a line of their own

        def failed(status: str):
            """The file's one record (its row and its JSON document): its outputs undone."""
            args.outputs.rollback(mark)
            return [{"file": f, "model": args.model, "curve": None, "rms": None,
                     "max_error": None, "status": status, "converged": False}]
        try:
            recs, doc = fit_file(f, args, batch=True)
        except NotConvergedError as exc:
            recs = failed(f"not converged: {exc}")
            doc = recs[0]
        except (InputError, ValueError) as exc:
            bad += 1
            recs = failed(f"bad input: {exc}")
            doc = recs[0]
        except Exception as exc:    # a bug met on one file: the other files are still fitted
            if os.environ.get("ELASTICA_DEBUG"):
                raise
            internal += 1
            recs = failed(f"internal error: {type(exc).__name__}: {exc}")
            doc = recs[0]
        for r in recs:
            name = f if "side" not in r else f"{f} [{r['side'] + 1}]"
            k = r["curve"]["k"] if r.get("curve") else None
            rows.append([name, r["model"], k, r["rms"], r["max_error"], _verdict(r)])
        all_recs += recs
        docs.append(doc)
        progress.step(Path(f).name)
    if args.json and "{stem}" not in args.json and (args.json == "-" or args.json.endswith(".json")):
        # each file's document, as one file's JSON holds it (a keyline's two sides together)
        write_json(docs, args.outputs.path(args.json))
    print(_table(["file", "model", "k", "rms", "max error", "status"], rows))
    n_noconv = sum(1 for r in all_recs if not r["converged"]) - bad - internal
    if internal:
        print(f"{PROG}: {internal} of {len(files)} files met an internal error (a bug: please "
              "report it; ELASTICA_DEBUG=1 for a traceback)", file=sys.stderr)
        return EXIT_INTERNAL
    if bad:
        print(f"{PROG}: {bad} of {len(files)} files had bad input", file=sys.stderr)
        return EXIT_BADINPUT
    return EXIT_NOCONV if n_noconv else EXIT_OK
