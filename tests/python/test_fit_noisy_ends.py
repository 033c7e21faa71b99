"""Noisy end points (QA25 F1): scans and sketches whose first and last points carry the same
noise as the rest, unevenly spaced (steps varying 5x), both models, far from the origin too.
The fit by distance ties its first and last points to its ends (the smooth curve ends at their
feet; the polygon's end vertices at the points): QA read its length as ~1.2 % short and its
rms as worse than the truth's. Measured (/tmp/fitends sweep, 360 fits, noise 0.1-1 % of the
length): the fit's point-to-curve rms below the truth's on the same points in 359 (the one
above by 0.05 %), the length unbiased (mean error -0.10 .. +0.44 noise rms, spread one noise
rms: the end points' own tangential noise), the ends within ~1 noise rms of the truth's;
fitting with the ends free instead (the curve cut to all its feet) bends and stretches the
ends (length +2.8 % / +19 % mean on scans / sketches). This pins the tie's behaviour: per
draw the rms at most the truth's (+0.2 %), length and end errors within 3 noise rms, over the
draws a length error without bias, and the same fit at every offset."""
import warnings

import numpy as np
import pytest
from scipy.special import ellipk

import libelastica as el
from fit_data import curve_distances

OFFSETS = ((0.0, 0.0), (1500.0, -800.0), (5e5, 5e6))


def noisy_draw(seed, kind):
    """A 100-long elastica (k 0.2-3, 0.3-1.2 half periods), its points at steps varying 5x
    (random or along a sine), isotropic noise of rms sigma on every point, the ends too:
    scan 60-300 points at 0.1-1 %, sketch 8-40 points at 0.2-1 %. (truth, points, sigma)."""
    rng = np.random.default_rng(seed)
    k = float(np.exp(rng.uniform(np.log(0.2), np.log(3.0))))
    half = 2 * ellipk(k * k) if k < 1 else 2 * ellipk(1 / k ** 2) / k
    span = rng.uniform(0.3, 1.2) * half
    truth = el.SmoothElastica(x0=0, y0=0, phi=rng.uniform(-np.pi, np.pi), mu=(span / 100.0) ** 2,
                              k=k, q=rng.uniform(-2, 2), length=100.0)
    lo, hi, nlo = (60, 300, 1e-3) if kind == "scan" else (8, 41, 2e-3)
    n = int(rng.integers(lo, hi))
    sigma = rng.uniform(nlo, 1e-2) * truth.length
    w = rng.uniform(1, 5, n - 1)
    if rng.random() < 0.5:
        w = 1 + 4 * (0.5 + 0.5 * np.sin(np.linspace(0, rng.uniform(2, 8), n - 1) + rng.uniform(0, 6)))
    s = np.concatenate([[0.0], np.cumsum(w)])
    P = truth.points(s * truth.length / s[-1]) + rng.normal(0, sigma / np.sqrt(2), (n, 2))
    return truth, np.ascontiguousarray(P), sigma


def measured(truth, P, model, off=(0.0, 0.0)):
    """(fit rms, truth rms, length error, larger end error) on the user's points, the fit's
    distances to its curve or polygon measured independently (fit_data.curve_distances)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = el.fit(P + np.asarray(off), model=model)
    assert r.status == 0
    c = r.curve
    d = curve_distances(c, P + np.asarray(off))[0]
    t = curve_distances(truth, P)[0]
    if model == "smooth":
        ends, length = c.points(np.array([0.0, c.length])), c.length
    else:
        V = c.points()
        ends, length = V[[0, -1]], float(np.sum(np.linalg.norm(np.diff(V, axis=0), axis=1)))
    ends = ends - np.asarray(off)
    true_ends = truth.points(np.array([0.0, truth.length]))
    e = min(np.max(np.linalg.norm(ends - true_ends, axis=1)),
            np.max(np.linalg.norm(ends[::-1] - true_ends, axis=1)))
    rms = lambda x: float(np.sqrt(np.mean(x ** 2)))
    return rms(d), rms(t), length - truth.length, float(e)


@pytest.mark.c_numerics
def test_noisy_ends_fit_is_at_least_the_truth():
    """Ten draws of each kind and model: each fit's rms at most 1.002 x the truth's (a smooth
    scan whose end point's noise put it 1.2 noise rms inside, two points' feet held at that end,
    below fit_ends.h's PILE_LEAST: 1.0014 x), its length and ends within 3 noise rms of the
    truth's; the forty length errors without bias (their mean within 0.5 noise rms: QA's
    ~1.2 % short was about one noise rms)."""
    lengths = []
    for kind in ("scan", "sketch"):
        for model in ("smooth", "discrete"):
            for seed in range(10):
                truth, P, sigma = noisy_draw(1000 * (kind == "scan") + seed, kind)
                fit, true, dl, e = measured(truth, P, model)
                assert fit <= 1.002 * true, (kind, model, seed, fit / true)
                assert abs(dl) <= 3 * sigma, (kind, model, seed, dl / sigma)
                assert e <= 3 * sigma, (kind, model, seed, e / sigma)
                lengths.append(dl / sigma)
    assert abs(np.mean(lengths)) <= 0.5, np.round(lengths, 2)


@pytest.mark.c_numerics
@pytest.mark.parametrize("model", ["smooth", "discrete"])
@pytest.mark.parametrize("kind", ["scan", "sketch"])
def test_noisy_ends_same_fit_far_from_the_origin(kind, model):
    truth, P, sigma = noisy_draw(77 + (kind == "scan"), kind)
    near = measured(truth, P, model)
    for off in OFFSETS[1:]:
        far = measured(truth, P, model, off)
        np.testing.assert_allclose(far[:2], near[:2], rtol=1e-6)
        np.testing.assert_allclose(far[2:], near[2:], atol=1e-6 * sigma + 1e-9 * np.hypot(*off))
