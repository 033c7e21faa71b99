"""Hermite interpolation: all elastic curves per problem (libelastica, seed 004)
against one G1 clothoid per problem (PyPI `clothoids`, ClothoidCurve.build_G1),
same 10 000 random problems, same run, the two calls interleaved problem by
problem. Both are timed per call from Python (libelastica through cffi, so both
carry a call overhead of ~1 us).
One JSON line per figure."""
import json
import time

import numpy as np

from libelastica._ffi import ffi, lib

N = 10000


def problems(n, seed=2024):
    rng = np.random.default_rng(seed)
    p1 = rng.uniform(-1, 1, (n, 2))
    a = rng.uniform(-np.pi, np.pi, n)
    b = rng.uniform(-np.pi, np.pi, n)
    d = np.hypot(p1[:, 0], p1[:, 1])
    sigma = rng.uniform(-10, 40, n) / d ** 2
    return p1, a, b, sigma


def timed_calls(p1, a, b, sigma):
    """Per-problem call times of libelastica (all solutions) and, when installed,
    of Clothoids.ClothoidCurve().build_G1 (one G1 clothoid), interleaved problem
    by problem so that both see the same machine state (this machine is noisy)."""
    opt = ffi.new("el_hermite_options *")
    lib.el_hermite_options_defaults(opt)
    res = ffi.new("el_hermite_result *")
    q0 = ffi.new("double[2]", [0.0, 0.0])
    t0, q1, t1 = ffi.new("double[2]"), ffi.new("double[2]"), ffi.new("double[2]")
    try:
        import Clothoids  # PyPI package `clothoids`
        curve = Clothoids.ClothoidCurve()
    except ImportError:
        curve = None
    ours = np.empty(len(a))
    theirs = np.empty(len(a)) if curve is not None else None
    x1, y1 = p1[:, 0].tolist(), p1[:, 1].tolist()
    aa, bb = a.tolist(), b.tolist()
    nsol = 0
    for i in range(len(a)):
        t0[0], t0[1] = np.cos(a[i]), np.sin(a[i])
        t1[0], t1[1] = np.cos(b[i]), np.sin(b[i])
        q1[0], q1[1] = x1[i], y1[i]
        opt.sigma = sigma[i]
        t = time.perf_counter_ns()
        st = lib.el_hermite_solve(q0, t0, q1, t1, opt, res)
        ours[i] = (time.perf_counter_ns() - t) * 1e-3
        if st == 0:
            nsol += res.count
            lib.el_hermite_result_free(res)
        if curve is not None:
            t = time.perf_counter_ns()
            curve.build_G1(0.0, 0.0, aa[i], x1[i], y1[i], bb[i])
            theirs[i] = (time.perf_counter_ns() - t) * 1e-3
    return ours, theirs, nsol / len(a)


def main():
    p1, a, b, sigma = problems(N)
    ours, theirs, per = timed_calls(p1, a, b, sigma)
    print(json.dumps({"bench": "hermite_all_solutions", "problems": N,
                      "median_us": round(float(np.median(ours)), 2), "mean_solutions": round(per, 2)}))
    if theirs is None:
        print(json.dumps({"bench": "clothoids_build_G1", "status": "unavailable (pip install clothoids)"}))
        return
    print(json.dumps({"bench": "clothoids_build_G1", "problems": N,
                      "median_us": round(float(np.median(theirs)), 2)}))
    ratio = float(np.median(ours) / np.median(theirs))
    print(json.dumps({"bench": "hermite_vs_clothoids_ratio",
                      "ratio": round(ratio, 2), "target": 20,
                      "readme": "all Hermite solutions of one problem",
                      "value": f"{float(np.median(ours)):.0f} us ({per:.1f} solutions on average); "
                               f"{ratio:.0f}x one G1 clothoid (PyPI `clothoids`)"}))


if __name__ == "__main__":
    main()
