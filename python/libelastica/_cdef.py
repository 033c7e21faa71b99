"""Private: the C declarations the binding uses, from the one public header.

``cdef_text`` is include/elastica.h without its preprocessor lines, as cffi's cdef
takes it. Parsing it costs every start ~40 ms (and pycparser's import), so the build
(``make lib``, the wheel) also writes it pre-parsed: cffi's out-of-line ABI module
(``set_source(name, None)``, pure Python, no C compiler), which records the CRC-32 of
the text it was made from. ``declarations`` takes such a module only when that digest
is the header's and this interpreter's cffi accepts its format (``_cffi_backend`` checks
the version the module states): else it parses the header as before. The same digest,
compiled into the library (``abi_header``: elastica_abi.h, el_abi_digest), tells at import
whether the library was built from the header the binding read.

Standard library only at import (the binding imports it on every start); cffi's parser
is imported by ``write_module`` alone. As a script, without the package (so without the
C library): ``python _cdef.py HEADER OUT.py [INTERNAL.h]``, ``python _cdef.py --abi HEADER OUT.h``,
``python _cdef.py --binding-abi INTERNAL.h OUT.h``.
"""
from __future__ import annotations

import importlib.util
import re
import sys
import zlib
from pathlib import Path

MODULE = "_elastica_abi"             # the pre-parsed module's name
FILE = MODULE + ".py"                # beside the library (make lib) or in the package (wheel)
_DIGEST = "CDEF_CRC32"               # the text's digest, a name of the module


def cdef_text(header) -> str:
    """The header as a cdef: the C++ guard and every preprocessor line removed
    (DESIGN.md: no macros in declarations)."""
    text = Path(header).read_text()
    text = re.sub(r"#ifdef __cplusplus.*?#endif", "", text, flags=re.S)
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("#"))


def digest(text: str) -> int:
    """The text's CRC-32: tells a module made from another header (an edit since the
    build), not a forgery; hashlib's import would cost a start 5 % of numpy's."""
    return zlib.crc32(text.encode())


def load_module(path: Path, text: str):
    """The FFI of the pre-parsed module at path when it was made from ``text``; None when
    there is none, it is another header's, or this cffi refuses its format."""
    if not path.is_file():
        return None
    spec = importlib.util.spec_from_file_location(f"libelastica.{MODULE}", path)
    module = importlib.util.module_from_spec(spec)
    try:
        spec.loader.exec_module(module)
    except ImportError:              # _cffi_backend: "... has unknown version"
        return None
    return module.ffi if getattr(module, _DIGEST, None) == digest(text) else None


def binding_text(header, internal=None) -> str:
    """The binding's cdef: the header's (:func:`cdef_text`), then where given the internal
    header's, libelastica/binding.h (the binding's own entry, not public: its declarations
    take the header's types only, so the header's digest covers their layout)."""
    text = cdef_text(header)
    return text if internal is None else text + "\n" + cdef_text(internal)


def declarations(header, folders, internal=None):
    """(ffi, path of the pre-parsed module used or None, the header's digest): the first
    of ``folders`` whose module was made from ``header`` and ``internal``
    (:func:`binding_text`), else their text parsed now (the same declarations). The
    digest is the public header's (el_abi_digest's)."""
    text = binding_text(header, internal)
    crc = digest(cdef_text(header))
    for folder in dict.fromkeys(Path(f) for f in folders):
        ffi = load_module(folder / FILE, text)
        if ffi is not None:
            return ffi, str(folder / FILE), crc
    from cffi import FFI
    ffi = FFI()
    ffi.cdef(text)
    return ffi, None, crc


def abi_header(header, out, macro: str = "EL_ABI_DIGEST") -> None:
    """Write elastica_abi.h: EL_ABI_DIGEST, the digest of ``header``'s declarations,
    which libelastica/abi.c returns from el_abi_digest (the header says how to check);
    macro EL_BINDING_DIGEST: binding_abi.h, binding.h's, which el_binding_digest returns
    (libelastica/binding.c; _fit_call.py calls el_binding_fit only where it is binding.h's
    the binding read)."""
    guard, flag = ("ELASTICA_ABI_H", "--abi") if macro == "EL_ABI_DIGEST" else ("EL_BINDING_ABI_H", "--binding-abi")
    Path(out).write_text(f"/* Written by the build (python/libelastica/_cdef.py {flag}) from {Path(header).name}. */\n"
                         f"#ifndef {guard}\n#define {guard}\n"
                         f"#define {macro} 0x{digest(cdef_text(header)):08x}UL\n#endif\n")


def write_module(header, out, internal=None) -> None:
    """Write the pre-parsed module of ``header`` (and ``internal``: :func:`binding_text`) to
    ``out`` (replaced whole, never left half written)."""
    import os
    import tempfile
    from cffi import FFI, __version__
    text = binding_text(header, internal)
    builder = FFI()
    builder.cdef(text)
    builder.set_source(MODULE, None)
    out = Path(out)
    with tempfile.TemporaryDirectory(dir=out.parent) as tmp:
        code = Path(builder.compile(tmpdir=tmp, verbose=False)).read_text()
        part = Path(tmp) / "part"
        part.write_text(f"# libelastica's declarations (include/elastica.h), parsed by cffi {__version__}:\n"
                        f"# written by _cdef.py; used only where {_DIGEST} is the header's.\n"
                        f"{_DIGEST} = {digest(text)!r}\n{code}")
        os.replace(part, out)


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "--abi":
        abi_header(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 4 and sys.argv[1] == "--binding-abi":
        abi_header(sys.argv[2], sys.argv[3], "EL_BINDING_DIGEST")
    elif len(sys.argv) in (3, 4):
        write_module(sys.argv[1], sys.argv[2], sys.argv[3] if len(sys.argv) == 4 else None)
    else:
        sys.exit("usage: python _cdef.py HEADER OUT.py [INTERNAL.h] | python _cdef.py --abi HEADER OUT.h | "
                 "python _cdef.py --binding-abi INTERNAL.h OUT.h")
