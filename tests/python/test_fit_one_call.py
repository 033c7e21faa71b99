"""el.fit's one crossing into C (_fit_call.py: libelastica/binding.h's el_binding_fit, not
public) against its plain path (the checks, the order screen, the fit and the figures one
call each, as without binding.h): the same results to the bit and the same warnings and
errors, over both models, both distances, uniform and chord parameters, 4 to 5000 points,
extents 1e-150 to 1e150, noisy uneven scans, hand sketches, shuffled points, an outlier, a
scan passed back and forth, and input the checks refuse; and the entry's figures against
the public functions it stands for."""
import importlib
import warnings

import numpy as np
import pytest

import libelastica as el
from libelastica._ffi import dptr, ffi, lib
from libelastica._median import median
from fit_data import sketched_s, uneven_scan

FC = importlib.import_module("libelastica._fit_call")


def test_the_binding_takes_the_one_call():
    """The suite's binding (the source tree's, binding.h read, the library built from it:
    el_binding_digest its digest) takes el_binding_fit: without it every comparison below
    would compare the plain path with itself (a skip here hid that: a stale build or a
    binding.h the wheel left out passed green)."""
    assert FC._ONE_CALL is not None, (FC.BINDING_DIGEST, lib.el_binding_digest())


def snapshot(r):
    """Every field of a FitResult, arrays and curves by their bytes and values."""
    out = {}
    for k, v in r.__dict__.items():
        if isinstance(v, np.ndarray):
            out[k] = (v.dtype.str, v.shape, v.tobytes())
        elif isinstance(v, (el.DiscreteElastica, el.SmoothElastica)):
            out[k] = sorted(v.__dict__.items())
        elif k == "free" and v is not None:
            out[k] = snapshot(v)
        else:
            out[k] = repr(v)
    return out


def outcome(P, kw):
    with warnings.catch_warnings(record=True) as w:
        warnings.simplefilter("always")
        try:
            got = snapshot(el.fit(P, **kw))
        except Exception as exc:           # the plain path's error, the same
            got = (type(exc).__name__, str(exc))
    return got, [(x.category.__name__, str(x.message), x.filename, x.lineno) for x in w]


def elastica(model, k, n, scale, rng, noise):
    if model == "discrete":
        c = el.DiscreteElastica(x0=0, y0=0, h=1.0 / n, phi=rng.uniform(-3, 3), z=2.5 / n, q=0.3, k=k, n=n)
        P = c.points()
    else:
        c = el.SmoothElastica(x0=0, y0=0, phi=rng.uniform(-3, 3), mu=1.0, k=k, q=0.3, length=2.5)
        P = c.points(np.linspace(0, c.length, n))
    L = float(np.sum(np.linalg.norm(np.diff(P, axis=0), axis=1)))
    P = P + rng.normal(0, noise * L, P.shape)
    return np.ascontiguousarray(scale * (P + 3.0))


def cases():
    rng = np.random.default_rng(11)
    for model in ("discrete", "smooth"):
        for n, k, scale, noise in ((4, 0.5, 1.0, 0.0), (7, 0.8, 1.0, 0.01), (30, 1.3, 1e3, 0.01),
                                   (200, 0.3, 1e-150, 0.001), (1000, 0.9, 1e150, 0.01),
                                   (1000, 4.0, 1.0, 0.01), (5000, 0.7, 1e-3, 0.001)):
            P = elastica(model, k, n, scale, rng, noise)
            yield f"{model}{n}", P, dict(model=model)
            yield f"{model}{n}p", P, dict(model=model, distance="paired")
            if model == "smooth":
                yield f"{model}{n}c", P, dict(model=model, param="chord")
    for seed in range(3):
        P = uneven_scan(seed)[0]
        S = sketched_s(seed)[0]
        yield f"uneven{seed}", P, dict(model="discrete")
        yield f"uneven_s{seed}", P, dict(model="smooth", param="chord")
        yield f"sketch{seed}", S, dict(model="discrete")
        yield f"sketch_s{seed}", S, dict(model="smooth")
    P = elastica("discrete", 0.9, 300, 1.0, rng, 0.01)
    Q = P.copy()
    Q[100] += 0.3
    yield "shuffled", P[rng.permutation(len(P))], {}
    yield "outlier", Q, {}
    yield "back_and_forth", np.vstack([P, P[::-1][1:]]), dict(model="smooth")
    yield "fixed", P, dict(fixed={"x0": float(P[0, 0]), "y0": float(P[0, 1])})
    yield "bounds", P, dict(model="smooth", bounds={"k": (0.0, 0.5)})
    yield "max_iter", P, dict(model="smooth", max_iter=1)
    yield "bad_option", P, dict(fixed={"nope": 1.0})
    yield "bad_tol", P, dict(tol=-1.0)
    yield "nan", np.array([[0, 0], [1, 1], [np.nan, 2], [3, 3], [4, 5.0]]), {}
    yield "inf", np.array([[0, 0], [1, 1], [np.inf, 2], [3, 3], [4, 5.0]]), dict(model="smooth")
    yield "repeats", np.array([[0, 0], [1, 1], [1, 1], [1, 1], [2, 3.0]]), {}
    yield "repeats_later", np.array([[0, 0], [1, 1], [2, 0.5], [3, 2], [3, 2], [3, 2.0]]), {}
    yield "all_equal", np.full((6, 2), 2.5), {}
    yield "minus_zero", np.full((5, 2), -0.0), {}
    yield "three", np.array([[0, 0], [1, 1], [2, 0.5]]), {}
    yield "float32", P.astype(np.float32), {}
    # far from the origin (a survey's coordinates: the rounding test's tolerance 16 ulp of
    # 1e6), a 1e-6 / 1e6 extent there, Fortran order and a strided view (as_point_array's
    # copies), 5 points, and the first two points 16 / 17 ulp apart (refused / taken)
    for scale in (1.0, 1e-6, 1e6):
        yield f"offset{scale:g}", scale * P + 1e6, {}
        yield f"offset{scale:g}_s", scale * P + 1e6, dict(model="smooth", param="chord")
    yield "fortran", np.asfortranarray(P), dict(model="smooth")
    yield "strided", np.vstack([P, P])[::2], {}
    yield "five", P[::70][:5], dict(model="smooth")
    for ulps in (16, 17):
        E = P[:60] + 1e6
        E[1] = E[0] + [ulps * np.spacing(float(E.max())), 0.0]
        yield f"head{ulps}ulp", E, {}
    yield "list", P[:40].tolist(), dict(model="smooth")


@pytest.mark.parametrize("name, P, kw", list(cases()), ids=lambda v: v if isinstance(v, str) else None)
def test_the_one_call_is_the_plain_path(name, P, kw, monkeypatch):
    calls, real = [], FC._ONE_CALL
    monkeypatch.setattr(FC, "_ONE_CALL", lambda *args: calls.append(1) or real(*args))
    one = outcome(P, kw)
    assert bool(calls) == (name not in ("three", "bad_option", "bad_tol")), calls   # (those: refused before)
    monkeypatch.setattr(FC, "_ONE_CALL", None)
    assert outcome(P, kw) == one


def call(P, model="discrete", step=1, turn=0, opt=None):
    n = len(P)
    o = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(o)
    res = ffi.new(f"el_fit_{model}_result *")
    d, f = np.empty(n), np.empty(n)
    sc, fig = ffi.new("el_order_screen_result *"), ffi.new("double[3]")
    st = lib.el_binding_fit(dptr(P), n, o, res if model == "discrete" else ffi.NULL,
                            res if model == "smooth" else ffi.NULL, dptr(d), dptr(f), 16.0, step,
                            turn, sc, fig)
    return st, res, d, sc, list(fig)


@pytest.mark.parametrize("n", [4, 5, 20, 201, 1000, 3001])
@pytest.mark.parametrize("model", ["discrete", "smooth"])
def test_the_entrys_figures_are_the_public_functions(model, n):
    rng = np.random.default_rng(n)
    P = elastica(model, 0.8, n, 10.0, rng, 0.01)
    step = n // 64 if n >= 200 else 1
    st, res, d, sc, fig = call(P, model, step, int(step > 1))
    want = ffi.new("el_order_screen_result *")
    assert lib.el_order_screen(dptr(P), n, step, int(step > 1), want) == lib.EL_OK
    assert (sc.extent, sc.length) == (want.extent, want.length)
    assert sc.turn == want.turn or (np.isnan(sc.turn) and np.isnan(want.turn))
    q = ffi.new("double *")
    assert lib.el_fit_noise_quick(dptr(P), n, q) == lib.EL_OK and fig[0] == q[0]
    assert st == lib.EL_OK
    assert fig[1] == median(np.abs(d)) == float(np.median(np.abs(d))) and fig[2] == float(np.abs(d).max())
    o = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(o)
    plain = ffi.new(f"el_fit_{model}_result *")
    d2, f2 = np.empty(n), np.empty(n)
    fit = lib.el_fit_discrete if model == "discrete" else lib.el_fit_smooth
    assert fit(dptr(P), n, o, ffi.NULL, plain, dptr(d2), dptr(f2)) == st
    assert bytes(ffi.buffer(plain)) == bytes(ffi.buffer(res)) and d2.tobytes() == d.tobytes()


def test_the_entry_refuses_what_the_plain_path_names():
    """-1, nothing fitted, figures NaN: a NaN, fewer than 4 points, repeats among the first
    4 (to 16 units in the last place), all zero, a NULL, both results or neither."""
    good = np.array([[0, 0], [1, 1], [2, 0.5], [3, 2.0]])
    nan = good.copy()
    nan[2, 1] = np.nan
    near = good.copy()
    near[1] = near[0] + 8 * np.spacing(3.0)
    for P in (nan, good[:3], near, np.zeros((5, 2))):
        st, res, d, sc, fig = call(np.ascontiguousarray(P))
        assert st == -1 and np.isnan(fig).all() and res.iterations == 0
    o = ffi.new("el_fit_options *")
    lib.el_fit_options_defaults(o)
    r, d, f = ffi.new("el_fit_discrete_result *"), np.empty(4), np.empty(4)
    s, sc, fig = ffi.new("el_fit_smooth_result *"), ffi.new("el_order_screen_result *"), ffi.new("double[3]")
    args = [dptr(good), 4, o, r, ffi.NULL, dptr(d), dptr(f), 16.0, 1, 0, sc, fig]
    assert lib.el_binding_fit(*args) == lib.EL_OK
    for i in (0, 2, 5, 6, 10):
        assert lib.el_binding_fit(*[ffi.NULL if j == i else a for j, a in enumerate(args)]) == -1
    assert lib.el_binding_fit(*args[:4], s, *args[5:]) == -1
    assert lib.el_binding_fit(*args[:3], ffi.NULL, ffi.NULL, *args[5:]) == -1
    assert lib.el_binding_fit(*args[:-1], ffi.NULL) == -1


def test_two_threads_fit_at_once_as_one_does():
    """el.fit's one call from two threads at once (the GIL released in the C call, no global
    state in binding.c): every result the same to the bit as the same fit alone (the
    warnings' threads are test_warnings_threads.py's)."""
    from together import run_together
    rng = np.random.default_rng(7)
    sets = [(elastica(model, k, n, 1.0, rng, 0.01), model)
            for model in ("discrete", "smooth") for k, n in ((0.4, 300), (1.2, 500), (3.0, 400))]

    def fit(P, model):
        return snapshot(el.fit(P, model=model))
    got = [[None] * len(sets) for _ in range(2)]

    def run(t):
        for i in (range(len(sets)) if t == 0 else reversed(range(len(sets)))):
            got[t][i] = fit(*sets[i])
    with warnings.catch_warnings():         # (process-wide: set here, not in the threads)
        warnings.simplefilter("ignore")
        alone = [fit(P, m) for P, m in sets]
        run_together(lambda: run(0), lambda: run(1))
    assert got[0] == alone and got[1] == alone
