"""RRR dyad: two links joined at ``out``, pinned at two known points (seed 003 §2).

Position (law of cosines, 003 eqs. φ3, φ41, φ51):

.. math::
    d = |B - A|,\\quad a = \\frac{r_a^2 - r_b^2 + d^2}{2d},\\quad
    h = \\sqrt{r_a^2 - a^2},\\quad
    C = A + a\\,\\hat u + \\sigma h\\,\\hat u_\\perp

Analogs: the closure equations ``|C−A|² = ra²``, ``|C−B|² = rb²`` differentiated
once and twice give a 2×2 linear system with rows ``(C−A)ᵀ, (C−B)ᵀ``; its
determinant is ``ra·rb·sin μ`` (μ the transmission angle), zero at a dead point.

Reactions (seed 003 §5.1–5.3): link a: ``R_A − R_C + F_a = 0``,
``(A−C)×R_A + M_a,C = 0``; link b: ``R_B + R_C + F_b = 0``, ``(B−C)×R_B + M_b,C = 0``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..kernel.emit import (DEAD_POINT_TOL, FAIL_COINCIDENT, FAIL_DEAD_POINT, FAIL_TOO_CLOSE,
                           FAIL_TOO_FAR, d, dd, fail, length_ref, pt)
from .base import Failure, Field, Group, Ref, fmt, register

__all__ = ["Dyad", "dyad_position", "dyad_emit", "dyad_failure", "dyad_reactions_block"]


def dyad_position(pts, a, b, ra, rb, branch):
    """C of an RRR dyad from A = pts[a], B = pts[b] (plain numpy, any dtype) [m].

    Examples
    --------
    A 3-4-5 triangle: ``|A–B|`` = 0.5 m, ra = 0.3 m, rb = 0.4 m; branch +1 puts C on
    the left of A → B (above the x axis), −1 on the right:

    >>> from assur.groups.rrr import dyad_position
    >>> pts = {"A": (0.0, 0.0), "B": (0.5, 0.0)}
    >>> [round(float(v), 3) for v in dyad_position(pts, "A", "B", 0.3, 0.4, 1)]  # [m]
    [0.18, 0.24]
    >>> [round(float(v), 3) for v in dyad_position(pts, "A", "B", 0.3, 0.4, -1)]  # [m]
    [0.18, -0.24]
    """
    ax, ay = pts[a]
    bx, by = pts[b]
    dx, dy = bx - ax, by - ay
    L = np.sqrt(dx * dx + dy * dy)
    aa = (ra * ra - rb * rb + L * L) / (2 * L)
    h = np.sqrt(ra * ra - aa * aa)
    ux, uy = dx / L, dy / L
    return ax + aa * ux - branch * h * uy, ay + aa * uy + branch * h * ux


def dyad_emit(E, i, row):
    """Kernel code of an RRR dyad; ``row = (out, A, B, ra_ref, rb_ref, branch)``.

    Examples
    --------
    Group 0 puts C in slot 2 from A (slot 0) and B (slot 1); ``ra`` is the
    coordinate 0 (ref −1, a cylinder), ``rb`` the parameter row 0; first order only:

    >>> from assur.kernel.emit import Emitter
    >>> from assur.groups.rrr import dyad_emit
    >>> E = Emitter(1, order=1)
    >>> dyad_emit(E, 0, (2, 0, 1, -1, 0, 1))
    >>> print("\\n".join(line.strip() for line in E.lines[:2]))
    t0ra = q[0, e]
    t0rb = params[0, d]
    >>> print(next(line.strip() for line in E.lines if line.strip().startswith("x2 =")))
    x2 = x0 + t0a * t0ux - (1.0) * t0h * t0uy
    """
    o, A, B, refa, refb, sig = row
    K = E.K
    ax, ay = pt(A)
    bx, by = pt(B)
    x, y = pt(o)
    ra, dra = length_ref(refa, K)
    rb, drb = length_ref(refb, K)
    t = f"t{i}"
    E(f"{t}ra = {ra}")
    E(f"{t}rb = {rb}")
    E(f"{t}dx = {bx} - {ax}")
    E(f"{t}dy = {by} - {ay}")
    E(f"{t}L = math.sqrt({t}dx * {t}dx + {t}dy * {t}dy)")
    fail(E, i, FAIL_COINCIDENT, f"{t}L == 0.0")
    fail(E, i, FAIL_TOO_FAR, f"{t}L > {t}ra + {t}rb")
    fail(E, i, FAIL_TOO_CLOSE, f"{t}L < abs({t}ra - {t}rb)")
    E(f"{t}iL = 1.0 / {t}L if {t}L > 0.0 else 0.0")
    E(f"{t}a = 0.5 * ({t}ra * {t}ra - {t}rb * {t}rb + {t}L * {t}L) * {t}iL")
    E(f"{t}h2 = {t}ra * {t}ra - {t}a * {t}a")
    E(f"{t}h = math.sqrt({t}h2) if {t}h2 > 0.0 else 0.0")
    E(f"{t}ux = {t}dx * {t}iL")
    E(f"{t}uy = {t}dy * {t}iL")
    E(f"{x} = {ax} + {t}a * {t}ux - ({sig}.0) * {t}h * {t}uy")
    E(f"{y} = {ay} + {t}a * {t}uy + ({sig}.0) * {t}h * {t}ux")
    E(f"{t}m11 = {x} - {ax}")
    E(f"{t}m12 = {y} - {ay}")
    E(f"{t}m21 = {x} - {bx}")
    E(f"{t}m22 = {y} - {by}")
    E(f"{t}det = {t}m11 * {t}m22 - {t}m12 * {t}m21")
    E(f"{t}rr = {t}ra * {t}rb")
    fail(E, i, FAIL_DEAD_POINT, f"abs({t}det) <= {DEAD_POINT_TOL!r} * abs({t}rr)")
    E(f"{t}idet = 1.0 / {t}det if {t}det != 0.0 else 0.0")
    for a in range(K):
        E(f"{t}r1 = {t}ra * {dra[a]} + {t}m11 * {d(ax, a)} + {t}m12 * {d(ay, a)}")
        E(f"{t}r2 = {t}rb * {drb[a]} + {t}m21 * {d(bx, a)} + {t}m22 * {d(by, a)}")
        E(f"{d(x, a)} = ({t}r1 * {t}m22 - {t}m12 * {t}r2) * {t}idet")
        E(f"{d(y, a)} = ({t}m11 * {t}r2 - {t}m21 * {t}r1) * {t}idet")
    if K == 1:
        # squared height g = cr²/L² with cr = (B−A) × (C−A), and its derivative, for
        # the continuity check between positions (assur.kernel.run.continuity)
        E(f"{t}cr = {t}dx * {t}m12 - {t}dy * {t}m11")
        E(f"{t}dcr = ({d(bx, 0)} - {d(ax, 0)}) * {t}m12 + {t}dx * ({d(y, 0)} - "
          f"{d(ay, 0)}) - ({d(by, 0)} - {d(ay, 0)}) * {t}m11 - {t}dy * ({d(x, 0)} - "
          f"{d(ax, 0)})")
        E(f"{t}dL2 = 2.0 * ({t}dx * ({d(bx, 0)} - {d(ax, 0)}) + {t}dy * ({d(by, 0)} - "
          f"{d(ay, 0)}))")
        E(f"g{i} = {t}cr * {t}cr * {t}iL * {t}iL")
        E(f"gd{i} = (2.0 * {t}cr * {t}dcr - {t}cr * {t}cr * {t}dL2 * {t}iL * {t}iL)"
          f" * {t}iL * {t}iL")
    for a, b in E.pairs:
        va = f"({d(x, a)} - {d(ax, a)})", f"({d(y, a)} - {d(ay, a)})"
        vb = f"({d(x, b)} - {d(ax, b)})", f"({d(y, b)} - {d(ay, b)})"
        wa = f"({d(x, a)} - {d(bx, a)})", f"({d(y, a)} - {d(by, a)})"
        wb = f"({d(x, b)} - {d(bx, b)})", f"({d(y, b)} - {d(by, b)})"
        E(f"{t}r1 = {dra[a]} * {dra[b]} - ({va[0]} * {vb[0]} + {va[1]} * {vb[1]})"
          f" + {t}m11 * {dd(ax, a, b)} + {t}m12 * {dd(ay, a, b)}")
        E(f"{t}r2 = {drb[a]} * {drb[b]} - ({wa[0]} * {wb[0]} + {wa[1]} * {wb[1]})"
          f" + {t}m21 * {dd(bx, a, b)} + {t}m22 * {dd(by, a, b)}")
        E(f"{dd(x, a, b)} = ({t}r1 * {t}m22 - {t}m12 * {t}r2) * {t}idet")
        E(f"{dd(y, a, b)} = ({t}m11 * {t}r2 - {t}m21 * {t}r1) * {t}idet")


def _sum(names, values, op):
    """'ra + rb = 0.6 + 0.6 = 1.2' with each part said once (numbers not repeated)."""
    sym = f" {op} ".join(names)
    num = f" {op} ".join(fmt(v) for v in values)
    total = values[0] + values[1] if op == "+" else values[0] - values[1]
    parts = [sym] if sym == num else [sym, num]
    return " = ".join(parts + [fmt(total)])


def dyad_failure(g, code, pts, v, nm, a, b, ra_ref, rb_ref):
    """Amount and message of an RRR-type failure (distances and dead points).

    Examples
    --------
    The outer joints 0.8 m apart, the links 0.3 + 0.4 m: too far by 0.1 m:

    >>> from assur.groups.rrr import Dyad, dyad_failure
    >>> from assur.kernel.emit import FAIL_TOO_FAR
    >>> g = Dyad("II", a="A", b="B", out="C", ra=0.3, rb=0.4)
    >>> pts = {"A": (0.0, 0.0), "B": (0.8, 0.0)}
    >>> f = dyad_failure(g, FAIL_TOO_FAR, pts, float, str, "A", "B", 0.3, 0.4)
    >>> round(f.amount, 6)  # [m]
    0.1
    >>> print(f.text)
    the distance |A–B| = 0.8 m exceeds 0.3 + 0.4 = 0.7 m by 100 mm
    """
    (ax, ay), (bx, by) = pts[a], pts[b]
    L = math.hypot(bx - ax, by - ay)
    ra, rb = v(ra_ref), v(rb_ref)
    if code == FAIL_TOO_FAR:
        amt = L - (ra + rb)
        return Failure(amt, f"the distance |{a}–{b}| = {L:.6g} m exceeds "
                            f"{_sum((nm(ra_ref), nm(rb_ref)), (ra, rb), '+')} m by "
                            f"{amt * 1e3:.3g} mm")
    if code == FAIL_TOO_CLOSE:
        amt = abs(ra - rb) - L
        sym = f"|{nm(ra_ref)} − {nm(rb_ref)}|"
        num = f"|{fmt(ra)} − {fmt(rb)}|"
        expr = " = ".join(([sym] if sym == num else [sym, num]) + [fmt(abs(ra - rb))])
        return Failure(amt, f"the distance |{a}–{b}| = {L:.6g} m is less than {expr} m by "
                            f"{amt * 1e3:.3g} mm")
    if code == FAIL_DEAD_POINT:
        aa = (ra * ra - rb * rb + L * L) / (2 * L)
        s = math.sqrt(max(ra * ra - aa * aa, 0.0)) * L / (ra * rb)
        return Failure(s, f"dead point: the links are collinear (sine of the transmission "
                          f"angle {s:.3g}), the analogs are singular")
    return Group.failure(g, code, pts, v, nm)


def dyad_reactions_block(r, a, b, c, la, lb, ra_ref, rb_ref):
    """Reverse-order step of an RRR-type group in the reaction context ``r``.

    Link a (A–C): ``R_A − R_C + F_a = 0``, ``(A−C)×R_A + M_a,C = 0``; link b (B–C):
    ``R_B + R_C + F_b = 0``, ``(B−C)×R_B + M_b,C = 0``; so
    ``[[−u_y, u_x], [−w_y, w_x]]·R_A = [r1, r2]`` with u = A−C, w = B−C (seed 003
    §5.1–5.3, group by group). R_C is the force of link a on link b [N]; all zero
    where the dyad is degenerate (a failed position: det = 0).

    Examples
    --------
    A two-bar truss: links 2 (A–C, 0.3 m) and 3 (B–C, 0.4 m) pinned to the frame at
    A and B 0.5 m apart, 100 N down at C. The bars carry 80 N and 60 N (3-4-5):

    >>> from assur import Mechanism
    >>> from assur.core.statics import ReactionContext
    >>> from assur.groups.rrr import dyad_reactions_block
    >>> m = (Mechanism("truss", coordinates=("S",))
    ...      .frame("A", 0.0, 0.0).frame("B", 0.5, 0.0)
    ...      .dyad("II", a="A", b="B", out="C", ra=0.3, rb=0.4, links=("2", "3")))
    >>> r = ReactionContext(m.solve([0.0]), set())
    >>> r.apply("3", "C", 0.0, -100.0)                   # [N]
    >>> dyad_reactions_block(r, "A", "B", "C", "2", "3", 0.3, 0.4)
    >>> [round(float(f[0, 0]), 3) for f in r.joints[("0", "2")][1:3]]  # frame on 2 at A [N]
    [48.0, 64.0]
    >>> [round(float(f[0, 0]), 3) for f in r.joints[("0", "3")][1:3]]  # frame on 3 at B [N]
    [-48.0, 36.0]
    """
    bA, bB = r.owner(a), r.owner(b)
    ax, ay = r.point(a)
    bx, by = r.point(b)
    cx, cy = r.point(c)
    fax, fay, mac = r.about(la, cx, cy)
    fbx, fby, mbc = r.about(lb, cx, cy)
    ux, uy = ax - cx, ay - cy
    wx, wy = bx - cx, by - cy
    idet = r.inv(ux * wy - uy * wx)
    r1 = -mac
    r2 = mbc - (wx * (fay + fby) - wy * (fax + fbx))
    rax = (r1 * wx - ux * r2) * idet
    ray = (wy * r1 - uy * r2) * idet
    rcx, rcy = rax + fax, ray + fay
    rbx, rby = -rcx - fbx, -rcy - fby
    r.record(bA, la, a, rax, ray)
    r.record(la, lb, c, rcx, rcy)
    r.record(bB, lb, b, rbx, rby)
    r.apply(bA, a, -rax, -ray)
    r.apply(bB, b, -rbx, -rby)
    for ref, (px, py), cyl, (fx, fy) in ((ra_ref, (ax, ay), la, (rcx, rcy)),
                                         (rb_ref, (bx, by), lb, (-rcx, -rcy))):
        if r.is_coord(ref):
            # the cylinder's rod end C pushes the other link with (fx, fy)
            L = np.hypot(cx - px, cy - py)
            r.actuator(ref, r.axial(cyl, c, fx, fy, (cx - px) / L, (cy - py) / L))


@register
@dataclass(frozen=True)
class Dyad(Group):
    """RRR dyad: joint ``out`` at distance ``ra`` from point ``a`` and ``rb`` from ``b``.

    Two links (``links = (link_a, link_b)``) joined at ``out``; the outer joints
    ``a`` and ``b`` are already known. A radius may be a generalized coordinate,
    which makes this the dyad with a cylinder of variable length (RPR written with
    the cylinder's pin-to-pin length). See the module docstring for the formulas.

    Examples
    --------
    >>> from assur import Mechanism
    >>> m = (Mechanism("four-bar", coordinates=("j1",))
    ...      .frame("A0", 0.0, 0.0).frame("B0", 0.4, 0.0)
    ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
    ...      .dyad("II", a="A", b="B0", out="C", ra=0.40, rb=0.30, branch=1,
    ...            links=("2", "3")))
    >>> m.points
    ('A0', 'B0', 'A', 'C')
    """

    a: str = ""
    b: str = ""
    out: str = ""
    ra: Ref = 0.0
    rb: Ref = 0.0
    branch: int = 1
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "dyad"
    kind: ClassVar[str] = "RRR dyad"
    kind_ru: ClassVar[str] = "диада ВВВ"
    link_roles: ClassVar = ("link at a", "link at b")
    continuity: ClassVar[bool] = True
    fields: ClassVar = (
        Field("a", "point", doc="first outer joint A (known)"),
        Field("b", "point", doc="second outer joint B (known)"),
        Field("out", "point", doc="the middle joint C it adds"),
        Field("ra", "value", "length", "positive", True, doc="|A–C| [m] or a coordinate"),
        Field("rb", "value", "length", "positive", True, doc="|B–C| [m] or a coordinate"),
        Field("branch", "branch", doc="+1: C left of A→B, −1: right"),
    )

    def inputs(self):
        """Names of the points this group needs solved first: ``(a, b)``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("III (6,7)").inputs()  # implement 6, top link 7
        ('56', '07')
        """
        return (self.a, self.b)

    def outputs(self):
        """Names of the points this group adds: ``(out,)``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("III (6,7)").outputs()  # implement 6, top link 7
        ('67',)
        """
        return (self.out,)

    def refs(self):
        """Length references of the group by role: ``ra``, ``rb``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> refs = m.group("III (6,7)").refs()
        >>> refs
        {'ra': 'L6', 'rb': 'L7'}
        >>> round(float(m.value_of(refs["ra"])), 3)  # L6, seed 003 §1.2 [m]
        0.515
        """
        return {"ra": self.ra, "rb": self.rb}

    def topology(self, t):
        """Create links a (A–C) and b (B–C) in the topology builder ``t``; C belongs to
        link b; a link whose radius is a generalized coordinate is variable.

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("truss", ("S",))
        >>> Dyad("II", a="A", b="B", out="C", ra="S", rb=0.4, links=("2", "3")).topology(t)
        ('2', '3')
        >>> t.bodies["2"], sorted(t.variable), t.owner("C")
        (['A', 'C'], ['2'], '3')
        """
        la, lb = t.link_names(self, 2)
        t.new(self, la, (self.a, self.out), variable=t.is_coord(self.ra))
        t.new(self, lb, (self.b, self.out), variable=t.is_coord(self.rb))
        t.own(self.out, lb)
        return (la, lb)

    def evaluate(self, pts, val):
        """Add ``out`` to ``pts`` by :func:`dyad_position` (plain numpy, any dtype).

        Examples
        --------
        A 3-4-5 triangle; a complex step of ``ra`` gives ∂C/∂ra exactly:

        >>> from assur.groups import Dyad
        >>> g = Dyad("II", a="A", b="B", out="C", ra="ra", rb="rb")
        >>> pts = {"A": (0.0, 0.0), "B": (0.5, 0.0)}
        >>> g.evaluate(pts, {"ra": 0.3, "rb": 0.4}.get)
        >>> [round(float(v), 3) for v in pts["C"]]                  # C [m]
        [0.18, 0.24]
        >>> g.evaluate(pts, {"ra": 0.3 + 1e-20j, "rb": 0.4}.get)
        >>> [round(float(v.imag / 1e-20), 3) for v in pts["C"]]   # ∂C/∂ra [m/m]
        [0.6, 0.8]
        """
        pts[self.out] = dyad_position(pts, self.a, self.b, val(self.ra), val(self.rb),
                                      self.branch)

    def compile(self, c):
        """The program row ``(out, a, b, ra, rb, branch)``: slots, length references
        (``−(j + 1)`` for coordinate j, else a parameter row) and the branch.

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.core.program import CompileContext
        >>> c = CompileContext(("S",), ("L7",))
        >>> c.slot("56"), c.slot("07")
        (0, 1)
        >>> Dyad("III", a="56", b="07", out="67", ra="S", rb="L7", branch=-1).compile(c)
        (2, 0, 1, -1, 0, -1)
        """
        return (c.slot(self.out), c.slot(self.a), c.slot(self.b), c.lref(self.ra),
                c.lref(self.rb), self.branch)

    @classmethod
    def emit(cls, E, i, row):
        """Emit the kernel code of group ``i`` with program ``row`` (:func:`dyad_emit`).

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.kernel.emit import Emitter
        >>> E = Emitter(1)                      # one coordinate, up to second order
        >>> Dyad.emit(E, 3, (2, 0, 1, -1, 0, 1))
        >>> print(next(line.strip() for line in E.lines if line.strip().startswith("y2 =")))
        y2 = y0 + t3a * t3uy + (1.0) * t3h * t3ux
        >>> sum(line.strip().startswith("x2_00 =") for line in E.lines)  # second analog
        1
        """
        dyad_emit(E, i, row)

    def failure(self, code, pts, v, nm):
        """Amount and message of failure ``code`` (:func:`dyad_failure`).

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.kernel.emit import FAIL_TOO_CLOSE
        >>> g = Dyad("III", a="A", b="B", out="C", ra="L6", rb="L7")
        >>> pts = {"A": (0.0, 0.0), "B": (0.2, 0.0)}
        >>> f = g.failure(FAIL_TOO_CLOSE, pts, {"L6": 0.5, "L7": 0.2}.get, str)
        >>> round(f.amount, 6)  # [m]
        0.1
        >>> print(f.text)
        the distance |A–B| = 0.2 m is less than |L6 − L7| = |0.5 − 0.2| = 0.3 m by 100 mm
        """
        return dyad_failure(self, code, pts, v, nm, self.a, self.b, self.ra, self.rb)

    def closure(self, P, val):
        """Largest violation of ``|C − A| = ra``, ``|C − B| = rb`` [m].

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> g = Dyad("II", a="A", b="B", out="C", ra=0.3, rb=0.4)
        >>> pts = {"A": (0.0, 0.0), "B": (0.5, 0.0), "C": (0.18, 0.24)}
        >>> round(float(g.closure(pts.get, float)), 9)   # [m]
        0.0
        >>> pts["C"] = (0.18, 0.25)                      # 10 mm off
        >>> round(float(g.closure(pts.get, float)), 4)   # |A–C| − ra [m]
        0.0081
        """
        cx, cy = P(self.out)
        res = 0.0
        for p, r in ((self.a, self.ra), (self.b, self.rb)):
            px, py = P(p)
            res = np.maximum(res, np.abs(np.hypot(cx - px, cy - py) - val(r)))
        return res

    def rod_ends(self, links, is_coord):
        """``(cylinder link, rod-end point)`` for each radius that is a coordinate.

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> g = Dyad("II", a="A", b="B", out="C", ra="S", rb=0.4)
        >>> g.rod_ends(("2", "3"), lambda ref: ref == "S")
        (('2', 'C'),)
        """
        return tuple((l, self.out) for ref, l in zip((self.ra, self.rb), links) if is_coord(ref))

    def reactions(self, r):
        """Joint reactions of the dyad (:func:`dyad_reactions_block`); a radius that is a
        coordinate adds the cylinder's axial force to ``r.act``.

        Examples
        --------
        A two-bar truss whose bar 2 (A–C) is a cylinder of length S = 0.3 m, bar 3
        (B–C) 0.4 m, A and B 0.5 m apart, 100 N down at C: the cylinder pushes 80 N:

        >>> from assur import Mechanism
        >>> from assur.core.statics import ReactionContext
        >>> m = (Mechanism("truss", coordinates=("S",))
        ...      .frame("A", 0.0, 0.0).frame("B", 0.5, 0.0)
        ...      .dyad("II", a="A", b="B", out="C", ra="S", rb=0.4, links=("2", "3")))
        >>> r = ReactionContext(m.solve([0.3]), set())
        >>> r.links = m.topology.group_links["II"]
        >>> r.apply("3", "C", 0.0, -100.0)                     # [N]
        >>> m.group("II").reactions(r)
        >>> round(float(r.act["S"][0, 0]), 3)                   # cylinder force [N]
        80.0
        >>> [round(float(f[0, 0]), 3) for f in r.joints[("0", "3")][1:3]]  # frame on 3 [N]
        [-48.0, 36.0]
        """
        la, lb = r.links
        dyad_reactions_block(r, self.a, self.b, self.out, la, lb, self.ra, self.rb)
