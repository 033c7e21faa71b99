"""The binding's one foot search (nearest.py: coarse samples, then each foot refined in its
samples' bracket): curve_feet against every point of a dense sampling of the curve (its
plain counterpart), sparse and dense coarse samples, k across 1, extreme scales and
offsets; refine_feet never moves a foot farther, and ends on the foot it brackets."""
import numpy as np
import pytest

import libelastica as el
from libelastica.nearest import bspline_at, curve_at, curve_feet, refine_feet

DENSE = 20001


def _dense(c, q):
    """Each point's distance to the nearest of DENSE samples (an upper bound of the true
    one, above it by at most the samples' sagitta) and that sample's s."""
    s = np.linspace(0.0, c.length, DENSE)
    P = c.points(s)
    best, at = np.full(len(q), np.inf), np.zeros(len(q))
    for a in range(0, DENSE, 5000):
        d = np.sqrt(((P[None, a:a + 5000, :] - q[:, None, :]) ** 2).sum(axis=2))
        j = np.argmin(d, axis=1)
        nearer = d[np.arange(len(q)), j] < best
        best[nearer], at[nearer] = d[np.arange(len(q)), j][nearer], s[a + j][nearer]
    return best, at


@pytest.mark.parametrize("k", [0.3, 0.999, 1.0, 1.001, 1.8])
@pytest.mark.parametrize("offset, scale", [(0.0, 1.0), (1e6, 1.0), (-3e8, 1e3), (5.0, 1e-6)])
@pytest.mark.parametrize("coarse", [9, None])
def test_curve_feet_are_the_nearest_points(k, offset, scale, coarse):
    c = el.SmoothElastica(x0=offset, y0=-offset, phi=0.3, mu=2.0 / scale ** 2, k=k, q=0.2,
                          length=4.0 * scale)
    rng = np.random.default_rng(3)
    q = np.vstack([c.points(rng.uniform(0, c.length, 60)) + rng.normal(0, 0.05 * scale, (60, 2)),
                   c.points(np.array([0.0, c.length])),          # on the curve, its ends
                   c.points(np.array([0.0])) + rng.uniform(-3, 3, (30, 2)) * scale])
    samples = None if coarse is None else c.points(np.linspace(0.0, c.length, coarse))
    d, s = curve_feet(c, q, samples)
    dense, _ = _dense(c, q)
    rounding = 1e-13 * (abs(offset) + scale)     # (evaluation: ~1e-14 relative)
    assert np.all((s >= 0.0) & (s <= c.length))
    # the foot is a point of the curve at that distance, and no sample of the curve nearer
    assert np.allclose(np.linalg.norm(c.points(s) - q, axis=1), d, rtol=0, atol=rounding)
    assert np.all(d <= dense + rounding), np.max(d - dense)
    # and the dense samples' nearest is not much farther (no nearer foot missed): a sample
    # within half a step h of the true foot lies at most min(h, h^2 (1 + kappa d) / 2d) farther
    h = 0.5 * c.length / (DENSE - 1)
    kappa = 2.0 * k * np.sqrt(c.mu)
    excess = np.minimum(h, h * h * (1.0 + kappa * d) / (2.0 * np.maximum(d, 1e-300)))
    assert np.all(dense - d <= 1.01 * excess + rounding), np.max(dense - d - excess)


def test_refine_feet_never_moves_a_foot_farther_and_ends_at_the_bracketed_foot():
    # a B-spline and a curve, feet started anywhere in their bracket (the whole domain):
    # the result is at least as near as the start, and its slope (C - p) . C' ~ 0 inside
    c = el.SmoothElastica(x0=1.0, y0=2.0, phi=0.3, mu=1.0, k=1.3, q=0.4, length=6.0)
    b = c.to_bspline(tol=1e-9)
    rng = np.random.default_rng(7)
    q = c.points(rng.uniform(0, c.length, 400)) + rng.normal(0, 0.4, (400, 2))
    for at, (lo, hi) in ((curve_at(c), (0.0, c.length)), (bspline_at(b), b.domain)):
        t0 = rng.uniform(lo, hi, len(q))
        start = np.sum((at(t0) - q) ** 2, axis=1)
        t, P, d2 = refine_feet(at, q, t0, lo, hi)
        assert np.all(d2 <= start)
        assert np.allclose(P, at(t), rtol=0, atol=1e-13) and np.allclose(d2, np.sum((P - q) ** 2, axis=1))
        _, D1, _ = at(t, True)
        slope = np.sum((P - q) * D1, axis=1) / np.linalg.norm(D1, axis=1)
        inside = (t > lo + 1e-9) & (t < hi - 1e-9)
        assert np.all(np.abs(slope[inside]) <= 1e-8 * (1 + np.sqrt(d2[inside]))), \
            np.max(np.abs(slope[inside]))


def _brute_feet(c, q):
    """Each point's distance to a curve by brute force: the nearest of samples no step of
    which turns more than 0.02 rad (max |kappa| x length / 0.02, at least DENSE), refined
    by golden section in that sample's neighbours' bracket."""
    m = max(DENSE, int(np.ceil(c.max_curvature * c.length / 0.02)) + 1)
    s = np.linspace(0.0, c.length, m)
    best, at = np.full(len(q), np.inf), np.zeros(len(q), dtype=int)
    for a in range(0, m, 4000):
        d = ((c.points(s[a:a + 4000])[None] - q[:, None]) ** 2).sum(axis=2)
        j = d.argmin(axis=1)
        nearer = d[np.arange(len(q)), j] < best
        best[nearer], at[nearer] = d[np.arange(len(q)), j][nearer], a + j[nearer]
    lo, hi = s[np.maximum(at - 1, 0)], s[np.minimum(at + 1, m - 1)]

    def f(x):
        return np.linalg.norm(c.points(x) - q, axis=1)
    r = (np.sqrt(5.0) - 1.0) / 2.0
    x1, x2 = hi - r * (hi - lo), lo + r * (hi - lo)
    f1, f2 = f(x1), f(x2)
    for _ in range(80):
        left = f1 <= f2
        hi, lo = np.where(left, x2, hi), np.where(left, lo, x1)
        x1, x2 = np.where(left, hi - r * (hi - lo), x2), np.where(left, x1, lo + r * (hi - lo))
        fx = f(np.where(left, x1, x2))
        f1, f2 = np.where(left, fx, f2), np.where(left, f1, fx)
    return np.minimum(np.sqrt(best), np.minimum(f1, f2))


@pytest.mark.parametrize("k, mu", [(0.9, 400.0), (0.999, 400.0), (1.0, 400.0), (1.001, 400.0),
                                   (1.8, 400.0), (1.8, 1.0), (3.0, 25.0)])
@pytest.mark.parametrize("offset", [0.0, 3e6])
def test_curve_feet_by_default_find_the_feet_of_loops_and_tight_curls(k, mu, offset):
    # curves of length 40 turning up to 19 rad between CURVE_SAMPLES' samples (k across 1,
    # 1.8 at mu = 1: a loop of 11 turns): the default samples follow the turning, so no
    # foot is missed near the curve, across its curls, or far off (before: up to 0.034 too
    # far at k = 0.999, rel. 1.6e-3 of the curve's size)
    c = el.SmoothElastica(x0=offset, y0=-offset, phi=0.3, mu=mu, k=k, q=0.2, length=40.0)
    size = float(np.ptp(c.points(np.linspace(0.0, c.length, 4001)), axis=0).max())
    rng = np.random.default_rng(1)
    q = np.vstack([c.points(rng.uniform(0, c.length, 30)) + rng.normal(0, 0.05 * size, (30, 2)),
                   c.points(rng.uniform(0, c.length, 15)) + rng.normal(0, 3 * size, (15, 2)),
                   c.points(rng.uniform(0, c.length, 5)) + rng.normal(0, 1e3 * size, (5, 2))])
    d, s = curve_feet(c, q)
    rounding = 1e-13 * (abs(offset) + 1e3 * size)
    assert np.allclose(np.linalg.norm(c.points(s) - q, axis=1), d, rtol=0, atol=rounding)
    # never farther than the brute force's (where several passes of a loop lie about as
    # near, it may refine another one's, a little farther)
    brute = _brute_feet(c, q)
    assert np.all(d <= brute + rounding + 1e-12 * size), np.max(d - brute)


@pytest.mark.parametrize("mu", [1e12, 1e20])
def test_curve_feet_default_samples_stay_bounded_on_a_tight_curl(mu):
    # a k ~ 1 elastica of length 1 at mu = 1e12 asked max |kappa| x length / STEP_TURN = 4e6
    # samples (314 MB, 3 s for 3 points), at mu = 1e20 4e10 (its exact max |kappa| listed
    # 1e10 inflections first): capped at MAX_SAMPLES, each distance the foot's own, and
    # never farther than half a step, length / 2^17, beyond the nearest of 2e5 samples
    from libelastica.nearest import MAX_SAMPLES, turning_samples
    c = el.SmoothElastica(x0=5.0, y0=-3.0, phi=0.3, mu=mu, k=0.999, q=0.2, length=1.0)
    assert c.max_curvature == pytest.approx(2 * 0.999 * np.sqrt(mu), rel=1e-15)
    assert turning_samples(c) == MAX_SAMPLES
    rng = np.random.default_rng(2)
    q = c.points(rng.uniform(0, 1, 20)) + rng.normal(0, 1e-3, (20, 2))
    d, s = curve_feet(c, q)
    assert np.allclose(np.linalg.norm(c.points(s) - q, axis=1), d, rtol=0, atol=1e-13)
    dense = c.points(np.linspace(0.0, 1.0, 200001))
    near = np.array([np.sqrt(((dense - p) ** 2).sum(axis=1).min()) for p in q])
    assert np.all(d <= near + 0.5 / (MAX_SAMPLES - 1) + 1e-13), np.max(d - near)


@pytest.mark.parametrize("k", [0.1, 0.5, 0.9, 0.999999, -0.7])
@pytest.mark.parametrize("length", [0.5, 3.0, 7.0, 40.0])
def test_max_curvature_the_same_with_or_without_listing_the_inflections(k, length):
    # the peak 2 |k| sqrt(mu) taken where u spans 2K is the largest of a dense sampling
    c = el.SmoothElastica(x0=0, y0=0, phi=0.1, mu=2.0, k=k, q=0.4, length=length)
    dense = np.abs(c.curvature(np.linspace(0.0, length, 200001))).max()
    assert dense <= c.max_curvature * (1 + 1e-12)
    assert c.max_curvature <= dense + 2.0 * np.sqrt(2.0) * (length / 2e5) ** 2 * 2.0


def _centred(c, q, samples):
    """curve_feet's arguments of its candidate searches (_table_dips, _sieved_dips)."""
    from libelastica.nearest import turning_samples
    if samples is None:
        samples = c.points(np.linspace(0.0, c.length, turning_samples(c)))
    o = samples.mean(axis=0)
    sm, qc = samples - o, q - o
    return (qc, np.einsum("ij,ij->i", qc, qc), sm, np.einsum("ij,ij->i", sm, sm),
            c.length / (len(samples) - 1)), samples


@pytest.mark.parametrize("k, mu, length", [(0.3, 1.0, 4.0), (0.999, 400.0, 40.0),
                                           (1.001, 1.0, 4.0), (1.82, 1.0, 40.0),
                                           (3.0, 25.0, 40.0)])
@pytest.mark.parametrize("offset, scale", [(0.0, 1.0), (1e6, 1.0), (5.0, 1e-6), (-3e8, 1e6)])
def test_curve_feet_sieve_finds_the_tables_samples_to_the_bit(k, mu, length, offset, scale,
                                                              monkeypatch):
    # the sieve of sample blocks (_sieved_dips, many points x many samples) against the full
    # table (_table_dips): the same candidate dips in the same order, so the same refine_feet
    # call and the same distances and feet; loops and curls (k across 1, an 11-turn loop),
    # sparse / default / dense samples, points on, near and far off the curve, one to many
    from libelastica import nearest
    c = el.SmoothElastica(x0=offset, y0=-offset, phi=0.3, mu=mu / scale ** 2, k=k, q=0.2,
                          length=length * scale)
    size = float(np.ptp(c.points(np.linspace(0.0, c.length, 4001)), axis=0).max())
    rng = np.random.default_rng(11)
    for coarse in (9, 257, None, 20001):
        samples = None if coarse is None else c.points(np.linspace(0.0, c.length, coarse))
        for m in (1, 40):
            on = [c.points(rng.uniform(0, c.length, m)) for _ in range(3)]
            q = np.vstack([on[0], on[1] + rng.normal(0, 1e-3 * size, (m, 2)),
                           on[2] + rng.normal(0, 0.3 * size, (m, 2)),
                           c.points(np.zeros(m)) + rng.normal(0, 1e3 * size, (m, 2))])
            args, S = _centred(c, q, samples)
            a, b = nearest._table_dips(*args), nearest._sieved_dips(*args)
            assert np.array_equal(a[0], b[0]) and np.array_equal(a[1], b[1])
            feet = []
            for cut in (0, 1 << 62):        # every call sieved, then every call a table
                monkeypatch.setattr(nearest, "FEET_TABLE", cut)
                feet.append(curve_feet(c, q, S))
            assert np.array_equal(feet[0][0], feet[1][0])
            assert np.array_equal(feet[0][1], feet[1][1])
