"""A pixel stroke whose pen retraces an end (it starts a few px into the stroke, runs back to
the true start, then along; or at the end runs back a few px) is fitted from end to end of its
ink: the curve neither stops short of the points beyond its tied end point (the smooth model,
fit_ends.c's piles_up: QA24 F10, max_error 2.7-7.8 px where the stroke without retrace fits at
1.1) nor runs on past the stroke where there is no ink (the discrete model paired with the
points, fit_pairing.c's el__fit_overruns: QA24 F9, 5.3 px past the start). Strokes as QA24's
sign maker's: traced at 0.35 px steps, noise 0.25 px, rounded to 0.5 px, y down."""
import warnings

import numpy as np
import pytest
from scipy.spatial import cKDTree

import libelastica as el

STEP, NOISE, QUANT = 0.35, 0.25, 0.5


def _stroke(seed, start, end):
    """A 60-200 px elastica stroke traced, noisy and quantised, with retraces of start and end
    px at its ends: (points, the traced stroke without noise)."""
    r = np.random.default_rng(seed)
    c = el.SmoothElastica(x0=0, y0=0, phi=r.uniform(-3, 3), mu=1.0, k=r.uniform(0.3, 0.9),
                          q=r.uniform(-1, 1), length=r.uniform(2.5, 4.5))
    T = c.points(np.linspace(0, c.length, 4000)) * r.uniform(60, 200) * (1, -1) + (300, 300)
    d = np.r_[0, np.cumsum(np.hypot(*np.diff(T, axis=0).T))]
    s = np.arange(0, d[-1], STEP)
    X0 = np.c_[np.interp(s, d, T[:, 0]), np.interp(s, d, T[:, 1])]
    m0, m1 = int(start / STEP), int(end / STEP)
    X = np.r_[X0[m0:0:-1], X0, X0[len(X0) - 2:len(X0) - m1 - 2:-1]]
    return np.round((X + r.normal(0, NOISE, X.shape)) / QUANT) * QUANT, X0


def _gaps(r, P):
    """The fitted curve's farthest sample from any point (a tail with no ink), and the farthest
    point from the curve (ink the curve does not reach)."""
    C = r.curve
    Q = C.points(np.linspace(0, C.length, 4000))
    return float(cKDTree(P).query(Q)[0].max()), float(cKDTree(Q).query(P)[0].max())


# (seed, start retrace px, end retrace px): both ends, either end alone; strokes whose fit went
# wrong before (smooth: 6, 9, 14 stopped 6.0-6.6 px short; discrete: 38, 60, 75 paired,
# running on 5.4-6.0 px past the ink)
CASES = [(6, 6.0, 6.0), (9, 6.0, 6.0), (14, 6.0, 6.0), (38, 0.0, 6.0), (60, 6.0, 0.0), (60, 6.0, 6.0),
         (75, 6.0, 6.0)]


@pytest.mark.parametrize("model", ["smooth", "discrete"])
@pytest.mark.parametrize("seed,start,end", CASES)
def test_a_stroke_with_a_retraced_end_is_fitted_from_end_to_end_of_its_ink(seed, start, end, model):
    P, X0 = _stroke(seed, start, end)
    plain = np.round((X0 + np.random.default_rng(seed).normal(0, NOISE, X0.shape)) / QUANT) * QUANT
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = el.fit(P, model=model)
        ref = el.fit(plain, model=model)
    over, short = _gaps(r, P)
    ref_over, ref_short = _gaps(ref, plain)
    # as the same stroke without its retrace: within a px of it each way (the noise's
    # extremes, ~4 sigma and a quantum), not the retrace's 5-6.5 px
    assert over < ref_over + 1.0, (over, ref_over)
    assert short < ref_short + 1.0, (short, ref_short)
    assert r.max_error < ref.max_error + 1.0
    assert r.rms < 1.15 * ref.rms


def _dwell_spike(seed, spike):
    """A stroke as _stroke's without retrace whose pen rests at its end (10 samples of the end
    point) and then, 2 samples before it lifts, jumps once spike px on along the end's tangent
    (a tablet's lift-off glitch): (points, the traced stroke without noise)."""
    r = np.random.default_rng(seed)
    _, X0 = _stroke(seed, 0.0, 0.0)
    e, t = X0[-1], X0[-1] - X0[-4]
    X = np.r_[X0, np.repeat(X0[-1:], 10, axis=0)]
    P = np.round((X + r.normal(0, NOISE, X.shape)) / QUANT) * QUANT
    P[-3] = np.round((e + spike * t / np.hypot(*t)) / QUANT) * QUANT
    return P, X0


# one point far past an end is an outlier, not a retrace: the smooth fit's pile-up refit tied
# to it drew the curve out to it, 4-12 px past the stroke's end, and its OutlierWarning went
# (fit_ends.c's piles_up took the farthest point beyond the end, not PILE_LEAST of them)
@pytest.mark.parametrize("seed", [6, 9, 14, 38])
def test_one_spike_past_a_dwelt_end_is_an_outlier_not_a_retrace(seed):
    P, X0 = _dwell_spike(seed, 8.0)
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = el.fit(P, model="smooth")
    C = r.curve
    Q = C.points(np.linspace(0, C.length, 4000))
    # the curve stays on the stroke (noise ~4 sigma), it does not run on to the spike
    assert float(cKDTree(X0).query(Q)[0].max()) < 1.5
    assert any(issubclass(x.category, el.OutlierWarning) for x in w), [str(x.message) for x in w]


def _broad(i):
    """Stroke i of 100 drawn with one generator (a sign maker's broad pen): 40-200 px, traced at
    0.25-1.2 px steps (odd i: the speed varying along it), retraces of 0-12 px at either end,
    noise 0.2-0.6 px, rounded to 1 px (i % 3 == 0) or 0.5 px, y down: the points."""
    r = np.random.default_rng(4242)
    for j in range(i + 1):
        k, L, phi, q, sc = r.uniform(0.2, 0.95), r.uniform(2, 4.5), r.uniform(-3, 3), r.uniform(-1, 1), r.uniform(40, 200)
        c = el.SmoothElastica(x0=0, y0=0, phi=phi, mu=1.0, k=k, q=q, length=L)
        T = c.points(np.linspace(0, c.length, 4000)) * sc * (1, -1) + (300, 300)
        d = np.r_[0, np.cumsum(np.hypot(*np.diff(T, axis=0).T))]
        step = r.uniform(0.25, 1.2)
        if j % 2:
            u = np.cumsum(step * (1 + 0.5 * np.sin(np.arange(int(3 * d[-1] / step)) * r.uniform(0.01, 0.05))))
            s = u[u < d[-1]]
        else:
            s = np.arange(0, d[-1], step)
        X0 = np.c_[np.interp(s, d, T[:, 0]), np.interp(s, d, T[:, 1])]
        a, b = r.uniform(0, 12), r.uniform(0, 12)
        m0, m1 = int(np.searchsorted(s, a)), int(np.searchsorted(d[-1] - s[::-1], b))
        X = np.r_[X0[m0:0:-1], X0, X0[len(X0) - 2:len(X0) - m1 - 2:-1]]
        quantum = 1.0 if j % 3 == 0 else 0.5
        P = np.round((X + r.normal(0, r.uniform(0.2, 0.6), X.shape)) / quantum) * quantum
    return P


def _polygon_gaps(r, P):
    """_gaps of a discrete fit by exact point-to-segment distance (the polygon, not samples)."""
    V = r.curve.points()
    A, B = V[:-1], V[1:]
    AB = B - A
    t = np.clip(np.einsum("pij,ij->pi", P[:, None] - A, AB) / np.einsum("ij,ij->i", AB, AB), 0, 1)
    short = float(np.hypot(*(P[:, None] - A - t[..., None] * AB).transpose(2, 0, 1)).min(axis=1).max())
    Q = (A[None] * (1 - np.linspace(0, 1, 20)[:, None, None]) + B[None] * np.linspace(0, 1, 20)[:, None, None])
    return float(cKDTree(P).query(Q.reshape(-1, 2))[0].max()), short


# a discrete fit by distance is tied to the stroke's first and last points as the smooth one is,
# and stopped short of a retraced end by up to 3.5 px (its pile-up refit, fit_ends.c, was the
# smooth model's only): strokes 71 (retraces 11.3 / 4.6 px), 73 (9.4 / 5.2), 92 (7.8 / 3.6) of
# _broad, their farthest point 3.49, 2.70, 2.61 px from the polygon; tied to the points farthest
# along it, 1.17, 0.94, 0.84 (62 of the 100 strokes > 2 px before, 43 after: the others' retrace
# lies less than FIT_RETRACE_PAST noise levels beyond the tied end)
@pytest.mark.parametrize("i", [71, 73, 92])
def test_a_discrete_fit_by_distance_reaches_a_retraced_end(i):
    P = _broad(i)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = el.fit(P, model="discrete")
    assert r.distance == "orthogonal"
    over, short = _polygon_gaps(r, P)
    assert short < 1.5, short
    assert over < 2.0, over
    assert abs(r.max_error - short) < 1e-6 * max(short, 1.0)


# QA24's strokes (_stroke) with a 9 px retrace at both ends, fitted by distance as a polygon: the
# polygon's end vertex, tied to the first point (9 px inside the stroke), settles between it and
# the ink's end, leaving the retrace's points < 2 px beyond it, below FIT_RETRACE_PAST levels,
# one above half as far: no pile-up was seen and the polygon stopped 2.01-2.31 px short (the same
# strokes without retrace 0.89-1.06). The tied point's own foot FIT_RETRACE_PAST levels in from
# the end is the retrace's mark (fit_ends.c piles_up): 0.98-1.13 px.
@pytest.mark.parametrize("seed", [11, 17, 21])
def test_a_discrete_fit_by_distance_reaches_an_end_retraced_by_a_few_noise_levels(seed):
    P, X0 = _stroke(seed, 9.0, 9.0)
    plain = np.round((X0 + np.random.default_rng(seed).normal(0, NOISE, X0.shape)) / QUANT) * QUANT
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = el.fit(P, model="discrete", distance="orthogonal")
        ref = el.fit(plain, model="discrete", distance="orthogonal")
    over, short = _gaps(r, P)
    ref_over, ref_short = _gaps(ref, plain)
    assert short < ref_short + 0.5, (short, ref_short)
    assert over < ref_over + 0.5, (over, ref_over)
    assert r.rms < 1.1 * ref.rms, (r.rms, ref.rms)
