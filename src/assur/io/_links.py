"""The link directions a model file without ``[links]`` gets from its groups
(:meth:`assur.io._assemble.Assembly.add_links`): the one place that states the rule.
"""

from __future__ import annotations

from ..groups import Link

__all__ = ["derived_links"]


def derived_links(mech) -> tuple[Link, ...]:
    """The links of a model file that has no ``[links]`` section.

    One link per rigid body that a group names (its ``links = [...]``) and that has at
    least two points, in the order of :attr:`Mechanism.bodies <assur.Mechanism.bodies>`
    (the order the groups define them); its name is the body's name and its direction
    runs from the body's first point to its second (for a cylinder lever's boom: from
    the pivot to the cylinder's pin). The frame ``"0"`` does not turn and is left out,
    and so are the bodies the groups do not name (``"<group>:a"``) and any body whose
    name a ``[distances]`` entry already uses (as its name or its angle's). A body of variable length (a cylinder)
    is a link too: its direction is the cylinder's.

    Why any two points will do: a rigid body turns as a whole, so the analogs dφ/dq
    and d²φ/dq² of the direction between any two of its points are the same; only the
    angle's constant offset depends on which two, and the tables say which (the
    column's label names both points).

    Parameters
    ----------
    mech : Mechanism
        The mechanism built from the file's frame and groups.

    Returns
    -------
    tuple of Link
        The derived links (:class:`assur.groups.Link`), none if no body qualifies.

    Examples
    --------
    A cylinder 2 (pins 01, 23) turning a lever 3 about 03:

    >>> from assur import Mechanism
    >>> from assur.io._links import derived_links
    >>> m = (Mechanism("lever", params={"L3": 0.2}).frame("01", 0.415, 0.563)
    ...      .frame("03", 0.25, 1.112)
    ...      .cylinder_lever("I", base="01", pivot="03", out="23", lever="L3", s="S",
    ...                      branch=-1, links=("2", "3")))
    >>> derived_links(m)
    (Link(name='2', tail='01', head='23'), Link(name='3', tail='03', head='23'))

    The loader applies it to the seed-004 crane, whose file has no ``[links]``: its
    boom 1 runs from the pivot O to the lift cylinder's pin B:

    >>> from assur import io
    >>> c = io.load(io.bundled("crane_lv184a")).mechanism
    >>> [(l.name, l.tail, l.head) for l in c.links][:3]
    [('3', 'A', 'B'), ('1', 'O', 'B'), ('4', 'Bc', 'E')]
    >>> c.tables["derived_links"]
    ('3', '1', '4', 'a2', 'c2', '2')
    """
    named = {n for g in mech.groups for n in g.group_links()}
    taken = {d.name for d in mech.distances} | {l.name for l in mech.links}
    out = []
    for name, body in mech.bodies.items():
        points = body["points"]
        if name == "0" or name not in named or name in taken or len(points) < 2:
            continue
        out.append(Link(name, points[0], points[1]))
    return tuple(out)
