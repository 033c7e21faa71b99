"""Elastic splines that cross themselves (issue 14): length mode prefers the fair spline of
the length asked, and the LoopWarning says where a spline returned crosses itself."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica.shape import self_crossings

# QA's ring77: 12 random ducks closed into a ring (tests/c/test_spline_reach.c's ring77)
RING77 = np.array([
    [1.114871201483529, 0.06296179947823506], [0.5268930130627169, 0.14471682098931363],
    [0.7002262459798201, 0.22878727946245084], [1.171136186509111, 0.7625165256147413],
    [-0.6232201739649377, 0.0006386487226305472], [-1.0328428299768375, -0.02805207981902149],
    [-0.4487961745896451, -0.31801768649958634], [-0.7908416001295514, -1.202444892387523],
    [-0.31667086307954834, -0.592213679706269], [-0.09621596250118901, -0.9049211859109808],
    [-0.08974183254317604, -1.042927207910349], [0.9393609599573067, -0.7763458991267597]])
SPIKE = np.array([[0, 0], [1, 0], [1.05, 1], [1.1, 0], [2, 0]], float)
# QA's rw15: a random walk of 11 ducks whose polygon crosses itself 5 times
RW15 = np.array([
    [6.616400999638113, 1.5793897344643046],
    [12.913887693559753, -7.012556293790113],
    [24.014298923337915, 7.492740308765932],
    [38.15916683121222, -2.9816848319514966],
    [26.424412522323138, -21.61096214123981],
    [33.28046827989525, -12.888399271506819],
    [30.4292999936489, -13.783904096357261],
    [39.162197945524696, -16.859823912884472],
    [19.065343852318783, -15.820341907608684],
    [15.92033581229428, -23.530964086146],
    [-10.603678162824576, -27.253507094704045]])


def _longest_side(p, closed):
    q = np.vstack([p, p[:1]]) if closed else p
    return float(np.hypot(*np.diff(q, axis=0).T).max())


def test_length_mode_prefers_the_fair_spline():
    """ring77 at the length of its fair spline at tension x (longest side)^2 = 20 (1.266 x
    its polygon): by that length the solve returned a spline crossing itself (20 -> 35.7,
    LoopWarning) though the fair one exists; now that one, silent."""
    h = _longest_side(RING77, True)
    fair = el.elastic_spline(RING77, tension=20.0 / h**2, closed=True)
    assert not fair.loops
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.LoopWarning)
        sp = el.elastic_spline(RING77, length=fair.length, closed=True)
    assert not sp.loops and self_crossings(sp.points(4000)) == 0
    assert sp.tension * h**2 == pytest.approx(20.0, rel=1e-6)
    assert sp.energy == pytest.approx(fair.energy, rel=1e-6)
    assert sp.length == pytest.approx(fair.length, rel=1e-12)


def test_loop_warning_names_the_crossing():
    """The spike's ducks below the least tension its fair family reaches: the spline returned
    loops within the span from duck 1 to 2 and across the next span; the warning says where
    (it named only the length before), and crossings() gives the spans."""
    with pytest.warns(el.LoopWarning, match=r"it crosses itself within the span from point 1 to 2, "
                                            r"where the spans from point 1 to 2 and from point 2 to 3 "
                                            r"cross, points counted from 0"):
        sp = el.elastic_spline(SPIKE, tension=0.125)
    assert sp.crossings() == [(1, 1), (1, 2)]
    # the spans named are where the samples cross: each crossing's segments lie in them
    assert self_crossings(sp.points(3000)) > 0
    fair = el.elastic_spline(SPIKE, tension=2.0)
    assert not fair.loops and fair.crossings() == []


def test_where_every_spline_loops_the_looping_one_is_flagged():
    """rw15 at tension x (longest span)^2 2 and 5: every spline the solver meets there loops
    round duck 7 (fair ones from ~18 up; by length fair only up to ~1.3 x the polygon), and
    the solve said NotConvergedError 'no spline through the points was reached'. Now the
    solver's searches judge candidates by the loop flag's own rule, and from nearby tensions
    the looping spline is reached: returned with loops and a LoopWarning naming the loop
    inside the span from duck 7 to 8."""
    h = _longest_side(RW15, False)
    for sh2 in (2.0, 5.0):
        with pytest.warns(el.LoopWarning, match="within the span from point 7 to 8"):
            sp = el.elastic_spline(RW15, tension=sh2 / h**2)
        assert sp.loops and (7, 7) in sp.crossings(), sh2
        assert sp.residual <= 1e-10
        assert np.allclose([p.x0 for p in sp.pieces], RW15[:-1, 0], atol=1e-9)


# QA's rw3: 7 ducks whose polygon does not cross, ducks 2 and 4 0.79 apart beside spans of
# 5 .. 17 (a turn of 171 degrees at duck 3): every spline found loops
RW3 = np.array([
    [13.525923883954862, 2.6961943657305354], [9.96683320319754, -7.6710872791900417],
    [4.253892293326146, -5.9684728814908343], [3.0360744530749209, -10.684577215358207],
    [4.9664251426859281, -6.3139600363014399], [18.495344105922491, -16.693455581918279],
    [25.276196270935831, -10.696206765695049]])


def test_where_the_polygon_does_not_cross_the_looping_one_is_flagged_too():
    """rw3 at tension x (longest span)^2 1: NotConvergedError 'no spline through the points
    was reached' though at 10 and 100 the spline found loops and says so. Where nothing
    is reached, the family from a taut start refused for looping is followed too (refair's
    loose pass): a looping spline of 5 x the polygon, flagged, with the LoopWarning, as at
    10."""
    h = _longest_side(RW3, False)
    for sh2 in (1.0, 10.0):
        with pytest.warns(el.LoopWarning):
            sp = el.elastic_spline(RW3, tension=sh2 / h**2)
        assert sp.loops and sp.residual <= 1e-10, sh2


# two random walks whose polygons cross themselves twice: C61 closed, W24 open
C61 = np.array([
    [0.38180803501383476, 2.4398859075439776], [0.47618295239741615, 1.9800329434256925],
    [0.6291614671336277, 0.6247011316098365], [1.1151455047432144, 0.5288874932557548],
    [1.4597446087350046, 0.9031227259018499], [0.4149537020418681, 2.233444365107266],
    [-0.5857171642742549, 3.135806800429161], [-2.1647929001981887, 3.5216840742559627],
    [-2.970357052340864, 3.5789286985380633], [-3.607071378437203, 1.4104536167684292]])


def test_a_spline_that_follows_its_crossing_polygon_is_unwarned():
    """C61's closed polygon crosses itself between spans 0 and 4 and 5 and 9; at tension x
    (longest span)^2 100 the solver returned a spline 1.33 x the polygon looping round duck
    9 (LoopWarning): its searches took every spline of such ducks as fair. Judged by the
    loop flag's rule they reach the one crossing only where its polygon does, 1.056 x."""
    from libelastica.shape import crossing_pairs
    q = np.vstack([C61, C61[:1]])
    assert crossing_pairs(q).tolist() == [[0, 4], [5, 9]]
    h = _longest_side(C61, True)
    poly = float(np.hypot(*np.diff(q, axis=0).T).sum())
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.LoopWarning)
        sp = el.elastic_spline(C61, tension=100.0 / h**2, closed=True)
    assert not sp.loops and sp.crossings() == [(0, 4), (5, 9)]
    assert sp.length < 1.1 * poly


def test_loops_where_the_polygon_crosses():
    """rw15's polygon crosses itself (spans 3-5, 3-6, 3-7, 4-6, 4-7), and loops was 0 for
    every spline of it; at tension x (longest span)^2 = 10 the spline crosses itself also
    between spans 6 and 7 (a loop around duck 7), which no crossing of the polygon matches:
    loops and a LoopWarning now say so."""
    from libelastica.shape import crossing_pairs
    h = _longest_side(RW15, False)
    assert crossing_pairs(RW15).tolist() == [[3, 5], [3, 6], [3, 7], [4, 6], [4, 7]]
    with pytest.warns(el.LoopWarning, match="from point 6 to 7 and from point 7 to 8"):
        sp = el.elastic_spline(RW15, tension=10.0 / h**2)
    assert sp.loops and (6, 7) in sp.crossings()


def test_a_figure_eight_that_follows_its_polygon_is_fair():
    """Ducks on a figure eight (open, and closed): the polygon crosses itself once and so does
    each spline, between the same spans; no LoopWarning. rw15 at tension x (longest
    span)^2 = 20: its spline crosses only where its polygon does, silent too."""
    t = np.linspace(0.0, 2.0 * np.pi, 9) + 0.3
    eight = np.c_[3.0 * np.sin(t), 1.6 * np.sin(t) * np.cos(t)]
    t = np.linspace(0.0, 2.0 * np.pi, 12, endpoint=False) + 0.3
    ring = np.c_[3.0 * np.sin(t), 1.6 * np.sin(t) * np.cos(t)]
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.LoopWarning)
        for pts, closed, pair in ((eight, False, (3, 7)), (ring, True, (5, 11))):
            h = _longest_side(pts, closed)
            for sh2 in (0.5, 10.0, 50.0):
                sp = el.elastic_spline(pts, tension=sh2 / h**2, closed=closed)
                assert not sp.loops and sp.crossings() == [pair], (closed, sh2)
        h = _longest_side(RW15, False)
        sp = el.elastic_spline(RW15, tension=20.0 / h**2)
    assert not sp.loops and sp.crossings() == [(3, 7), (4, 6), (4, 7)]
