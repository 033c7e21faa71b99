"""libelastica: Euler's elastica for CAD — exact evaluation, fairing, Hermite
interpolation, B-splines (Python binding of the C library)."""
from ._ffi import DomainError, ElasticaError, LengthRangeError, NotConvergedError, SingularError
from .core import DiscreteElastica, SmoothElastica
from . import io
from .cubic import SPARSE_POINTS, cubic_distances, smooth_fits_better
from .fit import (ConstraintError, ConvergenceWarning, FitResult, OrderWarning, WanderWarning, far_points,
                  far_points_summary, fit, wander_summary)
from .keyline import KeylineFit, fit_keyline
from .misfit import MISFIT_RATIO, Misfit, MisfitWarning, misfit, misfit_summary, noise_level
from .fit_cost import (COST_FLOOR, COST_RATIO, END_POINTS, END_SPAN, EndConditionWarning,
                       cost_summary, costly, end_condition_cost, end_costs, held_ends,
                       local_cost_summary)
from .order import ORDER_RATIO, Ordering, curve_order, out_of_order
from .prep import (KEYLINE_STEPS, RESAMPLE_MAX_VERTICES, Frame, Frame2D, find_inflection, keyline_runs,
                   keyline_step, pca_normalize, plane_fit, prepare_keyline, resample_equilateral,
                   resampled_polygon, ZIGZAG)
from .resampled import (RESAMPLE_RATIO, ResampledFit, ResampleWarning, fit_resampled, resample_summary,
                        resampled_fits_worse, resampled_reference)
from .blend import (SPREAD_MAX, BlendCurve, BlendLoopWarning, ConditionWarning, EllipticBlend, MQBlend,
                    blend_curve, eck_d, eck_omega)
from .hermite import HERMITE_SIGMA_D2_MAX, HermiteChain, HermiteSolutions, hermite, hermite_analyse
from .spline import DoublesBackError, ElasticSpline, LoopWarning, elastic_spline
from .bspline import (BSpline, cubic_through, interpolate_c2, keyline_bspline,
                      smooth_chain_to_bspline, smooth_to_bspline)
from .affine import (AffinePolyline, OsculatingConics, affine_coords, affine_curvature,
                     affine_curvature_exact, affine_elements, affine_length, affine_polyline,
                     chaikin, elastica_affine_curvature, elastica_inflections, lane_riesenfeld,
                     osculating_conics, parabolic_lengths, quadratic_bspline, uniform_bspline,
                     g2_bspline, quadratic_joint_curvatures)
from .g2quad import CoverageWarning, G2Quadratic, g2_quadratic

__version__ = "0.1.0"
