"""out_of_order's screen in C (el_order_screen, issue 16 target 2: el.fit runs it on every
call; its numpy formulas took ~27 us of a 0.6 ms fit): the C screen against the numpy
formulas it replaced (the points' extent, the every-k-th polyline's length and mean |turn|
a vertex, the whole polyline's length), and out_of_order's answers against the numpy
out_of_order it replaced, on ordered, shuffled, coiled, 3-D and degenerate sets."""
import importlib
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica import order as O

FC = importlib.import_module("libelastica._fit_call")
from libelastica._ffi import dptr, ffi, lib

# numpy's atan2 is vectorised (SVML on AVX-512): an ulp or two from glibc's; its sums of
# more than 8192 terms (numpy < 2) are blocked: an ulp from one pairwise sum
ULPS = 4


# ------------------------------------------------------------ the numpy formulas replaced

def np_length(xy):
    d = xy[1:] - xy[:-1]
    return float(np.sqrt(np.einsum("ij,ij->i", d, d)).sum())


def np_turn(xy):
    d = xy[1:] - xy[:-1]
    a, b = d[:-1], d[1:]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)     # the mean of nothing: nan
        return float(np.mean(np.abs(np.arctan2(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0],
                                               np.einsum("ij,ij->i", a, b)))))


def np_extent(xy):
    cols = xy.T.copy()
    return float((cols.max(axis=1) - cols.min(axis=1)).max())


def np_out_of_order(points, ratio=O.ORDER_RATIO, screen=True):
    """out_of_order as it was (9d00460), numpy throughout."""
    xy = O._plane_points(points, "out_of_order")
    if len(xy) < 3:
        return O.Ordering(None, np_length(xy), float("nan"))
    extent = np_extent(xy)
    step = len(xy) // O.SCREEN_POINTS if screen and len(xy) >= O.SCAN_POINTS else 1
    if step > 1:
        sc = xy[::step]
        if not np_length(sc) > ratio * extent or not np_turn(sc) > O.TURN_PER_VERTEX:
            return O.Ordering(None, float("nan"), float("nan"))
    given = np_length(xy)
    if not given > ratio * extent:
        return O.Ordering(None, given, float("nan"))
    order = O.curve_order(xy)
    along = np_length(xy[order])
    if screen and given > ratio * along and not np_turn(xy) > O.TURN_PER_VERTEX:
        return O.Ordering(None, given, along)
    return O.Ordering(order if given > ratio * along else None, given, along)


def screen(xy, step, turn=True):
    out = ffi.new("el_order_screen_result *")
    assert lib.el_order_screen(dptr(xy), len(xy), step, int(turn), out) == lib.EL_OK
    return out


def close(a, b, ulps=0):
    """a == b (both nan counts), or within ulps units in the last place of b."""
    if np.isnan(a) or np.isnan(b):
        return bool(np.isnan(a) and np.isnan(b))
    return a == b or abs(a - b) <= ulps * np.spacing(abs(b))


# ------------------------------------------------------------ point sets

def curve(n, rng, turns=0.3, noise=0.0):
    t = np.linspace(0.0, 2 * np.pi * turns, n)
    r = 1 + 0.05 * t
    P = np.c_[r * np.cos(t), r * np.sin(t)] * 10 ** rng.uniform(-3, 3)
    return P + rng.normal(0.0, noise * np.ptp(P, axis=0).max(), P.shape)


def sets(rng):
    """(name, points): in order, shuffled, coils (in order and shuffled), sparse and
    dense, n from 3 to 1e5, and the degenerate: repeated points, collinear, n < 3, n
    exactly SCAN_POINTS."""
    for n in (3, 4, 7, 8, 9, 17, 60, 129, O.SCAN_POINTS - 1, O.SCAN_POINTS, O.SCAN_POINTS + 1,
              257, 1000, 4099, 20000, 100000):
        for noise in (0.0, 0.01):
            P = curve(n, rng, 0.3, noise)
            yield f"arc{n}/{noise}", P
            yield f"shuffled{n}/{noise}", P[rng.permutation(n)]
            C = curve(n, rng, 3.0, noise)
            yield f"coil{n}/{noise}", C
            yield f"shuffled-coil{n}/{noise}", C[rng.permutation(n)]
    for n in (1, 2, 3, O.SCAN_POINTS, 1000):
        yield f"repeated{n}", np.tile([[1.5, -2.0]], (n, 1))
        yield f"collinear{n}", np.c_[np.arange(n), 2 * np.arange(n)] * 0.1
        yield f"collinear-back{n}", np.c_[rng.permutation(n), np.zeros(n)].astype(float)
        yield f"random{n}", rng.normal(size=(n, 2))
    P = curve(500, rng, 0.5, 0.001)
    yield "pairs-repeated", np.repeat(P, 2, axis=0)


def steps(n):
    return sorted({1, 2, 3, 8, max(1, n // O.SCREEN_POINTS), max(1, n - 1), n + 5})


def test_the_c_screen_is_the_numpy_formulas():
    rng = np.random.default_rng(16)
    checked = 0
    for name, P in sets(rng):
        xy = np.ascontiguousarray(P, dtype=float)
        for step in steps(len(xy)):
            s, sc = screen(xy, step), xy[::step]
            assert s.extent == np_extent(xy), (name, step)
            assert close(s.length, np_length(sc), ULPS), (name, step, s.length, np_length(sc))
            assert close(s.turn, np_turn(sc), ULPS), (name, step, s.turn, np_turn(sc))
            assert np.isnan(screen(xy, step, turn=False).turn)
            checked += 1
    assert checked > 500


@pytest.mark.parametrize("dim", (2, 3))
def test_out_of_order_answers_as_the_numpy_one(dim, monkeypatch):
    rng = np.random.default_rng(17 + dim)
    answers, calls = set(), []
    real = O._screen
    monkeypatch.setattr(O, "_screen", lambda xy, step, turn: calls.append(step) or real(xy, step, turn))
    # curve_order (the order both answers give, not what they differ in) is deterministic:
    # once a point set, not four times (both answers, screened or not: 3/4 of the test's time)
    orders, order_of = {}, O.curve_order

    def curve_order(xy, *args, **kwargs):
        key = (xy.shape, xy.tobytes(), args, tuple(sorted(kwargs.items())))
        if key not in orders:
            orders[key] = order_of(xy, *args, **kwargs)
        return orders[key].copy()
    monkeypatch.setattr(O, "curve_order", curve_order)
    for name, P in sets(rng):
        if len(P) > 20000:
            continue        # curve_order of a shuffled 1e5: seconds; the screen is checked above
        if dim == 3:        # tilted out of the xy plane, off the origin
            if len(P) < 3 or np.ptp(P, axis=0).min() == 0.0:
                continue    # plane_fit refuses collinear or equal points alike both ways
            a = rng.uniform(0, np.pi)
            R = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
            P = np.c_[P, rng.normal(0.0, 1e-6, len(P))] @ R.T + rng.uniform(-50, 50, 3)
        for scr in (True, False):
            got, want = el.out_of_order(P, screen=scr), np_out_of_order(P, screen=scr)
            assert (got.order is None) == (want.order is None), (name, scr)
            if got.order is not None:
                assert np.array_equal(got.order, want.order), (name, scr)
            assert close(got.given, want.given, ULPS) and close(got.along, want.along, ULPS), \
                (name, scr, got, want)
            answers.add((got.order is None, np.isnan(got.given), np.isnan(got.along)))
    # every branch taken: screened in order, within the extent, measured in order, flagged
    assert answers >= {(True, True, True), (True, False, True), (False, False, False)}, answers
    assert len(calls) > 100         # measured by the C screen


def test_fit_checks_the_order_through_the_c_screen(monkeypatch):
    """el.fit's check is the C screen (one el_order_screen of every k-th point on 1000
    noisy points in order: inside el_binding_fit's one call, _fit_call.py, else through
    order._screen), answered as before: no OrderWarning in order, one shuffled."""
    rng = np.random.default_rng(5)
    P = curve(1000, rng, 0.3, 0.002)
    calls = []
    real = O._screen
    monkeypatch.setattr(O, "_screen", lambda xy, step, turn: calls.append(step) or real(xy, step, turn))
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.OrderWarning)
        el.fit(P, distance="paired")
    assert calls == ([] if FC._ONE_CALL is not None else [1000 // O.SCREEN_POINTS])
    with pytest.warns(el.OrderWarning):
        el.fit(P[rng.permutation(1000)], distance="paired")


def test_the_c_screen_refuses_bad_input():
    xy = np.zeros((5, 2))
    out = ffi.new("el_order_screen_result *")
    out.extent = 7.0
    for args in ((ffi.NULL, 5, 1, 1, out), (dptr(xy), 0, 1, 1, out), (dptr(xy), 5, 0, 1, out),
                 (dptr(xy), 5, 1, 1, ffi.NULL)):
        assert lib.el_order_screen(*args) == lib.EL_EINVAL
    xy[3, 1] = np.nan
    assert lib.el_order_screen(dptr(xy), 5, 1, 1, out) == lib.EL_EINVAL
    assert out.extent == 7.0        # untouched on error
