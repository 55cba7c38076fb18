"""RRP dyad: a link pinned at a known point, its other end sliding on a line.

The joint ``out`` is at distance ``radius`` from ``a`` and on the line through the
known point ``line_point`` with direction ``direction`` [rad] from +x, or — with
``line_link = (P, Q)`` — turned ``direction`` from the moving direction P → Q (a
slider on a link). ``branch = +1`` takes the intersection further along the line.

Position: ``C = L0 + t·u`` with ``t² + 2t·u·(L0−A) + |L0−A|² − r² = 0``; the analogs
differentiate that quadratic once and twice.

Reactions: the link a (A–C) and the slider block b (at C) under their loads; the
guide acts on the block with a force ``N·n`` normal to the line and a moment.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..kernel.emit import (DEAD_POINT_TOL, FAIL_DEAD_POINT, FAIL_LINE, d, dd, emit_unit,
                           emit_zero_jets, fail, length_ref, pt)
from .base import Failure, Field, Group, Ref, fmt, register
from .rigid import unit_eval

__all__ = ["SliderDyad", "line_direction"]


def line_direction(r, direction, line_link):
    """Direction angle [rad] of a slider line in a reaction context, shape (m, n).

    Examples
    --------
    A line turned 0 rad from the crank A0 → A, with the crank at 90°:

    >>> import numpy as np
    >>> from assur.groups.rrp import line_direction
    >>> from assur.core.statics import ReactionContext
    >>> from assur import Mechanism
    >>> m = (Mechanism("slider-crank", coordinates=("j1",))
    ...      .frame("A0", 0.0, 0.0).frame("L0", 0.0, -0.24)
    ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
    ...      .slider_dyad("II", a="A", out="C", radius=0.40, line_point="L0",
    ...                   links=("2", "3")))
    >>> r = ReactionContext(m.solve([np.pi / 2]), set())      # j1 [rad]
    >>> round(float(np.degrees(line_direction(r, 0.0, ("A0", "A"))[0, 0])), 3)  # [°]
    90.0
    >>> float(line_direction(r, 0.5, None))                    # a fixed line [rad]
    0.5
    """
    beta = r.value(direction)
    if line_link:
        (px, py), (qx, qy) = r.point(line_link[0]), r.point(line_link[1])
        return np.arctan2(qy - py, qx - px) + beta
    return beta


@register
@dataclass(frozen=True)
class SliderDyad(Group):
    """RRP dyad: ``out`` at ``radius`` [m] from ``a``, on a line (see module).
    ``links = (link at a, slider)``; the slider block turns with the guide.

    Examples
    --------
    A slider-crank: crank 0.12 m, connecting rod 0.40 m, the slider on the
    horizontal line y = −0.24 m:

    >>> import numpy as np
    >>> from assur import Mechanism
    >>> m = (Mechanism("slider-crank", coordinates=("j1",))
    ...      .frame("A0", 0.0, 0.0).frame("L0", 0.0, -0.24)
    ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
    ...      .slider_dyad("II", a="A", out="C", radius=0.40, line_point="L0",
    ...                   links=("2", "3")))
    >>> r = m.solve([0.0, np.pi / 2])                # j1 [rad]
    >>> [round(float(x), 4) for x in r.x("C")]       # slider position [m]
    [0.44, 0.1744]
    >>> [round(float(v), 4) for v in r.dx("C")]      # ∂x_C/∂j1 [m/rad]
    [-0.09, -0.12]
    """

    a: str = ""
    out: str = ""
    radius: Ref = 0.0
    line_point: str = ""
    direction: Ref = 0.0
    line_link: tuple[str, str] | None = None
    branch: int = 1
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "slider_dyad"
    kind: ClassVar[str] = "RRP dyad"
    kind_ru: ClassVar[str] = "диада ВВП"
    link_roles: ClassVar = ("link at a", "slider")
    fields: ClassVar = (
        Field("a", "point", doc="the pinned end A (known)"),
        Field("out", "point", doc="the slider joint C it adds"),
        Field("radius", "value", "length", "positive", True, doc="|A–C| [m] or a coordinate"),
        Field("line_point", "point", doc="a point of the line (known)"),
        Field("direction", "value", "angle", default=0.0,
              doc="of the line from +x, or from line_link [°]"),
        Field("line_link", "line", default=None, doc="[P, Q]: the line turns with P→Q"),
        Field("branch", "branch", doc="+1: the intersection further along the line"),
    )

    def inputs(self):
        """Names of the points this group needs solved first: ``a``, ``line_point``
        and the points of ``line_link``, if given.

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> SliderDyad("II", a="A", out="C", radius=0.4, line_point="L0").inputs()
        ('A', 'L0')
        >>> SliderDyad("II", a="A", out="C", radius=0.4, line_point="L0",
        ...            line_link=("B", "D")).inputs()   # a line on the link B–D
        ('A', 'L0', 'B', 'D')
        """
        extra = tuple(self.line_link) if self.line_link else ()
        return (self.a, self.line_point) + extra

    def outputs(self):
        """Names of the points this group adds: ``(out,)``, the slider joint.

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> SliderDyad("II", a="A", out="C", radius=0.4, line_point="L0").outputs()
        ('C',)
        """
        return (self.out,)

    def refs(self):
        """References of the group by role: ``radius`` [m], ``direction`` [rad].

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> SliderDyad("II", a="A", out="C", radius="L2", line_point="L0").refs()
        {'radius': 'L2', 'direction': 0.0}
        """
        return {"radius": self.radius, "direction": self.direction}

    def topology(self, t):
        """Create the link a (A–C, owner of C) and the slider block (at C) that turns
        with the guide — the owner of ``line_point``, or the link carrying
        ``line_link``; returns ``(link a, slider, guide)``.

        Examples
        --------
        >>> from assur.core.topology import TopologyBuilder
        >>> from assur import Mechanism
        >>> m = (Mechanism("slider-crank", coordinates=("j1",))
        ...      .frame("A0", 0.0, 0.0).frame("L0", 0.0, -0.24)
        ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
        ...      .slider_dyad("II", a="A", out="C", radius=0.40, line_point="L0",
        ...                   links=("2", "3")))
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:-1]:                    # frame points and crank first
        ...     _ = g.topology(t)
        >>> m.group("II").topology(t)                  # the guide is the frame "0"
        ('2', '3', '0')
        >>> t.turns, t.owner("C")
        ({'3': '0'}, '2')
        """
        la, lb = t.link_names(self, 2)
        guide = (t.carrier(self, self.line_link[0], self.line_link[1], ()) if self.line_link
                 else t.owner(self.line_point))
        t.new(self, la, (self.a, self.out), variable=t.is_coord(self.radius))
        t.new(self, lb, (self.out,))
        t.own(self.out, la)
        t.turns_with(lb, guide)
        return (la, lb, guide)

    def evaluate(self, pts, val):
        """Add ``out`` to ``pts``: the intersection of the circle about ``a`` with the
        line (plain numpy, any dtype).

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> g = SliderDyad("II", a="A", out="C", radius=0.40, line_point="L0")
        >>> pts = {"A": (0.12, 0.0), "L0": (0.0, -0.24)}        # [m]
        >>> g.evaluate(pts, float)
        >>> [round(float(v), 3) for v in pts["C"]]               # C [m]
        [0.44, -0.24]
        >>> SliderDyad("II", a="A", out="C", radius=0.40, line_point="L0",
        ...            branch=-1).evaluate(pts, float)
        >>> [round(float(v), 3) for v in pts["C"]]               # the other one [m]
        [-0.2, -0.24]
        """
        beta = val(self.direction)
        ax, ay = pts[self.a]
        lx, ly = pts[self.line_point]
        if self.line_link:
            ux, uy = unit_eval(pts, self.line_link[0], self.line_link[1], beta)
        else:
            ux, uy = np.cos(beta) + 0 * ax, np.sin(beta) + 0 * ax
        r = val(self.radius)
        wx, wy = lx - ax, ly - ay
        b = ux * wx + uy * wy
        c = wx * wx + wy * wy - r * r
        t = -b + self.branch * np.sqrt(b * b - c)
        pts[self.out] = (lx + t * ux, ly + t * uy)

    def compile(self, c):
        """The program row ``(out, a, radius, line_point, P, Q, trig row, branch)``;
        ``P = Q = −1`` for a fixed line.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> from assur.groups import SliderDyad
        >>> g = SliderDyad("II", a="A", out="C", radius=0.40, line_point="L0")
        >>> c = CompileContext(("j1",), ())
        >>> c.slot("A"), c.slot("L0")
        (0, 1)
        >>> row = g.compile(c)
        >>> c.resolve(row)      # radius: first literal row; direction: trig row 0
        (2, 0, 0, 1, -1, -1, 0, 1)
        >>> c.literals          # the numbers: row of each [m, rad]
        {0.4: 0, 0.0: 1}
        """
        dp, dq = ((c.slot(self.line_link[0]), c.slot(self.line_link[1])) if self.line_link
                  else (-1, -1))
        return (c.slot(self.out), c.slot(self.a), c.lref(self.radius), c.slot(self.line_point),
                dp, dq, c.trig_angle(c.pref(self.direction)), self.branch)

    @classmethod
    def emit(cls, E, i, row):
        """Emit the kernel code of group ``i`` with program ``row`` (see :meth:`compile`).

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> from assur.kernel.emit import Emitter
        >>> E = Emitter(1, order=1)
        >>> SliderDyad.emit(E, 1, (2, 0, 0, 1, -1, -1, 0, 1))
        >>> print(E.lines[0].strip())          # the fixed line's cos from the trig table
        u1x = trig[0, d]
        >>> print(next(line.strip() for line in E.lines if line.strip().startswith("x2 =")))
        x2 = x1 + t1t * u1x
        """
        o, A, refr, L0, dP_, dQ_, trow, sig = row
        K = E.K
        ax, ay = pt(A)
        lx, ly = pt(L0)
        x, y = pt(o)
        rr, dr = length_ref(refr, K)
        t = f"t{i}"
        if dP_ >= 0:
            emit_unit(E, i, dP_, dQ_, f"trig[{trow}, d]", f"trig[{trow + 1}, d]")
        else:
            E(f"u{i}x = trig[{trow}, d]")
            E(f"u{i}y = trig[{trow + 1}, d]")
            emit_zero_jets(E, f"u{i}x")
            emit_zero_jets(E, f"u{i}y")
        E(f"{t}r = {rr}")
        E(f"{t}wx = {lx} - {ax}")
        E(f"{t}wy = {ly} - {ay}")
        E(f"{t}b = u{i}x * {t}wx + u{i}y * {t}wy")
        E(f"{t}c = {t}wx * {t}wx + {t}wy * {t}wy - {t}r * {t}r")
        E(f"{t}disc = {t}b * {t}b - {t}c")
        fail(E, i, FAIL_LINE, f"{t}disc < 0.0")
        E(f"{t}sq = math.sqrt({t}disc) if {t}disc > 0.0 else 0.0")
        E(f"{t}t = -{t}b + ({sig}.0) * {t}sq")
        E(f"{t}den = 2.0 * ({t}t + {t}b)")
        fail(E, i, FAIL_DEAD_POINT, f"abs({t}den) <= {DEAD_POINT_TOL!r} * abs({t}r)")
        E(f"{t}iden = 1.0 / {t}den if {t}den != 0.0 else 0.0")
        E(f"{x} = {lx} + {t}t * u{i}x")
        E(f"{y} = {ly} + {t}t * u{i}y")
        for a in range(K):
            E(f"{t}wx_{a} = {d(lx, a)} - {d(ax, a)}")
            E(f"{t}wy_{a} = {d(ly, a)} - {d(ay, a)}")
            E(f"{t}b_{a} = u{i}x_{a} * {t}wx + u{i}y_{a} * {t}wy + u{i}x * {t}wx_{a}"
              f" + u{i}y * {t}wy_{a}")
            E(f"{t}c_{a} = 2.0 * ({t}wx * {t}wx_{a} + {t}wy * {t}wy_{a}) - 2.0 * {t}r * {dr[a]}")
            E(f"{t}t_{a} = -(2.0 * {t}t * {t}b_{a} + {t}c_{a}) * {t}iden")
            E(f"{d(x, a)} = {d(lx, a)} + {t}t_{a} * u{i}x + {t}t * u{i}x_{a}")
            E(f"{d(y, a)} = {d(ly, a)} + {t}t_{a} * u{i}y + {t}t * u{i}y_{a}")
        for a, b in E.pairs:
            E(f"{t}wxab = {dd(lx, a, b)} - {dd(ax, a, b)}")
            E(f"{t}wyab = {dd(ly, a, b)} - {dd(ay, a, b)}")
            E(f"{t}bab = ({dd(f'u{i}x', a, b)} * {t}wx + {dd(f'u{i}y', a, b)} * {t}wy"
              f" + u{i}x_{a} * {t}wx_{b} + u{i}y_{a} * {t}wy_{b}"
              f" + u{i}x_{b} * {t}wx_{a} + u{i}y_{b} * {t}wy_{a}"
              f" + u{i}x * {t}wxab + u{i}y * {t}wyab)")
            E(f"{t}cab = 2.0 * ({t}wx_{a} * {t}wx_{b} + {t}wy_{a} * {t}wy_{b} + {t}wx * {t}wxab"
              f" + {t}wy * {t}wyab) - 2.0 * {dr[a]} * {dr[b]}")
            E(f"{t}tab = -(2.0 * {t}t_{a} * {t}t_{b} + 2.0 * {t}t_{a} * {t}b_{b}"
              f" + 2.0 * {t}t_{b} * {t}b_{a} + 2.0 * {t}t * {t}bab + {t}cab) * {t}iden")
            for c, lc in (("x", lx), ("y", ly)):
                E(f"{dd(c + str(o), a, b)} = {dd(lc, a, b)} + {t}tab * u{i}{c}"
                  f" + {t}t_{a} * u{i}{c}_{b} + {t}t_{b} * u{i}{c}_{a} + {t}t * "
                  f"{dd(f'u{i}{c}', a, b)}")

    def failure(self, code, pts, v, nm):
        """Amount and message of failure ``code``: the circle misses the line (amount
        [m]) or a dead point (the link square to the line).

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> from assur.kernel.emit import FAIL_LINE
        >>> g = SliderDyad("II", a="A", out="C", radius="L2", line_point="L0")
        >>> pts = {"A": (0.12, 0.0), "L0": (0.0, -0.24)}        # [m]
        >>> f = g.failure(FAIL_LINE, pts, lambda ref: {"L2": 0.2}.get(ref, ref), str)
        >>> round(f.amount, 6)   # [m]
        0.04
        >>> print(f.text)  # doctest: +NORMALIZE_WHITESPACE
        the circle of radius L2 = 0.2 m about 'A' does not reach the slider line
        through 'L0': it falls short by 40 mm
        """
        if code not in (FAIL_LINE, FAIL_DEAD_POINT):
            return super().failure(code, pts, v, nm)
        ax, ay = pts[self.a]
        lx, ly = pts[self.line_point]
        beta = v(self.direction)
        if self.line_link:
            (px, py), (qx, qy) = pts[self.line_link[0]], pts[self.line_link[1]]
            beta += math.atan2(qy - py, qx - px)
        ux, uy = math.cos(beta), math.sin(beta)
        wx, wy = lx - ax, ly - ay
        r = v(self.radius)
        if code == FAIL_LINE:
            amt = abs(ux * wy - uy * wx) - r
            return Failure(amt, f"the circle of radius {nm(self.radius)} = {fmt(r)} m about "
                                f"{self.a!r} does not reach the slider line through "
                                f"{self.line_point!r}: it falls short by {amt * 1e3:.3g} mm")
        bb = ux * wx + uy * wy
        amt = 2.0 * math.sqrt(max(bb * bb - (wx * wx + wy * wy - r * r), 0.0))
        return Failure(amt, f"dead point: the link {self.a}–{self.out} is perpendicular to the "
                            f"slider line (the two intersections merge), the analogs are "
                            f"singular")

    def closure(self, P, val):
        """Largest violation of ``|C − A| = radius`` and of C on the line [m].

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> g = SliderDyad("II", a="A", out="C", radius=0.40, line_point="L0")
        >>> pts = {"A": (0.12, 0.0), "L0": (0.0, -0.24), "C": (0.44, -0.24)}  # [m]
        >>> round(float(g.closure(pts.get, float)), 9)       # [m]
        0.0
        >>> pts["C"] = (0.44, -0.23)                         # 10 mm off the line
        >>> round(float(g.closure(pts.get, float)), 4)       # [m]
        0.01
        """
        cx, cy = P(self.out)
        px, py = P(self.a)
        res = np.abs(np.hypot(cx - px, cy - py) - val(self.radius))
        # C on the line: its distance from the line through line_point
        lx, ly = P(self.line_point)
        beta = val(self.direction)
        if self.line_link:
            (p0x, p0y), (p1x, p1y) = P(self.line_link[0]), P(self.line_link[1])
            beta = beta + np.arctan2(p1y - p0y, p1x - p0x)
        return np.maximum(res, np.abs(np.cos(beta) * (cy - ly) - np.sin(beta) * (cx - lx)))

    def rod_ends(self, links, is_coord):
        """``((link a, out),)`` when ``radius`` is a coordinate (a cylinder), else ().

        Examples
        --------
        >>> from assur.groups import SliderDyad
        >>> g = SliderDyad("II", a="A", out="C", radius="S", line_point="L0")
        >>> g.rod_ends(("2", "3"), lambda ref: ref == "S")
        (('2', 'C'),)
        >>> g.rod_ends(("2", "3"), lambda ref: False)
        ()
        """
        return ((links[0], self.out),) if is_coord(self.radius) else ()

    def reactions(self, r):
        """Joint reactions of the link a and the slider block; the guide's normal
        force and moment on the block are recorded as the guide's reaction.

        Examples
        --------
        The slider-crank at j1 = 0 (rod A–C along (0.8, −0.6)) with 100 N against the
        slider: the rod carries 125 N, the guide holds the block with 75 N:

        >>> from assur.core.statics import ReactionContext
        >>> from assur import Mechanism
        >>> m = (Mechanism("slider-crank", coordinates=("j1",))
        ...      .frame("A0", 0.0, 0.0).frame("L0", 0.0, -0.24)
        ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
        ...      .slider_dyad("II", a="A", out="C", radius=0.40, line_point="L0",
        ...                   links=("2", "3")))
        >>> r = ReactionContext(m.solve([0.0]), set())
        >>> r.links = m.topology.group_links["II"]
        >>> r.apply("3", "C", -100.0, 0.0)                    # [N]
        >>> m.group("II").reactions(r)
        >>> [round(float(f[0, 0]), 3) for f in r.joints[("2", "3")][1:3]]  # rod on block [N]
        [100.0, -75.0]
        >>> round(float(r.joints[("0", "3")][2][0, 0]), 3)   # guide on block, y [N]
        75.0
        """
        la, lb, guide = r.links
        A, C = self.a, self.out
        bA = r.owner(A)
        ax, ay = r.point(A)
        cx, cy = r.point(C)
        th = line_direction(r, self.direction, self.line_link)
        nx, ny = -np.sin(th), np.cos(th)
        fax, fay, mac = r.about(la, cx, cy)
        fbx, fby, mbc = r.about(lb, cx, cy)
        ux, uy = ax - cx, ay - cy
        den = ux * ny - uy * nx
        N = (mac - (ux * (fay + fby) - uy * (fax + fbx))) / den
        rax = -fax - fbx - N * nx
        ray = -fay - fby - N * ny
        rcx, rcy = rax + fax, ray + fay
        mg = -mbc
        r.record(bA, la, A, rax, ray)
        r.record(la, lb, C, rcx, rcy)
        r.record(guide, lb, C, N * nx, N * ny, mg)
        r.apply(bA, A, -rax, -ray)
        r.apply(guide, C, -N * nx, -N * ny)
        r.apply_moment(guide, -mg)
        if r.is_coord(self.radius):
            L = np.hypot(cx - ax, cy - ay)
            r.actuator(self.radius, r.axial(la, C, rcx, rcy, (cx - ax) / L, (cy - ay) / L))
