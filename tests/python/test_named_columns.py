"""Points in a table are read by their columns' names (QA19 W1: el.fit(DataFrame) read
them by position, so a frame ['y', 'x'] was fitted mirrored, silently, and ['x', 'y',
'intensity'] was refused as 3D points): x, y (and z), any case, a unit allowed, the names
the command line reads in a header; a table naming none is refused naming its columns.
Numpy structured / record arrays and any object with ``columns`` and ``table[name]`` (a
duck), and pandas' own DataFrames (make deps installs pandas for both Pythons). And (QA19 P1)
coordinates given as rows, (2, n), are refused with the advice to stack them as columns.
"""
from __future__ import annotations

import numpy as np
import pytest

import libelastica as el
from libelastica import io
from libelastica._values import same

CURVE = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.8, q=0.0, length=8.0)
P = CURVE.points(60) + np.random.default_rng(1).normal(0, 0.02, (60, 2))
X, Y = P[:, 0].copy(), P[:, 1].copy()


class Table:
    """A DataFrame's duck: ``columns`` and ``table[name]`` (a column)."""

    def __init__(self, **cols):
        self.columns = list(cols)
        self._cols = cols

    def __getitem__(self, name):
        return self._cols[name]


def tables(**cols):
    """The same columns as a duck table, a structured array and a record array."""
    r = np.rec.fromarrays(list(cols.values()), names=list(cols))
    return {"duck": Table(**cols), "structured": r.view(np.ndarray), "record": r}


# every public function taking points, called on them (a table, or the (n, 2) array)
CALLS = {
    "fit": lambda p: el.fit(p, model="smooth").curve,
    "fit discrete": lambda p: el.fit(p).rms,
    "noise_level": el.noise_level,
    "misfit": lambda p: el.misfit(p, np.r_[np.full(30, 0.02), np.full(30, 0.9)]),
    "elastic_spline": lambda p: el.elastic_spline(p, tension=0.5).length,
    "curve_order": el.curve_order,
    "out_of_order": el.out_of_order,
    "resample_equilateral": lambda p: el.resample_equilateral(p, 0.3),
    "find_inflection": el.find_inflection,
    "pca_normalize": lambda p: el.pca_normalize(p)[0],
    "keyline_runs": el.keyline_runs,
    "keyline_step": el.keyline_step,
    "prepare_keyline": lambda p: el.prepare_keyline(p).polygon,
    "far_points": lambda p: el.far_points(np.r_[np.zeros(59), 5.0], p),
    "fit_keyline": lambda p: el.fit_keyline(p).to_bspline().poles,
    "fit_resampled": lambda p: el.fit_resampled(p, 0.2),
    "blend_curve": lambda p: el.blend_curve(p).q,
    "interpolate_c2": lambda p: el.interpolate_c2(p).poles,
    "g2_quadratic": lambda p: el.g2_quadratic(p, 20),
    "affine_polyline": lambda p: el.affine_polyline(p, 6).points,
    "wander_summary": lambda p: el.wander_summary(2, p),
}


@pytest.mark.parametrize("call", sorted(CALLS))
def test_every_function_reads_a_table_by_name(call):
    """Columns ['y', 'x', 'intensity']: the x, y by name, the same answer as the array's."""
    want = CALLS[call](P)
    for kind, t in tables(y=Y, x=X, intensity=np.ones(60)).items():
        assert same(CALLS[call](t), want), kind


@pytest.mark.parametrize("kind", ["duck", "structured", "record"])
def test_names_as_the_command_line_reads_them(kind, tmp_path):
    """Any case, a unit in brackets; the same names a CSV header picks its columns by
    (io.read_points), and the same refusals."""
    want = el.fit(P, model="smooth").curve
    for xname, yname in (("X", "Y"), ("x [mm]", "y (mm)"), (" x ", "Y [m]")):
        t = tables(id=np.arange(60.0), **{yname: Y, xname: X})[kind]
        assert el.fit(t, model="smooth").curve == want
        csv = tmp_path / "p.csv"
        csv.write_text(f"id,{yname},{xname}\n" + "".join(f"{i},{float(y)!r},{float(x)!r}\n" for i, (x, y)
                                                          in enumerate(P)))
        assert np.array_equal(io.read_points(csv), P)
    for xname in ("xx", "lon", "x_mm"):          # not a coordinate's name, in either
        with pytest.raises(ValueError, match=r"its columns are \["):
            el.fit(tables(**{xname: X, "y": Y})[kind])
        csv.write_text(f"id,{xname},y,w\n" + "".join(f"{i},{x},{y},1\n" for i, (x, y)
                                                      in enumerate(P)))
        with pytest.raises(io.InputError, match="name the coordinates x, y"):
            io.read_points(csv)


@pytest.mark.parametrize("kind", ["duck", "structured", "record"])
def test_a_table_without_coordinates_is_refused_naming_its_columns(kind):
    with pytest.raises(ValueError, match=r"points: a table.s coordinates are read by "
                                         r"name, x, y.*\(any case.*its columns are "
                                         r"\['east', 'north'\]"):
        el.fit(tables(east=X, north=Y)[kind])
    with pytest.raises(ValueError, match=r"noise_level: points: .*name x twice"):
        el.noise_level(tables(x=X, X=Y, y=Y)[kind])


@pytest.mark.parametrize("kind", ["duck", "structured", "record"])
def test_z_is_read_where_3d_points_are_taken(kind):
    """fit refuses x, y, z as it refuses (n, 3) (with its plane-fit advice); plane_fit
    and fit_keyline read z; a function of 2D points refuses z, naming the columns."""
    Z = 0.1 * X
    t = tables(z=Z, y=Y, x=X)[kind]
    xyz = np.column_stack((X, Y, Z))
    with pytest.raises(ValueError, match=r"got \(60, 3\): 3D points are fitted in their plane"):
        el.fit(t)
    assert same(el.plane_fit(t), el.plane_fit(xyz))
    assert same(el.fit_keyline(t).to_bspline().poles, el.fit_keyline(xyz).to_bspline().poles)
    with pytest.raises(ValueError, match=r"noise_level: points: the table's columns "
                                         r"\['z', 'y', 'x'\] hold 3D points"):
        el.noise_level(t)
    with pytest.raises(ValueError, match=r"plane_fit: xyz: .* x, y, z .*its columns are "
                                         r"\['y', 'x'\]"):
        el.plane_fit(tables(y=Y, x=X)[kind])


class Positional(Table):
    """A frame made from an array: columns labelled 0, 1, converted by np.asarray."""

    def __init__(self, a):
        super().__init__()
        self.columns = list(range(a.shape[1]))
        self._cols = dict(enumerate(a.T))

    def __array__(self, dtype=None, copy=None):
        return np.column_stack([self._cols[c] for c in self.columns])


def test_positional_columns_are_read_by_position():
    """Integer labels (a DataFrame made from an array: 0, 1) are positions, as before."""
    assert el.fit(Positional(P), model="smooth").curve == el.fit(P, model="smooth").curve
    assert same(el.plane_fit(Positional(np.c_[P, X])), el.plane_fit(np.c_[P, X]))


def test_pandas_frames():
    import pandas as pd
    want = el.fit(P, model="smooth")
    assert el.fit(pd.DataFrame({"y": Y, "x": X}), model="smooth").curve == want.curve
    assert el.fit(pd.DataFrame({"x": X, "y": Y, "intensity": 1.0}), model="smooth").curve \
        == want.curve
    assert el.fit(pd.DataFrame({"id": range(60), "x": X, "y": Y}), model="smooth").curve \
        == want.curve
    assert el.fit(pd.DataFrame(P), model="smooth").curve == want.curve        # 0, 1
    assert el.fit(pd.DataFrame({"y": Y, "x": X}).astype("Float64"),
                  model="smooth").curve == want.curve
    with pytest.raises(ValueError, match=r"its columns are \['lat', 'lon'\]"):
        el.fit(pd.DataFrame({"lat": Y, "lon": X}))


@pytest.mark.parametrize("call, name", [(lambda a: el.fit(a), "points"),
                                        (el.noise_level, "noise_level: points"),
                                        (lambda a: el.elastic_spline(a, tension=0.5), "points"),
                                        (el.curve_order, "curve_order: points")])
def test_coordinates_as_rows_are_refused_with_the_advice(call, name):
    """QA19 P1: el.fit((x, y)) and (2, n) arrays: refused, now saying how to pass them."""
    for a in ((X, Y), P.T, [X.tolist(), Y.tolist()]):
        with pytest.raises(ValueError, match=rf"{name} must have shape \(n, 2\)(?: or \(n, 3\))?, "
                                             r"got \(2, 60\) \(pass np.column_stack\(\(x, y\)\), "
                                             r"or points.T\)"):
            call(a)


def test_rows_of_3d_coordinates_and_two_points():
    with pytest.raises(ValueError, match=r"got \(3, 60\) \(pass np.column_stack\(\(x, y, z\)\), "
                                         r"or points.T\)"):
        el.fit_keyline(np.vstack((X, Y, X)))
    # two points, (2, 2), are points, never transposed (n = 2 is ambiguous)
    two = P[:2]
    assert same(el.elastic_spline(two, tension=0.5), el.elastic_spline(two.tolist(), tension=0.5))
