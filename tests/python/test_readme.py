"""The README's Python and command-line examples run as printed (from the repository root)."""
import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text()


def blocks(lang):
    return re.findall(r"```" + lang + r"\n(.*?)```", README, flags=re.S)


def test_python_block_runs(monkeypatch, capsys):
    (code,) = [b for b in blocks("python") if "libelastica as el" in b]
    monkeypatch.chdir(ROOT)
    env = {}
    exec(compile(code, "README.md", "exec"), env)
    assert env["r"].rms < 1.0 and env["b"].max_deviation <= 1e-6
    assert len(env["sols"]) >= 2


def test_command_lines_run(tmp_path, monkeypatch, capsys):
    """Every `elastica` line of the README's sh blocks, as printed (QA17 P7: the batch line
    named files that do not exist and was skipped here): run in a temporary directory with
    examples/ at the repository's. A line with a `> FILE` redirection runs as a process of its
    own (its standard output's bytes into FILE); the others in this process (cli.main, the
    same exit status: the console script and `python -m libelastica` start the process
    without them, test_dxf_holds_the_splines and test_cli's subprocess tests run those)."""
    from cli_run import cli
    monkeypatch.chdir(tmp_path)
    env = dict(os.environ)
    ran = 0
    for line in "".join(blocks("sh")).splitlines():
        line = line.split("#")[0].strip()
        if not line.startswith("elastica "):
            continue
        args = shlex.split(line)[1:]
        args = [str(ROOT / a) if a.startswith("examples/") else a for a in args]
        if ">" in args:
            args, stdout = args[:args.index(">")], tmp_path / args[args.index(">") + 1]
            done = subprocess.run([sys.executable, "-m", "libelastica", *args], cwd=tmp_path,
                                  env=env, capture_output=True)
            assert done.returncode == 0, (line, done.stderr)
            stdout.write_bytes(done.stdout)
        else:
            code, _, err = cli(capsys, *args)
            assert code == 0, (line, err)
        ran += 1
    assert ran >= 15
    for name in ("fit.svg", "fit.json", "keyline.png", "keyline.dxf", "hermite.png",
                 "spline.json", "blend.svg", "out/sample_2d.json", "out/sample_s_curve.json",
                 "out/sample_3d.json"):
        assert (tmp_path / name).stat().st_size > 0, name
    assert b"SECTION" in (tmp_path / "fit.dxf").read_bytes()[:200]


def test_dxf_holds_the_splines(tmp_path):
    ezdxf = __import__("ezdxf")       # installed by `make deps` for both pythons
    out = tmp_path / "k.dxf"
    done = subprocess.run([sys.executable, "-m", "libelastica", "fit", str(ROOT / "examples/keyline_3d.csv"),
                           "--keyline", "--model", "smooth", "--bspline-tol", "1e-3", "--dxf", str(out)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    splines = ezdxf.readfile(str(out)).modelspace().query("SPLINE")
    assert len(splines) == 1                          # the keyline, through its joint
    for sp in splines:
        assert sp.dxf.degree == 3 and len(sp.control_points) >= 4
