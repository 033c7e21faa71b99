"""The `elastica` command (python -m libelastica) through subprocess, the way users
run it: exit statuses (0 ok, 1 no convergence, 2 bad input with one line on stderr
and no traceback), JSON that reproduces the geometry, pictures that are written."""
from __future__ import annotations

import json
import os
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica.io import InputError, read_points
from libelastica.report import have_matplotlib

ROOT = Path(__file__).resolve().parents[2]
EX = ROOT / "examples"
SAMPLE_2D = EX / "sample_2d.csv"
SAMPLE_3D = EX / "sample_3d.txt"
SAMPLE_S = EX / "sample_s_curve.csv"


def run(*args, cwd=None, env_extra=None):
    env = dict(os.environ)
    env.update(env_extra or {})
    return subprocess.run([sys.executable, "-m", "libelastica", *map(str, args)], cwd=cwd,
                          env=env, capture_output=True, text=True, timeout=120)


class Result:
    def __init__(self, returncode, stdout, stderr):
        self.returncode, self.stdout, self.stderr = returncode, stdout, stderr


def cli(capsys, *args):
    """The same command in-process (libelastica.cli.main), for the many small cases."""
    from libelastica.cli import main
    capsys.readouterr()
    try:
        code = main([str(a) for a in args])
    except SystemExit as exc:       # argparse: --help, usage errors
        code = exc.code
    out, err = capsys.readouterr()
    return Result(code, out, err)


def assert_one_line_error(r, code=2):
    assert r.returncode == code, (r.returncode, r.stdout, r.stderr)
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1, r.stderr
    assert "Traceback" not in r.stderr and "Traceback" not in r.stdout
    return lines[0]


def svg_ok(path: Path):
    assert path.is_file() and path.stat().st_size > 1000
    root = ET.parse(path).getroot()          # well-formed XML
    assert root.tag.endswith("svg")
    return root


# ------------------------------------------------------------------ help, usage errors

def test_help_lists_commands_with_examples(capsys):
    r = run("--help")
    assert r.returncode == 0
    for cmd in ("fit", "hermite", "bspline", "blend"):
        assert cmd in r.stdout
        rc = cli(capsys, cmd, "--help")
        assert rc.returncode == 0 and "examples:" in rc.stdout, cmd


def test_usage_error_is_one_line():
    assert "error" in assert_one_line_error(run("fit", "x.csv", "--model", "cubic"))


@pytest.mark.parametrize("args", [["fit"], ["hermite", "0", "0", "1"], ["nosuchcommand"],
                                  ["hermite", "0", "0", "1", "0", "1", "0", "1", "0"],
                                  ["fit", "x.csv", "--step", "abc"]])
def test_usage_errors_are_one_line(capsys, args):
    line = assert_one_line_error(cli(capsys, *args))
    assert "error" in line


# ------------------------------------------------------------------ bad input files

BAD = {
    "missing": None,
    "malformed.csv": "x,y\n0,0\n1,abc\n2,1\n",
    "two_points.csv": "0,0\n1,1\n",
    "nan.csv": "0,0\n1,nan\n2,1\n3,0\n",
    "inf.txt": "0 0\n1 inf\n2 1\n3 0\n",
    "four_columns.csv": "0,0,0,0\n1,1,1,1\n2,2,2,2\n",
    "ragged.csv": "0,0\n1,1,1\n2,2\n",
    "empty.csv": "# nothing\n",
    "same_point.csv": "1,1\n1,1\n1,1\n",
}


@pytest.mark.parametrize("name", ["missing", "malformed.csv"])
def test_bad_input_exit_2_one_line_subprocess(tmp_path, name):
    path = tmp_path / name
    if BAD[name] is not None:
        path.write_text(BAD[name])
    line = assert_one_line_error(run("fit", path, "--svg", tmp_path / "out.svg"))
    assert name in line                      # the message names the file
    assert not (tmp_path / "out.svg").exists()


@pytest.mark.parametrize("name", sorted(BAD))
def test_bad_input_exit_2_one_line(capsys, tmp_path, name):
    path = tmp_path / name
    if BAD[name] is not None:
        path.write_text(BAD[name])
    line = assert_one_line_error(cli(capsys, "fit", path, "--svg", tmp_path / "out.svg"))
    assert name in line
    assert not (tmp_path / "out.svg").exists()


def test_bad_npy_exit_2(capsys, tmp_path):
    np.save(tmp_path / "flat.npy", np.arange(10.0))
    assert_one_line_error(cli(capsys, "fit", tmp_path / "flat.npy"))
    (tmp_path / "junk.npy").write_bytes(b"not numpy")
    assert_one_line_error(cli(capsys, "fit", tmp_path / "junk.npy"))


def test_bad_numbers_on_command_line(capsys):
    assert_one_line_error(cli(capsys, "hermite", "0", "0", "1", "0", "nan", "0", "1", "0",
                              "--tension", "1"))
    assert_one_line_error(cli(capsys, "hermite", "0", "0", "1", "0", "0", "0", "1", "0",
                              "--tension", "1"))         # p0 == p1: DomainError -> 2
    assert_one_line_error(cli(capsys, "blend", "0", "0", "0", "0", "0", "0", "1", "1"))


# ------------------------------------------------------------------ readers

def test_read_points_formats(tmp_path):
    pts = np.array([[0.0, 0.0], [1.0, 0.5], [2.0, 0.7], [3.0, 0.6]])
    (tmp_path / "a.csv").write_text("# comment\nx,y\n" + "".join(f"{x},{y}\n" for x, y in pts))
    (tmp_path / "b.txt").write_text("".join(f"  {x}\t{y}  \n" for x, y in pts) + "\n")
    (tmp_path / "c.csv").write_text("".join(f"{x};{y}\n" for x, y in pts))
    np.save(tmp_path / "d.npy", pts)
    for name in ("a.csv", "b.txt", "c.csv", "d.npy"):
        got = read_points(tmp_path / name)
        assert got.dtype == np.float64 and got.flags.c_contiguous
        np.testing.assert_array_equal(got, pts)
    assert read_points(SAMPLE_3D).shape[1] == 3
    with pytest.raises(InputError):
        read_points(tmp_path / "a.csv", min_points=5)


def test_read_points_as_scanners_and_spreadsheets_write_them(tmp_path):
    """Semicolons or tabs with decimal commas (spreadsheets, digitisers in many locales),
    other files with tabs as they were read; a header that names
    the coordinate columns picks them by name, out of more columns (point ids, normals)
    or in another order ("id,x,y" read the ids as x before), the other columns text too (a
    survey's point names: "name,x,y,z" was refused, QA); more than 3 columns without such
    names, or with a name twice, is refused naming the way out."""
    pts = np.array([[0.0, -1.25], [1.5, 0.5], [2.0, 0.75], [3.0, 1e3]])
    z = np.array([0.5, 0.25, -3.0, 2.0])
    files = {
        "comma.csv": "x;y\n" + "".join(f"{x};{y}\n".replace(".", ",") for x, y in pts),
        "units.csv": "X [mm]; Y [mm]\n" + "".join(f"{x:.2f};{y:.2f}\n".replace(".", ",")
                                                  for x, y in pts),
        # tabs with decimal commas (a digitiser's export; refused as 'not a number', QA),
        # tabs with decimal points, and a comma-separated file with a tab after the commas
        "tabs.txt": "x\ty\n" + "".join(f"{x}\t{y}\n".replace(".", ",") for x, y in pts),
        "tabs_points.txt": "".join(f"{x}\t{y}\n" for x, y in pts),
        "comma_tab.csv": "".join(f"{x},\t{y}\n" for x, y in pts),
        "ids.csv": "id,x,y\n" + "".join(f"{i + 7},{x},{y}\n" for i, (x, y) in enumerate(pts)),
        "swapped.txt": "y x\n" + "".join(f"{y} {x}\n" for x, y in pts),
        "scan.csv": "id,x,y,z,nx,ny,nz\n" + "".join(f"{i},{x},{y},{c},0,0,1\n"
                                                     for i, ((x, y), c) in enumerate(zip(pts, z))),
        "survey.csv": "name,x,y,z\n" + "".join(f"P{i},{x},{y},{c}\n"
                                               for i, ((x, y), c) in enumerate(zip(pts, z))),
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text)
        got = read_points(tmp_path / name)
        want = np.c_[pts, z] if name in ("scan.csv", "survey.csv") else pts
        np.testing.assert_array_equal(got, want, err_msg=name)
    for text in ("1,2,3,4\n5,6,7,8\n9,1,2,3\n", "a,b,c,d\n1,2,3,4\n5,6,7,8\n9,1,2,3\n",
                 "x,x,y,z\n1,2,3,4\n5,6,7,8\n9,1,2,3\n"):
        (tmp_path / "bad.csv").write_text(text)
        with pytest.raises(InputError, match="name the coordinates x, y"):
            read_points(tmp_path / "bad.csv")
    (tmp_path / "names.csv").write_text("P0,1,2\nP1,3,4\nP2,5,7\n")       # no header: no names
    with pytest.raises(InputError, match="line 1: not a number"):
        read_points(tmp_path / "names.csv")


def test_read_points_with_quoted_or_spaced_decimal_commas(capsys, tmp_path):
    """A spreadsheet's export with ',' between the columns quotes its decimal commas
    ("102,697","4,576": csv's quoting rules keep them one field; refused as 'not a
    number in '102,697,4,576'', the fields joined again, QA), and a space-separated export
    writes them bare: both read, by read_points and by `elastica fit`. Unquoted decimal
    commas between commas are ambiguous: refused, the message saying so; a field that is
    no number is named as read. Every number of these is written d,ddd (3 decimals), as
    English thousands (#,##0) also write them: the user says which (--thousands none),
    as for a tab file (test_read_comma_thousands.py)."""
    pts = np.array([[102.697, 4.576], [98.1, 15.2], [90.3, 25.9], [79.9, 35.1],
                    [66.0, 43.3], [50.2, 49.6], [33.4, 53.4], [16.0, 55.2]])
    files = {
        "quoted.csv": "x,y\n" + "".join(f'"{x:.3f}","{y:.3f}"\n'.replace(".", ",") for x, y in pts),
        "spaces.txt": "x y\n" + "".join(f"{x:.3f}  {y:.3f}\n".replace(".", ",") for x, y in pts),
    }
    for name, text in files.items():
        (tmp_path / name).write_text(text)
        with pytest.raises(InputError, match="'102,697' is 102.697 or 102697"):
            read_points(tmp_path / name)
        np.testing.assert_array_equal(read_points(tmp_path / name, thousands=""), pts,
                                      err_msg=name)
        r = cli(capsys, "fit", tmp_path / name, "--thousands", "none", "--json",
                tmp_path / "f.json")
        assert r.returncode == 0, (name, r.stderr)
        assert json.loads((tmp_path / "f.json").read_text())["rms"] < 1.0, name
    (tmp_path / "bare.csv").write_text("x,y\n" + "".join(f"{x:.3f},{y:.3f}\n".replace(".", ",")
                                                          for x, y in pts))
    with pytest.raises(InputError, match="decimal commas.* quoted"):
        read_points(tmp_path / "bare.csv")
    (tmp_path / "word.csv").write_text('x,y\n"1,5","0,25"\n"2,5",abc\n"3,5","1,0"\n')
    with pytest.raises(InputError, match="line 3: not a number: 'abc'$"):
        read_points(tmp_path / "word.csv")


def _rows(n=40):
    """A German spreadsheet's rows: semicolons and decimal commas."""
    return [f"{i},5;{i * i / 10:.2f}".replace(".", ",") for i in range(n)]


def test_read_points_skips_a_title_and_reads_cp1252(capsys, tmp_path):
    """QA: a title line above the header was refused ('line 2: not a number: 'x''), a German
    Excel export's cp1252 header 'x (L\xe4nge)' too ('cannot read as text'); both read to the
    array of the clean file, by read_points and by `elastica fit`."""
    clean = tmp_path / "clean.csv"
    clean.write_text("x;y\n" + "\n".join(_rows()) + "\n")
    want = read_points(clean)
    files = {"title.csv": ("Profil 7 / Scan 2026-12-01\nx;y\n" + "\n".join(_rows())).encode(),
             "cp1252.csv": ("x (L\xe4nge);y (H\xf6he)\n" + "\n".join(_rows())).encode("cp1252"),
             "both.csv": ("Profil 7 \u2013 Scan\n\nx (L\xe4nge);y (H\xf6he)\n"
                          + "\n".join(_rows())).encode("cp1252"),
             "utf16.txt": ("Profil 7\r\nx (L\xe4nge)\ty\r\n"     # Excel's "Unicode text"
                           + "\r\n".join(r.replace(";", "\t") for r in _rows())).encode("utf-16")}
    for name, data in files.items():
        (tmp_path / name).write_bytes(data)
        np.testing.assert_array_equal(read_points(tmp_path / name), want, err_msg=name)
    r = cli(capsys, "fit", tmp_path / "both.csv", "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    # a line with a number is never skipped as a title: refused, naming it
    (tmp_path / "numeric.csv").write_text("Scan 7;2\nx;y\n" + "\n".join(_rows()))
    with pytest.raises(InputError, match="numeric.csv: line 1: not a number: 'Scan 7'"):
        read_points(tmp_path / "numeric.csv")


def test_read_points_messages_name_the_line(capsys, tmp_path):
    """QA: an empty cell said 'rows have different numbers of columns [1, 2]', bytes that
    are no text 'cannot read as text (UnicodeDecodeError)': each names its line now."""
    rows = _rows()
    (tmp_path / "empty.csv").write_text("x;y\n" + "\n".join(rows[:23] + ["23,5;"] + rows[24:]))
    with pytest.raises(InputError, match=r"empty.csv: line 25: 1 column where 39 of 40 rows "
                                         r"have 2 \(an empty cell\?\)"):
        read_points(tmp_path / "empty.csv")
    r = cli(capsys, "fit", tmp_path / "empty.csv")
    assert r.returncode == 2 and "line 25" in r.stderr
    (tmp_path / "binary.csv").write_bytes(("x;y\n" + "\n".join(rows[:5])).encode()
                                          + b"\n7;\x81\n" + "\n".join(rows[5:]).encode())
    with pytest.raises(InputError, match="line 7: byte 0x81 is neither UTF-8 nor Windows-1252"):
        read_points(tmp_path / "binary.csv")
    (tmp_path / "nan.csv").write_text("x,y\n0,0\n1,nan\n2,1\n3,0\n")
    with pytest.raises(InputError, match="nan.csv: line 3: not finite: 'nan'"):
        read_points(tmp_path / "nan.csv")


def test_read_points_at_any_line_end(capsys, tmp_path):
    """QA19 M0: a file whose lines end in CR alone (classic Mac, some instruments' exports)
    stopped `elastica fit` with "internal error: ... new-line character seen in unquoted
    field", exit 3, and a batch holding it wrote nothing for its good files. Read like the
    same rows ending in LF, at every separator; csv's own errors name the line."""
    rows = _rows()
    for sep in (";", ","):
        body = [r if sep == ";" else '"' + r.replace(";", '","') + '"' for r in rows]
        (tmp_path / "lf.csv").write_text("x" + sep + "y\n" + "\n".join(body) + "\n")
        (tmp_path / "cr.csv").write_bytes(("x" + sep + "y\r" + "\r".join(body) + "\r").encode())
        np.testing.assert_array_equal(read_points(tmp_path / "cr.csv"),
                                      read_points(tmp_path / "lf.csv"), err_msg=sep)
    r = cli(capsys, "fit", SAMPLE_2D, tmp_path / "cr.csv", "--json", "-")
    assert r.returncode == 0, r.stderr
    assert all(rec["converged"] for rec in json.loads(r.stdout))
    (tmp_path / "long.csv").write_text("x,y\n0,0\n1," + "1" * 200000 + "\n2,4\n3,9\n")
    with pytest.raises(InputError, match=r"long.csv: line 3: field larger than field limit"):
        read_points(tmp_path / "long.csv")


def test_fit_batch_goes_on_past_an_internal_error(capsys, tmp_path, monkeypatch):
    """QA19 M0: an internal error (a bug) met on one file of a batch ended the whole batch
    with nothing written for the files before and after it; now that file's row says
    "internal error", the others are fitted and written, and the exit status is 3."""
    import libelastica.cli_fit as cli_fit
    real = cli_fit.fit_file

    def broken(f, args, batch=False):
        if Path(f).name == "bug.csv":
            raise RuntimeError("a bug")
        return real(f, args, batch=batch)
    monkeypatch.setattr(cli_fit, "fit_file", broken)
    (tmp_path / "bug.csv").write_text(SAMPLE_2D.read_text())
    r = cli(capsys, "fit", SAMPLE_2D, tmp_path / "bug.csv", SAMPLE_S,
            "--json", tmp_path / "out" / "{stem}.json")
    assert r.returncode == 3, r.stderr
    assert "1 of 3 files met an internal error" in r.stderr
    assert "internal error: RuntimeError: a bug" in r.stdout
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["sample_2d.json",
                                                                    "sample_s_curve.json"]


def test_fit_batch_records_a_file_that_did_not_converge(capsys, tmp_path, monkeypatch):
    """A batch's file whose fit raised NotConvergedError left ``doc`` unset: a first file so
    ended the batch in an UnboundLocalError (exit 3), a later one put the file before's
    document in the batch's JSON in its place; now its document is its failure record, as
    bad input's and a bug's are."""
    import libelastica.cli_fit as cli_fit
    from libelastica._ffi import lib
    real = cli_fit.fit_file

    def stuck(f, args, batch=False):
        if Path(f).name.startswith("stuck"):
            raise el.NotConvergedError(lib.EL_ENOCONV, "no convergence here")
        return real(f, args, batch=batch)
    monkeypatch.setattr(cli_fit, "fit_file", stuck)
    for name in ("stuck1.csv", "stuck2.csv"):
        (tmp_path / name).write_text(SAMPLE_2D.read_text())
    files = [tmp_path / "stuck1.csv", SAMPLE_2D, tmp_path / "stuck2.csv"]
    r = cli(capsys, "fit", *files, "--json", tmp_path / "all.json")
    assert r.returncode == 1, r.stderr
    assert r.stdout.count("not converged: no convergence here") == 2
    docs = json.loads((tmp_path / "all.json").read_text())
    assert [d["file"] for d in docs] == [str(f) for f in files]
    for d in (docs[0], docs[2]):
        assert d["status"] == "not converged: no convergence here" and d["curve"] is None
    assert docs[1]["curve"] is not None


# ------------------------------------------------------------------ hermite

def test_hermite_table_json_and_svg(capsys, tmp_path):
    args = ["0", "0", "0", "1", "2", "0", "0", "-1", "--length", "4"]
    sols = el.hermite((0, 0), (0, 1), (2, 0), (0, -1), length=4.0)
    assert sols
    r = run("hermite", *args, "--svg", tmp_path / "h.svg",
            env_extra={"LIBELASTICA_NO_MATPLOTLIB": "1"})       # the built-in writer's polylines
    assert r.returncode == 0, r.stderr
    table = [ln for ln in r.stdout.splitlines()[2:] if ln.strip()][:-1]   # then the fair ones
    assert len(table) == len(sols) and r.stdout.splitlines()[-1].startswith("by energy;")
    root = svg_ok(tmp_path / "h.svg")
    assert sum(1 for e in root.iter() if e.tag.endswith("polyline")) >= len(sols)
    doc = json.loads(cli(capsys, "hermite", *args, "--json", "-").stdout)
    assert len(doc["solutions"]) == len(sols)
    for s in doc["solutions"]:
        c = el.SmoothElastica(**{k: v for k, v in s["curve"].items() if k != "type"})
        ends = c.points([0.0, c.length])     # every solution runs p0 -> p1
        assert "reversed" not in s
        np.testing.assert_allclose(ends, [[0, 0], [2, 0]], atol=1e-7)
        assert c.length == pytest.approx(4.0)


def test_hermite_chains_in_json_svg_and_bspline(capsys, tmp_path):
    """High tension: the solutions near the separatrix are chains; the JSON holds them
    as {"type": "chain", "pieces": [...]}, which rebuild to the same curve from p0 to
    p1, the picture draws every solution, and `bspline` converts a chain to one B-spline."""
    args = ["0", "0", "1", "0", "1", "0.2", "1", "0.1", "--tension", "1500"]
    r = run("hermite", *args, "--svg", tmp_path / "h.svg", env_extra={"LIBELASTICA_NO_MATPLOTLIB": "1"})
    assert r.returncode == 0, r.stderr
    doc = json.loads(cli(capsys, "hermite", *args, "--json", "-").stdout)
    kinds = [s["curve"]["type"] for s in doc["solutions"]]
    assert "chain" in kinds
    root = svg_ok(tmp_path / "h.svg")
    assert sum(1 for e in root.iter() if e.tag.endswith("polyline")) >= len(kinds)
    for s in doc["solutions"]:
        c = el.io.curve_from_dict(s["curve"])
        np.testing.assert_allclose(c.points([0.0, c.length]), [[0, 0], [1, 0.2]], atol=1e-9)
    chain = next(s for s in doc["solutions"] if s["curve"]["type"] == "chain")
    (tmp_path / "c.json").write_text(json.dumps(chain))
    out = json.loads(cli(capsys, "bspline", tmp_path / "c.json", "--tol", "1e-6", "--json", "-").stdout)
    assert out["curve"]["type"] == "chain" and 0 <= out["bspline"]["max_deviation"] <= 1e-6


def test_png_or_clear_error(tmp_path):
    out = tmp_path / "h.png"
    r = run("hermite", "0", "0", "1", "0", "1", "0", "1", "0", "--tension", "10", "--png", out)
    if have_matplotlib():
        assert r.returncode == 0, r.stderr
        assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    else:
        assert "matplotlib" in assert_one_line_error(r)


def test_svg_without_matplotlib(capsys, monkeypatch, tmp_path):
    """The built-in SVG writer (forced) draws the same picture without matplotlib."""
    out = tmp_path / "b.svg"
    r = run("blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--svg", out,
            env_extra={"LIBELASTICA_NO_MATPLOTLIB": "1"})
    assert r.returncode == 0, r.stderr
    root = svg_ok(out)
    texts = " ".join(e.text or "" for e in root.iter() if e.tag.endswith("text"))
    assert "curvature" in texts and "k = 0.5" in texts
    monkeypatch.setenv("LIBELASTICA_NO_MATPLOTLIB", "1")
    r = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--png",
            tmp_path / "b.png")
    assert "matplotlib" in assert_one_line_error(r)


# ------------------------------------------------------------------ fit

def _dist_to_curve(data, curve_dict):
    from libelastica.io import curve_from_dict
    from libelastica.report import closest_points
    c = curve_from_dict(curve_dict)
    xy = c.points(np.linspace(0, c.length, 2000)) if curve_dict["type"] == "smooth" else c.points()
    return np.linalg.norm(closest_points(data, xy) - data, axis=1)


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_fit_2d_json_svg(tmp_path, model):
    data = read_points(SAMPLE_2D)
    # discrete: matplotlib's SVG where installed; smooth: the built-in writer
    env = {"LIBELASTICA_NO_MATPLOTLIB": "1"} if model == "smooth" else {}
    r = run("fit", SAMPLE_2D, "--model", model, "--json", tmp_path / "f.json",
            "--svg", tmp_path / "f.svg", env_extra=env)
    assert r.returncode == 0, r.stderr
    assert "rms" in r.stdout
    doc = json.loads((tmp_path / "f.json").read_text())
    assert doc["converged"] and doc["curve"]["type"] == model
    assert doc["max_error"] >= doc["rms"] > 0
    d = _dist_to_curve(data, doc["curve"])       # sample noise: sigma 0.2 per coordinate
    assert d.max() < 1.5 and np.sqrt(np.mean(d ** 2)) < 0.5
    svg_ok(tmp_path / "f.svg")


def test_fit_3d_reports_the_plane(capsys, tmp_path):
    r = cli(capsys, "fit", SAMPLE_3D, "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    assert "plane fit" in r.stdout
    doc = json.loads((tmp_path / "f.json").read_text())
    n = np.array(doc["plane"]["normal"])
    # sample_3d.txt is sample_2d.csv rotated so that the plane normal is (0.6, 0, 0.8)
    assert abs(abs(n @ [0.6, 0.0, 0.8]) - 1.0) < 1e-3
    assert doc["plane"]["rms"] < 0.1
    assert doc["converged"] and doc["rms"] < 0.5


def test_fit_fix_start(capsys, tmp_path):
    data = read_points(SAMPLE_2D)
    r = cli(capsys, "fit", SAMPLE_2D, "--fix", "x0,y0", "--json", "-")
    assert r.returncode == 0, r.stderr
    c = json.loads(r.stdout)["curve"]
    assert (c["x0"], c["y0"]) == pytest.approx(tuple(data[0]), abs=1e-12)


def test_fit_keyline_two_sides(capsys, tmp_path):
    r = cli(capsys, "fit", SAMPLE_S, "--keyline", "--json", tmp_path / "k.json",
            "--svg", tmp_path / "k.svg")
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "k.json").read_text())
    assert len(doc["sides"]) == 2
    for side in doc["sides"]:
        assert side["converged"] and side["rms"] < 0.3      # sample noise sigma 0.1
        assert 0.9 * side["step"] < side["curve"]["h"] <= 1.01 * side["step"]   # h free (§5.4)
        assert len(side["distances"]) == side["n_points"] == len(side["foot_s"])
        assert np.sqrt(np.mean(np.square(side["distances"]))) == pytest.approx(side["rms"], rel=1e-12)
    a, b = (s["curve"] for s in doc["sides"])
    assert (a["x0"], a["y0"]) == pytest.approx((b["x0"], b["y0"]), abs=1e-12)  # one joint
    # the generating elastica (see the file's header) inflects where u = K(0.9)
    c = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.265625e-4, k=0.9, q=1.2, length=240)
    from scipy.special import ellipk
    true = c.points([(ellipk(0.81) - 1.2) / np.sqrt(c.mu)])[0]
    assert np.linalg.norm(np.array(doc["sides"][0]["inflection_point"]) - true) < 25.0
    svg_ok(tmp_path / "k.svg")


def test_fit_orthogonal_distances_and_constraints(capsys, tmp_path):
    """The smooth fit reports point-to-curve distances; end constraints from the command
    line are met (the first/last points, a tangent in degrees); one that cannot be met
    exits 2 naming it."""
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--json", tmp_path / "o.json")
    assert r.returncode == 0, r.stderr
    doc = json.loads((tmp_path / "o.json").read_text())
    assert doc["distance"] == "orthogonal" and len(doc["distances"]) == doc["n_points"]
    assert np.sqrt(np.mean(np.square(doc["distances"]))) == pytest.approx(doc["rms"], rel=1e-12)
    pts = np.loadtxt(SAMPLE_S, delimiter=",", skiprows=2)
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--start-point", "first", "--end-point", "last",
            "--start-tangent", "100", "--json", tmp_path / "c.json")
    assert r.returncode == 0, r.stderr
    c = el.io.curve_from_dict(json.loads((tmp_path / "c.json").read_text()))
    ends = c.points(np.array([0.0, c.length]))
    assert np.max(np.abs(ends - pts[[0, -1]])) <= 1e-9 * c.length
    assert abs(np.remainder(c.angle([0.0])[0] - np.radians(100) + np.pi, 2 * np.pi) - np.pi) <= 1e-9
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--start-point", "0,0", "--end-point", "1000,0",
            "--length", ",300")
    assert r.returncode == 2 and "length" in r.stderr
    r = cli(capsys, "fit", SAMPLE_S, "--distance", "paired", "--json", "-")   # the discrete model
    assert r.returncode == 0 and json.loads(r.stdout)["distance"] == "paired"
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--distance", "paired", "--json", "-")
    assert r.returncode == 0 and json.loads(r.stdout)["distance"] == "paired"


def test_fit_one_length_is_that_length(capsys):
    """`fit --length L` fits a curve of length L, as hermite's and spline's --length L
    (it was read as L or more: `--length 95` fitted the sample 99.7 long, exit 0); LO,HI
    stays a range, ',HI' an upper bound."""
    lengths = {}
    for spec in ("95", "95,95", "95,", ",95"):
        r = cli(capsys, "fit", SAMPLE_2D, "--model", "smooth", "--length", spec, "--json", "-")
        assert r.returncode == 0, r.stderr
        lengths[spec] = json.loads(r.stdout)["curve"]["length"]
    free = json.loads(cli(capsys, "fit", SAMPLE_2D, "--model", "smooth", "--json", "-").stdout)
    assert free["curve"]["length"] > 95 + 1
    assert lengths["95"] == pytest.approx(95, rel=1e-9) == lengths["95,95"]
    assert lengths["95,"] == pytest.approx(free["curve"]["length"], rel=1e-6)
    assert lengths[",95"] == pytest.approx(95, rel=1e-9)
    r = cli(capsys, "fit", SAMPLE_2D, "--length", "x")
    assert r.returncode == 2 and "--length: expected V or LO,HI" in r.stderr


def test_fit_discrete_bspline_keeps_the_end_constraints(capsys, tmp_path):
    """A discrete fit's B-spline (--bspline-tol, --dxf: the C2 cubic through its vertices)
    takes the constrained ends: a start tangent with a curvature (G2: both exactly), an end
    tangent (clamped), and so does `elastica bspline` of the fit's JSON; without
    constraints its ends are natural (curvature 0)."""
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--json", "-")
    c = el.io.curve_from_dict(json.loads(r.stdout)["curve"])
    a0, a1 = np.degrees(c.angle([0.0, c.length]))
    k0 = float(c.curvature([0.0])[0])
    r = cli(capsys, "fit", SAMPLE_S, "--start-tangent", a0, "--start-curvature", k0,
            "--end-tangent", a1, "--bspline-tol", "1e-6", "--json", "-")
    assert r.returncode == 0, r.stderr
    b = el.BSpline.from_dict(json.loads(r.stdout)["bspline"])
    d = b.derivative(np.array(b.domain), 1)
    got = np.degrees(np.arctan2(d[:, 1], d[:, 0]))
    assert np.max(np.abs(np.remainder(got - [a0, a1] + 180.0, 360.0) - 180.0)) < 1e-9
    assert abs(b.curvature([b.domain[0]])[0] - k0) <= 1e-9 * abs(k0)
    # the fit's JSON carries its constraints: `elastica bspline` makes the same B-spline
    (tmp_path / "f.json").write_text(r.stdout)
    r2 = cli(capsys, "bspline", tmp_path / "f.json", "--json", "-")
    assert r2.returncode == 0, r2.stderr
    again = el.BSpline.from_dict(json.loads(r2.stdout)["bspline"])
    assert np.array_equal(again.poles, b.poles) and np.array_equal(again.knots, b.knots)
    r = cli(capsys, "fit", SAMPLE_S, "--bspline-tol", "1e-6", "--json", "-")
    b = el.BSpline.from_dict(json.loads(r.stdout)["bspline"])
    assert np.max(np.abs(b.curvature(np.array(b.domain)))) < 1e-12


def test_fit_keyline_3d(capsys, tmp_path):
    r = cli(capsys, "fit", EX / "keyline_3d.csv", "--keyline", "--step", "3", "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    assert doc["sides"][0]["plane"]["rms"] < 1.0
    assert len(doc["sides"][0]["inflection_point"]) == 3       # mapped back to 3D
    # the file's own points to the keyline (the sides' figures are the resampled polygon's)
    kf = el.fit_keyline(read_points(EX / "keyline_3d.csv"), r=3)
    side = doc["sides"][0]
    assert side["input_points"] == 161 and side["input_rms"] == pytest.approx(kf.input_rms, rel=1e-12)
    assert side["input_max_error"] == pytest.approx(kf.input_max_error, rel=1e-12)
    r = cli(capsys, "fit", EX / "keyline_3d.csv", "--keyline", "--step", "3")
    assert f"keyline     rms {kf.input_rms:.6g}, max error {kf.input_max_error:.6g}" in r.stdout
    assert "(the file's 161 points to the keyline, in its plane)" in r.stdout


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_fit_keyline_bspline_is_one_curve_through_the_joint(capsys, tmp_path, fake_ezdxf, model):
    """--keyline with --bspline-tol / --dxf writes ONE B-spline from the first point to the
    last through the joint (two natural cubics of a discrete keyline each left the joint
    with its own tangent): the document's "bspline" and the DXF's one SPLINE, in the input's
    coordinates (the sides' curves: x''y'', "frame2d"); discrete, through every vertex of both sides, the joint once, to each
    side's "end"; smooth,
    on both halves to its certified deviation, the joint's tangent and zero curvature
    exact; `elastica bspline` of the fit's JSON gives the same B-spline."""
    r = cli(capsys, "fit", SAMPLE_S, "--keyline", "--model", model, "--bspline-tol", "1e-6",
            "--json", tmp_path / "k.json", "--dxf", tmp_path / "k.dxf")
    assert r.returncode == 0, r.stderr
    assert "B-spline    of the keyline" in r.stdout
    doc = json.loads((tmp_path / "k.json").read_text())
    assert all("bspline" not in side for side in doc["sides"])
    b_in = el.BSpline.from_dict(doc["bspline"])
    f = {k: np.array(v) for k, v in doc["sides"][0]["frame2d"].items()}   # input -> x''y''
    b = b_in.mapped(lambda p: (p - f["origin"]) @ np.c_[f["f1"], f["f2"]])
    first, second = (el.io.curve_from_dict(side["curve"]) for side in doc["sides"])
    if model == "discrete":      # each half continued to its "end" (KeylineFit.ends)
        tails = [c.continued_to(side["end"]) for c, side in zip((first, second), doc["sides"])]
        v = np.vstack([tails[0][::-1], first.points()[::-1], second.points()[1:], tails[1]])
        np.testing.assert_allclose(b(np.array(b.domain)), [side["end"] for side in doc["sides"]],
                                   rtol=0, atol=1e-9 * b.domain[1])
        t = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(v, axis=0), axis=1))])
        assert np.max(np.abs(b(t) - v)) <= 1e-9 * t[-1]
    else:
        s1, s2 = np.linspace(0.0, first.length, 200), np.linspace(0.0, second.length, 200)
        on_halves = np.vstack([first.points(s1), second.points(s2)])
        t = np.concatenate([first.length - s1, first.length + s2])   # near arc length
        for _ in range(4):         # the feet on the B-spline (Newton on (b - p) . b' = 0)
            d, d1, d2 = b(t) - on_halves, b.derivative(t), b.derivative(t, 2)
            t = np.clip(t - np.sum(d * d1, 1) / np.sum(d1 * d1 + d * d2, 1), *b.domain)
        assert np.max(np.linalg.norm(b(t) - on_halves, axis=1)) <= b.max_deviation <= 1e-6
        a = second.angle([0.0])[0]
        tangent = b.derivative([first.length])[0]
        u = tangent / np.linalg.norm(tangent)
        assert u[0] * np.sin(a) - u[1] * np.cos(a) == pytest.approx(0.0, abs=1e-12)
        assert abs(b.curvature([first.length])[0]) <= 1e-9 * np.max(np.abs(b.curvature(s1)))
    (_, ctrl, _, _, _), = [c for c in fake_ezdxf if c[0] == "spline"]
    np.testing.assert_allclose(np.array(ctrl)[:, :2], b_in.poles, rtol=0, atol=1e-9 * b.domain[1])
    r = cli(capsys, "bspline", tmp_path / "k.json", *(["--tol", "1e-6"] if model == "smooth" else []),
            "--json", "-")
    assert r.returncode == 0, r.stderr
    again = json.loads(r.stdout)
    assert len(again["sides"]) == 2
    np.testing.assert_allclose(el.BSpline.from_dict(again["bspline"]).poles, b_in.poles, rtol=0,
                               atol=1e-12 * b.domain[1])
    if model == "discrete":      # a batch's JSON: each file's document, as one file's
        r = cli(capsys, "fit", SAMPLE_S, SAMPLE_S, "--keyline", "--bspline-tol", "1e-6",
                "--json", tmp_path / "all.json")
        assert r.returncode == 0, r.stderr
        docs = json.loads((tmp_path / "all.json").read_text())
        assert [len(d["sides"]) for d in docs] == [2, 2] and all("bspline" in d for d in docs)
        r = cli(capsys, "bspline", tmp_path / "all.json", "--json", tmp_path / "all_b.json")
        out = json.loads((tmp_path / "all_b.json").read_text())
        assert [len(d["sides"]) for d in out["sides"]] == [2, 2]
        r = cli(capsys, "bspline", tmp_path / "all_b.json", "--json", "-")     # its own output again
        assert r.returncode == 0, r.stderr
        assert [d["bspline"] for d in json.loads(r.stdout)["sides"]] == [d["bspline"] for d in out["sides"]]


def test_fit_warns_of_a_curve_that_swings_between_two_points(tmp_path):
    """A sketch whose fit hooks away between its last two points (fit_data.swinging_sketch):
    one warning on stderr in the command's words, naming the gap, the points' places and
    what holds the curve there, the exit code 0, the JSON record's "wander_gap"; the sample
    S, which its fit follows, gives no such warning and no "wander_gap"."""
    from fit_data import swinging_sketch
    path = tmp_path / "sketch.csv"
    np.savetxt(path, swinging_sketch(), delimiter=",", header="x,y", comments="")
    r = run("fit", path, "--model", "smooth", "--json", "-")
    assert r.returncode == 0, r.stderr
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(f"elastica fit: warning: {path}: "), r.stderr
    assert ("between points 16 and 17 (counted from 0; at (-18.68, 53.13) and (-11.94, 96.06))"
            in lines[0] and "add a point between them, or bound the length (--length LO,HI)" in lines[0])
    assert json.loads(r.stdout)["wander_gap"] == 16
    r = run("fit", SAMPLE_S, "--json", "-")
    assert r.returncode == 0 and "wander" not in r.stderr and "wander_gap" not in json.loads(r.stdout)


def test_fit_warns_of_points_far_from_the_curve(capsys, tmp_path):
    """Three glitches in a scan: a warning on stderr names them (points 10, 30, 45 of the
    file, their distances), the fit's exit code unchanged, the JSON record lists them as
    "outliers"; the sample's own points give no such warning."""
    c = el.SmoothElastica(x0=0, y0=0, phi=0.3, mu=1 / 80 ** 2, k=0.7, q=0.2, length=250)
    pts = c.points(np.linspace(0, 250, 60)) + np.random.default_rng(3).normal(0, 0.1, (60, 2))
    pts[[10, 30, 45]] += [[15, -10], [-12, 8], [20, 20]]
    path = tmp_path / "scan.csv"
    np.savetxt(path, pts, delimiter=",", header="x,y", comments="")
    r = cli(capsys, "fit", path, "--model", "smooth", "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    assert "3 of 60 points lie" in r.stderr and "points 10, 30, 45, counted from 0" in r.stderr
    assert json.loads((tmp_path / "f.json").read_text())["outliers"] == [10, 30, 45]
    r = cli(capsys, "fit", SAMPLE_S, "--json", "-")
    assert r.returncode == 0 and "outliers" not in r.stderr
    assert json.loads(r.stdout)["outliers"] == []
    # a constrained fit: the glitches still named; the end points a length held short of
    # the data's leaves 2.2 off (the others within 0.5) are the constraint's cost, not
    # outliers to remove (QA: "points 0, 29 ... remove them to fit the rest")
    r = cli(capsys, "fit", path, "--model", "smooth", "--start-tangent", "17", "--json", "-")
    assert r.returncode == 0 and json.loads(r.stdout)["outliers"] == [10, 30, 45], r.stderr
    # ... said by their distances from the fit with free ends, where they stand apart (from
    # the constrained curve a glitch 6 off lay 2.34, "the others within 2.56", QA)
    free = np.abs(json.loads(cli(capsys, "fit", path, "--model", "smooth", "--json", "-").stdout)
                  ["distances"])
    rest = np.delete(free, [10, 30, 45]).max()
    assert (f"3 of 60 points lie {free[[10, 30, 45]].min():.3g} to {free[[10, 30, 45]].max():.3g} "
            f"from the curve with free ends, the others within {rest:.3g}") in r.stderr
    r = cli(capsys, "fit", SAMPLE_2D, "--model", "smooth", "--length", "95", "--json", "-")
    d = np.abs(json.loads(r.stdout)["distances"])
    assert r.returncode == 0 and min(d[0], d[-1]) > 4 * max(d[1:-1])
    assert "outliers" not in r.stderr and json.loads(r.stdout)["outliers"] == []
    # in a batch with its progress bar: the warning on a line of its own, the bar's line
    # wiped before it (it was written after the bar, "[###...] 1/3 s.csv  elastica fit: ...")
    r = cli(capsys, "fit", SAMPLE_S, path, SAMPLE_2D, "--progress", "--json", tmp_path / "b.json")
    assert r.returncode == 0, r.stderr
    warned = [line for line in r.stderr.split("\n") if "warning:" in line]
    assert len(warned) == 1 and "3 of 60 points lie" in warned[0]
    *before, shown = warned[0].split("\r")
    assert shown.startswith("elastica fit: warning:") and before[-1].strip() == "", warned[0]
    assert r.stderr.rstrip("\n").split("\r")[-1].startswith("[" + "#" * 30 + "] 3/3")


@pytest.mark.parametrize("case", ["3D one piece", "2D keyline", "3D keyline"])
def test_bspline_of_a_fit_json_writes_the_dxf_in_the_inputs_coordinates(capsys, tmp_path,
                                                                        fake_ezdxf, case):
    """`elastica bspline fit.json --dxf` writes the same SPLINE as `elastica fit --dxf`: in
    the input's coordinates (3D for a 3D scan, the input's axes for a keyline's x''y''), not
    the curve's own (it drew a 3D scan's curve in its fit plane's coordinates, at the origin).
    `bspline` of its own JSON gives that SPLINE again (its records lost the plane, the frame
    and a keyline's sides: a keyline came back as two splines, in the curve's coordinates)."""
    args = {"3D one piece": [SAMPLE_3D, "--model", "smooth"], "2D keyline": [SAMPLE_S, "--keyline"],
            "3D keyline": [EX / "keyline_3d.csv", "--keyline", "--step", "3"]}[case]
    r = cli(capsys, "fit", *args, "--json", tmp_path / "f.json", "--dxf", tmp_path / "f.dxf")
    assert r.returncode == 0, r.stderr
    r = cli(capsys, "bspline", tmp_path / "f.json", "--dxf", tmp_path / "b.dxf", "--json", tmp_path / "b.json")
    assert r.returncode == 0, r.stderr
    r = cli(capsys, "bspline", tmp_path / "b.json", "--dxf", tmp_path / "bb.dxf", "--json", tmp_path / "bb.json")
    assert r.returncode == 0, r.stderr
    fit_dxf, bspline_dxf, again_dxf = [c for c in fake_ezdxf if c[0] == "spline"]
    for other in (bspline_dxf, again_dxf):
        assert len(fit_dxf[1]) == len(other[1]) and fit_dxf[3] == other[3]
        np.testing.assert_allclose(np.array(other[1]), np.array(fit_dxf[1]), rtol=0, atol=1e-9)
    first, again = (json.loads((tmp_path / f).read_text()) for f in ("b.json", "bb.json"))
    assert first["bspline"] == again["bspline"]


def test_fit_not_converged_exit_1(capsys):
    """--max-iter caps Levenberg-Marquardt too: a free smooth fit (no Ipopt) stops at 1
    and exits 1; `fit --help` says so (it said "Ipopt iterations per start", QA16 P1)."""
    r = cli(capsys, "fit", SAMPLE_S, "--model", "smooth", "--max-iter", "1")
    assert r.returncode == 1, (r.stdout, r.stderr)
    assert "status" in r.stdout and "ok" not in r.stdout.split("status")[-1]
    said = " ".join(cli(capsys, "fit", "--help").stdout.split("--max-iter N")[-1].split()[:12])
    assert "Levenberg-Marquardt" in said and "Ipopt" in said, said


def test_fit_npy_and_bspline_roundtrip(capsys, tmp_path):
    np.save(tmp_path / "p.npy", read_points(SAMPLE_2D))
    r = cli(capsys, "fit", tmp_path / "p.npy", "--model", "smooth", "--json", tmp_path / "f.json")
    assert r.returncode == 0, r.stderr
    r = cli(capsys, "bspline", tmp_path / "f.json", "--tol", "1e-6", "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    from libelastica.io import bspline_from_dict, curve_from_dict
    b, c = bspline_from_dict(doc), curve_from_dict(doc)
    assert 0 <= b.max_deviation <= 1e-6
    t = np.linspace(*b.domain, 301)
    np.testing.assert_allclose(b.evaluate(t), c.points(np.linspace(0, c.length, 301)), atol=1e-5)


def test_fit_batch_summary_and_progress(tmp_path):
    files = [SAMPLE_2D, SAMPLE_3D, SAMPLE_S]
    r = run("fit", *files, "--progress", "--json", tmp_path / "out" / "{stem}.json",
            "--svg", tmp_path / "pics")
    assert r.returncode == 0, r.stderr
    assert "3/3" in r.stderr
    lines = r.stdout.strip().splitlines()
    assert lines[0].split()[:3] == ["file", "model", "k"] and len(lines) == 2 + len(files)
    for f in files:
        assert json.loads((tmp_path / "out" / f"{f.stem}.json").read_text())["converged"]
        svg_ok(tmp_path / "pics" / f"{f.stem}.svg")

def test_fit_batch_with_bad_file_exit_2(capsys, tmp_path):
    bad = tmp_path / "bad.csv"
    bad.write_text("0,0\n1,1\n")
    r = cli(capsys, "fit", SAMPLE_2D, bad, "--json", "-")
    assert r.returncode == 2
    recs = json.loads(r.stdout)
    assert recs[0]["converged"] and recs[1]["status"].startswith("bad input")


@pytest.fixture
def fake_ezdxf(monkeypatch):
    """A stand-in for ezdxf following its documented API (new(), modelspace(),
    add_open_spline(control_points, degree, knots, dxfattribs), add_point, saveas) that
    records the calls, so the DXF writer is checked where ezdxf is not installed."""
    import types
    calls = []

    class Msp:
        dxf = types.SimpleNamespace()

        def add_open_spline(self, control_points, degree=3, knots=None, dxfattribs=None):
            calls.append(("spline", list(control_points), degree, list(knots), dxfattribs))
            return types.SimpleNamespace(dxf=types.SimpleNamespace(flags=0))

        def add_point(self, p, dxfattribs=None):
            calls.append(("point", p, dxfattribs))

    class Doc:
        header = {}

        def modelspace(self):
            return Msp()

        def saveas(self, path):
            Path(path).write_text("dxf")

    fake = types.ModuleType("ezdxf")
    fake.new = lambda version="R2010": Doc()
    monkeypatch.setitem(sys.modules, "ezdxf", fake)
    return calls


def test_dxf_writer_passes_the_full_knot_vector(fake_ezdxf, tmp_path):
    """Distinct knots + multiplicities become DXF's flat, clamped knot vector."""
    from libelastica.io import write_dxf_spline
    c = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=0.8, q=0.0, length=3.0)
    b = c.to_bspline(tol=1e-6, degree=3)
    write_dxf_spline(b, tmp_path / "c.dxf", points=np.zeros((2, 2)))
    (_, ctrl, degree, knots, attribs), = [c for c in fake_ezdxf if c[0] == "spline"]
    assert degree == 3 and attribs == {"layer": "elastica"}
    assert len(knots) == len(ctrl) + degree + 1
    assert np.all(np.diff(knots) >= 0)
    assert knots[:4] == [b.knots[0]] * 4 and knots[-4:] == [b.knots[-1]] * 4   # clamped
    np.testing.assert_allclose(np.array(ctrl)[:, :2], b.poles)
    assert np.all(np.array(ctrl)[:, 2] == 0.0)
    assert sum(1 for c in fake_ezdxf if c[0] == "point") == 2


def test_fit_3d_dxf_in_input_coordinates(capsys, fake_ezdxf, tmp_path):
    """For 3D input the DXF spline is the fitted curve mapped back into 3D: its poles lie
    in the fitted plane and it starts next to the first measured point."""
    pts = read_points(SAMPLE_3D)
    r = cli(capsys, "fit", SAMPLE_3D, "--model", "smooth", "--dxf", tmp_path / "f.dxf",
            "--json", "-")
    assert r.returncode == 0, r.stderr
    doc = json.loads(r.stdout)
    (_, ctrl, _, _, _), = [c for c in fake_ezdxf if c[0] == "spline"]
    ctrl = np.array(ctrl)
    origin, normal = np.array(doc["plane"]["origin"]), np.array(doc["plane"]["normal"])
    assert np.abs((ctrl - origin) @ normal).max() < 1e-9
    assert np.linalg.norm(ctrl[0] - pts[0]) < 1.0            # noise sigma 0.2
    assert len([c for c in fake_ezdxf if c[0] == "point"]) == len(pts)


def test_fit_batch_table_and_json_say_the_misfit_and_sparse_verdicts(capsys, tmp_path):
    """QA20 F7: the batch table said 'ok' for a fit at 46 x the points' noise (a corner) and
    the JSON had no 'sparse' verdict; the row names both verdicts, the JSON holds "sparse"
    beside "misfit", a fit judged fine stays 'ok' (failed before: 'ok', no "sparse")."""
    rng = np.random.default_rng(20)
    t = np.linspace(0, 100, 200)
    corner = np.vstack([np.c_[t, 0 * t], np.c_[100 + 0 * t, t][1:]])     # a square corner
    corner += rng.normal(0, 0.05, corner.shape)
    clicks = np.array([[0, 0], [30, 0.5], [55, 3], [75, 9], [88, 17], [96, 27], [99, 38]], float)
    files = []
    for name, P in (("corner", corner), ("clicks", clicks)):
        files.append(tmp_path / f"{name}.csv")
        np.savetxt(files[-1], P, delimiter=",")
    r = cli(capsys, "fit", SAMPLE_2D, *files, "--json", tmp_path / "{stem}.json")
    rows = {Path(ln.split()[0]).name: ln for ln in r.stdout.splitlines()[2:]}
    assert rows[SAMPLE_2D.name].rstrip().endswith(" ok"), r.stdout
    assert "not one elastica" in rows["corner.csv"] and " x the noise" in rows["corner.csv"], r.stdout
    assert "polygon too coarse" in rows["clicks.csv"], r.stdout
    doc = json.loads((tmp_path / "clicks.json").read_text())
    assert doc["sparse"]["smooth_rms"] < doc["sparse"]["rms"], doc.get("sparse")
    assert "misfit" in json.loads((tmp_path / "corner.json").read_text())


@pytest.mark.parametrize("option", [["--tol", "1e-2"], ["--degree", "5"]])
def test_bspline_of_a_discrete_fit_refuses_options_it_would_ignore(capsys, tmp_path, option):
    """QA23 F1: `elastica bspline fit.json --tol T` of a discrete fit (the default model)
    wrote the same cubic through the vertices for any T: an option that would do nothing
    is refused (exit 2, naming it), nothing written; without it, and for a smooth fit,
    it works."""
    for model in ("discrete", "smooth"):
        r = cli(capsys, "fit", SAMPLE_2D, "--model", model, "--json", tmp_path / f"{model}.json")
        assert r.returncode == 0, r.stderr
    r = cli(capsys, "bspline", tmp_path / "discrete.json", *option, "--json", tmp_path / "b.json")
    assert r.returncode == 2 and option[0] in r.stderr and "--model smooth" in r.stderr, r.stderr
    assert not (tmp_path / "b.json").exists()
    assert cli(capsys, "bspline", tmp_path / "discrete.json", "--json", "-").returncode == 0
    r = cli(capsys, "bspline", tmp_path / "smooth.json", *option, "--json", "-")
    assert r.returncode == 0, r.stderr
