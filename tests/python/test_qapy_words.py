"""What the library says to a Python user with measured curves (QA qapy's findings F1, F9):
refusals that say why and advice that can be followed."""
from __future__ import annotations

import warnings

import numpy as np
import pytest

import libelastica as el
from cli_run import cli


def _outline():
    """QA F1's closed tile section, 150 x 20, its turning changing sign 4 times."""
    a = np.linspace(0, 2 * np.pi, 120, endpoint=False)
    o = np.c_[150 * np.cos(a), 20 * np.sin(a) + 10 * np.sin(2 * a)]
    return np.r_[o, o[:1]]


def test_a_closed_outline_is_refused_as_closed_not_as_turning_one_way():
    """fit_keyline said 'no inflection found: the points turn one way' of an outline that turns
    both ways 4 times, find_inflection the bare 'input outside the domain the method covers'."""
    o = _outline()
    for call in (lambda: el.fit_keyline(o, model="smooth"), lambda: el.fit_keyline(o),
                 lambda: el.find_inflection(o)):
        with pytest.raises(el.DomainError) as exc:
            call()
        said = str(exc.value)
        assert "closed outline" in said and "changes sign 4 times" in said, said
        assert "turn one way (" not in said and "outside the domain" not in said
        assert "open pieces with one inflection each" in said and "points[i:j]" in said


def test_the_closed_misfit_advice_does_not_send_the_user_to_fit_keyline_whole():
    o = _outline()
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        el.fit(o, model="smooth")
    said = [str(x.message) for x in w if issubclass(x.category, el.MisfitWarning)]
    assert said and "nearly closed" in said[0]
    assert "(a keyline, fit_keyline, or more)" not in said[0]
    assert "open pieces (points[i:j])" in said[0] and "one inflection each (fit_keyline)" in said[0]
    # and the advice works: an open piece with one inflection fits as a keyline
    assert el.fit_keyline(o[10:60], model="smooth").input_rms < 0.1


def test_open_refusals_stay_true():
    a = np.linspace(0, 2, 100)
    with pytest.raises(el.DomainError, match="no inflection found: the points turn one way"):
        el.find_inflection(np.c_[np.cos(a), np.sin(a)])
    with pytest.raises(el.DomainError, match="on a line"):
        el.find_inflection(np.c_[a, 2 * a])


def test_no_degrees_of_freedom_is_said_once_and_true(tmp_path, capsys):
    """5 points, discrete: 'std errors k=0.89 +- inf, ...' then 'no degrees of freedom left (7
    residuals, 7 parameters): standard errors NaN' (QA F9): inf and NaN for one thing."""
    f = tmp_path / "five.csv"
    f.write_text("x,y\n0,0\n1,1\n2,3\n3,3\n4,5\n")
    code, out, _ = cli(capsys, "fit", f)
    assert code == 0
    lines = [s for s in out.splitlines() if "std errors" in s or "degrees of freedom" in s]
    assert lines == ["std errors  none: no degrees of freedom left (5 points give 7 residuals, "
                     "the end points 2 each, for 7 parameters)"], out
    assert "+- inf" not in out
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        u = el.fit(np.loadtxt(f, delimiter=",", skiprows=1)).uncertainty()
    assert u.dof == 0 and "5 points give 7 residuals" in u.note


# QA F2's ship line: 30 uneven points along a 9000 mm elastica, noise 1.5 mm, 0.1 mm rounding
SHIP = np.array([(11997.6, 3503.2), (12128.7, 3635.7), (12133.3, 3637.3), (12235.5, 3755.6),
                 (12311.4, 3842.9), (12391.3, 3950.3), (12738.9, 4483.7), (12783.2, 4565.9),
                 (13798.2, 6354.7), (13829.1, 6392.4), (13990.4, 6596.3), (14229.9, 6837.3),
                 (14475.1, 7042.5), (14484.6, 7052.3), (14687.6, 7187.2), (14739.4, 7216.8),
                 (15184.4, 7413.6), (15474.8, 7482.0), (15588.4, 7500.2), (15783.0, 7517.4),
                 (16088.0, 7512.1), (16144.4, 7502.0), (17082.6, 7179.7), (17089.8, 7178.5),
                 (17678.9, 6722.6), (17815.2, 6580.1), (17973.6, 6405.1), (18114.0, 6229.0),
                 (18326.2, 5935.7), (18380.9, 5858.2)])


@pytest.mark.parametrize("n", [12, 20, 24])
def test_a_sparse_ship_line_says_the_smooth_model_fits_it_better(n):
    """The default (discrete) fit's exported cubic lay 2.79 / 5.83 mm (rms / max) from the 24
    points, the smooth curve 1.54 / 2.36, and no SparseWarning fired (a ratio of 1.8, the rule
    asked 2). At 30 points (2.50 against 1.49) it is not asked: from SPARSE_POINTS = 25 on no
    smooth fit is run (its cost, cubic.py)."""
    pts = SHIP[:n]
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        r = el.fit(pts)
    said = [str(x.message) for x in w if issubclass(x.category, el.SparseWarning)]
    assert len(said) == 1 and "use model='smooth'" in said[0], [str(x.message) for x in w]
    smooth = el.fit(pts, model="smooth")
    assert r.sparse == pytest.approx(smooth.rms)
    cubic = np.sqrt(np.mean(r.cubic_distances()[1] ** 2))
    from libelastica.cubic import SPARSE_RATIO
    assert cubic > SPARSE_RATIO * smooth.rms


def test_a_dense_discrete_fit_asks_for_no_smooth_fit():
    """At and above SPARSE_POINTS no smooth fit is run: a clean discrete curve of that many
    vertices fits itself, without a word."""
    d = el.DiscreteElastica(x0=0, y0=0, h=1.0, phi=0.2, z=0.05, q=0.3, k=0.8, n=el.SPARSE_POINTS)
    with warnings.catch_warnings():
        warnings.simplefilter("error", el.SparseWarning)
        assert el.fit(d.points()).sparse is None
