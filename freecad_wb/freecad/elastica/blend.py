"""Elastic blend: every elastic Hermite curve (seed 004) from an end of one edge to
an end of another, by tension (default: tension 0, the free batten) or by length;
each solution described (length, energy, inflections, loops, which way it turns,
largest curvature); the chosen one (lowest energy unless the user picked another) as a
B-spline of few poles; or, Continuity G2, the elastic spline between the two ends that also
meets both edges' curvature (two guide ducks hold it). The feature follows its
edges; writing it into a sketch is a copy."""
from __future__ import annotations

import json

import FreeCAD as App
import Part

from . import defaults
from .containers import set_shape
from .blend_g2 import g2_blend, g2_tension_reach
from .geometry import (binding_module, edge_end, el, global_element, is_sketch,
                       nearest_parameter, np, part_bspline, plane_coordinates, to_3d)
from .links import followed_edge
from .units import (length_mark, length_text, length_unit_mark, mm_marked, number_text,
                    per_area_mark, per_length, say,
                    per_length_mark, tension_mark, tension_or_zero,
                    tension_unit_mark)
from .proxy import (FeatureProxy, InputProblem, add_enum, add_geometry_index, add_length,
                    add_link, add_per_area, add_property, attach_view, bound_expression,
                    check_degree, check_number, check_tolerance,
                    read_only, set_said, VERSION)

MODES = ["length", "tension"]
CONTINUITIES = ["G1", "G2"]
BSPLINE_DEGREE = 5          # a blend's B-spline: few poles at the preference tolerance
RESULT_LISTS = ("Lengths", "Energies", "Tensions", "Inflections", "Loops", "MaxCurvatures",
                "Turns", "Descriptions", "G2Figures")
# what Tension 0 and Length 0 ask at G2 (the tooltips: not always the free batten, F10)
G2_FREE_TIP = ("G2: the free G2 batten, or where it is a far longer loop than its G1 "
               "solution the fairest G2 blend between the two lengths, which Status names")
G2_TIP = ("G1: one elastica, tangent to both edges. G2: tangent and curvature continuous at "
          "both joins. One elastica cannot meet both curvatures (8 conditions, 7 parameters), "
          "so the G2 blend is the batten between the two ends held by two guide ducks, a "
          "quarter of the way in from each edge and free to move across the line between the "
          "ends (drawn in orange with their forces): one tension throughout, the tension or "
          "length asked for (0: the free batten), bent from the chosen G1 solution. Held by its "
          "guide ducks, a G2 blend pulled does not straighten as G1 does (it may get longer), "
          "and beyond some tension there is none: the status says which tension it reaches")


class NoBlend(InputProblem):
    """Good ends, but no elastic curve joins them at this tension or length (another
    tension or length may give one): not bad input."""


def check_open(edge, what):
    """InputProblem when ``edge`` (named ``what``) is closed: its seam (parameter 0) is no
    end to blend from."""
    if edge.isClosed():
        raise InputProblem(f"{what} is a closed edge (a full {type(edge.Curve).__name__.lower()}"
                           "): a blend leaves an edge at an end vertex and it has none; use an "
                           "arc of it (trim or split it), or an elastic spline with an end on it")


def nearest_ends(e0, e1):
    """(at_end0, at_end1): the pair of ends of two edges closest to each other."""
    best = None
    for a in (False, True):
        for b in (False, True):
            d = (edge_end(e0, a)[0] - edge_end(e1, b)[0]).Length
            if best is None or d < best[0]:
                best = (d, a, b)
    return best[1], best[2]


# A picked point (Gui.Selection's PickedPoints, global) chooses its edge's end when it lies on
# the edge: within PICK_NEAR of its length (the view's tessellation of a curve is off it by a
# fraction of a percent); a scripted selection's (0, 0, 0) is no pick.
PICK_NEAR = 0.05


def picked_end(edge, point):
    """The end of ``edge`` nearer ``point`` (True: its end vertex), or None when ``point``
    is no pick on it (None, the scripted (0, 0, 0), or off the edge)."""
    if point is None or point.Length == 0.0:
        return None
    if edge.distToShape(Part.Vertex(point))[0] > PICK_NEAR * edge.Length:
        return None
    # along the edge (an arc's far end may be nearer in a straight line)
    u = nearest_parameter(edge, point)
    return edge.Curve.length(edge.FirstParameter, u) > 0.5 * edge.Length


def chosen_ends(e0, e1, pick0=None, pick1=None):
    """(at_end0, at_end1): each edge's end nearer where the user clicked it (picked_end), as
    Sketcher's trim and fillet read a click; an edge without a pick takes its end nearest
    the other's chosen end; neither picked: the nearest pair of ends (nearest_ends)."""
    a, b = picked_end(e0, pick0), picked_end(e1, pick1)
    if a is None and b is None:
        return nearest_ends(e0, e1)
    if a is None:
        p = edge_end(e1, b)[0]
        a = (edge_end(e0, True)[0] - p).Length < (edge_end(e0, False)[0] - p).Length
    elif b is None:
        p = edge_end(e0, a)[0]
        b = (edge_end(e1, True)[0] - p).Length < (edge_end(e1, False)[0] - p).Length
    return a, b


def describe(curve):
    """(inflections, loops, largest |curvature|) of a SmoothElastica or Hermite chain:
    the binding's descriptors (libelastica/shape.py), as `elastica hermite` shows them."""
    return len(el().elastica_inflections(curve)), curve.loops, curve.max_curvature


def blend_core(e0, at_end0, e1, at_end1, plane=None, mode="tension", value=0.0, none_ok=False):
    """All elastic Hermite curves from the chosen end of e0 to the chosen end of e1.

    The blend leaves e0 in its tangent direction and enters e1 along it. ``mode``
    'tension' (value = sigma, 1/mm^2) or 'length' (value = arc length in mm; 0 = the
    length of the lowest-energy free batten). Returns a dict with 'curves' (sorted
    by energy, plane coordinates), 'energies' (total_energy at the tension; bending energy
    by length), 'placement', 'distance'. Raises InputProblem; NoBlend where no curve joins
    the ends, unless ``none_ok`` ('curves' then empty: a G2 blend needs none, below)."""
    p0, d0 = edge_end(e0, at_end0)
    p1, d1 = edge_end(e1, at_end1)
    d1 = -d1                       # arriving at e1: pointing into it
    dist = (p1 - p0).Length
    if dist < 1e-9:
        raise InputProblem("the two edge ends coincide: nothing to blend")
    if mode not in MODES:
        raise InputProblem(f"unknown mode {mode!r} (length or tension)")
    value = check_number("Tension" if mode == "tension" else "Length", value, unit="1/mm^2"
                         if mode == "tension" else "mm")
    try:
        loc, plane = plane_coordinates([p0, p0 + d0 * dist, p1, p1 - d1 * dist], plane,
                                       flat=1e-6, what="two edge ends (with their tangents)")
        a0, a1 = loc[0], loc[2]
        t0, t1 = (loc[1] - a0) / dist, (a1 - loc[3]) / dist
        e = el()
        # to FreeCAD's Confusion (1e-7 mm), as its own geometry: edges in line to within it
        # are in line, joined by the straight segment (lines 1e-7 mm off each other's axis
        # 100 mm apart gave a 277 mm loop first: the near-straight curve was missed, QA)
        tol = max(1e-10, 1e-7 / dist)
        if mode == "tension":
            if value * dist * dist > e.HERMITE_SIGMA_D2_MAX:
                u = length_unit_mark()
                raise InputProblem(f"Tension = {per_area_mark(value, 6)}/{u}^2 is too high for "
                                   f"ends {length_mark(dist, 6)} apart: the solver covers "
                                   "tension times distance^2 up to "
                                   f"{e.HERMITE_SIGMA_D2_MAX:g}, here a tension of at most "
                                   f"{per_area_mark(e.HERMITE_SIGMA_D2_MAX / dist ** 2, 4, 'down')}/{u}^2")
            sols = e.hermite(a0, t0, a1, t1, tension=value, tol=tol)
        else:
            if value == 0.0:                      # the free batten's own length
                free = e.hermite(a0, t0, a1, t1, tension=0.0, tol=tol)
                if not free:
                    raise NoBlend("no free batten joins these ends: give a length")
                value = float(free[0].length)
            if value <= dist:
                raise InputProblem(f"length {length_mark(value, 6)} is not longer than the "
                                   f"{length_mark(dist, 6)} between the ends: any length above "
                                   f"{length_mark(dist, 6, 'up')} is possible")
            sols = e.hermite(a0, t0, a1, t1, length=value, tol=tol)
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"Hermite problem failed: {exc}") from None
    if not sols and not none_ok:
        raise NoBlend("no elastic curve joins these ends with this "
                      + ("length" if mode == "length" else "tension"))
    # under tension the curve minimises the bending energy plus sigma times its length:
    # ordered by that (at sigma > 0 a huge gentle loop has the least bending energy alone)
    energies = [total_energy(c, value if mode == "tension" else 0.0) for c in sols]
    if mode == "tension":
        order = sorted(range(len(sols)), key=energies.__getitem__)
        sols, energies = [sols[j] for j in order], [energies[j] for j in order]
    ends = ((e0, at_end0, a0, t0), (e1, at_end1, a1, t1))
    return {"curves": sols, "energies": energies, "placement": plane, "distance": dist, "ends": ends}


def inflections(pieces):
    """Inflections of a chain of elasticae (curvature continuous at the joins)."""
    return sum(len(el().elastica_inflections(p)) for p in pieces)


def bending_energy(curve):
    """The integral of kappa^2 ds (1/mm)."""
    return float(getattr(curve, "energy_value", None) or curve.energy())


def total_energy(curve, sigma):
    """Bending energy plus sigma times the length: what a blend under tension minimises."""
    return bending_energy(curve) + float(sigma) * float(curve.length)


def turning(chain, samples=129):
    """The tangent angle (unwrapped) of a chain of curves at ``samples`` points evenly
    spaced in arc length: a curve's shape whatever its size and place."""
    n = np()
    lengths = n.array([float(c.length) for c in chain])
    ends = n.cumsum(lengths)
    s = n.linspace(0.0, ends[-1], samples)
    piece = n.minimum(n.searchsorted(ends, s), len(chain) - 1)
    theta = n.empty(samples)
    for j, c in enumerate(chain):
        at = piece == j
        theta[at] = c.angle(n.clip(s[at] - (ends[j] - lengths[j]), 0.0, lengths[j]))
    return n.unwrap(theta)


# A solution followed as the edges move turns within SAME_SHAPE (rms, rad) of the curve
# shown before: two lines' blend of 90 mm, an end moved by 5 mm, 0.33-0.42 for the same
# solution, 1.8 and more for the others.
SAME_SHAPE = 1.0


def total_turn(chain):
    """The total turn (rad, + counter-clockwise seen from the plane's normal) of a chain of
    curves: each one's angle at its end less at its start (continuous along a curve, its
    loops' full turns included), summed."""
    return float(sum(c.angle([float(c.length)])[0] - c.angle([0.0])[0] for c in chain))


def nearest_shape(shown, curves):
    """The index of the curve whose turning (tangent angle along its normalised length) is
    nearest that of ``shown`` (the chain of curves shown), a common turn of the whole
    aside, when it is within SAME_SHAPE and the curve turns as many times, else None: the
    same solution, followed as the edges move, where an index names another curve, or
    none, once solutions appear or vanish.

    Every solution's total turn is the ends' tangent angle difference plus a whole number
    of turns (2 pi m), and along one solution as the edges move m stays: the curve followed
    turns within pi of the one shown. The rms alone let through a curve whose turning
    differs by a full turn over a short stretch (QA18gui F1: a clockwise loop turning
    -5.38 rad followed into an S turning -0.25, rms 0.955). Inflections and loops are no
    such invariant: they enter at an end or as the ends cross (a loop followed goes from
    no self-crossing to one, test_elastica_blend_pick)."""
    n = np()
    before, turn = turning(shown), total_turn(shown)
    best, j = None, None
    for i, c in enumerate(curves):
        if abs(total_turn([c]) - turn) >= n.pi:
            continue
        d = turning([c]) - before
        gap = float(n.sqrt(n.mean((d - d.mean()) ** 2)))
        if best is None or gap < best:
            best, j = gap, i
    return j if best is not None and best <= SAME_SHAPE else None


def plural(n, word):
    return f"{n} {word}{'' if n == 1 else 's'}"


def turn_text(turn):
    """', turns 308.21\u00b0 clockwise' (number_text) for a total turn (rad) of half a turn or more, which way
    seen from the plane's normal (a sketch's: as the Sketcher shows it), else '': a loop
    and its mirror image told apart (QA18gui F1)."""
    if turn is None or abs(turn) < np().pi:
        return ""
    return (f", turns {number_text(abs(np().degrees(turn)))}\u00b0 "
            f"{'counter-clockwise' if turn > 0 else 'clockwise'}")


def solution_text(i, length, energy, infl, loops, kmax, turn=None):
    return (f"{i + 1}: {length_text(length, 4)}, energy {per_length(energy)}, "
            f"{plural(infl, 'inflection')}, {plural(loops, 'loop')}{turn_text(turn)}, "
            f"max curvature {per_length(kmax)}")


def descriptions(obj):
    """Every solution of a blend in words, in the unit schema of now (its Descriptions: of
    the last recompute's)."""
    n = len(obj.Descriptions)
    data = [obj.Lengths, obj.Energies, obj.Inflections, obj.Loops, obj.MaxCurvatures]
    if any(len(d) != n for d in data):
        return list(obj.Descriptions)
    turns = getattr(obj, "Turns", [])
    if len(turns) != n:             # a file saved before Turns, not recomputed yet
        turns = [None] * n
    return [solution_text(j, *d) for j, d in enumerate(zip(*data, turns))]


def g2_figures(pieces):
    """[bending energy, inflections, largest |curvature|] of a G2 blend's pieces."""
    return [sum(bending_energy(p) for p in pieces), float(inflections(pieces)),
            max(float(p.max_curvature) for p in pieces)]


def g2_rows(obj):
    """The Solutions rows of a G2 blend, saying what is drawn (QA gui F10: under a 392.6 mm
    G2 result the rows listed the G1 lengths 206.8 and 380.1 mm alone): each row its G1
    solution ('G1 1: ...'), the picked one followed by the G2 blend drawn from it (its
    length, energy, inflections, largest curvature: its stored pieces). descriptions(obj)
    where the blend is G1, failed, or has no stored pieces."""
    rows = descriptions(obj)
    if obj.Continuity != "G2" or not rows or not obj.Curves:
        return rows
    figures = list(getattr(obj, "G2Figures", []))      # stored by apply: not read per refresh
    if len(figures) != 3:       # a file saved before G2Figures, not recomputed yet
        from .fit import stored_curves
        try:
            pieces = stored_curves(obj)[0]
        except (ValueError, KeyError, TypeError):
            return rows
        figures = g2_figures(pieces)
    energy, infl, kmax = figures
    drawn = (f"; drawn: the G2 blend bent from it, {length_text(float(obj.BlendLength), 4)}, "
             f"energy {per_length(energy)}, {plural(int(infl), 'inflection')}, "
             f"max curvature {per_length(kmax)}")
    i = obj.Solution - 1
    return [f"G1 {r}" + (drawn if j == i else "") for j, r in enumerate(rows)]


class BlendProxy(FeatureProxy):
    """Elastic Hermite curve between an end of one edge and an end of another."""

    kind = "Blend"
    followed_links = {"Edge1": "SketchGeometry1", "Edge2": "SketchGeometry2"}
    note_props = ("Mode", "Length")     # solved for a length where no free batten joins
    SET_AFTER = ("Solution",)           # recorded last: an edit of the problem resets it

    def setup(self, obj):
        tol, _, _ = defaults()
        add_link(obj, "App::PropertyLinkSub", "Edge1", "Input",
                 "First edge (the blend leaves it)")
        add_link(obj, "App::PropertyLinkSub", "Edge2", "Input",
                 "Second edge (the blend enters it)")
        add_property(obj, "App::PropertyBool", "AtEnd1", "Input",
                     "Leave the first edge at its end vertex (else at its start)", True)
        add_property(obj, "App::PropertyBool", "AtEnd2", "Input",
                     "Enter the second edge at its end vertex (else at its start)", False)
        for link, index in self.followed_links.items():
            add_geometry_index(obj, index, link)
        add_enum(obj, "Mode", "Blend", "Solve for a given tension (default: 0, the free "
                 "batten) or a given arc length", MODES, "tension")
        add_length(obj, "Length", "Blend",
                   "Arc length of the blend in length mode; 0 = the length of the "
                   "lowest-energy free batten (" + G2_FREE_TIP + ")", 0.0)
        add_per_area(obj, "Tension", "Blend",
                     "Tension sigma in tension mode (1/mm^2; 0 = free batten (" +
                     G2_FREE_TIP + "), negative = compression, G1 only)", 0.0)
        add_enum(obj, "Continuity", "Blend", G2_TIP, CONTINUITIES, "G1")
        add_property(obj, "App::PropertyInteger", "Solution", "Blend",
                     "Which solution, by bending energy, as the panel's list and Status "
                     "number them (1 = the lowest); reset to 1 by every edit of the blend's "
                     "parameters; a picked one follows its shape when the edges move (the "
                     "lowest where that shape is gone); bound to an expression, only it sets "
                     "Solution", 1)
        add_length(obj, "Tolerance", "BSpline",
                   "Largest distance of the B-spline from the elastica", tol)
        add_property(obj, "App::PropertyInteger", "Degree", "BSpline",
                     "Degree of the B-spline (3 to 7; high degrees need few poles)",
                     BSPLINE_DEGREE)
        add_property(obj, "App::PropertyFloatList", "Lengths", "Result",
                     "Arc length of every solution (mm)")
        add_property(obj, "App::PropertyFloatList", "Energies", "Result",
                     "Energy of every solution (1/mm): the bending energy (integral of kappa^2 "
                     "ds) plus, in tension mode, sigma times the length; the solutions are "
                     "ordered by it")
        add_property(obj, "App::PropertyFloatList", "Tensions", "Result",
                     "Tension sigma of every solution (1/mm^2)")
        add_property(obj, "App::PropertyIntegerList", "Inflections", "Result",
                     "Inflections of every solution")
        add_property(obj, "App::PropertyIntegerList", "Loops", "Result",
                     "Self-crossings (loops) of every solution")
        add_property(obj, "App::PropertyFloatList", "MaxCurvatures", "Result",
                     "Largest |curvature| of every solution (1/mm)")
        add_property(obj, "App::PropertyFloatList", "Turns", "Result",
                     "Total turn of every solution (rad, + counter-clockwise seen from the "
                     "Plane's normal): a picked solution is followed as the edges move only "
                     "into one turning as many times")
        add_property(obj, "App::PropertyStringList", "Descriptions", "Result",
                     "Every solution in words")
        add_property(obj, "App::PropertyFloatList", "G2Figures", "Result",
                     "G2: the blend drawn's bending energy (1/mm), inflections and largest "
                     "|curvature| (1/mm), as its Solutions row says them; empty for G1")
        if "SpanTensions" in obj.PropertiesList:   # version 1: the G2 end spans' own tensions
            obj.removeProperty("SpanTensions")
        add_property(obj, "App::PropertyVectorList", "GuideDucks", "Result",
                     "G2: the two guide ducks holding the batten (global coordinates), a "
                     "quarter of the way in from each edge; empty for G1")
        add_property(obj, "App::PropertyVectorList", "GuideForces", "Result",
                     "G2: the force each guide duck exerts on the batten (global directions, "
                     "in 1/mm^2: times EI/2 in N mm^2 gives newtons; normal to the batten)")
        add_property(obj, "App::PropertyFloat", "BlendLength", "Result",
                     "Length of the blend on screen (mm): the chosen solution's, or the G2 "
                     "batten's")
        add_per_area(obj, "BlendTension", "Result",
                     "Tension of the blend on screen (1/mm^2): the chosen solution's, or the "
                     "G2 batten's")
        add_property(obj, "App::PropertyInteger", "Poles", "Result", "Poles of the B-spline")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last solve")
        add_property(obj, "App::PropertyString", "Curves", "Result",
                     "The blend's elastica(e) (JSON, plane coordinates): the chosen solution, "
                     "or the G2 blend's pieces")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result", "The plane of the blend")
        if getattr(self, "_version", VERSION) < 4:       # a file's Solution counted from 0
            self._version = VERSION
            self._from_one(obj)
        read_only(obj, *RESULT_LISTS, "GuideDucks", "GuideForces", "BlendLength",
                  "BlendTension", "Poles", "Status", "Curves", "Plane")

    @staticmethod
    def _from_one(obj):
        """A document of version <= 3 counted Solution from 0: its value one up, an
        expression's '(...) + 1' (its cell keeps naming the same solution)."""
        expression = bound_expression(obj, "Solution")
        if expression:
            obj.setExpression("Solution", f"({expression}) + 1")
        obj.Solution = obj.Solution + 1

    def onChanged(self, obj, prop):
        self.drop_kept(obj, prop)
        if prop in self.followed_links and not self.link_changed(obj, prop):
            return                  # restored, or renamed following its sketch geometry
        if "Restore" in obj.State or getattr(self, "_restoring", False):
            return                  # (onDocumentRestored's setup: add_per_area's bounds)
        # the designer's pick (property editor, panel, macro): shown as picked, never read as
        # an edge move (the edges of a reopened file differ from the saved solve's by an ulp)
        if prop == "Solution" and not obj.Document.Transacting \
                and not getattr(self, "_setting", False):
            self._picked = True
        # a new problem: its lowest-energy solution (the panel re-applies a user's pick); not
        # where Undo/Redo restores the step (Transacting): Redo restores Solution before
        # Length, and a reset here lost the pick restored with it (QA23gui F1)
        if prop in ("Mode", "Length", "Tension", "AtEnd1", "AtEnd2", "Edge1", "Edge2") \
                and not obj.Document.Transacting:
            self._new_problem = True
            # only the value solved for changed (a switch of Solve for copies the shown
            # curve's): that curve kept where it is a solution (_kept_shown)
            self._value_only = getattr(self, "_value_only", True) and \
                prop in ("Mode", "Length", "Tension")
            if getattr(obj, "Solution", 1) != 1:
                self.set_solution(obj, 1)

    def set_solution(self, obj, i):
        """obj.Solution = i (from 1) written by the feature itself (no pick of the designer's);
        not where Solution is bound to an expression (a cell): then only it writes Solution
        (FreeCAD's rule), never the feature's reset or follow (QA19gui F6)."""
        if bound_expression(obj, "Solution"):
            return
        self._setting = True
        try:
            obj.Solution = i
        finally:
            self._setting = False

    def _followed_solution(self, obj, curves, energies):
        """The index (from 0) of obj.Solution (from 1) where the designer just picked it or
        an edit reset it; a picked one (not 1, the lowest energy) after the edges moved (other solutions, no parameter
        edited: an edit picks the lowest energy), the solution of the
        shape shown (nearest_shape), or the lowest-energy one where that shape is gone: the
        index of a picked one names another curve, or none, once solutions appear or vanish.
        Returns (index, whether the shape shown is gone, moved): moved, where Solution is
        bound to an expression (kept as it says), the index of the shape shown now (None:
        gone), else False."""
        new_problem, self._new_problem = getattr(self, "_new_problem", False), False
        value_only, self._value_only = getattr(self, "_value_only", True), True
        picked, self._picked = getattr(self, "_picked", False), False
        if new_problem and value_only and not bound_expression(obj, "Solution"):
            j = self._kept_shown(obj, curves)           # (bound: its expression alone sets it)
            if j is not None:
                self.set_solution(obj, j + 1)
                return j, False, False
        same = [(float(c.length), e) for c, e in zip(curves, energies)] == \
            list(zip(obj.Lengths, obj.Energies))
        shown = None if new_problem or picked or same or obj.Solution == 1 or not obj.Lengths \
            else self.plane_curves(obj)                # the last good solve's curve
        if shown is None:
            return obj.Solution - 1, False, False
        j = nearest_shape(shown[0], curves)
        if bound_expression(obj, "Solution"):
            # kept as its expression says; where the shape shown went, said (apply)
            return obj.Solution - 1, False, j
        return (0, True, False) if j is None else (j, False, False)

    def _kept_shown(self, obj, curves):
        """The index of the curve on screen among ``curves`` where the value solved for is its
        own (Length = BlendLength, Tension = BlendTension: a switch of Solve for), else None
        (QA23gui F2: 120 mm by length -> by its tension gave the lowest energy, 67.8 mm, though
        the 120 mm curve is listed there). G1 only: a G2 blend's Curves are its pieces."""
        if obj.Continuity != "G1" or not obj.Lengths or not curves:
            return None
        own = float(obj.Length) == obj.BlendLength if obj.Mode == "length" \
            else float(obj.Tension) == obj.BlendTension
        shown = self.plane_curves(obj) if own else None
        return nearest_shape(shown[0], curves) if shown else None

    def ends(self, obj):
        """The two linked edges (global), or InputProblem."""
        out = []
        for prop in self.followed_links:
            link = getattr(obj, prop)
            if link and not (link[1] and link[1][0].startswith("Edge")):
                raise InputProblem(f"{prop} links {link[0].Label}.{(link[1] or [''])[0]}: a "
                                   "blend needs two edges")
            edge = followed_edge(obj, prop)
            if edge is None:
                raise InputProblem(f"{prop} is empty: a blend needs two edges: link {prop}")
            check_open(edge, f"{prop} ({link[0].Label}.{link[1][0]})")
            out.append(edge)
        return out

    @staticmethod
    def sketch_plane(obj):
        """The plane of the edges' sketch when both are in one, else None (found from them)."""
        if obj.Edge1[0] == obj.Edge2[0] and is_sketch(obj.Edge1[0]):
            return obj.Edge1[0].getGlobalPlacement()
        return None

    def compute(self, obj):
        """blend_core's dict for the linked edges, plus the chosen solution's B-spline."""
        e1, e2 = self.ends(obj)
        plane = self.sketch_plane(obj)
        value = float(obj.Length) if obj.Mode == "length" else obj.Tension
        g2 = obj.Continuity == "G2"
        r = self.handed(blend_core, e1, obj.AtEnd1, e2, obj.AtEnd2, plane, obj.Mode, value,
                        none_ok=g2)
        curves = r["curves"]
        i, r["gone"], r["bound_moved"] = self._followed_solution(obj, curves, r["energies"])
        r["solution"] = i
        if curves and not 0 <= i < len(curves):
            raise InputProblem(f"Solution = {i + 1}: there are {len(curves)} solutions "
                               f"(1 to {len(curves)})")
        tol, degree = check_tolerance(float(obj.Tolerance)), check_degree(obj.Degree)
        if obj.Continuity == "G2":
            r["g2"], r["bspline"], r["g2_note"] = g2_blend(r, i, obj.Mode, value, tol, degree)
            return r
        try:
            # a SmoothElastica, or near the separatrix a Hermite chain: both give one B-spline
            r["bspline"] = curves[i].to_bspline(tol=tol, degree=degree)
        except ValueError as exc:
            raise InputProblem(f"B-spline failed: {exc}") from None
        return r

    def apply(self, obj, r):
        curves, i = r["curves"], r["solution"]
        followed = "" if i == obj.Solution - 1 and not r["gone"] else (
            f" (the lowest energy: solution {obj.Solution}'s shape is gone with the edges' "
            "move)" if r["gone"] else f" (solution {obj.Solution} before the edges moved)")
        if followed:
            self.set_solution(obj, i + 1)
        moved = r["bound_moved"]
        if moved is not False and moved != i:
            # bound: the expression's solution kept, the shape shown before named
            followed = (f" (Solution kept as {bound_expression(obj, 'Solution')} says: the shape shown "
                        "before is " + (f"solution {moved + 1} now" if moved is not None
                                        else "gone with the edges' move") + ")")
        set_shape(obj, part_bspline(r["bspline"], r["placement"]).toShape())
        described = [describe(c) for c in curves]
        obj.Lengths = [float(c.length) for c in curves]
        obj.Energies = r["energies"]
        # rounding noise as 0: by the free batten's own length, not 1.1e-16/mm^2 (F9)
        obj.Tensions = [tension_or_zero(getattr(c, "sigma", 0.0), c.length) for c in curves]
        obj.Inflections = [d[0] for d in described]
        obj.Loops = [d[1] for d in described]
        obj.MaxCurvatures = [d[2] for d in described]
        obj.Turns = [total_turn([c]) for c in curves]
        obj.Descriptions = [solution_text(j, L, E, *d, t) for j, (L, E, d, t) in
                            enumerate(zip(obj.Lengths, obj.Energies, described, obj.Turns))]
        obj.Poles = int(r["bspline"].npoles)
        obj.Plane = r["placement"]
        curve_to_dict = binding_module("io").curve_to_dict
        sp = r.get("g2")
        obj.Curves = json.dumps([curve_to_dict(c) for c in (sp.pieces if sp else [curves[i]])])
        obj.G2Figures = g2_figures(sp.pieces) if sp else []
        plc = r["placement"]
        obj.GuideDucks = to_3d(plc, sp.guides) if sp else []
        obj.GuideForces = [plc.Rotation.multVec(App.Vector(float(x), float(y), 0.0))
                           for x, y in (sp.guide_forces if sp else [])]
        obj.BlendLength = float(sp.length if sp else curves[i].length)
        obj.BlendTension = tension_or_zero(sp.tension, sp.length) if sp else obj.Tensions[i]
        if sp:
            # forces in 1/length^2 x EI/2, as the tension; marks: said in the schema of now
            # when the panel opens (proxy.said)
            forces = ", ".join(per_area_mark(float(np().hypot(*f))) for f in sp.guide_forces)
            bends = plural(inflections(sp.pieces), "inflection")
            free = "" if tension_or_zero(sp.tension, sp.length) else " (free batten)"
            if obj.Mode == "tension" and tension_or_zero(sp.tension, sp.length) < 0.0:
                # a figure the Tension box refuses at G2 (>= 0): what gives this blend instead
                free = (" (pushed together, which a G2 Tension cannot ask: Solve for a length "
                        f"keeps this blend, Length {mm_marked(f'{sp.length:.9g} mm')})")
            # "; " parts: the panel shows one a line
            start = f"G2 from solution {i + 1} of {len(curves)}{followed}{r['g2_note']}" \
                if curves else "G2 from the library's own start (no G1 solution at this tension)"
            status = (
                f"{start}; length "
                f"{length_mark(sp.length, 4)}, tension "
                f"{tension_mark(sp.tension, sp.length)}{free}; energy "
                f"{per_length_mark(sp.energy)}, max curvature "
                f"{per_length_mark(sp.max_curvature)}, {bends}"
                f"; guide ducks' forces {forces} ({tension_unit_mark()} \u00d7 EI/2)"
                + (f"; G2 to {sp.residual:.2g} (nearly straight under tension: double "
                   f"precision resolves its pieces to {sp.resolution:.2g}, the library's "
                   "tolerance is 1e-10)" if sp.residual > 1e-10 else ""))
        else:
            status = f"solution {i + 1} of {len(curves)}{followed}"
        set_said(obj, "Status", status)
        # why the blend is not the one asked (followed, another than the free batten shown):
        # in the Report view once, as FreeCAD's own features say theirs; the panel says one
        # line and the why under Details (blend_panel.status_line)
        why = say(status) if followed or (sp and r["g2_note"]) else ""
        if why and why != getattr(self, "_told", ""):
            App.Console.PrintMessage(f"Elastica {obj.Label}: {why}\n")
        self._told = why

    def on_error(self, obj):
        """A failed solve lists no solutions (the old curve stays, drawn dashed)."""
        for name in RESULT_LISTS:
            setattr(obj, name, [])

    def plane_curves(self, obj):
        from .fit import stored_curves
        return stored_curves(obj)


def make(doc, edge1, edge2, at_end1=None, at_end2=None, **props):
    """A new Blend feature; edge1/edge2 are (obj, 'EdgeN'); ends default to the
    nearest pair."""
    obj = doc.addObject("Part::FeaturePython", "ElasticaBlend")
    BlendProxy(obj)
    obj.Edge1 = (edge1[0], [edge1[1]])
    obj.Edge2 = (edge2[0], [edge2[1]])
    if at_end1 is None or at_end2 is None:
        a, b = nearest_ends(global_element(*edge1), global_element(*edge2))
        at_end1 = a if at_end1 is None else at_end1
        at_end2 = b if at_end2 is None else at_end2
    obj.AtEnd1, obj.AtEnd2 = bool(at_end1), bool(at_end2)
    for k, v in props.items():
        setattr(obj, k, v)
    attach_view(obj)
    return obj


def copy_into_sketch(blend, sketch=None):
    """Copy the blend's B-spline into the sketch of its edges (or ``sketch``), joined to
    both edges where they are in that sketch: an endpoint-to-endpoint Tangent at each
    joint (geometry.join_ends: coincident and G1 there, as Sketcher_CreateFillet joins its
    arc), added only where the sketch solves with them moving nothing. A G2 blend's
    curvature match is in the copy's poles as written: FreeCAD 0.20 has no curvature
    constraint for B-splines, so an edge edited later keeps the joints coincident and
    tangent only (the Sketcher bends the copy; the feature re-solves and says how far its
    copy is off). Returns the new geometry index."""
    from .geometry import write_to_sketch
    target = sketch or blend.Edge1[0]
    return write_to_sketch(blend, target, constrain_to=_joint_ends(blend, target))[0]


def _joint_ends(blend, sketch):
    """[(geo index, None) of Edge1, (geo index, None) of Edge2] in ``sketch`` (the geometry
    their links follow, SketchGeometry1/2; None where that edge is not in it): join_ends
    joins the copy's start and end to the end of each nearer to them."""
    out = []
    for prop, index in (("Edge1", "SketchGeometry1"), ("Edge2", "SketchGeometry2")):
        link, g = getattr(blend, prop), getattr(blend, index)
        ok = bool(link) and link[0] == sketch and 0 <= g < len(sketch.Geometry)
        out.append((g if ok else None, None))
    return out


__all__ = ["BlendProxy", "NoBlend", "g2_rows", "check_open", "blend_core", "g2_blend", "g2_tension_reach",
           "make", "copy_into_sketch", "nearest_ends",
           "chosen_ends", "picked_end",
           "edge_end", "MODES", "CONTINUITIES"]
