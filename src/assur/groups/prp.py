"""PRP dyad: two sliders joined by a pin, each sliding on a line (a cross-slide,
the Scotch yoke's yoke on a moving guide).

The joint ``out`` = C is the intersection of line *a* (through the known point
``a``, direction ``direction_a`` [rad] from +x, or turned from P → Q when
``line_link_a = (P, Q)``) and line *b* (likewise). With unit directions û_a, û_b the
closure equations are ``(C − P_i) × û_i = 0``; differentiated once and twice they
give the 2×2 system with rows ``(u_iy, −u_ix)``, determinant ``û_a × û_b`` (zero
when the lines are parallel: the group cannot assemble).

Reactions: slider a (link ``links[0]``) and slider b (``links[1]``, owner of C) are
joined at C; each guide acts on its slider with a force ``N_i·n̂_i`` normal to its
line and a moment. ``N_a n̂_a + N_b n̂_b = −(F_a + F_b)``; moments about C give the
guides' moments.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..kernel.emit import FAIL_PARALLEL, d, dd, emit_unit, emit_zero_jets, fail, pt
from .base import Failure, Field, Group, Ref, register
from .rigid import unit_eval
from .rrp import line_direction

__all__ = ["DoubleSliderDyad"]

#: |û_a × û_b| (sine of the angle between the lines) below which they count as parallel
PARALLEL_TOL = 1e-7


@register
@dataclass(frozen=True)
class DoubleSliderDyad(Group):
    """PRP dyad: C on line a and line b (see module). ``links = (slider a, slider b)``;
    each slider turns with its guide.

    Examples
    --------
    A wedge: the input slider P travels ``s`` along x and carries the vertical line
    a; line b is fixed at 45° through B0 = (0, 0.1) m, so C = (s, 0.1 + s):

    >>> import math
    >>> from assur import Mechanism
    >>> m = (Mechanism("wedge", coordinates=("s",))
    ...      .frame("C0", 0.0, 0.0).frame("B0", 0.0, 0.1)
    ...      .slider_input("slider 1", origin="C0", out="P", s="s", links=("1",))
    ...      .prp_dyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
    ...                direction_b=math.pi / 4, links=("2", "3")))
    >>> r = m.solve([0.1, 0.2])                          # s [m]
    >>> [round(float(v), 4) for v in r.y("C")]           # [m]
    [0.2, 0.3]
    >>> [round(float(v), 4) for v in r.dy("C")]          # ∂y_C/∂s [m/m]
    [1.0, 1.0]
    """

    a: str = ""
    b: str = ""
    out: str = ""
    direction_a: Ref = 0.0
    direction_b: Ref = 0.0
    line_link_a: tuple[str, str] | None = None
    line_link_b: tuple[str, str] | None = None
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "prp_dyad"
    kind: ClassVar[str] = "PRP dyad"
    kind_ru: ClassVar[str] = "диада ПВП"
    link_roles: ClassVar = ("slider a", "slider b")
    fields: ClassVar = (
        Field("a", "point", doc="a point of line a (known)"),
        Field("b", "point", doc="a point of line b (known)"),
        Field("out", "point", doc="the pin C it adds"),
        Field("direction_a", "value", "angle", default=0.0,
              doc="of line a from +x, or from line_link_a [°]"),
        Field("direction_b", "value", "angle", default=0.0,
              doc="of line b from +x, or from line_link_b [°]"),
        Field("line_link_a", "line", default=None, doc="[P, Q]: line a turns with P→Q"),
        Field("line_link_b", "line", default=None, doc="[P, Q]: line b turns with P→Q"),
    )

    def inputs(self):
        """Names of the points this group needs solved first: ``a``, ``b`` and the
        points of ``line_link_a``, ``line_link_b`` if given.

        Examples
        --------
        >>> from assur.groups import DoubleSliderDyad
        >>> DoubleSliderDyad("II", a="P", b="B0", out="C").inputs()
        ('P', 'B0')
        >>> DoubleSliderDyad("II", a="P", b="B0", out="C", line_link_a=("A0", "A")).inputs()
        ('P', 'B0', 'A0', 'A')
        """
        extra = tuple(self.line_link_a or ()) + tuple(self.line_link_b or ())
        return (self.a, self.b) + extra

    def outputs(self):
        """Names of the points this group adds: ``(out,)``, the pin C.

        Examples
        --------
        >>> from assur.groups import DoubleSliderDyad
        >>> DoubleSliderDyad("II", a="P", b="B0", out="C").outputs()
        ('C',)
        """
        return (self.out,)

    def refs(self):
        """Angle references of the group by role: ``direction_a``, ``direction_b`` [rad].

        Examples
        --------
        >>> from assur.groups import DoubleSliderDyad
        >>> DoubleSliderDyad("II", a="P", b="B0", out="C", direction_b="beta").refs()
        {'direction_a': 0.0, 'direction_b': 'beta'}
        """
        return {"direction_a": self.direction_a, "direction_b": self.direction_b}

    def _guide(self, t, point, line_link):
        return (t.carrier(self, line_link[0], line_link[1], ()) if line_link
                else t.owner(point))

    def topology(self, t):
        """Create the two slider blocks at C (C belongs to slider b), each turning with
        its guide (the owner of ``a``/``b`` or the link carrying the line); returns
        ``(slider a, slider b, guide a, guide b)``.

        Examples
        --------
        >>> from assur.core.topology import TopologyBuilder
        >>> import math
        >>> from assur import Mechanism
        >>> m = (Mechanism("wedge", coordinates=("s",))
        ...      .frame("C0", 0.0, 0.0).frame("B0", 0.0, 0.1)
        ...      .slider_input("slider 1", origin="C0", out="P", s="s", links=("1",))
        ...      .prp_dyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
        ...                direction_b=math.pi / 4, links=("2", "3")))
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:-1]:                  # frame points and input slider first
        ...     _ = g.topology(t)
        >>> m.group("II").topology(t)                # guides: input slider 1, frame 0
        ('2', '3', '1', '0')
        >>> t.turns["2"], t.turns["3"], t.owner("C")
        ('1', '0', '3')
        """
        la, lb = t.link_names(self, 2)
        ga = self._guide(t, self.a, self.line_link_a)
        gb = self._guide(t, self.b, self.line_link_b)
        t.new(self, la, (self.out,))
        t.new(self, lb, (self.out,))
        t.own(self.out, lb)
        t.turns_with(la, ga)
        t.turns_with(lb, gb)
        return (la, lb, ga, gb)

    def _units(self, pts, val, ref):
        """Unit directions of both lines (plain numpy)."""
        out = []
        for p, beta, ll in ((self.a, self.direction_a, self.line_link_a),
                            (self.b, self.direction_b, self.line_link_b)):
            be = val(beta)
            if ll:
                out.append(unit_eval(pts, ll[0], ll[1], be))
            else:
                out.append((np.cos(be) + 0 * ref, np.sin(be) + 0 * ref))
        return out

    def evaluate(self, pts, val):
        """Add ``out`` to ``pts``: the intersection of the two lines (plain numpy, any
        dtype).

        Examples
        --------
        >>> import math
        >>> from assur.groups import DoubleSliderDyad
        >>> g = DoubleSliderDyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
        ...                      direction_b=math.pi / 4)
        >>> pts = {"P": (0.2, 0.0), "B0": (0.0, 0.1)}             # [m]
        >>> g.evaluate(pts, float)
        >>> [round(float(v), 4) for v in pts["C"]]                # C [m]
        [0.2, 0.3]
        """
        (pax, pay), (pbx, pby) = pts[self.a], pts[self.b]
        (uax, uay), (ubx, uby) = self._units(pts, val, pax)
        cr = uax * uby - uay * ubx
        t = ((pbx - pax) * uby - (pby - pay) * ubx) / cr
        pts[self.out] = (pax + t * uax, pay + t * uay)

    def compile(self, c):
        """The program row ``(out, a, P_a, Q_a, trig row a, b, P_b, Q_b, trig row b)``;
        ``P = Q = −1`` for a fixed direction.

        Examples
        --------
        >>> from assur.core.program import CompileContext
        >>> import math
        >>> from assur.groups import DoubleSliderDyad
        >>> g = DoubleSliderDyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
        ...                      direction_b=math.pi / 4)
        >>> c = CompileContext(("s",), ())
        >>> c.slot("P"), c.slot("B0")
        (0, 1)
        >>> c.resolve(g.compile(c))   # trig rows 0 (90°) and 2 (45°)
        (2, 0, -1, -1, 0, 1, -1, -1, 2)
        """
        row = [c.slot(self.out)]
        for p, beta, ll in ((self.a, self.direction_a, self.line_link_a),
                            (self.b, self.direction_b, self.line_link_b)):
            dp, dq = (c.slot(ll[0]), c.slot(ll[1])) if ll else (-1, -1)
            row += [c.slot(p), dp, dq, c.trig_angle(c.pref(beta))]
        return tuple(row)

    @classmethod
    def emit(cls, E, i, row):
        """Emit the kernel code of group ``i`` with program ``row`` (see :meth:`compile`).

        Examples
        --------
        >>> from assur.groups import DoubleSliderDyad
        >>> from assur.kernel.emit import Emitter
        >>> E = Emitter(1, order=1)
        >>> DoubleSliderDyad.emit(E, 1, (2, 0, -1, -1, 0, 1, -1, -1, 2))
        >>> print(next(line.strip() for line in E.lines if "t1cr =" in line))  # û_a × û_b
        t1cr = u1px * u1qy - u1py * u1qx
        """
        o = row[0]
        K = E.K
        x, y = pt(o)
        t = f"t{i}"
        lines = []
        for tag, (P, dP_, dQ_, trow) in ((f"{i}p", row[1:5]), (f"{i}q", row[5:9])):
            if dP_ >= 0:
                emit_unit(E, i, dP_, dQ_, f"trig[{trow}, d]", f"trig[{trow + 1}, d]", tag=tag)
            else:
                E(f"u{tag}x = trig[{trow}, d]")
                E(f"u{tag}y = trig[{trow + 1}, d]")
                emit_zero_jets(E, f"u{tag}x")
                emit_zero_jets(E, f"u{tag}y")
            lines.append((f"u{tag}", pt(P)))
        (ua, (pax, pay)), (ub, (pbx, pby)) = lines
        E(f"{t}cr = {ua}x * {ub}y - {ua}y * {ub}x")
        fail(E, i, FAIL_PARALLEL, f"abs({t}cr) <= {PARALLEL_TOL!r}")
        E(f"{t}icr = 1.0 / {t}cr if {t}cr != 0.0 else 0.0")

        def solve(r1, r2, ox, oy):
            # rows (u_y, −u_x): X = (ua_x r2 − ub_x r1)/cr, Y = (ua_y r2 − ub_y r1)/cr
            E(f"{t}r1 = {r1}")
            E(f"{t}r2 = {r2}")
            E(f"{ox} = ({ua}x * {t}r2 - {ub}x * {t}r1) * {t}icr")
            E(f"{oy} = ({ua}y * {t}r2 - {ub}y * {t}r1) * {t}icr")

        def cross(vx, vy, u):
            return f"(({vx}) * {u}y - ({vy}) * {u}x)"

        solve(cross(pax, pay, ua), cross(pbx, pby, ub), x, y)
        for a in range(K):
            rr = []
            for u, (px, py) in ((ua, (pax, pay)), (ub, (pbx, pby))):
                rr.append(f"{cross(d(px, a), d(py, a), u)} - ({x} - {px}) * {u}y_{a}"
                          f" + ({y} - {py}) * {u}x_{a}")
            solve(rr[0], rr[1], d(x, a), d(y, a))
        for a, b in E.pairs:
            rr = []
            for u, (px, py) in ((ua, (pax, pay)), (ub, (pbx, pby))):
                rr.append(
                    f"{cross(dd(px, a, b), dd(py, a, b), u)}"
                    f" - (({d(x, a)} - {d(px, a)}) * {u}y_{b}"
                    f" - ({d(y, a)} - {d(py, a)}) * {u}x_{b})"
                    f" - (({d(x, b)} - {d(px, b)}) * {u}y_{a} - ({d(y, b)} - {d(py, b)}) * {u}x_{a})"
                    f" - (({x} - {px}) * {dd(u + 'y', a, b)} - ({y} - {py}) * {dd(u + 'x', a, b)})")
            solve(rr[0], rr[1], dd(x, a, b), dd(y, a, b))

    def failure(self, code, pts, v, nm):
        """Amount (the sine of the angle between the lines) and message of failure
        ``code``; other codes as the base class.

        Examples
        --------
        >>> from assur.groups import DoubleSliderDyad
        >>> from assur.kernel.emit import FAIL_PARALLEL
        >>> g = DoubleSliderDyad("II", a="P", b="B0", out="C")   # both lines along +x
        >>> pts = {"P": (0.2, 0.0), "B0": (0.0, 0.1)}             # [m]
        >>> f = g.failure(FAIL_PARALLEL, pts, float, str)
        >>> f.amount   # sin of the angle between the lines
        0.0
        >>> print(f.text)  # doctest: +NORMALIZE_WHITESPACE
        its two slider lines (through 'P' and 'B0') are parallel (angle between them 0°):
        they do not intersect
        """
        if code != FAIL_PARALLEL:
            return super().failure(code, pts, v, nm)
        (uax, uay), (ubx, uby) = self._units(pts, lambda r: v(r), 0.0)
        cr = float(uax * uby - uay * ubx)
        ang = math.degrees(math.asin(max(-1.0, min(1.0, cr))))
        return Failure(cr, f"its two slider lines (through {self.a!r} and {self.b!r}) are "
                           f"parallel (angle between them {ang:.3g}°): they do not intersect")

    def closure(self, P, val):
        """Largest distance of C from either line [m].

        Examples
        --------
        >>> import math
        >>> from assur.groups import DoubleSliderDyad
        >>> g = DoubleSliderDyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
        ...                      direction_b=math.pi / 4)
        >>> pts = {"P": (0.2, 0.0), "B0": (0.0, 0.1), "C": (0.2, 0.3)}   # [m]
        >>> round(float(g.closure(pts.get, float)), 9)           # [m]
        0.0
        >>> pts["C"] = (0.21, 0.3)                               # 10 mm off line a
        >>> round(float(g.closure(pts.get, float)), 4)           # [m]
        0.01
        """
        cx, cy = P(self.out)
        res = 0.0
        for p, beta, ll in ((self.a, self.direction_a, self.line_link_a),
                            (self.b, self.direction_b, self.line_link_b)):
            px, py = P(p)
            th = val(beta)
            if ll:
                (p0x, p0y), (p1x, p1y) = P(ll[0]), P(ll[1])
                th = th + np.arctan2(p1y - p0y, p1x - p0x)
            res = np.maximum(res, np.abs(np.cos(th) * (cy - py) - np.sin(th) * (cx - px)))
        return res

    def reactions(self, r):
        """Joint reactions: each guide's normal force and moment on its slider, and the
        pin force of slider a on slider b at C.

        Examples
        --------
        The wedge at s = 0.2 m with 100 N down on slider b: the fixed 45° guide holds
        it with (−100, 100) N, slider a pushes it with 100 N along x:

        >>> import math
        >>> from assur import Mechanism
        >>> m = (Mechanism("wedge", coordinates=("s",))
        ...      .frame("C0", 0.0, 0.0).frame("B0", 0.0, 0.1)
        ...      .slider_input("slider 1", origin="C0", out="P", s="s", links=("1",))
        ...      .prp_dyad("II", a="P", b="B0", out="C", direction_a=math.pi / 2,
        ...                direction_b=math.pi / 4, links=("2", "3")))
        >>> from assur.core.statics import ReactionContext
        >>> r = ReactionContext(m.solve([0.2]), set())          # s [m]
        >>> r.links = m.topology.group_links["II"]
        >>> r.apply("3", "C", 0.0, -100.0)                      # [N]
        >>> m.group("II").reactions(r)
        >>> [round(float(f[0, 0]), 3) for f in r.joints[("0", "3")][1:3]]  # guide b on 3 [N]
        [-100.0, 100.0]
        >>> round(float(r.joints[("2", "3")][1][0, 0]), 3)     # slider a on b, x [N]
        100.0
        """
        la, lb, ga, gb = r.links
        C = self.out
        cx, cy = r.point(C)
        tha = line_direction(r, self.direction_a, self.line_link_a)
        thb = line_direction(r, self.direction_b, self.line_link_b)
        nax, nay = -np.sin(tha), np.cos(tha)
        nbx, nby = -np.sin(thb), np.cos(thb)
        fax, fay, mac = r.about(la, cx, cy)
        fbx, fby, mbc = r.about(lb, cx, cy)
        gx, gy = -(fax + fbx), -(fay + fby)
        den = nax * nby - nay * nbx
        Na = (gx * nby - gy * nbx) / den
        Nb = (nax * gy - nay * gx) / den
        ma, mb = -mac, -mbc
        rx, ry = fax + Na * nax, fay + Na * nay
        r.record(ga, la, C, Na * nax, Na * nay, ma)
        r.record(gb, lb, C, Nb * nbx, Nb * nby, mb)
        r.record(la, lb, C, rx, ry)
        r.apply(ga, C, -Na * nax, -Na * nay)
        r.apply_moment(ga, -ma)
        r.apply(gb, C, -Nb * nbx, -Nb * nby)
        r.apply_moment(gb, -mb)
