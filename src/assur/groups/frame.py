"""Frame (ground) pivot: a point fixed at ``(x, y)`` [m], on link "0"."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from ..kernel.emit import emit_zero_jets, pt
from .base import Field, Group, Ref, register

__all__ = ["Frame"]


@register
@dataclass(frozen=True)
class Frame(Group):
    """A frame pivot at fixed coordinates ``x``, ``y`` [m] (numbers or parameters)."""

    x: Ref = 0.0
    y: Ref = 0.0

    type_name: ClassVar[str] = "frame"
    kind: ClassVar[str] = "frame point"
    kind_ru: ClassVar[str] = "шарнир стойки"
    link_roles: ClassVar = None
    fields: ClassVar = (Field("x", "value", "length", doc="x of the pivot [m]"),
                        Field("y", "value", "length", doc="y of the pivot [m]"))

    def inputs(self):
        return ()

    def outputs(self):
        return (self.name,)

    def refs(self):
        return {"x": self.x, "y": self.y}

    def topology(self, t):
        t.attach("0", self.name)
        return ()

    def evaluate(self, pts, val):
        x = val(self.x)
        pts[self.name] = (x, val(self.y) + 0 * x)

    def compile(self, c):
        rx, ry = c.pref(self.x), c.pref(self.y)
        c.frame_point(self.name, rx, ry)
        return (c.slot(self.name), rx, ry)

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
