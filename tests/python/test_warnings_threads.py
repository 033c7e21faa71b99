"""Two threads fitting at once each see exactly their own warnings: the binding keeps a
fit's warnings quiet (quiet_fit, the sparse and misfit checks' own fits, holding_tension's
splines, the CLI's) in its own thread only (_quiet.py), where warnings.catch_warnings
swapped the process's filters and showwarning: another thread's warnings were dropped
meanwhile, or said at the wrong line (g2quad's own fix: test_g2quad_threads)."""
import inspect
import threading
import warnings

import numpy as np

import libelastica as el
from libelastica._quiet import quiet, say
from libelastica.fit import quiet_fit
from together import run_together

# 7 points of a sine's period: the discrete fit's polygon cuts its bends, so el.fit says
# a SparseWarning (the smooth fit ~10 x nearer), once a fit, ~7 ms
T = np.linspace(0.0, 1.0, 7)
SINE = np.c_[100.0 * T, 20.0 * np.sin(2.0 * np.pi * T)]
LOUD_FITS = 120


def test_two_threads_fitting_at_once_see_their_own_warnings():
    done, failed, counts = threading.Event(), [], {"loud": 0, "quiet_loud": 0, "quiet": 0}
    lines = {}

    def loud():
        try:
            for _ in range(LOUD_FITS):
                lines["loud"] = inspect.currentframe().f_lineno + 1
                el.fit(SINE, model="discrete")              # says its SparseWarning here
                counts["loud"] += 1
        except BaseException as exc:                        # (said by the assert below)
            failed.append(exc)
        finally:
            done.set()

    def quiet_one():
        try:
            while not done.is_set():
                # the same fit kept quiet (its SparseWarning: none), and every 10th said
                quiet_fit(SINE, model="discrete", check_sparse=True)
                counts["quiet"] += 1
                if counts["quiet"] % 10 == 0:
                    lines["quiet_loud"] = inspect.currentframe().f_lineno + 1
                    el.fit(SINE, model="discrete")
                    counts["quiet_loud"] += 1
        except BaseException as exc:
            failed.append(exc)

    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        run_together(loud, quiet_one)
    assert not failed, failed
    assert counts["quiet"] > 20 and counts["quiet_loud"] > 1, counts
    assert all(issubclass(w.category, el.SparseWarning) and w.filename == __file__ for w in said), \
        [(w.category.__name__, w.filename, w.lineno, str(w.message)[:60]) for w in said]
    at = [w.lineno for w in said]
    # each thread's fits said their warning once each, at their own line; the quiet ones none
    assert (at.count(lines["loud"]), at.count(lines["quiet_loud"]), len(at)) == \
        (LOUD_FITS, counts["quiet_loud"], LOUD_FITS + counts["quiet_loud"]), counts


def test_a_quiet_scope_drops_or_collects_its_categories_only():
    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        with quiet(el.SparseWarning) as none:
            say("a", el.SparseWarning)
            with quiet(into=[]) as kept:                    # every category, collected
                say("b", el.MisfitWarning)
                say(el.SparseWarning("c"))
            say("d", el.MisfitWarning)                      # not its category: said
        say("e", el.SparseWarning)                          # outside: said
    assert none is None and [str(w) for w in kept] == ["b", "c"]
    assert [(str(w.message), w.filename) for w in said] == [("d", __file__), ("e", __file__)]


def test_a_collecting_scope_gets_the_text_the_caller_would_see():
    # quieted() answered True for a scope that collects (into=): elastic_spline then spared
    # the ladder of tensions above and collected its short advice ('a larger tension may
    # give one'), not the one a recording catch_warnings had and a caller sees; an inner
    # collecting scope decides over an outer one that drops
    pts = np.array([[0.0, 0.0], [1.0, 0.0], [0.5, 0.01], [2.0, 0.0]])
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        el.elastic_spline(pts, tension=1e-3)
    shown = [str(w.message) for w in seen if w.category is el.LoopWarning]
    assert len(shown) == 1 and "a larger tension may give one" not in shown[0], shown
    with quiet(el.LoopWarning, into=[]) as got:
        el.elastic_spline(pts, tension=1e-3)
    assert [str(w) for w in got] == shown
    with quiet(), quiet(el.LoopWarning, into=[]) as got:
        el.elastic_spline(pts, tension=1e-3)
    assert [str(w) for w in got] == shown
