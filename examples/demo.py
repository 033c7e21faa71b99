"""`make demo`: fit the bundled scanned roof-tile keyline with elasticae in FreeCAD,
headless, and write

  out/demo.FCStd  the scan (its points, and the 3D polyline the fits read), the
                  parametric Elastica features (the keyline fitted as one G2 curve
                  of two elasticae meeting at its inflection, seed 000 §5; a one-piece fit and a
                  discrete fit for comparison; a curvature comb; the G2 quadratic
                  B-spline of seed 002; an elastic spline, the batten through six
                  ducks set beside the keyline as for the next line of a lines plan),
                  each in its own colour named in its label, and a sketch "Keyline"
                  in the fitted plane holding the keyline: ONE B-spline, G2 at the joint.
                  Opened in FreeCAD, the features get their icons, colours and task
                  panels (double-click);
  out/demo.svg    the data and the fitted curves in the keyline's plane, with curvature;
  out/demo.json   the fitted parameters, errors, B-spline sizes and the plane;

and print a short report. Run as `freecadcmd examples/demo.py` (the Makefile sets
LIBELASTICA_PATH, PYTHONPATH and a throw-away HOME); the exit status is 0 only when
every step worked. Input and output paths can be changed with ELASTICA_DEMO_INPUT
and ELASTICA_DEMO_OUT.
"""
import os
import sys
import time
import traceback

HERE = os.path.dirname(os.path.abspath(__file__)) if "__file__" in globals() else \
    os.path.join(os.getcwd(), "examples")
ROOT = os.path.dirname(HERE)
for p in (os.path.join(ROOT, "python"), os.path.join(ROOT, "freecad_wb")):
    if p not in sys.path:
        sys.path.insert(0, p)
try:            # FreeCAD imported the `freecad` namespace before this script ran
    import freecad
    _wb = os.path.join(ROOT, "freecad_wb", "freecad")
    if _wb not in list(freecad.__path__):
        freecad.__path__.append(_wb)
except ImportError:
    pass

STEP = 3.0          # mm, equilateral resampling of the scan (seed 000 §5.3)
TOL = 1e-3          # mm, B-spline tolerance
NDUCKS = 6          # the elastic spline's ducks, on the keyline fit ...
DUCK_OFFSET = 60.0  # mm, ... moved this far across its chord


def run(src, out):
    import FreeCAD as App
    import Part
    import numpy as np

    import libelastica as el
    from libelastica.io import curve_to_dict, read_points, write_json
    from libelastica.report import curves_picture, save_picture
    from freecad.elastica import features as F
    from freecad.elastica import g2quad
    from freecad.elastica import spline as elastica_spline
    from freecad.elastica.viewproviders import PALETTE

    t0 = time.time()
    xyz = read_points(src)
    if xyz.shape[1] != 3:
        raise SystemExit(f"{src}: expected x,y,z columns")
    doc = App.newDocument("ElasticaDemo")

    scan_points = doc.addObject("Points::Feature", "ScanPoints")
    scan_points.Label = "Scanned keyline (points)"
    import Points
    scan_points.Points = Points.Points([App.Vector(*map(float, p)) for p in xyz])
    scan = doc.addObject("Part::Feature", "Scan")
    scan.Label = "Scanned keyline (polyline the fits read)"
    scan.Shape = Part.makePolygon([App.Vector(*map(float, p)) for p in xyz])
    scan.Visibility = False

    keyline = F.make_fit(doc, [(scan, [])], Model="smooth", SplitAtInflection=True,
                         ResampleStep=STEP, Tolerance=TOL, Degree=5)
    keyline.Label = "Keyline fit (two elasticae, G2)"
    # the same scan points as the smooth keyline (which fits the points themselves)
    whole = F.make_fit(doc, [(scan, [])], Model="smooth", Tolerance=TOL, Degree=5)
    whole.Label = "One-piece fit"
    discrete = F.make_fit(doc, [(scan, [])], Model="discrete", SplitAtInflection=True,
                          ResampleStep=STEP, Tolerance=TOL)
    discrete.Label = "Keyline fit (discrete elasticae)"
    comb = F.make_comb(doc, keyline, Samples=40)
    comb.Label = "Curvature comb of the keyline fit"
    # the GUI gives the fits the palette's colours in document order (viewproviders):
    # the labels name them, a legend in the tree
    for f, (colour, _) in zip((keyline, whole, discrete), PALETTE):
        f.Label = f"{f.Label} - {colour}"
    comb.Label += f" - light {PALETTE[0][0]}"
    whole.Visibility = discrete.Visibility = False    # the same curve again: shown on demand
    doc.recompute()
    for f in (keyline, whole, discrete):
        if f.Status.startswith("error") or not f.Shape.Edges:
            raise RuntimeError(f"{f.Label}: {f.Status}")
    if comb.Status != "ok":
        raise RuntimeError(f"comb: {comb.Status}")

    sketch = doc.addObject("Sketcher::SketchObject", "Keyline")
    sketch.Label = "Keyline (one G2 B-spline)"
    sketch.Placement = keyline.Plane
    ids = F.write_to_sketch(keyline, sketch)
    doc.recompute()
    dev = max(keyline.Shape.distToShape(Part.Vertex(p))[0]
              for e in sketch.Shape.Edges for p in e.discretize(50))
    if len(ids) != 1 or dev > 1e-6:
        raise RuntimeError(f"sketch B-spline: {len(ids)} curves, {dev:.3g} mm from the fit")
    g2 = g2quad.make(doc, [(sketch, [])], Edges=40)
    g2.Label = f"G2 quadratic B-spline (seed 002) - {PALETTE[3][0]}"
    doc.recompute()
    if g2.Status != "ok":
        raise RuntimeError(f"G2 quadratic B-spline: {g2.Status}")
    # a batten through six ducks beside the keyline (DUCK_OFFSET mm across its chord, in
    # its plane): the ducks are sketch points, moving one re-solves the batten
    on_keyline = F.to_plane(keyline.Plane, keyline.Shape.discretize(Number=NDUCKS))[:, :2]
    chord = on_keyline[-1] - on_keyline[0]
    across = np.array([-chord[1], chord[0]]) / np.hypot(*chord)
    ducks = doc.addObject("Sketcher::SketchObject", "Ducks")
    ducks.Label = f"Ducks ({NDUCKS} sketch points)"
    ducks.Placement = keyline.Plane
    for x, y in on_keyline + DUCK_OFFSET * across:
        ducks.addGeometry(Part.Point(App.Vector(float(x), float(y), 0.0)), False)
    batten = elastica_spline.make(doc, [(ducks, [])], Tolerance=TOL)
    batten.Label = f"Elastic spline through {NDUCKS} ducks - {PALETTE[4][0]}"
    doc.recompute()
    if batten.Status != "ok":
        raise RuntimeError(f"elastic spline: {batten.Status}")

    os.makedirs(out, exist_ok=True)
    fcstd = os.path.join(out, "demo.FCStd")
    keyline_name, whole_name = keyline.Name, whole.Name
    check_pts = [tuple(p) for e in keyline.Shape.Edges for p in e.discretize(40)]
    doc.saveAs(fcstd)

    # the picture and the JSON, in the keyline's plane
    plc = keyline.Plane
    data = F.to_plane(plc, [App.Vector(*map(float, p)) for p in xyz])   # x, y in plane; z off it
    halves = keyline.Proxy.plane_curves(keyline)[0]       # along the keyline: joint between
    one = whole.Proxy.plane_curves(whole)[0][0]
    # the one-piece fit lives in its own (equal up to rounding) plane: same PCA of the same scan
    lines = [f"keyline: 2 smooth elasticae (G2), rms {keyline.Rms:.3f} mm point to curve",
             f"k = {keyline.K[0]:.4f} / {keyline.K[1]:.4f}",
             f"one piece: rms {whole.Rms:.3f} mm, k = {whole.K[0]:.4f}",
             f"out of plane: {data[:, 2].std():.3f} mm rms"]
    pic = curves_picture([halves[0], halves[1], one],
                         ["elastica, first end -> inflection", "elastica, inflection -> last end",
                          "one-piece elastica"],
                         points=data[:, :2], title="Scanned roof-tile keyline: elastica fits",
                         params=lines, point_label="scan (projected on the fitted plane)")
    svg = os.path.join(out, "demo.svg")
    backend = save_picture(pic, svg)

    infl = plc.multVec(App.Vector(halves[1].x0, halves[1].y0, 0))

    # the keyline is one G2 curve: the halves meet at the joint with one tangent and
    # zero curvature, the elasticae exactly; its one B-spline, seen from both sides of
    # the joint's knot, the same
    end, z = np.array([halves[0].length]), np.array([0.0])
    brk = abs(np.remainder(halves[0].angle(end)[0] - halves[1].angle(z)[0] + np.pi, 2 * np.pi)
              - np.pi)
    bs = keyline.Shape.Edges[0].Curve
    u = min(bs.getKnots(), key=lambda t: (bs.value(t) - infl).Length)
    sides = []
    for a, b in ((u - 1.0, u), (u, u + 1.0)):
        c = bs.copy()
        c.segment(a, b)
        sides.append((App.Vector(c.tangent(u)[0]), c.curvature(u)))
    joint = {"tangent_break_deg": float(np.degrees(brk)), "curvature_1_per_mm": [
        float(halves[0].curvature(end)[0]), float(halves[1].curvature(z)[0])],
        "bspline_tangent_break_deg": float(np.degrees(sides[0][0].getAngle(sides[1][0]))),
        "bspline_curvature_1_per_mm": [float(k) for _, k in sides]}
    if (joint["tangent_break_deg"] > 1e-9 or joint["bspline_tangent_break_deg"] > 1e-7
            or max(abs(v) for v in joint["curvature_1_per_mm"]) > 1e-12
            or max(joint["bspline_curvature_1_per_mm"]) > 1e-9):
        raise RuntimeError(f"keyline joint is not G2: {joint}")

    def fit_json(f):
        b = f.Shape.Edges[0].Curve
        return {"label": f.Label, "model": f.Model, "split_at_inflection": f.SplitAtInflection,
                "resample_step_mm": f.ResampleStep.Value, "points": len(f.DataPoints),
                "error_measure": f.ErrorMeasure, "rms_mm": f.Rms, "max_error_mm": f.MaxError,
                "k": list(f.K), "status": f.Status,
                "curves": [dict(curve_to_dict(c), energy=float(c.energy()) if
                                isinstance(c, el.SmoothElastica) else None)
                           for c in f.Proxy.plane_curves(f)[0]],
                "bspline": {"degree": b.Degree, "poles": b.NbPoles, "length_mm": f.Shape.Length,
                            "tolerance_mm": f.Tolerance.Value, "deviation_mm": f.BSplineDeviation}}

    report = {
        "input": os.path.relpath(src, ROOT) if src.startswith(ROOT) else src,
        "points": int(len(xyz)),
        "plane": {"origin": list(plc.Base), "normal": list(plc.Rotation.multVec(App.Vector(0, 0, 1))),
                  "x_axis": list(plc.Rotation.multVec(App.Vector(1, 0, 0)))},
        "inflection_3d": list(infl),
        "joint": joint,
        "keyline": fit_json(keyline),
        "one_piece": fit_json(whole),
        "keyline_discrete": fit_json(discrete),
        "sketch": {"name": sketch.Name, "bsplines": len(ids)},
        "g2_quadratic": {"pieces": g2.Pieces, "poles": g2.Poles, "deviation_mm": g2.Deviation,
                         "curvature_jump": g2.CurvatureJump},
        "elastic_spline": {"ducks": NDUCKS, "tension_per_mm2": batten.SplineTension,
                           "length_mm": batten.SplineLength, "energy_per_mm": batten.Energy,
                           "max_curvature_per_mm": batten.MaxCurvature,
                           "duck_forces_ei_half_per_mm2": [v.Length for v in batten.DuckForces],
                           "bspline_poles": batten.Poles,
                           "bspline_deviation_mm": batten.BSplineDeviation},
        "files": {k: (os.path.relpath(v, ROOT) if v.startswith(ROOT + os.sep) else v) for k, v in
                  (("fcstd", fcstd), ("svg", svg), ("json", os.path.join(out, "demo.json")))},
        "seconds": round(time.time() - t0, 2),
    }
    sketch_name = sketch.Name
    App.closeDocument(doc.Name)

    # the saved document is parametric: reopen, recompute from the scan, same result
    doc = App.openDocument(fcstd)
    for f in (doc.getObject(keyline_name), doc.getObject(whole_name)):
        f.touch()
    doc.recompute()
    k2 = doc.getObject(keyline_name)
    same = (not k2.Status.startswith("error") and abs(k2.Rms - report["keyline"]["rms_mm"]) < 1e-6
            and max(k2.Shape.distToShape(Part.Vertex(App.Vector(*p)))[0] for p in check_pts) < 2 * TOL)
    App.closeDocument(doc.Name)
    if not same:
        raise RuntimeError(f"{fcstd}: reopened and recomputed, the keyline fit changed ({k2.Status})")
    report["reopened_and_recomputed"] = "same result"
    write_json(report, os.path.join(out, "demo.json"))

    print("")
    print("libelastica demo: scanned roof-tile keyline")
    print(f"  input             {report['input']} ({len(xyz)} points, 3D)")
    print(f"  plane fit         normal ({', '.join(f'{v:.3f}' for v in report['plane']['normal'])}), "
          f"points {lines[3].split(': ')[1]} off it")
    print(f"  inflection        ({', '.join(f'{v:.2f}' for v in infl)}) mm, the joint of the two halves")
    print(f"  joint             G2: tangent break {joint['tangent_break_deg']:.1e} deg, curvature "
          f"{joint['curvature_1_per_mm'][0]:.1e} / {joint['curvature_1_per_mm'][1]:.1e} 1/mm "
          f"(B-spline: {joint['bspline_tangent_break_deg']:.1e} deg, "
          f"{max(joint['bspline_curvature_1_per_mm']):.1e} 1/mm)")
    print("  distances         point to curve (rms, max), each point's nearest curve point")
    for key, title in (("keyline", "keyline, smooth"), ("keyline_discrete", "keyline, discrete"),
                       ("one_piece", "one piece, smooth")):
        r = report[key]
        print(f"  {title:18s}{r['points']} points, rms {r['rms_mm']:.3f} mm, max "
              f"{r['max_error_mm']:.3f} mm, k = {', '.join(f'{k:.4f}' for k in r['k'])}, "
              f"{r['status']}")
    kb = report["keyline"]["bspline"]
    print(f"  B-spline          {len(ids)} x degree {kb['degree']} in sketch '{sketch_name}' "
          f"(G2 at the joint), {kb['poles']} poles, within {kb['deviation_mm']:.2g} mm of the "
          "elasticae")
    files = report["files"]
    g = report["g2_quadratic"]
    print(f"  G2 quadratic      {g['pieces']} pieces, {g['poles']} poles, within "
          f"{g['deviation_mm']:.2g} mm of the keyline, curvature jumps {g['curvature_jump']:.1g}")
    b = report["elastic_spline"]
    print(f"  elastic spline    free batten through {b['ducks']} ducks, {b['length_mm']:.1f} mm, "
          f"energy {b['energy_per_mm']:.3g}/mm, largest duck force "
          f"{max(b['duck_forces_ei_half_per_mm2']):.3g} EI/2/mm^2, {b['bspline_poles']} poles")
    print(f"  wrote             {files['fcstd']}, {files['svg']} ({backend}), {files['json']}")
    print(f"  reopened          {files['fcstd']}: recomputed from the scan, same result")
    print(f"  time              {report['seconds']} s")


def main():
    src = os.environ.get("ELASTICA_DEMO_INPUT", os.path.join(HERE, "keyline_3d.csv"))
    out = os.environ.get("ELASTICA_DEMO_OUT", os.path.join(ROOT, "out"))
    try:
        run(os.path.abspath(src), os.path.abspath(out))
    except SystemExit:
        raise
    except BaseException:
        traceback.print_exc()
        print("demo FAILED", file=sys.stderr)
        sys.exit(1)
    sys.exit(0)


main()
