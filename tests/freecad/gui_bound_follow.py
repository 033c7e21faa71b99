"""An open panel follows its feature's recompute (gui_smoke.py calls run_all); QA21gui F2: a
blend's panel open (double-click) on a blend whose Tension is bound to a spreadsheet cell, the
cell changed 0.001 -> 0.003 /mm^2 and the document recomputed: the feature was solved again
(Tension 0.003) but the panel still showed Tension 0.001, its Length and its solution list: the
designer read the old blend. Now the bound box shows the cell's value and the results follow,
in every panel (panelexpressions.follow_recompute): the blend's and the fit's (ResampleStep
bound) are checked here.

Screenshot: gui_bound_cell_followed.png (the blend's panel after the cell changed)."""
import FreeCAD as App

import elastica_samples as S
from freecad.elastica import blend as B
from freecad.elastica import fit as F

G = None            # the gui_smoke module (check, wait, screenshot, double_click, ...)


def _items(panel):
    """The Solutions rows as read (units.unbroken's no-break spaces and joiners plain)."""
    return [panel.list.item(i).text().replace("\u00a0", " ").replace("\u2060", "")
            for i in range(panel.list.count())]


def blend_follows(doc, sheet):
    sheet.set("B1", "=0.001 / mm^2")
    sk = S.two_lines_sketch(doc)
    doc.recompute()
    b = B.make(doc, (sk, "Edge1"), (sk, "Edge2"), Mode="tension", Tension=0.001)
    b.setExpression("Tension", "Params.B1")
    doc.recompute()
    panel = G.double_click(b)
    G.wait()
    before = (panel.tension.value(), panel.length.value(), _items(panel))
    sheet.set("B1", "=0.003 / mm^2")
    doc.recompute()
    G.wait()
    now = (panel.tension.value(), panel.length.value(), _items(panel))
    G.screenshot("gui_bound_cell_followed.png")
    G.check(abs(b.Tension - 0.003) < 1e-15 and abs(now[0] - 0.003) < 1e-12
            and abs(before[0] - 0.001) < 1e-12,
            f"F2: the blend panel's bound Tension follows its cell 0.001 -> 0.003 "
            f"(box {before[0]} -> {now[0]}, feature {b.Tension})")
    from freecad.elastica.blend_panel import row_lines      # (one line a row; in full: tips)
    G.check(now[2] == row_lines(b) and now[2] != before[2]
            and abs(now[1] - float(b.BlendLength)) < 1e-3 and now[1] != before[1],
            f"F2: and its solution list and Length are the blend's of now ({before[1]} -> "
            f"{now[1]}, BlendLength {float(b.BlendLength)}; list {now[2][:1]})")
    G.check(panel.result.text() == panel.result_text(), "F2: its result text too")
    panel.accept()
    G.pump()


def fit_follows(doc, sheet):
    sheet.set("C1", "=2 mm")
    pts = S.points_sketch(doc, S.keyline_xy(30)[0], "Dots")
    doc.recompute()
    f = F.make(doc, [(pts, [])])
    f.setExpression("ResampleStep", "Params.C1")
    doc.recompute()
    panel = G.double_click(f)
    G.wait()
    before = (panel.step.value(), panel.result.text())
    sheet.set("C1", "=7 mm")
    doc.recompute()
    G.wait()
    now = (panel.step.value(), panel.result.text())
    G.check(float(f.ResampleStep) == 7.0 and now[0] == 7.0 and before[0] == 2.0
            and now[1] == panel.result_text() and now[1] != before[1],
            f"F2: the fit panel's bound Resample and its result follow the cell 2 -> 7 mm "
            f"({before[0]} -> {now[0]}; {before[1][:60]!r} -> {now[1][:60]!r})")
    panel.accept()
    G.pump()


def run_all(smoke):
    global G
    G = smoke
    doc = S.new_doc("ElasticaBoundFollow")
    sheet = doc.addObject("Spreadsheet::Sheet", "Params")
    blend_follows(doc, sheet)
    fit_follows(doc, sheet)
    App.closeDocument(doc.Name)
