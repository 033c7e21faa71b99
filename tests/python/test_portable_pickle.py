"""Pickles cross numpy versions (QA19 M2: a result pickled under numpy 2 (pyenv's python3)
did not load in FreeCAD's /usr/bin/python3, numpy 1.24: "No module named 'numpy._core'"):
results and curves pickle their arrays and numpy scalars as plain lists and numbers, so no
numpy module path is written; loaded, they equal the original (dtypes and shapes too).
Both directions run where make check runs this suite under both Pythons: this Python's
pickle is loaded by the other one, which writes it back for this one to compare.
"""
from __future__ import annotations

import copy
import functools
import io
import os
import pickle
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica._portable import PortablePickle
import pickle_objects

objects = functools.lru_cache(maxsize=None)(pickle_objects.objects)   # (built once: ~0.5 s)

HERE = Path(__file__).resolve().parent


def modules(data: bytes) -> set:
    """The top-level packages a pickle imports classes and functions from."""
    seen = set()

    class Recording(pickle.Unpickler):
        def find_class(self, module, name):
            seen.add(module.split(".")[0])
            return super().find_class(module, name)

    Recording(io.BytesIO(data)).load()
    return seen


def test_every_class_that_pickles_is_built():
    kinds = {type(v).__name__ for v in objects().values()}
    classes = {n for n in el.__all__ if isinstance(getattr(el, n), type) and (
        issubclass(getattr(el, n), PortablePickle) or hasattr(getattr(el, n), "_fields"))}
    assert classes <= kinds


@pytest.mark.parametrize("protocol", [2, 4, pickle.HIGHEST_PROTOCOL])
def test_no_numpy_module_in_a_pickle(protocol):
    for name, obj in objects().items():
        data = pickle.dumps(obj, protocol=protocol)
        assert modules(data) <= {"libelastica", "builtins", "copyreg"}, name
        back = pickle.loads(data)
        assert type(back) is type(obj) and back == obj, name


def test_copies_keep_their_meaning():
    """copy shares the arrays, deepcopy copies them, as before the portable pickle."""
    r = objects()["held"]
    c, d = copy.copy(r), copy.deepcopy(r)
    assert c == r and d == r and c.points is r.points and d.points is not r.points
    assert c.curve is r.curve and d.curve is not r.curve and d.free == r.free
    b = el.EllipticBlend(k=0.3)
    assert copy.copy(b) == b and copy.deepcopy(b) == b
    o = objects()["Ordering"]
    assert copy.copy(o) == o and copy.deepcopy(o).order is not o.order
    s = objects()["HermiteSolutions"]
    assert copy.deepcopy(s) == s and copy.copy(s)[0] is s[0]


def _describe(python: str):
    r = subprocess.run([python, "-c", "import sys, numpy; print(sys.version.split()[0], "
                        "numpy.__version__)"], capture_output=True, text=True, timeout=60)
    return r.stdout.strip() if r.returncode == 0 else None


def other_python():
    """A Python of another numpy than this one (make check runs this suite under both
    /usr/bin/python3 and the python3 on PATH), else None."""
    here = f"{sys.version.split()[0]} {np.__version__}"
    for cand in (os.environ.get("LIBELASTICA_OTHER_PYTHON"), "/usr/bin/python3",
                 shutil.which("python3")):
        if cand and Path(cand).exists() and _describe(cand) not in (None, here):
            return cand
    return None


ROUND_TRIP = """
import pickle, sys
objs = pickle.load(open(sys.argv[1], "rb"))
for name, v in objs.items():           # loaded and used under this numpy
    if hasattr(v, "curve"):
        v.curve.points(3)
    elif hasattr(v, "points") and callable(v.points):
        v.points(3)
pickle.dump(objs, open(sys.argv[2], "wb"), protocol=4)
"""


def test_a_pickle_crosses_to_the_other_numpy_and_back(tmp_path):
    other = other_python()
    if other is None:
        pytest.skip("no second Python with another numpy (make check runs both)")
    objs = objects()
    (tmp_path / "here.pkl").write_bytes(pickle.dumps(objs, protocol=4))
    r = subprocess.run([other, "-c", ROUND_TRIP, str(tmp_path / "here.pkl"),
                        str(tmp_path / "there.pkl")], capture_output=True, text=True,
                       cwd=HERE, env=os.environ, timeout=300)
    assert r.returncode == 0, f"{other} ({_describe(other)}): {r.stderr[-2000:]}"
    back = pickle.loads((tmp_path / "there.pkl").read_bytes())
    for name, obj in objs.items():
        assert type(back[name]) is type(obj) and back[name] == obj, name
