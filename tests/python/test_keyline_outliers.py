"""A keyline fit says which of the input points are spikes, as el.fit does (QA23 F2):
OutlierWarning counting the input's own points, KeylineFit.outliers, and `elastica fit
--keyline`'s warning line and JSON "input_outliers" by the file's rows."""
import json
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica.cli import main
from keyline_data import keyline_2d

SPIKES = [26, 141, 333]


def _scan(spikes=True, seed=3):
    """A 300 mm tile keyline, 400 points at irregular spacing, noise 0.2 mm, and 3 spikes
    of 3-6 mm along the normal (a scanner's glitches) at SPIKES."""
    rng = np.random.default_rng(seed)
    xy = keyline_2d(n=400, rng=rng)[0]
    pts = xy + rng.normal(0, 0.2, xy.shape)
    if spikes:
        t = np.gradient(xy, axis=0)
        nrm = np.c_[-t[:, 1], t[:, 0]] / np.hypot(*t.T)[:, None]
        pts[SPIKES] += np.array([3.0, -6.0, 4.5])[:, None] * nrm[SPIKES]
    return pts


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_fit_keyline_warns_of_spikes_by_the_inputs_numbers(model):
    """el.fit names the spikes (OutlierWarning); fit_keyline said nothing (QA23: 3 spikes of
    800 points, inlier rms up to 3.6 x the true curve's over 79 spiky profiles). Now it warns
    with the input's own numbers, KeylineFit.outliers the same; a clean scan: no warning."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        k = el.fit_keyline(_scan(), model=model)
    said = [w for w in caught if issubclass(w.category, el.OutlierWarning)]
    assert len(said) == 1 and list(said[0].message.indices) == SPIKES
    assert "points 26, 141, 333, counted from 0" in str(said[0].message)
    assert list(k.outliers) == SPIKES
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        k = el.fit_keyline(_scan(spikes=False), model=model)
    assert not [w for w in caught if issubclass(w.category, el.OutlierWarning)]
    assert k.outliers == ()


def test_cli_keyline_names_the_spikes_by_the_files_rows(capsys, tmp_path):
    """`elastica fit --keyline` printed "max error 6.26" only, its JSON's sides "outliers" in
    each side's own numbering (QA23). Now one warning line names the file's rows, and each
    side's record carries them as "input_outliers"."""
    f = tmp_path / "tile.csv"
    np.savetxt(f, _scan(), delimiter=",", header="x,y", comments="")
    capsys.readouterr()
    assert main(["fit", str(f), "--keyline", "--json", str(tmp_path / "k.json")]) == 0
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if "outliers?" in ln]
    assert len(lines) == 1 and "(keyline)" in lines[0] and "points 26, 141, 333, counted from 0" in lines[0]
    doc = json.loads((tmp_path / "k.json").read_text())
    assert [s["input_outliers"] for s in doc["sides"]] == [SPIKES, SPIKES]
