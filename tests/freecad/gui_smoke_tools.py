"""The other tools' panels, checked by the GUI smoke test (gui_smoke.py's run calls run_all after
the fit's, on its ElasticaSmoke document): the elliptic blend through points and by control
points (its convex-hull warning), Closed through five points; the G2 quadratic B-spline of the
fit's keyline sketch (its Edges arrow, an Edges count too small to cover); the curvature comb
of the blend. Screenshots: gui_ellblend_panel.png, gui_ellblend_closed.png,
gui_g2quad_panel.png, gui_comb_panel.png."""
import FreeCAD as App

G = None            # the gui_smoke module (check, wait, screenshot, ...)


def run_all(smoke, doc, S, ksk, blend):
    global G
    G = smoke
    ellblend_panel(doc, S)
    ellblend_closed_panel(doc, S)
    g2quad_panel(doc, ksk)
    comb_panel(doc, blend)


def ellblend_panel(doc, S):
    psk = S.points_sketch(doc, [(0, -60), (20, -25), (55, -20), (80, -55)], "FourPoints")
    panel = G.open_panel(doc, "Elastica_EllipticBlend", [(psk, "")], "Elliptic blend curve")
    e = panel.obj
    G.fits_combo_view(panel, "elliptic blend")
    G.check(e.Status == "ok" and "within" in panel.result.text(),
            f"elliptic blend panel shows the B-spline deviation ({e.Status})")
    G.check(not panel.d.isEnabled(), "elliptic blend through the points: d disabled")
    l0 = e.Shape.Length
    G.click_arrow(panel.k, up=True)
    G.wait()
    G.check(abs(e.K - 0.55) < 1e-12 and e.Status == "ok" and abs(e.Shape.Length - l0) > 1e-3,
            "elliptic blend: an arrow click on k previews k = 0.55")
    panel.mode.setCurrentIndex(1)
    G.wait()
    G.check(e.Mode == "control" and e.Status == "ok" and panel.d.isEnabled()
            and not panel.warning[0].isVisible() and
            e.ViewObject.Proxy.overlay_counts() == (4, 3),
            "elliptic blend panel: control points, d enabled, no warning, control polygon drawn")
    G.type_into(panel.k, "0.79")                 # m = 0.62: a blending function goes negative
    G.wait()
    G.check(not e.ConvexHull and e.Warnings and panel.warning[0].isVisible() and
            "convex hull" in panel.warning[1].text() and not G.error_line(panel),
            f"elliptic blend: the lost convex hull shown on the warning line ({e.Status})")
    G.screenshot("gui_ellblend_panel.png")
    G.type_into(panel.k, "0.55")
    G.wait()
    G.check(e.ConvexHull and not e.Warnings and not panel.warning[0].isVisible(),
            "elliptic blend: the warning line goes with the warning")
    panel.sketch.setCurrentIndex(panel.sketch.count() - 1)
    n0 = len(doc.Objects)
    G.check(panel.accept(), "elliptic blend panel accepts")
    G.pump()
    G.check(len(doc.Objects) == n0 + 1 and len(doc.Objects[-1].Geometry) == 1,
            "elliptic blend B-spline copied into a new sketch")


def ellblend_closed_panel(doc, S):
    """QA17 P5: five points through which the feature makes the C1 composite, Closed."""
    psk = S.points_sketch(doc, [(0, -60), (20, -25), (55, -20), (80, -55), (40, -80)],
                          "FivePoints")
    panel = G.open_panel(doc, "Elastica_EllipticBlend", [(psk, "")], "Elliptic blend curve")
    e = panel.obj
    G.check(e.Status == "ok" and not e.Shape.Edges[0].isClosed() and panel.closed.isEnabled()
            and not panel.d.isEnabled(), f"elliptic blend through five points ({e.Status})")
    panel.closed.click()                    # a mouse click on the check box
    G.wait()
    edge = e.Shape.Edges[0]
    G.check(e.Closed and e.Status == "ok" and edge.isClosed() and
            e.ViewObject.Proxy.overlay_counts() == (16, 15),
            f"elliptic blend panel: Closed closes the curve through five points ({e.Status})")
    from freecad.elastica.panelbase import show_box
    show_box(App.BoundBox(e.Shape.BoundBox))
    G.screenshot("gui_ellblend_closed.png")
    panel.mode.setCurrentIndex(1)           # five control points: no blend, said
    G.wait()
    G.check(not panel.closed.isEnabled() and "5 control points" in G.error_line(panel) and
            "3 n + 1" in G.error_line(panel),
            f"elliptic blend: control points disable Closed ({G.error_line(panel)})")
    panel.reject()
    G.pump()


def g2quad_panel(doc, ksk):
    panel = G.open_panel(doc, "Elastica_G2Quad", [(ksk, "Edge1")], "G2 quadratic B-spline")
    q = panel.obj
    G.fits_combo_view(panel, "G2 quadratic")
    G.check(q.Status == "ok" and q.Pieces == 2 and q.CurvatureJump < 1e-9 and "G2" in
            panel.result.text(), f"G2 quadratic: {q.Pieces} pieces, jump {q.CurvatureJump:.1g}")
    p0 = q.Poles
    G.click_arrow(panel.edges, up=True)
    G.wait()
    G.check(q.Edges == 25 and q.Poles != p0 and q.Status == "ok", "G2 quadratic: Edges arrow")
    G.check(q.ViewObject.Proxy.overlay_counts() == (26, 25), "G2 quadratic: its polyline drawn")
    e = ksk.Shape.Edges[0]
    ends = [e.valueAt(e.FirstParameter), e.valueAt(e.LastParameter)]
    mine = [v.Point for v in q.Shape.Vertexes]
    G.check(all(min((a - b).Length for b in mine) < 1e-9 for a in ends),
            "G2 quadratic ends exactly on the source's ends")
    G.screenshot("gui_g2quad_panel.png")
    G.type_into(panel.edges, "3")             # QA17 M2: too few to cover the S, an error
    G.wait()
    G.check("Edges = 3 leaves out" in G.error_line(panel) and "covers it" in G.error_line(panel)
            and "Invalid" in q.State, f"G2 quadratic: Edges 3 names the Edges that cover "
            f"({G.error_line(panel)})")
    G.type_into(panel.edges, "25")
    G.wait()
    G.check(q.Status == "ok" and not G.error_line(panel), "G2 quadratic: Edges 25 again")
    G.check(panel.accept(), "G2 quadratic panel accepts")


def comb_panel(doc, blend):
    n0 = G.run_on(doc, "Elastica_Comb", [(blend, "")])
    comb = doc.Objects[-1]
    G.check(len(doc.Objects) == n0 + 1 and comb.Status == "ok", "Curvature comb creates a comb")
    panel = G.double_click(comb)
    G.fits_combo_view(panel, "comb")
    s0, e0 = comb.Samples, len(comb.Shape.Edges)
    G.click_arrow(panel.samples, up=True)
    G.wait()
    G.check(comb.Samples == s0 + 1 and len(comb.Shape.Edges) > e0, "comb: Teeth arrow adds a tooth")
    G.screenshot("gui_comb_panel.png")
    panel.reject()
    G.pump()
    G.check(comb.Samples == s0 and len(comb.Shape.Edges) == e0, "comb Cancel reverts")
    # the blend and the edges it joins selected together: ONE comb on one scale (QA gui F5)
    sk = blend.Edge1[0]
    n0 = G.run_on(doc, "Elastica_Comb", [(blend, ""), (sk, "Edge1"), (sk, "Edge2")])
    both = doc.Objects[-1]
    G.check(len(doc.Objects) == n0 + 1 and both.Status == "ok" and both.Source[0] == blend and
            [(o, tuple(n)) for o, n in both.MoreSources] == [(sk, ("Edge1", "Edge2"))],
            f"Curvature comb of a blend and its two edges: one comb ({len(doc.Objects) - n0} "
            f"made, {both.Status})")
    doc.removeObject(both.Name)
