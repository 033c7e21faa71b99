"""Callables run at once, each in a thread of its own, for the tests that check the binding
from two threads (test_warnings_threads, test_g2quad_threads, test_fit_one_call,
test_hermite): each started, then each joined."""
from __future__ import annotations

import threading


def run_together(*targets) -> None:
    """Start a thread for each callable of ``targets``; return when every one is done."""
    threads = [threading.Thread(target=t) for t in targets]
    for th in threads:
        th.start()
    for th in threads:
        th.join()
