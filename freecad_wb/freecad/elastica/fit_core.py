"""The Fit elastica's computation, apart from its feature (fit.py): an elastica, or a
keyline as one G2 curve of two elasticae meeting at its inflection, fitted to 3D points in
their plane (resampled or not, with the end conditions of fit_ends.py), checked (a curve
shrunk to nothing, points left out by the resampled polygon, off their plane, far from the
curve, a fit that wanders between them, end conditions that cost accuracy) and measured:
the points' distances to the curve drawn (fit_shape.py's B-spline)."""
from __future__ import annotations

import math

import FreeCAD as App

from .fit_ends import (CONSTRAINT_FIELDS, constraint_fields, constraint_problem, end_constraints,
                       facing_the_edges, field_names)
from .fit_shape import foot_parameters, polygon_deviation, shape_bspline
from .geometry import binding_module, el, np, plane_coordinates, polyline_length, to_plane
from .nearest import drawn_distances, nearest_on
from .proxy import InputProblem, check_degree, check_number, check_tolerance
from .sources import curve_order, file_order
from .units import coordinate_mark, exact_mark, figure_mark, length_unit_mark

MIN_POINTS = 6          # fewer points cannot determine the 7 (5 shape) parameters of a fit
# the models, their names as the Fit panel's and the preference page's Model boxes show
# them (short: the Combo View leaves the box 110 px, which cut "Discrete elastica (" off)
# and in full (the items' tooltips)
MODELS = ["discrete", "smooth"]
MODEL_NAMES = {"discrete": "Discrete", "smooth": "Smooth"}
MODEL_TIPS = {"discrete": "Discrete elastica (Bobenko-Suris): one vertex per (resampled) point",
              "smooth": "Smooth elastica"}
DISTANCES = ["orthogonal", "paired"]
DISTANCE_NAMES = {"orthogonal": "Point to curve", "paired": "Paired (equilateral data)"}


def _status_text(r):
    st = int(getattr(r, "status", 0))
    if st == 0:
        return "converged"
    c = binding_module("_ffi")
    return "not converged (best curve kept): " + c.ffi.string(c.lib.el_strerror(st)).decode()


def _fit(xy, **options):
    """el.fit without its warnings (the binding's quiet_fit): the feature says them in its own
    words (_wanders, its Status)."""
    return binding_module("fit").quiet_fit(xy, **options)


def _distance(model, distance):
    """The distance el.fit is asked for: the panel's for the smooth model, the library's
    choice for the discrete one."""
    return distance if model == "smooth" else None


def _wanders(result, plane):
    """The warning for a fit in one piece that wanders away from its points between two of
    them (FitResult.wander_gap: it loops, strays, swings or passes them out of order, their
    distances small all the same), naming their places (the fit's order of the points is not
    the user's: no numbers), else none."""
    if result.wander_gap < 0:
        return []
    at = [plane.multVec(App.Vector(float(x), float(y), 0.0)) for x, y in result.points]
    said = el().wander_summary(result.wander_gap, [(v.x, v.y, v.z) for v in at],
                               numbered=False, length=exact_mark)
    return [f"{said}: add a point between them to hold the curve there"]


def _one_piece(xy, model, distance, fixed, constraints, fields):
    """The fit of points xy in one piece: (curves, results, data, feet, signed distances,
    rms, max error, None) as the library reports them, its result's ``free`` the fit with
    free ends where there are end conditions (el.fit's check_ends); fields:
    constraint_fields."""
    try:
        r = _fit(xy, model=model, fixed=fixed or None, constraints=constraints or None,
                 distance=_distance(model, distance), check_ends=True,
                 check_sparse=True)
    except el().ConstraintError as exc:
        raise constraint_problem(exc, fields) from None
    return [r.curve], [r], xy, r.foot_points(), r.distances, r.rms, r.max_error, None


# A curve shorter than COLLAPSED times the points' extent fits none of them: end conditions
# met nowhere near the points shrink a fit to nothing (QA: a start join on a wire drawn
# from its other end, 4e-12 mm long for 90 mm of points, rms 53 mm, kept as 'not
# converged' with no error mark, a shape the 3D view cannot mesh, drawing the last one)
COLLAPSED = 1e-3


def _constraint_cost(result, model, constraints, rms, dist, fields):
    """(rms of the same fit with free ends, or -1 when it failed; the warnings; the points'
    distances to that fit, or None): the binding's rule (el.costly overall, el.end_costs
    near each held end) on the free fit el.fit made (result.free, check_ends); fields:
    constraint_fields. rms, dist: the fit's as shown, a discrete fit's its drawn cubic's,
    and so the free fit's (drawn_distances)."""
    r, xy = result.free, result.points
    if r is None:
        return -1.0, [], None
    try:
        free_dist = r.distances if model == "smooth" else \
            drawn_distances(r.to_bspline(), xy, r.foot_s)[1]
        free = r.rms if model == "smooth" else _rms(free_dist)
    except (ValueError, ArithmeticError, RuntimeError):
        return -1.0, [], None
    extent = float(np().ptp(xy, axis=0).max())
    held = field_names(constraints, fields)
    if el().costly(rms, free, extent):
        return float(free), [el().cost_summary(held, free, rms, length=figure_mark)], free_dist
    near = el().end_costs(el().held_ends(constraints, None), r.foot_s, dist, free_dist, extent)
    said = [el().local_cost_summary(held, end, near_free, near_rms, length=figure_mark)
            for end, near_rms, near_free in near[:1]]
    return float(free), said, free_dist


def _check_length(bspline, extent, constraints, fields, reversed_joins):
    """Raise InputProblem for a fitted curve shorter than COLLAPSED times the points'
    extent (mm), naming the end conditions it gave way to."""
    n = np()
    length = polyline_length(bspline.evaluate(n.linspace(*bspline.domain, 65)))
    if length > COLLAPSED * extent:
        return
    why = (f"the end conditions ({field_names(constraints, fields)}) cannot be met along the points"
           if constraints else "check the points")
    raise InputProblem(f"the fit shrank to a curve {exact_mark(length, 2)} long, for points "
                       f"{exact_mark(extent, 4)} across: {why}" +
                       "".join(f". {w}" for w in reversed_joins[:1]))


def _rms(dist):
    return float(np().sqrt(np().mean(np().square(dist))))


def _beyond_the_ends(bspline, feet, dist, extent):
    """Which points lie beyond the curve's ends (their nearest point on it an end, farther
    than el.COST_FLOOR of their extent and el.COST_RATIO times the others' rms): those a split
    keyline's resampled polygon leaves out. Its
    equilateral polygon ends where no point lies a step further on (seed 000 §5.3), so up
    to a step of the points' run is not fitted, and the curve stops there too."""
    n = np()
    ends = bspline.evaluate(n.array(bspline.domain))
    at_end = n.min(n.linalg.norm(feet[:, None, :] - ends[None, :, :], axis=2), axis=1) \
        <= 1e-9 * (1.0 + extent)
    others = _rms(dist[~at_end]) if not at_end.all() else 0.0
    return at_end & (n.abs(dist) > max(el().COST_FLOOR * extent, el().COST_RATIO * others))


def _left_out(beyond, dist, step, used):
    """The warning for points a split keyline's resampled polygon left out
    (_beyond_the_ends), else none. ``used``: that polygon's step (its default where step
    is 0: a keyline is always resampled). One piece fits el.resampled_polygon, which ends
    at the points' ends: what stops its curve short of them (end conditions, a hook) is
    what stops the unresampled fit's, and the end conditions' cost says it."""
    if not beyond.any():
        return []
    d = np().abs(dist[beyond])
    m = int(beyond.sum())
    verb = "lies" if m == 1 else "lie"
    setting = (f"Resample = {exact_mark(step)}" if step else
               f"Resample = 0 takes {_default_step_name(used)}")
    way_out = "a shorter step leaves less out"
    return [f"{m} of {len(dist)} points {verb} beyond the curve's ends, up to "
            f"{figure_mark(d.max(), 3)} from it: the resampled polygon ({setting}) "
            "stops where no point lies a step further on, and the curve with it; Rms and "
            f"MaxError include them: {way_out}"]


def _off_plane(off, rms, extent):
    """The warning for points whose distances from their plane (``off``, mm) outweigh the
    fit's in-plane rms (and above el.COST_FLOOR of their extent): a plane curve cannot come
    closer to them than that, else none."""
    n = np()
    off_rms = _rms(off)
    if not (off_rms > rms and off_rms > el().COST_FLOOR * extent):
        return []
    return [f"the points lie up to {figure_mark(n.abs(off).max(), 3)} "
            f"(rms {figure_mark(off_rms, 3)}) off "
            f"their plane, the fit's: Rms and MaxError include that (in the plane the curve lies "
            f"{figure_mark(rms, 3)} from them, rms); a plane curve comes no closer"]


def _step_advice(length):
    """What a resampling step of points whose polyline is length long must be below, and
    the way out."""
    return (f"the points' polyline is {exact_mark(length, 4)} long, so {MIN_POINTS} points need "
            f"a step under {exact_mark(length / (MIN_POINTS - 1), 4, bound='down')}; 0 fits the points as they "
            "are")


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
    beyond = (f"longer than the points reach (all within {exact_mark(reach, 4)} of the end "
              "the polygon starts from)")
    if default is None:
        raise InputProblem(f"Resample = {exact_mark(step)} is {beyond}: "
                           + _step_advice(polyline_length(xy)))
    if step > 0:
        zero = f", or 0 for {_default_step_name(default)}" if default <= reach else ""
        raise InputProblem(f"Resample = {exact_mark(step)} is {beyond}: set a step under "
                           f"{exact_mark(reach, 4, bound='down')}{zero}")
    raise InputProblem(f"Resample = 0 takes {_default_step_name(default)}, which is {beyond}: "
                       f"set a step under {exact_mark(reach, 4, bound='down')}")


def _resampled(xy, step):
    """The points xy resampled into an equilateral polygon of segment step
    (el.resampled_polygon), at least MIN_POINTS vertices of it."""
    _check_reach(xy, step, [-1 if xy[-1, 0] < xy[0, 0] else 0])
    most, length = el().RESAMPLE_MAX_VERTICES, polyline_length(xy)
    if length / step > most - 1:
        raise InputProblem(f"Resample = {exact_mark(step)} would cut the points' "
                           f"{exact_mark(length, 4)} polyline into {length / step:.3g} segments, "
                           f"more than {most - 1}: use a step of at least "
                           f"{exact_mark(length / (most - 1), 4, bound='up')}, or 0 to fit the points as "
                           "they are")
    # the library's polygon (el.resampled_polygon): in the user's order, of the medians of
    # runs where the points' polyline is their noise's zigzag, ended at their end points
    out = el().resampled_polygon(xy, step)
    if len(out) < MIN_POINTS:
        # the vertices are step apart along the way, so few of them from a step short enough
        # for MIN_POINTS mean the walk jumped ahead: the points double back or pass close to
        # themselves within the step (seed 000 §5.3 jumps a hairpin narrower than it)
        why = (_step_advice(length) if step >= length / (MIN_POINTS - 1) else
               "the polygon jumps where the points double back or pass within the step of "
               "themselves; 0 fits the points as they are")
        raise InputProblem(f"Resample = {exact_mark(step)} leaves {len(out)} points; a fit "
                           f"needs {MIN_POINTS}: {why}")
    return out


def _far_from_resampled(xy, rms, result, polygon, constraints, step):
    """The warning for a fit of the polygon resampled at step whose points xy lie rms (in
    their plane) from it, far more than from their own smooth fit (el.resampled_reference:
    a polygon too coarse for the curve), else none."""
    ref = el().resampled_reference(xy, rms, polygon, result.curve, constraints or None)
    if ref is None:
        return []
    extent = float(np().ptp(xy, axis=0).max())
    return [el().resample_summary(step, rms, ref, extent=extent, length=exact_mark)]


def _keyline_step(xy):
    """The default step of a split keyline's polygon, the binding's (el.keyline_step:
    1/KEYLINE_STEPS of the polyline through the medians of runs of the points, robust
    to their noise's zigzag); fit_keyline resamples that polyline where Resample is 0."""
    return el().keyline_step(xy)


def _default_step_name(step):
    """What the default step of a split keyline is, for messages."""
    return (f"the default step, {exact_mark(step, 3)} = 1/{el().KEYLINE_STEPS} of the points' run "
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
    each by its recursion to its end point's foot (KeylineFit.ends). Returned with the
    sparse verdict of fit_keyline (KeylineFit.sparse: the smooth keyline's rms, or None)."""
    n = np()
    # its Status says a ConvergenceWarning; ordered by fit_core (file_order, curve_order);
    # fit_core's _misfit says a MisfitWarning, _coarse_keyline a SparseWarning (kf.sparse)
    e = el()
    with binding_module("_quiet").quiet(e.ConvergenceWarning, e.OrderWarning, e.MisfitWarning,
                                        e.SparseWarning):
        kf = el().fit_keyline(xy, r=step, model=model)
    first, second = kf.first, kf.second
    to_plane = kf.to_input                           # the sides' results live in x''y''
    skip = 1 if model == "discrete" else 0
    data = to_plane(n.vstack([first.points[::-1], second.points[skip:]]))
    feet = to_plane(n.vstack([first.foot_points()[::-1], second.foot_points()[skip:]]))
    dist = n.concatenate([-first.distances[::-1], second.distances[skip:]])
    halves = [kf.side_curve(which) for which in ("first", "second")]   # in the plane
    rms = _rms(dist)
    tails = None
    if kf.ends is not None:
        lead = first.curve.continued_to(kf.ends_local[0])
        tails = (kf.ends, polyline_length(n.vstack([first.curve.points()[-1:], lead])))
    return (halves, [first, second], data, feet, dist, rms, float(n.abs(dist).max()), tails), kf.sparse


def _coarse_polygon(xy, smooth, rms):
    """The warning for a discrete fit of fewer than el.SPARSE_POINTS points whose cubic lies
    rms from them where the smooth model's curve lies far nearer, smooth: its rms where
    el.fit found so (FitResult.sparse, its verdict), else None: none."""
    if smooth is None:
        return []
    return [f"{len(xy)} points give the discrete model a polygon of {len(xy) - 1} segments, "
            f"its cubic {figure_mark(rms, 3)} from them (rms), where the smooth model's curve lies "
            f"{figure_mark(smooth, 3)} "
            "from them: choose Model Smooth elastica for so few points"]


def _coarse_keyline(xy, smooth, rms):
    """The warning for a discrete keyline of fewer than el.SPARSE_POINTS points whose cubic
    lies rms from them where the smooth keyline lies far nearer, smooth: its rms where
    fit_keyline found so (KeylineFit.sparse, el.SparseWarning's verdict), else None: none."""
    if smooth is None:
        return []
    return [f"the discrete keyline of {len(xy)} points lies {figure_mark(rms, 3)} from them "
            f"(rms), where the smooth keyline lies {figure_mark(smooth, 3)} from them: their "
            "resampled polygon cuts their bends; choose Model Smooth elastica for so few points"]


def _number_named(number, names):
    """How a warning names the point given as ``number`` (from 1): its name in ``names``
    (sources.gather_points': a sketch's '<label>'s 26-Point' as the Sketcher's Elements panel
    lists it, a file's 'line 27 of points.csv', a picked 'Wire's Vertex3'), else (none: points
    sampled along edges) 'point 26 as given'."""
    if names and 0 < number <= len(names):
        return names[number - 1]
    return f"point {number} as given"


def _listed(said):
    """(the names ``said`` listed, a function shortening one of them as listed): a label they
    share said once ("Scan's 11-Point, 26-Point"), a file's lines as one ("lines 11, 26 of
    points.csv"); else each in full."""
    heads = {w.rsplit("'s ", 1)[0] for w in said if "'s " in w}
    if len(heads) == 1 and all("'s " in w for w in said):
        head = heads.pop() + "'s "
        return head + ", ".join(w[len(head):] for w in said), lambda w: w[len(head):]
    for row in ("line ", "row "):           # (a .npy array's rows)
        tails = {w.split(" of ", 1)[1] for w in said if w.startswith(row) and " of " in w}
        if len(tails) == 1 and all(w.startswith(row) and " of " in w for w in said):
            tail = " of " + tails.pop()
            return (f"{row[:-1]}s " + ", ".join(w[len(row):-len(tail)] for w in said) + tail,
                    lambda w: w[:-len(tail)])
    return ", ".join(said), lambda w: w


def _point_named(i, numbers, data, plane, sketch, names=None):
    """How a warning names fitted point i, the way the designer finds it (QA qagui F6: an
    outlier placed at global '(1835, 8.736, -278) mm', no number, was vertex 24 at (1556,
    -624.2) in the Sketcher): its name (_number_named: the Sketcher's element, the file's
    line, the vertex picked; ``names`` each given point's) and its place in
    the sketch's own coordinates (``sketch``: its global placement, inverted; None, or a
    point not in its plane: global coordinates). data: (n, 3) in the frame ``plane``."""
    at = plane.multVec(App.Vector(*map(float, data[i])))
    where = ""
    if sketch is not None:
        local = sketch.inverse().multVec(at)
        if abs(local.z) <= 1e-9 * (1.0 + at.Length):
            at, where = App.Vector(local.x, local.y, 0.0), "in the sketch "
    xyz = (at.x, at.y) if where else (at.x, at.y, at.z)
    # the unit named after the place: after '... within 24.7 \u00b5m' its mm read as \u00b5m
    return (f"{_number_named(int(numbers[i]), names)}, {where}at "
            f"({', '.join(coordinate_mark(v) for v in xyz)}) {length_unit_mark(written=True)}")


def _far_points(data, dist, plane, free=None, numbers=None, sketch=None, names=None):
    """The warning for points far from the fitted curve (el.far_points: glitches of a scan,
    points of other geometry), naming them (_number_named: by ``names``, each given point's,
    else by number as given) and the farthest's place (_point_named), else none. data: (n, 3)
    in the frame ``plane``; free: their distances to the fit with free ends (points held off
    only by the end conditions are no outliers to remove); numbers: each one's number as given
    (default 1 .. n); sketch: the sketch's placement (its coordinates named), or None."""
    n = np()
    far = el().far_points(dist, data, free_distances=free)
    if not len(far):
        return []
    numbers = n.arange(1, len(data) + 1) if numbers is None else numbers
    farthest = far[n.argmax(n.abs(n.asarray(dist if free is None else free, dtype=float))[far])]
    named = _point_named(farthest, numbers, data, plane, sketch, names)
    if len(far) > 1:
        listed = sorted(int(numbers[i]) for i in far)
        more = ", ..." if len(listed) > 10 else ""
        if names:
            said, short = _listed([_number_named(k, names) for k in listed[:10]])
            whole = _number_named(int(numbers[farthest]), names)
            named = f"{said}{more}; the farthest, {short(whole)}{named[len(whole):]}"
        else:
            named = (f"points {', '.join(map(str, listed[:10]))}{more} as given; the farthest, "
                     f"{named.split(' ', 1)[1].replace(' as given', '', 1)}")
    said = el().far_points_summary(dist, far, free_distances=free, length=figure_mark)
    return [f"{said} ({named}): "
            "outliers? Each pulls the fit towards itself: remove them to fit the rest"]


def _as_given(numbers):
    """Whether the points were fitted in the order given (either way): a stray point is
    named only there (el.stray_point: a cloud's curve order is a guess)."""
    k = list(range(1, len(numbers) + 1))
    return list(numbers) in (k, k[::-1])


def _stray(result, numbers, plane, data, sketch, names=None):
    """The warning for one stray point among a hand sketch's few (el.stray_point: far from
    the curve through the others, which it pulls; QA25gui F1: one of 18 sketched points
    mis-dragged 150 mm off, fitted with no word), naming it by its number as given and its
    place (_point_named), else none. result: the library's fit of the points as fitted (in
    the plane), numbers: each fitted point's number as given, data: the points (n, 3) in
    the frame ``plane``, sketch: the sketch's placement or None, names: as _point_named's."""
    stray = binding_module("stray").stray_point(result)
    if stray is None:
        return []
    i = stray[0]
    return [binding_module("misfit").stray_summary(
        len(result.points), stray, int(numbers[i]), length=figure_mark,
        named=_point_named(i, numbers, data, plane, sketch, names))]


def _misfit(xy, dist, plane, split, numbers, data, sketch, names=None):
    """The warning for points far farther from the fit than their own noise (el.misfit: they
    are not one elastica, or keyline), naming the likely corner or the farthest points
    (_point_named), else none. xy (n, 2) in the frame ``plane``, dist: their distances to the
    curve in it (None: not judged); numbers, data (n, 3), sketch, names: as _point_named's."""
    if dist is None:
        return []
    # (a keyline's: no stray points tried, the others' refit would be one elastica's)
    m = el().misfit(np().ascontiguousarray(xy, dtype=float), np().asarray(dist, dtype=float),
                    strays=not split)
    if m is None:
        # too few points for a verdict (QA22gui F7: 12 clicks across an inflection fitted
        # 1.92 mm, nothing said; split 0.41): the keyline asked where they turn both ways
        hint = None if split else el().split_hint(
            np().ascontiguousarray(xy, dtype=float), np().asarray(dist, dtype=float),
            how="Split at the inflection", length=exact_mark)
        return [hint] if hint else []
    at = [plane.multVec(App.Vector(float(x), float(y), 0.0)) for x, y in xy]
    said = el().misfit_summary(m, [(v.x, v.y, v.z) for v in at], numbered=False, length=exact_mark,
                               what="one keyline" if split else "one elastica",
                               named=lambda i: _point_named(i, numbers, data, plane, sketch, names))
    return [said]


def fit_core(points, plane=None, ordered=True, closed=False, model="discrete", split=False,
             distance="orthogonal", pin_start=False, pin_end=False, start_edge=None,
             end_edge=None, start_curvature=None, end_curvature=None, start_join="tangent",
             end_join="tangent", step=0.0, tol=1e-3, degree=3, start_at=None, end_at=None,
             names=None):
    """Fit elastica(e) to 3D points: in their order (``ordered``), in curve_order's (False)
    or a file's, kept when a curve's (None: file_order). ``distance``: what the smooth one-piece fit
    minimises ("orthogonal": point to curve; "paired": point i at arc length
    i L/(n-1), for equilateral data). ``start_edge`` / ``end_edge``: Part edges whose
    tangents the curve's ends follow (``start_at`` / ``end_at``: at which end, as
    fit_ends.tangent_angle); ``start_curvature`` / ``end_curvature``: 1/mm
    or None (free); ``start_join`` / ``end_join``: how that end meets its edge
    (end_constraints); ``names``: each point's name as the designer finds it (gather_points'
    names: the Sketcher's element, a file's line; None or empty: 'point 12 as given'), for
    the warnings. Returns a dict: 'curves' (plane coordinates; a keyline's two
    halves, each from the joint), 'results', 'bspline', 'placement', 'data' (the
    user's points, (n, 3) in the frame of the plane: never a resampled polygon, in the order
    fitted), 'numbers' (each one's number in the order given, from 1), 'feet'
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
                start_join=start_join, end_join=end_join, start_at=start_at, end_at=end_at)
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
    sketch = plane                     # a sketch's placement: its points are named in it
    try:
        xy, plane = plane_coordinates(points, plane, flat=None)
        # the user's points in the fit's frame: plane coordinates and distance from the plane
        user = n.column_stack([xy, to_plane(plane, points)[:, 2]])
        order, ordering = file_order(xy) if ordered is None else \
            (None if ordered else curve_order(xy), [])
        taken = user if order is None else user[order]
        user = facing_the_edges(taken, plane, start_edge, end_edge)
        # each fitted point's number in the order given (QA22gui F3: where the fit took them
        # in another, Distances[i] was not the sketch's point i, and nothing said so)
        numbers = n.arange(1, len(points) + 1) if order is None else n.asarray(order) + 1
        if user is not taken:
            numbers = numbers[::-1]
        xy = n.ascontiguousarray(user[:, :2])
        constraints, free_rms, warnings, used, reversed_joins = {}, -1.0, [], None, []
        free_dist, keyline_sparse = None, None
        if split:
            default = _keyline_step(xy)
            _check_reach(xy, step, [0, -1], default)
            used = step if step > 0 else default
            fitted, keyline_sparse = _keyline(xy, model, step if step > 0 else None)   # None: the default
        else:
            fixed = {}
            if step > 0:
                # it ends at the user's end points (pinned or not); the discrete h is fitted:
                # the polygon of noisy points is longer than their curve (h held at a 2 mm
                # step bulged a 4 m scan's curve to rms 13 mm, noise 0.5 mm)
                xy = _resampled(xy, step)
            constraints, reversed_joins = end_constraints(xy, plane, tol=tol, **ends)
            try:
                fitted = _one_piece(xy, model, distance, fixed, constraints, fields)
            except InputProblem as exc:
                if not reversed_joins:
                    raise
                raise InputProblem(f"{exc}. {reversed_joins[0]}") from None
        curves, results, data, feet, dist, rms, max_error, tails = fitted
        bspline = shape_bspline(model, curves, results, split, tol, degree, tails)
        _check_length(bspline, float(n.ptp(xy, axis=0).max()), constraints, fields,
                      reversed_joins)
        if model == "discrete":
            feet, dist = drawn_distances(bspline, data, foot_parameters(results, split, tails))
            rms, max_error = _rms(dist), float(np().abs(dist).max())
        if constraints:
            free_rms, warnings, free_dist = _constraint_cost(results[0], model, constraints, rms,
                                                             dist, fields)
        warnings = ordering + reversed_joins + warnings
        if model == "discrete" and not split and not step:
            warnings = warnings + _coarse_polygon(xy, results[0].sparse, rms)
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
        if model == "discrete" and split:   # the user's points to the keyline drawn
            warnings = warnings + _coarse_keyline(xy, keyline_sparse, plane_rms)
        # judged by the library's fit of the points it fitted, the one el.fit judges
        # (judged_fit: without end conditions, their cost said apart; none where asked to be
        # paired); a keyline's by the points'; a resampled polygon's by the user's points
        # and their distances to the curve drawn (the polygon's own noise is not theirs: a
        # 16-point sketch resampled at 4 mm lies on straight segments, its noise 0.0044 mm,
        # and was said "95.6 x their own noise: not one elastica"), where no end condition
        # adds its cost to those distances (the step's cost is said apart)
        judged = None if split or resampled else binding_module("fit").judged_fit(
            results[0], constraints, _distance(model, distance))
        named = (numbers, user, sketch, names)
        misfit = _misfit(user[:, :2], dist, plane, True, *named) if split else \
            (_misfit(user[:, :2], dist, plane, False, *named) if not constraints else []) \
            if resampled else \
            _misfit(judged.points, judged.distances, plane, False, *named) \
            if judged is not None else []
        dist = n.copysign(n.hypot(dist, user[:, 2]), dist)
        rms, max_error = _rms(dist), float(n.abs(dist).max())
        data = user
        if resampled and not split:
            warnings = warnings + _far_from_resampled(user[:, :2], plane_rms, results[0], xy,
                                                      constraints, step)
        warnings = warnings + (_left_out(beyond, dist, step, used) if split else []) + \
            _off_plane(user[:, 2], plane_rms, size) + \
            (_far_points(data[~beyond], dist[~beyond], plane,
                         None if resampled or free_dist is None else free_dist[~beyond],
                         numbers[~beyond], sketch, names)
             or ([] if split or resampled or constraints or not _as_given(numbers)
                 else _stray(results[0], numbers, plane, user, sketch, names))) + \
            ([] if split else _wanders(results[0], plane)) + misfit
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
        "numbers": [int(i) for i in numbers],
        "measure": measure, "rms": float(rms), "max_error": float(max_error),
        "k": [float(r.curve.k) for r in results],
        "end_curvatures": [float(v) for v in bspline.curvature(n.array(bspline.domain))],
        "bspline_deviation": (float(bspline.max_deviation) if model == "smooth"
                              else polygon_deviation(bspline, curves)),
        "status": "; ".join(_status_text(r) for r in results),
        "free_rms": free_rms, "warnings": warnings,
    }


def gathered_key(gathered, options):
    """What fit_core's result depends on, comparable with ==: gather_points' (points, plane,
    ordered, closed) and fit_core's options; None: not compared (tangent edges)."""
    if options.get("start_edge") is not None or options.get("end_edge") is not None:
        return None
    points, plane, ordered, closed = gathered
    return ([(p.x, p.y, p.z) for p in points],
            None if plane is None else tuple(plane.toMatrix().A), ordered, closed,
            sorted(options.items()))


def _fitted(gathered, notes, options):
    """fit_core's dict; after its error, the first of the ``notes`` (what gather_points left
    out): the way out of an error may be what was left out (a sketch's 4 points fitted,
    its curve left out)."""
    try:
        return fit_core(*gathered, **options)
    except InputProblem as exc:
        if not notes:
            raise
        raise InputProblem(f"{exc}. {notes[0]}") from None


def check_fit(gathered, notes, **options):
    """A command's check of its input: (gathered_key, fit_core's dict), for fit_gathered's
    ``checked`` (the new feature's first recompute); raises InputProblem as fit_gathered."""
    return gathered_key(gathered, options), _fitted(gathered, notes, options)


def fit_gathered(gathered, notes, checked=None, **options):
    """fit_core of gather_points' (points, plane, ordered, closed) with its ``notes`` (what
    it left out) first among the warnings, or after the error (_fitted). ``checked``: a
    command's check (check_fit), whose fit is taken where its input is this one: the Fit
    command's check and its new feature's first recompute read the same points (a 50 000-
    point scan was fitted twice, 2 x 9.6 s, QA19gui F3)."""
    key = gathered_key(gathered, options) if checked is not None else None
    if key is not None and checked[0] == key:
        r = dict(checked[1])
    else:
        r = _fitted(gathered, notes, options)
    r["warnings"] = notes + r["warnings"]
    return r


__all__ = ["fit_core", "fit_gathered", "check_fit", "MIN_POINTS", "MODELS", "MODEL_NAMES", "MODEL_TIPS",
           "DISTANCES", "DISTANCE_NAMES"]
