"""`elastica blend` (seed 003's elliptic blending curves) as users run it: the points it
takes (four, more, closed), the JSON that reproduces el.blend_curve, the warnings of a loop
and the DXF or a clear error."""
from __future__ import annotations

import json

import numpy as np
import pytest

import libelastica as el
from test_cli import assert_one_line_error, cli


def test_blend_takes_more_points_and_closed_ones(capsys):
    """`blend` took exactly four points (nargs=8): the closed blend and the composite through
    five points that el.blend_curve makes were out of the CLI's reach, and ten numbers gave
    argparse's 'unrecognized arguments: -3 20'. Three open points, which el.blend_curve
    takes, were refused; the loop warning now names where the curve loops."""
    pts = np.array([[0, 0], [100, 0], [101, 1], [50, 60], [-3, 20]], float)
    r = cli(capsys, "blend", *pts.ravel(), "--closed", "--json", "-")
    rec = json.loads(r.stdout)
    with pytest.warns(el.BlendLoopWarning):
        curve = el.blend_curve(pts, closed=True)
    assert r.returncode == 0 and rec["closed"] is True
    assert np.array_equal(np.asarray(rec["control_points"]), curve.q)
    assert rec["loops"] == curve.loops() == 1 and "loops" in r.stderr    # two close points
    assert rec["loop_places"][0]["between"] == [1, 2] and "between points 1 and 2" in r.stderr
    r = cli(capsys, "blend", *pts.ravel(), "--json", "-")
    with pytest.warns(el.BlendLoopWarning):
        open_curve = el.blend_curve(pts)
    assert r.returncode == 0 and np.array_equal(np.asarray(json.loads(r.stdout)["control_points"]),
                                                open_curve.q)
    r = cli(capsys, "blend", *pts[:3].ravel(), "--closed", "--json", "-")
    assert r.returncode == 0 and json.loads(r.stdout)["closed"] is True
    r = cli(capsys, "blend", *pts[:3].ravel(), "--json", "-")    # 3 open points: 2 segments
    assert r.returncode == 0 and np.array_equal(np.asarray(json.loads(r.stdout)["control_points"]),
                                                el.blend_curve(pts[:3]).q)
    for args in (pts.ravel()[:9], pts[:2].ravel()):      # odd count; 2 points
        r = cli(capsys, "blend", *args)
        assert_one_line_error(r)
        assert "x y pairs" in r.stderr and f"got {len(args)} numbers" in r.stderr


def test_blend_interpolates_the_four_points(capsys):
    pts = np.array([[0, 0], [0.3, 0.8], [0.7, 0.9], [1, 0]], dtype=float)
    r = cli(capsys, "blend", *pts.ravel(), "--m", "0.3", "--d", "2", "--tol", "1e-7", "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert doc["m"] == pytest.approx(0.3) and doc["d"] == pytest.approx(2.0)
    q = np.array(doc["control_points"])
    curve = el.blend_curve(pts, m=0.3, d=2.0)
    np.testing.assert_allclose(q, curve.q, atol=1e-12)
    xy = el.EllipticBlend(m=0.3, d=2.0).evaluate(q, np.linspace(0, 1, 2001))
    for p in pts:                              # interpolate mode passes through every point
        assert np.min(np.linalg.norm(xy - p, axis=1)) < 2e-3
    b = doc["bspline"]
    assert 0 <= b["max_deviation"] <= 1e-7
    assert len(b["knots"]) == len(b["mults"])


def test_dxf_or_clear_error(capsys, tmp_path):
    from libelastica.io import have_ezdxf
    out = tmp_path / "b.dxf"
    r = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--dxf", out)
    if have_ezdxf():
        assert r.returncode == 0, r.stderr
        import ezdxf
        splines = ezdxf.readfile(str(out)).modelspace().query("SPLINE")
        assert len(splines) == 1
    else:
        assert "ezdxf" in assert_one_line_error(r)
        assert not out.exists()
