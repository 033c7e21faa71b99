"""Point files whose thousands are grouped by '.' (Excel's #.##0 in a decimal-comma locale,
saved as ';' or tab separated text): read grouped where the file shows it, read with decimal
points where a field shows that, refused naming the line where nothing decides (QA19 W1, P2)."""
from __future__ import annotations

import numpy as np
import pytest

from libelastica.cli import main
from libelastica.io import InputError, read_points


def _read(tmp_path, text, **kw):
    p = tmp_path / "p.csv"
    p.write_text(text)
    return read_points(p, min_points=1, **kw)


@pytest.mark.parametrize("text, want", [
    # a column crossing 1000 (QA19 c6: read 1.000 as 1.0, rms 10.34 for 0.53)
    ("x;y\n980;1.250\n990;1.262\n1.000;1.270\n1.010;1.281\n",
     [[980, 1250], [990, 1262], [1000, 1270], [1010, 1281]]),
    ("x\ty\n980\t1.250\n1.000\t1.270\n", [[980, 1250], [1000, 1270]]),
    # decimal commas after the groups (QA19 P2: 'not a number: 1.250,0'; all rows: 'no data rows')
    ("x;y\n980,5;1.250,0\n1.000,5;1.270,5\n", [[980.5, 1250], [1000.5, 1270.5]]),
    ("x;y\n1.000,017;2.000,680\n1.005,357;2.004,199\n", [[1000.017, 2000.68], [1005.357, 2004.199]]),
    # a decimal comma elsewhere, two dots
    ("1,5;1.250\n2,5;1.300\n", [[1.5, 1250], [2.5, 1300]]),
    ("1.234.567;-2.000\n1.234.568;2.000\n", [[1234567, -2000], [1234568, 2000]]),
])
def test_grouped_where_the_file_shows_it(tmp_path, text, want):
    assert np.array_equal(_read(tmp_path, text), np.array(want, dtype=float))


@pytest.mark.parametrize("text, want", [
    # instrument exports with 3 decimals: a field the grouping cannot write decides
    ("0.125;1.250\n0.250;1.500\n", [[0.125, 1.25], [0.25, 1.5]]),
    ("1.250;-0.500\n2.000;1.000\n", [[1.25, -0.5], [2.0, 1.0]]),
    ("1.250;1.5\n2.000;3.25\n", [[1.25, 1.5], [2.0, 3.25]]),
    ("1.250;1234\n2.000;5\n", [[1.25, 1234], [2.0, 5]]),
    ("1.250;1e3\n2.000;2.000\n", [[1.25, 1000], [2.0, 2.0]]),
    # other separators: never grouped
    ("1.250,2.000\n1.000,3.000\n", [[1.25, 2.0], [1.0, 3.0]]),
    ("1.250 2.000\n1.000 3.000\n", [[1.25, 2.0], [1.0, 3.0]]),
])
def test_decimal_points_read_as_before(tmp_path, text, want):
    assert np.array_equal(_read(tmp_path, text), np.array(want, dtype=float))


@pytest.mark.parametrize("text", [
    "id;x;y\n999;1.250,5;2.000,0\n1000;1.260,5;2.010,0\n1001;1.270,5;2.020,0\n",
    "x;y;n\n1.250,5;2.000,0;5\n1.260,5;2.010,0;1500\n1.270,5;2.020,0;7\n",
])
def test_grouped_beside_an_integer_of_1000_or_more(tmp_path, text):
    """Review of 7882e4c..51525a7: an integer >= 1000 in any column (an id, a count) made
    the file 'not grouped' before a field only grouping writes (1.250,5) was looked at:
    refused 'not a number: '1.250,5''. Such a field now decides first."""
    want = [[1250.5, 2000.0], [1260.5, 2010.0], [1270.5, 2020.0]]
    assert np.array_equal(_read(tmp_path, text), np.array(want))


def test_undecided_file_refused_naming_the_line(tmp_path, capsys):
    """QA19 c5: every value >= 1000 written 1.000 was read / 1000, silently."""
    text = "x;y\n1.000;2.001\n1.005;2.004\n1.010;2.011\n1.020;2.030\n"
    with pytest.raises(InputError, match=r"p\.csv: line 2: '1\.000' is 1\.0 or 1000: .*"
                                         r"--thousands \..*thousands=''"):
        _read(tmp_path, text)
    assert _read(tmp_path, text, thousands=".")[1].tolist() == [1005, 2004]
    assert _read(tmp_path, text, thousands="")[1].tolist() == [1.005, 2.004]
    # the CLI: refused with exit 2, read with --thousands
    p = tmp_path / "p.csv"
    assert main(["fit", str(p)]) == 2
    assert "line 2: '1.000' is 1.0 or 1000" in capsys.readouterr().err
    assert main(["fit", str(p), "--thousands", ".", "--json", str(tmp_path / "f.json")]) == 0


def test_no_data_rows_names_the_first_skipped_line(tmp_path):
    """QA19 P2: a file of rows without a number said 'no data rows' naming no line."""
    with pytest.raises(InputError, match=r"no data rows \(line 2, 'x;y', and every line after "
                                         r"it skipped as a title or header"):
        _read(tmp_path, "# comment\nx;y\n1.2.3;4.5.6\n")
    # the file's own line, as written (main: the fields joined again, 'x;y')
    with pytest.raises(InputError, match=r"no data rows \(line 1, '\"x\" ; \"y\"', and"):
        _read(tmp_path, '"x" ; "y"\n1.2.3;4.5.6\n')


@pytest.mark.parametrize("text, want", [
    # an id column of 1.001's (part numbers) beside coordinates under 1000: refused before
    # ("'1.001' is 1.001 or 1001"), though no coordinate is written d.ddd
    ("id;x;y\n1.001;12;30\n1.002;15;34\n1.003;19;37\n", [[12, 30], [15, 34], [19, 37]]),
    ("Nr\ty\tx\n1.001\t30\t12\n1.002\t34\t15\n", [[12, 30], [15, 34]]),
    # a date column (yyyymmdd: an integer >= 1000) made a grouped x column read 1.000 as 1.0
    ("date;x;y\n20240517;980;5\n20240517;1.000;7\n20240518;1.020;9\n",
     [[980, 5], [1000, 7], [1020, 9]]),
    # a 1.5 in a weight column decided 'decimal points' for a grouped x column
    ("x;y;w\n980;5;1.5\n1.000;7;2.5\n1.020;9;0.5\n", [[980, 5], [1000, 7], [1020, 9]]),
])
def test_columns_beside_the_coordinates_do_not_decide(tmp_path, text, want):
    """Only the columns read as coordinates decide whether '.' groups thousands: an id, a
    date, a count beside them neither blocks the reading nor flips it."""
    assert np.array_equal(_read(tmp_path, text), np.array(want, dtype=float))


def test_an_id_column_does_not_decide_for_undecided_coordinates(tmp_path):
    """An id column of 1.234.567's (only grouping writes them) read coordinates all written
    d.ddd as grouped (1250 for what may be 1.25): they alone do not decide, so the file is
    refused naming the line, as without the id column."""
    text = "id;x;y\n1.234.567;1.250;2.000\n1.234.568;1.500;2.250\n"
    with pytest.raises(InputError, match=r"line 2: '1\.250' is 1\.25 or 1250"):
        _read(tmp_path, text)
    assert np.array_equal(_read(tmp_path, text, thousands="."), [[1250, 2000], [1500, 2250]])
    assert np.array_equal(_read(tmp_path, text, thousands=""), [[1.25, 2.0], [1.5, 2.25]])


def test_integers_beside_three_decimals_are_not_grouped(tmp_path):
    """Hand-typed in a decimal-point locale's general format (no trailing zeros): whole
    millimetres and eighths, 5 points, tab or ';' separated; every non-integer d.ddd and a
    column holding both, as a #.##0 column holds 980 and 1.000. It was read 0, 12125, 25,
    37375, 50, silently (1000 x too large): the column rule decides only where grouping
    keeps the column's consecutive points the nearer (io._grouped_nearer); here it does
    not, and the file is refused naming --thousands (both readings differ by 1000)."""
    typed = [["0", "0"], ["12.125", "4.125"], ["25", "6"], ["37.375", "4.875"], ["50", "0"]]
    for sep in ("\t", ";"):
        text = "".join(sep.join(r) + "\n" for r in typed)
        with pytest.raises(InputError, match=r"line 2: '12\.125' is 12\.125 or 12125"):
            _read(tmp_path, text)
        assert np.array_equal(_read(tmp_path, text, thousands=""),
                              np.array(typed, dtype=float)), sep
        # Excel's #.##0 crossing 1000 still reads grouped
        text = f"980{sep}5\n1.000{sep}7\n1.020{sep}9\n"
        assert np.array_equal(_read(tmp_path, text), [[980, 5], [1000, 7], [1020, 9]]), sep
