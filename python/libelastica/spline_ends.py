"""The ends of an elastic spline (elastic_spline's start / end): their conditions filled in
(natural, clamped, G2) and what is said of G2 ends where no spline is reached; the units
the solver works in (the mean chord), which a tension or a G2 end's curvature must fit."""
from __future__ import annotations

import numpy as np

from ._ffi import lib


def _end(spec, name: str, opt_end) -> None:
    """Fill an el_spline_end from None (natural), a tangent 2-vector or
    {"tangent": (tx, ty), "curvature": kappa} (G2)."""
    if spec is None:
        opt_end.kind = lib.EL_SPLINE_NATURAL
        return
    curvature = None
    if isinstance(spec, dict):
        unknown = set(spec) - {"tangent", "curvature"}
        if unknown or "tangent" not in spec:
            raise ValueError(f"elastic_spline: {name} must be None, a tangent (tx, ty) or "
                             f"{{'tangent': (tx, ty), 'curvature': k}}, got {spec!r}")
        tangent, curvature = spec["tangent"], spec.get("curvature")
    else:
        tangent = spec
    t = np.asarray(tangent, dtype=np.float64)
    if t.shape != (2,) or not np.all(np.isfinite(t)) or not np.hypot(*t) > 0.0:
        raise ValueError(f"elastic_spline: {name} tangent must be a nonzero finite 2-vector, "
                         f"got {tangent!r}")
    opt_end.tangent = [float(t[0]), float(t[1])]
    if curvature is None:
        opt_end.kind = lib.EL_SPLINE_TANGENT
        return
    if not np.isfinite(float(curvature)):
        raise ValueError(f"elastic_spline: {name} curvature must be finite, got {curvature!r}")
    opt_end.kind = lib.EL_SPLINE_G2
    opt_end.curvature = float(curvature)


def _g2_end_text(opt, chords) -> str:
    """Where no spline was reached: the G2 ends given (curvature, its radius, the end span's
    chord), as a likely cause, not a proven one (QA24 F12: end curvature 50, radius 0.02, at
    a span 10.4 long, was said as "no spline through the points was reached" alone)."""
    said = []
    for name, e, chord in (("start", opt.start, chords[0]), ("end", opt.end, chords[-1])):
        if e.kind != lib.EL_SPLINE_G2:
            continue
        k = float(e.curvature)
        r = f"radius {1 / abs(k):.3g}, " if k != 0.0 else ""
        said.append(f"the {name}'s G2 condition, curvature {k:.3g} ({r}its span {chord:.3g} "
                    f"long{f': {abs(k) * chord:.3g} x its radius' if abs(k) * chord > 1 else ''})")
    if not said:
        return ""
    return ("; " + " and ".join(said) + " may be what no spline through the points meets: "
            "try the same tangent alone (clamped) or a smaller curvature")


# el_spline_solve's units (spline.c's UNITS): the mean chord S in [1e-150, 1e150], sigma S^2,
# length / S and a G2 end's |curvature| S at most 1e150
UNITS_MAX = 1e150


def _units_problem(S, opt, closed, pts, chords):
    """What of the mean chord S of the points ``pts`` (their ``chords``) and the options opt
    (el_spline_options) the spline's units cannot represent (EL_EDOM before any search), as
    text; None where all is within. The points' scale is the mean chord's range, the one
    bound on it (points at 1e+-149 solve, coordinates and chords far past the pieces'
    Hermite 1e+-100), named with their chords and coordinates."""
    if not 1.0 / UNITS_MAX <= S <= UNITS_MAX:
        return (f"the points' mean chord {S:.4g} (chords from {chords.min():.3g} to "
                f"{chords.max():.3g}, coordinates up to {np.abs(pts).max():.3g}) is outside "
                "[1e-150, 1e150], the scales the solver represents: rescale the points (and "
                "tension, curvatures)")
    if opt.mode == lib.EL_SPLINE_TENSION and not opt.sigma * S * S <= UNITS_MAX:
        return (f"tension {opt.sigma:.4g} x (mean chord {S:.4g})^2 exceeds 1e150: no batten "
                "the solver represents is pulled so hard")
    if opt.mode == lib.EL_SPLINE_LENGTH and not opt.length / S <= UNITS_MAX:
        return (f"length {opt.length:.4g} / (mean chord {S:.4g}) exceeds 1e150: no batten the "
                "solver represents is so long against its chords")
    for name, e in (() if closed else (("start", opt.start), ("end", opt.end))):
        if e.kind == lib.EL_SPLINE_G2 and not abs(e.curvature) * S <= UNITS_MAX:
            return (f"the {name} curvature {e.curvature:.4g} x (mean chord {S:.4g}) exceeds "
                    "1e150: no batten the solver represents bends so sharply")
    return None
