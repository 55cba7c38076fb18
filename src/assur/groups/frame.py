"""Frame (ground) pivot: a point fixed at ``(x, y)`` [m], or placed by a length and an
angle from another frame point (seed 002: O3 = O1 + l10∠j10, O6 = O3 + l8∠j8), on
link "0"."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar

import numpy as np

from ..errors import ModelError
from ..kernel.emit import emit_zero_jets, pt
from .base import Field, Group, Ref, register

__all__ = ["Frame"]


@register
@dataclass(frozen=True)
class Frame(Group):
    """A frame pivot at fixed coordinates ``x``, ``y`` [m] (numbers or parameters) — or,
    in polar form, at ``origin + length·(cos angle, sin angle)`` from another frame
    point ``origin`` (``length`` [m], ``angle`` [rad] from +x, counter-clockwise;
    numbers or parameters)::

                       ● name
                      /
              length /
                    /  angle
          origin ●------------ +x

    The polar form is evaluated per design like any parameter (a pre-pass fills the
    point's rows of the parameter table), so its length and angle may be solved by
    ``[[solve]]`` conditions or vary over a batch of designs.

    Examples
    --------
    Seed 002's frame: O1 at the origin, O3 = O1 + l10∠j10 in the polar form:

    >>> from assur import examples
    >>> m = examples.combine_002()
    >>> m.group("O3")
    Frame(name='O3', x=None, y=None, origin='O1', length='l10', angle='j10')
    >>> pts = m.evaluate_positions({"j1": 0.0})
    >>> [round(float(v), 4) for v in pts["O3"]]    # 1.209 m at −7.125° from O1 [m]
    [1.1997, -0.15]

    A frame point in either form, by itself:

    >>> from assur.groups import Frame
    >>> Frame("01", x=0.415, y=0.563).refs()        # seed 003 §1.1 [m]
    {'x': 0.415, 'y': 0.563}
    >>> Frame("O3", origin="O1", length=1.209, angle=-0.124).inputs()
    ('O1',)
    """

    x: Ref | None = None
    y: Ref | None = None
    origin: str | None = None
    length: Ref | None = None
    angle: Ref | None = None

    type_name: ClassVar[str] = "frame"
    kind: ClassVar[str] = "frame point"
    kind_ru: ClassVar[str] = "шарнир стойки"
    link_roles: ClassVar = None
    out_fields: ClassVar = ()
    fields: ClassVar = (Field("x", "value", "length", default=None, doc="x of the pivot [m]"),
                        Field("y", "value", "length", default=None, doc="y of the pivot [m]"),
                        Field("origin", "point", default=None,
                              doc="polar form: the frame point it is placed from"),
                        Field("length", "value", "length", default=None,
                              doc="polar form: |origin–point| [m]"),
                        Field("angle", "value", "angle", default=None,
                              doc="polar form: direction origin → point from +x [°]"))

    @property
    def polar(self) -> bool:
        """True for a point placed by length and angle from ``origin``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> m.group("O3").polar, m.group("O1").polar
        (True, False)
        """
        return self.origin is not None

    @classmethod
    def check_fields(cls, given):
        """A message unless ``given`` is exactly ``{x, y}`` or ``{origin, length,
        angle}``, else None.

        Examples
        --------
        >>> from assur.groups import Frame
        >>> print(Frame.check_fields({"x", "y"}))
        None
        >>> Frame.check_fields({"origin", "length"})
        'the polar form needs origin, length and angle'
        >>> Frame.check_fields({"x"})
        'give x and y, or origin, length and angle'
        """
        cart, pol = given & {"x", "y"}, given & {"origin", "length", "angle"}
        if cart and pol:
            return "give either x and y, or origin, length and angle (not both forms)"
        if pol and pol != {"origin", "length", "angle"}:
            return "the polar form needs origin, length and angle"
        if not pol and cart != {"x", "y"}:
            return "give x and y, or origin, length and angle"
        return None

    def validate(self, coordinates):
        """A message if the fields given do not form one of the two forms
        (:meth:`check_fields`) or a value names a generalized coordinate, else None.

        Examples
        --------
        >>> from assur.groups import Frame
        >>> print(Frame("O3", origin="O1", length="l10", angle="j10").validate(("j1",)))
        None
        >>> Frame("P", x="S", y=0.0).validate(("S",))
        "a frame point cannot move: 'S' is a generalized coordinate"
        >>> Frame("P", x=0.0).validate(("S",))
        'give x and y, or origin, length and angle'
        """
        given = {f.name for f in self.fields if getattr(self, f.name) is not None}
        problem = self.check_fields(given)
        if problem:
            return problem
        for r in (self.x, self.y, self.length, self.angle):
            if isinstance(r, str) and r in coordinates:
                return f"a frame point cannot move: {r!r} is a generalized coordinate"
        return None

    def inputs(self):
        """The origin of a polar point; none for a point at ``(x, y)``.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> m.group("O3").inputs(), m.group("O1").inputs()
        (('O1',), ())
        """
        return (self.origin,) if self.polar else ()

    def outputs(self):
        """The frame point itself: its name is the group's name.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> [g.outputs() for g in m.groups[:3]]
        [('O1',), ('O3',), ('O6',)]
        """
        return (self.name,)

    def refs(self):
        """``x`` and ``y`` [m], or ``length`` [m] and ``angle`` [rad] of a polar point.

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> m.group("O3").refs()
        {'length': 'l10', 'angle': 'j10'}
        >>> examples.hitch_003().group("01").refs()
        {'x': 'X01', 'y': 'Y01'}
        """
        if self.polar:
            return {"length": self.length, "angle": self.angle}
        return {"x": self.x, "y": self.y}

    def topology(self, t):
        """Put the point on the frame, link "0"; a polar point's origin must be a frame
        point too. The frame point adds no link.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import Frame
        >>> from assur.core.topology import TopologyBuilder
        >>> m = examples.combine_002()
        >>> t = TopologyBuilder(m.name, m.coordinates)
        >>> [g.topology(t) for g in m.groups[:4]]       # O1, O3, O6, the crank
        [(), (), (), ('1',)]
        >>> t.bodies["0"]
        ['O1', 'O3', 'O6']
        >>> Frame("P", origin="A", length=0.1, angle=0.0).topology(t)
        Traceback (most recent call last):
        ...
        assur.errors.ModelError: frame point 'P' is placed from 'A', which is not a frame point (it moves with link '1')
        """
        if self.polar and t.owner(self.origin) != "0":
            raise ModelError(f"frame point {self.name!r} is placed from {self.origin!r}, "
                             f"which is not a frame point (it moves with link "
                             f"{t.owner(self.origin)!r})")
        t.attach("0", self.name)
        return ()

    def evaluate(self, pts, val):
        """Add the point: ``(x, y)``, or ``origin + length·(cos, sin)(angle)``.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.combine_002()
        >>> pts = {"O1": (0.0, 0.0)}
        >>> m.group("O3").evaluate(pts, lambda ref: ref_value(m.params, ref))
        >>> [round(float(v), 4) for v in pts["O3"]]      # O1 + l10∠j10 [m]
        [1.1997, -0.15]
        """
        if self.polar:
            ox, oy = pts[self.origin]
            r, a = val(self.length), val(self.angle)
            pts[self.name] = (ox + r * np.cos(a), oy + r * np.sin(a))
            return
        x = val(self.x)
        pts[self.name] = (x, val(self.y) + 0 * x)

    def compile(self, c):
        """``(slot, row of x, row of y)``; a polar point's rows are derived rows that
        its pre-pass (:meth:`prepare`) fills.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.core.program import CompileContext
        >>> m = examples.combine_002()
        >>> c = CompileContext(m.coordinates, tuple(m.params))
        >>> m.group("O1").compile(c)       # slot 0; x = y = the literal 0 [m]
        (0, ('lit', 0.0), ('lit', 0.0))
        >>> m.group("O3").compile(c)       # slot 1; two rows the pre-pass fills
        (1, ('der', 0), ('der', 1))
        >>> len(c.prepares)
        1
        """
        if self.polar:
            rx, ry = c.derived_row(), c.derived_row()
            ox, oy = c.frame_rows[self.origin]
            c.prepare(self, (rx, ry, ox, oy, c.pref(self.length), c.pref(self.angle)))
        else:
            rx, ry = c.pref(self.x), c.pref(self.y)
        c.frame_point(self.name, rx, ry)
        return (c.slot(self.name), rx, ry)

    def prepare(self, data, ptab, positions_at):
        """Fill the polar point's rows: ``(x, y) = origin + length·(cos, sin)(angle)``
        per design (the origin's rows are filled before, in solving order).

        Examples
        --------
        >>> from assur import examples
        >>> m = examples.combine_002()
        >>> prog = m.program()
        >>> ptab = prog.param_table(m.params)
        >>> gi, data = prog.prepares[0]
        >>> m.groups[gi].name
        'O3'
        >>> m.groups[gi].prepare(data, ptab, None)
        >>> rx, ry = prog.frame_rows["O3"]
        >>> round(float(ptab[rx, 0]), 4), round(float(ptab[ry, 0]), 4)   # O1 + l10∠j10 [m]
        (1.1997, -0.15)
        """
        rx, ry, ox, oy, rl, ra = data
        ptab[rx] = ptab[ox] + ptab[rl] * np.cos(ptab[ra])
        ptab[ry] = ptab[oy] + ptab[rl] * np.sin(ptab[ra])

    def closure(self, P, val):
        """|point − (origin + length∠angle)| [m] of a polar point; None otherwise.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups.base import ref_value
        >>> m = examples.combine_002()
        >>> pts = m.evaluate_positions({"j1": 0.0})
        >>> val = lambda ref: ref_value(m.params, ref)
        >>> print(m.group("O1").closure(pts.get, val))
        None
        >>> float(m.group("O3").closure(pts.get, val))             # [m]
        0.0
        >>> pts["O3"] = (pts["O3"][0], pts["O3"][1] + 0.002)       # O3 2 mm higher
        >>> round(float(m.group("O3").closure(pts.get, val)), 6)   # [m]
        0.002
        """
        if not self.polar:
            return None
        (x, y), (ox, oy) = P(self.name), P(self.origin)
        r, a = val(self.length), val(self.angle)
        return np.hypot(x - ox - r * np.cos(a), y - oy - r * np.sin(a))

    @classmethod
    def emit(cls, E, i, row):
        """Read the point from its parameter rows; its analogs are zero.

        Examples
        --------
        >>> from assur import examples
        >>> from assur.groups import Frame
        >>> from assur.kernel.emit import Emitter
        >>> row = examples.combine_002().program().rows[1]   # O3: op, slot, rows of x, y
        >>> E = Emitter(K=1, order=1)
        >>> Frame.emit(E, 1, row[1:])
        >>> [line.strip() for line in E.lines]
        ['x1 = params[12, d]', 'y1 = params[13, d]', 'x1_0 = 0.0', 'y1_0 = 0.0']
        """
        o, rx, ry = row
        x, y = pt(o)
        E(f"{x} = params[{rx}, d]")
        E(f"{y} = params[{ry}, d]")
        emit_zero_jets(E, x)
        emit_zero_jets(E, y)

    def reactions(self, r):
        """The frame takes every force passed to it: nothing to solve.

        Examples
        --------
        >>> import numpy as np
        >>> from assur import examples
        >>> from assur.core import statics
        >>> m = examples.combine_002()
        >>> r = statics.ReactionContext(m.solve([0.0]), set())
        >>> r.apply("0", "O3", 0.0, -100.0)                  # 100 N down at O3
        >>> m.group("O3").reactions(r)
        >>> r.joints                                         # no joint to solve
        {}
        >>> [round(float(np.squeeze(v)), 3) for v in r.wrench("0")]  # kept: Fx, Fy [N], M [N·m]
        [0.0, -100.0, -119.966]
        """
