"""A circuit: the components of one hydraulic drive, checked to fit together."""

from __future__ import annotations

from dataclasses import dataclass

from ..errors import ModelError
from .base import ROLES

__all__ = ["Circuit"]

#: how many components of each role a circuit takes: (least, most)
_COUNTS = {"pump": (1, 1), "relief": (0, 1), "valve": (0, 1), "line": (0, None),
           "volume": (1, 1), "cylinder": (1, 1), "divider": (0, 0)}


@dataclass(frozen=True)
class Circuit:
    """The open circuit of seed 001 lab 6 (fig. 6.1): a pump, optionally a relief
    valve and a directional valve, lines, the lumped oil volume and the working
    cylinder(s) on one generalized coordinate.

    Parameters
    ----------
    components : tuple
        Component objects (:func:`assur.drive.registry`), at most one of each role
        except lines.

    Raises
    ------
    ModelError
        A role missing or given twice, or a component the circuit does not take (a
        flow divider: the two-cylinder crane's drive is not simulated yet).
    """

    components: tuple

    def __post_init__(self):
        object.__setattr__(self, "components", tuple(self.components))
        by = {r: [] for r in ROLES}
        for c in self.components:
            by[c.role].append(c)
        for role, (lo, hi) in _COUNTS.items():
            n = len(by[role])
            if n < lo or (hi is not None and n > hi):
                want = f"exactly {lo}" if lo == hi else (f"at most {hi}" if lo == 0
                                                         else f"at least {lo}")
                names = [c.type_name for c in by[role]]
                raise ModelError(f"drive: expected {want} component(s) of role {role!r}, "
                                 f"found {n} {names}")

    def _one(self, role):
        return next((c for c in self.components if c.role == role), None)

    @property
    def pump(self):
        return self._one("pump")

    @property
    def relief(self):
        """The relief valve, or None."""
        return self._one("relief")

    @property
    def valve(self):
        return self._one("valve")

    @property
    def volume(self):
        return self._one("volume")

    @property
    def cylinder(self):
        return self._one("cylinder")

    @property
    def lines(self):
        """The components in series between the pump and the cylinder whose pressure
        losses make up a1, a2, a3: the lines and the directional valve."""
        return tuple(c for c in self.components if c.role in ("line", "valve"))

    @property
    def area(self) -> float:
        """Pressurised area of the cylinders [m²]."""
        return self.cylinder.area

    def pump_flow(self) -> float:
        """Q of the pump [m³/s]."""
        return self.pump.flow()

    def steady_speed(self) -> float:
        """The rod speed the pump's flow sets, Q/A [m/s] (lab 6: "the steady speed is
        set by the pump's flow and the area of the cylinders")."""
        return self.pump_flow() / self.area

    def relief_flow(self, p):
        """Flow through the relief valve at the pressure p [m³/s] (0 without one)."""
        rv = self.relief
        return 0.0 * p if rv is None else rv.flow(p, self.pump_flow())

    def loss_coefficients(self):
        """(a1, a2, a3) of lab 6 eq. (3), summed over the lines and the valve at the
        pump's flow [Pa·s²/m, Pa·s/m, Pa·s²/m²]."""
        a = [0.0, 0.0, 0.0]
        for c in self.lines:
            for i, v in enumerate(c.loss_coefficients(self.area, self.pump_flow())):
                a[i] += v
        return tuple(a)
