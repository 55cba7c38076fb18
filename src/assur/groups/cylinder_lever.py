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
    @property
    def a(self):
        """The dyad's joint A (``a``): the cylinder's frame pivot ``base``.

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")   # cylinder 2, lever 3
        >>> g.a, g.base
        ('01', '01')
        """
        return self.base

    @property
    def b(self):
        """The dyad's joint B (``b``): the lever's pivot ``pivot``.

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")   # cylinder 2, lever 3
        >>> g.b, g.pivot
        ('03', '03')
        """
        return self.pivot

    @property
    def ra(self):
        """The dyad's ``|A–C|`` (``ra``): the cylinder length ``s``, a coordinate.

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")   # cylinder 2, lever 3
        >>> g.ra, g.s
        ('S', 'S')
        """
        return self.s

    @property
    def rb(self):
        """The dyad's ``|B–C|`` (``rb``): the lever arm ``lever``.

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")   # cylinder 2, lever 3
        >>> g.rb, g.lever
        ('L3', 'L3')
        """
        return self.lever

    def inputs(self):
        """Names of the points this group needs solved first: ``(base, pivot)``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("I (2,3)").inputs()  # frame pivots, seed 003 §1.1
        ('01', '03')
        """
        return (self.base, self.pivot)

    def outputs(self):
        """Names of the points this group adds: ``(out,)``, the rod end on the lever.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("I (2,3)").outputs()
        ('23',)
        """
        return (self.out,)

    def refs(self):
        """Length references of the group by role: ``s`` (the coordinate), ``lever``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> m.group("I (2,3)").refs()
        {'s': 'S', 'lever': 'L3'}
        >>> round(float(m.value_of("L3")), 3)  # L3, seed 003 §1.2 [m]
        0.2
        """
        return {"s": self.s, "lever": self.lever}

    def coordinates_driven(self):
        """The generalized coordinate this group is driven by: ``(s,)``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("I (2,3)").coordinates_driven()  # cylinder length
        ('S',)
        """
        return (self.s,)

    def topology(self, t):
        """Create the cylinder (base–out, variable length) and the lever (pivot–out,
        owner of ``out``) in the topology builder ``t``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("hitch_003", ("S",))
        >>> g = examples.hitch_003().group("I (2,3)")   # cylinder 2, lever 3
        >>> g.topology(t)
        ('2', '3')
        >>> t.bodies["2"], sorted(t.variable), t.owner("23")
        (['01', '23'], ['2'], '3')
        """
        cyl, lev = t.link_names(self, 2)
        t.new(self, cyl, (self.base, self.out), variable=True)
        t.new(self, lev, (self.pivot, self.out), variable=t.is_coord(self.lever))
        t.own(self.out, lev)
        return (cyl, lev)

    def evaluate(self, pts, val):
        """Add ``out`` to ``pts``: the dyad's position with A = base, B = pivot,
        ra = s, rb = lever (:func:`~assur.groups.rrr.dyad_position`).

        Examples
        --------
        The hitch's lever point 23 at the shortest cylinder, S = Smin = 0.42 m:

        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")
        >>> pts = {"01": (0.415, 0.563), "03": (0.25, 1.112)}   # seed 003 §1.1 [m]
        >>> g.evaluate(pts, {"S": 0.42, "L3": 0.2}.get)
        >>> [round(float(v), 4) for v in pts["23"]]              # (X23, Y23) [m]
        [0.4027, 0.9828]
        """
        pts[self.out] = dyad_position(pts, self.base, self.pivot, val(self.s), val(self.lever),
                                      self.branch)

    def compile(self, c):
        """The program row ``(out, base, pivot, s, lever, branch)`` — the RRR dyad's
        row, so the kernel code is :func:`~assur.groups.rrr.dyad_emit`.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> g = examples.hitch_003().group("I (2,3)")
        >>> c = CompileContext(("S",), ("L3",))
        >>> c.slot("01"), c.slot("03")
        (0, 1)
        >>> g.compile(c)   # 23 in slot 2; s: coordinate 0 (−1); lever: row 0; branch
        (2, 0, 1, -1, 0, -1)
        """
        return (c.slot(self.out), c.slot(self.base), c.slot(self.pivot), c.lref(self.s),
                c.lref(self.lever), self.branch)

    @classmethod
    def emit(cls, E, i, row):
        """Emit the kernel code of group ``i`` with program ``row``
        (:func:`~assur.groups.rrr.dyad_emit`: the cylinder length is ``q[j, e]``).

        Examples
        --------
        >>> from assur.groups import CylinderLever
        >>> from assur.kernel.emit import Emitter
        >>> E = Emitter(1, order=1)
        >>> CylinderLever.emit(E, 0, (2, 0, 1, -1, 0, -1))
        >>> print(E.lines[0].strip())   # ra = s, the coordinate 0 at element e
        t0ra = q[0, e]
        """
        dyad_emit(E, i, row)

    def failure(self, code, pts, v, nm):
        """Amount and message of failure ``code`` (:func:`~assur.groups.rrr.dyad_failure`
        with A = base, B = pivot, ra = s, rb = lever).

        Examples
        --------
        The hitch's cylinder at S = 0.3 m cannot reach the lever:

        >>> from assur import examples
        >>> from assur.kernel.emit import FAIL_TOO_FAR
        >>> g = examples.hitch_003().group("I (2,3)")
        >>> pts = {"01": (0.415, 0.563), "03": (0.25, 1.112)}   # seed 003 §1.1 [m]
        >>> f = g.failure(FAIL_TOO_FAR, pts, {"S": 0.3, "L3": 0.2}.get, str)
        >>> round(f.amount, 4)   # [m]
        0.0733
        >>> print(f.text)
        the distance |01–03| = 0.573259 m exceeds S + L3 = 0.3 + 0.2 = 0.5 m by 73.3 mm
        """
        return dyad_failure(self, code, pts, v, nm, self.base, self.pivot, self.s, self.lever)

    def closure(self, P, val):
        """Largest violation of ``|out − base| = s``, ``|out − pivot| = lever`` [m].

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")
        >>> pts = {"01": (0.415, 0.563), "03": (0.25, 1.112)}   # seed 003 §1.1 [m]
        >>> val = {"S": 0.42, "L3": 0.2}.get                    # [m]
        >>> g.evaluate(pts, val)
        >>> round(float(g.closure(pts.get, val)), 9)            # [m]
        0.0
        >>> round(float(g.closure(pts.get, {"S": 0.43, "L3": 0.2}.get)), 4)  # [m]
        0.01
        """
        return Dyad.closure(self, P, val)

    def rod_ends(self, links, is_coord):
        """``((cylinder, out),)``: the rod end of the cylinder (the lever too, if its
        length is a coordinate).

        Examples
        --------
        >>> from assur import examples
        >>> g = examples.hitch_003().group("I (2,3)")
        >>> g.rod_ends(("2", "3"), lambda ref: ref == "S")
        (('2', '23'),)
        """
        return Dyad.rod_ends(self, links, is_coord)

    def reactions(self, r):
        """Joint reactions of the group (:func:`~assur.groups.rrr.dyad_reactions_block`)
        and the cylinder's axial force, added to ``r.act[s]`` [N].

        Examples
        --------
        1000 N down at the lever point 23; the cylinder force equals the load times
        the transmission ``∂y23/∂S`` (virtual work):

        >>> from assur import Mechanism
        >>> from assur.core.statics import ReactionContext
        >>> m = (Mechanism("lift", coordinates=("S",))
        ...      .frame("01", 0.0, 0.0).frame("03", 0.40, 0.25)
        ...      .cylinder_lever("I", base="01", pivot="03", out="23", lever=0.22, s="S",
        ...                      branch=-1, links=("2", "3")))
        >>> kin = m.solve([0.5])                               # S [m]
        >>> r = ReactionContext(kin, set())
        >>> r.links = m.topology.group_links["I"]
        >>> r.apply("3", "23", 0.0, -1000.0)                   # [N]
        >>> m.group("I").reactions(r)
        >>> round(float(r.act["S"][0, 0]), 3)                  # cylinder force [N]
        470.819
        >>> round(float(1000.0 * kin.dy("23")[0]), 3)          # P·∂y23/∂S [N]
        470.819
        """
        la, lb = r.links
        dyad_reactions_block(r, self.base, self.pivot, self.out, la, lb, self.s, self.lever)
