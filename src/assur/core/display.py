"""The unit systems results are shown in: one layer for every output.

Inside assur every value is SI (m, rad, N, Pa, kg, s). Every view — a table, a
CSV or XLSX header, a figure's axis, a report's text, a terminal line, a page
field, an error message — shows it through a :class:`DisplayUnits`: for each
*kind* of quantity (length, angle, force, pressure, moment, …) the unit it is shown
in. The conversion is made once, at the edge, with the factors of
:data:`assur.core.units.COMMON_UNITS` (bitwise pint's).

Unit systems (:data:`SYSTEMS`), chosen per model file (``[display] units``), per
command (``--units``) and on the page:

``file`` (the default)
    each kind in the unit the model file gave it (the unit most of its parameters
    of that kind are written in: ``P6 = "27.5 kN"`` shows every force in kN), a
    kind the file gives no unit for in the unit derived from those it gives
    (kN and m: moments in kN·m; mm: analogs in rad/mm), else SI with angles in
    degrees (:data:`assur.core.quantities.DEFAULT_UNITS`);
``engineering``
    mm, deg, kN, MPa, kN·m, l/min, kg (and the units derived from them);
``si``
    m, rad, N, Pa, N·m, m³/s, kg;
``imperial``
    in, deg, lbf, psi, lbf·ft, gal/min, lb.

The table of kinds (:data:`KINDS`) is also what tests check every output against:
a value of a kind is shown in no other unit than its system's.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field

import numpy as np

from .quantities import DEFAULT_UNITS, Unit, parameter_quantities
from .units import common_unit

__all__ = ["SYSTEMS", "KINDS", "DisplayUnits", "unit_system", "kind_of", "check_system",
           "factor", "parameter_units"]

#: the unit systems, ``file`` first (the default)
SYSTEMS = ("file", "engineering", "si", "imperial")


@dataclass(frozen=True)
class _Kind:
    """A kind of quantity: its unit in each fixed system (as shown: ``·``, ``²``) and,
    for a derived kind, the kinds it is made of (``((kind, power), …)``) to derive its
    unit in the ``file`` system."""

    si: str
    engineering: str
    imperial: str
    of: tuple = ()


#: every kind a result is shown as, and its unit per system (``file``: see the module)
KINDS = {
    "length": _Kind("m", "mm", "in"),
    "angle": _Kind("rad", "deg", "deg"),
    "force": _Kind("N", "kN", "lbf"),
    "pressure": _Kind("Pa", "MPa", "psi"),
    "moment": _Kind("N·m", "kN·m", "lbf·ft", (("force", 1), ("length", 1))),
    "mass": _Kind("kg", "kg", "lb"),
    "inertia": _Kind("kg·m²", "kg·m²", "lb·ft²"),
    "stiffness": _Kind("N/m", "kN/m", "lbf/in", (("force", 1), ("length", -1))),
    "velocity": _Kind("m/s", "m/s", "in/s", (("length", 1), ("time", -1))),
    "acceleration": _Kind("m/s²", "m/s²", "ft/s²"),
    "angular_velocity": _Kind("rad/s", "rad/s", "rad/s"),
    "angular_acceleration": _Kind("rad/s²", "rad/s²", "rad/s²"),
    "time": _Kind("s", "s", "s"),
    "energy": _Kind("J", "J", "ft·lbf"),
    "power": _Kind("W", "kW", "hp"),
    "area": _Kind("m²", "mm²", "in²", (("length", 2),)),
    "volume": _Kind("m³", "l", "gal"),
    "flow": _Kind("m³/s", "l/min", "gal/min"),
    # analogs: dφ/dS, dY/dφ, d²Y/dφ², dJ/dφ (the angle in radians in every system)
    "angle_per_length": _Kind("rad/m", "rad/mm", "rad/in", (("length", -1),)),
    "length_per_angle": _Kind("m/rad", "mm/rad", "in/rad", (("length", 1),)),
    "length_per_angle2": _Kind("m/rad²", "mm/rad²", "in/rad²", (("length", 1),)),
    "angle_per_length2": _Kind("rad/m²", "rad/mm²", "rad/in²", (("length", -2),)),
    "per_length": _Kind("1/m", "1/mm", "1/in", (("length", -1),)),
    "per_length2": _Kind("1/m²", "1/mm²", "1/in²", (("length", -2),)),
    "inertia_per_angle": _Kind("kg·m²/rad", "kg·m²/rad", "lb·ft²/rad"),
    "number": _Kind("-", "-", "-"),
    "percent": _Kind("%", "%", "%"),
}

#: the units of a derived kind in the ``file`` system, by the units of its parts
#: (a derivation not listed here falls back to the kind's default)
_DERIVED = {
    "moment": {("N", "m"): "N·m", ("kN", "m"): "kN·m", ("N", "mm"): "N·mm",
               ("lbf", "in"): "lbf·in", ("lbf", "ft"): "lbf·ft"},
    "stiffness": {("N", "m"): "N/m", ("kN", "m"): "kN/m", ("N", "mm"): "N/mm",
                  ("lbf", "in"): "lbf/in"},
    "velocity": {("m", "s"): "m/s", ("mm", "s"): "mm/s", ("in", "s"): "in/s"},
    "area": {("m",): "m²", ("mm",): "mm²", ("cm",): "cm²", ("in",): "in²"},
    "angle_per_length": {("m",): "rad/m", ("mm",): "rad/mm", ("in",): "rad/in"},
    "length_per_angle": {("m",): "m/rad", ("mm",): "mm/rad", ("in",): "in/rad"},
    "length_per_angle2": {("m",): "m/rad²", ("mm",): "mm/rad²", ("in",): "in/rad²"},
    "angle_per_length2": {("m",): "rad/m²", ("mm",): "rad/mm²", ("in",): "rad/in²"},
    "per_length": {("m",): "1/m", ("mm",): "1/mm", ("in",): "1/in"},
    "per_length2": {("m",): "1/m²", ("mm",): "1/mm²", ("in",): "1/in²"},
}

#: shown texts that are not a unit pint reads (factor 1 to themselves)
_PLAIN = {"-": 1.0, "%": 1.0}


def factor(text: str) -> float:
    """SI value of one ``text`` (``"kN·m"`` → 1000; ``"-"`` and ``"%"``: 1, a count
    and a percentage are shown as they are), for the units of :data:`KINDS` and
    :data:`assur.core.units.COMMON_UNITS`.

    Examples
    --------
    >>> from assur.core.display import factor
    >>> factor("kN·m"), factor("MPa"), factor("%")
    (1000.0, 1000000.0, 1.0)
    """
    if text in _PLAIN:
        return _PLAIN[text]
    c = common_unit(text)
    if c is None:
        raise KeyError(f"no factor for the unit {text!r}")
    return c.factor


def _unit(text: str) -> Unit:
    return Unit(text, factor(text))


#: shown text → kind, for every unit of every fixed system (and "deg")
_BY_TEXT = {}
for _name, _k in KINDS.items():
    for _text in (_k.si, _k.engineering, _k.imperial):
        _BY_TEXT.setdefault(_text, _name)
_BY_TEXT["deg"] = "angle"
#: a unit's dimension (length, mass, time, radian) → kind, for other units ("kN", "mm")
_BY_DIMENSION = {}
for _name, _k in KINDS.items():
    _c = common_unit(_k.si) if _k.si not in _PLAIN else None
    if _c is not None:
        _BY_DIMENSION.setdefault(_c.dimension + (_c.radian,), _name)


def kind_of(text: str) -> str | None:
    """The kind of a unit as a table or figure writes it, or None when it is of no
    kind of :data:`KINDS` (shown as it is).

    Examples
    --------
    >>> from assur.core.display import kind_of
    >>> kind_of("m"), kind_of("deg"), kind_of("N·m"), kind_of("J"), kind_of("kN")
    ('length', 'angle', 'moment', 'energy', 'force')
    >>> kind_of("rad/m"), kind_of("-"), kind_of("MPa/s")
    ('angle_per_length', 'number', None)
    """
    if text in _BY_TEXT:
        return _BY_TEXT[text]
    c = common_unit(text)
    if c is None:
        return None
    return _BY_DIMENSION.get(c.dimension + (c.radian,))


def check_system(system: str) -> str:
    """``system`` if it is one of :data:`SYSTEMS`, else ValueError naming them.

    Examples
    --------
    >>> from assur.core.display import check_system
    >>> check_system("imperial")
    'imperial'
    >>> check_system("metric")
    Traceback (most recent call last):
    ...
    ValueError: units must be one of: file, engineering, si, imperial; got 'metric'
    """
    if system not in SYSTEMS:
        raise ValueError(f"units must be one of: {', '.join(SYSTEMS)}; got {system!r}")
    return system


@dataclass(frozen=True)
class DisplayUnits:
    """The unit each kind of quantity is shown in.

    Attributes
    ----------
    system : str
        One of :data:`SYSTEMS`.
    units : dict of str to Unit
        ``{kind: Unit}`` for every kind of :data:`KINDS`.

    Examples
    --------
    >>> from assur.core.display import unit_system
    >>> eng = unit_system(None, "engineering")
    >>> eng["force"].text, eng.value(27500.0, "force")        # 27 500 N [kN]
    ('kN', 27.5)
    >>> values, text = eng.convert([0.42, 0.67], "m")           # a column in m → mm
    >>> [round(float(v), 9) for v in values], text
    ([420.0, 670.0], 'mm')
    >>> imp = unit_system(None, "imperial")
    >>> round(imp.value(17.5e6, "pressure"), 1), imp["pressure"].text   # 17.5 MPa [psi]
    (2538.2, 'psi')
    """

    system: str
    units: dict = field(default_factory=dict)

    def __getitem__(self, kind: str) -> Unit:
        """The unit of ``kind`` (a kind of :data:`KINDS`)."""
        return self.units[kind]

    def value(self, si, kind: str):
        """``si`` [SI] of ``kind`` in its display unit (a float, or an array).

        Examples
        --------
        >>> from assur.core.display import unit_system
        >>> unit_system(None, "engineering").value(17.5e6, "pressure")   # [MPa]
        17.5
        """
        return self.units[kind].of(si)

    def convert(self, values, text: str):
        """Values shown in ``text`` (a table column's unit: ``"m"``, ``"deg"``,
        ``"kN"``…) converted to this system: ``(values, unit text)``; a ratio of two
        units of known kinds with no kind of its own (``"MPa/s"``, ``"kg/m"``) in the
        system's units of its parts; any other unit of no known kind as it is.

        Examples
        --------
        >>> from assur.core.display import unit_system
        >>> si = unit_system(None, "si")
        >>> v, u = si.convert(180.0, "deg")            # 180° [rad]
        >>> round(float(v), 6), u
        (3.141593, 'rad')
        >>> v, u = si.convert(2.5, "MPa/s")            # a pressure per time
        >>> float(v), u
        (2500000.0, 'Pa/s')
        >>> v, u = unit_system(None, "engineering").convert(3000.0, "kg/m")
        >>> float(v), u                                # [kg/mm]
        (3.0, 'kg/mm')
        >>> si.convert(2.5, "furlong")                 # no kind: as it is
        (2.5, 'furlong')
        """
        kind = kind_of(text)
        if kind is None:
            top, slash, bottom = text.rpartition("/")
            if slash and kind_of(top) is not None and kind_of(bottom) is not None:
                v, u = self.convert(values, top)
                d, w = self.convert(1.0, bottom)
                return np.asarray(v, dtype=float) / float(d), f"{u}/{w}"
            return values, text
        target = self.units[kind]
        if target.text == text:
            return values, text
        scale = factor(text) / target.scale
        return np.asarray(values, dtype=float) * scale, target.text


def _fixed(system: str) -> dict:
    return {name: _unit(getattr(k, system)) for name, k in KINDS.items()}


def _defaults() -> dict:
    """SI, with angles in degrees (a kind the ``file`` system has no unit for)."""
    out = _fixed("si")
    out.update({k: u for k, u in DEFAULT_UNITS.items() if k in out and u.text != "-"})
    out["angle"] = Unit("deg", math.pi / 180)
    return out


def _given(mech) -> dict:
    """``{kind: Unit}`` the model file gives: per kind, the unit most of its parameters
    and other values of that kind are written in (the first such on a tie)."""
    if mech is None:
        return {}
    quantities = parameter_quantities(mech)
    votes: dict = {}

    def vote(kind, u):
        if kind in KINDS and kind not in ("number", "percent") and u is not None:
            votes.setdefault(kind, Counter())[(u.text, u.scale)] += 1

    for name, u in mech.units.items():
        vote(quantities.get(name), u)
    for u in mech.display.get("given", ()):  # values written with a unit, not parameters
        vote(kind_of(u.text), u)
    out = {}
    for kind, counts in votes.items():
        (text, scale), _ = counts.most_common(1)[0]
        out[kind] = Unit(text, scale)
    return out


def unit_system(mech, system: str | None = None) -> DisplayUnits:
    """The :class:`DisplayUnits` of ``system`` for the mechanism ``mech`` (whose model
    file's units the ``file`` system follows; None: no file).

    ``system`` None: the one the model file chose (``[display] units``), else
    ``"file"``; a :class:`DisplayUnits` is returned as it is (every view takes either).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.display import unit_system
    >>> u = unit_system(examples.hitch_003())    # hitch_003.toml: lengths in m, P6 in kN
    >>> [u[k].text for k in ("length", "angle", "force", "pressure", "moment")]
    ['m', 'deg', 'kN', 'MPa', 'kN·m']
    >>> [unit_system(None, s)["angle"].text for s in ("file", "si", "imperial")]
    ['deg', 'rad', 'deg']
    """
    if isinstance(system, DisplayUnits):
        return system
    if system is None:
        system = (mech.display.get("units") if mech is not None else None) or "file"
    check_system(system)
    if system != "file":
        return DisplayUnits(system, _fixed(system))
    units = _defaults()
    given = _given(mech)
    units.update(given)
    for name, k in KINDS.items():
        if name in given or not k.of:
            continue
        parts = tuple(units[part].text for part, _ in k.of)
        if not any(part in given for part, _ in k.of):
            continue  # nothing of it in the file: the default
        text = _DERIVED.get(name, {}).get(parts)
        if text is not None:
            units[name] = _unit(text)
    return DisplayUnits("file", units)


def parameter_units(mech, units: DisplayUnits) -> dict:
    """``{parameter: Unit}`` each parameter of ``mech`` is shown in: in the ``file``
    system the unit the file wrote it in (:func:`assur.core.quantities.display_units`),
    in another the system's unit of its quantity.

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.display import parameter_units, unit_system
    >>> m = examples.hitch_003()
    >>> [parameter_units(m, unit_system(m, s))["Dgc"].text for s in ("file", "imperial")]
    ['mm', 'in']
    """
    from .quantities import display_units

    shown = display_units(mech)
    if units.system == "file":
        return shown
    quantities = parameter_quantities(mech)
    # a parameter no group uses (a position of the range, a condition's target): the
    # kind of the unit the file wrote it in
    return {name: units.units.get(quantities.get(name) or kind_of(u.text), u)
            for name, u in shown.items()}
