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
    """C of an RRR dyad from A = pts[a], B = pts[b] (plain numpy, any dtype) [m]."""
    ax, ay = pts[a]
    bx, by = pts[b]
    dx, dy = bx - ax, by - ay
    L = np.sqrt(dx * dx + dy * dy)
    aa = (ra * ra - rb * rb + L * L) / (2 * L)
    h = np.sqrt(ra * ra - aa * aa)
    ux, uy = dx / L, dy / L
    return ax + aa * ux - branch * h * uy, ay + aa * uy + branch * h * ux


def dyad_emit(E, i, row):
    """Kernel code of an RRR dyad; ``row = (out, A, B, ra_ref, rb_ref, branch)``."""
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
    """Amount and message of an RRR-type failure (distances and dead points)."""
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
        return (self.a, self.b)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"ra": self.ra, "rb": self.rb}

    def topology(self, t):
        la, lb = t.link_names(self, 2)
        t.new(self, la, (self.a, self.out), variable=t.is_coord(self.ra))
        t.new(self, lb, (self.b, self.out), variable=t.is_coord(self.rb))
        t.own(self.out, lb)
        return (la, lb)

    def evaluate(self, pts, val):
        pts[self.out] = dyad_position(pts, self.a, self.b, val(self.ra), val(self.rb),
                                      self.branch)

    def compile(self, c):
        return (c.slot(self.out), c.slot(self.a), c.slot(self.b), c.lref(self.ra),
                c.lref(self.rb), self.branch)

    emit = classmethod(lambda cls, E, i, row: dyad_emit(E, i, row))

    def failure(self, code, pts, v, nm):
        return dyad_failure(self, code, pts, v, nm, self.a, self.b, self.ra, self.rb)

    def closure(self, P, val):
        cx, cy = P(self.out)
        res = 0.0
        for p, r in ((self.a, self.ra), (self.b, self.rb)):
            px, py = P(p)
            res = np.maximum(res, np.abs(np.hypot(cx - px, cy - py) - val(r)))
        return res

    def rod_ends(self, links, is_coord):
        return tuple((l, self.out) for ref, l in zip((self.ra, self.rb), links) if is_coord(ref))

    def reactions(self, r):
        la, lb = r.links
        dyad_reactions_block(r, self.a, self.b, self.out, la, lb, self.ra, self.rb)
