"""Benchmark of the fit (issues 3, 13, 16): a seeded suite of discrete and smooth
elasticae, k from 0.1 to 30 (log-uniform), 1-3 monotone pieces, 20-5000 points,
random similarity transforms, noise 0, 0.1 % and 1 % of the length; the smooth
model is fitted by orthogonal distance (the default), the discrete one paired.

Prints one JSON line per figure, baselines measured in the same run:
  fit_success       success rates (noise-free: rms <= 1e-8 length; noisy: rms <= 1.2 x
                    the rms of the noise actually added, both measured as the fit
                    measures: paired for the discrete model, along the normal for the
                    orthogonal smooth fit)
  fit_time, fit     median / p95 wall and process-CPU time per size and model (the C
                    call through cffi)
  fit_orthogonal_ratio  the smooth fits of 1000 noisy points by orthogonal distance
                    against the paired fits of the same points (target <= 2x)
  fit_scipy_lm_ratio    el.fit of 1000 noisy points (discrete) against
                    scipy.optimize.least_squares(method="lm") given the library's own
                    model and Jacobian (el_discrete_eval / el_discrete_jacobian) and the
                    library's initial guess (target: el.fit >= 3x faster); the median of
                    the per-curve ratios in each of several fresh processes, and the
                    median, min and max over the processes
  fit_keyline       the keyline of 1000-point scans as one G2 problem, both models,
                    against the two sides fitted apart (target < 20 ms)
  fit_lbfgs_ratio   a few of the same fits with Ipopt's limited-memory Hessian (the
                    paper's setting)
  fit_breakdown     where the time of a 1000-point fit goes (guess, iterations)
  fit_constrained   end constraints a designer sets: time against the free fit, rms, and
                    el.fit's check of what they cost (check_ends: one more, free, fit)
  fit_discrete_uneven  the discrete default on uneven points: rms / noise, orthogonal
                    against paired
bench/bench_fit.c has the C-side figures (threads, memory, scaling, formulation).
Environment: BENCH_FIT_QUICK=1 for a small suite.
"""
from __future__ import annotations

import json
import os
import sys
import time
import warnings

# OpenBLAS worker threads spin after numpy/scipy calls and would be charged to
# this process's CPU time (and steal a core from the fits): one thread.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

import numpy as np
from scipy.optimize import least_squares
from scipy.special import ellipk

import libelastica as el
from libelastica._ffi import dptr, ffi, lib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "python"))
from keyline_data import keyline_3d  # noqa: E402  (generated scan, independent of the library)

SEED = 20240603
SIZES = (20, 100, 1000, 5000)
NOISES = (0.0, 1e-3, 1e-2)


def half_period(k):
    return 2 * ellipk(k * k) if k < 1 else 2 * ellipk(1 / k ** 2) / k


def make_curve(model, k, n, pieces, rng):
    """Points (n, 2) of a random elastica, transformed by a random similarity."""
    span = pieces * half_period(k) * rng.uniform(0.8, 1.0)
    if model == "discrete":
        c = el.DiscreteElastica(x0=0, y0=0, h=1.0 / n, phi=rng.uniform(-np.pi, np.pi),
                                z=rng.choice([-1.0, 1.0]) * span / (n - 1),
                                q=rng.uniform(-2, 2), k=k, n=n)
        pts = c.points()
    else:
        mu = rng.uniform(0.5, 2.0)
        c = el.SmoothElastica(x0=0, y0=0, phi=rng.uniform(-np.pi, np.pi), mu=mu, k=k,
                              q=rng.uniform(-2, 2), length=span / np.sqrt(mu))
        pts = c.points(np.linspace(0, c.length, n))
    scale = 10.0 ** rng.uniform(-3, 3)
    a = rng.uniform(-np.pi, np.pi)
    R = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
    pts = scale * pts @ R.T + scale * rng.uniform(-10, 10, 2)
    return np.ascontiguousarray(pts)


def c_fit(model, pts, limited_memory=False, max_iter=200, distance=None, max_candidates=None):
    """The C fit through cffi: (status, result, (wall s, CPU s)). The discrete model
    paired (seed 000 (4.6), the suite's measure): the suite's points are taken at equal
    steps, which the library's default pairs too, but for a few short noisy ones whose
    spacing looks uneven."""
    opt = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(opt)
    if max_candidates:
        opt.max_candidates = max_candidates
    opt.limited_memory = 1 if limited_memory else 0
    opt.max_iter = max_iter
    if distance == "paired" or model == "discrete":
        opt.distance = lib.EL_DISTANCE_PAIRED
    n = pts.shape[0]
    ptr = dptr(pts)
    res = ffi.new(f"el_fit_{model}_result *")
    call = lib.el_fit_discrete if model == "discrete" else lib.el_fit_smooth
    c0, t0 = time.process_time(), time.perf_counter()
    st = call(ptr, n, opt, ffi.NULL, res, ffi.NULL, ffi.NULL)
    dt, dc = time.perf_counter() - t0, time.process_time() - c0
    return st, res, (dt, dc)


def median_ms(v):
    return round(1e3 * float(np.median(v)), 3)


def suite(per_cell):
    rng = np.random.default_rng(SEED)
    rows = []
    for model in ("discrete", "smooth"):
        for n in SIZES:
            for noise in NOISES:
                for _ in range(per_cell):
                    k = float(np.exp(rng.uniform(np.log(0.1), np.log(30.0))))
                    pieces = int(rng.integers(1, 4))
                    clean = make_curve(model, k, n, pieces, rng)
                    L = float(np.sum(np.linalg.norm(np.diff(clean, axis=0), axis=1)))
                    pts = clean + rng.normal(0, noise * L / np.sqrt(2), clean.shape) if noise else clean
                    pts = np.ascontiguousarray(pts)
                    noise_rms = noise_measure(model, pts, clean)
                    st, res, dt = c_fit(model, pts)
                    rms = fit_measure(model, res, pts)
                    rows.append(dict(model=model, n=n, noise=noise, k=k, pieces=pieces,
                                     ok=bool(good(rms, L, noise, noise_rms)),
                                     t=dt[0], cpu=dt[1], pts=pts, L=L, noise_rms=noise_rms,
                                     status=st, rms=rms, ipopt=bool(res.used_ipopt)))
    return rows


def noise_measure(model, pts, clean):
    """The rms of the noise as the fit measures it: paired (discrete), the whole
    displacement of each point; orthogonal (smooth), its part along the true curve's
    normal (central differences of the clean samples)."""
    e = pts - clean
    if model == "discrete":
        return float(np.sqrt(np.mean(np.sum(e ** 2, axis=1))))
    t = np.gradient(clean, axis=0)
    t /= np.linalg.norm(t, axis=1)[:, None]
    return float(np.sqrt(np.mean((e[:, 0] * -t[:, 1] + e[:, 1] * t[:, 0]) ** 2)))


def fit_measure(model, res, pts):
    """The fitted curve's rms in the same measure: paired distances of the vertices
    (discrete; the result's rms is to the polygon, which is smaller), the reported
    point-to-curve rms (smooth)."""
    if model != "discrete":
        return float(res.rms)
    V = np.empty_like(pts)
    if lib.el_discrete_eval(ffi.addressof(res.params), len(pts), dptr(V)) != lib.EL_OK:
        return np.inf
    return float(np.sqrt(np.mean(np.sum((V - pts) ** 2, axis=1))))


def good(rms, L, noise, noise_rms):
    """Noise-free: rms <= 1e-8 L; noisy: rms <= 1.2 x the noise in the same measure."""
    return rms <= 1e-8 * L if noise == 0 else rms <= 1.2 * noise_rms


def report_suite(rows):
    print(json.dumps({"bench": "fit_suite", "curves": len(rows), "seed": SEED}))
    rates = {}
    for noise in NOISES:
        sel = [r for r in rows if r["noise"] == noise]
        rates[noise] = float(np.mean([r["ok"] for r in sel]))
        by_model = {m: round(float(np.mean([r["ok"] for r in sel if r["model"] == m])), 4)
                    for m in ("discrete", "smooth")}
        print(json.dumps({"bench": "fit_success", "noise": noise, "curves": len(sel),
                          "success_rate": round(rates[noise], 4), "by_model": by_model,
                          "ipopt_used": int(sum(r["ipopt"] for r in sel)),
                          "target": 0.99 if noise == 0 else 0.97}))
        for r in [r for r in sel if not r["ok"]][:5]:
            print(json.dumps({"bench": "fit_failure", "model": r["model"], "n": r["n"],
                              "noise": noise, "k": round(r["k"], 4), "pieces": r["pieces"],
                              "status": r["status"],
                              "rms_rel": r["rms"] / (r["L"] if noise == 0 else r["noise_rms"])}))
    # wall time and process CPU time (the CPU figure is robust against other
    # processes sharing the machine)
    for model in ("discrete", "smooth"):
        for n in SIZES:
            sel = [r for r in rows if r["model"] == model and r["n"] == n]
            ts = np.array([r["t"] for r in sel]) * 1e3
            cs = np.array([r["cpu"] for r in sel]) * 1e3
            print(json.dumps({"bench": "fit_time", "model": model, "n": n,
                              "distance": "paired" if model == "discrete" else "orthogonal",
                              "median_ms": round(float(np.median(ts)), 3),
                              "p95_ms": round(float(np.percentile(ts, 95)), 3),
                              "median_cpu_ms": round(float(np.median(cs)), 3),
                              "p95_cpu_ms": round(float(np.percentile(cs, 95)), 3)}))
    md = {m: median_ms([r["cpu"] for r in rows if r["n"] == 1000 and r["model"] == m])
          for m in ("discrete", "smooth")}
    pct = ", ".join(f"{100 * rates[x]:.0f} %" for x in NOISES)
    print(json.dumps({"bench": "fit", "n": 1000, "median_cpu_ms": md, "target_ms": 3.0,
                      "readme": "fit of 1000 points (504-curve suite)",
                      "value": f"{md['discrete']:.1f} ms discrete, {md['smooth']:.1f} ms smooth "
                               f"(orthogonal); success {pct} at noise 0, 0.1 %, 1 %"}))


def orthogonal_ratio(rows):
    """The same smooth points (1000, noisy) by orthogonal distance and paired."""
    sel = [r for r in rows if r["model"] == "smooth" and r["n"] == 1000 and r["noise"] > 0]
    t_o, t_p = [], []
    for r in sel:
        t_o.append(min(c_fit("smooth", r["pts"])[2][1] for _ in range(3)))
        t_p.append(min(c_fit("smooth", r["pts"], distance="paired")[2][1] for _ in range(3)))
    mo, mp = median_ms(t_o), median_ms(t_p)
    ratio = float(np.median(np.array(t_o) / np.array(t_p)))
    print(json.dumps({"bench": "fit_orthogonal_ratio", "curves": len(sel), "n": 1000,
                      "median_cpu_ms_orthogonal": mo, "median_cpu_ms_paired": mp,
                      "median_ratio": round(ratio, 2), "target_ratio": 2.0,
                      "readme": "smooth fit of 1000 noisy points, orthogonal / paired",
                      "value": f"{mo:.1f} ms / {mp:.1f} ms (median ratio {ratio:.1f}x; target 2x)"}))


def scipy_lm_times(curves):
    """One process's measurement: for each curve (pts, L, noise, noise_rms) el.fit paired
    and least_squares('lm') with the library's model, Jacobian and start, timed in turn
    (process CPU time); a warm-up of both on the first curve is not counted."""
    out = []
    for idx, (pts, L, noise, noise_rms) in enumerate([curves[0]] + list(curves)):
        n = len(pts)
        c0 = time.process_time()
        f = el.fit(pts, distance="paired")      # scipy's problem: vertex i <-> point i
        t_el = time.process_time() - c0
        xy, J = np.empty((n, 2)), np.empty((n, 2, 7))
        prm = ffi.new("el_discrete_params *")

        def setp(p):
            prm.x0, prm.y0, prm.h, prm.phi, prm.z, prm.q, prm.k = p

        def fun(p):
            setp(p)
            if lib.el_discrete_eval(prm, n, dptr(xy)) != lib.EL_OK:
                return np.full(2 * n, 1e6)
            return (xy - pts).ravel()

        def jac(p):
            setp(p)
            lib.el_discrete_jacobian(prm, n, ffi.NULL, dptr(J))
            return J.reshape(2 * n, 7)

        p0 = np.array([getattr(f.initial, a) for a in ("x0", "y0", "h", "phi", "z", "q", "k")])
        c0 = time.process_time()
        s = least_squares(fun, p0, jac=jac, method="lm", xtol=1e-15, ftol=1e-15, gtol=1e-15)
        t_sp = time.process_time() - c0
        if idx == 0:
            continue                            # the warm-up
        rms_sp = float(np.sqrt(2 * s.cost / n))
        rms_el = float(np.sqrt(np.mean(np.sum((f.curve.points() - pts) ** 2, axis=1))))
        out.append(dict(t_el=t_el, t_sp=t_sp, ok_el=bool(good(rms_el, L, noise, noise_rms)),
                        ok_sp=bool(good(rms_sp, L, noise, noise_rms)), rel=rms_el / rms_sp - 1.0))
    return out


def scipy_lm_ratio(rows, quick):
    """el.fit against least_squares('lm') with the library's model, Jacobian and start.
    A process's Python timing is bimodal (the same code measured 7 or 16 us on
    el.hermite, seconds apart), so the measurement runs in several fresh processes
    (scipy_lm_times, the two timed in turn on each curve): the figure is the median over
    the processes of each one's median per-curve ratio, with their min and max."""
    import pickle
    import subprocess
    import tempfile
    sel = [r for r in rows if r["model"] == "discrete" and r["n"] == 1000 and r["noise"] > 0]
    if quick:
        sel = sel[:4]
    curves = [(r["pts"], r["L"], r["noise"], r["noise_rms"]) for r in sel]
    procs = 3 if quick else 7
    runs = []
    with tempfile.TemporaryDirectory() as tmp:
        data = os.path.join(tmp, "curves.pickle")
        with open(data, "wb") as fh:
            pickle.dump(curves, fh)
        for _ in range(procs):
            got = subprocess.run([sys.executable, os.path.abspath(__file__), "--scipy-lm-worker", data],
                                 check=True, capture_output=True, text=True).stdout
            runs.append(json.loads(got.strip().splitlines()[-1]))
    t_el = np.array([[c["t_el"] for c in run] for run in runs])      # (processes, curves)
    t_sp = np.array([[c["t_sp"] for c in run] for run in runs])
    ratios = np.median(t_sp / t_el, axis=1)                          # one per process
    ratio = float(np.median(ratios))
    me, ms = median_ms(np.median(t_el, axis=0)), median_ms(np.median(t_sp, axis=0))
    first = runs[0]                                                  # the fits are the same in each
    ok_el, ok_sp = sum(c["ok_el"] for c in first), sum(c["ok_sp"] for c in first)
    print(json.dumps({"bench": "fit_scipy_lm_ratio", "curves": len(sel), "n": 1000, "processes": procs,
                      "median_cpu_ms_el_fit": me, "median_cpu_ms_scipy_lm": ms,
                      "median_ratio": round(ratio, 2), "process_ratio_min": round(float(ratios.min()), 2),
                      "process_ratio_max": round(float(ratios.max()), 2), "target_ratio": 3.0,
                      "el_success_rate": round(ok_el / len(sel), 3),
                      "scipy_success_rate": round(ok_sp / len(sel), 3),
                      "median_paired_rms_el_over_scipy_minus_1": float(np.median([c["rel"] for c in first])),
                      "readme": "`el.fit` of 1000 noisy points vs scipy `least_squares('lm')` "
                                "(same Jacobian, same start)",
                      "value": f"{me:.1f} ms vs {ms:.1f} ms ({ratio:.1f}x faster, median of {procs} processes, "
                               f"{ratios.min():.1f}-{ratios.max():.1f}x; "
                               f"success {100 * ok_el / len(sel):.0f} % / {100 * ok_sp / len(sel):.0f} %)"}))


def keyline(quick):
    """1000-point scans (seed 000 §5: 300 mm, noise 0.3 mm, 5 seeds): one G2 problem, and
    for scale the two sides of the resampled polygon (~20 vertices each, r = length/100)
    fitted alone after the same preparation (the smooth joint fit takes the raw points). Per scan the fastest of a few
    runs; the median over the scans."""
    scans = [keyline_3d(n=1000, seed=seed).xyz for seed in range(2 if quick else 5)]
    reps = 2 if quick else 5
    out = {}
    for model in ("discrete", "smooth"):
        tj, ta, worst, ipopt = [], [], 0.0, False
        for xyz in scans:
            best_j = best_a = np.inf
            for _ in range(reps):
                c0 = time.process_time()
                kf = el.fit_keyline(xyz, model=model)
                best_j = min(best_j, time.process_time() - c0)
                c0 = time.process_time()
                r = float(np.sum(np.linalg.norm(np.diff(xyz, axis=0), axis=1))) / 100.0
                for side in el.prepare_keyline(xyz, r, 0).sides():
                    el.fit(side, model=model)
                best_a = min(best_a, time.process_time() - c0)
            tj.append(best_j)
            ta.append(best_a)
            worst = max(worst, kf.first.rms, kf.second.rms)
            ipopt |= kf.first.used_ipopt
        out[model] = dict(joint_ms=median_ms(tj), joint_max_ms=round(1e3 * max(tj), 3),
                          apart_ms=median_ms(ta), worst_rms_mm=round(worst, 4), ipopt=bool(ipopt))
    d, s = out["discrete"], out["smooth"]
    print(json.dumps({"bench": "fit_keyline", "points": 1000, "scans": len(scans), "noise_mm": 0.3, **out,
                      "target_ms": 20,
                      "readme": "keyline of a 1000-point scan as one G2 curve",
                      "value": f"{d['joint_ms']:.1f} ms discrete, {s['joint_ms']:.1f} ms smooth "
                               f"(the two sides of the resampled polygon fitted alone: {d['apart_ms']:.1f} / {s['apart_ms']:.1f} ms)"}))


def lbfgs_ratio(rows, quick):
    """A few 1000-point discrete fits with Ipopt's L-BFGS Hessian against the library's."""
    sel = [r for r in rows if r["model"] == "discrete" and r["n"] == 1000][::7][: 3 if quick else 9]
    t_gn, t_lm, ok = [], [], 0
    for r in sel:
        t_gn.append(c_fit("discrete", r["pts"])[2][1])
        # from the best guess only (3000 iterations for each further guess would
        # dominate the figure)
        _, res, dt = c_fit("discrete", r["pts"], limited_memory=True, max_iter=3000, max_candidates=1)
        t_lm.append(dt[1])
        ok += good(fit_measure("discrete", res, r["pts"]), r["L"], r["noise"], r["noise_rms"])
    ratio = float(np.median(t_lm) / np.median(t_gn))
    print(json.dumps({"bench": "fit_lbfgs_ratio", "curves": len(sel), "n": 1000,
                      "median_cpu_ms": median_ms(t_gn), "median_cpu_ms_lbfgs": median_ms(t_lm),
                      "ratio_of_medians": round(ratio, 1), "lbfgs_success_rate": round(ok / len(sel), 3),
                      "readme": "same fits with Ipopt's L-BFGS (the paper's setting)",
                      "value": f"{ratio:.0f}x slower"}))


def breakdown(rows):
    """Where the time of a 1000-point fit goes: the automatic guess and the rest."""
    for model in ("discrete", "smooth"):
        sel = [r for r in rows if r["model"] == model and r["n"] == 1000]
        tg, its = [], []
        for r in sel:
            pts = r["pts"]
            n = len(pts)
            cnt = ffi.new("size_t *")
            cand = ffi.new(f"el_{model}_params[6]")
            c0 = time.process_time()
            if model == "discrete":
                lib.el_guess_discrete(dptr(pts), n, cand, 6, cnt)
            else:
                lib.el_guess_smooth(dptr(pts), n, 0, cand, 6, cnt)
            tg.append(time.process_time() - c0)
            its.append(c_fit(model, pts)[1].iterations)
        print(json.dumps({"bench": "fit_breakdown", "model": model, "n": 1000,
                          "median_fit_cpu_ms": median_ms([r["cpu"] for r in sel]),
                          "median_guess_cpu_ms": median_ms(tg),
                          "median_iterations": float(np.median(its))}))


def constrained(quick):
    """Constrained fits a designer sets (issue 13): 40 points sketched along an S with both
    ends pinned at zero curvature (free ends), and 165 noisy points whose start tangent is
    0.2 rad off the data's with the end pinned; CPU time (fastest of a few runs) against
    the unconstrained fit of the same points, and the rms reached (the second's
    constrained optimum is 1.5083, found by scipy SLSQP); ``checked_cpu_ms``: el.fit's
    default, which fits with free ends too to say what the constraints cost (fit_cost.py)."""
    from fit_data import sketched_s
    pts40, _ = sketched_s(seed=7, n=40, wobble=0.3)
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65, q=0.25, length=330.0)
    xy = c.points(np.linspace(0, c.length, 165)) + np.random.default_rng(2).normal(0, 1.0, (165, 2))
    cases = [("40 sketched, both ends pinned at curvature 0", pts40,
              {"start_point": tuple(pts40[0]), "end_point": tuple(pts40[-1]), "start_curvature": 0.0,
               "end_curvature": 0.0}),
             ("165 noisy, start tangent 0.2 rad off, end pinned", xy,
              {"start_tangent": c.angle([0.0])[0] + 0.2, "end_point": tuple(xy[-1])})]
    reps = 2 if quick else 5
    for name, pts, con in cases:
        for model in ("smooth", "discrete"):
            t_c = t_f = t_k = np.inf
            for _ in range(reps):
                c0 = time.process_time()
                r = el.fit(pts, model=model, constraints=con, check_ends=False)
                t_c = min(t_c, time.process_time() - c0)
                c0 = time.process_time()
                el.fit(pts, model=model)
                t_f = min(t_f, time.process_time() - c0)
                with warnings.catch_warnings():     # (the first case's ends cost: 1.39 / 0.17)
                    warnings.simplefilter("ignore", el.EndConditionWarning)
                    c0 = time.process_time()
                    el.fit(pts, model=model, constraints=con)
                    t_k = min(t_k, time.process_time() - c0)
            print(json.dumps({"bench": "fit_constrained", "case": name, "model": model,
                              "cpu_ms": round(1e3 * t_c, 3), "unconstrained_cpu_ms": round(1e3 * t_f, 3),
                              "checked_cpu_ms": round(1e3 * t_k, 3),
                              "ratio": round(t_c / t_f, 2), "rms": round(r.rms, 4), "status": r.status,
                              "used_ipopt": r.used_ipopt}))


def wrong_conditions(quick):
    """End conditions the data do not share (a designer's wrong value, el.fit's
    EndConditionWarning): the 2000-point noisy scan of a 4 m elastica (noise 0.5 mm) and
    every 11th of its points held at 4 x the data's start curvature, and at a start
    tangent 0.3 rad off; CPU ms (fastest of a few runs, one at 2000 points) of the held
    fit against the free one, with rms, status and iterations (the deterministic proxy)."""
    ref = el.SmoothElastica(x0=0, y0=0, phi=0.25, mu=1.2e-6, k=0.6, q=0.3, length=4000.0)
    rng = np.random.default_rng(1)
    s = np.sort(rng.uniform(0, 4000, 2000))
    scan = ref.points(s) + rng.normal(0, 0.5, (2000, 2))
    k0 = float(ref.curvature(np.array([s[0]]))[0])
    cases = [("start curvature 4 x the data's", {"start_curvature": 4 * k0 + 1e-3}),
             ("start tangent 0.3 rad off", {"start_tangent": float(ref.angle(np.array([s[0]]))[0]) + 0.3})]
    for pts in ((scan[::11],) if quick else (scan[::11], scan)):
        reps = 1 if len(pts) > 1000 else (2 if quick else 3)
        for name, con in cases:
            for model in ("smooth", "discrete"):
                t_c = t_f = np.inf
                for _ in range(reps):
                    with warnings.catch_warnings():     # (a held fit that strays says so)
                        warnings.simplefilter("ignore")
                        c0 = time.process_time()
                        r = el.fit(pts, model=model, constraints=con, check_ends=False)
                        t_c = min(t_c, time.process_time() - c0)
                    c0 = time.process_time()
                    f = el.fit(pts, model=model)
                    t_f = min(t_f, time.process_time() - c0)
                print(json.dumps({"bench": "fit_wrong_conditions", "case": name, "model": model, "n": len(pts),
                                  "cpu_ms": round(1e3 * t_c, 1), "free_cpu_ms": round(1e3 * t_f, 2),
                                  "rms": round(r.rms, 4), "free_rms": round(f.rms, 4), "status": r.status,
                                  "iterations": r.iterations}))


def discrete_uneven(quick):
    """The discrete model's default on unevenly spaced points (a 175-point scan of spacing
    1:6 with two gaps, noise 0.15; 42 points of two densities with a gap, noise 0.2):
    rms of the point-to-polygon distances over the noise, by distance to the polygon
    (the default there) and paired (vertex i <-> point i), and their CPU times."""
    from fit_data import uneven_scan
    c = el.SmoothElastica(x0=0.0, y0=0.0, phi=-1.028, mu=(1.0 / 105.0) ** 2, k=0.65, q=0.25, length=330.0)
    t = np.concatenate([np.linspace(0, .3, 30), np.linspace(.45, 1, 12)]) * c.length
    data = [("175-point scan 1:6, two gaps", uneven_scan(seed=0)[0], 0.15),
            ("42 points, two densities", c.points(t) + np.random.default_rng(5).normal(0, 0.2, (42, 2)), 0.2)]
    reps = 2 if quick else 5
    for name, pts, noise in data:
        out = {}
        for dist in ("orthogonal", "paired"):
            best = np.inf
            for _ in range(reps):
                c0 = time.process_time()
                r = el.fit(pts, distance=dist)
                best = min(best, time.process_time() - c0)
            out[dist] = dict(rms_over_noise=round(r.rms / noise, 3), cpu_ms=round(1e3 * best, 3))
        print(json.dumps({"bench": "fit_discrete_uneven", "data": name, **out}))


def main():
    quick = os.environ.get("BENCH_FIT_QUICK") == "1"
    rows = suite(4 if quick else 21)        # 2 models x 4 sizes x 3 noises x 21 = 504 curves
    report_suite(rows)
    orthogonal_ratio(rows)
    scipy_lm_ratio(rows, quick)
    keyline(quick)
    lbfgs_ratio(rows, quick)
    breakdown(rows)
    constrained(quick)
    wrong_conditions(quick)
    discrete_uneven(quick)


if __name__ == "__main__":
    if sys.argv[1:2] == ["--scipy-lm-worker"]:      # one process of scipy_lm_ratio
        import pickle
        with open(sys.argv[2], "rb") as fh:
            print(json.dumps(scipy_lm_times(pickle.load(fh))))
    else:
        main()
