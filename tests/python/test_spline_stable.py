"""The free batten (tension 0) that is an equilibrium but no minimum: elastic_spline raises
the DomainError of a batten that slides off its ducks, naming the span (spline_stable.c);
stable ones are returned as before."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli

# QA19 W2: returned without a warning (E 2.2926, length 21.99), an unstable equilibrium
SHARP = [(0, 0), (5, 0), (10, 0.3), (5.5, 1.2), (0.5, 1.6)]


def turn(deg):
    """5 ducks: two along +x, a tip at (10, 0), two going back at deg from the incoming
    direction (QA19's sweep)."""
    t = np.radians(deg)
    d = np.array([np.cos(t), np.sin(t)])
    tip = np.array([10.0, 0.0])
    return np.array([(0, 0), (5, 0), tip, tip + 4.5 * d, tip + 9.5 * d + [0, 0.5]])


@pytest.mark.parametrize("points", [SHARP] + [turn(a) for a in (160, 163, 165, 167, 169, 170, 172)])
def test_an_unstable_free_batten_slides_off(points):
    with pytest.raises(el.DomainError, match="slides off its ducks") as info:
        el.elastic_spline(points)
    msg = str(info.value)
    assert "unstable equilibrium" in msg and "from point 2 to 3" in msg, msg
    assert "give a tension > 0 or a length" in msg


@pytest.mark.parametrize("points", [
    [(0, 0), (3.1, 1.2), (7.9, 1.6), (10.2, 0.4), (15.0, -1.9)],
    [(0, 0), (5, 0), (9, 1.5), (8, 5), (6, 9)],
    [(0, 0), (5, 0), (9.5, 1.0), (6.5, 3.5), (2.5, 5.5)],
    [(0, 0), (1, 1), (2, 0), (3, 1), (4, 0), (5, 1)],
    turn(140)])
def test_a_stable_free_batten_is_returned(points):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sp = el.elastic_spline(points)
    assert sp.tension == 0.0 and not sp.loops
    assert np.allclose(sp.points(np.r_[0, np.cumsum([p.length for p in sp.pieces])]), points, atol=1e-9)


def test_the_cli_says_it_slides_off(tmp_path, capsys):
    f = tmp_path / "ducks.csv"
    f.write_text("x,y\n" + "\n".join(f"{x},{y}" for x, y in SHARP) + "\n")
    code, out, err = cli(capsys, "spline", f)
    assert code != 0 and "from point 2 to 3" in err, err
