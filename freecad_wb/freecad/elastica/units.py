"""Lengths, curvatures and tensions in the user's unit schema (Edit > Preferences > General >
Units), as FreeCAD's own Quantity boxes and property editor show them: the properties stay in
mm (and 1/mm, 1/mm^2), the text the designer reads follows the schema ('5.94 in', '15.1 cm',
tension '0.409 1/in²'). No GUI: features' Status lines use it too."""
from __future__ import annotations

import math
import re
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal

import FreeCAD as App
import Part

# the schema's unit of a length of this size names 'the' length unit of the schema, for
# quantities per length (curvature, energy) and per length squared (tension): mm under
# Standard and Metric small parts, m under MKS, in under the inch schemas, cm Building Euro,
# ft Imperial civil (getUserPreferred's unit of 100 mm in each)
REFERENCE_MM = 100.0
# a unit as the parser reads it (1/in^2), where the schema writes a sign ('5.94 "')
_UNIT_NAME = {'"': "in", "'": "ft"}
UNITS_PREFERENCES = "User parameter:BaseApp/Preferences/Units"


def decimals():
    """Edit > Preferences > General > Units > Number of decimals: how many decimals FreeCAD's
    Quantity boxes, property view and UserString write (Base::UnitsApi::getDecimals, 2 by
    default). Read from the preference each time (FreeCAD's own copy is read at start and set
    by its preference page: a change in a running freecadcmd reaches only the parameter)."""
    default = int(App.Units.Quantity(1.0).Format["Precision"])
    return max(0, App.ParamGet(UNITS_PREFERENCES).GetInt("Decimals", default))


def number_text(x, at_least=None, bound=None):
    """A number as every panel text and box writes it (lengths in the unit the schema picks,
    curvatures, tensions, plain figures), as FreeCAD's Base::Quantity::getUserString writes a
    quantity: fixed notation, decimals() places ('151.00', '5.94'; '151.000000' at 6) where
    FreeCAD's own call (App.Units.Quantity(...).UserString) writes the same for a length.
    Where those places keep fewer than decimals() significant digits of a number below 1,
    FreeCAD's does not suffice: it writes a tension 0.000634 1/mm^2 and a tolerance 0.001 mm
    in inches '0.00' (its schemas scale no unit of 1/length^2 and no inch), here to as many
    places as keep decimals() of them ('0.00063', '0.000039'); below 1e-6 in scientific
    notation ('2.7e-07', where FreeCAD's Imperial decimal schema turns to it). ``at_least``:
    as many significant digits at least, for a figure a text asks to type back (a tension
    that gives a curve again: '0.00203109 1/mm\u00b2', not '0.0020'). ``bound``: 'up' for
    a figure a text says to stay above ('a step of at least'), rounded up at those places,
    'down' for one to stay below ('a step under'), rounded down: a bound typed back as
    written holds (to the nearest, 65.9511 mm under at 0 decimals was '66 mm'). A number
    below 1 keeps 1 significant digit at least (Decimals 0: '0.4', not '0')."""
    d, x = decimals(), float(x)
    keep = max(d, 1, int(at_least or 0))
    if x == 0.0 or not math.isfinite(x):
        return f"{0.0 if x == 0.0 else x:.{d}f}"
    # the lead digit of x as written (keep significant digits, rounded as it will be): 0.0997
    # is '0.10' as 0.1002 is, not '0.100' (one number, one format: review of F10's rows)
    shown_x = float(f"{x:.{keep - 1}e}") if not bound else \
        (ceil_digits if bound == "up" else floor_digits)(x, keep)
    lead = math.floor(math.log10(abs(shown_x)))
    if lead < -6:
        return f"{shown_x if bound else x:.{max(0, keep - 1)}e}"
    places = max(d, keep - 1 - lead)
    text = (f"{x:.{places}f}" if not bound else
            format(Decimal(repr(x)).quantize(Decimal(1).scaleb(-places),
                                             ROUND_CEILING if bound == "up" else ROUND_FLOOR), "f"))
    shown = max(d, max(d, 1) - 1 - lead)    # the places without at_least: a typed-back
    while at_least and text.endswith("0") and \
            len(text.partition(".")[2]) > shown:        # figure's own zeros not written
        text = text[:-1]
    return text


def user_length(mm):
    """(factor, unit): a length of ``mm`` millimetres in the user's unit schema is mm /
    factor unit, as FreeCAD's own Quantity boxes and property editor show it ('5.94 in',
    '15.1 cm', '1 \u00b5m')."""
    _, factor, unit = App.Units.Quantity(float(mm), App.Units.Length).getUserPreferred()
    if not factor or not unit:      # a schema's bare '0' (Building US): its unit of 1 mm
        _, factor, unit = App.Units.Quantity(1.0, App.Units.Length).getUserPreferred()
    return float(factor), unit


def length_text(mm, digits=None, bound=None):
    """A length (mm) as text in the user's schema, as FreeCAD's UserString writes it (the
    unit getUserPreferred picks, number_text: '151.00 mm', '5.94 in', '0.000039 in');
    ``digits``: the significant digits its stored marks name, of texts written before the
    Decimals preference was followed (number_text decides); ``bound``: number_text's."""
    factor, unit = user_length(mm)
    return f"{number_text(float(mm) / factor, bound=bound)} {unit}"


def noise(mm):
    """Whether a measured length (mm: an rms, a distance, a B-spline's deviation) is below
    FreeCAD's Confusion (Part.Precision.confusion(), 1e-7 mm: points nearer are one point to
    FreeCAD and OpenCASCADE), rounding noise at the document's precision."""
    return abs(float(mm)) < Part.Precision.confusion()


def figure_text(mm, digits=None):
    """A measured length (mm) as a panel says it: as length_text writes it, rounding noise
    (noise) as FreeCAD writes a 0 ('0.00 mm', '0.00 in'), not '1.2e-11 mm' (the feature's
    property keeps the figure)."""
    return length_text(0.0 if noise(mm) else mm, digits)


def feet_inches(mm):
    """A length (mm) as FreeCAD writes it under a schema of feet and inches (Building US:
    its Quantity boxes and property editor show 151 mm as '6"', 3000 mm as
    '9\' 10+1/8"', to 1/8 in), or None under another schema and where that text rounds a
    length to 0 (a tolerance of 0.001 mm is '0': its boxes keep decimal inches)."""
    if "ft-in" not in App.Units.listSchemas(App.Units.getSchema()):
        return None
    text = App.Units.Quantity(float(mm), App.Units.Length).UserString
    return None if float(mm) and text.strip("-") == "0" else text


def box_text(mm):
    """A length (mm) as a length box shows it: as length_text (the unit the schema picks, as
    Gui::QuantitySpinBox, number_text's decimals: '151.00 mm', '5.94 in', '1.00 \u00b5m')."""
    return length_text(mm)


def length_unit():
    """(factor, name): the schema's length unit (REFERENCE_MM), named as the unit parser
    reads it ('in' where the schema writes '"')."""
    factor, unit = user_length(REFERENCE_MM)
    return factor, _UNIT_NAME.get(unit, unit)


def per_length(value, digits=None):
    """A quantity per length (1/mm: curvature, energy) as text in the schema's length unit,
    number_text's decimals ('0.028/mm', '0.71/in'; ``digits``: as length_text's)."""
    factor, unit = length_unit()
    return f"{number_text(float(value) * factor)}/{unit}"


def tension_unit():
    """(factor, text): a tension in 1/mm^2 is value * factor in 1/unit\u00b2 of the schema's
    length unit."""
    factor, unit = length_unit()
    return factor * factor, f"1/{unit}\u00b2"


# A tension below this fraction of a curve's scale 1/length^2 is rounding noise: 0 (a blend
# by the free batten's own length solves to |sigma| ~ 1e-16/mm^2, QA18gui F9)
TENSION_NOISE = 1e-9


def tension_or_zero(sigma, length):
    """sigma (1/mm^2), or 0.0 where it is rounding noise (TENSION_NOISE) for a curve of
    ``length`` (mm)."""
    return 0.0 if abs(sigma) * length ** 2 < TENSION_NOISE else float(sigma)


def tension_text(sigma, length, digits=None, bound=None):
    """sigma (1/mm^2) in 1/length^2 of the user's unit schema, as the Tension fields show it
    ('0.00063 1/mm\u00b2', '0.41 1/in\u00b2': number_text), to ``digits`` significant
    digits at least (a tension to type back), rounding noise (tension_or_zero) shown as 0;
    ``bound``: number_text's."""
    factor, unit = tension_unit()
    return f"{number_text(tension_or_zero(sigma, length) * factor, digits, bound)} {unit}"


def area_text(value, digits=None):
    """A length squared (mm^2: the comb's scale) in the square of the schema's length unit
    ('12.50 mm\u00b2', '0.019 in\u00b2': number_text; ``digits``: as length_text's)."""
    factor, unit = length_unit()
    return f"{number_text(float(value) / factor ** 2)} {unit}\u00b2"


def unbroken(text):
    """``text`` with its quantities kept on one line where a widget wraps it: a no-break
    space between a number and its unit ('48.16 mm', '1 inflection'), a word joiner
    (U+2060, no width) after the '/' of a unit ('0.0483/mm'). The blend's Solutions list at
    1024x768 wrapped 'energy 0.0483/' | 'mm' (QA24gui F6): Qt's line breaking (Unicode's)
    allows a break after a '/' and at every space."""
    text = re.sub(r"(?<=\d) (?=\S)", "\u00a0", text)
    return re.sub(r"/(?=\w)", "/\u2060", text)


def outer_parts(text, sep="; "):
    """``text`` split at each ``sep`` outside parentheses: a Status's parts, one a panel
    line, without breaking a note's parenthesis at a '; ' of its own (review of F10: '...G1
    solution<br>bent from a longer ...)')."""
    parts, depth, start, i = [], 0, 0, 0
    while i < len(text):
        c = text[i]
        depth += (c == "(") - (c == ")" and depth > 0)
        if depth == 0 and text.startswith(sep, i):
            parts.append(text[start:i])
            i = start = i + len(sep)
            continue
        i += 1
    return parts + [text[start:]]


def unit_names(text):
    """``text`` (a tooltip) with '(mm', '(1/mm' and '(1/mm²' naming the schema's units,
    those the boxes show ('(in)', '(1/in)', '(1/in²)' under Imperial decimal)."""
    unit = length_unit()[1]
    return re.sub("\\((1/)?mm(\u00b2)?", lambda m: f"({m.group(1) or ''}{unit}{m.group(2) or ''}",
                  text)


# ------------------------------------------------------------------ texts said again
# A text a recompute writes (Status, Warnings) may hold its figures as marks: say() writes
# each in the schema of now, so a panel opened after a schema change says the stored text
# again in the new one without a recompute (proxy.said keeps the marked text).
_MARK = re.compile("\x01([LKkTNUuwRrMmEe])([^\x02]*)\x02")
_RANGE = re.compile("\x01([em])([^\x02]*)\x02 to \x01([EM])([^\x02]*)\x02")
# a length written '<number> mm' (the library's messages take a unit to write after their
# figures): not '1/mm', 'mm^2', 'N mm^2'
_NUM = r"(-?(?:\d+\.?\d*|\.\d+)(?:e[+-]?\d+)?)"
_MM = re.compile(rf"(?<![\w.\-])(?:{_NUM} to )?{_NUM} mm(?![\w^\u00b2/])")   # '9.05 to 16 mm' too


def _bound_flag(bound):
    """A mark's flag for number_text's ``bound`` ('up': a figure to stay above, rounded up;
    'down': one to stay below, rounded down)."""
    assert bound in (None, "up", "down"), bound
    return f"|{bound}" if bound else ""


def _bound_of(args):
    """The bound flag among a mark's fields (_bound_flag), or None."""
    return next((a for a in args[1:] if a in ("up", "down")), None)


def length_mark(mm, digits=3, bound=None):
    """A length (mm) written by say() as length_text writes it (``bound``: number_text's)."""
    return f"\x01L{float(mm)!r}|{digits}{_bound_flag(bound)}\x02"


def per_length_mark(value, digits=3, unit=True):
    """A quantity per length (1/mm) written by say() as per_length writes it (``unit``
    False: the number alone, in the same unit)."""
    return f"\x01{'K' if unit else 'k'}{float(value)!r}|{digits}\x02"


def tension_mark(sigma, length, digits=None, bound=None):
    """A tension (1/mm^2) written by say() as tension_text writes it (``digits``: at least
    as many significant digits, a tension the text asks to type back; ``bound``:
    number_text's)."""
    shown = "" if digits is None else int(digits)
    return f"\x01T{float(sigma)!r}|{float(length)!r}|{shown}{_bound_flag(bound)}\x02"


def per_area_mark(value, digits=3, bound=None):
    """A number per length squared (1/mm^2) written by say() in 1/unit^2 of the schema,
    without its unit (tension_unit_mark says it; ``bound``: number_text's)."""
    return f"\x01N{float(value)!r}|{digits}{_bound_flag(bound)}\x02"


def length_unit_mark(written=False):
    """The schema's length unit as the parser reads it ('mm', 'in': in '/in^2'), written by
    say(); ``written``: as FreeCAD writes it after a number, as the lengths beside it ('"'
    under US customary): the unit of numbers written without theirs (coordinate_mark)."""
    return "\x01w\x02" if written else "\x01u\x02"


def tension_unit_mark():
    """The tension unit ('1/mm\u00b2', '1/in\u00b2'), written by say()."""
    return "\x01U\x02"


def reach_mark(sigma, digits, up=False):
    """A tension (1/mm^2) that can be typed back: rounded DOWN (``up``: up, the least of a
    range above) to ``digits`` in the unit say() writes it in, with the unit (a reach typed
    back stays within reach)."""
    return f"\x01{'r' if up else 'R'}{float(sigma)!r}|{digits}\x02"


def _to_digits(x, digits, rounding):
    """x != 0 rounded (decimal ``rounding``) to ``digits`` significant digits of its shortest
    decimal (repr): a digit x has is kept (0.001707 / 1e-9 is 1706999.9999999998 in floats)."""
    exact = Decimal(repr(float(x)))
    return float(exact.quantize(Decimal(1).scaleb(exact.adjusted() - digits + 1), rounding))


def floor_digits(x, digits):
    """x != 0 rounded DOWN to ``digits`` significant digits (the float of its %g text)."""
    return _to_digits(x, digits, ROUND_FLOOR)


def ceil_digits(x, digits):
    """x != 0 rounded UP to ``digits`` significant digits (the float of its %g text)."""
    return _to_digits(x, digits, ROUND_CEILING)


def mm_marked(text):
    """``text`` (or a list of texts) with each '<number> mm' marked: say() writes it in the
    unit the schema picks for it (user_length, as exact_mark), to as many significant digits
    as written (at least 3), and as written where that unit is mm."""
    if isinstance(text, (list, tuple)):
        return [mm_marked(t) for t in text]
    return _MM.sub(lambda m: (f"\x01m{m.group(1)}\x02 to " if m.group(1) else "")
                   + f"\x01M{m.group(2)}\x02", text)


def coordinate_mark(mm, digits=4):
    """A coordinate (mm) without its unit, written by say() in the schema's length unit (the
    message names it after them, length_unit_mark(written=True): '(219.9, -101.6, -87.72)
    mm'), from its exact value (exact_mark)."""
    return exact_mark(mm, digits, with_unit=False)


def exact_mark(mm, digits=None, with_unit=True, figure=False, bound=None):
    """A length (mm) written by say() from its exact value in the unit FreeCAD's schema picks
    for it (user_length: '0.496 mm', '0.1192 m' under MKS), to ``digits`` significant digits
    (None: as '%g' writes it in mm, at least 3 in another unit), in mm as
    f'{mm:.{digits}g} mm'; ``with_unit`` False: the number alone, in the schema's length
    unit (a message names it once), or a range's ('9.05 to 16 mm': the unit of its end);
    ``figure``: a measured length, whose rounding noise say(figures=True) writes as 0
    (figure_text); ``bound``: number_text's (a step 'of at least' / 'under' it).
    The binding's summaries take it as their ``length`` formatter."""
    shown = "" if digits is None else int(digits)
    return (f"\x01{'E' if with_unit else 'e'}{float(mm)!r}|{shown}{'|f' if figure else ''}"
            f"{_bound_flag(bound)}\x02")


def figure_mark(mm, digits=None, with_unit=True):
    """A measured length (mm) written by say() as exact_mark, its rounding noise as 0 in a
    panel (say(figures=True): figure_text): the binding's summaries of distances take it as
    their ``length``."""
    return exact_mark(mm, digits, with_unit, figure=True)


def _written_in(value, written, digits, shown, bound=None):
    """``value`` (mm) as a number in ``shown`` = (factor, unit), number_text's decimals
    (``digits``: the marks' own, of texts stored before; ``bound``: number_text's);
    ``written``: its text in mm where a message wrote it (a '<number> mm' mark), written
    with its significant digits where the decimals' text, read back in mm to those digits,
    is not it: the library rounds its figures to their safe side ('raise tol to 0.00123 mm
    or more', bspline.at_least; 'any length above 328.182 mm'), which Decimals 2 wrote
    '0.0012 mm' and '328.18 mm', below the bound they name."""
    text = number_text(value / shown[0], bound=bound)
    if written is None:
        return text
    n = len(re.sub(r"e.*|[^0-9]", "", written).lstrip("0"))
    if float(f"{float(text) * shown[0]:.{n}g}") == float(f"{value:.{n}g}"):
        return text
    return number_text(value / shown[0], n, bound)


def _exact(args, with_unit, shown=None, figures=False):
    """An exact mark (E, e): with its unit in the unit FreeCAD's schema picks for its value
    (getUserPreferred: '0.496 mm' and '0.12 m' under MKS), without it in ``shown`` (a
    range's unit) or the schema's length unit (a message names it once); ``figures``: a
    measured length (figure_mark) at rounding noise as 0."""
    value, digits = float(args[0]), args[1]
    if figures and "f" in args[2:] and noise(value):
        value = 0.0
    shown = shown or (user_length(value) if with_unit else length_unit())
    return (_written_in(value, None, digits, shown, _bound_of(args))
            + (f" {shown[1]}" if with_unit else ""))


def _in_length_unit(written, with_unit=True, shown=None):
    """A '<number> mm' mark (M, m) as _exact writes it, to as many digits as written."""
    value = float(written)
    shown = shown or (user_length(value) if with_unit else length_unit())
    return _written_in(value, written, None, shown) + (f" {shown[1]}" if with_unit else "")


def _range(match, figures=False):
    """'<low> to <high> unit' (far points' '9.05 to 16 mm'): both in the unit of the one
    written with its unit."""
    (low_kind, low), (high_kind, high) = match.group(1, 2), match.group(3, 4)
    low, high = low.split("|"), high.split("|")
    shown = user_length(float(high[0]))
    said = (_exact(low, False, shown, figures) if low_kind == "e" else
            _in_length_unit(low[0], False, shown))
    return said + " to " + (_exact(high, True, shown, figures) if high_kind == "E" else
                            _in_length_unit(high[0], True, shown))


def _said(match, figures=False):
    kind, args = match.group(1), match.group(2).split("|")
    if kind == "L":
        return length_text(float(args[0]), bound=_bound_of(args))
    if kind == "K":
        return per_length(float(args[0]))
    if kind == "k":
        return number_text(float(args[0]) * length_unit()[0])
    if kind == "T":
        return tension_text(float(args[0]), float(args[1]), int(args[2]) if args[2] else None,
                            _bound_of(args))
    if kind == "N":
        return number_text(float(args[0]) * tension_unit()[0], bound=_bound_of(args))
    if kind == "u":
        return length_unit()[1]
    if kind == "w":
        return user_length(REFERENCE_MM)[1]
    if kind in "Mm":
        return _in_length_unit(args[0], kind == "M")
    if kind in "Ee":
        return _exact(args, kind == "E", figures=figures)
    if kind in "Rr":
        per, unit = tension_unit()
        rounded = floor_digits if kind == "R" else ceil_digits
        shown = float(args[0]) if per == 1.0 else rounded(float(args[0]) * per, int(args[1]))
        return f"{shown:.{int(args[1])}g} {unit}"
    return tension_unit()[1]


def say(text, figures=False):
    """``text`` (or a list of texts) with its marks written in the user's schema of now;
    ``figures`` (a panel's): measured lengths (figure_mark) at rounding noise as 0, where
    the report view and the properties keep the figures."""
    if isinstance(text, (list, tuple)):
        return [say(t, figures) for t in text]
    return _MARK.sub(lambda m: _said(m, figures), _RANGE.sub(lambda m: _range(m, figures), text))
