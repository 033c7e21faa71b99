"""A keyline fit's user-facing results in the points' own coordinates (QA16 F1): on 2D
points el.fit_keyline's to_bspline(), joint and ends came back in the fit's PCA frame x''y''
(centroid at the origin, rotated) - the exported B-spline lay 95 (a hand-drawn stroke) to
306 (a ship line) rms from the points whose input_distances said 0.366 - and so did the
`fit --keyline` JSON's "bspline", where its DXF was in the file's coordinates."""
from __future__ import annotations

import json

import numpy as np
import pytest
from scipy.interpolate import BSpline as ScipyBSpline
from scipy.spatial import cKDTree
from scipy.special import ellipk

import libelastica as el
from test_cli import cli

NOISE = 0.2
TURN, SHIFT = np.radians(57.0), np.array([480.0, -260.0])


def _rotated_s():
    """A 300 mm S (one elastica, inflection at s_i), 250 uneven points with noise 0.2,
    turned 57 deg and shifted (480, -260): its PCA frame is far from its coordinates.
    Returns (points, the inflection in those coordinates)."""
    rng = np.random.default_rng(4)
    c = el.SmoothElastica(x0=0, y0=0, phi=0.0, mu=(2.5 / 300) ** 2, k=0.7, q=0.5, length=300.0)
    s = np.sort(rng.uniform(0, 300, 250))
    s[0], s[-1] = 0, 300
    R = np.array([[np.cos(TURN), -np.sin(TURN)], [np.sin(TURN), np.cos(TURN)]])
    s_i = (ellipk(0.49) - c.q) / np.sqrt(c.mu)          # u = K(k): sn = 1, curvature 0
    P = (c.points(s) + rng.normal(0, NOISE, (250, 2))) @ R.T + SHIFT
    return P, c.points([s_i])[0] @ R.T + SHIFT


def _on(b, points, samples: int = 400001):
    """Each point's distance to the B-spline b, evaluated by scipy (densely sampled:
    within half a sample's spacing), and that spacing."""
    t = b.flat_knots()
    sb = ScipyBSpline(t, b.poles, b.degree)
    Q = sb(np.linspace(t[b.degree], t[-b.degree - 1], samples))
    gap = float(np.max(np.linalg.norm(np.diff(Q, axis=0), axis=1)))
    return cKDTree(Q).query(points)[0], gap


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_keyline_bspline_joint_and_ends_are_the_points_coordinates(model):
    """kl.to_bspline() lies on the points as near as the fit says they lie to the keyline
    (kl.input_distances), its ends at kl.ends (discrete) and the joint on it near the true
    inflection; side_points / side_curve there too; the x''y'' ones stay explicit
    (input_coords=False, joint_local, ends_local), and map by kl.to_input exactly."""
    P, inflection = _rotated_s()
    kl = el.fit_keyline(P, model=model)
    b = kl.to_bspline()
    d, gap = _on(b, P)
    if model == "smooth":      # the B-spline within its certified deviation of the halves
        assert np.max(np.abs(d - np.abs(kl.input_distances))) <= b.max_deviation + gap
    else:                      # the C2 cubic through the vertices, not their polygon
        assert np.sqrt(np.mean(d ** 2)) <= 1.02 * kl.input_rms
        assert np.max(d) <= 1.02 * kl.input_max_error
    assert np.sqrt(np.mean(d ** 2)) <= 1.2 * NOISE      # was 100-300 (x''y'')
    assert _on(b, kl.joint[None])[0][0] <= 1e-9 * 300 + gap
    assert np.linalg.norm(kl.joint - inflection) <= 3.0 * kl.prepared.r
    if model == "discrete":
        np.testing.assert_allclose(b(np.array(b.domain)), kl.ends, rtol=0, atol=1e-9 * 300)
        ends = P[[0, -1]] if np.linalg.norm(kl.ends[0] - P[0]) < 150.0 else P[[-1, 0]]
        assert np.all(np.linalg.norm(kl.ends - ends, axis=1) <= 3 * NOISE)   # either way
        np.testing.assert_array_equal(kl.ends, kl.to_input(kl.ends_local))
    for which in ("first", "second"):
        side = kl.side_curve(which)
        pts = side.points() if model == "discrete" else side.points(np.linspace(0, side.length, 500))
        assert np.max(_on(b, pts)[0]) <= 1e-6 * 300 + gap
        np.testing.assert_allclose(pts[0], kl.joint, rtol=0, atol=1e-9 * 300)
        assert np.max(_on(b, kl.side_points(which))[0]) <= 1e-6 * 300 + gap
        assert kl.side_curve(which, input_coords=False) == getattr(kl, which).curve
    local = kl.to_bspline(input_coords=False)
    assert kl.to_bspline() == local.mapped(kl.to_input)
    assert np.mean(_on(local, P)[0]) > 100.0       # x''y'' is not where the points are
    np.testing.assert_array_equal(kl.joint, kl.to_input(kl.joint_local))
    np.testing.assert_allclose(kl.joint_local, kl.first.curve.params[:2], rtol=0, atol=0)


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_keyline_json_bspline_is_the_files_coordinates(capsys, tmp_path, model):
    """`elastica fit --keyline --json` writes its "bspline" (and "inflection_point") in the
    file's coordinates, as its DXF and KeylineFit.to_bspline: on the file's points within
    the fit's distances; `elastica bspline` of that JSON writes the same B-spline."""
    P, _ = _rotated_s()
    np.savetxt(tmp_path / "s.csv", P, delimiter=",")
    r = cli(capsys, "fit", tmp_path / "s.csv", "--keyline", "--model", model,
            "--bspline-tol", "1e-6", "--json", tmp_path / "k.json")
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "k.json").read_text())
    b = el.BSpline.from_dict(doc["bspline"])
    kl = el.fit_keyline(P, model=model)
    assert b == kl.to_bspline(1e-6)
    d, gap = _on(b, P)
    side = doc["sides"][0]
    assert np.sqrt(np.mean(d ** 2)) <= 1.02 * side["input_rms"] + gap
    assert np.max(d) <= 1.02 * side["input_max_error"] + gap
    np.testing.assert_allclose(side["inflection_point"], kl.joint, rtol=0, atol=1e-12 * 300)
    r = cli(capsys, "bspline", tmp_path / "k.json", *(["--tol", "1e-6"] if model == "smooth" else []),
            "--json", "-")
    assert r.returncode == 0, r.stderr
    again = el.BSpline.from_dict(json.loads(r.stdout)["bspline"])
    np.testing.assert_allclose(again.poles, b.poles, rtol=0, atol=1e-12 * 300)
