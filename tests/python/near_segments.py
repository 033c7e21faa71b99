"""The segments of a dense polyline that can hold a point's nearest point, for the tests'
brute-force distances (test_cli_step, test_cubic): every segment looked at is 40 000 of
them a point; these are the few within reach, found by scipy's k-d tree, so the distance
measured over them is the same number as over all (the nearest segment is among them)."""
from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree


def candidate_segments(points, V):
    """For each point, the indices of the segments V[j]-V[j+1] that can hold its nearest point
    on the polyline V: that point q lies on a segment of length <= L (the longest), so its
    start is within |p - q| + L <= dv + L of p (dv: the nearest vertex's distance, no less
    than |p - q|); the segment ending at such a vertex is taken too."""
    V = np.asarray(V, dtype=float)
    nseg = len(V) - 1
    L = float(np.sqrt(np.max(np.sum(np.diff(V, axis=0) ** 2, axis=1))))
    tree = cKDTree(V)
    dv = tree.query(points)[0]
    out = []
    for p, r in zip(points, dv):
        j = np.asarray(tree.query_ball_point(p, (r + L) * (1 + 1e-9) + 1e-300), dtype=int)
        j = np.unique(np.concatenate([j, j - 1]))
        out.append(j[(j >= 0) & (j < nseg)])
    return out
