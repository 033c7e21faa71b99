"""How the summaries write a length: a caller's formatter, or the number and a unit."""
from __future__ import annotations

import math
from typing import Any, Callable, List, Mapping, Optional, Tuple

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


def coordinates(values, extent: float, digits: int = 6,
                length: Optional[LengthFormat] = None) -> str:
    """Coordinates written with ``digits`` significant digits of the curve's ``extent`` (its
    size), however far they lie from the origin: %g's 6 digits wrote x0 = 499999.97636 of a
    10-long curve as 500000, 0.024 off, 2/3 of its fit's rms (QA18 P1). ', '-joined, each
    by ``length(value, digits)`` where given (the summaries' formatter: :func:`lengths`)."""
    vals = [float(v) for v in (values if hasattr(values, "__len__") else [values])]
    big = max([abs(v) for v in vals if math.isfinite(v)] + [0.0])
    extra = 0
    if extent > 0 and math.isfinite(extent) and big > extent:
        extra = int(math.ceil(math.log10(big / extent)))
    n = min(17, digits + extra)
    return ", ".join(f"{v:.{n}g}" if length is None else length(v, n) for v in vals)


def curve_values(d: Mapping[str, Any]) -> List[Tuple[str, str]]:
    """(name, text) of a curve's parameters (io.curve_to_dict's dict, its "type" left out):
    x0, y0 by :func:`coordinates` to the digits of the curve's size (its length, or
    h (n - 1)), " rad" after phi, floats to 6 digits, others (n) as they print."""
    size = d.get("length") or d.get("h", 0.0) * max(d.get("n", 2) - 1, 1)
    return [(k, (coordinates(v, size) if k in ("x0", "y0") else
                 f"{v:.6g}" if isinstance(v, float) else str(v)) + (" rad" if k == "phi" else ""))
            for k, v in d.items() if k != "type"]
