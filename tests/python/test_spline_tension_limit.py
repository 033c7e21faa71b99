"""Elastic splines under a tension beyond what double precision resolves (elastica.h,
Accuracy): the error names the highest tension the search solved the points at (no bound), and why."""
from __future__ import annotations

import os

import numpy as np
import pytest

import libelastica as el

DUCKS = el.io.read_points(os.path.join(os.path.dirname(__file__), "..", "..", "examples",
                                       "ducks.csv"), 2)


@pytest.mark.parametrize("sh2", [700.0, 1000.0])
def test_too_high_a_tension_names_the_largest_that_solves(sh2):
    """examples/ducks.csv at tension x (longest span)^2 700 and 1000: no spline (its longest
    span's piece has 1 - k^2 ~ 4e-10 there, which a double resolves only in steps of
    4.4e-16); the error said only how random sketches fare. Now it names the largest
    tension that solves these ducks (~520 x span^-2: resolution 4e-7, its residual within
    1e-7), and that tension does solve, fair."""
    h2 = float(np.hypot(*np.diff(DUCKS, axis=0).T).max()) ** 2
    with pytest.raises(el.NotConvergedError, match=r"the highest tension the search solved "
                                                   r"them at is ~[0-9.]+ \(x \(longest span\)"
                                                   r"\^2 = 5\d\d; it found none above it.*no "
                                                   r"bound\).*elliptic modulus k") as e:
        el.elastic_spline(DUCKS, tension=sh2 / h2)
    largest = e.value.largest_tension
    assert 450.0 <= largest * h2 <= 560.0
    sp = el.elastic_spline(DUCKS, tension=largest)
    assert not sp.loops and sp.residual <= 1e-7


def test_the_largest_tension_named_is_no_bound():
    """The search's highest solving tension is not a bound, and the message says so (it
    said 'give a tension up to it'): near it the solve is not monotone. examples/ducks.csv x
    100 at tension x span^2 700: the search names 0.0088357; of 41 tensions within 1 % of
    it, 12 fail, either side (0.993 .. 0.9995 and 1.0065 .. 1.009 of it; 0.00883 typed back
    from '0.00883' fails, 0.00884 solves)."""
    ducks = 100.0 * DUCKS
    h2 = float(np.hypot(*np.diff(ducks, axis=0).T).max()) ** 2
    with pytest.raises(el.NotConvergedError, match="no bound") as e:
        el.elastic_spline(ducks, tension=700.0 / h2)
    assert "up to it" not in str(e.value)
    largest = e.value.largest_tension
    assert not el.elastic_spline(ducks, tension=largest).loops     # it solves
    with pytest.raises(el.NotConvergedError):                      # just below: not
        el.elastic_spline(ducks, tension=0.999 * largest)
