"""How the summaries write a length: a caller's formatter, or the number and a unit."""
from __future__ import annotations

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
