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
    link of ``origin`` (its guide).

    Examples
    --------
    The double-rod cylinder of seed 001 lab 4's modern steering drive: its rod ends
    1L and 1R slide along +x from the cylinder's middle C0 at −h_rod and +h_rod
    (h_rod = 0.35 m, illustrative):

    >>> from assur import examples
    >>> m = examples.steering_lab4_modern()
    >>> g = m.group("rod end 1L")
    >>> g.origin, g.s, g.offset, g.direction          # direction [rad]
    ('C0', 'S', '-h_rod', 0.0)
    >>> r = m.solve([0.0, 0.03])                      # S [m]
    >>> [round(float(v), 3) for v in r.x("1L")]       # [m]
    [-0.35, -0.32]
    >>> [round(float(v), 3) for v in r.x("1R")]       # [m]
    [0.35, 0.38]
    >>> round(float(r.dx("1L")[0]), 3)                # ∂x/∂S [m/m]
    1.0
    """

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
        """The point of the guide line.

        Examples
        --------
        >>> from assur import examples
        >>> examples.steering_lab4_modern().group("rod end 1L").inputs()
        ('C0',)
        """
        return (self.origin,)

    def outputs(self):
        """The slider point.

        Examples
        --------
        >>> from assur import examples
        >>> examples.steering_lab4_modern().group("rod end 1L").outputs()
        ('1L',)
        """
        return (self.out,)

    def refs(self):
        """``offset`` [m] and ``direction`` [rad].

        Examples
        --------
        >>> from assur import examples
        >>> examples.steering_lab4_modern().group("rod end 1L").refs()   # −h_rod; 0 [rad]
        {'offset': '-h_rod', 'direction': 0.0}
        """
        return {"offset": self.offset, "direction": self.direction}

    def coordinates_driven(self):
        """The travel ``s``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.steering_lab4_modern()
        >>> m.group("rod end 1L").coordinates_driven(), m.group("rod end 1R").coordinates_driven()
        (('S',), ('S',))
        """
        return (self.s,)

    def topology(self, t):
        """Create the slider (a body of one point, which owns it) turning with the
        guide, the link of ``origin``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.steering_lab4_modern()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:3]:                     # the frame points 03, 04, C0
        ...     _ = g.topology(t)
        >>> m.group("rod end 1L").topology(t)
        ('1L',)
        >>> t.bodies["1L"], t.owner("1L"), t.turns["1L"]
        (['1L'], '1L', '0')
        """
        (l,) = t.link_names(self, 1)
        t.new(self, l, (self.out,))
        t.own(self.out, l)
        t.turns_with(l, t.owner(self.origin))
        return (l,)

    def evaluate(self, pts, val):
        """Add ``out = origin + (s + offset)·(cos, sin)(direction)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.steering_lab4_modern()
        >>> pts = {"C0": (0.0, -0.3)}                                  # [m]
        >>> val = lambda ref: ref_value({**m.params, "S": 0.03}, ref)  # S = 30 mm
        >>> m.group("rod end 1L").evaluate(pts, val)
        >>> [round(float(v), 3) for v in pts["1L"]]                    # C0 + (S − h_rod, 0) [m]
        [-0.32, -0.3]
        """
        ox, oy = pts[self.origin]
        t = val(self.s) + val(self.offset)
        b = val(self.direction)
        pts[self.out] = (ox + t * np.cos(b), oy + t * np.sin(b))

    def compile(self, c):
        """``(slot of out, slot of origin, coordinate index, row of the offset, trig row
        of the direction)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.steering_lab4_modern()
        >>> names = m.program().param_names        # the parameters, then −a_half, −h_rod
        >>> c = CompileContext(m.coordinates, names)
        >>> c.slot("C0")
        0
        >>> m.group("rod end 1L").compile(c)       # 1L in slot 1; S; row of −h_rod; trig 0
        (1, 0, 0, 18, 0)
        >>> c.trig                                 # cos, sin of the literal direction 0
        [('angle', ('lit', 0.0))]
        """
        return (c.slot(self.out), c.slot(self.origin), c.coord(self.s), c.pref(self.offset),
                c.trig_angle(c.pref(self.direction)))

    @classmethod
    def emit(cls, E, i, row):
        """The slider's position and its analog ``∂/∂s = (cos, sin)(direction)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import SliderInput
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.steering_lab4_modern().program().rows[3]   # rod end 1L
        >>> E = Emitter(K=1, order=1)
        >>> SliderInput.emit(E, 3, row[1:])
        >>> for line in E.lines:
        ...     print(line.strip())
        t3t = q[0, e] + params[18, d]
        t3c = trig[0, d]
        t3s = trig[1, d]
        x3 = x2 + t3t * t3c
        y3 = y2 + t3t * t3s
        x3_0 = x2_0 + t3c
        y3_0 = y2_0 + t3s
        """
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
        """The guide's and the drive's force on the slider; the drive takes the loads'
        component along the line (the actuator of ``s``).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.steering_lab4_modern()
        >>> r = statics.ReactionContext(m.solve([0.0]), set())
        >>> r.apply("1L", "1L", 1000.0, 500.0)          # a load on the rod end 1L [N]
        >>> r.links = m.topology.group_links["rod end 1L"]
        >>> m.group("rod end 1L").reactions(r)
        >>> round(float(np.squeeze(r.act["S"])), 3)     # the drive, along the line [N]
        -1000.0
        >>> pt, fx, fy, mz = r.joints[("0", "1L")]      # guide + drive on the slider
        >>> pt, round(float(fx[0, 0]), 3), round(float(fy[0, 0]), 3)   # [N]
        ('1L', -1000.0, -500.0)
        """
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
