"""The library's errors survive pickle (multiprocessing, concurrent.futures send a worker's
exception back pickled): the class, message, status and the attributes callers read instead
of the message (elastic_spline's stopped / work, LengthRangeError's range, the fits'
constraint, EdgeCountError's cause)."""
import pickle

import numpy as np
import pytest

import libelastica as el

SHARP = np.array([[0, 0], [5, 0], [10, 0.3], [5.5, 1.2], [0.5, 1.6]])


def _raised(f):
    with pytest.raises(el.ElasticaError) as info:
        f()
    return info.value


@pytest.mark.parametrize("call", [
    lambda: el.elastic_spline(SHARP, length=22.0, max_iter=3, max_steps=3),   # stopped by its budget
    lambda: el.elastic_spline(SHARP),                                         # slides: DomainError
])
def test_a_spline_error_pickles_with_its_attributes(call):
    err = _raised(call)
    back = pickle.loads(pickle.dumps(err))
    assert type(back) is type(err) and str(back) == str(err) and back.args == err.args
    assert back.status == err.status
    assert (back.stopped, back.work) == (err.stopped, err.work)
    if isinstance(err, el.LengthRangeError):
        assert (back.shortest, back.longest, back.polygon) == (err.shortest, err.longest, err.polygon)


def test_an_error_with_its_own_init_pickles():
    # EdgeCountError(status, message, cause, edges): too few edges for a k = 1.5 loop
    err = _raised(lambda: el.affine_polyline(el.SmoothElastica(x0=0, y0=0, phi=0, mu=1.0, k=1.5,
                                                                q=0.0, length=12.0), 3))
    assert isinstance(err, el.EdgeCountError) and err.cause
    back = pickle.loads(pickle.dumps(err))
    assert type(back) is type(err) and str(back) == str(err) and back.__dict__ == err.__dict__
