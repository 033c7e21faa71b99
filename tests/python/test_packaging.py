"""`pip install ./python` into a fresh venv: the wheel compiles the C library from
the source tree and bundles it, so the installed package imports and fits with no
LIBELASTICA_PATH and no source tree on sys.path, and its declarations pre-parsed by cffi
(libelastica/_cdef.py) so that it starts without parsing the header. Offline: the in-tree build
backend has no build requirements, and --no-index --no-deps keeps pip off the
network (numpy/cffi come from the interpreter's own site-packages)."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

CHECK = r"""
import sys
from pathlib import Path
import numpy as np
import libelastica as el
pkg = Path(el.__file__).resolve().parent
assert Path(sys.prefix).resolve() in pkg.parents, pkg          # the installed copy
assert (pkg / "libelastica.so").is_file() and (pkg / "elastica.h").is_file()
assert el._ffi.CDEF_MODULE == str(pkg / "_elastica_abi.py")     # the header pre-parsed
assert (pkg / "binding.h").is_file()                           # el.fit's one call (_fit_call.py)
assert sys.modules["libelastica._fit_call"]._ONE_CALL is not None
assert "pycparser" not in sys.modules                          # (not parsed at import)
import ctypes
lib = ctypes.CDLL(str(pkg / "libelastica.so"))
assert hasattr(lib, "el_fit_smooth") and hasattr(lib, "el_binding_fit")
assert not hasattr(lib, "el__gsl_quiet")                       # internals stay local (exports.map)
c = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=0.8, q=0.0, length=3.0)
s = np.linspace(0, 3, 40)
pts = c.points(s)
r = el.fit(pts, model="smooth")
assert r.converged and r.rms < 1e-6, (r.status, r.rms)
assert abs(r.curve.k - 0.8) < 1e-6 and abs(r.curve.length - 3.0) < 1e-6
"""


def _clean_env():
    env = {k: v for k, v in os.environ.items()
           if k not in ("LIBELASTICA_PATH", "PYTHONPATH", "PIP_REQUIRE_VIRTUALENV")}
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    return env


def _venv(path: Path) -> Path:
    """A venv of this interpreter seeing its site-packages (numpy, cffi); without pip
    of its own when this interpreter's pip can install into it (--python, pip >= 22.3)."""
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip",
                    str(path)], check=True, capture_output=True)
    return path / "bin" / "python"


def test_pip_install_into_fresh_venv(tmp_path):
    env = _clean_env()
    py = _venv(tmp_path / "venv")
    pip = [sys.executable, "-m", "pip", "--python", str(py)]
    probe = subprocess.run(pip + ["--version"], env=env, capture_output=True, text=True)
    if probe.returncode != 0:       # an older pip: give the venv its own
        subprocess.run([str(py), "-m", "ensurepip", "--default-pip"], env=env, check=True,
                       capture_output=True)
        pip = [str(py), "-m", "pip"]
    r = subprocess.run(pip + ["install", "-q", "--no-index", "--no-deps", str(ROOT / "python")],
                       env=env, capture_output=True, text=True, cwd=tmp_path, timeout=600)
    assert r.returncode == 0, r.stdout + r.stderr
    r = subprocess.run([str(py), "-c", CHECK], env=env, capture_output=True, text=True,
                       cwd=tmp_path, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    script = tmp_path / "venv" / "bin" / "elastica"            # the console script
    r = subprocess.run([str(script), "fit", str(ROOT / "examples" / "sample_2d.csv"),
                        "--svg", "fit.svg"], env=env, capture_output=True, text=True,
                       cwd=tmp_path, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr
    assert "rms" in r.stdout and (tmp_path / "fit.svg").stat().st_size > 1000
