"""Inputs bound to an expression (a spreadsheet cell, an alias): the unit of its value checked
against the property's. FreeCAD 0.20 gives a bound property the expression's value whatever its
unit: a float or precision property drops the unit (a cell '=5 mm' read as a tension of 5
1/mm^2, QA19gui F9), a quantity property takes it as its own (a Length bound to '=0.002 / mm^2'
was solved as 0.002 mm, "length 2 um is not longer than ..." and then showed "120.0 1/mm^2" once
the cell was a plain 120; ResampleStep '=3 s' taken as 3 mm: QA21gui F1; Part::Box does the
same). Every bound input is refused when its value has another unit, the message naming the
cell's value and the unit expected."""
from __future__ import annotations

import FreeCAD as App

from .kept import is_input
from .proxy import LENGTH, PER_AREA, InputProblem
from .units import number_text

_U = App.Units.Unit
# what a bound value of each kind may be: (its unit, 'a <noun> is in <this>', an example,
# the unit a plain number is taken in)
_LENGTH = (_U(1), "a unit of length", "=12 cm", "mm")
_KINDS = {LENGTH: _LENGTH,
          PER_AREA: (_U(-2), "1/length^2", "=0.002 / mm^2", "1/mm^2")}
# float inputs with a unit (their tooltips'); every other float / integer input is a plain number
_FLOATS = {"StartCurvature": (_U(-1), "1/length", "=0.02 / mm", "1/mm"),
           "EndCurvature": (_U(-1), "1/length", "=0.02 / mm", "1/mm"),
           "Scale": (_U(2), "length^2", "=500 mm^2", "mm^2"),
           "Stiffness": (App.Units.Quantity("1 N*mm^2").Unit, "force x length^2",
                         "=2e5 N*mm^2", "N mm^2")}
_PLAIN = ("App::PropertyFloat", "App::PropertyInteger")


def _words(name):
    """'ResampleStep' -> 'resample step' (the noun of the message)."""
    return "".join(" " + c.lower() if c.isupper() and i else c.lower()
                   for i, c in enumerate(name))


def said(q):
    """A quantity in the unit the schema picks, to the Decimals preference as units.
    number_text writes it: not its UserString's '0.00' of a small one (0.002 1/mm^2 said
    "0.00 1/mm^2"; "0.0020 1/mm^2" at 2 decimals)."""
    _, factor, unit = q.getUserPreferred()
    return f"{number_text(q.Value / factor)} {unit}"


def expected(obj, name):
    """(unit, its words, an example, a plain number's unit) of input ``name``; (None, ...) for
    a plain number; None where no unit is known (a link, a string...)."""
    kind = obj.getTypeIdOfProperty(name)
    if kind in _KINDS:
        return _KINDS[kind]
    if kind in _PLAIN:
        return _FLOATS.get(name, (None, "", "", ""))
    return None


def check_bound_units(obj):
    """InputProblem for the first input of ``obj`` bound to an expression whose value has a
    unit other than the property's (a plain number is taken in the property's unit). A
    quantity property an earlier value of another unit left in that unit keeps it on screen
    until the document is reopened (FreeCAD's PropertyQuantity::setPathValue takes the unit
    of any value with one, and does not save it; its Part::Box does the same); its value is
    the number the feature solves. Not made again here: removing and adding the property
    inside the cell edit's transaction lost it at Undo (test_elastica_bound_undo)."""
    for name, expr in sorted(dict(getattr(obj, "ExpressionEngine", [])).items()):
        if name not in obj.PropertiesList or not is_input(obj, name):
            continue
        want = expected(obj, name)
        if want is None:
            continue
        try:
            q = obj.evalExpression(expr)
        except Exception:             # FreeCAD's own error on the expression: said by it
            continue
        unit = getattr(q, "Unit", None)
        if unit is not None and unit != _U() and unit != want[0]:
            noun = _words(name)
            if want[0] is None:
                raise InputProblem(f"{name} is bound to {expr} = {said(q)}: {name} is a "
                                   "plain number (no unit)")
            article = "an" if noun[0] in "aeiou" else "a"
            raise InputProblem(f"{name} is bound to {expr} = {said(q)}: {article} {noun} "
                               f"is in {want[1]} (e.g. '{want[2]}') or a plain number "
                               f"({want[3]})")

