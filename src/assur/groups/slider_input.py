"""Prismatic input: a slider driven along a fixed line by the coordinate ``s``.

``out = origin + (s + offset)·(cos direction, sin direction)`` [m].
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..kernel.emit import d, dd, pt
from .base import Field, Group, Ref, register

__all__ = ["SliderInput"]


@register
@dataclass(frozen=True)
class SliderInput(Group):
    """Slider ``out`` on the line through ``origin`` at ``direction`` [rad] from +x,
    at distance ``s + offset`` [m]. ``links = (slider,)``; the slider turns with the
    link of ``origin`` (its guide)."""

    origin: str = ""
    out: str = ""
    s: str = ""
    offset: Ref = 0.0
    direction: Ref = 0.0
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "slider_input"
    kind: ClassVar[str] = "slider input"
    kind_ru: ClassVar[str] = "входной ползун"
    driver_kind: ClassVar[str] = "slider"
    link_roles: ClassVar = ("slider",)
    fields: ClassVar = (
        Field("origin", "point", doc="a point of the guide line (known)"),
        Field("out", "point", doc="the slider point it adds"),
        Field("s", "coordinate", "length", doc="the travel, a coordinate [m]"),
        Field("offset", "value", "length", default=0.0, doc="added to s [m]"),
        Field("direction", "value", "angle", default=0.0, doc="of the line from +x [°]"),
    )

    def inputs(self):
        return (self.origin,)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"offset": self.offset, "direction": self.direction}

    def coordinates_driven(self):
        return (self.s,)

    def topology(self, t):
        (l,) = t.link_names(self, 1)
        t.new(self, l, (self.out,))
        t.own(self.out, l)
        t.turns_with(l, t.owner(self.origin))
        return (l,)

    def evaluate(self, pts, val):
        ox, oy = pts[self.origin]
        t = val(self.s) + val(self.offset)
        b = val(self.direction)
        pts[self.out] = (ox + t * np.cos(b), oy + t * np.sin(b))

    def compile(self, c):
        return (c.slot(self.out), c.slot(self.origin), c.coord(self.s), c.pref(self.offset),
                c.trig_angle(c.pref(self.direction)))

    @classmethod
    def emit(cls, E, i, row):
        o, A, j, s0, trow = row
        ax, ay = pt(A)
        x, y = pt(o)
        t = f"t{i}"
        E(f"{t}t = q[{j}, e] + params[{s0}, d]")
        E(f"{t}c = trig[{trow}, d]")
        E(f"{t}s = trig[{trow + 1}, d]")
        E(f"{x} = {ax} + {t}t * {t}c")
        E(f"{y} = {ay} + {t}t * {t}s")
        for a in range(E.K):
            extra = (f" + {t}c", f" + {t}s") if a == j else ("", "")
            E(f"{d(x, a)} = {d(ax, a)}{extra[0]}")
            E(f"{d(y, a)} = {d(ay, a)}{extra[1]}")
        for a, b in E.pairs:
            E(f"{dd(x, a, b)} = {dd(ax, a, b)}")
            E(f"{dd(y, a, b)} = {dd(ay, a, b)}")

    def reactions(self, r):
        (l,) = r.links
        C = self.out
        bG = r.owner(self.origin)
        cx, cy = r.point(C)
        beta = r.value(self.direction)  # per design: shape (m, 1) or scalar
        ux, uy = np.cos(beta), np.sin(beta)
        fx, fy, mc = r.about(l, cx, cy)
        # guide + drive on the slider: −(fx, fy) at C and −mc
        r.record(bG, l, C, -fx, -fy, -mc)
        r.apply(bG, C, fx, fy)
        r.apply_moment(bG, mc)
        r.actuator(self.s, -(fx * ux + fy * uy))
