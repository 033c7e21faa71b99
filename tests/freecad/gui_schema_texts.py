"""Panel texts in the user's unit schema, checked by the GUI smoke test (gui_smoke.py calls
run_all):

- the elliptic blend's loop warning gives its chords and loop width in the schema's length
  unit, as every other text: under any schema they were bare numbers ('chord 3.94, a loop
  1.3 wide' beside boxes in inches);
- the Fit panel's result line gives the B-spline's deviation in plain decimals, as its
  Tolerance box ('0.000039 in'): it said 'B-spline within 2.27e-05 in';
- a measured length at rounding noise (below FreeCAD's Confusion, 1e-7 mm) as FreeCAD
  writes it, 0: the fit of points on an elastica said 'rms 1.2e-11 mm, max 2.24e-11 mm',
  the elliptic blend of points in line 'B-spline within 7.11e-15 mm';
- under US customary the Fit panel's warning names the far points' place with its unit,
  '"' as FreeCAD writes inches there: it gave the place bare after '0.974 thou', read as
  thou.

Screenshots: gui_ellblend_loop_imperial.png, gui_fit_result_imperial.png,
gui_fit_rounding_noise.png, gui_ellblend_rounding_noise.png, gui_fit_outliers_us.png."""
import re

import FreeCAD as App
import FreeCADGui as Gui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)


def ellblend_loop_in_the_schema(doc):
    """Points whose interpolation at m = 0.52 loops, the panel open under Imperial decimal:
    its warning line says the loop's place and size in inches."""
    with G.user_schema(3):
        sk = S.points_sketch(doc, [(0.0, 0.0), (30.0, 80.0), (70.0, 90.0), (100.0, 0.0)],
                             "Looping")
        panel = G.open_panel(doc, "Elastica_EllipticBlend", [(sk, "")], "Elliptic blend curve")
        from freecad.elastica.ellblend import K_CONVENTIONS
        panel.conv.setCurrentIndex(K_CONVENTIONS.index("parameter"))      # m = k^2
        G.wait()
        G.type_into(panel.k, "0.52")
        G.wait()
        said = panel.warning[1].text()
        Gui.SendMsgToActiveView("ViewFit")
        G.screenshot("gui_ellblend_loop_imperial.png")
        G.check(panel.obj.KConvention == "parameter" and panel.obj.K == 0.52
                and panel.warning[0].isVisible() and "chord 3.94 in" in said
                and " in wide)" in said and "mm" not in said,
                f"the loop warning in inches: {said!r}")
        panel.reject()
        G.pump()


def fit_result_in_plain_decimals(doc):
    """The sample S curve's 40 points fitted under Imperial decimal: the result line's
    lengths (rms 0.0000442 in: below 1e-4 in, where '%.3g' turns to an exponent) in plain
    decimals, as the Tolerance box beside them ('0.000039 in')."""
    with G.user_schema(3):
        sk = S.points_sketch(doc, S.keyline_xy(40)[0], "Keyline")
        panel = G.open_panel(doc, "Elastica_Fit", [(sk, "")], "Fit elastica")
        G.wait()
        said = panel.result.text()
        lengths = re.findall(r"(-?[0-9.][0-9.e+-]*) in\b", said)
        G.screenshot("gui_fit_result_imperial.png")
        G.check(not panel.obj.Status.startswith("error") and len(lengths) >= 3
                and not any("e" in x for x in lengths)
                and 0 < min(float(x) for x in lengths) < 1e-4
                and panel.tol.text() == "0.000039 in",
                f"the Fit result line in plain decimals: {said!r}, "
                f"Tolerance {panel.tol.text()!r}")
        panel.reject()
        G.pump()


def rounding_noise_as_zero(doc):
    """The sample elastica's 40 points fitted by the smooth model (rms about 1e-11 mm) and
    the elliptic blend through four points in line (its B-spline within about 1e-14 mm):
    the result lines say 0 in the unit FreeCAD writes 0 in ('rms 0.00 mm, max 0.00 mm', '0.00 in'
    under Imperial decimal), a figure above the noise as before; the properties keep
    the figures."""
    sk = S.points_sketch(doc, S.keyline_xy(40)[0], "OnTheCurve")
    panel = G.open_panel(doc, "Elastica_Fit", [(sk, "")], "Fit elastica")
    panel.model.setCurrentIndex(1)                       # smooth
    G.wait()
    f = panel.obj
    said = panel.result.text()
    G.screenshot("gui_fit_rounding_noise.png")
    within = re.search(r"B-spline within ([0-9.]+) nm ", said)     # above the noise: as before
    G.check(f.Model == "smooth" and f.Rms < 1e-7 and f.MaxError < 1e-7
            and "rms 0.00 mm, max 0.00 mm<br>" in said and within and float(within.group(1)) > 100,
            f"a fit at rounding noise: 'rms 0.00 mm, max 0.00 mm' (Rms {f.Rms!r}): {said!r}")
    with G.user_schema(3):
        panel.refresh()
        said = panel.result.text()
        G.check("rms 0.00 in, max 0.00 in<br>" in said, f"and under Imperial decimal: {said!r}")
    panel.reject()
    G.pump()
    line = S.points_sketch(doc, [(0.0, 0.0), (10.0, 0.0), (20.0, 0.0), (30.0, 0.0)], "InLine")
    panel = G.open_panel(doc, "Elastica_EllipticBlend", [(line, "")], "Elliptic blend curve")
    G.wait()
    e = panel.obj
    said = panel.result.text()
    G.screenshot("gui_ellblend_rounding_noise.png")
    G.check(e.Status == "ok" and e.BSplineDeviation < 1e-7
            and said.startswith("B-spline within 0.00 mm of the curve (tolerance 1.00 \u00b5m)"),
            f"an elliptic blend at rounding noise: within 0.00 mm ({e.BSplineDeviation!r}): "
            f"{said!r}")
    panel.reject()
    G.pump()


def far_place_in_us_customary(doc):
    """40 points on the sample curve, noise 1 \u00b5m, two glitches 0.15 and 0.25 mm off,
    fitted under US customary: the warning line gives their distances in thou, as FreeCAD
    writes lengths under 2.54 mm there, and the farthest's place in inches, named '"'."""
    import numpy as np
    with G.user_schema(2):
        xy, _ = S.keyline_xy(40)
        xy = xy + np.random.default_rng(4).normal(0.0, 0.001, xy.shape) + [0.0, -160.0]
        xy[[10, 25]] += [[0.12, -0.09], [-0.20, 0.15]]
        sk = S.points_sketch(doc, xy, "FineScan")
        panel = G.open_panel(doc, "Elastica_Fit", [(sk, "")], "Fit elastica")
        panel.model.setCurrentIndex(1)                       # smooth
        G.wait()
        said = panel.warning[1].text()
        G.screenshot("gui_fit_outliers_us.png")
        G.check(panel.warning[0].isVisible() and "outliers?" in said
                and re.search(r"lie [0-9.]+ to [0-9.]+ thou from the curve", said)
                and re.search(r"FineScan's 11-Point, 26-Point; the farthest, 26-Point, in the "
                              r'sketch at \(-?[0-9.]+, -?[0-9.]+\) "\)', said),
                f"US customary: the far points in thou, their place in inches named: {said!r}")
        panel.reject()
        G.pump()


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaSchemaTexts")
    ellblend_loop_in_the_schema(doc)
    fit_result_in_plain_decimals(doc)
    rounding_noise_as_zero(doc)
    far_place_in_us_customary(doc)
    App.closeDocument(doc.Name)
