"""The CLI's text report writes coordinates to the curve's size, however far from the origin
(QA18 P1: 'x0=500000, y0=5e+06' for x0 = 499999.97636, 0.024 off on a 16-long fit of rms
0.034; g2quad 'starts at (500000, 5e+06)'), and the binding's summaries name places so."""
from __future__ import annotations

import json
import re

import numpy as np
import pytest

import libelastica as el
from libelastica._text import coordinates
from cli_run import cli

BASE = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.6, q=-1.2, length=4.5)
OFFSET = np.array([5e5, 5e6])


def _points(offset):
    P = BASE.points(np.linspace(0, BASE.length, 160))
    P = P + 0.01 * np.random.default_rng(7).standard_normal(P.shape)
    return 10.0 / np.ptp(P, axis=0).max() * P + offset


def _numbers(text):
    return [float(v) for v in text.split(", ")]


@pytest.mark.parametrize("model", ["smooth", "discrete"])
def test_fit_parameters_line_keeps_the_start_to_the_curves_size(tmp_path, capsys, model):
    src = tmp_path / "gis.csv"
    np.savetxt(src, _points(OFFSET), delimiter=",", fmt="%.17g")
    code, out, err = cli(capsys, "fit", src, "--model", model, "--json", tmp_path / "f.json")
    assert code == 0, err
    rec = json.loads((tmp_path / "f.json").read_text())["curve"]
    m = re.search(r"parameters  x0=([-\d.e+]+), y0=([-\d.e+]+),", out)
    x0, y0 = float(m.group(1)), float(m.group(2))
    size = rec.get("length") or rec["h"] * (rec["n"] - 1)
    # 6 digits of the curve's size: within 1e-6 of it (%g: 0.024 off, 1.5e-3 of it)
    assert abs(x0 - rec["x0"]) < 1e-5 * size and abs(y0 - rec["y0"]) < 1e-5 * size, (out, rec)


def test_g2quad_ends_keep_the_curves_size(tmp_path, capsys):
    src = tmp_path / "gis.csv"
    np.savetxt(src, _points(OFFSET), delimiter=",", fmt="%.17g")
    code, out, err = cli(capsys, "g2quad", src, "--fit", "--edges", 24, "--json",
                         tmp_path / "g.json")
    assert code == 0, err
    rec = json.loads((tmp_path / "g.json").read_text())
    m = re.search(r"starts at \(([^)]*)\), ends at \(([^)]*)\)", out)
    ends = np.array(rec["ends"])[[0, -1]]
    size = np.ptp(np.array(rec["polyline"]), axis=0).max()
    for said, want in zip((m.group(1), m.group(2)), ends):
        assert np.abs(np.array(_numbers(said)) - want).max() < 1e-5 * size, (said, want)


def test_coordinates_add_digits_for_the_offset_only():
    assert coordinates([499999.97636, 4999999.99333], 16.3) == "499999.97636, 4999999.99333"
    assert coordinates([-0.0236447123, 1.5], 16.3) == "-0.0236447, 1.5"   # as %.6g
    assert coordinates([1e-7], 1e-6) == "1e-07"


def _place(text, pattern):
    return [np.array(_numbers(g)) for g in re.search(pattern, text).groups()]


def test_summaries_name_places_to_the_points_size():
    """misfit_summary's corner and wander_summary's two points at QA18's GIS offset, by the
    CLI's helper (coordinates): they read '(5e+05, 5e+06)', 4 digits of the offset (main);
    now within 1e-4 of the points' size (4 digits of it), and as before at the origin."""
    from test_misfit import ship_line
    P = ship_line()
    with pytest.warns(el.MisfitWarning):
        m = el.misfit(P, el.fit(P, model="smooth").distances)
    size = np.ptp(P, axis=0).max()
    at = r"at point \d+ \(counted from 0; at \(([^)]*)\)\)"
    assert _place(el.misfit_summary(m, P), at)[0].tolist() == [
        float(f"{v:.4g}") for v in P[m.corner]]                   # at the origin: as before
    said = el.misfit_summary(m, P + OFFSET)
    assert np.abs(_place(said, at)[0] - (P + OFFSET)[m.corner]).max() < 1e-4 * size, said
    said = el.wander_summary(3, P + OFFSET)
    for got, want in zip(_place(said, r"at \(([^)]*)\) and \(([^)]*)\)\)"), (P + OFFSET)[3:5]):
        assert np.abs(got - want).max() < 1e-4 * size, said
