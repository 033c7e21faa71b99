"""Elliptic / MQ blending-function curves (seed 003) through the public Python API.

References are independent of the C library: scipy's Jacobi functions and K(m),
and Eck's control-point relation (2.6) inverted with numpy."""
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq
from scipy.special import ellipj, ellipk

import libelastica as el

T = np.linspace(0.0, 1.0, 201)
ELLIPTIC = [(0.0, 2.0), (0.3, 0.5), (np.sqrt(0.3), 2.0), (0.7, 3.0), (0.95, 5.0)]


@pytest.mark.parametrize("k,d", ELLIPTIC)
def test_partition_of_unity_and_end_conditions(k, d):
    b = el.EllipticBlend(k, d)
    h, dh = b.basis(T), b.basis(T, derivative=1)
    assert h.shape == (len(T), 4)
    np.testing.assert_allclose(h.sum(axis=1), 1.0, rtol=0, atol=1e-14)
    # (2.14) and the symmetry h_2(t) = h_1(1-t), h_3(t) = h_0(1-t)
    np.testing.assert_allclose(h[0], [1, 0, 0, 0], rtol=0, atol=1e-14)
    np.testing.assert_allclose(h[-1], [0, 0, 0, 1], rtol=0, atol=1e-14)
    np.testing.assert_allclose(dh[0], [-d, d, 0, 0], rtol=0, atol=1e-14 * (1 + d))
    np.testing.assert_allclose(dh[-1], [0, 0, -d, d], rtol=0, atol=1e-14 * (1 + d))
    np.testing.assert_allclose(h[:, 2], h[::-1, 1], rtol=0, atol=1e-14)
    np.testing.assert_allclose(h[:, 3], h[::-1, 0], rtol=0, atol=1e-14)
    # the span itself, against scipy (parameter m = k^2)
    K = ellipk(k * k)
    assert b.K == pytest.approx(K, rel=1e-14)
    f = b.span(T)
    np.testing.assert_allclose(f[:, 2], ellipj(K * T, k * k)[0], rtol=0, atol=1e-14)
    np.testing.assert_allclose(f[:, 1], ellipj(K * (1 - T), k * k)[0], rtol=0, atol=1e-14)


def test_end_tangents_along_control_legs():
    rng = np.random.default_rng(3)
    for k, d in ELLIPTIC:
        b = el.EllipticBlend(k, d)
        q = rng.uniform(-2, 2, (4, 2))
        xy, dxy = b.evaluate(q, [0.0, 1.0], derivative=True)
        np.testing.assert_allclose(xy, q[[0, 3]], atol=1e-14)
        np.testing.assert_allclose(dxy[0], d * (q[1] - q[0]), atol=1e-13 * (1 + d))
        np.testing.assert_allclose(dxy[1], d * (q[3] - q[2]), atol=1e-13 * (1 + d))


def _eck_from_26(c, t):
    """Eck's Omega_i from the control-point relation (2.6): b = T a, so
    phi = F^T a = F^T T^-1 b and Omega = T^-T F."""
    s = np.hypot(c, 1.0)
    al = c * s / (2 * c * c + 1 + c * s)
    Tm = np.array([[1, s, c, 0], [1 - al, s - al / s, c, al],
                   [al, c, s - al / s, 1 - al], [0, c, s, 1]])
    F = np.array([1 - t, np.sqrt(c * c + (1 - t) ** 2), np.sqrt(c * c + t * t), t])
    return np.linalg.solve(Tm.T, F).T, al


@pytest.mark.parametrize("c", [0.5, 1.0, 2.0])
def test_eck_omega_reproduced_by_generalised_construction(c):
    ref, al = _eck_from_26(c, T)
    assert el.eck_d(c) == pytest.approx(1 / al, rel=1e-14)
    mq = el.MQBlend(c)              # d defaults to Eck's 1/alpha(c)
    assert mq.d == pytest.approx(1 / al, rel=1e-14)
    tol = 1e-14 * np.abs(mq.matrix).sum()   # Omega_i are differences of O(|M|) terms
    np.testing.assert_allclose(mq.basis(T), ref, rtol=0, atol=tol)
    np.testing.assert_allclose(el.eck_omega(c, T), ref, rtol=0, atol=tol)
    # a different d is a different basis
    assert np.abs(el.MQBlend(c, 0.5).basis(T) - ref).max() > 1e-2


@pytest.mark.parametrize("d", [0.5, 3.0])
def test_figure1_bases(d):
    """Figure 1, (c, d) = (1, 1/2) and (1, 3): the defining conditions, and the
    Bernstein-like shape (nonnegative, h_0 decreasing, one bump for h_1)."""
    b = el.MQBlend(1.0, d)
    h, dh = b.basis(T), b.basis(T, derivative=1)
    np.testing.assert_allclose(h.sum(axis=1), 1.0, atol=1e-14)
    np.testing.assert_allclose(h[0], [1, 0, 0, 0], atol=1e-14)
    np.testing.assert_allclose(dh[0], [-d, d, 0, 0], atol=1e-13)
    np.testing.assert_allclose(dh[-1], [0, 0, -d, d], atol=1e-13)
    assert h.min() > -1e-14
    assert np.all(np.diff(h[:, 0]) < 0)
    assert np.count_nonzero(np.diff(np.sign(np.diff(h[:, 1])))) == 1


def test_rope_example_paper_convention():
    """(k, d) = (0.3, 2) with the paper's k = parameter m: printed control points,
    and the curve is C(t) = (t, sn(Kt | m = 0.3)) to rounding."""
    b = el.EllipticBlend(m=0.3, d=2.0)
    assert b.k == pytest.approx(np.sqrt(0.3), rel=1e-15)
    p = np.array([[0, 0], [0, 0], [0, 1], [1, 0]], float)
    q = b.control_points(p)
    np.testing.assert_allclose(q, [[0, 0], [0.5, 0.856945], [0.5, 1], [1, 1]], atol=5e-7)
    assert q[1, 1] == pytest.approx(ellipk(0.3) / 2, rel=1e-14)
    xy = b.evaluate(q, T)
    np.testing.assert_allclose(xy[:, 0], T, atol=1e-14)
    np.testing.assert_allclose(xy[:, 1], ellipj(ellipk(0.3) * T, 0.3)[0], atol=1e-14)
    np.testing.assert_allclose(b.coefficients(q), p, atol=1e-14)
    # the paper's printed system (2.17), solved with numpy, gives the same h_0, h_1
    K = ellipk(0.3)
    A = np.array([[1, 1, 0, 0, 0, 0, 0, 0], [0, 0, 1, 1, 0, 0, 0, 0], [-1, -K, 0, 1, 0, 0, 0, 0],
                  [0, 0, 0, 0, 1, 1, 0, 0], [0, 0, 0, 0, 0, 0, 1, 1], [0, 0, 0, 0, -1, -K, 0, 1],
                  [-1, 0, K, 1, 0, 0, 0, 0], [0, 1, 1, 0, 0, 1, 1, 0]])
    x = np.linalg.solve(A, [1, 0, 0, 0, 0, 0, -2.0, 0])
    np.testing.assert_allclose(b.matrix[:2].ravel(), x, atol=1e-13)
    # modulus 0.3 does not give the printed numbers
    q_mod = el.EllipticBlend(0.3, 2.0).control_points(p)
    assert abs(q_mod[1, 1] - 0.856945) > 0.05


def test_bad_input():
    with pytest.raises(el.DomainError):
        el.EllipticBlend(1.0, 2.0)
    with pytest.raises(el.DomainError):
        el.EllipticBlend(m=1.2, d=2.0)
    for k, d in [(-0.1, 2.0), (0.5, 0.0), (0.5, -1.0), (np.nan, 2.0), (0.5, np.inf)]:
        with pytest.raises(ValueError):
            el.EllipticBlend(k, d)
    with pytest.raises(ValueError):
        el.EllipticBlend(0.5, 2.0, m=0.25)
    with pytest.raises(el.DomainError):
        el.MQBlend(0.0, 1.0)
    with pytest.raises(ValueError):
        el.MQBlend(1.0, -1.0)
    # K(k) = 2: the end conditions do not determine h_0 (singular (2.17))
    ks = np.sqrt(brentq(lambda m: ellipk(m) - 2.0, 0.1, 0.9, xtol=1e-16))
    with pytest.raises(el.SingularError):
        el.EllipticBlend(ks, 2.0)
    b = el.EllipticBlend(0.5, 2.0)
    with pytest.raises(ValueError):
        b.evaluate(np.zeros((3, 2)), T)
    with pytest.raises(ValueError):
        b.basis([0.5, np.nan])
    with pytest.raises(ValueError):
        b.from_points(np.zeros((4, 2)), mode="bogus")
    with pytest.raises(el.SingularError, match="points 2 and 3 coincide"):
        b.from_points([[0, 0], [1, 1], [1, 1], [2, 0]])


def test_four_picked_points():
    pts = np.array([[0, 0], [1, 2], [3, 2.5], [4, 0]], float)
    b = el.EllipticBlend(0.6, 2.5)
    q = b.from_points(pts, "interpolate")
    chord = np.concatenate([[0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])
    np.testing.assert_allclose(b.evaluate(q, chord / chord[-1]), pts, atol=1e-12)
    np.testing.assert_array_equal(b.from_points(pts, "control"), pts)
    curve = el.blend_curve(pts, k=0.6, d=2.5)
    assert curve.nseg == 1
    np.testing.assert_allclose(curve.q, q, atol=1e-15)
    np.testing.assert_allclose(el.blend_curve(pts, mode="control", m=0.3).points([0, 1]),
                               pts[[0, 3]], atol=1e-14)


def test_composite_c1_through_points():
    pts = np.array([[0, 0], [1, 1], [2.5, 0.5], [3, -1], [4.5, 0]], float)
    curve = el.blend_curve(pts, k=0.5, d=2.0)
    assert curve.nseg == 4 and curve.q.shape == (13, 2)
    np.testing.assert_allclose(curve.points(np.arange(5.0)), pts, atol=1e-13)
    e = 1e-9
    for i in range(1, 4):
        xy, dxy = curve.basis.evaluate_composite(curve.q, [i - e, i + e], derivative=True)
        np.testing.assert_allclose(xy[0], xy[1], atol=1e-8)
        np.testing.assert_allclose(dxy[0], dxy[1], atol=1e-7)


def _flat_knots(bs):
    return np.repeat(np.asarray(bs.knots, float), np.asarray(bs.mults, int))


@pytest.mark.parametrize("tol", [1e-3, 1e-7])
def test_to_bspline_within_tolerance(tol):
    pytest.importorskip("libelastica.bspline")
    from scipy.interpolate import BSpline as SciBSpline
    b = el.EllipticBlend(m=0.3, d=2.0)
    q = b.control_points([[0, 0], [0, 0], [0, 1], [1, 0]])
    bs = b.to_bspline(q, tol)
    assert bs.degree == 3 and 0 <= bs.max_deviation <= tol
    t = np.linspace(0, 1, 4001)
    sp = SciBSpline(_flat_knots(bs), np.asarray(bs.poles), 3)
    err = np.hypot(*(sp(t) - b.evaluate(q, t)).T).max()
    assert err <= bs.max_deviation * (1 + 1e-6) + 1e-15
    # composite: the parameter runs over [0, nseg]
    curve = el.blend_curve([[0, 0], [1, 1], [2.5, 0.5], [3, -1]], k=0.5, d=2.0, mode="control")
    pts = np.array([[0, 0], [1, 1], [2, 0], [3, 1], [4, 0]], float)
    comp = el.blend_curve(pts, k=0.5)
    bs2 = comp.to_bspline(tol)
    t2 = np.linspace(0, comp.nseg, 4001)
    sp2 = SciBSpline(_flat_knots(bs2), np.asarray(bs2.poles), 3)
    assert np.hypot(*(sp2(t2) - comp.points(t2)).T).max() <= tol
    assert curve.to_bspline(tol).max_deviation <= tol


def test_pickle_and_copy_keep_the_basis():
    """Bases and blend curves pickle and deep-copy (their C basis is cffi data: TypeError
    before), the copies evaluating bit for bit as the originals."""
    import copy
    import pickle
    q = np.array([[0, 0], [0.3, 0.8], [0.7, 0.9], [1, 0.0], [1.4, -0.5], [2, 0.1], [2.5, 0.3]])
    for basis in (el.EllipticBlend(m=0.3, d=2.0), el.EllipticBlend(0.95, 5.0), el.MQBlend(0.4)):
        curve = el.BlendCurve(basis, q)
        for twin in (pickle.loads(pickle.dumps(curve)), copy.deepcopy(curve)):
            assert type(twin.basis) is type(basis) and repr(twin.basis) == repr(basis)
            assert np.array_equal(twin.basis.matrix, basis.matrix)
            assert np.array_equal(twin.points(), curve.points())
    c = el.blend_curve(q[:4], m=0.3)
    assert np.array_equal(pickle.loads(pickle.dumps(c)).points(), c.points())


@pytest.mark.parametrize("m,want", [(0.99, -1.054e-6), (0.995, -1.428e-7), (0.999, -1.375e-9)])
def test_convex_hull_flag_sees_the_dips_next_to_the_ends(m, want):
    # QA11: 64 samples missed these dips (within 0.008 of t = 1) and said convex_hull
    b = el.EllipticBlend(m=m, d=2.0)
    t = np.concatenate([np.linspace(0, 1, 20001), 1 - np.geomspace(1e-6, 1e-2, 20001)])
    h = b.basis(t)
    assert not b.convex_hull and b.basis_min <= h.min() + 1e-15
    assert b.basis_min == pytest.approx(want, rel=1e-3)
    # the warning shows the factor above 1 (1 - 2 basis_min at least), not '1'
    w = b.warnings()[0]
    factor = float(w.split("moving up to ")[1].split(" times")[0])
    assert factor > 1.0 and b.lebesgue >= 1 - 2 * b.basis_min - 1e-15


def test_warning_digits_show_the_factor_above_one():
    assert el.blend.above_one(1.002) == "1.002" and el.blend.above_one(1.0000021) == "1.000002"
    assert el.blend.above_one(4.2738) == "4.27" and el.blend.above_one(1.0) == "1"
    assert "up to 1.002 times" in el.EllipticBlend(m=0.9).warnings()[0]


@pytest.mark.parametrize("n", [4, 8])
def test_closed_sequences_close_smoothly_or_say_the_corner(n):
    th = np.linspace(0, 2 * np.pi, n + 1)
    pts = np.c_[np.cos(th), np.sin(th)] if n == 8 else np.array(
        [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]], float)
    pts[-1] = pts[0]
    open_ = el.blend_curve(pts, m=0.3)
    corner = {4: 53.13, 8: 10.72}[n]
    assert open_.seam_angle() == pytest.approx(corner, abs=0.01)
    assert any(f"{corner:.3g} deg corner" in w and "closed=True" in w for w in open_.warnings())
    for given in (pts, pts[:-1]):     # with or without the repeated first point
        c = el.blend_curve(given, m=0.3, closed=True)
        assert c.closed and c.nseg == n and c.warnings() == []
        assert c.seam_angle() < 1e-9
        xy, d = c.basis.evaluate_composite(c.q, np.arange(n + 1.0), derivative=True)
        np.testing.assert_allclose(xy, np.vstack([pts[:-1], pts[:1]]), atol=1e-13)
        np.testing.assert_allclose(d[-1], d[0], atol=1e-12)     # C1 at the seam
    with pytest.raises(ValueError, match="at least 3 distinct"):
        el.blend_curve([[0, 0], [1, 0], [0, 0]], m=0.3, closed=True)
    with pytest.raises(ValueError, match="interpolate"):
        el.blend_curve(pts[:4], m=0.3, mode="control", closed=True)


def test_overflow_is_named():
    with pytest.raises(el.DomainError, match="overflow"):
        el.blend_curve([[0, 0], [1e308, 1], [-1e308, 1], [3, 0]], m=0.3)
    with pytest.raises(el.DomainError, match="overflow"):
        el.EllipticBlend(m=0.3).composite_through([[0, 0], [1e308, 1], [-1e308, 1], [3, 0], [4, 4]])


ZIGZAG = [(0.0, 0.0), (40.0, 40.0), (0.0, 40.0), (40.0, 0.0)]   # a Z of four points


def _diameter(xy):
    xy = np.asarray(xy, float)
    return float(np.hypot(*(xy[:, None] - xy[None]).transpose(2, 0, 1)).max())


def test_ill_conditioned_interpolation_warns_with_its_figure():
    """Through a Z at k = 0.7 the collocation puts the control points 30 times as far
    apart as the points and the curve swings far outside them: ConditionWarning, with
    the spread and the swing; at k = 0.3, and as control points, nothing to say."""
    with pytest.warns(el.ConditionWarning, match="ill-conditioned") as rec:
        c = el.blend_curve(ZIGZAG, k=0.7)
    spread = _diameter(c.q) / _diameter(ZIGZAG)
    assert c.spread() == pytest.approx(spread, rel=1e-12) and spread > el.SPREAD_MAX
    assert f"{spread:.3g} times as far apart" in str(rec[0].message)
    swing = _diameter(c.points(np.linspace(0, 1, 2001))) / _diameter(ZIGZAG)
    assert swing > 2.0 and f"spans {swing:.3g} times" in str(rec[0].message)
    assert any("ill-conditioned" in w for w in c.warnings())
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        tame = el.blend_curve(ZIGZAG, k=0.3)
        assert tame.spread() < el.SPREAD_MAX and tame.warnings() == []
        given = el.blend_curve(ZIGZAG, k=0.7, mode="control")
        assert given.spread() == 1.0 and given.warnings() == []


def test_closed_blend_looping_between_close_points_warns():
    """QA13: five points, two of them 1.4 apart among chords of 60 to 100, closed: the
    curve loops between the close ones without a word. Now BlendLoopWarning (a
    LoopWarning), and loops() counts it; evenly spaced points say nothing."""
    pts = np.array([[0, 0], [100, 0], [101, 1], [50, 60], [-3, 20]], float)
    for given, closed in ((pts, True), (np.vstack([pts, pts[:1]]), False)):
        with pytest.warns(el.BlendLoopWarning, match="crosses itself once"):
            c = el.blend_curve(given, closed=closed)
        assert issubclass(el.BlendLoopWarning, el.LoopWarning) and c.loops() == 1
        # the loop is there: the segment between the close points crosses its own start
        xy = c.points(np.linspace(1.0, 2.0, 20001))
        assert el.shape.self_crossings(xy) == 1 and np.ptp(xy[:, 0]) > 10.0
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for n in (3, 5, 8):
            th = 2 * np.pi * np.arange(n) / n
            c = el.blend_curve(np.c_[np.cos(th), np.sin(th)] * 50, closed=True)
            assert c.loops() == 0
        bow_tie = el.blend_curve([[0, 0], [10, 0], [0, 10], [10, 10]], closed=True)
        assert bow_tie.loops() == 0     # crosses itself once, where its closing edge does
        assert el.shape.self_crossings(bow_tie.points(np.linspace(0, 4, 4001))) == 1
        spiral = np.linspace(0.5, 6 * np.pi, 60)
        assert el.blend_curve(np.c_[spiral * np.cos(spiral), spiral * np.sin(spiral)]).loops() == 0


def test_blend_loop_warning_names_the_points_and_the_loops_width():
    """QA F4: the loop warning fired on 31 of 40 sketched arcs but never said where, so the
    user could not act. Now it names the two points a loop lies between (counted from 0),
    their chord beside its neighbours and the loop's width; loop_places() gives them."""
    u = np.array([0.0, 0.09, 0.21, 0.30, 0.42, 0.55, 0.66, 0.78, 0.78 + 0.02, 0.91, 1.0])
    arc = 100.0 * np.c_[np.cos(u), np.sin(u)]          # R 100, clicks 7 and 8 2 mm apart
    with pytest.warns(el.BlendLoopWarning, match=r"between points 7 and 8 \(counted from 0; "
                      r"chord 2 beside 12 and 11, a loop [0-9.]+ wide\)"):
        c = el.blend_curve(arc)
    (place,) = c.loop_places()
    assert place["between"] == [7, 8] and place["chord"] == pytest.approx(2.0, rel=1e-3)
    assert 0.0 < place["width"] < 2.0 and c.loops() == 1
    assert f"{place['width']:.2g} wide" in c.warnings()[-1]
    even = 100.0 * np.c_[np.cos(np.linspace(0, 1, 11)), np.sin(np.linspace(0, 1, 11))]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert el.blend_curve(even).loop_places() == [] and el.blend_curve(even).warnings() == []


def test_blend_curve_passes_three_points_and_not_two():
    """Three open points are the 2-segment composite through them; two raise at once."""
    c = el.blend_curve([(0, 0), (1, 1), (2, 0)])
    assert c.nseg == 2 and np.allclose(c.points([0.0, 1.0, 2.0]), [(0, 0), (1, 1), (2, 0)])
    with pytest.raises(ValueError, match="at least 3 points"):
        el.blend_curve([(0, 0), (1, 1)])
