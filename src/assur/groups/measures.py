"""Named measures of a solved mechanism: link angles and distances between points."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Link", "Distance"]


@dataclass(frozen=True)
class Link:
    """A named link direction: the angle φ [rad] of the vector ``tail → head``."""

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
    """

    name: str
    a: str
    b: str
    angle: str | None = None
