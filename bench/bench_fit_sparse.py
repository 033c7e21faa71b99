"""Fits of sparse, unevenly spaced, noisy points (a designer's sketch): how often the
default fit strays from its points or ends in a worse basin than the curve they were
drawn from.

Each set: a smooth elastica of length 1 turning by at most 2 pi (k in [0.1, 0.95] or
[1.05, 3], mu in [0.5, 30], random phase and orientation), 6-59 points at uniformly
random arc lengths (the ends included), Gaussian noise of 0.1, 0.5 or 1 % of the
curve's extent per coordinate. Fitted free, with the true start point and tangent
(a curve continuing an edge G1), pinned at the true end points (FreeCAD's Pin start
and Pin end: the ends chart, no Ipopt) and with the true end points and tangents (a
curve joining two edges G1), pinned at the true end points with curvature 0 there (the
natural batten), by the smooth and the discrete model, and by the smooth
model with the true curve's start point, tangent and curvature and end point and tangent
(a blend joining geometry G2 at its start, G1 at its end).

  fit_sparse  per kind: sets, fits that stray (el__fit_stray's measure with the true
              noise: more than a tenth of the points' polygon length of curve
              unaccounted for by the arcs between feet), smooth fits whose rms is
              above 1.01 x the fit started from the true curve and above 1.01 x the
              true curve's own rms (it meets the constraints: they are its own; the
              fit from it follows the same starts, so both can be worse), errors,
              fits not certified (status other than 0), fits that ran Ipopt, and the
              median and maximum CPU time of a fit.
  fit_sparse_free, fit_sparse_pinned, fit_sparse_g1_ends, fit_sparse_natural  the free
              fits, those pinned at both ends, those joined G1 at both ends and the natural
              battens, both models: median, maximum and total CPU time, fits that ran Ipopt,
              not certified, errors (the natural battens: and those that stray).

`python3 bench/bench_fit_sparse.py SEED CASE` prints one set's points (the
sets tests/c/test_fit_basin.c takes its data from: seed 4 case 22, seed 4 case 532,
seed 5 case 194; tests/c/test_fit_held.c: seed 6 cases 29, 105, 141, seed 7 case 189)."""
import json
import sys
import time

import numpy as np

import libelastica as el

KINDS = {"free": (), "start G1": ("start_point", "start_tangent"), "pinned ends": ("start_point", "end_point"),
         "G1 both ends": ("start_point", "start_tangent", "end_point", "end_tangent"),
         "natural batten": ("start_point", "end_point")}
# pinned at both ends with curvature 0 there (FreeCAD's Pin start + Pin end + curvature 0 at
# both ends), whatever the curve's own end curvatures
ZERO_CURVATURES = {"natural batten": {"start_curvature": 0.0, "end_curvature": 0.0}}
# smooth only (the discrete model's start curvature other than 0 is an Ipopt row): a blend
# that must join geometry G2 at its start and G1 at its end
SMOOTH_KINDS = {"G2 start, G1 end": ("start_point", "start_tangent", "start_curvature", "end_point", "end_tangent")}


def sets(seed):
    """(case, points, true curve, noise, constraint values) of the seed's sets, in order;
    the case number counts the curves drawn, those turning by more than 2 pi skipped."""
    rng = np.random.default_rng(seed)
    case = -1
    while True:
        k = rng.choice([rng.uniform(0.1, 0.95), rng.uniform(1.05, 3.0)])
        mu = rng.uniform(0.5, 30.0)
        c = el.SmoothElastica(x0=0, y0=0, phi=rng.uniform(-3, 3), mu=mu, k=k * rng.choice([-1, 1]),
                              q=rng.uniform(-2, 2), length=1.0)
        n = int(rng.integers(6, 60))
        case += 1
        if np.ptp(c.angle(np.linspace(0, 1, 400))) > 6.3:
            continue
        s = np.sort(rng.uniform(0, 1, n))
        s[0], s[-1] = 0.0, 1.0
        p = c.points(s)
        sig = rng.choice([0.001, 0.005, 0.01]) * np.ptp(p, axis=0).max()
        pts = p + rng.normal(0, sig, p.shape)
        theta, kappa = c.angle(np.array([0.0, 1.0])), c.curvature(np.array([0.0, 1.0]))
        ends = {"start_point": tuple(p[0]), "start_tangent": float(theta[0]), "start_curvature": float(kappa[0]),
                "end_point": tuple(p[-1]), "end_tangent": float(theta[1])}
        yield case, pts, c, sig, ends


def stray(r, pts, sig, length):
    """el__fit_stray's measure (fit_wander.c) with the true noise level sig."""
    order = np.argsort(r.foot_s, kind="stable")
    f, q = r.foot_s[order], pts[order]
    chord = np.hypot(*np.diff(q, axis=0).T)
    poly = np.hypot(*np.diff(pts, axis=0).T).sum()
    lost = np.maximum(0.0, np.diff(f) - 1.6 * chord - 4 * sig).sum()
    lost += max(0.0, f[0] - 4 * sig) + max(0.0, length - f[-1] - 4 * sig)
    return lost / poly


def true_rms(c, pts):
    """The rms distance of the points to the curve c (the nearest of 20001 samples)."""
    q = c.points(np.linspace(0.0, c.length, 20001))
    return float(np.sqrt(np.mean([np.min((q[:, 0] - x) ** 2 + (q[:, 1] - y) ** 2) for x, y in pts])))


def measure(seed, count):
    def tally():
        return dict(stray=0, worse=0, worse_true=0, errors=0, uncertified=0, ipopt=0, t=[])
    out = {(m, k): tally() for m in ("smooth", "discrete") for k in KINDS}
    out.update({("smooth", k): tally() for k in SMOOTH_KINDS})
    names = dict(KINDS, **SMOOTH_KINDS)
    drawn = sets(seed)
    for _ in range(count):
        case, pts, c, sig, ends = next(drawn)
        truth = true_rms(c, pts)
        for (model, kind), o in out.items():
            cons = dict({name: ends[name] for name in names[kind]}, **ZERO_CURVATURES.get(kind, {})) or None
            c0 = time.process_time()
            try:
                r = el.fit(pts, model=model, constraints=cons)
            except (ValueError, ArithmeticError):
                o["t"].append(time.process_time() - c0)
                o["errors"] += 1
                continue
            o["t"].append(time.process_time() - c0)
            o["uncertified"] += int(r.status != 0)
            o["ipopt"] += int(r.used_ipopt)
            length = r.curve.length if model == "smooth" else r.curve.h * (len(pts) - 1)
            o["stray"] += int(stray(r, pts, sig, length) > 0.1)
            if model == "smooth":
                o["worse_true"] += int(r.rms > 1.01 * truth)
                try:
                    o["worse"] += int(r.rms > 1.01 * el.fit(pts, model=model, constraints=cons, initial=c).rms)
                except (ValueError, ArithmeticError):
                    pass
    return out


def main():
    if len(sys.argv) == 3:
        seed, case = int(sys.argv[1]), int(sys.argv[2])
        for c, pts, _, _, _ in sets(seed):
            if c == case:
                np.savetxt(sys.stdout, pts)
                return
            if c > case:
                sys.exit(f"case {case} of seed {seed} turns by more than 2 pi: not a set")
    seed, count = 5, 100
    res = measure(seed, count)
    for (model, kind), o in res.items():
        t = np.array(o["t"]) * 1e3
        line = {"bench": "fit_sparse", "model": model, "constraints": kind, "seed": seed, "sets": count,
                "stray": o["stray"], "errors": o["errors"], "uncertified": o["uncertified"],
                "ipopt": o["ipopt"], "median_cpu_ms": round(float(np.median(t)), 2),
                "max_cpu_ms": round(float(t.max()), 1)}
        if model == "smooth":
            line["worse_than_from_truth"] = o["worse"]
            line["worse_than_true_curve"] = o["worse_true"]
        print(json.dumps(line))
    total = sum(o["stray"] for o in res.values())
    errors = sum(o["errors"] for o in res.values())
    # the true curve meets every kind's constraints but the natural batten's (its own end
    # curvatures are not 0): that kind is not compared with it
    smooth = [o for (m, k), o in res.items() if m == "smooth" and k not in ZERO_CURVATURES]
    worse = sum(o["worse_true"] for o in smooth)
    print(json.dumps({"bench": "fit_sparse_all", "sets": count * len(res), "stray": total, "errors": errors,
                      "readme": "fits of 6-59 sparse uneven noisy points (smooth and discrete, free, "
                                "with a start tangent, pinned at both ends, G1 at both ends, natural batten; smooth "
                                "G2 start + G1 end) that stray from them",
                      "value": f"{total} of {count * len(res)}, {errors} errors (smooth: {worse} of "
                               f"{count * len(smooth)} above the true curve's rms by > 1 %)"}))


    kind_row(res, "free", "fit_sparse_free", "the same sketches fitted free, smooth / discrete", count)
    kind_row(res, "pinned ends", "fit_sparse_pinned",
             "the same sketches pinned at both ends (Pin start + Pin end), smooth / discrete", count)
    kind_row(res, "G1 both ends", "fit_sparse_g1_ends",
             "the same sketches joined G1 at both ends (the true end points and tangents), smooth / discrete", count)
    kind_row(res, "natural batten", "fit_sparse_natural",
             "the same sketches pinned at both ends with curvature 0 there (the natural batten), smooth / discrete",
             count, strays=True)


def kind_row(res, kind, bench, readme, count, strays=False):
    """One kind's figures over both models: CPU time (median, max, all the fits'), Ipopt,
    uncertified fits, errors (strays: and the fits that stray from their points)."""
    both = [res[(m, kind)] for m in ("smooth", "discrete")]
    stray_text = (f"; {res[('smooth', kind)]['stray']} / {res[('discrete', kind)]['stray']} stray from their points"
                  if strays else "")
    t = {m: np.array(res[(m, kind)]["t"]) * 1e3 for m in ("smooth", "discrete")}
    total = sum(float(v.sum()) for v in t.values()) * 1e-3
    print(json.dumps({"bench": bench, "sets": count, "models": 2,
                      "stray": {m: res[(m, kind)]["stray"] for m in ("smooth", "discrete")},
                      "median_cpu_ms": {m: round(float(np.median(v)), 2) for m, v in t.items()},
                      "max_cpu_ms": {m: round(float(v.max()), 1) for m, v in t.items()},
                      "total_cpu_s": round(total, 2),
                      "ipopt": sum(o["ipopt"] for o in both), "uncertified": sum(o["uncertified"] for o in both),
                      "errors": sum(o["errors"] for o in both),
                      "readme": readme,
                      "value": f"median {np.median(t['smooth']):.1f} / {np.median(t['discrete']):.1f} ms CPU, "
                               f"max {t['smooth'].max():.0f} / {t['discrete'].max():.0f} ms, {total:.2f} s for "
                               f"all {2 * count}; Ipopt in {sum(o['ipopt'] for o in both)} of {2 * count}, "
                               f"{sum(o['uncertified'] for o in both)} uncertified{stray_text}"}))

if __name__ == "__main__":
    main()
