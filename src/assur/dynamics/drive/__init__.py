"""Hydraulic components, one module each, behind one contract
(:mod:`assur.dynamics.drive.base`), and the circuit they form (:class:`Circuit`).

==================  ==========  ===================================================
type                role        equation
==================  ==========  ===================================================
gear_pump           pump        Q = q·n·η0
relief_valve        relief      Q_r = Q_nom·max(p − p_set, 0)/Δp_reg
directional_valve   valve       Δp = Δp_nom·(Q/Q_nom)·|Q/Q_nom|
line                line        a1 = ρL·A/A_h; a2 (laminar) or a3 (turbulent) from
                                the Darcy factor of :mod:`fluids`; ΣK·ρ/2·(A/A_h)²
line_losses         line        a1, a2, a3 given (lab 6 eq. 3)
oil_volume          volume      Q = A·Ṡ + ṗ·(V0 + A·(S − S0))/E_pr
cylinder            cylinder    F = count·A·p2; end stops s_min, s_max
flow_divider        divider     Q_i = s_i·Q
==================  ==========  ===================================================
"""

from .base import ROLES, component_type, register, registry, span
from .pump import GearPump
from .relief import ReliefValve
from .valve import DirectionalValve
from .line import Line, LineLosses
from .volume import BULK_MODULUS, OilVolume
from .cylinder import DriveCylinder
from .divider import FlowDivider
from .circuit import Circuit

__all__ = ["ROLES", "register", "registry", "component_type", "span", "GearPump", "ReliefValve",
           "DirectionalValve", "Line", "LineLosses", "OilVolume", "BULK_MODULUS",
           "DriveCylinder", "FlowDivider", "Circuit"]
