"""np.median of a 1-D float64 array by one np.partition call: the value and the warnings
np.median gives, without its Python layers (_ureduce, _median, mean, its NaN check) and its
partition at two places, which made the median 0.128 M of the 0.156 M instructions of
el.fit's outlier test (far_points, every fit) on a 1000-point fit's distances; with this
module far_points takes 0.094 M (callgrind), and a median ~19 us against np.median's 60.
"""
from __future__ import annotations

import math

import numpy as np

__all__ = ["median"]


def median(a: np.ndarray) -> float:
    """float(np.median(a)) of a 1-D float64 array: its middle value, or the mean of its two
    middle values ((0.0 + lo + hi) / 2, as np.mean takes two: their sum from 0.0, over 2),
    from np.partition at the upper middle place alone (with a second place, np.median's own
    call, it took twice as long), the lower one the largest below it; a NaN, which
    np.partition puts last, is found as the maximum above that place. np.median itself where
    a is empty, holds a NaN or the two middle values sum to no finite number (inf, inf -
    inf): its result and warnings ("Mean of empty slice", "invalid value"), as they are."""
    n = a.shape[0]
    if n == 0:
        return float(np.median(a))
    k = n // 2
    p = np.partition(a, k)
    if math.isnan(p[k:].max()):
        return float(np.median(a))
    if n % 2:
        return 0.0 + float(p[k])        # (np.mean's sum starts at 0.0: -0.0 gives 0.0)
    mid = 0.0 + float(p[:k].max()) + float(p[k])
    return mid / 2.0 if math.isfinite(mid) else float(np.median(a))
