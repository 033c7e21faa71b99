"""Ctrl-C during a long C call: a fit of 2000 points runs seconds in C, where Python's
KeyboardInterrupt waits until it returns. Inside :func:`interruptible` (the CLI) a call
through :func:`call` runs in a worker thread (cffi releases the GIL) while the caller's
thread waits on it, and the wait is what Ctrl-C interrupts: the KeyboardInterrupt comes at
once, the worker runs on to its end (a daemon: the process does not wait for it) holding
every object of the call, and its result is dropped. Elsewhere (the library) :func:`call`
is the plain call."""
from __future__ import annotations

import contextlib
import contextvars
import threading

# whether the calls of this context may run in a worker (the context's, not global: a
# thread or task of the caller's program sees its own)
_WORKER = contextvars.ContextVar("libelastica_interruptible", default=False)


@contextlib.contextmanager
def interruptible():
    """Within it, the main thread's :func:`call` returns at Ctrl-C (KeyboardInterrupt)."""
    token = _WORKER.set(True)
    try:
        yield
    finally:
        _WORKER.reset(token)


def _run(fn, args, keep, out):
    try:
        out.append((True, fn(*args)))
    except BaseException as exc:       # raised again in the caller's thread
        out.append((False, exc))


def call(fn, *args, keep=()):
    """fn(*args); inside :func:`interruptible`, from the main thread (the one signals
    interrupt), in a worker the caller waits on. ``keep``: the objects the C call reads or
    writes through pointers (numpy arrays behind ``dptr``), held by the worker until the
    call returns."""
    if not _WORKER.get() or threading.current_thread() is not threading.main_thread():
        return fn(*args)
    out: list = []
    worker = threading.Thread(target=_run, args=(fn, args, keep, out), daemon=True,
                              name="libelastica C call")
    worker.start()
    while worker.is_alive():    # KeyboardInterrupt here: the worker keeps fn, args, keep
        worker.join(0.05)       # (woken each 50 ms: a SIGINT another thread took is seen)
    ok, value = out[0]
    if not ok:
        raise value
    return value
