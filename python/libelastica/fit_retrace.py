"""el.fit's back-and-forth gate: points in order along a curve that run back over it (a scan
passed back and forth, QA20 F4) are fitted again in curve order where the fit in their order
shows it (its feet run back, it did not converge, or it lies far above the points' noise:
the misfit verdict), and that fit is kept where its feet run back or forth and its rms is
lower. Only :func:`libelastica.fit.fit`'s gate, for the user's own fits: a fit made only to
judge or compare (fit_keyline's one-elastica check, the misfit corner's parts) fits the
points as given (:func:`libelastica.fit.judging_fit`).
"""
from __future__ import annotations

import numpy as np

from ._ffi import dptr, ffi, lib
from ._interrupt import call
from .misfit import _Figures, _verdict
from .order import curve_order, run_back

# el_fit_options.distance's codes (fit.py's _DISTANCES)
_ORTHOGONAL = 1


def retrace_gate(model: str, pts: np.ndarray, o, res, st: int, dist: np.ndarray, foot: np.ndarray, s,
                 fig: _Figures):
    """The gate on fit ``res`` (status ``st``, distances ``dist``, feet ``foot``, smooth arc
    lengths ``s``) of ``pts`` in their order by options ``o``, the points' noise figures
    ``fig``: (res, st, dist, foot, s, back, given_rms, tried, flip), those of the fit in
    curve order where it is kept (given_rms: the fit in the points' order's rms; flip: a
    smooth curve to be run from point 0's end), else the fit's own with back (its feet's
    run back, :func:`run_back`, or None), given_rms None and tried the rms in curve order
    (None where not fitted)."""
    given_rms, tried, flip = None, None, False
    back = run_back(pts, foot, res.rms) if res.wander_gap < 0 else None
    far_back = run_back(pts, foot, res.rms, near=False) if back is None and res.wander_gap < 0 else None
    if (back is not None or st != lib.EL_OK or _verdict(fig, dist, float(res.rms), False) is not None
            or far_back is not None):
        retraced = _retraced(model, pts, o, float(res.rms))
        tried = retraced[-1]
        # feet that run back, the turn's first point a point or two past it (near=False), of a
        # fit in the points' order as near as curve order's: said as a run back with curve
        # order's rms (the discrete fit tied to a retraced end's extremes, fit_ends.c, reaches
        # the far end of a scan passed back over a third as curve order's does, 0.38608 both)
        if retraced[0] is None and back is None and tried is not None:
            back = far_back
        if retraced[0] is not None:   # a scan passed back and forth: fitted in curve order
            given_rms = float(res.rms)
            res, st, dist, foot, back, _ = retraced
            smooth = model == "smooth"
            flip = smooth and foot[0] > 0.5 * res.params.length   # run from point 0's end
            if flip:
                length = float(res.params.length)
                dist, foot = -dist, length - foot
                back = back._replace(s_first=length - back.s_first, s_last=length - back.s_last)
            s = foot.copy() if smooth else None
    return res, st, dist, foot, s, back, given_rms, tried, flip


def _retraced(model: str, pts: np.ndarray, o, rms: float):
    """The fit of points in order along a curve that run back over it (a scan passed back and
    forth, QA20: 300 points out and 300 back, noise 0.4, fitted by distance in their order a
    2936-long curve for 1500, looping back up to 454 from every point, rms 2.93; the discrete
    model 2562 long, rms 37.4, not converged): fitted in curve order (:func:`curve_order`,
    as order="curve" fits them; by distance, ``o``: the fit's options), where its feet, in
    the points' order, run back or forth (:func:`run_back`; curve order may start at the far end) and its rms (of the
    distances of the same points) is below ``rms``, the fit in their order's. Returns (res,
    status, distances, feet, Retrace, rms) with distances and feet in the points' order, or
    (None, ..., None, rms in curve order or None where not fitted)."""
    n = len(pts)
    idx = curve_order(pts)
    q = np.ascontiguousarray(pts[idx])
    res = ffi.new(f"el_fit_{model}_result *")
    dist, foot = np.empty(n), np.empty(n)
    was, o.distance = o.distance, _ORTHOGONAL
    try:
        st = call(lib.el_fit_smooth if model == "smooth" else lib.el_fit_discrete, dptr(q), n, o,
                  ffi.NULL, res, dptr(dist), dptr(foot), keep=(q, dist, foot))
    finally:
        o.distance = was
    if st not in (lib.EL_OK, lib.EL_ENOCONV, lib.EL_EMAXITER):
        return None, None, None, None, None, None
    back = None
    if res.wander_gap < 0 and res.rms < rms:
        inv = np.empty(n, dtype=np.intp)
        inv[idx] = np.arange(n)
        dist, foot = dist[inv], foot[inv]
        back = run_back(pts, foot, float(res.rms), near=False)
        if back is None:    # curve order may run from the other end: the feet from there
            p = res.params
            length = p.length if model == "smooth" else p.h * (n - 1)
            b = run_back(pts, length - foot, float(res.rms), near=False)
            back = b if b is None else b._replace(s_first=float(foot[b.first]),
                                                  s_last=float(foot[b.last]))
    if back is None:
        return None, None, None, None, None, float(res.rms)
    return res, st, dist, foot, back, float(res.rms)
