"""How the summaries write a length: a caller's formatter, or the number and a unit."""
from __future__ import annotations

import math
from typing import Callable, Optional

# length(value, digits, with_unit=True) -> text: ``digits`` significant digits (None: as
# '%g' writes them); with_unit False: the number alone ('9.05 to 16 mm')
LengthFormat = Callable[..., str]


def lengths(unit: str = "", length: Optional[LengthFormat] = None) -> LengthFormat:
    """``length`` where given (FreeCAD's: the exact value in the user's unit schema), else
    the number to ``digits`` and ``unit`` after it ('1.18 mm' for unit ' mm')."""
    if length is not None:
        return length
    return lambda v, digits=None, with_unit=True: \
        (f"{v:g}" if digits is None else f"{v:.{digits}g}") + (unit if with_unit else "")


def coordinates(values, extent: float, digits: int = 6) -> str:
    """Coordinates written with ``digits`` significant digits of the curve's ``extent`` (its
    size), however far they lie from the origin: %g's 6 digits wrote x0 = 499999.97636 of a
    10-long curve as 500000, 0.024 off, 2/3 of its fit's rms (QA18 P1). ', '-joined."""
    vals = [float(v) for v in (values if hasattr(values, "__len__") else [values])]
    big = max([abs(v) for v in vals if math.isfinite(v)] + [0.0])
    extra = 0
    if extent > 0 and math.isfinite(extent) and big > extent:
        extra = int(math.ceil(math.log10(big / extent)))
    return ", ".join(f"{v:.{min(17, digits + extra)}g}" for v in vals)
