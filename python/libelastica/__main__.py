"""``python -m libelastica``: the ``elastica`` command (see :mod:`libelastica.cli`; Ctrl-C
while it imports: :mod:`libelastica._entry`)."""
import sys

from libelastica._entry import main

if __name__ == "__main__":
    sys.exit(main())
