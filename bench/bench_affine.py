"""Seed 002 benchmark: the Table 1 analogue (k_i A^(-2/3) against the exact affine curvature
of an elastica, with the observed order) and the cost of the §4 algorithm. JSON lines."""
import json
import time

import numpy as np

import libelastica as el


def table(name, curve, ns, away=0.0, **kw):
    infl = el.elastica_inflections(curve)
    prev = None
    for n in ns:
        r = el.affine_polyline(curve, n, **kw)
        i, km = r.middle_curvature()
        smid = np.array([r.s[j - 1:j + 3].mean() for j in i])
        exact = el.elastica_affine_curvature(curve, smid)
        mask = np.ones(len(i), bool)
        for s0 in infl:
            mask &= np.abs(smid - s0) > away
        err = float(np.abs(km - exact)[mask].max())
        print(json.dumps({"bench": "affine_table", "curve": name, "n": n, "max_err": err,
                          "rel_err": err / float(np.abs(exact[mask]).max()),
                          "order": None if prev is None else round(float(np.log2(prev / err)), 3),
                          "psi": [float(p) for p in r.psi]}))
        prev = err


def timing(name, fn, repeat=15):
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    print(json.dumps({"bench": name, "median_ms": round(1e3 * float(np.median(ts)), 3)}))


def main():
    loop = el.SmoothElastica(0, 0, 0, 1.0, 1.3, 0.3, 4.0)
    wave = el.SmoothElastica(0, 0, 0, 1.0, 0.7, 0.3, 6.0)
    table("elastica k=1.3, exact tangents", loop, (15, 30, 60, 120, 240))
    table("elastica k=1.3, paper tangents", loop, (15, 30, 60, 120, 240), exact_tangents=False)
    table("elastica k=0.7, skip_frac=0.2", wave, (15, 30, 60, 120, 240), away=0.8, skip_frac=0.2)
    table("elastica k=0.7, paper skip l=2", wave, (15, 30, 60, 120, 240), away=0.8)
    timing("affine_polyline_n60_k1.3", lambda: el.affine_polyline(loop, 60))
    timing("affine_polyline_n60_k0.7_fit_ends", lambda: el.affine_polyline(wave, 60, skip_frac=0.2,
                                                                          fit_ends=True))
    pts = el.affine_polyline(loop, 60).points
    timing("quadratic_bspline_n60", lambda: el.quadratic_bspline(pts), repeat=100)
    # g2_quadratic at many edges: its deviation's nearest-point search (report.closest_points,
    # branch and bound; 34 s at n = 1000 when every segment was tried for every point);
    # n = 24, a glyph's S (QA25 F6: 84 ms CPU a call when ~230 splines were built in
    # g2ends' end searches, one per trial)
    s_curve = el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=0.8, q=-0.6, length=4.0)
    for n, repeat in ((24, 20), (1000, 3), (5000, 1)):
        ts = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            el.g2_quadratic(s_curve, n)
            ts.append(time.perf_counter() - t0)
        print(json.dumps({"bench": "g2_quadratic", "n": n, "median_ms": round(1e3 * float(np.median(ts)), 3)}))


if __name__ == "__main__":
    main()
