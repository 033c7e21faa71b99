"""DXF output of :mod:`libelastica.io`: B-splines as SPLINE entities (and points as POINTs)
through the optional ``ezdxf`` package, the drawing's unit and extents. Its public names
are io's (``io.write_dxf_spline``, ``io.have_ezdxf``, ``io.DXF_UNITS``), re-exported there."""
from __future__ import annotations

from pathlib import Path
from typing import Optional, Union

import numpy as np

from ._columns import InputError

PathLike = Union[str, Path]


def have_ezdxf() -> bool:
    """True when the optional DXF library ``ezdxf`` is importable."""
    try:
        import ezdxf  # noqa: F401
    except ImportError:
        return False
    return True


def _xyz(p) -> list:
    """A 2D or 3D point as three floats (z = 0 for 2D)."""
    v = [float(c) for c in p[:3]]
    return v + [0.0] * (3 - len(v))


#: DXF's $INSUNITS codes of the units a user can name (AutoCAD's table); 0 = unitless,
#: the default: a drawing in the coordinates' own units, scaled by nobody
DXF_UNITS = {"none": 0, "in": 1, "ft": 2, "mm": 4, "cm": 5, "m": 6, "um": 13}
_IMPERIAL = ("in", "ft")
# DXF SPLINE flags (group 70)
_DXF_CLOSED, _DXF_PERIODIC = 1, 2


def _dxf_flags(b, poles: np.ndarray, closed: bool) -> int:
    """A SPLINE's flags: closed when the curve is (its clamped ends meet: a closed
    spline's seam), periodic when its knots and poles also wrap around (unclamped ends,
    the last degree poles the first ones again)."""
    flags = 0
    if closed:
        flags |= _DXF_CLOSED
        p, m = int(b.degree), np.asarray(b.mults)
        if m[0] < p + 1 and m[-1] < p + 1 and np.array_equal(poles[:p], poles[-p:]):
            flags |= _DXF_PERIODIC
    return flags


def _extents(splines, points) -> tuple:
    """(min xyz, max xyz) of the curves and the points: the drawing's $EXTMIN / $EXTMAX
    (ezdxf leaves +-1e20, 'no extents'). A curve's: 64 samples per knot span, each
    coordinate's extremes then polished by Newton on its derivative's zero."""
    xyz = [] if points is None else [np.array([_xyz(p) for p in np.asarray(points, float)])]
    for b in splines:
        u = np.unique(np.concatenate([np.linspace(a, c, 65) for a, c in
                                      zip(b.knots[:-1], b.knots[1:])]))
        xy = b(u)
        dim = xy.shape[1]
        t = u[np.concatenate([np.argmin(xy, axis=0), np.argmax(xy, axis=0)])]
        axis = np.tile(np.arange(dim), 2)
        for _ in range(4):
            d1 = b.derivative(t, 1)[np.arange(len(t)), axis]
            d2 = b.derivative(t, 2)[np.arange(len(t)), axis]
            step = np.divide(d1, d2, out=np.zeros_like(d1), where=d2 != 0.0)
            t = np.clip(t - step, u[0], u[-1])
        xyz.append(np.array([_xyz(p) for p in np.vstack([xy, b(t)])]))
    allp = np.vstack(xyz)
    return tuple(allp.min(axis=0).tolist()), tuple(allp.max(axis=0).tolist())


def write_dxf_spline(splines, path: PathLike, points: Optional[np.ndarray] = None,
                     units: str = "none", closed: bool = False) -> None:
    """Write one BSpline (or a list of them; 2D or 3D poles) as DXF SPLINE entities on
    layer 'elastica' (control points, the full knot vector, degree) with ezdxf;
    ``points`` (n, 2) or (n, 3), if given, go on layer 'data' as POINT entities.
    ``units`` (a key of DXF_UNITS) is the drawing's $INSUNITS: "none" (0, unitless: CAD
    takes the numbers as they are; ezdxf's default 6, metres, made mm data import 1000 x
    too big where it is honoured), "mm", "cm", "m", "in", "ft", "um". $EXTMIN / $EXTMAX
    are the geometry's. ``closed``: the curves are closed (an elastic spline's ring),
    flagged so (and periodic where their knots are). Raises InputError when ezdxf is not
    installed or units is unknown."""
    try:
        import ezdxf
    except ImportError:
        raise InputError("DXF output needs the optional package ezdxf (pip install ezdxf)") from None
    if units not in DXF_UNITS:
        raise InputError(f"DXF units {units!r}: one of {', '.join(DXF_UNITS)}")
    if not isinstance(splines, (list, tuple)):
        splines = [splines]
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = DXF_UNITS[units]
    if units != "none":
        doc.header["$MEASUREMENT"] = 0 if units in _IMPERIAL else 1
    elif "$MEASUREMENT" in doc.header:   # ezdxf's new drawing says metric (1): no unit, no system
        del doc.header["$MEASUREMENT"]
    msp = doc.modelspace()
    for b in splines:
        knots = np.repeat(np.asarray(b.knots, dtype=np.float64), np.asarray(b.mults, dtype=np.int64))
        poles = np.array([_xyz(p) for p in np.asarray(b.poles, dtype=np.float64)])
        e = msp.add_open_spline([tuple(p) for p in poles.tolist()], degree=int(b.degree),
                                knots=knots.tolist(), dxfattribs={"layer": "elastica"})
        e.dxf.flags = _dxf_flags(b, poles, closed)
    if points is not None:
        for p in np.asarray(points, dtype=np.float64):
            msp.add_point(tuple(_xyz(p)), dxfattribs={"layer": "data"})
    if splines or points is not None:   # (ezdxf copies the model space's into the header)
        lo, hi = _extents(splines, points)
        msp.dxf.extmin, msp.dxf.extmax = lo, hi
        doc.header["$EXTMIN"], doc.header["$EXTMAX"] = lo, hi
    doc.saveas(str(path))
