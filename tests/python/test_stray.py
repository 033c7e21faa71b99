"""One stray point among a hand sketch's few points (QA25gui F1): named by el.fit's
OutlierWarning in both models and both orders, the drawn order kept by curve_order; clean
sketches draw no such warning."""

import numpy as np
import pytest

import libelastica as el
from fit_data import sketched_s
from test_fit_warns_qa21 import _outliers_said as _outliers
from libelastica.stray import stray_point


def _qa25gui_sketch():
    """QA25gui's p6.py: 18 points drawn along a 330 mm curve, 0.4 mm noise, at (1500, -800),
    point 5 6 mm off (a wobble), point 10 mis-dragged 150 mm."""
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65, q=0.25,
                          length=330.0)
    xy = c.points(np.linspace(0, c.length, 60))
    rng = np.random.default_rng(3)
    idx = np.sort(rng.choice(np.arange(1, 59), 16, replace=False))
    idx = np.r_[0, idx, 59]
    pts = xy[idx] + rng.normal(0, 0.4, (len(idx), 2)) + np.array([1500.0, -800.0])
    pts[5, 1] += 6.0
    pts[10, 1] += 150.0
    return pts


@pytest.mark.parametrize("model", ["discrete", "smooth"])
@pytest.mark.parametrize("order", ["given", "curve"])
def test_qa25gui_stray_point_is_named(model, order):
    pts = _qa25gui_sketch()
    r, said = _outliers(pts, model=model, order=order)
    assert len(said) == 1 and said[0].indices == (10,), [str(m) for m in said]
    assert "point 10" in str(said[0]) and "through the others" in str(said[0])
    # the drawn order is kept: the stray point is no end of the curve's, and no 608 mm hook
    assert r.order is None or list(r.order) == list(range(18))


def test_curve_order_keeps_the_drawn_order_but_for_a_stray_point():
    pts = _qa25gui_sketch()
    assert list(el.curve_order(pts)) == list(range(18))
    # a point that belongs at an end, made last, still moves there (a step from its neighbour)
    good = pts.copy()
    good[10, 1] -= 150.0
    moved = np.r_[good[1:10], good[:1], good[10:]]
    assert list(el.curve_order(moved)) in ([9] + list(range(9)) + list(range(10, 18)),
                                           (list(range(17, 9, -1)) + list(range(9)) + [9]))



def test_curve_order_moves_an_end_row_listed_inside_though_its_step_is_the_longest():
    """Sparse offsets whose spacing grows to the end (the last step, 30, the longest), the end
    row listed among the others: it lies farther from every other than their longest step, as
    a stray point does, but nearest the others' end, where it belongs (revD: _moved_stray kept
    the given zigzag 0..3, 100, 26..70)."""
    x = np.array([0, 5, 11, 18, 26, 35, 45, 56, 70, 100.0]) + 1500.0
    pts = np.column_stack([x, 0.002 * (x - 1500.0) ** 2 - 800.0])
    given = [0, 1, 2, 3, 9, 4, 5, 6, 7, 8]
    assert list(el.curve_order(pts[given])) in ([0, 1, 2, 3, 5, 6, 7, 8, 9, 4],
                                                [4, 9, 8, 7, 6, 5, 3, 2, 1, 0])


def _dragged(n, seed, factor, offset):
    pts, truth = sketched_s(seed, n, wobble=0.0)
    rng = np.random.default_rng(100 + seed)
    noise = 0.1
    pts = pts + rng.normal(0, noise, pts.shape) + np.asarray(offset)
    i = int(rng.integers(1, n - 1))
    tangent = np.diff(pts[[i - 1, i + 1]], axis=0)[0]
    normal = np.array([-tangent[1], tangent[0]]) / np.hypot(*tangent)
    pts[i] += factor * noise * normal * (1 if seed % 2 else -1)
    return pts, i


# (off 8 points, only 300 x: the others' noise among 7 reads 5 to 10 times the true 0.1
# there, noise_level's figure: see stray.py)
@pytest.mark.parametrize("n, factor", [(8, 300), (12, 20), (12, 60), (12, 300), (18, 20), (18, 60),
                                       (18, 300)])
@pytest.mark.parametrize("offset", [(0.0, 0.0), (1500.0, -800.0)])
def test_a_point_dragged_off_a_hand_sketch_is_named(n, offset, factor):
    for seed in range(3):
        pts, i = _dragged(n, seed, factor, offset)
        for model in ("discrete", "smooth"):
            for order in ("given", "curve"):
                _, said = _outliers(pts, model=model, order=order)
                assert len(said) == 1 and said[0].indices == (i,), \
                    (seed, model, order, i, [str(m) for m in said])


@pytest.mark.parametrize("n", [8, 12, 15, 18])
def test_clean_hand_sketches_draw_no_outlier_warning(n):
    for seed in range(10):
        pts, _ = sketched_s(seed, n)
        for model in ("discrete", "smooth"):
            r, said = _outliers(pts, model=model)
            assert said == [] and len(el.fit_outliers(r)) == 0, (seed, model, [str(m) for m in said])


def test_the_cli_names_the_stray_point_with_its_own_figures(tmp_path, capsys):
    """`elastica fit` said "1 of 18 points lies 1.89 from the curve, the others within 40.2"
    of the stray point the fit passed near (its JSON "outliers" from el.fit_outliers): now
    the distance to the curve through the others, and "stray" in the JSON."""
    import json
    from libelastica.cli import main
    path, out = tmp_path / "p6.csv", tmp_path / "p6.json"
    np.savetxt(path, _qa25gui_sketch(), delimiter=",", header="x,y", comments="")
    capsys.readouterr()
    assert main(["fit", str(path), "--json", str(out)]) == 0
    err = capsys.readouterr().err
    assert "1 of 18 points lies 121 from the curve through the others" in err, err
    assert "(point 10, counted from 0)" in err
    doc = json.loads(out.read_text())
    assert doc["outliers"] == [10] and doc["stray"]["distance"] > 100, doc.get("stray")


# 8 clicks (1 px noise, uneven) of a sine's period and of a parabola's tip, every one within
# 1.5 px of the drawn curve: one click alone in a long stretch (S: t 0.37 -> 0.64 -> 1.0)
# was named 'dragged off' at 26 x / 11 x the others' noise (revD)
_SPARSE_CLICKS = [
    [[-0.6, -0.9], [15.3, 19.1], [16.5, 20.6], [41.2, 45.2], [64.4, 59.4], [109.8, 45.3],
     [190.7, -45.6], [300.0, 0.5]],
    [[199.0, -42.3], [57.8, -22.6], [28.6, -16.4], [77.6, 25.6], [124.3, 32.5], [133.3, 32.5],
     [178.0, 37.5], [200.6, 40.3]]]


@pytest.mark.parametrize("clicks", range(len(_SPARSE_CLICKS)))
@pytest.mark.parametrize("offset", [(0.0, 0.0), (1500.0, -800.0)])
def test_a_click_alone_in_a_long_stretch_is_not_named(clicks, offset):
    pts = np.asarray(_SPARSE_CLICKS[clicks]) + np.asarray(offset)
    for model in ("discrete", "smooth"):
        r, said = _outliers(pts, model=model)
        assert said == [] and stray_point(r) is None, (model, [str(m) for m in said])


@pytest.mark.parametrize("n", [8, 12, 16])
def test_a_point_moved_off_exact_points_is_named_with_a_floor_for_their_noise(n):
    """Points exactly on a line (a CAD user's), one moved 30 off: named, their noise said as
    the floor (1e-4 of the extent), not 1e-14 ('2.8e+15 x their noise (1.1e-14), which lie
    9.4e+14 x nearer', revD)."""
    pts = np.column_stack([np.linspace(0.0, 100.0, n), np.zeros(n)]) + np.array([1500.0, -800.0])
    pts[n // 2, 1] += 30.0
    for model in ("discrete", "smooth"):
        r, said = _outliers(pts, model=model)
        s = stray_point(r)
        assert s is not None and s[0] == n // 2 and s[2] >= 1e-4 * 100.0, (model, s)
        assert len(said) == 1 and "3e+03 x their noise (0.01)" in str(said[0]), [str(m) for m in said]
