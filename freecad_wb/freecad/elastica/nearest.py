"""The points' nearest points on a fit's drawn B-spline: the binding's
(libelastica.nearest), loaded on first use as the rest of the binding."""
from __future__ import annotations

from .geometry import el


def drawn_distances(bspline, data, t0):
    el()
    from libelastica.nearest import drawn_distances as f
    return f(bspline, data, t0)


def nearest_on(bspline, data, seeds=256):
    el()
    from libelastica.nearest import nearest_on as f
    return f(bspline, data, seeds)
