"""g2_quadratic's own warnings in a thread leave another thread's alone: a local frame's
build (far from the origin) and the edge count search pass a list and a flag down
(g2quad._say) where they swapped the process's warnings filters and showwarning
(warnings.catch_warnings), catching another thread's warnings to say them again at
g2_quadratic's caller's line, or to drop them (revA: 365 of a thread's 3000 said again)."""
import threading
import time
import warnings

import numpy as np
import pytest

import libelastica as el
from together import run_together

OFF = np.array([512345.678, 5012345.432])
# test_g2quad's elastica turning 46.7 rad: no G2 quadratic from 7 to 25 edges, 26 covers
TURNING = dict(x0=-5.083034973582038, y0=-33.059037265720804, phi=1.6495229282221135,
               mu=3.7131648374362034, k=1.8201196947246816, q=3.082111327782377,
               length=7.253495089408346)


def _bean():
    # test_g2quad_offset's bean at a survey offset: built in a local frame, warned at its seam
    t = np.linspace(0, 2 * np.pi, 10, endpoint=False)
    r = 30 + 8 * np.cos(2 * t)
    pts = np.c_[1.2 * r * np.cos(t), r * np.sin(t) - 14 * np.cos(t) ** 2 * (np.sin(t) > 0)]
    return el.elastic_spline(pts + OFF, closed=True)


def test_another_threads_warnings_are_left_alone():
    bean, turning = _bean(), el.SmoothElastica(**TURNING)
    done, sent, failed = threading.Event(), [], []

    def builds():
        try:
            el.g2_quadratic(bean, 24)               # said: its seam (EndTangentWarning)
            with pytest.raises(el.EdgeCountError, match="n = 26 works"):
                el.g2_quadratic(turning, 21)        # the count search: 22 .. 26 built
        except BaseException as exc:                # (said by the assert below)
            failed.append(exc)
        finally:
            done.set()

    def other():
        # the other thread's own warnings, of g2_quadratic's category (its searches ignored
        # that category process-wide), until the builds are done
        while not done.is_set():
            warnings.warn(el.EndTangentWarning(f"other {len(sent)}"))
            sent.append(1)
            time.sleep(0.0005)

    with warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        run_together(builds, other)
    assert not failed, failed
    theirs = [w for w in said if str(w.message).startswith("other ")]
    ours = [w for w in said if str(w.message).startswith("g2_quadratic")]
    assert len(sent) > 100
    # each of the other thread's warnings said once, at its own line
    assert [str(w.message) for w in theirs] == [f"other {i}" for i in range(len(sent))]
    where = {(w.filename, w.lineno) for w in theirs}
    assert len(where) == 1 and where.pop()[0] == __file__
    # and the builds' own: the bean's, at the line that built it (none from the search)
    assert len(ours) == 1 and (ours[0].filename, ours[0].lineno) != (theirs[0].filename,
                                                                       theirs[0].lineno)
    assert ours[0].filename == __file__
