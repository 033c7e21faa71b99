"""Reading measured points and writing results: CSV / whitespace text / .npy
point files, JSON curve files, and DXF (a SPLINE entity, through the optional
``ezdxf`` package: written in :mod:`._dxf`, its names re-exported here; a header's columns
and unit are read in :mod:`._columns`).

Every reader raises :class:`InputError` (a ``ValueError``) with one short,
user-facing line for anything wrong with the input, so the command line can
print it and exit with status 2.
"""
from __future__ import annotations

import csv
import io as _io
import json
import math
import re
from pathlib import Path
from typing import Any, Dict, Optional, Union

import numpy as np

from ._columns import InputError, axis_columns, header_unit, not_a_table, unit_words_joined
from ._dxf import DXF_UNITS, have_ezdxf, write_dxf_spline  # noqa: F401  (re-exported: io's names)

__all__ = ["InputError", "read_input", "looks_like_json", "read_points", "read_points_unit",
           "curve_to_dict",
           "curve_from_dict", "bspline_to_dict", "bspline_from_dict", "write_json", "read_json",
           "write_dxf_spline", "have_ezdxf", "DXF_UNITS"]

PathLike = Union[str, Path]


# a number written with a decimal comma (1,5 or -0,25e3): semicolon-, tab- or space-separated
# files, or quoted between commas, from spreadsheets and digitisers in many locales
_DECIMAL_COMMA = re.compile(r"[+-]?\d*,\d+(?:[eE][+-]?\d+)?")
# a whole number: what unquoted decimal commas between commas leave of each half
_INTEGER = re.compile(r"[+-]?\d+")
# a number with '.' grouping its thousands, a decimal comma after it or not: 1.250, -12.345.678,
# 1.234,567 (Excel's #.##0 in a decimal-comma locale, saved as ';' or tab separated text)
_GROUPED = re.compile(r"[+-]?[1-9]\d{0,2}(?:\.\d{3})+(?:,\d+)?")
# the form a decimal point can also give: one dot, 1 to 3 digits before it, 3 after
_GROUPED_OR_POINT = re.compile(r"[+-]?[1-9]\d{0,2}\.\d{3}")
# a number with ',' grouping its thousands, a decimal point after it or not: 1,250, 1,250.5,
# -12,345,678 (English #,##0 and #,##0.00: a spreadsheet's or a report's tab export)
_EN_GROUPED = re.compile(r"[+-]?[1-9]\d{0,2}(?:,\d{3})+(?:\.\d+)?")
# what only that grouping writes: a decimal point after the groups, or two groups
_EN_ONLY = re.compile(r"[+-]?[1-9]\d{0,2}(?:(?:,\d{3})+\.\d+|(?:,\d{3}){2,}(?:\.\d+)?)")


def _uncommented(line: str) -> str:
    """The line without its '#' comment: from a '#' at the line's start or after a space,
    tab, ',' or ';' (a field's start; 'point#' in a header stays), outside a quoted field
    ("#3" in quotes is a field), to the end. A comment after the numbers
    ('12.3 4.5  # station 3') was refused as "not a number: '#'" (QA20 F6), and its
    commas or semicolons counted in the choice of separator; a whole-line comment leaves
    an empty line, skipped as before."""
    if "#" not in line:
        return line
    quoted = False
    for i, ch in enumerate(line):
        if ch == '"':
            quoted = not quoted     # csv's "" inside a quoted field toggles twice
        elif ch == "#" and not quoted and (i == 0 or line[i - 1] in " \t,;"):
            return line[:i].rstrip()
    return line


def _split_fields(lines, delim: Optional[str], name: str) -> list:
    """Each record's (line number, fields), numbered from 1: by csv's rules at delim (a
    quoted field holding a line end spans lines, counted as csv's line_num counts them:
    the record is numbered by its first line), else each line's at whitespace. csv's own
    errors (a field past its size limit: no point file's) as InputError naming the line."""
    if not delim:
        return [(k, line.split()) for k, line in enumerate(lines, start=1)]
    reader = csv.reader(lines, delimiter=delim, skipinitialspace=delim == " ")
    out, read = [], 0
    try:
        for fields in reader:
            out.append((read + 1, fields))
            read = reader.line_num
    except csv.Error as exc:
        raise InputError(f"{name}: line {reader.line_num}: {exc}") from None
    return out


# A line ends where a text editor ends it: at \n, \r\n or \r alone (str.splitlines also ends
# one at \f, \v, \x1c-\x1e, \x85, U+2028 and U+2029, so every line after such a character
# was named one too far on: "line 19 of scan.csv" for an editor's line 18)
_LINE_END = re.compile(r"\r\n|\r|\n")


def _text_lines(text: str) -> list:
    """``text``'s lines as an editor numbers them (_LINE_END), without their ends; a last
    line end opens no line (as str.splitlines)."""
    lines = _LINE_END.split(text)
    return lines[:-1] if lines and lines[-1] == "" else lines


def _parse_text(text: str, name: str, thousands: Optional[str] = None,
                line_numbers: Optional[list] = None) -> tuple:
    """Rows of numbers separated by semicolons, tabs or spaces (with decimal commas or
    points), or commas (decimal commas quoted, as spreadsheets write them: "1,5","0,25").
    Blank lines and lines starting with '#' are skipped, and a '#' comment after a row's
    numbers ('12.3 4.5  # station 3': _uncommented); so are the lines before the first
    row that holds a number when none of their fields is a number (a title, then a header
    such as ``x,y,z``: any number of them; a line with a number is never skipped), the last
    of which is the header. Rows of more than 3 columns (a
    scanner's point ids, normals, intensities; a survey's point names) are read
    when the header names the coordinate columns ``x``, ``y`` and optionally ``z`` (units in
    brackets allowed); a header that names them picks them by name in any case ("id,x,y",
    "y,x", "name,x,y,z"), the other columns need not be numbers. Thousands grouped by '.'
    (:func:`_thousands`) are read as such in ';' and tab separated files that show it.
    Returns the points and the unit the header names them in (None: _columns.header_unit);
    ``line_numbers``: a list each point's line in the text (from 1) is appended to, or None."""
    rows = []       # (line number, fields)
    header = None
    lines = [_uncommented(ln) for ln in _text_lines(text)]     # (a line number per line)
    data_lines = [ln for ln in lines if ln.strip()]
    sample = "\n".join(data_lines[:20])
    delim = None
    if ";" in sample:
        delim = ";"
    elif "," in sample and _decimal_commas_between(data_lines[:20], "\t"):
        delim = "\t"
    elif "," in sample and not _decimal_commas_between(data_lines[:20], None):
        delim = ","
    elif '"' in sample and "\t" in sample:
        delim = "\t"       # quoted fields between tabs ("1.5"<TAB>"2.5"): csv's quoting
    elif '"' in sample and all(ln.count('"') % 2 == 0 for ln in data_lines[:20]):
        delim = " "        # and between spaces (pandas' sep=' ', QUOTE_ALL; csv's
        #                    skipinitialspace reads a run of spaces as one separator)
    # csv's quoting rules: a quoted field keeps its commas ("102,697" from a spreadsheet
    # that writes decimal commas with ',' between the columns); lines end at any line end
    # (CR alone: classic Mac and some instruments' exports)
    split = []
    for lineno, fields in _split_fields(lines, delim, name):
        fields = [f for f in map(str.strip, fields) if f]
        if fields and not fields[0].startswith("#"):
            split.append((lineno, fields))
    tsep = "\t" if delim is None and "\t" in sample else delim
    # no field holds a comma (none in the text, or ',' separating unquoted fields) and no ';'
    # or tab separates them: neither ',' nor '.' grouping is the file's to decide
    # (_comma_thousands finds no 1,250, _thousands looks at ';' and tab files alone), so the
    # coordinate columns need not be picked out (a third of a 20 000-row read: QA23 F5)
    plain = thousands is None and tsep not in (";", "\t") and \
        ("," not in text or (delim == "," and '"' not in text))
    coords = _coordinate_fields(split) if thousands is None and not plain else split
    if _comma_thousands(coords, tsep, thousands, name):
        split = [(ln, [f.replace(",", "") if _EN_GROUPED.fullmatch(f) else f for f in fields])
                 for ln, fields in split]
        coords = _coordinate_fields(split) if thousands is None else split
    if _thousands(coords if tsep in (";", "\t") else split, tsep, thousands, name):
        split = [(ln, [f.replace(".", "").replace(",", ".") if _GROUPED.fullmatch(f) else f
                       for f in fields]) for ln, fields in split]
    skipped = None      # the number of the first line skipped as a title or header
    for lineno, fields in split:
        # a field holding a comma is a decimal comma whatever the separator (but where ','
        # groups thousands: _comma_thousands): a comma separator splits unquoted ones, and
        # the others have no comma between columns
        if thousands != "," and any("," in f for f in fields):
            fields = [f.replace(",", ".") if _DECIMAL_COMMA.fullmatch(f) else f for f in fields]
        if not rows and not any(_is_number(f) for f in fields) and \
                not all(_is_number(w) for f in fields for w in f.split()):   # '1.5 2.5' at ','
            header = fields            # a title or header line: the last one names columns
            skipped = skipped or lineno
            continue
        rows.append((lineno, fields))
    if not rows:
        why = ""
        if skipped:
            shown = lines[skipped - 1].strip()
            why = (f" (line {skipped}, {shown[:40] + '...' * (len(shown) > 40)!r}, and every "
                   "line after it skipped as a title or header: no field read as a number)")
        raise InputError(f"{name}: no data rows{why}")
    # unquoted decimal commas between commas split each number in two (102,697,4,576)
    whole = delim == "," and all(_INTEGER.fullmatch(f) for _, r in rows for f in r)
    hint = ('; decimal commas? Between commas they must be quoted ("102,697","4,576"), '
            "or the columns separated by semicolons") if whole else ""
    counts = {}
    for _, f in rows:
        counts[len(f)] = counts.get(len(f), 0) + 1
    width = max(counts, key=counts.get)     # most rows' number of columns
    if len(counts) != 1:
        lineno, f = next((ln, f) for ln, f in rows if len(f) != width)
        # '1.5 2.5' among '1.5,2.5' rows: the separator, not an empty cell (QA17 P2)
        spaced = [ln for ln, f in rows if len(f) == 1 and len(f[0].split()) > 1
                  and all(map(_is_number, f[0].split()))]
        if delim not in (None, " ") and spaced:
            sep = {"\t": "tabs"}.get(delim, f"'{delim}'")
            raise InputError(f"{name}: line {spaced[0]}: mixed separators: {len(spaced)} of "
                             f"{len(rows)} rows separate their columns by spaces, the others "
                             f"by {sep}; use one separator throughout")
        raise InputError(f"{name}: line {lineno}: {len(f)} column{'s' * (len(f) != 1)} where "
                         f"{counts[width]} of {len(rows)} rows have {width} (an empty cell?)"
                         f"{hint}")
    # by the header's names, as the binding's tables are; else by position
    header = header if header is None or delim is not None else unit_words_joined(header, width)
    named = axis_columns(header) if header is not None and len(header) == width else None
    cols = named if named is not None else list(range(width))
    if named is None:
        _refuse_row_numbers(rows, width, delim, name,       # (a title line is no header)
                            header if header is not None and len(header) == width else None)
    out = _convert(rows, cols, named is not None, name)
    if line_numbers is not None:
        line_numbers.extend(ln for ln, _ in rows)
    if named is None and width > 3:
        raise InputError(f"{name}: {width} columns: name the coordinates x, y (and z) "
                         f"in a header line to read them from more columns, or give 2 or 3{hint}")
    try:
        return out, header_unit([header[i] for i in named], name) if named else None
    except ValueError as exc:
        raise InputError(str(exc)) from None


def _convert(rows, cols, named: bool, name: str) -> np.ndarray:
    """The (len(rows), len(cols)) array of ``rows``' fields in columns ``cols`` ((line,
    fields) rows), every one a finite number: all rows at once, the same float() of the
    same strings as :func:`_convert_plain`, which reads them again row by row, for its
    message, wherever a field is no number or not finite (QA23 F5: 20 000 rows took
    250 ms, one np.all per row; np.loadtxt's way is not used: it parses numbers its own
    way, and the fields are split already)."""
    try:
        flat = [float(fields[c]) for _, fields in rows for c in cols]
    except ValueError:
        return _convert_plain(rows, cols, named, name)
    out = np.array(flat, dtype=np.float64).reshape(len(rows), len(cols))
    if not np.isfinite(out).all():
        return _convert_plain(rows, cols, named, name)
    return out


def _convert_plain(rows, cols, named: bool, name: str) -> np.ndarray:
    """:func:`_convert` row by row: InputError naming the first row's line with a field
    that is no number (the field), or else not finite."""
    out = np.empty((len(rows), len(cols)))
    for r, (lineno, fields) in enumerate(rows):
        bad = [c for c in cols if not _is_number(fields[c])]
        if bad:
            # the field itself: the fields joined again by commas showed a quoted field's
            # commas as separators ('102,697,4,576' for "102,697","4,576": QA)
            label = "" if named or any(_is_number(f[bad[0]]) for _, f in rows) \
                else (f" (column {bad[0] + 1} holds no number: names? a header line naming "
                      "the coordinate columns x, y (z) reads them)")
            raise InputError(f"{name}: line {lineno}: not a number: {fields[bad[0]]!r}{label}")
        out[r] = [float(fields[c]) for c in cols]
        if not np.all(np.isfinite(out[r])):
            raise InputError(f"{name}: line {lineno}: not finite: "
                             f"{fields[cols[int(np.argmax(~np.isfinite(out[r])))]]!r}")
    return out


def _refuse_row_numbers(rows, width: int, delim: Optional[str], name: str,
                        header=None) -> None:
    """InputError for 3 columns without a header whose first holds the rows' numbers, 0, 1,
    2, ... or 1, 2, 3, ... written as integers (QA21 F8: pandas' to_csv(header=False), a
    spreadsheet's row numbers; read as 3D points, a plane fit through (i, x, y) gave another
    curve, saying nothing). It may also be a 3D scan's x at unit stations: which one a file
    holds is the user's to say, in a header line, as for 4 columns or more; a constant third
    column is z (read: see below). A header line
    that names no x, y ('Nr,East,North') is there: the words ask to rename its columns."""
    if width != 3 or len(rows) < 3 or not _INTEGER.fullmatch(rows[0][1][0]):
        return
    start = int(rows[0][1][0])
    if start not in (0, 1) or any(not _INTEGER.fullmatch(f[0]) or int(f[0]) != start + i
                                  for i, (_, f) in enumerate(rows)):
        return
    # a constant third column is z (a plane curve: 'x y z' lines with z = 0, as FreeCAD's
    # Points export and .xyz files write them, of points at x = 0, 1, 2, ...): read as before;
    # as (row, x, y) its points would be a straight line at y = that constant
    third = [f[2] for _, f in rows]
    if all(_is_number(f) for f in third) and len({float(f) for f in third}) == 1:
        return
    if not any(map(_is_number, third)):     # names, not y: _convert_plain says so (QA qapy F12)
        return
    sep = {None: " ", "\t": "<TAB>"}.get(delim, delim)
    where = "in a header line above the rows" if header is None else \
        f"by the names of its header line ({(delim or ' ').join(header)!r} names no x, y)"
    raise InputError(
        f"{name}: column 1 holds {start}, {start + 1}, ... {start + len(rows) - 1}, one per row "
        f"(the rows' numbers?): read as x it makes 3D points; say which {where}: "
        f"'id{sep}x{sep}y' reads columns 2, 3 as x, y, 'x{sep}y{sep}z' all three")


def _coordinate_fields(split) -> list:
    """The fields of ``split``'s data rows ((line, fields) rows) in the columns that become
    coordinates, as :func:`_parse_text` picks them: the rows from the first holding a number
    (a decimal comma or '.'-grouped field counts: 1,5, 1.250,5, 1.234.567), the columns the
    header above names x, y (z), else all of them. An id, a date, a count beside the
    coordinates then neither blocks nor flips :func:`_thousands`' decision."""
    def numeric(f):
        return _is_number(f) or bool(_DECIMAL_COMMA.fullmatch(f) or _GROUPED.fullmatch(f)
                                     or _EN_GROUPED.fullmatch(f))
    header, rows = None, []
    for lineno, fields in split:
        if not rows and not any(map(numeric, fields)) and \
                not all(_is_number(w) for f in fields for w in f.split()):
            header = fields
            continue
        rows.append((lineno, fields))
    if not rows:
        return split
    counts = {}
    for _, f in rows:
        counts[len(f)] = counts.get(len(f), 0) + 1
    width = max(counts, key=counts.get)
    cols = axis_columns(header) if header is not None and len(header) == width else None
    if cols is None:
        return rows
    return [(ln, [f[c] for c in cols if c < len(f)]) for ln, f in rows]


def _thousands(split, delim, thousands: Optional[str], name: str) -> bool:
    """Whether '.' groups thousands in the fields of ``split`` ((line, fields) rows: the
    coordinate columns' alone, :func:`_coordinate_fields`).
    ``thousands``: '.' yes, '' no, None: what the file shows, in ';' and tab separated
    files (the decimal-comma locales' separators) holding a field of the grouped form
    (_GROUPED): no when some field is a number the grouping cannot write with a decimal
    point (0.125, 1.5, -0.250, 1234.5, 1e3); else yes when some field has a decimal comma
    or two dots (1.234.567: only grouping writes them, whatever an id column beside holds);
    else no when some field is an integer 1000 or more without a dot; yes when a column
    holds both plain integers and 1.250's that grouping reads nearer each other (980 above
    1.000: Excel's #.##0; not 0, 12.125, 25: _grouped_nearer). Else the file
    does not decide: InputError naming the first such field's line."""
    if thousands is not None:
        if thousands not in (".", ",", ""):
            raise InputError(f"thousands: '.', ',' or '' (none), got {thousands!r}")
        return thousands == "."
    if delim not in (";", "\t"):
        return False
    first = next(((ln, f) for ln, r in split for f in r if _GROUPED.fullmatch(f)), None)
    if first is None:
        return False
    plain_cols, dotted_cols, shows, big = set(), set(), False, False
    for _, r in split:
        for c, f in enumerate(r):
            if _INTEGER.fullmatch(f):
                big = big or abs(int(f)) >= 1000    # #.##0 would write 1.000
                plain_cols.add(c)
            elif _GROUPED_OR_POINT.fullmatch(f):
                dotted_cols.add(c)
            elif _GROUPED.fullmatch(f) or _DECIMAL_COMMA.fullmatch(f):
                shows = True                        # 1.234.567, 1.250,0, 1,5
            elif _is_number(f):
                return False                        # a decimal point: 0.125, 1.5, 1e3
    if shows:
        return True
    if big:
        return False
    if any(_grouped_nearer(split, c, ".") for c in plain_cols & dotted_cols):
        return True
    # Undecided: every coordinate is written d.ddd .. ddd.ddd, as both a fixed 3-decimal
    # export (a scanner's or CMM's %.3f) and a decimal-comma locale's #.##0 (Excel,
    # LibreOffice) write them, and none is a value only one of the two writes: a 0.250, a
    # 1.5 or 1.2500, a 1234.5 or plain 1250 (decimal point); a 1.250,5, a 1.234.567 or a 980
    # above a 1.000 (grouping). A minus sign decides nothing: #.##0 writes -1250 '-1.250'.
    # The two readings differ by 1000 exactly, so the user says which (readfix).
    ln, f = first
    point, grouped = float(f), int(f.replace('.', ''))
    raise InputError(
        f"{name}: line {ln}: {f!r} is {point!r} or {grouped}: every coordinate is written "
        "with 3 digits after one '.', as a 3-decimal export and a '.'-grouped #.##0 both "
        "write them, and none shows which (no 0.5, 1.25 or 1250; no 1.250,5 or 980); say "
        f"which (command line: --thousands none reads {point!r}, --thousands . reads "
        f"{grouped}; read_points(thousands='') or thousands='.')")


def _comma_thousands(split, delim, thousands: Optional[str], name: str) -> bool:
    """Whether ',' groups thousands (English #,##0: 1,250.5 is 1250.5) in the fields of
    ``split`` ((line, fields) rows: the coordinate columns' alone, :func:`_coordinate_fields`).
    ``thousands``: ',' yes, '.' or '' no (a comma is then a decimal comma), None: what the
    whole file shows, where some field has the grouped form (_EN_GROUPED): no when some field
    has a comma the grouping cannot write (1,5, 0,25, 1,2500, 1.250,5; InputError where
    another field is one only the grouping writes: 1,250.5 beside 1,5); else yes when some
    field has a decimal point after its groups or two groups (1,250.5, 1,234,567: only the
    grouping writes them), or some number has a decimal point that '.' grouping cannot write
    (0.5, 1234.5: the file's decimal separator is '.'), or a column holds both plain integers
    and 1,250's that grouping reads nearer each other (980 above 1,000: _grouped_nearer);
    no when some integer 1000 or more has no comma. Else every comma is written d,ddd ..
    ddd,ddd, as both English thousands and a decimal comma with 3 decimals write them
    (QA: a tab export's 1,250 read as 1.25, silently): refused naming the line, the two
    readings differing by 1000, whether tabs, spaces (Excel's space delimited .prn writes
    #,##0 as shown) or ',' (quoted: "1,250","2,000" is an English CSV's #,##0 as much as a
    German one's 3 decimals) separate the columns. ';' separated files (the decimal-comma
    locales' own) read grouped only where a 1,250.5 or 1,234,567 shows it."""
    if thousands is not None:
        return thousands == ","
    first = next(((ln, f) for ln, r in split for f in r
                  if "," in f and _EN_GROUPED.fullmatch(f)), None)
    if first is None:
        return False
    plain_cols, grouped_cols, only, point, big, comma = set(), set(), None, False, False, None
    for ln, r in split:
        for c, f in enumerate(r):
            if _EN_ONLY.fullmatch(f):
                only = only or (ln, f)              # 1,250.5, 1,234,567
            elif _EN_GROUPED.fullmatch(f):
                grouped_cols.add(c)                 # 1,250
            elif "," in f and (_DECIMAL_COMMA.fullmatch(f) or _GROUPED.fullmatch(f)):
                comma = comma or (ln, f)            # 1,5, 0,25, 1.250,5
            elif _INTEGER.fullmatch(f):
                big = big or abs(int(f)) >= 1000    # #,##0 would write 1,000
                plain_cols.add(c)
            elif _is_number(f) and "." in f and not _GROUPED.fullmatch(f):
                point = True                        # a decimal point: 0.5, 1234.5
    if comma and only:
        raise InputError(
            f"{name}: line {only[0]}: not a number: {only[1]!r}: ',' groups its thousands "
            f"(English #,##0.00) where line {comma[0]}'s {comma[1]!r} is a decimal comma, "
            "which decides the file's commas; one file writes its numbers one way")
    if comma:
        return False
    if only:
        return True
    if delim == ";":                    # decimal commas but there
        return False
    if point:
        return True
    if big:
        return False
    if any(_grouped_nearer(split, c) for c in plain_cols & grouped_cols):
        return True
    ln, f = first
    comma, grouped = float(f.replace(",", ".")), int(f.replace(",", ""))
    raise InputError(
        f"{name}: line {ln}: {f!r} is {comma!r} or {grouped}: every number with a comma has "
        "3 digits after one ',', as a decimal comma with 3 decimals and English thousands "
        "(#,##0) both write them, and none shows which (no 1,5 or 1250; no 1,250.5, 0.5 or "
        f"980); say which (command line: --thousands none reads {comma!r}, --thousands , "
        f"reads {grouped}; read_points(thousands='') or thousands=',')")


def _grouped_nearer(split, c: int, sep: str = ",") -> bool:
    """Whether column ``c``'s integers and d<sep>ddd's (980 and 1,000; 980 and 1.000) are
    nearer each other, row after row, read with ``sep`` grouping thousands (980, 1000,
    1020) than with it the decimal separator. Both a #,##0 / #.##0 column crossing 1000 and
    a general format (whole values beside 3 decimals, trailing zeros dropped: 0, 12,125,
    25 or 0, 12.125, 25) write such a column; a curve's consecutive points are near, so the
    reading that keeps them so is the file's (reviewer: 0, 12,125, 25 was read 0, 12125,
    25, silently)."""
    form = _EN_GROUPED if sep == "," else _GROUPED_OR_POINT
    col = [r[c] for _, r in split
           if c < len(r) and (_INTEGER.fullmatch(r[c]) or form.fullmatch(r[c]))]
    grouped = np.array([float(f.replace(sep, "")) for f in col])
    decimal = np.array([float(f.replace(sep, ".")) for f in col])
    return float(np.abs(np.diff(grouped)).sum()) < float(np.abs(np.diff(decimal)).sum())


def _decimal_commas_between(lines, sep) -> bool:
    """Whether lines holding commas are numbers with decimal commas separated by ``sep``
    (tabs, or None: any whitespace; an export as '1,5<TAB>0,25' or '1,5 0,25': QA, refused
    as 'not a number'): every line but a header splits at ``sep`` into numbers, some
    written with a decimal comma. Or (readfix) beside a column of text, as a German Excel's
    or LibreOffice's tab export writes a point name or a date ('P1<TAB>12,5<TAB>3,25',
    '17.05.2024<TAB>12,5<TAB>3,25', split at the commas before): every line splits into as
    many fields, at least two columns hold a number in every line, some with a decimal
    comma, and the others a number in none (a label, whatever its commas)."""
    def numeric(f):
        return bool(_is_number(f) or commas(f) or _GROUPED.fullmatch(f))

    def commas(f):      # 1,5; 1,250.5 (English thousands); 1.250,5 ('.' thousands)
        return bool(_DECIMAL_COMMA.fullmatch(f) or _EN_GROUPED.fullmatch(f)
                    or ("," in f and _GROUPED.fullmatch(f)))
    # (fields quoted between tabs or spaces: "1,5"<TAB>"2,5", "1,5" "2,5")
    rows = [[f.strip().strip('"') for f in ln.split(sep) if f.strip()] for ln in lines]
    while rows and not any(map(numeric, rows[0])):
        rows = rows[1:]                                   # a title, a header
    if not rows or any(len(r) < 2 for r in rows):
        return False
    if all(numeric(f) for r in rows for f in r):
        return any(commas(f) for r in rows for f in r)
    if len({len(r) for r in rows}) != 1:
        return False
    cols = list(zip(*rows))
    nums = [c for c in cols if all(map(numeric, c))]
    return len(nums) >= 2 and all(not any(map(numeric, c)) for c in cols if c not in nums) \
        and any(commas(f) for c in nums for f in c)


def _is_number(s: str) -> bool:
    try:
        float(s)
        return True
    except ValueError:
        return False


def _decode(data: bytes, name: str) -> str:
    """UTF-16 when the file starts with its byte-order mark (Excel's "Unicode text"), else
    UTF-8 (a BOM dropped), else Windows-1252: what Excel writes on Western European Windows
    ("x (Länge)" from a German export), latin-1 with a few more characters; every byte
    but 0x81, 0x8D, 0x8F, 0x90 and 0x9D is one. None of them: InputError naming the line of
    the first byte that is not text."""
    if data[:2] in (b"\xff\xfe", b"\xfe\xff"):
        try:
            return data.decode("utf-16")
        except UnicodeDecodeError:
            raise InputError(f"{name}: starts as UTF-16 but is not UTF-16 text") from None
    try:
        return data.decode("utf-8-sig")
    except UnicodeDecodeError:
        pass
    try:
        return data.decode("cp1252")
    except UnicodeDecodeError as exc:
        line = data.count(b"\n", 0, exc.start) + 1
        raise InputError(f"{name}: line {line}: byte 0x{data[exc.start]:02X} is neither UTF-8 "
                         "nor Windows-1252 text (save the file as UTF-8 CSV)") from None


_NPY_MAGIC = b"\x93NUMPY"


def read_input(path: PathLike) -> bytes:
    """The bytes of an input: '-' is standard input (read once); a pipe or device
    (/dev/stdin, a shell's <(...)) is read as a file is. InputError when missing or
    unreadable. For :func:`read_points` or :func:`read_json` to parse (``data=``) after
    :func:`looks_like_json` chose."""
    import sys
    if str(path) == "-":
        return sys.stdin.buffer.read()
    p = Path(path)
    if not p.exists():
        raise InputError(f"{path}: no such file")
    if p.is_dir():
        raise InputError(f"{path}: is a directory; give a file")
    try:
        return p.read_bytes()
    except OSError as exc:
        raise InputError(f"{path}: cannot read ({exc.strerror or exc.__class__.__name__})") \
            from None


def looks_like_json(data: bytes) -> bool:
    """Whether an input's bytes are JSON (an object or array) rather than points: their
    first non-blank byte (after a UTF-8 BOM) is '{' or '[', which no points file starts with."""
    head = data[3:] if data.startswith(b"\xef\xbb\xbf") else data
    head = head.lstrip()
    return head[:1] in (b"{", b"[")


def read_points(path: PathLike, min_points: int = 3, data: Optional[bytes] = None,
                thousands: Optional[str] = None) -> np.ndarray:
    """Read an (n, 2) or (n, 3) float64 array of points from ``path`` (and the unit its
    header names: :func:`read_points_unit`).

    Formats: ``.npy`` (a numeric array of shape (n, 2) or (n, 3)), otherwise text
    with comma (decimal commas quoted), semicolon, tab or whitespace (decimal commas
    allowed with these three) separated columns,
    ``#`` comments and optional title and header lines above the data (lines without a
    number; the last can pick the columns ``x``, ``y``, ``z`` out of more), UTF-8 or else
    Windows-1252 (:func:`_decode`). Every message about a row names its line.
    Raises :class:`InputError` for a missing or unreadable file, malformed rows, a
    column count other than 2 or 3 without such a header, NaN/inf values, fewer than
    ``min_points`` points, or all points equal. ``data``: the input's bytes read already
    (:func:`read_input`), ``path`` then naming it.

    Thousands: ';' and tab separated files from decimal-comma locales may group thousands
    by '.' (Excel's ``#.##0``: ``980;1.250`` is 980, 1250). Such a file is read grouped
    where it shows it (a decimal comma ``1.250,5``, a ``1.234.567``, or a column holding
    both ``980`` and ``1.000``); it is read with decimal points where a field shows that
    (``0.125``, ``1.5``, ``1234``); one that does not decide (every number ``d.ddd``) is
    refused naming the line. Only the columns read as coordinates decide (an id, a date
    or a count beside them, ``1.001`` or ``20240517``, does not). ``thousands='.'`` reads
    dots as grouping, ``thousands=''`` as decimal points, whatever the file.

    Tab or space separated files (and quoted fields) may group thousands by ',' (English
    ``#,##0``: ``1,250.5`` is 1250.5), read so where the file shows it (a ``1,250.5``, a
    ``1,234,567``, a ``0.5`` beside a ``1,250``, a column holding both ``980`` and
    ``1,000``); a comma the grouping cannot write (``1,5``) or a ``1250`` without one
    reads decimal commas; a file whose every comma is ``d,ddd`` is refused naming the
    line, between tabs, spaces or (quoted) commas (';': only a ``1,250.5`` or
    ``1,234,567`` reads grouped). ``thousands=','`` reads commas as grouping, whatever the
    file (and ``'.'`` or ``''`` a comma as a decimal comma). Fields may be quoted between
    commas, tabs or spaces (``"1.5" "2.5"``).
    """
    return read_points_unit(path, min_points, data, thousands)[0]


def read_points_unit(path: PathLike, min_points: int = 3, data: Optional[bytes] = None,
                     thousands: Optional[str] = None, lines: Optional[list] = None) -> tuple:
    """(points, unit): :func:`read_points`' points of ``path`` (``min_points``, ``data``,
    ``thousands`` as there) and the unit the header line names the coordinate columns in
    ('mm' for ``x [mm],y [mm]``; DXF_UNITS' spelling where it is one of those: 'um' for
    'µm'), None where it names none (and for .npy). Columns naming two units
    (``x [mm],y [m]``) raise :class:`InputError` naming both. ``lines``: a list each
    point's line in the file (from 1: where an editor shows it; for .npy its row, from 1)
    is appended to, or None (the FreeCAD Fit names a file's point by its line)."""
    name = "standard input" if str(path) == "-" else str(path)
    data = read_input(path) if data is None else data
    if data.startswith(_NPY_MAGIC) or (str(path) != "-" and Path(path).suffix.lower() == ".npy"):
        try:
            arr = np.load(_io.BytesIO(data), allow_pickle=False)
        except Exception as exc:   # numpy raises several types for corrupt files
            raise InputError(f"{name}: not a readable .npy file ({exc})") from None
        if not np.issubdtype(arr.dtype, np.number):
            raise InputError(f"{name}: .npy array is not numeric (dtype {arr.dtype})")
        arr, unit = np.asarray(arr, dtype=np.float64), None
        if lines is not None and arr.ndim == 2:
            lines.extend(range(1, arr.shape[0] + 1))
    else:
        said = not_a_table(data, name)     # a JSON, DXF or SVG given as points (revD)
        if said:
            raise InputError(said)
        arr, unit = _parse_text(_decode(data, name), name, thousands, lines)
    if arr.ndim != 2 or arr.shape[1] not in (2, 3):
        raise InputError(f"{name}: need 2 or 3 columns (x,y or x,y,z), got shape {arr.shape}")
    if not np.all(np.isfinite(arr)):
        bad = int(np.argwhere(~np.isfinite(arr))[0][0])
        raise InputError(f"{name}: point {bad} is not finite (NaN or inf)")
    if arr.shape[0] < min_points:
        raise InputError(f"{name}: need at least {min_points} points, got {arr.shape[0]}")
    if np.all(arr == arr[0]):
        raise InputError(f"{name}: all points are equal")
    return np.ascontiguousarray(arr), unit


# ---------------------------------------------------------------- JSON

def _floats(a) -> list:
    return np.asarray(a, dtype=np.float64).tolist()


def curve_to_dict(curve) -> Dict[str, Any]:
    """A JSON-ready dict of a SmoothElastica or DiscreteElastica (its type and parameters),
    or of a Hermite chain ({"type": "chain", "pieces": [smooth dicts]})."""
    from .core import DISCRETE_PARAMS, SMOOTH_PARAMS, DiscreteElastica, SmoothElastica
    from .hermite import HermiteChain
    if isinstance(curve, SmoothElastica):
        return {"type": "smooth", **{n: float(getattr(curve, n)) for n in SMOOTH_PARAMS}}
    if isinstance(curve, DiscreteElastica):
        return {"type": "discrete", **{n: float(getattr(curve, n)) for n in DISCRETE_PARAMS},
                "n": int(curve.n)}
    if isinstance(curve, HermiteChain):
        return {"type": "chain", "pieces": [curve_to_dict(p) for p in curve.pieces]}
    raise TypeError(f"not an elastica: {type(curve).__name__}")


def curve_from_dict(d: Dict[str, Any], name: str = "curve"):
    """Rebuild a SmoothElastica / DiscreteElastica / HermiteChain from :func:`curve_to_dict`'s dict
    (or a fit JSON holding one under ``"curve"``). Raises InputError when it is not one."""
    from .core import DISCRETE_PARAMS, SMOOTH_PARAMS, DiscreteElastica, SmoothElastica
    if isinstance(d, dict) and "curve" in d and isinstance(d["curve"], dict):
        d = d["curve"]
    if isinstance(d, dict) and d.get("type") == "chain":
        from .hermite import HermiteChain
        pieces = d.get("pieces")
        if not isinstance(pieces, list) or not pieces or \
                any(not isinstance(p, dict) or p.get("type") != "smooth" for p in pieces):
            raise InputError(f"{name}: a chain needs a list of smooth pieces")
        return HermiteChain([curve_from_dict(p, f"{name} piece {i}") for i, p in enumerate(pieces)])
    if not isinstance(d, dict) or d.get("type") not in ("smooth", "discrete"):
        raise InputError(f"{name}: no elastica curve (a 'type' of 'smooth', 'discrete' or 'chain')")
    names = SMOOTH_PARAMS if d["type"] == "smooth" else DISCRETE_PARAMS + ("n",)
    missing = [n for n in names if n not in d]
    if missing:
        raise InputError(f"{name}: {d['type']} curve lacks {', '.join(missing)}")
    try:
        kw = {n: float(d[n]) for n in names}
        if d["type"] == "smooth":
            return SmoothElastica(**kw)
        kw["n"] = int(kw["n"])
        return DiscreteElastica(**kw)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}: invalid {d['type']} curve: {exc}") from None


def bspline_to_dict(b) -> Dict[str, Any]:
    """A JSON-ready dict of a BSpline (degree, poles, knots, mults, max_deviation)."""
    return b.to_dict()


def bspline_from_dict(d: Dict[str, Any], name: str = "bspline"):
    """The BSpline of :func:`bspline_to_dict`'s dict (or a dict holding one under
    'bspline'); InputError when it is not one."""
    from .bspline import BSpline
    if isinstance(d, dict) and isinstance(d.get("bspline"), dict):
        d = d["bspline"]
    try:
        return BSpline.from_dict(d)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name}: not a B-spline ({exc})") from None


def _clean(obj):
    """Replace NaN/inf (not JSON) by None, numpy scalars/arrays by Python ones."""
    if isinstance(obj, dict):
        return {str(k): _clean(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_clean(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return _clean(obj.tolist())
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        v = float(obj)
        return v if math.isfinite(v) else None
    return obj


def write_json(obj: Any, path: PathLike) -> None:
    """Write ``obj`` as indented JSON to ``path`` ('-' = standard output)."""
    text = json.dumps(_clean(obj), indent=2) + "\n"
    if str(path) == "-":
        import sys
        sys.stdout.write(text)
    else:
        Path(path).write_text(text)


def read_json(path: PathLike, data: Optional[bytes] = None) -> Any:
    """Read a JSON file ('-': standard input; ``data``: its bytes read already, by
    :func:`read_input`); InputError when missing or malformed."""
    data = read_input(path) if data is None else data
    if str(path) == "-":
        path = "standard input"
    try:
        return json.loads(data.decode("utf-8-sig"))
    except (ValueError, UnicodeDecodeError) as exc:
        raise InputError(f"{path}: not valid JSON ({exc})") from None
