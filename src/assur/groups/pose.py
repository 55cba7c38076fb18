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
    [m] from ``origin`` when the coordinates equal ``at`` (numbers or parameters).

    Examples
    --------
    Seed 003's implement centre of mass S6, at (X6, Y6) = (0.857, 0.156) m from the
    suspension axis 56 at the working stroke S = Sp:

    >>> from assur import examples
    >>> m = examples.hitch_003()
    >>> g = m.group("centre of mass S6")
    >>> g.origin, g.toward, g.dx, g.dy, g.at
    ('56', '67', 'X6', 'Y6', ('Sp',))
    >>> Sp = float(m.params["Sp"])
    >>> round(Sp, 4)                          # solved; seed 003 prints 0.4694 [m]
    0.4694
    >>> p = m.solve([Sp]).point
    >>> [round(float(v), 3) for v in p("S6")[0] - p("56")[0]]   # (X6, Y6) [m]
    [0.857, 0.156]
    """

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
        """``origin`` and ``toward``.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("centre of mass S6").inputs()
        ('56', '67')
        """
        return (self.origin, self.toward)

    def outputs(self):
        """The point it adds.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("centre of mass S6").outputs()
        ('S6',)
        """
        return (self.out,)

    def refs(self):
        """``dx``, ``dy`` [m] and the pose ``at[j]`` of each coordinate j.

        Examples
        --------
        >>> from assur import examples
        >>> examples.hitch_003().group("centre of mass S6").refs()
        {'dx': 'X6', 'dy': 'Y6', 'at[0]': 'Sp'}
        """
        return {"dx": self.dx, "dy": self.dy,
                **{f"at[{j}]": a for j, a in enumerate(self.at)}}

    def validate(self, coordinates):
        """A message unless ``at`` gives every coordinate by a number or a parameter,
        else None.

        Examples
        --------
        >>> import dataclasses
        >>> from assur import examples
        >>> g = examples.hitch_003().group("centre of mass S6")
        >>> print(g.validate(("S",)))
        None
        >>> dataclasses.replace(g, at=()).validate(("S",))
        "at must give the pose of every coordinate ('S',), got ()"
        >>> dataclasses.replace(g, at=("S",)).validate(("S",))
        "the pose must be given by numbers or parameters, got 'S'"
        """
        if len(self.at) != len(coordinates):
            return (f"at must give the pose of every coordinate {tuple(coordinates)}, "
                    f"got {self.at!r}")
        for a in self.at:
            if isinstance(a, str) and a in coordinates:
                return f"the pose must be given by numbers or parameters, got {a!r}"
        return super().validate(coordinates)

    def topology(self, t):
        """Put the point on the one link that holds ``origin`` and ``toward``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.hitch_003()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> for g in m.groups[:9]:                 # the groups before S6
        ...     _ = g.topology(t)
        >>> m.group("centre of mass S6").topology(t), t.owner("S6")
        (('6',), '6')
        """
        b = t.carrier(self, self.origin, self.toward, self.group_links())
        t.attach(b, self.out)
        return (b,)

    def pose_offset(self, ox, oy, tx, ty, dx, dy):
        """(β [rad], ℓ [m]) of the point from the pose positions of origin, toward.

        Examples
        --------
        Seed 003 at S = Sp, where the implement 56 → 67 stands vertical (φ6 = 90°):

        >>> import numpy as np
        >>> from assur import examples
        >>> g = examples.hitch_003().group("centre of mass S6")
        >>> beta, ell = g.pose_offset(0.0, 0.0, 0.0, 1.0, 0.857, 0.156)   # [m]
        >>> round(float(np.degrees(beta)), 3), round(float(ell), 4)      # [deg], [m]
        (-79.683, 0.8711)
        """
        return np.arctan2(dy, dx) - np.arctan2(ty - oy, tx - ox), np.hypot(dx, dy)

    def evaluate(self, pts, val):
        """Add the point: its offset from the positions at the pose (``val.positions_at``
        solves the groups before it there), turned with the link.

        Examples
        --------
        :meth:`assur.Mechanism.evaluate_positions` gives ``val``; the plain-numpy point
        agrees with the kernel's:

        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> pts = m.evaluate_positions({"S": 0.42})          # runs every group's evaluate
        >>> [round(float(v), 4) for v in pts["S6"]]          # [m]
        [1.9923, 0.3329]
        >>> [round(float(v), 4) for v in m.solve([0.42]).point("S6")[0]]   # [m]
        [1.9923, 0.3329]
        """
        pose = val.positions_at(self, tuple(val(a) for a in self.at))
        (ox, oy), (tx, ty) = pose[self.origin], pose[self.toward]
        beta, ell = self.pose_offset(ox, oy, tx, ty, val(self.dx), val(self.dy))
        ux, uy = unit_eval(pts, self.origin, self.toward, beta)
        px, py = pts[self.origin]
        pts[self.out] = (px + ell * ux, py + ell * uy)

    def compile(self, c):
        """The row of a rigid point (:func:`assur.groups.rigid.rigid_emit`) whose angle
        and length are two derived rows, and the pre-pass that fills them.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.hitch_003()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> for g in m.groups[:9]:
        ...     _ = g.compile(c)
        >>> m.group("centre of mass S6").compile(c)   # S6; 56, 67; ℓ; trig row of β; mode 0
        (9, 7, 8, ('der', 1), 4, 0, 0, 0)
        >>> c.trig[-1], len(c.prepares)
        (('angle', ('der', 0)), 1)
        """
        rb, rl = c.derived_row(), c.derived_row()
        c.prepare(self, (rb, rl, c.pref(self.dx), c.pref(self.dy),
                         tuple(c.pref(a) for a in self.at)))
        return (c.slot(self.out), c.slot(self.origin), c.slot(self.toward), rl,
                c.trig_angle(rb), 0, 0, 0)

    @classmethod
    def emit(cls, E, i, row):
        """The point's jets, as a rigid point's (:func:`assur.groups.rigid.rigid_emit`).

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import PosePoint
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.hitch_003().program().rows[9]      # S6 in slot 9
        >>> E = Emitter(K=1, order=1)
        >>> PosePoint.emit(E, 9, row[1:])
        >>> [s for s in (line.strip() for line in E.lines) if s.startswith(("t9l ", "x9 "))]
        ['t9l = params[35, d]', 'x9 = x7 + t9l * u9x']
        """
        rigid_emit(E, i, row)

    def prepare(self, data, ptab, positions_at):
        """Fill the derived rows (β, ℓ) of ``ptab`` per design from the positions of
        origin and toward at the pose; ``positions_at(qpose, points)`` runs the groups
        before this one at ``qpose`` (k, m) and returns ``{point: (x, y)}`` of at least
        ``points``.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> m = examples.hitch_003()
        >>> prog = m.program()
        >>> ptab = prog.param_table(m.params)
        >>> gi, data = prog.prepares[0]
        >>> def positions_at(qpose, points):
        ...     return m.evaluate_positions(dict(zip(m.coordinates, qpose)), upto=gi)
        >>> m.groups[gi].prepare(data, ptab, positions_at)
        >>> rb, rl = data[:2]
        >>> round(float(np.degrees(ptab[rb, 0])), 3)   # β = atan(Y6/X6) − φ6(Sp) [deg]
        -79.683
        >>> round(float(ptab[rl, 0]), 4)               # ℓ = √(X6² + Y6²) [m]
        0.8711
        """
        rb, rl, rdx, rdy, rat = data
        qpose = np.stack([ptab[r] for r in rat])
        pose = positions_at(qpose, (self.origin, self.toward))
        (ox, oy), (tx, ty) = pose[self.origin], pose[self.toward]
        ptab[rb], ptab[rl] = self.pose_offset(ox, oy, tx, ty, ptab[rdx], ptab[rdy])

    def reactions(self, r):
        """A point on a link: nothing to solve.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.hitch_003()
        >>> r = statics.ReactionContext(m.solve([0.42]), set())
        >>> r.apply("6", "S6", 0.0, -27500.0)          # P6 at S6 [N]
        >>> m.group("centre of mass S6").reactions(r)
        >>> r.joints                                   # the weight stays on link 6
        {}
        """
