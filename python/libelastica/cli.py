"""The ``elastica`` command (also ``python -m libelastica``): fit elasticae to
measured points, solve Hermite problems, convert fitted curves to B-splines and
make elliptic blending curves, with JSON, SVG/PNG report pictures and DXF.

Exit status: 0 success, 1 a fit did not converge (or a Hermite problem has no
solution), 2 bad input (one line on stderr, no traceback), 3 an internal error (a bug:
one line, ELASTICA_DEBUG=1 for the traceback; a batch fits its other files first).
"""
from __future__ import annotations

import argparse
import contextlib
import io
import os
import re
import sys
from typing import Optional, Sequence

import numpy as np

from ._ffi import NotConvergedError
from ._entry import INTERRUPTED
from ._interrupt import end_if_a_call_runs, interruptible
from ._quiet import quiet
from .cli_common import (ANGLE_UNITS, EXIT_BADINPUT, EXIT_INTERNAL, EXIT_NOCONV, EXIT_OK, PROG,
                         _finite, _input_map, _mapped_bspline, _table, angle, holding_advice,
                         dxf_units, said_warnings, thousands, thousands_option, tol_option)
from .cli_fit import cmd_fit, fit_constraints
from .cli_g2quad import cmd_g2quad
from .cli_hermite import cmd_hermite
from .cli_outputs import Outputs, check_outputs
from .io import (DXF_UNITS, InputError, curve_from_dict, curve_to_dict, read_json,
                 read_points_unit, write_dxf_spline, write_json)

FIT_EXAMPLES = """examples:
  elastica fit points.csv --svg fit.svg --json fit.json
  elastica fit scan.csv --model smooth --png fit.png --bspline-tol 1e-4 --dxf fit.dxf
  elastica fit keyline_3d.csv --keyline --step 5 --svg keyline.svg   (3D: plane fit first)
  elastica fit a.csv b.csv c.npy --json 'out/{stem}.json' --svg out/   (batch + summary)
  elastica fit points.csv --fix x0,y0          (start pinned to the first data point)
  elastica fit points.csv --fix x0=0,y0=0,phi=30     (phi in degrees; phi=0.5rad: radians)
  elastica fit sketch.csv --model smooth --start-point first --end-point last --start-tangent 90
  elastica fit scan.csv --model smooth --distance paired   (point i at arc length i L/(n-1))

input: CSV, whitespace separated text or .npy, 2 columns (x, y) or 3 (x, y, z);
'#' comments and one header line are allowed. ';' or tab separated files may have decimal
commas, and thousands grouped by '.' (1.250,5; 980;1.000) or by ',' (1,250.5) where the file
shows it: else --thousands . or , or none says which.
angles (--fix phi, --start-tangent, --end-tangent): degrees, or radians with 'rad' after
the number ('0.5rad'); the JSON writes them in radians (phi, *_tangent_rad)."""

HERMITE_EXAMPLES = """examples:
  elastica hermite 0 0 1 0  1 0 1 0 --tension 10 --svg hermite.svg
  elastica hermite 0 0 0 1  2 0 0 -1 --length 4 --json -
  elastica hermite 0 0 1 0  1 0 1 0 --length 4 --solution 2 --dxf s.dxf --units mm

The solutions are listed by bending energy; the least can belong to a curve that loops:
'loops' counts its self-crossings, 'crosses itself' marks it (a batten cannot), and the
fair ones are named under the table (also in the JSON: loops, crosses_itself,
max_curvature, length). Curves that exist but that no smooth parameters meet to --tol are
counted under the table (and in the JSON's unrepresentable), with the --tol that returns
them; none is named fair while they are missing. No solution: exit 1 and nothing is
written."""

BSPLINE_EXAMPLES = """examples:
  elastica fit points.csv --model smooth --json fit.json
  elastica bspline fit.json --tol 1e-6 --json spline.json --dxf spline.dxf
  elastica hermite 0 0 1 0 1 0 1 0 --length 4 --json h.json && elastica bspline h.json --solution 2
  elastica spline ducks.csv --json s.json && elastica bspline s.json --dxf s.dxf --units mm"""

BLEND_EXAMPLES = """examples:
  elastica blend 0 0  0.3 0.8  0.7 0.9  1 0 --m 0.3 --d 2 --svg blend.svg
  elastica blend 0 0 0.5 0.857 0.5 1 1 1 --mode control --m 0.3 --json -"""

G2QUAD_EXAMPLES = """examples:
  elastica g2quad curve.csv --edges 30 --svg g2.svg --dxf g2.dxf
  elastica g2quad scan.csv --fit --edges 24 --dxf g2.dxf      # measured points: fit first
  elastica fit points.csv --model smooth --json fit.json && elastica g2quad fit.json --json -"""


class _Parser(argparse.ArgumentParser):
    """argparse with usage errors as ONE line on stderr (exit 2), and negative numbers
    with an exponent, and points X,Y whose X is negative, taken as values."""

    def __init__(self, *a, **kw):
        super().__init__(*a, **kw)
        # argparse takes '-1e-8' and '-5e3' for options (its negative-number pattern has no
        # exponent: `hermite ... 1 -1e-8` failed "arguments are required: V"), and a point
        # '-3120.5,1500.25' too (`fit --start-point -3120.5,1500.25` failed "expected one
        # argument", QA24: drawings with the origin amidships), and a range LO, with HI
        # empty ('--k -0.5,' failed the same way); no option of the CLI looks like a number,
        # so every one of them is a value
        number = r"(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?"
        self._negative_number_matcher = re.compile(
            rf"^-{number}(\s*(deg|rad)?|\s*,\s*([-+]?{number})?)$", re.IGNORECASE)

    def error(self, message: str):
        self.exit(EXIT_BADINPUT, f"{self.prog}: error: {message}\n")


def _ranged(kind, lo=None, hi=None, above=None, below=None):
    """An argparse type: a finite int / float within its range, the option and the range
    named in the usage error (the library's own refusal named neither: "invalid argument
    (NULL, NaN/inf, out of range or too few points)")."""
    bounds = ([f">= {lo:g}"] if lo is not None else []) + ([f"> {above:g}"] if above is not None else []) + \
             ([f"<= {hi:g}"] if hi is not None else []) + ([f"< {below:g}"] if below is not None else [])
    what = ("an integer " if kind is int else "a number ") + " and ".join(bounds)

    def parse(text: str):
        try:
            v = kind(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{text!r}: {what} is needed") from None
        if not np.isfinite(v) or (lo is not None and v < lo) or (hi is not None and v > hi) or \
                (above is not None and not v > above) or (below is not None and not v < below):
            raise argparse.ArgumentTypeError(f"{text}: {what} is needed")
        return v
    return parse


POSITIVE = _ranged(float, above=0.0)
DEGREE = _ranged(int, lo=3, hi=7)
SOLUTION = _ranged(int, lo=0)


def ANGLE(text: str) -> float:
    """An argparse type: cli_common.angle (degrees, or '0.5rad'), in radians."""
    try:
        return angle(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r}: an angle is needed ({ANGLE_UNITS})") from None


def _units_option(parser) -> None:
    """--units of a command that writes DXF: the drawing's $INSUNITS (io.DXF_UNITS)."""
    parser.add_argument("--units", choices=tuple(DXF_UNITS),
                        help="the DXF's drawing units ($INSUNITS; needs --dxf); default none "
                             "(unitless: CAD takes the numbers as they are)")


# ------------------------------------------------------------------ bspline

# what `bspline` keeps of each record it reads, so that its own output read again gives
# the same B-splines in the same coordinates: a keyline's sides, the input's plane and
# frame, a discrete fit's end constraints
_READ_AGAIN = ("side", "end", "plane", "frame2d", "constraints", "closed")


def _hermite_choice(doc, solution: int, name: str):
    """The record of `hermite --json`'s solution number ``solution`` (its "curve": a smooth
    elastica or a chain); InputError naming the solutions there are; a warning naming the
    fair ones when it crosses itself."""
    sols = doc["solutions"]
    if not isinstance(sols, list) or not sols:
        raise InputError(f"{name}: a Hermite JSON without solutions")
    if solution >= len(sols):
        raise InputError(f"--solution {solution}: {name} has {len(sols)} solutions "
                         f"(0 to {len(sols) - 1})")
    if isinstance(sols[solution], dict) and sols[solution].get("crosses_itself"):   # as `hermite --dxf`
        fair = [i for i, r in enumerate(sols) if isinstance(r, dict) and not r.get("crosses_itself")]
        print(f"{PROG} bspline: warning: {name}'s solution {solution} crosses itself: a batten "
              "cannot take that shape; " + (f"{doc['unrepresentable']} more were not "
                                           "representable" if doc.get("unrepresentable") else
                                           f"the fair ones are {', '.join(map(str, fair))} "
                                           "(--solution N)" if fair else
                                           "none of the solutions is fair"), file=sys.stderr)
    return sols[solution]


def _spline_chain(doc, name: str) -> dict:
    """`spline --json`'s pieces as one record of a chain (one G2 B-spline through all of
    them, as ElasticSpline.to_bspline makes it), with "closed" kept."""
    pieces = doc["pieces"]
    if not isinstance(pieces, list) or not pieces:
        raise InputError(f"{name}: a spline JSON without pieces")
    return {"curve": {"type": "chain", "pieces": pieces}, "closed": bool(doc.get("closed"))}


def _curve_groups(doc, solution: int = 0, name: str = "JSON"):
    """The curves of a JSON document in groups that make one B-spline each: a keyline
    fit's two sides (records with "side", each from the joint outwards) together, any
    other curve alone (a record, a list of them, a batch's documents, "sides", and
    `bspline`'s own output of those); of a `hermite` JSON its solution number
    ``solution``; of a `spline` JSON its pieces as one chain."""
    groups = []
    for d in doc if isinstance(doc, list) else [doc]:
        sides = d.get("sides") if isinstance(d, dict) else None
        if _is_hermite(d):
            groups.append([_hermite_choice(d, solution, name)])
        elif isinstance(d, dict) and isinstance(d.get("pieces"), list) and "type" not in d \
                and "curve" not in d:
            groups.append([_spline_chain(d, name)])
        elif sides is None:
            groups.append([d])
        elif len(sides) == 2 and all(isinstance(s, dict) and "side" in s for s in sides):
            groups.append(sides)
        else:
            groups += _curve_groups(sides, solution, name)
    return groups


def _kept(item) -> dict:
    return {k: item[k] for k in _READ_AGAIN if k in item} if isinstance(item, dict) else {}


def _is_hermite(doc) -> bool:
    """Whether a JSON document is (or holds) `hermite --json`'s solutions."""
    return any(isinstance(d, dict) and "solutions" in d and "curve" not in d
               for d in (doc if isinstance(doc, list) else [doc]))


def cmd_bspline(args) -> int:
    import libelastica as el
    doc = read_json(args.file)
    if args.solution is not None and not _is_hermite(doc):
        raise InputError(f"--solution {args.solution}: {args.file} is not a hermite JSON (no "
                         "solutions to choose from)")
    groups = _curve_groups(doc, args.solution or 0, args.file)
    units = dxf_units(args.file, doc.get("unit") if isinstance(doc, dict) else None, args) \
        if args.dxf else None       # a fit's JSON: its points file's header's (QA qapy F3)
    out, splines, names = [], [], []
    for items in groups:
        curves = [curve_from_dict(it, name=args.file) for it in items]
        # a discrete elastica's B-spline is the C2 cubic through its vertices: --tol and
        # --degree would do nothing (QA23 F1: the README's own example printed the same file
        # for any --tol)
        if isinstance(curves[0], el.DiscreteElastica) and (args.tol is not None or args.degree != 3):
            given = "--tol" if args.tol is not None else f"--degree {args.degree}"
            raise InputError(f"{given}: {args.file} holds a discrete elastica, whose B-spline is "
                             "the cubic through its vertices (no tolerance, degree 3); drop it, "
                             "or fit with --model smooth for a B-spline certified within a tolerance")
        # the DXF and the JSON in the input's coordinates (as `fit`'s; a 3D one-piece
        # record's x'y' one as "bspline_local", a keyline's as KeylineFit.to_bspline's)
        to_input = _input_map(items[0]) if isinstance(items[0], dict) else None
        if len(curves) == 2:           # a keyline: ONE B-spline through its joint
            ends = [it.get("end") if isinstance(it, dict) else None for it in items]
            with tol_option("--tol"):
                b = el.keyline_bspline(curves[0], curves[1], args.tol, args.degree,
                                       None if None in ends else ends)
            out.append({"sides": [{"curve": curve_to_dict(c), **_kept(it)} for c, it in zip(curves, items)],
                        "bspline": _mapped_bspline(b, to_input).to_dict()})
            names.append(f"keyline of two {type(curves[0]).__name__}")
        else:
            it = items[0]
            with tol_option("--tol"):
                b = el.bspline.fitted_bspline(curves[0], args.tol, args.degree, fit_constraints(
                    it.get("constraints") if isinstance(it, dict) else None))
            out.append({"curve": curve_to_dict(curves[0]), **_kept(it),
                        "bspline": _mapped_bspline(b, to_input).to_dict(),
                        **({"bspline_local": b.to_dict()} if to_input is not None else {})})
            names.append(f"chain of {len(curves[0].pieces)} elasticae" if
                         hasattr(curves[0], "pieces") else type(curves[0]).__name__)
        splines.append(_mapped_bspline(b, to_input))
    result = out[0] if len(out) == 1 else {"sides": out}
    if args.json:
        write_json(result, args.outputs.path(args.json))
    for name, b in zip(names, splines):
        dev = (f"max deviation {b.max_deviation:.3g}" if b.max_deviation >= 0 else
               "interpolates the vertices (deviation between them not certified)")
        print(f"{name}: B-spline degree {b.degree}, {b.npoles} poles, "
              f"{len(b.knots)} knots, {dev}")
    if args.dxf:
        closed = all(isinstance(it, dict) and it.get("closed") for items in groups for it in items)
        write_dxf_spline(splines, args.outputs.path(args.dxf), units=units, closed=closed)
    return EXIT_OK


# ------------------------------------------------------------------ blend

def cmd_blend(args) -> int:
    import libelastica as el
    from .report import curves_picture, polygon_curvature, save_picture
    v = [_finite(x, "blend coordinates") for x in args.values]
    fewest = 4 if args.mode == "control" else 3     # as el.blend_curve takes them
    if len(v) % 2 or len(v) < 2 * fewest:
        raise InputError(f"the points come as x y pairs, at least {fewest} of them"
                         f"{' with --mode control' if args.mode == 'control' else ''}: "
                         f"got {len(v)} numbers")
    pts = np.array(v, dtype=np.float64).reshape(-1, 2)
    kw = {"m": args.m} if args.m is not None else {"k": args.k if args.k is not None else 0.5}
    with quiet(el.ConditionWarning, el.BlendLoopWarning):   # said below, the CLI's words
        curve = el.blend_curve(pts, d=args.d, mode=args.mode, closed=args.closed, **kw)
    xy = curve.points(np.linspace(0.0, curve.nseg, 401))
    s, kappa = polygon_curvature(xy)
    rec = {"k": curve.basis.k, "m": curve.basis.m, "d": curve.basis.d, "mode": args.mode,
           "points": pts, "control_points": curve.q, "basis_min": curve.basis.basis_min,
           "convex_hull": curve.basis.convex_hull, "lebesgue": curve.basis.lebesgue,
           "condition": curve.basis.condition, "closed": curve.closed,
           "spread": curve.spread(), "loops": curve.loops(),
           "loop_places": curve.loop_places(), "warnings": curve.warnings()}
    for w in rec["warnings"]:
        print(f"{PROG} blend: warning: {w}", file=sys.stderr)
    b = None
    if args.tol is not None or args.dxf:
        with tol_option("--tol"):    # None: 1e-6 of the curve's length
            b = curve.to_bspline(args.tol)
        rec["bspline"] = b.to_dict()
    if args.json:
        write_json(rec, args.outputs.path(args.json))
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
        write_dxf_spline(b, args.outputs.path(args.dxf), points=pts,
                         units=dxf_units(None, None, args), closed=curve.closed)
    return EXIT_OK


# ------------------------------------------------------------------ spline

def _cli_tension(t) -> str:
    return f"--tension {t:.3g}"


def cmd_spline(args) -> int:
    import libelastica as el
    from .io import bspline_to_dict
    from .report import curves_picture, save_picture
    pts, unit = read_points_unit(args.file, min_points=2, thousands=thousands(args))
    units = dxf_units(args.file, unit, args) if args.dxf else None
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
    try:
        with quiet(el.LoopWarning, el.UnstableWarning):   # said below, in the CLI's words
            sp = el.elastic_spline(pts, **kw, start=ends["start"], end=ends["end"],
                                   closed=args.closed)
    except el.DomainError as exc:     # no free batten: a tension seen to hold, if one is
        if args.length is not None or args.tension != 0.0 or isinstance(exc, el.DoublesBackError):
            raise
        raise el.DomainError(exc.status, holding_advice(str(exc), pts, ends, args.closed)) from None
    if sp.loops:
        fix = (f"at tension {sp.tension:.6g}: " + ("give " if sp.holding()[0] is not None else "")
               + sp.holding_text(_cli_tension, "a --length")   # the ladder, solved once
               if args.length is None else f"of length {args.length:g} (tension "
               f"{sp.tension:.6g}): a shorter --length gives one")
        print(f"warning: the spline loops away from its ducks (crosses itself where their "
              f"polygon does not, or is longer than 4 x it: length {sp.length:.6g}); no fair "
              f"batten was found {fix}", file=sys.stderr)
    if sp.unstable:
        fix = (("give " if sp.holding()[0] is not None else "") + sp.holding_text(
            _cli_tension, "a --length") if args.length is None else
               f"try another --length than {args.length:g}, or a --tension")
        print("warning: " + sp.unstable_text(fix), file=sys.stderr)
    need_b = args.dxf or args.bspline_tol is not None
    b = None
    if need_b:
        with tol_option("--bspline-tol"):    # None: 1e-6 of the spline's length
            b = sp.to_bspline(args.bspline_tol, args.degree)
    rec = {"file": args.file, "unit": unit, "points": sp.data.tolist(), "closed": sp.closed, **kw,
           "tension": sp.tension, "length": sp.length, "energy": sp.energy,
           "max_curvature": sp.max_curvature, "residual": sp.residual, "loops": sp.loops,
           "unstable": sp.unstable,
           "pieces": [curve_to_dict(c) for c in sp.pieces], "guides": sp.guides.tolist(),
           "guide_forces": sp.guide_forces.tolist(), "guide_pieces": sp.guide_pieces,
           "forces": sp.forces.tolist(), "angles_rad": sp.angles.tolist(),
           "curvatures": sp.curvatures.tolist(),
           "bspline": bspline_to_dict(b) if b is not None else None}
    if args.json:
        write_json(rec, args.outputs.path(args.json))
    print(_table(["points", "pieces", "tension", "length", "energy", "max curvature",
                  "residual"], [[len(sp.data), len(sp.pieces), sp.tension, sp.length,
                                 sp.energy, sp.max_curvature, sp.residual]]))
    if b is not None:
        print(f"B-spline: degree {b.degree}, {len(b.poles)} poles, certified within "
              f"{b.max_deviation:.3g}")
    if args.dxf:
        write_dxf_spline(b, args.outputs.path(args.dxf), points=sp.data, units=units,
                         closed=sp.closed)
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
            save_picture(pic, args.outputs.path(spec))
    return EXIT_OK


# ------------------------------------------------------------------ parser

# '-' in each output's and input's help (QA17: --dxf - wrote a file named '-'): an output to
# standard output, the report then not printed; an input from standard input
_TO_STDOUT = "; '-': standard output (the report is then not printed)"
_PNG_TO_STDOUT = "; '-': standard output, if it is not a terminal (the report is then not printed)"
_FROM_STDIN = "; '-': standard input (once)"


def build_parser() -> argparse.ArgumentParser:
    """The argument parser of the ``elastica`` command."""
    p = _Parser(prog=PROG, formatter_class=argparse.RawDescriptionHelpFormatter,
                description="Euler's elastica for CAD: fit measured points, Hermite "
                            "interpolation, B-splines, elliptic blends.",
                epilog="examples:\n  elastica fit points.csv --svg fit.svg --json fit.json\n"
                       "  elastica hermite 0 0 1 0 1 0 1 0 --tension 10\n"
                       "  elastica bspline fit.json --dxf fit.dxf\n"
                       "  elastica blend 0 0 0.3 0.8 0.7 0.9 1 0 --svg blend.svg\n"
                       "  elastica COMMAND --help   (more examples)\n\n"
                       "exit status: 0 ok, 1 fit did not converge / no solution, 2 bad input, 3 internal error")
    from . import __version__
    p.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    raw = argparse.RawDescriptionHelpFormatter

    f = sub.add_parser("fit", help="fit an elastica to points (CSV / text / .npy)",
                       description="Fit a discrete (seed 000) or smooth elastica to measured "
                                   "points; several files run as a batch with a summary table.",
                       epilog=FIT_EXAMPLES, formatter_class=raw)
    f.add_argument("files", nargs="+", metavar="FILE",
                   help="point files (2 or 3 columns)" + _FROM_STDIN)
    thousands_option(f)
    f.add_argument("--model", choices=("discrete", "smooth"), default="discrete",
                   help="elastica model (default: discrete)")
    f.add_argument("--keyline", action="store_true",
                   help="split at the estimated inflection and fit each side (seed 000 §5)")
    f.add_argument("--fix", metavar="NAMES",
                   help="parameters held fixed: 'x0,y0' (start at the first point) or "
                        "'x0=0,y0=0,phi=30' (phi in degrees as every angle of the command "
                        "line, or phi=0.5rad; the JSON's curve holds it in radians)")
    f.add_argument("--distance", choices=("orthogonal", "paired"),
                   help="what is minimised: the points' distances to the curve or polygon "
                        "(default; the discrete model on equally spaced points: paired) or "
                        "point i <-> vertex i / arc length i L/(n-1)")
    c = f.add_argument_group("constraints (met to 1e-10 of the data's size, or exit 2 naming "
                             "the one that cannot be met)")
    c.add_argument("--start-point", metavar="X,Y|first", help="the curve starts here")
    c.add_argument("--end-point", metavar="X,Y|last", help="the curve ends here")
    c.add_argument("--start-tangent", type=ANGLE, metavar="DEG",
                   help="tangent direction at the start (the direction of travel): " + ANGLE_UNITS)
    c.add_argument("--end-tangent", type=ANGLE, metavar="DEG",
                   help="tangent direction at the end: " + ANGLE_UNITS)
    c.add_argument("--start-curvature", type=float, metavar="K",
                   help="curvature at the start (1/units, + turning left; 0: a free end)")
    c.add_argument("--end-curvature", type=float, metavar="K", help="curvature at the end")
    c.add_argument("--length", metavar="L|LO,HI",
                   help="the curve's length L, or its range (either end may be empty)")
    c.add_argument("--k", dest="k_range", metavar="K|LO,HI",
                   help="the modulus k, or its range (either end may be empty)")
    f.add_argument("--order", choices=("given", "curve"), default="given",
                   help="the points' order along the curve: the file's (default; warned of when "
                        "it is no curve's) or curve order (el.curve_order: a shuffled scan)")
    f.add_argument("--step", type=POSITIVE, metavar="R",
                   help="resample into an equilateral polygon of segment R first (--keyline "
                        "without it: the polyline through the medians of runs of the points, "
                        "cut into 100 segments)")
    f.add_argument("--json", metavar="PATH", help="write the result as JSON (angles in "
                   "radians: a curve's phi, constraints' *_tangent_rad)" + _TO_STDOUT)
    f.add_argument("--svg", metavar="PATH", help="write the report picture as SVG" + _TO_STDOUT)
    f.add_argument("--png", metavar="PATH",
                   help="write the report picture as PNG (matplotlib)" + _PNG_TO_STDOUT)
    f.add_argument("--bspline-tol", type=POSITIVE, metavar="TOL",
                   help="add the B-spline of the fitted curve (within TOL for smooth, default "
                        "1e-6 of its length with --dxf; "
                        "discrete: the C2 cubic through the vertices, with the end constraints, "
                        "and the points' distances to it)")
    f.add_argument("--degree", type=DEGREE, default=3, help="B-spline degree 3..7 (default 3)")
    f.add_argument("--max-iter", type=_ranged(int, lo=1), metavar="N",
                   help="iterations per start, of Levenberg-Marquardt and of Ipopt "
                        "where it runs (default 200)")
    f.add_argument("--dxf", metavar="PATH",
                   help="write the B-spline as a DXF SPLINE (ezdxf)" + _TO_STDOUT)
    _units_option(f)
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
    g.add_argument("--length", type=POSITIVE, metavar="L", help="arc length")
    h.add_argument("--json", metavar="PATH", help="write the solutions as JSON (each curve's phi "
                   "in radians)" + _TO_STDOUT)
    h.add_argument("--svg", metavar="PATH", help="picture of all solutions (SVG)" + _TO_STDOUT)
    h.add_argument("--png", metavar="PATH",
                   help="picture of all solutions (PNG, matplotlib)" + _PNG_TO_STDOUT)
    h.add_argument("--bspline-tol", type=POSITIVE, metavar="TOL",
                   help="add every solution's B-spline within TOL to the JSON (default 1e-6 "
                        "of its length with --dxf)")
    h.add_argument("--degree", type=DEGREE, default=3, help="B-spline degree 3..7 (default 3)")
    h.add_argument("--tol", type=POSITIVE, default=1e-10,
                   help="the solutions' end error allowed (default 1e-10); curves no smooth "
                        "parameters meet to it are counted 'not representable' (a larger "
                        "--tol returns them)")
    h.add_argument("--solution", type=SOLUTION, metavar="N",
                   help="the solution --dxf writes (default 0, the least energy; the table's "
                        "'crosses itself' column shows the fair ones)")
    h.add_argument("--dxf", metavar="PATH", help="write that solution's B-spline as a DXF SPLINE "
                                                 "(ezdxf), p0 and p1 as points" + _TO_STDOUT)
    _units_option(h)
    h.set_defaults(func=cmd_hermite)

    b = sub.add_parser("bspline", help="B-spline of a fitted curve's JSON",
                       description="Convert the curve in a JSON written by 'fit --json', "
                                   "'hermite --json' (one solution: --solution) or 'spline "
                                   "--json' into a B-spline (certified within --tol for a smooth "
                                   "elastica, a Hermite solution and a spline's pieces, one "
                                   "B-spline G2 through its points; the C2 cubic through the "
                                   "vertices for a discrete one; a keyline's two sides make one "
                                   "B-spline through the joint).",
                       epilog=BSPLINE_EXAMPLES, formatter_class=raw)
    b.add_argument("file", metavar="FIT.json",
                   help="a JSON of fit, hermite, spline or bspline" + _FROM_STDIN)
    b.add_argument("--solution", type=SOLUTION, metavar="N",
                   help="of a hermite JSON, solution N (default 0, the least energy)")
    b.add_argument("--tol", type=POSITIVE, help="tolerance (default 1e-6 of the curve's length)")
    b.add_argument("--degree", type=DEGREE, default=3, help="degree 3..7 (default 3)")
    b.add_argument("--json", metavar="PATH", help="write the B-spline as JSON" + _TO_STDOUT)
    b.add_argument("--dxf", metavar="PATH", help="write a DXF SPLINE (needs ezdxf)" + _TO_STDOUT)
    _units_option(b)
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
    sp.add_argument("file", metavar="FILE", help="the points (2 columns)" + _FROM_STDIN)
    thousands_option(sp)
    g = sp.add_mutually_exclusive_group()
    g.add_argument("--tension", type=float, default=0.0, metavar="SIGMA",
                   help="tension sigma >= 0 in 1/units^2 of the points (in mm: 1e-6 x the same "
                        "tension in m); solved up to sigma x (longest span)^2 ~ 300 "
                        "(default 0: the free-sliding batten)")
    g.add_argument("--length", type=POSITIVE, metavar="L", help="total length (sigma computed)")
    sp.add_argument("--closed", action="store_true", help="a closed curve through the points")
    for name in ("start", "end"):
        sp.add_argument(f"--{name}-tangent", type=float, nargs=2, metavar=("TX", "TY"),
                        help=f"clamp the {name} tangent (default: natural, curvature 0)")
        sp.add_argument(f"--{name}-curvature", type=float, metavar="K",
                        help=f"and its curvature: G2 to other geometry (needs --{name}-tangent)")
    sp.add_argument("--bspline-tol", type=POSITIVE, metavar="TOL",
                    help="add the B-spline within TOL to the JSON (default 1e-6 of its length "
                         "with --dxf)")
    sp.add_argument("--degree", type=DEGREE, default=3, help="B-spline degree 3..7 (default 3)")
    sp.add_argument("--json", metavar="PATH", help="write the spline as JSON (angles in radians: "
                    "angles_rad, each piece's phi)" + _TO_STDOUT)
    sp.add_argument("--svg", metavar="PATH",
                    help="picture with the curvature comb (SVG)" + _TO_STDOUT)
    sp.add_argument("--png", metavar="PATH",
                    help="picture with the curvature comb (PNG)" + _PNG_TO_STDOUT)
    sp.add_argument("--dxf", metavar="PATH",
                    help="write the B-spline as a DXF SPLINE (ezdxf)" + _TO_STDOUT)
    _units_option(sp)
    sp.set_defaults(func=cmd_spline)

    e = sub.add_parser("blend", help="elliptic blending curve through points (seed 003)",
                       description="An elliptic blending curve (basis {1-t, sn((1-t)K), sn(Kt), "
                                   "t}) through three points or more (a closed one with "
                                   "--closed), or with them as control points.",
                       epilog=BLEND_EXAMPLES, formatter_class=raw)
    e.add_argument("values", nargs="+", type=float, metavar="V",
                   help="x0 y0 x1 y1 x2 y2 ...: four points (one segment), three or more "
                        "than four (the C1 composite through them, open or --closed); --mode "
                        "control: 3 n + 1 control points")
    km = e.add_mutually_exclusive_group()
    km.add_argument("--k", type=_ranged(float, lo=0.0, below=1.0),
                    help="elliptic modulus k in [0, 1) (default 0.5)")
    km.add_argument("--m", type=_ranged(float, lo=0.0, below=1.0),
                    help="elliptic parameter m = k^2 in [0, 1) (the paper's 'k')")
    e.add_argument("--d", type=POSITIVE, default=2.0, help="end-derivative parameter > 0 (default 2)")
    e.add_argument("--mode", choices=("interpolate", "control"), default="interpolate",
                   help="pass through the points (default) or use them as control points")
    e.add_argument("--closed", action="store_true", help="a closed curve through the points, "
                   "smooth where it closes (a repeated first point is dropped): 3 or 4 segments")
    e.add_argument("--tol", type=POSITIVE, metavar="TOL", help="add the cubic B-spline within TOL "
                   "(default 1e-6 of the curve's length with --dxf)")
    e.add_argument("--json", metavar="PATH", help="write the result as JSON" + _TO_STDOUT)
    e.add_argument("--svg", metavar="PATH", help="picture (SVG)" + _TO_STDOUT)
    e.add_argument("--png", metavar="PATH", help="picture (PNG, matplotlib)" + _PNG_TO_STDOUT)
    e.add_argument("--dxf", metavar="PATH",
                   help="write the B-spline as a DXF SPLINE (ezdxf)" + _TO_STDOUT)
    _units_option(e)
    e.set_defaults(func=cmd_blend)

    q = sub.add_parser("g2quad", help="curvature-continuous quadratic B-spline of a curve (seed 002)",
                       description="Approximate a curve (points: CSV / text / .npy, 2 or 3 "
                                   "columns; or a smooth elastica from 'fit --json') by an affine "
                                   "arc-length polyline and build one G2 uniform quadratic "
                                   "B-spline per inflection-free piece, ending exactly on the "
                                   "curve's ends and inflections.",
                       epilog=G2QUAD_EXAMPLES, formatter_class=raw)
    q.add_argument("file", metavar="FILE",
                   help="points (a dense sampling: ~20 per edge) or FIT.json" + _FROM_STDIN)
    thousands_option(q)
    q.add_argument("--edges", type=int, metavar="N",
                   help="polyline edges (default: points/20, at least 6; 40 for a fit or --fit)")
    q.add_argument("--fit", action="store_true",
                   help="fit one smooth elastica to the points first and build from it: "
                        "measured or rounded points (the construction takes their second and "
                        "third differences)")
    q.add_argument("--json", metavar="PATH",
                   help="write the result as JSON (end_tangent_error_rad: the source's ends' "
                        "tangent error, what the report's 'end tangents' line prints; "
                        "piece_end_tangent_error_rad: every piece end's, the inflections' "
                        "included; unheld_joints: the joints where the pieces meet not G1, "
                        "{joint, angle_rad, why}, joint j where bsplines[j] starts; "
                        "deviation: the largest distance from the source)"
                        + _TO_STDOUT)
    q.add_argument("--svg", metavar="PATH", help="picture (SVG)" + _TO_STDOUT)
    q.add_argument("--png", metavar="PATH", help="picture (PNG, matplotlib)" + _PNG_TO_STDOUT)
    q.add_argument("--dxf", metavar="PATH",
                   help="write the B-splines as DXF SPLINEs (ezdxf)" + _TO_STDOUT)
    _units_option(q)
    q.set_defaults(func=cmd_g2quad)
    return p


def main(argv: Optional[Sequence[str]] = None) -> int:
    """Run the ``elastica`` command; returns the exit status (0, 1, 2 or 3)."""
    parser = build_parser()
    args = parser.parse_args(argv)
    inputs = list(getattr(args, "files", None) or []) + [getattr(args, "file", None)] \
        + list(getattr(args, "inputs", None) or [])
    args.outputs = Outputs(inputs)
    try:
        try:
            if inputs.count("-") > 1:   # standard input can be read once
                raise InputError("'-' (standard input) is given more than once: give it once")
            check_outputs(args)
            # Ctrl-C during a C fit: at once, not when it returns; an output on stdout: the
            # report is not printed (as --json - never printed it)
            with interruptible(), said_warnings(args.command), \
                    (contextlib.redirect_stdout(io.StringIO()) if args.to_stdout
                     else contextlib.nullcontext()):
                status = args.func(args)
            args.outputs.commit()
            return status
        except NotConvergedError as exc:
            args.outputs.abort()
            print(f"{PROG} {args.command}: {exc}", file=sys.stderr)   # it says what did not converge
            return EXIT_NOCONV
        except BaseException as exc:
            msg = args.outputs.explain(" ".join(str(exc).split()))   # names no temporary
            args.outputs.abort()
            if isinstance(exc, (InputError, ValueError, OSError, OverflowError)) and \
                    not isinstance(exc, BrokenPipeError):
                raise InputError(msg or type(exc).__name__) from None
            raise
    except BrokenPipeError:     # `elastica ... --dxf - | head`: the reader is gone
        sys.stdout = open(os.devnull, "w")     # (and Python's flush at exit says nothing)
        return EXIT_OK
    except (InputError, ValueError, OSError, OverflowError) as exc:
        msg = " ".join(str(exc).split()) or type(exc).__name__
        print(f"{PROG} {args.command}: {msg}", file=sys.stderr)
        return EXIT_BADINPUT
    except KeyboardInterrupt as exc:
        print(f"{PROG}: interrupted", file=sys.stderr)
        end_if_a_call_runs(exc, INTERRUPTED)    # (the outputs are aborted above)
        return INTERRUPTED
    except Exception as exc:   # a bug: one line unless ELASTICA_DEBUG asks for the traceback
        if os.environ.get("ELASTICA_DEBUG"):
            raise
        print(f"{PROG} {args.command}: internal error: {type(exc).__name__}: {exc} "
              "(set ELASTICA_DEBUG=1 for a traceback)", file=sys.stderr)
        return EXIT_INTERNAL


if __name__ == "__main__":
    sys.exit(main())
