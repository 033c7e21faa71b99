"""Point files as spreadsheets and instruments export them (readfix; files as
/tmp/readfix/gen_files.py writes them): a tab export with decimal commas beside a text column
(a point's name, a date) was split at its commas; a file whose every coordinate is written
d.ddd is refused saying which option reads which number; 3 columns without a header whose
first holds the rows' numbers are refused naming the header that says which (QA21 F8)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from cli_run import cli
from libelastica.io import InputError, read_points

PTS = np.array([(100 + 40 * math.cos(t / 10), 50 + 30 * math.sin(t / 10)) for t in range(25)])
WANT = np.round(PTS, 3)


def _dc(v, n=3):
    return f"{v:.{n}f}".replace(".", ",")


def _write(tmp_path, name, text, encoding="utf-8"):
    p = tmp_path / name
    p.write_bytes(text.encode(encoding))
    return p


def test_tab_export_with_decimal_commas_beside_a_text_column(tmp_path):
    """German Excel's 'Text (Tab-delimited)' (cp1252, CRLF) with a point-name column, and
    LibreOffice's tab CSV with a date column: read before as split at the commas ('not a
    number: 'P1\\t140''). Their every number is written d,ddd (3 decimals, 60 .. 140), as
    English thousands (#,##0) also write them: the user says which (thousands='', --thousands
    none: test_read_comma_thousands.py), between tabs and between spaces."""
    names = _write(tmp_path, "names.txt", "Punkt\tx (L\xe4nge)\ty (H\xf6he)\r\n" + "".join(
        f"P{i + 1}\t{_dc(x)}\t{_dc(y)}\r\n" for i, (x, y) in enumerate(PTS)), "cp1252")
    with pytest.raises(InputError, match=r"line 2: '140,000' is 140\.0 or 140000: .*"
                                         r"--thousands none reads 140\.0"):
        read_points(names)
    assert np.array_equal(read_points(names, thousands=""), WANT)
    dates = _write(tmp_path, "dates.csv", "Datum\tX\tY\tZ\n" + "".join(
        f"17.05.2024\t{_dc(x)}\t{_dc(y)}\t{_dc(1.5, 1)}\n" for x, y in PTS))
    assert np.array_equal(read_points(dates), np.c_[WANT, np.full(len(PTS), 1.5)])
    # the name last, and spaces between the columns
    last = _write(tmp_path, "last.txt", "x y Punkt\n" + "".join(
        f"{_dc(x)} {_dc(y)} P{i}\n" for i, (x, y) in enumerate(PTS)))
    with pytest.raises(InputError, match=r"line 2: '140,000' is 140\.0 or 140000"):
        read_points(last)
    assert np.array_equal(read_points(last, thousands=""), WANT)


def test_a_text_column_without_a_header_is_named(tmp_path):
    """Without a header the name column is refused as in a comma-separated file ("P0,1,2"),
    the message saying the column holds no number and what reads the file."""
    p = _write(tmp_path, "p.txt", "".join(f"P{i + 1}\t{_dc(x)}\t{_dc(y)}\n"
                                          for i, (x, y) in enumerate(PTS)))
    with pytest.raises(InputError, match=r"line 1: not a number: 'P1' \(column 1 holds no "
                                         r"number: names\? a header line naming the coordinate"):
        read_points(p, thousands="")
    _write(tmp_path, "p.txt", "name\tx\ty\n" + p.read_text())
    assert np.array_equal(read_points(p, thousands=""), WANT)


@pytest.mark.parametrize("shift, evidence", [
    ((-139.5, 0), "0.500"),          # a leading zero (x crosses 0: 0.500, -0.297)
    ((0, 0), "1.5"),                 # a value with 1 decimal
    ((0, 0), "1.2500"),              # 4 decimals
    ((0, 0), "1250.000"),            # > 999 without a group separator
])
def test_three_decimals_decided_by_a_field(tmp_path, shift, evidence):
    rows = [f"{x + shift[0]:.3f}\t{y + shift[1]:.3f}" for x, y in PTS] + [f"{evidence}\t1.000"]
    got = read_points(_write(tmp_path, "p.txt", "\n".join(rows) + "\n"))
    assert np.array_equal(got[:-1], np.round(PTS + shift, 3)) and got[-1, 0] == float(evidence)


def test_three_decimals_everywhere_says_which_option_reads_what(tmp_path, capsys):
    """A scanner's %.3f tab export of coordinates 1 .. 999 (and -1.787 .. -999: #.##0 writes
    -1250 as '-1.250', so a minus decides nothing): refused, the message naming what each
    option reads; read with --thousands none as the user says."""
    for shift in (0, -140):
        p = _write(tmp_path, "scan.txt", "".join(f"{x + shift:.3f}\t{y:.3f}\n" for x, y in PTS
                                                 if abs(x + shift) >= 1))
        first = p.read_text().split("\t")[0]
        with pytest.raises(InputError, match=(
                rf"line 1: '{first}' is {float(first)!r} or {int(first.replace('.', ''))}: "
                r"every coordinate is written with 3 digits after one '\.'.* --thousands none "
                rf"reads {float(first)!r}, --thousands \. reads {int(first.replace('.', ''))}; "
                r"read_points\(thousands=''\) or thousands='\.'\)")):
            read_points(p)
    code, _, err = cli(capsys, "fit", p, "--model", "smooth")
    assert code == 2 and "--thousands none reads -1.787" in err, err
    code, out, err = cli(capsys, "fit", p, "--model", "smooth", "--thousands", "none")
    assert code in (0, 1) and "(22 points)" in out, err


@pytest.mark.parametrize("start, fmt", [(0, "{:.17g}"), (1, "{:.4f}")])
def test_a_first_column_of_row_numbers_is_refused_naming_the_header(tmp_path, capsys, start,
                                                                    fmt):
    """QA21 F8: pandas' to_csv(header=False) (0, 1, 2, ...) and a spreadsheet's row numbers
    (1, 2, 3, ...) beside x, y were read as 3D points (a plane fit through (i, x, y)) without
    a word. Refused, naming the header line that reads either way; with it, read."""
    body = "".join(f"{i + start}," + fmt.format(x) + "," + fmt.format(y) + "\n"
                   for i, (x, y) in enumerate(PTS))
    p = _write(tmp_path, "p.csv", body)
    with pytest.raises(InputError, match=rf"p\.csv: column 1 holds {start}, {start + 1}, \.\.\. "
                                         rf"{start + 24}, one per row .*'id,x,y' reads columns "
                                         r"2, 3 as x, y, 'x,y,z' all three"):
        read_points(p)
    assert cli(capsys, "fit", p)[0] == 2
    _write(tmp_path, "p.csv", "id,x,y\n" + body)
    assert np.allclose(read_points(p), PTS, atol=5e-5)
    _write(tmp_path, "p.csv", "x,y,z\n" + body)
    assert read_points(p).shape == (25, 3)
    # not row numbers: 2 columns (y over a station), another start, a gap, a float index
    for text in ("".join(f"{i},{y}\n" for i, y in enumerate(PTS[:, 1])),
                 "".join(f"{i + 2},{x},{y}\n" for i, (x, y) in enumerate(PTS)),
                 "".join(f"{i + (i > 5)},{x},{y}\n" for i, (x, y) in enumerate(PTS)),
                 "".join(f"{i}.0,{x},{y}\n" for i, (x, y) in enumerate(PTS))):
        assert read_points(_write(tmp_path, "q.csv", text)).shape[0] == 25


@pytest.mark.parametrize("head, sep", [("Nr,East,North", ","), ("Punkt;Rechtswert;Hochwert", ";")])
def test_row_numbers_under_a_header_naming_no_axes_ask_to_rename_it(tmp_path, head, sep):
    """A surveyor's export with a header line whose names are not x, y ('Nr,East,North') and
    the rows' numbers in column 1 is refused as row numbers are; the words must not ask for
    a header line above the rows (the file has one) but name it and ask to rename its
    columns. A title line above headerless rows (no header: another width) still asks for
    one."""
    body = "".join(f"{i + 1}{sep}{x:.4f}{sep}{y:.4f}\n" for i, (x, y) in enumerate(PTS))
    p = _write(tmp_path, "h.csv", head + "\n" + body)
    with pytest.raises(InputError) as exc:
        read_points(p)
    msg = str(exc.value)
    assert "above the rows" not in msg and repr(head) in msg and "names no x, y" in msg, msg
    assert f"'id{sep}x{sep}y' reads columns 2, 3" in msg, msg
    p = _write(tmp_path, "t.csv", "My scan of 2024\n" + body)
    with pytest.raises(InputError, match="in a header line above the rows"):
        read_points(p)
    _write(tmp_path, "h.csv", f"id{sep}x{sep}y\n" + body)
    assert np.allclose(read_points(tmp_path / "h.csv"), PTS, atol=5e-5)


@pytest.mark.parametrize("sep", [" ", "\t", ","])
def test_x_y_z_lines_of_a_plane_curve_at_unit_x_are_read(tmp_path, sep):
    """'x y z' lines with z = 0 (FreeCAD's Points export, a .xyz file) of points sampled at
    x = 0, 1, 2, ... were read as before 9011bd6 and then refused as row numbers: a constant
    third column is z (as (row, x, y) they would be a straight line), so they are read, all
    three columns, bit for bit. Row numbers beside x, y that vary stay refused."""
    pts = np.array([(i, (i - 5) ** 2 / 10 + 0.125 * (i % 3), 0.0) for i in range(11)])
    text = "".join(sep.join(f"{v:g}" for v in p) + "\n" for p in pts)
    assert np.array_equal(read_points(_write(tmp_path, "c.xyz", text)), pts)
    moved = pts + (0, 0, 7.5)       # another plane z = 7.5
    text = "".join(sep.join(f"{v:g}" for v in p) + "\n" for p in moved)
    assert np.array_equal(read_points(_write(tmp_path, "d.xyz", text)), moved)
    varying = "".join(sep.join(f"{v:g}" for v in (i, x, y)) + "\n" for i, (x, y) in enumerate(PTS))
    with pytest.raises(InputError, match="one per row"):
        read_points(_write(tmp_path, "e.xyz", varying))


def test_a_json_dxf_or_svg_given_as_points_is_named_so(tmp_path, capsys):
    """A drawing or a JSON given where points go (review revD: a DXF said 'line 1118: 2 columns
    where 3717 of 3730 rows have 1 (an empty cell?)', a fit's JSON 'line 10: not a number:
    ']'', an SVG 'no data rows ...'): each is named for what it is, by read_points and the CLI."""
    docs = {"fit.json": '{\n  "model": "smooth",\n  "curve": {"x0": 0}\n}\n',
            "pts.json": "[[0, 0], [1, 1], [2, 4], [3, 9]]\n",
            "d.dxf": "  0\r\nSECTION\r\n  2\r\nHEADER\r\n  0\r\nENDSEC\r\n  0\r\nEOF\r\n",
            "p.svg": '\ufeff<?xml version="1.0"?>\n<svg xmlns="http://www.w3.org/2000/svg"/>\n'}
    for name, text in docs.items():
        path = _write(tmp_path, name, text)
        kind = {"json": "JSON", "dxf": "DXF", "svg": "SVG / XML"}[name.rsplit(".", 1)[1]]
        with pytest.raises(InputError, match=f"a {kind} document, not a table of points"):
            read_points(path)
        code, _, err = cli(capsys, "spline", path)
        assert code == 2 and f"a {kind} document, not a table of points" in err, err
    # a table that starts with a number, a header or a comment is still one
    for text in ("0,0\n1,1\n2,4\n", "x,y\n0,0\n1,1\n2,4\n", "# <points>\n0 0\n1 1\n2 4\n"):
        assert read_points(_write(tmp_path, "t.csv", text)).shape == (3, 2)
