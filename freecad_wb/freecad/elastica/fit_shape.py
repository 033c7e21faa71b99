"""The shape of a Fit elastica: ONE B-spline of the fitted curve (a keyline's two halves
joined G2, a discrete fit's C2 cubic through its polygon), the data points' parameters on
a discrete fit's cubic, and how far that cubic lies from its polygon."""
from __future__ import annotations

from .geometry import chain_bspline, np, polyline_length


def foot_parameters(results, split, tails=None):
    """The data points' parameters on a discrete fit's cubic from their polygon feet: the
    arc length of each foot (a keyline's first half reversed, from the first point, then the
    second's after the joint vertex; after its ``tails``' lead, fit_core's _keyline)."""
    if not split:
        return results[0].foot_s
    n = np()
    first, second = results
    joint = polyline_length(first.curve.points()) + (0.0 if tails is None else tails[1])
    return n.concatenate([joint - first.foot_s[::-1], joint + second.foot_s[1:]])


def polygon_deviation(bspline, curves, samples=32):
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
    # each span's np.linspace(a, b, samples, endpoint=False), its arithmetic, at once
    step = (k[1:] - k[:-1]) / samples
    t = n.concatenate([(n.arange(samples) * step[:, None] + k[:-1, None]).ravel(), k[-1:]])
    px, py = bspline.evaluate(t).T
    j = n.clip(n.searchsorted(c, t) - 1, 0, len(V) - 2)
    # each sample's squared distance to its segment and the two beside it, by columns (a
    # 50 000-point fit's 1.6 M samples: 2.0 s as (n, 2) rows, 0.4 s so); sqrt at the end
    X, Y = V[:, 0], V[:, 1]
    DX, DY = n.diff(X), n.diff(Y)
    DD = n.maximum(DX * DX + DY * DY, 1e-300)
    best = n.full(len(t), n.inf)
    for dj in (-1, 0, 1):
        i = n.clip(j + dj, 0, len(V) - 2)
        ax, ay, dx, dy = X[i], Y[i], DX[i], DY[i]
        u = n.clip(((px - ax) * dx + (py - ay) * dy) / DD[i], 0.0, 1.0)
        ex, ey = px - (ax + u * dx), py - (ay + u * dy)
        n.minimum(best, ex * ex + ey * ey, out=best)
    return float(n.sqrt(best.max()))


def shape_bspline(model, curves, results, split, tol, degree, tails=None):
    """ONE B-spline of the fit, run from the first point to the last: smooth, the
    G2 B-spline of the elastica (a keyline: its first half reversed, then the second;
    end points, tangents and curvatures exact, so the constraints hold on it and the
    joint is G2); discrete, the C2 cubic through the vertices (a keyline's both
    halves), natural at free ends, the constrained tangent, curvature or both (G2) at
    others; ``tails``: a discrete keyline's (fit_core's _keyline), to its ends."""
    if split or model == "smooth":
        return chain_bspline(curves, tol, degree, keyline=split,
                             ends=None if tails is None else tails[0])
    return results[0].to_bspline()          # the fit's end constraints on the cubic


__all__ = ["foot_parameters", "polygon_deviation", "shape_bspline"]
