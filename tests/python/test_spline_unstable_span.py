"""By tension, a span past its force-free length (gamma_j = -dL_j/dsigma < 0 at fixed end
angles) is a maximum of integral kappa^2 + sigma ds in its own length: the spline is no
minimum (spline_stable.c's TENSION_COUNT: neg(H) + #{gamma_j < 0}). Before, tension mode
counted neg(H) only and read such a spline stable. Checked independently of the library's
second variation: el.hermite by length at the same ends, d2/dl2 (integral kappa^2 + sigma l)
by a central difference, its sign against ElasticSpline.unstable on every Hermite branch."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el

P0, P1 = (0.0, 0.0), (1.0, 0.0)


def second_difference(t0, t1, sigma, q):
    """d2/dl2 of integral kappa^2 + sigma l at fixed ends, on q's branch (el.hermite by length)."""
    d, f = 1e-3 * q.length, []
    for dd in (-d, 0.0, d):
        sols = [r for r in el.hermite(P0, t0, P1, t1, length=q.length + dd) if hasattr(r, "phi")]
        r = min(sols, key=lambda r: abs(r.k - q.k) + abs(r.mu - q.mu) + abs(r.phi - q.phi))
        f.append(r.energy() + sigma * (q.length + dd))
    return (f[0] - 2 * f[1] + f[2]) / d ** 2


def branches(t0, t1, sigma):
    out = []
    for q in el.hermite(P0, t0, P1, t1, tension=sigma):
        if not hasattr(q, "phi") or q.length > 20:
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")   # Unstable-, LoopWarning: the branch as it is
            sp = el.elastic_spline([P0, P1], tension=sigma, start=t0, end=t1, initial=[q])
        assert sp.length == pytest.approx(q.length, rel=1e-9)   # the branch it started on
        out.append((q, sp))
    return out


def test_u_turn_span_past_its_force_free_length_is_unstable():
    """The U-turn (tangents up, then down) at sigma 0.3 has four branches; the one of length
    2.894 has gamma = -2.458 and d2/dl2 = 1 / gamma = -0.4067: unstable (read stable before)."""
    t0, t1, sigma = (0.0, 1.0), (0.0, -1.0), 0.3
    seen = {}
    for q, sp in branches(t0, t1, sigma):
        c = second_difference(t0, t1, sigma, q)
        assert sp.unstable == (c < 0), (q.length, c)
        seen[round(q.length, 3)] = (c, sp)
    c, sp = seen[2.894]
    assert c == pytest.approx(1 / -2.458, rel=2e-3)
    assert sp.unstable and sp.unstable_span == 0
    with pytest.warns(el.UnstableWarning, match="snap to another shape"):
        el.elastic_spline([P0, P1], tension=sigma, start=t0, end=t1,
                          initial=[min(el.hermite(P0, t0, P1, t1, tension=sigma),
                                       key=lambda r: abs(r.length - 2.894))])
    assert sum(not s.unstable for _, s in seen.values()) == 3


@pytest.mark.parametrize("seed", range(4))
def test_verdict_agrees_with_the_length_difference_on_random_ends(seed):
    """Random end tangents and tensions, every branch: the verdict is the sign of d2/dl2
    (on 400 such draws, 957 branches, 96 negative: 96 misread before, 0 after but one
    difference that picked another branch)."""
    rng = np.random.default_rng(100 + seed)
    negative = agree = total = 0
    for _ in range(12):
        a0, a1 = rng.uniform(-np.pi, np.pi, 2)
        t0, t1 = (np.cos(a0), np.sin(a0)), (np.cos(a1), np.sin(a1))
        sigma = 10 ** rng.uniform(-1.5, 1.0)
        for q, sp in branches(t0, t1, sigma):
            c = second_difference(t0, t1, sigma, q)
            if abs(c) > 1e3:      # another branch picked by the difference: no verdict
                continue
            total += 1
            negative += c < 0
            agree += sp.unstable == (c < 0)
    assert total >= 10 and negative >= 1 and agree == total, (agree, total, negative)


def test_free_batten_span_past_its_force_free_length_slides():
    """Tension 0 (the 'slides' check takes the same count, TENSION_COUNT): a clamped span
    started (initial=) on a Hermite branch with d2/dl2 integral kappa^2 < 0 is no free batten
    (DomainError, it slides off); one with d2/dl2 > 0 is returned as it is. Before, every
    branch was returned (6 of the 10 below have d2/dl2 < 0)."""
    rng = np.random.default_rng(5)
    slid = kept = 0
    for _ in range(20):
        a0, a1 = rng.uniform(-np.pi, np.pi, 2)
        t0, t1 = (np.cos(a0), np.sin(a0)), (np.cos(a1), np.sin(a1))
        for q in el.hermite(P0, t0, P1, t1, tension=0.0):
            if not hasattr(q, "phi") or q.length > 20:
                continue
            c = second_difference(t0, t1, 0.0, q)
            if abs(c) > 1e3:      # another branch picked by the difference: no verdict
                continue
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                if c < 0:
                    with pytest.raises(el.DomainError, match="slides off"):
                        el.elastic_spline([P0, P1], tension=0.0, start=t0, end=t1, initial=[q])
                    slid += 1
                else:
                    sp = el.elastic_spline([P0, P1], tension=0.0, start=t0, end=t1, initial=[q])
                    assert sp.length == pytest.approx(q.length, rel=1e-9) and not sp.unstable
                    kept += 1
    assert slid >= 5 and kept >= 3, (slid, kept)


# Multi-span (TENSION_COUNT's Schur structure needs free knot angles too): hand-like ducks, one
# span started (initial=) on a longer Hermite branch of its end angles at the given tension
# (/tmp/revspline/fdcheck.py's cases 18 and 38 of 160, all 160 agreeing with the library)
MULTI = {
    "natural": ([(0.0, 0.0), (-0.238591376375, -0.811659697041), (0.523085648489, -1.092280476224),
                 (1.701007954656, -1.498738766755), (2.006084717604, -1.028188787857)],
                0.7081432543570075, False,
                [(0.0, 0.0, -0.585856930399896, 3.1044789280155416, 0.7463417012401921, -1.9056606504634868, 0.907302100787049),
                 (-0.23859137637509134, -0.8116596970407214, -1.7421948377856367, 3.6686258778481795, 0.7404435897433811, 0.49569344432796075, 0.8466471109957481),
                 (0.5230856484886385, -1.0922804762236331, 2.5315953137692526, 0.3049163225214981, -1.0395213228741742, 1.8036815104086845, 1.2562788723621885),
                 (1.701007954656212, -1.498738766755329, 1.0636666459160848, 8.274567276269412, 0.7220769867808867, -1.9824655629678796, 1.3401808956740704)]),
    "clamped": ([(0.0, 0.0), (0.333708317889, 0.608070431567), (0.134997174573, 2.314757282152),
                 (-0.877158685887, 2.918622368683)],
                0.1783095274006117, True,
                [(0.0, 0.0, 1.37465414433407, 12.607839631744842, 0.7096024855990747, -3.49701149714846, 1.6901608652919855),
                 (0.333708317888952, 0.6080704315665948, 2.907775983266814, 2.5657829271061754, 0.7192870033252746, -3.623589477200045, 1.8504949109049016),
                 (0.13499717457275712, 2.3147572821518825, 1.1895233201503337, 2.4212863608937787, 0.7200073746033082, 0.616143233570744, 1.20571138894028)]),
}


def span_energy(p0, p1, a0, a1, length, ref):
    """e_j + its length's share: integral kappa^2 on the el.hermite-by-length branch nearest ref."""
    sols = [r for r in el.hermite(p0, (np.cos(a0), np.sin(a0)), p1, (np.cos(a1), np.sin(a1)),
                                  length=length, samples=24, grid=12) if hasattr(r, "phi")]
    ref_pts = ref.points(np.linspace(0.0, ref.length, 24))
    dist = [np.max(np.linalg.norm(r.points(np.linspace(0.0, r.length, 24)) - ref_pts, axis=1)) for r in sols]
    return sols[int(np.argmin(dist))].energy()


def fd_hessian(pts, sigma, sp, free_ends, d=1e-3):
    """The dense second variation of sum_j (integral kappa^2 + sigma l_j) in the free knot angles
    and every span length, by central differences of each span's (ta, tb, l) energy."""
    n = len(pts)
    free = [i for i in range(n) if free_ends or 0 < i < n - 1]
    col = {i: t for t, i in enumerate(free)}
    hess = np.zeros((len(free) + n - 1, len(free) + n - 1))
    for j, q in enumerate(sp.pieces):
        x0, h = np.array([sp.angles[j], sp.angles[j + 1], q.length]), np.array([d, d, d * q.length])
        f = lambda e: span_energy(pts[j], pts[j + 1], *(x0 + np.array(e) * h), q) + sigma * (x0[2] + e[2] * h[2])
        hs, eye = np.zeros((3, 3)), np.eye(3, dtype=int)
        for a in range(3):
            hs[a, a] = (f(eye[a]) - 2 * f((0, 0, 0)) + f(-eye[a])) / h[a] ** 2
            for b in range(a + 1, 3):
                hs[a, b] = hs[b, a] = (f(eye[a] + eye[b]) - f(eye[a] - eye[b]) - f(eye[b] - eye[a])
                                       + f(-eye[a] - eye[b])) / (4 * h[a] * h[b])
        idx = [col.get(j), col.get(j + 1), len(free) + j]
        for a in range(3):
            for b in range(3):
                if idx[a] is not None and idx[b] is not None:
                    hess[idx[a], idx[b]] += hs[a, b]
    return hess, len(free)


def multi_case(case, from_initial=True):
    pts, sigma, clamped, initial = MULTI[case]
    pts = np.array(pts)
    ends = {}
    if clamped:
        d0, d1 = pts[1] - pts[0], pts[-1] - pts[-2]
        ends = dict(start=tuple(d0 / np.linalg.norm(d0)), end=tuple(d1 / np.linalg.norm(d1)))
    pieces = [el.SmoothElastica(x0=p[0], y0=p[1], phi=p[2], mu=p[3], k=p[4], q=p[5], length=p[6]) for p in initial]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sp = el.elastic_spline(pts, tension=sigma, initial=pieces if from_initial else None, **ends)
    return pts, sigma, clamped, sp


@pytest.mark.parametrize("case", sorted(MULTI))
def test_multi_span_past_its_force_free_length_is_unstable(case):
    """4-5 ducks, one span on its long branch: the FD second variation has a negative eigenvalue,
    its free-length part H (the Schur complement on the lengths) none, one negative c_j
    (1 / gamma_j): unstable by #{gamma_j < 0} alone, that span named (read stable before)."""
    pts, sigma, clamped, sp = multi_case(case)
    hess, k = fd_hessian(pts, sigma, sp, not clamped)
    a, b, c = hess[:k, :k], hess[:k, k:], hess[k:, k:]
    negative_c = [j for j in range(len(c)) if c[j, j] < 0]
    assert np.linalg.eigvalsh(hess)[0] < -0.5 and len(negative_c) == 1
    assert np.linalg.eigvalsh(a - b @ np.linalg.solve(c, b.T))[0] > 0.5   # H alone: stable
    assert sp.unstable and sp.unstable_span == negative_c[0]


def test_multi_span_fair_spline_is_stable():
    """The natural case's ducks by the library's own solve (no initial=): every eigenvalue of
    the same FD second variation positive, and the library says stable. (The clamped case's
    fair spline has a span 6e-4 longer than its chord, c_j ~ 1e6: beyond this difference.)"""
    pts, sigma, clamped, sp = multi_case("natural", from_initial=False)
    hess, _ = fd_hessian(pts, sigma, sp, not clamped)
    assert np.linalg.eigvalsh(hess)[0] > 0.5 and not sp.unstable


# revspline's finding 1: six natural ducks whose default solve at tension 0 .. 0.1 landed on a
# batten 7.16 .. 7.18 long with a span past its force-free length (energy 13.54 at 0), refused
# at 0 once TENSION_COUNT counted it ("slides off", false) and returned unstable at 0.03 / 0.1,
# where the family followed from sigma 1e-3 reaches a stable one 5.69 .. 5.70 long (12.07)
DUCKS6 = np.array([(0.0, 0.0), (0.15878318, 0.5261761), (1.17663445, 0.48656332), (3.00721167, 0.16157516),
                   (3.78365615, 0.80591715), (3.88522718, 0.07318801)])


@pytest.mark.parametrize("tension", [0.0, 0.03, 0.1])
def test_unstable_default_batten_gives_way_to_the_stable_family(tension):
    """STABLE_FAMILY: the default solve keeps the stable equilibrium the family from a small
    tension reaches (the same spline as started from tension 1e-3's by initial=), of less
    integral kappa^2 + sigma ds, stable by the FD second variation (every eigenvalue > 0)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sp = el.elastic_spline(DUCKS6, tension=tension)
        ref = el.elastic_spline(DUCKS6, tension=tension,
                                initial=el.elastic_spline(DUCKS6, tension=1e-3).pieces)
    assert not sp.unstable and not ref.unstable
    assert sp.length == pytest.approx(ref.length, rel=1e-8)
    assert sp.energy == pytest.approx(ref.energy, rel=1e-8)
    hess, _ = fd_hessian(DUCKS6, tension, sp, True)
    assert np.linalg.eigvalsh(hess)[0] > 0.0


# a noisy quarter-and-more arc of 5 ducks (radius 10) by length 1.3 x its polygon: every span past
# its force-free length, c_j (FD) -0.025, -0.517, -0.521, -0.019
ARC5 = [(9.910214341197186, 0.040916281076017615), (8.933509151949544, 4.4364191371501525),
        (6.010524610121105, 8.016906931427384), (1.9439945526196745, 9.86560495439407),
        (-2.6518130341928767, 9.666898304952458)]


def test_span_named_is_the_most_negative_c_j():
    """Where only the spans' lengths make the mode, the span named (elastica.h: "moving most
    along that mode") is the one of most negative c_j = d2/dl2 integral kappa^2 at fixed end
    angles (C's least eigenvalue), by a central difference of el.hermite by length; 3f30dda
    named the least gamma_j = 1 / c_j, the least unstable span (3 here, c_j -0.019)."""
    pts = np.array(ARC5)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sp = el.elastic_spline(pts, length=23.64951212082401)
    c = []
    for j, q in enumerate(sp.pieces):
        d = 1e-3 * q.length
        f = [span_energy(pts[j], pts[j + 1], sp.angles[j], sp.angles[j + 1], q.length + e, q) for e in (-d, 0.0, d)]
        c.append((f[0] - 2 * f[1] + f[2]) / d ** 2)
    assert sum(x < 0 for x in c) >= 2 and sp.unstable
    assert sp.unstable_span == int(np.argmin(c)), c


def test_dense_fair_batten_is_not_read_unstable_from_rounding():
    """1000 ducks on a fair curve (bench_spline's sine, unevenly spaced): the free batten and
    the spline at a small tension are stable minima (every span nearly straight, gamma_j
    O(h^3 theta^2) > 0); the spans' rounding gave gamma_j down to -2.1e-8 h^3 and tension 0
    was refused as sliding off, tension 1e-3 called unstable."""
    n = 1000
    t = np.arange(n) / (n - 1)
    x = 12 * (t + 0.35 * t * (1 - t) * np.sin(5 * t))
    pts = np.c_[x, np.sin(x) + 0.3 * np.cos(2.3 * x)]
    for tension in (0.0, 1e-3):
        with warnings.catch_warnings():
            warnings.simplefilter("error")
            sp = el.elastic_spline(pts, tension=tension)
        assert not sp.unstable, tension
