"""The ``elastica hermite`` command: every elastica through two points with two tangents
(el.hermite), as a table, JSON, pictures and the DXF of one solution (cli.py registers it)."""
from __future__ import annotations

import sys

import numpy as np

from ._quiet import quiet
from ._text import coordinates
from .cli_common import EXIT_NOCONV, EXIT_OK, PROG, _finite, _table, dxf_units, tol_option
from .io import InputError, curve_to_dict, write_dxf_spline, write_json


def _solution_record(i: int, c) -> dict:
    """One Hermite solution as the JSON and the table show it: what it is (curve, tension,
    energy, inflection, end curvatures, residual) and what picks the fair one among them
    (length, loops = self-crossings, crosses_itself, largest curvature: shape.py)."""
    e = getattr(c, "energy_value", None)
    loops = c.loops
    return {"index": i, "curve": curve_to_dict(c), "sigma": getattr(c, "sigma", None),
            "energy": e if e is not None else c.energy(), "length": c.length,
            "has_inflection": getattr(c, "has_inflection", None), "loops": loops,
            "crosses_itself": loops > 0, "max_curvature": c.max_curvature,
            "kappa0": getattr(c, "kappa0", None), "kappa1": getattr(c, "kappa1", None),
            "residual": getattr(c, "residual", None)}


def _hermite_tol_advice(p0, t0, p1, t1, kw, tol: float) -> str:
    """What returns the solutions el.hermite counted unrepresentable at ``tol``: the
    smallest of 10 x, 100 x ... 1e4 x tol that returns them all (solved again to know)."""
    import libelastica as el
    for larger in tol * 10.0 ** np.arange(1, 5):
        with quiet(RuntimeWarning):
            if not el.hermite(p0, t0, p1, t1, **kw, tol=larger).unrepresentable:
                return f"--tol {larger:.0e} returns them"
    return f"not even --tol {tol * 1e4:.0e} returns them"


def cmd_hermite(args) -> int:
    import libelastica as el
    from .report import curves_picture, save_picture
    v = [_finite(x, "hermite coordinates") for x in args.values]
    p0, t0, p1, t1 = v[0:2], v[2:4], v[4:6], v[6:8]
    kw = {"tension": args.tension} if args.tension is not None else {"length": args.length}
    _finite(next(iter(kw.values())), "--tension/--length")
    if args.solution is not None and not args.dxf:
        raise InputError(f"--solution {args.solution} picks the solution --dxf writes: give --dxf "
                         "too (the table and the JSON have them all)")
    chosen = args.solution or 0
    with quiet(into=[]) as caught:     # the binding's, said below the CLI's way
        sols = el.hermite(p0, t0, p1, t1, **kw, tol=args.tol)
    for w in caught:
        print(f"{PROG} hermite: warning: {str(w).removeprefix('hermite: ')}",
              file=sys.stderr)
    missing = sols.unrepresentable
    advice = _hermite_tol_advice(p0, t0, p1, t1, kw, args.tol) if missing else ""
    more = f"{missing} more not representable at tol {args.tol:g}: {advice}"
    if not sols:      # nothing is written: no file of an empty answer for a script to take
        print(f"{PROG} hermite: no elastica through these points and tangents"
              + (f" is representable at tol {args.tol:g} ({missing} exist): {advice}"
                 if missing else ""), file=sys.stderr)
        return EXIT_NOCONV
    if chosen >= len(sols):
        raise InputError(f"--solution {chosen}: there are {len(sols)} solutions "
                         f"(0 to {len(sols) - 1})" + (f"; {more}" if missing else ""))
    recs = [_solution_record(i, c) for i, c in enumerate(sols)]
    b = None
    # every solution's B-spline (G2 ends, as `bspline` makes it of the JSON), the DXF the chosen one's
    if args.bspline_tol is not None or args.dxf:
        for r, c in zip(recs, sols):    # tol None: 1e-6 of each solution's length
            with tol_option("--bspline-tol"):
                r["bspline"] = el.bspline.fitted_bspline(c, args.bspline_tol, args.degree).to_dict()
        b = el.BSpline.from_dict(recs[chosen]["bspline"])
    if args.dxf and recs[chosen]["crosses_itself"]:
        fair = [r["index"] for r in recs if not r["crosses_itself"]]
        print(f"{PROG} hermite: warning: --dxf writes solution {chosen}, which crosses itself "
              f"({recs[chosen]['loops']} loop(s)): a batten cannot take that shape; "
              + (f"{more}" if missing else f"the fair ones are {', '.join(map(str, fair))} "
                 "(--solution N)" if fair else "none of the solutions is fair"), file=sys.stderr)
    out = {"p0": p0, "t0": t0, "p1": p1, "t1": t1, **kw, "tol": args.tol,
           "unrepresentable": missing, "solutions": recs}
    if args.json:
        write_json(out, args.outputs.path(args.json))
    # near the separatrix a chain of pieces ("curve": {"type": "chain", ...}), k its first piece's
    print(_table(["#", "sigma", "length", "k", "energy", "inflection", "loops",
                  "crosses itself", "max curvature", "kappa0", "kappa1", "residual"],
                 [[r["index"], r["sigma"], r["length"], c.k, r["energy"],
                   "yes" if r["has_inflection"] else "no", r["loops"],
                   "YES" if r["crosses_itself"] else "no", r["max_curvature"], r["kappa0"],
                   r["kappa1"], r["residual"]] for r, c in zip(recs, sols)]))
    fair = [r["index"] for r in recs if not r["crosses_itself"]]
    # a curve is named fair only when none is missing: the missing may be the fair one
    # (QA: a near-straight bow's one returned curve, 2.19 x its chord, was called fair)
    print(f"by energy; {len(sols) - len(fair)} of {len(sols)} cross themselves (a batten "
          "cannot)" + (f"; {more}: none is named fair while they are missing" if missing
                       else f": the fair ones are {', '.join(map(str, fair))}" if fair
                       else ": none is fair"))
    if b is not None:
        print(f"B-spline of solution {chosen}: degree {b.degree}, {b.npoles} poles, "
              f"certified within {b.max_deviation:.3g}")
    for spec in (args.svg, args.png):
        if spec:
            what = f"tension {args.tension:g}" if args.tension is not None else \
                f"length {args.length:g}"
            chord = float(np.hypot(*(np.asarray(p1, float) - np.asarray(p0, float))))
            drawn = []
            for c in sols:             # every solution runs p0 -> p1 (k < -1: clockwise loop)
                s = np.linspace(0.0, c.length, 400)
                drawn.append((c.points(s), s, c.curvature(s)))
            pic = curves_picture(drawn, [f"solution {i} (E = {r['energy']:.4g})"
                                         + (", crosses itself" if r["crosses_itself"] else "")
                                         for i, r in enumerate(recs)],
                                 points=np.array([p0, p1]),
                                 title=f"Hermite elasticae, {what}: {len(sols)} solutions",
                                 params=[f"p0 = ({coordinates(p0, chord)}), t0 = ({t0[0]:g}, {t0[1]:g})",
                                         f"p1 = ({coordinates(p1, chord)}), t1 = ({t1[0]:g}, {t1[1]:g})"]
                                 + [f"#{i}: k={c.k:.4g} L={c.length:.4g}"
                                    + (f" ({len(c.pieces)} pieces)" if hasattr(c, "pieces") else "")
                                    for i, c in enumerate(sols[:12])])
            save_picture(pic, args.outputs.path(spec))
    if args.dxf:
        write_dxf_spline(b, args.outputs.path(args.dxf), points=np.array([p0, p1]),
                         units=dxf_units(None, None, args))
    return EXIT_OK
