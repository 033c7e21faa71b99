"""The CLI in-process for the tests (libelastica.cli.main): exit code, stdout, stderr."""
from __future__ import annotations

from libelastica.cli import main


def cli(capsys, *args):
    """(code, out, err) of `elastica *args` (argparse's usage errors and --help: their exit code)."""
    capsys.readouterr()
    try:
        code = main([str(a) for a in args])
    except SystemExit as exc:
        code = exc.code
    out, err = capsys.readouterr()
    return code, out, err
