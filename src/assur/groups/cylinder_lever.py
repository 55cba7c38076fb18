"""Cylinder–lever input group: a lever pivoted at ``pivot`` turned by a cylinder.

The cylinder (pin-to-pin length = generalized coordinate ``s`` [m]) joins the frame
pivot ``base`` to the lever point ``out`` at distance ``lever`` [m] from ``pivot``
(rocking cylinder, "four-bar with a middle prismatic pair"; seed 003 §2.1 φ3(S),
seed 000 FI3, seed 001 lab 4 eq. 3). Kinematically it is the RRR dyad
(:mod:`assur.groups.rrr`) with ``a = base, ra = s, b = pivot, rb = lever``;
``branch`` follows the dyad's convention for the directed line base → pivot.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

from .base import Field, Group, Ref, register
from .rrr import dyad_emit, dyad_failure, dyad_position, dyad_reactions_block, Dyad

__all__ = ["CylinderLever"]


@register
@dataclass(frozen=True)
class CylinderLever(Group):
    """Input group: lever ``pivot–out`` turned by the cylinder ``base–out`` of length ``s``.

    ``links = (cylinder, lever)``.

    Examples
    --------
    >>> from assur import Mechanism
    >>> m = (Mechanism("lift", coordinates=("S",))
    ...      .frame("01", 0.0, 0.0).frame("03", 0.40, 0.25)
    ...      .cylinder_lever("I", base="01", pivot="03", out="23", lever=0.22, s="S",
    ...                      branch=-1, links=("2", "3")))
    >>> m.group("I").inputs(), m.group("I").outputs()
    (('01', '03'), ('23',))
    """

    base: str = ""
    pivot: str = ""
    out: str = ""
    lever: Ref = 0.0
    s: str = ""
    branch: int = 1
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "cylinder_lever"
    kind: ClassVar[str] = "cylinder–lever group"
    kind_ru: ClassVar[str] = "группа «гидроцилиндр – рычаг»"
    driver_kind: ClassVar[str] = "length"
    link_roles: ClassVar = ("cylinder", "lever")
    continuity: ClassVar[bool] = True
    fields: ClassVar = (
        Field("base", "point", doc="frame pivot of the cylinder"),
        Field("pivot", "point", doc="pivot of the lever"),
        Field("out", "point", doc="the rod-end joint on the lever it adds"),
        Field("lever", "value", "length", "positive", True, doc="|pivot–out| [m]"),
        Field("s", "coordinate", "length", doc="the cylinder length, a coordinate [m]"),
        Field("branch", "branch", doc="+1: out left of base→pivot, −1: right"),
    )

    # the RRR dyad's roles (A = base, B = pivot, ra = s, rb = lever)
    a = property(lambda self: self.base)
    b = property(lambda self: self.pivot)
    ra = property(lambda self: self.s)
    rb = property(lambda self: self.lever)

    def inputs(self):
        return (self.base, self.pivot)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"s": self.s, "lever": self.lever}

    def coordinates_driven(self):
        return (self.s,)

    def topology(self, t):
        cyl, lev = t.link_names(self, 2)
        t.new(self, cyl, (self.base, self.out), variable=True)
        t.new(self, lev, (self.pivot, self.out), variable=t.is_coord(self.lever))
        t.own(self.out, lev)
        return (cyl, lev)

    def evaluate(self, pts, val):
        pts[self.out] = dyad_position(pts, self.base, self.pivot, val(self.s), val(self.lever),
                                      self.branch)

    def compile(self, c):
        return (c.slot(self.out), c.slot(self.base), c.slot(self.pivot), c.lref(self.s),
                c.lref(self.lever), self.branch)

    emit = classmethod(lambda cls, E, i, row: dyad_emit(E, i, row))

    def failure(self, code, pts, v, nm):
        return dyad_failure(self, code, pts, v, nm, self.base, self.pivot, self.s, self.lever)

    closure = Dyad.closure
    rod_ends = Dyad.rod_ends

    def reactions(self, r):
        la, lb = r.links
        dyad_reactions_block(r, self.base, self.pivot, self.out, la, lb, self.s, self.lever)
