"""A keyline's default resampling (prep.keyline_runs / keyline_step) on dense noisy scans
(QA): 1/100 of the points' own polyline, their noise's zigzag 25-50 x the curve, left a
polygon of 2-8 segments and a false "no inflection found"; the default now finds the
inflection of an S tile, in fit_keyline and `elastica fit --keyline`, and still refuses
points that turn one way."""
from __future__ import annotations

import json

import numpy as np
import pytest

import libelastica as el
from test_cli import cli

# an S tile 300 long: curvature 2 k sqrt(mu) cn(sqrt(mu) s + q) is 0 where sqrt(mu) s + q = K(k)
SQRT_MU, K_MOD, Q, LENGTH = 2.5 / 300.0, 0.6, 0.5, 300.0
TILE = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=SQRT_MU ** 2, k=K_MOD, q=Q, length=LENGTH)
S_INFLECTION = (1.7507196 - Q) / SQRT_MU          # K(0.6) = 1.7507196: s = 150.1
# the joint's arc length on the true tile within 7 % of its length: on the 12 scans below
# the discrete keyline's joint lay 0.3-18.9 from s = 150.1, the smooth one's 1.5-9.5; on
# main 18 of the 24 fits raised (only the 1500-point 0.5 % scans were fitted)
JOINT_TOL = 0.07 * LENGTH


def tile_scan(n, noise, seed):
    """n unevenly spaced points of the tile (gamma(0.5) gaps), normal noise of ``noise``
    times its size."""
    rng = np.random.default_rng(seed)
    s = np.cumsum(rng.gamma(0.5, 1.0, n))
    s = (s - s[0]) / (s[-1] - s[0]) * LENGTH
    p = TILE.points(s)
    return p + rng.normal(0.0, noise * np.ptp(p, axis=0).max(), p.shape)


def arc_length_on_tile(point):
    """The arc length of the tile's point nearest ``point`` (to 0.01)."""
    s = np.linspace(0.0, LENGTH, 30001)
    return float(s[np.argmin(np.linalg.norm(TILE.points(s) - point, axis=1))])


SCANS = [(n, noise, seed) for n in (1500, 3000) for noise in (0.005, 0.01) for seed in range(3)]


@pytest.mark.parametrize("model", ["discrete", "smooth"])
@pytest.mark.parametrize("n,noise,seed", SCANS)
def test_default_step_finds_the_tile_inflection(n, noise, seed, model):
    pts = tile_scan(n, noise, seed)
    kf = el.fit_keyline(pts, model=model)
    joint = kf.joint
    assert abs(arc_length_on_tile(joint) - S_INFLECTION) < JOINT_TOL
    # the polygon has about KEYLINE_STEPS segments (90-100 here; 2-8 of the zigzag's length
    # on main; the walk cuts corners of what noise the medians keep)
    assert len(kf.prepared.polygon) - 1 >= 0.8 * el.KEYLINE_STEPS
    # and the keyline lies at the noise from the points (rms of the noise: its sigma)
    assert kf.input_rms < 1.1 * noise * np.ptp(pts, axis=0).max()


def test_keyline_step_is_the_medians_run():
    """Up to 2 KEYLINE_STEPS points the points' own polyline; beyond, the medians of runs
    of n // KEYLINE_STEPS: on the 3000-point 1 % scan near the tile's length, not 50 x it."""
    pts = tile_scan(3000, 0.01, 0)
    raw = float(np.sum(np.linalg.norm(np.diff(pts, axis=0), axis=1)))
    assert raw > 40 * LENGTH
    assert LENGTH / el.KEYLINE_STEPS < el.keyline_step(pts) < 1.1 * LENGTH / el.KEYLINE_STEPS
    runs = el.keyline_runs(pts)
    assert len(runs) == el.KEYLINE_STEPS + 2
    assert np.array_equal(runs[0], pts[0]) and np.array_equal(runs[-1], pts[-1])
    few = tile_scan(150, 0.0, 0)
    assert np.array_equal(el.keyline_runs(few), few)
    length = float(np.sum(np.linalg.norm(np.diff(few, axis=0), axis=1)))
    assert el.keyline_step(few) == pytest.approx(length / el.KEYLINE_STEPS, rel=1e-12)


@pytest.mark.parametrize("n,noise,turn,seed", [(3000, 0.01, 1.5, 0), (1500, 0.005, 0.6, 1),
                                               (3000, 0.005, 3.0, 3)])
@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_dense_noisy_arc_still_has_no_inflection(n, noise, turn, seed, model):
    """Points of a circular arc (one way) with the same noise: refused, saying so."""
    rng = np.random.default_rng(seed)
    s = np.cumsum(rng.gamma(0.5, 1.0, n))
    s = (s - s[0]) / (s[-1] - s[0]) * turn
    p = 150.0 * np.column_stack([np.sin(s), 1.0 - np.cos(s)])
    p += rng.normal(0.0, noise * np.ptp(p, axis=0).max(), p.shape)
    with pytest.raises(el.DomainError, match="no inflection"):
        el.fit_keyline(p, model=model)


def test_an_inflection_next_to_an_end_is_said_in_segments_of_the_polygon():
    """An arc whose last three points hook back (a pen's flick): the inflection estimate
    lies 2 segments from the end, refused, and the message counts segments of the resampled
    polygon (QA25gui I1: "lies 2 segment(s) from an end of the 99", a number without its
    noun)."""
    t = np.linspace(0.0, 1.2, 200)
    p = 100.0 * np.column_stack([np.sin(t), 1.0 - np.cos(t)])
    p[-3:, 1] -= [0.5, 1.0, 2.0]
    with pytest.raises(el.DomainError,
                       match=r"lies 2 of the resampled polygon's 99 segments from an end"):
        el.fit_keyline(p)


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_cli_keyline_of_a_dense_noisy_scan(capsys, tmp_path, model):
    """`elastica fit scan.csv --keyline` without --step: exit 0, the inflection point near
    the tile's, the step the default's (QA: exit 2 "no inflection found")."""
    pts = tile_scan(3000, 0.005, 6)
    path = tmp_path / "tile_scan.csv"
    np.savetxt(path, pts, delimiter=",", header="x,y", comments="", fmt="%.3f")
    r = cli(capsys, "fit", path, "--keyline", "--model", model, "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    side = doc["sides"][0]
    assert abs(arc_length_on_tile(np.array(side["inflection_point"])) - S_INFLECTION) < JOINT_TOL
    assert side["step"] == pytest.approx(el.keyline_step(np.loadtxt(path, delimiter=",",
                                                                    skiprows=1)), rel=1e-12)
