"""The ``elastica`` command's entry (the console script's and ``python -m libelastica``'s).
Ctrl-C while it still imports (numpy, cffi, the library: most of its start-up) ends it as
Ctrl-C later does, exit 130 and "elastica: interrupted", not a KeyboardInterrupt traceback:
the package's first import (of this module) installs a SIGINT handler that says so and
ends the process, in the command's process only, and :func:`main` gives SIGINT back to
Python once the command is imported (cli.main then says it, as before). Before this module
(Python's own start-up: site, runpy) Python's handling stays."""
import os
import signal
import sys

INTERRUPTED = 130       # 128 + SIGINT: the exit status of every Ctrl-C (cli.main too)


def _is_command() -> bool:
    """Whether this process is the ``elastica`` command: its console script, or
    ``python -m libelastica`` (sys.orig_argv, Python >= 3.10), not a program importing
    the package."""
    if sys.argv and os.path.basename(sys.argv[0]) == "elastica":
        return True
    argv = list(getattr(sys, "orig_argv", ()))[1:]
    while argv:
        a = argv.pop(0)
        if a.startswith("-m"):
            return (a[2:] or (argv[0] if argv else "")) == "libelastica"
        if a in ("-X", "-W"):       # options with a value
            argv = argv[1:]
        elif a == "-c" or not a.startswith("-"):    # a program or a script
            return False
    return False


def _interrupted(signum, frame):
    # at once: an exception raised here can be lost in the import it lands in (seen:
    # compiling a module, the command then ran on and exited 0); nothing is written yet
    sys.stdout.flush()
    print("elastica: interrupted", file=sys.stderr, flush=True)
    os._exit(INTERRUPTED)


if _is_command() and signal.getsignal(signal.SIGINT) is signal.default_int_handler:
    try:
        signal.signal(signal.SIGINT, _interrupted)
    except ValueError:      # not the main thread: Python's own handling stays
        pass


def main() -> int:
    """The console script's and ``python -m libelastica``'s: import the command (Ctrl-C
    there: the handler above), give SIGINT back to Python, run it."""
    from .cli import main as run
    if signal.getsignal(signal.SIGINT) is _interrupted:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    return run()
