"""What the ``elastica`` command's subcommands share (cli.py, cli_fit.py): the exit
statuses and program name, numbers and tables for the terminal, argument checks, the
batch progress bar, a fitted curve's B-spline and a plane's record."""
from __future__ import annotations

import re
import sys
from contextlib import contextmanager
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from .io import InputError


@contextmanager
def tol_option(option: str):
    """A B-spline's tol not reached (NotConvergedError, exit 1) or below what doubles
    resolve (DomainError, exit 2) said with the option that sets it (QA: "raise tol" named
    no option)."""
    from ._ffi import DomainError, NotConvergedError
    try:
        yield
    except (NotConvergedError, DomainError) as exc:
        raise type(exc)(exc.status, f"{exc} ({option} sets tol)") from None

EXIT_OK, EXIT_NOCONV, EXIT_BADINPUT, EXIT_INTERNAL = 0, 1, 2, 3

PROG = "elastica"


@contextmanager
def said_warnings(command: str):
    """Every warning raised under the command that it does not say itself, said on stderr
    in the command's words: one line 'elastica COMMAND: warning: ...', without Python's
    file:line, category and source line, and without the binding function's name ('fit: ')
    before it (QA20 F3: `fit --start-tangent 400` showed 'fit.py:692: UserWarning: ...' and
    its source line). The binding's radians check (AngleUnitWarning: degrees?) is not said:
    the command line reads every angle with its unit (angle(); a tangent past a full turn is
    said by cli_fit in degrees)."""
    import warnings
    import libelastica as el

    def show(message, category, filename, lineno, file=None, line=None):
        text = " ".join(str(message).split())
        name, colon, rest = text.partition(": ")
        if colon and name.isidentifier() and callable(getattr(el, name, None)):
            text = rest     # 'fit: ...' of el.fit: the command names itself
        print(f"{PROG} {command}: warning: {text}", file=sys.stderr)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", el.AngleUnitWarning)
        warnings.showwarning = show
        yield


def _fmt(v: Any, width: int = 0) -> str:
    if isinstance(v, float):
        s = f"{v:.6g}"
    elif v is None:
        s = "-"
    else:
        s = str(v)
    return s.rjust(width) if width else s


def _table(headers: Sequence[str], rows: Sequence[Sequence[Any]]) -> str:
    cells = [[_fmt(c) for c in r] for r in rows]
    widths = [max([len(h)] + [len(r[i]) for r in cells]) for i, h in enumerate(headers)]
    lines = ["  ".join(h.ljust(w) for h, w in zip(headers, widths)),
             "  ".join("-" * w for w in widths)]
    lines += ["  ".join(c.ljust(w) for c, w in zip(r, widths)) for r in cells]
    return "\n".join(ln.rstrip() for ln in lines)


def _float_list(text: str, n: int, what: str) -> List[float]:
    try:
        vals = [float(v) for v in text.split(",")]
    except ValueError:
        raise InputError(f"{what}: expected {n} comma-separated numbers, got {text!r}") from None
    if len(vals) != n or not all(np.isfinite(vals)):
        raise InputError(f"{what}: expected {n} finite comma-separated numbers, got {text!r}")
    return vals


ANGLE_UNITS = "degrees, or radians with 'rad' after the number ('0.5rad')"
_ANGLE = re.compile(r"\s*(\S+?)\s*(deg|rad)?\s*", re.IGNORECASE)


def angle(text: str) -> float:
    """An angle of the command line in radians (what el.fit takes): degrees, as every angle
    the user types ('30', '30deg'), or radians with 'rad' after it ('0.5rad'); ValueError
    when it is no finite number."""
    m = _ANGLE.fullmatch(text)
    if m is None:
        raise ValueError(f"no angle: {text!r}")
    v = float(m.group(1))
    if not np.isfinite(v):
        raise ValueError(f"no finite angle: {text!r}")
    return v if (m.group(2) or "").lower() == "rad" else np.radians(v)


def _finite(x: float, what: str) -> float:
    if not np.isfinite(x):
        raise InputError(f"{what} must be finite, got {x}")
    return x


def _status_text(status: Any) -> str:
    from ._ffi import ffi, lib
    if isinstance(status, (int, np.integer)) and not isinstance(status, bool):
        return "ok" if status == lib.EL_OK else ffi.string(lib.el_strerror(int(status))).decode()
    return str(status)


def _converged(res: Any) -> bool:
    """Whether a FitResult converged (its status EL_OK, or a 'converged' flag)."""
    from ._ffi import lib
    if hasattr(res, "converged"):
        return bool(res.converged)
    status = getattr(res, "status", 0)
    if isinstance(status, (int, np.integer)) and not isinstance(status, bool):
        return int(status) == lib.EL_OK
    if isinstance(status, bool):
        return status
    return str(status).lower() in ("ok", "converged", "success", "el_ok")


class _Progress:
    """A text progress bar on stderr (batch mode). clear() wipes the bar's line before
    other output (a file's warnings) would be written after it on the same line."""
    WIDTH = 30

    def __init__(self, total: int, enabled: bool):
        self.total, self.enabled, self.done = total, enabled, 0
        self.shown = 0      # characters of the bar's line on the screen (no newline yet)

    def step(self, label: str) -> None:
        self.done += 1
        if not self.enabled:
            return
        filled = int(self.WIDTH * self.done / max(self.total, 1))
        line = f"[{'#' * filled}{'.' * (self.WIDTH - filled)}] {self.done}/{self.total} {label[:40]:<40}"
        sys.stderr.write("\r" + line)
        self.shown = len(line)
        if self.done == self.total:
            sys.stderr.write("\n")
            self.shown = 0
        sys.stderr.flush()

    def clear(self) -> None:
        if self.shown:
            sys.stderr.write("\r" + " " * self.shown + "\r")
            sys.stderr.flush()
            self.shown = 0


def _input_map(rec: Dict[str, Any]):
    """The map from a fit record's curve coordinates to its input's, as `fit` writes its
    DXF: a keyline's x''y'' to the plane ("frame2d"), the plane to 3D ("plane"); None when
    they are the same."""
    from .prep import Frame, Frame2D
    maps = []
    f2, pl = rec.get("frame2d"), rec.get("plane")
    if f2:
        maps.append(Frame2D(origin=np.asarray(f2["origin"], float), f1=np.asarray(f2["f1"], float),
                            f2=np.asarray(f2["f2"], float), eigenvalues=np.zeros(2)).to_parent)
    if pl:
        maps.append(Frame(origin=np.asarray(pl["origin"], float), e1=np.asarray(pl["e1"], float),
                          e2=np.asarray(pl["e2"], float), e3=np.asarray(pl["normal"], float),
                          eigenvalues=np.zeros(3), rms=float(pl["rms"])).to_3d)
    if not maps:
        return None

    def to_input(xy):
        for m in maps:
            xy = m(xy)
        return xy
    return to_input


def _mapped_bspline(b, to_input):
    """The BSpline b with its poles mapped by to_input (BSpline.mapped: an isometry, the
    curve maps exactly); b itself when to_input is None."""
    return b if to_input is None else b.mapped(to_input)


def _plane_record(frame) -> Optional[Dict[str, Any]]:
    if frame is None:
        return None
    return {"origin": frame.origin, "normal": frame.e3, "e1": frame.e1, "e2": frame.e2,
            "rms": frame.rms}


def thousands_option(parser) -> None:
    """--thousands of a command that reads point files (io.read_points' thousands)."""
    parser.add_argument("--thousands", choices=(".", ",", "none"),
                        help="how point files group thousands: '.' (980;1.250 is 980, 1250: "
                             "Excel's #.##0 with decimal commas), ',' (1,250 is 1250: English "
                             "#,##0, '.' the decimal point), or none (1.250 is 1.25, 1,250 is "
                             "1.25); default: what the file shows, a file that does not show "
                             "it refused")


def thousands(args) -> Optional[str]:
    """io.read_points' thousands from --thousands: '.', '' (none) or None (the file decides)."""
    t = getattr(args, "thousands", None)
    return None if t is None else ("" if t == "none" else t)


def holding_advice(said: str, pts, ends, closed) -> str:
    """The spline command's DomainError at tension 0 (no free batten, ``said``) in the CLI's
    words: the least tension of el.holding_tension's ladder whose spline holds (solved: no
    loops, not unstable), for the designer to type; or that none of them does."""
    from .spline import SMALL_TENSION_TEXT, holding_tension, ladder_words, sharpest_turn
    said = said.replace(SMALL_TENSION_TEXT, "")
    m, tension, sp, polygon = holding_tension(pts, ends["start"], ends["end"], closed)
    if sp is None:
        i, deg = sharpest_turn(pts, closed)
        n = len(pts)
        return (f"{said}; no tension of {ladder_words()} / the polygon squared (polygon "
                f"{polygon:.6g}) "
                "gives a spline that holds without loops: at each it loops, is an unstable "
                "equilibrium (a real batten would snap) or is not found; move apart points "
                f"{(i - 1) % n} and {(i + 1) % n}, either side of the sharpest turn (at point "
                f"{i}, {deg:.3g} deg, counted from 0), or give a --length")
    return (f"{said}: --tension {tension:.3g} ({m:g} / the polygon {polygon:.6g} squared) gives "
            f"a fair spline that holds (length {sp.length:.6g}, {sp.length / polygon:.3g} x the "
            f"polygon), the least of {ladder_words(4)} / polygon^2 that neither loops nor is "
            "an unstable equilibrium (a smaller one may: a real batten bent so would snap)")


def dxf_units(path, unit: Optional[str], args) -> str:
    """The DXF's $INSUNITS (a key of io.DXF_UNITS) for a file whose header names ``unit``
    (io.read_points_unit; None: none): --units where given ('none' too: an untagged
    drawing), else the header's where DXF has it, else 'none'. A --units naming another
    unit than the header's of ``path`` (``args`` the command's) is an InputError naming both,
    one DXF cannot say too (km, yd: QA revD, 'x [km]' with --units m made a drawing 1000 x
    too small); a header's px, of no size, may be given one."""
    from .io import DXF_UNITS
    given = getattr(args, "units", None)     # (None: not given)
    if given not in (None, "none") and unit not in (None, "px") and unit != given:
        raise InputError(f"{path}: --units {given} but its header gives the coordinates in "
                         f"{unit}: drop --units (" + (
                             f"the header's {unit} tags the DXF" if unit in DXF_UNITS else
                             f"DXF's --units cannot say {unit}: the drawing is left unitless")
                         + ") or fix the header")
    return given if given is not None else unit if unit in DXF_UNITS else "none"
