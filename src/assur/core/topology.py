"""The bodies (links) of a mechanism, derived from its groups: a public, frozen
:class:`Topology` (DESIGN.md §9). Each group type says which links it creates and
which link owns each point it adds (:meth:`assur.groups.base.Group.topology`)."""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from ..errors import ModelError

__all__ = ["Topology", "TopologyBuilder", "build_topology"]


@dataclass(frozen=True)
class Topology:
    """Bodies of a mechanism.

    Attributes
    ----------
    bodies : mapping of str to tuple of str
        Points of each rigid body; the frame is ``"0"``.
    variable : frozenset of str
        Bodies whose length is a generalized coordinate (cylinders, telescopic arms).
    owner : mapping of str to str
        The body that owns each point: loads at the point and later groups attached
        there act on it (an RRR dyad's middle joint belongs to its second link; an RRP
        dyad's slider joint to its first).
    group_links : mapping of str to tuple of str
        The links of each group, in the order of its ``link_roles`` (then guides).
    turns_with : mapping of str to str
        Bodies with a single point (slider blocks, sleeves) and the body whose angle
        they share (their guide or rod).

    Examples
    --------
    The bodies of the seed-003 hitch (link numbers of the seed):

    >>> from assur import examples
    >>> t = examples.hitch_003().topology
    >>> t.bodies["0"], t.bodies["5"]              # frame pivots; lower link 5
    (('01', '03', '05', '07'), ('05', '45', '56'))
    >>> sorted(t.variable), t.owner["23"]         # the cylinder 2; 23 is on the lever 3
    (['2'], '3')
    >>> t.group_links["III (6,7)"]
    ('6', '7')
    """

    bodies: Mapping[str, tuple[str, ...]]
    variable: frozenset
    owner: Mapping[str, str]
    group_links: Mapping[str, tuple[str, ...]]
    turns_with: Mapping[str, str]

    def angle_points(self, body: str) -> tuple[str, str] | None:
        """Two points whose direction gives the body's angle, following ``turns_with``
        for single-point bodies; None for the frame (it does not turn).

        Examples
        --------
        >>> from assur import Mechanism, examples
        >>> t = examples.hitch_003().topology
        >>> t.angle_points("5"), t.angle_points("0")   # lower link 5; the frame
        (('05', '45'), None)

        A sleeve has one point and turns with its rod:

        >>> m = (Mechanism("slotted lever", coordinates=("j1",))
        ...      .frame("A0", 0.0, 0.0).frame("B", 0.16, 0.0)
        ...      .crank("crank", pivot="A0", out="A", radius=0.12, q="j1", links=("1",))
        ...      .rpr_dyad("II", a="A", b="B", out="E", length=0.55, links=("2", "3")))
        >>> m.topology.bodies["3"], m.topology.angle_points("3")
        (('B',), ('A', 'E'))
        """
        seen = set()
        while body != "0" and body not in seen:
            seen.add(body)
            pts = self.bodies[body]
            if len(pts) >= 2:
                return pts[0], pts[1]
            if body not in self.turns_with:
                return None
            body = self.turns_with[body]
        return None


class TopologyBuilder:
    """What a group's :meth:`~assur.groups.base.Group.topology` works with.

    Examples
    --------
    The bodies of the hitch's first groups, built group by group:

    >>> from assur import examples
    >>> from assur.core.topology import TopologyBuilder
    >>> m = examples.hitch_003()
    >>> t = TopologyBuilder(m.name, m.coordinates)
    >>> for g in m.groups[:6]:                # frame points 01…07, I (2,3), arm 34
    ...     _ = g.topology(t)
    >>> t.bodies["3"], sorted(t.variable), t.owner("34")
    (['03', '23', '34'], ['2'], '3')
    """

    def __init__(self, mechanism_name: str, coordinates):
        self.where = f"mechanism {mechanism_name!r}"
        self.coordinates = tuple(coordinates)
        self.bodies: dict = {"0": []}
        self.variable: set = set()
        self.owners: dict = {}
        self.turns: dict = {}

    def is_coord(self, ref) -> bool:
        """True if ``ref`` names a generalized coordinate.

        Examples
        --------
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("hitch_003", ("S",))
        >>> t.is_coord("S"), t.is_coord("L3"), t.is_coord(0.2)
        (True, False, False)
        """
        return isinstance(ref, str) and ref in self.coordinates

    def link_names(self, g, n: int) -> tuple[str, ...]:
        """The ``n`` link names a group gives, or ``"<group>:a"``, ``":b"``.

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("four-bar", ("j1",))
        >>> t.link_names(Dyad("II", links=("2", "3")), 2), t.link_names(Dyad("II"), 2)
        (('2', '3'), ('II:a', 'II:b'))
        >>> t.link_names(Dyad("II", links=("2",)), 2)  # doctest: +NORMALIZE_WHITESPACE
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'four-bar': RRR dyad 'II' has 2 link(s),
        got links=('2',)
        """
        given = g.group_links()
        if given and len(given) != n:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r} has {n} link(s), "
                             f"got links={given!r}")
        return given or tuple(f"{g.name}:{c}" for c in "ab"[:n])

    def new(self, g, name: str, points, variable: bool = False) -> None:
        """Create body ``name`` holding ``points``.

        Examples
        --------
        >>> from assur.groups import Dyad
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("truss", ("S",))
        >>> g = Dyad("II", a="A", b="B", out="C", ra="S", rb=0.4)
        >>> t.new(g, "2", ("A", "C"), variable=True)     # a cylinder
        >>> t.bodies["2"], sorted(t.variable)
        (['A', 'C'], ['2'])
        >>> t.new(g, "2", ("B", "C"))  # doctest: +NORMALIZE_WHITESPACE
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'truss': RRR dyad 'II' names its link '2', but
        an earlier group already has a link of that name (a group adds new links; name
        them uniquely)
        """
        if name in self.bodies:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r} names its link {name!r}, but "
                             f"an earlier group already has a link of that name (a group adds "
                             f"new links; name them uniquely)")
        self.bodies[name] = list(points)
        if variable:
            self.variable.add(name)

    def attach(self, body: str, point: str) -> None:
        """Put ``point`` on the existing ``body`` and make it the owner.

        Examples
        --------
        The hitch's arm point 34 on the lever 3:

        >>> from assur.groups import CylinderLever
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("hitch_003", ("S",))
        >>> t.new(CylinderLever("I (2,3)"), "3", ("03", "23"))
        >>> t.attach("3", "34")
        >>> t.bodies["3"], t.owner("34")
        (['03', '23', '34'], '3')
        """
        self.bodies[body].append(point)
        self.owners[point] = body

    def own(self, point: str, body: str) -> None:
        """Make ``body`` the owner of ``point``.

        Examples
        --------
        A dyad's middle joint belongs to its second link:

        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("four-bar", ("j1",))
        >>> t.own("C", "3")
        >>> t.owner("C")
        '3'
        """
        self.owners[point] = body

    def owner(self, point: str) -> str:
        """The body that owns ``point`` (set by :meth:`own` or :meth:`attach`).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.hitch_003()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:5]:              # frame points 01…07, I (2,3)
        ...     _ = g.topology(t)
        >>> t.owner("03"), t.owner("23")        # a frame pivot; the rod end on lever 3
        ('0', '3')
        >>> t.owner("45")
        Traceback (most recent call last):
        ...
        KeyError: '45'
        """
        return self.owners[point]

    def turns_with(self, body: str, other: str) -> None:
        """A single-point ``body`` turns with ``other`` (its guide).

        Examples
        --------
        >>> from assur.core.topology import TopologyBuilder
        >>> t = TopologyBuilder("slotted lever", ("j1",))
        >>> t.turns_with("3", "2")             # the sleeve 3 turns with the rod 2
        >>> t.turns
        {'3': '2'}
        """
        self.turns[body] = other

    def carrier(self, g, p: str, q: str, given=()) -> str:
        """The one rigid body that holds both ``p`` and ``q`` (checked against a link
        name the group gives).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import SliderDyad
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.hitch_003()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:5]:              # frame points 01…07, I (2,3)
        ...     _ = g.topology(t)
        >>> g = SliderDyad("slide", a="01", out="X", radius=0.3, line_point="03")
        >>> t.carrier(g, "03", "23")            # a slider line on the lever 3
        '3'

        The cylinder 2 (01–23) has a variable length and cannot carry one:

        >>> t.carrier(g, "01", "23")  # doctest: +NORMALIZE_WHITESPACE
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: mechanism 'hitch_003': RRP dyad 'slide': link '2' has a
        variable length (a cylinder) and cannot carry a rigid point or a slider line
        """
        cands = [b for b, v in self.bodies.items() if p in v and q in v]
        if given:
            if given[0] not in self.bodies:
                raise ModelError(f"{self.where}: {g.kind} {g.name!r}: link {given[0]!r} is not "
                                 f"defined by an earlier group")
            if given[0] not in cands:
                raise ModelError(f"{self.where}: {g.kind} {g.name!r}: points {p!r} and {q!r} are "
                                 f"not both on link {given[0]!r}")
            cands = [given[0]]
        if len(cands) != 1:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r}: points {p!r} and {q!r} must lie "
                             f"on one rigid link, found {cands or 'none'}")
        if cands[0] in self.variable:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r}: link {cands[0]!r} has a "
                             f"variable length (a cylinder) and cannot carry a rigid point or a "
                             f"slider line")
        return cands[0]


def build_topology(name, coordinates, groups) -> Topology:
    """The :class:`Topology` of a group sequence (each group adds its bodies).

    Examples
    --------
    >>> from assur import examples
    >>> from assur.core.topology import build_topology
    >>> m = examples.hitch_003()
    >>> t = build_topology(m.name, m.coordinates, m.groups)
    >>> t.bodies["6"]                          # implement 6: 56, 67, S6, test frame F610
    ('56', '67', 'S6', 'F610')
    >>> t == m.topology
    True
    """
    t = TopologyBuilder(name, coordinates)
    links = {}
    for g in groups:
        links[g.name] = tuple(g.topology(t))
    return Topology(
        bodies=MappingProxyType({k: tuple(v) for k, v in t.bodies.items()}),
        variable=frozenset(t.variable), owner=MappingProxyType(dict(t.owners)),
        group_links=MappingProxyType(links), turns_with=MappingProxyType(dict(t.turns)))
