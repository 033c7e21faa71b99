"""Fit elastica: an elastica, or a keyline as one G2 curve of two elasticae meeting at
its inflection, fitted to sketch edges / vertices, a Points object, a wire or 3D
polyline (plane fit) or a CSV file, with optional end conditions (pinned ends, end
tangents from picked edges, end curvatures). Its shape is ONE B-spline of the fitted
curve; it keeps the fitted points, their point-to-curve distances and their feet on
the curve, which the view provider draws as markers and residual segments."""
from __future__ import annotations

import dataclasses
import json
import math
from warnings import catch_warnings, simplefilter

import FreeCAD as App
import Part

from . import defaults
from .geometry import (chain_bspline, el, np, part_bspline, polyline_length,
                       plane_coordinates, plane_curvature, to_3d, to_plane)
from .links import followed_edge, followed_reader
from .proxy import (FeatureProxy, InputProblem, add_enum, add_geometry_index, add_length,
                    add_link, add_property, check_degree, check_number, check_tolerance,
                    new_feature, read_only)
from .nearest import drawn_distances, nearest_on
from .sources import curve_order, file_order, gather_points

MIN_POINTS = 6          # fewer points cannot determine the 7 (5 shape) parameters of a fit
MODELS = ["discrete", "smooth"]
MODEL_NAMES = {"discrete": "Discrete elastica (Bobenko-Suris)", "smooth": "Smooth elastica"}
DISTANCES = ["orthogonal", "paired"]
DISTANCE_NAMES = {"orthogonal": "Point to curve", "paired": "Paired (equilateral data)"}
# the library's constraint names -> the fields that set them (messages name the field)
CONSTRAINT_FIELDS = {"start_point": "Pin start", "end_point": "Pin end",
                     "start_tangent": "Start tangent", "end_tangent": "End tangent",
                     "start_curvature": "Start curvature", "end_curvature": "End curvature"}
# How an end meets its tangent edge: its tangent only, or joined to the edge's end (the
# CAD sense: G1 = the point and the tangent, G2 = the curvature too)
CONTINUITIES = ["tangent", "G1", "G2"]
CONTINUITY_NAMES = {"tangent": "Tangent only", "G1": "G1", "G2": "G2"}


def _status_text(r):
    st = int(getattr(r, "status", 0))
    if st == 0:
        return "converged"
    from libelastica._ffi import ffi, lib
    return "not converged (best curve kept): " + ffi.string(lib.el_strerror(st)).decode()


def tangent_angle(edge, at, forward, plane):
    """(angle, at_end): the angle in ``plane`` of ``edge``'s tangent at its end nearest
    to ``at`` (projected into the plane), signed so it points along ``forward`` (a plane
    vector), and whether that end is the edge's last."""
    n = np()
    a, b = edge.FirstParameter, edge.LastParameter
    at_end = (edge.valueAt(a) - at).Length > (edge.valueAt(b) - at).Length
    t = plane.Rotation.inverted().multVec(App.Vector(edge.tangentAt(b if at_end else a)))
    if math.hypot(t.x, t.y) < 1e-9 * max(t.Length, 1e-300):
        raise InputProblem("the tangent edge is perpendicular to the fit plane")
    if t.x * forward[0] + t.y * forward[1] < 0:
        t = -t
    return float(n.arctan2(t.y, t.x)), at_end


def end_constraints(xy, plane, pin_start=False, pin_end=False, start_edge=None, end_edge=None,
                    start_curvature=None, end_curvature=None, start_join="tangent",
                    end_join="tangent", tol=1e-3):
    """el.fit's constraints for plane points xy (in their order): pinned ends at the
    first / last point, tangents of Part edges at their ends nearest those points
    (the direction of travel), curvatures (1/mm, + turning left seen from the plane's
    normal, 0 = a free end or an inflection). ``start_join`` / ``end_join`` (CONTINUITIES):
    how that end meets its edge: its tangent only, or joined to the edge's end (G1: its
    point, in the fit plane, and tangent; G2: its curvature there too, signed by the
    direction of travel); the edge's end may lie off the fit plane by up to ``tol`` (mm,
    the B-spline's tolerance: a plane fitted to scanned points is not the sketch's).
    Returns (constraints, warnings: a join whose edge leaves its joined end back towards
    the points, which the curve meets only by turning back)."""
    c, warnings = {}, []
    if pin_start:
        c["start_point"] = (float(xy[0][0]), float(xy[0][1]))
    if pin_end:
        c["end_point"] = (float(xy[-1][0]), float(xy[-1][1]))
    for name, value in (("start_curvature", start_curvature), ("end_curvature", end_curvature)):
        if value is not None:
            c[name] = check_number(CONSTRAINT_FIELDS[name], value, unit="1/mm")
    extent = float(np().ptp(xy, axis=0).max())
    # the direction of travel near each end: over an eighth of the points (noise-proof)
    m = max(1, len(xy) // 8)
    for where, edge, join, i, forward in (("start", start_edge, start_join, 0, xy[m] - xy[0]),
                                          ("end", end_edge, end_join, -1, xy[-1] - xy[-1 - m])):
        End = where.capitalize()
        if join not in CONTINUITIES:
            raise InputProblem(f"{End}Continuity = {join!r}: one of {', '.join(CONTINUITIES)}")
        if join != "tangent" and edge is None:
            raise InputProblem(f"{End} join {join} joins the {where} tangent's edge: pick one "
                               f"({End} tangent), or set Tangent only")
        if join != "tangent" and f"{where}_point" in c:
            raise InputProblem(f"Pin {where} and {where} join {join} both set the {where} point: "
                               f"clear Pin {where} (the join starts at the edge's end)")
        if join == "G2" and f"{where}_curvature" in c:
            raise InputProblem(f"{End} curvature and {where} join G2 both set the curvature "
                               f"there: clear {End} curvature (G2 takes the edge's)")
        if edge is None:
            continue
        at = plane.multVec(App.Vector(float(xy[i][0]), float(xy[i][1]), 0.0))
        angle, at_end = tangent_angle(edge, at, forward, plane)
        c[f"{where}_tangent"] = angle
        if join == "tangent":
            continue
        u = edge.LastParameter if at_end else edge.FirstParameter
        p = plane.inverse().multVec(edge.valueAt(u))
        if abs(p.z) > max(tol, 1e-7 + 1e-9 * extent):   # 1e-7 mm: FreeCAD's Confusion
            raise InputProblem(f"the {where} edge's end lies {abs(p.z):.3g} mm off the fit plane, "
                               f"more than the Tolerance {tol:g} mm: no {join} join in it "
                               "(Tangent only follows its direction)")
        c[f"{where}_point"] = (float(p.x), float(p.y))
        # the edge from its joined end, in the plane: a continuation of the curve at its end,
        # behind it at its start; else the curve turns back into it (a cusp), and a fit meets
        # that by looping (QA: a G2 end join on an arc leaving back over its points, a fit
        # looping 130 mm above points 20 mm high, status converged)
        into = plane.Rotation.inverted().multVec(App.Vector(edge.tangentAt(u)) * (-1 if at_end else 1))
        ahead = into.x * forward[0] + into.y * forward[1]
        if ahead < 0 if where == "end" else ahead > 0:
            # the joined end is the edge's nearer the points' own end: an edge nearer their
            # other end is the other end's (QA: 'join the edge's other end' was no way out)
            other = "end" if where == "start" else "start"
            near = math.hypot(p.x - xy[-1 - i][0], p.y - xy[-1 - i][1]) < \
                math.hypot(p.x - xy[i][0], p.y - xy[i][1])
            way_out = (f"it lies nearer the points' {other}: pick it as {other.capitalize()} "
                       "tangent" if near else "pick an edge that the points continue" if
                       where == "start" else "pick an edge that continues the points")
            warnings.append(f"{End} join {join}: the edge leaves its joined end back along the "
                            f"points, so the curve turns back into it (a cusp) and loops to do "
                            f"so: {way_out}, or set Tangent only")
        if join == "G2":
            c[f"{where}_curvature"] = plane_curvature(
                edge, at_end, (math.cos(angle), math.sin(angle)), plane, f"the {where} edge")
    return c, warnings


def constraint_fields(start_join="tangent", end_join="tangent"):
    """The field each library constraint comes from: a G1 / G2 join's point, tangent and
    (G2) curvature are the join's."""
    fields = dict(CONSTRAINT_FIELDS)
    for where, join in (("start", start_join), ("end", end_join)):
        if join in ("G1", "G2"):
            for what in ("point", "tangent") + (("curvature",) if join == "G2" else ()):
                fields[f"{where}_{what}"] = f"{where.capitalize()} join {join}"
    return fields


def _constraint_problem(exc, fields=CONSTRAINT_FIELDS):
    """InputProblem naming the field of a constraint the library could not meet."""
    field = fields.get(exc.constraint, exc.constraint or "a constraint")
    why = str(exc).replace("fit: ", "", 1)
    return InputProblem(f"{field} cannot be met: {why}; free it or change it")


def _fit(xy, **options):
    """el.fit without its warnings (the binding's quiet_fit): the feature says them in its own
    words (_wanders, its Status)."""
    el()
    from libelastica.fit import quiet_fit
    return quiet_fit(xy, **options)


def _wanders(result, plane):
    """The warning for a fit in one piece that wanders away from its points between two of
    them (FitResult.wander_gap: it loops, strays, swings or passes them out of order, their
    distances small all the same), naming their places (the fit's order of the points is not
    the user's: no numbers), else none."""
    if result.wander_gap < 0:
        return []
    at = [plane.multVec(App.Vector(float(x), float(y), 0.0)) for x, y in result.points]
    said = el().wander_summary(result.wander_gap, [(v.x, v.y, v.z) for v in at], " mm",
                               numbered=False)
    return [f"{said}: add a point between them to hold the curve there"]


def _one_piece(xy, model, distance, fixed, constraints, fields):
    """The fit of points xy in one piece: (curves, results, data, feet, signed distances,
    rms, max error, None) as the library reports them; fields: constraint_fields."""
    try:
        r = _fit(xy, model=model, fixed=fixed or None, constraints=constraints or None,
                 distance=distance if model == "smooth" else None)
    except el().ConstraintError as exc:
        raise _constraint_problem(exc, fields) from None
    return [r.curve], [r], xy, r.foot_points(), r.distances, r.rms, r.max_error, None


# End conditions that raise the rms above COST_RATIO times the free-ended fit's (and by
# more than COST_FLOOR of the data's extent) are worth a warning: a curvature or a
# tangent far from the data's own is met by a curl or a swing that fits nothing (a
# smooth fit of the noisy 330 mm sample S meets 0.05/mm, four times its own end
# curvature, with rms 9 mm against 0.29 mm free).
COST_RATIO, COST_FLOOR = 2.0, 1e-4
# A curve shorter than COLLAPSED times the points' extent fits none of them: end conditions
# met nowhere near the points shrink a fit to nothing (QA: a start join on a wire drawn
# from its other end, 4e-12 mm long for 90 mm of points, rms 53 mm, kept as 'not
# converged' with no error mark, a shape the 3D view cannot mesh, drawing the last one)
COLLAPSED = 1e-3


def _constraint_cost(xy, model, distance, fixed, constraints, rms, fields):
    """(rms of the same fit with free ends, or -1 when it fails; the warnings; the points'
    distances to that fit, or None); fields: constraint_fields. A discrete fit's distances
    are its drawn cubic's (drawn_distances)."""
    try:
        r = _fit(xy, model=model, fixed=fixed or None,
                 distance=distance if model == "smooth" else None)
        dist = r.distances if model == "smooth" else \
            drawn_distances(r.to_bspline(), xy, r.foot_s)[1]
        free = r.rms if model == "smooth" else _rms(dist)
    except (ValueError, ArithmeticError, RuntimeError):
        return -1.0, [], None
    extent = float(np().ptp(xy, axis=0).max())
    if not (rms > COST_RATIO * free and rms - free > COST_FLOOR * extent):
        return float(free), [], dist
    return float(free), [f"the end conditions ({_named(constraints, fields)}) raise the rms "
                         f"from {free:.3g} mm (free ends) to {rms:.3g} mm: check that they match "
                         "the data"], dist


def _named(constraints, fields):
    """The fields that set ``constraints`` (constraint_fields), each once, in the panel's order."""
    return ", ".join(dict.fromkeys(fields[c] for c in CONSTRAINT_FIELDS if c in constraints))


def _check_length(bspline, extent, constraints, fields, reversed_joins):
    """Raise InputProblem for a fitted curve shorter than COLLAPSED times the points'
    extent (mm), naming the end conditions it gave way to."""
    n = np()
    length = polyline_length(bspline.evaluate(n.linspace(*bspline.domain, 65)))
    if length > COLLAPSED * extent:
        return
    why = (f"the end conditions ({_named(constraints, fields)}) cannot be met along the points"
           if constraints else "check the points")
    raise InputProblem(f"the fit shrank to a curve {length:.2g} mm long, for points "
                       f"{extent:.4g} mm across: {why}" +
                       "".join(f". {w}" for w in reversed_joins[:1]))


def _rms(dist):
    return float(np().sqrt(np().mean(np().square(dist))))


def _beyond_the_ends(bspline, feet, dist, extent):
    """Which points lie beyond the curve's ends (their nearest point on it an end, farther
    than COST_FLOOR of their extent and COST_RATIO times the others' rms): those a
    resampled polygon leaves out. An
    equilateral polygon ends where no point lies a step further on (seed 000 §5.3), so up
    to a step of the points' run is not fitted, and the curve stops there too."""
    n = np()
    ends = bspline.evaluate(n.array(bspline.domain))
    at_end = n.min(n.linalg.norm(feet[:, None, :] - ends[None, :, :], axis=2), axis=1) \
        <= 1e-9 * (1.0 + extent)
    others = _rms(dist[~at_end]) if not at_end.all() else 0.0
    return at_end & (n.abs(dist) > max(COST_FLOOR * extent, COST_RATIO * others))


def _left_out(beyond, dist, step, used=None):
    """The warning for points a resampled fit left out (_beyond_the_ends), else none.
    ``used``: the step of a split keyline's polygon (its default where step is 0: a
    keyline is always resampled, so 0 leaves nothing out only in one piece)."""
    if not beyond.any():
        return []
    d = np().abs(dist[beyond])
    m = int(beyond.sum())
    verb = "lies" if m == 1 else "lie"
    if used is None:
        setting, way_out = f"Resample = {step:g} mm", "a shorter step leaves less out, 0 none"
    else:
        setting = (f"Resample = {step:g} mm" if step else
                   f"Resample = 0 takes {_default_step_name(used)}")
        way_out = "a shorter step leaves less out"
    return [f"{m} of {len(dist)} points {verb} beyond the curve's ends, up to "
            f"{float(d.max()):.3g} mm from it: the resampled polygon ({setting}) "
            "stops where no point lies a step further on, and the curve with it; Rms and "
            f"MaxError include them: {way_out}"]


def _off_plane(off, rms, extent):
    """The warning for points whose distances from their plane (``off``, mm) outweigh the
    fit's in-plane rms (and above COST_FLOOR of their extent): a plane curve cannot come
    closer to them than that, else none."""
    n = np()
    off_rms = _rms(off)
    if not (off_rms > rms and off_rms > COST_FLOOR * extent):
        return []
    return [f"the points lie up to {float(n.abs(off).max()):.3g} mm (rms {off_rms:.3g} mm) off "
            f"their plane, the fit's: Rms and MaxError include that (in the plane the curve lies "
            f"{rms:.3g} mm from them, rms); a plane curve comes no closer"]


def _foot_parameters(results, split, tails=None):
    """The data points' parameters on a discrete fit's cubic from their polygon feet: the
    arc length of each foot (a keyline's first half reversed, from the first point, then the
    second's after the joint vertex; after its ``tails``' lead, _keyline)."""
    if not split:
        return results[0].foot_s
    n = np()
    first, second = results
    joint = polyline_length(first.curve.points()) + (0.0 if tails is None else tails[1])
    return n.concatenate([joint - first.foot_s[::-1], joint + second.foot_s[1:]])


def _step_advice(length):
    """What a resampling step of points whose polyline is length long must be below, and
    the way out."""
    return (f"the points' polyline is {length:.4g} mm long, so {MIN_POINTS} points need a step "
            f"under {length / (MIN_POINTS - 1):.4g} mm; 0 fits the points as they are")


def _check_reach(xy, step, starts, default=None):
    """Refuse, in the panel's terms, a resampling step longer than any point lies from
    the polygon's start (the library's rule: no second vertex). starts: the indices the
    start may be (one piece: the end of smaller x; a keyline: either end, its own
    frame decides); ``default``: a split keyline's default step (_keyline_step), the
    one checked where step is 0."""
    n = np()
    reach = max(float(n.max(n.hypot(xy[:, 0] - xy[i, 0], xy[:, 1] - xy[i, 1]))) for i in starts)
    used = default if default is not None and not step > 0 else step
    if not used > reach:
        return
    beyond = (f"longer than the points reach (all within {reach:.4g} mm of the end the "
              "polygon starts from)")
    if default is None:
        raise InputProblem(f"Resample = {step:g} mm is {beyond}: "
                           + _step_advice(polyline_length(xy)))
    if step > 0:
        zero = f", or 0 for {_default_step_name(default)}" if default <= reach else ""
        raise InputProblem(f"Resample = {step:g} mm is {beyond}: set a step under "
                           f"{reach:.4g} mm{zero}")
    raise InputProblem(f"Resample = 0 takes {_default_step_name(default)}, which is {beyond}: "
                       f"set a step under {reach:.4g} mm")


def _resampled(xy, step):
    """The points xy resampled into an equilateral polygon of segment step
    (el.resample_equilateral), at least MIN_POINTS vertices of it."""
    _check_reach(xy, step, [-1 if xy[-1, 0] < xy[0, 0] else 0])
    most, length = el().RESAMPLE_MAX_VERTICES, polyline_length(xy)
    if length / step > most - 1:
        raise InputProblem(f"Resample = {step:g} mm would cut the points' {length:.4g} mm "
                           f"polyline into {length / step:.3g} segments, more than {most - 1}: use "
                           f"a step of at least {length / (most - 1):.4g} mm, or 0 to fit the "
                           "points as they are")
    out = el().resample_equilateral(xy, step)
    if xy[-1, 0] < xy[0, 0]:
        out = out[::-1].copy()       # it starts from the end of smaller x: the user's order
    if len(out) < MIN_POINTS:
        # the vertices are step apart along the way, so few of them from a step short enough
        # for MIN_POINTS mean the walk jumped ahead: the points double back or pass close to
        # themselves within the step (seed 000 §5.3 jumps a hairpin narrower than it)
        why = (_step_advice(length) if step >= length / (MIN_POINTS - 1) else
               "the polygon jumps where the points double back or pass within the step of "
               "themselves; 0 fits the points as they are")
        raise InputProblem(f"Resample = {step:g} mm leaves {len(out)} points; a fit needs "
                           f"{MIN_POINTS}: {why}")
    return out


def _apart(p, q):
    """Whether points p and q differ by more than a rounding of their size."""
    return float(np().hypot(*(p - q))) > 1e-12 * (1.0 + float(np().abs(q).max()))


def _keyline_step(xy):
    """The default step of a split keyline's polygon, the binding's (el.keyline_step:
    1/KEYLINE_STEPS of the polyline through the medians of runs of the points, robust
    to their noise's zigzag); fit_keyline resamples that polyline where Resample is 0."""
    return el().keyline_step(xy)


def _default_step_name(step):
    """What the default step of a split keyline is, for messages."""
    return (f"the default step, {step:.3g} mm = 1/{el().KEYLINE_STEPS} of the points' run "
            "through their medians in runs along it")


def _keyline(xy, model, step):
    """The keyline of points xy as one G2 curve (el.fit_keyline, its polygon's step
    ``step``, None for the binding's default): its two halves as
    the library gives them (plane coordinates, each from the joint outwards, with
    opposite tangents and zero curvature there), the results, and the fitted points,
    feet and signed distances (+ = left of the travel) in the order of travel from
    the first point, each point once (the discrete joint vertex belongs to both), and a
    discrete keyline's tails: (its ends in the plane, the length its first half's
    continuation adds before it), else None. The discrete halves fit the resampled polygon,
    which stops up to a step short of the points (seed 000 §5.3): their B-spline continues
    each by its recursion to its end point's foot (KeylineFit.ends)."""
    n = np()
    with catch_warnings():                           # its Status says it
        simplefilter("ignore", el().ConvergenceWarning)
        kf = el().fit_keyline(xy, r=step, model=model)
    first, second = kf.first, kf.second
    to_plane = kf.prepared.frame2d.to_parent         # the halves live in x''y''
    skip = 1 if model == "discrete" else 0
    data = to_plane(n.vstack([first.points[::-1], second.points[skip:]]))
    feet = to_plane(n.vstack([first.foot_points()[::-1], second.foot_points()[skip:]]))
    dist = n.concatenate([-first.distances[::-1], second.distances[skip:]])
    halves = [_moved(r.curve, kf.prepared.frame2d) for r in (first, second)]
    rms = _rms(dist)
    tails = None
    if kf.ends is not None:
        lead = first.curve.continued_to(kf.ends[0])
        tails = (to_plane(kf.ends), polyline_length(n.vstack([first.curve.points()[-1:], lead])))
    return halves, [first, second], data, feet, dist, rms, float(n.abs(dist).max()), tails


def _moved(curve, frame2d):
    """The same elastica in the parent coordinates of a (proper, rotation-only)
    Frame2D: the start point mapped, the tangent angle phi turned by the frame's
    angle; nothing else changes under a rigid motion."""
    x0, y0 = frame2d.to_parent(np().array([curve.x0, curve.y0]))
    turn = math.atan2(frame2d.f1[1], frame2d.f1[0])
    return dataclasses.replace(curve, x0=float(x0), y0=float(y0), phi=float(curve.phi + turn))


def _polygon_deviation(bspline, curves, samples=32):
    """The largest distance of a discrete fit's cubic from its polygon (the vertices of
    its one or two curves, a keyline's first half reversed), sampled ``samples`` times per
    span: the cubic is parametrised by chord length, so the samples of a span lie near
    that segment (measured against its two neighbours too). What the drawn B-spline adds
    to the polygon's distances (9 sketched points: rms 0.013 mm to the polygon, 0.056 to
    the B-spline)."""
    n = np()
    V = curves[0].points() if len(curves) == 1 else n.vstack([curves[0].points()[::-1], curves[1].points()[1:]])
    c = n.concatenate([[0.0], n.cumsum(n.linalg.norm(n.diff(V, axis=0), axis=1))])
    k = n.unique(bspline.knots)
    t = n.concatenate([n.linspace(a, b, samples, endpoint=False)
                       for a, b in zip(k[:-1], k[1:])] + [k[-1:]])
    P = bspline.evaluate(t)
    j = n.clip(n.searchsorted(c, t) - 1, 0, len(V) - 2)
    best = n.full(len(t), n.inf)
    for dj in (-1, 0, 1):
        i = n.clip(j + dj, 0, len(V) - 2)
        A, D = V[i], V[i + 1] - V[i]
        u = n.clip(n.sum((P - A) * D, axis=1) / n.maximum(n.sum(D * D, axis=1), 1e-300), 0.0, 1.0)
        best = n.minimum(best, n.linalg.norm(P - (A + u[:, None] * D), axis=1))
    return float(best.max())


def _shape_bspline(model, curves, results, split, tol, degree, tails=None):
    """ONE B-spline of the fit, run from the first point to the last: smooth, the
    G2 B-spline of the elastica (a keyline: its first half reversed, then the second;
    end points, tangents and curvatures exact, so the constraints hold on it and the
    joint is G2); discrete, the C2 cubic through the vertices (a keyline's both
    halves), natural at free ends, the constrained tangent, curvature or both (G2) at
    others; ``tails``: a discrete keyline's (_keyline), to its ends."""
    if split or model == "smooth":
        return chain_bspline(curves, tol, degree, keyline=split,
                             ends=None if tails is None else tails[0])
    return results[0].to_bspline()          # the fit's end constraints on the cubic


def _coarse_polygon(xy, constraints, rms):
    """The warning for a discrete fit of fewer than el.SPARSE_POINTS points whose cubic
    lies rms from them where the smooth model's curve lies far nearer
    (el.smooth_fits_better), else none."""
    smooth = el().smooth_fits_better(xy, rms, constraints)
    if smooth is None:
        return []
    return [f"{len(xy)} points give the discrete model a polygon of {len(xy) - 1} segments, "
            f"its cubic {rms:.3g} mm from them (rms), where the smooth model's curve lies {smooth:.3g} mm "
            "from them: choose Model Smooth elastica for so few points"]


def _far_points(data, dist, plane, free=None):
    """The warning for points far from the fitted curve (el.far_points: glitches of a scan,
    points of other geometry), naming the farthest's place, else none. data: (n, 3) in the
    frame ``plane``; free: their distances to the fit with free ends (points held off only
    by the end conditions are no outliers to remove)."""
    n = np()
    far = el().far_points(dist, data, free_distances=free)
    if not len(far):
        return []
    farthest = far[n.argmax(n.abs(n.asarray(dist if free is None else free, dtype=float))[far])]
    worst = plane.multVec(App.Vector(*map(float, data[farthest])))
    return [f"{el().far_points_summary(dist, far, ' mm', free)} (the farthest at ({worst.x:.4g}, "
            f"{worst.y:.4g}, {worst.z:.4g})): outliers? Each pulls the fit towards itself: "
            "remove them to fit the rest"]


def _facing_the_edges(xy, plane, start_edge, end_edge):
    """The points in the direction whose start lies nearer the start tangent's edge and
    whose end nearer the end's: the edges say which end the user means. Points without an
    order are sorted along their principal axis, whichever way it points; a wire or a
    file drawn from the other end runs away from its start edge, which a start join then
    meets only by turning back (QA: a wire drawn right to left, its lead-in line at the
    left joined G1, fitted as a curve 4e-12 mm long, rms 53 mm). xy: plane coordinates,
    and the distance from the plane as a third column if any."""
    def dist(edge, i):
        return edge.distToShape(Part.Vertex(plane.multVec(App.Vector(*map(float, xy[i])))))[0]

    votes = [dist(e, -1) - dist(e, 0) if w == "start" else dist(e, 0) - dist(e, -1)
             for w, e in (("start", start_edge), ("end", end_edge)) if e is not None]
    return xy[::-1].copy() if votes and sum(v < 0 for v in votes) > len(votes) / 2 else xy


def fit_core(points, plane=None, ordered=True, closed=False, model="discrete", split=False,
             distance="orthogonal", pin_start=False, pin_end=False, start_edge=None,
             end_edge=None, start_curvature=None, end_curvature=None, start_join="tangent",
             end_join="tangent", step=0.0, tol=1e-3, degree=3):
    """Fit elastica(e) to 3D points: in their order (``ordered``), in curve_order's (False)
    or a file's, kept when a curve's (None: file_order). ``distance``: what the smooth one-piece fit
    minimises ("orthogonal": point to curve; "paired": point i at arc length
    i L/(n-1), for equilateral data). ``start_edge`` / ``end_edge``: Part edges whose
    tangents the curve's ends follow; ``start_curvature`` / ``end_curvature``: 1/mm
    or None (free); ``start_join`` / ``end_join``: how that end meets its edge
    (end_constraints). Returns a dict: 'curves' (plane coordinates; a keyline's two
    halves, each from the joint), 'results', 'bspline', 'placement', 'data' (the
    user's points, (n, 3) in the frame of the plane: never a resampled polygon), 'feet'
    (their nearest points on the curve), 'distances' (signed, + = left; in 3D),
    'measure', 'rms', 'max_error' (point to curve: the library's figures for points it
    fitted as they are and in its plane, else measured on the curve drawn), 'k',
    'end_curvatures' (the shape's at its first and last point, 1/mm, + turning left),
    'status', 'free_rms' (the same fit with free ends; -1 without end conditions or when
    that fit fails) and 'warnings' (end conditions
    that cost accuracy; a discrete fit of few points whose polygon the smooth model's
    curve beats).
    Raises InputProblem with a user message."""
    n = np()
    if model not in MODELS:
        raise InputProblem(f"unknown model {model!r} (discrete or smooth)")
    if distance not in DISTANCES:
        raise InputProblem(f"unknown distance {distance!r} (orthogonal or paired)")
    if closed:
        raise InputProblem("the input is a closed curve: an elastica fit needs an open one")
    if len(points) < MIN_POINTS:
        raise InputProblem(f"{len(points)} point{'s' if len(points) != 1 else ''}: a fit needs "
                           f"at least {MIN_POINTS}")
    step = check_number("Resampling step", step, 0.0, None, "mm")
    tol = check_tolerance(tol)
    if model == "smooth":
        degree = check_degree(degree)
    ends = dict(pin_start=pin_start, pin_end=pin_end, start_edge=start_edge, end_edge=end_edge,
                start_curvature=start_curvature, end_curvature=end_curvature,
                start_join=start_join, end_join=end_join)
    fields = constraint_fields(start_join, end_join)
    joins = [f"{w} join {j}" for w, j in (("Start", start_join), ("End", end_join))
             if j != "tangent"]
    if start_join == end_join == "G2" and not split:
        raise InputProblem("G2 joins at both ends are 8 conditions on the 7 parameters of one "
                           "elastica (met together only by one elastica's own ends): set one "
                           "join G1 or Tangent only; for a batten through the points joining "
                           "both edges G2, use Elastic spline (G2 to edge at both ends)")
    if split:
        given = dict(start_point=pin_start, end_point=pin_end, start_tangent=start_edge,
                     end_tangent=end_edge, start_curvature=start_curvature,
                     end_curvature=end_curvature)
        chosen = [CONSTRAINT_FIELDS[k] for k, v in given.items()
                  if v is not None and v is not False] + joins
        if chosen:
            raise InputProblem(f"{', '.join(chosen)}: a split keyline is one G2 curve fitted "
                               "with free ends (the library's keyline fit takes no end "
                               "conditions); clear them or fit in one piece")
        if model == "smooth" and distance == "paired":
            raise InputProblem("a smooth keyline is fitted by point-to-curve distance: set "
                               "Distance to point to curve, or fit in one piece")
    try:
        xy, plane = plane_coordinates(points, plane, flat=None)
        # the user's points in the fit's frame: plane coordinates and distance from the plane
        user = n.column_stack([xy, to_plane(plane, points)[:, 2]])
        order, ordering = file_order(xy) if ordered is None else \
            (None if ordered else curve_order(xy), [])
        user = _facing_the_edges(user if order is None else user[order], plane, start_edge,
                                 end_edge)
        xy = n.ascontiguousarray(user[:, :2])
        constraints, free_rms, warnings, used, reversed_joins = {}, -1.0, [], None, []
        free_dist = None
        if split:
            default = _keyline_step(xy)
            _check_reach(xy, step, [0, -1], default)
            used = step if step > 0 else default
            fitted = _keyline(xy, model, step if step > 0 else None)   # None: the default
        else:
            fixed = {}
            if step > 0:
                polygon = _resampled(xy, step)
                # a pinned end is the user's point, which the polygon stops short of by up
                # to a step: the data runs on to it, no longer equilateral there
                pins = [pin_start and _apart(polygon[0], xy[0]),
                        pin_end and _apart(polygon[-1], xy[-1])]
                xy = n.vstack([xy[:1]] * pins[0] + [polygon] + [xy[-1:]] * pins[1])
                if model == "discrete" and not any(pins):
                    fixed["h"] = step            # the polygon's segment (seed 000 §5.4)
            constraints, reversed_joins = end_constraints(xy, plane, tol=tol, **ends)
            try:
                fitted = _one_piece(xy, model, distance, fixed, constraints, fields)
            except InputProblem as exc:
                if not reversed_joins:
                    raise
                raise InputProblem(f"{exc}. {reversed_joins[0]}") from None
        curves, results, data, feet, dist, rms, max_error, tails = fitted
        bspline = _shape_bspline(model, curves, results, split, tol, degree, tails)
        _check_length(bspline, float(n.ptp(xy, axis=0).max()), constraints, fields,
                      reversed_joins)
        if model == "discrete":
            feet, dist = drawn_distances(bspline, data, _foot_parameters(results, split, tails))
            rms, max_error = _rms(dist), float(np().abs(dist).max())
        if constraints:
            free_rms, warnings, free_dist = _constraint_cost(xy, model, distance, fixed,
                                                             constraints, rms, fields)
        warnings = ordering + reversed_joins + warnings
        if model == "discrete" and not split and not step:
            warnings = warnings + _coarse_polygon(xy, constraints, rms)
        # the figures are the user's points': where the library fitted a resampled polygon
        # (whose tail it may leave out), their distances to the curve drawn
        size = float(n.ptp(user[:, :2], axis=0).max())
        resampled = data.shape != user[:, :2].shape or \
            not n.allclose(data, user[:, :2], rtol=0.0, atol=1e-9 * (1.0 + size))
        beyond = n.zeros(len(user), dtype=bool)
        if resampled:
            feet, dist = nearest_on(bspline, n.ascontiguousarray(user[:, :2]))
            beyond = _beyond_the_ends(bspline, feet, dist, size)
        # and in 3D: the curve lies in the plane, so a point's distance from the plane adds
        # to its distance in it (a scan off its plane fits 0.02 mm in it, 0.45 mm in 3D)
        plane_rms = _rms(dist)
        dist = n.copysign(n.hypot(dist, user[:, 2]), dist)
        rms, max_error = _rms(dist), float(n.abs(dist).max())
        data = user
        warnings = warnings + _left_out(beyond, dist, step, used) + \
            _off_plane(user[:, 2], plane_rms, size) + \
            _far_points(data[~beyond], dist[~beyond], plane,
                        None if resampled or free_dist is None else free_dist[~beyond]) + \
            ([] if split else _wanders(results[0], plane))
    except InputProblem:
        raise
    except (ValueError, ArithmeticError, RuntimeError) as exc:
        if split and "no inflection" in str(exc):
            # the library's reason (none found; one of noise near an end, or that two
            # elasticae fit no better than one turning one way), in the panel's terms
            why = str(exc).split(": ", 1)[-1].replace("fit them as one curve",
                                                        "fit them without splitting the keyline")
            raise InputProblem(why) from None
        raise InputProblem(f"fit failed: {exc}") from None
    if not (n.all(n.isfinite(dist)) and math.isfinite(rms)):
        raise InputProblem("fit failed: non-finite error")
    measure = "point to curve" if model == "smooth" else \
        "point to curve (the cubic through the polygon's vertices)"
    if resampled:
        measure += ", from the points given (not the resampled polygon)"
    if n.abs(user[:, 2]).max() > 1e-9 * (1.0 + size):
        measure += ", in 3D (their distance from the fit plane included)"
    return {
        "curves": curves, "results": results, "bspline": bspline, "placement": plane,
        "data": data, "feet": feet, "distances": n.asarray(dist, dtype=float),
        "measure": measure, "rms": float(rms), "max_error": float(max_error),
        "k": [float(r.curve.k) for r in results],
        "end_curvatures": [float(v) for v in bspline.curvature(n.array(bspline.domain))],
        "bspline_deviation": (float(bspline.max_deviation) if model == "smooth"
                              else _polygon_deviation(bspline, curves)),
        "status": "; ".join(_status_text(r) for r in results),
        "free_rms": free_rms, "warnings": warnings,
    }


def fit_gathered(gathered, notes, **options):
    """fit_core of gather_points' (points, plane, ordered, closed) with its ``notes`` (what
    it left out) first among the warnings, or after the error: the way out of an error may
    be what was left out (a sketch's 4 points fitted, its curve left out)."""
    try:
        r = fit_core(*gathered, **options)
    except InputProblem as exc:
        if not notes:
            raise
        raise InputProblem(f"{exc}. {notes[0]}") from None
    r["warnings"] = notes + r["warnings"]
    return r


class FitProxy(FeatureProxy):
    """Elastica fitted to sketch edges / vertices, a Points object, a wire or a CSV file."""

    kind = "Fit"
    followed_links = {"Source": "SourceGeometry", "StartTangent": "StartTangentGeometry",
                      "EndTangent": "EndTangentGeometry"}

    def setup(self, obj):
        tol, deg, model = defaults()
        add_link(obj, "App::PropertyLinkSubList", "Source", "Input",
                 "Sketch edges or vertices, a Points object, or a wire / 3D polyline to fit")
        add_property(obj, "App::PropertyFile", "CsvFile", "Input",
                     "A CSV / text file of x,y[,z] points (mm), used instead of Source when set")
        add_property(obj, "App::PropertyInteger", "SamplesPerEdge", "Input",
                     "Points sampled on each curved source edge (4 to 10000)", 60)
        add_enum(obj, "Model", "Fit",
                 "discrete: Bobenko-Suris discrete elastica through the (resampled) points; "
                 "smooth: the smooth elastica", MODELS, model)
        add_enum(obj, "Distance", "Fit",
                 "What a smooth one-piece fit minimises: orthogonal = each point's distance "
                 "to the curve (any spacing); paired = point i against arc length i L/(n-1), "
                 "for equilateral data (e.g. resampled). A discrete fit minimises the distance "
                 "to its polygon on unevenly spaced points and pairs point i with vertex i on "
                 "equally spaced ones; rms and max error are point-to-curve distances either way",
                 DISTANCES, "orthogonal")
        add_property(obj, "App::PropertyBool", "SplitAtInflection", "Fit",
                     "Fit a keyline as one G2 curve of two elasticae meeting at its inflection "
                     "(seed 000 §5: same point, tangent and zero curvature there); free ends",
                     False)
        add_property(obj, "App::PropertyBool", "PinStart", "Fit",
                     "The curve starts exactly at the first data point (one-piece fits)",
                     bool(getattr(obj, "PinEnds", False)))
        add_property(obj, "App::PropertyBool", "PinEnd", "Fit",
                     "The curve ends exactly at the last data point (one-piece fits)", False)
        add_link(obj, "App::PropertyLinkSub", "StartTangent", "Fit",
                 "An edge whose tangent (at its end nearest the data's start, projected "
                 "into the fit plane) the curve follows there (one-piece fits; empty: free)")
        add_link(obj, "App::PropertyLinkSub", "EndTangent", "Fit",
                 "An edge whose tangent (at its end nearest the data's end, projected into "
                 "the fit plane) the curve follows there (one-piece fits; empty: free)")
        for link, index in self.followed_links.items():
            add_geometry_index(obj, index, link)
        for where in ("Start", "End"):
            add_enum(obj, f"{where}Continuity", "Fit",
                     f"How the curve meets its {where}Tangent edge: tangent = follows its "
                     f"tangent (at the end nearest the data's {where.lower()}); G1 = joins "
                     "the edge there (starts at that end, in the fit plane, with its tangent); "
                     "G2 = and its curvature", CONTINUITIES, "tangent")
            add_property(obj, "App::PropertyBool", f"Use{where}Curvature", "Fit",
                         f"Hold the curve's curvature at its {where.lower()} at "
                         f"{where}Curvature (one-piece fits)", False)
            add_property(obj, "App::PropertyFloat", f"{where}Curvature", "Fit",
                         f"Curvature (1/mm) at the curve's {where.lower()} when "
                         f"Use{where}Curvature: 0 = a free end or an inflection; + turns left "
                         "seen from the fit plane's normal (a sketch's normal)", 0.0)
        if "PinEnds" in obj.PropertiesList:            # documents of version 1
            obj.removeProperty("PinEnds")
        add_length(obj, "ResampleStep", "Fit",
                   "Equilateral resampling step (mm) before fitting; 0 keeps the points. A "
                   "split keyline: the step of its preparation (0 = the polyline through the "
                   "medians of runs of the points, cut into 100 segments: scan noise does "
                   "not lengthen it); the discrete one fits that polygon, the smooth one the "
                   "points themselves", 0.0)
        add_length(obj, "Tolerance", "BSpline",
                   "Largest distance (mm) of the B-spline from the fitted smooth elastica", tol)
        add_property(obj, "App::PropertyInteger", "Degree", "BSpline",
                     "Degree of the B-spline (3 to 7) of a smooth fit; a discrete fit's vertices "
                     "are joined by the C2 cubic through them (natural at free ends)", deg)
        for name, tip in (("Rms", "Root mean square distance of the points given (never "
                                  "resampled ones) from the curve, in 3D (mm; see ErrorMeasure)"),
                          ("MaxError", "Largest distance of a point given from the curve, in "
                                       "3D (mm)"),
                          ("BSplineDeviation", "Certified distance of the B-spline from the "
                                               "smooth elastica (mm); of a discrete fit's cubic "
                                               "through the vertices, its largest distance from "
                                               "the polygon (sampled)")):
            add_property(obj, "App::PropertyFloat", name, "Result", tip)
        add_property(obj, "App::PropertyFloat", "FreeRms", "Result",
                     "Rms of the same fit with free ends (mm; -1 without end conditions, or "
                     "when that fit fails): what the end conditions cost")
        add_property(obj, "App::PropertyStringList", "Warnings", "Result",
                     "What the designer should know about this fit (empty: none)")
        add_property(obj, "App::PropertyFloatList", "K", "Result", "Elliptic modulus k of each curve")
        add_property(obj, "App::PropertyFloatList", "EndCurvatures", "Result",
                     "Curvature (1/mm) of the shape at its start and end, + turning left seen "
                     "from the fit plane's normal (a G2 join's: its edge's)")
        add_property(obj, "App::PropertyString", "Status", "Result", "Outcome of the last fit")
        add_property(obj, "App::PropertyString", "ErrorMeasure", "Result",
                     "What Rms and MaxError measure")
        add_property(obj, "App::PropertyFloatList", "Distances", "Result",
                     "Signed distance (mm) of each fitted point from the curve, + = left of it "
                     "seen from the fit plane's normal, in the order of DataPoints")
        add_property(obj, "App::PropertyString", "Curves", "Result",
                     "The fitted curves' parameters (JSON, plane coordinates); a split "
                     "keyline's two halves each run from the joint")
        add_property(obj, "App::PropertyPlacement", "Plane", "Result",
                     "The plane of the fit (sketch placement or PCA plane)")
        add_property(obj, "App::PropertyVectorList", "DataPoints", "Result",
                     "The points given (never the resampled ones), global coordinates")
        add_property(obj, "App::PropertyVectorList", "FootPoints", "Result",
                     "Each data point's nearest point on the curve (its polygon for a discrete "
                     "fit), global coordinates")
        read_only(obj, "Rms", "MaxError", "BSplineDeviation", "FreeRms", "Warnings", "K",
                  "EndCurvatures", "Status",
                  "ErrorMeasure",
                  "Distances", "Curves", "Plane", "DataPoints", "FootPoints")

    def compute(self, obj):
        """The fit as a dict (see fit_core); raises InputProblem."""
        if not 4 <= obj.SamplesPerEdge <= 10000:
            raise InputProblem(f"SamplesPerEdge = {obj.SamplesPerEdge} is not usable: 4 to 10000")
        # renames Source: read it after; a CSV file is read instead of Source, not its geometry
        element = None if obj.CsvFile else followed_reader(obj, "Source")
        notes = []
        gathered = gather_points(obj.Source, obj.CsvFile, obj.SamplesPerEdge, link="Source",
                                 element=element, notes=notes)
        edges = {}
        for key, prop in (("start_edge", "StartTangent"), ("end_edge", "EndTangent")):
            edge = followed_edge(obj, prop)
            if edge is not None:
                edges[key] = edge
        return fit_gathered(gathered, notes, **core_options(obj), **edges)

    def apply(self, obj, r):
        plc = r["placement"]
        obj.Shape = part_bspline(r["bspline"], plc).toShape()
        obj.Rms = r["rms"]
        obj.MaxError = r["max_error"]
        obj.ErrorMeasure = r["measure"]
        obj.K = r["k"]
        obj.EndCurvatures = r["end_curvatures"]
        obj.BSplineDeviation = r["bspline_deviation"]
        obj.Plane = plc
        obj.DataPoints = [plc.multVec(App.Vector(*map(float, p))) for p in r["data"]]
        obj.FootPoints = to_3d(plc, r["feet"])
        obj.Distances = [float(d) for d in r["distances"]]
        from libelastica.io import curve_to_dict
        obj.Curves = json.dumps([curve_to_dict(c) for c in r["curves"]])
        obj.Status = r["status"] or "ok"
        obj.FreeRms = r["free_rms"]
        if r["warnings"] != list(obj.Warnings):
            # once per change of the warnings, not on every recompute of the same fit
            for w in r["warnings"]:
                App.Console.PrintWarning(f"Elastica {obj.Label}: {w}\n")
            obj.Warnings = r["warnings"]

    def plane_curves(self, obj):
        """(curves, placement) of the last successful fit, or None: the curves along
        its shape from the first point to the last (a smooth keyline's first half
        reversed; Curves keeps the library's halves, each from the joint)."""
        stored = stored_curves(obj)
        if stored and len(stored[0]) == 2 and isinstance(stored[0][0], el().SmoothElastica):
            first, second = stored[0]
            return [first.reversed(), second], stored[1]
        return stored


def stored_curves(obj):
    """(curves, plane) from a feature's Curves JSON, or None."""
    if not getattr(obj, "Curves", ""):
        return None
    from libelastica.io import curve_from_dict
    try:
        return [curve_from_dict(d) for d in json.loads(obj.Curves)], obj.Plane
    except ValueError:
        return None


def core_options(props):
    """fit_core's keyword arguments (but the tangent edges) from Fit property values:
    a feature, or a dict of them (a command's options; missing ones take the
    defaults of a new feature)."""
    if isinstance(props, dict):
        get = props.get
    else:
        def get(name, default=None):
            return getattr(props, name, default)
    return dict(model=get("Model", "discrete"), split=get("SplitAtInflection", False),
                distance=get("Distance", "orthogonal"), pin_start=get("PinStart", False),
                pin_end=get("PinEnd", False),
                start_curvature=get("StartCurvature", 0.0) if get("UseStartCurvature") else None,
                end_curvature=get("EndCurvature", 0.0) if get("UseEndCurvature") else None,
                start_join=get("StartContinuity", "tangent"),
                end_join=get("EndContinuity", "tangent"), step=float(get("ResampleStep", 0.0)),
                tol=float(get("Tolerance", 1e-3)), degree=get("Degree", 3))


def make(doc, sources=(), csv_file="", **props):
    """A new Fit feature in ``doc``; ``sources`` [(obj, [subnames])]; props set Model,
    Distance, SplitAtInflection, PinStart, PinEnd, UseStartCurvature, StartCurvature,
    StartContinuity ("tangent" / "G1" / "G2"), ResampleStep, Tolerance, Degree, ..."""
    if "PinEnds" in props:                       # the version-1 name (recorded macros)
        props["PinStart"] = props.pop("PinEnds")
    return new_feature(doc, "ElasticaFit", FitProxy,
                       Source=[(o, tuple(s) or ("",)) for o, s in sources],
                       CsvFile=csv_file or "", **props)


__all__ = ["FitProxy", "fit_core", "fit_gathered", "core_options", "make", "stored_curves",
           "MODELS", "MODEL_NAMES", "DISTANCES", "DISTANCE_NAMES", "CONSTRAINT_FIELDS",
           "CONTINUITIES", "CONTINUITY_NAMES"]
