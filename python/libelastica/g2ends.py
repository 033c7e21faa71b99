"""The ends of g2_quadratic's pieces (seed 002 §2.5 splines, g2quad.py): the end vertices of
an affine arc-length polyline moved so that its G2 quadratic B-spline (:func:`g2_bspline`)
starts with the source's curvature (_match_start: x_1 on the line keeping A_2 = A) and its
tangent too (_hold_start: x_1, x_2 slid, _slid), every joint staying G2; _matched_ends does
both ends of a piece.
"""
from __future__ import annotations

import math
from typing import Optional, Tuple

import numpy as np

from ._ffi import DomainError
from .affine import g2_bspline


def _start_curvature(bs) -> float:
    """Curvature at the start of a clamped quadratic B-spline: det(b1-b0, b2-b1) / (2|b1-b0|^3)
    of its first Bezier segment (b2 the joint of poles 1, 2)."""
    P, K = bs.poles, bs.knots
    j = ((K[2] - K[1]) * P[1] + (K[1] - K[0]) * P[2]) / (K[2] - K[0])
    d0, d1 = P[1] - P[0], j - P[1]
    return float((d0[0] * d1[1] - d0[1] * d1[0]) / (2.0 * np.linalg.norm(d0) ** 3))


def _match_start(x: np.ndarray, start, end, kappa: float) -> Optional[np.ndarray]:
    """The polyline x (>= 6 vertices) with x_1 moved so that g2_bspline(x, start, end) starts
    with curvature kappa, or None (no such place within 0.5..1.5 x its edge).
    Why: the vertices lie on the source, so the uniform spline runs inside it by ~kappa h^2/8
    and the end parabola (start, c, m_2) bridging to it over ~1.5 h ends with ~0.71 kappa on
    a circle (legs 0.793 h and h/sqrt 2: (0.707/0.793)^3). x_1 slides on the line
    det(x_2 - x_1, v_2) = A (v_1 = t u + (A/|v_2|) w, u = v_2/|v_2|, det(w, u) = 1), which keeps
    A_2 = A and so every joint G2; t moves m_2, v_1 and the end parabola's legs, and the root
    of its start curvature - kappa is taken nearest the polyline's own t (bisection)."""
    v2 = x[3] - x[2]
    A = float(v2[1] * (x[2] - x[1])[0] - v2[0] * (x[2] - x[1])[1])
    n2 = float(np.hypot(*v2))
    u = v2 / n2
    w = np.array([u[1], -u[0]])
    t0 = float((x[2] - x[1]) @ u)

    def f(t):
        y = x.copy()
        y[1] = x[2] - (t * u + (A / n2) * w)
        try:
            return _start_curvature(g2_bspline(y, start, end)) - kappa, y
        except DomainError:
            return math.nan, y
    ts = t0 * np.linspace(0.5, 1.5, 41)
    fs = np.array([f(t)[0] for t in ts])
    ok = np.isfinite(fs[:-1]) & np.isfinite(fs[1:]) & (np.sign(fs[:-1]) != np.sign(fs[1:]))
    if not ok.any():
        return None
    i = int(np.nonzero(ok)[0][np.argmin(np.abs(np.nonzero(ok)[0] - 20))])
    lo, hi, flo = ts[i], ts[i + 1], fs[i]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        fm = f(mid)[0]
        if not math.isfinite(fm):
            return None
        if np.sign(fm) == np.sign(flo):
            lo, flo = mid, fm
        else:
            hi = mid
    return f(lo if abs(flo) <= abs(f(hi)[0]) else hi)[1]


def _slid(x: np.ndarray, s: float, t: float) -> np.ndarray:
    """x with x_2 slid by s v_3 (v_i = x_{i+1} - x_i: keeps A_3 = det(v_2, v_3)) and x_1 at
    t on the line that keeps A_2 = A_3 (as _match_start's): still an affine arc-length
    polyline, every joint G2."""
    y = x.copy()
    v3 = x[4] - x[3]
    A = float(v3[1] * (x[3] - x[2])[0] - v3[0] * (x[3] - x[2])[1])
    y[2] = x[2] + s * v3
    v2 = y[3] - y[2]
    n2 = float(np.hypot(*v2))
    u = v2 / n2
    y[1] = y[2] - (t * u + (A / n2) * np.array([u[1], -u[0]]))
    return y


# _hold_start's Newton box (|s| <= 0.5: x_2 slid by at most half of v_3; t, x_1's step along
# v_2, within 0.5 .. 1.5 x its own), and the wider one tried from a grid's best HOLD_SEEDS
# points where that finds no root (x_2 still short of x_3, t within 0.25 .. 2 x its own)
HOLD_BOX = (0.5, 0.5, 1.5)
HOLD_WIDE = (0.9, 0.25, 2.0)
HOLD_SEEDS = 3


def _hold_start(x: np.ndarray, start, end, kappa: float, tangent) -> Optional[np.ndarray]:
    """The polyline x (>= 8 vertices) with x_1, x_2 slid (_slid) so that g2_bspline(x, start,
    end) starts with curvature kappa AND along the unit ``tangent``, or None (Newton on
    (s, t) from the polyline's own, finite-difference Jacobian, backtracking, in HOLD_BOX;
    where that finds none, from the best points of a grid over HOLD_WIDE, in it). Two end vertices give the two freedoms one
    (_match_start) lacks: the end parabola keeps the source's tangent too (QA17 P4: 0.68
    deg off at 24 edges, a kink where the source joined a line G1). Worked relative to
    x_0 (QA18 W3: at a GIS offset (5e5, 5e6) the poles' differences carried ~ulp(5e6)/edge
    ~2e-9 rad, above the 1e-9 accepted, and the end fell back: 0.9 deg off)."""
    origin = x[0].copy()
    x, start, end = x - origin, np.asarray(start) - origin, np.asarray(end) - origin
    u = (x[3] - x[2]) / np.hypot(*(x[3] - x[2]))
    t0 = float((x[2] - x[1]) @ u)
    scale = np.array([1.0, abs(t0)])

    def f(z, box=HOLD_BOX):
        smax, tlo, thi = box
        if not (abs(z[0]) <= smax and tlo * abs(t0) <= abs(z[1]) <= thi * abs(t0)):
            return None, None
        y = _slid(x, *z)
        try:
            bs = g2_bspline(y, start, end)
        except DomainError:
            return None, None
        d = bs.poles[1] - bs.poles[0]
        angle = math.atan2(d[0] * tangent[1] - d[1] * tangent[0], d @ tangent)
        return np.array([(_start_curvature(bs) - kappa) / abs(kappa), angle]), y

    def newton(z, box):
        r, y = f(z, box)
        for _ in range(60):
            if r is None:
                return None
            if np.max(np.abs(r)) < 1e-12:
                return y + origin
            J = np.empty((2, 2))
            for j in range(2):
                dz = np.zeros(2)
                dz[j] = 1e-7 * scale[j]
                rj = f(z + dz, box)[0]
                if rj is None:
                    return None
                J[:, j] = (rj - r) / dz[j]
            try:
                step = np.linalg.solve(J, -r)
            except np.linalg.LinAlgError:
                return None
            lam = 1.0
            while lam > 1e-4:
                r2, y2 = f(z + lam * step, box)
                if r2 is not None and np.linalg.norm(r2) < np.linalg.norm(r):
                    break
                lam /= 2.0
            else:
                break                       # no step improves: rounding's floor, or none
            z, r, y = z + lam * step, r2, y2
        return y + origin if np.max(np.abs(r)) < 1e-9 else None   # rounding: ~1e-10 at 1000 edges

    held = newton(np.array([0.0, t0]), HOLD_BOX)
    if held is not None:
        return held
    # none from the polyline's own place: the root may lie farther (a spiral turning 5.9
    # times at 26 edges, 83 deg an edge: x_2 slid 0.665 v_3; the ends were left 30.7 deg
    # off): Newton in HOLD_WIDE from the nearest points of a 13 x 13 grid over it
    smax, tlo, thi = HOLD_WIDE
    seeds = []
    for sv in np.linspace(-smax, smax, 13):
        for tf in np.linspace(tlo, thi, 13):
            r = f(np.array([sv, tf * t0]), HOLD_WIDE)[0]
            if r is not None:
                seeds.append((float(np.linalg.norm(r)), sv, tf * t0))
    for _, sv, tv in sorted(seeds)[:HOLD_SEEDS]:
        held = newton(np.array([sv, tv]), HOLD_WIDE)
        if held is not None:
            return held
    return None


def _matched_ends(x: np.ndarray, start, end, k_start: Optional[float],
                  k_end: Optional[float], t_start=None,
                  t_end=None) -> Tuple[np.ndarray, np.ndarray, list]:
    """The piece's polyline with x_1 / x_{m-1} moved so its G2 spline's ends have the
    curvatures k_start / k_end (None, 0 or no such place: that end as it was); and that
    polyline with, where the unit tangents t_start / t_end are given and m >= 7, x_1, x_2 /
    x_{m-1}, x_{m-2} moved instead so they have those tangents too (_hold_start; no such
    place: the curvature alone), each end's moves found once for both. The two ends' moves
    are independent for m >= 5 (x_1 depends on x_2, x_3 only; x_{m-1} on x_{m-2}, x_{m-3}),
    for m >= 7 with x_2, x_{m-2} moved (on x_3, x_4 / x_{m-3}, x_{m-4}); fewer vertices are
    left as they are. Third: whether each end's tangent was held, [start, end] (None: not
    tried)."""
    holds = [None, None]
    if len(x) < 6:
        return x, x, holds
    y, held = x.copy(), x.copy()
    if k_start:
        z = _match_start(x, start, end, k_start)
        if z is not None:
            y[1] = held[1] = z[1]
        if t_start is not None and len(x) >= 8:
            z = _hold_start(x, start, end, k_start, t_start)
            if z is not None:
                held[1:3] = z[1:3]
            holds[0] = z is not None
    if k_end:     # the same at the end, travelled backwards (its curvature changes sign)
        r = x[::-1].copy()
        z = _match_start(r, end, start, -k_end)
        if z is not None:
            y[-2] = held[-2] = z[1]
        if t_end is not None and len(x) >= 8:
            z = _hold_start(r, end, start, -k_end, -np.asarray(t_end))
            if z is not None:
                held[-3:-1] = z[2:0:-1]
            holds[1] = z is not None
    return y, held, holds
