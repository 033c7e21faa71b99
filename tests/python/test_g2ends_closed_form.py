"""g2ends' closed form of a G2 end parabola's start (QA25 F6: g2_quadratic spent 66 % of its
84 ms in ~230 splines built a call to read their start curvature): _start_parabola gives the
same bits as the spline el_affine_g2_bspline builds (its first Bezier segment's curvature,
det(c - P, m_2 - c) / (2 |c - P|^3), and c - P), NaN where the C function refuses the start,
and g2_quadratic builds a few splines a piece, not one per trial."""
from __future__ import annotations

import math

import numpy as np
import pytest

import libelastica as el
from libelastica import g2ends
from libelastica._ffi import DomainError
from libelastica.affine import g2_bspline


def _polyline(rng, offset):
    """An affine arc-length-ish polyline of 8 vertices (a noisy arc), at ``offset``."""
    th = np.cumsum(rng.uniform(0.05, 0.6, 8)) * rng.choice([-1, 1])
    r = 10 ** rng.uniform(-2, 3)
    x = r * np.c_[np.cos(th), np.sin(th)] + rng.normal(0, 1e-3 * r, (8, 2))
    return x + offset


@pytest.mark.parametrize("offset", [(0.0, 0.0), (512345.678, 5012345.432), (-3.5, 7.25)])
def test_start_parabola_is_the_splines_start_bit_for_bit(offset):
    rng = np.random.default_rng(11)
    same = refused = 0
    for _ in range(400):
        x = _polyline(rng, np.array(offset))
        start = x[0] + rng.normal(0, 0.3, 2) * np.linalg.norm(x[1] - x[0])
        pts = [tuple(map(float, x[i])) for i in (1, 2, 3)]
        got = g2ends._start_parabola(tuple(map(float, start)), *pts)
        try:
            bs = g2_bspline(x, start, None)
        except DomainError:
            assert got is not None and not isinstance(got, tuple) and np.isnan(got)
            refused += 1
            continue
        assert isinstance(got, tuple)
        d = bs.poles[1] - bs.poles[0]
        assert got[0] == g2ends._start_curvature(bs)     # bit for bit, not to a tolerance
        assert (got[1], got[2]) == (d[0], d[1])
        same += 1
    assert same > 200 and refused > 20      # both kinds met


def test_defining_identity_start_curvature_of_the_parabola():
    """The closed form is the end parabola's: its curvature at the start, taken from three
    points of the spline near it (Menger), tends to it."""
    rng = np.random.default_rng(3)
    for _ in range(20):
        x = _polyline(rng, np.zeros(2))
        start = x[0]
        try:
            bs = g2_bspline(x, start, None)
        except DomainError:
            continue
        k = g2ends._start_parabola(tuple(start), *[tuple(x[i]) for i in (1, 2, 3)])[0]
        h = 1e-4 * (bs.knots[1] - bs.knots[0])
        a, b, c = bs(np.array([bs.knots[0], bs.knots[0] + h, bs.knots[0] + 2 * h]))
        ab, bc, ac = b - a, c - b, c - a
        menger = 2 * (ab[0] * bc[1] - ab[1] * bc[0]) / (
            np.linalg.norm(ab) * np.linalg.norm(bc) * np.linalg.norm(ac))
        assert menger == pytest.approx(k, rel=1e-3)


@pytest.fixture
def built(monkeypatch):
    """The splines g2ends builds (g2_bspline's calls), counted in the list returned."""
    calls = []
    real = g2ends.g2_bspline

    def counting(*a, **k):
        calls.append(1)
        return real(*a, **k)
    monkeypatch.setattr(g2ends, "g2_bspline", counting)
    return calls


def test_g2_quadratic_builds_a_few_splines_a_piece(built):
    """An S (2 pieces) at 24 edges, both ends' tangents held: each trial of _match_start /
    _hold_start is the closed form; the splines built are the pieces' and their candidates."""
    c = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=0.8, q=-0.6, length=4.0)
    g = el.g2_quadratic(c, 24)
    assert len(g.bsplines) == 2
    assert len(built) <= 4, len(built)     # 230 a call before


def test_the_tangent_residual_is_the_splines_bit_for_bit():
    """_match_tangent's residual (g2qfix's _slide_x1: the angle from the held tangent to the
    start leg poles[1] - poles[0]) from the closed form's c - P equals the built spline's."""
    rng = np.random.default_rng(12)
    same = 0
    for _ in range(400):
        x = _polyline(rng, np.array((512345.678, 5012345.432)) * rng.integers(0, 2))
        start = x[0] + rng.normal(0, 0.3, 2) * np.linalg.norm(x[1] - x[0])
        got = g2ends._start_parabola(tuple(map(float, start)), *[tuple(map(float, x[i])) for i in (1, 2, 3)])
        try:
            bs = g2_bspline(x, start, None)
        except DomainError:
            continue
        T = rng.normal(size=2)
        T /= np.hypot(*T)
        d = bs.poles[1] - bs.poles[0]
        want = math.atan2(d[0] * T[1] - d[1] * T[0], d @ T)     # the residual on the poles
        assert g2ends._angle(got[1], got[2], (float(T[0]), float(T[1]))) == want
        same += 1
    assert same > 200


def _ends_moved(x, start, end, kappa, T):
    return (g2ends._match_start(x, start, end, kappa), g2ends._match_tangent(x, start, end, T),
            g2ends._hold_start(x, start, end, kappa, T))


def test_closed_form_trials_give_the_built_splines_ends(monkeypatch):
    """_match_start, _match_tangent and _hold_start with every trial in closed form return
    the same polylines, bit for bit, as with every trial's spline built (_start_parabola
    made to say 'the C function decides'): the search is unchanged, only its cost."""
    rng = np.random.default_rng(5)
    cases = []
    for i in range(60):
        th = np.cumsum(np.full(10, rng.uniform(0.05, 0.3))) * rng.choice([-1, 1])
        r = 10 ** rng.uniform(-1, 3)
        x = r * np.c_[np.cos(th), np.sin(th)] + np.array([512345.678, 5012345.432]) * (i % 3 == 0)
        start = x[0] + rng.normal(0, 0.02, 2) * r * (th[1] - th[0])
        end = x[-1]
        T = np.array([-np.sin(th[0]), np.cos(th[0])]) * np.sign(th[1] - th[0])
        kappa = float(np.sign(th[1] - th[0])) / r * rng.uniform(0.8, 1.2)
        cases.append((x, start, end, kappa, T))
    fast = [_ends_moved(*c) for c in cases]
    monkeypatch.setattr(g2ends, "_start_parabola", lambda *a: None)
    built = [_ends_moved(*c) for c in cases]
    found = 0
    for a, b in zip(fast, built):
        for za, zb in zip(a, b):
            assert (za is None) == (zb is None)
            if za is not None:
                assert np.array_equal(za, zb)
                found += 1
    assert found > 100


@pytest.mark.parametrize("closed", [False, True])
def test_g2_quadratic_of_a_free_or_closed_spline_builds_a_few_splines(built, closed):
    """A free (natural-end) spline holds each end's tangent alone (_match_tangent) and a
    closed one holds both ends at its seam: each trial in closed form too."""
    ducks = np.array([(500, 720), (680, 620), (730, 360), (640, 110), (500, 40), (330, 110),
                      (250, 360), (320, 620)], float) if closed else np.array(
        [(520, 700), (380, 640), (330, 520), (450, 420), (580, 320), (560, 180), (420, 120),
         (300, 170)], float)
    g = el.g2_quadratic(el.elastic_spline(ducks, closed=closed), 24)
    assert len(built) <= 4, len(built)
    assert g.source_end_tangent_error < 1e-12     # the ends held (exactly, to rounding)


def test_an_end_the_c_function_refuses_is_refused_in_closed_form_too(monkeypatch):
    """The end side (_end_refused, checked once) says what el_affine_g2_bspline says for the
    end point on either side of the last joint's tangent line, far and a hair off it: at
    1e-32 off (mu ~ 1e-16) its knots lam + (m - 3) + mu and lam + (m - 3) round equal and
    the C call refuses (EL_EDOM) although mu^2 > 0; the slides then find no end, as with
    every trial's spline built (revE: _end_refused said False, _match_start found one)."""
    t = np.linspace(0.0, 1.2, 8)
    x = 5.0 * np.c_[np.cos(t), np.sin(t)]
    v = x[6] - x[5]
    ang = math.atan2(v[1], v[0])
    R = np.array([[math.cos(ang), math.sin(ang)], [-math.sin(ang), math.cos(ang)]])
    x = (x - x[5]) @ R.T                    # the last edge on the x axis, exactly
    x[5] = 0.0
    x[6, 1] = 0.0
    T = (x[1] - x[0]) / np.linalg.norm(x[1] - x[0])   # the start's own leg
    cases = []
    for off in (0.5, 1e-3, 1e-20, 1e-30, 1e-32, 1e-34, 1e-40, 0.0):
        for sgn in (1.0, -1.0):
            cases.append(np.array([1.3 * x[6, 0], sgn * off]))
    refused = 0
    fast = []
    for end in cases:
        try:
            g2_bspline(x, x[0], end)
            c_refuses = False
        except DomainError:
            c_refuses = True
        r = g2ends._end_refused(x, x[0], end)
        assert r is None or r == c_refuses, (end, r, c_refuses)
        refused += c_refuses
        fast.append((g2ends._match_start(x, x[0], end, 0.3),
                     g2ends._match_tangent(x, x[0], end, T)))
    assert refused >= 6
    monkeypatch.setattr(g2ends, "_start_parabola", lambda *a: None)
    for end, (fs, ft) in zip(cases, fast):
        bs = g2ends._match_start(x, x[0], end, 0.3)
        bt = g2ends._match_tangent(x, x[0], end, T)
        for a, b in ((fs, bs), (ft, bt)):
            assert (a is None) == (b is None), end
            if a is not None:
                assert np.array_equal(a, b)
