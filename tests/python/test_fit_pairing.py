"""The discrete fit's default distance pairs vertex i with point i only where the points are
one pass at equal steps (libelastica/fit_pairing.c). QA18: a scan passed back and forth
over part of its length was paired, its polygon retraced, and the refit by distance from
that polygon stayed there (rms 0.49, length 63 for 30, a MisfitWarning naming a false
corner); a scan with single points missing was paired across the gaps (rms up to 1.22 x
the orthogonal fit's, no warning). Both now fit as distance="orthogonal" does; scans at
equal steps without dropouts stay paired."""
import re
import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli

TRUTH = dict(x0=0, y0=0, phi=0.1, mu=0.04, k=0.75, q=-0.9, length=30.0)
NOISE = 0.05


def _truth():
    return el.SmoothElastica(**TRUTH)


def _fit_warned(P, **kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = el.fit(P, **kw)
    return r, [x for x in w if issubclass(x.category, (el.MisfitWarning, el.WanderWarning))]


# s 0 -> 12, back to 8, on to 30: 188 points 0.2 apart both ways. Main: seed 3 rms 0.487,
# length 63.2, status 0, a MisfitWarning (a corner at point 164) and a WanderWarning;
# seed 23 rms 1.097, length 34.1, status 6 (7 of 60 seeds so); neither named the points
# that run back
@pytest.mark.parametrize("seed", [3, 23])
def test_back_and_forth_scan_fits_as_orthogonal(seed):
    s = np.r_[np.linspace(0, 12, 60), np.linspace(12, 8, 20)[1:], np.linspace(8, 30, 110)[1:]]
    P = _truth().points(s) + NOISE * np.random.default_rng(seed).standard_normal((len(s), 2))
    r, warned = _fit_warned(P)
    o = _fit_warned(P, distance="orthogonal")[0]
    length = r.curve.h * (r.curve.n - 1)
    assert r.status == 0 and r.distance == "orthogonal"
    assert r.rms < 1.2 * NOISE and abs(length - 30.0) < 0.5, (r.rms, length)
    assert r.rms <= o.rms * (1 + 1e-6), (r.rms, o.rms)
    # said once, where it happens: the points that run back (59..78 as drawn), not a corner
    said = [str(x.message) for x in warned]
    assert len(said) == 1 and warned[0].category is el.OrderWarning, said
    m = re.match(r"fit: points (\d+) to (\d+) \(counted from 0\) run back along the curve", said[0])
    assert m and abs(int(m[1]) - 59) <= 2 and abs(int(m[2]) - 78) <= 2, said
    # kept in the result (the CLI's quiet fit says it from there)
    assert r.retrace is not None and (r.retrace.first, r.retrace.last) == (int(m[1]), int(m[2]))


def _dropout_scan(seed, ndrop):
    """QA18's scan: 200 points at equal steps along the curve, ndrop single points left out
    (between points 10 and 190), noise 0.05."""
    rng = np.random.default_rng(seed)
    keep = np.ones(200, bool)
    keep[rng.choice(np.arange(10, 190), ndrop, replace=False)] = False
    return _truth().points(np.linspace(0, 30, 200)[keep]) + NOISE * rng.standard_normal((keep.sum(), 2))


# main paired these at 1.223, 1.127 (two dropouts) and 1.057, 1.064 (one) x the orthogonal
# fit's rms, silently
@pytest.mark.parametrize("seed, ndrop", [(1003, 2), (1008, 2), (1003, 1), (1018, 1)])
def test_dropouts_fit_as_orthogonal(seed, ndrop):
    P = _dropout_scan(seed, ndrop)
    r, warned = _fit_warned(P)
    o = el.fit(P, distance="orthogonal")
    assert r.distance == "orthogonal"
    assert r.rms <= o.rms * (1 + 1e-6), (r.rms, o.rms)
    assert not warned, [str(x.message) for x in warned]     # in order: nothing runs back
    assert r.retrace is None


# the same scans without dropouts that the spacing test passes: paired as before, at
# 1.001-1.010 x the orthogonal fit's rms
@pytest.mark.parametrize("seed", [1000, 1007, 1014])
def test_even_scans_stay_paired(seed):
    r, warned = _fit_warned(_dropout_scan(seed, 0))
    assert r.distance == "paired" and not warned


def test_cli_names_the_points_that_run_back(capsys, tmp_path):
    """`elastica fit` says it in its own words (its fits are quiet): once, the points named."""
    s = np.r_[np.linspace(0, 12, 60), np.linspace(12, 8, 20)[1:], np.linspace(8, 30, 110)[1:]]
    P = _truth().points(s) + NOISE * np.random.default_rng(3).standard_normal((len(s), 2))
    path = tmp_path / "backforth.csv"
    np.savetxt(path, P, delimiter=",")
    code, out, err = cli(capsys, "fit", path)
    assert code == 0 and "fitted paired" not in out
    said = [line for line in err.splitlines() if "run back along the curve" in line]
    assert len(said) == 1 and re.search(r"points (5[7-9]|6[01]) to (7[6-9]|80) \(counted from 0\)", said[0]), err
    assert "corner" not in err and "wanders" not in err, err


def test_resampled_scan_at_its_spacing_fits_as_close_as_its_points():
    """test_resample_fit.py's QA scan (2000 points 2 mm apart along 4 m, noise 0.5 mm)
    resampled at 2 mm: the polygon (2046 vertices) is equilateral, but its 4094 mm run
    through the noise puts its vertices unevenly along the curve, and its paired fit's
    points step by 0.68 vertex: fitted by distance, on the user's points 1.0008 x their own
    fit's rms (main, paired: 1.104 x)."""
    from libelastica.fit import quiet_fit
    from test_resample_fit import rms_to, scan
    xy = scan(2000, 0.5)
    own = rms_to(quiet_fit(xy, model="discrete").to_bspline(), xy)
    f = el.fit_resampled(xy, 2.0, "discrete")
    assert f.rms < 1.02 * own, (f.rms, own)


def _passed_back_and_forth(seeds, n=100):
    """QA20 F4's scan, smaller: n points out along a 1500 mm elastica (denser at its start),
    n others back, noise 0.4 mm (/tmp/qa20/py/f4_back_and_forth.py: 300 and 300)."""
    truth = el.SmoothElastica(x0=5000.0, y0=-3000.0, phi=0.4, mu=1 / 400.0 ** 2, k=0.7, q=0.3,
                              length=1500.0)

    def one_pass(seed):
        rng = np.random.default_rng(seed)
        s = 1500 * (np.sort(rng.uniform(0, 1500, n)) / 1500) ** 1.3
        return truth.points(s) + rng.normal(0, 0.4, (n, 2))
    return np.vstack([one_pass(seeds[0]), one_pass(seeds[1])[::-1]])


# main: smooth named points 100 to 197 both times; discrete (6, 7) a MisfitWarning alone
# ('a corner at point 100? Split there', rms 32.5), (1, 2) a WanderWarning (rms 22.7); at
# QA's 300 + 300 discrete status 6, rms 37.4, no OrderWarning
@pytest.mark.parametrize("model", ["smooth", "discrete"])
@pytest.mark.parametrize("seeds", [(6, 7), (1, 2)])
def test_a_scan_passed_back_and_forth_over_its_whole_length_is_named_by_both_models(model, seeds):
    r, warned = _fit_warned(_passed_back_and_forth(seeds), model=model)
    said = [str(x.message) for x in warned if x.category is el.OrderWarning]
    assert len(said) == 1 and not [x for x in warned if x.category is el.WanderWarning], \
        [str(x.message) for x in warned]
    m = re.match(r"fit: points (\d+) to (\d+) \(counted from 0\) run back along the curve", said[0])
    assert m and abs(int(m[1]) - 100) <= 1 and int(m[2]) >= 195, said
    assert r.retrace is not None and (r.retrace.first, r.retrace.last) == (int(m[1]), int(m[2]))


def test_cli_names_a_whole_scan_passed_back_and_forth_for_the_discrete_model(capsys, tmp_path):
    """`elastica fit` (discrete, the default) of QA20 F4's scan says the points that run back,
    once, and not the wander that they make (main: a WanderWarning's line and a corner)."""
    path = tmp_path / "bf.csv"
    np.savetxt(path, _passed_back_and_forth((1, 2)), delimiter=",")
    code, out, err = cli(capsys, "fit", path)
    said = [line for line in err.splitlines() if "run back along the curve" in line]
    assert len(said) == 1 and re.search(r"points (99|100|101) to 19\d \(counted from 0\)", said[0]), err
    assert "wanders" not in err, err
