"""A report picture of many points is drawn thinned to what is visible (QA17 S1: 10^5 points
drew 10^5 markers and residual segments, a 38 MB SVG in 11.6 s); a small one is drawn whole."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica import report
from libelastica.io import read_points

SAMPLE = Path(__file__).resolve().parents[2] / "examples" / "sample_2d.csv"


@pytest.fixture
def fitted():
    return el.fit(read_points(SAMPLE), model="smooth")


def dense(curve, n):
    s = np.linspace(0.0, curve.length, n)
    xy = curve.points(s)
    return xy + 0.01 * np.random.default_rng(1).standard_normal(xy.shape), xy


def test_many_points_are_drawn_thinned(fitted, tmp_path, monkeypatch):
    monkeypatch.setenv("LIBELASTICA_NO_MATPLOTLIB", "1")      # the built-in SVG: countable
    data, feet = dense(fitted.curve, 100_000)
    pic = report.fit_picture(data, fitted.curve, model_points=feet)
    out = tmp_path / "big.svg"
    report.save_picture(pic, out)
    svg = out.read_text()
    assert len(svg) < 2_000_000                                # main: 10^5 of each, ~20 MB
    markers, residuals = svg.count("<rect x="), svg.count('stroke="#1f77b4" stroke-width="0.8"')
    assert 1000 <= markers <= 2 * report.MAX_MARKS + 10       # data + the data polygon's curvature
    assert 1000 <= residuals <= report.MAX_MARKS
    assert "of the 100000 points" in svg                       # the picture says so
    # the first and last data points are drawn (evenly along them, ends kept)
    thin = report.thinned(pic)
    np.testing.assert_array_equal(thin.layers[0].xy[[0, -1]], data[[0, -1]])
    np.testing.assert_array_equal(thin.residuals[1][[0, -1]], feet[[0, -1]])


def test_small_pictures_are_drawn_whole(fitted):
    data = read_points(SAMPLE)
    pic = report.fit_picture(data, fitted.curve, fitted.initial, model_points=fitted.foot_points())
    assert report.thinned(pic) is pic
