"""The way out that a looping or unstable spline's words give, where no tension holds.

The needle (a 179 deg turn between points 2 mm apart, P = 398 mm): at every rung of
HOLD_MULTIPLES / P^2 its spline loops or is an unstable equilibrium (1 .. 100 / P^2 both,
1000 / P^2 loops; el.holding_tension: none), yet LoopWarning said "a larger tension, or a
length, gives one", UnstableWarning "try a larger tension than ...", the CLI "give a larger
--tension": advice that cannot work. Widening the tip works (10 mm: holds at 100 / P^2).
Now the words come from the ladder above the spline's tension (ElasticSpline.holding,
solved once): the tension that holds, or that none does and the points either side of the
sharpest turn to move apart."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli

NEEDLE = [(0, 0), (100, 0), (101, 100), (102, 0), (200, 0)]     # mm, 2 mm wide tip
SHARP = [(0, 0), (5, 0), (10, 0.3), (5.5, 1.2), (0.5, 1.6)]


def polygon(points):
    return float(np.sum(np.hypot(*np.diff(np.asarray(points, float), axis=0).T)))


def spline(points, tension):
    with warnings.catch_warnings(record=True) as rec:
        warnings.simplefilter("always")
        sp = el.elastic_spline(points, tension=tension)
    return sp, {w.category: str(w.message) for w in rec}


@pytest.mark.parametrize("m", [10, 100])
def test_the_needle_says_no_tension_holds(m):
    sp, said = spline(NEEDLE, m / polygon(NEEDLE) ** 2)
    assert sp.loops and sp.unstable
    for cat in (el.LoopWarning, el.UnstableWarning):
        msg = said[cat]
        assert "larger tension than" not in msg and "a larger tension, or a length" not in msg, msg
        assert "no larger tension of 1 .. 1000 / the polygon squared holds" in msg, msg
        assert "move apart points 1 and 3, either side of the sharpest turn (at point 2" in msg, msg
    # what it says is so: no rung holds, and moving points 1 and 3 apart gives one that does
    assert el.holding_tension(NEEDLE)[0] is None
    wide = [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]
    assert el.holding_tension(wide)[0] is not None


def test_where_a_larger_tension_holds_it_is_named_and_holds():
    sp, said = spline(SHARP, 0.01)
    msg = said[el.UnstableWarning]
    m, tension, P = sp.holding()
    assert tension > 0.01 and f"try tension {tension:.3g} ({m:g} / the polygon squared" in msg, msg
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        held = el.elastic_spline(SHARP, tension=tension)
    assert not held.loops and not held.unstable


def test_ignored_warnings_spare_the_ladder():
    """Callers that say their own words (CLI, FreeCAD) ignore the warnings: no solves."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.LoopWarning)
        warnings.simplefilter("ignore", el.UnstableWarning)
        sp = el.elastic_spline(NEEDLE, tension=10 / polygon(NEEDLE) ** 2)
    assert getattr(sp, "_holding", None) is None
    assert sp.holding()[0] is None and sp._holding is not None


def test_the_cli_names_the_turn(tmp_path, capsys):
    path = tmp_path / "needle.csv"
    np.savetxt(path, NEEDLE, delimiter=",")
    code, _, err = cli(capsys, "spline", path, "--tension", f"{10 / polygon(NEEDLE) ** 2:.4g}")
    assert code == 0 and "larger --tension" not in err, err
    assert err.count("move apart points 1 and 3") == 2 and "or try a --length" in err, err
    code, _, err = cli(capsys, "spline", path, "--tension", "0")
    assert code == 2 and "move apart points 1 and 3, either side of the sharpest turn" in err, err


def test_sharpest_turn():
    assert el.spline.sharpest_turn(NEEDLE)[0] == 2
    i, deg = el.spline.sharpest_turn([(0, 0), (4, 0), (4, 4), (0, 4)], closed=True)
    assert deg == pytest.approx(90.0) and i in range(4)
