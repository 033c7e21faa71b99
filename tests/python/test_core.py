"""The Python binding of the core: SmoothElastica and DiscreteElastica as users call them."""
import math

import numpy as np
import pytest

import libelastica as el


def fd_jacobian(make, params, names, evaluate, h=1e-6):
    cols = []
    for name in names:
        step = h * max(1.0, abs(params[name]))
        plus, minus = dict(params), dict(params)
        plus[name] += step
        minus[name] -= step
        cols.append((evaluate(make(**plus)) - evaluate(make(**minus))) / (2 * step))
    return np.stack(cols, axis=-1)


@pytest.mark.parametrize("k", [0.3, 0.9, 1.2, 3.0, -2.0])
def test_smooth_jacobian_matches_finite_differences(k):
    params = dict(x0=0.4, y0=-1.0, phi=0.8, mu=1.3, k=k, q=0.25, length=3.0)
    t = np.array([0.0, 0.13, 0.5, 0.77, 1.0])
    c = el.SmoothElastica(**params)
    jac = c.jacobian(t * c.length)
    assert jac.shape == (5, 2, 7)
    fd = fd_jacobian(el.SmoothElastica, params, el.core.SMOOTH_PARAMS,
                     lambda e: e.points(t * e.length))
    assert np.allclose(jac, fd, rtol=1e-6, atol=1e-6 * np.abs(jac).max())


@pytest.mark.parametrize("k", [0.5, 0.95, 1.05, 2.0])
def test_discrete_jacobian_matches_finite_differences(k):
    params = dict(x0=0.1, y0=0.2, h=0.08, phi=-0.4, z=0.09, q=0.3, k=k)
    d = el.DiscreteElastica(n=40, **params)
    jac = d.jacobian()
    assert jac.shape == (40, 2, 7)
    fd = fd_jacobian(lambda **p: el.DiscreteElastica(n=40, **p), params,
                     el.core.DISCRETE_PARAMS, lambda e: e.points())
    assert np.allclose(jac, fd, rtol=1e-6, atol=1e-6 * np.abs(jac).max())


def test_smooth_geometry_from_python():
    c = el.SmoothElastica(x0=1, y0=2, phi=0.3, mu=1.0, k=0.8, q=0.0, length=5.0)
    s = np.linspace(0, c.length, 2001)
    p = c.points(s)
    assert np.allclose(p[0], [1, 2])
    seg = np.hypot(*np.diff(p, axis=0).T)
    assert abs(seg.sum() - c.length) < 1e-5          # arc length parametrisation
    theta = c.angle(s)
    kappa = c.curvature(s)
    assert np.allclose(np.gradient(theta, s)[2:-2], kappa[2:-2], atol=1e-4)
    assert abs(theta[0] - (c.phi + 2 * math.asin(c.k * 0.0))) < 1e-15
    energy = np.sum((kappa[1:] ** 2 + kappa[:-1] ** 2) / 2 * np.diff(s))
    assert abs(c.energy() - energy) < 1e-5 * energy
    assert c.points(2.5).shape == (2,)                # a scalar s: one point (QA17 W3)
    assert c.points().shape == (101, 2)               # default sampling of [0, length]


def test_discrete_geometry_from_python():
    d = el.DiscreteElastica(x0=0, y0=0, h=0.1, phi=0, z=0.1, q=0.0, k=0.8, n=50)
    p = d.points()
    assert p.shape == (50, 2)
    assert np.allclose(np.hypot(*np.diff(p, axis=0).T), 0.1, atol=1e-14)
    kappa = d.curvature()
    assert kappa.shape == (48,)
    a, b = p[1:-1] - p[:-2], p[2:] - p[1:-1]
    turn = np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0], (a * b).sum(axis=1))
    assert np.allclose(kappa, 2 / d.h * np.tan(turn / 2), atol=1e-10)


def _jacobi(u, k):
    """sn, cn, dn (u; k) from scipy (parameter m = k^2; k > 1 by the reciprocal modulus:
    k sn(u; k) = sn(k u; 1/k), cn(u; k) = dn(k u; 1/k), dn(u; k) = cn(k u; 1/k))."""
    from scipy.special import ellipj
    if k <= 1.0:
        sn, cn, dn, _ = ellipj(u, k * k)
        return sn, cn, dn
    sn, cn, dn, _ = ellipj(k * u, 1.0 / (k * k))
    return sn / k, dn, cn


@pytest.mark.parametrize("k", [1e-8, 0.3, 0.99, 1.0, 1.01, 5.0])
@pytest.mark.parametrize("z", [1e-12, 2.4e-8, -1e-6])
def test_discrete_curvature_keeps_its_digits_at_small_steps(k, z):
    """kappa_i = (2/h) tan(K_i/2), K_i = a(u_i + z) - a(u_i - z), the integral of a' = k cn
    (sin a = k sn, cos a = dn: seed 000 (3.4), (4.3)); its Maclaurin series in z, K =
    2 k z cn + (k z^3 / 3) cn (k^2 sn^2 - dn^2), from scipy's Jacobi functions at u_i. The
    difference of the two a's lost eps / |K| relative (1.9e-7 at z = 2.4e-8)."""
    d = el.DiscreteElastica(x0=1.0, y0=-2.0, h=0.02, phi=0.4, z=z, q=0.37, k=k, n=400)
    u = d.q + d.z * np.arange(1, d.n - 1)
    sn, cn, dn = _jacobi(u, k)
    K = 2 * k * z * cn + k * z ** 3 / 3 * cn * (k * k * sn * sn - dn * dn)
    ref = 2 / d.h * np.tan(K / 2)
    scale = 2 / d.h * k * abs(z)               # the largest |kappa| (cn = 1)
    err = np.abs(d.curvature() - ref)
    assert np.all(err <= 100 * np.finfo(float).eps * (np.abs(ref) + 1e-3 * scale)), \
        f"{np.max(err / np.abs(ref)):.3g} relative"


@pytest.mark.parametrize("bad", [dict(mu=0.0), dict(mu=-1.0), dict(k=float("nan")), dict(length=-1.0),
                                 dict(q=float("nan")), dict(phi=float("inf"))])
def test_smooth_bad_parameters_raise_value_error(bad):
    params = dict(x0=0, y0=0, phi=0, mu=1.0, k=0.5, q=0.0, length=1.0)
    params.update(bad)
    name = next(iter(bad))     # the message names the field (QA: it said only "invalid argument")
    with pytest.raises(ValueError, match=f"SmoothElastica: {name} must be "):
        el.SmoothElastica(**params)


@pytest.mark.parametrize("bad", [dict(h=0.0), dict(h=-0.1), dict(k=-1.0), dict(z=float("nan")),
                                 dict(n=1), dict(n=2.5)])
def test_discrete_bad_parameters_raise_value_error(bad):
    params = dict(x0=0, y0=0, h=0.1, phi=0, z=0.1, q=0.0, k=0.8, n=50)
    params.update(bad)
    with pytest.raises(ValueError):
        el.DiscreteElastica(**params)


def test_bad_arc_lengths_raise_and_errors_carry_status():
    c = el.SmoothElastica()
    with pytest.raises(el.ElasticaError) as info:
        c.points([0.0, float("nan")])
    assert info.value.status == 1
    with pytest.raises(ValueError):
        c.points(np.zeros((2, 2)))


def test_parameters_are_plain_and_editable():
    c = el.SmoothElastica(k=0.5)
    c.k = 1.5   # a dataclass: FreeCAD and users edit fields directly
    assert c.curvature([0.0])[0] == pytest.approx(2 * 1.5 * math.sqrt(c.mu) * 1.0)
    assert list(c.params) == [c.x0, c.y0, c.phi, c.mu, c.k, c.q, c.length]


def test_discrete_to_bspline_interpolates_vertices():
    d = el.DiscreteElastica(x0=0, y0=0, h=0.1, phi=0.2, z=0.1, q=0.3, k=0.8, n=30)
    b = d.to_bspline()
    chord = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(d.points(), axis=0).T))])
    assert b.degree == 3
    assert np.allclose(b.evaluate(chord), d.points(), atol=1e-12)


def test_negative_k_gives_clockwise_loops():
    ccw = el.SmoothElastica(k=2.0, length=4.0)
    cw = el.SmoothElastica(k=-2.0, length=4.0)
    assert (ccw.curvature() > 0).all() and (cw.curvature() < 0).all()
    assert np.allclose(cw.points() * [1, -1], ccw.points(), atol=1e-12)   # phi = 0: mirror in the x axis


def test_sparse_grid_matches_pointwise_evaluation():
    """Issue 12: 32 equally spaced samples over 50 (about nine periods) took the
    addition-theorem path with steps of u ~ 1.6 and came out 2.7e-3 off; every fast
    path must equal one-point evaluation."""
    c = el.SmoothElastica(mu=1, k=0.8, q=0, length=50)
    s = np.linspace(0, 50, 32)
    fast = c.points(s)
    one = np.array([c.points(np.array([si]))[0] for si in s])
    assert np.abs(fast - one).max() <= 1e-13
    # the same for the Jacobian, the angle and the curvature, and for sorted scattered s
    jac = c.jacobian(s)
    jac_one = np.array([c.jacobian(np.array([si]))[0] for si in s])
    assert np.abs(jac - jac_one).max() <= 1e-12 * np.abs(jac_one).max()
    for what in ("angle", "curvature"):
        assert np.abs(getattr(c, what)(s) - [getattr(c, what)(np.array([si]))[0] for si in s]).max() <= 1e-13
    rng = np.random.default_rng(3)
    ss = np.sort(rng.uniform(0, 50, 500))
    one = np.array([c.points(np.array([si]))[0] for si in ss])
    assert np.abs(c.points(ss) - one).max() <= 1e-13


@pytest.mark.parametrize("k", [1.0, -1.0])
def test_separatrix_sparse_grid_is_finite(k):
    """k = +-1 with a step of u ~ 2 returned NaN with EL_OK."""
    c = el.SmoothElastica(mu=4.0, k=k, q=-3.0, length=30)
    s = np.linspace(0, 30, 31)
    p = c.points(s)
    assert np.isfinite(p).all()
    one = np.array([c.points(np.array([si]))[0] for si in s])
    assert np.abs(p - one).max() <= 1e-12


@pytest.mark.parametrize("k", [0.0, 0.4, -0.9, 1.0, -1.0, 1.3, -2.5])
def test_reversed_is_the_same_curve_backwards(k):
    c = el.SmoothElastica(x0=1, y0=2, phi=0.4, mu=0.7, k=k, q=0.3, length=5.0)
    r = c.reversed()
    for s in (np.array([0.0, c.length]), np.linspace(0.0, c.length, 41)):
        assert np.abs(r.points(s) - c.points(c.length - s)).max() < 1e-12
        assert np.abs(r.curvature(s) + c.curvature(c.length - s)).max() < 1e-12
        turn = np.remainder(r.angle(s) - c.angle(c.length - s), 2 * np.pi)
        assert np.abs(turn - np.pi).max() < 1e-12
    assert r.reversed().points(np.array([0.0]))[0] == pytest.approx(c.points(np.array([0.0]))[0], abs=1e-12)


def test_self_crossings_counts_every_pair_across_runs():
    """shape.self_crossings tests only the runs of segments whose bounding boxes overlap:
    the same count as every pair of segments tested (random walks, clouds, wobbly loops
    and rounded ones with touching and collinear segments, over many runs)."""
    from libelastica.shape import CROSSING_BLOCK, self_crossings

    def every_pair(xy):
        a, b = xy[:-1], xy[1:]
        def side(p, q, r):
            return (q[..., 0] - p[..., 0]) * (r[..., 1] - p[..., 1]) - \
                   (q[..., 1] - p[..., 1]) * (r[..., 0] - p[..., 0])
        A, B, C, D = a[:, None], b[:, None], a[None], b[None]
        cross = (side(A, B, C) * side(A, B, D) < 0) & (side(C, D, A) * side(C, D, B) < 0)
        i, j = np.indices(cross.shape)
        return int(np.count_nonzero(cross & (j > i + 1)))

    rng = np.random.default_rng(7)
    total = 0
    for trial in range(60):
        n = int(rng.integers(2, 10 * CROSSING_BLOCK))
        if trial % 3 == 0:
            xy = rng.normal(size=(n, 2)).cumsum(0)
        elif trial % 3 == 1:
            xy = rng.normal(size=(n, 2))
        else:
            t = np.linspace(0, rng.uniform(1, 30), n)
            xy = np.c_[np.cos(t) * (1 + 0.3 * np.sin(5 * t)), np.sin(2 * t)]
        if trial % 4 == 0:
            xy = np.round(xy, 1)
        want = every_pair(xy)
        assert self_crossings(xy) == want, (trial, n)
        total += want
    assert total > 10000
    # a run's last segment reaching far out of its other points, crossed in the next run
    rng2 = np.random.default_rng(8)
    xy = np.vstack([rng2.uniform(0, 1, (CROSSING_BLOCK, 2)), [[100, 0.5], [50, 10], [50, -10]],
                    [50, -10] + rng2.uniform(0, 1, (CROSSING_BLOCK, 2))])
    assert self_crossings(xy) == every_pair(xy) >= 1
