"""'-' on the command line (QA17 W2): standard output for every output option of every
subcommand (JSON, SVG, PNG when stdout is no terminal, DXF), standard input for the input
file (once); errors name the option, never a temporary. Also the ends `g2quad` prints of
3D points (QA17 P6) and a file mixing separators (QA17 P2)."""
from __future__ import annotations

import io
import json
import shutil
import sys
from pathlib import Path

import numpy as np
import pytest

from cli_run import cli
from libelastica.io import read_points

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "examples" / "sample_2d.csv"
KEYLINE = ROOT / "examples" / "keyline_3d.csv"


@pytest.fixture
def work(tmp_path, monkeypatch):
    shutil.copy(SAMPLE, tmp_path / "a.csv")
    monkeypatch.chdir(tmp_path)
    return tmp_path


def stdin(monkeypatch, data: bytes) -> None:
    monkeypatch.setattr(sys, "stdin", io.TextIOWrapper(io.BytesIO(data)))


def binary(capsysbinary, *args):
    """(code, stdout bytes, stderr text) of an in-process run."""
    from libelastica.cli import main
    capsysbinary.readouterr()
    code = main([str(a) for a in args])
    out, err = capsysbinary.readouterr()
    return code, out, err.decode()


COMMANDS = {   # subcommand -> its arguments, writing every format the subcommand has
    "fit": ["fit", "a.csv"],
    "hermite": ["hermite", "0", "0", "1", "0", "1", "0", "1", "0", "--length", "4"],
    "spline": ["spline", "a.csv", "--tension", "0.5"],
    "blend": ["blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0"],
    "g2quad": ["g2quad", "a.csv", "--edges", "8"],
}
HEADS = {"json": b"{", "svg": b"<?xml", "png": b"\x89PNG", "dxf": b"  0\nSECTION"}


@pytest.mark.parametrize("fmt", ["json", "svg", "png", "dxf"])
@pytest.mark.parametrize("cmd", sorted(COMMANDS))
def test_dash_is_stdout_for_every_format(work, capsysbinary, cmd, fmt):
    if fmt == "png":
        pytest.importorskip("matplotlib")
    if fmt == "dxf":
        pytest.importorskip("ezdxf")
    code, out, err = binary(capsysbinary, *COMMANDS[cmd], f"--{fmt}", "-")
    assert code == 0, err
    assert out.lstrip(b"\r\n ").startswith(HEADS[fmt].lstrip()), out[:80]   # nothing but the file
    assert not (work / "-").exists()        # main wrote a FILE named '-' for --dxf -
    assert not list(work.glob(".-*"))       # nor left a temporary
    if fmt == "json":
        json.loads(out)


def test_dash_output_equals_the_file(work, capsysbinary):
    code, out, err = binary(capsysbinary, "fit", KEYLINE, "--keyline", "--json", "-")
    assert code == 0, err
    code, _, err = binary(capsysbinary, "fit", KEYLINE, "--keyline", "--json", "f.json")
    assert code == 0, err
    assert out == (work / "f.json").read_bytes()


def test_png_to_a_terminal_is_refused_naming_the_option(work, capsys, monkeypatch):
    pytest.importorskip("matplotlib")
    monkeypatch.setattr(sys.stdout, "isatty", lambda: True)
    code, out, err = cli(capsys, "fit", "a.csv", "--png", "-")
    assert code == 2 and "--png -" in err and "terminal" in err
    assert out == ""


def test_two_outputs_to_stdout_are_refused(work, capsys):
    code, out, err = cli(capsys, "fit", "a.csv", "--json", "-", "--svg", "-")
    assert code == 2 and "--json -" in err and "--svg -" in err
    assert out == ""


def test_batch_picture_to_stdout_is_refused(work, capsys):
    shutil.copy(SAMPLE, work / "b.csv")
    code, out, err = cli(capsys, "fit", "a.csv", "b.csv", "--svg", "-")
    assert code == 2 and "--svg -" in err
    assert out == ""


def test_error_names_no_temporary(work, capsys, monkeypatch):
    """A writer's failure on '-' is said with the option (main: the temporary's name)."""
    import libelastica.report as report

    def failing(pic, path):
        raise ValueError(f"{path}: cannot draw this")
    monkeypatch.setattr(report, "save_picture", failing)
    code, out, err = cli(capsys, "fit", "a.csv", "--svg", "-")
    assert code == 2 and "--svg -: cannot draw this" in err, err
    assert ".tmp" not in err and "elastica-stdout" not in err
    code, out, err = cli(capsys, "fit", "a.csv", "--svg", "p.svg")
    assert code == 2 and "p.svg: cannot draw this" in err and ".p.svg." not in err, err
    assert out == ""


def test_nothing_on_stdout_when_the_command_fails(work, capsys):
    code, out, err = cli(capsys, "hermite", "0", "0", "1", "0", "1", "0", "1", "0",
                         "--length", "4", "--solution", "99", "--dxf", "-")
    assert code == 2 and "--solution 99" in err
    assert out == ""


@pytest.mark.parametrize("data", ["csv", "npy"])
def test_dash_is_stdin(work, capsys, monkeypatch, data):
    ref = cli(capsys, "fit", "a.csv", "--json", "-")
    assert ref[0] == 0
    if data == "csv":
        raw = SAMPLE.read_bytes()
    else:
        buf = io.BytesIO()
        np.save(buf, read_points(SAMPLE))
        raw = buf.getvalue()
    stdin(monkeypatch, raw)
    code, out, err = cli(capsys, "fit", "-", "--json", "-")
    assert code == 0, err
    got, want = json.loads(out), json.loads(ref[1])
    assert got["rms"] == pytest.approx(want["rms"], rel=1e-12)


def test_stdin_json_for_bspline(work, capsys, monkeypatch):
    code, out, err = cli(capsys, "fit", "a.csv", "--model", "smooth", "--json", "-")
    assert code == 0, err
    stdin(monkeypatch, out.encode())
    code, out2, err = cli(capsys, "bspline", "-", "--json", "-")
    assert code == 0, err
    assert json.loads(out2)["bspline"]["degree"] == 3


def test_dash_twice_is_refused(work, capsys, monkeypatch):
    stdin(monkeypatch, SAMPLE.read_bytes())
    code, out, err = cli(capsys, "fit", "-", "-")
    assert code == 2 and "standard input" in err and "once" in err


def test_help_says_what_dash_means(capsys):
    for cmd in COMMANDS:
        code, out, _ = cli(capsys, cmd, "--help")
        assert code == 0
        text = " ".join(out.split())
        assert "'-': standard output" in text, cmd
        if cmd not in ("hermite", "blend"):      # those take numbers, no file
            assert "'-': standard input" in text, cmd


def test_g2quad_prints_the_ends_in_the_files_coordinates(work, capsys):
    """QA17 P6: 3D points -> the ends printed in 3D, as the DXF has them (main: the fit
    plane's 2D frame, matching nothing the user has)."""
    ezdxf = pytest.importorskip("ezdxf")
    code, out, err = cli(capsys, "g2quad", KEYLINE, "--fit", "--edges", "24", "--dxf", "g2.dxf")
    assert code == 0, err
    line = next(ln for ln in out.splitlines() if "starts at" in ln)
    start, end = (np.array([float(v) for v in part.split("(")[1].split(")")[0].split(",")])
                  for part in line.split("ends at"))
    splines = list(ezdxf.readfile("g2.dxf").modelspace().query("SPLINE"))
    first = np.array(splines[0].control_points[0])
    last = np.array(splines[-1].control_points[-1])
    assert start.shape == (3,) and end.shape == (3,)
    np.testing.assert_allclose(start, first, rtol=1e-5)   # printed to 6 digits
    np.testing.assert_allclose(end, last, rtol=1e-5)


def test_mixed_separators_are_named(work, capsys):
    """QA17 P2: ',' and ' ' rows alternating: said as mixed separators (main: "1 column
    where 30 of 59 rows have 2 (an empty cell?)")."""
    pts = read_points(SAMPLE)
    with open("mixed.csv", "w") as f:
        for i, (x, y) in enumerate(pts[:, :2]):
            f.write(f"{x:.6f},{y:.6f}\n" if i % 2 else f"{x:.6f} {y:.6f}\n")
    code, out, err = cli(capsys, "fit", "mixed.csv")
    assert code == 2
    assert "mixed separators" in err and "line 1" in err, err
    assert f"of {len(pts)} rows" in err and "empty cell" not in err


def test_g2quad_reads_a_fits_json_on_standard_input(work, monkeypatch, capsysbinary):
    """`elastica fit a.csv --json - | elastica g2quad -`: '-' was read as points only ("standard
    input: line 61: not a number: ']'"); JSON on standard input is now read as a .json file
    is (the same record but for "file"), and points there as before."""
    code, fit, err = binary(capsysbinary, "fit", "a.csv", "--model", "smooth", "--json", "-")
    assert code == 0, err
    (work / "fit.json").write_bytes(fit)
    code, filed, err = binary(capsysbinary, "g2quad", "fit.json", "--json", "-")
    assert code == 0, err
    stdin(monkeypatch, fit)
    code, piped, err = binary(capsysbinary, "g2quad", "-", "--json", "-")
    assert code == 0 and err == "", err
    a, b = json.loads(filed), json.loads(piped)
    assert b.pop("file") == "-" and a.pop("file") == "fit.json" and a == b
    stdin(monkeypatch, SAMPLE.read_bytes())
    code, pts, err = binary(capsysbinary, "g2quad", "-", "--json", "-")
    code2, pts_file, _ = binary(capsysbinary, "g2quad", "a.csv", "--json", "-")
    a, b = json.loads(pts), json.loads(pts_file)
    assert code == code2 == 0 and a.pop("file") == "-" and b.pop("file") == "a.csv" and a == b
