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
    """Direction angle [rad] of a slider line in a reaction context, shape (m, n)."""
    beta = r.value(direction)
    if line_link:
        (px, py), (qx, qy) = r.point(line_link[0]), r.point(line_link[1])
        return np.arctan2(qy - py, qx - px) + beta
    return beta


@register
@dataclass(frozen=True)
class SliderDyad(Group):
    """RRP dyad: ``out`` at ``radius`` [m] from ``a``, on a line (see module).
    ``links = (link at a, slider)``; the slider block turns with the guide."""

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
        extra = tuple(self.line_link) if self.line_link else ()
        return (self.a, self.line_point) + extra

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"radius": self.radius, "direction": self.direction}

    def topology(self, t):
        la, lb = t.link_names(self, 2)
        guide = (t.carrier(self, self.line_link[0], self.line_link[1], ()) if self.line_link
                 else t.owner(self.line_point))
        t.new(self, la, (self.a, self.out), variable=t.is_coord(self.radius))
        t.new(self, lb, (self.out,))
        t.own(self.out, la)
        t.turns_with(lb, guide)
        return (la, lb, guide)

    def evaluate(self, pts, val):
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
        dp, dq = ((c.slot(self.line_link[0]), c.slot(self.line_link[1])) if self.line_link
                  else (-1, -1))
        return (c.slot(self.out), c.slot(self.a), c.lref(self.radius), c.slot(self.line_point),
                dp, dq, c.trig_angle(c.pref(self.direction)), self.branch)

    @classmethod
    def emit(cls, E, i, row):
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
        return ((links[0], self.out),) if is_coord(self.radius) else ()

    def reactions(self, r):
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
