"""Compatibility names of the version-1 layout (one features.py). Documents saved
by it refer to ``freecad.elastica.features.<Class>`` for their proxies and view
providers, and recorded macros call ``features.make_fit(...)`` etc.: those names
stay here as aliases of the modules that now hold them (one module per feature,
sources.py, geometry.py, viewproviders.py). New code imports those modules."""
from .blend import BlendProxy, blend_core, make as make_blend, nearest_ends
from .comb import CombProxy, comb_core, make as make_comb
from .ellblend import (EllipticBlendProxy, K_CONVENTIONS, MODES as ELLBLEND_MODES,
                       ellblend_core, make as make_ellblend)
from .fit import FitProxy, make as make_fit
from .fit_core import fit_core
from .geometry import (curve_bspline, link_edge, part_bspline, placement_from_frame, to_3d,
                       to_plane, write_to_sketch)
from .links import sketch_geo_of_edge
from .proxy import InputProblem
from .sources import gather_points, gather_vertices
from .viewproviders import ViewProvider

__all__ = ["BlendProxy", "blend_core", "make_blend", "nearest_ends", "CombProxy", "comb_core",
           "make_comb", "EllipticBlendProxy", "K_CONVENTIONS", "ELLBLEND_MODES", "ellblend_core",
           "make_ellblend", "FitProxy", "fit_core", "make_fit", "curve_bspline", "link_edge",
           "part_bspline", "placement_from_frame", "sketch_geo_of_edge", "to_3d", "to_plane",
           "write_to_sketch", "InputProblem", "gather_points", "gather_vertices", "ViewProvider"]
