"""Elliptic blending curves (seed 003): basis set-up, evaluation, and B-spline
conversion of the rope example (poles and time per tolerance). JSON lines."""
import json
import time

import numpy as np

import libelastica as el


def median_ms(fn, repeat=21):
    ts = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        ts.append(time.perf_counter() - t0)
    return round(1e3 * float(np.median(ts)), 4)


def main():
    rope = el.EllipticBlend(m=0.3, d=2.0)           # the paper's (k, d) = (0.3, 2), k read as m
    coeffs = np.array([[0.0, 0.0], [0.0, 0.0], [0.0, 1.0], [1.0, 0.0]])
    q = rope.control_points(coeffs)                   # C(t) = (t, sn(Kt)) in the basis
    t = np.linspace(0, 1, 1000)
    print(json.dumps({"bench": "blend", "what": "basis_setup", "median_ms": median_ms(
        lambda: el.EllipticBlend(m=0.3, d=2.0))}))
    print(json.dumps({"bench": "blend", "what": "evaluate", "n": 1000,
                      "median_ms": median_ms(lambda: rope.evaluate(q, t))}))
    for tol in (1e-3, 1e-6, 1e-9):
        b = rope.to_bspline(q, tol)
        print(json.dumps({"bench": "blend", "what": "rope_to_bspline", "tol": tol,
                          "poles": int(len(b.poles)), "max_deviation": b.max_deviation,
                          "median_ms": median_ms(lambda: rope.to_bspline(q, tol), repeat=5)}))


if __name__ == "__main__":
    main()
