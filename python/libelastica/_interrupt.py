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
import os
import sys
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


class CallInterrupted(KeyboardInterrupt):
    """Ctrl-C while a worker's C call runs (:func:`call`); ``running()``: whether it still
    does."""

    def __init__(self, done: threading.Event):
        super().__init__()
        self._done = done

    def running(self) -> bool:
        return not self._done.is_set()


def end_if_a_call_runs(exc: BaseException, status: int) -> None:
    """After a KeyboardInterrupt: where its worker is still in the C call, end the process
    now with ``status`` (stdio flushed, nothing else run): exit's teardown of the libraries
    under the running call crashed it (SIGSEGV in the fit, Debian's Python 3.11.2).
    Returns when no call runs."""
    if isinstance(exc, CallInterrupted) and exc.running():
        for stream in (sys.stdout, sys.stderr):
            try:
                stream.flush()
            except (OSError, ValueError):
                pass
        os._exit(status)


def _run(fn, args, keep, out, done):
    try:
        out.append((True, fn(*args)))
    except BaseException as exc:       # raised again in the caller's thread
        out.append((False, exc))
    finally:
        done.set()


def call(fn, *args, keep=()):
    """fn(*args); inside :func:`interruptible`, from the main thread (the one signals
    interrupt), in a worker the caller waits on. ``keep``: the objects the C call reads or
    writes through pointers (numpy arrays behind ``dptr``), held by the worker until the
    call returns."""
    if not _WORKER.get() or threading.current_thread() is not threading.main_thread():
        return fn(*args)
    out: list = []
    done = threading.Event()    # (not Thread.is_alive: a join interrupted by Ctrl-C makes it
    #                              False while the thread runs, Python 3.11.2)
    worker = threading.Thread(target=_run, args=(fn, args, keep, out, done), daemon=True,
                              name="libelastica C call")
    try:
        worker.start()              # (its wait for the thread's start is interruptible too:
        #                              Ctrl-C there found the call running, under load)
        while not done.wait(0.05):  # (woken each 50 ms: a SIGINT another thread took is seen)
            pass
    except KeyboardInterrupt:       # the worker keeps fn, args, keep
        raise CallInterrupted(done) from None
    ok, value = out[0]
    if not ok:
        raise value
    return value
