"""Values with units in model files: parsing, kinds, conversion to SI.

A value in a model file is a plain number or a string ``"<number> <unit>"``
(``"17.5 MPa"``, ``"22 deg"``, ``"80 mm"``, ``"80 l/min"``, ``"27.5 kN"``). The unit is
read by pint — here, at the edge, and nowhere else (DESIGN.md §7). Every value
has a *kind* (length, angle, force, …) that follows from the key it is used at;
the unit must have the kind's dimension, and the value converts to the kind's SI
unit. A plain number is taken as SI, except for angles, where it is degrees.

No expression is ever evaluated: the number is matched by a regular expression,
and the unit, restricted to letters, digits, ``* / ^ ( )``, spaces, ``%`` and
``°·²³``, is handed to pint's unit parser.

The units model files use most (m, mm, deg, kN, MPa, kg, N*m, l/min, rpm, …) are
read from a small table, :data:`COMMON_UNITS`, holding for each its factor to SI
base units and its dimension, bitwise as pint gives them
(``tests/io/test_units.py`` compares every entry with pint): building pint's
registry costs about 0.2 s of every command's start, so it is built only for a
unit outside the table.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from functools import lru_cache

from ..core.units import _DEG, COMMON_UNITS, _Common, _normalise, common_unit  # noqa: F401

_NUMBER = re.compile(r"\s*([-+]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
_UNIT_CHARS = re.compile(r"^[A-Za-zµμΩ°%·²³0-9*/^(). _-]*$")
_NAME = re.compile(r"^[^\W\d]\w*$")
#: largest integer a file may hold (a float above it loses more than rounding)
_MAX_INT = 10**300


@dataclass(frozen=True)
class Kind:
    """What a key holds: its name, SI unit (pint syntax) and an example for messages."""

    name: str
    article: str
    si: str
    example: str

    def __str__(self):
        return self.name


LENGTH = Kind("length", "a length", "m", '"0.48 m"')
ANGLE = Kind("angle", "an angle", "rad", '"22 deg"')
FORCE = Kind("force", "a force", "N", '"27.5 kN"')
PRESSURE = Kind("pressure", "a pressure", "Pa", '"17.5 MPa"')
MASS = Kind("mass", "a mass", "kg", '"1500 kg"')
MOMENT = Kind("moment", "a moment", "N*m", '"2.9 kN*m"')
STIFFNESS = Kind("stiffness", "a spring rate", "N/m", '"20 kN/m"')
INERTIA = Kind("inertia", "a moment of inertia", "kg*m**2", '"12 kg*m^2"')
NUMBER = Kind("number", "a plain number", "", "0.84")

KINDS = {k.name: k for k in (LENGTH, ANGLE, FORCE, PRESSURE, MASS, MOMENT, STIFFNESS, INERTIA,
                             NUMBER)}
#: the acceleration of gravity ([model] gravity)
ACCELERATION = Kind("acceleration", "an acceleration", "m/s**2", '"9.81 m/s^2"')
KINDS[ACCELERATION.name] = ACCELERATION
#: the speed of a crank and the times of a given ω(t) ([motion])
ANGULAR_VELOCITY = Kind("angular velocity", "an angular velocity", "rad/s", '"300 rpm"')
TIME = Kind("time", "a time", "s", '"0.5 s"')
KINDS[ANGULAR_VELOCITY.name] = ANGULAR_VELOCITY
KINDS[TIME.name] = TIME
#: the speed of a cylinder's rod ([motion] of a length coordinate)
VELOCITY = Kind("velocity", "a velocity", "m/s", '"0.05 m/s"')
KINDS[VELOCITY.name] = VELOCITY



def _is_degree(unit: str) -> bool:
    c = common_unit(unit)
    if c is not None:
        return c.is_angle and c.factor == _DEG
    return _parse_units(unit) == registry().degree


@lru_cache(maxsize=1)
def registry():
    """The pint unit registry (created once, on the first value with a unit).

    pint keeps its parsed definitions in ``<assur cache>/pint`` (beside the kernels,
    :func:`assur.kernel.cache_dir`), which makes later processes build it ~7× faster;
    where that folder cannot be written the registry is built from the definitions.
    """
    import pint

    from ..kernel.cache import cache_dir
    try:
        return pint.UnitRegistry(cache_folder=cache_dir().parent / "pint")
    except OSError:  # an unwritable cache: pint parses its definitions itself
        return pint.UnitRegistry()


def is_name(text: str) -> bool:
    """A parameter or coordinate name: a letter or ``_`` then letters, digits, ``_``."""
    return bool(_NAME.match(text))


@dataclass(frozen=True)
class Raw:
    """A value as written: ``magnitude`` and ``unit`` (``None`` for a plain number)."""

    magnitude: float
    unit: str | None
    text: str


class UnitError(ValueError):
    """A value string that is not ``<number> <unit>`` or whose unit pint does not know."""


def parse(value) -> Raw | str:
    """A file value → :class:`Raw` (number, maybe with a unit) or a name (``str``).

    Raises
    ------
    UnitError
        For a string that is neither a name nor ``<number> <unit>`` (empty message),
        or an unknown unit (the message names it).
    """
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        if isinstance(value, int) and abs(value) > _MAX_INT:  # float() would overflow
            raise UnitError("expected a number of at most 1e300 in magnitude")
        if not math.isfinite(value):  # TOML has inf and nan
            raise UnitError("expected a finite number")
        return Raw(value, None, repr(value))
    text = value.strip()
    if is_name(text):
        return text
    m = _NUMBER.match(text)
    if not m:
        raise UnitError("")
    mag = float(m.group(1))
    if not math.isfinite(mag):  # "1e999" reads as inf
        raise UnitError("expected a finite number (at most about 1.8e308 in magnitude)")
    unit = m.group(2)
    if not unit:
        return Raw(mag, None, value)
    if not _UNIT_CHARS.match(unit) or unit[:1].isdigit():
        raise UnitError(f'cannot read the unit "{unit}"')
    problem = _unit_problem(unit)
    if problem:
        raise UnitError(problem)
    return Raw(mag, unit, value)


@lru_cache(maxsize=4096)
def _unit_problem(unit: str) -> str | None:
    """Why pint cannot use ``unit`` (unknown, or a scale to SI beyond a float), or None;
    cached: a file repeats the same few units (loading stays linear in its size)."""
    if common_unit(unit) is not None:
        return None
    try:
        u = _parse_units(unit)
    except Exception:  # pint raises several types for unknown or malformed units
        return f'unknown unit "{unit}"'
    try:  # the unit's scale to SI must be a finite, non-zero float ("km^1000" is not)
        scale = registry().Quantity(1.0, u).to_base_units().magnitude
        _root(unit)
    except (OverflowError, ZeroDivisionError, ArithmeticError):
        scale = math.inf
    if not (math.isfinite(scale) and scale != 0.0):
        return (f'cannot use the unit "{unit}": its scale to SI units is beyond the range of '
                f"a float; expected a unit such as m, mm, kN, MPa, deg")
    return None


@lru_cache(maxsize=4096)
def _parse_units(unit: str):
    return registry().parse_units(_normalise(unit))


@lru_cache(maxsize=4096)
def _root(unit: str):
    return registry().get_root_units(_parse_units(unit))[1]


@lru_cache(maxsize=4096)
def _dimensionality(unit: str):
    return registry().Quantity(1.0, _parse_units(unit)).dimensionality


def unit_kind(raw: Raw) -> Kind | None:
    """The kind a unit belongs to, or None when it is none of :data:`KINDS`."""
    for k in KINDS.values():
        if _compatible(raw, k):
            return k
    return None


@lru_cache(maxsize=4096)
def _compatible_unit(unit: str, kind: Kind) -> bool:
    c = common_unit(unit)
    k = common_unit(kind.si) if kind.si else None
    if c is not None and (kind is ANGLE or kind is NUMBER or k is not None):
        if kind is ANGLE:
            return c.is_angle
        if kind is NUMBER:
            return c.is_number
        return not c.is_angle and c.dimension == k.dimension
    ureg = registry()
    root = _root(unit)
    if kind is ANGLE:
        return root == ureg.radian
    if kind is NUMBER:
        return root == ureg.dimensionless
    if root == ureg.radian:
        return False
    return _dimensionality(unit) == ureg.parse_units(kind.si).dimensionality


def _compatible(raw: Raw, kind: Kind) -> bool:
    return _compatible_unit(raw.unit, kind)


def to_si(raw: Raw, kind: Kind | None):
    """The SI value of ``raw`` used as ``kind`` (None: whatever its unit says).

    A plain number is SI; for an angle it is degrees. Raises :class:`UnitError`
    when the unit has another dimension than ``kind``.
    """
    if raw.unit is None:
        if kind is ANGLE:
            return math.radians(raw.magnitude)
        if kind is None or kind is NUMBER:
            return raw.magnitude  # an integer count stays an integer
        return float(raw.magnitude)
    unit = _normalise(raw.unit)
    if kind is None:
        factor = _base_factor(unit)
        if factor is None:  # an offset unit (°C…): pint converts the value itself
            q = registry().Quantity(raw.magnitude, unit).to_base_units()
            return _finite(float(q.magnitude), raw)
        return _finite(raw.magnitude * factor, raw)
    if not _compatible(raw, kind):
        raise UnitError(f"expected {kind.article} (e.g. {kind.example})")
    if kind is ANGLE and _is_degree(raw.unit):
        return math.radians(raw.magnitude)  # the same rounding as a plain number
    return _finite(raw.magnitude * _factor(raw.unit, kind.si or "dimensionless"), raw)


def display_unit(raw: Raw, kind: Kind | None):
    """The :class:`assur.core.quantities.Unit` to show a value written as ``raw`` in, used as
    ``kind``: the unit the file wrote (``"27.5 kN"`` → kN), or for a plain number the
    kind's default (an angle in degrees, otherwise SI)."""
    from ..core.quantities import DEFAULT_UNITS, Unit, unit_text

    name = kind.name if kind is not None else (unit_kind(raw).name
                                               if raw.unit and unit_kind(raw) else None)
    if raw.unit is None:
        return DEFAULT_UNITS.get(name, Unit("-"))
    if kind is ANGLE and _is_degree(raw.unit):
        return Unit(unit_text(raw.unit), math.pi / 180)
    if kind is not None:
        return Unit(unit_text(raw.unit), _factor(raw.unit, kind.si or "dimensionless"))
    factor = _base_factor(_normalise(raw.unit))
    return Unit(unit_text(raw.unit), factor) if factor else DEFAULT_UNITS.get(name, Unit("-"))


@lru_cache(maxsize=4096)
def _base_factor(unit: str):
    """The base-unit value of 1 ``unit``, or None for an offset unit; cached per unit
    (loading is linear in the number of values, not in pint's parsing)."""
    c = common_unit(unit)
    if c is not None:
        return c.factor
    q = registry().Quantity(1.0, unit)
    if not q._is_multiplicative:
        return None
    return float(q.to_base_units().magnitude)


@lru_cache(maxsize=4096)
def _factor(unit: str, si: str) -> float:
    """The SI value of 1 ``unit`` (the kinds have no offset units), cached."""
    c = common_unit(unit)
    k = common_unit(si) if si != "dimensionless" else _Common(1.0)
    if c is not None and k is not None and k.factor == 1.0:
        return c.factor
    return float(registry().Quantity(1.0, _parse_units(unit)).to(si).magnitude)


def _finite(si: float, raw: Raw) -> float:
    if not math.isfinite(si):
        raise UnitError("expected a value whose size in SI units is a finite number (at "
                        "most about 1.8e308)")
    return si
