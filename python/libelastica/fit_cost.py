"""What a fit's end conditions cost: a fit held to constraints or fixed parameters (a
tangent, a curvature, a point, a G1/G2 join in FreeCAD) against the same fit with free
ends. Conditions far from the data's own are met by a curl or a swing that fits nothing
(a smooth fit of a noisy 330 mm S meets 0.05/mm at its start, four times its own end
curvature, at rms 9 mm against 0.29 mm free): :func:`fit` warns (EndConditionWarning),
the CLI and FreeCAD's Fit feature say it in their words, all by :func:`costly`. A wrong
condition whose damage stays near its end (a start tangent 17 deg off on an 800-point scan:
rms 1.68 x free overall, 2.4 x over the first tenth) is caught there: :func:`end_costs`.

The free fit is one more fit of the same points, of the same model and options, and
cheaper than most constrained ones (no Ipopt): bench_fit.py's fit_constrained figures.
"""
from __future__ import annotations

import dataclasses
import math
from typing import Iterable, Mapping, Optional

import numpy as np

from ._quiet import say
from ._text import LengthFormat, lengths

__all__ = ["COST_RATIO", "COST_FLOOR", "END_SPAN", "END_POINTS", "EndConditionWarning", "costly",
           "cost_summary", "end_condition_cost", "end_costs", "held_ends", "held_names",
           "local_cost_summary"]

# End conditions that raise the rms above COST_RATIO times the free-ended fit's, and by
# more than COST_FLOOR of the points' extent, are worth a warning (the floor: on nearly
# exact data any condition doubles a misfit of the model's own rounding).
COST_RATIO, COST_FLOOR = 2.0, 1e-4
# The same rule near each held end: the points within END_SPAN of the points' run along
# the free fit from that end, judged only where they are END_POINTS or more (on fewer, a
# free end's fit of its last few noisy points reads as a cost: 3 false alarms in 96 fits
# of 10-40 sketched points holding their true ends, none with this floor).
END_SPAN, END_POINTS = 0.1, 10
_START_FIXED = ("x0", "y0", "phi", "kappa0")


class EndConditionWarning(RuntimeWarning):
    """:func:`fit`'s warning that its constraints or fixed parameters raise the rms above
    COST_RATIO times the same fit's with free ends (:func:`costly`): ``rms`` the fit's,
    ``free_rms`` the free one's (``FitResult.free``), ``held`` what was held; or near one
    end only (:func:`end_costs`): ``end`` "start" / "end" (None: overall), ``local_rms`` /
    ``free_local_rms`` both fits' rms over the points near it (NaN where overall)."""

    def __init__(self, message: str = "", rms: float = math.nan, free_rms: float = math.nan,
                 held: Iterable[str] = (), end: Optional[str] = None,
                 local_rms: float = math.nan, free_local_rms: float = math.nan):
        super().__init__(message)
        self.rms, self.free_rms, self.held = float(rms), float(free_rms), tuple(held)
        self.end, self.local_rms, self.free_local_rms = end, float(local_rms), float(free_local_rms)


def costly(rms: float, free_rms: float, extent: float) -> bool:
    """Whether a fit held to end conditions at ``rms`` costs accuracy against the same fit
    with free ends at ``free_rms``: above COST_RATIO times it and by more than COST_FLOOR
    of the points' ``extent`` (the largest side of their bounding box). Compare like with
    like: both the points' distances to the curves they were fitted to (a discrete fit's
    polygons), or both to the curves drawn (its cubics, as FreeCAD shows)."""
    return rms > COST_RATIO * free_rms and rms - free_rms > COST_FLOOR * extent


def cost_summary(held: str, free_rms: float, rms: float, unit: str = "",
                 length: Optional[LengthFormat] = None) -> str:
    """What the warning says (Python's, the CLI's, FreeCAD's): ``held`` names the end
    conditions in the caller's terms, ``free_rms`` / ``rms`` the fit's with free ends and
    held (input units), ``unit`` follows each figure (e.g. " mm"), or
    ``length(value, digits)`` writes each (FreeCAD's: in the user's unit schema)."""
    fmt = lengths(unit, length)
    return (f"the end conditions ({held}) raise the rms from {fmt(free_rms, 3)} (free ends) to "
            f"{fmt(rms, 3)}: check that they match the data")


def local_cost_summary(held: str, end: str, free_rms: float, rms: float, unit: str = "",
                       length: Optional[LengthFormat] = None) -> str:
    """What the warning says where the cost is near one ``end`` (:func:`end_costs`);
    ``held``, ``free_rms``, ``rms`` (there), ``unit`` / ``length`` as :func:`cost_summary`'s."""
    fmt = lengths(unit, length)
    return (f"the end conditions ({held}) raise the rms near the {end} (the first "
            f"{END_SPAN:.0%} of the points' run from it) from {fmt(free_rms, 3)} (free ends) to "
            f"{fmt(rms, 3)}: check that they match the data")


def held_ends(constraints: Optional[Mapping[str, object]],
              fixed: Optional[Mapping[str, float]]) -> list:
    """Which ends the end conditions hold, "start" and/or "end": the constraints' names
    say it; fixed x0, y0, phi, kappa0 are the start's (a length or shape held: neither)."""
    names = list(constraints or ())
    ends = [e for e in ("start", "end") if any(k.startswith(e + "_") for k in names)]
    if "start" not in ends and any(k in _START_FIXED for k in (fixed or ())):
        ends.insert(0, "start")
    return ends


def end_costs(ends: Iterable[str], foot_s, distances, free_distances, extent: float) -> list:
    """[(end, rms, free rms)] for each of ``ends`` where the end conditions cost accuracy
    near it (:func:`costly` on both fits' rms over its points): the points within END_SPAN
    of their run along the free fit (``foot_s``, its arc lengths of their feet) from that
    end, where they are END_POINTS or more. Distances like with like (:func:`costly`):
    ``distances`` the held fit's, ``free_distances`` the free fit's (both (n,), the same
    points); ``extent`` the points' largest bounding-box side (costly's floor)."""
    s = np.asarray(foot_s, dtype=float)
    d, f = np.asarray(distances, dtype=float), np.asarray(free_distances, dtype=float)
    run = float(np.ptp(s)) if s.size else 0.0
    if not (run > 0.0 and d.shape == f.shape == s.shape):
        return []
    t = (s - s.min()) / run
    out = []
    for end in ends:
        near = t <= END_SPAN if end == "start" else t >= 1.0 - END_SPAN
        if near.sum() < END_POINTS:
            continue
        rms, free = (float(np.sqrt(np.mean(np.square(x[near])))) for x in (d, f))
        if costly(rms, free, extent):
            out.append((end, rms, free))
    return out


def held_names(constraints: Optional[Mapping[str, object]],
               fixed: Optional[Mapping[str, float]]) -> list:
    """:func:`fit`'s end conditions by name: its constraints' keys, then "fixed <name>"."""
    return list(constraints or ()) + [f"fixed {k}" for k in (fixed or ())]


def _ends_cost(result, fixed=None) -> list:
    """end_costs of ``result`` against its free fit, by the fitted points' distances."""
    free = result.free
    ends = held_ends(result.constraints, fixed)
    if not ends or free.foot_s is None or result.distances is None or free.distances is None:
        return []
    return end_costs(ends, free.foot_s, result.distances, free.distances,
                     float(np.ptp(result.points, axis=0).max()))


def end_condition_cost(result, fixed: Optional[Mapping[str, float]] = None) -> Optional[float]:
    """The rms of ``result``'s fit with free ends (``FitResult.free``) where its end
    conditions cost accuracy (:func:`costly`, by the fitted points' distances to each
    curve, overall or near a held end: :func:`end_costs`; ``fixed``: the fit's, whose
    x0, y0, phi hold its start), else None (also without a free fit)."""
    free = getattr(result, "free", None)
    if free is None:
        return None
    extent = float(np.ptp(result.points, axis=0).max())
    if costly(result.rms, free.rms, extent) or _ends_cost(result, fixed):
        return float(free.rms)
    return None


def checked_ends(result, fixed: Optional[Mapping[str, float]], options: dict,
                 stacklevel: int = 3):
    """:func:`fit`'s ``check_ends``: ``result`` (a fit with constraints or ``fixed``
    parameters) with ``free``, the fit of its points by the same ``options`` without them
    (None where that fit fails: no verdict), and an EndConditionWarning where they cost
    accuracy."""
    from .fit import quiet_fit
    try:
        free = quiet_fit(result.points, check_ends=False, **options)
    except (ValueError, ArithmeticError, RuntimeError):
        return result
    result = dataclasses.replace(result, free=free)
    held = held_names(result.constraints, fixed)
    extent = float(np.ptp(result.points, axis=0).max())
    local = _ends_cost(result, fixed)
    if costly(result.rms, free.rms, extent):
        said, at = cost_summary(", ".join(held), free.rms, result.rms), (None, math.nan, math.nan)
    elif local:
        at = local[0]       # (end, rms, free rms)
        said = local_cost_summary(", ".join(held), at[0], at[2], at[1])
    else:
        return result
    say(EndConditionWarning(
        f"fit: {said} (FitResult.free is the fit with free ends; check_ends=False skips it)",
        result.rms, free.rms, held, *at), stacklevel=stacklevel)
    return result
