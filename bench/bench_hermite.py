"""Hermite interpolation: all elastic curves per problem (libelastica, seed 004)
against one G1 clothoid per problem (PyPI `clothoids`, ClothoidCurve.build_G1),
same 10 000 random problems, same run, the two calls interleaved problem by
problem. Both are timed per call from Python (libelastica through cffi, so both
carry a call overhead of ~1 us). Then the cost of the Python API: `el.hermite`
against the bare C call on the same problems, alternately (and in alternating
order); the overhead is the median of the per-problem differences.

A process's timings on this machine are bimodal (the same code measures 4 or
17 us of overhead in two processes seconds apart, whatever the order), so the
measurement runs in RUNS fresh processes and each figure is the median over
them of the per-process figure (a ratio is formed within each process, from
calls interleaved problem by problem); the per-process values are listed too.
One JSON line per figure; "readme"/"value" mark the README's figures."""
import json
import subprocess
import sys
import time

import numpy as np

from libelastica._ffi import ffi, lib

N = 10000
RUNS = 5


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


def python_overhead(p1, a, b, sigma, n=3000):
    """Per-problem time of el.hermite minus that of the bare C call (cffi, buffers
    prepared once) on the same problem, the two alternately and in alternating order
    (the second call of a pair finds the caches warm)."""
    import libelastica as el
    opt = ffi.new("el_hermite_options *")
    lib.el_hermite_options_defaults(opt)
    res = ffi.new("el_hermite_result *")
    buf = ffi.new("double[8]")
    diff = np.empty(n)
    probs = [((0.0, 0.0), (float(np.cos(a[i])), float(np.sin(a[i]))), (float(p1[i, 0]), float(p1[i, 1])),
              (float(np.cos(b[i])), float(np.sin(b[i]))), float(sigma[i])) for i in range(n)]

    def bare(q0, t0, q1, t1, s):
        buf[0:8] = q0 + t0 + q1 + t1
        opt.sigma = s
        t = time.perf_counter_ns()
        lib.el_hermite_solve(buf, buf + 2, buf + 4, buf + 6, opt, res)
        lib.el_hermite_result_free(res)
        return time.perf_counter_ns() - t

    def api(q0, t0, q1, t1, s):
        t = time.perf_counter_ns()
        el.hermite(q0, t0, q1, t1, tension=s)
        return time.perf_counter_ns() - t

    for i, q in enumerate(probs):
        if i % 2:
            tc = bare(*q)
            tp = api(*q)
        else:
            tp = api(*q)
            tc = bare(*q)
        diff[i] = (tp - tc) * 1e-3
    return float(np.median(diff))


def one_process():
    """This process's figures (medians over its problems), as a dict."""
    p1, a, b, sigma = problems(N)
    ours, theirs, per = timed_calls(p1, a, b, sigma)
    out = {"ours_us": float(np.median(ours)), "solutions": per,
           "overhead_us": python_overhead(p1, a, b, sigma)}
    if theirs is not None:
        out["theirs_us"] = float(np.median(theirs))
        out["ratio"] = out["ours_us"] / out["theirs_us"]
    return out


def main():
    if sys.argv[1:] == ["--one-process"]:
        print(json.dumps(one_process()))
        return
    runs = [json.loads(subprocess.run([sys.executable, __file__, "--one-process"], check=True,
                                      capture_output=True, text=True).stdout) for _ in range(RUNS)]

    def median(key):
        return float(np.median([r[key] for r in runs]))

    def each(key, digits=2):
        return [round(r[key], digits) for r in runs]

    print(json.dumps({"bench": "hermite_all_solutions", "problems": N, "processes": RUNS,
                      "median_us": round(median("ours_us"), 2), "per_process_us": each("ours_us"),
                      "mean_solutions": round(runs[0]["solutions"], 2)}))
    over = median("overhead_us")
    print(json.dumps({"bench": "hermite_python_overhead", "problems": 3000, "processes": RUNS,
                      "median_us": round(over, 2), "per_process_us": each("overhead_us"),
                      "target": 10, "readme": "Python overhead of `el.hermite` (over the C call)",
                      "value": f"{over:.1f} us (median of {RUNS} processes: "
                               f"{min(each('overhead_us', 1))}-{max(each('overhead_us', 1))})"}))
    if "ratio" not in runs[0]:
        print(json.dumps({"bench": "clothoids_build_G1", "status": "unavailable (pip install clothoids)"}))
        return
    print(json.dumps({"bench": "clothoids_build_G1", "problems": N, "processes": RUNS,
                      "median_us": round(median("theirs_us"), 2), "per_process_us": each("theirs_us")}))
    ratio = median("ratio")
    print(json.dumps({"bench": "hermite_vs_clothoids_ratio", "processes": RUNS, "ratio": round(ratio, 2),
                      "per_process": each("ratio"), "target": 10,
                      "readme": "all Hermite solutions by tension against one G1 clothoid (PyPI `clothoids`)",
                      "value": f"{ratio:.1f}x (median of {RUNS} processes: "
                               f"{min(each('ratio', 1))}-{max(each('ratio', 1))}x)"}))


if __name__ == "__main__":
    main()
