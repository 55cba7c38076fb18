"""Relief valve (seed 001 lab 6, valve 2 of fig. 6.1: p_ПК = 16–20 MPa)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...texts import Text
from .base import nonneg, positive, register

__all__ = ["ReliefValve"]


@register
@dataclass(frozen=True)
class ReliefValve:
    """A direct-acting relief valve with a linear regulation characteristic.

    ``Q_r = Q_nom·max(p − p_set, 0)/Δp_reg`` [m³/s]: closed below its setting
    p_set, passing the nominal flow Q_nom at p_set + Δp_reg (the *regulation
    range*, the pressure rise from cracking to full flow) and more above it.
    Lab 6: "above the setting of relief valve 2 the oil goes through it to the tank
    until the pressure in the line falls" (the valve is inertia-free, as the lab
    takes it).

    Parameters
    ----------
    setting : float
        Cracking pressure p_set [Pa] (lab 6: 16–20 MPa).
    regulation_range : float
        Δp_reg [Pa] (> 0).
    nominal_flow : float, optional
        Q_nom [m³/s]; by default the pump's flow (:class:`assur.dynamics.drive.Circuit`).
    coordinate : str, optional
        The generalized coordinate of the cylinder whose branch this relief valve is in
        (without it the valve guards every branch: port relief valves of
        one setting).
    name : str, optional

    Examples
    --------
    >>> from assur.dynamics.drive import ReliefValve
    >>> valve = ReliefValve(setting=16e6, regulation_range=1e6)   # [Pa]: lab 6's 16 MPa
    >>> q = 51.84 / 60e3                 # the pump's flow [m³/s] (51.84 l/min)
    >>> [round(float(valve.flow(p, q)) * 60e3, 2) for p in (15e6, 16.5e6, 17e6)]  # [l/min]
    [0.0, 25.92, 51.84]
    """

    setting: float
    regulation_range: float
    nominal_flow: float | None = None
    coordinate: str | None = None
    name: str | None = None

    type_name: ClassVar[str] = "relief_valve"
    title: ClassVar[Text] = Text("relief valve", ru="предохранительный клапан")
    role: ClassVar[str] = "relief"
    quantities: ClassVar = {"setting": "pressure", "regulation_range": "pressure",
                            "nominal_flow": "flow"}

    def __post_init__(self):
        nonneg(self, "setting")
        positive(self, "regulation_range")
        if self.nominal_flow is not None:
            positive(self, "nominal_flow")

    def flow(self, p, nominal_flow):
        """Flow through the valve Q_r [m³/s] at the pressure p [Pa] (array or
        scalar), with ``nominal_flow`` [m³/s] when the valve has none of its own.

        Examples
        --------
        >>> import numpy as np
        >>> from assur.dynamics.drive import ReliefValve
        >>> valve = ReliefValve(16e6, 1e6, nominal_flow=1e-3)   # [Pa], [Pa], [m³/s]
        >>> p = np.array([10e6, 16e6, 16.25e6, 18e6])             # [Pa]
        >>> (valve.flow(p, nominal_flow=5e-4) * 1e3).round(6).tolist()   # its own Q_nom [l/s]
        [0.0, 0.0, 0.25, 2.0]
        """
        q = self.nominal_flow if self.nominal_flow is not None else nominal_flow
        return q * np.maximum(p - self.setting, 0.0) / self.regulation_range

    def conductance(self, nominal_flow):
        """dQ_r/dp above the setting [m³/(s·Pa)].

        Examples
        --------
        >>> from assur.dynamics.drive import ReliefValve
        >>> valve = ReliefValve(16e6, 1e6)     # [Pa]; Q_nom from the circuit
        >>> round(valve.conductance(8.64e-4) * 1e9, 6)   # [l/s per MPa]: 0.864 l/s over 1 MPa
        0.864
        """
        q = self.nominal_flow if self.nominal_flow is not None else nominal_flow
        return q / self.regulation_range
