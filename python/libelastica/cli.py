"""The ``elastica`` command (also ``python -m libelastica``): fit elasticae to
measured points, solve Hermite problems, convert fitted curves to B-splines and
make elliptic blending curves, with JSON, SVG/PNG report pictures and DXF.

Exit status: 0 success, 1 a fit did not converge (or a Hermite problem has no
solution), 2 bad input (one line on stderr, no traceback).
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from ._ffi import NotConvergedError
from .cli_outputs import Outputs, check_outputs, out_path
from .io import (InputError, curve_from_dict, curve_to_dict, read_json, read_points,
                 write_dxf_spline, write_json)

EXIT_OK, EXIT_NOCONV, EXIT_BADINPUT, EXIT_INTERNAL = 0, 1, 2, 3

PROG = "elastica"

FIT_EXAMPLES = """examples:
  elastica fit points.csv --svg fit.svg --json fit.json
  elastica fit scan.csv --model smooth --png fit.png --bspline-tol 1e-4 --dxf fit.dxf
  elastica fit keyline_3d.csv --keyline --step 5 --svg keyline.svg   (3D: plane fit first)
  elastica fit a.csv b.csv c.npy --json 'out/{stem}.json' --svg out/   (batch + summary)
  elastica fit points.csv --fix x0,y0          (start pinned to the first data point)
  elastica fit points.csv --fix x0=0,y0=0,phi=0
  elastica fit sketch.csv --model smooth --start-point first --end-point last --start-tangent 90
  elastica fit scan.csv --model smooth --distance paired   (point i at arc length i L/(n-1))

input: CSV, whitespace separated text or .npy, 2 columns (x, y) or 3 (x, y, z);
'#' comments and one header line are allowed."""

HERMITE_EXAMPLES = """examples:
  elastica hermite 0 0 1 0  1 0 1 0 --tension 10 --svg hermite.svg
  elastica hermite 0 0 0 1  2 0 0 -1 --length 4 --json -"""

BSPLINE_EXAMPLES = """examples:
  elastica fit points.csv --model smooth --json fit.json
  elastica bspline fit.json --tol 1e-6 --json spline.json --dxf spline.dxf"""

BLEND_EXAMPLES = """examples:
  elastica blend 0 0  0.3 0.8  0.7 0.9  1 0 --m 0.3 --d 2 --svg blend.svg
  elastica blend 0 0 0.5 0.857 0.5 1 1 1 --mode control --m 0.3 --json -"""

G2QUAD_EXAMPLES = """examples:
  elastica g2quad curve.csv --edges 30 --svg g2.svg --dxf g2.dxf
  elastica fit points.csv --model smooth --json fit.json && elastica g2quad fit.json --json -"""


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors as ONE line on stderr (exit 2)."""

    def error(self, message: str):
        self.exit(EXIT_BADINPUT, f"{self.prog}: error: {message}\n")


class NoConvergence(Exception):
    """Raised inside the CLI when the command succeeded in form but a fit did not converge."""


# ------------------------------------------------------------------ helpers

def _fmt(v: Any, width: int = 0) -> str:
    if isinstance(v, float):
        s = f"{v:.6g}"
    elif v is None:
        s = "-"
    else:
        s = str(v)
    return s.rjust(width) if width else s


def _table(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    cells = [[_fmt(c) for c in r] for r in rows]
    widths = [max([len(h)] + [len(r[i]) for r in cells]) for i, h in enumerate(headers)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers, widths)),
             "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths)) for r in cells]
    return "\n".join(ln.rstrip() for ln in lines)


def _float_list(text: str, n: int, what: str) -> List[float]:
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise InputError(f"{what}: expected {n} comma-separated numbers, got {text!r}") from None
    if len(vals) != n or not all(np.isfinite(vals)):
        raise InputError(f"{what}: expected {n} finite comma-separated numbers, got {text!r}")
    return vals


def _finite(x: float, what: str) -> float:
    if not np.isfinite(x):
        raise InputError(f"{what} must be finite, got {x}")
    return x


def _status_text(status: Any) -> str:
    from ._ffi import ffi, lib
    if isinstance(status, (int, np.integer)) and not isinstance(status, bool):
        return "ok" if status == lib.EL_OK else ffi.string(lib.el_strerror(int(status))).decode()
    return str(status)


def _converged(res: Any) -> bool:
    """Whether a FitResult converged (its status EL_OK, or a 'converged' flag)."""
    from ._ffi import lib
    if hasattr(res, "converged"):
        return bool(res.converged)
    status = getattr(res, "status", 0)
    if isinstance(status, (int, np.integer)) and not isinstance(status, bool):
        return int(status) == lib.EL_OK
    if isinstance(status, bool):
        return status
    return str(status).lower() in ("ok", "converged", "success", "el_ok")


class _Progress:
    """A text progress bar on stderr (batch mode)."""

    def __init__(self, total: int, enabled: bool):
        self.total, self.enabled, self.done = total, enabled, 0

    def step(self, label: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        width = 30
        filled = int(width * self.done / max(self.total, 1))
        bar = "#" * filled + "." * (width - filled)
        sys.stderr.write(f"\r[{bar}] {self.done}/{self.total} {label[:40]:<40}")
        if self.done == self.total:
            sys.stderr.write("\n")
        sys.stderr.flush()


# ------------------------------------------------------------------ fit

def _parse_fix(spec: Optional[str], data: np.ndarray, keyline: bool = False) -> Dict[str, float]:
    """--fix 'x0,y0' (the start pinned to the first data point) or 'x0=1,y0=2,phi=0'
    (explicit values). With --keyline, x0/y0 are already pinned at the inflection, so
    bare 'x0'/'y0' are dropped."""
    fixed: Dict[str, float] = {}
    for item in (spec or "").split(","):
        item = item.strip()
        if not item:
            continue
        name, _, value = item.partition("=")
        name = name.strip()
        if value:
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


def _bspline_of(curve, tol: float, degree: int):
    """The B-spline of a fitted curve: tolerance-certified for a smooth elastica (or a
    Hermite chain of them); for a discrete one the C2 cubic through its vertices
    (max_deviation unknown, -1)."""
    from .core import DiscreteElastica
    if not isinstance(curve, DiscreteElastica):
        return curve.to_bspline(tol=tol, degree=degree)
    from .bspline import interpolate_c2
    return interpolate_c2(curve.points())


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


def _side_record(res, data: np.ndarray, model: str) -> Dict[str, Any]:
    rec = {"model": model, "n_points": int(len(data)),
           "curve": curve_to_dict(res.curve),
           "initial": curve_to_dict(res.initial) if res.initial is not None else None,
           "rms": float(res.rms), "max_error": float(res.max_error),
           "iterations": int(res.iterations), "status": _status_text(res.status),
           "converged": _converged(res)}
    if getattr(res, "distances", None) is not None:
        # point-to-curve distances (+ = left of the curve) and each foot's arc length
        rec.update(distance=res.distance, distances=[float(v) for v in res.distances],
                   foot_s=[float(v) for v in res.foot_s])
    return rec


def _constraints(args, data: np.ndarray) -> Dict[str, Any]:
    """el.fit's constraints from the command line (angles in degrees there)."""
    con: Dict[str, Any] = {}
    for end, idx, word in (("start", 0, "first"), ("end", -1, "last")):
        spec = getattr(args, f"{end}_point")
        if spec is not None:
            con[f"{end}_point"] = (tuple(float(v) for v in data[idx, :2]) if spec.strip() == word
                                   else tuple(_float_list(spec, 2, f"--{end}-point")))
        ang = getattr(args, f"{end}_tangent")
        if ang is not None:
            con[f"{end}_tangent"] = np.radians(_finite(ang, f"--{end}-tangent"))
        kap = getattr(args, f"{end}_curvature")
        if kap is not None:
            con[f"{end}_curvature"] = _finite(kap, f"--{end}-curvature")
    for name in ("length", "k"):
        spec = getattr(args, name if name == "length" else "k_range")
        if spec is not None:
            lo, _, hi = spec.partition(",")
            try:
                con[name] = (float(lo) if lo.strip() else None, float(hi) if hi.strip() else None)
            except ValueError:
                raise InputError(f"--{name}: expected LO,HI (either may be empty), got {spec!r}") from None
    return con


def _plane_record(frame) -> Optional[Dict[str, Any]]:
    if frame is None:
        return None
    return {"origin": frame.origin, "normal": frame.e3, "e1": frame.e1, "e2": frame.e2,
            "rms": frame.rms}


def fit_file(path: str, args, batch: bool) -> List[Dict[str, Any]]:
    """Fit one file; returns one record per fitted curve (two with --keyline) and writes
    the requested outputs. Raises InputError / ValueError for bad input."""
    import libelastica as el
    pts = read_points(path, min_points=4)
    if args.step is not None:
        _finite(args.step, "--step")
    records: List[Dict[str, Any]] = []
    pictures = []                       # (data (n,2), FitResult) per record
    extra_info: Dict[str, Any] = {}
    if args.keyline:
        # seed 000 §5 as one G2 curve: plane fit, resampling (segment --step),
        # re-normalisation, inflection, two elasticae sharing the joint
        if _constraints(args, pts) or getattr(args, "distance", None):
            raise InputError("--keyline: the joint is the keyline's constraint; end constraints "
                             "and --distance apply to one-piece fits")
        fixed = _parse_fix(args.fix, pts[:, :2], keyline=True)
        kres = el.fit_keyline(pts, r=args.step, **_fit_kwargs(args, fixed))
        prep = kres.prepared
        plane = _plane_record(prep.frame)
        to_input = prep.to_input
        extra_info = {"inflection_index": int(kres.inflection),
                      "inflection_point": prep.to_input(kres.joint),
                      "step": prep.r, "coordinates": "x''y'' (PCA frame of the resampled polygon)",
                      "frame2d": {"origin": prep.frame2d.origin, "f1": prep.frame2d.f1,
                                  "f2": prep.frame2d.f2}}
        for i, res in enumerate((kres.first, kres.second)):
            rec = _side_record(res, res.points, args.model)
            rec["side"] = i
            records.append(rec)
            pictures.append((res.points, res))
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
            total = float(np.sum(np.linalg.norm(np.diff(xy, axis=0), axis=1)))
            if not 0 < args.step < total:
                raise InputError(f"{path}: --step must be in (0, {total:.6g}) (the polyline's "
                                 f"length), got {args.step}")
            data = el.resample_equilateral(xy, args.step)
            if len(data) < 4:
                raise InputError(f"{path}: --step {args.step} leaves only {len(data)} points")
        res = el.fit(data, **_fit_kwargs(args, _parse_fix(args.fix, data), _constraints(args, data)))
        records.append(_side_record(res, data, args.model))
        pictures.append((data, res))
    for rec in records:
        rec.update({"file": str(path), "plane": plane, "step": args.step, **extra_info})
    splines = []
    if args.bspline_tol is not None or args.dxf:
        tol = _finite(args.bspline_tol if args.bspline_tol is not None else 1e-6, "--bspline-tol")
        for rec, (_, res) in zip(records, pictures):
            b = _bspline_of(res.curve, tol, args.degree)
            rec["bspline"] = b.to_dict()
            splines.append(b)
    if to_input is not None:
        # B-splines are affine invariant: mapping the poles maps the curve exactly, so the
        # DXF gets the curves in the input's coordinates (3D for 3D input)
        from .bspline import BSpline
        splines = [BSpline(b.degree, to_input(b.poles), b.knots, b.mults, b.max_deviation)
                   for b in splines]
    _write_fit_outputs(path, args, batch, records, pictures, splines, pts)
    return records


def _write_fit_outputs(path, args, batch, records, pictures, splines, points) -> None:
    """JSON, pictures (in the fit's plane coordinates) and DXF (splines and points in the
    input's coordinates) of one file."""
    from .report import fit_picture, save_picture
    jpath = out_path(args.json, path, ".json", batch) if args.json and args.json != "-" and not (
        batch and args.json.endswith(".json") and "{stem}" not in args.json) else None
    if jpath is not None:
        write_json(records[0] if len(records) == 1 else {"file": str(path), "sides": records},
                   args.outputs.path(jpath))
    for spec, ext in ((args.svg, ".svg"), (args.png, ".png")):
        out = out_path(spec, path, ext, batch)
        if out is None or not pictures:
            continue
        pic = None
        for i, ((d, res), rec) in enumerate(zip(pictures, records)):
            extra = [f"rms = {rec['rms']:.4g}, max error = {rec['max_error']:.4g}",
                     f"iterations = {rec['iterations']}, status = {rec['status']}"]
            if rec.get("plane"):
                extra.append(f"plane fit rms = {rec['plane']['rms']:.4g}")
            p = fit_picture(d, res.curve, res.initial, model_points=res.foot_points(),
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
                         points=points)


def _print_fit(rec: Dict[str, Any]) -> None:
    print(f"file        {rec['file']}")
    if rec.get("plane"):
        n = np.asarray(rec["plane"]["normal"])
        print(f"3D input    plane fit: normal ({n[0]:.4g}, {n[1]:.4g}, {n[2]:.4g}), "
              f"rms distance {rec['plane']['rms']:.4g}")
    if "side" in rec:
        print(f"side        {rec['side'] + 1}")
    print(f"model       {rec['model']}  ({rec['n_points']} points)")
    if rec.get("curve"):
        print("parameters  " + ", ".join(f"{k}={_fmt(v)}" for k, v in rec["curve"].items()
                                         if k != "type"))
        how = {"orthogonal": "point-to-curve", "paired": "point-to-curve; fitted paired"}.get(
            rec.get("distance"), "")
        print(f"rms         {_fmt(rec['rms'])}" + (f"   ({how} distances)" if how else ""))
        print(f"max error   {_fmt(rec['max_error'])}")
        print(f"iterations  {rec['iterations']}")
    if rec.get("bspline"):
        b = rec["bspline"]
        dev = (f"max deviation {_fmt(b['max_deviation'])}" if b["max_deviation"] >= 0
               else "through the vertices (C2 cubic)")
        print(f"B-spline    degree {b['degree']}, {len(b['poles'])} poles, {dev}")
    print(f"status      {rec['status']}")


def cmd_fit(args) -> int:
    files = args.files
    batch = len(files) > 1
    if not batch:
        recs = fit_file(files[0], args, batch=False)
        if args.json == "-":
            write_json(recs[0] if len(recs) == 1 else {"file": files[0], "sides": recs}, "-")
        else:
            for i, r in enumerate(recs):
                if i:
                    print()
                _print_fit(r)
        return EXIT_OK if all(r["converged"] for r in recs) else EXIT_NOCONV
    progress = _Progress(len(files), args.progress or sys.stderr.isatty())
    rows, all_recs, bad = [], [], 0
    for f in files:
        mark = args.outputs.mark()
        try:
            recs = fit_file(f, args, batch=True)
        except NotConvergedError as exc:
            args.outputs.rollback(mark)
            recs = [{"file": f, "model": args.model, "curve": None, "rms": None,
                     "max_error": None, "status": f"not converged: {exc}", "converged": False}]
        except (InputError, ValueError) as exc:
            args.outputs.rollback(mark)
            bad += 1
            recs = [{"file": f, "model": args.model, "curve": None, "rms": None,
                     "max_error": None, "status": f"bad input: {exc}", "converged": False}]
        for r in recs:
            name = f if "side" not in r else f"{f} [{r['side'] + 1}]"
            k = r["curve"]["k"] if r.get("curve") else None
            rows.append([name, r["model"], k, r["rms"], r["max_error"], r["status"]])
        all_recs += recs
        progress.step(Path(f).name)
    if args.json and "{stem}" not in args.json and (args.json == "-" or args.json.endswith(".json")):
        write_json(all_recs, "-" if args.json == "-" else args.outputs.path(args.json))
    if args.json != "-":
        print(_table(["file", "model", "k", "rms", "max error", "status"], rows))
    n_noconv = sum(1 for r in all_recs if not r["converged"]) - bad
    if bad:
        print(f"{PROG}: {bad} of {len(files)} files had bad input", file=sys.stderr)
        return EXIT_BADINPUT
    return EXIT_NOCONV if n_noconv else EXIT_OK


# ------------------------------------------------------------------ hermite

def cmd_hermite(args) -> int:
    import libelastica as el
    from .report import curves_picture, save_picture
    v = [_finite(x, "hermite coordinates") for x in args.values]
    p0, t0, p1, t1 = v[0:2], v[2:4], v[4:6], v[6:8]
    kw = {"tension": args.tension} if args.tension is not None else {"length": args.length}
    _finite(next(iter(kw.values())), "--tension/--length")
    sols = el.hermite(p0, t0, p1, t1, **kw)
    rows, recs = [], []
    for i, c in enumerate(sols):
        e = getattr(c, "energy_value", None)
        rec = {"index": i, "curve": curve_to_dict(c), "sigma": getattr(c, "sigma", None),
               "energy": e if e is not None else c.energy(),
               "has_inflection": getattr(c, "has_inflection", None),
               "kappa0": getattr(c, "kappa0", None), "kappa1": getattr(c, "kappa1", None),
               "residual": getattr(c, "residual", None)}
        recs.append(rec)
        # near the separatrix a chain of pieces ("curve": {"type": "chain", ...}), k its first piece's
        rows.append([i, rec["sigma"], c.length, c.k, rec["energy"],
                     "yes" if rec["has_inflection"] else "no", rec["kappa0"], rec["kappa1"],
                     rec["residual"]])
    out = {"p0": p0, "t0": t0, "p1": p1, "t1": t1, **kw, "solutions": recs}
    if args.json:
        write_json(out, "-" if args.json == "-" else args.outputs.path(args.json))
    if args.json != "-":
        if rows:
            print(_table(["#", "sigma", "length", "k", "energy", "inflection", "kappa0",
                          "kappa1", "residual"], rows))
        else:
            print("no elastica through these points and tangents")
    for spec in (args.svg, args.png):
        if spec:
            what = f"tension {args.tension:g}" if args.tension is not None else \
                f"length {args.length:g}"
            drawn = []
            for c in sols:             # every solution runs p0 -> p1 (k < -1: clockwise loop)
                s = np.linspace(0.0, c.length, 400)
                drawn.append((c.points(s), s, c.curvature(s)))
            pic = curves_picture(drawn, [f"solution {i} (E = {r['energy']:.4g})"
                                        for i, r in enumerate(recs)],
                                 points=np.array([p0, p1]),
                                 title=f"Hermite elasticae, {what}: {len(sols)} solutions",
                                 params=[f"p0 = ({p0[0]:g}, {p0[1]:g}), t0 = ({t0[0]:g}, {t0[1]:g})",
                                         f"p1 = ({p1[0]:g}, {p1[1]:g}), t1 = ({t1[0]:g}, {t1[1]:g})"]
                                 + [f"#{i}: k={c.k:.4g} L={c.length:.4g}"
                                    + (f" ({len(c.pieces)} pieces)" if hasattr(c, "pieces") else "")
                                    for i, c in enumerate(sols[:12])])
            save_picture(pic, args.outputs.path(spec))
    if not sols:
        print(f"{PROG} hermite: no solution", file=sys.stderr)
        return EXIT_NOCONV
    return EXIT_OK


# ------------------------------------------------------------------ bspline

def cmd_bspline(args) -> int:
    doc = read_json(args.file)
    items = doc.get("sides") if isinstance(doc, dict) and "sides" in doc else \
        (doc if isinstance(doc, list) else [doc])
    curves = [curve_from_dict(it, name=args.file) for it in items]
    _finite(args.tol, "--tol")
    splines = [_bspline_of(c, args.tol, args.degree) for c in curves]
    out = [{"curve": curve_to_dict(c), "bspline": b.to_dict()} for c, b in zip(curves, splines)]
    result = out[0] if len(out) == 1 else {"sides": out}
    if args.json:
        write_json(result, "-" if args.json == "-" else args.outputs.path(args.json))
    if args.json != "-":
        for c, b in zip(curves, splines):
            dev = (f"max deviation {b.max_deviation:.3g}" if b.max_deviation >= 0 else
                   "interpolates the vertices (deviation between them not certified)")
            print(f"{type(c).__name__}: B-spline degree {b.degree}, {b.npoles} poles, "
                  f"{len(b.knots)} knots, {dev}")
    if args.dxf:
        write_dxf_spline(splines, args.outputs.path(args.dxf))
    return EXIT_OK


# ------------------------------------------------------------------ blend

def cmd_blend(args) -> int:
    import libelastica as el
    from .report import curves_picture, polygon_curvature, save_picture
    v = [_finite(x, "blend coordinates") for x in args.values]
    pts = np.array(v, dtype=np.float64).reshape(4, 2)
    kw = {"m": args.m} if args.m is not None else {"k": args.k if args.k is not None else 0.5}
    curve = el.blend_curve(pts, d=args.d, mode=args.mode, **kw)
    xy = curve.points(np.linspace(0.0, curve.nseg, 401))
    s, kappa = polygon_curvature(xy)
    rec = {"k": curve.basis.k, "m": curve.basis.m, "d": curve.basis.d, "mode": args.mode,
           "points": pts, "control_points": curve.q, "basis_min": curve.basis.basis_min,
           "convex_hull": curve.basis.convex_hull, "lebesgue": curve.basis.lebesgue,
           "condition": curve.basis.condition}
    for w in curve.basis.warnings():
        print(f"{PROG} blend: warning: {w}", file=sys.stderr)
    b = None
    if args.tol is not None or args.dxf:
        b = curve.to_bspline(_finite(args.tol if args.tol is not None else 1e-6, "--tol"))
        rec["bspline"] = b.to_dict()
    if args.json:
        write_json(rec, "-" if args.json == "-" else args.outputs.path(args.json))
    if args.json != "-":
        print(f"elliptic blend: k = {curve.basis.k:.6g} (m = {curve.basis.m:.6g}), "
              f"d = {curve.basis.d:.6g}, K = {curve.basis.K:.6g}")
        print(_table(["control point", "x", "y"], [[i, q[0], q[1]] for i, q in enumerate(curve.q)]))
        if b is not None:
            print(f"B-spline: degree {b.degree}, {b.npoles} poles, max deviation "
                  f"{b.max_deviation:.3g}")
    for spec in (args.svg, args.png):
        if spec:
            pic = curves_picture([(xy, s, kappa)], ["blend curve"], points=pts,
                                 title="elliptic blending curve (seed 003)",
                                 params=[f"k = {curve.basis.k:.6g}", f"m = k^2 = {curve.basis.m:.6g}",
                                         f"d = {curve.basis.d:.6g}", f"mode = {args.mode}"]
                                 + [f"q{i} = ({q[0]:.4g}, {q[1]:.4g})" for i, q in enumerate(curve.q)])
            from .report import Layer
            pic.layers.insert(1, Layer(np.asarray(curve.q), "control polygon", "#1f77b4",
                                       marker="o", line=True, size=4.0))
            save_picture(pic, args.outputs.path(spec))
    if args.dxf:
        write_dxf_spline(b, args.outputs.path(args.dxf), points=pts)
    return EXIT_OK


# ------------------------------------------------------------------ spline

def cmd_spline(args) -> int:
    import libelastica as el
    from .io import bspline_to_dict
    from .report import curves_picture, save_picture
    pts = read_points(args.file, min_points=2)
    if pts.shape[1] != 2:
        raise InputError(f"{args.file}: an elastic spline needs 2 columns (x, y), got 3")
    kw = {"tension": args.tension} if args.length is None else {"length": args.length}
    _finite(next(iter(kw.values())), "--tension/--length")
    ends = {}
    for name in ("start", "end"):
        t, k = getattr(args, f"{name}_tangent"), getattr(args, f"{name}_curvature")
        if k is not None and t is None:
            raise InputError(f"--{name}-curvature needs --{name}-tangent (a G2 end)")
        if t is not None and args.closed:
            raise InputError(f"--{name}-tangent: a closed curve has no ends")
        ends[name] = None if t is None else (
            t if k is None else {"tangent": t, "curvature": _finite(k, f"--{name}-curvature")})
    sp = el.elastic_spline(pts, **kw, start=ends["start"], end=ends["end"], closed=args.closed)
    need_b = args.dxf or args.bspline_tol is not None
    b = sp.to_bspline(_finite(args.bspline_tol or 1e-6, "--bspline-tol"), args.degree) \
        if need_b else None
    rec = {"file": args.file, "points": sp.data.tolist(), "closed": sp.closed, **kw,
           "tension": sp.tension, "length": sp.length, "energy": sp.energy,
           "max_curvature": sp.max_curvature, "residual": sp.residual,
           "pieces": [curve_to_dict(c) for c in sp.pieces], "guides": sp.guides.tolist(),
           "guide_forces": sp.guide_forces.tolist(), "guide_pieces": sp.guide_pieces,
           "forces": sp.forces.tolist(), "angles": sp.angles.tolist(),
           "curvatures": sp.curvatures.tolist(),
           "bspline": bspline_to_dict(b) if b is not None else None}
    if args.json:
        write_json(rec, args.json)
    if args.json != "-":
        print(_table(["points", "pieces", "tension", "length", "energy", "max curvature",
                      "residual"], [[len(sp.data), len(sp.pieces), sp.tension, sp.length,
                                     sp.energy, sp.max_curvature, sp.residual]]))
        if b is not None:
            print(f"B-spline: degree {b.degree}, {len(b.poles)} poles, certified within "
                  f"{b.max_deviation:.3g}")
    if args.dxf:
        write_dxf_spline(b, args.dxf, points=sp.data)
    for spec in (args.svg, args.png):
        if spec:
            n = max(400, 40 * len(sp.pieces))
            s = sp.arclengths(n)
            xy, comb = sp.points(n), sp.comb(n)
            what = f"tension {sp.tension:.6g}" + (f" (length {args.length:g})"
                                                  if args.length is not None else "")
            pic = curves_picture([(xy, s, sp.curvature(n)), (comb, s, None)],
                                 ["elastic spline", "curvature comb"], points=sp.data,
                                 title=f"Elastic spline through {len(sp.data)} points, {what}",
                                 params=[f"pieces {len(sp.pieces)}", f"tension {sp.tension:.6g}",
                                         f"length {sp.length:.6g}", f"energy {sp.energy:.6g}",
                                         f"max curvature {sp.max_curvature:.6g}",
                                         f"residual {sp.residual:.2g}"])
            save_picture(pic, spec)
    return EXIT_OK


# ------------------------------------------------------------------ g2quad

def cmd_g2quad(args) -> int:
    """Seed 002: a curve (points, or a smooth elastica from 'fit --json') -> one G2
    quadratic B-spline per inflection-free piece, ending exactly on the curve."""
    import libelastica as el
    from .bspline import BSpline
    from .core import SmoothElastica
    from .report import Layer, curves_picture, save_picture
    source, frame, plane = args.file, None, None
    if args.edges is not None and args.edges < 3:
        raise InputError(f"--edges must be at least 3, got {args.edges}")
    if args.file.lower().endswith(".json"):
        doc = read_json(args.file)
        items = doc.get("sides") if isinstance(doc, dict) and "sides" in doc else [doc]
        if len(items) != 1:
            raise InputError(f"{args.file}: {len(items)} curves; give one (e.g. one side's JSON)")
        curve = curve_from_dict(items[0], name=args.file)
        src = curve if isinstance(curve, SmoothElastica) else curve.points()
        curve_source = src is curve
        data = curve.points(np.linspace(0.0, curve.length, 400)) if curve_source else src
        n = args.edges or 40
    else:
        pts = read_points(args.file, min_points=4)
        if pts.shape[1] == 3:
            src, frame = el.plane_fit(pts)
            plane = _plane_record(frame)
        else:
            src = pts
        data, curve_source = src, False
        n = args.edges or max(6, (len(src) - 1) // 20)    # seed 002 §4.2: ~20 samples per vertex
    g = el.g2_quadratic(src, n)
    jumps = f"{g.curvature_jump:.2g}"
    rec = {"file": str(source), "edges": int(n), "pieces": len(g.bsplines), "plane": plane,
           "ends": g.ends, "covers_source": g.covers_source, "deviation": g.deviation,
           "curvature_jump": g.curvature_jump, "end_tangent_error_rad": g.end_tangent_error,
           "polyline": g.polyline.points, "A": g.polyline.A,
           "bsplines": [b.to_dict() for b in g.bsplines]}
    if args.json:
        write_json(rec, args.json)
    if args.json != "-":
        pieces = len(g.bsplines)
        split = f"{pieces} pieces split at {pieces - 1} inflection(s)" if pieces > 1 else \
            "1 inflection-free piece"
        print(f"G2 quadratic B-spline: {split}, {n} edges, {g.npoles} poles (degree 2, "
              "uniform inside)")
        print(f"  starts at ({g.ends[0][0]:.6g}, {g.ends[0][1]:.6g}), ends at "
              f"({g.ends[-1][0]:.6g}, {g.ends[-1][1]:.6g}), exactly on the source")
        if not g.covers_source:
            print("  warning: an end of the source next to an inflection is left out (too short "
                  "for 3 edges); noisy points: fit first (elastica fit --model smooth --json) "
                  "and pass the JSON", file=sys.stderr)
        print(f"  largest relative curvature jump at a joint: {jumps} (G2)")
        print(f"  largest distance from the source: {g.deviation:.3g}")
        if g.end_tangent_error is not None:
            print(f"  end tangents off the source's by at most {np.degrees(g.end_tangent_error):.3g} deg")
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
            save_picture(pic, spec)
    if args.dxf:
        splines = g.bsplines if frame is None else [
            BSpline(b.degree, frame.to_3d(b.poles), b.knots, b.mults) for b in g.bsplines]
        write_dxf_spline(splines, args.dxf)
    return EXIT_OK


# ------------------------------------------------------------------ parser

def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``elastica`` command."""
    p = _Parser(prog=PROG, formatter_class=argparse.RawDescriptionHelpFormatter,
                description="Euler's elastica for CAD: fit measured points, Hermite "
                            "interpolation, B-splines, elliptic blends.",
                epilog="examples:\n  elastica fit points.csv --svg fit.svg --json fit.json\n"
                       "  elastica hermite 0 0 1 0 1 0 1 0 --tension 10\n"
                       "  elastica bspline fit.json --tol 1e-6 --dxf fit.dxf\n"
                       "  elastica blend 0 0 0.3 0.8 0.7 0.9 1 0 --svg blend.svg\n"
                       "  elastica COMMAND --help   (more examples)\n\n"
                       "exit status: 0 ok, 1 fit did not converge / no solution, 2 bad input")
    from . import __version__
    p.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    raw = argparse.RawDescriptionHelpFormatter

    f = sub.add_parser("fit", help="fit an elastica to points (CSV / text / .npy)",
                       description="Fit a discrete (seed 000) or smooth elastica to measured "
                                   "points; several files run as a batch with a summary table.",
                       epilog=FIT_EXAMPLES, formatter_class=raw)
    f.add_argument("files", nargs="+", metavar="FILE", help="point files (2 or 3 columns)")
    f.add_argument("--model", choices=("discrete", "smooth"), default="discrete",
                   help="elastica model (default: discrete)")
    f.add_argument("--keyline", action="store_true",
                   help="split at the estimated inflection and fit each side (seed 000 §5)")
    f.add_argument("--fix", metavar="NAMES",
                   help="parameters held fixed: 'x0,y0' (start at the first point) or "
                        "'x0=0,y0=0,phi=0'")
    f.add_argument("--distance", choices=("orthogonal", "paired"),
                   help="what is minimised: the points' distances to the curve or polygon "
                        "(default; the discrete model on evenly spaced points: paired) or "
                        "point i <-> vertex i / arc length i L/(n-1)")
    c = f.add_argument_group("constraints (met to 1e-10 of the data's size, or exit 2 naming "
                             "the one that cannot be met)")
    c.add_argument("--start-point", metavar="X,Y|first", help="the curve starts here")
    c.add_argument("--end-point", metavar="X,Y|last", help="the curve ends here")
    c.add_argument("--start-tangent", type=float, metavar="DEG",
                   help="tangent direction at the start (degrees, the direction of travel)")
    c.add_argument("--end-tangent", type=float, metavar="DEG", help="tangent direction at the end")
    c.add_argument("--start-curvature", type=float, metavar="K",
                   help="curvature at the start (1/units, + turning left; 0: a free end)")
    c.add_argument("--end-curvature", type=float, metavar="K", help="curvature at the end")
    c.add_argument("--length", metavar="LO,HI", help="range of the curve's length (either may be empty)")
    c.add_argument("--k", dest="k_range", metavar="LO,HI", help="range of the modulus k")
    f.add_argument("--step", type=float, metavar="R",
                   help="resample into an equilateral polygon of segment R first")
    f.add_argument("--json", metavar="PATH", help="write the result as JSON ('-' = stdout)")
    f.add_argument("--svg", metavar="PATH", help="write the report picture as SVG")
    f.add_argument("--png", metavar="PATH", help="write the report picture as PNG (matplotlib)")
    f.add_argument("--bspline-tol", type=float, metavar="TOL",
                   help="add the B-spline of the fitted curve (within TOL for smooth)")
    f.add_argument("--degree", type=int, default=3, help="B-spline degree (default 3)")
    f.add_argument("--max-iter", type=int, metavar="N", help="Ipopt iterations per start (default 200)")
    f.add_argument("--dxf", metavar="PATH", help="write the B-spline as a DXF SPLINE (ezdxf)")
    f.add_argument("--progress", action="store_true",
                   help="always draw the batch progress bar (default: when stderr is a terminal)")
    f.set_defaults(func=cmd_fit)

    h = sub.add_parser("hermite", help="all elasticae between two points with tangents",
                       description="All elastic curves from (x0,y0) with tangent (tx0,ty0) to "
                                   "(x1,y1) with tangent (tx1,ty1), of given tension or length "
                                   "(seed 004).", epilog=HERMITE_EXAMPLES, formatter_class=raw)
    h.add_argument("values", nargs=8, type=float, metavar="V",
                   help="x0 y0 tx0 ty0 x1 y1 tx1 ty1")
    g = h.add_mutually_exclusive_group(required=True)
    g.add_argument("--tension", type=float, metavar="SIGMA", help="tension sigma")
    g.add_argument("--length", type=float, metavar="L", help="arc length")
    h.add_argument("--json", metavar="PATH", help="write the solutions as JSON ('-' = stdout)")
    h.add_argument("--svg", metavar="PATH", help="picture of all solutions (SVG)")
    h.add_argument("--png", metavar="PATH", help="picture of all solutions (PNG, matplotlib)")
    h.set_defaults(func=cmd_hermite)

    b = sub.add_parser("bspline", help="B-spline of a fitted curve's JSON",
                       description="Convert the curve in a JSON written by 'fit --json' into a "
                                   "B-spline (certified within --tol for a smooth elastica; the "
                                   "C2 cubic through the vertices for a discrete one).",
                       epilog=BSPLINE_EXAMPLES, formatter_class=raw)
    b.add_argument("file", metavar="FIT.json")
    b.add_argument("--tol", type=float, default=1e-6, help="tolerance (default 1e-6)")
    b.add_argument("--degree", type=int, default=3, help="degree (default 3)")
    b.add_argument("--json", metavar="PATH", help="write the B-spline as JSON ('-' = stdout)")
    b.add_argument("--dxf", metavar="PATH", help="write a DXF SPLINE (needs ezdxf)")
    b.set_defaults(func=cmd_bspline)

    sp = sub.add_parser(
        "spline", help="elastic spline (a batten) through points",
        description="The elastic spline through the points: a chain of elasticae of one "
                    "tension, G2 at every point (a batten through its ducks), with its "
                    "curvature comb, forces and one certified G2 B-spline.",
        epilog="examples:\n  elastica spline ducks.csv --tension 0.5 --svg spline.svg\n"
               "  elastica spline ducks.csv --length 12.5 --json - \n"
               "  elastica spline ring.csv --closed --tension 1 --dxf ring.dxf\n"
               "  elastica spline ducks.csv --start-tangent 1 0 --start-curvature 0.2\n\n"
               "input: CSV, whitespace separated text or .npy, 2 columns (x, y)",
        formatter_class=raw)
    sp.add_argument("file", metavar="FILE", help="the points (2 columns)")
    g = sp.add_mutually_exclusive_group()
    g.add_argument("--tension", type=float, default=0.0, metavar="SIGMA",
                   help="tension sigma >= 0, 1/length^2 (default 0: the free-sliding batten)")
    g.add_argument("--length", type=float, metavar="L", help="total length (sigma computed)")
    sp.add_argument("--closed", action="store_true", help="a closed curve through the points")
    for name in ("start", "end"):
        sp.add_argument(f"--{name}-tangent", type=float, nargs=2, metavar=("TX", "TY"),
                        help=f"clamp the {name} tangent (default: natural, curvature 0)")
        sp.add_argument(f"--{name}-curvature", type=float, metavar="K",
                        help=f"and its curvature: G2 to other geometry (needs --{name}-tangent)")
    sp.add_argument("--bspline-tol", type=float, metavar="TOL",
                    help="add the B-spline within TOL to the JSON (default 1e-6 with --dxf)")
    sp.add_argument("--degree", type=int, default=3, help="B-spline degree 3..7 (default 3)")
    sp.add_argument("--json", metavar="PATH", help="write the spline as JSON ('-' = stdout)")
    sp.add_argument("--svg", metavar="PATH", help="picture with the curvature comb (SVG)")
    sp.add_argument("--png", metavar="PATH", help="picture with the curvature comb (PNG)")
    sp.add_argument("--dxf", metavar="PATH", help="write the B-spline as a DXF SPLINE (ezdxf)")
    sp.set_defaults(func=cmd_spline)

    e = sub.add_parser("blend", help="elliptic blending curve from four points (seed 003)",
                       description="An elliptic blending curve (basis {1-t, sn((1-t)K), sn(Kt), "
                                   "t}) through four points, or with them as control points.",
                       epilog=BLEND_EXAMPLES, formatter_class=raw)
    e.add_argument("values", nargs=8, type=float, metavar="V", help="x0 y0 x1 y1 x2 y2 x3 y3")
    km = e.add_mutually_exclusive_group()
    km.add_argument("--k", type=float, help="elliptic modulus k in [0, 1) (default 0.5)")
    km.add_argument("--m", type=float, help="elliptic parameter m = k^2 (the paper's 'k')")
    e.add_argument("--d", type=float, default=2.0, help="end-derivative parameter (default 2)")
    e.add_argument("--mode", choices=("interpolate", "control"), default="interpolate",
                   help="pass through the points (default) or use them as control points")
    e.add_argument("--tol", type=float, metavar="TOL", help="add the cubic B-spline within TOL")
    e.add_argument("--json", metavar="PATH", help="write the result as JSON ('-' = stdout)")
    e.add_argument("--svg", metavar="PATH", help="picture (SVG)")
    e.add_argument("--png", metavar="PATH", help="picture (PNG, matplotlib)")
    e.add_argument("--dxf", metavar="PATH", help="write the B-spline as a DXF SPLINE (ezdxf)")
    e.set_defaults(func=cmd_blend)

    q = sub.add_parser("g2quad", help="curvature-continuous quadratic B-spline of a curve (seed 002)",
                       description="Approximate a curve (points: CSV / text / .npy, 2 or 3 "
                                   "columns; or a smooth elastica from 'fit --json') by an affine "
                                   "arc-length polyline and build one G2 uniform quadratic "
                                   "B-spline per inflection-free piece, ending exactly on the "
                                   "curve's ends and inflections.",
                       epilog=G2QUAD_EXAMPLES, formatter_class=raw)
    q.add_argument("file", metavar="FILE", help="points (a dense sampling: ~20 per edge) or FIT.json")
    q.add_argument("--edges", type=int, metavar="N",
                   help="polyline edges (default: points/20, at least 6; 40 for a fit)")
    q.add_argument("--json", metavar="PATH", help="write the result as JSON ('-' = stdout)")
    q.add_argument("--svg", metavar="PATH", help="picture (SVG)")
    q.add_argument("--png", metavar="PATH", help="picture (PNG, matplotlib)")
    q.add_argument("--dxf", metavar="PATH", help="write the B-splines as DXF SPLINEs (ezdxf)")
    q.set_defaults(func=cmd_g2quad)
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the ``elastica`` command; returns the exit status (0, 1 or 2)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    args.outputs = Outputs(list(getattr(args, "files", None) or []) + [getattr(args, "file", None)]
                            + list(getattr(args, "inputs", None) or []))
    try:
        try:
            check_outputs(args)
            status = args.func(args)
            args.outputs.commit()
            return status
        except NotConvergedError as exc:
            args.outputs.abort()
            print(f"{PROG} {args.command}: did not converge: {exc}", file=sys.stderr)
            return EXIT_NOCONV
        except BaseException:
            args.outputs.abort()
            raise
    except (InputError, ValueError, OSError, OverflowError) as exc:
        msg = " ".join(str(exc).split()) or type(exc).__name__
        print(f"{PROG} {args.command}: {msg}", file=sys.stderr)
        return EXIT_BADINPUT
    except KeyboardInterrupt:
        print(f"{PROG}: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:   # a bug: one line unless ELASTICA_DEBUG asks for the traceback
        if os.environ.get("ELASTICA_DEBUG"):
            raise
        print(f"{PROG} {args.command}: internal error: {type(exc).__name__}: {exc} "
              "(set ELASTICA_DEBUG=1 for a traceback)", file=sys.stderr)
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
