"""Private: load libelastica's shared library with cffi (ABI mode).

The declarations come from the one public header, include/elastica.h, with its
preprocessor lines removed, so they are never retyped by hand. The header is
found next to this package (installed copy) or in the source tree; the
library through LIBELASTICA_PATH, a bundled copy, the source tree's build/,
or the system loader (pkg-config install).
"""
from __future__ import annotations

import os
import re
from pathlib import Path

import numpy as np
from cffi import FFI

_HERE = Path(__file__).resolve().parent
_SRC_ROOT = _HERE.parent.parent


def _find(candidates):
    for c in candidates:
        if c and Path(c).is_file():
            return str(c)
    return None


def _header_text() -> str:
    path = _find([_HERE / "elastica.h", _SRC_ROOT / "include" / "elastica.h",
                  "/usr/local/include/elastica.h", "/usr/include/elastica.h"])
    if path is None:
        raise ImportError("libelastica: elastica.h not found (reinstall the package)")
    text = Path(path).read_text()
    text = re.sub(r"#ifdef __cplusplus.*?#endif", "", text, flags=re.S)
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("#"))


def _load(ffi: FFI):
    env = os.environ.get("LIBELASTICA_PATH")
    if env and not Path(env).is_file():
        raise ImportError(f"libelastica: LIBELASTICA_PATH={env} is not a file")
    path = env or _find([_HERE / "libelastica.so", _SRC_ROOT / "build" / "libelastica.so"])
    try:
        return ffi.dlopen(path or "libelastica.so.0")
    except OSError as exc:
        raise ImportError(
            "libelastica: the C library was not found; build it with `make` in the "
            "source tree, set LIBELASTICA_PATH, or `make install`") from exc


ffi = FFI()
ffi.cdef(_header_text())
lib = _load(ffi)


class ElasticaError(ValueError):
    """A libelastica call failed; ``status`` is the C status code."""

    def __init__(self, status: int, message: str):
        super().__init__(message)
        self.status = status


class NotConvergedError(ElasticaError):
    """An iteration stopped before converging (EL_ENOCONV / EL_EMAXITER)."""


class DomainError(ElasticaError):
    """Valid input outside what the method covers (EL_EDOM)."""


class SingularError(ElasticaError):
    """Degenerate input: collinear or coincident data, singular systems (EL_ESINGULAR)."""


_ERRORS = {lib.EL_ENOCONV: NotConvergedError, lib.EL_EMAXITER: NotConvergedError,
           lib.EL_EDOM: DomainError, lib.EL_ESINGULAR: SingularError}


def check(status: int, what: str = "") -> None:
    """Raise the exception that matches a C status (pynacl's `ensure` pattern)."""
    if status != lib.EL_OK:
        msg = ffi.string(lib.el_strerror(status)).decode()
        raise _ERRORS.get(status, ElasticaError)(status, f"{what}: {msg}" if what else msg)


def as_points(a, name: str = "points", dim: int = 2) -> np.ndarray:
    """A C-contiguous float64 (n, dim) array (no copy when it already is one)."""
    arr = np.ascontiguousarray(a, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != dim:
        raise ValueError(f"{name} must have shape (n, {dim}), got {arr.shape}")
    return arr


def as_vector(a, name: str = "values") -> np.ndarray:
    """A C-contiguous float64 1-D array (a scalar becomes length 1)."""
    arr = np.ascontiguousarray(np.atleast_1d(a), dtype=np.float64)
    if arr.ndim != 1:
        raise ValueError(f"{name} must be one-dimensional, got shape {arr.shape}")
    return arr


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
