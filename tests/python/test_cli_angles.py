"""Every angle the CLI writes names its unit (QA18 P2): `fit --start-tangent 12` (degrees)
was written back as "constraints": {"start_tangent": 0.2094} (radians, unnamed), a spline's
tangent angles as "angles", and the report's phi had no unit."""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np

import libelastica as el
from cli_run import cli
from libelastica.cli import build_parser
from libelastica.cli_fit import _parse_fix

EX = Path(__file__).resolve().parents[2] / "examples"
SAMPLE_S = EX / "sample_s_curve.csv"


def _free_end_angles(capsys):
    """The start and end tangent angles (degrees) of the sample's free smooth fit: end
    conditions it meets."""
    c = el.io.curve_from_dict(json.loads(cli(capsys, "fit", SAMPLE_S, "--model", "smooth",
                                             "--json", "-")[1]))
    return tuple(float(a) for a in np.degrees(c.angle([0.0, c.length])))


def _unnamed_angles(doc, path=""):
    """Keys of numbers (or lists of them) that hold an angle (their name says angle or
    tangent) without "_rad" / "_deg"."""
    out = []
    if isinstance(doc, dict):
        for k, v in doc.items():
            numeric = isinstance(v, (int, float)) and not isinstance(v, bool) or (
                isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v))
            if numeric and re.search(r"angle|tangent", k) and not re.search(r"_(rad|deg)$", k):
                out.append(f"{path}.{k}")
            out += _unnamed_angles(v, f"{path}.{k}")
    elif isinstance(doc, list):
        for i, v in enumerate(doc):
            out += _unnamed_angles(v, f"{path}[{i}]")
    return out


def test_every_angle_in_the_json_names_its_unit(capsys, tmp_path):
    a0, a1 = _free_end_angles(capsys)
    code, out, err = cli(capsys, "fit", SAMPLE_S, "--start-tangent", a0, "--end-tangent", a1,
                         "--bspline-tol", "1e-6", "--json", tmp_path / "f.json")
    assert code == 0, err
    fit = json.loads((tmp_path / "f.json").read_text())
    assert fit["constraints"] == {"start_tangent_rad": np.radians(a0), "end_tangent_rad": np.radians(a1)}
    code, out, err = cli(capsys, "spline", EX / "ducks.csv", "--json", tmp_path / "s.json")
    assert code == 0, err
    spline = json.loads((tmp_path / "s.json").read_text())
    sp = el.elastic_spline(el.io.read_points(EX / "ducks.csv"), tension=0.0)
    assert np.array_equal(spline["angles_rad"], sp.angles)
    code, out, err = cli(capsys, "g2quad", tmp_path / "f.json", "--edges", "24",
                         "--json", tmp_path / "g.json")
    assert code == 0, err
    code, out, err = cli(capsys, "bspline", tmp_path / "f.json", "--json", tmp_path / "b.json")
    assert code == 0, err
    for name in ("f", "s", "g", "b"):
        doc = json.loads((tmp_path / f"{name}.json").read_text())
        assert not _unnamed_angles(doc), (name, _unnamed_angles(doc))


def test_bspline_reads_the_tangent_in_radians_under_either_key(capsys, tmp_path):
    """`elastica bspline` of a discrete fit's JSON keeps its end tangents (start_tangent_rad),
    and of one written before the unit was named (start_tangent, radians) the same."""
    a0 = _free_end_angles(capsys)[0]
    code, out, err = cli(capsys, "fit", SAMPLE_S, "--start-tangent", a0, "--json", tmp_path / "f.json")
    assert code == 0, err
    doc = json.loads((tmp_path / "f.json").read_text())
    old = dict(doc, constraints={"start_tangent": doc["constraints"]["start_tangent_rad"]})
    (tmp_path / "old.json").write_text(json.dumps(old))
    splines = []
    for name in ("f", "old"):
        code, out, err = cli(capsys, "bspline", tmp_path / f"{name}.json", "--json", "-")
        assert code == 0, err
        splines.append(el.BSpline.from_dict(json.loads(out)["bspline"]))
    assert np.array_equal(splines[0].poles, splines[1].poles)
    d = splines[0].derivative(np.array(splines[0].domain[:1]), 1)[0]
    assert abs(np.degrees(np.arctan2(d[1], d[0])) - a0) < 1e-9


def test_the_report_names_phis_unit(capsys, tmp_path):
    code, out, err = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--svg", tmp_path / "f.svg")
    assert code == 0, err
    phi = re.search(r"phi=(\S+) rad,", out)
    assert phi, out
    doc = json.loads(cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--json", "-")[1])
    assert float(phi.group(1)) == float(f"{doc['curve']['phi']:.6g}")
    assert re.search(r"phi = \S+ rad", (tmp_path / "f.svg").read_text())


def test_every_angle_typed_is_in_degrees(capsys):
    """`--fix phi=30` was 30 radians beside --start-tangent's degrees: every angle of the
    command line is now degrees, or radians with 'rad' after it; the JSON keeps radians."""
    def fitted(*opts):
        code, out, err = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", *opts, "--json", "-")
        assert code == 0, err
        return json.loads(out)
    assert fitted("--fix", "phi=30")["curve"]["phi"] == np.radians(30.0)
    assert _parse_fix("x0,phi=-30deg", np.zeros((2, 2))) == {"x0": 0.0, "phi": np.radians(-30.0)}
    assert fitted("--fix", "phi=0.5rad")["curve"]["phi"] == 0.5
    a0 = _free_end_angles(capsys)[0]
    want = fitted("--start-tangent", a0)
    rad = float(np.radians(a0))
    for typed in (f"{a0!r}deg", f"{rad!r}rad", f"{rad!r} RAD"):
        got = fitted("--start-tangent", typed)
        assert got["constraints"] == want["constraints"] and got["curve"] == want["curve"], typed
    args = build_parser().parse_args(["fit", "p.csv", "--end-tangent", "-30deg"])
    assert args.end_tangent == np.radians(-30.0)
    for opts, said in ((["--fix", "phi=30grad"], "--fix: phi='30grad' is not an angle (degrees"),
                       (["--start-tangent", "nan"], "argument --start-tangent: 'nan': an angle is "
                                                    "needed (degrees")):
        code, _, err = cli(capsys, "fit", SAMPLE_S, *opts)
        assert code == 2 and said in err, err
    helped = " ".join(cli(capsys, "fit", "--help")[1].split())
    assert "'x0=0,y0=0,phi=30' (phi in degrees as every angle of the command line" in helped
    assert "angles (--fix phi, --start-tangent, --end-tangent): degrees" in helped


def _elastica(*args):
    """`python -m libelastica *args` as a user runs it: (exit code, stderr)."""
    r = subprocess.run([sys.executable, "-m", "libelastica", *map(str, args)], env=dict(os.environ),
                       capture_output=True, text=True, timeout=120)
    return r.returncode, r.stderr


def test_a_tangent_past_a_full_turn_is_said_in_degrees(tmp_path):
    """QA20 F3: `fit --start-tangent 400` (degrees) showed the binding's radians check to the
    user who typed degrees: 'fit.py:692: UserWarning: ... the binding takes radians ...;
    degrees? use math.radians(6.98132)' and its Python source line. The command says it in
    degrees, once, and fits the direction (the JSON keeps the angle typed, in radians);
    the `bspline` of that JSON (cubic_through's check) says nothing of it."""
    for typed, said in (("400", "--start-tangent 400 deg is 40 deg turned once more"),
                        ("-1120deg", "--start-tangent -1120 deg is -40 deg turned 3 times more"),
                        ("7rad", "--start-tangent 401.0705 deg is 41.0705 deg turned once more")):
        code, err = _elastica("fit", SAMPLE_S, "--start-tangent", typed, "--json", tmp_path / "f.json")
        assert code in (0, 1), err
        assert "UserWarning" not in err and ".py:" not in err and "math.radians" not in err, err
        assert err.count(said) == 1, err
        assert json.loads((tmp_path / "f.json").read_text())["constraints"]["start_tangent_rad"] == \
            (7.0 if typed == "7rad" else np.radians(float(typed.removesuffix("deg"))))
    code, err = _elastica("bspline", tmp_path / "f.json", "--json", tmp_path / "b.json")
    assert code == 0 and err == "", err
    code, err = _elastica("fit", SAMPLE_S, "--end-tangent", "353")     # within a turn: silent
    assert "turned" not in err and "deg" not in err, err


def test_a_library_warning_the_command_does_not_say_is_said_in_its_words(capsys, monkeypatch):
    """Any warning raised under a command and not said by it is one line 'elastica CMD:
    warning: ...' on stderr, without Python's file:line, category, source line and the
    binding function's 'fit: ' (QA20 F3: every CLI warning path)."""
    import libelastica.cli_fit as cli_fit
    fit = cli_fit.quiet_fit

    def warned(*args, **kwargs):
        warnings.warn("fit: something the command does not say", RuntimeWarning)
        return fit(*args, **kwargs)
    monkeypatch.setattr(cli_fit, "quiet_fit", warned)
    code, out, err = cli(capsys, "fit", SAMPLE_S, "--model", "smooth")
    assert code == 0, err
    assert "elastica fit: warning: something the command does not say\n" in err, err
    assert "RuntimeWarning" not in err and ".py:" not in err, err
