"""Directional valve (seed 001 lab 6, valve 3 of fig. 6.1)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..errors import ModelError
from .base import nonneg, positive, register

__all__ = ["DirectionalValve", "POSITIONS"]

#: the valve's positions this version simulates (lab 6: the right section raises)
POSITIONS = ("raise",)


@register
@dataclass(frozen=True)
class DirectionalValve:
    """A directional valve in its *raise* position: the pump's line is connected to
    the cylinder's piston side, with a pressure loss of an orifice

    ``Δp = Δp_nom·(Q/Q_nom)·|Q/Q_nom|`` [Pa]

    (Δp_nom at the catalogue's nominal flow Q_nom). Lab 6 takes the valve as
    inertia-free; its loss joins the line's turbulent term a3·Ṡ|Ṡ| (with Q = A·Ṡ:
    ``a3 += Δp_nom·(A/Q_nom)²``).

    Parameters
    ----------
    position : {"raise"}
        The valve's position during the simulation (lowering, through the rod side
        and a throttle, is not simulated yet).
    dp_nominal : float
        Pressure loss at the nominal flow Δp_nom [Pa] (≥ 0).
    nominal_flow : float
        Q_nom [m³/s] (> 0).
    name : str, optional
    """

    position: str = "raise"
    dp_nominal: float = 0.0
    nominal_flow: float = 1.0e-3
    name: str | None = None

    type_name: ClassVar[str] = "directional_valve"
    role: ClassVar[str] = "valve"
    quantities: ClassVar = {"dp_nominal": "pressure", "nominal_flow": "flow"}

    def __post_init__(self):
        if self.position not in POSITIONS:
            raise ModelError(f"directional_valve: position must be one of: {list(POSITIONS)}, "
                             f"got {self.position!r}")
        nonneg(self, "dp_nominal")
        positive(self, "nominal_flow")

    def loss_coefficients(self, area, flow):
        """(a1, a2, a3) of the valve's loss referred to the piston speed Ṡ of a
        piston area ``area`` [m²] (Δp = a1·S̈ + a2·Ṡ + a3·Ṡ|Ṡ|) [Pa·s²/m, Pa·s/m,
        Pa·s²/m²]; ``flow`` (the working flow) is not needed by an orifice."""
        return 0.0, 0.0, self.dp_nominal * (area / self.nominal_flow) ** 2
