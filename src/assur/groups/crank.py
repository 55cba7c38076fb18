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
        return (self.pivot,)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"radius": self.radius, "phase": self.phase}

    def coordinates_driven(self):
        return (self.q,)

    def topology(self, t):
        (l,) = t.link_names(self, 1)
        t.new(self, l, (self.pivot, self.out), variable=t.is_coord(self.radius))
        t.own(self.out, l)
        return (l,)

    def evaluate(self, pts, val):
        px, py = pts[self.pivot]
        r = val(self.radius)
        th = val(self.q) + val(self.phase)
        pts[self.out] = (px + r * np.cos(th), py + r * np.sin(th))

    def compile(self, c):
        return (c.slot(self.out), c.slot(self.pivot), c.lref(self.radius), c.coord(self.q),
                c.pref(self.phase))

    @classmethod
    def emit(cls, E, i, row):
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
