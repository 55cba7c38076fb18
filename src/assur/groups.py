"""Structural (Assur) groups: the building blocks of a mechanism.

A mechanism is a set of frame points followed by an ordered list of groups; each
group is solved from points already known and adds new points (Assur–Artobolevsky
decomposition). The groups here are *descriptions* (immutable dataclasses); they
are compiled into the program run by :mod:`assur._kernel`, and each also carries
a plain-numpy :meth:`evaluate` of its position formulas that works for any dtype
(complex included). That second implementation is what the tests differentiate by
complex step to check the kernel's exact analogs.

Sign conventions
----------------
Right-handed x–y frame, angles from +x, counter-clockwise positive (BRIEF.md).

``branch`` of a dyad: ``+1`` puts the new joint *C* on the left of the directed
line from the first outer joint *A* to the second *B* (counter-clockwise turn
from AB to AC), ``-1`` on the right::

            C (branch +1)
           / \\
      ra  /   \\  rb
         /     \\
        A ------> B
         \\     /
          \\   /
            C (branch -1)

A *length reference* (``ra``, ``lever``, ``length``…) is either a number [m], the
name of a model parameter, or the name of a generalized coordinate (a cylinder
length that drives the group).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Union

import numpy as np

from . import _kernel as K

Ref = Union[str, float, int]


def _fmt(v):
    return f"{v:.6g}"


@dataclass(frozen=True)
class Group:
    """Base of all structural groups."""

    name: str

    #: kernel op code
    op = -1
    #: human description used in messages
    kind = "group"

    def inputs(self) -> tuple[str, ...]:
        """Names of the points this group needs solved first."""
        raise NotImplementedError

    def outputs(self) -> tuple[str, ...]:
        """Names of the points this group adds."""
        raise NotImplementedError

    def refs(self) -> dict[str, Ref]:
        """Length/angle references of the group by role."""
        return {}

    def group_links(self) -> tuple[str, ...]:
        return tuple(getattr(self, "links", ()) or ())


@dataclass(frozen=True)
class Frame(Group):
    """A frame (ground) pivot at fixed coordinates ``x``, ``y`` [m]."""

    x: Ref = 0.0
    y: Ref = 0.0
    op = K.OP_FRAME
    kind = "frame point"

    def inputs(self):
        return ()

    def outputs(self):
        return (self.name,)

    def refs(self):
        return {"x": self.x, "y": self.y}

    def evaluate(self, pts, val):
        x = val(self.x)
        pts[self.name] = (x, val(self.y) + 0 * x)


@dataclass(frozen=True)
class Dyad(Group):
    """RRR dyad: joint ``out`` at distance ``ra`` from point ``a`` and ``rb`` from ``b``.

    Two links (``links = (link_a, link_b)``) joined at ``out``; the outer joints
    ``a`` and ``b`` are already known. A radius may be a generalized coordinate,
    which makes this the dyad with a cylinder of variable length (RPR written with
    the cylinder's pin-to-pin length), and with ``a`` a frame pivot of the
    cylinder and ``b`` the lever pivot it is the *cylinder–lever* input group
    (four-bar with a middle prismatic pair, seed 003 §2.1).

    Position (law of cosines, 003 eqs. φ3, φ41, φ51):

    .. math::
        d = |B - A|,\\quad a = \\frac{r_a^2 - r_b^2 + d^2}{2d},\\quad
        h = \\sqrt{r_a^2 - a^2},\\quad
        C = A + a\\,\\hat u + \\sigma h\\,\\hat u_\\perp

    Analogs: the closure equations ``|C-A|² = ra²``, ``|C-B|² = rb²``
    differentiated once and twice give a 2x2 linear system with matrix rows
    ``(C-A)ᵀ, (C-B)ᵀ``; its determinant is ``ra·rb·sin μ`` (μ the transmission
    angle), zero at a dead point.
    """

    a: str = ""
    b: str = ""
    out: str = ""
    ra: Ref = 0.0
    rb: Ref = 0.0
    branch: int = 1
    links: tuple[str, ...] = ()
    op = K.OP_RRR
    kind = "RRR dyad"

    def inputs(self):
        return (self.a, self.b)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"ra": self.ra, "rb": self.rb}

    def evaluate(self, pts, val):
        ax, ay = pts[self.a]
        bx, by = pts[self.b]
        ra, rb = val(self.ra), val(self.rb)
        dx, dy = bx - ax, by - ay
        L = np.sqrt(dx * dx + dy * dy)
        aa = (ra * ra - rb * rb + L * L) / (2 * L)
        h = np.sqrt(ra * ra - aa * aa)
        ux, uy = dx / L, dy / L
        s = self.branch
        pts[self.out] = (ax + aa * ux - s * h * uy, ay + aa * uy + s * h * ux)


@dataclass(frozen=True)
class CylinderLever(Group):
    """Input group: a lever pivoted at ``pivot`` turned by a cylinder from ``base``.

    The cylinder (pin-to-pin length = generalized coordinate ``s`` [m]) joins the
    frame pivot ``base`` to the lever point ``out`` at distance ``lever`` [m] from
    ``pivot`` (rocking cylinder, "four-bar with a middle prismatic pair"; seed 003
    §2.1 φ3(S), seed 000 FI3, seed 001 lab 4 eq. 3). Kinematically it is the RRR
    :class:`Dyad` with ``a = base, ra = s, b = pivot, rb = lever``; ``branch``
    follows the dyad's convention for the directed line base → pivot.
    ``links = (cylinder, lever)``.
    """

    base: str = ""
    pivot: str = ""
    out: str = ""
    lever: Ref = 0.0
    s: str = ""
    branch: int = 1
    links: tuple[str, ...] = ()
    op = K.OP_RRR
    kind = "cylinder–lever group"

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

    evaluate = Dyad.evaluate


@dataclass(frozen=True)
class Crank(Group):
    """Crank input: ``out = pivot + r·(cos(q + phase), sin(q + phase))``.

    ``angle`` is the generalized coordinate [rad]; ``phase`` a fixed offset [rad].
    """

    pivot: str = ""
    out: str = ""
    radius: Ref = 0.0
    angle: str = ""
    phase: Ref = 0.0
    links: tuple[str, ...] = ()
    op = K.OP_CRANK
    kind = "crank"

    def inputs(self):
        return (self.pivot,)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"radius": self.radius, "phase": self.phase}

    def evaluate(self, pts, val):
        px, py = pts[self.pivot]
        r = val(self.radius)
        th = val(self.angle) + val(self.phase)
        pts[self.out] = (px + r * np.cos(th), py + r * np.sin(th))


@dataclass(frozen=True)
class SliderInput(Group):
    """Prismatic input: a slider driven along a fixed line by coordinate ``s``.

    ``out = origin + (s + offset)·(cos direction, sin direction)`` [m].
    """

    origin: str = ""
    out: str = ""
    s: str = ""
    offset: Ref = 0.0
    direction: Ref = 0.0
    links: tuple[str, ...] = ()
    op = K.OP_SLIDE
    kind = "slider input"

    def inputs(self):
        return (self.origin,)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"offset": self.offset, "direction": self.direction}

    def evaluate(self, pts, val):
        ox, oy = pts[self.origin]
        t = val(self.s) + val(self.offset)
        b = val(self.direction)
        pts[self.out] = (ox + t * np.cos(b), oy + t * np.sin(b))


def _unit_eval(pts, p, q, beta):
    px, py = pts[p]
    qx, qy = pts[q]
    dx, dy = qx - px, qy - py
    r = np.sqrt(dx * dx + dy * dy)
    cb, sb = np.cos(beta), np.sin(beta)
    return (cb * dx - sb * dy) / r, (sb * dx + cb * dy) / r


@dataclass(frozen=True)
class RigidPoint(Group):
    """A point fixed on a rigid link: at ``length`` from ``origin``, turned ``angle``
    from the direction ``origin → toward`` (both points of the same link).

    Either ``angle`` [rad] is given (003: φ34 = φ3 + φBD, φBD = 22°; the implement's
    centre of mass S6), or the three sides of the link's triangle: ``base`` =
    |origin–toward|, ``length`` = |origin–out| and ``opposite`` = |toward–out|
    with ``branch`` = ±1 the side of the turn (000: the bell-crank L3, L4, L34,
    DELFI = acos((L3² + L4² − L34²)/(2·L3·L4))). A triangle that cannot close
    fails with the violated inequality.

    ``links = (name,)`` optionally names the existing link that carries the point
    (checked); by default it is the one rigid link holding both ``origin`` and
    ``toward``. A ``length`` that is a generalized coordinate makes a telescopic arm.
    """

    origin: str = ""
    toward: str = ""
    out: str = ""
    length: Ref = 0.0
    angle: Ref | None = None
    base: Ref | None = None
    opposite: Ref | None = None
    branch: int = 1
    links: tuple[str, ...] = ()
    op = K.OP_RIGID
    kind = "rigid point"

    def inputs(self):
        return (self.origin, self.toward)

    def outputs(self):
        return (self.out,)

    def refs(self):
        if self.angle is not None:
            return {"length": self.length, "angle": self.angle}
        return {"length": self.length, "base": self.base, "opposite": self.opposite}

    def beta(self, val):
        if self.angle is not None:
            return val(self.angle)
        b, ell, o = val(self.base), val(self.length), val(self.opposite)
        return self.branch * np.arccos((b * b + ell * ell - o * o) / (2 * b * ell))

    def evaluate(self, pts, val):
        ux, uy = _unit_eval(pts, self.origin, self.toward, self.beta(val))
        ell = val(self.length)
        px, py = pts[self.origin]
        pts[self.out] = (px + ell * ux, py + ell * uy)


@dataclass(frozen=True)
class SliderDyad(Group):
    """RRP dyad: joint ``out`` at distance ``radius`` from ``a`` and on a line.

    The line passes through the known point ``line_point`` with direction
    ``direction`` [rad] measured from +x, or — when ``line_link = (P, Q)`` is given —
    turned ``direction`` from the moving direction P → Q (a slider on a link).
    ``branch = +1`` takes the intersection further along the line direction.

    Position: ``C = L0 + t·u`` with ``t² + 2t·u·(L0−A) + |L0−A|² − r² = 0``.
    """

    a: str = ""
    out: str = ""
    radius: Ref = 0.0
    line_point: str = ""
    direction: Ref = 0.0
    line_link: tuple[str, str] | None = None
    branch: int = 1
    links: tuple[str, ...] = ()
    op = K.OP_RRP
    kind = "RRP dyad"

    def inputs(self):
        extra = tuple(self.line_link) if self.line_link else ()
        return (self.a, self.line_point) + extra

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"radius": self.radius, "direction": self.direction}

    def evaluate(self, pts, val):
        beta = val(self.direction)
        ax, ay = pts[self.a]
        lx, ly = pts[self.line_point]
        if self.line_link:
            ux, uy = _unit_eval(pts, self.line_link[0], self.line_link[1], beta)
        else:
            ux, uy = np.cos(beta) + 0 * ax, np.sin(beta) + 0 * ax
        r = val(self.radius)
        wx, wy = lx - ax, ly - ay
        b = ux * wx + uy * wy
        c = wx * wx + wy * wy - r * r
        t = -b + self.branch * np.sqrt(b * b - c)
        pts[self.out] = (lx + t * ux, ly + t * uy)


@dataclass(frozen=True)
class Link:
    """A named link direction: the angle φ of the vector ``tail → head``."""

    name: str
    tail: str
    head: str


@dataclass(frozen=True)
class Distance:
    """A named distance between two points (e.g. a dependent cylinder length S2)."""

    name: str
    a: str
    b: str


GROUP_TYPES = {
    "frame": Frame,
    "dyad": Dyad,
    "cylinder_lever": CylinderLever,
    "crank": Crank,
    "slider_input": SliderInput,
    "rigid": RigidPoint,
    "slider_dyad": SliderDyad,
}
