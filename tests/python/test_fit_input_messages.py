"""el.fit's input messages name what was given (QA25 F5): an extent outside the range the
fit covers (the point, column and value), None / a generator / a stray object (its type)."""
import numpy as np
import pytest

import libelastica as el

ARC = 10.0 * np.c_[np.cos(np.linspace(0, 3, 40)), np.sin(np.linspace(0, 3, 40))]


def test_an_extent_beyond_the_fits_range_names_the_point_and_the_range():
    """The smooth fit of points spanning 2e151 said only "fit: input outside the domain the
    method covers"; now the extent, the range (el_fit's header: ~1e-150 .. 1e150), the
    farthest point, its column and value."""
    P = ARC * 1e150
    with pytest.raises(el.DomainError) as exc:
        el.fit(P, model="smooth")
    said = str(exc.value)
    assert "1e+150" in said and "1e-150" in said and "column" in said, said
    i = int(said.split("point ")[1].split()[0])
    j = int(said.split(" in column ")[1].split(",")[0])
    v = float(said.split(" has ")[1].split()[0])
    assert P[i, j] == v and abs(P[i, j] - np.median(P[:, j])) == np.max(np.abs(P - np.median(P, axis=0)))
    with pytest.raises(el.DomainError, match="span only .* less than the 1e-150"):
        el.fit(ARC * 1e-170, model="smooth")


@pytest.mark.parametrize("given, said", [
    (None, r"got NoneType \(None\)"),
    ((tuple(p) for p in ARC), "got generator: an iterator numpy cannot read as one; pass list"),
    ({"a": 1}, "got dict {'a': 1}"),
    ([[1, 2], [3, None], [4, 5], [6, 7]], r"element \(1, 1\) is NoneType None"),
])
def test_what_is_not_an_array_of_reals_is_named(given, said):
    """fit(None) and a generator of tuples said "points must hold real numbers only":
    now what was given (its type, and where in an array) and what is wanted."""
    with pytest.raises(ValueError, match=said):
        el.fit(given)
