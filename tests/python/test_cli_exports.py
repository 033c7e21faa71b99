"""The Python/CLI user's Hermite table and exports (QA 6): which solutions cross
themselves (loops, largest curvature, length: in Python, the table and the JSON),
`hermite --dxf`, `bspline` of a Hermite or spline JSON, and the DXF's units, extents
and closed flag, each re-read with ezdxf."""
from __future__ import annotations

import json
import re
import math

import numpy as np
import pytest

import libelastica as el
from libelastica.bspline import fitted_bspline
from cli_run import cli

# the QA's example: solutions 0 and 1 have the least energy (11.17) and loop; 2 and 3 are
# the fair S curves
EXAMPLE = ["0", "0", "1", "0", "1", "0", "1", "0", "--length", "4"]
ENDS = ((0.0, 0.0), (1.0, 0.0), (1.0, 0.0), (1.0, 0.0))


def dense_max_curvature(c, n=200001):
    return float(np.abs(c.curvature(np.linspace(0.0, c.length, n))).max())


def test_solutions_say_which_cross_themselves():
    """Python: every solution's loops / crosses_itself / max_curvature / length; the two of
    least energy turn a full turn (a loop: the tangent comes back after 2 pi) and cross
    themselves, the S curves turn back (no net turn) and do not."""
    sols = el.hermite(*ENDS, length=4.0)
    assert [round(c.energy_value, 2) for c in sols] == [11.17, 11.17, 18.76, 18.76]
    assert [c.loops for c in sols] == [1, 1, 0, 0]
    assert [c.crosses_itself for c in sols] == [True, True, False, False]
    for c in sols:
        turn = abs(c.angle([c.length])[0] - c.angle([0.0])[0])
        assert (turn > math.pi) == c.crosses_itself
        assert c.length == pytest.approx(4.0)
        dense = dense_max_curvature(c)
        assert dense <= c.max_curvature <= dense * (1 + 1e-9)


@pytest.mark.parametrize("k", [0.3, 0.8, 0.999, 1.0001, 1.7, -4.0])
def test_max_curvature_is_the_exact_peak(k):
    """max_curvature is the largest |kappa| exactly (peaks between samples included), for
    curves that reach the peak 2 |k| sqrt(mu) and ones that do not (a short piece), and a
    Hermite chain's over its pieces."""
    for q, length in ((0.37, 9.0), (0.2, 0.3), (-1.1, 0.5)):
        c = el.SmoothElastica(x0=1, y0=-2, phi=0.4, mu=2.5, k=k, q=q, length=length)
        dense = dense_max_curvature(c)
        assert dense <= c.max_curvature <= dense * (1 + 1e-9)
    chain = el.hermite((0, 0), (1, 0), (1, 0.2), (1, 0.1), tension=1500.0)
    chains = [c for c in chain if isinstance(c, el.HermiteChain)]
    assert chains
    for c in chains:         # (a peak 0.04 wide: the samples, 7e-6 apart, miss its top by 1e-9)
        dense = dense_max_curvature(c)
        assert dense <= c.max_curvature <= dense * (1 + 1e-8)


def test_hermite_table_and_json_show_the_fair_ones(capsys):
    """The table's columns loops / crosses itself / max curvature / length, in the order by
    energy, and a line naming the fair ones; the JSON's records the same."""
    sols = el.hermite(*ENDS, length=4.0)
    code, out, _ = cli(capsys, "hermite", *EXAMPLE)
    assert code == 0
    lines = out.splitlines()
    head = lines[0]
    for col in ("length", "energy", "loops", "crosses itself", "max curvature"):
        assert col in head
    rows = lines[2:2 + len(sols)]
    at = head.index("crosses itself")
    assert [r[at:at + 3].strip() for r in rows] == ["YES", "YES", "no", "no"]
    assert lines[2 + len(sols)].endswith("the fair ones are 2, 3")
    code, out, _ = cli(capsys, "hermite", *EXAMPLE, "--json", "-")
    recs = json.loads(out)["solutions"]
    assert [r["loops"] for r in recs] == [1, 1, 0, 0]
    assert [r["crosses_itself"] for r in recs] == [True, True, False, False]
    assert [r["energy"] for r in recs] == sorted(r["energy"] for r in recs)
    for r, c in zip(recs, sols):
        assert r["length"] == pytest.approx(4.0)
        assert r["max_curvature"] == pytest.approx(c.max_curvature, rel=1e-12)


def test_hermite_dxf_is_the_chosen_solution(capsys, tmp_path):
    """`hermite --solution 2 --dxf --units mm`: one SPLINE, solution 2's B-spline (its
    poles and knots; G2 ends, as `bspline` makes it of the JSON), p0 and p1 as points, $INSUNITS 4 (mm), the extents the curve's;
    without --solution the least energy's; --bspline-tol puts every solution's in the JSON."""
    ezdxf = pytest.importorskip("ezdxf")
    sols = el.hermite(*ENDS, length=4.0)
    code, _, err = cli(capsys, "hermite", *EXAMPLE, "--solution", "2", "--dxf", tmp_path / "h.dxf",
                       "--units", "mm", "--bspline-tol", "1e-7", "--json", tmp_path / "h.json")
    assert code == 0, err
    doc = ezdxf.readfile(str(tmp_path / "h.dxf"))
    assert not doc.audit().errors
    assert doc.header["$INSUNITS"] == 4
    (spl,) = doc.modelspace().query("SPLINE")
    b = fitted_bspline(sols[2], 1e-7, 3)
    np.testing.assert_allclose(np.array([tuple(p)[:2] for p in spl.control_points]), b.poles,
                               rtol=0, atol=1e-15)
    assert list(spl.knots) == np.repeat(b.knots, b.mults).tolist()
    pts = sorted(tuple(e.dxf.location)[:2] for e in doc.modelspace().query("POINT"))
    assert pts == [(0.0, 0.0), (1.0, 0.0)]
    xy = b(np.linspace(*b.domain, 20001))
    np.testing.assert_allclose(doc.header["$EXTMIN"][:2], xy.min(axis=0), rtol=0, atol=1e-6)
    np.testing.assert_allclose(doc.header["$EXTMAX"][:2], xy.max(axis=0), rtol=0, atol=1e-6)
    recs = json.loads((tmp_path / "h.json").read_text())["solutions"]
    assert all(0 < r["bspline"]["max_deviation"] <= 1e-7 for r in recs)
    code, _, _ = cli(capsys, "hermite", *EXAMPLE, "--dxf", tmp_path / "h0.dxf")
    (spl,) = ezdxf.readfile(str(tmp_path / "h0.dxf")).modelspace().query("SPLINE")
    np.testing.assert_allclose(np.array([tuple(p)[:2] for p in spl.control_points]),   # default:
                               fitted_bspline(sols[0], 1e-6 * sols[0].length, 3).poles,  # 1e-6 of
                               rtol=0, atol=1e-15)                                   # the length


def test_bspline_of_a_hermite_json(capsys, tmp_path):
    """`bspline h.json`: the least-energy solution's B-spline, --solution N that one's; a
    solution that is not there is named (exit 2, one line, nothing written)."""
    sols = el.hermite(*ENDS, length=4.0)
    assert cli(capsys, "hermite", *EXAMPLE, "--json", tmp_path / "h.json")[0] == 0
    for args, i in (([], 0), (["--solution", "3"], 3)):
        code, out, err = cli(capsys, "bspline", tmp_path / "h.json", *args, "--json", "-")
        assert code == 0, err
        b = el.BSpline.from_dict(json.loads(out)["bspline"])
        np.testing.assert_allclose(b.poles, fitted_bspline(sols[i], 1e-6 * sols[i].length, 3).poles,
                                   rtol=0, atol=1e-15)     # the default: 1e-6 of the length
    code, _, err = cli(capsys, "bspline", tmp_path / "h.json", "--solution", "4", "--json",
                       tmp_path / "b.json")
    assert code == 2 and "4 solutions (0 to 3)" in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "b.json").exists()


@pytest.mark.parametrize("closed", [False, True])
def test_bspline_of_a_spline_json_and_the_dxf_closed_flag(capsys, tmp_path, closed):
    """`bspline s.json`: the spline's pieces as its ONE G2 B-spline (ElasticSpline.to_bspline's);
    the DXF of a closed spline (from `spline --closed` and from `bspline` of its JSON) has
    its SPLINE flagged closed (flag 1; not periodic: its seam is a clamped end), an open
    one's not; unitless by default ($INSUNITS 0, not ezdxf's 6, metres)."""
    ezdxf = pytest.importorskip("ezdxf")
    ring = np.array([[0.0, 0.0], [10.0, 0.0], [12.0, 8.0], [3.0, 9.0]])
    (tmp_path / "p.csv").write_text("x,y\n" + "\n".join(f"{x},{y}" for x, y in ring) + "\n")
    more = ["--closed"] if closed else []
    code, _, err = cli(capsys, "spline", tmp_path / "p.csv", "--tension", "0.05", *more,
                       "--json", tmp_path / "s.json", "--dxf", tmp_path / "s.dxf")
    assert code == 0, err
    sp = el.elastic_spline(ring, tension=0.05, closed=closed)
    code, out, err = cli(capsys, "bspline", tmp_path / "s.json", "--json", "-", "--dxf",
                         tmp_path / "b.dxf")
    assert code == 0, err
    b = el.BSpline.from_dict(json.loads(out)["bspline"])
    np.testing.assert_allclose(b.poles, sp.to_bspline(1e-6 * sp.length, 3).poles, rtol=0,
                               atol=1e-12)                 # the default: 1e-6 of the length
    for name in ("s.dxf", "b.dxf"):
        doc = ezdxf.readfile(str(tmp_path / name))
        assert not doc.audit().errors
        assert doc.header["$INSUNITS"] == 0
        (spl,) = doc.modelspace().query("SPLINE")
        assert spl.dxf.flags == (1 if closed else 0) and spl.closed == closed
        lo, hi = np.array(doc.header["$EXTMIN"][:2]), np.array(doc.header["$EXTMAX"][:2])
        xy, dev = sp.points(4000), b.max_deviation + 1e-12   # the SPLINE is within dev of it
        assert np.all(lo <= xy.min(axis=0) + dev) and np.all(xy.max(axis=0) - dev <= hi)
        np.testing.assert_allclose([lo, hi], [xy.min(axis=0), xy.max(axis=0)], rtol=0, atol=1e-3)


@pytest.mark.parametrize("units, code", [("mm", 4), ("cm", 5), ("m", 6), ("in", 1)])
def test_dxf_units_are_the_users(capsys, tmp_path, units, code):
    """--units names the drawing's unit ($INSUNITS, and $MEASUREMENT metric or imperial)."""
    ezdxf = pytest.importorskip("ezdxf")
    assert cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--dxf",
               tmp_path / "e.dxf", "--units", units)[0] == 0
    doc = ezdxf.readfile(str(tmp_path / "e.dxf"))
    assert doc.header["$INSUNITS"] == code
    assert doc.header["$MEASUREMENT"] == (0 if units == "in" else 1)


def test_dxf_at_large_coordinates_and_tols_that_cannot_be_met(capsys, tmp_path):
    """`spline --dxf` of 50 points 1 km long in mm and `blend --dxf` 300 m long: written,
    the default tol 1e-6 of the length (exit 1 before: "tolerance 1e-06 not reached
    (certified 1e-06); raise tol", "did not converge", QA); a tol that cannot be met says
    what can and names its option (exit 1 not reached, 2 below the rounding floor),
    nothing written."""
    ezdxf = pytest.importorskip("ezdxf")
    t = np.linspace(0.0, 1.0, 50)
    np.savetxt(tmp_path / "km.csv", 1e6 * np.c_[t, 0.3 * np.sin(3.0 * t)], delimiter=",")
    blend = ["0", "0", "1e5", "1e5", "2e5", "1e5", "3e5", "0"]
    for args in (["spline", tmp_path / "km.csv", "--tension", "0"], ["blend", *blend]):
        code, _, err = cli(capsys, *args, "--json", tmp_path / "ok.json", "--dxf", tmp_path / "ok.dxf")
        assert code == 0, err
        rec = json.loads((tmp_path / "ok.json").read_text())
        assert 0 < rec["bspline"]["max_deviation"] <= 1e-6 * (rec.get("length") or 3.6e5)
        assert len(ezdxf.readfile(str(tmp_path / "ok.dxf")).modelspace().query("SPLINE")) == 1
    for args, code_, said in (
            (["spline", tmp_path / "km.csv", "--tension", "0", "--bspline-tol", "1e-9"], 2,
             r"the smallest possible is max over the pieces = 3\.66e-08 \(--bspline-tol sets tol\)"),
            (["blend", *blend, "--tol", "1e-6"], 1,
             r"raise tol to 2\.28e-06 or more .*\(--tol sets tol\)"),
            (["blend", *blend, "--tol", "1e-12"], 2, r"the smallest possible is .*\(--tol sets tol\)")):
        code, _, err = cli(capsys, *args, "--json", tmp_path / "no.json", "--dxf", tmp_path / "no.dxf")
        assert code == code_ and re.search(said, err) and len(err.strip().splitlines()) == 1, err
        assert not (tmp_path / "no.json").exists() and not (tmp_path / "no.dxf").exists()
