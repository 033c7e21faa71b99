"""Lengths, curvatures and tensions in the user's unit schema (Edit > Preferences > General >
Units), as FreeCAD's own Quantity boxes and property editor show them: the properties stay in
mm (and 1/mm, 1/mm^2), the text the designer reads follows the schema ('5.94 in', '15.1 cm',
tension '0.409 1/in²'). No GUI: features' Status lines use it too."""
from __future__ import annotations

import FreeCAD as App

# the schema's unit of a length of this size names 'the' length unit of the schema, for
# quantities per length (curvature, energy) and per length squared (tension): mm under
# Standard and Metric small parts, m under MKS, in under the inch schemas, cm Building Euro,
# ft Imperial civil (getUserPreferred's unit of 100 mm in each)
REFERENCE_MM = 100.0
# a unit as the parser reads it (1/in^2), where the schema writes a sign ('5.94 "')
_UNIT_NAME = {'"': "in", "'": "ft"}


def user_length(mm):
    """(factor, unit): a length of ``mm`` millimetres in the user's unit schema is mm /
    factor unit, as FreeCAD's own Quantity boxes and property editor show it ('5.94 in',
    '15.1 cm', '1 \u00b5m')."""
    _, factor, unit = App.Units.Quantity(float(mm), App.Units.Length).getUserPreferred()
    if not factor or not unit:      # a schema's bare '0' (Building US): its unit of 1 mm
        _, factor, unit = App.Units.Quantity(1.0, App.Units.Length).getUserPreferred()
    return float(factor), unit


def length_text(mm, digits=3):
    """A length (mm) as text in the user's schema, to ``digits`` significant digits
    ('151 mm', '5.94 in')."""
    factor, unit = user_length(mm)
    return f"{float(mm) / factor:.{digits}g} {unit}"


def length_unit():
    """(factor, name): the schema's length unit (REFERENCE_MM), named as the unit parser
    reads it ('in' where the schema writes '"')."""
    factor, unit = user_length(REFERENCE_MM)
    return factor, _UNIT_NAME.get(unit, unit)


def per_length(value, digits=3):
    """A quantity per length (1/mm: curvature, energy) as text in the schema's length unit
    ('0.0278/mm', '0.706/in')."""
    factor, unit = length_unit()
    return f"{float(value) * factor:.{digits}g}/{unit}"


def tension_unit():
    """(factor, text): a tension in 1/mm^2 is value * factor in 1/unit\u00b2 of the schema's
    length unit."""
    factor, unit = length_unit()
    return factor * factor, f"1/{unit}\u00b2"


def tension_text(sigma, length, digits=3):
    """sigma (1/mm^2) in 1/length^2 of the user's unit schema, as the Tension fields show it
    ('0.000634 1/mm\u00b2', '0.409 1/in\u00b2'), to ``digits`` significant digits,
    rounding noise (below 1e-9 of the scale 1/length^2) shown as 0."""
    factor, unit = tension_unit()
    return f"{0.0 if abs(sigma) * length ** 2 < 1e-9 else sigma * factor:.{digits}g} {unit}"
