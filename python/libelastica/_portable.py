"""Private: pickles that cross numpy versions (QA19 M2: a result pickled under numpy 2 did
not load under FreeCAD's numpy 1.24, "No module named 'numpy._core'": numpy pickles its
arrays and scalars by its own module paths, which numpy 2 renamed). A result or curve
pickles its state with every numpy array as its dtype, shape and a plain list, and every
numpy scalar as a Python number, restored to the same arrays (same dtype, shape and
values: == holds, _values.py) on load under either numpy. copy / deepcopy keep their
usual meaning (arrays shared / copied), not this detour.
"""
from __future__ import annotations

import copy

import numpy as np

__all__ = ["PortablePickle", "PortableTuple", "portable"]


def _array(dtype: str, shape, data) -> np.ndarray:
    """An array back from :class:`_Array`'s plain form."""
    if dtype == "|O":
        out = np.empty(len(data), dtype=object)
        out[:] = data
        return out.reshape(shape)
    return np.array(data, dtype=np.dtype(dtype)).reshape(shape)


def _scalar(dtype: str, value):
    return np.dtype(dtype).type(value)


class _Array:
    """An array as pickle writes it: (dtype, shape, a flat list): no numpy module path."""
    __slots__ = ("a",)

    def __init__(self, a):
        self.a = a

    def __reduce__(self):
        a = self.a
        if a.dtype.kind == "O":
            return _array, ("|O", a.shape, [portable(v) for v in a.ravel()])
        return _array, (a.dtype.str, a.shape, a.ravel().tolist())


class _Scalar(_Array):
    __slots__ = ()

    def __reduce__(self):
        return _scalar, (self.a.dtype.str, self.a.item())


def portable(v):
    """``v`` with each numpy array and scalar in it (lists, tuples, dicts, named tuples
    looked into) replaced by its plain form; structured arrays are left as they are."""
    if isinstance(v, np.ndarray):
        return _Array(v) if v.dtype.names is None else v
    if isinstance(v, np.generic):
        return _Scalar(v)
    if type(v) in (list, tuple):
        return type(v)(portable(x) for x in v)
    if type(v) is dict:
        return {k: portable(x) for k, x in v.items()}
    if isinstance(v, tuple) and hasattr(v, "_fields"):
        return _Tuple(v)
    return v


class _Tuple(_Array):
    """A named tuple: rebuilt from its fields in plain form."""
    __slots__ = ()

    def __reduce__(self):
        return PortableTuple.reduce(self.a)


def _set_state(obj, state):
    """``state`` into ``obj`` as pickle's default does: __setstate__ when the class has
    one, else its __dict__ updated; nothing for None."""
    if state is not None:
        if hasattr(obj, "__setstate__"):
            obj.__setstate__(state)
        else:
            obj.__dict__.update(state)


def _restore(cls, state, items=None):
    """An instance of ``cls`` with ``state`` (and a list's ``items``), as pickle's default
    does: no __init__."""
    obj = cls.__new__(cls)
    if items:
        obj.extend(items)
    _set_state(obj, state)
    return obj


class PortableTuple:
    """Methods for a NamedTuple class (which takes no mixin): ``__reduce__ =
    PortableTuple.reduce`` and the two copies, which keep copy's meaning."""

    @staticmethod
    def reduce(self):
        return type(self), tuple(portable(x) for x in self)

    @staticmethod
    def copy(self):
        return type(self)(*self)

    @staticmethod
    def deepcopy(self, memo):
        return type(self)(*copy.deepcopy(tuple(self), memo))


class PortablePickle:
    """Mixin: pickle by the instance's state (``__getstate__``'s, else its attributes; a
    list's items too) with numpy arrays and scalars in plain form (:func:`portable`), so
    the pickle loads under numpy 1.x and 2.x alike. A class that defines its own
    ``__reduce__`` (by parameters: blend.py's bases) keeps it, and copies by it where it
    sets ``__copy__ = __deepcopy__ = None`` (copy's default then)."""

    __slots__ = ()

    def _pickled_state(self):
        get = getattr(self, "__getstate__", None)    # (object has it from Python 3.11)
        state = get() if get is not None else None
        return dict(vars(self)) if state is None and hasattr(self, "__dict__") else state

    def __reduce__(self):
        items = portable(list(self)) if isinstance(self, list) else None
        return _restore, (type(self), portable(self._pickled_state()), items)

    def __copy__(self):
        return _restore(type(self), copy.copy(self._pickled_state()),
                        list(self) if isinstance(self, list) else None)

    def __deepcopy__(self, memo):
        new = _restore(type(self), None)
        memo[id(self)] = new
        if isinstance(self, list):
            new.extend(copy.deepcopy(list(self), memo))
        _set_state(new, copy.deepcopy(self._pickled_state(), memo))
        return new
