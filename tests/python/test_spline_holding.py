"""Where no free batten passes the points (tension 0: DomainError), what tension to give:
the least that gives a spline a real batten holds. The error says that a small tension may
give one that loops or is unstable (a real batten bent so would snap) and names
el.holding_tension; that function solves the FreeCAD command's ladder 1 .. 1000 / P^2 and
returns the least tension whose spline neither loops nor is unstable; the CLI's spline at
tension 0 names it, verified (the FreeCAD spike's least tension without loops, 10 / P^2,
is unstable: the tension the designer was left to guess)."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli

SPIKE = [(0, 0), (100, 0), (105, 100), (110, 0), (200, 0)]       # mm, the FreeCAD command's
NEEDLE = [(0, 0), (100, 0), (101, 100), (102, 0), (200, 0)]      # 2 mm wide: none holds
# QA19 W2's sharp turn (x 10 mm, sketched by hand), far from the origin
SHARP = np.array([(0, 0), (50, 0), (100, 3), (55, 12), (5, 16)], float) + (12345.6, -7.5)


def polygon(points):
    return float(np.sum(np.hypot(*np.diff(np.asarray(points, float), axis=0).T)))


def quiet(points, tension):
    """The spline at ``tension`` with every warning an error: it neither loops nor is unstable."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return el.elastic_spline(points, tension=tension)


@pytest.mark.parametrize("points, multiple", [(SPIKE, 100), (SHARP, 50)])
def test_the_least_tension_that_holds(points, multiple):
    with pytest.raises(el.DomainError, match="slides off its ducks"):
        el.elastic_spline(points)
    m, tension, sp, P = el.holding_tension(points)
    assert (m, P) == (multiple, pytest.approx(polygon(points), rel=1e-12))
    assert tension == float(f"{m / P ** 2:.3g}")
    assert not sp.loops and not sp.unstable
    again = quiet(points, tension)                    # holds, solved afresh
    assert again.length == sp.length and again.length < 1.2 * P
    # every smaller rung loops, is unstable, or has no spline: the least that holds
    for k in el.spline.HOLD_MULTIPLES[:el.spline.HOLD_MULTIPLES.index(m)]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                low = el.elastic_spline(points, tension=float(f"{k / P ** 2:.3g}"))
            except ValueError:
                continue
        assert low.loops or low.unstable, k


def test_the_spike_at_its_least_tension_without_loops_would_snap():
    """The tension the FreeCAD command started at (10 / P^2): fair, no loops, unstable."""
    P = polygon(SPIKE)
    with pytest.warns(el.UnstableWarning):
        sp = el.elastic_spline(SPIKE, tension=float(f"{10 / P ** 2:.3g}"))
    assert not sp.loops and sp.unstable


def test_none_holds():
    m, tension, sp, P = el.holding_tension(NEEDLE)
    assert (m, tension, sp) == (None, None, None) and P == pytest.approx(polygon(NEEDLE))


def test_the_error_says_a_small_tension_may_not_hold():
    with pytest.raises(el.DomainError) as info:
        el.elastic_spline(SPIKE, tension=0.0)
    msg = str(info.value)
    assert msg.index("give a tension > 0 or a length") < msg.index("a small tension may give")
    for words in ("loops, LoopWarning", "would not hold, UnstableWarning",
                  "el.holding_tension(points)"):
        assert words in msg, msg


def test_cli_names_a_tension_that_holds(capsys, tmp_path):
    path = tmp_path / "spike.csv"
    np.savetxt(path, SHARP, delimiter=",")            # 5 mm ducks 12 m from the origin
    code, _, err = cli(capsys, "spline", path)
    assert code == 2 and "slides off its ducks" in err, err
    assert "--tension 0.0013 (50 / the polygon 196.141 squared) gives a fair spline that holds" \
        in err, err
    assert "LoopWarning" not in err and "holding_tension" not in err       # the API's words
    code, out, err = cli(capsys, "spline", path, "--tension", "0.0013")
    assert code == 0 and "warning" not in err, err


def test_cli_says_where_none_holds(capsys, tmp_path):
    path = tmp_path / "needle.csv"
    np.savetxt(path, NEEDLE, delimiter=",")
    code, _, err = cli(capsys, "spline", path, "--tension", "0")
    assert code == 2 and "no tension of 1 .. 1000 / the polygon squared" in err, err
    assert "give a --length" in err and "gives a fair spline" not in err


@pytest.mark.parametrize("points", [[(0, 0), (0, 0)], [(3, 4)] * 4,
                                    [(0, 0), (1, 0), (1, 0), (2, 1)]])
def test_holding_tension_refuses_bad_points(points):
    """Bad points are a ValueError naming them, as el.elastic_spline's: not "no tension holds"
    (None: the coincident pair was caught as 'none at this tension' at every rung) nor a
    ZeroDivisionError (all points equal: polygon 0)."""
    with pytest.raises(ValueError, match="coincid"):
        el.holding_tension(points)
    with pytest.raises(ValueError, match="coincid"):
        el.holding_tension(points, closed=True)


def test_holding_tension_says_points_that_double_back():
    """Points that double back within their noise are refused before any solve, at every
    tension (DoublesBackError): said as elastic_spline says it, not "none holds"."""
    from test_spline_noise import stroke
    with pytest.raises(el.DoublesBackError, match="double back on themselves"):
        el.holding_tension(stroke())


def test_the_ladder_is_said_from_its_list(capsys, tmp_path, monkeypatch):
    """The ladder's words come from spline.HOLD_MULTIPLES, the list el.holding_tension
    solves: they were typed by hand ('1 .. 1000', '1, 2, 5, 10 .. 1000') in five texts (the
    binding's advice and docstring, the CLI's two, FreeCAD's), which a change of the list
    would have left saying another ladder. Another list is said as it is, and no source
    file types the numbers."""
    import re
    from pathlib import Path

    import libelastica.spline as spline
    assert (spline.ladder_words(), spline.ladder_words(4)) == ("1 .. 1000", "1, 2, 5, 10 .. 1000")
    n = len(spline.HOLD_MULTIPLES)      # all shown: each once, no '..' (revsmall finding 10)
    every = ", ".join(f"{m:g}" for m in spline.HOLD_MULTIPLES)
    assert [spline.ladder_words(s) for s in (n - 1, n, n + 5)] == [every] * 3
    assert f"tries {spline.ladder_words()} / polygon^2" in spline.SMALL_TENSION_TEXT
    monkeypatch.setattr(spline, "HOLD_MULTIPLES", (3, 30, 300))
    path = tmp_path / "needle.csv"
    np.savetxt(path, NEEDLE, delimiter=",")
    code, _, err = cli(capsys, "spline", path, "--tension", "0")
    assert code == 2 and "no tension of 3 .. 300 / the polygon squared" in err, err
    root = Path(__file__).resolve().parents[2]
    typed = [f"{p.relative_to(root)}:{i}" for p in sorted(
        list((root / "python" / "libelastica").glob("*.py")) + list((root / "freecad_wb").rglob("*.py")))
        for i, line in enumerate(p.read_text(encoding="utf-8").splitlines(), 1)
        if re.search(r"\b1 \.\. 1000\b|\b1, 2, 5\b", line) and "HOLD_MULTIPLES =" not in line]
    assert typed == [], typed
