"""Which generalized coordinates move which points and links: the chains they drive.

A mechanism with k > 1 coordinates (the loader of seed 001 lab 1: the boom cylinder
S and the traverse cylinder S1) has points that only some coordinates move: the
suspension axis 09 and the boom's centre of mass S3 ride on the boom, which S alone
turns; the tool's centre of mass S9 rides on the traverse, which both move. A
quantity taken *through* a coordinate that does not move a point — its transmission
number I = ∂Y/∂q, the capacity G = F·η/I of the cylinder on q, a ratio U_ij whose
link j does not turn with q — is not a number (it is 0 or 0/0): tables and figures
leave it out with a note instead of showing a column of zeros, NaN or a spike.

The answer is structural (from the groups, not from numbers): a group's outputs are
moved by the coordinates that drive it (its ``coordinates_driven()`` and any length
or angle of it that names a coordinate, e.g. a dyad whose radius is a cylinder) and
by everything that moves its input points. A pose point's fixed pose (``at``) does
not make it move.
"""

from __future__ import annotations

__all__ = ["point_coordinates", "link_coordinates", "moves"]


def _point_table(mech):
    """``{point: frozenset of coordinates}`` for every point (memoized per mechanism)."""
    def make():
        coords = set(mech.coordinates)
        out = {p: frozenset() for p in mech.frame_points}
        for g in mech.groups:
            drives = set(g.coordinates_driven())
            drives |= {r for r in g.refs().values() if isinstance(r, str) and r in coords}
            for p in g.inputs():
                drives |= out.get(p, frozenset())
            for p in g.outputs():
                out[p] = frozenset(drives)
        return out
    return mech.memo(("chains",), make)


def point_coordinates(mech, point) -> frozenset:
    """The generalized coordinates that move ``point`` [names].

    Raises
    ------
    KeyError
        If ``point`` is not a point of the mechanism.

    Examples
    --------
    The loader of seed 001 lab 1: the suspension axis 09 rides on the boom, which
    the boom cylinder S alone turns; the tool's centre of mass S9 moves with both.

    >>> from assur import examples
    >>> from assur.core.chains import point_coordinates
    >>> loader = examples.loader_lab1()
    >>> sorted(point_coordinates(loader, "09")), sorted(point_coordinates(loader, "S9"))
    (['S'], ['S', 'S1'])
    >>> sorted(point_coordinates(loader, "01"))  # a frame point
    []
    >>> point_coordinates(loader, "99")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    KeyError: "loader_lab1: no point '99'; points: ['01', '03', '23', ...]"
    """
    table = _point_table(mech)
    if point not in table:
        raise KeyError(f"{mech.name}: no point {point!r}; points: {list(table)}")
    return table[point]


def link_coordinates(mech, link) -> frozenset:
    """The generalized coordinates that turn or stretch ``link`` (a link of
    :meth:`Mechanism.link` or a body named by a group): those that move any of its
    points.

    Examples
    --------
    The loader of seed 001 lab 1: the boom (link 3) turns with S only, the tool
    (link 9) with both cylinders.

    >>> from assur import examples
    >>> from assur.core.chains import link_coordinates
    >>> loader = examples.loader_lab1()
    >>> sorted(link_coordinates(loader, "3")), sorted(link_coordinates(loader, "9"))
    (['S'], ['S', 'S1'])
    """
    declared = {l.name: (l.tail, l.head) for l in mech.links}
    if link in declared:
        pts = declared[link]
    else:
        bodies = mech.bodies
        if link not in bodies:
            raise KeyError(f"{mech.name}: no link {link!r}")
        pts = bodies[link]["points"]
    out = frozenset()
    for p in pts:
        out |= point_coordinates(mech, p)
    return out


def moves(mech, coordinate, point=None, link=None) -> bool:
    """True if ``coordinate`` moves ``point`` (or turns ``link``).

    Examples
    --------
    The traverse cylinder S1 of the loader (seed 001 lab 1) does not move the
    suspension axis 09 on the boom, but turns the tool (link 9):

    >>> from assur import examples
    >>> from assur.core.chains import moves
    >>> loader = examples.loader_lab1()
    >>> moves(loader, "S1", point="09"), moves(loader, "S1", link="9")
    (False, True)
    >>> moves(loader, "S1")
    Traceback (most recent call last):
    ...
    ValueError: give exactly one of point=, link=
    """
    if (point is None) == (link is None):
        raise ValueError("give exactly one of point=, link=")
    deps = point_coordinates(mech, point) if point is not None else link_coordinates(mech, link)
    return coordinate in deps
