"""libelastica.hermite: all elastic curves through two points with two tangents
(seed 004), checked against an independent brute-force shooting search."""
import warnings

import numpy as np
import pytest
from scipy.special import ellipk

import libelastica as el

# ---------------------------------------------------------------- brute force (independent)
# Shooting on the ODE 2 k'' + k^3 - sigma k = 0 with theta' = k, z' = exp(i theta),
# from p0 = 0, t0 = (1, 0); vectorised RK4 over all starts of all problems, damped
# Newton with a finite-difference Jacobian. Nothing here uses the library's formulas.


def _rk4(k0, dk0, sig, L, nsteps):
    h = L / nsteps
    z = np.zeros(k0.shape, complex)
    w = np.ones(k0.shape, complex)
    k = k0.astype(float).copy()
    dk = dk0.astype(float).copy()
    h2, h6 = 0.5 * h, h / 6
    for _ in range(nsteps):
        a_w = 1j * k * w; a_d = 0.5 * k * (sig - k * k)
        w2 = w + h2 * a_w; k2 = k + h2 * dk; d2 = dk + h2 * a_d
        b_w = 1j * k2 * w2; b_d = 0.5 * k2 * (sig - k2 * k2)
        w3 = w + h2 * b_w; k3 = k + h2 * d2; d3 = dk + h2 * b_d
        c_w = 1j * k3 * w3; c_d = 0.5 * k3 * (sig - k3 * k3)
        w4 = w + h * c_w; k4 = k + h * d3; d4 = dk + h * c_d
        d_w = 1j * k4 * w4; d_d = 0.5 * k4 * (sig - k4 * k4)
        z = z + h6 * (w + 2 * w2 + 2 * w3 + w4)
        w = w + h6 * (a_w + 2 * b_w + 2 * c_w + d_w)
        k, dk = k + h6 * (dk + 2 * d2 + 2 * d3 + d4), dk + h6 * (a_d + 2 * b_d + 2 * c_d + d_d)
    return z, w


def _residual(u, mode, P, phi1, fixed, nsteps):
    k0, dk0 = u[..., 0], u[..., 1]
    sig, L = (fixed, u[..., 2]) if mode == "tension" else (u[..., 2], fixed)
    z, w = _rk4(k0, dk0, sig, L, nsteps)
    return np.stack([z.real - P[..., 0], z.imag - P[..., 1], np.angle(w * np.exp(-1j * phi1))], -1)


def _newton(u, mode, P, phi1, fixed, nsteps, iters):
    for _ in range(iters):
        r = _residual(u, mode, P, phi1, fixed, nsteps)
        h = 1e-6 * (1 + np.abs(u))
        up = u[:, None, :] + h[:, None, :] * np.eye(3)[None]
        rp = _residual(up, mode, P[:, None], phi1[:, None], fixed[:, None], nsteps)
        J = np.swapaxes((rp - r[:, None, :]) / h[:, :, None], 1, 2)
        ok = np.isfinite(J).all(axis=(1, 2)) & np.isfinite(r).all(axis=1)
        ok[ok] &= np.abs(np.linalg.det(J[ok])) > 1e-300
        step = np.zeros_like(u)
        step[ok] = np.linalg.solve(J[ok], -r[ok][..., None])[..., 0]
        sc = np.minimum(1.0, 2.0 / (np.linalg.norm(step / (1 + np.abs(u)), axis=1) + 1e-300))
        u = u + sc[:, None] * step
        u[~np.isfinite(u)] = 0.0
    return u, np.linalg.norm(_residual(u, mode, P, phi1, fixed, nsteps), axis=1)


def _scan_starts(problems, nk=20, S=8.0, nsteps=128, keep=40):
    """Tension: integrate a (k0, k0') grid once to arc length S; the lowest local
    minima in s of |x(s) - P|^2 + angle error^2 are the starts (k0, k0', s)."""
    n2 = nk * nk
    cols = []
    for P, phi1, sig in problems:
        B = 10.5 + np.sqrt(2 * max(sig, 0.0))
        Q = 8 + 0.5 * (B * B + abs(sig)) ** 0.75
        g0, g1 = np.meshgrid(np.linspace(-B, B, nk), np.linspace(-Q, Q, nk))
        cols.append((g0.ravel(), g1.ravel(), np.full(n2, sig), np.full(n2, P[0] + 1j * P[1]),
                     np.full(n2, np.exp(-1j * phi1))))
    k0, dk0, sig, Pc, e1 = (np.concatenate(c) for c in zip(*cols))
    h = S / nsteps
    z = np.zeros(k0.shape, complex); w = np.ones(k0.shape, complex); k = k0.copy(); dk = dk0.copy()
    res = np.empty((nsteps, k0.size))
    for i in range(nsteps):
        # one RK4 step: w' = i kappa w is linear in w, so the step from (z, w) is
        # (z + w zz, w ww) with (zz, ww) the step from (0, 1)
        zz, ww = _rk4(k, dk, sig, h, 1)
        z, w = z + w * zz, w * ww
        k, dk = _kstep(k, dk, sig, h)
        res[i] = np.abs(z - Pc) ** 2 + np.angle(w * e1) ** 2
    res[~np.isfinite(res)] = np.inf
    starts = []
    for j in range(len(problems)):
        r = res[:, j * n2:(j + 1) * n2]
        si, ti = np.nonzero((r[1:-1] < r[:-2]) & (r[1:-1] <= r[2:]))
        order = np.argsort(r[1:-1][si, ti])[:keep]
        starts.append(np.column_stack([k0[j * n2 + ti[order]], dk0[j * n2 + ti[order]],
                                       (si[order] + 2) * h]))
    return starts


def _kstep(k, dk, sig, h):
    """One RK4 step of kappa'' = (sig kappa - kappa^3) / 2."""
    f = lambda k: 0.5 * k * (sig - k * k)
    a1, b1 = dk, f(k)
    a2, b2 = dk + 0.5 * h * b1, f(k + 0.5 * h * a1)
    a3, b3 = dk + 0.5 * h * b2, f(k + 0.5 * h * a2)
    a4, b4 = dk + h * b3, f(k + h * a3)
    return k + h / 6 * (a1 + 2 * a2 + 2 * a3 + a4), dk + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4)


def _period(k0, dk0, sig):
    """Period of kappa from the first integral (kappa')^2 + kappa^4/4 - sigma kappa^2/2 = C:
    with |F| = sqrt((k0^2 - sig)^2 + 4 k0'^2), kappa_m^2 = |F| + sig, m = kappa_m^2/(2|F|)."""
    Fn = np.hypot(k0 ** 2 - sig, 2 * dk0)
    m = (Fn + sig) / (2 * Fn)
    if m < 1:
        return 4 * ellipk(m) / np.sqrt(Fn / 2), m
    return 2 * ellipk(1 / m) / (np.sqrt(m) * np.sqrt(Fn / 2)), m


def brute_force(problems, mode, starts=48, coarse=48, fine=400, seed=0):
    """problems: (P with |P| = 1, end tangent angle phi1, sigma or L) with p0 = 0,
    t0 = (1, 0). Returns per problem the (k0, k0', L, sigma) found."""
    rng = np.random.default_rng(seed)
    P = np.array([p[0] for p in problems]); phi1 = np.array([p[1] for p in problems])
    fx = np.array([p[2] for p in problems], dtype=float)
    scanned = _scan_starts(problems) if mode == "tension" else None
    us, idx = [], []
    for i in range(len(problems)):
        if mode == "tension":
            u = scanned[i]
        else:
            L = fx[i]
            B = 10.5 / L + 6.0
            u = np.column_stack([rng.uniform(-B, B, starts), rng.uniform(-0.3, 0.3, starts) * B * B,
                                 rng.uniform(-(10.5 / L) ** 2, 60.0, starts)])
        us.append(u); idx += [i] * len(u)
    u, idx = np.concatenate(us), np.array(idx)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        u, r = _newton(u, mode, P[idx], phi1[idx], fx[idx], coarse, 14)
        good = np.isfinite(r) & (r < 3e-2)
        if mode == "tension":
            good &= u[:, 2] > 0
        u, idx = u[good], idx[good]
        key = np.round(np.column_stack([idx, u / (1 + np.abs(u))]), 3)
        _, first = np.unique(key, axis=0, return_index=True)
        u, idx = u[first], idx[first]
        u, r = _newton(u, mode, P[idx], phi1[idx], fx[idx], fine, 4)
    out = [[] for _ in problems]
    for j in np.nonzero(np.isfinite(r) & (r < 1e-8))[0]:
        i = idx[j]
        if mode == "tension":
            k0, dk0, L, sig = u[j, 0], u[j, 1], u[j, 2], fx[i]
        else:
            k0, dk0, sig, L = u[j, 0], u[j, 1], u[j, 2], fx[i]
        T, m = _period(k0, dk0, sig)
        if L <= 0 or not L <= T * (1 - 1e-6) or abs(m - 1) < 1e-6:
            continue  # not of length <= one period (or on the separatrix)
        if not any(abs(k0 - a[0]) < 1e-6 * (1 + abs(k0)) and abs(L - a[2]) < 1e-6 * L for a in out[i]):
            out[i].append((k0, dk0, L, sig))
    return out


def _problems(n, mode, seed):
    rng = np.random.default_rng(seed)
    out = []
    for _ in range(n):
        a, b = rng.uniform(-np.pi, np.pi, 2)
        fixed = rng.uniform(-15, 40) if mode == "tension" else rng.uniform(1.05, 3.0)
        out.append((np.array([np.cos(a), np.sin(a)]), b, fixed))
    return out


def _solve(P, phi1, fixed, mode):
    kw = {"tension": fixed} if mode == "tension" else {"length": fixed}
    return el.hermite([0, 0], [1, 0], P, [np.cos(phi1), np.sin(phi1)], **kw)


# ---------------------------------------------------------------- checks of one solution

def _wrap(a):
    return (a + np.pi) % (2 * np.pi) - np.pi


def _check_ends(c, p0, t0, p1, t1, tol=1e-10):
    p0, t0, p1, t1 = (np.asarray(v, float) for v in (p0, t0, p1, t1))
    d = np.hypot(*(p1 - p0))
    xy = c.points([0.0, c.length])
    th = c.angle([0.0, c.length])
    assert np.hypot(*(xy[0] - p0)) <= tol * d
    assert np.hypot(*(xy[1] - p1)) <= tol * d
    assert abs(_wrap(th[0] - np.arctan2(t0[1], t0[0]))) <= tol
    assert abs(_wrap(th[1] - np.arctan2(t1[1], t1[0]))) <= tol
    # curvature at the ends along p0 -> p1; a loop (|k| > 1) turns with the sign of k
    kap = c.curvature([0.0, c.length])
    ktol = max(1e-8, 100 * tol)        # the reported end curvatures, looser with a looser tol
    assert kap == pytest.approx([c.kappa0, c.kappa1], rel=ktol, abs=ktol)
    if abs(c.k) > 1:
        assert np.all(np.sign(kap) == np.sign(c.k)) and not c.has_inflection


def _period_of_curve(c):
    """Period of the curvature of a returned curve, from kappa and kappa' at s = 0
    (finite differences of the evaluated curvature) and its sigma."""
    h = 1e-5 / max(1.0, abs(c.kappa0))
    k = c.curvature([-h, 0.0, h], extrapolate=True)   # (a central difference at s = 0)
    return _period(k[1], (k[2] - k[0]) / (2 * h), c.sigma)[0]


# ---------------------------------------------------------------- tests

def test_paper_case1_example():
    P = np.array([0.868, -0.497]); V = np.array([-0.917, -0.398])
    P, V = P / np.linalg.norm(P), V / np.linalg.norm(V)   # printed data are rounded
    a = el.hermite_analyse(P, V, 10.99)
    assert a["case"] == 1
    assert 4.852 < a["kappa_bound"] <= 11.5                  # paper's table: < 11.5
    (lo1, hi1), (lo2, hi2) = a["intervals"]
    assert hi1 == pytest.approx(-2.71, abs=5e-3) and lo2 == pytest.approx(-0.356, abs=5e-3)
    R1, R2 = [-4.006, 0.478, 1.079], [-4.375, -3.777, -2.718, 2.299, 4.076]
    roots = np.array(a["roots"]); br = np.array(a["root_branch"])
    assert np.allclose(np.sort(roots), np.sort(R1 + R2), atol=5e-3)
    g1 = {br[np.argmin(abs(roots - r))] for r in R1}
    g2 = {br[np.argmin(abs(roots - r))] for r in R2}
    assert len(g1) == 1 and len(g2) == 1 and g1 != g2
    assert np.allclose(a["special"], [-5.283, -3.315, 0.675, 3.315], atol=2e-3)
    sols = el.hermite([0, 0], [0, 1], P, V, tension=10.99)
    assert any(abs(s.kappa0 + 4.852) < 2e-3 for s in sols)
    for s in sols:
        _check_ends(s, [0, 0], [0, 1], P, V)


def test_solutions_meet_ends_sorted_and_within_one_period():
    rng = np.random.default_rng(3)
    n = 0
    for _ in range(40):
        p0, p1 = rng.uniform(-2, 2, 2), rng.uniform(-2, 2, 2)
        a, b = rng.uniform(-np.pi, np.pi, 2)
        t0, t1 = [np.cos(a), np.sin(a)], [np.cos(b), np.sin(b)]
        d = np.hypot(*(p1 - p0))
        sols = el.hermite(p0, t0, p1, t1, tension=rng.uniform(-10, 40) / d ** 2)
        assert [s.energy_value for s in sols] == sorted(s.energy_value for s in sols)
        for s in sols:
            _check_ends(s, p0, t0, p1, t1)
            assert s.energy_value == pytest.approx(s.energy(), rel=1e-8, abs=1e-12)
            assert s.length <= _period_of_curve(s) * (1 + 1e-6)
            kap = s.curvature(np.linspace(0, s.length, 801))
            big = np.abs(kap) > 1e-6 * np.abs(kap).max()
            assert s.has_inflection == bool(np.any(np.diff(np.sign(kap[big])) != 0))
            n += 1
    assert n > 40


def test_clockwise_loops_have_negative_k_and_run_p0_to_p1():
    """Mirroring the data in the x axis mirrors every solution: a loop keeps |k|
    and flips the sign of k; both run from p0 to p1 (checked by _check_ends)."""
    rng = np.random.default_rng(11)
    signs = set()
    for _ in range(25):
        p1 = rng.uniform(-2, 2, 2)
        a, b = rng.uniform(-np.pi, np.pi, 2)
        t0, t1 = np.array([np.cos(a), np.sin(a)]), np.array([np.cos(b), np.sin(b)])
        m = np.array([1.0, -1.0])
        sig = rng.uniform(0, 40) / (p1 @ p1)
        sols = el.hermite([0, 0], t0, p1, t1, tension=sig)
        mirr = el.hermite([0, 0], t0 * m, p1 * m, t1 * m, tension=sig)
        assert len(sols) == len(mirr)
        for s, r in zip(sols, mirr):          # same energies, so the same order
            _check_ends(s, [0, 0], t0, p1, t1)
            _check_ends(r, [0, 0], t0 * m, p1 * m, t1 * m)
            assert r.energy_value == pytest.approx(s.energy_value, rel=1e-8, abs=1e-12)
            assert r.kappa0 == pytest.approx(-s.kappa0, rel=1e-7, abs=1e-9)
            if abs(s.k) > 1 + 1e-6:
                assert r.k == pytest.approx(-s.k, rel=1e-7)
                signs.add(np.sign(s.k))
    assert signs == {-1.0, 1.0}


@pytest.mark.c_numerics
@pytest.mark.parametrize("mode", ["tension", "length"])
def test_completeness_against_brute_force(mode):
    problems = _problems(200, mode, seed=5 if mode == "tension" else 6)   # issue 5: >= 200 per mode
    found = brute_force(problems, mode)
    nbrute = 0
    for (P, phi1, fixed), bl in zip(problems, found):
        sols = _solve(P, phi1, fixed, mode)
        for s in sols:
            _check_ends(s, [0, 0], [1, 0], P, [np.cos(phi1), np.sin(phi1)])
        for k0, dk0, L, sig in bl:
            nbrute += 1
            assert any(abs(s.kappa0 - k0) < 1e-4 * (1 + abs(k0)) and abs(s.length - L) < 1e-4 * L
                       and abs(s.sigma - sig) < 1e-4 * (1 + abs(sig)) for s in sols), \
                f"solver missed k0={k0}, L={L}, sigma={sig} for P={P}, phi1={phi1}, {mode}={fixed}"
    assert nbrute >= 100   # the search must actually find solutions to compare


def test_length_mode_sigma_and_length():
    p0, t0, p1, t1 = [0, 0], [1, 0.3], [2, 0.5], [0.2, -1]
    for L in (2.5, 4.0):
        sols = el.hermite(p0, t0, p1, t1, length=L)
        assert sols
        for s in sols:
            assert s.length == L   # the given length is exact, not the root finder's approximation
            _check_ends(s, p0, t0, p1, t1)
            # the returned sigma is the curve's: tension mode with it returns the same curve
            again = el.hermite(p0, t0, p1, t1, tension=s.sigma)
            assert any(abs(a.kappa0 - s.kappa0) < 1e-6 * (1 + abs(s.kappa0)) and
                       abs(a.length - L) < 1e-7 * L for a in again)


def test_degenerate_data():
    # collinear: the straight segment is the lowest-energy solution
    for sig in (-3.0, 0.0, 5.0):
        sols = el.hermite([1, 1], [3, 4], [4, 5], [0.6, 0.8], tension=sig)
        assert sols[0].k == 0 and sols[0].energy_value == 0 and sols[0].length == pytest.approx(5)
    sols = el.hermite([1, 1], [3, 4], [4, 5], [0.6, 0.8], length=5.0)
    assert len(sols) == 1 and sols[0].k == 0
    # buckled strip (Euler): collinear data, L > |p1 - p0|, compressed solutions
    sols = el.hermite([0, 0], [1, 0], [1, 0], [1, 0], length=1.3)
    assert any(s.sigma < 0 for s in sols)
    for s in sols:
        _check_ends(s, [0, 0], [1, 0], [1, 0], [1, 0])
    # t1 = -t0 (case 3) and t1 = t0 offset
    for sig in (-2.0, 0.0, 3.0):
        for p1, t1 in (([0, 1], [-1, 0]), ([1, 1], [1, 0])):
            for s in el.hermite([0, 0], [1, 0], p1, t1, tension=sig):
                _check_ends(s, [0, 0], [1, 0], p1, t1)
    # sigma < 0 so strong that no period is as long as the chord: no curve
    assert el.hermite([0, 0], [1, 0], [1, 0.5], [0, 1], tension=-500.0) == []
    with pytest.raises(el.DomainError, match="p0 and p1 coincide"):
        el.hermite([0, 0], [1, 0], [0, 0], [0, 1], tension=1.0)
    with pytest.raises(el.DomainError, match=r"length 1 is not longer than \|p1 - p0\| = 1.41421"):
        el.hermite([0, 0], [1, 0], [1, 1], [0, 1], length=1.0)
    # the tension range, sigma |p1 - p0|^2 <= HERMITE_SIGMA_D2_MAX, named with the bound here
    d2 = 2.0 ** 2 + 1.0
    assert len(el.hermite([1, 1], [1, 0], [3, 2], [1, 0], tension=el.HERMITE_SIGMA_D2_MAX / d2 * 0.999)) > 0
    with pytest.raises(el.DomainError, match=r"past the 100000 the solver covers \(here a tension of at most 20000\)"):
        el.hermite([1, 1], [1, 0], [3, 2], [1, 0], tension=el.HERMITE_SIGMA_D2_MAX / d2 * 1.001)
    with pytest.raises(el.DomainError, match="outside the range the solver covers"):
        el.hermite([0, 0], [1, 0], [1e-120, 0], [1, 0], tension=1.0)
    with pytest.raises(ValueError):
        el.hermite([0, 0], [0, 0], [1, 1], [0, 1], tension=1.0)
    with pytest.raises(ValueError):
        el.hermite([0, 0], [1, 0], [1, 1], [0, 1])
    with pytest.raises(ValueError):
        el.hermite([0, 0], [1, 0], [1, 1], [0, 1], tension=1.0, length=2.0)
    with pytest.raises(ValueError):
        el.hermite([0, np.nan], [1, 0], [1, 1], [0, 1], tension=1.0)


def test_plain_floats_and_arrays_give_the_same_solutions():
    """The binding's fast path for tuples of Python floats and the general one (lists of
    ints, numpy arrays) solve the same problem."""
    a = el.hermite((0.0, 0.0), (1.0, 0.2), (1.5, 0.7), (-0.3, 1.0), tension=7.0)
    b = el.hermite([0, 0], np.array([1.0, 0.2]), np.array([1.5, 0.7]), [-0.3, 1], tension=7)
    assert len(a) == len(b) > 0
    for x, y in zip(a, b):
        assert x == y and x.energy_value == y.energy_value and x.kappa1 == y.kappa1
    for bad in [(float("nan"), 0.0), (float("inf"), 0.0), (0.0, -float("inf")), (1.0,), (1.0, 2.0, 3.0)]:
        with pytest.raises(ValueError):
            el.hermite(bad, (1.0, 0.0), (1.0, 1.0), (0.0, 1.0), tension=1.0)


def test_fast_paths_equal_the_general_path_and_refusals_leave_no_state():
    """hermite()'s fast paths (tuples of floats, a float tension or length, options
    checked only when they change) against the general path (arrays, numpy scalars,
    explicit options) on random problems, chains near the separatrix included; and a
    refused call (NaN/inf tension or length, a bad option) changes no later result."""
    rng = np.random.default_rng(31)
    def key(sols):
        return [(type(s).__name__, s.length, s.kappa0, s.kappa1, s.energy_value, s.has_inflection)
                for s in sols]
    bad_calls = [dict(tension=float("nan")), dict(length=float("inf")), dict(tension="x"),
                 dict(tension=1.0, tol=0.0), dict(tension=1.0, samples=True),
                 dict(tension=1.0, grid=-1), dict(length=-2.0)]
    chains = 0
    for i in range(120):
        a, b = rng.uniform(-np.pi, np.pi, 2)
        p1 = rng.uniform(-1, 1, 2)
        t0, t1 = (float(np.cos(a)), float(np.sin(a))), (float(np.cos(b)), float(np.sin(b)))
        mode = "tension" if i % 3 else "length"
        value = float(rng.uniform(-10, 3000) if mode == "tension" else rng.uniform(1.05, 3) * np.hypot(*p1))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", RuntimeWarning)
            fast = el.hermite((0.0, 0.0), t0, (float(p1[0]), float(p1[1])), t1, **{mode: value})
            bad = bad_calls[i % len(bad_calls)]
            with pytest.raises(ValueError):
                el.hermite((0.0, 0.0), t0, (float(p1[0]), float(p1[1])), t1, **bad)
            general = el.hermite(np.zeros(2), np.array(t0), p1, list(t1), **{mode: np.float64(value)},
                                 tol=np.float64(1e-10), samples=np.int64(12), grid=6.0, max_solutions=64)
            again = el.hermite((0.0, 0.0), t0, (float(p1[0]), float(p1[1])), t1, **{mode: value})
        assert key(fast) == key(general) == key(again)
        assert fast.unrepresentable == general.unrepresentable and fast.complete == general.complete
        chains += sum(isinstance(s, el.HermiteChain) for s in fast)
    assert chains > 0   # the chain rows of the fast unpacking were exercised


def test_options_equal_to_the_last_ones_but_refused_are_still_refused():
    """hermite() skips checking tol, samples, grid and max_solutions when they are the
    very objects set by the call before: a refused value equal to the last valid one
    (grid=True after grid=1, samples=12.5 after 12.5 was refused) is refused again."""
    ends = ((0.0, 0.0), (1.0, 0.0), (1.0, 0.5), (0.0, 1.0))
    first = el.hermite(*ends, tension=2.0, grid=1)
    with pytest.raises(ValueError):
        el.hermite(*ends, tension=2.0, grid=True)
    for _ in range(2):
        with pytest.raises(ValueError):
            el.hermite(*ends, tension=2.0, samples=12.5)
    with pytest.raises(ValueError):
        el.hermite(*ends, tension=2.0, tol=None)
    again = el.hermite(*ends, tension=2.0, grid=1)
    assert [(s.length, s.k) for s in again] == [(s.length, s.k) for s in first]


def test_more_solutions_than_the_thread_array_holds_are_all_returned():
    """The binding solves into a per-thread array (el_hermite_solve_into); a problem
    with more solutions than it holds is solved again into a larger one, and returns
    the same solutions as with room for all of them."""
    import sys
    H = sys.modules["libelastica.hermite"]
    ends = ((0.0, 0.0), (1.0, 0.0), (1.0, 0.2), (1.0, 0.1))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)
        roomy = el.hermite(*ends, tension=1500.0)
        assert len(roomy) >= 3
        H._local.state = H._with_capacity(H._local.state, 1)
        tight = el.hermite(*ends, tension=1500.0)
    assert len(H._local.state[2]) == len(roomy) + 1   # grown to the count
    assert [(type(s), s.length, s.k, s.kappa0, s.energy_value) for s in tight] == \
           [(type(s), s.length, s.k, s.kappa0, s.energy_value) for s in roomy]
    assert any(isinstance(s, el.HermiteChain) for s in tight)


def test_tension_keeps_steep_roots():
    """Seven elastic curves of tension 2 join (0, 0) to (1, 0.3), both tangents along x, of
    four lengths: each meets the ends (el_smooth_eval, to 1e-10) at that tension; the tangents
    being parallel, the half turn about the chord's midpoint with the curve reversed maps
    each onto a solution (its partner: kappa0 and kappa1 swapped and negated), one of them
    onto itself. Before the root finder's interpolation steps and its jump test on |f|
    halving (hermite_tension.c's bracket_root, 0049e00), two lengths (k 1.103, length 5.016;
    k 0.752, length 2.779) were lost; before WHOLE_PERIOD (hermite_objective.c) the
    partners of three."""
    inner = ((0.0, 0.0), (1.0, 0.0), (1.0, 0.3), (1.0, 0.0))
    sols = el.hermite(*inner, tension=2.0)
    assert len(sols) == 7
    assert len({round(c.length, 6) for c in sols}) == 4
    ends = np.array([c.curvature(np.array([0.0, c.length])) for c in sols])
    for k0, k1 in ends:
        assert np.min(np.hypot(ends[:, 0] + k1, ends[:, 1] + k0)) <= 1e-8 * (1.0 + abs(k0) + abs(k1))
    for c in sols:
        assert c.sigma == 2.0
        end = c.points(np.array([c.length]))[0]
        assert np.hypot(end[0] - 1.0, end[1] - 0.3) <= 1e-10
        th = c.angle(np.array([0.0, c.length]))
        assert abs(np.angle(np.exp(1j * th[0]))) <= 1e-10 and abs(np.angle(np.exp(1j * th[1]))) <= 1e-10


def test_a_call_made_inside_a_call_leaves_its_results_intact():
    """A finaliser (or signal handler) that calls hermite while another call in the same
    thread reads its results from the thread's memory: that call still returns its own
    solutions (the inner one gets memory of its own). The garbage collector is set to
    run after every few allocations, so the finaliser runs at every point of the call."""
    import gc
    import sys

    def sols(r):
        return [(c.k, c.q, c.length, c.sigma) for c in r]

    outer = ((0.0, 0.0), (0.0, 1.0), (2.0, 0.0), (0.0, -1.0))
    inner = ((0.0, 0.0), (1.0, 0.0), (1.0, 0.3), (1.0, 0.0))
    ref, ref_inner = sols(el.hermite(*outer, length=4.0)), sols(el.hermite(*inner, tension=0.5))
    assert len(ref) != len(ref_inner)
    inner_runs, inside = [], []

    class Cyclic:
        def __del__(self):
            inside.append(sys._getframe(1).f_code.co_name == "hermite")
            inner_runs.append(sols(el.hermite(*inner, tension=0.5)))

    old = gc.get_threshold()
    gc.collect()
    gc.freeze()     # the session's heap out of the collections below (each ~0.13 s in make check)
    try:
        for threshold in range(1, 40):
            gc.collect()
            gc.set_threshold(threshold, 1000, 1000)
            c = Cyclic()
            c.me = c
            del c
            got = sols(el.hermite(*outer, length=4.0))
            gc.set_threshold(*old)
            gc.collect()
            assert got == ref, threshold
    finally:
        gc.set_threshold(*old)
        gc.unfreeze()
    assert sum(inside) >= 3     # the finaliser ran inside the call (the point of the test)
    assert len(inner_runs) == 39 and all(r == ref_inner for r in inner_runs)


def test_two_threads_solve_at_once():
    """The binding's per-thread buffers: concurrent calls give the serial results."""
    from together import run_together
    rng = np.random.default_rng(8)
    probs = [(tuple(rng.uniform(-2, 2, 2)), tuple(rng.uniform(-1, 1, 2)), float(rng.uniform(0, 30)))
             for _ in range(60)]
    def solve(p):
        return [(s.length, s.kappa0) for s in el.hermite((0.0, 0.0), (1.0, 0.0), p[0], p[1], tension=p[2])]
    serial = [solve(p) for p in probs]
    out = [[None] * len(probs) for _ in range(2)]
    def run(k):
        for i, p in enumerate(probs):
            out[k][i] = solve(p)
    run_together(lambda: run(0), lambda: run(1))
    assert out[0] == serial and out[1] == serial


def test_curves_near_the_separatrix_are_chains_that_evaluate_like_one_curve():
    """At high tension (sigma |p1-p0|^2 = 1500) most curves lie so close to the
    separatrix that no single SmoothElastica meets tol (issue 12): every one is
    returned all the same (none unrepresentable, no warning), those through a saddle
    as a HermiteChain: it meets the ends like a SmoothElastica, its pieces follow each
    other with continuous position, angle and curvature (to 1e-7 of the largest), its
    energy is the sum of theirs, one B-spline is within tol of it everywhere, and its
    JSON round trip is the same curve."""
    p0, t0, p1, t1 = (0.0, 0.0), (1.0, 0.0), (1.0, 0.2), (1.0, 0.1)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        sols = el.hermite(p0, t0, p1, t1, tension=1500.0)
    assert sols.unrepresentable == 0 and sols.complete
    chains = [c for c in sols if isinstance(c, el.HermiteChain)]
    assert len(chains) >= 2
    for c in sols:
        _check_ends(c, p0, t0, p1, t1)
    for c in chains:
        assert 2 <= len(c.pieces) <= 3 and c.length == pytest.approx(sum(p.length for p in c.pieces))
        assert c.energy() == pytest.approx(c.energy_value, rel=1e-9)
        s = np.linspace(0.0, c.length, 4001)
        th, kap = c.angle(s), c.curvature(s)
        assert np.max(np.abs(np.diff(th))) < 0.05            # continuous across the joints
        assert abs(c.sigma - 1500.0) <= 1e-12 * 1500.0
        for a, b in zip(c.pieces[:-1], c.pieces[1:]):
            assert np.hypot(*(a.points([a.length])[0] - b.points([0.0])[0])) <= 1e-12
            assert abs(a.curvature([a.length])[0] - b.curvature([0.0])[0]) <= 1e-7 * np.max(np.abs(kap))
        assert len(c.inflections()) == len(el.elastica_inflections(c))
        assert (len(c.inflections()) > 0) == c.has_inflection
        b = c.to_bspline(tol=1e-7, degree=5)
        assert b.max_deviation <= 1e-7
        # the certified distance (across the curve: the parameters differ along it)
        gap = b.evaluate(s) - c.points(s)
        assert np.max(np.abs(gap[:, 0] * np.sin(th) - gap[:, 1] * np.cos(th))) <= 1e-7
        again = el.io.curve_from_dict(el.io.curve_to_dict(c))
        assert np.array_equal(again.points(s), c.points(s))


def test_length_mode_work_limit_returns_the_solutions_found_with_a_warning(monkeypatch):
    """EL_EMAXITER (length mode's work limit) keeps the solutions found so far: the
    list holds them, complete is False and a RuntimeWarning says so."""
    import sys
    H = sys.modules["libelastica.hermite"]       # the module (el.hermite is the function)
    real = H._solve_into                          # (lib.el_hermite_solve_into)

    def limited(*args):
        real(*args)
        return H.lib.EL_EMAXITER

    monkeypatch.setattr(H, "_solve_into", limited)
    with pytest.warns(RuntimeWarning, match="work limit"):
        sols = el.hermite((0, 0), (0, 1), (2, 0), (0, -1), length=4.0)
    assert not sols.complete and len(sols) > 0
    for c in sols:
        _check_ends(c, (0, 0), (0, 1), (2, 0), (0, -1))


@pytest.mark.parametrize("a", [1e-4, 3e-4, 1e-3])
def test_tangents_near_the_chord_give_the_near_straight_curve_first(a):
    """A shallow arc's tangents +-a off the chord at tension 0 (two nearly aligned edges):
    the near-straight curve, energy ~ 4 a^2 / d, is the first solution (only a loop of
    energy 23 was returned for a from 1e-9 to 3e-4, QA)."""
    sols = el.hermite((0, 0), (np.cos(a), np.sin(a)), (1, 0), (np.cos(a), -np.sin(a)), tension=0.0)
    assert sols[0].energy_value == pytest.approx(4 * a * a, rel=1e-2)
    assert sols[0].length == pytest.approx(1.0, abs=1e-5)


def test_near_straight_curve_beyond_the_parameters_is_counted_and_named():
    """Tangents 1e-6 rad off the chord at tension 0: the near-straight curve is a sliver of
    a huge elastica that the parameters meet only to ~1e-10; counted unrepresentable with a
    warning that says so, and returned with a larger tol."""
    t0, t1 = (np.cos(1e-6), np.sin(1e-6)), (np.cos(1e-6), -np.sin(1e-6))
    with pytest.warns(RuntimeWarning, match="nearly straight"):
        sols = el.hermite((0, 0), t0, (1, 0), t1, tension=0.0)
    assert sols.unrepresentable == 1 and all(s.energy_value > 1 for s in sols)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        loose = el.hermite((0, 0), t0, (1, 0), t1, tension=0.0, tol=1e-8)
    assert loose[0].energy_value == pytest.approx(4e-12, rel=1e-2) and loose[0].residual <= 1e-8


@pytest.mark.parametrize("scale", [1e-9, 1e-3, 1e6, 1e9])
def test_the_fair_u_is_found_at_every_scale_and_place(scale):
    # QA: (0, 0) t (1, 0) to (0, 1) t (-1, 0), length 1.05 x the chord: the fair U (energy
    # 54.9 / chord, a chain near the separatrix) was counted unrepresentable at scales
    # <= 1e-3 and >= 1e6, and away from the origin the coordinates' rounding cost others
    ref = el.hermite((0.0, 0.0), (1, 0), (0.0, 1.0), (-1, 0), length=1.05)
    for off in (0.0, 1e6):
        p0 = (off * scale, -off * scale)
        p1 = (p0[0], p0[1] + scale)
        with warnings.catch_warnings():
            warnings.simplefilter("error")      # no "unrepresentable" RuntimeWarning
            s = el.hermite(p0, (1, 0), p1, (-1, 0), length=1.05 * scale)
        assert s.unrepresentable == 0 and len(s) == len(ref) == 4
        e = sorted(c.energy_value * scale for c in s)
        assert e[0] == pytest.approx(54.903, abs=1e-3)
        assert np.allclose(e, sorted(c.energy_value for c in ref), rtol=1e-8)
        for c in s:
            xy = c.points(np.array([0.0, c.length]))
            assert np.abs(xy - np.array([p0, p1])).max() <= 1e-10 * scale + 4e-16 * abs(off * scale)


@pytest.mark.parametrize("mode, value", [("tension", 5.0), ("tension", 0.5), ("length", 1.5),
                                         ("length", 2.5), ("length", 4.0)])
def test_a_u_turn_keeps_its_solutions_when_its_data_move(mode, value):
    # QA21 F1: (0, 0) t (0, 1) to (1, 0) t (0, -1) has 4 solutions; p1 moved by 1e-12, or t0
    # turned by 1e-12 rad, gave 0 (1e-8: 1 or 2), silently, and so did the same U-turn turned
    # by 0.5 rad and shifted by (3000, -2100) (the rounding of the shift moves it so)
    def rot(v, a):
        return np.array([np.cos(a) * v[0] - np.sin(a) * v[1], np.sin(a) * v[0] + np.cos(a) * v[1]])
    p0, t0, p1, t1 = np.zeros(2), np.array([0.0, 1.0]), np.array([1.0, 0.0]), np.array([0.0, -1.0])
    ref = sorted(c.energy_value for c in el.hermite(p0, t0, p1, t1, **{mode: value}))
    assert len(ref) == 4
    cases = []
    for eps in (1e-14, 1e-12, 1e-10, 1e-8, 1e-6, 1e-4, 1e-2):
        for dp in ((eps, 0.0), (0.0, eps), (-eps, 0.0), (0.0, -eps)):
            cases.append((eps, 1.0, p0, t0, p1 + dp, t1))
        cases.append((eps, 1.0, p0, rot(t0, eps), p1, t1))
        cases.append((eps, 1.0, p0, t0, p1, rot(t1, -eps)))
    for scale in (1e-3, 1.0, 1e5):
        off = np.array([3000.0, -2100.0]) * scale
        cases.append((1e-12, scale, off, rot(t0, 0.5), rot(p1 * scale, 0.5) + off, rot(t1, 0.5)))
    for eps, scale, a, ta, b, tb in cases:
        kw = {mode: value / scale ** 2 if mode == "tension" else value * scale}
        s = el.hermite(a, ta, b, tb, **kw)
        assert len(s) == 4 and s.unrepresentable == 0, (eps, scale, a, ta, b, tb)
        for c in s:
            _check_ends(c, a, ta, b, tb)
        e = sorted(c.energy_value * scale for c in s)
        assert np.allclose(e, ref, rtol=20 * eps + 1e-9)


def test_a_loops_mirror_image_is_kept_beside_it():
    # tangents along the chord at sigma |p1 - p0|^2 = 5000: the segment, a loop turning once
    # counter-clockwise (separatrix, a chain) and its mirror image in the chord; the mirror was
    # taken for the loop itself (the chains' first pieces turn alike) and dropped
    t = np.array([np.cos(-2.5), np.sin(-2.5)])
    for d in (1.0, 0.1, 1e4):
        p0, p1 = np.zeros(2), d * t
        sols = el.hermite(p0, t, p1, t, tension=5000.0 / d**2)
        rm = np.sqrt(2500.0)                       # sqrt(mu) |p1 - p0|
        loops = [c for c in sols if c.energy_value * d > 1e-6]
        assert len(sols) == 3 and sorted(np.sign(c.k) for c in loops) == [-1, 1]
        for c in sols:
            _check_ends(c, p0, t, p1, t)
        for c in loops:
            assert c.length / d == pytest.approx(1.0 + 4.0 / rm, rel=1e-9)
            assert c.energy_value * d == pytest.approx(8.0 * rm, rel=1e-9)
