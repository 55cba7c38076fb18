"""A rigid point known by its offset from a joint at one pose of the mechanism.

Seed 003 fixes the implement's centre of mass S6 by its offset (X6, Y6) from the
suspension axis 56 at the working stroke S = Sp:
``φS6 = 2π + atan(Y6/X6) − φ6(Sp)``, ``LS6 = √(X6² + Y6²)``. The angle and length
are derived per design by a pre-pass at the pose (:meth:`PosePoint.prepare`), after
which the point is a :mod:`rigid point <assur.groups.rigid>` given by length and angle.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from .base import Field, Group, register
from .rigid import rigid_emit, unit_eval

__all__ = ["PosePoint"]


@register
@dataclass(frozen=True)
class PosePoint(Group):
    """Point ``out`` on the link of ``origin`` and ``toward``, at offset ``(dx, dy)``
    [m] from ``origin`` when the coordinates equal ``at`` (numbers or parameters)."""

    origin: str = ""
    toward: str = ""
    out: str = ""
    dx: object = 0.0
    dy: object = 0.0
    at: tuple = ()
    links: tuple[str, ...] = ()

    type_name: ClassVar[str] = "pose_point"
    kind: ClassVar[str] = "rigid point fixed at a pose"
    kind_ru: ClassVar[str] = "точка звена, заданная в положении"
    link_roles: ClassVar = None
    fields: ClassVar = (
        Field("origin", "point", doc="a point of the carrying link"),
        Field("toward", "point", doc="another point of the same link"),
        Field("out", "point", doc="the point it adds"),
        Field("dx", "value", "length", doc="x offset from origin at the pose [m]"),
        Field("dy", "value", "length", doc="y offset from origin at the pose [m]"),
        Field("at", "position", doc="the pose: {coordinate = value}"),
    )

    def inputs(self):
        return (self.origin, self.toward)

    def outputs(self):
        return (self.out,)

    def refs(self):
        return {"dx": self.dx, "dy": self.dy,
                **{f"at[{j}]": a for j, a in enumerate(self.at)}}

    def validate(self, coordinates):
        if len(self.at) != len(coordinates):
            return (f"at must give the pose of every coordinate {tuple(coordinates)}, "
                    f"got {self.at!r}")
        for a in self.at:
            if isinstance(a, str) and a in coordinates:
                return f"the pose must be given by numbers or parameters, got {a!r}"
        return super().validate(coordinates)

    def topology(self, t):
        b = t.carrier(self, self.origin, self.toward, self.group_links())
        t.attach(b, self.out)
        return (b,)

    def pose_offset(self, ox, oy, tx, ty, dx, dy):
        """(β [rad], ℓ [m]) of the point from the pose positions of origin, toward."""
        return np.arctan2(dy, dx) - np.arctan2(ty - oy, tx - ox), np.hypot(dx, dy)

    def evaluate(self, pts, val):
        pose = val.positions_at(self, tuple(val(a) for a in self.at))
        (ox, oy), (tx, ty) = pose[self.origin], pose[self.toward]
        beta, ell = self.pose_offset(ox, oy, tx, ty, val(self.dx), val(self.dy))
        ux, uy = unit_eval(pts, self.origin, self.toward, beta)
        px, py = pts[self.origin]
        pts[self.out] = (px + ell * ux, py + ell * uy)

    def compile(self, c):
        rb, rl = c.derived_row(), c.derived_row()
        c.prepare(self, (rb, rl, c.pref(self.dx), c.pref(self.dy),
                         tuple(c.pref(a) for a in self.at)))
        return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward), rl,
                c.trig_angle(rb), 0, 0, 0)

    emit = classmethod(lambda cls, E, i, row: rigid_emit(E, i, row))

    def prepare(self, data, ptab, positions_at):
        """Fill the derived rows (β, ℓ) of ``ptab`` per design from the positions of
        origin and toward at the pose; ``positions_at(qpose)`` runs the groups before
        this one at ``qpose`` (k, m) and returns ``{point: (x, y)}``."""
        rb, rl, rdx, rdy, rat = data
        qpose = np.stack([ptab[r] for r in rat])
        pose = positions_at(qpose, (self.origin, self.toward))
        (ox, oy), (tx, ty) = pose[self.origin], pose[self.toward]
        ptab[rb], ptab[rl] = self.pose_offset(ox, oy, tx, ty, ptab[rdx], ptab[rdy])

    def reactions(self, r):
        """A point on a link: nothing to solve."""
