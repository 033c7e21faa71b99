"""A unit named in a CSV header ('x [mm],y [mm]') is kept (QA qapy F3: read, then lost: the
report printed bare numbers, the JSON had no unit, the DXF was unitless unless --units was
given again): it shows in the report and the JSON, and tags the DXF unless --units says
otherwise; a --units naming another unit, or columns naming two, are refused naming both."""
from __future__ import annotations

import json

import numpy as np
import pytest

from cli_run import cli
from libelastica.io import InputError, read_points, read_points_unit


def _ship(tmp_path, header="x [mm],y [mm]", name="ship.csv"):
    """A ship's line (QA F2's kind): 30 points, 9 m long, at (12000, 3500) mm."""
    t = np.linspace(0.0, 1.0, 30)
    xy = np.c_[12000 + 9000 * t, 3500 + 900 * np.sin(2.2 * t)]
    xy += np.random.default_rng(3).normal(0.0, 1.5, xy.shape)
    path = tmp_path / name
    path.write_text(header + "\n" + "\n".join(f"{x:.1f},{y:.1f}" for x, y in xy) + "\n")
    return path


def test_read_points_unit_names_the_header_unit(tmp_path):
    for header, unit in (("x [mm],y [mm]", "mm"), ("X (MM),Y (mm)", "mm"), ("x,y", None),
                         ("x [µm],y", "um"), ("x [inch],y [inch]", "in"), ("x [px],y [px]", "px"), ("x (Länge),y (Höhe)", None),
                         ("id,x [m],y [m]", "m")):
        path = tmp_path / "p.csv"
        rows = "\n".join(f"{i},{i},{i * i}" if header.startswith("id") else f"{i},{i * i}"
                         for i in range(5))
        path.write_text(f"{header}\n{rows}\n")
        pts, got = read_points_unit(path)
        assert got == unit, header
        assert np.array_equal(pts, read_points(path))     # read_points: the same points
    path.write_text("x [mm],y [m]\n0,0\n1,1\n2,4\n")
    with pytest.raises(InputError, match=r"two units, 'mm' \('x \[mm\]'\) and 'm' \('y \[m\]'\)"):
        read_points_unit(path)


def test_a_tab_or_space_separated_header_with_units_names_its_columns(tmp_path):
    """review revD: 'x [mm]<TAB>y [mm]' (a spreadsheet's tab export) and 'X (mm) Y (mm)' were
    split at every blank, named no column: the unit was lost, and 'y [mm]<TAB>x [mm]' was
    read by position, mirrored."""
    rows = [(0.0, 1.0), (1.0, 2.0), (4.0, 3.0), (9.0, 5.0)]
    for sep, header, unit, want in (
            ("\t", "x [mm]\ty [mm]", "mm", rows), (" ", "X (mm) Y (mm)", "mm", rows),
            ("\t", "y [in]\tx [in]", "in", [(b, a) for a, b in rows]),
            (" ", "Punkt x [m] y [m]", "m", rows)):
        path = tmp_path / "p.txt"
        lines = [sep.join(([str(i)] if header.startswith("Punkt") else []) + [f"{a}", f"{b}"])
                 for i, (a, b) in enumerate(rows)]
        path.write_text(header + "\n" + "\n".join(lines) + "\n")
        pts, got = read_points_unit(path)
        assert got == unit and np.array_equal(pts, np.array(want)), (header, got, pts)
    path.write_text("x [mm]\ty [m]\n0\t0\n1\t1\n2\t4\n")
    with pytest.raises(InputError, match="two units"):
        read_points_unit(path)


def test_the_header_unit_shows_in_the_report_json_and_dxf(tmp_path, capsys):
    ezdxf = pytest.importorskip("ezdxf")
    path = _ship(tmp_path)
    code, out, err = cli(capsys, "fit", path, "--model", "smooth", "--json", tmp_path / "s.json",
                         "--dxf", tmp_path / "s.dxf")
    assert code == 0, err
    assert "(coordinates in mm: its header)" in out
    rms = [ln for ln in out.splitlines() if ln.startswith("rms ")][0]
    assert rms.split()[2] == "mm", rms
    assert [ln for ln in out.splitlines() if ln.startswith("max error")][0].endswith(" mm")
    # the B-spline's figures too (review revD: 'max deviation 0.00737', 'lie rms 2.5, max 5.2')
    assert [ln for ln in out.splitlines() if ln.startswith("B-spline")][0].endswith(" mm"), out
    out = cli(capsys, "fit", path, "--bspline-tol", "0.01")[1]
    lie = [ln for ln in out.splitlines() if "points lie rms" in ln][0]
    assert lie.split("lie rms ")[1].split()[1] == "mm," and " mm from it" in lie, lie
    assert json.loads((tmp_path / "s.json").read_text())["unit"] == "mm"
    assert ezdxf.readfile(tmp_path / "s.dxf").header["$INSUNITS"] == 4       # mm
    # --units none: an untagged drawing, as asked; --units mm: the same unit, no conflict
    for units, code_want in (("none", 0), ("mm", 4)):
        assert cli(capsys, "fit", path, "--dxf", tmp_path / "n.dxf", "--units", units)[0] == 0
        assert ezdxf.readfile(tmp_path / "n.dxf").header["$INSUNITS"] == code_want
    # a keyline's and the g2quad's of the fit's JSON keep it too
    code, _, err = cli(capsys, "g2quad", tmp_path / "s.json", "--dxf", tmp_path / "g.dxf",
                       "--json", tmp_path / "g.json")
    assert code == 0, err
    assert ezdxf.readfile(tmp_path / "g.dxf").header["$INSUNITS"] == 4
    assert json.loads((tmp_path / "g.json").read_text())["unit"] == "mm"
    code, _, err = cli(capsys, "bspline", tmp_path / "s.json", "--dxf", tmp_path / "b.dxf")
    assert code == 0, err
    assert ezdxf.readfile(tmp_path / "b.dxf").header["$INSUNITS"] == 4
    code, _, err = cli(capsys, "bspline", tmp_path / "s.json", "--dxf", tmp_path / "b.dxf",
                       "--units", "m")
    assert code == 2 and "--units m but its header gives the coordinates in mm" in err, err


def test_a_file_without_a_unit_is_unitless_as_before(tmp_path, capsys):
    ezdxf = pytest.importorskip("ezdxf")
    path = _ship(tmp_path, header="x,y")
    code, out, err = cli(capsys, "fit", path, "--json", tmp_path / "s.json",
                         "--dxf", tmp_path / "s.dxf")
    assert code == 0, err
    assert "coordinates in" not in out and " mm" not in out
    assert json.loads((tmp_path / "s.json").read_text())["unit"] is None
    assert ezdxf.readfile(tmp_path / "s.dxf").header["$INSUNITS"] == 0
    assert cli(capsys, "fit", path, "--dxf", tmp_path / "s.dxf", "--units", "m")[0] == 0
    assert ezdxf.readfile(tmp_path / "s.dxf").header["$INSUNITS"] == 6


def test_units_conflicting_with_the_header_are_refused_naming_both(tmp_path, capsys):
    pytest.importorskip("ezdxf")
    path = _ship(tmp_path)
    code, out, err = cli(capsys, "fit", path, "--dxf", tmp_path / "s.dxf", "--units", "m")
    assert code == 2
    assert "--units m but its header gives the coordinates in mm" in err, err
    assert not (tmp_path / "s.dxf").exists()
    code, _, err = cli(capsys, "spline", path, "--dxf", tmp_path / "s.dxf", "--units", "in")
    assert code == 2 and "--units in but its header gives the coordinates in mm" in err, err
    mixed = _ship(tmp_path, header="x [mm],y [m]", name="mixed.csv")
    code, _, err = cli(capsys, "fit", mixed)
    assert code == 2 and "two units, 'mm'" in err and "'m' ('y [m]')" in err, err
    # a unit DXF cannot say is no license for another (QA revD: 'x [km]' with --units m
    # tagged the drawing m, 1000 x too small); a pixel has no size: any unit may be given
    km = _ship(tmp_path, header="x [km],y [km]", name="km.csv")
    code, _, err = cli(capsys, "fit", km, "--dxf", tmp_path / "k.dxf", "--units", "m")
    assert code == 2 and "--units m but its header gives the coordinates in km" in err, err
    assert not (tmp_path / "k.dxf").exists()
    px = _ship(tmp_path, header="x [px],y [px]", name="px.csv")
    assert cli(capsys, "fit", px, "--dxf", tmp_path / "p.dxf", "--units", "mm")[0] == 0
