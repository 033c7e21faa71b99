"""g2_quadratic far from the origin (survey coordinates): the result at the offset is the
origin's translated, to what its own coordinates resolve (half an ulp of the offset) plus
rounding of the curve's size, and as G2 as at the origin (g2quad_points._local_origin; the
C polyline's own local origin: tests/c/test_affine_offset.c)."""
import warnings

import numpy as np
import pytest

import libelastica as el

OFF = np.array([512345.678, 5012345.432])
HALF_ULP = 0.5 * np.spacing(OFF)        # the offset result's own rounding, per coordinate


def _build(src, n, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.EndTangentWarning)
        return el.g2_quadratic(src, n, **kw)


def _apart(g_far, g_near, shift):
    """How far g_far's poles, polyline and ends less ``shift`` are from g_near's, beyond
    HALF_ULP, relative to g_near's size; and the largest relative knot difference."""
    size = float(np.max(np.ptp(g_near.polyline.points, axis=0)))
    assert len(g_far.bsplines) == len(g_near.bsplines)
    d = [np.abs(g_far.polyline.points - shift - g_near.polyline.points) - HALF_ULP,
         np.abs(np.asarray(g_far.ends) - shift - np.asarray(g_near.ends)) - HALF_ULP]
    dk = 0.0
    for bf, bn in zip(g_far.bsplines, g_near.bsplines):
        d.append(np.abs(bf.poles - shift - bn.poles) - HALF_ULP)
        assert np.array_equal(bf.mults, bn.mults)
        dk = max(dk, float(np.max(np.abs(bf.knots - bn.knots) / np.maximum(np.abs(bn.knots), 1))))
    return max(float(np.max(x)) for x in d) / size, dk


@pytest.mark.parametrize("with_tangents", [False, True])
def test_points_at_a_survey_offset_give_the_origins_result_translated(with_tangents):
    # main: poles 3.7e-7 of the size off the translate, curvature jumps 2.2e-7, end curvature
    # 1.2e-7 off (the C polyline and g2ends computed in the offset's 9.3e-10 ulps)
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=0.4, mu=1.0, k=0.7, q=0.2, length=3.0)
    s = np.linspace(0.0, c.length, 401)
    far = c.points(s) + OFF
    near = far - OFF                     # exact (Sterbenz): the same samples
    th = c.angle(s)
    tan = np.c_[np.cos(th), np.sin(th)] if with_tangents else None
    g_far, g_near = _build(far, 16, tangents=tan), _build(near, 16, tangents=tan)
    apart, dk = _apart(g_far, g_near, OFF)
    # (measured 1.7e-12 and 4.6e-11: the two compute in frames (OFF - R) apart, and the knots'
    # end intervals follow t1, the minimiser of a flat psi; main 1.4e-7 and 4.7e-7)
    assert apart <= 1e-11 and dk <= 2e-10, (apart, dk)
    assert g_far.curvature_jump <= 1e-12 and g_near.curvature_jump <= 1e-12
    assert g_far.end_curvature_error <= 1e-11
    assert abs(g_far.deviation - g_near.deviation) <= 1e-11 * c.length   # (7.6e-14 measured)


@pytest.mark.parametrize("source", ["curve", "spline", "closed"])
def test_curves_at_a_survey_offset_give_the_origins_result_translated(source):
    # the curve at the offset evaluated in a local frame (its start(s) moved, exactly):
    # main 5.4e-7 / 8.5e-7 / 2e-6 of the size off, jumps to 1.6e-6, a closed spline's seam
    # 1.8e-9 relative (median of 20)
    if source == "curve":
        kw = dict(phi=-1.0, mu=4.0, k=0.8, q=0.3, length=2.0)
        near = el.SmoothElastica(x0=0.0, y0=0.0, **kw)
        far = el.SmoothElastica(x0=OFF[0], y0=OFF[1], **kw)
        n = 24
    else:
        closed = source == "closed"
        t = np.linspace(0.0, 2 * np.pi, 7)[:-1] if closed else np.linspace(0.0, 3.0, 5)
        pts = (np.c_[13 * np.cos(t), 10 * np.sin(t)] if closed
               else np.c_[12 * t, 3 * np.sin(2 * t)])
        near = el.elastic_spline(pts, closed=closed)
        far = el.elastic_spline(pts + OFF, closed=closed)
        n = 48
    g_far, g_near = _build(far, n), _build(near, n)
    apart, dk = _apart(g_far, g_near, OFF)
    # the sources themselves differ: el.elastic_spline solved at the offset (its C solve in
    # the offset's ulps: ~1e-9 of the size apart), SmoothElastica's start rounded there
    tol = 1e-11 if source == "curve" else 1e-9
    # (measured 5e-13, 1.9e-10, 3.1e-11 apart; knots 2.4e-12, 1.7e-9, 1.8e-10)
    assert apart <= tol and dk <= 20 * tol, (apart, dk)
    assert g_far.curvature_jump <= 1e-12, g_far.curvature_jump
    if source == "closed":
        assert g_far.seam_is_g2 and g_far.seam_curvature_jump <= 1e-12, g_far.seam_curvature_jump


def test_near_the_origin_nothing_is_moved():
    # a curve within 16 extents of (0, 0) in both coordinates is built as before: the same bits
    from libelastica.g2quad_points import _local_origin
    assert not np.any(_local_origin(np.array([[0.0, 0.0], [3.0, 4.0]]) + 60.0))
    R = _local_origin(np.array([[0.0, 0.0], [3.0, 4.0]]) + OFF)
    assert np.all(R % 4.0 == 0.0) and np.all(np.abs(R - OFF) <= 2.0)



def test_a_warning_at_a_survey_offset_names_the_callers_line():
    # the local build's warnings are said again at the caller of g2_quadratic, the line the
    # origin's name (they named the caller's caller: stacklevel one frame too far)
    t = np.linspace(0, 2 * np.pi, 10, endpoint=False)
    r = 30 + 8 * np.cos(2 * t)
    pts = np.c_[1.2 * r * np.cos(t), r * np.sin(t) - 14 * np.cos(t) ** 2 * (np.sin(t) > 0)]
    where = []
    for src in (pts, pts + OFF):    # the bean of test_g2quad_seam: warned at its seam
        sp = el.elastic_spline(src, closed=True)
        with warnings.catch_warnings(record=True) as said:
            warnings.simplefilter("always")
            el.g2_quadratic(sp, 24)
        assert said
        where.append({(w.filename, w.lineno) for w in said})
    assert where[0] == where[1] and {f for f, _ in where[1]} == {__file__}, where


def test_a_closed_seam_at_a_survey_offset_is_judged_on_the_poles_handed_back():
    # the seam figures are the local build's (~1e-14), the poles handed back carry the
    # offset's rounding: seam_bound covers what they resolve (a 1.3 x 1 oval, 64 edges:
    # 6.4e-9 relative measured on them against a bound of 1e-9 before)
    from libelastica.g2ends import _joins
    t = np.linspace(0.0, 2 * np.pi, 9)[:-1]
    for scale in (1.0, 0.05):
        g = _build(el.elastic_spline(scale * np.c_[13 * np.cos(t), 10 * np.sin(t)] + OFF,
                                     closed=True), 64)
        first, last = g.bsplines[0], g.bsplines[-1]
        angle, jump = _joins([last, first])
        k = abs(float(first.curvature(first.knots[:1])[0]))
        assert g.seam_is_g2 and g.seam_curvature_jump <= 1e-12
        assert angle <= g.seam_bound[0] and jump / k <= g.seam_bound[1], (angle, jump / k, g.seam_bound)
