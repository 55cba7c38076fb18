"""RPR dyad: a rod pinned at a known joint, sliding through a sleeve pivoted at a
known point (the slotted lever / кулиса; a passive cylinder).

The rod is pinned at ``a``; the sleeve turns about ``b`` and guides the rod along a
line at the signed perpendicular distance ``offset`` = e from ``b`` (positive: b
on the left of the rod's direction a → sleeve). The group adds the point ``out``
on the rod at ``length`` ℓ from ``a`` along the rod. With ``w = B − A``,
``D = |w|²`` and the slide ``s = σ·√(D − e²)`` (``branch`` σ = +1: the sleeve
ahead of ``a`` along the rod), the rod's direction is

.. math::
    \\hat u = \\frac{s\\,w - e\\,R_{90}\\,w}{D},\\qquad B = A + s\\,\\hat u + e\\,R_{90}\\hat u,
    \\qquad \\text{out} = A + \\ell\\,\\hat u.

The analogs differentiate ``s² = D − e²`` and ``û·D = s·w − e·R₉₀w`` once and twice
(exact; singular where s = 0, the sleeve at the rod's pin). The distance
``|a–b|`` (the passive cylinder's length) is ``√(s² + e²)``; name it with
:meth:`~assur.Mechanism.distance`.

Reactions: the sleeve (at ``b``) takes from the rod a force ``N·n̂`` normal to the
rod and a moment ``M_p``; about ``b`` the sleeve gives ``M_p = −M_sleeve(b)``, about
``a`` the rod gives ``N = (M_rod(a) − M_p)/s``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..kernel.emit import (DEAD_POINT_TOL, FAIL_COINCIDENT, FAIL_DEAD_POINT, FAIL_TOO_CLOSE,
                           d, dd, fail, length_ref, pt)
from .base import Failure, Field, Group, Ref, fmt, register

__all__ = ["SleeveDyad"]


@register
@dataclass(frozen=True)
class SleeveDyad(Group):
    """RPR dyad: rod pinned at ``a`` through a sleeve pivoted at ``b`` (see module).
    ``links = (rod, sleeve)``; the sleeve turns with the rod.

    Examples
    --------
    A slotted lever (кулиса): the crank pin A (radius 0.12 m) drives the rod 2
    through the sleeve 3 pivoted at B, 0.16 m from the crank's pivot:

    >>> import numpy as np
    >>> from assur import Mechanism
    >>> m = (Mechanism("slotted lever", coordinates=("j1",))
    ...      .frame("A0", 0.0, 0.0).frame("B", 0.16, 0.0)
    ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
    ...      .rpr_dyad("II", a="A", b="B", out="E", length=0.55, links=("2", "3")))
    >>> r = m.solve([0.0, np.pi / 2])                     # j1 [rad]
    >>> [round(float(v), 4) for v in r.phi("2", degrees=True)]  # rod angle [°]
    [0.0, -36.8699]
    >>> [round(float(v), 4) for v in r.y("E")]            # the rod's end E, y [m]
    [0.0, -0.21]
    """

    a: str = ""
    b: str = ""
    out: str = ""
    length: Ref = 0.0
    offset: Ref = 0.0
    branch: int = 1
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "rpr_dyad"
    kind: ClassVar[str] = "RPR dyad"
    kind_ru: ClassVar[str] = "диада ВПВ (кулиса)"
    link_roles: ClassVar = ("rod", "sleeve")
    fields: ClassVar = (
        Field("a", "point", doc="the rod's pin A (known)"),
        Field("b", "point", doc="the sleeve's pivot B (known)"),
        Field("out", "point", doc="the point of the rod it adds"),
        Field("length", "value", "length", "positive", doc="|A–out| along the rod [m]"),
        Field("offset", "value", "length", default=0.0,
              doc="signed distance of B from the rod's line [m]"),
        Field("branch", "branch", doc="+1: the sleeve ahead of A along the rod"),
    )

    def inputs(self):
        """Names of the points this group needs solved first: ``(a, b)``.

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55)
        >>> g.inputs()           # the rod's pin, the sleeve's pivot
        ('A', 'B')
        """
        return (self.a, self.b)

    def outputs(self):
        """Names of the points this group adds: ``(out,)``, a point of the rod.

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55)
        >>> g.outputs()
        ('E',)
        """
        return (self.out,)

    def refs(self):
        """Length references of the group by role: ``length``, ``offset`` [m].

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> SleeveDyad("II", a="A", b="B", out="E", length="L2").refs()
        {'length': 'L2', 'offset': 0.0}
        """
        return {"length": self.length, "offset": self.offset}

    def validate(self, coordinates):
        """A message if ``length`` or ``offset`` names a generalized coordinate (the
        group has no input), else the base checks (branch ±1).

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> print(SleeveDyad("II", a="A", b="B", out="E", length=0.55).validate(("j1",)))
        None
        >>> print(SleeveDyad("II", a="A", b="B", out="E", length="j1").validate(("j1",)))
        length must be a number or a parameter, not the coordinate 'j1'
        """
        for role, ref in self.refs().items():
            if isinstance(ref, str) and ref in coordinates:
                return f"{role} must be a number or a parameter, not the coordinate {ref!r}"
        return super().validate(coordinates)

    def topology(self, t):
        """Create the rod (a–out, owner of ``out``) and the sleeve (at b), which turns
        with the rod, in the topology builder ``t``.

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("slotted lever", ("j1",))
        >>> SleeveDyad("II", a="A", b="B", out="E", length=0.55, links=("2", "3")).topology(t)
        ('2', '3')
        >>> t.bodies["2"], t.bodies["3"], t.turns, t.owner("E")
        (['A', 'E'], ['B'], {'3': '2'}, '2')
        """
        rod, sleeve = t.link_names(self, 2)
        t.new(self, rod, (self.a, self.out))
        t.new(self, sleeve, (self.b,))
        t.own(self.out, rod)
        t.turns_with(sleeve, rod)
        return (rod, sleeve)

    def evaluate(self, pts, val):
        """Add ``out`` to ``pts`` by the formulas of the module docstring (plain numpy,
        any dtype).

        Examples
        --------
        The rod from A through B (``|A–B|`` = 0.2 m, direction (0.8, −0.6)), E at 0.55 m:

        >>> from assur.groups import SleeveDyad
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55)
        >>> pts = {"A": (0.0, 0.12), "B": (0.16, 0.0)}          # [m]
        >>> g.evaluate(pts, float)
        >>> [round(float(v), 4) for v in pts["E"]]              # E [m]
        [0.44, -0.21]
        """
        ax, ay = pts[self.a]
        bx, by = pts[self.b]
        e, ell = val(self.offset), val(self.length)
        wx, wy = bx - ax, by - ay
        D = wx * wx + wy * wy
        s = self.branch * np.sqrt(D - e * e)
        ux = (s * wx + e * wy) / D
        uy = (s * wy - e * wx) / D
        pts[self.out] = (ax + ell * ux, ay + ell * uy)

    def compile(self, c):
        """The program row ``(out, a, b, length, offset row, branch)``.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> from assur.groups import SleeveDyad
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55)
        >>> c = CompileContext(("j1",), ())
        >>> c.slot("A"), c.slot("B")
        (0, 1)
        >>> c.resolve(g.compile(c))   # length, offset: the literal rows 0 and 1
        (2, 0, 1, 0, 1, 1)
        >>> c.literals                # the numbers: row of each [m]
        {0.55: 0, 0.0: 1}
        """
        return (c.slot(self.out), c.slot(self.a), c.slot(self.b), c.lref(self.length),
                c.pref(self.offset), self.branch)

    @classmethod
    def emit(cls, E, i, row):
        """Emit the kernel code of group ``i`` with program ``row`` (see :meth:`compile`).

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> from assur.kernel.emit import Emitter
        >>> E = Emitter(1, order=1)
        >>> SleeveDyad.emit(E, 1, (2, 0, 1, 0, 1, 1))
        >>> print("\\n".join(line.strip() for line in E.lines[:2]))  # length, offset
        t1l = params[0, d]
        t1e = params[1, d]
        >>> print(next(line.strip() for line in E.lines if line.strip().startswith("x2 =")))
        x2 = x0 + t1l * t1ux
        """
        o, A, B, lref, pe, sig = row
        K = E.K
        ax, ay = pt(A)
        bx, by = pt(B)
        x, y = pt(o)
        ell, dell = length_ref(lref, K)
        t = f"t{i}"
        E(f"{t}l = {ell}")
        E(f"{t}e = params[{pe}, d]")
        E(f"{t}wx = {bx} - {ax}")
        E(f"{t}wy = {by} - {ay}")
        E(f"{t}D = {t}wx * {t}wx + {t}wy * {t}wy")
        fail(E, i, FAIL_COINCIDENT, f"{t}D == 0.0")
        E(f"{t}s2 = {t}D - {t}e * {t}e")
        fail(E, i, FAIL_TOO_CLOSE, f"{t}s2 < 0.0")
        E(f"{t}s = ({sig}.0) * math.sqrt({t}s2) if {t}s2 > 0.0 else 0.0")
        fail(E, i, FAIL_DEAD_POINT, f"abs({t}s) <= {DEAD_POINT_TOL!r} * math.sqrt({t}D)")
        E(f"{t}iD = 1.0 / {t}D if {t}D > 0.0 else 0.0")
        E(f"{t}is = 1.0 / {t}s if {t}s != 0.0 else 0.0")
        # u·D = s·w − e·R90(w), R90(w) = (−wy, wx)
        E(f"{t}ux = ({t}s * {t}wx + {t}e * {t}wy) * {t}iD")
        E(f"{t}uy = ({t}s * {t}wy - {t}e * {t}wx) * {t}iD")
        E(f"{x} = {ax} + {t}l * {t}ux")
        E(f"{y} = {ay} + {t}l * {t}uy")
        for a in range(K):
            E(f"{t}wx_{a} = {d(bx, a)} - {d(ax, a)}")
            E(f"{t}wy_{a} = {d(by, a)} - {d(ay, a)}")
            E(f"{t}D_{a} = 2.0 * ({t}wx * {t}wx_{a} + {t}wy * {t}wy_{a})")
            E(f"{t}s_{a} = 0.5 * {t}D_{a} * {t}is")
            E(f"{t}ux_{a} = ({t}s_{a} * {t}wx + {t}s * {t}wx_{a} + {t}e * {t}wy_{a}"
              f" - {t}ux * {t}D_{a}) * {t}iD")
            E(f"{t}uy_{a} = ({t}s_{a} * {t}wy + {t}s * {t}wy_{a} - {t}e * {t}wx_{a}"
              f" - {t}uy * {t}D_{a}) * {t}iD")
            for c, pc in (("x", ax), ("y", ay)):
                E(f"{d(c + str(o), a)} = {d(pc, a)} + {t}l * {t}u{c}_{a}"
                  + (f" + {dell[a]} * {t}u{c}" if dell[a] != "0.0" else ""))
        for a, b in E.pairs:
            E(f"{t}wxab = {dd(bx, a, b)} - {dd(ax, a, b)}")
            E(f"{t}wyab = {dd(by, a, b)} - {dd(ay, a, b)}")
            E(f"{t}Dab = 2.0 * ({t}wx_{a} * {t}wx_{b} + {t}wy_{a} * {t}wy_{b}"
              f" + {t}wx * {t}wxab + {t}wy * {t}wyab)")
            E(f"{t}sab = (0.5 * {t}Dab - {t}s_{a} * {t}s_{b}) * {t}is")
            for c, w_, sgn, wo in (("x", "wx", "+", "wy"), ("y", "wy", "-", "wx")):
                E(f"{t}u{c}ab = ({t}sab * {t}{w_} + {t}s_{a} * {t}{w_}_{b} + {t}s_{b} * "
                  f"{t}{w_}_{a} + {t}s * {t}{w_}ab {sgn} {t}e * {t}{wo}ab"
                  f" - {t}u{c}_{a} * {t}D_{b} - {t}u{c}_{b} * {t}D_{a} - {t}u{c} * {t}Dab)"
                  f" * {t}iD")
            for c, pc in (("x", ax), ("y", ay)):
                extra = ""
                if dell[a] != "0.0":
                    extra += f" + {dell[a]} * {t}u{c}_{b}"
                if dell[b] != "0.0":
                    extra += f" + {dell[b]} * {t}u{c}_{a}"
                E(f"{dd(c + str(o), a, b)} = {dd(pc, a, b)} + {t}l * {t}u{c}ab{extra}")

    def failure(self, code, pts, v, nm):
        """Amount and message of failure ``code``: the offset exceeds ``|a–b|`` (amount
        [m]), or a dead point (the sleeve at the rod's pin).

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> from assur.kernel.emit import FAIL_TOO_CLOSE
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55, offset="e")
        >>> pts = {"A": (0.0, 0.12), "B": (0.16, 0.0)}          # [m]
        >>> f = g.failure(FAIL_TOO_CLOSE, pts, lambda ref: {"e": 0.25}.get(ref, ref), str)
        >>> round(f.amount, 6)   # [m]
        0.05
        >>> print(f.text)  # doctest: +NORMALIZE_WHITESPACE
        the distance |A–B| = 0.2 m is less than the sleeve's offset |e| = 0.25 m by 50 mm:
        the rod cannot reach the sleeve
        """
        (ax, ay), (bx, by) = pts[self.a], pts[self.b]
        L = math.hypot(bx - ax, by - ay)
        e = v(self.offset)
        if code == FAIL_TOO_CLOSE:
            amt = abs(e) - L
            return Failure(amt, f"the distance |{self.a}–{self.b}| = {L:.6g} m is less than the "
                                f"sleeve's offset |{nm(self.offset)}| = {fmt(abs(e))} m by "
                                f"{amt * 1e3:.3g} mm: the rod cannot reach the sleeve")
        if code == FAIL_DEAD_POINT:
            s = math.sqrt(max(L * L - e * e, 0.0))
            return Failure(s, f"dead point: the sleeve is at the rod's pin (slide {s:.3g} m), "
                              f"the analogs are singular")
        return super().failure(code, pts, v, nm)

    def closure(self, P, val):
        """Largest violation of ``|out − a| = length`` and of b at the offset from the
        rod's line [m].

        Examples
        --------
        >>> from assur.groups import SleeveDyad
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55)
        >>> pts = {"A": (0.0, 0.12), "B": (0.16, 0.0), "E": (0.44, -0.21)}  # [m]
        >>> round(float(g.closure(pts.get, float)), 9)       # [m]
        0.0
        >>> g = SleeveDyad("II", a="A", b="B", out="E", length=0.55, offset="e")
        >>> round(float(g.closure(pts.get, lambda ref: {"e": 0.01}.get(ref, ref))), 4)  # [m]
        0.01
        """
        ax, ay = P(self.a)
        bx, by = P(self.b)
        ox, oy = P(self.out)
        ell = val(self.length)
        res = np.abs(np.hypot(ox - ax, oy - ay) - ell)
        # B at the offset e from the rod's line: (B − A) × û = −e  (û × R90û = 1)
        cr = ((bx - ax) * (oy - ay) - (by - ay) * (ox - ax)) / ell
        return np.maximum(res, np.abs(cr + val(self.offset)))

    def reactions(self, r):
        """Joint reactions of the rod and the sleeve: the sleeve's force ``N·n̂`` normal
        to the rod and its moment, the pins at a and b.

        Examples
        --------
        The slotted lever at j1 = 90° (rod along (0.8, −0.6), the sleeve 0.2 m from
        A) with 100 N down at E: the sleeve takes 44 N·m / 0.2 m = 220 N:

        >>> import numpy as np
        >>> from assur.core.statics import ReactionContext
        >>> from assur import Mechanism
        >>> m = (Mechanism("slotted lever", coordinates=("j1",))
        ...      .frame("A0", 0.0, 0.0).frame("B", 0.16, 0.0)
        ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
        ...      .rpr_dyad("II", a="A", b="B", out="E", length=0.55, links=("2", "3")))
        >>> r = ReactionContext(m.solve([np.pi / 2]), set())   # j1 [rad]
        >>> r.links = m.topology.group_links["II"]
        >>> r.apply("2", "E", 0.0, -100.0)                     # [N]
        >>> m.group("II").reactions(r)
        >>> [round(float(f[0, 0]), 3) for f in r.joints[("0", "3")][1:3]]  # frame on 3 [N]
        [132.0, 176.0]
        >>> [round(float(f[0, 0]), 3) for f in r.joints[("1", "2")][1:3]]  # crank on 2 [N]
        [-132.0, -76.0]
        """
        rod, sleeve = r.links
        A, B, O = self.a, self.b, self.out
        bA, bB = r.owner(A), r.owner(B)
        ax, ay = r.point(A)
        bx, by = r.point(B)
        ox, oy = r.point(O)
        ell = r.value(self.length)
        ux, uy = (ox - ax) / ell, (oy - ay) / ell
        nx, ny = -uy, ux
        s = (bx - ax) * ux + (by - ay) * uy
        frx, fry, mra = r.about(rod, ax, ay)
        fsx, fsy, msb = r.about(sleeve, bx, by)
        mp = -msb
        N = (mra - mp) / s
        r.record(rod, sleeve, B, N * nx, N * ny, mp)
        rax, ray = -frx + N * nx, -fry + N * ny
        rbx, rby = -fsx - N * nx, -fsy - N * ny
        r.record(bA, rod, A, rax, ray)
        r.record(bB, sleeve, B, rbx, rby)
        r.apply(bA, A, -rax, -ray)
        r.apply(bB, B, -rbx, -rby)
