"""Points out of order along their curve (a scanner's or a point picker's unordered cloud):
el.fit warns (OrderWarning) and fits them in curve order with order="curve"; the CLI says it
and takes --order curve; points in order stay silent (QA10 t5: shuffled, they fitted as a
coil, status 0, no warning, at a lower rms than the true curve)."""
import json
import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli


def sheer_line(seed=2, n=2500, noise=0.001, off=(5.0e6, -2.0e5)):
    """QA10's ship's sheer line (mm): 30 m, 1.2 m sag, dense and sparse runs, noise 30 mm."""
    r = np.random.default_rng(seed)
    t = np.cumsum(r.exponential(1.0, n) * (1 + 3 * (np.arange(n) % 400 < 100)))
    t = (t - t[0]) / (t[-1] - t[0])
    x = 30000 * t
    y = 1200 * (2 * t - 1) ** 2 + 150 * t ** 3
    return np.c_[x, y] + r.normal(0, noise * 30000, (n, 2)) + np.array(off)


def batten_photo(seed=3, n=60, noise=0.02):
    """QA10's photographed batten (pixels), 2 % noise."""
    r = np.random.default_rng(seed)
    c = el.SmoothElastica(x0=300, y0=900, phi=0.5, mu=1e-5, k=0.6, q=-0.4, length=1400)
    return c.points(np.sort(r.uniform(0, 1400, n))) + r.normal(0, noise * 1000, (n, 2))


def tile_scan(seed=1, n=800, noise=0.005, off=(1.2e5, 3.4e4), outliers=3):
    """QA10's roof-tile keyline scan (mm): a gap, outliers, far from the origin."""
    r = np.random.default_rng(seed)
    t = np.sort(r.uniform(0, 1, n) ** 1.15)
    t = t[(t < 0.42) | (t > 0.52)]
    x = 320 * t
    y = 40 * np.sin(2 * np.pi * (t - 0.1)) * (1 - 0.3 * t)
    P = np.c_[x, y] + r.normal(0, noise * 320, (len(t), 2))
    idx = r.choice(len(P), outliers, replace=False)
    P[idx] += r.normal(0, 0.05 * 320, (outliers, 2))
    return P + np.array(off)


def shuffled(P):
    g = np.random.default_rng(9)
    g.standard_normal(P.shape)          # QA10's stream
    return P[g.permutation(len(P))]


DATA = {"sheer": sheer_line, "batten": batten_photo, "tile": tile_scan}


def fit_silent(P, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.WanderWarning)
        return el.fit(P, model="smooth", **kw)


@pytest.mark.parametrize("name", DATA)
def test_shuffled_points_warn_and_fit_in_curve_order(name):
    P = DATA[name]()
    Q = shuffled(P)
    with pytest.warns(el.WanderWarning, match="not in order along a curve.*order='curve'") as said:
        coil = el.fit(Q, model="smooth")
    assert any(issubclass(w.category, el.OrderWarning) for w in said)
    true = fit_silent(P)
    # what the warning is about: a coil many times the curve (2.82 x for the tile since 5d427a4
    # cut free smooth fits to their feet's range; 3 x and more before)
    assert coil.curve.length > 2.5 * true.curve.length
    r = fit_silent(Q, order="curve")
    assert np.array_equal(r.points, Q[r.order]) and sorted(r.order) == list(range(len(Q)))
    # no coil: the fit in order's (measured: length 0.1 %, 0.9 %, 4 % off for sheer, tile,
    # batten, rms x 0.999, 0.994, 1.054: the batten's 20 px noise swaps points 23 px apart)
    assert abs(r.curve.length - true.curve.length) < 0.10 * true.curve.length
    assert r.rms < 1.10 * true.rms


@pytest.mark.parametrize("name", DATA)
@pytest.mark.parametrize("model", ["smooth", "discrete"])
def test_points_in_order_stay_silent(name, model):
    P = DATA[name]()
    for X in (P, P[::-1].copy()):
        r = None
        with warnings.catch_warnings():
            warnings.simplefilter("error", el.OrderWarning)
            r = el.fit(X, model=model)
        assert r.order is None
        assert el.out_of_order(X).order is None


def test_out_of_order_measures_and_screens():
    t = np.linspace(0, 3, 300)
    P = np.c_[t, np.sin(t)]
    o = el.out_of_order(P)
    assert o.order is None and np.isnan(o.along)       # O(n): within 3x the extent
    Q = shuffled(P)
    o = el.out_of_order(Q)
    assert o.order is not None and o.given > el.ORDER_RATIO * o.along
    assert np.allclose(np.abs(np.diff(Q[o.order][:, 0])), 3 / 299)   # the curve's order back
    assert np.array_equal(el.out_of_order(Q, screen=False).order, o.order)
    with pytest.raises(ValueError):
        el.curve_order(np.zeros((5, 4)))


def test_cli_warns_of_a_shuffled_file_and_orders_it(capsys, tmp_path):
    Q = shuffled(tile_scan())
    f = tmp_path / "scan.csv"
    np.savetxt(f, Q, delimiter=",")
    code, _, err = cli(capsys, "fit", f, "--model", "smooth")
    assert code == 0 and "not in order along a curve" in err and "--order curve" in err
    out = tmp_path / "fit.json"
    code, _, err = cli(capsys, "fit", f, "--model", "smooth", "--order", "curve", "--json", out)
    assert code == 0 and "not in order" not in err
    doc = json.loads(out.read_text())
    assert sorted(doc["order"]) == list(range(len(Q))) and doc["curve"]["length"] < 400


@pytest.mark.parametrize("step", [None, 1.0])
def test_cli_in_curve_order_names_the_file_rows(capsys, tmp_path, step):
    """QA17 W2b: a shuffled scan with one glitch 2.0 off its curve at file row 126, fitted
    --order curve: the CLI named point 100 (the glitch's place in curve order, a good
    point's row) and its JSON "distances" were in curve order."""
    c = el.SmoothElastica(0, 0, 0.2, 0.01, 0.7, 0.3, 100.0)
    rng = np.random.default_rng(4)
    P = c.points(np.linspace(0, 100, 200)) + rng.normal(0, 0.05, (200, 2))
    d = P[101] - P[99]
    P[100] += 2.0 * np.array([-d[1], d[0]]) / np.hypot(*d)
    perm = rng.permutation(200)
    Q, row = P[perm], int(np.flatnonzero(perm == 100)[0])
    f, out = tmp_path / "scan.csv", tmp_path / "fit.json"
    np.savetxt(f, Q, delimiter=",")
    code, _, err = cli(capsys, "fit", f, "--model", "smooth", "--order", "curve", "--json", out,
                       *(("--step", step) if step else ()))
    doc = json.loads(out.read_text())
    assert code == 0 and doc["outliers"] == [row] and f"(points {row}, counted" in err
    dist = np.abs(doc["distances"])
    assert int(np.argmax(dist)) == row and 1.5 < dist[row] < 2.5
    assert np.all(np.delete(dist, row) < 0.3)


def test_cli_in_curve_order_names_the_wander_gaps_file_rows(capsys, tmp_path):
    """The sketch whose fit swings between its points 16 and 17 (fit_data.swinging_sketch),
    its rows shuffled and fitted --order curve: the JSON's "wander_gap" was 16, a place in
    curve order (the file's rows 16 and 17 are other points); now "wander_points" names the
    two points' file rows (the warning's places), and in file order (the sketch as drawn)
    the gap's two rows, beside "wander_gap" as before."""
    from fit_data import swinging_sketch
    P = swinging_sketch()
    perm = np.random.default_rng(3).permutation(len(P))
    rows = [int(np.flatnonzero(perm == i)[0]) for i in (16, 17)]
    assert rows != [16, 17]
    f, out = tmp_path / "sketch.csv", tmp_path / "fit.json"
    np.savetxt(f, P[perm], delimiter=",", header="x,y", comments="")
    code, _, err = cli(capsys, "fit", f, "--model", "smooth", "--order", "curve", "--json", out)
    doc = json.loads(out.read_text())
    assert code == 0 and doc["wander_points"] == rows and "wander_gap" not in doc, err
    places = " and ".join(f"({P[perm][r][0]:.4g}, {P[perm][r][1]:.4g})" for r in rows)
    assert f"between the points at {places}" in err, err
    np.savetxt(f, P, delimiter=",", header="x,y", comments="")
    code, _, err = cli(capsys, "fit", f, "--model", "smooth", "--json", out)
    doc = json.loads(out.read_text())
    assert code == 0 and doc["wander_gap"] == 16 and doc["wander_points"] == [16, 17], err


def test_keyline_of_a_shuffled_scan_warns():
    P = tile_scan()
    with pytest.warns(el.OrderWarning, match="curve_order"):
        try:
            el.fit_keyline(shuffled(P))
        except el.ElasticaError:
            pass        # a cloud's polyline may show no inflection: the warning came first
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.OrderWarning)
        el.fit_keyline(P)


def test_a_noisy_coil_in_order_is_screened_without_curve_order(monkeypatch):
    """A dense noisy scan of a curve longer than 3 x its extent (an orbital elastica's
    coil) passes the length screen however ordered; its screen's turning is a curve's, so
    out_of_order answers without curve_order (bench_fit.py's 1000 points on k = 1.3 paid
    its 16 ms in a 1 ms fit), and the same points shuffled still are flagged."""
    from libelastica import order as O
    rng = np.random.default_rng(7)
    t = np.linspace(0.0, 6.0 * np.pi, 1000)
    coil = np.c_[np.cos(t) * (1 + 0.05 * t), np.sin(t) * (1 + 0.05 * t)]
    pts = coil + rng.normal(0.0, 0.01, coil.shape)
    assert O.polyline_length(pts[::len(pts) // O.SCREEN_POINTS]) > 3.0 * np.ptp(pts, axis=0).max()
    calls = []
    real = O.curve_order
    monkeypatch.setattr(O, "curve_order", lambda xy: calls.append(1) or real(xy))
    assert O.out_of_order(pts).order is None
    assert not calls
    assert O.out_of_order(pts[rng.permutation(len(pts))]).order is not None


def test_a_noisy_scan_in_order_whose_screen_turns_is_cleared_by_its_run_means(monkeypatch):
    """1000 points on a discrete elastica of k = 8 (a loop and more) in order, 1.5 % noise:
    the polyline through every step-th point turns 1.43 rad a vertex, past
    TURN_PER_VERTEX, but the one through the means of runs of step points 0.39 rad, so
    out_of_order answers without curve_order (which finds them in order: 2.0 x); the same
    points shuffled still are flagged."""
    from libelastica import order as O
    n = 1000
    c = el.DiscreteElastica(x0=0, y0=0, h=1.0 / n, phi=0.3, z=0.7 / (n - 1), q=0.5, k=8.0, n=n)
    P = c.points()
    L = O.polyline_length(P)
    pts = P + np.random.default_rng(0).normal(0, 0.015 * L / np.sqrt(2), P.shape)
    step = n // O.SCREEN_POINTS
    assert O.polyline_length(pts[::step]) > 3.0 * np.ptp(pts, axis=0).max()
    assert O._screen(np.ascontiguousarray(pts), step, True).turn > O.TURN_PER_VERTEX
    assert O.out_of_order(pts, screen=False).order is None
    calls = []
    real = O.curve_order
    monkeypatch.setattr(O, "curve_order", lambda xy: calls.append(1) or real(xy))
    o = O.out_of_order(pts)
    assert o.order is None and np.isnan(o.given) and not calls
    Q = pts[np.random.default_rng(1).permutation(n)]
    assert O.out_of_order(Q).order is not None and calls


def test_a_shuffled_keyline_with_no_inflection_in_its_order_says_curve_order(capsys, tmp_path):
    """QA20 F9: the 3D keyline example shuffled, fitted as a keyline in the file's order:
    'no inflection found: ... fit them as one curve' was wrong advice (in curve order it fits,
    rms 0.128); the error says to fit in curve order, in Python and on the command line (the
    advice taken works). Failed before: 'fit them as one curve'."""
    import pathlib
    P = np.loadtxt(pathlib.Path(__file__).parents[2] / "examples" / "keyline_3d.csv", delimiter=",",
                   comments="#", skiprows=2)
    Q = P[np.random.default_rng(20).permutation(len(P))]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.OrderWarning)
        with pytest.raises(el.DomainError) as exc:
            el.fit_keyline(Q)
        said = str(exc.value)
        assert "curve_order" in said and "--order curve" in said, said
        assert "as one curve" not in said, said
        assert el.fit_keyline(Q[el.curve_order(Q)]).input_rms < 0.5     # the advice works
    path = tmp_path / "kl_shuf.csv"
    np.savetxt(path, Q, delimiter=",")
    code, _, err = cli(capsys, "fit", "--keyline", path)
    assert code == 2 and "--order curve" in err and "as one curve" not in err, err
    code, _, err = cli(capsys, "fit", "--keyline", "--order", "curve", path)
    assert code == 0, err
