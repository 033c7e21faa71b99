"""Fits made only to judge or compare (fit.judging_fit) skip el.fit's back-and-forth gate
(fit_retrace.py: a fit in curve order, curve_order ~3 ms on 1000 points, where the fit in
the points' order is a misfit): fit_keyline's one-elastica check fits an S by one elastica,
a misfit by design, which that gate refitted in curve order (a 1000-point scan's keyline
5.7 -> 23.8 ms, the README's figure at 187e56f). The user's own fits keep the gate."""
from __future__ import annotations

import numpy as np
import pytest

import libelastica as el
import libelastica.fit_retrace as fit_retrace
from keyline_data import keyline_3d


@pytest.fixture
def retrace_calls(monkeypatch):
    """Counts the gate's fits in curve order and its curve_order calls."""
    calls = {"retraced": 0, "curve_order": 0}
    retraced, curve_order = fit_retrace._retraced, fit_retrace.curve_order

    def counted_retraced(*args, **kwargs):
        calls["retraced"] += 1
        return retraced(*args, **kwargs)

    def counted_curve_order(*args, **kwargs):
        calls["curve_order"] += 1
        return curve_order(*args, **kwargs)
    monkeypatch.setattr(fit_retrace, "_retraced", counted_retraced)
    monkeypatch.setattr(fit_retrace, "curve_order", counted_curve_order)
    return calls


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_keyline_check_fit_passes_no_back_and_forth_gate(retrace_calls, model):
    """A 1000-point keyline scan (bench_fit.py's keyline figure, seeds 0-4: on main the gate
    refitted the check's fit in curve order on seeds 3 and 4, 1-2 times a keyline): its
    one-elastica check (_check_keyline_split) is a verdict, fitted without the gate; the
    keyline found."""
    kf = el.fit_keyline(keyline_3d(n=1000, seed=3).xyz, model=model)
    assert retrace_calls == {"retraced": 0, "curve_order": 0}
    assert kf.joint is not None


def test_misfit_corner_parts_pass_no_back_and_forth_gate(retrace_calls):
    """misfit's corner search fits each candidate's two parts (smooth) to judge them: no
    gate. Points of two arcs meeting at a corner: the verdict names the corner."""
    t = np.linspace(0.0, 1.0, 200)
    a = np.column_stack([50.0 * np.cos(np.pi * (1 - t)), 50.0 * np.sin(np.pi * (1 - t))])
    b = np.column_stack([50.0 + 40.0 * t, -60.0 * t])
    pts = np.concatenate([a, b[1:]]) + np.random.default_rng(3).normal(0.0, 0.05, (399, 2))
    d = el.fit(pts, model="smooth", check_misfit=False).distances
    assert retrace_calls["retraced"] <= 1          # (the user's fit above may take its gate)
    before = dict(retrace_calls)
    m = el.misfit(pts, d)
    assert m is not None and abs(m.corner - 199) <= 10
    assert retrace_calls == before


def test_users_fit_keeps_the_gate(retrace_calls):
    """el.fit of a scan passed back and forth (test_fit_retrace's QA20 F4 shape) still takes
    the gate: fitted in curve order, as before."""
    s = np.concatenate([np.linspace(0.0, 1.0, 300), np.linspace(1.0, 0.0, 300)])
    xy = np.column_stack([1500.0 * s, 200.0 * np.sin(2.0 * s)])
    xy = xy + np.random.default_rng(1).normal(0.0, 0.4, xy.shape)
    with pytest.warns(el.OrderWarning):
        el.fit(xy, model="smooth")
    assert retrace_calls["retraced"] == 1
