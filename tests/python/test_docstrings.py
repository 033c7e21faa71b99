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
               if name not in ("self", "kwargs", "options", "n", "points", "r", "side", "s")
               and p.kind is not p.VAR_KEYWORD
               and not re.search(rf"(``|\b){name}(``|\b)", doc)]
    assert not missing, f"{call.__qualname__}: {missing}"


def _public_callables():
    """(name, callable, its docstring) of every public function of libelastica.__all__, every
    class (its signature against the class docstring: a dataclass's fields, a constructor's
    parameters) and every public method a class defines."""
    out = []
    for name in el.__all__:
        obj = getattr(el, name)
        if inspect.ismodule(obj) or not callable(obj) or (
                isinstance(obj, type) and issubclass(obj, BaseException)):
            continue
        out.append((name, obj, inspect.getdoc(obj) or ""))
        if isinstance(obj, type):
            out += [(f"{name}.{m}", getattr(obj, m), inspect.getdoc(getattr(obj, m)) or "")
                    for m in vars(obj) if not m.startswith("_") and callable(getattr(obj, m))]
    return out


def _undescribed(call, doc):
    try:
        params = inspect.signature(call).parameters.items()
    except (TypeError, ValueError):
        return []
    return [name for name, p in params if name not in ("self", "cls")
            and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
            and not re.search(rf"(?<![\w.]){name}(?!\w)", doc)]


def test_every_public_parameter_is_named_in_its_docstring():
    """help() of every public function, class and method names each parameter a caller
    may pass (QA18 P3: 42 were not, e.g. g2_quadratic's samples_per_vertex,
    SmoothElastica.angle's extrapolate, BlendCurve's q / closed / through)."""
    missing = {name: m for name, call, doc in _public_callables() if (m := _undescribed(call, doc))}
    assert not missing, f"{len(missing)} callables: {missing}"


def test_hermite_says_which_energy():
    doc = inspect.getdoc(el.hermite)
    assert re.search(r"energy_value``: integral of kappa\^2 ds as the solve\s+computed it", doc)
    assert "energy()" in doc
    c = el.hermite((0, 0), (1, 0), (2, 0), (0, 1), tension=1.0)[0]
    assert abs(c.energy() - c.energy_value) <= 1e-9 * c.energy_value


# every attribute / method of the binding that holds or returns an angle, and the unit its
# docstring must name (QA18 P2: SmoothElastica's phi and ElasticSpline.angles had none)
ANGLES = [(el.SmoothElastica, "phi", "radians"), (el.SmoothElastica.angle, "theta", "radians"),
          (el.DiscreteElastica, "phi", "radians"), (el.HermiteChain.angle, "theta", "radians"),
          (el.ElasticSpline, "angles", "radians"), (el.ElasticSpline.angle, "angle", "rad"),
          (el.G2Quadratic, "end_tangent_error", "radians"), (el.G2Quadratic, "join_angle", "radians"),
          (el.G2Quadratic, "source_end_tangent_error", "radians"),
          (el.BlendCurve.seam_angle, "angle", "DEGREES"), (el.FitResult, "constraints", "radians")]


@pytest.mark.parametrize("obj, name, unit", ANGLES, ids=lambda v: getattr(v, "__qualname__", v))
def test_every_angle_names_its_unit(obj, name, unit):
    """The sentence of the docstring naming the angle names its unit too (seam_angle, the
    one in degrees, says so loudly)."""
    doc = " ".join((inspect.getdoc(obj) or "").split())
    sentences = [s for s in re.split(r"(?<=[.;])\s", doc) if re.search(rf"\b{name}\b", s)]
    assert any(re.search(rf"\b{unit}\b", s) for s in sentences), (name, sentences)
