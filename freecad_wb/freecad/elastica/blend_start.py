"""Where an Elastic blend starts when the free batten (tension 0) is not the blend to show:
no free batten joins the ends (G1: starting_length, what the command and the panel start
by, free_or_length), or the free G2 batten is a snake (fairer_than_free, g2_blend's): by
length at the fairest of LENGTH_MULTIPLES times the distance between the ends, and said."""
from __future__ import annotations
import math

from .blend import NoBlend, bending_energy, blend_core, describe, inflections, plural
from .blend_g2 import G2_REACH_MULTIPLES, G2_TENSION_DIGITS, g2_problem, quiet_g2
from .geometry import edge_end, el, np
from .kept import checked_call
from .units import length_mark, per_length_mark, tension_mark


# Where the free batten (tension 0) does not exist (its bending energy falls without end
# as the curve gets longer: no length is the batten's own), the Elastic blend command
# starts by length at the fairest of these multiples of the distance between the ends.
LENGTH_MULTIPLES = (1.25, 1.5, 2.0, 3.0)


def starting_length(e0, at_end0, e1, at_end1, plane=None, hand=None):
    """A length to start a blend by, where the free batten does not join the ends: of
    LENGTH_MULTIPLES times their distance (3 digits), the one whose lowest-energy solution
    is the fairest, loop-free first, then by its bending energy times its length (the
    energy of its shape whatever its size). Returns (length, note for the user); raises
    NoBlend when no such length has a solution. ``hand``: as free_or_length's."""
    dist = (edge_end(e1, at_end1)[0] - edge_end(e0, at_end0)[0]).Length
    best = None
    for m in LENGTH_MULTIPLES:
        length = float(f"{m * dist:.3g}")
        try:
            checked = checked_call(blend_core, e0, at_end0, e1, at_end1, plane, "length", length)
        except NoBlend:
            continue
        c = checked[1]["curves"][0]
        key = (describe(c)[1] > 0, bending_energy(c) * length)
        if best is None or key < best[0]:
            best = (key, m, length, checked)
    if best is None:
        raise NoBlend("no elastic curve joins these ends, free or at "
                      f"{', '.join(f'{m:g}' for m in LENGTH_MULTIPLES)} times their distance")
    _, m, length, checked = best
    if hand is not None:
        hand.append(checked)
    return length, (f"no free batten (tension 0) joins these ends: solved for a length "
                    f"instead, {length_mark(length, 6)} ({m:g} \u00d7 the {length_mark(dist, 4)} "
                    "between them, the "
                    f"fairest of {LENGTH_MULTIPLES[0]:g} to {LENGTH_MULTIPLES[-1]:g} \u00d7); "
                    "change it, or solve for a tension > 0")


def free_or_length(e0, at_end0, e1, at_end1, plane=None, hand=None):
    """None where the free batten (tension 0) joins the ends; else starting_length's
    (length, note): what the Elastic blend command and its panel start by. ``hand``: a list
    given the blend solved (kept.checked_call), for the feature's next recompute
    (FeatureProxy.handed): solved once."""
    try:
        checked = checked_call(blend_core, e0, at_end0, e1, at_end1, plane)
    except NoBlend:
        return starting_length(e0, at_end0, e1, at_end1, plane, hand)
    if hand is not None:
        hand.append(checked)
    return None


def fairest_by_length(pts, ends, sibling):
    """The G2 blend between the two points ``pts`` with ``ends`` by length at the fairest of
    LENGTH_MULTIPLES times their distance (3 digits), bent from the G1 solution ``sibling``
    (a SmoothElastica) as a blend by length is: fewest inflections, then the lowest bending
    energy times length. Returns ((inflections, energy x length), multiple, el.ElasticSpline),
    or None where no length solves. The tension's sign is not checked: a blend pushed
    together (tension < 0) may be the fairest; its callers guard it (fair_where_no_free
    refuses it, kept_by_tension gives no tension to type for it, Tension 0 keeps it)."""
    n, e = np(), el()
    dist = float(n.linalg.norm(pts[1] - pts[0]))
    best = None
    for m in LENGTH_MULTIPLES:
        length = float(f"{m * dist:.3g}")
        try:
            sp = e.elastic_spline(pts, **ends, length=length, initial=[sibling])
        except (ValueError, ArithmeticError, RuntimeError):
            continue
        key = (inflections(sp.pieces), float(sp.energy) * float(sp.length))
        if best is None or key < best[0]:
            best = (key, m, sp)
    return best


def fair_where_no_free(pts, ends, sibling):
    """Where the free G2 batten (tension 0) between ``pts`` with ``ends`` was not found (its
    solve from the G1 solution ``sibling`` and from the library's own start failed):
    fairest_by_length's blend, as where it is a snake (fairer_than_free), where it has at
    most one inflection more than ``sibling`` and is not pushed together; returns
    (el.ElasticSpline, note for Status), else None (g2_blend's error stands).

    Why: the QA22gui F5 chain (a line into an arc, ends 168 mm apart) has the fair 210 mm
    blend at arc radius 23 mm and 25 mm (the free batten a snake there) but no free G2 batten
    found at 23.5 to 24.5 mm: the default G2 blend read "no G2 blend at tension 0", so a
    designer dragging the radius saw blend, error, blend."""
    e = el()
    if not isinstance(sibling, e.SmoothElastica):
        return None
    best = fairest_by_length(pts, ends, sibling)
    if best is None:
        return None
    (infl, _), m, sp = best
    # a fair blend only: at most one inflection more than the G1 solution it is bent from
    # (the QA chain's: 1 -> 2), not pushed together (tension < 0); sweeps of random line/arc
    # ends also gave 3-5 inflections up to 3 x the distance, no default: the error stands
    if infl > len(e.elastica_inflections(sibling)) + 1 or float(sp.tension) < 0.0:
        return None
    return sp, " (no free G2 batten (tension 0) was found here: shown instead " + \
        kept_by_tension(pts, sp, m, infl) + ")"


def kept_by_tension(pts, sp, m, infl):
    """The note's words for the blend ``sp`` fairest_by_length chose (multiple ``m``,
    ``infl`` inflections), and how to keep it: Tension 0, the default that shows it (each
    recompute finds it again, as fairer_along's), or its own tension to G2_TENSION_DIGITS
    digits; where it is pushed together (tension < 0, which fairest_by_length does not
    refuse) no tension to type (a G2 Tension is >= 0: the box and g2_blend refuse it),
    Tension 0 alone.

    Why not the length: a blend by length is bent from the G1 solution OF that length, not
    from the free one this blend was bent from, and reaches another branch (QA22gui F5, arc
    radius 25 mm: Length 210 mm, what the panel copies on switching to length mode, gives a
    5-inflection blend pushed together, tension -0.00941/mm^2, 4.3 x this one's bending
    energy); Tension = this blend's 0.00203109/mm^2 gives it again."""
    dist = float(np().linalg.norm(pts[1] - pts[0]))
    keep = (f"at tension {tension_mark(sp.tension, dist, G2_TENSION_DIGITS)}: Tension 0 keeps "
            "it, and so does that tension" if float(sp.tension) >= 0.0 else
            "pushed together: Tension 0 keeps it (a G2 Tension cannot be below 0)")
    return (f"the fairest by length, {length_mark(sp.length, 6)} = {m:g} \u00d7 the "
            f"{length_mark(dist, 4)} between the ends, {plural(infl, 'inflection')}, {keep}; "
            "a Length bends another branch")


def fairer_than_free(pts, ends, sibling, free):
    """Where the free G2 batten ``free`` (tension 0, bent from the G1 solution ``sibling``,
    None: the library's own start) between the two points ``pts`` with ``ends`` has more
    inflections than ``sibling``: the G2 blend by length at the fairest of LENGTH_MULTIPLES
    times the distance (3 digits; bent from ``sibling`` as a blend by length is), when it
    has fewer inflections than ``free`` and a lower bending energy times length; returns
    (el.ElasticSpline, note for Status), else None (the free batten is the blend).

    Why (QA22gui F5: a line into an arc of radius 25 mm, ends 168 mm apart): the G2 blend
    bent from the 1-inflection G1 batten stays on a 2-inflection family whose tension
    never reaches 0 (by length 200 -> 335 mm its tension falls from 0.0084 to 0.00036/mm^2
    near 245 mm and rises again, its bending energy rises 0.090 -> 0.153/mm): that family
    has no free member, and the only tension-0 equilibrium the solver reaches is on the
    4-inflection family, a 284 mm snake of bending energy 0.529/mm (energy x length 150,
    against 20 for the same family's 210 mm, 1.25 x): a stationary point no batten laid by
    hand between these ends would take. As where no free G1 batten exists
    (starting_length), a length at the fairest multiple is the start, and said."""
    e = el()
    # (a Hermite chain near the separatrix: no single-piece start, as g2_blend's)
    if not isinstance(sibling, e.SmoothElastica):
        return None
    free_infl = inflections(free.pieces)
    if free_infl <= len(e.elastica_inflections(sibling)):
        return None
    best = fairest_by_length(pts, ends, sibling)
    if best is None or best[0][0] >= free_infl or \
            best[0][1] >= float(free.energy) * float(free.length):
        return None
    (infl, _), m, sp = best
    return sp, (f" (tension 0 gives a {length_mark(free.length, 4)} snake of "
                f"{plural(free_infl, 'inflection')}, bending energy "
                f"{per_length_mark(free.energy)}: shown instead "
                + kept_by_tension(pts, sp, m, infl) + ")")


# The default G2 blend (Tension 0 asked): the free G2 batten unless it is more than
# ALONG_LONGER x the G1 solution it is bent from and a G2 blend of the same branch between
# the two lengths, at ALONG_STEPS lengths, is fairer by more than ALONG_GAIN in bending
# energy x length (fewest inflections first).
ALONG_LONGER = 1.25
ALONG_STEPS = 12
ALONG_GAIN = 0.9


def fairer_along(pts, ends, sibling, free):
    """Where the free G2 batten ``free`` (tension 0, bent from the G1 solution ``sibling``)
    is far longer than that solution (ALONG_LONGER) and less fair: the fairest G2 blend of
    lengths between
    the two (ALONG_STEPS of them, the sibling's included, each bent from ``sibling``, the
    best refined between its neighbours: _refined): at
    most as many inflections as ``free`` and as ``sibling`` plus one, fewest first, then the
    lowest bending energy x length (the energy of its shape whatever its size, as
    fairest_by_length). Returns (el.ElasticSpline, note for Status) where its energy x length
    is below ALONG_GAIN x the free batten's, else None (the free batten is the blend).

    Why (QA gui F10): bent from the G1 solution, the free batten between a line and an arc
    of radius 60 mm is 392.6 mm long and 128 mm off the chord, against the G1 solution's
    206.8 and 43: a tall loop over the arc, the G2 version of the 380 mm G1 solution 2 (bent
    from that one, the same curve). Its bending energy is not the branch's least (0.0997/mm
    against 0.0994 at 274 mm; of 13 line / arc / B-spline pairs, at most 1.2 % below the
    least of the branch's shorter members, and 6.6 % and 19 % above it on two): along the
    guided batten's family the guide ducks do work, so tension 0 is not its least energy.
    The fairest by energy x length is 245.5 mm (25.2 against 39.1, 2 inflections as the
    free one; the best of the grid refined, _refined). Where the free batten is about
    the G1 length (lines, an arc into a line: at most 1.2 x in the 13 pairs; the batten a few
    % longer and pushed hard instead, tension -0.12/mm^2 on a 48 mm blend, is no better
    seen) it stays the blend."""
    e = el()
    if not isinstance(sibling, e.SmoothElastica):
        return None
    a, b = float(sibling.length), float(free.length)
    if b <= ALONG_LONGER * a:
        return None         # about the G1 solution's length: the free batten is the blend
    free_infl = inflections(free.pieces)
    cap = min(free_infl, len(e.elastica_inflections(sibling)) + 1)
    free_key = float(free.energy) * b
    def probe(length):
        """((inflections, energy x length), spline) at ``length``, or None (no solve)."""
        try:
            sp = quiet_g2(pts, ends, length=length, initial=[sibling])
        except (ValueError, ArithmeticError, RuntimeError):
            return None
        return (inflections(sp.pieces), float(sp.energy) * float(sp.length)), sp

    best, at = None, None
    for k in range(ALONG_STEPS):
        got = probe(a + (b - a) * k / ALONG_STEPS)
        if got is not None and got[0][0] <= cap and (best is None or got[0] < best[0]):
            best, at = got, k
    if best is None:
        return None
    best = _refined(probe, best, a + (b - a) * max(at - 1, 0) / ALONG_STEPS,
                    a + (b - a) * min(at + 1, ALONG_STEPS) / ALONG_STEPS)
    if best[0][1] >= ALONG_GAIN * free_key:
        return None
    (infl, fair), sp = best
    dist = float(np().linalg.norm(pts[1] - pts[0]))
    # no tension to type back where it is below 0 (a G2 Tension is >= 0: review of F10); one
    # parenthesis without '; ' (the panel breaks the Status at them: outer_parts)
    pull = (f"at tension {tension_mark(sp.tension, dist, G2_TENSION_DIGITS)}"
            if float(sp.tension) >= 0.0 else "pushed together")
    return sp, (f" (the free batten (tension 0) is {length_mark(b, 4)} long, bending energy "
                f"\u00d7 length {free_key:.3g}: shown instead the fairest between it and the G1 "
                f"solution's {length_mark(a, 4)}, {length_mark(sp.length, 6)}, "
                f"{plural(infl, 'inflection')}, energy \u00d7 length {fair:.3g}, {pull}: "
                "Tension 0 keeps it, and so does Solve for a length at its length, which the "
                "switch copies; another Length is solved from that length's own G1 solution, "
                "and bent from a longer G1 solution the free batten may be its own)")


# golden-section steps refining the best of the ALONG_STEPS lengths within its two grid
# steps: 0.618^ALONG_REFINE of them (31 mm for F4's line and arc: to ~0.04 mm)
ALONG_REFINE = 14


def _refined(probe, best, lo, hi):
    """The lowest energy x length of the G2 blends of lengths in [lo, hi] with as many
    inflections as ``best`` (probe(length): ((inflections, energy x length), spline) or
    None), by golden section from ``best`` (the best of the grid, at a grid length inside):
    the grid alone made the blend jump ~7 mm as an edge moved 2 mm, its best switching to
    the next length (review of F10). Hand-written: FreeCAD's Python has no scipy, and each
    probe is a spline solve the library's minimisers cannot call."""
    def key(length):
        got = probe(length)
        if got is None or got[0][0] != best[0][0]:
            return math.inf, got
        return got[0][1], got

    r = 0.5 * (math.sqrt(5.0) - 1.0)
    x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
    (f1, g1), (f2, g2) = key(x1), key(x2)
    for step in range(ALONG_REFINE + 1):
        for f, g in ((f1, g1), (f2, g2)):       # the better probe, after each step
            if f < best[0][1]:
                best = g
        if step == ALONG_REFINE:
            return best
        if f1 <= f2:
            hi, x2, f2, g2 = x2, x1, f1, g1
            x1 = hi - r * (hi - lo)
            f1, g1 = key(x1)
        else:
            lo, x1, f1, g1 = x1, x2, f2, g2
            x2 = lo + r * (hi - lo)
            f2, g2 = key(x2)


__all__ = ["LENGTH_MULTIPLES", "starting_length", "free_or_length", "fairest_by_length",
           "fair_where_no_free", "fairer_than_free", "kept_by_tension", "fairer_along",
           "ALONG_LONGER", "ALONG_STEPS", "ALONG_GAIN", "ALONG_REFINE"]


def g2_start(e0, at_end0, e1, at_end1, plane, length):
    """What G2 starts by where it was asked at a length the command chose (no free G1 batten
    joins the ends: free_or_length) and no G2 blend of that length was found: ('tension',
    0.0) where the free G2 batten exists (the guide ducks may hold one where no free G1
    batten exists), else ('length', L) for the fairest of the lengths G2_REACH_MULTIPLES
    times the distance between the ends (3 digits, the lengths g2_lengths_hint's error
    lists: each solves): not pushed together (tension >= 0), fewest inflections, then the
    nearest ``length``; else None (the error stands). QA23gui F4: line -> arc R25, the
    command's 69.1 mm; G2 said 'no G2 blend of length 69.1 mm ... found at 92.2, 115, 138,
    184, 277 mm': the nearest, 92.2 mm, is pushed together with 4 inflections; G2 starts at
    115 mm (2 inflections, tension 0.00336/mm^2, what QA typed)."""
    r = blend_core(e0, at_end0, e1, at_end1, plane, "length", length, none_ok=True)
    pts, ends = g2_problem(r)
    try:
        quiet_g2(pts, ends)
        return "tension", 0.0
    except (ValueError, ArithmeticError, RuntimeError):
        pass
    best = None
    for L in sorted({float(f"{m * r['distance']:.3g}") for m in G2_REACH_MULTIPLES}):
        try:
            sp = quiet_g2(pts, ends, length=L)
        except (ValueError, ArithmeticError, RuntimeError):
            continue
        key = (inflections(sp.pieces), abs(L - length))
        if float(sp.tension) >= 0.0 and (best is None or key < best[0]):
            best = (key, L)
    return None if best is None else ("length", best[1])
