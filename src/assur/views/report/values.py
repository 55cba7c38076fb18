"""Values shown to the user in the units the user gave them (DESIGN.md §12).

A parameter the model file wrote as ``"27.5 kN"`` is shown as 27.5 kN (кН), a solved
condition ``phi6 = "90 deg"`` as ``φ6(S = Sp) = 90°``; SI stays inside. The units come
from :func:`assur.core.quantities.display_units` (what the file gave, else the quantity's
default: SI, angles in degrees). Files are named by their name, not by the path of
the machine that ran them. Used by the HTML report and the CLI.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...core.quantities import DEFAULT_UNITS, display_units
from .labels import t, unit

__all__ = ["parameter_value", "with_unit", "symbol", "solved_line"]


def parameter_value(v, u, lang="en"):
    """A parameter's value [SI] in its display unit ``u`` (:class:`assur.core.quantities.Unit`),
    9 significant digits (the decimal comma in Russian); a batch of designs as its
    count and span.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.quantities import display_units
    >>> m = examples.hitch_003()
    >>> units = display_units(m)
    >>> units["P6"].text, parameter_value(m.params["P6"], units["P6"])  # implement weight
    ('kN', '27.5')
    >>> parameter_value(m.params["L4"], units["L4"])  # L4 [m], solved from Y56(Smin) = 0.2 m
    '0.661283167'
    >>> parameter_value([0.40, 0.45, 0.50], units["L4"])  # a batch of three designs [m]
    '[3] 0.4 … 0.5'
    >>> parameter_value(m.params["L4"], units["L4"], "ru")
    '0,661283167'
    """
    a = np.asarray(v, dtype=float) / u.scale
    if a.ndim and a.size > 1:
        text = f"[{a.size}] {a.min():.6g} … {a.max():.6g}"
    else:
        text = f"{float(a.reshape(-1)[0]):.9g}"
    return text.replace(".", ",") if lang == "ru" else text


def with_unit(x, u, lang, digits=6):
    """``x`` [SI] written in the unit ``u``: ``90°``, ``0.2 m`` (``м`` in Russian).

    Examples
    --------
    >>> import math
    >>> from assur.core.quantities import Unit
    >>> with_unit(math.pi / 2, Unit("deg", math.pi / 180), "en")  # π/2 rad
    '90°'
    >>> with_unit(0.2, Unit("m"), "ru")  # 0.2 m, with the decimal comma
    '0,2 м'
    >>> with_unit(27500.0, Unit("kN", 1e3), "en")  # 27 500 N
    '27.5 kN'
    """
    v = f"{u.of(x):.{digits}g}"
    if lang == "ru":
        v = v.replace(".", ",")
    if u.is_degrees:
        return v + "°"
    return v if u.text in ("-", "") else f"{v} {unit(u.text, lang)}"


def symbol(quantity):
    """A condition's quantity as the seeds write it: ``phi6`` → ``φ6``.

    Examples
    --------
    >>> symbol("phi6"), symbol("Y56")
    ('φ6', 'Y56')
    """
    return "φ" + quantity[3:] if quantity.startswith("phi") else quantity


def solved_line(sc, mech, lang, units=None, shown=None):
    """One solved ``[[solve]]`` condition of ``mech`` in the user's units and the
    report's language, with its file named by its name only (not the path of the
    machine that ran it): ``L7 = 0.752169525 m: φ6(S = Sp) = 90° (hitch_003.toml:234;
    residual 1.3e-12°)``. ``units``: the unit of each parameter
    (:func:`assur.core.display.parameter_units`; default: as the file gives them);
    ``shown``: the :class:`assur.core.display.DisplayUnits` of the report (default: the
    condition in the unit its file wrote it in).

    Examples
    --------
    >>> from assur import io
    >>> model = io.load(io.bundled("hitch_003"))
    >>> [sc.condition.unknown for sc in model.solved]  # the seed's three Find blocks
    ['L4', 'Sp', 'L7']
    >>> solved_line(model.solved[0], model.mechanism, "en")  # doctest: +ELLIPSIS
    'L4 = 0.661283167 m: Y56(S = Smin) = 0.2 m (hitch_003.toml:...; residual ... m)'
    >>> solved_line(model.solved[2], model.mechanism, "ru")  # doctest: +ELLIPSIS
    'L7 = 0,752169525 м: φ6(S = Sp) = 90° (hitch_003.toml:...; невязка ...°)'
    >>> from assur.core.display import parameter_units, unit_system
    >>> imp = unit_system(model.mechanism, "imperial")
    >>> solved_line(model.solved[0], model.mechanism, "en",
    ...             parameter_units(model.mechanism, imp), imp)  # doctest: +ELLIPSIS
    'L4 = 26.0347704 in: Y56(S = Smin) = 7.87402 in (hitch_003.toml:...; residual ... in)'
    """
    units = display_units(mech) if units is None else units
    c = sc.condition
    kind = "angle" if c.quantity.startswith("phi") else "length"
    cu = c.unit or DEFAULT_UNITS[kind]
    if shown is not None and shown.system != "file":
        cu = shown[kind]

    def pos(k, v):  # a position: a parameter's name, or a number in the coordinate's unit
        if isinstance(v, str):
            return v
        kind = "angle" if mech.coordinate_kind(k) == "angle" else "length"
        return with_unit(v, shown[kind] if shown is not None else DEFAULT_UNITS[kind], lang)

    at = ", ".join(f"{k} = {pos(k, v)}" for k, v in c.at.items())
    where = f"{Path(c.source).name}; " if c.source else ""
    return t("solved_line", lang, c.unknown, with_unit(sc.value, units[c.unknown], lang, 9),
             f"{symbol(c.quantity)}({at}) = {with_unit(c.target, cu, lang)}", where,
             with_unit(sc.residual, cu, lang, 2))
