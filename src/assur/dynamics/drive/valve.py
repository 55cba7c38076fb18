"""Directional valve (seed 001 lab 6, valve 3 of fig. 6.1)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ...errors import ModelError
from ...texts import Text
from .base import nonneg, positive, register

__all__ = ["DirectionalValve", "POSITIONS"]

#: the valve's working positions: ``raise`` feeds the piston side (lab 6: the right
#: section raises; S grows), ``lower`` the rod side (the flow reversed; S shrinks)
POSITIONS = ("raise", "lower")


@register
@dataclass(frozen=True)
class DirectionalValve:
    """A directional valve in a working position: in *raise* the pump's line is
    connected to the cylinder's piston side (the rod extends, S grows), in *lower*
    to its rod side (the flow reversed: the rod retracts, S shrinks; the annulus
    π·(D² − d²)/4 is pressurised), the other side drained; with the pressure loss
    of an orifice

    ``Δp = Δp_nom·(Q/Q_nom)·|Q/Q_nom|`` [Pa]

    (Δp_nom at the catalogue's nominal flow Q_nom). Lab 6 takes the valve as
    inertia-free; its loss joins the line's turbulent term a3·u|u| (u the rod's
    speed in the driven sense, Q = A·u: ``a3 += Δp_nom·(A/Q_nom)²``).

    Parameters
    ----------
    position : {"raise", "lower"}
        The valve's position during the simulation.
    dp_nominal : float
        Pressure loss at the nominal flow Δp_nom [Pa] (≥ 0).
    nominal_flow : float
        Q_nom [m³/s] (> 0).
    coordinate : str, optional
        The generalized coordinate of the cylinder whose branch this valve is in
        (needed when the circuit drives more than one coordinate).
    name : str, optional

    Examples
    --------
    >>> import math
    >>> from assur.dynamics.drive import DirectionalValve
    >>> valve = DirectionalValve("raise", dp_nominal=0.3e6,      # 0.3 MPa [Pa]
    ...                          nominal_flow=80 / 60e3)         # at 80 l/min [m³/s]
    >>> area = math.pi * 0.125 ** 2 / 4            # lab 6's piston [m²]
    >>> a3 = valve.loss_coefficients(area, None)[2]
    >>> round(a3 * 0.0704 ** 2 / 1e6, 3)           # Δp [MPa] at the steady 70.4 mm/s
    0.126
    >>> DirectionalValve("hold")
    Traceback (most recent call last):
    ...
    assur.errors.ModelError: directional_valve: position must be one of: ['raise', 'lower'], got 'hold'
    """

    position: str = "raise"
    dp_nominal: float = 0.0
    nominal_flow: float = 1.0e-3
    coordinate: str | None = None
    name: str | None = None

    type_name: ClassVar[str] = "directional_valve"
    title: ClassVar[Text] = Text("directional valve", ru="распределитель")
    #: what reports call each word of the file's ``position``
    words: ClassVar[dict] = {"raise": Text("raise (to the piston side)",
                                           ru="подъём (в поршневую полость)"),
                             "lower": Text("lower (to the rod side)",
                                           ru="опускание (в штоковую полость)")}
    role: ClassVar[str] = "valve"
    quantities: ClassVar = {"dp_nominal": "pressure", "nominal_flow": "flow"}

    @property
    def sense(self) -> int:
        """+1 (``raise``: the force pushes S up) or −1 (``lower``) [-].

        Examples
        --------
        >>> from assur.dynamics.drive import DirectionalValve
        >>> DirectionalValve("raise").sense, DirectionalValve("lower").sense
        (1, -1)
        """
        return 1 if self.position == "raise" else -1

    def __post_init__(self):
        if self.position not in POSITIONS:
            raise ModelError(f"directional_valve: position must be one of: {list(POSITIONS)}, "
                             f"got {self.position!r}")
        nonneg(self, "dp_nominal")
        positive(self, "nominal_flow")

    def loss_coefficients(self, area, flow):
        """(a1, a2, a3) of the valve's loss referred to the piston speed Ṡ of a
        piston area ``area`` [m²] (Δp = a1·S̈ + a2·Ṡ + a3·Ṡ|Ṡ|) [Pa·s²/m, Pa·s/m,
        Pa·s²/m²]; ``flow`` (the working flow) is not needed by an orifice.

        Examples
        --------
        >>> from assur.dynamics.drive import DirectionalValve
        >>> valve = DirectionalValve(dp_nominal=0.3e6, nominal_flow=1e-3)   # [Pa], [m³/s]
        >>> a1, a2, a3 = valve.loss_coefficients(area=0.01, flow=None)      # [m²]
        >>> a1, a2, round(a3)        # a3 = 0.3e6·(0.01/1e-3)² [Pa·s²/m²]
        (0.0, 0.0, 30000000)
        """
        return 0.0, 0.0, self.dp_nominal * (area / self.nominal_flow) ** 2
