"""What el.fit and el.elastic_spline say where G2 end conditions cannot be met (QA24 F7, F12)."""
import numpy as np
import pytest

import libelastica as el


def test_fit_held_g2_at_both_ends_points_to_the_g2_spline():
    # QA24 F7: all 8 G2 conditions are refused (documented) without naming the way that
    # joins G2 at both ends
    rng = np.random.default_rng(0)
    D = np.array([[0, 0], [10, 3], [20, 4], [30, 3.0]]).repeat(3, 0) + rng.normal(0, .01, (12, 2))
    with pytest.raises(el.ConstraintError) as e:
        el.fit(D, model="smooth", constraints=dict(start_point=(0, 0), end_point=(30, 3),
                                                   start_tangent=0.3, end_tangent=-0.1,
                                                   start_curvature=0, end_curvature=0.01))
    assert "el.elastic_spline(" in str(e.value) and "G2 at both ends" in str(e.value)


def test_spline_that_fails_names_its_g2_end():
    # QA24 F12: a G2 end of curvature 50 (radius 0.02) at a span 10 long: "no spline through
    # the points was reached" alone; the same end's tangent alone solves
    D = np.array([[0, 0], [10, 3], [20, 4], [30, 3.0]])
    with pytest.raises(el.NotConvergedError) as e:
        el.elastic_spline(D, end={"tangent": (1, -0.2), "curvature": 50.0})
    said = str(e.value)
    assert "end's G2 condition, curvature 50 (radius 0.02" in said
    assert "start's" not in said
    el.elastic_spline(D, end=(1, -0.2))       # (the tangent alone is met)
