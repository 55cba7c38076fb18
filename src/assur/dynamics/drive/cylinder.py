"""The working cylinder(s) of the drive (seed 001 lab 6, cylinder 5 of fig. 6.1),
with its end stops."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ...core.cylinders import chamber_area
from ...errors import ModelError
from ...texts import Text
from .base import positive, register

__all__ = ["DriveCylinder"]


@register
@dataclass(frozen=True)
class DriveCylinder:
    """Identical cylinders in parallel driving one generalized coordinate (their
    pin-to-pin length S), the piston side pressurised::

        base o====[ p2 |=========o rod end      F = count·A·p2, pushing (S grows)

    ``A = π·D²/4`` per cylinder; the rod's annulus π·(D² − d²)/4 is drained (the
    chamber areas of :func:`assur.core.cylinders.chamber_area`). The
    stroke ends at the stops ``s_min`` and ``s_max`` (pin-to-pin lengths): a
    piston reaching a stop stays there (its kinetic energy is lost in the impact,
    which the simulation records) until the force reverses.

    Parameters
    ----------
    coordinate : str
        The generalized coordinate S of the mechanism [m].
    bore : float
        Piston diameter D [m] (lab 6: 0.125).
    rod : float
        Rod diameter d [m] (lab 6: 0.05).
    s_min, s_max : float
        Pin-to-pin lengths at the stops [m].
    count : int
        Number of cylinders (lab 6: the load is shared equally; their rods move
        alike) [-].
    name : str, optional

    Examples
    --------
    >>> from assur.dynamics.drive import DriveCylinder
    >>> cyl = DriveCylinder("S", bore=0.125, rod=0.05, s_min=0.55, s_max=0.8)  # lab 6 [m]
    >>> round(cyl.area * 17e6 / 1e3, 1)      # push at 17 MPa [kN]
    208.6
    >>> DriveCylinder("S", bore=0.05, rod=0.125, s_min=0.55, s_max=0.8)
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: cylinder 'S': rod = 0.125 m must be smaller than bore = 0.05 m
    """

    coordinate: str
    bore: float
    rod: float
    s_min: float
    s_max: float
    count: int = 1
    name: str | None = None

    type_name: ClassVar[str] = "cylinder"
    title: ClassVar[Text] = Text("cylinder", ru="гидроцилиндр")
    role: ClassVar[str] = "cylinder"
    quantities: ClassVar = {"bore": "length", "rod": "length", "s_min": "length",
                            "s_max": "length", "count": "number"}
    #: cylinders working as one: 1 … 100
    spans: ClassVar = {"count": (1, 100)}

    def __post_init__(self):
        positive(self, "bore", "rod", "s_min", "s_max", "count")
        if not self.rod < self.bore:
            raise ModelError(f"cylinder {self.name or self.coordinate!r}: rod = {self.rod} m "
                             f"must be smaller than bore = {self.bore} m")
        if not self.s_min < self.s_max:
            raise ModelError(f"cylinder {self.name or self.coordinate!r}: s_min = "
                             f"{self.s_min} m must be below s_max = {self.s_max} m")
        if int(self.count) != self.count:
            raise ModelError(f"cylinder {self.name or self.coordinate!r}: count = "
                             f"{self.count!r} must be a whole number")

    @property
    def piston_area(self) -> float:
        """A = π·D²/4 of one cylinder [m²].

        Examples
        --------
        >>> from assur.dynamics.drive import DriveCylinder
        >>> cyl = DriveCylinder("S", bore=0.125, rod=0.05, s_min=0.55, s_max=0.8)
        >>> round(cyl.piston_area * 1e4, 1)    # [cm²], lab 6's 122.7 cm²
        122.7
        """
        return chamber_area(self.bore, self.rod, 0.0, "piston")

    @property
    def rod_side_area(self) -> float:
        """π·(D² − d²)/4 of one cylinder [m²].

        Examples
        --------
        >>> from assur.dynamics.drive import DriveCylinder
        >>> cyl = DriveCylinder("S", bore=0.125, rod=0.05, s_min=0.55, s_max=0.8)
        >>> round(cyl.rod_side_area * 1e4, 1)  # the annulus [cm²]
        103.1
        """
        return chamber_area(self.bore, self.rod, 0.0, "rod")

    @property
    def area(self) -> float:
        """The pressurised area of all the cylinders, count·A [m²].

        Examples
        --------
        >>> from assur.dynamics.drive import DriveCylinder
        >>> two = DriveCylinder("S", bore=0.08, rod=0.04, s_min=0.42, s_max=0.67, count=2)
        >>> round(two.area * 1e4, 2)           # two 80 mm pistons [cm²]
        100.53
        """
        return self.count * self.piston_area
