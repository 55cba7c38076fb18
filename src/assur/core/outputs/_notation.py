"""The outputs' notation (:mod:`assur.core.outputs`): an output written as a function
call (``"Rx(0, 5)"``) or a formula's name, parsed and resolved against a mechanism,
and the SI unit of its values.
"""

from __future__ import annotations

import functools
import re

from ...errors import ModelError

REDUCTIONS = ("min", "max", "argmin", "argmax")
#: unit of each output function (SI; "q" stands for the coordinate's unit)
OUTPUT_UNITS = {"X": "m", "Y": "m", "dX": "m/q", "dY": "m/q", "I": "m/q", "phi": "rad",
                "dphi": "rad/q", "length": "m", "dlength": "m/q", "F": "N", "Fr": "N",
                "Rx": "N", "Ry": "N", "R": "N", "Rm": "N·m", "p": "Pa", "G": "N",
                "reserve": "%", "Xc": "m", "Yc": "m", "formula": "SI"}
_ARITY = {"X": (1,), "Y": (1,), "dX": (1, 2), "dY": (1, 2), "I": (1, 2), "phi": (1,),
          "dphi": (1, 2), "length": (1,), "dlength": (1, 2), "F": (1,), "Fr": (1,),
          "Rx": (2,), "Ry": (2,), "R": (2,), "Rm": (2,), "p": (1,), "G": (2,),
          "reserve": (3,), "Xc": (0,), "Yc": (0,)}
_CALL = re.compile(r"^\s*([A-Za-z]+)\s*\((.*)\)\s*$")
_NAME = re.compile(r"^\s*([^\W\d]\w*)\s*$")


@functools.lru_cache(maxsize=4096)
def parse_output(text: str) -> tuple:
    """``"Rx(0, 5)"`` → ``("Rx", ("0", "5"))``, ``"Xc"`` → ``("Xc", ())``, the name of
    a formula ``"p_c"`` → ``("formula", ("p_c",))`` (whether the model has it is checked
    where the mechanism is known); raises :class:`ModelError`.

    Examples
    --------
    >>> from assur.core.outputs import parse_output
    >>> parse_output("Rx(0, 5)"), parse_output("Xc"), parse_output("p_c")
    (('Rx', ('0', '5')), ('Xc', ()), ('formula', ('p_c',)))
    >>> parse_output("Q(56)")
    Traceback (most recent call last):
        ...
    assur.errors.ModelError: unknown output 'Q(56)': expected one of X(…), Y(…), dX(…), dY(…), I(…), phi(…), dphi(…), length(…), dlength(…), F(…), Fr(…), Rx(…), Ry(…), R(…), Rm(…), p(…), G(…), reserve(…), Xc, Yc or the name of a formula of the model's [[tables.formulas]]
    """
    bare = _NAME.match(str(text))
    if bare:
        name = bare.group(1)
        return (name, ()) if _ARITY.get(name) == (0,) else ("formula", (name,))
    m = _CALL.match(str(text))
    if not m or m.group(1) not in _ARITY:
        raise ModelError(f"unknown output {text!r}: expected one of "
                         f"{', '.join(f + ('' if _ARITY[f] == (0,) else '(…)') for f in _ARITY)}"
                         f" or the name of a formula of the model's [[tables.formulas]]")
    args = tuple(a.strip().strip("'\"") for a in m.group(2).split(",")) if m.group(2).strip() \
        else ()
    if len(args) not in _ARITY[m.group(1)]:
        raise ModelError(f"output {text!r}: {m.group(1)} takes "
                         f"{' or '.join(map(str, _ARITY[m.group(1)]))} argument(s)")
    return m.group(1), args


def formula_of(mech, name):
    """The :class:`assur.core.columns.Formula` of ``mech`` named ``name``; raises
    :class:`ModelError` naming the formulas it has.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import formula_of
    >>> formula_of(examples.hitch_003(), "GS6max").unit          # seed 003 table 6.1
    'N'
    """
    from ..columns import formulas_of
    fs = formulas_of(mech)
    for f in fs:
        if f.name == name:
            return f
    raise ModelError(f"unknown output {name!r}: model {mech.name!r} has no formula of that "
                     f"name (its [[tables.formulas]]: {[f.name for f in fs] or 'none'}); "
                     f"the outputs are " + ", ".join(
                         f + ("" if _ARITY[f] == (0,) else "(…)") for f in _ARITY))


def resolve_output(mech, text) -> tuple:
    """:func:`parse_output` of ``text`` for ``mech``: a formula's name becomes
    ``("formula", (name, expression))`` — the expression is part of the kernel's key —
    after checking that ``mech`` has it and that its names exist.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import resolve_output
    >>> m = examples.hitch_003()
    >>> resolve_output(m, "G(ГЦ, S6)")
    ('G', ('ГЦ', 'S6'))
    >>> resolve_output(m, "GS6max")[1][1]                       # the expression: its key
    '(P_mcxa*b + P_gr*(a + L) - 0.2*(P6 + P_mcxa + P_gr)) / X(S6)'
    """
    fn, args = text if isinstance(text, tuple) else parse_output(text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        f.check(mech)
        return fn, (f.name, f.expr)
    return fn, args


def output_unit(mech, text) -> str:
    """The SI unit of an output's values: ``"q"`` of :data:`OUTPUT_UNITS` becomes the
    coordinate's unit (``m`` for a cylinder, ``rad`` for a crank), ``F``/``Fr`` of an
    angle coordinate are moments [N·m]; a formula's own unit when its scale is 1,
    else ``"SI"``.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import output_unit
    >>> m = examples.hitch_003()
    >>> output_unit(m, "p(ГЦ)"), output_unit(m, "dY(56)"), output_unit(m, "GS6max")
    ('Pa', 'm/m', 'N')
    >>> output_unit(examples.combine_002(), "F(j1)")      # the crank's driving moment
    'N·m'
    """
    fn, args = resolve_output(mech, text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        return f.unit if f.scale == 1.0 else "SI"
    u = OUTPUT_UNITS[fn]
    if "q" in u:
        c = args[1] if len(args) > 1 else mech.coordinates[0]
        u = u.replace("q", "rad" if mech.coordinate_kind(c) == "angle" else "m")
    if fn in ("F", "Fr") and mech.coordinate_kind(args[0]) == "angle":
        u = "N·m"
    return u


def display_unit(mech, text):
    """The :class:`assur.core.quantities.Unit` to show an output in: a formula's own unit
    and scale (``p_c`` in kN/m if the formula says so), else :func:`output_unit`.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.outputs import display_unit
    >>> m = examples.hitch_003()
    >>> display_unit(m, "GS6max").text, display_unit(m, "dY(56)").text
    ('N', 'm/m')
    """
    from ..quantities import Unit
    fn, args = resolve_output(mech, text)
    if fn == "formula":
        f = formula_of(mech, args[0])
        return Unit(f.unit, f.scale)
    return Unit(output_unit(mech, (fn, args)))
