"""Panel texts in the user's unit schema, checked by the GUI smoke test (gui_smoke.py calls
run_all):

- the elliptic blend's loop warning gives its chords and loop width in the schema's length
  unit, as every other text: under any schema they were bare numbers ('chord 3.94, a loop
  1.3 wide' beside boxes in inches).

Screenshot: gui_ellblend_loop_imperial.png."""
import FreeCAD as App
import FreeCADGui as Gui

import elastica_samples as S

G = None            # the gui_smoke module (check, wait, screenshot, open_panel, ...)


def ellblend_loop_in_the_schema(doc):
    """Points whose interpolation at m = 0.52 loops, the panel open under Imperial decimal:
    its warning line says the loop's place and size in inches."""
    prefs = App.ParamGet("User parameter:BaseApp/Preferences/Units")
    old = prefs.GetInt("UserSchema", 0)
    prefs.SetInt("UserSchema", 3)
    App.Units.setSchema(3)
    try:
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
    finally:
        prefs.SetInt("UserSchema", old)
        App.Units.setSchema(old)


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaSchemaTexts")
    ellblend_loop_in_the_schema(doc)
    App.closeDocument(doc.Name)
