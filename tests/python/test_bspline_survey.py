"""B-splines of curves in survey coordinates and of chains with a nearly straight piece
(QA23): the default tol stays above what double precision resolves, and a chain's
DomainError names the piece and the cause that failed first."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica.bspline import FLOOR_MARGIN, resolvable_tol

OFFSETS = {"mm": (np.array([4.0e8, 5.6e9]), 40.0), "m": (np.array([4.0e5, 5.6e6]), 0.04)}


def _detail(unit):
    """A moulding detail (40 mm) scanned in survey coordinates: points with 0.05 % noise."""
    off, L = OFFSETS[unit]
    c = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1e-2 * (40.0 / L) ** 2, k=0.7, q=0.3, length=L)
    rng = np.random.default_rng(0)
    return c, off, c.points(200) + rng.normal(0, 5e-4 * L, (200, 2))


def _own_distance(b, curve):
    """max over 2000 points of the curve of their distance to the B-spline (the nearest
    foot, el.nearest_on), both relative to the curve's start: no rounding of the offset."""
    from libelastica.nearest import nearest_on
    return float(np.max(np.abs(nearest_on(b, curve.points(2000))[1])))


@pytest.mark.parametrize("unit", ["mm", "m"])
def test_default_to_bspline_works_in_survey_coordinates(unit):
    """README: the default tol works "at any scale". 1e-6 of a 40 mm detail at (4e8, 5.6e9)
    mm is 4e-5, below the 6.0e-5 double precision resolves there: fit(smooth), a
    SmoothElastica, elastic_spline, hermite and blend_curve all raised DomainError (QA23
    F3). Now each default is FLOOR_MARGIN x that floor, certified, and lies where the
    curve is; an explicit tol below the floor keeps its DomainError."""
    c, off, pts = _detail(unit)
    far = el.SmoothElastica(x0=off[0], y0=off[1], phi=c.phi, mu=c.mu, k=c.k, q=c.q, length=c.length)
    floor = resolvable_tol(far)
    assert 1e-6 * far.length < floor          # the case: the old default was below the floor
    b = far.to_bspline()
    assert 0.0 <= b.max_deviation <= FLOOR_MARGIN * floor
    # the B-spline is where the curve is: compare near the origin (shift both exactly)
    local = el.BSpline(b.degree, b.poles - off, b.knots, b.mults)
    assert _own_distance(local, c) <= b.max_deviation + 1e-9 * c.length
    makers = {
        "fit smooth": lambda: el.fit(pts + off, model="smooth").to_bspline(),
        "elastic_spline": lambda: el.elastic_spline(pts[::25] + off, tension=0.0).to_bspline(),
        "hermite": lambda: el.hermite(off, (1, 0), off + c.length * np.array([1.0, 0.125]),
                                      (1, 0.3), tension=1e-3 / (c.length / 40) ** 2)[0].to_bspline(),
        "blend_curve": lambda: el.blend_curve(pts[::40] + off).to_bspline(),
    }
    for what, make in makers.items():
        b = make()
        assert 0.0 <= b.max_deviation <= 1e-3 * c.length, what
        assert np.all(np.abs(b.poles - off).max(axis=0) < 2 * c.length), what
    with pytest.raises(el.DomainError, match="below what double precision resolves"):
        far.to_bspline(0.5 * floor)
    with pytest.raises(el.DomainError, match="below what double precision resolves"):
        el.elastic_spline(pts[::25] + off, tension=0.0).to_bspline(0.5 * floor)


def test_cli_dxf_of_a_survey_detail_exits_0(tmp_path):
    """`elastica fit --model smooth --dxf` and `spline --dxf` of the detail in mm at (4e8,
    5.6e9) exited 2 ("below what double precision resolves", QA23 F3)."""
    c, off, pts = _detail("mm")
    f = tmp_path / "detail.csv"
    np.savetxt(f, pts + off, delimiter=",", header="x,y", comments="", fmt="%.6f")
    for cmd in (["fit", str(f), "--model", "smooth", "--dxf", str(tmp_path / "a.dxf")],
                ["spline", str(f), "--dxf", str(tmp_path / "b.dxf")]):
        r = subprocess.run([sys.executable, "-m", "libelastica"] + cmd, capture_output=True, text=True)
        assert r.returncode == 0, (cmd, r.stderr)


def _midbody():
    """QA23's 100 m waterline (mm) with a parallel middle body, flat from 35 % to 65 % of
    the length, through 40 stations (/tmp/qa23/ship/run_ship.py, half-breadth ~7.5 m)."""
    return np.loadtxt(Path(__file__).parent.parent / "data" / "waterline_midbody40.csv",
                      delimiter=",", skiprows=1)


def test_chain_names_the_piece_below_the_floor_not_the_one_turning_most():
    """A batten through a waterline's flat middle: a straight span's phase |q|/sqrt(mu) ~
    1.7e9 puts its floor at 1.7e-5, so to_bspline(1e-5) fails there first; it said "piece 39
    of 39 ... needs more than 10000 poles" (the piece turning most, QA23 F7). Now the first
    piece below the floor is named, with the floor and why; 2e-5 still works."""
    sp = el.elastic_spline(_midbody(), tension=0.0)
    floors = np.array([resolvable_tol(c) for c in sp.pieces])
    tol = min(1e-5, 0.6 * floors.max())       # 1e-5 (floor 1.67e-5 at piece 20)
    first = int(np.flatnonzero(floors > tol)[0])
    turns = [2 * abs(c.k) * np.sqrt(c.mu) * c.length for c in sp.pieces]
    assert first != int(np.argmax(turns))    # the case: the piece turning most is another
    with pytest.raises(el.DomainError) as e:
        sp.to_bspline(tol)
    said = str(e.value)
    assert f"piece {first + 1} of {len(sp.pieces)}: tol = {tol:.3g} is below what double" in said
    assert "poles" not in said and "|q|/sqrt(mu)" in said
    assert sp.to_bspline(max(2e-5, 1.01 * floors.max())).max_deviation <= 2e-5
