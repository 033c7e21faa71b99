"""The points' nearest points on a fit's drawn B-spline: the binding's
(libelastica.nearest), loaded on first use as the rest of the binding."""
from __future__ import annotations

from .geometry import binding_module


def drawn_distances(bspline, data, t0):
    return binding_module("nearest").drawn_distances(bspline, data, t0)


def nearest_on(bspline, data, seeds=256):
    return binding_module("nearest").nearest_on(bspline, data, seeds)
