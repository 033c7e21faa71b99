"""An elastic spline says the work its solve spent (el_spline_result's work / stopped):
chain evaluations over every path the search tried, and whether its budget (8 x max_steps x
max_iter evaluations) ended the search."""
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
    # search for a fair batten finds none within its budget (8 x 60 x 60 evaluations) and
    # returns the looping one it has, with the LoopWarning
    ring = np.array([[56.26748344186248, 17.920616218495244], [54.78961364864862, 22.790742388702352],
                     [31.633030185799896, 44.65575702035343], [0.17032025509748824, 36.05492430539231],
                     [-32.0353177414845, 42.58511436629945], [-52.65295419014353, 31.113439909769358],
                     [-54.9632004974034, 30.406003208858156], [-33.90587214378512, -15.022415440571152],
                     [-33.055426884852395, -14.676981402821989], [-5.843805737371669, -63.6270436682498],
                     [-4.109168261265303, -60.46901377128901], [31.35495602652135, -17.854245434541106]])
    h = np.hypot(*np.diff(ring, axis=0).T).max()
    with pytest.warns(el.LoopWarning):
        sp = el.elastic_spline(ring, tension=0.01 / h ** 2, closed=True)
    assert sp.stopped is True and sp.loops
    assert 8 * 60 * 60 <= sp.work <= 1.1 * 8 * 60 * 60
