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
    """A named distance [m] between two points (e.g. a dependent cylinder length S2)."""

    name: str
    a: str
    b: str
