"""A spline by tension > 0 or by length that is an equilibrium but no minimum
(el_spline_result.unstable, spline_stable.c): returned, with ElasticSpline.unstable and an
UnstableWarning saying in a designer's words that a batten bent so would snap to another
shape; the CLI says it; stable splines raise nothing (QA19 W2's ducks under tension were
returned as if they were the batten)."""
from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli

SHARP = [(0, 0), (5, 0), (10, 0.3), (5.5, 1.2), (0.5, 1.6)]
SPIKE = [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]     # mm, the FreeCAD command's
# a hand-sketched stroke far from the origin, uneven spacing (stable at every tension here)
SKETCH = np.array([(0.0, 0.0), (3.1, 1.2), (7.9, 1.6), (10.2, 0.4), (15.0, -1.9), (21.3, -2.2)]) \
    + (12345.6, -7.5)


def polygon(points):
    return float(np.sum(np.hypot(*np.diff(np.asarray(points, float), axis=0).T)))


def turn(deg):
    t = np.radians(deg)
    d = np.array([np.cos(t), np.sin(t)])
    tip = np.array([10.0, 0.0])
    return np.array([(0, 0), (5, 0), tip, tip + 4.5 * d, tip + 9.5 * d + [0, 0.5]])


@pytest.mark.parametrize("points, by", [(SHARP, {"tension": 1e-2}), (turn(170), {"tension": 1e-3}),
                                        (turn(165), {"tension": 0.03}), (SPIKE, {"tension": 6.57e-5}),
                                        (turn(170), {"length": 1.3})])
def test_an_unstable_spline_warns(points, by):
    by = {k: v * polygon(points) if k == "length" else v for k, v in by.items()}  # x the polygon
    with pytest.warns(el.UnstableWarning) as rec:
        sp = el.elastic_spline(points, **by)
    # by length 1.3 x: it crosses itself too (LoopWarning beside)
    assert sp.unstable and sp.unstable_span == 2 and sp.loops == ("length" in by)
    msg = str(next(w.message for w in rec if w.category is el.UnstableWarning))
    assert "unstable equilibrium" in msg and "snap to another shape" in msg, msg
    assert "between points 2 and 3" in msg and ("solved: it holds" in msg if "tension" in by
                                           else "another length" in msg), msg
    # the spline itself is the one returned before: G2 through its ducks
    ends = np.r_[0, np.cumsum([p.length for p in sp.pieces])]
    assert np.allclose(sp.points(ends), points, atol=1e-9 * np.ptp(points))


@pytest.mark.parametrize("points, by", [(SHARP, {"tension": 0.3}), (turn(170), {"tension": 1.0}),
                                        (turn(120), {"tension": 1e-2}), (SPIKE, {"tension": 1e-3}),
                                        (SKETCH, {"tension": 1e-4}), (SKETCH, {"tension": 1.0}),
                                        (turn(120), {"length": 1.2}), (SKETCH, {"length": 1.3})])
def test_a_stable_spline_is_quiet(points, by):
    by = {k: v * polygon(points) if k == "length" else v for k, v in by.items()}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sp = el.elastic_spline(points, **by)
    assert not sp.unstable and sp.unstable_span is None


def test_the_cli_says_it(tmp_path, capsys):
    f = tmp_path / "ducks.csv"
    f.write_text("x,y\n" + "\n".join(f"{x},{y}" for x, y in SHARP) + "\n")
    code, out, err = cli(capsys, "spline", f, "--tension", "0.01", "--json", tmp_path / "s.json")
    assert code == 0 and "unstable equilibrium" in err and "snap to another shape" in err, err
    assert "give --tension 0.13 (50 / the polygon squared, solved: it holds)" in err and \
        "between points 2 and 3" in err, err
    assert "UnstableWarning" not in err and ".py:" not in err, err
    assert json.loads((tmp_path / "s.json").read_text())["unstable"] is True
    code, out, err = cli(capsys, "spline", f, "--tension", "0.3")
    assert code == 0 and "unstable" not in err, err


def test_one_summary_for_every_caller(tmp_path, capsys):
    """UnstableWarning, the CLI's warning and the FreeCAD batten's caution say one summary,
    ElasticSpline.unstable_text, each with its own way out (a keyword, a flag, a property):
    three hand-written copies had drifted apart ('from point 2 to 3' vs 'between points 2
    and 3', tension to 4 or 6 digits)."""
    with pytest.warns(el.UnstableWarning) as rec:
        sp = el.elastic_spline(SHARP, tension=0.01)
    msg = str(next(w.message for w in rec if w.category is el.UnstableWarning))
    assert msg == "elastic_spline: " + sp.unstable_text(
        "try " + sp.holding_text()), msg
    f = tmp_path / "ducks.csv"
    f.write_text("x,y\n" + "\n".join(f"{x},{y}" for x, y in SHARP) + "\n")
    code, out, err = cli(capsys, "spline", f, "--tension", "0.01")
    fix = "give " + sp.holding_text(lambda t: f"--tension {t:.3g}", "a --length")
    assert code == 0 and f"warning: {sp.unstable_text(fix)}\n" in err, err
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert el.elastic_spline(SHARP, tension=0.3).unstable_text("x") == ""
