"""One rule for the arc lengths every curve's points / angle / curvature take (QA17 W3):
an int n is a count, n equally spaced over [0, length]; a float or an array (0-d
included) holds arc lengths, a scalar giving numpy's shapes ((2,), ()); s outside
[0, length] raises naming the range, the same for SmoothElastica, HermiteChain,
ElasticSpline and DiscreteElastica (along its polygon: QA19 M1), SmoothElastica /
HermiteChain continuing past the ends with extrapolate=True.
"""
from __future__ import annotations

import numpy as np
import pytest

import libelastica as el

CURVE = el.SmoothElastica(x0=1, y0=2, phi=0.3, mu=1.0, k=0.8, q=0.1, length=5.0)
POLYGON = el.DiscreteElastica(x0=1, y0=2, h=0.1, phi=0.3, z=0.1, q=0.1, k=0.8, n=50)
DUCKS = np.array([[0, 0], [2, 1], [4, 0], [6, -1], [8, 0]], float)


def curves():
    chain = next(c for c in el.hermite((0, 0), (1, 0), (1, 0.2), (1, 0.1), tension=1500.0)
                 if isinstance(c, el.HermiteChain))
    return [CURVE, chain, el.elastic_spline(DUCKS, tension=0.5), POLYGON]


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


# every class of the binding with the rule's methods, and one of it (a new curve class
# must be added here: test_every_curve_class_is_walked)
RULE = ("points", "angle", "curvature")
WALK = {"SmoothElastica": lambda: CURVE, "DiscreteElastica": lambda: POLYGON,
        "HermiteChain": lambda: curves()[1], "ElasticSpline": lambda: curves()[2],
        "BlendCurve": lambda: el.blend_curve(DUCKS, k=0.3),
        "fit's default": lambda: el.fit(POLYGON.points()).curve}
OTHER_RULE = {"BSpline"}      # B-spline parameters, an int not a count (test above)


def test_every_curve_class_is_walked():
    found = {name for name in el.__all__ if isinstance(getattr(el, name), type)
             and any(callable(getattr(getattr(el, name), m, None)) for m in RULE)}
    assert found - OTHER_RULE == set(WALK) - {"fit's default"}


@pytest.mark.parametrize("name", sorted(WALK))
def test_every_curve_takes_an_int_an_array_a_scalar(name):
    """QA19 M1: the default fit's curve, a DiscreteElastica, broke the rule: points(200) a
    TypeError, no angle, curvature(0.5) a TypeError."""
    curve = WALK[name]()
    end = float(curve.nseg) if isinstance(curve, el.BlendCurve) else curve.length
    methods = [m for m in RULE if callable(getattr(curve, m, None))]
    assert methods == (["points"] if isinstance(curve, el.BlendCurve) else list(RULE))
    for m in methods:
        f = getattr(curve, m)
        tail = (2,) if m == "points" else ()
        assert f(7).shape == (7,) + tail
        assert f(np.array([0.0, 0.3 * end, end])).shape == (3,) + tail
        assert np.shape(f(0.3 * end)) == tail
        assert np.array_equal(f(0.3 * end), f([0.3 * end])[0])


def test_a_polygon_along_its_arc_length():
    """DiscreteElastica along its polygon (length (n - 1) h, vertex i at s = i h): its points
    on the segments, its potential theta_i (seed 000 (4.4)) and its vertices' curvature
    (2/h) tan(K/2) (3.4) interpolated linearly; a segment's midpoint has the segment's
    direction, (theta_i + theta_{i+1})/2."""
    d, h = POLYGON, POLYGON.h
    V, theta = d.points(), d.angle()
    assert d.length == (d.n - 1) * h and theta.shape == (d.n,)
    assert np.allclose(d.points(np.arange(d.n) * h), V, atol=1e-14, rtol=0)
    mid = (np.arange(d.n - 1) + 0.5) * h
    assert np.allclose(d.points(mid), (V[:-1] + V[1:]) / 2, atol=1e-14, rtol=0)
    seg = np.diff(V, axis=0)
    assert np.allclose(d.angle(mid), np.unwrap(np.arctan2(seg[:, 1], seg[:, 0])), atol=1e-13,
                       rtol=0)
    kappa = d.vertex_curvature()
    assert np.allclose(kappa[1:-1], d.curvature(), rtol=1e-13, atol=0)
    # (3.4) from the potential: K_i = (theta_{i+1} - theta_{i-1}) / 2
    assert np.allclose(kappa[1:-1], 2 / h * np.tan((theta[2:] - theta[:-2]) / 4), rtol=1e-12)
    # the ends': the interior vertices of the polygon continued one vertex past each end
    longer = el.DiscreteElastica(**{**vars(d), "q": d.q - d.z, "n": d.n + 2})
    assert np.allclose(kappa, longer.curvature(), rtol=1e-12, atol=0)
    assert np.allclose(d.curvature(np.arange(d.n) * h), kappa, rtol=1e-12, atol=1e-14)
    assert np.allclose(d.curvature(mid), (kappa[:-1] + kappa[1:]) / 2, rtol=1e-12)
    assert d.points().shape == (d.n, 2) and d.curvature().shape == (d.n - 2,)   # as before


@pytest.mark.parametrize("k, z", [(1.5, 0.3), (2.5, -0.4), (0.8, 1e-16), (0.6, 0.0)])
def test_a_polygon_potential_is_continuous(k, z):
    """A loop's (k > 1) potential counts its turns (continuous, as SmoothElastica.angle);
    a step z too small for the smooth closed form (1e-16, 0) still gives the potential."""
    d = el.DiscreteElastica(x0=0, y0=0, h=0.2, phi=0.4, z=z, q=0.3, k=k, n=80)
    theta = d.angle()
    assert np.all(np.abs(np.diff(theta)) < np.pi)
    seg = np.diff(d.points(), axis=0)
    assert np.allclose(np.angle(np.exp(1j * ((theta[:-1] + theta[1:]) / 2
                                            - np.arctan2(seg[:, 1], seg[:, 0])))), 0,
                       atol=1e-13)
    if abs(k * z) > 0.1:
        assert abs(theta[-1] - theta[0]) > 2 * np.pi    # turns counted, not wrapped
