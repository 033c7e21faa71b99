"""Report pictures: the data, the initial guess, the fitted curve, the residual
vectors, a curvature plot and the parameters, like seed 000's Figure 5 (black
squares: input, green triangles: initial guess, red: the elastica).

An SVG is written directly (polylines, marks and text: the same panels, legends and
parameters as matplotlib drew them, without importing it: QA qapy F13, --svg cost 3 x
the fit, mostly matplotlib's import); a PNG is drawn with matplotlib when it is
installed, else refused. ``LIBELASTICA_NO_MATPLOTLIB=1`` acts as if it were not.

A picture is described by a :class:`Picture` (plain data: point sets, polylines,
residual segments, curvature graphs, parameter lines) that both back ends draw;
:func:`fit_picture`, :func:`curves_picture` build one from libelastica objects.
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import List, Optional, Sequence, Tuple, Union
from xml.sax.saxutils import escape

import numpy as np

from ._text import curve_values
from .io import InputError

__all__ = ["Layer", "Graph", "Picture", "fit_picture", "curves_picture", "save_picture",
           "have_matplotlib", "closest_points", "polygon_curvature"]

PathLike = Union[str, Path]

COLORS = ["#d62728", "#1f77b4", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf"]


@dataclass
class Layer:
    """Points or a polyline in the geometry panel. ``marker``: 's' square, '^'
    triangle, 'o' circle, '' none; ``line``: draw the polyline."""
    xy: np.ndarray
    label: str
    color: str
    marker: str = ""
    line: bool = False
    size: float = 4.0


@dataclass
class Graph:
    """One curve of the curvature panel: kappa against arc length s."""
    s: np.ndarray
    kappa: np.ndarray
    label: str
    color: str
    marker: str = ""
    line: bool = True
    primary: bool = True     # the panel's y-range covers primary graphs; others are clipped


@dataclass
class Picture:
    """A report picture: geometry panel (layers + residual segments), curvature
    panel (graphs) and the parameter lines."""
    title: str
    layers: List[Layer] = field(default_factory=list)
    residuals: Optional[Tuple[np.ndarray, np.ndarray]] = None   # (from (n,2), to (n,2))
    graphs: List[Graph] = field(default_factory=list)
    params: List[str] = field(default_factory=list)


# ------------------------------------------------------------- geometry helpers

def _closest_brute(p: np.ndarray, a: np.ndarray, d: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """Each point's closest foot on the segments a + t d, every segment tried: (foot (n, 2),
    squared distance (n,)); ties go to the first segment. x and y apart ((n, m) arrays, no
    (n, m, 2) ones summed over their last axis): the same operations in the same order, the
    same bits, 2.4 x less time (QA25 F6: g2_quadratic's deviation spent most of its in here)."""
    px, py = p[:, 0:1], p[:, 1:2]
    ax, ay, dx, dy = a[:, 0], a[:, 1], d[:, 0], d[:, 1]
    dd = np.maximum(dx * dx + dy * dy, 1e-300)
    t = np.clip(((px - ax) * dx + (py - ay) * dy) / dd, 0.0, 1.0)
    fx, fy = ax + t * dx, ay + t * dy
    ex, ey = fx - px, fy - py
    d2 = ex * ex + ey * ey
    i = np.argmin(d2, axis=1)
    r = np.arange(len(i))
    return np.stack([fx[r, i], fy[r, i]], axis=1), d2[r, i], i


_BLOCK = 64     # points per chunk and segments per block of closest_points' search


def _box_gap2(lo, hi, blo, bhi) -> np.ndarray:
    """Squared distance between the box [lo, hi] and each box [blo, bhi] (k, 2): a lower
    bound of the distance of any point in the first to any point in the others."""
    g = np.maximum(0.0, np.maximum(blo - hi, lo - bhi))
    return np.sum(g * g, axis=1)


def closest_points(points: np.ndarray, polyline: np.ndarray, segments: bool = False):
    """For each of ``points`` (n, 2), the closest point (n, 2) of the polyline (m, 2);
    ``segments``: and the index (n,) of the segment each lies on, as (feet, indices).

    Branch and bound, the same feet as trying every segment (ties to the first): points in
    chunks of 64 and segments in blocks of 64 consecutive ones, each with its bounding box;
    a chunk first takes its feet on the block whose box is nearest its own, and the largest
    of those distances bounds every point's nearest one; a block whose box lies farther
    from the chunk's box than that holds no nearer foot (the box gap is a lower bound), the
    rest are searched in order. O(n m / 4096) box tests and, on a curve sampled in order,
    a few blocks per chunk: 33 ms for 16000 points on 20000 segments, 30 s tried one by one."""
    p = np.asarray(points, dtype=np.float64)
    poly = np.asarray(polyline, dtype=np.float64)
    a, d = poly[:-1], np.diff(poly, axis=0)
    m = len(a)
    if len(p) * m <= _BLOCK * _BLOCK:
        feet, _, seg = _closest_brute(p, a, d)
        return (feet, seg) if segments else feet
    nb = -(-m // _BLOCK)
    b, b_ = np.minimum(poly[:-1], poly[1:]), np.maximum(poly[:-1], poly[1:])   # segment boxes
    pad = nb * _BLOCK - m
    blo = np.concatenate([b, np.repeat(b[-1:], pad, 0)]).reshape(nb, _BLOCK, 2).min(axis=1)
    bhi = np.concatenate([b_, np.repeat(b_[-1:], pad, 0)]).reshape(nb, _BLOCK, 2).max(axis=1)
    out, index = np.empty_like(p), np.empty(len(p), dtype=np.intp)
    for c in range(0, len(p), _BLOCK):
        q = p[c:c + _BLOCK]
        gap = _box_gap2(q.min(axis=0), q.max(axis=0), blo, bhi)
        j = int(np.argmin(gap))
        sl = slice(j * _BLOCK, min(m, (j + 1) * _BLOCK))
        bound = float(np.max(_closest_brute(q, a[sl], d[sl])[1]))
        keep = np.nonzero(gap <= bound * (1.0 + 1e-9))[0]   # (margin: rounding of the two)
        seg = (keep[:, None] * _BLOCK + np.arange(_BLOCK)[None, :]).ravel()
        seg = seg[seg < m]
        out[c:c + _BLOCK], _, i = _closest_brute(q, a[seg], d[seg])
        index[c:c + _BLOCK] = seg[i]
    return (out, index) if segments else out


def polygon_curvature(xy: np.ndarray) -> Tuple[np.ndarray, np.ndarray]:
    """Signed Menger curvature of a polygon at its interior vertices, with the
    vertices' arc lengths: (s (n-2,), kappa (n-2,)); positive = turning left."""
    xy = np.asarray(xy, dtype=np.float64)
    a, b, c = xy[:-2], xy[1:-1], xy[2:]
    ab, bc, ac = b - a, c - b, c - a
    cross = ab[:, 0] * bc[:, 1] - ab[:, 1] * bc[:, 0]
    den = (np.linalg.norm(ab, axis=1) * np.linalg.norm(bc, axis=1) * np.linalg.norm(ac, axis=1))
    with np.errstate(divide="ignore", invalid="ignore"):
        kappa = np.where(den > 0, 2.0 * cross / den, 0.0)
    s = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(xy, axis=0), axis=1))])
    return s[1:-1], kappa


def _curve_samples(curve, n: int = 400):
    """(xy, s, kappa, vertices-or-None) of a SmoothElastica / DiscreteElastica."""
    from .core import SmoothElastica
    if isinstance(curve, SmoothElastica):
        s = np.linspace(0.0, curve.length, n)
        return curve.points(s), s, curve.curvature(s), None
    xy = curve.points()
    kappa = curve.curvature() if curve.n >= 3 else np.empty(0)
    s = curve.h * np.arange(1, curve.n - 1)
    return xy, s, kappa, xy


def _curve_params(curve) -> List[str]:
    from .io import curve_to_dict
    d = curve_to_dict(curve)
    n = d.get("n")
    items = [f"{k} = {text}" for k, text in curve_values(d) if k != "n"]
    head = f"{d['type']} elastica" + (f", n = {n}" if n is not None else "")
    return [head] + [", ".join(items[i:i + 3]) for i in range(0, len(items), 3)]


def fit_picture(data: np.ndarray, curve, initial=None, title: str = "",
                extra: Sequence[str] = (), model_points: Optional[np.ndarray] = None) -> Picture:
    """The report picture of a fit (seed 000 Figure 5): data points (black squares),
    initial guess (green triangles), the fitted elastica (red), residual vectors
    from each data point to the curve, the curvature of the data polygon and of
    the fit, the fitted parameters and the ``extra`` lines (rms, status ...).
    ``model_points`` (n, 2): the curve point each data point's distance is measured to
    (FitResult.foot_points()); without them each residual goes to the nearest point of
    the curve's samples."""
    from .core import DiscreteElastica
    data = np.asarray(data, dtype=np.float64)[:, :2]
    pic = Picture(title=title)
    pic.layers.append(Layer(data, "data", "#000000", marker="s", size=3.5))
    if initial is not None:
        ixy, _, _, _ = _curve_samples(initial)
        pic.layers.append(Layer(ixy, "initial guess", "#2ca02c", marker="^" if isinstance(
            initial, DiscreteElastica) else "", line=True, size=3.5))
    xy, s, kappa, verts = _curve_samples(curve, 600)
    pic.layers.append(Layer(xy, "elastica", "#d62728", marker="o" if verts is not None else "",
                            line=True, size=3.0))
    if model_points is not None and len(model_points) == len(data):
        foot = np.asarray(model_points)   # the fit's own feet: the residual segments it reports
    elif verts is not None and len(verts) == len(data):
        foot = verts                      # the discrete fit pairs data point i with vertex i
    else:
        foot = closest_points(data, xy)
    pic.residuals = (data, foot)
    if len(data) >= 3:
        ds, dk = polygon_curvature(data)
        pic.graphs.append(Graph(ds, dk, "data polygon", "#7f7f7f", marker="s", line=False,
                                primary=False))
    pic.graphs.append(Graph(s, kappa, "elastica", "#d62728",
                            marker="o" if verts is not None else "", line=True))
    pic.params = _curve_params(curve) + list(extra)
    return pic


def curves_picture(curves: Sequence, labels: Sequence[str], points: Optional[np.ndarray] = None,
                   title: str = "", params: Sequence[str] = (),
                   point_label: str = "given points") -> Picture:
    """A picture of several curves (Hermite solutions, blends): each curve either an
    elastica or a tuple (xy (n,2), s (m,), kappa (m,)); ``points`` drawn as squares."""
    pic = Picture(title=title, params=list(params))
    if points is not None:
        pic.layers.append(Layer(np.asarray(points, dtype=np.float64), point_label, "#000000",
                                marker="s", size=4.0))
    for i, (c, lab) in enumerate(zip(curves, labels)):
        color = COLORS[i % len(COLORS)]
        if isinstance(c, tuple):
            xy, s, kappa = c
        else:
            xy, s, kappa, _ = _curve_samples(c, 400)
        pic.layers.append(Layer(np.asarray(xy), lab, color, line=True))
        if kappa is not None and len(kappa):
            pic.graphs.append(Graph(np.asarray(s), np.asarray(kappa), lab, color))
    return pic


def _kappa_limits(graphs: Sequence[Graph]) -> Tuple[float, float]:
    """y-range of the curvature panel: the primary graphs (the fitted curves) with a
    margin of half their span, so the noisy data polygon's curvature cannot squash them."""
    prim = [g.kappa for g in graphs if g.primary and len(g.kappa)] or \
        [g.kappa for g in graphs if len(g.kappa)]
    if not prim:
        return -1.0, 1.0
    k = np.concatenate(prim)
    k = k[np.isfinite(k)]
    if not k.size:
        return -1.0, 1.0
    lo, hi = float(k.min()), float(k.max())
    pad = max(0.5 * (hi - lo), 0.25 * max(abs(lo), abs(hi)), 1e-12)
    return lo - pad, hi + pad


# ------------------------------------------------------------- back ends

def have_matplotlib() -> bool:
    """True when matplotlib is importable and not disabled by LIBELASTICA_NO_MATPLOTLIB."""
    if os.environ.get("LIBELASTICA_NO_MATPLOTLIB"):
        return False
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        return False
    return True


MAX_MARKS = 2000        # markers (and residual segments) per point set a picture draws
MAX_VERTICES = 10000    # vertices per polyline (a g2quad of 50 edges: 10^4, drawn whole)


def _every(n: int, most: int) -> np.ndarray:
    """Indices of at most ``most`` of n items, evenly along them, first and last kept."""
    return np.unique(np.linspace(0, n - 1, most).round().astype(np.intp))


def thinned(pic: Picture) -> Picture:
    """The picture as it is visible (QA17 S1: 10^5 points drew 10^5 markers and residual
    segments, 38 MB of SVG in 11.6 s): each point set at most MAX_MARKS markers chosen
    evenly along it (residual segments with the data, the first layer), each polyline at
    most MAX_VERTICES vertices; a parameter line says how many were drawn. Pictures
    within these bounds are returned as they are."""
    def most(item) -> int:       # a Layer's or Graph's limit: vertices of a bare line, else marks
        return MAX_VERTICES if item.line and not item.marker else MAX_MARKS

    def thin(item, *fields):     # the item with its arrays ``fields`` cut to most(item)
        n = len(getattr(item, fields[0]))
        if n <= most(item):
            return item
        keep = _every(n, most(item))
        return replace(item, **{f: getattr(item, f)[keep] for f in fields})

    big = [len(L.xy) for L in pic.layers if len(L.xy) > most(L)]
    res = pic.residuals
    if res is not None and len(res[0]) > MAX_MARKS:
        big.append(len(res[0]))
        keep = _every(len(res[0]), MAX_MARKS)
        res = (res[0][keep], res[1][keep])
    if not big:
        return pic
    layers = [thin(L, "xy") for L in pic.layers]
    graphs = [thin(g, "s", "kappa") for g in pic.graphs]
    return Picture(pic.title, layers, res, graphs,
                   pic.params + [f"drawn: at most {MAX_MARKS} of the {max(big)} points, evenly"])


def save_picture(pic: Picture, path: PathLike) -> str:
    """Write the picture to ``path`` (.svg or .png, chosen by the suffix), thinned to what
    is visible (:func:`thinned`); returns the back end used ('svg': the built-in writer,
    always for an SVG; 'matplotlib': a PNG's). PNG without matplotlib raises InputError
    (one line, for the command line)."""
    suffix = Path(path).suffix.lower()
    if suffix not in (".svg", ".png"):
        raise InputError(f"{path}: picture must end in .svg or .png")
    pic = thinned(pic)
    if suffix == ".png" and have_matplotlib():
        _save_matplotlib(pic, path)
        return "matplotlib"
    if suffix == ".png":
        raise InputError(f"{path}: PNG pictures need matplotlib (pip install matplotlib); "
                         "--svg works without it")
    Path(path).write_text(_svg(pic), encoding="utf-8")
    return "svg"


_MPL_MARKERS = {"s": "s", "^": "^", "o": "o", "": None}


def _save_matplotlib(pic: Picture, path: PathLike) -> None:
    from matplotlib.figure import Figure   # no pyplot: no global state, no GUI back end
    fig = Figure(figsize=(11, 7.5), dpi=110)
    gs = fig.add_gridspec(2, 2, height_ratios=[2.2, 1], width_ratios=[2.2, 1])
    ax = fig.add_subplot(gs[0, :])
    axk = fig.add_subplot(gs[1, 0])
    axp = fig.add_subplot(gs[1, 1])
    if pic.residuals is not None:
        a, b = pic.residuals
        segs = np.stack([a, b], axis=1)
        from matplotlib.collections import LineCollection
        ax.add_collection(LineCollection(segs, colors="#1f77b4", linewidths=0.8,
                                         label="residuals"))
    for L in pic.layers:
        ax.plot(L.xy[:, 0], L.xy[:, 1], color=L.color, linestyle="-" if L.line else "none",
                marker=_MPL_MARKERS.get(L.marker), markersize=L.size, linewidth=1.2,
                markerfacecolor="none" if L.marker == "o" else L.color, label=L.label)
    ax.set_aspect("equal", adjustable="datalim")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="best", fontsize=8)
    if pic.title:
        ax.set_title(pic.title)
    for g in pic.graphs:
        axk.plot(g.s, g.kappa, color=g.color, linestyle="-" if g.line else "none",
                 marker=_MPL_MARKERS.get(g.marker), markersize=3, label=g.label)
    if pic.graphs:
        axk.set_ylim(*_kappa_limits(pic.graphs))
    axk.axhline(0.0, color="#999999", linewidth=0.6)
    axk.set_xlabel("arc length s")
    axk.set_ylabel("curvature κ")
    axk.grid(True, alpha=0.3)
    if pic.graphs:
        axk.legend(loc="best", fontsize=8)
    axp.axis("off")
    axp.text(0.0, 1.0, "\n".join(pic.params), va="top", ha="left", family="monospace",
             fontsize=8, transform=axp.transAxes)
    fig.tight_layout()
    fig.savefig(str(path))


# ---- the built-in SVG writer (no dependencies)

def _nice_ticks(lo: float, hi: float, n: int = 5) -> List[float]:
    if not (math.isfinite(lo) and math.isfinite(hi)) or hi <= lo:
        return [lo]
    raw = (hi - lo) / n
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=10 * mag)
    first = math.ceil(lo / step) * step
    return [first + i * step for i in range(int((hi - first) / step + 1e-9) + 1)]


class _Panel:
    """Maps data coordinates into a pixel box (y up), optionally with equal aspect."""

    def __init__(self, box, xs, ys, equal: bool, pad_y: float = 0.08):
        self.x, self.y, self.w, self.h = box
        xs = np.concatenate([np.ravel(v) for v in xs]) if xs else np.zeros(1)
        ys = np.concatenate([np.ravel(v) for v in ys]) if ys else np.zeros(1)
        xs, ys = xs[np.isfinite(xs)], ys[np.isfinite(ys)]
        x0, x1 = (float(xs.min()), float(xs.max())) if xs.size else (0.0, 1.0)
        y0, y1 = (float(ys.min()), float(ys.max())) if ys.size else (0.0, 1.0)
        if x1 - x0 < 1e-12:
            x0, x1 = x0 - 0.5, x1 + 0.5
        if y1 - y0 < 1e-12:
            y0, y1 = y0 - 0.5, y1 + 0.5
        px, py = 0.05 * (x1 - x0), pad_y * (y1 - y0)
        x0, x1, y0, y1 = x0 - px, x1 + px, y0 - py, y1 + py
        if equal:
            sx, sy = self.w / (x1 - x0), self.h / (y1 - y0)
            sc = min(sx, sy)
            cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
            x0, x1 = cx - 0.5 * self.w / sc, cx + 0.5 * self.w / sc
            y0, y1 = cy - 0.5 * self.h / sc, cy + 0.5 * self.h / sc
        self.x0, self.x1, self.y0, self.y1 = x0, x1, y0, y1

    def px(self, xy: np.ndarray) -> np.ndarray:
        xy = np.asarray(xy, dtype=np.float64)
        u = self.x + (xy[..., 0] - self.x0) / (self.x1 - self.x0) * self.w
        v = self.y + self.h - (xy[..., 1] - self.y0) / (self.y1 - self.y0) * self.h
        return np.stack([u, v], axis=-1)

    def frame(self, out: List[str], xlabel: str = "", ylabel: str = "") -> None:
        out.append(f'<rect x="{self.x:.1f}" y="{self.y:.1f}" width="{self.w:.1f}" '
                   f'height="{self.h:.1f}" fill="none" stroke="#444" stroke-width="0.8"/>')
        for t in _nice_ticks(self.x0, self.x1):
            u = self.px(np.array([t, self.y0]))[0]
            out.append(f'<line x1="{u:.1f}" y1="{self.y:.1f}" x2="{u:.1f}" '
                       f'y2="{self.y + self.h:.1f}" stroke="#ddd" stroke-width="0.5"/>')
            out.append(f'<text x="{u:.1f}" y="{self.y + self.h + 12:.1f}" font-size="9" '
                       f'text-anchor="middle">{t:.4g}</text>')
        for t in _nice_ticks(self.y0, self.y1):
            v = self.px(np.array([self.x0, t]))[1]
            out.append(f'<line x1="{self.x:.1f}" y1="{v:.1f}" x2="{self.x + self.w:.1f}" '
                       f'y2="{v:.1f}" stroke="#ddd" stroke-width="0.5"/>')
            out.append(f'<text x="{self.x - 4:.1f}" y="{v + 3:.1f}" font-size="9" '
                       f'text-anchor="end">{t:.4g}</text>')
        if xlabel:
            out.append(f'<text x="{self.x + self.w / 2:.1f}" y="{self.y + self.h + 26:.1f}" '
                       f'font-size="10" text-anchor="middle">{escape(xlabel)}</text>')
        if ylabel:
            out.append(f'<text x="{self.x - 40:.1f}" y="{self.y + self.h / 2:.1f}" font-size="10" '
                       f'text-anchor="middle" transform="rotate(-90 {self.x - 40:.1f} '
                       f'{self.y + self.h / 2:.1f})">{escape(ylabel)}</text>')


def _marks(out: List[str], pts: np.ndarray, marker: str, color: str, size: float) -> None:
    r = size / 2 + 0.5
    for u, v in pts:
        if marker == "s":
            out.append(f'<rect x="{u - r:.1f}" y="{v - r:.1f}" width="{2 * r:.1f}" '
                       f'height="{2 * r:.1f}" fill="{color}"/>')
        elif marker == "^":
            out.append(f'<path d="M{u:.1f},{v - r:.1f}L{u + r:.1f},{v + r:.1f}L{u - r:.1f},'
                       f'{v + r:.1f}Z" fill="{color}"/>')
        elif marker == "o":
            out.append(f'<circle cx="{u:.1f}" cy="{v:.1f}" r="{r:.1f}" fill="none" '
                       f'stroke="{color}" stroke-width="0.9"/>')


def _polyline(out: List[str], pts: np.ndarray, color: str, width: float = 1.2) -> None:
    pts = pts[np.all(np.isfinite(pts), axis=1)]
    if len(pts) < 2:
        return
    d = " ".join(f"{u:.2f},{v:.2f}" for u, v in pts)
    out.append(f'<polyline points="{d}" fill="none" stroke="{color}" stroke-width="{width}"/>')


def _legend(out: List[str], x: float, y: float, items) -> None:
    items = list(items)
    if not items:
        return
    w = 30 + 6.2 * max(len(it[0]) for it in items)
    out.append(f'<rect x="{x - 4:.1f}" y="{y - 9:.1f}" width="{w:.1f}" height="{14 * len(items) + 4}" '
               f'fill="white" fill-opacity="0.85" stroke="#ccc" stroke-width="0.5"/>')
    for i, (label, color, marker, line) in enumerate(items):
        yy = y + 14 * i
        if line:
            out.append(f'<line x1="{x:.1f}" y1="{yy:.1f}" x2="{x + 18:.1f}" y2="{yy:.1f}" '
                       f'stroke="{color}" stroke-width="1.5"/>')
        _marks(out, np.array([[x + 9, yy]]), marker, color, 4)
        out.append(f'<text x="{x + 24:.1f}" y="{yy + 3:.1f}" font-size="10">'
                   f'{escape(label)}</text>')


def _svg(pic: Picture) -> str:
    W, H = 1100, 760
    out = ['<?xml version="1.0" encoding="utf-8" standalone="no"?>',   # (as matplotlib's)
           f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
           f'viewBox="0 0 {W} {H}" font-family="sans-serif">',
           f'<rect width="{W}" height="{H}" fill="white"/>']
    if pic.title:
        out.append(f'<text x="{W / 2}" y="22" font-size="15" text-anchor="middle">'
                   f'{escape(pic.title)}</text>')
    # geometry panel
    xs = [L.xy[:, 0] for L in pic.layers]
    ys = [L.xy[:, 1] for L in pic.layers]
    geo = _Panel((60, 36, W - 90, 430), xs, ys, equal=True)
    geo.frame(out, "x", "y")
    if pic.residuals is not None:
        a, b = geo.px(pic.residuals[0]), geo.px(pic.residuals[1])
        for (u0, v0), (u1, v1) in zip(a, b):
            out.append(f'<line x1="{u0:.2f}" y1="{v0:.2f}" x2="{u1:.2f}" y2="{v1:.2f}" '
                       f'stroke="#1f77b4" stroke-width="0.8"/>')
    legend = []
    if pic.residuals is not None:
        legend.append(("residuals", "#1f77b4", "", True))
    for L in pic.layers:
        pts = geo.px(L.xy)
        if L.line:
            _polyline(out, pts, L.color)
        if L.marker:
            _marks(out, pts, L.marker, L.color, L.size)
        legend.append((L.label, L.color, L.marker, L.line))
    _legend(out, geo.x + 10, geo.y + 14, legend)
    # curvature panel
    if pic.graphs:
        lo, hi = _kappa_limits(pic.graphs)
        kp = _Panel((60, 510, 640, 200), [g.s for g in pic.graphs], [np.array([lo, hi])],
                    equal=False, pad_y=0.0)
        kp.frame(out, "arc length s", "curvature κ")
        if kp.y0 < 0 < kp.y1:
            _polyline(out, kp.px(np.array([[kp.x0, 0.0], [kp.x1, 0.0]])), "#999", 0.6)
        for g in pic.graphs:
            inside = (g.kappa >= lo) & (g.kappa <= hi)
            if not g.primary:
                g = Graph(g.s[inside], g.kappa[inside], g.label, g.color, g.marker, g.line)
            pts = kp.px(np.column_stack([g.s, g.kappa]))
            if g.line:
                _polyline(out, pts, g.color)
            if g.marker:
                _marks(out, pts, g.marker, g.color, 3)
        _legend(out, kp.x + 10, kp.y + 14,
                [(g.label, g.color, g.marker, g.line) for g in pic.graphs])
    # parameters
    for i, line in enumerate(pic.params):
        out.append(f'<text x="740" y="{520 + 14 * i}" font-size="11" font-family="monospace">'
                   f'{escape(line)}</text>')
    out.append("</svg>")
    return "\n".join(out) + "\n"
