"""el.fit's checks from the C fit's figures (el_fit_options.figures): its quick noise figure
and the median of |distances| the fit's one call returns are the binding's own (misfit's
_noise, _median.median of np.abs), and the outlier test screened by that median and the
result's max_error warns exactly where far_points names points (noisy scans with and
without points dragged off, both models, paired and by distance, sketches of few points)."""
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica._ffi import dptr, ffi, lib
from libelastica._median import median
from libelastica.fit import OUTLIER_FACTOR, far_points
from libelastica.misfit import OutlierWarning, _noise


def _sets():
    rng = np.random.default_rng(16)
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=0.3, mu=1.0, k=0.8, q=0.2, length=4.0)
    for n in (8, 19, 20, 21, 100, 1000):
        for uneven in (False, True):
            s = np.linspace(0, 1, n) ** (1.5 if uneven else 1.0) * c.length
            pts = c.points(s) + rng.normal(0, 0.004, (n, 2))
            yield pts
            drag = pts.copy()
            drag[n // 3] += (0.3, -0.2)
            yield drag


@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_the_c_fits_figures_are_the_bindings(model):
    for pts in _sets():
        n = len(pts)
        o = ffi.new("el_fit_options *")
        lib.el_fit_options_defaults(o)
        o.figures = 1
        res = ffi.new(f"el_fit_{model}_result *")
        dist, foot = np.empty(n), np.empty(n)
        call = lib.el_fit_discrete if model == "discrete" else lib.el_fit_smooth
        assert call(dptr(pts), n, o, ffi.NULL, res, dptr(dist), dptr(foot)) == lib.EL_OK
        assert res.median_distance == median(np.abs(dist))
        assert res.max_error == np.abs(dist).max()
        assert res.noise_quick == _noise(pts, quick=True)


@pytest.mark.parametrize("model", ["discrete", "smooth"])
@pytest.mark.parametrize("distance", [None, "paired"])
def test_outlier_warnings_as_far_points_name(model, distance):
    warned_sets = 0
    for pts in _sets():
        with warnings.catch_warnings(record=True) as w:
            warnings.simplefilter("always")
            r = el.fit(pts, model=model, distance=distance)
        said = [x for x in w if issubclass(x.category, OutlierWarning)]
        far = far_points(r.distances, r.points)
        if len(pts) >= 20:
            assert bool(said) == bool(len(far))
            # the screen's own test: none far where the largest distance is within the factor
            screened = not r.max_error > OUTLIER_FACTOR * (1.4826 * median(np.abs(r.distances)))
            assert not (screened and len(far))
        warned_sets += bool(said)
    assert warned_sets >= 1
