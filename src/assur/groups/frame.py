"""Frame (ground) pivot: a point fixed at ``(x, y)`` [m], or placed by a length and an
angle from another frame point (seed 002: O3 = O1 + l10∠j10, O6 = O3 + l8∠j8), on
link "0"."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..errors import ModelError
from ..kernel.emit import emit_zero_jets, pt
from .base import Field, Group, Ref, register

__all__ = ["Frame"]


@register
@dataclass(frozen=True)
class Frame(Group):
    """A frame pivot at fixed coordinates ``x``, ``y`` [m] (numbers or parameters) — or,
    in polar form, at ``origin + length·(cos angle, sin angle)`` from another frame
    point ``origin`` (``length`` [m], ``angle`` [rad] from +x, counter-clockwise;
    numbers or parameters)::

                       ● name
                      /
              length /
                    /  angle
          origin ●------------ +x

    The polar form is evaluated per design like any parameter (a pre-pass fills the
    point's rows of the parameter table), so its length and angle may be solved by
    ``[[solve]]`` conditions or vary over a batch of designs.
    """

    x: Ref | None = None
    y: Ref | None = None
    origin: str | None = None
    length: Ref | None = None
    angle: Ref | None = None

    type_name: ClassVar[str] = "frame"
    kind: ClassVar[str] = "frame point"
    kind_ru: ClassVar[str] = "шарнир стойки"
    link_roles: ClassVar = None
    out_fields: ClassVar = ()
    fields: ClassVar = (Field("x", "value", "length", default=None, doc="x of the pivot [m]"),
                        Field("y", "value", "length", default=None, doc="y of the pivot [m]"),
                        Field("origin", "point", default=None,
                              doc="polar form: the frame point it is placed from"),
                        Field("length", "value", "length", default=None,
                              doc="polar form: |origin–point| [m]"),
                        Field("angle", "value", "angle", default=None,
                              doc="polar form: direction origin → point from +x [°]"))

    @property
    def polar(self) -> bool:
        """True for a point placed by length and angle from ``origin``."""
        return self.origin is not None

    @classmethod
    def check_fields(cls, given):
        cart, pol = given & {"x", "y"}, given & {"origin", "length", "angle"}
        if cart and pol:
            return "give either x and y, or origin, length and angle (not both forms)"
        if pol and pol != {"origin", "length", "angle"}:
            return "the polar form needs origin, length and angle"
        if not pol and cart != {"x", "y"}:
            return "give x and y, or origin, length and angle"
        return None

    def validate(self, coordinates):
        given = {f.name for f in self.fields if getattr(self, f.name) is not None}
        problem = self.check_fields(given)
        if problem:
            return problem
        for r in (self.x, self.y, self.length, self.angle):
            if isinstance(r, str) and r in coordinates:
                return f"a frame point cannot move: {r!r} is a generalized coordinate"
        return None

    def inputs(self):
        return (self.origin,) if self.polar else ()

    def outputs(self):
        return (self.name,)

    def refs(self):
        if self.polar:
            return {"length": self.length, "angle": self.angle}
        return {"x": self.x, "y": self.y}

    def topology(self, t):
        if self.polar and t.owner(self.origin) != "0":
            raise ModelError(f"frame point {self.name!r} is placed from {self.origin!r}, "
                             f"which is not a frame point (it moves with link "
                             f"{t.owner(self.origin)!r})")
        t.attach("0", self.name)
        return ()

    def evaluate(self, pts, val):
        if self.polar:
            ox, oy = pts[self.origin]
            r, a = val(self.length), val(self.angle)
            pts[self.name] = (ox + r * np.cos(a), oy + r * np.sin(a))
            return
        x = val(self.x)
        pts[self.name] = (x, val(self.y) + 0 * x)

    def compile(self, c):
        if self.polar:
            rx, ry = c.derived_row(), c.derived_row()
            ox, oy = c.frame_rows[self.origin]
            c.prepare(self, (rx, ry, ox, oy, c.pref(self.length), c.pref(self.angle)))
        else:
            rx, ry = c.pref(self.x), c.pref(self.y)
        c.frame_point(self.name, rx, ry)
        return (c.slot(self.name), rx, ry)

    def prepare(self, data, ptab, positions_at):
        """Fill the polar point's rows: ``(x, y) = origin + length·(cos, sin)(angle)``
        per design (the origin's rows are filled before, in solving order)."""
        rx, ry, ox, oy, rl, ra = data
        ptab[rx] = ptab[ox] + ptab[rl] * np.cos(ptab[ra])
        ptab[ry] = ptab[oy] + ptab[rl] * np.sin(ptab[ra])

    def closure(self, P, val):
        """|point − (origin + length∠angle)| [m] of a polar point; None otherwise."""
        if not self.polar:
            return None
        (x, y), (ox, oy) = P(self.name), P(self.origin)
        r, a = val(self.length), val(self.angle)
        return np.hypot(x - ox - r * np.cos(a), y - oy - r * np.sin(a))

    @classmethod
    def emit(cls, E, i, row):
        o, rx, ry = row
        x, y = pt(o)
        E(f"{x} = params[{rx}, d]")
        E(f"{y} = params[{ry}, d]")
        emit_zero_jets(E, x)
        emit_zero_jets(E, y)

    def reactions(self, r):
        """The frame takes every force passed to it: nothing to solve."""
