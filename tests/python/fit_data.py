"""Data a designer fits (issue 13), shared by the fit tests and bench/bench_fit.py:
unevenly spaced scans with gaps, a few points sketched along an S, and an
independent point-to-curve distance to check the fit's own numbers against.

The curves are made with libelastica's evaluation (tested on its own against
mpmath and ODE integration); the distances use dense sampling and a bounded
scalar minimisation (scipy), nothing of the fit's projection.

    >>> pts, truth = uneven_scan(seed=0)
    >>> pts.shape
    (175, 2)
"""
from __future__ import annotations

import numpy as np
from scipy.optimize import minimize_scalar

import libelastica as el


def uneven_scan(seed: int = 0, noise: float = 0.15, n: int = 175, k: float = 0.8,
                length: float = 120.0):
    """n points along an S-shaped smooth elastica (one inflection, length
    ``length``), spacing varying smoothly over a ratio of 1:6 along the curve,
    two gaps (10 and 6 mean spacings), isotropic Gaussian noise of sigma
    ``noise`` per coordinate. Returns (points (n, 2), the true SmoothElastica
    over the span of the samples)."""
    rng = np.random.default_rng(seed)
    mu = (1.6 * 2.0 * np.pi / length) ** 2 / 4.0     # ~1.6 quarter periods of cn: one inflection
    truth = el.SmoothElastica(x0=3.0, y0=-2.0, phi=0.4, mu=mu, k=k, q=0.6, length=length)
    # density 1 .. 6 (spacing ratio 1:6) varying along the curve, two gaps
    t = np.linspace(0.0, 1.0, 4000)
    dens = 1.0 + 5.0 * (0.5 + 0.5 * np.sin(2.0 * np.pi * (t + 0.1 * rng.uniform())))
    dens[(t > 0.30) & (t < 0.30 + 10.0 / n)] = 0.0
    dens[(t > 0.70) & (t < 0.70 + 6.0 / n)] = 0.0
    cdf = np.concatenate([[0.0], np.cumsum(0.5 * (dens[1:] + dens[:-1]) * np.diff(t))])
    cdf /= cdf[-1]
    s = np.interp(np.linspace(0.0, 1.0, n), cdf, t) * length
    pts = truth.points(s) + rng.normal(0.0, noise, (n, 2))
    return np.ascontiguousarray(pts), truth


def sketched_s(seed: int = 0, n: int = 15, wobble: float = 0.5):
    """n points placed by hand along an S about 100 mm long: uneven spacing
    (0.5 to 1.5 of the mean), each off the curve by up to ``wobble`` mm.
    Returns (points (n, 2), the SmoothElastica they were placed along)."""
    rng = np.random.default_rng(seed)
    truth = el.SmoothElastica(x0=0.0, y0=0.0, phi=-0.9, mu=(1.0 / 30.0) ** 2, k=0.85, q=0.4,
                              length=100.0)
    gaps = rng.uniform(0.5, 1.5, n - 1)
    s = np.concatenate([[0.0], np.cumsum(gaps)])
    s *= truth.length / s[-1]
    pts = truth.points(s) + rng.uniform(-wobble, wobble, (n, 2))
    return np.ascontiguousarray(pts), truth


def dense_end_scan(curve, p: float, end: str, seed: int, n: int = 200, noise: float = 0.05):
    """A scan dense at one end (QA18's draws): n points along ``curve`` at s = L u^p (end
    "start"; "end": mirrored, dense at s = L), noise per coordinate."""
    rng = np.random.default_rng(seed)
    u = np.linspace(0, 1, n) ** p
    s = curve.length * (u if end == "start" else 1 - u[::-1])
    return curve.points(s) + noise * rng.standard_normal((n, 2))


def sheer_scan(n: int = 1500, seed: int = 1):
    """A scanned sheer line (QA15's sheer1500.csv for n = 1500): a smooth elastica 30 m
    long in mm, points denser at the bow, none between 40 and 50 % of the length, 2 mm
    noise along the normal and 5 outliers of 50-200 mm (n = 1500: 1365 points).
    Returns (points (m, 2), the SmoothElastica)."""
    rng = np.random.default_rng(seed)
    c = el.SmoothElastica(x0=0, y0=0, phi=0.12, mu=1 / 9000.0 ** 2, k=0.35, q=-1.2, length=30000.0)
    s = np.sort(rng.uniform(0, 1, n) ** 1.3) * c.length
    s[0], s[-1] = 0.0, c.length
    s = s[~((s > 0.4 * c.length) & (s < 0.5 * c.length))]
    th = c.angle(s)
    nrm = np.c_[-np.sin(th), np.cos(th)]
    xy = c.points(s) + nrm * rng.normal(0, 2.0, len(s))[:, None]
    idx = rng.choice(np.arange(10, len(s) - 10), 5, replace=False)
    xy[idx] += nrm[idx] * rng.uniform(50, 200, 5)[:, None] * rng.choice([-1, 1], 5)[:, None]
    return np.ascontiguousarray(xy), c


def swinging_sketch():
    """18 points sketched along 100 mm (bench_fit_sparse.py seed 5 case 670 in mm: uneven,
    noise 1 mm) whose smooth (status 0) and discrete fits hook away between the last two
    points, 43 mm apart: the smooth curve 12 mm off their chord, every point within 1.6 mm
    of it. Returns the points (18, 2)."""
    return 100.0 * np.array([
        [0.0006418172386133665, -0.009172698423006604], [-0.0393050280158322, 0.0888978269240638],
        [-0.04410652357552151, 0.07781816337897415], [-0.06945529273743643, 0.13534246980265838],
        [-0.0681711519605496, 0.18711934872776317], [-0.08534547502582791, 0.17483787973439557],
        [-0.07971644440404725, 0.19351333159523354], [-0.08292744962692104, 0.22925476870406705],
        [-0.11768717301276027, 0.26796689603919843], [-0.13233479065612236, 0.33431893963611714],
        [-0.13570815118322452, 0.3441094674465781], [-0.11974186746684463, 0.3577549927298168],
        [-0.14291521256031886, 0.39371468126658143], [-0.14679271320366788, 0.3947725451877166],
        [-0.15124322533443688, 0.42582445746101916], [-0.17995681897253346, 0.500828792412778],
        [-0.1867935999826268, 0.5313171576065319], [-0.11944538649982038, 0.960615311034519]])


def polygon_distances(q, pts):
    """Distance of every point q (m, 2) to the polygon of the points pts (n, 2)."""
    A, AB = pts[:-1], np.diff(pts, axis=0)
    t = np.clip(np.einsum("mij,ij->mi", q[:, None, :] - A[None], AB) / np.sum(AB * AB, 1), 0.0, 1.0)
    return np.linalg.norm(q[:, None, :] - A[None] - t[..., None] * AB[None], axis=2).min(axis=1)


def curve_distances(curve, pts, samples: int = 20000):
    """Distance of every point to the curve (a SmoothElastica over [0, length]
    or the polygon of a DiscreteElastica), measured independently of the fit:
    nearest of ``samples`` dense samples, then a bounded scalar minimisation
    between its neighbours. Returns (distances (n,), arc length of the nearest
    point (n,))."""
    pts = np.asarray(pts, dtype=float)
    if isinstance(curve, el.DiscreteElastica):
        V = curve.points()
        A, B = V[:-1], V[1:]
        AB = B - A
        t = np.clip(np.einsum("pij,ij->pi", pts[:, None, :] - A[None], AB) / np.sum(AB * AB, 1),
                    0.0, 1.0)
        C = A[None] + t[..., None] * AB[None]
        d = np.linalg.norm(pts[:, None, :] - C, axis=2)
        j = np.argmin(d, axis=1)
        return d[np.arange(len(pts)), j], (j + t[np.arange(len(pts)), j]) * curve.h
    s = np.linspace(0.0, curve.length, samples)
    xy = curve.points(s)
    ds = s[1] - s[0]
    dist, foot = np.empty(len(pts)), np.empty(len(pts))
    # each point's nearest sample, the first of least (x - px)^2 + (y - py)^2: the sums of
    # np.sum((xy - p) ** 2, axis=1), found 64 points at once (bit for bit the same
    # indices; 3000 points, one 20000-sample pass each, 10 of ell3000's 30 s)
    near = np.empty(len(pts), dtype=np.intp)
    for a in range(0, len(pts), 64):
        ex = xy[:, 0] - pts[a:a + 64, :1]
        ey = xy[:, 1] - pts[a:a + 64, 1:]
        ex *= ex
        ey *= ey
        ex += ey
        near[a:a + 64] = np.argmin(ex, axis=1)
    for i, p in enumerate(pts):
        j = int(near[i])
        lo, hi = max(s[j] - ds, 0.0), min(s[j] + ds, curve.length)
        r = minimize_scalar(lambda v: float(np.sum((curve.points(np.array([v]))[0] - p) ** 2)),
                            bounds=(lo, hi), method="bounded", options={"xatol": 1e-12 * curve.length})
        cand = [(r.fun, r.x), (float(np.sum((xy[j] - p) ** 2)), s[j])]
        f, x = min(cand)
        dist[i], foot[i] = np.sqrt(f), x
    return dist, foot
