"""el.fit's checks of its points that need the C status first (off the common path): why a
fit returned EL_EDOM / EL_EINVAL for input it accepted, the point, column and value named."""
from __future__ import annotations

import numpy as np

from ._ffi import DomainError, invalid, lib

__all__ = []

# el_fit_smooth / el_fit_discrete (include/elastica.h) cover data whose extent lies within
# ~1e-150 .. 1e150 (their mu ~ 1 / extent^2 must stay a normal double)
EXTENT_LO, EXTENT_HI = 1e-150, 1e150


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
