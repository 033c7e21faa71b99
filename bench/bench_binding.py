"""Binding overhead: a 1000-point fit through the Python API (libelastica.fit:
numpy checks, option and result structs, FitResult objects) against the same fit
called straight into the C library (el_fit_discrete / el_fit_smooth through cffi
with the buffers and options prepared beforehand, so only the C call is timed).
Target: Python within 1.2x of C. Prints one JSON line per model:
{"bench": "binding_fit", "model": ..., "n": 1000, "c_min_ms": ..., "py_min_ms": ...,
 "c_median_ms": ..., "py_median_ms": ..., "ratio": py_min / c_min, "target_ratio": 1.2}."""
from __future__ import annotations

import json
import statistics
import time

import numpy as np

import libelastica as el
from libelastica._ffi import dptr, ffi, lib

N = 1000
REPEAT = 15


def data(model: str) -> np.ndarray:
    rng = np.random.default_rng(1000)
    if model == "discrete":
        c = el.DiscreteElastica(x0=0, y0=0, h=0.01, phi=0.2, z=0.003, q=0.4, k=0.8, n=N)
        pts = c.points()
    else:
        c = el.SmoothElastica(x0=0, y0=0, phi=0.2, mu=0.09, k=0.8, q=0.4, length=10.0)
        pts = c.points(np.linspace(0, c.length, N))
    return np.ascontiguousarray(pts + rng.normal(0, 1e-3, pts.shape))


def times_ms(fa, fb):
    """Times (ms) of fa and fb, called alternately so that machine load hits both
    alike; one warm-up call each (the first loads Ipopt's solvers)."""
    fa()
    fb()
    ta, tb = [], []
    for _ in range(REPEAT):
        for fn, ts in ((fa, ta), (fb, tb)):
            t0 = time.perf_counter()
            fn()
            ts.append(1e3 * (time.perf_counter() - t0))
    return ta, tb


def main() -> None:
    for model in ("discrete", "smooth"):
        pts = data(model)
        opt = ffi.new("el_fit_options *")
        lib.el_fit_options_defaults(opt)
        res = ffi.new(f"el_fit_{model}_result *")
        cfit = lib.el_fit_discrete if model == "discrete" else lib.el_fit_smooth
        xy = dptr(pts)
        dist, foot = ffi.new("double[]", N), ffi.new("double[]", N)   # as el.fit, which reports both

        def c_call():
            cfit(xy, N, opt, ffi.NULL, res, dist, foot)

        def py_call():
            el.fit(pts, model=model)

        tc, tp = times_ms(c_call, py_call)
        # the ratio of the minima is the overhead itself (timeit's advice: the minimum is
        # the run least disturbed by other processes); the medians are printed beside it
        print(json.dumps({"bench": "binding_fit", "model": model, "n": N,
                          "c_min_ms": round(min(tc), 3), "py_min_ms": round(min(tp), 3),
                          "c_median_ms": round(statistics.median(tc), 3),
                          "py_median_ms": round(statistics.median(tp), 3),
                          "ratio": round(min(tp) / min(tc), 3), "target_ratio": 1.2}))


if __name__ == "__main__":
    main()
