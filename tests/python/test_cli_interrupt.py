"""Ctrl-C during `elastica fit`'s C fit ends the command there: exit 130, "interrupted",
nothing written, no traceback. It used to take effect only when the C fit returned (a
2000-point fit: seconds later): the C call now runs in a worker thread the command waits on
(libelastica._interrupt), and the wait is what SIGINT interrupts."""
from __future__ import annotations

import os
import signal
import subprocess
import sys
import time

import numpy as np
import pytest

import libelastica as el
from libelastica._interrupt import call, interruptible


def _threads(pid: int) -> int:
    try:
        return len(os.listdir(f"/proc/{pid}/task"))
    except FileNotFoundError:
        return 0


def _sigint_default():
    """The child's SIGINT as a terminal gives it: make runs from a background job (nohup,
    CI) hand it SIGINT ignored, which Python then keeps (no KeyboardInterrupt at all)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


@pytest.mark.skipif(not os.path.isdir("/proc/self/task"), reason="needs Linux /proc")
@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_sigint_during_the_c_fit(tmp_path, model):
    """SIGINT sent while the C fit runs (its worker thread alive: the process has two threads,
    OpenBLAS held to one) ends the process while that fit still runs: the worker is then
    still in C, so the process exits with two threads' work undone; exit 130, no output
    file, one line on stderr."""
    # a fit that runs seconds, not milliseconds (a plain 2000-point fit takes ~5 ms, so the
    # worker could end between two polls): held to a start curvature 4 x the scan's, which
    # Ipopt works at (3 s smooth, 12 s discrete, measured)
    rng = np.random.default_rng(1)
    c = el.SmoothElastica(x0=0, y0=0, phi=0.25, mu=1.2e-6, k=0.6, q=0.3, length=4000.0)
    s = np.sort(rng.uniform(0, 4000, 2000))
    P = c.points(s) + rng.normal(0, 0.5, (2000, 2))
    wrong = 4.0 * float(c.curvature(s[:1])[0]) + 1e-3
    np.savetxt(tmp_path / "p.csv", P, delimiter=",")
    env = dict(os.environ, OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    proc = subprocess.Popen([sys.executable, "-m", "libelastica", "fit", str(tmp_path / "p.csv"),
                             "--model", model, "--start-curvature", repr(wrong),
                             "--json", str(tmp_path / "f.json")],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=_sigint_default)
    while proc.poll() is None and _threads(proc.pid) < 2:     # the C fit's worker started
        time.sleep(0.005)
    assert proc.poll() is None, "the fit ended before its C call was seen in a worker"
    proc.send_signal(signal.SIGINT)
    out, err = proc.communicate(timeout=120)
    assert proc.returncode == 130, err
    assert err.strip() == "elastica: interrupted", err
    assert out == "" and sorted(p.name for p in tmp_path.iterdir()) == ["p.csv"]


def test_call_returns_at_keyboardinterrupt_while_the_worker_runs():
    """In the main thread inside interruptible(), call() raises the KeyboardInterrupt while
    fn still runs (here: waits for an event set only afterwards); outside, fn runs in the
    caller's thread; fn's own exception comes through."""
    import threading
    release, started = threading.Event(), threading.Event()

    def blocked():
        started.set()
        release.wait(60)
        return "done"

    def interrupt():
        started.wait(60)
        signal.raise_signal(signal.SIGINT)      # to this thread: the main thread's handler runs

    threading.Thread(target=interrupt, daemon=True).start()
    previous = signal.signal(signal.SIGINT, signal.default_int_handler)   # (ignored under nohup)
    try:
        with interruptible(), pytest.raises(KeyboardInterrupt):
            call(blocked)
    finally:
        signal.signal(signal.SIGINT, previous)
    assert not release.is_set()
    release.set()
    assert call(threading.current_thread) is threading.current_thread()    # no worker outside
    with interruptible():
        assert call(threading.current_thread) is not threading.current_thread()
        with pytest.raises(ZeroDivisionError):
            call(lambda: 1 / 0)


_HOOK = """import signal, sys
class _InterruptAt:     # SIGINT to this process as it starts importing the module named
    def find_spec(self, name, path=None, target=None):
        if name == {module!r}:
            signal.raise_signal(signal.SIGINT)
        return None
sys.meta_path.insert(0, _InterruptAt())
"""


def _command(tmp_path, how: str):
    """The argv of the elastica command started as ``how``: "-m" (python -m libelastica) or
    "script" (the console script pip writes from pyproject.toml's [project.scripts])."""
    if how == "-m":
        return [sys.executable, "-m", "libelastica"]
    import tomllib
    root = os.path.join(os.path.dirname(__file__), "..", "..")
    with open(os.path.join(root, "python", "pyproject.toml"), "rb") as f:
        target = tomllib.load(f)["project"]["scripts"]["elastica"]
    module, func = target.split(":")
    script = tmp_path / "bin" / "elastica"
    script.parent.mkdir()
    script.write_text(f"import sys\nfrom {module} import {func}\nsys.exit({func}())\n")
    return [sys.executable, str(script)]


@pytest.mark.parametrize("how", ["-m", "script"])
@pytest.mark.parametrize("module", ["libelastica._ffi", "libelastica.cli"])
def test_sigint_while_the_command_imports(tmp_path, how, module):
    """SIGINT while the command still imports (numpy, cffi, the library: most of its 0.1 s
    start-up; here raised as the import of ``module`` starts, by a sitecustomize) ends it as
    Ctrl-C later does: exit 130, "elastica: interrupted", nothing written. Before: a
    KeyboardInterrupt traceback, killed by SIGINT."""
    (tmp_path / "hook").mkdir()
    (tmp_path / "hook" / "sitecustomize.py").write_text(_HOOK.format(module=module))
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(tmp_path / "hook")] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    sample = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "sample_2d.csv")
    out = tmp_path / "f.json"
    r = subprocess.run(_command(tmp_path, how) + ["fit", sample, "--json", str(out)], env=env,
                       capture_output=True, text=True, timeout=120, preexec_fn=_sigint_default)
    assert r.returncode == 130 and r.stderr.strip() == "elastica: interrupted", r.stderr
    assert r.stdout == "" and not out.exists()


def test_a_program_importing_the_package_keeps_pythons_sigint():
    """Only the command's process gets the start-up handler: a program (here -c) that
    imports libelastica keeps Python's KeyboardInterrupt."""
    r = subprocess.run([sys.executable, "-c", "import signal, libelastica\n"
                        "print(signal.getsignal(signal.SIGINT) is signal.default_int_handler)"],
                       capture_output=True, text=True, timeout=120, preexec_fn=_sigint_default)
    assert r.returncode == 0 and r.stdout.strip() == "True", r.stderr
