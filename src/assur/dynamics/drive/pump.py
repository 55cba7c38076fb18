"""Gear pump (seed 001 lab 6, pump 1 of fig. 6.1: НШ-32)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

from ...core.inputs import MIN_EFFICIENCY
from ...texts import Text
from .base import positive, register

__all__ = ["GearPump"]


@register
@dataclass(frozen=True)
class GearPump:
    """A fixed-displacement (gear) pump delivering a constant flow.

    Lab 6 eq. (1): ``Q = q·n·η0``.

    Parameters
    ----------
    displacement : float
        Volume per revolution q [m³] (НШ-32: 32 cm³).
    speed : float
        Shaft speed ω [rad/s] (1800 rpm = 188.5 rad/s); n = ω/2π [rev/s].
    eta_volumetric : float
        Volumetric efficiency η0 [-] (lab 6: 0.9), in (0, 1].
    name : str, optional

    Examples
    --------
    >>> import math
    >>> pump = GearPump(32e-6, 1800 * 2 * math.pi / 60, 0.9)
    >>> round(pump.flow() * 60e3, 3)   # l/min
    51.84
    """

    displacement: float
    speed: float
    eta_volumetric: float = 1.0
    name: str | None = None

    type_name: ClassVar[str] = "gear_pump"
    title: ClassVar[Text] = Text("gear pump", ru="шестерённый насос")
    role: ClassVar[str] = "pump"
    quantities: ClassVar = {"displacement": "volume", "speed": "angular velocity",
                            "eta_volumetric": "number"}
    #: a volumetric efficiency within the project's efficiencies [MIN_EFFICIENCY, 1]
    #: (1e-9 left the cycles' forces 0/0)
    spans: ClassVar = {"eta_volumetric": (MIN_EFFICIENCY, 1.0)}

    def __post_init__(self):
        positive(self, "displacement", "speed", "eta_volumetric")
        if self.eta_volumetric > 1:
            from ...errors import ModelError
            raise ModelError(f"gear_pump: eta_volumetric = {self.eta_volumetric!r} must be "
                             f"in (0, 1]")

    def flow(self) -> float:
        """Delivered flow Q = q·n·η0 [m³/s].

        Examples
        --------
        >>> import math
        >>> from assur.dynamics.drive import GearPump
        >>> pump = GearPump(32e-6, 1800 * 2 * math.pi / 60, 0.9)   # НШ-32 at 1800 rpm
        >>> round(pump.flow() * 1e6, 1)      # [cm³/s]: 32 cm³ · 30 1/s · 0.9
        864.0
        """
        return self.displacement * self.speed / (2 * math.pi) * self.eta_volumetric
