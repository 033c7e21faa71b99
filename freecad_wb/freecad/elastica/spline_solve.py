"""The elastic spline feature's solves (spline.py): el.elastic_spline through the ducks with
the accepted-residual rule, and a failure said in the workbench's words: the G2 battens the
library met nearest the tension asked, the largest tension it resolves, the free batten's
length, a G2 end blamed only where the batten with tangent ends exists, the work budget's
end (raise MaxIter) without a further solve."""
from __future__ import annotations

import math
import re

from .geometry import binding_module, el
from .proxy import InputProblem, ShapeProblem
from .units import ceil_digits, floor_digits, length_mark, reach_mark, tension_mark

ACCEPTED_RESIDUAL = 1e-6    # a spline the solver resolves only to this is still shown (noted)
MAX_ITER = 60               # Newton iterations per solve: the library's default (el_spline_options)


class NoSpline(InputProblem):
    """Good points, but no batten passes them at this tension or length (another tension
    or length may give one): not bad input."""


class DoublesBack(NoSpline, ShapeProblem):
    """Points that double back within their noise (el.DoublesBackError): no tension or
    length gives a batten through them that does not loop. The points were what the command
    takes (a ShapeProblem: its box is titled by the command, not 'Wrong selection ... Select
    the points', QA23gui F8)."""


# the binding's advice (libelastica spline._fair_advice) in the workbench's words: its
# Python and CLI names (el.fit, `elastica fit`) are not a designer's (QA23gui F8)
FAIR_ADVICE = (
    ("fair the points with el.fit (`elastica fit`) instead, or thin them to points farther "
     "apart than their noise",
     "these are scan points, too many and too noisy for a batten through each: fair them with "
     "the Fit elastica command (Elastica menu) instead, or thin them to points farther apart "
     "than their noise"),
    ("el.fit fits open curves only: for a closed outline thin the points to fewer ducks "
     "farther apart than their noise (or fit its open arcs with el.fit)",
     "the Fit elastica command fits open curves only: for a closed outline thin the points "
     "to fewer ducks farther apart than their noise (or fair its open arcs with it)"))


def _fair_words(text):
    """The library's DoublesBackError message with FAIR_ADVICE's words, its Python slice
    'points[::k]' left out."""
    for api, gui in FAIR_ADVICE:
        text = text.replace(api, gui)
    return re.sub(r" \(points\[::\d+\], (\d+) points\)", r" (\1 points)", text)


def _library_message(exc):
    """The binding's message in the workbench's words (its advice at tension 0 names the
    Python API's warnings: said here for the panel)."""
    return str(exc).replace("elastic_spline: ", "").replace(
        binding_module("spline").SMALL_TENSION_TEXT,
        " (a small tension may give a batten that loops, or one a real batten bent so would "
        "not hold: raise it until the Warnings say neither; the Elastic spline command, "
        f"given no tension, starts at the least of {binding_module('spline').ladder_words()} "
        "/ P\u00b2 that holds)")


# Significant digits a tension of a G2 batten met is said to: the first that, typed back,
# solves (the arc of radius 20 mm into a line, by tension 0.003: 0.00171 as the binding
# says it does not; 0.001707 does)
G2_MET_DIGITS = (4, 6)


def g2_solves(solve, tension):
    """Whether ``solve(tension)`` (an el.elastic_spline by that tension) gives a batten."""
    try:
        return solve(tension) is not None
    except (ValueError, ArithmeticError, RuntimeError):
        return False


def g2_met_hint(met, solve, advice="give a tension it reached, or a length"):
    """Where no G2 batten was found at the tension asked: the library's G2 battens met
    nearest it (el.NotConvergedError's g2_met: below, above, each (tension, length) or
    None), each tension rounded down (below) or up (above) to the first of G2_MET_DIGITS
    that ``solve(tension)`` solves (g2_solves), with its length, then ``advice``; None
    where it met none of tension > 0."""
    said = []
    for j, m in enumerate(met or ()):
        if m is None or not m[0] > 0.0:     # a negative tension cannot be asked of a G2 end
            continue
        rounded = ceil_digits if j else floor_digits
        for digits in G2_MET_DIGITS:
            tension = rounded(m[0], digits)
            if g2_solves(solve, tension):
                break
        said.append(f"{'from' if j else 'up to'} {reach_mark(tension, digits, up=j == 1)} "
                    f"(length {length_mark(m[1], 4)})")
    if not said:
        return None
    return ("with G2 ends the solver reached battens of tension " + " and ".join(said) +
            ", none at this one" + (" (between such tensions there may be none)"
                                    if len(said) == 2 else "") + f": {advice}")


def _tangent_only(spec):
    return spec["tangent"] if isinstance(spec, dict) else spec


def quiet_spline(xy, **kw):
    """el.elastic_spline(xy, **kw) with its LoopWarning and UnstableWarning quiet in this
    thread only (libelastica._quiet): a looping or unstable spline is noted by its caller
    (spline_core's Status, a probe's hint), not a red report-view line."""
    e = el()
    with binding_module("_quiet").quiet(e.LoopWarning, e.UnstableWarning):
        return e.elastic_spline(xy, **kw)


def _solve(xy, mode, value, closed, start, end, max_iter=MAX_ITER):
    """el.elastic_spline with the accepted-residual rule; NoSpline when no batten passes the
    points at this tension or length, InputProblem for the rest.
    When a spline with G2 ends fails by tension, the message names the G2 battens the
    library met nearest it (g2_met_hint); where it met none, the same with tangent ends is
    tried: if that one exists, the message blames the G2 end (its span found no tension).
    Not where the call's work budget ended it (the error's stopped): each of those is a new
    call with a budget of its own (the fuzz's 7 ducks at tension 49.5 with a G2 start: three
    of ~1.3 s each, then the G2 end blamed): the message says to raise MaxIter instead."""
    e = el()
    kw = {"tension": value} if mode == "tension" else {"length": value}
    largest = met = None

    def solve(**by):
        return quiet_spline(xy, start=start, end=end, closed=closed, max_iter=max_iter, **by)

    try:
        return solve(**kw), ""
    except e.NotConvergedError as exc:
        sp = getattr(exc, "spline", None)
        if sp is not None and sp.residual <= ACCEPTED_RESIDUAL:
            return sp, (f"resolved to {sp.residual:.1g} only (a piece close to a circular arc, "
                        "or a very high tension)")
        if exc.stopped:   # the budget, not the points, tension or ends: no further solve
            raise NoSpline(f"no equilibrium found: the solver stopped at its work budget "
                           f"({exc.work} evaluations at MaxIter = {max_iter}) before it could "
                           f"tell whether one exists at this {mode}: raise MaxIter (the budget "
                           "grows with it), or try another tension or length") from None
        failure = "no equilibrium found: the solver did not converge; try another tension or length"
        largest = getattr(exc, "largest_tension", None)
        met = None if largest else g2_met_hint(getattr(exc, "g2_met", None),
                                                 lambda t: solve(tension=t))
        if met or largest:
            span = max(math.hypot(b[0] - a[0], b[1] - a[1])
                       for a, b in zip(xy, list(xy[1:]) + (list(xy[:1]) if closed else [])))
        if met:       # G2 ends: the tensions of the G2 battens met (the binding's g2_met)
            failure = f"no equilibrium found at Tension = {tension_mark(value, span, 6)}: {met}"
        elif largest:   # beyond what a double resolves (the binding's search, elastica.h Accuracy)
            failure = (f"no equilibrium found at Tension = {tension_mark(value, span, 6)}: "
                       f"the highest tension the search solved these points at is about "
                       f"{tension_mark(largest, span, 3)}; it found none above it (the nearly "
                       "straight spans between the points are then more than double precision "
                       "resolves: the elliptic modulus of their pieces too near 1), but near "
                       "it the solve is not monotone, so it is no bound: give a tension near "
                       "it or lower, and another where one fails")
        elif isinstance(exc, e.LengthRangeError):   # the lengths reached, in the library's words
            failure = _library_message(exc)
        elif mode == "length":
            try:   # the free batten's length, for scale
                free = e.elastic_spline(xy, start=start, end=end, closed=closed,
                                        max_iter=max_iter).length
                failure = (f"no equilibrium found at Length = {value:g} mm: the solver did not "
                           f"converge; the free batten through these points is {free:.6g} mm "
                           "long: try a length nearer it")
            except ValueError:
                pass
    except e.DoublesBackError as exc:   # the same at every tension and length
        raise DoublesBack(_fair_words(_library_message(exc))) from None
    except e.DomainError as exc:
        failure = _library_message(exc)
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        raise InputProblem(f"elastic spline failed: {_library_message(exc)}") from None
    # a G2 batten with a largest tension exists below it: its end is not what fails (and the
    # tangent batten's solve would search its own largest, as long again: QA16 S1)
    if any(isinstance(s, dict) for s in (start, end)) and not largest and not met:
        try:
            e.elastic_spline(xy, start=_tangent_only(start), end=_tangent_only(end),
                             closed=closed, max_iter=max_iter, **kw)
            failure = ("no equilibrium with this G2 end: the batten with a tangent end exists, "
                       "but bending its end to the edge's curvature with a guide duck did not "
                       "converge (a curl too tight for the span next to it" + (
                           ", or a length the G2 batten cannot reach: pulled it gets at most "
                           "1-2 % shorter than free" if mode == "length" else "")
                       + "); use a tangent end, or move the point next to it")
        except ValueError:
            pass
    raise NoSpline(failure)
