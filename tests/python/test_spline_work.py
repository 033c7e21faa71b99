"""An elastic spline says the work its call spent (el_spline_result's work / stopped):
chain evaluations over every solve and search it made, and whether its budget (one for the
call, max_steps x max_iter x (16 + 64 / m) evaluations for m pieces) ended it."""
import numpy as np
import pytest

import libelastica as el


def test_a_spline_says_its_work_and_whether_the_budget_ended_it():
    # five hand-placed ducks, by tension and by length: solved well within the budget
    ducks = np.array([[0, 0], [1, 0.4], [2, 0.1], [3.2, 0.8], [4, 0]], dtype=float)
    for kw in (dict(tension=0.5), dict(length=5.0)):
        sp = el.elastic_spline(ducks, **kw)
        assert isinstance(sp.work, int) and isinstance(sp.stopped, bool)
        assert 0 < sp.work < 8 * 60 * 60
        assert sp.stopped is False
        # each Newton iteration evaluates the chain at least once
        assert sp.work >= sp.iterations


def test_a_search_the_budget_ended_says_so():
    # a closed ring of 12 uneven ducks at sigma h^2 0.01 (the spline sweep's #325): the
    # search for a fair batten finds none (32 793 evaluations at the defaults, within their
    # budget 3600 x (16 + 64 / 12) = 76 800); at 30 x 30 the budget, 900 x (16 + 64 / 12) =
    # 19 200, ends it and the looping one it has is returned, with the LoopWarning
    ring = np.array([[56.26748344186248, 17.920616218495244], [54.78961364864862, 22.790742388702352],
                     [31.633030185799896, 44.65575702035343], [0.17032025509748824, 36.05492430539231],
                     [-32.0353177414845, 42.58511436629945], [-52.65295419014353, 31.113439909769358],
                     [-54.9632004974034, 30.406003208858156], [-33.90587214378512, -15.022415440571152],
                     [-33.055426884852395, -14.676981402821989], [-5.843805737371669, -63.6270436682498],
                     [-4.109168261265303, -60.46901377128901], [31.35495602652135, -17.854245434541106]])
    h = np.hypot(*np.diff(ring, axis=0).T).max()
    with pytest.warns(el.LoopWarning):
        sp = el.elastic_spline(ring, tension=0.01 / h ** 2, closed=True, max_iter=30, max_steps=30)
    assert sp.stopped is True and sp.loops
    # no search past it; a known state's re-evaluation is let through (el__chain_reeval:
    # the pieces' figures are then those of the spline returned), a few at most (2 here)
    budget = 900 * 16 + 900 * 64 // 12
    assert budget <= sp.work <= budget + 8


def test_an_error_the_budget_caused_says_so():
    # 7 sketched ducks by length 22: solved at the defaults; at 3 x 3 the budget (240) ends the
    # search and the error named lengths "met" as if no other were reachable
    pts = np.array([[0, 0], [3, 1], [6, 0.5], [9, 2.2], [12, 1.1], [14, 3.4], [17, 2.9]], float)
    assert el.elastic_spline(pts, length=22.0).stopped is False
    with pytest.raises((el.NotConvergedError, el.LengthRangeError)) as info:
        el.elastic_spline(pts, length=22.0, max_iter=3, max_steps=3)
    assert "work budget" in str(info.value) and "max_iter" in str(info.value)
    # and says so as an attribute (FreeCAD's feature reads it rather than the message)
    assert info.value.stopped is True and info.value.work > 0


def test_an_error_the_budget_did_not_cause_says_not_stopped():
    # test_spline.py's G2 blend between two edges at a tension no G2 blend has: its search
    # ends within the budget, stopped False (the cause is the tension, not the budget)
    p = np.array([[20.0, 20.0], [90.0, 60.0]])
    with pytest.raises(el.NotConvergedError) as info:
        el.elastic_spline(p, tension=0.01, start={"tangent": (0, 1), "curvature": 0.05},
                          end={"tangent": (1, 0), "curvature": 0.0})
    assert info.value.stopped is False and 0 < info.value.work < 3600 * (16 + 64)


def test_what_the_units_cannot_represent_is_refused_with_its_cause():
    # el_spline_solve's EL_EDOM before any search (spline.c's UNITS): the mean chord S outside
    # [1e-150, 1e150], tension x S^2 or a G2 end's |curvature| x S above 1e150 (the fuzz's
    # collinear ducks at 1e300, a G2 end of curvature 1.8e308); the message names the cause
    # (the points' mean chord, with their chords and coordinates), not the tension-0 batten
    # sliding off its ducks that EL_EDOM says otherwise
    line = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 4.0], [3.0, 6.0]])
    g2 = {"tangent": (1.0, 0.2), "curvature": 1e307}
    scale = r"mean chord .* \(chords from .*\) is outside \[1e-150, 1e150\].* rescale the points"
    cases = [(dict(points=line * 1e300, tension=42.3), scale), (dict(points=line * 1e-300), scale),
             (dict(points=line * 1e80, tension=1e-9), r"tension 1e-09 x \(mean chord"),
             (dict(points=line, tension=1e307), "tension"),
             (dict(points=line, length=20.0, end=g2), "end curvature"),
             (dict(points=line, start=g2), "start curvature"),
             # points the solver represents (1e+-120 solve), the tension or curvature not:
             # the cause named, not the points' range
             (dict(points=line * 1e120, tension=1.0), r"tension 1 x \(mean chord"),
             (dict(points=line * 1e-120, start={"tangent": (1.0, 0.2), "curvature": 1e275}),
              "start curvature"),
             # a length over the mean chord past 1e150 (here inf in the solver's units: the
             # free batten, 1e-320 of it, came back as the spline)
             (dict(points=line * 1e-20, length=1e300), r"length 1e\+300 / \(mean chord")]
    for kw, cause in cases:
        with pytest.raises(el.DomainError, match=cause) as e:
            el.elastic_spline(**kw)
        assert "slides" not in str(e.value)
    # just inside: solved as any spline (the points' scale 1e150 is their mean chord)
    sp = el.elastic_spline(np.array([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]) * 1e150)
    assert len(sp.pieces) == 2
    assert el.elastic_spline(line * 1e120, tension=1e-245).tension == 1e-245
