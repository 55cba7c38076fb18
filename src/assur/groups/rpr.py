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
    ``links = (rod, sleeve)``; the sleeve turns with the rod."""

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
        return (self.a, self.b)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"length": self.length, "offset": self.offset}

    def validate(self, coordinates):
        for role, ref in self.refs().items():
            if isinstance(ref, str) and ref in coordinates:
                return f"{role} must be a number or a parameter, not the coordinate {ref!r}"
        return super().validate(coordinates)

    def topology(self, t):
        rod, sleeve = t.link_names(self, 2)
        t.new(self, rod, (self.a, self.out))
        t.new(self, sleeve, (self.b,))
        t.own(self.out, rod)
        t.turns_with(sleeve, rod)
        return (rod, sleeve)

    def evaluate(self, pts, val):
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
        return (c.slot(self.out), c.slot(self.a), c.slot(self.b), c.lref(self.length),
                c.pref(self.offset), self.branch)

    @classmethod
    def emit(cls, E, i, row):
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
        ax, ay = P(self.a)
        bx, by = P(self.b)
        ox, oy = P(self.out)
        ell = val(self.length)
        res = np.abs(np.hypot(ox - ax, oy - ay) - ell)
        # B at the offset e from the rod's line: (B − A) × û = −e  (û × R90û = 1)
        cr = ((bx - ax) * (oy - ay) - (by - ay) * (ox - ax)) / ell
        return np.maximum(res, np.abs(cr + val(self.offset)))

    def reactions(self, r):
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
