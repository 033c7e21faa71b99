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
import tempfile
from pathlib import Path
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from ._ffi import NotConvergedError
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


def _out_path(spec: Optional[str], source: str, ext: str, batch: bool) -> Optional[Path]:
    """Output path for one input: spec itself, spec with {stem} filled in, or (batch,
    no {stem}) a directory spec/ holding <stem><ext>. Nothing is created here:
    :class:`_Outputs` makes the directories when the file is written."""
    if not spec:
        return None
    stem = Path(source).stem
    if "{stem}" in spec:
        return Path(spec.replace("{stem}", stem))
    if batch:
        return Path(spec) / f"{stem}{ext}"
    return Path(spec)


class _Outputs:
    """The one place the command writes files (every subcommand goes through it).

    - An output that is one of the command's inputs (the same file: by os.path.samefile,
      so ``./a.csv``, links and ``{stem}`` patterns are caught) is refused before
      anything is written (InputError: exit 2); so is a path given twice.
    - Each output is written to a temporary next to it (same suffix, so the writers
      still choose the format by it); :meth:`commit` renames them all into place
      only when every one was written, :meth:`abort` removes them (and the
      directories made for them): a failing output leaves nothing behind.

    A subcommand names its input files ``file`` / ``files`` (or sets ``args.inputs``)
    and writes with ``path = args.outputs.path(target)`` then ``write_x(..., path)``.
    """

    def __init__(self, inputs: Sequence[str]):
        self._inputs = [Path(p) for p in inputs if p and p != "-" and Path(p).exists()]
        self._staged: List[tuple] = []      # (temporary, final)
        self._finals: set = set()
        self._made: List[Path] = []         # directories created, deepest last

    def check(self, target) -> Path:
        """Refuse target when it is an input or already an output of this command."""
        final = Path(target)
        if final.exists():
            for inp in self._inputs:
                try:
                    same = os.path.samefile(final, inp)
                except OSError:
                    same = False
                if same:
                    raise InputError(f"{final}: refusing to overwrite the input file {inp}")
        key = os.path.abspath(final)
        if key in self._finals:
            raise InputError(f"{final}: the same output path is given twice")
        return final

    def path(self, target) -> Path:
        """A temporary to write ``target``'s content to (renamed at commit)."""
        final = self.check(target)
        self._finals.add(os.path.abspath(final))
        missing = []
        parent = final.parent
        while not parent.exists():
            missing.append(parent)
            parent = parent.parent
        for d in reversed(missing):
            d.mkdir()
            self._made.append(d)
        try:
            fd, tmp = tempfile.mkstemp(prefix=f".{final.name}.", suffix=final.suffix or ".tmp",
                                       dir=str(final.parent))
        except OSError as exc:
            raise InputError(f"{final}: cannot write there ({exc.strerror})") from None
        os.close(fd)
        self._staged.append((Path(tmp), final))
        return Path(tmp)

    def mark(self) -> int:
        """A point to :meth:`rollback` to (a batch drops the outputs of a failed file)."""
        return len(self._staged)

    def rollback(self, mark: int) -> None:
        for tmp, final in self._staged[mark:]:
            self._finals.discard(os.path.abspath(final))
            try:
                tmp.unlink()
            except OSError:
                pass
        del self._staged[mark:]

    def commit(self) -> None:
        for tmp, final in self._staged:
            os.replace(tmp, final)
        self._staged = []

    def abort(self) -> None:
        for tmp, _ in self._staged:
            try:
                tmp.unlink()
            except OSError:
                pass
        for d in reversed(self._made):
            try:
                d.rmdir()
            except OSError:
                pass
        self._staged, self._made = [], []


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
    """The B-spline of a fitted curve: tolerance-certified for a smooth elastica; for a
    discrete one the C2 cubic through its vertices (max_deviation unknown, -1)."""
    from .core import SmoothElastica
    if isinstance(curve, SmoothElastica):
        return curve.to_bspline(tol=tol, degree=degree)
    from .bspline import interpolate_c2
    return interpolate_c2(curve.points())


def _fit_kwargs(args, fixed: Dict[str, float]) -> Dict[str, Any]:
    kw: Dict[str, Any] = {"model": args.model}
    if fixed:
        kw["fixed"] = fixed
    if args.max_iter is not None:
        kw["max_iter"] = args.max_iter
    return kw


def _side_record(res, data: np.ndarray, model: str) -> Dict[str, Any]:
    return {"model": model, "n_points": int(len(data)),
            "curve": curve_to_dict(res.curve),
            "initial": curve_to_dict(res.initial) if res.initial is not None else None,
            "rms": float(res.rms), "max_error": float(res.max_error),
            "iterations": int(res.iterations), "status": _status_text(res.status),
            "converged": _converged(res)}


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
        # seed 000 §5: plane fit, resampling (segment --step), re-normalisation,
        # inflection, one fit per side with (x0, y0) pinned at the inflection
        fixed = _parse_fix(args.fix, pts[:, :2], keyline=True)
        kres = el.fit_keyline(pts, r=args.step, **_fit_kwargs(args, fixed))
        prep = kres.prepared
        plane = _plane_record(prep.frame)
        to_input = prep.to_input
        extra_info = {"inflection_index": int(kres.inflection),
                      "inflection_point": prep.to_input(prep.polygon[kres.inflection]),
                      "step": prep.r, "coordinates": "x''y'' (PCA frame of the resampled polygon)",
                      "frame2d": {"origin": prep.frame2d.origin, "f1": prep.frame2d.f1,
                                  "f2": prep.frame2d.f2}}
        for i, (res, sdata) in enumerate(zip((kres.first, kres.second), prep.sides())):
            rec = _side_record(res, sdata, args.model)
            rec["side"] = i
            records.append(rec)
            pictures.append((sdata, res))
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
        res = el.fit(data, **_fit_kwargs(args, _parse_fix(args.fix, data)))
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
    jpath = _out_path(args.json, path, ".json", batch) if args.json and args.json != "-" and not (
        batch and args.json.endswith(".json") and "{stem}" not in args.json) else None
    if jpath is not None:
        write_json(records[0] if len(records) == 1 else {"file": str(path), "sides": records},
                   args.outputs.path(jpath))
    for spec, ext in ((args.svg, ".svg"), (args.png, ".png")):
        out = _out_path(spec, path, ext, batch)
        if out is None or not pictures:
            continue
        pic = None
        for i, ((d, res), rec) in enumerate(zip(pictures, records)):
            extra = [f"rms = {rec['rms']:.4g}, max error = {rec['max_error']:.4g}",
                     f"iterations = {rec['iterations']}, status = {rec['status']}"]
            if rec.get("plane"):
                extra.append(f"plane fit rms = {rec['plane']['rms']:.4g}")
            p = fit_picture(d, res.curve, res.initial, model_points=res.model_points(),
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
        write_dxf_spline(splines, args.outputs.path(_out_path(args.dxf, path, ".dxf", batch)),
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
        print(f"rms         {_fmt(rec['rms'])}")
        print(f"max error   {_fmt(rec['max_error'])}")
        print(f"iterations  {rec['iterations']}")
    if rec.get("bspline"):
        b = rec["bspline"]
        dev = (f"max deviation {_fmt(b['max_deviation'])}" if b["max_deviation"] >= 0
               else "through the vertices (C2 cubic)")
        print(f"B-spline    degree {b['degree']}, {len(b['poles'])} poles, {dev}")
    print(f"status      {rec['status']}")


OUTPUT_OPTIONS = (("json", ".json"), ("svg", ".svg"), ("png", ".png"), ("dxf", ".dxf"))


def _check_outputs(args) -> None:
    """Fail early (before any work) on outputs this installation cannot write, and on
    an output that would replace an input (the same check again at writing)."""
    files = list(getattr(args, "files", None) or [])
    batch = len(files) > 1
    for opt, ext in OUTPUT_OPTIONS:
        spec = getattr(args, opt, None)
        if not spec or spec == "-":
            continue
        for source in files or [spec]:
            args.outputs.check(_out_path(spec, source, ext, batch))
    if getattr(args, "png", None):
        from .report import have_matplotlib
        if not have_matplotlib():
            raise InputError("--png needs matplotlib (pip install matplotlib); --svg works without it")
    if getattr(args, "dxf", None):
        from .io import have_ezdxf
        if not have_ezdxf():
            raise InputError("--dxf needs the optional package ezdxf (pip install ezdxf)")


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
                                 + [f"#{i}: k={c.k:.4g} L={c.length:.4g}" for i, c in
                                    enumerate(sols[:12])])
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
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the ``elastica`` command; returns the exit status (0, 1 or 2)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    args.outputs = _Outputs(list(getattr(args, "files", None) or []) + [getattr(args, "file", None)]
                            + list(getattr(args, "inputs", None) or []))
    try:
        try:
            _check_outputs(args)
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
