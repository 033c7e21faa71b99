"""One rule for == over every public result and curve (QA18 M2): value equality, arrays by
np.array_equal with shapes and dtypes, NaN equal to NaN; == never raises; pickle / copy /
deepcopy round trips compare equal; a changed value compares unequal."""
from __future__ import annotations

import copy
import dataclasses
import pickle
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica._values import same

C = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.6, q=-1.2, length=4.5)
S = el.SmoothElastica(x0=0, y0=0, phi=-0.5, mu=1.0, k=0.8, q=-1.0, length=6.0)
RNG = np.random.default_rng(1)
P = C.points(np.linspace(0, 4.5, 120)) + 0.01 * RNG.standard_normal((120, 2))
PS = S.points(90) + 0.01 * RNG.standard_normal((90, 2))

BUILD = {
    "FitResult smooth": lambda: el.fit(P, model="smooth"),
    "FitResult discrete": lambda: el.fit(P),
    "KeylineFit": lambda: el.fit_keyline(PS, model="smooth"),
    "G2Quadratic": lambda: el.g2_quadratic(C, 24),
    "AffinePolyline": lambda: el.affine_polyline(C, 24),
    "ElasticSpline": lambda: el.elastic_spline(P[::20], tension=0.5),
    "HermiteChain": lambda: next(s for s in el.hermite((0, 0), (1, 0.05), (10, 0), (1, -0.05),
                                                       tension=900.0)
                                 if isinstance(s, el.HermiteChain)),
    "HermiteSolutions": lambda: el.hermite((0, 0), (0, 1), (2, 0), (0, -1), length=4.0),
    "EllipticBlend": lambda: el.EllipticBlend(k=0.3, d=2.0),
    "MQBlend": lambda: el.MQBlend(0.5),
    "BlendCurve": lambda: el.blend_curve(P[::30], k=0.3),
    "Ordering": lambda: el.out_of_order(P),
    "Frame": lambda: el.plane_fit(np.c_[P, 0.1 * P[:, 0]])[1],
    "PreparedKeyline": lambda: el.prepare_keyline(PS, None, 0),
    "SmoothElastica": lambda: C,
    "BSpline": lambda: C.to_bspline(),
}


def build(name):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return BUILD[name]()


@pytest.mark.parametrize("name", sorted(BUILD))
def test_equal_by_value_through_copies_and_a_second_build(name):
    """QA18 M2: FitResult, KeylineFit, G2Quadratic, AffinePolyline raised 'truth value of an
    array is ambiguous' on ==; ElasticSpline, HermiteChain, EllipticBlend compared by
    identity (EllipticBlend(k=0.3, d=2.0) == EllipticBlend(k=0.3, d=2.0) False), BlendCurve's
    pickle False, an Ordering with along = nan unequal to its own copy."""
    a = build(name)
    for b in (pickle.loads(pickle.dumps(a)), copy.copy(a), copy.deepcopy(a), build(name)):
        assert (a == b) is True and (a != b) is False, name
    assert (a == "something else") is False and (a != None) is True   # noqa: E711


def _changed(obj):
    """obj with one array (or number) changed by one ulp, or None."""
    if dataclasses.is_dataclass(obj):
        for f in dataclasses.fields(obj):
            v = getattr(obj, f.name)
            if isinstance(v, np.ndarray) and v.dtype.kind == "f" and v.size:
                w = v.copy()
                w.flat[-1] = np.nextafter(w.flat[-1], np.inf)
                return dataclasses.replace(obj, **{f.name: w})
    if hasattr(obj, "__dict__"):
        for k, v in vars(obj).items():
            if not k.startswith("_") and isinstance(v, np.ndarray) and v.size:
                other = copy.copy(obj)
                w = v.copy()
                w.flat[-1] = np.nextafter(w.flat[-1], np.inf)
                setattr(other, k, w)
                return other
    return None


@pytest.mark.parametrize("name", ["FitResult smooth", "FitResult discrete", "KeylineFit",
                                  "G2Quadratic", "AffinePolyline", "ElasticSpline",
                                  "BlendCurve"])
def test_one_ulp_of_one_array_makes_them_unequal(name):
    a = build(name)
    b = _changed(a)
    assert b is not None and (a == b) is False and (a != b) is True


def test_the_rule_shapes_dtypes_nan():
    x = np.arange(6.0)
    assert same(x, x.copy()) and not same(x, x.reshape(2, 3)) and not same(x, x.astype(np.float32))
    assert not same(x, list(x)) and same(np.array([np.nan, 1.0]), np.array([np.nan, 1.0]))
    assert same(float("nan"), float("nan")) and not same(1.0, float("nan"))
    assert el.EllipticBlend(k=0.3) != el.EllipticBlend(k=0.31)
    assert el.EllipticBlend(k=0.3) != el.MQBlend(0.3)
    assert hash(el.EllipticBlend(k=0.3, d=2.0)) == hash(el.EllipticBlend(k=0.3, d=2.0))
    r = build("FitResult smooth")
    with pytest.raises(TypeError):      # arrays inside: unhashable, as before
        hash(r)
