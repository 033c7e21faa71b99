"""Panel texts in the user's unit schema, checked by the GUI smoke test (gui_smoke.py calls
run_all):

- the elliptic blend's loop warning gives its chords and loop width in the schema's length
  unit, as every other text: under any schema they were bare numbers ('chord 3.94, a loop
  1.3 wide' beside boxes in inches);
- the Fit panel's result line gives the B-spline's deviation in plain decimals, as its
  Tolerance box ('0.0000394 in'): it said 'B-spline within 2.27e-05 in'.

Screenshots: gui_ellblend_loop_imperial.png, gui_fit_result_imperial.png."""
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
    decimals, as the Tolerance box beside them ('0.0000394 in')."""
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
                and panel.tol.text() == "0.0000394 in",
                f"the Fit result line in plain decimals: {said!r}, "
                f"Tolerance {panel.tol.text()!r}")
        panel.reject()
        G.pump()


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaSchemaTexts")
    ellblend_loop_in_the_schema(doc)
    fit_result_in_plain_decimals(doc)
    App.closeDocument(doc.Name)
