"""The binding's declarations pre-parsed by the build (cffi's out-of-line ABI module,
libelastica/_cdef.py): the binding starts through it without parsing the header, it
holds exactly the header's declarations under this interpreter's cffi (the suite runs
under Debian's cffi 1.15 and PyPI's 2.0), and the binding parses the header as before
when the module is missing, made from another header, or of a format cffi refuses."""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from cffi import FFI

from libelastica import _cdef, _ffi

LIBRARY = Path(_ffi._LIBRARY)
BUILT = LIBRARY.parent / _cdef.FILE          # make lib writes it beside the library
TEXT = _cdef.binding_text(_ffi._header(), _ffi._internal(_ffi._header()))   # (with binding.h's)

PROBE = ("import sys, libelastica as el, libelastica._ffi as f; "
         "print(f.CDEF_MODULE); print('pycparser' in sys.modules); "
         "print(repr(el.hermite((0, 0), (1, 0), (1, 0.3), (0.6, 0.8), tension=3.0)[0]))")


def probe(library: Path):
    """(the pre-parsed module used or 'None', pycparser imported?, a Hermite solution's
    repr) of a fresh interpreter whose binding loads ``library``."""
    env = dict(os.environ, LIBELASTICA_PATH=str(library))
    r = subprocess.run([sys.executable, "-c", PROBE], env=env, capture_output=True, text=True,
                       timeout=120)
    assert r.returncode == 0, r.stderr
    module, parsed, solution = r.stdout.splitlines()
    return module, parsed == "True", solution


def library_in(folder: Path) -> Path:
    """The build's library, seen from a folder of its own (a link)."""
    link = folder / "libelastica.so"
    link.symlink_to(LIBRARY)
    return link


def test_build_writes_the_module_beside_the_library():
    assert BUILT.is_file(), f"{BUILT}: `make lib` writes it"
    assert _ffi.CDEF_MODULE == str(BUILT)


def test_binding_starts_without_parsing_the_header():
    module, parsed, _ = probe(LIBRARY)
    assert module == str(BUILT)
    assert not parsed                     # pycparser never imported: no cdef parse


def _declarations(ffi, lib):
    """Everything the binding can reach, as text: types (fields with offsets, sizes),
    functions' signatures, constants' values. Type names without 'struct ': the
    out-of-line module calls a typedef'd struct 'struct X' where the parse says 'X', the
    same type (the header's every typedef is ``typedef struct X {...} X``, checked)."""
    def name(t):
        return t.cname.replace("struct ", "")
    out = {}
    typedefs, structs, unions = ffi.list_types()
    for n in typedefs:
        t = ffi.typeof(n)
        assert t is ffi.typeof(f"struct {n}")
        out[n] = (name(t), ffi.sizeof(t), ffi.alignof(t),
                  [(f, name(ft.type), ft.offset, ft.bitsize) for f, ft in t.fields])
    assert sorted(structs) == sorted(typedefs) and not unions
    for n in dir(lib):
        v = getattr(lib, n)
        out[n] = name(ffi.typeof(v)) if isinstance(v, ffi.CData) else v
    return out


def test_prebuilt_declarations_are_the_headers():
    inline = FFI()
    inline.cdef(TEXT)
    prebuilt = _cdef.load_module(BUILT, TEXT)
    assert prebuilt is not None
    want = _declarations(inline, inline.dlopen(str(LIBRARY)))
    got = _declarations(prebuilt, prebuilt.dlopen(str(LIBRARY)))
    assert len(want) > 140 and got == want


def test_without_the_module_the_header_is_parsed(tmp_path):
    module, parsed, solution = probe(library_in(tmp_path))
    assert module == "None" and parsed
    assert solution == probe(LIBRARY)[2]


def test_a_module_of_another_header_is_not_used(tmp_path):
    header = tmp_path / "elastica.h"
    header.write_text(Path(_ffi._header()).read_text() + "\nint el_not_in_the_library(void);\n")
    _cdef.write_module(header, tmp_path / _cdef.FILE)
    assert _cdef.load_module(tmp_path / _cdef.FILE, _cdef.cdef_text(header)) is not None
    assert _cdef.load_module(tmp_path / _cdef.FILE, TEXT) is None
    module, parsed, _ = probe(library_in(tmp_path))
    assert module == "None" and parsed


def test_a_module_this_cffi_refuses_is_not_used(tmp_path):
    code = BUILT.read_text()
    assert "_version = 0x2601," in code
    (tmp_path / _cdef.FILE).write_text(code.replace("_version = 0x2601,", "_version = 0x9999,"))
    assert _cdef.load_module(tmp_path / _cdef.FILE, TEXT) is None
    module, parsed, _ = probe(library_in(tmp_path))
    assert module == "None" and parsed

