"""Lines from the pump to the cylinder (seed 001 lab 6, line 4 of fig. 6.1) and their
pressure loss, lab 6 eq. (3): ``p2 = p1 − (a1·S̈ + a2·Ṡ + a3·Ṡ|Ṡ|)``.

The lab prints the turbulent term as ``a3·S²``: a slip (BRIEF.md) — the turbulent
and local losses grow with the square of the velocity and keep its sign, so the
term is ``a3·Ṡ|Ṡ|``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from ...texts import Text
from .base import nonneg, positive, register

__all__ = ["Line", "LineLosses"]


@register
@dataclass(frozen=True)
class LineLosses:
    """The lab's loss coefficients given directly (eq. 3).

    Parameters
    ----------
    a1 : float
        Inertia of the oil referred to the piston [Pa·s²/m].
    a2 : float
        Laminar loss [Pa·s/m].
    a3 : float
        Turbulent and local losses [Pa·s²/m²].
    coordinate : str, optional
        The generalized coordinate of the cylinder whose branch this line is in
        (needed when the circuit drives more than one coordinate).
    name : str, optional

    Examples
    --------
    >>> from assur.dynamics.drive import LineLosses
    >>> line = LineLosses(a1=2.7e5, a2=1.5e6, a3=3.5e7)   # [Pa·s²/m, Pa·s/m, Pa·s²/m²]
    >>> a1, a2, a3 = line.loss_coefficients(area=0.0123, flow=8.64e-4)
    >>> round((a2 * 0.0704 + a3 * 0.0704 ** 2) / 1e6, 3)   # Δp [MPa] at 70.4 mm/s, steady
    0.279
    """

    a1: float = 0.0
    a2: float = 0.0
    a3: float = 0.0
    coordinate: str | None = None
    name: str | None = None

    type_name: ClassVar[str] = "line_losses"
    title: ClassVar[Text] = Text("line losses", ru="потери в магистрали")
    role: ClassVar[str] = "line"
    quantities: ClassVar = {"a1": "inertance", "a2": "resistance", "a3": "turbulent resistance"}

    def __post_init__(self):
        nonneg(self, "a1", "a2", "a3")

    def loss_coefficients(self, area, flow):
        """(a1, a2, a3) as given (``area`` [m²] and ``flow`` [m³/s] are not used).

        Examples
        --------
        >>> from assur.dynamics.drive import LineLosses
        >>> LineLosses(a2=1.5e6).loss_coefficients(area=0.0123, flow=8.64e-4)  # [SI]
        (0.0, 1500000.0, 0.0)
        """
        return float(self.a1), float(self.a2), float(self.a3)


@register
@dataclass(frozen=True)
class Line:
    """A hose or pipe of length L and bore d filled with oil (density ρ, kinematic
    viscosity ν), with local resistances ΣK (bends, fittings).

    The oil moves with u = Q/A_h = (A/A_h)·Ṡ (A the pistons' area, A_h = π·d²/4), so
    referred to the piston speed (lab 6: "the motion of the oil column and its
    derivatives are expressed through those of the piston by continuity"):

    * inertia: ``a1 = ρ·L·A/A_h`` [Pa·s²/m];
    * friction by the Darcy factor f of :func:`fluids.friction.friction_factor` at the
      working flow's Reynolds number Re = u·d/ν (relative roughness ε/d):
      laminar (Re below :data:`fluids.friction.LAMINAR_TRANSITION_PIPE`, f = 64/Re):
      ``Δp = f·(L/d)·ρu²/2`` is linear in u: ``a2 = 32·ρ·ν·L·A/(A_h·d²)``;
      turbulent: ``a3 = f(Re)·(L/d)·(ρ/2)·(A/A_h)²`` (f frozen at the working flow);
    * local resistances: ``a3 += ΣK·(ρ/2)·(A/A_h)²`` (ΣK e.g. from
      :mod:`fluids.fittings`).

    Parameters
    ----------
    length : float
        L [m].
    diameter : float
        Bore d [m].
    density : float
        ρ [kg/m³] (a mineral hydraulic oil: 870).
    viscosity : float
        Kinematic viscosity ν [m²/s] (ISO VG 46 at 40 °C: 46e-6).
    roughness : float
        Absolute roughness ε [m] (a hose: 1.5e-6... 1e-5).
    fittings : float
        Sum of the local loss coefficients ΣK [-].
    coordinate : str, optional
        The generalized coordinate of the cylinder whose branch this line is in
        (needed when the circuit drives more than one coordinate).
    name : str, optional

    Examples
    --------
    >>> line = Line(length=5.0, diameter=0.016, density=870.0, viscosity=46e-6)
    >>> a1, a2, a3 = line.loss_coefficients(area=0.0122718, flow=8.64e-4)
    >>> round(line.reynolds(8.64e-4))
    1495
    >>> round(a2 * 0.0704 / 1e3, 1)      # kPa at the working speed
    107.5
    """

    length: float
    diameter: float
    density: float = 870.0
    viscosity: float = 46e-6
    roughness: float = 1.5e-6
    fittings: float = 0.0
    coordinate: str | None = None
    name: str | None = None

    type_name: ClassVar[str] = "line"
    title: ClassVar[Text] = Text("line", ru="трубопровод")
    role: ClassVar[str] = "line"
    quantities: ClassVar = {"length": "length", "diameter": "length", "density": "density",
                            "viscosity": "kinematic viscosity", "roughness": "length",
                            "fittings": "number"}
    #: a smooth pipe's roughness is 0; at most 1000 fittings on one line
    spans: ClassVar = {"roughness": (0.0, 1e-2), "fittings": (0, 1000)}

    def __post_init__(self):
        positive(self, "length", "diameter", "density", "viscosity")
        nonneg(self, "roughness", "fittings")

    @property
    def area(self) -> float:
        """Bore area A_h = π·d²/4 [m²].

        Examples
        --------
        >>> from assur.dynamics.drive import Line
        >>> round(Line(length=5.0, diameter=0.016).area * 1e6, 2)   # [mm²] of a 16 mm bore
        201.06
        """
        return math.pi * self.diameter ** 2 / 4

    def reynolds(self, flow) -> float:
        """Re = u·d/ν at the flow ``flow`` [m³/s].

        Examples
        --------
        >>> from assur.dynamics.drive import Line
        >>> line = Line(length=5.0, diameter=0.016, viscosity=46e-6)   # [m], [m], [m²/s]
        >>> round(line.reynolds(8.64e-4)), round(line.reynolds(-8.64e-4))  # [-], either sense
        (1495, 1495)
        """
        return abs(flow) / self.area * self.diameter / self.viscosity

    def loss_coefficients(self, area, flow):
        """(a1, a2, a3) referred to the speed of a piston of area ``area`` [m²] at the
        working flow ``flow`` [m³/s] (which fixes the regime and f) [Pa·s²/m,
        Pa·s/m, Pa·s²/m²].

        Examples
        --------
        >>> import math
        >>> from assur.dynamics.drive import Line
        >>> line = Line(length=5.0, diameter=0.016, fittings=6)   # lab 6's hose [m]
        >>> area = math.pi * 0.125 ** 2 / 4                       # piston [m²]
        >>> a1, a2, a3 = line.loss_coefficients(area, flow=8.64e-4)   # laminar, Re = 1495
        >>> round(a1), round(a2), round(a3)     # [Pa·s²/m, Pa·s/m, Pa·s²/m²]
        (265503, 1526642, 9723008)
        >>> a1, a2, a3 = line.loss_coefficients(area, flow=3e-3)      # turbulent
        >>> a2, round(a3 / 1e6, 2)              # a2 [Pa·s/m]; a3 [MPa·s²/m²]
        (0.0, 28.51)
        """
        from fluids.friction import LAMINAR_TRANSITION_PIPE, friction_factor
        r = area / self.area
        rho, L, d = self.density, self.length, self.diameter
        a1 = rho * L * r
        Re = self.reynolds(flow)
        a3 = self.fittings * rho / 2 * r ** 2
        if Re < LAMINAR_TRANSITION_PIPE:
            # f = 64/Re: Δp = 32·ρ·ν·L·u/d² (Hagen–Poiseuille), linear in u
            a2 = 32 * rho * self.viscosity * L / d ** 2 * r
            return a1, a2, a3
        f = friction_factor(Re=Re, eD=self.roughness / d)
        return a1, 0.0, a3 + f * L / d * rho / 2 * r ** 2
