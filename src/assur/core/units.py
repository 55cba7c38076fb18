"""The units assur reads and shows: their factors to SI and dimensions.

:data:`COMMON_UNITS` holds, for the units model files and reports use most (m, mm,
deg, kN, MPa, kg, N*m, l/min, rpm; in, lbf, psi, lbf*ft, gal/min, lb…), the factor
to SI base units and the dimension, bitwise as pint gives them
(``tests/io/test_units.py`` compares every entry with pint). Reading a file
(:mod:`assur.io`) looks a unit up here before it builds pint's registry (about
0.2 s of a command's start); showing a value (:mod:`assur.core.display`) converts
from SI with the same factors, so a value read in a unit and shown in it is the
number the user wrote.
"""

from __future__ import annotations

import re
from typing import NamedTuple

__all__ = ["COMMON_UNITS", "common_unit"]


class _Common(NamedTuple):
    """A unit of :data:`COMMON_UNITS`: ``factor`` to SI base units and the exponents of
    length, mass, time and of the radian in its base units."""

    factor: float
    length: int = 0
    mass: int = 0
    time: int = 0
    radian: int = 0

    @property
    def dimension(self) -> tuple:
        """pint's dimensionality (the radian is dimensionless)."""
        return (self.length, self.mass, self.time)

    @property
    def is_angle(self) -> bool:
        """Whose root unit is the radian (pint's test of an angle)."""
        return (self.length, self.mass, self.time, self.radian) == (0, 0, 0, 1)

    @property
    def is_number(self) -> bool:
        """Whose root unit is dimensionless."""
        return (self.length, self.mass, self.time, self.radian) == (0, 0, 0, 0)


_DEG = 0.017453292519943295  # pint's degree in radians (= math.radians(1.0))

#: the common units, keyed as written after :func:`_normalise` with no spaces around
#: ``*`` and ``/``: factor to SI base units and dimension, bitwise those of pint
#: (the odd last digits of l, cm³, l/min are pint's own rounding)
COMMON_UNITS: dict[str, _Common] = {
    # length
    "m": _Common(1.0, length=1), "mm": _Common(0.001, length=1),
    "cm": _Common(0.01, length=1), "km": _Common(1000.0, length=1),
    # angle
    "deg": _Common(_DEG, radian=1), "degree": _Common(_DEG, radian=1),
    "degrees": _Common(_DEG, radian=1), "rad": _Common(1.0, radian=1),
    "radian": _Common(1.0, radian=1),
    # force, pressure, moment, spring rate
    "N": _Common(1.0, 1, 1, -2), "kN": _Common(1000.0, 1, 1, -2),
    "MN": _Common(1000000.0, 1, 1, -2),
    "Pa": _Common(1.0, -1, 1, -2), "kPa": _Common(1000.0, -1, 1, -2),
    "MPa": _Common(1000000.0, -1, 1, -2), "bar": _Common(100000.0, -1, 1, -2),
    "N*m": _Common(1.0, 2, 1, -2), "kN*m": _Common(1000.0, 2, 1, -2),
    "N/m": _Common(1.0, 0, 1, -2), "kN/m": _Common(1000.0, 0, 1, -2),
    "N/mm": _Common(1000.0, 0, 1, -2),
    # mass, moment of inertia, density
    "kg": _Common(1.0, mass=1), "g": _Common(0.001, mass=1), "t": _Common(1000.0, mass=1),
    "kg*m**2": _Common(1.0, 2, 1), "kg/m**3": _Common(1.0, -3, 1),
    # time, velocity, acceleration, angular velocity
    "s": _Common(1.0, time=1), "ms": _Common(0.001, time=1), "min": _Common(60.0, time=1),
    "m/s": _Common(1.0, 1, 0, -1), "mm/s": _Common(0.001, 1, 0, -1),
    "m/s**2": _Common(1.0, 1, 0, -2),
    "rad/s": _Common(1.0, time=-1, radian=1), "rpm": _Common(0.10471975511965977, time=-1, radian=1),
    # area, volume, flow, kinematic viscosity
    "m**2": _Common(1.0, length=2), "mm**2": _Common(1e-06, length=2),
    "cm**2": _Common(0.0001, length=2),
    "m**3": _Common(1.0, length=3), "cm**3": _Common(1.0000000000000002e-06, length=3),
    "l": _Common(0.0010000000000000002, length=3), "L": _Common(0.0010000000000000002, length=3),
    "l/min": _Common(1.666666666666667e-05, 3, 0, -1),
    "L/min": _Common(1.666666666666667e-05, 3, 0, -1),
    "m**3/s": _Common(1.0, 3, 0, -1), "mm**2/s": _Common(1e-06, 2, 0, -1),
    "m**2/s": _Common(1.0, 2, 0, -1),
    # hydraulic line coefficients (inertance, laminar and turbulent loss)
    "Pa*s**2/m": _Common(1.0, -2, 1, 0), "Pa*s/m": _Common(1.0, -2, 1, -1),
    "Pa*s**2/m**2": _Common(1.0, -3, 1, 0),
    # per length, per time, power
    "m**-1": _Common(1.0, length=-1), "1/m": _Common(1.0, length=-1),
    "m**-2": _Common(1.0, length=-2), "1/m**2": _Common(1.0, length=-2),
    "1/s": _Common(1.0, time=-1), "Hz": _Common(1.0, time=-1),
    "W": _Common(1.0, 2, 1, -3), "kW": _Common(1000.0, 2, 1, -3),
    # plain numbers
    "%": _Common(0.01), "percent": _Common(0.01),
    # imperial units (the display system "imperial", assur.core.display)
    "in": _Common(0.0254, length=1), "inch": _Common(0.0254, length=1),
    "ft": _Common(0.30479999999999996, length=1),
    "lbf": _Common(4.4482216152605005, 1, 1, -2), "psi": _Common(6894.7572931683635, -1, 1, -2),
    "lbf*ft": _Common(1.3558179483314006, 2, 1, -2), "lbf/in": _Common(175.12683524647645, 0, 1, -2),
    "lb": _Common(0.4535923700000001, mass=1), "lb*ft**2": _Common(0.0421401100938048, 2, 1),
    "gal": _Common(0.0037854117839999993, length=3), "in**2": _Common(0.00064516, length=2),
    "gal/min": _Common(6.309019639999999e-05, 3, 0, -1), "in/s": _Common(0.0254, 1, 0, -1),
    "ft/s**2": _Common(0.30479999999999996, 1, 0, -2), "hp": _Common(745.6998715822701, 2, 1, -3),
    "ft*lbf": _Common(1.3558179483314006, 2, 1, -2),
    "lbf*in": _Common(0.11298482902761671, 2, 1, -2), "N*mm": _Common(0.001, 2, 1, -2),
    # energy; angular acceleration; analogs (per length, per angle) shown in reports
    "J": _Common(1.0, 2, 1, -2), "kJ": _Common(1000.0, 2, 1, -2),
    "rad/s**2": _Common(1.0, time=-2, radian=1),
    "rad/m": _Common(1.0, length=-1, radian=1), "rad/mm": _Common(1000.0, length=-1, radian=1),
    "rad/in": _Common(39.37007874015748, length=-1, radian=1),
    "m/rad": _Common(1.0, length=1, radian=-1), "mm/rad": _Common(0.001, length=1, radian=-1),
    "in/rad": _Common(0.0254, length=1, radian=-1),
    "m/rad**2": _Common(1.0, length=1, radian=-2), "mm/rad**2": _Common(0.001, length=1, radian=-2),
    "in/rad**2": _Common(0.0254, length=1, radian=-2),
    "rad/m**2": _Common(1.0, length=-2, radian=1), "rad/mm**2": _Common(1e6, length=-2, radian=1),
    "rad/in**2": _Common(1550.0031000062002, length=-2, radian=1),
    "1/mm": _Common(1000.0, length=-1), "1/in": _Common(39.37007874015748, length=-1),
    "1/mm**2": _Common(1e6, length=-2), "1/in**2": _Common(1550.0031000062002, length=-2),
    "kg*m**2/rad": _Common(1.0, 2, 1, 0, -1), "lb*ft**2/rad": _Common(0.0421401100938048, 2, 1, 0, -1),
}


_AROUND_OPS = re.compile(r"\s*([*/])\s*")


def _normalise(unit: str) -> str:
    return (unit.replace("·", "*").replace("²", "**2").replace("³", "**3")
            .replace("°", "deg").replace("^", "**"))


def _key(unit: str) -> str:
    return _AROUND_OPS.sub(r"\1", _normalise(unit).strip())


def common_unit(unit: str) -> _Common | None:
    """``unit``'s entry in :data:`COMMON_UNITS`, or None (then pint reads it).

    Examples
    --------
    >>> from assur.core.units import common_unit
    >>> common_unit("kN·m").factor, common_unit("lbf * ft").dimension
    (1000.0, (2, 1, -2))
    >>> common_unit("furlong") is None
    True
    """
    return COMMON_UNITS.get(_key(unit))
