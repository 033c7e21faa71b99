"""QA21 F6: 40 hand-placed ducks along a wavy run (ducks40.csv, the QA's t4 data), by length
at 1.05 x their polygon: LengthRangeError, the family 'met lengths .. 1.0499 x'. The family
does go on: past its fold at sigma x (mean chord)^2 = -7.29 it comes back up towards sigma = 0,
longer and longer, through a second free batten (~1.07 x) into tension. The length-mode path
stopped short because one continuation step (sigma h^2 -0.90 -> +2.32) landed on the taut
branch (1.008 x) and followed it away (spline_path.c's JUMP). Checked here independently of
the library's formulas: each piece integrated on its own lands on the next duck with the
next piece's curvature, and the tension moves continuously along the lengths."""
from __future__ import annotations

import os
import warnings

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import libelastica as el

HERE = os.path.dirname(os.path.abspath(__file__))


def ducks():
    pts = np.loadtxt(os.path.join(HERE, "ducks40.csv"), delimiter=",", skiprows=1)
    return pts, float(np.hypot(*np.diff(pts, axis=0).T).sum())


def landed(sp, pts):
    """Largest miss of the next duck (relative to the polygon) and of the next curvature
    (times the longest span), each piece integrated from its start state:
    theta' = kappa, 2 kappa'' = sigma kappa - kappa^3."""
    sigma, pos, cur = sp.tension, 0.0, 0.0
    span = np.hypot(*np.diff(pts, axis=0).T).max()
    for j, p in enumerate(sp.pieces):
        h, s = 1e-6, np.array([0.0, 1e-6])
        th0, (k0, k1) = p.angle(s[:1])[0], p.curvature(s)
        dk0 = (k1 - k0) / h + h / 2 * 0.5 * (sigma * k0 - k0 ** 3)

        def rhs(_, y):
            return [np.cos(y[2]), np.sin(y[2]), y[3], y[4], 0.5 * (sigma * y[3] - y[3] ** 3)]

        sol = solve_ivp(rhs, (0.0, p.length), [*pts[j], th0, k0, dk0], rtol=1e-11, atol=1e-12)
        pos = max(pos, np.hypot(*(sol.y[:2, -1] - pts[j + 1])))
        cur = max(cur, abs(sol.y[3, -1] - sp.curvatures[j + 1]) * span)
    return pos, cur


@pytest.mark.parametrize("f", [1.05, 1.06, 1.1])
def test_ducks40_by_length_past_the_jump(f):
    pts, poly = ducks()
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.LoopWarning)
        sp = el.elastic_spline(pts, length=f * poly)
    assert sp.length == pytest.approx(f * poly, rel=1e-9) and not sp.loops
    pos, cur = landed(sp, pts)
    assert pos < 1e-6 * poly and cur < 1e-4, (pos, cur)


def test_ducks40_tension_continues_along_the_lengths():
    """The lengths just below and past the former bound lie on one family: the tension moves
    by a little (x (mean chord)^2: -0.896 at 1.0499 x, -0.887 at 1.05 x), and it crosses
    zero (a second free batten) between 1.06 and 1.08 x."""
    pts, poly = ducks()
    h2 = (poly / (len(pts) - 1)) ** 2
    s = [el.elastic_spline(pts, length=f * poly).tension * h2 for f in (1.049, 1.0499, 1.05, 1.06, 1.08)]
    assert s[0] < s[1] < s[2] < s[3] < 0.0 < s[4], s
    assert abs(s[2] - s[1]) < 0.02, s
