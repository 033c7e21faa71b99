"""In-tree PEP 517 / PEP 660 build backend for the libelastica Python package.

Why not setuptools: the wheel has to carry a C library built from the source
tree next to this folder, and `pip install ./python` must work offline in a
fresh venv; setuptools (plus `wheel`) would have to be fetched from an index for
an isolated build. This backend uses only the standard library:

* build_wheel: compiles ../libelastica/*.c (or csrc/ in an sdist) with $CC and
  `pkg-config --cflags --libs gsl ipopt` into libelastica/libelastica.so, copies
  ../include/elastica.h beside it with its declarations pre-parsed by cffi
  (libelastica/_cdef.py; skipped when this interpreter has no cffi: the package then
  parses the header at import), and zips the package, the metadata from
  pyproject.toml and the `elastica` console script into a wheel. The library is
  found by libelastica/_ffi.py next to the package first (unless LIBELASTICA_PATH
  is set). With LIBELASTICA_SKIP_BUILD=1 no library is bundled (pure wheel): the
  package then needs LIBELASTICA_PATH or a `make install`ed library.
* build_editable: a wheel holding a .pth file pointing at this folder; the
  library then comes from the source tree's build/ (`make`) or LIBELASTICA_PATH.
* build_sdist: the package, this backend and a copy of the C sources in csrc/.
"""
from __future__ import annotations

import base64
import concurrent.futures
import hashlib
import io
import os
import re
import shlex
import subprocess
import sys
import sysconfig
import tarfile
import tempfile
import zipfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
PKG = "libelastica"
SONAME = "libelastica.so.0"
ABI_FILE = "_elastica_abi.py"          # libelastica/_cdef.py's FILE

try:
    import tomllib
except ImportError:          # Python < 3.11: the build requirement 'tomli'
    import tomli as tomllib


# ------------------------------------------------------------------ metadata

def _project() -> dict:
    with open(HERE / "pyproject.toml", "rb") as f:
        return tomllib.load(f)["project"]


def _version() -> str:
    text = (HERE / PKG / "__init__.py").read_text()
    m = re.search(r'^__version__\s*=\s*["\']([^"\']+)["\']', text, re.M)
    if not m:
        raise RuntimeError("libelastica/__init__.py has no __version__")
    return m.group(1)


def _metadata() -> str:
    p = _project()
    lines = ["Metadata-Version: 2.1", f"Name: {p['name']}", f"Version: {_version()}",
             f"Summary: {p.get('description', '')}"]
    if "requires-python" in p:
        lines.append(f"Requires-Python: {p['requires-python']}")
    if "license" in p and "text" in p["license"]:
        lines.append(f"License: {p['license']['text']}")
    for dep in p.get("dependencies", []):
        lines.append(f"Requires-Dist: {dep}")
    for extra, deps in p.get("optional-dependencies", {}).items():
        lines.append(f"Provides-Extra: {extra}")
        for dep in deps:
            lines.append(f'Requires-Dist: {dep}; extra == "{extra}"')
    readme = HERE.parent / "README.md"
    body = readme.read_text() if readme.is_file() else ""
    if body:
        lines.append("Description-Content-Type: text/markdown")
    return "\n".join(lines) + "\n\n" + body


def _entry_points() -> str:
    scripts = _project().get("scripts", {})
    if not scripts:
        return ""
    return "[console_scripts]\n" + "".join(f"{k} = {v}\n" for k, v in scripts.items())


def _dist_info() -> str:
    return f"{PKG}-{_version()}.dist-info"


# ------------------------------------------------------------------ the C library

def _c_sources():
    """(source dir with *.c, include dir with elastica.h) from the repository or an sdist."""
    for src, inc in ((HERE.parent / "libelastica", HERE.parent / "include"),
                     (HERE / "csrc" / "libelastica", HERE / "csrc" / "include")):
        if src.is_dir() and (inc / "elastica.h").is_file() and list(src.glob("*.c")):
            return src, inc
    return None, None


def _pkg_config(*args: str) -> list:
    try:
        out = subprocess.run(["pkg-config", *args, "gsl", "ipopt"], check=True,
                             capture_output=True, text=True).stdout
    except (OSError, subprocess.CalledProcessError) as exc:
        raise RuntimeError("libelastica: pkg-config could not find GSL and Ipopt "
                           "(Debian: apt-get install pkg-config libgsl-dev coinor-libipopt-dev)"
                           ) from exc
    return shlex.split(out)


def _per_file_cflags(cc: list) -> dict:
    """The Makefile's flags of one object alone: hermite_lanes_avx2.c, the four AVX2 lanes of
    the Hermite objective (run only where the processor has AVX2, hermite_lanes.c's
    __builtin_cpu_supports), is compiled with -mavx2 and without fused multiply-add on
    x86-64 (the same test as the Makefile's: $CC -dumpmachine); elsewhere it builds empty."""
    try:
        machine = subprocess.run(cc + ["-dumpmachine"], check=True, capture_output=True,
                                 text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        machine = ""
    if machine.startswith("x86_64"):
        return {"hermite_lanes_avx2.c": ["-mavx2", "-ffp-contract=off"]}
    return {}


def _build_library(outdir: Path) -> Path:
    """Compile the C library into outdir/libelastica.so (the same flags as the Makefile,
    without -Werror: a newer compiler's warning must not break a user's install)."""
    src, inc = _c_sources()
    if src is None:
        raise RuntimeError("libelastica: C sources not found next to the Python package; "
                           "set LIBELASTICA_SKIP_BUILD=1 and LIBELASTICA_PATH to use an installed "
                           "library")
    cc = shlex.split(os.environ.get("CC", "cc"))
    objdir = outdir / "obj"
    objdir.mkdir(parents=True, exist_ok=True)
    # elastica_abi.h: the header's digest, which the library's el_abi_digest returns (abi.c)
    subprocess.run([sys.executable, "-E", str(HERE / PKG / "_cdef.py"), "--abi", str(inc / "elastica.h"),
                    str(objdir / "elastica_abi.h")], check=True)
    # binding_abi.h: binding.h's, which el_binding_digest returns (binding.c; _fit_call.py)
    subprocess.run([sys.executable, "-E", str(HERE / PKG / "_cdef.py"), "--binding-abi", str(src / "binding.h"),
                    str(objdir / "binding_abi.h")], check=True)
    cflags = ["-std=c99", "-O2", "-fPIC", f"-I{inc}", f"-I{src}", f"-I{objdir}"] + _pkg_config("--cflags")
    own = _per_file_cflags(cc)

    def compile_one(c: Path) -> Path:
        obj = objdir / (c.stem + ".o")
        subprocess.run(cc + cflags + own.get(c.name, []) + ["-c", str(c), "-o", str(obj)], check=True)
        return obj

    sources = sorted(src.glob("*.c"))
    with concurrent.futures.ThreadPoolExecutor(max_workers=os.cpu_count() or 2) as pool:
        objs = list(pool.map(compile_one, sources))
    so = outdir / "libelastica.so"
    # the API alone, as the Makefile's library (libelastica/exports.map: el__* stay local)
    exports = [f"-Wl,--version-script={src / 'exports.map'}"] if (src / "exports.map").is_file() else []
    subprocess.run(cc + ["-shared", f"-Wl,-soname,{SONAME}"] + exports + ["-o", str(so)]
                   + [str(o) for o in objs] + _pkg_config("--libs") + ["-lm", "-pthread"],
                   check=True)
    return so


def _abi_module(header: Path, internal: Path):
    """The header's declarations and the internal header's (binding.h) pre-parsed
    (libelastica/_cdef.py) by this interpreter's cffi, or None when it has none. Run with
    -E: pip's build isolation hides the interpreter's site-packages (through PYTHONPATH),
    where cffi, a dependency, is."""
    with tempfile.TemporaryDirectory(prefix="libelastica-abi-") as tmp:
        out = Path(tmp) / ABI_FILE
        r = subprocess.run([sys.executable, "-E", str(HERE / PKG / "_cdef.py"), str(header), str(out),
                            str(internal)],
                           capture_output=True, text=True)
        return out.read_bytes() if r.returncode == 0 else None


# ------------------------------------------------------------------ wheel writing

def _record_line(arcname: str, data: bytes) -> str:
    digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
    return f"{arcname},sha256={digest},{len(data)}"


def _write_wheel(wheel_directory: str, tag: str, files: dict) -> str:
    """files: arcname -> bytes (package files); adds the .dist-info and RECORD."""
    di = _dist_info()
    files = dict(files)
    files[f"{di}/METADATA"] = _metadata().encode()
    files[f"{di}/WHEEL"] = ("Wheel-Version: 1.0\nGenerator: libelastica _build_backend\n"
                            f"Root-Is-Purelib: {'true' if tag.endswith('-any') else 'false'}\n"
                            f"Tag: {tag}\n").encode()
    ep = _entry_points()
    if ep:
        files[f"{di}/entry_points.txt"] = ep.encode()
    files[f"{di}/top_level.txt"] = f"{PKG}\n".encode()
    name = f"{PKG}-{_version()}-{tag}.whl"
    record = [_record_line(a, d) for a, d in files.items()] + [f"{di}/RECORD,,"]
    with zipfile.ZipFile(Path(wheel_directory) / name, "w", zipfile.ZIP_DEFLATED) as z:
        for arc, data in files.items():
            info = zipfile.ZipInfo(arc, date_time=(2020, 1, 1, 0, 0, 0))
            info.external_attr = (0o755 if arc.endswith(".so") else 0o644) << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, data)
        z.writestr(f"{di}/RECORD", "\n".join(record) + "\n")
    return name


def _package_files() -> dict:
    files = {}
    for p in sorted((HERE / PKG).rglob("*")):
        if p.is_file() and "__pycache__" not in p.parts and p.suffix not in (".pyc", ".so"):
            if p.name in ("elastica.h", "binding.h", ABI_FILE):
                continue               # a stale copy; the build adds the tree's own
            files[p.relative_to(HERE).as_posix()] = p.read_bytes()
    return files


def _platform_tag() -> str:
    return "py3-none-" + re.sub(r"[-.]", "_", sysconfig.get_platform())


# ------------------------------------------------------------------ PEP 517 hooks

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    files = _package_files()
    src, inc = _c_sources()
    if inc is not None:
        files[f"{PKG}/elastica.h"] = (inc / "elastica.h").read_bytes()
        files[f"{PKG}/binding.h"] = (src / "binding.h").read_bytes()      # (_ffi._internal)
        abi = _abi_module(inc / "elastica.h", src / "binding.h")
        if abi is not None:
            files[f"{PKG}/{ABI_FILE}"] = abi
    if os.environ.get("LIBELASTICA_SKIP_BUILD"):
        return _write_wheel(wheel_directory, "py3-none-any", files)
    with tempfile.TemporaryDirectory(prefix="libelastica-build-") as tmp:
        so = _build_library(Path(tmp))
        files[f"{PKG}/libelastica.so"] = so.read_bytes()
    return _write_wheel(wheel_directory, _platform_tag(), files)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    files = {f"__editable__.{PKG}.pth": (str(HERE) + "\n").encode()}
    return _write_wheel(wheel_directory, "py3-none-any", files)


def build_sdist(sdist_directory, config_settings=None):
    base = f"{PKG}-{_version()}"
    name = f"{base}.tar.gz"
    src, inc = _c_sources()
    with tarfile.open(Path(sdist_directory) / name, "w:gz") as tar:
        def add(path: Path, arc: str):
            tar.add(str(path), arcname=f"{base}/{arc}",
                    filter=lambda ti: None if "__pycache__" in ti.name else ti)
        add(HERE / "pyproject.toml", "pyproject.toml")
        add(HERE / "_build_backend.py", "_build_backend.py")
        for arc, data in _package_files().items():
            ti = tarfile.TarInfo(f"{base}/{arc}")
            ti.size = len(data)
            tar.addfile(ti, io.BytesIO(data))
        if src is not None and not str(src).startswith(str(HERE)):
            for f in sorted(src.glob("*.[ch]")) + [src / "exports.map"]:
                add(f, f"csrc/libelastica/{f.name}")
            add(inc / "elastica.h", "csrc/include/elastica.h")
        pkg_info = _metadata().encode()
        ti = tarfile.TarInfo(f"{base}/PKG-INFO")
        ti.size = len(pkg_info)
        tar.addfile(ti, io.BytesIO(pkg_info))
    return name


if __name__ == "__main__":     # python _build_backend.py DIR: build a wheel by hand
    print(build_wheel(sys.argv[1] if len(sys.argv) > 1 else "."))
