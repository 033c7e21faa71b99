"""The Elastic blend's task panel (taskpanels.py holds the other features' panels and
open_for; the machinery, ``Panel``, is in panelbase.py): Solve for a length or a tension,
Continuity G1 / G2, the list of solutions to pick from (the pick kept across sessions);
where the command or G2 did not start at the free batten, the length chosen and why
(blend_start), on its warning line."""
from __future__ import annotations

import re

from PySide import QtCore, QtGui

from . import blend as B
from . import blend_start as BS
from .geometry import is_sketch
from .panelbase import Panel, said_now
from .units import length_mark, length_text, outer_parts, per_length, unbroken


G2_LIST_TIP = (". G2: these are the G1 solutions; the G2 blend is bent from the one picked "
               "(its branch: loops, inflections), and that row says what is drawn: the G2 "
               "blend's length (its energy, inflections and curvature in the row's tooltip)")


class BlendPanel(Panel):
    title = "Elastic blend"
    icon_name = "blend"

    def build(self):
        o = self.obj
        self.picked = self.saved_pick()  # the user's choice of solution, kept across edits
        if self.note and o.Mode == "length":
            self.auto = float(o.Length)  # the command's length (no free batten)
        g = self.box("Elastic blend")
        self.warning_row(g)             # why the command did not start at the free batten
        self.mode = self.choice(g, "Solve for", "Mode", B.MODES, ["a length", "a tension"],
                                "A tension (0: the free batten, the fairest curve; G2: see "
                                "Tension) or a given arc length")
        self.length = self.number(g, "Length", "Length", 0.0, 1e7, 1.0, "mm",
                                  "Arc length of the blend (mm); 0 = the free batten's length (" +
                                  B.G2_FREE_TIP + "). In tension mode: the chosen solution's "
                                  "length",
                                  when=lambda: o.Mode == "length")
        self.tension = self.number(g, "Tension", "Tension", -1e6, 1e6, self.tension_step(),
                                   "1/mm\u00b2", "Tension sigma (1/mm\u00b2): 0 = free batten (" +
                                   B.G2_FREE_TIP + "), > 0 pulls the curve straighter (G1; a "
                                   "G2 blend is held by its guide ducks: see Continuity), < 0 "
                                   "compresses it (G1 only). In length "
                                   "mode: the chosen solution's tension", when=lambda: o.Mode == "tension")
        self.end1 = self.check(g, "Leave edge 1 at its end vertex", "AtEnd1",
                               "Checked: from the first edge's end vertex; else its start")
        self.end2 = self.check(g, "Enter edge 2 at its end vertex", "AtEnd2",
                               "Checked: into the second edge's end vertex; else its start")
        self.continuity = self.choice(g, "Continuity", "Continuity", B.CONTINUITIES,
                                      ["G1 (tangent)", "G2 (curvature)"], B.G2_TIP)
        s = self.box("Solutions")
        self.list = QtGui.QListWidget()
        # one line a row, cut with an ellipsis where the 260 px Combo View ends (its
        # tooltip in full): wrapped, one row ran to three lines (review revT)
        self.list.setWordWrap(False)
        self.list.setHorizontalScrollBarPolicy(QtCore.Qt.ScrollBarAlwaysOff)
        self.list.setTextElideMode(QtCore.Qt.ElideRight)
        self.list.setMinimumHeight(90)
        self.list.setMaximumHeight(140)       # about three solutions; the panel stays short
        self.list.setToolTip(self.LIST_TIP)
        self.list.currentRowChanged.connect(self.pick)
        self.row(s, "", self.list)
        # the G2 batten of the free length (Length 0) starts from the library's own guess:
        # no G1 solution to pick
        self.enablers.append((self.list, lambda: not (o.Continuity == "G2" and
                                                      o.Mode == "length" and o.Length == 0)))
        self.row(s, "", self.result)
        self.details_rows(s)
        self.bspline_box("the elastica", "Degree of the B-spline (3 to 7): 5 to 7 need few "
                         "poles")
        out = self.box("Output")
        same = bool(o.Edge1) and bool(o.Edge2) and o.Edge1[0] == o.Edge2[0] and is_sketch(o.Edge1[0])
        self.into_sketch = self.check(out, "Copy into the edges' sketch", "_copy",
                                      "OK adds a copy of the B-spline to the edges' sketch, "
                                      "joined to both by Tangent constraints (coincident and "
                                      "tangent, as Sketcher's fillet joins its arc). G2 is in "
                                      "the copy's poles as written: FreeCAD has no curvature "
                                      "constraint for B-splines, so when the edges are edited "
                                      "later the Sketcher keeps the joints coincident and "
                                      "tangent only (the blend feature re-solves G2 and says "
                                      "how far its copy is off)",
                                      target=self, when=lambda: same)

    _copy = False

    def saved_pick(self):
        """The Solution picked before this panel opened (another panel session, the property
        editor): kept across this panel's edits as a pick made in it is (update), not
        dropped by the first length typed (QA23gui F5: solution 2 -> 'solution 1 of 4' at
        130 mm). None for the lowest (1) or one an expression sets."""
        o = self.obj
        return o.Solution if o.Solution > 1 and not self.expression("Solution") else None

    def tension_step(self):
        """An arrow step of about a tenth of the tension scale 1/distance^2."""
        try:
            e1, e2 = self.obj.Proxy.ends(self.obj)
            a = B.edge_end(e1, self.obj.AtEnd1)[0]
            d = (B.edge_end(e2, self.obj.AtEnd2)[0] - a).Length
            return float(f"{0.1 / d ** 2:.0e}") if d > 0 else 1e-4
        except Exception:
            return 1e-4

    def changed(self, prop):
        o = self.obj
        if prop != "Continuity":
            self.g2_from = None         # an edit: G1 no longer returns to the command's length
        if prop in ("Mode", "AtEnd1", "AtEnd2"):
            self.note = ""              # the command's choice of mode is the user's now
        if prop == "Mode":
            self.auto = None
            self.picked = None          # the feature keeps the curve shown (_kept_shown)
            if o.Mode == "length" and o.Lengths:
                # length mode starts from the length of the curve on screen
                o.Length = o.BlendLength
            elif o.Mode == "length" and float(o.Length) == 0.0:
                self.start_by_length()  # none on screen: where no free batten, the command's
            elif o.Mode == "tension" and o.Lengths and not self.expression("Tension"):
                # and tension mode from the tension of the curve on screen: not 0, which
                # may have no batten (QA12: reset to 0 after "no free batten joins these ends")
                o.Tension = o.BlendTension
                self.show_mode()
        elif prop in ("AtEnd1", "AtEnd2"):
            self.ends_changed()
        elif prop == "Continuity":
            self.continuity_changed()

    auto = None         # the length the command or the panel chose (no free batten), if shown
    g2_from = None      # (auto, note) where G2 left the command's length (G1 restores them)
    G2_STARTED = "G2 solved for "       # g2_started's note: G2's start, no G1 note

    def continuity_changed(self):
        """G2 asked at the length the command chose (``auto``: no free G1 batten joins the
        ends, not the designer's length) where no G2 blend of it is found: the free G2
        batten, else the fairest length a G2 blend is found at (blend_start.g2_start), said
        on the warning line, before the error (QA23gui F4: line -> arc R25, the command's
        69.1 mm, G2 refused 'no G2 blend of length 69.1 mm ... found at 92.2, 115, ...').
        Back to G1 before anything else changed: the command's length again; else G2's note
        dropped (G1 at G2's length: its words are false)."""
        o = self.obj
        if self.expression("Mode") or self.expression("Length") or self.expression("Tension"):
            return                      # the expressions decide the values
        if o.Continuity == "G2" and o.Mode == "length" and self.auto is not None \
                and float(o.Length) == self.auto:
            self.g2_from = (self.auto, self.note)      # tried by update, after the solve
        elif o.Continuity == "G1" and self.g2_from is not None:
            (self.auto, note), self.g2_from = self.g2_from, None
            o.Mode, o.Length = "length", self.auto
            self.note = note
            self.show_mode()
        elif o.Continuity == "G1" and self.G2_STARTED in self.note:
            self.note = ""              # g2_started's words, false at G1 (another edit came first)

    def g2_started(self):
        """After G2's solve at the command's length (continuity_changed): where it failed,
        g2_start's mode and value set, and said; True where so (solve again)."""
        o = self.obj
        auto = self.g2_from[0] if self.g2_from else None
        if auto is None or o.Continuity != "G2" or o.Mode != "length" or \
                float(o.Length) != auto or not o.Status.startswith("error"):
            return False
        try:
            e1, e2 = o.Proxy.ends(o)
            start = BS.g2_start(e1, o.AtEnd1, e2, o.AtEnd2, o.Proxy.sketch_plane(o), auto)
        except Exception:       # bad ends: the feature's Status says it
            return False
        if start is None:
            return False
        if start[0] == "tension":
            o.Mode, o.Tension = "tension", 0.0
            which = "the free G2 batten (tension 0), which the guide ducks hold"
        else:
            o.Length = start[1]
            which = (f"{length_mark(start[1], 4)}, the fairest length a G2 blend was found "
                     "at (not pushed together, fewest inflections)")
        self.note = (f"No free G1 batten joins these ends and no G2 blend of the command's "
                     f"length {length_mark(auto, 4)} was found: {self.G2_STARTED}{which}; "
                     f"back to G1, {length_mark(auto, 4)} again")
        self.show_mode()
        return True

    def ends_changed(self):
        """New ends, as the command starts: the free batten where one joins them, else a
        length (blend_start.free_or_length, said on the warning line); only where the free batten
        was asked (Tension 0) or the length shown is the one chosen so (not the user's)."""
        o = self.obj
        auto = o.Mode == "length" and self.auto is not None and float(o.Length) == self.auto
        if not (auto or (o.Mode == "tension" and o.Tension == 0.0)):
            return
        if not self.start_by_length() and auto and self.free:
            self.auto = None
            o.Mode = "tension"          # Tension is still 0: the free batten
            self.show_mode()

    free = False        # the last free_or_length found the free batten

    def start_by_length(self):
        """Length mode at blend_start.free_or_length's length where no free batten joins the
        ends (True), the reason on the warning line; False where the free batten exists
        (self.free) or the ends are bad (the solve says why)."""
        o = self.obj
        self.free, hand = False, []
        try:
            e1, e2 = o.Proxy.ends(o)
            start = BS.free_or_length(e1, o.AtEnd1, e2, o.AtEnd2, o.Proxy.sketch_plane(o),
                                     hand=hand)
        except Exception:       # bad ends or none found: the feature's Status says it
            return False
        if hand:                # solved here: the next recompute takes it (handed)
            o.Proxy.checked = hand[-1]
        if start is None:
            self.free = True
            return False
        if self.expression("Mode") or self.expression("Length"):
            # the expressions decide the values; a bound Length is one to solve for (the
            # binding stays), not a free batten that does not exist (QA12)
            if self.expression("Mode"):
                return False
            o.Mode, self.auto = "length", float(o.Length)   # chosen here: ends_changed redoes it
            self.note = (f"No free batten (tension 0) joins these ends: solved for the length "
                         f"Length is bound to ({self.expression('Length')}), "
                         f"{length_mark(float(o.Length), 4)}")
            self.show_mode()
            return True
        o.Mode, o.Length = "length", start[0]
        self.auto, self.note = start        # kept with the values it explains: after them
        self.show_mode()
        return True

    def show_mode(self):
        """The Solve for and Length fields after the panel set them (no signal)."""
        o = self.obj
        self.mode.blockSignals(True)
        self.mode.setCurrentIndex(B.MODES.index(o.Mode))
        self.mode.blockSignals(False)
        given = self.length if o.Mode == "length" else self.tension
        self.show_value(given, float(getattr(o, "Length" if o.Mode == "length" else "Tension")))
        self.refresh_enabled()

    def update(self):
        super().update()
        o = self.obj
        if self.g2_started():
            super().update()
        if self.picked and not o.Status.startswith("error") and o.Solution != self.picked \
                and self.picked <= len(o.Lengths) and not self.expression("Solution"):
            o.Solution = self.picked            # the user's pick survives the edit
            super().update()

    def view_objects(self):
        return [link[0] for link in (self.obj.Edge1, self.obj.Edge2) if link]

    def pick(self, row):
        if self.expression("Solution"):      # its expression picks (F6)
            self.refresh()
            return
        if row >= 0 and row + 1 != self.obj.Solution:      # Solution counts from 1
            self.picked = row + 1
            self.obj.Solution = row + 1
            self.update()

    def descriptions(self):
        return B.g2_rows(self.obj)

    def details_rows(self, grid):
        """A "Details" toggle under the one-line result (FreeCAD's own message boxes' Show
        Details...): the full Status, hidden until asked, and shown only where it says more."""
        self.more = QtGui.QToolButton()
        self.more.setText("Details")
        self.more.setCheckable(True)
        self.more.setAutoRaise(True)
        self.more.setToolButtonStyle(QtCore.Qt.ToolButtonTextBesideIcon)
        self.more.setArrowType(QtCore.Qt.RightArrow)
        self.more.setToolTip("Why this blend: the full Status (also in the Report view, once "
                             "a recompute)")
        self.details = QtGui.QLabel()
        self.details.setWordWrap(True)
        self.details.setTextInteractionFlags(QtCore.Qt.TextSelectableByMouse)
        self.details.setVisible(False)
        self.more.toggled.connect(self.show_details)
        self.row(grid, "", self.more)
        self.row(grid, "", self.details)

    def show_details(self, shown=None):
        shown = self.more.isChecked() if shown is None else shown
        self.more.setArrowType(QtCore.Qt.DownArrow if shown else QtCore.Qt.RightArrow)
        self.details.setVisible(bool(shown) and self.more.isVisible())

    def full_text(self):
        """The Status in full, one part a line, and the B-spline (the Details, the tooltip)."""
        o = self.obj
        said = said_now(o, "Status")
        if said.startswith("error"):
            return "<br>".join(outer_parts(said.removeprefix("error: ")))
        return "<br>".join(outer_parts(said) + [f"B-spline: {o.Poles} poles, degree {o.Degree}"])

    def show_error(self):
        """The error line in one line (what is wrong, the action to take: error_line), the
        full message in its tooltip and under Details."""
        super().show_error()
        o = self.obj
        if self.error is not None and not (self._input_said or self._ok_said) and \
                o.Status.startswith("error"):
            self.error[1].setText(unbroken(error_line(said_now(o, "Status"))))   # '1/mm²' whole
            self.error[1].setToolTip(self.full_text())
        elif self.error is not None:
            self.error[1].setToolTip("")

    def refresh(self):
        o = self.obj
        self.list.blockSignals(True)
        self.list.clear()
        full = self.descriptions()
        for j, t in enumerate(row_lines(o)):         # one line each, in full in its tooltip
            self.list.addItem(unbroken(t))          # quantities whole
            self.list.item(j).setToolTip(unbroken(full[j]) if j < len(full) else "")
        if o.Descriptions:
            self.list.setCurrentRow(max(0, min(o.Solution - 1, len(o.Descriptions) - 1)))
        self.list.blockSignals(False)
        # a G2 blend is solved for a tension >= 0 (pushed: give a length); a negative one
        # typed before stays, and the feature says why it is refused
        g2_tension = o.Continuity == "G2" and o.Mode == "tension" and o.Tension >= 0
        self.tension.blockSignals(True)
        self.tension.setMinimum(0.0 if g2_tension else -1e6)
        self.tension.blockSignals(False)
        # the field not being solved for shows the value of the curve on screen; after a
        # failed solve none (the dashed curve is the last good one's); the field solved
        # for shows what is asked
        for box, value, prop in ((self.length, o.BlendLength, "Length"),
                                 (self.tension, o.BlendTension, "Tension")):
            if o.Mode == prop.lower():
                if box.specialValueText():
                    self.show_value(box, float(getattr(o, prop)))
            elif o.Descriptions:
                self.show_value(box, value)
            else:
                self.show_no_value(box)
        self.list.setToolTip(self.LIST_TIP + (G2_LIST_TIP if o.Continuity == "G2" else ""))
        super().refresh()
        full = self.full_text()
        self.result.setToolTip("" if o.Status.startswith("error") else full)
        notes = [] if self.warning is None or o.Status.startswith("error") else self.warnings()
        if self.warning is not None:
            # the amber line in one line too (it ran to seven in the 260 px Combo View: review
            # revT): what is wrong; the note in full is its tooltip and heads the Details
            self.warning[1].setText("<br>".join(unbroken(warning_line(w)) for w in notes))
            self.warning[1].setToolTip("<br>".join(notes))
            full = "<br>".join(notes + [full])
        self.details.setText(full)
        said = self.error[1].text() if o.Status.startswith("error") else self.result.text()
        self.more.setVisible(bool(o.Status) and full != said)
        self.show_details()

    LIST_TIP = ("Every elastic curve for these ends, by bending energy: length, energy, "
                "inflections, loops (each row's tooltip: its largest curvature and turn too); "
                "pick one to use it")

    def result_text(self):
        return unbroken(status_line(self.obj))     # its quantities whole, as the rows

    def copy_code(self):
        if not (self.into_sketch.isEnabled() and self.into_sketch.isChecked()):
            return ""
        doc = f"App.getDocument({self.doc.Name!r})"
        return ("from freecad.elastica import blend as elastica_blend\n"
                f"elastica_blend.copy_into_sketch({doc}.getObject({self.obj.Name!r}))\n")


# ----------------------------------------------------------------- one line a state
# FreeCAD's own panels say one line (what was made, or what is wrong and the one action to
# take) and give the why on demand: the Status in full is the Details, the tooltip and the
# Report view's (blend.BlendProxy.apply: once a recompute); QA's F4 line and arc at G2 said
# ~14 lines in the Combo View (/tmp/fcblend/shots/g10_g2.png).

def _no_asides(text):
    """``text`` without its parenthesised asides (nested ones too)."""
    out, depth = [], 0
    for c in text:
        if c == "(":
            depth += 1
        elif c == ")" and depth:
            depth -= 1
        elif not depth:
            out.append(c)
    return re.sub(r"\s+", " ", "".join(out)).strip(" ,;:")


def status_line(obj):
    """One line for a solved blend: what is drawn, its length, and where it is not what
    was asked for (the fairest of its branch shown instead of the free batten, no free G2
    batten found, the library's own start), in a few words; the why is the Details'."""
    o = obj
    status = said_now(o, "Status")
    first = outer_parts(status)[0]
    length = length_text(float(o.BlendLength), 4)
    picked = f"solution {o.Solution} of {len(o.Lengths)}"
    if o.Continuity != "G2" or not status.startswith("G2"):
        return f"G1 blend, {length}: {picked}" + (" (followed: see Details)" if "(" in first
                                                  else "")
    if "shown instead the fairest between it and the G1" in first:
        what = "fairest of its branch"
    elif "snake" in first:
        what = "fairest by length (free batten: a snake)"
    elif "no free G2 batten (tension 0) was found" in first:
        what = "fairest by length (no free batten)"
    elif "library's own start" in first:
        what = "from the library's own start" + ("" if "did not bend" not in first
                                                  else f", not {picked}")
    elif "(free batten)" in status:
        what = f"free batten, from {picked}"
    else:
        what = f"from {picked}"
    return f"G2 blend, {length}: {what}"


def warning_line(note):
    """One line for a note on the warning line: what is wrong, the note's first part without
    its asides, up to its first ': ' where longer than a Combo View line (~40 characters)."""
    what = _no_asides(outer_parts(note)[0])
    return what if len(what) <= 40 else what.split(": ", 1)[0]


def error_line(status):
    """One line for a failed solve (``status``: 'error: ...' as said): what is wrong (the
    message's first part, its asides left to the Details) and the one action its hint
    names (the lengths a G2 blend was found at, the highest tension one was, ...)."""
    text = status.removeprefix("error: ")
    parts = outer_parts(text)
    if len(parts) == 1 and "(" not in text:
        return text[:1].upper() + text[1:]
    what = _no_asides(parts[0])
    if "no G2 blend found between these edges" in text:   # blend_g2.g2_lengths_hint: none anywhere
        return "No G2 blend found between these edges (tension 0 and lengths tried): use G1"
    m = re.search(r"G2 blends were found at the lengths (.*?) \(tried", text)
    n = re.search(r"found at tensions up to about (.*?), but none", text)
    free = re.search(r"the free G2 batten \(tension 0\) is (.*?) long", text)
    met = re.search(r"reached battens of tension up to (.*?) \(length", text)
    if m:
        found = m.group(1).split(", ")
        action = ("Solve for a length of " + found[0] if len(found) == 1 else
                  f"Solve for a length, {found[0]} to {found[-1]}") + ", or G1"
    elif n or met:
        action = f"try a tension up to {(n or met).group(1)}, a length, or G1"
    elif free:
        action = f"try a length from {free.group(1)}, or G1"
    else:                       # the advice after the last part's last ': '
        tail = _no_asides(parts[-1]).rsplit(": ", 1)
        action = tail[-1] if len(parts) > 1 or len(tail) > 1 else ""
    line = f"{what}: {action}" if action and action not in what else what
    return line[:1].upper() + line[1:]


def row_lines(obj):
    """The Solutions rows in one line each (blend.descriptions / g2_rows in full are their
    tooltips): length, energy, inflections, loops where any; at G2 each row its G1 solution
    and the picked one the G2 blend drawn from it (its length) right after the G1 length: a
    row is one line, cut with an ellipsis where the Combo View ends."""
    n = len(obj.Descriptions)
    data = [obj.Lengths, obj.Energies, obj.Inflections, obj.Loops]
    if any(len(d) != n for d in data):
        return list(obj.Descriptions)
    g2 = obj.Continuity == "G2" and bool(obj.Curves)
    # at G2 the drawn blend's length right after its G1 solution's, in the ~30 characters an
    # elided row keeps at 260 px ('G1' and 'drawn' are the tooltip's: g2_rows)
    drawn = f" \u2192 G2 {length_text(float(obj.BlendLength), 4)}" if g2 else ""
    return [f"{j + 1}: {length_text(L, 4)}"
            + (drawn if j == obj.Solution - 1 else "") + f", energy {per_length(E)}, "
            f"{B.plural(i, 'inflection')}" + (f", {B.plural(lp, 'loop')}" if lp else "")
            for j, (L, E, i, lp) in enumerate(zip(*data))]
