"""Keyline preparation (seed 000 §5.3) through the Python API: plane fit,
equilateral resampling, PCA re-normalisation, RDP-style inflection estimate."""
import numpy as np
import pytest

import libelastica as el
from keyline_data import keyline_3d, random_rotation


# ---------------------------------------------------------------- helpers

def polyline_distance(pts, poly):
    """Distance from each of pts (m, 2) to the polyline poly (n, 2)."""
    P, Q = poly[:-1], poly[1:]
    d = Q - P
    L2 = np.einsum("ij,ij->i", d, d)
    out = np.empty(len(pts))
    for i, X in enumerate(pts):
        t = np.where(L2 > 0, np.einsum("ij,ij->i", X - P, d) / np.where(L2 > 0, L2, 1), 0.0)
        t = np.clip(t, 0.0, 1.0)
        out[i] = np.min(np.linalg.norm(P + t[:, None] * d - X, axis=1))
    return out


def farthest_hit(poly, A, r):
    """Largest arc-length position (from poly[0]) of a point of the polyline at
    distance r from A, by the quadratic on every segment; -1 if none."""
    P, Q = poly[:-1], poly[1:]
    d = Q - P
    L = np.linalg.norm(d, axis=1)
    cum = np.concatenate([[0.0], np.cumsum(L)])
    f = P - A
    a = np.einsum("ij,ij->i", d, d)
    b = np.einsum("ij,ij->i", f, d)
    c = np.einsum("ij,ij->i", f, f) - r * r
    disc = b * b - a * c
    ok = (a > 0) & (disc >= 0)
    best = -1.0
    for sgn in (1.0, -1.0):
        t = np.where(ok, (-b + sgn * np.sqrt(np.where(ok, disc, 0))) / np.where(a > 0, a, 1), -1)
        good = ok & (t >= -1e-12) & (t <= 1 + 1e-12)
        if good.any():
            best = max(best, np.max((cum[:-1] + np.clip(t, 0, 1) * L)[good]))
    return best


def check_resampling(poly, r, out, info, scale=1.0):
    seg = np.linalg.norm(np.diff(out, axis=0), axis=1)
    assert np.max(np.abs(seg - r)) <= 1e-12 * r                     # equilateral
    assert np.max(polyline_distance(out, poly)) <= 1e-12 * scale     # on the curve
    assert np.all(np.diff(info.s) > 0)                              # never goes back
    for k in range(len(out)):                                       # the rule, vertex by vertex
        far = farthest_hit(poly, out[k], r)
        if k + 1 < len(out):
            assert far == pytest.approx(info.s[k + 1], abs=1e-9 * scale)
        else:
            assert far <= info.s[k] + 1e-9 * scale                  # stop point


# ---------------------------------------------------------------- plane fit

@pytest.mark.parametrize("seed", [0, 1, 2])
def test_plane_fit_recovers_tilted_plane(seed):
    kl = keyline_3d(seed=seed, noise=0.0)
    xy, frame = el.plane_fit(kl.xyz)
    M = frame.matrix
    assert np.allclose(M.T @ M, np.eye(3), atol=1e-14)
    assert np.allclose(np.cross(frame.e1, frame.e2), frame.e3, atol=1e-14)      # right-handed
    assert abs(frame.e3 @ kl.plane_normal) == pytest.approx(1.0, abs=1e-12)
    assert frame.e3[2] > 0
    assert frame.e1 @ (kl.xyz[-1] - kl.xyz[0]) > 0
    assert frame.rms <= 1e-12 * kl.length
    assert np.allclose(frame.origin, kl.xyz.mean(axis=0), rtol=0, atol=1e-12 * 1000)
    # 3D -> 2D -> 3D
    assert np.max(np.abs(frame.to_3d(xy) - kl.xyz)) <= 1e-11 * 1000
    # the plane coordinates are the design coordinates up to a rigid motion
    d2 = np.linalg.norm(xy[:, None] - xy[None, ::37], axis=2)
    dd = np.linalg.norm(kl.xy[:, None] - kl.xy[None, ::37], axis=2)
    assert np.max(np.abs(d2 - dd)) <= 1e-10 * kl.length


def test_plane_fit_noisy_keyline():
    kl = keyline_3d(seed=7, noise=1e-3)
    xy, frame = el.plane_fit(kl.xyz)
    assert abs(frame.e3 @ kl.plane_normal) > 1 - 1e-5
    # isotropic noise: the out-of-plane rms estimates sigma
    assert 0.8 * kl.noise < frame.rms < 1.2 * kl.noise
    assert frame.rms ** 2 == pytest.approx(frame.eigenvalues[2], rel=1e-9)
    xy2, z = frame.project(kl.xyz, return_z=True)
    assert np.allclose(xy2, xy, atol=1e-9)
    assert np.allclose(frame.to_3d(xy) + z[:, None] * frame.e3, kl.xyz, atol=1e-9)
    # one point in, one point out
    assert frame.to_3d(xy[5]).shape == (3,)
    assert np.allclose(frame.project(kl.xyz[5]), xy[5])


def test_plane_fit_bad_input():
    with pytest.raises(ValueError):
        el.plane_fit(np.zeros((2, 3)))
    with pytest.raises(ValueError):
        el.plane_fit(np.ones((5, 2)))
    bad = keyline_3d(n=20).xyz
    bad[3, 1] = np.nan
    with pytest.raises(ValueError):
        el.plane_fit(bad)
    with pytest.raises(el.SingularError):
        el.plane_fit(np.tile([1.0, 2.0, 3.0], (10, 1)))


# ---------------------------------------------------------------- resampling

def test_resample_s_curve_and_info():
    t = np.linspace(-2, 2, 301)
    poly = np.c_[30 * t, 20 * np.sin(1.3 * t) + 3 * t ** 2]
    for r in (0.5, 3.0, 25.0):
        out, info = el.resample_equilateral(poly, r, return_info=True)
        check_resampling(poly, r, out, info, scale=100)
        assert not info.reversed
        assert 0 <= info.remainder
        assert (len(out) - 1) * r <= info.s[-1] + 1e-9           # chords <= arc length
    # a right-to-left input is walked from its left end
    out2, info2 = el.resample_equilateral(poly[::-1], 3.0, return_info=True)
    assert info2.reversed
    assert np.allclose(out2, el.resample_equilateral(poly, 3.0), atol=1e-12)


def hairpin(gap):
    a = np.linspace(-np.pi / 2, np.pi / 2, 21)[1:-1]
    low = np.c_[np.linspace(0, 10, 41), np.zeros(41)]
    turn = np.c_[10 + 0.5 * gap * np.cos(a), 0.5 * gap + 0.5 * gap * np.sin(a)]
    high = np.c_[np.linspace(10, 4, 31), np.full(31, gap)]
    return np.vstack([low, turn, high])


def test_resample_hairpin_nearest_far_end():
    poly = hairpin(0.6)              # narrower than r: jump across to the returning branch
    out, info = el.resample_equilateral(poly, 1.0, return_info=True)
    check_resampling(poly, 1.0, out, info, scale=10)
    assert out[:, 0].max() < 10.0
    assert np.sum((out[:-1, 1] < 1e-12) & (out[1:, 1] > 0.6 - 1e-12)) == 1
    poly = hairpin(3.0)              # wider: follow the turn
    out, info = el.resample_equilateral(poly, 1.0, return_info=True)
    check_resampling(poly, 1.0, out, info, scale=10)
    assert out[:, 0].max() > 11.0


def test_resample_stop_point():
    poly = np.array([[0, 0], [5, 0], [5, 0.3], [4.98, 0.3]])
    out, info = el.resample_equilateral(poly, 1.0, return_info=True)
    check_resampling(poly, 1.0, out, info, scale=5)
    assert np.allclose(out[-1], [5, 0], atol=1e-14)
    assert info.remainder == pytest.approx(0.32, abs=1e-14)


def test_resample_random_walks():
    rng = np.random.default_rng(3)
    for _ in range(5):
        poly = np.cumsum(rng.normal(size=(150, 2)), axis=0)
        poly[:, 0] += np.linspace(0, 40, 150)
        out, info = el.resample_equilateral(poly, 1.7, return_info=True)
        check_resampling(poly, 1.7, out, info, scale=100)


def test_resample_bad_input():
    poly = np.c_[np.arange(4.0), np.zeros(4)]
    for r in (0.0, -1.0, np.nan, np.inf, 3.5):
        with pytest.raises(ValueError):
            el.resample_equilateral(poly, r)
    for r in (0.0, -1.0):
        with pytest.raises(ValueError, match="must be positive"):
            el.resample_equilateral(poly, r)
    with pytest.raises(ValueError, match=r"r = 3.5 is longer than the polyline reaches: its points lie within 3 of"):
        el.resample_equilateral(poly, 3.5)
    # the reach from the start A_1, the end of smaller x (here the last point): 6.40, where
    # the first point's is 5; r = 6 has its A_2 on the first side walked
    hook = np.array([[5.0, 0.0], [5.0, 4.0], [0.0, 0.0]])
    assert len(el.resample_equilateral(hook, 6.0)) == 2
    with pytest.raises(ValueError, match=r"lie within 6\.40312 of its start"):
        el.resample_equilateral(hook, 6.5)
    with pytest.raises(ValueError, match="at least 2"):
        el.resample_equilateral(poly[:1], 0.5)
    # the vertex limit the binding exports: a segment below length / (limit - 1) is refused
    limit = el.RESAMPLE_MAX_VERTICES
    with pytest.raises(el.DomainError, match=str(limit)):
        el.resample_equilateral(poly, 0.999 * 3.0 / (limit - 1))
    assert len(el.resample_equilateral(poly, 1.001 * 3.0 / (limit - 1))) > 0.99 * limit
    bad = poly.copy()
    bad[2, 0] = np.inf
    with pytest.raises(ValueError):
        el.resample_equilateral(bad, 0.5)
    with pytest.raises(el.SingularError):
        el.resample_equilateral(np.ones((5, 2)), 0.5)
    # repeated consecutive points are fine
    rep = np.array([[0, 0], [1, 0], [1, 0], [3, 0.0]])
    assert len(el.resample_equilateral(rep, 0.5)) == 7


# ---------------------------------------------------------------- PCA re-normalisation

def test_pca_normalize():
    rng = np.random.default_rng(11)
    t = rng.uniform(-3, 3, 200)
    a = 2.1
    R = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    pts = np.c_[t, 0.5 * np.sin(2 * t)] @ R.T + [40, -7]
    out, f = el.pca_normalize(pts)
    assert np.allclose(out.mean(axis=0), 0, atol=1e-12)
    D = out.T @ out / len(out)
    assert abs(D[0, 1]) <= 1e-12 * D[0, 0]
    assert np.allclose(np.diag(D), f.eigenvalues, rtol=1e-12, atol=1e-12)
    assert f.f1[0] > 0 and f.f2[1] > 0
    assert np.linalg.det(np.c_[f.f1, f.f2]) == pytest.approx(1.0, abs=1e-14)
    assert np.allclose(f.to_parent(out), pts, atol=1e-11)
    assert np.allclose(f.to_local(pts), out, atol=1e-12)
    with pytest.raises(el.SingularError):
        el.pca_normalize(np.ones((4, 2)))
    with pytest.raises(ValueError):
        el.pca_normalize(np.ones((1, 2)))


# ---------------------------------------------------------------- inflection

def reference_inflection(xy, side=0):
    """An independent numpy transcription of seed 000 §5.3 steps (1)-(4) as
    documented in elastica.h (index-ordered chords for 'upper side'; the
    switch rule also applied at step (2); automatic point 2)."""
    n = len(xy)

    def seg_dist(k, i, j):
        A, B, X = xy[i], xy[j], xy[k]
        d = B - A
        t = np.clip((X - A) @ d / (d @ d), 0, 1) if d @ d > 0 else 0.0
        return np.linalg.norm(X - A - t * d)

    def side_of(k, i, j):
        i, j = min(i, j), max(i, j)
        d, w = xy[j] - xy[i], xy[k] - xy[i]
        return int(np.sign(d[0] * w[1] - d[1] * w[0]))

    def farthest(i, j):
        ks = range(min(i, j) + 1, max(i, j))
        return max(ks, key=lambda k: (seg_dist(k, i, j), -k))

    p3 = farthest(0, n - 1)
    sigma = side_of(p3, 0, n - 1)

    def evidence(e):
        a = p3
        for lvl in range(n):
            ks = range(min(a, e) + 1, max(a, e))
            wrong = [seg_dist(k, a, e) for k in ks if side_of(k, a, e) == -sigma]
            if wrong and max(wrong) > 0:
                return (lvl, -max(wrong))
            same = [(seg_dist(k, a, e), -k) for k in ks if side_of(k, a, e) == sigma]
            if not same:
                return (n, 0.0)
            a = -max(same)[1]
        return (n, 0.0)

    if side == 0:
        p2 = n - 1 if evidence(n - 1) <= evidence(0) else 0
    else:
        p2 = n - 1 if side > 0 else 0
    a, b = p2, p3
    while True:
        c = farthest(a, b)
        sc = side_of(c, a, b)
        if sc != 0 and sc == sigma:
            a, b = b, a
        a, b, sigma = b, c, sc
        if abs(a - b) <= 1:
            return b


@pytest.mark.parametrize("seed", range(6))
def test_inflection_matches_reference(seed):
    rng = np.random.default_rng(seed)
    t = np.linspace(-1, 1.3, 120)
    xy = np.c_[t, rng.uniform(1, 3) * (t - 0.1) ** 3 - 0.5 * (t - 0.1)]
    xy += rng.normal(0, 1e-3, xy.shape)
    xy = xy @ random_rotation(rng)[:2, :2].T
    assert el.find_inflection(xy) == reference_inflection(xy)
    for side in (-1, 1):
        assert el.find_inflection(xy, side=side) == reference_inflection(xy, side)


def pipeline(kl, r):
    """seed 000 §5.3 on a generated keyline; returns (polygon, inflection index,
    the true inflection in the polygon's x''y'' coordinates, plane frame, 2D frame)."""
    xy, frame = el.plane_fit(kl.xyz)
    poly = el.resample_equilateral(xy, r)
    poly2, f2 = el.pca_normalize(poly)
    i = el.find_inflection(poly2)
    true2 = f2.to_local(frame.project(kl.inflection_xyz))
    return poly2, i, true2, frame, f2


def test_keyline_pipeline_noise_free():
    for seed in range(5):
        kl = keyline_3d(seed=seed, noise=0.0)
        r = kl.length / 150
        poly, i, true2, frame, f2 = pipeline(kl, r)
        assert np.linalg.norm(poly[i] - true2) <= r
        # back to 3D through both frames: within r of the true 3D inflection
        p3 = frame.to_3d(f2.to_parent(poly[i]))
        assert np.linalg.norm(p3 - kl.inflection_xyz) <= r


def test_keyline_pipeline_noisy():
    """The estimate is local, so noise moves it (about like sqrt(noise));
    at 1e-5 of the length (3 um on 300 mm) it stays within a few r."""
    errs = []
    for seed in range(12):
        kl = keyline_3d(seed=seed, noise=1e-5)
        r = kl.length / 100
        poly, i, true2, frame, f2 = pipeline(kl, r)
        errs.append(np.linalg.norm(poly[i] - true2) / r)
    assert max(errs) <= 4.0, errs


def test_keyline_pipeline_scale_invariant():
    kl = keyline_3d(seed=4, noise=1e-4)
    r = kl.length / 120
    base_poly, base_i = pipeline(kl, r)[:2]
    for s in (1e-9, 1e9):
        kl2 = keyline_3d(seed=4, noise=1e-4)
        kl2.xyz = kl.xyz * s
        kl2.inflection_xyz = kl.inflection_xyz * s
        poly, i = pipeline(kl2, r * s)[:2]
        assert i == base_i
        assert len(poly) == len(base_poly)
        assert np.allclose(poly / s, base_poly, atol=1e-8 * kl.length)


def test_inflection_bad_input():
    a = np.linspace(0, 2, 40)
    with pytest.raises(el.DomainError):
        el.find_inflection(np.c_[np.cos(a), np.sin(a)])              # convex arc
    with pytest.raises(el.DomainError):
        el.find_inflection(np.c_[a, 2 * a])                           # collinear
    with pytest.raises(el.SingularError):
        el.find_inflection(np.ones((10, 2)))
    with pytest.raises(ValueError):
        el.find_inflection(np.c_[a, np.sin(3 * a)][:3])
    with pytest.raises(ValueError):
        el.find_inflection(np.c_[a, np.sin(3 * a)], side=2)
    bad = np.c_[a, np.sin(3 * a)]
    bad[4, 1] = np.nan
    with pytest.raises(ValueError):
        el.find_inflection(bad)


def test_prepare_keyline():
    kl = keyline_3d(seed=9, noise=0.0)
    r = kl.length / 150
    prep = el.prepare_keyline(kl.xyz, r)
    poly, i = pipeline(kl, r)[:2]
    assert prep.inflection == i
    assert np.array_equal(prep.polygon, poly)
    assert np.linalg.norm(prep.to_input(prep.polygon[i]) - kl.inflection_xyz) <= r
    left, right = prep.sides()
    assert np.array_equal(left[0], right[0]) and np.array_equal(left[0], poly[i])
    assert len(left) + len(right) == len(poly) + 1
    # 2D input: no plane fit
    p2 = el.prepare_keyline(kl.xy, r)
    assert p2.frame is None and p2.inflection is not None
    assert p2.to_input(p2.polygon).shape == (len(p2.polygon), 2)
    # a convex arc: no inflection
    a = np.linspace(0, 2, 100)
    arc = el.prepare_keyline(np.c_[np.cos(a), np.sin(a)], 0.05)
    assert arc.inflection is None
    with pytest.raises(el.DomainError, match="no inflection found: the points turn one way"):
        arc.sides()
