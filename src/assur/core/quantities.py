"""What each parameter of a mechanism measures, and the unit it is shown in.

Inside assur every value is SI (m, rad, N, Pa, kg, s). At the edges a value is shown
in the unit the user gave it (DESIGN.md §12): a model file that writes
``P6 = "27.5 kN"`` sees 27.5 kN in its report, not 27500 N. The loader records a
:class:`Unit` per parameter in :attr:`Mechanism.units`; a parameter without one is
shown in its quantity's default unit (:data:`DEFAULT_UNITS`: SI, angles in degrees).

The quantity of a parameter follows from where the mechanism uses it, through each
concept's own declaration — a group type's :class:`~assur.groups.Field` quantities,
a load's or a cylinder's ``quantities``, the machine's :meth:`quantities` — never
from a list of types kept here.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

__all__ = ["Unit", "DEFAULT_UNITS", "parameter_quantities", "display_units", "unit_text"]


@dataclass(frozen=True)
class Unit:
    """A unit to show values in.

    Attributes
    ----------
    text : str
        Its symbol as the user wrote it, normalised for display (``"kN"``,
        ``"MPa"``, ``"mm"``, ``"deg"``, ``"kN·m"``, ``"-"``).
    scale : float
        The SI value of one unit (kN: 1000; deg: π/180) [SI per unit].

    Examples
    --------
    >>> from assur.core.quantities import Unit
    >>> kN = Unit("kN", 1000.0)                # one kN is 1000 N
    >>> kN.of(27500.0)                         # P6 = 27 500 N shown in kN [kN]
    27.5
    """

    text: str
    scale: float = 1.0

    def of(self, si):
        """``si`` (SI) expressed in this unit.

        Examples
        --------
        >>> import math
        >>> from assur.core.quantities import Unit
        >>> Unit("MPa", 1e6).of(17.5e6)            # Pgc_max = 17.5e6 Pa [MPa]
        17.5
        >>> round(Unit("deg", math.pi / 180).of(math.pi / 2), 6)   # π/2 rad [deg]
        90.0
        """
        return si / self.scale

    @property
    def is_degrees(self) -> bool:
        """True for degrees (``"deg"`` or ``"°"`` with the scale π/180): a value shown
        in it is an angle.

        Examples
        --------
        >>> import math
        >>> from assur.core.quantities import Unit
        >>> Unit("deg", math.pi / 180).is_degrees, Unit("rad").is_degrees
        (True, False)
        >>> Unit("deg").is_degrees                 # named deg, but scale 1 [rad per unit]
        False
        """
        return self.text in ("deg", "°") and abs(self.scale - math.pi / 180) < 1e-15


#: the unit a quantity is shown in when the user gave none (SI; angles in degrees)
DEFAULT_UNITS = {
    "length": Unit("m"), "angle": Unit("deg", math.pi / 180), "force": Unit("N"),
    "pressure": Unit("Pa"), "mass": Unit("kg"), "moment": Unit("N·m"),
    "stiffness": Unit("N/m"), "inertia": Unit("kg·m²"), "number": Unit("-"),
    "acceleration": Unit("m/s²"), "angular_velocity": Unit("rad/s"),
}

_SUPERSCRIPT = {"2": "²", "3": "³"}


def unit_text(text: str) -> str:
    """A unit as a user wrote it (pint syntax), written for reading: ``kN*m`` →
    ``kN·m``, ``kg*m^2`` → ``kg·m²``, ``m/s**2`` → ``m/s²``, ``degree`` → ``deg``.

    Examples
    --------
    >>> from assur.core.quantities import unit_text
    >>> [unit_text(u) for u in ("kN*m", "kg*m^2", "m/s**2", "degree", "")]
    ['kN·m', 'kg·m²', 'm/s²', 'deg', '-']
    """
    s = text.strip()
    s = re.sub(r"\s*\*\*\s*([23])\b", lambda m: _SUPERSCRIPT[m.group(1)], s)
    s = re.sub(r"\s*\^\s*([23])\b", lambda m: _SUPERSCRIPT[m.group(1)], s)
    s = re.sub(r"\s*\*\s*", "·", s)
    s = re.sub(r"\b(degrees?)\b", "deg", s)
    return s or "-"


def parameter_quantities(mech) -> dict:
    """``{parameter: quantity}`` of the parameters ``mech`` uses ("length", "angle",
    "force", …; see :data:`DEFAULT_UNITS`); a parameter used nowhere is absent.

    A parameter used as a position of a coordinate (a ``[[solve]]`` position, a
    pose's ``at``) has the coordinate's quantity (a length, or a crank angle).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.quantities import parameter_quantities
    >>> q = parameter_quantities(examples.hitch_003())
    >>> q["L4"], q["phiBD"], q["P6"], q["Pgc_max"], q["eta"]
    ('length', 'angle', 'force', 'pressure', 'number')
    >>> "Smin" in q                            # used only by the [range] and [[solve]]
    False
    """
    from ..groups.base import signed_name
    out: dict = {}

    def put(ref, q):
        ref = signed_name(ref) or ref  # "-a" is a use of a
        if isinstance(ref, str) and ref in mech.params and q and ref not in out:
            out[ref] = q

    for g in mech.groups:
        fields = {f.name: f for f in g.fields}
        for name, ref in g.refs().items():
            f = fields.get(name)
            put(ref, f.quantity if f is not None else None)
        for f in g.fields:
            if f.role == "position":  # one value per coordinate, in their order
                pose = getattr(g, f.name, None) or ()
                pairs = pose.items() if hasattr(pose, "items") else zip(mech.coordinates, pose)
                for c, ref in pairs:
                    put(ref, _coordinate_quantity(mech, c))
    for part in tuple(mech.loads) + tuple(mech.cylinders):
        for name, q in getattr(part, "quantities", {}).items():
            put(getattr(part, name, None), q)
    machine = mech.machine
    if machine is not None and hasattr(machine, "quantities"):
        for ref, q in machine.quantities().items():
            put(ref, q)
    return out


def _coordinate_quantity(mech, c):
    return "angle" if mech.coordinate_kind(c) == "angle" else "length"


def display_units(mech) -> dict:
    """``{parameter: Unit}`` for every parameter of ``mech``: the unit it was given in
    (:attr:`Mechanism.units`), else its quantity's default, else ``"-"``.

    Examples
    --------
    >>> from assur import Mechanism, examples
    >>> from assur.core.quantities import display_units
    >>> u = display_units(examples.hitch_003())   # the units hitch_003.toml gives
    >>> u["P6"].text, u["Dgc"].text, u["phiBD"].text
    ('kN', 'mm', 'deg')
    >>> m = Mechanism("lever", coordinates=("S",), params={"L3": 0.2, "k": 1.0})
    >>> m = m.frame("01", 0.415, 0.563).frame("03", 0.25, 1.112)
    >>> m = m.cylinder_lever("lever", base="01", pivot="03", out="23", lever="L3",
    ...                      s="S", branch=-1, links=("2", "3"))
    >>> u = display_units(m)                   # no units given: the defaults, "-" if unused
    >>> u["L3"].text, u["k"].text
    ('m', '-')
    """
    quantities = parameter_quantities(mech)
    return {name: mech.units.get(name) or DEFAULT_UNITS.get(quantities.get(name), Unit("-"))
            for name in mech.params}
