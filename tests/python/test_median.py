"""_median.median, far_points' typical distance (every el.fit's outlier test): np.median's
value bit for bit and its warnings, on odd, even, empty and NaN inputs, ties, signed zeros,
infinities and the distances of a noisy scan's fit."""
from __future__ import annotations

import math
import warnings

import numpy as np

import libelastica as el
from libelastica._median import median


def _same(a: np.ndarray) -> None:
    with warnings.catch_warnings(record=True) as want_said:
        warnings.simplefilter("always")
        want = float(np.median(a))
    with warnings.catch_warnings(record=True) as got_said:
        warnings.simplefilter("always")
        got = median(a)
    assert type(got) is float
    assert (math.isnan(want) and math.isnan(got)) or \
        np.float64(got).tobytes() == np.float64(want).tobytes(), (a, want, got)
    assert [(w.category, str(w.message)) for w in got_said] == \
        [(w.category, str(w.message)) for w in want_said], a


def test_median_is_np_median_on_odd_even_empty_and_nan():
    for a in ([], [3.0], [2.0, 1.0], [5.0, 1.0, 4.0], [4.0, 1.0, 3.0, 2.0], [np.nan], [1.0, np.nan],
              [1.0, np.nan, 2.0], [np.nan, np.nan, 0.5, 7.0], [-0.0], [-0.0, -0.0], [0.0, -0.0, 1.0, -1.0],
              [np.inf, 1.0], [-np.inf, np.inf], [np.inf, np.inf, 1.0, 2.0], [1e308, 1e308], [2.0, 2.0, 2.0, 2.0]):
        _same(np.array(a, dtype=float))


def test_median_is_np_median_on_random_arrays():
    rng = np.random.default_rng(16)
    for _ in range(3000):
        n = int(rng.integers(0, 60))
        a = rng.normal(size=n) * 10.0 ** int(rng.integers(-300, 300))
        if rng.random() < 0.3:
            a = np.round(a)                             # ties
        if rng.random() < 0.3:
            a = np.where(a == 0.0, -0.0, a)             # signed zeros
        for _ in range(int(rng.integers(0, 3))):
            if n and rng.random() < 0.15:
                a[rng.integers(0, n)] = rng.choice([np.inf, -np.inf, np.nan])
        _same(a)


def test_median_of_a_fit_s_distances():
    rng = np.random.default_rng(3)
    s = np.sort(rng.uniform(0.0, 6.0, 1001))           # uneven spacing, far from the origin
    pts = np.column_stack([1e4 + s, -3e3 + np.sin(s)]) + rng.normal(0.0, 0.01, (1001, 2))
    d = np.abs(el.fit(pts).distances)
    _same(d)
    _same(d[:-1])
