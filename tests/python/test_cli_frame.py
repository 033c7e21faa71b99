"""A 3D one-piece fit's B-spline in the file's coordinates: `elastica fit` of 3D points wrote
its JSON "bspline" in the fitted plane's x'y' (where the curve is) while its DXF and a
keyline's "bspline" were in 3D; exported, that B-spline lay nowhere near the points. Now
"bspline" is in the input's coordinates, the plane's one "bspline_local", in `fit`'s JSON
and `bspline`'s."""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica.cli_common import _input_map
from libelastica.io import read_points
from libelastica.nearest import nearest_on
from test_cli import cli
from test_keyline_frame import _on      # a point's distance to a B-spline, by scipy

EX = Path(__file__).resolve().parents[2] / "examples"


@pytest.mark.parametrize("name,model", [("sample_3d.txt", "smooth"), ("sample_3d.txt", "discrete"),
                                        ("keyline_3d.csv", "smooth"), ("keyline_3d.csv", "discrete")])
def test_fit_3d_bspline_lies_on_the_files_points(capsys, tmp_path, name, model):
    """The JSON's "bspline" lies on the file's 3D points as far as the fit says: each point's
    3D distance is its in-plane distance (the fit's, smooth; its B-spline's, discrete: the
    cubic through the vertices) and its height over the plane, Pythagoras; "bspline_local"
    is the plane's, mapped exactly by the record's plane; `bspline` of the JSON the same."""
    P = read_points(EX / name)
    r = cli(capsys, "fit", EX / name, "--model", model, "--bspline-tol", "1e-7",
            "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "f.json").read_text())
    b, local = (el.BSpline.from_dict(doc[k]) for k in ("bspline", "bspline_local"))
    assert b.poles.shape[1] == 3 and local.poles.shape[1] == 2
    assert b == local.mapped(_input_map(doc))
    pl = doc["plane"]
    height = (P - np.array(pl["origin"])) @ np.array(pl["normal"])
    d3, gap = _on(b, P)
    if model == "smooth":       # the fit's distances, to the B-spline's certified deviation
        d2 = np.abs(doc["distances"])
        tol = b.max_deviation + gap
    else:                       # the cubic's own (bspline_rms), in the plane
        xy = (P - np.array(pl["origin"])) @ np.c_[pl["e1"], pl["e2"]]
        d2 = nearest_on(local, np.ascontiguousarray(xy))[1]
        assert np.sqrt(np.mean(d2 ** 2)) == pytest.approx(doc["bspline_rms"], rel=1e-9)
        tol = 1e-9 * np.ptp(P) + gap
    assert np.max(np.abs(d3 - np.hypot(d2, height))) <= tol
    assert np.sqrt(np.mean(d3 ** 2)) <= 1.01 * np.sqrt(doc["rms"] ** 2 + pl["rms"] ** 2) + tol
    assert np.mean(_on(local.mapped(lambda p: np.c_[p, np.zeros(len(p))]), P)[0]) > 10 * doc["rms"]
    r = cli(capsys, "bspline", tmp_path / "f.json", *(["--tol", "1e-7"] if model == "smooth" else []),
            "--json", "-")
    assert r.returncode == 0, r.stderr
    again = json.loads(r.stdout)
    assert el.BSpline.from_dict(again["bspline"]) == b
    assert el.BSpline.from_dict(again["bspline_local"]) == local


def test_fit_2d_bspline_unchanged(capsys):
    """2D input: one "bspline", in the file's (and the curve's) coordinates, no local one."""
    r = cli(capsys, "fit", EX / "sample_2d.csv", "--model", "smooth", "--bspline-tol", "1e-7",
            "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert "bspline_local" not in doc
    res = el.fit(read_points(EX / "sample_2d.csv"), model="smooth")
    assert el.BSpline.from_dict(doc["bspline"]) == res.to_bspline(1e-7)
