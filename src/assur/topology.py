"""The bodies (links) of a mechanism, derived from its groups: a public, frozen
:class:`Topology` (DESIGN.md §9). Each group type says which links it creates and
which link owns each point it adds (:meth:`assur.groups.base.Group.topology`)."""

from __future__ import annotations

from dataclasses import dataclass
from types import MappingProxyType
from typing import Mapping

from .errors import ModelError

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
        there act on it (a dyad's middle joint belongs to its second link).
    group_links : mapping of str to tuple of str
        The links of each group, in the order of its ``link_roles`` (then guides).
    turns_with : mapping of str to str
        Bodies with a single point (slider blocks, sleeves) and the body whose angle
        they share (their guide or rod).
    """

    bodies: Mapping[str, tuple[str, ...]]
    variable: frozenset
    owner: Mapping[str, str]
    group_links: Mapping[str, tuple[str, ...]]
    turns_with: Mapping[str, str]

    def angle_points(self, body: str) -> tuple[str, str] | None:
        """Two points whose direction gives the body's angle, following ``turns_with``
        for single-point bodies; None for the frame (it does not turn)."""
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
    """What a group's :meth:`~assur.groups.base.Group.topology` works with."""

    def __init__(self, mechanism_name: str, coordinates):
        self.where = f"mechanism {mechanism_name!r}"
        self.coordinates = tuple(coordinates)
        self.bodies: dict = {"0": []}
        self.variable: set = set()
        self.owners: dict = {}
        self.turns: dict = {}

    def is_coord(self, ref) -> bool:
        """True if ``ref`` names a generalized coordinate."""
        return isinstance(ref, str) and ref in self.coordinates

    def link_names(self, g, n: int) -> tuple[str, ...]:
        """The ``n`` link names a group gives, or ``"<group>:a"``, ``":b"``."""
        given = g.group_links()
        if given and len(given) != n:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r} has {n} link(s), "
                             f"got links={given!r}")
        return given or tuple(f"{g.name}:{c}" for c in "ab"[:n])

    def new(self, g, name: str, points, variable: bool = False) -> None:
        """Create body ``name`` holding ``points``."""
        if name in self.bodies:
            raise ModelError(f"{self.where}: {g.kind} {g.name!r} names its link {name!r}, but "
                             f"an earlier group already has a link of that name (a group adds "
                             f"new links; name them uniquely)")
        self.bodies[name] = list(points)
        if variable:
            self.variable.add(name)

    def attach(self, body: str, point: str) -> None:
        """Put ``point`` on the existing ``body`` and make it the owner."""
        self.bodies[body].append(point)
        self.owners[point] = body

    def own(self, point: str, body: str) -> None:
        """Make ``body`` the owner of ``point``."""
        self.owners[point] = body

    def owner(self, point: str) -> str:
        return self.owners[point]

    def turns_with(self, body: str, other: str) -> None:
        """A single-point ``body`` turns with ``other`` (its guide)."""
        self.turns[body] = other

    def carrier(self, g, p: str, q: str, given=()) -> str:
        """The one rigid body that holds both ``p`` and ``q`` (checked against a link
        name the group gives)."""
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
    """The :class:`Topology` of a group sequence (each group adds its bodies)."""
    t = TopologyBuilder(name, coordinates)
    links = {}
    for g in groups:
        links[g.name] = tuple(g.topology(t))
    return Topology(
        bodies=MappingProxyType({k: tuple(v) for k, v in t.bodies.items()}),
        variable=frozenset(t.variable), owner=MappingProxyType(dict(t.owners)),
        group_links=MappingProxyType(links), turns_with=MappingProxyType(dict(t.turns)))
