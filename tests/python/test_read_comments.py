"""'#' comments in point files: a whole line, and (QA20 F6) a comment after a row's numbers
('12.3 4.5  # station 3'), which was refused as "line 1: not a number: '#'" while a
whole-line comment was read. A '#' in a quoted field or inside a word ('point#') is no
comment."""
import numpy as np
import pytest

from cli_run import cli
from libelastica.io import InputError, read_points

STATIONS = np.array([[12398.0, 2193.9], [12910.1, 2131.4], [13552.0, 2066.3],
                     [13952.7, 2029.6], [14282.6, 2004.6], [14706.4, 1975.3]])


def _read(tmp_path, text, name="p.txt"):
    (tmp_path / name).write_bytes(text.encode())
    return read_points(tmp_path / name)


@pytest.mark.parametrize("sep", [" ", "\t", ",", ";"])
def test_a_comment_after_the_numbers_is_skipped(tmp_path, sep):
    # the comment holds the other separators and a number: none of them is read
    rows = [f"{x:.1f}{sep}{y:.1f}  # station {i}, port; 3 m" for i, (x, y) in enumerate(STATIONS)]
    text = "# x y in mm\n" + "\r\n".join(rows) + "\n"
    assert np.array_equal(_read(tmp_path, text), STATIONS)
    header = f"x{sep}y # mm\n" + "\n".join(f"{x:.1f}{sep}{y:.1f} #{i}" for i, (x, y) in enumerate(STATIONS))
    assert np.array_equal(_read(tmp_path, header), STATIONS)


def test_a_hash_in_a_quoted_field_or_a_word_is_no_comment(tmp_path):
    text = 'point#,x,y\n' + "".join(f'"P#{i}",{x},{y}\n' for i, (x, y) in enumerate(STATIONS))
    assert np.array_equal(_read(tmp_path, text), STATIONS)
    # a '#' glued to a number is not a comment: the field is still no number
    with pytest.raises(InputError, match=r"line 2: not a number: '2131.4#1'"):
        _read(tmp_path, "12398.0 2193.9\n12910.1 2131.4#1\n13552.0 2066.3\n")


def test_the_cli_fits_qa20s_commented_stations(capsys, tmp_path):
    path = tmp_path / "inline_comments.txt"
    path.write_text("".join(f"{x} {y}  # station {i}\n" for i, (x, y) in enumerate(STATIONS)))
    code, out, err = cli(capsys, "fit", path, "--model", "smooth")
    assert code in (0, 1) and "not a number" not in err, err
    assert "(6 points)" in out, out


@pytest.mark.parametrize("end", ["\n", "\r\n", "\r"])
def test_each_points_line_in_the_file_is_told(tmp_path, end):
    """The FreeCAD Fit names a file's point by its line (an editor's, from 1): titles, the
    header, comments and blank lines are counted, as every line ending is."""
    from libelastica.io import read_points_unit
    rows = ["Survey 7", "x;y", ""]
    for i, (x, y) in enumerate(STATIONS):
        rows.append(f"{x:.1f};{y:.1f}")
        if i == 2:
            rows += ["# the second day", ""]
    (tmp_path / "s.csv").write_bytes((end.join(rows) + end).encode())
    lines = []
    pts = read_points_unit(tmp_path / "s.csv", 1, None, None, lines)[0]
    assert np.array_equal(pts, STATIONS)
    assert lines == [4, 5, 6, 9, 10, 11]
    assert [rows[k - 1] for k in lines] == [f"{x:.1f};{y:.1f}" for x, y in STATIONS]
    np.save(tmp_path / "s.npy", STATIONS)
    lines = []
    read_points_unit(tmp_path / "s.npy", 1, None, None, lines)
    assert lines == [1, 2, 3, 4, 5, 6]
