"""Crank input: ``out = pivot + r·(cos(q + phase), sin(q + phase))`` (seed 002,
seed 001 lab 3: the crank angle φ1 is the generalized coordinate)."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..errors import ModelError
from ..kernel.emit import d, dd, length_ref, pt
from .base import Field, Group, Ref, register

__all__ = ["Crank"]


@register
@dataclass(frozen=True)
class Crank(Group):
    """Crank ``pivot–out`` of radius ``radius`` [m] turned by the coordinate
    ``q`` [rad] plus a fixed ``phase`` [rad]. ``links = (crank,)``.

    The coordinate keyword is ``q`` (as ``s`` is for the cylinder–lever group and the
    slider input): ``angle`` means a fixed angle in every group that has one.

    Reactions: the frame holds the crank at its pivot with the force and the
    driving moment ``M = −Σ M_pivot`` of the loads on the crank.

    Examples
    --------
    Seed 002's crank l1 = 0.15 m about O1, turned by the coordinate j1:

    >>> import numpy as np
    >>> from assur import examples
    >>> m = examples.combine_002()
    >>> m.group("crank 1")
    Crank(name='crank 1', pivot='O1', out='A', radius='l1', q='j1', phase=0.0, links=('1',))
    >>> r = m.solve(np.radians([0.0, 90.0]))                  # j1 [rad]
    >>> [round(float(v), 3) for v in r.x("A")]                # xA [m]
    [0.15, 0.0]
    >>> [round(float(v), 3) for v in r.y("A")]                # yA [m]
    [0.0, 0.15]
    >>> round(float(r.dy("A")[0]), 3)                         # ∂yA/∂j1 at j1 = 0 [m/rad]
    0.15
    """

    pivot: str = ""
    out: str = ""
    radius: Ref = 0.0
    q: str = ""
    phase: Ref = 0.0
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "crank"
    kind: ClassVar[str] = "crank"
    kind_ru: ClassVar[str] = "кривошип"
    driver_kind: ClassVar[str] = "angle"
    link_roles: ClassVar = ("crank",)
    fields: ClassVar = (
        Field("pivot", "point", doc="the crank's pivot (known)"),
        Field("out", "point", doc="the crank pin it adds"),
        Field("radius", "value", "length", "positive", True, doc="|pivot–out| [m]"),
        Field("q", "coordinate", "angle", doc="the crank angle, a coordinate [°]"),
        Field("phase", "value", "angle", default=0.0, doc="added to the angle [°]"),
    )

    def inputs(self):
        """The pivot.

        Examples
        --------
        >>> from assur import examples
        >>> examples.combine_002().group("crank 1").inputs()
        ('O1',)
        """
        return (self.pivot,)

    def outputs(self):
        """The crank pin.

        Examples
        --------
        >>> from assur import examples
        >>> examples.combine_002().group("crank 1").outputs()
        ('A',)
        """
        return (self.out,)

    def refs(self):
        """``radius`` [m] and ``phase`` [rad].

        Examples
        --------
        >>> from assur import examples
        >>> examples.combine_002().group("crank 1").refs()     # l1; phase 0 [rad]
        {'radius': 'l1', 'phase': 0.0}
        """
        return {"radius": self.radius, "phase": self.phase}

    def coordinates_driven(self):
        """The crank angle ``q``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.combine_002().group("crank 1").coordinates_driven()
        ('j1',)
        """
        return (self.q,)

    def topology(self, t):
        """Create the crank ``pivot–out`` (variable if its radius is a coordinate); it
        owns the pin.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.combine_002()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:3]:                     # the frame points O1, O3, O6
        ...     _ = g.topology(t)
        >>> m.group("crank 1").topology(t)
        ('1',)
        >>> t.bodies["1"], t.owner("A"), "1" in t.variable
        (['O1', 'A'], '1', False)
        """
        (l,) = t.link_names(self, 1)
        t.new(self, l, (self.pivot, self.out), variable=t.is_coord(self.radius))
        t.own(self.out, l)
        return (l,)

    def evaluate(self, pts, val):
        """Add ``out = pivot + radius·(cos, sin)(q + phase)``.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.combine_002()
        >>> pts = {"O1": (0.0, 0.0)}
        >>> val = lambda ref: ref_value({**m.params, "j1": np.pi / 2}, ref)   # j1 = 90°
        >>> m.group("crank 1").evaluate(pts, val)
        >>> [round(float(v), 3) for v in pts["A"]]      # [m]
        [0.0, 0.15]
        """
        px, py = pts[self.pivot]
        r = val(self.radius)
        th = val(self.q) + val(self.phase)
        pts[self.out] = (px + r * np.cos(th), py + r * np.sin(th))

    def compile(self, c):
        """``(slot of out, slot of pivot, length reference of the radius, coordinate
        index, row of the phase)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.combine_002()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> c.slot("O1")
        0
        >>> row = m.group("crank 1").compile(c)
        >>> row              # A in slot 1, O1 in 0, l1 in row 0, j1, a literal phase
        (1, 0, 0, 0, ('lit', 0.0))
        >>> c.resolve(row)   # the literal's row follows the 10 parameters
        (1, 0, 0, 0, 10)
        """
        return (c.slot(self.out), c.slot(self.pivot), c.lref(self.radius), c.coord(self.q),
                c.pref(self.phase))

    @classmethod
    def emit(cls, E, i, row):
        """The pin's position and its analogs ``∂/∂q = r·(−sin, cos)``,
        ``∂²/∂q² = −r·(cos, sin)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import Crank
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.combine_002().program().rows[3]   # op; A in slot 3, O1 in 0
        >>> E = Emitter(K=1, order=2)
        >>> Crank.emit(E, 3, row[1:])
        >>> for line in E.lines[-4:]:
        ...     print(line.strip())
        x3_0 = x0_0 - t3r * t3s
        y3_0 = y0_0 + t3r * t3c
        x3_00 = x0_00 - t3r * t3c
        y3_00 = y0_00 - t3r * t3s
        """
        o, A, refr, j, ph = row
        K = E.K
        ax, ay = pt(A)
        x, y = pt(o)
        rr, dr = length_ref(refr, K)
        t = f"t{i}"
        E(f"{t}r = {rr}")
        E(f"{t}th = q[{j}, e] + params[{ph}, d]")
        E(f"{t}c = math.cos({t}th)")
        E(f"{t}s = math.sin({t}th)")
        E(f"{x} = {ax} + {t}r * {t}c")
        E(f"{y} = {ay} + {t}r * {t}s")
        # out = pivot + r(q)·(cos θ, sin θ): θ' = δ_aj; r may itself be a coordinate
        for a in range(K):
            ex, ey = "", ""
            if a == j:
                ex += f" - {t}r * {t}s"
                ey += f" + {t}r * {t}c"
            if dr[a] != "0.0":
                ex += f" + {t}c"
                ey += f" + {t}s"
            E(f"{d(x, a)} = {d(ax, a)}{ex}")
            E(f"{d(y, a)} = {d(ay, a)}{ey}")
        for a, b in E.pairs:
            ex, ey = "", ""
            if a == j and b == j:
                ex += f" - {t}r * {t}c"
                ey += f" - {t}r * {t}s"
            for u_, v_ in ((a, b), (b, a)):
                # r'_u · θ'_v · (−sin, cos), both orders of the mixed derivative
                if dr[u_] != "0.0" and v_ == j:
                    ex += f" - {t}s"
                    ey += f" + {t}c"
            E(f"{dd(x, a, b)} = {dd(ax, a, b)}{ex}")
            E(f"{dd(y, a, b)} = {dd(ay, a, b)}{ey}")

    def reactions(self, r):
        """The frame's force on the crank at the pivot and the driving moment
        ``M = −Σ M_pivot`` (the actuator of ``q``).

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.combine_002()
        >>> r = statics.ReactionContext(m.solve([0.0]), set())   # the crank along +x
        >>> r.apply("1", "A", 0.0, -100.0)                      # 100 N down at the pin A
        >>> r.links = m.topology.group_links["crank 1"]
        >>> m.group("crank 1").reactions(r)
        >>> round(float(np.squeeze(r.act["j1"])), 3)            # driving moment [N·m]
        15.0
        >>> pt, fx, fy, mz = r.joints[("0", "1")]               # frame on crank, at O1
        >>> pt, round(float(fy[0, 0]), 3), round(float(mz[0, 0]), 3)   # [N], [N·m]
        ('O1', 100.0, 15.0)
        """
        (l,) = r.links
        if r.is_coord(self.radius):
            raise ModelError(f"reactions of crank {self.name!r} with a variable radius are not "
                             f"modelled (use the virtual-work forces)")
        P = self.pivot
        bP = r.owner(P)
        px, py = r.point(P)
        fx, fy, mp = r.about(l, px, py)
        r.record(bP, l, P, -fx, -fy, -mp)
        r.apply(bP, P, fx, fy)
        r.apply_moment(bP, mp)
        r.actuator(self.q, -mp)
