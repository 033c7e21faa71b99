"""el.fit's checks of its points that need the C status first (off the common path): why a
fit returned EL_EDOM / EL_EINVAL for input it accepted, the point, column and value named;
its count of the points, repeats counted once (:func:`require_distinct`); and the values of
its constraints (pairs, numbers: fit._set_constraints)."""
from __future__ import annotations

import numbers

import numpy as np

from ._ffi import DomainError, as_real, invalid, lib

__all__ = []

# el_fit_smooth / el_fit_discrete (include/elastica.h) cover data whose extent lies within
# ~1e-150 .. 1e150 (their mu ~ 1 / extent^2 must stay a normal double)
EXTENT_LO, EXTENT_HI = 1e-150, 1e150


# points nearer than this many units in the last place of the points' largest coordinate
# are one point to the fit (QA revD: [0, 0], [1, 1], [1, 1 + 2 eps], [1 + 2 eps, 1] passed
# as 4 distinct points and "fitted" a curve of rms 9e-16 through 2)
ROUNDING_ULPS = 16
# a refusal names at most this many of each point's repeats (QA revD: 100 000 rows of two
# points alternating made a message of 689 000 characters)
SAID_REPEATS = 8


def _runs(idx) -> str:
    """'2 to 4', '2, 4', '3' of ascending indices (a run of 3 or more as 'a to b'); past
    SAID_REPEATS items, '..., N in all'."""
    out, i = [], 0
    while i < len(idx) and len(out) < SAID_REPEATS:
        j = i
        while j + 1 < len(idx) and idx[j + 1] == idx[j] + 1:
            j += 1
        out += [f"{idx[i]} to {idx[j]}"] if j - i >= 2 else [str(v) for v in idx[i:j + 1]]
        i = j + 1
    if i < len(idx) or len(out) > SAID_REPEATS:
        return ", ".join(out[:SAID_REPEATS]) + f", ... ({len(idx)} in all)"
    return ", ".join(out)


def _distinct(x, y, tol: float, need: int, owner=None) -> list:
    """The first index of each of up to ``need`` points of (x, y) more than ``tol`` apart
    (in x or in y) from every earlier one; ``owner`` (optional, filled) gives each row the
    first index it repeats."""
    firsts, new = [], np.ones(len(x), dtype=bool)
    while len(firsts) < need and new.any():
        i = int(np.argmax(new))
        firsts.append(i)
        near = (np.abs(x - x[i]) <= tol) & (np.abs(y - y[i]) <= tol)
        if owner is not None:
            owner[new & near] = i
        new &= ~near
    return firsts


def require_distinct(pts: np.ndarray, name: str = "fit", need: int = 4) -> None:
    """ValueError where ``pts`` (n, 2) hold fewer than ``need`` points, or 2 .. need - 1
    distinct ones in more rows, naming the repeats (QA qapy F6: [[0, 0]] + 4 x [[1, 1]] said
    only "singular or degenerate input", [0, 0], [1, 1] alternating "fitted" a curve of rms
    4e-14): "only 2 distinct points (points 2 to 4 repeat point 1, (1, 1)): need at least 4".
    Points within ROUNDING_ULPS units in the last place of the largest coordinate of each
    other are one (equal to rounding: no curve can be told from them). All points equal is
    :func:`fit`'s SingularError (they name no curve at all). ``name``: the caller's, before
    the message. One pass for the points' size, then none where the first 4 (or 64) rows
    hold ``need`` distinct points, else at most ``need`` passes. Not el_fit_distinct's rule
    (a run of *consecutive* repeats within 1e-12 of the rms radius, kept once for the noise
    figure): this one counts *any* earlier equal point, so rows alternating between two
    points are 2 distinct points, not n."""
    n = len(pts)
    if n < need:
        raise ValueError(f"{name}: need at least {need} points, got {n}")
    tol = ROUNDING_ULPS * np.spacing(max(float(pts.max()), -float(pts.min())))
    head = pts[:need].tolist()
    if all(abs(p[0] - q[0]) > tol or abs(p[1] - q[1]) > tol
           for a, p in enumerate(head) for q in head[a + 1:]):     # (almost any data)
        return
    x, y = pts[:, 0], pts[:, 1]     # (columns apart: np.any(axis=1) of (n, 2) is 10 x slower)
    if len(_distinct(x[:64], y[:64], tol, need)) == need:
        return
    owner = np.full(n, -1)
    firsts = _distinct(x, y, tol, need, owner)
    if len(firsts) == need or len(firsts) == 1:
        return
    said, rounded = [], False
    for i in firsts:
        rep = np.flatnonzero(owner == i)[1:]
        rounded = rounded or bool(np.any((x[rep] != x[i]) | (y[rep] != y[i])))
        if len(rep):
            said.append(f"point{'s' * (len(rep) > 1)} {_runs(rep.tolist())} "
                        f"repeat{'s' * (len(rep) == 1)} point {i}, "
                        f"({pts[i, 0]:.10g}, {pts[i, 1]:.10g})")
    how = f"; equal to rounding, within {tol:.3g}" if rounded else ""
    raise ValueError(f"{name}: only {len(firsts)} distinct points in {n} ({'; '.join(said)}"
                     f"{how}): need at least {need}")


def explain_input_status(st: int, pts: np.ndarray, name: str = "fit") -> None:
    """Raise the error that says why ``st`` (EL_EINVAL / EL_EDOM from the C fit) came of
    ``pts`` (n, 2), when the points are the cause: a NaN / inf (point, column, value), or an
    extent outside EXTENT_LO .. EXTENT_HI (the point farthest from the median, its column and
    value, the extent and the range: QA25 F5, a 1e308 coordinate said only "input outside
    the domain the method covers"); else return (another cause: the caller's words)."""
    if st not in (lib.EL_EINVAL, lib.EL_EDOM):
        return
    if not np.isfinite(pts).all():
        i, j = (int(v) for v in np.argwhere(~np.isfinite(pts))[0])
        raise invalid(f"{name}: points must be finite: point {i} has {float(pts[i, j])} in "
                      f"column {j}")
    with np.errstate(over="ignore", invalid="ignore"):
        span = np.ptp(pts, axis=0)
        extent = float(np.max(span))
        if EXTENT_LO <= extent <= EXTENT_HI or extent == 0.0:
            return
        far = np.abs(pts - np.median(pts, axis=0))
    i, j = (int(v) for v in np.unravel_index(int(np.argmax(far)), far.shape))
    if extent > EXTENT_HI:
        raise DomainError(st, (
            f"{name}: the points span {extent:.3g} (column {int(np.argmax(span))}), more than "
            f"the {EXTENT_HI:g} the fit covers (its data extent within ~{EXTENT_LO:g} .. "
            f"{EXTENT_HI:g}): point {i} has {float(pts[i, j]):.17g} in column {j}, the "
            "farthest from the points' median; drop it if it is a stray, or scale the points "
            "(the fit is unit-equivariant)"))
    raise DomainError(st, (
        f"{name}: the points span only {extent:.3g}, less than the {EXTENT_LO:g} the fit "
        f"covers (its data extent within ~{EXTENT_LO:g} .. {EXTENT_HI:g}): scale them, e.g. "
        "points / np.ptp(points) (the fit is unit-equivariant)"))


# fit's constraint values (fit._set_constraints)
def _pair(value, name: str):
    try:
        a, b = (as_real(v, name, finite=False) if v is not None else None for v in value)
    except (TypeError, ValueError):
        raise ValueError(f"fit: constraint {name!r} must be a pair, got {value!r}") from None
    return a, b


def _is_number(value) -> bool:
    """A real number (Python's or numpy's, a 0-d array), not a pair."""
    return (isinstance(value, numbers.Real) and not isinstance(value, bool)) or \
        (isinstance(value, np.ndarray) and value.ndim == 0)
