"""One rule for the arc lengths every curve's points / angle / curvature take (QA17 W3):
an int n is a count, n equally spaced over [0, length]; a float or an array (0-d
included) holds arc lengths, a scalar giving numpy's shapes ((2,), ()); s outside
[0, length] raises naming the range, the same for SmoothElastica, HermiteChain and
ElasticSpline (SmoothElastica / HermiteChain continue past the ends with extrapolate=True).
"""
from __future__ import annotations

import numpy as np
import pytest

import libelastica as el

CURVE = el.SmoothElastica(x0=1, y0=2, phi=0.3, mu=1.0, k=0.8, q=0.1, length=5.0)
DUCKS = np.array([[0, 0], [2, 1], [4, 0], [6, -1], [8, 0]], float)


def curves():
    chain = next(c for c in el.hermite((0, 0), (1, 0), (1, 0.2), (1, 0.1), tension=1500.0)
                 if isinstance(c, el.HermiteChain))
    return [CURVE, chain, el.elastic_spline(DUCKS, tension=0.5)]


@pytest.mark.parametrize("curve", curves(), ids=lambda c: type(c).__name__)
def test_a_scalar_is_an_arc_length_of_numpy_shape(curve):
    """QA17: ElasticSpline.points(np.array(2.0)) gave the 2 END points (a count),
    SmoothElastica.points(2.0) shape (1, 2); a computed L/2 as np.float64 a TypeError."""
    at = 0.4 * curve.length
    for s in (at, np.float64(at), np.array(at), np.asarray(curve.length / 2), np.float32(at)):
        want = float(s)
        p, k, a = curve.points(s), curve.curvature(s), curve.angle(s)
        assert p.shape == (2,) and np.shape(k) == () and np.shape(a) == ()
        assert np.array_equal(p, curve.points([want])[0])
        assert k == curve.curvature([want])[0] and a == curve.angle([want])[0]


@pytest.mark.parametrize("curve", curves(), ids=lambda c: type(c).__name__)
def test_an_int_is_a_count(curve):
    for n in (2, 7, np.int64(7)):
        assert np.array_equal(curve.points(n), curve.points(np.linspace(0, curve.length, int(n))))
    with pytest.raises(ValueError, match="n must be >= 2, got 1"):
        curve.points(1)


@pytest.mark.parametrize("curve", curves(), ids=lambda c: type(c).__name__)
def test_outside_the_curve_is_refused_naming_the_range(curve):
    """QA17: SmoothElastica.points(2 L) gave a point of the formula continued (-75.6,
    142.4 for an 85-long fit) where ElasticSpline refused: one rule, the curve's range."""
    L = curve.length
    for s in ([-1.0], [0.0, 2 * L], -1.0, np.array(2 * L)):
        with pytest.raises(ValueError, match=r"outside the curve, \[0, "):
            curve.points(s)
    # the ends themselves, and a computed length's rounding, are on it
    assert curve.points([0.0, L, L * (1 + 1e-15)]).shape == (3, 2)


@pytest.mark.parametrize("curve", curves(), ids=lambda c: type(c).__name__)
def test_a_refusal_names_the_method_called(curve):
    """The arc-length messages named the class ('SmoothElastica: arc length s = 10.0 is
    outside the curve'), where the rest of the binding's name the method called (19c2aab:
    'BSpline.curvature: parameter t ...')."""
    L, cls = curve.length, type(curve).__name__
    methods = ["points", "angle", "curvature"] + (["jacobian"] if cls == "SmoothElastica" else [])
    for method in methods:
        with pytest.raises(ValueError, match=rf"^{cls}\.{method}: arc length s = {2 * L!r} is "
                                             r"outside the curve, \[0, "):
            getattr(curve, method)(2 * L)
        with pytest.raises(ValueError, match=rf"^{cls}\.{method}: the number of points n must "
                                             "be >= 2, got 1"):
            getattr(curve, method)(1)


def test_extrapolate_continues_the_elastica():
    """extrapolate=True keeps the formula past the ends (affine_polyline's Newton step on
    a foot point past the end uses it): the same points as the longer curve's."""
    longer = el.SmoothElastica(**{**{n: getattr(CURVE, n) for n in el.core.SMOOTH_PARAMS},
                                  "length": 12.0})
    s = np.array([7.5, 11.0])
    assert np.array_equal(CURVE.points(s, extrapolate=True), longer.points(s))
    assert np.array_equal(CURVE.angle(s, extrapolate=True), longer.angle(s))
    assert np.array_equal(CURVE.curvature(s, extrapolate=True), longer.curvature(s))


def _blends():
    return [el.blend_curve(DUCKS[:4], k=0.3), el.blend_curve(DUCKS, k=0.3),
            el.blend_curve(DUCKS[:4], k=0.3, closed=True)]


@pytest.mark.parametrize("blend", _blends(), ids=["segment", "composite", "closed"])
def test_a_blend_curve_takes_the_rule_over_its_parameter(blend):
    """QA18 M4: BlendCurve.points(5) gave ONE point at t = 5 (extrapolated), points(-0.1)
    and points(1e9) points off the curve, a float shape (1, 2). Its parameter t in [0, nseg]
    (not arc length) now takes the curves' rule: an int a count, a scalar shape (2,), t
    outside raises naming the range."""
    T = float(blend.nseg)
    for n in (2, 5, np.int64(7)):
        assert np.array_equal(blend.points(n), blend.points(np.linspace(0, T, int(n))))
    for t in (0.5 * T, np.float64(0.5 * T), np.array(0.5 * T)):
        p = blend.points(t)
        assert p.shape == (2,) and np.array_equal(p, blend.points([0.5 * T])[0])
    for t in (-0.1, 1e9, [0.0, T + 0.5], np.array(-1.0)):
        with pytest.raises(ValueError, match=r"BlendCurve.points: parameter t.* is outside "
                                             r"the curve, \[0, "):
            blend.points(t)
    with pytest.raises(ValueError, match="n must be >= 2, got 1"):
        blend.points(1)
    assert blend.points().shape == (100 * blend.nseg + 1, 2)      # the default, as before
    assert blend.points([0.0, T, T * (1 + 1e-15)]).shape == (3, 2)


def test_a_bspline_takes_parameters_and_a_scalar_gives_one_value():
    """QA18 M4: BSpline.evaluate(2.0) gave shape (1, 2) where the curves' points(2.0) give
    (2,). Its t are B-spline parameters in its domain, an int too (not a count, unlike the
    curves': n samples are evaluate(np.linspace(*domain, n))); outside raises naming the
    method called and the domain (QA18 M3: it said 'BSpline.derivative', no domain)."""
    b = CURVE.to_bspline()
    for t in (2.0, np.float64(2.0), np.array(2.0), 2):
        assert b.evaluate(t).shape == (2,) and b(t).shape == (2,)
        assert np.array_equal(b.evaluate(t), b.evaluate([2.0])[0])
        assert np.array_equal(b.derivative(t, 2), b.derivative([2.0], 2)[0])
        assert np.shape(b.curvature(t)) == () and b.curvature(t) == b.curvature([2.0])[0]
    lo, hi = b.domain
    for method in ("evaluate", "derivative", "curvature"):
        for t, where in ((hi + 1.0, "t"), ([lo, -1.0], r"t\[1\]"), (int(hi) + 1, "t")):
            with pytest.raises(el.DomainError, match=rf"BSpline.{method}: parameter {where} = "
                                                     rf".* outside the B-spline's domain "
                                                     rf"\[{lo!r}, {hi!r}\]"):
                getattr(b, method)(t)
