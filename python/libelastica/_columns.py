"""Private: points from a table with named columns (QA19 W1: el.fit(DataFrame) read the
columns by position, so a frame ['y', 'x'] was fitted mirrored). A pandas DataFrame, a
numpy structured or record array, or any object with ``columns`` and ``table[name]``
(duck-typed: pandas is never imported) gives its coordinates by name: ``x``, ``y`` and
``z``, any case, a unit allowed ("x [mm]", "Y (m)"), the names the command line reads in a
header (io.py: one table, :data:`AXIS_NAME`). Columns labelled by position only (integers,
a DataFrame built from an array) are read by position, as any array is.
"""
from __future__ import annotations

import re
from typing import List, Optional

import numpy as np


class InputError(ValueError):
    """Bad user input (a file that is missing, malformed, or holds unusable points)."""
    __module__ = "libelastica.io"   # (defined here, below io and _dxf, which both raise it)


# a coordinate column's name: x, Y, "z [mm]", "x (mm)" (a CSV header's too: io.py)
AXIS_NAME = re.compile(r"\s*([xyzXYZ])\s*(?:[\[(](.*)[\])])?\s*")
# a header's length unit, as the DXF's $INSUNITS names it (io.DXF_UNITS) where it is one of
# those; other words in brackets ('x (Länge)', 'y [east]') name no unit
_UNIT_ALIASES = {"µm": "um", "μm": "um", "micron": "um", "inch": "in", "inches": "in",
                 "foot": "ft", "feet": "ft", "metre": "m", "meter": "m", "metres": "m",
                 "meters": "m", **{u: u for u in ("nm", "um", "mm", "cm", "dm", "m", "km", "in",
                                                  "ft", "yd", "mi", "px", "pt")}}


def axis_of(label) -> Optional[str]:
    """'x', 'y' or 'z' for a column name that names that coordinate, else None."""
    m = AXIS_NAME.fullmatch(label) if isinstance(label, str) else None
    return m.group(1).lower() if m else None


def header_unit(labels, name: str = "points") -> Optional[str]:
    """The length unit the coordinate columns among ``labels`` name ('mm' for "x [mm],y [mm]",
    "X (MM)"; io.DXF_UNITS' spelling where it is one of those: 'um' for 'µm', 'in' for
    'inch'; else km, nm, dm, yd, mi, px, pt), None where none names one (a word that is no
    unit, 'x (Länge)', names none). Columns naming two units raise
    ValueError naming both (``name`` the input's)."""
    units = {}
    for label in labels:
        m = AXIS_NAME.fullmatch(label) if isinstance(label, str) else None
        if m and m.group(2) and m.group(2).strip():
            u = _UNIT_ALIASES.get(m.group(2).strip().lower())
            if u:
                units.setdefault(u, label)
    if len(units) > 1:
        (a, la), (b, lb) = list(units.items())[:2]
        raise ValueError(f"{name}: the columns name two units, {a!r} ({la!r}) and {b!r} "
                         f"({lb!r}): give the coordinates in one unit")
    return next(iter(units), None)


def not_a_table(data: bytes, name: str) -> Optional[str]:
    """io.read_points' message for a JSON, DXF or SVG/XML document given as points, by its
    first bytes after a BOM ('{' or '[', '0' then 'SECTION', '<'), None for anything else
    (review revD: a DXF said 'line 1118: 2 columns where 3717 of 3730 rows have 1 (an empty
    cell?)', a fit's JSON 'line 10: not a number: ']'': a table's messages)."""
    head = (data[3:] if data.startswith(b"\xef\xbb\xbf") else data).lstrip()[:64]
    kind = "JSON" if head[:1] in (b"{", b"[") else "SVG / XML" if head[:1] == b"<" else \
        "DXF" if re.match(rb"0\s*\n\s*SECTION\b", head) else None
    return None if kind is None else (
        f"{name}: a {kind} document, not a table of points: give x, y (z) per line (comma, "
        "semicolon, tab or space separated) or .npy")


def unit_words_joined(fields, width: int) -> list:
    """A header line split at every blank ('x [mm]<TAB>y [mm]' or 'X (mm) Y (mm)' read as
    whitespace separated: x, [mm], y, [mm]) with each bracketed word joined to the name
    before it, where that makes ``width`` fields; else ``fields`` (review revD: such a
    header named no columns, so its unit was lost)."""
    if len(fields) == width:
        return fields
    out = []
    for f in fields:
        if out and re.fullmatch(r"[\[(].*[\])]", f):
            out[-1] += " " + f
        else:
            out.append(f)
    return out if len(out) == width else fields


def column_labels(a) -> Optional[List]:
    """A table's column labels (a structured dtype's field names, a DataFrame-like
    ``columns``), None for anything else (arrays, lists)."""
    if isinstance(a, np.ndarray):
        return list(a.dtype.names) if a.dtype.names else None
    cols = getattr(a, "columns", None)
    if cols is None or isinstance(cols, (str, bytes)) or not hasattr(a, "__getitem__"):
        return None
    try:
        return list(cols)
    except TypeError:
        return None


def axis_columns(labels) -> Optional[List[int]]:
    """The positions of the x, y (and z) columns among ``labels``, in that order; None
    when they name no x or no y, or one of x, y, z twice (the command line's header rule
    too: io.py)."""
    axes = [axis_of(label) for label in labels]
    if "x" not in axes or "y" not in axes or any(axes.count(c) > 1 for c in "xyz"):
        return None
    return [axes.index(c) for c in "xyz" if c in axes]


def table_points(a, name: str = "points", dim: Optional[int] = 2):
    """``a`` itself unless it is a table with named columns; then its x, y columns, and z
    where ``dim`` is 3 (required) or None (when present), as one (n, 2 or 3) array. A table
    whose names hold no x and y, or name one twice, or (``dim`` 2) hold a z, raises
    ValueError naming its columns and what is expected."""
    labels = column_labels(a)
    if labels is None or all(
            isinstance(v, (int, np.integer)) and not isinstance(v, (bool, np.bool_))
            for v in labels):
        return a
    cols = axis_columns(labels)
    if cols is None:
        axes = {}
        for label in labels:
            axis = axis_of(label)
            if axis in axes:
                raise ValueError(f"{name}: the table's columns {labels!r} name {axis} twice "
                                 f"({axes[axis]!r}, {label!r}); keep one")
            if axis:
                axes[axis] = label
    if cols is None or (dim == 3 and len(cols) < 3):
        want = "x, y, z" if dim == 3 else "x, y" if dim == 2 else "x, y (and z)"
        raise ValueError(f"{name}: a table's coordinates are read by name, {want} (any case, "
                         f"a unit allowed: 'x [mm]'); its columns are {labels!r}: rename "
                         "them, or pass an array of the coordinates in that order")
    if dim == 2 and len(cols) == 3:
        raise ValueError(f"{name}: the table's columns {labels!r} hold 3D points (x, y, z); "
                         "this takes x, y: select those two columns, or fit 3D points in "
                         "their plane (el.plane_fit)")
    return np.column_stack([np.asarray(a[labels[i]]) for i in cols])
