"""The ``[lift_test]`` section of a model file: the standard lift-capacity test of a
three-point hitch (ISO 789-2 / SAE J283; :mod:`assur.machines.hitch_lift`).

```toml
[lift_test]
hitch = "56"              # the lower-link hitch point
frame = "F610"            # the test frame's load point, 610 mm behind (a point of the model)
pressure_share = 0.9      # of the relief-valve setting (default 0.9)
positions = 6             # evenly spaced over the lift range (at least 6, the default)
# cylinder = "ГЦ"         # the cylinder tested (default: the only one)
```

Kept apart from the rest of the schema: :mod:`assur.io._schema` only admits the table,
:mod:`assur.io._build` calls :func:`build_lift_test` once the mechanism is built, and
the result is :attr:`assur.io.Model.lift_test`. Every error names the file, line and
key.
"""

from __future__ import annotations

from typing import Optional

from pydantic import BaseModel, ConfigDict, Field, StrictInt

from ..errors import ModelError
from ..machines.hitch_lift import LiftTest, check_lift_memory
from . import _schema as S
from ._units import NUMBER

__all__ = ["LiftTestSection", "build_lift_test"]


class LiftTestSection(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, populate_by_name=False)

    hitch: S.Name
    frame: Optional[S.Name] = None
    cylinder: Optional[S.Name] = None
    pressure_share: S.Value = 0.9
    positions: Optional[StrictInt] = Field(6, ge=6)


def build_lift_test(builder, mech):
    """The :class:`assur.machines.hitch_lift.LiftTest` of the file ``builder`` reads (None without
    a ``[lift_test]`` table); ``mech`` is the mechanism built from it."""
    raw = builder.data.get("lift_test")
    if raw is None:
        return None
    spec, errors = S.validate(LiftTestSection, raw, ("lift_test",))
    if errors:
        path, problem = errors[0]
        raise builder.error(path, problem)
    points = set(mech.points) | set(mech.frame_points)
    for key in ("hitch", "frame"):
        p = getattr(spec, key)
        if p is not None and p not in points:
            raise builder.error(("lift_test", key), f'expected a point of the model, found '
                                                    f'"{p}"{S.did_you_mean(p, points)}')
    if spec.hitch in mech.frame_points:
        raise builder.error(("lift_test", "hitch"), f'"{spec.hitch}" is a frame point, which does '
                                                    f"not move: expected the point the "
                                                    f"implement hangs on")
    names = [c.name for c in mech.cylinders]
    if spec.cylinder is not None and spec.cylinder not in names:
        raise builder.error(("lift_test", "cylinder"),
                            f'expected a cylinder of the model ({", ".join(names) or "none"}), '
                            f'found "{spec.cylinder}"{S.did_you_mean(spec.cylinder, names)}')
    if not names:
        raise builder.error(("lift_test",), "the lift test needs a cylinder ([[cylinders]])")
    try:  # the positions' analysis must fit in memory (before anything is allocated)
        check_lift_memory(mech, 6 if spec.positions is None else spec.positions)
    except ModelError as e:
        raise builder.error(("lift_test", "positions"), str(e)) from None
    share = builder.value(("lift_test", "pressure_share"), spec.pressure_share, NUMBER)
    share = float(mech.params[share]) if isinstance(share, str) else float(share)
    try:
        return LiftTest(spec.hitch, spec.frame, spec.cylinder, share, spec.positions)
    except ModelError as e:
        raise builder.error(("lift_test", "pressure_share"), str(e)) from None
