"""pytest's configuration for tests/python: one marker, c_numerics.

make check runs these tests under two Pythons, FreeCAD's (/usr/bin/python3, Debian's numpy
and cffi) and the python3 first on PATH (pip's numpy and cffi), because the binding — cffi's
ABI module, numpy's array conversions, warnings, exceptions, the CLI, pickling, packaging —
may behave differently under each. A test marked c_numerics asserts what the C library
computes (a fit's rms, a spline's residual, the solutions found) on inputs it makes itself,
through binding calls that unmarked tests make too: under a second Python it would run the
same C code on the same doubles a second time and prove nothing new about the binding. So
make check runs it under FreeCAD's Python only (check-python-path passes
-m "not c_numerics"; pytest's summary counts the tests it deselected), and a plain `pytest`
runs it as any other test.

Mark a test c_numerics only when all of these hold:
- its cost is in the C library (a fit, a spline, a Hermite solve), not in Python or numpy
  code of the package (numpy's versions differ between the two Pythons: numpy code of the
  package is tested under both);
- it asserts numbers or statuses of the C library's results, not messages, warnings'
  texts, types, file or command-line output, pickles or packaging;
- the binding calls it makes (el.fit, el.elastic_spline, ... with the same kinds of
  arguments) are made by unmarked tests as well.
"""
from __future__ import annotations


def pytest_configure(config):
    config.addinivalue_line(
        "markers",
        "c_numerics: asserts the C library's numbers through binding calls other tests make "
        "too; make check runs it under one Python only (tests/python/conftest.py says why)")
