"""The ``[dynamics]`` section of a model file: the flywheel's target (or a given
flywheel) and the counter-masses balancing may place (docs/crank-dynamics.md).

```toml
[dynamics]
delta = 0.05                      # target coefficient of speed irregularity δ [-]
# flywheel = "7.5 kg*m^2"         # or: a given flywheel J_f on the crank (δ is found)
objective = "amplitudes"          # balancing: amplitudes | max_amplitude | area

[[dynamics.counter_masses]]       # where a counter-mass may go, within bounds
link = "3"
mass = ["0 kg", "30 kg"]
along = ["-300 mm", "300 mm"]     # along the link's first → second point
offset = ["-100 mm", "100 mm"]    # to the left of that line
```

Kept apart from the rest of the schema: :mod:`assur.io._schema` only admits the
table, :mod:`assur.io._build` calls :func:`build_dynamics` once the mechanism is
built, and the result is :attr:`assur.io.Model.dynamics`. Values take units (or
are parameter names), and every error names the file, line and key.
"""

from __future__ import annotations

import typing
from dataclasses import dataclass
from typing import Optional

from pydantic import BaseModel, ConfigDict, model_validator
from pydantic_core import PydanticCustomError

from ..dynamics.balancing import OBJECTIVES, CounterMass
from . import _schema as S
from ..groups.base import ref_value
from ._units import INERTIA, LENGTH, MASS, NUMBER

__all__ = ["DynamicsSpec", "build_dynamics"]


class _Section(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=False)


class CounterMassEntry(_Section):
    link: S.Name
    mass: tuple[S.Value, S.Value]
    along: tuple[S.Value, S.Value] = (0.0, 0.0)
    offset: tuple[S.Value, S.Value] = (0.0, 0.0)


class DynamicsSection(_Section):
    delta: S.Value = None
    flywheel: S.Value = None
    objective: typing.Literal[OBJECTIVES] = "amplitudes"
    counter_masses: list[CounterMassEntry] = []

    @model_validator(mode="after")
    def _one_flywheel(self):
        if self.delta is not None and self.flywheel is not None:
            raise PydanticCustomError("dynamics", "expected delta (a target δ) or flywheel (a "
                                                  "given J_f), not both")
        return self


@dataclass(frozen=True)
class DynamicsSpec:
    """The ``[dynamics]`` section in SI.

    Attributes
    ----------
    delta : float or None
        Target coefficient of speed irregularity δ [-].
    flywheel : float or None
        A given flywheel's moment of inertia J_f [kg·m²].
    objective : str
        Balancing objective (:data:`assur.dynamics.balancing.OBJECTIVES`).
    counter_masses : tuple of CounterMass
        Where counter-masses may go, with their bounds [kg, m, m].
    """

    delta: Optional[float]
    flywheel: Optional[float]
    objective: str
    counter_masses: tuple


def build_dynamics(builder, mech):
    """The :class:`DynamicsSpec` of the file ``builder`` reads (None without a
    ``[dynamics]`` table); ``mech`` is the mechanism built from it."""
    raw = builder.data.get("dynamics")
    if raw is None:
        return None
    spec, errors = S.validate(DynamicsSection, raw, ("dynamics",))
    if errors:
        path, problem = errors[0]
        raise builder.error(path, problem)

    def value(path, v, kind, flag=None):
        si = builder.value(path, v, kind, flag)
        return float(ref_value(mech.params, si))

    delta = flywheel = None
    if spec.delta is not None:
        delta = value(("dynamics", "delta"), spec.delta, NUMBER)
        if not 0 < delta < 2:
            raise builder.error(("dynamics", "delta"), f"expected a coefficient of speed "
                                                       f"irregularity in (0, 2), found {delta!r}")
    if spec.flywheel is not None:
        flywheel = value(("dynamics", "flywheel"), spec.flywheel, INERTIA, "nonneg")
    moving = sorted(b for b in mech.topology.bodies if b != "0")
    cms = []
    for i, c in enumerate(spec.counter_masses):
        at = ("dynamics", "counter_masses", i)
        if c.link not in moving:
            raise builder.error(at + ("link",), f'expected a moving link (one of: '
                                                f'{", ".join(moving)}), found "{c.link}"'
                                                f"{S.did_you_mean(c.link, moving)}")
        bounds = {}
        for key, kind, flag in (("mass", MASS, "nonneg"), ("along", LENGTH, None),
                                ("offset", LENGTH, None)):
            lo, hi = (value(at + (key, j), v, kind, flag)
                      for j, v in enumerate(getattr(c, key)))
            if lo > hi:
                raise builder.error(at + (key,), f"expected bounds [low, high] with low ≤ high, "
                                                 f"found {S.show(list(getattr(c, key)))}")
            bounds[key] = (lo, hi)
        cms.append(CounterMass(c.link, **bounds))
    return DynamicsSpec(delta, flywheel, spec.objective, tuple(cms))
