"""The ends of g2_quadratic's pieces (seed 002 §2.5 splines, g2quad.py): the end vertices of
an affine arc-length polyline moved so that its G2 quadratic B-spline (:func:`g2_bspline`)
starts with the source's curvature (_match_start: x_1 on the line keeping A_2 = A) and its
tangent too (_hold_start: x_1, x_2 slid, _slid), every joint staying G2; _matched_ends does
both ends of a piece; the ends where two pieces meet (an inflection) held to the source's
tangent there, both or neither, so the pieces meet G1 (_joint_end, _held_joints,
_hold_joints; those that do not, _unheld_joints); the source's end curvature and a closed
source's seam estimated from samples (_end_curvature, _seam_estimate) and the ends' errors (_rel_err, _menger_max).
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


def _start_parabola(P, x1, x2, x3):
    """The start of g2_bspline(x, P, ...) from the four points it depends on (P = start,
    x_1, x_2, x_3: floats (x, y)), without building the spline: (curvature, c - P) of its
    first Bezier segment (P, c, m_2) as _start_curvature and poles[1] - poles[0] read them;
    NaN where el_affine_g2_bspline refuses the start (EL_EDOM: P not ahead of the joint's
    tangent); None where the C function must decide (non-finite input, A_2 = 0, knots or
    poles near overflow). The C code's operations in its order (affine.c g2_end; the joint
    m_2 = (c + lambda x_2)/(1 + lambda) as _start_curvature takes it from the knots): the
    same bits. Its defining identity: the end parabola (P, c, m_2), c = m_2 - (lambda/2) v_1,
    lambda^2 = 2 det(m_2 - P, v_1) / A_2, starts with curvature det(c - P, m_2 - c) /
    (2 |c - P|^3) (affine.c's derivation; tests/python/test_g2ends_closed_form.py)."""
    v1x, v1y = x2[0] - x1[0], x2[1] - x1[1]
    A = v1x * (x3[1] - x2[1]) - v1y * (x3[0] - x2[0])
    if not (A != 0.0 and math.isfinite(A + x1[0] + x1[1] + x2[0] + x2[1])):
        return None
    m2x, m2y = 0.5 * (x1[0] + x2[0]), 0.5 * (x1[1] + x2[1])
    l2 = 2.0 * ((m2x - P[0]) * v1y - (m2y - P[1]) * v1x) / A
    if not (l2 > 0.0) or not math.isfinite(l2):
        return math.nan
    lam = math.sqrt(l2)
    if not lam < 1e15:          # knots lam + j no longer increasing: C's check decides
        return None
    h = 0.5 * lam
    cx, cy = m2x - h * v1x, m2y - h * v1y
    k2 = lam + 1.0
    a = k2 - lam
    jx, jy = (a * cx + lam * x2[0]) / k2, (a * cy + lam * x2[1]) / k2
    d0x, d0y = cx - P[0], cy - P[1]
    if d0x == 0.0 and d0y == 0.0:  # (rounding: c on P; the built spline says)
        return None
    d1x, d1y = jx - cx, jy - cy
    kappa = (d0x * d1y - d0y * d1x) / (2.0 * math.sqrt(d0x * d0x + d0y * d0y) ** 3)
    return (kappa, d0x, d0y) if math.isfinite(cx + cy) else None


def _end_refused(x: np.ndarray, start, end) -> Optional[bool]:
    """Whether g2_bspline(x, start, end) is refused (DomainError) for a reason that no move
    of x_1, x_2 changes: its end parabola's (x_{m-3}.. x_{m-1} and ``end``; m >= 7, or m >= 5
    with x_1 alone moved); None where the C function must decide (A_{m-2} = 0: a
    SingularError; near overflow; mu <= 0.1, its knots possibly tied by rounding)."""
    m = len(x) - 1
    P = (float(end[0]), float(end[1]))
    e1, e2, e3 = (tuple(map(float, x[i])) for i in (m - 1, m - 2, m - 3))
    # affine.c g2_end(end, m_{m-1}, v_{m-2}, A_{m-2}, -1): mu^2 = 2 det(m - P, v) / A
    mx, my = 0.5 * (e1[0] + e2[0]), 0.5 * (e1[1] + e2[1])
    vx, vy = e1[0] - e2[0], e1[1] - e2[1]     # v_{m-2}, as the C code takes it
    wx, wy = e2[0] - e3[0], e2[1] - e3[1]     # v_{m-3}
    A = wx * vy - wy * vx
    if A == 0.0 or not math.isfinite(A):
        return None             # (SingularError, not a DomainError: the C call says)
    l2 = 2.0 * ((mx - P[0]) * vy - (my - P[1]) * vx) / A
    if not (l2 > 0.0) or not math.isfinite(l2):
        return True
    # the C call decides near overflow, and where mu = sqrt(l2) <= 0.1: its last knot
    # lam + (m - 3) + mu may round onto lam + (m - 3) (ulp 1/8 at _start_parabola's
    # lam < 1e15), which el_bspline_check refuses (EL_EDOM) though l2 > 0
    return None if not 0.01 < l2 < 1e30 else False


def _start_of(bs):
    """(curvature, c - P) of a built spline's start as _start_parabola gives them: the
    path where the C function decides."""
    d = bs.poles[1] - bs.poles[0]
    return _start_curvature(bs), float(d[0]), float(d[1])


def _angle(dx: float, dy: float, T) -> float:
    """Signed angle from the unit tangent T (floats) to the start leg (dx, dy) = c - P."""
    return math.atan2(dx * T[1] - dy * T[0], dx * T[0] + dy * T[1])


def _match_start(x: np.ndarray, start, end, kappa: float) -> Optional[np.ndarray]:
    """The polyline x (>= 6 vertices) with x_1 moved so that g2_bspline(x, start, end) starts
    with curvature kappa, or None (no such place within 0.5..1.5 x its edge).
    Why: the vertices lie on the source, so the uniform spline runs inside it by ~kappa h^2/8
    and the end parabola (start, c, m_2) bridging to it over ~1.5 h ends with ~0.71 kappa on
    a circle (legs 0.793 h and h/sqrt 2: (0.707/0.793)^3). x_1 slides on the line
    det(x_2 - x_1, v_2) = A (_slide_x1), which keeps A_2 = A and so every joint G2."""
    return _slide_x1(x, start, end, lambda k, dx, dy: k - kappa)


def _match_tangent(x: np.ndarray, start, end, tangent) -> Optional[np.ndarray]:
    """The polyline x (>= 6 vertices) with x_1 moved on _match_start's line (_slide_x1) so
    that g2_bspline(x, start, end) starts along the unit ``tangent``, or None. For an end of
    zero curvature (a free batten's natural end): no G2 quadratic ends with curvature 0 (its
    end parabola would be straight, and so, joint by joint, every one), so _hold_start's
    curvature target cannot be met and the tangent is held alone (QA25 F4: a free spline's
    ends 0.147 deg off at 24 edges, warned at every count)."""
    T = (float(tangent[0]), float(tangent[1]))
    return _slide_x1(x, start, end, lambda k, dx, dy: _angle(dx, dy, T))


def _slide_x1(x: np.ndarray, start, end, residual) -> Optional[np.ndarray]:
    """The polyline x (>= 4 vertices) with x_1 slid on the line det(x_2 - x_1, v_2) = A
    (v_1 = t u + (A/|v_2|) w, u = v_2/|v_2|, det(w, u) = 1), which keeps A_2 = A and so every
    joint G2, to the root of ``residual(kappa, dx, dy)`` of g2_bspline(x, start, end)'s start
    (its curvature and first leg c - P) nearest the polyline's own t (a sign change on 41
    points over 0.5..1.5 x it, then bisection; a sign change that is no root, atan2's wrap
    at pi or a pole, passed over: ROOT_SHRINK); None if none. Each trial's start is
    _start_parabola's closed form, the same bits as the spline's (QA25 F6: ~100 splines
    built a call for it before); the spline is built only where the C function decides."""
    v2 = x[3] - x[2]
    A = float(v2[1] * (x[2] - x[1])[0] - v2[0] * (x[2] - x[1])[1])
    n2 = float(np.hypot(*v2))
    u = v2 / n2
    w = np.array([u[1], -u[0]])
    t0 = float((x[2] - x[1]) @ u)
    # (x_1 is x_{m-3} at m = 4, x_{m-2} at 3: the far end's parabola then built each trial)
    refused = _end_refused(x, start, end) if len(x) >= 6 else None
    P = (float(start[0]), float(start[1]))
    ux, uy, aw0, aw1 = float(u[0]), float(u[1]), float((A / n2) * w[0]), float((A / n2) * w[1])
    x2, x3 = (float(x[2][0]), float(x[2][1])), (float(x[3][0]), float(x[3][1]))

    def vertex(t):
        return x2[0] - (t * ux + aw0), x2[1] - (t * uy + aw1)

    def f(t):
        k = _start_parabola(P, vertex(t), x2, x3)
        if k is None or refused is None:    # (the C function decides: the spline built)
            y = x.copy()
            y[1] = vertex(t)
            try:
                return residual(*_start_of(g2_bspline(y, start, end)))
            except DomainError:
                return math.nan
        return math.nan if refused or not isinstance(k, tuple) else residual(*k)
    ts = t0 * np.linspace(0.5, 1.5, 41)
    fs = np.array([f(float(t)) for t in ts])
    ok = np.isfinite(fs[:-1]) & np.isfinite(fs[1:]) & (np.sign(fs[:-1]) != np.sign(fs[1:]))
    for i in sorted(np.nonzero(ok)[0], key=lambda i: abs(i - 20)):
        lo, hi, flo = float(ts[i]), float(ts[i + 1]), float(fs[i])
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            fm = f(mid)
            if not math.isfinite(fm):
                return None
            if np.sign(fm) == np.sign(flo):
                lo, flo = mid, fm
            else:
                hi = mid
        fhi = f(hi)
        t, fr = (lo, flo) if abs(flo) <= abs(fhi) else (hi, fhi)
        # a root, not a jump across zero: atan2's wrap (the leg at pi from the tangent, the
        # piece leaving backwards) or a pole changes sign where |residual| stays large
        if abs(fr) <= ROOT_SHRINK * max(abs(fs[i]), abs(fs[i + 1])):
            y = x.copy()
            y[1] = vertex(t)
            return y
    return None


# _slide_x1's bisection ends at a root only where its residual fell below ROOT_SHRINK x the
# bracket's (at a root ~1e-13 of it; at atan2's wrap ~1: the angle pi, the piece backwards)
ROOT_SHRINK = 1e-6


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

    v3 = x[4] - x[3]
    A3 = float(v3[1] * (x[3] - x[2])[0] - v3[0] * (x[3] - x[2])[1])
    v3x, v3y = float(v3[0]), float(v3[1])
    x2, x3 = (float(x[2][0]), float(x[2][1])), (float(x[3][0]), float(x[3][1]))
    P, T = (float(start[0]), float(start[1])), (float(tangent[0]), float(tangent[1]))
    refused = _end_refused(x, start, end)

    def f(z, box=HOLD_BOX):
        """The residuals at z = (s, t), or None (outside the box, or no spline); the
        spline's start by _start_parabola (_slid's operations on floats: the same bits)."""
        smax, tlo, thi = box
        if not (abs(z[0]) <= smax and tlo * abs(t0) <= abs(z[1]) <= thi * abs(t0)):
            return None
        sv, tv = float(z[0]), float(z[1])
        y2 = (x2[0] + sv * v3x, x2[1] + sv * v3y)
        v2x, v2y = x3[0] - y2[0], x3[1] - y2[1]
        n2 = float(np.hypot(v2x, v2y))
        ux, uy = v2x / n2, v2y / n2
        an = A3 / n2
        y1 = (y2[0] - (tv * ux + an * uy), y2[1] - (tv * uy + an * -ux))
        k = _start_parabola(P, y1, y2, x3)
        if k is None or refused is None:     # (the C function decides: the spline built)
            try:
                bs = g2_bspline(_slid(x, *z), start, end)
            except DomainError:
                return None
            k = _start_of(bs)
        elif refused or not isinstance(k, tuple):
            return None
        return np.array([(k[0] - kappa) / abs(kappa), _angle(k[1], k[2], T)])

    def newton(z, box):
        r = f(z, box)
        for _ in range(60):
            if r is None:
                return None
            if np.max(np.abs(r)) < 1e-12:
                return _slid(x, *z) + origin
            J = np.empty((2, 2))
            for j in range(2):
                dz = np.zeros(2)
                dz[j] = 1e-7 * scale[j]
                rj = f(z + dz, box)
                if rj is None:
                    return None
                J[:, j] = (rj - r) / dz[j]
            try:
                step = np.linalg.solve(J, -r)
            except np.linalg.LinAlgError:
                return None
            lam = 1.0
            while lam > 1e-4:
                r2 = f(z + lam * step, box)
                if r2 is not None and np.linalg.norm(r2) < np.linalg.norm(r):
                    break
                lam /= 2.0
            else:
                break                       # no step improves: rounding's floor, or none
            z, r = z + lam * step, r2
        return _slid(x, *z) + origin if np.max(np.abs(r)) < 1e-9 else None   # rounding: ~1e-10 at 1000 edges

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
            r = f(np.array([sv, tf * t0]), HOLD_WIDE)
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
    if k_start == 0.0 and t_start is not None:     # a zero-curvature end: the tangent alone
        z = _match_tangent(x, start, end, t_start)
        if z is not None:
            held[1] = z[1]
        holds[0] = z is not None
    if k_start:
        z = _match_start(x, start, end, k_start)
        if z is not None:
            y[1] = held[1] = z[1]
        if t_start is not None and len(x) >= 8:
            z = _hold_start(x, start, end, k_start, t_start)
            if z is not None:
                held[1:3] = z[1:3]
            holds[0] = z is not None
    if k_end == 0.0 and t_end is not None:
        z = _match_tangent(x[::-1].copy(), end, start, -np.asarray(t_end))
        if z is not None:
            held[-2] = z[1]
        holds[1] = z is not None
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


def _end_curvature(samples: np.ndarray, reverse: bool, tangents=None) -> Optional[float]:
    """Signed curvature at the first (reverse: the last) of dense samples of a curve, in
    the direction of travel, from the 8 samples at that end (chord length s): with their
    tangents, theta'(0) of a cubic theta(s) by least squares (first differences: the
    samples' rounding counts ~1/s less); without, det(x', x'') / |x'|^3 of x(s), y(s)
    cubics. None for fewer than 5 samples."""
    q = samples[::-1] if reverse else samples
    q = q[:8] - q[0]
    if len(q) < 5:
        return None
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))])
    if not s[-1] > 0:
        return None
    V = np.vander(s / s[-1], 4, increasing=True)
    if tangents is not None:
        t = (tangents[::-1] if reverse else tangents)[:8]
        theta = np.unwrap(np.arctan2(t[:, 1], t[:, 0]))
        k = np.linalg.lstsq(V, theta - theta[0], rcond=None)[0][1] / s[-1]
    else:
        c = np.linalg.lstsq(V, q, rcond=None)[0]
        d1, d2 = c[1] / s[-1], 2.0 * c[2] / s[-1] ** 2
        k = (d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(*d1) ** 3
    return float(-k if reverse else k)      # (backwards from the end: the sign turns)


def _seam_estimate(samples: np.ndarray) -> Tuple[np.ndarray, float]:
    """The unit tangent and signed curvature at the first (= last) of dense samples of a
    closed curve, from the 8 samples either side of it (the curve continued across its
    seam): x(s), y(s) cubics by least squares in chord length s, as _end_curvature's at
    an end, here centred (QA25 F3: each end's own one-sided tangents closed 4.8 deg apart at
    24 edges)."""
    q = np.vstack([samples[-9:-1], samples[:9]]) - samples[0]
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(q, axis=0), axis=1))])
    s = (s - s[8]) / (s[-1] - s[0])
    c = np.linalg.lstsq(np.vander(s, 4, increasing=True), q, rcond=None)[0]
    d1, d2 = c[1], 2.0 * c[2]
    return d1 / np.hypot(*d1), float((d1[0] * d2[1] - d1[1] * d2[0]) / np.hypot(*d1) ** 3)


def _rel_err(a: float, b: float, scale: float = 0.0) -> float:
    """|a - b| / max(|a|, |b|) (scale 0), or |a - b| / max(|b|, scale): relative to the
    source's curvature scale (end_curvature_error; QA13: near an end of zero curvature the
    first read ~1 whatever the size of the error)."""
    m = max(abs(a), abs(b)) if scale <= 0.0 else max(abs(b), scale)
    return abs(a - b) / m if m > 0 else 0.0


def _menger_max(x: np.ndarray) -> float:
    """Largest discrete (three-point) curvature of sampled points, 0 for fewer than 3."""
    if len(x) < 3:
        return 0.0
    a, b = x[1:-1] - x[:-2], x[2:] - x[1:-1]
    cross = np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0])
    den = np.linalg.norm(a, axis=1) * np.linalg.norm(b, axis=1) * np.linalg.norm(x[2:] - x[:-2], axis=1)
    ok = den > 0
    return float(np.max(2.0 * cross[ok] / den[ok])) if ok.any() else 0.0


def _tangent_alone(x: np.ndarray, held: np.ndarray, start, end, t_start, t_end,
                   which) -> Optional[np.ndarray]:
    """``held`` with each end in ``which`` (0: start, 1: end) holding its unit tangent alone
    (_match_tangent: x_1 / x_{m-1} slid on the uniform polyline x, x_2 / x_{m-2} as in x),
    or None where one has no such place. Where both were to be held and that fails, or
    holding both takes the spline farther from the source, the tangent alone: a near-free
    end (curvature 6e-5 .. 6e-8 of the largest: its G2 hold strays, its tangent does not)
    and a closed outline's seam (the same tangent at both ends: G1 at least)."""
    y = held.copy()
    for e in which:
        if e == 0:
            z = _match_tangent(x, start, end, t_start)
            if z is None:
                return None
            y[1], y[2] = z[1], x[2]
        else:
            z = _match_tangent(x[::-1].copy(), end, start, -np.asarray(t_end))
            if z is None:
                return None
            y[-2], y[-3] = z[1], x[-3]
    return y


def _seam_rounding(first, last, kscale: float) -> Tuple[float, float]:
    """What the poles' coordinates resolve at a closed outline's seam (the first spline's
    start, the last's end): (angle in radians, curvature jump relative to kscale). A pole
    at |P| carries eps |P| of rounding; the end tangent, a leg d = P_1 - P_0 of length h,
    turns by ~eps |P| / h, and the end curvature det(d_0, d_1) / (2 h^3) moves by
    ~eps |P| h / h^3, i.e. eps |P| / (h^2 kscale) relative; x 16 for the few operations on
    each (an 8-duck oval at (512345.678, 5012345.432), 64 edges: 1.2e-10 rad and 1.5e-9
    apart, bounds 1.7e-8 and 1.3e-7; at the origin 1e-14, bounds 1e-15: SEAM_G2 governs)."""
    P = max(float(np.max(np.abs(first.poles))), float(np.max(np.abs(last.poles))))
    h = min(float(np.hypot(*(first.poles[1] - first.poles[0]))),
            float(np.hypot(*(last.poles[-1] - last.poles[-2]))))
    if not h > 0.0:
        return 0.0, 0.0
    res = float(16.0 * np.finfo(float).eps * P / h)
    return res, res / (h * kscale) if kscale > 0.0 else res


def _joins(splines) -> Tuple[float, float]:
    """Largest tangent angle (radians) and signed-curvature jump where consecutive
    pieces meet."""
    angle = jump = 0.0
    for a, b in zip(splines, splines[1:]):
        ta, tb = a.derivative(a.knots[-1:])[0], b.derivative(b.knots[:1])[0]
        angle = max(angle, abs(math.atan2(ta[0] * tb[1] - ta[1] * tb[0], ta @ tb)))
        jump = max(jump, abs(float(a.curvature(a.knots[-1:])[0] - b.curvature(b.knots[:1])[0])))
    return angle, jump


# a piece's end at an inflection (where two pieces meet) holds the source's tangent there
# when both pieces have this many edges or more (x_1 alone, _match_tangent; from 7 on x_1,
# x_2, _hold_start, as at the source's own ends): a piece's two ends then move vertices
# that neither end's parabola reads for the other (as _matched_ends'), at 4 too: x_1 slid
# keeping A_2 leaves the far end's parabola (m_3, v_2, A_2) as it was; at 3 edges x_1 is in
# both end parabolas (A_1, A_2): slid, the piece is no longer G2 inside (a k 0.9 S at 12
# edges: relative jump 0.105 at m_2) and the far end turns
JOINT_HOLD_EDGES = 4


def _joint_end(x: np.ndarray, start, end, tangent, which: int) -> Optional[np.ndarray]:
    """The piece's polyline x with its end ``which`` (0: start, 1: end), an inflection of the
    source, holding the source's unit ``tangent`` there, or None where it has no such place.
    x_1, x_2 (x_{m-1}, x_{m-2}) slid (_hold_start) so that the end parabola takes the tangent
    and keeps the curvature the uniform end has (g2_bspline(x)'s there); where that finds
    none, x_1 (x_{m-1}) alone (_match_tangent: the end curvature then ~6 % larger, 0.00066
    against 0.00062 /mm on the QA S at 24 edges). Why the uniform end's curvature: no G2
    quadratic ends with curvature 0, the inflection's (_match_tangent); a smaller one is
    reached only through a bump in the curvature just inside (the QA S at 24 edges: 0.5 x
    it halves the joint's jump but leaves |kappa| no longer rising from the joint, 0.29 of
    the source's largest curvature off it against 0.063)."""
    r = x if which == 0 else x[::-1].copy()
    P, Q = (start, end) if which == 0 else (end, start)
    T = np.asarray(tangent, dtype=float) * (1.0 if which == 0 else -1.0)
    try:
        kappa = _start_curvature(g2_bspline(r, P, Q))
    except DomainError:
        return None
    z = _hold_start(r, P, Q, kappa, T) if kappa != 0.0 and len(x) >= 8 else None
    if z is None:
        z = _match_tangent(r, P, Q, T)
        if z is None:
            return None
        z[2] = r[2]
    return z if which == 0 else z[::-1].copy()


def _held_joints(points: np.ndarray, piece_start, ends: np.ndarray, ends_dir) -> dict:
    """Where two pieces of a G2 quadratic meet (joint j: piece j-1's end, piece j's start, at
    an inflection of the source): {j: (piece j-1's polyline, piece j's, the unit tangent they
    hold)} with both ends holding the source's tangent there (_joint_end: the pieces then
    meet G1, QA gui F3), for the joints where both pieces have JOINT_HOLD_EDGES edges or more and both find a place; held
    only so, since one side held alone can turn the two farther apart (0.39 deg against 0.26
    at 12 edges of an S). ``ends_dir`` None (point data without tangents): the two uniform
    ends' mean tangent there, the one both then hold (G1 needs only one tangent)."""
    held = {}
    for j in range(1, len(piece_start) - 1):
        a, m, b = piece_start[j - 1], piece_start[j], piece_start[j + 1]
        if min(m - a, b - m) < JOINT_HOLD_EDGES:
            continue
        T = None if ends_dir is None else ends_dir[j]
        if T is None:
            try:
                bl = g2_bspline(points[a:m + 1], ends[j - 1], ends[j])
                br = g2_bspline(points[m:b + 1], ends[j], ends[j + 1])
            except DomainError:
                continue
            tl, tr = bl.derivative(bl.knots[-1:])[0], br.derivative(br.knots[:1])[0]
            T = tl / np.hypot(*tl) + tr / np.hypot(*tr)
            T = T / np.hypot(*T)
        left = _joint_end(points[a:m + 1], ends[j - 1], ends[j], T, 1)
        right = None if left is None else _joint_end(points[m:b + 1], ends[j], ends[j + 1],
                                                     T, 0)
        if right is not None:
            held[j] = (left, right, T)
    return held


def _hold_joints(built: list, joints: dict, ends: np.ndarray, factor: float,
                 deviation) -> set:
    """g2_quadratic's pieces ``built`` [(x, spline, deviation, ...)] with the ends of each
    joint j in ``joints`` (_held_joints: piece j-1's end, piece j's start) moved to hold the
    source's tangent there, both or neither: kept where neither piece's ``deviation(p,
    spline)`` exceeds ``factor`` x its own before (a short piece beside the inflection can
    stray farther locally, a 0.235 mm piece of 15 edges to 0.376 mm beside one of 0.269, and
    then stays as it was). Its own, not the largest of all pieces: beside a bad piece a good
    one grew 6 x (review revC: a noisy stroke at 24 edges, 33.8 -> 209 mm from its samples
    beside one of 280, which held fell to 82.6). In place; joints from left to right, so a
    piece between two carries both moves, each against the piece as built, except a piece of
    4 edges: its end is found again on its polyline as moved for its start (x_1 and x_3 each
    slid keeping A_2 against the other as it was change A_2 by t s det(u_2, u_1): neither
    joint G1, 5.6e-5 and 6.6e-5 rad on a k 0.3 S of 4 + 4 + 4 edges; x_3 slid keeping the
    moved A_2 leaves the start's parabola (m_2, v_1, A_2) as it is); none found: the joint is
    dropped from ``joints`` (not held, no end found). Returns the joints held."""
    limit, kept = [factor * b[2] for b in built], set()
    for j in sorted(joints):
        ends_of = list(joints[j][:2])
        if len(built[j - 1][0]) == 5 and j - 1 in kept:
            ends_of[0] = _joint_end(built[j - 1][0], ends[j - 1], ends[j], joints[j][2], 1)
            if ends_of[0] is None:
                del joints[j]
                continue
        new = []
        for p, lo, hi in ((j - 1, -3, -1), (j, 1, 3)):
            x = built[p][0].copy()
            x[lo:hi] = ends_of[p - j + 1][lo:hi]
            try:
                bs = g2_bspline(x, ends[p], ends[p + 1])
            except DomainError:
                break
            new.append((x, bs, deviation(p, bs)))
        if len(new) == 2 and all(d <= limit[p] for p, (_, _, d) in zip((j - 1, j), new)):
            for p, (x, bs, d) in zip((j - 1, j), new):
                built[p] = (x, bs, d) + tuple(built[p][3:])
            kept.add(j)
    return kept


def _unheld_joints(splines, piece_start, joints: dict, kept: set, g1: float) -> tuple:
    """The joints j (piece j-1's end, piece j's start) whose pieces meet more than ``g1``
    radians apart: ((j, angle, why), ...), why in words: a piece of fewer than
    JOINT_HOLD_EDGES edges, no end holding the tangent there (_held_joints: none, or the
    only one the wrong way), or the hold refused for a piece's deviation (_hold_joints)."""
    out = []
    for j in range(1, len(splines)):
        a, b = splines[j - 1], splines[j]
        ta, tb = a.derivative(a.knots[-1:])[0], b.derivative(b.knots[:1])[0]
        angle = abs(math.atan2(ta[0] * tb[1] - ta[1] * tb[0], ta @ tb))
        if angle <= g1:
            continue
        edges = [int(piece_start[q + 1] - piece_start[q]) for q in (j - 1, j)]
        why = (f"a piece of {min(edges)} edges (held from {JOINT_HOLD_EDGES})"
               if min(edges) < JOINT_HOLD_EDGES else
               "no end found that holds the tangent there" if j not in joints else
               "held, a piece would stray farther from the source" if j not in kept else
               "held, yet apart")
        out.append((j, angle, why))
    return tuple(out)
