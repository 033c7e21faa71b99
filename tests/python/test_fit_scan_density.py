"""Scanner-density points (QA23 F5): a profile scanned from above has its points dense where
it is flat and sparse where it is steep (here density ~ max(|cos theta|, 0.08): spacing
1:12 between points, 1:2 between the means of 32 blocks of them), far closer than their
noise where dense. Such points are not evenly spaced, yet both tests of even spacing took
them for it: the smooth fit's fractions (el_fit_fractions, param "auto") came out uniform,
7.7 % of the length off, and its paired start crawled 200 iterations to a curve far from the
points before the fit by distance crawled 200 more (234 in all against 4 for evenly spaced
points, 0.9 s for 20 000 points); the discrete model paired the points with its vertices,
five guesses crawling 163-200 iterations each (927). Iteration counts here, not times."""
import numpy as np
import pytest

import libelastica as el

OFFSET = np.array([4.0e5, 5.6e6])      # a scan's coordinates, far from the origin


def _curve():
    return el.SmoothElastica(x0=0.0, y0=0.0, phi=-0.3, mu=(2.2 / 350.0) ** 2, k=0.6, q=0.4,
                             length=350.0)


def _scan(n, noise, seed=1):
    """n points of _curve() at arc lengths of density max(|cos theta|, 0.08) (uniform draws
    sorted, the ends kept), noise along y (the beam), at OFFSET; and their arc lengths."""
    c = _curve()
    s = np.linspace(0.0, c.length, 20001)
    w = np.maximum(np.abs(np.cos(c.angle(s))), 0.08)
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (w[1:] + w[:-1]) * np.diff(s))])
    rng = np.random.default_rng(seed)
    u = np.sort(rng.uniform(0.0, 1.0, n))
    u[0], u[-1] = 0.0, 1.0
    si = np.interp(u, cdf / cdf[-1], s)
    P = c.points(si)
    P[:, 1] += rng.normal(0.0, noise, n)
    return P + OFFSET, si


def _true_rms(P, si):
    """rms distance of the points P (at OFFSET) to _curve(), by Newton's method for each
    foot from the arc length the point was taken at (own measure, not the fit's)."""
    c, Q = _curve(), P - OFFSET
    s = si.copy()
    for _ in range(8):
        th = c.angle(s)
        d = Q - c.points(s)
        s = np.clip(s + d[:, 0] * np.cos(th) + d[:, 1] * np.sin(th), 0.0, c.length)
    return float(np.sqrt(np.mean(np.sum((Q - c.points(s)) ** 2, axis=1))))


@pytest.mark.parametrize("n, noise", [(2000, 0.0), (2000, 0.2), (20000, 0.2)])
def test_scan_fractions_are_chord_fractions(n, noise):
    """param "auto" takes the scan for what it is (chord fractions, measured along the means of
    its blocks where its points are closer than their noise): within 1 % of the length of
    the points' own arc lengths (uniform ones: 7.7 % off)."""
    P, si = _scan(n, noise)
    r = el.fit(P, model="smooth")
    assert r.param_mode == "chord"
    # the paired fit's fractions (the first start of the orthogonal fit)
    p = el.fit(P, model="smooth", distance="paired")
    t = p.foot_s / p.curve.length
    assert np.max(np.abs(t - si / _curve().length)) < 0.01


def test_evenly_spaced_noisy_points_stay_uniform():
    """The same curve at equal steps, noise 0.2: still uniform fractions."""
    c = _curve()
    rng = np.random.default_rng(1)
    P = c.points(np.linspace(0.0, c.length, 2000)) + rng.normal(0.0, 0.2 / np.sqrt(2.0), (2000, 2))
    assert el.fit(P + OFFSET, model="smooth").param_mode == "uniform"


@pytest.mark.parametrize("n, noise", [(2000, 0.0), (2000, 0.2), (20000, 0.2)])
def test_smooth_fit_of_a_scan_takes_few_iterations(n, noise):
    """As few iterations as evenly spaced points take (4-5): at most 20 (were 338, 511, 234),
    and the fit at least as close as the curve the points were taken from."""
    P, si = _scan(n, noise)
    r = el.fit(P, model="smooth")
    assert r.status == 0
    assert r.iterations <= 20
    true_rms = _true_rms(P, si)
    assert r.rms <= true_rms * (1.0 + 1e-9) + 1e-9 * _curve().length


def test_discrete_fit_of_a_dense_noisy_scan_is_by_distance():
    """20 000 points closer than their noise: fitted by distance from the start, at most 60
    iterations (were 927), as close as the curve they were taken from."""
    P, si = _scan(20000, 0.2)
    r = el.fit(P, model="discrete")
    assert r.status == 0
    assert r.iterations <= 60
    true_rms = _true_rms(P, si)
    assert r.rms <= true_rms * (1.0 + 1e-9)


@pytest.mark.parametrize("n, step", [(5000, 0.01), (20000, 0.0018)])
def test_evenly_spaced_points_far_closer_than_their_noise_stay_paired(n, step):
    """Points at equal steps 20-110 x closer than their noise (0.2) are what the discrete
    model's pairing (seed 000 (4.6)) is for: the chords of w = (n-1)/16 points vary by the
    noise nu each, their extremes over n runs by ~ sqrt(2 ln n) nu each way, beyond the 4 nu
    5cee373 allowed: 20 000 such points (5000) were fitted by distance 20 (7) of 20 times (33
    iterations, 6 x the CPU), paired before it (2). Over 5 seeds, all paired."""
    for seed in range(5):
        rng = np.random.default_rng(seed)
        s = np.arange(n) * step
        R = 50.0
        P = np.c_[R * np.sin(s / R), R * (1.0 - np.cos(s / R))]
        P = P + rng.normal(0.0, 0.2 / np.sqrt(2.0), P.shape) + OFFSET
        r = el.fit(P, model="discrete")
        assert r.status == 0
        assert r.distance == "paired", (seed, r.distance, r.iterations)
