"""What a fit's end conditions cost: a fit held to constraints or fixed parameters (a
tangent, a curvature, a point, a G1/G2 join in FreeCAD) against the same fit with free
ends. Conditions far from the data's own are met by a curl or a swing that fits nothing
(a smooth fit of a noisy 330 mm S meets 0.05/mm at its start, four times its own end
curvature, at rms 9 mm against 0.29 mm free): :func:`fit` warns (EndConditionWarning),
the CLI and FreeCAD's Fit feature say it in their words, all by :func:`costly`.

The free fit is one more fit of the same points, of the same model and options, and
cheaper than most constrained ones (no Ipopt): bench_fit.py's fit_constrained figures.
"""
from __future__ import annotations

import dataclasses
import math
import warnings
from typing import Iterable, Mapping, Optional

import numpy as np

from ._text import LengthFormat, lengths

__all__ = ["COST_RATIO", "COST_FLOOR", "EndConditionWarning", "costly", "cost_summary",
           "end_condition_cost", "held_names"]

# End conditions that raise the rms above COST_RATIO times the free-ended fit's, and by
# more than COST_FLOOR of the points' extent, are worth a warning (the floor: on nearly
# exact data any condition doubles a misfit of the model's own rounding).
COST_RATIO, COST_FLOOR = 2.0, 1e-4


class EndConditionWarning(RuntimeWarning):
    """:func:`fit`'s warning that its constraints or fixed parameters raise the rms above
    COST_RATIO times the same fit's with free ends (:func:`costly`): ``rms`` the fit's,
    ``free_rms`` the free one's (``FitResult.free``), ``held`` what was held."""

    def __init__(self, message: str = "", rms: float = math.nan, free_rms: float = math.nan,
                 held: Iterable[str] = ()):
        super().__init__(message)
        self.rms, self.free_rms, self.held = float(rms), float(free_rms), tuple(held)


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
    conditions in the caller's terms, ``unit`` follows each figure (e.g. " mm"), or
    ``length(value, digits)`` writes each (FreeCAD's: in the user's unit schema)."""
    fmt = lengths(unit, length)
    return (f"the end conditions ({held}) raise the rms from {fmt(free_rms, 3)} (free ends) to "
            f"{fmt(rms, 3)}: check that they match the data")


def held_names(constraints: Optional[Mapping[str, object]],
               fixed: Optional[Mapping[str, float]]) -> list:
    """:func:`fit`'s end conditions by name: its constraints' keys, then "fixed <name>"."""
    return list(constraints or ()) + [f"fixed {k}" for k in (fixed or ())]


def end_condition_cost(result) -> Optional[float]:
    """The rms of ``result``'s fit with free ends (``FitResult.free``) where its end
    conditions cost accuracy (:func:`costly`, by the fitted points' distances to each
    curve), else None (also without a free fit)."""
    free = getattr(result, "free", None)
    if free is None:
        return None
    extent = float(np.ptp(result.points, axis=0).max())
    return float(free.rms) if costly(result.rms, free.rms, extent) else None


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
    free_rms = end_condition_cost(result)
    if free_rms is not None:
        held = held_names(result.constraints, fixed)
        warnings.warn(EndConditionWarning(
            "fit: " + cost_summary(", ".join(held), free_rms, result.rms) +
            " (FitResult.free is the fit with free ends; check_ends=False skips it)",
            result.rms, free_rms, held), stacklevel=stacklevel)
    return result
