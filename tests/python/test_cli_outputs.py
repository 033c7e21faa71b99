"""Issue 12, the command line never damages input: an output that is an input is
refused (exit 2) before anything is written, outputs are written all or nothing,
overflowing arguments are bad input (exit 2), and `blend` warns when the basis
leaves the convex hull."""
from __future__ import annotations

import hashlib
import json
import os
import shutil
from pathlib import Path

import pytest

from cli_run import cli

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "examples" / "sample_2d.csv"


def digest(p: Path) -> str:
    return hashlib.sha256(p.read_bytes()).hexdigest()


@pytest.fixture
def work(tmp_path, monkeypatch):
    shutil.copy(SAMPLE, tmp_path / "a.csv")
    monkeypatch.chdir(tmp_path)
    return tmp_path


@pytest.mark.parametrize("args", [
    ["fit", "a.csv", "--json", "a.csv"],
    ["fit", "a.csv", "--json", "./a.csv"],
    ["fit", "a.csv", "--json", "{stem}.csv"],
    ["fit", "a.csv", "--svg", "a.csv"],
    ["fit", "a.csv", "--dxf", "a.csv"],
    ["fit", "a.csv", "--keyline", "--json", "a.csv"],
    ["fit", "a.csv", "--json", "ok.json", "--svg", "a.csv"],   # the first output neither
], ids=lambda a: " ".join(a))
def test_output_that_is_an_input_is_refused(work, capsys, args):
    before = digest(work / "a.csv")
    code, _, err = cli(capsys, *args)
    assert code == 2 and "refusing to overwrite the input file" in err
    assert digest(work / "a.csv") == before
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]   # nothing else written


def test_output_that_is_an_input_through_a_link_is_refused(work, capsys):
    os.link(work / "a.csv", work / "hard.csv")
    os.symlink(work / "a.csv", work / "soft.csv")
    before = digest(work / "a.csv")
    for target in ("hard.csv", "soft.csv"):
        code, _, err = cli(capsys, "fit", "a.csv", "--json", target)
        assert code == 2 and "refusing" in err
    assert digest(work / "a.csv") == before


def test_bspline_json_onto_its_input_is_refused(work, capsys):
    assert cli(capsys, "fit", "a.csv", "--model", "smooth", "--json", "f.json")[0] == 0
    before = digest(work / "f.json")
    code, _, err = cli(capsys, "bspline", "f.json", "--json", "f.json")
    assert code == 2 and "refusing" in err
    assert digest(work / "f.json") == before


def test_batch_stem_pattern_onto_an_input_is_refused(work, capsys):
    shutil.copy(work / "a.csv", work / "b.csv")
    before = digest(work / "b.csv")
    code, _, err = cli(capsys, "fit", "a.csv", "b.csv", "--json", "{stem}.csv")
    assert code == 2 and "refusing" in err
    assert digest(work / "b.csv") == before


def test_a_failing_output_leaves_nothing(work, capsys):
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "ok.json", "--svg", "/proc/x.svg")
    assert code == 2 and "/proc/x.svg" in err
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]   # no ok.json, no temporaries
    code, _, _ = cli(capsys, "fit", "a.csv", "--json", "new/dir/ok.json", "--svg", "/proc/x.svg")
    assert code == 2 and not (work / "new").exists()            # nor the directories made


def test_outputs_are_complete_when_all_succeed(work, capsys):
    code, _, _ = cli(capsys, "fit", "a.csv", "--json", "out/a.json", "--svg", "out/a.svg")
    assert code == 0
    assert json.loads((work / "out" / "a.json").read_text())["model"] == "discrete"
    assert (work / "out" / "a.svg").read_text().lstrip().startswith("<")
    assert sorted(p.name for p in (work / "out").iterdir()) == ["a.json", "a.svg"]


def test_same_output_twice_is_refused(work, capsys):
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "x.svg", "--svg", "./x.svg")
    assert code == 2 and "twice" in err
    assert not (work / "x.svg").exists()


@pytest.mark.parametrize("args", [
    ["spline", "a.csv", "--tension", "1", "--json", "o.json", "--dxf", "o.json"],
    ["spline", "a.csv", "--tension", "1", "--json", "o.svg", "--svg", "./o.svg"],
    ["hermite", "0", "0", "1", "0", "1", "0", "1", "0", "--length", "4", "--json", "o.dxf",
     "--dxf", "o.dxf"],
    ["fit", "a.csv", "--json", "o.dxf", "--dxf", "o.dxf"],
], ids=lambda a: " ".join(a))
def test_two_outputs_to_one_path_are_refused(work, capsys, args):
    """Two outputs to one path: exit 2 naming both options, before anything is written
    (`spline --json o.json --dxf o.json` exited 0 with the DXF there, QA)."""
    code, _, err = cli(capsys, *args)
    assert code == 2 and "given twice" in err and len(err.strip().splitlines()) == 1
    opts = [a for a in args if a.startswith("--") and a not in ("--tension", "--length")]
    assert all(o in err for o in opts[-2:])
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]


def test_hermite_without_a_solution_writes_nothing(work, capsys):
    """No Hermite solution: exit 1, one line, and no file (a JSON of "solutions": [] and an
    empty picture were written, QA); to stdout neither."""
    args = ["hermite", "0", "0", "1", "0", "1", "0", "-1", "0", "--tension", "0"]
    code, out, err = cli(capsys, *args, "--json", "o.json", "--svg", "o.svg")
    assert code == 1 and "no elastica" in err and len(err.strip().splitlines()) == 1
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]
    code, out, err = cli(capsys, *args, "--json", "-")
    assert code == 1 and out == ""


@pytest.mark.parametrize("args", [
    ["fit", "a.csv", "--model", "smooth", "--bspline-tol", "1e-6", "--degree", "99999999999999"],
    ["fit", "a.csv", "--max-iter", "99999999999999999999"],
    ["fit", "a.csv", "--step", "1e-9"],
    ["fit", "a.csv", "--step", "1e-320"],
    ["hermite", "0", "0", "0", "1", "2", "0", "0", "-1", "--tension", "1e400"],
    ["bspline", "f.json", "--degree", "4294967296"],
], ids=lambda a: " ".join(a))
def test_overflowing_arguments_exit_2(work, capsys, args):
    cli(capsys, "fit", "a.csv", "--model", "smooth", "--json", "f.json")
    code, _, err = cli(capsys, *args)
    assert code == 2, err
    assert "internal error" not in err and len(err.strip().splitlines()) == 1


@pytest.mark.parametrize("keyline", [[], ["--keyline"]], ids=["one piece", "keyline"])
def test_step_beyond_the_points_reach_is_the_librarys_rule(tmp_path, capsys, keyline):
    """A step longer than the points' reach from the polygon's start (7.011; their
    polyline is 7.118 long) cannot make a polygon: refused with the library's
    message naming the reach, with or without --keyline (the one-piece fit's own check
    said "(0, length)"), as is a step beyond the length; a short step fits."""
    path = tmp_path / "p.csv"
    path.write_text("0,0\n1,0.2\n2,0.3\n3,0.2\n4,0\n5,-0.3\n6,-0.5\n7,-0.4\n")
    for step in ("7.05", "7.5"):       # within the polyline's length, beyond it
        code, _, err = cli(capsys, "fit", str(path), "--step", step, *keyline)
        assert code == 2 and "longer than the polyline reaches" in err and "7.01142" in err, err
        assert len(err.strip().splitlines()) == 1
    for step in ("0", "-1"):
        code, _, err = cli(capsys, "fit", str(path), "--step", step, *keyline)
        assert code == 2 and f"argument --step: {step}: a number > 0 is needed" in err, err
    if not keyline:        # a keyline of 8 points cannot be split; one piece fits
        code, out, err = cli(capsys, "fit", str(path), "--step", "0.5", "--json", "-")
        assert code == 0 and json.loads(out)["step"] == 0.5, err


def test_step_past_the_vertex_limit_says_what_is_possible(work, capsys):
    code, _, err = cli(capsys, "fit", "a.csv", "--step", "1e-9")
    assert code == 2 and "EL_RESAMPLE_MAX_VERTICES" in err and "r >= " in err


def test_blend_warns_when_the_convex_hull_is_lost(work, capsys):
    code, out, err = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0",
                         "--m", "0.62", "--json", "-")
    rec = json.loads(out)
    assert code == 0 and "warning" in err and "convex hull" in err
    assert rec["convex_hull"] is False and rec["basis_min"] < 0 and rec["lebesgue"] > 1
    code, out, err = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0",
                         "--m", "0.3", "--json", "-")
    assert code == 0 and "warning" not in err and json.loads(out)["convex_hull"] is True
    code, _, err = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0",
                       "--m", "0.6438")
    assert code == 2 and "singular neighbourhood" in err


def test_outputs_get_the_permissions_a_new_or_replaced_file_has(work, capsys):
    """Every output was written through a 0600 temporary and kept that mode: colleagues
    (and a CAD server) could not read the DXF or JSON, and an existing 0644 file turned
    0600. Now a new file gets what the umask gives (0644 under 022, 0664 under 002), a
    replaced one keeps its own mode."""
    old = os.umask(0o022)
    try:
        (work / "kept.json").write_text("old")
        os.chmod(work / "kept.json", 0o640)
        code, _, err = cli(capsys, "fit", "a.csv", "--json", "new.json", "--svg", "new.svg")
        assert code == 0, err
        code, _, err = cli(capsys, "fit", "a.csv", "--json", "kept.json")
        assert code == 0, err
        os.umask(0o002)
        code, _, err = cli(capsys, "fit", "a.csv", "--json", "group.json")
        assert code == 0, err
    finally:
        os.umask(old)
    mode = {p: os.stat(work / p).st_mode & 0o777 for p in ("new.json", "new.svg", "kept.json", "group.json")}
    assert mode == {"new.json": 0o644, "new.svg": 0o644, "kept.json": 0o640, "group.json": 0o664}
    assert json.loads((work / "kept.json").read_text())["converged"]


@pytest.mark.parametrize("args, said", [
    (["fit", "a.csv", "--json", "sub"], "sub: is a directory; give a file name"),
    (["fit", "a.csv", "--svg", "x.png"], "--svg x.png: the picture's file name must end in .svg"),
    (["fit", "a.csv", "--png", "x.txt"], "--png x.txt: the picture's file name must end in .png"),
], ids=["directory", "svg named png", "png named txt"])
def test_output_names_that_cannot_be_written_as_asked_are_refused(work, capsys, args, said):
    """An existing directory as an output file failed at the rename ("[Errno 21] Is a
    directory: '.sub.x1y2.tmp' -> 'sub'"), a picture named for another format was written
    in the format of its name (--svg x.png: a PNG) or failed naming the temporary."""
    (work / "sub").mkdir()
    code, _, err = cli(capsys, *args)
    assert code == 2 and said in err and ".tmp" not in err, err
    assert sorted(p.name for p in work.iterdir()) == ["a.csv", "sub"] and not any((work / "sub").iterdir())


@pytest.mark.parametrize("args, said", [
    (["fit", "a.csv", "--model", "smooth", "--bspline-tol", "0"], "argument --bspline-tol: 0: a number > 0 is needed"),
    (["fit", "a.csv", "--degree", "2"], "argument --degree: 2: an integer >= 3 and <= 7 is needed"),
    (["fit", "a.csv", "--max-iter", "0"], "argument --max-iter: 0: an integer >= 1 is needed"),
    (["fit", "a.csv", "--step", "-1"], "argument --step: -1: a number > 0 is needed"),
    (["fit", "a.csv", "--model", "smooth", "--fix", "mu=-1"], "fixed mu must be > 0, got -1"),
    (["bspline", "a.json", "--tol", "-1"], "argument --tol: -1: a number > 0 is needed"),
    (["hermite", "0", "0", "0", "0", "1", "0", "1", "0", "--length", "2"], "the tangent t0 = (0, 0) has no direction"),
    (["hermite", "0", "0", "1", "0", "1", "0", "1", "0", "--length", "-2"], "argument --length: -2: a number > 0 is needed"),
    (["blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--d", "0"], "argument --d: 0: a number > 0 is needed"),
    (["blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0", "--k", "1"], "argument --k: 1: a number >= 0 and < 1 is needed"),
    (["spline", "a.csv", "--degree", "8"], "argument --degree: 8: an integer >= 3 and <= 7 is needed"),
], ids=lambda a: " ".join(a) if isinstance(a, list) else None)
def test_option_out_of_range_is_named(work, capsys, args, said):
    """Options out of their range name the option and the range (the library's refusal
    said "invalid argument (NULL, NaN/inf, out of range or too few points)" for each)."""
    (work / "a.json").write_text("{}")
    code, _, err = cli(capsys, *args)
    assert code == 2 and said in err and "NULL" not in err, err
    assert len(err.strip().splitlines()) == 1


def test_blend_closed_and_the_corner_said(work, capsys):
    square = ["0", "0", "1", "0", "1", "1", "0", "0"]
    code, out, err = cli(capsys, "blend", *square, "--m", "0.3", "--json", "-")
    assert code == 0 and "56.6 deg corner" in err and "--closed" in err
    code, out, err = cli(capsys, "blend", *square, "--m", "0.3", "--closed", "--json", "-")
    rec = json.loads(out)
    assert code == 0 and "warning" not in err and rec["closed"] is True
    assert len(rec["control_points"]) == 10 and rec["control_points"][0] == rec["control_points"][-1]
    code, _, err = cli(capsys, "blend", "0", "0", "1e308", "1", "-1e308", "1", "3", "0")
    assert code != 0 and "overflow" in err and "singular" not in err


def test_blend_says_an_ill_conditioned_interpolation_and_its_loop(work, capsys):
    """The points of the QA repro at m = 0.52: control points 40 times as far apart as
    the points, the curve 3.16 times their size and crossing itself. The CLI said
    nothing (FreeCAD warned); now one line each, in its words, the figures in the JSON."""
    code, out, err = cli(capsys, "blend", "0", "0", "0.3", "0.8", "0.7", "0.9", "1", "0",
                         "--m", "0.52", "--json", "-")
    rec = json.loads(out)
    assert code == 0 and rec["spread"] > 20 and rec["loops"] == 1
    lines = err.strip().splitlines()
    assert len(lines) == 2 and all(x.startswith("elastica blend: warning: ") for x in lines), err
    assert f"lie up to {rec['spread']:.3g} times as far apart" in lines[0] and "loops" in lines[1]
    assert rec["warnings"] == [x.removeprefix("elastica blend: warning: ") for x in lines]


def test_a_missing_directory_above_the_outputs_is_refused(work, capsys):
    """QA21 F7: `--json /nonexistent/dir/x.json` made /nonexistent/dir and exited 0. A path
    missing more than the output's own directory is refused (exit 2), naming the first
    missing directory, nothing made or written; the output's own directory in one that
    exists is made as before (out/a.json, a batch's out/{stem}.json)."""
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "nodir/sub/x.json", "--svg", "ok.svg")
    assert code == 2 and "nodir/sub/x.json: no directory nodir " in err, err
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "deep/er/still/x.json")
    assert code == 2 and "no directory deep " in err and not (work / "deep").exists(), err
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "new/x.json")
    assert code == 0 and (work / "new" / "x.json").is_file(), err


def test_an_output_through_a_link_replaces_the_file_it_names(work, capsys):
    """QA23: os.replace onto a link replaced the link, leaving its target stale."""
    (work / "shared").mkdir()
    (work / "shared" / "target.json").write_text("old")
    os.symlink("shared/target.json", work / "link.json")
    os.symlink("shared/new.json", work / "dangling.json")
    code, _, _ = cli(capsys, "fit", "a.csv", "--json", "link.json", "--svg", "dangling.svg")
    assert code == 0
    code, _, _ = cli(capsys, "fit", "a.csv", "--json", "dangling.json")
    assert code == 0
    for link, target in (("link.json", "target.json"), ("dangling.json", "new.json")):
        assert (work / link).is_symlink()
        assert json.loads((work / "shared" / target).read_text())["model"] == "discrete"
    assert sorted(p.name for p in (work / "shared").iterdir()) == ["new.json", "target.json"]


def test_two_outputs_through_links_to_one_file_are_refused(work, capsys):
    """Two names of one file (links to it, or a link and the file) are one output: the
    same-output check compared the paths as written, so `--json l1.json --dxf l2.json`
    through two links wrote the DXF over the JSON and exited 0."""
    (work / "target.json").write_text("old")
    os.symlink("target.json", work / "l1.json")
    os.symlink("target.json", work / "l2.json")
    os.symlink("new.json", work / "d1.json")       # links to one file not made yet
    os.symlink("new.json", work / "d2.json")
    for pair in (("l1.json", "l2.json"), ("target.json", "l1.json"), ("d1.json", "d2.json")):
        code, _, err = cli(capsys, "fit", "a.csv", "--json", pair[0], "--dxf", pair[1])
        assert code == 2 and "given twice" in err, pair
    assert (work / "target.json").read_text() == "old" and not (work / "new.json").exists()


@pytest.mark.parametrize("fifo, args, said", [
    ("pipe.json", ["fit", "bad.csv", "--json", "pipe.json"], "bad.csv"),
    ("pipe.dxf", ["fit", "a.csv", "--json", "a.csv", "--dxf", "pipe.dxf"],
     "refusing to overwrite the input")], ids=["failing command", "refused before its turn"])
def test_a_fifo_output_of_a_failing_command_is_closed_for_its_reader(work, capsys, fifo, args, said):
    """A command that fails before writing opened no output, so a reader waiting on a FIFO
    output blocked for ever (`mkfifo p; cat p & elastica fit bad.csv --json p`); a
    shell's '> p' would have opened it and closed it: the reader sees the end. Also where
    another output is refused before the FIFO's turn: `--json a.csv --dxf p` (the input
    refused) left p's reader blocked, though `--json p --dxf a.csv` released it (only the
    outputs checked before the refusal were known as FIFOs). Linux reports POLLHUP on a
    FIFO's read end only once a writer has opened it since."""
    import select
    (work / "bad.csv").write_text("x,y\n1,nan\n")
    os.mkfifo(work / fifo)
    fd = os.open(work / fifo, os.O_RDONLY | os.O_NONBLOCK)    # the waiting reader
    try:
        code, _, err = cli(capsys, *args)
        assert code == 2 and said in err, err
        poller = select.poll()
        poller.register(fd, select.POLLIN)
        events = poller.poll(0)
        assert events and events[0][1] & select.POLLHUP
        assert os.read(fd, 100) == b""
    finally:
        os.close(fd)
    assert sorted(p.name for p in work.iterdir()) == sorted(["a.csv", "bad.csv", fifo])


def test_an_output_that_is_a_fifo_is_written_through(work, capsys):
    """QA23: an output that is not a regular file (a FIFO here; /dev/null, /dev/full as
    root) was replaced by a regular file, and its reader got nothing."""
    import stat
    import threading
    fifo = work / "pipe.json"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()), daemon=True)
    reader.start()
    code, _, _ = cli(capsys, "fit", "a.csv", "--json", "pipe.json")
    assert code == 0
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)       # still the FIFO, not a file
    reader.join(timeout=30)
    assert got and json.loads(got[0])["model"] == "discrete"
    assert sorted(p.name for p in work.iterdir()) == ["a.csv", "pipe.json"]   # no temporaries


def test_an_output_through_an_open_descriptor_is_written_through(work, capsys):
    """`--json /dev/stdout | jq` and bash's `--json >(gzip > f.gz)` (/dev/fd/N) name a pipe
    through /proc/self/fd, whose link's target has no path (pipe:[inode]): feb6ef1 read the
    link by realpath, found no file there and made its temporary beside it, in /proc: exit 2,
    'cannot write there (No such file or directory)', the reader got nothing. Written through
    as the FIFO is (an open descriptor's pipe here, in-process: nothing under /dev touched)."""
    import threading
    r, w = os.pipe()
    got = []

    def read():
        with os.fdopen(r, "rb") as f:
            got.append(f.read())
    reader = threading.Thread(target=read, daemon=True)
    reader.start()
    try:
        code, _, err = cli(capsys, "fit", "a.csv", "--json", f"/dev/fd/{w}")
    finally:
        os.close(w)
    reader.join(timeout=30)
    assert code == 0, err
    assert got and json.loads(got[0])["model"] == "discrete"
    assert sorted(p.name for p in work.iterdir()) == ["a.csv"]      # no temporaries


def test_a_written_through_output_that_fails_leaves_the_others_unwritten(work, capsys):
    """feb6ef1 writes the outputs that are not regular files first at commit, so that one
    failing (/dev/full as root: 'No space left on device') leaves no other output renamed
    into place and nothing on standard output. A UNIX socket stands in for the failing
    device (open() of it fails with ENXIO; nothing under /dev touched): before feb6ef1 it was
    replaced by a JSON file, exit 0; with the renames first, b.svg was left behind."""
    import socket
    import stat
    sock = socket.socket(socket.AF_UNIX)
    try:
        sock.bind("node.json")          # relative: work is the current directory
        code, out, err = cli(capsys, "fit", "a.csv", "--json", "node.json", "--svg", "b.svg",
                             "--dxf", "-")
    finally:
        sock.close()
    assert code == 2 and "node.json: cannot write" in err, err
    assert stat.S_ISSOCK(os.lstat(work / "node.json").st_mode)     # the node itself kept
    assert sorted(p.name for p in work.iterdir()) == ["a.csv", "node.json"]   # no b.svg, no temporaries
    assert "SECTION" not in out          # the DXF for stdout not copied


def test_an_output_through_a_descriptor_on_a_file_appends_as_the_shell_opened_it(work, capsys):
    """`elastica fit a.csv --json /dev/stdout >> log` replaced log by the JSON alone (its
    earlier lines gone; with '> out' the summary printed to stdout went to the replaced
    file): the link through /proc/self/fd was followed to the file and a temporary renamed
    onto it. What /dev/stdout or /dev/fd/N names is the descriptor the shell opened (its
    mode, its offset): written through it (here a descriptor of log.txt opened to append)."""
    log = work / "log.txt"
    log.write_text("earlier line\n")
    inode = os.stat(log).st_ino
    fd = os.open(log, os.O_WRONLY | os.O_APPEND)
    try:
        code, _, err = cli(capsys, "fit", "a.csv", "--json", f"/dev/fd/{fd}")
    finally:
        os.close(fd)
    assert code == 0, err
    assert os.stat(log).st_ino == inode                 # the file the shell opened, not a new one
    text = log.read_text()
    assert text.startswith("earlier line\n"), text[:80]
    assert json.loads(text[len("earlier line\n"):])["model"] == "discrete"
    assert sorted(p.name for p in work.iterdir()) == ["a.csv", "log.txt"]


def test_two_descriptors_on_one_file_are_two_outputs(work, capsys):
    """`elastica fit a.csv --json /dev/stdout --dxf /dev/stderr > log 2>&1` (or `> /dev/null
    2>&1`, or both on one terminal) wrote both outputs one after the other; ffbd6f1 keyed
    outputs by the file they reach (its inode, or the realpath: /dev/null), so the two
    descriptors were 'the same output path is given twice', exit 2. Descriptors are written
    through at their end, as the shell opened them: both kept (here two descriptors of
    log.txt opened to append, and two of /dev/null)."""
    log = work / "log.txt"
    log.write_text("earlier line\n")
    fd = os.open(log, os.O_WRONLY | os.O_APPEND)
    fd2 = os.dup(fd)                                    # 2>&1
    null = os.open(os.devnull, os.O_WRONLY)
    null2 = os.dup(null)
    try:
        code, _, err = cli(capsys, "fit", "a.csv", "--json", f"/dev/fd/{fd}", "--dxf", f"/dev/fd/{fd2}")
        code_null, _, err_null = cli(capsys, "fit", "a.csv", "--json", f"/dev/fd/{null}",
                                     "--dxf", f"/dev/fd/{null2}")
    finally:
        for d in (fd, fd2, null, null2):
            os.close(d)
    assert code == 0, err
    assert code_null == 0, err_null
    text = log.read_text()
    assert text.startswith("earlier line\n") and '"model": "discrete"' in text and "SECTION" in text
    assert sorted(p.name for p in work.iterdir()) == ["a.csv", "log.txt"]
    # the same descriptor named twice is still one output given twice
    code, _, err = cli(capsys, "fit", "a.csv", "--json", "/dev/stdout", "--dxf", "/dev/stdout")
    assert code == 2 and "given twice" in err
