"""Points that are not one elastica: a fit whose distances lie far above the points' own
noise level (:func:`noise_level`, from the points alone), and where the likely corner is.

QA: a straight run meeting an elastica at a 35-degree corner (400 points, noise 0.3) was
fitted at rms 10.9 with no word; split by hand at the corner, 0.28 and 0.31. :func:`misfit`
says so (:func:`fit` warns :class:`MisfitWarning`) and names the corner.

>>> import numpy as np, libelastica as el
>>> rng = np.random.default_rng(1)
>>> c = el.SmoothElastica(x0=0, y0=0, phi=0.3, mu=1e-4, k=0.8, q=0.2, length=200)
>>> P = c.points(np.linspace(0, 200, 100)) + rng.normal(0, 0.1, (100, 2))
>>> print(el.misfit(P, el.fit(P, model="smooth").distances))
None
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional, Tuple

import numpy as np

from ._ffi import as_points, check, dptr, ffi, lib
from ._quiet import quiet, say
from ._text import LengthFormat, coordinates, lengths
from ._values import ValueEquality

__all__ = ["MISFIT_RATIO", "MisfitWarning", "Misfit", "noise_level", "window_noise", "misfit",
           "misfit_summary", "split_hint", "OutlierWarning", "outliers_summary", "fit_outliers", "stray_summary"]

# A fit's rms over the points' noise level (no verdict where el.far_points names glitches:
# they pull the fit, and are said apart). Measured (rms / noise_level, 692 fits, both
# models): noisy elasticae at most 1.32 (bench_fit.py's 504-curve suite, fit_data.py's uneven
# scans at 4 noise levels and sketches of 15 and 30 points, examples/, QA's hand-drawn stroke
# 1.05; el_fit_noise alone: up to 2.1 on sketches). Noise-free points are far above their
# noise wherever they are no elastica, and the rms must also exceed MISFIT_FLOOR of their
# extent: the discrete polygon on a smooth elastica's points 9.4 x, 8e-6 of it; a G2 fit's
# free fit to a sketched B-spline edge (test_elastica_fit_reopen.py) 33 x, 0.07 mm on 80 mm,
# 8.7e-4. Not one elastica: keylines of two elasticae (keyline_data.py) fitted as one 6.1 to
# 15 x at noise 0.05, 2.1e-3 of the extent (0.3: 2.1-2.4 x), QA's ship line with a 35-degree
# corner 24 x, 1.1e-2; a tile's outline 37 x, 3.7e-2.
MISFIT_RATIO = 4.0
MISFIT_FLOOR = 1e-3
MISFIT_MIN_POINTS = 20
# The corner: a point where the tangents of quadratics fitted to the CORNER_WINDOW-th of the
# points before it and after it turn most (up to CORNER_CANDIDATES such peaks), kept when the
# two parts split there fit each within MISFIT_RATIO x the noise and their curves turn there
# by more than CORNER_TURN. Measured: QA's ship line, the peak at point 162 of the corner's
# 160, the parts at 0.6 x the noise, turning 48.6 degrees (its corner's 48.7); the tile, no
# split whose parts both fit; keylines (keyline_data.py, two elasticae joined G2, noise 0.05,
# fitted as one elastica): parts that fit, turning 0.1-7.8 degrees (no corner).
CORNER_TURN = np.radians(15.0)
CORNER_WINDOW = 25
CORNER_CANDIDATES = 3
CORNER_MIN_SIDE = 10
CORNER_SAMPLES = 2000
# Where no corner stands out, the farthest STRAY_MOST points (1, then 2, ...) are left out and
# the others fitted again (smooth): where they then fit within MISFIT_RATIO x the noise,
# those points account for the misfit and are named (points dragged off among many, under
# far_points' threshold); else the farthest is named as NOT the cause (QA qagui F7: 40 points
# of a sine-like S, point 17 moved 9 mm: rms 2.76, 2.51 without it, 10.3 x the noise either
# way; said "a corner, or curves of more than one piece" of a shape with no corner).
STRAY_MOST = 3
# ... among at most STRAY_SEARCH_POINTS points: beyond, far_points (20 points on) names points
# dragged off, and the refits cost (a 1000-point S scan, no corner: 3 smooth refits 275 ms of
# misfit's 623 ms, a third of its el.fit; revH).
STRAY_SEARCH_POINTS = 200


class MisfitWarning(RuntimeWarning):
    """:func:`fit`'s warning that the fitted curve lies far farther from the points than
    their own noise (:func:`misfit`): they are not one elastica (a corner, two curves, a
    shape of more than one piece), and where a corner stands out, where."""


@dataclass(frozen=True, eq=False, unsafe_hash=True)   # (hash: as before)
class Misfit(ValueEquality):
    """:func:`misfit`'s verdict: ``rms``, the fit's;
    ``noise``, the points' noise level (:func:`noise_level`); ``ratio`` = rms / noise;
    ``corner``: the index of the likely corner, -1 where none stands out; ``parts``: the rms
    of the two parts split there (smooth fits), else None; where no corner stands out
    (``corner`` -1), ``strays``: the farthest points left out (indices, farthest first; those
    that account for the misfit where leaving them out lets the others fit within
    MISFIT_RATIO x the noise, else the farthest alone), ``stray_distances``: theirs to the
    curve, ``without``: the rms of the others' smooth fit (None: not tried)."""
    rms: float
    noise: float
    ratio: float
    corner: int = -1
    parts: Optional[Tuple[float, float]] = None
    strays: Tuple[int, ...] = ()
    stray_distances: Tuple[float, ...] = ()
    without: Optional[float] = None

    @property
    def strays_account(self) -> bool:
        """Whether the points ``strays`` account for the misfit: without them the others fit
        within MISFIT_RATIO x the noise."""
        return self.without is not None and self.without <= MISFIT_RATIO * self.noise


def noise_level(points) -> float:
    """The points' own noise level (n >= 4, (n, 2)): the rms of a point's distance to the
    smooth curve under it, from the points alone (no fit): the larger of el_fit_noise's
    (third differences; of every k-th point on points sorted densely along their curve)
    and, from WINDOW_POINTS points on, :func:`window_noise`'s, of them and of every k-th of
    them (_spread_noise). Repeated points (a scanner writing each point twice, a pen at
    rest) count once: the figure is that of the points without their repeats (4 distinct
    points at least), window_noise's weighing each by its run where runs differ (pixels
    traced at sub-pixel steps: _runs)."""
    fig = _Figures(as_points(points, "noise_level: points", 2, 4))
    if len(fig.seen) < 4:
        raise ValueError(f"noise_level: points: need at least 4 distinct points, got {len(fig.seen)} "
                         "(repeated points count once)")
    return fig.level


# Repeats carry no noise (QA20: every point of a 400-point corner scan written twice read its
# noise 0.051 as 0.226, and el.fit's MisfitWarning, 12.3 x the noise, was lost): el_fit_noise
# keeps a run of repeats once, and the windows here see the same points, el_fit_distinct's
# (the C rule, one for both: a point within 1e-12 of the points' rms radius plus 4 rounding
# units of the first point's |x| + |y| of the last point kept is left out; slowly drifting
# near-copies, each within that of the one before, are kept where they drift past it).
def _distinct(pts: np.ndarray) -> np.ndarray:
    """Checked points without their repeats (el_fit_distinct: el_fit_noise's rule); pts
    itself where there are none."""
    out, m = np.empty_like(pts), ffi.new("size_t *")
    check(lib.el_fit_distinct(dptr(pts), len(pts), dptr(out), m), "noise_level")
    return pts if m[0] == len(pts) else out[:m[0]]


class _Figures:
    """The noise figures of one set of checked points (as _noise's), each computed once, when
    first asked: el.fit asks them in up to three tests of one fit (its check of a fit in the
    points' order, of points that turn back, and the misfit verdict), on the same points.
    ``quick`` / ``plain``: el_fit_noise_quick's / el_fit_noise's of the points (their repeats
    counted once there: the figures of ``seen``); quick 0 where fewer than 4 distinct
    points leave none (the figure is a filter: 0 lets every fit on); ``seen``: the points
    without their repeats (:func:`_distinct`); ``level``: :func:`noise_level`'s."""
    __slots__ = ("pts", "_seen", "_quick", "_plain", "_level")

    def __init__(self, pts: np.ndarray):
        self.pts = pts
        self._seen = self._quick = self._plain = self._level = None

    @property
    def seen(self) -> np.ndarray:
        if self._seen is None:
            self._seen = _distinct(self.pts)
        return self._seen

    @property
    def quick(self) -> float:
        if self._quick is None:
            try:
                self._quick = _noise(self.pts, quick=True)
            except ValueError:
                self._quick = 0.0
        return self._quick

    @property
    def plain(self) -> float:
        if self._plain is None:
            self._plain = _noise(self.pts)
        return self._plain

    @property
    def level(self) -> float:
        if self._level is None:
            self._level = _noise_level(self.seen, self.plain, _runs(self.pts, self.seen))
        return self._level


def _noise_level(pts: np.ndarray, plain: float, runs: Optional[np.ndarray] = None) -> float:
    """noise_level of checked points without repeats whose _noise is ``plain``; ``runs``:
    how many times each was given (:func:`_runs`), None where once each."""
    return max(plain, _window_noise(pts, plain, runs), _spread_noise(pts))


# Repeats counted once leave the points' spread to the curve misread where the repeats are
# not alike: pixels traced at sub-pixel steps repeat the more the longer the curve's chord
# through them, i.e. the nearer their centre lies to it (QA24 F2: a letter 'o' of 428
# integer pixels, 258 distinct: the distinct pixels lie 0.396 from the ellipse (rms), all
# 428, the points the fit's rms is taken over, 0.352; window_noise of the distinct 0.441,
# el.fit's rms 1.55 read as 3.5 x the noise, no MisfitWarning). window_noise then weighs
# each distinct point by its run (weighted least squares, the fit of all the points, and
# the weighted mean square over the distinct points' degrees of freedom): 0.383; points
# repeated alike (a scanner writing each twice, QA20) keep their figure.
def _runs(pts: np.ndarray, seen: np.ndarray) -> Optional[np.ndarray]:
    """How many consecutive times each of ``seen`` (:func:`_distinct`'s points of ``pts``)
    stands in ``pts``: exact repeats; None where there are none, or where el_fit_distinct's
    rule kept other points (near-copies drifting: each point then counts once)."""
    if seen is pts:
        return None
    first = np.flatnonzero(np.r_[True, np.any(pts[1:] != pts[:-1], axis=1)])
    if len(first) != len(seen) or not np.array_equal(pts[first], seen):
        return None
    runs = np.diff(np.r_[first, len(pts)]).astype(float)
    return None if np.all(runs == runs[0]) else runs


def _noise(pts: np.ndarray, quick: bool = False) -> float:
    """el_fit_noise of checked points (C-contiguous float64, (n, 2)); quick:
    el_fit_noise_quick's (consecutive points alone: never above it, lower on points sorted
    densely along a short curve)."""
    out = ffi.new("double *")
    check((lib.el_fit_noise_quick if quick else lib.el_fit_noise)(dptr(pts), len(pts), out),
          "noise_level")
    return float(out[0])


# Noise correlated from point to point (a polygon resampled along noisy points, smoothed
# data) cancels in third differences: equilateral polygons of fit_data.py's noisy scans
# (0.15) measured 0.024-0.061 there, 0.094-0.22 by cubics through WINDOW_POINTS points (the
# scans themselves: 0.14-0.19 either way), their fits' rms 0.13-0.53 (a gap's chord).
WINDOW_POINTS = 15
WINDOW_SAMPLES = 4096
# a window is taken where its curve's shape beyond a cubic leaves at most WINDOW_SHAPE of the
# points' noise (rms; its figure then at most 1.05 x the noise's) and its cubic turns by at
# most WINDOW_TURN radians (_followed)
WINDOW_SHAPE = 0.3
WINDOW_TURN = 1.0
# the median of a chi-square of WINDOW_POINTS - 4 degrees over its mean
_WINDOW_MEDIAN = 0.9401


# Points sorted along their curve (curve_order's of a dense scan, its spacing far below the
# noise) are nearly in line along it and scattered across it: windows of consecutive points
# are narrower along the curve than across, their cubics run across the band and see a
# fraction of the noise (el_fit_noise_quick's stencils likewise; el_fit_noise's take every
# k-th point, k doubled until they span the band). Measured on one elastica, noise 0.05,
# curve order (its given order 0.050 either way): 3e4 points 0.0055 and 0.015, 1e5 0.0014
# and 0.0045; window_noise of every (n // SPREAD_POINTS)-th point: 0.050, 0.049.
SPREAD_POINTS = 2000


def _spread_noise(pts: np.ndarray) -> float:
    """window_noise of every k-th point, k = n // SPREAD_POINTS (0 below 2 x SPREAD_POINTS)."""
    k = len(pts) // SPREAD_POINTS
    return window_noise(pts[::k]) if k >= 2 else 0.0


def _polyfits(t: np.ndarray, Y: np.ndarray, degree: int, max_cond: Optional[float] = None):
    """Least-squares polynomials of degree 2 or 3 in t, batched (windows of points): t (k, m)
    the parameters, Y (k, m, c) the values, by the normal equations. Returns the design
    matrices A (k', m, degree + 1) of 1, t, t^2 (, t^3), the coefficients (k', degree + 1,
    c), lowest power first, and which windows are fitted: with max_cond, the k' whose normal
    matrix's condition number is below it (a boolean mask), else all (None)."""
    A = np.stack([np.ones_like(t), t, t * t, t ** 3][:degree + 1], -1)
    ok = None
    if max_cond is not None:
        ok = np.linalg.cond(np.einsum("kmi,kmj->kij", A, A)) < max_cond
        A, Y = A[ok], Y[ok]
    c = np.linalg.solve(np.einsum("kmi,kmj->kij", A, A), np.einsum("kmi,kmc->kic", A, Y))
    return A, c, ok


def window_noise(points, noise: Optional[float] = None) -> float:
    """The rms of a point's distance to the smooth curve under it from cubics y(x) fitted in
    the principal frame of windows of WINDOW_POINTS consecutive points (up to WINDOW_SAMPLES
    of them, evenly spread): their residuals' mean square per degree of freedom, the median
    over the windows that follow their curve (:func:`_followed`: the part of its shape no
    cubic holds below WINDOW_SHAPE x ``noise``, default el_fit_noise's figure of the points,
    and turning by WINDOW_TURN at most); 0 for fewer points or where none does."""
    return _window_noise(as_points(points, "window_noise: points", 2), noise)


def _window_noise(P: np.ndarray, noise: Optional[float] = None,
                  runs: Optional[np.ndarray] = None) -> float:
    """window_noise of checked points P; ``runs`` (n,): each point's weight (_runs), the
    windows' cubics and mean squares weighted by them, None: all alike."""
    from numpy.lib.stride_tricks import sliding_window_view
    m = WINDOW_POINTS
    if len(P) < m:
        return 0.0
    at = np.unique(np.linspace(0, len(P) - m, min(WINDOW_SAMPLES, len(P) - m + 1)).astype(int))
    W = sliding_window_view(P, m, axis=0).transpose(0, 2, 1)[at]
    C = W - W.mean(axis=1, keepdims=True)
    u = np.linalg.eigh(np.einsum("kmi,kmj->kij", C, C))[1][:, :, 1]     # principal direction
    x = np.einsum("kmi,ki->km", C, u)
    y = C[:, :, 1] * u[:, [0]] - C[:, :, 0] * u[:, [1]]
    t = x / np.maximum(np.abs(x).max(axis=1, keepdims=True), np.finfo(float).tiny)
    A, c, ok = _polyfits(t, y[..., None], 3, max_cond=1e12)     # not folded onto a point
    if not np.any(ok):
        return 0.0
    if runs is None:
        r = y[ok] - np.einsum("kmi,ki->km", A, c[..., 0])
        ms = np.sum(r * r, axis=1) / (m - 4)
    else:   # the same windows (their curve followed as unweighted), the points weighed
        ms = _weighted_ms(A, y[ok], sliding_window_view(runs, m)[at][ok])
    if noise is None:
        noise = _noise(np.ascontiguousarray(P))
    keep = _followed(A, c[..., 0], x[ok], noise)
    if not np.any(keep):
        return 0.0
    return float(np.sqrt(np.median(ms[keep]) / _WINDOW_MEDIAN))


def _weighted_ms(A: np.ndarray, y: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The mean squares per degree of freedom of windows' cubics (design matrices A (k, m,
    4), values y (k, m)) fitted to their points each repeated w (k, m) times (weighted least
    squares): sum w r^2 / sum w x m / (m - 4), the weighted mean over the distinct points'
    degrees of freedom (points repeated alike: the unweighted figure)."""
    m = A.shape[1]
    N = np.einsum("km,kmi,kmj->kij", w, A, A)
    c = np.linalg.solve(N, np.einsum("km,kmi,km->ki", w, A, y)[..., None])[..., 0]
    r = y - np.einsum("kmi,ki->km", A, c)
    return np.sum(w * r * r, axis=1) / np.sum(w, axis=1) * m / (m - 4)


def _followed(A: np.ndarray, c: np.ndarray, x: np.ndarray, noise: float) -> np.ndarray:
    """Which windows' cubics follow their curve (window_noise's): those where the part of the
    curve no cubic y(x) holds, its quartic term, leaves a residual rms of at most
    WINDOW_SHAPE x ``noise`` (el_fit_noise's: third differences, which cancel a cubic's
    turning; not the window's own residual, which would keep the windows whose shape the
    estimate misses) and that turn by WINDOW_TURN at most. A curve of curvature kappa with y' = 0 at the
    frame's origin has y'' = kappa (1 + y'^2)^(3/2), so its fourth derivative there is
    kappa'' + 3 kappa^3: the quartic term about kappa^3 x^4 / 8 (a circle's), taken with the
    largest |kappa| of the window's cubic (A, c: its design matrix in t = x / max|x| and its
    coefficients; x the abscissae) and projected off the cubics as the fit leaves it. Sparse
    points on a turning curve (QA21: 40 points along a clothoid turning 5 rad, 15 of them
    turning up to 1.9 rad) leave their shape in the cubic's residual: 13 x the noise there
    (1.36 for 0.105)."""
    xs = np.maximum(np.abs(x).max(axis=1), np.finfo(float).tiny)
    t = A[:, :, 1]
    # in the window's own units (c / xs, kappa xs): kappa^3 x^4 / 8 = (kappa xs)^3 xs t^4 / 8,
    # which neither x^4 nor kappa^3 overflows or underflows (points at 1e150: x^4 = inf,
    # kappa^3 = 0, q NaN and numpy's overflow / invalid RuntimeWarnings, no window followed)
    cs = c / xs[:, None]
    d1 = cs[:, [1]] + 2 * cs[:, [2]] * t + 3 * cs[:, [3]] * t * t
    h = np.hypot(1.0, d1)
    kx = np.max(np.abs(2 * cs[:, [2]] + 6 * cs[:, [3]] * t) / h / h / h, axis=1)
    q = (kx ** 3 / 8 * xs)[:, None] * t ** 4
    AtA = np.einsum("kmi,kmj->kij", A, A)
    beta = np.linalg.solve(AtA, np.einsum("kmi,km->ki", A, q)[..., None])[..., 0]
    shape = np.sum((q - np.einsum("kmi,ki->km", A, beta)) ** 2, axis=1) / (A.shape[1] - 4)
    turn = np.ptp(np.arctan(d1), axis=1)
    return (shape <= (WINDOW_SHAPE * noise) ** 2) & (turn <= WINDOW_TURN)


def _rms_near(distances, points) -> float:
    from .fit import far_points
    d = np.abs(np.asarray(distances, dtype=float))
    return float(np.sqrt(np.mean(np.delete(d, far_points(d, points)) ** 2)))


def _turns(P: np.ndarray, w: int):
    """At points w .. n-w-1: the angle between the tangents there of the quadratics (in chord
    length) fitted to the w + 1 points ending there and the w + 1 starting there."""
    from numpy.lib.stride_tricks import sliding_window_view
    s = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(P, axis=0).T))])
    S, X = sliding_window_view(s, w + 1), sliding_window_view(P, w + 1, axis=0)

    def tangent(at):
        t = S - S[:, [at]]
        t = t / np.maximum(np.abs(t).max(axis=1, keepdims=True), 1e-300)
        return _polyfits(t, X.transpose(0, 2, 1), 2)[1][:, 1, :]
    left, right = tangent(w)[:-w - 1], tangent(0)[w:-1]
    i = np.arange(w, len(P) - w)
    cross = left[:, 0] * right[:, 1] - left[:, 1] * right[:, 0]
    return i, np.abs(np.arctan2(cross, np.sum(left * right, axis=1)))


def _corner(pts: np.ndarray, noise: float):
    """The likely corner of points that are not one elastica: (index, the two parts' rms)
    or (-1, None). Each candidate's parts (of every step-th point: CORNER_SAMPLES at most)
    are fitted by the smooth model (their rms, far points left out; the turn between the
    first's end tangent and the second's start)."""
    from .fit import judging_fit
    step = max(1, -(-len(pts) // CORNER_SAMPLES))
    P = pts[::step]
    w = max(6, len(P) // CORNER_WINDOW)
    if len(P) < 2 * w + 3:
        return -1, None
    i, a = _turns(P, w)
    peaks = []
    for j in np.argsort(-a, kind="stable"):
        if all(abs(int(i[j]) - p) > w for p in peaks):
            peaks.append(int(i[j]))
        if len(peaks) == CORNER_CANDIDATES:
            break
    best = (-1, None, np.inf)
    for p in peaks:
        c = p * step
        if min(p + 1, len(P) - p) < CORNER_MIN_SIDE:      # (step 1: c + 1, n - c)
            continue
        parts, fits = [], []
        for side in (P[:p + 1], P[p:]):     # thinned: 1e5 points took 10 s
            fig = _Figures(np.ascontiguousarray(side))
            if len(fig.seen) < MISFIT_MIN_POINTS:   # no verdict on so few: not said to fit
                break
            try:
                fits.append(judging_fit(side, model="smooth"))     # a verdict: no gate
            except (ValueError, ArithmeticError, RuntimeError):
                break
            rms = _rms_near(fits[-1].distances, side)
            if not rms <= MISFIT_RATIO * fig.level:   # misfit's test, the part's own noise
                break
            parts.append(rms)
        if len(parts) < 2:
            continue
        a, b = fits[0].curve, fits[1].curve
        turn = np.angle(np.exp(1j * (b.angle(np.zeros(1))[0] - a.angle(np.full(1, a.length))[0])))
        if abs(turn) > CORNER_TURN and max(parts) <= MISFIT_RATIO * noise and max(parts) < best[2]:
            best = (c, (parts[0], parts[1]), max(parts))
    return best[0], best[1]


def misfit(points, distances, corner: bool = True, strays: bool = True) -> Optional[Misfit]:
    """Whether a fit lies far farther from its points than their own noise: their rms above
    MISFIT_RATIO x :func:`noise_level` and MISFIT_FLOOR of the points' extent
    (MISFIT_MIN_POINTS distinct points at least; none of them far, :func:`far_points`); then a
    :class:`Misfit` (with ``corner``: where the points turn most and the two parts split
    there each fit within MISFIT_RATIO x the noise, their curves turning there by more than
    CORNER_TURN; two smooth fits per candidate), else None. Where no corner stands out,
    with ``strays`` the farthest points are left out and the others fitted again as one
    smooth elastica (Misfit.strays): False for a fit of another shape (a keyline's), whose
    figures one elastica's would not match.
    points (n, 2): the fitted points; distances (n,): theirs to the curve."""
    pts = as_points(points, "misfit: points", 2)
    d = np.asarray(distances, dtype=float)
    if d.shape != (len(pts),):
        raise ValueError("misfit: distances (n,) for points (n, 2) are needed")
    return _verdict(_Figures(pts), d, float(np.sqrt(np.mean(d * d))), corner, strays)


def _verdict(fig: _Figures, d: np.ndarray, rms_all: float, corner: bool = True,
             strays: bool = True) -> Optional[Misfit]:
    """misfit of the points of ``fig`` (:class:`_Figures`: the figures computed once for all
    verdicts of the same points), their distances and their rms (a fit's own, el.fit's
    path: 0.011 ms of a 1000-point discrete fit's 0.5 where it is silent). Its first test
    takes el_fit_noise_quick's figure, never above el_fit_noise's: el_fit_noise's stride
    search (twice the instructions) and the points without their repeats are computed only
    where that test is passed."""
    pts = fig.pts
    # the window figure and el_fit_noise's stride search (points sorted densely along a
    # short curve) only raise el_fit_noise_quick's figure: both paid only where it is passed
    # (and the distinct points counted there: fewer points than MISFIT_MIN_POINTS have fewer)
    if len(pts) < MISFIT_MIN_POINTS or not rms_all > MISFIT_RATIO * fig.quick:
        return None
    if len(fig.seen) < MISFIT_MIN_POINTS:     # (the noise figures: repeats count once)
        return None
    noise = fig.plain
    if not rms_all > MISFIT_RATIO * noise:
        return None
    from .fit import far_points
    if len(far_points(d, pts)):               # glitches pull the fit: said apart, refit without
        return None
    noise = fig.level
    rms, extent = rms_all, float(np.max(np.ptp(pts, axis=0)))
    if not (rms > MISFIT_RATIO * noise and rms > MISFIT_FLOOR * extent):
        return None
    at, parts = _corner(pts, noise) if corner else (-1, None)
    search = corner and strays and at < 0 and len(pts) <= STRAY_SEARCH_POINTS
    far = _strays(pts, d, noise) if search else ((), None)
    return Misfit(rms, noise, rms / noise if noise > 0 else np.inf, at, parts, far[0],
                  tuple(float(abs(d[i])) for i in far[0]), far[1])


def _strays(pts: np.ndarray, d: np.ndarray, noise: float):
    """(the farthest points that account for the misfit, the others' rms) where leaving out
    the farthest 1 .. STRAY_MOST points lets the others' smooth fit lie within MISFIT_RATIO x
    ``noise``; else ((the farthest,), the others' rms without it); ((), None) where no fit
    of the others is made (a failed fit)."""
    from .fit import judging_fit
    order = [int(i) for i in np.argsort(-np.abs(d), kind="stable")[:STRAY_MOST]]
    first = None
    for k in range(1, len(order) + 1):
        if len(pts) - k < MISFIT_MIN_POINTS:
            break
        try:
            r = judging_fit(np.delete(pts, order[:k], axis=0), model="smooth")
        except (ValueError, ArithmeticError, RuntimeError):
            break
        rms = float(np.sqrt(np.mean(np.asarray(r.distances, dtype=float) ** 2)))
        if rms <= MISFIT_RATIO * noise and _stand_off(r.curve, pts[order[:k]], rms):
            return tuple(order[:k]), rms
        first = first or (tuple(order[:1]), rms)
    return first or ((), None)


def _stand_off(curve, left: np.ndarray, rms: float) -> bool:
    """Whether the points ``left`` out lie off the curve the others take, each farther than
    MISFIT_RATIO x that fit's rms: points dragged off do, innocent ones that were merely the
    farthest from a fit pulled towards the dragged ones do not (22 points, 8 and 9 dragged
    60 off: the fit passed near them, the farthest 16 and 0 left out gave rms 2.23 under 3 x
    a noise figure the dragged points raised (0.787), yet lay 4.05 and 9.26 off the refit;
    8 and 9 lie 54 and 59 off theirs, rms 0.016)."""
    from .nearest import curve_feet
    d, _ = curve_feet(curve, left)
    return bool(np.all(d > MISFIT_RATIO * rms))


def _places(points: np.ndarray, rows, fmt: LengthFormat) -> list:
    """"(x, y)" of each of ``points[rows]``, 4 digits of the points' size however far from
    the origin (the CLI's coordinates): a warning's places (misfit_summary's, fit.py's
    wander_summary's)."""
    size = float(np.ptp(points, axis=0).max())
    return [f"({coordinates(points[i], size, 4, fmt)})" for i in rows]


# Points whose ends lie within CLOSED_GAP of their extent (the largest side of their box)
# of each other and that enclose CLOSED_AREA of its square at least (shoelace, the gap
# closed) are said to be nearly closed where misfit names no corner: QA24's letter 'o' (97 %
# of a 30 x 40 ellipse in pixels): ends 8.06 apart, 10 % of 80, area 0.59 x 80^2 (a 10 x 80
# ellipse 0.098); a scan passed out and back over its own pass returns to its start enclosing
# nothing (a square's two sides, noise 0.1 / 0.4: 0.0002 / 0.0009; said "nearly closed").
CLOSED_GAP = 0.25
CLOSED_AREA = 0.05


def _nearly_closed(points: np.ndarray):
    """(the gap between the first and the last point, over the extent) of points (n, 2), or
    (n, 3) in a plane (FreeCAD names places in 3D), in curve order whose ends lie within
    CLOSED_GAP of their extent and that enclose CLOSED_AREA x its square, else None."""
    extent = float(np.max(np.ptp(points, axis=0)))
    gap = float(np.linalg.norm(points[-1] - points[0]))
    if not (extent > 0 and gap <= CLOSED_GAP * extent):
        return None
    p = points - points.mean(axis=0)
    if p.shape[1] == 2:
        p = np.column_stack([p, np.zeros(len(p))])
    # the polygon's vector area (half the sum of p_i x p_i+1): its length the enclosed area
    # in whatever plane the points lie
    area = 0.5 * float(np.linalg.norm(np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)))
    return (gap, gap / extent) if area >= CLOSED_AREA * extent * extent else None


def _point_named(i: int, points, fmt: LengthFormat, numbered: bool, named) -> str:
    """How misfit_summary names point i: named(i) where given, else "point 7 (counted from
    0; at (x, y))", or "(x, y)" alone where not ``numbered``."""
    if named is not None:
        return named(i)
    place = "" if points is None else _places(np.asarray(points, dtype=float), [i], fmt)[0]
    return (f"point {i} (counted from 0{'; at ' + place if place else ''})"
            if numbered or not place else place)


def _strays_said(m: Misfit, points, fmt: LengthFormat, numbered: bool, named, what: str) -> str:
    """misfit_summary's words where no corner stands out: the farthest points named, as the
    cause where they account for the misfit (Misfit.strays_account), else as not the cause;
    a corner never named (none stands out)."""
    names = [_point_named(i, points, fmt, numbered, named) for i in m.strays]
    far = ", ".join(f"{n}, {fmt(v, 3)} from the curve" for n, v in zip(names, m.stray_distances))
    if m.strays_account:
        one = len(m.strays) == 1
        return (f": the farthest {'point' if one else f'{len(m.strays)} points'} account"
                f"{'s' if one else ''} for it ({far}): without {'it' if one else 'them'} the "
                f"others fit at rms {fmt(m.without, 3)}. Dragged off? Remove or move "
                f"{'it' if one else 'them'} to fit the rest")
    why = (f", and the farthest point is not the cause ({far}; without it rms "
           f"{fmt(m.without, 3)})" if m.strays else "")
    return (f": no corner stands out{why}; {what} does not take their shape, or they are "
            "curves of more than one piece: fit each alone, or pass an elastic spline through "
            "the points")


def misfit_summary(m: Misfit, points=None, unit: str = "", numbered: bool = True,
                   length: Optional[LengthFormat] = None, what: str = "one elastica",
                   named=None) -> str:
    """What a warning of points that are not one elastica says (:func:`fit`'s, the CLI's and
    FreeCAD's), of :func:`misfit`'s verdict ``m``: "the curve lies 10.9 from the points
    (rms), 24 x their own noise (0.456): they are not one elastica; a corner at point 162
    (counted from 0; at (x, y))? Split there, the two parts fit at rms 0.28 and 0.31".
    points: the fitted points (n, 2), or (n, 3) where they are named in 3D (FreeCAD's), to name
    the corner's place (4 digits of their size however far from the origin: the CLI's
    coordinates); ``unit``, ``length`` as
    :func:`wander_summary`'s; numbered False: by its place alone, where the numbers are the
    fit's order, not the user's; what: the model ("one keyline" for :func:`fit_keyline`'s);
    named: a function of a point's index giving how it is named instead (FreeCAD's "point 24
    as given, at (x, y) mm in the sketch"). Where no corner stands out, the farthest points
    (``m.strays``) are named: as the cause where they account for the misfit, else as not."""
    fmt = lengths(unit, length)
    said = (f"the curve lies {fmt(m.rms, 3)} from the points (rms), {m.ratio:.3g} x their own "
            f"noise ({fmt(m.noise, 3)}): they are not {what}")
    if m.corner < 0:
        closed = None if points is None else _nearly_closed(np.asarray(points, dtype=float))
        if closed is not None:     # (QA24 F1: a letter 'o' of pixels, 97 % of an ellipse)
            return (said + f": their ends lie {fmt(closed[0], 3)} apart, {closed[1]:.0%} of "
                    "their extent, a nearly closed shape, which no one elastica follows, nor "
                    "one keyline (fit_keyline takes an open piece with one inflection): cut "
                    "it into open pieces (points[i:j]) that turn one way (fit) or hold one "
                    "inflection each (fit_keyline) and fit each alone")
        return said + _strays_said(m, points, fmt, numbered, named, what)
    where = "at " + _point_named(m.corner, points, fmt, numbered, named)
    return (said + f"; a corner {where}? Split there, the two parts fit at rms "
            f"{fmt(m.parts[0], 3)} and {fmt(m.parts[1], 3)}")


# Fewer points than MISFIT_MIN_POINTS get no misfit verdict: their noise level alone says
# too little (QA22gui F7: 12 clicks with 0.8 mm jitter read 0.467). Where they turn both ways,
# split_hint asks the keyline (two elasticae joined G2 at the inflection, fit_keyline) too: a
# fit above SPLIT_RATIO x the noise level that the keyline fits SPLIT_GAIN x as close or
# closer is said, with both figures. Measured (/tmp/fcmend2/hint_rule.py): F7's 12 clicks
# along a guitar waist 1.92 (4.1 x), the keyline 0.41; 12 noisy points of 149 true elasticae
# with an inflection (noise 0.05 to 0.8 on curves 20 to 72 long): said of 1, a fit stuck far
# off (2.92 at noise 0.2; the keyline 0.076); the keyline's extra parameters alone bring 3
# fits at the noise below 0.5 x, all under SPLIT_RATIO. The waist curve's clicks at 8 to 19
# points (50 sets): said of 6, the keyline elsewhere no closer than 0.5 x.
SPLIT_RATIO = 2.0
SPLIT_GAIN = 0.5


def split_hint(points, distances, how: str = "fit_keyline", unit: str = "",
               length: Optional[LengthFormat] = None) -> Optional[str]:
    """For fewer than MISFIT_MIN_POINTS points (where :func:`misfit` says nothing), the words
    saying that two elasticae joined at their inflection fit them far closer: their fit's rms
    (of ``distances``, theirs to its curve) above SPLIT_RATIO x :func:`noise_level`, and the
    smooth keyline (:func:`fit_keyline`) within SPLIT_GAIN x that rms; else None (points
    that turn one way, a keyline that fails or fits no better). ``points`` (n, 2) in curve
    order; ``how``: the way to split, as the caller's user asks for it; ``unit``, ``length``
    as :func:`misfit_summary`'s. Costs a keyline fit (~13 ms on 12 points) where the first
    test is passed."""
    pts = as_points(points, "split_hint: points", 2)
    d = np.asarray(distances, dtype=float)
    if d.shape != (len(pts),):
        raise ValueError("split_hint: distances (n,) for points (n, 2) are needed")
    if not 6 <= len(pts) < MISFIT_MIN_POINTS:
        return None
    rms = float(np.sqrt(np.mean(d * d)))
    try:
        noise = noise_level(pts)
    except ValueError:
        return None
    if not rms > SPLIT_RATIO * noise:
        return None
    from .keyline import fit_keyline
    try:
        with quiet():           # the keyline is asked, not shown (this thread's: _quiet.py)
            kf = fit_keyline(pts, model="smooth")
    except (ValueError, ArithmeticError, RuntimeError):
        return None                             # no inflection, or no keyline: no hint
    if not kf.input_rms <= SPLIT_GAIN * rms:
        return None
    fmt = lengths(unit, length)
    return (f"the curve lies {fmt(rms, 3)} from the points (rms), {rms / noise:.2g} x their own "
            f"noise ({fmt(noise, 3)}), and they turn both ways: split at the inflection "
            f"({how}), two elasticae fit them at rms {fmt(kf.input_rms, 3)}")


class OutlierWarning(RuntimeWarning):
    """:func:`fit`'s warning that some points lie far from the fitted curve, standing apart
    from the others (:func:`far_points`: scan glitches, points of other geometry): each
    pulls the fit towards itself (QA21: one glitch of 40 points pulled the curve 0.91, 26 x
    the noise, off the true shape). ``indices``: the points, counted from 0 in the caller's
    order; the CLI and FreeCAD say the same."""

    def __init__(self, message: str, indices=()):
        super().__init__(message)
        self.indices = tuple(int(i) for i in indices)


def outliers_summary(distances, far, rows=None, free_distances=None, unit: str = "",
                     length: Optional[LengthFormat] = None) -> str:
    """What a warning of points far from the curve says (:func:`fit`'s OutlierWarning, the
    CLI's line): far_points_summary's figures of ``distances`` (the fit's, or with
    ``free_distances`` the free fit's as there), ``unit`` and ``length`` writing them as
    there, the points ``far`` (``rows``: their numbers for the user, default ``far``; 10 at
    most named) and what to do: "1 of 40 points lies 3.9 from the curve, the others within
    0.12: outliers? (points 13, counted from 0) Each pulls the fit towards itself: remove
    them to fit the rest"."""
    from .fit import far_points_summary
    rows = [int(i) for i in (far if rows is None else rows)]
    named = ", ".join(str(i) for i in rows[:10]) + (", ..." if len(rows) > 10 else "")
    said = far_points_summary(distances, far, unit, free_distances, length)
    return (f"{said}: outliers? (points {named}, counted from 0) Each pulls the fit towards "
            "itself: remove them to fit the rest")


def fit_outliers(r, free_distances=None) -> np.ndarray:
    """The points of fit result ``r`` far from its curve, by the rule :func:`fit` warns with
    (OutlierWarning) and the CLI says: :func:`far_points` of its distances; a constrained
    fit's (``r.constraints``) judged with the distances of the fit without them too
    (``free_distances``, default ``r.free``'s where :func:`fit` made it): points held off
    only by the constraints are no outliers. Among fewer than OUTLIER_MIN_POINTS points (a
    hand sketch's), an unconstrained fit's one stray point (:func:`libelastica.stray.stray_point`:
    far from the curve of the others). Indices into ``r.points``."""
    return _fit_outliers(r, free_distances)[0]


def _fit_outliers(r, free_distances=None, screened=None):
    """:func:`fit_outliers` with stray_point's figures (index, distance, noise, gain) where
    it named a stray point, else None. screened: el.fit's one call's (median, maximum,
    distances) of |distances| (_fit_call.py), far_points' test of them where they are
    ``r.distances``' and known: none far there, without far_points' numpy calls."""
    from .fit import OUTLIER_FACTOR, OUTLIER_MIN_POINTS, far_points
    if r.distances is None:
        return np.empty(0, dtype=np.intp), None
    if free_distances is None and r.constraints and getattr(r, "free", None) is not None:
        free_distances = r.free.distances
    if (screened is not None and free_distances is None and screened[2] is r.distances
            and len(r.distances) >= OUTLIER_MIN_POINTS and not math.isnan(screened[0])
            and _none_far(screened[0], screened[1], OUTLIER_FACTOR)):
        far = np.empty(0, dtype=np.intp)      # (far_points' answer: none beyond the factor)
    else:
        far = far_points(r.distances, r.points, free_distances=free_distances)
    # (stray_point names none among OUTLIER_MIN_POINTS points or more: neither asked nor
    # imported there, el.fit's every fit of as many; a function-level import costs a lookup)
    if len(far) or r.constraints or (r.points is not None and len(r.points) >= OUTLIER_MIN_POINTS):
        return far, None
    from .stray import stray_point
    stray = stray_point(r)
    return (far, None) if stray is None else (np.array([stray[0]], dtype=np.intp), stray)


def _none_far(median_d: float, max_d: float, factor: float) -> bool:
    """far_points' first test (fit.py), which _fit_outliers asks of el.fit's one call's
    figures too: no |distance| beyond ``factor`` x the typical one, 1.4826 x the median
    |distance| (``median_d``; ``max_d`` the largest)."""
    return not max_d > factor * (1.4826 * median_d)


def _warn_outliers(r, screened=None) -> None:
    """:func:`fit`'s OutlierWarning of result ``r`` where :func:`fit_outliers` names points
    (numbered in the caller's order: ``r.order``'s where fitted in curve order; screened:
    :func:`_fit_outliers`')."""
    far, stray = _fit_outliers(r, screened=screened)
    if not len(far):
        return
    rows = sorted(int(r.order[i]) for i in far) if r.order is not None else far
    free = r.free.distances if r.constraints and r.free is not None else None
    said = outliers_summary(r.distances, far, rows, free) if stray is None else \
        stray_summary(len(r.points), stray, rows[0])
    # stacklevel: _warn_outliers, _fit, fit, its caller
    say(OutlierWarning("fit: " + said, rows), stacklevel=4)


def stray_summary(n: int, stray, row: int, unit: str = "",
                  length: Optional[LengthFormat] = None, named: Optional[str] = None) -> str:
    """What a warning of one stray point among few says (:func:`fit`'s OutlierWarning, the
    CLI's and FreeCAD's): stray: :func:`libelastica.stray.stray_point`'s figures; row: its
    number for the user, counted from 0 (``unit``, ``length`` as in
    :func:`outliers_summary`); named: how the point is named instead of "point 10, counted
    from 0" (FreeCAD's "point 11 as given, at (x, y, z) mm"): "1 of 18 points lies 150 from
    the curve through the others, 210 x their noise (0.71): dragged off? (point 10, counted
    from 0) ..."."""
    fmt = lengths(unit, length)
    named = named or f"point {row}, counted from 0"
    return (f"1 of {n} points lies {fmt(stray[1], 3)} from the curve through the others, "
            f"{stray[1] / stray[2]:.2g} x their noise ({fmt(stray[2], 2)}), which lie "
            f"{stray[3]:.2g} x nearer their curve without it: a point dragged off? ({named}) "
            "It pulls the fit towards itself: remove or move it to fit the rest")
