"""Elastica workbench for FreeCAD: fit sketches and scanned keylines with Euler's
elastica, elastic Hermite blends between edges, curvature combs, B-splines back
into sketches. All numerics come from the libelastica Python binding.

Namespace package ``freecad.elastica`` (no ``freecad/__init__.py`` here): FreeCAD
finds it through a Mod folder holding ``freecad_wb`` (a symlink is enough).
"""
import importlib
import os
import sys

__version__ = "0.2.0"

_HERE = os.path.dirname(os.path.realpath(__file__))
ICONPATH = os.path.join(_HERE, "resources", "icons")
# freecad_wb/freecad/elastica -> the source tree root
_SRC_ROOT = os.path.realpath(os.path.join(_HERE, "..", "..", ".."))
PREF_PATH = "User parameter:BaseApp/Preferences/Mod/Elastica"


def icon(name):
    """Absolute path of one of the workbench's SVG icons."""
    return os.path.join(ICONPATH, name + ".svg")


def ensure_binding():
    """Import libelastica: the source tree's binding when the workbench lives in one
    (``python/`` beside ``freecad_wb/``, tried first: the same version as the
    workbench; it finds ``build/libelastica.so`` itself, or LIBELASTICA_PATH), else
    an installed package. The C sources' folder ``libelastica/`` must not pass for
    the package when FreeCAD has put the tree's root on sys.path (an Addon Manager
    install): a package without ``__file__`` is such a namespace and is dropped."""
    src = os.path.join(_SRC_ROOT, "python")
    if os.path.isdir(os.path.join(src, "libelastica")) and src not in sys.path:
        sys.path.insert(0, src)
    mod = sys.modules.get("libelastica")
    if mod is not None and getattr(mod, "__file__", None) is None:
        del sys.modules["libelastica"]
    importlib.import_module("libelastica")
    if getattr(sys.modules["libelastica"], "__file__", None) is None:
        del sys.modules["libelastica"]
        raise ImportError("libelastica: found only a folder of that name, not the Python "
                          "package")
    return sys.modules["libelastica"]


def library_problem():
    """'' when the libelastica binding loads, else a message naming the exact
    command that builds the C library (for this source tree): the library is missing,
    or was built from another elastica.h than the binding's (the binding's ImportError
    names both files)."""
    try:
        ensure_binding()
        return ""
    except (ImportError, OSError) as exc:
        src = _SRC_ROOT if os.path.isfile(os.path.join(_SRC_ROOT, "Makefile")) else ""
        how = (f"run  make -C {src} freecad-install  (or  make -C {src} lib)" if src else
               "install the libelastica Python package and its C library")
        what = "is missing" if "another elastica.h" not in str(exc) else "does not match the binding"
        return f"the libelastica library {what} ({exc}); {how}, then restart FreeCAD"


def defaults():
    """The workbench's defaults: (tolerance mm, B-spline degree, model)."""
    import FreeCAD as App
    p = App.ParamGet(PREF_PATH)
    tol = p.GetFloat("Tolerance", 0.001)
    deg = p.GetInt("Degree", 3)
    model = p.GetString("Model", "discrete")
    return (tol if 1e-9 <= tol <= 1e3 else 0.001, deg if 3 <= deg <= 7 else 3,
            model if model in ("discrete", "smooth") else "discrete")
