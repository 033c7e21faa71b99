"""read_points names a file's line as a text editor numbers it: lines end at \\n, \\r\\n or
\\r alone (str.splitlines, which io used, also ends one at a form feed, U+2028, \\v, \\x85,
...), and a quoted field holding a line end spans lines as the csv module counts them (io
numbered csv's records); the FreeCAD Fit names its points so (test_elastica_fit_csv_lines)."""
import pytest

from libelastica import io

ROWS = "1.5,2\n3,4.5\n5,7\n8,1,9\n"          # the bad row (3 columns) is the head's + 4


@pytest.mark.parametrize("head, line", [
    ("# a\fb\nx,y\n", 6),                     # a form feed inside a comment
    ("# a\u2028b\u2029c\x85d\vx\nx,y\n", 6),  # other splitlines ends inside a comment
    ('"Profile\n7",\nx,y\n', 7),              # a title quoted across two lines
    ("# a\rx,y\r\n", 6),                      # \r alone, \r\n: line ends
])
def test_a_bad_rows_line_is_an_editors(head, line):
    with pytest.raises(io.InputError, match=rf"scan.csv: line {line}: 3 columns"):
        io.read_points("scan.csv", data=(head + ROWS).encode())


def test_each_points_line():
    lines = []
    text = '# a\fb\n"t\nu",x,y\nP1,1,2\n"P\n2",3,4\r\nP3,5,7\rP4,6,9\n'
    arr, unit = io.read_points_unit("scan.csv", 3, text.encode(), None, lines)
    assert arr.tolist() == [[1, 2], [3, 4], [5, 7], [6, 9]]
    assert lines == [4, 5, 7, 8]      # the quoted 'P\n2' named by its first line
