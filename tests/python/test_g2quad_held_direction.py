"""A held tangent means the same direction: an end or inflection of the G2 quadratic said to
hold the source's tangent runs along it, not against it. g2ends._slide_x1 took any sign
change of its residual for a root: of _match_tangent's angle (atan2, in (-pi, pi]) that
included the wrap at pi, where the start leg points backwards, so a piece was reported held
(no EndTangentWarning, the joint's vertices moved) while leaving the source's tangent at 180
deg. Constructed here: samples of an S whose tangents at the ends, or at the inflection, point
against the points' order (a stroke's ends drawn backwards)."""
import math
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica import g2ends as G

QA_S = el.SmoothElastica(x0=1500, y0=-800, phi=0.3, mu=(1 / 120.0) ** 2, k=0.6, q=0.2,
                         length=380.0)


def _samples(n):
    s = np.linspace(0, QA_S.length, 20 * n + 1)
    th = QA_S.angle(s)
    return s, QA_S.points(s), np.c_[np.cos(th), np.sin(th)]


def _build(P, n, **kw):
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        g = el.g2_quadratic(P, n, **kw)
    return g, [w.message for w in said]


@pytest.mark.parametrize("n", [12, 24, 48])
def test_reversed_end_tangents_are_not_held(n):
    """Free ends (end curvature 0: the tangent held alone, _match_tangent) whose tangents point
    backwards: before, both 'held' at 180 deg, silently; now each said by EndTangentWarning."""
    s, P, T = _samples(n)
    T[[0, -1]] *= -1.0
    g, said = _build(P, n, tangents=T, end_curvatures=(0.0, 0.0))
    miss = [w for w in said if isinstance(w, el.EndTangentWarning)]
    assert len(miss) == 1 and [m[0] for m in miss[0].misses] == ["start", "end"]
    assert all(math.degrees(a) > 170 for _, a in miss[0].misses)
    assert math.degrees(g.source_end_tangent_error) > 170
    # the same ends the right way round: held (~1e-13), unwarned
    g, said = _build(P, n, tangents=_samples(n)[2], end_curvatures=(0.0, 0.0))
    assert g.source_end_tangent_error < 1e-9 and not said


@pytest.mark.parametrize("n", [12, 24, 48])
def test_a_reversed_inflection_tangent_holds_no_joint(n):
    """The tangent at the inflection's sample reversed: no end holds it (both were slid to run
    backwards along it, inflection_tangent_error 180 deg); the joint is left as the plain
    build's, and named in unheld_joints."""
    s, P, T = _samples(n)
    i = int(np.argmin(np.abs(s - el.affine.elastica_inflections(QA_S)[0])))
    T[i] *= -1.0
    g, _ = _build(P, n, tangents=T)
    ok, _ = _build(P, n, tangents=_samples(n)[2])
    assert ok.join_angle < 1e-12 and g.join_angle > 1e-6
    assert math.degrees(g.inflection_tangent_error) > 170
    ((j, angle, why),) = g.unheld_joints
    assert j == 1 and angle == g.join_angle and why == "no end found that holds the tangent there"


def test_match_tangent_finds_no_root_at_the_wrap():
    """_match_tangent asked for the reverse of an end's own tangent: None (the leg at pi is
    atan2's wrap, no root); asked for the end's tangent: a leg along it, angle ~0 (mod 2 pi)."""
    n = 24
    s, P, T = _samples(n)
    ap = el.affine_polyline(P, n, tangents=T)
    x = ap.points[:ap.piece_start[1] + 1]
    end = P[int(ap.infl_param[0])]
    assert G._match_tangent(x, P[0], end, -T[0]) is None
    y = G._match_tangent(x, P[0], end, T[0])
    d = el.g2_bspline(y, P[0], end).poles[1] - P[0]
    assert abs(G._angle(d[0], d[1], T[0])) < 1e-9 and d @ T[0] > 0
