"""el.fit's checks of its points that need the C status first (off the common path): why a
fit returned EL_EDOM / EL_EINVAL for input it accepted, the point, column and value named;
and its count of the points, repeats counted once (:func:`require_distinct`)."""
from __future__ import annotations

import numpy as np

from ._ffi import DomainError, invalid, lib

__all__ = []

# el_fit_smooth / el_fit_discrete (include/elastica.h) cover data whose extent lies within
# ~1e-150 .. 1e150 (their mu ~ 1 / extent^2 must stay a normal double)
EXTENT_LO, EXTENT_HI = 1e-150, 1e150


def _runs(idx) -> str:
    """'2 to 4', '2, 4', '3' of ascending indices (a run of 3 or more as 'a to b')."""
    out, i = [], 0
    while i < len(idx):
        j = i
        while j + 1 < len(idx) and idx[j + 1] == idx[j] + 1:
            j += 1
        out += [f"{idx[i]} to {idx[j]}"] if j - i >= 2 else [str(v) for v in idx[i:j + 1]]
        i = j + 1
    return ", ".join(out)


def require_distinct(pts: np.ndarray, name: str = "fit", need: int = 4) -> None:
    """ValueError where ``pts`` (n, 2) hold fewer than ``need`` points, or 2 .. need - 1
    distinct ones in more rows, naming the repeats (QA qapy F6: [[0, 0]] + 4 x [[1, 1]] said
    only "singular or degenerate input", [0, 0], [1, 1] alternating "fitted" a curve of rms
    4e-14): "only 2 distinct points (points 2 to 4 repeat point 1, (1, 1)): need at least 4".
    All points equal is :func:`fit`'s SingularError (they name no curve at all). ``name``:
    the caller's, before the message. At most ``need`` passes over the points (none where
    the first 64 rows hold ``need`` distinct ones)."""
    n = len(pts)
    if n < need:
        raise ValueError(f"{name}: need at least {need} points, got {n}")
    if len({tuple(p) for p in pts[:need].tolist()}) == need or \
            len({tuple(p) for p in pts[:64].tolist()}) >= need:    # (almost any data: ~2 us)
        return
    x, y = pts[:, 0], pts[:, 1]     # (columns apart: np.any(axis=1) of (n, 2) is 10 x slower)
    firsts, new = [], np.ones(n, dtype=bool)
    while len(firsts) < need and new.any():
        i = int(np.argmax(new))
        firsts.append(i)
        new &= (x != x[i]) | (y != y[i])
    if len(firsts) == need or len(firsts) == 1:
        return
    said = []
    for i in firsts:
        rep = np.flatnonzero((x == x[i]) & (y == y[i]))[1:].tolist()
        if rep:
            said.append(f"point{'s' * (len(rep) > 1)} {_runs(rep)} repeat{'s' * (len(rep) == 1)}"
                        f" point {i}, ({pts[i, 0]:.10g}, {pts[i, 1]:.10g})")
    raise ValueError(f"{name}: only {len(firsts)} distinct points in {n} ({'; '.join(said)}): "
                     f"need at least {need}")


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
