"""One rule for == over the binding's results and curves (QA18 M2: FitResult == its pickled
copy raised "truth value of an array is ambiguous", EllipticBlend(k=0.3) == EllipticBlend(
k=0.3) was False): value equality. Arrays are equal by np.array_equal with their shapes and
dtypes equal too; NaN equals NaN (a field "not measured" is the same in a copy), so a
pickle / copy / deepcopy round trip compares equal; == never raises. Objects of different
classes are not equal; equal objects are not hashable unless their class says so.
"""
from __future__ import annotations

import dataclasses
import math
import numbers

import numpy as np

from ._portable import PortablePickle

__all__ = ["ValueEquality", "field_summary", "same"]


def same(a, b) -> bool:
    """Whether a and b hold the same values by the rule above (recursing into dataclasses,
    lists, tuples and dicts)."""
    if a is b:
        return True
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        if not (isinstance(a, np.ndarray) and isinstance(b, np.ndarray)) \
                or a.shape != b.shape or a.dtype != b.dtype:
            return False
        if a.dtype.kind == "O":
            return all(same(x, y) for x, y in zip(a.ravel(), b.ravel()))
        return bool(np.array_equal(a, b, equal_nan=a.dtype.kind in "fc"))
    if isinstance(a, numbers.Number) and isinstance(b, numbers.Number) \
            and not isinstance(a, bool) and not isinstance(b, bool):
        if isinstance(a, numbers.Real) and isinstance(b, numbers.Real) \
                and math.isnan(a) and math.isnan(b):
            return True
        return bool(a == b)
    if type(a) is not type(b):
        return False
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if dataclasses.is_dataclass(a) and not isinstance(a, ValueEquality):
        return all(same(getattr(a, f.name), getattr(b, f.name)) for f in dataclasses.fields(a))
    try:
        return bool(a == b)
    except (ValueError, TypeError):       # an object whose == is elementwise
        return False


class ValueEquality(PortablePickle):
    """Mixin: == (and so !=) by :func:`same` over :meth:`_values` (a dataclass's fields; else
    the instance's attributes but private caches); unhashable (results are mutable or hold
    arrays). Pickles cross numpy versions (_portable.py)."""

    __slots__ = ()

    def _values(self):
        if dataclasses.is_dataclass(self):
            return tuple(getattr(self, f.name) for f in dataclasses.fields(self))
        return {k: v for k, v in vars(self).items() if not k.startswith("_")}

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return same(self._values(), other._values())

    __hash__ = None


def field_summary(obj, head: str = "") -> str:
    """A dataclass's repr in a line (QA18 P4: FitResult's printed every array, ~10 kB):
    ``head`` first, then each field, an array as its shape ('<(160, 2) array>'), a float
    as %.6g, a nested result by its own repr."""
    def one(v):
        if isinstance(v, np.ndarray):
            return f"<{v.shape} array>" if v.size > 4 else np.array2string(v, separator=", ")
        if isinstance(v, float):
            return f"{v:.6g}"
        return repr(v)
    items = [head] if head else []
    items += [f"{f.name}={one(getattr(obj, f.name))}" for f in dataclasses.fields(obj)]
    return f"{type(obj).__name__}({', '.join(items)})"
