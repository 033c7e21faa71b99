"""Held start states whose continuation has no basin to follow (QA15 F2).

A smooth fit held at a scan's first point and a start tangent continues from the fit with
that tangent free (el__fit_held_start, fit_constraints.c). On QA15's sheer scan the paired
fit with the tangent free does not converge (it crawls towards k = 1), and its 32 stages
towards the tangent crawled to max_iter each: the paired held fit cost 34779 iterations
(10 s) for the fit the direct starts reach in 234; the fit by distance ran it (its refit from
the paired curve) for tangents 16.85-18 deg, 10 s against 0.4 s at 16 and 20 deg.
Iterations are the deterministic proxy of the time.
"""
import warnings

import numpy as np
import pytest

import libelastica as el
from fit_data import sheer_scan


@pytest.fixture(scope="module")
def sheer():
    return sheer_scan()[0]


def _held(xy, deg):
    return {"start_point": tuple(xy[0]), "start_tangent": float(np.radians(deg))}


@pytest.mark.c_numerics
@pytest.mark.parametrize("deg", [16.0, 17.0])
def test_paired_held_start_does_not_crawl_through_its_stages(sheer, deg):
    """The paired fit held at the first point and a tangent 0.8 rad off the data's
    (-30.8 deg): main 34005 / 34779 iterations, then 230 / 234 at the same rms (main:
    1098.1995913832054 / 1118.9880241368064 mm); since 5cee373 (the scan's spacing judged
    without its noise: chord fractions) 567 / 573 at rms 927.1 / 949.7, the free paired fit
    40 iterations at rms 14.0 where it crawled 274 to rms 521."""
    r = el.fit(sheer, model="smooth", distance="paired", check_ends=False, constraints=_held(sheer, deg))
    assert r.status == 0
    # the crawl through 32 stages took ~34 000 iterations: a bound far below it (the free
    # paired fit's 10 x was the bound while it took 274; it takes 40 now)
    assert r.iterations <= 1500, r.iterations
    main_rms = {16.0: 1098.1995913832054, 17.0: 1118.9880241368064}[deg]
    assert r.rms <= main_rms * (1 + 1e-9), r.rms
    th = r.curve.angle(np.array([0.0]))[0]
    assert abs(np.remainder(th - np.radians(deg) + np.pi, 2 * np.pi) - np.pi) <= 1e-9
    assert np.hypot(*(r.curve.points(np.array([0.0]))[0] - sheer[0])) <= 1e-6


@pytest.mark.c_numerics
def test_held_fit_by_distance_keeps_its_basin(sheer):
    """The fit by distance at 17 deg (its refit from the paired curve above, no longer
    10 s): the same basin as main's (rms 945.5388336000649 mm, length 30397.9 mm), and the
    rms between its neighbours' at 16 and 20 deg (923.2 and 1013.1) as the tangent moves
    away from the data's."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.EndConditionWarning)
        fits = [el.fit(sheer, model="smooth", constraints=_held(sheer, d)) for d in (16.0, 17.0, 20.0)]
    r, rms = fits[1], [f.rms for f in fits]
    assert r.status == 0
    assert r.rms <= 945.5388336000649 * (1 + 1e-9), r.rms
    assert abs(r.curve.length - 30397.9) <= 1.0, r.curve.length
    assert rms[0] < rms[1] < rms[2], rms


def _sketched_elastica(seed, n):
    """n noise-free points of a smooth elastica (k across 1, loops included) sketched densely
    over its first 30 %, a gap, sparser over its last 55 % (test_fit.py's _elastica_sampled),
    the curve's size and its end tangents."""
    rng = np.random.default_rng(seed)
    k = rng.uniform(0.3, 1.6)
    L = rng.uniform(2, 6)
    c = el.SmoothElastica(x0=0, y0=0, phi=rng.uniform(-1, 1), mu=rng.uniform(0.3, 2), k=k,
                          q=rng.uniform(0, 3), length=L)
    a = int(0.7 * n)
    P = c.points(np.concatenate([np.linspace(0, 0.3 * L, a), np.linspace(0.45 * L, L, n - a)]))
    th = c.angle(np.array([0.0, L]))
    size = np.sqrt(np.mean(np.sum((P - P.mean(0)) ** 2, 1)))
    return P, size, {"start_tangent": float(th[0]), "end_tangent": float(th[1]),
                     "start_curvature": float(c.curvature(np.array([0.0]))[0])}


@pytest.mark.c_numerics
@pytest.mark.parametrize("seed, n", [(1, 1000), (5, 200)])
def test_exact_held_fit_stops_once_its_feet_are_settled(seed, n):
    """Noise-free sketched points held at both end tangents (the end one Ipopt's row): the
    first start's fit ends at rms ~1e-5 of the size with feet on another pass of the curve
    than its nearest points, and its refit from those (settle_feet's, fit.c) is exact. Main
    fitted every other start first, to that same point or above it, and refitted only the
    kept one at the end: 7639 iterations (1000 points, 4.9 s CPU) and 2660 (200), for the
    exact fit the first start's refit reaches in 31 and 34 (fit_choose.c, settle_early)."""
    P, size, held = _sketched_elastica(seed, n)
    tangents = {w: held[w] for w in ("start_tangent", "end_tangent")}
    r = el.fit(P, "smooth", constraints=tangents, check_ends=False)
    assert r.status == 0
    assert r.rms <= 1e-9 * size, r.rms / size
    # the work: main's 2660-7639 iterations; the refit after the first start, ~30
    assert r.iterations <= 200, r.iterations


@pytest.mark.c_numerics
def test_exact_g2_held_fit_at_an_offset_stops_once_its_feet_are_settled():
    """The same with the start curvature held too (G2 at the start: a curvature row besides
    the tangents'), 30 sketched points in millimetres 1e6 mm from the origin (a CAD part's
    placement): the first start's fit has feet on another pass, its refit from the nearest
    feet is exact (fit_choose.c, settle_early). Before it: 2509 iterations over every start
    for the same exact fit; now 32."""
    P, size, held = _sketched_elastica(14, 30)
    held["start_curvature"] /= 1e3
    r = el.fit(P * 1e3 + 1e6, "smooth", constraints=held, check_ends=False)
    assert r.status == 0
    assert r.rms <= 1e-9 * 1e3 * size, r.rms / (1e3 * size)
    assert abs(r.curve.curvature(np.array([0.0]))[0] - held["start_curvature"]) <= \
        1e-9 * abs(held["start_curvature"])
    assert r.iterations <= 200, r.iterations
