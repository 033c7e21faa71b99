"""Results print as a summary, not their arrays (QA18 P4: repr(FitResult) was ~10 kB for 160
points, every distance, foot and point printed; KeylineFit 16 kB)."""
from __future__ import annotations

import re

import numpy as np
import pytest

import libelastica as el
from test_equality import BUILD, build


@pytest.mark.parametrize("name", sorted(set(BUILD) - {"HermiteSolutions"}))
def test_a_repr_is_a_line_whatever_the_data_size(name):
    """(HermiteSolutions is a list of its curves: as many reprs as solutions.)"""
    r = repr(build(name))
    assert len(r) < 600 and "\n" not in r, (name, len(r), r[:200])


def test_fit_result_repr_says_what_matters():
    P = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=1.0, k=0.6, q=-1.2, length=4.5).points(1000)
    P = P + 0.01 * np.random.default_rng(3).standard_normal(P.shape)
    r = el.fit(P, model="smooth")
    assert re.fullmatch(r"FitResult\(smooth, 1000 points, orthogonal, rms 0\.0\d+, max 0\.0\d+, "
                        r"converged, curve=SmoothElastica\(.*\)\)", repr(r)), repr(r)
    assert len(repr(r)) < 300
