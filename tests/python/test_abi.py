"""The binding refuses, at import, a library built from another header than the one it
read (el_abi_digest, the CRC-32 of the header's declarations, _cdef.py): cffi lays out
every struct by its header, and a library built from another one writes past them (an
older binding's el_spline_result with a newer library: "free(): invalid pointer" in
FreeCAD). The ImportError names both files and what to rebuild."""
from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import libelastica as el
from libelastica import _cdef, _ffi

PACKAGE = Path(_ffi.__file__).resolve().parent
LIBRARY = Path(_ffi._LIBRARY)
HEADER = Path(_ffi._header())


def start(package_root: Path, library: Path):
    """(exit status, stderr) of a fresh interpreter importing the binding found under
    ``package_root`` with ``library``."""
    env = dict(os.environ, LIBELASTICA_PATH=str(library), PYTHONPATH=str(package_root))
    r = subprocess.run([sys.executable, "-c", "import libelastica"], env=env, cwd=package_root,
                       capture_output=True, text=True, timeout=120)
    return r.returncode, r.stderr


def binding_with_header(tmp_path: Path, text: str) -> Path:
    """A copy of the binding whose header (beside the package, found first) is ``text``;
    no pre-parsed module of its own (the build's beside the library is another header's
    unless ``text`` is the header)."""
    root = tmp_path / "site"
    shutil.copytree(PACKAGE, root / "libelastica",
                    ignore=shutil.ignore_patterns("__pycache__", _cdef.FILE, "*.so*", "elastica.h"))
    (root / "libelastica" / "elastica.h").write_text(text)
    return root


def without_residual(text: str) -> str:
    """The header with el_spline_result one double shorter, as a binding older than a
    field would read it."""
    start_ = text.index("typedef struct el_spline_result {")
    end = text.index("} el_spline_result;", start_)
    struct = text[start_:end]
    line = next(s for s in struct.splitlines(keepends=True) if s.lstrip().startswith("double residual;"))
    return text[:start_] + struct.replace(line, "", 1) + text[end:]


def test_the_library_states_the_headers_digest():
    assert _ffi.lib.el_abi_digest() == _cdef.digest(_cdef.cdef_text(HEADER))


def test_the_same_header_imports(tmp_path):
    """The copy the other tests change starts as it is (their ImportError is the header's)."""
    status, err = start(binding_with_header(tmp_path, HEADER.read_text()), LIBRARY)
    assert status == 0, err


def test_a_library_built_from_another_header_is_refused(tmp_path):
    text = without_residual(HEADER.read_text())
    from cffi import FFI
    old, new = FFI(), FFI()
    old.cdef(_cdef.cdef_text(HEADER))
    changed = tmp_path / "changed.h"
    changed.write_text(text)
    new.cdef(_cdef.cdef_text(changed))
    assert new.sizeof("el_spline_result") == old.sizeof("el_spline_result") - 8
    root = binding_with_header(tmp_path, text)
    status, err = start(root, LIBRARY)
    assert status != 0
    last = err.strip().splitlines()[-1]
    assert last.startswith("ImportError: libelastica: the C library"), err
    assert str(LIBRARY) in last and str(root / "libelastica" / "elastica.h") in last, last
    assert "built from another elastica.h" in last and "make lib" in last, last


@pytest.mark.skipif(shutil.which(os.environ.get("CC", "cc")) is None, reason="no C compiler")
def test_a_library_without_the_digest_is_refused(tmp_path):
    """A library older than el_abi_digest (a stub: the binding looks symbols up lazily,
    so without the check it imports)."""
    src = tmp_path / "old.c"
    src.write_text("const char *el_version(void) { return \"0.0.9\"; }\n")
    so = tmp_path / "libelastica.so"
    subprocess.run([os.environ.get("CC", "cc"), "-shared", "-fPIC", str(src), "-o", str(so)], check=True)
    status, err = start(PACKAGE.parent, so)
    assert status != 0
    last = err.strip().splitlines()[-1]
    assert last.startswith("ImportError: libelastica: the C library"), err
    assert str(so) in last and str(HEADER) in last and "has no el_abi_digest" in last, last


def test_version_is_the_headers():
    """__version__ (pyproject.toml's, read from __init__.py), the loaded library's
    el_version() and the header's EL_VERSION_STRING / _MAJOR / _MINOR / _PATCH (the one
    place the version is written: the Makefile reads it there) are the same."""
    import re

    import libelastica as el
    text = HEADER.read_text()
    macro = {m[0]: m[1] for m in re.findall(r"^#define EL_VERSION_(\w+) (\S+)$", text, re.M)}
    assert set(macro) == {"MAJOR", "MINOR", "PATCH", "STRING"}, macro
    assert macro["STRING"] == f'"{macro["MAJOR"]}.{macro["MINOR"]}.{macro["PATCH"]}"'
    assert el.__version__ == macro["STRING"].strip('"')
    assert _ffi.ffi.string(_ffi.lib.el_version()).decode() == el.__version__


ONE_CALL_PROBE = ("import numpy as np, libelastica as el, libelastica._fit_call as f; "
                  "t = np.linspace(0, 2, 40); P = np.column_stack([t, 0.3 * t * t + 0.01 * np.sin(7 * t)]); "
                  "print(f._ONE_CALL is not None); print(el.fit(P, check_misfit=False).rms.hex())")


@pytest.mark.parametrize("changed", [False, True])
def test_el_fit_calls_the_entry_of_its_own_binding_h_alone(tmp_path, changed):
    """el.fit's one call (el_binding_fit, libelastica/binding.h: not in elastica.h, so not
    under el_abi_digest) only where the library was built from the binding.h the binding
    read (el_binding_digest, binding.h's CRC-32): a binding.h whose entry takes one argument
    more (an older or a newer library's) would pass its arguments otherwise than the library
    reads them; el.fit takes its plain path there, the same fit."""
    internal = Path(_ffi._internal(str(HEADER)))
    text = internal.read_text()
    assert _ffi.lib.el_binding_digest() == _cdef.digest(_cdef.cdef_text(internal)) == _ffi.BINDING_DIGEST
    if changed:
        assert text.count("double *figures);") == 1
        text = text.replace("double *figures);", "double *figures, double extra);")
    root = binding_with_header(tmp_path, HEADER.read_text())
    (root / "libelastica" / "binding.h").write_text(text)
    env = dict(os.environ, LIBELASTICA_PATH=str(LIBRARY), PYTHONPATH=str(root))
    r = subprocess.run([sys.executable, "-c", ONE_CALL_PROBE], env=env, cwd=root, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 0, r.stderr
    called, rms = r.stdout.split()
    assert called == str(not changed)
    t = np.linspace(0, 2, 40)
    assert rms == el.fit(np.column_stack([t, 0.3 * t * t + 0.01 * np.sin(7 * t)]), check_misfit=False).rms.hex()
