"""Named measures of a solved mechanism: link angles and distances between points."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Link", "Distance"]


@dataclass(frozen=True)
class Link:
    """A named link direction: the angle φ [rad] of the vector ``tail → head``.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> m.links[1]                                   # the lever 3
    Link(name='3', tail='03', head='23')
    >>> r = m.solve([0.42])                          # S = Smin [m]
    >>> round(float(r.phi("3", degrees=True)[0]), 1)  # φ3, seed 003 table 2.1 [deg]
    -40.2
    """

    name: str
    tail: str
    head: str


@dataclass(frozen=True)
class Distance:
    """A named distance [m] between two points (e.g. a dependent cylinder length S2, or
    seed 002's helper vectors l7 = |C–O6|, l9 = |A–O3|).

    ``angle`` optionally names the distance's direction ``a → b`` too, the angle
    φ_angle [rad] from +x, counter-clockwise (seed 002: the vector l7 at the angle
    j7): the mechanism then holds a :class:`Link` of that name from ``a`` to ``b``
    (:meth:`assur.Mechanism.distance`), tabulated, plotted and usable in conditions
    like any link angle.

    Examples
    --------
    >>> from assur import examples
    >>> m = examples.combine_002()
    >>> m.distances[0]                               # seed 002's helper vector l9
    Distance(name='l9', a='A', b='O3', angle='9')
    >>> r = m.solve([0.0])                           # j1 = 0 [rad]
    >>> round(float(r.length("l9")[0]), 4)           # |A − O3| [m]
    1.0603
    >>> round(float(r.phi("9", degrees=True)[0]), 3)  # its angle j9 [deg]
    -8.13
    """

    name: str
    a: str
    b: str
    angle: str | None = None
