"""Private: load libelastica's shared library with cffi (ABI mode).

The declarations come from the one public header, include/elastica.h, with its
preprocessor lines removed, so they are never retyped by hand (_cdef.py): pre-parsed
by the build (cffi's out-of-line module beside the library or in the package) when
that module was made from this header, else parsed now. The header is found next to
this package (installed copy) or in the source tree; the library through
LIBELASTICA_PATH, a bundled copy, the source tree's build/, or the system loader
(pkg-config install). At import the library must have been built from the header the
declarations come from (its el_abi_digest is the header's): cffi lays out every struct
by that header, and a library built from another writes past them.
"""
from __future__ import annotations

import copyreg
import decimal
import math
import numbers
import os
from pathlib import Path
from typing import Optional

import numpy as np

from . import _cdef
from ._columns import table_points

_HERE = Path(__file__).resolve().parent
_SRC_ROOT = _HERE.parent.parent


def _find(candidates):
    for c in candidates:
        if c and Path(c).is_file():
            return str(c)
    return None


def _header() -> str:
    path = _find([_HERE / "elastica.h", _SRC_ROOT / "include" / "elastica.h",
                  "/usr/local/include/elastica.h", "/usr/include/elastica.h"])
    if path is None:
        raise ImportError("libelastica: elastica.h not found (reinstall the package)")
    return path


def _internal(header: str) -> Optional[str]:
    """The binding's internal header (libelastica/binding.h, _cdef.binding_text) that goes
    with ``header``: beside it in the package, or the source tree's; None for an installed
    elastica.h (the binding then takes its plain paths: _fit_call.py)."""
    here = Path(header).parent
    return _find([here / "binding.h"] if here == _HERE else
                 [_SRC_ROOT / "libelastica" / "binding.h"] if here == _SRC_ROOT / "include" else [])


def _library() -> Optional[str]:
    """The library's file, None for the system loader's."""
    env = os.environ.get("LIBELASTICA_PATH")
    if env and not Path(env).is_file():
        raise ImportError(f"libelastica: LIBELASTICA_PATH={env} is not a file")
    return env or _find([_HERE / "libelastica.so", _SRC_ROOT / "build" / "libelastica.so"])


def _load(ffi, path: Optional[str]):
    try:
        return ffi.dlopen(path or "libelastica.so.0")
    except OSError as exc:
        raise ImportError(
            "libelastica: the C library was not found; build it with `make` in the "
            "source tree, set LIBELASTICA_PATH, or `make install`") from exc


def _check_abi(lib, header: str, library: Optional[str], digest: int) -> None:
    """ImportError naming both files unless the library was built from ``header``
    (el_abi_digest, the CRC-32 of its declarations, is ``digest``: _cdef.py)."""
    try:
        built = lib.el_abi_digest()
    except AttributeError:           # a library older than el_abi_digest
        built = None
    if built == digest:
        return
    where = library or "libelastica.so.0 (the system loader's)"
    said = ("has no el_abi_digest (older than this binding)" if built is None else
            f"was built from another elastica.h (digest {built:#010x})")
    raise ImportError(
        f"libelastica: the C library {where} {said}, not from the header this binding "
        f"read, {header} (digest {digest:#010x}): its structs would be laid out otherwise. "
        f"Rebuild the library from that header (`make lib` in its source tree, or "
        f"reinstall the Python package), or set LIBELASTICA_PATH to the library built with it")


_LIBRARY = _library()
_HEADER = _header()
# pre-parsed in the package (wheel), else beside the library (make lib); CDEF_MODULE:
# the module used, None when the header was parsed (~40 ms more)
_INTERNAL = _internal(_HEADER)
ffi, CDEF_MODULE, _DIGEST = _cdef.declarations(_HEADER, [_HERE] + ([Path(_LIBRARY).parent] if _LIBRARY else []),
                                                _INTERNAL)
# binding.h's digest (el_binding_digest's where the library was built from it: _fit_call.py)
BINDING_DIGEST = _cdef.digest(_cdef.cdef_text(_INTERNAL)) if _INTERNAL else None
lib = _load(ffi, _LIBRARY)
_check_abi(lib, _HEADER, _LIBRARY, _DIGEST)


class ElasticaError(ValueError):
    """A libelastica call failed; ``status`` is the C status code."""

    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status = status

    def __reduce__(self):
        # pickle's default rebuilds an exception as cls(*self.args), args being the message
        # alone: ElasticaError(message) raised TypeError in the loading process (a worker's
        # error sent back by multiprocessing / concurrent.futures) and the attributes callers
        # read (status, stopped, work, shortest, constraint, cause...) were lost. Rebuilt
        # without __init__ (subclasses take other arguments), its __dict__ restored
        return copyreg.__newobj__, (type(self),) + self.args, self.__dict__


class NotConvergedError(ElasticaError):
    """An iteration stopped before converging (EL_ENOCONV / EL_EMAXITER)."""


class LengthRangeError(NotConvergedError):
    """A length the solve did not reach, mostly beyond the splines it met (EL_ERANGE): ``shortest``, ``longest``
    (the least and greatest lengths met on the one family of splines the solver followed:
    the range it met, not a bound on the splines through the points; others, e.g. tension
    mode's, may be shorter or longer), ``longest_fair`` (the longest of them that does not
    cross itself, 0 if none) and ``polygon``."""


class DomainError(ElasticaError):
    """Valid input outside what the method covers (EL_EDOM)."""


class SingularError(ElasticaError):
    """Degenerate input: collinear or coincident data, singular systems (EL_ESINGULAR)."""


class AngleUnitWarning(UserWarning):
    """An angle the binding takes in radians is past a full turn: degrees given by mistake?
    (warn_if_degrees; the elastica command, which reads every angle with its unit, turns it
    off and says a tangent past a full turn in degrees.)"""


_ERRORS = {lib.EL_ENOCONV: NotConvergedError, lib.EL_EMAXITER: NotConvergedError,
           lib.EL_ERANGE: LengthRangeError,
           lib.EL_EDOM: DomainError, lib.EL_ESINGULAR: SingularError}


# the C texts of these two say "(best result seen returned)": true of the C call's out
# parameters, not of a raised exception, which returns nothing
_RAISED_TEXT = {lib.EL_ENOCONV: "did not converge", lib.EL_EMAXITER: "iteration limit reached"}


def check(status: int, what: str = "") -> None:
    """Raise the exception that matches a C status (pynacl's `ensure` pattern)."""
    if status != lib.EL_OK:
        msg = _RAISED_TEXT.get(status) or ffi.string(lib.el_strerror(status)).decode()
        raise _ERRORS.get(status, ElasticaError)(status, f"{what}: {msg}" if what else msg)


# ------------------------------------------------------------------ input validation
#
# Every public entry converts its arguments with these helpers, so that wrong
# types and out-of-range values raise ValueError (never TypeError, OverflowError
# or AttributeError from deep inside, never a silent truncation of complex
# numbers or a C integer that wraps).

INT_MIN, INT_MAX = -2 ** 31, 2 ** 31 - 1
SIZE_MAX = 2 ** 64 - 1


def _is_real(v) -> bool:
    """A real number (Fraction and Decimal included), not a bool."""
    return isinstance(v, (numbers.Real, decimal.Decimal)) and not isinstance(v, (bool, np.bool_))


def as_real_array(a, name: str = "values") -> np.ndarray:
    """A C-contiguous float64 array of ``a`` (no copy when it already is one).

    Accepted: real numbers (float32/64, longdouble, signed and unsigned ints),
    nested lists of them, and object arrays of real numbers (Fraction, Decimal).
    Refused with ValueError: complex (the imaginary part would be dropped),
    datetime/timedelta, float16 (3 significant digits), booleans, strings,
    None and other objects, and masked arrays with a masked value (numpy's asarray
    keeps the masked data: the mask would be ignored)."""
    if isinstance(a, np.ndarray):
        arr = a
        # (asarray would keep the masked values; a plain ndarray has none: is_masked's
        # getmask is nomask for it, and the call cost 1.5 us of as_real_array's 5.5 us)
        if type(a) is not np.ndarray and np.ma.is_masked(a):
            raise ValueError(f"{name} is a masked array with masked values (the mask would be "
                             "ignored): drop them first, e.g. np.ma.compress_rows(P) for points, "
                             "a.compressed() for a 1-D array")
    else:
        try:
            arr = np.asarray(a)
        except (TypeError, ValueError) as exc:   # ragged nesting
            raise ValueError(f"{name} must be an array of real numbers ({exc})") from None
    kind = arr.dtype.kind
    if kind == "c":
        raise ValueError(f"{name} must be real; complex values are refused (the imaginary "
                         "part would be dropped)")
    if kind in "mM":
        raise ValueError(f"{name} must be real numbers, not datetime/timedelta values")
    if kind == "f" and arr.dtype.itemsize < 4:
        raise ValueError(f"{name}: float16 keeps about 3 digits; convert to float64 first")
    if kind == "O":   # (astype would turn None into NaN and complex into an error)
        if arr.ndim == 0 and not _is_real(arr.item()):
            # not an array at all: None, a generator, a dict (QA25 F5: "must hold real
            # numbers only" named neither what was given nor what is wanted)
            raise ValueError(_not_an_array(a, name))
        bad = next((i for i, v in enumerate(arr.flat) if not _is_real(v)), None)
        if bad is not None:
            where = np.unravel_index(bad, arr.shape)
            v = arr.flat[bad]
            raise ValueError(f"{name} must hold real numbers only: element {tuple(map(int, where))} "
                             f"is {type(v).__name__} {_shown(v)}")
        try:
            arr = arr.astype(np.float64)
        except (TypeError, ValueError, OverflowError):
            raise ValueError(f"{name} must hold real numbers only") from None
    elif kind not in "fiu":
        raise ValueError(f"{name} must be real numbers, got dtype {arr.dtype}")
    return np.ascontiguousarray(arr, dtype=np.float64)


def _shown(v) -> str:
    """A value in a message: its repr, cut to 60 characters."""
    r = repr(v)
    return r if len(r) <= 60 else r[:57] + "..."


def _not_an_array(a, name: str) -> str:
    """The words for ``a`` given where an array of real numbers is wanted, naming its type
    (an iterator / generator: numpy cannot read it; list() it first)."""
    said = f"{name} must be an array of real numbers (for points (n, 2): a numpy array or a " \
           f"list of (x, y) pairs), got {type(a).__name__}"
    if a is None:
        return said + " (None)"
    if hasattr(a, "__next__") or isinstance(a, (range, set, frozenset)) or \
            (hasattr(a, "__iter__") and not hasattr(a, "__len__")):
        return said + ": an iterator numpy cannot read as one; pass list(...) of it"
    return said + f" {_shown(a)}"


def as_point_array(a, name: str = "points", dim: Optional[int] = None) -> np.ndarray:
    """:func:`as_real_array` of points: every public function taking points converts them
    here (or in :func:`as_points`). A table with named columns (a DataFrame, a structured
    array) gives its x, y (and z: ``dim`` 3, or None when present) by name, as the command
    line reads a header (_columns.py)."""
    if type(a) is not np.ndarray or a.dtype.names:
        a = table_points(a, name, dim)
    return as_real_array(a, name)


def transpose_hint(shape, dims=(2,)) -> str:
    """The advice for coordinates given as rows ((2, n) for (n, 2): el.fit((x, y)), QA19
    P1); never applied silently (n = 2 is ambiguous); '' for any other shape."""
    if len(shape) != 2 or shape[0] not in dims or shape[1] in dims:
        return ""
    return f" (pass np.column_stack(({', '.join('xyz'[:shape[0]])})), or points.T)"


def as_points(a, name: str = "points", dim: Optional[int] = 2, min_rows: int = 0) -> np.ndarray:
    """A C-contiguous float64 (n, dim) array (no copy when it already is one);
    dim None: any number of columns >= 1; at least ``min_rows`` rows, all finite.
    Tables are read by their columns' names (:func:`as_point_array`)."""
    return checked_points(as_point_array(a, name, dim), name, dim, min_rows)


def checked_points(arr: np.ndarray, name: str = "points", dim: Optional[int] = 2,
                   min_rows: int = 0) -> np.ndarray:
    """:func:`as_points`'s checks (shape, rows, finite) of an array :func:`as_point_array`
    has already converted (el.fit's, which converts before it looks at the columns): the
    conversion not made twice."""
    if arr.ndim != 2 or (dim is not None and arr.shape[1] != dim) or arr.shape[1] < 1:
        want = f"(n, {dim})" if dim is not None else "(n, dim)"
        raise ValueError(f"{name} must have shape {want}, got {arr.shape}"
                         f"{transpose_hint(arr.shape, (dim,))}")
    if len(arr) < min_rows:
        raise invalid(f"{name}: need at least {min_rows} points, got {len(arr)}")
    # (the C library's EL_EINVAL, with the row named) .all(), not np.all: its Python
    # wrapper cost a third of the check on el.fit's 1000 points
    if not np.isfinite(arr).all():
        i, j = (int(v) for v in np.argwhere(~np.isfinite(arr))[0])
        raise invalid(f"{name} must be finite: point {i} has {float(arr[i, j])} in column {j}")
    return arr


def as_vector(a, name: str = "values", finite: bool = False) -> np.ndarray:
    """A C-contiguous float64 1-D array (a scalar becomes length 1); finite=True refuses
    NaN/inf naming the first such entry."""
    arr = as_real_array(a, name)
    if arr.ndim == 0:
        arr = arr.reshape(1)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, got shape {arr.shape}")
    if finite and not np.all(np.isfinite(arr)):
        i = int(np.argmax(~np.isfinite(arr)))
        raise invalid(f"{name}[{i}] must be finite, got {float(arr[i])}")
    return arr


def as_real(x, name: str, *, finite: bool = True) -> float:
    """A Python float from a real scalar (int, float, numpy real, Fraction, Decimal,
    a 0-d array); ValueError for complex, bool, strings, None, arrays of size > 1,
    and (finite=True) NaN/inf or an int too large for a double."""
    if type(x) is float:   # the common case, fast
        if finite and not math.isfinite(x):
            raise invalid(f"{name} must be finite, got {x!r}")
        return x
    if isinstance(x, np.ndarray):
        if x.ndim != 0:
            raise ValueError(f"{name} must be a number, got an array of shape {x.shape}")
        x = x[()]
    if isinstance(x, (bool, np.bool_, str, bytes)) or x is None:
        raise ValueError(f"{name} must be a real number, got {x!r}")
    if isinstance(x, numbers.Complex) and not isinstance(x, numbers.Real):
        raise ValueError(f"{name} must be real, got the complex {x!r}")
    try:
        v = float(x)
    except (TypeError, ValueError, OverflowError):
        raise ValueError(f"{name} must be a real number, got {x!r}") from None
    if finite and not math.isfinite(v):
        raise invalid(f"{name} must be finite, got {v}")
    return v


def as_int(x, name: str, lo: Optional[int] = INT_MIN, hi: Optional[int] = INT_MAX) -> int:
    """A Python int from an integral number (int, numpy integer, or a float with
    an integral value) in [lo, hi] (default: C int's range; None: unbounded);
    ValueError otherwise (bool, fractions, strings, out of range)."""
    if isinstance(x, np.ndarray) and x.ndim == 0:
        x = x[()]
    if isinstance(x, (bool, np.bool_)):
        raise ValueError(f"{name} must be an integer, got {x!r}")
    if type(x) is int and (lo is None or x >= lo) and (hi is None or x <= hi):
        return x   # the common case, fast
    if isinstance(x, (int, np.integer)):
        v = int(x)
    elif isinstance(x, (float, np.floating)) and math.isfinite(x) and float(x).is_integer():
        v = int(x)
    else:
        raise ValueError(f"{name} must be an integer, got {x!r}")
    if (lo is not None and v < lo) or (hi is not None and v > hi):
        raise invalid(f"{name} must be {_int_range(lo, hi)}, got {v}")
    return v


def _int_range(lo: Optional[int], hi: Optional[int]) -> str:
    """'3..7', '>= 2' or '<= 5': a C type's own limit is not worth naming."""
    lo = None if lo is not None and lo <= INT_MIN else lo
    hi = None if hi is not None and hi >= INT_MAX else hi
    if lo is not None and hi is not None:
        return f"{lo}..{hi}"
    return f">= {lo}" if lo is not None else f"<= {hi}" if hi is not None else "an integer"


def invalid(message: str) -> ElasticaError:
    """The C library's EL_EINVAL as an exception whose message names the argument, its
    allowed range and the value given (checked in Python before the call)."""
    return ElasticaError(lib.EL_EINVAL, message)


def as_positive(x, name: str, *, zero: bool = False) -> float:
    """as_real for a length, a tolerance, a scale: finite and > 0 (>= 0 with zero=True);
    else ElasticaError (EL_EINVAL) "name must be > 0, got x"."""
    v = as_real(x, name)
    if v < 0 or (v == 0 and not zero):
        raise invalid(f"{name} must be {'>=' if zero else '>'} 0, got {shown(v)}")
    return v


def as_degree(x, name: str) -> int:
    """A B-spline approximation degree: 3..7 (el_smooth_to_bspline's range)."""
    d = as_int(x, name, None, None)
    require(3 <= d <= 7, name, "3..7", d)
    return d


def require(ok: bool, name: str, rule: str, value) -> None:
    """ElasticaError (EL_EINVAL) "name must be <rule>, got value" unless ok: an argument
    checked before the C call, so the message names what the C status cannot."""
    if not ok:
        raise invalid(f"{name} must be {rule}, got {shown(value)}")


def shown(value) -> str:
    """A value as a message shows it: a real number as short as it reads back exactly
    (0, -0.001, 0.30000000000000004), anything else by repr."""
    if not _is_real(value):
        return repr(value)
    v = float(value)
    return f"{v:g}" if float(f"{v:g}") == v or not math.isfinite(v) else repr(v)


def warn_if_degrees(angle: float, name: str, stacklevel: int = 3) -> None:
    """Warn when an angle the binding takes in radians looks like degrees (|angle| > 2 pi:
    the command line's --start-tangent 90 is degrees, fit's constraints radians):
    AngleUnitWarning."""
    if abs(angle) > 2 * math.pi:
        from ._quiet import say
        say(f"{name} = {angle:g}: the binding takes radians (|angle| > 2 pi is "
            f"read modulo 2 pi); degrees? use math.radians({angle:g}) (a continuous "
            "angle past a full turn, as curve.angle gives on a loop, is fine)",
            AngleUnitWarning, stacklevel=stacklevel + 1)


def as_size(x, name: str, lo: int = 0, hi: int = SIZE_MAX) -> int:
    """as_int for a C size_t (a count): in [lo, hi]."""
    return as_int(x, name, lo, hi)


def dptr(arr: np.ndarray):
    """`double *` into a C-contiguous float64 numpy array, without a copy."""
    return ffi.cast("double *", ffi.from_buffer(arr))


def bspline_from_c(b) -> "BSpline":
    """Copy a filled el_bspline into a Python BSpline and free the C arrays."""
    from .bspline import BSpline
    try:
        poles = np.frombuffer(ffi.buffer(b.poles, 8 * b.dim * b.npoles), dtype=np.float64)
        knots = np.frombuffer(ffi.buffer(b.knots, 8 * b.nknots), dtype=np.float64)
        mults = np.array([b.mults[i] for i in range(b.nknots)], dtype=np.int64)
        return BSpline(degree=int(b.degree), poles=poles.reshape(-1, b.dim).copy(),
                       knots=knots.copy(), mults=mults, max_deviation=float(b.max_deviation))
    finally:
        lib.el_bspline_free(b)
