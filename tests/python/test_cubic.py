"""A discrete fit's exported B-spline told as it is (QA): the C2 cubic through the polygon's
vertices runs elsewhere than the polygon, so the fit's rms / max error (the polygon's) are
not the exported curve's; FitResult.cubic_distances and `elastica fit` state its own, and
few points that the smooth model fits far better draw a warning naming --model smooth."""
from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

import libelastica as el
from near_segments import candidate_segments
from test_cli import cli

# the QA's 7-click sketch (a clothoid-like run): polygon rms 0.316 / max 0.561, its cubic
# 0.647 / 1.487, the smooth model's curve 0.031
CLICKS = np.array([[0, 0], [30, 0.5], [55, 3], [75, 9], [88, 17], [96, 27], [99, 38]], float)


def polyline_distances(points, V):
    """Each point's distance to the polyline V, every segment that can hold its nearest point
    looked at (near_segments: the same minimum as over all of them)."""
    A, D = V[:-1], np.diff(V, axis=0)
    out = []
    for p, j in zip(points, candidate_segments(points, V)):
        a, d = A[j], D[j]
        t = np.clip(np.sum((p - a) * d, axis=1) / np.sum(d * d, axis=1), 0.0, 1.0)
        out.append(np.min(np.linalg.norm(p - a - t[:, None] * d, axis=1)))
    return np.array(out)


def measured(bspline, points, samples=200001):
    """The points' distances to the B-spline, measured on ``samples`` samples of it."""
    lo, hi = bspline.domain
    return polyline_distances(points, bspline.evaluate(np.linspace(lo, hi, samples))[:, :2])


def test_cubic_distances_are_the_exported_curves():
    r = el.fit(CLICKS, model="discrete")
    b = r.to_bspline(tol=1e-3)
    feet, d = r.cubic_distances(b)
    truth = measured(b, CLICKS)
    np.testing.assert_allclose(np.abs(d), truth, atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(CLICKS - feet, axis=1), truth, atol=1e-6)
    # and they are not the polygon's, which rms / max_error report
    assert np.sqrt(np.mean(d ** 2)) > 2.0 * r.rms
    assert np.max(np.abs(d)) > 2.0 * r.max_error
    with pytest.raises(ValueError, match="discrete"):
        el.fit(CLICKS, model="smooth").cubic_distances()


def test_smooth_fits_better_on_few_points_only():
    r = el.fit(CLICKS, model="discrete")
    smooth = el.smooth_fits_better(CLICKS, r.rms)
    assert smooth == pytest.approx(el.fit(CLICKS, model="smooth").rms, rel=1e-9)
    assert smooth < r.rms / 2
    # where the polygon fits as well: no verdict
    assert el.smooth_fits_better(CLICKS, 1.5 * smooth) is None
    # SPARSE_POINTS or more points: not run (none of 191 such sketches needed it)
    d = el.DiscreteElastica(x0=0, y0=0, h=1.0, phi=0.2, z=0.05, q=0.3, k=0.8, n=el.SPARSE_POINTS)
    assert el.smooth_fits_better(d.points(), 100.0) is None


def test_fit_of_few_points_warns_where_the_smooth_model_fits_far_better():
    """The one-piece discrete fit of few points: el.fit says what the CLI and FreeCAD said
    (SparseWarning, FitResult.sparse the smooth fit's rms), on the larger of its polygon's
    rms and its cubic's (CLICKS: 0.316, 0.647; smooth 0.031), its constraints kept; points
    the polygon fits (a discrete elastica's), the smooth model, check_sparse=False and
    quiet_fit draw none."""
    smooth = el.fit(CLICKS, model="smooth").rms
    with pytest.warns(el.SparseWarning, match="use model='smooth'") as w:
        r = el.fit(CLICKS)
    assert len(w) == 1 and r.sparse == smooth
    cubic = np.sqrt(np.mean(r.cubic_distances()[1] ** 2))
    assert f"{r.rms:.3g}" in str(w[0].message) and f"{cubic:.3g}" in str(w[0].message)
    held = {"start_tangent": 0.0}
    with pytest.warns(el.SparseWarning):
        rc = el.fit(CLICKS, constraints=held)
    assert rc.sparse == el.fit(CLICKS, model="smooth", constraints=held).rms
    d = el.DiscreteElastica(x0=0, y0=0, h=1.0, phi=0.2, z=0.15, q=0.3, k=0.8, n=12)
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.SparseWarning)
        assert el.fit(d.points()).sparse is None
        assert el.fit(CLICKS, model="smooth").sparse is None
        assert el.fit(CLICKS, check_sparse=False).sparse is None
        from libelastica.fit import quiet_fit
        assert quiet_fit(CLICKS).sparse is None
        assert quiet_fit(CLICKS, check_sparse=True).sparse == smooth


def test_cli_states_the_bsplines_own_distances_and_points_to_smooth(capsys, tmp_path):
    path = tmp_path / "clicks.csv"
    np.savetxt(path, CLICKS, delimiter=",", header="x,y", comments="")
    r = cli(capsys, "fit", path, "--bspline-tol", "1e-3", "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    fit = el.fit(CLICKS, model="discrete")
    d = measured(fit.to_bspline(), CLICKS)
    rec = json.loads((tmp_path / "f.json").read_text())
    assert rec["bspline_rms"] == pytest.approx(np.sqrt(np.mean(d ** 2)), abs=1e-6)
    assert rec["bspline_max_error"] == pytest.approx(d.max(), abs=1e-6)
    assert (f"the points lie rms {rec['bspline_rms']:.6g}, max {rec['bspline_max_error']:.6g} "
            "from it") in r.stdout
    assert "use --model smooth" in r.stderr
    assert f"where the smooth model's curve lies {el.fit(CLICKS, model='smooth').rms:.3g}" in r.stderr
    # said once, in the CLI's words (el.fit's SparseWarning not printed as well)
    assert r.stderr.count("warning") == 1 and "SparseWarning" not in r.stderr
    # the smooth model's B-spline is within its tol: nothing to add, nothing to warn
    r = cli(capsys, "fit", path, "--model", "smooth", "--bspline-tol", "1e-3")
    assert r.returncode == 0 and "lie rms" not in r.stdout and "warning" not in r.stderr


def test_cli_no_warning_where_the_polygon_fits(capsys, tmp_path):
    """Points of a discrete elastica (the polygon exact): no warning, and without a B-spline
    no cubic figures."""
    d = el.DiscreteElastica(x0=0, y0=0, h=1.0, phi=0.2, z=0.15, q=0.3, k=0.8, n=12)
    path = tmp_path / "exact.csv"
    np.savetxt(path, d.points(), delimiter=",", header="x,y", comments="")
    r = cli(capsys, "fit", path)
    assert r.returncode == 0 and "warning" not in r.stderr and "lie rms" not in r.stdout


def test_cli_keyline_states_the_bsplines_distances(capsys, tmp_path):
    """A discrete keyline's B-spline: the file's points against it, measured here."""
    from test_keyline_step import tile_scan
    pts = tile_scan(1500, 0.005, 1)
    path = tmp_path / "tile.csv"
    np.savetxt(path, pts, delimiter=",", header="x,y", comments="")
    r = cli(capsys, "fit", path, "--keyline", "--bspline-tol", "1e-3", "--json", tmp_path / "k.json")
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "k.json").read_text())
    kf = el.fit_keyline(np.loadtxt(path, delimiter=",", skiprows=1))
    local = kf.prepared.frame2d.to_local(np.loadtxt(path, delimiter=",", skiprows=1))
    d = measured(kf.to_bspline(input_coords=False), local, 40001)   # x''y'', 400 samples a span
    assert doc["bspline_rms"] == pytest.approx(np.sqrt(np.mean(d ** 2)), abs=1e-5)
    assert doc["bspline_max_error"] == pytest.approx(d.max(), abs=1e-5)
    # not the keyline's polygon figures (those of the "keyline rms" line)
    assert doc["bspline_rms"] != doc["sides"][0]["input_rms"]
    assert f"the file's points lie rms {doc['bspline_rms']:.6g}" in r.stdout


def s_sketch(n):
    """QA17 W4's sketch (b1_keyline_sparse.py, b1_s8.csv): n points on an S, noise 0.3."""
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65, q=0.25,
                          length=330.0)
    return c.points(np.linspace(0, c.length, n)) + np.random.default_rng(n).normal(0, 0.3, (n, 2))


def test_sparse_discrete_keyline_warns_as_the_one_piece_fit(capsys, tmp_path):
    """QA17 W4: a discrete keyline of 8 points on an S lay rms 1.457 from them (the smooth
    keyline 0.042) without a word, where the one-piece fit's CLI warns: fit_keyline warns
    (SparseWarning, KeylineFit.sparse the smooth keyline's rms), `elastica fit --keyline`
    says it on stderr; the smooth keyline, and 24 points (1.1 x), draw none."""
    P = s_sketch(8)
    smooth = el.fit_keyline(P, model="smooth")
    with pytest.warns(el.SparseWarning, match="use model='smooth'"):
        kf = el.fit_keyline(P)
    assert kf.input_rms > 10 * smooth.input_rms and kf.sparse == smooth.input_rms
    assert smooth.sparse is None
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.SparseWarning)
        assert el.fit_keyline(s_sketch(24)).sparse is None
    path = tmp_path / "s8.csv"
    np.savetxt(path, P, delimiter=",", header="x,y", comments="")
    r = cli(capsys, "fit", path, "--keyline")
    assert r.returncode == 0 and "SparseWarning" not in r.stderr
    assert (f"the discrete keyline lies {kf.input_rms:.3g} from the 8 points (rms), where the "
            f"smooth keyline lies {smooth.input_rms:.3g} from them: use --model smooth") in r.stderr
    r = cli(capsys, "fit", path, "--keyline", "--model", "smooth")
    assert r.returncode == 0 and "warning" not in r.stderr
