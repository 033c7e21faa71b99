"""What a Python user with measured curves reads in the results (QA qapy F6, F7, F8, F10 to
F13): a message for points that repeat, each figure named by the curve it is to, a keyline
side in the file's frame, a B-spline's unknown deviation that reads as none, a string
column named, and an SVG without matplotlib."""
from __future__ import annotations

import json
import math
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from cli_run import cli
from fit_data import polygon_distances, uneven_scan
from libelastica.fit_input import require_distinct
from libelastica.io import read_points

EX = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_two_distinct_points_in_five_rows_are_refused_as_too_few(model):
    """[0, 0] then 4 x [1, 1] raised SingularError 'singular or degenerate input', [0, 0],
    [1, 1] alternating 'fitted' a curve of rms 4e-14: both now as [[0, 0], [1, 1]] is, a
    ValueError saying how many distinct points there are and which rows repeat."""
    cases = {((0, 0), (1, 1), (1, 1), (1, 1), (1, 1)):
             "only 2 distinct points in 5 (points 2 to 4 repeat point 1, (1, 1)): need at least 4",
             ((0, 0), (1, 1), (0, 0), (1, 1), (0, 0)):
             "only 2 distinct points in 5 (points 2, 4 repeat point 0, (0, 0); point 3 repeats "
             "point 1, (1, 1)): need at least 4",
             ((0, 0), (1, 1), (2, 0.5), (2, 0.5), (1, 1), (0, 0)):
             "only 3 distinct points in 6 (point 5 repeats point 0, (0, 0); point 4 repeats "
             "point 1, (1, 1); point 3 repeats point 2, (2, 0.5)): need at least 4"}
    for pts, said in cases.items():
        with pytest.raises(ValueError) as exc:
            el.fit(np.array(pts, dtype=float), model=model)
        assert str(exc.value) == f"fit: {said}"
        assert not isinstance(exc.value, el.ElasticaError)     # as 'need at least 4 points'
    with pytest.raises(ValueError, match=r"^fit: need at least 4 points, got 2$"):
        el.fit(np.array([[0.0, 0.0], [1.0, 1.0]]), model=model)
    with pytest.raises(el.SingularError, match="all points are equal"):
        el.fit(np.ones((5, 2)), model=model)
    # 4 distinct among repeats still fit
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.SparseWarning)
        r = el.fit(np.array([[0, 0], [0, 0], [1, 0.5], [2, 0.8], [3, 0.9], [3, 0.9]], float),
                   model=model)
    assert r.curve is not None


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_points_equal_to_rounding_are_one_and_many_repeats_are_counted(model):
    """QA revD: points a few units in the last place apart passed as distinct ([0, 0], [1, 1],
    [1, 1 + 2 eps], [1 + 2 eps, 1] "fitted" a curve of rms 9e-16 through 2 points), and
    100 000 rows of 2 points alternating made a message of 689 000 characters."""
    e = np.finfo(float).eps
    cases = [[[0, 0], [1, 1], [1, 1 + 2 * e], [1 + 2 * e, 1], [1, 1]],
             [[0, 0], [1, 1], [0, 1e-300], [1, 1], [1e-300, 0]],
             [[5e8, -3e8], [5e8 + 1e-7, -3e8], [5e8 + 7e-6, -3e8], [5e8, -3e8 - 1e-7],
              [5e8, -3e8 - 7e-6]]]          # ulp(5e8) = 6e-8: 3 points, each twice
    for pts in cases:
        with pytest.raises(ValueError, match=r"^fit: only [23] distinct points in 5 \(.*; "
                           r"equal to rounding, within [0-9.e-]+\): need at least 4$"):
            el.fit(np.array(pts, dtype=float), model=model)
    big = np.tile([[0.0, 0.0], [1.0, 1.0]], (50_000, 1))
    with pytest.raises(ValueError) as exc:
        el.fit(big, model=model)
    said = str(exc.value)
    assert len(said) < 400 and "(49999 in all) repeat point 0, (0, 0)" in said, said
    # points far apart at a large offset, and tiny data near 0, are still distinct
    t = np.linspace(0.0, 1.0, 6)
    for xy in (np.c_[1e7 + t, 2e6 + t * t], np.c_[1e-9 * t, 1e-9 * t ** 3]):
        require_distinct(xy)


def test_the_cli_says_the_repeats_of_a_file(tmp_path, capsys):
    path = tmp_path / "dup5.csv"
    path.write_text("0,0\n1,1\n1,1\n1,1\n1,1\n")
    code, _, err = cli(capsys, "fit", path)
    assert code == 2 and "only 2 distinct points in 5 (points 2 to 4 repeat point 1" in err, err


def _resampled(model):
    xy = uneven_scan(seed=2, noise=0.3, n=300)[0]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return xy, el.fit_resampled(xy, 6.0, model=model)


def test_a_resampled_fit_names_its_distance_to_its_curve():
    """fit_resampled's discrete r.rms is to r.bspline (the cubic through the polygon), not to
    r.curve (the polygon), whose distance el.fit's rms is: r.curve_rms, r.curve_max_error,
    r.curve_distances() are that one (to the polygon, every segment tried), r.rms kept."""
    xy, r = _resampled("discrete")
    own = polygon_distances(xy, r.curve.points())          # unsigned, brute force
    d = r.curve_distances()
    assert np.allclose(np.abs(d), own, rtol=0, atol=1e-12 * np.ptp(xy))
    assert r.curve_rms == pytest.approx(np.sqrt(np.mean(own ** 2)), rel=1e-12)
    assert r.curve_max_error == pytest.approx(own.max(), rel=1e-12)
    assert r.curve_rms != pytest.approx(r.rms, rel=1e-3)   # two figures, two names
    # the same distance as el.fit's: a fit's own result measured as a resampled one is
    f = el.fit(xy[::5], model="discrete")
    same = el.ResampledFit(result=f, polygon=f.points, points=f.points, step=1.0,
                           bspline=f.to_bspline(), distances=f.distances, feet=f.points,
                           rms=f.rms, max_error=f.max_error)
    assert np.allclose(same.curve_distances(), f.distances, rtol=0, atol=1e-9 * np.ptp(xy))
    assert same.curve_rms == pytest.approx(f.rms, rel=1e-6)
    # smooth: the B-spline within tol of the curve: the same figures
    _, s = _resampled("smooth")
    assert s.curve_rms == s.rms and np.array_equal(s.curve_distances(), s.distances)


def test_the_keyline_report_prints_each_side_in_the_files_frame(capsys, tmp_path):
    code, out, err = cli(capsys, "fit", EX / "sample_s_curve.csv", "--keyline", "--model",
                         "smooth", "--json", tmp_path / "k.json")
    assert code in (0, 1), err
    doc = json.loads((tmp_path / "k.json").read_text())
    lines = [ln for ln in out.splitlines() if ln.startswith("parameters")]
    assert len(lines) == 2 and all(ln.endswith("(the file's x, y)") for ln in lines), out
    assert out.count("(x''y'': the keyline's PCA frame)") == 2
    assert out.count("(the one fit of both sides)") == 2
    joint = doc["sides"][0]["inflection_point"]
    for side in doc["sides"]:
        c = side["curve_input"]
        assert (c["x0"], c["y0"]) == pytest.approx(tuple(joint), rel=1e-9, abs=1e-9)
        assert f"x0={c['x0']:.6g}"[:8] in out


def test_cubic_distances_are_named_and_a_discrete_cubics_deviation_is_nan():
    xy = uneven_scan(seed=1, n=40)[0]
    r = el.fit(xy, model="discrete")
    cd = r.cubic_distances()
    feet, d = cd                                   # unpacks as before
    assert cd.feet is feet and cd.distances is d and feet.shape == (40, 2) and d.shape == (40,)
    b = r.to_bspline()
    assert math.isnan(b.max_deviation)             # unknown: was -1.0, read as a number
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        kl = el.fit_keyline(read_points(EX / "sample_s_curve.csv"), model="discrete")
    assert math.isnan(kl.to_bspline(1e-4).max_deviation)
    doc = b.to_dict()
    assert math.isnan(doc["max_deviation"])
    assert math.isnan(el.BSpline.from_dict({**doc, "max_deviation": None}).max_deviation)
    assert math.isnan(el.BSpline.from_dict({**doc, "max_deviation": -1.0}).max_deviation)
    assert el.BSpline.from_dict({**doc, "max_deviation": 0.25}).max_deviation == 0.25
    assert np.array_equal(el.BSpline.from_dict(doc).evaluate([0.5]), b.evaluate([0.5]))


def test_a_string_column_is_named_when_x_counts_the_rows(tmp_path, capsys):
    path = tmp_path / "names.csv"
    path.write_text("0,0,a\n1,1,b\n2,3,c\n3,3,d\n4,5,e\n")
    code, _, err = cli(capsys, "fit", path)
    assert code == 2
    assert "line 1: not a number: 'a' (column 3 holds no number: names?" in err, err
    assert "rows' numbers" not in err
    path.write_text("0,0,1\n1,1,2\n2,3,3\n3,3,4\n4,5,7\n")       # numbers: as before
    assert "(the rows' numbers?)" in cli(capsys, "fit", path)[2]


def test_svg_is_written_without_importing_matplotlib(tmp_path):
    svg = tmp_path / "f.svg"
    code = ("import sys\nfrom libelastica.cli import main\n"
            f"c = main(['fit', {str(EX / 'sample_2d.csv')!r}, '--model', 'smooth', '--svg', "
            f"{str(svg)!r}])\n"
            "print(c, any(m == 'matplotlib' or m.startswith('matplotlib.') for m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True, timeout=300).stdout.split()
    assert out[-2:] == ["0", "False"], out
    text = svg.read_text()
    assert text.startswith("<?xml") and "<svg" in text and "<polyline" in text and "curvature" in text


def test_a_negative_deviation_other_than_unknown_is_refused_and_old_pickles_read_nan():
    """review revD of a5ff62c: BSpline(..., max_deviation=-0.5) read NaN (a typo taken for
    'unknown'); a BSpline pickled before it holds -1.0 and compared unequal to its rebuilt
    self (the constructor reads -1 as NaN)."""
    import pickle
    args = (1, [[0.0, 0.0], [1.0, 1.0]], [0.0, 1.0], [2, 2])
    for bad in (-0.5, -2.0, -math.inf):
        with pytest.raises(ValueError, match="max_deviation must be >= 0, NaN or -1"):
            el.BSpline(*args, max_deviation=bad)
    assert math.isnan(el.BSpline(*args, max_deviation=-1.0).max_deviation)
    old = el.BSpline(*args, max_deviation=0.25)
    old.max_deviation = -1.0                    # as a pickle of before a5ff62c holds it
    back = pickle.loads(pickle.dumps(old))
    assert math.isnan(back.max_deviation) and back == el.BSpline(*args)
    assert pickle.loads(pickle.dumps(el.BSpline(*args, max_deviation=0.25))).max_deviation == 0.25
