"""Runs a group of freecadcmd test modules in one FreeCAD process (freecad.mk's fc-tests):
`freecadcmd tests/freecad/fc_group.py` with FC_GROUP (module names, blank-separated),
FC_GROUP_LOGS (a folder) and FC_MODULE_TIMEOUT (seconds) in the environment.

Each FreeCAD start-up (App, Part, Sketcher, numpy, the binding and the workbench imported)
costs ~1-2 s of CPU, paid 73 times by one `freecadcmd -t` per module. Here each module runs
as `freecadcmd -t` runs it (FreeCAD's TestApp.TestText: unittest's loader by name, a
TextTestRunner at verbosity 2 on sys.stdout), its output, Python's and FreeCAD's C++
console's alike (file descriptors 1 and 2), in a log of its own (<logs>/<module>.log, read
by freecad.mk as before); between modules every document still open is closed and the
workbench's message list (commands.MESSAGES) emptied, as a fresh process would start.
A module that runs longer than FC_MODULE_TIMEOUT s (a hang guard, as freecad.mk's timeout
per freecadcmd was) ends the process with the traceback of every thread in its log
(faulthandler); the modules after it then have no log, and freecad.mk says so.
Ends by sys.exit(1) when a module failed (freecadcmd exits 0 when a script raises)."""
import faulthandler
import os
import sys

import FreeCAD as App


def close_documents():
    for name in list(App.listDocuments()):
        App.closeDocument(name)


def forget_messages():
    commands = sys.modules.get("freecad.elastica.commands")
    if commands is not None:
        del commands.MESSAGES[:]


def run_module(name, log_path, timeout):
    """unittest's result of module ``name``, its output in ``log_path``."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    fd = os.open(log_path, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(fd, 1)
    os.dup2(fd, 2)
    faulthandler.dump_traceback_later(timeout, exit=True, file=fd)
    try:
        import TestApp                       # FreeCAD's Mod/Test: what -t runs
        result = TestApp.TestText(name)
    finally:
        faulthandler.cancel_dump_traceback_later()
        sys.stdout.flush()
        sys.stderr.flush()
        os.dup2(saved[0], 1)
        os.dup2(saved[1], 2)
        for f in saved + (fd,):
            os.close(f)
    return result


def main():
    names = os.environ["FC_GROUP"].split()
    logs = os.environ["FC_GROUP_LOGS"]
    timeout = float(os.environ.get("FC_MODULE_TIMEOUT", "400"))
    failed = 0
    for name in names:
        close_documents()
        forget_messages()
        result = run_module(name, os.path.join(logs, name + ".log"), timeout)
        failed += not result.wasSuccessful()
    close_documents()
    sys.exit(1 if failed else 0)


main()
