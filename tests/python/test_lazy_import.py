"""`import libelastica` loads what a fit needs and the rest (keylines, resampled fits, blends,
splines, B-splines, affine polylines, G2 quadratics) when first used: `elastica --help`
loaded all of it. The public API is the same: every name `import libelastica` gave, the
same object, and `from libelastica import *` the same names."""
from __future__ import annotations

import subprocess
import sys
import types

import libelastica as el

LAZY = ("keyline", "resampled", "blend", "spline", "affine", "g2quad")
# every public name of `import libelastica` before (121, and SparseWarning, spline's UnstableWarning, g2quad's CoverageError,
# covering_edges, EndTangentWarning, affine's EdgeCountError, spline's holding_tension, misfit's OutlierWarning,
# fit_outliers and outliers_summary, affine's EndPieces and affine_end_pieces, misfit's split_hint, fit_uncertainty since, g2quad's StrayWarning: classes, functions, constants, the submodules it gave as attributes)
PUBLIC = sorted("""AffinePolyline AngleUnitWarning BSpline BlendCurve BlendLoopWarning COST_FLOOR COST_RATIO
ConditionWarning ConstraintError ConvergenceWarning CoverageError CoverageWarning DiscreteElastica DomainError
DoublesBackError END_POINTS END_SPAN EdgeCountError ElasticSpline ElasticaError EllipticBlend EndConditionWarning
EndPieces EndTangentWarning FitResult Frame Frame2D G2Quadratic HERMITE_SIGMA_D2_MAX HermiteChain
HOOK_RATIO HermiteSolutions HookWarning KEYLINE_STEPS KeylineFit LengthRangeError LoopWarning MISFIT_RATIO MQBlend Misfit MisfitWarning
NotConvergedError ORDER_RATIO OrderWarning Ordering OutlierWarning OsculatingConics RESAMPLE_MAX_VERTICES
RESAMPLE_RATIO ResampleWarning ResampledFit SPARSE_POINTS SPREAD_MAX SeamWarning SingularError SmoothElastica
SparseWarning StrayWarning UnstableWarning WanderWarning ZIGZAG affine
affine_coords affine_curvature affine_curvature_exact affine_elements affine_end_pieces
affine_length affine_polyline blend blend_curve bspline chaikin core cost_summary costly cubic
covering_edges cubic_distances cubic_through curve_order eck_d eck_omega elastic_spline elastica_affine_curvature
elastica_inflections end_condition_cost end_costs far_points far_points_summary find_inflection
fit fit_cost fit_input fit_outliers fit_keyline fit_resampled fit_retrace fit_uncertainty g2_bspline g2_quadratic g2quad held_ends hermite
holding_tension hermite_analyse interpolate_c2 io keyline keyline_bspline keyline_runs keyline_step
lane_riesenfeld local_cost_summary misfit misfit_summary noise_level order osculating_conics
out_of_order outliers_summary parabolic_lengths pca_normalize plane_fit prep prepare_keyline quadratic_bspline
quadratic_joint_curvatures resample_equilateral resample_summary resampled resampled_fits_worse
resampled_polygon resampled_reference shape smooth_chain_to_bspline smooth_fits_better
smooth_to_bspline spline split_hint uniform_bspline wander_summary""".split())


def _run(code: str) -> str:
    return subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          check=True, timeout=120).stdout


def test_help_does_not_load_what_it_does_not_use():
    out = _run("import sys, libelastica.cli\n"
               "print(' '.join(m for m in sys.modules if m.startswith('libelastica.')))")
    assert not {f"libelastica.{m}" for m in LAZY} & set(out.split()), out


def test_public_api_unchanged():
    assert len(PUBLIC) == 142       # in a fresh process: a submodule imported adds its name
    assert _run("import libelastica as el\n"
                "print(' '.join(sorted(n for n in dir(el) if not n.startswith('_'))))").split() == PUBLIC
    names = _run("from libelastica import *\n"
                 "print(' '.join(sorted(n for n in dir() if not n.startswith('_'))))").split()
    assert names == PUBLIC
    for name in PUBLIC:
        value = getattr(el, name)
        if isinstance(value, types.ModuleType):
            assert value is sys.modules[f"libelastica.{name}"]
        elif isinstance(value, (type, types.FunctionType)):     # as its module defines it
            assert value is getattr(sys.modules[value.__module__], value.__name__)
    assert callable(el.fit) and callable(el.misfit) and callable(el.hermite)


def test_a_module_imported_later_keeps_the_functions():
    """Importing a lazy module (as `from libelastica.keyline import ...` does) leaves el.fit,
    el.misfit, el.hermite the functions, and an unknown name an AttributeError."""
    out = _run("import libelastica as el, libelastica.keyline, libelastica.spline\n"
               "from libelastica.blend import EllipticBlend\n"
               "print(el.fit.__module__, el.misfit.__module__, el.hermite.__module__,\n"
               "      el.EllipticBlend is EllipticBlend, el.keyline.__name__)\n"
               "try:\n    el.nothing\nexcept AttributeError as e:\n    print('AE', e)")
    assert out.split("\n")[0] == ("libelastica.fit libelastica.misfit libelastica.hermite True "
                                  "libelastica.keyline")
    assert "AE module 'libelastica' has no attribute 'nothing'" in out
