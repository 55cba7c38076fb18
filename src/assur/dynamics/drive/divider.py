"""Flow divider (seed 004 eqs. 63–68: the boom's and the stick's cylinders fed from
one pump)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ...errors import ModelError
from ...texts import Text
from .base import register

__all__ = ["FlowDivider"]


@register
@dataclass(frozen=True)
class FlowDivider:
    """Divides one flow Q into fixed shares, whatever the loads:

    ``Q_i = s_i·Q``,  Σ s_i = 1,

    so a cylinder fed Q_i on a side of area A_i moves at V_i = Q_i/A_i [m/s].

    Parameters
    ----------
    shares : tuple of float
        s_i [-], each in (0, 1], summing to 1.
    name : str, optional

    Examples
    --------
    >>> FlowDivider((0.5, 0.5)).flows(80 / 60e3)
    array([0.00066667, 0.00066667])
    """

    shares: tuple = (0.5, 0.5)
    name: str | None = None

    type_name: ClassVar[str] = "flow_divider"
    title: ClassVar[Text] = Text("flow divider", ru="делитель потока")
    role: ClassVar[str] = "divider"
    quantities: ClassVar = {}

    def __post_init__(self):
        s = np.asarray(self.shares, dtype=float)
        if s.ndim != 1 or s.size < 2 or not np.all(np.isfinite(s)) or np.any(s <= 0) \
                or abs(s.sum() - 1) > 1e-12:
            raise ModelError(f"flow_divider: shares = {self.shares!r} must be two or more "
                             f"numbers > 0 summing to 1")

    def flows(self, flow):
        """Q_i = s_i·Q [m³/s] of the flow ``flow`` [m³/s].

        Examples
        --------
        >>> from assur.dynamics.drive import FlowDivider
        >>> q = FlowDivider((0.6, 0.4)).flows(80 / 60e3)   # 80 l/min [m³/s]
        >>> (q * 60e3).round(6).tolist()                    # [l/min]
        [48.0, 32.0]
        """
        return np.asarray(self.shares, dtype=float) * flow

    def speeds(self, flow, areas):
        """V_i = s_i·Q/A_i [m/s] of cylinders of areas ``areas`` [m²].

        Examples
        --------
        >>> from assur.dynamics.drive import FlowDivider
        >>> v = FlowDivider((0.5, 0.5)).speeds(80 / 60e3, [0.01, 0.005])   # [m³/s], [m²]
        >>> v.round(6).tolist()                                            # [m/s]
        [0.066667, 0.133333]
        """
        return self.flows(flow) / np.asarray(areas, dtype=float)
