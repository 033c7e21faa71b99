"""The G2 blend (blend.py's Continuity G2): the elastic spline between the two edge ends
that also meets both edges' curvature, held by two guide ducks (el.elastic_spline with G2
ends); where none is found, what to try instead: the free G2 batten's length, the lengths
that solve, the highest tension one was found at. blend_start.py finds the fairer start
where the free batten is a snake or missing."""
from __future__ import annotations

from .geometry import el, np, plane_curvature
from .proxy import InputProblem
from .spline_solve import g2_met_hint, g2_solves, quiet_spline
from .units import (floor_digits, length_mark, per_area_mark, per_length_mark, reach_mark,
                    tension_mark, tension_unit_mark)

# Significant digits of the tensions the G2 error messages give: 3 told 0.00176823 (none
# found) from 0.00177 (solved) as the same "0.00177" (QA12).
G2_TENSION_DIGITS = 6


def g2_problem(r):
    """(pts, ends) of the G2 blend between the ends of blend_core's result ``r``: the two
    edge ends (plane coordinates) and el.elastic_spline's start / end (tangent, curvature)."""
    (e0, at0, a0, t0), (e1, at1, a1, t1) = r["ends"]
    plane = r["placement"]
    ends = {"start": {"tangent": tuple(t0),
                      "curvature": plane_curvature(e0, at0, t0, plane, "the first edge")},
            "end": {"tangent": tuple(t1),
                    "curvature": plane_curvature(e1, at1, t1, plane, "the second edge")}}
    return np().vstack([a0, a1]), ends


def g2_blend(r, i, mode, value, tol, degree):
    """The G2 blend between the ends of blend_core's result ``r``: el.elastic_spline
    through the two edge ends with G2 ends (the edges' tangent AND curvature). One
    elastica cannot do it (8 conditions, 7 parameters); the library holds the batten
    with a guide duck a quarter of the chord in from each end, free to move across
    the chord, at one common tension: by ``mode`` 'tension' (value >= 0, 1/mm^2) or
    'length' (value in mm; 0: the free batten), bent from solution ``i`` (its G1
    sibling: the branch the user chose; if that does not bend, the library's own
    start, said in the note). Returns (el.ElasticSpline, its B-spline, note).
    Raises InputProblem."""
    pts, ends = g2_problem(r)
    k0, k1 = ends["start"]["curvature"], ends["end"]["curvature"]
    a0, a1 = pts
    if mode == "tension" and value < 0:
        raise InputProblem(f"Tension = {per_area_mark(value, 6)} {tension_unit_mark()}: a G2 "
                           "blend is solved for a tension >= 0; "
                           "for one pushed together give a length")
    n, e = np(), el()
    kw = {"length": value} if mode == "length" and value > 0 else \
        {"tension": value if mode == "tension" else 0.0}
    note = ""
    # no G1 solution (walls at tension 0: the clamped free batten slides off its ducks, the
    # guided one exists): the library's own start, which solves it by length then
    sibling = r["curves"][i] if r["curves"] and (mode == "tension" or value > 0) else None
    try:
        try:   # the chosen G1 solution as the sibling (a chain of pieces cannot be one)
            if not isinstance(sibling, e.SmoothElastica):
                raise ValueError("no single-piece G1 solution to start from")
            sp = e.elastic_spline(pts, **ends, **kw, initial=[sibling])
        except (ValueError, ArithmeticError, RuntimeError):
            sp = e.elastic_spline(pts, **ends, **kw)
            if sibling is not None:
                note = f" (solution {i + 1} did not bend to G2: from the library's own start)"
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        from .blend_start import fair_where_no_free   # (blend_start builds on this module)
        # the free batten asked and none found: the fairest by length, as for a snake below
        fair = fair_where_no_free(pts, ends, r["curves"][i] if r["curves"] else None) \
            if kw == {"tension": 0.0} else None
        if fair is not None:
            sp, note = fair
            return sp, g2_bspline(sp, tol, degree), note
        dist = float(n.linalg.norm(a1 - a0))
        asked = (f"of length {length_mark(value, 6)}" if "length" in kw else
                 f"at tension {tension_mark(kw['tension'], dist, G2_TENSION_DIGITS)}")
        # by tension, the G2 battens the library met nearest it (the binding's g2_met)
        hint = g2_met_hint(getattr(exc, "g2_met", None),
                           lambda t: e.elastic_spline(pts, **ends, tension=t),
                           "give a tension it reached, a length, or G1") \
            if "tension" in kw and kw["tension"] > 0.0 else None
        if kw == {"tension": 0.0}:
            # the free batten asked (Tension 0, the default): no tension to pull it by, the
            # lengths that do solve (QA: arc -> arc said "pick another tension or length"
            # where Length mode has G2 blends of 153 to 404 mm)
            found = g2_lengths_hint(pts, ends, dist, "Solve for a length and give one "
                                    "of those, or G1")
            hint = None if found.startswith("no G2 blend found") else found
        hint = hint or g2_failure_hint(pts, ends, kw, dist)
        # not the exception's words about the spline it keeps: nothing is returned here
        solve = "the batten's solve did not converge" if isinstance(exc, e.NotConvergedError) \
            else f"the batten's solve: {str(exc).replace('elastic_spline: ', '', 1)}"
        raise InputProblem(f"no G2 blend {asked} ({solve}); the edges' curvatures are "
                           f"{per_length_mark(k0, 3, unit=False)} and {per_length_mark(k1)}; "
                           f"{hint}") from None
    if kw == {"tension": 0.0}:     # the free batten asked (Tension 0, or Length 0)
        from .blend_start import fairer_along, fairer_than_free   # (builds on this module)
        sibling = r["curves"][i] if r["curves"] else None
        fair = fairer_than_free(pts, ends, sibling, sp)
        if fair is None and not note:       # bent from the sibling: the branch between
            fair = fairer_along(pts, ends, sibling, sp)
        if fair is not None:
            sp, note = fair
    return sp, g2_bspline(sp, tol, degree), note


def g2_bspline(sp, tol, degree):
    """The G2 blend ``sp``'s B-spline, or InputProblem."""
    try:
        return sp.to_bspline(tol, degree)
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"B-spline failed: {exc}") from None


def g2_failure_hint(pts, ends, kw, dist):
    """What a G2 blend between ``pts`` with ``ends`` that failed by ``kw`` (el.elastic_spline's
    tension= or length=; ``dist`` between the ends) says to try, where the library names no
    G2 batten met nearest the tension: the free G2 batten's length, the lengths that solve
    (g2_lengths_hint) or the highest tension found (g2_tension_reach)."""
    n, e = np(), el()
    hint = "pick another tension or length, or G1"
    try:
        free = e.elastic_spline(n.vstack(pts), **ends).length
        hint = (f"the free G2 batten (tension 0) is {length_mark(free, 4)} long; pulled it "
                "gets at "
                "most 1-2 % shorter, pushed longer: try a length from there, or G1"
                if "length" in kw else
                "the free G2 batten (tension 0) exists: try a lower tension, or G1")
    except (ValueError, ArithmeticError, RuntimeError):
        if "length" in kw:   # QA17 M1: which lengths do give one, not a guess
            hint = g2_lengths_hint(pts, ends, dist)
    reach = g2_tension_reach(pts, ends) if "tension" in kw else None
    if reach is not None and reach > kw.get("tension", 0.0):
        # below the reach the solver's paths missed one: QA16's arc of radius 18-23 mm
        # into a line has a free G2 batten (230 mm at 20 mm, found by an independent
        # shooting solve) that bending the G1 blend does not reach past a fold; "(there
        # can be gaps below it)" read as if the tension asked should work
        hint = (f"G2 battens were found at tensions up to about "
                f"{reach_mark(reach, G2_TENSION_DIGITS)}, but none at this one: the "
                "solver bends the G1 blend into G2 and can miss a batten that exists; "
                "try another tension up to that, a length, or G1")
    elif reach is not None and reach > 0.0:
        # rounded down in the unit shown: typed back, it is within reach
        hint += (f"; the largest tension a G2 batten was found at is about "
                 f"{reach_mark(reach, G2_TENSION_DIGITS)} "
                 "(there can be gaps below it): held by its guide ducks, a G2 blend pulled "
                 "does not straighten as G1 does, and beyond some tension there is none")
    return hint


# Lengths (times the distance between the ends) the G2 batten is solved for when none is
# found at the tension asked (the highest tension among them is said) or at the length
# asked (those that solved, to 3 digits, are said). Along a G2 batten's
# family the guides do work (d(int kappa^2 + sigma L)/d sigma = L + sum f . dg/d sigma), so
# pulling need not shorten it: walls 100 mm apart (curvature 0, tangents normal to the line
# between the ends) rise and lengthen, 231 mm at 0.0005/mm^2, 397 mm at 0.0023; by length
# 3 x: 0.00185, 4 x: 0.00231, 6 x: 0.00242/mm^2, 10 x: none (QA9 w5).
G2_REACH_MULTIPLES = (1.25, 1.5, 2.0, 2.5, 3.0, 4.0, 6.0, 10.0)


def quiet_g2(pts, ends, **by):
    """el.elastic_spline(pts, **ends, **by) for a probe (the lengths an error lists, where G2
    starts): its LoopWarning / UnstableWarning were red report-view lines (QA23gui s2)."""
    return quiet_spline(pts, **ends, **by)


def g2_by_length(pts, ends, lengths):
    """[(length, tension)] of the G2 battens between the two points ``pts`` with ``ends``
    (el.elastic_spline's start/end) solved by each of ``lengths`` (mm), as a blend with no
    previous solution is; those not solved left out."""
    found = []
    for length in lengths:
        try:
            found.append((length, float(quiet_g2(pts, ends, length=length).tension)))
        except (ValueError, ArithmeticError, RuntimeError):
            continue
    return found


def g2_lengths_hint(pts, ends, dist, action="try one of those, or G1"):
    """What a G2 blend by length that failed (and no free G2 batten) says to try: the
    lengths of G2_REACH_MULTIPLES times ``dist`` (3 digits: typed back, each solves) at
    which one was found, then ``action`` (what to do with them); where none was, that no G2
    blend was found (tension 0, which every caller has tried, and those lengths): use G1.
    QA17 M1 (line into an arc 75 mm apart): none at 80 .. 130 mm, the family followed
    folds at 135.5 mm (an independent shooting solve); 150 .. 300 found."""
    lengths = [float(f"{m * dist:.3g}") for m in G2_REACH_MULTIPLES]
    found = [length for length, _ in g2_by_length(pts, ends, lengths)]
    span = (f"{G2_REACH_MULTIPLES[0]:g} to {G2_REACH_MULTIPLES[-1]:g} \u00d7 the "
            f"{length_mark(dist, 4)} between the ends")
    if not found:
        # every caller has tried tension 0 (the free G2 batten) first; "pick a tension"
        # named a box disabled in length mode (QA gui3 G3), and no tension was known to work
        return f"no G2 blend found between these edges (tried: tension 0, and lengths {span}): use G1"
    said = ", ".join(length_mark(length, 3) for length in found)
    return f"G2 blends were found at the lengths {said} (tried: {span}): {action}"


def g2_tension_reach(pts, ends):
    """The highest tension, rounded down to G2_TENSION_DIGITS (else fewer) significant
    digits, at which a G2 batten between the two points ``pts`` with ``ends`` (el.elastic_spline's start/end)
    is solved by that tension (as a blend with no previous solution is), among the
    tensions of those solved by length at G2_REACH_MULTIPLES times their distance; None
    when none is. (QA12: by length 0.0017682x/mm^2, yet none solved at 0.00176823, one at
    0.00176 and 0.00177: the tensions solved are not an interval; the one said solved.)"""
    n, e = np(), el()
    dist = float(n.linalg.norm(pts[1] - pts[0]))
    found = [floor_digits(sigma, G2_TENSION_DIGITS) for _, sigma in
             g2_by_length(pts, ends, [m * dist for m in G2_REACH_MULTIPLES]) if sigma > 0.0]
    tried = set()

    def solve(tension):
        return e.elastic_spline(pts, **ends, tension=tension)

    for sigma in sorted(found, reverse=True):
        for digits in range(G2_TENSION_DIGITS, 1, -1):   # rounded down further if none there
            t = floor_digits(sigma, digits)
            if t in tried:
                continue
            tried.add(t)
            if g2_solves(solve, t):
                return t
    return None


__all__ = ["G2_TENSION_DIGITS", "G2_REACH_MULTIPLES", "g2_problem", "g2_blend", "g2_bspline",
           "g2_failure_hint", "quiet_g2", "g2_by_length", "g2_lengths_hint", "g2_tension_reach"]
