"""el.fit's one crossing into C: libelastica/binding.h's el_binding_fit (not public) checks
the points as el.fit's plain path does (finite, the first four apart: require_distinct's
rounding test), screens their order (order.py's el_order_screen), fits, and computes the
noise figure and the distances' median and maximum el.fit's later tests ask (misfit.py's
_Figures.quick, far_points' outlier test), where the plain path crosses into C for each
and runs numpy over the arrays (bench_fit.py's worker, 1000 points after scipy's fit:
~0.3 ms of el.fit's ~1.3, cold caches). Every answer is the plain path's own: where a check
refuses, or the binding was read without binding.h (an installed elastica.h) or the library
lacks the entry or was built from another binding.h (:func:`_entry`), :func:`one_call`
answers None and el.fit takes the plain path, which says why; figures the entry could not compute (NaN) are left to the plain code."""
from __future__ import annotations

import math

import numpy as np

from ._ffi import BINDING_DIGEST, dptr, ffi, lib
from ._interrupt import call
from .fit_input import ROUNDING_ULPS
from .misfit import _Figures
from .order import _screen_step, ordering


def _entry(lib, digest):
    """lib's el_binding_fit where the library was built from the binding.h the binding read
    (its el_binding_digest is that header's ``digest``), else None: not declared (no
    binding.h), not in the library (an older one), or another binding.h's (an older or
    newer library: called with these declarations it would read its arguments otherwise,
    memory corruption, where the plain path is right with any library of this elastica.h)."""
    try:
        fn, built = lib.el_binding_fit, lib.el_binding_digest()
    except AttributeError:
        return None
    return fn if digest is not None and built == digest else None


_ONE_CALL = _entry(lib, BINDING_DIGEST)


def one_call(pts: np.ndarray, model: str, options):
    """el.fit's checks, order screen and fit of points ``pts`` (as_point_array's) in one call:
    ``(pts, n, unordered, fig, o, res, status, distances, foot_s, screened)`` (screened: the
    median and maximum of |distances| and the array they are of, for :func:`libelastica.misfit._fit_outliers`),
    or None for the plain path. ``options(n)``: the fit's el_fit_options (fit._options,
    no initial curve, no constraints); an error there is the plain path's to raise."""
    if _ONE_CALL is None or pts.ndim != 2 or pts.shape[1] != 2 or len(pts) < 4:
        return None
    n = len(pts)
    try:
        o = options(n)
    except (TypeError, AttributeError, ValueError):
        return None
    step = _screen_step(n)                                       # (order.ordering's screen)
    res = ffi.new(f"el_fit_{model}_result *")
    dist, foot = np.empty(n), np.empty(n)
    sc, figures = ffi.new("el_order_screen_result *"), ffi.new("double[3]")
    discrete = model == "discrete"
    st = call(_ONE_CALL, dptr(pts), n, o, res if discrete else ffi.NULL, ffi.NULL if discrete else res,
              dptr(dist), dptr(foot), float(ROUNDING_ULPS), step, step > 1, sc, figures,
              keep=(pts, dist, foot))
    if st < 0:
        return None
    fig = _Figures(pts)
    if not math.isnan(figures[0]):
        fig._quick = figures[0]
    return (pts, n, ordering(pts, screened=sc), fig, o, res, st, dist, foot,
            (figures[1], figures[2], dist))
