"""libelastica: Euler's elastica for CAD — exact evaluation, fairing, Hermite
interpolation, B-splines (Python binding of the C library)."""
import importlib as _importlib

from . import _entry   # first: Ctrl-C while the elastica command imports (only then) exits 130
from ._ffi import (AngleUnitWarning, DomainError, ElasticaError, LengthRangeError, NotConvergedError,
                   SingularError)
from .core import DiscreteElastica, SmoothElastica
from . import io
from .cubic import SPARSE_POINTS, SparseWarning, cubic_distances, smooth_fits_better
from .fit import (ConstraintError, ConvergenceWarning, FitResult, OrderWarning, WanderWarning, far_points,
                  far_points_summary, fit, wander_summary)
from .misfit import (MISFIT_RATIO, Misfit, MisfitWarning, OutlierWarning, fit_outliers, misfit,
                     misfit_summary, noise_level, outliers_summary, split_hint)
from .fit_cost import (COST_FLOOR, COST_RATIO, END_POINTS, END_SPAN, EndConditionWarning,
                       cost_summary, costly, end_condition_cost, end_costs, held_ends,
                       local_cost_summary)
from .order import ORDER_RATIO, Ordering, curve_order, out_of_order
from .prep import (KEYLINE_STEPS, RESAMPLE_MAX_VERTICES, Frame, Frame2D, find_inflection, keyline_runs,
                   keyline_step, pca_normalize, plane_fit, prepare_keyline, resample_equilateral,
                   resampled_polygon, ZIGZAG)
# eager: its function has its module's name (importing the module later would rebind it)
from .hermite import HERMITE_SIGMA_D2_MAX, HermiteChain, HermiteSolutions, hermite, hermite_analyse

# imported when first used (PEP 562), so that `elastica --help` and a fit do not load them:
# name -> its module
_LAZY = {name: module for module, names in {
    "keyline": ("KeylineFit", "fit_keyline"),
    "resampled": ("RESAMPLE_RATIO", "ResampledFit", "ResampleWarning", "fit_resampled",
                  "resample_summary", "resampled_fits_worse", "resampled_reference"),
    "blend": ("SPREAD_MAX", "BlendCurve", "BlendLoopWarning", "ConditionWarning", "EllipticBlend",
              "MQBlend", "blend_curve", "eck_d", "eck_omega"),
    "spline": ("DoublesBackError", "ElasticSpline", "LoopWarning", "SeamWarning", "UnstableWarning",
               "elastic_spline", "holding_tension"),
    "spline_hook": ("HOOK_RATIO", "HookWarning"),
    "bspline": ("BSpline", "cubic_through", "interpolate_c2", "keyline_bspline",
                "smooth_chain_to_bspline", "smooth_to_bspline"),
    "affine": ("AffinePolyline", "OsculatingConics", "affine_coords", "affine_curvature",
               "affine_curvature_exact", "affine_elements", "affine_length", "affine_polyline",
               "chaikin", "elastica_affine_curvature", "elastica_inflections", "lane_riesenfeld",
               "osculating_conics", "parabolic_lengths", "quadratic_bspline", "uniform_bspline",
               "g2_bspline", "quadratic_joint_curvatures", "EdgeCountError", "EndPieces",
               "affine_end_pieces"),
    "g2quad": ("CoverageError", "CoverageWarning", "EndTangentWarning", "G2Quadratic",
               "StrayWarning", "covering_edges", "g2_quadratic"),
}.items() for name in names}
# the submodules `import libelastica` always gave as attributes
_SUBMODULES = ("affine", "blend", "bspline", "core", "cubic", "fit_cost", "g2quad", "io", "keyline",
               "order", "prep", "resampled", "shape", "spline")

__version__ = "0.1.0"


def __getattr__(name):
    if name in _LAZY:
        value = getattr(_importlib.import_module(f".{_LAZY[name]}", __name__), name)
    elif name in _SUBMODULES:
        value = _importlib.import_module(f".{name}", __name__)
    else:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    globals()[name] = value
    return value


__all__ = sorted({n for n in globals() if not n.startswith("_") and n != "annotations"}
                 | set(_LAZY) | set(_SUBMODULES))


def __dir__():
    return sorted(set(globals()) | set(__all__))
