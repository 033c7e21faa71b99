"""Elastic splines through scan points that double back within their noise (QA16 F4): a
hand-drawn stroke where the hand slowed has points closer than their jitter, its polygon
runs forward, back and forward again (a Z) many times; no batten passes it, at tension 0
(it slides off) nor under tension or by length (the solver found none in 0.5 / 6 s).
elastic_spline says so before solving, names the places and points to el.fit or thinning;
splines the tests and QA sketches solve have no such places (their Zs are long spans)."""
from __future__ import annotations

import numpy as np
import pytest

import libelastica as el
import libelastica.spline as spline_mod
from libelastica.spline import back_steps

from test_spline_loops import RW15


def stroke():
    """300 points along a 120 deg arc of radius 100, drawn 30 x slower in its middle
    fifth, jitter 0.35: the QA's handdrawn.csv in kind (46 back-steps)."""
    n = 300
    speed = np.interp(np.linspace(0, 1, n - 1), [0, .3, .5, .7, 1], [1, 1, 1 / 30, 1, 1])
    t = np.concatenate([[0.0], np.cumsum(speed)])
    t *= np.radians(120) / t[-1]
    arc = np.column_stack([100 * np.sin(t), 100 * (1 - np.cos(t))])
    return arc + np.random.default_rng(16).normal(0.0, 0.35, (n, 2))


def is_z(P, i):
    """The span from point i to i + 1 runs back against the spans before and after it."""
    d = np.diff(P[i - 1:i + 3], axis=0)
    return np.dot(d[0], d[1]) < 0 and np.dot(d[1], d[2]) < 0


class Unsolved:
    """The library, with el_spline_solve counted (refused input never reaches it); with
    ``status``, the solve returns it without solving."""
    def __init__(self, lib, status=None):
        self.lib, self.solves, self.status = lib, 0, status

    def __getattr__(self, name):
        if name != "el_spline_solve":
            return getattr(self.lib, name)
        self.solves += 1
        if self.status is None:
            return self.lib.el_spline_solve
        return lambda *args: self.status


@pytest.mark.parametrize("how", [{}, {"tension": 1e-4}, {"tension": 0.01}, {"tension": 1.0},
                                 {"length": 1.05}, {"length": 1.5}])
def test_points_that_double_back_are_refused_before_the_solve(how, monkeypatch):
    P = stroke()
    places = back_steps(P)
    assert len(places) >= spline_mod.BACK_STEPS_MANY and all(is_z(P, i) for i in places)
    extent = np.ptp(P, axis=0).max()
    assert all(np.hypot(*(P[i + 1] - P[i])) < 0.02 * extent for i in places)
    if "length" in how:
        how = {"length": how["length"] * np.hypot(*np.diff(P, axis=0).T).sum()}
    counted = Unsolved(spline_mod.lib)
    monkeypatch.setattr(spline_mod, "lib", counted)
    with pytest.raises(el.DoublesBackError) as exc:
        el.elastic_spline(P, **how)
    assert counted.solves == 0            # refused at once, not after seconds of solving
    msg = str(exc.value)
    assert isinstance(exc.value, el.DomainError) and exc.value.places == places
    assert f"double back on themselves {len(places)} times" in msg
    first = ", ".join(f"{i} to {i + 1}" for i in places[:4])
    assert f"from point {first} and {len(places) - 4} more" in msg
    assert "el.fit" in msg and "thin" in msg and "give a tension" not in msg


def test_the_advice_works():
    """el.fit fairs the stroke to its noise; every 20th point is a spline without loops."""
    P = stroke()
    assert el.fit(P, model="smooth").rms < 0.4
    thin = P[::20]
    assert back_steps(thin) == []
    sp = el.elastic_spline(thin)
    assert not sp.loops


def test_a_few_are_named_when_no_spline_is_found(monkeypatch):
    """Fewer back-steps are not refused (a spline may pass them); where none is found the
    error names them (first: the free batten's 'slides off', then the tension advice)."""
    P = stroke()[::6]
    places = back_steps(P)
    assert 0 < len(places) < spline_mod.BACK_STEPS_MANY
    with pytest.raises(el.DomainError) as exc:
        el.elastic_spline(P)
    msg = str(exc.value)
    assert not isinstance(exc.value, el.DoublesBackError)
    assert "doubles back" in msg and f"from point {places[0]} to {places[0] + 1}" in msg
    assert msg.index("doubles back") < msg.index("give a tension")
    # where the solver reaches none under tension (its status forced: which tensions solve
    # these points is the solver's business, the test_spline suites')
    failing = Unsolved(spline_mod.lib, status=spline_mod.lib.EL_ENOCONV)
    monkeypatch.setattr(spline_mod, "lib", failing)
    with pytest.raises(el.NotConvergedError, match=f"reached; their polygon doubles back .* "
                                                   f"from point {places[0]} to {places[0] + 1} "):
        el.elastic_spline(P, tension=1e-3)
    assert failing.solves == 1


def test_designs_whose_polygon_doubles_back_are_no_noise():
    """A random walk's Zs (spans >= 0.06 of its extent), a zigzag's right angles, a star's
    tips: none is a back-step, so they solve (or fail) as before."""
    assert all(is_z(RW15, i) for i in (4, 5, 6)) and back_steps(RW15) == []
    assert back_steps([[i, i % 2] for i in range(10)]) == []
    star = [[r * np.cos(a), r * np.sin(a)] for a, r in
            zip(np.linspace(0, 2 * np.pi, 16, endpoint=False), [20, 6] * 8)]
    assert back_steps(star, closed=True) == []


def test_closed_back_steps_count_the_closing_span():
    P = np.array([[0, 0], [10, 0], [20, 0], [19.9, 0.1], [30, 0], [40, 3], [50, 10]], float)
    assert back_steps(P) == [2]
    assert back_steps(np.roll(P, -3, axis=0), closed=True) == [6]   # from the last to the first
    assert back_steps(np.roll(P, -2, axis=0), closed=True) == [0]


def test_cli_says_it_at_once(capsys, tmp_path):
    """`elastica spline` of such points, by tension or length: exit 2 with the places."""
    from cli_run import cli
    path = tmp_path / "stroke.csv"
    P = stroke()
    np.savetxt(path, P, delimiter=",")
    places = back_steps(P)
    for how in (["--tension", "0"], ["--tension", "0.01"], ["--length", "400"]):
        code, _, err = cli(capsys, "spline", path, *how)
        assert code == 2 and f"from point {places[0]} to {places[0] + 1}" in err
        assert "elastica fit" in err and "slides off its ducks; give" not in err


def test_a_closed_noisy_scan_is_advised_what_works_for_a_closed_outline():
    """QA20 F10: a noisy 400-point cam scan through elastic_spline(closed=True) was advised
    to 'fair the points with el.fit', which fits open curves only. The advice for a closed
    outline names a thinning that doubles back nowhere, and the spline through it is found
    and follows the cam (failed before: no thinning named, el.fit advised)."""
    rng = np.random.default_rng(2)
    t = np.sort(rng.uniform(0, 2 * np.pi, 400))
    cam = lambda a: np.column_stack([(30 + 8 * np.cos(a) + 3 * np.sin(2 * a)) * np.cos(a),
                                     (30 + 8 * np.cos(a) + 3 * np.sin(2 * a)) * np.sin(a)])
    S = cam(t) + rng.normal(0, 0.05, (400, 2))
    with pytest.raises(el.DoublesBackError) as exc:
        el.elastic_spline(S, closed=True)
    said = str(exc.value)
    assert "open curves only" in said and "fair the points with el.fit" not in said, said
    import re
    k = int(re.search(r"points\[::(\d+)\]", said).group(1))
    assert not back_steps(S[::k], True)
    sp = el.elastic_spline(S[::k], closed=True)          # the advice taken works
    X = np.vstack([p.points(np.linspace(0, p.length, 40)) for p in sp.pieces])
    T = cam(np.linspace(0, 2 * np.pi, 4000))
    assert np.sqrt(((X[:, None, :] - T[None]) ** 2).sum(-1)).min(axis=1).max() < 10 * 0.05
    # an open scan keeps its advice: el.fit fits it
    with pytest.raises(el.DoublesBackError, match="fair the points with el.fit"):
        el.elastic_spline(stroke())
