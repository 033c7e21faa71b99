"""The CLI after QA 8: Hermite curves not representable at --tol counted (table, JSON)
and no curve named fair while one is missing, Hermite's warnings the CLI's way; negative
numbers with an exponent taken as numbers; the spline's loop warning in length mode;
options that would do nothing refused, a self-crossing export warned of, no $MEASUREMENT
in a unitless DXF."""
from __future__ import annotations

import json
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica.cli import build_parser, main

# a near-straight bow at tension 0: the curve along the chord is a sliver of a huge
# elastica, met only to ~1e-16 / angle (elastica.h): unrepresentable at tol 1e-10
BOW = ["0", "0", "1", "0.000001", "1", "0", "1", "-0.000001", "--tension", "0"]
# solutions 0 and 1 cross themselves, 2 and 3 are fair (test_cli_exports.py)
EXAMPLE = ["0", "0", "1", "0", "1", "0", "1", "0", "--length", "4"]


def cli(capsys, *args):
    capsys.readouterr()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            code = main([str(a) for a in args])
        except SystemExit as exc:
            code = exc.code
    out, err = capsys.readouterr()
    assert not caught, [str(w.message) for w in caught]   # said on stderr, not raised
    return code, out, err


def test_hermite_counts_the_unrepresentable_and_names_no_fair_one(capsys, tmp_path):
    """The bow's one returned curve (2.19 x the chord) is not called fair while the straight
    one is missing: the line under the table and the JSON count it, the warning is one
    'warning:' line, and --tol 1e-9 (the one the line names) returns it."""
    code, out, err = cli(capsys, "hermite", *BOW, "--json", tmp_path / "b.json")
    assert code == 0
    last = out.splitlines()[-1]
    assert "1 more not representable at tol 1e-10: --tol 1e-09 returns them" in last
    assert "fair ones are" not in last
    assert err.startswith("elastica hermite: warning: 1 more curve(s) exist")
    assert len(err.strip().splitlines()) == 1 and "RuntimeWarning" not in err
    doc = json.loads((tmp_path / "b.json").read_text())
    assert doc["unrepresentable"] == 1 and doc["tol"] == 1e-10 and len(doc["solutions"]) == 1
    code, out, err = cli(capsys, "hermite", *BOW, "--tol", "1e-9", "--json", "-")
    doc = json.loads(out)
    assert code == 0 and not err and doc["unrepresentable"] == 0
    assert min(r["length"] for r in doc["solutions"]) == pytest.approx(1.0, abs=1e-9)
    code, out, _ = cli(capsys, "hermite", *BOW, "--tol", "1e-9")
    assert out.splitlines()[-1].endswith("the fair ones are 0, 1")


@pytest.mark.parametrize("args, where, value", [
    (["hermite", "0", "0", "1", "0", "1", "0", "1", "-1e-8", "--tension", "1"], "values", -1e-8),
    (["hermite", "-5e3", "0", "1", "0", "-4.999E+3", "0", "1", "0", "--tension", "1e-9"],
     "values", -5e3),
    (["hermite", "0", "0", "1", "0", "1", "0", "1", "0", "--tension", "-2e-1"], "tension", -0.2),
    (["blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "-1e-3"], "values", -1e-3),
    (["spline", "p.csv", "--start-tangent", "1", "-1e-9"], "start_tangent", -1e-9),
    (["fit", "p.csv", "--end-curvature", "-.5e-2"], "end_curvature", -0.005),
    (["fit", "p.csv", "--start-point", "-3120.5,1500.25"], "start_point", "-3120.5,1500.25"),
    (["fit", "p.csv", "--end-point", "-1e3, -2.5E-1"], "end_point", "-1e3, -2.5E-1"),
    (["fit", "p.csv", "--length", "-5,"], "length", "-5,"),
    (["fit", "p.csv", "--k", "-0.5, 0.9"], "k_range", "-0.5, 0.9")])
def test_negative_numbers_with_an_exponent_are_numbers(args, where, value):
    """argparse took '-1e-8' for an option ('the following arguments are required: V'), and
    a point whose X is negative too ('--start-point -3120.5,1500.25': "expected one
    argument", QA24), and a range LO, with HI empty ('--length -5,')."""
    got = getattr(build_parser().parse_args(args), where)
    assert value in (got if isinstance(got, list) else [got])


def test_hermite_with_an_exponent_runs(capsys):
    code, out, err = cli(capsys, "hermite", "0", "0", "1", "0", "1", "0", "1", "-1e-8",
                         "--tension", "1")
    assert code == 0, err
    assert "fair ones are" in out


def test_spline_loop_warning_in_length_mode_says_shorter(capsys, tmp_path):
    """Too long a length loops: the advice is a shorter length (it was 'a larger --tension
    or a --length' to a user who had given the length), in the CLI and in Python; the
    shorter length gives a fair batten."""
    t = np.linspace(0.0, 2.0 * np.pi, 9)[:-1]
    ring = np.c_[30.0 * np.cos(t), 10.0 * np.sin(t)]
    (tmp_path / "ring.csv").write_text("x,y\n" + "".join(f"{x:.17g},{y:.17g}\n" for x, y in ring))
    code, _, err = cli(capsys, "spline", tmp_path / "ring.csv", "--closed", "--length", "1000")
    assert code == 0
    assert "a shorter --length gives one" in err and "--tension" not in err
    with pytest.warns(el.LoopWarning, match="length 1000 .*a shorter length gives one"):
        el.elastic_spline(ring, length=1000.0, closed=True)
    assert not el.elastic_spline(ring, length=200.0, closed=True).loops


@pytest.mark.parametrize("args, said", [
    (["hermite", *EXAMPLE, "--solution", "1"], "--solution 1 picks the solution --dxf writes"),
    (["hermite", *EXAMPLE, "--units", "mm"], "--units mm sets the DXF's units: give --dxf too"),
    (["hermite", *EXAMPLE, "--units", "none"], "--units none sets the DXF's units"),
    (["blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--units", "cm"], "give --dxf too"),
    (["bspline", "s.json", "--solution", "2"], "s.json is not a hermite JSON")])
def test_options_that_would_do_nothing_are_refused(capsys, tmp_path, monkeypatch, args, said):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("0 0\n1 1\n2 0\n")
    assert cli(capsys, "spline", "p.csv", "--json", "s.json")[0] == 0
    code, _, err = cli(capsys, *args, "--json", "o.json")
    assert code == 2 and said in err and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "o.json").exists()


def test_exporting_a_self_crossing_solution_warns(capsys, tmp_path):
    """`hermite --dxf` of a solution that crosses itself (the default 0 here) and `bspline`
    of one warn, naming the fair ones; a fair one's export does not."""
    pytest.importorskip("ezdxf")
    for extra in ([], ["--solution", "1"]):
        code, _, err = cli(capsys, "hermite", *EXAMPLE, *extra, "--dxf", tmp_path / "h.dxf")
        assert code == 0 and (tmp_path / "h.dxf").exists()
        assert err.startswith("elastica hermite: warning: --dxf writes solution") and \
            "crosses itself" in err and "the fair ones are 2, 3" in err
    code, _, err = cli(capsys, "hermite", *EXAMPLE, "--solution", "2", "--dxf", tmp_path / "h.dxf",
                       "--json", tmp_path / "h.json")
    assert code == 0 and not err
    code, _, err = cli(capsys, "bspline", tmp_path / "h.json", "--solution", "1")
    assert code == 0 and err.startswith("elastica bspline: warning:") and "crosses itself" in err \
        and "the fair ones are 2, 3" in err
    code, _, err = cli(capsys, "bspline", tmp_path / "h.json", "--solution", "3")
    assert code == 0 and not err


@pytest.mark.parametrize("units", [None, "none"])
def test_unitless_dxf_has_no_measurement(capsys, tmp_path, units):
    """A unitless DXF says no unit system either (ezdxf's new drawing wrote $MEASUREMENT 1,
    metric)."""
    ezdxf = pytest.importorskip("ezdxf")
    more = ["--units", units] if units else []
    assert cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--dxf",
               tmp_path / "e.dxf", *more)[0] == 0
    doc = ezdxf.readfile(str(tmp_path / "e.dxf"))
    assert not doc.audit().errors
    assert doc.header["$INSUNITS"] == 0 and "$MEASUREMENT" not in doc.header
