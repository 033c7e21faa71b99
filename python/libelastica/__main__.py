"""``python -m libelastica``: the ``elastica`` command (see :mod:`libelastica.cli`)."""
import sys

from libelastica.cli import main

if __name__ == "__main__":
    sys.exit(main())
