"""help() names every parameter of the binding's main calls (QA17 P5: help(el.fit) said
nothing of tol= or limited_memory=, help(el.hermite) of samples, grid, max_solutions,
help(el.blend_curve) of d, help(el.elastic_spline) of max_iter, max_steps), and says
which of a Hermite solution's energy() and energy_value to read."""
from __future__ import annotations

import inspect
import re

import pytest

import libelastica as el

CALLS = [el.fit, el.fit_keyline, el.hermite, el.blend_curve, el.elastic_spline,
         el.g2_quadratic, el.SmoothElastica.points, el.ElasticSpline.points]


@pytest.mark.parametrize("call", CALLS, ids=lambda c: c.__qualname__)
def test_every_parameter_is_described(call):
    doc = inspect.getdoc(call) or ""
    missing = [name for name, p in inspect.signature(call).parameters.items()
               if name not in ("self", "kwargs", "options", "curve_or_points", "n",
                               "samples_per_vertex", "points", "r", "side", "s")
               and p.kind is not p.VAR_KEYWORD
               and not re.search(rf"(``|\b){name}(``|\b)", doc)]
    assert not missing, f"{call.__qualname__}: {missing}"


def test_hermite_says_which_energy():
    doc = inspect.getdoc(el.hermite)
    assert re.search(r"energy_value``: integral of kappa\^2 ds as the solve\s+computed it", doc)
    assert "energy()" in doc
    c = el.hermite((0, 0), (1, 0), (2, 0), (0, 1), tension=1.0)[0]
    assert abs(c.energy() - c.energy_value) <= 1e-9 * c.energy_value
